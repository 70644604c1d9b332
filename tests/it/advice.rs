//! Advice as data (issue 38, points 1–4): every warning is a value with a
//! stable id that reaches every output — the command line, summary.json,
//! each study point (through shards and merge), regression records and the
//! convergence report — and `--deny-warnings` / `allow` act on it.
//!
//! The warning scene: a 100 kN force at α = v / (2 f₁ L) = 2 over the Yang &
//! Yau beam (f₁ = 4.7779 Hz, L = 25 m: v = 477.8 m/s) with no free
//! vibration. Above α = 1 the largest deflection comes after the force has
//! left the span (Frýba 1972, §1.3), so the midspan record ends at its
//! largest value: `run-ends-at-peak`.

use crate::support::{Scratch, assert_exit, manifest_dir, text, vbi};

/// The α = 2 crossing, ending as the force leaves; `extra` is appended
/// (an `allow` list or a study).
fn scene(extra: &str) -> String {
    format!(
        "name: advice-alpha-2
bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
  modes: {{count: 4}}
  damping: {{type: modal, ratio: 0.02}}
vehicles:
  - {{type: moving_force, loads: [100.0e3], speed: 477.8 m/s}}
solver: {{time_step: 2.0e-4, free_vibration: 0.0}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 12.5}}
{extra}"
    )
}

fn summary(folder: &std::path::Path) -> serde_json::Value {
    let text = std::fs::read_to_string(folder.join("summary.json")).expect("summary.json");
    serde_json::from_str(&text).expect("summary.json parses")
}

fn ids(summary: &serde_json::Value) -> Vec<String> {
    summary["advice"]
        .as_array()
        .expect("summary.json has an advice list")
        .iter()
        .map(|a| a["id"].as_str().expect("an id").to_string())
        .collect()
}

/// docs/advice.md is what `vbi advice --markdown` generates from the
/// registry, and lists every id.
#[test]
fn the_advice_reference_is_generated_from_the_code() {
    let committed =
        std::fs::read_to_string(manifest_dir().join("docs/advice.md")).expect("docs/advice.md");
    assert_eq!(
        committed,
        vbi::advice::reference_markdown(),
        "docs/advice.md differs from `vbi advice --markdown`: regenerate it"
    );
    for kind in vbi::advice::KINDS {
        assert!(
            committed.contains(&format!("## {}\n", kind.id)),
            "{}",
            kind.id
        );
    }
    let dir = Scratch::new("advice", "explain");
    let out = vbi(&["advice", "run-ends-at-peak"], dir.dir());
    assert_exit(&out, 0);
    assert!(text(&out.stdout).contains("free_vibration"));
    let out = vbi(&["advice", "run-end-at-peak"], dir.dir());
    assert_exit(&out, 2);
    assert!(text(&out.stderr).contains("did you mean `run-ends-at-peak`?"));
}

