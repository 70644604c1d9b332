//! A resolved study: the `study` section with every default filled in.

use serde::Serialize;

use super::Grid;
pub use crate::scenario::raw::SweepRoughnessRaw as SweepRoughness;

/// A study over variants of the scene.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Study {
    /// Separation map over velocity ratio × mass ratio.
    SeparationMap {
        /// Velocity ratios swept.
        velocity_ratio: Grid,
        /// Mass ratios swept.
        mass_ratio: Grid,
    },
    /// DAF against vehicle speed, on one or more surfaces.
    SpeedSweep(SpeedSweep),
}

/// A speed sweep. See [`crate::scenario::raw::SpeedSweepRaw`].
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SpeedSweep {
    /// Speeds, m/s.
    pub speeds: Grid,
    /// Surfaces swept; `None`: the scene's own surface only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roughness: Option<Vec<SweepRoughness>>,
    /// Random profiles per random surface.
    pub samples: usize,
    /// Span of the plots, from 1.
    pub span: usize,
    /// Girder line of the roughness plot, from 1.
    pub girder: usize,
}

impl SpeedSweep {
    /// The speeds, m/s, in sweep order.
    pub fn speed_values(&self) -> Vec<f64> {
        self.speeds.values()
    }

    /// Slowest and fastest speed, m/s.
    ///
    /// From the grid's ends, without listing its values: the speeds are
    /// evenly spaced, so the ends bound them (and a count from the input is
    /// never allocated here).
    pub fn speed_range(&self) -> (f64, f64) {
        let (from, to) = (self.speeds.from, self.speeds.to);
        if self.speeds.count <= 1 {
            (from, from)
        } else {
            (from.min(to), from.max(to))
        }
    }
}
