//! `history.png`: every recorded history of a run as a picture, one panel per
//! kind of quantity (with its unit), the static crossing response in grey
//! under each bridge displacement, and dashed lines where each vehicle's
//! front axle enters the bridge and its last axle leaves it.

use std::path::Path;

use super::plot::{self, Marker, Panel, PlotError, Series};
use crate::record::History;
use crate::scenario::resolved::{Quantity, Scenario};

/// The words for a quantity on an axis.
fn axis_name(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::BridgeDisplacement => "bridge displacement",
        Quantity::BridgeAcceleration => "bridge acceleration",
        Quantity::BridgeMoment => "bending moment",
        Quantity::BridgeShear => "shear force",
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
    draw_history_plot(path, scenario, history, false)
}

/// Writes the history chart of a run to `path` as SVG.
pub fn write_history_svg(
    path: &Path,
    scenario: &Scenario,
    history: &History,
) -> Result<(), PlotError> {
    draw_history_plot(path, scenario, history, true)
}

fn draw_history_plot(
    path: &Path,
    scenario: &Scenario,
    history: &History,
    svg: bool,
) -> Result<(), PlotError> {
    // Panels in the order their kind first appears; one per (quantity, unit).
    let mut keys: Vec<(Quantity, &str)> = Vec::new();
    for c in &history.columns {
        if !keys.contains(&(c.quantity, c.unit)) {
            keys.push((c.quantity, c.unit));
        }
    }
    let panels: Vec<Panel> = keys
        .iter()
        .map(|&(quantity, unit)| {
            let columns = history
                .columns
                .iter()
                .filter(|c| c.quantity == quantity && c.unit == unit);
            Panel {
                y_label: format!("{} ({unit})", axis_name(quantity)),
                series: columns
                    .clone()
                    .map(|c| Series {
                        label: &c.name,
                        x: &history.time,
                        y: &c.values,
                    })
                    .collect(),
                references: columns
                    .filter_map(|c| {
                        c.static_values.as_ref().map(|s| Series {
                            label: "",
                            x: &history.time,
                            y: s,
                        })
                    })
                    .collect(),
            }
        })
        .collect();
    if panels.is_empty() {
        return Ok(());
    }
    let title = format!(
        "{}: recorded histories (grey: static crossing)",
        scenario.name
    );
    let title = if panels.iter().all(|p| p.references.is_empty()) {
        format!("{}: recorded histories", scenario.name)
    } else {
        title
    };
    let chart = if svg {
        plot::history_chart_svg
    } else {
        plot::history_chart
    };
    chart(path, &title, "time (s)", &panels, &bridge_markers(scenario))
}
