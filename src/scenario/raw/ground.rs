//! The `ground_motion` section: earthquake acceleration records.

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::{AccelerationUnit, Direction};

/// One component of earthquake ground motion: an acceleration record
/// applied as a uniform support excitation (every support moves together),
/// in relative coordinates: the bridge feels −M δ üg, the vehicles −m üg
/// (a vertical record acts as gravity g + üg on them).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GroundMotionRaw {
    /// The record: a PEER NGA `.AT2` file (units from its header, usually
    /// g) or a CSV table `time [s], acceleration [unit]` (evenly spaced or
    /// not); the path is relative to this scenario file.
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub file: String,
    /// Direction of the motion: `vertical` (positive upward), `lateral` or
    /// `longitudinal`. Default vertical.
    #[serde(default)]
    #[schemars(extend("default" = "vertical"))]
    pub direction: Option<Direction>,
    /// Factor on the record's accelerations (dimensionless), e.g. to scale
    /// a record to a design peak ground acceleration. Default 1.
    #[serde(default)]
    #[schemars(extend("default" = 1.0))]
    pub scale: Option<f64>,
    /// Time of the run at which the record's time 0 falls, s (negative: the
    /// run starts part way through the record). Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub start_time: Option<f64>,
    /// Units of a CSV table's accelerations when its header does not state
    /// them (`g`, `m/s^2`, `cm/s^2`); a unit given both ways must agree.
    /// `.AT2` files state theirs.
    #[serde(default)]
    pub units: Option<AccelerationUnit>,
}
