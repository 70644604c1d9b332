//! One scene end to end: build → solve → record → report.

use std::path::Path;
use std::time::Instant;

use thiserror::Error;

use crate::model::{BuildError, Model};
use crate::record::{History, Recorder};
use crate::report::summary::Summary;
use crate::report::{self, ReportError};
use crate::scenario::Loaded;
use crate::solve::{self, Progress, SolveError};

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
    let start = Instant::now();
    let Loaded { scenario, bridge } = loaded;
    let model = Model::build(&scenario, bridge)?;
    let mut recorder = Recorder::new(&model, &scenario.record).map_err(BuildError::from)?;
    solve::run(&model, &mut recorder, progress)?;
    let history = recorder.finish();
    let wall_time = start.elapsed().as_secs_f64();
    let summary = Summary::new(&scenario.name, &model, &history, wall_time);
    Ok(Outcome {
        model,
        history,
        summary,
    })
}

/// Writes `summary.json`, `history.csv` and `resolved.yaml` into `out`
/// (created if needed), each atomically.
pub fn write_results(
    out: &Path,
    scenario: &crate::scenario::resolved::Scenario,
    outcome: &Outcome,
) -> Result<(), RunError> {
    std::fs::create_dir_all(out).map_err(|source| ReportError::Io {
        path: out.to_path_buf(),
        source,
    })?;
    let summary =
        serde_json::to_string_pretty(&outcome.summary).expect("summary serialises") + "\n";
    let resolved = serde_json::to_value(scenario).expect("scenario serialises");
    let yaml = format!(
        "# Resolved by vbi {}: the scene as run, every default filled in.\n{}",
        env!("CARGO_PKG_VERSION"),
        report::yaml::to_yaml(&resolved)
    );
    report::write_atomic(
        &out.join("history.csv"),
        &report::history_csv(&outcome.history),
    )?;
    report::write_atomic(&out.join("resolved.yaml"), yaml.as_bytes())?;
    // summary.json last: its presence means the run's results are complete.
    report::write_atomic(&out.join("summary.json"), summary.as_bytes())?;
    Ok(())
}
