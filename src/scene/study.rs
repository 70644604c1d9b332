//! A resolved study: the `study` section with every default filled in.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

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
    pub trains: Vec<HslmModel>,
    /// Maximum line speed, m/s.
    pub line_speed: f64,
    /// Speeds, m/s.
    pub speeds: ResonanceSpeeds,
    /// The track on the deck.
    pub deck: Deck,
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

/// Evenly spaced values from `from` to `to` inclusive.
#[derive(Debug, Clone, Deserialize, JsonSchema, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Grid {
    /// First value.
    #[schemars(transform = super::schema_rules::positive)]
    pub from: f64,
    /// Last value.
    #[schemars(transform = super::schema_rules::positive)]
    pub to: f64,
    /// Number of values (≥ 1; 1 gives `from` only).
    #[schemars(range(min = 1))]
    #[schemars(transform = super::schema_rules::grid_count)]
    pub count: usize,
}

/// One surface of a speed sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SweepRoughness {
    /// Perfectly smooth surface.
    Smooth,
    /// Random profile with A_r = 4e-6 m³/cycle.
    VeryGood,
    /// Random profile with A_r = 16e-6 m³/cycle.
    Good,
    /// Random profile with A_r = 64e-6 m³/cycle.
    Average,
    /// Random profile with A_r = 256e-6 m³/cycle.
    Poor,
    /// Random profile with A_r = 1024e-6 m³/cycle.
    VeryPoor,
    /// FRA track class 1 vertical profile (the scene's rail sampling, or
    /// the 1–80 m band), as in the LCP paper's Figs. 8–9.
    Fra1,
    /// FRA track class 2.
    Fra2,
    /// FRA track class 3.
    Fra3,
    /// FRA track class 4.
    Fra4,
    /// FRA track class 5.
    Fra5,
    /// FRA track class 6.
    Fra6,
}

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

/// The track on the deck, which sets the deck-acceleration limit of
/// EN 1990 A2.4.4.2.1(1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Deck {
    /// Ballasted track: 3.5 m/s².
    Ballasted,
    /// Direct-fastened track: 5 m/s².
    DirectFastening,
}
