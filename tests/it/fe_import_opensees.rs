//! Imported FE models checked the way an engineer checks an export (issue
//! 38, point 6): a simply supported girder written as OpenSees writes it
//! (a 2D frame, ndm 2, ndf 3: `ux, uy, rz` with y up, `rz` = +∂v/∂x) under
//! each of its constraint handlers, and the same girder in the wrong units.
//!
//! - `Transformation` and `Plain` drop the fixed DOFs from the system: the
//!   supports' vertical DOFs are absent from the DOF map. The first is
//!   written here as Matrix Market (shortest round-trip decimals, the
//!   equations numbered backwards as a bandwidth-reducing numberer may),
//!   the second as dense text in the layout of `printA('-file')` (a blank
//!   line, then one matrix row a line, each number followed by a space),
//!   once with every digit and once with 6 significant digits (C's `%g`, a
//!   C++ stream's default precision).
//! - `Penalty` keeps every DOF and adds α = 1e20 on the diagonal of K and
//!   M at the fixed ones: refused at that entry, and read right once the
//!   scene lists those DOFs under `constrained`.
//!
//! The reference is the same girder as `type: beam` (the same Hermite
//! elements, checked against closed forms in tests/it/physics.rs), which has
//! no axial DOFs; the frame's axial ones are uncoupled from bending in a
//! straight girder and stiff enough (first axial mode ≈ 560 Hz) to stay
//! above the 150 Hz the scenes keep, so the two runs must agree to
//! round-off: 1e-8 of each column's peak from files with every digit. The
//! 6-digit file is read, but 6 digits are not enough for a girder's
//! stiffness (measured: first frequency 5.0143 Hz against 5.0000 Hz, peaks
//! 6.4e-3 apart; a smooth shape's bending energy is a small difference of
//! large entries, so each entry's rounding by up to 5e-6 of itself grows
//! by about (L/h)² to (L/h)⁴): its peaks are held to 1e-2 only.

use crate::support;

use std::fmt::Write as _;

use support::{Scratch, assert_exit, max_abs, text, vbi};
use vbi::plan::{load_file, load_str};
use vbi::run::{Outcome, simulate};

/// The girder: the LCP paper's Fig. 4 bridge (20 m, EI = 3.2423e9 N·m²,
/// 2000 kg/m) in 12 elements, with an axial stiffness EA = 4e12 N.
const SPAN: f64 = 20.0;
const ELEMENTS: usize = 12;
const EI: f64 = 3.2423e9;
const EA: f64 = 4.0e12;
const MASS: f64 = 2000.0;
const NODES: usize = ELEMENTS + 1;
const ORDER: usize = 3 * NODES;
/// OpenSees' penalty number (`constraints Penalty 1e20 1e20`).
const PENALTY: f64 = 1e20;

/// The frame's full K and M (dense, every DOF; row 3i + d is node i + 1's
/// ux, uy, rz for d = 0, 1, 2), rz = +∂v/∂x, consistent masses (axial
/// mh/6 [2 1; 1 2], bending mh/420 [156 …]) as elasticBeamColumn -cMass.
fn frame() -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let mut k = vec![vec![0.0; ORDER]; ORDER];
    let mut m = vec![vec![0.0; ORDER]; ORDER];
    let h = SPAN / ELEMENTS as f64;
    let c = EI / (h * h * h);
    let kb = [
        [12.0 * c, 6.0 * h * c, -12.0 * c, 6.0 * h * c],
        [6.0 * h * c, 4.0 * h * h * c, -6.0 * h * c, 2.0 * h * h * c],
        [-12.0 * c, -6.0 * h * c, 12.0 * c, -6.0 * h * c],
        [6.0 * h * c, 2.0 * h * h * c, -6.0 * h * c, 4.0 * h * h * c],
    ];
    let q = MASS * h / 420.0;
    let mb = [
        [156.0 * q, 22.0 * h * q, 54.0 * q, -13.0 * h * q],
        [
            22.0 * h * q,
            4.0 * h * h * q,
            13.0 * h * q,
            -3.0 * h * h * q,
        ],
        [54.0 * q, 13.0 * h * q, 156.0 * q, -22.0 * h * q],
        [
            -13.0 * h * q,
            -3.0 * h * h * q,
            -22.0 * h * q,
            4.0 * h * h * q,
        ],
    ];
    let (ka, ma) = (EA / h, MASS * h / 6.0);
    for e in 0..ELEMENTS {
        let (a, b) = (3 * e, 3 * (e + 1));
        let axial = [a, b];
        for i in 0..2 {
            for j in 0..2 {
                let same = if i == j { 1.0 } else { -1.0 };
                k[axial[i]][axial[j]] += same * ka;
                m[axial[i]][axial[j]] += if i == j { 2.0 } else { 1.0 } * ma;
            }
        }
        let bending = [a + 1, a + 2, b + 1, b + 2];
        for i in 0..4 {
            for j in 0..4 {
                k[bending[i]][bending[j]] += kb[i][j];
                m[bending[i]][bending[j]] += mb[i][j];
            }
        }
    }
    (k, m)
}

