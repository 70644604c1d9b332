//! The scenario format: loading with source locations, semantic checks,
//! defaults.
//!
//! Data flow: text → [`yaml::parse`] (a position-marked tree; or data the
//! caller parsed, given synthetic locations named by key path) →
//! [`de::from_node`] (serde types in [`raw`], tagged unions dispatched on
//! `type` without losing positions) → [`resolve`] (checks and defaults) →
//! an owned [`Described`] scene ([`load_str`], [`load_file`],
//! [`load_value`]), which the planning stage ([`crate::plan::plan`])
//! finishes into a [`resolved::Scenario`].

pub(crate) mod allow;
pub mod bridges;
pub mod budget;
pub(crate) mod cars;
pub mod checker;
pub mod data_files;
#[allow(missing_docs)]
pub mod de;
pub mod derive;
#[allow(missing_docs)]
pub mod diagnostic;
pub mod envelopes;
pub mod fe_import;
mod from_data;
pub(crate) mod ground;
pub mod load;
pub(crate) mod long_run;
pub mod names;
pub(crate) mod output;
pub(crate) mod plausible;
pub mod rail;
pub mod rail_3d;
pub mod raw;
pub(crate) mod records;
pub mod resolve;
/// The resolved scene, which the format produces: [`crate::scene`].
pub use crate::scene as resolved;
pub mod resonance;
pub mod resonance_grid;
pub mod schema;
pub mod surfaces;
pub mod sweep;
pub mod truck;
pub mod vehicles;
#[allow(missing_docs)]
pub mod yaml;

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

pub use self::budget::LoadOptions;
pub use self::data_files::DataAccess;
pub use self::diagnostic::Diagnostic;
pub use self::load::{
    Described, load_file, load_file_with, load_str, load_str_with, load_value, load_value_with,
};
use self::raw::ScenarioRaw;
pub use self::records::quantity_name_of;
use self::yaml::Location;

/// Why a scenario could not be loaded.
#[derive(Debug, Error)]
pub enum LoadError {
    /// The file could not be read.
    #[error("{}: cannot read: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is not a valid scenario.
    #[error("{}", Diagnostics(.0))]
    Invalid(Vec<Diagnostic>),
}

/// Most diagnostics printed for one file; the rest are counted.
pub const MAX_SHOWN: usize = 50;

/// Most passes of the type checker over one file: each pass reports one
/// type error and removes the offending entry, so a file with thousands of
/// them stays fast (each pass is linear in the file).
const MAX_TYPE_PASSES: usize = 100;

/// Largest scenario file read, bytes: far above any real scene (the
/// largest shipped one is a few kB), and small enough that parsing and
/// diagnostics stay well under a second.
pub const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;

struct Diagnostics<'a>(&'a [Diagnostic]);

impl fmt::Display for Diagnostics<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Front ends print the whole as `error: {this}`: every diagnostic
        // after the first gets its own `error: `, as cargo prints them.
        for (i, d) in self.0.iter().take(MAX_SHOWN).enumerate() {
            if i > 0 {
                writeln!(f)?;
                write!(f, "error: ")?;
            }
            write!(f, "{d}")?;
        }
        if self.0.len() > MAX_SHOWN {
            let rest = self.0.len() - MAX_SHOWN;
            let file = &self.0[0].file;
            write!(
                f,
                "\n{file}: {rest} more error{} not shown ({} in all)",
                if rest == 1 { "" } else { "s" },
                self.0.len()
            )?;
        }
        Ok(())
    }
}

/// The options of [`crate::plan::load_file`] and
/// [`crate::plan::load_str`]: the file's `limits` apply.
pub fn trusted() -> LoadOptions {
    LoadOptions {
        trust_limits: true,
        ..LoadOptions::default()
    }
}

