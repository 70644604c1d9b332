//! The resolved surface profile.

use std::sync::Arc;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::Spectrum;

// Grid and series sizes of a sampled profile: counts the format budgets
// before anything is allocated, and the profile builders use.

/// Grid nodes per shortest wavelength of a sampled random profile: quintic
/// Hermite interpolation error 1.3e-6 of the shortest wave's amplitude
/// (the quintic Hermite grid of `surface::interp`).
pub const NODES_PER_WAVELENGTH: f64 = 10.0;

/// Grid nodes per shortest wavelength of the plate paper's power-law series
/// (one period, so the grid costs 32·N nodes whatever the run's length):
/// finer than [`NODES_PER_WAVELENGTH`] because the plate paper's results are
/// reproduced to six digits, curvature included (the wheel's v²r″ term):
/// the quintic Hermite error of r is (2π/32)⁶/46080 = 1.3e-9 of the shortest
/// wave's amplitude, of r″ about (2π/32)⁴/384 = 3.9e-6 of its curvature
/// (`random_grid_follows_the_series` measures both).
pub const POWER_LAW_NODES_PER_WAVELENGTH: usize = 32;

/// Grid nodes of the power-law series' period grid for `terms` terms:
/// [`POWER_LAW_NODES_PER_WAVELENGTH`] per shortest wavelength over one
/// period, plus two (one interval past the period).
pub fn power_law_grid_nodes(terms: usize) -> usize {
    POWER_LAW_NODES_PER_WAVELENGTH * terms.max(1) + 2
}

/// Nodes of the grid a sampled profile needs to reach `reach` (m from the
/// entrance) with the given shortest wavelength (m); f64 so a hostile size
/// cannot wrap (budgeted while resolving).
pub fn grid_nodes(reach: f64, shortest_wavelength: f64) -> f64 {
    (reach.max(0.0) / (shortest_wavelength / NODES_PER_WAVELENGTH)).ceil() + 2.0
}

/// Default terms per decade of wavelength of a band's series (bins 2.3 %
/// wide in Ω).
pub const TERMS_PER_DECADE: f64 = 100.0;
/// Fewest terms of a band's default series.
pub const MIN_BAND_TERMS: usize = 10;

/// Default number of terms over a band: [`TERMS_PER_DECADE`] per decade of
/// wavelength, at least [`MIN_BAND_TERMS`].
pub fn default_terms(shortest: f64, longest: f64) -> usize {
    ((TERMS_PER_DECADE * (longest / shortest).log10()).ceil() as usize).max(MIN_BAND_TERMS)
}

/// How a random track or road profile is sampled (the spectral
/// representation of [`crate::surface::synth`]).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Sampling {
    /// Shortest wavelength of the band, m.
    pub shortest_wavelength: f64,
    /// Longest wavelength of the band, m.
    pub longest_wavelength: f64,
    /// Number of terms N.
    pub terms: usize,
    /// Seed of the ChaCha8 streams.
    pub seed: u64,
    /// Identical or independent rails.
    pub rails: Rails,
    /// Fade-in length on the approach, m (0: start at the entrance with
    /// r(0) = 0).
    pub run_in: f64,
    /// Whether the rails' alignment (lateral irregularity) is sampled too,
    /// from the spectrum's alignment form. Written only when true: ISO 8608
    /// roads have no alignment key, and resolved.yaml must load again.
    #[serde(skip_serializing_if = "is_false")]
    pub alignment: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// A measured profile as read from its CSV file.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredProfile {
    /// x of the points, m from the entrance, strictly increasing.
    pub x: Vec<f64>,
    /// Elevation under the left rail (or every wheel), m.
    pub left: Vec<f64>,
    /// Elevation under the right rail, m, if the file gives one.
    pub right: Option<Vec<f64>>,
    /// Lateral position of the left and right rails (m, + to the left of
    /// travel), if the file gives them (five columns).
    pub lateral: Option<(Vec<f64>, Vec<f64>)>,
}

