//! Independent reference solutions shared by the physics tests, and the
//! small helpers those tests share for running scenes and reading results.

#![allow(dead_code)] // each test module uses its own subset

pub mod event_reference;
pub mod impact_reference;
pub mod multi_reference;
pub mod plate_fe;
pub mod reference;
pub mod vehicle_reference;

use std::path::{Path, PathBuf};

use vbi::plan::load_str;
use vbi::run::{Outcome, simulate};

/// The repository root (where Cargo.toml is).
pub fn manifest_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the `vbi` binary with `args` in `cwd`.
pub fn vbi<S: AsRef<std::ffi::OsStr>>(args: &[S], cwd: &Path) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run vbi")
}

/// Runs the `vbi` binary with `args` in the test's own working directory
/// (cargo runs tests in the repository root).
pub fn vbi_here<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .output()
        .expect("run vbi")
}

/// [`vbi`], its exit code and its two streams as text.
pub fn vbi_streams<S: AsRef<std::ffi::OsStr>>(
    args: &[S],
    cwd: &Path,
) -> (Option<i32>, String, String) {
    let out = vbi(args, cwd);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// A command's output as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The command exited with `code` and did not panic (its streams shown if not).
pub fn assert_exit(out: &std::process::Output, code: i32) {
    assert_eq!(
        out.status.code(),
        Some(code),
        "stdout:\n{}\nstderr:\n{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(!text(&out.stderr).contains("panicked"));
}

/// Loads and runs a scene given as YAML text, panicking with the error.
pub fn run_yaml(yaml: &str) -> Outcome {
    let loaded = load_str(yaml, "test.yaml").unwrap_or_else(|e| panic!("{e}"));
    simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// The recorded history named `name`.
pub fn column<'a>(outcome: &'a Outcome, name: &str) -> &'a [f64] {
    &outcome
        .history
        .columns
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no column {name}"))
        .values
}

/// Largest absolute value (of a slice or of any iterator of values).
pub fn max_abs<T: std::borrow::Borrow<f64>>(values: impl IntoIterator<Item = T>) -> f64 {
    values.into_iter().fold(0.0, |m, v| m.max(v.borrow().abs()))
}

/// Largest absolute value of the finite values (NaN and ±∞ skipped).
pub fn max_abs_finite(values: &[f64]) -> f64 {
    values
        .iter()
        .filter(|v| v.is_finite())
        .fold(0.0, |m, v| m.max(v.abs()))
}

/// Asserts that the histories `names` of two runs agree everywhere to
/// `tolerance` × the peak |value| of `reference`'s history.
pub fn assert_histories_agree(run: &Outcome, reference: &Outcome, names: &[&str], tolerance: f64) {
    for name in names {
        let (a, b) = (column(run, name), column(reference, name));
        let peak = max_abs(b);
        let worst = a
            .iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        eprintln!("{name}: differs by {:.2e} of its peak", worst / peak);
        assert!(
            worst <= tolerance * peak,
            "{name}: differs by {worst} against a peak of {peak}"
        );
    }
}

/// A scratch folder under the system temp dir, unique per process, test
/// binary and test, removed on drop.
pub struct Scratch(PathBuf);

impl Scratch {
    /// Creates the empty folder for `test` of the test binary `binary`.
    pub fn new(binary: &str, test: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("vbi-{binary}-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create scratch dir");
        Scratch(dir)
    }

    /// The folder.
    pub fn dir(&self) -> &Path {
        &self.0
    }

    /// The path of `name` inside the folder.
    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// The names of the folder's entries, sorted.
    pub fn entries(&self) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(&self.0)
            .expect("read scratch dir")
            .map(|e| {
                e.expect("dir entry")
                    .file_name()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect();
        names.sort();
        names
    }
}

/// A scratch folder like [`Scratch`]'s (`vbi-<binary>-<pid>-<test>` under
/// the system temp dir, emptied first) that is kept after the test.
pub fn scratch_dir(binary: &str, test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("vbi-{binary}-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create scratch dir");
    dir
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs `f` in a rayon pool of `threads` threads, or in the global pool
/// when `None`.
pub fn on_threads<T: Send>(threads: Option<usize>, f: impl FnOnce() -> T + Send) -> T {
    match threads {
        None => f(),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("pool")
            .install(f),
    }
}
