//! The small parameter of EMBS per contact direction (EMBS paper,
//! Section 2: ε = Ω = ω_p/ω_B, "the frequency ratio of the primary
//! suspension system of the vehicle with respect to the fundamental
//! frequency of the bridge").
//!
//! The expansion is about the bridge's motion *at the contacts*: the group
//! m_w⁻¹ k_w of Eq. 4 is compared with the bridge's own W_Bᵀ m_B⁻¹ k_B. A
//! bridge mode that does not move the rails in a direction (a deck sliding
//! on its bearings, a pier swaying under a rigid track) does not set the
//! scale of that direction. So ω_B,dir is the lowest kept mode whose share
//! of the contact points' static flexibility in that direction is at least
//! [`FLEXIBILITY_SHARE`]:
//!
//!   s_i = Σ_p φ_i(p)²/ω_i² / Σ_j Σ_p φ_j(p)²/ω_j²,
//!
//! p over the contact lines of that direction (each vertical wheel on its
//! rail, the lateral wheels on the track) at every mesh node along the
//! deck, φ_i(p) the mode's displacement there in that direction (unit
//! modal mass): Σ_i φ_i(p)²/ω_i² is the static flexibility at p of the
//! kept modes (m/N), and s_i the part of it mode i carries.
//!
//! ω_p is given two ways: the wheelset on its primary suspension,
//! √(k_w/m_w) of a contact DOF (the group m_w⁻¹ k_w of Eq. 4, the one the
//! expansion is in, and ε), and the sprung mass per wheel on the same
//! springs, √(k_w/m_s) (m_s the static suspension force on the wheel over
//! g; laterally the vehicle's sprung mass over its lateral contacts).

use crate::contact::ContactDirection;
use crate::model::Model;
use crate::vehicle::WheelKind;

/// A mode sets ω_B,dir when it carries at least this share of the contact
/// points' static flexibility in that direction (dimensionless). At the
/// rails most of that flexibility is the track's own (rails on pads and
/// ballast), spread over hundreds of local modes, so a span's bending
/// carries a few per cent only: on scenarios/viaduct-2span (modes to
/// 80 Hz) the 11.54 Hz vertical bending carries 2.9 % vertically and the
/// 5.56 Hz sway 2.2 % laterally, while the 2.03 Hz longitudinal mode
/// carries 3e-5 and 2e-33, and no mode below them more than 0.19 %
/// (tests/embs.rs).
pub const FLEXIBILITY_SHARE: f64 = 0.01;

/// The small parameter of one contact direction.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionalScale {
    /// The contact direction.
    pub direction: ContactDirection,
    /// ε = ω_p/ω_B,dir with ω_p the wheelset on its primary suspension
    /// (dimensionless).
    pub epsilon: f64,
    /// The same with ω_p the sprung mass per wheel on the primary
    /// suspension (dimensionless).
    pub epsilon_sprung: f64,
    /// Highest wheelset frequency on the primary suspension, √(k_w/m_w)/2π
    /// over the contact DOFs in this direction, Hz.
    pub wheelset_frequency: f64,
    /// Highest frequency of the sprung mass per wheel on the primary
    /// suspension, √(k_w/m_s)/2π, Hz.
    pub sprung_frequency: f64,
    /// The bridge mode setting ω_B,dir, numbered from 1 among the kept modes.
    pub bridge_mode: usize,
    /// Its frequency ω_B,dir/2π, Hz.
    pub bridge_frequency: f64,
    /// Its share of the contact points' static flexibility (dimensionless).
    pub flexibility_share: f64,
    /// The lowest kept mode's frequency, Hz, and its share of the same
    /// flexibility (dimensionless): what ε would be divided by if the
    /// direction were ignored.
    pub lowest_mode: (f64, f64),
}

