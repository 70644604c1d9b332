//! Verification of the Rayleigh–Ritz plate deck (`vbi::bridge::plate`):
//! natural frequencies against closed forms, the continuous beam and an
//! independent conforming plate finite-element model
//! (tests/it/support/plate_fe.rs); static influence lines against the beam and
//! Maxwell's reciprocity; and the consistency of the fast line evaluation.
//! Each test states where its reference comes from and its tolerance.

use crate::support::plate_fe;

use std::f64::consts::PI;

use nalgebra::DMatrix;
use plate_fe::BfsPlate;
use vbi::bridge::beam::BeamModel;
use vbi::bridge::plate::PlateModes;
use vbi::scenario::resolved::{Beam, Damping, Modes, Plate, PlateEdges, Rigidity, Terms};

/// The paper's three spans (Section 3.2), m.
const SPANS: [f64; 3] = [24.0, 30.0, 24.0];
/// The paper's deck width (Section 3.2), m.
const WIDTH: f64 = 13.715;

fn no_modes() -> Modes {
    Modes {
        count: None,
        max_frequency: None,
        static_correction: true,
    }
}

/// A plate description with the given geometry, material and basis.
#[allow(clippy::too_many_arguments)]
fn plate(
    spans: &[f64],
    width: f64,
    thickness: Option<f64>,
    mass_per_area: f64,
    rigidity: Rigidity,
    edges: PlateEdges,
    (longitudinal, transverse): (usize, usize),
) -> Plate {
    Plate {
        spans: spans.to_vec(),
        width,
        thickness,
        mass_per_area,
        rigidity,
        edges,
        terms: Terms {
            longitudinal,
            transverse,
        },
        elements_per_span: 20,
        modes: no_modes(),
        damping: Damping::Modal { ratio: 0.0 },
        girder_lines: Vec::new(),
    }
}

