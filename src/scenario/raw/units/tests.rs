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

#[test]
fn si_prefixes_work_on_every_dimension_bit_for_bit() {
    // Any SI prefix on any symbol that takes one: the value is the
    // decimal shift of the written number, read with one rounding.
    let cases = [
        (&STIFFNESS, "1.6 GN/m", "1.6e9"),
        (&STIFFNESS, "1.6 kN/mm", "1.6e6"),
        (&STIFFNESS, "1.6 MN/mm", "1.6e9"),
        (&STIFFNESS, "1.6 N/µm", "1.6e6"),
        (&BENDING_STIFFNESS, "8.323 MN*m^2", "8.323e6"),
        (&BENDING_STIFFNESS, "8.323 kN*cm^2", "0.8323"),
        (&BENDING_STIFFNESS, "8.323e-3 TN*m^2", "8.323e9"),
        (&LENGTH, "25 mm", "0.025"),
        (&LENGTH, "25 µm", "25e-6"),
        (&LENGTH, "25 μm", "25e-6"),
        (&LENGTH, "25 um", "25e-6"),
        (&LENGTH, "25 dm", "2.5"),
        (&LENGTH, "25 dam", "250"),
        (&LENGTH, "2.5 hm", "250"),
        (&LENGTH, "25 nm", "25e-9"),
        (&MASS, "25 kg", "25"),
        (&MASS, "25 Mg", "25000"),
        (&MASS, "25 mg", "25e-6"),
        (&FORCE, "2.5 GN", "2.5e9"),
        (&FORCE, "2.5 mN", "0.0025"),
        (&DAMPING, "3.5 MN*s/m", "3.5e6"),
        (&DAMPING, "3.5 kN*s/mm", "3.5e6"),
        (&DAMPING, "3.5 GNs/m", "3.5e9"),
        (&TIME, "2.5 µs", "2.5e-6"),
        (&TIME, "2.5 ks", "2500"),
        (&FREQUENCY, "2.5 MHz", "2.5e6"),
        (&FREQUENCY, "2.5 mHz", "0.0025"),
        (&ACCELERATION, "2.5 mm/s^2", "0.0025"),
        (&ACCELERATION, "2.5 cm/s²", "0.025"),
        (&ACCELERATION, "2.5 m/ms^2", "2.5e6"),
        (&MASS_PER_LENGTH, "2.303 Mg/m", "2303"),
        (&MASS_PER_LENGTH, "2.303 kg/mm", "2303"),
        (&MASS_PER_AREA, "0.5 t/m^2", "500"),
        (&MASS_PER_AREA, "5 kg/cm^2", "50000"),
        (&DENSITY, "2.5 Mg/m^3", "2500"),
        (&DENSITY, "2.5 kg/dm³", "2500"),
        (&PRESSURE, "210 N/mm^2", "2.1e8"),
        (&PRESSURE, "210 kN/m^2", "2.1e5"),
        (&PRESSURE, "0.21 TPa", "2.1e11"),
        (&INERTIA, "1.7 Mg*m^2", "1700"),
        (&PLATE_RIGIDITY, "4.2 GN*m", "4.2e9"),
        (&PLATE_RIGIDITY, "4.2 kN*mm", "4.2"),
        (&TORSIONAL_STIFFNESS, "4 MN*m^2/mrad", "4e9"),
        (&TORSIONAL_STIFFNESS, "4 TN*m^2", "4e12"),
        (&INERTIA_PER_LENGTH, "60 Mg*m^2/m", "60000"),
        (&HERTZ_COEFFICIENT, "87 MN/m^1.5", "8.7e7"),
        (&ROUGHNESS_COEFFICIENT, "16 mm^3/cycle", "16e-9"),
        (&ROUGHNESS_COEFFICIENT, "16 dm^3", "0.016"),
        (&ANGLE, "500 µrad", "5e-4"),
    ];
    for (dimension, text, si) in cases {
        let want: f64 = si.parse().unwrap();
        let got = dimension
            .parse(text)
            .unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(got.to_bits(), want.to_bits(), "{text}: {got} vs {want}");
    }
    // A prefix with a half exponent is a power of √10: one multiplication.
    let got = HERTZ_COEFFICIENT.parse("1 N/mm^1.5").unwrap();
    assert!((got / 10f64.powf(4.5) - 1.0).abs() < 1e-15, "{got}");
    // A bare `g` is standard gravity, so the gram always has a prefix.
    let e = MASS.parse("25 g").unwrap_err();
    assert!(e.contains("found an acceleration (`g`)"), "{e}");
    // Symbols without prefixes: tonne, minute, degree, cycle.
    for (dimension, text) in [
        (&MASS, "2 kt"),
        (&TIME, "2 kmin"),
        (&ANGLE, "2 mdeg"),
        (&ROUGHNESS_COEFFICIENT, "2 m^3/kcycle"),
    ] {
        let e = dimension.parse(text).unwrap_err();
        assert!(e.contains("unknown unit"), "{text}: {e}");
    }
    // A prefix that does not exist, or a prefix alone.
    for (dimension, text) in [(&LENGTH, "2 xm"), (&LENGTH, "2 k"), (&FORCE, "2 kkN")] {
        assert!(dimension.parse(text).is_err(), "{text}");
    }
    // The wrong dimension is still named with a prefix on it.
    let e = BENDING_STIFFNESS.parse("3.2 GN/m").unwrap_err();
    assert!(e.contains("found a stiffness (`GN/m`)"), "{e}");
    let e = LENGTH.parse("25 µs").unwrap_err();
    assert!(e.contains("found a time (`µs`)"), "{e}");
}

