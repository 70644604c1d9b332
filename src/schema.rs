//! The JSON Schema of the scenario format, generated from the serde types.

use serde_json::Value;

use crate::scenario::raw::ScenarioRaw;

/// The schema as pretty-printed JSON with a trailing newline (what
/// `vbi schema` prints and `schema/vbi.schema.json` holds).
pub fn schema_json() -> String {
    let mut schema = schemars::schema_for!(ScenarioRaw);
    schema.insert("title".into(), "vbi scenario".into());
    let mut value = schema.to_value();
    describe_tags(&mut value);
    serde_json::to_string_pretty(&value).expect("schema serialises") + "\n"
}

/// schemars adds the `type` tag of each tagged-union variant without a
/// description; editors show descriptions on hover, so give every tag one.
fn describe_tags(value: &mut Value) {
    match value {
        Value::Object(map) => {
            if let Some(Value::Object(tag)) =
                map.get_mut("properties").and_then(|p| p.get_mut("type"))
                && !tag.contains_key("description")
                && let Some(Value::String(variant)) = tag.get("const").cloned()
            {
                tag.insert(
                    "description".into(),
                    Value::String(format!("Selects this variant: `{variant}`.")),
                );
            }
            map.values_mut().for_each(describe_tags);
        }
        Value::Array(items) => items.iter_mut().for_each(describe_tags),
        _ => {}
    }
}
