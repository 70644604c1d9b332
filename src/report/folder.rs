//! The output folder of a scene: its default name, creating it (and
//! clearing what a killed run left), the `resolved.yaml` that names the scene
//! file whose results it holds, and the refusal to mix two scenes' files.

use std::path::{Path, PathBuf};

use super::ReportError;
use crate::scene::Scenario;

/// The default output folder of a scene: `results/` and its `name` made
/// safe as one folder name ([`crate::scenario::names::folder_name`]: no
/// separators, no `..`, not absolute, no control characters), then
/// `suffix`. A name from someone else's file therefore cannot put results
/// anywhere but under `results/`.
pub fn default_out(name: &str, suffix: &str) -> PathBuf {
    let folder = crate::scenario::names::folder_name(name);
    Path::new("results").join(format!("{folder}{suffix}"))
}

/// Creates the output folder and removes the partial files a run killed
/// from outside left there ([`super::PARTIAL_MARK`] in the name, written by
/// another process id that is no longer running here).
pub fn create_out(out: &Path) -> Result<(), ReportError> {
    std::fs::create_dir_all(out).map_err(|source| ReportError::Io {
        path: out.to_path_buf(),
        source,
    })?;
    super::remove_stale_partials(out);
    Ok(())
}

/// The resolved scenario as YAML, with a header line (and, when the scene
/// knows its file, a second one naming it: [`FROM`]).
pub fn resolved_yaml(scenario: &Scenario) -> String {
    let resolved = serde_json::to_value(scenario).expect("scenario serialises");
    let from = scenario.source_file.as_ref().map_or_else(String::new, |f| {
        // One line whatever the name holds.
        let f: String = f.chars().filter(|c| !c.is_control()).collect();
        format!("{FROM}{f}\n")
    });
    let read = read_pins(scenario);
    format!(
        "# Resolved by vbi {}: the scene as run, every default filled in.\n{from}{read}{}",
        env!("CARGO_PKG_VERSION"),
        super::yaml::to_yaml(&resolved)
    )
}

/// The header lines that pin the data files `scenario` read, one each, so
/// that a scene written with them reruns from any folder reading only these
/// bytes ([`crate::scenario::data_files::READ`]). A path that would not fit
/// on one line is left unpinned.
pub fn read_pins(scenario: &Scenario) -> String {
    scenario
        .data_read
        .iter()
        .filter(|r| !r.path.chars().any(char::is_control))
        .map(|r| {
            format!(
                "{}{} {}\n",
                crate::scenario::data_files::READ,
                r.sha256,
                r.path
            )
        })
        .collect()
}

/// The start of `resolved.yaml`'s line that names the scene file whose
/// results the folder holds.
pub const FROM: &str = "# From: ";

/// The file that names a folder's scene where no `resolved.yaml` does:
/// `vbi converge`'s folder and the `--shard` parts' folder hold one line,
/// [`FROM`] and the scene file ([`mark_folder`]).
pub const OWNER_FILE: &str = ".vbi-owner";

/// The scene file whose results the folder `out` holds, as its
/// `resolved.yaml` names it, or else its [`OWNER_FILE`]; `None` when there
/// is none or it names none. Only each file's first 8 kB are read (the
/// header is its first lines).
pub fn folder_owner(out: &Path) -> Option<String> {
    named_in(out, "resolved.yaml").or_else(|| named_in(out, OWNER_FILE))
}

/// The scene file the file `name` in `folder` names in its first three
/// lines ([`FROM`]), reading at most its first 8 kB.
fn named_in(folder: &Path, name: &str) -> Option<String> {
    use std::io::Read;
    let file = crate::guarded_file::open_regular(&folder.join(name)).ok()?;
    let mut head = Vec::new();
    file.take(8192).read_to_end(&mut head).ok()?;
    let head = String::from_utf8_lossy(&head);
    head.lines()
        .take(3)
        .find_map(|l| l.strip_prefix(FROM))
        .map(str::to_string)
}

/// Writes the [`OWNER_FILE`] naming `source` (canonical) into `out` (made
/// if missing): the folder's results are that scene file's, so another
/// scene's `vbi run`, `converge` or `--shard` into it is refused
/// ([`claim_folder`]).
pub fn mark_folder(out: &Path, source: &str) -> std::io::Result<()> {
    std::fs::create_dir_all(out)?;
    let source: String = source.chars().filter(|c| !c.is_control()).collect();
    crate::atomic_file::write_atomic(
        &out.join(OWNER_FILE),
        format!("{FROM}{source}\n").as_bytes(),
    )
    .map_err(std::io::Error::other)
}

/// Refuses to write the results of the scene file `source` (canonical) into
/// `out` when the folder holds another scene file's results (issue 22: two
/// scenes must not mix their files in one folder); `force` allows it.
pub fn claim_folder(out: &Path, source: &str, force: bool) -> Result<(), String> {
    match folder_owner(out) {
        Some(owner) if owner != source && !force => Err(format!(
            "{} holds the results of another scene file, {owner}; give this one its own folder \
             with `--out DIR`, or replace them with `--force`",
            out.display()
        )),
        _ => Ok(()),
    }
}

/// The name a scene file is known by in `resolved.yaml`: its canonical
/// path (symlinks resolved), or its absolute path when that fails. A
/// `resolved.yaml` rerun is known by the scene file it names ([`FROM`]), so
/// that it may rerun into the folder that holds its results.
pub fn source_name(file: &Path) -> String {
    if file.file_name() == Some(std::ffi::OsStr::new("resolved.yaml"))
        && let Some(parent) = file.parent()
        && let Some(original) = named_in(
            if parent.as_os_str().is_empty() {
                Path::new(".")
            } else {
                parent
            },
            "resolved.yaml",
        )
    {
        return original;
    }
    std::fs::canonicalize(file)
        .or_else(|_| std::path::absolute(file))
        .unwrap_or_else(|_| file.to_path_buf())
        .display()
        .to_string()
}
