//! What a scene records and how it writes it: the recordable quantities,
//! the history's file format and a plate's moment component.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Recordable quantities.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// Bridge vertical displacement at `x` (and `y` on a plate), m, positive
    /// upward. The summary also gives the static crossing response and the
    /// DAF at that point.
    BridgeDisplacement,
    /// Bridge vertical acceleration at `x` (and `y` on a plate), m/s², positive upward.
    BridgeAcceleration,
    /// Bending moment of a beam bridge at `x`, N·m, positive sagging; from
    /// the modes with the mode-acceleration static correction (beams only).
    BridgeMoment,
    /// Shear force of a beam bridge at `x`, N: dM/dx, the resultant of the
    /// upward forces left of the section; its right-hand limit where a wheel
    /// stands on the section (beams only).
    BridgeShear,
    /// Vertical reaction of a beam bridge's support at `x` (the position of
    /// an abutment or pier), N, positive upward on the deck: the jump of the
    /// shear there plus a wheel standing exactly on it, the beam's inertia
    /// included, so that the reactions balance the loads and the deck's
    /// inertia at every step. On an imported model, the reaction at a DOF
    /// listed under `constrained` (`node` and `direction`, or the track
    /// node at `x` whose uz is constrained), N or N·m on the structure:
    /// K_cf u + M_cf ü from its rows of the matrices; the reactions of all
    /// supports balance the loads and ∫ m ü to round-off. On a plate deck
    /// with free edges, the whole force of the support line across the deck
    /// at `x`, N, from virtual work with the span-wise hat of that support
    /// (the lines balance the loads and ∫∫ ρh ẅ dA to round-off).
    BridgeReaction,
    /// Contact force of a wheel, N, positive in compression.
    ContactForce,
    /// Gap between a wheel and the surface under it, m: positive when the wheel
    /// is lifted off (separated); negative is the compression of an elastic or
    /// Hertz contact; 0 under permanent contact.
    ContactGap,
    /// Vehicle DOF displacement from its static equilibrium on the rigid flat
    /// approach, m (or rad), positive upward.
    VehicleDisplacement,
    /// Vehicle DOF acceleration, m/s² (or rad/s²), positive upward.
    VehicleAcceleration,
}

/// File format of the time history.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum HistoryFormat {
    /// history.csv: a header row with units, then one row per written step.
    #[default]
    Csv,
    /// history.npy (NPY 1.0, little-endian float64, C order) and
    /// history_columns.txt.
    Npy,
    /// Both files.
    Both,
}

/// Which side of a section a beam's shear or moment is taken on: they jump
/// where a support or a wheel stands on the section.
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    Default,
    serde::Serialize,
    serde::Deserialize,
    schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// The left-hand limit V(x⁻): the element left of the section; a wheel
    /// exactly on it not yet passed.
    Left,
    /// The right-hand limit V(x⁺) (the default): the element right of it.
    #[default]
    Right,
}

/// Which moment per unit width.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize, schemars::JsonSchema,
)]
pub enum PlateMoment {
    /// m_x: longitudinal bending (about the transverse axis), N·m/m.
    #[serde(rename = "mx")]
    Longitudinal,
    /// m_y: transverse bending, N·m/m.
    #[serde(rename = "my")]
    Transverse,
    /// m_xy: twisting, N·m/m.
    #[serde(rename = "mxy")]
    Twisting,
}
