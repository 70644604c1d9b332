//! The H20-44 truck as written in a scenario.

use schemars::JsonSchema;
use serde::Deserialize;

/// H20-44 truck.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct H20TruckRaw {
    /// Constant speed, m/s.
    pub speed: f64,
    /// Time at which the front axle reaches the bridge entrance, s. Default 0.
    #[serde(default)]
    pub entry_time: Option<f64>,
    /// Position of the front axle at t = 0, m (≤ 0).
    #[serde(default)]
    pub start_position: Option<f64>,
    /// Transverse position y of the truck's centre line on a plate deck, m.
    /// Default: the deck's centre line.
    #[serde(default)]
    pub lateral_position: Option<f64>,
    /// Overrides of the preset's parameters; omitted ones keep the preset.
    #[serde(default)]
    pub parameters: Option<H20TruckParametersRaw>,
}

/// H20-44 parameters (each optional: the preset fills the rest). Per-wheel
/// springs and dashpots are the same left and right.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct H20TruckParametersRaw {
    /// Body (sprung) mass m_v, kg.
    #[serde(default)]
    pub body_mass: Option<f64>,
    /// Body pitch moment of inertia, kg·m².
    #[serde(default)]
    pub body_pitch_inertia: Option<f64>,
    /// Body roll moment of inertia, kg·m².
    #[serde(default)]
    pub body_roll_inertia: Option<f64>,
    /// Front axle mass with its wheels m₁, kg.
    #[serde(default)]
    pub front_axle_mass: Option<f64>,
    /// Rear axle mass with its wheels m₂, kg.
    #[serde(default)]
    pub rear_axle_mass: Option<f64>,
    /// Front axle roll moment of inertia I₁, kg·m².
    #[serde(default)]
    pub front_axle_roll_inertia: Option<f64>,
    /// Rear axle roll moment of inertia I₂, kg·m².
    #[serde(default)]
    pub rear_axle_roll_inertia: Option<f64>,
    /// Distance from the front axle back to the body's centre of gravity a₁, m.
    #[serde(default)]
    pub front_axle_to_centre: Option<f64>,
    /// Distance from the body's centre of gravity back to the rear axle a₂, m.
    #[serde(default)]
    pub centre_to_rear_axle: Option<f64>,
    /// Distance between the front tyres s_t1, m.
    #[serde(default)]
    pub front_track: Option<f64>,
    /// Distance between the rear tyres s_t2, m.
    #[serde(default)]
    pub rear_track: Option<f64>,
    /// Distance between the front suspensions s₁, m.
    #[serde(default)]
    pub front_suspension_spacing: Option<f64>,
    /// Distance between the rear suspensions s₂, m.
    #[serde(default)]
    pub rear_suspension_spacing: Option<f64>,
    /// Front suspension stiffness per wheel, N/m.
    #[serde(default)]
    pub front_suspension_stiffness: Option<f64>,
    /// Rear suspension stiffness per wheel, N/m.
    #[serde(default)]
    pub rear_suspension_stiffness: Option<f64>,
    /// Front suspension damping per wheel, N·s/m.
    #[serde(default)]
    pub front_suspension_damping: Option<f64>,
    /// Rear suspension damping per wheel, N·s/m.
    #[serde(default)]
    pub rear_suspension_damping: Option<f64>,
    /// Front tyre stiffness per wheel, N/m.
    #[serde(default)]
    pub front_tyre_stiffness: Option<f64>,
    /// Rear tyre stiffness per wheel, N/m.
    #[serde(default)]
    pub rear_tyre_stiffness: Option<f64>,
    /// Front tyre damping per wheel, N·s/m.
    #[serde(default)]
    pub front_tyre_damping: Option<f64>,
    /// Rear tyre damping per wheel, N·s/m.
    #[serde(default)]
    pub rear_tyre_damping: Option<f64>,
}
