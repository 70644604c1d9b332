//! The command line end to end: `run` and its output files, the resolved
//! scenario round trip, `modes`, `schema`, help and usage errors.

use crate::support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;
use support::{Scratch, assert_exit, manifest_dir, text, vbi};

/// The Yang & Yau sprung-mass scenario with a 1 ms step (900 steps), copied
/// into `dir`.
fn quick_yang_yau(dir: &Scratch) -> PathBuf {
    let src = std::fs::read_to_string(manifest_dir().join("scenarios/yang-yau-sprung-mass.yaml"))
        .expect("read scenario");
    assert!(src.contains("time_step: 1.0e-4"), "scenario changed");
    let quick = src.replace("time_step: 1.0e-4", "time_step: 1.0e-3");
    let path = dir.path("yang-yau.yaml");
    std::fs::write(&path, quick).expect("write scenario");
    path
}

fn run_quiet(scenario: &Path, out_dir: &Path, cwd: &Path) -> Output {
    vbi(
        &[
            "run".as_ref(),
            scenario.as_os_str(),
            "--out".as_ref(),
            out_dir.as_os_str(),
            "--quiet".as_ref(),
        ],
        cwd,
    )
}

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).expect("read summary.json");
    serde_json::from_str(&text).expect("summary.json is valid JSON")
}

fn file_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// history.png is a real picture of the histories: a PNG 900 px wide, one
/// 260 px panel per kind of quantity (the Yang & Yau scene records five:
/// bridge displacement and acceleration, vehicle displacement and
/// acceleration, contact force), with the first series' colour (tab10 blue)
/// drawn over a good part of it and the grey dashed entry/exit lines.
fn assert_history_picture(path: &Path) {
    let file = std::fs::File::open(path).expect("history.png");
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("a PNG");
    let info = decoder.info().clone();
    let mut rgb = vec![0; decoder.output_buffer_size().expect("size")];
    decoder.next_frame(&mut rgb).expect("PNG data");
    assert_eq!(info.width, 900);
    let panels = (info.height - 85) / 260;
    assert_eq!(info.height, 85 + 260 * panels, "whole panels");
    assert_eq!(panels, 5);
    let pixels: Vec<&[u8]> = rgb.chunks(3).collect();
    let blue = pixels.iter().filter(|p| **p == [31, 119, 180]).count();
    let grey = pixels.iter().filter(|p| **p == [120, 120, 120]).count();
    assert!(blue > 2_000, "{blue} pixels of the first line");
    assert!(grey > 200, "{grey} pixels of entry/exit lines");
}

#[test]
fn run_writes_summary_history_and_resolved_scenario() {
    let scratch = Scratch::new("cli", "run-writes");
    let scenario = quick_yang_yau(&scratch);
    let out_dir = scratch.path("out");
    let out = run_quiet(&scenario, &out_dir, scratch.dir());
    assert_exit(&out, 0);
    assert_eq!(text(&out.stderr), "", "--quiet prints nothing on stderr");
    assert_eq!(text(&out.stdout), "", "run prints nothing on stdout");
    // Exactly the four results: no temporary files left from atomic writes.
    assert_eq!(
        file_names(&out_dir),
        [
            "history.csv",
            "history.png",
            "resolved.yaml",
            "summary.json"
        ]
    );
    assert_history_picture(&out_dir.join("history.png"));

    let summary = read_json(&out_dir.join("summary.json"));
    assert_eq!(summary["scenario"], "yang-yau-sprung-mass");
    let steps = summary["run"]["steps"].as_u64().expect("run.steps") as usize;
    // 25 m at 100 km/h is 0.9 s; 1 ms steps.
    assert_eq!(steps, 900);
    assert_eq!(summary["run"]["time_step"], 1.0e-3);
    let quantities = summary["quantities"].as_array().expect("quantities");
    let names: Vec<&str> = quantities
        .iter()
        .map(|q| q["name"].as_str().expect("quantity name"))
        .collect();
    assert_eq!(
        names,
        [
            "midspan",
            "midspan_acceleration",
            "body",
            "body_acceleration",
            "contact_force"
        ]
    );

    let history = std::fs::read_to_string(out_dir.join("history.csv")).expect("history.csv");
    let mut lines = history.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    // Every header carries its unit: `time [s]`, `name [unit]`.
    assert_eq!(header[0], "time [s]");
    for name in &names {
        assert!(
            header.iter().any(
                |h| h.strip_prefix(name).is_some_and(|u| u.starts_with(" [")) && h.ends_with(']')
            ),
            "{name} with its unit not in {header:?}"
        );
    }
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), steps + 1, "one row per step plus t = 0");
    for row in &rows {
        let fields: Vec<&str> = row.split(',').collect();
        assert_eq!(fields.len(), header.len(), "{row}");
        for f in fields {
            let v: f64 = f.parse().unwrap_or_else(|_| panic!("not a number: {f}"));
            assert!(v.is_finite(), "{row}");
        }
    }
    let first_time: f64 = rows[0].split(',').next().unwrap().parse().unwrap();
    let last_time: f64 = rows[steps].split(',').next().unwrap().parse().unwrap();
    assert_eq!(first_time, 0.0);
    assert!((last_time - 0.9).abs() < 1e-9, "{last_time}");

    let resolved = std::fs::read_to_string(out_dir.join("resolved.yaml")).expect("resolved.yaml");
    assert!(
        resolved.contains("name: \"yang-yau-sprung-mass\""),
        "{resolved}"
    );
    assert!(resolved.contains("time_step: 0.001"), "{resolved}");
}

