//! The small CSV tables next to imported matrices: the DOF map
//! (`dof,node,direction`: matrix row from 1, node id, one of ux … rz) and a
//! rail (`node,x`: node id and its coordinate along the track, m, strictly
//! increasing). A header row is required (it names the columns); blank lines
//! and `#` comments are skipped.

use super::{Direction, ReadError};
use crate::text_table::quoted;

/// Data rows of a CSV table after its header `expected`: (line, fields).
fn rows<'t>(text: &'t str, expected: &[&str]) -> Result<Vec<(usize, Vec<&'t str>)>, ReadError> {
    let mut out = Vec::new();
    let mut header = false;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = trimmed.split(',').map(str::trim).collect();
        if !header {
            let names: Vec<String> = fields.iter().map(|f| f.to_ascii_lowercase()).collect();
            if names != expected {
                return Err(ReadError::new(
                    n,
                    Some(1),
                    format!(
                        "the header must be `{}` (the first line that is not blank or a `#` \
                         comment); this line is not: is it the right file?",
                        expected.join(",")
                    ),
                ));
            }
            header = true;
            continue;
        }
        if fields.len() != expected.len() {
            return Err(ReadError::new(
                n,
                None,
                format!(
                    "a row has {} columns ({}), this one has {}",
                    expected.len(),
                    expected.join(", "),
                    fields.len()
                ),
            ));
        }
        out.push((n, fields));
    }
    if !header {
        return Err(ReadError::new(
            1,
            None,
            format!(
                "the file is empty; it needs the header `{}`",
                expected.join(",")
            ),
        ));
    }
    Ok(out)
}

fn whole(line: usize, field: &str, column: usize) -> Result<u64, ReadError> {
    field.parse().map_err(|_| {
        ReadError::new(
            line,
            Some(column),
            format!("`{}` is not a whole number", quoted(field)),
        )
    })
}

/// Reads a DOF map: for matrix row i (from 0) its (node, direction).
/// `order` is the matrices' order: every row 1 … order must appear once.
pub fn dof_map(text: &str, order: usize) -> Result<Vec<(u64, Direction)>, ReadError> {
    let rows = rows(text, &["dof", "node", "direction"])?;
    let mut map: Vec<Option<(u64, Direction)>> = vec![None; order];
    let mut seen = std::collections::HashMap::new();
    for (n, f) in &rows {
        let dof = whole(*n, f[0], 1)?;
        if dof == 0 || dof > order as u64 {
            return Err(ReadError::new(
                *n,
                Some(1),
                format!("dof {dof} is outside the matrices' rows 1 … {order}"),
            ));
        }
        let node = whole(*n, f[1], 2)?;
        let direction = Direction::parse(f[2]).ok_or_else(|| {
            ReadError::new(
                *n,
                Some(3),
                format!(
                    "`{}` is not a direction (ux, uy, uz, rx, ry, rz)",
                    quoted(f[2])
                ),
            )
        })?;
        let slot = &mut map[dof as usize - 1];
        if slot.is_some() {
            return Err(ReadError::new(
                *n,
                Some(1),
                format!("dof {dof} is mapped twice"),
            ));
        }
        if let Some(first) = seen.insert((node, direction), *n) {
            return Err(ReadError::new(
                *n,
                Some(2),
                format!(
                    "node {node} {} is mapped twice (first on line {first})",
                    direction.name()
                ),
            ));
        }
        *slot = Some((node, direction));
    }
    if let Some(missing) = map.iter().position(Option::is_none) {
        return Err(ReadError::new(
            rows.last().map_or(1, |r| r.0),
            None,
            format!(
                "the map has {} rows but the matrices have {order}; dof {} is missing",
                rows.len(),
                missing + 1
            ),
        ));
    }
    Ok(map.into_iter().flatten().collect())
}

/// Reads a rail: (node, x) pairs with x strictly increasing, at least two.
pub fn rail(text: &str) -> Result<Vec<(u64, f64)>, ReadError> {
    let rows = rows(text, &["node", "x"])?;
    let mut out: Vec<(u64, f64)> = Vec::with_capacity(rows.len());
    for (n, f) in &rows {
        let node = whole(*n, f[0], 1)?;
        let x: f64 = f[1].parse().map_err(|_| {
            ReadError::new(*n, Some(2), format!("`{}` is not a number", quoted(f[1])))
        })?;
        check_next(&out, node, x).map_err(|m| ReadError::new(*n, Some(2), m))?;
        out.push((node, x));
    }
    if out.len() < 2 {
        return Err(ReadError::new(
            rows.last().map_or(1, |r| r.0),
            None,
            format!(
                "a rail needs at least two nodes, this file has {}",
                out.len()
            ),
        ));
    }
    Ok(out)
}

/// Whether (node, x) may follow `before` along a rail: x finite and
/// beyond the previous node's.
pub fn check_next(before: &[(u64, f64)], node: u64, x: f64) -> Result<(), String> {
    if !x.is_finite() {
        return Err(format!("x = {x} is not a finite number"));
    }
    if let Some(&(prev_node, prev)) = before.last()
        && x <= prev
    {
        return Err(format!(
            "node {node} at x = {x} m does not lie beyond node {prev_node} at {prev} m \
             (x must increase strictly along a rail)"
        ));
    }
    Ok(())
}