/// Each kept mode's share of the static flexibility of the contact points
/// in `direction`, at every mesh node on the deck along each contact line
/// `ys` (m across; ignored laterally, where a wheelset follows the track).
/// All zeros when the bridge does not move that way.
pub fn flexibility_shares(model: &Model, direction: ContactDirection, ys: &[f64]) -> Vec<f64> {
    let bridge = &model.bridge;
    let n = bridge.mode_count();
    let mut share = vec![0.0; n];
    let mut values = vec![0.0; n];
    for &x in bridge.node_x().iter().filter(|&&x| bridge.is_on(x)) {
        for &y in ys {
            bridge.mode_values_in(direction, x, y, &mut values);
            for ((s, v), w) in share
                .iter_mut()
                .zip(&values)
                .zip(&bridge.circular_frequencies)
            {
                *s += v * v / (w * w);
            }
        }
    }
    let total: f64 = share.iter().sum();
    if total > 0.0 {
        share.iter_mut().for_each(|s| *s /= total);
    }
    share
}

/// The small parameter in `direction`: `None` where no vehicle has a
/// contact DOF in it, or no kept mode moves its contacts.
pub fn directional_scale(model: &Model, direction: ContactDirection) -> Option<DirectionalScale> {
    let (mut wheelset, mut sprung) = (0.0f64, 0.0f64);
    let mut ys: Vec<f64> = Vec::new();
    for (w, r) in model.wheels.iter().enumerate() {
        let vehicle = &model.vehicles[r.vehicle];
        let wheel = &vehicle.wheels[r.wheel];
        let WheelKind::Dof(d) = wheel.kind else {
            continue;
        };
        if wheel.direction != direction || vehicle.mass[(d, d)] <= 0.0 {
            continue;
        }
        let k = vehicle.stiffness[(d, d)];
        wheelset = wheelset.max((k / vehicle.mass[(d, d)]).sqrt());
        let sprung_mass = match direction {
            // The suspension's static force on the wheel over g.
            ContactDirection::Vertical => {
                (model.static_wheel_loads[w] + vehicle.gravity_load[d]) / model.gravity
            }
            // The vehicle's sprung mass shared by its lateral contacts.
            ContactDirection::Lateral => {
                let of_vehicle = |dir| {
                    model
                        .wheels
                        .iter()
                        .enumerate()
                        .filter(|(_, s)| s.vehicle == r.vehicle)
                        .filter_map(|(v, s)| {
                            let wheel = &vehicle.wheels[s.wheel];
                            match wheel.kind {
                                WheelKind::Dof(e) if wheel.direction == dir => Some((v, e)),
                                _ => None,
                            }
                        })
                        .collect::<Vec<_>>()
                };
                let vertical: f64 = of_vehicle(ContactDirection::Vertical)
                    .iter()
                    .map(|&(v, e)| {
                        (model.static_wheel_loads[v] + vehicle.gravity_load[e]) / model.gravity
                    })
                    .sum();
                vertical / of_vehicle(ContactDirection::Lateral).len() as f64
            }
        };
        if sprung_mass > 0.0 {
            sprung = sprung.max((k / sprung_mass).sqrt());
        }
        let y = vehicle.path_y + wheel.lateral;
        if !ys.contains(&y) {
            ys.push(y);
        }
    }
    if wheelset == 0.0 {
        return None;
    }
    if direction == ContactDirection::Lateral {
        ys = vec![0.0];
    }
    let shares = flexibility_shares(model, direction, &ys);
    let mode = shares.iter().position(|&s| s >= FLEXIBILITY_SHARE)?;
    let omega = model.bridge.circular_frequencies[mode];
    let hz = std::f64::consts::TAU.recip();
    Some(DirectionalScale {
        direction,
        epsilon: wheelset / omega,
        epsilon_sprung: sprung / omega,
        wheelset_frequency: wheelset * hz,
        sprung_frequency: sprung * hz,
        bridge_mode: mode + 1,
        bridge_frequency: omega * hz,
        flexibility_share: shares[mode],
        lowest_mode: (model.bridge.circular_frequencies[0] * hz, shares[0]),
    })
}

