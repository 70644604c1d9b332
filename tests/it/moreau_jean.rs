//! Rigid contact through impacts (issue 29): Moreau–Jean time stepping, so
//! the separation statistics after a landing have a limit as Δt → 0.
//!
//! The hopping surface of `hard_cases.rs` (the LCP paper's oscillator at
//! 30 m/s over a 3 mm, 1.5 m harmonic surface, 20 m beam): the wheel lands
//! and lifts repeatedly. Before Moreau–Jean, Δt = 1e-4, 5e-5, 2.5e-5 and
//! 1.25e-5 s gave 12, 10, 6 and 14 contact-loss episodes and 0.088, 0.083,
//! 0.070 and 0.096 s separated (no trend). Measured figures are printed with
//! `eprintln!` (`--nocapture` shows them).

use crate::support::run_yaml;
use vbi::run::Outcome;

// The LCP separation paper's bridge (20 m, f₁ ≈ 5.0 Hz).
const SPAN: f64 = 20.0;
const EI: f64 = 3.2423e9;
const MASS_PER_LENGTH: f64 = 2000.0;

fn hopping_scene(dt: f64, amplitude: f64, contact: &str) -> String {
    format!(
        "name: hopping\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
         stiffness: 4.0e6, damping: 2.53e4, speed: 30.0}}]\n\
         surface: {{type: harmonic, amplitude: {amplitude}, wavelength: 1.5}}\n\
         contact: {contact}\n\
         solver: {{time_step: {dt}, free_vibration: 0.2}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: force, quantity: contact_force}}, {{name: gap, quantity: contact_gap}}]\n"
    )
}

/// (episodes, time separated s, largest gap m, mid-span DAF).
fn statistics(outcome: &Outcome) -> (usize, f64, f64, f64) {
    let wheel = &outcome.summary.separation[0];
    let daf = outcome
        .summary
        .quantities
        .iter()
        .find(|q| q.name == "mid")
        .and_then(|q| q.daf)
        .expect("mid-span DAF");
    (wheel.episodes, wheel.time_separated, wheel.max_gap, daf)
}

/// Separation statistics converge (issue 29, point 3). On the 4.5 mm
/// surface with e = 0 (`hopping_statistics_converge_on_the_higher_surface`)
/// the spurious flights of `no_spurious_flights_before_lift_offs` shifted the
/// lift-offs before the held wheel's period-2 filter (0.23695, 0.237325 and
/// 0.236275 s separated at Δt = 5e-5, 2.5e-5 and 1.25e-5 s); with it: 16
/// episodes at every step, 0.23550, 0.23597 and 0.23585 s separated,
/// largest gap 0.4074, 0.4078 and 0.4079 mm, DAF 1.14157, 1.14199, 1.14301
/// — the DAF's changes growing, the static correction's residual spring
/// ringing under the landed wheel (`impacts_converge_with_the_static_correction`);
/// with the residual quasi-static: 0.23490, 0.23485, 0.23487 s, 0.4072,
/// 0.4076, 0.4077 mm, DAF 1.14158, 1.14197, 1.14222.
/// (An episode: a flight whose gap passes
/// 1 µm, `RIGID_LOSS_GAP`; the sub-micrometre flights at the end of an
/// accumulation of bounces grow in number as the step resolves more of
/// them, 6, 12 and 24 of them at Δt = 5e-5, 2.5e-5 and 1.25e-5 s on the 3 mm
/// surface with e = 0.5, so without the floor the count had no limit:
/// 4, 6, 7). Measured: 3 mm, e = 0.5: 4 episodes at every step, 0.019000,
/// 0.019100, 0.019175 s separated, largest gap 0.31315, 0.31233,
/// 0.31192 mm. On the 3 mm surface with a plastic
/// landing (e = 0) the wheel, kicked up at the entrance (the surface slope
/// jumps there, an impact at t = 0), never leaves the surface again: the
/// surface's largest downward acceleration a(2πv/λ)² = 47 m/s² is below
/// the g + preload/m_u = 49 m/s² it needs — the flights the displacement-level
/// scheme showed there were its trapezoidal rebound. With e = 0.5 on the
/// same surface the wheel bounces and lands repeatedly, and on a 4.5 mm
/// surface (71 m/s²) it hops plastically: the same number of contact-loss
/// episodes at the two finest steps, and the time separated, the largest
/// gap and the DAF change less from Δt/4 to Δt/8 than from Δt/2 to Δt/4.
#[test]
fn hopping_statistics_converge() {
    hopping_cases_converge(&[(0.003, 0.0), (0.003, 0.5)]);
}

