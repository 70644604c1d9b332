//! The dense path of the eigen solver, for small pencils (a coarse beam, a
//! plate's Ritz basis): every mode at once by the inverted reduction.
//!
//! K c = λ M c is solved as M c = μ K c, μ = 1/λ, reduced with the Cholesky
//! factor K = L Lᵀ to the standard problem A y = μ y, A = L⁻¹ M L⁻ᵀ. A dense
//! symmetric eigen solver finds each μ to about ε‖A‖ absolutely, and
//! ‖A‖ = μ_max = 1/λ_min: the lowest modes — the ones a response uses — keep
//! full relative accuracy whatever the spread of the spectrum, and only the
//! highest lose digits. (Reduced forwards, ‖A‖ = λ_max, which grows like
//! elements⁴ on a beam and swamps the fundamental on fine meshes.) Each
//! λ is then the Rayleigh quotient cᵀKc / cᵀMc = 1/(cᵀMc) of its vector
//! (cᵀKc = 1 from the reduction). Sequential (`Par::Seq`): bit-identical
//! whatever the thread count. Cost O(n³) time, O(n²) memory.

use faer::{Mat, Par, Side};

use crate::bridge::BridgeError;

/// Every eigenpair of K c = λ M c (K, M symmetric positive definite): λ
/// ascending (rad²/s²) and the M-normalised vectors (cᵀMc = 1) as columns,
/// each with its largest-magnitude entry positive (reproducible signs).
pub fn lowest_inverted(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    faer::set_global_parallelism(Par::Seq);
    let n = stiffness.nrows();
    // About eight n × n work matrices (the reduction, faer's eigen solver,
    // the sorted vectors): refuse what cannot be had instead of aborting.
    ensure_memory(n, n, 8)?;
    let llt = stiffness
        .llt(Side::Lower)
        .map_err(|_| BridgeError::StiffnessNotPositive)?;
    let lower = llt.L();
    // A = L⁻¹ M L⁻ᵀ: first X = L⁻¹ M, then A = L⁻¹ Xᵀ (M symmetric).
    let mut x = mass.clone();
    lower.solve_lower_triangular_in_place(x.as_mut());
    let mut a = x.transpose().to_owned();
    lower.solve_lower_triangular_in_place(a.as_mut());
    let a = Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] + a[(j, i)]));
    let eig = a
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    // c = L⁻ᵀ y is K-normalised (cᵀKc = 1).
    let mut vectors = eig.U().to_owned();
    lower
        .transpose()
        .solve_upper_triangular_in_place(vectors.as_mut());
    let modal_masses: Vec<f64> = (0..n)
        .map(|m| {
            let c = vectors.col(m);
            let mc = mass * c;
            c.iter().zip(mc.iter()).map(|(a, b)| a * b).sum::<f64>()
        })
        .collect();
    if modal_masses.iter().any(|&mm| !(mm > 0.0 && mm.is_finite())) {
        return Err(BridgeError::MassNotPositive);
    }
    // λ = 1/(cᵀMc); ascending λ is descending modal mass.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&p, &q| modal_masses[q].total_cmp(&modal_masses[p]));
    let eigenvalues = order.iter().map(|&m| modal_masses[m].recip()).collect();
    let mut sorted = Mat::<f64>::zeros(n, n);
    for (mode, &m) in order.iter().enumerate() {
        let scale = modal_masses[m].sqrt().recip();
        let mut largest = 0.0f64;
        for r in 0..n {
            if vectors[(r, m)].abs() > largest.abs() {
                largest = vectors[(r, m)];
            }
        }
        let sign = if largest < 0.0 { -1.0 } else { 1.0 };
        for r in 0..n {
            sorted[(r, mode)] = sign * scale * vectors[(r, m)];
        }
    }
    Ok((eigenvalues, sorted))
}

/// Every eigenpair of K c = λ M c by the forward reduction: M = L Lᵀ,
/// A = L⁻¹ K L⁻ᵀ, c = L⁻ᵀ y (so cᵀMc = 1), λ ascending, signs as in
/// [`lowest_inverted`]. The dense solver finds each λ to about ε‖A‖ = ε·λₙ
/// absolutely: accurate at the top of the spectrum, where the inverted
/// reduction is not ([`super::Pencil`]'s dense path takes each mode from
/// the better one). Cost O(n³) time, O(n²) memory.
pub fn every_forward(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    faer::set_global_parallelism(Par::Seq);
    let n = stiffness.nrows();
    ensure_memory(n, n, 8)?;
    let llt = mass
        .llt(Side::Lower)
        .map_err(|_| BridgeError::MassNotPositive)?;
    let lower = llt.L();
    let mut x = stiffness.clone();
    lower.solve_lower_triangular_in_place(x.as_mut());
    let mut a = x.transpose().to_owned();
    lower.solve_lower_triangular_in_place(a.as_mut());
    let a = Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] + a[(j, i)]));
    let eig = a
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    let values: Vec<f64> = eig.S().column_vector().iter().copied().collect();
    let mut vectors = eig.U().to_owned();
    lower
        .transpose()
        .solve_upper_triangular_in_place(vectors.as_mut());
    for mode in 0..n {
        let mut largest = 0.0f64;
        for r in 0..n {
            if vectors[(r, mode)].abs() > largest.abs() {
                largest = vectors[(r, mode)];
            }
        }
        if largest < 0.0 {
            for r in 0..n {
                vectors[(r, mode)] = -vectors[(r, mode)];
            }
        }
    }
    Ok((values, vectors))
}

/// Every eigenpair of a small projected pencil A y = λ B y (B positive
/// definite, A symmetric, both k × k with k a handful): B = L Lᵀ,
/// C = L⁻¹ A L⁻ᵀ, y = L⁻ᵀ z (so yᵀBy = 1), λ ascending. Forward: the
/// projected spectrum of one cluster spans no decades. Cost O(k³).
pub fn lowest_forward_small(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    let k = stiffness.nrows();
    let mass = Mat::from_fn(k, k, |i, j| 0.5 * (mass[(i, j)] + mass[(j, i)]));
    let llt = mass
        .llt(Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    let lower = llt.L();
    let mut x = Mat::from_fn(k, k, |i, j| 0.5 * (stiffness[(i, j)] + stiffness[(j, i)]));
    lower.solve_lower_triangular_in_place(x.as_mut());
    let mut c = x.transpose().to_owned();
    lower.solve_lower_triangular_in_place(c.as_mut());
    let c = Mat::from_fn(k, k, |i, j| 0.5 * (c[(i, j)] + c[(j, i)]));
    let eig = c
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    let values: Vec<f64> = eig.S().column_vector().iter().copied().collect();
    let mut y = eig.U().to_owned();
    lower
        .transpose()
        .solve_upper_triangular_in_place(y.as_mut());
    Ok((values, y))
}

/// Checks that `copies` matrices of `rows × cols` f64 can be allocated,
/// before a dense kernel that would abort on failure allocates them.
pub fn ensure_memory(rows: usize, cols: usize, copies: usize) -> Result<(), BridgeError> {
    let entries = rows
        .checked_mul(cols)
        .and_then(|e| e.checked_mul(copies))
        .ok_or(BridgeError::OutOfMemory)?;
    let mut probe: Vec<f64> = Vec::new();
    probe
        .try_reserve_exact(entries)
        .map_err(|_| BridgeError::OutOfMemory)?;
    Ok(())
}
