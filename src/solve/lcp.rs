//! Lemke's complementary pivoting method for small dense linear complementarity problems.
//!
//! # Problem
//! LCP(M, q): given `M ∈ ℝⁿˣⁿ` (row-major) and `q ∈ ℝⁿ`, find `z ∈ ℝⁿ` with
//! `z ≥ 0`, `s = M z + q ≥ 0` and `zᵢ sᵢ = 0` for every `i`. In vbi `z` are the wheel
//! contact forces and `s` the contact gaps; `n` is the number of wheels (≤ ~16).
//!
//! # Method
//! * If `q ≥ 0`, `z = 0` is a solution and is returned at once (0 pivots).
//! * Otherwise Lemke's method runs on the augmented system `w − M z − d z₀ = q`, `w, z, z₀ ≥ 0`,
//!   `wᵢ zᵢ = 0`, with the **covering vector `d = 1`** (all ones). Any `d > 0` is valid; `d = 1`
//!   is the classical choice: it needs no knowledge of `M`, and it makes the first pivot
//!   (`z₀` enters) leave on the row of the most negative `qᵢ`, so that `z₀ = −minᵢ qᵢ`.
//! * The tableau is kept dense, `n × (2n+2)`, columns `[w | z | z₀ | rhs]`, and holds
//!   `B⁻¹ [I, −M, −d, q]` for the current basis `B`. The initial basis is `w` (matrix `I`), so
//!   the `w` block of the tableau *is* `B⁻¹`, which the lexicographic rule below needs.
//! * Each step the complement of the variable that just left enters; a minimum-ratio test picks
//!   the leaving row; a Gauss–Jordan pivot updates the tableau. Lemke stops when `z₀` leaves
//!   (solution) or when the entering column has no positive entry (secondary ray →
//!   [`LcpError::NoSolution`]). For copositive-plus `M` (e.g. every positive semidefinite `M`,
//!   symmetric or not) a secondary ray proves that the LCP is infeasible; for a P-matrix (e.g.
//!   symmetric positive definite) the solution exists, is unique, and Lemke always finds it.
//!
//! # Tie-breaking: lexicographic minimum ratio
//! Among the rows `i` whose entering-column entry `aᵢ` is positive, the leaving row minimises the
//! vector `(q̄ᵢ, (B⁻¹)ᵢ₁, …, (B⁻¹)ᵢₙ) / aᵢ` lexicographically. Since `B⁻¹` is nonsingular the
//! minimiser is unique, every basic solution stays lexicographically positive, no basis can
//! repeat, and Lemke terminates in finitely many pivots even on degenerate problems — the
//! standard anti-cycling rule (Cottle, Pang & Stone, *The Linear Complementarity Problem*, 1992,
//! §4.4). The first pivot uses the same rule with `aᵢ = dᵢ = 1`. One refinement: if the row of
//! `z₀` is among the minimum-ratio rows, it is chosen, which ends the method at a solution.
//!
//! # Tolerances (all relative)
//! Rows are divided by `μ = max|Mᵢⱼ|` (1 if `M = 0`), which leaves `z` unchanged and puts the
//! `z` block of the tableau on the same O(1) scale as the `w` block.
//! * Pivot: `aᵢ` counts as positive only if `aᵢ > 1e-14 · max(1, maxₖ|aₖ|)` ([`PIVOT_TOL`]).
//!   Entries below it are treated as zero, so an SPD `M` whose condition number approaches
//!   ~1e13 may be reported as [`LcpError::NoSolution`] (tested to always solve up to 1e12).
//! * Ties: two ratios (per lexicographic component) are equal if they differ by at most
//!   `1e-11 · (r + |min|)`, where `r = max|q|/μ` for the `q̄` column and `r = 1` for `B⁻¹`
//!   columns ([`TIE_TOL`]).
//! * Acceptance: with `s = Mz + q`, `viol = maxᵢ max(−sᵢ, −μzᵢ, min(μ|zᵢ|, |sᵢ|))` must satisfy
//!   `viol ≤ 1e-9 · max(‖q‖∞, μ‖z‖∞)` ([`ACCEPT_TOL`]), else [`LcpError::Inaccurate`].
//!
//! After Lemke, negative round-off in `z` is clamped to 0, then a *cleanup* solve is made on the
//! final basis: with `A` the set of basic `zᵢ`, `M_AA z_A = −q_A` is solved by Gaussian
//! elimination with partial pivoting (`M_AA` is nonsingular for any Lemke basis). This removes the
//! round-off accumulated in the tableau and is backward stable; it is returned whenever it passes
//! the acceptance test, otherwise the clamped tableau values are returned if they pass.
//!
//! # Cost
//! One pivot costs `n(2n+2)` multiply-adds, i.e. O(n²). Typically Lemke needs about `|A| + 1`
//! pivots (`n + 1` when every wheel ends in contact); the worst case is exponential, the limit is
//! `50n + 100` ([`LcpError::PivotLimit`]). The cleanup costs O(|A|³) plus one or two O(n²)
//! residual evaluations. `solve` allocates nothing unless `n` exceeds the size the workspace was
//! created for (it then grows once). Measured on random SPD problems (release build, loaded
//! 2-core machine): about 0.06–0.1, 0.12–0.2, 0.23–0.45 and 0.65–1.3 µs per solve for
//! n = 1, 2, 4 and 8.
#![allow(clippy::needless_range_loop)]