/// The 4.5 mm, e = 0 case of [`hopping_statistics_converge`] (see its doc).
#[test]
fn hopping_statistics_converge_on_the_higher_surface() {
    hopping_cases_converge(&[(0.0045, 0.0)]);
}

/// (amplitude m, restitution) cases at Δt = 5e-5, 2.5e-5 and 1.25e-5 s.
fn hopping_cases_converge(cases: &[(f64, f64)]) {
    let base = 1.0e-4;
    for &(amplitude, restitution) in cases {
        let rows: Vec<_> = (1..4)
            .map(|level| {
                let dt = base / f64::from(1u32 << level);
                let contact = format!("{{type: rigid, restitution: {restitution}}}");
                let s = statistics(&run_yaml(&hopping_scene(dt, amplitude, &contact)));
                eprintln!(
                    "a {amplitude}, e {restitution}, Δt {dt:.3e}: {} episodes, {:.5} s separated, \
                     max gap {:.4} mm, DAF {:.5}",
                    s.0,
                    s.1,
                    s.2 * 1e3,
                    s.3
                );
                s
            })
            .collect();
        let label = format!("a = {amplitude} m, e = {restitution}");
        if restitution == 0.0 && amplitude == 0.003 {
            assert!(rows.iter().all(|r| r.0 == 0), "{label}: {rows:?}");
            continue;
        }
        assert!(rows[2].0 > 0, "{label}: no separation");
        assert_eq!(
            rows[1].0, rows[2].0,
            "{label}: episode counts at the two finest steps"
        );
        for (name, k) in [("time separated", 1), ("max gap", 2), ("DAF", 3)] {
            let value = |r: &(usize, f64, f64, f64)| [r.0 as f64, r.1, r.2, r.3][k];
            let (d1, d2) = (
                (value(&rows[1]) - value(&rows[0])).abs(),
                (value(&rows[2]) - value(&rows[1])).abs(),
            );
            assert!(
                d2 < 0.75 * d1 + 1e-3 * value(&rows[2]).abs(),
                "{label}: {name} changes {d1:.3e}, {d2:.3e}"
            );
        }
    }
}

