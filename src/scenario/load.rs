//! The format's public entry: a scene read and checked, every check that
//! needs no physics, and returned as an owned [`Described`] scene, which
//! the planning stage ([`crate::plan::plan`]) finishes.
//!
//! A described scene owns what the plan needs to place its own diagnostics
//! exactly as the format places its: the parsed tree (every node's
//! location), the source text (the excerpts), the file's raw form (the
//! sections the plan resolves against the modes: contact, study, records,
//! envelopes, output) and the type errors that did not stop the
//! description, which the plan reports with its own, in one round.

use std::collections::HashSet;
use std::path::Path;

use super::checker::Checker;
use super::diagnostic::Diagnostic;
use super::from_data::KeyPaths;
use super::raw::ScenarioRaw;
use super::resolve::{Sections, cross_checks, describe};
use super::yaml::{self, Location};
use super::{
    BOM, LoadError, LoadOptions, Parsed, check_types, parse_raw_all, read_source, trusted,
};
use crate::scene::{Bridge, Vehicle};

/// A scene the format read and checked, before the planning stage: the
/// bridge, vehicles, surface, ground motion and solver settings resolved
/// without physics, and what the plan needs to report its own findings
/// where the file wrote them. Owned: it borrows neither the text nor the
/// tree it came from.
///
/// Type errors in entries the rest of the scene does not need (an unknown
/// key in a record, say) do not stop the description: they are kept in
/// [`Described::errors`], and [`crate::plan::plan`] reports them together
/// with its own, in the order of the file, as one round.
#[derive(Debug, Clone)]
pub struct Described {
    /// The name diagnostics give the file.
    file: String,
    /// The text, without a byte order mark (empty for a tree the caller
    /// built).
    source: String,
    /// The parsed tree: every node's location.
    root: yaml::Node,
    /// The file as parsed, without the entries type errors were in.
    raw: ScenarioRaw,
    /// Type errors found, located.
    typed: Vec<Diagnostic>,
    /// Mappings and sequences that lost an entry to a type error, and the
    /// placeholders for required values with one.
    pruned: Vec<Location>,
    /// The sections checked without physics, with the budgets.
    sections: Sections,
    /// What the checks of the description reported (nothing, as
    /// `describe` stops at the first stage with errors; kept so the plan's
    /// collector continues exactly where the format's stopped).
    checked: Vec<Diagnostic>,
    /// For a tree the caller built: the key path of every synthetic
    /// location.
    paths: Option<KeyPaths>,
}

impl Described {
    /// The scene's `name`.
    pub fn name(&self) -> &str {
        &self.raw.name
    }

    /// The name diagnostics give the file.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// Type errors the description went on past (see [`Described`]); the
    /// plan fails with them, and its own, if there are any.
    pub fn errors(&self) -> Vec<Diagnostic> {
        let mut errors = self.typed.clone();
        if let Some(paths) = &self.paths {
            paths.relocate(&mut errors);
        }
        errors
    }

    /// The bridge as described (its modes not yet chosen).
    pub fn bridge(&self) -> &Bridge {
        &self.sections.bridge
    }

    /// The vehicles as described (dimensionless groups not yet derived).
    pub fn vehicles(&self) -> &[Vehicle] {
        &self.sections.vehicles
    }

    /// How the scene was loaded.
    pub fn options(&self) -> &LoadOptions {
        &self.sections.options
    }

