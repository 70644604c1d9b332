//! `envelopes:` — maxima and minima of bridge quantities at every point along
//! the deck, computed during the run (no histories kept).

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::Quantity;

/// Envelopes along the whole deck (beams): at every mesh node, or at
/// `points` evenly spaced points, plus every support (an interior one twice:
/// its left-hand and right-hand limits) and, with `bridge_moment`, each
/// vehicle's absolute-maximum-moment section of every span, the largest and
/// smallest value of each quantity over the run, with the time and the lead
/// vehicle's position when each occurred, beside the static crossing's
/// (exact where a wheel passes the point) and the point's DAF; written to
/// `envelopes.csv` and `envelopes.png`, the peaks to `summary.json`
/// (`envelope_peaks`).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EnvelopesRaw {
    /// The bridge quantities enveloped: any of `bridge_displacement`,
    /// `bridge_acceleration`, `bridge_moment`, `bridge_shear`. Default: all four.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_empty)]
    pub quantities: Option<Vec<Quantity>>,
    /// Number of evenly spaced points from the entrance to the exit, both
    /// included (at least 2); the supports and the peak sections are added.
    /// Default: every node of the beam's mesh.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_two)]
    pub points: Option<usize>,
    /// Highest mode frequency the acceleration envelope includes, Hz.
    /// Default as for a `bridge_acceleration` record: the greater of
    /// {{FLOOR_HZ}} Hz, {{FUNDAMENTAL_FACTOR}} f₁ and f₃ of the bridge (EN 1990
    /// A2.4.4.2.1(4)).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::frequency::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::frequency::schema")]
    pub max_frequency: Option<f64>,
}
