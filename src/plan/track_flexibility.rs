//! The automatic mode count on an imported track under wheels with mass:
//! keep modes until they carry the rails' static flexibility under a wheel.
//!
//! The static correction adds the modes left out as a massless spring, the
//! residual flexibility R(c, c) = G(c, c) − Σᵢ φᵢ(c)²/ωᵢ² at a contact c
//! (G the full model's static flexibility, m/N). Under a moving force that
//! is exact for the quasi-static part, whatever R. Under a wheel with mass
//! held to the rail it is not: the wheel bounces on the track's local
//! stiffness (rail on its pads and sleepers) at a frequency set by the
//! whole flexibility G, and the modes that carry it — on a ballasted track
//! the rail-on-pad band, 550 Hz to 2.2 kHz on the generated two-span
//! viaduct — lie far above every frequency [`super::content`] counts as
//! excited. While they are left out, the share of G the spring carries has
//! no inertia, and the contact force, the rail and the deck accelerations
//! it drives converge only as that share falls. Measured on
//! embs-viaduct-ave-s103-quake (an AVE-S103 car at 300 km/h, max error over
//! the history against every one of the model's 1,584 modes, same step):
//!
//! | modes (top, Hz) | largest residual share, vertical | contact force | deck acc. (30 Hz) |
//! |---|---|---|---|
//! | 564 (276) | 12 % | 3.9 % | 2.8 % |
//! | 792 (690) | 5.0 % | 3.1 % | 1.4 % |
//! | 1,128 (2,242) | 0.38 % | 0.32 % | 0.17 % |
//!
//! The share is taken as max_c R(c, c) / max_c G(c, c) over the rail nodes
//! in each direction the wheels hold (vertical on each rail; lateral, the
//! rails' average, for a 3D train): normalised by the largest G so that a
//! point where the track barely deflects (a support, a rail end under its
//! entry ramp) does not divide by nearly zero.
//!
//! A beam keeps its own rule ([`super::content::MODES_PER_SPAN`] per span
//! leave about 0.1 % of the deflection under a wheel): there the track is
//! the beam. Above [`crate::bridge::CONTACT_CORRECTION_DOFS`] DOFs (or with
//! `modes.static_correction: false`) the contacts carry no static
//! correction: the share left out is then missing, not a spring. The rule
//! does not grow the modes there (a long viaduct's rail-on-pad band holds
//! tens of thousands); G is solved at a sample of rail nodes instead and the
//! share the kept modes leave out, however they were chosen, goes into the
//! summary and a run warning ([`measure_without_correction`]).

use crate::bridge::{ContactPoint, ModalBridge, ModeRequest, RailsFlexibility};
use crate::contact::ContactDirection;
use crate::scenario::budget::Budget;
use crate::scenario::checker::Checker;
use crate::scene::Bridge;
use crate::scene::Vehicle;
use crate::vehicle::{VehicleModel, WheelKind};

/// The largest share of the rails' static flexibility under a wheel that
/// the automatic choice leaves to the static correction's massless spring.
/// At 0.5 % the golden EMBS scene keeps 1,069 modes (to 1.76 kHz), where
/// every recorded quantity is within 0.5 % of `vbi converge`'s reference
/// (every mode, Δt/4; worst the wheelset lateral force, 0.465 %).
pub const TRACK_RESIDUAL_SHARE: f64 = 0.005;

/// Which contacts the vehicles hold with a mass of their own on them
/// (vertical, lateral): a wheel on a DOF (an oscillator's unsprung mass, a
/// rail car's or a 3D train's wheelset), not a moving force or a truck's
/// massless tyre point.
pub fn wheels_with_mass(vehicles: &[Vehicle], gravity: f64) -> (bool, bool) {
    let (mut vertical, mut lateral) = (false, false);
    for vehicle in vehicles {
        let model = VehicleModel::build(vehicle, gravity);
        for wheel in &model.wheels {
            if let WheelKind::Dof(dof) = wheel.kind
                && model.mass[(dof, dof)] > 0.0
            {
                match wheel.direction {
                    ContactDirection::Vertical => vertical = true,
                    ContactDirection::Lateral => lateral = true,
                }
            }
        }
    }
    (vertical, lateral)
}

/// The contact points the rule samples: every rail node of the track, on
/// each rail vertically (`rails` of them: y = +1 m is the first rail, −1 m
/// the second, [`crate::bridge::fe_import::modal::track_weights_at`]), and
/// laterally when `lateral`.
pub fn sample_points(modal: &ModalBridge, rails: usize, lateral: bool) -> Vec<ContactPoint> {
    points_at(modal.node_x().iter().copied(), rails, lateral)
}

