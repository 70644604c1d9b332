//! Resolving 3D trains (`type: train_3d`): the AVE-S103 preset, overrides,
//! and the expansion into cars.

use super::cars::{CarRules, resolve_cars};
use super::checker::Checker;
use super::plausible::{DAMPING, MASS, STIFFNESS, within};
use super::raw::{Train3dParametersRaw, Train3dRaw};
use super::vehicles::{check_acceleration, check_speed, entry_time, lateral};
use crate::scene::{Train3d, Train3dCar, Train3dParameters, Vehicle};

/// The 3D car preset: the Siemens Velaro AVE-S103 of the EMBS paper's
/// Table 2 (Section 3.2), legible in our copy, per axle box (primary) and
/// per side of a bogie (secondary): body 47 800 kg, I_x 119 328, I_y and
/// I_z 1 957 888 kg·m²; bogie 3 500 kg, I_x 2 835, I_y 1 715, I_z
/// 4 235 kg·m²; wheelset 1 800 kg, I_x 1 000 kg·m²; primary k = 12 500 /
/// 120 000 / 1 200 kN/m and c = 9 / 27.9 / 10 kN·s/m (x / y / z);
/// secondary k = 240 / 240 / 350 kN/m and c = 30 / 30 / 20 kN·s/m; bogie
/// spacing d_b = 17.375 m (a = 8.6875 m); wheelbase d_w = 2.5 m
/// (b = 1.25 m); heights of the centres of gravity 1.50 m (body) and
/// 0.530 m (bogie); rolling radius R₀ = 0.43 m.
///
/// Not in Table 2, and so assumptions to override with a real car's data:
/// the lateral half spacings of the primary and secondary suspensions
/// (1.0 m each, the ICE 3 family's axle boxes and air springs are about
/// 2 m apart), the contact half spacing b₀ = 0.75 m (standard gauge,
/// 1 435 mm, contact points ≈ 1.5 m apart) and the secondary suspension's
/// height, 1.0 m above the rail (between the bogie's and the body's centre
/// of gravity).
pub const AVE_S103_PRESET: Train3dParameters = Train3dParameters {
    body_mass: 47_800.0,
    body_roll_inertia: 119_328.0,
    body_pitch_inertia: 1_957_888.0,
    body_yaw_inertia: 1_957_888.0,
    bogie_mass: 3_500.0,
    bogie_roll_inertia: 2_835.0,
    bogie_pitch_inertia: 1_715.0,
    bogie_yaw_inertia: 4_235.0,
    wheelset_mass: 1_800.0,
    wheelset_roll_inertia: 1_000.0,
    primary_stiffness: [12.5e6, 120e6, 1.2e6],
    primary_damping: [9e3, 27.9e3, 10e3],
    secondary_stiffness: [240e3, 240e3, 350e3],
    secondary_damping: [30e3, 30e3, 20e3],
    half_bogie_spacing: 17.375 / 2.0,
    half_wheelbase: 1.25,
    primary_half_spacing: 1.0,
    secondary_half_spacing: 1.0,
    contact_half_spacing: 0.75,
    body_height: 1.50,
    bogie_height: 0.53,
    secondary_height: 1.0,
    wheel_radius: 0.43,
};

/// A 3D car's wheelset span 2(a + b), m.
fn span(p: &Train3dParameters) -> f64 {
    2.0 * (p.half_bogie_spacing + p.half_wheelbase)
}

