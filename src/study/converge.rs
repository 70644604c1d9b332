//! Convergence study: speed against error (`vbi converge`).
//!
//! One scene is run at a fine REFERENCE resolution and along two LADDERS of
//! cheaper resolutions, and every recorded quantity of every run is compared
//! with the reference:
//!
//! - reference: time step h_ref = Δt / 4 (Δt the scenario's step) and
//!   N_ref = min(2 N, N_avail) modes (N the scenario's modes, N_avail all the
//!   mesh offers);
//! - time-step ladder: steps Δt, 2Δt, 4Δt, … (`levels` runs) at N_ref modes,
//!   so its errors are those of the time integration alone;
//! - mode ladder: N, N/2, N/4 modes (at least 1, duplicates and N_ref
//!   dropped) at Δt, so its errors add modal truncation;
//! - combined ladder, run after the other two: every step h > Δt of the
//!   time-step ladder within tolerance together with every mode count of
//!   the mode ladder within tolerance (coarsest step and fewest modes
//!   last). The two errors roughly add, so a pair can fail although both
//!   halves pass: it is measured, not assumed.
//!
//! Every ladder step is an integer multiple k of h_ref (powers of two, exact
//! in floating point), so sample i of a run lies at the reference's sample
//! i·k. Over the common samples S (the shorter run's duration), with e = u − u_ref,
//!
//! - max-abs error = max_S |e| / max_S |u_ref|,
//! - RMS error = √(Σ_S e²) / √(Σ_S u_ref²),
//!
//! both dimensionless (a reference identically zero gives 0 for a zero error
//! and +∞ otherwise). The observed order of accuracy of a time-step halving
//! h → 2h is p = log₂(e(2h) / e(h)) with e the max-abs error; Newmark's
//! average acceleration gives p → 2 in the asymptotic range. The reference's
//! own error biases p slightly upward (for e ∝ h², by the factor
//! (4h² − h_ref²)/(h² − h_ref²) inside the logarithm; p ≈ 2.07 at h = 4 h_ref).
//!
//! Runs go one after another (not in parallel) so their wall times do not
//! compete; a run shorter than [`MIN_TIMING`] is repeated (at most
//! [`MAX_REPEATS`] times) and the fastest time kept, which keeps the
//! "cheapest" choice stable for runs of a few milliseconds. Everything but
//! the wall times is deterministic.

mod answer;
mod measure;
mod plot;

pub use self::measure::{cheapest_within, median, observed_orders, relative_errors};

use std::time::Instant;

use thiserror::Error;

use crate::bridge::{BridgeError, ModalBridge};
use crate::plan::Loaded;
use crate::run::{self, Outcome, RunError};
use crate::scene::Modes;

/// The reference's time step is the scenario's divided by this.
pub const REFERENCE_REFINEMENT: usize = 4;
/// Default number of time-step ladder runs.
pub const DEFAULT_LEVELS: usize = 5;
/// Runs shorter than this (s) are repeated to time them.
pub const MIN_TIMING: f64 = 0.05;
/// Most timings of one run.
pub const MAX_REPEATS: usize = 5;

/// Settings of a convergence study.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Runs on the time-step ladder: Δt·2⁰ … Δt·2^(levels−1); at least 1.
    pub levels: usize,
    /// Largest acceptable worst max-abs relative error (0.01 = 1 %).
    pub tolerance: f64,
    /// Recorded quantities (by name) left out of the overall "cheapest
    /// within tolerance" (still measured and judged on their own).
    pub exclude: Vec<String>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            levels: DEFAULT_LEVELS,
            tolerance: 0.01,
            exclude: Vec::new(),
        }
    }
}

/// Why a study could not be carried out.
#[derive(Debug, Error)]
pub enum ConvergeError {
    /// The options are out of range.
    #[error("{0}")]
    Options(String),
    /// The reference bridge could not be built.
    #[error("the reference bridge: {0}")]
    Bridge(#[from] BridgeError),
    /// The reference run failed, so nothing can be compared.
    #[error("the reference run ({label}) failed: {source}")]
    Reference {
        /// Label of the reference run.
        label: String,
        /// The cause.
        source: RunError,
    },
}

/// Which set of runs a run belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ladder {
    /// The finest run everything is compared with.
    Reference,
    /// Coarser time steps at the reference's mode count.
    TimeStep,
    /// Fewer modes at the scenario's time step.
    Modes,
    /// A coarser step of the time-step ladder together with fewer modes of
    /// the mode ladder, both within tolerance on their own ladder.
    Combined,
}

