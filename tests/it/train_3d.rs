//! The 27-DOF 3D car of the EMBS paper (Section 3.2, Table 2: the
//! AVE-S103). Each test states its reference and tolerance.

use crate::support;

use std::f64::consts::PI;

use nalgebra::{DMatrix, DVector};
use support::{column, max_abs, run_yaml};
use vbi::scenario::rail_3d::AVE_S103_PRESET;
use vbi::scenario::resolved::{Train3d, Train3dCar, Train3dParameters};
use vbi::vehicle::VehicleModel;
use vbi::vehicle::train_3d;

const G: f64 = 9.81;

fn car(p: Train3dParameters) -> VehicleModel {
    train_3d::build(
        &Train3d {
            speed: 20.0,
            acceleration: 0.0,
            entry_time: 0.0,
            lateral_position: None,
            cars: vec![Train3dCar {
                spacing: None,
                offset: 0.0,
                parameters: p,
            }],
        },
        G,
    )
}

/// A car with every value changed from the preset (and the heights and
/// spacings all different), so no two parameters can be swapped unnoticed.
fn other() -> Train3dParameters {
    Train3dParameters {
        body_mass: 41_000.0,
        body_roll_inertia: 90_000.0,
        body_pitch_inertia: 1.7e6,
        body_yaw_inertia: 1.6e6,
        bogie_mass: 2_900.0,
        bogie_roll_inertia: 2_100.0,
        bogie_pitch_inertia: 1_500.0,
        bogie_yaw_inertia: 3_300.0,
        wheelset_mass: 1_500.0,
        wheelset_roll_inertia: 800.0,
        primary_stiffness: [9e6, 7e6, 1.1e6],
        primary_damping: [5e3, 8e3, 12e3],
        secondary_stiffness: [170e3, 190e3, 300e3],
        secondary_damping: [20e3, 25e3, 40e3],
        half_bogie_spacing: 9.0,
        half_wheelbase: 1.3,
        primary_half_spacing: 0.95,
        secondary_half_spacing: 1.1,
        contact_half_spacing: 0.7465,
        body_height: 1.7,
        bogie_height: 0.6,
        secondary_height: 0.95,
        wheel_radius: 0.46,
    }
}

/// The preset is the paper's Table 2, value for value (per axle box and
/// per side), with the stated assumptions for what Table 2 lacks.
#[test]
fn preset_is_the_papers_table_2() {
    let p = AVE_S103_PRESET;
    assert_eq!(p.body_mass, 47_800.0);
    assert_eq!(p.body_roll_inertia, 119_328.0);
    assert_eq!(p.body_pitch_inertia, 1_957_888.0);
    assert_eq!(p.body_yaw_inertia, 1_957_888.0);
    assert_eq!(p.bogie_mass, 3_500.0);
    assert_eq!(p.bogie_roll_inertia, 2_835.0);
    assert_eq!(p.bogie_pitch_inertia, 1_715.0);
    assert_eq!(p.bogie_yaw_inertia, 4_235.0);
    assert_eq!(p.wheelset_mass, 1_800.0);
    assert_eq!(p.wheelset_roll_inertia, 1_000.0);
    assert_eq!(p.primary_stiffness, [12_500e3, 120_000e3, 1_200e3]);
    assert_eq!(p.primary_damping, [9e3, 27.9e3, 10e3]);
    assert_eq!(p.secondary_stiffness, [240e3, 240e3, 350e3]);
    assert_eq!(p.secondary_damping, [30e3, 30e3, 20e3]);
    assert_eq!(2.0 * p.half_bogie_spacing, 17.375);
    assert_eq!(2.0 * p.half_wheelbase, 2.5);
    assert_eq!(p.body_height, 1.5);
    assert_eq!(p.bogie_height, 0.53);
    assert_eq!(p.wheel_radius, 0.43);
}

