//! The time history on disk: `history.csv` (a header with units, one row per
//! written step) and `history.npy` (NPY 1.0: one little-endian float64
//! array in C order, a row per written step, with `history_columns.txt`
//! naming its columns). Both are streamed through a buffer into the
//! atomic writer's temporary file, never assembled in memory.
//!
//! Time stamps are clean: the time of step k is k·Δt rounded to the
//! decimals that Δt itself needs (Δt = 1e-4 s → 4 decimals), so 3000 steps
//! of 1e-4 s print as `0.3`, not `0.30000000000000004`; a Δt with no short
//! decimal form (an automatic step such as 7.457…e-5 s) keeps k·Δt as
//! computed, printed in its shortest round-trip form.

use std::io::{self, Write};
use std::path::Path;

use crate::record::History;

use super::ReportError;

/// Column names with their units: `time [s]`, then each record as
/// `name [unit]`, and `name_static [m]` after each bridge displacement.
pub fn column_labels(history: &History) -> Vec<String> {
    let mut out = vec!["time [s]".to_string()];
    for c in &history.columns {
        out.push(format!("{} [{}]", c.name, c.unit));
        if c.static_values.is_some() {
            out.push(format!("{}_static [{}]", c.name, c.unit));
        }
    }
    out
}

/// The decimals Δt needs (the fewest, up to 12, that give it back to
/// 1e-9 relative), or `None` if it has no such short form.
pub fn time_decimals(time_step: f64) -> Option<i32> {
    (0..=12).find(|&d| {
        let scale = 10f64.powi(d);
        let rounded = (time_step * scale).round() / scale;
        rounded > 0.0 && ((rounded - time_step) / time_step).abs() <= 1e-9
    })
}

/// Rounds `t` (s) to `decimals` (see the module doc); unchanged where the
/// scaled value would leave the exactly representable integers.
#[inline]
pub fn clean_time(t: f64, decimals: Option<i32>) -> f64 {
    match decimals {
        Some(d) => {
            let scale = 10f64.powi(d);
            let scaled = t * scale;
            if scaled.abs() < 9.0e15 {
                scaled.round() / scale
            } else {
                t
            }
        }
        None => t,
    }
}

/// Number of rows and of columns of the history table.
fn shape(history: &History) -> (usize, usize) {
    let columns = history.row_width();
    let rows = history
        .spilled
        .as_ref()
        .map_or(history.time.len(), |s| s.rows);
    (rows, columns)
}

/// Calls `visit` with every row of the table in order (time first, then
/// each column's value and static value): from memory, or read back from
/// the file a streamed run wrote ([`crate::record::spill`]).
pub fn each_row(history: &History, mut visit: impl FnMut(&[f64])) -> io::Result<()> {
    if let Some(spilled) = &history.spilled {
        return spilled.for_each_row(visit);
    }
    let (_, columns) = shape(history);
    let mut row = Vec::with_capacity(columns);
    for (i, &t) in history.time.iter().enumerate() {
        row.clear();
        row.push(t);
        for c in &history.columns {
            row.push(c.values[i]);
            if let Some(s) = &c.static_values {
                row.push(s[i]);
            }
        }
        visit(&row);
    }
    Ok(())
}

/// Writes the CSV text of `history` to `out` (Δt `time_step`, s). Values in
/// SI units, shortest round-trip formatting (ryu), `0` for ±0.
pub fn write_csv(out: &mut dyn Write, history: &History, time_step: f64) -> io::Result<()> {
    let labels = column_labels(history);
    // Names come from the scenario: quote a label that holds a comma or a
    // quote (RFC 4180), so the header keeps one field per column.
    let header: Vec<String> = labels
        .iter()
        .map(|l| {
            if l.contains([',', '"', '\n', '\r']) {
                format!("\"{}\"", l.replace('"', "\"\""))
            } else {
                l.clone()
            }
        })
        .collect();
    out.write_all(header.join(",").as_bytes())?;
    out.write_all(b"\n")?;
    let decimals = time_decimals(time_step);
    let mut buffer = ryu::Buffer::new();
    let mut line = Vec::with_capacity(256);
    let mut written = Ok(());
    each_row(history, |row| {
        if written.is_err() {
            return;
        }
        line.clear();
        for (k, &value) in row.iter().enumerate() {
            let x = if k == 0 {
                clean_time(value, decimals)
            } else {
                value
            };
            if k > 0 {
                line.push(b',');
            }
            if x == 0.0 {
                line.push(b'0');
            } else {
                line.extend_from_slice(buffer.format(x).as_bytes());
            }
        }
        line.push(b'\n');
        written = out.write_all(&line);
    })?;
    written
}

