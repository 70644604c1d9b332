//! The `output` section: how densely and in which format the history is
//! written.

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::HistoryFormat;

/// What the time history files hold. Only what is WRITTEN is thinned: the
/// extremes, DAFs and separation statistics in summary.json are computed
/// from every step.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OutputRaw {
    /// Write every N-th step of the history (t = 0, NΔt, 2NΔt, …). Give
    /// this or `interval`. Default 1: every step.
    #[serde(default)]
    #[schemars(range(min = 1))]
    #[schemars(extend("default" = 1))]
    pub every: Option<u64>,
    /// Time between written samples, s: rounded to the nearest whole number
    /// of time steps (at least one), which the resolved scenario shows as
    /// `every`. Give this or `every`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub interval: Option<f64>,
    /// Format of the time history: `csv` (history.csv), `npy` (history.npy,
    /// one float64 array with a row per written step and a column per
    /// quantity, read by numpy.load, pandas and MATLAB's readNPY, with its
    /// column names and units in history_columns.txt) or `both`.
    /// Default csv.
    #[serde(default)]
    #[schemars(extend("default" = "csv"))]
    pub format: Option<HistoryFormat>,
}

impl HistoryFormat {
    /// Whether history.csv is written.
    pub fn csv(self) -> bool {
        matches!(self, Self::Csv | Self::Both)
    }

    /// Whether history.npy is written.
    pub fn npy(self) -> bool {
        matches!(self, Self::Npy | Self::Both)
    }
}