/// A time step (s) and a mode count.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Time step, s.
    pub time_step: f64,
    /// Bridge modes kept.
    pub modes: usize,
}

impl Resolution {
    /// E.g. `dt=1e-4 s, 10 modes`.
    pub fn label(&self) -> String {
        let plural = if self.modes == 1 { "" } else { "s" };
        format!(
            "dt={} s, {} mode{plural}",
            short(self.time_step),
            self.modes
        )
    }
}

/// `x` in exponent notation with at most 4 significant digits and no
/// trailing zeros: 1e-4, 2.5e-5, 1.6e-3.
pub fn short(x: f64) -> String {
    let text = format!("{x:.3e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) if mantissa.contains('.') => {
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            format!("{mantissa}e{exponent}")
        }
        _ => text,
    }
}

/// A fraction as a percentage without trailing zeros: 0.01 → `1`,
/// 0.005 → `0.5`, 0.07 → `7` (at most 6 decimals).
pub fn percent(fraction: f64) -> String {
    let text = format!("{:.6}", 100.0 * fraction);
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Relative errors of one recorded quantity against the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct QuantityError {
    /// Column name from the scenario.
    pub name: String,
    /// Unit of the quantity.
    pub unit: &'static str,
    /// max|e| / max|u_ref| over the common samples, dimensionless.
    pub max_abs: f64,
    /// √Σe² / √Σu_ref² over the common samples, dimensionless.
    pub rms: f64,
}

/// One run of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct RunReport {
    /// E.g. `dt=2e-4 s, 20 modes`.
    pub label: String,
    /// Which ladder.
    pub ladder: Ladder,
    /// Time step, s.
    pub time_step: f64,
    /// Bridge modes kept.
    pub modes: usize,
    /// Steps integrated (None if the run failed).
    pub steps: Option<usize>,
    /// Fastest wall time of `run::simulate`, s (None if the run failed).
    pub wall_time: Option<f64>,
    /// Errors per recorded quantity in scenario order, or why the run failed.
    pub errors: Result<Vec<QuantityError>, String>,
    /// The run's advice (its summary's, [`crate::advice`]): a run that
    /// warns is no reference for the cheapest choice without a look.
    pub advice: Vec<crate::advice::Advice>,
}

impl RunReport {
    /// Largest max-abs relative error over the quantities (None if failed).
    /// NaN compares as +∞, so a non-finite error never passes a tolerance.
    pub fn worst_max_abs(&self) -> Option<f64> {
        self.worst(|q| q.max_abs)
    }

    /// Largest max-abs relative error over the quantities not named in
    /// `excluded` (None if failed).
    pub fn worst_max_abs_except(&self, excluded: &[String]) -> Option<f64> {
        self.worst(|q| {
            if excluded.contains(&q.name) {
                0.0
            } else {
                q.max_abs
            }
        })
    }

    /// Largest RMS relative error over the quantities (None if failed).
    pub fn worst_rms(&self) -> Option<f64> {
        self.worst(|q| q.rms)
    }

    fn worst(&self, f: impl Fn(&QuantityError) -> f64) -> Option<f64> {
        let errors = self.errors.as_ref().ok()?;
        Some(errors.iter().map(f).fold(0.0, |worst, e| {
            if e.is_nan() {
                f64::INFINITY
            } else {
                worst.max(e)
            }
        }))
    }
}

/// Observed order of one time-step halving for one quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Order {
    /// Quantity name.
    pub quantity: String,
    /// The coarser step 2h, s.
    pub coarse_step: f64,
    /// The finer step h, s.
    pub fine_step: f64,
    /// p = log₂(e(2h) / e(h)) from the max-abs errors.
    pub order: f64,
}

