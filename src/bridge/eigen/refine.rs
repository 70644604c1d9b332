//! Refinement of eigenpairs that miss the residual bound: shifted inverse
//! iteration with a Rayleigh–Ritz projection over each cluster
//! ([`Pencil::refine_shifted`]), a few passes kept only while they lower the
//! worst residual ([`Pencil::refine_inaccurate`]), and the helpers they
//! share (symmetric M-orthonormalisation, energy residuals, ordering).

use faer::Mat;
use faer::Par::Seq;

use super::sparse::{Factor, SymmetricSparse, multiply, shifted};
use super::{Pencil, RESIDUAL_BOUND, dense, kernels, lanczos};
use crate::bridge::BridgeError;

/// Relative gap below which neighbours are refined together by
/// [`Pencil::refine_shifted`].
const REFINE_CLUSTER_GAP: f64 = 1e-6;

/// Most passes of [`Pencil::refine_shifted`].
const REFINE_PASSES: usize = 6;

/// Relative distance of [`Pencil::refine_shifted`]'s shift below its
/// cluster.
const REFINE_SHIFT: f64 = 1e-7;

impl Pencil {
    /// Refines the pairs whose energy residual exceeds a tenth of
    /// [`RESIDUAL_BOUND`] by one step of shifted inverse iteration and a
    /// Rayleigh–Ritz projection over their cluster (neighbours closer than
    /// [`REFINE_CLUSTER_GAP`] relatively, refined together so a
    /// near-degenerate pair keeps two independent vectors): X = (K − σM)⁻¹ M Φ
    /// with σ just below the cluster, which divides the error along mode j
    /// by |λⱼ − σ|/|λ − σ| ~ (relative gap)/10⁻⁷. Measured on the
    /// 1,584-DOF generated viaduct, 1,132 modes: the best of the dense
    /// solve and its polishing left modes 1,036–1,131 at up to 2.8e-8
    /// (faer's dense eigen solver keeps the top of an inverted spectrum
    /// less well than LAPACK's); refined, all below 1e-10. Cost one sparse
    /// LDLᵀ of K − σM per cluster refined, so only for the dense path's
    /// orders (≤ [`DENSE_SHARE_LIMIT`]).
    pub(super) fn refine_shifted(
        &self,
        eigenvalues: &mut [f64],
        vectors: &mut Mat<f64>,
        residuals: &[f64],
        stiffness: Option<lanczos::Product<'_>>,
    ) -> Result<(), BridgeError> {
        let (n, count) = (vectors.nrows(), eigenvalues.len());
        let mut column = vec![0.0; n];
        let mut product = vec![0.0; n];
        let mut refined_modes = Vec::new();
        let scratch = std::cell::RefCell::new(vec![0.0; n]);
        let mut first = 0;
        while first < count {
            let mut end = first + 1;
            while end < count
                && eigenvalues[end] - eigenvalues[end - 1]
                    <= REFINE_CLUSTER_GAP * eigenvalues[end].abs()
            {
                end += 1;
            }
            let (a, b) = (first, end);
            first = end;
            // NaN counts as failing.
            if residuals[a..b].iter().all(|&r| r <= 0.1 * RESIDUAL_BOUND) {
                continue;
            }
            let shift = eigenvalues[a] * (1.0 - REFINE_SHIFT);
            let factor = Factor::new(&shifted(&self.stiffness, &self.mass, shift)?)?;
            let mut workspace = factor.workspace()?;
            // With an accurate K, each solve is refined against K − σM
            // applied through it ([`lanczos::RefinedSolve`]): the factor
            // of the assembled matrix alone leaves an error of order ε·κ
            // in the smooth components (ε(L/πh)⁴ relatively on a beam,
            // 5.7e-8 at 400 elements per 25 m), which a refined high mode
            // would pass on to the low ones through the orthogonalisation
            // below (measured: mode 1 of 500 at 400 elements, 4.5e-7).
            let shifted_product = |x: &[f64], y: &mut [f64]| {
                if let Some(apply) = stiffness {
                    let mut m_x = scratch.borrow_mut();
                    apply(x, y);
                    multiply(&self.mass, x, &mut m_x);
                    for (yi, mi) in y.iter_mut().zip(m_x.iter()) {
                        *yi -= shift * mi;
                    }
                }
            };
            let refine: Option<lanczos::Product<'_>> = stiffness.map(|_| &shifted_product as _);
            let mut solver = lanczos::RefinedSolve::new(&factor, refine, n);
            let k = b - a;
            let mut x = Mat::<f64>::zeros(n, k);
            for c in 0..k {
                let phi: Vec<f64> = vectors.col(a + c).iter().copied().collect();
                multiply(&self.mass, &phi, &mut column);
                solver.solve(&mut column, &mut workspace);
                multiply(&self.mass, &column, &mut product);
                let norm = column
                    .iter()
                    .zip(&product)
                    .map(|(u, v)| u * v)
                    .sum::<f64>()
                    .sqrt();
                if !(norm > 0.0 && norm.is_finite()) {
                    return Err(BridgeError::EigenFailed);
                }
                for i in 0..n {
                    x[(i, c)] = column[i] / norm;
                }
            }
            // Rayleigh–Ritz on span X: Xᵀ K X y = λ Xᵀ M X y.
            // K through the accurate product when there is one (a beam's
            // curvature form: the assembled K loses ε(L/πh)⁴ relatively).
            let assembled = |x: &[f64], y: &mut [f64]| multiply(&self.stiffness, x, y);
            let apply_stiffness: lanczos::Product<'_> = stiffness.unwrap_or(&assembled);
            let apply_mass = |x: &[f64], y: &mut [f64]| multiply(&self.mass, x, y);
            let mut projected_k = Mat::<f64>::zeros(k, k);
            let mut projected_m = Mat::<f64>::zeros(k, k);
            for (target, apply) in [
                (&mut projected_k, apply_stiffness),
                (&mut projected_m, &apply_mass as lanczos::Product<'_>),
            ] {
                for c in 0..k {
                    let xc: Vec<f64> = x.col(c).iter().copied().collect();
                    apply(&xc, &mut product);
                    for r in 0..k {
                        target[(r, c)] = x.col(r).iter().zip(&product).map(|(u, v)| u * v).sum();
                    }
                }
            }
            let (values, coefficients) = dense::lowest_forward_small(&projected_k, &projected_m)?;
            let refined = kernels::product(x.as_ref(), coefficients.as_ref(), Seq);
            for c in 0..k {
                eigenvalues[a + c] = values[c];
                vectors.col_mut(a + c).copy_from(refined.col(c));
            }
            refined_modes.extend(a..b);
        }
        if refined_modes.is_empty() {
            return Ok(());
        }
        // The other vectors' errors along the refined modes (what a close
        // neighbour's residual hardly shows, measured 1.5e-8 in φᵢᵀMφⱼ)
        // removed: φⱼ −= (φᵢᵀMφⱼ) φᵢ, i refined, j not. This corrects φⱼ,
        // since φᵢ is now the accurate one; the change to λⱼ is second
        // order. Cost O(n · count · refined).
        let mut m_refined = Mat::<f64>::zeros(n, refined_modes.len());
        for (c, &mode) in refined_modes.iter().enumerate() {
            let phi: Vec<f64> = vectors.col(mode).iter().copied().collect();
            multiply(&self.mass, &phi, &mut product);
            for i in 0..n {
                m_refined[(i, c)] = product[i];
            }
        }
        let mut is_refined = vec![false; count];
        for &mode in &refined_modes {
            is_refined[mode] = true;
        }
        for j in (0..count).filter(|&j| !is_refined[j]) {
            for (c, &i) in refined_modes.iter().enumerate() {
                let overlap: f64 = m_refined
                    .col(c)
                    .iter()
                    .zip(vectors.col(j).iter())
                    .map(|(u, v)| u * v)
                    .sum();
                for r in 0..n {
                    let correction = overlap * vectors[(r, i)];
                    vectors[(r, j)] -= correction;
                }
            }
        }
        // What mixing remains is between refined close neighbours (a
        // shift 10⁻⁷ below a mode divides the error along a neighbour 10⁻⁶
        // away only by 11; measured 9.3e-8 in φᵢᵀMφⱼ): removed by the
        // symmetric (Löwdin) orthonormalisation Φ G^{-1/2}, G = ΦᵀMΦ, the
        // smallest change that makes the set M-orthonormal. It mixes pairs
        // in proportion to their overlap, large only between close
        // neighbours, so a residual moves by about overlap × relative gap.
        // Cost O(n · count²) + O(count³).
        lowdin(&self.mass, vectors)
    }

    /// Refines the pairs whose energy residual misses a tenth of
    /// [`RESIDUAL_BOUND`] ([`Pencil::refine_shifted`]; K through
    /// `stiffness` when given, else the assembled matrix).
    ///
    /// Why: every formulation of [`Pencil::lowest_unverified`] works with
    /// the one shift σ = 0 (the inverse K⁻¹M), whose operator and projected
    /// problems are exact only to ε/λ₁ absolutely, so mode k keeps a
    /// relative error of about ε·λₖ/λ₁ in its eigenvalue and
    /// ε·λₖ/(λ₁·gap) in its vector, whatever the restart or block scheme
    /// (measured on a 25 m beam: 100 elements, mode 66 of the dense
    /// reduction at 1.9e-8, λ₆₆/λ₁ ≈ 2·10⁷; 200 elements, mode 44 of an
    /// 80-mode Lanczos at 2.0e-7). Shifted inverse iteration with a shift
    /// just below each such cluster is accurate relative to |λ − σ|
    /// instead of λ₁. A few passes, each only over what still misses.
    /// Cost: one solve per mode for the residuals, one LDLᵀ per cluster
    /// refined.
    pub(super) fn refine_inaccurate(
        &self,
        eigenvalues: &mut [f64],
        vectors: &mut Mat<f64>,
        stiffness: Option<lanczos::Product<'_>>,
    ) -> Result<(), BridgeError> {
        let assembled = |x: &[f64], y: &mut [f64]| multiply(&self.stiffness, x, y);
        let product: lanczos::Product<'_> = stiffness.unwrap_or(&assembled);
        let factor = self.stiffness_factor()?;
        let mut residuals = energy_residuals(product, &self.mass, factor, eigenvalues, vectors)?;
        let worst = |r: &[f64]| {
            r.iter().fold(
                0.0f64,
                |a, &b| if b.is_nan() { f64::INFINITY } else { a.max(b) },
            )
        };
        for _ in 0..REFINE_PASSES {
            if residuals.iter().all(|&r| r <= 0.1 * RESIDUAL_BOUND) {
                break;
            }
            // A pass is kept only if it leaves the worst residual lower:
            // on pencils whose lowest eigenvalue is tiny against the shift's
            // resolution (a 10 km span, EI = 1 N·m² on 10,000 elements, the
            // hostile corpus) the shifted solve loses the accurate low modes
            // (measured: mode 1 from below 1e-8 to 1.7e-3).
            let (kept_values, kept_vectors) = (eigenvalues.to_vec(), vectors.clone());
            let before = worst(&residuals);
            self.refine_shifted(eigenvalues, vectors, &residuals, stiffness)?;
            sort_pairs(eigenvalues, vectors);
            let refined = energy_residuals(product, &self.mass, factor, eigenvalues, vectors)?;
            // `worst` maps NaN to infinity, so the comparison is total.
            if worst(&refined) >= before {
                eigenvalues.copy_from_slice(&kept_values);
                *vectors = kept_vectors;
                break;
            }
            residuals = refined;
        }
        Ok(())
    }
}

/// The symmetric (Löwdin) M-orthonormalisation Φ ← Φ G^{-1/2}, G = ΦᵀMΦ:
/// the smallest change that makes the set M-orthonormal (Löwdin 1950). It
/// mixes pairs in proportion to their overlap. Cost O(n · count²) +
/// O(count³).
pub(super) fn lowdin(mass: &SymmetricSparse, vectors: &mut Mat<f64>) -> Result<(), BridgeError> {
    let (n, count) = (vectors.nrows(), vectors.ncols());
    let mut product = vec![0.0; n];
    let mut m_vectors = Mat::<f64>::zeros(n, count);
    for mode in 0..count {
        let phi: Vec<f64> = vectors.col(mode).iter().copied().collect();
        multiply(mass, &phi, &mut product);
        for i in 0..n {
            m_vectors[(i, mode)] = product[i];
        }
    }
    let gram = kernels::product(vectors.transpose(), m_vectors.as_ref(), Seq);
    let gram = Mat::from_fn(count, count, |i, j| 0.5 * (gram[(i, j)] + gram[(j, i)]));
    let (sigma, u) =
        kernels::symmetric_eigen(gram.as_ref(), Seq).ok_or(BridgeError::EigenFailed)?;
    if sigma.iter().any(|&v| !(v > 0.0 && v.is_finite())) {
        return Err(BridgeError::EigenFailed);
    }
    let scaled = Mat::from_fn(count, count, |i, j| u[(i, j)] / sigma[j].sqrt());
    let inverse_root = kernels::product(scaled.as_ref(), u.transpose(), Seq);
    *vectors = kernels::product(vectors.as_ref(), inverse_root.as_ref(), Seq);
    Ok(())
}

/// Puts the pairs in ascending order of λ (a refinement may move an
/// eigenvalue past a neighbour the first solve had misplaced). Stable, so
/// pairs in order stay bit for bit where they are.
pub(super) fn sort_pairs(eigenvalues: &mut [f64], vectors: &mut Mat<f64>) {
    if eigenvalues.windows(2).all(|w| w[0] <= w[1]) {
        return;
    }
    let mut order: Vec<usize> = (0..eigenvalues.len()).collect();
    order.sort_by(|&a, &b| eigenvalues[a].total_cmp(&eigenvalues[b]));
    let values: Vec<f64> = order.iter().map(|&j| eigenvalues[j]).collect();
    eigenvalues.copy_from_slice(&values);
    *vectors = Mat::from_fn(vectors.nrows(), order.len(), |i, j| vectors[(i, order[j])]);
}

/// Energy-norm relative residuals √(rᵀK⁻¹r / φᵀKφ), r = Kφ − λMφ, of
/// every pair (the figure [`super::verify`] checks), by the sparse products and
/// the factor of K. Cost O(count · nnz(L)).
pub(super) fn energy_residuals(
    stiffness: lanczos::Product<'_>,
    mass: &SymmetricSparse,
    factor: &Factor,
    eigenvalues: &[f64],
    vectors: &Mat<f64>,
) -> Result<Vec<f64>, BridgeError> {
    let n = vectors.nrows();
    let mut workspace = factor.workspace()?;
    let (mut k_phi, mut m_phi) = (vec![0.0; n], vec![0.0; n]);
    let (mut residual, mut flexible) = (vec![0.0; n], vec![0.0; n]);
    Ok(eigenvalues
        .iter()
        .enumerate()
        .map(|(mode, &lambda)| {
            let phi: Vec<f64> = vectors.col(mode).iter().copied().collect();
            stiffness(&phi, &mut k_phi);
            multiply(mass, &phi, &mut m_phi);
            for i in 0..n {
                residual[i] = k_phi[i] - lambda * m_phi[i];
            }
            flexible.copy_from_slice(&residual);
            factor.solve_in_place(&mut flexible, &mut workspace);
            let energy_r: f64 = residual.iter().zip(&flexible).map(|(a, b)| a * b).sum();
            let energy_phi: f64 = phi.iter().zip(&k_phi).map(|(a, b)| a * b).sum();
            (energy_r.abs() / energy_phi).sqrt()
        })
        .collect())
}

/// Index of the candidate whose worst residual is smallest (NaN loses;
/// ties go to the earlier one). Candidates are never mixed: vectors of
/// two solves are M-orthogonal only to their accuracy, and measured mixes
/// broke the 1e-8 orthonormality bound.
pub fn best_candidate(residuals: &[Vec<f64>]) -> usize {
    let worst = |r: &Vec<f64>| {
        r.iter().fold(
            0.0f64,
            |a, &b| if b.is_nan() { f64::INFINITY } else { a.max(b) },
        )
    };
    let mut best = 0;
    for c in 1..residuals.len() {
        if worst(&residuals[c]) < worst(&residuals[best]) {
            best = c;
        }
    }
    best
}