/// The rows `fix 1 1 1 0` and `fix 13 0 1 0` hold: node 1's ux and uy,
/// node 13's uy.
fn fixed() -> Vec<usize> {
    vec![0, 1, 3 * (NODES - 1) + 1]
}

/// The DOF names of a frame row: OpenSees' (`ux, uy, rz`, y up) or vbi's
/// (`ux, uz, ry`, z up, ry = −∂w/∂x: the row's rotation negated).
fn name(row: usize, y_up: bool) -> &'static str {
    match (row % 3, y_up) {
        (0, _) => "ux",
        (1, true) => "uy",
        (1, false) => "uz",
        (_, true) => "rz",
        (_, false) => "ry",
    }
}

/// An export: the frame's rows `kept` in this order (equation i + 1 is
/// `kept[i]`), `K.mtx`, `M.mtx` and `dofs.csv` as text; `scale` = (force,
/// mass, length) unit factors (1, 1, 1 for N, kg, m; 1e-3, 1e-3, 1 for kN,
/// t, m; 1, 1e-3, 1e3 for N, t, mm); `y_up`: OpenSees' names, else vbi's
/// (rotations negated); `dense`: printA's dense text (`digits`: 6
/// significant digits, else every one), else Matrix Market symmetric with
/// every digit.
struct Export {
    kept: Vec<usize>,
    k: Vec<Vec<f64>>,
    m: Vec<Vec<f64>>,
    y_up: bool,
    dense: bool,
    /// Dense text in 6 significant digits (`%g`), else every digit.
    six_digits: bool,
    /// (force, mass, length) unit factors.
    scale: (f64, f64, f64),
}

impl Export {
    fn new(kept: Vec<usize>, y_up: bool, dense: bool) -> Self {
        let (k, m) = frame();
        Self {
            kept,
            k,
            m,
            y_up,
            dense,
            six_digits: false,
            scale: (1.0, 1.0, 1.0),
        }
    }

    /// The rows of Transformation/Plain: every one but the fixed ones.
    fn free_rows() -> Vec<usize> {
        let fixed = fixed();
        (0..ORDER).filter(|r| !fixed.contains(r)).collect()
    }

    /// Entry (i, j) of K or M in the export's units and sign convention.
    fn value(&self, matrix: &[Vec<f64>], stiffness: bool, i: usize, j: usize) -> f64 {
        let (force, mass, length) = self.scale;
        let (a, b) = (self.kept[i], self.kept[j]);
        // Each rotation index carries one length (N·m/rad = N/m · m²);
        // a translation divides by one in K and nothing in M.
        let rotations = (a % 3 == 2) as i32 + (b % 3 == 2) as i32;
        let unit = if stiffness {
            force / length * length.powi(rotations)
        } else {
            mass * length.powi(rotations)
        };
        let sign = if self.y_up {
            1.0
        } else {
            // θ = +∂w/∂x here; vbi's ry is −∂w/∂x.
            if rotations == 1 { -1.0 } else { 1.0 }
        };
        sign * unit * matrix[a][b]
    }

