//! Independent reference solutions shared by the physics tests, and the
//! small helpers those tests share for running scenes and reading results.

#![allow(dead_code)] // each test binary uses its own subset

pub mod event_reference;
pub mod reference;

use vbi::run::{Outcome, simulate};
use vbi::scenario::load_str;

/// Loads and runs a scene given as YAML text, panicking with the error.
pub fn run_yaml(yaml: &str) -> Outcome {
    let loaded = load_str(yaml, "test.yaml").unwrap_or_else(|e| panic!("{e}"));
    simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// The recorded history named `name`.
pub fn column<'a>(outcome: &'a Outcome, name: &str) -> &'a [f64] {
    &outcome
        .history
        .columns
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no column {name}"))
        .values
}

/// Largest absolute value.
pub fn max_abs(values: &[f64]) -> f64 {
    values.iter().fold(0.0, |m, v| m.max(v.abs()))
}
