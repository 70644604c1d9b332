//! Numerical stability on hard cases: very stiff contact at a step that does
//! not resolve it, a rigid wheel hopping over a rough deck, speeds at and
//! above the critical resonance, a long undamped free-vibration tail, a
//! 30-span viaduct with 300 modes, extreme vehicle-to-bridge mass ratios, and
//! a conditionally stable Newmark variant on both sides of its stability
//! limit.
//!
//! Every case asserts three things, each able to fail:
//! - **finite**: no NaN or infinity in any history or summary value;
//! - **bounded**: a stated physical bound (a multiple of the static
//!   response, an independent closed form, or the conservation / decay of the
//!   free-vibration amplitude), argued in each test's comment;
//! - **converged**: the same scene at a finer step (or with more modes)
//!   agrees within a stated tolerance.
//!
//! Measured figures are printed with `eprintln!` (`--nocapture` shows them).

use crate::support;

use support::{column, max_abs};

use std::f64::consts::PI;

use support::reference as exact;
use vbi::plan::load_str;
use vbi::record::SEPARATION_GAP;
use vbi::report::summary::QuantitySummary;
use vbi::run::{Outcome, RunError, simulate};
use vbi::solve::SolveError;

fn try_run(text: &str) -> Result<Outcome, RunError> {
    let loaded = load_str(text, "hard_case.yaml").unwrap_or_else(|e| panic!("{e}\n{text}"));
    simulate(loaded, &mut |_, _| {})
}

fn run(text: &str) -> Outcome {
    try_run(text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn quantity<'a>(outcome: &'a Outcome, name: &str) -> &'a QuantitySummary {
    outcome
        .summary
        .quantities
        .iter()
        .find(|q| q.name == name)
        .unwrap_or_else(|| panic!("no quantity {name}"))
}

fn daf(outcome: &Outcome, name: &str) -> f64 {
    quantity(outcome, name).daf.expect("DAF of a displacement")
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// No NaN or infinity anywhere: times, every recorded column (and its static
/// companion), every summary extreme and DAF, every separation statistic.
fn assert_finite(outcome: &Outcome, label: &str) {
    assert!(
        outcome.history.time.iter().all(|t| t.is_finite()),
        "{label}: non-finite time"
    );
    for c in &outcome.history.columns {
        assert!(
            c.values.iter().all(|v| v.is_finite()),
            "{label}: non-finite value in {}",
            c.name
        );
        if let Some(s) = &c.static_values {
            assert!(
                s.iter().all(|v| v.is_finite()),
                "{label}: non-finite static value in {}",
                c.name
            );
        }
    }
    for q in &outcome.summary.quantities {
        let values = [
            q.max.value,
            q.min.value,
            q.max_abs.value,
            q.daf.unwrap_or(1.0),
        ];
        assert!(
            values.iter().all(|v| v.is_finite()),
            "{label}: non-finite summary of {}: {q:?}",
            q.name
        );
    }
    for w in &outcome.summary.separation {
        assert!(
            w.max_gap.is_finite() && w.time_separated.is_finite(),
            "{label}: {w:?}"
        );
    }
}

/// RMS of the step-to-step change of a history.
fn step_variation_rms(values: &[f64]) -> f64 {
    let sum: f64 = values.windows(2).map(|w| (w[1] - w[0]).powi(2)).sum();
    (sum / (values.len() - 1) as f64).sqrt()
}

// The LCP separation paper's bridge (20 m, f₁ ≈ 5.0 Hz).
const SPAN: f64 = 20.0;
const EI: f64 = 3.2423e9;
const MASS_PER_LENGTH: f64 = 2000.0;

fn stiff_contact_scene(contact: &str, dt: f64, alpha: f64) -> String {
    format!(
        "name: stiff-contact\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
         stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}}]\n\
         surface: {{type: harmonic, amplitude: 0.0005, wavelength: 5.0}}\n\
         contact: {contact}\n\
         solver: {{time_step: {dt}, free_vibration: 0.5, newmark: {{alpha: {alpha}}}}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: force, quantity: contact_force}}, \
         {{name: sprung_acc, quantity: vehicle_acceleration, dof: sprung}}]\n"
    )
}

