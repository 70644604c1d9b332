//! Broken scenario files (`tests/bad/`, one defect each) must be rejected by
//! every command with exit code 2, a located `FILE:LINE:COL: message`, a
//! source excerpt with a caret, no panic, and no output left behind.

use std::ffi::OsStr;
use std::path::PathBuf;

use crate::support::{Scratch, manifest_dir, text, vbi};
use std::process::Output;

/// One broken file and what its diagnostic must say.
struct Case {
    /// File name in `tests/bad/`.
    file: &'static str,
    /// 1-based line of the diagnostic.
    line: usize,
    /// 1-based column, or `None` if only the line is pinned down.
    col: Option<usize>,
    /// A substring the message must contain.
    message: &'static str,
}

const fn case(file: &'static str, line: usize, col: Option<usize>, message: &'static str) -> Case {
    Case {
        file,
        line,
        col,
        message,
    }
}

/// Line 1 of every file (except the empty and non-scenario ones) is a comment
/// naming its defect, so the scenario proper starts on line 2.
const CASES: &[Case] = &[
    // Structure: unknown keys, wrong types, missing parts.
    case(
        "unknown-key-top-level.yaml",
        9,
        Some(1),
        "unknown field `colour`",
    ),
    case(
        "unknown-key-in-bridge-type-last.yaml",
        5,
        Some(3),
        "unknown field `bending_stifness`, expected one of `spans`, `bending_stiffness`",
    ),
    case(
        "unknown-key-in-vehicle.yaml",
        11,
        Some(5),
        "unknown field `sprung_mas`, expected one of `sprung_mass`",
    ),
    case(
        "wrong-type-string-for-number.yaml",
        12,
        Some(16),
        "invalid type: string \"fast\"",
    ),
    case(
        "missing-vehicles.yaml",
        2,
        Some(1),
        "missing field `vehicles`",
    ),
    case(
        "missing-bridge-type.yaml",
        4,
        Some(3),
        "missing `type`; expected one of `beam`",
    ),
    case(
        "unknown-bridge-type.yaml",
        4,
        Some(9),
        "unknown variant `truss`, expected one of `beam`, `plate`, `fe_import`",
    ),
    case(
        "list-not-mapping.yaml",
        2,
        Some(1),
        "invalid type: sequence",
    ),
    // Physical sanity.
    case(
        "negative-mass.yaml",
        11,
        Some(18),
        "sprung mass must be positive, got -5750",
    ),
    case(
        "negative-mass-per-length.yaml",
        7,
        Some(20),
        "mass per length must be positive, got -2303",
    ),
    case(
        "zero-span.yaml",
        5,
        Some(11),
        "span length must be positive, got 0",
    ),
    case(
        "negative-span.yaml",
        5,
        Some(17),
        "span length must be positive, got -10",
    ),
    case(
        "record-x-off-bridge.yaml",
        17,
        Some(55),
        "x = 30 m is off the bridge, which runs from 0 to 25 m",
    ),
    // YAML syntax and encoding.
    case(
        "yaml-unclosed-bracket.yaml",
        6,
        Some(20),
        "(inside the `[` opened at line 5, column 10)",
    ),
    case(
        "yaml-bad-indentation.yaml",
        6,
        Some(4),
        "YAML syntax error: while parsing a block mapping",
    ),
    case("empty.yaml", 1, Some(1), "the file is empty"),
    case("comment-only.yaml", 1, Some(1), "the file is empty"),
    case(
        "duplicate-yaml-key.yaml",
        8,
        Some(3),
        "duplicate key `mass_per_length` (first defined at line 7)",
    ),
    // The YAML scanner reports the position just after the tab, so only the
    // line is pinned down.
    case("tab-indented.yaml", 4, None, "tabs disallowed"),
    case("non-utf8.yaml", 3, Some(19), "not valid UTF-8 (byte 0xE9)"),
    // Numbers that are not finite.
    case(
        "huge-number.yaml",
        6,
        Some(22),
        "`1e400` is not a finite number",
    ),
    case("nan.yaml", 7, Some(20), "`.nan` is not a finite number"),
    case("inf.yaml", 13, Some(12), "`.inf` is not a finite number"),
    // Solver and modes.
    case(
        "negative-time-step.yaml",
        15,
        Some(14),
        "time step must be positive, got -0.001",
    ),
    case(
        "newmark-gamma-below-half.yaml",
        16,
        Some(32),
        "Newmark γ must be at least 0.5",
    ),
    case(
        "modes-count-too-large.yaml",
        9,
        Some(18),
        "50 modes requested but the mesh has only 8",
    ),
    case(
        "max-frequency-below-first-mode.yaml",
        8,
        Some(26),
        "no mode has a frequency at most 1 Hz",
    ),
    // Vehicles.
    case(
        "start-position-on-bridge.yaml",
        14,
        Some(21),
        "must start on the approach (start_position ≤ 0), got 5",
    ),
    case(
        "entry-time-and-start-position.yaml",
        15,
        Some(21),
        "give `entry_time` or `start_position`, not both",
    ),
    // Records.
    case(
        "record-wheel-3-one-wheel-vehicle.yaml",
        18,
        Some(71),
        "wheel 3 does not exist; vehicle 1 (oscillator) has only wheel 1",
    ),
    case(
        "unknown-dof.yaml",
        19,
        Some(67),
        "unknown DOF `body` of vehicle 1; expected one of sprung, wheel",
    ),
    case(
        "duplicate-record-names.yaml",
        18,
        Some(12),
        "duplicate record name `midspan`",
    ),
    // Speed sweeps.
    case(
        "speed-sweep-unknown-roughness.yaml",
        18,
        Some(23),
        "unknown variant `bumpy`, expected one of `smooth`, `very_good`",
    ),
    // Plate decks, trucks, random roads.
    case(
        "lateral-position-on-beam.yaml",
        11,
        Some(23),
        "`lateral_position` places a vehicle across a plate deck; a beam has no width",
    ),
    case(
        "plate-lateral-off-deck.yaml",
        13,
        Some(23),
        "wheels at y = 2.5850 to 4.4150 m fall off the deck, which spans 0 to 4 m",
    ),
    case(
        "plate-mass-and-density.yaml",
        9,
        Some(12),
        "give `mass_per_area` or `density`, not both",
    ),
    case(
        "random-class-and-coefficient.yaml",
        11,
        Some(51),
        "give the roughness `class` or its `coefficient`, not both",
    ),
    case(
        "truck-negative-tyre-stiffness.yaml",
        11,
        Some(40),
        "front_tyre_stiffness must be positive, got -1000000",
    ),
    case(
        "speed-sweep-zero-count.yaml",
        17,
        Some(40),
        "a speed sweep needs 1 to 500 speeds, got 0",
    ),
    case(
        "speed-sweep-span-out-of-range.yaml",
        18,
        Some(9),
        "span 3 does not exist; the bridge has 2 spans",
    ),
    case(
        "speed-sweep-samples-of-smooth.yaml",
        19,
        Some(12),
        "`samples` applies to random surfaces",
    ),
];