    fn write(&self, matrix: &[Vec<f64>], stiffness: bool) -> String {
        let n = self.kept.len();
        let mut out = String::new();
        if self.dense {
            out.push('\n');
            for i in 0..n {
                for j in 0..n {
                    let v = self.value(matrix, stiffness, i, j);
                    if self.six_digits {
                        write!(out, "{} ", g6(v)).unwrap();
                    } else {
                        write!(out, "{v:e} ").unwrap();
                    }
                }
                out.push('\n');
            }
            return out;
        }
        let mut lower = Vec::new();
        for i in 0..n {
            for j in 0..=i {
                let v = self.value(matrix, stiffness, i, j);
                if v != 0.0 {
                    lower.push(format!("{} {} {v:e}", i + 1, j + 1));
                }
            }
        }
        writeln!(
            out,
            "%%MatrixMarket matrix coordinate real symmetric\n% OpenSees export\n{n} {n} {}",
            lower.len()
        )
        .unwrap();
        for l in lower {
            out.push_str(&l);
            out.push('\n');
        }
        out
    }

    fn dof_map(&self) -> String {
        let mut out = String::from("dof,node,direction\n");
        for (i, &row) in self.kept.iter().enumerate() {
            writeln!(out, "{},{},{}", i + 1, row / 3 + 1, name(row, self.y_up)).unwrap();
        }
        out
    }

    /// The rail: every node, x in the export's length unit.
    fn rail(&self) -> String {
        let mut out = String::from("node,x\n");
        for i in 0..NODES {
            let x = SPAN * i as f64 / ELEMENTS as f64 * self.scale.2;
            writeln!(out, "{},{x}", i + 1).unwrap();
        }
        out
    }

    /// Writes K.mtx, M.mtx, dofs.csv and rail.csv into `dir`.
    fn write_files(&self, dir: &std::path::Path) {
        std::fs::write(dir.join("K.mtx"), self.write(&self.k, true)).unwrap();
        std::fs::write(dir.join("M.mtx"), self.write(&self.m, false)).unwrap();
        std::fs::write(dir.join("dofs.csv"), self.dof_map()).unwrap();
        std::fs::write(dir.join("rail.csv"), self.rail()).unwrap();
    }
}

/// `v` as C's `%g` prints it (6 significant digits, trailing zeros
/// dropped, a two-digit signed exponent), which is how an OpenSees stream
/// writes a double.
fn g6(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let exponent = v.abs().log10().floor() as i32;
    let sci = format!("{v:.5e}");
    let (mantissa, e) = sci.split_once('e').unwrap();
    let e: i32 = e.parse().unwrap();
    let trim = |s: &str| {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if (-5..6).contains(&exponent) && (-5..6).contains(&e) {
        let decimals = (5 - e).max(0) as usize;
        trim(&format!("{v:.decimals$}"))
    } else {
        let sign = if e < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), e.abs())
    }
}

/// The crossing both bridges carry: an oscillator at 25 m/s, permanent
/// contact, a fixed step and the modes up to 150 Hz (the five lowest
/// bending modes; the frame's axial ones lie above).
const CROSSING: &str = "  modes: {max_frequency: 150.0}
  damping: {type: modal, ratio: 0.02}
vehicles:
  - {type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}
contact: {type: permanent}
solver: {time_step: 2.0e-4, free_vibration: 0.05}
record:
  - {name: quarter, quantity: bridge_displacement, x: 5.0}
  - {name: middle, quantity: bridge_displacement, x: 10.0}
  - {name: middle_acc, quantity: bridge_acceleration, x: 10.0}
  - {name: force, quantity: contact_force}
";

fn beam_scene() -> String {
    format!(
        "name: girder-beam
bridge:
  type: beam
  spans: [{SPAN}]
  bending_stiffness: {EI:e}
  mass_per_length: {MASS}
  elements_per_span: {ELEMENTS}
{CROSSING}"
    )
}

