//! Every diagnostic of a file in one round (issue 28.1): type errors
//! (unknown keys, wrong types, unknown enum values), semantic errors (a
//! value out of its range) and cross-field errors (a record point off the
//! bridge, a DOF the vehicle lacks) are reported together, each located,
//! with a "did you mean" for a misspelt key, enum value or DOF name.

use crate::support::{manifest_dir, text, vbi};

/// The `FILE:LINE:COL: ` heads of the diagnostics about `file` in `stderr`.
fn located(stderr: &str, file: &str) -> Vec<(usize, usize)> {
    stderr
        .lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("error: ").unwrap_or(l);
            let rest = rest.strip_prefix(file)?.strip_prefix(':')?;
            let mut parts = rest.splitn(3, ':');
            let line = parts.next()?.parse().ok()?;
            let col = parts.next()?.parse().ok()?;
            Some((line, col))
        })
        .collect()
}

#[test]
fn seven_mistakes_give_seven_located_diagnostics_in_one_check() {
    let file = "tests/multi/seven-mistakes.yaml";
    let out = vbi(&["check", file], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let mut got = located(&stderr, file);
    got.sort();
    // Line and column of each mistake, as the comments in the file say.
    let want = vec![
        (13, 18), // car_spacing 15 m < the car's 20 m wheelset span (semantic)
        (14, 29), // FRA class 7 (semantic)
        (15, 26), // `stifness` (unknown key)
        (16, 26), // free_vibration: long (wrong type)
        (18, 31), // `bridge_displacment` (unknown enum value)
        (19, 62), // x = 62.5 m off a 32 m bridge (cross-field)
        (20, 63), // `body_bouncee` (unknown DOF, cross-field)
    ];
    assert_eq!(got, want, "{stderr}");
    for help in [
        "help: did you mean `stiffness`?",
        "help: did you mean `bridge_displacement`?",
        "help: did you mean `body_bounce`?",
    ] {
        assert!(stderr.contains(help), "no `{help}` in\n{stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
}
