//! The checks every returned set of modes passes (module doc of
//! [`super`]): energy-norm residuals and M-orthonormality ([`verify`]), and
//! completeness by the inertia (Sturm) count in a gap above the last mode
//! ([`inertia_check`]); [`check_dense`] applies them to a dense pencil.

use faer::Mat;
use faer::Par::Seq;

use super::parallel;
use super::sparse::{Factor, SymmetricSparse, multiply, symmetric_from_entries};
use super::{ModeCheck, ORTHONORMALITY_BOUND, Pencil, RESIDUAL_BOUND, kernels};
use crate::bridge::BridgeError;

/// Relative gap below which two eigenvalues count as one cluster (a cut never
/// separates them for the completeness check).
pub(super) const CLUSTER_GAP: f64 = 1e-9;

/// Where the completeness check cuts the spectrum.
pub(super) enum Gap {
    /// At σ (rad²/s²), strictly between two eigenvalues.
    Between(f64),
    /// Every mode of the model was found: nothing to count.
    All,
}

/// The completeness check: at a shift in the gap, the inertia count
/// (`count_below`) must equal the number of eigenvalues solved below it;
/// returns (shift, count), or `None` when every mode was solved.
pub(super) fn inertia_check(
    gap: Gap,
    eigenvalues: &[f64],
    count: usize,
    count_below: impl FnOnce(f64) -> Result<usize, BridgeError>,
) -> Result<Option<(f64, usize)>, BridgeError> {
    let Gap::Between(shift) = gap else {
        return Ok(None);
    };
    let found = count_below(shift)?;
    let expected = cluster_end(eigenvalues, count);
    if found != expected {
        return Err(BridgeError::ModesMissing {
            below: shift.sqrt() / (2.0 * std::f64::consts::PI),
            solved: expected,
            counted: found,
        });
    }
    Ok(Some((shift, found)))
}

/// Index one past the cluster that contains eigenvalue `count − 1`.
fn cluster_end(eigenvalues: &[f64], count: usize) -> usize {
    let mut end = count;
    while end < eigenvalues.len()
        && eigenvalues[end] - eigenvalues[end - 1] <= CLUSTER_GAP * eigenvalues[end].abs()
    {
        end += 1;
    }
    end
}

/// A shift in the first clear gap at or after the first `count`
/// eigenvalues; `None` if the computed ones end inside a cluster.
pub(super) fn first_gap(eigenvalues: &[f64], count: usize, complete: bool) -> Option<Gap> {
    let end = cluster_end(eigenvalues, count);
    if end < eigenvalues.len() {
        Some(Gap::Between(
            0.5 * (eigenvalues[end - 1] + eigenvalues[end]),
        ))
    } else if complete {
        Some(Gap::All)
    } else {
        None
    }
}

/// Checks each pair's energy-norm residual and the set's M-orthonormality
/// against the bounds; `solve_stiffness` overwrites its argument b with
/// K⁻¹b. Returns (largest energy residual, largest plain residual, largest
/// orthonormality error). Cost O(count · nnz(L)) + O(n · count²).
pub fn verify(
    stiffness: impl Fn(&[f64], &mut [f64]),
    mass: impl Fn(&[f64], &mut [f64]),
    mut solve_stiffness: impl FnMut(&mut [f64]),
    eigenvalues: &[f64],
    vectors: &Mat<f64>,
) -> Result<(f64, f64, f64), BridgeError> {
    let n = vectors.nrows();
    let count = eigenvalues.len();
    let mut m_vectors = Mat::<f64>::zeros(n, count);
    let mut largest_residual = 0.0f64;
    let mut largest_plain_residual = 0.0f64;
    let mut scratch = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    for (mode, &lambda) in eigenvalues.iter().enumerate() {
        let phi = vectors.col(mode).try_as_col_major().unwrap().as_slice();
        let m_phi = m_vectors
            .col_mut(mode)
            .try_as_col_major_mut()
            .unwrap()
            .as_slice_mut();
        let (relative, plain) = mode_residuals(
            (&stiffness, &mass, &mut solve_stiffness),
            lambda,
            phi,
            m_phi,
            &mut scratch,
        );
        accept(mode, lambda, relative)?;
        largest_residual = largest_residual.max(relative);
        largest_plain_residual = largest_plain_residual.max(plain);
    }
    let orthonormality_error = orthonormality(vectors, &m_vectors, Seq)?;
    Ok((
        largest_residual,
        largest_plain_residual,
        orthonormality_error,
    ))
}

