//! The `study` section: many runs derived from the scene.

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::{Grid, RoughnessClass, SweepRoughness};

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
    /// separation.csv, envelopes.csv, one envelope_<record>.png per record
    /// (the first case), and with several speeds separation_probability.png
    /// and expected_gap.png.
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
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
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
    pub roughness: Option<Vec<SweepRoughness>>,
    /// Sample histories drawn in grey behind the envelopes (0 to
    /// {{MAX_SHOWN}}; dimensionless count). Default {{DEFAULT_SHOWN}} (every
    /// sample when there are fewer).
    #[serde(default)]
    #[schemars(range(max = crate::scenario::sweep::MAX_SHOWN))]
    #[schemars(extend("default" = crate::scenario::sweep::DEFAULT_SHOWN))]
    pub show: Option<usize>,
}

/// Grid of a separation map.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationMapRaw {
    /// Velocity ratios α = v / (2 f₁ L) to sweep (dimensionless).
    pub velocity_ratio: Grid,
    /// Vehicle-to-bridge mass ratios (m_s + m_u) / (m L) to sweep (dimensionless).
    pub mass_ratio: Grid,
}

impl Grid {
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
    /// seed from the scene's random surface if it has one, else
    /// {{DEFAULT_SAMPLING_LENGTHS}} × the bridge length, one term per
    /// {{DEFAULT_SHORTEST_WAVELENGTH}} m of it and seed 1). Default: the
    /// scene's own surface only.
    #[serde(default)]
    pub roughness: Option<Vec<SweepRoughness>>,
    /// Random profiles per random surface (≥ 1; dimensionless count): sample
    /// k (from 1) uses seed + k − 1. Smooth and harmonic surfaces run once.
    /// Default 1.
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub samples: Option<usize>,
    /// Span (counted from 1 at the entrance) at whose middle the plots and
    /// the summary show the DAF. Default: the longest span (the first of
    /// equally long ones), e.g. span 2 of the plate paper's 3-span deck.
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub span: Option<usize>,
    /// Girder line (counted from 1 in `bridge.girder_lines`) of the
    /// roughness plot, the DAF map and the summary. Default 1 (a beam has
    /// only line 1).
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub girder: Option<usize>,
}

impl SweepRoughness {
    /// The power-law roughness class of an entry (`None` for `smooth` and
    /// the FRA track classes).
    pub fn class(self) -> Option<RoughnessClass> {
        match self {
            SweepRoughness::Smooth
            | SweepRoughness::Fra1
            | SweepRoughness::Fra2
            | SweepRoughness::Fra3
            | SweepRoughness::Fra4
            | SweepRoughness::Fra5
            | SweepRoughness::Fra6 => None,
            SweepRoughness::VeryGood => Some(RoughnessClass::VeryGood),
            SweepRoughness::Good => Some(RoughnessClass::Good),
            SweepRoughness::Average => Some(RoughnessClass::Average),
            SweepRoughness::Poor => Some(RoughnessClass::Poor),
            SweepRoughness::VeryPoor => Some(RoughnessClass::VeryPoor),
        }
    }

    /// The FRA track class (1–6) of an FRA entry.
    pub fn fra_class(self) -> Option<u8> {
        match self {
            SweepRoughness::Fra1 => Some(1),
            SweepRoughness::Fra2 => Some(2),
            SweepRoughness::Fra3 => Some(3),
            SweepRoughness::Fra4 => Some(4),
            SweepRoughness::Fra5 => Some(5),
            SweepRoughness::Fra6 => Some(6),
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
            None => self.class().map_or("smooth", RoughnessClass::name),
        }
    }
}
