//! `study: {type: resonance_check}` — the railway deck-acceleration check of
//! EN 1991-2 6.4.6 with the HSLM-A trains.

use schemars::JsonSchema;
use serde::Deserialize;

use super::SpeedRaw;
use crate::scene::{Deck, HslmModel};

impl Deck {
    /// The peak deck-acceleration limit, m/s² (EN 1990 A2.4.4.2.1(1)).
    pub fn acceleration_limit(self) -> f64 {
        match self {
            Deck::Ballasted => 3.5,
            Deck::DirectFastening => 5.0,
        }
    }
}

/// Speeds of a resonance check.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ResonanceSpeedsRaw {
    /// Lowest speed, m/s or with its unit. Default {{DEFAULT_LOWEST_SPEED}}
    /// m/s (EN 1991-2 6.4.6.2(1)).
    #[serde(default)]
    #[schemars(extend("default" = crate::scenario::resonance::DEFAULT_LOWEST_SPEED))]
    pub from: Option<SpeedRaw>,
    /// Highest speed, m/s or with its unit. Default
    /// {{DEFAULT_TOP_SPEED_FACTOR}} × `line_speed` (EN 1991-2 6.4.6.2(1)).
    #[serde(default)]
    pub to: Option<SpeedRaw>,
    /// Speed step, m/s or with its unit. Default {{DEFAULT_SPEED_STEP_KM_H}} km/h (EN 1991-2 6.4.6.2
    /// asks for smaller steps near resonance: refine there).
    #[serde(default)]
    pub step: Option<SpeedRaw>,
}

/// Resonance check (EN 1991-2 6.4.6 with Annex E): each HSLM-A train of
/// `trains` crosses the bridge alone, as moving axle forces, at every speed
/// from `speeds.from` to `speeds.to` (default {{DEFAULT_TOP_SPEED_FACTOR}} × `line_speed`); each run
/// gives the largest |displacement| and |acceleration| along the deck
/// (acceleration filtered at `max_frequency`, EN 1990 A2.4.4.2.1(4)).
/// Writes resonance.csv, resonance.png and a summary with the governing
/// train and speed against the deck-acceleration limit. The scene's own
/// vehicles are replaced; beams only.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ResonanceCheckRaw {
    /// Trains to run, `A1` … `A10`. Default: all ten.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_empty)]
    pub trains: Option<Vec<HslmModel>>,
    /// The maximum line speed, m/s or with its unit (`300 km/h`).
    pub line_speed: SpeedRaw,
    /// Speeds to run. Defaults: {{DEFAULT_LOWEST_SPEED}} m/s to
    /// {{DEFAULT_TOP_SPEED_FACTOR}} × `line_speed` in
    /// {{DEFAULT_SPEED_STEP_KM_H}} km/h steps. The grid always holds
    /// {{DEFAULT_TOP_SPEED_FACTOR}} × `line_speed` (EN 1991-2
    /// 6.4.6.2(1)) and, per train, each resonance speed f₀·D/k with quarter
    /// steps around it.
    #[serde(default)]
    pub speeds: Option<ResonanceSpeedsRaw>,
    /// The track: `ballasted` (limit 3.5 m/s²) or `direct_fastening`
    /// (5 m/s²). Default `ballasted`.
    #[serde(default)]
    pub deck: Option<Deck>,
    /// Highest mode frequency the deck acceleration includes, Hz. Default:
    /// the greater of {{FLOOR_HZ}} Hz, {{FUNDAMENTAL_FACTOR}} f₁ and f₃ of the bridge (EN 1990
    /// A2.4.4.2.1(4)); the bridge's modes up to it are summed only if
    /// `bridge.modes` keeps them (leave it out and the automatic choice
    /// does).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::frequency::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::frequency::schema")]
    pub max_frequency: Option<f64>,
    /// Add the damping Δζ of EN 1991-2 6.4.6.3.1(3) for spans below 30 m
    /// (vehicle–bridge interaction): Δζ [%] = (0.0187 L − 0.00064 L²) /
    /// (1 − 0.0441 L − 0.0044 L² + 0.000255 L³), L the span in m, to every
    /// mode's damping ratio. A single span only. Default `false`.
    #[serde(default)]
    #[schemars(extend("default" = false))]
    pub additional_damping: Option<bool>,
}