mod dense;
mod lemke;
mod shared;

use dense::gauss_solve;
use lemke::{finish, lemke};
pub use shared::SharedWarmStart;

/// Relative threshold for an entering-column entry to count as a positive pivot.
pub const PIVOT_TOL: f64 = 1e-14;
/// Relative tolerance under which two ratios of the ratio test count as tied.
pub const TIE_TOL: f64 = 1e-11;
/// Relative violation of feasibility/complementarity accepted for the returned `z`.
pub const ACCEPT_TOL: f64 = 1e-9;

/// Reusable storage for LCPs up to a given size; `solve` allocates nothing.
///
/// Holds the `n × (2n+2)` tableau, the basis, ratio-test scratch and the cleanup system, i.e.
/// about `3n² + 9n` words. If `solve` gets a larger `n`, the workspace is replaced by a larger one
/// (the only allocation `solve` can make).
#[derive(Debug, Clone)]
pub struct LcpWorkspace {
    cap: usize,
    tab: Vec<f64>,           // n × (2n+2) tableau [w | z | z0 | rhs]
    basis: Vec<usize>,       // basic variable of each row: w_j = j, z_j = n + j, z0 = 2n
    cand: Vec<(usize, f64)>, // candidate rows of the ratio test with their pivot entry
    vals: Vec<f64>,          // one lexicographic component of the candidates
    active: Vec<usize>,      // indices j with z_j basic at the end
    mat: Vec<f64>,           // |A| × |A| cleanup matrix
    rhs: Vec<f64>,           // cleanup right-hand side / solution
    pivots: Vec<usize>,      // cleanup row exchanges
    z_lemke: Vec<f64>,       // z read from the final tableau
}

impl LcpWorkspace {
    /// Workspace for LCPs with `n ≤ max_size`.
    pub fn new(max_size: usize) -> Self {
        let n = max_size;
        Self {
            cap: n,
            tab: vec![0.0; n * (2 * n + 2)],
            basis: vec![0; n],
            cand: vec![(0, 0.0); n],
            vals: vec![0.0; n],
            active: vec![0; n],
            mat: vec![0.0; n * n],
            rhs: vec![0.0; n],
            pivots: vec![0; n],
            z_lemke: vec![0.0; n],
        }
    }

    /// Largest `n` this workspace serves without growing.
    pub fn max_size(&self) -> usize {
        self.cap
    }
}

/// Why [`solve`] produced no solution (`size` is n, the number of contacts).
#[allow(missing_docs)]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LcpError {
    /// Lemke's method terminated on a secondary ray: the LCP has no solution (M is not
    /// copositive-plus-solvable for this q).
    #[error(
        "LCP of size {size} has no solution: Lemke's method ended on a secondary ray \
         (for copositive-plus M, e.g. positive semidefinite, no z ≥ 0 with Mz + q ≥ 0 exists; \
         for other M, Lemke's method cannot solve this instance)"
    )]
    NoSolution { size: usize },
    /// Pivot limit reached (cycling).
    #[error("LCP of size {size}: Lemke's method hit its pivot limit of {pivots} pivots (cycling)")]
    PivotLimit { size: usize, pivots: usize },
    /// Non-finite input.
    #[error("LCP input is not finite: M or q contains NaN or infinity")]
    NonFinite,
    /// Lemke ended at a basis whose solution violates feasibility/complementarity by more than
    /// [`ACCEPT_TOL`] relative to the problem scale (numerically too ill-conditioned).
    #[error(
        "LCP of size {size}: Lemke's result violates feasibility/complementarity by {residual:e} \
         relative to the problem scale (numerically too ill-conditioned)"
    )]
    Inaccurate { size: usize, residual: f64 },
}

