//! Imported FE models through the binary: the sign convention of the
//! rotation DOFs (a textbook beam's θ = +∂w/∂x labelled `ry` must not run
//! silently as this program's right-handed ry = −∂w/∂x), duplicated
//! entries, and symmetry errors located at their file's line.
//!
//! The reference model is `vbi export beam` of a `type: beam` scene (its
//! Hermite elements are checked against closed forms in tests/it/physics.rs;
//! tests/it/fe_import.rs checks the export against the beam to 1e-8). The
//! textbook convention is made from it by flipping the sign of every matrix
//! entry with exactly one ry index, which is exactly the change of variable
//! θ = −ry: its runs must equal the export's bit for bit once declared.

use std::path::Path;

use crate::support::{Scratch, assert_exit, vbi};
use std::process::Output;

use vbi::scenario::fe_import::{abaqus, harwell_boeing};
use vbi::scene::imported::Direction;

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A 20 m simply supported beam (the LCP paper's Fig. 4 bridge, 10
/// elements) crossed by the moving oscillator with rigid contact.
const BEAM_SCENE: &str = "name: rotations
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2423e9
  mass_per_length: 2000.0
  elements_per_span: 10
  modes: {count: 8}
  damping: {type: modal, ratio: 0.02}
vehicles:
  - type: oscillator
    dimensionless: {velocity_ratio: 0.3, mass_ratio: 1.0, unsprung_ratio: 0.25, frequency_ratio: 0.5, damping_ratio: 0.1}
contact: {type: rigid}
solver: {time_step: 2.0e-4, free_vibration: 0.05}
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
  - {name: midspan_acc, quantity: bridge_acceleration, x: 10.0}
  - {name: contact_force, quantity: contact_force}
";

/// `vbi export beam` of [`BEAM_SCENE`] into `dir`.
fn export(dir: &Path) {
    std::fs::write(dir.join("beam.yaml"), BEAM_SCENE).unwrap();
    let out = vbi(&["export", "beam", "beam.yaml", "--out", "export"], dir);
    assert_exit(&out, 0);
}

/// The 1-based rows of `dofs.csv` that are rotations about y.
fn ry_rows(dofs_csv: &str) -> Vec<usize> {
    dofs_csv
        .lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[2].trim() == "ry").then(|| f[0].parse().unwrap())
        })
        .collect()
}

/// A Matrix Market file with the sign of every entry with exactly one
/// index in `rotations` flipped: θ = −ry, the textbook convention.
fn flip_rotations(mtx: &str, rotations: &[usize]) -> String {
    let mut out = String::new();
    let mut sized = false;
    for line in mtx.lines() {
        if line.starts_with('%') || !sized {
            sized |= !line.starts_with('%');
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        let (r, c): (usize, usize) = (f[0].parse().unwrap(), f[1].parse().unwrap());
        let v = if rotations.contains(&r) != rotations.contains(&c) {
            f[2].strip_prefix('-')
                .map_or_else(|| format!("-{}", f[2]), str::to_string)
        } else {
            f[2].to_string()
        };
        out.push_str(&format!("{r} {c} {v}\n"));
    }
    out
}

/// The lower triangle (0-based) of a Matrix Market file.
fn entries(mtx: &str) -> (usize, Vec<(usize, usize, f64)>) {
    let mut lines = mtx.lines().filter(|l| !l.starts_with('%'));
    let order = lines.next().unwrap().split_whitespace().next().unwrap();
    let lower = lines
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            let index = |k: usize| f[k].parse::<usize>().unwrap() - 1;
            (index(0), index(1), f[2].parse().unwrap())
        })
        .collect();
    (order.parse().unwrap(), lower)
}

/// The exported beam's (node, direction) per row: uz, ry of node 1, 2, …
fn beam_dofs(order: usize) -> Vec<(u64, Direction)> {
    (0..order)
        .map(|i| {
            let d = [Direction::Uz, Direction::Ry][i % 2];
            (i as u64 / 2 + 1, d)
        })
        .collect()
}

