//! Physical plausibility: values far outside anything built or driven are
//! refused with the accepted range and its unit, because the run would
//! otherwise "succeed" with nonsense (a suspension of 1e20 N/m makes the
//! coupled system so stiff that the automatic step gives 10⁸ steps, or an
//! explicit step gives accelerations of hundreds of m/s²).
//!
//! The ranges are deliberately wide — several orders of magnitude beyond
//! laboratory models and the heaviest trains and bridges — so that only
//! typing slips (a missing exponent sign, N for kN twice over) and hostile
//! inputs are caught. They apply to every derived value as well: oscillators
//! given by dimensionless groups, stiffnesses given as ratios, and every
//! point of a study.
//!
//! The table of ranges (the constants below; SI units):
//!
//! | quantity | range | unit |
//! |---|---|---|
//! | mass | 1e-3 to 1e10 | kg |
//! | moment of inertia (pitch, roll, yaw) | 1e-6 to 1e13 | kg·m² |
//! | suspension, tyre or contact spring | 1e-3 to 1e13 | N/m |
//! | suspension or tyre damper | 0 to 1e12 | N·s/m |
//! | axle load | 1e-3 to 1e9 | N |
//! | Hertz coefficient | 1e-3 to 1e15 | N/m^1.5 |
//! | bending stiffness EI (vertical, lateral) | 1e-3 to 1e16 | N·m² |
//! | torsional stiffness GJ | 1e-3 to 1e16 | N·m²/rad |
//! | mass per length | 1e-3 to 1e7 | kg/m |
//! | polar mass per length | 1e-6 to 1e10 | kg·m²/m |
//! | plate rigidity | 1e-3 to 1e15 | N·m |
//! | mass per area | 1e-3 to 1e6 | kg/m² |
//! | span | 1e-2 to 1e4 | m |
//! | rail height above the shear centre | −100 to 100 | m |
//! | a length within a vehicle (spacing, height, track, radius) | 1e-3 to 1e3 | m |
//! | gravity | 1e-3 to 300 | m/s² |
//! | time before a vehicle reaches the bridge | 0 to 86 400 | s |
//! | a vehicle's speed | 1e-3 to 1e3 | m/s |
//! | free vibration after the last exit | 0 to 86 400 | s |
//! | plate thickness | 1e-3 to 100 | m |
//! | plate (deck) width | 1e-2 to 1e3 | m |
//! | plate material density | 1 to 1e5 | kg/m³ |
//! | explicit time step | 1e-9 to 1 | s |
//! | Rayleigh damping frequency | 1e-3 to 1e5 | Hz |
//! | surface elevation or alignment (amplitude, shape height, profile value) | −0.5 to 0.5 | m |
//! | surface length (wavelength, band, shape length, run-in, sampling length) | 1e-3 to 1e4 | m |
//! | power-law roughness coefficient A_r | 0 to 0.1 | m³/cycle |
//!
//! The surface ranges ([`SURFACE_ELEVATION`], [`SURFACE_LENGTH`],
//! [`ROUGHNESS_COEFFICIENT`]) come from the standards that classify road
//! and track irregularities (ISO 8608 for roads, EN 13848 for track
//! geometry): a surface is the irregularity about the road's or track's
//! design line, millimetres to centimetres high over wavelengths of
//! millimetres to a few hundred metres, never metres high.

use super::checker::Checker;
use crate::scene::{Bridge, Contact, Rigidity, Vehicle};