/// Natural frequencies in Hz of the lowest `count` Ritz modes.
fn ritz_frequencies(plate: &Plate, count: usize) -> Vec<f64> {
    let (_, omegas) = PlateModes::build(plate).expect("plate builds");
    omegas[..count].iter().map(|w| w / (2.0 * PI)).collect()
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The orthotropic deck of the plate paper, Section 3.2: spans 24–30–24 m,
/// b = 13.715 m, h = 0.212 m, ρ = 3265.29 kg/m³ (ρh = 692.24 kg/m²),
/// Dx = 2.41e9, Dy = 2.18e7, Dxy = 1.14e8 N·m, ν_xy = 0.3, free edges.
fn orthotropic_deck(terms: (usize, usize)) -> Plate {
    plate(
        &SPANS,
        WIDTH,
        Some(0.212),
        3265.29 * 0.212,
        Rigidity::Orthotropic {
            flexural_rigidity_x: 2.41e9,
            flexural_rigidity_y: 2.18e7,
            torsional_rigidity: 1.14e8,
            equivalent_rigidity: 0.3 * 2.18e7 + 2.0 * 1.14e8,
            poisson_ratio: 0.3,
        },
        PlateEdges::Free,
        terms,
    )
}

/// The isotropic concrete deck of `isotropic_three_span_deck_matches_bfs_reference`
/// (the deck of `scenarios/plate-isotropic-*.yaml`).
fn isotropic_deck(terms: (usize, usize)) -> Plate {
    plate(
        &[12.0, 16.0, 12.0],
        10.0,
        Some(0.8),
        2500.0 * 0.8,
        Rigidity::Isotropic {
            youngs_modulus: 3.5e10,
            poisson_ratio: 0.2,
        },
        PlateEdges::Free,
        terms,
    )
}

/// Rigidities (Dx, Dy, D1, Dxy) of the plate paper's orthotropic deck, N·m,
/// typed from the paper (Section 3.2) for the reference: D1 = ν_xy·Dy.
const ORTHOTROPIC_RIGIDITIES: (f64, f64, f64, f64) = (2.41e9, 2.18e7, 0.3 * 2.18e7, 1.14e8);

/// Rigidities of an isotropic plate, N·m, from the textbook (Timoshenko &
/// Woinowsky-Krieger, Theory of Plates and Shells, §1–§10): D = Eh³/12(1−ν²),
/// Dx = Dy = D, D1 = νD, Dxy = (1−ν)D/2 — written here, not taken from vbi.
fn isotropic_rigidities(
    youngs_modulus: f64,
    poisson_ratio: f64,
    thickness: f64,
) -> (f64, f64, f64, f64) {
    let d = youngs_modulus * thickness * thickness * thickness
        / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
    (d, d, poisson_ratio * d, 0.5 * (1.0 - poisson_ratio) * d)
}

/// The BFS reference for the deck's geometry with the given rigidities and
/// mass per area (typed by the caller, not read back from vbi's resolved
/// deck), `per_metre` elements per metre along the spans and `across`
/// elements over the width.
fn bfs_reference(
    deck: &Plate,
    rigidities: (f64, f64, f64, f64),
    mass_per_area: f64,
    per_metre: f64,
    across: usize,
) -> BfsPlate {
    BfsPlate {
        spans: deck.spans.clone(),
        width: deck.width,
        mass_per_area,
        rigidities,
        elements_along: deck
            .spans
            .iter()
            .map(|s| (s * per_metre).round() as usize)
            .collect(),
        elements_across: across,
    }
}

/// Compares the lowest 10 Ritz frequencies of `deck` with the BFS reference
/// on two meshes (2 m × b/7 and 1 m × b/14 elements): the reference must be
/// converged (coarse vs fine within 0.2 %) and the Ritz model must agree
/// with the fine reference within 2 % (the tolerance) and, more
/// strictly, within 0.2 %: the two models agree to ~0.05 %, while dropping
/// the coupling term D1 (ν = 0.2) moves the isotropic deck's frequencies by
/// only 0.4–1.5 %, which the 2 % bound alone would let through. Returns the
/// largest Ritz error.
fn compare_with_bfs(
    name: &str,
    deck: &Plate,
    rigidities: (f64, f64, f64, f64),
    mass_per_area: f64,
) -> f64 {
    const COUNT: usize = 10;
    let ritz = ritz_frequencies(deck, COUNT);
    let coarse_mesh = bfs_reference(deck, rigidities, mass_per_area, 0.5, 7);
    let fine_mesh = bfs_reference(deck, rigidities, mass_per_area, 1.0, 14);
    let coarse = coarse_mesh.lowest_frequencies(COUNT);
    let fine = fine_mesh.lowest_frequencies(COUNT);
    println!(
        "{name}: BFS dofs coarse {} fine {}",
        coarse_mesh.dofs(),
        fine_mesh.dofs()
    );
    println!("mode  Ritz (Hz)   BFS fine    BFS coarse  Ritz err   mesh diff");
    let mut worst = 0.0f64;
    for k in 0..COUNT {
        let error = relative(ritz[k], fine[k]);
        let mesh = relative(coarse[k], fine[k]);
        worst = worst.max(error);
        println!(
            "{:>4}  {:>9.5}   {:>9.5}   {:>9.5}   {:>7.4} %  {:>7.4} %",
            k + 1,
            ritz[k],
            fine[k],
            coarse[k],
            100.0 * error,
            100.0 * mesh
        );
        assert!(
            mesh < 2e-3,
            "{name}: BFS reference not converged in mode {}: {} vs {} Hz",
            k + 1,
            coarse[k],
            fine[k]
        );
        assert!(
            error < 0.02,
            "{name}: mode {} Ritz {} Hz vs BFS {} Hz, beyond the issue's 2 %",
            k + 1,
            ritz[k],
            fine[k]
        );
        assert!(
            error < 2e-3,
            "{name}: mode {} Ritz {} Hz vs BFS {} Hz, beyond 0.2 %",
            k + 1,
            ritz[k],
            fine[k]
        );
    }
    worst
}

/// The isotropic plate simply supported on all four edges: a = 20 m,
/// b = 8 m, h = 0.2 m, E = 30 GPa, ν = 0.2, ρ = 2400 kg/m³.
const SS_PLATE: (f64, f64, f64, f64, f64, f64) = (20.0, 8.0, 0.2, 3.0e10, 0.2, 2400.0);

/// [`SS_PLATE`] with a basis of `terms` (longitudinal, transverse).
fn ss_plate(terms: (usize, usize)) -> Plate {
    let (a, b, h, e, nu, rho) = SS_PLATE;
    plate(
        &[a],
        b,
        Some(h),
        rho * h,
        Rigidity::Isotropic {
            youngs_modulus: e,
            poisson_ratio: nu,
        },
        PlateEdges::SimplySupported,
        terms,
    )
}

/// Isotropic plate simply supported on all four edges, 20 m × 8 m (not
/// 20 × 10: a = 2b makes (2,2) and (4,1) coincide, so their order is moot),
/// h = 0.2 m, E = 30 GPa, ν = 0.2, ρ = 2400 kg/m³, against the closed form
/// ω_mn = π²[(m/a)² + (n/b)²]√(D/ρh) (Leissa, Vibration of Plates, NASA
/// SP-160, 1969, eq. 4.26): the lowest 6 frequencies within 5e-4 (measured
/// 5.6e-5 at most, mode (4,1) with 8 × 6 terms), and each
/// mode's character is its (m, n).
#[test]
fn simply_supported_plate_matches_closed_form() {
    let (a, b, h, e, nu, rho) = SS_PLATE;
    let deck = ss_plate((8, 6));
    let (modes, omegas) = PlateModes::build(&deck).unwrap();
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    let mut exact: Vec<(f64, usize, usize)> = (1..=8)
        .flat_map(|m| (1..=6).map(move |n| (m, n)))
        .map(|(m, n)| {
            let (mf, nf) = (m as f64, n as f64);
            let omega = PI * PI * ((mf / a).powi(2) + (nf / b).powi(2)) * (d / (rho * h)).sqrt();
            (omega, m, n)
        })
        .collect();
    exact.sort_by(|p, q| p.0.total_cmp(&q.0));
    for k in 0..6 {
        let (omega, m, n) = exact[k];
        println!(
            "mode {} ({m},{n}): Ritz {:.6} Hz, Leissa {:.6} Hz",
            k + 1,
            omegas[k] / (2.0 * PI),
            omega / (2.0 * PI)
        );
        assert!(
            relative(omegas[k], omega) < 5e-4,
            "mode {}: {} vs {}",
            k + 1,
            omegas[k],
            omega
        );
        assert_eq!(modes.character(k), (m, n), "mode {}", k + 1);
    }
}

/// Natural circular frequencies (rad/s) of the lowest `count` modes of an
/// Euler–Bernoulli beam continuous over pinned supports, from the exact
/// transcendental frequency equation: on each span the general solution
/// w = A cos βξ + B sin βξ + C e^{−βξ} + D e^{−β(l−ξ)} (decaying
/// exponentials keep the determinant well scaled), with w = 0 at every support, w'' = 0 at both ends and w',
/// w'' continuous over the interior supports; the roots β of the 4S × 4S
/// determinant, found by scanning and bisection, give ω = β²√(EI/m).
fn continuous_beam_omegas(spans: &[f64], ei: f64, m: f64, count: usize) -> Vec<f64> {
    let s = spans.len();
    let determinant = |beta: f64| {
        let mut matrix = DMatrix::<f64>::zeros(4 * s, 4 * s);
        // Rows [w, w'/β, w''/β²] of span `k`'s basis at local ξ.
        let rows = |k: usize, xi: f64| {
            let l = spans[k];
            let (c, sn) = ((beta * xi).cos(), (beta * xi).sin());
            let (e0, e1) = ((-beta * xi).exp(), (-beta * (l - xi)).exp());
            [[c, sn, e0, e1], [-sn, c, -e0, e1], [-c, -sn, e0, e1]]
        };
        let mut row = 0;
        let put = |matrix: &mut DMatrix<f64>, row: usize, k: usize, v: [f64; 4], sign: f64| {
            for (j, vj) in v.iter().enumerate() {
                matrix[(row, 4 * k + j)] += sign * vj;
            }
        };
        let start = rows(0, 0.0);
        put(&mut matrix, row, 0, start[0], 1.0);
        row += 1;
        put(&mut matrix, row, 0, start[2], 1.0);
        row += 1;
        for (k, &span) in spans.iter().enumerate() {
            let end = rows(k, span);
            put(&mut matrix, row, k, end[0], 1.0);
            row += 1;
            if k + 1 < s {
                let next = rows(k + 1, 0.0);
                put(&mut matrix, row, k + 1, next[0], 1.0);
                row += 1;
                for d in 1..3 {
                    put(&mut matrix, row, k, end[d], 1.0);
                    put(&mut matrix, row, k + 1, next[d], -1.0);
                    row += 1;
                }
            } else {
                put(&mut matrix, row, k, end[2], 1.0);
                row += 1;
            }
        }
        assert_eq!(row, 4 * s);
        matrix.determinant()
    };
    let mut roots = Vec::new();
    let (mut beta, step) = (1e-3, 1e-4);
    let mut previous = determinant(beta);
    while roots.len() < count {
        let next_beta = beta + step;
        let value = determinant(next_beta);
        if value.signum() != previous.signum() {
            let (mut lo, mut hi, mut f_lo) = (beta, next_beta, previous);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                let f_mid = determinant(mid);
                if f_mid.signum() == f_lo.signum() {
                    (lo, f_lo) = (mid, f_mid);
                } else {
                    hi = mid;
                }
            }
            roots.push(0.5 * (lo + hi));
        }
        (beta, previous) = (next_beta, value);
    }
    roots.iter().map(|b| b * b * (ei / m).sqrt()).collect()
}

