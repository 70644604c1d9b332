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
        if gauss_solve(a, b, k) {
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
/// partial pivoting. Returns `false` if a pivot is below `1e-14 · max|a|` (numerically singular).
fn gauss_solve(a: &mut [f64], b: &mut [f64], k: usize) -> bool {
    let tiny = 1e-14 * max_abs(a);
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
        if p != c {
            for j in c..k {
                a.swap(c * k + j, p * k + j);
            }
            b.swap(c, p);
        }
        for i in c + 1..k {
            let f = a[i * k + c] / a[c * k + c];
            if f != 0.0 {
                for j in c + 1..k {
                    a[i * k + j] -= f * a[c * k + j];
                }
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
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift64* PRNG: deterministic, no dependencies.
    struct Rng(u64);
    impl Rng {
        fn next_u64(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
        }
        fn unif(&mut self, a: f64, b: f64) -> f64 {
            a + (b - a) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
        }
        fn int(&mut self, k: usize) -> usize {
            (self.next_u64() % k as u64) as usize
        }
        fn vec(&mut self, len: usize, a: f64, b: f64) -> Vec<f64> {
            (0..len).map(|_| self.unif(a, b)).collect()
        }
    }

    /// Relative violation computed independently of the solver (no clamping):
    /// max(−zᵢ‖M‖, −sᵢ, min(|zᵢ|‖M‖, |sᵢ|)) / max(‖q‖∞, ‖M‖‖z‖∞), ‖M‖ = max|Mᵢⱼ|.
    fn rel_violation(m: &[f64], q: &[f64], z: &[f64]) -> f64 {
        let (n, mn) = (q.len(), max_abs(m).max(1e-300));
        let (mut v, mut sc) = (0.0f64, 0.0f64);
        for i in 0..n {
            let s: f64 = q[i] + (0..n).map(|j| m[i * n + j] * z[j]).sum::<f64>();
            v = v
                .max(-s)
                .max(-z[i] * mn)
                .max((z[i].abs() * mn).min(s.abs()));
            sc = sc.max(q[i].abs()).max(z[i].abs() * mn);
        }
        if sc > 0.0 { v / sc } else { v }
    }

    fn assert_valid(m: &[f64], q: &[f64], z: &[f64], tol: f64) {
        let v = rel_violation(m, q, z);
        assert!(
            z.iter().all(|&x| x >= 0.0) && v <= tol,
            "viol {v:e}\nM {m:?}\nq {q:?}\nz {z:?}"
        );
    }

    /// Gaussian elimination with partial pivoting on nested Vecs (independent of `gauss_solve`).
    fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
        let k = b.len();
        let amax = a.iter().flatten().fold(0.0f64, |x, y| x.max(y.abs()));
        for c in 0..k {
            let p = (c..k).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
            if a[p][c].abs() <= 1e-15 * amax {
                return None;
            }
            a.swap(c, p);
            b.swap(c, p);
            for i in c + 1..k {
                let f = a[i][c] / a[c][c];
                (c..k).for_each(|j| a[i][j] -= f * a[c][j]);
                b[i] -= f * b[c];
            }
        }
        for c in (0..k).rev() {
            b[c] = (b[c] - (c + 1..k).map(|j| a[c][j] * b[j]).sum::<f64>()) / a[c][c];
        }
        Some(b)
    }

    /// Enumerates all 2ⁿ complementary bases (M_AA z_A = −q_A); returns the z with the smallest
    /// violation and that violation.
    fn brute_force(m: &[f64], q: &[f64]) -> (Vec<f64>, f64) {
        let n = q.len();
        let mut best = (vec![0.0; n], f64::INFINITY);
        for mask in 0u32..(1 << n) {
            let act: Vec<usize> = (0..n).filter(|i| mask >> i & 1 == 1).collect();
            let a = act
                .iter()
                .map(|&i| act.iter().map(|&j| m[i * n + j]).collect())
                .collect();
            let Some(x) = dense_solve(a, act.iter().map(|&i| -q[i]).collect()) else {
                continue;
            };
            let mut z = vec![0.0; n];
            act.iter().zip(&x).for_each(|(&i, &v)| z[i] = v);
            let v = rel_violation(m, q, &z);
            if v < best.1 {
                best = (z, v);
            }
        }
        best
    }

    /// `B Bᵀ` for `b` of shape n×r (row-major).
    fn gram(b: &[f64], n: usize, r: usize) -> Vec<f64> {
        (0..n * n)
            .map(|ij| (0..r).map(|k| b[ij / n * r + k] * b[ij % n * r + k]).sum())
            .collect()
    }

    /// `q = s* − M z*`, so that (z*, s*) solves LCP(M, q) when z*, s* ≥ 0 are complementary.
    fn planted(m: &[f64], zs: &[f64], ss: &[f64]) -> Vec<f64> {
        let n = zs.len();
        (0..n)
            .map(|i| ss[i] - (0..n).map(|j| m[i * n + j] * zs[j]).sum::<f64>())
            .collect()
    }

    fn random_spd(rng: &mut Rng, n: usize) -> Vec<f64> {
        let mut m = gram(&rng.vec(n * n, -1.0, 1.0), n, n);
        let eps = rng.unif(0.01, 1.0);
        (0..n).for_each(|i| m[i * n + i] += eps);
        m
    }

    fn random_diag_dominant(rng: &mut Rng, n: usize) -> Vec<f64> {
        let mut m = rng.vec(n * n, -1.0, 1.0);
        for i in 0..n {
            let off: f64 = (0..n).filter(|&j| j != i).map(|j| m[i * n + j].abs()).sum();
            m[i * n + i] = off + rng.unif(0.1, 1.0);
        }
        m
    }

    /// Q Λ Qᵀ, Q random orthogonal (Gram–Schmidt twice), eigenvalues log-spaced in [1/cond, 1].
    fn random_ill_spd(rng: &mut Rng, n: usize, cond: f64) -> Vec<f64> {
        let mut qm = rng.vec(n * n, -1.0, 1.0);
        for _ in 0..2 {
            for c in 0..n {
                for p in 0..c {
                    let d: f64 = (0..n).map(|r| qm[r * n + c] * qm[r * n + p]).sum();
                    (0..n).for_each(|r| qm[r * n + c] -= d * qm[r * n + p]);
                }
                let nrm = (0..n).map(|r| qm[r * n + c].powi(2)).sum::<f64>().sqrt();
                (0..n).for_each(|r| qm[r * n + c] /= nrm);
            }
        }
        let lam = |k: usize| {
            if n == 1 {
                1.0
            } else {
                cond.powf(-(k as f64) / (n - 1) as f64)
            }
        };
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..=i {
                let v: f64 = (0..n).map(|k| qm[i * n + k] * lam(k) * qm[j * n + k]).sum();
                (m[i * n + j], m[j * n + i]) = (v, v);
            }
        }
        m
    }

    fn run(m: &[f64], q: &[f64]) -> (Result<usize, LcpError>, Vec<f64>) {
        let mut z = vec![f64::NAN; q.len()];
        let r = solve(m, q, &mut z, &mut LcpWorkspace::new(q.len()));
        (r, z)
    }

    /// Test 1: 3 840 random P-matrix LCPs (SPD AᵀA + εI, diagonally dominant nonsymmetric, SPD
    /// with condition number 1e8), n = 1..10, M and q scaled by random factors 1e±6, against
    /// brute-force enumeration (unique solution). Tolerance ‖z − z_ref‖∞ ≤ tol·‖z_ref‖∞ with
    /// tol = 1e-9 (well conditioned) or 1e-6 (cond 1e8: both sides carry cond·ε errors).
    #[test]
    fn matches_brute_force_on_p_matrices() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut ws = LcpWorkspace::new(4); // deliberately small: must grow
        let (mut cases, mut worst) = (0, [0.0f64; 3]);
        for family in 0..3 {
            for n in 1..=10 {
                for t in 0..if n <= 8 { 150 } else { 40 } {
                    let mut m = match family {
                        0 => random_spd(&mut rng, n),
                        1 => random_diag_dominant(&mut rng, n),
                        _ => random_ill_spd(&mut rng, n, 1e8),
                    };
                    let (sm, sq) = (
                        10f64.powf(rng.unif(-6.0, 6.0)),
                        10f64.powf(rng.unif(-6.0, 6.0)),
                    );
                    m.iter_mut().for_each(|x| *x *= sm);
                    // every fourth case: all wheels in contact (q < 0)
                    let hi = if t % 4 == 0 { -0.1 } else { 1.0 };
                    let q: Vec<f64> = rng.vec(n, -1.0, hi).iter().map(|x| x * sq).collect();
                    let (zref, v) = brute_force(&m, &q);
                    assert!(
                        v < 1e-7,
                        "brute force failed: family {family} n {n} viol {v}"
                    );
                    let mut z = vec![f64::NAN; n];
                    let piv = solve(&m, &q, &mut z, &mut ws)
                        .unwrap_or_else(|e| panic!("{family} {n}: {e}"));
                    assert!((1..=50 * n + 100).contains(&piv) || q.iter().all(|&x| x >= 0.0));
                    let diff: Vec<f64> = z.iter().zip(&zref).map(|(x, y)| x - y).collect();
                    let err = max_abs(&diff) / max_abs(&zref).max(1e-300);
                    let tol = if family == 2 { 1e-6 } else { 1e-9 };
                    assert!(
                        err <= tol,
                        "family {family} n {n} err {err:e}\nz {z:?}\nref {zref:?}"
                    );
                    assert_valid(&m, &q, &z, 1e-9);
                    worst[family] = worst[family].max(err);
                    cases += 1;
                }
            }
        }
        assert_eq!(cases, 3 * (8 * 150 + 2 * 40));
        eprintln!("brute-force cases: {cases}, worst relative error per family: {worst:?}");
    }

    /// Test 1b: SPD with condition numbers 1e8..1e12 is always solved, and thanks to the cleanup
    /// solve the result is backward stable (violation ≤ 2e-15; without cleanup it reaches 2e-14).
    #[test]
    fn ill_conditioned_spd_backward_stable() {
        let mut rng = Rng(5);
        for t in 0..4000 {
            let n = 1 + t % 10;
            let cond = 10f64.powf(rng.unif(8.0, 12.0));
            let (m, q) = (random_ill_spd(&mut rng, n, cond), rng.vec(n, -1.0, 1.0));
            let (r, z) = run(&m, &q);
            r.unwrap_or_else(|e| panic!("n {n}: {e}"));
            assert_valid(&m, &q, &z, 2e-15);
        }
    }

    /// Test 2a: 1 600 P-matrix LCPs with many zeros in q (z = 0, s = 0 ties); still unique.
    #[test]
    fn zeros_in_q_match_brute_force() {
        let mut rng = Rng(12345);
        for n in 1..=8 {
            for t in 0..200 {
                let m = if t % 2 == 0 {
                    random_spd(&mut rng, n)
                } else {
                    random_diag_dominant(&mut rng, n)
                };
                let q: Vec<f64> = (0..n)
                    .map(|_| [0.0, 0.0, -1.0, 1.0, -0.5][rng.int(5)])
                    .collect();
                let (zref, _) = brute_force(&m, &q);
                let (r, z) = run(&m, &q);
                r.unwrap();
                let diff: Vec<f64> = z.iter().zip(&zref).map(|(x, y)| x - y).collect();
                assert!(
                    max_abs(&diff) <= 1e-9 * max_abs(&zref).max(1.0),
                    "{m:?} {q:?}"
                );
                assert_valid(&m, &q, &z, 1e-9);
            }
        }
    }

    /// Test 2b: 3 000 degenerate monotone LCPs — PSD M = BBᵀ (rank r ≤ n, integer B), some with a
    /// skew-symmetric part, repeated rows/columns (identical wheels) or a zero row/column — with a
    /// planted degenerate integer solution (zᵢ = sᵢ = 0 for some i), so exact ratio ties occur.
    /// M is copositive-plus and the LCP feasible, so Lemke must return a valid solution.
    #[test]
    fn degenerate_psd_with_planted_solution() {
        let mut rng = Rng(777);
        let mut ties = 0;
        for case in 0..3000 {
            let n = 1 + rng.int(10);
            let r = 1 + rng.int(n);
            let b: Vec<f64> = (0..n * r).map(|_| rng.int(5) as f64 - 2.0).collect();
            let mut m = gram(&b, n, r);
            if case % 3 == 1 {
                for (i, j) in (0..n).flat_map(|i| (0..i).map(move |j| (i, j))) {
                    let s = rng.int(5) as f64 - 2.0; // skew part keeps xᵀMx ≥ 0
                    m[i * n + j] += s;
                    m[j * n + i] -= s;
                }
            }
            if case % 5 == 2 {
                let (i, j) = (rng.int(n), rng.int(n)); // wheel j := wheel i
                (0..n).for_each(|k| m[j * n + k] = m[i * n + k]);
                (0..n).for_each(|k| m[k * n + j] = m[k * n + i]);
            }
            if case % 7 == 3 {
                let i = rng.int(n); // zero row and column
                (0..n).for_each(|k| (m[i * n + k], m[k * n + i]) = (0.0, 0.0));
            }
            let pick = |rng: &mut Rng, x: usize| {
                if x == rng.int(3) {
                    1.0 + rng.int(3) as f64
                } else {
                    0.0
                }
            };
            let zs: Vec<f64> = (0..n).map(|_| pick(&mut rng, 0)).collect();
            let ss: Vec<f64> = zs
                .iter()
                .map(|&z| if z == 0.0 { pick(&mut rng, 1) } else { 0.0 })
                .collect();
            let q = planted(&m, &zs, &ss);
            let mut sorted = q.clone();
            sorted.sort_by(f64::total_cmp);
            ties += usize::from(sorted.windows(2).any(|w| w[0] == w[1] && w[0] < 0.0));
            let (res, z) = run(&m, &q);
            res.unwrap_or_else(|e| panic!("case {case}: {e}\nM {m:?}\nq {q:?}"));
            assert_valid(&m, &q, &z, 1e-9);
        }
        assert!(
            ties > 100,
            "too few tied initial ratios ({ties}) to exercise tie-breaking"
        );
    }

    /// Test 2c: hand-made degenerate cases, with exact answers and pivot counts where unique.
    #[test]
    fn degenerate_hand_cases() {
        let check = |m: &[f64], q: &[f64], expect: Option<&[f64]>, pivots: Option<usize>| {
            let (r, z) = run(m, q);
            let p = r.unwrap();
            assert_valid(m, q, &z, 1e-12);
            if let Some(e) = expect {
                assert!(
                    z.iter().zip(e).all(|(a, b)| (a - b).abs() <= 1e-12),
                    "{z:?} vs {e:?}"
                );
            }
            assert!(pivots.is_none_or(|pv| pv == p), "pivots {p} vs {pivots:?}");
            z
        };
        let eye3 = [1., 0., 0., 0., 1., 0., 0., 0., 1.];
        // Two / four identical wheels: any split of the total load is a solution.
        let z = check(&[1.0; 4], &[-1.0, -1.0], None, Some(2));
        assert!((z[0] + z[1] - 1.0).abs() < 1e-12);
        let z = check(&[1.0; 16], &[-2.0; 4], None, Some(2));
        assert!((z.iter().sum::<f64>() - 2.0).abs() < 1e-12);
        check(&eye3, &[-1.0; 3], Some(&[1.0; 3]), Some(4));
        check(&eye3, &[0.0, -1.0, 0.0], Some(&[0.0, 1.0, 0.0]), None);
        check(
            &[2.0, 1.0, 1.0, 2.0],
            &[-1.0, -1.0],
            Some(&[1.0 / 3.0; 2]),
            Some(3),
        );
        check(&[2.0, 1.0, 1.0, 2.0], &[0.0, 0.0], Some(&[0.0; 2]), Some(0));
        check(
            &[2.0, 1.0, 1.0, 2.0],
            &[-2.0, -1.0],
            Some(&[1.0, 0.0]),
            None,
        ); // z₂ = s₂ = 0
        check(&[0.0; 4], &[0.0, 1.0], Some(&[0.0; 2]), Some(0));
        check(&[0.0, 0.0, 0.0, 1.0], &[0.0, -1.0], Some(&[0.0, 1.0]), None); // zero row, q₁ = 0
        check(&[0.0, 0.0, 0.0, 1.0], &[2.0, -1.0], Some(&[0.0, 1.0]), None);
        check(&[4.0], &[-2.0], Some(&[0.5]), Some(2));
        check(&[], &[], Some(&[]), Some(0));
        // z0 ties with other rows; choosing z0 to leave ends after 3 pivots (5 otherwise).
        let m = [2.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1.0];
        check(&m, &[-3.0, -2.0, -1.0], Some(&[1.0, 1.0, 0.0]), Some(3));
    }

    /// Test 2d: 60 000 general integer matrices in {-1, 0, 1} with planted degenerate solutions.
    /// With plain smallest-index tie-breaking Lemke cycles on ~0.1% of these (the three 4×4 cases
    /// first are such); the lexicographic rule must never hit the pivot limit, and any solution it
    /// returns must be valid (M is not copositive-plus here, so a secondary ray is legitimate).
    #[test]
    fn lexicographic_rule_prevents_cycling() {
        #[rustfmt::skip]
        let mut cases: Vec<(Vec<f64>, Vec<f64>)> = vec![
            (vec![0., 1., 0., 0., 0., -1., 1., 1., 1., 1., -1., -1., -1., -1., 0., 0.], vec![-1., 1., -1., 1.]),
            (vec![0., 0., 1., 1., 1., 0., -1., 1., -1., -1., -1., -1., 0., -1., -1., -1.], vec![-1., -1., 1., 1.]),
            (vec![0., 0., 1., 0., 1., 0., 0., 0., -1., -1., 0., 1., 0., -1., 0., -1.], vec![-1., -1., 0., 1.]),
        ];
        let mut rng = Rng(31337);
        for _ in 0..60000 {
            let n = 2 + rng.int(6);
            let m: Vec<f64> = (0..n * n).map(|_| rng.int(3) as f64 - 1.0).collect();
            let zs: Vec<f64> = (0..n).map(|_| [1.0, 0.0, 0.0, 0.0][rng.int(4)]).collect();
            let ss: Vec<f64> = zs
                .iter()
                .map(|&z| {
                    if z == 0.0 {
                        [1.0, 0.0][rng.int(2)]
                    } else {
                        0.0
                    }
                })
                .collect();
            let q = planted(&m, &zs, &ss);
            cases.push((m, q));
        }
        let mut solved = 0;
        for (m, q) in &cases {
            match run(m, q) {
                (Ok(_), z) => {
                    assert_valid(m, q, &z, 1e-12);
                    solved += 1;
                }
                (Err(LcpError::NoSolution { .. }), _) => {}
                (Err(e), _) => panic!("M {m:?} q {q:?}: {e}"),
            }
        }
        assert!(solved > cases.len() / 2);
    }

    /// Test 3: infeasible problems give `NoSolution`, never a panic; non-finite input is rejected;
    /// a Lemke result that fails verification gives `Inaccurate`.
    #[test]
    fn no_solution_non_finite_inaccurate() {
        let no = |m: &[f64], q: &[f64]| {
            assert_eq!(run(m, q).0, Err(LcpError::NoSolution { size: q.len() }))
        };
        no(&[-1.0], &[-1.0]);
        no(&[0.0], &[-1.0]);
        no(&[0.0, 1.0, -1.0, 0.0], &[-1.0, -1.0]);
        no(&[1.0, -1.0, -1.0, 1.0], &[-1.0, -1.0]);
        let mut rng = Rng(4242);
        for _ in 0..500 {
            // M = −N with N ≥ 0 and q < 0: s = q − Nz < 0 for every z ≥ 0.
            let n = 1 + rng.int(8);
            no(&rng.vec(n * n, -1.0, 0.0), &rng.vec(n, -1.0, -0.01));
            // PSD M = BBᵀ with Bᵀ1 = 0 (so M1 = 0) and 1ᵀq < 0: then 1ᵀs = 1ᵀq < 0.
            let n = 2 + rng.int(7);
            let r = 1 + rng.int(n - 1);
            let mut b = rng.vec(n * r, -1.0, 1.0);
            for k in 0..r {
                let mean = (0..n).map(|i| b[i * r + k]).sum::<f64>() / n as f64;
                (0..n).for_each(|i| b[i * r + k] -= mean);
            }
            let mut q = rng.vec(n, -1.0, 1.0);
            let shift = (q.iter().sum::<f64>() + 0.5) / n as f64;
            q.iter_mut().for_each(|x| *x -= shift);
            no(&gram(&b, n, r), &q);
        }
        assert_eq!(run(&[f64::NAN], &[-1.0]).0, Err(LcpError::NonFinite));
        assert_eq!(run(&[1.0], &[f64::INFINITY]).0, Err(LcpError::NonFinite));
        assert_eq!(
            run(&[1.0, 0.0, 0.0, 1.0], &[1.0, f64::NAN]).0,
            Err(LcpError::NonFinite)
        );
        let msg = LcpError::NoSolution { size: 3 }.to_string();
        assert!(
            msg.contains("no solution") && msg.contains("size 3"),
            "{msg}"
        );
        // Verification: a final tableau claiming z = 5 for M = [0], q = [−1] (s = −1) is rejected.
        let mut ws = LcpWorkspace::new(1);
        (ws.basis[0], ws.tab[3]) = (1, 5.0);
        let r = finish(&[0.0], &[-1.0], 1, 1.0, &mut [0.0], &mut ws);
        assert!(
            matches!(r, Err(LcpError::Inaccurate { size: 1, residual }) if residual > 0.1),
            "{r:?}"
        );
    }

    /// Test 4: `solve` performs no heap allocation (counted per thread by a test allocator).
    mod alloc_free {
        use super::*;
        use std::alloc::{GlobalAlloc, Layout, System};
        use std::cell::Cell;

        thread_local!(static ALLOCS: Cell<usize> = const { Cell::new(0) });
        struct Counting;
        unsafe impl GlobalAlloc for Counting {
            unsafe fn alloc(&self, l: Layout) -> *mut u8 {
                let _ = ALLOCS.try_with(|c| c.set(c.get() + 1));
                unsafe { System.alloc(l) }
            }
            unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
                unsafe { System.dealloc(p, l) }
            }
        }
        #[global_allocator]
        static GLOBAL: Counting = Counting;

        #[test]
        fn solve_does_not_allocate() {
            let mut rng = Rng(99);
            let mut probs: Vec<(Vec<f64>, Vec<f64>)> = (1..=16)
                .map(|n| (random_spd(&mut rng, n), rng.vec(n, -1.0, 1.0)))
                .collect();
            probs.extend([
                (vec![-1.0], vec![-1.0]),
                (vec![f64::NAN], vec![-1.0]),
                (vec![1.0; 4], vec![-1.0; 2]),
            ]);
            let (mut ws, mut z) = (LcpWorkspace::new(16), vec![0.0; 16]);
            let before = ALLOCS.with(Cell::get);
            let mut pivots = 0;
            for _ in 0..10 {
                for (m, q) in &probs {
                    pivots += solve(m, q, &mut z[..q.len()], &mut ws).unwrap_or(0);
                }
            }
            assert_eq!(ALLOCS.with(Cell::get) - before, 0);
            assert!(pivots > 0);
            let v: Vec<u8> = std::hint::black_box(Vec::with_capacity(3)); // the counter does count
            assert!(ALLOCS.with(Cell::get) > before && v.capacity() >= 3);
        }
    }
}
