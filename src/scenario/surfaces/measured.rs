//! Reading a measured profile's CSV file: rows `x, elevation`,
//! `x, left, right` or `x, left, right, left_lateral, right_lateral` (m:
//! each rail's vertical and lateral position, as recording cars deliver
//! track geometry), `#` comments and blank lines skipped, an optional
//! header as the first row. Every problem is reported at the scenario's
//! `surface.file` with the CSV's own line and column in the message; the
//! file's size and row count are budgeted before anything is allocated per
//! row.

use super::super::budget::Budget;
use super::super::checker::Checker;
use super::super::data_files::{self, DataFile};
use crate::scenario::ground::not_a_number;
use crate::scenario::plausible::{SURFACE_ELEVATION, SURFACE_SOURCE, number};
use crate::scene::MeasuredProfile;

/// Why a profile's text is refused: its 1-based line, the message and a
/// `help:` line if there is something to type instead.
pub(super) type ParseError = (usize, String, Option<String>);

/// Fewest bytes a data row takes (`0,0` and a line break).
const MIN_ROW_BYTES: f64 = 4.0;

/// Reads the profile at `path`; `None` after reporting why not.
pub(super) fn read(
    data: &DataFile,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Option<MeasuredProfile> {
    const AT: &str = "surface.file";
    let (shown, size) = (&data.shown, data.size);
    // At most size/4 rows: budget them before reading the file whole.
    let most_rows = (size as f64 / MIN_ROW_BYTES).ceil();
    if !budget.check(
        ck,
        AT,
        "profile_points",
        &format!(
            "rows the measured profile {shown} may hold ({size} bytes, 4 bytes a row at least)"
        ),
        most_rows,
    ) {
        return None;
    }
    let text = match data_files::read_text(data, ck) {
        Ok(text) => text,
        Err(message) => {
            ck.error(AT, message);
            return None;
        }
    };
    match parse(&text) {
        Ok(p) => Some(p),
        Err((line, message, help)) => {
            ck.error_with_help(AT, format!("{shown}:{line}: {message}"), help);
            None
        }
    }
}

/// Parses the CSV text; the values must be finite and within
/// ±[`SURFACE_ELEVATION`] (a profile is the irregularity about the design
/// line, [`crate::scenario::plausible`]).
pub(super) fn parse(text: &str) -> Result<MeasuredProfile, ParseError> {
    let rows = crate::text_table::count(text);
    let mut x = Vec::with_capacity(rows);
    let mut left = Vec::with_capacity(rows);
    let mut right: Vec<f64> = Vec::new();
    let (mut left_lateral, mut right_lateral): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut columns = None;
    for row in crate::text_table::rows(text) {
        let (n, fields) = (row.line, row.fields);
        if row.header {
            continue;
        }
        let count = fields.len();
        if !matches!(count, 2 | 3 | 5) {
            return Err((
                n,
                format!(
                    "a row has 2 columns (x, elevation), 3 (x, left, right) or 5 (x, left, \
                     right, left_lateral, right_lateral), this one has {count}"
                ),
                None,
            ));
        }
        match columns {
            None => {
                columns = Some(count);
                if count >= 3 {
                    right.reserve(rows);
                }
                if count == 5 {
                    left_lateral.reserve(rows);
                    right_lateral.reserve(rows);
                }
            }
            Some(c) if c != count => {
                return Err((
                    n,
                    format!("this row has {count} columns, the rows above have {c}"),
                    None,
                ));
            }
            Some(_) => {}
        }
        let mut values = [0.0; 5];
        for (k, field) in fields.iter().enumerate() {
            let v: f64 = field
                .parse()
                .map_err(|_| (n, not_a_number(k, field, !x.is_empty(), ""), None))?;
            if !v.is_finite() {
                return Err((n, not_a_number(k, field, true, "finite "), None));
            }
            if k > 0 && v.abs() > SURFACE_ELEVATION {
                return Err((
                    n,
                    format!(
                        "column {}: {} of {} m is outside the physically plausible range {} to \
                         {} m ({SURFACE_SOURCE})",
                        k + 1,
                        column_name(count, k),
                        number(v),
                        -SURFACE_ELEVATION,
                        SURFACE_ELEVATION
                    ),
                    Some(
                        "the profile is the irregularity about the design line, in metres \
                         (20 mm is 0.02): remove its grade and offset, or convert from mm"
                            .into(),
                    ),
                ));
            }
            values[k] = v;
        }
        if let Some(&prev) = x.last()
            && values[0] <= prev
        {
            return Err((
                n,
                format!(
                    "column 1: x = {} does not exceed the previous row's {prev} (x must increase strictly)",
                    values[0]
                ),
                None,
            ));
        }
        x.push(values[0]);
        left.push(values[1]);
        if count >= 3 {
            right.push(values[2]);
        }
        if count == 5 {
            left_lateral.push(values[3]);
            right_lateral.push(values[4]);
        }
    }
    if x.len() < 2 {
        return Err((
            text.lines().count().max(1),
            format!(
                "a measured profile needs at least two rows, this file has {}",
                x.len()
            ),
            None,
        ));
    }
    Ok(MeasuredProfile {
        x,
        left,
        right: (columns >= Some(3)).then_some(right),
        lateral: (columns == Some(5)).then_some((left_lateral, right_lateral)),
    })
}

/// What column `k` (0-based, not x) of a `count`-column profile holds.
fn column_name(count: usize, k: usize) -> &'static str {
    match (count, k) {
        (2, _) => "an elevation",
        (_, 1) => "the left rail's elevation",
        (_, 2) => "the right rail's elevation",
        (_, 3) => "the left rail's lateral position (its deviation from the design line)",
        _ => "the right rail's lateral position (its deviation from the design line)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_header_comments_and_two_rails() {
        let p = parse("# track 2\nx,left,right\n0, 0.001, 0.002\n\n1.5,0,-0.001\n").unwrap();
        assert_eq!(p.x, vec![0.0, 1.5]);
        assert_eq!(p.left, vec![0.001, 0.0]);
        assert_eq!(p.right, Some(vec![0.002, -0.001]));
        let p = parse("0 0\n1 1e-3\n").unwrap();
        assert_eq!(p.right, None);
        assert_eq!(p.lateral, None);
    }

    #[test]
    fn reads_both_rails_vertical_and_lateral() {
        let p = parse(
            "x,left,right,left_lateral,right_lateral\n0,1e-3,2e-3,3e-3,4e-3\n2,0,0,-1e-3,-2e-3\n",
        )
        .unwrap();
        assert_eq!(p.x, vec![0.0, 2.0]);
        assert_eq!(p.right, Some(vec![2e-3, 0.0]));
        assert_eq!(p.lateral, Some((vec![3e-3, -1e-3], vec![4e-3, -2e-3])));
    }

    #[test]
    fn bad_rows_are_located() {
        assert_eq!(parse("x,r\n0,0\n1,nan\n").unwrap_err().0, 3);
        assert_eq!(parse("0,0\n1,abc\n").unwrap_err().0, 2);
        assert_eq!(parse("0,0\n0,1\n").unwrap_err().0, 2);
        assert_eq!(parse("0,0\n1,1,1\n").unwrap_err().0, 2);
        // Four columns: neither per-rail vertical nor the recording car's five.
        let (line, message, _) = parse("0,0,0,0\n").unwrap_err();
        assert_eq!(line, 1);
        assert!(
            message.contains("5 (x, left, right, left_lateral, right_lateral)"),
            "{message}"
        );
        // A bad lateral value is named by its column.
        let (line, message, _) = parse("0,0,0,0,0\n1,0,0,0,x\n").unwrap_err();
        assert_eq!(line, 2);
        assert!(message.contains("column 5"), "{message}");
        assert_eq!(parse("0,0,0,0,0\n1,0,0,0\n").unwrap_err().0, 2);
        assert!(parse("0,0\n").is_err());
    }
}
