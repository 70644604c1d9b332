//! The JSON Schema of the scenario format, generated from the serde types.

use crate::scenario::raw::ScenarioRaw;

/// The schema as pretty-printed JSON with a trailing newline (what
/// `vbi schema` prints and `schema/vbi.schema.json` holds).
pub fn schema_json() -> String {
    let mut schema = schemars::schema_for!(ScenarioRaw);
    schema.insert("title".into(), "vbi scenario".into());
    serde_json::to_string_pretty(&schema).expect("schema serialises") + "\n"
}
