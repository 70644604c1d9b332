//! `envelopes.csv`: the envelope of each quantity along the deck
//! ([`crate::record::envelope`]) as a table, and `envelopes.png`, the same
//! as a picture: one panel per quantity, its max and min against x, each
//! one's peak marked, the supports as dashed lines.

use std::path::Path;

use super::number;
use super::plot::{self, Marker, Panel, PlotError, Series};
use crate::record::envelope::{Envelope, Extremes};
use crate::scenario::quantity_name_of;
use crate::scene::Scenario;

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

/// `envelopes.png`: per quantity a panel with its largest and smallest value
/// at every point along the deck (`<quantity>_max`, `<quantity>_min`, as the
/// columns of `envelopes.csv`), the peak of each marked with its value and
/// position, and a dashed line at every support (the ends and the piers).
pub fn write_envelope_plot(
    path: &Path,
    scenario: &Scenario,
    envelope: &Envelope,
) -> Result<(), PlotError> {
    if envelope.columns.is_empty() || envelope.x.is_empty() {
        return Ok(());
    }
    let names: Vec<String> = envelope
        .columns
        .iter()
        .map(|c| quantity_name_of(c.quantity))
        .collect();
    let labels: Vec<[String; 2]> = names
        .iter()
        .map(|n| [format!("{n}_max"), format!("{n}_min")])
        .collect();
    let sides: Vec<[Vec<f64>; 2]> = envelope
        .columns
        .iter()
        .map(|c| {
            let side = |f: fn(&Extremes) -> f64| c.extremes.iter().map(f).collect();
            [side(|e| e.max), side(|e| e.min)]
        })
        .collect();
    let panels: Vec<Panel> = envelope
        .columns
        .iter()
        .enumerate()
        .map(|(k, c)| Panel {
            y_label: format!("{} ({})", names[k].replace('_', " "), c.unit),
            unit: c.unit.to_string(),
            series: (0..2)
                .map(|side| Series {
                    label: &labels[k][side],
                    x: &envelope.x,
                    y: &sides[k][side],
                })
                .collect(),
            references: Vec::new(),
        })
        .collect();
    let mut at = 0.0;
    let mut supports = vec![Marker {
        x: 0.0,
        label: "support".into(),
    }];
    for span in scenario.bridge.spans() {
        at += span;
        supports.push(Marker {
            x: at,
            label: "support".into(),
        });
    }
    plot::history_chart(
        path,
        &format!(
            "{}: envelopes along the deck over the crossing (o: peak)",
            scenario.name
        ),
        "position along the deck x (m)",
        &panels,
        &supports,
    )
}
