//! Golden-file regression for the user's own scenes (issue 30):
//! `vbi regress approve SCENES… --store DIR` runs the scenes and writes a
//! golden record of each into the store; `vbi regress check` re-runs them
//! and compares, quantity by quantity, against tolerances relative to each
//! quantity's peak ([`settings`]), and tells a changed scene from changed
//! results.
//!
//! The store holds one folder per scene, named after the scene file's stem:
//! `record.tsv` ([`record`]: summary, decimated history, study tables) and
//! `resolved.yaml` (the resolved scene, to show what changed in it), and
//! optionally `regress.yaml` (tolerances). Scenes run in parallel (rayon);
//! results come back in the order the scenes were given.

pub mod compare;
pub mod record;
pub mod report;
pub mod settings;

use std::path::{Path, PathBuf};
use std::time::Instant;

use rayon::prelude::*;

use crate::scenario::LoadOptions;
use compare::Comparison;
use record::Record;
use settings::Settings;

/// The name of a scene's record file in its store folder.
pub const RECORD_FILE: &str = "record.tsv";
/// The name of a scene's resolved scene in its store folder.
pub const RESOLVED_FILE: &str = "resolved.yaml";

/// Errors that stop a whole `vbi regress` command (one scene's failure
/// does not: it is that scene's [`Verdict::CouldNotRun`]).
#[derive(Debug, thiserror::Error)]
pub enum RegressError {
    /// `regress.yaml` is unreadable or invalid.
    #[error("{0}")]
    Settings(String),
    /// A scene file's stem cannot name a folder of the store.
    #[error(
        "{file}: its name gives the store key `{key}`, which cannot name a folder of the \
         store ({why})\n  = help: rename the scene file (e.g. `scene.yaml`)"
    )]
    BadKey {
        /// The scene file, escaped.
        file: String,
        /// The key, escaped.
        key: String,
        /// Why not.
        why: &'static str,
    },
    /// Two scene files would share one store folder.
    #[error("{first} and {second} share the name `{key}` in the store: give one another file name")]
    SameKey {
        /// The name.
        key: String,
        /// One file.
        first: String,
        /// The other.
        second: String,
    },
}

/// The key of a scene file in the store: its file stem.
pub fn scene_key(file: &Path) -> String {
    file.file_stem()
        .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned())
}

/// A scene run to its record.
#[derive(Debug, Clone)]
pub struct Ran {
    /// The resolved scene, without its comment header.
    pub resolved: String,
    /// Its record.
    pub record: Record,
    /// Wall time of the run, s.
    pub seconds: f64,
}

