//! `vbi man`: one manual page per command — `vbi(1)`, `vbi-run(1)`, …,
//! `vbi-regress-check(1)` — rendered from the command line's definition
//! (clap_mangen), each with an EXIT STATUS section stating the codes that
//! command returns and a SEE ALSO section that names only pages written here.
//!
//! `vbi man` prints vbi(1); `vbi man PAGE` prints one page (`run`,
//! `regress-check` or `vbi-run`); `vbi man --dir DIR` writes every page as
//! `DIR/<page>.1`.

use std::path::Path;
use std::process::ExitCode;

use clap::CommandFactory;

use super::cli::Cli;
use super::{EXIT_FAILED, EXIT_INVALID, emit};

/// One manual page: its name (`vbi-run`) and its roff text.
struct Page {
    name: String,
    roff: String,
}

/// Usage errors (an unknown option, a missing argument), which every
/// command shares: clap reports them and exits 2; `--help` and `--version`
/// exit 0.
const USAGE: (u8, &str) = (
    2,
    "The command line itself is wrong: an unknown subcommand or option, a missing or malformed argument (`--help` and `--version` exit 0).",
);

/// The exit codes the command of page `name` returns (read from the code
/// that returns them: `src/main.rs` and its `*_cmd.rs` modules).
fn exit_status(name: &str) -> Vec<(u8, &'static str)> {
    const OK: (u8, &str) = (0, "Success.");
    const DENIED: (u8, &str) = (
        4,
        "The work succeeded and its files are written, but `--deny-warnings` was given and the scene or its run drew a warning the scene does not allow (`allow: [{id, reason}]`; `vbi advice` explains each id).",
    );
    match name {
        "vbi" => vec![
            OK,
            (
                1,
                "A run, a study or a write failed: the solution diverged or stopped being finite, a solver did not converge, a file could not be written (`vbi regress check`: a scene or its results changed).",
            ),
            (
                2,
                "Invalid input: a scene, part or data file that does not parse or fails a check or a budget, a file that cannot be read, an output folder holding another scene's results, a usage error.",
            ),
            (
                3,
                "A check ran and its verdict is \"fails\" (an HSLM resonance check above the deck-acceleration limit); its files are written.",
            ),
            DENIED,
        ],
        "vbi-run" => vec![
            OK,
            (
                1,
                "The run or the study failed (the solution diverged, a contact problem had no solution, an iteration did not converge), or its files could not be written.",
            ),
            (
                2,
                "The scene is invalid or cannot be read, the output folder holds another scene file's results (without `--force`), `--shard` does not fit the study, or `--sample` names no sample of a Monte Carlo study.",
            ),
            (
                3,
                "A resonance check ran and fails (a deck acceleration above the limit); its files are written.",
            ),
            (
                4,
                "As 0, but `--deny-warnings` was given and the scene or its run drew a warning the scene does not allow (not with `--shard`, whose part records the advice for `vbi merge`).",
            ),
        ],
        "vbi-merge" => vec![
            OK,
            (
                1,
                "A run of the parts' scene failed, or the merged files could not be written.",
            ),
            (
                2,
                "A part is missing, given twice, of another scene or shard count, not a part, too large, or the scene it holds is invalid; or the output folder holds another scene file's results.",
            ),
            (
                3,
                "The merged study is a resonance check that fails; its files are written.",
            ),
            DENIED,
        ],
        "vbi-check" => vec![
            (0, "Every file is valid."),
            (
                2,
                "A file is invalid or cannot be read, or (with `--shards N`) its study does not split into N shards.",
            ),
            (
                4,
                "Every file is valid, but `--deny-warnings` was given and a scene draws a warning it does not allow.",
            ),
        ],
        "vbi-advice" => vec![OK, (2, "The id is not an advice id.")],
        "vbi-schema" | "vbi-completions" => vec![OK],
        "vbi-export" => vec![
            OK,
            (1, "The files could not be written."),
            (
                2,
                "The scene is invalid or cannot be read, or its bridge is not a `type: beam`.",
            ),
        ],
        "vbi-modes" => vec![
            OK,
            (1, "The mode shapes (`--shapes`) could not be written."),
            (2, "The scene is invalid or cannot be read."),
        ],
        "vbi-generate" | "vbi-generate-viaduct" => vec![
            OK,
            (1, "The model's files could not be written."),
            (2, "A parameter is out of range."),
        ],
        "vbi-converge" => vec![
            OK,
            (
                1,
                "A run of the ladder failed, or the files could not be written.",
            ),
            (
                2,
                "The scene is invalid or cannot be read, the options do not fit it, or the output folder holds another scene file's results.",
            ),
            DENIED,
        ],
        "vbi-man" => vec![
            OK,
            (1, "A page could not be rendered or written."),
            (2, "PAGE names no manual page."),
        ],
        "vbi-init" => vec![
            OK,
            (1, "The scene or the schema could not be written."),
            (
                2,
                "The file exists (without `--force`), or the bridge and the vehicle do not combine.",
            ),
        ],
        "vbi-regress" => vec![
            (0, "Every scene passes (check) or was approved (approve)."),
            (1, "`check`: a scene or its results changed."),
            (
                2,
                "A scene could not run or has no record, the store or its `regress.yaml` is invalid, or the JUnit file could not be written.",
            ),
        ],
        "vbi-regress-approve" => vec![
            (0, "Every scene ran and its record was written."),
            (
                2,
                "A scene could not run (its old record is kept), or the store is unusable.",
            ),
        ],
        "vbi-regress-check" => vec![
            (0, "Every scene passes."),
            (
                1,
                "A scene or its results changed beyond the tolerances (the report says which and where).",
            ),
            (
                2,
                "A scene could not run or has no record, the store's `regress.yaml` is invalid, or the JUnit file could not be written.",
            ),
        ],
        _ => vec![OK],
    }
}

