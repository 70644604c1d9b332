//! Every vehicle preset pinned to the numbers of its source (issue 40.4).
//! Each test names the source (paper and table, or standard and clause)
//! and its tolerance. The sources' values are written out here, not read
//! from the code, so a changed preset fails against the source.

use vbi::scenario::LoadError;
use vbi::scenario::rail::LCP_RAIL_CAR_PRESET;
use vbi::scenario::rail_3d::AVE_S103_PRESET;
use vbi::scenario::resolved::{HslmModel, Vehicle};
use vbi::scenario::truck::H20_44_PRESET;
use vbi::vehicle::h20_44;

/// 1 kip = 1 000 lbf; 1 lbf = 0.453 592 37 kg × 9.806 65 m/s² (exact).
const KIP: f64 = 1000.0 * 0.453_592_37 * 9.806_65;
/// 1 ft = 0.3048 m (exact).
const FT: f64 = 0.3048;

/// `value` within `tolerance` (absolute) of `source`.
fn near(what: &str, value: f64, source: f64, tolerance: f64) {
    assert!(
        (value - source).abs() <= tolerance,
        "{what}: {value} against the source's {source} (± {tolerance})"
    );
}

/// The one vehicle of a beam scene whose vehicle entry is `vehicle`, resolved.
fn resolved(vehicle: &str) -> Result<Vehicle, LoadError> {
    let text = format!(
        "name: preset\nbridge: {{type: beam, spans: [25.0], bending_stiffness: 8.323e9, \
         mass_per_length: 2303.0, modes: {{count: 2}}}}\nvehicles: [{vehicle}]\n\
         solver: {{time_step: 1.0e-3}}\n\
         record: [{{name: midspan, quantity: bridge_displacement, x: 12.5}}]\n"
    );
    let loaded = vbi::plan::load_str(&text, "preset.yaml")?;
    Ok(loaded
        .scenario
        .vehicles
        .into_iter()
        .next()
        .expect("a vehicle"))
}

/// The axle loads (N) and spacings (m) of a moving-force vehicle.
fn axles(vehicle: &str) -> (Vec<f64>, Vec<f64>) {
    match resolved(vehicle).unwrap_or_else(|e| panic!("{vehicle}: {e}")) {
        Vehicle::MovingForce(m) => (m.loads, m.axle_spacings),
        other => panic!("{vehicle} resolved into {}", other.type_name()),
    }
}

/// `type: aashto_h20_44` is AASHTO's H20-44 (AASHTO Standard Specifications
/// for Highway Bridges, 17th ed., Art. 3.7.6, Fig. 3.7.6A): 8 000 lb
/// (0.2 W) front, 32 000 lb (0.8 W) rear, 14 ft apart, converted exactly
/// (±1e-9 relative, round-off); to the three significant figures of the
/// issue (35.6 kN, 142.3 kN, 4.27 m) as well.
#[test]
fn aashto_h20_44_is_the_standard_s_axles() {
    let (loads, spacings) = axles("{type: aashto_h20_44, speed: 20.0}");
    assert_eq!((loads.len(), spacings.len()), (2, 1));
    near("front axle, N", loads[0], 8.0 * KIP, 1e-9 * KIP);
    near("rear axle, N", loads[1], 32.0 * KIP, 1e-9 * KIP);
    near("axle spacing, m", spacings[0], 14.0 * FT, 1e-12);
    near("front axle, kN", loads[0] / 1e3, 35.6, 0.05);
    near("rear axle, kN", loads[1] / 1e3, 142.3, 0.05);
    near(
        "total, lb",
        loads.iter().sum::<f64>() / KIP * 1000.0,
        40_000.0,
        1e-6,
    );
}

