//! Every default the schema states (and so docs/format.md, generated from
//! it) is the one the code applies (issue 40.3). The numbers of the
//! automatic choices and of the presets are written into the descriptions
//! from the constants the code uses (`{{NAME}}` in a doc comment,
//! [`vbi::schema::documented_constants`]); these tests check that every
//! such slot is filled and used, that a default stated in words is the
//! schema's `default` keyword, that the keyword is what the resolved scene
//! holds where the file leaves the key out, that `limits` states the
//! budgets the checks apply, and that a study writes the files its
//! description names.

use std::path::Path;

use regex::Regex;
use serde_json::Value;

use crate::support::{Scratch, manifest_dir, vbi};

fn schema() -> Value {
    serde_json::from_str(&vbi::schema::schema_json()).expect("the schema parses")
}

/// The `.rs` files under `dir`, with their text.
fn sources(dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).expect("read src") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).expect("read source");
            out.push((path.display().to_string(), text));
        }
    }
}

/// No `{{NAME}}` is left in the schema or the committed reference, and
/// every constant of the table fills at least one doc comment of src/.
#[test]
fn every_documented_constant_is_filled_in_and_used() {
    let text = vbi::schema::schema_json();
    let reference = std::fs::read_to_string(manifest_dir().join("docs/format.md")).unwrap();
    let slot = Regex::new(r"\{\{[^}]*\}\}").unwrap();
    for (what, body) in [("the schema", &text), ("docs/format.md", &reference)] {
        let left: Vec<&str> = slot.find_iter(body).map(|m| m.as_str()).collect();
        assert!(left.is_empty(), "{what} has unfilled slots {left:?}");
    }
    let mut files = Vec::new();
    sources(&manifest_dir().join("src"), &mut files);
    for (name, value) in vbi::schema::documented_constants() {
        let slot = format!("{{{{{name}}}}}");
        assert!(
            files.iter().any(|(_, text)| text.contains(&slot)),
            "{slot} (= {value}) is in the table but no doc comment states it"
        );
    }
}

/// A stated default that is a plain number ("Default 20.", "Default: 1 m",
/// in SI units) is the property's `default` keyword, so that the keyword the
/// next test compares with the code is the number the reader sees. A
/// conditional default (its sentence says "except", "when", "unless" or
/// ", or") has no single value and is left to its own tests.
#[test]
fn a_default_stated_in_words_is_the_default_keyword() {
    let stated = Regex::new(
        r"[Dd]efault:? (-?\d+(?:\.\d+)?(?:e-?\d+)?)( ?(?:m/s|km/h|m|s|Hz))?(?:[.;,:](?:\s|$)|\s\(|$)",
    )
    .unwrap();
    let mut problems = Vec::new();
    let mut checked = 0;
    walk(&schema(), "", &mut |path, node| {
        let Some(text) = node.get("description").and_then(Value::as_str) else {
            return;
        };
        let Some(found) = stated.captures(text) else {
            return;
        };
        let at = found.get(0).unwrap().start();
        let start = text[..at].rfind(". ").map_or(0, |i| i + 2);
        let end = text[at..].find(". ").map_or(text.len(), |i| at + i);
        let sentence = &text[start..end];
        let conditional = ["except", " when ", ", or", "unless"]
            .iter()
            .any(|w| sentence.contains(w));
        let unit = found.get(2).map_or("", |u| u.as_str().trim());
        if conditional || unit == "km/h" {
            return;
        }
        let number: f64 = found[1].parse().unwrap();
        checked += 1;
        match node.get("default").and_then(Value::as_f64) {
            Some(keyword) if (keyword - number).abs() <= 1e-12 * number.abs() => {}
            other => problems.push(format!(
                "{path}: the text says {:?}, the `default` keyword is {other:?}",
                found.get(0).unwrap().as_str()
            )),
        }
    });
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(checked >= 40, "only {checked} stated defaults found");
}

/// Calls `f` on every object of `value` with its JSON pointer.
fn walk(value: &Value, path: &str, f: &mut dyn FnMut(&str, &Value)) {
    match value {
        Value::Object(map) => {
            f(path, value);
            for (key, item) in map {
                walk(item, &format!("{path}/{key}"), f);
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                walk(item, &format!("{path}/{i}"), f);
            }
        }
        _ => {}
    }
}

