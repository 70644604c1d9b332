//! Units where engineers write them (issue 28.2): every physical number may
//! be a string with its unit (`25 m`, `40 t`, `1.6e6 N/m`, `170 kN`,
//! `30 Hz`, `0.35 g`, …), which must resolve to exactly the scene the SI
//! numbers give (bit for bit: the resolved scenes' Debug texts, which print
//! each f64 at round-trip precision, are equal), must be refused with its
//! location when the unit is of another dimension, and resolved.yaml must
//! write SI numbers.

use crate::support::{Scratch, manifest_dir, text, vbi};

/// Pairs of (SI, with units) for one scene. Speeds stay plain: a speed
/// with its unit is marked as stated (`speeds_stated`, which silences the
/// km/h-typed-as-m/s warning), the one intended difference.
fn same_scene(si: &str, units: &str) {
    let a = vbi::plan::load_str(si, "si.yaml").unwrap_or_else(|e| panic!("SI scene: {e}"));
    let b = vbi::plan::load_str(units, "units.yaml")
        .unwrap_or_else(|e| panic!("scene with units: {e}"));
    let (a, b) = (format!("{:?}", a.scenario), format!("{:?}", b.scenario));
    assert_eq!(a, b, "the scene with units differs from the SI one");
}

const BEAM_OSCILLATOR_SI: &str = "\
name: units
gravity: 9.81
bridge:
  type: beam
  spans: [25.0, 0.25]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
  modes: {count: 4, max_frequency: 3000.0}
vehicles:
  - type: oscillator
    sprung_mass: 5750.0
    unsprung_mass: 575.0
    stiffness: 1.595e6
    damping: 3500.0
    speed: 27.5
    acceleration: -3.4323275
    start_position: -0.0011
contact: {type: elastic, stiffness: 1.0e9}
solver: {time_step: 0.0025, free_vibration: 0.1}
record:
  - {name: midspan, quantity: bridge_displacement, x: 12.5}
  - {name: acceleration, quantity: bridge_acceleration, x: 12.5, max_frequency: 30.0}
";

const BEAM_OSCILLATOR_UNITS: &str = "\
name: units
gravity: 9.81 m/s^2
bridge:
  type: beam
  spans: [25 m, 250 mm]
  bending_stiffness: 8.323 GN*m^2
  mass_per_length: 2.303 t/m
  modes: {count: 4, max_frequency: 3 kHz}
vehicles:
  - type: oscillator
    sprung_mass: 5.75 t
    unsprung_mass: 575 kg
    stiffness: 1595 kN/m
    damping: 3.5 kN*s/m
    speed: 27.5
    acceleration: -0.35 g
    start_position: -1.1 mm
contact: {type: elastic, stiffness: 1000 MN/m}
solver: {time_step: 2.5 ms, free_vibration: 100 ms}
record:
  - {name: midspan, quantity: bridge_displacement, x: 0.0125 km}
  - {name: acceleration, quantity: bridge_acceleration, x: 1250 cm, max_frequency: 30 Hz}
";

#[test]
fn unit_strings_resolve_to_the_si_scene_bit_for_bit() {
    // 0.35 g is 0.35 × 9.80665 m/s² (standard gravity, exact) = 3.4323275
    // m/s² exactly in decimal, which `-0.35 g` must give bit for bit (a
    // floating-point product would be 3.4323274999999995).
    same_scene(BEAM_OSCILLATOR_SI, BEAM_OSCILLATOR_UNITS);
}

