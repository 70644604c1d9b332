//! `type: aashto_h20_44` and `type: aashto_hs20_44`: AASHTO's standard
//! trucks as moving axle forces ([`crate::scene::aashto`]).

use schemars::JsonSchema;
use serde::Deserialize;

use super::{MovingForceRaw, SpeedRaw};
use crate::scene::aashto::{
    H20_44_AXLE_LOADS, H20_44_AXLE_SPACING, HS20_44_AXLE_LOADS, HS20_44_REAR_SPACING_MIN,
    hs20_44_spacings,
};

/// AASHTO's H20-44 truck as axle loads (AASHTO Standard Specifications for
/// Highway Bridges, 17th ed., Art. 3.7.6, Fig. 3.7.6A): 8 kip (35.59 kN)
/// front and 32 kip (142.34 kN) rear axle, 14 ft (4.267 m) apart.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AashtoH20Raw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`80 km/h`).
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
    /// Transverse position y of the axle loads on a plate deck, m (each axle
    /// load acts there whole; AASHTO's two wheels of an axle are 6 ft =
    /// 1.829 m apart). Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
}

/// AASHTO's HS20-44 truck as axle loads (AASHTO Standard Specifications for
/// Highway Bridges, 17th ed., Art. 3.7.7, Fig. 3.7.7A; the design truck of
/// AASHTO LRFD Art. 3.6.1.2.2): 8 kip (35.59 kN), 32 kip (142.34 kN) and
/// 32 kip axles, 14 ft (4.267 m) and then `rear_axle_spacing` apart.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AashtoHs20Raw {
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`80 km/h`).
    pub speed: SpeedRaw,
    /// Spacing V between the rear tractor axle and the semitrailer axle, m:
    /// 14 ft to 30 ft (4.2672 to 9.144 m), "the spacing that produces the
    /// maximum stresses" (Fig. 3.7.7A; LRFD 3.6.1.2.2). Default 4.2672 m
    /// (14 ft).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::hs20_44_rear_spacing)]
    #[schemars(extend("default" = HS20_44_REAR_SPACING_MIN))]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub rear_axle_spacing: Option<f64>,
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
    /// Transverse position y of the axle loads on a plate deck, m (each axle
    /// load acts there whole; AASHTO's two wheels of an axle are 6 ft =
    /// 1.829 m apart). Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
}

impl AashtoH20Raw {
    /// The same truck as explicit moving forces.
    pub fn moving_force(&self) -> MovingForceRaw {
        MovingForceRaw {
            loads: H20_44_AXLE_LOADS.to_vec(),
            axle_spacings: Some(vec![H20_44_AXLE_SPACING]),
            axle_positions: None,
            speed: self.speed,
            acceleration: self.acceleration,
            entry_time: self.entry_time,
            start_position: self.start_position,
            lateral_position: self.lateral_position,
        }
    }
}

impl AashtoHs20Raw {
    /// The same truck as explicit moving forces (the rear spacing as
    /// written; the resolver checks its range).
    pub fn moving_force(&self) -> MovingForceRaw {
        let rear = self.rear_axle_spacing.unwrap_or(HS20_44_REAR_SPACING_MIN);
        MovingForceRaw {
            loads: HS20_44_AXLE_LOADS.to_vec(),
            axle_spacings: Some(hs20_44_spacings(rear).to_vec()),
            axle_positions: None,
            speed: self.speed,
            acceleration: self.acceleration,
            entry_time: self.entry_time,
            start_position: self.start_position,
            lateral_position: self.lateral_position,
        }
    }
}
