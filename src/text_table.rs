//! Rows of the small numeric text tables users hand in (measured profiles,
//! ground-motion records): `#` comments and blank lines skipped, fields
//! split on commas (or on whitespace when a line has none), and a first
//! row with a non-numeric field taken as the header.

/// At most this many characters of a data file's field are quoted in a
/// message: enough to see a typo (`1.0e4x`), too few to print a file.
pub const MAX_QUOTED: usize = 16;

/// A field of a data file as a message may quote it (issue 23): control
/// characters dropped, cut to [`MAX_QUOTED`] characters with `…`. Only a
/// file that has identified as its format (its header or banner matched, or
/// a row before parsed) is quoted at all.
pub fn quoted(field: &str) -> String {
    let clean: String = field.chars().filter(|c| !c.is_control()).collect();
    if clean.chars().count() <= MAX_QUOTED {
        clean
    } else {
        let cut: String = clean.chars().take(MAX_QUOTED).collect();
        format!("{cut}…")
    }
}

/// One non-blank, non-comment line of a table.
#[derive(Debug, Clone, PartialEq)]
pub struct Row<'a> {
    /// Line number in the file, from 1.
    pub line: usize,
    /// The fields, trimmed.
    pub fields: Vec<&'a str>,
    /// Whether this is the header (the first row, with a non-numeric field).
    pub header: bool,
}

/// The rows of `text` in order. Allocates one small vector per row; the
/// callers budget the file's size before reading it.
pub fn rows(text: &str) -> impl Iterator<Item = Row<'_>> {
    let mut first = true;
    text.lines().enumerate().filter_map(move |(i, line)| {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return None;
        }
        let fields: Vec<&str> = if line.contains(',') {
            line.split(',').map(str::trim).collect()
        } else {
            line.split_whitespace().collect()
        };
        let header = first && fields.iter().any(|f| f.parse::<f64>().is_err());
        first = false;
        Some(Row {
            line: i + 1,
            fields,
            header,
        })
    })
}

/// Rows that are not comments, blanks — the capacity to reserve.
pub fn count(text: &str) -> usize {
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splits_skips_and_finds_the_header() {
        let found: Vec<Row> = rows("# c\nx, y\n\n1 2\n3,4\n").collect();
        assert_eq!(found.len(), 3);
        assert!(found[0].header && found[0].fields == ["x", "y"] && found[0].line == 2);
        assert!(!found[1].header && found[1].fields == ["1", "2"] && found[1].line == 4);
        assert_eq!(found[2].fields, ["3", "4"]);
        assert!(!rows("1,2\nx,y\n").nth(1).unwrap().header);
    }
}
