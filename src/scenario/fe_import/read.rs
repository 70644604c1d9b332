//! What the readers return and the assembly of an imported model from the
//! matrices, DOF map and rails they read: sizes, symmetry, masses,
//! constraints and rail nodes checked against each other, the free DOFs kept.

use std::collections::HashMap;

use thiserror::Error;

use crate::scene::imported::{
    Axes, Direction, ImportedModel, RailDofs, RailEntry, RotationSign, SupportRow,
};

use super::{entries, matrix_market, penalty, rotation};

/// A problem at a line (and column) of one file.
#[derive(Debug, Clone, Error, PartialEq)]
#[error("{}: {message}", match column { Some(c) => format!("line {line}, column {c}"), None => format!("line {line}") })]
pub struct ReadError {
    /// Line from 1.
    pub line: usize,
    /// Column from 1, where meaningful.
    pub column: Option<usize>,
    /// What is wrong.
    pub message: String,
    /// What to do about it, if there is more to say than the message.
    pub help: Option<String>,
}

impl ReadError {
    /// An error at `line` (and `column`).
    pub fn new(line: usize, column: Option<usize>, message: impl Into<String>) -> Self {
        Self {
            line,
            column,
            message: message.into(),
            help: None,
        }
    }

    /// The same error with a `help:` line.
    pub fn with_help(mut self, help: Option<String>) -> Self {
        self.help = help;
        self
    }
}

/// Called with a header's declared (rows, entries) before anything is
/// allocated for them; an error message refuses them.
pub type SizeCheck<'a> = &'a mut dyn FnMut(u64, u64) -> Result<(), String>;

/// A matrix as read: order, whether one triangle stands for both, the
/// entries (row, column, value) from 0, and the DOF map the format implies
/// (Abaqus), if any.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixFile {
    /// Rows = columns.
    pub order: usize,
    /// One triangle stored, mirrored on assembly.
    pub symmetric: bool,
    /// (row, column, value), 0-based.
    pub entries: Vec<(usize, usize, f64)>,
    /// (line, column) of each entry in its file, from 1: where a duplicate
    /// or an asymmetric entry is reported.
    pub places: Vec<(usize, usize)>,
    /// (node, direction) of each row, when the format names them.
    pub dofs: Option<Vec<(u64, Direction)>>,
}

/// Reads a finite real number of an entry line.
pub(crate) fn parse_value(field: &str, line: &str, n: usize) -> Result<f64, ReadError> {
    let column = Some(matrix_market::column_of(line, field));
    // Fortran writes exponents as D (1.0D+03).
    let v: f64 = field.replace(['D', 'd'], "e").parse().map_err(|_| {
        ReadError::new(
            n,
            column,
            format!("`{}` is not a number", crate::text_table::quoted(field)),
        )
    })?;
    if !v.is_finite() {
        return Err(ReadError::new(
            n,
            column,
            format!(
                "`{}` is not a finite number",
                crate::text_table::quoted(field)
            ),
        ));
    }
    Ok(v)
}

/// Which input a problem of [`ImportedModel::assemble`] comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// The stiffness file.
    Stiffness,
    /// The mass file.
    Mass,
    /// The damping file.
    Damping,
    /// The DOF map.
    DofMap,
    /// `constrained[i]`.
    Constrained(usize),
    /// Rail i.
    Rail(usize),
    /// `track`.
    Track,
    /// `rotation_sign` of this rotation (or where it belongs).
    RotationSign(Direction),
}

/// A problem found while assembling an imported model.
#[derive(Debug, Clone, Error, PartialEq)]
#[error("{message}")]
pub struct AssemblyError {
    /// Where it comes from.
    pub source_input: Source,
    /// (line, column) in that input's file, from 1, when one entry is to blame.
    pub place: Option<(usize, usize)>,
    /// What is wrong.
    pub message: String,
    /// What to do about it, if there is more to say than the message.
    pub help: Option<String>,
}

impl AssemblyError {
    /// The same error with a `help:` line.
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }
}

pub(crate) fn fail<T>(source: Source, message: impl Into<String>) -> Result<T, AssemblyError> {
    Err(AssemblyError {
        source_input: source,
        place: None,
        message: message.into(),
        help: None,
    })
}

/// [`fail`] at an entry's (line, column) of the source's file.
pub(crate) fn fail_at<T>(
    source: Source,
    place: (usize, usize),
    message: impl Into<String>,
) -> Result<T, AssemblyError> {
    Err(AssemblyError {
        source_input: source,
        place: Some(place),
        message: message.into(),
        help: None,
    })
}

