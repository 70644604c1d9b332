//! The `vbi` command line's arguments: every subcommand and option, with
//! the help texts `--help`, the manual page and the completions show.

use std::path::PathBuf;

use clap::{Parser, Subcommand};

/// Vehicle–bridge interaction dynamics from a YAML scene.
#[derive(Debug, Parser)]
#[command(name = "vbi", version, about, propagate_version = true)]
pub(super) struct Cli {
    #[command(subcommand)]
    pub(super) command: Command,
    /// Lift the resource limits (DOFs, steps, wheels, records, study points,
    /// output size) for a scene that really needs more; see `limits` in the format.
    #[arg(long, global = true)]
    pub(super) allow_large: bool,
    /// Let the file's own `limits` section raise limits above the defaults
    /// (without it a file can only lower them, so a stranger's file cannot
    /// lift them for you).
    #[arg(long, global = true)]
    pub(super) trust_limits: bool,
    /// Folder of the modes cache: an imported model's modes are read from it
    /// when a valid file holds them and written to it when solved. Default
    /// for `run`: `.vbi-cache` inside the output folder; other commands use a
    /// cache only when given one.
    #[arg(long, global = true, value_name = "DIR")]
    pub(super) modes_cache: Option<PathBuf>,
    /// Solve every imported model's modes afresh and write no cache.
    #[arg(long, global = true, conflicts_with = "modes_cache")]
    pub(super) no_modes_cache: bool,
    /// Let scenes read files in DIR and below (repeatable): without it a
    /// scene reads only files inside its own folder tree (symlinks resolved)
    /// and no absolute path.
    #[arg(long, global = true, value_name = "DIR")]
    pub(super) data_dir: Vec<PathBuf>,
    /// Fail with exit code 4 when the scene or its run draws a warning the
    /// scene does not allow (`allow: [{id, reason}]`; the ids are in
    /// docs/advice.md). The results are written all the same.
    #[arg(long, global = true)]
    pub(super) deny_warnings: bool,
    /// Threads for the eigen solve and the study runs. Default: the
    /// `VBI_THREADS` environment variable, else `RAYON_NUM_THREADS`, else
    /// every core. Results are bit-identical whatever the number.
    #[arg(long, global = true, value_name = "N")]
    pub(super) threads: Option<std::num::NonZeroUsize>,
}

#[derive(Debug, Subcommand)]
pub(super) enum Command {
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
    /// Explain an advice id (a warning or note vbi makes), or list them all
    /// (with --markdown: the reference, docs/advice.md).
    Advice {
        /// The id, e.g. `run-ends-at-peak`. Without it: every id.
        id: Option<String>,
        /// Print the whole reference (Markdown).
        #[arg(long, conflicts_with = "id")]
        markdown: bool,
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
    /// Print a manual page (roff), or write every page: `vbi man --dir
    /// ~/.local/share/man/man1` (vbi.1, vbi-run.1, …), then `man vbi-run`.
    Man {
        /// The page to print: a subcommand (`run`, `regress-check`) or a
        /// page name (`vbi-run`). Default: vbi(1).
        page: Option<String>,
        /// Write every page (one per command, `<page>.1`) into DIR instead.
        #[arg(long, value_name = "DIR", conflicts_with = "page")]
        dir: Option<PathBuf>,
    },
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
    /// `regress.yaml` in the store (see docs/guide/regression.md).
    Regress {
        #[command(subcommand)]
        action: Regress,
    },
}

#[derive(Debug, Subcommand)]
pub(super) enum Regress {
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
pub(super) enum Generate {
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