/// Static wheel loads equal the weight shares: each of the eight rail
/// contacts carries (m_c + 2m_b + 4m_w) g / 8 to 1e-9 (the car is
/// symmetric fore–aft and left–right, so the hyperstatic support on eight
/// contacts still shares equally), and the lateral contacts carry nothing.
/// Preset: (47 800 + 7 000 + 7 200) · 9.81 / 8 = 76 027.5 N.
#[test]
fn static_wheel_loads_are_the_weight_shares() {
    for p in [AVE_S103_PRESET, other()] {
        let model = car(p);
        let (_, forces) = model.static_equilibrium(1, &|_| 0.0).unwrap();
        let share = train_3d::static_contact_load(&p, G);
        assert_eq!(forces.len(), 12);
        for (w, force) in forces.iter().enumerate() {
            let expected = if w % 3 == 2 { 0.0 } else { share };
            assert!(
                (force - expected).abs() <= 1e-9 * share,
                "contact {w}: {force} N against {expected} N"
            );
        }
        let total: f64 = forces.iter().sum();
        let weight = -model.gravity_load.sum();
        assert!((total - weight).abs() <= 1e-9 * weight);
    }
    assert!((train_3d::static_contact_load(&AVE_S103_PRESET, G) - 76_027.5).abs() < 1e-6);
}

/// K and C are symmetric, and K annihilates the rigid motions the model
/// allows: a lift of the whole car (every vertical coordinate +1 m), a
/// lateral shift (every lateral DOF +1 m) and a roll by 1 rad about the
/// track's centre line at rail level (each body's lateral DOF −h, roll 1;
/// each wheelset's lateral −R₀, z_L = +b₀, z_R = −b₀), to 1e-9 of the
/// stiffest spring. A spring attached at a wrong height or side breaks the
/// roll at order 1.
#[test]
fn matrices_are_symmetric_and_rigid_motions_cost_nothing() {
    for p in [AVE_S103_PRESET, other()] {
        let model = car(p);
        let (k, c) = (&model.stiffness, &model.damping);
        assert_eq!((k - k.transpose()).amax(), 0.0);
        assert_eq!((c - c.transpose()).amax(), 0.0);
        let mut lift = DVector::zeros(27);
        let mut shift = DVector::zeros(27);
        let mut roll = DVector::zeros(27);
        for (body, h) in [
            (0, p.body_height),
            (5, p.bogie_height),
            (10, p.bogie_height),
        ] {
            lift[body + 1] = 1.0;
            shift[body] = 1.0;
            roll[body] = -h;
            roll[body + 3] = 1.0;
        }
        for w in 0..4 {
            let (y, left, right) = train_3d::wheelset_dofs(w);
            lift[left] = 1.0;
            lift[right] = 1.0;
            shift[y] = 1.0;
            roll[y] = -p.wheel_radius;
            roll[left] = p.contact_half_spacing;
            roll[right] = -p.contact_half_spacing;
        }
        let stiffest = p.primary_stiffness[1];
        for (name, mode) in [("lift", &lift), ("shift", &shift), ("roll", &roll)] {
            assert!((k * mode).amax() <= 1e-9 * stiffest, "{name}: {}", k * mode);
            assert!((c * mode).amax() <= 1e-9 * p.primary_damping[1], "{name}");
        }
        // The wheelset's mass in contact coordinates: a lift carries m_w,
        // a roll φ = 1 carries I_wx.
        let (_, left, _) = train_3d::wheelset_dofs(2);
        let m = model.mass.fixed_view::<2, 2>(left, left).into_owned();
        let lift2 = nalgebra::Vector2::new(1.0, 1.0);
        let roll2 = nalgebra::Vector2::new(p.contact_half_spacing, -p.contact_half_spacing);
        assert!((lift2.dot(&(m * lift2)) - p.wheelset_mass).abs() < 1e-9 * p.wheelset_mass);
        assert!(
            (roll2.dot(&(m * roll2)) - p.wheelset_roll_inertia).abs()
                < 1e-9 * p.wheelset_roll_inertia
        );
        assert!(lift2.dot(&(m * roll2)).abs() < 1e-9 * p.wheelset_mass);
    }
}

