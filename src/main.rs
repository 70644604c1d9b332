//! The `vbi` command line: parses arguments, calls the library, prints, and
//! maps errors to exit codes (0 success, 1 a run failed, 2 invalid input, 3 a
//! check fails, 4 a warning denied; each command's in its manual page,
//! `man_cmd`).
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
    // Messages carry names and text from files that may be someone
    // else's: no control character (ESC, NUL, CR) reaches the terminal
    // raw, whatever path built the message (issue 39.3).
    let text = match args.as_str() {
        Some(s) => vbi::guarded_file::escape_controls(s),
        None => vbi::guarded_file::escape_controls(&args.to_string()),
    };
    let written = if to_stderr {
        let mut stream = std::io::stderr().lock();
        stream
            .write_all(text.as_bytes())
            .and_then(|()| stream.flush())
    } else {
        let mut stream = std::io::stdout().lock();
        stream
            .write_all(text.as_bytes())
            .and_then(|()| stream.flush())
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

/// Set once from `--deny-warnings`: every command that makes advice fails
/// with [`EXIT_WARNINGS`] on a warning the scene does not allow.
static DENY_WARNINGS: AtomicBool = AtomicBool::new(false);

/// Prints each piece of `advice` about `file` on stderr, rustc-style: the
/// id in brackets, where (key path) the cause is, the message and its help;
/// advice the scene allows in one line with its reason.
fn print_advice(file: &str, advice: &[vbi::advice::Advice]) {
    print_advice_in(file, None, advice);
}

/// [`print_advice`] with each key path also shown as `file:line:col` in
/// the scene file `path` (read again, a regular file only, size-checked).
fn print_advice_located(path: &Path, advice: &[vbi::advice::Advice]) {
    let source = if advice.is_empty() || !path.is_file() {
        None
    } else {
        vbi::scenario::read_source(path).ok().map(|(text, _)| text)
    };
    print_advice_in(&path.display().to_string(), source.as_deref(), advice);
}

fn print_advice_in(file: &str, source: Option<&str>, advice: &[vbi::advice::Advice]) {
    for a in advice {
        let word = a.severity.word();
        let at = a
            .location
            .as_deref()
            .map(|l| {
                let place = source
                    .and_then(|text| vbi::scenario::checker::locate_in(text, l))
                    .map(|loc| format!(":{loc}"))
                    .unwrap_or_default();
                format!("{place} ({l})")
            })
            .unwrap_or_default();
        if let Some(reason) = &a.allowed {
            errln!(
                "note[{}]: {file}{at}: allowed by the scene: {}",
                a.id,
                vbi::scenario::diagnostic::escaped(reason)
            );
            continue;
        }
        let mut text = a.message.clone();
        match a.points.as_slice() {
            [] => {}
            [one] => text.push_str(&format!(" (at {one})")),
            [first, rest @ ..] => text.push_str(&format!(
                " (at {first} and {} more: summary.json lists them)",
                rest.len()
            )),
        }
        errln!("{word}[{}]: {file}{at}: {text}", a.id);
        if let Some(help) = &a.help {
            errln!("  = help: {help}");
        }
    }
}

/// `code`, or [`EXIT_WARNINGS`] where `code` is success, `--deny-warnings`
/// is set and `advice` holds a warning the scene does not allow.
fn deny_warnings(advice: &[vbi::advice::Advice], code: ExitCode) -> ExitCode {
    let denied = vbi::advice::denied_warnings(advice);
    if code != ExitCode::SUCCESS || denied == 0 || !DENY_WARNINGS.load(Ordering::Relaxed) {
        return code;
    }
    errln!(
        "error: {denied} warning{} denied by `--deny-warnings` (allow one in the scene with \
         `allow: [{{id: ID, reason: \"...\"}}]`)",
        if denied == 1 { "" } else { "s" }
    );
    ExitCode::from(EXIT_WARNINGS)
}

/// `vbi advice [ID] [--markdown]`: one id explained, every id listed, or
/// the whole reference.
fn advice_cmd(id: Option<&str>, markdown: bool) -> ExitCode {
    use vbi::advice::{KINDS, kind, reference_markdown};
    if markdown {
        out!("{}", reference_markdown());
        return ExitCode::SUCCESS;
    }
    let Some(id) = id else {
        for k in KINDS {
            outln!("{:<34} {:<8} {}", k.id, k.severity.word(), k.meaning);
        }
        return ExitCode::SUCCESS;
    };
    match kind(id) {
        Some(k) => {
            outln!("{} ({})\n\n{}\n", k.id, k.severity.word(), k.meaning);
            outln!("why it matters: {}\n", k.why);
            outln!("how to fix it: {}\n", k.fix);
            outln!("example: {}", k.example);
            ExitCode::SUCCESS
        }
        None => {
            errln!(
                "error: `{}` is not an advice id",
                vbi::scenario::diagnostic::escaped(id)
            );
            let help = vbi::scenario::diagnostic::did_you_mean(id, KINDS.iter().map(|k| k.id))
                .unwrap_or_else(|| "`vbi advice` lists every id".to_string());
            errln!("  = help: {help}");
            ExitCode::from(EXIT_INVALID)
        }
    }
}

const EXIT_FAILED: u8 = 1;
const EXIT_INVALID: u8 = 2;
/// A check ran and its verdict is "fails" (an HSLM resonance check above
/// the deck-acceleration limit): distinct from a failed run and bad input.
const EXIT_CHECK_FAILED: u8 = 3;
/// The run or check succeeded, but `--deny-warnings` was given and it made
/// a warning the scene does not allow (docs/advice.md).
const EXIT_WARNINGS: u8 = 4;

// After the macros, which they use.
mod cli;
mod converge_cmd;
mod generate_cmd;
mod init_cmd;
mod man_cmd;
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
    let threads = threads(cli.threads);
    // The command runs in a rayon pool of its own with that many threads
    // (the library sets no process-wide parallelism; it is passed down as
    // `LoadOptions::par`).
    match rayon::ThreadPoolBuilder::new()
        .num_threads(threads.get())
        .build()
    {
        Ok(pool) => pool.install(|| dispatch(cli, threads)),
        Err(e) => {
            errln!("error: could not start {threads} threads: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}

/// The thread count: `--threads`, else `VBI_THREADS`, else
/// `RAYON_NUM_THREADS`, else the machine's cores (a variable that is not a
/// positive whole number is ignored).
fn threads(given: Option<std::num::NonZeroUsize>) -> std::num::NonZeroUsize {
    let from_env = |name: &str| {
        std::env::var(name)
            .ok()
            .and_then(|v| v.trim().parse::<std::num::NonZeroUsize>().ok())
    };
    given
        .or_else(|| from_env("VBI_THREADS"))
        .or_else(|| from_env("RAYON_NUM_THREADS"))
        .or_else(|| std::thread::available_parallelism().ok())
        .unwrap_or(std::num::NonZeroUsize::MIN)
}

/// Runs the parsed command with `threads` threads.
fn dispatch(cli: Cli, threads: std::num::NonZeroUsize) -> ExitCode {
    DENY_WARNINGS.store(cli.deny_warnings, Ordering::Relaxed);
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
        par: if threads.get() == 1 {
            faer::Par::Seq
        } else {
            faer::Par::Rayon(threads)
        },
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
        Command::Advice { id, markdown } => advice_cmd(id.as_deref(), markdown),
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
        Command::Man { page, dir } => man_cmd::man(page.as_deref(), dir.as_deref()),
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