/// The text of a scenario file and its name for diagnostics; the size is
/// checked before the file is read whole.
pub fn read_source(path: &Path) -> Result<(String, String), LoadError> {
    let io = |source| LoadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = path.display().to_string();
    // The size is checked before the file is read whole.
    let meta = std::fs::metadata(path).map_err(io)?;
    if meta.is_dir() {
        return Err(io(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            "it is a folder, not a scene file",
        )));
    }
    let size = meta.len();
    if size > MAX_FILE_BYTES {
        return Err(LoadError::Invalid(vec![Diagnostic::new(
            &file,
            "",
            Location { line: 1, col: 1 },
            format!(
                "the file is {size} bytes; a scenario file may have at most {MAX_FILE_BYTES} bytes"
            ),
        )]));
    }
    // A regular file only (a FIFO would wait for a writer forever, a
    // device such as `/dev/zero` never ends), read at most one byte past
    // the limit (a file that grows while read).
    let file_handle = crate::guarded_file::open_regular(path).map_err(|e| {
        if e.kind() == std::io::ErrorKind::Other {
            LoadError::Invalid(vec![Diagnostic::new(
                &file,
                "",
                Location { line: 1, col: 1 },
                "this is not a regular file (a folder, a device or a pipe); a scene is a YAML \
                 file",
            )])
        } else {
            io(e)
        }
    })?;
    let mut bytes = Vec::new();
    std::io::Read::read_to_end(
        &mut std::io::Read::take(file_handle, MAX_FILE_BYTES + 1),
        &mut bytes,
    )
    .map_err(io)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(LoadError::Invalid(vec![Diagnostic::new(
            &file,
            "",
            Location { line: 1, col: 1 },
            format!(
                "the input is longer than {MAX_FILE_BYTES} bytes, the most a scenario file may have"
            ),
        )]));
    }
    match String::from_utf8(bytes) {
        Ok(source) => Ok((source, file)),
        Err(e) => Err(not_utf8(&file, e.as_bytes(), e.utf8_error().valid_up_to())),
    }
}

/// A located error at the first byte that is not UTF-8 (e.g. a file saved
/// as Latin-1), instead of an unlocated read error.
fn not_utf8(file: &str, bytes: &[u8], valid_up_to: usize) -> LoadError {
    let valid = String::from_utf8_lossy(&bytes[..valid_up_to]);
    // Count line breaks like the YAML scanner: `\n`, `\r\n` and a lone `\r`.
    let line = 1 + valid.matches('\n').count() + valid.matches('\r').count()
        - valid.matches("\r\n").count();
    let line_start = valid.rfind(['\n', '\r']).map_or(0, |i| i + 1);
    let col = valid[line_start..].chars().count() + 1;
    let source = String::from_utf8_lossy(bytes);
    let message = format!(
        "the file is not valid UTF-8 (byte 0x{:02X}); save it with UTF-8 encoding",
        bytes[valid_up_to]
    );
    LoadError::Invalid(vec![Diagnostic::new(
        file,
        &source,
        Location { line, col },
        message,
    )])
}

/// The UTF-8 byte order mark some Windows editors write first.
const BOM: char = '\u{FEFF}';

/// Refuses characters YAML does not allow in a file and that would
/// otherwise be misread: a NUL ends saphyr's input early (the rest of the
/// file silently vanished into "missing field"), other C0 controls but tab
/// and line breaks, DEL and the C1 controls are not printable (YAML 1.2,
/// production c-printable).
fn unprintable(source: &str, file: &str) -> Result<(), LoadError> {
    let printable = |c: char| {
        matches!(c, '\t' | '\n' | '\r' | BOM)
            || !(c.is_control() || matches!(c, '\u{FFFE}' | '\u{FFFF}'))
            || c == '\u{85}'
    };
    let Some((at, c)) = source.char_indices().find(|&(_, c)| !printable(c)) else {
        return Ok(());
    };
    let before = &source[..at];
    let line = 1 + before.matches('\n').count() + before.matches('\r').count()
        - before.matches("\r\n").count();
    let line_start = before.rfind(['\n', '\r']).map_or(0, |i| i + 1);
    let col = before[line_start..].chars().count() + 1;
    Err(LoadError::Invalid(vec![Diagnostic::new(
        file,
        source,
        Location { line, col },
        format!(
            "the file contains the control character U+{:04X}, which YAML does not allow; \
             remove it (was the file saved as text?)",
            c as u32
        ),
    )]))
}

