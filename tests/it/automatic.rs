//! Modelling only what a scene needs: the automatic mode cut-off and time
//! step, their reasons in the summary, and user overrides.

use crate::support;

use support::max_abs;
use support::reference as exact;
use vbi::plan::load_str;
use vbi::run::{Outcome, simulate};

fn run(text: &str) -> Outcome {
    let loaded = load_str(text, "test.yaml").unwrap_or_else(|e| panic!("{e}"));
    simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

fn yang_yau(modes: &str, time_step: &str) -> String {
    format!(
        "name: yy\nbridge: {{type: beam, spans: [25.0], bending_stiffness: 8.323e9, mass_per_length: 2303.0{modes}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 5750.0, stiffness: 1.595e6, speed: 27.777777777777778}}]\n\
         solver: {{free_vibration: 0.0{time_step}}}\n\
         record:\n\
         - {{name: midspan, quantity: bridge_displacement, x: 12.5}}\n\
         - {{name: body_acceleration, quantity: vehicle_acceleration, dof: sprung}}\n"
    )
}

fn peak(outcome: &Outcome, name: &str) -> f64 {
    outcome
        .summary
        .quantities
        .iter()
        .find(|q| q.name == name)
        .map(|q| q.max_abs.value.abs())
        .expect("recorded")
}

/// The automatic cut-off keeps the Yang & Yau (1997) benchmark within 0.5 %
/// of the independent reference (tests/it/support: 40 analytic modes, RK4 at
/// 5e-6 s) on both the mid-span deflection and the vehicle acceleration, with
/// fewer modes than a generous fixed count (40), at the scenario's step and
/// at the automatic step; the summary says how many modes and why.
#[test]
fn automatic_modes_keep_yang_yau_within_half_a_percent() {
    let case = exact::yang_yau_1997();
    let reference = exact::sprung_mass_reference(&case, 40, 5e-6, case.crossing_time());
    let deflection = max_abs(&reference.midspan_deflection);
    let acceleration = max_abs(&reference.vehicle_acceleration);
    let generous = run(&yang_yau(", modes: {count: 40}", ", time_step: 1.0e-4"));
    for step in [", time_step: 1.0e-4", ""] {
        let automatic = run(&yang_yau("", step));
        let used = automatic.summary.run.modes_used;
        assert!(used < generous.summary.run.modes_used, "{used} modes");
        assert!(
            automatic
                .summary
                .run
                .modes_selection
                .starts_with("automatic")
        );
        for (name, exact_peak) in [("midspan", deflection), ("body_acceleration", acceleration)] {
            let error = (peak(&automatic, name) - exact_peak).abs() / exact_peak;
            eprintln!(
                "{name}{step}: {used} automatic modes, Δt = {:.3e} s, error {:.3} %",
                automatic.summary.run.time_step,
                error * 100.0
            );
            assert!(error < 0.005, "{name}{step}: {:.3} %", error * 100.0);
        }
    }
}

/// The cut-off follows the excitation: a stiff elastic contact adds the wheel
/// hop (√(k_c/m_u)/2π = 50 Hz for 1e8 N/m under 1000 kg) and roughness adds
/// v/λ, so more modes are kept (cut-off ≥ 4 × 50 Hz) and the default step
/// resolves the hop with ≥ 20 steps per period; the cut-off is written back
/// as `max_frequency` so the resolved scenario reproduces the choice.
#[test]
fn cutoff_and_step_follow_the_excitation() {
    let scene = |contact: &str| {
        format!(
            "name: hop\nbridge: {{type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0}}\n\
             vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}}]\n\
             contact: {contact}\n"
        )
    };
    let permanent = load_str(&scene("{type: permanent}"), "a").expect("valid");
    let elastic = load_str(&scene("{type: elastic, stiffness: 1.0e8}"), "b").expect("valid");
    let hop = (1.0e8f64 / 1000.0).sqrt() / (2.0 * std::f64::consts::PI);
    let cutoff = elastic
        .scenario
        .bridge
        .modes()
        .max_frequency
        .expect("written back");
    assert!(cutoff >= 4.0 * hop, "cut-off {cutoff} Hz");
    assert!(elastic.bridge.mode_count() > permanent.bridge.mode_count());
    let top = elastic
        .bridge
        .frequencies()
        .last()
        .copied()
        .unwrap()
        .max(hop);
    assert!(elastic.scenario.solver.time_step <= 1.0 / (20.0 * top) * (1.0 + 1e-12));
    assert!(elastic.scenario.solver.time_step < permanent.scenario.solver.time_step);
}

/// Every automatic choice can be overridden: an explicit mode count and time
/// step are used as given and reported as requested.
#[test]
fn explicit_choices_override_the_automatic_ones() {
    let outcome = run(&yang_yau(", modes: {count: 7}", ", time_step: 2.0e-4"));
    assert_eq!(outcome.summary.run.modes_used, 7);
    assert_eq!(outcome.summary.run.time_step, 2.0e-4);
    assert!(outcome.summary.run.modes_selection.starts_with("requested"));
}

/// A deck acceleration sums every mode up to its filter (EN 1990
/// A2.4.4.2.1, here 30 Hz); `bridge.modes` set below it leaves the modes
/// between out of the sum, and the run says so. Three 25 m spans of the
/// Yang & Yau beam (f₁ = 4.78 Hz; the first bending group ends near 9 Hz,
/// the second starts at 19 Hz): the lowest three modes against every mode
/// to 30 Hz, two axles at 200 km/h.
#[test]
fn a_deck_acceleration_filter_above_the_modes_kept_is_named() {
    let scene = |modes: &str| {
        format!(
            "name: filter\nbridge: {{type: beam, spans: [25.0, 25.0, 25.0], bending_stiffness: 8.323e9, \
             mass_per_length: 2303.0, modes: {modes}}}\n\
             vehicles: [{{type: moving_force, loads: [170.0e3, 170.0e3], axle_spacings: [3.0], speed: 200 km/h}}]\n\
             solver: {{free_vibration: 0.2}}\n\
             record:\n\
             - {{name: acc, quantity: bridge_acceleration, x: 6.25, max_frequency: 30.0}}\n"
        )
    };
    let warned = |modes: &str| {
        let loaded = load_str(&scene(modes), "test.yaml").unwrap_or_else(|e| panic!("{e}"));
        let outcome = simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
        let warnings = vbi::advice::texts(&outcome.summary.advice);
        let named: Vec<String> = warnings
            .into_iter()
            .filter(|w| w.contains("`acc` (30 Hz)") && w.contains("missing from it"))
            .collect();
        (
            peak(&outcome, "acc"),
            outcome.summary.run.frequencies.clone(),
            named,
        )
    };
    let (few, few_frequencies, few_named) = warned("{count: 3}");
    let (all, all_frequencies, all_named) = warned("{max_frequency: 30.0}");
    assert_eq!(few_named.len(), 1, "{few_named:?}");
    assert!(
        few_named[0].contains(&format!("up to {:.2} Hz", few_frequencies[2])),
        "{few_named:?}"
    );
    assert!(
        few_named[0].contains(&format!(
            "of the {} it has up to 30 Hz",
            all_frequencies.len()
        )),
        "{few_named:?}"
    );
    assert!(all_named.is_empty(), "{all_named:?}");
    assert!(all_frequencies.len() > 3 && *all_frequencies.last().unwrap() <= 30.0);
    // What the warning is about: the modes left out move the peak.
    let moved = (few - all).abs() / all;
    eprintln!(
        "3 modes {few:.4} m/s², {} modes {all:.4} m/s²: {moved:.3}",
        all_frequencies.len()
    );
    assert!(moved > 0.05, "{moved}");
}
