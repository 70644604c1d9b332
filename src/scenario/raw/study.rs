//! The `study` section: many runs derived from the scene.

use schemars::JsonSchema;
use serde::Deserialize;

use super::RoughnessClassRaw;

/// A study: many runs derived from the scene.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
#[schemars(tag = "type")]
pub enum StudyRaw {
    /// Separation map (the LCP separation paper's Fig. 6): the scene's single
    /// oscillator, given with `dimensionless`, is run over a grid of velocity
    /// ratio × vehicle-to-bridge mass ratio with its other ratios fixed; each
    /// point is marked separated if any wheel loses contact. Needs unilateral
    /// contact. Writes study.csv and separation_map.png.
    SeparationMap(SeparationMapRaw),
    /// Speed sweep (the plate paper's Figs. 12, 13 and 17): every vehicle
    /// takes each speed of `speeds` in turn (keeping its entry time), on each
    /// surface of `roughness`; each run gives the DAF at the middle of every
    /// span on every girder line, the DAF of every `bridge_displacement`
    /// record and the largest force of every `contact_force` record. Writes
    /// study.csv, daf_speed.png, daf_speed_roughness.png and daf_map.png. The
    /// automatic mode cut-off and time step cover the whole sweep (its top
    /// speed and its slowest, longest run).
    SpeedSweep(SpeedSweepRaw),
    /// Monte Carlo study (the LCP separation paper, Section 5.2, Figs. 7–9):
    /// `samples` random profiles of the scene's random surface (or of each
    /// class of `roughness`), sample k's seed mixed from `seed` and k, at
    /// the scene's speed or at each speed of `speeds`. Per case (surface ×
    /// speed): the mean, standard deviation and mean ± 3σ of every recorded
    /// history, and per wheel the probability of separation and the expected
    /// largest gap with their confidence intervals. Writes study.csv,
    /// envelopes.csv, envelopes.png, and with several speeds
    /// separation_probability.png and expected_gap.png.
    MonteCarlo(MonteCarloRaw),
    /// Railway resonance check with the HSLM-A trains of EN 1991-2 Annex E:
    /// see its fields.
    ResonanceCheck(super::ResonanceCheckRaw),
}

/// A Monte Carlo study over random surface profiles.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MonteCarloRaw {
    /// Random profiles per case (≥ 1; dimensionless count).
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scenario::schema::at_least_one)]
    pub samples: usize,
    /// Study seed: sample k (from 1) uses the k-th output of SplitMix64
    /// started from this seed (the same k-th seed on every case, every
    /// machine and every thread count). Default 1.
    #[serde(default)]
    #[schemars(extend("default" = 1))]
    pub seed: Option<u64>,
    /// Speeds (each > 0), m/s or with their unit; every vehicle takes each
    /// in turn (keeping its entry time). Default: the scene's own speeds.
    #[serde(default)]
    pub speeds: Option<super::SpeedGridRaw>,
    /// Roughness classes (`very_good` … `very_poor`), each replacing the
    /// scene's surface as in a speed sweep. Default: the scene's own random
    /// surface. `smooth` is refused: it is not random.
    #[serde(default)]
    pub roughness: Option<Vec<SweepRoughnessRaw>>,
    /// Sample histories drawn in grey behind the envelopes (0 to 20;
    /// dimensionless count). Default 5.
    #[serde(default)]
    #[schemars(range(max = 20))]
    #[schemars(extend("default" = 5))]
    pub show: Option<usize>,
}

/// Grid of a separation map.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationMapRaw {
    /// Velocity ratios α = v / (2 f₁ L) to sweep (dimensionless).
    pub velocity_ratio: GridRaw,
    /// Vehicle-to-bridge mass ratios (m_s + m_u) / (m L) to sweep (dimensionless).
    pub mass_ratio: GridRaw,
}

/// Evenly spaced values from `from` to `to` inclusive.
#[derive(Debug, Clone, Deserialize, JsonSchema, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GridRaw {
    /// First value.
    #[schemars(transform = crate::scenario::schema::positive)]
    pub from: f64,
    /// Last value.
    #[schemars(transform = crate::scenario::schema::positive)]
    pub to: f64,
    /// Number of values (≥ 1; 1 gives `from` only).
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scenario::schema::grid_count)]
    pub count: usize,
}