/// Every number in `a` and `b` equal, except `run.wall_time`.
fn assert_same_summary(mut a: Value, mut b: Value) {
    for v in [&mut a, &mut b] {
        let run = v["run"].as_object_mut().expect("run");
        assert!(run.remove("wall_time").is_some(), "no run.wall_time");
    }
    assert_eq!(a, b);
}

#[test]
fn resolved_scenario_checks_runs_and_resolves_to_itself() {
    let scratch = Scratch::new("cli", "resolved-round-trip");
    let scenario = quick_yang_yau(&scratch);
    let first = scratch.path("first");
    assert_exit(&run_quiet(&scenario, &first, scratch.dir()), 0);
    let resolved = first.join("resolved.yaml");

    let out = vbi(&["check".as_ref(), resolved.as_os_str()], scratch.dir());
    assert_exit(&out, 0);
    assert_eq!(text(&out.stdout), format!("{}: ok\n", resolved.display()));

    let second = scratch.path("second");
    assert_exit(&run_quiet(&resolved, &second, scratch.dir()), 0);
    assert_same_summary(
        read_json(&first.join("summary.json")),
        read_json(&second.join("summary.json")),
    );
    // Resolving a resolved scenario changes nothing but the header line
    // naming the scene file it came from, and the results are the same.
    let read = |dir: &Path, name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
    let body = |text: String| -> String {
        text.lines()
            .filter(|l| !l.starts_with(vbi::run::FROM))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert!(read(&first, "resolved.yaml").contains("# From: "));
    assert_eq!(
        body(read(&first, "resolved.yaml")),
        body(read(&second, "resolved.yaml"))
    );
    assert_eq!(read(&first, "history.csv"), read(&second, "history.csv"));
}

#[test]
fn run_without_quiet_reports_on_stderr() {
    let scratch = Scratch::new("cli", "run-loud");
    let scenario = quick_yang_yau(&scratch);
    let out_dir = scratch.path("out");
    let out = vbi(
        &[
            "run".as_ref(),
            scenario.as_os_str(),
            "--out".as_ref(),
            out_dir.as_os_str(),
        ],
        scratch.dir(),
    );
    assert_exit(&out, 0);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("yang-yau-sprung-mass: 900 steps"),
        "{stderr}"
    );
    assert!(stderr.contains("midspan"), "{stderr}");
    assert!(
        stderr.contains(&format!("results in {}", out_dir.display())),
        "{stderr}"
    );
    assert!(out_dir.join("summary.json").is_file());
}

/// f₁ = (π/L)² √(EI/m) / (2π) for a simply supported Euler–Bernoulli beam.
fn first_frequency(length: f64, ei: f64, m: f64) -> f64 {
    use std::f64::consts::PI;
    (PI / length).powi(2) * (ei / m).sqrt() / (2.0 * PI)
}

