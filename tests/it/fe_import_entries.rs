//! Imported matrices through the binary (issue 23): a repeated entry is
//! refused rather than summed (a duplicated line of the exported beam's K
//! took f₁ from 5.0 to 8.33 Hz without a word), in every format where one
//! can occur, and a symmetry error names its file, line and column — the
//! damping matrix's too.
//!
//! A Matrix Market `symmetric` file legally lists one triangle: (i, j) and
//! (j, i) in it are the same entry given twice. A `general` file lists both,
//! and (i, j) twice is a duplicate.

use crate::support::{Scratch, vbi};

const MM: &str = "%%MatrixMarket matrix coordinate real symmetric\n";
const GENERAL: &str = "%%MatrixMarket matrix coordinate real general\n";
/// Two DOFs, k = [[2, −1], [−1, 2]] MN/m, m = 100 kg each.
const K: &str = "2 2 3\n1 1 2.0e6\n2 1 -1.0e6\n2 2 2.0e6\n";
const M: &str = "2 2 2\n1 1 100.0\n2 2 100.0\n";

/// The same two-DOF stiffness as a fixed-width Harwell–Boeing file: column
/// pointers, row indices, then values (line 7).
fn hb(kind: &str, entries: usize, pointers: &str, indices: &str, values: &str) -> String {
    format!(
        "two DOFs{:64}KEY     \n{:>14}{:>14}{:>14}{:>14}{:>14}\n{kind}{:>25}{:>14}{:>14}{:>14}\n\
         {:<16}{:<16}{:<20}{:<20}\n{pointers}\n{indices}\n{values}\n",
        "", 3, 1, 1, 1, 0, 2, 2, entries, 0, "(4I8)", "(4I8)", "(4E10.3)", ""
    )
}

/// `vbi check` of a two-DOF model made of `files` (defaults: K.mtx, M.mtx,
/// dofs.csv, rail.csv); returns stderr, the exit code asserted 2.
fn refused(test: &str, files: &[(&str, &str)], bridge: &str) -> String {
    let scratch = Scratch::new("fe_import_entries", test);
    let defaults = [
        ("K.mtx", format!("{MM}{K}")),
        ("M.mtx", format!("{MM}{M}")),
        (
            "dofs.csv",
            "dof,node,direction\n1,1,uz\n2,2,uz\n".to_string(),
        ),
        ("rail.csv", "node,x\n1,0.0\n2,5.0\n".to_string()),
    ];
    for (name, text) in &defaults {
        std::fs::write(scratch.path(name), text).unwrap();
    }
    for (name, text) in files {
        std::fs::write(scratch.path(name), text).unwrap();
    }
    let scene = format!(
        "name: entries\nbridge:\n  type: fe_import\n{bridge}  rails: [{{name: rail, file: rail.csv}}]\n\
         vehicles: [{{type: moving_force, speed: 10.0, loads: [1.0e4]}}]\n"
    );
    std::fs::write(scratch.path("scene.yaml"), scene).unwrap();
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    let message = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{test}: {message}");
    assert!(!message.contains("panicked"), "{message}");
    message
}

/// A refused case: name, files replaced, the scene's bridge keys, and what
/// the message must say.
type Case<'a> = (&'a str, Vec<(&'a str, String)>, String, &'a str);

const FILES: &str = "  stiffness: K.mtx\n  mass: M.mtx\n  dof_map: dofs.csv\n";

