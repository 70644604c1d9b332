//! The one eigen path of every bridge: the lowest modes of K φ = λ M φ
//! (λ = ω², rad²/s²), each checked before anyone uses it.
//!
//! Large sparse models go through shift-invert Lanczos on an LDLᵀ
//! factorisation ([`lanczos`], [`sparse`]); small ones (order ≤
//! [`DENSE_LIMIT`]) through the dense inverted reduction ([`dense`]), which
//! is faster there and as accurate for the low modes. Both formulations work
//! with the inverse operator, so the lowest eigenvalues keep full relative
//! accuracy whatever the spread of the spectrum (a forward reduction loses
//! them to ε·λ_max once a mesh is fine, the defect this design removes).
//!
//! Every returned mode passes three checks, or the solve is an error:
//! - residual in the energy norm, ‖r‖_{K⁻¹} / ‖Kφ‖_{K⁻¹} ≤ [`RESIDUAL_BOUND`]
//!   with r = Kφ − λMφ and ‖r‖²_{K⁻¹} = rᵀK⁻¹r (so ‖Kφ‖_{K⁻¹} = √λ). For an
//!   eigenvalue off by δλ it equals |δλ|/λ, the relative error a user cares
//!   about, and it is immune to the round-off of the stored vector: the
//!   plain Euclidean ratio ‖r‖/‖Kφ‖ of even the exactly rounded eigenvector
//!   is ε·λ_max/λ (the mesh's condition, ~10¹² on a fine beam), so it cannot
//!   certify anything there. The plain ratio is still reported;
//! - M-orthonormality max|ΦᵀMΦ − I| ≤ [`ORTHONORMALITY_BOUND`];
//! - completeness: the LDLᵀ inertia of K − σM at σ in the gap above the last
//!   returned eigenvalue counts exactly the modes returned (Sturm sequence
//!   property), so no mode in the range is missing.

pub mod cache;
pub mod dense;
pub mod lanczos;
pub mod sparse;

use faer::Mat;

use self::sparse::{Factor, SymmetricSparse, multiply, shifted, symmetric_from_entries};
use super::BridgeError;

/// Largest accepted relative residual ‖Kφ − λMφ‖_{K⁻¹}/‖Kφ‖_{K⁻¹} of a
/// returned mode (module doc).
pub const RESIDUAL_BOUND: f64 = 1e-8;
/// Largest accepted deviation of ΦᵀMΦ from the identity.
pub const ORTHONORMALITY_BOUND: f64 = 1e-8;
/// Orders up to which the dense inverted reduction is used.
pub const DENSE_LIMIT: usize = 200;
/// Orders up to which the dense reduction is also used for an assembled
/// pencil (an imported model) when the modes asked for are a large share
/// of the order ([`DENSE_SHARE`]): a Krylov
/// space that spans most of the pencil gains nothing over the dense solve
/// and loses accuracy (measured: 804 of the 1,584 modes of a generated
/// two-span viaduct, mode 3's residual 1.0e-5 by Lanczos; the dense solve
/// of that order takes about a second and 160 MB).
pub const DENSE_SHARE_LIMIT: usize = 4000;
/// The share of the order above which [`DENSE_SHARE_LIMIT`] applies.
pub const DENSE_SHARE: f64 = 0.25;
/// Relative gap below which neighbours are refined together by
/// [`Pencil::refine_shifted`].
const REFINE_CLUSTER_GAP: f64 = 1e-6;
/// Most passes of [`Pencil::refine_shifted`].
const REFINE_PASSES: usize = 6;
/// Relative distance of [`Pencil::refine_shifted`]'s shift below its
/// cluster.
const REFINE_SHIFT: f64 = 1e-7;
/// Relative gap below which two eigenvalues count as one cluster (a cut never
/// separates them for the completeness check).
const CLUSTER_GAP: f64 = 1e-9;