    /// Finishes the scene with `plan`, the planning stage
    /// ([`crate::plan::plan`] passes its choices here): it reports through
    /// a collector over this scene's tree, so its diagnostics are located
    /// as the format's, merged with the type errors kept and ordered as
    /// they have always been. If the plan stops before the records, they
    /// are still checked against the bridge and vehicles as written.
    pub(crate) fn plan_with<T>(
        self,
        plan: impl FnOnce(Sections, &ScenarioRaw, &mut Checker<'_>) -> Option<T>,
    ) -> Result<T, LoadError> {
        let Described {
            file,
            source,
            root,
            raw,
            typed,
            pruned,
            sections,
            checked,
            paths,
        } = self;
        let options = sections.options.clone();
        let mut ck = Checker::new(&file, &source, &root);
        ck.set_data_access(options.data.clone());
        ck.pruned = pruned.clone();
        ck.diagnostics = checked;
        // A file with errors already is not planned: the plan's checks
        // need the modes (an eigen solve of seconds), and its answer would
        // be about a scene the file does not describe (issue 39.6: the
        // fuzzer's 50 s check of a scene whose one error was a subnormal
        // `limits.eigen_work`, read as the default budget meanwhile).
        let planned = if typed.is_empty() {
            plan(sections, &raw, &mut ck)
        } else {
            None
        };
        if planned.is_none() && !ck.records_checked {
            cross_checks(&raw, &mut ck, &options);
        }
        let checked = ck.diagnostics;
        finish(planned, typed, &pruned, &root, checked).map_err(|e| relocated(e, paths.as_ref()))
    }
}

/// Reads and checks a scenario file with the default budgets, as raised or
/// lowered by the file's own `limits` (the caller chose the file).
pub fn load_file(path: &Path) -> Result<Described, LoadError> {
    load_file_with(path, trusted())
}

/// Reads and checks a scenario file.
pub fn load_file_with(path: &Path, options: LoadOptions) -> Result<Described, LoadError> {
    let (source, file) = read_source(path)?;
    load_str_with(&source, &file, options)
}

/// Parses and checks a scenario from text with the default budgets, as
/// raised or lowered by its own `limits`; `file` labels diagnostics.
pub fn load_str(source: &str, file: &str) -> Result<Described, LoadError> {
    load_str_with(source, file, trusted())
}

/// Parses and checks a scenario from text; `file` labels diagnostics.
///
/// Type errors do not stop the checks: what is left without the entries
/// they are in is checked too, and the diagnostics of both come together,
/// in the order of the file. A check that blames a mapping or sequence that
/// lost an entry to a type error is left out (its complaint, e.g. an empty
/// list, is a consequence of that error).
pub fn load_str_with(
    source: &str,
    file: &str,
    options: LoadOptions,
) -> Result<Described, LoadError> {
    let parsed = {
        let _t = crate::timings::stage(|| "parse the scene".into());
        parse_raw_all(source, file)?
    };
    let source = source.strip_prefix(BOM).unwrap_or(source);
    let _t = crate::timings::stage(|| "resolve the scene (files read)".into());
    described(parsed, file, source, options, None)
}

/// Checks a scene the caller already parsed (a `serde_json::Value`: from
/// JSON, a Python dict, …) with the default budgets, as raised or lowered
/// by its own `limits`; `file` labels diagnostics. There is no text, so
/// diagnostics name the key path instead of a line and column
/// ([`Diagnostic::path`]: `vehicles[0].speed`).
///
/// Numbers are read as the YAML text of their shortest round-trip form
/// would be, strings as quoted YAML strings (a number with a unit is a
/// string: `"90 km/h"`). Files the scene names (ground records, FE
/// matrices, measured profiles) are looked for in `file`'s folder, as for
/// a scene file of that name (`.` for a bare name such as `<data>`).
///
/// ```
/// let scene = serde_json::json!({
///     "name": "from-data",
///     "bridge": {"type": "beam", "spans": [25.0], "bending_stiffness": 8.323e9,
///                "mass_per_length": 2303.0},
///     "vehicles": [{"type": "moving_force", "loads": [100.0e3], "speed": -25.0}],
/// });
/// let Err(vbi::scenario::LoadError::Invalid(errors)) =
///     vbi::scenario::load_value(&scene, "<data>")
/// else {
///     panic!("a negative speed is refused");
/// };
/// assert_eq!(errors[0].path.as_deref(), Some("vehicles[0].speed"));
/// ```
pub fn load_value(value: &serde_json::Value, file: &str) -> Result<Described, LoadError> {
    load_value_with(value, file, trusted())
}

/// [`load_value`] with the given options.
pub fn load_value_with(
    value: &serde_json::Value,
    file: &str,
    options: LoadOptions,
) -> Result<Described, LoadError> {
    let (root, paths) = KeyPaths::tree(value, file)?;
    let parsed = check_types(root, file, "");
    described(parsed, file, "", options, Some(paths))
}

/// The format's checks on a parsed file: the sections the plan starts from
/// described, or every diagnostic found (the records' checked against the
/// bridge and vehicles as written when an earlier error stopped the
/// description).
fn described(
    parsed: Parsed,
    file: &str,
    source: &str,
    options: LoadOptions,
    paths: Option<KeyPaths>,
) -> Result<Described, LoadError> {
    let Some((raw, root)) = parsed.raw else {
        return Err(relocated(
            LoadError::Invalid(parsed.diagnostics),
            paths.as_ref(),
        ));
    };
    let mut ck = Checker::new(file, source, &root);
    ck.bridge_unreadable = parsed.bridge_unreadable;
    ck.bridge_unknown = parsed.bridge_unreadable;
    ck.placeheld = !parsed.placeholders.is_empty();
    ck.pruned = parsed
        .pruned
        .iter()
        .chain(&parsed.placeholders)
        .copied()
        .collect();
    let sections = describe(&raw, &mut ck, options.clone());
    if sections.is_none() && !ck.records_checked {
        cross_checks(&raw, &mut ck, &options);
    }
    let checked = std::mem::take(&mut ck.diagnostics);
    drop(ck);
    // What blames a placeholder is about a value already reported.
    let mut pruned = parsed.pruned;
    pruned.extend(parsed.placeholders);
    let Some(sections) = sections else {
        let failed = finish::<()>(None, parsed.diagnostics, &pruned, &root, checked);
        return Err(relocated(failed.unwrap_err(), paths.as_ref()));
    };
    Ok(Described {
        file: file.to_owned(),
        source: source.to_owned(),
        root,
        raw,
        typed: parsed.diagnostics,
        pruned,
        sections,
        checked,
        paths,
    })
}

/// The result of the checks: `resolved` if nothing was found, else every
/// diagnostic, the type errors first and the checks' after them (each once,
/// less the consequences of a type error), all in the order of the file
/// when there were type errors.
fn finish<T>(
    resolved: Option<T>,
    typed: Vec<Diagnostic>,
    pruned: &[Location],
    root: &yaml::Node,
    checked: Vec<Diagnostic>,
) -> Result<T, LoadError> {
    let mut diagnostics = typed;
    let typed = diagnostics.len();
    // A check may run twice (the records after an earlier error): each
    // message once. Hashed: a hostile file has thousands.
    let mut seen: HashSet<(usize, usize, String)> = diagnostics
        .iter()
        .map(|d| (d.loc.line, d.loc.col, d.message.clone()))
        .collect();
    // A vehicle lost to a type error renumbers the ones after it: the
    // records' vehicle numbers are not checked against that list.
    let renumbered = root
        .get("vehicles")
        .is_some_and(|v| pruned.contains(&v.loc))
        .then(|| section_lines(root, "record"))
        .flatten();
    for d in checked {
        let consequence = pruned.contains(&d.loc)
            || renumbered.is_some_and(|(from, to)| (from..to).contains(&d.loc.line));
        if !consequence && seen.insert((d.loc.line, d.loc.col, d.message.clone())) {
            diagnostics.push(d);
        }
    }
    match resolved {
        Some(planned) if diagnostics.is_empty() => Ok(planned),
        _ => {
            if typed > 0 {
                // Read top to bottom, as the file is.
                diagnostics.sort_by_key(|d| (d.loc.line, d.loc.col));
            }
            Err(LoadError::Invalid(diagnostics))
        }
    }
}

/// `error` with its diagnostics named by key path, for a tree the caller
/// built (`paths`).
fn relocated(mut error: LoadError, paths: Option<&KeyPaths>) -> LoadError {
    if let (LoadError::Invalid(diagnostics), Some(paths)) = (&mut error, paths) {
        paths.relocate(diagnostics);
    }
    error
}

/// The lines a top-level section spans: from its key to the next top-level
/// key (or the end of the file).
fn section_lines(root: &yaml::Node, key: &str) -> Option<(usize, usize)> {
    let yaml::NodeKind::Mapping(entries) = &root.kind else {
        return None;
    };
    let from = root.key_loc(key)?.line;
    let to = entries
        .iter()
        .map(|(k, _)| k.loc.line)
        .filter(|&line| line > from)
        .min()
        .unwrap_or(usize::MAX);
    Some((from, to))
}