/// Parses a scenario's text into its raw form; `file` labels diagnostics.
///
/// Every type error (unknown key, wrong type, missing field) in the file is
/// reported, not only the first ([`parse_raw_all`]).
pub fn parse_raw(source: &str, file: &str) -> Result<(ScenarioRaw, yaml::Node), LoadError> {
    let parsed = parse_raw_all(source, file)?;
    match parsed.raw {
        Some(raw) if parsed.diagnostics.is_empty() => Ok(raw),
        _ => Err(LoadError::Invalid(parsed.diagnostics)),
    }
}

/// A file's type errors and what is left of it without the entries they
/// are in.
pub struct Parsed {
    /// The scenario without the offending entries, and its tree (which
    /// keeps the source locations), if the rest still makes a scenario
    /// (`None`: a required part was among them).
    pub raw: Option<(ScenarioRaw, yaml::Node)>,
    /// The type errors, located.
    pub diagnostics: Vec<Diagnostic>,
    /// The mappings and sequences that lost an entry: a check that finds
    /// something missing there is a consequence of a type error.
    pub pruned: Vec<Location>,
    /// Whether `bridge`, a required section, did not parse (or is absent):
    /// a stand-in took its place in `raw` so that the other sections are
    /// still checked, and it must not be checked itself.
    pub bridge_unreadable: bool,
    /// Where a placeholder stands for a required field's value that has a
    /// type error ([`yaml::NodeKind::Placeholder`]): the rest of its mapping
    /// is read and checked, no check may blame the placeholder itself, and
    /// no check that needs the physics of the scene (the plan) is made.
    pub placeholders: Vec<Location>,
}

/// Parses a scenario's text and reports every type error (unknown key,
/// wrong type, missing field) in it: after each one the offending entry is
/// removed from the tree and the deserialisation is repeated, and the
/// "missing field" that a removal causes in its parent is not reported:
/// the removed value is given back as a placeholder
/// ([`yaml::NodeKind::Placeholder`]), so that a bad required field does
/// not take the rest of its mapping with it (a vehicle's other fields, a
/// record's position); a placeholder that does not fit (a mapping or list
/// was asked for) goes, and its parent with it.
/// What is left, if it still deserialises, is returned for the semantic
/// checks, so that a file's mistakes of every kind come in one round.
/// Only an unreadable file (not YAML, empty, control characters) is an
/// `Err`.
pub fn parse_raw_all(source: &str, file: &str) -> Result<Parsed, LoadError> {
    let source = source.strip_prefix(BOM).unwrap_or(source);
    unprintable(source, file)?;
    let invalid = |loc: Location, message: String| {
        LoadError::Invalid(vec![Diagnostic::new(file, source, loc, message)])
    };
    let node = match yaml::parse(source) {
        Ok(Some(node)) => node,
        Ok(None) => {
            return Err(invalid(
                Location { line: 1, col: 1 },
                "the file is empty; a scenario needs at least `name`, `bridge` and `vehicles`"
                    .into(),
            ));
        }
        // Scanner errors already say "YAML syntax error"; say it once.
        Err(e) if e.message.starts_with("YAML syntax error") => {
            return Err(invalid(e.loc, e.message));
        }
        Err(e) => return Err(invalid(e.loc, format!("YAML syntax error: {}", e.message))),
    };
    Ok(check_types(node, file, source))
}

