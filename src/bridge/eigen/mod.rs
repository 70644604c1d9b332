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

pub mod block;
pub mod cache;
mod checks;
pub mod dense;
pub mod kernels;
pub mod lanczos;
pub mod parallel;
mod refine;
pub mod sparse;

use faer::Mat;
use faer::Par::Seq;

pub use self::checks::{check_dense, verify};
use self::checks::{first_gap, inertia_check};
pub use self::refine::best_candidate;
use self::refine::energy_residuals;
use self::sparse::{Factor, SymmetricSparse, multiply, shifted};
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
    /// The parallelism of the solve ([`Pencil::with_parallelism`]).
    par: faer::Par,
}

impl Clone for Pencil {
    fn clone(&self) -> Self {
        Self::new(self.stiffness.clone(), self.mass.clone()).with_parallelism(self.par)
    }
}

impl Pencil {
    /// A pencil of two symmetric sparse matrices of the same order.
    pub fn new(stiffness: SymmetricSparse, mass: SymmetricSparse) -> Self {
        Self {
            stiffness,
            mass,
            stiffness_factor: std::sync::OnceLock::new(),
            par: faer::Par::Seq,
        }
    }

    /// The pencil with the eigen solve's parallelism set to `par`
    /// (sequential by default): `Par::Rayon(t)` lets the n × k work of a
    /// solve use t threads of the current rayon pool. The result is
    /// bit-identical whatever `par` is: the work is split into parts fixed
    /// by the sizes alone and combined in a fixed order ([`parallel`]),
    /// never as a scheduler happens to run it.
    pub fn with_parallelism(mut self, par: faer::Par) -> Self {
        self.par = par;
        self
    }

    /// The parallelism of the eigen solve.
    pub fn parallelism(&self) -> faer::Par {
        self.par
    }

    /// Order n.
    pub fn order(&self) -> usize {
        self.stiffness.nrows()
    }

    /// The factorisation of K, positive definite (a supported bridge).
    pub fn stiffness_factor(&self) -> Result<&Factor, BridgeError> {
        let factor = self.stiffness_factor.get_or_init(|| {
            let _t = crate::timings::stage(|| "factor K".into());
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
                    let overlaps = kernels::product_col(lower.transpose(), vectors.col(k), Seq);
                    let correction = kernels::product_col(
                        vectors.as_ref().subcols(0, k),
                        overlaps.as_ref(),
                        Seq,
                    );
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

    /// Number of eigenvalues below `eigenvalue` (rad²/s²): the negative
    /// pivots of LDLᵀ(K − λM). Cost one sparse factorisation.
    pub fn count_below(&self, eigenvalue: f64) -> Result<usize, BridgeError> {
        if eigenvalue <= 0.0 {
            return Ok(0);
        }
        let _t = crate::timings::stage(|| "inertia count (K - sigma M factored)".into());
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
    /// the figures in `pairs.check`. The modes are checked on the threads
    /// the pencil's parallelism allows, with the same figures whatever
    /// their number.
    pub fn verify(
        &self,
        pairs: &mut Eigenpairs,
        stiffness: impl Fn(&[f64], &mut [f64]) + Sync,
    ) -> Result<(), BridgeError> {
        let factor = self.stiffness_factor()?;
        let _t = crate::timings::stage(|| "verify the modes".into());
        let (largest_residual, largest_plain_residual, orthonormality_error) =
            checks::verify_parallel(
                &stiffness,
                &self.mass,
                factor,
                &pairs.eigenvalues,
                &pairs.vectors,
                self.par,
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
                let polish = |vectors| {
                    lanczos::polish_block(&self.mass, &self.stiffness, factor, vectors, self.par)
                };
                let once = polish(&unpolished.1)?;
                let twice = polish(&once.1)?;
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
                // A large assembled pencil: block Lanczos (matrix–matrix
                // re-orthogonalisation, multi-right-hand-side solves;
                // [`block`]), the single-vector run where it declines.
                let blocked = if stiffness.is_none() && n > DENSE_SHARE_LIMIT {
                    let _t = crate::timings::stage(|| format!("block Lanczos, {want} wanted"));
                    block::lowest(&self.mass, factor, want, self.par)?
                } else {
                    None
                };
                let ritz = match blocked {
                    Some((_, ritz)) => ritz,
                    None => lanczos::lowest(&self.mass, factor, 0.0, want, stiffness)?.1,
                };
                match stiffness {
                    // An accurate product (a beam): per-vector polish with
                    // refined solves and Rayleigh quotients through it.
                    Some(_) => lanczos::polish(&self.mass, factor, stiffness, product, &ritz)?,
                    // The assembled matrices are all there is: block
                    // Rayleigh–Ritz, by matrix products.
                    None => {
                        let _t = crate::timings::stage(|| "block Rayleigh-Ritz polish".into());
                        lanczos::polish_block(&self.mass, &self.stiffness, factor, &ritz, self.par)?
                    }
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