/// The matrix formats a scene can read, with the export's K and M written
/// in textbook convention: (label, K file, M file, dof_map, files).
fn textbook_formats(export: &Path) -> Vec<(&'static str, String, String, Option<String>)> {
    let rows = ry_rows(&std::fs::read_to_string(export.join("dofs.csv")).unwrap());
    let mut formats = Vec::new();
    let mut mapping = String::from(" Matrix Eqn   Node   DOF\n");
    for name in ["K", "M"] {
        let text = std::fs::read_to_string(export.join(format!("{name}.mtx"))).unwrap();
        let slope = flip_rotations(&text, &rows);
        std::fs::write(export.join(format!("{name}-slope.mtx")), &slope).unwrap();
        let (order, lower) = entries(&slope);
        // General: both triangles written.
        let mut general = format!(
            "%%MatrixMarket matrix coordinate real general\n{order} {order} {}\n",
            lower
                .iter()
                .map(|e| if e.0 == e.1 { 1 } else { 2 })
                .sum::<usize>()
        );
        for &(r, c, v) in &lower {
            general.push_str(&format!("{} {} {v:e}\n", r + 1, c + 1));
            if r != c {
                general.push_str(&format!("{} {} {v:e}\n", c + 1, r + 1));
            }
        }
        std::fs::write(export.join(format!("{name}-slope-general.mtx")), general).unwrap();
        let dofs = beam_dofs(order);
        std::fs::write(
            export.join(format!("{name}-slope.abq")),
            abaqus::write_symmetric(&dofs, &lower),
        )
        .unwrap();
        std::fs::write(
            export.join(format!("{name}-slope.hb")),
            harwell_boeing::write_symmetric(order, &lower, "textbook beam"),
        )
        .unwrap();
        if name == "K" {
            for (i, (node, d)) in dofs.iter().enumerate() {
                let label = if *d == Direction::Uz { "UZ" } else { "ROTY" };
                mapping.push_str(&format!("{:>8}{:>8}{:>8}\n", i + 1, node, label));
            }
        }
    }
    std::fs::write(export.join("slope.mapping"), mapping).unwrap();
    for (label, k, m, map) in [
        ("mtx", "K-slope.mtx", "M-slope.mtx", Some("dofs.csv")),
        (
            "general",
            "K-slope-general.mtx",
            "M-slope-general.mtx",
            Some("dofs.csv"),
        ),
        ("abaqus", "K-slope.abq", "M-slope.abq", None),
        ("hb", "K-slope.hb", "M-slope.hb", Some("slope.mapping")),
    ] {
        formats.push((label, k.to_string(), m.to_string(), map.map(str::to_string)));
    }
    formats
}

/// The export's scene on other files, with `extra` lines added to its
/// bridge; returns its text and the line of the bridge's first key.
fn scene_on(export: &Path, k: &str, m: &str, map: Option<&str>, extra: &str) -> (String, usize) {
    let scene = std::fs::read_to_string(export.join("scenario.yaml")).unwrap();
    let mut scene = scene
        .replace("\"K.mtx\"", &format!("\"{k}\""))
        .replace("\"M.mtx\"", &format!("\"{m}\""))
        .replace(
            "  type: \"fe_import\"\n",
            &format!("  type: \"fe_import\"\n{extra}"),
        );
    match map {
        Some(map) => scene = scene.replace("\"dofs.csv\"", &format!("\"{map}\"")),
        None => scene = scene.replace("  dof_map: \"dofs.csv\"\n", ""),
    }
    assert!(scene.contains(k), "{scene}");
    let line = scene
        .lines()
        .position(|l| l.starts_with("  type: \"fe_import\""))
        .unwrap()
        + 1;
    (scene, line)
}

/// `vbi check` of `scene` written as `name` into `dir`.
fn check(dir: &Path, name: &str, scene: &str) -> Output {
    std::fs::write(dir.join(name), scene).unwrap();
    vbi(&["check", name], dir)
}

