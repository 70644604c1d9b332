//! `vbi._vbi`: the Rust side of the Python package. It loads a scene (a
//! file path or YAML text), runs it with the GIL released, and hands the
//! results back as plain Python objects and numpy arrays; the pure-Python
//! layer (`python/vbi/__init__.py`) turns them into pandas DataFrames.
//!
//! Nothing here prints: errors become Python exceptions, progress goes to
//! the caller's callback.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use vbi::execute::{Results, execute};
use vbi::plan::{self, Loaded};
use vbi::run::RunError;
use vbi::scenario::{LoadError, LoadOptions};
use vbi::solve::SolveError;
use vbi::solve::cancel::CancelToken;

pyo3::create_exception!(
    _vbi,
    InvalidScene,
    PyValueError,
    "A scene failed its checks; args[0] is the list of diagnostics as \
     (file, line, column, message, rendered) tuples."
);

/// How often the caller's thread takes the GIL during a run to check for
/// Ctrl-C and call the progress callback: often enough that Ctrl-C feels
/// immediate, rarely enough that nothing else notices.
const SIGNAL_CHECK_INTERVAL: Duration = Duration::from_millis(100);

/// Where a scene comes from: a file (`kind = "path"`) or YAML text
/// (`kind = "text"`, labelled `name` in diagnostics and resolving data files
/// against the current folder).
fn source_of(kind: &str, scene: &str, name: &str) -> PyResult<Source> {
    match kind {
        "path" => Ok(Source::Path(PathBuf::from(scene))),
        "text" => Ok(Source::Text {
            text: scene.to_owned(),
            name: name.to_owned(),
        }),
        other => Err(PyValueError::new_err(format!(
            "unknown scene kind {other:?} (expected \"path\" or \"text\")"
        ))),
    }
}

enum Source {
    Path(PathBuf),
    Text { text: String, name: String },
}

impl Source {
    fn load(&self) -> Result<Loaded, LoadError> {
        match self {
            Source::Path(path) => plan::load_file(path),
            Source::Text { text, name } => plan::load_str(text, name),
        }
    }
}

/// A load error as a Python exception: every diagnostic for an invalid
/// scene, `OSError` for an unreadable file.
fn load_error(error: LoadError) -> PyErr {
    match error {
        LoadError::Io { .. } => PyOSError::new_err(error.to_string()),
        LoadError::Invalid(diagnostics) => {
            let items: Vec<(String, usize, usize, String, String)> = diagnostics
                .iter()
                .map(|d| {
                    (
                        d.file.clone(),
                        d.loc.line,
                        d.loc.col,
                        d.message.clone(),
                        d.to_string(),
                    )
                })
                .collect();
            InvalidScene::new_err((items,))
        }
    }
}

/// True when a run error is the cancellation asked for by the progress
/// path (possibly inside a failed Monte Carlo sample).
fn is_cancelled(error: &RunError) -> bool {
    match error {
        RunError::Solve(SolveError::Cancelled) => true,
        RunError::Sample { source, .. } => is_cancelled(source),
        _ => false,
    }
}

/// Checks a scene and returns its resolved YAML; raises `InvalidScene`.
#[pyfunction]
#[pyo3(signature = (kind, scene, name = "<string>"))]
fn check(py: Python<'_>, kind: &str, scene: &str, name: &str) -> PyResult<String> {
    let source = source_of(kind, scene, name)?;
    let loaded = py.detach(|| source.load()).map_err(load_error)?;
    Ok(vbi::run::resolved_yaml(&loaded.scenario))
}

