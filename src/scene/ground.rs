//! The resolved ground motion.

use std::sync::Arc;

use serde::Serialize;

use crate::ground::{AccelerationUnit, Direction, GroundRecord};

/// One ground-motion component, its record read and checked.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct GroundMotion {
    /// The record's file (absolute path).
    pub file: String,
    /// Direction of the motion.
    pub direction: Direction,
    /// Factor on the record's accelerations.
    pub scale: f64,
    /// Run time of the record's time 0, s.
    pub start_time: f64,
    /// Units of the file's accelerations.
    pub units: AccelerationUnit,
    /// The record on the run's clock, m/s², scaled.
    #[serde(skip)]
    pub record: Arc<GroundRecord>,
}

/// Whether a record is in the relative or the absolute frame.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, serde::Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Frame {
    /// Relative to the moving ground (what the structure feels: deflections
    /// and the accelerations of its deformation).
    #[default]
    Relative,
    /// Absolute (inertial): relative plus the ground's own motion.
    Absolute,
}

impl Frame {
    /// The default, left out of `resolved.yaml`.
    pub fn is_relative(&self) -> bool {
        *self == Frame::Relative
    }
}
