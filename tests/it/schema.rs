//! The JSON Schema of the scenario format: the committed copy is current, it
//! is a valid draft 2020-12 schema with a description on every property,
//! every example scenario validates against it and declares it for editors,
//! and it rejects invalid documents.

use std::path::{Path, PathBuf};

use jsonschema::Validator;
use serde_json::Value;

const MODELINE: &str = "# yaml-language-server: $schema=../schema/vbi.schema.json";
const DRAFT_2020_12: &str = "https://json-schema.org/draft/2020-12/schema";

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn committed_schema_path() -> PathBuf {
    root().join("schema").join("vbi.schema.json")
}

fn schema() -> Value {
    serde_json::from_str(&vbi::schema::schema_json()).expect("schema_json() is JSON")
}

fn validator() -> Validator {
    jsonschema::draft202012::new(&schema())
        .unwrap_or_else(|e| panic!("the schema does not compile as draft 2020-12: {e}"))
}

/// Every `*.yaml` / `*.yml` file in `scenarios/`, sorted by name.
fn scenario_files() -> Vec<PathBuf> {
    let dir = root().join("scenarios");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| {
            p.is_file()
                && p.extension()
                    .is_some_and(|ext| ext == "yaml" || ext == "yml")
        })
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no scenarios found in {}", dir.display());
    files
}

/// YAML text to JSON the way the schema sees it (core-schema scalars).
fn yaml_to_json(source: &str, what: &str) -> Value {
    vbi::scenario::yaml::parse(source)
        .unwrap_or_else(|e| panic!("{what}: YAML syntax error: {e:?}"))
        .map_or(Value::Null, |node| node.to_json())
}

/// Validation errors of `instance`, one line each (`/json/pointer: message`).
fn errors(validator: &Validator, instance: &Value) -> Vec<String> {
    validator
        .iter_errors(instance)
        .map(|e| format!("{}: {e}", e.instance_path()))
        .collect()
}

// ---------------------------------------------------------------------------
// (a) the committed copy is current
// ---------------------------------------------------------------------------

#[test]
fn committed_schema_is_current() {
    let path = committed_schema_path();
    let committed = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let generated = vbi::schema::schema_json();
    if committed != generated {
        let first = committed
            .lines()
            .zip(generated.lines())
            .position(|(a, b)| a != b)
            .map_or_else(
                || "lengths differ".to_string(),
                |i| {
                    format!(
                        "first difference at line {}:\n  committed: {}\n  generated: {}",
                        i + 1,
                        committed.lines().nth(i).unwrap_or_default(),
                        generated.lines().nth(i).unwrap_or_default()
                    )
                },
            );
        panic!(
            "schema/vbi.schema.json is out of date with the scenario types ({first}).\n\
             Regenerate it with:\n    cargo run --release -- schema > schema/vbi.schema.json"
        );
    }
}

// ---------------------------------------------------------------------------
// (b), (c) every scenario validates and declares the schema
// ---------------------------------------------------------------------------

#[test]
fn every_scenario_is_valid_against_the_schema() {
    let validator = validator();
    let mut failures = Vec::new();
    for path in scenario_files() {
        let name = path.display().to_string();
        let source =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {name}: {e}"));
        let instance = yaml_to_json(&source, &name);
        for error in errors(&validator, &instance) {
            failures.push(format!("{name}: {error}"));
        }
    }
    assert!(
        failures.is_empty(),
        "scenarios invalid against the schema:\n  {}",
        failures.join("\n  ")
    );
}

#[test]
fn every_scenario_declares_the_schema_on_its_first_line() {
    let mut failures = Vec::new();
    for path in scenario_files() {
        let source = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let first = source.lines().next().unwrap_or_default();
        if first.trim_end_matches('\r') != MODELINE {
            failures.push(format!("{}: first line is {first:?}", path.display()));
        }
    }
    assert!(
        failures.is_empty(),
        "every scenario must start with the line\n{MODELINE}\n\
         (editors autocomplete and check from it):\n  {}",
        failures.join("\n  ")
    );
}