/// A mass, kg: a gram up to 10¹⁰ kg (a hundred of the heaviest trains).
pub const MASS: (f64, f64) = (1e-3, 1e10);
/// A suspension, tyre or contact spring, N/m.
pub const STIFFNESS: (f64, f64) = (1e-3, 1e13);
/// A suspension or tyre damper, N·s/m.
pub const DAMPING: (f64, f64) = (0.0, 1e12);
/// An axle load, N (10⁹ N is 100,000 t).
pub const LOAD: (f64, f64) = (1e-3, 1e9);
/// A Hertz coefficient, N/m^1.5 (steel wheels on rail are ~1e11).
pub const HERTZ: (f64, f64) = (1e-3, 1e15);
/// A beam's bending stiffness EI, N·m² (large box girders are ~1e13).
pub const BENDING_STIFFNESS: (f64, f64) = (1e-3, 1e16);
/// A beam's mass per length, kg/m.
pub const MASS_PER_LENGTH: (f64, f64) = (1e-3, 1e7);
/// A plate's flexural rigidity, N·m.
pub const PLATE_RIGIDITY: (f64, f64) = (1e-3, 1e15);
/// A plate's mass per area, kg/m².
pub const MASS_PER_AREA: (f64, f64) = (1e-3, 1e6);
/// A moment of inertia of a body, bogie, axle or wheelset, kg·m²: a gram
/// at 3 cm is 1e-6; a hundred heavy trains' mass at 30 m, 1e13.
pub const MOMENT_OF_INERTIA: (f64, f64) = (1e-6, 1e13);
/// A beam's torsional stiffness GJ, N·m²/rad (as EI).
pub const TORSIONAL_STIFFNESS: (f64, f64) = (1e-3, 1e16);
/// A beam's polar mass moment of inertia per length, kg·m²/m (the largest
/// mass per length at a 30 m radius of gyration is ~1e10).
pub const POLAR_MASS_PER_LENGTH: (f64, f64) = (1e-6, 1e10);
/// A span, m (the longest built is about 2 km).
pub const SPAN: (f64, f64) = (1e-2, 1e4);
/// The height of the rail heads above a 3D beam's shear centre, m (either
/// sign).
pub const RAIL_HEIGHT: (f64, f64) = (-100.0, 100.0);
/// A length within a vehicle: spacings of axles, bogies, springs and
/// cars, heights, tracks, a wheel's radius, m.
pub const VEHICLE_LENGTH: (f64, f64) = (1e-3, 1e3);
/// Gravitational acceleration, m/s² (the Sun's surface is 274).
pub const GRAVITY: (f64, f64) = (1e-3, 300.0);
/// Time before a vehicle reaches the bridge, s (one day).
pub const ENTRY_TIME: (f64, f64) = (0.0, 86_400.0);
/// A vehicle's speed, m/s: a millimetre a second (a creep test) to the
/// format's [`super::vehicles::MAX_SPEED`] (1 km/s, six times the fastest
/// train, the 2015 maglev record of 603 km/h = 168 m/s).
pub const SPEED: (f64, f64) = (1e-3, super::vehicles::MAX_SPEED);
/// Free vibration after the last vehicle leaves, s (one day).
pub const FREE_VIBRATION: (f64, f64) = (0.0, 86_400.0);

/// A plate's thickness, m: a millimetre (laboratory strips) to 100 m
/// (the deepest box girders are about 15 m deep).
pub const PLATE_THICKNESS: (f64, f64) = (1e-3, 100.0);
/// A plate deck's width, m: a centimetre (laboratory strips) to 1 km (the
/// widest decks carry about 20 lanes, some 60 m).
pub const DECK_WIDTH: (f64, f64) = (1e-2, 1e3);
/// A plate material's density, kg/m³: from 1 (aerogels are about 2) to
/// 1e5 (osmium, the densest element, is 22,590).
pub const DENSITY: (f64, f64) = (1.0, 1e5);
/// An explicit time step, s: from a nanosecond (a wheel at 500 km/h
/// travels 0.14 µm; the stiffest Hertz contact of a steel wheel rings at a
/// few kHz) to a second (it resolves nothing above 0.5 Hz, below the
/// first mode of any bridge but the longest suspension spans).
pub const TIME_STEP: (f64, f64) = (1e-9, 1.0);
/// A frequency at which Rayleigh damping is matched, Hz: from 1 mHz
/// (below the first mode of the longest suspension bridges, about 0.05 Hz)
/// to 100 kHz (far above any mode a vehicle excites; laboratory models
/// reach a few kHz).
pub const RAYLEIGH_FREQUENCY: (f64, f64) = (1e-3, 1e5);