/// Case 1 — very stiff contact at a step that does not resolve it. The LCP
/// paper's oscillator (1000 kg wheel, 4000 kg body) on a 0.5 mm, 5 m harmonic
/// surface at 25 m/s (no separation), Δt = 4 ms: the contact frequency
/// ω_c = √(k_c/m_w) gives ω_cΔt = 4.0 (elastic 1e9 N/m), 12.6 (1e10 N/m) and
/// 4.4 (Hertz C = 1e11 N/m^1.5, tangent stiffness 1.5 C^(2/3) P^(1/3) at the
/// static load), while the bridge (f₁ ≈ 5 Hz) and the roughness (5 Hz) get 50
/// steps per period. The implicit LCP step is unconditionally stable, so:
/// - finite, and bounded: mid-span DAF < 2 and contact force below 3× the
///   static wheel load — the converged response (Δt/8) peaks at DAF 1.34 and
///   2.0× the static load, and an instability grows geometrically, so it
///   would cross both within a few steps;
/// - the bridge does not care that the contact is unresolved: mid-span
///   maximum deflection within 1 % of the run at Δt/8 (measured ≤ 0.12 %),
///   body acceleration maximum within 2 % (measured ≤ 0.6 %), with α = 0 and
///   with α = −0.1;
/// - HHT α = −0.1 damps the unresolved contact oscillation that
///   average-acceleration Newmark (α = 0, spectral radius 1) keeps: the RMS
///   of the step-to-step contact-force change is less than 0.6 of α = 0's
///   (measured 0.47, 0.21, 0.44).
#[test]
fn very_stiff_contact_at_an_unresolved_step() {
    let (dt, wheel_mass) = (4.0e-3, 1000.0);
    for (contact, tangent_stiffness) in [
        ("{type: elastic, stiffness: 1.0e9}", None),
        ("{type: elastic, stiffness: 1.0e10}", None),
        ("{type: hertz, coefficient: 1.0e11}", Some(1.0e11)),
    ] {
        let fine = run(&stiff_contact_scene(contact, dt / 8.0, 0.0));
        let load = fine.model.static_wheel_loads[0];
        let k_c = match tangent_stiffness {
            Some(c) => 1.5 * f64::powf(c, 2.0 / 3.0) * load.cbrt(),
            None => match fine.model.contact {
                vbi::model::ContactLaw::Elastic { stiffness } => stiffness,
                ref other => panic!("{other:?}"),
            },
        };
        let omega_dt = (k_c / wheel_mass).sqrt() * dt;
        assert!(omega_dt > 3.0, "{contact}: ω_cΔt = {omega_dt}");
        assert_finite(&fine, contact);
        let fine_mid = quantity(&fine, "mid").max_abs.value;
        let fine_body = quantity(&fine, "sprung_acc").max_abs.value;
        let mut variation = Vec::new();
        for alpha in [0.0, -0.1] {
            let coarse = run(&stiff_contact_scene(contact, dt, alpha));
            let label = format!("{contact}, α = {alpha}");
            assert_finite(&coarse, &label);
            let force = column(&coarse, "force");
            let (dynamic, mid, body) = (
                daf(&coarse, "mid"),
                quantity(&coarse, "mid").max_abs.value,
                quantity(&coarse, "sprung_acc").max_abs.value,
            );
            let (force_max, force_min) = (
                force.iter().copied().fold(f64::MIN, f64::max),
                force.iter().copied().fold(f64::MAX, f64::min),
            );
            let rms = step_variation_rms(force);
            eprintln!(
                "stiff {label}: ω_cΔt = {omega_dt:.1}, DAF {dynamic:.5} (Δt/8: {:.5}), \
                 mid max {mid:.5e} m ({:+.3} %), body acc max {body:.4} m/s² ({:+.3} %), \
                 force {force_min:.0}…{force_max:.0} N (static {load:.0}, Δt/8 max {:.0}), \
                 step-to-step force RMS {rms:.1} N",
                daf(&fine, "mid"),
                (mid / fine_mid - 1.0) * 100.0,
                (body / fine_body - 1.0) * 100.0,
                quantity(&fine, "force").max.value,
            );
            assert!(dynamic < 2.0, "{label}: DAF {dynamic}");
            assert!(
                force_min >= 0.0 && force_max < 3.0 * load,
                "{label}: force {force_min}…{force_max} N"
            );
            assert!(
                relative(mid, fine_mid) < 0.01,
                "{label}: mid-span max {mid} vs {fine_mid} at Δt/8"
            );
            assert!(
                relative(body, fine_body) < 0.02,
                "{label}: body acceleration max {body} vs {fine_body} at Δt/8"
            );
            variation.push(rms);
        }
        let ratio = variation[1] / variation[0];
        eprintln!("stiff {contact}: force variation RMS ratio α=−0.1 / α=0: {ratio:.3}");
        assert!(
            ratio < 0.6,
            "{contact}: HHT α = −0.1 should damp the unresolved contact oscillation: \
             step-to-step RMS {} vs {} N",
            variation[1],
            variation[0]
        );
    }
}

// 4.5 mm: the surface's downward acceleration a(2πv/λ)² = 71 m/s² exceeds
// the g + preload/m_u = 49 m/s² a plastically landed wheel needs to lift
// (at 3 mm, 47 m/s², it never lifts after the entrance kick).
const HOP_AMPLITUDE: f64 = 0.0045;

