//! `type: hslm`: an HSLM-A train of EN 1991-2 Annex E as moving forces.

use schemars::JsonSchema;
use serde::Deserialize;

use super::{MovingForceRaw, SpeedRaw};
use crate::vehicle::hslm::{HSLM_A, HslmTrain};

/// The ten HSLM-A universal trains (EN 1991-2 Table E.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
pub enum HslmModel {
    /// N = 18 coaches, D = 18 m, d = 2.0 m, P = 170 kN.
    A1,
    /// N = 17, D = 19 m, d = 3.5 m, P = 200 kN.
    A2,
    /// N = 16, D = 20 m, d = 2.0 m, P = 180 kN.
    A3,
    /// N = 15, D = 21 m, d = 3.0 m, P = 190 kN.
    A4,
    /// N = 14, D = 22 m, d = 2.0 m, P = 170 kN.
    A5,
    /// N = 13, D = 23 m, d = 2.0 m, P = 180 kN.
    A6,
    /// N = 13, D = 24 m, d = 2.0 m, P = 190 kN.
    A7,
    /// N = 12, D = 25 m, d = 2.5 m, P = 190 kN.
    A8,
    /// N = 11, D = 26 m, d = 2.0 m, P = 210 kN.
    A9,
    /// N = 11, D = 27 m, d = 2.0 m, P = 210 kN.
    A10,
}

impl HslmModel {
    /// All ten, A1 first.
    pub const ALL: [HslmModel; 10] = [
        HslmModel::A1,
        HslmModel::A2,
        HslmModel::A3,
        HslmModel::A4,
        HslmModel::A5,
        HslmModel::A6,
        HslmModel::A7,
        HslmModel::A8,
        HslmModel::A9,
        HslmModel::A10,
    ];

    /// Its row of Table E.1.
    pub fn train(self) -> HslmTrain {
        HSLM_A[self as usize]
    }

    /// `HSLM-A3` and so on.
    pub fn label(self) -> String {
        format!("HSLM-A{}", self as usize + 1)
    }
}

/// An HSLM-A train (EN 1991-2 Annex E, Table E.1 and Figure E.2): its axle
/// forces P at the layout of power cars, end coaches and N intermediate
/// coaches, crossing as moving forces (no inertia).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HslmRaw {
    /// Which train: `A1` … `A10`.
    pub model: HslmModel,
    /// Constant speed: m/s, or with its unit (`300 km/h`).
    pub speed: SpeedRaw,
    /// Time at which the front axle reaches the bridge entrance, s. Default 0.
    /// Give this or `start_position`, not both.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the front axle at t = 0, m (≤ 0: on the approach).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the loads on a plate deck, m. Default: the
    /// deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
}

impl HslmRaw {
    /// The same train as explicit moving forces.
    pub fn moving_force(&self) -> MovingForceRaw {
        let train = self.model.train();
        let positions = train.axle_positions();
        MovingForceRaw {
            loads: vec![train.axle_force; positions.len()],
            axle_spacings: None,
            axle_positions: Some(positions),
            speed: self.speed,
            entry_time: self.entry_time,
            start_position: self.start_position,
            lateral_position: self.lateral_position,
            // The HSLM trains of EN 1991-2 run at constant speeds.
            acceleration: None,
        }
    }
}
