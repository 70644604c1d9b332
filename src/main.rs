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

use clap::{CommandFactory, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use vbi::scenario::{self, LoadError};

/// Vehicle–bridge interaction dynamics from a YAML scene.
#[derive(Debug, Parser)]
#[command(name = "vbi", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Lift the resource limits (DOFs, steps, wheels, records, study points,
    /// output size) for a scene that really needs more; see `limits` in the format.
    #[arg(long, global = true)]
    allow_large: bool,
    /// Let the file's own `limits` section raise limits above the defaults
    /// (without it a file can only lower them, so a stranger's file cannot
    /// lift them for you).
    #[arg(long, global = true)]
    trust_limits: bool,
    /// Folder of the modes cache: an imported model's modes are read from it
    /// when a valid file holds them and written to it when solved. Default
    /// for `run`: `.vbi-cache` inside the output folder; other commands use a
    /// cache only when given one.
    #[arg(long, global = true, value_name = "DIR")]
    modes_cache: Option<PathBuf>,
    /// Solve every imported model's modes afresh and write no cache.
    #[arg(long, global = true, conflicts_with = "modes_cache")]
    no_modes_cache: bool,
    /// Let scenes read files in DIR and below (repeatable): without it a
    /// scene reads only files inside its own folder tree (symlinks resolved)
    /// and no absolute path.
    #[arg(long, global = true, value_name = "DIR")]
    data_dir: Vec<PathBuf>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene and write summary.json, history.csv, history.png and resolved.yaml.
    Run {
        /// The scenario file.
        file: PathBuf,
        /// Output folder. Default: results/<file stem> (results/bridge for bridge.yaml).
        #[arg(long)]
        out: Option<PathBuf>,
        /// No progress bar.
        #[arg(long, short)]
        quiet: bool,
        /// Also write the history plot as SVG (history.svg).
        #[arg(long)]
        svg: bool,
        /// Run only shard K of N of the study (a contiguous slice of its
        /// runs) and write part-K-of-N.json into the output folder; `vbi
        /// merge` combines the parts.
        #[arg(long, value_name = "K/N", value_parser = vbi::study::shard::Shard::parse, conflicts_with = "sample")]
        shard: Option<vbi::study::shard::Shard>,
        /// Run sample K (from 1) of a Monte Carlo study alone, as a single
        /// scene (its first case: first surface, first speed), and write the
        /// single-run outputs.
        #[arg(long, value_name = "K", value_parser = clap::value_parser!(u64).range(1..))]
        sample: Option<u64>,
        /// Write into the output folder even if it holds another scene
        /// file's results (its `resolved.yaml` names that file).
        #[arg(long)]
        force: bool,
    },
    /// Combine the part files of a sharded study into exactly the files an
    /// unsharded run writes (summary.json's wall_time: the parts' sum).
    Merge {
        /// The part files (part-K-of-N.json), all N of them.
        #[arg(required = true)]
        parts: Vec<PathBuf>,
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
        /// No closing message.
        #[arg(long, short)]
        quiet: bool,
        /// Write into the output folder even if it holds another scene
        /// file's results.
        #[arg(long)]
        force: bool,
    },
    /// Parse and validate scenario files; exit 2 if any is invalid.
    Check {
        /// Scenario files.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Also check that each file's study splits into N shards (`vbi
        /// run --shard K/N`, K = 1..N): exit 2 if it has no study, fewer
        /// runs than N, or N exceeds `limits.study_points`.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
        shards: Option<u64>,
    },
    /// Print the JSON Schema of the scenario format (with --markdown: the
    /// key reference, docs/format.md, generated from it).
    Schema {
        /// Print the readable key reference (Markdown) instead of the schema.
        #[arg(long)]
        markdown: bool,
    },
    /// Write a scene's bridge as an imported FE model: `vbi export beam
    /// SCENE --out DIR` writes K.mtx, M.mtx (Matrix Market), dofs.csv,
    /// rail.csv and scenario.yaml (the same crossing on those files).
    Export {
        /// What to export: `beam` (a `type: beam` bridge).
        #[arg(value_parser = ["beam"])]
        what: String,
        /// The scenario file.
        file: PathBuf,
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
    },
    /// Natural frequencies (and, with --shapes, mode shapes) of a scene's bridge.
    Modes {
        /// The scenario file.
        file: PathBuf,
        /// Write mode shapes at the mesh nodes to this CSV file (`-`: stdout).
        #[arg(long)]
        shapes: Option<PathBuf>,
        /// Print the modes as JSON, at full precision, with the checks every
        /// mode passed (residual, M-orthonormality, Sturm count).
        #[arg(long)]
        json: bool,
    },
    /// Write a generated finite-element bridge model (Matrix Market K and M,
    /// DOF map, rail tracks) for `type: fe_import` and benchmarks.
    Generate {
        #[command(subcommand)]
        what: Generate,
    },
    /// Speed against error: the scene at finer and coarser time steps and
    /// mode counts, each recorded quantity's error against the finest run,
    /// and the wall time of each; writes converge.csv and converge.png.
    Converge {
        /// The scenario file.
        file: PathBuf,
        /// Largest acceptable error for the "cheapest" choice: 1% or 0.01.
        #[arg(long, default_value = "1%", allow_hyphen_values = true, value_parser = vbi::study::converge::parse_tolerance)]
        tolerance: f64,
        /// Runs on the time-step ladder (the scenario's step × 1, 2, 4, …).
        #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=16))]
        levels: u32,
        /// Output folder. Default: results/<file stem>-converge.
        #[arg(long)]
        out: Option<PathBuf>,
        /// No progress and no closing message (the table is still printed).
        #[arg(long, short)]
        quiet: bool,
        /// Leave this recorded quantity (by name) out of the overall
        /// "cheapest within tolerance" (it is still measured and judged on
        /// its own); may be repeated.
        #[arg(long, value_name = "NAME")]
        exclude: Vec<String>,
        /// Write into the output folder even if it holds another scene
        /// file's results.
        #[arg(long)]
        force: bool,
    },
    /// Print a shell completion script: `vbi completions bash >
    /// ~/.local/share/bash-completion/completions/vbi` (zsh: a file `_vbi` on
    /// `$fpath`; fish: `~/.config/fish/completions/vbi.fish`).
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the manual page (roff): `vbi man > ~/.local/share/man/man1/vbi.1`.
    Man,
    /// Write a commented starter scene (and the schema beside it, for the
    /// editor) that `vbi check` accepts and `vbi run` runs.
    Init {
        /// The bridge.
        #[arg(long, value_enum, default_value = "beam")]
        bridge: vbi::init::StarterBridge,
        /// The vehicle.
        #[arg(long, value_enum, default_value = "oscillator")]
        vehicle: vbi::init::StarterVehicle,
        /// The scene file to write.
        #[arg(default_value = "scene.yaml")]
        file: PathBuf,
        /// Replace an existing file.
        #[arg(long)]
        force: bool,
    },
    /// Golden-file regression for your own scenes: `approve` runs them and
    /// stores a compact record of their results in the store folder,
    /// `check` re-runs them and compares (exit 0 all pass, 1 a result or
    /// scene changed, 2 a scene could not run or has no record). Tolerances:
    /// `regress.yaml` in the store (see the README, "Regression").
    Regress {
        #[command(subcommand)]
        action: Regress,
    },
}