/// The contact points at the rail positions `xs` (m): on each of the
/// `rails` vertically, and laterally (the rails' average) when `lateral`.
fn points_at(xs: impl Iterator<Item = f64>, rails: usize, lateral: bool) -> Vec<ContactPoint> {
    let ys: &[f64] = if rails == 2 { &[1.0, -1.0] } else { &[0.0] };
    let mut points = Vec::new();
    for x in xs {
        for &y in ys {
            points.push((ContactDirection::Vertical, x, y));
        }
        if lateral {
            points.push((ContactDirection::Lateral, x, 0.0));
        }
    }
    points
}

/// The rails of the track (one or two; a beam's line is one).
fn rails_of(bridge: &Bridge) -> usize {
    match bridge {
        Bridge::FeImport(fe) => fe.track.len(),
        _ => 1,
    }
}

/// Rail nodes sampled per rail and direction where the contacts carry no
/// static correction ([`measure_without_correction`]): one G a node costs
/// a sparse solve, so a long model's 2,591 nodes a rail (the 30-span
/// viaduct of `vbi generate viaduct`) are sampled evenly, every node within
/// [`END_NODES`] of a rail's ends included (a free rail end is where the
/// track is most flexible).
pub const SAMPLED_NODES: usize = 256;

/// Nodes at each end of the rails always sampled.
pub const END_NODES: usize = 8;

/// [`sample_points`] on at most [`SAMPLED_NODES`] rail nodes evenly spaced
/// by index, plus the [`END_NODES`] at each end. Whether every node is in.
pub fn sampled_points(
    modal: &ModalBridge,
    rails: usize,
    lateral: bool,
) -> (Vec<ContactPoint>, bool) {
    let xs = modal.node_x();
    let stride = xs.len().div_ceil(SAMPLED_NODES).max(1);
    let last = xs.len().saturating_sub(1);
    let kept = |i: &usize| i.is_multiple_of(stride) || *i < END_NODES || last - i < END_NODES;
    let every = (0..xs.len()).all(|i| kept(&i));
    let sampled = (0..xs.len()).filter(kept).map(|i| xs[i]);
    (points_at(sampled, rails, lateral), every)
}

/// Measures what the kept modes of an imported track whose contacts carry
/// no static correction leave out of the rails' static flexibility under
/// a wheel (G by sparse solves at [`sampled_points`]) into
/// `modal.rails_flexibility`, and says it in the selection. There the
/// share left out is not a massless spring but missing: the wheels ride on
/// rails stiffer than the model's by it (recorded displacements still get
/// their static share, [`crate::record`], when `modes.static_correction` is
/// on), and the wheels' bounce on the track it stands for is not modelled.
/// Measured on the 30-span viaduct (scenarios/full-scale, 148 modes to
/// 15 Hz): against modes to 30 Hz at
/// half the step the deck displacements are within 0.8 %, the rail's
/// vertical displacement 17 % and the deck accelerations 21–36 % off
/// (BENCHMARKS.md). The automatic choice does not grow the modes here: at
/// this size the modes that carry the rails' flexibility (the rail-on-pad
/// band, near 2 kHz) number in the tens of thousands; the run warns
/// instead ([`crate::report::advice`]).
pub(super) fn measure_without_correction(
    modal: &mut ModalBridge,
    bridge: &Bridge,
    lateral_mass: bool,
) -> Result<(), crate::bridge::BridgeError> {
    let (points, every_node) = sampled_points(modal, rails_of(bridge), lateral_mass);
    let Some(flexibility) = modal.track_flexibility_at(&points) else {
        return Ok(());
    };
    let flexibility = flexibility?;
    let shares = shares_of(modal, &points, &flexibility);
    let Some(&left_out) = shares.last() else {
        return Ok(());
    };
    let typical_left_out = typical_share(modal, &points, &flexibility);
    modal.rails_flexibility = Some(RailsFlexibility {
        left_out,
        typical_left_out,
        points: points.len(),
        every_node,
        static_correction: false,
        limited: false,
    });
    let why = if modal.static_correction {
        format!(
            "on a model of over {} DOFs the contacts get no static correction",
            crate::bridge::CONTACT_CORRECTION_DOFS
        )
    } else {
        "`modes.static_correction` is off".to_string()
    };
    modal.selection.push_str(&format!(
        "; at a typical rail point they carry {:.1} % of the rails' static flexibility under \
         a wheel (the automatic rule's ρ, the largest share left out against the most \
         flexible point: {}{:.1} %; {} rail points{}), and {why}: the wheels ride on rails \
         stiffer than the model's by the share left out",
        100.0 * (1.0 - typical_left_out),
        if every_node { "" } else { "at least " },
        100.0 * left_out,
        points.len(),
        if every_node { "" } else { " sampled" },
    ));
    Ok(())
}

