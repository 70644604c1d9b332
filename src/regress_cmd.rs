//! `vbi regress approve` and `vbi regress check`: the command-line side of
//! [`vbi::regress`] (printing, exit codes).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::{EXIT_INVALID, emit};

pub(super) fn approve(
    _scenes: &[PathBuf],
    _store: &Path,
    _options: &vbi::scenario::LoadOptions,
) -> ExitCode {
    errln!("error: vbi regress approve is not implemented yet");
    ExitCode::from(EXIT_INVALID)
}

pub(super) fn check(
    _scenes: &[PathBuf],
    _store: &Path,
    _options: &vbi::scenario::LoadOptions,
    _junit: Option<&Path>,
    _out: Option<PathBuf>,
) -> ExitCode {
    errln!("error: vbi regress check is not implemented yet");
    ExitCode::from(EXIT_INVALID)
}