#[derive(Debug, Subcommand)]
enum Regress {
    /// Run the scenes and write (or replace) their golden records in the store.
    Approve {
        /// Scenario files (single runs and studies).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Folder of the golden records (created): one folder per scene,
        /// named after the file's stem.
        #[arg(long, value_name = "DIR")]
        store: PathBuf,
    },
    /// Re-run the scenes and compare them with their golden records.
    Check {
        /// Scenario files (single runs and studies).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Folder of the golden records.
        #[arg(long, value_name = "DIR")]
        store: PathBuf,
        /// Also write the result as JUnit XML (one test case per scene).
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Folder for the plots of old against new of each changed history
        /// column or study table column (in DIR/<scene>/).
        /// Default: results/regress.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
}

#[derive(Debug, Subcommand)]
enum Generate {
    /// A multi-span railway viaduct in the layout of the EMBS paper (deck,
    /// piers, bearings, ballast, sleepers, pads, two rails; Table 1 defaults).
    Viaduct {
        /// Number of simply supported spans.
        #[arg(long, default_value_t = 30)]
        spans: usize,
        /// Span length, m.
        #[arg(long, default_value_t = 25.0)]
        span_length: f64,
        /// Pier height, m.
        #[arg(long, default_value_t = 10.0)]
        pier_height: f64,
        /// Track length on the embankment at each end, m.
        #[arg(long, default_value_t = 10.0)]
        approach_length: f64,
        /// Nominal sleeper spacing, m.
        #[arg(long, default_value_t = 0.6)]
        sleeper_spacing: f64,
        /// Rail elements between two sleepers (mesh refinement).
        #[arg(long, default_value_t = 2)]
        rail_divisions: usize,
        /// Elements along each pier.
        #[arg(long, default_value_t = 10)]
        pier_elements: usize,
        /// Output folder (created; its files are replaced).
        #[arg(long)]
        out: PathBuf,
    },
}

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

// After the macros, which it uses.
mod regress_cmd;
mod studies;
use studies::{merge, run_sample, run_shard, write_study};

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
    let load = |file: &Path| scenario::load_file_with(file, options.clone());
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
            let loaded = scenario::load_file_with(&file, options.clone());
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

fn generate(what: Generate) -> ExitCode {
    let Generate::Viaduct {
        spans,
        span_length,
        pier_height,
        approach_length,
        sleeper_spacing,
        rail_divisions,
        pier_elements,
        out,
    } = what;
    let params = vbi::generate::viaduct::ViaductParams {
        spans,
        span_length,
        pier_height,
        approach_length,
        sleeper_spacing,
        rail_divisions,
        pier_elements,
        ..Default::default()
    };
    match vbi::generate::write_viaduct(&params, &out) {
        Ok(reduced) => {
            outln!(
                "wrote {} ({} DOFs, {} + {} stored entries in K and M)",
                out.display(),
                reduced.order,
                reduced.stiffness.len(),
                reduced.mass.len()
            );
            ExitCode::SUCCESS
        }
        Err(e @ vbi::generate::WriteError::Params(_)) => {
            errln!("error: {e}");
            ExitCode::from(EXIT_INVALID)
        }
        Err(e) => {
            errln!("error: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}

/// The default output folder: `results/<file stem><suffix>`. From the file,
/// not the scene's `name`: two files that share a `name` do not overwrite
/// each other's results, and a `name` with `/` or `..` cannot lead outside
/// `results/`.
fn default_out(file: &Path, suffix: &str) -> PathBuf {
    let stem = file
        .file_stem()
        .map_or_else(|| "scene".into(), |s| s.to_string_lossy());
    Path::new("results").join(format!("{stem}{suffix}"))
}

fn load_error(e: &LoadError) -> ExitCode {
    errln!("error: {e}");
    match e {
        LoadError::Io { .. } => ExitCode::from(EXIT_INVALID),
        LoadError::Invalid(_) => ExitCode::from(EXIT_INVALID),
    }
}

fn run(
    loaded: Result<scenario::Loaded, LoadError>,
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
    for warning in vbi::report::advice::scene_warnings(&scenario) {
        errln!("warning: {}: {warning}", file.display());
    }
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
        study => return write_study(&out, &scenario, &study, quiet),
    };
    if let Err(e) = vbi::run::write_results_with(&out, &scenario, &outcome, svg) {
        errln!("error: {e}");
        return ExitCode::from(EXIT_FAILED);
    }
    for warning in vbi::report::advice::run_warnings(&scenario, &outcome.summary) {
        errln!("warning: {}: {warning}", file.display());
    }
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
        errln!("results in {}", out.display());
    }
    ExitCode::SUCCESS
}

fn check(
    files: &[PathBuf],
    load: &dyn Fn(&Path) -> Result<scenario::Loaded, LoadError>,
    shards: Option<u64>,
    allow_large: bool,
) -> ExitCode {
    let mut invalid = false;
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
                for warning in vbi::report::advice::scene_warnings(&loaded.scenario) {
                    errln!("warning: {}: {warning}", file.display());
                }
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
        ExitCode::SUCCESS
    }
}

fn modes(
    file: &Path,
    options: scenario::LoadOptions,
    shapes: Option<&Path>,
    json: bool,
) -> ExitCode {
    let vbi::scenario::bridge_only::ModesScene {
        name,
        bridge,
        scenario,
    } = match scenario::load_file_for_modes(file, options) {
        Ok(scene) => scene,
        Err(e) => return load_error(&e),
    };
    let plate = bridge.width().is_some();
    if json {
        outln!("{}", modes_json(&name, &bridge, scenario.as_ref()));
        return ExitCode::SUCCESS;
    }
    out!(
        "{}: {} modes used of {} available ({})\n{:>5} {:>14} {:>14} {:>12}{}\n",
        name,
        bridge.mode_count(),
        bridge.available_modes,
        bridge.selection,
        "mode",
        "frequency_Hz",
        "period_s",
        "damping",
        // A plate mode's (m, n): its dominant longitudinal and transverse terms.
        if plate { "  (m, n)" } else { "" }
    );
    for (i, (f, z)) in bridge
        .frequencies()
        .iter()
        .zip(&bridge.damping_ratios)
        .enumerate()
    {
        let character = if plate {
            format!("  {}", bridge.mode_character(i))
        } else {
            String::new()
        };
        outln!(
            "{:>5} {:>14.6} {:>14.6} {:>12.4}{character}",
            i + 1,
            f,
            1.0 / f,
            z
        );
    }
    if let Some(scenario) = &scenario {
        print_vehicle_frequencies(scenario);
    }
    if let Some(path) = shapes {
        let text = vbi::report::mode_shapes_csv(&bridge);
        if path == Path::new("-") {
            out!("{text}");
        } else {
            if let Err(e) = vbi::report::write_atomic(path, text.as_bytes()) {
                errln!("error: {e}");
                return ExitCode::from(EXIT_FAILED);
            }
            errln!("mode shapes written to {}", path.display());
        }
    }
    ExitCode::SUCCESS
}

/// The modes of `bridge` as JSON: every frequency at full precision
/// (shortest round-trip decimal), damping, character, and the checks the
/// modes passed ([`vbi::bridge::eigen::ModeCheck`]); and, when the scene
/// has vehicles, each vehicle's natural frequencies with its wheels on
/// rigid ground at full precision (the text output prints them to four
/// decimals).
fn modes_json(
    name: &str,
    bridge: &vbi::bridge::ModalBridge,
    scenario: Option<&vbi::scenario::resolved::Scenario>,
) -> String {
    let check = bridge.check;
    let two_pi = 2.0 * std::f64::consts::PI;
    let modes: Vec<serde_json::Value> = bridge
        .frequencies()
        .iter()
        .zip(&bridge.circular_frequencies)
        .zip(&bridge.damping_ratios)
        .enumerate()
        .map(|(i, ((f, w), z))| {
            serde_json::json!({
                "mode": i + 1,
                "frequency_hz": f,
                "circular_frequency_rad_s": w,
                "period_s": 1.0 / f,
                "damping_ratio": z,
                "character": bridge.mode_character(i),
            })
        })
        .collect();
    let value = serde_json::json!({
        "scenario": name,
        "modes_used": bridge.mode_count(),
        "modes_available": bridge.available_modes,
        "selection": bridge.selection,
        "check": {
            "solver": if check.dense { "dense inverted reduction" } else { "shift-invert Lanczos" },
            "largest_energy_residual": check.largest_residual,
            "largest_plain_residual": check.largest_plain_residual,
            "residual_bound": vbi::bridge::eigen::RESIDUAL_BOUND,
            "orthonormality_error": check.orthonormality_error,
            "orthonormality_bound": vbi::bridge::eigen::ORTHONORMALITY_BOUND,
            "sturm_count": check.inertia.map(|(shift, count)| serde_json::json!({
                "below_hz": shift.sqrt() / two_pi,
                "modes": count,
            })),
        },
        "modes": modes,
        "vehicles": scenario.map_or_else(Vec::new, vehicle_frequencies_json),
    });
    serde_json::to_string_pretty(&value).expect("JSON of numbers and strings")
}

/// Each vehicle's natural frequencies (Hz, wheels on rigid ground, massless
/// DOFs condensed out) as JSON objects `{vehicle, type, frequencies_hz}`,
/// every frequency in its shortest round-trip form.
fn vehicle_frequencies_json(
    scenario: &vbi::scenario::resolved::Scenario,
) -> Vec<serde_json::Value> {
    use vbi::scenario::content::vehicle_frequencies;
    use vbi::vehicle::VehicleModel;
    scenario
        .vehicles
        .iter()
        .enumerate()
        .map(|(i, vehicle)| {
            let model = VehicleModel::build(vehicle, scenario.gravity);
            serde_json::json!({
                "vehicle": i + 1,
                "type": vehicle.type_name(),
                "frequencies_hz": vehicle_frequencies(&model, None),
            })
        })
        .collect()
}

/// Each vehicle's own natural frequencies with its wheels held on rigid
/// ground (massless DOFs condensed out), to set against the bridge's.
fn print_vehicle_frequencies(scenario: &vbi::scene::Scenario) {
    use vbi::scenario::content::vehicle_frequencies;
    use vbi::vehicle::VehicleModel;
    let hz = |f: &[f64]| {
        if f.is_empty() {
            "none (no mass on springs)".to_string()
        } else {
            f.iter()
                .map(|f| format!("{f:.4}"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    outln!("vehicle natural frequencies, Hz (wheels on rigid ground):");
    for (i, vehicle) in scenario.vehicles.iter().enumerate() {
        let model = VehicleModel::build(vehicle, scenario.gravity);
        outln!(
            "{:>5} {:<14} {}",
            i + 1,
            vehicle.type_name(),
            hz(&vehicle_frequencies(&model, None))
        );
    }
}

#[allow(clippy::too_many_arguments)]
fn converge(
    loaded: Result<scenario::Loaded, LoadError>,
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
    if !quiet {
        errln!("results in {}", out.display());
    }
    ExitCode::SUCCESS
}

/// The study as a table on stdout: one row per run, then the observed
/// orders and the cheapest run within tolerance.
fn print_convergence(study: &vbi::study::converge::Convergence) {
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

/// `vbi init`: the starter scene, and `vbi.schema.json` beside it so the
/// modeline (a path relative to the scene) works wherever the folder is.
fn init(
    bridge: vbi::init::StarterBridge,
    vehicle: vbi::init::StarterVehicle,
    file: &Path,
    force: bool,
) -> ExitCode {
    const SCHEMA_FILE: &str = "vbi.schema.json";
    let text = match vbi::init::starter(bridge, vehicle, SCHEMA_FILE) {
        Ok(text) => text,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(EXIT_INVALID);
        }
    };
    if file.exists() && !force {
        errln!(
            "error: {} exists: choose another file name or add --force to replace it",
            file.display()
        );
        return ExitCode::from(EXIT_INVALID);
    }
    let folder = match file.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let schema_path = folder.join(SCHEMA_FILE);
    let written = std::fs::create_dir_all(&folder)
        .and_then(|()| vbi::report::atomic::write_atomic(file, text.as_bytes()))
        .and_then(|()| {
            vbi::report::atomic::write_atomic(&schema_path, vbi::schema::schema_json().as_bytes())
        });
    match written {
        Ok(()) => {
            errln!(
                "wrote {} (and {} for the editor); next: vbi check {0}, then vbi run {0}",
                file.display(),
                schema_path.display()
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            errln!("error: {}: {e}", file.display());
            ExitCode::from(EXIT_FAILED)
        }
    }
}
