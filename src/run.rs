//! One scene end to end: build → solve → record, results returned as data
//! ([`Outcome`]); [`write_results`] hands them to the report layer. Studies
//! ([`crate::study`]) compose this; [`crate::execute`] picks scene or study.

use std::path::{Path, PathBuf};
use std::time::Instant;

use thiserror::Error;

use crate::model::{BuildError, Model};
use crate::plan::Loaded;
use crate::record::{History, Recorder};
use crate::report::summary::Summary;
use crate::report::{self, ReportError};
use crate::scene::Scenario;
use crate::solve::{self, Progress, SolveError};

pub use crate::report::folder::{
    FROM, OWNER_FILE, claim_folder, create_out, default_out, folder_owner, mark_folder,
    resolved_yaml, source_name,
};

/// Errors of a run after loading.
#[derive(Debug, Error)]
pub enum RunError {
    /// Building the model failed.
    #[error(transparent)]
    Build(#[from] BuildError),
    /// The integration failed.
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// Writing results failed.
    #[error(transparent)]
    Report(#[from] ReportError),
    /// A plot could not be drawn.
    #[error(transparent)]
    Plot(#[from] crate::report::plot::PlotError),
    /// `method: embs` refused: ε ≥ 1 in a recorded direction
    /// ([`crate::solve::embs_scale::refusal`]).
    #[error("{0}")]
    EmbsOutOfRange(String),
    /// One sample of a Monte Carlo study failed (the study stops).
    #[error("sample {sample} of case {case} failed{rerun}: {source}")]
    Sample {
        /// Sample number from 1.
        sample: usize,
        /// The case: surface, and speed when swept.
        case: String,
        /// How to run that sample alone, when `--sample` can (first case).
        rerun: String,
        /// Why it failed.
        source: Box<RunError>,
    },
}

/// Results of one scene.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The model that was integrated.
    pub model: Model,
    /// Recorded time histories.
    pub history: History,
    /// Extremes and metadata.
    pub summary: Summary,
}

/// Builds and integrates a loaded scenario.
pub fn simulate(loaded: Loaded, progress: Progress<'_>) -> Result<Outcome, RunError> {
    run_scene(loaded, progress, None)
}

/// One scene through build → solve → record, the rows streamed to the
/// folder of `stream` when they would pass its byte bound.
fn run_scene(
    loaded: Loaded,
    progress: Progress<'_>,
    stream: Option<(&Path, f64)>,
) -> Result<Outcome, RunError> {
    let start = Instant::now();
    let Loaded { scenario, bridge } = loaded;
    let model = Model::build(&scenario, bridge)?;
    let mut recorder = Recorder::new(&model, &scenario.record)
        .and_then(|r| r.with_envelopes(scenario.envelopes.as_ref()))
        .map_err(BuildError::from)?
        .every(scenario.output.every);
    let io = |source| -> RunError {
        ReportError::Io {
            path: stream.map_or_else(PathBuf::new, |(out, _)| out.to_path_buf()),
            source,
        }
        .into()
    };
    // A comparison keeps both histories in memory to difference them.
    let compare = model.embs.is_some_and(|e| e.compare);
    if let Some((out, above_bytes)) = stream.filter(|_| !compare) {
        let rows = (model.steps / scenario.output.every.max(1)) as f64 + 1.0;
        if rows * recorder.row_width() as f64 * 8.0 > above_bytes {
            recorder = recorder.spill_into(out).map_err(io)?;
        }
    }
    if let Some(why) = crate::solve::embs_scale::refusal(&model, &scenario.record) {
        return Err(RunError::EmbsOutOfRange(why));
    }
    // A method that shows the zero order of its expansion alone (EMBS with
    // its first order) has it recorded too, for the a-posteriori check of
    // the expansion (report::embs).
    let mut zero_order = if solve::shows_zero_order(&model) {
        Some(
            Recorder::new(&model, &scenario.record)
                .map_err(BuildError::from)?
                .every(scenario.output.every),
        )
    } else {
        None
    };
    let (stats, solve_time, reference) = solve_compared(
        &model,
        &scenario,
        &mut recorder,
        zero_order.as_mut(),
        progress,
    );
    let stats = stats?;
    let reference = reference.transpose()?;
    let zero_order = zero_order.map(Recorder::finish);
    let history = recorder.finish_spilled().map_err(io)?;
    let wall_time = start.elapsed().as_secs_f64();
    let mut summary = Summary::new(&scenario.name, &model, &history, &stats, wall_time);
    if model.method == crate::scene::SolverMethod::Embs {
        summary.embs = Some(report::embs::EmbsSummary::new(
            &model,
            &scenario.record,
            &history,
            zero_order.as_ref(),
            reference
                .as_ref()
                .map(|(h, coupled_time)| (h, *coupled_time, solve_time)),
        ));
    }
    if let crate::scene::Bridge::FeImport(fe) = &scenario.bridge {
        summary.imported_model = fe.totals;
    }
    summary.advice = report::advice::advice_of(&scenario, &summary);
    Ok(Outcome {
        model,
        history,
        summary,
    })
}

/// A reference run's history and its solve time, s.
type Reference = (History, f64);

/// Integrates `model` with its method into `recorder` (and `zero_order`,
/// [`solve::run_method`]), and with the method it is compared with, when
/// the scene asks ([`solve::reference_method`]: EMBS with `coupled`): the
/// same model and records through the reference as well, on a second
/// thread while the method runs (the two runs share nothing but the
/// model; on two cores the pair takes the time of the slower one).
/// Returns the method's result, its solve time (s) and the reference's.
fn solve_compared(
    model: &Model,
    scenario: &Scenario,
    recorder: &mut Recorder<'_>,
    zero_order: Option<&mut Recorder<'_>>,
    progress: Progress<'_>,
) -> (
    Result<solve::SolveStats, SolveError>,
    f64,
    Option<Result<Reference, RunError>>,
) {
    let reference_method = solve::reference_method(model);
    std::thread::scope(|scope| {
        let reference_run = reference_method.map(|method| {
            let token = solve::cancel::current();
            let (record, every) = (&scenario.record, scenario.output.every);
            scope.spawn(move || {
                solve::cancel::in_scope(token.as_ref(), || -> Result<_, RunError> {
                    let mut recorder = Recorder::new(model, record)
                        .map_err(BuildError::from)?
                        .every(every);
                    let start = Instant::now();
                    solve::run_method(model, method, &mut recorder, None, &mut |_, _| {})?;
                    Ok((recorder.finish(), start.elapsed().as_secs_f64()))
                })
            })
        });
        let solve_start = Instant::now();
        let stats = solve::run_method(
            model,
            model.method,
            recorder,
            zero_order.map(|z| z as &mut dyn solve::Observer),
            progress,
        );
        let solve_time = solve_start.elapsed().as_secs_f64();
        let reference = reference_run.map(|handle| {
            handle
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
        });
        (stats, solve_time, reference)
    })
}

/// Written samples (rows × columns × 8 bytes) above which a run streams
/// its rows to disk ([`simulate_into`]): below it the history stays in
/// memory, which is faster to write and plot; above it memory stays at
/// this whatever the step count.
pub const STREAM_ABOVE_BYTES: f64 = 32.0e6;

/// [`simulate`] with the written rows streamed to a file in the output
/// folder `out` (created if needed) as the run goes, instead of kept in
/// memory ([`crate::record::spill`]), when they would take more than
/// [`STREAM_ABOVE_BYTES`]: the history files and the plot are then written
/// from that file by [`write_results_with`], and the file is removed when
/// the outcome is dropped (or the run fails).
pub fn simulate_into(
    loaded: Loaded,
    out: &Path,
    progress: Progress<'_>,
) -> Result<Outcome, RunError> {
    simulate_streaming_above(loaded, out, progress, STREAM_ABOVE_BYTES)
}

/// [`simulate_into`] streaming above `stream_above_bytes` of written
/// samples (0: always).
pub fn simulate_streaming_above(
    loaded: Loaded,
    out: &Path,
    progress: Progress<'_>,
    stream_above_bytes: f64,
) -> Result<Outcome, RunError> {
    create_out(out)?;
    run_scene(loaded, progress, Some((out, stream_above_bytes)))
}

/// Writes `summary.json`, the history (`history.csv` and/or `history.npy`
/// with `history_columns.txt`, as `output.format` asks), `history.png` and
/// `resolved.yaml` into `out` (created if needed), each atomically.
pub fn write_results(out: &Path, scenario: &Scenario, outcome: &Outcome) -> Result<(), RunError> {
    write_results_with(out, scenario, outcome, false)
}

/// [`write_results`], and `history.svg` when `svg`.
pub fn write_results_with(
    out: &Path,
    scenario: &Scenario,
    outcome: &Outcome,
    svg: bool,
) -> Result<(), RunError> {
    create_out(out)?;
    let summary =
        serde_json::to_string_pretty(&outcome.summary).expect("summary serialises") + "\n";
    let yaml = resolved_yaml(scenario);
    report::history_files::write_history(
        out,
        &outcome.history,
        outcome.model.time_step,
        scenario.output.format,
    )?;
    report::write_atomic(&out.join("resolved.yaml"), yaml.as_bytes())?;
    if let Some(envelope) = &outcome.history.envelope {
        report::write_atomic(
            &out.join("envelopes.csv"),
            report::envelopes::envelope_csv(envelope).as_bytes(),
        )?;
        report::envelopes::write_envelope_plot(&out.join("envelopes.png"), scenario, envelope)?;
    }
    if outcome.model.bridge.width().is_some() {
        report::write_atomic(
            &out.join("daf_table.csv"),
            report::girder_daf_csv(&outcome.history.girder_dafs).as_bytes(),
        )?;
    }
    report::history_plot::write_history_plot(&out.join("history.png"), scenario, &outcome.history)?;
    if svg {
        report::history_plot::write_history_svg(
            &out.join("history.svg"),
            scenario,
            &outcome.history,
        )?;
    }
    // summary.json last: its presence means the run's results are complete.
    report::write_atomic(&out.join("summary.json"), summary.as_bytes())?;
    Ok(())
}
