//! Unit tests of the parent module.

use super::super::yaml::{Location, parse};
use super::*;
use serde::Deserialize;

#[derive(Deserialize, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
struct Scene {
    name: String,
    bridge: Bridge,
    vehicles: Vec<Vehicle>,
    #[serde(default)]
    note: Option<String>,
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(rename_all = "snake_case")]
enum Bridge {
    Beam(Beam),
    Plate(Plate),
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
struct Beam {
    spans: Vec<f64>,
    bending_stiffness: f64,
    #[serde(default)]
    modes: Option<Modes>,
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
struct Plate {
    width: f64,
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
enum Vehicle {
    Oscillator { sprung_mass: f64, speed: f64 },
    MovingForce { loads: Vec<f64> },
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(untagged)]
enum Modes {
    Count { count: usize },
    MaxFrequency { max_frequency: f64 },
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
enum Support {
    Pinned,
    Fixed,
    Spring { k: f64 },
    Pair(f64, f64),
    Wrapped(Plate),
    Nested(Bridge),
}

fn at(line: usize, col: usize) -> Option<Location> {
    Some(Location { line, col })
}

fn load<T: de::DeserializeOwned>(src: &str) -> Result<T, DeError> {
    from_node(&parse(src).expect("valid YAML").expect("non-empty"))
}

/// Deserialize and expect an error; returns (location, message).
fn fail<T: de::DeserializeOwned + std::fmt::Debug>(src: &str) -> (Option<Location>, String) {
    let e = load::<T>(src).expect_err("expected an error");
    (e.loc, e.message)
}

const GOOD: &str = "\
name: demo
bridge:
  spans: [20.0, 30]
  bending_stiffness: 1.0e9
  modes: {count: 4}
  type: beam
vehicles:
  - type: oscillator
    sprung_mass: 4000
    speed: .5
  - {type: moving_force, loads: [1e5, -3]}
";

#[test]
fn good_scene_with_type_last_and_flow_vehicle() {
    let scene: Scene = load(GOOD).unwrap();
    let want = Scene {
        name: "demo".into(),
        bridge: Bridge::Beam(Beam {
            spans: vec![20.0, 30.0],
            bending_stiffness: 1e9,
            modes: Some(Modes::Count { count: 4 }),
        }),
        vehicles: vec![
            Vehicle::Oscillator {
                sprung_mass: 4000.0,
                speed: 0.5,
            },
            Vehicle::MovingForce {
                loads: vec![1e5, -3.0],
            },
        ],
        note: None,
    };
    assert_eq!(scene, want);
}

#[test]
fn flow_style_bridge_and_untagged_modes() {
    let src = "name: x\nbridge: {type: beam, spans: [20.0], bending_stiffness: 2, modes: {max_frequency: 50}}\nvehicles: []\nnote: hi\n";
    let scene: Scene = load(src).unwrap();
    let Bridge::Beam(beam) = &scene.bridge else {
        panic!("{scene:?}")
    };
    assert_eq!(beam.spans, vec![20.0]);
    assert_eq!(
        beam.modes,
        Some(Modes::MaxFrequency {
            max_frequency: 50.0
        })
    );
    assert_eq!(scene.note.as_deref(), Some("hi"));
    let src = "name: x\nbridge: {type: beam, spans: [1], bending_stiffness: 2, modes: {count: -1}}\nvehicles: []\n";
    let (loc, msg) = fail::<Scene>(src);
    assert_eq!(loc, at(2, 63));
    assert_eq!(msg, "data did not match any variant of untagged enum Modes");
}

#[test]
fn unknown_key_in_newtype_variant_with_type_last() {
    let src = "name: demo\nbridge:\n  spans: [20.0]\n  bending_stifness: 1.0e9\n  type: beam\nvehicles: []\n";
    let (loc, msg) = fail::<Scene>(src);
    assert_eq!(loc, at(4, 3));
    assert_eq!(
        msg,
        "unknown field `bending_stifness`, expected one of `spans`, `bending_stiffness`, `modes`"
    );
}

#[test]
fn unknown_key_in_struct_variant() {
    let src = GOOD.replace("    sprung_mass: 4000", "    sprung_mas: 4000");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(9, 5));
    assert_eq!(
        msg,
        "unknown field `sprung_mas`, expected `sprung_mass` or `speed`"
    );
}

#[test]
fn wrong_type_deep_in_vehicle() {
    let src = GOOD.replace("speed: .5", "speed: \"fast\"");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(10, 12));
    assert_eq!(msg, "invalid type: string \"fast\", expected f64");
    let src = GOOD.replace("loads: [1e5, -3]", "loads: [1e5, abc]");
    assert_eq!(fail::<Scene>(&src).0, at(11, 39));
}

#[test]
fn missing_field_points_at_mapping() {
    let src = GOOD.replace("    speed: .5\n", "");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(8, 5));
    assert_eq!(msg, "missing field `speed`");
    let src = GOOD.replace("  bending_stiffness: 1.0e9\n", "");
    assert_eq!(
        fail::<Scene>(&src),
        (at(3, 3), "missing field `bending_stiffness`".into())
    );
    assert_eq!(
        fail::<Scene>("name: x\nvehicles: []\n"),
        (at(1, 1), "missing field `bridge`".into())
    );
}

#[test]
fn missing_type() {
    let src = GOOD.replace("  type: beam\n", "");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(3, 3));
    assert_eq!(msg, "missing `type`; expected one of `beam`, `plate`");
}

