//! Moving scanner errors that saphyr reports late (on the line after the
//! mistake, or past a tag) back to their cause.

use super::Location;

/// The text of line `line` (1-based), without its break; lines end at
/// `\n`, `\r\n` or a lone `\r`, as the scanner counts them.
fn line_text(source: &str, line: usize) -> Option<&str> {
    lines(source).nth(line.checked_sub(1)?)
}

/// The lines of `source`, split at `\n`, `\r\n` and lone `\r`.
fn lines(source: &str) -> impl Iterator<Item = &str> {
    source
        .split('\n')
        .flat_map(|l| l.strip_suffix('\r').unwrap_or(l).split('\r'))
}

/// Where the tag of a node written at `loc` starts. saphyr marks a tagged
/// node where its content starts, which for a block collection is the
/// line after the tag (`bridge: !custom` then `  type: beam`, or `- !tag`
/// then the item's first key): from the node back, over white space, line
/// breaks, comments and an anchor, the token before it is the tag. Without
/// one there (it cannot be found), `loc`.
pub(super) fn tag_start(source: &str, loc: Location) -> Location {
    let lines: Vec<&str> = lines(source).take(loc.line).collect();
    if lines.len() < loc.line {
        return loc;
    }
    for line in (1..=loc.line).rev() {
        let text: Vec<char> = if line == loc.line {
            lines[line - 1]
                .chars()
                .take(loc.col.saturating_sub(1))
                .collect()
        } else {
            lines[line - 1].chars().collect()
        };
        let text = without_comment(&text);
        let mut end = text.len();
        // The tokens of the line from its end: anchors are skipped, a tag
        // is the answer, anything else means the tag is not found.
        while end > 0 {
            while end > 0 && text[end - 1].is_whitespace() {
                end -= 1;
            }
            if end == 0 {
                break;
            }
            let mut start = end;
            while start > 0 && !is_separator(text[start - 1]) {
                start -= 1;
            }
            if start == end {
                // A flow indicator (`[`, `{`, `,`) or a block one (`-`, `:`
                // are not separators): nothing before it is the tag.
                return loc;
            }
            match text[start] {
                '!' => {
                    return Location {
                        line,
                        col: start + 1,
                    };
                }
                '&' => end = start,
                _ => {
                    // A tag glued to a flow indicator (`[!foo x`): its `!`.
                    return match text[start..end].iter().position(|&c| c == '!') {
                        Some(i) if line == loc.line => Location {
                            line,
                            col: start + i + 1,
                        },
                        _ => loc,
                    };
                }
            }
        }
    }
    loc
}

/// Whether `c` ends a token before a tag: white space or a flow indicator.
fn is_separator(c: char) -> bool {
    c.is_whitespace() || matches!(c, '[' | '{' | ',')
}

/// `text` up to a comment (a `#` at the start or after white space; quotes
/// are not followed, which only matters on a line that holds no tag).
fn without_comment(text: &[char]) -> &[char] {
    let hash = (0..text.len()).find(|&i| text[i] == '#' && (i == 0 || text[i - 1].is_whitespace()));
    &text[..hash.unwrap_or(text.len())]
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
