//! The dimensions of the format: the units a message lists (the SI one
//! first) and the forms they are written in, each symbol with any SI prefix
//! it takes ([`super::SYMBOLS`]).

use super::{Dimension, exact};

/// A dimension written in `forms` (and `aliases`), listing `listed`.
const fn dimension(
    name: &'static str,
    si: &'static str,
    listed: &'static [&'static str],
    forms: &'static [&'static str],
) -> Dimension {
    Dimension {
        name,
        si,
        listed,
        forms,
        aliases: &[],
    }
}

/// A length and its units.
pub const LENGTH: Dimension = dimension("a length", "m", &["m", "mm", "cm", "km"], &["m"]);
/// A mass and its units (the gram always with a prefix: a bare `g` is
/// standard gravity).
pub const MASS: Dimension = dimension("a mass", "kg", &["kg", "t"], &["g", "t"]);
/// A force and its units.
pub const FORCE: Dimension = dimension("a force", "N", &["N", "kN", "MN"], &["N"]);
/// A stiffness and its units.
pub const STIFFNESS: Dimension = dimension(
    "a stiffness",
    "N/m",
    &["N/m", "kN/m", "MN/m", "GN/m", "N/mm", "kN/mm"],
    &["N/m"],
);
/// A damping coefficient and its units.
pub const DAMPING: Dimension = dimension(
    "a damping coefficient",
    "N*s/m",
    &["N*s/m", "kN*s/m", "MN*s/m"],
    &["N*s/m"],
);
/// A time and its units.
pub const TIME: Dimension = dimension("a time", "s", &["s", "ms", "min"], &["s", "min"]);
/// A frequency and its units.
pub const FREQUENCY: Dimension = dimension("a frequency", "Hz", &["Hz", "kHz"], &["Hz"]);
/// An acceleration and its units: `g` is standard gravity, 9.80665 m/s².
pub const ACCELERATION: Dimension = Dimension {
    name: "an acceleration",
    si: "m/s^2",
    listed: &["m/s^2", "g"],
    forms: &["m/s^2"],
    aliases: &[("g", exact(980_665, -5))],
};
/// A bending stiffness and its units.
pub const BENDING_STIFFNESS: Dimension = dimension(
    "a bending stiffness",
    "N*m^2",
    &["N*m^2", "kN*m^2", "MN*m^2", "GN*m^2"],
    &["N*m^2"],
);
/// A mass per length and its units.
pub const MASS_PER_LENGTH: Dimension = dimension(
    "a mass per length",
    "kg/m",
    &["kg/m", "t/m"],
    &["g/m", "t/m"],
);
/// A mass per area and its units.
pub const MASS_PER_AREA: Dimension = dimension(
    "a mass per area",
    "kg/m^2",
    &["kg/m^2", "t/m^2"],
    &["g/m^2", "t/m^2"],
);
/// A density and its units.
pub const DENSITY: Dimension = dimension(
    "a density",
    "kg/m^3",
    &["kg/m^3", "t/m^3"],
    &["g/m^3", "t/m^3"],
);
/// A modulus (pressure) and its units.
pub const PRESSURE: Dimension = dimension(
    "a modulus (pressure)",
    "Pa",
    &["Pa", "kPa", "MPa", "GPa", "N/mm^2"],
    &["Pa", "N/m^2"],
);
/// A moment of inertia and its units.
pub const INERTIA: Dimension = dimension(
    "a moment of inertia",
    "kg*m^2",
    &["kg*m^2", "t*m^2"],
    &["g*m^2", "t*m^2"],
);
/// A plate rigidity and its units.
pub const PLATE_RIGIDITY: Dimension = dimension(
    "a plate rigidity",
    "N*m",
    &["N*m", "kN*m", "MN*m"],
    &["N*m"],
);

/// A torsional stiffness GJ (torque per twist per length, N·m/(rad/m))
/// and its units; the radian, a ratio, may be left out (`2 GN*m^2`).
pub const TORSIONAL_STIFFNESS: Dimension = dimension(
    "a torsional stiffness",
    "N*m^2/rad",
    &[
        "N*m^2/rad",
        "kN*m^2/rad",
        "MN*m^2/rad",
        "GN*m^2/rad",
        "N*m^2",
        "kN*m^2",
        "MN*m^2",
        "GN*m^2",
    ],
    &["N*m^2/rad", "N*m^2"],
);
/// A polar mass moment of inertia per length (a 3D beam's I_p) and its
/// units.
pub const INERTIA_PER_LENGTH: Dimension = dimension(
    "a moment of inertia per length",
    "kg*m^2/m",
    &["kg*m^2/m", "t*m^2/m"],
    &["g*m^2/m", "t*m^2/m"],
);
/// The coefficient C of a Hertz contact, F = C δ^1.5 (N/m^1.5), and its
/// units.
pub const HERTZ_COEFFICIENT: Dimension = dimension(
    "a Hertz coefficient",
    "N/m^1.5",
    &["N/m^1.5", "kN/m^1.5", "MN/m^1.5", "GN/m^1.5"],
    &["N/m^1.5"],
);
/// A road roughness coefficient A_r, the displacement PSD at Ω₀ = 1/2π
/// cycle/m: m²/(cycle/m) = m³/cycle (the cycle, a count, may be left out,
/// as ISO 8608 writes G_d(n₀) in m³); `cm^3` is the 10⁻⁶ m³ the classes
/// are tabulated in.
pub const ROUGHNESS_COEFFICIENT: Dimension = dimension(
    "a roughness coefficient",
    "m^3/cycle",
    &["m^3/cycle", "cm^3/cycle", "m^3", "cm^3"],
    &["m^3/cycle", "m^3"],
);
/// An angle and its units (`deg` in floating point: π/180 has no decimal
/// form).
pub const ANGLE: Dimension = dimension("an angle", "rad", &["rad", "mrad", "deg"], &["rad", "deg"]);

/// Every dimension, to name the one a misplaced unit belongs to.
pub(super) const ALL: [&Dimension; 20] = [
    &LENGTH,
    &MASS,
    &FORCE,
    &STIFFNESS,
    &DAMPING,
    &TIME,
    &FREQUENCY,
    &ACCELERATION,
    &BENDING_STIFFNESS,
    &MASS_PER_LENGTH,
    &MASS_PER_AREA,
    &DENSITY,
    &PRESSURE,
    &INERTIA,
    &PLATE_RIGIDITY,
    &TORSIONAL_STIFFNESS,
    &INERTIA_PER_LENGTH,
    &HERTZ_COEFFICIENT,
    &ROUGHNESS_COEFFICIENT,
    &ANGLE,
];
