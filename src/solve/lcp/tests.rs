//! Unit tests of the parent module.

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

/// Warm start: on 600 random SPD LCPs (n = 1..32, planted solutions with
/// random contact sets) `solve_warm` returns a valid solution equal to
/// Lemke's (1e-9 of ‖z‖∞; the P-matrix LCP has one solution) whatever the
/// guess: the right contact set (0 pivots: accepted without Lemke), a
/// wrong one, none, or everything (these fall back to Lemke unless they
/// happen to verify).
#[test]
fn warm_start_agrees_with_lemke() {
    let mut rng = Rng(0x5151_2026_1123_0011);
    let mut ws = LcpWorkspace::new(2);
    for case in 0..600 {
        let n = 1 + case % 32;
        let m = random_spd(&mut rng, n);
        let active: Vec<bool> = (0..n).map(|_| rng.unif(0.0, 1.0) < 0.6).collect();
        let zs: Vec<f64> = active
            .iter()
            .map(|&a| if a { rng.unif(0.1, 2.0) } else { 0.0 })
            .collect();
        let ss: Vec<f64> = active
            .iter()
            .map(|&a| if a { 0.0 } else { rng.unif(0.1, 2.0) })
            .collect();
        let q = planted(&m, &zs, &ss);
        let (reference, z_ref) = run(&m, &q);
        reference.expect("Lemke solves an SPD LCP");
        let wrong: Vec<f64> = active.iter().map(|&a| if a { 0.0 } else { 1.0 }).collect();
        for (label, guess) in [
            ("right", zs.clone()),
            ("wrong", wrong),
            ("none", vec![0.0; n]),
            ("all", vec![1.0; n]),
        ] {
            let mut z = vec![f64::NAN; n];
            let pivots = solve_warm(&m, &q, &mut z, &mut ws, &guess).expect("solves");
            if label == "right" && active.iter().any(|&a| a) {
                assert_eq!(pivots, 0, "case {case}: the right set needs no pivot");
            }
            assert_valid(&m, &q, &z, 1e-9);
            let scale = z_ref.iter().fold(1e-300f64, |a, v| a.max(v.abs()));
            for (a, b) in z.iter().zip(&z_ref) {
                assert!(
                    (a - b).abs() <= 1e-9 * scale,
                    "case {case} ({label}): {a} against {b}"
                );
            }
        }
    }
}

/// The shared warm start is `solve_warm`, bit for bit: 300 matrices
/// (SPD, nonsymmetric diagonally dominant — which makes the elimination
/// exchange rows — and a singular one), each solved for 12 right-hand
/// sides whose guesses cycle through more contact sets than the shared
/// start keeps (so sets are evicted and eliminated again), against
/// `solve_warm` on each alone: the same forces to the last bit and the
/// same pivot counts, errors alike.
#[test]
fn shared_warm_start_is_solve_warm_bit_for_bit() {
    let mut rng = Rng(0x5151_2026_1126_0001);
    let mut alone = LcpWorkspace::new(2);
    let mut shared_work = LcpWorkspace::new(2);
    let mut shared = SharedWarmStart::new(1);
    let mut exchanges = 0;
    for case in 0..300 {
        let n = 1 + case % 9;
        let mut m = match case % 3 {
            0 => random_spd(&mut rng, n),
            _ => random_diag_dominant(&mut rng, n),
        };
        if case % 3 == 1 {
            // Small diagonal, large off-diagonal first column: partial
            // pivoting must exchange rows.
            for i in 0..n {
                m[i * n] *= 10.0 * (i + 1) as f64;
            }
            exchanges += 1;
        }
        if case % 50 == 7 && n > 1 {
            // A singular matrix: two equal rows and columns.
            for j in 0..n {
                m[n + j] = m[j];
            }
            for i in 0..n {
                m[i * n + 1] = m[i * n];
            }
        }
        shared.reset();
        for rhs in 0..12 {
            let q = rng.vec(n, -1.0, 0.5);
            let guess: Vec<f64> = (0..n)
                .map(|i| if (rhs * 7 + i * 3) % 5 < 3 { 1.0 } else { 0.0 })
                .collect();
            let (mut z_alone, mut z_shared) = (vec![f64::NAN; n], vec![f64::NAN; n]);
            let a = solve_warm(&m, &q, &mut z_alone, &mut alone, &guess);
            let b = shared.solve(&m, &q, &mut z_shared, &mut shared_work, &guess);
            assert_eq!(a, b, "case {case}, right-hand side {rhs}");
            if a.is_ok() {
                let bits = |z: &[f64]| z.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&z_alone), bits(&z_shared), "case {case}, rhs {rhs}");
            }
        }
    }
    assert!(exchanges > 0);
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
                let piv =
                    solve(&m, &q, &mut z, &mut ws).unwrap_or_else(|e| panic!("{family} {n}: {e}"));
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
    let no =
        |m: &[f64], q: &[f64]| assert_eq!(run(m, q).0, Err(LcpError::NoSolution { size: q.len() }));
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