/// `node` with its `$ref` followed (once per level).
fn deref<'a>(root: &'a Value, node: &'a Value) -> &'a Value {
    match node.get("$ref").and_then(Value::as_str) {
        Some(target) => root.pointer(target.trim_start_matches('#')).unwrap_or(node),
        None => node,
    }
}

/// The object schemas `resolved` may be an instance of: `node` itself, or
/// the variants of its `oneOf`/`anyOf` whose `type` tag is `resolved`'s.
fn variants<'a>(root: &'a Value, node: &'a Value, resolved: &Value) -> Vec<&'a Value> {
    let node = deref(root, node);
    let mut out = Vec::new();
    for key in ["oneOf", "anyOf"] {
        for variant in node
            .get(key)
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            let variant = deref(root, variant);
            let tag = variant
                .pointer("/properties/type")
                .and_then(|t| t.get("const").or_else(|| t.pointer("/enum/0")));
            match (tag, resolved.get("type")) {
                (Some(tag), Some(kind)) if tag == kind => out.push(variant),
                (None, _) if variant.get("properties").is_some() => out.push(variant),
                _ => {}
            }
        }
    }
    if node.get("properties").is_some() {
        out.push(node);
    }
    out
}

/// Compares, under `node`, every key the resolved scene holds and the file
/// left out with the key's `default` keyword; counts the comparisons.
fn compare(
    root: &Value,
    node: &Value,
    resolved: &Value,
    written: Option<&Value>,
    path: &str,
    problems: &mut Vec<String>,
    compared: &mut usize,
) {
    match resolved {
        Value::Object(map) => {
            for variant in variants(root, node, resolved) {
                let Some(Value::Object(properties)) = variant.get("properties") else {
                    continue;
                };
                for (key, value) in map {
                    let Some(property) = properties.get(key) else {
                        continue;
                    };
                    let given = written.and_then(|w| w.get(key));
                    let at = format!("{path}.{key}");
                    if given.is_none()
                        && let Some(default) = property.get("default")
                    {
                        *compared += 1;
                        let same = match (default.as_f64(), value.as_f64()) {
                            (Some(a), Some(b)) => (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
                            _ => default == value,
                        };
                        if !same {
                            problems.push(format!(
                                "{at}: the schema's default is {default}, the resolved scene has {value}"
                            ));
                        }
                    }
                    compare(root, property, value, given, &at, problems, compared);
                }
            }
        }
        Value::Array(items) => {
            let node = deref(root, node);
            if let Some(item_schema) = node.get("items") {
                for (i, item) in items.iter().enumerate() {
                    let given = written.and_then(|w| w.get(i));
                    let at = format!("{path}[{i}]");
                    compare(root, item_schema, item, given, &at, problems, compared);
                }
            }
        }
        _ => {}
    }
}

/// Small scenes that leave most keys out, between them covering every
/// section the resolved scene writes back.
const SCENES: &[&str] = &[
    // A beam, an oscillator, a harmonic surface, every record kind.
    "name: a
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2e9, mass_per_length: 2000.0}
vehicles: [{type: oscillator, sprung_mass: 4000.0, stiffness: 4.0e6, speed: 20.0}]
surface: {type: harmonic, amplitude: 0.001, wavelength: 5.0}
record:
  - {name: d, quantity: bridge_displacement, x: 10.0}
  - {name: a, quantity: bridge_acceleration, x: 10.0}
  - {name: m, quantity: bridge_moment, x: 10.0}
  - {name: f, quantity: contact_force, wheel: 1}
  - {name: v, quantity: vehicle_acceleration, dof: sprung}
envelopes: {}
",
    // A plate, the plate paper's truck, a random road, the iterative solver.
    "name: b
bridge: {type: plate, spans: [10.0, 12.0], width: 8.0, thickness: 0.5, density: 2500.0,
         rigidity: {type: isotropic, youngs_modulus: 3.0e10}, modes: {count: 12}}
vehicles: [{type: h20_44, speed: 20.0, lateral_position: 3.0}]
surface: {type: random, class: good}
solver: {method: iterative}
record: [{name: d, quantity: bridge_displacement, x: 11.0, y: 4.0}]
",
    // AASHTO's trucks as axle loads, an ISO road, the elastic contact.
    "name: c
bridge: {type: beam, spans: [25.0], bending_stiffness: 8.0e9, mass_per_length: 2300.0}
vehicles:
  - {type: aashto_hs20_44, speed: 25.0}
  - {type: oscillator, sprung_mass: 5000.0, unsprung_mass: 500.0, stiffness: 2.0e6, speed: 25.0, entry_time: 0.5}
surface: {type: iso8608, class: B}
contact: {type: elastic, stiffness: 1.0e8}
record: [{name: d, quantity: bridge_displacement, x: 12.5}]
",
    // A rail car and a train on FRA track, rigid contact.
    "name: d
bridge: {type: beam, spans: [32.0], bending_stiffness: 1.3e10, mass_per_length: 12000.0}
vehicles:
  - {type: rail_car, speed: 40.0}
  - {type: train, count: 2, car_spacing: 25.0, speed: 40.0, entry_time: 2.0}
surface: {type: fra, class: 6}
contact: {type: rigid}
record: [{name: d, quantity: bridge_displacement, x: 16.0}]
",
    // A speed sweep.
    "name: e
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2e9, mass_per_length: 2000.0}
vehicles: [{type: moving_force, loads: [1.0e5], speed: 20.0}]
record: [{name: d, quantity: bridge_displacement, x: 10.0}]
study: {type: speed_sweep, speeds: {from: 10.0, to: 30.0, count: 3}}
",
    // A Monte Carlo study.
    "name: f
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2e9, mass_per_length: 2000.0, modes: {count: 3}}
vehicles: [{type: oscillator, sprung_mass: 4000.0, stiffness: 4.0e6, speed: 20.0}]
surface: {type: random, coefficient: 1.0e-6, sampling_length: 40.0, terms: 40}
record: [{name: d, quantity: bridge_displacement, x: 10.0}]
study: {type: monte_carlo, samples: 6}
",
    // A resonance check.
    "name: g