/// Surface profile. Serialises to the input format (`type` and its fields),
/// so the resolved scenario can be run again.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Surface {
    /// Smooth.
    Smooth,
    /// r(x) = amplitude · sin(2πx/wavelength + phase), x ≥ 0.
    Harmonic {
        /// m
        amplitude: f64,
        /// m
        wavelength: f64,
        /// rad
        phase: f64,
        /// Vertical (the rails' elevation) or lateral (the track's
        /// alignment); written only when lateral.
        #[serde(skip_serializing_if = "TrackDirection::is_vertical")]
        direction: TrackDirection,
    },
    /// Random profile from the PSD A_r (Ω/Ω₀)⁻² (the plate paper's series).
    Random {
        /// The class A_r was taken from.
        #[serde(skip_serializing_if = "Option::is_none")]
        class: Option<RoughnessClass>,
        /// A_r, m³/cycle.
        coefficient: f64,
        /// L_c, m.
        sampling_length: f64,
        /// N.
        terms: usize,
        /// Seed.
        seed: u64,
    },
    /// FRA vertical track profile.
    Fra {
        /// Track class 1–6.
        class: u8,
        /// Band, terms, seed, rails.
        #[serde(flatten)]
        sampling: Sampling,
    },
    /// German high-speed vertical track profile.
    German {
        /// Interference level.
        interference: super::Interference,
        /// Band, terms, seed, rails.
        #[serde(flatten)]
        sampling: Sampling,
    },
    /// ISO 8608 road profile.
    Iso8608 {
        /// Road class A–H.
        class: super::IsoClass,
        /// Band, terms, seed, rails.
        #[serde(flatten)]
        sampling: Sampling,
    },
    /// A measured profile.
    Measured {
        /// The CSV file as resolved (relative to the scenario's folder, made
        /// absolute so the written scenario runs from anywhere).
        file: String,
        /// The points read from it.
        #[serde(skip)]
        profile: Arc<MeasuredProfile>,
    },
    /// A linear ramp ([`crate::surface::shapes::Shape::Ramp`]), m.
    Ramp {
        /// m
        start: f64,
        /// m
        length: f64,
        /// m
        height: f64,
        /// Vertical (the rails' elevation) or lateral (the track's
        /// alignment); written only when lateral.
        #[serde(skip_serializing_if = "TrackDirection::is_vertical")]
        direction: TrackDirection,
    },
    /// A step ([`crate::surface::shapes::Shape::Step`]), m.
    Step {
        /// m
        position: f64,
        /// m
        height: f64,
        /// Vertical (the rails' elevation) or lateral (the track's
        /// alignment); written only when lateral.
        #[serde(skip_serializing_if = "TrackDirection::is_vertical")]
        direction: TrackDirection,
    },
    /// A cosine bump, or a dip with negative height
    /// ([`crate::surface::shapes::Shape::Bump`]), m.
    Bump {
        /// m
        start: f64,
        /// m
        length: f64,
        /// m (negative: a dip)
        height: f64,
        /// Vertical (the rails' elevation) or lateral (the track's
        /// alignment); written only when lateral.
        #[serde(skip_serializing_if = "TrackDirection::is_vertical")]
        direction: TrackDirection,
    },
    /// Straight lines between `[x, r]` points, m.
    PiecewiseLinear {
        /// `[x, r]`, m.
        points: Vec<[f64; 2]>,
        /// Vertical (the rails' elevation) or lateral (the track's
        /// alignment); written only when lateral.
        #[serde(skip_serializing_if = "TrackDirection::is_vertical")]
        direction: TrackDirection,
    },
}

impl Surface {
    /// Whether the profile is a random sample (its seed picks it).
    pub fn is_random(&self) -> bool {
        matches!(
            self,
            Surface::Random { .. }
                | Surface::Fra { .. }
                | Surface::German { .. }
                | Surface::Iso8608 { .. }
        )
    }

