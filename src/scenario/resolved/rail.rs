//! Resolved rail vehicles: the 10-DOF rail car and trains of them.

use serde::Serialize;

/// Four-axle rail car (10 DOFs).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RailCar {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front wheelset reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the track's centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// Every parameter, preset values filled in.
    pub parameters: RailCarParameters,
}

/// Rail car parameters (see the raw format for each meaning); SI units.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct RailCarParameters {
    /// Car body mass M_c, kg.
    pub body_mass: f64,
    /// Car body pitch moment of inertia J_c, kg·m².
    pub body_pitch_inertia: f64,
    /// Mass of one bogie frame M_b, kg.
    pub bogie_mass: f64,
    /// Pitch moment of inertia of one bogie J_b, kg·m².
    pub bogie_pitch_inertia: f64,
    /// Mass of one wheelset M_w, kg.
    pub wheelset_mass: f64,
    /// Primary suspension stiffness per wheelset k_p, N/m.
    pub primary_stiffness: f64,
    /// Primary suspension damping per wheelset c_p, N·s/m.
    pub primary_damping: f64,
    /// Secondary suspension stiffness per bogie k_s, N/m.
    pub secondary_stiffness: f64,
    /// Secondary suspension damping per bogie c_s, N·s/m.
    pub secondary_damping: f64,
    /// Half the distance between the bogie centres a, m.
    pub half_bogie_spacing: f64,
    /// Half the distance between a bogie's two wheelsets b, m.
    pub half_wheelbase: f64,
}

/// A train of rail cars running together.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Train {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the first car's front wheelset reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the track's centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// The cars, front first (the expansion of `count`/`car_spacing` or of
    /// the `cars` list). Car k's wheelsets are the train's wheels
    /// 4(k−1)+1 … 4k; its DOFs are named `car{k}_body_bounce`, ….
    pub cars: Vec<TrainCar>,
}

/// One car of a train.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct TrainCar {
    /// Distance of the car's front wheelset behind the train's first
    /// wheelset, m.
    pub offset: f64,
    /// The car's parameters.
    pub parameters: RailCarParameters,
}

impl Train {
    /// Distance from the first wheelset back to the last one, m.
    pub fn length(&self) -> f64 {
        self.cars.last().map_or(0.0, |c| {
            c.offset + crate::vehicle::rail_car::wheelset_span(&c.parameters)
        })
    }
}