/// Natural frequencies (Hz) of the DOFs `dofs` of `model` with every other
/// DOF held, ascending.
fn held_frequencies(model: &VehicleModel, dofs: std::ops::Range<usize>) -> Vec<f64> {
    let n = dofs.len();
    let k = model
        .stiffness
        .view((dofs.start, dofs.start), (n, n))
        .into_owned();
    let m = model
        .mass
        .view((dofs.start, dofs.start), (n, n))
        .into_owned();
    // M is diagonal on a body: M^(-1/2) K M^(-1/2) is symmetric.
    let scale = DMatrix::from_diagonal(&m.diagonal().map(|v| 1.0 / v.sqrt()));
    let mut values: Vec<f64> = (&scale * k * &scale)
        .symmetric_eigenvalues()
        .iter()
        .map(|l| l.max(0.0).sqrt() / (2.0 * PI))
        .collect();
    values.sort_by(f64::total_cmp);
    values
}

/// The two frequencies (Hz) of a 2-DOF system M = diag(m1, m2),
/// K = [[k11, k12], [k12, k22]]: roots of m1 m2 λ² − (k11 m2 + k22 m1) λ
/// + k11 k22 − k12² = 0.
fn two_dof(m1: f64, m2: f64, k11: f64, k12: f64, k22: f64) -> [f64; 2] {
    let b = k11 * m2 + k22 * m1;
    let disc = (b * b - 4.0 * m1 * m2 * (k11 * k22 - k12 * k12)).sqrt();
    let hz = |l: f64| l.sqrt() / (2.0 * PI);
    [
        hz((b - disc) / (2.0 * m1 * m2)),
        hz((b + disc) / (2.0 * m1 * m2)),
    ]
}

fn hz(stiffness: f64, mass: f64) -> f64 {
    (stiffness / mass).sqrt() / (2.0 * PI)
}

/// Hand-derived frequencies of the car body on its four secondary spring
/// sets with the bogies held (e₂ = h₂ − h_c, the springs' height over the
/// body's centre of gravity):
/// - bounce 4k_z/m_c;
/// - pitch (4k_z a² + 4k_x e₂²)/I_y (the longitudinal springs act through
///   the pitch's motion at their height);
/// - yaw (4k_y a² + 4k_x d₂²)/I_z;
/// - lateral and roll coupled through the height: K = [[4k_y, −4k_y e₂],
///   [−4k_y e₂, 4k_y e₂² + 4k_z d₂²]] on diag(m_c, I_x).
fn hand_body(p: &Train3dParameters) -> Vec<f64> {
    let [kx, ky, kz] = p.secondary_stiffness;
    let (a, d2, e2) = (
        p.half_bogie_spacing,
        p.secondary_half_spacing,
        p.secondary_height - p.body_height,
    );
    let sway = two_dof(
        p.body_mass,
        p.body_roll_inertia,
        4.0 * ky,
        -4.0 * ky * e2,
        4.0 * ky * e2 * e2 + 4.0 * kz * d2 * d2,
    );
    let mut all = vec![
        hz(4.0 * kz, p.body_mass),
        hz(4.0 * kz * a * a + 4.0 * kx * e2 * e2, p.body_pitch_inertia),
        hz(4.0 * ky * a * a + 4.0 * kx * d2 * d2, p.body_yaw_inertia),
        sway[0],
        sway[1],
    ];
    all.sort_by(f64::total_cmp);
    all
}

