//! `type: hslm`: an HSLM-A train of EN 1991-2 Annex E as moving forces.

use schemars::JsonSchema;
use serde::Deserialize;

use super::{MovingForceRaw, SpeedRaw};
use crate::scene::HslmModel;
use crate::scene::hslm::{HSLM_A, HslmTrain};

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
    /// Time at which the front axle reaches the bridge entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
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
