//! Issue 38, point 5: automatic choices never lower accuracy quietly. Every
//! shipped example and `vbi init` starter is right at its own settings: its
//! headline peaks are within 0.5 % of the converged answer, and the
//! deck-acceleration filter it applies by default is the EN 1990 one of the
//! bridge itself, max(30 Hz, 1.5 f₁, f₃) (EN 1990 A2.4.4.2.1(4); EN 1991-2
//! 6.4.6.5(3)), whatever `bridge.modes` keeps.
//!
//! The converged answer is the scene at a finer step and with more modes,
//! as `vbi converge` builds its reference (Δt/4 and 2N modes,
//! src/study/converge.rs), with the modes reaching at least twice the count
//! up to the highest acceleration filter (a filter above the kept modes
//! sums modes that 2N may not reach), and the scene's default filters
//! resolved from the bridge's lowest three modes (the reference's `modes:`
//! is a count of at least 3, so its f₃ is a kept mode's).
//!
//! The headline peaks: a single scene's largest |value| of every record; a
//! resonance check's largest deck acceleration and displacement of every
//! train (what its verdict reads). Tolerance 0.5 %, the accuracy target of
//! the automatic choices (tests/it/automatic_shipped.rs).
//!
//! Run here: the railway example (the one that capped its modes) and every
//! starter, 26 s on 2 cores. The other examples set no `bridge.modes`
//! (the automatic choice keeps every mode up to their filters) and were
//! checked by hand with `vbi converge --levels 1` (worst recorded
//! quantity's max-abs error over the history at the scene's own step and
//! modes against Δt/4 and 2N modes, a stricter measure than the peak):
//! road-bridge-check 0.055 % (pier_moment), seismic-crossing 0.391 %
//! (body_acceleration), separation-study's scene 0.060 % (wheel1_force),
//! imported-fe/scene 0.000 %.

use std::path::Path;

use vbi::bridge::{ModalBridge, ModeRequest};
use vbi::execute::{Results, execute};
use vbi::init::{StarterBridge, StarterVehicle, starter};
use vbi::plan::{self, Loaded};
use vbi::scenario::resolved::{Quantity, Study};

/// The accuracy target of the automatic choices (summary's
/// `accuracy_target`).
const TOLERANCE: f64 = 0.005;

/// The scene's text with its `bridge.modes` line replaced by
/// `modes: {modes}` (one added under `bridge:` if it has none).
fn with_modes(text: &str, modes: &str) -> String {
    let has = text.lines().any(|l| l.trim_start().starts_with("modes:"));
    let mut out = String::with_capacity(text.len() + 40);
    for line in text.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("modes:") {
            let indent = &line[..line.len() - trimmed.len()];
            out.push_str(&format!("{indent}modes: {modes}\n"));
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if !has && line == "bridge:" {
            out.push_str(&format!("  modes: {modes}\n"));
        }
    }
    out
}

/// The highest deck-acceleration filter the scene applies, Hz (`None`
/// without deck accelerations).
fn highest_filter(loaded: &Loaded) -> Option<f64> {
    let scenario = &loaded.scenario;
    let records = scenario
        .record
        .iter()
        .filter(|r| r.quantity == Quantity::BridgeAcceleration)
        .filter_map(|r| r.max_frequency);
    let envelope = scenario
        .envelopes
        .iter()
        .filter(|e| e.quantities.contains(&Quantity::BridgeAcceleration))
        .filter_map(|e| e.max_frequency);
    let study = match &scenario.study {
        Some(Study::ResonanceCheck(check)) => Some(check.max_frequency),
        _ => None,
    };
    records.chain(envelope).chain(study).reduce(f64::max)
}

