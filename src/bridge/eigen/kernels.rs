//! Dense kernels with the parallelism passed per call.
//!
//! faer's high-level methods (`Mat::llt`, `Mat::self_adjoint_eigen`, the
//! `*` operator, the triangular solves of a `MatRef`) read a process-wide
//! setting; the library never sets it (a Python host or another library in
//! the same process owns it). These call faer's low-level functions with an
//! explicit [`Par`] instead, with the same default parameters, so a call
//! with `Par::Seq` gives exactly what the method gave under a sequential
//! global setting. The eigen solver passes `Par::Seq` for all k × k work
//! (cheap, and faer's parallel kernels may split a reduction by the thread
//! count); its n × k work is split by [`super::parallel`] instead.

use faer::diag::Diag;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::matmul::matmul;
use faer::{Accum, Col, ColRef, Mat, MatRef, Par};

/// L of A = L Lᵀ (A symmetric positive definite, its lower triangle read),
/// the upper triangle of L zero; `None` if A is not positive definite.
/// As `Mat::llt(Side::Lower)`. Cost O(n³).
pub fn cholesky_lower(a: MatRef<'_, f64>, par: Par) -> Option<Mat<f64>> {
    use faer::linalg::cholesky::llt::factor;
    let n = a.nrows();
    let mut l = Mat::<f64>::zeros(n, n);
    l.copy_from_triangular_lower(a);
    let mut memory = MemBuffer::new(factor::cholesky_in_place_scratch::<f64>(
        n,
        par,
        Default::default(),
    ));
    factor::cholesky_in_place(
        l.as_mut(),
        Default::default(),
        par,
        MemStack::new(&mut memory),
        Default::default(),
    )
    .ok()?;
    for j in 1..n {
        for i in 0..j {
            l[(i, j)] = 0.0;
        }
    }
    Some(l)
}

/// Eigenvalues (ascending) and orthonormal eigenvectors (columns) of the
/// symmetric A (its lower triangle read); `None` if the solver fails. As
/// `Mat::self_adjoint_eigen(Side::Lower)`. Cost O(n³).
pub fn symmetric_eigen(a: MatRef<'_, f64>, par: Par) -> Option<(Vec<f64>, Mat<f64>)> {
    use faer::linalg::evd;
    let n = a.nrows();
    let mut u = Mat::<f64>::zeros(n, n);
    let mut s = Diag::<f64>::zeros(n);
    let mut memory = MemBuffer::new(evd::self_adjoint_evd_scratch::<f64>(
        n,
        evd::ComputeEigenvectors::Yes,
        par,
        Default::default(),
    ));
    evd::self_adjoint_evd(
        a,
        s.as_mut(),
        Some(u.as_mut()),
        par,
        MemStack::new(&mut memory),
        Default::default(),
    )
    .ok()?;
    Some((s.column_vector().iter().copied().collect(), u))
}

/// A B, as the `*` operator.
pub fn product(a: MatRef<'_, f64>, b: MatRef<'_, f64>, par: Par) -> Mat<f64> {
    let mut out = Mat::<f64>::zeros(a.nrows(), b.ncols());
    matmul(out.as_mut(), Accum::Replace, a, b, 1.0, par);
    out
}

/// A x, as the `*` operator of a matrix and a column.
pub fn product_col(a: MatRef<'_, f64>, x: ColRef<'_, f64>, par: Par) -> Col<f64> {
    let mut out = Col::<f64>::zeros(a.nrows());
    matmul(out.as_mut(), Accum::Replace, a, x, 1.0, par);
    out
}

/// X ← L⁻¹ X for a lower triangular L.
pub fn solve_lower(l: MatRef<'_, f64>, x: faer::MatMut<'_, f64>, par: Par) {
    faer::linalg::triangular_solve::solve_lower_triangular_in_place(l, x, par);
}

/// X ← U⁻¹ X for an upper triangular U.
pub fn solve_upper(u: MatRef<'_, f64>, x: faer::MatMut<'_, f64>, par: Par) {
    faer::linalg::triangular_solve::solve_upper_triangular_in_place(u, x, par);
}
