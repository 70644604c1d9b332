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

/// Sets whose eliminations [`SharedWarmStart`] keeps at once.
const SHARED_SETS: usize = 8;

/// One contact set's elimination.
#[derive(Debug, Clone, Default)]
struct SetFactor {
    /// The contact set A.
    active: Vec<usize>,
    /// Whether M_AA was numerically nonsingular.
    regular: bool,
    /// Row exchanged with row c at column c.
    pivots: Vec<usize>,
    /// The eliminated M_AA: multipliers below the diagonal, U above.
    factors: Vec<f64>,
}

/// The warm start of [`solve_warm`] for many right-hand sides `q` with one
/// matrix `M` (the lanes of [`super::lockstep`]): the elimination of M_AA
/// for a contact set A is done once per set and replayed on each `q`, with
/// exactly the operations [`gauss_solve`] performs on its right-hand side,
/// so the result is bit-identical to [`solve_warm`]'s. Up to
/// [`SHARED_SETS`] sets are kept (lanes that separate differ in their
/// sets). Call [`Self::reset`] whenever `M` changes.
#[derive(Debug, Clone)]
pub struct SharedWarmStart {
    /// Whether `scale`, `finite` and the sets belong to the current `M`.
    valid: bool,
    /// max|Mᵢⱼ| (1 if M = 0), and whether M is finite.
    scale: f64,
    finite: bool,
    /// The eliminations of the current `M`: the first `used` are valid.
    sets: Vec<SetFactor>,
    used: usize,
    /// The slot the next new set replaces once all are used.
    next: usize,
    /// Scratch: this call's contact set and right-hand side.
    set: Vec<usize>,
    rhs: Vec<f64>,
}

impl SharedWarmStart {
    /// Storage for LCPs up to size `n`.
    pub fn new(n: usize) -> Self {
        Self {
            valid: false,
            scale: 1.0,
            finite: true,
            sets: (0..SHARED_SETS)
                .map(|_| SetFactor {
                    active: Vec::with_capacity(n),
                    regular: false,
                    pivots: vec![0; n],
                    factors: vec![0.0; n * n],
                })
                .collect(),
            used: 0,
            next: 0,
            set: Vec::with_capacity(n),
            rhs: vec![0.0; n],
        }
    }

    /// Forgets the eliminations: `M` is about to change.
    pub fn reset(&mut self) {
        self.valid = false;
        self.used = 0;
        self.next = 0;
    }

    /// [`solve_warm`] with the elimination of each contact set shared
    /// between calls of the same `m`.
    pub fn solve(
        &mut self,
        m: &[f64],
        q: &[f64],
        z: &mut [f64],
        work: &mut LcpWorkspace,
        previous: &[f64],
    ) -> Result<usize, LcpError> {
        let n = q.len();
        assert_eq!(m.len(), n * n, "lcp: m must be n×n row-major");
        assert_eq!(z.len(), n, "lcp: z must have length n");
        assert_eq!(previous.len(), n, "lcp: previous must have length n");
        if self.rhs.len() < n {
            // Larger than the size it was made for: grow once.
            self.rhs.resize(n, 0.0);
        }
        if !self.valid {
            self.valid = true;
            self.finite = m.iter().all(|x| x.is_finite());
            self.scale = match max_abs(m) {
                a if a > 0.0 => a,
                _ => 1.0,
            };
        }
        if !(self.finite && q.iter().all(|x| x.is_finite())) {
            return Err(LcpError::NonFinite);
        }
        if q.iter().any(|&v| v < 0.0) && previous.iter().any(|&v| v > 0.0) {
            self.set.clear();
            self.set.extend((0..n).filter(|&i| previous[i] > 0.0));
            let slot = match self.sets[..self.used]
                .iter()
                .position(|f| f.active == self.set)
            {
                Some(slot) => slot,
                None => {
                    let slot = if self.used < SHARED_SETS {
                        self.used += 1;
                        self.used - 1
                    } else {
                        let slot = self.next;
                        self.next = (self.next + 1) % SHARED_SETS;
                        slot
                    };
                    let factor = &mut self.sets[slot];
                    factor.active.clone_from(&self.set);
                    factor.eliminate(m, n);
                    slot
                }
            };
            let factor = &self.sets[slot];
            if factor.regular {
                let k = factor.active.len();
                let b = &mut self.rhs[..k];
                for (r, &i) in factor.active.iter().enumerate() {
                    b[r] = -q[i];
                }
                factor.replay(b);
                z.fill(0.0);
                for (r, &i) in factor.active.iter().enumerate() {
                    z[i] = b[r].max(0.0);
                }
                if violation(m, q, z, self.scale) <= ACCEPT_TOL {
                    return Ok(0);
                }
            }
        }
        solve(m, q, z, work)
    }
}

