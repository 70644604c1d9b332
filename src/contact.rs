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