/// Applies the overrides `o` (at `path`) to `p`, checking each given value.
fn apply(
    p: &mut Train3dParameters,
    o: Option<&Train3dParametersRaw>,
    path: &str,
    ck: &mut Checker<'_>,
) {
    let Some(o) = o else { return };
    let [pkx, pky, pkz] = &mut p.primary_stiffness;
    let [pcx, pcy, pcz] = &mut p.primary_damping;
    let [skx, sky, skz] = &mut p.secondary_stiffness;
    let [scx, scy, scz] = &mut p.secondary_damping;
    // (name, target, given, zero allowed)
    let fields: [(&str, &mut f64, Option<f64>, bool); 31] = [
        ("body_mass", &mut p.body_mass, o.body_mass, false),
        (
            "body_roll_inertia",
            &mut p.body_roll_inertia,
            o.body_roll_inertia,
            false,
        ),
        (
            "body_pitch_inertia",
            &mut p.body_pitch_inertia,
            o.body_pitch_inertia,
            false,
        ),
        (
            "body_yaw_inertia",
            &mut p.body_yaw_inertia,
            o.body_yaw_inertia,
            false,
        ),
        ("bogie_mass", &mut p.bogie_mass, o.bogie_mass, false),
        (
            "bogie_roll_inertia",
            &mut p.bogie_roll_inertia,
            o.bogie_roll_inertia,
            false,
        ),
        (
            "bogie_pitch_inertia",
            &mut p.bogie_pitch_inertia,
            o.bogie_pitch_inertia,
            false,
        ),
        (
            "bogie_yaw_inertia",
            &mut p.bogie_yaw_inertia,
            o.bogie_yaw_inertia,
            false,
        ),
        (
            "wheelset_mass",
            &mut p.wheelset_mass,
            o.wheelset_mass,
            false,
        ),
        (
            "wheelset_roll_inertia",
            &mut p.wheelset_roll_inertia,
            o.wheelset_roll_inertia,
            false,
        ),
        (
            "primary_longitudinal_stiffness",
            pkx,
            o.primary_longitudinal_stiffness,
            true,
        ),
        (
            "primary_lateral_stiffness",
            pky,
            o.primary_lateral_stiffness,
            false,
        ),
        (
            "primary_vertical_stiffness",
            pkz,
            o.primary_vertical_stiffness,
            false,
        ),
        (
            "primary_longitudinal_damping",
            pcx,
            o.primary_longitudinal_damping,
            true,
        ),
        (
            "primary_lateral_damping",
            pcy,
            o.primary_lateral_damping,
            true,
        ),
        (
            "primary_vertical_damping",
            pcz,
            o.primary_vertical_damping,
            true,
        ),
        (
            "secondary_longitudinal_stiffness",
            skx,
            o.secondary_longitudinal_stiffness,
            true,
        ),
        (
            "secondary_lateral_stiffness",
            sky,
            o.secondary_lateral_stiffness,
            false,
        ),
        (
            "secondary_vertical_stiffness",
            skz,
            o.secondary_vertical_stiffness,
            false,
        ),
        (
            "secondary_longitudinal_damping",
            scx,
            o.secondary_longitudinal_damping,
            true,
        ),
        (
            "secondary_lateral_damping",
            scy,
            o.secondary_lateral_damping,
            true,
        ),
        (
            "secondary_vertical_damping",
            scz,
            o.secondary_vertical_damping,
            true,
        ),
        (
            "half_bogie_spacing",
            &mut p.half_bogie_spacing,
            o.half_bogie_spacing,
            false,
        ),
        (
            "half_wheelbase",
            &mut p.half_wheelbase,
            o.half_wheelbase,
            true,
        ),
        (
            "primary_half_spacing",
            &mut p.primary_half_spacing,
            o.primary_half_spacing,
            false,
        ),
        (
            "secondary_half_spacing",
            &mut p.secondary_half_spacing,
            o.secondary_half_spacing,
            false,
        ),
        (
            "contact_half_spacing",
            &mut p.contact_half_spacing,
            o.contact_half_spacing,
            false,
        ),
        ("body_height", &mut p.body_height, o.body_height, false),
        ("bogie_height", &mut p.bogie_height, o.bogie_height, false),
        (
            "secondary_height",
            &mut p.secondary_height,
            o.secondary_height,
            false,
        ),
        ("wheel_radius", &mut p.wheel_radius, o.wheel_radius, false),
    ];
    for (name, target, given, allow_zero) in fields {
        if let Some(value) = given {
            let at = format!("{path}.{name}");
            if allow_zero {
                ck.non_negative(&at, value, name);
            } else {
                ck.positive(&at, value, name);
            }
            *target = value;
        }
    }
}

