//! Support reactions of imported models (issue 40.1): read from the model's
//! own equations at its `constrained` DOFs, R_c = K_cf u + M_cf ü, in the
//! mode-acceleration form (src/bridge/fe_import/reaction.rs).
//!
//! The model is a 2 × 30 m continuous beam (EI = 1e10 N·m², m = 5000 kg/m,
//! 20 Hermite elements per span) written by `vbi export beam`, its three
//! supports' uz listed under `constrained`; 100 kN crosses at 30 m/s, then
//! 0.5 s of free vibration. Two independent checks:
//! - force balance, an identity of the FE equations whatever modes are
//!   kept: Σ R_c = P (on the deck) + Σ_f (M δ)_f ü_f, with ü_f read at every
//!   free DOF of the model (δ = 1 on every uz) and M δ summed here from the
//!   exported M.mtx itself — to 1e-9 of P at every step, 10 modes and all;
//! - with every mode kept, the reactions equal those of the `type: beam`
//!   run of the same scene, which tests/it/section_forces.rs pins to a
//!   direct (non-modal) integration of the full FE model to 1e-9 of P.

use crate::support;

use support::{Scratch, column, run_yaml};
use vbi::plan::{load_file, load_str};
use vbi::run::simulate;

const SPAN: f64 = 30.0;
const LOAD: f64 = 100.0e3;
const SPEED: f64 = 30.0;
const STEP: f64 = 1.0e-3;
const ELEMENTS: usize = 20;

fn beam_scene(modes: usize) -> String {
    format!(
        "name: reactions
bridge:
  type: beam
  spans: [{SPAN}, {SPAN}]
  bending_stiffness: 1.0e10
  mass_per_length: 5000.0
  elements_per_span: {ELEMENTS}
  modes: {{count: {modes}}}
vehicles:
  - {{type: moving_force, loads: [{LOAD}], speed: {SPEED}}}
solver: {{time_step: {STEP}, free_vibration: 0.5}}
record:
  - {{name: r1, quantity: bridge_reaction, x: 0}}
  - {{name: r2, quantity: bridge_reaction, x: {SPAN}}}
  - {{name: r3, quantity: bridge_reaction, x: {}}}
",
        2.0 * SPAN
    )
}

/// The exported files in `dir` and an imported scene on them recording the
/// three reactions (the middle one by node, the others by x) and the
/// acceleration of every free DOF (`a<node>z`, `a<node>r`), unfiltered (the
/// balance needs every kept mode's).
fn imported_scene(dir: &std::path::Path, modes: usize) -> String {
    let beam = load_str(&beam_scene(modes), "beam.yaml").unwrap_or_else(|e| panic!("{e}"));
    for (name, text) in vbi::export::beam_files(&beam.scenario).expect("export") {
        if name != "scenario.yaml" {
            std::fs::write(dir.join(name), text).expect("write");
        }
    }
    let nodes = 2 * ELEMENTS + 1;
    let supports = [1, ELEMENTS + 1, nodes];
    let mut records = format!(
        "  - {{name: r1, quantity: bridge_reaction, x: 0}}\n  \
         - {{name: r2, quantity: bridge_reaction, node: {}, direction: uz}}\n  \
         - {{name: r3, quantity: bridge_reaction, x: {}}}\n",
        ELEMENTS + 1,
        2.0 * SPAN
    );
    for node in 1..=nodes {
        if !supports.contains(&node) {
            records.push_str(&format!(
                "  - {{name: a{node}z, quantity: bridge_acceleration, node: {node}, direction: uz, max_frequency: 1.0e9}}\n"
            ));
        }
        records.push_str(&format!(
            "  - {{name: a{node}r, quantity: bridge_acceleration, node: {node}, direction: ry, max_frequency: 1.0e9}}\n"
        ));
    }
    format!(
        "name: reactions-imported
bridge:
  type: fe_import
  stiffness: K.mtx
  mass: M.mtx
  dof_map: dofs.csv
  constrained: [{{node: 1, direction: uz}}, {{node: {}, direction: uz}}, {{node: {nodes}, direction: uz}}]
  rails: [{{name: rail, file: rail.csv}}]
  modes: {{count: {modes}}}
vehicles:
  - {{type: moving_force, loads: [{LOAD}], speed: {SPEED}}}
solver: {{time_step: {STEP}, free_vibration: 0.5}}
record:
{records}",
        ELEMENTS + 1
    )
}

