//! `history.png`: every recorded history of a run as a picture, one panel per
//! kind of quantity (with its unit), the static crossing response dashed in
//! its record's colour under each bridge displacement (`<name> static` in the
//! legend), each record's peak (largest |value|) marked and labelled with its
//! value and time, and dashed grey lines where each vehicle's front axle
//! enters the bridge and its last axle leaves it.

use std::path::Path;

use super::plot::{self, HistoryLayout, Marker, Panel, PlotError, Reference, Series};
use crate::record::History;
use crate::scene::{Quantity, Scenario};

/// The words for a quantity on an axis.
fn axis_name(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::BridgeDisplacement => "bridge displacement",
        Quantity::BridgeAcceleration => "bridge acceleration",
        Quantity::BridgeMoment => "bending moment",
        Quantity::BridgeShear => "shear force",
        Quantity::BridgeReaction => "support reaction",
        Quantity::ContactForce => "contact force",
        Quantity::ContactGap => "contact gap",
        Quantity::VehicleDisplacement => "vehicle displacement",
        Quantity::VehicleAcceleration => "vehicle acceleration",
    }
}

/// Entry (front axle at x = 0) and exit (last axle at x = L) of every vehicle.
pub fn bridge_markers(scenario: &Scenario) -> Vec<Marker> {
    let length = scenario.bridge.length();
    let many = scenario.vehicles.len() > 1;
    scenario
        .vehicles
        .iter()
        .enumerate()
        .flat_map(|(i, v)| {
            let who = if many {
                format!("v{} ", i + 1)
            } else {
                String::new()
            };
            let entry = v.entry_time();
            [
                Marker {
                    x: entry,
                    label: format!("{who}enters"),
                },
                Marker {
                    x: v.exit_time(length),
                    // A braking vehicle may stop on the bridge instead.
                    label: if v.motion().time_at(length + v.length()).is_some() {
                        format!("{who}leaves")
                    } else {
                        format!("{who}stops")
                    },
                },
            ]
        })
        .collect()
}

/// Writes the history chart of a run to `path` (PNG).
pub fn write_history_plot(
    path: &Path,
    scenario: &Scenario,
    history: &History,
) -> Result<(), PlotError> {
    with_panels(scenario, history, |title, axis, panels, markers| {
        plot::history_chart(path, title, axis, panels, markers)
    })
    .map(|_| ())
}

/// Writes the history chart of a run to `path` as SVG.
pub fn write_history_svg(
    path: &Path,
    scenario: &Scenario,
    history: &History,
) -> Result<(), PlotError> {
    with_panels(scenario, history, |title, axis, panels, markers| {
        plot::history_chart_svg(path, title, axis, panels, markers)
    })
    .map(|_| ())
}

/// Where the history chart of a run puts its lines, peak labels, markers
/// and legends ([`plot::history_layout`]); none when nothing is recorded.
pub fn history_plot_layout(
    scenario: &Scenario,
    history: &History,
) -> Result<Option<HistoryLayout>, PlotError> {
    with_panels(scenario, history, plot::history_layout)
}

/// Buckets of a streamed history's plot: each keeps its rows' first and
/// last time and every column's minimum and maximum, so a chart of 10⁷
/// rows draws 2 × 4096 points per series with every peak in place.
const PLOT_BUCKETS: usize = 4096;

/// A streamed history ([`crate::record::spill`]) reduced for drawing:
/// rows in buckets of ⌈rows / [`PLOT_BUCKETS`]⌉, each bucket two rows at
/// its first and last time holding every column's minimum and maximum in
/// the order they came. Memory O(PLOT_BUCKETS · columns).
fn reduced_for_plot(history: &History) -> Result<History, PlotError> {
    let Some(spilled) = &history.spilled else {
        return Ok(history.clone());
    };
    // Up to 2 × PLOT_BUCKETS rows: every row, as the history in memory
    // would draw them.
    let per_bucket = if spilled.rows <= 2 * PLOT_BUCKETS {
        1
    } else {
        spilled.rows.div_ceil(PLOT_BUCKETS)
    };
    let width = spilled.width;
    let mut reduced = history.clone();
    reduced.spilled = None;
    let mut table: Vec<Vec<f64>> = vec![Vec::new(); width];
    // Per value: (min, index of min, max, index of max) in the bucket.
    let mut bucket: Vec<(f64, usize, f64, usize)> = Vec::new();
    let (mut first_time, mut last_time, mut in_bucket) = (0.0, 0.0, 0usize);
    let mut flush = |bucket: &mut Vec<(f64, usize, f64, usize)>, first: f64, last: f64| {
        if bucket.is_empty() {
            return;
        }
        if per_bucket == 1 {
            for (k, &(value, ..)) in bucket.iter().enumerate() {
                table[k].push(value);
            }
            bucket.clear();
            return;
        }
        table[0].push(first);
        table[0].push(last);
        for (k, &(low, at_low, high, at_high)) in bucket.iter().enumerate().skip(1) {
            let (a, b) = if at_low <= at_high {
                (low, high)
            } else {
                (high, low)
            };
            table[k].push(a);
            table[k].push(b);
        }
        bucket.clear();
    };
    spilled
        .for_each_row(|row| {
            if in_bucket == 0 {
                first_time = row[0];
                bucket.extend(row.iter().map(|&v| (v, 0, v, 0)));
            } else {
                for (slot, &v) in bucket.iter_mut().zip(row) {
                    if v < slot.0 {
                        *slot = (v, in_bucket, slot.2, slot.3);
                    }
                    if v > slot.2 {
                        *slot = (slot.0, slot.1, v, in_bucket);
                    }
                }
            }
            last_time = row[0];
            in_bucket += 1;
            if in_bucket == per_bucket {
                flush(&mut bucket, first_time, last_time);
                in_bucket = 0;
            }
        })
        .map_err(|e| PlotError::InvalidInput(format!("reading the streamed history: {e}")))?;
    flush(&mut bucket, first_time, last_time);
    let mut columns = table.into_iter();
    reduced.time = columns.next().unwrap_or_default();
    for c in &mut reduced.columns {
        c.values = columns.next().unwrap_or_default();
        if c.static_values.is_some() {
            c.static_values = Some(columns.next().unwrap_or_default());
        }
    }
    Ok(reduced)
}

