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

impl Direction {
    /// The name used in the scenario file.
    pub fn name(self) -> &'static str {
        match self {
            Direction::Vertical => "vertical",
            Direction::Lateral => "lateral",
            Direction::Longitudinal => "longitudinal",
        }
    }
}

/// Standard acceleration of gravity, m/s² (ISO 80000-3; CGPM 1901).
pub const STANDARD_GRAVITY: f64 = 9.80665;

impl AccelerationUnit {
    /// Metres per second squared per unit.
    pub fn in_si(self) -> f64 {
        match self {
            AccelerationUnit::MetresPerSecondSquared => 1.0,
            AccelerationUnit::CentimetresPerSecondSquared => 0.01,
            AccelerationUnit::StandardGravity => STANDARD_GRAVITY,
        }
    }

    /// The unit as written in files and messages.
    pub fn name(self) -> &'static str {
        match self {
            AccelerationUnit::MetresPerSecondSquared => "m/s^2",
            AccelerationUnit::CentimetresPerSecondSquared => "cm/s^2",
            AccelerationUnit::StandardGravity => "g",
        }
    }

    /// Recognises a unit written in a file header: `g`, `G`, `m/s^2`,
    /// `m/s2`, `m/s/s`, `cm/s^2`, `gal`, … (case and spaces ignored).
    pub fn parse(text: &str) -> Option<Self> {
        let t: String = text
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect::<String>()
            .to_ascii_lowercase()
            .replace("sec", "s")
            .replace('²', "^2");
        match t.as_str() {
            "g" | "g's" | "gs" => Some(AccelerationUnit::StandardGravity),
            "m/s^2" | "m/s2" | "m/s/s" | "ms^-2" | "ms-2" => {
                Some(AccelerationUnit::MetresPerSecondSquared)
            }
            "cm/s^2" | "cm/s2" | "cm/s/s" | "gal" | "cms^-2" | "cms-2" => {
                Some(AccelerationUnit::CentimetresPerSecondSquared)
            }
            _ => None,
        }
    }
}

impl GroundRecord {
    /// A record from samples (`time` strictly increasing, s, on the file's
    /// clock; `acceleration` in m/s² before `scale`), shifted so that its
    /// time 0 falls at `start_time` (s) of the run. The caller has checked
    /// the samples (finite, increasing, at least two).
    pub fn new(time: &[f64], acceleration: &[f64], scale: f64, start_time: f64) -> Self {
        let time: Vec<f64> = time.iter().map(|t| t + start_time).collect();
        let acceleration: Vec<f64> = acceleration.iter().map(|a| a * scale).collect();
        let n = time.len();
        let (mut velocity, mut displacement) = (vec![0.0; n], vec![0.0; n]);
        for k in 1..n {
            let h = time[k] - time[k - 1];
            let (a0, a1) = (acceleration[k - 1], acceleration[k]);
            // Exact integrals of the linear acceleration over the interval.
            velocity[k] = velocity[k - 1] + 0.5 * h * (a0 + a1);
            displacement[k] =
                displacement[k - 1] + velocity[k - 1] * h + h * h * (a0 / 3.0 + a1 / 6.0);
        }
        Self {
            time,
            acceleration,
            velocity,
            displacement,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_recognised() {
        assert_eq!(
            AccelerationUnit::parse("G"),
            Some(AccelerationUnit::StandardGravity)
        );
        assert_eq!(
            AccelerationUnit::parse("cm/sec/sec"),
            Some(AccelerationUnit::CentimetresPerSecondSquared)
        );
        assert_eq!(
            AccelerationUnit::parse(" m/s² "),
            Some(AccelerationUnit::MetresPerSecondSquared)
        );
        assert_eq!(AccelerationUnit::parse("in/s^2"), None);
    }
}