/// The residual share left by the lowest N kept modes, for every N from 1
/// to the modes kept: ρ(N) = max over directions of max_c R_N(c, c) /
/// max_c G(c, c) (the module's rule). `None` when the contacts carry no
/// static correction ([`ModalBridge::static_flexibility`]). Cost
/// O(points × modes).
pub fn residual_shares(modal: &ModalBridge, points: &[ContactPoint]) -> Option<Vec<f64>> {
    let flexibility = points
        .iter()
        .map(|&point| modal.static_flexibility(point, point))
        .collect::<Option<Vec<f64>>>()?;
    Some(shares_of(modal, points, &flexibility))
}

/// ρ(N) for every N from 1 to the modes kept, from the full model's
/// static flexibility G(c, c) at each point (`flexibility[i]` at
/// `points[i]`, m/N). Cost O(points × modes).
pub fn shares_of(modal: &ModalBridge, points: &[ContactPoint], flexibility: &[f64]) -> Vec<f64> {
    let modes = modal.mode_count();
    let omega = &modal.circular_frequencies;
    let mut shares = vec![0.0f64; modes];
    let mut values = vec![0.0; modes];
    for direction in [ContactDirection::Vertical, ContactDirection::Lateral] {
        let mut largest_residual = vec![0.0f64; modes];
        let mut largest_flexibility = 0.0f64;
        for (&point, &full) in points.iter().zip(flexibility) {
            if point.0 != direction {
                continue;
            }
            largest_flexibility = largest_flexibility.max(full);
            modal.contact_mode_values_in(direction, point.1, point.2, &mut values);
            let mut residual = full;
            for ((largest, value), w) in largest_residual.iter_mut().zip(&values).zip(omega) {
                residual -= value * value / (w * w);
                *largest = largest.max(residual);
            }
        }
        if largest_flexibility > 0.0 {
            for (share, residual) in shares.iter_mut().zip(&largest_residual) {
                *share = share.max(residual / largest_flexibility);
            }
        }
    }
    shares
}

/// The median over the points of R(c, c) / G(c, c) at every kept mode
/// (points where G vanishes left out): the share a wheel meets at a
/// typical rail point ([`RailsFlexibility::typical_left_out`]). Cost
/// O(points × modes).
pub fn typical_share(modal: &ModalBridge, points: &[ContactPoint], flexibility: &[f64]) -> f64 {
    let mut values = vec![0.0; modal.mode_count()];
    let mut shares: Vec<f64> = points
        .iter()
        .zip(flexibility)
        .filter(|&(_, &full)| full > 0.0)
        .map(|(&point, &full)| {
            modal.contact_mode_values_in(point.0, point.1, point.2, &mut values);
            let modal_part: f64 = values
                .iter()
                .zip(&modal.circular_frequencies)
                .map(|(value, w)| value * value / (w * w))
                .sum();
            ((full - modal_part) / full).clamp(0.0, 1.0)
        })
        .collect();
    if shares.is_empty() {
        return 0.0;
    }
    shares.sort_by(f64::total_cmp);
    shares[shares.len() / 2]
}

/// The fewest of the kept modes whose residual share is at most
/// [`TRACK_RESIDUAL_SHARE`]; `None` when even all of them leave more.
pub fn modes_needed(shares: &[f64]) -> Option<usize> {
    shares
        .iter()
        .position(|&share| share <= TRACK_RESIDUAL_SHARE)
        .map(|i| i + 1)
}

