//! Contact directions: how a wheel meets the bridge.
//!
//! A contact point is (rail, position x along the bridge, direction): the
//! bridge answers with its mode components in that direction there
//! ([`crate::bridge::ModalBridge::mode_components`]), the vehicle with the
//! one DOF of its model that follows it ([`crate::vehicle::WheelKind::Dof`]).
//! Vertical-only scenes have only vertical contacts and keep their cost.

/// Gap above which a wheel with zero contact force counts as separated, m.
/// Rigid LCP contact leaves round-off gaps of ~1e-15 m at touching wheels.
pub const SEPARATION_GAP: f64 = 1e-9;

/// Gap a rigid-contact flight must exceed to count as a contact-loss
/// episode, m (its time and largest gap count from its start, when the gap
/// first passed [`SEPARATION_GAP`]). Rigid contact idealises a wheel whose
/// real (Hertz) compression under its static load is tens of micrometres
/// (50 kN on a steel wheel and rail: ≈ 60 µm); a flight that never opens
/// 1 µm is within 2 % of that compression, so an elastic wheel would have
/// stayed loaded. Without this floor the count has no limit as Δt → 0: with
/// restitution e > 0 a bouncing wheel's flights shrink geometrically (an
/// accumulation of impacts, infinitely many flights in a finite time), each
/// step resolving a few more of them, and a contact force that just touches
/// zero opens nanometre gaps for a step or two. Elastic and Hertz contact
/// count every flight above [`SEPARATION_GAP`]: their compression is the
/// model's own, and their counts converge.
pub const RIGID_LOSS_GAP: f64 = 1e-6;

/// The direction in which a contact point follows the bridge (and the
/// track irregularity of its rail).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ContactDirection {
    /// Vertical, +z up. The contact force is the compression between
    /// wheel and rail (N, positive pushing the wheel up and the deck down).
    #[default]
    Vertical,
    /// Lateral, +y to the left of travel (toward larger deck y). The
    /// contact force is the rail's guiding force on the wheelset (N,
    /// positive pushing the wheelset toward +y and the deck toward −y).
    Lateral,
}

impl ContactDirection {
    /// Lower-case name, as in the scenario format.
    pub fn name(self) -> &'static str {
        match self {
            ContactDirection::Vertical => "vertical",
            ContactDirection::Lateral => "lateral",
        }
    }
}

impl std::fmt::Display for ContactDirection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}
