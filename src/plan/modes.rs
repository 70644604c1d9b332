//! The automatic mode choice (no `bridge.modes` in the file): the modes
//! the scene excites, those the deck accelerations sum, twice the minimum
//! under heavy wheels, those that carry an imported track's flexibility
//! under a wheel, and those that carry 90 % of the mass under ground
//! motion; written back as a count and a cut-off with the reason.

use crate::bridge::{ModalBridge, ModeRequest};
use crate::scenario::budget::Budget;
use crate::scenario::checker::Checker;
use crate::scene::*;

use super::budget::eigen_fits;
use super::content::{self, Excitation};
use super::track_flexibility;

/// Share of the bridge's mass the automatic modes carry under ground
/// motion (EN 1998-1 4.3.3.3.1(3)).
const GROUND_MASS_SHARE: f64 = 0.9;

/// A solve of the bridge's modes for a request, its error blamed on a key
/// path of the file.
pub(super) type Build<'a> = dyn Fn(ModeRequest) -> Result<ModalBridge, (&'static str, String)> + 'a;

/// What the scene asks of the automatic modes.
pub(super) struct Needs<'a> {
    /// The frequencies the vehicles, surface and study excite.
    pub excitations: &'a [Excitation],
    /// The highest filter a recorded deck acceleration (or a resonance
    /// check's verdict) sums modes up to, Hz.
    pub record_cutoff: Option<f64>,
    /// The vehicles (heavy wheels keep twice the minimum).
    pub vehicles: &'a [Vehicle],
    /// The ground motion records (their mass share).
    pub ground_motion: &'a [GroundMotion],
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// The minimum modes for the quasi-static shape.
    pub minimum: usize,
    /// Whether wheels with a mass of their own hold vertical / lateral
    /// contacts ([`track_flexibility::wheels_with_mass`]).
    pub vertical_mass: bool,
    /// See `vertical_mass`.
    pub lateral_mass: bool,
}

/// The automatic modes, from the minimum solve `modal`: keeps the modes
/// `needs` asks for and says why in `selection`; returns them with the
/// cut-off to write back (Hz, at least the last kept mode's frequency), or
/// `None` once a budget or a solve reported an error.
pub(super) fn automatic(
    mut modal: ModalBridge,
    bridge: &Bridge,
    needs: &Needs<'_>,
    budget: &Budget,
    ck: &mut Checker<'_>,
    build: &Build<'_>,
) -> Option<(ModalBridge, f64)> {
    // Keep the modes this scene excites; the caller writes the cut-off back
    // so the resolved scenario reproduces the choice.
    let (mut cutoff, mut dynamic, top) = content::mode_cutoff(&modal, needs.excitations);
    // Deck accelerations sum every mode up to their own cut-off (30 Hz
    // or more, EN 1990 A2.4.4.2.1(4)): keep all of them, so that the
    // filtered acceleration is complete and converges with the step.
    let acceleration_cut = needs.record_cutoff.filter(|&cut| cut > cutoff);
    if let Some(cut) = acceleration_cut {
        cutoff = cut;
        dynamic = true;
    }
    // Heavy wheels feel the bridge's acceleration under them, which a
    // few modes resolve poorly: keep twice the minimum.
    let heavy = content::heavy_wheels(needs.vehicles, bridge, needs.gravity);
    let heavy_floor = 2 * content::minimum_modes(bridge);
    let floor = if heavy {
        heavy_floor.min(ModalBridge::available_of(bridge))
    } else {
        needs.minimum
    };
    dynamic |= heavy;
    if dynamic {
        // The cut-off the excitation asks for may keep more modes than the
        // budget allows (a very long or very flexible span): count them
        // with one factorisation before solving for them.
        let kept = ModalBridge::count_up_to(bridge, cutoff)
            .ok()
            .flatten()
            .map_or(floor, |n| n.max(floor));
        if !budget.check(
            ck,
            "bridge.spans",
            "modes",
            &format!("bridge modes up to the {cutoff:.4} Hz the vehicles excite"),
            kept as f64,
        ) || !eigen_fits(budget, ck, "bridge.spans", bridge, kept)
        {
            return None;
        }
        modal = match build(ModeRequest::AtLeastUpTo(floor, cutoff)) {
            Ok(m) => m,
            Err((path, message)) => {
                ck.error(path, message);
                return None;
            }
        };
    }
    // The cut-off written back must reproduce the modes kept.
    cutoff = cutoff.max(modal.frequencies().last().copied().unwrap_or(0.0));
    modal.selection = match acceleration_cut {
        _ if heavy => format!(
            "automatic: {} modes up to {cutoff:.2} Hz, at least twice the {} of the \
             minimum because a wheel's mass exceeds {} of a span's (its contact force \
             follows the deck's acceleration under it)",
            modal.mode_count(),
            content::minimum_modes(bridge),
            content::HEAVY_WHEEL_RATIO
        ),
        Some(cut) => format!(
            "automatic: {} modes, every one up to {cut:.2} Hz that the deck accelerations \
             sum (EN 1990 A2.4.4.2.1: max(30 Hz, 1.5 f₁, f₃) unless the record sets \
             `max_frequency`)",
            modal.mode_count()
        ),
        None => {
            let per_span = needs.minimum / content::floor_spans(bridge).max(1);
            let mut reason =
                content::mode_reason(modal.mode_count(), cutoff, dynamic, &top, per_span);
            if !dynamic && needs.minimum < content::minimum_modes(bridge) {
                reason.push_str(
                    "; the static correction adds the quasi-static share of the modes left out",
                );
            }
            reason
        }
    };
    // An imported track under wheels with mass: keep modes until they
    // carry the rails' static flexibility under a wheel (the static
    // correction's spring has no inertia; [`track_flexibility`]).
    if modal.is_imported() && modal.static_correction && (needs.vertical_mass || needs.lateral_mass)
    {
        modal = track_flexibility::keep_rails_flexibility(
            modal,
            bridge,
            needs.lateral_mass,
            budget,
            ck,
            build,
        )?;
        cutoff = cutoff.max(modal.frequencies().last().copied().unwrap_or(0.0));
    }
    // Ground motion: keep modes until they carry 90 % of the bridge's
    // mass (EN 1998-1 4.3.3.3.1(3)).
    if !needs.ground_motion.is_empty() {
        modal = ground_motion_modes(modal, bridge, needs.ground_motion, budget, ck, build)?;
        let top = modal.frequencies().last().copied().unwrap_or(0.0);
        cutoff = cutoff.max(top);
    }
    Some((modal, cutoff))
}