#[test]
fn forces_lengths_and_truck_parameters_with_units() {
    let si = "\
name: units
bridge: {type: beam, spans: [30.0], bending_stiffness: 1.2e11, mass_per_length: 18000.0}
vehicles:
  - type: moving_force
    loads: [170000.0, 1000000.0]
    axle_spacings: [4.3]
    speed: 20.0
    entry_time: 0.5
  - type: h20_44
    speed: 25.0
    parameters:
      body_mass: 20000.0
      body_pitch_inertia: 170000.0
      front_axle_to_centre: 3.2
      front_suspension_stiffness: 500000.0
      front_suspension_damping: 2500.0
      front_tyre_stiffness: 1750000.0
surface: {type: bump, start: 10.0, length: 0.5, height: 0.02}
";
    let units = si
        .replace("loads: [170000.0, 1000000.0]", "loads: [170 kN, 1 MN]")
        .replace("axle_spacings: [4.3]", "axle_spacings: [4300 mm]")
        .replace("entry_time: 0.5", "entry_time: 500 ms")
        .replace("body_mass: 20000.0", "body_mass: 20 t")
        .replace(
            "body_pitch_inertia: 170000.0",
            "body_pitch_inertia: 170 t*m^2",
        )
        .replace("front_axle_to_centre: 3.2", "front_axle_to_centre: 3.2 m")
        .replace("stiffness: 500000.0", "stiffness: 500 kN/m")
        .replace("damping: 2500.0", "damping: 2.5 kNs/m")
        .replace("tyre_stiffness: 1750000.0", "tyre_stiffness: 1.75 MN/m")
        .replace("height: 0.02", "height: 20 mm")
        .replace("spans: [30.0]", "spans: [30 m]")
        .replace(
            "bending_stiffness: 1.2e11",
            "bending_stiffness: 1.2e8 kN·m²",
        )
        .replace("mass_per_length: 18000.0", "mass_per_length: 18 t/m");
    assert!(
        !units.contains("500000.0") && !units.contains("0.02}"),
        "{units}"
    );
    same_scene(si, &units);
}

#[test]
fn plate_moduli_densities_and_rigidities_with_units() {
    let si = "\
name: units
bridge:
  type: plate
  spans: [12.0]
  width: 10.0
  thickness: 0.8
  density: 2500.0
  rigidity: {type: isotropic, youngs_modulus: 3.5e10}
  modes: {count: 4}
vehicles:
  - {type: moving_force, loads: [100000.0], speed: 20.0, lateral_position: 5.0}
";
    let units = si
        .replace("width: 10.0", "width: 10 m")
        .replace("thickness: 0.8", "thickness: 800 mm")
        .replace("density: 2500.0", "density: 2.5 t/m^3")
        .replace("youngs_modulus: 3.5e10", "youngs_modulus: 35 GPa")
        .replace("loads: [100000.0]", "loads: [100 kN]");
    same_scene(si, &units);
    let orthotropic = "\
name: units
bridge:
  type: plate
  spans: [12.0]
  width: 10.0
  mass_per_area: 2000.0
  rigidity: {type: orthotropic, flexural_rigidity_x: 1.0e9, flexural_rigidity_y: 2.0e8, torsional_rigidity: 1.0e8}
  modes: {count: 4}
vehicles:
  - {type: moving_force, loads: [100000.0], speed: 20.0}
";
    let with_units = orthotropic
        .replace("mass_per_area: 2000.0", "mass_per_area: 2 t/m²")
        .replace(
            "flexural_rigidity_x: 1.0e9",
            "flexural_rigidity_x: 1000 MN*m",
        )
        .replace(
            "flexural_rigidity_y: 2.0e8",
            "flexural_rigidity_y: 2e5 kN*m",
        )
        .replace("torsional_rigidity: 1.0e8", "torsional_rigidity: 1e8 N·m");
    same_scene(orthotropic, &with_units);
}