/// Runs a scene or its study with the GIL released. The run goes on a
/// worker thread while the calling thread waits without the GIL and, every
/// 0.1 s, takes it to check for Ctrl-C (Python runs signal handlers only on
/// the main thread, so the check must happen on the caller's thread) and to
/// call `progress(done, total)` when it moved. Ctrl-C, or an exception in
/// the callback, cancels the run ([`vbi::solve::cancel`]) and is raised.
/// `workdir` is an empty folder where a study writes its tables (read back
/// by the caller).
#[pyfunction]
#[pyo3(signature = (kind, scene, name = "<string>", progress = None, workdir = None))]
fn run<'py>(
    py: Python<'py>,
    kind: &str,
    scene: &str,
    name: &str,
    progress: Option<Py<PyAny>>,
    workdir: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let source = source_of(kind, scene, name)?;
    let loaded = py.detach(|| source.load()).map_err(load_error)?;
    let scenario = loaded.scenario.clone();
    let token = CancelToken::new();
    let done = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    let on_progress = |d: usize, t: usize| {
        // Study points finish out of order: keep the largest count.
        done.fetch_max(d, Ordering::Relaxed);
        total.store(t, Ordering::Relaxed);
    };
    let (finished, wait) = mpsc::channel::<()>();
    let wait = Mutex::new(wait);
    // The first error raised on the caller's side (KeyboardInterrupt, or
    // the callback's own), re-raised once the run has stopped.
    let mut raised: Option<PyErr> = None;
    let results = std::thread::scope(|s| {
        let worker = s.spawn(|| {
            let results = token.scope(|| execute(loaded, &on_progress));
            let _ = finished.send(());
            results
        });
        let mut reported = (0, 0);
        loop {
            let over = py.detach(|| {
                !matches!(
                    wait.lock()
                        .expect("wait lock")
                        .recv_timeout(SIGNAL_CHECK_INTERVAL),
                    Err(RecvTimeoutError::Timeout)
                )
            });
            if raised.is_none() {
                let now = (done.load(Ordering::Relaxed), total.load(Ordering::Relaxed));
                let result = py.check_signals().and_then(|()| match &progress {
                    Some(callback) if now != reported && now.1 > 0 => {
                        reported = now;
                        callback.call1(py, now).map(drop)
                    }
                    _ => Ok(()),
                });
                if let Err(e) = result {
                    raised = Some(e);
                    token.cancel();
                }
            }
            if over {
                break;
            }
        }
        worker
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    });
    if let Some(e) = raised {
        return Err(e);
    }
    let results = match results {
        Ok(results) => results,
        Err(e) if is_cancelled(&e) => {
            return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(
                "the run was cancelled",
            ));
        }
        Err(e) => return Err(PyRuntimeError::new_err(e.to_string())),
    };
    let out = PyDict::new(py);
    out.set_item("resolved", vbi::run::resolved_yaml(&scenario))?;
    out.set_item(
        "advice",
        serde_json::to_string(&results.advice(&scenario)).expect("advice serialises"),
    )?;
    match results {
        Results::Scene(outcome) => {
            out.set_item("kind", "scene")?;
            scene_results(py, &out, *outcome)?;
        }
        study => {
            out.set_item("kind", "study")?;
            let Some(dir) = workdir else {
                return Err(PyValueError::new_err("a study needs a workdir"));
            };
            py.detach(|| write_study(&dir, &scenario, &study))
                .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        }
    }
    Ok(out)
}

/// A study's files, written by the same code as `vbi run`.
fn write_study(
    out: &Path,
    scenario: &vbi::scene::Scenario,
    results: &Results,
) -> Result<(), RunError> {
    use vbi::study;
    match results {
        Results::Scene(_) => unreachable!("a study's results"),
        Results::SeparationMap(map) => study::separation_map::write(out, scenario, map),
        Results::SpeedSweep(sweep) => study::speed_sweep::write(out, scenario, sweep),
        Results::MonteCarlo(mc) => study::monte_carlo::write(out, scenario, mc),
        Results::ResonanceCheck(check) => study::resonance::write(out, scenario, check),
    }
}