#[test]
fn a_space_inside_a_unit_is_refused_with_what_to_write() {
    // `25 m m` was read as 25 mm (spaces inside a unit were dropped).
    let e = LENGTH.parse("25 m m").unwrap_err();
    assert!(e.contains("has a space inside its unit `m m`"), "{e}");
    assert!(
        e.contains("\nhelp: write the unit without spaces: `mm`"),
        "{e}"
    );
    let e = LENGTH.parse("1 m m").unwrap_err();
    assert!(e.contains("space inside its unit"), "{e}");
    let e = STIFFNESS.parse("1.6e6 N / m").unwrap_err();
    assert!(
        e.contains("help: write the unit without spaces: `N/m`"),
        "{e}"
    );
    // Neither spelling is a unit of the dimension: both are named.
    let e = BENDING_STIFFNESS.parse("3 kN m^2").unwrap_err();
    assert!(
        e.contains("(`kNm^2` and `kN*m^2` are different units)") || e.contains("`kN*m^2`"),
        "{e}"
    );
    // Between the number and the unit, a space is the usual spelling.
    assert_eq!(LENGTH.parse("25 mm").unwrap(), 0.025);
    assert_eq!(LENGTH.parse(" 25mm ").unwrap(), 0.025);
}

#[test]
fn nan_infinite_and_subnormal_values_are_refused() {
    for text in [
        "NaN m",
        "nan mm",
        "inf m",
        "-inf m",
        "infinity km",
        "1e999 m",
    ] {
        let e = LENGTH.parse(text).unwrap_err();
        assert!(e.contains("is not a finite number"), "{text}: {e}");
    }
    // Subnormal: nonzero and below f64::MIN_POSITIVE in magnitude, as
    // written or once scaled.
    for text in ["1e-320 m", "-1e-320 m", "1e-306 mm", "3e-306 mN/m"] {
        let dimension = if text.ends_with("N/m") {
            &STIFFNESS
        } else {
            &LENGTH
        };
        let e = dimension.parse(text).unwrap_err();
        assert!(e.contains("subnormal"), "{text}: {e}");
        assert!(e.contains("\nhelp: write 0"), "{text}: {e}");
    }
    let e = LENGTH.parse("1e-400 m").unwrap_err();
    assert!(e.contains("would be read as 0"), "{e}");
    // Zero, and the smallest normal numbers, are numbers.
    assert_eq!(LENGTH.parse("0 mm").unwrap(), 0.0);
    assert_eq!(LENGTH.parse("0e-400 m").unwrap(), 0.0);
    assert_eq!(
        LENGTH.parse("2.2250738585072014e-308 m").unwrap(),
        f64::MIN_POSITIVE
    );
    // A subnormal written number scaled into the normal range is fine.
    assert_eq!(STIFFNESS.parse("1e-310 GN/m").unwrap(), 1e-301);
}

#[test]
fn the_schema_pattern_accepts_what_parse_accepts_and_nothing_else() {
    let cases = [
        (&STIFFNESS, "1.6 GN/m"),
        (&STIFFNESS, "1.6 kN/mm"),
        (&STIFFNESS, "1.6 N/m"),
        (&STIFFNESS, "1.6 N / m"),
        (&STIFFNESS, "1.6 N*m"),
        (&BENDING_STIFFNESS, "8 MN*m^2"),
        (&BENDING_STIFFNESS, "8 MN·m²"),
        (&BENDING_STIFFNESS, "8 GN/m"),
        (&LENGTH, "25 mm"),
        (&LENGTH, "25 µm"),
        (&LENGTH, "25 m m"),
        (&LENGTH, "25 s"),
        (&MASS, "25 g"),
        (&MASS, "25 kg"),
        (&MASS, "25 Mg"),
        (&MASS, "25 kt"),
        (&DAMPING, "3 kNs/m"),
        (&DAMPING, "3 kN*s/mm"),
        (&ACCELERATION, "0.3 g"),
        (&ACCELERATION, "0.3 m/s2"),
        (&ACCELERATION, "0.3 mm/s^2"),
        (&ANGLE, "30°"),
        (&ANGLE, "30 mdeg"),
        (&HERTZ_COEFFICIENT, "8 MN/m^1.5"),
        (&HERTZ_COEFFICIENT, "8 MN/m^1.50"),
        (&PRESSURE, "210 N/mm²"),
        (&TIME, "2 min"),
        (&TIME, "2 kmin"),
    ];
    for (dimension, text) in cases {
        let schema = dimension.schema().to_value();
        let pattern = schema["anyOf"][1]["pattern"].as_str().unwrap();
        let regex = regex::Regex::new(pattern).unwrap();
        assert_eq!(
            regex.is_match(text),
            dimension.parse(text).is_ok(),
            "{text} against {pattern}"
        );
    }
}