bridge: {type: beam, spans: [20.0], bending_stiffness: 2.43e10, mass_per_length: 15000.0, modes: {count: 3}}
vehicles: [{type: hslm, model: A1, speed: 50.0}]
record: [{name: a, quantity: bridge_acceleration, x: 10.0}]
study: {type: resonance_check, trains: [A1], line_speed: 200 km/h}
",
];

/// Where a scene leaves a key out, the resolved scene (what resolved.yaml
/// writes) holds the schema's `default` for it: the keyword stated for the
/// reader is the value the code applied.
#[test]
fn the_resolved_scene_holds_the_schema_s_defaults() {
    let root = schema();
    let mut problems = Vec::new();
    let mut compared = 0;
    for text in SCENES {
        let written = vbi::scenario::yaml::parse(text)
            .expect("YAML")
            .expect("a document")
            .to_json();
        let loaded = vbi::plan::load_str(text, "defaults.yaml").unwrap_or_else(|e| panic!("{e}"));
        let resolved = serde_json::to_value(&loaded.scenario).expect("the scene serialises");
        let name = written["name"].as_str().unwrap_or("?").to_owned();
        compare(
            &root,
            &root,
            &resolved,
            Some(&written),
            &name,
            &mut problems,
            &mut compared,
        );
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(compared >= 60, "only {compared} defaults compared");
}

/// Every `limits` budget's stated default and `default` keyword are the
/// budget the checks apply ([`vbi::scenario::resolved::Limits`]'s default).
#[test]
fn limits_state_the_budgets_the_checks_apply() {
    let root = schema();
    let applied =
        serde_json::to_value(vbi::scenario::resolved::Limits::default()).expect("limits serialise");
    let properties = root
        .pointer("/$defs/Limits/properties")
        .and_then(Value::as_object)
        .expect("the limits section");
    let Value::Object(applied) = applied else {
        panic!("limits serialise to a map");
    };
    assert_eq!(properties.len(), applied.len(), "one property per budget");
    for (key, value) in &applied {
        let property = &properties[key];
        assert_eq!(property.get("default"), Some(value), "limits.{key}");
        let text = property["description"].as_str().unwrap();
        let stated = vbi::schema::number(value.as_f64().unwrap());
        assert!(
            text.contains(&format!("efault {stated}")),
            "limits.{key}: {text:?} does not state {stated}"
        );
    }
}

/// A Monte Carlo study writes the files its description names (the
/// envelope plot is one `envelope_<record>.png` per record, not
/// `envelopes.png`).
#[test]
fn a_monte_carlo_study_writes_the_files_its_description_names() {
    let root = schema();
    let mut described = None;
    walk(&root, "", &mut |_, node| {
        if node.pointer("/properties/type/const") == Some(&Value::from("monte_carlo")) {
            described = node["description"].as_str().map(str::to_owned);
        }
    });
    let described = described.expect("the monte_carlo variant");
    let writes = described
        .split("Writes ")
        .nth(1)
        .expect("the description says what it writes");
    let names: Vec<&str> = Regex::new(r"[a-z_<>]+\.(?:csv|png)")
        .unwrap()
        .find_iter(writes)
        .map(|m| m.as_str())
        .collect();
    assert!(names.len() >= 5, "{names:?}");
    let dir = Scratch::new("documented_defaults", "monte_carlo");
    let scene = "name: mc
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2e9, mass_per_length: 2000.0, modes: {count: 3}}
vehicles: [{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 500.0, stiffness: 4.0e6, speed: 20.0}]
contact: {type: elastic, stiffness: 4.0e8}
surface: {type: random, coefficient: 1.0e-6, sampling_length: 40.0, terms: 40}
solver: {time_step: 2.0e-3}
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
  - {name: force, quantity: contact_force, wheel: 1}
study: {type: monte_carlo, samples: 2, speeds: {from: 15.0, to: 20.0, count: 2}}
";
    std::fs::write(dir.path("mc.yaml"), scene).unwrap();
    let out = vbi(&["run", "mc.yaml", "--out", "r", "-q"], dir.dir());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for name in names {
        let files: Vec<String> = if name.contains("<record>") {
            ["midspan", "force"]
                .iter()
                .map(|r| name.replace("<record>", r))
                .collect()
        } else {
            vec![name.to_owned()]
        };
        for file in files {
            assert!(
                dir.path("r").join(&file).is_file(),
                "the description names {file}, the study did not write it"
            );
        }
    }
    assert!(!dir.path("r").join("envelopes.png").exists());
}

