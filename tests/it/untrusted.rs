//! Issue 23: files from other people that passed `vbi check` while asking
//! for unbounded work or holding nonsense, and refusals blamed on the wrong
//! field. Each test loads a small scene through the library and asserts
//! the diagnostic's place (line:column) and wording.

use vbi::plan::{load_str, load_str_with};
use vbi::scenario::{LoadError, LoadOptions};

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
    // 600 axles: more than the default 500 wheels (line 8 is the vehicle).
    let loads = vec!["1e4"; 600].join(", ");
    let spacings = vec!["0.1"; 599].join(", ");
    let text = |limits: &str| {
        scene(&format!(
            "  - {{type: moving_force, loads: [{loads}], axle_spacings: [{spacings}], speed: 20.0}}\n\
             record: [{{name: midspan, quantity: bridge_displacement, x: 12.5}}]\n{limits}"
        ))
    };
    let raised = text("limits: {wheels: 1000, modes: 1.0e15, eigen_work: 1.0e15}\n");
    let untrusted = LoadOptions::default();
    let all = refused(&raised, untrusted.clone());
    assert!(all.starts_with("8:3:"), "{all}");
    for words in [
        "limits.wheels",
        "raises the limit to 1000",
        "--trust-limits",
        "--allow-large",
    ] {
        assert!(all.contains(words), "`{words}` missing from:\n{all}");
    }
    // Allowed on the command line, the file's limits apply.
    let trusted = LoadOptions {
        trust_limits: true,
        ..LoadOptions::default()
    };
    load_str_with(&raised, "t.yaml", trusted).unwrap_or_else(|e| panic!("{e}"));
    // The library's `load_str` is called by a program that chose the file.
    load_str(&raised, "t.yaml").unwrap_or_else(|e| panic!("{e}"));
    // Lowering a limit in the file always works, trusted or not.
    let lowered = text("limits: {wheels: 100}\n");
    let all = refused(&lowered, untrusted.clone());
    assert!(
        all.starts_with("8:3:") && all.contains("limit of 100"),
        "{all}"
    );
    // Without a `limits` section the default refuses, and says how to raise it.
    let all = refused(&text(""), untrusted);
    assert!(
        all.contains("limit of 500") && all.contains("--trust-limits"),
        "{all}"
    );
}

/// Moments of inertia had no range: 1e308 kg·m² passed.
#[test]
fn inertias_of_1e308_are_refused() {
    let text = scene(
        "  - type: rail_car\n    speed: 20.0\n    parameters: {body_pitch_inertia: 1.0e308}\n",
    );
    assert_refused_at(&text, "10:38", &["body_pitch_inertia", "kg·m²"]);
}

/// A tab after `:` is valid YAML (a separator, not indentation).
#[test]
fn a_tab_after_a_colon_is_accepted() {
    let text = scene(
        "  - type: oscillator\n    sprung_mass:\t5750.0\n    stiffness: 1.595e6\n    speed:\t27.7\n",
    );
    load_str(&text, "t.yaml").unwrap_or_else(|e| panic!("{e}"));
}

/// The YAML layer: a tab after a value's `:` is separation white space
/// (YAML 1.2, production s-separate-in-line), parsed like a space; quoted
/// tabs and every location are those of the text as written.
#[test]
fn yaml_tab_after_colon_separates_like_a_space() {
    use vbi::scenario::yaml::{Location, parse};
    let src = "a:\t25\nb:\t\t-1.5\nc: 'x:\ty'\nd:\tword # é\ne:\n  - f:\tg\n";
    let node = parse(src).unwrap().unwrap();
    assert_eq!(
        node.to_json(),
        serde_json::json!({"a": 25, "b": -1.5, "c": "x:\ty", "d": "word", "e": [{"f": "g"}]})
    );
    let at = |line, col| Location { line, col };
    assert_eq!(node.get("a").unwrap().loc, at(1, 4));
    assert_eq!(node.get("b").unwrap().loc, at(2, 5));
    assert_eq!(node.get("d").unwrap().loc, at(4, 4));
    // A tab in indentation is still refused, at the tab.
    let e = parse("a:\t1\nb:\n\tc: 2\n").unwrap_err();
    assert_eq!(e.loc, at(3, 1), "{}", e.message);
    // A scenario-sized file written with tabs throughout (2,000 lines) is
    // repaired quickly; a huge one stays bounded in time.
    let lines =
        |n: usize, sep: &str| -> String { (0..n).map(|i| format!("k{i}:{sep}v\n")).collect() };
    let start = std::time::Instant::now();
    assert!(parse(&lines(2_000, " ")).is_ok());
    eprintln!("2,000 lines with spaces: {:?}", start.elapsed());
    let start = std::time::Instant::now();
    assert!(parse(&lines(2_000, "\t")).is_ok());
    eprintln!("2,000 lines with tabs: {:?}", start.elapsed());
    let start = std::time::Instant::now();
    if let Err(e) = parse(&lines(100_000, "\t")) {
        assert!(e.message.contains("tab"), "{}", e.message);
    }
    eprintln!("100,000 lines with tabs: {:?}", start.elapsed());
    assert!(
        start.elapsed().as_secs_f64() < 10.0,
        "{:?}",
        start.elapsed()
    );
}