/// Impacts and the static correction agree (issue 43, point 4). On the
/// 4.5 mm hopping case with 10 modes and the static correction on (the
/// default), the wheel lands a dozen times; its residual flexibility R (the
/// left-out modes' static flexibility) is quasi-static, so the wheel now
/// follows it kinematically instead of riding on the spring 1/R with its
/// 1 t mass (a 1.2 kHz contact mode that each landing set ringing). Before,
/// the mid-span peak moved by 1.06, 2.58 and 6.84 µm per halving of Δt from
/// 5e-5 s (2.87830, 2.87936, 2.88194, 2.88878 mm: no limit) and the DAF by
/// 4.2e-4, 1.0e-3; now 0.99, 0.63 and 0.30 µm (first order, as the run
/// without the correction, 0.97, 0.64, 0.33 µm): 2.87832, 2.87931,
/// 2.87994, 2.88024 mm. Asserted: each change of the peak, the DAF and the
/// time separated below 0.75× the previous one (the first-order rate is
/// 0.5×), and the peak within 0.01 % of the uncorrected run's at the
/// finest step (the correction adds the left-out modes' quasi-static share
/// at mid-span, 2e-5 of the peak here).
#[test]
fn impacts_converge_with_the_static_correction() {
    let rows: Vec<(f64, f64, f64)> = (1..5)
        .map(|level| {
            let dt = 1.0e-4 / f64::from(1u32 << level);
            let run = run_yaml(&hopping_scene(dt, 0.0045, "{type: rigid}"));
            let peak = max_abs(column(&run, "mid"));
            let (_, separated, _, daf) = statistics(&run);
            eprintln!(
                "Δt {dt:.3e}: mid-span peak {:.5} mm, DAF {daf:.5}, {separated:.6} s separated",
                peak * 1e3
            );
            (peak, daf, separated)
        })
        .collect();
    for (name, value) in [
        (
            "mid-span peak",
            (|r: &(f64, f64, f64)| r.0) as fn(&(f64, f64, f64)) -> f64,
        ),
        ("DAF", |r| r.1),
        ("time separated", |r| r.2),
    ] {
        let changes: Vec<f64> = rows
            .windows(2)
            .map(|w| (value(&w[1]) - value(&w[0])).abs())
            .collect();
        for pair in changes.windows(2) {
            assert!(
                pair[1] < 0.75 * pair[0],
                "{name} does not converge in Δt: changes {changes:?}"
            );
        }
    }
    let uncorrected = run_yaml(&hopping_scene(6.25e-6, 0.0045, "{type: rigid}").replace(
        "modes: {count: 10}",
        "modes: {count: 10, static_correction: false}",
    ));
    let bare = max_abs(column(&uncorrected, "mid"));
    assert!(
        (rows[3].0 - bare).abs() < 1e-4 * bare,
        "corrected peak {:e} against uncorrected {bare:e}",
        rows[3].0
    );
}

use crate::support::column;
use crate::support::impact_reference::{RigidCase, rigid_reference};
use crate::support::max_abs;

/// The hopping case with 4 modes and no static correction, as the
/// event-driven reference models it (analytic sine modes; vbi's 20-element
/// beam puts the first four frequencies within 1e-5 of them).
fn reference_case(amplitude: f64, restitution: f64) -> RigidCase {
    RigidCase {
        length: SPAN,
        bending_stiffness: EI,
        mass_per_length: MASS_PER_LENGTH,
        damping_ratio: 0.02,
        sprung_mass: 4000.0,
        unsprung_mass: 1000.0,
        stiffness: 4.0e6,
        damping: 2.53e4,
        speed: 30.0,
        amplitude,
        wavelength: 1.5,
        modes: 4,
        restitution,
    }
}

fn reference_scene(dt: f64, amplitude: f64, restitution: f64) -> String {
    format!(
        "name: hopping-reference\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 4, static_correction: false}}, \
         damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
         stiffness: 4.0e6, damping: 2.53e4, speed: 30.0}}]\n\
         surface: {{type: harmonic, amplitude: {amplitude}, wavelength: 1.5}}\n\
         contact: {{type: rigid, restitution: {restitution}}}\n\
         solver: {{time_step: {dt}, free_vibration: 0.0, newmark: {{alpha: 0.0}}}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: gap, quantity: contact_gap}}, \
         {{name: wheel, quantity: vehicle_displacement, dof: wheel}}, \
         {{name: body, quantity: vehicle_displacement, dof: sprung}}]\n"
    )
}

/// Largest difference over the history relative to the reference's peak
/// (or to `floor` if that is larger).
fn history_error(run: &[f64], reference: &[f64], stride: usize, floor: f64) -> f64 {
    let n = run.len().min((reference.len() - 1) / stride + 1);
    let peak = reference.iter().fold(floor, |m, v| m.max(v.abs()));
    (0..n).fold(0.0f64, |m, i| m.max((run[i] - reference[i * stride]).abs())) / peak
}

