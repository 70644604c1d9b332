//! The report stage: summary.json, the CSV time history and the resolved
//! scenario, each written whole or not at all.

pub mod advice;
pub use crate::atomic_file as atomic;
pub mod embs;
pub mod envelopes;
pub mod folder;
pub mod history_files;
pub mod history_plot;
pub mod plot;
pub mod summary;
pub mod yaml;

use std::io;
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::record::History;

/// Errors writing results.
#[derive(Debug, Error)]
pub enum ReportError {
    /// A file could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: io::Error,
    },
}

pub use crate::atomic_file::{PARTIAL_MARK, partial_name, remove_stale_partials};

/// Writes `contents` to `path` whole or not at all ([`atomic::write_atomic`]).
pub fn write_atomic(path: &Path, contents: &[u8]) -> Result<(), ReportError> {
    atomic::write_atomic(path, contents).map_err(|source| ReportError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// The time history as CSV text (see [`history_files::write_csv`]), Δt
/// `time_step` s.
pub fn history_csv(history: &History, time_step: f64) -> Vec<u8> {
    let mut out = Vec::new();
    history_files::write_csv(&mut out, history, time_step).expect("writing to memory");
    out
}

/// A CSV column heading in the one style of every file vbi writes
/// (issue 26.5): `name [unit]` with the SI unit in brackets (`speed [m/s]`,
/// `bridge_moment_max [N*m]`), or the bare name for a dimensionless column
/// (`unit` empty: `probability`, `daf`).
pub fn heading(name: &str, unit: &str) -> String {
    if unit.is_empty() {
        name.to_string()
    } else {
        format!("{name} [{unit}]")
    }
}

/// A speed in m/s as km/h for output, with the float noise of the
/// conversion rounded away (12 significant digits): a speed given as
/// `359 km/h` is written `359`, not `359.00000000000006` (issue 26.5).
pub use crate::scenario::resonance_grid::km_h;

/// `x` rounded to 12 significant digits, for output: the float noise of
/// k·Δt or of a unit conversion removed (`0.018000000000000002` → `0.018`).
pub use crate::scenario::resonance_grid::clean;

/// Shortest round-trip text of `x`: plain notation for moderate magnitudes,
/// exponent notation for very small or large ones, and `0` for ±0.
pub fn number(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if (1e-4..1e15).contains(&x.abs()) {
        x.to_string()
    } else {
        format!("{x:e}")
    }
}

/// Mode shapes sampled at the mesh nodes and mid-element points as CSV:
/// `x [m]` then `mode1 [1/kg^0.5]`, `mode2 [1/kg^0.5]`, … (mass-normalised,
/// 1/√kg). On a plate deck the columns are `x [m]`, `y [m]`, modes…,
/// sampled along both edges and the centre line.
pub fn mode_shapes_csv(bridge: &crate::bridge::ModalBridge) -> String {
    let modes = bridge.mode_count();
    let lines = match bridge.width() {
        None => vec![None],
        Some(b) => vec![Some(0.0), Some(0.5 * b), Some(b)],
    };
    let mut out = String::from(if lines[0].is_some() {
        "x [m],y [m]"
    } else {
        "x [m]"
    });
    for i in 1..=modes {
        out.push_str(&format!(",mode{i} [1/kg^0.5]"));
    }
    out.push('\n');
    let nodes = bridge.node_x();
    let mut values = vec![0.0; modes];
    let mut points = Vec::with_capacity(2 * nodes.len());
    for (i, &x) in nodes.iter().enumerate() {
        if i > 0 {
            points.push(0.5 * (nodes[i - 1] + x));
        }
        points.push(x);
    }
    for line in lines {
        for &x in &points {
            bridge.mode_values(x, line.unwrap_or(0.0), &mut values);
            out.push_str(&number(x));
            if let Some(y) = line {
                out.push(',');
                out.push_str(&number(y));
            }
            for v in &values {
                out.push(',');
                out.push_str(&number(*v));
            }
            out.push('\n');
        }
    }
    out
}

/// The DAF table of a plate deck as CSV: one row per span and girder line,
/// `span,girder,x [m],y [m],dynamic_max_abs [m],static_max_abs [m],daf`.
pub fn girder_daf_csv(rows: &[crate::record::GirderDaf]) -> String {
    let mut out =
        String::from("span,girder,x [m],y [m],dynamic_max_abs [m],static_max_abs [m],daf\n");
    for r in rows {
        out.push_str(&format!(
            "{},{},{},{},{},{},{}\n",
            r.span,
            r.girder,
            number(r.x),
            number(r.y),
            number(r.dynamic_max_abs),
            number(r.static_max_abs),
            number(r.daf)
        ));
    }
    out
}
