//! HSLM-A trains (EN 1991-2 Annex E) and the resonance check: the train
//! geometry against Table E.1 and Figure E.2 (axles of A1 and A10 counted
//! and placed by hand), an HSLM vehicle resolving to those moving forces,
//! and the first resonance of a simply supported span at v = f₁ D.

use vbi::execute::{Results, execute};
use vbi::plan::load_str;
use vbi::scenario::resolved::Vehicle;
use vbi::scene::HslmModel;

/// HSLM-A1 (N = 18, D = 18 m, d = 2 m, P = 170 kN) by hand from Figure E.2:
/// power car 0, 3, 14, 17 m; end coach bogie 3.525 m behind: 20.525,
/// 22.525 (centre 21.525); first Jacobs bogie centre D − (3.525 + d)/2 =
/// 15.2375 m further: 36.7625 (axles 35.7625, 37.7625); 19 Jacobs bogies at
/// D; the rear end bogie centre 15.2375 m behind the last (360.7625):
/// 376 (375, 377); rear power car from 380.525 to 397.525 m: 2·4 + 2·2 +
/// 2·19 = 50 axles. HSLM-A10 (N = 11, D = 27 m, d = 2 m, P = 210 kN): first
/// Jacobs centre 21.525 + 24.2375 = 45.7625, last 45.7625 + 11·27 =
/// 342.7625, rear end bogie centre 367, rear power car 371.525 … 388.525:
/// 36 axles.
#[test]
fn hslm_geometry_matches_en_1991_2_table_e1() {
    let a1 = HslmModel::A1.train();
    assert_eq!(
        (a1.coaches, a1.coach_length, a1.bogie_axle_spacing),
        (18, 18.0, 2.0)
    );
    assert_eq!(a1.axle_force, 170.0e3);
    let x = a1.axle_positions();
    assert_eq!(x.len(), 50);
    let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
    let expect = [
        (0, 0.0),
        (3, 17.0),
        (4, 20.525),
        (5, 22.525),
        (6, 35.7625),
        (7, 37.7625),
        (8, 53.7625),
        (42, 359.7625),
        (43, 361.7625),
        (44, 375.0),
        (45, 377.0),
        (46, 380.525),
        (49, 397.525),
    ];
    for (i, at) in expect {
        assert!(close(x[i], at), "A1 axle {}: {} vs {at}", i + 1, x[i]);
    }
    let a10 = HslmModel::A10.train();
    assert_eq!(
        (a10.coaches, a10.coach_length, a10.bogie_axle_spacing),
        (11, 27.0, 2.0)
    );
    assert_eq!(a10.axle_force, 210.0e3);
    let x = a10.axle_positions();
    assert_eq!(x.len(), 36);
    for (i, at) in [
        (6, 44.7625),
        (7, 46.7625),
        (8, 71.7625),
        (29, 343.7625),
        (30, 366.0),
        (31, 368.0),
        (32, 371.525),
        (35, 388.525),
    ] {
        assert!(close(x[i], at), "A10 axle {}: {} vs {at}", i + 1, x[i]);
    }
    // Axle counts 2 (N + 7) and P of every train of Table E.1.
    let table = [
        (18, 18.0, 2.0, 170.0),
        (17, 19.0, 3.5, 200.0),
        (16, 20.0, 2.0, 180.0),
        (15, 21.0, 3.0, 190.0),
        (14, 22.0, 2.0, 170.0),
        (13, 23.0, 2.0, 180.0),
        (13, 24.0, 2.0, 190.0),
        (12, 25.0, 2.5, 190.0),
        (11, 26.0, 2.0, 210.0),
        (11, 27.0, 2.0, 210.0),
    ];
    for (model, (n, d_big, d, p)) in HslmModel::ALL.into_iter().zip(table) {
        let t = model.train();
        assert_eq!(
            (
                t.coaches,
                t.coach_length,
                t.bogie_axle_spacing,
                t.axle_force
            ),
            (n, d_big, d, p * 1e3),
            "{}",
            model.label()
        );
        assert_eq!(t.axle_positions().len(), 2 * (n + 7));
    }
}

const BRIDGE: &str = "bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 2.43e10
  mass_per_length: 15000.0
  modes: {max_frequency: 50.0}
  damping: {type: modal, ratio: 0.01}
";

