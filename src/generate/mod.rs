//! Generated finite-element bridge models, written in the exchange format
//! the `fe_import` bridge reads (`vbi generate viaduct`):
//! - `K.mtx`, `M.mtx`: Matrix Market `coordinate real symmetric`, 1-based,
//!   lower triangle, N/m (N·m/rad) and kg (kg·m²), every value in its
//!   shortest round-trip decimal form (the f64 is read back exactly);
//! - `dof_map.csv`: `dof,node,direction` (dof = matrix row from 1,
//!   direction in ux, uy, uz, rx, ry, rz; x along the track, z up);
//! - `rail_left.csv`, `rail_right.csv`: `node,x` along each rail;
//! - `README.txt`: the parameters, the sizes and the component masses.
//!
//! Constrained DOFs (the ground, the pier bases) are removed from the
//! matrices and absent from the map.

pub mod frame;
pub mod viaduct;

use std::fmt::Write as _;
use std::path::Path;

use crate::bridge::BridgeError;
use crate::bridge::eigen::Pencil;
use crate::bridge::eigen::sparse::symmetric_from_entries;
use viaduct::{Assembled, DIRECTIONS, ViaductParams};

/// A model with its constrained DOFs removed.
#[derive(Debug, Clone)]
pub struct Reduced {
    /// Order (free DOFs).
    pub order: usize,
    /// For each free DOF (row from 0): (node id from 1, direction 0..6).
    pub dof_map: Vec<(usize, usize)>,
    /// Stiffness, lower triangle, (row, column, value) sorted by column
    /// then row, duplicates summed; N/m, N·m/rad.
    pub stiffness: Vec<(usize, usize, f64)>,
    /// Mass likewise, kg, kg·m².
    pub mass: Vec<(usize, usize, f64)>,
}

/// Removes the fixed nodes' DOFs, renumbers, sorts and sums duplicates (in
/// insertion order, so the sums are deterministic).
pub fn reduce(model: &Assembled) -> Reduced {
    let mut free = vec![usize::MAX; 6 * model.nodes.len()];
    let mut dof_map = Vec::new();
    for (node, &fixed) in model.fixed.iter().enumerate() {
        if !fixed {
            for d in 0..6 {
                free[6 * node + d] = dof_map.len();
                dof_map.push((node + 1, d));
            }
        }
    }
    let compact = |entries: &[(usize, usize, f64)]| {
        let mut kept: Vec<(usize, usize, f64)> = entries
            .iter()
            .filter_map(|&(r, c, v)| {
                let (r, c) = (free[r], free[c]);
                (r != usize::MAX && c != usize::MAX).then(|| (r.max(c), r.min(c), v))
            })
            .collect();
        // Stable: equal keys keep their insertion order.
        kept.sort_by_key(|&(r, c, _)| (c, r));
        let mut out: Vec<(usize, usize, f64)> = Vec::with_capacity(kept.len());
        for (r, c, v) in kept {
            match out.last_mut() {
                Some(last) if last.0 == r && last.1 == c => last.2 += v,
                _ => out.push((r, c, v)),
            }
        }
        out.retain(|e| e.2 != 0.0);
        out
    };
    Reduced {
        order: dof_map.len(),
        stiffness: compact(&model.stiffness),
        mass: compact(&model.mass),
        dof_map,
    }
}

impl Reduced {
    /// The pencil (K, M) of the model.
    pub fn pencil(&self) -> Result<Pencil, BridgeError> {
        Ok(Pencil::new(
            symmetric_from_entries(self.order, self.stiffness.iter().copied(), true)?,
            symmetric_from_entries(self.order, self.mass.iter().copied(), true)?,
        ))
    }
}