fn hopping_scene(dt: f64) -> String {
    format!(
        "name: hopping\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
         stiffness: 4.0e6, damping: 2.53e4, speed: 30.0}}]\n\
         surface: {{type: harmonic, amplitude: {HOP_AMPLITUDE}, wavelength: 1.5}}\n\
         contact: {{type: rigid}}\n\
         solver: {{time_step: {dt}, free_vibration: 0.2}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: force, quantity: contact_force}}, {{name: gap, quantity: contact_gap}}]\n"
    )
}

/// Contact-loss episodes as (start index, landing index, largest gap).
fn episodes(outcome: &Outcome) -> Vec<(usize, Option<usize>, f64)> {
    let (force, gap) = (column(outcome, "force"), column(outcome, "gap"));
    let mut list = Vec::new();
    let mut current: Option<(usize, f64)> = None;
    for i in 0..gap.len() {
        let apart = force[i] <= 0.0 && gap[i] > SEPARATION_GAP;
        current = match (current, apart) {
            (None, true) => Some((i, gap[i])),
            (Some((s, g)), true) => Some((s, g.max(gap[i]))),
            (Some((s, g)), false) => {
                list.push((s, Some(i), g));
                None
            }
            (None, false) => None,
        };
    }
    if let Some((s, g)) = current {
        list.push((s, None, g));
    }
    list
}

/// Hops whose largest gap exceeds 0.1 mm (3 % of the amplitude): the
/// physical flights, as opposed to sub-micrometre chatter.
fn hops(outcome: &Outcome) -> usize {
    episodes(outcome).iter().filter(|e| e.2 > 1.0e-4).count()
}

/// Case 2 — rigid LCP contact with repeated loss and regain of contact: the
/// LCP paper's oscillator at 30 m/s over a 4.5 mm, 1.5 m harmonic surface
/// (surface acceleration a(2πv/λ)² = 71 m/s², above the 49 m/s² the wheel
/// needs to lift), Moreau–Jean impacts with e = 0, Δt = 1e-4 s against Δt/4:
/// - at least 3 contact-loss episodes, contact force never negative;
/// - gaps finite and below 10× the amplitude (a wheel leaving at the largest
///   surface velocity v·2πa/λ = 0.57 m/s rises at most (0.57)²/2g = 16 mm
///   in free flight while the surface under it falls at most 2a = 9 mm);
/// - the largest gap within 10 % of the run at Δt/4.
///
/// Convergence of the episode counts, times and gaps: tests/it/moreau_jean.rs.
#[test]
fn rigid_contact_repeated_hops() {
    let dt = 1.0e-4;
    let coarse = run(&hopping_scene(dt));
    let fine = run(&hopping_scene(dt / 4.0));
    let mut max_gaps = Vec::new();
    for (label, outcome) in [("Δt", &coarse), ("Δt/4", &fine)] {
        assert_finite(outcome, label);
        let wheel = &outcome.summary.separation[0];
        let force = column(outcome, "force");
        let gap = column(outcome, "gap");
        eprintln!(
            "hopping {label}: {} episodes ({} hops > 0.1 mm), max gap {:.4e} m ({:.2} a), \
             time separated {:.4} s, min force {:.3e} N, mid-span DAF {:.4}",
            wheel.episodes,
            hops(outcome),
            wheel.max_gap,
            wheel.max_gap / HOP_AMPLITUDE,
            wheel.time_separated,
            force.iter().copied().fold(f64::MAX, f64::min),
            daf(outcome, "mid"),
        );
        assert!(wheel.episodes >= 3, "{label}: {wheel:?}");
        assert!(
            force.iter().all(|&f| f >= 0.0),
            "{label}: negative contact force"
        );
        assert!(
            gap.iter()
                .all(|g| g.is_finite() && *g < 10.0 * HOP_AMPLITUDE),
            "{label}: gap beyond 10 amplitudes: {}",
            wheel.max_gap
        );
        max_gaps.push(wheel.max_gap);
    }
    assert!(
        relative(max_gaps[0], max_gaps[1]) < 0.10,
        "max gap {} at Δt vs {} at Δt/4",
        max_gaps[0],
        max_gaps[1]
    );
}

