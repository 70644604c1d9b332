//! The automatic mode choice: the modes a scene's excitation, its deck
//! accelerations, its heavy wheels and its ground motion ask for, each with
//! its reason in the modal bridge's `selection` (written to resolved.yaml
//! and the summary). A decision of the planning stage (issue 25), taken
//! while loading until that stage is split out.

use super::budget::Budget;
use super::checker::Checker;
use super::content::{self, Excitation};
use crate::bridge::{ModalBridge, ModeRequest};
use crate::scene::{Bridge, GroundMotion, Vehicle};

/// Share of the bridge's mass the automatic modes carry under ground
/// motion (EN 1998-1 4.3.3.3.1(3)).
const GROUND_MASS_SHARE: f64 = 0.9;

/// Grows `modal` (solved for the minimum modes) to the automatic choice
/// and returns the cut-off to write back, Hz; `None` after a located error
/// (a budget refused, a solve failed). `build` solves for a request, its
/// error located at a path of the file.
#[allow(clippy::too_many_arguments)]
pub(super) fn choose(
    modal: &mut ModalBridge,
    bridge: &Bridge,
    build: &impl Fn(ModeRequest) -> Result<ModalBridge, (&'static str, String)>,
    excitations: &[Excitation],
    record_cutoff: Option<f64>,
    vehicles: &[Vehicle],
    ground_motion: &[GroundMotion],
    minimum: usize,
    gravity: f64,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Option<f64> {
    // Automatic: keep the modes this scene excites; write the cut-off back
    // so the resolved scenario reproduces the choice.
    let (mut cutoff, mut dynamic, top) = content::mode_cutoff(modal, excitations);
    // Deck accelerations sum every mode up to their own cut-off (30 Hz
    // or more, EN 1990 A2.4.4.2.1(4)): keep all of them, so that the
    // filtered acceleration is complete and converges with the step.
    let acceleration_cut = record_cutoff.filter(|&cut| cut > cutoff);
    if let Some(cut) = acceleration_cut {
        cutoff = cut;
        dynamic = true;
    }
    // Heavy wheels feel the bridge's acceleration under them, which a
    // few modes resolve poorly: keep twice the minimum.
    let heavy = content::heavy_wheels(vehicles, bridge, gravity);
    let floor = if heavy {
        (2 * minimum).min(ModalBridge::available_of(bridge))
    } else {
        minimum
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
        ) || !budget.eigen(ck, "bridge.spans", bridge, kept)
        {
            return None;
        }
        *modal = match build(ModeRequest::AtLeastUpTo(floor, cutoff)) {
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
            "automatic: {} modes up to {cutoff:.2} Hz, at least twice the {minimum} of the \
             minimum because a wheel's mass exceeds {} of a span's (its contact force \
             follows the deck's acceleration under it)",
            modal.mode_count(),
            content::HEAVY_WHEEL_RATIO
        ),
        Some(cut) => format!(
            "automatic: {} modes, every one up to {cut:.2} Hz that the deck accelerations \
             sum (EN 1990 A2.4.4.2.1: max(30 Hz, 1.5 f₁, f₃) unless the record sets \
             `max_frequency`)",
            modal.mode_count()
        ),
        None => content::mode_reason(
            modal.mode_count(),
            cutoff,
            dynamic,
            &top,
            content::modes_per_span(bridge),
        ),
    };
    // Ground motion: keep modes until they carry 90 % of the bridge's
    // mass (EN 1998-1 4.3.3.3.1(3)); the uniform inertia load of a
    // vertical record excites the symmetric modes, each less than the
    // last, so a few suffice.
    // A lateral record asks the same of the lateral modes (a bridge in
    // the vertical plane has no lateral mass to carry: skipped).
    if !ground_motion.is_empty() {
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
            ) || !budget.eigen(ck, "ground_motion", bridge, more)
            {
                return None;
            }
            *modal = match build(ModeRequest::Lowest(more)) {
                Ok(m) => m,
                Err((path, message)) => {
                    ck.error(path, message);
                    return None;
                }
            };
        }
        let top = modal.frequencies().last().copied().unwrap_or(0.0);
        cutoff = cutoff.max(top);
    }
    Some(cutoff)
}
