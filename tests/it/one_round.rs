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

/// One diagnostic a `tests/multi/NAME.expected` file asks for.
struct Expected {
    at: (usize, usize),
    /// A part of the message.
    message: String,
    /// Parts of its `help:` lines.
    helps: Vec<String>,
}

/// The diagnostics a `tests/multi/NAME.expected` file asks of its
/// `NAME.yaml`: `LINE:COL: part of the message` per diagnostic, each
/// followed by `  help: part of a help line` for each help it must give
/// (`#` comments).
fn expected(path: &std::path::Path) -> Vec<Expected> {
    let mut out: Vec<Expected> = Vec::new();
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    for l in text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
    {
        if let Some(help) = l.trim_start().strip_prefix("help: ") {
            let last = out
                .last_mut()
                .unwrap_or_else(|| panic!("{}: a help before any diagnostic", path.display()));
            last.helps.push(help.to_owned());
            continue;
        }
        let mut parts = l.splitn(3, ':');
        let mut number = || -> usize {
            parts
                .next()
                .and_then(|p| p.trim().parse().ok())
                .unwrap_or_else(|| panic!("{}: not `LINE:COL: message`: {l}", path.display()))
        };
        let at = (number(), number());
        let message = parts.next().unwrap_or_default().trim().to_owned();
        out.push(Expected {
            at,
            message,
            helps: Vec::new(),
        });
    }
    out
}

#[test]
fn every_multi_fixture_gives_its_every_diagnostic_in_one_check() {
    // Each `tests/multi/NAME.yaml` has several mistakes, and its
    // `NAME.expected` lists every one: one `vbi check` must report exactly
    // those (no mistake hidden by another, none repeated or invented), each
    // as `error: FILE:LINE:COL: message` with the help asked for, exit code
    // 2, no panic.
    let folder = manifest_dir().join("tests/multi");
    let mut fixtures: Vec<_> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    fixtures.sort();
    assert!(fixtures.len() >= 7, "{fixtures:?}");
    let mut failures = Vec::new();
    for yaml in &fixtures {
        let want = expected(&yaml.with_extension("expected"));
        let file = format!(
            "tests/multi/{}",
            yaml.file_name().unwrap().to_str().unwrap()
        );
        let out = vbi(&["check", &file], manifest_dir());
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{file}:\n{stderr}");
        assert!(!stderr.contains("panicked"), "{file}:\n{stderr}");
        let mut got = located(&stderr, &file);
        got.sort();
        let mut at: Vec<_> = want.iter().map(|w| w.at).collect();
        at.sort();
        if got != at {
            failures.push(format!(
                "{file}: located {got:?}, expected {at:?}\n{stderr}"
            ));
            continue;
        }
        // Each diagnostic's block: its head line to the next `error: `.
        let lines: Vec<&str> = stderr.lines().collect();
        for w in &want {
            let head = format!("error: {file}:{}:{}: ", w.at.0, w.at.1);
            let Some(start) = lines
                .iter()
                .position(|l| l.starts_with(&head) && l.contains(w.message.as_str()))
            else {
                failures.push(format!("{file}: no `{head}…{}…` in\n{stderr}", w.message));
                continue;
            };
            let end = lines[start + 1..]
                .iter()
                .position(|l| l.starts_with("error: "))
                .map_or(lines.len(), |i| start + 1 + i);
            for help in &w.helps {
                let given = lines[start..end]
                    .iter()
                    .any(|l| l.trim_start().starts_with("= help: ") && l.contains(help.as_str()));
                if !given {
                    failures.push(format!(
                        "{file}: `{head}` has no help `{help}` in\n{stderr}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
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

#[test]
fn a_bridge_that_does_not_parse_hides_no_other_section_s_errors() {
    // `bridge` is required: when it fails to parse, the vehicles, solver
    // and records are still checked (without the bridge), so that the
    // file's every error comes in this one `vbi check`.
    let file = "tests/multi/bridge-type-error.yaml";
    let out = vbi(&["check", file], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let mut got = located(&stderr, file);
    got.sort();
    // Line and column of each mistake, as the comments in the file say.
    let want = vec![
        (8, 22),  // bending_stiffness: stiff (type)
        (12, 18), // sprung mass −5750 kg (semantic)
        (17, 21), // time step −0.001 s (semantic)
        (19, 59), // vehicle 3 of one (cross-field, needs no bridge)
        (20, 76), // max_frequency on a displacement (semantic)
    ];
    assert_eq!(got, want, "{stderr}");
    for message in [
        "sprung mass must be positive",
        "time step must be positive",
        "vehicle 3 does not exist",
        "`max_frequency` is not used by `bridge_displacement`",
    ] {
        assert!(stderr.contains(message), "no `{message}` in\n{stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_bridge_with_an_error_of_its_own_still_lets_the_records_be_checked() {
    // The bridge parses but is invalid (a negative span): the records are
    // checked against the vehicles alone, in the same round.
    let scratch = crate::support::Scratch::new("one_round", "bridge-semantic");
    let path = scratch.path("scene.yaml");
    std::fs::write(
        &path,
        "name: bridge-semantic
bridge: {type: beam, spans: [-32.0], bending_stiffness: 1.3e10, mass_per_length: 12000.0}
vehicles: [{type: moving_force, loads: [1.0e5], speed: 20.0}]
record:
  - {name: deck, quantity: bridge_displacement, x: 16.0, dof: body_bounce}
  - {name: body, quantity: vehicle_displacement, vehicle: 2, dof: body_bounce}
",
    )
    .unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let file = path.display().to_string();
    let mut got = located(&stderr, &file);
    got.sort();
    // The span, `dof` on a bridge quantity, vehicle 2 of one.
    assert_eq!(got, vec![(2, 30), (5, 63), (6, 59)], "{stderr}");
    for message in [
        "a span length must be positive, got -32",
        "`dof` is not used by `bridge_displacement`",
        "vehicle 2 does not exist; the scene has only vehicle 1",
    ] {
        assert!(stderr.contains(message), "no `{message}` in\n{stderr}");
    }
}

#[test]
fn vehicles_that_do_not_parse_hide_no_solver_error() {
    // `vehicles` written as a mapping, not a list: a type error; the
    // solver is still checked in the same round (the records, numbered
    // against a vehicle list that is not there, are not).
    let scratch = crate::support::Scratch::new("one_round", "vehicles-mapping");
    let path = scratch.path("scene.yaml");
    std::fs::write(
        &path,
        "name: vehicles-mapping
bridge: {type: beam, spans: [32.0], bending_stiffness: 1.3e10, mass_per_length: 12000.0}
vehicles: {type: moving_force, loads: [1.0e5], speed: 20.0}
solver: {time_step: -1.0}
",
    )
    .unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let mut got = located(&stderr, &path.display().to_string());
    got.sort();
    assert_eq!(got, vec![(3, 11), (4, 21)], "{stderr}");
    assert!(
        stderr.contains("invalid type: map, expected a sequence"),
        "{stderr}"
    );
    assert!(
        stderr.contains("time step must be positive, got -1"),
        "{stderr}"
    );
}
