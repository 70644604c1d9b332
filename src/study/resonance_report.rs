//! The files of a resonance check: resonance.csv (every run),
//! resonance_trains.csv (the verdict per train), resonance.png (deck
//! acceleration against speed per train, with the limit as a black dashed
//! line, each train's verdict in its legend entry and the overall one in
//! the title), resonance_displacement.png,
//! resolved.yaml and, last, summary.json; and the verdict table the
//! command line prints.

use std::fmt::Write as _;
use std::path::Path;

use super::resonance::{ResonancePoint, ResonanceResults};
use crate::report::plot::{Series, line_chart, line_chart_with_reference};
use crate::report::{number, write_atomic};
use crate::run::RunError;
use crate::scenario::resonance_grid::km_h;
use crate::scene::Scenario;

impl ResonanceResults {
    /// resonance.csv: one row per run, with whether it keeps within the
    /// limit.
    pub fn to_csv(&self) -> Vec<u8> {
        let mut out = String::from(
            "train,speed [m/s],speed [km/h],max_displacement [m],displacement_at [m],\
             max_acceleration [m/s^2],acceleration_at [m],time_step [s],within_limit\n",
        );
        for p in &self.points {
            let row = [
                self.trains[p.train].clone(),
                number(p.speed),
                number(km_h(p.speed)),
                number(p.max_displacement),
                number(p.displacement_at),
                number(p.max_acceleration),
                number(p.acceleration_at),
                number(p.time_step),
                (p.max_acceleration <= self.limit).to_string(),
            ];
            out.push_str(&row.join(","));
            out.push('\n');
        }
        out.into_bytes()
    }

    /// resonance_trains.csv: the verdict per train (resonance speeds
    /// separated by spaces).
    pub fn trains_csv(&self) -> Vec<u8> {
        let mut out = String::from(
            "train,coach_length [m],resonance_speeds [km/h],runs,max_acceleration [m/s^2],\
             speed [km/h],acceleration_at [m],limit [m/s^2],passes\n",
        );
        for v in self.verdicts() {
            let resonances: Vec<String> =
                v.resonance_speeds_km_h.iter().map(|&r| number(r)).collect();
            let (a, speed, x) = v.max_acceleration.as_ref().map_or_else(
                || ("-".into(), "-".into(), "-".into()),
                |g| (number(g.value), number(g.speed_km_h), number(g.x)),
            );
            let _ = writeln!(
                out,
                "{},{},{},{},{a},{speed},{x},{},{}",
                v.train,
                number(v.coach_length_m),
                resonances.join(" "),
                v.runs,
                number(self.limit),
                if v.passes { "pass" } else { "FAIL" }
            );
        }
        out.into_bytes()
    }

    /// The verdict as a text table: per train its largest deck acceleration,
    /// where, and pass/FAIL; then the overall verdict.
    pub fn verdict_table(&self) -> String {
        let mut out = format!(
            "{:<9} {:>5} {:>12} {:>10} {:>8}  verdict (limit {} m/s^2)\n",
            "train", "D (m)", "max a (m/s2)", "at (km/h)", "x (m)", self.limit
        );
        for v in self.verdicts() {
            let (a, speed, x) = v.max_acceleration.as_ref().map_or_else(
                || ("-".into(), "-".into(), "-".into()),
                |g| (format!("{:.3}", g.value), number(g.speed_km_h), number(g.x)),
            );
            let _ = writeln!(
                out,
                "{:<9} {:>5} {a:>12} {speed:>10} {x:>8}  {}",
                v.train,
                number(v.coach_length_m),
                if v.passes { "pass" } else { "FAIL" }
            );
        }
        let _ = writeln!(out, "{}", self.verdict_line());
        out
    }

    /// One line: `PASSES` or `FAILS (HSLM-A1, HSLM-A3 above 3.5 m/s^2)`.
    pub fn verdict_line(&self) -> String {
        let failing: Vec<String> = self
            .verdicts()
            .into_iter()
            .filter(|v| !v.passes)
            .map(|v| v.train)
            .collect();
        if failing.is_empty() {
            format!(
                "EN 1991-2 resonance check PASSES (every train within {} m/s^2)",
                self.limit
            )
        } else {
            format!(
                "EN 1991-2 resonance check FAILS ({} above {} m/s^2)",
                failing.join(", "),
                self.limit
            )
        }
    }

    /// Per train, its runs' (km/h, value) in speed order.
    fn curves(&self, value: impl Fn(&ResonancePoint) -> f64) -> Vec<(Vec<f64>, Vec<f64>)> {
        (0..self.trains.len())
            .map(|t| {
                self.points
                    .iter()
                    .filter(|p| p.train == t)
                    .map(|p| (km_h(p.speed), value(p)))
                    .unzip()
            })
            .collect()
    }
}

/// Writes the check's files into `out` (see the module documentation).
pub fn write(out: &Path, scenario: &Scenario, results: &ResonanceResults) -> Result<(), RunError> {
    crate::report::folder::create_out(out)?;
    write_atomic(&out.join("resonance.csv"), &results.to_csv())?;
    write_atomic(&out.join("resonance_trains.csv"), &results.trains_csv())?;
    let speed_label = "speed (km/h)";
    let accelerations = results.curves(|p| p.max_acceleration);
    // Each train's verdict in its legend entry.
    let labels: Vec<String> = results
        .verdicts()
        .iter()
        .map(|v| format!("{} {}", v.train, if v.passes { "pass" } else { "FAIL" }))
        .collect();
    let series: Vec<Series> = labels
        .iter()
        .zip(&accelerations)
        .map(|(label, (x, y))| Series { label, x, y })
        .collect();
    let (lo, hi) = accelerations
        .iter()
        .flat_map(|(x, _)| x)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let limit_x = [lo, hi];
    let limit_y = [results.limit; 2];
    let limit_label = format!(
        "limit {} m/s^2 ({}, EN 1990 A2.4.4.2.1)",
        results.limit,
        results.deck.replace('_', " ")
    );
    let limit = Series {
        label: &limit_label,
        x: &limit_x,
        y: &limit_y,
    };
    line_chart_with_reference(
        &out.join("resonance.png"),
        &format!(
            "{}: {}",
            scenario.name,
            if results.passes() {
                "PASSES".to_string()
            } else {
                let failing = results.verdicts().iter().filter(|v| !v.passes).count();
                format!("FAILS ({failing} of {} trains)", results.trains.len())
            }
        ),
        speed_label,
        // The mode cut-off on the axis: the title holds the verdict only,
        // so it fits the plot's width.
        &format!(
            "max |deck acceleration| (m/s^2), modes up to {:.1} Hz",
            results.max_frequency
        ),
        &series,
        &limit,
    )?;
    let displacements = results.curves(|p| p.max_displacement * 1e3);
    let series: Vec<Series> = results
        .trains
        .iter()
        .zip(&displacements)
        .map(|(label, (x, y))| Series { label, x, y })
        .collect();
    line_chart(
        &out.join("resonance_displacement.png"),
        &format!("{}: peak deck displacement", scenario.name),
        speed_label,
        "max |deck displacement| (mm)",
        &series,
        false,
        false,
    )?;
    write_atomic(
        &out.join("resolved.yaml"),
        crate::report::folder::resolved_yaml(scenario).as_bytes(),
    )?;
    let summary = results.summary(&scenario.name);
    let text = crate::study::summary_json(&summary, results.advice(scenario));
    write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}