/// Hand-derived frequencies of a bogie with the body and the wheelsets
/// held: four primary sets at (±b, ±d₁, e₁ = R₀ − h_b) and two secondary
/// sets at (0, ±d₂, e₂ = h₂ − h_b):
/// - bounce (4k₁z + 2k₂z)/m_b;
/// - pitch (4k₁z b² + 4k₁x e₁² + 2k₂x e₂²)/I_y;
/// - yaw (4k₁y b² + 4k₁x d₁² + 2k₂x d₂²)/I_z;
/// - lateral and roll: K = [[4k₁y + 2k₂y, −(4k₁y e₁ + 2k₂y e₂)],
///   [·, 4k₁y e₁² + 2k₂y e₂² + 4k₁z d₁² + 2k₂z d₂²]] on diag(m_b, I_x).
fn hand_bogie(p: &Train3dParameters) -> Vec<f64> {
    let [k1x, k1y, k1z] = p.primary_stiffness;
    let [k2x, k2y, k2z] = p.secondary_stiffness;
    let (b, d1, d2) = (
        p.half_wheelbase,
        p.primary_half_spacing,
        p.secondary_half_spacing,
    );
    let (e1, e2) = (
        p.wheel_radius - p.bogie_height,
        p.secondary_height - p.bogie_height,
    );
    let sway = two_dof(
        p.bogie_mass,
        p.bogie_roll_inertia,
        4.0 * k1y + 2.0 * k2y,
        -(4.0 * k1y * e1 + 2.0 * k2y * e2),
        4.0 * k1y * e1 * e1 + 2.0 * k2y * e2 * e2 + 4.0 * k1z * d1 * d1 + 2.0 * k2z * d2 * d2,
    );
    let mut all = vec![
        hz(4.0 * k1z + 2.0 * k2z, p.bogie_mass),
        hz(
            4.0 * k1z * b * b + 4.0 * k1x * e1 * e1 + 2.0 * k2x * e2 * e2,
            p.bogie_pitch_inertia,
        ),
        hz(
            4.0 * k1y * b * b + 4.0 * k1x * d1 * d1 + 2.0 * k2x * d2 * d2,
            p.bogie_yaw_inertia,
        ),
        sway[0],
        sway[1],
    ];
    all.sort_by(f64::total_cmp);
    all
}

/// Natural frequencies on rigid ground: the body's bounce, pitch, yaw,
/// lateral and roll on the secondary suspension (bogies held) and each
/// bogie's five on its suspensions (body and wheelsets held) equal the
/// hand-derived closed forms above to 1e-9, for the preset and for a car
/// with every value changed. Preset body: lateral/roll 0.4985 and
/// 1.1705 Hz, yaw 0.7800 Hz, bounce 0.8613 Hz, pitch 0.9746 Hz (the
/// closed forms' values, pinned to 1e-4 Hz).
#[test]
fn natural_frequencies_on_rigid_ground_match_closed_forms() {
    for p in [AVE_S103_PRESET, other()] {
        let model = car(p);
        let body = held_frequencies(&model, 0..5);
        let hand = hand_body(&p);
        eprintln!("body   {body:.4?}\nhand   {hand:.4?}");
        for (c, h) in body.iter().zip(&hand) {
            assert!((c - h).abs() <= 1e-9 * h, "body: {c} Hz against {h} Hz");
        }
        for first in [5, 10] {
            let bogie = held_frequencies(&model, first..first + 5);
            let hand = hand_bogie(&p);
            eprintln!("bogie  {bogie:.4?}\nhand   {hand:.4?}");
            for (c, h) in bogie.iter().zip(&hand) {
                assert!((c - h).abs() <= 1e-9 * h, "bogie: {c} Hz against {h} Hz");
            }
        }
    }
    let hand = hand_body(&AVE_S103_PRESET);
    for (h, e) in hand.iter().zip([0.4985, 0.7800, 0.8613, 0.9746, 1.1705]) {
        assert!((h - e).abs() < 1e-4, "{hand:?}");
    }
}

