//! Resolving rail vehicles: the rail car's preset and overrides, and a
//! train's expansion into cars.

use super::cars::{CarRules, resolve_cars};
use super::checker::Checker;
use super::plausible::{DAMPING, MASS, MOMENT_OF_INERTIA, STIFFNESS, VEHICLE_LENGTH, within};
use super::raw;
use super::vehicles::{check_acceleration, check_speed, entry_time, lateral};
use crate::scene::wheelset_span;
use crate::scene::{RailCar, RailCarParameters, Train, TrainCar, Vehicle};

/// The rail car preset: the LCP separation paper's Table 2 (Section 5.2),
/// whose values are legible in our copy: car body M_c = 31 994 kg and
/// J_c = 2.1e6 kg·m²; bogie M_b = 3 333 kg and J_b = 3 200 kg·m²; wheelset
/// M_w = 1 650 kg; primary suspension k_p = 4 720 kN/m and c_p = 160 kN·s/m
/// per wheelset; secondary suspension k_s = 160 kN/m and c_s = 200 kN·s/m
/// per bogie; half bogie spacing a = 8.75 m; half wheelbase b = 1.25 m.
/// Every value can be overridden in `parameters`.
pub const LCP_RAIL_CAR_PRESET: RailCarParameters = RailCarParameters {
    body_mass: 31_994.0,
    body_pitch_inertia: 2.1e6,
    bogie_mass: 3_333.0,
    bogie_pitch_inertia: 3_200.0,
    wheelset_mass: 1_650.0,
    primary_stiffness: 4.72e6,
    primary_damping: 1.6e5,
    secondary_stiffness: 1.6e5,
    secondary_damping: 2.0e5,
    half_bogie_spacing: 8.75,
    half_wheelbase: 1.25,
};

/// Most cars in one train (a freight train of 3 km has ~200 cars); the
/// wheel budget (`limits.wheels`) usually binds first.
pub const MAX_CARS: usize = 1_000;

/// Applies the overrides `o` (at `path`) to `p`, checking each given value.
fn apply(
    p: &mut RailCarParameters,
    o: Option<&raw::RailCarParametersRaw>,
    path: &str,
    ck: &mut Checker<'_>,
) {
    let Some(o) = o else { return };
    let mut take = |target: &mut f64, given: Option<f64>, name: &str, allow_zero: bool| {
        if let Some(value) = given {
            let at = format!("{path}.{name}");
            if allow_zero {
                ck.non_negative(&at, value, name);
            } else {
                ck.positive(&at, value, name);
            }
            *target = value;
        }
    };
    take(&mut p.body_mass, o.body_mass, "body_mass", false);
    take(
        &mut p.body_pitch_inertia,
        o.body_pitch_inertia,
        "body_pitch_inertia",
        false,
    );
    take(&mut p.bogie_mass, o.bogie_mass, "bogie_mass", false);
    take(
        &mut p.bogie_pitch_inertia,
        o.bogie_pitch_inertia,
        "bogie_pitch_inertia",
        false,
    );
    take(
        &mut p.wheelset_mass,
        o.wheelset_mass,
        "wheelset_mass",
        false,
    );
    take(
        &mut p.primary_stiffness,
        o.primary_stiffness,
        "primary_stiffness",
        false,
    );
    take(
        &mut p.primary_damping,
        o.primary_damping,
        "primary_damping",
        true,
    );
    take(
        &mut p.secondary_stiffness,
        o.secondary_stiffness,
        "secondary_stiffness",
        false,
    );
    take(
        &mut p.secondary_damping,
        o.secondary_damping,
        "secondary_damping",
        true,
    );
    take(
        &mut p.half_bogie_spacing,
        o.half_bogie_spacing,
        "half_bogie_spacing",
        true,
    );
    take(
        &mut p.half_wheelbase,
        o.half_wheelbase,
        "half_wheelbase",
        true,
    );
}

