//! The JSON Schema of the scenario format, generated from the serde types.
//!
//! schemars writes what the types say; editors (the YAML language server)
//! need a little more to complete and check well, which [`schema_json`] adds
//! after generation: no `"default": null` (the language server throws on it
//! and stops completing), optional fields without the `null` alternative
//! (nobody writes `gravity: ~`, and the alternative hides the object type the
//! server needs to insert `key:` and a new line), `"type": "object"` on every
//! tagged union, and each tag described by its variant's text. The value
//! rules (`exclusiveMinimum`, `minItems`, …) sit on the fields themselves as
//! `#[schemars(transform = …)]` with the functions below, each mirroring a
//! check of `vbi check` (tests/schema.rs holds the two to the same limits).

use schemars::Schema;
use serde_json::{Map, Value};

use crate::scene::schema_rules::set;

use crate::scenario::raw::ScenarioRaw;

/// The schema's `$id`: a stable name for it (issue 28.5), the same
/// wherever the file is copied; editors find the file through the scene's
/// modeline or their `yaml.schemas` setting, not through this URL.
pub const SCHEMA_ID: &str = "https://vbi.dev/schema/vbi.schema.json";

/// The schema as pretty-printed JSON with a trailing newline (what
/// `vbi schema` prints and `schema/vbi.schema.json` holds).
pub fn schema_json() -> String {
    let mut schema = schemars::schema_for!(ScenarioRaw);
    schema.insert("$id".into(), SCHEMA_ID.into());
    schema.insert("title".into(), "vbi scenario".into());
    let mut value = schema.to_value();
    tidy_optional(&mut value);
    type_unions(&mut value);
    describe_tags(&mut value);
    bare_tags(&mut value);
    unwrap_descriptions(&mut value);
    fill_constants(&mut value, &documented_constants());
    limits_defaults(&mut value);
    drop_raw_suffix(&mut value);
    serde_json::to_string_pretty(&value).expect("schema serialises") + "\n"
}