/// A 32 m beam (f₁ = 1.62 Hz) and a harmonic rail of 2 mm amplitude and
/// 11 m wavelength on both rails, the car at 200 km/h with `extra` added
/// to its line.
fn scene(vehicle: &str) -> String {
    format!(
        r#"
name: train-3d
bridge:
  type: beam
  spans: [32.0]
  bending_stiffness: 1.3448174e10
  mass_per_length: 12000.0
  modes: {{count: 6}}
  damping: {{type: modal, ratio: 0.02}}
vehicles: [{vehicle}]
surface: {{type: harmonic, amplitude: 2.0e-3, wavelength: 11.0}}
contact: {{type: permanent}}
solver: {{time_step: 2.0e-4, free_vibration: 1.0}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 16.0}}
  - {{name: body_bounce, quantity: vehicle_displacement, dof: body_bounce}}
  - {{name: body_pitch, quantity: vehicle_displacement, dof: body_pitch}}
  - {{name: front_bogie, quantity: vehicle_displacement, dof: front_bogie_bounce}}
  - {{name: rear_pitch, quantity: vehicle_displacement, dof: rear_bogie_pitch}}
"#
    )
}

/// Extra records of the 3D car.
const LATERAL_RECORDS: &str = r#"
  - {name: body_lateral, quantity: vehicle_displacement, dof: body_lateral}
  - {name: body_roll, quantity: vehicle_displacement, dof: body_roll}
  - {name: body_yaw, quantity: vehicle_displacement, dof: body_yaw}
  - {name: bogie_lateral, quantity: vehicle_displacement, dof: front_bogie_lateral}
  - {name: bogie_roll, quantity: vehicle_displacement, dof: rear_bogie_roll}
  - {name: bogie_yaw, quantity: vehicle_displacement, dof: rear_bogie_yaw}
  - {name: w1_left, quantity: contact_force, wheel: 1}
  - {name: w1_right, quantity: contact_force, wheel: 2}
  - {name: w1_lateral, quantity: contact_force, wheel: 3}
  - {name: w4_left, quantity: contact_force, wheel: 10}
  - {name: w4_right, quantity: contact_force, wheel: 11}
"#;

/// Left–right symmetry on a straight track with identical rails: the
/// lateral, yaw and roll DOFs of body and bogies stay at rounding level
/// (< 1e-9 of the body's bounce swing, measured 3e-12; an asymmetric
/// spring gives order 1e-2), the lateral contacts carry < 1e-9 of the wheel load, and the
/// left and right contact forces of each wheelset agree to 1e-10 of the
/// static load.
#[test]
fn a_symmetric_car_on_identical_rails_stays_symmetric() {
    let outcome = run_yaml(&(scene("{type: train_3d, speed: 200 km/h}") + LATERAL_RECORDS));
    let bounce = max_abs(column(&outcome, "body_bounce"));
    assert!(bounce > 1e-4, "the car must move: {bounce}");
    for name in [
        "body_lateral",
        "body_roll",
        "body_yaw",
        "bogie_lateral",
        "bogie_roll",
        "bogie_yaw",
    ] {
        let swing = max_abs(column(&outcome, name));
        eprintln!("{name}: {:.2e} of the bounce", swing / bounce);
        assert!(swing <= 1e-9 * bounce, "{name}: {swing}");
    }
    let load = train_3d::static_contact_load(&AVE_S103_PRESET, G);
    assert!(max_abs(column(&outcome, "w1_lateral")) <= 1e-9 * load);
    for (left, right) in [("w1_left", "w1_right"), ("w4_left", "w4_right")] {
        let (l, r) = (column(&outcome, left), column(&outcome, right));
        let gap = l
            .iter()
            .zip(r)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(gap <= 1e-10 * load, "{left}/{right}: {gap} N");
        assert!(max_abs(l) > load, "{left} must carry the load");
    }
}

