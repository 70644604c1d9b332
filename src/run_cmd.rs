//! `vbi run` of one scene and `vbi check`: loading, running with a
//! progress bar, writing the results, and the exit codes of bad input.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::studies::{self, write_study};
use super::{EXIT_FAILED, EXIT_INVALID, deny_warnings, emit, print_advice_located};
use vbi::plan;
use vbi::scenario::LoadError;

/// The default output folder: `results/<file stem><suffix>`. From the file,
/// not the scene's `name`: two files that share a `name` do not overwrite
/// each other's results, and a `name` with `/` or `..` cannot lead outside
/// `results/`.
pub(super) fn default_out(file: &Path, suffix: &str) -> PathBuf {
    let stem = file
        .file_stem()
        .map_or_else(|| "scene".into(), |s| s.to_string_lossy());
    Path::new("results").join(format!("{stem}{suffix}"))
}

pub(super) fn load_error(e: &LoadError) -> ExitCode {
    errln!("error: {e}");
    match e {
        LoadError::Io { .. } => ExitCode::from(EXIT_INVALID),
        LoadError::Invalid(_) => ExitCode::from(EXIT_INVALID),
    }
}

pub(super) fn run(
    loaded: Result<plan::Loaded, LoadError>,
    file: &Path,
    out: Option<PathBuf>,
    quiet: bool,
    svg: bool,
    force: bool,
) -> ExitCode {
    let mut loaded = match loaded {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    let out = out.unwrap_or_else(|| default_out(file, ""));
    // The folder is claimed before the work: another scene's results in it
    // are not mixed with these.
    let source = vbi::run::source_name(file);
    if let Err(message) = vbi::run::claim_folder(&out, &source, force) {
        errln!("error: {message}");
        return ExitCode::from(EXIT_INVALID);
    }
    loaded.scenario.source_file = Some(source);
    let scenario = loaded.scenario.clone();
    // The scene's own advice before the work, so that a long run's
    // warning is read before it ends; the run's after it.
    let before = vbi::plan::advice::scene_advice(&scenario);
    print_advice_located(file, &before);
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        // No length until the run reports one: a bar of length 0 reads
        // 100 % (indicatif), which flashed before every run's first step.
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} {msg} [{bar:30}] {percent}% eta {eta}")
                .expect("valid template")
                .progress_chars("=> "),
        );
        bar.set_message(scenario.name.clone());
        bar
    };
    let progress = |done: usize, total: usize| studies::advance(&bar, done, total);
    let results = match vbi::execute::execute_into(loaded, &out, &progress) {
        Ok(r) => r,
        Err(e) => {
            bar.abandon();
            errln!("error: {}: {e}", file.display());
            return ExitCode::from(EXIT_FAILED);
        }
    };
    bar.finish_and_clear();
    let outcome = match results {
        vbi::execute::Results::Scene(outcome) => outcome,
        study => {
            let code = write_study(&out, &scenario, &study, quiet);
            let advice = study.advice(&scenario);
            print_advice_located(file, &advice[before.len().min(advice.len())..]);
            return deny_warnings(&advice, code);
        }
    };
    if let Err(e) = vbi::run::write_results_with(&out, &scenario, &outcome, svg) {
        errln!("error: {e}");
        return ExitCode::from(EXIT_FAILED);
    }
    let advice = &outcome.summary.advice;
    let after: Vec<_> = advice
        .iter()
        .filter(|a| !before.contains(a))
        .cloned()
        .collect();
    print_advice_located(file, &after);
    if !quiet {
        let s = &outcome.summary;
        errln!(
            "{}: {} steps of {:.3e} s, {} modes, {:.1} ms",
            s.scenario,
            s.run.steps,
            s.run.time_step,
            s.run.modes_used,
            s.run.wall_time * 1e3
        );
        for q in &s.quantities {
            let daf = q.daf.map(|d| format!("  DAF {d:.4}")).unwrap_or_default();
            errln!(
                "  {:<24} max|.| {:>12.5e} {} at t = {:.4} s{daf}",
                q.name,
                q.max_abs.value,
                q.unit,
                q.max_abs.time
            );
        }
        for peak in &s.envelope_peaks {
            for (what, at) in [("max", &peak.max), ("min", &peak.min)] {
                let daf = at.daf.map(|d| format!("  DAF {d:.4}")).unwrap_or_default();
                let side = if at.side == vbi::scene::Side::Left {
                    " (left)"
                } else {
                    ""
                };
                let support = if at.support { ", a support" } else { "" };
                errln!(
                    "  envelope {:<17} {what} {:>12.5e} {} at x = {:.3} m{side}{support}, t = {:.4} s{daf}",
                    peak.quantity,
                    at.value,
                    peak.unit,
                    at.x,
                    at.time
                );
            }
        }
        errln!("results in {}", out.display());
    }
    deny_warnings(advice, ExitCode::SUCCESS)
}

pub(super) fn check(
    files: &[PathBuf],
    load: &dyn Fn(&Path) -> Result<plan::Loaded, LoadError>,
    shards: Option<u64>,
    allow_large: bool,
) -> ExitCode {
    let mut invalid = false;
    let mut advice = Vec::new();
    for file in files {
        match load(file) {
            Ok(loaded) => {
                if let Some(count) = shards {
                    let name = file.display().to_string();
                    let count = usize::try_from(count).unwrap_or(usize::MAX);
                    match vbi::study::shard::check_shards(&loaded, &name, count, allow_large) {
                        Ok((study, size)) => {
                            outln!("{name}: ok ({study} study of {size} runs, {count} shards)")
                        }
                        Err(e) => {
                            invalid = true;
                            errln!("error: {e}");
                        }
                    }
                    continue;
                }
                outln!("{}: ok", file.display());
                let own = vbi::plan::advice::scene_advice(&loaded.scenario);
                print_advice_located(file, &own);
                advice.extend(own);
            }
            Err(e) => {
                invalid = true;
                errln!("error: {e}");
            }
        }
    }
    if invalid {
        ExitCode::from(EXIT_INVALID)
    } else {
        deny_warnings(&advice, ExitCode::SUCCESS)
    }
}
