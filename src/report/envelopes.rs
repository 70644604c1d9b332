//! `envelopes.csv`: the envelope of each quantity along the deck
//! ([`crate::record::envelope`]) as a table.

use super::number;
use crate::record::envelope::{Envelope, Extremes};
use crate::scenario::quantity_name_of;

/// `envelopes.csv`: one row per point, for each quantity its max and min
/// with time and lead-vehicle position, units in the header.
pub fn envelope_csv(envelope: &Envelope) -> String {
    let mut out = String::from("x [m]");
    for column in &envelope.columns {
        let name = quantity_name_of(column.quantity);
        let unit = column.unit;
        for side in ["max", "min"] {
            out.push_str(&format!(
                ",{},{name}_{side}_time [s],{name}_{side}_position [m]",
                super::heading(&format!("{name}_{side}"), unit)
            ));
        }
    }
    out.push('\n');
    for (p, x) in envelope.x.iter().enumerate() {
        out.push_str(&number(*x));
        for column in &envelope.columns {
            let e = column
                .extremes
                .get(p)
                .copied()
                .unwrap_or(Extremes::new(0.0, 0.0, 0.0));
            for value in [
                e.max,
                e.max_time,
                e.max_position,
                e.min,
                e.min_time,
                e.min_position,
            ] {
                out.push(',');
                out.push_str(&number(value));
            }
        }
        out.push('\n');
    }
    out
}