/// Moreau–Jean against the event-driven reference with Newton's law,
/// through every landing of the crossing (the entrance kick, then repeated
/// landings and lift-offs; with e = 0.5 chattering sequences, bounces of
/// geometrically shrinking height ended by an accumulation): the gap, wheel,
/// body and mid-span histories converge at first order.
#[test]
fn moreau_jean_follows_the_impact_reference() {
    let t_end = SPAN / 30.0;
    let finest = 2.5e-5;
    // (amplitude m, e, bound on every relative history error at Δt = 2.5e-5 s,
    // set at 3× the largest measured by the first, all-impulse Moreau–Jean
    // step, 4.2e-4, 2.1e-3 and 4.5e-3; the hybrid step with the held wheel's
    // period-2 filter measures 7.5e-4 (body), 2.1e-3 (gap) and 6.6e-3 (mid),
    // each falling at first order from Δt = 1e-4 s except the last, 4.8e-3
    // at 5e-5 s: a chattering sequence's landings fall on the grid).
    for (amplitude, restitution, bound) in [
        (0.0045, 0.0, 1.5e-3),
        (0.003, 0.5, 7e-3),
        (0.0045, 0.5, 1.5e-2),
    ] {
        let reference = rigid_reference(&reference_case(amplitude, restitution), t_end, finest, 10);
        let sprung_static = -4000.0 * 9.81 / 4.0e6;
        let body: Vec<f64> = reference.sprung.iter().map(|y| y - sprung_static).collect();
        let hops = reference.landings.len();
        eprintln!(
            "a = {amplitude}, e = {restitution}: reference {} landings, {} lift-offs, first landings {:?}",
            hops,
            reference.losses.len(),
            &reference.landings[..hops.min(6)]
        );
        let mut errors = Vec::new();
        for level in 0..3 {
            let stride = 1usize << (2 - level);
            let dt = finest * stride as f64;
            let run = run_yaml(&reference_scene(dt, amplitude, restitution));
            let e = [
                history_error(column(&run, "gap"), &reference.gap, stride, amplitude),
                history_error(column(&run, "wheel"), &reference.wheel, stride, 0.0),
                history_error(column(&run, "body"), &body, stride, 0.0),
                history_error(column(&run, "mid"), &reference.midspan, stride, 0.0),
            ];
            let s = &run.summary.separation[0];
            eprintln!(
                "  vbi: {} episodes, {:.5} s separated, max gap {:.4} mm; reference {} lift-offs",
                s.episodes,
                s.time_separated,
                s.max_gap * 1e3,
                reference.losses.len()
            );
            eprintln!(
                "a = {amplitude}, e = {restitution}, Δt {dt:.2e}: errors gap {:.3e}, wheel {:.3e}, body {:.3e}, mid {:.3e}",
                e[0], e[1], e[2], e[3]
            );
            errors.push(e);
        }
        for k in 0..4 {
            assert!(
                errors[2][k] < bound,
                "a = {amplitude}, e = {restitution}: quantity {k} error {:.3e} above {bound:.1e}",
                errors[2][k]
            );
            assert!(
                errors[2][k] < 0.75 * errors[0][k],
                "e = {restitution}: quantity {k} does not converge: {errors:?}"
            );
        }
    }
}