/// The converged reference of the scene `text` (loaded as `file`) whose
/// plan is `loaded`: Δt/4 and max(2N, 2 × the modes up to the highest
/// filter) modes, the default filters from the bridge's own f₁ and f₃.
fn reference(text: &str, file: &str, loaded: &Loaded) -> Loaded {
    let three = plan::load_str(&with_modes(text, "{count: 3}"), file)
        .unwrap_or_else(|e| panic!("{file} with 3 modes: {e}"));
    let mut scenario = three.scenario.clone();
    let available = loaded.bridge.available_modes;
    let to_filter = highest_filter(&three)
        .and_then(|f| ModalBridge::count_up_to(&scenario.bridge, f).ok().flatten())
        .unwrap_or(0);
    let modes = (2 * loaded.bridge.mode_count())
        .max(2 * to_filter)
        .min(available);
    scenario.solver.time_step = loaded.scenario.solver.time_step / 4.0;
    let m = scenario.bridge.modes_mut();
    m.count = Some(modes);
    m.max_frequency = None;
    let bridge = ModalBridge::build(&scenario.bridge).unwrap();
    Loaded { scenario, bridge }
}

/// The headline peaks of a result: (what, value).
fn headline(results: &Results) -> Vec<(String, f64)> {
    match results {
        Results::Scene(outcome) => outcome
            .summary
            .quantities
            .iter()
            .map(|q| (q.name.clone(), q.max_abs.value.abs()))
            .collect(),
        Results::ResonanceCheck(check) => {
            let mut out = Vec::new();
            for (t, train) in check.trains.iter().enumerate() {
                let points = check.points.iter().filter(|p| p.train == t);
                let (a, u) = points.fold((0.0f64, 0.0f64), |(a, u), p| {
                    (a.max(p.max_acceleration), u.max(p.max_displacement))
                });
                out.push((format!("{train} deck acceleration"), a));
                out.push((format!("{train} deck displacement"), u));
            }
            out
        }
        _ => panic!("no headline peaks defined for this study"),
    }
}

/// Runs `text` at its own settings and at the converged reference; returns
/// the failures (empty: every headline peak within [`TOLERANCE`]) and the
/// figures, for the message.
fn compare(text: &str, file: &str) -> (Vec<String>, Vec<String>) {
    let start = std::time::Instant::now();
    let loaded = plan::load_str(text, file).unwrap_or_else(|e| panic!("{file}: {e}"));
    let fine = reference(text, file, &loaded);
    let label = format!(
        "{file} ({} modes, dt {:.3e} s; reference {} modes, dt {:.3e} s)",
        loaded.bridge.mode_count(),
        loaded.scenario.solver.time_step,
        fine.bridge.mode_count(),
        fine.scenario.solver.time_step
    );
    let scenario = loaded.scenario.clone();
    let results = execute(loaded, &|_, _| {}).unwrap();
    // Right at its own settings, and nothing to warn about the filter.
    let said: Vec<_> = results
        .advice(&scenario)
        .into_iter()
        .filter(|a| a.id == FILTER_ABOVE_MODES)
        .map(|a| a.message)
        .collect();
    assert!(said.is_empty(), "{label}: {said:?}");
    let own = headline(&results);
    let converged = headline(&execute(fine, &|_, _| {}).unwrap());
    let (mut failures, mut figures) = (Vec::new(), Vec::new());
    for ((name, value), (_, reference)) in own.iter().zip(&converged) {
        let error = (value - reference).abs() / reference.abs().max(f64::MIN_POSITIVE);
        let line = format!(
            "{label}: {name} {value:.6e} against {reference:.6e} ({:.3} %)",
            100.0 * error
        );
        eprintln!("{line}");
        if error.is_nan() || error > TOLERANCE {
            failures.push(line.clone());
        }
        figures.push(line);
    }
    assert_eq!(own.len(), converged.len(), "{label}");
    eprintln!("{label}: {:.1} s", start.elapsed().as_secs_f64());
    (failures, figures)
}

/// The bridge's own lowest three frequencies, Hz, whatever `bridge.modes`
/// keeps.
fn lowest_three(loaded: &Loaded) -> Vec<f64> {
    ModalBridge::build_with(&loaded.scenario.bridge, ModeRequest::Lowest(3))
        .unwrap()
        .frequencies()
}