/// How a set of modes was verified.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeCheck {
    /// Largest relative residual in the energy norm over the returned modes
    /// (the checked one).
    pub largest_residual: f64,
    /// Largest plain relative residual ‖Kφ − λMφ‖/‖Kφ‖ (reported only: it
    /// is bounded below by ε·λ_max/λ on fine meshes).
    pub largest_plain_residual: f64,
    /// Largest |ΦᵀMΦ − I| entry.
    pub orthonormality_error: f64,
    /// Shift σ (rad²/s²) of the inertia count and the count found there
    /// (`None` when every mode of the model was returned).
    pub inertia: Option<(f64, usize)>,
    /// Whether the dense path was used (else shift-invert Lanczos).
    pub dense: bool,
}

/// Lowest eigenpairs: λ ascending (rad²/s²), M-normalised vectors as columns.
#[derive(Debug, Clone)]
pub struct Eigenpairs {
    /// λ = ω², rad²/s², ascending.
    pub eigenvalues: Vec<f64>,
    /// φ (n × count), φᵀMφ = 1.
    pub vectors: Mat<f64>,
    /// The checks they passed.
    pub check: ModeCheck,
}

/// A symmetric pencil (K, M), stiffness positive definite on the free DOFs,
/// mass positive definite.
#[derive(Debug)]
pub struct Pencil {
    /// Stiffness, N/m (N·m/rad for rotations).
    pub stiffness: SymmetricSparse,
    /// Mass, kg (kg·m² for rotations).
    pub mass: SymmetricSparse,
    /// LDLᵀ of K, made on first use (static solves and the Lanczos operator).
    stiffness_factor: std::sync::OnceLock<Result<Factor, BridgeError>>,
}

impl Clone for Pencil {
    fn clone(&self) -> Self {
        Self::new(self.stiffness.clone(), self.mass.clone())
    }
}

impl Pencil {
    /// A pencil of two symmetric sparse matrices of the same order.
    pub fn new(stiffness: SymmetricSparse, mass: SymmetricSparse) -> Self {
        Self {
            stiffness,
            mass,
            stiffness_factor: std::sync::OnceLock::new(),
        }
    }

    /// Order n.
    pub fn order(&self) -> usize {
        self.stiffness.nrows()
    }

