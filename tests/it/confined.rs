//! Issue 23 point 1: the files a scene names are read only inside the scene
//! file's folder tree (after resolving symlinks) or a folder the user names
//! with `--data-dir`; a refusal names the path and the option and never
//! quotes a byte of the file.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::support;
use support::Scratch;
use support::vbi_streams as vbi;

/// A secret outside every scene folder: no output may ever contain it.
const CANARY: &str = "CANARY-SECRET-8a41f2";

fn scenarios() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios")
}

/// A copy of the quake scene in `scratch/scene/` with its record folder, and
/// a canary file (`secret.txt`, a passwd-like line with the canary) beside
/// the scene folder, outside it.
fn quake_copy(scratch: &Scratch) -> (PathBuf, PathBuf) {
    let scene = scratch.path("scene");
    fs::create_dir_all(scene.join("records")).unwrap();
    fs::copy(
        scenarios().join("quake-vertical-rail-car.yaml"),
        scene.join("quake-vertical-rail-car.yaml"),
    )
    .unwrap();
    let secret = scratch.path("secret.txt");
    fs::write(
        &secret,
        format!("root:x:0:0:root:/root:/bin/bash {CANARY}\n1,{CANARY}\n"),
    )
    .unwrap();
    (scene, secret)
}

fn assert_no_canary(what: &str, stdout: &str, stderr: &str) {
    assert!(
        !stdout.contains(CANARY) && !stderr.contains(CANARY) && !stderr.contains("root:x:0"),
        "{what}: the canary leaked:\n{stdout}\n{stderr}"
    );
}

/// The reproducer: a record that is a symlink to a file outside the
/// scene's folder is refused before it is read, with the path and the way
/// to allow it, and none of its content.
#[test]
fn a_symlink_out_of_the_scene_folder_is_refused_without_its_content() {
    let scratch = Scratch::new("confined", "symlink");
    let (scene, secret) = quake_copy(&scratch);
    std::os::unix::fs::symlink(&secret, scene.join("records/synthetic-vertical.AT2")).unwrap();
    let (code, stdout, stderr) = vbi(&["check", "quake-vertical-rail-car.yaml"], &scene);
    assert_no_canary("symlink", &stdout, &stderr);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("--data-dir"), "{stderr}");
    assert!(stderr.contains("synthetic-vertical.AT2"), "{stderr}");
}

/// The same record outside the folder is read when the user names its
/// folder with `--data-dir`, by a relative path through a symlink or by an
/// absolute path; an absolute path without it is refused.
#[test]
fn data_dir_lets_a_scene_read_outside_its_folder() {
    let scratch = Scratch::new("confined", "data-dir");
    let (scene, _) = quake_copy(&scratch);
    let shared = scratch.path("shared");
    fs::create_dir_all(&shared).unwrap();
    let record = shared.join("vertical.AT2");
    fs::copy(scenarios().join("records/synthetic-vertical.AT2"), &record).unwrap();
    std::os::unix::fs::symlink(&record, scene.join("records/synthetic-vertical.AT2")).unwrap();
    let file = "quake-vertical-rail-car.yaml";
    let (code, _, stderr) = vbi(&["check", file], &scene);
    assert_eq!(code, Some(2), "{stderr}");
    let (code, _, stderr) = vbi(&["check", "--data-dir", "../shared", file], &scene);
    assert_eq!(code, Some(0), "{stderr}");
    // An absolute path: only with --data-dir.
    let text = fs::read_to_string(scene.join(file)).unwrap();
    let absolute = text.replace("records/synthetic-vertical.AT2", record.to_str().unwrap());
    fs::write(scene.join("absolute.yaml"), absolute).unwrap();
    let (code, _, stderr) = vbi(&["check", "absolute.yaml"], &scene);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("is an absolute path") && stderr.contains("--data-dir"),
        "{stderr}"
    );
    let dir = shared.to_str().unwrap();
    let (code, _, stderr) = vbi(&["check", "--data-dir", dir, "absolute.yaml"], &scene);
    assert_eq!(code, Some(0), "{stderr}");
}