/// The largest elevation (or lateral offset) of a surface irregularity
/// about its design line, m: a harmonic's amplitude, a bump's height, a
/// dip's depth, a ramp's or step's rise, a point of a piecewise-linear or
/// measured profile. Half a metre is some twenty times what EN 13848-5
/// tolerates on any track before immediate action (longitudinal level and
/// alignment of about ±10–30 mm mean to peak over the D1 band, 3–25 m), five
/// times the tallest road hump (75–100 mm), and the standard deviation of
/// ISO 8608's roughest class, H, over its whole band of 0.1–100 m (most of
/// it in waves longer than 10 m). A profile of metres is a terrain or an
/// error of units, not a surface.
pub const SURFACE_ELEVATION: f64 = 0.5;
/// A length along a surface, m: a harmonic's wavelength, a spectrum's
/// band, a random road's sampling length, the length of a bump, dip or
/// ramp, a run-in. A millimetre is the finest road texture (ISO 13473's
/// macrotexture, 0.5–50 mm), below the shortest rail corrugation (some
/// 25 mm); 10 km is fifty times the longest wavelength EN 13848-1 measures
/// (its D3 band, 70–200 m) and a hundred times ISO 8608's longest (100 m).
pub const SURFACE_LENGTH: (f64, f64) = (1e-3, 1e4);
/// A power-law road's roughness coefficient A_r, m³/cycle (the spectrum
/// A_r (Ω/Ω₀)⁻², Ω₀ = 1/2π cycle/m): 0.1 is ISO 8608's class H, the
/// roughest it names (G_d(n₀) above 0.131 m³ at n₀ = 0.1 cycle/m, which is
/// A_r = G_d(n₀)(2π n₀)² above 0.052 m³/cycle here), fifty times the plate
/// paper's very poor class (at most 2.048e-3). A road in good condition is
/// 16e-6.
pub const ROUGHNESS_COEFFICIENT: (f64, f64) = (0.0, 0.1);

/// Where the surface ranges come from, said in their messages.
pub(crate) const SURFACE_SOURCE: &str = "a road's or track's irregularity about its design \
     line is millimetres to centimetres high: ISO 8608, EN 13848-5";
/// Where the surface length range comes from, said in its messages.
pub(crate) const SURFACE_LENGTH_SOURCE: &str = "road and track irregularities have wavelengths \
     from millimetres, texture and rail corrugation, to a few hundred metres: ISO 8608 \
     classifies roads over 0.1–100 m, EN 13848-1's longest band, D3, ends at 200 m";

/// [`within_because`] with a `help:` line saying what to type instead.
#[allow(clippy::too_many_arguments)]
pub(crate) fn within_help(
    ck: &mut Checker<'_>,
    path: &str,
    what: &str,
    value: f64,
    (lo, hi): (f64, f64),
    unit: &str,
    source: &str,
    help: String,
) {
    let outside = value.is_nan() || value > hi || (value > 0.0 && value < lo);
    if outside {
        let (value, lo, hi) = (number(value), number(lo), number(hi));
        ck.error_with_help(
            path,
            format!(
                "{what} of {value} {unit} is outside the physically plausible range {lo} to {hi} {unit} ({source})"
            ),
            Some(help),
        );
    }
}

/// A surface elevation (`value`, m) within ±[`SURFACE_ELEVATION`] at
/// `path`, or within 0 to [`SURFACE_ELEVATION`] unless `signed` (a negative
/// value is then the sign checks'); `help` says what to type instead.
pub(crate) fn surface_elevation(
    ck: &mut Checker<'_>,
    path: &str,
    what: &str,
    (value, signed): (f64, bool),
    help: String,
) {
    let hi = SURFACE_ELEVATION;
    if value.abs() <= hi || (!signed && value < 0.0) {
        return;
    }
    let lo = if signed { -hi } else { 0.0 };
    ck.error_with_help(
        path,
        format!(
            "{what} of {} m is outside the physically plausible range {lo} to {hi} m ({SURFACE_SOURCE})",
            number(value),
        ),
        Some(help),
    );
}

