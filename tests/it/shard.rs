//! Sharding: `vbi run --shard K/N` then `vbi merge` writes exactly the files
//! an unsharded run writes, byte for byte (summary.json up to its
//! `wall_time`), for N = 1, 3 and 7 shards and for every study type
//! (Monte Carlo, separation map, speed sweep); missing, duplicated and
//! foreign parts are refused with exit code 2 and a message naming them.

use crate::support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use support::Scratch;
use support::vbi_here as vbi;

fn ok(out: &Output) {
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

const BEAM: &str = "bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, elements_per_span: 10, modes: {count: 4}, damping: {type: modal, ratio: 0.02}}";

fn monte_carlo() -> String {
    format!(
        "name: mc-shard
{BEAM}
vehicles:
  - {{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}}
contact: {{type: elastic, stiffness: 4.0e8}}
surface: {{type: random, coefficient: 2.56e-4, sampling_length: 40.0, terms: 80, seed: 3}}
solver: {{method: lcp, time_step: 1.0e-3, free_vibration: 0.05}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 10.0}}
  - {{name: force, quantity: contact_force, wheel: 1}}
study: {{type: monte_carlo, samples: 5, seed: 2, show: 3, speeds: {{from: 15, to: 30, count: 2}}}}
"
    )
}

fn separation_map() -> String {
    format!(
        "name: map-shard
{BEAM}
vehicles:
  - type: oscillator
    dimensionless: {{velocity_ratio: 0.3, mass_ratio: 1.0, unsprung_ratio: 0.25, frequency_ratio: 0.5, damping_ratio: 0.1}}
contact: {{type: elastic, stiffness_ratio: 100.0}}
solver: {{time_step: 5.0e-4}}
study:
  type: separation_map
  velocity_ratio: {{from: 0.1, to: 0.5, count: 3}}
  mass_ratio: {{from: 0.2, to: 1.0, count: 3}}
"
    )
}

fn speed_sweep() -> String {
    format!(
        "name: sweep-shard
{BEAM}
vehicles:
  - {{type: moving_force, loads: [6.0e4, 1.4e5], axle_spacings: [4.3], speed: 20.0}}
surface: {{type: random, coefficient: 1.6e-5, sampling_length: 40.0, terms: 80, seed: 3}}
solver: {{time_step: 1.0e-3, free_vibration: 0.05}}
record:
  - {{name: mid, quantity: bridge_displacement, x: 10.0}}
study: {{type: speed_sweep, speeds: {{from: 10, to: 30, count: 4}}, roughness: [smooth, good], samples: 2}}
"
    )
}

/// Every file of a folder, sorted, with summary.json's `wall_time` removed.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let path = e.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            let mut bytes = std::fs::read(&path).unwrap();
            if name == "summary.json" {
                let text = String::from_utf8(bytes).unwrap();
                let kept: Vec<&str> = text
                    .lines()
                    .filter(|l| !l.trim_start().starts_with("\"wall_time\""))
                    .collect();
                assert!(
                    kept.len() < text.lines().count(),
                    "summary.json has a wall_time"
                );
                bytes = kept.join("\n").into_bytes();
            }
            (name, bytes)
        })
        .collect();
    out.sort();
    out
}

/// Runs `text` unsharded and in 1, 3 and 7 shards, merges, and compares;
/// gives the names of the files compared.
fn sharded_equals_unsharded(test: &str, text: &str) -> Vec<String> {
    sharded_equals_unsharded_exiting(test, text, 0)
}