#[test]
fn unknown_type_value() {
    let src = GOOD.replace("type: beam", "type: bem");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(6, 9));
    assert_eq!(msg, "unknown variant `bem`, expected `beam` or `plate`");
    let src = GOOD.replace("type: beam", "type: [beam]");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(6, 9));
    assert_eq!(
        msg,
        "`type` must name a variant; expected one of `beam`, `plate`"
    );
    let src = GOOD.replace("type: moving_force", "type: truck");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(11, 12));
    assert_eq!(
        msg,
        "unknown variant `truck`, expected `oscillator` or `moving_force`"
    );
}

#[test]
fn non_finite_numbers_are_rejected() {
    for (text, col) in [(".nan", 12), ("1e400", 12), ("-.inf", 12), ("-1e999", 12)] {
        let src = GOOD.replace("speed: .5", &format!("speed: {text}"));
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(
            (loc, msg),
            (at(10, col), format!("`{text}` is not a finite number"))
        );
    }
    // Also through `deserialize_any`, so untagged enums cannot sneak a NaN in.
    // (serde buffers untagged content with `deserialize_any` first, so
    // the error even survives the untagged enum and points at the value.)
    let src = GOOD.replace("{count: 4}", "{max_frequency: .nan}");
    assert_eq!(
        fail::<Scene>(&src),
        (at(5, 26), "`.nan` is not a finite number".into())
    );
    assert_eq!(
        fail::<serde_json::Value>("[.nan]"),
        (at(1, 2), "`.nan` is not a finite number".into())
    );
    assert_eq!(
        fail::<f32>("1e39"),
        (at(1, 1), "`1e39` is out of range for f32".into())
    );
}

#[test]
fn numbers() {
    assert_eq!(
        load::<Vec<f64>>("[12, -3, 1.5, 1e5, 1.0e-4, .5, +1, 0x1F, 0o10]").unwrap(),
        [12.0, -3.0, 1.5, 1e5, 1e-4, 0.5, 1.0, 31.0, 8.0]
    );
    assert_eq!(load::<f32>("2.5").unwrap(), 2.5);
    assert_eq!(load::<Vec<u8>>("[0, 255, 0x10]").unwrap(), [0, 255, 16]);
    assert_eq!(
        load::<Vec<i64>>("[-9223372036854775808, +7]").unwrap(),
        [i64::MIN, 7]
    );
    assert_eq!(load::<usize>("42").unwrap(), 42);
    assert_eq!(
        load::<u128>("0xFFFFFFFFFFFFFFFFFFFF").unwrap(),
        0xFFFF_FFFF_FFFF_FFFF_FFFF
    );
    assert_eq!(
        fail::<Vec<u8>>("[1, 256]"),
        (at(1, 5), "`256` is out of range for u8".into())
    );
    assert_eq!(fail::<i8>("-129").1, "`-129` is out of range for i8");
    assert_eq!(fail::<u32>("-1").1, "`-1` is out of range for u32");
    assert_eq!(
        fail::<u64>("999999999999999999999999999999999999999999").1,
        "`999999999999999999999999999999999999999999` is out of range for u64"
    );
    assert_eq!(
        fail::<usize>("2.0").1,
        "invalid type: floating point `2.0`, expected usize"
    );
    assert_eq!(
        fail::<i32>("'3'").1,
        "invalid type: string \"3\", expected i32"
    );
    assert_eq!(
        fail::<f64>("\"abc\"").1,
        "invalid type: string \"abc\", expected f64"
    );
    assert_eq!(
        fail::<f64>("'1.5'").1,
        "invalid type: string \"1.5\", expected f64"
    );
    assert_eq!(
        fail::<f64>("true").1,
        "invalid type: boolean `true`, expected f64"
    );
    assert_eq!(fail::<f64>("~").1, "invalid type: null, expected f64");
    assert_eq!(fail::<f64>("[1]").1, "invalid type: sequence, expected f64");
}

