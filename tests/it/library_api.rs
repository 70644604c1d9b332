//! The library API as another front end uses it (issue 25, point 5): load
//! (text, file or data already parsed) → plan → run as separate calls, the
//! diagnostics of both stages located and ordered as the command line
//! prints them, and a scene given as data located by key path.

use std::path::Path;

use vbi::scenario::{Diagnostic, LoadError, yaml};

use crate::support::manifest_dir;

/// The diagnostics of a failed load or plan.
fn invalid<T: std::fmt::Debug>(result: Result<T, LoadError>) -> Vec<Diagnostic> {
    match result {
        Err(LoadError::Invalid(d)) => d,
        other => panic!("expected diagnostics, got {other:?}"),
    }
}

/// A scenario file's tree as data (what a JSON reader or a Python dict
/// would hand over): the YAML tree with its scalars resolved.
fn as_data(path: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(path).unwrap();
    yaml::parse(&text).unwrap().unwrap().to_json()
}

/// The seven mistakes of tests/multi/seven-mistakes.yaml given as data:
/// the same messages in the same order as from the file, each named by
/// its key path instead of a line and column.
#[test]
fn a_scene_given_as_data_gets_the_file_s_diagnostics_by_key_path() {
    let path = manifest_dir().join("tests/multi/seven-mistakes.yaml");
    let from_text = invalid(vbi::scenario::load_file(&path));
    let from_data = invalid(vbi::scenario::load_value(&as_data(&path), "<data>"));
    let messages = |d: &[Diagnostic]| d.iter().map(|d| d.message.clone()).collect::<Vec<_>>();
    assert_eq!(messages(&from_data), messages(&from_text));
    let paths: Vec<&str> = from_data
        .iter()
        .map(|d| d.path.as_deref().unwrap())
        .collect();
    assert_eq!(
        paths,
        [
            "vehicles[0].car_spacing",
            "surface.class",
            "contact.stifness",
            "solver.free_vibration",
            "record[0].quantity",
            "record[1].x",
            "record[2].dof",
        ]
    );
    let helps = |d: &[Diagnostic]| d.iter().map(|d| d.help.clone()).collect::<Vec<_>>();
    assert_eq!(helps(&from_data), helps(&from_text));
    // Rendered without a line, column or excerpt there is none of.
    let shown = from_data[2].to_string();
    assert!(
        shown.starts_with("<data>: contact.stifness: unknown field `stifness`"),
        "{shown}"
    );
    assert!(
        shown.contains("= help: did you mean `stiffness`?"),
        "{shown}"
    );
    assert!(!shown.contains(" | "), "{shown}");
}

/// A missing key is blamed on the mapping that lacks it; a mistake at the
/// top level on the scene (an empty path).
#[test]
fn a_missing_key_is_blamed_on_its_mapping_s_path() {
    let scene = serde_json::json!({
        "name": "missing",
        "bridge": {"type": "beam", "spans": [20.0], "mass_per_length": 1.0e4},
        "vehicles": [{"type": "moving_force", "loads": [1.0e5], "speed": 20.0}],
    });
    let d = invalid(vbi::scenario::load_value(&scene, "<data>"));
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].path.as_deref(), Some("bridge"));
    assert!(d[0].message.contains("bending_stiffness"), "{}", d[0]);
    let d = invalid(vbi::scenario::load_value(
        &serde_json::json!([1, 2]),
        "<data>",
    ));
    assert_eq!(d[0].path.as_deref(), Some(""));
    assert!(
        d[0].to_string().starts_with("<data>: invalid type"),
        "{}",
        d[0]
    );
}

/// Every shipped scene reads the same from its text and from its tree as
/// data: the bridge and vehicles the format describes are equal.
#[test]
fn shipped_scenes_describe_the_same_from_text_and_from_data() {
    let dir = manifest_dir().join("scenarios");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    assert!(files.len() > 20, "{files:?}");
    for file in &files {
        let name = file.display().to_string();
        let text = vbi::scenario::load_file(file).unwrap_or_else(|e| panic!("{e}"));
        let data = vbi::scenario::load_value(&as_data(file), &name)
            .unwrap_or_else(|e| panic!("{name} as data: {e}"));
        assert_eq!(data.name(), text.name(), "{name}");
        assert_eq!(data.bridge(), text.bridge(), "{name}");
        assert_eq!(data.vehicles(), text.vehicles(), "{name}");
        assert!(
            data.errors().is_empty() && text.errors().is_empty(),
            "{name}"
        );
    }
}

/// Load and plan as two calls give what the one call gives: the resolved
/// scene (every automatic choice written back) from text and from data.
#[test]
fn load_then_plan_resolves_as_the_one_call_does() {
    let file = manifest_dir().join("scenarios/moving-force-slow.yaml");
    let one_call = vbi::plan::load_file(&file).unwrap();
    let described = vbi::scenario::load_file(&file).unwrap();
    let two_calls = vbi::plan::plan(described).unwrap();
    let data = vbi::scenario::load_value(&as_data(&file), &file.display().to_string()).unwrap();
    let from_data = vbi::plan::plan(data).unwrap();
    let resolved = |l: &vbi::plan::Loaded| serde_json::to_string(&l.scenario).unwrap();
    assert_eq!(resolved(&two_calls), resolved(&one_call));
    assert_eq!(resolved(&from_data), resolved(&one_call));
    assert_eq!(
        two_calls.bridge.frequencies(),
        one_call.bridge.frequencies()
    );
}

/// A type error in a section the description does not need (a record's
/// unknown key) does not stop the load: the described scene carries it,
/// and the plan reports it with its own findings (a record off the bridge)
/// in one round, in the order of the file, as the one call does.
#[test]
fn the_plan_reports_the_type_errors_the_load_went_on_past() {
    let yaml = "\
name: pending
bridge: {type: beam, spans: [20.0], bending_stiffness: 1.0e10, mass_per_length: 1.0e4,
         modes: {count: 3}}
vehicles: [{type: moving_force, loads: [1.0e5], speed: 20.0}]
solver: {time_step: 1.0e-3}
record:
  - {name: a, quantity: bridge_displacement, x: 10.0, colour: red}
  - {name: b, quantity: bridge_displacement, x: 30.0}
";
    let described = vbi::scenario::load_str(yaml, "pending.yaml").unwrap();
    let pending = described.errors();
    assert_eq!(pending.len(), 1, "{pending:?}");
    assert_eq!((pending[0].loc.line, pending[0].loc.col), (7, 55));
    let two_calls = invalid(vbi::plan::plan(described));
    let one_call = invalid(vbi::plan::load_str(yaml, "pending.yaml"));
    let shown = |d: &[Diagnostic]| d.iter().map(|d| d.to_string()).collect::<Vec<_>>();
    assert_eq!(shown(&two_calls), shown(&one_call));
    let lines: Vec<usize> = two_calls.iter().map(|d| d.loc.line).collect();
    assert_eq!(lines, [7, 8], "{two_calls:?}");
}
