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
    })
}

/// Reads `file` whole as UTF-8 text: opened non-blocking, checked again to
/// be a regular file on the open handle, at most its size plus one byte
/// read. The error is the whole message.
pub(crate) fn read_text(file: &DataFile) -> Result<String, String> {
    let shown = &file.shown;
    let mut bytes = Vec::new();
    let read = open_regular(&file.real).and_then(|f| {
        f.take(file.size.saturating_add(1))
            .read_to_end(&mut bytes)
            .map(|_| ())
    });
    if let Err(e) = read {
        return Err(format!("cannot read {shown}: {}", io_reason(&e)));
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "{shown} is not UTF-8 text (byte {} is not); is it the right file?",
            e.utf8_error().valid_up_to() + 1
        )
    })
}

/// Opens `path` for reading without blocking (a FIFO put in a regular
/// file's place would otherwise wait for a writer) and refuses anything
/// but a regular file by the open handle's own metadata.
pub fn open_regular(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    if !file.metadata()?.is_file() {
        return Err(std::io::Error::other(
            "not a regular file (a folder, a device or a pipe)",
        ));
    }
    Ok(file)
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