fn bad_dir() -> PathBuf {
    manifest_dir().join("tests").join("bad")
}

/// Number of diagnostics: lines that start with `error: `.
fn diagnostics(stderr: &str) -> usize {
    stderr.lines().filter(|l| l.starts_with("error: ")).count()
}

/// Problems with one invocation on one bad file (empty if it behaved).
fn judge(case: &Case, label: &str, shown_path: &str, out: &Output) -> Vec<String> {
    let stderr = text(&out.stderr);
    let stdout = text(&out.stdout);
    let mut problems = Vec::new();
    let mut fail = |what: String| problems.push(format!("{} [{label}]: {what}", case.file));
    if out.status.code() != Some(2) {
        fail(format!("exit code {:?}, want 2", out.status.code()));
    }
    let located = match case.col {
        Some(col) => format!("error: {shown_path}:{}:{col}: ", case.line),
        None => format!("error: {shown_path}:{}:", case.line),
    };
    if !stderr.contains(&located) {
        fail(format!("stderr lacks `{located}`"));
    }
    if !stderr.contains(case.message) {
        fail(format!("stderr lacks message `{}`", case.message));
    }
    // One defect per file: exactly one diagnostic.
    let errors = diagnostics(&stderr);
    if errors != 1 {
        fail(format!("{errors} diagnostics, want 1"));
    }
    // The excerpt: the offending line with its number in the gutter, and a caret.
    // A suggestion (`= help: did you mean …?`, rustc's form) may follow the caret.
    let gutter = format!("\n{} |", case.line);
    let excerpt_end = match stderr.trim_end().rsplit_once('\n') {
        Some((before, last)) if last.trim_start().starts_with("= help: ") => before,
        _ => stderr.trim_end(),
    };
    if !stderr.contains(&gutter) || !excerpt_end.ends_with('^') {
        fail("no source excerpt with a caret".into());
    }
    if stderr.contains("YAML syntax error: YAML syntax error") {
        fail("doubled `YAML syntax error` prefix".into());
    }
    if stderr.contains("panicked") || stdout.contains("panicked") {
        fail("panicked".into());
    }
    if !problems.is_empty() {
        problems.push(format!("--- stdout:\n{stdout}--- stderr:\n{stderr}"));
    }
    problems
}

