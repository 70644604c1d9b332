//! The `vbi` command line: parses arguments, calls the library, prints, and
//! maps errors to exit codes (0 success, 1 a run failed, 2 invalid input).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use vbi::scenario::{self, LoadError};

/// Vehicle–bridge interaction dynamics from a YAML scene.
#[derive(Debug, Parser)]
#[command(name = "vbi", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene and write summary.json, history.csv and resolved.yaml.
    Run {
        /// The scenario file.
        file: PathBuf,
        /// Output folder. Default: results/<scenario name>.
        #[arg(long)]
        out: Option<PathBuf>,
        /// No progress bar.
        #[arg(long, short)]
        quiet: bool,
    },
    /// Parse and validate scenario files; exit 2 if any is invalid.
    Check {
        /// Scenario files.
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
    /// Print the JSON Schema of the scenario format.
    Schema,
    /// Natural frequencies (and, with --shapes, mode shapes) of a scene's bridge.
    Modes {
        /// The scenario file.
        file: PathBuf,
        /// Write mode shapes at the mesh nodes to this CSV file.
        #[arg(long)]
        shapes: Option<PathBuf>,
    },
}

const EXIT_FAILED: u8 = 1;
const EXIT_INVALID: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Run { file, out, quiet } => run(&file, out, quiet),
        Command::Check { files } => check(&files),
        Command::Schema => {
            print!("{}", vbi::schema::schema_json());
            ExitCode::SUCCESS
        }
        Command::Modes { file, shapes } => modes(&file, shapes.as_deref()),
    }
}

fn load_error(e: &LoadError) -> ExitCode {
    eprintln!("error: {e}");
    match e {
        LoadError::Io { .. } => ExitCode::from(EXIT_INVALID),
        LoadError::Invalid(_) => ExitCode::from(EXIT_INVALID),
    }
}

fn run(file: &Path, out: Option<PathBuf>, quiet: bool) -> ExitCode {
    let loaded = match scenario::load_file(file) {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    let scenario = loaded.scenario.clone();
    let out = out.unwrap_or_else(|| Path::new("results").join(&scenario.name));
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} {msg} [{bar:30}] {percent}% eta {eta}")
                .expect("valid template")
                .progress_chars("=> "),
        );
        bar.set_message(scenario.name.clone());
        bar
    };
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let results = match vbi::run::execute(loaded, &progress) {
        Ok(r) => r,
        Err(e) => {
            bar.abandon();
            eprintln!("error: {}: {e}", file.display());
            return ExitCode::from(EXIT_FAILED);
        }
    };
    bar.finish_and_clear();
    let outcome = match results {
        vbi::run::Results::Scene(outcome) => outcome,
        vbi::run::Results::SeparationMap(map) => {
            if let Err(e) = vbi::run::write_study(&out, &scenario, &map) {
                eprintln!("error: {e}");
                return ExitCode::from(EXIT_FAILED);
            }
            if !quiet {
                eprintln!(
                    "{}: separation map of {} points, {} separated, {:.2} s",
                    scenario.name,
                    map.points.len(),
                    map.separated_count(),
                    map.wall_time
                );
                eprintln!("results in {}", out.display());
            }
            return ExitCode::SUCCESS;
        }
    };
    if let Err(e) = vbi::run::write_results(&out, &scenario, &outcome) {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_FAILED);
    }
    if !quiet {
        let s = &outcome.summary;
        eprintln!(
            "{}: {} steps of {:.3e} s, {} modes, {:.1} ms",
            s.scenario,
            s.run.steps,
            s.run.time_step,
            s.run.modes_used,
            s.run.wall_time * 1e3
        );
        for q in &s.quantities {
            let daf = q.daf.map(|d| format!("  DAF {d:.4}")).unwrap_or_default();
            eprintln!(
                "  {:<24} max|.| {:>12.5e} {} at t = {:.4} s{daf}",
                q.name, q.max_abs.value, q.unit, q.max_abs.time
            );
        }
        eprintln!("results in {}", out.display());
    }
    ExitCode::SUCCESS
}

fn check(files: &[PathBuf]) -> ExitCode {
    let mut invalid = false;
    for file in files {
        match scenario::load_file(file) {
            Ok(_) => println!("{}: ok", file.display()),
            Err(e) => {
                invalid = true;
                eprintln!("error: {e}");
            }
        }
    }
    if invalid {
        ExitCode::from(EXIT_INVALID)
    } else {
        ExitCode::SUCCESS
    }
}

fn modes(file: &Path, shapes: Option<&Path>) -> ExitCode {
    let loaded = match scenario::load_file(file) {
        Ok(l) => l,
        Err(e) => return load_error(&e),
    };
    let bridge = &loaded.bridge;
    println!(
        "{}: {} modes used of {} available",
        loaded.scenario.name,
        bridge.mode_count(),
        bridge.available_modes
    );
    println!(
        "{:>5} {:>14} {:>14} {:>12}",
        "mode", "frequency_Hz", "period_s", "damping"
    );
    for (i, (f, z)) in bridge
        .frequencies()
        .iter()
        .zip(&bridge.damping_ratios)
        .enumerate()
    {
        println!("{:>5} {:>14.6} {:>14.6} {:>12.4}", i + 1, f, 1.0 / f, z);
    }
    if let Some(path) = shapes {
        let text = vbi::report::mode_shapes_csv(bridge);
        if let Err(e) = vbi::report::write_atomic(path, text.as_bytes()) {
            eprintln!("error: {e}");
            return ExitCode::from(EXIT_FAILED);
        }
        println!("mode shapes written to {}", path.display());
    }
    ExitCode::SUCCESS
}