/// Pages related to page `name` beyond its parent and its own
/// subcommands, for SEE ALSO.
fn related(name: &str) -> &'static [&'static str] {
    match name {
        "vbi-run" => &[
            "vbi-check",
            "vbi-merge",
            "vbi-converge",
            "vbi-advice",
            "vbi-init",
        ],
        "vbi-merge" => &["vbi-run"],
        "vbi-check" => &["vbi-run", "vbi-schema", "vbi-advice"],
        "vbi-advice" => &["vbi-run", "vbi-check"],
        "vbi-schema" => &["vbi-init", "vbi-check"],
        "vbi-export" => &["vbi-run", "vbi-modes"],
        "vbi-modes" => &["vbi-run", "vbi-converge"],
        "vbi-generate" | "vbi-generate-viaduct" => &["vbi-run", "vbi-modes"],
        "vbi-converge" => &["vbi-run", "vbi-modes"],
        "vbi-completions" => &["vbi-man"],
        "vbi-man" => &["vbi-completions"],
        "vbi-init" => &["vbi-check", "vbi-run", "vbi-schema"],
        "vbi-regress" | "vbi-regress-approve" | "vbi-regress-check" => &["vbi-run"],
        _ => &[],
    }
}

/// Escapes text for roff: backslashes, hyphens (so that `man` prints a
/// minus), and a leading `.` or `'`, which would start a request.
fn roff_text(text: &str) -> String {
    let escaped = text.replace('\\', "\\e").replace('-', "\\-");
    if escaped.starts_with('.') || escaped.starts_with('\'') {
        format!("\\&{escaped}")
    } else {
        escaped
    }
}