impl SetFactor {
    /// Eliminates M_AA as [`gauss_solve`] does, keeping the multipliers
    /// and the row exchanges.
    fn eliminate(&mut self, m: &[f64], n: usize) {
        let k = self.active.len();
        self.pivots.resize(k.max(self.pivots.len()), 0);
        self.factors.resize((k * k).max(self.factors.len()), 0.0);
        let a = &mut self.factors[..k * k];
        for (r, &i) in self.active.iter().enumerate() {
            for (c, &j) in self.active.iter().enumerate() {
                a[r * k + c] = m[i * n + j];
            }
        }
        self.regular = eliminate(a, k, &mut self.pivots);
    }

    /// `gauss_solve`'s operations on the right-hand side `b` (length |A|),
    /// which becomes the solution.
    fn replay(&self, b: &mut [f64]) {
        let k = b.len();
        substitute(&self.factors[..k * k], k, &self.pivots, b);
    }
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |acc: f64, x| acc.max(x.abs()))
}

/// Runs Lemke's method; on success the final basis is in `work.basis`, the tableau in `work.tab`.
fn lemke(
    m: &[f64],
    q: &[f64],
    n: usize,
    mu: f64,
    work: &mut LcpWorkspace,
) -> Result<usize, LcpError> {
    let w = 2 * n + 2;
    let z0 = 2 * n;
    let inv_mu = 1.0 / mu;
    for (i, row) in work.tab[..n * w].chunks_exact_mut(w).enumerate() {
        row.fill(0.0);
        row[i] = 1.0;
        for j in 0..n {
            row[n + j] = -m[i * n + j] * inv_mu;
        }
        row[z0] = -1.0;
        row[z0 + 1] = q[i] * inv_mu;
        work.basis[i] = i;
    }
    let qref = max_abs(q) * inv_mu;
    let limit = 50 * n + 100;
    // First pivot: z0 enters; its column is −d = −1, so every row blocks with aᵢ = dᵢ = 1.
    let mut entering = z0;
    let mut row =
        select_row(work, n, entering, -1.0, qref).ok_or(LcpError::NoSolution { size: n })?;
    let mut pivots = 0;
    loop {
        pivot(&mut work.tab, n, row, entering);
        pivots += 1;
        let leaving = std::mem::replace(&mut work.basis[row], entering);
        if leaving == z0 {
            return Ok(pivots);
        }
        if pivots >= limit {
            return Err(LcpError::PivotLimit { size: n, pivots });
        }
        entering = if leaving < n {
            leaving + n
        } else {
            leaving - n
        };
        row = select_row(work, n, entering, 1.0, qref).ok_or(LcpError::NoSolution { size: n })?;
    }
}

/// Lexicographic minimum-ratio test on column `col` (entries multiplied by `sign`).
/// Returns `None` if no entry is a positive pivot (secondary ray).
fn select_row(
    work: &mut LcpWorkspace,
    n: usize,
    col: usize,
    sign: f64,
    qref: f64,
) -> Option<usize> {
    let (tab, w) = (&work.tab, 2 * n + 2);
    let colmax = (0..n).fold(0.0, |acc: f64, i| acc.max(tab[i * w + col].abs()));
    let thr = PIVOT_TOL * colmax.max(1.0);
    let mut len = 0;
    for i in 0..n {
        let a = sign * tab[i * w + col];
        if a > thr {
            work.cand[len] = (i, a);
            len += 1;
        }
    }
    if len <= 1 {
        return (len == 1).then_some(work.cand[0].0);
    }
    // First component: the ratio q̄ᵢ / aᵢ itself.
    let vals = &mut work.vals;
    len = keep_minimal(tab, w, 2 * n + 1, &mut work.cand[..len], vals, qref);
    if let Some(&(i, _)) = work.cand[..len].iter().find(|c| work.basis[c.0] == 2 * n) {
        return Some(i); // z0 can leave: the next basis is a solution
    }
    // Then the rows of B⁻¹ (the w block), column by column.
    for k in 0..n {
        if len == 1 {
            break;
        }
        len = keep_minimal(tab, w, k, &mut work.cand[..len], vals, 1.0);
    }
    Some(work.cand[0].0)
}

/// Keeps in `cand` the rows `(i, aᵢ)` whose value `tab[i][k] / aᵢ` is within the tie tolerance
/// of the minimum; returns how many were kept (≥ 1).
fn keep_minimal(
    tab: &[f64],
    w: usize,
    k: usize,
    cand: &mut [(usize, f64)],
    vals: &mut [f64],
    reference: f64,
) -> usize {
    let mut min = f64::INFINITY;
    for (v, &(i, a)) in vals.iter_mut().zip(cand.iter()) {
        *v = tab[i * w + k] / a;
        min = min.min(*v);
    }
    let cut = min + TIE_TOL * (reference + min.abs());
    let mut kept = 0;
    for t in 0..cand.len() {
        if vals[t] <= cut {
            cand[kept] = cand[t];
            kept += 1;
        }
    }
    kept
}

