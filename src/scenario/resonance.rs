//! Resolving a resonance check: trains, speeds, deck and filter checked,
//! every default filled in.

use super::checker::Checker;
use super::raw::{self, km_h_to_m_s};
use super::resonance_grid::additional_damping_percent;
use super::vehicles::MAX_SPEED;
use crate::scene::{AdditionalDamping, Bridge, ResonanceCheck, ResonanceSpeeds, Vehicle};
use crate::scene::{Deck, HslmModel};

/// Most speeds per train (a count from the input, checked before the grid
/// is built).
pub const MAX_RESONANCE_SPEEDS: usize = 10_000;

/// EN 1991-2 6.4.6.2(1): speeds from 40 m/s.
pub const DEFAULT_LOWEST_SPEED: f64 = 40.0;
/// EN 1991-2 6.4.6.2(1): speeds up to 1.2 × the line speed.
pub const DEFAULT_TOP_SPEED_FACTOR: f64 = 1.2;
/// The default speed step, km/h (EN 1991-2 6.4.6.2 asks for smaller steps
/// near resonance: the check refines there).
pub const DEFAULT_SPEED_STEP_KM_H: f64 = 5.0;

/// `first_frequency`: the bridge's f₁, Hz; `default_filter`: the deck
/// acceleration's cut-off, Hz, where the check gives none (the planning
/// stage's EN 1990 filter, from the bridge's own modes).
pub(crate) fn resolve_resonance(
    raw: &raw::ResonanceCheckRaw,
    bridge: &Bridge,
    first_frequency: f64,
    default_filter: f64,
    ck: &mut Checker<'_>,
) -> ResonanceCheck {
    if matches!(bridge, Bridge::Plate(_)) {
        ck.error(
            "study",
            "a resonance check is computed on beam bridges only (it envelopes the deck along \
             its length)",
        );
    }
    let trains = raw
        .trains
        .clone()
        .unwrap_or_else(|| HslmModel::ALL.to_vec());
    if trains.is_empty() {
        ck.error(
            "study.trains",
            "list at least one train, or leave `trains` out for all ten",
        );
    }
    for (i, t) in trains.iter().enumerate() {
        if trains[..i].contains(t) {
            ck.error(
                &format!("study.trains[{i}]"),
                format!("{} is listed twice", t.label()),
            );
        }
    }
    let line_speed = raw.line_speed.meters_per_second();
    let speed_ok = |ck: &mut Checker<'_>, at: &str, v: f64| {
        let fine = v.is_finite() && v > 0.0 && v <= MAX_SPEED;
        if !fine {
            ck.error(
                at,
                format!("a speed must be positive and at most {MAX_SPEED} m/s, got {v} m/s"),
            );
        }
        fine
    };
    let line_fine = speed_ok(ck, "study.line_speed", line_speed);
    let given = raw.speeds.as_ref();
    let from = given
        .and_then(|s| s.from)
        .map_or(DEFAULT_LOWEST_SPEED, |v| v.meters_per_second());
    let to = given
        .and_then(|s| s.to)
        .map_or(DEFAULT_TOP_SPEED_FACTOR * line_speed, |v| {
            v.meters_per_second()
        });
    let step = given
        .and_then(|s| s.step)
        .map_or(km_h_to_m_s(DEFAULT_SPEED_STEP_KM_H), |v| {
            v.meters_per_second()
        });
    let fine = speed_ok(ck, "study.speeds.from", from)
        & speed_ok(ck, "study.speeds.to", to)
        & speed_ok(ck, "study.speeds.step", step);
    let speeds = ResonanceSpeeds { from, to, step };
    if fine {
        if to < from {
            ck.error(
                "study.speeds",
                format!("the highest speed {to} m/s is below the lowest {from} m/s"),
            );
        } else if (to - from) / step >= MAX_RESONANCE_SPEEDS as f64 {
            ck.error(
                "study.speeds.step",
                format!(
                    "{from} to {to} m/s in steps of {step} m/s are more than \
                     {MAX_RESONANCE_SPEEDS} speeds; take a larger step"
                ),
            );
        }
    }
    let max_frequency = match raw.max_frequency {
        Some(f) if !(f.is_finite() && f > 0.0) => {
            ck.error(
                "study.max_frequency",
                format!("the acceleration cut-off must be a positive frequency in Hz, got {f}"),
            );
            f64::NAN
        }
        Some(f) => f,
        None => default_filter,
    };
    let additional_damping = if raw.additional_damping == Some(true) {
        match bridge.spans() {
            [span] => Some(AdditionalDamping {
                span: *span,
                ratio: additional_damping_percent(*span) / 100.0,
            }),
            spans => {
                ck.error(
                    "study.additional_damping",
                    format!(
                        "the additional damping of EN 1991-2 6.4.6.3.1(3) is given for a \
                         single span (Figure 6.15, L the span length); this bridge has {} spans",
                        spans.len()
                    ),
                );
                None
            }
        }
    } else {
        None
    };
    let check = ResonanceCheck {
        trains,
        line_speed,
        speeds,
        deck: raw.deck.unwrap_or(Deck::Ballasted),
        max_frequency,
        first_frequency,
        additional_damping,
    };
    if line_fine && fine && to >= from && (to - from) / step < MAX_RESONANCE_SPEEDS as f64 {
        // Resonance speeds f₀·D/k crowd at low speeds on a stiff deck:
        // count them before any grid is built.
        let resonances: usize = (0..check.trains.len())
            .map(|t| check.resonance_count(t))
            .sum();
        if resonances >= MAX_RESONANCE_SPEEDS {
            ck.error(
                "study.speeds.from",
                format!(
                    "the trains have {resonances} resonance speeds f₀·D/k between {from} m/s \
                     and the top speed (f₀ = {} Hz), more than {MAX_RESONANCE_SPEEDS}; start higher",
                    check.first_frequency
                ),
            );
        }
    }
    check
}

/// The vehicle of one run: `train` alone at `speed` (m/s), its front axle
/// entering at t = 0.
pub fn train_vehicle(train: HslmModel, speed: f64) -> Vehicle {
    let raw = train.train();
    let positions = raw.axle_positions();
    Vehicle::MovingForce(crate::scene::MovingForce {
        loads: vec![raw.axle_force; positions.len()],
        axle_spacings: positions.windows(2).map(|w| w[1] - w[0]).collect(),
        speed,
        entry_time: 0.0,
        lateral_position: None,
        acceleration: 0.0,
    })
}
