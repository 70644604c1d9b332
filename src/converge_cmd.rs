//! `vbi converge`: runs a scene at refined settings and prints the
//! convergence table.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::run_cmd::{default_out, load_error};
use super::{EXIT_FAILED, EXIT_INVALID, deny_warnings, emit, print_advice_located};
use vbi::plan;
use vbi::scenario::LoadError;

#[allow(clippy::too_many_arguments)]
pub(super) fn converge(
    loaded: Result<plan::Loaded, LoadError>,
    file: &Path,
    tolerance: f64,
    levels: usize,
    out: Option<PathBuf>,
    quiet: bool,
    exclude: Vec<String>,
    force: bool,
) -> ExitCode {
    use vbi::study::converge::{self as study, ConvergeError, Options};
    let loaded = match loaded {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    let out = out.unwrap_or_else(|| default_out(file, "-converge"));
    // As `vbi run`: the folder is claimed before the work.
    let source = vbi::run::source_name(file);
    if let Err(message) = vbi::run::claim_folder(&out, &source, force) {
        errln!("error: {message}");
        return ExitCode::from(EXIT_INVALID);
    }
    if loaded.scenario.study.is_some() && !quiet {
        errln!(
            "note: {}: the study section is ignored; converging the base scene",
            file.display()
        );
    }
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} run {pos}/{len} {msg}")
                .expect("valid template"),
        );
        bar
    };
    let mut progress = |index: usize, total: usize, label: &str| {
        bar.set_length(total as u64);
        bar.set_position(index as u64 + 1);
        bar.set_message(label.to_string());
    };
    let options = Options {
        levels,
        tolerance,
        exclude,
    };
    let study = match study::converge(&loaded, &options, &mut progress) {
        Ok(s) => s,
        Err(e) => {
            bar.abandon();
            errln!("error: {}: {e}", file.display());
            let code = match e {
                ConvergeError::Options(_) => EXIT_INVALID,
                _ => EXIT_FAILED,
            };
            return ExitCode::from(code);
        }
    };
    bar.finish_and_clear();
    print_convergence(&study);
    let written = vbi::run::mark_folder(&out, &source)
        .map_err(|e| format!("cannot write {}: {e}", out.display()))
        .and_then(|()| {
            vbi::report::write_atomic(&out.join("converge.csv"), &study.to_csv())
                .map_err(|e| e.to_string())
        })
        .and_then(|()| {
            study
                .plot(&out.join("converge.png"))
                .map_err(|e| e.to_string())
        })
        .and_then(|()| {
            // The answer to paste; none (and no stale one from an earlier
            // study in the folder) when no run is within tolerance.
            let path = out.join("cheapest.yaml");
            match study.cheapest_yaml() {
                Some(yaml) => {
                    vbi::report::write_atomic(&path, yaml.as_bytes()).map_err(|e| e.to_string())
                }
                None => match std::fs::remove_file(&path) {
                    Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                        Err(format!("cannot remove {}: {e}", path.display()))
                    }
                    _ => Ok(()),
                },
            }
        });
    if let Err(e) = written {
        errln!("error: {e}");
        return ExitCode::from(EXIT_FAILED);
    }
    // The reference's advice and the cheapest run's: what the answer rests on.
    let mut advice = study.reference.advice.clone();
    if let Some(cheapest) = study.cheapest_run() {
        advice.extend(
            cheapest
                .advice
                .iter()
                .filter(|a| !advice.contains(a))
                .cloned()
                .collect::<Vec<_>>(),
        );
    }
    print_advice_located(file, &advice);
    if !quiet {
        errln!("results in {}", out.display());
    }
    deny_warnings(&advice, ExitCode::SUCCESS)
}