/// Checks that the default deck-acceleration filters of `text` (its
/// records' and its resonance check's) are the bridge's own
/// max(30 Hz, 1.5 f₁, f₃) (EN 1990 A2.4.4.2.1(4)), whose f₃ must be
/// `ratio` × f₁ within 1e-4 (a simply supported Euler–Bernoulli beam:
/// fₙ = n² f₁, so 9; the FE beam of 20 cubic elements per span is that
/// close), and above `at_least` Hz.
fn default_filters_are_the_bridges(what: &str, text: &str, at_least: f64) {
    let loaded = plan::load_str(text, what).unwrap();
    let f = lowest_three(&loaded);
    assert!((f[2] / (9.0 * f[0]) - 1.0).abs() < 1e-4, "{what}: {f:?}");
    let expected = 30.0f64.max(1.5 * f[0]).max(f[2]);
    assert!(expected > at_least, "{what}: {expected}");
    let record = loaded
        .scenario
        .record
        .iter()
        .find(|r| r.quantity == Quantity::BridgeAcceleration)
        .and_then(|r| r.max_frequency)
        .unwrap();
    let Some(Study::ResonanceCheck(check)) = &loaded.scenario.study else {
        panic!("{what}: a resonance check");
    };
    for (which, got) in [("record", record), ("resonance check", check.max_frequency)] {
        assert!(
            (got / expected - 1.0).abs() < 1e-12,
            "{what}: the {which}'s default filter is {got} Hz, not the bridge's \
             max(30 Hz, 1.5 f1, f3) = {expected} Hz ({} modes kept)",
            loaded.bridge.mode_count()
        );
    }
}

/// The railway example kept modes to 30 Hz (the first mode only, 7.65 Hz)
/// on a 15 m span whose f₃ is 9 f₁ = 68.8 Hz; the HSLM starter modes to
/// 30 Hz on a 20 m span with f₁ = 5.0 Hz, f₃ = 45 Hz. The default filter is
/// f₃ of the bridge, not of the kept modes (which made it 30 Hz and the
/// example's HSLM-A1 peak 11 % low, silently).
#[test]
fn the_default_acceleration_filter_is_the_bridges_own_f3_whatever_modes_are_kept() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/railway-resonance-check.yaml");
    let example = std::fs::read_to_string(&file).unwrap();
    let hslm = starter(StarterBridge::Beam, StarterVehicle::Hslm, "vbi.schema.json").unwrap();
    for (what, text, at_least) in [
        ("railway example", &example, 68.0),
        ("hslm starter", &hslm, 44.0),
    ] {
        default_filters_are_the_bridges(what, text, at_least);
        // At a 30 Hz cap (what both shipped before the fix) and at one mode.
        for modes in ["{max_frequency: 30.0}", "{count: 1}"] {
            let capped = with_modes(text, modes);
            assert_ne!(&capped, text, "{what} has a `modes:` line");
            default_filters_are_the_bridges(&format!("{what}, modes {modes}"), &capped, at_least);
        }
    }
}

/// The railway example's verdict figures (each train's largest deck
/// acceleration and displacement) are within 0.5 % of the converged check.
#[test]
fn the_railway_example_is_converged_at_its_own_settings() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/railway-resonance-check.yaml");
    let text = std::fs::read_to_string(&file).unwrap();
    let (failures, _) = compare(&text, &file.to_string_lossy());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The starters this file runs, one test each (they run in parallel).
const STARTERS: &[(StarterBridge, StarterVehicle)] = &[
    (StarterBridge::Beam, StarterVehicle::Hslm),
    (StarterBridge::Beam, StarterVehicle::MovingForce),
    (StarterBridge::Beam, StarterVehicle::Oscillator),
    (StarterBridge::Beam, StarterVehicle::H20_44),
    (StarterBridge::Beam, StarterVehicle::RailCar),
    (StarterBridge::Beam, StarterVehicle::Train),
    (StarterBridge::Beam, StarterVehicle::Train3d),
    (StarterBridge::Plate, StarterVehicle::MovingForce),
    (StarterBridge::Plate, StarterVehicle::Oscillator),
    (StarterBridge::Plate, StarterVehicle::H20_44),
];

/// [`STARTERS`] is every pair `vbi init` writes a starter for.
#[test]
fn every_init_starter_is_measured() {
    use clap::ValueEnum;
    for bridge in StarterBridge::value_variants() {
        for vehicle in StarterVehicle::value_variants() {
            assert_eq!(
                starter(*bridge, *vehicle, "s.json").is_ok(),
                STARTERS.contains(&(*bridge, *vehicle)),
                "{bridge:?} {vehicle:?}"
            );
        }
    }
}

