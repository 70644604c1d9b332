//! Histories streamed to disk while the run goes: each written sample row
//! (time, then every column's value and static value, as the history's
//! table) is appended to a file of little-endian f64 in the output folder
//! instead of growing vectors, so a run's memory does not grow with its
//! step count. The file carries the partial-file mark
//! ([`crate::atomic_file::PARTIAL_MARK`]): it is removed when the last
//! [`SpilledRows`] handle goes (after the history files are written from
//! it), and a run killed from outside leaves it visible for the next run
//! into the folder to remove. Cost per row: one buffered write of
//! 8 × width bytes.

use std::fs::File;
use std::io::{self, BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

/// The rows of a run being written. Dropped unfinished (a run that
/// failed), it removes its file.
#[derive(Debug)]
pub struct SpillWriter {
    /// Owns the file (removes it on drop) until [`SpillWriter::finish`].
    rows_handle: Option<SpilledRows>,
    file: BufWriter<File>,
    rows: usize,
    width: usize,
    bytes: Vec<u8>,
    /// The first write error, reported at [`SpillWriter::finish`].
    error: Option<io::Error>,
}

impl SpillWriter {
    /// A new spill file in `folder` for rows of `width` values.
    pub fn create(folder: &Path, width: usize) -> io::Result<Self> {
        let path = folder.join(crate::atomic_file::partial_name("history.rows", "-spill"));
        let file = File::create_new(&path)?;
        Ok(Self {
            rows_handle: Some(SpilledRows {
                path,
                rows: 0,
                width,
            }),
            file: BufWriter::with_capacity(1 << 16, file),
            rows: 0,
            width,
            bytes: Vec::with_capacity(8 * width),
            error: None,
        })
    }

    /// Appends one row (`width` values).
    pub fn push(&mut self, row: impl Iterator<Item = f64>) {
        self.bytes.clear();
        for x in row {
            self.bytes.extend_from_slice(&x.to_le_bytes());
        }
        debug_assert_eq!(self.bytes.len(), 8 * self.width);
        if self.error.is_none()
            && let Err(e) = self.file.write_all(&self.bytes)
        {
            self.error = Some(e);
        }
        self.rows += 1;
    }

    /// Flushes the file; the rows, or the first write error (the file then
    /// removed).
    pub fn finish(mut self) -> io::Result<SpilledRows> {
        let flushed = match self.error.take() {
            Some(e) => Err(e),
            None => self.file.flush(),
        };
        let mut rows = self.rows_handle.take().expect("finished once");
        rows.rows = self.rows;
        flushed.map(|()| rows)
    }
}

/// A finished spill file: `rows` rows of `width` values. Removed on drop.
#[derive(Debug)]
pub struct SpilledRows {
    path: PathBuf,
    /// Number of rows.
    pub rows: usize,
    /// Values per row.
    pub width: usize,
}

impl SpilledRows {
    /// Calls `visit` with every row in order. Reads through a buffer: memory
    /// O(width).
    pub fn for_each_row(&self, mut visit: impl FnMut(&[f64])) -> io::Result<()> {
        let mut reader = BufReader::with_capacity(1 << 16, File::open(&self.path)?);
        let mut bytes = vec![0u8; 8 * self.width];
        let mut row = vec![0.0; self.width];
        for _ in 0..self.rows {
            reader.read_exact(&mut bytes)?;
            for (x, chunk) in row.iter_mut().zip(bytes.chunks_exact(8)) {
                *x = f64::from_le_bytes(chunk.try_into().expect("8 bytes"));
            }
            visit(&row);
        }
        Ok(())
    }
}

impl Drop for SpilledRows {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}