/// A very narrow isotropic plate strip (5 cm wide) with ν = 0, so D·b = EI,
/// on the 24–30–24 m spans with free edges.
fn narrow_strip() -> (Plate, f64, f64) {
    let (b, h, e, rho) = (0.05, 0.2, 3.0e10, 2400.0);
    let deck = plate(
        &SPANS,
        b,
        Some(h),
        rho * h,
        Rigidity::Isotropic {
            youngs_modulus: e,
            poisson_ratio: 0.0,
        },
        PlateEdges::Free,
        (18, 8),
    );
    let ei = e * h.powi(3) / 12.0 * b;
    let m = rho * h * b;
    (deck, ei, m)
}

/// A 5 cm wide strip on 24–30–24 m behaves as the continuous beam of the
/// same EI = D·b and m = ρhb: its lowest 4 modes (all longitudinal bending;
/// the strip's torsion and transverse modes lie far above) reproduce the
/// exact frequencies of the continuous Euler–Bernoulli beam (transcendental
/// frequency equation, `continuous_beam_omegas`) within 8e-5 (measured
/// 8.7e-6 at most, mode 4).
#[test]
fn narrow_strip_matches_continuous_beam() {
    let (deck, ei, m) = narrow_strip();
    let (modes, omegas) = PlateModes::build(&deck).unwrap();
    let exact = continuous_beam_omegas(&SPANS, ei, m, 4);
    for k in 0..4 {
        println!(
            "mode {}: strip {:.6} Hz, beam {:.6} Hz, character {:?}",
            k + 1,
            omegas[k] / (2.0 * PI),
            exact[k] / (2.0 * PI),
            modes.character(k)
        );
        assert!(relative(omegas[k], exact[k]) < 8e-5, "mode {}", k + 1);
        assert_eq!(modes.character(k), (k + 1, 1), "mode {}", k + 1);
    }
}

