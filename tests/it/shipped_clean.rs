//! The shipped scenes are clean: `vbi check scenarios/*.yaml` accepts every
//! file and prints no warning the scene does not intend. A new warning on a
//! shipped scene either shows a scene that says something it does not mean
//! or a warning rule that fires on a legitimate scene: fix the one that is
//! wrong, or list the warning here with the reason it is intended.

use std::process::Command;

/// Warnings a shipped scene draws on purpose: (file, part of the message,
/// why).
const INTENDED: &[(&str, &str, &str)] = &[
    (
        "lcp-fig9-rail-car-fra.yaml",
        "is maintained for at most",
        "the LCP paper's Fig. 9 runs the rail car at 300 km/h over FRA classes 4-6, \
     far above their maintained speeds: the scene reproduces the paper, and the \
     warning tells a user who copies it that such track is not a 300 km/h line's",
    ),
    (
        "rail-fra5-oscillator.yaml",
        "is maintained for at most",
        "a quarter of the LCP paper's rail car at the paper's 300 km/h over FRA class 5, \
     as in its Monte Carlo study: the same paper setting, the same honest warning",
    ),
];

#[test]
fn vbi_check_on_the_shipped_scenes_prints_no_unintended_warning() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut files: Vec<String> = std::fs::read_dir(format!("{root}/scenarios"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .map(|p| p.strip_prefix(root).unwrap().display().to_string())
        .collect();
    files.sort();
    assert!(files.len() > 20, "{files:?}");
    let out = Command::new(env!("CARGO_BIN_EXE_vbi"))
        .arg("check")
        .args(&files)
        .current_dir(root)
        .output()
        .expect("run vbi");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(stdout.lines().count(), files.len(), "{stdout}");
    assert!(stdout.lines().all(|l| l.ends_with(": ok")), "{stdout}");
    let unintended: Vec<&str> = stderr
        .lines()
        .filter(|l| {
            !INTENDED
                .iter()
                .any(|(file, part, _)| l.contains(file) && l.contains(part))
        })
        .collect();
    assert!(
        unintended.is_empty(),
        "unintended output of `vbi check scenarios/*.yaml`:\n{}",
        unintended.join("\n")
    );
}