#[test]
fn a_unit_of_the_wrong_dimension_is_refused_where_it_is_written() {
    let scratch = Scratch::new("units", "wrong-dimension");
    let scene = BEAM_OSCILLATOR_SI
        .replace("spans: [25.0, 0.25]", "spans: [25 s, 0.25]")
        .replace("sprung_mass: 5750.0", "sprung_mass: 5750 N")
        .replace("stiffness: 1.595e6", "stiffness: 1.595e6 furlongs");
    let path = scratch.path("wrong.yaml");
    std::fs::write(&path, scene).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let file = path.display().to_string();
    for (line, col, message) in [
        (
            5,
            11,
            "expected a length (m, mm, cm, km), found a time (`s`) in `25 s`",
        ),
        (
            11,
            18,
            "expected a mass (kg, t), found a force (`N`) in `5750 N`",
        ),
        (13, 16, "found the unknown unit `furlongs`"),
    ] {
        let head = format!("{file}:{line}:{col}: ");
        let found = stderr
            .lines()
            .any(|l| l.contains(&head) && l.contains(message));
        assert!(found, "no `{head}…{message}` in\n{stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn resolved_yaml_writes_si_numbers() {
    let scratch = Scratch::new("units", "resolved");
    let mut resolved = Vec::new();
    for (name, scene) in [("si", BEAM_OSCILLATOR_SI), ("units", BEAM_OSCILLATOR_UNITS)] {
        let path = scratch.path(&format!("{name}.yaml"));
        std::fs::write(&path, scene).unwrap();
        let out_dir = scratch.path(&format!("{name}-out"));
        let out = vbi(
            &[
                "run".as_ref(),
                path.as_os_str(),
                "--out".as_ref(),
                out_dir.as_os_str(),
                "--quiet".as_ref(),
            ],
            manifest_dir(),
        );
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let yaml = std::fs::read_to_string(out_dir.join("resolved.yaml")).unwrap();
        // The file it came from is named in a comment: not the scene.
        let body: Vec<&str> = yaml
            .lines()
            .filter(|l| !l.starts_with('#') && !l.contains(".yaml"))
            .collect();
        resolved.push(body.join("\n"));
    }
    assert_eq!(resolved[0], resolved[1]);
    assert!(!resolved[1].contains(" t/m") && !resolved[1].contains("GN"));
    assert!(resolved[1].contains("2303"), "{}", resolved[1]);
}

/// The mixed units of issue 28.2's leftovers (GJ in N·m²/rad, I_p in
/// kg·m²/m, Hertz C in N/m^1.5, Rayleigh frequencies in Hz, a phase in
/// rad or deg), written with their units, resolve to the SI scene.
#[test]
fn torsion_hertz_rayleigh_and_phase_with_units() {
    let si = "\
name: units
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 4.0e10
  mass_per_length: 15000.0
  lateral_bending_stiffness: 1.0e11
  torsional_stiffness: 4.0e9
  polar_mass: 60000.0
  damping: {type: rayleigh, frequencies: [2.0, 30.0], ratio: 0.02}
  modes: {count: 6}
vehicles:
  - {type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}
surface: {type: harmonic, amplitude: 0.003, wavelength: 1.5, phase: PHASE}
contact: {type: hertz, coefficient: 1.0e11}
";
    let units = si
        .replace(
            "torsional_stiffness: 4.0e9",
            "torsional_stiffness: 4 GN*m^2/rad",
        )
        .replace("polar_mass: 60000.0", "polar_mass: 60 t*m^2/m")
        .replace("frequencies: [2.0, 30.0]", "frequencies: [2 Hz, 0.03 kHz]")
        .replace("coefficient: 1.0e11", "coefficient: 100 GN/m^1.5");
    // A phase in mrad is a decimal shift (bit for bit 0.5); in degrees it
    // is one multiplication by the f64 nearest π/180, the documented rule.
    same_scene(
        &si.replace("PHASE", "0.5"),
        &units.replace("PHASE", "500 mrad"),
    );
    let degrees = 30.0 * (std::f64::consts::PI / 180.0);
    same_scene(
        &si.replace("PHASE", &format!("{degrees:?}")),
        &units.replace("PHASE", "30 deg"),
    );
    same_scene(
        &si.replace("PHASE", &format!("{degrees:?}")),
        &units
            .replace("PHASE", "30°")
            .replace("4 GN*m^2/rad", "4e6 kN·m²"),
    );
}

/// A road's roughness coefficient A_r (m³/cycle; ISO 8608 tabulates it in
/// 10⁻⁶ m³ = cm³) and a piecewise-linear profile's `[x, r]` points.
#[test]
fn roughness_coefficients_and_profile_points_with_units() {
    let si = "\
name: units
bridge: {type: beam, spans: [30.0], bending_stiffness: 1.2e11, mass_per_length: 18000.0}
vehicles:
  - {type: moving_force, loads: [100000.0], speed: 20.0}
surface: {type: random, coefficient: 1.6e-5, seed: 3}
";
    for written in ["16 cm^3", "16 cm³/cycle", "1.6e-5 m^3/cycle", "1.6e-5 m³"] {
        same_scene(
            si,
            &si.replace("coefficient: 1.6e-5", &format!("coefficient: {written}")),
        );
    }
    let points = si.replace(
        "{type: random, coefficient: 1.6e-5, seed: 3}",
        "{type: piecewise_linear, points: [[0.0, 0.0], [5.0, 0.02], [5.5, 0.0]]}",
    );
    let with_units = points.replace(
        "[[0.0, 0.0], [5.0, 0.02], [5.5, 0.0]]",
        "[[0 m, 0 mm], [5 m, 20 mm], [550 cm, 0.0]]",
    );
    same_scene(&points, &with_units);
}

/// An imported model's inline rail nodes (`x`, m) and Rayleigh frequencies
/// (Hz) with their units: the two-DOF model of tests/it/fe_import.rs.
#[test]
fn imported_rail_nodes_and_frequencies_with_units() {
    let scratch = Scratch::new("units", "fe_import");
    for (name, text) in [
        (
            "K.mtx",
            "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2.0e6\n2 1 -1.0e6\n2 2 2.0e6\n",
        ),
        (
            "M.mtx",
            "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 100.0\n2 2 100.0\n",
        ),
        ("dofs.csv", "dof,node,direction\n1,1,uz\n2,2,uz\n"),
    ] {
        std::fs::write(scratch.path(name), text).unwrap();
    }
    let si = "\
name: units
bridge:
  type: fe_import
  stiffness: K.mtx
  mass: M.mtx
  dof_map: dofs.csv
  rails: [{name: rail, nodes: [{node: 1, x: 0.0}, {node: 2, x: 5.0}]}]
  damping: {type: rayleigh, frequencies: [10.0, 30.0], ratio: 0.02}
  modes: {count: 2}
vehicles: [{type: moving_force, speed: 10.0, loads: [1.0e4]}]
";
    let units = si
        .replace("x: 0.0}", "x: 0 m}")
        .replace("x: 5.0}", "x: 5000 mm}")
        .replace("[10.0, 30.0]", "[10 Hz, 30 Hz]");
    let mut resolved = Vec::new();
    for (name, text) in [("si.yaml", si), ("units.yaml", &units)] {
        let path = scratch.path(name);
        std::fs::write(&path, text).unwrap();
        let loaded = vbi::plan::load_file(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        resolved.push(format!("{:?}", loaded.scenario));
    }
    assert_eq!(resolved[0], resolved[1]);
    // A rail position is a length.
    let path = scratch.path("wrong.yaml");
    std::fs::write(&path, units.replace("x: 5000 mm}", "x: 5 s}")).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let head = format!("{}:7:64: ", path.display());
    assert!(
        stderr.lines().any(|l| l.contains(&head)
            && l.contains("expected a length (m, mm, cm, km), found a time (`s`) in `5 s`")),
        "no `{head}…` in\n{stderr}"
    );
}

#[test]
fn the_new_dimensions_refuse_a_wrong_unit_where_it_is_written() {
    let scratch = Scratch::new("units", "wrong-mixed");
    let scene = "\
name: units
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 4.0e10
  mass_per_length: 15000.0
  lateral_bending_stiffness: 1.0e11
  torsional_stiffness: 4 MN*m
  polar_mass: 60 t
  damping: {type: rayleigh, frequencies: [2 Hz, 30 s], ratio: 0.02}
vehicles:
  - {type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}
surface: {type: harmonic, amplitude: 0.003, wavelength: 1.5, phase: 90 s}
contact: {type: hertz, coefficient: 1.0e11 N/m}
";
    let path = scratch.path("wrong.yaml");
    std::fs::write(&path, scene).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let file = path.display().to_string();
    for (line, col, message) in [
        (
            8,
            24,
            "expected a torsional stiffness (N*m^2/rad, kN*m^2/rad",
        ),
        (8, 24, "found a plate rigidity (`MN*m`) in `4 MN*m`"),
        (
            9,
            15,
            "expected a moment of inertia per length (kg*m^2/m, t*m^2/m), found a mass (`t`)",
        ),
        (
            10,
            49,
            "expected a frequency (Hz, kHz), found a time (`s`) in `30 s`",
        ),
        (
            13,
            69,
            "expected an angle (rad, mrad, deg), found a time (`s`) in `90 s`",
        ),
        (
            14,
            37,
            "expected a Hertz coefficient (N/m^1.5, kN/m^1.5, MN/m^1.5, GN/m^1.5), found a stiffness (`N/m`)",
        ),
    ] {
        let head = format!("{file}:{line}:{col}: ");
        let found = stderr
            .lines()
            .any(|l| l.contains(&head) && l.contains(message));
        assert!(found, "no `{head}…{message}` in\n{stderr}");
    }
    // A roughness coefficient is not a length.
    let road = "\
name: units
bridge: {type: beam, spans: [30.0], bending_stiffness: 1.2e11, mass_per_length: 18000.0}
vehicles: [{type: moving_force, loads: [100000.0], speed: 20.0}]
surface: {type: random, coefficient: 16 cm}
";
    std::fs::write(&path, road).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    let head = format!("{file}:4:38: ");
    assert!(
        stderr.lines().any(|l| l.contains(&head)
            && l.contains("expected a roughness coefficient (m^3/cycle, cm^3/cycle, m^3, cm^3), found a length (`cm`)")),
        "no `{head}…` in\n{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn any_si_prefix_on_any_dimension_resolves_to_the_si_scene_bit_for_bit() {
    // Issue 38.8: `GN/m` was refused although `GN*m^2` was accepted; every
    // symbol that takes a prefix now takes any SI prefix.
    let with_prefixes = BEAM_OSCILLATOR_SI
        .replace("spans: [25.0, 0.25]", "spans: [25000 mm, 250000 µm]")
        .replace(
            "bending_stiffness: 8.323e9",
            "bending_stiffness: 8323 MN*m^2",
        )
        .replace("mass_per_length: 2303.0", "mass_per_length: 2.303 Mg/m")
        .replace("max_frequency: 3000.0", "max_frequency: 0.003 MHz")
        .replace("sprung_mass: 5750.0", "sprung_mass: 5.75 Mg")
        .replace("stiffness: 1.595e6", "stiffness: 1.595 kN/mm")
        .replace("damping: 3500.0", "damping: 0.0035 MN*s/m")
        .replace("start_position: -0.0011", "start_position: -1100 µm")
        .replace("stiffness: 1.0e9", "stiffness: 1 GN/m")
        .replace("time_step: 0.0025", "time_step: 2500 µs")
        .replace("x: 12.5}", "x: 125 dm}");
    assert!(with_prefixes.contains("1 GN/m") && with_prefixes.contains("125 dm"));
    same_scene(BEAM_OSCILLATOR_SI, &with_prefixes);
}

#[test]
fn strict_units_are_refused_where_they_are_written() {
    // Issue 38.8: `25 m m` was read as 25 mm; a `NaN km/h` or `1e-320
    // km/h` speed passed the speed check and was refused only later, at
    // the time step.
    let scratch = Scratch::new("units", "strict");
    let scene = BEAM_OSCILLATOR_SI
        .replace("spans: [25.0, 0.25]", "spans: [25 m m, 0.25]")
        .replace("speed: 27.5", "speed: NaN km/h")
        .replace("x: 12.5}", "x: 1e-320 m}");
    let path = scratch.path("strict.yaml");
    std::fs::write(&path, &scene).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let file = path.display().to_string();
    for (line, col, message) in [
        (5, 11, "`25 m m` has a space inside its unit `m m`"),
        (15, 12, "`NaN` in `NaN km/h` is not a finite number"),
        (21, 55, "`1e-320 m` is 1e-320 m, a subnormal number"),
    ] {
        let head = format!("error: {file}:{line}:{col}: ");
        let found = stderr
            .lines()
            .any(|l| l.starts_with(&head) && l.contains(message));
        assert!(found, "no `{head}…{message}` in\n{stderr}");
    }
    assert!(!stderr.contains("time step"), "{stderr}");
    assert!(
        stderr.contains("= help: write the unit without spaces: `mm`"),
        "{stderr}"
    );
    // A subnormal speed, alone: refused at the speed, not at the time step.
    let scene = BEAM_OSCILLATOR_SI.replace("speed: 27.5", "speed: 1e-320 km/h");
    std::fs::write(&path, &scene).unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let errors: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("error: "))
        .collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with(&format!(
            "error: {file}:15:12: `1e-320 km/h` is 2.777e-321 m/s, a subnormal number"
        )),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}