/// Result of a convergence study.
#[derive(Debug, Clone, PartialEq)]
pub struct Convergence {
    /// Scenario name.
    pub scenario: String,
    /// The reference run (its errors are zero by definition).
    pub reference: RunReport,
    /// The ladder runs: time-step ladder (finest first), then mode ladder
    /// (most modes first).
    pub runs: Vec<RunReport>,
    /// Observed orders of every successive halving on the time-step ladder
    /// with both errors finite and positive: halvings finest first, quantities
    /// in scenario order.
    pub orders: Vec<Order>,
    /// Median of `orders` (None if there are none).
    pub median_order: Option<f64>,
    /// The tolerance used, dimensionless.
    pub tolerance: f64,
    /// Index into `runs` of the cheapest run within tolerance on every
    /// quantity not excluded.
    pub cheapest: Option<usize>,
    /// Quantities left out of `cheapest`.
    pub excluded: Vec<String>,
    /// Per recorded quantity (scenario order): its name and the index into
    /// `runs` of the cheapest run within tolerance on that quantity alone.
    pub cheapest_per_quantity: Vec<(String, Option<usize>)>,
    /// The scene's `modes.static_correction`, kept by every run (and so by
    /// the YAML that hands over the cheapest run).
    pub static_correction: bool,
}

/// The reference resolution and the ladder runs for a scene with time step
/// `time_step` (s), `modes` modes kept and `available` modes offered.
pub fn plan(
    time_step: f64,
    modes: usize,
    available: usize,
    levels: usize,
) -> (Resolution, Vec<(Ladder, Resolution)>) {
    let reference_modes = (2 * modes).min(available).max(modes);
    let reference = Resolution {
        time_step: time_step / REFERENCE_REFINEMENT as f64,
        modes: reference_modes,
    };
    let mut ladder: Vec<(Ladder, Resolution)> = (0..levels)
        .map(|level| {
            let resolution = Resolution {
                time_step: time_step * (1u64 << level) as f64,
                modes: reference_modes,
            };
            (Ladder::TimeStep, resolution)
        })
        .collect();
    let mut counts: Vec<usize> = vec![modes, (modes / 2).max(1), (modes / 4).max(1)];
    counts.dedup();
    for count in counts.into_iter().filter(|&c| c != reference_modes) {
        let resolution = Resolution {
            time_step,
            modes: count,
        };
        ladder.push((Ladder::Modes, resolution));
    }
    (reference, ladder)
}