#[test]
fn modes_prints_the_yang_yau_frequencies_and_writes_shapes() {
    let scratch = Scratch::new("cli", "modes");
    let scenario = manifest_dir().join("scenarios/yang-yau-sprung-mass.yaml");
    let shapes = scratch.path("shapes.csv");
    let out = vbi(
        &[
            "modes".as_ref(),
            scenario.as_os_str(),
            "--shapes".as_ref(),
            shapes.as_os_str(),
        ],
        scratch.dir(),
    );
    assert_exit(&out, 0);
    let stdout = text(&out.stdout);
    let mut lines = stdout.lines();
    assert_eq!(
        lines.next(),
        Some(
            "yang-yau-sprung-mass: 10 modes used of 40 available (requested: the lowest 10 modes)"
        )
    );
    let header: Vec<&str> = lines.next().unwrap().split_whitespace().collect();
    assert_eq!(header, ["mode", "frequency_Hz", "period_s", "damping"]);
    let table: Vec<Vec<f64>> = lines
        .by_ref()
        .take(10)
        .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(table.len(), 10, "{stdout}");
    for (i, row) in table.iter().enumerate() {
        assert_eq!(row[0], (i + 1) as f64);
        // Both printed with 6 decimals.
        assert!(
            (row[2] - 1.0 / row[1]).abs() <= 5.1e-7,
            "period = 1/f: {row:?}"
        );
        assert_eq!(row[3], 0.0, "undamped");
        if i > 0 {
            assert!(row[1] > table[i - 1][1], "ascending frequencies");
        }
    }
    let f1 = table[0][1];
    assert_eq!(format!("{f1:.4}"), "4.7779");
    let closed_form = first_frequency(25.0, 8.323e9, 2303.0);
    assert_eq!(format!("{closed_form:.4}"), "4.7779");
    assert!(
        (f1 - closed_form).abs() / closed_form < 1e-5,
        "{f1} vs {closed_form}"
    );
    // The vehicle's own frequency: the sprung mass on its spring over a
    // wheel held on rigid ground, f = √(k/m)/2π (k = 1.595e6 N/m, m = 5750 kg).
    assert_eq!(
        lines.next(),
        Some("vehicle natural frequencies, Hz (wheels on rigid ground):")
    );
    let vehicle: Vec<&str> = lines.next().unwrap().split_whitespace().collect();
    let closed_form = (1.595e6f64 / 5750.0).sqrt() / (2.0 * std::f64::consts::PI);
    assert_eq!(vehicle, ["1", "oscillator", &format!("{closed_form:.4}")]);
    // Status on stderr, data on stdout.
    assert!(
        text(&out.stderr).contains(&format!("mode shapes written to {}", shapes.display())),
        "{}",
        text(&out.stderr)
    );
    assert_eq!(lines.next(), None);

    let csv = std::fs::read_to_string(&shapes).expect("shapes CSV");
    let mut rows = csv.lines();
    let header: Vec<&str> = rows.next().unwrap().split(',').collect();
    let want: Vec<String> = std::iter::once("x [m]".to_owned())
        .chain((1..=10).map(|i| format!("mode{i} [1/kg^0.5]")))
        .collect();
    assert_eq!(header, want);
    let values: Vec<Vec<f64>> = rows
        .map(|r| r.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert!(values.len() >= 21, "at least the 21 mesh nodes");
    assert!(values.iter().all(|r| r.len() == 11));
    assert_eq!(values[0][0], 0.0);
    assert_eq!(values.last().unwrap()[0], 25.0);
    // Pinned ends: every mode vanishes at both supports.
    for r in [&values[0], values.last().unwrap()] {
        assert!(r[1..].iter().all(|v| v.abs() < 1e-12), "{r:?}");
    }
    assert!(values.iter().flatten().all(|v| v.is_finite()));
}

#[test]
fn schema_output_equals_the_committed_schema() {
    let out = vbi(&["schema"], manifest_dir());
    assert_exit(&out, 0);
    let committed = std::fs::read_to_string(manifest_dir().join("schema/vbi.schema.json"))
        .expect("schema/vbi.schema.json");
    assert!(
        text(&out.stdout) == committed,
        "`vbi schema` differs from schema/vbi.schema.json; regenerate it with \
         `vbi schema > schema/vbi.schema.json`"
    );
    let _: Value = serde_json::from_str(&committed).expect("the schema is JSON");
}

#[test]
fn help_and_version_exit_zero() {
    for args in [
        &["--help"][..],
        &["help"],
        &["run", "--help"],
        &["check", "--help"],
        &["modes", "--help"],
        &["schema", "--help"],
    ] {
        let out = vbi(args, manifest_dir());
        assert_exit(&out, 0);
        assert!(text(&out.stdout).contains("Usage: vbi"), "{args:?}");
    }
    let out = vbi(&["run", "--help"], manifest_dir());
    let help = text(&out.stdout);
    assert!(help.contains("--out") && help.contains("--quiet"), "{help}");
    let out = vbi(&["--version"], manifest_dir());
    assert_exit(&out, 0);
    assert_eq!(
        text(&out.stdout),
        format!("vbi {}\n", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn usage_errors_exit_two() {
    for args in [
        &["frobnicate"][..],
        &[],
        &["check"],
        &["run"],
        &["run", "scenarios/yang-yau-sprung-mass.yaml", "--bogus"],
        &["modes"],
    ] {
        let out = vbi(args, manifest_dir());
        assert_exit(&out, 2);
        assert!(text(&out.stderr).contains("Usage"), "{args:?}");
    }
    let out = vbi(&["frobnicate"], manifest_dir());
    assert!(text(&out.stderr).contains("unrecognized subcommand 'frobnicate'"));
}

/// A bridge-only scene: `vbi modes` lists its modes; `vbi check` and `vbi
/// run` still want vehicles.
#[test]
fn modes_works_without_vehicles() {
    let scratch = Scratch::new("cli", "modes-bridge-only");
    let path = scratch.path("deck.yaml");
    std::fs::write(
        &path,
        "name: deck\nbridge:\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\n",
    )
    .unwrap();
    let out = vbi(&["modes".as_ref(), path.as_os_str()], scratch.dir());
    assert_exit(&out, 0);
    let stdout = text(&out.stdout);
    let first = stdout.lines().nth(2).expect("first mode row");
    let f1: f64 = first.split_whitespace().nth(1).unwrap().parse().unwrap();
    let closed_form = first_frequency(25.0, 8.323e9, 2303.0);
    assert!(
        (f1 - closed_form).abs() / closed_form < 1e-5,
        "{f1} vs {closed_form}"
    );
    assert!(stdout.starts_with("deck: 5 modes used"), "{stdout}");
    assert!(!stdout.contains("vehicle natural"), "{stdout}");
    // A broken bridge is still an invalid file.
    std::fs::write(&path, "name: deck\nbridge:\n  type: beam\n  spans: [-25.0]\n  bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\n").unwrap();
    let out = vbi(&["modes".as_ref(), path.as_os_str()], scratch.dir());
    assert_exit(&out, 2);
    assert!(text(&out.stderr).contains("deck.yaml:4:11: a span length must be positive"));
    let out = vbi(&["check".as_ref(), path.as_os_str()], scratch.dir());
    assert_exit(&out, 2);
}

/// Runs vbi with stdout into a pipe whose reader has gone (what `| head`
/// does once it has its lines), stderr captured.
fn vbi_into_closed_pipe(args: &[&std::ffi::OsStr], cwd: &Path) -> Output {
    use std::process::Stdio;
    let (reader, writer) = std::io::pipe().expect("pipe");
    drop(reader);
    Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .stdout(Stdio::from(writer))
        .stderr(Stdio::piped())
        .output()
        .expect("run vbi")
}

#[test]
fn a_closed_pipe_ends_the_output_quietly() {
    let scratch = Scratch::new("cli", "closed-pipe");
    let scenarios = manifest_dir().join("scenarios");
    let yang_yau = scenarios.join("yang-yau-sprung-mass.yaml");
    let shapes = scratch.path("shapes.csv");
    let cases: Vec<(Vec<&std::ffi::OsStr>, i32)> = vec![
        (
            vec!["check".as_ref(), yang_yau.as_os_str(), yang_yau.as_os_str()],
            0,
        ),
        (vec!["schema".as_ref()], 0),
        (vec!["modes".as_ref(), yang_yau.as_os_str()], 0),
        (
            vec![
                "modes".as_ref(),
                yang_yau.as_os_str(),
                "--shapes".as_ref(),
                "-".as_ref(),
            ],
            0,
        ),
        (
            vec![
                "modes".as_ref(),
                yang_yau.as_os_str(),
                "--shapes".as_ref(),
                shapes.as_os_str(),
            ],
            0,
        ),
        (vec!["--help".as_ref()], 0),
    ];
    for (args, code) in &cases {
        let out = vbi_into_closed_pipe(args, scratch.dir());
        assert_eq!(
            out.status.code(),
            Some(*code),
            "{args:?}: {}",
            text(&out.stderr)
        );
        assert!(
            !text(&out.stderr).contains("panicked"),
            "{args:?}: {}",
            text(&out.stderr)
        );
    }
    // The work is still done: the shapes file was written.
    assert!(shapes.is_file());
    // An invalid file among them keeps its exit code.
    let bad = manifest_dir().join("tests/bad/negative-span.yaml");
    let out = vbi_into_closed_pipe(
        &["check".as_ref(), yang_yau.as_os_str(), bad.as_os_str()],
        scratch.dir(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("negative-span.yaml"));
}

/// Two files that give the same `name:` write to different default folders.
#[test]
fn the_default_output_folder_comes_from_the_file_not_the_name() {
    let scratch = Scratch::new("cli", "default-out");
    let quick = std::fs::read_to_string(quick_yang_yau(&scratch)).unwrap();
    for stem in ["first", "second"] {
        std::fs::write(scratch.path(&format!("{stem}.yaml")), &quick).unwrap();
        let out = vbi(&["run", &format!("{stem}.yaml"), "--quiet"], scratch.dir());
        assert_exit(&out, 0);
    }
    for stem in ["first", "second"] {
        let summary = scratch
            .dir()
            .join("results")
            .join(stem)
            .join("summary.json");
        assert!(summary.is_file(), "{} missing", summary.display());
    }
    assert!(!scratch.dir().join("results/yang-yau-sprung-mass").exists());
}

/// `--svg` adds the history plot as SVG: the same panels, as vectors.
#[test]
fn run_with_svg_writes_the_history_as_svg_too() {
    let scratch = Scratch::new("cli", "svg");
    let scenario = quick_yang_yau(&scratch);
    let out_dir = scratch.path("out");
    let out = vbi(
        &[
            "run".as_ref(),
            scenario.as_os_str(),
            "--out".as_ref(),
            out_dir.as_os_str(),
            "--quiet".as_ref(),
            "--svg".as_ref(),
        ],
        scratch.dir(),
    );
    assert_exit(&out, 0);
    let svg = std::fs::read_to_string(out_dir.join("history.svg")).expect("history.svg");
    assert!(
        svg.starts_with("<svg width=\"900\" height=\"1385\""),
        "{}",
        &svg[..80]
    );
    // One polyline per recorded history (five) and its static response (one).
    let lines = svg.matches("<polyline").count();
    assert!(lines >= 6, "{lines} polylines");
    for label in [
        "midspan",
        "body_acceleration",
        "contact force (N)",
        "enters",
        "leaves",
    ] {
        assert!(svg.contains(label), "no `{label}` in the SVG");
    }
    assert!(out_dir.join("history.png").is_file());
}

/// `vbi completions SHELL` prints a script that names every subcommand (a
/// shell loads it as is), and `vbi man` a roff page with the same commands;
/// an unknown shell is a usage error (exit 2), not a panic.
#[test]
fn completions_and_man_page_generate() {
    let dir = Scratch::new("cli", "completions");
    let subcommands = [
        "run", "merge", "check", "schema", "export", "modes", "generate", "converge",
    ];
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = vbi(&["completions", shell], dir.dir());
        assert_exit(&out, 0);
        let script = text(&out.stdout);
        for name in subcommands {
            assert!(
                script.contains(name),
                "{shell} completions lack `{name}`:\n{script}"
            );
        }
        assert!(
            script.contains("allow-large"), // fish writes `-l allow-large`
            "{shell}: no global options"
        );
    }
    // bash accepts the script as syntax (where bash exists).
    if let Ok(status) = Command::new("bash")
        .arg("-n")
        .arg("-c")
        .arg(text(&vbi(&["completions", "bash"], dir.dir()).stdout))
        .status()
    {
        assert!(status.success(), "bash -n rejects the completion script");
    }
    let man = vbi(&["man"], dir.dir());
    assert_exit(&man, 0);
    let page = text(&man.stdout);
    assert!(
        page.starts_with(".ie") || page.contains(".TH vbi"),
        "{page}"
    );
    assert!(page.contains(".TH vbi 1"), "no man-page header:\n{page}");
    for name in subcommands {
        assert!(page.contains(name), "man page lacks `{name}`");
    }
    let bad = vbi(&["completions", "cmd.exe"], dir.dir());
    assert_exit(&bad, 2);
    assert!(
        text(&bad.stderr).contains("possible values"),
        "{}",
        text(&bad.stderr)
    );
}

/// `vbi init` writes, for every bridge × vehicle pair the models combine, a
/// starter scene that `vbi check` accepts without a warning and `vbi run`
/// runs (a resonance check may fail its verdict, exit 3, never its run), and
/// the schema beside it for the modeline; a pair the models do not combine
/// is refused with the valid pairs (exit 2), and an existing file is not
/// replaced without --force.
#[test]
fn init_starters_check_and_run_for_every_pair() {
    let dir = Scratch::new("cli", "init");
    let bridges = ["beam", "plate"];
    let vehicles = [
        "moving_force",
        "oscillator",
        "h20_44",
        "rail_car",
        "train",
        "train_3d",
        "hslm",
    ];
    let railway = ["rail_car", "train", "train_3d", "hslm"];
    for bridge in bridges {
        for vehicle in vehicles {
            let folder = dir.path(&format!("{bridge}-{vehicle}"));
            let scene = folder.join("scene.yaml");
            let out = vbi(
                &[
                    "init",
                    "--bridge",
                    bridge,
                    "--vehicle",
                    vehicle,
                    scene.to_str().unwrap(),
                ],
                dir.dir(),
            );
            if bridge == "plate" && railway.contains(&vehicle) {
                assert_exit(&out, 2);
                assert!(
                    text(&out.stderr).contains("no starter scene"),
                    "{}",
                    text(&out.stderr)
                );
                assert!(!scene.exists());
                continue;
            }
            assert_exit(&out, 0);
            let written = std::fs::read_to_string(&scene).unwrap();
            assert!(
                written.starts_with("# yaml-language-server: $schema=vbi.schema.json\n"),
                "{written}"
            );
            let schema = std::fs::read_to_string(folder.join("vbi.schema.json")).unwrap();
            let committed =
                std::fs::read_to_string(manifest_dir().join("schema/vbi.schema.json")).unwrap();
            assert_eq!(
                schema, committed,
                "the schema beside the starter is vbi's own"
            );
            let check = vbi(&["check", scene.to_str().unwrap()], &folder);
            assert_exit(&check, 0);
            assert!(
                !text(&check.stderr).contains("warning"),
                "{bridge} × {vehicle} starter warns:\n{}",
                text(&check.stderr)
            );
            let run = vbi(
                &[
                    "run",
                    "--quiet",
                    scene.to_str().unwrap(),
                    "--out",
                    "results",
                ],
                &folder,
            );
            let code = run.status.code();
            assert!(
                code == Some(0) || (vehicle == "hslm" && code == Some(3)),
                "{bridge} × {vehicle}: exit {code:?}\n{}",
                text(&run.stderr)
            );
            assert!(folder.join("results/summary.json").is_file());
        }
    }
    // An existing file is kept unless --force.
    let scene = dir.path("beam-oscillator/scene.yaml");
    let again = vbi(&["init", scene.to_str().unwrap()], dir.dir());
    assert_exit(&again, 2);
    assert!(
        text(&again.stderr).contains("--force"),
        "{}",
        text(&again.stderr)
    );
    let forced = vbi(&["init", "--force", scene.to_str().unwrap()], dir.dir());
    assert_exit(&forced, 0);
}

/// docs/format.md is exactly what `vbi schema --markdown` generates from the
/// schema (regenerate it with `cargo run --release -- schema --markdown >
/// docs/format.md`), it covers every top-level key, and each example that is
/// not cut from a shipped scene validates when added to one.
#[test]
fn format_reference_matches_the_schema_and_its_examples_validate() {
    let dir = Scratch::new("cli", "format-reference");
    let out = vbi(&["schema", "--markdown"], dir.dir());
    assert_exit(&out, 0);
    let generated = text(&out.stdout);
    let committed = std::fs::read_to_string(manifest_dir().join("docs/format.md"))
        .expect("docs/format.md is committed");
    assert!(
        generated == committed,
        "docs/format.md differs from `vbi schema --markdown`: regenerate it"
    );
    for key in [
        "name",
        "bridge",
        "vehicles",
        "surface",
        "contact",
        "solver",
        "record",
        "study",
        "limits",
        "ground_motion",
        "envelopes",
        "output",
        "gravity",
    ] {
        assert!(
            generated.contains(&format!("| `{key}`")),
            "no row for `{key}`"
        );
    }
    assert!(
        generated.contains("`type: plate`"),
        "union alternatives listed"
    );
    let base = std::fs::read_to_string(manifest_dir().join("scenarios/yang-yau-sprung-mass.yaml"))
        .unwrap();
    for (key, snippet) in vbi::format_reference::SNIPPET_EXAMPLES {
        let scene = dir.path(&format!("{key}.yaml"));
        std::fs::write(&scene, format!("{base}{snippet}")).unwrap();
        let check = vbi(&["check", scene.to_str().unwrap()], dir.dir());
        assert_exit(&check, 0);
        assert!(
            generated.contains(snippet),
            "the `{key}` example is in the reference"
        );
    }
}

/// Every scene under examples/ validates and runs without a warning it does
/// not allow (the
/// resonance check, whose study is the slowest, validates; the shipped
/// hslm-resonance-20m golden runs that study), each from a copy of the
/// examples folder so results land in the scratch folder.
#[test]
fn examples_check_and_run() {
    let dir = Scratch::new("cli", "examples");
    let source = manifest_dir().join("examples");
    let copy = dir.path("examples");
    copy_tree(&source, &copy);
    let scenes = [
        ("road-bridge-check.yaml", true),
        ("railway-resonance-check.yaml", false),
        ("separation-study.yaml", true),
        ("seismic-crossing.yaml", true),
        ("imported-fe/scene.yaml", true),
    ];
    let listed = std::fs::read_to_string(source.join("README.md")).unwrap();
    for (scene, run) in scenes {
        assert!(
            listed.contains(&format!("`{scene}`")),
            "examples/README.md lists {scene}"
        );
        let check = vbi(&["check", scene], &copy);
        assert_exit(&check, 0);
        assert!(
            !text(&check.stderr).contains("warning"),
            "{scene} warns:\n{}",
            text(&check.stderr)
        );
        if run {
            // A warning the run draws and the scene does not allow fails
            // the run (exit 4): a shipped example says what it means.
            let out = vbi(
                &["run", "--quiet", "--deny-warnings", scene, "--out", "out"],
                &copy,
            );
            assert_exit(&out, 0);
            assert!(copy.join("out/summary.json").is_file());
            std::fs::remove_dir_all(copy.join("out")).unwrap();
        }
    }
    // Every YAML file in examples/ is one of the above.
    let mut found = 0;
    for entry in std::fs::read_dir(&source)
        .unwrap()
        .chain(std::fs::read_dir(source.join("imported-fe")).unwrap())
    {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "yaml") {
            found += 1;
        }
    }
    assert_eq!(found, scenes.len(), "an example scene is not tested");
}

fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

/// `vbi man --dir DIR` writes one page per command (issue 41.7): every
/// subcommand of `vbi --help` has its page, every page has an EXIT STATUS
/// section, and every `name(1)` a page refers to (SUBCOMMANDS, SEE ALSO)
/// is a page that was written. `vbi man` prints vbi(1) and `vbi man run`
/// vbi-run(1), the same text as the files.
#[test]
fn man_pages_one_per_command_with_exit_status() {
    let dir = Scratch::new("cli", "man-pages");
    let pages = dir.path("man");
    let wrote = vbi(
        &["man".as_ref(), "--dir".as_ref(), pages.as_os_str()],
        dir.dir(),
    );
    assert_exit(&wrote, 0);
    let names: Vec<String> = file_names(&pages)
        .into_iter()
        .map(|f| f.strip_suffix(".1").expect("a section-1 page").to_string())
        .collect();
    let help = text(&vbi(&["--help"], dir.dir()).stdout);
    let commands: Vec<&str> = help
        .split("Commands:")
        .nth(1)
        .expect("a command list")
        .split("Options:")
        .next()
        .unwrap()
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(commands.len() >= 13, "{commands:?}");
    for command in &commands {
        assert!(
            names.contains(&format!("vbi-{command}")),
            "no page for `vbi {command}`: {names:?}"
        );
    }
    for nested in [
        "vbi-regress-approve",
        "vbi-regress-check",
        "vbi-generate-viaduct",
    ] {
        assert!(names.contains(&nested.to_string()), "no page {nested}");
    }
    for name in &names {
        let page = std::fs::read_to_string(pages.join(format!("{name}.1"))).unwrap();
        assert!(page.contains(&format!(".TH {name} 1")), "{name}: no header");
        let status = page
            .split(".SH \"EXIT STATUS\"")
            .nth(1)
            .unwrap_or_else(|| panic!("{name}: no EXIT STATUS section"));
        assert!(status.contains("\\fB0\\fR"), "{name}: exit 0 not stated");
        assert!(
            status.contains("\\fB2\\fR"),
            "{name}: usage errors not stated"
        );
        // Every reference `word(1)`, hyphens and fonts unescaped.
        let plain = page
            .replace("\\-", "-")
            .replace("\\fB", "")
            .replace("\\fR", "")
            .replace("\\fI", "");
        for (at, _) in plain.match_indices("(1)") {
            let start = plain[..at]
                .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
                .map_or(0, |i| i + 1);
            let target = &plain[start..at];
            assert!(
                names.iter().any(|n| n == target),
                "{name} refers to {target}(1), which is not a page"
            );
        }
        if name != "vbi" {
            assert!(plain.contains("SEE ALSO"), "{name}: no SEE ALSO");
        }
    }
    let main = vbi(&["man"], dir.dir());
    assert_exit(&main, 0);
    assert_eq!(
        text(&main.stdout),
        std::fs::read_to_string(pages.join("vbi.1")).unwrap()
    );
    let run = vbi(&["man", "run"], dir.dir());
    assert_exit(&run, 0);
    assert_eq!(
        text(&run.stdout),
        std::fs::read_to_string(pages.join("vbi-run.1")).unwrap()
    );
    let none = vbi(&["man", "nonsense"], dir.dir());
    assert_exit(&none, 2);
    assert!(
        text(&none.stderr).contains("vbi-run"),
        "{}",
        text(&none.stderr)
    );
}

/// The README's first scene (its first ```yaml block, five lines) is what
/// it says: `vbi check` accepts it without a warning and `vbi run` runs it
/// (issue 41.7).
#[test]
fn the_readme_first_scene_runs() {
    let readme = std::fs::read_to_string(manifest_dir().join("README.md")).unwrap();
    let scene = readme
        .split("```yaml\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("a yaml block in the README");
    assert_eq!(
        scene.lines().count(),
        5,
        "a first scene in five lines:\n{scene}"
    );
    let dir = Scratch::new("cli", "readme-first");
    let path = dir.path("first.yaml");
    std::fs::write(&path, scene).unwrap();
    let check = vbi(&["check".as_ref(), path.as_os_str()], dir.dir());
    assert_exit(&check, 0);
    assert!(
        !text(&check.stderr).contains("warning"),
        "{}",
        text(&check.stderr)
    );
    let out = dir.path("out");
    assert_exit(&run_quiet(&path, &out, dir.dir()), 0);
    for file in [
        "summary.json",
        "history.csv",
        "history.png",
        "resolved.yaml",
    ] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
}

/// The front door (issue 41.7): README.md stays under 10 KB, and every
/// relative link of the README, the guide, docs/methods.md, docs/cluster.md
/// and BENCHMARKS.md names a file that exists and, with `#anchor`, a
/// heading of that file (GitHub's slugs: lower case, spaces to `-`,
/// punctuation dropped).
#[test]
fn front_door_links_resolve() {
    let root = manifest_dir();
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    assert!(
        readme.len() <= 10 * 1024,
        "README.md is {} bytes",
        readme.len()
    );
    let slug = |heading: &str| -> String {
        heading
            .trim()
            .to_lowercase()
            .chars()
            .filter(|c| c.is_alphanumeric() || *c == '-' || *c == '_' || *c == ' ')
            .map(|c| if c == ' ' { '-' } else { c })
            .collect()
    };
    let mut files: Vec<PathBuf> = [
        "README.md",
        "BENCHMARKS.md",
        "docs/methods.md",
        "docs/cluster.md",
    ]
    .iter()
    .map(|f| root.join(f))
    .collect();
    let guide = root.join("docs/guide");
    files.extend(file_names(&guide).iter().map(|f| guide.join(f)));
    assert!(files.len() > 15, "the guide has its topics");
    let mut broken = Vec::new();
    for file in &files {
        let body = std::fs::read_to_string(file).unwrap();
        // Links outside code blocks.
        let prose: String = body.split("```").step_by(2).collect::<Vec<_>>().join("\n");
        for (at, _) in prose.match_indices("](") {
            let rest = &prose[at + 2..];
            let link = &rest[..rest.find(')').unwrap_or(rest.len())];
            if link.starts_with("http") || link.contains(' ') {
                continue;
            }
            let (path, anchor) = link.split_once('#').unwrap_or((link, ""));
            let target = if path.is_empty() {
                file.clone()
            } else {
                file.parent().unwrap().join(path)
            };
            if !target.exists() {
                broken.push(format!("{}: {link}", file.display()));
                continue;
            }
            if !anchor.is_empty() && target.extension().is_some_and(|e| e == "md") {
                let text = std::fs::read_to_string(&target).unwrap();
                if !text
                    .lines()
                    .filter(|l| l.starts_with('#'))
                    .any(|l| slug(l.trim_start_matches('#')) == anchor)
                {
                    broken.push(format!("{}: {link} (no such heading)", file.display()));
                }
            }
        }
    }
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}