/// Rigid landings are perfectly inelastic (docs/guide/contact.md: "with rigid contact a
/// landing wheel … leaves the step with the surface's vertical velocity"):
/// - after every landing the wheel stays on the surface or leaves it with a
///   relative velocity below 10 % of its approach velocity (a plastic
///   landing leaves it at rest relative to the surface);
/// - the first hop is converged: its largest gap within 1 % and its landing
///   time within 1 ms between Δt and Δt/4 (every hop is compared with an
///   event-driven reference in tests/it/moreau_jean.rs).
#[test]
fn rigid_landings_are_inelastic() {
    let dt = 1.0e-4;
    let coarse = run(&hopping_scene(dt));
    let fine = run(&hopping_scene(dt / 4.0));
    for (label, outcome, step) in [("Δt", &coarse, dt), ("Δt/4", &fine, dt / 4.0)] {
        let gap = column(outcome, "gap");
        for (start, landing, _) in episodes(outcome) {
            let Some(i) = landing else { continue };
            if i < start + 2 || i + 2 >= gap.len() {
                continue;
            }
            let approach = (gap[i - 2] - gap[i - 1]) / step;
            if approach < 0.05 {
                continue;
            }
            // The relative velocity leaving the landing step, by the
            // second-order one-sided difference (−3g₀ + 4g₁ − g₂)/2Δt: a
            // wheel that lands plastically and lifts off again at once
            // because the surface drops away faster than g (this surface is
            // marginal, see below) leaves at relative velocity 0 with a
            // relative acceleration, which a first difference over the next
            // steps would count as a rebound (measured at t = 0.0595 s:
            // gaps 0, 0.24, 1.19 µm — first difference 0.010 m/s, velocity
            // at the landing −0.001 m/s).
            let rebound = (-3.0 * gap[i] + 4.0 * gap[i + 1] - gap[i + 2]) / (2.0 * step);
            eprintln!(
                "landing {label} at t = {:.5} s: approach {approach:.3} m/s, rebound {rebound:.3} m/s",
                outcome.history.time[i]
            );
            assert!(
                rebound < 0.1 * approach,
                "{label}: the wheel landing at t = {:.5} s at {approach:.3} m/s leaves again at {rebound:.3} m/s",
                outcome.history.time[i]
            );
        }
    }
    let first = |o: &Outcome| {
        let (start, landing, gap) = episodes(o)[0];
        let _ = start;
        (gap, o.history.time[landing.expect("the first hop lands")])
    };
    let ((gap_a, land_a), (gap_b, land_b)) = (first(&coarse), first(&fine));
    eprintln!(
        "first hop: {gap_a:.5e} m landing at {land_a:.5} s (Δt), {gap_b:.5e} m at {land_b:.5} s (Δt/4)"
    );
    assert!(
        (gap_a - gap_b).abs() / gap_b < 0.01,
        "first hop {gap_a} vs {gap_b}"
    );
    assert!(
        (land_a - land_b).abs() < 1e-3,
        "first landing {land_a} vs {land_b}"
    );
}

// Frýba's beam (physics.rs): 25 m, f₁ = 4.78 Hz.
const FRYBA_SPAN: f64 = 25.0;
const FRYBA_EI: f64 = 8.323e9;
const FRYBA_MASS: f64 = 2303.0;
const FRYBA_FORCE: f64 = 1.0e5;

fn critical_scene(vehicle: &str, dt: f64, free_vibration: f64) -> String {
    format!(
        "name: critical\n\
         bridge: {{type: beam, spans: [{FRYBA_SPAN}], bending_stiffness: {FRYBA_EI}, \
         mass_per_length: {FRYBA_MASS}, modes: {{count: 12}}}}\n\
         vehicles: [{vehicle}]\n\
         solver: {{time_step: {dt}, free_vibration: {free_vibration}}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: {}}}, \
         {{name: force, quantity: contact_force}}]\n",
        FRYBA_SPAN / 2.0
    )
}