/// The same advice on the terminal (with its id and help), in summary.json
/// (with its figures), and through `--deny-warnings` (exit 4, results
/// written all the same); `allow` with a reason silences it and keeps the
/// reason in summary.json.
#[test]
fn a_scene_warning_reaches_the_terminal_the_summary_and_the_exit_code() {
    let dir = Scratch::new("advice", "scene");
    std::fs::write(dir.path("warns.yaml"), scene("")).unwrap();
    let out = vbi(&["run", "warns.yaml", "--out", "a", "-q"], dir.dir());
    assert_exit(&out, 0);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("warning[run-ends-at-peak]: warns.yaml:13:5 (record[0]):"),
        "{stderr}"
    );
    assert!(
        stderr.contains("= help: record longer with `solver.free_vibration`"),
        "{stderr}"
    );
    let s = summary(&dir.path("a"));
    assert_eq!(ids(&s), ["run-ends-at-peak"]);
    let advice = &s["advice"][0];
    assert_eq!(advice["severity"], "warning");
    assert_eq!(advice["location"], "record[0]");
    // The figure is the record's end: 25 m at 477.8 m/s.
    let t = advice["figures"]["time_s"].as_f64().unwrap();
    assert!((t - 25.0 / 477.8).abs() < 2.0e-4, "{t}");

    let out = vbi(
        &["run", "warns.yaml", "--out", "b", "-q", "--deny-warnings"],
        dir.dir(),
    );
    assert_exit(&out, 4);
    assert!(text(&out.stderr).contains("1 warning denied by `--deny-warnings`"));
    assert!(dir.path("b/summary.json").exists(), "results are written");

    let allowed = scene(
        "allow:\n  - {id: run-ends-at-peak, reason: \"only the forced phase is of interest\"}\n",
    );
    std::fs::write(dir.path("allowed.yaml"), allowed).unwrap();
    let out = vbi(
        &["run", "allowed.yaml", "--out", "c", "-q", "--deny-warnings"],
        dir.dir(),
    );
    assert_exit(&out, 0);
    assert!(
        !text(&out.stderr).contains("warning["),
        "{}",
        text(&out.stderr)
    );
    let s = summary(&dir.path("c"));
    assert_eq!(
        s["advice"][0]["allowed"],
        "only the forced phase is of interest"
    );
    // resolved.yaml keeps the allow list.
    let resolved = std::fs::read_to_string(dir.path("c/resolved.yaml")).unwrap();
    assert!(resolved.contains("run-ends-at-peak"), "{resolved}");
}

/// An `allow` entry that names no advice id is an error at its line, with
/// the id it was probably meant to be; an empty reason likewise.
#[test]
fn an_allow_entry_is_checked() {
    let dir = Scratch::new("advice", "allow_check");
    let bad = scene(
        "allow:\n  - {id: run-end-at-peak, reason: x}\n  - {id: implausible-speed, reason: \"\"}\n",
    );
    std::fs::write(dir.path("bad.yaml"), bad).unwrap();
    let out = vbi(&["check", "bad.yaml"], dir.dir());
    assert_exit(&out, 2);
    let stderr = text(&out.stderr);
    assert!(stderr.contains("bad.yaml:15:"), "{stderr}");
    assert!(
        stderr.contains("did you mean `run-ends-at-peak`?"),
        "{stderr}"
    );
    assert!(stderr.contains("bad.yaml:16:"), "{stderr}");
    assert!(stderr.contains("needs a reason"), "{stderr}");
}