/// The constants the format's descriptions state, by the name a doc comment
/// writes between double braces (`Default {{DEFAULT_GRAVITY}}.`): each the
/// constant the code takes its default from (issue 40.3), so a stated
/// default cannot drift from the one applied. [`schema_json`] writes their
/// values in; tests/it/documented_defaults.rs checks that none is left
/// unfilled and that each is used.
pub fn documented_constants() -> Vec<(String, String)> {
    use crate::scene::automatic as auto;
    let mut table: Vec<(String, String)> = [
        ("DEFAULT_GRAVITY", number(super::resolve::DEFAULT_GRAVITY)),
        (
            "DEFAULT_ELEMENTS_PER_SPAN",
            super::resolve::DEFAULT_ELEMENTS_PER_SPAN.to_string(),
        ),
        (
            "MAX_ELEMENTS_PER_SPAN",
            crate::scene::MAX_ELEMENTS_PER_SPAN.to_string(),
        ),
        (
            "DEFAULT_RIGID_ALPHA",
            number(super::resolve::DEFAULT_RIGID_ALPHA),
        ),
        ("SAFETY", number(auto::SAFETY)),
        ("MODES_PER_SPAN", auto::MODES_PER_SPAN.to_string()),
        (
            "MODES_PER_SPAN_CORRECTED",
            auto::MODES_PER_SPAN_CORRECTED.to_string(),
        ),
        ("PLATE_FAMILIES", auto::PLATE_FAMILIES.to_string()),
        (
            "PLATE_MODES_PER_SPAN",
            (auto::MODES_PER_SPAN * auto::PLATE_FAMILIES).to_string(),
        ),
        ("HEAVY_WHEEL_RATIO", number(auto::HEAVY_WHEEL_RATIO)),
        ("STEPS_PER_PERIOD", number(auto::STEPS_PER_PERIOD)),
        ("CROSSING_STEPS", number(auto::CROSSING_STEPS)),
        ("PHASE_BUDGET", number(auto::PHASE_BUDGET)),
        ("FLOOR_HZ", number(auto::FLOOR_HZ)),
        ("FUNDAMENTAL_FACTOR", number(auto::FUNDAMENTAL_FACTOR)),
        (
            "DEFAULT_LONGITUDINAL_TERMS_PER_SPAN",
            super::bridges::DEFAULT_LONGITUDINAL_TERMS_PER_SPAN.to_string(),
        ),
        (
            "MIN_LONGITUDINAL_TERMS",
            super::bridges::MIN_LONGITUDINAL_TERMS.to_string(),
        ),
        (
            "DEFAULT_TRANSVERSE_TERMS",
            super::bridges::DEFAULT_TRANSVERSE_TERMS.to_string(),
        ),
        (
            "DEFAULT_ISOTROPIC_POISSON",
            number(super::bridges::DEFAULT_ISOTROPIC_POISSON),
        ),
        (
            "DEFAULT_ORTHOTROPIC_POISSON",
            number(super::bridges::DEFAULT_ORTHOTROPIC_POISSON),
        ),
        (
            "DEFAULT_ENTRY_LENGTH",
            number(super::fe_import::DEFAULT_ENTRY_LENGTH),
        ),
        (
            "DEFAULT_SHORTEST_WAVELENGTH",
            number(super::surfaces::DEFAULT_SHORTEST_WAVELENGTH),
        ),
        (
            "DEFAULT_SAMPLING_LENGTHS",
            number(super::surfaces::DEFAULT_SAMPLING_LENGTHS),
        ),
        ("RAIL_BAND_SHORTEST", number(super::surfaces::RAIL_BAND.0)),
        ("RAIL_BAND_LONGEST", number(super::surfaces::RAIL_BAND.1)),
        ("ROAD_BAND_SHORTEST", number(super::surfaces::ROAD_BAND.0)),
        ("ROAD_BAND_LONGEST", number(super::surfaces::ROAD_BAND.1)),
        ("TERMS_PER_DECADE", number(crate::scene::TERMS_PER_DECADE)),
        ("MIN_BAND_TERMS", crate::scene::MIN_BAND_TERMS.to_string()),
        ("DEFAULT_TOLERANCE", number(crate::scene::DEFAULT_TOLERANCE)),
        (
            "DEFAULT_MAX_ITERATIONS",
            crate::scene::DEFAULT_MAX_ITERATIONS.to_string(),
        ),
        (
            "DEFAULT_LOWEST_SPEED",
            number(super::resonance::DEFAULT_LOWEST_SPEED),
        ),
        (
            "DEFAULT_TOP_SPEED_FACTOR",
            number(super::resonance::DEFAULT_TOP_SPEED_FACTOR),
        ),
        (
            "DEFAULT_SPEED_STEP_KM_H",
            number(super::resonance::DEFAULT_SPEED_STEP_KM_H),
        ),
        ("DEFAULT_SHOWN", super::sweep::DEFAULT_SHOWN.to_string()),
        ("MAX_SHOWN", super::sweep::MAX_SHOWN.to_string()),
    ]
    .into_iter()
    .map(|(name, value)| (name.to_owned(), value))
    .collect();
    // Every budget of `limits`, by its key: `{{limits.dofs}}`.
    let limits = serde_json::to_value(crate::scene::Limits::default()).expect("limits serialise");
    if let Value::Object(map) = limits {
        for (key, value) in map {
            if let Some(x) = value.as_f64() {
                table.push((format!("limits.{key}"), number(x)));
            }
        }
    }
    table
}