/// Case 3 — speeds at and above the critical resonance, velocity ratio
/// v/(2f₁L) = 1 and 2 (239 and 478 m/s on Frýba's 25 m beam), undamped, for
/// a moving force and an oscillator (mass ratio 0.2, unsprung ratio 0.25,
/// frequency ratio 0.5, no suspension damping), with 1.5 fundamental periods
/// of free vibration (above critical speed the maximum comes after the exit):
/// - finite;
/// - bounded: the moving force's DAF within 5e-4 of Frýba's closed form
///   (50 exact sine modes, tests/it/support; measured 1.3e-5 and 6.3e-5), and
///   the light oscillator's DAF within 15 % of the moving force's (measured
///   −5 % and −8 %: a physical bound, not an error);
/// - converged: DAF within 1e-3 of the run at Δt/4 (measured ≤ 2.0e-4).
#[test]
fn speeds_at_and_above_critical() {
    let f1 = exact::simply_supported_circular_frequency(1, FRYBA_SPAN, FRYBA_EI, FRYBA_MASS)
        / (2.0 * PI);
    let period = 1.0 / f1;
    for ratio in [1.0, 2.0] {
        let speed = ratio * 2.0 * f1 * FRYBA_SPAN;
        let free_vibration = 1.5 * period;
        let t_end = FRYBA_SPAN / speed + free_vibration;
        let dt = t_end / (2000.0 * t_end / period).ceil();
        let case = exact::MovingForceBeam {
            length: FRYBA_SPAN,
            bending_stiffness: FRYBA_EI,
            mass_per_length: FRYBA_MASS,
            damping_ratio: 0.0,
            force: FRYBA_FORCE,
            speed,
        };
        let reference = exact::moving_force_max_midspan(&case, 50, t_end).0
            / exact::static_midspan_deflection(FRYBA_FORCE, FRYBA_SPAN, FRYBA_EI);
        let force = format!("{{type: moving_force, loads: [{FRYBA_FORCE}], speed: {speed}}}");
        let oscillator = format!(
            "{{type: oscillator, dimensionless: {{velocity_ratio: {ratio}, mass_ratio: 0.2, \
             unsprung_ratio: 0.25, frequency_ratio: 0.5, damping_ratio: 0.0}}}}"
        );
        let mut dafs = Vec::new();
        for (name, vehicle) in [("moving force", &force), ("oscillator", &oscillator)] {
            let coarse = run(&critical_scene(vehicle, dt, free_vibration));
            let fine = run(&critical_scene(vehicle, dt / 4.0, free_vibration));
            assert_finite(&coarse, name);
            assert_finite(&fine, name);
            let (a, b) = (daf(&coarse, "mid"), daf(&fine, "mid"));
            eprintln!(
                "critical v/(2f₁L) = {ratio} ({speed:.1} m/s) {name}: DAF {a:.5} at Δt = {dt:.3e} s, \
                 {b:.5} at Δt/4 ({:+.4} %); Frýba {reference:.5}",
                (a / b - 1.0) * 100.0
            );
            assert!(relative(a, b) < 1e-3, "{name}, ratio {ratio}: {a} vs {b}");
            dafs.push(a);
        }
        assert!(
            relative(dafs[0], reference) < 5e-4,
            "ratio {ratio}: moving force DAF {} vs Frýba {reference}",
            dafs[0]
        );
        assert!(
            relative(dafs[1], dafs[0]) < 0.15,
            "ratio {ratio}: oscillator DAF {} vs moving force {}",
            dafs[1],
            dafs[0]
        );
    }
}

fn tail_scene(modes: usize, alpha: f64, dt: f64) -> String {
    format!(
        "name: tail\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: {modes}}}}}\n\
         vehicles: [{{type: moving_force, loads: [1.0e5], speed: 25.0}}]\n\
         solver: {{time_step: {dt}, free_vibration: 20.0, newmark: {{alpha: {alpha}}}}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}]\n"
    )
}

/// Largest |value| and RMS of `values` over the samples with time in [from, to].
fn window(time: &[f64], values: &[f64], from: f64, to: f64) -> (f64, f64) {
    let picked: Vec<f64> = time
        .iter()
        .zip(values)
        .filter(|(t, _)| (from - 1e-9..=to + 1e-9).contains(*t))
        .map(|(_, v)| *v)
        .collect();
    let rms = (picked.iter().map(|v| v * v).sum::<f64>() / picked.len() as f64).sqrt();
    (max_abs(&picked), rms)
}

/// Ratio (last 5 s / first 5 s of the tail) of the mid-span maximum and RMS.
fn tail_ratios(outcome: &Outcome, exit: f64) -> (f64, f64) {
    let time = &outcome.history.time;
    let mid = column(outcome, "mid");
    let end = *time.last().expect("samples");
    let first = window(time, mid, exit, exit + 5.0);
    let last = window(time, mid, end - 5.0, end);
    (last.0 / first.0, last.1 / first.1)
}

/// Free vibration of q̈ + ω²q = 0 under HHT-α (Hilber, Hughes & Taylor 1977,
/// written from the textbook equations, not from vbi): from q = 1, q̇ = 0,
/// the RMS ratio of the windows [span − 5 s, span] and [0, 5 s].
fn hht_free_vibration_rms_ratio(omega: f64, alpha: f64, dt: f64, span: f64) -> f64 {
    let (beta, gamma) = ((1.0 - alpha).powi(2) / 4.0, 0.5 - alpha);
    let w2 = omega * omega;
    let (mut q, mut v) = (1.0f64, 0.0f64);
    let mut a = -w2 * q;
    let steps = (span / dt).round() as usize;
    let mut values = vec![q];
    for _ in 0..steps {
        // a₁ + (1+α)ω²q₁ − αω²q₀ = 0 with q₁ = q₀ + Δt v₀ + Δt²((½−β)a₀ + βa₁).
        let predictor = q + dt * v + dt * dt * (0.5 - beta) * a;
        let a_new = (alpha * w2 * q - (1.0 + alpha) * w2 * predictor)
            / (1.0 + (1.0 + alpha) * w2 * beta * dt * dt);
        let q_new = predictor + dt * dt * beta * a_new;
        v += dt * ((1.0 - gamma) * a + gamma * a_new);
        (q, a) = (q_new, a_new);
        values.push(q);
    }
    let time: Vec<f64> = (0..=steps).map(|i| i as f64 * dt).collect();
    window(&time, &values, span - 5.0, span).1 / window(&time, &values, 0.0, 5.0).1
}

