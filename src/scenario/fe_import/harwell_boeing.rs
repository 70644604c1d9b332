//! Harwell–Boeing assembled matrices (Duff, Grimes & Lewis, "Users' Guide
//! for the Harwell-Boeing Sparse Matrix Collection", 1992), as ANSYS's
//! `HBMAT` writes them: a 4-line header (5 with right-hand sides) of
//! fixed-width Fortran fields, then the column pointers, row indices and
//! values, each in the Fortran format the header names (`(10I8)`,
//! `(1P,4E20.12)`, …), read as fixed-width fields so numbers that touch
//! (`-1.0E+00-2.0E+00`) are still apart. `RSA` (real symmetric, lower
//! triangle by columns) and `RUA` (real unsymmetric) are read; pattern,
//! complex and elemental matrices are refused.
//!
//! ANSYS's `.mapping` file (written with `HBMAT,…,Mapping=YES`) names each
//! matrix equation's node and DOF: a header line, then `eqn node label`
//! rows with labels UX, UY, UZ, ROTX, ROTY, ROTZ; [`mapping`] reads it.

use super::{Direction, MatrixFile, ReadError, SizeCheck};

/// Fields per line and field width of a Fortran format such as `(10I8)`,
/// `(1P,4E20.12)` or `(3D26.18)`.
fn fortran_format(format: &str) -> Option<(usize, usize)> {
    let inner = format.trim().trim_start_matches('(').trim_end_matches(')');
    // A leading scale factor (`1P,`) does not change the field widths.
    let spec = inner.rsplit(',').next()?.trim().to_ascii_uppercase();
    // `1P4E20.12` without the comma: the scale factor ends at the P.
    let spec = match spec.find('P') {
        Some(p) => &spec[p + 1..],
        None => &spec[..],
    };
    let letter = spec.find(|c: char| c.is_ascii_alphabetic())?;
    let count: usize = if letter == 0 {
        1
    } else {
        spec[..letter].parse().ok()?
    };
    let rest = &spec[letter + 1..];
    let width: usize = rest.split('.').next()?.parse().ok()?;
    (count > 0 && width > 0).then_some((count, width))
}

/// Reads `count` fixed-width fields from `lines` (from `*next`).
fn fields<T>(
    lines: &[&str],
    next: &mut usize,
    count: usize,
    (per_line, width): (usize, usize),
    what: &str,
    mut parse: impl FnMut(&str, usize, usize) -> Result<T, ReadError>,
) -> Result<Vec<T>, ReadError> {
    let mut out = Vec::new();
    out.try_reserve_exact(count)
        .map_err(|_| ReadError::new(*next + 1, None, "the declared sizes do not fit in memory"))?;
    while out.len() < count {
        let Some(line) = lines.get(*next) else {
            return Err(ReadError::new(
                lines.len(),
                None,
                format!(
                    "the file ends after {} of the {count} {what} (truncated?)",
                    out.len()
                ),
            ));
        };
        let n = *next + 1;
        *next += 1;
        for k in 0..per_line {
            if out.len() == count {
                break;
            }
            let start = k * width;
            if start >= line.len() {
                break;
            }
            let end = (start + width).min(line.len());
            let field = line
                .get(start..end)
                .ok_or_else(|| ReadError::new(n, Some(start + 1), "a field is not plain ASCII"))?;
            if field.trim().is_empty() {
                break;
            }
            out.push(parse(field.trim(), n, start + 1)?);
        }
    }
    Ok(out)
}

/// A header integer field of `line` at columns `from..to` (0-based).
fn header_int(line: &str, n: usize, from: usize, to: usize, what: &str) -> Result<u64, ReadError> {
    let field = line.get(from..to.min(line.len())).unwrap_or("").trim();
    field.parse().map_err(|_| {
        ReadError::new(
            n,
            Some(from + 1),
            format!("{what} (columns {}–{to}) is not a whole number", from + 1),
        )
    })
}