/// Runs the study. `progress` gets (run index from 0, number of runs, label)
/// before each run, the reference first.
pub fn converge(
    loaded: &Loaded,
    options: &Options,
    progress: &mut dyn FnMut(usize, usize, &str),
) -> Result<Convergence, ConvergeError> {
    if options.levels == 0 {
        return Err(ConvergeError::Options(
            "levels must be at least 1".to_string(),
        ));
    }
    if !(options.tolerance.is_finite() && options.tolerance > 0.0) {
        return Err(ConvergeError::Options(format!(
            "the tolerance must be a positive number, not {}",
            options.tolerance
        )));
    }
    let (reference_resolution, ladder) = plan(
        loaded.scenario.solver.time_step,
        loaded.bridge.mode_count(),
        loaded.bridge.available_modes,
        options.levels,
    );
    let total = 1 + ladder.len();
    let label = reference_resolution.label();
    progress(0, total, &label);
    let reference_loaded = at_resolution(loaded, reference_resolution)?;
    let (outcome, wall_time) =
        timed(&reference_loaded).map_err(|source| ConvergeError::Reference { label, source })?;
    let reference_history = outcome.history;
    let reference = report(
        Ladder::Reference,
        reference_resolution,
        Some((outcome.model.steps, wall_time)),
        Ok(relative_errors(&reference_history, &reference_history, 1)),
        outcome.summary.advice,
    );

    let names: Vec<String> = reference_history
        .columns
        .iter()
        .map(|c| c.name.clone())
        .collect();
    if let Some(unknown) = options.exclude.iter().find(|e| !names.contains(e)) {
        return Err(ConvergeError::Options(format!(
            "--exclude {unknown}: the scene records no quantity of that name (it records {})",
            names.join(", ")
        )));
    }
    let mut runs = Vec::with_capacity(ladder.len());
    let mut measure = |kind: Ladder, resolution: Resolution, index: usize, total: usize| {
        progress(index + 1, total, &resolution.label());
        let stride = (resolution.time_step / reference_resolution.time_step).round() as usize;
        let result = at_resolution(loaded, resolution)
            .map_err(|e| e.to_string())
            .and_then(|l| timed(&l).map_err(|e| e.to_string()));
        match result {
            Ok((outcome, wall_time)) => report(
                kind,
                resolution,
                Some((outcome.model.steps, wall_time)),
                Ok(relative_errors(
                    &reference_history,
                    &outcome.history,
                    stride,
                )),
                outcome.summary.advice,
            ),
            Err(message) => report(kind, resolution, None, Err(message), Vec::new()),
        }
    };
    for (index, &(kind, resolution)) in ladder.iter().enumerate() {
        runs.push(measure(kind, resolution, index, total));
    }
    // The combined ladder, from what the two ladders measured.
    let combined = combined_plan(
        &runs,
        loaded.scenario.solver.time_step,
        reference_resolution.modes,
        options.tolerance,
        &options.exclude,
    );
    let total = total + combined.len();
    for resolution in combined {
        let index = runs.len();
        runs.push(measure(Ladder::Combined, resolution, index, total));
    }
    let orders = observed_orders(&runs);
    let median_order = median(orders.iter().map(|o| o.order).collect());
    let cheapest = cheapest_within(&runs, options.tolerance, &options.exclude);

    let cheapest_per_quantity = names
        .iter()
        .map(|name| {
            let others: Vec<String> = names.iter().filter(|n| *n != name).cloned().collect();
            (
                name.clone(),
                cheapest_within(&runs, options.tolerance, &others),
            )
        })
        .collect();
    Ok(Convergence {
        scenario: loaded.scenario.name.clone(),
        reference,
        runs,
        orders,
        median_order,
        tolerance: options.tolerance,
        cheapest,
        excluded: options.exclude.clone(),
        cheapest_per_quantity,
        static_correction: loaded.scenario.bridge.modes().static_correction,
    })
}

/// The combined ladder: every time-step-ladder step coarser than
/// `time_step` (s) whose run is within `tolerance`, paired with every
/// mode-ladder count below `reference_modes` whose run is within it (the
/// quantities in `excluded` left out, as for the cheapest run); finest step
/// first, then most modes first.
pub fn combined_plan(
    runs: &[RunReport],
    time_step: f64,
    reference_modes: usize,
    tolerance: f64,
    excluded: &[String],
) -> Vec<Resolution> {
    let within = |r: &&RunReport| {
        r.worst_max_abs_except(excluded)
            .is_some_and(|e| e <= tolerance)
    };
    let steps: Vec<f64> = runs
        .iter()
        .filter(|r| r.ladder == Ladder::TimeStep && r.time_step > time_step)
        .filter(within)
        .map(|r| r.time_step)
        .collect();
    let counts: Vec<usize> = runs
        .iter()
        .filter(|r| r.ladder == Ladder::Modes && r.modes < reference_modes)
        .filter(within)
        .map(|r| r.modes)
        .collect();
    steps
        .iter()
        .flat_map(|&time_step| {
            counts
                .iter()
                .map(move |&modes| Resolution { time_step, modes })
        })
        .collect()
}

/// A run's report; `cost` is (steps, wall time in s) of a successful run.
fn report(
    ladder: Ladder,
    resolution: Resolution,
    cost: Option<(usize, f64)>,
    errors: Result<Vec<QuantityError>, String>,
    advice: Vec<crate::advice::Advice>,
) -> RunReport {
    RunReport {
        advice,
        label: resolution.label(),
        ladder,
        time_step: resolution.time_step,
        modes: resolution.modes,
        steps: cost.map(|c| c.0),
        wall_time: cost.map(|c| c.1),
        errors,
    }
}

