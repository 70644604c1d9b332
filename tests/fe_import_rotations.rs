//! Imported FE models through the binary: the sign convention of the
//! rotation DOFs (a textbook beam's θ = +∂w/∂x labelled `ry` must not run
//! silently as this program's right-handed ry = −∂w/∂x), duplicated
//! entries, and symmetry errors located at their file's line.
//!
//! The reference model is `vbi export beam` of a `type: beam` scene (its
//! Hermite elements are checked against closed forms in tests/physics.rs;
//! tests/fe_import.rs checks the export against the beam to 1e-8). The
//! textbook convention is made from it by flipping the sign of every matrix
//! entry with exactly one ry index, which is exactly the change of variable
//! θ = −ry: its runs must equal the export's bit for bit once declared.

mod support;

use std::path::Path;
use std::process::{Command, Output};

use support::Scratch;

fn vbi<S: AsRef<std::ffi::OsStr>>(args: &[S], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run vbi")
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn assert_exit(out: &Output, code: i32) {
    assert_eq!(
        out.status.code(),
        Some(code),
        "stdout:\n{}\nstderr:\n{}",
        String::from_utf8_lossy(&out.stdout),
        stderr(out)
    );
    assert!(!stderr(out).contains("panicked"));
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

/// Writes the textbook-convention K and M (`K-slope.mtx`, `M-slope.mtx`)
/// and a scene using them (`slope.yaml`, with `extra` added to its bridge)
/// next to the export.
fn textbook_scene(export: &Path, extra: &str) -> String {
    let rows = ry_rows(&std::fs::read_to_string(export.join("dofs.csv")).unwrap());
    for name in ["K", "M"] {
        let text = std::fs::read_to_string(export.join(format!("{name}.mtx"))).unwrap();
        std::fs::write(
            export.join(format!("{name}-slope.mtx")),
            flip_rotations(&text, &rows),
        )
        .unwrap();
    }
    let scene = std::fs::read_to_string(export.join("scenario.yaml")).unwrap();
    let scene = scene
        .replace("\"K.mtx\"", "\"K-slope.mtx\"")
        .replace("\"M.mtx\"", "\"M-slope.mtx\"")
        .replace(
            "  type: \"fe_import\"\n",
            &format!("  type: \"fe_import\"\n{extra}"),
        );
    assert!(scene.contains("K-slope.mtx"), "{scene}");
    std::fs::write(export.join("slope.yaml"), &scene).unwrap();
    scene
}

#[test]
fn a_textbook_rotation_convention_is_refused() {
    let scratch = Scratch::new("fe_import_rotations", "refused");
    export(scratch.dir());
    let export = scratch.path("export");
    // The export itself is in the program's convention: accepted.
    assert_exit(&vbi(&["check", "scenario.yaml"], &export), 0);
    textbook_scene(&export, "");
    let out = vbi(&["check", "slope.yaml"], &export);
    assert_exit(&out, 2);
    let message = stderr(&out);
    assert!(message.contains("rotation_sign"), "{message}");
    assert!(message.contains("+∂w/∂x"), "{message}");
}
