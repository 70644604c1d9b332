//! The guarded file layer (issue 39.1): how vbi opens, reads and creates
//! files and folders that someone else may have prepared — a scene's data
//! files, a modes cache, shard parts, a regression store, `vbi init`'s
//! targets. Below every layer that touches the disk, beside
//! [`crate::atomic_file`] (which every write then goes through).
//!
//! The rules, each a failure mode seen on a hostile corpus:
//! - only regular files are read: a FIFO would block the reader forever, a
//!   device (`/dev/zero`) never ends, a folder is not text. The file is
//!   opened non-blocking and judged by the open handle's own metadata, so a
//!   file swapped between a check and the open is still caught;
//! - the size is checked against a budget before a byte is read, and at
//!   most the budget plus one byte is read (a file that grows while read is
//!   caught too): a 3 GB sparse file is refused, not loaded;
//! - inside a folder that owns its entries (a regression store), no entry
//!   may be a symbolic link: a link can point anywhere, and writing through
//!   it or quoting what it points to would leak or clobber a file outside;
//! - a name that becomes a path component (a store key from a scene's file
//!   stem) is a plain name: never empty, `.` or `..`, no separator, no
//!   control character;
//! - a file is created only where none exists unless the caller was told
//!   to replace it ([`create_new`]).

use std::fs::{File, OpenOptions};
use std::io::{self, Read, Write};
use std::path::{Component, Path};

/// Why a guarded read or write was refused. Its text names the path (as
/// given, escaped) and the reason, never the file's content.
#[derive(Debug, thiserror::Error)]
pub enum GuardError {
    /// Not a regular file: a folder, a FIFO, a socket or a device.
    #[error("{path} is not a regular file (a folder, a device or a pipe)")]
    NotRegular {
        /// The path, escaped.
        path: String,
    },
    /// Larger than the reader's budget.
    #[error("{path} has {size} bytes, more than the {limit} this file may have")]
    TooLarge {
        /// The path, escaped.
        path: String,
        /// Its size, bytes.
        size: u64,
        /// The budget, bytes.
        limit: u64,
    },
    /// A symbolic link where the folder's own entries must be.
    #[error(
        "{path} is a symbolic link; vbi reads and writes only the folder's own files and \
         folders here, never through a link"
    )]
    Symlink {
        /// The path, escaped.
        path: String,
    },
    /// Exists already, and the caller may not replace it.
    #[error("{path} exists already")]
    Exists {
        /// The path, escaped.
        path: String,
    },
    /// Not UTF-8 text.
    #[error("{path} is not UTF-8 text")]
    NotText {
        /// The path, escaped.
        path: String,
    },
    /// Any other I/O failure.
    #[error("{path}: {reason}")]
    Io {
        /// The path, escaped.
        path: String,
        /// The reason, without the OS error number.
        reason: String,
        /// The kind of the I/O error.
        kind: io::ErrorKind,
    },
}

impl GuardError {
    /// Whether the file does not exist (a reader may then take a default).
    pub fn is_not_found(&self) -> bool {
        matches!(self, GuardError::Io { kind, .. } if *kind == io::ErrorKind::NotFound)
    }
}

/// `path` as shown in a message: its control characters escaped (a file
/// name can hold ESC or NUL), as rustc shows them.
pub fn shown(path: &Path) -> String {
    escape_controls(&path.display().to_string())
}