#[test]
fn the_two_dof_model_itself_is_accepted() {
    // Every refusal below starts from these files, so it is its own defect's.
    let scratch = Scratch::new("fe_import_entries", "good");
    for (name, text) in [
        ("K.mtx", format!("{MM}{K}")),
        ("M.mtx", format!("{MM}{M}")),
        (
            "dofs.csv",
            "dof,node,direction\n1,1,uz\n2,2,uz\n".to_string(),
        ),
        ("rail.csv", "node,x\n1,0.0\n2,5.0\n".to_string()),
        (
            "K.hb",
            hb(
                "RSA",
                3,
                "       1       3       4",
                "       1       2       2",
                " 2.000E+06-1.000E+06 2.000E+06",
            ),
        ),
        (
            "K.abq",
            "1,3, 1,3, 2.0e6\n2,3, 1,3, -1.0e6\n2,3, 2,3, 2.0e6\n".to_string(),
        ),
        ("M.abq", "1,3, 1,3, 100.0\n2,3, 2,3, 100.0\n".to_string()),
    ] {
        std::fs::write(scratch.path(name), text).unwrap();
    }
    for (name, bridge) in [
        ("mtx", FILES.to_string()),
        ("hb", FILES.replace("K.mtx", "K.hb")),
        ("abaqus", "  stiffness: K.abq\n  mass: M.abq\n".to_string()),
    ] {
        let scene = format!(
            "name: entries\nbridge:\n  type: fe_import\n{bridge}  rails: [{{name: rail, file: rail.csv}}]\n\
             vehicles: [{{type: moving_force, speed: 10.0, loads: [1.0e4]}}]\n"
        );
        std::fs::write(scratch.path("scene.yaml"), scene).unwrap();
        let out = vbi(&["check", "scene.yaml"], scratch.dir());
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn repeated_entries_are_refused_with_both_lines() {
    let abaqus_m = "1,3, 1,3, 100.0\n2,3, 2,3, 100.0\n";
    let cases: Vec<Case<'_>> = vec![
        (
            "general_twice",
            vec![(
                "K.mtx",
                format!(
                    "{GENERAL}2 2 5\n1 1 2.0e6\n2 1 -1.0e6\n1 2 -1.0e6\n2 2 2.0e6\n1 1 2.0e6\n"
                ),
            )],
            FILES.into(),
            "K.mtx:7:1: entry (1, 1) (node 1 uz, node 1 uz) repeats entry (1, 1) of line 3: an assembled matrix lists each entry once",
        ),
        (
            "symmetric_both_triangles",
            vec![(
                "K.mtx",
                format!("{MM}2 2 4\n1 1 2.0e6\n2 1 -1.0e6\n1 2 -1.0e6\n2 2 2.0e6\n"),
            )],
            FILES.into(),
            "K.mtx:5:1: entry (1, 2) (node 1 uz, node 2 uz) repeats entry (2, 1) of line 4: the file holds one triangle",
        ),
        (
            "symmetric_twice",
            vec![(
                "M.mtx",
                format!("{MM}2 2 3\n1 1 100.0\n2 2 100.0\n2 2 100.0\n"),
            )],
            FILES.into(),
            "M.mtx:5:1: entry (2, 2) (node 2 uz, node 2 uz) repeats entry (2, 2) of line 4",
        ),
        (
            "harwell_boeing",
            vec![(
                "K.hb",
                hb(
                    "RSA",
                    3,
                    "       1       3       4",
                    "       1       1       2",
                    " 2.000E+06-1.000E+06 2.000E+06",
                ),
            )],
            FILES.replace("K.mtx", "K.hb"),
            "K.hb:7:11: entry (1, 1) (node 1 uz, node 1 uz) repeats entry (1, 1) of line 7",
        ),
        (
            "abaqus",
            vec![
                (
                    "K.abq",
                    "** K\n1,3, 1,3, 2.0e6\n2,3, 1,3, -1.0e6\n2,3, 2,3, 2.0e6\n2,3, 1,3, -1.0e6\n"
                        .into(),
                ),
                ("M.abq", abaqus_m.into()),
            ],
            "  stiffness: K.abq\n  mass: M.abq\n".into(),
            "K.abq:5:1: entry (2, 1) (node 2 uz, node 1 uz) repeats entry (2, 1) of line 3",
        ),
        (
            "abaqus_both_triangles",
            vec![
                (
                    "K.abq",
                    "1,3, 1,3, 2.0e6\n2,3, 1,3, -1.0e6\n1,3, 2,3, -1.0e6\n2,3, 2,3, 2.0e6\n".into(),
                ),
                ("M.abq", abaqus_m.into()),
            ],
            "  stiffness: K.abq\n  mass: M.abq\n".into(),
            "K.abq:3:1: entry (1, 2) (node 1 uz, node 2 uz) repeats entry (2, 1) of line 2: the file holds one triangle",
        ),
    ];
    let mut wrong = Vec::new();
    for (name, files, bridge, expected) in cases {
        let files: Vec<(&str, &str)> = files.iter().map(|(n, t)| (*n, t.as_str())).collect();
        let message = refused(name, &files, &bridge);
        if !message.contains(expected) {
            wrong.push(format!("{name}: no `{expected}` in\n{message}"));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn symmetry_errors_name_their_file_line_and_column() {
    let cases: Vec<Case<'_>> = vec![
        (
            "general",
            vec![(
                "K.mtx",
                format!("{GENERAL}2 2 4\n1 1 2.0e6\n2 1 -1.0e6\n1 2 -2.0e6\n2 2 2.0e6\n"),
            )],
            FILES.into(),
            "K.mtx:5:1: the matrix is not symmetric: entry (1, 2) = -2000000 but (2, 1) = -1000000 at line 4 (rows node 1 uz and node 2 uz)",
        ),
        (
            "general_absent",
            vec![(
                "K.mtx",
                format!("{GENERAL}2 2 3\n1 1 2.0e6\n2 1 -1.0e6\n2 2 2.0e6\n"),
            )],
            FILES.into(),
            "K.mtx:4:1: the matrix is not symmetric: entry (2, 1) = -1000000 but (1, 2) is absent (0)",
        ),
        (
            "harwell_boeing_rua",
            vec![(
                "K.hb",
                hb(
                    "RUA",
                    4,
                    "       1       3       5",
                    "       1       2       1       2",
                    " 2.000E+06-1.000E+06-2.000E+06 2.000E+06",
                ),
            )],
            FILES.replace("K.mtx", "K.hb"),
            "K.hb:7:21: the matrix is not symmetric: entry (1, 2) = -2000000 but (2, 1) = -1000000 at line 7",
        ),
        (
            "damping",
            vec![(
                "C.mtx",
                format!("{GENERAL}2 2 4\n1 1 2.0e3\n2 1 -1.0e3\n1 2 -2.0e3\n2 2 2.0e3\n"),
            )],
            format!("{FILES}  damping: {{type: matrix, file: C.mtx}}\n"),
            "C.mtx:5:1: the matrix is not symmetric: entry (1, 2) = -2000 but (2, 1) = -1000 at line 4",
        ),
    ];
    let mut wrong = Vec::new();
    for (name, files, bridge, expected) in cases {
        let files: Vec<(&str, &str)> = files.iter().map(|(n, t)| (*n, t.as_str())).collect();
        let message = refused(name, &files, &bridge);
        if !message.contains(expected) {
            wrong.push(format!("{name}: no `{expected}` in\n{message}"));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