/// [`verify`] with K⁻¹ by `factor`, the modes checked on the threads `par`
/// allows (each mode's figures computed as [`verify`] computes them, so the
/// result is the same whatever the thread count; the Gram matrix by
/// [`super::parallel::product_tn`]).
pub(super) fn verify_parallel(
    stiffness: &(dyn Fn(&[f64], &mut [f64]) + Sync),
    mass: &SymmetricSparse,
    factor: &Factor,
    eigenvalues: &[f64],
    vectors: &Mat<f64>,
    par: faer::Par,
) -> Result<(f64, f64, f64), BridgeError> {
    let n = vectors.nrows();
    let count = eigenvalues.len();
    let mut m_vectors = Mat::<f64>::zeros(n, count);
    let figures = std::sync::Mutex::new(vec![(0.0, 0.0); count]);
    parallel::for_columns_with_solves(
        par,
        factor,
        m_vectors.as_mut(),
        |mode, m_phi, workspace, scratch| {
            let phi = vectors.col(mode).try_as_col_major().unwrap().as_slice();
            let apply_mass = |x: &[f64], y: &mut [f64]| multiply(mass, x, y);
            let solve = |x: &mut [f64]| factor.solve_in_place(x, workspace);
            let pair = mode_residuals(
                (stiffness, apply_mass, solve),
                eigenvalues[mode],
                phi,
                m_phi,
                scratch,
            );
            figures.lock().unwrap()[mode] = pair;
        },
    )?;
    let figures = figures.into_inner().unwrap();
    let mut largest_residual = 0.0f64;
    let mut largest_plain_residual = 0.0f64;
    for (mode, (&lambda, &(relative, plain))) in eigenvalues.iter().zip(&figures).enumerate() {
        accept(mode, lambda, relative)?;
        largest_residual = largest_residual.max(relative);
        largest_plain_residual = largest_plain_residual.max(plain);
    }
    let orthonormality_error = orthonormality(vectors, &m_vectors, par)?;
    Ok((
        largest_residual,
        largest_plain_residual,
        orthonormality_error,
    ))
}

/// One pair's (energy-norm, plain) relative residuals; M φ into `m_phi`.
/// `scratch`: three n-vectors, overwritten.
fn mode_residuals(
    (stiffness, mass, mut solve_stiffness): (
        impl Fn(&[f64], &mut [f64]),
        impl Fn(&[f64], &mut [f64]),
        impl FnMut(&mut [f64]),
    ),
    lambda: f64,
    phi: &[f64],
    m_phi: &mut [f64],
    scratch: &mut parallel::Scratch,
) -> (f64, f64) {
    let n = phi.len();
    let [k_phi, residual, flexible] = scratch;
    stiffness(phi, k_phi);
    mass(phi, m_phi);
    let norm_k: f64 = k_phi.iter().map(|v| v * v).sum::<f64>().sqrt();
    for i in 0..n {
        residual[i] = k_phi[i] - lambda * m_phi[i];
    }
    let plain = residual.iter().map(|v| v * v).sum::<f64>().sqrt() / norm_k;
    // ‖r‖²_{K⁻¹} = rᵀK⁻¹r; ‖Kφ‖²_{K⁻¹} = φᵀKφ.
    flexible.copy_from_slice(residual);
    solve_stiffness(flexible);
    let energy_r: f64 = residual
        .iter()
        .zip(flexible.iter())
        .map(|(a, b)| a * b)
        .sum();
    let energy_phi: f64 = phi.iter().zip(k_phi.iter()).map(|(a, b)| a * b).sum();
    ((energy_r.abs() / energy_phi).sqrt(), plain)
}