/// A single scene's results: the history as arrays (the recorded vectors
/// handed to numpy as they are, not copied), the summary as JSON text, and
/// the report layer's tables as CSV text (the same bytes `vbi run` writes).
fn scene_results(
    py: Python<'_>,
    out: &Bound<'_, PyDict>,
    mut outcome: vbi::run::Outcome,
) -> PyResult<()> {
    use vbi::report::history_files::{clean_time, each_row, time_decimals};
    // The time stamps exactly as history.csv writes them.
    let decimals = time_decimals(outcome.model.time_step);
    let history = &mut outcome.history;
    let mut time = std::mem::take(&mut history.time);
    let mut taken: Vec<(Vec<f64>, Option<Vec<f64>>)> = history
        .columns
        .iter_mut()
        .map(|c| (std::mem::take(&mut c.values), c.static_values.take()))
        .collect();
    if history.spilled.is_some() {
        // A streamed history is read back from its file.
        time.clear();
        for (values, statics) in &mut taken {
            values.clear();
            if let Some(s) = statics {
                s.clear();
            }
        }
        each_row(history, |row| {
            time.push(row[0]);
            let mut k = 1;
            for (values, statics) in &mut taken {
                values.push(row[k]);
                k += 1;
                if let Some(s) = statics {
                    s.push(row[k]);
                    k += 1;
                }
            }
        })
        .map_err(|e| PyOSError::new_err(e.to_string()))?;
    }
    for t in &mut time {
        *t = clean_time(*t, decimals);
    }
    out.set_item("time", time.into_pyarray(py))?;
    let columns = PyList::empty(py);
    for (c, (values, statics)) in history.columns.iter().zip(taken) {
        columns.append((
            c.name.as_str(),
            c.unit,
            values.into_pyarray(py),
            statics.map(|s| s.into_pyarray(py)),
        ))?;
    }
    out.set_item("columns", columns)?;
    let history = &outcome.history;
    let summary =
        serde_json::to_string_pretty(&outcome.summary).expect("summary serialises") + "\n";
    out.set_item("summary", summary)?;
    out.set_item(
        "separation",
        serde_json::to_string(&history.separation).expect("separation serialises"),
    )?;
    if let Some(envelope) = &history.envelope {
        out.set_item(
            "envelopes_csv",
            vbi::report::envelopes::envelope_csv(envelope),
        )?;
    }
    if outcome.model.bridge.width().is_some() {
        out.set_item(
            "daf_table_csv",
            vbi::report::girder_daf_csv(&history.girder_dafs),
        )?;
    }
    Ok(())
}

/// The bridge's modes: frequencies (Hz), circular frequencies (rad/s),
/// damping ratios and the mass-normalised shapes (1/√kg) sampled at the
/// mesh nodes and mid-element points (points × modes), as `vbi modes
/// --shapes` writes them.
#[pyfunction]
#[pyo3(signature = (kind, scene, name = "<string>"))]
fn modes<'py>(
    py: Python<'py>,
    kind: &str,
    scene: &str,
    name: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let source = source_of(kind, scene, name)?;
    let loaded = py
        .detach(|| match &source {
            Source::Path(path) => plan::load_file_for_modes(path, trusted()),
            Source::Text { text, name } => plan::bridge_only::load_for_modes(text, name, trusted()),
        })
        .map_err(load_error)?;
    let bridge = &loaded.bridge;
    let count = bridge.mode_count();
    let lines = match bridge.width() {
        None => vec![0.0],
        Some(b) => vec![0.0, 0.5 * b, b],
    };
    let nodes = bridge.node_x();
    let mut points = Vec::with_capacity(2 * nodes.len());
    for (i, &x) in nodes.iter().enumerate() {
        if i > 0 {
            points.push(0.5 * (nodes[i - 1] + x));
        }
        points.push(x);
    }
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    let mut shapes = Vec::new();
    let mut values = vec![0.0; count];
    for &y in &lines {
        for &x in &points {
            bridge.mode_values(x, y, &mut values);
            xs.push(x);
            ys.push(y);
            shapes.extend_from_slice(&values);
        }
    }
    let rows = xs.len();
    let shapes = Array2::from_shape_vec((rows, count), shapes)
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    let out = PyDict::new(py);
    out.set_item("name", &loaded.name)?;
    out.set_item("frequency", bridge.frequencies().into_pyarray(py))?;
    out.set_item(
        "circular_frequency",
        PyArray1::from_slice(py, &bridge.circular_frequencies),
    )?;
    out.set_item(
        "damping_ratio",
        PyArray1::from_slice(py, &bridge.damping_ratios),
    )?;
    out.set_item("x", xs.into_pyarray(py))?;
    out.set_item("y", bridge.width().map(|_| ys.into_pyarray(py)))?;
    out.set_item("shapes", shapes.into_pyarray(py))?;
    let characters: Vec<String> = (0..count)
        .map(|i| bridge.mode_character(i).to_string())
        .collect();
    out.set_item("character", characters)?;
    Ok(out)
}

/// The load options of `plan::load_file`: the file's own `limits` apply.
fn trusted() -> LoadOptions {
    LoadOptions {
        trust_limits: true,
        ..LoadOptions::default()
    }
}

/// The Rust extension of the `vbi` package.
#[pymodule]
fn _vbi(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(modes, m)?)?;
    m.add("InvalidScene", m.py().get_type::<InvalidScene>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
