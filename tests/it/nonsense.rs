//! Issue 39, point 5: nonsense that ran. A surface of metres (a harmonic
//! of 10 km amplitude ran to a mid-span of −4,758 m), a run whose wheels ×
//! steps × modes nothing budgeted, refusals that named `inf` instead of the
//! cause, and a YAML tag located a line off. Each test loads a small scene
//! through the library (or the binary, for what the terminal shows) and
//! asserts the diagnostic's place (line:column), wording and `help:` line.

use vbi::plan::load_str_with;
use vbi::scenario::{Diagnostic, LoadError, LoadOptions};

const BEAM: &str = "bridge:\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\n";
const OSC: &str =
    "  - type: oscillator\n    sprung_mass: 5750.0\n    stiffness: 1.595e6\n    speed: 27.7\n";

/// `name` + the beam + the oscillator + `rest` (line 1 is `name`, lines
/// 2–6 the beam, 7–11 the vehicles, `rest` from line 12).
fn scene(rest: &str) -> String {
    format!("name: t\n{BEAM}vehicles:\n{OSC}{rest}")
}

fn diagnostics(text: &str, options: LoadOptions) -> Vec<Diagnostic> {
    match load_str_with(text, "t.yaml", options) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(LoadError::Invalid(d)) => d,
        Err(e) => panic!("{e}"),
    }
}