/// The orthotropic 24–30–24 m deck of the paper's Section 3.2 (Table 4's
/// numbers are not legible and Zhu & Law 2002's are not available): the
/// lowest 10 Ritz frequencies (default 18 × 8 basis) against the independent
/// BFS plate finite-element model within 2 % (the tolerance), the
/// reference converged to 0.2 % between 2 m and 1 m meshes; and the Ritz
/// basis converged: 18 × 8 vs 30 × 12 terms within 0.3 % (measured 0.039 %
/// at most, mode 10; the Ritz errors against BFS are 0.033 % at most).
#[test]
fn orthotropic_deck_matches_bfs_reference() {
    let deck = orthotropic_deck((18, 8));
    let worst = compare_with_bfs(
        "orthotropic deck",
        &deck,
        ORTHOTROPIC_RIGIDITIES,
        3265.29 * 0.212,
    );
    println!("largest Ritz error {:.4} %", 100.0 * worst);
    let default_basis = ritz_frequencies(&deck, 10);
    let larger_basis = ritz_frequencies(&orthotropic_deck((30, 12)), 10);
    for k in 0..10 {
        let change = relative(default_basis[k], larger_basis[k]);
        println!(
            "mode {}: 18×8 {:.5} Hz, 30×12 {:.5} Hz ({:.4} %)",
            k + 1,
            default_basis[k],
            larger_basis[k],
            100.0 * change
        );
        assert!(change < 3e-3, "mode {} not converged in the basis", k + 1);
    }
}

