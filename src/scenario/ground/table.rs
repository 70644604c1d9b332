//! Ground acceleration tables in CSV: rows `time, acceleration` (s, and
//! the unit of the header or of the scenario's `units`), `#` comments and
//! blank lines skipped, time strictly increasing (the samples need not be
//! evenly spaced). A header row names the unit in brackets,
//! `time [s], acceleration [g]` (or `[m/s^2]`, `[cm/s^2]`).

use crate::scene::AccelerationUnit;

/// A parsed table.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Sample times, s.
    pub time: Vec<f64>,
    /// Accelerations in `unit`.
    pub acceleration: Vec<f64>,
    /// The unit the header states, if it does.
    pub unit: Option<AccelerationUnit>,
}

/// Why a table could not be read: (1-based line, message).
pub type TableError = (usize, String);

/// The unit in brackets of a header field, `acceleration [g]` → g.
fn bracketed_unit(field: &str, line: usize) -> Result<Option<AccelerationUnit>, TableError> {
    let (Some(open), Some(close)) = (field.find('['), field.rfind(']')) else {
        return Ok(None);
    };
    if close <= open {
        return Ok(None);
    }
    let inner = &field[open + 1..close];
    AccelerationUnit::parse(inner).map(Some).ok_or((
        line,
        "the header's acceleration unit in `[…]` is not g, m/s^2 or cm/s^2".to_string(),
    ))
}

/// Parses the CSV text; the caller has budgeted its size.
pub fn parse(text: &str) -> Result<Table, TableError> {
    let mut table = Table {
        time: Vec::new(),
        acceleration: Vec::new(),
        unit: None,
    };
    for row in crate::text_table::rows(text) {
        let (n, fields) = (row.line, row.fields);
        if row.header {
            if let Some(field) = fields.get(1) {
                table.unit = bracketed_unit(field, n)?;
            }
            if let Some(time) = fields.first()
                && let (Some(open), Some(close)) = (time.find('['), time.rfind(']'))
                && close > open
                && !matches!(time[open + 1..close].trim(), "s" | "sec" | "seconds")
            {
                return Err((
                    n,
                    "the time column's header must say seconds, `[s]`".to_string(),
                ));
            }
            continue;
        }
        if fields.len() != 2 {
            return Err((
                n,
                format!(
                    "a row has 2 columns (time, acceleration), this one has {}",
                    fields.len()
                ),
            ));
        }
        let mut values = [0.0; 2];
        for (k, field) in fields.iter().enumerate() {
            let v: f64 = field
                .parse()
                .map_err(|_| (n, not_a_number(k, field, !table.time.is_empty(), "")))?;
            if !v.is_finite() {
                return Err((n, not_a_number(k, field, true, "finite ")));
            }
            values[k] = v;
        }
        if let Some(&previous) = table.time.last()
            && values[0] <= previous
        {
            return Err((
                n,
                format!(
                    "column 1: time {} s does not exceed the previous row's {previous} s (time must increase strictly)",
                    values[0]
                ),
            ));
        }
        if let Some(&previous) = table.time.last() {
            let interval = values[0] - previous;
            let (lo, hi) = super::SAMPLING_INTERVAL;
            if !(lo..=hi).contains(&interval) {
                return Err((
                    n,
                    format!(
                        "column 1: time {} s is {interval:e} s after the previous row's \
                         {previous} s, outside the plausible sampling interval of a \
                         ground-motion record, {lo:e} to {hi} s (accelerographs sample at \
                         50–1000 Hz)",
                        values[0]
                    ),
                ));
            }
        }
        if values[0].abs() > super::RECORD_DURATION {
            return Err((
                n,
                format!(
                    "column 1: time {} s is beyond the plausible ±{} s (one day) of a \
                     ground-motion record",
                    values[0],
                    super::RECORD_DURATION
                ),
            ));
        }
        table.time.push(values[0]);
        table.acceleration.push(values[1]);
    }
    if table.time.len() < 2 {
        return Err((
            text.lines().count().max(1),
            format!(
                "a ground-motion record needs at least two rows, this file has {}",
                table.time.len()
            ),
        ));
    }
    Ok(table)
}

/// "column K: `field` is not a number", quoting the field only once a row
/// has parsed (the file identified as a table, issue 23).
pub(in crate::scenario) fn not_a_number(
    k: usize,
    field: &str,
    identified: bool,
    kind: &str,
) -> String {
    if identified {
        format!(
            "column {}: `{}` is not a {kind}number",
            k + 1,
            crate::text_table::quoted(field)
        )
    } else {
        format!(
            "column {}: the first row is not a {kind}number (is it the right file?)",
            k + 1
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_units_from_the_header() {
        let t = parse("# El Centro\ntime [s], acceleration [g]\n0, 0.01\n0.02, -0.02\n").unwrap();
        assert_eq!(t.unit, Some(AccelerationUnit::StandardGravity));
        assert_eq!(t.time, vec![0.0, 0.02]);
        let t = parse("0 1\n0.5 2\n").unwrap();
        assert_eq!(t.unit, None);
    }

    #[test]
    fn bad_rows_are_located() {
        assert_eq!(parse("t,a\n0,0\n0,1\n").unwrap_err().0, 3);
        assert_eq!(parse("0,0\n1,inf\n").unwrap_err().0, 2);
        assert_eq!(parse("0,0\n1,1,1\n").unwrap_err().0, 2);
        assert_eq!(
            parse("time [s], acceleration [ft/s^2]\n0,0\n")
                .unwrap_err()
                .0,
            1
        );
        assert_eq!(
            parse("time [ms], acceleration [g]\n0,0\n").unwrap_err().0,
            1
        );
        assert!(parse("0,0\n").is_err());
    }
}
