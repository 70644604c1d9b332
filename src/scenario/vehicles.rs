//! The vehicles' resolution: each vehicle checked and its defaults filled in
//! as the file writes it, and the checks the vehicle types share (speed,
//! acceleration, entry time, the path's lateral position).

use super::checker::Checker;
use super::raw;
use crate::scene::aashto::{HS20_44_REAR_SPACING_MAX, HS20_44_REAR_SPACING_MIN};
use crate::scene::*;

/// Entry time from `entry_time` / `start_position` (front axle at t = 0),
/// for a vehicle at `speed` (m/s, at t = 0) with constant `acceleration`
/// (m/s²). A braking vehicle must still be moving when it reaches the
/// entrance: one that stops before gets a located error.
pub(crate) fn entry_time(
    ck: &mut Checker<'_>,
    at: &str,
    speed: f64,
    acceleration: f64,
    entry_time: Option<f64>,
    start_position: Option<f64>,
) -> f64 {
    let stop = crate::scene::motion::Motion {
        speed,
        acceleration,
        entry_time: 0.0,
    }
    .stop_time();
    // A speed with a type error (a placeholder stands for it): where the
    // vehicle would stop is not known.
    let speed_known = !ck.is_placeholder(&format!("{at}.speed"));
    let stop = stop.filter(|_| speed_known);
    match (entry_time, start_position) {
        (Some(_), Some(_)) => {
            ck.error(
                &format!("{at}.start_position"),
                "give `entry_time` or `start_position`, not both",
            );
            0.0
        }
        (Some(t), None) => {
            ck.non_negative(&format!("{at}.entry_time"), t, "entry time");
            if let Some(stop) = stop.filter(|&stop| t >= stop && speed > 0.0) {
                ck.error(
                    &format!("{at}.entry_time"),
                    format!(
                        "braking at {acceleration} m/s² from {speed} m/s, the vehicle stops at \
                         t = {stop:.4} s, before its entry time of {t} s"
                    ),
                );
            }
            t
        }
        (None, Some(x)) => {
            if x > 0.0 {
                ck.error(
                    &format!("{at}.start_position"),
                    format!("the vehicle must start on the approach (start_position ≤ 0), got {x}"),
                );
            }
            if speed <= 0.0 || !acceleration.is_finite() || !speed_known {
                return 0.0;
            }
            match crate::scene::motion::time_to_cover(speed, acceleration, (-x).max(0.0)) {
                Some(t) => t,
                None => {
                    let reach = speed * speed / (-2.0 * acceleration);
                    ck.error(
                        &format!("{at}.acceleration"),
                        format!(
                            "braking at {acceleration} m/s² from {speed} m/s, the vehicle stops \
                             after {reach:.4} m, {:.4} m before the bridge (start_position {x})",
                            -x - reach
                        ),
                    );
                    0.0
                }
            }
        }
        (None, None) => 0.0,
    }
}

/// Largest |acceleration| accepted, m/s² (ten times what any train or road
/// vehicle brakes at; beyond it the input is surely a unit mistake).
pub const MAX_ACCELERATION: f64 = 100.0;

/// Checks a vehicle's acceleration (`None`: 0) and returns it, m/s².
pub(crate) fn check_acceleration(ck: &mut Checker<'_>, at: &str, acceleration: Option<f64>) -> f64 {
    let a = acceleration.unwrap_or(0.0);
    if !a.is_finite() || a.abs() > MAX_ACCELERATION {
        ck.error(
            &format!("{at}.acceleration"),
            format!("an acceleration must be a number within ±{MAX_ACCELERATION} m/s², got {a}"),
        );
        return 0.0;
    }
    a
}

/// Highest vehicle speed accepted, m/s (beyond any vehicle; keeps the time
/// grid and the contact kinematics meaningful).
pub const MAX_SPEED: f64 = 1000.0;

pub(crate) fn check_speed(ck: &mut Checker<'_>, at: &str, speed: f64) {
    ck.positive(&format!("{at}.speed"), speed, "speed");
    if speed > MAX_SPEED {
        ck.error(
            &format!("{at}.speed"),
            format!("a speed of {speed} m/s is above {MAX_SPEED} m/s"),
        );
    }
}

