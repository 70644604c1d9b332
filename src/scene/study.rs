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
    /// Monte Carlo over random surface samples.
    MonteCarlo(MonteCarlo),
    /// HSLM-A resonance check (EN 1991-2 6.4.6).
    ResonanceCheck(ResonanceCheck),
}

/// A resonance check. See [`crate::scenario::raw::ResonanceCheckRaw`].
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResonanceCheck {
    /// Trains, in run order.
    pub trains: Vec<crate::scenario::raw::HslmModel>,
    /// Maximum line speed, m/s.
    pub line_speed: f64,
    /// Speeds, m/s.
    pub speeds: ResonanceSpeeds,
    /// The track on the deck.
    pub deck: crate::scenario::raw::DeckRaw,
    /// Highest mode frequency of the deck acceleration, Hz.
    pub max_frequency: f64,
    /// The bridge's first natural frequency f₀, Hz: the trains resonate at
    /// f₀·D/k (D the coach length, k = 1, 2, …). Derived from the bridge
    /// on every load, so resolved.yaml does not write it (the format has
    /// no such key).
    #[serde(skip)]
    pub first_frequency: f64,
    /// The additional damping of EN 1991-2 6.4.6.3.1(3), when asked for;
    /// resolved.yaml writes the file's `additional_damping: true` (Δζ is
    /// derived again from the span on load).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "additional_damping_asked"
    )]
    pub additional_damping: Option<AdditionalDamping>,
}

/// `additional_damping` as the format writes it: whether it was asked for.
fn additional_damping_asked<S: serde::Serializer>(
    damping: &Option<AdditionalDamping>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    serializer.serialize_bool(damping.is_some())
}

/// EN 1991-2 6.4.6.3.1(3): the damping added to every mode for spans
/// below 30 m (vehicle–bridge interaction lowers the peak at resonance).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct AdditionalDamping {
    /// Span length L, m.
    pub span: f64,
    /// Δζ, a damping ratio (dimensionless; 0.003 is 0.3 %).
    pub ratio: f64,
}

/// Speeds of a resonance check, m/s.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct ResonanceSpeeds {
    /// Lowest, m/s.
    pub from: f64,
    /// Highest, m/s.
    pub to: f64,
    /// Step, m/s.
    pub step: f64,
}

/// A Monte Carlo study. See [`crate::scenario::raw::MonteCarloRaw`].
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MonteCarlo {
    /// Samples per case.
    pub samples: usize,
    /// Study seed.
    pub seed: u64,
    /// Speeds, m/s; `None`: the scene's own.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speeds: Option<Grid>,
    /// Surfaces; `None`: the scene's own random surface.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roughness: Option<Vec<SweepRoughness>>,
    /// Sample histories drawn behind the envelopes.
    pub show: usize,
}

impl MonteCarlo {
    /// Cases (surfaces × speeds), each run `samples` times.
    pub fn cases(&self) -> usize {
        self.roughness.as_ref().map_or(1, Vec::len) * self.speeds.as_ref().map_or(1, |g| g.count)
    }

    /// Slowest and fastest swept speed, m/s (`None`: the scene's own).
    pub fn speed_range(&self) -> Option<(f64, f64)> {
        let g = self.speeds.as_ref()?;
        Some(if g.count <= 1 {
            (g.from, g.from)
        } else {
            (g.from.min(g.to), g.from.max(g.to))
        })
    }
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
