//! The one way results reach the disk: whole or not at all.
//!
//! Every output file (summary, CSV, resolved scenario, plots, study tables,
//! mode shapes) goes through [`write_atomic`]: the bytes go to a new
//! temporary file beside the target (a name no other writer in this or any
//! other process uses: `NAME.vbi-partial-PID-N`, created exclusively, and
//! visible, so that a run killed mid-write leaves nothing hidden and the next
//! run into the folder removes it, [`super::remove_stale_partials`]), are flushed
//! to the disk (`sync_all`, so that after a crash the renamed file is never
//! empty or short), and the file is renamed onto the target, which readers
//! then see either old or new, never partial. On any failure the temporary
//! file is removed and the target is left as it was.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

/// Writes `bytes` to `path` atomically (see the module doc).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let file_name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("'{}' names no file", path.display()),
        )
    })?;
    let tmp_name = super::partial_name(
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
    let tmp_name = super::partial_name(
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
