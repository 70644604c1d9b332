//! Small dense kernels for the per-step contact systems (a few wheels), on
//! caller-provided storage so the time loop allocates nothing.

/// Solves A x = b in place for a symmetric positive definite `n`×`n` matrix
/// stored row-major in `a` (overwritten by its Cholesky factor) and `b`
/// (overwritten by x). Returns false if A is not positive definite.
/// Cost n³/6 multiply–adds.
pub fn cholesky_solve(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    for j in 0..n {
        let mut diag = a[j * n + j];
        for k in 0..j {
            diag -= a[j * n + k] * a[j * n + k];
        }
        if diag.is_nan() || diag <= 0.0 {
            return false;
        }
        let diag = diag.sqrt();
        a[j * n + j] = diag;
        for i in j + 1..n {
            let mut s = a[i * n + j];
            for k in 0..j {
                s -= a[i * n + k] * a[j * n + k];
            }
            a[i * n + j] = s / diag;
        }
    }
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= a[i * n + k] * b[k];
        }
        b[i] = s / a[i * n + i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= a[k * n + i] * b[k];
        }
        b[i] = s / a[i * n + i];
    }
    true
}

/// Solves A x = b in place for a general `n`×`n` matrix stored row-major in
/// `a` (overwritten by its LU factors) by Gaussian elimination with partial
/// pivoting; `b` is overwritten by x. Returns false if A is singular to
/// working precision. Cost n³/3 multiply–adds.
pub fn lu_solve(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..n {
        let pivot_row = (k..n)
            .max_by(|&i, &j| a[i * n + k].abs().total_cmp(&a[j * n + k].abs()))
            .unwrap_or(k);
        let pivot = a[pivot_row * n + k];
        if pivot.is_nan() || pivot.abs() <= scale * 1e-14 {
            return false;
        }
        if pivot_row != k {
            for j in 0..n {
                a.swap(k * n + j, pivot_row * n + j);
            }
            b.swap(k, pivot_row);
        }
        for i in k + 1..n {
            let factor = a[i * n + k] / pivot;
            a[i * n + k] = factor;
            for j in k + 1..n {
                a[i * n + j] -= factor * a[k * n + j];
            }
            b[i] -= factor * b[k];
        }
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for j in i + 1..n {
            s -= a[i * n + j] * b[j];
        }
        b[i] = s / a[i * n + i];
    }
    true
}

/// Factors a general `n`×`n` matrix stored row-major in `a` in place into
/// L U with partial pivoting (row `k` swapped with `pivots[k]`), for
/// several right-hand sides ([`lu_apply`]). Returns false if A is singular
/// to working precision. Cost n³/3 multiply–adds.
pub fn lu_factor(a: &mut [f64], pivots: &mut [usize], n: usize) -> bool {
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..n {
        let pivot_row = (k..n)
            .max_by(|&i, &j| a[i * n + k].abs().total_cmp(&a[j * n + k].abs()))
            .unwrap_or(k);
        pivots[k] = pivot_row;
        let pivot = a[pivot_row * n + k];
        if pivot.is_nan() || pivot.abs() <= scale * 1e-14 {
            return false;
        }
        if pivot_row != k {
            for j in 0..n {
                a.swap(k * n + j, pivot_row * n + j);
            }
        }
        for i in k + 1..n {
            let factor = a[i * n + k] / pivot;
            a[i * n + k] = factor;
            for j in k + 1..n {
                a[i * n + j] -= factor * a[k * n + j];
            }
        }
    }
    true
}

/// Solves A x = b in place with the factors of [`lu_factor`]; `b` is
/// overwritten by x. Cost n² multiply–adds; the same arithmetic as
/// [`lu_solve`], so the answers agree bit for bit.
pub fn lu_apply(a: &[f64], pivots: &[usize], b: &mut [f64], n: usize) {
    // P b first: every later swap also moved the multipliers stored below
    // the diagonal, so L is that of P A = L U.
    for k in 0..n {
        if pivots[k] != k {
            b.swap(k, pivots[k]);
        }
    }
    for k in 0..n {
        for i in k + 1..n {
            b[i] -= a[i * n + k] * b[k];
        }
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for j in i + 1..n {
            s -= a[i * n + j] * b[j];
        }
        b[i] = s / a[i * n + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_spd_system_and_rejects_indefinite() {
        // A = [[4, 2, 0], [2, 5, 1], [0, 1, 3]], x = [1, -2, 3] → b = A x.
        let mut a = [4.0, 2.0, 0.0, 2.0, 5.0, 1.0, 0.0, 1.0, 3.0];
        let mut b = [0.0, -5.0, 7.0];
        assert!(cholesky_solve(&mut a, &mut b, 3));
        for (x, e) in b.iter().zip([1.0, -2.0, 3.0]) {
            assert!((x - e).abs() < 1e-14);
        }
        let mut a = [1.0, 2.0, 2.0, 1.0];
        let mut b = [1.0, 1.0];
        assert!(!cholesky_solve(&mut a, &mut b, 2));
    }

    /// Factor once, solve twice: the same bits as `lu_solve` on each.
    #[test]
    fn factored_solves_equal_the_one_shot_solve() {
        let a = vec![0.0, 2.0, 1.0, 3.0, 1.0, -1.0, 1.0, 4.0, 5.0];
        let mut factors = a.clone();
        let mut pivots = [0; 3];
        assert!(lu_factor(&mut factors, &mut pivots, 3));
        for b in [[1.0, 2.0, 3.0], [-0.5, 7.0, 0.25]] {
            let (mut x, mut y, mut m) = (b, b, a.clone());
            assert!(lu_solve(&mut m, &mut x, 3));
            lu_apply(&factors, &pivots, &mut y, 3);
            assert_eq!(x, y);
        }
    }

    #[test]
    fn lu_solves_nonsymmetric_system_needing_pivoting() {
        // A = [[0, 2, 1], [1, 1, 0], [3, 0, 1]], x = [1, 2, -1].
        let mut a = [0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let mut b = [3.0, 3.0, 2.0];
        assert!(lu_solve(&mut a, &mut b, 3));
        for (x, e) in b.iter().zip([1.0, 2.0, -1.0]) {
            assert!((x - e).abs() < 1e-14);
        }
        let mut a = [1.0, 2.0, 2.0, 4.0];
        let mut b = [1.0, 1.0];
        assert!(!lu_solve(&mut a, &mut b, 2));
    }
}