fn shown(d: &[Diagnostic]) -> String {
    d.iter()
        .map(|d| {
            format!(
                "{}:{}: {}{}",
                d.loc.line,
                d.loc.col,
                d.message,
                d.help
                    .as_ref()
                    .map_or(String::new(), |h| format!("\n  = help: {h}"))
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The first diagnostic is at `at` (`LINE:COL`) and holds every one of
/// `words`; its `help:` line holds every one of `help`.
fn assert_first(text: &str, options: LoadOptions, at: &str, words: &[&str], help: &[&str]) {
    let d = diagnostics(text, options);
    let all = shown(&d);
    let first = &d[0];
    assert_eq!(
        format!("{}:{}", first.loc.line, first.loc.col),
        at,
        "expected the first error at {at}:\n{all}"
    );
    for w in words {
        assert!(first.message.contains(w), "`{w}` missing from:\n{all}");
    }
    let h = first.help.as_deref().unwrap_or_default();
    for w in help {
        assert!(h.contains(w), "`{w}` missing from the help line:\n{all}");
    }
    for w in ["inf", "NaN"] {
        assert!(!first.message.contains(w), "`{w}` in:\n{all}");
    }
}

fn refused_at(text: &str, at: &str, words: &[&str], help: &[&str]) {
    assert_first(text, LoadOptions::default(), at, words, help);
}

fn allow_large() -> LoadOptions {
    LoadOptions {
        allow_large: true,
        ..LoadOptions::default()
    }
}

/// The case of the issue: a harmonic of 10 km ran with exit 0.
#[test]
fn a_harmonic_of_ten_kilometres_is_refused_at_its_amplitude() {
    let text = scene("surface: {type: harmonic, amplitude: 10 km, wavelength: 5}\n");
    refused_at(
        &text,
        "12:38",
        &["harmonic amplitude of 10000 m", "0 to 0.5 m", "ISO 8608"],
        &["`amplitude: 5 mm`"],
    );
    // --allow-large lifts budgets, not plausibility.
    assert_first(
        &text,
        allow_large(),
        "12:38",
        &["harmonic amplitude"],
        &["amplitude"],
    );
    // A lateral harmonic (the track's alignment) too.
    refused_at(
        &scene("surface: {type: harmonic, amplitude: 0.6, wavelength: 5, direction: lateral}\n"),
        "12:38",
        &["alignment amplitude of 0.6 m"],
        &["amplitude"],
    );
}

/// Every other elevation of a surface: a shape's height or depth, a
/// ramp's or step's rise either way, a point of a piecewise-linear
/// profile, the power-law coefficient.
#[test]
fn shape_heights_points_and_coefficients_of_metres_are_refused() {
    for (surface, at, words, help) in [
        (
            "{type: bump, start: 2, length: 1, height: 2}",
            "12:52",
            "a bump height of 2 m",
            "`height: 50 mm`",
        ),
        (
            "{type: dip, start: 2, length: 1, depth: 2 m}",
            "12:50",
            "a dip depth of 2 m",
            "`depth: 30 mm`",
        ),
        (
            "{type: ramp, start: 2, length: 1, height: -3}",
            "12:52",
            "a ramp's rise of -3 m is outside the physically plausible range -0.5 to 0.5 m",
            "`height: 20 mm`",
        ),
        (
            "{type: step, position: 2, height: 1}",
            "12:44",
            "a step's height of 1 m",
            "`height: 10 mm`",
        ),
        (
            "{type: piecewise_linear, points: [[0, 0], [5, 0.01], [8, -2]]}",
            "12:63",
            "point 3's elevation r of -2 m",
            "`[8, 0.02]`",
        ),
        (
            "{type: random, coefficient: 15, seed: 1}",
            "12:38",
            "a roughness coefficient of 15 m³/cycle is outside the physically plausible range 0 to 0.1",
            "`coefficient: 16e-6`",
        ),
    ] {
        refused_at(
            &scene(&format!("surface: {surface}\n")),
            at,
            &[words],
            &[help],
        );
    }
    // The edges of the ranges pass.
    for surface in [
        "{type: harmonic, amplitude: 0.5, wavelength: 1.0e4}",
        "{type: ramp, start: 2, length: 5, height: -0.5}",
        "{type: random, coefficient: 0.1, terms: 100, seed: 1}",
    ] {
        load_str_with(
            &scene(&format!("surface: {surface}\n")),
            "t.yaml",
            LoadOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{surface}: {e}"));
    }
}

/// Lengths along the surface: a wavelength, a shape's length, a band, a
/// run-in or a sampling length of 20 km, or of a nanometre once the budget
/// that refuses its grid is lifted.
#[test]
fn surface_lengths_outside_a_millimetre_to_ten_kilometres_are_refused() {
    for (surface, at, words) in [
        (
            "{type: harmonic, amplitude: 0.001, wavelength: 20 km}",
            "12:57",
            "a wavelength of 20000 m is outside the physically plausible range 0.001 to 10000 m",
        ),
        (
            "{type: bump, start: 2, length: 2.0e4, height: 0.01}",
            "12:41",
            "a bump length of 20000 m",
        ),
        (
            "{type: ramp, start: 2, length: 2.0e4, height: 0.01}",
            "12:41",
            "a ramp length of 20000 m",
        ),
        (
            "{type: german, interference: low, longest_wavelength: 5.0e4}",
            "12:64",
            "a longest wavelength of 50000 m",
        ),
        (
            "{type: fra, class: 5, run_in: 2.0e4}",
            "12:40",
            "a run-in of 20000 m",
        ),
        (
            "{type: random, class: good, sampling_length: 2.0e4, terms: 100}",
            "12:55",
            "a sampling length",
        ),
    ] {
        refused_at(
            &scene(&format!("surface: {surface}\n")),
            at,
            &[words, "EN 13848-1"],
            &["metres"],
        );
    }
    // A nanometre band: the grid's budget refuses it first (it says which
    // limit), and with the budgets lifted the band itself is refused.
    let text = scene("surface: {type: fra, class: 5, shortest_wavelength: 1.0e-9, terms: 100}\n");
    refused_at(&text, "12:53", &["limits.profile_points"], &[]);
    assert_first(
        &text,
        allow_large(),
        "12:53",
        &["a shortest wavelength of 1e-9 m"],
        &["`shortest_wavelength: 1.0`"],
    );
    // A bump shorter than a step's travel keeps its own, more telling
    // refusal (and only that one).
    let text = scene(
        "surface: {type: bump, start: 2, length: 1.0e-300, height: 0.01}\nsolver: {time_step: 1.0e-4}\n",
    );
    let d = diagnostics(&text, LoadOptions::default());
    assert_eq!(d.len(), 1, "{}", shown(&d));
    assert!(d[0].message.contains("shorter than the"), "{}", shown(&d));
}

/// A measured profile's values are refused at the scene's `file` key with
/// the CSV's own line, column and what the column holds.
#[test]
fn a_measured_profile_of_metres_is_refused_at_its_row() {
    let dir = crate::support::Scratch::new("nonsense", "measured");
    std::fs::write(
        dir.path("road.csv"),
        "x,elevation\n-50,0\n0,0.001\n10,3.0\n200,0\n",
    )
    .unwrap();
    std::fs::write(
        dir.path("track.csv"),
        "x,left,right,left_lateral,right_lateral\n-50,0,0,0,0\n0,0.001,0,0,0\n10,0,0,0,-0.7\n200,0,0,0,0\n",
    )
    .unwrap();
    for (file, words) in [
        ("road.csv", "road.csv:4: column 2: an elevation of 3 m"),
        (
            "track.csv",
            "track.csv:4: column 5: the right rail's lateral position (its deviation from the design line) of -0.7 m",
        ),
    ] {
        let path = dir.path("scene.yaml");
        std::fs::write(
            &path,
            scene(&format!("surface: {{type: measured, file: {file}}}\n")),
        )
        .unwrap();
        let err = match vbi::plan::load_file(&path) {
            Ok(_) => panic!("{file} accepted"),
            Err(LoadError::Invalid(d)) => d,
            Err(e) => panic!("{e}"),
        };
        let all = shown(&err);
        assert_eq!((err[0].loc.line, err[0].loc.col), (12, 33), "{all}");
        assert!(err[0].message.contains(words), "`{words}` missing:\n{all}");
        assert!(
            err[0].help.as_deref().unwrap_or_default().contains("0.02"),
            "{all}"
        );
    }
}

/// `syn-tag-custom`: a tag was located where saphyr marks the node after
/// it, for a block collection the next line. Each tag is blamed at its own
/// `!`, whatever follows it: a scalar, a flow or block collection, a key,
/// a comment, an anchor, a lone-CR line break.
#[test]
fn a_yaml_tag_is_located_at_the_tag_itself() {
    use vbi::scenario::yaml::parse;
    let beam_after = |tagged: &str| {
        format!(
            "name: t\nbridge: {tagged}\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n  \
             mass_per_length: 2303.0\nvehicles:\n{OSC}"
        )
    };
    let cases: Vec<(String, (usize, usize))> = vec![
        // On a mapping value whose block mapping starts on the next line.
        (beam_after("!custom"), (2, 9)),
        (
            beam_after("  !custom   # a comment\n  # another\n"),
            (2, 11),
        ),
        (beam_after("&b !!python/object:x"), (2, 12)),
        // On a sequence item whose mapping starts on the next line.
        (
            format!(
                "name: t\n{BEAM}vehicles:\n  - !!python/object:foo\n    type: oscillator\n    \
                 sprung_mass: 5750.0\n    stiffness: 1.595e6\n    speed: 27.7\n"
            ),
            (8, 5),
        ),
        // On a block sequence starting the next line.
        (format!("name: t\n{BEAM}vehicles: !custom\n{OSC}"), (7, 11)),
        // On a scalar item, a flow sequence, a key, the document.
        (
            format!(
                "name: t\nbridge:\n  type: beam\n  spans:\n    - !custom 25.0\n  \
                 bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\nvehicles:\n{OSC}"
            ),
            (5, 7),
        ),
        (
            scene("").replace("spans: [25.0]", "spans: !foo [25.0]"),
            (4, 10),
        ),
        (
            scene("").replace("spans: [25.0]", "!custom spans: [25.0]"),
            (4, 3),
        ),
        (format!("!custom\n{}", scene("")), (1, 1)),
        ("a: [1, !foo\n   2]\n".into(), (1, 8)),
        ("a: 1\rb: !x\r  c: 1\r".into(), (2, 4)),
    ];
    for (text, (line, col)) in cases {
        let e = parse(&text).expect_err(&text);
        assert_eq!(
            (e.loc.line, e.loc.col, e.message.as_str()),
            (line, col, "YAML tags are not supported"),
            "{text}"
        );
        // The loader reports it at the same place.
        let d = diagnostics(&text, LoadOptions::default());
        assert_eq!((d[0].loc.line, d[0].loc.col), (line, col), "{}", shown(&d));
    }
}

/// `tr-count-125-allowed`: 125 rail cars passed `check` and the run went
/// on for hours (wheels × steps × modes was budgeted nowhere). The run's
/// work is refused at the train's `count`, naming the product, its
/// factors, the limit and what fits; `--allow-large` lifts it.
#[test]
fn the_work_of_a_run_is_budgeted_at_its_cause() {
    let train = |count: usize| {
        format!(
            "name: t\n{BEAM}vehicles:\n  - {{type: train, speed: 30, count: {count}, car_spacing: 25}}\n\
             record: [{{name: m, quantity: bridge_displacement, x: 12.5}}]\n"
        )
    };
    refused_at(
        &train(125),
        "8:37",
        &[
            "work of the run",
            "steps × (500 wheels × (5 modes + 2352 for their contact system",
            "`limits.run_work`",
            "`limits: {run_work: 5.000e11}`",
            "--allow-large",
            "vehicle 1 has 500 of the 500 wheels",
            "(this train: `count: 14`)",
        ],
        &[],
    );
    load_str_with(&train(125), "t.yaml", allow_large()).unwrap_or_else(|e| panic!("{e}"));
    // Ten cars (6e7, about 2 s) pass.
    load_str_with(&train(10), "t.yaml", LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    // Where the modes make the work, they are blamed, with the count that fits.
    let modes = format!(
        "name: t\n{BEAM}  elements_per_span: 400\n  modes: {{count: 400}}\nvehicles:\n{OSC}\
         record: [{{name: m, quantity: bridge_displacement, x: 12.5}}]\n\
         solver: {{time_step: 1.0e-5, free_vibration: 60}}\n"
    );
    refused_at(
        &modes,
        "8:18",
        &[
            "1 wheels × (400 modes + 1 for their contact system",
            "`limits.run_work`",
            "modes fit (`bridge.modes: {count: ",
        ],
        &[],
    );
}