/// The LCP paper's rigid cases (Figs. 4–5, `scenarios/lcp-fig4-rigid.yaml`
/// and `lcp-fig5-rigid.yaml`) at their step, half and a quarter of it: the
/// same contact-loss episodes at the two finest steps, and the first loss,
/// time separated, largest gap and mid-span DAF changing less between the
/// two finest steps than between the two coarsest (first order).
#[test]
fn paper_rigid_cases_converge() {
    for name in ["lcp-fig4-rigid.yaml", "lcp-fig5-rigid.yaml"] {
        let text =
            std::fs::read_to_string(crate::support::manifest_dir().join("scenarios").join(name))
                .expect("scene");
        let rows: Vec<(usize, f64, f64, f64, f64)> = (0..3)
            .map(|level| {
                let dt = 5.0e-5 / f64::from(1u32 << level);
                let run = run_yaml(&text.replace("time_step: 5.0e-5", &format!("time_step: {dt}")));
                let w = &run.summary.separation[0];
                let daf = run
                    .summary
                    .quantities
                    .iter()
                    .find(|q| q.name == "midspan")
                    .and_then(|q| q.daf)
                    .expect("DAF");
                let row = (
                    w.episodes,
                    w.first_loss_time.unwrap_or(0.0),
                    w.time_separated,
                    w.max_gap,
                    daf,
                );
                eprintln!("{name} Δt {dt:.3e}: {row:?}");
                row
            })
            .collect();
        assert_eq!(rows[1].0, rows[2].0, "{name}: episodes {rows:?}");
        let values = |r: &(usize, f64, f64, f64, f64)| [r.1, r.2, r.3, r.4];
        for k in 0..4 {
            let (a, b, c) = (
                values(&rows[0])[k],
                values(&rows[1])[k],
                values(&rows[2])[k],
            );
            assert!(
                (c - b).abs() <= 0.75 * (b - a).abs() + 1e-3 * c.abs(),
                "{name}: statistic {k}: {a}, {b}, {c}"
            );
        }
    }
}

/// A coefficient of restitution outside [0, 1] is refused with its file,
/// line and column.
#[test]
fn restitution_outside_zero_to_one_is_refused() {
    for bad in ["1.5", "-0.1"] {
        let text = hopping_scene(1e-4, 0.003, &format!("{{type: rigid, restitution: {bad}}}"));
        let error = vbi::plan::load_str(&text, "hop.yaml")
            .err()
            .unwrap_or_else(|| panic!("restitution {bad} accepted"))
            .to_string();
        assert!(error.contains("restitution"), "{error}");
        assert!(error.contains("hop.yaml:5:37"), "{error}");
    }
}

/// The reference scene with `damping` (bridge ratio, vehicle N·s/m) and a
/// contact force column.
fn reference_scene_with(dt: f64, amplitude: f64, restitution: f64, damping: (f64, f64)) -> String {
    reference_scene(dt, amplitude, restitution)
        .replace(
            "damping: {type: modal, ratio: 0.02}",
            &format!("damping: {{type: modal, ratio: {}}}", damping.0),
        )
        .replace("damping: 2.53e4", &format!("damping: {}", damping.1))
        .replace(
            "{name: gap, quantity: contact_gap}",
            "{name: gap, quantity: contact_gap}, {name: force, quantity: contact_force}",
        )
}

/// Flights: maximal runs of samples with a gap above `SEPARATION_GAP` (a
/// rigid wheel with a gap carries no force; the recorded force is averaged
/// over 1 ms after a landing), as (first index, last index, largest gap m).
fn flights(gap: &[f64]) -> Vec<(usize, usize, f64)> {
    let mut out: Vec<(usize, usize, f64)> = Vec::new();
    let mut open = false;
    for (k, &g) in gap.iter().enumerate() {
        let apart = g > vbi::record::SEPARATION_GAP;
        match (apart, open) {
            (true, false) => out.push((k, k, g)),
            (true, true) => {
                let last = out.last_mut().expect("open flight");
                last.1 = k;
                last.2 = last.2.max(g);
            }
            _ => {}
        }
        open = apart;
    }
    out
}