/// Each point of a speed sweep gets its run's advice; the study's
/// summary.json gathers it by id with every point it was made at, and a
/// sharded run merged gives the same summary.
#[test]
fn study_points_carry_their_advice_through_shards_and_merge() {
    let dir = Scratch::new("advice", "study");
    let sweep =
        scene("study: {type: speed_sweep, speeds: {from: 400 m/s, to: 480 m/s, count: 3}}\n");
    std::fs::write(dir.path("sweep.yaml"), sweep).unwrap();
    let out = vbi(&["run", "sweep.yaml", "--out", "whole", "-q"], dir.dir());
    assert_exit(&out, 0);
    assert!(
        text(&out.stderr).contains("warning[run-ends-at-peak]"),
        "{}",
        text(&out.stderr)
    );
    let whole = summary(&dir.path("whole"));
    let advice = whole["advice"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["id"] == "run-ends-at-peak")
        .expect("the sweep's points warn");
    let points: Vec<&str> = advice["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    assert_eq!(points.len(), 3, "{points:?}");
    assert!(points[0].contains("1440.0 km/h"), "{points:?}");
    for k in ["1/2", "2/2"] {
        let out = vbi(
            &["run", "sweep.yaml", "--shard", k, "--out", "parts", "-q"],
            dir.dir(),
        );
        assert_exit(&out, 0);
    }
    let out = vbi(
        &[
            "merge",
            "-q",
            "--out",
            "merged",
            "parts/part-1-of-2.json",
            "parts/part-2-of-2.json",
        ],
        dir.dir(),
    );
    assert_exit(&out, 0);
    assert_eq!(summary(&dir.path("merged"))["advice"], whole["advice"]);
    let out = vbi(
        &[
            "merge",
            "-q",
            "--deny-warnings",
            "--out",
            "merged2",
            "parts/part-1-of-2.json",
            "parts/part-2-of-2.json",
        ],
        dir.dir(),
    );
    assert_exit(&out, 4);
}

/// A Monte Carlo study's samples carry their advice into its summary.
#[test]
fn monte_carlo_samples_carry_their_advice() {
    let dir = Scratch::new("advice", "monte_carlo");
    let mc = scene("study: {type: monte_carlo, samples: 3, seed: 1}\n").replace(
        "record:",
        "surface: {type: random, class: good, sampling_length: 30.0, terms: 32, seed: 1}\nrecord:",
    );
    std::fs::write(dir.path("mc.yaml"), mc).unwrap();
    let out = vbi(&["run", "mc.yaml", "--out", "r", "-q"], dir.dir());
    assert_exit(&out, 0);
    let s = summary(&dir.path("r"));
    let advice = s["advice"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["id"] == "run-ends-at-peak")
        .unwrap_or_else(|| panic!("{s}"));
    assert_eq!(advice["points"].as_array().unwrap().len(), 3);
}

/// `vbi regress`: advice that appears is a reported change.
#[test]
fn regress_reports_advice_that_appears() {
    let dir = Scratch::new("advice", "regress");
    let quiet = scene("").replace("free_vibration: 0.0", "free_vibration: 0.3");
    std::fs::write(dir.path("s.yaml"), &quiet).unwrap();
    let out = vbi(
        &["regress", "approve", "s.yaml", "--store", "st"],
        dir.dir(),
    );
    assert_exit(&out, 0);
    let record = std::fs::read_to_string(dir.path("st/s/record.tsv")).unwrap();
    assert!(
        !record.contains("advice."),
        "no advice at 0.3 s free vibration"
    );
    std::fs::write(dir.path("s.yaml"), scene("")).unwrap();
    let out = vbi(&["regress", "check", "s.yaml", "--store", "st"], dir.dir());
    let stdout = text(&out.stdout) + &text(&out.stderr);
    assert!(stdout.contains("advice.run-ends-at-peak"), "{stdout}");
    assert_ne!(out.status.code(), Some(0), "{stdout}");
}

/// `vbi converge`: each run's warnings in converge.csv's `advice` column.
#[test]
fn converge_reports_each_runs_advice() {
    let dir = Scratch::new("advice", "converge");
    std::fs::write(dir.path("s.yaml"), scene("")).unwrap();
    let out = vbi(
        &["converge", "s.yaml", "--levels", "1", "--out", "c", "-q"],
        dir.dir(),
    );
    assert_exit(&out, 0);
    let csv = std::fs::read_to_string(dir.path("c/converge.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(header.ends_with(",advice"), "{header}");
    assert!(
        csv.lines().skip(1).all(|l| l.ends_with("run-ends-at-peak")),
        "{csv}"
    );
    assert!(
        text(&out.stderr).contains("warning[run-ends-at-peak]"),
        "{}",
        text(&out.stderr)
    );
}

/// The library's results carry the advice: `Summary::advice` of a run,
/// made by the run itself, not by the command line.
#[test]
fn the_library_result_carries_the_advice() {
    let outcome = crate::support::run_yaml(&scene(""));
    let ids: Vec<&str> = outcome
        .summary
        .advice
        .iter()
        .map(|a| a.id.as_str())
        .collect();
    assert_eq!(ids, ["run-ends-at-peak"]);
    let json = serde_json::to_value(&outcome.summary).unwrap();
    assert_eq!(json["advice"][0]["id"], "run-ends-at-peak");
}