/// [`sharded_equals_unsharded`] for a study whose `run` and `merge` exit
/// with `verdict` (3: a resonance check that fails); each shard exits 0.
fn sharded_equals_unsharded_exiting(test: &str, text: &str, verdict: i32) -> Vec<String> {
    let exits = |out: &Output| {
        assert_eq!(
            out.status.code(),
            Some(verdict),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let scratch = Scratch::new("shard", test);
    let scene = scratch.path("scene.yaml");
    std::fs::write(&scene, text).unwrap();
    let s = scene.to_str().unwrap();
    let whole = scratch.path("whole");
    exits(&vbi(&["run", s, "-q", "--out", whole.to_str().unwrap()]));
    let reference = files(&whole);
    assert!(
        reference.len() >= 4,
        "{:?}",
        reference.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for n in [1usize, 3, 7] {
        let parts_dir = scratch.path(&format!("parts{n}"));
        let mut parts: Vec<PathBuf> = Vec::new();
        for k in 1..=n {
            ok(&vbi(&[
                "run",
                s,
                "-q",
                "--shard",
                &format!("{k}/{n}"),
                "--out",
                parts_dir.to_str().unwrap(),
            ]));
            parts.push(parts_dir.join(format!("part-{k}-of-{n}.json")));
        }
        // Only the part files are written by a shard, besides the mark
        // naming the folder's scene (.vbi-owner, issue 23.1).
        let written: Vec<String> = std::fs::read_dir(&parts_dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|name| name != vbi::run::OWNER_FILE)
            .collect();
        assert_eq!(written.len(), n, "{written:?}");
        assert!(parts_dir.join(vbi::run::OWNER_FILE).is_file());
        let merged = scratch.path(&format!("merged{n}"));
        let mut args = vec!["merge", "-q", "--out", merged.to_str().unwrap()];
        // Given in reverse: the order of the arguments does not matter.
        let names: Vec<String> = parts
            .iter()
            .rev()
            .map(|p| p.display().to_string())
            .collect();
        args.extend(names.iter().map(String::as_str));
        exits(&vbi(&args));
        let got = files(&merged);
        assert_eq!(
            got.iter().map(|f| &f.0).collect::<Vec<_>>(),
            reference.iter().map(|f| &f.0).collect::<Vec<_>>()
        );
        for ((name, a), (_, b)) in got.iter().zip(&reference) {
            assert!(a == b, "{test}: {name} differs after merging {n} shards");
        }
    }
    reference.into_iter().map(|f| f.0).collect()
}

#[test]
fn monte_carlo_shards_merge_to_the_unsharded_files() {
    let names = sharded_equals_unsharded("mc", &monte_carlo());
    // Every output of a Monte Carlo study with speeds, compared above.
    for file in [
        "envelope_force.png",
        "envelope_midspan.png",
        "envelopes.csv",
        "expected_gap.png",
        "resolved.yaml",
        "separation.csv",
        "separation_probability.png",
        "study.csv",
        "summary.json",
    ] {
        assert!(names.iter().any(|n| n == file), "{file} missing: {names:?}");
    }
}

#[test]
fn separation_map_shards_merge_to_the_unsharded_files() {
    let names = sharded_equals_unsharded("map", &separation_map());
    assert!(names.iter().any(|n| n == "separation_map.png"));
}

#[test]
fn speed_sweep_shards_merge_to_the_unsharded_files() {
    let names = sharded_equals_unsharded("sweep", &speed_sweep());
    assert!(names.iter().any(|n| n == "daf_map.png"));
}

/// A resonance check with two trains on a 20 m span, 280 to 360 km/h in
/// 20 km/h steps refined around HSLM-A1's resonance f₁D = 323.89 km/h; it
/// fails (HSLM-A1 near 27 m/s²), so `run` and `merge` exit 3.
fn resonance_check() -> String {
    "name: resonance-shard
bridge: {type: beam, spans: [20.0], bending_stiffness: 2.43e10, mass_per_length: 15000.0, modes: {max_frequency: 50.0}, damping: {type: modal, ratio: 0.01}}
vehicles: [{type: hslm, model: A1, speed: 300 km/h}]
study: {type: resonance_check, trains: [A1, A10], line_speed: 300 km/h, speeds: {from: 280 km/h, to: 360 km/h, step: 20 km/h}}
"
    .to_owned()
}

#[test]
fn resonance_check_shards_merge_to_the_unsharded_files() {
    let names = sharded_equals_unsharded_exiting("resonance", &resonance_check(), 3);
    for file in [
        "resolved.yaml",
        "resonance.csv",
        "resonance_trains.csv",
        "resonance.png",
        "resonance_displacement.png",
        "summary.json",
    ] {
        assert!(names.iter().any(|n| n == file), "{file} missing: {names:?}");
    }
}

#[test]
fn missing_duplicated_and_foreign_parts_are_refused() {
    let scratch = Scratch::new("shard", "refused");
    let a = scratch.path("a.yaml");
    let b = scratch.path("b.yaml");
    std::fs::write(&a, monte_carlo()).unwrap();
    std::fs::write(&b, monte_carlo().replace("seed: 2", "seed: 9")).unwrap();
    let dir = |name: &str| scratch.path(name).display().to_string();
    for k in 1..=3 {
        let shard = format!("{k}/3");
        ok(&vbi(&[
            "run",
            a.to_str().unwrap(),
            "-q",
            "--shard",
            &shard,
            "--out",
            &dir("a"),
        ]));
    }
    ok(&vbi(&[
        "run",
        b.to_str().unwrap(),
        "-q",
        "--shard",
        "2/3",
        "--out",
        &dir("b"),
    ]));
    let part = |d: &str, k: usize| format!("{}/part-{k}-of-3.json", dir(d));
    let refused = |parts: &[String], expect: &str| {
        let mut args = vec!["merge".to_string(), "--out".into(), dir("merged")];
        args.extend(parts.iter().cloned());
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = vbi(&refs);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(expect), "expected `{expect}` in: {stderr}");
        assert!(
            !scratch.path("merged").exists(),
            "nothing written on refusal"
        );
    };
    refused(&[part("a", 1), part("a", 3)], "1 of 3 shards missing: 2");
    refused(
        &[part("a", 1), part("a", 2), part("a", 2), part("a", 3)],
        "shard 2 of 3 is given twice",
    );
    refused(
        &[part("a", 1), part("b", 2), part("a", 3)],
        "is from another scenario",
    );
    // A part whose results were cut (or edited) is refused, not indexed.
    let mut value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(part("a", 2)).unwrap()).unwrap();
    value["data"]["samples"].as_array_mut().unwrap().pop();
    let cut = scratch.path("cut.json");
    std::fs::write(&cut, value.to_string()).unwrap();
    refused(
        &[part("a", 1), cut.display().to_string(), part("a", 3)],
        "cut.json's results do not match their digest",
    );
    // With the digest forged to match, the slice's shape still refuses it.
    let data: vbi::study::shard::PartData = serde_json::from_value(value["data"].clone()).unwrap();
    value["data_digest"] = vbi::study::shard::data_digest(&data).into();
    std::fs::write(&cut, value.to_string()).unwrap();
    refused(
        &[part("a", 1), cut.display().to_string(), part("a", 3)],
        "shard 2 of 3: it holds",
    );
    // One number of the results edited: the digest refuses it.
    let mut value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(part("a", 2)).unwrap()).unwrap();
    let text = value["data"].to_string();
    let digit = text.find(|c: char| c.is_ascii_digit() && c != '0').unwrap();
    let mut edited = text.clone();
    edited.replace_range(
        digit..digit + 1,
        if &text[digit..digit + 1] == "9" {
            "8"
        } else {
            "9"
        },
    );
    value["data"] = serde_json::from_str(&edited).unwrap();
    std::fs::write(&cut, value.to_string()).unwrap();
    refused(
        &[part("a", 1), cut.display().to_string(), part("a", 3)],
        "do not match their digest",
    );
    let junk = scratch.path("junk.json");
    std::fs::write(&junk, "{\"format\": 1}").unwrap();
    refused(&[junk.display().to_string()], "not a vbi part file");
    // A scene without a study cannot be sharded.
    let plain = scratch.path("plain.yaml");
    let text = monte_carlo();
    let scene = &text[..text.find("study:").unwrap()];
    std::fs::write(&plain, scene).unwrap();
    let out = vbi(&[
        "run",
        plain.to_str().unwrap(),
        "--shard",
        "1/2",
        "--out",
        &dir("plain"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no `study` section"));
    // A malformed shard is a usage error.
    let out = vbi(&["run", a.to_str().unwrap(), "--shard", "4/3"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn an_unusable_part_names_its_shard_and_the_command_that_writes_it_again() {
    let scratch = Scratch::new("shard", "unusable");
    std::fs::write(scratch.path("mc.yaml"), monte_carlo()).unwrap();
    let vbi_in = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_vbi"))
            .args(args)
            .current_dir(scratch.dir())
            .output()
            .unwrap()
    };
    for k in 1..=3 {
        ok(&vbi_in(&[
            "run",
            "mc.yaml",
            "-q",
            "--shard",
            &format!("{k}/3"),
            "--out",
            "my parts",
        ]));
    }
    let parts: Vec<String> = (1..=3)
        .map(|k| format!("my parts/part-{k}-of-3.json"))
        .collect();
    let merge = |parts: &[String]| {
        let mut args = vec!["merge", "--out", "merged"];
        args.extend(parts.iter().map(String::as_str));
        let out = vbi_in(&args);
        assert_eq!(out.status.code(), Some(2));
        assert!(
            !scratch.path("merged").exists(),
            "nothing written on refusal"
        );
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    // The exact command, the folder quoted for the shell (it has a space).
    let command = "`vbi run mc.yaml --shard 2/3 --out 'my parts'`";
    let path = scratch.path("my parts/part-2-of-3.json");
    let text = std::fs::read(&path).unwrap();
    // Cut mid-write (a task killed while writing without the atomic rename),
    // emptied, removed, and left out of the list.
    std::fs::write(&path, &text[..text.len() / 2]).unwrap();
    let cut = merge(&parts);
    assert!(
        cut.contains("part-2-of-3.json: not a vbi part file: it ends early")
            && cut.contains("shard 2 of 3 is unusable")
            && cut.contains(command),
        "{cut}"
    );
    std::fs::write(&path, "").unwrap();
    let empty = merge(&parts);
    assert!(
        empty.contains("shard 2 of 3 is unusable") && empty.contains(command),
        "{empty}"
    );
    std::fs::remove_file(&path).unwrap();
    let gone = merge(&parts);
    assert!(
        gone.contains("cannot read")
            && gone.contains("shard 2 of 3 is unusable")
            && gone.contains(command),
        "{gone}"
    );
    let left_out = merge(&[parts[0].clone(), parts[2].clone()]);
    assert!(
        left_out.contains("1 of 3 shards missing: 2 (runs 3..6)") && left_out.contains(command),
        "{left_out}"
    );
    // Run as printed, the merge goes through.
    let printed = command.trim_matches('`');
    let bin = Path::new(env!("CARGO_BIN_EXE_vbi")).parent().unwrap();
    let status = Command::new("sh")
        .args(["-c", printed])
        .current_dir(scratch.dir())
        .env(
            "PATH",
            format!(
                "{}:{}",
                bin.display(),
                std::env::var("PATH").unwrap_or_default()
            ),
        )
        .status()
        .unwrap();
    assert!(status.success());
    let mut args = vec!["merge", "-q", "--out", "merged"];
    args.extend(parts.iter().map(String::as_str));
    ok(&vbi_in(&args));
}

#[test]
fn running_a_finished_shard_again_replaces_its_part_atomically() {
    use std::os::unix::fs::MetadataExt;
    let scratch = Scratch::new("shard", "rerun");
    // Enough samples that the run lasts while the part is read below.
    let scene = scratch.path("mc.yaml");
    std::fs::write(&scene, monte_carlo().replace("samples: 5", "samples: 400")).unwrap();
    let dir = scratch.path("parts");
    let args = [
        "run",
        scene.to_str().unwrap(),
        "-q",
        "--shard",
        "2/2",
        "--out",
        dir.to_str().unwrap(),
    ];
    ok(&vbi(&args));
    let path = dir.join("part-2-of-2.json");
    let first = std::fs::read(&path).unwrap();
    let inode = std::fs::metadata(&path).unwrap().ino();
    // While the shard runs again, the part on disk is always the whole
    // old one (never truncated, never half written).
    let mut again = Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .spawn()
        .unwrap();
    let mut reads = 0;
    while again.try_wait().unwrap().is_none() {
        let now = std::fs::read(&path).unwrap();
        if std::fs::metadata(&path).map(|m| m.ino()).ok() == Some(inode) {
            assert!(now == first, "the old part changed in place");
        }
        let parsed: serde_json::Value = serde_json::from_slice(&now).expect("a whole part");
        assert_eq!(parsed["shard"], 2);
        reads += 1;
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(again.wait().unwrap().success());
    assert!(reads > 3, "the run was too short to watch ({reads} reads)");
    // Replaced by a rename (a new file), and nothing else left behind.
    assert_ne!(std::fs::metadata(&path).unwrap().ino(), inode);
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name != vbi::run::OWNER_FILE)
        .collect();
    assert_eq!(names, ["part-2-of-2.json"]);
    // The same results (the wall time aside).
    let strip = |bytes: &[u8]| {
        let mut v: serde_json::Value = serde_json::from_slice(bytes).unwrap();
        v["wall_time"] = serde_json::Value::Null;
        v
    };
    assert_eq!(strip(&first), strip(&std::fs::read(&path).unwrap()));
}

#[test]
fn part_names_and_rerun_commands() {
    let of = |name: &str| vbi::study::shard::Shard::from_file_name(Path::new(name));
    assert_eq!(
        of("dir/part-3-of-8.json"),
        Some(vbi::study::shard::Shard { index: 3, count: 8 })
    );
    for bad in [
        "part-0-of-8.json",
        "part-9-of-8.json",
        "part-3-of-8",
        "p-3-of-8.json",
    ] {
        assert_eq!(of(bad), None, "{bad}");
    }
    let shard = vbi::study::shard::Shard { index: 3, count: 8 };
    assert_eq!(
        vbi::study::shard::rerun_command(
            Some("s.yaml"),
            shard,
            Path::new("out/parts/part-3-of-8.json")
        ),
        "vbi run s.yaml --shard 3/8 --out out/parts"
    );
    assert_eq!(
        vbi::study::shard::rerun_command(Some("it's.yaml"), shard, Path::new("part-3-of-8.json")),
        "vbi run 'it'\\''s.yaml' --shard 3/8 --out ."
    );
    assert_eq!(
        vbi::study::shard::rerun_command(
            Some("a\u{1b}[2J.yaml"),
            shard,
            Path::new("my parts/p.json")
        ),
        "vbi run SCENE --shard 3/8 --out 'my parts'"
    );
}
