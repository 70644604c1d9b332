//! `resolved.yaml` reruns as it is, from any folder and without flags
//! (issue 38, point 7): it names its data files by absolute path and pins
//! each with the SHA-256 of the bytes the original run read (`# Read:`
//! header lines). A pinned file is read only as those bytes; a changed or
//! missing one is refused with one message that shows nothing of it; and a
//! scene without pins is confined as before.
//!
//! The scene: `examples/seismic-crossing.yaml` (a rail car over a 32 m span
//! during the shipped synthetic AT2 record), copied with its record into a
//! scratch folder.

use crate::support::{Scratch, assert_exit, manifest_dir, text, vbi};
use std::path::Path;

/// Copies the seismic example and its record into `dir/scene/`; returns the
/// scene file.
fn copy_example(dir: &Path) -> std::path::PathBuf {
    let scene = dir.join("scene");
    std::fs::create_dir_all(scene.join("records")).unwrap();
    let examples = manifest_dir().join("examples");
    std::fs::copy(
        examples.join("seismic-crossing.yaml"),
        scene.join("seismic-crossing.yaml"),
    )
    .unwrap();
    std::fs::copy(
        examples.join("records/synthetic-vertical.AT2"),
        scene.join("records/synthetic-vertical.AT2"),
    )
    .unwrap();
    scene.join("seismic-crossing.yaml")
}

/// Runs the copied example into `scene/results/first` and returns that
/// folder.
fn first_run(dir: &Path) -> std::path::PathBuf {
    let file = copy_example(dir);
    let out = dir.join("scene/results/first");
    let run = vbi(
        &[
            "run".as_ref(),
            file.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
            "-q".as_ref(),
        ],
        dir,
    );
    assert_exit(&run, 0);
    out
}

