//! The vehicles as written in a scenario: the union of every vehicle type,
//! the moving force and the sprung-mass oscillator (given directly or by
//! dimensionless groups).

use schemars::JsonSchema;
use serde::Deserialize;

use super::*;

/// A vehicle crossing the bridge. Its reference point is its FRONT axle; the
/// other axles follow at their offsets behind it.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
#[schemars(tag = "type")]
// The truck's optional parameters make its variant large; a parse-time
// value made once per vehicle, so boxing would buy nothing.
#[allow(clippy::large_enum_variant)]
pub enum VehicleRaw {
    /// A set of constant vertical axle loads at fixed spacings (no inertia).
    MovingForce(MovingForceRaw),
    /// Moving oscillator: sprung mass on a spring–damper over a wheel mass
    /// (the LCP paper's Fig. 1). `unsprung_mass: 0` is the 1-DOF sprung mass
    /// on a massless wheel (Yang & Yau 1997).
    Oscillator(OscillatorRaw),
    /// The plate paper's two-axle truck with seven DOFs (its Section 2.2,
    /// Fig. 2 and Appendix A, which call it H20-44 after AASHTO): body
    /// bounce, pitch and roll, each axle bounce and roll, a tyre
    /// spring–damper under each of its four wheels and a suspension
    /// spring–damper above it. The preset carries the static wheel forces
    /// the paper states for the empty truck (Section 3.2: Fg1 = 58.81 kN per
    /// front wheel, Fg3 = 32.42 kN per rear wheel; its vehicle table, Table 1,
    /// is not legible in our copy): NOT AASHTO's H20-44 axle loads (8 and
    /// 32 kip, `aashto_h20_44`). Parameters default to the preset (see
    /// `parameters`).
    #[serde(rename = "h20_44")]
    H20Truck(H20TruckRaw),
    /// AASHTO's H20-44 truck as moving axle forces (no inertia): 35.59 kN
    /// (8 kip) front and 142.34 kN (32 kip) rear axle 4.267 m (14 ft) apart
    /// (AASHTO Standard Specifications for Highway Bridges, 17th ed.,
    /// Art. 3.7.6, Fig. 3.7.6A); resolved into a `moving_force`.
    #[serde(rename = "aashto_h20_44")]
    AashtoH20(AashtoH20Raw),
    /// AASHTO's HS20-44 truck as moving axle forces (no inertia): 35.59 kN
    /// (8 kip), 142.34 kN (32 kip) and 142.34 kN axles, 4.267 m (14 ft) and
    /// `rear_axle_spacing` (14–30 ft) apart (AASHTO Standard Specifications
    /// for Highway Bridges, 17th ed., Art. 3.7.7, Fig. 3.7.7A; the design
    /// truck of AASHTO LRFD Art. 3.6.1.2.2); resolved into a `moving_force`.
    #[serde(rename = "aashto_hs20_44")]
    AashtoHs20(AashtoHs20Raw),
    /// Four-axle rail car with ten DOFs: car body and two bogies (bounce
    /// and pitch each) over four wheelsets (bounce), a primary
    /// spring–dashpot between each wheelset and its bogie and a secondary
    /// one between each bogie and the body (the LCP separation paper's
    /// Section 5.2). The wheelsets ride the rail through the contact model.
    /// Parameters default to the paper's Table 2 (see `parameters`).
    RailCar(RailCarRaw),
    /// A train of rail cars at one speed: `count` identical cars at
    /// `car_spacing`, or a `cars` list. Resolved into one vehicle whose
    /// wheels are every car's wheelsets, numbered front to rear.
    Train(TrainRaw),
    /// A train of 3D high-speed cars, 27 DOFs each (the EMBS paper's
    /// AVE-S103): body and bogies with lateral, vertical, yaw, roll and
    /// pitch motion over wheelsets that follow their rails vertically and
    /// laterally (permanent contact; no creep, no flange contact).
    #[serde(rename = "train_3d")]
    Train3d(Train3dRaw),
    /// An HSLM-A train of EN 1991-2:2003 Annex E (`model: A1` … `A10`; the
    /// coach count, coach length, bogie axle spacing and axle force of
    /// Table E.1 at the layout of Fig. E.2) as moving axle forces; resolved
    /// into a `moving_force` with its axle positions.
    Hslm(HslmRaw),
}

