//! The study commands of the `vbi` command line: writing a study's
//! results, `vbi run --shard K/N`, `vbi run --sample K` and `vbi merge`.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::run_cmd::{default_out, load_error, run};
use super::{EXIT_CHECK_FAILED, EXIT_FAILED, EXIT_INVALID, deny_warnings, emit, print_advice};
use vbi::plan;
use vbi::scenario::{self, LoadError};

/// Writes a study's results into `out` and says what it found.
pub(super) fn write_study(
    out: &Path,
    scenario: &vbi::scene::Scenario,
    results: &vbi::execute::Results,
    quiet: bool,
) -> ExitCode {
    use vbi::execute::Results;
    let written = match results {
        Results::Scene(_) => unreachable!("a study's results"),
        Results::SeparationMap(map) => vbi::study::separation_map::write(out, scenario, map),
        Results::SpeedSweep(sweep) => vbi::study::speed_sweep::write(out, scenario, sweep),
        Results::MonteCarlo(mc) => vbi::study::monte_carlo::write(out, scenario, mc),
        Results::ResonanceCheck(check) => vbi::study::resonance::write(out, scenario, check),
    };
    if let Err(e) = written {
        errln!("error: {e}");
        return ExitCode::from(EXIT_FAILED);
    }
    // A failed resonance check is a verdict, not an error: the files are
    // written, the exit status tells CI.
    let verdict = match results {
        Results::ResonanceCheck(check) if !check.passes() => ExitCode::from(EXIT_CHECK_FAILED),
        _ => ExitCode::SUCCESS,
    };
    // `--quiet` hides progress and chatter, never a verdict.
    if quiet && !matches!(results, Results::ResonanceCheck(_)) {
        return verdict;
    }
    match results {
        Results::Scene(_) => {}
        Results::ResonanceCheck(check) => {
            let summary = check.summary(&scenario.name);
            let governing = summary
                .governing_acceleration
                .map(|g| {
                    format!(
                        ", largest deck acceleration {:.3} m/s^2 ({}, {} km/h, x = {} m): {} the {} m/s^2 limit",
                        g.value,
                        g.train,
                        g.speed_km_h,
                        g.x,
                        if summary.passes { "within" } else { "ABOVE" },
                        summary.acceleration_limit
                    )
                })
                .unwrap_or_default();
            errln!(
                "{}: resonance check of {} runs{governing}, {:.2} s",
                scenario.name,
                check.points.len(),
                check.wall_time
            );
            errln!("{}", check.verdict_table().trim_end());
            if quiet {
                return verdict;
            }
        }
        Results::SeparationMap(map) => errln!(
            "{}: separation map of {} points, {} separated, {:.2} s",
            scenario.name,
            map.points.len(),
            map.separated_count(),
            map.wall_time
        ),
        Results::SpeedSweep(sweep) => {
            let largest = vbi::study::speed_sweep::SweepSummary::new(&scenario.name, sweep)
                .largest_daf
                .map(|l| {
                    format!(
                        ", largest DAF {:.4} ({}, {}, {:.1} km/h)",
                        l.daf, l.column, l.roughness, l.speed_km_h
                    )
                })
                .unwrap_or_default();
            errln!(
                "{}: speed sweep of {} runs{largest}, {:.2} s",
                scenario.name,
                sweep.points.len(),
                sweep.wall_time
            );
        }
        Results::MonteCarlo(mc) => {
            // The wheel that separated in the most samples (the first such
            // in case order), its probability with the 95 % interval and
            // the count it comes from: 0 of 16 reads 0 (0–0.194), not 0.
            let highest = (0..mc.cases.len())
                .flat_map(|c| mc.wheel_statistics(c).into_iter().map(move |w| (c, w)))
                .reduce(|best, next| {
                    if next.1.separated > best.1.separated {
                        next
                    } else {
                        best
                    }
                });
            let highest = highest
                .map(|(c, w)| {
                    let speed = mc
                        .speed(c)
                        .map(|v| format!(", {:.1} km/h", vbi::report::km_h(v)))
                        .unwrap_or_default();
                    format!(
                        ", highest probability of separation {:.4} (95 % interval {:.4}–{:.4}; {} of {} samples; {}{speed}, vehicle {} wheel {})",
                        w.probability,
                        w.probability_low,
                        w.probability_high,
                        w.separated,
                        mc.samples,
                        mc.labels[c],
                        w.vehicle,
                        w.wheel
                    )
                })
                .unwrap_or_default();
            errln!(
                "{}: Monte Carlo of {} runs ({} cases × {} samples){highest}, {:.2} s",
                scenario.name,
                mc.sample_results.len(),
                mc.cases.len(),
                mc.samples,
                mc.wall_time
            );
        }
    }
    errln!("results in {}", out.display());
    verdict
}

