//! Resolving `envelopes:`: the quantities and points checked against the
//! bridge, every default filled in.

use super::checker::Checker;
use super::raw;
use super::records::quantity_name_of;
use crate::scene::Quantity;
use crate::scene::{Bridge, Envelopes};

/// Most envelope points: each keeps two influence lines over the mesh and
/// a few mode vectors, so their memory grows as points × (nodes + modes).
pub const MAX_ENVELOPE_POINTS: usize = 2_000;

/// The quantities an envelope may hold, in the default order.
pub const ENVELOPE_QUANTITIES: [Quantity; 4] = [
    Quantity::BridgeDisplacement,
    Quantity::BridgeMoment,
    Quantity::BridgeShear,
    Quantity::BridgeAcceleration,
];

/// The highest mode frequency the acceleration envelope sums, Hz (`None`
/// without one): its own `max_frequency`, else `default_filter` (the
/// planning stage's); what the automatic mode choice must keep.
pub(crate) fn acceleration_cut(
    raw: Option<&raw::EnvelopesRaw>,
    default_filter: f64,
) -> Option<f64> {
    let raw = raw?;
    let quantities = raw.quantities.as_deref().unwrap_or(&ENVELOPE_QUANTITIES);
    quantities.contains(&Quantity::BridgeAcceleration).then(|| {
        raw.max_frequency
            .filter(|f| f.is_finite() && *f > 0.0)
            .unwrap_or(default_filter)
    })
}

/// `default_filter`: the acceleration envelope's cut-off, Hz, where it
/// gives none (as for [`super::records::resolve_records`]).
pub(crate) fn resolve_envelopes(
    raw: Option<&raw::EnvelopesRaw>,
    default_filter: Option<f64>,
    bridge: &Bridge,
    ck: &mut Checker<'_>,
) -> Option<Envelopes> {
    let raw = raw?;
    if matches!(bridge, Bridge::Plate(_)) {
        ck.error(
            "envelopes",
            "envelopes along the deck are computed for beam bridges only; on a plate deck \
             record the points of interest with `record`",
        );
    }
    let quantities = raw
        .quantities
        .clone()
        .unwrap_or_else(|| ENVELOPE_QUANTITIES.to_vec());
    if quantities.is_empty() {
        ck.error(
            "envelopes.quantities",
            "list at least one quantity, or leave `quantities` out for all four",
        );
    }
    for (i, q) in quantities.iter().enumerate() {
        let at = format!("envelopes.quantities[{i}]");
        if !ENVELOPE_QUANTITIES.contains(q) {
            ck.error(
                &at,
                format!(
                    "`{}` has no envelope along the deck; expected one of bridge_displacement, \
                     bridge_moment, bridge_shear, bridge_acceleration",
                    quantity_name_of(*q)
                ),
            );
        } else if quantities[..i].contains(q) {
            ck.error(&at, format!("`{}` is listed twice", quantity_name_of(*q)));
        }
    }
    match raw.points {
        Some(n) if n < 2 => ck.error(
            "envelopes.points",
            format!("an envelope needs at least 2 points (both deck ends), got {n}"),
        ),
        Some(n) if n > MAX_ENVELOPE_POINTS => ck.error(
            "envelopes.points",
            format!(
                "{n} envelope points are more than the {MAX_ENVELOPE_POINTS} this build keeps \
                 (each holds influence lines over the whole mesh); use fewer"
            ),
        ),
        _ => {}
    }
    if let Bridge::Beam(beam) = bridge {
        let nodes = beam.elements().saturating_add(1);
        if raw.points.is_none() && nodes > MAX_ENVELOPE_POINTS {
            ck.error(
                "envelopes",
                format!(
                    "the mesh has {nodes} nodes, more than the {MAX_ENVELOPE_POINTS} envelope \
                     points this build keeps; give `points:` (evenly spaced) instead"
                ),
            );
        }
    }
    let max_frequency = if quantities.contains(&Quantity::BridgeAcceleration) {
        match raw.max_frequency {
            Some(f) if !(f.is_finite() && f > 0.0) => {
                ck.error(
                    "envelopes.max_frequency",
                    format!("the acceleration cut-off must be a positive frequency in Hz, got {f}"),
                );
                None
            }
            Some(f) => Some(f),
            None => default_filter,
        }
    } else {
        if raw.max_frequency.is_some() {
            ck.error(
                "envelopes.max_frequency",
                "`max_frequency` filters the acceleration envelope, which is not asked for",
            );
        }
        None
    };
    Some(Envelopes {
        quantities,
        points: raw.points,
        max_frequency,
    })
}