/// Parses a Harwell–Boeing file.
pub fn parse(text: &str, sizes: SizeCheck<'_>) -> Result<MatrixFile, ReadError> {
    let lines: Vec<&str> = text.lines().collect();
    if lines.len() < 4 {
        return Err(ReadError::new(
            lines.len().max(1),
            None,
            "a Harwell–Boeing file has a header of at least 4 lines",
        ));
    }
    let rhs_cards = header_int(lines[1], 2, 56, 70, "RHSCRD").unwrap_or(0);
    let kind = lines[2].get(..3).unwrap_or("").to_ascii_uppercase();
    match kind.as_str() {
        "RSA" | "RUA" => {}
        other => {
            return Err(ReadError::new(
                3,
                Some(1),
                format!(
                    "matrix type `{}` is not read: a stiffness or mass matrix is real and \
                     assembled (RSA or RUA)",
                    crate::text_table::quoted(other)
                ),
            ));
        }
    }
    let rows = header_int(lines[2], 3, 14, 28, "NROW")?;
    let cols = header_int(lines[2], 3, 28, 42, "NCOL")?;
    let entries = header_int(lines[2], 3, 42, 56, "NNZERO")?;
    if rows != cols {
        return Err(ReadError::new(
            3,
            None,
            format!("the matrix is {rows} × {cols}; a stiffness or mass matrix is square"),
        ));
    }
    sizes(rows, entries).map_err(|m| ReadError::new(3, None, m))?;
    let format_at = |from: usize, to: usize, what: &str| {
        let f = lines[3].get(from..to.min(lines[3].len())).unwrap_or("");
        fortran_format(f).ok_or_else(|| {
            ReadError::new(
                4,
                Some(from + 1),
                format!(
                    "{what} format `{}` is not read",
                    crate::text_table::quoted(f.trim())
                ),
            )
        })
    };
    let pointer_format = format_at(0, 16, "pointer")?;
    let index_format = format_at(16, 32, "index")?;
    let value_format = format_at(32, 52, "value")?;
    let mut next = if rhs_cards > 0 { 5 } else { 4 };
    let n = rows as usize;
    let nnz = entries as usize;
    let whole = |f: &str, line: usize, col: usize| -> Result<u64, ReadError> {
        f.parse().map_err(|_| {
            ReadError::new(
                line,
                Some(col),
                format!("`{}` is not a whole number", crate::text_table::quoted(f)),
            )
        })
    };
    let pointers = fields(
        &lines,
        &mut next,
        n + 1,
        pointer_format,
        "column pointers",
        whole,
    )?;
    let indices = fields(
        &lines,
        &mut next,
        nnz,
        index_format,
        "row indices",
        |f, l, c| {
            let i = whole(f, l, c)?;
            if i == 0 || i > rows {
                return Err(ReadError::new(
                    l,
                    Some(c),
                    format!("row index {i} is outside 1 … {rows}"),
                ));
            }
            Ok(i as usize - 1)
        },
    )?;
    let values = fields(&lines, &mut next, nnz, value_format, "values", |f, l, c| {
        let line = lines[l - 1];
        let value = super::parse_value(f, line, l).map_err(|e| ReadError {
            column: Some(c),
            ..e
        })?;
        Ok((value, (l, c)))
    })?;
    if pointers[0] != 1 || pointers[n] != entries + 1 || pointers.windows(2).any(|w| w[1] < w[0]) {
        return Err(ReadError::new(
            5,
            None,
            format!(
                "the column pointers must rise from 1 to NNZERO + 1 = {}; they run from {} to {}",
                entries + 1,
                pointers[0],
                pointers[n]
            ),
        ));
    }
    let mut triplets = Vec::with_capacity(nnz);
    let mut places = Vec::with_capacity(nnz);
    for col in 0..n {
        for p in pointers[col] as usize - 1..pointers[col + 1] as usize - 1 {
            triplets.push((indices[p], col, values[p].0));
            places.push(values[p].1);
        }
    }
    Ok(MatrixFile {
        order: n,
        symmetric: kind == "RSA",
        entries: triplets,
        places,
        dofs: None,
    })
}