/// Moves one run's bar to `done` of `total`, never back: a study's parallel
/// workers report their counts out of order (a batch finishing after a later
/// one reports the smaller count), and a bar that stepped back looked like a
/// restart. Never further than `total` either.
pub(super) fn advance(bar: &ProgressBar, done: usize, total: usize) {
    let total = total as u64;
    if bar.length() != Some(total) {
        bar.set_length(total);
    }
    let done = (done as u64).min(total);
    if done > bar.position() {
        bar.set_position(done);
    }
}

fn progress_bar(quiet: bool, message: &str) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    // indicatif draws nothing when stderr is not a terminal. No length until
    // the work reports one (a length of 0 reads 100 %).
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{bar:30}] {pos}/{len} eta {eta}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar.set_message(message.to_string());
    bar
}

/// `vbi run --shard K/N`: the slice's part file in the output folder.
pub(super) fn run_shard(
    loaded: Result<plan::Loaded, LoadError>,
    file: &Path,
    options: &scenario::LoadOptions,
    out: Option<PathBuf>,
    quiet: bool,
    shard: vbi::study::shard::Shard,
    force: bool,
) -> ExitCode {
    use vbi::study::shard::{self, ShardError};
    let loaded = match loaded {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    // The parts' folder is claimed before the work, as `vbi run`'s: parts of
    // another scene file are not mixed with these.
    let owner = vbi::run::source_name(file);
    let out = out.unwrap_or_else(|| default_out(file, ""));
    if let Err(message) = vbi::run::claim_folder(&out, &owner, force) {
        errln!("error: {message}");
        return ExitCode::from(EXIT_INVALID);
    }
    // The text as loaded goes into the part, so that the merge needs no
    // access to the file; a file changed since is caught by the hash.
    let source = match vbi::guarded_file::read_text_bounded(file, vbi::scenario::MAX_FILE_BYTES) {
        Ok(s) => s,
        Err(e) => {
            errln!("error: cannot read the scene again: {e}");
            return ExitCode::from(EXIT_INVALID);
        }
    };
    let bar = progress_bar(
        quiet,
        &format!(
            "{} shard {}/{}",
            loaded.scenario.name, shard.index, shard.count
        ),
    );
    let progress = |done: usize, total: usize| advance(&bar, done, total);
    let name = file.display().to_string();
    let part = match shard::run_shard(&loaded, &name, &source, options, shard, &progress) {
        Ok(p) => p,
        Err(e) => {
            bar.abandon();
            errln!("error: {e}");
            let code = match e {
                ShardError::Run(_) => EXIT_FAILED,
                _ => EXIT_INVALID,
            };
            return ExitCode::from(code);
        }
    };
    bar.finish_and_clear();
    let path = out.join(shard.file_name());
    let written = vbi::run::mark_folder(&out, &owner).and_then(|()| {
        vbi::report::write_atomic(&path, shard::part_json(&part).as_bytes())
            .map_err(std::io::Error::other)
    });
    if let Err(e) = written {
        errln!("error: {}: {e}", path.display());
        return ExitCode::from(EXIT_FAILED);
    }
    if !quiet {
        errln!(
            "{}: shard {} of {}: runs {}..{} of {}, {:.2} s; part in {}",
            loaded.scenario.name,
            part.shard,
            part.shards,
            part.first,
            part.end,
            part.size,
            part.wall_time,
            path.display()
        );
    }
    ExitCode::SUCCESS
}

/// `vbi run --sample K`: sample K of a Monte Carlo study as one scene.
pub(super) fn run_sample(
    loaded: Result<plan::Loaded, LoadError>,
    file: &Path,
    out: Option<PathBuf>,
    quiet: bool,
    svg: bool,
    force: bool,
    k: u64,
) -> ExitCode {
    use vbi::scene::Study;
    let loaded = match loaded {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    let Some(Study::MonteCarlo(mc)) = &loaded.scenario.study else {
        errln!(
            "error: {}: --sample applies to a Monte Carlo study (`study: {{type: monte_carlo, ...}}`)",
            file.display()
        );
        return ExitCode::from(EXIT_INVALID);
    };
    if k > mc.samples as u64 {
        errln!(
            "error: {}: sample {k} does not exist; the study has {} samples (counted from 1)",
            file.display(),
            mc.samples
        );
        return ExitCode::from(EXIT_INVALID);
    }
    let case = vbi::study::monte_carlo::cases(mc)[0];
    let scenario = vbi::study::monte_carlo::sample_scenario(
        &loaded.scenario,
        &loaded.bridge,
        mc,
        case,
        (k - 1) as usize,
    );
    let loaded = plan::Loaded {
        scenario,
        bridge: loaded.bridge,
    };
    let out = out.unwrap_or_else(|| default_out(file, &format!("-sample{k}")));
    run(Ok(loaded), file, Some(out), quiet, svg, force)
}

/// The merge reads one part at a time (megabytes of text, then its parsed
/// nodes) and frees it before the next. glibc serves such blocks with mmap
/// and returns them on free, but after the first free it raises its mmap
/// threshold to that size (its dynamic threshold), so the next parts land
/// in the heap, where fragmentation keeps them resident: measured on the
/// rail car's 14 MB part, 70 MB peak RSS, 47 MB with the threshold fixed
/// (BENCHMARKS.md, "Studies on a Slurm cluster"). Setting `M_MMAP_THRESHOLD` fixes it at glibc's initial 128 kB and
/// turns the adjustment off (mallopt(3)).
fn keep_large_buffers_out_of_the_heap() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets an allocator parameter; called before the
    // merge allocates its parts, on the main thread.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 128 * 1024);
    }
}

