//! Resolving the plate paper's 7-DOF truck (`type: h20_44`): the preset and
//! the user's overrides.

use super::checker::Checker;
use super::raw;
use super::vehicles::{check_acceleration, check_speed, entry_time, lateral};
use crate::scene::{H20Truck, H20TruckParameters, Vehicle};

/// The preset of the plate paper's truck (`type: h20_44`).
///
/// The paper (Section 2.2) models "H20-44 ... in accordance with AASHTO",
/// and the geometry is AASHTO's H20-44: 4.27 m (14 ft) between the axles
/// and 1.83 m (6 ft) between the wheels of an axle. Its loads are not:
/// AASHTO's H20-44 has 8 kip (35.59 kN) on the front and 32 kip
/// (142.34 kN) on the rear axle ([`crate::scene::aashto`]), while the paper
/// states 2 × 58.81 kN front and 2 × 32.42 kN rear. The plate paper's
/// Table 1, which lists its vehicle data after Marchesiello et al. (1999,
/// J. Sound Vib. 224(3) 541–561) and Zhu & Law (2002, J. Sound Vib. 251(4)
/// 697–716), is not legible in our copy, and neither cited table could be
/// consulted here. The masses and the position of the centre of gravity are
/// therefore set to reproduce the static wheel loads the plate paper states
/// for the empty truck, 58.81 kN under each front wheel and 32.42 kN under
/// each rear wheel (its Section 3.2, Eq. 8): m_v = 16 200 kg, m₁ = m₂ =
/// 1 200 kg, a₁ = 1.426 m, a₂ = 2.844 m give 58.81 and 32.42 kN at
/// g = 9.81 m/s². Inertias, springs and dashpots are values typical of a
/// two-axle truck of this weight, chosen to give a body bounce near 2 Hz and
/// axle hop near 10 Hz: pitch 1.0e5 and roll 2.0e4 kg·m², axle roll 600
/// kg·m²; suspension 8.0e5 (front) and 6.0e5 N/m (rear) per wheel with
/// 1.2e4 and 8.0e3 N·s/m; tyres 1.75e6 N/m and 2.0e3 N·s/m per wheel;
/// suspensions 1.1 m apart. Every value can be overridden in `parameters`.
pub const H20_44_PRESET: H20TruckParameters = H20TruckParameters {
    body_mass: 16_200.0,
    body_pitch_inertia: 1.0e5,
    body_roll_inertia: 2.0e4,
    front_axle_mass: 1_200.0,
    rear_axle_mass: 1_200.0,
    front_axle_roll_inertia: 600.0,
    rear_axle_roll_inertia: 600.0,
    front_axle_to_centre: 1.426,
    centre_to_rear_axle: 2.844,
    front_track: 1.83,
    rear_track: 1.83,
    front_suspension_spacing: 1.1,
    rear_suspension_spacing: 1.1,
    front_suspension_stiffness: 8.0e5,
    rear_suspension_stiffness: 6.0e5,
    front_suspension_damping: 1.2e4,
    rear_suspension_damping: 8.0e3,
    front_tyre_stiffness: 1.75e6,
    rear_tyre_stiffness: 1.75e6,
    front_tyre_damping: 2.0e3,
    rear_tyre_damping: 2.0e3,
};

/// Resolves one H20-44 truck at `at` (e.g. `vehicles[0]`).
pub(crate) fn resolve_h20(
    v: &raw::H20TruckRaw,
    at: &str,
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vehicle {
    check_speed(ck, at, v.speed.0);
    let mut p = H20_44_PRESET;
    if let Some(o) = &v.parameters {
        let pat = format!("{at}.parameters");
        let mut take = |target: &mut f64, given: Option<f64>, name: &str, allow_zero: bool| {
            if let Some(value) = given {
                let path = format!("{pat}.{name}");
                if allow_zero {
                    ck.non_negative(&path, value, name);
                } else {
                    ck.positive(&path, value, name);
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
        take(
            &mut p.body_roll_inertia,
            o.body_roll_inertia,
            "body_roll_inertia",
            false,
        );
        take(
            &mut p.front_axle_mass,
            o.front_axle_mass,
            "front_axle_mass",
            false,
        );
        take(
            &mut p.rear_axle_mass,
            o.rear_axle_mass,
            "rear_axle_mass",
            false,
        );
        take(
            &mut p.front_axle_roll_inertia,
            o.front_axle_roll_inertia,
            "front_axle_roll_inertia",
            false,
        );
        take(
            &mut p.rear_axle_roll_inertia,
            o.rear_axle_roll_inertia,
            "rear_axle_roll_inertia",
            false,
        );
        take(
            &mut p.front_axle_to_centre,
            o.front_axle_to_centre,
            "front_axle_to_centre",
            true,
        );
        take(
            &mut p.centre_to_rear_axle,
            o.centre_to_rear_axle,
            "centre_to_rear_axle",
            true,
        );
        take(&mut p.front_track, o.front_track, "front_track", false);
        take(&mut p.rear_track, o.rear_track, "rear_track", false);
        take(
            &mut p.front_suspension_spacing,
            o.front_suspension_spacing,
            "front_suspension_spacing",
            false,
        );
        take(
            &mut p.rear_suspension_spacing,
            o.rear_suspension_spacing,
            "rear_suspension_spacing",
            false,
        );
        take(
            &mut p.front_suspension_stiffness,
            o.front_suspension_stiffness,
            "front_suspension_stiffness",
            false,
        );
        take(
            &mut p.rear_suspension_stiffness,
            o.rear_suspension_stiffness,
            "rear_suspension_stiffness",
            false,
        );
        take(
            &mut p.front_suspension_damping,
            o.front_suspension_damping,
            "front_suspension_damping",
            true,
        );
        take(
            &mut p.rear_suspension_damping,
            o.rear_suspension_damping,
            "rear_suspension_damping",
            true,
        );
        take(
            &mut p.front_tyre_stiffness,
            o.front_tyre_stiffness,
            "front_tyre_stiffness",
            false,
        );
        take(
            &mut p.rear_tyre_stiffness,
            o.rear_tyre_stiffness,
            "rear_tyre_stiffness",
            false,
        );
        take(
            &mut p.front_tyre_damping,
            o.front_tyre_damping,
            "front_tyre_damping",
            true,
        );
        take(
            &mut p.rear_tyre_damping,
            o.rear_tyre_damping,
            "rear_tyre_damping",
            true,
        );
        if p.front_axle_to_centre + p.centre_to_rear_axle <= 0.0 {
            ck.error(&pat, "the axles must be apart: a₁ + a₂ > 0");
        }
    }
    let half_track = 0.5 * p.front_track.max(p.rear_track);
    let lateral_position = lateral(ck, at, v.lateral_position, width, half_track);
    Vehicle::H20Truck(H20Truck {
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
        lateral_position,
        parameters: p,
    })
}
