//! Unit tests of the parent module.

use super::*;

fn render(source: &str, line: usize, col: usize, msg: &str) -> String {
    Diagnostic::new("scenarios/bad.yaml", source, Location { line, col }, msg).to_string()
}

#[test]
fn renders_like_rustc() {
    let src = "name: x\nbridge: {}\nvehicles:\n  - type: oscillator\n  sprung_mas: 4000.0\n";
    let got = render(
        src,
        5,
        3,
        "unknown field `sprung_mas`, expected one of `sprung_mass`, `unsprung_mass`",
    );
    let want = "\
scenarios/bad.yaml:5:3: unknown field `sprung_mas`, expected one of `sprung_mass`, `unsprung_mass`
  |
5 |   sprung_mas: 4000.0
  |   ^";
    assert_eq!(got, want);
}

#[test]
fn gutter_grows_with_line_number() {
    let src = format!("{}key: value\n", "a: 1\n".repeat(11));
    let want = "f.yaml:12:6: bad\n   |\n12 | key: value\n   |      ^";
    let got = Diagnostic::new("f.yaml", &src, Location { line: 12, col: 6 }, "bad").to_string();
    assert_eq!(got, want);
}

#[test]
fn tabs_expand_and_caret_follows() {
    let got = render("a:\t\tx\n", 1, 5, "m");
    assert_eq!(
        got,
        "scenarios/bad.yaml:1:5: m\n  |\n1 | a:        x\n  |           ^"
    );
}

#[test]
fn multibyte_columns_count_chars() {
    let got = render("nämé: ü\n", 1, 7, "m");
    assert_eq!(
        got,
        "scenarios/bad.yaml:1:7: m\n  |\n1 | nämé: ü\n  |       ^"
    );
}

#[test]
fn crlf_and_lone_cr_line_breaks() {
    let src = "a: 1\r\nb: 2\r\nc: 3\rd: 4";
    assert_eq!(
        Diagnostic::new("f", src, Location { line: 2, col: 4 }, "m")
            .source_line
            .as_deref(),
        Some("b: 2")
    );
    assert_eq!(
        Diagnostic::new("f", src, Location { line: 4, col: 1 }, "m")
            .source_line
            .as_deref(),
        Some("d: 4")
    );
    assert_eq!(
        render(src, 2, 4, "m"),
        "scenarios/bad.yaml:2:4: m\n  |\n2 | b: 2\n  |    ^"
    );
}

#[test]
fn locations_at_and_past_the_end() {
    // The empty line after the final newline: where EOF errors land.
    assert_eq!(
        render("a: [1,\n", 2, 1, "m"),
        "scenarios/bad.yaml:2:1: m\n  |\n2 |\n  | ^"
    );
    // Past the end of a line: the caret still goes to the column.
    assert_eq!(
        render("ab", 1, 5, "m"),
        "scenarios/bad.yaml:1:5: m\n  |\n1 | ab\n  |     ^"
    );
    // Lines that do not exist: header only.
    assert_eq!(render("a: 1\n", 9, 1, "m"), "scenarios/bad.yaml:9:1: m");
    assert_eq!(
        render("", 1, 1, "m"),
        "scenarios/bad.yaml:1:1: m\n  |\n1 |\n  | ^"
    );
    assert_eq!(render("", 2, 1, "m"), "scenarios/bad.yaml:2:1: m");
}

#[test]
fn works_with_parse_and_deserialize_errors() {
    use super::super::{de::from_node, yaml::parse};
    let src = "a: 1\na: 2\n";
    let e = parse(src).unwrap_err();
    let d = Diagnostic::new("s.yaml", src, e.loc, e.message);
    assert_eq!(
        d.to_string(),
        "s.yaml:2:1: duplicate key `a` (first defined at line 1)\n  |\n2 | a: 2\n  | ^"
    );
    let src = "- 1\n- x\n";
    let e = from_node::<Vec<f64>>(&parse(src).unwrap().unwrap()).unwrap_err();
    let d = Diagnostic::new("s.yaml", src, e.loc.unwrap(), e.message);
    let want = "s.yaml:2:3: invalid type: string \"x\", expected f64\n  |\n2 | - x\n  |   ^";
    assert_eq!(d.to_string(), want);
    let boxed: Box<dyn std::error::Error> = Box::new(d);
    assert!(boxed.to_string().starts_with("s.yaml:2:3: "));
}