/// The vertical-only motion of the 3D car equals the 2D rail car with the
/// same data: with no longitudinal springs (they add pitch stiffness
/// through the heights, which the 2D car does not have), the 3D car on
/// identical rails against the 10-DOF car with body/bogie/wheelset masses
/// and pitch inertias the same and each suspension's two sides summed
/// (k_p = 2k₁z, c_p = 2c₁z per wheelset; k_s = 2k₂z, c_s = 2c₂z per bogie):
/// deck, body bounce and pitch, bogie bounce and pitch agree to 1e-9 of
/// their swing, and each 2D wheelset force equals the sum of the 3D left
/// and right forces to 1e-9 of the static load.
#[test]
fn vertical_motion_equals_the_two_dimensional_car() {
    let p = AVE_S103_PRESET;
    let three = run_yaml(
        &(scene(
            "{type: train_3d, speed: 200 km/h, parameters: {primary_longitudinal_stiffness: 0, \
             primary_longitudinal_damping: 0, secondary_longitudinal_stiffness: 0, \
             secondary_longitudinal_damping: 0}}",
        ) + r#"
  - {name: w1_left, quantity: contact_force, wheel: 1}
  - {name: w1_right, quantity: contact_force, wheel: 2}
  - {name: w4_left, quantity: contact_force, wheel: 10}
  - {name: w4_right, quantity: contact_force, wheel: 11}
"#),
    );
    let two = run_yaml(
        &(scene(&format!(
            "{{type: rail_car, speed: 200 km/h, parameters: {{body_mass: {}, \
             body_pitch_inertia: {}, bogie_mass: {}, bogie_pitch_inertia: {}, wheelset_mass: {}, \
             primary_stiffness: {}, primary_damping: {}, secondary_stiffness: {}, \
             secondary_damping: {}, half_bogie_spacing: {}, half_wheelbase: {}}}}}",
            p.body_mass,
            p.body_pitch_inertia,
            p.bogie_mass,
            p.bogie_pitch_inertia,
            p.wheelset_mass,
            2.0 * p.primary_stiffness[2],
            2.0 * p.primary_damping[2],
            2.0 * p.secondary_stiffness[2],
            2.0 * p.secondary_damping[2],
            p.half_bogie_spacing,
            p.half_wheelbase,
        )) + r#"
  - {name: w1, quantity: contact_force, wheel: 1}
  - {name: w4, quantity: contact_force, wheel: 4}
"#),
    );
    for name in [
        "midspan",
        "body_bounce",
        "body_pitch",
        "front_bogie",
        "rear_pitch",
    ] {
        let (a, b) = (column(&three, name), column(&two, name));
        assert_eq!(a.len(), b.len());
        let swing = max_abs(b);
        let gap = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        eprintln!("{name}: swing {swing:.3e}, gap {gap:.3e}");
        assert!(
            swing > 0.0 && gap <= 1e-9 * swing,
            "{name}: {gap} of {swing}"
        );
    }
    let load = train_3d::static_contact_load(&p, G);
    for (w, left, right) in [("w1", "w1_left", "w1_right"), ("w4", "w4_left", "w4_right")] {
        let sum: Vec<f64> = column(&three, left)
            .iter()
            .zip(column(&three, right))
            .map(|(l, r)| l + r)
            .collect();
        let gap = sum
            .iter()
            .zip(column(&two, w))
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        eprintln!("{w}: gap {gap:.3e} N");
        assert!(gap <= 1e-9 * load, "{w}: {gap} N");
    }
}

/// Bad 3D trains are refused with a located message (exit 2 through the
/// CLI): unilateral contact, overlapping cars, a wheelbase longer than the
/// bogie spacing, a zero contact spacing, a DOF of the 2D car.
#[test]
fn bad_3d_trains_are_refused_with_a_located_message() {
    let base = scene("{type: train_3d, speed: 200 km/h}");
    for (edit, field, words) in [
        (
            base.replace("contact: {type: permanent}", "contact: {type: rigid}"),
            "contact",
            "train_3d",
        ),
        (
            base.replace(
                "{type: train_3d, speed: 200 km/h}",
                "{type: train_3d, speed: 200 km/h, count: 2, car_spacing: 10.0}",
            ),
            "car_spacing",
            "overlaps",
        ),
        (
            base.replace(
                "{type: train_3d, speed: 200 km/h}",
                "{type: train_3d, speed: 200 km/h, parameters: {half_wheelbase: 9.0}}",
            ),
            "parameters",
            "half_wheelbase",
        ),
        (
            base.replace(
                "{type: train_3d, speed: 200 km/h}",
                "{type: train_3d, speed: 200 km/h, parameters: {contact_half_spacing: 0}}",
            ),
            "contact_half_spacing",
            "positive",
        ),
        (
            base.replace("dof: body_pitch}", "dof: wheelset1}"),
            "wheelset1`",
            "unknown DOF",
        ),
    ] {
        let error = vbi::plan::load_str(&edit, "t.yaml")
            .unwrap_err()
            .to_string();
        assert!(
            error.contains(field) && error.contains(words),
            "{field}: {error}"
        );
    }
    // An implausible value is named and blamed where the file gives it.
    // (Before, the message said only "a length" and pointed at the vehicle.)
    for field in [
        "secondary_vertical_stiffness",
        "wheelset_roll_inertia",
        "body_height",
    ] {
        let edit = base.replace(
            "{type: train_3d, speed: 200 km/h}",
            &format!("{{type: train_3d, speed: 200 km/h, parameters: {{{field}: 1.0e30}}}}"),
        );
        let (line, text) = edit
            .lines()
            .enumerate()
            .find(|(_, l)| l.contains(field))
            .unwrap();
        // At the value.
        let column = text.find("1.0e30").unwrap() + 1;
        let error = vbi::plan::load_str(&edit, "t.yaml")
            .unwrap_err()
            .to_string();
        let place = format!("t.yaml:{}:{column}: car 1: {field}, ", line + 1);
        assert!(
            error.contains(&place) && error.contains("physically plausible"),
            "expected {place}…, got: {error}"
        );
    }
}

/// The wheelsets follow the track's alignment sideways: on an FRA class 5
/// track with `alignment: true`, wheelset 2 repeats wheelset 1's lateral
/// displacement one wheelbase (2.5 m = 50 steps at 50 m/s and 1 ms)
/// later, to 1e-9 of its swing (the bridge is a plane beam: only the
/// alignment moves them sideways), and the body sways (> 1e-3 of the
/// wheelsets' swing), where with straight rails it stays at rest (the
/// symmetry test).
#[test]
fn wheelsets_follow_the_alignment() {
    let outcome = run_yaml(
        r#"
name: alignment
bridge: {type: beam, spans: [20.0], bending_stiffness: 1.0e11, mass_per_length: 20000.0, modes: {count: 4}}
vehicles: [{type: train_3d, speed: 50.0, start_position: -30.0}]
surface: {type: fra, class: 5, alignment: true, rails: independent, seed: 4}
contact: {type: permanent}
solver: {time_step: 1.0e-3}
record:
  - {name: w1, quantity: vehicle_displacement, dof: wheelset1_lateral}
  - {name: w2, quantity: vehicle_displacement, dof: wheelset2_lateral}
  - {name: body, quantity: vehicle_displacement, dof: body_lateral}
"#,
    );
    let (w1, w2) = (column(&outcome, "w1"), column(&outcome, "w2"));
    let swing = max_abs(w1);
    assert!(swing > 1e-4, "the alignment moves the wheelsets: {swing}");
    let gap = (0..w1.len() - 50)
        .map(|n| (w2[n + 50] - w1[n]).abs())
        .fold(0.0, f64::max);
    eprintln!("swing {swing:.3e} m, gap {gap:.3e}");
    assert!(gap <= 1e-9 * swing, "{gap} of {swing}");
    let body = max_abs(column(&outcome, "body"));
    assert!(body > 1e-3 * swing, "the body sways: {body}");
}
