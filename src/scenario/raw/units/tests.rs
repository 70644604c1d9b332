//! Unit reading: bit-for-bit SI values, misplaced units named, schema
//! patterns.

use super::*;

#[test]
fn decimal_prefixes_read_as_the_si_number_bit_for_bit() {
    let cases = [
        (&LENGTH, "250 mm", "0.25"),
        (&LENGTH, "1.1 mm", "0.0011"),
        (&LENGTH, "0.025 km", "25"),
        (&LENGTH, "25m", "25"),
        (&LENGTH, "3.3 cm", "0.033"),
        (&MASS, "40 t", "40000"),
        (&MASS, "5.75 t", "5750"),
        (&STIFFNESS, "1.595e3 kN/m", "1.595e6"),
        (&STIFFNESS, "1.6 MN/m", "1.6e6"),
        (&FORCE, "170 kN", "170000"),
        (&FORCE, "0.1 MN", "100000"),
        (&TIME, "2.5 ms", "0.0025"),
        (&FREQUENCY, "30 Hz", "30"),
        (&BENDING_STIFFNESS, "8.323 GN*m^2", "8.323e9"),
        (&BENDING_STIFFNESS, "8.323 GN·m²", "8.323e9"),
        (&MASS_PER_LENGTH, "2.303 t/m", "2303"),
        (&DAMPING, "3.5 kN*s/m", "3500"),
        (&DAMPING, "3.5 kNs/m", "3500"),
        (&PRESSURE, "210 GPa", "2.1e11"),
        (&INERTIA, "1.7e3 t*m^2", "1.7e6"),
        (&TORSIONAL_STIFFNESS, "4 GN*m^2/rad", "4e9"),
        (&TORSIONAL_STIFFNESS, "4e6 kN·m²", "4e9"),
        (&INERTIA_PER_LENGTH, "60 t*m^2/m", "60000"),
        (&INERTIA_PER_LENGTH, "1.5 t·m²/m", "1500"),
        (&HERTZ_COEFFICIENT, "100 GN/m^1.5", "1e11"),
        (&HERTZ_COEFFICIENT, "8.7e7 kN/m^1.5", "8.7e10"),
        (&ROUGHNESS_COEFFICIENT, "16 cm^3", "16e-6"),
        (&ROUGHNESS_COEFFICIENT, "16 cm³/cycle", "16e-6"),
        (&ROUGHNESS_COEFFICIENT, "1.6e-5 m^3/cycle", "1.6e-5"),
        (&FREQUENCY, "0.03 kHz", "30"),
        (&ANGLE, "500 mrad", "0.5"),
        (&ANGLE, "0.5 rad", "0.5"),
    ];
    for (dimension, text, si) in cases {
        let want: f64 = si.parse().unwrap();
        let got = dimension.parse(text).unwrap();
        assert_eq!(got.to_bits(), want.to_bits(), "{text}: {got} vs {want}");
    }
    // g is standard gravity, 9.80665 m/s² exactly: the product is
    // computed in decimal, 0.35 g = 3.4323275 m/s² (one multiplication
    // in floating point would give 3.4323274999999995).
    assert_eq!(ACCELERATION.parse("0.35 g").unwrap(), 3.4323275);
    assert_eq!(ACCELERATION.parse("1 g").unwrap(), STANDARD_GRAVITY);
    assert_eq!(TIME.parse("1.5 min").unwrap(), 90.0);
    assert_eq!(ACCELERATION.parse("3.5 m/s^2").unwrap(), 3.5);
    assert_eq!(ACCELERATION.parse("3.5 m/s²").unwrap(), 3.5);
}

#[test]
fn degrees_are_one_multiplication_by_pi_over_180() {
    // π/180 has no decimal form: `deg` multiplies once by the f64 nearest
    // it (0.017453292519943295), so 180° is π to the last bit and 90° is
    // π/2 (both products happen to round to the f64 nearest the exact one).
    let per_degree = std::f64::consts::PI / 180.0;
    assert_eq!(ANGLE.parse("30 deg").unwrap(), 30.0 * per_degree);
    assert_eq!(ANGLE.parse("30°").unwrap(), 30.0 * per_degree);
    assert_eq!(ANGLE.parse("180 deg").unwrap(), std::f64::consts::PI);
    assert_eq!(ANGLE.parse("90°").unwrap(), std::f64::consts::FRAC_PI_2);
}

#[test]
fn a_unit_of_another_dimension_is_named() {
    let e = LENGTH.parse("25 s").unwrap_err();
    assert!(
        e.contains("expected a length (m, mm, cm, km), found a time (`s`)"),
        "{e}"
    );
    let e = MASS.parse("40 tonnes").unwrap_err();
    assert!(e.contains("unknown unit `tonnes`"), "{e}");
    assert!(LENGTH.parse("25").unwrap_err().contains("no unit"));
    // EI and GJ share N·m²; only GJ's `/rad` tells them apart.
    let e = BENDING_STIFFNESS.parse("4 GN*m^2/rad").unwrap_err();
    assert!(
        e.contains("found a torsional stiffness (`GN*m^2/rad`)"),
        "{e}"
    );
    let e = HERTZ_COEFFICIENT.parse("1e11 N/m").unwrap_err();
    assert!(e.contains("found a stiffness (`N/m`)"), "{e}");
    let e = ROUGHNESS_COEFFICIENT.parse("16 cm").unwrap_err();
    assert!(e.contains("found a length (`cm`)"), "{e}");
    assert!(LENGTH.parse("1e999 m").unwrap_err().contains("finite"));
}

#[test]
fn the_schema_pattern_matches_what_parse_accepts() {
    // The pattern is a JSON Schema (ECMA 262) regex; these spellings
    // are plain enough that the shapes agree: checked by the schema
    // tests through jsonschema (tests/it/schema.rs).
    let schema = STIFFNESS.schema().to_value();
    let pattern = schema["anyOf"][1]["pattern"].as_str().unwrap();
    assert!(pattern.contains(r"kN\/m"), "{pattern}");
}
