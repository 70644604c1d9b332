//! Speeds as engineers write them: `speed: 72 km/h` runs exactly the scene
//! `speed: 20.0` (m/s) runs, the resolved scenario shows m/s, a bad unit is a
//! located error, and implausible speeds and records that end before the
//! response peaks are warned about.

use vbi::advice::texts;
use vbi::plan::advice::scene_advice;
use vbi::plan::load_str;

fn scene_warnings(scenario: &vbi::scene::Scenario) -> Vec<String> {
    texts(&scene_advice(scenario))
}
use crate::support::{column, max_abs, run_yaml};
use vbi::run::Outcome;

/// The histories `names` of two runs agree everywhere to `tolerance` × the
/// peak of `reference`'s, which is not zero ([`support::assert_histories_agree`]).
fn assert_histories_agree(run: &Outcome, reference: &Outcome, names: &[&str], tolerance: f64) {
    for name in names {
        assert!(
            max_abs(column(reference, name)) > 0.0,
            "{name}: no response"
        );
    }
    crate::support::assert_histories_agree(run, reference, names, tolerance);
}

/// The Yang & Yau (1997) beam (L = 25 m, f₁ = 4.7779 Hz) under one moving
/// force; `SPEED` and `FREE` are replaced per case.
const SCENE: &str = "\
name: units
bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
  modes: {count: 6}
vehicles:
  - type: moving_force
    loads: [100.0e3]
    speed: SPEED
  - type: oscillator
    sprung_mass: 5750.0
    stiffness: 1.595e6
    speed: SPEED
    entry_time: 0.2
solver: {time_step: 1.0e-3, free_vibration: FREE}
record:
  - {name: midspan, quantity: bridge_displacement, x: 12.5}
  - {name: body, quantity: vehicle_displacement, vehicle: 2, dof: sprung}
";

fn scene(speed: &str, free_vibration: f64) -> String {
    SCENE
        .replace("SPEED", speed)
        .replace("FREE", &free_vibration.to_string())
}

#[test]
fn km_h_and_m_s_give_the_same_run() {
    let in_m_s = run_yaml(&scene("20.0", 0.1));
    for written in ["72 km/h", "72km/h", "'72 km/h'", "20 m/s"] {
        let other = run_yaml(&scene(written, 0.1));
        // 72 km/h = 20 m/s up to one rounding of 72 × (1000/3600).
        assert_eq!(
            in_m_s.history.time.len(),
            other.history.time.len(),
            "{written}"
        );
        assert_histories_agree(&other, &in_m_s, &["midspan", "body"], 1e-12);
    }
}

#[test]
fn the_resolved_scenario_shows_m_s() {
    let loaded = load_str(&scene("90 km/h", 0.1), "units.yaml").unwrap_or_else(|e| panic!("{e}"));
    for v in &loaded.scenario.vehicles {
        assert!((v.speed() - 25.0).abs() < 1e-12, "{}", v.speed());
    }
    let yaml = vbi::run::resolved_yaml(&loaded.scenario);
    assert!(!yaml.contains("km/h"), "{yaml}");
    assert_eq!(yaml.matches("speed: 25.0").count(), 2, "{yaml}");
}

#[test]
fn a_speed_with_an_unknown_unit_is_a_located_error() {
    for (written, says) in [
        ("72 mph", "km/h"),
        ("fast km/h", "not a number"),
        ("[72]", "speed"),
    ] {
        let err = load_str(&scene(written, 0.1), "units.yaml")
            .err()
            .unwrap_or_else(|| panic!("`{written}` accepted"))
            .to_string();
        assert!(err.starts_with("units.yaml:11:12: "), "{written}: {err}");
        assert!(err.contains(says), "{written}: {err}");
    }
}

#[test]
fn implausible_speeds_are_warned_about() {
    // 300 m/s (1080 km/h) is surely a km/h value; 300 km/h is a fast train.
    let fast = load_str(&scene("300", 0.1), "units.yaml").unwrap_or_else(|e| panic!("{e}"));
    let warnings = scene_warnings(&fast.scenario);
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert!(warnings[0].contains("1080 km/h") && warnings[0].contains("`speed: 300 km/h`"));
    let train = load_str(&scene("300 km/h", 0.1), "units.yaml").unwrap_or_else(|e| panic!("{e}"));
    assert!(scene_warnings(&train.scenario).is_empty());
    // Written with its unit, 300 m/s is meant (a moving force at a stiff
    // beam's critical speed 2 f₁ L, scenarios/moving-force-critical.yaml):
    // no warning. The bare number's warning says how to state it.
    assert!(
        warnings[0].contains("write `speed: 300 m/s`"),
        "{warnings:?}"
    );
    let meant = load_str(&scene("300 m/s", 0.1), "units.yaml").unwrap_or_else(|e| panic!("{e}"));
    assert!(scene_warnings(&meant.scenario).is_empty());
}

/// Above the critical speed v_cr = 2 f₁ L = 238.9 m/s the largest deflection
/// comes after the force has left the span (Frýba, Vibration of Solids and
/// Structures under Moving Loads, 1972, §1.3: for α > 1 the maximum lies in
/// the free-vibration phase). At α = 2 a record without free vibration ends
/// with the midspan still deflecting further; one period more catches the peak.
#[test]
fn a_record_that_ends_before_the_peak_is_warned_about() {
    let force_only = |free: f64| {
        SCENE
            .replace(
                "  - type: oscillator\n    sprung_mass: 5750.0\n    stiffness: 1.595e6\n    speed: SPEED\n    entry_time: 0.2\n",
                "",
            )
            .replace(
                "  - {name: body, quantity: vehicle_displacement, vehicle: 2, dof: sprung}\n",
                "",
            )
            .replace("time_step: 1.0e-3", "time_step: 1.0e-4")
            .replace("SPEED", "477.8")
            .replace("FREE", &free.to_string())
    };
    let short = force_only(0.0);
    let outcome = run_yaml(&short);
    let loaded = load_str(&short, "units.yaml").unwrap();
    let warnings = texts(&vbi::report::advice::run_advice(
        &loaded.scenario,
        &outcome.summary,
    ));
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(
        warnings[0].starts_with("`midspan` is largest at the very end"),
        "{warnings:?}"
    );
    let long = force_only(0.25);
    let outcome = run_yaml(&long);
    let loaded = load_str(&long, "units.yaml").unwrap();
    assert!(vbi::report::advice::run_advice(&loaded.scenario, &outcome.summary).is_empty());
}

#[test]
fn a_speed_sweep_takes_km_h_too() {
    let sweep = |speeds: &str| {
        let text = format!(
            "{}study:\n  type: speed_sweep\n  speeds: {speeds}\n",
            scene("20.0", 0.1)
        );
        let loaded = load_str(&text, "units.yaml").unwrap_or_else(|e| panic!("{e}"));
        vbi::run::resolved_yaml(&loaded.scenario)
    };
    let in_km_h = sweep("{from: 36 km/h, to: 144 km/h, count: 4}");
    assert_eq!(in_km_h, sweep("{from: 10.0, to: 40.0, count: 4}"));
    assert!(
        in_km_h.contains("from: 10.0") && in_km_h.contains("to: 40.0"),
        "{in_km_h}"
    );
}
