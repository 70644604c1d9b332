//! Dense symmetric eigen and linear solves for bridge models (faer).
//!
//! All calls run sequentially (`Par::Seq`) so results are bit-identical
//! whatever the thread count; parallelism lives at the study level instead.

use faer::linalg::solvers::Solve;
use faer::{Mat, Par, Side};

use super::BridgeError;

fn sequential() {
    // Global in faer; we only ever want the sequential, deterministic kernels.
    faer::set_global_parallelism(Par::Seq);
}

/// Solves K φ = λ M φ for symmetric K and symmetric positive definite M.
///
/// Reduction to standard form with the Cholesky factor M = L Lᵀ:
/// A = L⁻¹ K L⁻ᵀ, A y = λ y, φ = L⁻ᵀ y, so φᵀ M φ = yᵀ y = 1 (mass-normalised).
/// Eigenvalues ascending (λ = ω², rad²/s²); each vector's sign is fixed so
/// that its largest-magnitude entry is positive, making shapes reproducible.
/// Cost O(n³) time, O(n²) memory.
pub fn generalized_symmetric(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    sequential();
    let n = stiffness.nrows();
    let llt = mass
        .llt(Side::Lower)
        .map_err(|_| BridgeError::MassNotPositive)?;
    let lower = llt.L();
    // A = L⁻¹ K L⁻ᵀ: first X = L⁻¹ K, then A = L⁻¹ Xᵀ (K symmetric).
    let mut x = stiffness.clone();
    lower.solve_lower_triangular_in_place(x.as_mut());
    let mut a = x.transpose().to_owned();
    lower.solve_lower_triangular_in_place(a.as_mut());
    // Symmetrise round-off.
    let a = Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] + a[(j, i)]));
    let eig = a
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    let values: Vec<f64> = (0..n).map(|i| eig.S()[i]).collect();
    let mut vectors = eig.U().to_owned();
    lower
        .transpose()
        .solve_upper_triangular_in_place(vectors.as_mut());
    for j in 0..n {
        let mut largest = 0.0f64;
        for i in 0..n {
            if vectors[(i, j)].abs() > largest.abs() {
                largest = vectors[(i, j)];
            }
        }
        if largest < 0.0 {
            for i in 0..n {
                vectors[(i, j)] = -vectors[(i, j)];
            }
        }
    }
    Ok((values, vectors))
}

/// Solves K u = b for symmetric positive definite K (Cholesky). O(n³).
pub fn solve_spd(stiffness: &Mat<f64>, mut rhs: Mat<f64>) -> Result<Mat<f64>, BridgeError> {
    sequential();
    let llt = stiffness
        .llt(Side::Lower)
        .map_err(|_| BridgeError::StiffnessNotPositive)?;
    llt.solve_in_place(rhs.as_mut());
    Ok(rhs)
}