/// The imported scene over K.mtx, M.mtx, dofs.csv and rail.csv, with
/// `extra` bridge keys (two-space indented lines) and `rest` after the
/// bridge (default: [`CROSSING`]'s).
fn import_scene(extra: &str) -> String {
    format!(
        "name: girder-opensees
bridge:
  type: fe_import
  stiffness: K.mtx
  mass: M.mtx
  dof_map: dofs.csv
  rails: [{{name: girder, file: rail.csv}}]
{extra}{CROSSING}"
    )
}

fn run(loaded: vbi::plan::Loaded) -> Outcome {
    simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

fn beam_outcome() -> Outcome {
    run(load_str(&beam_scene(), "beam.yaml").unwrap_or_else(|e| panic!("{e}")))
}

/// Loads the scene `yaml` written into `dir` (with its files).
fn load_in(dir: &std::path::Path, yaml: &str) -> Result<vbi::plan::Loaded, String> {
    let path = dir.join("scene.yaml");
    std::fs::write(&path, yaml).unwrap();
    load_file(&path).map_err(|e| e.to_string())
}

/// The largest difference of the recorded peaks (max and min of each
/// column) between two runs, relative to the column's largest |value|.
fn peak_difference(a: &Outcome, b: &Outcome) -> f64 {
    let mut worst = 0.0f64;
    for (x, y) in a.history.columns.iter().zip(&b.history.columns) {
        assert_eq!(x.name, y.name);
        let peak = max_abs(&x.values);
        assert!(peak > 0.0, "{} is recorded", x.name);
        let max = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
        for (p, q) in [
            (max(&x.values), max(&y.values)),
            (min(&x.values), min(&y.values)),
        ] {
            worst = worst.max((p - q).abs() / peak);
        }
    }
    worst
}

/// The minimum of the `middle` record (the mid-span's peak deflection, m).
fn midspan_peak(outcome: &Outcome) -> f64 {
    support::column(outcome, "middle")
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min)
}

/// Transformation: the fixed DOFs dropped (the supports' uy absent from the
/// map), the equations numbered from the last node back, OpenSees' names
/// with `axes: y_up`: the beam's run to 1e-8 of each column's peak.
#[test]
fn a_transformation_export_runs_as_the_beam() {
    let scratch = Scratch::new("fe_import_opensees", "transformation");
    let mut kept = Export::free_rows();
    kept.reverse();
    Export::new(kept, true, false).write_files(scratch.dir());
    let imported =
        load_in(scratch.dir(), &import_scene("  axes: y_up\n")).unwrap_or_else(|e| panic!("{e}"));
    let (beam, imported) = (beam_outcome(), run(imported));
    let difference = peak_difference(&beam, &imported);
    eprintln!(
        "transformation: mid-span peak {:.6e} m, beam {:.6e} m, peaks within {difference:.2e}",
        midspan_peak(&imported),
        midspan_peak(&beam)
    );
    assert!(difference <= 1e-8, "peaks differ by {difference:e}");
}

/// Plain: the same system as dense text in printA('-file')'s layout, read
/// as a dense matrix: with every digit, the beam's run to 1e-8 of each
/// peak; with 6 significant digits, to 1e-2 (measured 6.4e-3: see the
/// module's note).
#[test]
fn a_plain_export_in_dense_text_runs_as_the_beam() {
    let scratch = Scratch::new("fe_import_opensees", "plain");
    let beam = beam_outcome();
    for (six_digits, tolerance) in [(false, 1e-8), (true, 1e-2)] {
        let mut export = Export::new(Export::free_rows(), true, true);
        export.six_digits = six_digits;
        export.write_files(scratch.dir());
        let imported = load_in(scratch.dir(), &import_scene("  axes: y_up\n"))
            .unwrap_or_else(|e| panic!("{e}"));
        let imported = run(imported);
        let difference = peak_difference(&beam, &imported);
        eprintln!(
            "plain (dense, {}): mid-span peak {:.6e} m, beam {:.6e} m, peaks within {difference:.2e}",
            if six_digits {
                "6 digits"
            } else {
                "every digit"
            },
            midspan_peak(&imported),
            midspan_peak(&beam)
        );
        assert!(
            difference <= tolerance,
            "six digits {six_digits}: peaks differ by {difference:e}"
        );
    }
}

