//! The diagnostics collector every section's checks report through: a
//! problem at a key's path becomes a located diagnostic (file, line,
//! column), and the checks every section shares.

use super::diagnostic::{Diagnostic, Lines};
use super::yaml::{Location, Node, PathSeg};

/// Collects diagnostics while resolving one file.
pub(crate) struct Checker<'a> {
    pub(crate) file: &'a str,
    pub(crate) source: &'a str,
    lines: Lines<'a>,
    pub(crate) root: &'a Node,
    /// Where the files the scene names may be read from.
    data: super::data_files::DataAccess,
    /// The data files read so far, with their content hashes (in the order
    /// read, each once).
    read: std::cell::RefCell<Vec<crate::scene::DataRead>>,
    pub diagnostics: Vec<Diagnostic>,
    /// Whether the records were checked: an error that stops the
    /// resolution before them leaves them to `resolve::cross_checks`.
    pub(crate) records_checked: bool,
    /// No valid bridge to check the other sections against: the file's
    /// `bridge` did not parse (a stand-in took its place, set by the
    /// loader) or has errors of its own. Checks that need the bridge's
    /// length or width are then left out, not failed.
    pub bridge_unknown: bool,
    /// The file's `bridge` did not parse: it is not resolved at all.
    pub bridge_unreadable: bool,
    /// Placeholders stand for required values with type errors (see
    /// [`super::yaml::NodeKind::Placeholder`]): the sections are checked,
    /// what depends on a placeholder's value is not, and the scene is not
    /// planned (its physics would be that of the placeholders).
    pub placeheld: bool,
    /// The sequences and mappings that lost an entry to a type error, and
    /// the placeholders (set by the loader).
    pub(crate) pruned: Vec<Location>,
}

/// Parses "vehicles[0].speed" into path segments.
fn parse_path(path: &str) -> Vec<PathSeg<'_>> {
    let mut segs = Vec::new();
    for part in path.split('.') {
        let (key, rest) = part.split_once('[').unwrap_or((part, ""));
        if !key.is_empty() {
            segs.push(PathSeg::Key(key));
        }
        for idx in rest.split('[') {
            if let Ok(i) = idx.trim_end_matches(']').parse() {
                segs.push(PathSeg::Index(i));
            }
        }
    }
    segs
}

impl<'a> Checker<'a> {
    pub(crate) fn new(file: &'a str, source: &'a str, root: &'a Node) -> Self {
        Self {
            file,
            source,
            lines: Lines::new(source),
            root,
            data: Default::default(),
            read: Default::default(),
            diagnostics: Vec::new(),
            records_checked: false,
            bridge_unknown: false,
            bridge_unreadable: false,
            placeheld: false,
            pruned: Vec::new(),
        }
    }

    /// Whether the value at `path` is a placeholder for a value with a type
    /// error (already reported): a check of it or against it is not made.
    pub(crate) fn is_placeholder(&self, path: &str) -> bool {
        self.root
            .at(&parse_path(path))
            .is_some_and(|n| matches!(n.kind, super::yaml::NodeKind::Placeholder))
    }

    /// Whether the section at `path` is not as the file wrote it: it holds
    /// a placeholder, or a list that lost an item to a type error. Its own
    /// checks are made, but it is no reference for the checks of another
    /// section (a bridge that lost a span has no known length, a vehicle
    /// that lost an axle no known wheel count).
    pub(crate) fn uncertain(&self, path: &str) -> bool {
        self.lost_at(path).is_some()
    }

    /// Where the section at `path` is not as the file wrote it (see
    /// [`Checker::uncertain`]): the first placeholder or list that lost an
    /// item in it.
    fn lost_at(&self, path: &str) -> Option<Location> {
        fn lost(node: &Node, pruned: &[Location]) -> Option<Location> {
            use super::yaml::NodeKind;
            match &node.kind {
                NodeKind::Placeholder => Some(node.loc),
                NodeKind::Sequence(_) if pruned.contains(&node.loc) => Some(node.loc),
                NodeKind::Sequence(items) => items.iter().find_map(|n| lost(n, pruned)),
                NodeKind::Mapping(entries) => entries.iter().find_map(|(_, v)| lost(v, pruned)),
                NodeKind::Null | NodeKind::Scalar { .. } => None,
            }
        }
        self.root
            .at(&parse_path(path))
            .and_then(|n| lost(n, &self.pruned))
    }