#[test]
fn every_bad_file_is_in_the_table_and_vice_versa() {
    let mut on_disk: Vec<String> = std::fs::read_dir(bad_dir())
        .expect("tests/bad exists")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = CASES.iter().map(|c| c.file.to_owned()).collect();
    listed.sort();
    let before = listed.len();
    listed.dedup();
    assert_eq!(before, listed.len(), "a file is listed twice");
    assert_eq!(on_disk, listed);
}

#[test]
fn check_rejects_each_bad_file_with_a_located_error() {
    let mut problems = Vec::new();
    for case in CASES {
        // Relative path, as a user would type it from the project root.
        let rel = format!("tests/bad/{}", case.file);
        let out = vbi::<&OsStr>(&["check".as_ref(), rel.as_ref()], manifest_dir());
        problems.extend(judge(case, "check", &rel, &out));
        if !out.stdout.is_empty() {
            problems.push(format!("{} [check]: printed on stdout", case.file));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn run_rejects_each_bad_file_and_writes_nothing() {
    let mut problems = Vec::new();
    for case in CASES {
        let scratch = Scratch::new(
            "bad-inputs",
            &format!("run-{}", case.file.trim_end_matches(".yaml")),
        );
        let path = bad_dir().join(case.file);
        let out_dir = scratch.path("out");
        // The scratch dir is also the working directory, so a default
        // `results/` folder would show up too.
        let out = vbi::<&OsStr>(
            &[
                "run".as_ref(),
                path.as_os_str(),
                "--out".as_ref(),
                out_dir.as_os_str(),
            ],
            scratch.dir(),
        );
        problems.extend(judge(case, "run", &path.display().to_string(), &out));
        let left = scratch.entries();
        if !left.is_empty() {
            problems.push(format!("{} [run]: left behind {left:?}", case.file));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn modes_rejects_each_bad_file_and_writes_no_shapes() {
    let mut problems = Vec::new();
    // `vbi modes` needs only the bridge: a file without vehicles is valid
    // there (tests/it/cli.rs, `modes_works_without_vehicles`).
    for case in CASES.iter().filter(|c| c.file != "missing-vehicles.yaml") {
        let scratch = Scratch::new(
            "bad-inputs",
            &format!("modes-{}", case.file.trim_end_matches(".yaml")),
        );
        let path = bad_dir().join(case.file);
        let shapes = scratch.path("shapes.csv");
        let out = vbi::<&OsStr>(
            &[
                "modes".as_ref(),
                path.as_os_str(),
                "--shapes".as_ref(),
                shapes.as_os_str(),
            ],
            scratch.dir(),
        );
        problems.extend(judge(case, "modes", &path.display().to_string(), &out));
        let left = scratch.entries();
        if !left.is_empty() {
            problems.push(format!("{} [modes]: left behind {left:?}", case.file));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn check_reports_every_bad_file_among_several() {
    let good = "scenarios/yang-yau-sprung-mass.yaml";
    let bad1 = "tests/bad/negative-mass.yaml";
    let bad2 = "tests/bad/unknown-key-top-level.yaml";
    // The good file sits between the bad ones: checking goes on after an error.
    let out = vbi::<&OsStr>(
        &[
            "check".as_ref(),
            bad1.as_ref(),
            good.as_ref(),
            bad2.as_ref(),
        ],
        manifest_dir(),
    );
    let stderr = text(&out.stderr);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(&format!("error: {bad1}:11:18: ")),
        "{stderr}"
    );
    assert!(stderr.contains(&format!("error: {bad2}:9:1: ")), "{stderr}");
    assert_eq!(diagnostics(&stderr), 2, "{stderr}");
    assert_eq!(stdout, format!("{good}: ok\n"));
    assert!(!stderr.contains("panicked"), "{stderr}");

    // All good: exit 0, one `ok` per file.
    let out = vbi::<&OsStr>(
        &["check".as_ref(), good.as_ref(), good.as_ref()],
        manifest_dir(),
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), format!("{good}: ok\n{good}: ok\n"));
}

#[test]
fn missing_file_is_invalid_input_with_a_clear_message() {
    let scratch = Scratch::new("bad-inputs", "missing-file");
    let missing = "tests/bad/no-such-scenario.yaml";
    let out_dir = scratch.path("out");
    let shapes = scratch.path("shapes.csv");
    let runs: [Vec<&std::ffi::OsStr>; 3] = [
        vec!["check".as_ref(), missing.as_ref()],
        vec![
            "run".as_ref(),
            missing.as_ref(),
            "--out".as_ref(),
            out_dir.as_os_str(),
        ],
        vec![
            "modes".as_ref(),
            missing.as_ref(),
            "--shapes".as_ref(),
            shapes.as_os_str(),
        ],
    ];
    for args in runs {
        let out = vbi(&args, manifest_dir());
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with(&format!("error: {missing}: cannot read: ")),
            "{args:?}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    assert!(scratch.entries().is_empty());

    // A folder is not a scenario file either.
    let out = vbi::<&OsStr>(&["check".as_ref(), "tests/bad".as_ref()], manifest_dir());
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("error: tests/bad: cannot read: "));
}

/// Issue 38: a deck-acceleration record whose own `max_frequency` (1e5 Hz)
/// sets the automatic step is named as the cause where the step budget is
/// hit, with a cut-off that fits; the speed was blamed before ("a speed of
/// at least 73 m/s fits").
#[test]
fn a_raised_acceleration_cut_off_is_blamed_for_the_steps() {
    let scratch = crate::support::Scratch::new("bad_inputs", "raised-cut-off");
    let scene = scratch.path("acc.yaml");
    std::fs::write(
        &scene,
        "name: acc\nbridge:\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n  \
         mass_per_length: 2303.0\nvehicles:\n  - type: moving_force\n    loads: [100 kN]\n    \
         speed: 27.7\nrecord:\n  - {name: a, quantity: bridge_acceleration, x: 12.5, \
         max_frequency: 1e5}\n",
    )
    .unwrap();
    let out = vbi::<&OsStr>(&["check".as_ref(), scene.as_os_str()], scratch.dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("acc.yaml:12:70: time steps"), "{stderr}");
    assert!(stderr.contains("a `max_frequency` up to about"), "{stderr}");
    assert!(!stderr.contains("a speed of at least"), "{stderr}");
}