/// A Matrix Market file of a lower triangle.
pub fn matrix_market(order: usize, entries: &[(usize, usize, f64)], what: &str) -> String {
    let mut out = String::with_capacity(40 * entries.len() + 200);
    out.push_str("%%MatrixMarket matrix coordinate real symmetric\n");
    let _ = writeln!(out, "% {what}, written by vbi generate");
    let _ = writeln!(out, "{order} {order} {}", entries.len());
    let mut buffer = ryu::Buffer::new();
    for &(r, c, v) in entries {
        let _ = writeln!(out, "{} {} {}", r + 1, c + 1, buffer.format(v));
    }
    out
}

/// Errors of `vbi generate`.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// Bad parameters.
    #[error(transparent)]
    Params(#[from] viaduct::GenerateError),
    /// A file could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: std::path::PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// Generates the viaduct and writes its files into `out` (created if
/// missing; each file written whole or not at all). Returns the order.
pub fn write_viaduct(params: &ViaductParams, out: &Path) -> Result<Reduced, WriteError> {
    let model = viaduct::assemble(params)?;
    let reduced = reduce(&model);
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| WriteError::Io { path, source }
    };
    std::fs::create_dir_all(out).map_err(io(out))?;
    let mut files: Vec<(&str, String)> = vec![
        (
            "K.mtx",
            matrix_market(
                reduced.order,
                &reduced.stiffness,
                "stiffness, N/m and N·m/rad",
            ),
        ),
        (
            "M.mtx",
            matrix_market(reduced.order, &reduced.mass, "mass, kg and kg·m²"),
        ),
    ];
    let mut map = String::from("dof,node,direction\n");
    for (i, &(node, d)) in reduced.dof_map.iter().enumerate() {
        let _ = writeln!(map, "{},{},{}", i + 1, node, DIRECTIONS[d]);
    }
    files.push(("dof_map.csv", map));
    let mut buffer = ryu::Buffer::new();
    for (name, rail) in ["rail_left.csv", "rail_right.csv"]
        .into_iter()
        .zip(&model.rails)
    {
        let mut text = String::from("node,x\n");
        for &n in rail {
            let _ = writeln!(text, "{},{}", n + 1, buffer.format(model.nodes[n][0]));
        }
        files.push((name, text));
    }
    files.push(("README.txt", info(params, &model, &reduced)));
    for (name, text) in files {
        let path = out.join(name);
        crate::atomic_file::write_atomic(&path, text.as_bytes()).map_err(io(&path))?;
    }
    Ok(reduced)
}

/// The info file: what was generated, its sizes and masses.
fn info(p: &ViaductParams, model: &Assembled, reduced: &Reduced) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Viaduct generated by vbi generate viaduct (EMBS paper layout, Table 1 defaults)."
    );
    let _ = writeln!(
        t,
        "spans: {} x {} m, piers {} m high, approaches {} m",
        p.spans, p.span_length, p.pier_height, p.approach_length
    );
    let _ = writeln!(
        t,
        "sleeper spacing (nominal): {} m, rail elements per sleeper bay: {}, pier elements: {}",
        p.sleeper_spacing, p.rail_divisions, p.pier_elements
    );
    let _ = writeln!(
        t,
        "nodes: {} ({} fixed)",
        model.nodes.len(),
        model.fixed.iter().filter(|f| **f).count()
    );
    let _ = writeln!(t, "DOFs (order of K and M): {}", reduced.order);
    let _ = writeln!(
        t,
        "stored entries (lower triangle): K {}, M {}",
        reduced.stiffness.len(),
        reduced.mass.len()
    );
    let _ = writeln!(t, "rail nodes: {} per rail", model.rails[0].len());
    let _ = writeln!(t, "component masses (kg):");
    let mut total = 0.0;
    for (name, m) in &model.component_masses {
        let _ = writeln!(t, "  {name}: {m:.1}");
        total += m;
    }
    let _ = writeln!(t, "  total: {total:.1}");
    let _ = writeln!(
        t,
        "files: K.mtx, M.mtx (Matrix Market, lower triangle, 1-based), dof_map.csv, rail_left.csv (y = +{0} m), rail_right.csv (y = -{0} m)",
        p.rail_offset
    );
    t
}