    /// The same surface with its seed replaced (random kinds), or itself
    /// (deterministic ones): one sample of a Monte Carlo study.
    pub fn reseeded(&self, seed: u64) -> Surface {
        let mut out = self.clone();
        match &mut out {
            Surface::Random { seed: s, .. } => *s = seed,
            Surface::Fra { sampling, .. }
            | Surface::German { sampling, .. }
            | Surface::Iso8608 { sampling, .. } => sampling.seed = seed,
            _ => {}
        }
        out
    }

    /// The seed of a random profile.
    pub fn seed(&self) -> Option<u64> {
        match self {
            Surface::Random { seed, .. } => Some(*seed),
            _ => self.spectrum().map(|(_, s)| s.seed),
        }
    }

    /// A short name for tables and plots: `smooth`, `harmonic`, the
    /// power-law class or `random`, `fra5` (as a study's `roughness` list
    /// names it), `german-low`, `iso-C`,
    /// `measured`, `ramp`, `step`, `bump`, `dip`, `piecewise-linear`.
    pub fn label(&self) -> String {
        match self {
            Surface::Smooth => "smooth".into(),
            Surface::Harmonic { .. } => "harmonic".into(),
            Surface::Random { class: Some(c), .. } => c.name().into(),
            Surface::Random { class: None, .. } => "random".into(),
            Surface::Fra { .. } | Surface::German { .. } | Surface::Iso8608 { .. } => {
                self.spectrum().map(|(s, _)| s.label()).unwrap_or_default()
            }
            Surface::Measured { .. } => "measured".into(),
            Surface::Ramp { .. } => "ramp".into(),
            Surface::Step { .. } => "step".into(),
            Surface::Bump { height, .. } if *height < 0.0 => "dip".into(),
            Surface::Bump { .. } => "bump".into(),
            Surface::PiecewiseLinear { .. } => "piecewise-linear".into(),
        }
    }

    /// Whether the surface displaces the rails sideways: a lateral shape
    /// or harmonic, a measured profile with lateral columns, or a
    /// spectrum sampling the alignment.
    pub fn has_lateral_geometry(&self) -> bool {
        match self {
            Surface::Harmonic { direction, .. }
            | Surface::Ramp { direction, .. }
            | Surface::Step { direction, .. }
            | Surface::Bump { direction, .. }
            | Surface::PiecewiseLinear { direction, .. } => !direction.is_vertical(),
            Surface::Measured { profile, .. } => profile.lateral.is_some(),
            _ => self.spectrum().is_some_and(|(_, s)| s.alignment),
        }
    }

    /// The spectrum and sampling of a spectral random profile.
    pub fn spectrum(&self) -> Option<(Spectrum, Sampling)> {
        match *self {
            Surface::Fra { class, sampling } => Some((Spectrum::Fra { class }, sampling)),
            Surface::German {
                interference,
                sampling,
            } => Some((Spectrum::German { interference }, sampling)),
            Surface::Iso8608 { class, sampling } => Some((Spectrum::Iso8608 { class }, sampling)),
            _ => None,
        }
    }
}

/// Road roughness classes (A_r ranges in m³/cycle): very good 2e-6–8e-6,
/// good 8e-6–32e-6, average 32e-6–128e-6, poor 128e-6–512e-6, very poor
/// 512e-6–2048e-6.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RoughnessClass {
    /// A_r = 4e-6.
    VeryGood,
    /// A_r = 16e-6.
    Good,
    /// A_r = 64e-6.
    Average,
    /// A_r = 256e-6.
    Poor,
    /// A_r = 1024e-6.
    VeryPoor,
}

/// The direction a deterministic profile displaces the rails in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TrackDirection {
    /// The rails' elevation (m, positive upward): every vehicle's wheels
    /// follow it.
    #[default]
    Vertical,
    /// The track's alignment (m, + to the left of travel): both rails
    /// displaced sideways; a `train_3d`'s wheelsets follow it, no other
    /// vehicle has a lateral DOF at the rail.
    Lateral,
}

/// Whether the two rails (wheel tracks) carry the same random profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Rails {
    /// The same sample under both.
    Identical,
    /// Independent samples (ChaCha8 streams 0 and 1 of the seed).
    Independent,
}