// ---------------------------------------------------------------------------
// (d) the schema rejects invalid documents
// ---------------------------------------------------------------------------

/// A small valid scene; each case below breaks it in one way.
const VALID: &str = "\
name: minimal
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2e9
  mass_per_length: 2000.0
vehicles:
  - type: moving_force
    loads: [100000.0]
    speed: 20.0
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
";

#[test]
fn the_base_document_of_the_invalid_cases_is_valid() {
    let instance = yaml_to_json(VALID, "base document");
    let found = errors(&validator(), &instance);
    assert!(found.is_empty(), "base document rejected: {found:#?}");
}

#[test]
fn invalid_documents_are_rejected() {
    let cases: &[(&str, &str, &str)] = &[
        (
            "unknown top-level key",
            "name: minimal\n",
            "name: minimal\ncolour: red\n",
        ),
        (
            "unknown key in the bridge",
            "  mass_per_length: 2000.0\n",
            "  mass_per_length: 2000.0\n  colour: red\n",
        ),
        (
            "unknown key in a vehicle",
            "    speed: 20.0\n",
            "    speed: 20.0\n    colour: red\n",
        ),
        (
            "misspelt key",
            "  bending_stiffness: 3.2e9\n",
            "  bending_stifness: 3.2e9\n",
        ),
        (
            "wrong type: string for a number",
            "speed: 20.0",
            "speed: fast",
        ),
        (
            "wrong type: number for a list",
            "spans: [20.0]",
            "spans: 20.0",
        ),
        (
            "wrong type: list item",
            "loads: [100000.0]",
            "loads: [heavy]",
        ),
        (
            "wrong type: string for a name",
            "name: minimal",
            "name: [minimal]",
        ),
        ("missing bridge type", "  type: beam\n", ""),
        (
            "missing vehicle type",
            "  - type: moving_force\n    loads",
            "  - loads",
        ),
        ("unknown bridge type", "type: beam", "type: suspension"),
        (
            "unknown vehicle type",
            "type: moving_force",
            "type: hovercraft",
        ),
        ("unknown quantity", "bridge_displacement", "bridge_colour"),
        ("missing required field", "  spans: [20.0]\n", ""),
        ("missing name", "name: minimal\n", ""),
        ("missing bridge", "bridge:", "brige:"),
        ("document is not a mapping", VALID, "- just\n- a list\n"),
    ];
    let validator = validator();
    let mut accepted = Vec::new();
    for (what, from, to) in cases {
        assert!(VALID.contains(from), "case {what:?}: {from:?} not in VALID");
        let source = VALID.replacen(from, to, 1);
        let instance = yaml_to_json(&source, what);
        if validator.is_valid(&instance) {
            accepted.push(format!("{what}:\n{source}"));
        }
    }
    assert!(
        accepted.is_empty(),
        "the schema accepts invalid documents:\n{}",
        accepted.join("\n")
    );
}