/// vbi's own axis names (uz up, ry = −∂w/∂x) with the supports' uz dropped
/// from the files rather than listed under `constrained`: docs/guide/imports.md's
/// promise, a rail node without its vertical DOF is a support. A rail node
/// with no DOF at all in the map is still refused (a wrong id must not
/// become a support).
#[test]
fn a_rail_node_whose_vertical_dof_was_dropped_is_a_support() {
    let scratch = Scratch::new("fe_import_opensees", "dropped");
    Export::new(Export::free_rows(), false, false).write_files(scratch.dir());
    let imported = load_in(scratch.dir(), &import_scene("")).unwrap_or_else(|e| panic!("{e}"));
    let vbi::scenario::resolved::Bridge::FeImport(fe) = &imported.scenario.bridge else {
        panic!("not imported")
    };
    assert_eq!(
        fe.model.free_rail_ends(),
        (false, false),
        "held by the supports"
    );
    let (beam, imported) = (beam_outcome(), run(imported));
    let difference = peak_difference(&beam, &imported);
    assert!(difference <= 1e-8, "peaks differ by {difference:e}");
    // Node 13 dropped altogether (as a clamped node would be).
    let kept: Vec<usize> = Export::free_rows()
        .into_iter()
        .filter(|r| r / 3 != NODES - 1)
        .collect();
    Export::new(kept, false, false).write_files(scratch.dir());
    let message = load_in(scratch.dir(), &import_scene("")).unwrap_err();
    assert!(
        message.contains("node 13 is not in the DOF map") && message.contains("help:"),
        "{message}"
    );
}

/// OpenSees' names without `axes`: the map has no uz, and the message says
/// that vbi's vertical is z and what to write.
#[test]
fn opensees_names_without_axes_are_refused_with_the_mapping() {
    let scratch = Scratch::new("fe_import_opensees", "names");
    Export::new(Export::free_rows(), true, false).write_files(scratch.dir());
    std::fs::write(scratch.path("scene.yaml"), import_scene("")).unwrap();
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    assert_exit(&out, 2);
    let message = text(&out.stderr);
    for words in ["no uz", "vertical is z", "axes: y_up"] {
        assert!(message.contains(words), "`{words}` not in:\n{message}");
    }
}

/// Penalty: every DOF kept, α = 1e20 added on K's and M's diagonal at the
/// fixed ones. Refused (exit 2) at the first such entry of K, with the
/// file's line and column and a help naming the handlers and
/// `constrained`; M's alone is refused at M. Listing the three DOFs under
/// `constrained` removes them, which leaves Transformation's system: the
/// beam's run to 1e-8.
#[test]
fn a_penalty_export_is_refused_at_its_entry_and_reads_with_constrained() {
    let scratch = Scratch::new("fe_import_opensees", "penalty");
    let mut export = Export::new((0..ORDER).collect(), true, false);
    for r in fixed() {
        export.k[r][r] += PENALTY;
        export.m[r][r] += PENALTY;
    }
    export.write_files(scratch.dir());
    // Node 1's ux is row 1: the first entry line of K, line 4 (banner,
    // comment, size line).
    std::fs::write(scratch.path("scene.yaml"), import_scene("  axes: y_up\n")).unwrap();
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    assert_exit(&out, 2);
    let message = text(&out.stderr);
    for words in [
        "K.mtx:4:",
        "node 1 ux",
        "penalty",
        "help:",
        "Transformation",
        "Plain",
        "constrained",
    ] {
        assert!(message.contains(words), "`{words}` not in:\n{message}");
    }
    // Only M's penalty.
    let (k, _) = frame();
    let mut only_m = Export::new((0..ORDER).collect(), true, false);
    only_m.m = export.m.clone();
    only_m.k = k;
    only_m.write_files(scratch.dir());
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    assert_exit(&out, 2);
    let message = text(&out.stderr);
    assert!(
        message.contains("M.mtx:4:") && message.contains("penalty"),
        "{message}"
    );
    // The penalised DOFs listed as constrained: vbi's names (z up).
    export.write_files(scratch.dir());
    let listed = "  axes: y_up\n  constrained: [{node: 1, direction: ux}, {node: 1, direction: uz}, \
                  {node: 13, direction: uz}]\n";
    let imported = load_in(scratch.dir(), &import_scene(listed)).unwrap_or_else(|e| panic!("{e}"));
    let difference = peak_difference(&beam_outcome(), &run(imported));
    assert!(difference <= 1e-8, "peaks differ by {difference:e}");
}