#[test]
fn a_textbook_rotation_convention_is_refused_in_every_format() {
    let scratch = Scratch::new("fe_import_rotations", "refused");
    export(scratch.dir());
    let export = scratch.path("export");
    // The export itself is in the program's convention: accepted.
    assert_exit(&vbi(&["check", "scenario.yaml"], &export), 0);
    for (label, k, m, map) in textbook_formats(&export) {
        let (scene, line) = scene_on(&export, &k, &m, map.as_deref(), "");
        let out = check(&export, &format!("{label}.yaml"), &scene);
        assert_exit(&out, 2);
        let message = stderr(&out);
        // At the bridge, where `rotation_sign` belongs; the convention, the
        // evidence (8 of the 10 segments: the two at the supports have a
        // fixed uz) and the fix.
        for expected in [
            format!("{label}.yaml:{line}:3: "),
            "the stiffness says ∂w/∂x = +ry (a textbook beam's θ) on 8 of its 10 segments".into(),
            "the scene reads ∂w/∂x = −ry".into(),
            "= +1.000 as read, where a beam element joining them gives exactly −1".into(),
            "declare `rotation_sign: {ry: -1}` under `bridge`".into(),
        ] {
            assert!(
                message.contains(&expected),
                "{label}: no `{expected}` in\n{message}"
            );
        }
        // Declared, the same files are accepted.
        let (scene, _) = scene_on(
            &export,
            &k,
            &m,
            map.as_deref(),
            "  rotation_sign: {ry: -1}\n",
        );
        assert_exit(
            &check(&export, &format!("{label}-declared.yaml"), &scene),
            0,
        );
    }
}

/// The columns of a `history.csv`: (names, rows).
fn history(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let names = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (names, rows)
}

#[test]
fn declared_textbook_rotations_run_as_the_export_bit_for_bit() {
    let scratch = Scratch::new("fe_import_rotations", "runs");
    export(scratch.dir());
    let export = scratch.path("export");
    let formats = textbook_formats(&export);
    let (label, k, m, map) = &formats[0];
    assert_eq!(*label, "mtx");
    let (scene, _) = scene_on(&export, k, m, map.as_deref(), "  rotation_sign: {ry: -1}\n");
    std::fs::write(export.join("declared.yaml"), scene).unwrap();
    let run = |scene: &str, out: &str, cwd: &Path| {
        let o = vbi(
            &["run", scene, "--out", out, "--quiet", "--no-modes-cache"],
            cwd,
        );
        assert_exit(&o, 0);
        std::fs::read(cwd.join(out).join("history.csv")).unwrap()
    };
    // θ = −ry is an exact change of variable (a sign flip of the entries
    // with one ry index, undone on reading): the same numbers bit for bit.
    let declared = run("declared.yaml", "declared", &export);
    let exported = run("scenario.yaml", "exported", &export);
    assert!(
        declared == exported,
        "the declared textbook import differs from the export"
    );
    // And the beam scene itself: the export reads the beam's element
    // matrices from shortest round-trip decimals and solves another
    // eigenproblem path, so the histories agree to round-off: measured
    // 5e-13 (midspan displacement), 3e-11 (contact force) and 5e-11
    // (midspan acceleration) of each column's peak on this crossing; bound
    // 3e-10.
    run("beam.yaml", "beam", scratch.dir());
    let (names, beam) = history(&scratch.path("beam/history.csv"));
    let (names_imported, imported) = history(&export.join("declared/history.csv"));
    assert_eq!(names, names_imported);
    assert_eq!(beam.len(), imported.len());
    for j in 1..names.len() {
        let peak = beam.iter().fold(0.0f64, |a, r| a.max(r[j].abs()));
        let worst = beam
            .iter()
            .zip(&imported)
            .fold(0.0f64, |a, (x, y)| a.max((x[j] - y[j]).abs()));
        assert!(
            worst <= 3e-10 * peak,
            "{}: {worst} against peak {peak}",
            names[j]
        );
    }
}

#[test]
fn a_sign_the_stiffness_contradicts_is_refused_at_the_option() {
    let scratch = Scratch::new("fe_import_rotations", "option");
    export(scratch.dir());
    let export = scratch.path("export");
    let (scene, line) = scene_on(
        &export,
        "K.mtx",
        "M.mtx",
        Some("dofs.csv"),
        "  rotation_sign: {ry: -1}\n",
    );
    let out = check(&export, "wrong.yaml", &scene);
    assert_exit(&out, 2);
    let message = stderr(&out);
    // `  rotation_sign: {ry: -1}`: the value at column 23 of the line after `type`.
    let at = format!("wrong.yaml:{}:23: ", line + 1);
    for expected in [
        at.as_str(),
        "the stiffness says ∂w/∂x = −ry on 8 of its 10 segments",
        "but the scene reads ∂w/∂x = +ry (with `rotation_sign: {ry: -1}`)",
        "Fix: remove `rotation_sign`",
    ] {
        assert!(message.contains(expected), "no `{expected}` in\n{message}");
    }
    let (scene, _) = scene_on(
        &export,
        "K.mtx",
        "M.mtx",
        Some("dofs.csv"),
        "  rotation_sign: {ry: 2}\n",
    );
    let out = check(&export, "two.yaml", &scene);
    assert_exit(&out, 2);
    let message = stderr(&out);
    assert!(
        message.contains(&format!(
            "two.yaml:{}:23: a rotation's sign is -1 or 1, got 2",
            line + 1
        )),
        "{message}"
    );
}

