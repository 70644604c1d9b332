//! Oscillators given by dimensionless groups, derived once the bridge's
//! first natural frequency is known (LCP separation paper, Table 1).

use crate::bridge::ModalBridge;
use crate::scenario::checker::Checker;
use crate::scenario::raw;
use crate::scene::*;

/// Relative difference below which a given value agrees with a derived one.
const AGREEMENT: f64 = 1e-9;

/// Checks that an optional given value agrees with a derived one.
fn agree(ck: &mut Checker<'_>, path: &str, given: Option<f64>, derived: f64, what: &str) {
    if let Some(g) = given
        && (g - derived).abs() > AGREEMENT * derived.abs().max(g.abs())
    {
        ck.error(
            path,
            format!("{what} {g} disagrees with the {derived} derived from the dimensionless groups; give one or the other"),
        );
    }
}

/// Fills in oscillators given by dimensionless groups, now that the bridge's
/// first natural frequency f₁ is known (LCP separation paper, Table 1).
pub(crate) fn derive_dimensionless(
    raws: &[raw::VehicleRaw],
    vehicles: &mut [Vehicle],
    bridge: &Bridge,
    modal: &ModalBridge,
    ck: &mut Checker<'_>,
) {
    let f1 = modal.frequencies()[0];
    for (i, (raw, vehicle)) in raws.iter().zip(vehicles.iter_mut()).enumerate() {
        let raw::VehicleRaw::Oscillator(o) = raw else {
            continue;
        };
        let Some(d) = &o.dimensionless else { continue };
        let at = format!("vehicles[{i}]");
        let groups = Dimensionless {
            velocity_ratio: d.velocity_ratio,
            mass_ratio: d.mass_ratio,
            unsprung_ratio: d.unsprung_ratio.unwrap_or(0.0),
            frequency_ratio: d.frequency_ratio,
            damping_ratio: d.damping_ratio.unwrap_or(0.0),
        };
        let dpath = |field: &str| format!("{at}.dimensionless.{field}");
        ck.positive(
            &dpath("velocity_ratio"),
            groups.velocity_ratio,
            "velocity ratio",
        );
        ck.positive(&dpath("mass_ratio"), groups.mass_ratio, "mass ratio");
        ck.non_negative(
            &dpath("unsprung_ratio"),
            groups.unsprung_ratio,
            "unsprung ratio",
        );
        ck.positive(
            &dpath("frequency_ratio"),
            groups.frequency_ratio,
            "frequency ratio",
        );
        crate::scenario::checker::check_ratio(ck, &dpath("damping_ratio"), groups.damping_ratio);
        let mut derived = groups.derive(f1, modal.length, bridge.mass_per_length(), 0.0);
        // The derived speed is blamed on the ratio that gives it.
        if derived.speed > crate::scenario::vehicles::MAX_SPEED {
            ck.error(
                &dpath("velocity_ratio"),
                format!(
                    "a velocity ratio of {} gives a speed of {:.4e} m/s (2 × ratio × f1 × L, \
                     f1 = {f1:.4} Hz, L = {} m), above {} m/s",
                    groups.velocity_ratio,
                    derived.speed,
                    modal.length,
                    crate::scenario::vehicles::MAX_SPEED
                ),
            );
        }
        agree(
            ck,
            &format!("{at}.sprung_mass"),
            o.sprung_mass,
            derived.sprung_mass,
            "sprung_mass",
        );
        agree(
            ck,
            &format!("{at}.unsprung_mass"),
            o.unsprung_mass,
            derived.unsprung_mass,
            "unsprung_mass",
        );
        agree(
            ck,
            &format!("{at}.stiffness"),
            o.stiffness,
            derived.stiffness,
            "stiffness",
        );
        agree(
            ck,
            &format!("{at}.damping"),
            o.damping,
            derived.damping,
            "damping",
        );
        agree(
            ck,
            &format!("{at}.speed"),
            o.speed.map(|s| s.0),
            derived.speed,
            "speed",
        );
        derived.acceleration =
            crate::scenario::vehicles::check_acceleration(ck, &at, o.acceleration);
        derived.entry_time = crate::scenario::vehicles::entry_time(
            ck,
            &at,
            derived.speed,
            derived.acceleration,
            o.entry_time,
            o.start_position,
        );
        derived.lateral_position = vehicle.lateral_position();
        *vehicle = Vehicle::Oscillator(derived);
    }
}
