//! Matrix Market coordinate files (NIST, "The Matrix Market Exchange
//! Formats: Initial Design", Boisvert, Pozo & Remington 1996):
//! `%%MatrixMarket matrix coordinate real symmetric|general`, `%` comment
//! lines, a size line `rows cols entries`, then `row col value` lines with
//! 1-based indices. A symmetric file holds one triangle (the lower, by the
//! standard; either is accepted, each entry is mirrored once).
//! `pattern`, `complex`, `integer`-free `array` and `skew-symmetric`/
//! `hermitian` files are refused: a stiffness or mass matrix is real and
//! symmetric.

use super::{MatrixFile, ReadError, SizeCheck};

/// Parses a Matrix Market coordinate file. `sizes` is called with the
/// header's (rows, entries) before anything is allocated per entry.
pub fn parse(text: &str, sizes: SizeCheck<'_>) -> Result<MatrixFile, ReadError> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    let Some((_, banner)) = lines.next() else {
        return Err(ReadError::new(1, None, "the file is empty"));
    };
    let words: Vec<String> = banner
        .split_whitespace()
        .map(str::to_ascii_lowercase)
        .collect();
    if words.first().map(String::as_str) != Some("%%matrixmarket") {
        return Err(ReadError::new(
            1,
            Some(1),
            "a Matrix Market file starts with `%%MatrixMarket matrix coordinate real symmetric|general`",
        ));
    }
    if words.len() != 5 || words[1] != "matrix" {
        return Err(ReadError::new(
            1,
            None,
            "the banner needs 5 words: `%%MatrixMarket matrix coordinate real symmetric|general`",
        ));
    }
    if words[2] != "coordinate" {
        return Err(ReadError::new(
            1,
            None,
            format!(
                "`{}` storage is not read; write the matrix in `coordinate` form",
                crate::text_table::quoted(&words[2])
            ),
        ));
    }
    match words[3].as_str() {
        "real" | "double" | "integer" => {}
        other => {
            return Err(ReadError::new(
                1,
                None,
                format!(
                    "`{}` entries are not read: a stiffness or mass matrix has real values \
                     (`pattern` has none, `complex` is not a structural matrix)",
                    crate::text_table::quoted(other)
                ),
            ));
        }
    }
    let symmetric = match words[4].as_str() {
        "symmetric" => true,
        "general" => false,
        other => {
            return Err(ReadError::new(
                1,
                None,
                format!(
                    "`{}` symmetry is not read; use `symmetric` or `general`",
                    crate::text_table::quoted(other)
                ),
            ));
        }
    };
    // The size line: the first line that is neither a comment nor blank.
    let (size_line, size) = loop {
        match lines.next() {
            None => {
                return Err(ReadError::new(
                    text.lines().count().max(1),
                    None,
                    "the file ends before its size line `rows columns entries`",
                ));
            }
            Some((_, l)) if l.trim().is_empty() || l.trim_start().starts_with('%') => continue,
            Some((n, l)) => break (n, l),
        }
    };
    let fields: Vec<&str> = size.split_whitespace().collect();
    if fields.len() != 3 {
        return Err(ReadError::new(
            size_line,
            None,
            format!(
                "the size line needs 3 whole numbers `rows columns entries`, it has {} fields",
                fields.len()
            ),
        ));
    }
    let mut numbers = [0u64; 3];
    for (k, f) in fields.iter().enumerate() {
        numbers[k] = f.parse().map_err(|_| {
            ReadError::new(
                size_line,
                Some(column_of(size, f)),
                format!("`{}` is not a whole number", crate::text_table::quoted(f)),
            )
        })?;
    }
    let [rows, cols, entries] = numbers;
    if rows != cols {
        return Err(ReadError::new(
            size_line,
            None,
            format!("the matrix is {rows} × {cols}; a stiffness or mass matrix is square"),
        ));
    }
    sizes(rows, entries).map_err(|m| ReadError::new(size_line, None, m))?;
    // Checked above against the budget, so these fit in memory.
    let order = rows as usize;
    let mut triplets = Vec::new();
    triplets.try_reserve_exact(entries as usize).map_err(|_| {
        ReadError::new(size_line, None, "the declared entries do not fit in memory")
    })?;
    let mut places = Vec::new();
    places.try_reserve_exact(entries as usize).map_err(|_| {
        ReadError::new(size_line, None, "the declared entries do not fit in memory")
    })?;
    let mut last_line = size_line;
    for (n, line) in lines {
        last_line = n;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('%') {
            continue;
        }
        if triplets.len() as u64 == entries {
            return Err(ReadError::new(
                n,
                None,
                format!("the size line declares {entries} entries but the file holds more"),
            ));
        }
        let fields: Vec<&str> = trimmed.split_whitespace().collect();
        if fields.len() != 3 {
            return Err(ReadError::new(
                n,
                None,
                format!(
                    "an entry line is `row column value`, this one has {} fields",
                    fields.len()
                ),
            ));
        }
        let index = |k: usize| -> Result<usize, ReadError> {
            let f = fields[k];
            let col = Some(column_of(line, f));
            let i: u64 = f.parse().map_err(|_| {
                ReadError::new(
                    n,
                    col,
                    format!("`{}` is not a whole number", crate::text_table::quoted(f)),
                )
            })?;
            if i == 0 || i > rows {
                return Err(ReadError::new(
                    n,
                    col,
                    format!("index {i} is outside 1 … {rows}"),
                ));
            }
            Ok(i as usize - 1)
        };
        let (row, col) = (index(0)?, index(1)?);
        let value = super::parse_value(fields[2], line, n)?;
        triplets.push((row, col, value));
        places.push((n, column_of(line, fields[0])));
    }
    if (triplets.len() as u64) < entries {
        return Err(ReadError::new(
            last_line,
            None,
            format!(
                "the file ends after {} of the {entries} entries its size line declares (truncated?)",
                triplets.len()
            ),
        ));
    }
    Ok(MatrixFile {
        order,
        symmetric,
        entries: triplets,
        places,
        dofs: None,
    })
}

/// 1-based column of `field` (a subslice of `line`) in `line`.
pub(super) fn column_of(line: &str, field: &str) -> usize {
    (field.as_ptr() as usize).saturating_sub(line.as_ptr() as usize) + 1
}

/// Writes a symmetric matrix (lower triangle, 1-based, shortest
/// round-trip decimal values) in Matrix Market coordinate form.
pub fn write_symmetric(order: usize, lower: &[(usize, usize, f64)], comment: &str) -> String {
    let mut out = String::from("%%MatrixMarket matrix coordinate real symmetric\n");
    for line in comment.lines() {
        out.push_str(&format!("% {line}\n"));
    }
    out.push_str(&format!("{order} {order} {}\n", lower.len()));
    let mut buffer = ryu::Buffer::new();
    for &(r, c, v) in lower {
        out.push_str(&format!("{} {} {}\n", r + 1, c + 1, buffer.format(v)));
    }
    out
}
