//! The vehicles of the scene: moving forces (AASHTO trucks and HSLM trains
//! among them), oscillators, the plate paper's 7-DOF truck, rail cars and
//! trains (their kinematics: [`crate::scene::motion`]).

use serde::Serialize;

use super::*;

/// A vehicle.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Vehicle {
    /// Constant axle loads.
    MovingForce(MovingForce),
    /// Two-mass oscillator.
    Oscillator(Oscillator),
    /// The plate paper's seven-DOF truck (`h20_44`: its Section 2.2; static
    /// wheel forces 58.81 / 32.42 kN, not AASHTO's H20-44 axle loads).
    #[serde(rename = "h20_44")]
    H20Truck(H20Truck),
    /// Four-axle 10-DOF rail car.
    RailCar(RailCar),
    /// A train of rail cars.
    Train(Train),
    /// A train of 27-DOF 3D cars.
    #[serde(rename = "train_3d")]
    Train3d(Train3d),
}

impl Vehicle {
    /// Transverse position of the vehicle's path on a plate deck, m.
    pub fn lateral_position(&self) -> Option<f64> {
        match self {
            Vehicle::MovingForce(v) => v.lateral_position,
            Vehicle::Oscillator(v) => v.lateral_position,
            Vehicle::H20Truck(v) => v.lateral_position,
            Vehicle::RailCar(v) => v.lateral_position,
            Vehicle::Train(v) => v.lateral_position,
            Vehicle::Train3d(v) => v.lateral_position,
        }
    }

    /// Constant acceleration, m/s².
    pub fn acceleration(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.acceleration,
            Vehicle::Oscillator(v) => v.acceleration,
            Vehicle::H20Truck(v) => v.acceleration,
            Vehicle::RailCar(v) => v.acceleration,
            Vehicle::Train(v) => v.acceleration,
            Vehicle::Train3d(v) => v.acceleration,
        }
    }

    /// Speed at t = 0, m/s.
    pub fn speed(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.speed,
            Vehicle::Oscillator(v) => v.speed,
            Vehicle::H20Truck(v) => v.speed,
            Vehicle::RailCar(v) => v.speed,
            Vehicle::Train(v) => v.speed,
            Vehicle::Train3d(v) => v.speed,
        }
    }
    /// Time at which the front axle reaches the entrance, s.
    pub fn entry_time(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.entry_time,
            Vehicle::Oscillator(v) => v.entry_time,
            Vehicle::H20Truck(v) => v.entry_time,
            Vehicle::RailCar(v) => v.entry_time,
            Vehicle::Train(v) => v.entry_time,
            Vehicle::Train3d(v) => v.entry_time,
        }
    }
    /// Sets the time at which the front axle reaches the entrance, s.
    pub fn set_entry_time(&mut self, t: f64) {
        match self {
            Vehicle::MovingForce(v) => v.entry_time = t,
            Vehicle::Oscillator(v) => v.entry_time = t,
            Vehicle::H20Truck(v) => v.entry_time = t,
            Vehicle::RailCar(v) => v.entry_time = t,
            Vehicle::Train(v) => v.entry_time = t,
            Vehicle::Train3d(v) => v.entry_time = t,
        }
    }
    /// Distance from the front axle back to the rear axle, m.
    pub fn length(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.axle_spacings.iter().sum(),
            Vehicle::Oscillator(_) => 0.0,
            Vehicle::H20Truck(v) => {
                v.parameters.front_axle_to_centre + v.parameters.centre_to_rear_axle
            }
            Vehicle::RailCar(v) => wheelset_span(&v.parameters),
            Vehicle::Train(v) => v.length(),
            Vehicle::Train3d(v) => v.length(),
        }
    }
    /// Type name as written in the format.
    pub fn type_name(&self) -> &'static str {
        match self {
            Vehicle::MovingForce(_) => "moving_force",
            Vehicle::Oscillator(_) => "oscillator",
            Vehicle::H20Truck(_) => "h20_44",
            Vehicle::RailCar(_) => "rail_car",
            Vehicle::Train(_) => "train",
            Vehicle::Train3d(_) => "train_3d",
        }
    }
}

/// Constant axle loads.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MovingForce {
    /// Axle loads, N, front first.
    pub loads: Vec<f64>,
    /// Spacings between consecutive axles, m.
    pub axle_spacings: Vec<f64>,
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front axle reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
}

/// The plate paper's seven-DOF truck (`type: h20_44`; its Section 2.2 and
/// Appendix A), which the paper names H20-44 after AASHTO but loads with its
/// own static wheel forces, 58.81 kN front and 32.42 kN rear (Section 3.2).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct H20Truck {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front axle reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// Every parameter, preset values filled in.
    pub parameters: H20TruckParameters,
}

/// The plate paper's truck parameters (see the raw format for each
/// meaning); SI units.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct H20TruckParameters {
    /// kg.
    pub body_mass: f64,
    /// kg·m².
    pub body_pitch_inertia: f64,
    /// kg·m².
    pub body_roll_inertia: f64,
    /// kg.
    pub front_axle_mass: f64,
    /// kg.
    pub rear_axle_mass: f64,
    /// kg·m².
    pub front_axle_roll_inertia: f64,
    /// kg·m².
    pub rear_axle_roll_inertia: f64,
    /// m.
    pub front_axle_to_centre: f64,
    /// m.
    pub centre_to_rear_axle: f64,
    /// m.
    pub front_track: f64,
    /// m.
    pub rear_track: f64,
    /// m.
    pub front_suspension_spacing: f64,
    /// m.
    pub rear_suspension_spacing: f64,
    /// N/m.
    pub front_suspension_stiffness: f64,
    /// N/m.
    pub rear_suspension_stiffness: f64,
    /// N·s/m.
    pub front_suspension_damping: f64,
    /// N·s/m.
    pub rear_suspension_damping: f64,
    /// N/m.
    pub front_tyre_stiffness: f64,
    /// N/m.
    pub rear_tyre_stiffness: f64,
    /// N·s/m.
    pub front_tyre_damping: f64,
    /// N·s/m.
    pub rear_tyre_damping: f64,
}

/// Two-mass oscillator.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Oscillator {
    /// Sprung mass, kg.
    pub sprung_mass: f64,
    /// Unsprung mass, kg.
    pub unsprung_mass: f64,
    /// Suspension stiffness, N/m.
    pub stiffness: f64,
    /// Suspension damping, N·s/m.
    pub damping: f64,
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the wheel reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// The dimensionless groups these values were derived from, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dimensionless: Option<Dimensionless>,
}
