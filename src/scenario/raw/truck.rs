//! The plate paper's 7-DOF truck (`type: h20_44`) as written in a scenario.

use schemars::JsonSchema;
use serde::Deserialize;

/// The plate paper's 7-DOF truck (its Section 2.2, Fig. 2, Appendix A).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct H20TruckRaw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`100 km/h`).
    pub speed: super::SpeedRaw,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the front axle reaches the bridge entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the front axle at t = 0, m (≤ 0).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the truck's centre line on a plate deck, m.
    /// Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Overrides of the preset's parameters; omitted ones keep the preset.
    /// The preset: axles 4.27 m apart, wheels 1.83 m apart (the geometry of
    /// AASHTO's H20-44, 14 ft and 6 ft); body 16 200 kg, axles 1 200 kg
    /// each, centre of gravity 1.426 m behind the front axle, which give the
    /// static wheel forces the plate paper states for its empty truck
    /// (Section 3.2: Fg1 = 58.81 kN front, Fg3 = 32.42 kN rear; 182.5 kN in
    /// all). These are NOT AASHTO's H20-44 axle loads (35.59 kN front,
    /// 142.34 kN rear: `type: aashto_h20_44`). The paper's vehicle table
    /// (Table 1) is not legible in our copy and the tables of the sources it
    /// cites (Marchesiello et al. 1999, Zhu & Law 2002) were not available,
    /// so the inertias (pitch 1.0e5, roll 2.0e4, axle roll 600 kg·m²),
    /// suspensions (8.0e5 / 6.0e5 N/m, 1.2e4 / 8.0e3 N·s/m per wheel, 1.1 m
    /// apart) and tyres (1.75e6 N/m, 2.0e3 N·s/m) are typical values: body
    /// bounce near 2 Hz, axle hop near 10 Hz.
    #[serde(default)]
    pub parameters: Option<H20TruckParametersRaw>,
}

/// The plate paper's truck parameters (each optional: the preset fills the
/// rest). Per-wheel springs and dashpots are the same left and right.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct H20TruckParametersRaw {
    /// Body (sprung) mass m_v, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub body_mass: Option<f64>,
    /// Body pitch moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_pitch_inertia: Option<f64>,
    /// Body roll moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_roll_inertia: Option<f64>,
    /// Front axle mass with its wheels m₁, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub front_axle_mass: Option<f64>,
    /// Rear axle mass with its wheels m₂, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub rear_axle_mass: Option<f64>,
    /// Front axle roll moment of inertia I₁, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub front_axle_roll_inertia: Option<f64>,
    /// Rear axle roll moment of inertia I₂, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub rear_axle_roll_inertia: Option<f64>,
    /// Distance from the front axle back to the body's centre of gravity a₁, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub front_axle_to_centre: Option<f64>,
    /// Distance from the body's centre of gravity back to the rear axle a₂, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub centre_to_rear_axle: Option<f64>,
    /// Distance between the front tyres s_t1, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub front_track: Option<f64>,
    /// Distance between the rear tyres s_t2, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub rear_track: Option<f64>,
    /// Distance between the front suspensions s₁, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub front_suspension_spacing: Option<f64>,
    /// Distance between the rear suspensions s₂, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub rear_suspension_spacing: Option<f64>,
    /// Front suspension stiffness per wheel, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub front_suspension_stiffness: Option<f64>,
    /// Rear suspension stiffness per wheel, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub rear_suspension_stiffness: Option<f64>,
    /// Front suspension damping per wheel, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub front_suspension_damping: Option<f64>,
    /// Rear suspension damping per wheel, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub rear_suspension_damping: Option<f64>,
    /// Front tyre stiffness per wheel, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub front_tyre_stiffness: Option<f64>,
    /// Rear tyre stiffness per wheel, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub rear_tyre_stiffness: Option<f64>,
    /// Front tyre damping per wheel, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub front_tyre_damping: Option<f64>,
    /// Rear tyre damping per wheel, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub rear_tyre_damping: Option<f64>,
}
