//! Lemke's complementary pivoting on the dense tableau (see the parent
//! module's doc): the pivoting itself, the lexicographic leaving-row rule
//! and the final cleanup solve on the solution's basis.

#![allow(clippy::needless_range_loop)]

use super::dense::gauss_solve;
use super::{ACCEPT_TOL, LcpError, LcpWorkspace, PIVOT_TOL, TIE_TOL, max_abs, violation};

/// Runs Lemke's method; on success the final basis is in `work.basis`, the tableau in `work.tab`.
pub(super) fn lemke(
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
pub(super) fn select_row(
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
pub(super) fn keep_minimal(
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
pub(super) fn pivot(tab: &mut [f64], n: usize, r: usize, c: usize) {
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
pub(super) fn finish(
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
