//! Outputs that load cleanly everywhere (issue 26, point 5): every CSV file
//! every command writes names its columns in ONE style, `name [unit]` with the
//! SI unit in brackets (`time [s]`, `speed [km/h]`, `midspan_max [m]`,
//! `max_acceleration [m/s^2]`) and a dimensionless column without a bracket
//! (`probability`, `daf`, `velocity_ratio`); and a speed the user wrote in
//! km/h comes back as written (`359`, never `359.00000000000006`).
//!
//! The scenes below are shipped scenes (or a shipped scene with a study
//! added) chosen so that every CSV writer runs: a history, a Monte Carlo
//! study (samples, separation, envelopes), a separation map, a speed sweep, a
//! resonance check (runs and trains), a plate's DAF table, deck envelopes,
//! `vbi converge`, `vbi modes --shapes` and a regression store.

use std::path::{Path, PathBuf};

use regex::Regex;

use crate::support::{manifest_dir, scratch_dir, text, vbi};

/// The one header style: a name (letters, digits, `_`, `.`, `-`), then
/// optionally a space and the unit in brackets (`m`, `m/s^2`, `N*m`, `km/h`).
const HEADER_FIELD: &str = r"^[A-Za-z0-9_.\-]+( \[[A-Za-z0-9*/^.]+\])?$";

/// Runs `vbi args` in the repository, accepting the exit codes `ok`.
fn run(args: &[&str], ok: &[i32]) {
    let out = vbi(args, manifest_dir());
    assert!(
        out.status.code().is_some_and(|c| ok.contains(&c)),
        "vbi {args:?}: {:?}\nstdout:\n{}\nstderr:\n{}",
        out.status,
        text(&out.stdout),
        text(&out.stderr)
    );
}

/// Every `*.csv` file under `dir` (recursively).
fn csv_files(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            csv_files(&path, found);
        } else if path.extension().is_some_and(|e| e == "csv") {
            found.push(path);
        }
    }
}

/// A shipped scene with `extra` appended, written into `dir`.
fn scene_with(dir: &Path, shipped: &str, extra: &str) -> String {
    let text = std::fs::read_to_string(manifest_dir().join(shipped)).unwrap();
    let path = dir.join(Path::new(shipped).file_name().unwrap());
    std::fs::write(&path, format!("{text}{extra}")).unwrap();
    path.display().to_string()
}