/// The isotropic three-span example (paper Section 3.1). Its Table 1 is not
/// legible, so the geometry and material are ASSUMED, as in the shipped
/// scenarios `plate-isotropic-*.yaml`: a solid concrete slab on 12–16–12 m
/// spans, b = 10 m, h = 0.8 m, E = 35 GPa, ν = 0.2, ρ = 2500 kg/m³, free
/// edges. The lowest 10 Ritz frequencies
/// (18 × 8 basis) against the BFS reference within 2 %, the reference
/// converged to 0.2 %.
#[test]
fn isotropic_three_span_deck_matches_bfs_reference() {
    let worst = compare_with_bfs(
        "isotropic deck",
        &isotropic_deck((18, 8)),
        isotropic_rigidities(3.5e10, 0.2, 0.8),
        2500.0 * 0.8,
    );
    println!("largest Ritz error {:.4} %", 100.0 * worst);
}

/// On the narrow strip the influence line of the middle span's mid-point
/// (x = 39 m, centre line) equals the continuous beam's (vbi's
/// Hermite-element `BeamModel::influence_line`, exact at the nodes for
/// Euler–Bernoulli) within 0.5 % of its peak, everywhere along the bridge.
#[test]
fn narrow_strip_influence_line_matches_beam() {
    let (deck, ei, m) = narrow_strip();
    let (modes, _) = PlateModes::build(&deck).unwrap();
    let y = 0.5 * deck.width;
    let plate_line = modes.influence_line(39.0, y, y).unwrap();
    let beam = BeamModel::new(&Beam {
        spans: SPANS.to_vec(),
        bending_stiffness: ei,
        mass_per_length: m,
        elements_per_span: vec![20; SPANS.len()],
        modes: no_modes(),
        damping: Damping::Modal { ratio: 0.0 },
        sway: None,
    })
    .unwrap();
    let beam_line = beam.influence_line(39.0).unwrap();
    let peak = beam_line.value_at(39.0);
    assert!(peak > 0.0, "a downward load deflects the point downward");
    let mut worst = 0.0f64;
    for k in 0..=780 {
        let x = 0.1 * k as f64;
        worst = worst.max((plate_line.value_at(x) - beam_line.value_at(x)).abs() / peak);
    }
    println!(
        "peak: strip {:.6e} m/N, beam {:.6e} m/N; worst difference {:.4} % of peak",
        plate_line.value_at(39.0),
        peak,
        100.0 * worst
    );
    assert!(worst < 5e-3);
}