/// Resolves one rail car at `at` (e.g. `vehicles[0]`).
pub(crate) fn resolve_rail_car(
    v: &raw::RailCarRaw,
    at: &str,
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vehicle {
    check_speed(ck, at, v.speed.0);
    let mut p = LCP_RAIL_CAR_PRESET;
    let parameters_at = format!("{at}.parameters");
    apply(&mut p, v.parameters.as_ref(), &parameters_at, ck);
    check_geometry(ck, &parameters_at, &p);
    Vehicle::RailCar(RailCar {
        speed: v.speed.0,
        acceleration: check_acceleration(ck, at, v.acceleration),
        entry_time: entry_time(
            ck,
            at,
            v.speed.0,
            v.acceleration.unwrap_or(0.0),
            v.entry_time,
            v.start_position,
        ),
        lateral_position: lateral(ck, at, v.lateral_position, width, 0.0),
        parameters: p,
    })
}

/// Resolves a train at `at`: `count` cars at `car_spacing`, or the `cars`
/// list, each car's front-wheelset offset behind the first car's summed
/// from the spacings. A spacing shorter than the car ahead's wheelset span
/// would put wheels of two cars out of order on the track and is refused.
pub(crate) fn resolve_train(
    v: &raw::TrainRaw,
    at: &str,
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vehicle {
    check_speed(ck, at, v.speed.0);
    let mut shared = LCP_RAIL_CAR_PRESET;
    apply(
        &mut shared,
        v.parameters.as_ref(),
        &format!("{at}.parameters"),
        ck,
    );
    let rules = CarRules {
        apply,
        check: check_geometry,
        span: wheelset_span,
    };
    let list = v.cars.as_ref().map(|list| {
        list.iter()
            .map(|c| (c.spacing, c.parameters.as_ref()))
            .collect()
    });
    let cars = resolve_cars(
        ck,
        at,
        &rules,
        shared,
        &format!("{at}.parameters"),
        v.count,
        v.car_spacing,
        list,
        false,
    )
    .into_iter()
    .map(|c| TrainCar {
        spacing: c.spacing,
        offset: c.offset,
        parameters: c.parameters,
    })
    .collect();
    Vehicle::Train(Train {
        speed: v.speed.0,
        acceleration: check_acceleration(ck, at, v.acceleration),
        entry_time: entry_time(
            ck,
            at,
            v.speed.0,
            v.acceleration.unwrap_or(0.0),
            v.entry_time,
            v.start_position,
        ),
        lateral_position: lateral(ck, at, v.lateral_position, width, 0.0),
        cars,
    })
}

/// Plausible masses, springs and dampers of one car's parameters; `at` is
/// where they are blamed and `car` names the car of a train in messages.
pub(crate) fn check_plausible(
    ck: &mut Checker<'_>,
    at: &str,
    car: Option<usize>,
    p: &RailCarParameters,
) {
    // The field named in the message, and blamed where the file gives it
    // (the train's `parameters`; a car's own override, or a preset value,
    // falls back to the nearest node the file has).
    let what = |field: &str, s: &str| match car {
        Some(k) => format!("car {k}: {field}, {s}"),
        None => format!("{field}, {s}"),
    };
    let path = |field: &str| format!("{at}.{field}");
    for (field, value) in [
        ("body_mass", p.body_mass),
        ("bogie_mass", p.bogie_mass),
        ("wheelset_mass", p.wheelset_mass),
    ] {
        within(ck, &path(field), &what(field, "a mass"), value, MASS, "kg");
    }
    for (field, value) in [
        ("primary_stiffness", p.primary_stiffness),
        ("secondary_stiffness", p.secondary_stiffness),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a spring stiffness"),
            value,
            STIFFNESS,
            "N/m",
        );
    }
    for (field, value) in [
        ("primary_damping", p.primary_damping),
        ("secondary_damping", p.secondary_damping),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a suspension damping"),
            value,
            DAMPING,
            "N·s/m",
        );
    }
    for (field, value) in [
        ("body_pitch_inertia", p.body_pitch_inertia),
        ("bogie_pitch_inertia", p.bogie_pitch_inertia),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a moment of inertia"),
            value,
            MOMENT_OF_INERTIA,
            "kg·m²",
        );
    }
    for (field, value) in [
        ("half_bogie_spacing", p.half_bogie_spacing),
        ("half_wheelbase", p.half_wheelbase),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a length"),
            value,
            VEHICLE_LENGTH,
            "m",
        );
    }
}

/// Geometry a rail car needs to stand: each bogie on two wheelsets apart
/// (a zero wheelbase leaves the bogie's pitch without a spring: no static
/// equilibrium), and the two bogies apart and not overlapping (the rear
/// wheelset of the front bogie ahead of the front wheelset of the rear
/// one: a > b). Blamed at the field the file gives, else at the car's
/// parameters.
pub(crate) fn check_geometry(ck: &mut Checker<'_>, path: &str, p: &RailCarParameters) {
    let at = |field: &str| {
        let given = format!("{path}.{field}");
        if ck.has(&given) {
            given
        } else {
            path.to_owned()
        }
    };
    if p.half_wheelbase <= 0.0 {
        let at = at("half_wheelbase");
        ck.error(
            &at,
            format!(
                "half_wheelbase must be positive, got {} m: a bogie needs its two wheelsets \
                 apart to stand (with 0 its pitch has no support)",
                p.half_wheelbase
            ),
        );
    } else if p.half_bogie_spacing <= p.half_wheelbase {
        let at = at("half_bogie_spacing");
        ck.error(
            &at,
            format!(
                "half_bogie_spacing ({} m) must be more than half_wheelbase ({} m): the two \
                 bogies' wheelsets would overlap",
                p.half_bogie_spacing, p.half_wheelbase
            ),
        );
    }
}