/// Flips the sign of every entry of a Matrix Market file with exactly one
/// index among the `direction` rows of a `dof,node,direction` map.
fn flip_direction(dir: &Path, matrix: &str, direction: &str) -> String {
    let map = std::fs::read_to_string(dir.join("dof_map.csv")).unwrap();
    let rows: Vec<usize> = map
        .lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[2].trim() == direction).then(|| f[0].parse().unwrap())
        })
        .collect();
    let name = format!("{matrix}-{direction}.mtx");
    let text = std::fs::read_to_string(dir.join(format!("{matrix}.mtx"))).unwrap();
    let mut rows_sorted = rows;
    rows_sorted.sort_unstable();
    let flipped = flip_sorted(&text, &rows_sorted);
    std::fs::write(dir.join(&name), flipped).unwrap();
    name
}

/// [`flip_rotations`] with a binary search (the viaduct has hundreds of rows).
fn flip_sorted(mtx: &str, sorted: &[usize]) -> String {
    let mut out = String::new();
    let mut sized = false;
    for line in mtx.lines() {
        if line.starts_with('%') || !sized {
            sized |= !line.starts_with('%');
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        let (r, c): (usize, usize) = (f[0].parse().unwrap(), f[1].parse().unwrap());
        let one = sorted.binary_search(&r).is_ok() != sorted.binary_search(&c).is_ok();
        let v = match (one, f[2].strip_prefix('-')) {
            (false, _) => f[2].to_string(),
            (true, Some(positive)) => positive.to_string(),
            (true, None) => format!("-{}", f[2]),
        };
        out.push_str(&format!("{r} {c} {v}\n"));
    }
    out
}

#[test]
fn a_generated_viaduct_passes_and_its_flipped_rotations_are_refused() {
    // A 3D model: rails as 3D frames on pads, sleepers, ballast springs and
    // a deck on bearings. Its rails' segments give σ̂ = ±1.000 in both
    // planes, so its ry and rz are each checked against the stiffness.
    let scratch = Scratch::new("fe_import_rotations", "viaduct");
    let out = vbi(
        &[
            "generate",
            "viaduct",
            "--spans",
            "1",
            "--span-length",
            "10",
            "--approach-length",
            "3",
            "--out",
            "via",
        ],
        scratch.dir(),
    );
    assert_exit(&out, 0);
    let dir = scratch.path("via");
    let scene = |k: &str, m: &str, extra: &str| {
        format!(
            "name: via\nbridge:\n  type: fe_import\n{extra}  stiffness: {k}\n  mass: {m}\n  dof_map: dof_map.csv\n  \
             rails: [{{name: left, file: rail_left.csv}}, {{name: right, file: rail_right.csv}}]\n  \
             modes: {{count: 4}}\nvehicles: [{{type: moving_force, speed: 10.0, loads: [1.0e4]}}]\n"
        )
    };
    assert_exit(
        &check(&dir, "as-written.yaml", &scene("K.mtx", "M.mtx", "")),
        0,
    );
    for (direction, found) in [("ry", "∂w/∂x = +ry"), ("rz", "∂v/∂x = −rz")] {
        let (k, m) = (
            flip_direction(&dir, "K", direction),
            flip_direction(&dir, "M", direction),
        );
        let out = check(&dir, &format!("{direction}.yaml"), &scene(&k, &m, ""));
        assert_exit(&out, 2);
        let message = stderr(&out);
        for expected in [
            format!("{direction}.yaml:3:3: "),
            format!("rail `left`: the stiffness says {found}"),
            format!("declare `rotation_sign: {{{direction}: -1}}`"),
        ] {
            assert!(message.contains(&expected), "no `{expected}` in\n{message}");
        }
        let declared = scene(&k, &m, &format!("  rotation_sign: {{{direction}: -1}}\n"));
        assert_exit(
            &check(&dir, &format!("{direction}-declared.yaml"), &declared),
            0,
        );
    }
}

/// The criterion's claim (src/bridge/fe_import/rotation.rs): for a
/// mirror-symmetric element free of strain under rigid motions,
/// K[uⱼ,rᵢ] − K[uᵢ,rⱼ] = σ·h·K[uᵢ,uⱼ] exactly, and only the elements
/// joining i and j enter it. Checked on Timoshenko elements (shear
/// parameter Φ = 12EI/(κGAh²) from 0 to 3; Przemieniecki, Theory of Matrix
/// Structural Analysis, 1968, §5.6, θ = +∂w/∂x) of unequal lengths with
/// vertical and rotational springs at every node: every segment votes +1
/// (σ̂ of the first = 1 to 1e-12); flipped (θ = −ry), −1; and a segment
/// whose node is fixed does not vote.
#[test]
fn the_criterion_holds_for_unequal_timoshenko_elements_on_springs() {
    use vbi::scenario::fe_import::rotation::rail_evidence;
    use vbi::scene::imported::RailDofs;
    let lengths = [1.0, 0.3, 2.0, 0.7];
    let shear = [0.0, 0.5, 3.0, 1.2];
    let ei = 6.4e6;
    let nodes = lengths.len() + 1;
    for sign in [1.0, -1.0] {
        let mut k = Vec::new();
        for (e, (&h, &phi)) in lengths.iter().zip(&shear).enumerate() {
            let c = ei / ((1.0 + phi) * h * h * h);
            let local = [
                [12.0, 6.0 * h, -12.0, 6.0 * h],
                [6.0 * h, (4.0 + phi) * h * h, -6.0 * h, (2.0 - phi) * h * h],
                [-12.0, -6.0 * h, 12.0, -6.0 * h],
                [6.0 * h, (2.0 - phi) * h * h, -6.0 * h, (4.0 + phi) * h * h],
            ];
            // DOFs uz, θ per node; θ = sign · (file's rotation).
            let flip = |a: usize| if a % 2 == 1 { sign } else { 1.0 };
            for (a, row) in local.iter().enumerate() {
                for (b, value) in row.iter().enumerate() {
                    k.push((2 * e + a, 2 * e + b, flip(a) * flip(b) * c * value));
                }
            }
        }
        for n in 0..nodes {
            k.push((2 * n, 2 * n, 5.0e8)); // pad
            k.push((2 * n + 1, 2 * n + 1, 4.5e4)); // pad rotation
        }
        let mut x = vec![0.0];
        for h in lengths {
            x.push(x.last().unwrap() + h);
        }
        let rail = |fixed: Option<usize>| RailDofs {
            name: "rail".into(),
            nodes: (1..=nodes as u64).collect(),
            x: x.clone(),
            displacement: [
                (0..nodes)
                    .map(|n| (Some(n) != fixed).then_some(2 * n))
                    .collect(),
                vec![None; nodes],
            ],
            rotation: [
                (0..nodes).map(|n| Some(2 * n + 1)).collect(),
                vec![None; nodes],
            ],
            hermite: [true, false],
        };
        let k_free = |fixed: Option<usize>| -> Vec<(usize, usize, f64)> {
            k.iter()
                .copied()
                .filter(|&(a, b, _)| fixed.is_none_or(|f| a != 2 * f && b != 2 * f))
                .collect()
        };
        let evidence = rail_evidence(&k_free(None), &rail(None), 0);
        let (votes, first) = evidence.votes(sign);
        assert_eq!(votes, lengths.len(), "{evidence:?}");
        assert_eq!(evidence.votes(-sign).0, 0);
        assert!((first.unwrap().2 - sign).abs() <= 1e-12, "{evidence:?}");
        // The third node fixed: the two segments touching it are silent.
        let evidence = rail_evidence(&k_free(Some(2)), &rail(Some(2)), 0);
        assert_eq!(
            (evidence.votes(sign).0, evidence.silent),
            (2, 2),
            "{evidence:?}"
        );
    }
}
