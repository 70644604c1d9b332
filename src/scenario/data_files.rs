//! Confined reads of the data files a scene names (FE matrices, rail and
//! DOF-map CSVs, ground-motion records, measured profiles).
//!
//! A scene comes from someone else (issue 23): a path in it must not read
//! the user's other files and print them in a diagnostic. A relative path
//! is resolved against the scene file's folder, its symlinks are resolved
//! (`canonicalize`), and the real file must lie inside that folder's tree
//! or inside a folder the user named on the command line (`--data-dir`,
//! repeatable). An absolute path is read only inside a `--data-dir`. Only
//! regular files are read: a device (`/dev/zero`), a FIFO or a folder is
//! refused before it is opened, and the file is opened non-blocking and
//! checked again on the open handle (a file swapped for a FIFO in between
//! cannot hang the read). A refusal names the path and the option, never a
//! byte of the file.
//!
//! A `resolved.yaml` reruns from anywhere (issue 38.7): it names each data
//! file by its absolute path, and its header lists the files the original
//! run read with the SHA-256 of their bytes ([`READ`]). Such a pinned path is
//! read wherever it is (inside the scene's folder too), but its bytes are used only when their hash equals
//! the pinned one; otherwise the file is refused without a word of its
//! content, and whether it exists is not told either. A stranger's file can
//! thus pin only bytes its author already knows: nothing is disclosed, and
//! no other path is let through.

use std::io::Read;
use std::path::{Path, PathBuf};

use super::checker::Checker;

/// Where the files a scene names may be read from.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DataAccess {
    /// Folders outside the scene's own folder tree whose files (and whose
    /// subfolders' files) a scene may read: `--data-dir`, as given.
    pub data_dirs: Vec<PathBuf>,
    /// The folder tree a scene's relative paths must stay inside, in place
    /// of the scene file's own folder. `vbi merge` sets the current folder:
    /// a part file names its scene's file, and that name is not trusted to
    /// say which folder may be read.
    pub confine_to: Option<PathBuf>,
}

/// A data file allowed to be read: the path shown in messages and written
/// in the resolved scene, and its size, bytes.
#[derive(Debug, Clone)]
pub(crate) struct DataFile {
    /// The absolute path (the scene's folder joined with the name as
    /// written, symlinks not resolved), as diagnostics show it.
    pub shown: String,
    /// The real file (symlinks resolved): what is opened.
    pub real: PathBuf,
    /// Size from the file's metadata, bytes.
    pub size: u64,
    /// The SHA-256 (lower-case hex) its bytes must have: the scene's header
    /// pins it ([`READ`]) and it lies outside the folders otherwise allowed.
    pub pinned: Option<String>,
}

/// The start of a scene header's line that pins a data file: `# Read:
/// sha256:<64 hex digits> <absolute path>`, as `resolved.yaml` writes one
/// per file its run read.
pub const READ: &str = "# Read: sha256:";

/// The SHA-256 of `bytes`, lower-case hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The hash `source`'s header pins for the path `named`, if any: only the
/// comment lines before the first other line count, and only well-formed
/// ones (64 hex digits, an absolute path).
fn pinned_hash(source: &str, named: &str) -> Option<String> {
    source
        .lines()
        .take_while(|l| l.trim().is_empty() || l.starts_with('#'))
        .filter_map(|l| l.strip_prefix(READ))
        .filter_map(|rest| rest.split_once(' '))
        .find(|(hash, path)| {
            *path == named
                && Path::new(path).is_absolute()
                && hash.len() == 64
                && hash
                    .bytes()
                    .all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase())
        })
        .map(|(hash, _)| hash.to_string())
}

impl DataFile {
    /// The absolute path as shown.
    pub fn path(&self) -> &Path {
        Path::new(&self.shown)
    }
}