    /// A check of the section at `path` that fails because a type error
    /// (already reported) changed it: an error where that error is, which
    /// the loader leaves out as its consequence, but which stops the
    /// resolution like any error (a vehicle one axle short is not planned).
    /// At `path` itself if the section is as written.
    pub(crate) fn consequence(&mut self, path: &str, message: impl Into<String>) {
        match self.lost_at(path) {
            Some(loc) => {
                let diagnostic = self.lines.diagnostic(self.file, loc, message);
                self.diagnostics.push(diagnostic);
            }
            None => self.error(path, message),
        }
    }

    /// Sets where the files the scene names may be read from.
    pub(crate) fn set_data_access(&mut self, data: super::data_files::DataAccess) {
        self.data = data;
    }

    /// Where the files the scene names may be read from.
    pub(crate) fn data_access(&self) -> &super::data_files::DataAccess {
        &self.data
    }

    /// Notes that the data file `path` was read with content hash `sha256`.
    pub(crate) fn note_read(&self, path: &str, sha256: String) {
        let mut read = self.read.borrow_mut();
        if !read.iter().any(|r| r.path == path) {
            read.push(crate::scene::DataRead {
                path: path.to_string(),
                sha256,
            });
        }
    }

    /// The data files read so far ([`Self::note_read`]).
    pub(crate) fn data_read(&self) -> Vec<crate::scene::DataRead> {
        self.read.borrow().clone()
    }

    fn location(&self, path: &str) -> Location {
        self.root.locate(&parse_path(path))
    }

    /// Records an error at `path`.
    pub(crate) fn error(&mut self, path: &str, message: impl Into<String>) {
        let loc = self.location(path);
        let diagnostic = self.lines.diagnostic(self.file, loc, message);
        self.diagnostics.push(diagnostic);
    }

    /// Whether an error recorded since the first `since` diagnostics is at
    /// the place of `path` (one message per key: a later, more general
    /// check leaves a key a specific one refused).
    pub(crate) fn blamed_since(&self, since: usize, path: &str) -> bool {
        let loc = self.location(path);
        self.diagnostics
            .get(since..)
            .is_some_and(|new| new.iter().any(|d| d.loc == loc))
    }

    /// Records an error at `path` with a `help:` line (a suggestion).
    pub(crate) fn error_with_help(
        &mut self,
        path: &str,
        message: impl Into<String>,
        help: Option<String>,
    ) {
        let loc = self.location(path);
        let diagnostic = self
            .lines
            .diagnostic(self.file, loc, message)
            .with_help(help);
        self.diagnostics.push(diagnostic);
    }

    /// The scenario file's name as given (relative paths in the scene are
    /// relative to its folder).
    pub(crate) fn file(&self) -> &str {
        self.file
    }

    pub(crate) fn positive(&mut self, path: &str, value: f64, what: &str) {
        if value <= 0.0 {
            self.error(path, format!("{what} must be positive, got {value}"));
        }
    }

    /// Whether the file writes the key at `path` (defaults are blamed on the
    /// section that could set them instead).
    pub(crate) fn has(&self, path: &str) -> bool {
        let segs = parse_path(path);
        let (last, parent) = match segs.split_last() {
            Some((PathSeg::Key(k), parent)) => (*k, parent),
            _ => return false,
        };
        let mut node = self.root;
        for seg in parent {
            let next = match seg {
                PathSeg::Key(k) => node.get(k),
                PathSeg::Index(i) => match &node.kind {
                    super::yaml::NodeKind::Sequence(items) => items.get(*i),
                    _ => None,
                },
            };
            match next {
                Some(n) => node = n,
                None => return false,
            }
        }
        node.get(last).is_some()
    }

    pub(crate) fn non_negative(&mut self, path: &str, value: f64, what: &str) {
        if value < 0.0 {
            self.error(path, format!("{what} must not be negative, got {value}"));
        }
    }
}

pub(crate) fn check_ratio(ck: &mut Checker<'_>, path: &str, ratio: f64) {
    if !(0.0..1.0).contains(&ratio) {
        ck.error(
            path,
            format!("a damping ratio must be in [0, 1), got {ratio}"),
        );
    }
}

/// Where the key path `path` (the format's syntax: `vehicles[0].speed`)
/// stands in the scenario text `source`: the deepest node of the path the
/// text has, or `None` when the text does not parse. For the front ends to
/// show an advice's location as `file:line:col`.
pub fn locate_in(source: &str, path: &str) -> Option<super::yaml::Location> {
    let root = super::yaml::parse(source).ok()??;
    Some(root.locate(&parse_path(path)))
}