/// Loads and runs the scene `file` into its record.
pub fn run_scene(file: &Path, options: &LoadOptions, bins: usize) -> Result<Ran, String> {
    let start = Instant::now();
    let loaded = crate::plan::load_file_with(file, options.clone()).map_err(|e| e.to_string())?;
    let resolved = canonical_scene(&loaded.scenario);
    let scenario = loaded.scenario.clone();
    let results = crate::execute::execute(loaded, &|_, _| {})
        .map_err(|e| format!("{}: {e}", file.display()))?;
    let advice = results.advice(&scenario);
    let record = Record::new(&scene_key(file), &resolved, &results, &advice, bins);
    Ok(Ran {
        resolved,
        record,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Significant digits of the numbers of the resolved scene in the store
/// and its hash: a scene edit below 1e-12 relative (a number printed
/// another way by a tool, a round-off in a derived value) is not a change
/// of the scene; its effect on the results is judged by the tolerances.
pub const SCENE_DIGITS: usize = 12;

/// The resolved scene as YAML (every default filled in, as in a run's
/// `resolved.yaml`), without the header that names the version and the
/// file, its numbers rounded to [`SCENE_DIGITS`] significant digits.
pub fn canonical_scene(scenario: &crate::scenario::resolved::Scenario) -> String {
    fn round(value: &mut serde_json::Value) {
        match value {
            serde_json::Value::Number(n) if n.is_f64() => {
                let x = n.as_f64().unwrap_or(f64::NAN);
                let rounded: f64 = format!("{:.*e}", SCENE_DIGITS - 1, x).parse().unwrap_or(x);
                if let Some(r) = serde_json::Number::from_f64(rounded) {
                    *n = r;
                }
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(round),
            serde_json::Value::Object(map) => map.values_mut().for_each(round),
            _ => {}
        }
    }
    let mut value = serde_json::to_value(scenario).unwrap_or(serde_json::Value::Null);
    round(&mut value);
    crate::report::yaml::to_yaml(&value)
}

/// The largest `record.tsv` or approved `resolved.yaml` read from a store,
/// bytes: a record of the maximum 100,000 history bins of a few dozen
/// columns is some 50 MB; a link to `/dev/zero` or a 3 GB sparse file is
/// refused before it is read.
pub const MAX_RECORD_BYTES: u64 = 256 << 20;

/// Each scene's store key is a plain folder name (never `.`, `..` or a
/// path: a scene file `...yaml` has the stem `..`, which would put its
/// record in the store's parent), and no two scenes share one.
fn check_keys(files: &[PathBuf]) -> Result<(), RegressError> {
    let mut seen: Vec<(String, &PathBuf)> = Vec::new();
    for f in files {
        let key = scene_key(f);
        if let Some(why) = crate::guarded_file::plain_name_fault(&key) {
            return Err(RegressError::BadKey {
                file: crate::guarded_file::shown(f),
                key: crate::guarded_file::escape_controls(&key),
                why,
            });
        }
        if let Some((_, first)) = seen.iter().find(|(k, _)| *k == key) {
            return Err(RegressError::SameKey {
                key: crate::guarded_file::escape_controls(&key),
                first: crate::guarded_file::shown(first),
                second: crate::guarded_file::shown(f),
            });
        }
        seen.push((key, f));
    }
    Ok(())
}

/// What `approve` did with one scene.
#[derive(Debug, Clone, PartialEq)]
pub enum Approved {
    /// No record before.
    New,
    /// The record changed.
    Updated,
    /// The same record as before.
    Unchanged,
    /// The scene did not run (the message says why); its record is kept.
    CouldNotRun(String),
}

/// Runs `files` (in parallel) and writes their records into `store`.
pub fn approve(
    files: &[PathBuf],
    store: &Path,
    options: &LoadOptions,
) -> Result<Vec<Approved>, RegressError> {
    check_keys(files)?;
    let settings = Settings::load(store).map_err(RegressError::Settings)?;
    crate::guarded_file::no_link(store)
        .and_then(|()| {
            std::fs::create_dir_all(store).map_err(|e| crate::guarded_file::GuardError::Io {
                path: crate::guarded_file::shown(store),
                reason: e.to_string(),
                kind: e.kind(),
            })
        })
        .map_err(|e| RegressError::Settings(e.to_string()))?;
    let runs: Vec<Result<Ran, String>> = files
        .par_iter()
        .map(|f| run_scene(f, options, settings.history_bins))
        .collect();
    Ok(files
        .iter()
        .zip(runs)
        .map(|(file, ran)| match ran {
            Ok(ran) => {
                write_record(store, &scene_key(file), &ran).unwrap_or_else(Approved::CouldNotRun)
            }
            Err(e) => Approved::CouldNotRun(e),
        })
        .collect())
}

/// Writes a scene's record into its own folder of the store: a real
/// folder (a link there is refused, not written through), whose files are
/// replaced atomically (a link in a file's place is replaced, not
/// followed).
fn write_record(store: &Path, key: &str, ran: &Ran) -> Result<Approved, String> {
    use crate::guarded_file as guarded;
    let folder = guarded::own_folder(store, key).map_err(|e| e.to_string())?;
    let path = folder.join(RECORD_FILE);
    let text = ran.record.to_text();
    let before = match guarded::no_link(&path)
        .and_then(|()| guarded::read_text_bounded(&path, MAX_RECORD_BYTES))
    {
        Ok(before) => Some(before),
        Err(e) if e.is_not_found() => None,
        // A record that cannot be read (a pipe, a huge file) is replaced.
        Err(_) => Some(String::new()),
    };
    if before.as_deref() == Some(text.as_str()) {
        return Ok(Approved::Unchanged);
    }
    crate::report::write_atomic(&folder.join(RESOLVED_FILE), ran.resolved.as_bytes())
        .map_err(|e| e.to_string())?;
    crate::report::write_atomic(&path, text.as_bytes()).map_err(|e| e.to_string())?;
    Ok(if before.is_some() {
        Approved::Updated
    } else {
        Approved::New
    })
}

/// The verdict on one scene.
#[derive(Debug, Clone)]
pub enum Verdict {
    /// Scene and results as approved (within tolerance).
    Pass,
    /// The scene or its results changed.
    Changed,
    /// The scene did not run, or has no readable record.
    CouldNotRun(String),
}

/// The check of one scene.
#[derive(Debug, Clone)]
pub struct SceneCheck {
    /// The scene file.
    pub file: PathBuf,
    /// Its key in the store.
    pub key: String,
    /// The verdict.
    pub verdict: Verdict,
    /// The comparison, when both records exist.
    pub comparison: Option<Comparison>,
    /// The diff of the resolved scene (approved → now) when it changed.
    pub scene_diff: Vec<String>,
    /// The golden and the new record (for the plots).
    pub records: Option<(Record, Record)>,
    /// Wall time of the run, s.
    pub seconds: f64,
}

/// Re-runs `files` (in parallel) and compares them with their records in
/// `store`; the checks in the order of `files`.
pub fn check(
    files: &[PathBuf],
    store: &Path,
    options: &LoadOptions,
) -> Result<Vec<SceneCheck>, RegressError> {
    check_keys(files)?;
    let settings = Settings::load(store).map_err(RegressError::Settings)?;
    Ok(files
        .par_iter()
        .map(|f| check_one(f, store, options, &settings))
        .collect())
}

fn check_one(file: &Path, store: &Path, options: &LoadOptions, settings: &Settings) -> SceneCheck {
    let key = scene_key(file);
    let mut result = SceneCheck {
        file: file.to_path_buf(),
        key: key.clone(),
        verdict: Verdict::Pass,
        comparison: None,
        scene_diff: Vec::new(),
        records: None,
        seconds: 0.0,
    };
    let folder = store.join(&key);
    let record_path = folder.join(RECORD_FILE);
    let old = match crate::guarded_file::read_own_text(&folder, RECORD_FILE, MAX_RECORD_BYTES) {
        Ok(text) => Record::from_text(&text)
            .map_err(|e| format!("{}: {e}", crate::guarded_file::shown(&record_path))),
        Err(e) if e.is_not_found() => Err(format!(
            "no golden record {}: approve the scene first with `vbi regress approve`",
            crate::guarded_file::shown(&record_path)
        )),
        Err(e) => Err(format!("the golden record cannot be read: {e}")),
    };
    let old = match old {
        Ok(r) => r,
        Err(e) => {
            result.verdict = Verdict::CouldNotRun(e);
            return result;
        }
    };
    // The approved resolution, so that old and new bins align.
    let ran = match run_scene(file, options, old.history_bins) {
        Ok(r) => r,
        Err(e) => {
            result.verdict = Verdict::CouldNotRun(e);
            return result;
        }
    };
    result.seconds = ran.seconds;
    let comparison = compare::compare(&key, &old, &ran.record, settings);
    if comparison.scene_changed {
        let approved = crate::guarded_file::read_own_text(&folder, RESOLVED_FILE, MAX_RECORD_BYTES)
            .unwrap_or_default();
        result.scene_diff = compare::line_diff(&approved, &ran.resolved, 200);
    }
    if comparison.scene_changed || !comparison.results_pass() {
        result.verdict = Verdict::Changed;
    }
    result.comparison = Some(comparison);
    result.records = Some((old, ran.record));
    result
}