/// Maxwell–Betti reciprocity on the wide orthotropic deck: the deflection
/// at P under a unit load at Q equals the deflection at Q under a unit
/// load at P, for two off-centre points on different spans, to 1e-9
/// relative (a property of the symmetric Ritz stiffness; round-off only).
#[test]
fn influence_lines_are_reciprocal() {
    let (modes, _) = PlateModes::build(&orthotropic_deck((18, 8))).unwrap();
    let (p, q) = ((10.0, 3.1), (43.7, 11.2));
    let at_p_load_q = modes.influence_line(p.0, p.1, q.1).unwrap().value_at(q.0);
    let at_q_load_p = modes.influence_line(q.0, q.1, p.1).unwrap().value_at(p.0);
    println!("G_P(Q) = {at_p_load_q:.12e} m/N, G_Q(P) = {at_q_load_p:.12e} m/N");
    assert!(at_p_load_q.abs() > 0.0);
    assert!(relative(at_p_load_q, at_q_load_p) < 1e-9);
    // The point's own deflection under its load is positive (downward).
    let own = modes.influence_line(p.0, p.1, p.1).unwrap().value_at(p.0);
    assert!(own > 0.0);
}

/// The precomputed line field (`line(y)`) and the direct double sum
/// (`values_slopes_curvatures_at`) are the same functions: values, slopes
/// and curvatures agree to 1e-12 of each quantity's largest magnitude at
/// 200 pseudo-random points, for 20 kept modes; and `values_at` matches.
#[test]
fn line_field_matches_direct_evaluation() {
    let (mut modes, _) = PlateModes::build(&orthotropic_deck((18, 8))).unwrap();
    let kept = 20;
    modes.truncate(kept);
    let mut state = 12345u64;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    // Per point: [direct values, slopes, curvatures, values_at, line values,
    // line slopes, line curvatures].
    let mut samples: Vec<[Vec<f64>; 7]> = Vec::new();
    for _ in 0..200 {
        let (x, y) = (78.0 * uniform(), WIDTH * uniform());
        let line = modes.line(y);
        assert_eq!(line.components(), kept);
        let [v, s, c, v_only, lv, ls, lc] = std::array::from_fn(|_| vec![0.0; kept]);
        let mut sample = [v, s, c, v_only, lv, ls, lc];
        let [v, s, c, v_only, lv, ls, lc] = &mut sample;
        modes.values_slopes_curvatures_at(x, y, v, s, c);
        modes.values_at(x, y, v_only);
        line.values_slopes_curvatures_at(x, lv, ls, lc);
        samples.push(sample);
    }
    // Largest magnitude of quantity `q` over every point and mode.
    let scale = |q: usize| {
        samples
            .iter()
            .flat_map(|sample| sample[q].iter().map(|a| a.abs()))
            .fold(0.0, f64::max)
    };
    let (sv, ss, sc) = (scale(0), scale(1), scale(2));
    assert!(sv > 0.0 && ss > 0.0 && sc > 0.0);
    for [v, s, c, v_only, lv, ls, lc] in &samples {
        for m in 0..kept {
            assert!((v[m] - lv[m]).abs() <= 1e-12 * sv, "value, mode {m}");
            assert!(
                (v[m] - v_only[m]).abs() <= 1e-12 * sv,
                "values_at, mode {m}"
            );
            assert!((s[m] - ls[m]).abs() <= 1e-12 * ss, "slope, mode {m}");
            assert!((c[m] - lc[m]).abs() <= 1e-12 * sc, "curvature, mode {m}");
        }
    }
    let mut v_only = vec![0.0; kept];
    // Off the deck every mode is zero.
    modes.values_at(-1.0, 1.0, &mut v_only);
    assert!(v_only.iter().all(|&a| a == 0.0));
    modes.values_at(80.0, 1.0, &mut v_only);
    assert!(v_only.iter().all(|&a| a == 0.0));
}