/// A FIFO or a device in a record's place is refused before it is opened:
/// no hang, no endless read.
#[test]
fn fifos_and_devices_are_refused_before_opening() {
    let scratch = Scratch::new("confined", "fifo");
    let (scene, _) = quake_copy(&scratch);
    let fifo = scene.join("records/synthetic-vertical.AT2");
    let made = Command::new("mkfifo").arg(&fifo).status().expect("mkfifo");
    assert!(made.success());
    let start = std::time::Instant::now();
    let (code, _, stderr) = vbi(&["check", "quake-vertical-rail-car.yaml"], &scene);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("not a regular file"), "{stderr}");
    assert!(start.elapsed().as_secs() < 10, "took {:?}", start.elapsed());
    // A device, even inside a folder the user allowed.
    let text = fs::read_to_string(scene.join("quake-vertical-rail-car.yaml")).unwrap();
    fs::write(
        scene.join("zero.yaml"),
        text.replace("records/synthetic-vertical.AT2", "/dev/zero"),
    )
    .unwrap();
    let (code, _, stderr) = vbi(&["check", "--data-dir", "/dev", "zero.yaml"], &scene);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("not a regular file"), "{stderr}");
    // A FIFO as a part file.
    let (code, _, stderr) = vbi(
        &["merge", "--out", "merged", fifo.to_str().unwrap()],
        &scene,
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(!scene.join("merged").exists());
}

const MAP: &str = "name: map
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, elements_per_span: 10, modes: {count: 4}, damping: {type: modal, ratio: 0.02}}
vehicles:
  - type: oscillator
    dimensionless: {velocity_ratio: 0.3, mass_ratio: 1.0, unsprung_ratio: 0.25, frequency_ratio: 0.5, damping_ratio: 0.1}
contact: {type: elastic, stiffness_ratio: 100.0}
solver: {time_step: 5.0e-4}
study:
  type: separation_map
  velocity_ratio: {from: 0.1, to: 0.5, count: 2}
  mass_ratio: {from: 0.2, to: 1.0, count: 2}
";

/// Issue 23 point 3: a shard count beyond the study's runs is refused by
/// `vbi run --shard`; parts forged from a real one (so that their scene hash
/// is right) with 10^11 or 2^64 − 1 shards, or `allow_large`, are refused by
/// `vbi merge` in well under a second, without allocating per shard.
#[test]
fn forged_shard_counts_and_allow_large_are_refused() {
    let scratch = Scratch::new("confined", "shards");
    let dir = scratch.dir();
    fs::write(dir.join("map.yaml"), MAP).unwrap();
    let (code, _, stderr) = vbi(
        &[
            "run",
            "-q",
            "map.yaml",
            "--shard",
            "1/99999999999",
            "--out",
            "p",
        ],
        dir,
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("at most one shard a run"), "{stderr}");
    let (code, _, stderr) = vbi(
        &["run", "-q", "map.yaml", "--shard", "1/1", "--out", "p"],
        dir,
    );
    assert_eq!(code, Some(0), "{stderr}");
    let real: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(dir.join("p/part-1-of-1.json")).unwrap()).unwrap();
    let forge = |name: &str, edit: &dyn Fn(&mut serde_json::Value)| -> PathBuf {
        let mut part = real.clone();
        edit(&mut part);
        let path = dir.join(name);
        fs::write(&path, part.to_string()).unwrap();
        path
    };
    let cases: Vec<(PathBuf, &str)> = vec![
        (
            forge("huge.json", &|p| {
                p["shards"] = 99_999_999_999u64.into();
                p["end"] = 0.into();
            }),
            "at most one shard a run",
        ),
        (
            forge("max.json", &|p| {
                p["shards"] = u64::MAX.into();
                p["end"] = 0.into();
            }),
            "at most one shard a run",
        ),
        (
            forge("allow.json", &|p| p["allow_large"] = true.into()),
            "merge with `--allow-large` too",
        ),
        (
            forge("size.json", &|p| p["size"] = 99_999_999_999u64.into()),
            "claims a 99999999999-run study",
        ),
        (
            forge("hash.json", &|p| {
                p["scenario_hash"] = "0123456789abcdef".into()
            }),
            "their hash",
        ),
    ];
    for (part, expect) in cases {
        let start = std::time::Instant::now();
        let (code, _, stderr) = vbi(&["merge", "--out", "m", part.to_str().unwrap()], dir);
        assert_eq!(code, Some(2), "{}: {stderr}", part.display());
        assert!(
            stderr.contains(expect),
            "{}: expected `{expect}`: {stderr}",
            part.display()
        );
        assert!(start.elapsed().as_secs() < 5, "took {:?}", start.elapsed());
        assert!(!dir.join("m").exists());
    }
}