/// The history chart's title, time axis label, panels and markers handed
/// to `draw`; none drawn when nothing is recorded.
fn with_panels<R>(
    scenario: &Scenario,
    history: &History,
    draw: impl FnOnce(&str, &str, &[Panel], &[Marker]) -> Result<R, PlotError>,
) -> Result<Option<R>, PlotError> {
    let reduced;
    let history = if history.spilled.is_some() {
        reduced = reduced_for_plot(history)?;
        &reduced
    } else {
        history
    };
    // The crossing fills the time axis: a long approach (a spectrum's
    // run-in) is left out of the picture, not of history.csv (issue 40.7).
    let first = approach_end(scenario, &history.time);
    let time = &history.time[first..];
    // Panels in the order their kind first appears; one per (quantity, unit).
    let mut keys: Vec<(Quantity, &str)> = Vec::new();
    for c in &history.columns {
        if !keys.contains(&(c.quantity, c.unit)) {
            keys.push((c.quantity, c.unit));
        }
    }
    // Legend entries of the static responses: `<record> static`.
    let static_labels: Vec<String> = history
        .columns
        .iter()
        .map(|c| format!("{} static", c.name))
        .collect();
    let panels: Vec<Panel> = keys
        .iter()
        .map(|&(quantity, unit)| {
            let columns: Vec<usize> = (0..history.columns.len())
                .filter(|&i| {
                    let c = &history.columns[i];
                    c.quantity == quantity && c.unit == unit
                })
                .collect();
            Panel {
                y_label: format!("{} ({unit})", axis_name(quantity)),
                unit: unit.to_string(),
                series: columns
                    .iter()
                    .map(|&i| Series {
                        label: &history.columns[i].name,
                        x: time,
                        y: history.columns[i].values.get(first..).unwrap_or_default(),
                    })
                    .collect(),
                references: columns
                    .iter()
                    .enumerate()
                    .filter_map(|(of, &i)| {
                        history.columns[i]
                            .static_values
                            .as_ref()
                            .map(|s| Reference {
                                of,
                                line: Series {
                                    label: &static_labels[i],
                                    x: time,
                                    y: s.get(first..).unwrap_or_default(),
                                },
                            })
                    })
                    .collect(),
            }
        })
        .collect();
    if panels.is_empty() {
        return Ok(None);
    }
    let title = if panels.iter().all(|p| p.references.is_empty()) {
        format!("{}: recorded histories (o: peak)", scenario.name)
    } else {
        format!(
            "{}: recorded histories (dashed: static crossing; o: peak)",
            scenario.name
        )
    };
    let axis = match time.first() {
        Some(&t) if first > 0 => {
            format!("time (s); the approach before {t:.2} s is in history.csv")
        }
        _ => "time (s)".to_owned(),
    };
    let markers: Vec<Marker> = bridge_markers(scenario)
        .into_iter()
        .filter(|m| time.first().is_none_or(|&t| m.x >= t))
        .collect();
    draw(&title, &axis, &panels, &markers).map(Some)
}

/// The first sample the history plot shows: a little before the first
/// vehicle reaches the bridge when the approach before it is more than a
/// quarter of the run (a spectrum's run-in of 4.5 s in an 8.4 s run), else
/// the first. The margin is a twentieth of the rest of the run.
fn approach_end(scenario: &Scenario, time: &[f64]) -> usize {
    let (Some(&start), Some(&end)) = (time.first(), time.last()) else {
        return 0;
    };
    let entry = scenario
        .vehicles
        .iter()
        .map(|v| v.entry_time())
        .fold(f64::INFINITY, f64::min);
    if !(entry.is_finite() && entry - start > 0.25 * (end - start)) {
        return 0;
    }
    let from = entry - (end - entry) / 20.0;
    time.partition_point(|&t| t < from)
}
