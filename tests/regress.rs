//! `vbi regress` end to end through the binary (issue 30): approve then
//! check passes; a 0.1 % stiffness change fails naming the quantity; a
//! 1e-13 relative change passes; a study's table change is caught; a scene
//! edit is reported as such; the JUnit XML has the structure CI tools read;
//! the example CI workflow's command lines run as written.

mod support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use support::Scratch;

fn manifest_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn vbi<S: AsRef<std::ffi::OsStr>>(args: &[S], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run vbi")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn assert_exit(out: &Output, code: i32) {
    assert_eq!(
        out.status.code(),
        Some(code),
        "stdout:\n{}\nstderr:\n{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(!text(&out.stderr).contains("panicked"));
}

/// A shipped scene copied into the scratch folder.
fn copy_scene(dir: &Scratch, name: &str) -> PathBuf {
    let src = std::fs::read_to_string(manifest_dir().join("scenarios").join(name))
        .expect("read scenario");
    let path = dir.path(name);
    std::fs::write(&path, src).expect("write scenario");
    path
}

#[test]
fn approve_then_check_passes() {
    let dir = Scratch::new("regress", "approve_then_check");
    let scene = copy_scene(&dir, "moving-force-slow.yaml");
    let store = dir.path("golden");
    let out = vbi(
        &["regress".as_ref(), "approve".as_ref(), scene.as_os_str(), "--store".as_ref(), store.as_os_str()],
        dir.dir(),
    );
    assert_exit(&out, 0);
    let out = vbi(
        &["regress".as_ref(), "check".as_ref(), scene.as_os_str(), "--store".as_ref(), store.as_os_str()],
        dir.dir(),
    );
    assert_exit(&out, 0);
    assert!(text(&out.stdout).contains("pass"), "{}", text(&out.stdout));
}