/// Issue 23: a forged part whose scene names /etc/passwd (absolutely, or by
/// its own file name placed in /etc) reads nothing outside the current
/// folder's tree and prints none of it.
#[test]
fn a_forged_part_reads_nothing_outside() {
    let scratch = Scratch::new("confined", "forged-scene");
    let (_, secret) = quake_copy(&scratch);
    let part = |file: &str, source: String| {
        serde_json::json!({
            "format": "vbi-part-2", "vbi_version": "0", "scenario_hash": "0",
            "scenario_file": file, "scenario_source": source, "allow_large": false,
            "study": "separation_map", "size": 4, "shard": 1, "shards": 1, "first": 0,
            "end": 4, "wall_time": 0.0, "data_digest": "0", "data": {"study": "separation_map", "points": []}
        })
        .to_string()
    };
    let quake = |path: &str| format!("{MAP}ground_motion:\n  - {{file: {path}, units: g}}\n");
    let secret_dir = secret.parent().unwrap();
    let cases = [
        part("/etc/x.yaml", quake("passwd")),
        part(
            secret_dir.join("x/x.yaml").to_str().unwrap(),
            quake("../secret.txt"),
        ),
        part("x.yaml", quake("../../../../../../../../../etc/passwd")),
    ];
    let work = scratch.path("work");
    fs::create_dir_all(&work).unwrap();
    for (i, text) in cases.iter().enumerate() {
        let path = work.join(format!("part{i}.json"));
        fs::write(&path, text).unwrap();
        let (code, stdout, stderr) = vbi(&["merge", "--out", "m", path.to_str().unwrap()], &work);
        assert_no_canary(&format!("part {i}"), &stdout, &stderr);
        assert_eq!(code, Some(2), "{stderr}");
        assert!(stderr.contains("--data-dir"), "{stderr}");
    }
}

/// Issue 22 point 7: `fe.yaml` and `flip/fe.yaml` both defaulted to
/// `results/fe`; the second is now refused with the way out, `--force`
/// replaces, and the same scene runs into its own folder again.
#[test]
fn two_scene_files_never_share_a_results_folder() {
    let scratch = Scratch::new("confined", "folders");
    let dir = scratch.dir();
    let scene = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/hostile/cases/ok-plain.yaml"),
    )
    .unwrap();
    fs::create_dir_all(dir.join("flip")).unwrap();
    fs::write(dir.join("fe.yaml"), &scene).unwrap();
    fs::write(dir.join("flip/fe.yaml"), &scene).unwrap();
    let (code, _, stderr) = vbi(&["run", "-q", "fe.yaml"], dir);
    assert_eq!(code, Some(0), "{stderr}");
    let resolved = fs::read_to_string(dir.join("results/fe/resolved.yaml")).unwrap();
    let (code, _, stderr) = vbi(&["run", "-q", "fe.yaml"], dir);
    assert_eq!(code, Some(0), "the same scene again: {stderr}");
    let (code, _, stderr) = vbi(&["run", "-q", "flip/fe.yaml"], dir);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("another scene file")
            && stderr.contains("--out")
            && stderr.contains("--force"),
        "{stderr}"
    );
    assert_eq!(
        fs::read_to_string(dir.join("results/fe/resolved.yaml")).unwrap(),
        resolved,
        "the refused run wrote into the folder"
    );
    let (code, _, stderr) = vbi(&["run", "-q", "--force", "flip/fe.yaml"], dir);
    assert_eq!(code, Some(0), "{stderr}");
    let now = fs::read_to_string(dir.join("results/fe/resolved.yaml")).unwrap();
    assert!(now.contains("flip/fe.yaml"), "{now}");
}