/// Navier's double series for the simply supported rectangular plate
/// (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, §§ 28–29):
/// a unit downward load at (ξ, η) on a × b, flexural rigidity D, Poisson ν;
/// w (downward) = Σ Wₘₙ sin(mπx/a) sin(nπy/b), Wₘₙ = 4 sin(mπξ/a)
/// sin(nπη/b) / (abDπ⁴ [(m/a)² + (n/b)²]²). Returns (m_x, m_y, m_xy) at
/// (x, y), N·m/m per N: m_x = −D(w_xx + ν w_yy) and m_y likewise (sagging
/// positive for w downward), m_xy = D(1 − ν) w_xy (Timoshenko's sign).
/// `terms` in each direction.
#[allow(clippy::too_many_arguments)]
fn navier_moments(
    (a, b, d, nu): (f64, f64, f64, f64),
    (xi, eta): (f64, f64),
    (x, y): (f64, f64),
    terms: usize,
) -> (f64, f64, f64) {
    let (mut mx, mut my, mut mxy) = (0.0, 0.0, 0.0);
    for m in 1..=terms {
        let alpha = m as f64 * PI / a;
        for n in 1..=terms {
            let beta = n as f64 * PI / b;
            let w = 4.0 * (alpha * xi).sin() * (beta * eta).sin()
                / (a * b * d * (alpha * alpha + beta * beta).powi(2));
            let (sx, sy) = ((alpha * x).sin(), (beta * y).sin());
            mx += d * w * (alpha * alpha + nu * beta * beta) * sx * sy;
            my += d * w * (nu * alpha * alpha + beta * beta) * sx * sy;
            mxy += d * (1.0 - nu) * w * alpha * beta * (alpha * x).cos() * (beta * y).cos();
        }
    }
    (mx, my, mxy)
}

/// The plate's moments per unit width under a unit load, from the full
/// Ritz stiffness (the static part of every recorded plate moment), against
/// Navier's series on the isotropic 20 m × 8 m plate simply supported on
/// all four edges, at points off the load (where both series converge
/// fast), with a 36 × 16 basis on 80 elements per span: within 5e-3 of the
/// largest moment (measured 2026-11-24: m_x 9.3e-4, m_y 2.7e-4, m_xy
/// 2.0e-3; m_x and m_y converge at first order in the element size: 6.1e-3,
/// 2.8e-3, 1.3e-3 at 20, 40, 80 elements with 18 × 16 terms; m_xy with the
/// basis).
#[test]
fn plate_moments_match_navier() {
    use vbi::scene::PlateMoment;
    let (a, b, h, e, nu, _) = SS_PLATE;
    let deck = ss_plate((36, 16));
    let mut deck = deck;
    deck.elements_per_span = 80;
    let (modes, omegas) = PlateModes::build(&deck).unwrap();
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    let eta = 2.0;
    let mut worst = [0.0f64; 3];
    let mut largest = 0.0f64;
    for &(x, y) in &[(10.0, 5.0), (13.0, 6.0), (4.0, 4.5)] {
        let probes = [
            PlateMoment::Longitudinal,
            PlateMoment::Transverse,
            PlateMoment::Twisting,
        ]
        .map(|c| modes.moment_probe(x, y, c, &omegas, &[eta]).unwrap());
        for &xi in &[3.0, 6.0, 16.5] {
            let exact = navier_moments((a, b, d, nu), (xi, eta), (x, y), 400);
            let mut value = [0.0];
            for (k, (probe, reference)) in
                probes.iter().zip([exact.0, exact.1, exact.2]).enumerate()
            {
                probe.lines[0].values_at(xi, &mut value);
                largest = largest.max(reference.abs());
                worst[k] = worst[k].max((value[0] - reference).abs());
            }
        }
    }
    println!(
        "Ritz against Navier, of the largest moment {largest:.4e}: m_x {:.1e}, m_y {:.1e}, m_xy {:.1e}",
        worst[0] / largest,
        worst[1] / largest,
        worst[2] / largest
    );
    for (k, w) in worst.iter().enumerate() {
        assert!(*w < 5e-3 * largest, "component {k}: {:.2e}", w / largest);
    }
}

