//! Where the wheels travel over the run, from the built vehicle models.

use crate::scenario::surfaces::Travel;
use crate::scene::Vehicle;
use crate::vehicle::VehicleModel;

/// Where the wheels of `vehicles` travel over a bridge of `length` m.
pub(crate) fn travel(
    vehicles: &[Vehicle],
    gravity: f64,
    length: f64,
    free_vibration: f64,
) -> Travel {
    let models: Vec<VehicleModel> = vehicles
        .iter()
        .map(|v| VehicleModel::build(v, gravity))
        .collect();
    let end_time = models
        .iter()
        .map(|m| m.exit_time(length))
        .fold(0.0, f64::max)
        + free_vibration;
    let start = models
        .iter()
        .map(|m| m.front_position(0.0) - m.wheels.iter().map(|w| w.offset).fold(0.0, f64::max))
        .fold(0.0, f64::min);
    let end = models
        .iter()
        .map(|m| m.front_position(end_time))
        .fold(0.0, f64::max);
    Travel { start, end }
}