/// A dense text matrix that is not square is named as such, with the
/// formats vbi reads; a file that is no format at all says which it tried.
#[test]
fn a_dense_text_matrix_is_named_for_what_it_is() {
    let scratch = Scratch::new("fe_import_opensees", "dense");
    Export::new(Export::free_rows(), true, true).write_files(scratch.dir());
    std::fs::write(scratch.path("scene.yaml"), import_scene("  axes: y_up\n")).unwrap();
    // A row cut short.
    let k = std::fs::read_to_string(scratch.path("K.mtx")).unwrap();
    let mut lines: Vec<String> = k.lines().map(str::to_string).collect();
    let cut: Vec<&str> = lines[3].split_whitespace().collect();
    lines[3] = cut[..cut.len() - 1].join(" ");
    std::fs::write(scratch.path("K.mtx"), lines.join("\n") + "\n").unwrap();
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    assert_exit(&out, 2);
    let message = text(&out.stderr);
    for words in [
        "K.mtx:4:",
        "dense text matrix",
        "Matrix Market",
        "Harwell",
        "help:",
    ] {
        assert!(message.contains(words), "`{words}` not in:\n{message}");
    }
    // Neither dense nor any other format.
    std::fs::write(scratch.path("K.mtx"), "stiffness of the girder\n0 1 x\n").unwrap();
    let out = vbi(&["check", "scene.yaml"], scratch.dir());
    assert_exit(&out, 2);
    let message = text(&out.stderr);
    assert!(
        message.contains("Matrix Market")
            && message.contains("dense")
            && !message.contains("`0 1`"),
        "{message}"
    );
}