/// No spurious flights before a lift-off (issue 29, point 4): every flight
/// of the wheel (gap above 1 nm) on the 4.5 mm surface with e = 0 is one of
/// the event-driven reference's lift-offs, 12 of them, at Δt = 1e-4, 5e-5,
/// 2.5e-5 and 1.25e-5 s, none below 1 µm, and the summary counts them all.
/// Before the held wheel's period-2 filter (`smoothed_held_motion` in
/// src/solve/unilateral/landing.rs) the wheel held by the displacement-level law
/// took an alternating contact force growing as m·s‴·t/3 (the trapezoidal
/// rule's alternating velocity error under a position constraint; measured
/// 3 kN per ms here), which touched zero on alternate steps before each
/// real lift-off: 44–54 flights of 1–3 steps and 1–10 nm (32–42 of them
/// below 1 µm).
#[test]
fn no_spurious_flights_before_lift_offs() {
    let t_end = SPAN / 30.0;
    let reference = rigid_reference(&reference_case(0.0045, 0.0), t_end, 2.5e-5, 10);
    for dt in [1.0e-4, 5.0e-5, 2.5e-5, 1.25e-5] {
        let run = run_yaml(&reference_scene_with(dt, 0.0045, 0.0, (0.02, 2.53e4)));
        let all = flights(column(&run, "gap"));
        let small = all.iter().filter(|f| f.2 < 1e-6).count();
        eprintln!(
            "Δt {dt:.2e}: {} flights, {small} below 1 µm; reference {} lift-offs; summary {} episodes",
            all.len(),
            reference.losses.len(),
            run.summary.separation[0].episodes
        );
        assert_eq!(small, 0, "Δt {dt}: flights below 1 µm: {all:?}");
        assert_eq!(all.len(), reference.losses.len(), "Δt {dt}: {all:?}");
        assert_eq!(run.summary.separation[0].episodes, all.len(), "Δt {dt}");
    }
}

/// The same without spurious flights on the 10-mode hopping scene of
/// [`hopping_statistics_converge`] (4.5 mm, e = 0, α = 0, 0.2 s of free
/// vibration): the same 16 flights at Δt = 2.5e-5 and 1.25e-5 s (the last
/// still open at the run's end), none below 1 µm (measured;
/// before the held wheel's period-2 filter the 4-mode scene showed 44–54).
/// Without `static_correction: false` flights below 0.1 µm remain at the
/// finest steps (16, 29 and 102 flights at Δt = 5e-5, 2.5e-5 and 1.25e-5 s;
/// 16, 16 and 52 with the rigid default α = −0.05): the wheel's mass on the residual (quasi-static)
/// flexibility of the modes left out is a stiff undamped oscillator that
/// the step resolves once it is fine enough, excited because a landing's
/// impulse bypasses that flexibility; the 1 µm episode floor
/// (`RIGID_LOSS_GAP`) keeps them out of the statistics.
#[test]
fn no_spurious_flights_with_ten_modes() {
    let mut counts = Vec::new();
    for dt in [2.5e-5, 1.25e-5] {
        let text = hopping_scene(dt, 0.0045, "{type: rigid, restitution: 0.0}")
            .replace(
                "modes: {count: 10}",
                "modes: {count: 10, static_correction: false}",
            )
            .replace(
                "free_vibration: 0.2}",
                "free_vibration: 0.2, newmark: {alpha: 0.0}}",
            );
        let run = run_yaml(&text);
        let all = flights(column(&run, "gap"));
        let small = all.iter().filter(|f| f.2 < 1e-6).count();
        eprintln!(
            "10 modes, Δt {dt:.2e}: {} flights, {small} below 1 µm",
            all.len()
        );
        assert_eq!(small, 0, "Δt {dt}: flights below 1 µm: {all:?}");
        assert_eq!(run.summary.separation[0].episodes, all.len(), "Δt {dt}");
        counts.push(all.len());
    }
    assert_eq!(counts[0], counts[1], "flights at the two steps: {counts:?}");
}

