//! Dense text matrices: one row of the matrix a line, its numbers separated
//! by blanks, as OpenSees' `printA('-file', …)` writes the system matrix
//! (a blank line first, each number followed by a space, 6 significant
//! digits by default) and as MATLAB's `save -ascii` or NumPy's `savetxt`
//! write a 2-D array. Blank lines and `#` or `%` comments are skipped. The
//! matrix must be square; it is read as a `general` file (both triangles,
//! checked for symmetry and symmetrised on assembly), its zeros dropped.

use super::{MatrixFile, ReadError, SizeCheck, parse_value};

/// What the file was taken for, said in each of its errors.
pub const LOOKS_DENSE: &str = "this looks like a dense text matrix (rows of numbers, one matrix \
                               row a line, as OpenSees `printA('-file')` writes)";

/// The formats vbi reads, for a `help:` line.
pub const FORMATS_HELP: &str = "vbi reads Matrix Market coordinate files (`%%MatrixMarket \
                                matrix coordinate real symmetric|general`), Harwell–Boeing \
                                RSA/RUA (ANSYS `HBMAT`), Abaqus `*MATRIX GENERATE` coordinate \
                                output and square dense text matrices (docs/guide/imports.md)";

/// Whether `text` is a dense text matrix: its first three lines that are
/// not blank or comments (all of them, if fewer) hold numbers only, and
/// it does not start with a Matrix Market banner (`%%`). A
/// Harwell–Boeing file's third header line starts with its type (`RSA`),
/// a Matrix Market file with its banner, an Abaqus file's lines hold
/// commas.
pub fn looks_dense(text: &str) -> bool {
    if text.trim_start().starts_with("%%") {
        return false;
    }
    let mut rows = data_lines(text).take(3).peekable();
    rows.peek().is_some()
        && rows.all(|(n, line)| {
            line.split_whitespace()
                .all(|field| parse_value(field, line, n).is_ok())
        })
}

/// The lines that are not blank or comments, numbered from 1.
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().filter_map(|(i, line)| {
        let trimmed = line.trim();
        (!trimmed.is_empty() && !trimmed.starts_with('#') && !trimmed.starts_with('%'))
            .then_some((i + 1, line))
    })
}

/// Parses a dense text matrix. `sizes` is called with (rows, nonzero
/// entries at most) once the first row gives the order, before anything is
/// allocated for it.
pub fn parse(text: &str, sizes: SizeCheck<'_>) -> Result<MatrixFile, ReadError> {
    let help = || Some(FORMATS_HELP.to_string());
    let mut order = None;
    let mut first_line = 0;
    let mut row = 0;
    let mut entries = Vec::new();
    let mut places = Vec::new();
    for (n, line) in data_lines(text) {
        let fields: Vec<&str> = line.split_whitespace().collect();
        let order = *order.get_or_insert_with(|| {
            first_line = n;
            fields.len()
        });
        if row == 0 {
            sizes(order as u64, (order as u64).saturating_mul(order as u64))
                .map_err(|m| ReadError::new(n, None, format!("{LOOKS_DENSE}: {m}")))?;
        }
        if fields.len() != order {
            return Err(ReadError::new(
                n,
                None,
                format!(
                    "{LOOKS_DENSE}, but this line has {} numbers where the first row (line \
                     {first_line}) has {order}: every row of a dense matrix has one number a \
                     column",
                    fields.len()
                ),
            )
            .with_help(help()));
        }
        if row == order {
            return Err(ReadError::new(
                n,
                None,
                format!(
                    "{LOOKS_DENSE}, but it has more than {order} rows of {order} numbers: a \
                     stiffness or mass matrix is square"
                ),
            )
            .with_help(help()));
        }
        for (column, field) in fields.iter().enumerate() {
            let value = parse_value(field, line, n).map_err(|e| ReadError {
                message: format!("{LOOKS_DENSE}: {}", e.message),
                ..e
            })?;
            if value != 0.0 {
                entries.push((row, column, value));
                places.push((n, super::matrix_market::column_of(line, field)));
            }
        }
        row += 1;
    }
    let Some(order) = order else {
        return Err(ReadError::new(1, None, "the file holds no matrix").with_help(help()));
    };
    if row < order {
        return Err(ReadError::new(
            text.lines().count().max(1),
            None,
            format!(
                "{LOOKS_DENSE}, but it has {row} rows of {order} numbers: a stiffness or mass \
                 matrix is square (is the file cut short?)"
            ),
        )
        .with_help(help()));
    }
    Ok(MatrixFile {
        order,
        symmetric: false,
        entries,
        places,
        dofs: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<MatrixFile, ReadError> {
        parse(text, &mut |_, _| Ok(()))
    }

    #[test]
    fn reads_opensees_printa_output() {
        // A blank line, then rows each followed by a space.
        let file = read("\n2e+06 -1e+06 \n-1e+06 2e+06 \n").unwrap();
        assert_eq!(file.order, 2);
        assert!(!file.symmetric);
        assert_eq!(
            file.entries,
            vec![(0, 0, 2e6), (0, 1, -1e6), (1, 0, -1e6), (1, 1, 2e6)]
        );
        assert_eq!(file.places[1], (2, 7));
        assert!(looks_dense("\n2e+06 -1e+06 \n-1e+06 2e+06 \n"));
    }

    #[test]
    fn tells_other_formats_apart() {
        assert!(!looks_dense(
            "%%MatrixMarket matrix coordinate real general\n1 1 1\n1 1 2\n"
        ));
        assert!(!looks_dense("1, 1, 1, 1, 2.0\n"));
        assert!(!looks_dense(
            "title\n   1   1   1   1\nRSA  2  2  3  0\n(3I8) (3I8) (3E10.3)\n"
        ));
        assert!(!looks_dense(""));
    }

    #[test]
    fn refuses_ragged_and_rectangular_matrices() {
        let e = read("1 2 3\n4 5\n7 8 9\n").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(
            e.message.contains("dense text matrix") && e.help.is_some(),
            "{e:?}"
        );
        let e = read("1 2\n3 4\n5 6\n").unwrap_err();
        assert!(e.message.contains("more than 2 rows"), "{e:?}");
        let e = read("1 2 3\n4 5 6\n").unwrap_err();
        assert!(e.message.contains("2 rows of 3"), "{e:?}");
        let e = read("1 x\n3 4\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, Some(3)));
    }
}