/// Above this ε in a direction the expansion in powers of ε cannot
/// converge (the wheelset on its primary suspension is faster than every
/// bridge mode that moves the contacts that way), and a run recording
/// quantities of that direction is refused unless it is compared with
/// `coupled` or the scene overrides (`solver.allow_large_epsilon`).
pub const DIVERGENT_EPSILON: f64 = 1.0;

/// The contact direction whose dynamics a recorded quantity shows: a
/// bridge record by its DOF direction (uz, ry vertical; uy, rx, rz
/// lateral; ux neither), a vehicle DOF by its name (lateral, yaw and roll
/// DOFs lateral, the rest vertical), a contact quantity by its wheel's
/// direction. `None` for a quantity of neither.
pub fn record_direction(model: &Model, record: &crate::scene::Record) -> Option<ContactDirection> {
    use crate::scene::Quantity;
    use crate::scene::imported::Direction;
    match record.quantity {
        Quantity::BridgeDisplacement | Quantity::BridgeAcceleration => {
            match record.direction.unwrap_or_default() {
                Direction::Uz | Direction::Ry => Some(ContactDirection::Vertical),
                Direction::Uy | Direction::Rx | Direction::Rz => Some(ContactDirection::Lateral),
                Direction::Ux => None,
            }
        }
        Quantity::BridgeMoment | Quantity::BridgeShear | Quantity::BridgeReaction => {
            Some(ContactDirection::Vertical)
        }
        Quantity::VehicleDisplacement | Quantity::VehicleAcceleration => {
            let name = record.dof.as_deref().unwrap_or("");
            if ["lateral", "yaw", "roll"].iter().any(|k| name.contains(k)) {
                Some(ContactDirection::Lateral)
            } else {
                Some(ContactDirection::Vertical)
            }
        }
        Quantity::ContactForce | Quantity::ContactGap => {
            let vehicle = record.vehicle.unwrap_or(1).checked_sub(1)?;
            let wheel = record.wheel.unwrap_or(1).checked_sub(1)?;
            let index = model.wheel_index(vehicle, wheel)?;
            let r = model.wheels[index];
            Some(model.vehicles[r.vehicle].wheels[r.wheel].direction)
        }
    }
}

/// Why an EMBS run of `model` recording `records` is refused: a direction
/// with ε ≥ [`DIVERGENT_EPSILON`] whose quantities are recorded, without
/// `compare` or `allow_large_epsilon`. `None` when it may run.
pub fn refusal(model: &Model, records: &[crate::scene::Record]) -> Option<String> {
    let options = model.embs?;
    if options.compare || options.allow_large_epsilon {
        return None;
    }
    [ContactDirection::Vertical, ContactDirection::Lateral]
        .into_iter()
        .filter_map(|d| directional_scale(model, d))
        .filter(|s| s.epsilon >= DIVERGENT_EPSILON)
        .find_map(|s| {
            let recorded: Vec<&str> = records
                .iter()
                .filter(|r| record_direction(model, r) == Some(s.direction))
                .map(|r| r.name.as_str())
                .collect();
            (!recorded.is_empty()).then(|| {
                format!(
                    "`method: embs` cannot represent the {dir} dynamics of this scene: \
                     ε = ω_p/ω_B = {eps:.3} ≥ {DIVERGENT_EPSILON} {dir}ly (the wheelset on its \
                     primary suspension at {fw:.2} Hz against bridge mode {mode} at {fb:.2} Hz, \
                     the lowest carrying ≥ {share:.0} % of the contacts' {dir} static \
                     flexibility), so the expansion in ε does not converge, and {names} \
                     record{s} {dir} quantities; use `method: coupled`, or set \
                     `solver.compare: true` to see EMBS against it, or \
                     `solver.allow_large_epsilon: true` to run it anyway",
                    dir = s.direction.name(),
                    eps = s.epsilon,
                    fw = s.wheelset_frequency,
                    mode = s.bridge_mode,
                    fb = s.bridge_frequency,
                    share = 100.0 * FLEXIBILITY_SHARE,
                    names = recorded.join(", "),
                    s = if recorded.len() == 1 { "s" } else { "" },
                )
            })
        })
}