/// The scene file's folder: the parent of the name as given, `.` for a bare
/// file name.
fn scene_folder(file: &str) -> PathBuf {
    match Path::new(file).parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Resolves `named` (a path as written in the scene) and checks it may be
/// read; `what` names the file in messages (`the measured profile`, or
/// empty). The error is the whole message, reported by the caller at its key.
pub(crate) fn locate(named: &str, what: &str, ck: &Checker<'_>) -> Result<DataFile, String> {
    let cannot = |shown: &str, e: &std::io::Error| {
        let what = if what.is_empty() {
            String::new()
        } else {
            format!("{what} ")
        };
        format!("cannot read {what}{shown}: {}", io_reason(e))
    };
    let access = ck.data_access();
    let base = scene_folder(ck.file());
    let written = Path::new(named);
    let joined = base.join(written);
    let shown = std::path::absolute(&joined)
        .unwrap_or_else(|_| joined.clone())
        .display()
        .to_string();
    let option = "run with `--data-dir DIR` naming a folder that holds it";
    // A pinned file is read wherever it is, and only as the bytes pinned.
    if let Some(pinned) = pinned_hash(ck.source, named) {
        return Ok(pinned_file(named, pinned));
    }
    if written.is_absolute() && access.data_dirs.is_empty() {
        return Err(format!(
            "`{named}` is an absolute path; a scene reads files only inside its own folder \
             tree — give a path relative to the scene, or {option}"
        ));
    }
    let own = access.confine_to.clone().unwrap_or(base);
    let real = match std::fs::canonicalize(&joined) {
        Ok(real) => real,
        // A missing file is reported as missing only inside the allowed
        // folders: outside them, whether a file exists is not told either.
        Err(e) => {
            let within = |root: &Path| {
                let root = std::path::absolute(root).unwrap_or_else(|_| root.to_path_buf());
                lexical(Path::new(&shown)).starts_with(lexical(&root))
            };
            let allowed = (!written.is_absolute() && within(&own))
                || access.data_dirs.iter().any(|d| within(d));
            return Err(if allowed {
                cannot(&shown, &e)
            } else {
                format!(
                    "{shown} is outside the scene's folder; a scene reads files only inside its \
                     own folder tree — to allow it, {option}"
                )
            });
        }
    };
    let mut roots: Vec<PathBuf> = Vec::new();
    if !written.is_absolute() {
        roots.extend(std::fs::canonicalize(&own).ok());
    }
    roots.extend(
        access
            .data_dirs
            .iter()
            .filter_map(|d| std::fs::canonicalize(d).ok()),
    );
    if !roots.iter().any(|root| real.starts_with(root)) {
        let through = if lexical(Path::new(&shown)) == real {
            String::new()
        } else {
            format!(" (through a symlink, to {})", real.display())
        };
        let folder = std::path::absolute(&own).unwrap_or(own);
        return Err(format!(
            "{shown} is outside {}{through}; a scene reads files only inside its own folder \
             tree — to allow it, {option}",
            if written.is_absolute() {
                "every `--data-dir`".to_string()
            } else {
                format!("the scene's folder {}", folder.display())
            }
        ));
    }
    let meta = std::fs::metadata(&real).map_err(|e| cannot(&shown, &e))?;
    if !meta.is_file() {
        return Err(format!(
            "{shown} is not a regular file (a folder, a device or a pipe); name a file"
        ));
    }
    Ok(DataFile {
        shown,
        real,
        size: meta.len(),
        pinned: None,
    })
}

/// A file the header pins ([`READ`]): whatever it is, [`read_text`] opens it
/// as a regular file and uses its bytes only if their hash is `pinned`. Its
/// size is taken at the open (a missing file reads as empty here, so that
/// the budget checks before the read tell nothing of it either).
fn pinned_file(named: &str, pinned: String) -> DataFile {
    let real = PathBuf::from(named);
    let size = std::fs::metadata(&real)
        .ok()
        .filter(|m| m.is_file())
        .map_or(0, |m| m.len());
    DataFile {
        shown: named.to_string(),
        real,
        size,
        pinned: Some(pinned),
    }
}

/// Reads `file` whole as UTF-8 text: opened non-blocking, checked again to
/// be a regular file on the open handle, at most its size plus one byte
/// read; the bytes' hash is noted in `ck` (for `resolved.yaml`'s header)
/// and, for a pinned file, must equal the pin. The error is the whole
/// message.
pub(crate) fn read_text(file: &DataFile, ck: &Checker<'_>) -> Result<String, String> {
    let shown = &file.shown;
    let mut bytes = Vec::new();
    let read = crate::guarded_file::open_regular(&file.real).and_then(|f| {
        f.take(file.size.saturating_add(1))
            .read_to_end(&mut bytes)
            .map(|_| ())
    });
    let hash = read.is_ok().then(|| sha256_hex(&bytes));
    if let Some(pinned) = &file.pinned
        && hash.as_ref() != Some(pinned)
    {
        // Missing, unreadable or changed: one message, no content.
        return Err(format!(
            "{shown} is not the file this scene's run read: it is missing or its bytes do not \
             have the SHA-256 its `# Read:` header line pins; rerun the original scene, or put \
             the file back as it was"
        ));
    }
    if let Err(e) = read {
        return Err(format!("cannot read {shown}: {}", io_reason(&e)));
    }
    if let Some(hash) = hash {
        ck.note_read(shown, hash);
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "{shown} is not UTF-8 text (byte {} is not); is it the right file?",
            e.utf8_error().valid_up_to() + 1
        )
    })
}

/// `path` with `.` and `..` removed by their names alone (no symlink is
/// followed: used only for a path that does not exist).
fn lexical(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// An I/O error's reason without the OS error number.
fn io_reason(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error") {
        Some(i) => text[..i].to_string(),
        None => text,
    }
}