#[test]
fn bools_strings_options_units() {
    assert_eq!(
        load::<Vec<bool>>("[true, True, TRUE, false, False, FALSE]").unwrap(),
        [true, true, true, false, false, false]
    );
    assert_eq!(
        fail::<bool>("yes").1,
        "invalid type: string \"yes\", expected a boolean"
    );
    assert_eq!(
        fail::<bool>("'true'").1,
        "invalid type: string \"true\", expected a boolean"
    );
    assert_eq!(
        load::<Vec<String>>("- 123\n- 'q'\n- true\n- 1.5\n- \"\"\n- |\n  b\n").unwrap(),
        ["123", "q", "true", "1.5", "", "b\n"]
    );
    assert_eq!(
        fail::<String>("~").1,
        "invalid type: null, expected a string"
    );
    assert_eq!(
        fail::<String>("{a: 1}").1,
        "invalid type: map, expected a string"
    );
    assert_eq!(
        load::<Vec<Option<u8>>>("[~, 3, null, ]").unwrap(),
        [None, Some(3), None]
    );
    assert_eq!(load::<Vec<()>>("[~, null]").unwrap(), [(), ()]);
    assert_eq!(
        fail::<()>("0").1,
        "invalid type: integer `0`, expected unit"
    );
    assert_eq!(load::<char>("x").unwrap(), 'x');
    assert_eq!(
        fail::<char>("xy").1,
        "invalid value: string \"xy\", expected a character"
    );
}

#[test]
fn sequences_tuples_maps() {
    assert_eq!(
        load::<(u8, String)>("[1, a]").unwrap(),
        (1, "a".to_string())
    );
    assert_eq!(
        fail::<(u8, u8)>("[1, 2, 3]"),
        (
            at(1, 8),
            "unexpected extra element; expected 2 element(s)".into()
        )
    );
    assert_eq!(
        fail::<(u8, u8)>("[1]").1,
        "invalid length 1, expected a tuple of size 2"
    );
    let m: std::collections::BTreeMap<String, f64> = load("{a: 1, b: 2.5}").unwrap();
    assert_eq!(
        m.into_iter().collect::<Vec<_>>(),
        [("a".into(), 1.0), ("b".into(), 2.5)]
    );
    assert_eq!(
        fail::<Vec<f64>>("x: 1").1,
        "invalid type: map, expected a sequence"
    );
    #[derive(Deserialize, Debug)]
    struct Meters(f64);
    assert_eq!(load::<Meters>("3").unwrap().0, 3.0);
    assert_eq!(
        fail::<Meters>("a"),
        (at(1, 1), "invalid type: string \"a\", expected f64".into())
    );
}

#[test]
fn deserialize_any_follows_core_schema() {
    let v: serde_json::Value =
        load("{a: ~, b: True, c: -3, d: 18446744073709551615, e: 1.5, f: '7', g: [x]}").unwrap();
    let want = serde_json::json!({"a": null, "b": true, "c": -3, "d": 18446744073709551615u64,
                                      "e": 1.5, "f": "7", "g": ["x"]});
    assert_eq!(v, want);
}

