//! Moving constant forces: axle loads at fixed spacings, no inertia
//! (Frýba, Vibration of Solids and Structures under Moving Loads, ch. 1).

use nalgebra::{DMatrix, DVector};

use super::{VehicleModel, Wheel, WheelKind};
use crate::scene::MovingForce;

/// A load set has no degrees of freedom; each axle is a [`WheelKind::Load`].
pub fn build(v: &MovingForce) -> VehicleModel {
    let mut offset = 0.0;
    let wheels = v
        .loads
        .iter()
        .enumerate()
        .map(|(i, &load)| {
            if i > 0 {
                offset += v.axle_spacings[i - 1];
            }
            Wheel {
                offset,
                lateral: 0.0,
                kind: WheelKind::Load(load),
                direction: crate::contact::ContactDirection::Vertical,
            }
        })
        .collect();
    VehicleModel {
        dof_names: Vec::new(),
        mass: DMatrix::zeros(0, 0),
        damping: DMatrix::zeros(0, 0),
        stiffness: DMatrix::zeros(0, 0),
        gravity_load: DVector::zeros(0),
        lateral_ground_load: DVector::zeros(0),
        blocks: Vec::new(),
        wheels,
        speed: v.speed,
        acceleration: 0.0,
        entry_time: v.entry_time,
        path_y: v.lateral_position.unwrap_or(0.0),
    }
}