/// [`within`] with where the range comes from (`source`, said after it).
pub(crate) fn within_because(
    ck: &mut Checker<'_>,
    path: &str,
    what: &str,
    value: f64,
    (lo, hi): (f64, f64),
    unit: &str,
    source: &str,
) {
    let outside = value.is_nan() || value > hi || (value > 0.0 && value < lo);
    if outside {
        let (value, lo, hi) = (number(value), number(lo), number(hi));
        ck.error(
            path,
            format!(
                "{what} of {value} {unit} is outside the physically plausible range {lo} to {hi} {unit} ({source})"
            ),
        );
    }
}

/// Refuses `value` outside `[lo, hi]` (both inclusive) at `path`. A zero
/// or negative value is left to the sign checks, which say "must be
/// positive" once, rather than twice. Whether it refused.
pub(crate) fn within(
    ck: &mut Checker<'_>,
    path: &str,
    what: &str,
    value: f64,
    (lo, hi): (f64, f64),
    unit: &str,
) -> bool {
    let outside = value.is_nan() || value > hi || (value > 0.0 && value < lo);
    if outside {
        let (value, lo, hi) = (number(value), number(lo), number(hi));
        ck.error(
            path,
            format!(
                "{what} of {value} {unit} is outside the physically plausible range {lo} to {hi} {unit}"
            ),
        );
    }
    outside
}