/// The type checker's passes over a tree ([`parse_raw_all`]); `source`
/// (the tree's text, empty for a tree the caller built) gives the
/// diagnostics their excerpts.
fn check_types(node: yaml::Node, file: &str, source: &str) -> Parsed {
    let first = match de::from_node::<ScenarioRaw>(&node) {
        Ok(raw) => {
            return Parsed {
                raw: Some((raw, node)),
                diagnostics: Vec::new(),
                pruned: Vec::new(),
                bridge_unreadable: false,
                placeholders: Vec::new(),
            };
        }
        Err(e) => e,
    };
    let lines = diagnostic::Lines::new(source);
    let mut diagnostics: Vec<Diagnostic> = Vec::new();
    let mut tree = node;
    // Mappings and sequences that lost an entry: a missing field there is a
    // consequence of an error already reported.
    let mut pruned: Vec<Location> = Vec::new();
    let mut error = first;
    let mut rest = None;
    // Required sections given a stand-in.
    let mut stood_in: Vec<&'static str> = Vec::new();
    // Mapping entries removed, and where placeholders stand.
    let mut removed: Vec<Removed> = Vec::new();
    let mut placeholders: Vec<Location> = Vec::new();
    for pass in 1.. {
        let loc = error.loc.unwrap_or(tree.loc);
        // A placeholder that does not fit its place: not the file's error.
        let misfit = placeholders.contains(&loc);
        let missing = error
            .message
            .strip_prefix("missing field `")
            .and_then(|rest| rest.strip_suffix('`'));
        let consequence = misfit
            || pruned.contains(&loc)
                && (missing.is_some() || error.message.starts_with("missing `type`"));
        let message = plain_words(&error.message);
        let seen = diagnostics
            .iter()
            .any(|d| d.loc == loc && d.message == message);
        if !consequence && !seen {
            let help = error
                .help
                .clone()
                .or_else(|| diagnostic::suggest_for_serde(&message));
            diagnostics.push(lines.diagnostic(file, loc, message).with_help(help));
        }
        if pass >= MAX_TYPE_PASSES {
            diagnostics.push(lines.diagnostic(
                file,
                tree.loc,
                format!("stopped after {pass} type errors; fix these and check again"),
            ));
            break;
        }
        // A required field lost to a type error: a placeholder in its
        // place (once; if it does not fit, the mapping goes instead).
        let refill = match missing {
            Some(field) if consequence && !misfit => removed
                .iter_mut()
                .find(|r| r.parent == loc && r.key.as_str() == Some(field) && !r.refilled),
            _ => None,
        };
        // A required section lost to a type error (or never written) gets
        // a stand-in, so that the other sections are still checked.
        let section = ["name", "bridge", "vehicles"]
            .into_iter()
            .find(|s| missing == Some(*s));
        if let Some(entry) = refill {
            entry.refilled = true;
            if !refill_at(&mut tree, entry) {
                break;
            }
            placeholders.push(entry.value);
            // The mapping has the field again.
            if let Some(i) = pruned.iter().position(|p| *p == loc) {
                pruned.remove(i);
            }
        } else if misfit {
            placeholders.retain(|p| *p != loc);
            match prune(&mut tree, loc, &mut pruned) {
                Some(_) => {}
                None => break,
            }
        } else if loc == tree.loc
            && let Some(section) = section
            && !stood_in.contains(&section)
        {
            if !stand_in(&mut tree, section) {
                break;
            }
            stood_in.push(section);
            // What is checked against a stand-in name or vehicle list
            // (located at the root, where the stand-in is) is a
            // consequence; a stand-in bridge is not checked at all.
            if section != "bridge" {
                pruned.push(tree.loc);
            }
        } else {
            match prune(&mut tree, loc, &mut pruned) {
                Some(Some(entry)) => removed.push(entry),
                Some(None) => {}
                None => break,
            }
        }
        match de::from_node::<ScenarioRaw>(&tree) {
            Ok(raw) => {
                rest = Some(raw);
                break;
            }
            Err(e) => error = e,
        }
    }
    Parsed {
        raw: rest.map(|raw| (raw, tree)),
        diagnostics,
        pruned,
        bridge_unreadable: stood_in.contains(&"bridge"),
        placeholders,
    }
}

/// A mapping entry the type checker removed: the mapping (its location),
/// the key, and where the value was written (where a placeholder goes if
/// the mapping cannot do without it).
struct Removed {
    parent: Location,
    key: yaml::Node,
    value: Location,
    /// A placeholder was put back for it.
    refilled: bool,
}

