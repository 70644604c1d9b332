//! The divergence guard under ground motion (issue 22, point 5): its
//! energy scale must know every energy source, the prescribed support
//! motion included, so a light vehicle on a shaking bridge is not stopped
//! as "diverged", while a genuinely unstable seismic run still is.

use std::f64::consts::PI;
use std::path::PathBuf;

use vbi::plan::load_str;
use vbi::run::{Outcome, RunError, simulate};
use vbi::solve::SolveError;

/// A fresh folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("vbi-guard-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn try_run(dir: &std::path::Path, yaml: &str) -> Result<Outcome, RunError> {
    let file = dir.join("scene.yaml");
    let loaded = load_str(yaml, file.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"));
    simulate(loaded, &mut |_, _| {})
}

/// The 25 m beam (EI = 8e10 N·m², m = 18 000 kg/m, f₁ = 5.30 Hz,
/// 2 % modal damping) with a 100 N force.
fn light_force_scene(ground: &str, speed: f64, solver: &str) -> String {
    format!(
        "name: light\n\
         bridge: {{type: beam, spans: [25.0], bending_stiffness: 8.0e10, mass_per_length: 18000.0,\n\
         \x20 damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles:\n  - {{type: moving_force, loads: [100.0], speed: {speed}}}\n\
         solver: {{free_vibration: 0.2{solver}}}\n\
         {ground}\
         record:\n\
         \x20 - {{name: midspan, quantity: bridge_displacement, x: 12.5}}\n"
    )
}

/// A constant vertical ground acceleration of 1 m/s² for 3 s.
fn constant_record(dir: &std::path::Path) -> String {
    let mut text = String::from("time [s], acceleration [m/s^2]\n");
    for k in 0..=30 {
        text.push_str(&format!("{}, 1.0\n", k as f64 * 0.1));
    }
    let file = dir.join("constant.csv");
    std::fs::write(&file, text).unwrap();
    // Named beside the scene: a scene reads only inside its own folder.
    "ground_motion:\n  - {file: constant.csv, direction: vertical}\n".to_string()
}

fn peak(outcome: &Outcome, name: &str) -> f64 {
    let column = outcome
        .history
        .columns
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    column.values.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// Issue 22 reproducer: a 100 N force under a constant 1 m/s² vertical
/// record used to stop at t = 0.011 s ("1.0e6 times its physical scale of
/// 2.165e-5 J"): the scale counted only the 100 N. It must run to the
/// end, and the deck must sag by the static deflection under the body
/// force m·üg (5 m üg L⁴/(384 EI) = 5·18000·1·25⁴/(384·8e10) = 1.144
/// mm; the 100 N adds 0.001 mm), with the dynamic overshoot of a suddenly
/// applied load at most doubling it.
#[test]
fn a_light_force_under_a_constant_record_runs_to_the_end() {
    let dir = folder("constant");
    let yaml = light_force_scene(&constant_record(&dir), 12.5, "");
    let outcome = try_run(&dir, &yaml).unwrap_or_else(|e| panic!("{e}"));
    let sag = 5.0 * 18000.0 * 25f64.powi(4) / (384.0 * 8.0e10);
    let w = peak(&outcome, "midspan");
    eprintln!("peak mid-span {w:.4e} m, static sag under 1 m/s² {sag:.4e} m");
    assert!(
        w > sag && w < 2.1 * sag,
        "peak {w} m against static {sag} m"
    );
}

/// Issue 22 reproducer: the shipped 0.1 g synthetic record with a 100 N
/// force at 2.5 m/s (a 10 s crossing through the strong phase) used to
/// stop as diverged; it must run to the end.
#[test]
fn a_light_force_under_the_shipped_record_runs_to_the_end() {
    let dir = folder("shipped");
    let record =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/records/synthetic-vertical.AT2");
    // A copy beside the scene: a scene reads only inside its own folder.
    std::fs::copy(&record, dir.join("synthetic-vertical.AT2")).unwrap();
    let ground = "ground_motion:\n  - {file: synthetic-vertical.AT2, direction: vertical}\n";
    let outcome =
        try_run(&dir, &light_force_scene(ground, 2.5, "")).unwrap_or_else(|e| panic!("{e}"));
    let w = peak(&outcome, "midspan");
    eprintln!("peak mid-span {w:.4e} m");
    assert!(w.is_finite() && w > 0.0);
}

/// A genuinely diverging seismic run still stops, early and with its cause:
/// Newmark β = 0.01, γ = 0.5 is stable for ωΔt ≤ 1/√(γ/2 − β) = 2.041
/// (Bathe, Table 9.3); at twice that step for the highest of 10 modes the
/// run under the constant 1 m/s² record must return a divergence before a
/// tenth of its duration, naming the time step.
#[test]
fn an_unstable_newmark_step_under_ground_motion_still_stops() {
    let dir = folder("unstable");
    let ground = constant_record(&dir);
    let scene = |beta: f64, dt: f64| {
        light_force_scene(
            &ground,
            12.5,
            &format!(", time_step: {dt}, newmark: {{beta: {beta}, gamma: 0.5}}"),
        )
        .replace("damping:", "modes: {count: 10}, damping:")
    };
    let reference = try_run(&dir, &scene(0.25, 1.0e-4)).unwrap_or_else(|e| panic!("{e}"));
    let omega_max = 2.0 * PI * reference.summary.run.frequencies.last().expect("modes");
    let limit = 1.0 / (0.25f64 - 0.01).sqrt() / omega_max;
    let end = reference.model.end_time();
    // Below the limit the same scene runs (the guard does not stop it).
    try_run(&dir, &scene(0.01, 0.9 * limit)).unwrap_or_else(|e| panic!("0.9× the limit: {e}"));
    match try_run(&dir, &scene(0.01, 2.0 * limit)) {
        Ok(_) => panic!("twice the stability limit under ground motion returned Ok"),
        Err(error) => {
            let message = error.to_string();
            eprintln!("β = 0.01 at 2× the limit under ground motion: {message}");
            match error {
                RunError::Solve(SolveError::Diverged { time, .. }) => {
                    assert!(time < 0.1 * end, "stopped at {time} of {end} s")
                }
                other => panic!("expected a divergence, got {other:?}"),
            }
            assert!(message.contains("time step"), "{message}");
        }
    }
}