/// Gauss–Jordan pivot of the tableau on row `r`, column `c`.
fn pivot(tab: &mut [f64], n: usize, r: usize, c: usize) {
    let w = 2 * n + 2;
    let (head, rest) = tab[..n * w].split_at_mut(r * w);
    let (prow, tail) = rest.split_at_mut(w);
    let inv = 1.0 / prow[c];
    prow.iter_mut().for_each(|x| *x *= inv);
    prow[c] = 1.0;
    for row in head.chunks_exact_mut(w).chain(tail.chunks_exact_mut(w)) {
        let f = row[c];
        if f != 0.0 {
            row.iter_mut()
                .zip(prow.iter())
                .for_each(|(x, &p)| *x -= f * p);
            row[c] = 0.0;
        }
    }
}

/// Reads `z` from the final tableau, tries the cleanup solve on the same basis and verifies.
fn finish(
    m: &[f64],
    q: &[f64],
    n: usize,
    mu: f64,
    z: &mut [f64],
    work: &mut LcpWorkspace,
) -> Result<(), LcpError> {
    let w = 2 * n + 2;
    let zl = &mut work.z_lemke[..n];
    zl.fill(0.0);
    let mut k = 0;
    for i in 0..n {
        let b = work.basis[i];
        if (n..2 * n).contains(&b) {
            zl[b - n] = work.tab[i * w + 2 * n + 1].max(0.0);
            work.active[k] = b - n;
            k += 1;
        }
    }
    // Cleanup: M_AA z_A = −q_A on the final basis; accepted whenever it verifies.
    let mut clean_viol = f64::INFINITY;
    z.fill(0.0);
    if k > 0 {
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
            for (r, &i) in act.iter().enumerate() {
                z[i] = b[r].max(0.0);
            }
            clean_viol = violation(m, q, z, mu);
        }
    }
    if clean_viol <= ACCEPT_TOL {
        return Ok(());
    }
    // Fallback: the (clamped) values read from the tableau.
    z.copy_from_slice(zl);
    let lemke_viol = violation(m, q, z, mu);
    if lemke_viol <= ACCEPT_TOL {
        Ok(())
    } else {
        let residual = lemke_viol.min(clean_viol);
        Err(LcpError::Inaccurate { size: n, residual })
    }
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

/// Solves `a x = b` in place (`a` row-major k×k, solution in `b`) by Gaussian elimination with
/// partial pivoting ([`eliminate`], then [`substitute`]; `pivots` holds k row exchanges).
/// Returns `false` if a pivot is below `1e-14 · max|a|` (numerically singular).
fn gauss_solve(a: &mut [f64], b: &mut [f64], k: usize, pivots: &mut [usize]) -> bool {
    if !eliminate(a, k, pivots) {
        return false;
    }
    substitute(a, k, pivots, b);
    true
}

/// Gaussian elimination with partial pivoting of `a` (row-major k×k) in place: U on and
/// above the diagonal, each column's multipliers below it, and in `pivots[c]` the row
/// exchanged with row c at column c. A row exchange moves columns c.. only, so the
/// multipliers of earlier columns stay with the rows they were made for, which is where
/// [`substitute`] meets them. Returns `false` if a pivot is below `1e-14 · max|a|`
/// (numerically singular). Cost k³/3 multiply-adds.
fn eliminate(a: &mut [f64], k: usize, pivots: &mut [usize]) -> bool {
    let tiny = 1e-14 * max_abs(&a[..k * k]);
    for c in 0..k {
        let mut p = c;
        for i in c + 1..k {
            if a[i * k + c].abs() > a[p * k + c].abs() {
                p = i;
            }
        }
        if a[p * k + c].abs() <= tiny {
            return false;
        }
        pivots[c] = p;
        if p != c {
            for j in c..k {
                a.swap(c * k + j, p * k + j);
            }
        }
        for i in c + 1..k {
            let f = a[i * k + c] / a[c * k + c];
            a[i * k + c] = f;
            if f != 0.0 {
                for j in c + 1..k {
                    a[i * k + j] -= f * a[c * k + j];
                }
            }
        }
    }
    true
}

/// Solves with an [`eliminate`]d `a`: the row exchanges and multipliers applied to `b` in
/// the order of the elimination, then back substitution; the solution replaces `b`. The
/// same operations on `b`, in the same order, as eliminating with `b` alongside. Cost k².
fn substitute(a: &[f64], k: usize, pivots: &[usize], b: &mut [f64]) {
    for c in 0..k {
        let p = pivots[c];
        if p != c {
            b.swap(c, p);
        }
        for i in c + 1..k {
            let f = a[i * k + c];
            if f != 0.0 {
                b[i] -= f * b[c];
            }
        }
    }
    for c in (0..k).rev() {
        let mut s = b[c];
        for j in c + 1..k {
            s -= a[c * k + j] * b[j];
        }
        b[c] = s / a[c * k + c];
    }
}

#[cfg(test)]
mod tests;