/// Unit strings (issue 28.2): the schema accepts each dimension's units
/// where `vbi check` does, and refuses a unit of another dimension or none.
#[test]
fn the_schema_accepts_units_of_the_right_dimension_only() {
    let validator = validator();
    let accepted: &[(&str, &str)] = &[
        ("spans: [20.0]", "spans: [20 m, 20000 mm, 0.02 km, 2e3 cm]"),
        ("bending_stiffness: 3.2e9", "bending_stiffness: 3.2 GN*m^2"),
        ("bending_stiffness: 3.2e9", "bending_stiffness: 3.2 GN·m²"),
        ("mass_per_length: 2000.0", "mass_per_length: 2 t/m"),
        ("loads: [100000.0]", "loads: [100 kN]"),
        ("loads: [100000.0]", "loads: [0.1 MN]"),
        ("loads: [100000.0]", "loads: [1e5 N]"),
        ("speed: 20.0", "speed: 72 km/h"),
        ("x: 10.0", "x: 10 m"),
        (
            "    speed: 20.0\n",
            "    speed: 20.0\n    acceleration: -0.1 g\n    entry_time: 250 ms\n",
        ),
        (
            "  - type: moving_force\n    loads: [100000.0]\n    speed: 20.0\n",
            "  - {type: oscillator, sprung_mass: 5.75 t, stiffness: 1595 kN/m, \
             damping: 3.5 kN*s/m, speed: 20.0}\n",
        ),
        (
            "  mass_per_length: 2000.0\n",
            "  mass_per_length: 2000.0\n  modes: {max_frequency: 30 Hz}\n",
        ),
        // Any SI prefix on every dimension (issue 38.8).
        ("bending_stiffness: 3.2e9", "bending_stiffness: 3200 MN*m^2"),
        ("mass_per_length: 2000.0", "mass_per_length: 2 Mg/m"),
        ("spans: [20.0]", "spans: [20000000 µm]"),
        ("loads: [100000.0]", "loads: [1e-4 GN]"),
        // A variant whose fields all default, as its bare tag.
        ("name: minimal\n", "name: minimal\ncontact: rigid\n"),
        ("name: minimal\n", "name: minimal\ncontact: permanent\n"),
    ];
    let refused: &[(&str, &str)] = &[
        ("spans: [20.0]", "spans: [20 s]"),
        ("spans: [20.0]", "spans: [20 kg]"),
        ("spans: [20.0]", "spans: [20 furlongs]"),
        ("bending_stiffness: 3.2e9", "bending_stiffness: 3.2 GN/m"),
        ("mass_per_length: 2000.0", "mass_per_length: 2 t"),
        ("loads: [100000.0]", "loads: [100 kN/m]"),
        ("x: 10.0", "x: '10'"),
        ("x: 10.0", "x: ten m"),
        // Strict units (issue 38.8): no space inside a unit, no NaN, the
        // gram only with a prefix (a bare `g` is standard gravity).
        ("spans: [20.0]", "spans: [20 m m]"),
        ("spans: [20.0]", "spans: [20 k m]"),
        ("x: 10.0", "x: NaN m"),
        ("speed: 20.0", "speed: NaN km/h"),
        ("speed: 20.0", "speed: 72 km / h"),
        ("mass_per_length: 2000.0", "mass_per_length: 2000000 g/m"),
        ("name: minimal\n", "name: minimal\ncontact: rigdi\n"),
        ("name: minimal\n", "name: minimal\nsurface: harmonic\n"),
    ];
    let mut wrong = Vec::new();
    for (valid, cases) in [(true, accepted), (false, refused)] {
        for (from, to) in cases {
            assert!(VALID.contains(from), "{from:?} not in VALID");
            let source = VALID.replacen(from, to, 1);
            let instance = yaml_to_json(&source, to);
            if validator.is_valid(&instance) != valid {
                wrong.push(format!("{to} (want valid: {valid})"));
            }
            // `vbi check` agrees (the schema is only as right as this).
            let checked = vbi::plan::load_str(&source, "units.yaml").is_ok();
            if checked != valid {
                wrong.push(format!("{to}: vbi check says valid = {checked}"));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The schema names itself (issue 28.5): editors and other schemas refer to
/// it by this `$id` wherever the file is copied.
#[test]
fn the_schema_has_an_id() {
    assert_eq!(
        schema()["$id"],
        "https://vbi.dev/schema/vbi.schema.json",
        "the editor set-up (docs/guide/editor.md) states this $id"
    );
}

// ---------------------------------------------------------------------------
// (e) the schema itself: draft 2020-12, resolvable, documented
// ---------------------------------------------------------------------------

#[test]
fn schema_is_valid_draft_2020_12() {
    let schema = schema();
    assert_eq!(
        schema.get("$schema").and_then(Value::as_str),
        Some(DRAFT_2020_12),
        "the schema must declare draft 2020-12"
    );
    if let Err(e) = jsonschema::draft202012::meta::validate(&schema) {
        panic!(
            "the schema is not a valid draft 2020-12 schema: {e} at {}",
            e.instance_path()
        );
    }
    // It compiles, and every local reference points at something.
    let _ = validator();
    let mut refs = Vec::new();
    collect_refs(&schema, &mut refs);
    assert!(!refs.is_empty(), "expected $defs references in the schema");
    let dangling: Vec<&String> = refs
        .iter()
        .filter(|r| {
            r.strip_prefix('#')
                .is_none_or(|pointer| schema.pointer(pointer).is_none())
        })
        .collect();
    assert!(dangling.is_empty(), "unresolvable $ref: {dangling:?}");
}

fn collect_refs(value: &Value, out: &mut Vec<String>) {
    match value {
        Value::Object(map) => {
            if let Some(Value::String(r)) = map.get("$ref") {
                out.push(r.clone());
            }
            map.values().for_each(|v| collect_refs(v, out));
        }
        Value::Array(items) => items.iter().for_each(|v| collect_refs(v, out)),
        _ => {}
    }
}

/// Keywords whose value is one subschema.
const SUBSCHEMA: &[&str] = &[
    "additionalProperties",
    "items",
    "contains",
    "not",
    "if",
    "then",
    "else",
    "propertyNames",
    "unevaluatedItems",
    "unevaluatedProperties",
];
/// Keywords whose value is a list of subschemas.
const SUBSCHEMA_LIST: &[&str] = &["allOf", "anyOf", "oneOf", "prefixItems"];
/// Keywords whose value maps names to subschemas (other than `properties`).
const SUBSCHEMA_MAP: &[&str] = &[
    "$defs",
    "definitions",
    "patternProperties",
    "dependentSchemas",
];

/// Walks the schema and lists (JSON pointer, property schema) of every
/// property without a non-empty description.
fn undocumented_properties(schema: &Value, pointer: &str, out: &mut Vec<String>) {
    let Value::Object(map) = schema else {
        return;
    };
    for (key, value) in map {
        let here = format!("{pointer}/{key}");
        if key == "properties" {
            let Value::Object(properties) = value else {
                continue;
            };
            for (name, property) in properties {
                let at = format!("{here}/{name}");
                let documented = property
                    .get("description")
                    .and_then(Value::as_str)
                    .is_some_and(|d| !d.trim().is_empty());
                if !documented {
                    out.push(format!("{at}  {property}"));
                }
                undocumented_properties(property, &at, out);
            }
        } else if SUBSCHEMA.contains(&key.as_str()) {
            undocumented_properties(value, &here, out);
        } else if SUBSCHEMA_LIST.contains(&key.as_str()) {
            if let Value::Array(items) = value {
                for (i, item) in items.iter().enumerate() {
                    undocumented_properties(item, &format!("{here}/{i}"), out);
                }
            }
        } else if SUBSCHEMA_MAP.contains(&key.as_str())
            && let Value::Object(entries) = value
        {
            for (name, entry) in entries {
                undocumented_properties(entry, &format!("{here}/{name}"), out);
            }
        }
    }
}

#[test]
fn every_property_has_a_description() {
    let schema = schema();
    let mut missing = Vec::new();
    undocumented_properties(&schema, "#", &mut missing);
    assert!(
        missing.is_empty(),
        "{} schema propert{} without a description (the doc comment of the field \
         becomes the description; say the unit there):\n  {}",
        missing.len(),
        if missing.len() == 1 { "y" } else { "ies" },
        missing.join("\n  ")
    );
}

#[test]
fn the_description_walk_finds_an_undocumented_property() {
    let schema = serde_json::json!({
        "properties": {"a": {"description": "documented", "type": "number"}},
        "$defs": {"D": {"oneOf": [{"properties": {"b": {"type": "string"}}}]}}
    });
    let mut missing = Vec::new();
    undocumented_properties(&schema, "#", &mut missing);
    assert_eq!(missing.len(), 1, "{missing:?}");
    assert!(missing[0].starts_with("#/$defs/D/oneOf/0/properties/b "));
}

// ---------------------------------------------------------------------------
// (f) the schema's value rules are those of `vbi check`
// ---------------------------------------------------------------------------

/// Each case edits the valid base document to a value just past one of the
/// limits the schema declares (`exclusiveMinimum`, `minimum`, `maximum`,
/// `minItems`, `enum`), and to one just inside it: the schema and `vbi check`
/// must agree on both, so an editor never flags what runs nor passes what
/// `vbi check` refuses.
#[test]
fn the_schema_limits_are_those_of_vbi_check() {
    let cases: &[(&str, &str, &str, &str)] = &[
        // (what, replaced, past the limit, just inside)
        (
            "span length",
            "spans: [20.0]",
            "spans: [0.0]",
            "spans: [10.0]",
        ),
        (
            "span list",
            "spans: [20.0]",
            "spans: []",
            "spans: [20.0, 20.0]",
        ),
        (
            "bending stiffness",
            "bending_stiffness: 3.2e9",
            "bending_stiffness: 0",
            "bending_stiffness: 1.0",
        ),
        (
            "mass per length",
            "mass_per_length: 2000.0",
            "mass_per_length: -1",
            "mass_per_length: 1.0",
        ),
        (
            "elements per span",
            "  mass_per_length: 2000.0\n",
            "  mass_per_length: 2000.0\n  elements_per_span: 0\n",
            "  mass_per_length: 2000.0\n  elements_per_span: 1\n",
        ),
        (
            "mode count",
            "  mass_per_length: 2000.0\n",
            "  mass_per_length: 2000.0\n  modes: {count: 0}\n",
            "  mass_per_length: 2000.0\n  modes: {count: 1}\n",
        ),
        (
            "damping ratio",
            "  mass_per_length: 2000.0\n",
            "  mass_per_length: 2000.0\n  damping: {type: modal, ratio: 1.0}\n",
            "  mass_per_length: 2000.0\n  damping: {type: modal, ratio: 0.0}\n",
        ),
        (
            "vehicle list",
            "vehicles:\n  - type: moving_force\n    loads: [100000.0]\n    speed: 20.0\n",
            "vehicles: []\n",
            "vehicles:\n  - type: moving_force\n    loads: [100000.0]\n    speed: 20.0\n",
        ),
        ("speed", "speed: 20.0", "speed: 0.0", "speed: 0.1"),
        ("top speed", "speed: 20.0", "speed: 1000.5", "speed: 1000.0"),
        (
            "axle load",
            "loads: [100000.0]",
            "loads: [-1.0]",
            "loads: [1.0]",
        ),
        (
            "axle loads",
            "loads: [100000.0]",
            "loads: []",
            "loads: [1.0]",
        ),
        (
            "entry time",
            "speed: 20.0",
            "speed: 20.0\n    entry_time: -0.5",
            "speed: 20.0\n    entry_time: 0.0",
        ),
        (
            "start position",
            "speed: 20.0",
            "speed: 20.0\n    start_position: 0.5",
            "speed: 20.0\n    start_position: 0.0",
        ),
        (
            "gravity",
            "name: minimal\n",
            "name: minimal\ngravity: 0\n",
            "name: minimal\ngravity: 1.0\n",
        ),
        ("empty name", "name: minimal\n", "name: ''\n", "name: m\n"),
        (
            "time step",
            "name: minimal\n",
            "name: minimal\nsolver: {time_step: 0.0}\n",
            "name: minimal\nsolver: {time_step: 0.001}\n",
        ),
        (
            "free vibration",
            "name: minimal\n",
            "name: minimal\nsolver: {free_vibration: -0.1}\n",
            "name: minimal\nsolver: {free_vibration: 0.0}\n",
        ),
        (
            "Newmark γ",
            "name: minimal\n",
            "name: minimal\nsolver: {newmark: {gamma: 0.49}}\n",
            "name: minimal\nsolver: {newmark: {gamma: 0.5}}\n",
        ),
        (
            "HHT α",
            "name: minimal\n",
            "name: minimal\nsolver: {newmark: {alpha: 0.01}}\n",
            "name: minimal\nsolver: {newmark: {alpha: -0.3}}\n",
        ),
        (
            "roughness wavelength",
            "name: minimal\n",
            "name: minimal\nsurface: {type: harmonic, amplitude: 0.001, wavelength: 0.0}\n",
            "name: minimal\nsurface: {type: harmonic, amplitude: 0.001, wavelength: 1.0}\n",
        ),
    ];
    let validator = validator();
    let mut disagreements = Vec::new();
    for (what, from, past, inside) in cases {
        assert!(VALID.contains(from), "case {what:?}: {from:?} not in VALID");
        for (edit, should_pass) in [(past, false), (inside, true)] {
            let source = VALID.replacen(from, edit, 1);
            let schema_ok = validator.is_valid(&yaml_to_json(&source, what));
            let check = vbi::plan::load_str(&source, "case.yaml");
            let check_ok = check.is_ok();
            if schema_ok != should_pass || check_ok != should_pass {
                disagreements.push(format!(
                    "{what} ({edit:?}): expected {}, schema {}, vbi check {}{}",
                    if should_pass { "valid" } else { "invalid" },
                    if schema_ok { "accepts" } else { "rejects" },
                    if check_ok { "accepts" } else { "rejects" },
                    check.err().map(|e| format!(" ({e})")).unwrap_or_default(),
                ));
            }
        }
    }
    assert!(
        disagreements.is_empty(),
        "the schema and `vbi check` disagree:\n  {}",
        disagreements.join("\n  ")
    );
}

#[test]
fn optional_fields_have_no_null_default_and_unions_are_objects() {
    let text = vbi::schema::schema_json();
    assert!(
        !text.contains("\"default\": null"),
        "a `\"default\": null` makes yaml-language-server stop completing"
    );
    let schema = schema();
    for name in [
        "Bridge", "Vehicle", "Surface", "Contact", "Damping", "Rigidity", "Study",
    ] {
        let union = &schema["$defs"][name];
        let alternatives = union["oneOf"].as_array().expect("a union");
        // A variant whose fields all default may also be its bare tag
        // (`contact: rigid`, issue 38.8): a string alternative for each,
        // and the union typed object first (editors still insert `key:`
        // and a new line, lsp::every_top_level_key_is_completed).
        let bare: Vec<&Value> = alternatives
            .iter()
            .filter(|a| a["type"] == "string")
            .collect();
        for tag in &bare {
            let variant = tag["const"].as_str().expect("a bare tag names its variant");
            assert!(
                alternatives.iter().any(|a| a["type"] == "object"
                    && a["properties"]["type"]["const"] == variant
                    && a["required"] == serde_json::json!(["type"])),
                "{name}: the bare tag `{variant}` is not a variant whose fields all default"
            );
        }
        let want = if bare.is_empty() {
            serde_json::json!("object")
        } else {
            serde_json::json!(["object", "string"])
        };
        assert_eq!(
            union["type"], want,
            "the tagged union {name} needs \"type\": \"object\" for editors to insert `key:`"
        );
    }
    // Those that have variants written as bare tags.
    for (name, tag) in [
        ("Contact", "rigid"),
        ("Contact", "permanent"),
        ("Surface", "smooth"),
    ] {
        assert!(
            schema["$defs"][name]["oneOf"]
                .as_array()
                .unwrap()
                .iter()
                .any(|a| a["type"] == "string" && a["const"] == tag),
            "{name} has no bare `{tag}`"
        );
    }
    assert_eq!(schema["properties"]["gravity"]["default"], 9.81);
}