#[test]
fn unit_struct_tuple_and_scalar_variants() {
    assert_eq!(load::<Support>("pinned").unwrap(), Support::Pinned);
    assert_eq!(load::<Support>("'fixed'").unwrap(), Support::Fixed);
    assert_eq!(load::<Support>("{type: pinned}").unwrap(), Support::Pinned);
    assert_eq!(
        load::<Support>("k: 2\ntype: spring").unwrap(),
        Support::Spring { k: 2.0 }
    );
    assert_eq!(
        load::<Support>("{type: wrapped, width: 3}").unwrap(),
        Support::Wrapped(Plate { width: 3.0 })
    );
    let (loc, msg) = fail::<Support>("type: fixed\nk: 1\n");
    assert_eq!(
        (loc, msg.as_str()),
        (at(2, 1), "unexpected key `k` for `type: fixed`")
    );
    let (loc, msg) = fail::<Support>("x: 1\ny: 2\n");
    let want =
        "missing `type`; expected one of `pinned`, `fixed`, `spring`, `pair`, `wrapped`, `nested`";
    assert_eq!((loc, msg.as_str()), (at(1, 1), want));
    let (loc, msg) = fail::<Vec<Support>>("- pinned\n- pinnned\n");
    assert_eq!(loc, at(2, 3));
    assert!(
        msg.starts_with("unknown variant `pinnned`, expected one of `pinned`"),
        "{msg}"
    );
    let (loc, msg) = fail::<Support>("spring");
    assert_eq!(loc, at(1, 1));
    assert_eq!(
        msg,
        "`spring` is a variant with fields: write it as a mapping with `type: spring` and its fields"
    );
    let (loc, msg) = fail::<Support>("{type: pair}");
    assert_eq!(
        (loc, msg.as_str()),
        (
            at(1, 1),
            "variant `pair` is a tuple variant, which is not supported"
        )
    );
    assert_eq!(
        fail::<Support>("[1]").1,
        "invalid type: sequence, expected enum Support"
    );
    assert_eq!(
        fail::<Support>("~").1,
        "invalid type: null, expected enum Support"
    );
    let (loc, msg) = fail::<Support>("{type: spring, k: 1, type2: 3}");
    assert_eq!(
        (loc, msg.as_str()),
        (at(1, 22), "unknown field `type2`, expected `k`")
    );
    // `type` is consumed by dispatch: an enum nested in the same mapping sees none.
    let (loc, msg) = fail::<Support>("{type: nested, spans: [1]}");
    assert_eq!(
        (loc, msg.as_str()),
        (at(1, 1), "missing `type`; expected one of `beam`, `plate`")
    );
}

#[test]
fn aliases_deserialize() {
    let src = "name: a\nbridge: {type: plate, width: 4}\nvehicles:\n  - &v {type: oscillator, sprung_mass: 1, speed: 2}\n  - *v\n";
    let scene: Scene = load(src).unwrap();
    assert_eq!(scene.vehicles.len(), 2);
    assert_eq!(scene.vehicles[0], scene.vehicles[1]);
    // An error in an aliased node's root points at the alias.
    let src = "name: a\nbridge: &b {type: plate}\nvehicles:\n  - *b\n";
    let (loc, msg) = fail::<Scene>(src);
    assert_eq!((loc, msg.as_str()), (at(2, 12), "missing field `width`"));
    let src = "name: a\nbridge: {type: plate, width: 1}\nvehicles:\n  - *missing\n";
    assert!(parse(src).is_err());
}

#[test]
fn root_errors_and_note() {
    assert_eq!(
        fail::<Scene>("[1]"),
        (
            at(1, 1),
            "invalid type: sequence, expected struct Scene".into()
        )
    );
    let src = GOOD.replace("name: demo", "name: demo\nnote: ~\nextra: 1");
    let (loc, msg) = fail::<Scene>(&src);
    assert_eq!(loc, at(3, 1));
    assert!(msg.starts_with("unknown field `extra`"), "{msg}");
}

/// A variant whose fields all have defaults.
#[derive(Deserialize, Debug, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
enum Contact {
    Permanent,
    Rigid {
        #[serde(default)]
        restitution: Option<f64>,
    },
    Spring {
        k: f64,
        #[serde(default)]
        c: Option<f64>,
    },
    Wrapped(Defaults),
    Needs(Plate),
}

