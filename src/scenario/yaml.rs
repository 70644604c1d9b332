//! A position-marked YAML tree built from `saphyr-parser` events.
//!
//! Off-the-shelf serde YAML front ends buffer internally tagged enums and lose
//! source positions on the way, so an error inside a `bridge:` section would be
//! reported at the wrong place. We therefore parse into our own tree in which
//! every node (and every mapping key) remembers where it was written, and
//! deserialize from that tree (see `super::de`).
//!
//! The tree deliberately supports only the YAML subset a scenario file needs:
//! one document, no tags, no merge keys, no complex keys. Everything else is
//! rejected with a located [`SyntaxError`] instead of being half-supported.

use saphyr_parser::{Event, Marker, Parser, ScalarStyle};
use std::collections::HashMap;

/// Deepest nesting we accept. Deserialization and `Drop` recurse once per
/// level, so a cap keeps hostile inputs like `[[[[...` from blowing the stack.
pub(crate) const MAX_DEPTH: usize = 128;
/// Upper bound on nodes after alias expansion, against "billion laughs" inputs.
pub(crate) const MAX_NODES: usize = 1_000_000;

/// 1-based line and column of a node or key in the source text.
///
/// Columns count Unicode scalar values (chars), not bytes, like rustc.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Default)]
pub struct Location {
    pub line: usize,
    pub col: usize,
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.line, self.col)
    }
}