/// `type: aashto_hs20_44` is AASHTO's HS20-44 (Standard Specifications,
/// 17th ed., Art. 3.7.7, Fig. 3.7.7A; the LRFD design truck, Art.
/// 3.6.1.2.2, Fig. 3.6.1.2.2-1): 8, 32 and 32 kip, 14 ft and V = 14 ft to
/// 30 ft apart (±1e-9 relative); V defaults to 14 ft. The LRFD SI editions
/// round them to 35 kN, 145 kN, 145 kN, 4.3 m and 4.3–9.0 m: within their
/// rounding (2 %) too. A V outside 14–30 ft is refused at its key.
#[test]
fn aashto_hs20_44_is_the_standard_s_axles_with_its_variable_spacing() {
    let (loads, spacings) = axles("{type: aashto_hs20_44, speed: 20.0}");
    assert_eq!((loads.len(), spacings.len()), (3, 2));
    for (load, kip) in loads.iter().zip([8.0, 32.0, 32.0]) {
        near("axle load, N", *load, kip * KIP, 1e-9 * KIP);
    }
    near("front spacing, m", spacings[0], 14.0 * FT, 1e-12);
    near("default rear spacing V, m", spacings[1], 14.0 * FT, 1e-12);
    for (load, lrfd_si) in loads.iter().zip([35e3, 145e3, 145e3]) {
        near("LRFD SI axle, N", *load, lrfd_si, 0.02 * lrfd_si);
    }
    near("LRFD SI spacing, m", spacings[0], 4.3, 0.02 * 4.3);

    let (_, longest) = axles("{type: aashto_hs20_44, speed: 20.0, rear_axle_spacing: 9.144}");
    near("longest V, m", longest[1], 30.0 * FT, 1e-12);
    near("LRFD SI longest V, m", longest[1], 9.0, 0.02 * 9.0);

    for outside in ["4.0", "9.2"] {
        let entry = format!("{{type: aashto_hs20_44, speed: 20.0, rear_axle_spacing: {outside}}}");
        let Err(LoadError::Invalid(errors)) = resolved(&entry) else {
            panic!("V = {outside} m is outside 14–30 ft and must be refused");
        };
        assert!(
            errors
                .iter()
                .any(|e| e.message.contains("rear axle spacing") && e.message.contains("30 ft")),
            "{errors:?}"
        );
    }
}

/// The plate paper's truck (`type: h20_44`) keeps the static wheel forces
/// the paper states for its empty truck (Section 3.2, with Fig. 16:
/// Fg1 = 58.81 kN per front wheel, Fg3 = 32.42 kN per rear wheel; ±5 N, half
/// the paper's last digit) at g = 9.81 m/s², and AASHTO's H20-44 geometry
/// (Fig. 3.7.6A: 14 ft between the axles, 6 ft between the wheels) to the
/// preset's two decimals (±5 mm). Its loads are NOT AASHTO's: its front
/// axle carries 3.3 times AASHTO's 8 kip, its rear axle less than half of
/// 32 kip.
#[test]
fn the_plate_paper_s_truck_is_the_paper_s_not_aashto_s_loads() {
    let wheels = h20_44::static_wheel_loads(&H20_44_PRESET, 9.81);
    for (wheel, paper) in wheels.iter().zip([58_810.0, 58_810.0, 32_420.0, 32_420.0]) {
        near("static wheel force, N", *wheel, paper, 5.0);
    }
    let p = H20_44_PRESET;
    near(
        "axle spacing, m",
        p.front_axle_to_centre + p.centre_to_rear_axle,
        14.0 * FT,
        0.005,
    );
    near("front track, m", p.front_track, 6.0 * FT, 0.005);
    near("rear track, m", p.rear_track, 6.0 * FT, 0.005);
    let front_axle = wheels[0] + wheels[1];
    let rear_axle = wheels[2] + wheels[3];
    assert!(front_axle > 3.0 * 8.0 * KIP && rear_axle < 0.5 * 32.0 * KIP);
    // The scene's `h20_44` is this preset.
    let Ok(Vehicle::H20Truck(truck)) = resolved("{type: h20_44, speed: 20.0}") else {
        panic!("h20_44 resolves into the 7-DOF truck");
    };
    assert_eq!(truck.parameters, H20_44_PRESET);
}

/// The rail car preset is the LCP separation paper's Table 2 ("Parameters
/// of the vehicle", Section 5.2), digit for digit (exact: the table's values
/// converted from kN to N). The table labels J_c and J_b "roll" moments;
/// the car of its Fig. 3 pitches, and the preset uses them as pitch.
#[test]
fn the_rail_car_is_the_lcp_paper_s_table_2() {
    let p = LCP_RAIL_CAR_PRESET;
    for (what, value, table) in [
        ("mass of vehicle body, kg", p.body_mass, 31_994.0),
        (
            "mass moment of body, kg m2",
            p.body_pitch_inertia,
            2_100_000.0,
        ),
        ("mass of bogie, kg", p.bogie_mass, 3_333.0),
        (
            "mass moment of bogie, kg m2",
            p.bogie_pitch_inertia,
            3_200.0,
        ),
        ("mass of wheel-pair, kg", p.wheelset_mass, 1_650.0),
        (
            "first suspension stiffness, N/m",
            p.primary_stiffness,
            4_720e3,
        ),
        (
            "2nd suspension stiffness, N/m",
            p.secondary_stiffness,
            160e3,
        ),
        ("first suspension damping, N s/m", p.primary_damping, 160e3),
        ("2nd suspension damping, N s/m", p.secondary_damping, 200e3),
        ("half-distance of two bogies, m", p.half_bogie_spacing, 8.75),
        (
            "half-distance of two wheel-pairs, m",
            p.half_wheelbase,
            1.25,
        ),
    ] {
        near(what, value, table, 0.0);
    }
    let Ok(Vehicle::RailCar(car)) = resolved("{type: rail_car, speed: 20.0}") else {
        panic!("rail_car resolves into the rail car");
    };
    assert_eq!(car.parameters, LCP_RAIL_CAR_PRESET);
}