/// A value as typed by people: plain while short, else with an exponent.
pub(crate) fn number(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Checks a resolved (possibly derived) vehicle; `at` is its path.
/// `entry_field` is `start_position` when the file places the vehicle by
/// position, so a far-away start is blamed where it is written.
pub(crate) fn check_vehicle(ck: &mut Checker<'_>, at: &str, entry_field: &str, vehicle: &Vehicle) {
    let p = |field: &str| format!("{at}.{field}");
    match vehicle {
        Vehicle::MovingForce(v) => {
            for (k, &load) in v.loads.iter().enumerate() {
                within(
                    ck,
                    &p(&format!("loads[{k}]")),
                    "an axle load",
                    load,
                    LOAD,
                    "N",
                );
            }
            // An axle spacing is a length within a vehicle (issue 39.5: a
            // spacing of 1e308 m was blamed on the speed, "over the inf s
            // run"); blamed where the file writes it, a spacing or the
            // position of the axle behind it.
            let by_position = !ck.has(&p("axle_spacings")) && ck.has(&p("axle_positions"));
            for (k, &spacing) in v.axle_spacings.iter().enumerate() {
                let path = if by_position {
                    p(&format!("axle_positions[{}]", k + 1))
                } else {
                    p(&format!("axle_spacings[{k}]"))
                };
                within(ck, &path, "an axle spacing", spacing, VEHICLE_LENGTH, "m");
            }
        }
        Vehicle::Oscillator(o) => {
            within(
                ck,
                &p("sprung_mass"),
                "a sprung mass",
                o.sprung_mass,
                MASS,
                "kg",
            );
            if o.unsprung_mass != 0.0 {
                within(
                    ck,
                    &p("unsprung_mass"),
                    "an unsprung mass",
                    o.unsprung_mass,
                    MASS,
                    "kg",
                );
            }
            within(
                ck,
                &p("stiffness"),
                "a suspension stiffness",
                o.stiffness,
                STIFFNESS,
                "N/m",
            );
            within(
                ck,
                &p("damping"),
                "a suspension damping",
                o.damping,
                DAMPING,
                "N·s/m",
            );
        }
        Vehicle::RailCar(c) => {
            super::rail::check_plausible(ck, &p("parameters"), None, &c.parameters);
        }
        Vehicle::Train(t) => {
            for (k, car) in t.cars.iter().enumerate() {
                super::rail::check_plausible(ck, &p("parameters"), Some(k + 1), &car.parameters);
            }
            let spacings = t.cars.iter().map(|c| c.spacing);
            check_car_spacings(ck, at, spacings);
        }
        Vehicle::Train3d(t) => {
            for (k, car) in t.cars.iter().enumerate() {
                super::rail_3d::check_plausible(ck, &p("parameters"), k + 1, &car.parameters);
            }
            check_car_spacings(ck, at, t.cars.iter().map(|c| c.spacing));
        }
        Vehicle::H20Truck(t) => {
            let q = &t.parameters;
            // Blamed at the override when the file gives one.
            let p = |field: &str| format!("{at}.parameters.{field}");
            for (field, value) in [
                ("body_mass", q.body_mass),
                ("front_axle_mass", q.front_axle_mass),
                ("rear_axle_mass", q.rear_axle_mass),
            ] {
                within(ck, &p(field), "a mass", value, MASS, "kg");
            }
            for (field, value) in [
                ("front_suspension_stiffness", q.front_suspension_stiffness),
                ("rear_suspension_stiffness", q.rear_suspension_stiffness),
                ("front_tyre_stiffness", q.front_tyre_stiffness),
                ("rear_tyre_stiffness", q.rear_tyre_stiffness),
            ] {
                within(ck, &p(field), "a spring stiffness", value, STIFFNESS, "N/m");
            }
            for (field, value) in [
                ("body_pitch_inertia", q.body_pitch_inertia),
                ("body_roll_inertia", q.body_roll_inertia),
                ("front_axle_roll_inertia", q.front_axle_roll_inertia),
                ("rear_axle_roll_inertia", q.rear_axle_roll_inertia),
            ] {
                within(
                    ck,
                    &p(field),
                    "a moment of inertia",
                    value,
                    MOMENT_OF_INERTIA,
                    "kg·m²",
                );
            }
            for (field, value) in [
                ("front_suspension_damping", q.front_suspension_damping),
                ("rear_suspension_damping", q.rear_suspension_damping),
                ("front_tyre_damping", q.front_tyre_damping),
                ("rear_tyre_damping", q.rear_tyre_damping),
            ] {
                within(ck, &p(field), "a damping", value, DAMPING, "N·s/m");
            }
            for (field, value) in [
                ("front_axle_to_centre", q.front_axle_to_centre),
                ("centre_to_rear_axle", q.centre_to_rear_axle),
                ("front_track", q.front_track),
                ("rear_track", q.rear_track),
                ("front_suspension_spacing", q.front_suspension_spacing),
                ("rear_suspension_spacing", q.rear_suspension_spacing),
            ] {
                within(ck, &p(field), "a length", value, VEHICLE_LENGTH, "m");
            }
        }
    }
    within(ck, &p("speed"), "a speed", vehicle.speed(), SPEED, "m/s");
    within(
        ck,
        &p(entry_field),
        "the time before the vehicle reaches the bridge",
        vehicle.entry_time(),
        ENTRY_TIME,
        "s",
    );
}

/// Checks a train's car spacings (front wheelset to front wheelset, m) as
/// lengths within a vehicle, blamed at `car_spacing` when the file writes
/// one spacing for all cars, else at the car's own `spacing`.
fn check_car_spacings(ck: &mut Checker<'_>, at: &str, spacings: impl Iterator<Item = Option<f64>>) {
    let one = format!("{at}.car_spacing");
    let shared = ck.has(&one);
    for (k, spacing) in spacings.enumerate() {
        let Some(spacing) = spacing else { continue };
        let path = if shared {
            one.clone()
        } else {
            format!("{at}.cars[{k}].spacing")
        };
        let refused = within(ck, &path, "a car spacing", spacing, VEHICLE_LENGTH, "m");
        if shared && refused {
            // One message for the one value, not one per car.
            return;
        }
    }
}

/// Checks the bridge's stiffness and mass.
pub(crate) fn check_bridge(ck: &mut Checker<'_>, bridge: &Bridge) {
    match bridge {
        // An imported model's matrices are the user's FE program's; its
        // checks (symmetry, masses, stiffness) are made on import.
        Bridge::FeImport(_) => {}
        Bridge::Beam(b) => {
            check_spans(ck, &b.spans);
            if let Some(sway) = &b.sway {
                within(
                    ck,
                    "bridge.lateral_bending_stiffness",
                    "a lateral bending stiffness",
                    sway.lateral_bending_stiffness,
                    BENDING_STIFFNESS,
                    "N·m²",
                );
                within(
                    ck,
                    "bridge.torsional_stiffness",
                    "a torsional stiffness",
                    sway.torsional_stiffness,
                    TORSIONAL_STIFFNESS,
                    "N·m²/rad",
                );
                within(
                    ck,
                    "bridge.polar_mass",
                    "a polar mass moment of inertia per length",
                    sway.polar_mass,
                    POLAR_MASS_PER_LENGTH,
                    "kg·m²/m",
                );
                let h = sway.rail_height;
                if !(RAIL_HEIGHT.0..=RAIL_HEIGHT.1).contains(&h) {
                    ck.error(
                        "bridge.rail_height",
                        format!(
                            "a rail height of {} m is outside the physically plausible range {} to {} m",
                            number(h),
                            RAIL_HEIGHT.0,
                            RAIL_HEIGHT.1
                        ),
                    );
                }
            }
            within(
                ck,
                "bridge.bending_stiffness",
                "a bending stiffness",
                b.bending_stiffness,
                BENDING_STIFFNESS,
                "N·m²",
            );
            within(
                ck,
                "bridge.mass_per_length",
                "a mass per length",
                b.mass_per_length,
                MASS_PER_LENGTH,
                "kg/m",
            );
        }
        Bridge::Plate(p) => {
            check_spans(ck, &p.spans);
            within(
                ck,
                "bridge.mass_per_area",
                "a mass per area",
                p.mass_per_area,
                MASS_PER_AREA,
                "kg/m²",
            );
            let (dx, dy, _, _) = p.rigidity.rigidities(p.thickness.unwrap_or(0.0));
            let path = match p.rigidity {
                Rigidity::Isotropic { .. } => "bridge.rigidity.youngs_modulus",
                Rigidity::Orthotropic { .. } => "bridge.rigidity",
            };
            for d in [dx, dy] {
                if p.thickness.is_some() || matches!(p.rigidity, Rigidity::Orthotropic { .. }) {
                    within(ck, path, "a flexural rigidity", d, PLATE_RIGIDITY, "N·m");
                }
            }
        }
    }
}

/// Each span within [`SPAN`] (zero and negative ones are the sign checks').
fn check_spans(ck: &mut Checker<'_>, spans: &[f64]) {
    for (k, &span) in spans.iter().enumerate() {
        within(ck, &format!("bridge.spans[{k}]"), "a span", span, SPAN, "m");
    }
}

/// Checks a contact spring, which may have been derived from a ratio.
pub(crate) fn check_contact(ck: &mut Checker<'_>, contact: &Contact) {
    match contact {
        Contact::Elastic {
            stiffness,
            stiffness_ratio,
        } => {
            let path = if stiffness_ratio.is_some() {
                "contact.stiffness_ratio"
            } else {
                "contact.stiffness"
            };
            within(
                ck,
                path,
                "a contact stiffness",
                *stiffness,
                STIFFNESS,
                "N/m",
            );
        }
        Contact::Hertz { coefficient } => {
            within(
                ck,
                "contact",
                "a Hertz coefficient",
                *coefficient,
                HERTZ,
                "N/m^1.5",
            );
        }
        Contact::Permanent | Contact::Rigid { .. } => {}
    }
}
