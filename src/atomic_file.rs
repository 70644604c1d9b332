//! The one way files reach the disk: whole or not at all. Below every layer
//! that writes (the modes cache, the spilled history rows, the report).
//!
//! Every output file (summary, CSV, resolved scenario, plots, study tables,
//! mode shapes) goes through [`write_atomic`]: the bytes go to a new
//! temporary file beside the target (a name no other writer in this or any
//! other process uses: `NAME.vbi-partial-PID-N`, created exclusively, and
//! visible, so that a run killed mid-write leaves nothing hidden and the next
//! run into the folder removes it, [`remove_stale_partials`]), are flushed
//! to the disk (`sync_all`, so that after a crash the renamed file is never
//! empty or short), and the file is renamed onto the target, which readers
//! then see either old or new, never partial. On any failure the temporary
//! file is removed and the target is left as it was.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

/// What marks a file being written: `summary.json.vbi-partial-1234` until
/// it is complete and renamed. Visible (no leading dot) and recognisable,
/// so a run killed from outside leaves nothing hidden, and the next run into
/// the same folder removes it ([`remove_stale_partials`]).
pub const PARTIAL_MARK: &str = ".vbi-partial-";

/// The temporary name of `file_name` while this process writes it; `tag`
/// tells apart several temporaries of one process.
pub fn partial_name(file_name: &str, tag: &str) -> String {
    format!("{file_name}{PARTIAL_MARK}{}{tag}", std::process::id())
}

/// Removes the partial files in `folder` that a process no longer running
/// left behind (killed mid-write). A process that is still running (its
/// `/proc` entry exists) keeps its files; where there is no `/proc`, only
/// files older than an hour are removed. Best effort: errors are ignored.
pub fn remove_stale_partials(folder: &Path) {
    let Ok(entries) = fs::read_dir(folder) else {
        return;
    };
    let me = std::process::id();
    let proc_fs = Path::new("/proc/self").exists();
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some((_, after)) = name.rsplit_once(PARTIAL_MARK) else {
            continue;
        };
        let digits: String = after.chars().take_while(char::is_ascii_digit).collect();
        let Ok(pid) = digits.parse::<u32>() else {
            continue;
        };
        let stale = if proc_fs {
            pid != me && !Path::new("/proc").join(pid.to_string()).exists()
        } else {
            entry
                .metadata()
                .and_then(|m| m.modified())
                .ok()
                .and_then(|t| t.elapsed().ok())
                .is_some_and(|age| age.as_secs() > 3600)
        };
        if stale && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Writes `bytes` to `path` atomically (see the module doc).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let file_name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("'{}' names no file", path.display()),
        )
    })?;
    let tmp_name = partial_name(
        &file_name.to_string_lossy(),
        &format!("-{}", COUNTER.fetch_add(1, Ordering::Relaxed)),
    );
    let tmp = path.with_file_name(tmp_name);
    let mut file = File::create_new(&tmp)?;
    let written = file
        .write_all(bytes)
        .and_then(|()| file.sync_all())
        .and_then(|()| {
            drop(file);
            fs::rename(&tmp, path)
        });
    if written.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    written
}

/// Writes what `write` produces to `path` atomically, streamed through a
/// buffer into the temporary file (nothing is assembled in memory); the
/// same guarantees as [`write_atomic`].
pub fn write_atomic_with(
    path: &Path,
    write: &dyn Fn(&mut dyn Write) -> io::Result<()>,
) -> io::Result<()> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let file_name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("'{}' names no file", path.display()),
        )
    })?;
    let tmp_name = partial_name(
        &file_name.to_string_lossy(),
        &format!("-s{}", COUNTER.fetch_add(1, Ordering::Relaxed)),
    );
    let tmp = path.with_file_name(tmp_name);
    let file = File::create_new(&tmp)?;
    let mut buffered = io::BufWriter::with_capacity(1 << 16, file);
    let written = write(&mut buffered)
        .and_then(|()| {
            buffered
                .into_inner()
                .map_err(io::IntoInnerError::into_error)
        })
        .and_then(|file| file.sync_all())
        .and_then(|()| fs::rename(&tmp, path));
    if written.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("vbi-atomic-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn writes_whole_and_replaces_without_leftovers() {
        let dir = scratch("replace");
        let path = dir.join("a.csv");
        fs::write(&path, b"old").unwrap();
        write_atomic(&path, b"new contents").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new contents");
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_failed_rename_leaves_the_target_and_no_temporary() {
        let dir = scratch("fail");
        let target = dir.join("taken");
        fs::create_dir(&target).unwrap();
        fs::write(target.join("keep"), b"x").unwrap();
        assert!(write_atomic(&target, b"y").is_err());
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
        assert!(target.join("keep").exists());
        assert!(write_atomic(Path::new("/"), b"y").is_err());
        fs::remove_dir_all(&dir).unwrap();
    }
}