/// docs/cluster.md is written by hand: its option table states the
/// defaults of slurm/vbi-array.sh (`${VBI_SLURM_…:-default}`), and the
/// `limits` budgets it names are [`vbi::scenario::resolved::Limits`]'s.
#[test]
fn the_cluster_guide_states_the_script_s_and_the_limits_defaults() {
    let guide = std::fs::read_to_string(manifest_dir().join("docs/cluster.md")).unwrap();
    let script = std::fs::read_to_string(manifest_dir().join("slurm/vbi-array.sh")).unwrap();
    let applied: std::collections::HashMap<&str, &str> =
        Regex::new(r"\$\{(VBI_SLURM_[A-Z_]+):-([^}]*)\}")
            .unwrap()
            .captures_iter(&script)
            .map(|c| (c.get(1).unwrap().as_str(), c.get(2).unwrap().as_str()))
            .collect();
    let row = Regex::new(r"(?m)^\|[^|]+\| `(VBI_SLURM_[A-Z_]+)` \| ([^|]+) \|").unwrap();
    let mut rows = 0;
    for found in row.captures_iter(&guide) {
        let variable = &found[1];
        let stated = found[2].trim().trim_matches('`');
        let default = applied
            .get(variable)
            .unwrap_or_else(|| panic!("{variable} is not read by the script"));
        if default.is_empty() {
            assert!(
                stated == "the cluster's" || stated.starts_with("as "),
                "{variable}: the guide says {stated:?}, the script leaves it to sbatch"
            );
        } else {
            assert_eq!(stated, *default, "{variable}");
        }
        rows += 1;
    }
    assert_eq!(rows, applied.len(), "one row per variable the script reads");
    let budgets =
        serde_json::to_value(vbi::scenario::resolved::Limits::default()).expect("limits serialise");
    let mut named = 0;
    for found in Regex::new(r"`limits\.(\w+)` \(default ([0-9][0-9 ]*)")
        .unwrap()
        .captures_iter(&guide)
    {
        let stated: f64 = found[2].replace(' ', "").parse().unwrap();
        assert_eq!(
            budgets[&found[1]].as_f64(),
            Some(stated),
            "limits.{}",
            &found[1]
        );
        named += 1;
    }
    assert!(named >= 1, "the guide names the study_points budget");
}
