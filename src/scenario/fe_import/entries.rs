//! The entries of a read matrix as both triangles on the DOF map's rows:
//! a `symmetric` file's triangle mirrored, a `general` file checked for
//! symmetry and symmetrised, repeated entries refused. Each problem names
//! the entry's line and column in its file.

use std::collections::HashMap;

use super::{AssemblyError, Direction, MatrixFile, SYMMETRY_TOLERANCE, Source, fail, fail_at};

/// (line, column) of each map row's diagonal entry in `file`, where it has
/// one (the first, if repeated: [`both_triangles`] refuses the repeat).
pub(super) fn diagonal_places(
    file: &MatrixFile,
    position: &HashMap<(u64, Direction), usize>,
) -> Vec<Option<(usize, usize)>> {
    let mut out = vec![None; position.len()];
    for (e, &(r, c, _)) in file.entries.iter().enumerate() {
        if r != c {
            continue;
        }
        let row = match &file.dofs {
            Some(dofs) => dofs.get(r).and_then(|d| position.get(d)).copied(),
            None => Some(r),
        };
        if let Some(slot) = row.and_then(|row| out.get_mut(row))
            && slot.is_none()
        {
            *slot = file.places.get(e).copied();
        }
    }
    out
}

/// Both triangles of a read matrix on the map's DOFs: a symmetric file's
/// triangle mirrored (refused if it holds entries of both triangles), a
/// general file checked for symmetry within [`SYMMETRY_TOLERANCE`] and
/// symmetrised, a file naming its own DOFs (Abaqus) renumbered by the map.
pub(super) fn both_triangles(
    file: MatrixFile,
    map: &[(u64, Direction)],
    position: &HashMap<(u64, Direction), usize>,
    source: Source,
) -> Result<Vec<(usize, usize, f64)>, AssemblyError> {
    let renumber: Option<Vec<usize>> = match &file.dofs {
        Some(dofs) => {
            let mut out = Vec::with_capacity(dofs.len());
            for &(node, d) in dofs {
                match position.get(&(node, d)) {
                    Some(&i) => out.push(i),
                    None => {
                        return fail(
                            source,
                            format!(
                                "node {node} {} is not among the stiffness matrix's DOFs",
                                d.name()
                            ),
                        );
                    }
                }
            }
            Some(out)
        }
        None => {
            if file.order != map.len() {
                return fail(
                    source,
                    format!(
                        "the matrix has order {} but the DOF map and stiffness have {}",
                        file.order,
                        map.len()
                    ),
                );
            }
            None
        }
    };
    let at = |i: usize| renumber.as_ref().map_or(i, |r| r[i]);
    let place = |e: usize| file.places.get(e).copied().unwrap_or((0, 0));
    let name = |i: usize| format!("node {} {}", map[i].0, map[i].1.name());
    // Each matrix position once: a symmetric file's (i, j) and (j, i) are
    // the same entry, a general file's are two. FE programs write assembled
    // matrices, so a repeated position is an editing or export error; its
    // values are not summed (a repeated 1.0 doubles a stiffness silently).
    // The entries sorted by position (and file order within one) put the
    // repeats of a position next to each other; the one reported is the
    // first in file order that repeats an earlier entry.
    let (mut lower, mut upper) = (None, None);
    let (mut renumbered_lower, mut renumbered_upper) = (false, false);
    let mut keys: Vec<((usize, usize), usize)> = Vec::with_capacity(file.entries.len());
    for (e, &(r, c, _)) in file.entries.iter().enumerate() {
        if r > c {
            lower.get_or_insert(e);
        } else if r < c {
            upper.get_or_insert(e);
        }
        let (a, b) = (at(r), at(c));
        renumbered_lower |= a > b;
        renumbered_upper |= a < b;
        keys.push(((a, b), e));
    }
    keys.sort_unstable();
    // A symmetric file with positions on both sides of the diagonal: its
    // (i, j) and (j, i) meet only once each position is taken as i ≤ j.
    let normalised: Option<Vec<((usize, usize), usize)>> =
        (file.symmetric && renumbered_lower && renumbered_upper).then(|| {
            let mut normalised: Vec<_> = keys
                .iter()
                .map(|&((a, b), e)| ((a.min(b), a.max(b)), e))
                .collect();
            normalised.sort_unstable();
            normalised
        });
    let repeat = normalised
        .as_ref()
        .unwrap_or(&keys)
        .windows(2)
        .filter(|pair| pair[0].0 == pair[1].0)
        .map(|pair| (pair[1].1, pair[0].1))
        .min();
    drop(normalised);
    if let Some((e, earlier)) = repeat {
        let (r, c, _) = file.entries[e];
        let (a, b) = (at(r), at(c));
        let (line, _) = place(earlier);
        let (er, ec, _) = file.entries[earlier];
        let how = if file.symmetric && (er, ec) != (r, c) {
            "the file holds one triangle (`symmetric`), each off-diagonal entry once; this \
             one is given in both"
        } else {
            "an assembled matrix lists each entry once"
        };
        return fail_at(
            source,
            place(e),
            format!(
                "entry ({}, {}) ({}, {}) repeats entry ({}, {}) of line {line}: {how}. \
                 Repeated entries are refused rather than summed; remove one",
                r + 1,
                c + 1,
                name(a),
                name(b),
                er + 1,
                ec + 1
            ),
        );
    }
    let mut out = Vec::with_capacity(2 * keys.len());
    if file.symmetric {
        if let (Some(l), Some(u)) = (lower, upper) {
            let (later, earlier) = (l.max(u), l.min(u));
            let (er, ec, _) = file.entries[earlier];
            let (r, c, _) = file.entries[later];
            return fail_at(
                source,
                place(later),
                format!(
                    "a `symmetric` file must hold one triangle only; entry ({}, {}) is on the \
                     other side of the diagonal from entry ({}, {}) of line {} (write the file \
                     as `general`)",
                    r + 1,
                    c + 1,
                    er + 1,
                    ec + 1,
                    place(earlier).0
                ),
            );
        }
        for ((r, c), e) in keys {
            let v = file.entries[e].2;
            out.push((r, c, v));
            if r != c {
                out.push((c, r, v));
            }
        }
        return Ok(out);
    }
    let largest = file.entries.iter().fold(0.0f64, |a, e| a.max(e.2.abs()));
    // No position repeats: the entry at a position, by binary search.
    let first = |position: (usize, usize)| {
        keys.binary_search_by(|probe| probe.0.cmp(&position))
            .ok()
            .map(|k| keys[k].1)
    };
    for &((r, c), e) in &keys {
        let v = file.entries[e].2;
        let mirror = first((c, r));
        let mirror_value = mirror.map_or(0.0, |m| file.entries[m].2);
        if (v - mirror_value).abs() > SYMMETRY_TOLERANCE * largest {
            let other = match mirror {
                Some(m) => format!(
                    "({}, {}) = {mirror_value} at line {}",
                    c + 1,
                    r + 1,
                    place(m).0
                ),
                None => format!("({}, {}) is absent (0)", c + 1, r + 1),
            };
            return fail_at(
                source,
                place(e),
                format!(
                    "the matrix is not symmetric: entry ({}, {}) = {v} but {other} \
                     (rows {} and {}), beyond {SYMMETRY_TOLERANCE:e} of the largest entry",
                    r + 1,
                    c + 1,
                    name(r),
                    name(c)
                ),
            );
        }
        // (A + Aᵀ)/2: each stored entry contributes half to both places.
        out.push((r, c, 0.5 * v));
        out.push((c, r, 0.5 * v));
    }
    Ok(out)
}