#[test]
fn resolved_yaml_reruns_from_another_folder_with_the_same_history() {
    let scratch = Scratch::new("it", "resolved_anywhere_rerun");
    let first = first_run(scratch.dir());
    let resolved = std::fs::read_to_string(first.join("resolved.yaml")).unwrap();
    let record = scratch.path("scene/records/synthetic-vertical.AT2");
    let bytes = std::fs::read(&record).unwrap();
    let pin = format!(
        "# Read: sha256:{} {}",
        vbi::scenario::data_files::sha256_hex(&bytes),
        std::path::absolute(&record).unwrap().display()
    );
    assert!(
        resolved.lines().take(4).any(|l| l == pin),
        "resolved.yaml's header pins the record it read ({pin}):\n{}",
        &resolved[..600.min(resolved.len())]
    );
    // From an unrelated folder, no flags but the output folder.
    let elsewhere = scratch.path("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    let resolved_file = first.join("resolved.yaml");
    let again = vbi(
        &[
            "run".as_ref(),
            resolved_file.as_os_str(),
            "--out".as_ref(),
            "out".as_ref(),
            "-q".as_ref(),
        ],
        &elsewhere,
    );
    assert_exit(&again, 0);
    assert_eq!(
        std::fs::read(first.join("history.csv")).unwrap(),
        std::fs::read(elsewhere.join("out/history.csv")).unwrap(),
        "the rerun's history is the original's, byte for byte"
    );
    // Into its own folder too: the rerun is the same scene's, not another's.
    let in_place = vbi(
        &[
            "run".as_ref(),
            resolved_file.as_os_str(),
            "--out".as_ref(),
            first.as_os_str(),
            "-q".as_ref(),
        ],
        &elsewhere,
    );
    assert_exit(&in_place, 0);
}

#[test]
fn a_changed_pinned_file_is_refused_without_its_content() {
    let scratch = Scratch::new("it", "resolved_anywhere_changed");
    let first = first_run(scratch.dir());
    let record = scratch.path("scene/records/synthetic-vertical.AT2");
    let mut bytes = std::fs::read(&record).unwrap();
    // One sample's digit changed: a record that still parses.
    let at = bytes.iter().rposition(u8::is_ascii_digit).unwrap();
    bytes[at] = if bytes[at] == b'1' { b'2' } else { b'1' };
    std::fs::write(&record, &bytes).unwrap();
    let resolved_file = first.join("resolved.yaml");
    let out = scratch.path("out");
    let changed = vbi(
        &[
            "run".as_ref(),
            resolved_file.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
        ],
        scratch.dir(),
    );
    assert_exit(&changed, 2);
    let stderr = text(&changed.stderr);
    assert!(
        stderr.contains("is not the file this scene's run read"),
        "{stderr}"
    );
    // Missing reads the same: whether a pinned file exists is not told.
    std::fs::remove_file(&record).unwrap();
    let missing = vbi(
        &[
            "run".as_ref(),
            resolved_file.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
        ],
        scratch.dir(),
    );
    assert_exit(&missing, 2);
    assert_eq!(
        text(&missing.stderr).lines().next(),
        stderr.lines().next(),
        "a missing pinned file gets the changed one's message"
    );
}

/// A stranger's scene that pins a file outside its folder with a hash it
/// guessed is refused, shows nothing of the file, and says the same whether
/// the file exists; a pin below the header, or for another path, lets
/// nothing through, and without a pin the path is confined as before.
#[test]
fn a_pin_with_the_wrong_hash_discloses_nothing() {
    let scratch = Scratch::new("it", "resolved_anywhere_forged");
    let secret = scratch.path("private/secret.AT2");
    std::fs::create_dir_all(secret.parent().unwrap()).unwrap();
    std::fs::write(&secret, "CANARY-SECRET-7f3a\n1 0.01\n0.5\n").unwrap();
    let secret = std::path::absolute(&secret).unwrap();
    let missing = std::path::absolute(scratch.path("private/none.AT2")).unwrap();
    let scene_dir = scratch.path("stranger");
    std::fs::create_dir_all(&scene_dir).unwrap();
    let scene = |pinned: &Path, named: &Path, header: bool| {
        let pin = format!("# Read: sha256:{} {}\n", "0".repeat(64), pinned.display());
        let body = format!(
            "name: forged
bridge: {{type: beam, spans: [20.0], bending_stiffness: 3.0e9, mass_per_length: 2000.0}}
vehicles: [{{type: moving_force, loads: [100.0e3], speed: 20.0}}]
ground_motion:
  - {{direction: vertical, file: \"{}\"}}
",
            named.display()
        );
        if header {
            format!("{pin}{body}")
        } else {
            format!("{body}{pin}")
        }
    };
    let run = |yaml: &str| {
        let file = scene_dir.join("forged.yaml");
        std::fs::write(&file, yaml).unwrap();
        let out = vbi(&["check".as_ref(), file.as_os_str()], &scene_dir);
        assert_exit(&out, 2);
        let stderr = text(&out.stderr);
        assert!(
            !stderr.contains("CANARY"),
            "the file's content is shown: {stderr}"
        );
        stderr
    };
    let existing = run(&scene(&secret, &secret, true));
    assert!(
        existing.contains("is not the file this scene's run read"),
        "{existing}"
    );
    let absent = run(&scene(&missing, &missing, true));
    assert_eq!(
        existing
            .lines()
            .next()
            .unwrap()
            .replace(&secret.display().to_string(), "X"),
        absent
            .lines()
            .next()
            .unwrap()
            .replace(&missing.display().to_string(), "X"),
        "an existing and a missing file read the same"
    );
    for (yaml, why) in [
        (scene(&secret, &secret, false), "a pin below the header"),
        (scene(&missing, &secret, true), "a pin for another path"),
    ] {
        let stderr = run(&yaml);
        assert!(
            stderr.contains("is an absolute path; a scene reads files only inside"),
            "{why}: the path is confined as without a pin: {stderr}"
        );
    }
}
