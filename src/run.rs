//! One scene end to end: build → solve → record → report.

use std::path::{Path, PathBuf};
use std::time::Instant;

use thiserror::Error;

use crate::model::{BuildError, Model};
use crate::record::{History, Recorder};
use crate::report::summary::Summary;
use crate::report::{self, ReportError};
use crate::scenario::Loaded;
use crate::scenario::resolved::{Scenario, Study};
use crate::solve::{self, Progress, SolveError};
use crate::study::monte_carlo::{self, MonteCarloResults};
use crate::study::separation_map::{self, SeparationMap};
use crate::study::speed_sweep::{self, SweepResults};

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

/// What a scenario file produces: one scene, or a study.
#[derive(Debug, Clone)]
pub enum Results {
    /// A single scene.
    Scene(Box<Outcome>),
    /// A separation map.
    SeparationMap(SeparationMap),
    /// A speed sweep.
    SpeedSweep(SweepResults),
    /// A Monte Carlo study.
    MonteCarlo(MonteCarloResults),
    /// A railway resonance check.
    ResonanceCheck(crate::study::resonance::ResonanceResults),
}

/// Runs the scenario's study if it has one, else the scene.
/// `progress` gets (done, total) in steps (scene) or grid points (study).
pub fn execute(
    loaded: Loaded,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Results, RunError> {
    match &loaded.scenario.study {
        Some(Study::SeparationMap {
            velocity_ratio,
            mass_ratio,
        }) => Ok(Results::SeparationMap(separation_map::run(
            &loaded.scenario,
            &loaded.bridge,
            velocity_ratio,
            mass_ratio,
            progress,
        )?)),
        Some(Study::SpeedSweep(sweep)) => Ok(Results::SpeedSweep(speed_sweep::run(
            &loaded.scenario,
            &loaded.bridge,
            sweep,
            progress,
        )?)),
        Some(Study::ResonanceCheck(check)) => Ok(Results::ResonanceCheck(
            crate::study::resonance::run(&loaded.scenario, &loaded.bridge, check, progress)?,
        )),
        Some(Study::MonteCarlo(mc)) => Ok(Results::MonteCarlo(monte_carlo::run(
            &loaded.scenario,
            &loaded.bridge,
            mc,
            progress,
        )?)),
        None => Ok(Results::Scene(Box::new(simulate(loaded, &mut |d, t| {
            progress(d, t)
        })?))),
    }
}

/// Summary of a separation-map study.
#[derive(Debug, Clone, serde::Serialize)]
pub struct StudySummary {
    /// Scenario name.
    pub scenario: String,
    /// Study type.
    pub study: &'static str,
    /// vbi version.
    pub vbi_version: &'static str,
    /// Wall time of all points, s.
    pub wall_time: f64,
    /// Number of grid points.
    pub points: usize,
    /// Points where the wheel lost contact.
    pub separated: usize,
    /// Velocity ratios swept.
    pub velocity_ratios: Vec<f64>,
    /// Mass ratios swept.
    pub mass_ratios: Vec<f64>,
}

/// Writes a study's `summary.json`, `study.csv`, `separation_map.png` and
/// `resolved.yaml` into `out`.
pub fn write_study(out: &Path, scenario: &Scenario, map: &SeparationMap) -> Result<(), RunError> {
    create_out(out)?;
    let summary = StudySummary {
        scenario: scenario.name.clone(),
        study: "separation_map",
        vbi_version: env!("CARGO_PKG_VERSION"),
        wall_time: map.wall_time,
        points: map.points.len(),
        separated: map.separated_count(),
        velocity_ratios: map.velocity_ratios.clone(),
        mass_ratios: map.mass_ratios.clone(),
    };
    report::write_atomic(&out.join("study.csv"), &map.to_csv())?;
    let state: Vec<bool> = map.points.iter().map(|p| p.separated).collect();
    crate::report::plot::binary_map(
        &out.join("separation_map.png"),
        &format!("{}: wheel–bridge separation", scenario.name),
        "velocity ratio v / (2 f1 L)",
        "vehicle-to-bridge mass ratio (ms + mu) / (m L)",
        &map.velocity_ratios,
        &map.mass_ratios,
        &state,
        "separated",
        "no separation",
    )?;
    report::write_atomic(
        &out.join("resolved.yaml"),
        resolved_yaml(scenario).as_bytes(),
    )?;
    let text = serde_json::to_string_pretty(&summary).expect("summary serialises") + "\n";
    report::write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}

/// Writes a speed sweep's `study.csv`, `daf_speed.png`,
/// `daf_speed_roughness.png`, `daf_map.png`, `resolved.yaml` and, last,
/// `summary.json` into `out`.
pub fn write_speed_sweep(
    out: &Path,
    scenario: &Scenario,
    results: &SweepResults,
) -> Result<(), RunError> {
    speed_sweep::write(out, scenario, results)
}

/// The default output folder of a scene: `results/` and its `name` made
/// safe as one folder name ([`crate::scenario::names::folder_name`]: no
/// separators, no `..`, not absolute, no control characters), then
/// `suffix`. A name from someone else's file therefore cannot put results
/// anywhere but under `results/`.
pub fn default_out(name: &str, suffix: &str) -> PathBuf {
    let folder = crate::scenario::names::folder_name(name);
    Path::new("results").join(format!("{folder}{suffix}"))
}

/// Creates the output folder and removes the partial files a run killed
/// from outside left there ([`report::PARTIAL_MARK`] in the name, written by
/// another process id that is no longer running here).
pub(crate) fn create_out(out: &Path) -> Result<(), RunError> {
    std::fs::create_dir_all(out).map_err(|source| ReportError::Io {
        path: out.to_path_buf(),
        source,
    })?;
    report::remove_stale_partials(out);
    Ok(())
}

/// The resolved scenario as YAML, with a header line (and, when the scene
/// knows its file, a second one naming it: [`FROM`]).
pub fn resolved_yaml(scenario: &Scenario) -> String {
    let resolved = serde_json::to_value(scenario).expect("scenario serialises");
    let from = scenario.source_file.as_ref().map_or_else(String::new, |f| {
        // One line whatever the name holds.
        let f: String = f.chars().filter(|c| !c.is_control()).collect();
        format!("{FROM}{f}\n")
    });
    format!(
        "# Resolved by vbi {}: the scene as run, every default filled in.\n{from}{}",
        env!("CARGO_PKG_VERSION"),
        report::yaml::to_yaml(&resolved)
    )
}

/// The start of `resolved.yaml`'s line that names the scene file whose
/// results the folder holds.
pub const FROM: &str = "# From: ";

/// The file that names a folder's scene where no `resolved.yaml` does:
/// `vbi converge`'s folder and the `--shard` parts' folder hold one line,
/// [`FROM`] and the scene file ([`mark_folder`]).
pub const OWNER_FILE: &str = ".vbi-owner";

/// The scene file whose results the folder `out` holds, as its
/// `resolved.yaml` names it, or else its [`OWNER_FILE`]; `None` when there
/// is none or it names none. Only each file's first 8 kB are read (the
/// header is its first lines).
pub fn folder_owner(out: &Path) -> Option<String> {
    use std::io::Read;
    let named_in = |name: &str| -> Option<String> {
        let file = crate::scenario::data_files::open_regular(&out.join(name)).ok()?;
        let mut head = Vec::new();
        file.take(8192).read_to_end(&mut head).ok()?;
        let head = String::from_utf8_lossy(&head);
        head.lines()
            .take(3)
            .find_map(|l| l.strip_prefix(FROM))
            .map(str::to_string)
    };
    named_in("resolved.yaml").or_else(|| named_in(OWNER_FILE))
}

/// Writes the [`OWNER_FILE`] naming `source` (canonical) into `out` (made
/// if missing): the folder's results are that scene file's, so another
/// scene's `vbi run`, `converge` or `--shard` into it is refused
/// ([`claim_folder`]).
pub fn mark_folder(out: &Path, source: &str) -> std::io::Result<()> {
    std::fs::create_dir_all(out)?;
    let source: String = source.chars().filter(|c| !c.is_control()).collect();
    crate::report::write_atomic(
        &out.join(OWNER_FILE),
        format!("{FROM}{source}\n").as_bytes(),
    )
    .map_err(std::io::Error::other)
}

/// Refuses to write the results of the scene file `source` (canonical) into
/// `out` when the folder holds another scene file's results (issue 22: two
/// scenes must not mix their files in one folder); `force` allows it.
pub fn claim_folder(out: &Path, source: &str, force: bool) -> Result<(), String> {
    match folder_owner(out) {
        Some(owner) if owner != source && !force => Err(format!(
            "{} holds the results of another scene file, {owner}; give this one its own folder \
             with `--out DIR`, or replace them with `--force`",
            out.display()
        )),
        _ => Ok(()),
    }
}

/// The name a scene file is known by in `resolved.yaml`: its canonical
/// path (symlinks resolved), or its absolute path when that fails.
pub fn source_name(file: &Path) -> String {
    std::fs::canonicalize(file)
        .or_else(|_| std::path::absolute(file))
        .unwrap_or_else(|_| file.to_path_buf())
        .display()
        .to_string()
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
    // EMBS with its first order also records the zero order alone, for
    // the a-posteriori check of the expansion (report::embs).
    let mut zero_order = match model.embs {
        Some(e)
            if e.first_order && model.method == crate::scenario::resolved::SolverMethod::Embs =>
        {
            Some(
                Recorder::new(&model, &scenario.record)
                    .map_err(BuildError::from)?
                    .every(scenario.output.every),
            )
        }
        _ => None,
    };
    let solve_start = Instant::now();
    let stats = match zero_order.as_mut() {
        Some(zero) => solve::embs::run_orders(&model, &mut recorder, Some(zero), progress)
            .map(|()| solve::SolveStats::default())?,
        None => solve::run(&model, &mut recorder, progress)?,
    };
    let solve_time = solve_start.elapsed().as_secs_f64();
    let zero_order = zero_order.map(Recorder::finish);
    let history = recorder.finish_spilled().map_err(io)?;
    let wall_time = start.elapsed().as_secs_f64();
    let mut summary = Summary::new(&scenario.name, &model, &history, &stats, wall_time);
    if model.method == crate::scenario::resolved::SolverMethod::Embs {
        // The same model and records through `coupled`, as the reference.
        let reference = if compare {
            let mut coupled = Recorder::new(&model, &scenario.record)
                .map_err(BuildError::from)?
                .every(scenario.output.every);
            let coupled_start = Instant::now();
            solve::coupled::run(&model, &mut coupled, &mut |_, _| {})?;
            let coupled_time = coupled_start.elapsed().as_secs_f64();
            Some((coupled.finish(), coupled_time))
        } else {
            None
        };
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
    Ok(Outcome {
        model,
        history,
        summary,
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

/// [`execute`] with a single scene's rows streamed to the output folder
/// `out` ([`simulate_into`]); studies run as in [`execute`].
pub fn execute_into(
    loaded: Loaded,
    out: &Path,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Results, RunError> {
    if loaded.scenario.study.is_some() {
        return execute(loaded, progress);
    }
    Ok(Results::Scene(Box::new(simulate_into(
        loaded,
        out,
        &mut |d, t| progress(d, t),
    )?)))
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
            crate::record::envelope::envelope_csv(envelope).as_bytes(),
        )?;
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