/// Case 4 — no structural damping, 20 s of free vibration after a 100 kN
/// force crosses the 20 m beam at 25 m/s (Δt = 2 ms, 5 modes):
/// - finite;
/// - bounded, average-acceleration Newmark (α = 0) conserves each mode's
///   energy exactly (it is the trapezoidal rule, a Cayley transform), so the
///   mid-span amplitude neither grows nor decays: max over the last 5 s
///   within [0.999, 1.001] × the max over the first 5 s after the exit;
/// - with HHT α = −0.05 it decays (ratio < 0.999), and for a single mode the
///   decay of the RMS over the windows matches an independent HHT recurrence
///   for that mode's frequency within 2 % of the decrement (measured 0.3 %:
///   6.567e-4 against 6.587e-4).
#[test]
fn undamped_free_vibration_tail() {
    let (dt, exit) = (2.0e-3, SPAN / 25.0);
    let plain = run(&tail_scene(5, 0.0, dt));
    assert_finite(&plain, "α = 0");
    let (max_ratio, rms_ratio) = tail_ratios(&plain, exit);
    eprintln!("tail α = 0, 5 modes: last/first 5 s max {max_ratio:.6}, RMS {rms_ratio:.6}");
    assert!(
        (0.999..=1.001).contains(&max_ratio),
        "undamped tail amplitude ratio {max_ratio}"
    );

    let hht = run(&tail_scene(5, -0.05, dt));
    assert_finite(&hht, "α = −0.05");
    let (max_ratio, _) = tail_ratios(&hht, exit);
    eprintln!("tail α = −0.05, 5 modes: last/first 5 s max {max_ratio:.6}");
    assert!(max_ratio < 0.999, "HHT tail does not decay: {max_ratio}");

    let single = run(&tail_scene(1, -0.05, dt));
    assert_finite(&single, "α = −0.05, 1 mode");
    let end = *single.history.time.last().expect("samples");
    let omega = 2.0 * PI * single.summary.run.frequencies[0];
    let expected = hht_free_vibration_rms_ratio(omega, -0.05, dt, end - exit);
    let (_, measured) = tail_ratios(&single, exit);
    eprintln!(
        "tail α = −0.05, 1 mode (ωΔt = {:.4}): RMS ratio {measured:.7}, HHT recurrence {expected:.7}",
        omega * dt
    );
    assert!(
        ((1.0 - measured) - (1.0 - expected)).abs() < 0.02 * (1.0 - expected),
        "HHT decay {measured} vs {expected}"
    );
}

const VIADUCT_SPAN: f64 = 30.0;
const VIADUCT_EI: f64 = 1.0e10;
const VIADUCT_MASS: f64 = 1.0e4;

fn viaduct_scene(modes: usize) -> String {
    format!(
        "name: viaduct\n\
         bridge: {{type: beam, spans: [{}], bending_stiffness: {VIADUCT_EI}, \
         mass_per_length: {VIADUCT_MASS}, elements_per_span: 10, modes: {{count: {modes}}}}}\n\
         vehicles: [{{type: moving_force, loads: [2.0e5], speed: 60.0}}]\n\
         solver: {{time_step: 1.0e-3}}\n\
         record: [{{name: span15, quantity: bridge_displacement, x: {}}}]\n",
        vec![VIADUCT_SPAN.to_string(); 30].join(", "),
        14.5 * VIADUCT_SPAN
    )
}

