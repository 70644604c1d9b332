//! Moving scanner errors that saphyr reports late (on the line after the
//! mistake, or past a tag) back to their cause.

use super::Location;

/// The text of line `line` (1-based), without its break.
fn line_text(source: &str, line: usize) -> Option<&str> {
    source
        .split('\n')
        .nth(line.checked_sub(1)?)
        .map(|l| l.trim_end_matches('\r'))
}

/// Where the tag of a node written at `loc` starts: the last `!` before it
/// on the same line (the tag and the node are on one line in a scenario).
pub(super) fn tag_start(source: &str, loc: Location) -> Location {
    let Some(text) = line_text(source, loc.line) else {
        return loc;
    };
    let before: Vec<char> = text.chars().take(loc.col.saturating_sub(1)).collect();
    match before.iter().rposition(|&c| c == '!') {
        // Back to the first `!` of a `!!tag`.
        Some(mut i) => {
            while i > 0 && before[i - 1] == '!' {
                i -= 1;
            }
            Location {
                line: loc.line,
                col: i + 1,
            }
        }
        None => loc,
    }
}

/// saphyr reports some mistakes where it notices them, on the line after
/// the one at fault; move the location back to the cause and say what it
/// is:
/// * a key without `:` (or with `:` and no space, `spans:[1]`) is seen as a
///   plain scalar that continues onto the next line, and the error comes at
///   the next key: blame the previous content line if it has no `: `;
/// * a tab in the indentation of a line is reported at the end of the
///   previous scalar: blame the first tab-indented line from there on.
pub(super) fn relocate(source: &str, loc: Location, info: &str) -> (Location, &'static str) {
    if info.contains("tab") {
        for line in loc.line..=loc.line + 1 {
            let Some(text) = line_text(source, line) else {
                break;
            };
            let indent: Vec<char> = text.chars().take_while(|c| c.is_whitespace()).collect();
            if let Some(i) = indent.iter().position(|&c| c == '\t') {
                let at = Location { line, col: i + 1 };
                return (
                    at,
                    " (indent with spaces: YAML forbids tabs in indentation)",
                );
            }
        }
        return (loc, "");
    }
    if info.contains("simple key expect ':'") || info.contains("could not find expected ':'") {
        let content = |l: usize| {
            line_text(source, l).filter(|t| {
                let t = t.trim();
                !t.is_empty() && !t.starts_with('#')
            })
        };
        let previous = (1..loc.line).rev().find_map(|l| content(l).map(|t| (l, t)));
        if let Some((line, text)) = previous {
            let body = text.split(" #").next().unwrap_or(text).trim_end();
            let keyed = body.contains(": ") || body.ends_with(':');
            if !keyed {
                let col = text.chars().take_while(|c| c.is_whitespace()).count() + 1;
                let hint = if body.contains(':') {
                    " (a key's `:` needs a space after it, as in `key: value`)"
                } else {
                    " (this line has no `:` after its key)"
                };
                return (Location { line, col }, hint);
            }
        }
    }
    (loc, "")
}