// Ground motion: keep modes until they carry 90 % of the bridge's
// mass (EN 1998-1 4.3.3.3.1(3)); the uniform inertia load of a
// vertical record excites the symmetric modes, each less than the
// last, so a few suffice.
// A lateral record asks the same of the lateral modes (a bridge in
// the vertical plane has no lateral mass to carry: skipped).
fn ground_motion_modes(
    mut modal: ModalBridge,
    bridge: &Bridge,
    ground_motion: &[GroundMotion],
    budget: &Budget,
    ck: &mut Checker<'_>,
    build: &Build<'_>,
) -> Option<ModalBridge> {
    let available = ModalBridge::available_of(bridge);
    let has = |d| ground_motion.iter().any(|g| g.direction == d);
    let (vertical, lateral) = (
        has(crate::scene::Direction::Vertical),
        has(crate::scene::Direction::Lateral),
    );
    loop {
        let share = |(participation, mass): (Vec<f64>, f64)| {
            if mass > 0.0 {
                participation.iter().map(|g| g * g).sum::<f64>() / mass
            } else {
                1.0
            }
        };
        let mut ratio = 1.0f64;
        if vertical {
            ratio = ratio.min(share(modal.vertical_participation(bridge)));
        }
        if lateral {
            ratio = ratio.min(share(modal.lateral_participation(bridge)));
        }
        let count = modal.mode_count();
        if ratio >= GROUND_MASS_SHARE || count >= available {
            if ratio >= GROUND_MASS_SHARE {
                modal.selection.push_str(&format!(
                    "; for the ground motion they carry {:.1} % of the bridge's mass (EN 1998-1 4.3.3.3.1: at least {:.0} %)",
                    100.0 * ratio,
                    100.0 * GROUND_MASS_SHARE
                ));
            }
            break;
        }
        let more = (2 * count).min(available);
        if !budget.check(
            ck,
            "ground_motion",
            "modes",
            "bridge modes for 90 % of the mass under ground motion",
            more as f64,
        ) || !eigen_fits(budget, ck, "ground_motion", bridge, more)
        {
            return None;
        }
        modal = match build(ModeRequest::Lowest(more)) {
            Ok(m) => m,
            Err((path, message)) => {
                ck.error(path, message);
                return None;
            }
        };
    }
    Some(modal)
}