/// Grows the automatic modes `modal` of an imported track until the modes
/// left out carry at most [`TRACK_RESIDUAL_SHARE`] of the rails' static
/// flexibility under a wheel (doubling, within the limits on modes and on
/// the eigen solve's work), then keeps the lowest that do; the selection
/// says what they carry. `lateral_mass`: the wheels also hold the track
/// sideways. `None` after an error reported to `ck`.
pub(super) fn keep_rails_flexibility(
    mut modal: ModalBridge,
    bridge: &Bridge,
    lateral_mass: bool,
    budget: &Budget,
    ck: &mut Checker<'_>,
    build: &dyn Fn(ModeRequest) -> Result<ModalBridge, (&'static str, String)>,
) -> Option<ModalBridge> {
    let points = sample_points(&modal, rails_of(bridge), lateral_mass);
    let available = ModalBridge::available_of(bridge);
    let modal_floor = modal.mode_count();
    let modal_selection = modal.selection.clone();
    let prepared = |mut m: ModalBridge| -> Result<ModalBridge, (&'static str, String)> {
        m.prepare_contact_correction()
            .map_err(|e| ("bridge", e.to_string()))?;
        Ok(m)
    };
    let mut checked = match prepared(modal) {
        Ok(m) => m,
        Err((path, message)) => {
            ck.error(path, message);
            return None;
        }
    };
    let mut share = None;
    let mut limited = false;
    while let Some(shares) = residual_shares(&checked, &points) {
        let count = checked.mode_count();
        if let Some(needed) = modes_needed(&shares) {
            // The lowest `needed` of a larger set: solve for them
            // alone (the other rules asked for no more than before).
            if needed < count && needed > modal_floor {
                checked = match build(ModeRequest::Lowest(needed)).and_then(prepared) {
                    Ok(m) => m,
                    Err((path, message)) => {
                        ck.error(path, message);
                        return None;
                    }
                };
            }
            share = Some(shares[checked.mode_count() - 1]);
            break;
        }
        // Every mode kept leaves no residual: met above, but round-off
        // must not loop.
        if count >= available {
            share = shares.last().copied();
            break;
        }
        // Twice as many, or as many as the limits on modes and on
        // the eigen solve's work (DOFs × modes²) allow: beyond them
        // the choice keeps what it has and says what they carry.
        let dofs = available as f64;
        let fitting = |n: usize| {
            budget.refusal("modes", "", n as f64).is_none()
                && budget
                    .refusal("eigen_work", "", dofs * (n as f64).powi(2))
                    .is_none()
        };
        let mut more = (2 * count).min(available);
        if !fitting(more) {
            let by_work = (budget.limit_of("eigen_work") / dofs).sqrt().floor() as usize;
            more = more.min(by_work).min(budget.limit_of("modes") as usize);
        }
        if more <= count || !fitting(more) {
            share = shares.last().copied();
            limited = true;
            break;
        }
        checked = match build(ModeRequest::Lowest(more)).and_then(prepared) {
            Ok(m) => m,
            Err((path, message)) => {
                ck.error(path, message);
                return None;
            }
        };
    }
    let grown = checked.mode_count() > modal_floor;
    checked.selection = modal_selection;
    modal = checked;
    if let Some(share) = share {
        let flexibility: Vec<f64> = points
            .iter()
            .map(|&point| modal.static_flexibility(point, point).unwrap_or(0.0))
            .collect();
        modal.rails_flexibility = Some(RailsFlexibility {
            left_out: share,
            typical_left_out: typical_share(&modal, &points, &flexibility),
            points: points.len(),
            every_node: true,
            static_correction: true,
            limited,
        });
        if limited {
            modal.selection = format!(
                "automatic: {} modes up to {:.2} Hz, as many as the limits allow (`limits.modes`, \
                 `limits.eigen_work`); they carry {:.1} % of the rails' static flexibility under \
                 a wheel, short of the {:.1} % the automatic choice aims at (the modes left \
                 out ride the wheels' mass as a massless spring): the contact forces and the rail \
                 and deck accelerations are not converged",
                modal.mode_count(),
                modal.frequencies().last().copied().unwrap_or(0.0),
                100.0 * (1.0 - share),
                100.0 * (1.0 - TRACK_RESIDUAL_SHARE)
            );
        } else if grown {
            modal.selection = format!(
                "automatic: {} modes up to {:.2} Hz, so that they carry {:.1} % of the \
                 rails' static flexibility under a wheel (at least {:.1} %: the modes \
                 left out ride the wheels' mass as a massless spring)",
                modal.mode_count(),
                modal.frequencies().last().copied().unwrap_or(0.0),
                100.0 * (1.0 - share),
                100.0 * (1.0 - TRACK_RESIDUAL_SHARE)
            );
        } else {
            modal.selection.push_str(&format!(
                "; they carry {:.1} % of the rails' static flexibility under a wheel",
                100.0 * (1.0 - share)
            ));
        }
    }
    Some(modal)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fewest_modes_meeting_the_share_are_counted_from_one() {
        assert_eq!(modes_needed(&[0.5, 0.1, 0.004, 0.001]), Some(3));
        assert_eq!(modes_needed(&[0.5, 0.1]), None);
        assert_eq!(modes_needed(&[0.0]), Some(1));
    }
}