#[test]
fn every_csv_header_of_every_command_is_name_space_unit_in_brackets() {
    let dir = scratch_dir("csv-headers", "style");
    let out = |name: &str| dir.join(name).display().to_string();
    // A history (with static columns).
    run(
        &[
            "run",
            "scenarios/lcp-fig4-elastic.yaml",
            "--quiet",
            "--out",
            &out("history"),
        ],
        &[0],
    );
    // A Monte Carlo study: study.csv, separation.csv, envelopes.csv.
    run(
        &[
            "run",
            "scenarios/lcp-fig7-monte-carlo.yaml",
            "--quiet",
            "--out",
            &out("mc"),
        ],
        &[0],
    );
    // A separation map (study.csv with the derived parameters).
    run(
        &[
            "run",
            "scenarios/lcp-fig6-harmonic.yaml",
            "--quiet",
            "--out",
            &out("map"),
        ],
        &[0],
    );
    // A resonance check: resonance.csv and resonance_trains.csv (exit 3
    // when a limit is exceeded).
    run(
        &[
            "run",
            "scenarios/hslm-resonance-20m.yaml",
            "--quiet",
            "--out",
            &out("resonance"),
        ],
        &[0, 3],
    );
    // A plate: daf_table.csv.
    run(
        &[
            "run",
            "scenarios/plate-isotropic-32.5.yaml",
            "--quiet",
            "--out",
            &out("plate"),
        ],
        &[0],
    );
    // Envelopes along the deck.
    run(
        &[
            "run",
            "examples/road-bridge-check.yaml",
            "--quiet",
            "--out",
            &out("envelopes"),
        ],
        &[0],
    );
    // A speed sweep keeping every record.
    let sweep = scene_with(
        &dir,
        "scenarios/lcp-fig4-elastic.yaml",
        "study: {type: speed_sweep, speeds: {from: 20.0, to: 40.0, count: 2}}\n",
    );
    run(&["run", &sweep, "--quiet", "--out", &out("sweep")], &[0]);
    // converge.csv.
    run(
        &[
            "converge",
            "scenarios/lcp-fig4-elastic.yaml",
            "--levels",
            "2",
            "--out",
            &out("converge"),
        ],
        &[0, 1],
    );
    // Mode shapes.
    run(
        &[
            "modes",
            "scenarios/lcp-fig4-elastic.yaml",
            "--shapes",
            &out("modes.csv"),
        ],
        &[0],
    );
    // A regression store's records.
    run(
        &[
            "regress",
            "approve",
            "scenarios/lcp-fig4-elastic.yaml",
            "--store",
            &out("store"),
        ],
        &[0],
    );

    let pattern = Regex::new(HEADER_FIELD).unwrap();
    let mut files = Vec::new();
    csv_files(&dir, &mut files);
    files.sort();
    let names: Vec<String> = files
        .iter()
        .map(|f| f.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    for expected in [
        "history.csv",
        "study.csv",
        "separation.csv",
        "envelopes.csv",
        "resonance.csv",
        "resonance_trains.csv",
        "daf_table.csv",
        "converge.csv",
        "modes.csv",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "no {expected} among {names:?}"
        );
    }
    let mut wrong = Vec::new();
    for file in &files {
        let content = std::fs::read_to_string(file).unwrap();
        let header = content.lines().find(|l| !l.starts_with('#')).unwrap_or("");
        for field in header.split(',') {
            let field = field.trim_matches('"');
            if !pattern.is_match(field) {
                wrong.push(format!(
                    "{}: `{field}`",
                    file.strip_prefix(&dir).unwrap().display()
                ));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{} CSV header fields are not `name [unit]` ({HEADER_FIELD}):\n{}",
        wrong.len(),
        wrong.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// 359 km/h is 99.7222… m/s; converted there and back in binary it is
/// 359.00000000000006. Every output that shows the speed in km/h writes
/// `359`, and no output writes the float noise of the conversion.
#[test]
fn a_speed_given_in_km_h_comes_back_as_written_in_every_output() {
    let dir = scratch_dir("csv-headers", "km_h");
    // A Monte Carlo study over one speed given in km/h (a speed grid), and a
    // speed sweep over the same speed: both write speed [km/h] columns and
    // summary.json.
    let mc = scene_with(&dir, "scenarios/lcp-fig8-monte-carlo-speeds.yaml", "");
    let text_in = std::fs::read_to_string(&mc).unwrap();
    let text_in = text_in
        .replace("samples: 8", "samples: 2")
        .replace(
            "speeds: {from: 10 km/h, to: 80 km/h, count: 8}",
            "speeds: {from: 359 km/h, to: 359 km/h, count: 1}",
        )
        .replace("roughness: [very_good, good, average]", "roughness: [good]");
    assert!(text_in.contains("359 km/h") && text_in.contains("samples: 2"));
    std::fs::write(&mc, text_in).unwrap();
    let out = |name: &str| dir.join(name).display().to_string();
    run(&["run", &mc, "--quiet", "--out", &out("mc")], &[0]);
    let sweep = scene_with(
        &dir,
        "scenarios/lcp-fig4-elastic.yaml",
        "study: {type: speed_sweep, speeds: {from: 359 km/h, to: 359 km/h, count: 1}}\n",
    );
    run(&["run", &sweep, "--quiet", "--out", &out("sweep")], &[0]);

    let mut km_h_cells = 0;
    for folder in ["mc", "sweep"] {
        for entry in std::fs::read_dir(dir.join(folder)).unwrap() {
            let path = entry.unwrap().path();
            let Ok(content) = std::fs::read_to_string(&path) else {
                continue;
            };
            for noise in ["359.0000000", "358.9999999"] {
                assert!(
                    !content.contains(noise),
                    "{} writes {noise}…",
                    path.display()
                );
            }
            if path.extension().is_some_and(|e| e == "csv") {
                let mut lines = content.lines();
                let header: Vec<&str> = lines.next().unwrap().split(',').collect();
                let Some(column) = header.iter().position(|h| *h == "speed [km/h]") else {
                    continue;
                };
                for line in lines {
                    assert_eq!(
                        line.split(',').nth(column),
                        Some("359"),
                        "{}: {line}",
                        path.display()
                    );
                    km_h_cells += 1;
                }
            }
        }
    }
    assert!(
        km_h_cells >= 3,
        "only {km_h_cells} speed [km/h] cells checked"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