/// `type: hslm` resolves to the table's moving forces at its axle positions.
#[test]
fn an_hslm_vehicle_is_its_moving_forces() {
    let text =
        format!("name: hslm\n{BRIDGE}vehicles:\n  - {{type: hslm, model: A10, speed: 300 km/h}}\n");
    let loaded = load_str(&text, "hslm.yaml").unwrap_or_else(|e| panic!("{e}"));
    let Vehicle::MovingForce(force) = &loaded.scenario.vehicles[0] else {
        panic!("an HSLM train resolves to moving forces");
    };
    let positions = HslmModel::A10.train().axle_positions();
    assert_eq!(force.loads, vec![210.0e3; 36]);
    let mut x = 0.0;
    for (spacing, pair) in force.axle_spacings.iter().zip(positions.windows(2)) {
        x += spacing;
        assert!((x - pair[1]).abs() < 1e-9);
    }
    assert!((force.speed - 300.0 / 3.6).abs() < 1e-12);
}

/// EN 1991-2 Annex E: an HSLM-A train excites a simply supported span at
/// its first resonance when the coach length D is one wavelength of the
/// first mode, v = f₁ D. HSLM-A1 (D = 18 m) over the 20 m span (f₁ from the
/// model, ≈ 5.0 Hz): the peak deck acceleration over speeds f₁ D ± 30 km/h
/// in 5 km/h steps (refined around f₁ D) lies within one step of f₁ D, and
/// the check fails the 3.5 m/s² ballasted limit there.
#[test]
fn the_first_resonance_of_hslm_a1_is_at_f1_times_d() {
    let probe = load_str(
        &format!("name: f1\n{BRIDGE}vehicles: [{{type: hslm, model: A1, speed: 80.0}}]\n"),
        "f1.yaml",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let f1 = probe.bridge.frequencies()[0];
    let resonance = f1 * 18.0 * 3.6;
    let from = (resonance / 5.0).round() * 5.0 - 30.0;
    let text = format!(
        "name: resonance\n{BRIDGE}vehicles: [{{type: hslm, model: A1, speed: 80.0}}]
study:
  type: resonance_check
  trains: [A1]
  line_speed: 300 km/h
  speeds: {{from: {from} km/h, to: {} km/h, step: 5 km/h}}
",
        from + 60.0
    );
    let loaded = load_str(&text, "resonance.yaml").unwrap_or_else(|e| panic!("{e}"));
    let Ok(Results::ResonanceCheck(check)) = execute(loaded, &|_, _| {}) else {
        panic!("a resonance check");
    };
    // The 13 regular speeds, f₁ D itself (to 0.01 km/h, EN 1991-2 6.4.6.2
    // refinement near resonance) and 1.2 × 300 = 360 km/h are all run.
    let run_at = |v: f64| {
        check
            .points
            .iter()
            .any(|p| (p.speed * 3.6 - v).abs() <= 0.005 + 1e-9)
    };
    for i in 0..13 {
        assert!(
            run_at(from + 5.0 * i as f64),
            "{} km/h",
            from + 5.0 * i as f64
        );
    }
    assert!(run_at(resonance) && run_at(360.0));
    let peak = check
        .points
        .iter()
        .max_by(|a, b| a.max_acceleration.total_cmp(&b.max_acceleration))
        .unwrap();
    let peak_km_h = peak.speed * 3.6;
    eprintln!(
        "f1 = {f1:.4} Hz, f1 D = {resonance:.1} km/h, peak {:.3} m/s^2 at {peak_km_h:.1} km/h",
        peak.max_acceleration
    );
    assert!(
        (peak_km_h - resonance).abs() <= 5.0 + 1e-9,
        "peak at {peak_km_h} km/h, f1 D = {resonance} km/h"
    );
    let summary = check.summary("resonance");
    assert!(!summary.passes);
    assert_eq!(summary.acceleration_limit, 3.5);
    // The displacement peaks at mid-span, the acceleration at resonance
    // well above its off-resonance values.
    assert!((peak.displacement_at - 10.0).abs() < 1e-9);
    let first = &check.points[0];
    assert!(peak.max_acceleration > 2.0 * first.max_acceleration);
}

/// A resonance check on a plate deck is refused with a located message.
#[test]
fn a_plate_refuses_a_resonance_check() {
    let text = "name: p
bridge:
  type: plate
  spans: [20.0]
  width: 8.0
  thickness: 0.8
  density: 2500.0
  rigidity: {type: isotropic, youngs_modulus: 3.5e10, poisson_ratio: 0.2}
  modes: {count: 10}
vehicles: [{type: hslm, model: A1, speed: 80.0}]
study: {type: resonance_check, line_speed: 300 km/h}
";
    let error = match load_str(text, "plate.yaml") {
        Ok(_) => panic!("a plate accepted a resonance check"),
        Err(e) => e.to_string(),
    };
    assert!(error.contains("plate.yaml:11:"), "{error}");
    assert!(error.contains("beam bridges only"), "{error}");
}