/// Relative tolerance of the symmetry check of a `general` matrix:
/// |Aᵢⱼ − Aⱼᵢ| ≤ tol · max|A| (FE programs print 6–16 digits; 1e-6 admits
/// the 7 significant digits of a single-precision print).
pub const SYMMETRY_TOLERANCE: f64 = 1e-6;

/// A rail as given: name and (node, x) pairs.
pub type RailNodes = (String, Vec<(u64, f64)>);

impl ImportedModel {
    /// Checks the read matrices, map, constraints and rails against each
    /// other and keeps the free DOFs. `map` is required unless the
    /// stiffness file names its DOFs (Abaqus). `rotation_sign` flips the files'
    /// slope rotations into this program's convention, which each rail's
    /// stiffness must then confirm ([`rotation`]); `sign_declared` says
    /// the scene wrote `rotation_sign` (then a rail whose stiffness cannot
    /// tell the sign is taken at the scene's word). `axes` names the files'
    /// vertical: their directions are read as vbi's ([`Axes::read`]) before
    /// anything else, so `constrained`, `rotation_sign` and every message
    /// speak vbi's axes.
    #[allow(clippy::too_many_arguments)]
    pub fn assemble(
        mut stiffness: MatrixFile,
        mut mass: MatrixFile,
        mut damping: Option<MatrixFile>,
        map: Option<Vec<(u64, Direction)>>,
        constrained: &[(u64, Direction)],
        rails: &[RailNodes],
        track: &[usize],
        rotation_sign: RotationSign,
        sign_declared: bool,
        axes: Axes,
    ) -> Result<Self, AssemblyError> {
        // The files' directions in vbi's axes (an Abaqus file names its own).
        for file in [Some(&mut stiffness), Some(&mut mass), damping.as_mut()]
            .into_iter()
            .flatten()
        {
            if let Some(dofs) = &mut file.dofs {
                for dof in dofs.iter_mut() {
                    dof.1 = axes.read(dof.1).0;
                }
            }
        }
        let map = map.map(|map| {
            map.into_iter()
                .map(|(node, d)| (node, axes.read(d).0))
                .collect()
        });
        let map = match (map, &stiffness.dofs) {
            (Some(map), _) => map,
            (None, Some(dofs)) => dofs.clone(),
            (None, None) => {
                return fail(
                    Source::DofMap,
                    "a `dof_map` is needed: the stiffness file does not name its DOFs",
                );
            }
        };
        let n = stiffness.order;
        if map.len() != n {
            return fail(
                Source::DofMap,
                format!(
                    "the DOF map has {} rows but the stiffness matrix has {n}",
                    map.len()
                ),
            );
        }
        // The map's names first: a y-up model's are refused before anything
        // read in them is reported.
        if !map.iter().any(|d| d.1 == Direction::Uz) {
            return Err(no_vertical(&map, axes));
        }
        let position: HashMap<(u64, Direction), usize> =
            map.iter().enumerate().map(|(i, &k)| (k, i)).collect();
        let stiffness_diagonal = entries::diagonal_places(&stiffness, &position);
        let mass_diagonal = entries::diagonal_places(&mass, &position);
        let k = entries::both_triangles(stiffness, &map, &position, Source::Stiffness)?;
        let m = entries::both_triangles(mass, &map, &position, Source::Mass)?;
        let c = match damping {
            Some(c) => Some(entries::both_triangles(
                c,
                &map,
                &position,
                Source::Damping,
            )?),
            None => None,
        };
        // θ_here = sign · θ_file: D K D with D = diag(sign), exact; the
        // axes' turn likewise (vbi's ry = −rz of a y-up file).
        let (k, m, c) = if rotation_sign.is_default() && axes.is_default() {
            (k, m, c)
        } else {
            let sign = |i: usize| {
                let (_, turned) = axes.read(axes.written(map[i].1));
                turned * rotation_sign.of(map[i].1) as f64
            };
            let flip = |entries: Vec<(usize, usize, f64)>| -> Vec<(usize, usize, f64)> {
                entries
                    .into_iter()
                    .map(|(r, c, v)| (r, c, sign(r) * sign(c) * v))
                    .collect()
            };
            (flip(k), flip(m), c.map(flip))
        };
        let mut free = vec![true; n];
        for (i, &(node, direction)) in constrained.iter().enumerate() {
            match position.get(&(node, direction)) {
                Some(&dof) => free[dof] = false,
                None => {
                    let turned = if axes.is_default() {
                        String::new()
                    } else {
                        format!(
                            "; with `axes: {}` the scene names vbi's directions (z up): the \
                             files' {} is {} here",
                            axes.name(),
                            axes.written(direction).name(),
                            direction.name()
                        )
                    };
                    return fail(
                        Source::Constrained(i),
                        format!(
                            "node {node} {} is not in the DOF map (a DOF removed from the \
                             matrices already must not be listed){turned}",
                            direction.name()
                        ),
                    );
                }
            }
        }
        let mut translational_mass = [0.0; 3];
        for (axis, direction) in [Direction::Ux, Direction::Uy, Direction::Uz]
            .into_iter()
            .enumerate()
        {
            // + 0.0: an empty sum is −0.0, shown as such in summary.json.
            translational_mass[axis] = m
                .iter()
                .filter(|&&(r, c, _)| map[r].1 == direction && map[c].1 == direction)
                .map(|e| e.2)
                .sum::<f64>()
                + 0.0;
        }
        let mut index = vec![None; n];
        let mut dofs = Vec::new();
        for dof in 0..n {
            if free[dof] {
                index[dof] = Some(dofs.len());
                dofs.push(map[dof]);
            }
        }
        if dofs.is_empty() {
            return fail(Source::Constrained(0), "every DOF is constrained");
        }
        let restrict = |entries: Vec<(usize, usize, f64)>| -> Vec<(usize, usize, f64)> {
            entries
                .into_iter()
                .filter_map(|(r, c, v)| Some((index[r]?, index[c]?, v)))
                .collect()
        };
        // The supports move with the ground too: M δ over the full matrix,
        // then kept on the free rows.
        let mut vertical_inertia = vec![0.0; dofs.len()];
        let mut lateral_inertia = vec![0.0; dofs.len()];
        for &(r, c, v) in &m {
            match (index[r], map[c].1) {
                (Some(row), Direction::Uz) => vertical_inertia[row] += v,
                (Some(row), Direction::Uy) => lateral_inertia[row] += v,
                _ => {}
            }
        }
        // The supports' rows on the free columns, for their reactions.
        let support_of: HashMap<usize, usize> = constrained
            .iter()
            .enumerate()
            .filter_map(|(i, key)| position.get(key).map(|&g| (g, i)))
            .collect();
        let mut supports: Vec<SupportRow> = constrained
            .iter()
            .map(|&(node, direction)| SupportRow {
                node,
                direction,
                stiffness: Vec::new(),
                mass: Vec::new(),
                vertical_inertia: 0.0,
                lateral_inertia: 0.0,
            })
            .collect();
        for (entries, is_mass) in [(&k, false), (&m, true)] {
            for &(r, c, v) in entries.iter() {
                let Some(&s) = support_of.get(&r) else {
                    continue;
                };
                let row = &mut supports[s];
                if let Some(col) = index[c] {
                    if is_mass {
                        row.mass.push((col, v));
                    } else {
                        row.stiffness.push((col, v));
                    }
                }
                if is_mass {
                    match map[c].1 {
                        Direction::Uz => row.vertical_inertia += v,
                        Direction::Uy => row.lateral_inertia += v,
                        _ => {}
                    }
                }
            }
        }
        let (k, m) = (restrict(k), restrict(m));
        let c = c.map(restrict);
        // Diagonals: a free DOF needs stiffness and mass of its own.
        let diagonal = |entries: &[(usize, usize, f64)]| {
            let mut d = vec![0.0; dofs.len()];
            for &(r, c, v) in entries {
                if r == c {
                    d[r] += v;
                }
            }
            d
        };
        for (i, (kd, md)) in diagonal(&k).into_iter().zip(diagonal(&m)).enumerate() {
            let (node, direction) = dofs[i];
            let name = format!("node {node} {}", direction.name());
            if md < 0.0 {
                return fail(
                    Source::Mass,
                    format!("{name} has a negative diagonal mass {md}"),
                );
            }
            if md == 0.0 {
                return fail(
                    Source::Mass,
                    format!(
                        "{name} carries no mass (diagonal 0): massless DOFs are refused rather than \
                         condensed; export a consistent mass matrix (with rotary inertia), or list \
                         the DOF under `constrained` if it is really fixed"
                    ),
                );
            }
            if kd <= 0.0 {
                return fail(
                    Source::Stiffness,
                    format!(
                        "{name} has a diagonal stiffness {kd}, not positive (is it held by anything?)"
                    ),
                );
            }
        }
        let free_places = |places: &[Option<(usize, usize)>]| -> Vec<Option<(usize, usize)>> {
            (0..n).filter(|&g| free[g]).map(|g| places[g]).collect()
        };
        penalty::check(
            &k,
            &dofs,
            &free_places(&stiffness_diagonal),
            Source::Stiffness,
        )?;
        penalty::check(&m, &dofs, &free_places(&mass_diagonal), Source::Mass)?;
        if let Some(short) = rails.iter().position(|r| r.1.len() < 2) {
            return fail(Source::Rail(short), "a rail needs at least two nodes");
        }
        // Rails: every node in the map; one without uz is a support (the
        // export dropped its fixed DOFs), unless no node of the rail has
        // one (the map has uz: checked above). Deck coordinates from the
        // first node of any rail.
        let origin = rails.iter().map(|r| r.1[0].1).fold(f64::INFINITY, f64::min);
        let end = rails
            .iter()
            .map(|r| r.1[r.1.len() - 1].1)
            .fold(f64::NEG_INFINITY, f64::max);
        let nodes_in_map: std::collections::HashSet<u64> = map.iter().map(|d| d.0).collect();
        let mut rail_dofs = Vec::with_capacity(rails.len());
        for (ri, (name, nodes)) in rails.iter().enumerate() {
            let find = |node: u64, d: Direction| position.get(&(node, d)).copied();
            let name_shown = crate::scenario::diagnostic::escaped(name);
            for &(node, _) in nodes {
                if !nodes_in_map.contains(&node) {
                    return Err(AssemblyError {
                        source_input: Source::Rail(ri),
                        place: None,
                        message: format!(
                            "rail `{name_shown}`: node {node} is not in the DOF map (no DOF of \
                             it is): a rail node without its vertical DOF is taken as a support \
                             only when the map holds another DOF of it, so that a mistyped id is \
                             not read as a support"
                        ),
                        help: Some(
                            "check the node id; a node fixed in every direction, which the \
                             export dropped, must be exported with its DOFs and these listed \
                             under `bridge.constrained`"
                                .into(),
                        ),
                    });
                }
            }
            if nodes
                .iter()
                .all(|&(node, _)| find(node, Direction::Uz).is_none())
            {
                return fail(
                    Source::Rail(ri),
                    format!(
                        "rail `{name_shown}`: none of its nodes has a uz DOF in the map (vbi's \
                         vertical is z): a rail every node of which is held vertically carries \
                         nothing"
                    ),
                );
            }
            let column = |d: Direction| -> Vec<Option<usize>> {
                nodes
                    .iter()
                    .map(|&(node, _)| find(node, d).and_then(|g| index[g]))
                    .collect()
            };
            let has_all = |d: Direction| nodes.iter().all(|&(node, _)| find(node, d).is_some());
            rail_dofs.push(RailDofs {
                name: name.clone(),
                nodes: nodes.iter().map(|p| p.0).collect(),
                x: nodes.iter().map(|p| p.1 - origin).collect(),
                displacement: [column(Direction::Uz), column(Direction::Uy)],
                rotation: [column(Direction::Ry), column(Direction::Rz)],
                hermite: [has_all(Direction::Ry), has_all(Direction::Rz)],
            });
        }
        if track.is_empty() || track.iter().any(|&t| t >= rails.len()) {
            return fail(Source::Track, "the track names no rail");
        }
        for rail in &rail_dofs {
            for plane in 0..2 {
                if rail.hermite[plane] {
                    rotation::check(&k, rail, plane, rotation_sign, sign_declared)?;
                }
            }
        }
        Ok(Self {
            dofs,
            stiffness: k,
            mass: m,
            damping: c,
            rails: rail_dofs,
            track: track.to_vec(),
            length: end - origin,
            translational_mass,
            vertical_inertia,
            lateral_inertia,
            entry: RailEntry {
                start: 0.0,
                end: end - origin,
                entry: 0.0,
                exit: 0.0,
            },
            supports,
        })
    }
}

/// The DOF map has no vertical DOF: what it has, and how a y-up model is
/// read.
fn no_vertical(map: &[(u64, Direction)], axes: Axes) -> AssemblyError {
    let mut names: Vec<Direction> = map.iter().map(|d| axes.written(d.1)).collect();
    names.sort_unstable();
    names.dedup();
    let names: Vec<&str> = names.into_iter().map(Direction::name).collect();
    let (message, help) = match axes {
        Axes::ZUp => (
            format!(
                "the DOF map has no uz DOF: vbi's vertical is z (x along the track, y lateral, z \
                 up), and the map's directions are {}",
                names.join(", ")
            ),
            "a model with y up (an OpenSees 2D frame, ndm 2 ndf 3: ux, uy, rz) is read with \
             `axes: y_up` under `bridge` (its uy as vbi's uz, its rz as ry = −rz); otherwise \
             name the vertical DOFs uz in the map",
        ),
        Axes::YUp => (
            format!(
                "the DOF map has no uy DOF, the vertical of `axes: y_up`; its directions are {}",
                names.join(", ")
            ),
            "leave `axes` out if the files' vertical is z",
        ),
    };
    AssemblyError {
        source_input: Source::DofMap,
        place: None,
        message,
        help: Some(help.into()),
    }
}