/// The starter's headline peaks are within 0.5 % of the converged answer.
fn starter_is_converged(index: usize) {
    let (bridge, vehicle) = STARTERS[index];
    let text = starter(bridge, vehicle, "vbi.schema.json").unwrap();
    let (failures, _) = compare(&text, &format!("init-{bridge:?}-{vehicle:?}.yaml"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

macro_rules! starters_converged {
    ($($name:ident: $index:expr;)*) => {$(
        #[test]
        fn $name() {
            starter_is_converged($index);
        }
    )*};
}

starters_converged! {
    init_beam_hslm_is_converged: 0;
    init_beam_moving_force_is_converged: 1;
    init_beam_oscillator_is_converged: 2;
    init_beam_h20_44_is_converged: 3;
    init_beam_rail_car_is_converged: 4;
    init_beam_train_is_converged: 5;
    init_beam_train_3d_is_converged: 6;
    init_plate_moving_force_is_converged: 7;
    init_plate_oscillator_is_converged: 8;
    init_plate_h20_44_is_converged: 9;
}

/// The ids of the advice of running `text` (a scene or a study).
fn advice_of(text: &str, file: &str) -> Vec<vbi::advice::Advice> {
    let loaded = plan::load_str(text, file).unwrap_or_else(|e| panic!("{file}: {e}"));
    let scenario = loaded.scenario.clone();
    execute(loaded, &|_, _| {}).unwrap().advice(&scenario)
}

const FILTER_ABOVE_MODES: &str = "acceleration-filter-above-modes";

/// A `bridge.modes` the file sets that stops below the default filter is
/// said, with the bridge's own filter: the railway example's span capped at
/// 30 Hz (one mode, 7.65 Hz) or at one mode has three modes up to its
/// f₃ = 68.8 Hz. (Before the filter came from the kept modes: 30 Hz under
/// the cap, 7.65 Hz under the count, and no word.) As a single run and as
/// the resonance check, whose verdict reads the deck acceleration.
#[test]
fn modes_set_below_the_default_acceleration_filter_are_said() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/railway-resonance-check.yaml");
    let file = file.to_string_lossy();
    let example = std::fs::read_to_string(file.as_ref()).unwrap();
    let (scene, study) = example.split_at(example.find("\nstudy:").unwrap());
    // One train at two speeds: the check's advice, cheaply.
    let study = study.replace("[A1, A2, A3]", "[A1]").replace(
        "from: 100 km/h, to: 240 km/h",
        "from: 200 km/h, to: 240 km/h",
    );
    for modes in ["{max_frequency: 30.0}", "{count: 1}"] {
        for (what, text) in [
            ("scene", with_modes(scene, modes)),
            (
                "resonance check",
                with_modes(&format!("{scene}{study}"), modes),
            ),
        ] {
            let advice = advice_of(&text, &file);
            let a = advice
                .iter()
                .find(|a| a.id == FILTER_ABOVE_MODES)
                .unwrap_or_else(|| panic!("{what}, modes {modes}: not said: {advice:#?}"));
            assert_eq!(a.location.as_deref(), Some("bridge.modes"), "{what}");
            assert!(
                (a.figures["filter_hz"] / 68.83 - 1.0).abs() < 1e-3,
                "{a:#?}"
            );
            assert_eq!(a.figures["modes_to_filter"], 3.0, "{a:#?}");
            assert_eq!(a.figures["modes_used"], 1.0, "{a:#?}");
        }
    }
}

/// A plate deck too: its modes up to the filter are counted by its Ritz
/// problem (a plate has no Sturm count; before, no count meant no word).
/// The plate starter at two modes: the filter is at least its f₃, above
/// the two kept.
#[test]
fn a_plate_with_modes_below_the_acceleration_filter_is_said() {
    let text = starter(StarterBridge::Plate, StarterVehicle::MovingForce, "s.json").unwrap();
    let advice = advice_of(&with_modes(&text, "{count: 2}"), "plate.yaml");
    let a = advice
        .iter()
        .find(|a| a.id == FILTER_ABOVE_MODES)
        .unwrap_or_else(|| panic!("not said: {advice:#?}"));
    assert!(a.figures["modes_to_filter"] >= 3.0, "{a:#?}");
    assert_eq!(a.figures["modes_used"], 2.0, "{a:#?}");
}