/// Renders the page of `cmd` (built, with its display name `vbi-…`);
/// `parent` names the page of the command it belongs to.
fn render(cmd: &clap::Command, parent: Option<&str>) -> std::io::Result<Page> {
    let name = cmd
        .get_display_name()
        .unwrap_or_else(|| cmd.get_name())
        .to_string();
    let man =
        clap_mangen::Man::new(cmd.clone()).source(format!("vbi {}", env!("CARGO_PKG_VERSION")));
    let mut out = Vec::new();
    man.render_title(&mut out)?;
    man.render_name_section(&mut out)?;
    man.render_synopsis_section(&mut out)?;
    man.render_description_section(&mut out)?;
    if cmd.get_arguments().any(|a| !a.is_hide_set()) {
        man.render_options_section(&mut out)?;
    }
    let children: Vec<String> = cmd
        .get_subcommands()
        .filter(|s| !s.is_hide_set())
        .map(|s| format!("{name}-{}", s.get_name()))
        .collect();
    if !children.is_empty() {
        man.render_subcommands_section(&mut out)?;
    }
    let mut roff = String::from_utf8_lossy(&out).into_owned();
    roff.push_str(".SH \"EXIT STATUS\"\n");
    let mut codes = exit_status(&name);
    if !codes.iter().any(|(code, _)| *code == USAGE.0) {
        codes.push(USAGE);
    }
    for (code, meaning) in codes {
        roff.push_str(&format!(".TP\n\\fB{code}\\fR\n{}\n", roff_text(meaning)));
    }
    let mut see: Vec<String> = Vec::new();
    if parent.is_some() {
        see.push("vbi".to_string());
    }
    if let Some(p) = parent.filter(|p| *p != "vbi") {
        see.push(p.to_string());
    }
    see.extend(children);
    see.extend(related(&name).iter().map(|s| s.to_string()));
    let mut seen = std::collections::HashSet::new();
    see.retain(|p| *p != name && seen.insert(p.clone()));
    if !see.is_empty() {
        roff.push_str(".SH \"SEE ALSO\"\n");
        let refs: Vec<String> = see
            .iter()
            .map(|p| format!("\\fB{}\\fR(1)", roff_text(p)))
            .collect();
        roff.push_str(&refs.join(", "));
        roff.push('\n');
    }
    let mut tail = Vec::new();
    if cmd.get_version().is_some() {
        man.render_version_section(&mut tail)?;
    }
    roff.push_str(&String::from_utf8_lossy(&tail));
    Ok(Page { name, roff })
}

/// Every page: vbi(1) first, then each subcommand's (depth first).
fn pages() -> std::io::Result<Vec<Page>> {
    fn walk(
        cmd: &clap::Command,
        parent: Option<&str>,
        pages: &mut Vec<Page>,
    ) -> std::io::Result<()> {
        let page = render(cmd, parent)?;
        let name = page.name.clone();
        pages.push(page);
        for sub in cmd.get_subcommands().filter(|s| !s.is_hide_set()) {
            walk(sub, Some(&name), pages)?;
        }
        Ok(())
    }
    let mut cmd = Cli::command().disable_help_subcommand(true);
    cmd.build();
    let mut pages = Vec::new();
    walk(&cmd, None, &mut pages)?;
    Ok(pages)
}

/// `vbi man [PAGE] [--dir DIR]`.
pub(super) fn man(page: Option<&str>, dir: Option<&Path>) -> ExitCode {
    let pages = match pages() {
        Ok(p) => p,
        Err(e) => {
            errln!("error: could not render the manual pages: {e}");
            return ExitCode::from(EXIT_FAILED);
        }
    };
    if let Some(dir) = dir {
        if let Err(e) = std::fs::create_dir_all(dir) {
            errln!("error: {}: {e}", dir.display());
            return ExitCode::from(EXIT_FAILED);
        }
        for p in &pages {
            let path = dir.join(format!("{}.1", p.name));
            if let Err(e) = vbi::report::write_atomic(&path, p.roff.as_bytes()) {
                errln!("error: {}: {e}", path.display());
                return ExitCode::from(EXIT_FAILED);
            }
        }
        errln!("wrote {} manual pages to {}", pages.len(), dir.display());
        return ExitCode::SUCCESS;
    }
    let wanted = match page {
        None => "vbi".to_string(),
        Some(p) if p == "vbi" || p.starts_with("vbi-") => p.to_string(),
        Some(p) => format!("vbi-{p}"),
    };
    match pages.iter().find(|p| p.name == wanted) {
        Some(p) => {
            out!("{}", p.roff);
            ExitCode::SUCCESS
        }
        None => {
            errln!(
                "error: `{}` names no manual page",
                vbi::scenario::diagnostic::escaped(page.unwrap_or_default())
            );
            let names: Vec<&str> = pages.iter().map(|p| p.name.as_str()).collect();
            errln!("  = help: the pages are {}", names.join(", "));
            ExitCode::from(EXIT_INVALID)
        }
    }
}