/// Case 5 — a 30 × 30 m continuous beam on pinned supports, 10 Hermite
/// elements per span (571 free DOFs, well under the resolver's 20 000), 300
/// modes (up to 215 Hz, ωΔt = 1.35 at Δt = 1 ms), crossed by a 200 kN force at
/// 60 m/s (velocity ratio 0.57, near the single span's worst case):
/// - frequencies ascending; the first equals the single span's
///   (π/L)²√(EI/m)/2π within 5e-5 (measured 6.8e-6; a mode with a node at
///   every support is the simply supported span mode, and it is the lowest),
///   and the lowest of the second band (31st mode) the span's second mode
///   within 1e-3 (measured 1.07e-4, 20 elements per span);
/// - mid-span of the 15th span: finite, DAF < 2 (a constant force crossing
///   once cannot exceed Frýba's single-span maximum of about 1.74 by much;
///   measured 1.29), and within 0.3 % of the run with 150 modes (measured
///   0.045 %).
#[test]
fn thirty_span_viaduct_with_three_hundred_modes() {
    let full = run(&viaduct_scene(300));
    let reduced = run(&viaduct_scene(150));
    assert_finite(&full, "300 modes");
    assert_finite(&reduced, "150 modes");
    let info = &full.summary.run;
    assert_eq!(info.modes_used, 300);
    let f = &info.frequencies;
    assert!(
        f.windows(2).all(|w| w[0] <= w[1]),
        "frequencies not ascending"
    );
    let span_mode = |j: usize| {
        exact::simply_supported_circular_frequency(j, VIADUCT_SPAN, VIADUCT_EI, VIADUCT_MASS)
            / (2.0 * PI)
    };
    let (a, b) = (daf(&full, "span15"), daf(&reduced, "span15"));
    eprintln!(
        "viaduct: {} of {} modes, {:.4}…{:.2} Hz; f₁ {:.6} Hz vs span {:.6} ({:.2e}); \
         f₃₁ {:.5} vs span f₂ {:.5} ({:.2e}); DAF span 15: {a:.5} (300 modes), {b:.5} (150), \
         {:+.3} %; wall {:.2} s + {:.2} s",
        info.modes_used,
        info.modes_available,
        f[0],
        f[f.len() - 1],
        f[0],
        span_mode(1),
        relative(f[0], span_mode(1)),
        f[30],
        span_mode(2),
        relative(f[30], span_mode(2)),
        (a / b - 1.0) * 100.0,
        info.wall_time,
        reduced.summary.run.wall_time,
    );
    assert!(relative(f[0], span_mode(1)) < 5e-5, "f₁ = {}", f[0]);
    assert!(relative(f[30], span_mode(2)) < 1e-3, "f₃₁ = {}", f[30]);
    assert!(a < 2.0, "DAF {a}");
    assert!(relative(a, b) < 3e-3, "DAF {a} (300 modes) vs {b} (150)");
}

fn mass_ratio_scene(vehicle: &str, dt: f64) -> String {
    format!(
        "name: mass-ratio\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}}}\n\
         vehicles: [{vehicle}]\n\
         solver: {{time_step: {dt}, free_vibration: 0.5}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: force, quantity: contact_force}}, \
         {{name: mid_acc, quantity: bridge_acceleration, x: 10.0}}]\n"
    )
}

/// Case 6 — extreme vehicle-to-bridge mass ratios on the undamped 20 m beam
/// (m L = 40 000 kg), permanent contact:
/// - 1 kg oscillator (0.8 kg body at 5 Hz, 0.2 kg wheel; mass ratio 2.5e-5):
///   the bridge barely moves (0.57 µm) and cannot shake the vehicle, so the
///   contact force equals the weight within 2e-4 (measured 2.7e-5) and the
///   mid-span history equals that of a 9.81 N moving force within 1e-3 of
///   its peak (measured 1.2e-4);
/// - oscillator as heavy as the bridge (mass ratio 1, velocity ratio 0.2,
///   frequency ratio 0.5, 10 % suspension damping): finite, bounded (DAF < 2,
///   contact force between 0 and 2× the static wheel load: measured DAF 1.35
///   and 0.66–1.27× static), and the maxima of mid-span deflection and
///   acceleration and of the contact force within 2 % of the run at Δt/4
///   (measured ≤ 0.21 %, the acceleration).
#[test]
fn extreme_mass_ratios() {
    let dt = 1.0e-3;
    let tiny = run(&mass_ratio_scene(
        "{type: oscillator, sprung_mass: 0.8, unsprung_mass: 0.2, stiffness: 790.0, \
         damping: 2.5, speed: 25.0}",
        dt,
    ));
    let load = run(&mass_ratio_scene(
        "{type: moving_force, loads: [9.81], speed: 25.0}",
        dt,
    ));
    assert_finite(&tiny, "1 kg oscillator");
    let weight = 9.81;
    let force_deviation = column(&tiny, "force")
        .iter()
        .fold(0.0f64, |m, f| m.max((f - weight).abs()))
        / weight;
    let (w, w_load) = (column(&tiny, "mid"), column(&load, "mid"));
    let deflection_deviation = w
        .iter()
        .zip(w_load)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
        / max_abs(w_load);
    eprintln!(
        "mass ratio 2.5e-5: contact force within {force_deviation:.2e} of the weight, \
         mid-span max {:.4e} m, history within {deflection_deviation:.2e} of a moving force",
        max_abs(w)
    );
    assert!(force_deviation < 2e-4, "{force_deviation}");
    assert!(deflection_deviation < 1e-3, "{deflection_deviation}");

    let heavy = "{type: oscillator, dimensionless: {velocity_ratio: 0.2, mass_ratio: 1.0, \
                 unsprung_ratio: 0.25, frequency_ratio: 0.5, damping_ratio: 0.1}}";
    let coarse = run(&mass_ratio_scene(heavy, dt));
    let fine = run(&mass_ratio_scene(heavy, dt / 4.0));
    assert_finite(&coarse, "heavy");
    assert_finite(&fine, "heavy, Δt/4");
    let static_load = coarse.model.static_wheel_loads[0];
    let force = quantity(&coarse, "force");
    eprintln!(
        "mass ratio 1: DAF {:.5} (Δt/4 {:.5}), force {:.4e}…{:.4e} N (static {static_load:.4e})",
        daf(&coarse, "mid"),
        daf(&fine, "mid"),
        force.min.value,
        force.max.value
    );
    assert!(daf(&coarse, "mid") < 2.0);
    assert!(force.min.value > 0.0 && force.max.value < 2.0 * static_load);
    for (name, pick) in [
        (
            "mid",
            (|q: &QuantitySummary| q.max_abs.value) as fn(&QuantitySummary) -> f64,
        ),
        ("mid_acc", |q| q.max_abs.value),
        ("force", |q| q.max.value),
        ("force", |q| q.min.value),
    ] {
        let (a, b) = (pick(quantity(&coarse, name)), pick(quantity(&fine, name)));
        eprintln!(
            "mass ratio 1: {name} {a:.5e} vs {b:.5e} at Δt/4 ({:+.3} %)",
            (a / b - 1.0) * 100.0
        );
        assert!(relative(a, b) < 0.02, "{name}: {a} vs {b}");
    }
}