/// Issue 23 point 1 caveat: `vbi converge`'s folder and the `--shard` parts'
/// folder are claimed as `vbi run`'s is. `fe-converge` of `fe.yaml` refuses
/// `flip/fe.yaml` (and `--force` replaces it); the parts' folder of
/// `sweep.yaml` refuses `flip/sweep.yaml`'s shard, and a run's folder
/// refuses another scene's shard.
#[test]
fn converge_and_shard_folders_are_claimed_like_run_folders() {
    let scratch = Scratch::new("confined", "claimed");
    let dir = scratch.dir();
    let scene = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/hostile/cases/ok-plain.yaml"),
    )
    .unwrap();
    let sweep =
        format!("{scene}study: {{type: speed_sweep, speeds: {{from: 10, to: 20, count: 4}}}}\n");
    fs::create_dir_all(dir.join("flip")).unwrap();
    for (name, text) in [("fe.yaml", &scene), ("sweep.yaml", &sweep)] {
        fs::write(dir.join(name), text).unwrap();
        fs::write(dir.join("flip").join(name), text).unwrap();
    }
    let refused = |args: &[&str], what: &str| {
        let (code, _, stderr) = vbi(args, dir);
        assert_eq!(code, Some(2), "{what}: {stderr}");
        assert!(
            stderr.contains("another scene file")
                && stderr.contains("--out")
                && stderr.contains("--force"),
            "{what}: {stderr}"
        );
    };
    let accepted = |args: &[&str], what: &str| {
        let (code, _, stderr) = vbi(args, dir);
        assert_eq!(code, Some(0), "{what}: {stderr}");
    };
    // Converge.
    fn converge(file: &str) -> [&str; 5] {
        ["converge", "-q", "--levels", "2", file]
    }
    accepted(&converge("fe.yaml"), "the first converge");
    accepted(&converge("fe.yaml"), "the same scene again");
    let table = fs::read_to_string(dir.join("results/fe-converge/converge.csv")).unwrap();
    refused(&converge("flip/fe.yaml"), "another scene's converge");
    assert_eq!(
        fs::read_to_string(dir.join("results/fe-converge/converge.csv")).unwrap(),
        table,
        "the refused converge wrote into the folder"
    );
    accepted(
        &["converge", "-q", "--levels", "2", "--force", "flip/fe.yaml"],
        "--force",
    );
    refused(&converge("fe.yaml"), "the folder is now flip/fe.yaml's");
    // Shards.
    accepted(&["run", "-q", "--shard", "1/2", "sweep.yaml"], "shard 1");
    accepted(&["run", "-q", "--shard", "2/2", "sweep.yaml"], "shard 2");
    refused(
        &["run", "-q", "--shard", "2/2", "flip/sweep.yaml"],
        "another scene's shard",
    );
    assert!(!dir.join("results/sweep/resolved.yaml").exists());
    accepted(&["run", "-q", "fe.yaml"], "a run");
    refused(
        &[
            "run",
            "-q",
            "--shard",
            "1/2",
            "--out",
            "results/fe",
            "sweep.yaml",
        ],
        "a shard into another scene's run folder",
    );
    accepted(
        &[
            "run",
            "-q",
            "--shard",
            "1/2",
            "--out",
            "results/fe",
            "--force",
            "sweep.yaml",
        ],
        "a shard with --force",
    );
}
