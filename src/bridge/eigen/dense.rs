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
//! (cᵀKc = 1 from the reduction). Sequential (`Par::Seq`, passed per call:
//! [`super::kernels`]): bit-identical whatever the thread count. Cost O(n³) time, O(n²) memory.

use faer::{Mat, Par};

use super::kernels::{cholesky_lower, product_col, solve_lower, solve_upper, symmetric_eigen};

use crate::bridge::BridgeError;

/// Every eigenpair of K c = λ M c (K, M symmetric positive definite): λ
/// ascending (rad²/s²) and the M-normalised vectors (cᵀMc = 1) as columns,
/// each with its largest-magnitude entry positive (reproducible signs).
pub fn lowest_inverted(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    let n = stiffness.nrows();
    // About eight n × n work matrices (the reduction, faer's eigen solver,
    // the sorted vectors): refuse what cannot be had instead of aborting.
    ensure_memory(n, n, 8)?;
    let lower =
        cholesky_lower(stiffness.as_ref(), Par::Seq).ok_or(BridgeError::StiffnessNotPositive)?;
    let lower = lower.as_ref();
    // A = L⁻¹ M L⁻ᵀ: first X = L⁻¹ M, then A = L⁻¹ Xᵀ (M symmetric).
    let mut x = mass.clone();
    solve_lower(lower, x.as_mut(), Par::Seq);
    let mut a = x.transpose().to_owned();
    solve_lower(lower, a.as_mut(), Par::Seq);
    let a = Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] + a[(j, i)]));
    let (_, eigenvectors) =
        symmetric_eigen(a.as_ref(), Par::Seq).ok_or(BridgeError::EigenFailed)?;
    // c = L⁻ᵀ y is K-normalised (cᵀKc = 1).
    let mut vectors = eigenvectors;
    solve_upper(lower.transpose(), vectors.as_mut(), Par::Seq);
    let modal_masses: Vec<f64> = (0..n)
        .map(|m| {
            let c = vectors.col(m);
            let mc = product_col(mass.as_ref(), c, Par::Seq);
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
    let n = stiffness.nrows();
    ensure_memory(n, n, 8)?;
    let lower = cholesky_lower(mass.as_ref(), Par::Seq).ok_or(BridgeError::MassNotPositive)?;
    let lower = lower.as_ref();
    let mut x = stiffness.clone();
    solve_lower(lower, x.as_mut(), Par::Seq);
    let mut a = x.transpose().to_owned();
    solve_lower(lower, a.as_mut(), Par::Seq);
    let a = Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] + a[(j, i)]));
    let (values, eigenvectors) =
        symmetric_eigen(a.as_ref(), Par::Seq).ok_or(BridgeError::EigenFailed)?;
    let mut vectors = eigenvectors;
    solve_upper(lower.transpose(), vectors.as_mut(), Par::Seq);
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
    let lower = cholesky_lower(mass.as_ref(), Par::Seq).ok_or(BridgeError::EigenFailed)?;
    let lower = lower.as_ref();
    let mut x = Mat::from_fn(k, k, |i, j| 0.5 * (stiffness[(i, j)] + stiffness[(j, i)]));
    solve_lower(lower, x.as_mut(), Par::Seq);
    let mut c = x.transpose().to_owned();
    solve_lower(lower, c.as_mut(), Par::Seq);
    let c = Mat::from_fn(k, k, |i, j| 0.5 * (c[(i, j)] + c[(j, i)]));
    let (values, eigenvectors) =
        symmetric_eigen(c.as_ref(), Par::Seq).ok_or(BridgeError::EigenFailed)?;
    let mut y = eigenvectors;
    solve_upper(lower.transpose(), y.as_mut(), Par::Seq);
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