/// `summary.json`'s `imported_model` of a run in `dir`.
fn imported_summary(dir: &std::path::Path) -> serde_json::Value {
    let out = vbi(&["run", "scene.yaml", "--out", "out", "--quiet"], dir);
    assert_exit(&out, 0);
    let text = std::fs::read_to_string(dir.join("out/summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
    summary["imported_model"].clone()
}

fn advice_ids(dir: &std::path::Path) -> Vec<String> {
    let text = std::fs::read_to_string(dir.join("out/summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
    summary["advice"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["id"].as_str().unwrap().to_string())
        .collect()
}

/// The model's totals, in SI and in two wrong unit systems. Under a 200 kN
/// moving force, the static deflection (the total weight at mid-length:
/// node 7) is P L³ / 48 EI = 10.28 mm, exact for Hermite elements; the
/// vertical mass is δᵀMδ over the map's uy rows (the supports' dropped),
/// computed here from the frame. In kN and t both read 1000 times off (mass
/// small, deflection large): both warnings. In N, mm and t the mass per
/// metre is 10⁶ times small and the deflection (in mm, read as m) is
/// span/1945 of a 20,000 m "track": the mass warning alone. `vbi modes`
/// prints the same figures.
#[test]
fn units_are_checked_by_mass_and_static_deflection() {
    let scratch = Scratch::new("fe_import_opensees", "units");
    let dir = scratch.dir();
    let (_, m) = frame();
    let kept = Export::free_rows();
    let vertical: f64 = kept
        .iter()
        .filter(|&&a| a % 3 == 1)
        .flat_map(|&a| kept.iter().filter(|&&b| b % 3 == 1).map(move |&b| (a, b)))
        .map(|(a, b)| m[a][b])
        .sum();
    let axial: f64 = kept
        .iter()
        .filter(|&&a| a % 3 == 0)
        .flat_map(|&a| kept.iter().filter(|&&b| b % 3 == 0).map(move |&b| (a, b)))
        .map(|(a, b)| m[a][b])
        .sum();
    let load = 2.0e5;
    let deflection = load * SPAN.powi(3) / (48.0 * EI);
    let scene = |length: f64| {
        format!(
            "name: girder-units
bridge:
  type: fe_import
  stiffness: K.mtx
  mass: M.mtx
  dof_map: dofs.csv
  axes: y_up
  rails: [{{name: girder, file: rail.csv}}]
  modes: {{count: 4}}
vehicles: [{{type: moving_force, speed: {} m/s, loads: [{load}]}}]
solver: {{time_step: 2.0e-3}}
record:
  - {{name: middle, quantity: bridge_displacement, x: {}}}
",
            20.0 * length.min(45.0),
            10.0 * length
        )
    };
    let close = |value: &serde_json::Value, expected: f64, what: &str| {
        let v = value.as_f64().unwrap_or_else(|| panic!("{what}: {value}"));
        assert!(
            (v - expected).abs() <= 1e-6 * expected.abs(),
            "{what}: {v} against {expected}"
        );
        v
    };
    let ids = [
        "import-mass-per-length-low",
        "import-static-deflection-large",
    ];
    for (units, scale, warned) in [
        ("N, kg, m", (1.0, 1.0, 1.0), [false, false]),
        ("kN, t, m", (1e-3, 1e-3, 1.0), [true, true]),
        ("N, t, mm", (1.0, 1e-3, 1e3), [true, false]),
    ] {
        let mut export = Export::new(kept.clone(), true, false);
        export.scale = scale;
        export.write_files(dir);
        std::fs::write(dir.join("scene.yaml"), scene(scale.2)).unwrap();
        let figures = imported_summary(dir);
        let (force, mass, length) = scale;
        let z = close(
            &figures["mass"]["z"],
            vertical * mass,
            &format!("{units}: mass z"),
        );
        close(
            &figures["mass"]["x"],
            axial * mass,
            &format!("{units}: mass x"),
        );
        close(&figures["mass"]["y"], 0.0, &format!("{units}: mass y"));
        close(
            &figures["length"],
            SPAN * length,
            &format!("{units}: length"),
        );
        close(
            &figures["mass_per_length"],
            z / (SPAN * length),
            &format!("{units}: mass per length"),
        );
        close(&figures["static_load"], load, &format!("{units}: load"));
        // Displacements come out in the file's length unit, read as m.
        let w = close(
            &figures["static_deflection"],
            deflection * length / force,
            &format!("{units}: deflection"),
        );
        eprintln!("{units}: vertical mass {z:.6} kg, static deflection {w:.6} m");
        let advice = advice_ids(dir);
        for (id, expected) in ids.iter().zip(warned) {
            assert_eq!(
                advice.iter().any(|a| a == id),
                expected,
                "{units}: {id} in {advice:?}"
            );
        }
        let out = vbi(&["modes", "scene.yaml"], dir);
        assert_exit(&out, 0);
        let stdout = text(&out.stdout);
        assert!(
            stdout.contains("mass") && stdout.contains("static deflection"),
            "{units}: {stdout}"
        );
    }
}

/// Issue 40.6: an imported mode is named by the direction that carries
/// most of its kinetic energy. The frame's ux DOFs form a bar fixed at
/// node 1 (`fix 1 1 1 0`) and free at node 13, uncoupled from the bending
/// of the straight girder, so its 12 axial modes carry all of their energy
/// in ux and the 24 bending ones all in uz and ry: every mode's share is
/// 100.0 %, 12 are `axial`, 24 `vertical`, none `lateral` or `torsion`.
/// The first axial mode is the fixed-free bar's: on 12 equal linear
/// elements with consistent mass the discrete modes are exactly
/// sin(k x) with k = π/2L, at ω² = (EA/m)(6/h²)(1 − cos kh)/(2 + cos kh)
/// (the interior equations' dispersion relation; the free end holds by
/// the mode's symmetry about x = L, as cos kL = 0): matched to 1e-9; the
/// continuous bar's ω = (π/2L)√(EA/m) (Rao, Mechanical Vibrations,
/// §8.4) lies 7.1e-4 below it ((kh)²/24), held to 1e-3. `vbi modes`
/// shows the names in its table.
#[test]
fn imported_modes_are_named_by_their_kinetic_energy() {
    use std::f64::consts::PI;
    let scratch = Scratch::new("fe_import_opensees", "directions");
    Export::new(Export::free_rows(), true, false).write_files(scratch.dir());
    let yaml = import_scene("  axes: y_up\n")
        .replace("modes: {max_frequency: 150.0}", "modes: {count: 36}");
    let loaded = load_in(scratch.dir(), &yaml).unwrap_or_else(|e| panic!("{e}"));
    // Every mode, none left out (the plan leaves the axial ones out: a
    // vertical wheel does no work on them; checked below).
    let bridge = vbi::bridge::ModalBridge::build(&loaded.scenario.bridge).unwrap();
    let planned = &loaded.bridge;
    assert_eq!(planned.mode_count(), 24, "{}", planned.selection);
    assert_eq!(planned.left_out.len(), 12, "{}", planned.selection);
    assert!(planned.left_out.iter().all(|m| m.direction == "axial"));
    let names: Vec<String> = (0..bridge.mode_count())
        .map(|i| bridge.mode_character(i))
        .collect();
    assert_eq!(names.len(), 36);
    assert_eq!(names[0], "vertical 1 (100.0 %)");
    let count = |d: &str| names.iter().filter(|n| n.starts_with(d)).count();
    assert_eq!(
        (
            count("axial"),
            count("vertical"),
            count("lateral"),
            count("torsion")
        ),
        (12, 24, 0, 0),
        "{names:#?}"
    );
    assert!(names.iter().all(|n| n.ends_with("(100.0 %)")), "{names:#?}");
    let first_axial = names.iter().position(|n| n == "axial 1 (100.0 %)").unwrap();
    let omega = 2.0 * PI * bridge.frequencies()[first_axial];
    let h = SPAN / ELEMENTS as f64;
    let k = PI / (2.0 * SPAN);
    let discrete =
        (EA / MASS * 6.0 / (h * h) * (1.0 - (k * h).cos()) / (2.0 + (k * h).cos())).sqrt();
    let continuous = k * (EA / MASS).sqrt();
    eprintln!(
        "first axial mode (mode {}): {omega:.9} rad/s, discrete {discrete:.9}, continuous \
         {continuous:.9} ({:.2e})",
        first_axial + 1,
        (omega - continuous) / continuous
    );
    assert!((omega - discrete).abs() <= 1e-9 * discrete);
    assert!((omega - continuous).abs() <= 1e-3 * continuous);
    // The table of `vbi modes`.
    let path = scratch.path("scene.yaml");
    let out = vbi(&["modes", path.to_str().unwrap()], scratch.dir());
    assert_exit(&out, 0);
    let table = text(&out.stdout);
    assert!(
        table.contains("direction (kinetic energy share)"),
        "{table}"
    );
    assert!(table.contains("  vertical 24 (100.0 %)"), "{table}");
    assert!(!table.contains("  axial 1 (100.0 %)"), "{table}");
    // The axial modes the plan left out are listed after the kept ones,
    // the first at the bar's frequency.
    let (_, left) = table
        .split_once("left out (nothing in the scene moves them):\n")
        .expect("the left-out modes listed");
    assert_eq!(
        left.lines().filter(|l| l.ends_with("  axial")).count(),
        12,
        "{table}"
    );
    assert!(
        left.contains(&format!("{:.6}", omega / (2.0 * PI))),
        "{table}"
    );
    assert!(
        table.contains("12 modes left out of them and of the count (12 axial at"),
        "{table}"
    );
}