/// `text` with every control character (C0 but `\n` and `\t`, DEL, C1) and the
/// non-characters U+FFFE/U+FFFF escaped as Rust writes them (`\u{1b}`,
/// `\0`, `\r`), and the bidirectional overrides (U+202A–U+202E,
/// U+2066–U+2069): text from a file or a key can then neither repaint or
/// reorder the reader's terminal nor break an XML document.
pub fn escape_controls(text: &str) -> String {
    // The bidirectional overrides and isolates too: they reorder what the
    // terminal shows after them ("Trojan Source").
    let dangerous = |c: char| {
        (c.is_control() && !matches!(c, '\n' | '\t'))
            || matches!(c, '\u{fffe}' | '\u{ffff}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
    };
    if !text.chars().any(dangerous) {
        return text.to_owned();
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if dangerous(c) {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

/// At most `max` characters of `text` (an ellipsis marks a cut), escaped
/// as [`escape_controls`] does and with line breaks as `\n`: a key or a
/// field quoted from a file that may be someone else's.
pub fn excerpt(text: &str, max: usize) -> String {
    let short: String = text.chars().take(max).collect();
    let more = if short.len() < text.len() { "…" } else { "" };
    format!("{}{more}", escape_controls(&short).replace('\n', "\\n"))
}

fn io_error(path: &Path, e: &io::Error) -> GuardError {
    let text = e.to_string();
    let reason = match text.find(" (os error") {
        Some(i) => text[..i].to_string(),
        None => text,
    };
    GuardError::Io {
        path: shown(path),
        reason,
        kind: e.kind(),
    }
}

/// Opens `path` for reading without blocking (a FIFO put in a regular
/// file's place would otherwise wait for a writer) and refuses anything
/// but a regular file by the open handle's own metadata. Follows a
/// symbolic link (callers that own a folder check [`no_link`] first).
pub fn open_regular(path: &Path) -> io::Result<File> {
    let mut options = OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    if !file.metadata()?.is_file() {
        return Err(io::Error::other(
            "not a regular file (a folder, a device or a pipe)",
        ));
    }
    Ok(file)
}

/// The bytes of the regular file `path`, of at most `limit` bytes: the
/// size is checked on the open handle before reading, and at most
/// `limit + 1` bytes are read.
///
/// # Errors
/// [`GuardError::NotRegular`], [`GuardError::TooLarge`] or
/// [`GuardError::Io`] (not found among them: [`GuardError::is_not_found`]).
pub fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, GuardError> {
    let file = open_regular(path).map_err(|e| match e.kind() {
        io::ErrorKind::Other => GuardError::NotRegular { path: shown(path) },
        _ => io_error(path, &e),
    })?;
    let size = file.metadata().map_err(|e| io_error(path, &e))?.len();
    if size > limit {
        return Err(GuardError::TooLarge {
            path: shown(path),
            size,
            limit,
        });
    }
    let mut bytes = Vec::with_capacity(size as usize);
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| io_error(path, &e))?;
    if bytes.len() as u64 > limit {
        return Err(GuardError::TooLarge {
            path: shown(path),
            size: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}

/// [`read_bounded`] as UTF-8 text.
///
/// # Errors
/// As [`read_bounded`], and [`GuardError::NotText`].
pub fn read_text_bounded(path: &Path, limit: u64) -> Result<String, GuardError> {
    String::from_utf8(read_bounded(path, limit)?)
        .map_err(|_| GuardError::NotText { path: shown(path) })
}

/// `Ok` if `path` is not a symbolic link (it may not exist).
///
/// # Errors
/// [`GuardError::Symlink`] for a link; [`GuardError::Io`] when its
/// metadata cannot be read for another reason than its absence.
pub fn no_link(path: &Path) -> Result<(), GuardError> {
    match std::fs::symlink_metadata(path) {
        Ok(meta) if meta.file_type().is_symlink() => Err(GuardError::Symlink { path: shown(path) }),
        Ok(_) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(io_error(path, &e)),
    }
}

/// The regular file `name` of the folder `folder`, read as text of at most
/// `limit` bytes, where the folder owns its entries: neither the file nor
/// the folder may be a symbolic link.
///
/// # Errors
/// As [`read_text_bounded`], and [`GuardError::Symlink`].
pub fn read_own_text(folder: &Path, name: &str, limit: u64) -> Result<String, GuardError> {
    let path = folder.join(name);
    no_link(folder)?;
    no_link(&path)?;
    read_text_bounded(&path, limit)
}

/// Why `name` cannot be a path component of its own (`None`: it can): it is
/// empty, `.` or `..`, holds a separator (`/`, `\`), a `:` (a Windows
/// drive or stream) or a control character, or is longer than 200 bytes.
pub fn plain_name_fault(name: &str) -> Option<&'static str> {
    if name.is_empty() {
        return Some("it is empty");
    }
    if name == "." || name == ".." || name.chars().all(|c| c == '.') {
        return Some("it is made of dots only, which names a folder, not an entry");
    }
    if name.contains(['/', '\\', ':']) {
        return Some("it holds a path separator");
    }
    if name.chars().any(|c| c.is_control()) {
        return Some("it holds a control character");
    }
    if name.len() > 200 {
        return Some("it is longer than 200 bytes");
    }
    let mut components = Path::new(name).components();
    match (components.next(), components.next()) {
        (Some(Component::Normal(_)), None) => None,
        _ => Some("it is not a plain file name"),
    }
}

/// Makes the folder `name` inside `root` (which must exist), where `root`
/// owns its entries: an existing `root/name` must be a real folder, not a
/// link (to somewhere outside) nor a file. Returns its path.
///
/// # Errors
/// [`GuardError::Symlink`], [`GuardError::NotRegular`] (a file or device
/// in its place) or [`GuardError::Io`].
pub fn own_folder(root: &Path, name: &str) -> Result<std::path::PathBuf, GuardError> {
    no_link(root)?;
    let folder = root.join(name);
    no_link(&folder)?;
    match std::fs::create_dir(&folder) {
        Ok(()) => Ok(folder),
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
            match std::fs::symlink_metadata(&folder) {
                Ok(meta) if meta.is_dir() => Ok(folder),
                Ok(meta) if meta.file_type().is_symlink() => Err(GuardError::Symlink {
                    path: shown(&folder),
                }),
                Ok(_) => Err(GuardError::NotRegular {
                    path: shown(&folder),
                }),
                Err(e) => Err(io_error(&folder, &e)),
            }
        }
        Err(e) => Err(io_error(&folder, &e)),
    }
}

/// Writes `bytes` to a new file `path`, which must not exist (created
/// exclusively: no symlink is followed, no file replaced, even one made
/// between a check and the write). On a failure after creating it the
/// partial file is removed.
///
/// # Errors
/// [`GuardError::Exists`] when anything (a file, a folder, a link) is
/// there; [`GuardError::Io`] otherwise.
pub fn create_new(path: &Path, bytes: &[u8]) -> Result<(), GuardError> {
    let mut file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(|e| match e.kind() {
            io::ErrorKind::AlreadyExists => GuardError::Exists { path: shown(path) },
            _ => io_error(path, &e),
        })?;
    let written = file.write_all(bytes).and_then(|()| file.sync_all());
    if let Err(e) = written {
        drop(file);
        let _ = std::fs::remove_file(path);
        return Err(io_error(path, &e));
    }
    Ok(())
}

/// Whether a file may be written at `path` with `force` (replace what is
/// there): nothing there, or a regular file (not a link, a folder or a
/// device) and `force`.
///
/// # Errors
/// [`GuardError::Exists`] without `force`; [`GuardError::Symlink`] or
/// [`GuardError::NotRegular`] for what is never replaced.
pub fn writable(path: &Path, force: bool) -> Result<(), GuardError> {
    match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(io_error(path, &e)),
        Ok(meta) if meta.file_type().is_symlink() => Err(GuardError::Symlink { path: shown(path) }),
        Ok(meta) if !meta.is_file() => Err(GuardError::NotRegular { path: shown(path) }),
        Ok(_) if force => Ok(()),
        Ok(_) => Err(GuardError::Exists { path: shown(path) }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_names() {
        assert_eq!(plain_name_fault("bridge"), None);
        assert_eq!(plain_name_fault("my.scene"), None);
        for bad in ["", ".", "..", "...", "a/b", "a\\b", "c:x", "a\u{1b}b"] {
            assert!(plain_name_fault(bad).is_some(), "{bad:?}");
        }
    }

    #[test]
    fn controls_are_escaped_newlines_kept() {
        assert_eq!(escape_controls("m\u{1b}[31m"), "m\\u{1b}[31m");
        assert_eq!(escape_controls("a\0b"), "a\\0b");
        assert_eq!(escape_controls("a\u{ffff}"), "a\\u{ffff}");
        assert_eq!(escape_controls("two\nlines"), "two\nlines");
        assert_eq!(escape_controls("tab\there"), "tab\there");
        assert_eq!(escape_controls("cr\rhere"), "cr\\rhere");
        assert_eq!(escape_controls("a\u{202e}b"), "a\\u{202e}b");
    }

    /// A scratch folder removed when dropped.
    struct Dir(std::path::PathBuf);
    impl Dir {
        fn path(&self) -> &Path {
            &self.0
        }
    }
    impl Drop for Dir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    #[cfg(unix)]
    #[test]
    fn devices_fifos_and_links_are_refused() {
        let dir = std::env::temp_dir().join(format!("vbi-guarded-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let dir = Dir(dir);
        assert!(matches!(
            read_bounded(Path::new("/dev/zero"), 100),
            Err(GuardError::NotRegular { .. })
        ));
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            assert!(matches!(
                read_bounded(&fifo, 100),
                Err(GuardError::NotRegular { .. })
            ));
        }
        let big = dir.path().join("big");
        std::fs::write(&big, vec![b'x'; 101]).unwrap();
        assert!(matches!(
            read_bounded(&big, 100),
            Err(GuardError::TooLarge { size: 101, .. })
        ));
        std::os::unix::fs::symlink(&big, dir.path().join("link")).unwrap();
        assert!(matches!(
            read_own_text(dir.path(), "link", 1000),
            Err(GuardError::Symlink { .. })
        ));
        assert!(matches!(
            create_new(&dir.path().join("link"), b"x"),
            Err(GuardError::Exists { .. })
        ));
        assert_eq!(std::fs::read(&big).unwrap().len(), 101);
        std::os::unix::fs::symlink(dir.path(), dir.path().join("out")).unwrap();
        assert!(matches!(
            own_folder(dir.path(), "out"),
            Err(GuardError::Symlink { .. })
        ));
    }
}