/// (M δ) per DOF of the exported M.mtx (1-based DOF 2i+1 is node i+1's
/// uz, 2i+2 its ry), δ = 1 on every uz: a symmetric coordinate file, one
/// triangle stored.
fn inertia_of_uz(mtx: &str) -> Vec<f64> {
    let mut lines = mtx.lines().filter(|l| !l.starts_with('%'));
    let size: Vec<usize> = lines
        .next()
        .expect("size line")
        .split_whitespace()
        .map(|t| t.parse().expect("size"))
        .collect();
    let mut out = vec![0.0; size[0]];
    let is_uz = |dof: usize| dof % 2 == 1;
    for line in lines {
        let t: Vec<&str> = line.split_whitespace().collect();
        if t.len() < 3 {
            continue;
        }
        let (r, c, v): (usize, usize, f64) = (
            t[0].parse().unwrap(),
            t[1].parse().unwrap(),
            t[2].parse().unwrap(),
        );
        if is_uz(c) {
            out[r - 1] += v;
        }
        if r != c && is_uz(r) {
            out[c - 1] += v;
        }
    }
    out
}

/// The static reference columns of the records `names`.
fn static_columns<'a>(run: &'a vbi::run::Outcome, names: &[&str]) -> Vec<&'a [f64]> {
    names
        .iter()
        .map(|n| {
            run.history
                .columns
                .iter()
                .find(|c| c.name == *n)
                .and_then(|c| c.static_values.as_deref())
                .expect("a static reference")
        })
        .collect()
}

#[test]
fn imported_reactions_balance_the_load_and_the_inertia_and_equal_the_beams() {
    let scratch = Scratch::new("it", "imported_reactions");
    let dir = scratch.dir();
    for modes in [10, 79] {
        let yaml = imported_scene(dir, modes);
        std::fs::write(dir.join("scenario.yaml"), &yaml).expect("write");
        let loaded = load_file(&dir.join("scenario.yaml")).unwrap_or_else(|e| panic!("{e}"));
        let run = simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
        let inertia = inertia_of_uz(&std::fs::read_to_string(dir.join("M.mtx")).unwrap());
        let r = [column(&run, "r1"), column(&run, "r2"), column(&run, "r3")];
        let nodes = 2 * ELEMENTS + 1;
        let mut worst = 0.0_f64;
        let mut peak_inertia = 0.0_f64;
        for (i, &t) in run.history.time.iter().enumerate() {
            let on = if SPEED * t <= 2.0 * SPAN { LOAD } else { 0.0 };
            let mut force = 0.0;
            for node in 1..=nodes {
                let (uz, ry) = (2 * node - 2, 2 * node - 1);
                if let Some(c) = run
                    .history
                    .columns
                    .iter()
                    .find(|c| c.name == format!("a{node}z"))
                {
                    force += inertia[uz] * c.values[i];
                }
                force += inertia[ry] * column(&run, &format!("a{node}r"))[i];
            }
            let sum = r[0][i] + r[1][i] + r[2][i];
            worst = worst.max((sum - on - force).abs());
            peak_inertia = peak_inertia.max(force.abs());
        }
        assert!(
            peak_inertia > 0.05 * LOAD,
            "{modes} modes: the crossing is not dynamic ({peak_inertia} N)"
        );
        assert!(
            worst <= 1e-9 * LOAD,
            "{modes} modes: Σ R − P − ∫m ü is {worst} N"
        );
        if modes == 79 {
            let beam = run_yaml(&beam_scene(modes));
            for name in ["r1", "r2", "r3"] {
                let (a, b) = (column(&run, name), column(&beam, name));
                let off = a
                    .iter()
                    .zip(b)
                    .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
                assert!(
                    off <= 1e-8 * LOAD,
                    "{name}: the imported reaction is {off} N from the beam's"
                );
            }
        }
        // The static reference: the static reactions carry the load on the
        // deck, exactly.
        let statics = static_columns(&run, &["r1", "r2", "r3"]);
        for i in 0..statics[0].len() {
            let t = run.history.time[i];
            let on = if SPEED * t <= 2.0 * SPAN { LOAD } else { 0.0 };
            let sum: f64 = statics.iter().map(|s| s[i]).sum();
            assert!(
                (sum - on).abs() <= 1e-9 * LOAD,
                "static reactions sum to {sum} N at t = {t} s, not {on} N"
            );
        }
    }
}