/// The NPY 1.0 header of a C-order little-endian float64 array of
/// `rows × columns`: magic `\x93NUMPY`, version 1.0, the header length
/// (u16 LE) and the dict text padded with spaces to end in `\n` on a
/// 64-byte boundary (NumPy's format specification, numpy.lib.format).
pub fn npy_header(rows: usize, columns: usize) -> Vec<u8> {
    let dict =
        format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({rows}, {columns}), }}");
    let unpadded = 10 + dict.len() + 1;
    let padding = (64 - unpadded % 64) % 64;
    let length = dict.len() + padding + 1;
    let mut out = Vec::with_capacity(10 + length);
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(length as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out.extend(std::iter::repeat_n(b' ', padding));
    out.push(b'\n');
    out
}

/// Writes `history` as an NPY array to `out` (same values and time stamps
/// as the CSV).
pub fn write_npy(out: &mut dyn Write, history: &History, time_step: f64) -> io::Result<()> {
    let (rows, columns) = shape(history);
    out.write_all(&npy_header(rows, columns))?;
    let decimals = time_decimals(time_step);
    let mut line = Vec::with_capacity(8 * columns);
    let mut written = Ok(());
    each_row(history, |row| {
        if written.is_err() {
            return;
        }
        line.clear();
        line.extend_from_slice(&clean_time(row[0], decimals).to_le_bytes());
        for x in &row[1..] {
            line.extend_from_slice(&x.to_le_bytes());
        }
        written = out.write_all(&line);
    })?;
    written
}

/// Writes the history files `format` asks for into the folder `out`:
/// history.csv, and/or history.npy with history_columns.txt; each atomic
/// and streamed.
pub fn write_history(
    out: &Path,
    history: &History,
    time_step: f64,
    format: crate::scene::HistoryFormat,
) -> Result<(), ReportError> {
    let streamed = |name: &str, write: &dyn Fn(&mut dyn Write) -> io::Result<()>| {
        let path = out.join(name);
        super::atomic::write_atomic_with(&path, write).map_err(|source| ReportError::Io {
            path: path.clone(),
            source,
        })
    };
    if format.csv() {
        streamed("history.csv", &|w| write_csv(w, history, time_step))?;
    }
    if format.npy() {
        let names = column_labels(history).join("\n") + "\n";
        super::write_atomic(&out.join("history_columns.txt"), names.as_bytes())?;
        streamed("history.npy", &|w| write_npy(w, history, time_step))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_is_aligned_and_parsable() {
        for (rows, columns) in [(0, 1), (3, 7), (1_000_001, 12)] {
            let h = npy_header(rows, columns);
            assert_eq!(h.len() % 64, 0);
            assert_eq!(&h[..8], b"\x93NUMPY\x01\x00");
            let length = u16::from_le_bytes([h[8], h[9]]) as usize;
            assert_eq!(10 + length, h.len());
            assert_eq!(*h.last().unwrap(), b'\n');
            let text = std::str::from_utf8(&h[10..]).unwrap();
            assert!(
                text.contains(&format!("'shape': ({rows}, {columns})")),
                "{text}"
            );
        }
    }

    #[test]
    fn time_stamps_are_clean() {
        let d = time_decimals(1e-4);
        assert_eq!(d, Some(4));
        assert_eq!(clean_time(3000.0 * 1e-4, d), 0.3);
        assert_eq!(
            ryu::Buffer::new().format(clean_time(3000.0 * 1e-4, d)),
            "0.3"
        );
        assert_eq!(time_decimals(2.5e-5), Some(6));
        assert_eq!(time_decimals(0.5), Some(1));
        assert_eq!(time_decimals(7.457_123_456_789_1e-5), None);
        // Where the decimals would reach beyond f64's integers, t stays.
        assert_eq!(clean_time(1e10, Some(12)), 1e10);
        // Every k·Δt of a long run rounds to the nearest decimal.
        for k in 0..100_000u32 {
            let t = clean_time(f64::from(k) * 1e-4, d);
            let text = ryu::Buffer::new().format(t).to_string();
            assert!(text.len() <= 8, "{k}: {text}");
            assert_eq!(
                t,
                format!("{:.4}", f64::from(k) / 1e4).parse::<f64>().unwrap()
            );
        }
    }
}