/// Reads an ANSYS `.mapping` file: for matrix equation i (from 0) its
/// (node, direction). Lines whose first word is not a whole number (the
/// header) are skipped.
pub fn mapping(text: &str, order: usize) -> Result<Vec<(u64, Direction)>, ReadError> {
    let mut map: Vec<Option<(u64, Direction)>> = vec![None; order];
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let words: Vec<&str> = line.split_whitespace().collect();
        let Some(Ok(eqn)) = words.first().map(|w| w.parse::<u64>()) else {
            continue;
        };
        if words.len() < 3 {
            return Err(ReadError::new(
                n,
                None,
                "a mapping row is `equation node dof`",
            ));
        }
        if eqn == 0 || eqn > order as u64 {
            return Err(ReadError::new(
                n,
                None,
                format!("equation {eqn} is outside the matrices' rows 1 … {order}"),
            ));
        }
        let node: u64 = words[1]
            .parse()
            .map_err(|_| ReadError::new(n, None, "the second word is not a node number"))?;
        let direction = match words[2].to_ascii_uppercase().as_str() {
            "UX" => Direction::Ux,
            "UY" => Direction::Uy,
            "UZ" => Direction::Uz,
            "ROTX" => Direction::Rx,
            "ROTY" => Direction::Ry,
            "ROTZ" => Direction::Rz,
            other => {
                return Err(ReadError::new(
                    n,
                    None,
                    format!(
                        "DOF `{}` is not one of UX, UY, UZ, ROTX, ROTY, ROTZ",
                        crate::text_table::quoted(other)
                    ),
                ));
            }
        };
        let slot = &mut map[eqn as usize - 1];
        if slot.is_some() {
            return Err(ReadError::new(
                n,
                None,
                format!("equation {eqn} is mapped twice"),
            ));
        }
        *slot = Some((node, direction));
    }
    if let Some(missing) = map.iter().position(Option::is_none) {
        return Err(ReadError::new(
            text.lines().count().max(1),
            None,
            format!("equation {} of {order} has no mapping row", missing + 1),
        ));
    }
    Ok(map.into_iter().flatten().collect())
}

/// Writes a symmetric matrix (lower triangle) as an `RSA` file with
/// `(8I10)` pointers and indices and `(1P,4E26.17)` values.
pub fn write_symmetric(order: usize, lower: &[(usize, usize, f64)], title: &str) -> String {
    let mut by_column: Vec<Vec<(usize, f64)>> = vec![Vec::new(); order];
    for &(r, c, v) in lower {
        let (r, c) = if r >= c { (r, c) } else { (c, r) };
        by_column[c].push((r, v));
    }
    let mut pointers = vec![1usize];
    let (mut indices, mut values) = (Vec::new(), Vec::new());
    for column in &mut by_column {
        column.sort_by_key(|e| e.0);
        for &(r, v) in column.iter() {
            indices.push(r + 1);
            values.push(v);
        }
        pointers.push(indices.len() + 1);
    }
    let cards = |count: usize, per: usize| count.div_ceil(per);
    let (ptr, ind, val) = (
        cards(pointers.len(), 8),
        cards(indices.len(), 8),
        cards(values.len(), 4),
    );
    let mut out = format!(
        "{:<72}{:<8}\n",
        title.chars().take(72).collect::<String>(),
        "VBI"
    );
    out.push_str(&format!(
        "{:>14}{:>14}{:>14}{:>14}{:>14}\n",
        ptr + ind + val,
        ptr,
        ind,
        val,
        0
    ));
    out.push_str(&format!(
        "RSA           {:>14}{:>14}{:>14}{:>14}\n",
        order,
        order,
        values.len(),
        0
    ));
    out.push_str(&format!(
        "{:<16}{:<16}{:<20}{:<20}\n",
        "(8I10)", "(8I10)", "(1P,4E26.17)", ""
    ));
    let ints = |out: &mut String, list: &[usize]| {
        for chunk in list.chunks(8) {
            for i in chunk {
                out.push_str(&format!("{i:>10}"));
            }
            out.push('\n');
        }
    };
    ints(&mut out, &pointers);
    ints(&mut out, &indices);
    for chunk in values.chunks(4) {
        for v in chunk {
            out.push_str(&format!("{v:>26.17E}"));
        }
        out.push('\n');
    }
    out
}
