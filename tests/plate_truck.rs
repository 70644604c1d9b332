//! The H20-44 truck on the plate paper's orthotropic deck: the iterative
//! solver against `coupled`, the slow crossing against the static influence
//! surface, and the DAF table. Each test states its source and tolerance.

mod support;

use support::{assert_histories_agree, column, max_abs, run_yaml};

/// The orthotropic 24–30–24 m deck of the plate paper (Section 3.2), with a
/// scene-specific tail: truck, surface, solver and records.
fn orthotropic(tail: &str) -> String {
    format!(
        r#"
name: orthotropic-test
bridge:
  type: plate
  spans: [24.0, 30.0, 24.0]
  width: 13.715
  thickness: 0.212
  density: 3265.29
  rigidity: {{type: orthotropic, flexural_rigidity_x: 2.41e9, flexural_rigidity_y: 2.18e7, torsional_rigidity: 1.14e8, poisson_ratio: 0.3}}
  modes: {{count: 45}}
  damping: {{type: modal, ratio: 0.02}}
  girder_lines: [1.3715, 4.1145, 6.8575, 9.6005, 12.3435]
{tail}"#
    )
}

/// `iterative` (the paper's uncoupled scheme, tolerance 1e-10) and `coupled`
/// give the same histories to 1e-7 of each peak for the eccentric truck on a
/// good road, and the iteration needs only a few passes per step (the paper:
/// about two).
#[test]
fn iterative_agrees_with_coupled_on_the_plate() {
    let run = |method: &str, extra: &str| {
        run_yaml(&orthotropic(&format!(
            r#"vehicles:
  - {{type: h20_44, speed: 30.0, lateral_position: 2.743}}
surface: {{type: random, coefficient: 15.0e-6, seed: 1}}
solver: {{method: {method}, time_step: 3.12e-3{extra}}}
record:
  - {{name: g1, quantity: bridge_displacement, x: 39.0, y: 1.3715}}
  - {{name: g5, quantity: bridge_displacement, x: 39.0, y: 12.3435}}
  - {{name: acc, quantity: bridge_acceleration, x: 39.0, y: 1.3715}}
  - {{name: f1, quantity: contact_force, vehicle: 1, wheel: 1}}
  - {{name: f4, quantity: contact_force, vehicle: 1, wheel: 4}}
  - {{name: roll, quantity: vehicle_displacement, vehicle: 1, dof: body_roll}}
"#
        )))
    };
    let iterative = run("iterative", ", tolerance: 1.0e-10");
    let coupled = run("coupled", "");
    assert_histories_agree(
        &iterative,
        &coupled,
        &["g1", "g5", "acc", "f1", "f4", "roll"],
        1e-7,
    );
    let stats = iterative.summary.run.iterations.expect("iteration counts");
    assert!(stats.mean <= 4.0 && stats.max <= 6, "{stats:?}");
    // The eccentric truck rolls the deck: the near girder deflects more.
    let (near, far) = (
        max_abs(column(&coupled, "g1")),
        max_abs(column(&coupled, "g5")),
    );
    assert!(near > 2.0 * far, "near {near} m, far {far} m");
}

/// A very slow crossing (1 m/s, smooth road) is quasi-static: at every span's
/// middle on every girder line the DAF is 1 within 1 % (what is left is the
/// 45-mode truncation, which the static reference does not have, and the
/// truck's slow bounce), and the static reference at mid-span 2 of girder 3
/// (deck centre) under the centred truck equals the sum of the four wheel
/// loads times the influence surface there — checked through its symmetry:
/// the centred truck deflects girders 1 and 5 equally to 1e-9.
#[test]
fn slow_crossing_is_the_static_influence_surface() {
    let outcome = run_yaml(&orthotropic(
        r#"vehicles:
  - {type: h20_44, speed: 1.0}
solver: {method: iterative, time_step: 0.02}
record:
  - {name: g1, quantity: bridge_displacement, x: 39.0, y: 1.3715}
"#,
    ));
    let table = &outcome.summary.girder_dafs;
    assert_eq!(table.len(), 15, "3 spans × 5 girder lines");
    for row in table {
        assert!(
            (row.daf - 1.0).abs() <= 0.01,
            "span {} girder {}: DAF {}",
            row.span,
            row.girder,
            row.daf
        );
    }
    for span in 1..=3 {
        let g = |girder: usize| {
            table
                .iter()
                .find(|r| r.span == span && r.girder == girder)
                .map(|r| r.static_max_abs)
                .expect("row")
        };
        assert!(
            (g(1) - g(5)).abs() <= 1e-9 * g(1),
            "span {span}: {} vs {}",
            g(1),
            g(5)
        );
        assert!(g(3) > g(1), "the centre line carries the centred truck");
    }
}

/// A step whose iteration cannot converge within `max_iterations` stops the
/// run: the library returns the solver's error naming the time, the vehicle
/// position and the remaining change, and `vbi run` exits with 1 and leaves
/// no results behind.
#[test]
fn iteration_that_does_not_converge_stops_the_run() {
    let yaml = orthotropic(
        r#"vehicles:
  - {type: h20_44, speed: 30.0}
surface: {type: random, class: average, seed: 1}
solver: {method: iterative, time_step: 3.12e-3, tolerance: 1.0e-14, max_iterations: 2}
"#,
    );
    let loaded = vbi::scenario::load_str(&yaml, "stuck.yaml").expect("valid scene");
    let error = vbi::run::simulate(loaded, &mut |_, _| {})
        .expect_err("two iterations cannot reach 1e-14")
        .to_string();
    for part in [
        "did not converge",
        "t = ",
        "vehicle 1 front at x = ",
        "max_iterations",
    ] {
        assert!(error.contains(part), "{error}");
    }
    let dir = std::env::temp_dir().join(format!("vbi-stuck-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("stuck.yaml");
    std::fs::write(&file, &yaml).expect("scene written");
    let out = dir.join("out");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(["run", "--quiet", "--out"])
        .arg(&out)
        .arg(&file)
        .output()
        .expect("vbi runs");
    assert_eq!(status.status.code(), Some(1), "{status:?}");
    assert!(
        !out.join("summary.json").exists() && !out.join("history.csv").exists(),
        "no partial results"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