    /// The factorisation of K, positive definite (a supported bridge).
    pub fn stiffness_factor(&self) -> Result<&Factor, BridgeError> {
        let factor = self.stiffness_factor.get_or_init(|| {
            let factor = Factor::new(&self.stiffness).map_err(|e| match e {
                BridgeError::SingularShift => BridgeError::StiffnessNotPositive,
                other => other,
            })?;
            if factor.negative_pivots() > 0 {
                return Err(BridgeError::StiffnessNotPositive);
            }
            Ok(factor)
        });
        factor.as_ref().map_err(Clone::clone)
    }

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
    fn refine_shifted(
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
            let refined = &x * &coefficients;
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

    /// The lowest `want` pairs by the dense reductions: the inverted one
    /// ([`dense::lowest_inverted`]) keeps each λₖ to about ε·λₖ/λ₁
    /// relatively, the forward one ([`dense::every_forward`]) to about
    /// ε·λₙ/λₖ, so the modes above the crossover λₖ > √(λ₁λₙ) are taken
    /// from the forward one (measured: the top of a 200-element beam's
    /// spectrum, relative gaps of 1.8e-4 against the inverted reduction's
    /// ε·λₙ/λ₁ ≈ 9e-6, left residuals of 7.5e-3 that shifted inverse
    /// iteration could not repair). Vectors of two solves are M-orthogonal
    /// only to their accuracy, so the forward ones are orthogonalised
    /// against the lower ones. Requests below the crossover are unchanged.
    fn dense_two_sided(&self, want: usize) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
        let (stiffness, mass) = (self.stiffness.to_dense(), self.mass.to_dense());
        let (mut values, all) = dense::lowest_inverted(&stiffness, &mass)?;
        let n = values.len();
        let crossover = (values[0] * values[n - 1]).sqrt();
        let mut vectors = all.subcols(0, want).to_owned();
        drop(all);
        values.truncate(want);
        if values[want - 1] <= crossover {
            return Ok((values, vectors));
        }
        let (forward_values, forward) = dense::every_forward(&stiffness, &mass)?;
        let first = (0..want)
            .find(|&k| forward_values[k] > crossover)
            .unwrap_or(want);
        // Each forward vector M-orthogonalised against every lower one
        // (twice, classical Gram–Schmidt), lowest first, so the correction
        // goes into the higher mode: an overlap δ moved into mode k costs
        // its residual about δ·√(λₖ/λⱼ), which a low mode j's own residual
        // bounds (its error along mode k is below η_j·√(λⱼ/λₖ)), while the
        // reverse would put δ·√(λₖ/λⱼ) into the low mode (measured with a
        // symmetric orthonormalisation: mode 1 of 500 on a 400-element
        // beam at 2.2e-2 before refinement).
        let mut m_phi = vec![0.0; n];
        let mut m_vectors = Mat::<f64>::zeros(n, want);
        for k in 0..want {
            if k >= first {
                values[k] = forward_values[k];
                vectors.col_mut(k).copy_from(forward.col(k));
                for _pass in 0..2 {
                    let lower = m_vectors.as_ref().subcols(0, k);
                    let overlaps = lower.transpose() * vectors.col(k);
                    let correction = vectors.as_ref().subcols(0, k) * &overlaps;
                    for i in 0..n {
                        vectors[(i, k)] -= correction[i];
                    }
                }
                let phi: Vec<f64> = vectors.col(k).iter().copied().collect();
                multiply(&self.mass, &phi, &mut m_phi);
                let norm = phi
                    .iter()
                    .zip(&m_phi)
                    .map(|(a, b)| a * b)
                    .sum::<f64>()
                    .sqrt();
                if !(norm > 0.0 && norm.is_finite()) {
                    return Err(BridgeError::EigenFailed);
                }
                for i in 0..n {
                    vectors[(i, k)] /= norm;
                }
            }
            let phi: Vec<f64> = vectors.col(k).iter().copied().collect();
            multiply(&self.mass, &phi, &mut m_phi);
            for i in 0..n {
                m_vectors[(i, k)] = m_phi[i];
            }
        }
        Ok((values, vectors))
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
    fn refine_inaccurate(
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

    /// Number of eigenvalues below `eigenvalue` (rad²/s²): the negative
    /// pivots of LDLᵀ(K − λM). Cost one sparse factorisation.
    pub fn count_below(&self, eigenvalue: f64) -> Result<usize, BridgeError> {
        if eigenvalue <= 0.0 {
            return Ok(0);
        }
        let matrix = shifted(&self.stiffness, &self.mass, eigenvalue)?;
        Ok(Factor::new(&matrix)?.negative_pivots())
    }

    /// The lowest `count` modes, checked (module doc), residuals through
    /// the assembled K.
    pub fn lowest(&self, count: usize) -> Result<Eigenpairs, BridgeError> {
        let mut pairs = self.lowest_unverified(count, None)?;
        let assembled = |x: &[f64], y: &mut [f64]| multiply(&self.stiffness, x, y);
        match self.verify(&mut pairs, assembled) {
            // A large pencil is refined only when its check fails (small
            // ones were refined already: [`Pencil::lowest_unverified`]).
            Err(BridgeError::ModeCheckFailed { .. }) if self.order() > DENSE_SHARE_LIMIT => {
                self.refine_inaccurate(&mut pairs.eigenvalues, &mut pairs.vectors, None)?;
                self.verify(&mut pairs, assembled)?;
            }
            checked => checked?,
        }
        Ok(pairs)
    }

    /// Checks `pairs` (module doc) with `stiffness` applying K (a model may
    /// offer a more accurate form than the assembled matrix) and records
    /// the figures in `pairs.check`.
    pub fn verify(
        &self,
        pairs: &mut Eigenpairs,
        stiffness: impl Fn(&[f64], &mut [f64]),
    ) -> Result<(), BridgeError> {
        let factor = self.stiffness_factor()?;
        let mut workspace = factor.workspace()?;
        let (largest_residual, largest_plain_residual, orthonormality_error) = verify(
            stiffness,
            |x, y| multiply(&self.mass, x, y),
            |x| factor.solve_in_place(x, &mut workspace),
            &pairs.eigenvalues,
            &pairs.vectors,
        )?;
        pairs.check.largest_residual = largest_residual;
        pairs.check.largest_plain_residual = largest_plain_residual;
        pairs.check.orthonormality_error = orthonormality_error;
        Ok(())
    }

    /// The lowest `count` modes with the inertia (completeness) check done
    /// but not yet the residual and orthonormality checks
    /// ([`Pencil::verify`]); their figures are NaN until then. `stiffness`,
    /// an accurate product with K, turns on iterative refinement of every
    /// solve ([`lanczos::lowest`]).
    pub fn lowest_unverified(
        &self,
        count: usize,
        stiffness: Option<lanczos::Product<'_>>,
    ) -> Result<Eigenpairs, BridgeError> {
        let n = self.order();
        if count > n || n == 0 || count == 0 {
            return Err(BridgeError::TooManyModes {
                requested: count.max(1),
                available: n,
            });
        }
        // The share rule applies to beams too: a Lanczos run that nearly
        // exhausts the space loses its last vectors to round-off (measured:
        // all 399 modes of a 200-element beam, one Ritz value twice, the
        // Sturm count one short), while the dense solve's inaccurate modes
        // (assembled K, the single shift) are refined against the accurate
        // product ([`Pencil::refine_inaccurate`]).
        let dense = n <= DENSE_LIMIT
            || (n <= DENSE_SHARE_LIMIT && (count + 4) as f64 >= DENSE_SHARE * n as f64);
        let assembled = |x: &[f64], y: &mut [f64]| multiply(&self.stiffness, x, y);
        let product: lanczos::Product<'_> = stiffness.unwrap_or(&assembled);
        // Solve a few more than asked, so the cut can sit in a clear gap.
        let mut extra = 4;
        loop {
            let want = (count + extra).min(n);
            let (mut eigenvalues, mut vectors) = if dense && n > DENSE_LIMIT {
                // A large share of a mid-sized pencil: dense, then polished
                // like Lanczos' Ritz vectors (the dense reduction's highest
                // modes keep only ε/λ₁ absolute accuracy; measured: mode 581
                // of 690 on a 1,404-DOF generated viaduct, energy residual
                // 1.03e-8 unpolished). Each pass divides a vector's error
                // along a higher mode j by λⱼ/λ, but its projected problem
                // adds round-off of its own at the top of the block
                // (measured: 1,132 of the 1,584 modes of the generated
                // two-span viaduct, mode 1,036: 4.3e-10 unpolished, 1.4e-8
                // after two passes). So the one of the three (unpolished,
                // once, twice) with the smallest worst residual is kept
                // ([`best_candidate`]); what still misses the bound is
                // refined below.
                let unpolished = self.dense_two_sided(want)?;
                let factor = self.stiffness_factor()?;
                faer::set_global_parallelism(faer::Par::Seq);
                let once =
                    lanczos::polish_block(&self.mass, &self.stiffness, factor, &unpolished.1)?;
                let twice = lanczos::polish_block(&self.mass, &self.stiffness, factor, &once.1)?;
                let mut candidates = vec![unpolished, once, twice];
                let residuals = candidates
                    .iter()
                    .map(|(values, vectors)| {
                        energy_residuals(&assembled, &self.mass, factor, values, vectors)
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                candidates.swap_remove(best_candidate(&residuals))
            } else if dense {
                self.dense_two_sided(want)?
            } else {
                let factor = self.stiffness_factor()?;
                if stiffness.is_none() {
                    // The dense k × k work (tridiagonal and Rayleigh–Ritz
                    // eigen problems, Cholesky) runs sequentially, as the
                    // dense path's does, so the result does not depend on
                    // the thread count.
                    faer::set_global_parallelism(faer::Par::Seq);
                }
                let (_, ritz) = lanczos::lowest(&self.mass, factor, 0.0, want, stiffness)?;
                match stiffness {
                    // An accurate product (a beam): per-vector polish with
                    // refined solves and Rayleigh quotients through it.
                    Some(_) => lanczos::polish(&self.mass, factor, stiffness, product, &ritz)?,
                    // The assembled matrices are all there is: block
                    // Rayleigh–Ritz, by matrix products.
                    None => lanczos::polish_block(&self.mass, &self.stiffness, factor, &ritz)?,
                }
            };
            // Cheap where a factorisation is (small pencils, beams); a
            // large import is refined only if its check fails
            // ([`Pencil::lowest`]), since the residuals cost a solve per mode.
            if n <= DENSE_SHARE_LIMIT || stiffness.is_some() {
                self.refine_inaccurate(&mut eigenvalues, &mut vectors, stiffness)?;
            }
            let Some(gap) = first_gap(&eigenvalues, count, eigenvalues.len() == n) else {
                extra *= 2;
                continue;
            };
            let inertia = inertia_check(gap, &eigenvalues, count, |shift| self.count_below(shift))?;
            return Ok(Eigenpairs {
                eigenvalues: eigenvalues[..count].to_vec(),
                vectors: vectors.subcols(0, count).to_owned(),
                check: ModeCheck {
                    largest_residual: f64::NAN,
                    largest_plain_residual: f64::NAN,
                    orthonormality_error: f64::NAN,
                    inertia,
                    dense,
                },
            });
        }
    }
}

/// The symmetric (Löwdin) M-orthonormalisation Φ ← Φ G^{-1/2}, G = ΦᵀMΦ:
/// the smallest change that makes the set M-orthonormal (Löwdin 1950). It
/// mixes pairs in proportion to their overlap. Cost O(n · count²) +
/// O(count³).
fn lowdin(mass: &SymmetricSparse, vectors: &mut Mat<f64>) -> Result<(), BridgeError> {
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
    let gram = vectors.transpose() * &m_vectors;
    let gram = Mat::from_fn(count, count, |i, j| 0.5 * (gram[(i, j)] + gram[(j, i)]));
    let eig = gram
        .self_adjoint_eigen(faer::Side::Lower)
        .map_err(|_| BridgeError::EigenFailed)?;
    let (u, sigma) = (eig.U(), eig.S().column_vector());
    if sigma.iter().any(|&v| !(v > 0.0 && v.is_finite())) {
        return Err(BridgeError::EigenFailed);
    }
    let scaled = Mat::from_fn(count, count, |i, j| u[(i, j)] / sigma[j].sqrt());
    let inverse_root = &scaled * u.transpose();
    *vectors = &*vectors * &inverse_root;
    Ok(())
}

/// Puts the pairs in ascending order of λ (a refinement may move an
/// eigenvalue past a neighbour the first solve had misplaced). Stable, so
/// pairs in order stay bit for bit where they are.
fn sort_pairs(eigenvalues: &mut [f64], vectors: &mut Mat<f64>) {
    if eigenvalues.windows(2).all(|w| w[0] <= w[1]) {
        return;
    }
    let mut order: Vec<usize> = (0..eigenvalues.len()).collect();
    order.sort_by(|&a, &b| eigenvalues[a].total_cmp(&eigenvalues[b]));
    let values: Vec<f64> = order.iter().map(|&j| eigenvalues[j]).collect();
    eigenvalues.copy_from_slice(&values);
    *vectors = Mat::from_fn(vectors.nrows(), order.len(), |i, j| vectors[(i, order[j])]);
}

/// Where the completeness check cuts the spectrum.
enum Gap {
    /// At σ (rad²/s²), strictly between two eigenvalues.
    Between(f64),
    /// Every mode of the model was found: nothing to count.
    All,
}

/// The completeness check: at a shift in the gap, the inertia count
/// (`count_below`) must equal the number of eigenvalues solved below it;
/// returns (shift, count), or `None` when every mode was solved.
fn inertia_check(
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

/// Energy-norm relative residuals √(rᵀK⁻¹r / φᵀKφ), r = Kφ − λMφ, of
/// every pair (the figure [`verify`] checks), by the sparse products and
/// the factor of K. Cost O(count · nnz(L)).
fn energy_residuals(
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
fn first_gap(eigenvalues: &[f64], count: usize, complete: bool) -> Option<Gap> {
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
    let mut k_phi = vec![0.0; n];
    let mut m_vectors = Mat::<f64>::zeros(n, count);
    let mut m_phi = vec![0.0; n];
    let mut residual = vec![0.0; n];
    let mut flexible = vec![0.0; n];
    let mut largest_residual = 0.0f64;
    let mut largest_plain_residual = 0.0f64;
    for (mode, &lambda) in eigenvalues.iter().enumerate() {
        let phi: Vec<f64> = vectors.col(mode).iter().copied().collect();
        stiffness(&phi, &mut k_phi);
        mass(&phi, &mut m_phi);
        let norm_k: f64 = k_phi.iter().map(|v| v * v).sum::<f64>().sqrt();
        for i in 0..n {
            residual[i] = k_phi[i] - lambda * m_phi[i];
        }
        let plain = residual.iter().map(|v| v * v).sum::<f64>().sqrt() / norm_k;
        // ‖r‖²_{K⁻¹} = rᵀK⁻¹r; ‖Kφ‖²_{K⁻¹} = φᵀKφ.
        flexible.copy_from_slice(&residual);
        solve_stiffness(&mut flexible);
        let energy_r: f64 = residual.iter().zip(&flexible).map(|(a, b)| a * b).sum();
        let energy_phi: f64 = phi.iter().zip(&k_phi).map(|(a, b)| a * b).sum();
        let relative = (energy_r.abs() / energy_phi).sqrt();
        let accepted = lambda > 0.0 && lambda.is_finite() && relative <= RESIDUAL_BOUND;
        if !accepted {
            return Err(BridgeError::ModeCheckFailed {
                mode: mode + 1,
                what: "relative residual ‖Kφ − ω²Mφ‖/‖Kφ‖ in the energy norm",
                value: relative,
                bound: RESIDUAL_BOUND,
            });
        }
        largest_residual = largest_residual.max(relative);
        largest_plain_residual = largest_plain_residual.max(plain);
        for i in 0..n {
            m_vectors[(i, mode)] = m_phi[i];
        }
    }
    let gram = vectors.transpose() * &m_vectors;
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
    Ok((
        largest_residual,
        largest_plain_residual,
        orthonormality_error,
    ))
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
    let stiffness_llt = stiffness
        .llt(faer::Side::Lower)
        .map_err(|_| BridgeError::StiffnessNotPositive)?;
    let (largest_residual, largest_plain_residual, orthonormality_error) = verify(
        |x, y| dense_multiply(stiffness, x, y),
        |x, y| dense_multiply(mass, x, y),
        |x| {
            use faer::linalg::solvers::Solve;
            let len = x.len();
            stiffness_llt.solve_in_place(faer::MatMut::from_column_major_slice_mut(x, len, 1));
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
