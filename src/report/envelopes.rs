//! `envelopes.csv`: the envelope of each quantity along the deck
//! ([`crate::record::envelope`]) as a table, and `envelopes.png`, the same
//! as a picture: one panel per quantity, its max and min against x, each
//! one's peak marked, the supports as dashed lines.

use std::path::Path;

use super::number;
use super::plot::{self, HistoryLayout, Marker, Panel, PlotError, Reference, Series};
use crate::record::envelope::{Envelope, EnvelopeColumn, Extremes};
use crate::scenario::quantity_name_of;
use crate::scene::{Scenario, Side};

/// `envelopes.csv`: one row per point — its x, which side of it (`left` for
/// the first of an interior support's two rows: the shear jumps there by
/// the reaction), whether it is a support — and for each quantity its max
/// and min with time and lead-vehicle position, then, where the quantity
/// has a static part, the static crossing's max and min and the point's
/// dynamic factor max|E|/max|E_static| (empty where the static envelope
/// is near zero); units in the header.
pub fn envelope_csv(envelope: &Envelope) -> String {
    let mut out = String::from("x [m],side,support");
    for column in &envelope.columns {
        let name = quantity_name_of(column.quantity);
        let unit = column.unit;
        for side in ["max", "min"] {
            out.push_str(&format!(
                ",{},{name}_{side}_time [s],{name}_{side}_position [m]",
                super::heading(&format!("{name}_{side}"), unit)
            ));
        }
        if !column.statics.is_empty() {
            for side in ["max", "min"] {
                out.push(',');
                out.push_str(&super::heading(&format!("{name}_static_{side}"), unit));
            }
            out.push_str(&format!(",{name}_daf"));
        }
    }
    out.push('\n');
    for (p, x) in envelope.x.iter().enumerate() {
        out.push_str(&number(*x));
        let side = match envelope.side.get(p) {
            Some(Side::Left) => "left",
            _ => "right",
        };
        let support = envelope.support.get(p).copied().unwrap_or(false);
        out.push_str(&format!(",{side},{}", if support { "yes" } else { "no" }));
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
            if !column.statics.is_empty() {
                let s = column
                    .statics
                    .get(p)
                    .copied()
                    .unwrap_or(Extremes::new(0.0, 0.0, 0.0));
                out.push_str(&format!(",{},{},", number(s.max), number(s.min)));
                if let Some(daf) = column.daf(p) {
                    out.push_str(&number(daf));
                }
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
    with_panels(scenario, envelope, |title, axis, panels, markers| {
        plot::history_chart(path, title, axis, panels, markers)
    })
    .map(|_| ())
}

/// Where `envelopes.png` puts its lines, peak labels, support markers and
/// legends ([`plot::history_layout`]); none without an envelope.
pub fn envelope_plot_layout(
    scenario: &Scenario,
    envelope: &Envelope,
) -> Result<Option<HistoryLayout>, PlotError> {
    with_panels(scenario, envelope, plot::history_layout)
}

/// The envelope chart's title, axis label, panels and markers handed to
/// `draw`; none drawn without an envelope.
fn with_panels<R>(
    scenario: &Scenario,
    envelope: &Envelope,
    draw: impl FnOnce(&str, &str, &[Panel], &[Marker]) -> Result<R, PlotError>,
) -> Result<Option<R>, PlotError> {
    if envelope.columns.is_empty() || envelope.x.is_empty() {
        return Ok(None);
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
    let static_labels: Vec<[String; 2]> = names
        .iter()
        .map(|n| [format!("{n}_static_max"), format!("{n}_static_min")])
        .collect();
    let statics: Vec<[Vec<f64>; 2]> = envelope
        .columns
        .iter()
        .map(|c| {
            let side = |f: fn(&Extremes) -> f64| c.statics.iter().map(f).collect();
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
            // The static crossing's envelope, dashed beside each side.
            references: if c.statics.is_empty() {
                Vec::new()
            } else {
                (0..2)
                    .map(|side| Reference {
                        of: side,
                        line: Series {
                            label: &static_labels[k][side],
                            x: &envelope.x,
                            y: &statics[k][side],
                        },
                    })
                    .collect()
            },
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
    draw(
        &format!(
            "{}: envelopes along the deck over the crossing (o: peak)",
            scenario.name
        ),
        "position along the deck x (m)",
        &panels,
        &supports,
    )
    .map(Some)
}

/// Where an envelope peaks: the value, the point and when.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PeakAt {
    /// The value, in the quantity's unit.
    pub value: f64,
    /// The point along the deck, m.
    pub x: f64,
    /// `left` at the left-hand limit of an interior support, else `right`.
    pub side: Side,
    /// Whether the point is a support.
    pub support: bool,
    /// When it occurred, s.
    pub time: f64,
    /// The lead vehicle's front-axle position then, m.
    pub lead_position: f64,
    /// The static crossing's extreme of the same sign at the same point,
    /// in the quantity's unit (none for accelerations).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_value: Option<f64>,
    /// The point's dynamic factor max|E|/max|E_static| (none where there
    /// is no static envelope or it is near zero).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub daf: Option<f64>,
}

/// The peaks of one enveloped quantity along the deck (`summary.json`'s
/// `envelope_peaks`, and the terminal's lines after a run).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EnvelopePeak {
    /// The quantity (`bridge_moment`, …).
    pub quantity: String,
    /// Its unit.
    pub unit: &'static str,
    /// The largest value anywhere along the deck.
    pub max: PeakAt,
    /// The smallest value anywhere along the deck.
    pub min: PeakAt,
}

/// The peaks of every enveloped quantity: the largest and the smallest
/// value over every point (the first point wins a tie).
pub fn envelope_peaks(envelope: &Envelope) -> Vec<EnvelopePeak> {
    envelope
        .columns
        .iter()
        .filter(|c| !c.extremes.is_empty())
        .map(|c| {
            let largest = (0..c.extremes.len()).fold(0, |b, p| {
                if c.extremes[p].max > c.extremes[b].max {
                    p
                } else {
                    b
                }
            });
            let smallest = (0..c.extremes.len()).fold(0, |b, p| {
                if c.extremes[p].min < c.extremes[b].min {
                    p
                } else {
                    b
                }
            });
            EnvelopePeak {
                quantity: quantity_name_of(c.quantity),
                unit: c.unit,
                max: peak_at(envelope, c, largest, true),
                min: peak_at(envelope, c, smallest, false),
            }
        })
        .collect()
}

fn peak_at(envelope: &Envelope, column: &EnvelopeColumn, p: usize, max: bool) -> PeakAt {
    let e = column.extremes[p];
    let (value, time, lead_position) = if max {
        (e.max, e.max_time, e.max_position)
    } else {
        (e.min, e.min_time, e.min_position)
    };
    PeakAt {
        value,
        x: envelope.x[p],
        side: envelope.side.get(p).copied().unwrap_or_default(),
        support: envelope.support.get(p).copied().unwrap_or(false),
        time,
        lead_position,
        static_value: column
            .statics
            .get(p)
            .map(|s| if max { s.max } else { s.min }),
        daf: column.daf(p),
    }
}