impl GridRaw {
    /// The values.
    pub fn values(&self) -> Vec<f64> {
        if self.count <= 1 {
            return vec![self.from];
        }
        (0..self.count)
            .map(|i| self.from + (self.to - self.from) * i as f64 / (self.count - 1) as f64)
            .collect()
    }
}

/// A speed sweep over one or more road surfaces.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SpeedSweepRaw {
    /// Speeds to sweep (each > 0), in m/s or with their unit; every vehicle
    /// takes each speed in turn. 10–150 km/h is `{from: 10 km/h, to: 150
    /// km/h, count: 15}` or `{from: 2.7778, to: 41.667, count: 15}`.
    pub speeds: super::SpeedGridRaw,
    /// Surfaces to sweep: `smooth`, or a roughness class (`very_good`,
    /// `good`, `average`, `poor`, `very_poor`) that replaces the scene's
    /// surface by a random profile of that class (sampling length, terms and
    /// seed from the scene's random surface if it has one, else twice the
    /// bridge length, one term per 0.5 m of it and seed 1). Default: the
    /// scene's own surface only.
    #[serde(default)]
    pub roughness: Option<Vec<SweepRoughnessRaw>>,
    /// Random profiles per random surface (≥ 1; dimensionless count): sample
    /// k (from 1) uses seed + k − 1. Smooth and harmonic surfaces run once.
    /// Default 1.
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scenario::schema::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub samples: Option<usize>,
    /// Span (counted from 1 at the entrance) at whose middle the plots and
    /// the summary show the DAF. Default: the longest span (the first of
    /// equally long ones), e.g. span 2 of the plate paper's 3-span deck.
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scenario::schema::at_least_one)]
    pub span: Option<usize>,
    /// Girder line (counted from 1 in `bridge.girder_lines`) of the
    /// roughness plot, the DAF map and the summary. Default 1 (a beam has
    /// only line 1).
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scenario::schema::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub girder: Option<usize>,
}

/// One surface of a speed sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SweepRoughnessRaw {
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

impl SweepRoughnessRaw {
    /// The power-law roughness class of an entry (`None` for `smooth` and
    /// the FRA track classes).
    pub fn class(self) -> Option<RoughnessClassRaw> {
        match self {
            SweepRoughnessRaw::Smooth
            | SweepRoughnessRaw::Fra1
            | SweepRoughnessRaw::Fra2
            | SweepRoughnessRaw::Fra3
            | SweepRoughnessRaw::Fra4
            | SweepRoughnessRaw::Fra5
            | SweepRoughnessRaw::Fra6 => None,
            SweepRoughnessRaw::VeryGood => Some(RoughnessClassRaw::VeryGood),
            SweepRoughnessRaw::Good => Some(RoughnessClassRaw::Good),
            SweepRoughnessRaw::Average => Some(RoughnessClassRaw::Average),
            SweepRoughnessRaw::Poor => Some(RoughnessClassRaw::Poor),
            SweepRoughnessRaw::VeryPoor => Some(RoughnessClassRaw::VeryPoor),
        }
    }

    /// The FRA track class (1–6) of an FRA entry.
    pub fn fra_class(self) -> Option<u8> {
        match self {
            SweepRoughnessRaw::Fra1 => Some(1),
            SweepRoughnessRaw::Fra2 => Some(2),
            SweepRoughnessRaw::Fra3 => Some(3),
            SweepRoughnessRaw::Fra4 => Some(4),
            SweepRoughnessRaw::Fra5 => Some(5),
            SweepRoughnessRaw::Fra6 => Some(6),
            _ => None,
        }
    }

    /// Whether the entry is a random profile (a power-law or FRA class).
    pub fn is_random(self) -> bool {
        self.class().is_some() || self.fra_class().is_some()
    }

    /// The entry's name as written in the format.
    pub fn name(self) -> &'static str {
        match self.fra_class() {
            Some(c) => ["fra1", "fra2", "fra3", "fra4", "fra5", "fra6"][usize::from(c) - 1],
            None => self.class().map_or("smooth", RoughnessClassRaw::name),
        }
    }
}