pub(crate) fn resolve_vehicles(
    raws: &[raw::VehicleRaw],
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Option<Vec<Vehicle>> {
    let before = ck.diagnostics.len();
    let out = vehicles_as_written(raws, width, ck);
    (ck.diagnostics.len() == before).then_some(out)
}

/// The vehicles as the file writes them, checked; one per entry even where
/// an entry has errors (its values then are placeholders), so that records
/// can still be checked against their kinds, wheels and cars.
pub(crate) fn vehicles_as_written(
    raws: &[raw::VehicleRaw],
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vec<Vehicle> {
    if raws.is_empty() {
        ck.error("vehicles", "`vehicles` needs at least one vehicle");
    }
    let mut out = Vec::with_capacity(raws.len());
    for (i, raw) in raws.iter().enumerate() {
        let at = format!("vehicles[{i}]");
        // An HSLM train or an AASHTO truck is its table's moving forces.
        if let raw::VehicleRaw::AashtoHs20(h) = raw
            && let Some(rear) = h.rear_axle_spacing
            && !(HS20_44_REAR_SPACING_MIN..=HS20_44_REAR_SPACING_MAX).contains(&rear)
        {
            ck.error(
                &format!("{at}.rear_axle_spacing"),
                format!(
                    "the HS20-44 rear axle spacing is {HS20_44_REAR_SPACING_MIN} m (14 ft) to \
                     {HS20_44_REAR_SPACING_MAX} m (30 ft) (AASHTO Fig. 3.7.7A), got {rear} m"
                ),
            );
        }
        let forces;
        let raw = match raw.as_axle_forces() {
            Some(moving_force) => {
                forces = raw::VehicleRaw::MovingForce(moving_force);
                &forces
            }
            None => raw,
        };
        match raw {
            raw::VehicleRaw::MovingForce(v) => {
                check_speed(ck, &at, v.speed.0);
                if v.loads.is_empty() {
                    ck.error(
                        &format!("{at}.loads"),
                        "`loads` needs at least one axle load",
                    );
                }
                for (k, &p) in v.loads.iter().enumerate() {
                    ck.positive(&format!("{at}.loads[{k}]"), p, "an axle load");
                }
                let spacings = match (&v.axle_positions, &v.axle_spacings) {
                    (Some(positions), given) => {
                        if given.is_some() {
                            ck.error(
                                &format!("{at}.axle_positions"),
                                "give `axle_spacings` or `axle_positions`, not both",
                            );
                        }
                        axle_positions_to_spacings(ck, &at, positions, v.loads.len())
                    }
                    (None, given) => given.clone().unwrap_or_default(),
                };
                if v.axle_positions.is_none() && spacings.len() + 1 != v.loads.len().max(1) {
                    let path = if v.axle_spacings.is_some() {
                        format!("{at}.axle_spacings")
                    } else {
                        at.clone()
                    };
                    let message = format!(
                        "{} axle loads need {} axle spacings, found {}",
                        v.loads.len(),
                        v.loads.len().saturating_sub(1),
                        spacings.len()
                    );
                    // A consequence of the type error that lost an axle.
                    if lost_axle(ck, &at) {
                        ck.consequence(&at, message);
                    } else {
                        ck.error(&path, message);
                    }
                }
                for (k, &s) in spacings.iter().enumerate() {
                    ck.positive(&format!("{at}.axle_spacings[{k}]"), s, "an axle spacing");
                }
                let acceleration = check_acceleration(ck, &at, v.acceleration);
                let entry = entry_time(
                    ck,
                    &at,
                    v.speed.0,
                    acceleration,
                    v.entry_time,
                    v.start_position,
                );
                out.push(Vehicle::MovingForce(MovingForce {
                    loads: v.loads.clone(),
                    axle_spacings: spacings,
                    speed: v.speed.0,
                    acceleration,
                    entry_time: entry,
                    lateral_position: lateral(ck, &at, v.lateral_position, width, 0.0),
                }));
            }
            raw::VehicleRaw::Oscillator(v) => {
                let unsprung = v.unsprung_mass.unwrap_or(0.0);
                let lateral_position = lateral(ck, &at, v.lateral_position, width, 0.0);
                let damping = v.damping.unwrap_or(0.0);
                if v.dimensionless.is_some() {
                    // Derived once the bridge's first frequency is known.
                    out.push(Vehicle::Oscillator(Oscillator {
                        sprung_mass: 0.0,
                        unsprung_mass: 0.0,
                        stiffness: 0.0,
                        damping: 0.0,
                        speed: 0.0,
                        acceleration: 0.0,
                        entry_time: 0.0,
                        lateral_position,
                        dimensionless: None,
                    }));
                    continue;
                }
                let mut required = |field: &str, value: Option<f64>| {
                    value.unwrap_or_else(|| {
                        ck.error(
                            &at,
                            format!("an oscillator needs `{field}` (or `dimensionless`)"),
                        );
                        0.0
                    })
                };
                let (sprung, stiffness, speed) = (
                    required("sprung_mass", v.sprung_mass),
                    required("stiffness", v.stiffness),
                    required("speed", v.speed.map(|s| s.0)),
                );
                check_speed(ck, &at, speed);
                ck.positive(&format!("{at}.sprung_mass"), sprung, "sprung mass");
                ck.non_negative(&format!("{at}.unsprung_mass"), unsprung, "unsprung mass");
                ck.positive(
                    &format!("{at}.stiffness"),
                    stiffness,
                    "suspension stiffness",
                );
                ck.non_negative(&format!("{at}.damping"), damping, "suspension damping");
                let acceleration = check_acceleration(ck, &at, v.acceleration);
                let entry =
                    entry_time(ck, &at, speed, acceleration, v.entry_time, v.start_position);
                out.push(Vehicle::Oscillator(Oscillator {
                    sprung_mass: sprung,
                    unsprung_mass: unsprung,
                    stiffness,
                    damping,
                    speed,
                    acceleration,
                    entry_time: entry,
                    lateral_position,
                    dimensionless: None,
                }));
            }
            raw::VehicleRaw::H20Truck(v) => {
                out.push(super::truck::resolve_h20(v, &at, width, ck));
            }
            raw::VehicleRaw::RailCar(v) => {
                out.push(super::rail::resolve_rail_car(v, &at, width, ck));
            }
            // Turned into moving forces above.
            raw::VehicleRaw::Hslm(_)
            | raw::VehicleRaw::AashtoH20(_)
            | raw::VehicleRaw::AashtoHs20(_) => {}
            raw::VehicleRaw::Train(v) => {
                out.push(super::rail::resolve_train(v, &at, width, ck));
            }
            raw::VehicleRaw::Train3d(v) => {
                out.push(super::rail_3d::resolve_train_3d(v, &at, width, ck));
            }
        }
    }
    out
}

/// An axle-load train's axle positions behind its front axle (0 first,
/// strictly increasing, one per load) as the spacings between consecutive
/// axles, m; errors at `{at}.axle_positions`.
/// Whether the axle lists of the vehicle at `at` lost an item to a type
/// error (already reported): their lengths are then not compared.
fn lost_axle(ck: &Checker<'_>, at: &str) -> bool {
    ["loads", "axle_spacings", "axle_positions"]
        .iter()
        .any(|list| ck.uncertain(&format!("{at}.{list}")))
}

fn axle_positions_to_spacings(
    ck: &mut Checker<'_>,
    at: &str,
    positions: &[f64],
    loads: usize,
) -> Vec<f64> {
    let path = format!("{at}.axle_positions");
    if positions.len() != loads {
        let message = format!(
            "{loads} axle loads need {loads} axle positions, found {}",
            positions.len()
        );
        // A consequence of the type error that lost an axle.
        if lost_axle(ck, at) {
            ck.consequence(at, message);
        } else {
            ck.error(&path, message);
        }
        return Vec::new();
    }
    if let Some(&first) = positions.first()
        && first != 0.0
    {
        ck.error(
            &format!("{path}[0]"),
            format!("the front axle is the reference: its position must be 0, got {first}"),
        );
    }
    let mut spacings = Vec::with_capacity(positions.len().saturating_sub(1));
    for (k, pair) in positions.windows(2).enumerate() {
        let spacing = pair[1] - pair[0];
        if spacing <= 0.0 {
            ck.error(
                &format!("{path}[{}]", k + 1),
                format!(
                    "axle positions must increase from front to rear: {} m follows {} m",
                    pair[1], pair[0]
                ),
            );
        }
        spacings.push(spacing);
    }
    spacings
}

/// The transverse position of a vehicle's path: only on a plate (default
/// its centre line), with every wheel at `half_track` either side on the deck.
pub(crate) fn lateral(
    ck: &mut Checker<'_>,
    at: &str,
    given: Option<f64>,
    width: Option<f64>,
    half_track: f64,
) -> Option<f64> {
    match (given, width) {
        // Without a valid bridge the deck's width is not known.
        (Some(given), None) if ck.bridge_unknown => Some(given),
        (Some(_), None) => {
            ck.error(
                &format!("{at}.lateral_position"),
                "`lateral_position` places a vehicle across a plate deck; a beam has no width",
            );
            None
        }
        (None, None) => None,
        (given, Some(width)) => {
            let y = given.unwrap_or(width / 2.0);
            if y - half_track < 0.0 || y + half_track > width {
                let path = if given.is_some() {
                    format!("{at}.lateral_position")
                } else {
                    at.to_owned()
                };
                ck.error(
                    &path,
                    format!(
                        "wheels at y = {:.4} to {:.4} m fall off the deck, which spans 0 to {width} m",
                        y - half_track,
                        y + half_track
                    ),
                );
            }
            Some(y)
        }
    }
}