fn newmark_scene(beta: f64, dt: f64) -> String {
    format!(
        "name: newmark\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}}}\n\
         vehicles: [{{type: moving_force, loads: [1.0e5], speed: 25.0}}]\n\
         solver: {{time_step: {dt}, free_vibration: 0.5, newmark: {{beta: {beta}, gamma: 0.5}}}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}]\n"
    )
}

/// Case 7 — a conditionally stable Newmark variant on both sides of its limit.
/// The resolver rejects β = 0 (explicit central difference), so β = 0.01,
/// γ = 0.5: undamped, stable for ωΔt ≤ 1/√(γ/2 − β) = 2.041 (Bathe, Table
/// 9.3; the amplification matrix's trace leaves [−2, 2] beyond it). With 10
/// modes of the 20 m beam (highest 502 Hz) the limit is Δt = 6.47e-4 s.
/// - at 0.9× the limit: finite, DAF < 2 and within 1e-3 of
///   average-acceleration Newmark at the same step (measured 1.05e-4);
/// - at 1.02× and 2× the limit: the run returns an error (not results with
///   huge numbers), a divergence stopped early (before a tenth of the run),
///   whose message names the time and the likely cause (the time step with
///   these Newmark parameters).
#[test]
fn conditionally_stable_newmark_limit() {
    let reference = run(&newmark_scene(0.25, 1.0e-4));
    let omega_max = 2.0 * PI * reference.summary.run.frequencies.last().expect("modes");
    let limit = 1.0 / (0.25f64 - 0.01).sqrt() / omega_max;

    let dt = 0.9 * limit;
    let stable = run(&newmark_scene(0.01, dt));
    let average = run(&newmark_scene(0.25, dt));
    assert_finite(&stable, "β = 0.01 below the limit");
    let (a, b) = (daf(&stable, "mid"), daf(&average, "mid"));
    eprintln!(
        "Newmark β = 0.01: limit Δt = {limit:.4e} s (f_max {:.1} Hz); at 0.9× DAF {a:.6} vs {b:.6} (β = 1/4)",
        omega_max / (2.0 * PI)
    );
    assert!(a < 2.0 && relative(a, b) < 1e-3, "DAF {a} vs {b}");

    for factor in [1.02, 2.0] {
        let dt = factor * limit;
        let end = average.model.end_time();
        match try_run(&newmark_scene(0.01, dt)) {
            Ok(outcome) => panic!(
                "{factor}× the stability limit returned Ok (finite: {}, max |w| {:e} m)",
                outcome
                    .history
                    .columns
                    .iter()
                    .all(|c| c.values.iter().all(|v| v.is_finite())),
                quantity(&outcome, "mid").max_abs.value
            ),
            Err(error) => {
                let message = error.to_string();
                eprintln!("Newmark β = 0.01 at {factor}× the limit: {message}");
                match error {
                    RunError::Solve(SolveError::Diverged { time, .. }) => {
                        assert!(
                            time > 0.0 && time < 0.1 * end,
                            "stopped at {time} of {end} s"
                        )
                    }
                    other => panic!("expected a divergence, got {other:?}"),
                }
                assert!(message.contains("t = "), "{message}");
                assert!(message.contains("time step"), "{message}");
                assert!(message.contains("β = 0.01"), "{message}");
            }
        }
    }
}

// Rigid hopping statistics converge (Moreau–Jean impacts, issue 29): see
// tests/it/moreau_jean.rs.
