//! Rail vehicles as written in a scenario: the 10-DOF rail car and trains.

use schemars::JsonSchema;
use serde::Deserialize;

/// Four-axle rail car.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RailCarRaw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`300 km/h`).
    pub speed: super::SpeedRaw,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the front wheelset reaches the bridge entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the front wheelset at t = 0, m (≤ 0).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the track's centre line on a plate deck, m.
    /// Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Overrides of the preset's parameters; omitted ones keep the preset.
    /// The preset is the LCP separation paper's Table 2 (Section 5.2): body
    /// 31 994 kg and 2.1e6 kg·m²; bogie 3 333 kg and 3 200 kg·m²; wheelset
    /// 1 650 kg; primary suspension 4 720 kN/m and 160 kN·s/m per wheelset;
    /// secondary 160 kN/m and 200 kN·s/m per bogie; half bogie spacing
    /// 8.75 m; half wheelbase 1.25 m.
    #[serde(default)]
    pub parameters: Option<RailCarParametersRaw>,
}

/// Rail car parameters (each optional: the preset fills the rest).
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RailCarParametersRaw {
    /// Car body mass M_c, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub body_mass: Option<f64>,
    /// Car body pitch moment of inertia J_c, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_pitch_inertia: Option<f64>,
    /// Mass of one bogie frame M_b, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub bogie_mass: Option<f64>,
    /// Pitch moment of inertia of one bogie J_b, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub bogie_pitch_inertia: Option<f64>,
    /// Mass of one wheelset M_w, kg (the contact DOF's mass).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub wheelset_mass: Option<f64>,
    /// Primary suspension stiffness per wheelset (bogie ↔ wheelset) k_p, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub primary_stiffness: Option<f64>,
    /// Primary suspension damping per wheelset c_p, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub primary_damping: Option<f64>,
    /// Secondary suspension stiffness per bogie (body ↔ bogie) k_s, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub secondary_stiffness: Option<f64>,
    /// Secondary suspension damping per bogie c_s, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub secondary_damping: Option<f64>,
    /// Half the distance between the two bogie centres a, m (≥ 0).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub half_bogie_spacing: Option<f64>,
    /// Half the distance between the two wheelsets of a bogie b, m (≥ 0).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub half_wheelbase: Option<f64>,
}

/// A train of rail cars at one speed. Give `count` identical cars with
/// `car_spacing`, or the `cars` list. Every car is the rail car of
/// `type: rail_car` (the preset, with `parameters` overriding it for every
/// car and each car's own `parameters` on top). Wheels are numbered front to
/// rear over the whole train (car k has wheels 4k−3 … 4k); `record` picks a
/// car with `car:`.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrainRaw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`300 km/h`).
    pub speed: super::SpeedRaw,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the first car's front wheelset reaches the bridge
    /// entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the first car's front wheelset at t = 0, m (≤ 0).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the track's centre line on a plate deck, m.
    /// Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Number of identical cars (with `car_spacing`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub count: Option<usize>,
    /// Distance between the front wheelsets of consecutive cars, m (with
    /// `count`); at least a car's wheelset span 2(a + b).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub car_spacing: Option<f64>,
    /// The cars, front first (instead of `count`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_empty)]
    pub cars: Option<Vec<TrainCarRaw>>,
    /// Overrides of the rail car preset for every car.
    #[serde(default)]
    pub parameters: Option<RailCarParametersRaw>,
}

/// One car of a `cars` list.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrainCarRaw {
    /// Distance from the previous car's front wheelset to this car's front
    /// wheelset, m; at least the previous car's wheelset span. Required for
    /// every car but the first (which has none).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub spacing: Option<f64>,
    /// Overrides for this car, on top of the train's `parameters`.
    #[serde(default)]
    pub parameters: Option<RailCarParametersRaw>,
}

/// A train of 3D high-speed cars (the EMBS paper's Section 3.2): each car
/// a body and two bogies (lateral, vertical, yaw, roll, pitch) over four
/// wheelsets (lateral, vertical, roll), 27 DOFs, with primary and
/// secondary suspensions in three directions. One car unless `count` or
/// `cars` says more. The wheelsets follow their rails vertically and
/// laterally with the rails' irregularities (contact `permanent`; no creep
/// forces, no flange contact). Parameters default to the AVE-S103 preset
/// (see `parameters`).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Train3dRaw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`300 km/h`).
    pub speed: super::SpeedRaw,
    /// Constant acceleration along the path, m/s² (negative: braking). Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the first car's front wheelset reaches the bridge
    /// entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the first car's front wheelset at t = 0, m (≤ 0).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the track's centre line on a plate deck, m.
    /// Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Number of identical cars (with `car_spacing` when more than one).
    /// Default 1.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub count: Option<usize>,
    /// Distance between the front wheelsets of consecutive cars, m (with
    /// `count`); more than a car's wheelset span 2(a + b).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub car_spacing: Option<f64>,
    /// The cars, front first (instead of `count`).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_empty)]
    pub cars: Option<Vec<Train3dCarRaw>>,
    /// Overrides of the AVE-S103 preset for every car. The preset is the
    /// EMBS paper's Table 2: body 47 800 kg, roll 119 328, pitch and yaw
    /// 1 957 888 kg·m²; bogie 3 500 kg, roll 2 835, pitch 1 715, yaw
    /// 4 235 kg·m²; wheelset 1 800 kg, roll 1 000 kg·m²; primary per axle
    /// box 12 500 / 120 000 / 1 200 kN/m and 9 / 27.9 / 10 kN·s/m
    /// (longitudinal / lateral / vertical); secondary per side
    /// 240 / 240 / 350 kN/m and 30 / 30 / 20 kN·s/m; bogie spacing
    /// 17.375 m; wheelbase 2.5 m; heights 1.50 m (body), 0.53 m (bogie);
    /// rolling radius 0.43 m. Table 2 has no lateral spacings and no
    /// secondary height: the preset takes 1.0 m half spacings for both
    /// suspensions, 0.75 m for the contact points (standard gauge) and a
    /// secondary height of 1.0 m above the rail — typical of the ICE 3
    /// family, to be overridden with the real car's values.
    #[serde(default)]
    pub parameters: Option<Train3dParametersRaw>,
}

