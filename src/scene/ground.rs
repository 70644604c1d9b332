//! The resolved ground motion.

use std::sync::Arc;

use serde::Serialize;

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

/// Direction of a ground-motion component.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// Vertical, positive upward.
    Vertical,
    /// Lateral (across the track), positive to the left of travel.
    Lateral,
    /// Longitudinal (along the track), positive in the direction of travel.
    Longitudinal,
}

/// Units a record's accelerations are given in.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize, schemars::JsonSchema,
)]
pub enum AccelerationUnit {
    /// m/s².
    #[serde(rename = "m/s^2")]
    MetresPerSecondSquared,
    /// cm/s² (gal).
    #[serde(rename = "cm/s^2")]
    CentimetresPerSecondSquared,
    /// Standard gravity g = 9.80665 m/s² (ISO 80000-3), the unit of PEER
    /// records, whatever the scene's own `gravity`.
    #[serde(rename = "g")]
    StandardGravity,
}

/// A ground acceleration record on the run's clock, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundRecord {
    /// Sample times on the run's clock, s, strictly increasing.
    pub(crate) time: Vec<f64>,
    /// Ground acceleration at each sample, m/s² (scaled).
    pub(crate) acceleration: Vec<f64>,
    /// Ground velocity at each sample, m/s (from rest at the first one).
    pub(crate) velocity: Vec<f64>,
    /// Ground displacement at each sample, m (from 0 at the first one).
    pub(crate) displacement: Vec<f64>,
}