/// Solves LCP(M, q); `m` row-major n×n, `q` length n; writes λ into `z` (len n). Returns the
/// number of pivots.
///
/// `n = q.len()`; panics if `m.len() != n²` or `z.len() != n`. On error `z` holds zeros or a
/// partial result and must not be used.
pub fn solve(
    m: &[f64],
    q: &[f64],
    z: &mut [f64],
    work: &mut LcpWorkspace,
) -> Result<usize, LcpError> {
    let n = q.len();
    assert_eq!(
        m.len(),
        n * n,
        "lcp::solve: m must be n×n row-major, n = q.len()"
    );
    assert_eq!(z.len(), n, "lcp::solve: z must have length n = q.len()");
    if !m.iter().chain(q).all(|x| x.is_finite()) {
        return Err(LcpError::NonFinite);
    }
    z.fill(0.0);
    if q.iter().all(|&v| v >= 0.0) {
        return Ok(0);
    }
    if n > work.cap {
        *work = LcpWorkspace::new(n);
    }
    let mu = match max_abs(m) {
        a if a > 0.0 => a,
        _ => 1.0,
    };
    let pivots = lemke(m, q, n, mu, work)?;
    finish(m, q, n, mu, z, work)?;
    Ok(pivots)
}

/// Solves LCP(M, q) like [`solve`], trying first the contact set of a
/// previous solution `previous` (the indices with `previous[i] > 0`): the
/// system M_AA z_A = −q_A of that set is solved by Gaussian elimination
/// (O(|A|³/3), the same cleanup solve [`solve`] ends with) and accepted if
/// it passes the same acceptance test (feasibility and complementarity to
/// [`ACCEPT_TOL`]), which makes it the LCP's solution (unique for a
/// P-matrix, e.g. the SPD contact compliance). Otherwise, or when the set
/// is empty, Lemke runs from scratch. Between time steps the contact set
/// rarely changes, so a step costs one |A|-sized solve and one O(n²)
/// residual instead of |A| + 1 Lemke pivots of O(n²) each. Returns the
/// number of Lemke pivots (0 when the previous set was accepted).
pub fn solve_warm(
    m: &[f64],
    q: &[f64],
    z: &mut [f64],
    work: &mut LcpWorkspace,
    previous: &[f64],
) -> Result<usize, LcpError> {
    let n = q.len();
    assert_eq!(m.len(), n * n, "lcp::solve_warm: m must be n×n row-major");
    assert_eq!(z.len(), n, "lcp::solve_warm: z must have length n");
    assert_eq!(
        previous.len(),
        n,
        "lcp::solve_warm: previous must have length n"
    );
    if !m.iter().chain(q).all(|x| x.is_finite()) {
        return Err(LcpError::NonFinite);
    }
    if q.iter().any(|&v| v < 0.0) && previous.iter().any(|&v| v > 0.0) {
        if n > work.cap {
            *work = LcpWorkspace::new(n);
        }
        let mut k = 0;
        for (i, &p) in previous.iter().enumerate() {
            if p > 0.0 {
                work.active[k] = i;
                k += 1;
            }
        }
        let act = &work.active[..k];
        let a = &mut work.mat[..k * k];
        let b = &mut work.rhs[..k];
        for (r, &i) in act.iter().enumerate() {
            for (c, &j) in act.iter().enumerate() {
                a[r * k + c] = m[i * n + j];
            }
            b[r] = -q[i];
        }
        if gauss_solve(a, b, k, &mut work.pivots) {
            z.fill(0.0);
            for (r, &i) in act.iter().enumerate() {
                z[i] = b[r].max(0.0);
            }
            let mu = match max_abs(m) {
                a if a > 0.0 => a,
                _ => 1.0,
            };
            if violation(m, q, z, mu) <= ACCEPT_TOL {
                return Ok(0);
            }
        }
    }
    solve(m, q, z, work)
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |acc: f64, x| acc.max(x.abs()))
}

/// Relative violation `maxᵢ max(−sᵢ, −μzᵢ, min(μ|zᵢ|, |sᵢ|)) / max(‖q‖∞, μ‖z‖∞)` of `z`.
fn violation(m: &[f64], q: &[f64], z: &[f64], mu: f64) -> f64 {
    let n = q.len();
    let (mut viol, mut scale) = (0.0f64, 0.0f64);
    for i in 0..n {
        let s = q[i]
            + m[i * n..(i + 1) * n]
                .iter()
                .zip(z)
                .map(|(a, b)| a * b)
                .sum::<f64>();
        let zi = z[i] * mu;
        if !(s.is_finite() && zi.is_finite()) {
            return f64::INFINITY;
        }
        viol = viol.max(-s).max(-zi).max(zi.abs().min(s.abs()));
        scale = scale.max(q[i].abs()).max(zi.abs());
    }
    if scale > 0.0 { viol / scale } else { 0.0 }
}

#[cfg(test)]
mod tests;