/// One car of a 3D train's `cars` list.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Train3dCarRaw {
    /// Distance from the previous car's front wheelset to this car's front
    /// wheelset, m; more than the previous car's wheelset span. Required
    /// for every car but the first.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub spacing: Option<f64>,
    /// Overrides for this car, on top of the train's `parameters`.
    #[serde(default)]
    pub parameters: Option<Train3dParametersRaw>,
}

/// 3D car parameters (each optional: the AVE-S103 preset fills the rest).
/// Suspension rates are per spring: per axle box (primary, two per
/// wheelset) and per side of a bogie (secondary, two per bogie).
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Train3dParametersRaw {
    /// Car body mass, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub body_mass: Option<f64>,
    /// Car body roll moment of inertia (about the longitudinal axis), kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_roll_inertia: Option<f64>,
    /// Car body pitch moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_pitch_inertia: Option<f64>,
    /// Car body yaw moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub body_yaw_inertia: Option<f64>,
    /// Mass of one bogie frame, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub bogie_mass: Option<f64>,
    /// Bogie roll moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub bogie_roll_inertia: Option<f64>,
    /// Bogie pitch moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub bogie_pitch_inertia: Option<f64>,
    /// Bogie yaw moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub bogie_yaw_inertia: Option<f64>,
    /// Mass of one wheelset, kg.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub wheelset_mass: Option<f64>,
    /// Wheelset roll moment of inertia, kg·m².
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia::schema")]
    pub wheelset_roll_inertia: Option<f64>,
    /// Primary longitudinal stiffness per axle box, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub primary_longitudinal_stiffness: Option<f64>,
    /// Primary lateral stiffness per axle box, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub primary_lateral_stiffness: Option<f64>,
    /// Primary vertical stiffness per axle box, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub primary_vertical_stiffness: Option<f64>,
    /// Primary longitudinal damping per axle box, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub primary_longitudinal_damping: Option<f64>,
    /// Primary lateral damping per axle box, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub primary_lateral_damping: Option<f64>,
    /// Primary vertical damping per axle box, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub primary_vertical_damping: Option<f64>,
    /// Secondary longitudinal stiffness per side of a bogie, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub secondary_longitudinal_stiffness: Option<f64>,
    /// Secondary lateral stiffness per side of a bogie, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub secondary_lateral_stiffness: Option<f64>,
    /// Secondary vertical stiffness per side of a bogie, N/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub secondary_vertical_stiffness: Option<f64>,
    /// Secondary longitudinal damping per side of a bogie, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub secondary_longitudinal_damping: Option<f64>,
    /// Secondary lateral damping per side of a bogie, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub secondary_lateral_damping: Option<f64>,
    /// Secondary vertical damping per side of a bogie, N·s/m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub secondary_vertical_damping: Option<f64>,
    /// Half the distance between the bogie centres a, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub half_bogie_spacing: Option<f64>,
    /// Half the distance between a bogie's two wheelsets b, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub half_wheelbase: Option<f64>,
    /// Half the lateral distance between a wheelset's two axle boxes d₁, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub primary_half_spacing: Option<f64>,
    /// Half the lateral distance between a bogie's two secondary springs d₂, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub secondary_half_spacing: Option<f64>,
    /// Half the lateral distance between a wheelset's two wheel–rail
    /// contact points b₀, m (0.75 on standard gauge).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub contact_half_spacing: Option<f64>,
    /// Height of the car body's centre of gravity above the rail head, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub body_height: Option<f64>,
    /// Height of a bogie's centre of gravity above the rail head, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub bogie_height: Option<f64>,
    /// Height of the secondary suspension above the rail head, m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub secondary_height: Option<f64>,
    /// Nominal rolling radius R₀ (the axle's height above the rail head), m.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub wheel_radius: Option<f64>,
}
