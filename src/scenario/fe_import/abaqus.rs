//! Abaqus `*MATRIX GENERATE` text output (`*MATRIX OUTPUT, STIFFNESS=YES,
//! MASS=YES, FORMAT=COORDINATE`): one entry a line, `row node, row dof,
//! column node, column dof, value`, comma separated; Abaqus writes one
//! triangle of a symmetric matrix. Lines starting with `*` (keywords,
//! `**` comments) are skipped. DOFs 1–6 are ux, uy, uz, rx, ry, rz
//! (Abaqus Analysis User's Guide, "Conventions": degrees of freedom), so the
//! file implies its own DOF map: every (node, dof) that appears, ordered by
//! node then dof.

use std::collections::BTreeMap;

use super::{Direction, MatrixFile, ReadError};

/// A (node, Abaqus DOF number) key.
type Key = (u64, u8);

/// Parses an Abaqus coordinate matrix.
pub fn parse(text: &str) -> Result<MatrixFile, ReadError> {
    let mut raw: Vec<(Key, Key, f64)> = Vec::new();
    let mut places = Vec::new();
    let mut keys: BTreeMap<Key, usize> = BTreeMap::new();
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('*') {
            continue;
        }
        let fields: Vec<&str> = trimmed.split(',').map(str::trim).collect();
        if fields.len() != 5 {
            return Err(ReadError::new(
                n,
                None,
                format!(
                    "an entry line is `node, dof, node, dof, value`, this one has {} fields",
                    fields.len()
                ),
            ));
        }
        let whole = |k: usize| -> Result<u64, ReadError> {
            let f = fields[k];
            f.parse().map_err(|_| {
                ReadError::new(
                    n,
                    Some(super::matrix_market::column_of(line, f)),
                    format!("`{}` is not a whole number", crate::text_table::quoted(f)),
                )
            })
        };
        let dof = |k: usize| -> Result<u8, ReadError> {
            let d = whole(k)?;
            if !(1..=6).contains(&d) {
                return Err(ReadError::new(
                    n,
                    Some(super::matrix_market::column_of(line, fields[k])),
                    format!("DOF {d} is not one of 1 … 6 (ux, uy, uz, rx, ry, rz)"),
                ));
            }
            Ok(d as u8)
        };
        let a = (whole(0)?, dof(1)?);
        let b = (whole(2)?, dof(3)?);
        let value = super::parse_value(fields[4], line, n)?;
        keys.insert(a, 0);
        keys.insert(b, 0);
        raw.push((a, b, value));
        places.push((n, super::matrix_market::column_of(line, fields[0])));
    }
    if raw.is_empty() {
        return Err(ReadError::new(
            text.lines().count().max(1),
            None,
            "the file holds no `node, dof, node, dof, value` entry",
        ));
    }
    let mut dofs = Vec::with_capacity(keys.len());
    for (index, (key, slot)) in keys.iter_mut().enumerate() {
        *slot = index;
        dofs.push((key.0, Direction::ALL[key.1 as usize - 1]));
    }
    let entries = raw
        .into_iter()
        .map(|(a, b, v)| (keys[&a], keys[&b], v))
        .collect();
    Ok(MatrixFile {
        order: dofs.len(),
        symmetric: true,
        entries,
        places,
        dofs: Some(dofs),
    })
}

/// Writes a symmetric matrix (lower triangle) in this form, each row and
/// column named by its (node, direction).
pub fn write_symmetric(dofs: &[(u64, Direction)], lower: &[(usize, usize, f64)]) -> String {
    let mut out = String::from("** vbi: *MATRIX GENERATE coordinate output\n");
    let mut buffer = ryu::Buffer::new();
    for &(r, c, v) in lower {
        let (a, b) = (dofs[r], dofs[c]);
        out.push_str(&format!(
            "{},{}, {},{}, {}\n",
            a.0,
            a.1.abaqus(),
            b.0,
            b.1.abaqus(),
            buffer.format(v)
        ));
    }
    out
}