/// Puts a placeholder for the entry `removed` back into its mapping (the
/// deepest mapping at its parent's location); `false` if there is none.
fn refill_at(node: &mut yaml::Node, removed: &Removed) -> bool {
    use self::yaml::{Node, NodeKind};
    let here = node.loc == removed.parent;
    match &mut node.kind {
        NodeKind::Mapping(entries) => {
            if entries.iter_mut().any(|(_, v)| refill_at(v, removed)) {
                return true;
            }
            if here {
                let placeholder = Node {
                    kind: NodeKind::Placeholder,
                    loc: removed.value,
                };
                entries.push((removed.key.clone(), placeholder));
            }
            here
        }
        NodeKind::Sequence(items) => items.iter_mut().any(|v| refill_at(v, removed)),
        NodeKind::Null | NodeKind::Scalar { .. } | NodeKind::Placeholder => false,
    }
}

/// Puts a stand-in for the required `section` into the root mapping
/// `tree`, every node at the root's location: `name: unnamed`, an empty
/// `vehicles` list, or a valid beam `bridge` (which the loader marks
/// unreadable, so it is never resolved or checked). `false` if the root is
/// not a mapping.
fn stand_in(tree: &mut yaml::Node, section: &str) -> bool {
    use self::yaml::{Node, NodeKind};
    let loc = tree.loc;
    let NodeKind::Mapping(entries) = &mut tree.kind else {
        return false;
    };
    let scalar = |text: &str| Node {
        kind: NodeKind::Scalar {
            text: text.into(),
            plain: true,
        },
        loc,
    };
    let entry = |key: &str, value: Node| (scalar(key), value);
    let list = |items: Vec<Node>| Node {
        kind: NodeKind::Sequence(items),
        loc,
    };
    let value = match section {
        "name" => scalar("unnamed"),
        "vehicles" => list(Vec::new()),
        _ => Node {
            kind: NodeKind::Mapping(vec![
                entry("type", scalar("beam")),
                entry("spans", list(vec![scalar("1.0")])),
                entry("bending_stiffness", scalar("1.0")),
                entry("mass_per_length", scalar("1.0")),
            ]),
            loc,
        },
    };
    entries.push(entry(section, value));
    true
}

/// Removes the deepest mapping entry (by its key or value) or sequence item
/// written at `loc`, noting its parent in `pruned`: `Some` with the entry
/// removed (`None` for a sequence item), `None` if only the root is there
/// (nothing left to remove).
fn prune(
    node: &mut yaml::Node,
    loc: Location,
    pruned: &mut Vec<Location>,
) -> Option<Option<Removed>> {
    use self::yaml::NodeKind;
    let parent = node.loc;
    match &mut node.kind {
        NodeKind::Mapping(entries) => {
            for i in 0..entries.len() {
                if let Some(inner) = prune(&mut entries[i].1, loc, pruned) {
                    return Some(inner);
                }
                if entries[i].0.loc == loc || entries[i].1.loc == loc {
                    let (key, value) = entries.remove(i);
                    pruned.push(parent);
                    return Some(Some(Removed {
                        parent,
                        key,
                        value: value.loc,
                        refilled: false,
                    }));
                }
            }
            None
        }
        NodeKind::Sequence(items) => {
            for i in 0..items.len() {
                if let Some(inner) = prune(&mut items[i], loc, pruned) {
                    return Some(inner);
                }
                if items[i].loc == loc {
                    items.remove(i);
                    pruned.push(parent);
                    return Some(None);
                }
            }
            None
        }
        NodeKind::Null | NodeKind::Scalar { .. } | NodeKind::Placeholder => None,
    }
}

/// Replaces Rust type names in serde's messages with words a user knows:
/// `struct OscillatorRaw` → `a mapping`, `f64` → `a number`, `usize` → `a
/// whole number`.
fn plain_words(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(i) = rest.find("struct ") {
        out.push_str(&rest[..i]);
        let after = &rest[i + "struct ".len()..];
        let end = after
            .find(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .unwrap_or(after.len());
        out.push_str(if &after[..end] == "ScenarioRaw" {
            "a mapping with the scenario's keys (name, bridge, vehicles, …)"
        } else {
            "a mapping"
        });
        rest = &after[end..];
    }
    out.push_str(rest);
    let mut out = out.replace("expected f64", "expected a number");
    for int in ["usize", "u64", "u32", "u16", "u8", "i64", "i32"] {
        out = out.replace(&format!("expected {int}"), "expected a whole number");
    }
    out
}
