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
    /// A suggestion printed under the excerpt as rustc's `= help:` line
    /// (`did you mean `stiffness`?`), if one is close enough.
    pub help: Option<String>,
    /// For a scene given as data rather than text
    /// ([`super::load_value`]): the key path of the place
    /// (`vehicles[0].speed`, empty for the scene as a whole); `loc` is
    /// then 0:0, there being no line or column.
    pub path: Option<String>,
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
            source_line: excerpt(source_line(source, loc.line).as_deref()),
            help: None,
            path: None,
        }
    }

    /// A diagnostic at a key path of a scene given as data (no text).
    pub fn at_path(
        file: impl Into<String>,
        path: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        Diagnostic {
            file: file.into(),
            loc: Location::default(),
            message: message.into(),
            source_line: None,
            help: None,
            path: Some(path.into()),
        }
    }

    /// The same diagnostic with a `help:` line.
    pub fn with_help(mut self, help: Option<String>) -> Self {
        self.help = help;
        self
    }
}

/// The candidate closest to `word` if it is close enough to be a likely
/// misspelling: at most a third of the word's characters edited (at least
/// one), by the optimal string alignment distance (a swap of two adjacent
/// letters counts once, as typists make them), ties to the first listed.
pub fn closest<'c>(word: &str, candidates: impl IntoIterator<Item = &'c str>) -> Option<&'c str> {
    let limit = (word.chars().count() / 3).max(1);
    candidates
        .into_iter()
        .filter(|c| *c != word)
        .map(|c| (strsim::osa_distance(word, c), c))
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// rustc's wording of a suggestion.
pub fn did_you_mean<'c>(
    word: &str,
    candidates: impl IntoIterator<Item = &'c str>,
) -> Option<String> {
    closest(word, candidates).map(|c| format!("did you mean `{c}`?"))
}

/// The suggestion for serde's `unknown field `x`, expected …` and `unknown
/// variant `x`, expected …` messages: the names it lists in backticks.
pub fn suggest_for_serde(message: &str) -> Option<String> {
    let rest = message
        .strip_prefix("unknown field `")
        .or_else(|| message.strip_prefix("unknown variant `"))?;
    let (word, listed) = rest.split_once('`')?;
    let listed = listed.split_once("expected")?.1;
    let names = listed.split('`').skip(1).step_by(2);
    did_you_mean(word, names)
}

/// Where each line of a source text starts, so that many diagnostics cost
/// a binary search each instead of a scan of the file each (20,000 errors
/// in a 1.5 MB file were quadratic).
pub struct Lines<'a> {
    source: &'a str,
    /// Byte offset of the start of each line; line breaks as the YAML
    /// scanner counts them (`\n`, `\r\n`, lone `\r`).
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    pub fn new(source: &'a str) -> Self {
        let bytes = source.as_bytes();
        let mut starts = vec![0];
        let mut i = 0;
        while i < bytes.len() {
            match bytes[i] {
                b'\n' => starts.push(i + 1),
                b'\r' if bytes.get(i + 1) == Some(&b'\n') => {
                    starts.push(i + 2);
                    i += 1;
                }
                b'\r' => starts.push(i + 1),
                _ => {}
            }
            i += 1;
        }
        Lines { source, starts }
    }

    /// Line `line` (1-based) without its line break, if it exists.
    pub fn line(&self, line: usize) -> Option<&'a str> {
        let start = *self.starts.get(line.max(1) - 1)?;
        let rest = &self.source[start..];
        let end = rest.find(['\n', '\r']).unwrap_or(rest.len());
        Some(&rest[..end])
    }

    /// A diagnostic at `loc` with its source line.
    pub fn diagnostic(
        &self,
        file: impl Into<String>,
        loc: Location,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic {
            file: file.into(),
            loc,
            message: message.into(),
            source_line: excerpt(self.line(loc.line)),
            help: None,
            path: None,
        }
    }
}

/// Longest source line shown under a diagnostic, in bytes; a longer one
/// (a minified or hostile file) is not copied into every diagnostic.
const MAX_EXCERPT: usize = 400;

fn excerpt(line: Option<&str>) -> Option<String> {
    line.filter(|l| l.len() <= MAX_EXCERPT).map(str::to_owned)
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
        // The message and help quote keys, units, names and file names of
        // the scene, which may hold any character a YAML escape can write
        // (`"\e[2J"`): shown escaped, never raw (issue 39.3).
        let safe = crate::guarded_file::escape_controls;
        let (file, message) = (safe(&self.file), safe(&self.message));
        let help = self.help.as_deref().map(safe);
        match self.path.as_deref() {
            // A scene given as data: its place is a key path.
            Some("") => write!(f, "{file}: {message}")?,
            Some(path) => write!(f, "{file}: {}: {message}", safe(path))?,
            None => write!(f, "{file}:{line}:{col}: {message}")?,
        }
        let Some(text) = &self.source_line else {
            if let Some(help) = &help {
                write!(f, "\n  = help: {help}")?;
            }
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
        write!(f, "{gutter} | {}^", " ".repeat(caret_pad))?;
        if let Some(help) = &help {
            write!(f, "\n{gutter} = help: {help}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Diagnostic {}

#[cfg(test)]
mod tests;

/// `text` with its control characters (C0, DEL, C1, and U+FFFE/U+FFFF) shown
/// escaped as rustc shows them (`\u{1b}`, `\n`), so that text from a file
/// can neither repaint the reader's terminal nor break a line.
pub fn escaped(text: &str) -> String {
    if !text.chars().any(needs_escape) {
        return text.to_string();
    }
    text.chars()
        .map(|c| {
            if needs_escape(c) {
                c.escape_debug().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

fn needs_escape(c: char) -> bool {
    c.is_control() || c == '\u{fffe}' || c == '\u{ffff}'
}
