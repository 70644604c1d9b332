//! User-facing rendering of a located error, in the style of rustc/cargo:
//!
//! ```text
//! scenarios/bad.yaml:5:3: unknown field `sprung_mas`, expected `sprung_mass` or `speed`
//!   |
//! 5 |   sprung_mas: 4000.0
//!   |   ^
//! ```
//!
//! The first line is `FILE:LINE:COL: message` so editors and terminals can
//! jump to the spot; the excerpt shows the user what we mean without them
//! having to count columns.

use super::yaml::Location;

/// Width a tab is expanded to in the excerpt, so the caret lines up.
const TAB_WIDTH: usize = 4;

/// One located error in a scenario file, rendered like rustc/cargo.
#[derive(Debug, Clone)]
pub struct Diagnostic {
    pub file: String,
    pub loc: Location,
    pub message: String,
    /// The source line `loc.line` (without its line break), if it exists.
    pub source_line: Option<String>,
}

impl Diagnostic {
    pub fn new(
        file: impl Into<String>,
        source: &str,
        loc: Location,
        message: impl Into<String>,
    ) -> Self {
        Diagnostic {
            file: file.into(),
            loc,
            message: message.into(),
            source_line: source_line(source, loc.line),
        }
    }
}

/// Line `line` (1-based) of `source`, splitting on `\n`, `\r\n` and lone `\r`
/// like the YAML scanner does. A line just after a final line break exists
/// (and is empty): errors at the end of the file point there.
fn source_line(source: &str, line: usize) -> Option<String> {
    let mut rest = source;
    for _ in 1..line.max(1) {
        let brk = rest.find(['\n', '\r'])?;
        let width = if rest[brk..].starts_with("\r\n") {
            2
        } else {
            1
        };
        rest = &rest[brk + width..];
    }
    let end = rest.find(['\n', '\r']).unwrap_or(rest.len());
    Some(rest[..end].to_owned())
}

impl std::fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Location { line, col } = self.loc;
        write!(f, "{}:{line}:{col}: {}", self.file, self.message)?;
        let Some(text) = &self.source_line else {
            return Ok(());
        };
        let gutter = " ".repeat(line.to_string().len());
        let mut shown = String::new();
        let mut caret_pad = 0;
        for (i, c) in text.chars().enumerate() {
            let width = if c == '\t' { TAB_WIDTH } else { 1 };
            if i + 1 < col {
                caret_pad += width;
            }
            match c {
                '\t' => shown.push_str(&" ".repeat(TAB_WIDTH)),
                c if c.is_control() => shown.push(' '),
                c => shown.push(c),
            }
        }
        // Columns past the end of the line (e.g. at EOF) count one per char.
        caret_pad += col.saturating_sub(1).saturating_sub(text.chars().count());
        let shown = shown.trim_end();
        writeln!(f)?;
        writeln!(f, "{gutter} |")?;
        if shown.is_empty() {
            writeln!(f, "{line} |")?;
        } else {
            writeln!(f, "{line} | {shown}")?;
        }
        write!(f, "{gutter} | {}^", " ".repeat(caret_pad))
    }
}

impl std::error::Error for Diagnostic {}

#[cfg(test)]
mod tests {
    use super::*;

    fn render(source: &str, line: usize, col: usize, msg: &str) -> String {
        Diagnostic::new("scenarios/bad.yaml", source, Location { line, col }, msg).to_string()
    }

    #[test]
    fn renders_like_rustc() {
        let src = "name: x\nbridge: {}\nvehicles:\n  - type: oscillator\n  sprung_mas: 4000.0\n";
        let got = render(
            src,
            5,
            3,
            "unknown field `sprung_mas`, expected one of `sprung_mass`, `unsprung_mass`",
        );
        let want = "\
scenarios/bad.yaml:5:3: unknown field `sprung_mas`, expected one of `sprung_mass`, `unsprung_mass`
  |
5 |   sprung_mas: 4000.0
  |   ^";
        assert_eq!(got, want);
    }

    #[test]
    fn gutter_grows_with_line_number() {
        let src = format!("{}key: value\n", "a: 1\n".repeat(11));
        let want = "f.yaml:12:6: bad\n   |\n12 | key: value\n   |      ^";
        let got = Diagnostic::new("f.yaml", &src, Location { line: 12, col: 6 }, "bad").to_string();
        assert_eq!(got, want);
    }

    #[test]
    fn tabs_expand_and_caret_follows() {
        let got = render("a:\t\tx\n", 1, 5, "m");
        assert_eq!(
            got,
            "scenarios/bad.yaml:1:5: m\n  |\n1 | a:        x\n  |           ^"
        );
    }

    #[test]
    fn multibyte_columns_count_chars() {
        let got = render("nämé: ü\n", 1, 7, "m");
        assert_eq!(
            got,
            "scenarios/bad.yaml:1:7: m\n  |\n1 | nämé: ü\n  |       ^"
        );
    }

    #[test]
    fn crlf_and_lone_cr_line_breaks() {
        let src = "a: 1\r\nb: 2\r\nc: 3\rd: 4";
        assert_eq!(
            Diagnostic::new("f", src, Location { line: 2, col: 4 }, "m")
                .source_line
                .as_deref(),
            Some("b: 2")
        );
        assert_eq!(
            Diagnostic::new("f", src, Location { line: 4, col: 1 }, "m")
                .source_line
                .as_deref(),
            Some("d: 4")
        );
        assert_eq!(
            render(src, 2, 4, "m"),
            "scenarios/bad.yaml:2:4: m\n  |\n2 | b: 2\n  |    ^"
        );
    }

    #[test]
    fn locations_at_and_past_the_end() {
        // The empty line after the final newline: where EOF errors land.
        assert_eq!(
            render("a: [1,\n", 2, 1, "m"),
            "scenarios/bad.yaml:2:1: m\n  |\n2 |\n  | ^"
        );
        // Past the end of a line: the caret still goes to the column.
        assert_eq!(
            render("ab", 1, 5, "m"),
            "scenarios/bad.yaml:1:5: m\n  |\n1 | ab\n  |     ^"
        );
        // Lines that do not exist: header only.
        assert_eq!(render("a: 1\n", 9, 1, "m"), "scenarios/bad.yaml:9:1: m");
        assert_eq!(
            render("", 1, 1, "m"),
            "scenarios/bad.yaml:1:1: m\n  |\n1 |\n  | ^"
        );
        assert_eq!(render("", 2, 1, "m"), "scenarios/bad.yaml:2:1: m");
    }

    #[test]
    fn works_with_parse_and_deserialize_errors() {
        use super::super::{de::from_node, yaml::parse};
        let src = "a: 1\na: 2\n";
        let e = parse(src).unwrap_err();
        let d = Diagnostic::new("s.yaml", src, e.loc, e.message);
        assert_eq!(
            d.to_string(),
            "s.yaml:2:1: duplicate key `a` (first defined at line 1)\n  |\n2 | a: 2\n  | ^"
        );
        let src = "- 1\n- x\n";
        let e = from_node::<Vec<f64>>(&parse(src).unwrap().unwrap()).unwrap_err();
        let d = Diagnostic::new("s.yaml", src, e.loc.unwrap(), e.message);
        let want = "s.yaml:2:3: invalid type: string \"x\", expected f64\n  |\n2 | - x\n  |   ^";
        assert_eq!(d.to_string(), want);
        let boxed: Box<dyn std::error::Error> = Box::new(d);
        assert!(boxed.to_string().starts_with("s.yaml:2:3: "));
    }
}
