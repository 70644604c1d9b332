//! Issue 23: files from other people that passed `vbi check` while asking
//! for unbounded work or holding nonsense, and refusals blamed on the wrong
//! field. Each test loads a small scene through the library and asserts
//! the diagnostic's place (line:column) and wording.

use vbi::scenario::{LoadError, LoadOptions, load_str, load_str_with};

const BEAM: &str = "bridge:\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\n";

/// `name` + the beam + `vehicles:` + `rest` (line 1 is `name`, lines 2–6
/// the beam, line 7 `vehicles:`, `rest` from line 8).
fn scene(rest: &str) -> String {
    format!("name: t\n{BEAM}vehicles:\n{rest}")
}

/// The diagnostics of a refused scene as `LINE:COL: message` lines.
fn refused(text: &str, options: LoadOptions) -> String {
    match load_str_with(text, "t.yaml", options) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(LoadError::Invalid(d)) => d
            .iter()
            .map(|d| format!("{}:{}: {}", d.loc.line, d.loc.col, d.message))
            .collect::<Vec<_>>()
            .join("\n"),
        Err(e) => panic!("{e}"),
    }
}

fn assert_refused_at(text: &str, at: &str, words: &[&str]) {
    let all = refused(text, LoadOptions::default());
    let first = all.lines().next().unwrap_or_default();
    assert!(
        first.starts_with(&format!("{at}:")),
        "expected the first error at {at}:\n{all}"
    );
    for w in words {
        assert!(first.contains(w), "`{w}` missing from:\n{all}");
    }
}

/// A file's own `limits:` above the defaults does not lift them for
/// whoever checks it: the refusal says the file asks for more and how to
/// allow it.
#[test]
fn limits_raised_inside_a_file_need_the_command_line() {
    let text = scene(
        "  - {type: oscillator, sprung_mass: 5750.0, stiffness: 1.595e6, speed: 27.7}\n\
         limits: {modes: 1.0e15, eigen_work: 1.0e15}\n",
    );
    assert_refused_at(&text, "9:10", &["limits.modes", "--trust-limits"]);
    // Allowed on the command line, the file's limits apply.
    let trusted = LoadOptions {
        trust_limits: true,
        ..LoadOptions::default()
    };
    load_str_with(&text, "t.yaml", trusted).unwrap_or_else(|e| panic!("{e}"));
    // Lowering a limit in the file always works.
    let lower = scene(
        "  - {type: oscillator, sprung_mass: 5750.0, stiffness: 1.595e6, speed: 27.7}\n\
         limits: {modes: 100, steps: 1.0e6}\n",
    );
    load_str(&lower, "t.yaml").unwrap_or_else(|e| panic!("{e}"));
}

/// Moments of inertia had no range: 1e308 kg·m² passed.
#[test]
fn inertias_of_1e308_are_refused() {
    let text = scene(
        "  - type: rail_car\n    speed: 20.0\n    parameters: {body_pitch_inertia: 1.0e308}\n",
    );
    assert_refused_at(&text, "10:35", &["body_pitch_inertia", "kg·m²"]);
}

/// A tab after `:` is valid YAML (a separator, not indentation).
#[test]
fn a_tab_after_a_colon_is_accepted() {
    let text = scene("  - type: oscillator\n    sprung_mass:\t5750.0\n    stiffness: 1.595e6\n    speed:\t27.7\n");
    load_str(&text, "t.yaml").unwrap_or_else(|e| panic!("{e}"));
}