/// Whether mode `mode` (from 0) passes the residual bound.
fn accept(mode: usize, lambda: f64, relative: f64) -> Result<(), BridgeError> {
    if lambda > 0.0 && lambda.is_finite() && relative <= RESIDUAL_BOUND {
        return Ok(());
    }
    Err(BridgeError::ModeCheckFailed {
        mode: mode + 1,
        what: "relative residual ‖Kφ − ω²Mφ‖/‖Kφ‖ in the energy norm",
        value: relative,
        bound: RESIDUAL_BOUND,
    })
}

/// Largest |ΦᵀMΦ − I| entry, checked against the bound (`m_vectors` = M Φ).
fn orthonormality(
    vectors: &Mat<f64>,
    m_vectors: &Mat<f64>,
    par: faer::Par,
) -> Result<f64, BridgeError> {
    let count = vectors.ncols();
    let mut gram = Mat::<f64>::zeros(count, count);
    parallel::product_tn(gram.as_mut(), vectors.as_ref(), m_vectors.as_ref(), par);
    let mut orthonormality_error = 0.0f64;
    for i in 0..count {
        for j in 0..count {
            let target = if i == j { 1.0 } else { 0.0 };
            let error = (gram[(i, j)] - target).abs();
            if error.is_nan() || error > ORTHONORMALITY_BOUND {
                return Err(BridgeError::ModeCheckFailed {
                    mode: i.max(j) + 1,
                    what: "M-orthonormality |φᵢᵀMφⱼ − δᵢⱼ|",
                    value: error,
                    bound: ORTHONORMALITY_BOUND,
                });
            }
            orthonormality_error = orthonormality_error.max(error);
        }
    }
    Ok(orthonormality_error)
}

/// Checks the lowest `count` of every eigenpair of a dense pencil (a Ritz
/// model, whose dense solve returns them all) like [`Pencil::lowest`]:
/// residuals, M-orthonormality and the inertia count above the last one.
/// Cost O(n³) (one LDLᵀ of the shifted pencil) + O(n² · count).
pub fn check_dense(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
    eigenvalues: &[f64],
    vectors: &Mat<f64>,
    count: usize,
) -> Result<ModeCheck, BridgeError> {
    let n = stiffness.nrows();
    let count = count.min(n);
    let to_sparse = |a: &Mat<f64>| {
        symmetric_from_entries(
            n,
            (0..n)
                .flat_map(|j| (0..n).map(move |i| (i, j)))
                .filter_map(|(i, j)| {
                    let v = a[(i, j)];
                    (v != 0.0).then_some((i, j, v))
                }),
            false,
        )
    };
    let gap = first_gap(eigenvalues, count, true).unwrap_or(Gap::All);
    let inertia = inertia_check(gap, eigenvalues, count, |shift| {
        Pencil::new(to_sparse(stiffness)?, to_sparse(mass)?).count_below(shift)
    })?;
    let kept = vectors.subcols(0, count).to_owned();
    let lower = kernels::cholesky_lower(stiffness.as_ref(), Seq)
        .ok_or(BridgeError::StiffnessNotPositive)?;
    let (largest_residual, largest_plain_residual, orthonormality_error) = verify(
        |x, y| dense_multiply(stiffness, x, y),
        |x, y| dense_multiply(mass, x, y),
        |x| {
            let len = x.len();
            let mut x = faer::MatMut::from_column_major_slice_mut(x, len, 1);
            kernels::solve_lower(lower.as_ref(), x.as_mut(), Seq);
            kernels::solve_upper(lower.transpose(), x, Seq);
        },
        &eigenvalues[..count],
        &kept,
    )?;
    Ok(ModeCheck {
        largest_residual,
        largest_plain_residual,
        orthonormality_error,
        inertia,
        dense: true,
    })
}

fn dense_multiply(a: &Mat<f64>, x: &[f64], y: &mut [f64]) {
    for (i, yi) in y.iter_mut().enumerate() {
        *yi = (0..x.len()).map(|j| a[(i, j)] * x[j]).sum();
    }
}
