//! Issue 23 point 1: the files a scene names are read only inside the scene
//! file's folder tree (after resolving symlinks) or a folder the user names
//! with `--data-dir`; a refusal names the path and the option and never
//! quotes a byte of the file.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

mod support;
use support::Scratch;

/// A secret outside every scene folder: no output may ever contain it.
const CANARY: &str = "CANARY-SECRET-8a41f2";

fn vbi(args: &[&str], cwd: &Path) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run vbi");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

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
