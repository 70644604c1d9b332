//! The scenario format: loading with source locations, semantic checks,
//! defaults.
//!
//! Data flow: text → [`yaml::parse`] (a position-marked tree) →
//! [`de::from_node`] (serde types in [`raw`], tagged unions dispatched on
//! `type` without losing positions) → [`resolve`] (checks and defaults) →
//! [`resolved::Scenario`].

pub mod bridge_only;
pub mod bridges;
pub mod content;
#[allow(missing_docs)]
pub mod de;
pub mod derive;
#[allow(missing_docs)]
pub mod diagnostic;
pub mod raw;
mod records;
pub mod resolve;
pub mod resolved;
pub mod surfaces;
pub mod sweep;
pub mod truck;
#[allow(missing_docs)]
pub mod yaml;

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

pub use self::diagnostic::Diagnostic;
use self::raw::ScenarioRaw;
use self::resolved::Scenario;
use self::yaml::Location;
use crate::bridge::ModalBridge;

/// A scenario that passed every check, with the bridge's modal model built
/// while resolving.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The resolved scenario.
    pub scenario: Scenario,
    /// The modal bridge.
    pub bridge: ModalBridge,
}

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

struct Diagnostics<'a>(&'a [Diagnostic]);

impl fmt::Display for Diagnostics<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{d}")?;
        }
        Ok(())
    }
}

/// Reads and resolves a scenario file.
pub fn load_file(path: &Path) -> Result<Loaded, LoadError> {
    let (source, file) = read_source(path)?;
    load_str(&source, &file)
}

/// Reads a scenario file for `vbi modes`, which needs no vehicles
/// ([`bridge_only::load_for_modes`]).
pub fn load_file_for_modes(path: &Path) -> Result<bridge_only::ModesScene, LoadError> {
    let (source, file) = read_source(path)?;
    bridge_only::load_for_modes(&source, &file)
}

/// The text of a scenario file and its name for diagnostics.
fn read_source(path: &Path) -> Result<(String, String), LoadError> {
    let bytes = std::fs::read(path).map_err(|source| LoadError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let file = path.display().to_string();
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

/// Parses a scenario's text into its raw form; `file` labels diagnostics.
pub fn parse_raw(source: &str, file: &str) -> Result<(ScenarioRaw, yaml::Node), LoadError> {
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
    match de::from_node::<ScenarioRaw>(&node) {
        Ok(raw) => Ok((raw, node)),
        Err(e) => Err(invalid(e.loc.unwrap_or(node.loc), plain_words(&e.message))),
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

/// Parses and resolves a scenario from text; `file` labels diagnostics.
pub fn load_str(source: &str, file: &str) -> Result<Loaded, LoadError> {
    let (raw, node) = parse_raw(source, file)?;
    let mut checker = resolve::Checker::new(file, source, &node);
    match resolve::resolve(&raw, &mut checker) {
        Some((scenario, bridge)) if checker.diagnostics.is_empty() => {
            Ok(Loaded { scenario, bridge })
        }
        _ => Err(LoadError::Invalid(checker.diagnostics)),
    }
}