impl Location {
    /// saphyr markers have a 1-based line but a 0-based column.
    fn from_marker(m: &Marker) -> Self {
        Location {
            line: m.line().max(1),
            col: m.col() + 1,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum NodeKind {
    /// `~`, `null`, `Null`, `NULL` or an empty plain scalar.
    Null,
    /// `plain` is false for quoted and block scalars, which are always strings.
    Scalar {
        text: String,
        plain: bool,
    },
    Sequence(Vec<Node>),
    /// (key node, value node) pairs in source order.
    Mapping(Vec<(Node, Node)>),
    /// Never parsed from text: stands, at the place of a value that has a
    /// type error, for a required field's value (the type checker puts it
    /// there, `super::check_types`), so that the rest of its mapping is
    /// still read and checked. It deserialises as the simplest value of
    /// whatever type is asked for (1, `false`, an empty string, an enum's
    /// first variant); no check may blame it.
    Placeholder,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    pub kind: NodeKind,
    pub loc: Location,
}

#[derive(Debug, Clone, thiserror::Error)]
#[error("{message}")]
pub struct SyntaxError {
    pub loc: Location,
    pub message: String,
}

/// One step of a path into the tree, see [`Node::locate`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathSeg<'a> {
    Key(&'a str),
    Index(usize),
}

/// A plain scalar resolved with the YAML 1.2 core schema.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Resolved<'a> {
    Null,
    Bool(bool),
    Int(i128),
    /// Integer syntax whose value does not fit in an `i128`.
    IntOverflow,
    /// May be non-finite (`.inf`, `.nan`, or an overflowing literal like `1e400`).
    Float(f64),
    Str(&'a str),
}

impl Node {
    /// The value stored under `key` if `self` is a mapping with that (scalar) key.
    pub fn get(&self, key: &str) -> Option<&Node> {
        self.entry(key).map(|(_, v)| v)
    }

    /// Where `key` itself is written, if `self` is a mapping containing it.
    pub fn key_loc(&self, key: &str) -> Option<Location> {
        self.entry(key).map(|(k, _)| k.loc)
    }

    fn entry(&self, key: &str) -> Option<&(Node, Node)> {
        match &self.kind {
            NodeKind::Mapping(entries) => entries.iter().find(|(k, _)| k.as_str() == Some(key)),
            _ => None,
        }
    }

    /// Text of a scalar (plain or quoted); `None` for null and collections.
    pub fn as_str(&self) -> Option<&str> {
        match &self.kind {
            NodeKind::Scalar { text, .. } => Some(text),
            _ => None,
        }
    }

    /// The node at `path`, if the tree has it.
    pub fn at(&self, path: &[PathSeg]) -> Option<&Node> {
        let mut node = self;
        for seg in path {
            node = match (seg, &node.kind) {
                (PathSeg::Key(k), NodeKind::Mapping(_)) => node.get(k)?,
                (PathSeg::Index(i), NodeKind::Sequence(items)) => items.get(*i)?,
                _ => return None,
            };
        }
        Some(node)
    }

    /// Whether a [`NodeKind::Placeholder`] is this node or inside it.
    pub fn holds_placeholder(&self) -> bool {
        match &self.kind {
            NodeKind::Placeholder => true,
            NodeKind::Sequence(items) => items.iter().any(Node::holds_placeholder),
            NodeKind::Mapping(entries) => entries.iter().any(|(_, v)| v.holds_placeholder()),
            NodeKind::Null | NodeKind::Scalar { .. } => false,
        }
    }

    /// Location of the deepest existing node along `path`.
    ///
    /// Semantic checks that run after deserialization know *which* field is
    /// wrong but not where it was written; this maps the field path back to the
    /// source. If a step is missing we stop at the enclosing collection, which
    /// is where the user would have to add the entry.
    pub fn locate(&self, path: &[PathSeg]) -> Location {
        let mut node = self;
        for seg in path {
            let next = match (seg, &node.kind) {
                (PathSeg::Key(k), NodeKind::Mapping(_)) => node.get(k),
                (PathSeg::Index(i), NodeKind::Sequence(items)) => items.get(*i),
                _ => None,
            };
            match next {
                Some(n) => node = n,
                None => break,
            }
        }
        node.loc
    }

    /// Convert to JSON with core-schema resolution, for JSON Schema validation.
    ///
    /// Non-finite floats have no JSON representation and become their source
    /// text as a string; null keys become the key `"null"`.
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::Value;
        match &self.kind {
            NodeKind::Null | NodeKind::Placeholder => Value::Null,
            NodeKind::Scalar { text, plain: false } => Value::String(text.clone()),
            NodeKind::Scalar { text, plain: true } => match resolve_plain(text) {
                Resolved::Null => Value::Null,
                Resolved::Bool(b) => Value::Bool(b),
                Resolved::Int(i) => {
                    if let Ok(v) = i64::try_from(i) {
                        Value::from(v)
                    } else if let Ok(v) = u64::try_from(i) {
                        Value::from(v)
                    } else {
                        float_json(i as f64, text)
                    }
                }
                Resolved::IntOverflow => float_json(text.parse().unwrap_or(f64::NAN), text),
                Resolved::Float(f) => float_json(f, text),
                Resolved::Str(s) => Value::String(s.to_owned()),
            },
            NodeKind::Sequence(items) => Value::Array(items.iter().map(Node::to_json).collect()),
            NodeKind::Mapping(entries) => Value::Object(
                entries
                    .iter()
                    .map(|(k, v)| (k.as_str().unwrap_or("null").to_owned(), v.to_json()))
                    .collect(),
            ),
        }
    }
}

/// Parse one YAML document. `Ok(None)` for an empty/whitespace/comment-only document.
pub fn parse(source: &str) -> Result<Option<Node>, SyntaxError> {
    match parse_once(source, None) {
        Err(Failure::TabAfterColon(_)) => parse_untabbed(source),
        Err(Failure::Syntax(e)) => Err(e),
        Ok(tree) => Ok(tree),
    }
}

/// saphyr refuses a tab between a value's `:` and a value that starts with
/// a letter, digit or `-` (`speed:\t25`), which YAML 1.2 allows (a tab is
/// separation white space there, production s-separate-in-line). Every tab
/// in the white space after a `:` that content follows is replaced by a
/// space (one byte for one, so every location stays where it was) and the
/// text parsed again. A `:` inside a quoted or block scalar is content, not
/// an indicator: if a replaced tab falls inside one, the text is instead
/// repaired one scanner error at a time, each reparse bounded.
fn parse_untabbed(source: &str) -> Result<Option<Node>, SyntaxError> {
    let (patched, replaced) = untab_all(source);
    let mut quoted = Vec::new();
    match parse_once(&patched, Some(&mut quoted)) {
        Ok(tree) => {
            let inside = |&i: &usize| quoted.iter().any(|&(a, b)| a <= i && i < b);
            if !replaced.iter().any(inside) {
                return Ok(tree);
            }
        }
        Err(Failure::Syntax(e)) => return Err(e),
        Err(Failure::TabAfterColon(_)) => {}
    }
    // One repair per scanner error; the characters scanned over all passes
    // are bounded so that a hostile file stays fast.
    const SCAN_BUDGET: usize = 4 << 20;
    let mut text = source.to_owned();
    let mut scanned = 0;
    loop {
        match parse_once(&text, None) {
            Err(Failure::TabAfterColon(at)) => {
                scanned += at.max(1);
                if scanned > SCAN_BUDGET || !untab_after_colon(&mut text, at) {
                    return Err(err(
                        byte_location(source, at),
                        "YAML syntax error: ':' must be followed by a space here (too many tabs \
                         after `:` to repair)",
                    ));
                }
            }
            Err(Failure::Syntax(e)) => return Err(e),
            Ok(tree) => return Ok(tree),
        }
    }
}

/// `text` with every tab replaced by a space in the white space that
/// follows a `:` and precedes content on the same line; and the character
/// indices replaced.
fn untab_all(text: &str) -> (String, Vec<usize>) {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut replaced = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        out.push(chars[i]);
        if chars[i] == ':' {
            let run = chars[i + 1..]
                .iter()
                .take_while(|&&c| c == ' ' || c == '\t')
                .count();
            let next = chars.get(i + 1 + run).copied();
            let content = next.is_some_and(|c| !matches!(c, '\n' | '\r' | '#'));
            for (k, &c) in chars.iter().enumerate().skip(i + 1).take(run) {
                if content && c == '\t' {
                    out.push(' ');
                    replaced.push(k);
                } else {
                    out.push(c);
                }
            }
            i += run;
        }
        i += 1;
    }
    (out, replaced)
}

/// Why one parse stopped.
enum Failure {
    /// A tab after a value's `:`, the scanner stopped at byte `.0` (after it).
    TabAfterColon(usize),
    Syntax(SyntaxError),
}

/// Replaces by spaces the tabs between the `:` and byte `at` of `text`, where
/// saphyr stopped after them. `false` if there are none (nothing to repair).
fn untab_after_colon(text: &mut String, at: usize) -> bool {
    let Some(head) = text.get(..at) else {
        return false;
    };
    let run = head.len() - head.trim_end_matches([' ', '\t']).len();
    let start = at - run;
    if run == 0 || !text[..start].ends_with(':') || !text[start..at].contains('\t') {
        return false;
    }
    let spaces = " ".repeat(run);
    text.replace_range(start..at, &spaces);
    true
}

/// The line and column of byte `at` of `text` (lines broken like the scanner).
fn byte_location(text: &str, at: usize) -> Location {
    let before = text.get(..at).unwrap_or(text);
    let line = 1 + before.matches('\n').count() + before.matches('\r').count()
        - before.matches("\r\n").count();
    let start = before.rfind(['\n', '\r']).map_or(0, |i| i + 1);
    Location {
        line,
        col: before[start..].chars().count() + 1,
    }
}

/// One parse of `source`; `quoted` collects the character spans of its
/// quoted and block scalars.
fn parse_once(
    source: &str,
    mut quoted: Option<&mut Vec<(usize, usize)>>,
) -> Result<Option<Node>, Failure> {
    let mut parser = Parser::new_from_str(source);
    let mut builder = Builder {
        source,
        stack: Vec::new(),
        anchors: HashMap::new(),
        root: None,
        nodes: 0,
        documents: 0,
    };
    while let Some(next) = parser.next_event() {
        match next {
            Ok((ev, span)) => {
                if let (Some(q), Event::Scalar(_, style, _, _)) = (quoted.as_deref_mut(), &ev)
                    && *style != ScalarStyle::Plain
                {
                    q.push((
                        span.start.index(),
                        span.end.index().max(span.start.index() + 1),
                    ));
                }
                builder.event(ev, &span).map_err(Failure::Syntax)?
            }
            Err(e) if e.info() == "':' must be followed by a valid YAML whitespace" => {
                return Err(Failure::TabAfterColon(char_to_byte(
                    source,
                    e.marker().index(),
                )));
            }
            Err(e) => {
                let loc = Location::from_marker(e.marker());
                let (loc, hint) = relocate(source, loc, e.info());
                let mut message = builder.scan_error_message(e.info());
                message.push_str(hint);
                return Err(Failure::Syntax(err(loc, message)));
            }
        }
    }
    Ok(builder.root.map(|b| b.node))
}

/// The byte offset of the `chars`-th character of `text` (saphyr's marker
/// index counts characters).
fn char_to_byte(text: &str, chars: usize) -> usize {
    text.char_indices()
        .nth(chars)
        .map_or(text.len(), |(i, _)| i)
}

mod builder;
mod relocate;
mod scalar;
use builder::{Builder, err};
use relocate::{relocate, tag_start};
use scalar::float_json;
pub use scalar::resolve_plain;

#[cfg(test)]
mod tests;