/// A recorded plate moment converges with the mode count through its
/// static correction: a 100 kN force crossing the simply supported 20 m ×
/// 8 m plate at 1 m/s along y = 2 m (nearly quasi-static: the first mode is
/// 4.8 Hz), m_x and m_y at (10, 5) with 4 modes against 40 — within 1e-2
/// of the peak (measured 2026-11-24: m_x 3.3e-3, m_y 1.8e-3; what the 40
/// modes add is their small dynamic part) — and, at the instants the load
/// passes x = 6 m and 16.5 m, Navier's static moment within 1.5e-2 of the
/// peak (measured 2.2e-4 to 6.8e-3: the 20-element basis's first-order
/// error, 6.1e-3 of the largest moment in `plate_moments_match_navier`).
#[test]
fn recorded_plate_moments_converge_with_modes() {
    let scene = |modes: &str| {
        format!(
            "name: plate-moment\n\
             bridge:\n\
             \x20 type: plate\n\
             \x20 spans: [20.0]\n\
             \x20 width: 8.0\n\
             \x20 thickness: 0.2\n\
             \x20 density: 2400.0\n\
             \x20 rigidity: {{type: isotropic, youngs_modulus: 3.0e10, poisson_ratio: 0.2}}\n\
             \x20 edges: simply_supported\n\
             \x20 terms: {{longitudinal: 18, transverse: 16}}\n\
             \x20 modes: {modes}\n\
             \x20 damping: {{type: modal, ratio: 0.02}}\n\
             vehicles:\n  - {{type: moving_force, loads: [1.0e5], speed: 1.0, lateral_position: 2.0}}\n\
             solver: {{time_step: 2.0e-3}}\n\
             record:\n\
             \x20 - {{name: mx, quantity: bridge_moment, x: 10.0, y: 5.0}}\n\
             \x20 - {{name: my, quantity: bridge_moment, x: 10.0, y: 5.0, component: my}}\n"
        )
    };
    let run = |modes: &str| {
        let loaded = vbi::plan::load_str(&scene(modes), "plate-moment.yaml")
            .unwrap_or_else(|e| panic!("{e}"));
        vbi::run::simulate(loaded, &mut |_, _| {}).unwrap()
    };
    let (few, all) = (run("{count: 4}"), run("{count: 40}"));
    let column = |o: &vbi::run::Outcome, name: &str| -> Vec<f64> {
        o.history
            .columns
            .iter()
            .find(|c| c.name == name)
            .unwrap()
            .values
            .clone()
    };
    let (a, b, h, e, nu) = (20.0, 8.0, 0.2, 3.0e10, 0.2);
    let d = e * h * h * h / (12.0 * (1.0 - nu * nu));
    for (k, name) in ["mx", "my"].iter().enumerate() {
        let (x4, xall) = (column(&few, name), column(&all, name));
        let peak = xall.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let worst = x4
            .iter()
            .zip(&xall)
            .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
        println!(
            "{name}: 4 modes against 40: {:.1e} of the peak",
            worst / peak
        );
        assert!(worst < 1e-2 * peak, "{name}: {:.2e}", worst / peak);
        for xi in [6.0, 16.5] {
            // The load is at x = t · 1 m/s; Δt = 2 ms.
            let step = (xi / 2.0e-3f64).round() as usize;
            let exact = navier_moments((a, b, d, nu), (xi, 2.0), (10.0, 5.0), 400);
            let reference = 1.0e5 * [exact.0, exact.1][k];
            let error = (xall[step] - reference).abs() / peak;
            println!(
                "{name} with the load at {xi} m: {:.3e} against Navier {reference:.3e} ({error:.1e})",
                xall[step]
            );
            assert!(error < 1.5e-2, "{name} at {xi} m: {error:.2e} of the peak");
        }
    }
}