/// A documented number as people write it: integers below 1e5 whole
/// (`20`, `10000`), larger and smaller magnitudes in e-notation (`2e9`,
/// `1e-8`), the rest in Rust's shortest round-trip form (`0.5`, `-0.05`).
pub fn number(x: f64) -> String {
    let magnitude = x.abs();
    if x.fract() == 0.0 && magnitude < 1e5 {
        format!("{}", x as i64)
    } else if magnitude >= 1e5 || (magnitude < 1e-3 && x != 0.0) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// The `default` of every `limits` budget: [`crate::scene::Limits`]'s own
/// default, the one the checks apply.
fn limits_defaults(value: &mut Value) {
    let defaults = serde_json::to_value(crate::scene::Limits::default()).expect("limits serialise");
    let Some(Value::Object(properties)) = value.pointer_mut("/$defs/LimitsRaw/properties") else {
        return;
    };
    for (key, property) in properties.iter_mut() {
        if let (Some(default), Value::Object(property)) = (defaults.get(key), property) {
            property.insert("default".into(), default.clone());
        }
    }
}

/// Writes the values of `table` into every description's `{{NAME}}`; a
/// name not in the table stays as written (the test finds it).
fn fill_constants(value: &mut Value, table: &[(String, String)]) {
    match value {
        Value::Object(map) => {
            if let Some(Value::String(text)) = map.get_mut("description")
                && text.contains("{{")
            {
                for (name, number) in table {
                    *text = text.replace(&format!("{{{{{name}}}}}"), number);
                }
            }
            map.values_mut().for_each(|v| fill_constants(v, table));
        }
        Value::Array(items) => items.iter_mut().for_each(|v| fill_constants(v, table)),
        _ => {}
    }
}

/// The `$defs` names without the `Raw` suffix of the format's internal
/// types (`BridgeRaw` → `Bridge`), and every `$ref` to them: editors show
/// these names, and users write a bridge, not a `BridgeRaw`. No two types
/// differ only by the suffix (the names are the types' own, all in one
/// `$defs`), so the renaming is one to one.
fn drop_raw_suffix(value: &mut Value) {
    const PREFIX: &str = "#/$defs/";
    fn plain(name: &str) -> &str {
        name.strip_suffix("Raw")
            .filter(|n| !n.is_empty())
            .unwrap_or(name)
    }
    fn walk(value: &mut Value) {
        match value {
            Value::Object(map) => {
                if let Some(Value::String(target)) = map.get_mut("$ref")
                    && let Some(name) = target.strip_prefix(PREFIX)
                {
                    *target = format!("{PREFIX}{}", plain(name));
                }
                map.values_mut().for_each(walk);
            }
            Value::Array(items) => items.iter_mut().for_each(walk),
            _ => {}
        }
    }
    if let Some(Value::Object(defs)) = value.get_mut("$defs") {
        let renamed: Map<String, Value> = std::mem::take(defs)
            .into_iter()
            .map(|(name, def)| (plain(&name).to_string(), def))
            .collect();
        *defs = renamed;
    }
    walk(value);
}

/// Removes `"default": null` and the `null` alternative of optional fields:
/// `{"type": ["number", "null"]}` → `{"type": "number"}` and
/// `{"anyOf": [{"$ref": …}, {"type": "null"}]}` → `{"$ref": …}`.
fn tidy_optional(value: &mut Value) {
    match value {
        Value::Object(map) => {
            if map.get("default") == Some(&Value::Null) {
                map.remove("default");
            }
            if let Some(Value::Array(types)) = map.get_mut("type") {
                types.retain(|t| t != "null");
                if types.len() == 1 {
                    let only = types.remove(0);
                    map.insert("type".into(), only);
                }
            }
            if let Some(Value::Array(alternatives)) = map.get("anyOf") {
                let is_null = |v: &Value| v.get("type") == Some(&Value::from("null"));
                if alternatives.len() == 2 && alternatives.iter().any(is_null) {
                    let kept = alternatives
                        .iter()
                        .find(|v| !is_null(v))
                        .cloned()
                        .unwrap_or_default();
                    map.remove("anyOf");
                    if let Value::Object(inner) = kept {
                        for (k, v) in inner {
                            map.entry(k).or_insert(v);
                        }
                    }
                }
            }
            map.values_mut().for_each(tidy_optional);
        }
        Value::Array(items) => items.iter_mut().for_each(tidy_optional),
        _ => {}
    }
}

/// A `oneOf` whose alternatives are all objects (a tagged union) gets
/// `"type": "object"` itself, so that an editor accepting the key that holds
/// it inserts `key:` and a new line rather than a bare `key`.
fn type_unions(value: &mut Value) {
    match value {
        Value::Object(map) => {
            let all_objects = map
                .get("oneOf")
                .and_then(Value::as_array)
                .is_some_and(|alts| {
                    !alts.is_empty()
                        && alts
                            .iter()
                            .all(|a| a.get("type") == Some(&Value::from("object")))
                });
            if all_objects && !map.contains_key("type") {
                map.insert("type".into(), "object".into());
            }
            map.values_mut().for_each(type_unions);
        }
        Value::Array(items) => items.iter_mut().for_each(type_unions),
        _ => {}
    }
}

/// schemars adds the `type` tag of each tagged-union variant without a
/// description; editors show it on hover over `type: …` and beside the
/// completion of the value, so it carries the variant's own text.
fn describe_tags(value: &mut Value) {
    match value {
        Value::Object(map) => {
            let variant_text = map
                .get("description")
                .and_then(Value::as_str)
                .map(str::to_owned);
            if let Some(Value::Object(tag)) =
                map.get_mut("properties").and_then(|p| p.get_mut("type"))
                && !tag.contains_key("description")
                && let Some(Value::String(variant)) = tag.get("const").cloned()
            {
                let text = match variant_text {
                    Some(text) => format!("`{variant}`: {text}"),
                    None => format!("Selects this variant: `{variant}`."),
                };
                tag.insert("description".into(), Value::String(text));
            }
            map.values_mut().for_each(describe_tags);
        }
        Value::Array(items) => items.iter_mut().for_each(describe_tags),
        _ => {}
    }
}

/// A variant of a tagged union whose fields all have defaults may be
/// written as its bare tag (`contact: rigid` for `contact: {type: rigid}`,
/// as the loader reads it): each such variant gets a string alternative,
/// and a union typed `object` (for editors, [`type_unions`]) is typed
/// `object` or `string`.
fn bare_tags(value: &mut Value) {
    match value {
        Value::Object(map) => {
            map.values_mut().for_each(bare_tags);
            let Some(Value::Array(alternatives)) = map.get_mut("oneOf") else {
                return;
            };
            let bare: Vec<Value> = alternatives
                .iter()
                .filter(|a| a.get("required") == Some(&serde_json::json!(["type"])))
                .filter_map(|a| {
                    let variant = a.pointer("/properties/type/const")?.as_str()?;
                    Some(serde_json::json!({
                        "type": "string",
                        "const": variant,
                        "description": format!(
                            "`{variant}` alone: the same as `{{type: {variant}}}`, every field \
                             at its default."
                        ),
                    }))
                })
                .collect();
            if bare.is_empty() {
                return;
            }
            alternatives.extend(bare);
            if map.get("type") == Some(&Value::from("object")) {
                map.insert("type".into(), serde_json::json!(["object", "string"]));
            }
        }
        Value::Array(items) => items.iter_mut().for_each(bare_tags),
        _ => {}
    }
}

/// Doc comments are wrapped at ~80 columns; editors render each line break
/// of a description as a new paragraph, so lines are joined within a
/// paragraph (a blank line, or a line starting a `-` list item, still
/// breaks).
fn unwrap_descriptions(value: &mut Value) {
    match value {
        Value::Object(map) => {
            if let Some(Value::String(text)) = map.get_mut("description") {
                *text = unwrap_paragraphs(text);
            }
            map.values_mut().for_each(unwrap_descriptions);
        }
        Value::Array(items) => items.iter_mut().for_each(unwrap_descriptions),
        _ => {}
    }
}

fn unwrap_paragraphs(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        out.push_str(line);
        if let Some(next) = lines.peek() {
            let breaks = line.trim().is_empty()
                || next.trim().is_empty()
                || next.trim_start().starts_with("- ");
            out.push(if breaks { '\n' } else { ' ' });
        }
    }
    out
}

/// The vehicle DOF names `record: … dof:` accepts (every vehicle type's;
/// `vbi check` then checks the name against the recorded vehicle's type).
pub fn dof_name(schema: &mut Schema) {
    let names: Vec<Value> = crate::scene::dof_names::oscillator::DOF_NAMES
        .iter()
        .chain(crate::scene::dof_names::h20_44::DOF_NAMES.iter())
        .chain(crate::scene::dof_names::rail_car::DOF_NAMES.iter())
        .chain(crate::scene::dof_names::train_3d::DOF_NAMES.iter())
        .map(|&n| Value::from(n))
        .collect();
    set(schema, "enum", names);
}

/// A speed in m/s: > 0 and at most [`crate::scenario::vehicles::MAX_SPEED`] (`check_speed`).
pub fn speed(schema: &mut Schema) {
    crate::scene::schema_rules::positive(schema);
    set(schema, "maximum", crate::scenario::vehicles::MAX_SPEED);
}
