//! `resolved.yaml` reproduces the run it describes (issue 22, point 4):
//! every automatic choice (modes, time step, output interval) is written
//! in a form that cannot round away a mode, and a mode cut-off given at a
//! mode's own printed frequency keeps that mode.

use vbi::run::{Outcome, resolved_yaml, simulate};
use vbi::scenario::{Loaded, load_str};

fn load(yaml: &str, name: &str) -> Loaded {
    load_str(yaml, name).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn run(loaded: Loaded, name: &str) -> Outcome {
    simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Loads `yaml`, runs it, runs its resolved form, and asserts the two
/// histories are bit for bit the same (times and every column), with the
/// same modes, time step and output interval.
pub fn assert_resolved_reproduces(yaml: &str, name: &str) {
    let first = load(yaml, name);
    let resolved = resolved_yaml(&first.scenario);
    let again = load(&resolved, &format!("{name} resolved"));
    assert_eq!(
        first.bridge.frequencies(),
        again.bridge.frequencies(),
        "{name}: the resolved form keeps other modes\n{resolved}"
    );
    let (a, b) = (run(first, name), run(again, name));
    assert_eq!(a.model.time_step, b.model.time_step, "{name}: time step");
    assert_eq!(a.history.every, b.history.every, "{name}: output interval");
    assert_eq!(a.history.time, b.history.time, "{name}: sample times");
    assert_eq!(a.history.columns.len(), b.history.columns.len());
    for (x, y) in a.history.columns.iter().zip(&b.history.columns) {
        let same = x.values.len() == y.values.len()
            && x
                .values
                .iter()
                .zip(&y.values)
                .all(|(p, q)| p.to_bits() == q.to_bits());
        assert!(same, "{name}: column {} differs on the re-run", x.name);
    }
}

/// The plane beam of the README's 3D example: 25 m, EI = 8e10 N·m², m =
/// 18 000 kg/m (f₁ = 5.299 Hz, f₃ = 9 f₁ = 47.688 Hz).
const PLANE_BEAM: &str = "{type: beam, spans: [25.0], bending_stiffness: 8.0e10, mass_per_length: 18000.0";

/// Issue 22 reproducer: `{max_frequency: 47.6876464074312}` (mode 3 as
/// printed) kept 2 modes. A cut-off at any kept mode's own frequency, exact
/// or as printed to 15 significant digits, keeps that mode and no more.
#[test]
fn a_cut_off_at_a_modes_printed_frequency_keeps_it() {
    let yaml = |modes: &str| {
        format!(
            "name: cut\nbridge: {PLANE_BEAM}, modes: {modes}}}\n\
             vehicles: [{{type: moving_force, loads: [1.0e5], speed: 20.0}}]\n"
        )
    };
    let issue = load(&yaml("{max_frequency: 47.6876464074312}"), "issue");
    assert_eq!(issue.bridge.mode_count(), 3, "{:?}", issue.bridge.frequencies());
    let all = load(&yaml("{count: 12}"), "all");
    for (k, f) in all.bridge.frequencies().iter().enumerate() {
        for cut in [*f, format!("{f:.14e}").parse().unwrap()] {
            let kept = load(&yaml(&format!("{{max_frequency: {cut:?}}}")), "cut");
            assert_eq!(kept.bridge.mode_count(), k + 1, "cut-off {cut:?} Hz at mode {}", k + 1);
        }
    }
}