/// The 3D car preset is the AVE-S103 of the EMBS paper's Table 2
/// ("Mechanical and geometrical properties of the AVE-S103 high-speed
/// train"), digit for digit (±1e-9 relative: kN to N and d_b / 2). The
/// table's wheelset yaw inertia has no DOF in the model (the wheelsets
/// follow their rails), and the lateral spacings it does not give are the
/// preset's stated assumptions, not pinned here.
#[test]
fn the_3d_car_is_the_embs_paper_s_table_2() {
    let p = AVE_S103_PRESET;
    let exact = |what: &str, value: f64, table: f64| near(what, value, table, 1e-9 * table.abs());
    exact("car body mass, kg", p.body_mass, 47_800.0);
    exact(
        "car body roll inertia, kg m2",
        p.body_roll_inertia,
        119_328.0,
    );
    exact(
        "car body pitch inertia, kg m2",
        p.body_pitch_inertia,
        1_957_888.0,
    );
    exact(
        "car body yaw inertia, kg m2",
        p.body_yaw_inertia,
        1_957_888.0,
    );
    exact("bogie mass, kg", p.bogie_mass, 3_500.0);
    exact("bogie roll inertia, kg m2", p.bogie_roll_inertia, 2_835.0);
    exact("bogie pitch inertia, kg m2", p.bogie_pitch_inertia, 1_715.0);
    exact("bogie yaw inertia, kg m2", p.bogie_yaw_inertia, 4_235.0);
    exact("wheelset mass, kg", p.wheelset_mass, 1_800.0);
    exact(
        "wheelset roll inertia, kg m2",
        p.wheelset_roll_inertia,
        1_000.0,
    );
    for (k, (value, table)) in p
        .primary_stiffness
        .iter()
        .zip([12_500e3, 120_000e3, 1_200e3])
        .enumerate()
    {
        exact(&format!("primary stiffness {k}, N/m"), *value, table);
    }
    for (k, (value, table)) in p
        .primary_damping
        .iter()
        .zip([9e3, 27.9e3, 10e3])
        .enumerate()
    {
        exact(&format!("primary damping {k}, N s/m"), *value, table);
    }
    for (k, (value, table)) in p
        .secondary_stiffness
        .iter()
        .zip([240e3, 240e3, 350e3])
        .enumerate()
    {
        exact(&format!("secondary stiffness {k}, N/m"), *value, table);
    }
    for (k, (value, table)) in p
        .secondary_damping
        .iter()
        .zip([30e3, 30e3, 20e3])
        .enumerate()
    {
        exact(&format!("secondary damping {k}, N s/m"), *value, table);
    }
    exact("bogie spacing d_b, m", 2.0 * p.half_bogie_spacing, 17.375);
    exact("wheelset spacing d_w, m", 2.0 * p.half_wheelbase, 2.50);
    exact("car body centre of gravity h_cb, m", p.body_height, 1.50);
    exact("bogie centre of gravity h_b, m", p.bogie_height, 0.530);
    exact("rolling radius R_0, m", p.wheel_radius, 0.43);
}

/// The HSLM-A trains are EN 1991-2:2003 Table E.1 (number of intermediate
/// coaches N, coach length D, bogie axle spacing d, point force P), row by
/// row (exact), and `type: hslm` resolves into P at every one of the
/// 2 (N + 7) axles of Fig. E.2.
#[test]
fn the_hslm_trains_are_en_1991_2_table_e1() {
    const TABLE_E1: [(usize, f64, f64, f64); 10] = [
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
    for (model, (n, big_d, d, p_kn)) in HslmModel::ALL.into_iter().zip(TABLE_E1) {
        let train = model.train();
        let label = model.label();
        assert_eq!(train.coaches, n, "{label}: N");
        near(&format!("{label}: D, m"), train.coach_length, big_d, 0.0);
        near(&format!("{label}: d, m"), train.bogie_axle_spacing, d, 0.0);
        near(&format!("{label}: P, N"), train.axle_force, p_kn * 1e3, 0.0);
        let (loads, _) = axles(&format!(
            "{{type: hslm, model: A{}, speed: 20.0}}",
            model as usize + 1
        ));
        assert_eq!(loads.len(), 2 * (n + 7), "{label}: axles");
        assert!(loads.iter().all(|&l| l == p_kn * 1e3), "{label}: P");
    }
}
