//! Plausibility of every point of a study whose vehicles derive from the
//! bridge's first frequency (a separation map).

use crate::bridge::ModalBridge;
use crate::scenario::checker::Checker;
use crate::scenario::plausible::*;
use crate::scene::{Bridge, Contact, Study, Vehicle};

/// Checks every point of a study: a separation map derives the oscillator
/// (and a contact stiffness given as a ratio) at each grid point, and its
/// speed, masses and stiffness are monotonic in the two swept ratios, so
/// the grid's four corners bound every point.
pub(crate) fn check_study(
    ck: &mut Checker<'_>,
    study: &Study,
    vehicles: &[Vehicle],
    contact: &Contact,
    modal: &ModalBridge,
    bridge: &Bridge,
) {
    let Study::SeparationMap {
        velocity_ratio,
        mass_ratio,
    } = study
    else {
        // A speed sweep's speeds are checked against the speed limit where
        // the sweep is resolved; its other values are the scene's own.
        return;
    };
    let Some(Vehicle::Oscillator(o)) = vehicles.first() else {
        return;
    };
    let Some(groups) = o.dimensionless else {
        return;
    };
    let Some(&f1) = modal.frequencies().first() else {
        return;
    };
    let (v_lo, v_hi) = (
        velocity_ratio.from.min(velocity_ratio.to),
        velocity_ratio.from.max(velocity_ratio.to),
    );
    let (m_lo, m_hi) = (
        mass_ratio.from.min(mass_ratio.to),
        mass_ratio.from.max(mass_ratio.to),
    );
    for (v, m, vpath, mpath) in [
        (
            v_lo,
            m_lo,
            "study.velocity_ratio.from",
            "study.mass_ratio.from",
        ),
        (v_hi, m_hi, "study.velocity_ratio.to", "study.mass_ratio.to"),
    ] {
        let mut point = groups;
        point.velocity_ratio = v;
        point.mass_ratio = m;
        let derived = point.derive(f1, modal.length, bridge.mass_per_length(), 0.0);
        let speed = derived.speed;
        if !(speed > 0.0 && speed <= crate::scenario::vehicles::MAX_SPEED) {
            ck.error(
                vpath,
                format!(
                    "the study's velocity ratio {v} gives a speed of {} m/s (2 × ratio × f1 × L with f1 = {f1:.4} Hz, L = {} m), outside 0 to {} m/s",
                    number(speed),
                    modal.length,
                    crate::scenario::vehicles::MAX_SPEED
                ),
            );
        }
        let sub = ck.diagnostics.len();
        within(
            ck,
            mpath,
            "the study's derived sprung mass",
            derived.sprung_mass,
            MASS,
            "kg",
        );
        within(
            ck,
            mpath,
            "the study's derived suspension stiffness",
            derived.stiffness,
            STIFFNESS,
            "N/m",
        );
        if let Contact::Elastic {
            stiffness_ratio: Some(ratio),
            ..
        } = contact
        {
            within(
                ck,
                mpath,
                "the study's derived contact stiffness",
                ratio * derived.stiffness,
                STIFFNESS,
                "N/m",
            );
        }
        // One message per corner is enough.
        ck.diagnostics.truncate(sub + 1);
    }
}
