//! Dense Gaussian elimination with partial pivoting for the small systems
//! of a contact set (the warm starts and Lemke's cleanup solve).

#![allow(clippy::needless_range_loop)]

use super::max_abs;

/// Solves `a x = b` in place (`a` row-major k×k, solution in `b`) by Gaussian elimination with
/// partial pivoting ([`eliminate`], then [`substitute`]; `pivots` holds k row exchanges).
/// Returns `false` if a pivot is below `1e-14 · max|a|` (numerically singular).
pub(super) fn gauss_solve(a: &mut [f64], b: &mut [f64], k: usize, pivots: &mut [usize]) -> bool {
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
pub(super) fn eliminate(a: &mut [f64], k: usize, pivots: &mut [usize]) -> bool {
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
pub(super) fn substitute(a: &[f64], k: usize, pivots: &[usize], b: &mut [f64]) {
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
