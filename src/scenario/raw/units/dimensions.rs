//! The dimensions of the format and their units (the SI one first).

use super::{Dimension, Scale, decimal, exact};

/// A length and its units.
pub const LENGTH: Dimension = Dimension {
    name: "a length",
    si: "m",
    units: &[
        ("m", decimal(0)),
        ("mm", decimal(-3)),
        ("cm", decimal(-2)),
        ("km", decimal(3)),
    ],
};
/// A mass and its units.
pub const MASS: Dimension = Dimension {
    name: "a mass",
    si: "kg",
    units: &[("kg", decimal(0)), ("t", decimal(3))],
};
/// A force and its units.
pub const FORCE: Dimension = Dimension {
    name: "a force",
    si: "N",
    units: &[("N", decimal(0)), ("kN", decimal(3)), ("MN", decimal(6))],
};
/// A stiffness and its units.
pub const STIFFNESS: Dimension = Dimension {
    name: "a stiffness",
    si: "N/m",
    units: &[
        ("N/m", decimal(0)),
        ("kN/m", decimal(3)),
        ("MN/m", decimal(6)),
        ("N/mm", decimal(3)),
        ("kN/mm", decimal(6)),
    ],
};
/// A damping coefficient and its units.
pub const DAMPING: Dimension = Dimension {
    name: "a damping coefficient",
    si: "N*s/m",
    units: &[
        ("N*s/m", decimal(0)),
        ("kN*s/m", decimal(3)),
        ("MN*s/m", decimal(6)),
    ],
};
/// A time and its units.
pub const TIME: Dimension = Dimension {
    name: "a time",
    si: "s",
    units: &[
        ("s", decimal(0)),
        ("ms", decimal(-3)),
        ("min", exact(60, 0)),
    ],
};
/// A frequency and its units.
pub const FREQUENCY: Dimension = Dimension {
    name: "a frequency",
    si: "Hz",
    units: &[("Hz", decimal(0)), ("kHz", decimal(3))],
};
/// An acceleration and its units.
pub const ACCELERATION: Dimension = Dimension {
    name: "an acceleration",
    si: "m/s^2",
    units: &[("m/s^2", decimal(0)), ("g", exact(980_665, -5))],
};
/// A bending stiffness and its units.
pub const BENDING_STIFFNESS: Dimension = Dimension {
    name: "a bending stiffness",
    si: "N*m^2",
    units: &[
        ("N*m^2", decimal(0)),
        ("kN*m^2", decimal(3)),
        ("MN*m^2", decimal(6)),
        ("GN*m^2", decimal(9)),
    ],
};
/// A mass per length and its units.
pub const MASS_PER_LENGTH: Dimension = Dimension {
    name: "a mass per length",
    si: "kg/m",
    units: &[("kg/m", decimal(0)), ("t/m", decimal(3))],
};
/// A mass per area and its units.
pub const MASS_PER_AREA: Dimension = Dimension {
    name: "a mass per area",
    si: "kg/m^2",
    units: &[("kg/m^2", decimal(0)), ("t/m^2", decimal(3))],
};
/// A density and its units.
pub const DENSITY: Dimension = Dimension {
    name: "a density",
    si: "kg/m^3",
    units: &[("kg/m^3", decimal(0)), ("t/m^3", decimal(3))],
};
/// A modulus (pressure) and its units.
pub const PRESSURE: Dimension = Dimension {
    name: "a modulus (pressure)",
    si: "Pa",
    units: &[
        ("Pa", decimal(0)),
        ("kPa", decimal(3)),
        ("MPa", decimal(6)),
        ("GPa", decimal(9)),
    ],
};
/// A moment of inertia and its units.
pub const INERTIA: Dimension = Dimension {
    name: "a moment of inertia",
    si: "kg*m^2",
    units: &[("kg*m^2", decimal(0)), ("t*m^2", decimal(3))],
};
/// A plate rigidity and its units.
pub const PLATE_RIGIDITY: Dimension = Dimension {
    name: "a plate rigidity",
    si: "N*m",
    units: &[
        ("N*m", decimal(0)),
        ("kN*m", decimal(3)),
        ("MN*m", decimal(6)),
    ],
};

/// A torsional stiffness GJ (torque per twist per length, N·m/(rad/m))
/// and its units; the radian, a ratio, may be left out (`2 GN*m^2`).
pub const TORSIONAL_STIFFNESS: Dimension = Dimension {
    name: "a torsional stiffness",
    si: "N*m^2/rad",
    units: &[
        ("N*m^2/rad", decimal(0)),
        ("kN*m^2/rad", decimal(3)),
        ("MN*m^2/rad", decimal(6)),
        ("GN*m^2/rad", decimal(9)),
        ("N*m^2", decimal(0)),
        ("kN*m^2", decimal(3)),
        ("MN*m^2", decimal(6)),
        ("GN*m^2", decimal(9)),
    ],
};
/// A polar mass moment of inertia per length (a 3D beam's I_p) and its
/// units.
pub const INERTIA_PER_LENGTH: Dimension = Dimension {
    name: "a moment of inertia per length",
    si: "kg*m^2/m",
    units: &[("kg*m^2/m", decimal(0)), ("t*m^2/m", decimal(3))],
};
/// The coefficient C of a Hertz contact, F = C δ^1.5 (N/m^1.5), and its
/// units.
pub const HERTZ_COEFFICIENT: Dimension = Dimension {
    name: "a Hertz coefficient",
    si: "N/m^1.5",
    units: &[
        ("N/m^1.5", decimal(0)),
        ("kN/m^1.5", decimal(3)),
        ("MN/m^1.5", decimal(6)),
        ("GN/m^1.5", decimal(9)),
    ],
};
/// A road roughness coefficient A_r, the displacement PSD at Ω₀ = 1/2π
/// cycle/m: m²/(cycle/m) = m³/cycle (the cycle, a count, may be left out,
/// as ISO 8608 writes G_d(n₀) in m³); `cm^3` is the 10⁻⁶ m³ the classes
/// are tabulated in.
pub const ROUGHNESS_COEFFICIENT: Dimension = Dimension {
    name: "a roughness coefficient",
    si: "m^3/cycle",
    units: &[
        ("m^3/cycle", decimal(0)),
        ("cm^3/cycle", decimal(-6)),
        ("m^3", decimal(0)),
        ("cm^3", decimal(-6)),
    ],
};
/// π/180: radians per degree (the f64 nearest to it).
const RADIANS_PER_DEGREE: f64 = std::f64::consts::PI / 180.0;
/// An angle and its units (`deg` in floating point: π/180 has no decimal
/// form).
pub const ANGLE: Dimension = Dimension {
    name: "an angle",
    si: "rad",
    units: &[
        ("rad", decimal(0)),
        ("mrad", decimal(-3)),
        ("deg", Scale::Irrational(RADIANS_PER_DEGREE)),
    ],
};

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