/// The study as a table on stdout: one row per run, then the observed
/// orders and the cheapest run within tolerance.
pub(super) fn print_convergence(study: &vbi::study::converge::Convergence) {
    use vbi::study::converge::short;
    let percent = |e: Option<f64>| e.map_or("-".to_string(), |e| format!("{:.4}", 100.0 * e));
    let reference = &study.reference;
    let rows: Vec<(String, &vbi::study::converge::RunReport, String, String)> = std::iter::once((
        format!("{} (reference)", reference.label),
        reference,
        "-".to_string(),
        "-".to_string(),
    ))
    .chain(study.runs.iter().map(|r| {
        let errors = (percent(r.worst_max_abs()), percent(r.worst_rms()));
        (r.label.clone(), r, errors.0, errors.1)
    }))
    .collect();
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0).max(3);
    outln!(
        "{}: convergence against {}",
        study.scenario,
        reference.label
    );
    outln!(
        "{:<width$} {:>10} {:>6} {:>10} {:>14} {:>14}",
        "run",
        "dt_s",
        "modes",
        "wall_ms",
        "max_abs_err_%",
        "rms_err_%"
    );
    for (label, run, max_abs, rms) in &rows {
        let wall = run
            .wall_time
            .map_or("-".to_string(), |t| format!("{:.2}", 1e3 * t));
        out!(
            "{label:<width$} {:>10} {:>6} {wall:>10} {max_abs:>14} {rms:>14}",
            short(run.time_step),
            run.modes,
        );
        match &run.errors {
            Err(message) => outln!("  failed: {message}"),
            Ok(_) => outln!(),
        }
        let warned: Vec<&str> = run
            .advice
            .iter()
            .filter(|a| a.is_denied_warning())
            .map(|a| a.id.as_str())
            .collect();
        if !warned.is_empty() {
            outln!("{:<width$}   warns: {}", "", warned.join(", "));
        }
    }
    let names = study.quantities();
    if study.orders.is_empty() {
        outln!("observed order: none (fewer than two successful time-step runs)");
    } else {
        let col = names.iter().map(|n| n.len()).max().unwrap_or(0).max(6);
        outln!("observed order p = log2(e(2h)/e(h)) of the max-abs error:");
        out!("{:<24}", "dt halving");
        for n in &names {
            out!(" {n:>col$}");
        }
        outln!();
        let mut pairs: Vec<(f64, f64)> = study
            .orders
            .iter()
            .map(|o| (o.coarse_step, o.fine_step))
            .collect();
        pairs.dedup();
        for (coarse, fine) in pairs {
            let pair = format!(
                "{} -> {}",
                vbi::study::converge::short(coarse),
                vbi::study::converge::short(fine)
            );
            out!("{pair:<24}");
            for n in &names {
                let p = study
                    .orders
                    .iter()
                    .find(|o| o.coarse_step == coarse && o.quantity == *n)
                    .map_or("-".to_string(), |o| format!("{:.3}", o.order));
                out!(" {p:>col$}");
            }
            outln!();
        }
        if let Some(m) = study.median_order {
            outln!("median observed order: {m:.3}");
        }
    }
    let tolerance = vbi::study::converge::percent(study.tolerance);
    let left_out = if study.excluded.is_empty() {
        String::new()
    } else {
        format!(" (leaving out {})", study.excluded.join(", "))
    };
    match study.cheapest_run() {
        Some(run) => outln!("cheapest within {tolerance} %{left_out}: {}", run.label),
        None => {
            outln!("cheapest within {tolerance} %{left_out}: none (every run's error exceeds it)")
        }
    }
    for (name, cheapest) in &study.cheapest_per_quantity {
        match cheapest {
            Some(i) => outln!(
                "  {name}: cheapest within {tolerance} %: {}",
                study.runs[*i].label
            ),
            None => outln!("  {name}: no run within {tolerance} %"),
        }
    }
    if let Some(yaml) = study.cheapest_yaml() {
        // Ready to paste (also written to cheapest.yaml).
        outln!();
        out!("{yaml}");
    }
}