#[test]
fn a_reaction_at_a_dof_that_is_not_constrained_is_refused_with_the_supports() {
    let scratch = Scratch::new("it", "imported_reaction_refused");
    let dir = scratch.dir();
    let yaml =
        imported_scene(dir, 10).replace("node: 21, direction: uz}\n", "node: 5, direction: uz}\n");
    std::fs::write(dir.join("scenario.yaml"), &yaml).expect("write");
    let error = match load_file(&dir.join("scenario.yaml")) {
        Ok(_) => panic!("a reaction at a free DOF was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(
        error.contains("node 5 uz is not a constrained DOF") && error.contains("node 21 uz"),
        "{error}"
    );
}

/// A plate deck's line reactions (src/bridge/plate/reactions.rs): a 15 +
/// 20 m deck, 8 m wide and 0.8 m thick with free edges (ρh = 1920 kg/m², f₁ ≈ 7 Hz), 100 kN at 25 m/s
/// 2 m off the centre line (so torsion is excited), then free vibration.
/// The inertia ∫∫ρh ẅ dA is summed here from recorded accelerations at the
/// Gauss points of every element (2 along, 3 across: exact for the Ritz
/// basis, cubic per element in x and of degree 3 in y), so the balance
/// Σ R = P (on the deck) + ∫∫ρh ẅ dA is checked to 1e-9 of P at every
/// step, with 12 modes and with all 40; the static reference columns sum to
/// the load exactly.
fn plate_scene(modes: usize) -> String {
    let (spans, elements) = ([15.0, 20.0], 8usize);
    let mut records = String::from(
        "  - {name: r1, quantity: bridge_reaction, x: 0}\n  \
         - {name: r2, quantity: bridge_reaction, x: 15}\n  \
         - {name: r3, quantity: bridge_reaction, x: 35}\n",
    );
    let gx = [-1.0 / 3.0f64.sqrt(), 1.0 / 3.0f64.sqrt()];
    let gy = [-(0.6f64.sqrt()), 0.0, 0.6f64.sqrt()];
    let mut start = 0.0;
    let mut k = 0;
    for span in spans {
        let h = span / elements as f64;
        for e in 0..elements {
            for t in gx {
                let x = start + h * (e as f64 + 0.5 * (1.0 + t));
                for s in gy {
                    let y = 4.0 * (1.0 + s);
                    records.push_str(&format!(
                        "  - {{name: g{k}, quantity: bridge_acceleration, x: {x}, y: {y}, \
                         max_frequency: 1.0e9}}\n"
                    ));
                    k += 1;
                }
            }
        }
        start += span;
    }
    format!(
        "name: plate-reactions
bridge:
  type: plate
  spans: [15.0, 20.0]
  width: 8.0
  thickness: 0.8
  density: 2400.0
  rigidity: {{type: isotropic, youngs_modulus: 3.0e10, poisson_ratio: 0.2}}
  edges: free
  elements_per_span: {elements}
  terms: {{longitudinal: 10, transverse: 4}}
  modes: {{count: {modes}}}
vehicles:
  - {{type: moving_force, loads: [{LOAD}], speed: 25.0, lateral_position: 2.0}}
solver: {{time_step: 1.0e-3, free_vibration: 0.3}}
record:
{records}"
    )
}

#[test]
fn plate_line_reactions_balance_the_load_and_the_inertia() {
    // Gauss weights (element length / 2 · w_x) (width / 2 · w_y).
    let wy = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
    for modes in [12, 40] {
        let run = run_yaml(&plate_scene(modes));
        let r = [column(&run, "r1"), column(&run, "r2"), column(&run, "r3")];
        let mut weights = Vec::new();
        for span in [15.0, 20.0] {
            let h = span / 8.0;
            for _ in 0..8 * 2 {
                for w in wy {
                    weights.push(1920.0 * 0.5 * h * 4.0 * w);
                }
            }
        }
        let accelerations: Vec<&[f64]> = (0..weights.len())
            .map(|k| column(&run, &format!("g{k}")))
            .collect();
        let (mut worst, mut peak_inertia) = (0.0_f64, 0.0_f64);
        for (i, &t) in run.history.time.iter().enumerate() {
            let on = if 25.0 * t <= 35.0 { LOAD } else { 0.0 };
            let inertia: f64 = weights
                .iter()
                .zip(&accelerations)
                .map(|(w, a)| w * a[i])
                .sum();
            let sum = r[0][i] + r[1][i] + r[2][i];
            worst = worst.max((sum - on - inertia).abs());
            peak_inertia = peak_inertia.max(inertia.abs());
        }
        eprintln!("{modes} modes: balance {worst:.3e} N, peak inertia {peak_inertia:.0} N");
        assert!(
            peak_inertia > 0.02 * LOAD,
            "{modes} modes: the crossing is not dynamic ({peak_inertia} N)"
        );
        assert!(
            worst <= 1e-9 * LOAD,
            "{modes} modes: Σ R − P − ∫∫ρh ẅ is {worst} N"
        );
        let statics = static_columns(&run, &["r1", "r2", "r3"]);
        for (i, &t) in run.history.time.iter().enumerate() {
            let on = if 25.0 * t <= 35.0 { LOAD } else { 0.0 };
            let sum: f64 = statics.iter().map(|s| s[i]).sum();
            assert!(
                (sum - on).abs() <= 1e-9 * LOAD,
                "static line reactions sum to {sum} N at t = {t} s, not {on} N"
            );
        }
    }
}

/// On one span the line reactions are statically determinate whatever the
/// plate does across its width: the static reference is P (1 − ξ/L) at
/// x = 0 and P ξ/L at x = L for the load at ξ, to round-off (lever rule).
#[test]
fn a_single_span_plates_static_line_reactions_are_the_lever_rule() {
    let yaml = plate_scene(12)
        .replace("spans: [15.0, 20.0]", "spans: [20.0]")
        .lines()
        .filter(|l| !l.contains("bridge_acceleration") && !l.contains("name: r3"))
        .collect::<Vec<_>>()
        .join("\n")
        .replace("x: 15}", "x: 20}");
    let run = run_yaml(&yaml);
    let statics = static_columns(&run, &["r1", "r2"]);
    let (a, b) = (statics[0], statics[1]);
    for (i, &t) in run.history.time.iter().enumerate() {
        let xi = 25.0 * t;
        let (ea, eb) = if xi <= 20.0 {
            (LOAD * (1.0 - xi / 20.0), LOAD * xi / 20.0)
        } else {
            (0.0, 0.0)
        };
        assert!(
            (a[i] - ea).abs() <= 1e-9 * LOAD && (b[i] - eb).abs() <= 1e-9 * LOAD,
            "t = {t} s: {} and {} N against {ea} and {eb} N",
            a[i],
            b[i]
        );
    }
}
