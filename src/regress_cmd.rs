//! `vbi regress approve` and `vbi regress check`: the command-line side of
//! [`vbi::regress`] (printing, exit codes: 0 all pass, 1 a scene or its
//! results changed, 2 a scene could not run or the store is unusable).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::{EXIT_FAILED, EXIT_INVALID, emit};
use vbi::regress::{self, Approved, report};

pub(super) fn approve(
    scenes: &[PathBuf],
    store: &Path,
    options: &vbi::scenario::LoadOptions,
) -> ExitCode {
    let approved = match regress::approve(scenes, store, options) {
        Ok(a) => a,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(EXIT_INVALID);
        }
    };
    let mut failed = false;
    for (file, outcome) in scenes.iter().zip(&approved) {
        let key = regress::scene_key(file);
        match outcome {
            Approved::New => outln!("approved {key} (new record)"),
            Approved::Updated => outln!("approved {key} (record updated)"),
            Approved::Unchanged => outln!("approved {key} (record unchanged)"),
            Approved::CouldNotRun(why) => {
                failed = true;
                outln!("ERROR {key}: could not run, its record is kept");
                errln!("error: {why}");
            }
        }
    }
    if failed {
        ExitCode::from(EXIT_INVALID)
    } else {
        ExitCode::SUCCESS
    }
}

pub(super) fn check(
    scenes: &[PathBuf],
    store: &Path,
    options: &vbi::scenario::LoadOptions,
    junit: Option<&Path>,
    out: Option<PathBuf>,
) -> ExitCode {
    let checks = match regress::check(scenes, store, options) {
        Ok(c) => c,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(EXIT_INVALID);
        }
    };
    let out = out.unwrap_or_else(|| Path::new("results").join("regress"));
    let plots = match report::write_plots(&checks, &out) {
        Ok(p) => p,
        Err(e) => {
            errln!("warning: the plots of old against new were not written: {e}");
            Vec::new()
        }
    };
    out!("{}", report::text(&checks, &plots));
    if let Some(path) = junit
        && let Err(e) = vbi::report::write_atomic(path, report::junit(&checks).as_bytes())
    {
        errln!("error: {e}");
        return ExitCode::from(EXIT_INVALID);
    }
    let tally = report::Tally::of(&checks);
    if tally.could_not_run > 0 {
        ExitCode::from(EXIT_INVALID)
    } else if tally.changed > 0 {
        ExitCode::from(EXIT_FAILED)
    } else {
        ExitCode::SUCCESS
    }
}