/// The relative normal velocity at sample `k` from the quadratic through
/// samples `k`, `k + s` and `k + 2s` of `gap` (s = ±1), at the time where
/// that quadratic crosses 0 nearest to sample `k` (m/s).
fn gap_velocity_at_contact(gap: &[f64], k: usize, backward: bool, dt: f64) -> f64 {
    let at = |j: usize| gap[j];
    // Samples at times 0, σh, 2σh (σ = −1 backward).
    let sigma = if backward { -1.0 } else { 1.0 };
    let (g0, g1, g2) = if backward {
        (at(k), at(k - 1), at(k - 2))
    } else {
        (at(k), at(k + 1), at(k + 2))
    };
    let h = sigma * dt;
    // g(τ) = g0 + bτ + cτ².
    let c = (g2 - 2.0 * g1 + g0) / (2.0 * h * h);
    let b = (g1 - g0) / h - c * h;
    // The root of g nearest to τ = 0 (g0 is the sample closest to contact).
    let tau = if c.abs() < 1e-300 {
        -g0 / b
    } else {
        let disc = (b * b - 4.0 * c * g0).max(0.0).sqrt();
        let (r1, r2) = ((-b + disc) / (2.0 * c), (-b - disc) / (2.0 * c));
        if r1.abs() < r2.abs() { r1 } else { r2 }
    };
    b + 2.0 * c * tau
}

/// Energy (issue 29): with e = 1 and no damping (bridge and vehicle), an
/// impact loses no energy. The only energy an impact can take is that of
/// the relative normal motion, ½m*U² (m* the wheel's effective mass against
/// the deck); Newton's law with e = 1 leaves U⁺ = −U⁻, so the fraction lost
/// at each landing is 1 − (U⁺/U⁻)². Measured from the gap history (U⁻ from
/// the last three samples of the flight, U⁺ from the first three of the
/// next, each at its zero crossing: first order) at every landing of a
/// flight above 10 µm on the 4.5 mm surface (4 modes, α = 0). Measured
/// largest loss over 23, 25 and 17 bounces: 6.4e-2, 9.1e-3 and 2.7e-3 at
/// Δt = 5e-5, 2.5e-5 and 1.25e-5 s (it falls at least at first order).
#[test]
fn elastic_impacts_lose_no_energy() {
    let mut worst = Vec::new();
    for dt in [5.0e-5, 2.5e-5, 1.25e-5] {
        let run = run_yaml(&reference_scene_with(dt, 0.0045, 1.0, (0.0, 0.0)));
        let gap = column(&run, "gap");
        let all = flights(gap);
        let mut losses = Vec::new();
        for pair in all.windows(2) {
            let (before, after) = (pair[0], pair[1]);
            // A bounce: the next flight starts right after this one lands,
            // and both are real flights.
            if after.0 > before.1 + 3 || before.2 < 1e-5 || before.1 - before.0 < 3 {
                continue;
            }
            if after.1 < after.0 + 2 {
                continue;
            }
            let approach = gap_velocity_at_contact(gap, before.1, true, dt);
            // The landing sample (gap 0) starts the bounce's quadratic.
            let departure = gap_velocity_at_contact(gap, after.0 - 1, false, dt);
            losses.push(1.0 - (departure / approach).powi(2));
        }
        let largest = losses.iter().fold(0.0f64, |m, l| m.max(l.abs()));
        eprintln!(
            "e = 1, Δt {dt:.2e}: {} flights, {} bounces, largest energy fraction lost {largest:.3e}",
            all.len(),
            losses.len()
        );
        assert!(!losses.is_empty(), "Δt {dt}: no bounce measured");
        worst.push(largest);
    }
    assert!(worst[2] < 0.6 * worst[0], "no first-order fall: {worst:?}");
    assert!(worst[2] < ENERGY_BOUND, "{worst:?}");
}

/// Bound on the energy fraction lost at a bounce at Δt = 1.25e-5 s (3× the
/// largest measured, 2.7e-3).
const ENERGY_BOUND: f64 = 8e-3;
