//! The `vbi` command line: parses arguments, calls the library, prints, and
//! maps errors to exit codes (0 success, 1 a run failed, 2 invalid input).
//!
//! Streams follow the usual convention: stdout carries what a command
//! produces (the schema, `check`'s verdicts, the modes table, mode shapes
//! with `--shapes -`, the convergence table), stderr everything about the
//! work (progress, run summaries, notes, errors). A reader that closes either
//! early (`vbi check *.yaml | head -1`) ends that output, not the program:
//! later writes to it are dropped, the command still writes its files and
//! exits with its usual code.

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};

use clap::{CommandFactory, Parser};

use vbi::plan;
use vbi::scenario;

/// Whether stdout / stderr still has a reader.
static STDOUT_OPEN: AtomicBool = AtomicBool::new(true);
static STDERR_OPEN: AtomicBool = AtomicBool::new(true);

/// Writes to stdout (`to_stderr` false) or stderr; a failed write (a closed
/// pipe) marks the stream closed instead of panicking as `println!` does.
fn emit(to_stderr: bool, args: fmt::Arguments<'_>) {
    let open = if to_stderr {
        &STDERR_OPEN
    } else {
        &STDOUT_OPEN
    };
    if !open.load(Ordering::Relaxed) {
        return;
    }
    let written = if to_stderr {
        let mut stream = std::io::stderr().lock();
        stream.write_fmt(args).and_then(|()| stream.flush())
    } else {
        let mut stream = std::io::stdout().lock();
        stream.write_fmt(args).and_then(|()| stream.flush())
    };
    if written.is_err() {
        open.store(false, Ordering::Relaxed);
    }
}

/// `out!` to stdout that survives a closed pipe.
macro_rules! out {
    ($($arg:tt)*) => { emit(false, format_args!($($arg)*)) };
}
/// `println!` to stdout that survives a closed pipe.
macro_rules! outln {
    () => { emit(false, format_args!("\n")) };
    ($($arg:tt)*) => { emit(false, format_args!("{}\n", format_args!($($arg)*))) };
}
/// `errln!` that survives a closed pipe.
macro_rules! errln {
    ($($arg:tt)*) => { emit(true, format_args!("{}\n", format_args!($($arg)*))) };
}

const EXIT_FAILED: u8 = 1;
const EXIT_INVALID: u8 = 2;
/// A check ran and its verdict is "fails" (an HSLM resonance check above
/// the deck-acceleration limit): distinct from a failed run and bad input.
const EXIT_CHECK_FAILED: u8 = 3;

// After the macros, which they use.
mod cli;
mod converge_cmd;
mod generate_cmd;
mod init_cmd;
mod modes_cmd;
mod regress_cmd;
mod run_cmd;
mod studies;
use cli::{Cli, Command, Regress};
use converge_cmd::converge;
use generate_cmd::generate;
use init_cmd::init;
use modes_cmd::modes;
use run_cmd::{check, default_out, load_error, run};
use studies::{merge, run_sample, run_shard};

fn main() -> ExitCode {
    let cli = Cli::parse();
    // The modes cache: the one given, else `.vbi-cache` in the output
    // folder of a command that has one (nothing is written outside it).
    let cache_in = |out: Option<&Path>| -> Option<PathBuf> {
        if cli.no_modes_cache {
            None
        } else {
            cli.modes_cache
                .clone()
                .or_else(|| out.map(vbi::bridge::eigen::cache::default_folder))
        }
    };
    let data = scenario::DataAccess {
        data_dirs: cli.data_dir.clone(),
        confine_to: None,
    };
    let options = scenario::LoadOptions {
        allow_large: cli.allow_large,
        trust_limits: cli.trust_limits,
        modes_cache: cache_in(None),
        data: data.clone(),
    };
    let load = |file: &Path| plan::load_file_with(file, options.clone());
    match cli.command {
        Command::Run {
            file,
            out,
            quiet,
            svg,
            shard,
            sample,
            force,
        } => {
            let folder = out.clone().unwrap_or_else(|| default_out(&file, ""));
            let options = scenario::LoadOptions {
                modes_cache: cache_in(Some(&folder)),
                ..options.clone()
            };
            let loaded = plan::load_file_with(&file, options.clone());
            match (shard, sample) {
                (Some(shard), _) => run_shard(loaded, &file, &options, out, quiet, shard, force),
                (None, Some(k)) => run_sample(loaded, &file, out, quiet, svg, force, k),
                (None, None) => run(loaded, &file, out, quiet, svg, force),
            }
        }
        Command::Merge {
            parts,
            out,
            quiet,
            force,
        } => merge(&parts, &out, &options, quiet, force),
        Command::Check { files, shards } => check(&files, &load, shards, cli.allow_large),
        Command::Schema { markdown } => {
            let schema = vbi::schema::schema_json();
            if markdown {
                out!("{}", vbi::format_reference::markdown(&schema));
            } else {
                out!("{schema}");
            }
            ExitCode::SUCCESS
        }
        Command::Completions { shell } => {
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "vbi", &mut script);
            out!("{}", String::from_utf8_lossy(&script));
            ExitCode::SUCCESS
        }
        Command::Init {
            bridge,
            vehicle,
            file,
            force,
        } => init(bridge, vehicle, &file, force),
        Command::Man => {
            let mut page = Vec::new();
            match clap_mangen::Man::new(Cli::command()).render(&mut page) {
                Ok(()) => {
                    out!("{}", String::from_utf8_lossy(&page));
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    errln!("error: could not render the manual page: {e}");
                    ExitCode::from(EXIT_FAILED)
                }
            }
        }
        Command::Export { what: _, file, out } => match load(&file) {
            Ok(loaded) => match vbi::export::export_beam(&loaded.scenario, &out) {
                Ok(()) => {
                    errln!("wrote {}", out.join("scenario.yaml").display());
                    ExitCode::SUCCESS
                }
                Err(e @ vbi::export::ExportError::NotABeam) => {
                    errln!("error: {}: {e}", file.display());
                    ExitCode::from(EXIT_INVALID)
                }
                Err(e) => {
                    errln!("error: {e}");
                    ExitCode::from(EXIT_FAILED)
                }
            },
            Err(e) => load_error(&e),
        },
        Command::Modes { file, shapes, json } => modes(&file, options, shapes.as_deref(), json),
        Command::Generate { what } => generate(what),
        Command::Regress { action } => match action {
            Regress::Approve { scenes, store } => regress_cmd::approve(&scenes, &store, &options),
            Regress::Check {
                scenes,
                store,
                junit,
                out,
            } => regress_cmd::check(&scenes, &store, &options, junit.as_deref(), out),
        },
        Command::Converge {
            file,
            tolerance,
            levels,
            out,
            quiet,
            exclude,
            force,
        } => converge(
            load(&file),
            &file,
            tolerance,
            levels as usize,
            out,
            quiet,
            exclude,
            force,
        ),
    }
}