#[derive(Deserialize, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
struct Defaults {
    #[serde(default)]
    width: Option<f64>,
}

#[test]
fn a_variant_whose_fields_all_default_may_be_its_bare_tag() {
    // `contact: rigid` was refused once `rigid` gained a field.
    assert_eq!(
        load::<Contact>("rigid").unwrap(),
        Contact::Rigid { restitution: None }
    );
    assert_eq!(
        load::<Contact>("rigid").unwrap(),
        load::<Contact>("{type: rigid}").unwrap()
    );
    assert_eq!(
        load::<Contact>("wrapped").unwrap(),
        Contact::Wrapped(Defaults { width: None })
    );
    assert_eq!(load::<Contact>("permanent").unwrap(), Contact::Permanent);
    // A required field: the mapping is needed, and the message says so.
    let (loc, msg) = fail::<Contact>("spring");
    assert_eq!(
        (loc, msg.as_str()),
        (
            at(1, 1),
            "`spring` is a variant with fields: write it as a mapping with `type: spring` and its fields"
        )
    );
    let (loc, msg) = fail::<Vec<Contact>>("- rigid\n- needs");
    assert_eq!(
        (loc, msg.as_str()),
        (
            at(2, 3),
            "`needs` is a variant with parameters: write it as a mapping with `type: needs` and its fields"
        )
    );
    // A misspelt bare tag is still an unknown variant.
    let (loc, msg) = fail::<Contact>("rigdi");
    assert_eq!(loc, at(1, 1));
    assert!(msg.starts_with("unknown variant `rigdi`"), "{msg}");
}

#[derive(Deserialize, Debug, PartialEq)]
struct Required {
    speed: f64,
    count: usize,
    name: String,
    flag: bool,
    kind: Support,
}

#[test]
fn a_placeholder_reads_as_the_simplest_value_of_any_type() {
    use super::super::yaml::{Node, NodeKind};
    let placeholder = Node {
        kind: NodeKind::Placeholder,
        loc: Location { line: 3, col: 7 },
    };
    let key = |text: &str| Node {
        kind: NodeKind::Scalar {
            text: text.into(),
            plain: true,
        },
        loc: Location { line: 1, col: 1 },
    };
    let entries = ["speed", "count", "name", "flag", "kind"]
        .into_iter()
        .map(|k| (key(k), placeholder.clone()))
        .collect();
    let mapping = Node {
        kind: NodeKind::Mapping(entries),
        loc: Location { line: 1, col: 1 },
    };
    assert_eq!(
        from_node::<Required>(&mapping).unwrap(),
        Required {
            speed: 1.0,
            count: 1,
            name: String::new(),
            flag: false,
            kind: Support::Pinned,
        }
    );
    // A collection or a variant with fields is asked for: an error at the
    // placeholder (the type checker then drops it).
    let e = from_node::<Vec<f64>>(&placeholder).unwrap_err();
    assert_eq!(e.loc, at(3, 7));
    let e = from_node::<Plate>(&placeholder).unwrap_err();
    assert_eq!(e.loc, at(3, 7));
    let e = from_node::<Contact>(&Node {
        kind: NodeKind::Placeholder,
        loc: Location { line: 3, col: 7 },
    });
    assert_eq!(e.unwrap(), Contact::Permanent);
}

#[test]
fn subnormal_numbers_are_refused_with_help() {
    let e = load::<f64>("1e-320").unwrap_err();
    assert!(e.message.contains("subnormal"), "{}", e.message);
    assert_eq!(e.help.as_deref(), Some("write 0, or check the exponent"));
    let e = load::<f64>("-4.9e-324").unwrap_err();
    assert!(e.message.contains("subnormal"), "{}", e.message);
    let e = load::<f64>("1e-400").unwrap_err();
    assert!(e.message.contains("would be read as 0"), "{}", e.message);
    assert_eq!(load::<f64>("0.0e-400").unwrap(), 0.0);
    assert_eq!(
        load::<f64>("2.2250738585072014e-308").unwrap(),
        f64::MIN_POSITIVE
    );
}
