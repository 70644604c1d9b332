//! `converge.png`: each ladder against its own setting (issue 28 point 7).
//!
//! Against wall time the mode ladder's runs cost nearly the same, so its
//! line stood as a vertical stroke; here the left panel is the error against
//! the time step (the time-step ladder at the reference's modes, one line a
//! quantity, and the combined ladder's worst error per mode count, dashed),
//! the right one the error against the modes kept at the scene's step. The
//! tolerance is drawn on both, and the cheapest run within it is circled
//! and labelled with its setting and wall time.

use std::path::Path;

use super::{Convergence, Ladder, RunReport, percent, short};
use crate::report::plot::{self, LadderPanel, LadderPanelLayout, PlotError, Series};

/// (x, y) points of one line.
type Line = (String, Vec<f64>, Vec<f64>);

impl Convergence {
    /// Writes the two-panel chart to `path` (PNG).
    pub fn plot(&self, path: &Path) -> Result<(), PlotError> {
        self.with_panels(|title, y_label, panels, tolerance, tolerance_label| {
            plot::ladder_chart(path, title, y_label, panels, tolerance, tolerance_label)
        })
    }

    /// Where [`Self::plot`] puts each panel's plotting area and abscissa
    /// tick labels: the image's width and height and one entry a panel.
    pub fn plot_layout(&self) -> Result<(u32, u32, Vec<LadderPanelLayout>), PlotError> {
        self.with_panels(plot::ladder_layout)
    }

    /// The chart's title, ordinate label, panels and tolerance handed to `draw`.
    fn with_panels<R>(
        &self,
        draw: impl FnOnce(&str, &str, &[LadderPanel], f64, &str) -> Result<R, PlotError>,
    ) -> Result<R, PlotError> {
        let names = self.quantities();
        let ok = |r: &&RunReport| r.wall_time.is_some() && r.errors.is_ok();
        let error = |r: &RunReport, q: usize| r.errors.as_ref().map_or(f64::NAN, |e| e[q].max_abs);
        let worst = |r: &RunReport| r.worst_max_abs_except(&self.excluded).unwrap_or(f64::NAN);
        let on = |ladder: Ladder| -> Vec<&RunReport> {
            self.runs
                .iter()
                .filter(|r| r.ladder == ladder)
                .filter(ok)
                .collect()
        };
        let steps = on(Ladder::TimeStep);
        let modes = on(Ladder::Modes);
        let combined = on(Ladder::Combined);
        let base_step = self.runs.first().map_or(f64::NAN, |r| r.time_step);
        // The mode ladder runs at the scene's step, as does the time-step
        // ladder's first run (at the reference's modes): one line.
        let mut mode_runs: Vec<&RunReport> = modes
            .iter()
            .copied()
            .chain(steps.iter().copied().filter(|r| r.time_step == base_step))
            .collect();
        mode_runs.sort_by_key(|r| r.modes);

        let per_quantity = |runs: &[&RunReport], x: &dyn Fn(&RunReport) -> f64| -> Vec<Line> {
            names
                .iter()
                .enumerate()
                .map(|(q, name)| {
                    let xs = runs.iter().map(|r| x(r)).collect();
                    let ys = runs.iter().map(|r| error(r, q)).collect();
                    (name.to_string(), xs, ys)
                })
                .collect()
        };
        let step_lines = per_quantity(&steps, &|r| r.time_step);
        let mode_lines = per_quantity(&mode_runs, &|r| r.modes as f64);
        // Combined: per mode count, from the mode-ladder run at the scene's
        // step through the coarser steps.
        let mut counts: Vec<usize> = combined.iter().map(|r| r.modes).collect();
        counts.sort_unstable_by(|a, b| b.cmp(a));
        counts.dedup();
        let combined_lines: Vec<Line> = counts
            .iter()
            .map(|&m| {
                let mut runs: Vec<&RunReport> = modes
                    .iter()
                    .chain(&combined)
                    .copied()
                    .filter(|r| r.modes == m)
                    .collect();
                runs.sort_by(|a, b| a.time_step.total_cmp(&b.time_step));
                let plural = if m == 1 { "" } else { "s" };
                (
                    format!("worst, {m} mode{plural} (combined)"),
                    runs.iter().map(|r| r.time_step).collect(),
                    runs.iter().map(|r| worst(r)).collect(),
                )
            })
            .collect();

        let chosen = self.cheapest_run();
        let chosen_label = chosen.map(|r| {
            let wall = r
                .wall_time
                .map_or(String::new(), |t| format!(", {:.3} ms", 1e3 * t));
            format!("cheapest: {}{wall}", r.label)
        });
        let mark = |ladders: &[Ladder], x: &dyn Fn(&RunReport) -> f64| {
            chosen
                .filter(|r| ladders.contains(&r.ladder))
                .zip(chosen_label.as_deref())
                .map(|(r, label)| (x(r), worst(r), label))
        };
        fn series(lines: &[Line]) -> Vec<Series<'_>> {
            lines
                .iter()
                .map(|(label, x, y)| Series { label, x, y })
                .collect()
        }
        let reference_modes = self.reference.modes;
        let step_title = format!("time-step ladder ({reference_modes} modes) and combined");
        let mode_title = format!("mode ladder (Δt = {} s)", short(base_step));
        let panels = [
            LadderPanel {
                title: &step_title,
                x_label: "time step Δt (s)",
                log_x: true,
                series: series(&step_lines),
                dashed: series(&combined_lines),
                chosen: mark(&[Ladder::TimeStep, Ladder::Combined], &|r| r.time_step),
            },
            LadderPanel {
                title: &mode_title,
                x_label: "bridge modes kept",
                log_x: false,
                series: series(&mode_lines),
                dashed: Vec::new(),
                chosen: mark(&[Ladder::Modes], &|r| r.modes as f64),
            },
        ];
        draw(
            &format!(
                "{}: error against {} (reference)",
                self.scenario, self.reference.label
            ),
            "max-abs error / max |reference|",
            &panels,
            self.tolerance,
            &format!("tolerance {} %", percent(self.tolerance)),
        )
    }
}