impl VehicleRaw {
    /// A vehicle that is a set of axle forces from a table (an HSLM train,
    /// an AASHTO truck) as the `moving_force` it resolves into; `None` for
    /// every other vehicle.
    pub fn as_axle_forces(&self) -> Option<MovingForceRaw> {
        match self {
            VehicleRaw::Hslm(v) => Some(v.moving_force()),
            VehicleRaw::AashtoH20(v) => Some(v.moving_force()),
            VehicleRaw::AashtoHs20(v) => Some(v.moving_force()),
            _ => None,
        }
    }

    /// The speed as written (`None`: an oscillator given by its
    /// dimensionless groups, its speed derived from the velocity ratio).
    pub fn speed(&self) -> Option<SpeedRaw> {
        match self {
            VehicleRaw::MovingForce(v) => Some(v.speed),
            VehicleRaw::Oscillator(v) => v.speed,
            VehicleRaw::H20Truck(v) => Some(v.speed),
            VehicleRaw::RailCar(v) => Some(v.speed),
            VehicleRaw::Train(v) => Some(v.speed),
            VehicleRaw::Train3d(v) => Some(v.speed),
            VehicleRaw::Hslm(v) => Some(v.speed),
            VehicleRaw::AashtoH20(v) => Some(v.speed),
            VehicleRaw::AashtoHs20(v) => Some(v.speed),
        }
    }
}

/// Where and how fast a vehicle travels.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MovingForceRaw {
    /// Axle loads, N (downward, positive), front axle first.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::force::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::force::list_schema")]
    pub loads: Vec<f64>,
    /// Distances between consecutive axles, m; one fewer than `loads`.
    /// Give this or `axle_positions`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive_items)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub axle_spacings: Option<Vec<f64>>,
    /// Distance of each axle behind the front axle, m: 0 first, then
    /// increasing; one per load (an axle-load train such as an HSLM train).
    /// Give this or `axle_spacings`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub axle_positions: Option<Vec<f64>>,
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`100 km/h`).
    pub speed: SpeedRaw,
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
    /// Give this or `start_position`, not both.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the front axle at t = 0, m (≤ 0: on the approach).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the loads on a plate deck, m. Default: the
    /// deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
}

/// Moving oscillator parameters: physical, or derived from the LCP separation
/// paper's dimensionless groups with `dimensionless`.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OscillatorRaw {
    /// Sprung (body) mass, kg. Required unless `dimensionless` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub sprung_mass: Option<f64>,
    /// Unsprung (wheel) mass, kg. Default 0: a massless wheel.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub unsprung_mass: Option<f64>,
    /// Suspension stiffness, N/m. Required unless `dimensionless` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub stiffness: Option<f64>,
    /// Suspension damping, N·s/m. Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub damping: Option<f64>,
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`100 km/h`). Required unless
    /// `dimensionless` is given.
    #[serde(default)]
    pub speed: Option<SpeedRaw>,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the wheel reaches the bridge entrance, s. Default 0, or on a
    /// random surface with a run-in the time to reach the entrance from
    /// x = −`run_in` (`surface.run_in`).
    /// Give this or `start_position`, not both.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the wheel at t = 0, m (≤ 0: on the approach).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the wheel on a plate deck, m. Default: the
    /// deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Derive masses, stiffness, damping and speed from dimensionless groups
    /// relative to the bridge (its first natural frequency f₁, length L and
    /// mass per length m). Physical fields given as well must agree with the
    /// derived values (the resolved scenario lists both).
    #[serde(default)]
    pub dimensionless: Option<DimensionlessRaw>,
}

/// The dimensionless groups of the LCP separation paper's Table 1 (standard
/// definitions; its formulas were lost in extraction).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DimensionlessRaw {
    /// Velocity ratio α = v / (2 f₁ L) (dimensionless; 1 = the critical speed
    /// of the moving-force resonance).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub velocity_ratio: f64,
    /// Vehicle-to-bridge mass ratio (m_s + m_u) / (m L) (dimensionless).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub mass_ratio: f64,
    /// Unsprung-to-sprung mass ratio m_u / m_s (dimensionless). Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    pub unsprung_ratio: Option<f64>,
    /// Bridge-to-vehicle frequency ratio f₁ / f_v with f_v = √(k/m_s) / 2π
    /// (dimensionless).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub frequency_ratio: f64,
    /// Vehicle damping ratio ζ_v = c / (2√(k m_s)) (dimensionless). Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::ratio)]
    #[schemars(extend("default" = 0.0))]
    pub damping_ratio: Option<f64>,
}