/// `vbi merge`: the parts' study written as an unsharded run writes it.
pub(super) fn merge(
    parts: &[PathBuf],
    out: &Path,
    options: &scenario::LoadOptions,
    quiet: bool,
    force: bool,
) -> ExitCode {
    use vbi::study::shard::{self, ShardError};
    keep_large_buffers_out_of_the_heap();
    let mut merged = match shard::merge(parts, options) {
        Ok(m) => m,
        Err(e) => {
            errln!("error: {e}");
            let code = match e {
                ShardError::Run(_) => EXIT_FAILED,
                _ => EXIT_INVALID,
            };
            return ExitCode::from(code);
        }
    };
    // The parts name their scene's file as `vbi run` was given it, relative
    // to where it ran.
    let source = vbi::run::source_name(Path::new(&merged.scenario_file));
    if let Err(message) = vbi::run::claim_folder(out, &source, force) {
        errln!("error: {message}");
        return ExitCode::from(EXIT_INVALID);
    }
    merged.loaded.scenario.source_file = Some(source);
    let code = write_study(out, &merged.loaded.scenario, &merged.results, quiet);
    let advice = merged.results.advice(&merged.loaded.scenario);
    print_advice(&merged.scenario_file, &advice);
    deny_warnings(&advice, code)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bar_reads_0_until_told_a_length_and_never_steps_back() {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        // Not 100 % before the first report (a length of 0 would be).
        assert_eq!(bar.length(), None);
        advance(&bar, 6, 10);
        advance(&bar, 4, 10); // a worker's late report
        assert_eq!((bar.position(), bar.length()), (6, Some(10)));
        advance(&bar, 10, 10);
        advance(&bar, 12, 10);
        assert_eq!(bar.position(), 10);
    }
}