/// Geometry a car needs: its wheelsets in order along the track.
fn check_geometry(ck: &mut Checker<'_>, path: &str, p: &Train3dParameters) {
    if p.half_wheelbase <= 0.0 {
        ck.error(
            path,
            format!(
                "half_wheelbase must be positive, got {} m: a bogie needs its two wheelsets \
                 apart to stand (with 0 its pitch has no support)",
                p.half_wheelbase
            ),
        );
    } else if p.half_wheelbase >= p.half_bogie_spacing {
        ck.error(
            path,
            format!(
                "half_wheelbase ({} m) must be less than half_bogie_spacing ({} m): the two \
                 bogies' wheelsets would overlap",
                p.half_wheelbase, p.half_bogie_spacing
            ),
        );
    }
}

/// Resolves a 3D train at `at`: one car, `count` cars at `car_spacing`, or
/// the `cars` list.
pub(crate) fn resolve_train_3d(
    v: &Train3dRaw,
    at: &str,
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vehicle {
    check_speed(ck, at, v.speed.0);
    let mut shared = AVE_S103_PRESET;
    let shared_at = format!("{at}.parameters");
    apply(&mut shared, v.parameters.as_ref(), &shared_at, ck);
    let rules = CarRules {
        apply,
        check: check_geometry,
        span,
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
        &shared_at,
        v.count,
        v.car_spacing,
        list,
        true,
    )
    .into_iter()
    .map(|c| Train3dCar {
        spacing: c.spacing,
        offset: c.offset,
        parameters: c.parameters,
    })
    .collect();
    Vehicle::Train3d(Train3d {
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

/// Plausible masses, inertias, springs and dampers of car `car` (from 1).
pub(crate) fn check_plausible(ck: &mut Checker<'_>, at: &str, car: usize, p: &Train3dParameters) {
    // The field named in the message, and blamed where the file gives it
    // (the train's `parameters`; a car's own override, or a preset value,
    // falls back to the nearest node the file has).
    let what = |field: &str, s: &str| format!("car {car}: {field}, {s}");
    let path = |field: &str| format!("{at}.{field}");
    for (field, value) in [
        ("body_mass", p.body_mass),
        ("bogie_mass", p.bogie_mass),
        ("wheelset_mass", p.wheelset_mass),
        ("body_roll_inertia", p.body_roll_inertia),
        ("body_pitch_inertia", p.body_pitch_inertia),
        ("body_yaw_inertia", p.body_yaw_inertia),
        ("bogie_roll_inertia", p.bogie_roll_inertia),
        ("bogie_pitch_inertia", p.bogie_pitch_inertia),
        ("bogie_yaw_inertia", p.bogie_yaw_inertia),
        ("wheelset_roll_inertia", p.wheelset_roll_inertia),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a mass or moment of inertia"),
            value,
            MASS,
            "kg or kg·m²",
        );
    }
    let directions = ["longitudinal", "lateral", "vertical"];
    for (group, values) in [
        ("primary", &p.primary_stiffness),
        ("secondary", &p.secondary_stiffness),
    ] {
        for (direction, &value) in directions.iter().zip(values) {
            let field = format!("{group}_{direction}_stiffness");
            within(
                ck,
                &path(&field),
                &what(&field, "a spring stiffness"),
                value,
                STIFFNESS,
                "N/m",
            );
        }
    }
    for (group, values) in [
        ("primary", &p.primary_damping),
        ("secondary", &p.secondary_damping),
    ] {
        for (direction, &value) in directions.iter().zip(values) {
            let field = format!("{group}_{direction}_damping");
            within(
                ck,
                &path(&field),
                &what(&field, "a suspension damping"),
                value,
                DAMPING,
                "N·s/m",
            );
        }
    }
    for (field, value) in [
        ("half_bogie_spacing", p.half_bogie_spacing),
        ("half_wheelbase", p.half_wheelbase),
        ("primary_half_spacing", p.primary_half_spacing),
        ("secondary_half_spacing", p.secondary_half_spacing),
        ("contact_half_spacing", p.contact_half_spacing),
        ("body_height", p.body_height),
        ("bogie_height", p.bogie_height),
        ("secondary_height", p.secondary_height),
        ("wheel_radius", p.wheel_radius),
    ] {
        within(
            ck,
            &path(field),
            &what(field, "a length"),
            value,
            (1e-3, 1e3),
            "m",
        );
    }
}