/// The scene at another resolution: the time step replaced, the lowest
/// `modes` modes kept (any frequency cut-off dropped), the bridge rebuilt;
/// a study section is dropped (the base scene is converged). This is the
/// scene every run of a study integrates.
pub fn at_resolution(loaded: &Loaded, resolution: Resolution) -> Result<Loaded, BridgeError> {
    let mut scenario = loaded.scenario.clone();
    scenario.study = None;
    scenario.solver.time_step = resolution.time_step;
    *scenario.bridge.modes_mut() = Modes {
        count: Some(resolution.modes),
        max_frequency: None,
        static_correction: loaded.scenario.bridge.modes().static_correction,
    };
    let bridge = ModalBridge::build(&scenario.bridge)?;
    Ok(Loaded { scenario, bridge })
}

/// Runs `loaded`, repeating while the total stays under [`MIN_TIMING`] (at
/// most [`MAX_REPEATS`] runs); returns the first outcome and the fastest
/// wall time, s.
fn timed(loaded: &Loaded) -> Result<(Outcome, f64), RunError> {
    let mut first = None;
    let mut fastest = f64::INFINITY;
    let mut spent = 0.0;
    for _ in 0..MAX_REPEATS {
        let mut copy = loaded.clone();
        // Errors are measured over every step: `output.every` thins what a
        // run writes, not what converge compares.
        copy.scenario.output.every = 1;
        let start = Instant::now();
        let outcome = run::simulate(copy, &mut |_, _| {})?;
        let elapsed = start.elapsed().as_secs_f64();
        fastest = fastest.min(elapsed);
        spent += elapsed;
        first.get_or_insert(outcome);
        if spent >= MIN_TIMING {
            break;
        }
    }
    Ok((first.expect("at least one run"), fastest))
}

/// Parses a tolerance: `1%` (percent) or `0.01` (a fraction); it must be
/// positive and finite.
pub fn parse_tolerance(text: &str) -> Result<f64, String> {
    let trimmed = text.trim();
    let (number, scale) = match trimmed.strip_suffix('%') {
        Some(n) => (n.trim(), 0.01),
        None => (trimmed, 1.0),
    };
    let bad = || {
        format!("`{text}` is not a tolerance; give a percentage like 1% or a fraction like 0.01")
    };
    let value = number.parse::<f64>().map_err(|_| bad())? * scale;
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!("the tolerance must be positive, not `{text}`"))
    }
}

impl Convergence {
    /// The cheapest run within tolerance.
    pub fn cheapest_run(&self) -> Option<&RunReport> {
        self.cheapest.map(|i| &self.runs[i])
    }

    /// Names of the recorded quantities, in scenario order.
    pub fn quantities(&self) -> Vec<&str> {
        match &self.reference.errors {
            Ok(errors) => errors.iter().map(|q| q.name.as_str()).collect(),
            Err(_) => Vec::new(),
        }
    }

    /// CSV, one row per ladder run × quantity: `label, time_step [s]`,
    /// `modes, steps, wall_time [s]`, `quantity, max_abs_error, rms_error`
    /// (dimensionless fractions), `failure` (the message of a failed run,
    /// whose other measured fields are empty), `advice` (the ids of the run's
    /// warnings, space-separated).
    pub fn to_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        let header = "label,time_step [s],modes,steps,wall_time [s],quantity,max_abs_error,\
                      rms_error,failure,advice";
        out.write_record(header.split(','))
            .expect("writing to memory");
        let number = crate::report::number;
        for run in &self.runs {
            let head = [
                run.label.clone(),
                number(run.time_step),
                run.modes.to_string(),
                run.steps.map(|s| s.to_string()).unwrap_or_default(),
                run.wall_time.map(number).unwrap_or_default(),
            ];
            // The ids of the run's warnings, space-separated.
            let warned = run
                .advice
                .iter()
                .filter(|a| a.is_denied_warning())
                .map(|a| a.id.as_str())
                .collect::<Vec<_>>()
                .join(" ");
            for (q, name) in self.quantities().into_iter().enumerate() {
                let (max_abs, rms, failure) = match &run.errors {
                    Ok(errors) => (number(errors[q].max_abs), number(errors[q].rms), ""),
                    Err(message) => (String::new(), String::new(), message.as_str()),
                };
                let tail = [name, &max_abs, &rms, failure, &warned];
                out.write_record(head.iter().map(String::as_str).chain(tail))
                    .expect("writing to memory");
            }
        }
        out.into_inner().expect("writing to memory")
    }
}
