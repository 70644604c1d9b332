//! Resolving an `fe_import` bridge: reads its files (paths relative to the
//! scenario), budgets their sizes before reading, and checks them against
//! each other. Every problem is reported at the scenario key that names the
//! file, with the file's own line and column in the message.

use std::sync::Arc;

use super::budget::Budget;
use super::checker::Checker;
use super::data_files::{self, DataFile};
use super::raw;
pub mod abaqus;
pub mod dense;
mod entries;
pub mod harwell_boeing;
pub mod matrix_market;
mod penalty;
mod read;
pub mod rotation;
pub mod tables;

pub use self::read::{
    AssemblyError, MatrixFile, RailNodes, ReadError, SYMMETRY_TOLERANCE, SizeCheck, Source,
};
pub(crate) use self::read::{fail, fail_at, parse_value};
use crate::scene::imported::{Direction, ImportedModel};
use crate::scene::*;

/// Fewest bytes a matrix entry line takes (`1 1 1` and a line break is 6;
/// Abaqus's `1,1,1,1,1` 10): the size check before reading counts 10.
const MIN_ENTRY_BYTES: f64 = 10.0;

/// Default length over which a wheel's load enters an imported track at a
/// free rail end, m: a little beyond the distance ahead of a wheel at which
/// a continuous rail on ballasted track already bends under it (the first
/// zero of its deflection line, 1.7–2.1 m: `crate::bridge::fe_import::entry`),
/// and long enough that the ramp rings no track mode above the automatic
/// cut-off: measured on scenarios/viaduct-2span (issue 24.4;
/// docs/guide/imports.md).
pub const DEFAULT_ENTRY_LENGTH: f64 = 3.0;

/// Resolves the `fe_import` bridge; `None` after reporting its problems.
pub(crate) fn resolve(
    raw: &raw::FeImportRaw,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Option<FeImport> {
    let before = ck.diagnostics.len();
    let stiffness_file = locate(&raw.stiffness, "bridge.stiffness", ck);
    let mass_file = locate(&raw.mass, "bridge.mass", ck);
    let stiffness = stiffness_file.as_ref().and_then(|f| {
        let _t = crate::timings::stage(|| "read the stiffness matrix".into());
        read_matrix(f, "bridge.stiffness", budget, ck)
    });
    let mass = mass_file.as_ref().and_then(|f| {
        let _t = crate::timings::stage(|| "read the mass matrix".into());
        read_matrix(f, "bridge.mass", budget, ck)
    });
    let mut damping_shown: Option<String> = None;
    let (damping, damping_file) = match &raw.damping {
        None => (ImportDamping::Modal { ratio: 0.0 }, None),
        Some(raw::ImportDampingRaw::Modal { ratio }) => {
            super::checker::check_ratio(ck, "bridge.damping.ratio", *ratio);
            (ImportDamping::Modal { ratio: *ratio }, None)
        }
        Some(raw::ImportDampingRaw::Rayleigh { frequencies, ratio }) => {
            super::checker::check_ratio(ck, "bridge.damping.ratio", *ratio);
            for (i, &f) in frequencies.iter().enumerate() {
                ck.positive(
                    &format!("bridge.damping.frequencies[{i}]"),
                    f,
                    "a Rayleigh frequency",
                );
            }
            if frequencies[0] == frequencies[1] {
                ck.error(
                    "bridge.damping.frequencies",
                    "the two Rayleigh frequencies must differ",
                );
            }
            (
                ImportDamping::Rayleigh {
                    frequencies: *frequencies,
                    ratio: *ratio,
                },
                None,
            )
        }
        Some(raw::ImportDampingRaw::Matrix { file }) => {
            let located = locate(file, "bridge.damping.file", ck);
            let read = located
                .as_ref()
                .and_then(|f| read_matrix(f, "bridge.damping.file", budget, ck));
            damping_shown = located.as_ref().map(|f| f.shown.clone());
            (
                ImportDamping::Matrix {
                    file: located.map_or_else(|| file.clone(), |f| f.shown),
                },
                read,
            )
        }
    };
    let dof_map_file = raw
        .dof_map
        .as_deref()
        .map(|f| locate(f, "bridge.dof_map", ck));
    let rails_read = crate::timings::stage(|| "read the rails".into());
    let mut rails = Vec::with_capacity(raw.rails.len());
    let mut rail_inputs = Vec::with_capacity(raw.rails.len());
    if raw.rails.is_empty() {
        ck.error(
            "bridge.rails",
            "give at least one rail (the nodes the wheels run over)",
        );
    }
    for (i, rail) in raw.rails.iter().enumerate() {
        let at = format!("bridge.rails[{i}]");
        if raw.rails[..i].iter().any(|r| r.name == rail.name) {
            ck.error(
                &format!("{at}.name"),
                format!("a second rail named `{}`", rail.name),
            );
        }
        match (&rail.file, &rail.nodes) {
            (Some(file), None) => {
                let at = format!("{at}.file");
                let data = locate(file, &at, ck);
                if let Some(data) = &data
                    && let Some(text) = read_text(data, &at, budget, ck)
                    && let Some(nodes) = located(tables::rail(&text), &data.shown, &at, ck)
                {
                    rails.push((rail.name.clone(), nodes));
                }
                rail_inputs.push(RailInput {
                    name: rail.name.clone(),
                    file: Some(data.map_or_else(|| file.clone(), |d| d.shown)),
                    nodes: None,
                });
            }
            (None, Some(nodes)) => {
                let mut pairs: Vec<(u64, f64)> = Vec::with_capacity(nodes.len());
                for (k, n) in nodes.iter().enumerate() {
                    if let Err(m) = tables::check_next(&pairs, n.node, n.x) {
                        ck.error(&format!("{at}.nodes[{k}].x"), m);
                        break;
                    }
                    pairs.push((n.node, n.x));
                }
                if nodes.len() < 2 {
                    ck.error(&format!("{at}.nodes"), "a rail needs at least two nodes");
                }
                rails.push((rail.name.clone(), pairs));
                rail_inputs.push(RailInput {
                    name: rail.name.clone(),
                    file: None,
                    nodes: Some(nodes.iter().map(|n| n.resolved()).collect()),
                });
            }
            _ => ck.error(
                &at,
                "a rail needs `file` (a CSV `node,x`) or `nodes`, one of them",
            ),
        }
    }
    drop(rails_read);
    let track = match &raw.track {
        Some(names) => names.clone(),
        None if (1..=2).contains(&raw.rails.len()) => {
            raw.rails.iter().map(|r| r.name.clone()).collect()
        }
        None => {
            ck.error(
                "bridge",
                "with more than two rails, name the one or two the vehicles run on in `track`",
            );
            Vec::new()
        }
    };
    if !(1..=2).contains(&track.len()) && raw.track.is_some() {
        ck.error("bridge.track", "`track` names one rail or two");
    }
    let mut track_index = Vec::new();
    for (i, name) in track.iter().enumerate() {
        match raw.rails.iter().position(|r| &r.name == name) {
            Some(t) => track_index.push(t),
            None => ck.error(
                &format!("bridge.track[{i}]"),
                format!("no rail is named `{name}`"),
            ),
        }
    }
    let constrained: Vec<NodeDof> = raw.constrained.clone().unwrap_or_default();
    let rotation_sign = raw.rotation_sign.unwrap_or_default();
    let axes = raw.axes.unwrap_or_default();
    for (name, sign) in [("ry", rotation_sign.ry), ("rz", rotation_sign.rz)] {
        if sign != 1 && sign != -1 {
            ck.error(
                &format!("bridge.rotation_sign.{name}"),
                format!("a rotation's sign is -1 or 1, got {sign}"),
            );
        }
    }
    let modes = super::bridges::resolve_modes(ck, raw.modes.as_ref());
    if ck.diagnostics.len() != before {
        return None;
    }
    let (stiffness, mass) = (stiffness?, mass?);
    let (stiffness_file, mass_file) = (stiffness_file?, mass_file?);
    let dof_map_file = match dof_map_file {
        Some(f) => Some(f?),
        None => None,
    };
    let map_read = crate::timings::stage(|| "read the DOF map".into());
    let map = match &dof_map_file {
        Some(data) => {
            let shown = data.shown.clone();
            let text = read_text(data, "bridge.dof_map", budget, ck)?;
            // A CSV with its header, or ANSYS's `.mapping` file.
            let csv = text
                .lines()
                .map(str::trim)
                .find(|l| !l.is_empty() && !l.starts_with('#'))
                .is_some_and(|l| l.to_ascii_lowercase().replace(' ', "").starts_with("dof,"));
            let read = if csv {
                tables::dof_map(&text, stiffness.order)
            } else {
                harwell_boeing::mapping(&text, stiffness.order)
            };
            Some(located(read, &shown, "bridge.dof_map", ck)?)
        }
        None => None,
    };
    drop(map_read);
    let assembly = crate::timings::stage(|| "assemble the model".into());
    let pairs: Vec<(u64, Direction)> = constrained.iter().map(|c| (c.node, c.direction)).collect();
    let mut model = match ImportedModel::assemble(
        stiffness,
        mass,
        damping_file,
        map,
        &pairs,
        &rails,
        &track_index,
        rotation_sign,
        raw.rotation_sign.is_some(),
        axes,
    ) {
        Ok(model) => model,
        Err(e) => {
            let (path, file) = match e.source_input {
                Source::Stiffness => ("bridge.stiffness".to_string(), Some(&stiffness_file.shown)),
                Source::Mass => ("bridge.mass".to_string(), Some(&mass_file.shown)),
                Source::Damping => ("bridge.damping.file".to_string(), damping_shown.as_ref()),
                Source::DofMap => (
                    "bridge.dof_map".to_string(),
                    dof_map_file.as_ref().map(|f| &f.shown),
                ),
                Source::Constrained(i) => (format!("bridge.constrained[{i}]"), None),
                Source::Rail(i) => (format!("bridge.rails[{i}]"), None),
                Source::Track => ("bridge.track".to_string(), None),
                Source::RotationSign(r) => {
                    // At the option if written, else where it belongs.
                    let at = format!("bridge.rotation_sign.{}", r.name());
                    let at = if ck.has(&at) {
                        at
                    } else {
                        "bridge".to_string()
                    };
                    (at, Some(&stiffness_file.shown))
                }
            };
            let message = match (file, e.place) {
                (Some(f), Some((line, column))) => format!("{f}:{line}:{column}: {}", e.message),
                (Some(f), None) => format!("{f}: {}", e.message),
                (None, _) => e.message,
            };
            ck.error_with_help(&path, message, e.help);
            return None;
        }
    };
    drop(assembly);
    // A wheel's load enters the track over `entry_length` at each free rail
    // end (bridge::fe_import::entry), none where the support holds it.
    // The default keeps both ramps on the outer quarters of a short track.
    let entry_length = raw
        .entry_length
        .unwrap_or(DEFAULT_ENTRY_LENGTH.min(0.25 * model.length));
    if entry_length.is_finite() {
        ck.non_negative("bridge.entry_length", entry_length, "the entry length");
    } else {
        ck.error(
            "bridge.entry_length",
            format!("the entry length must be a finite length in m, got {entry_length}"),
        );
    }
    let (free_start, free_end) = model.free_rail_ends();
    if entry_length.is_finite()
        && (free_start || free_end)
        && entry_length * (free_start as u8 + free_end as u8) as f64 > model.length
    {
        ck.error(
            "bridge.entry_length",
            format!(
                "the entry length {entry_length} m at the free rail ends does not fit on the \
                 {:.4} m track",
                model.length
            ),
        );
    }
    if ck.diagnostics.len() > before {
        return None;
    }
    model.entry.entry = if free_start { entry_length } else { 0.0 };
    model.entry.exit = if free_end { entry_length } else { 0.0 };
    Some(FeImport {
        stiffness: stiffness_file.shown,
        mass: mass_file.shown,
        dof_map: dof_map_file.map(|f| f.shown),
        constrained,
        damping,
        rails: rail_inputs,
        track,
        modes,
        rotation_sign,
        axes,
        entry_length,
        spans: vec![model.length],
        totals: Some(model.totals()),
        model: Arc::new(model),
    })
}

/// A reader's result, its error reported as `file:line:column: message` at `at`.
fn located<T>(
    result: Result<T, ReadError>,
    shown: &str,
    at: &str,
    ck: &mut Checker<'_>,
) -> Option<T> {
    match result {
        Ok(v) => Some(v),
        Err(e) => {
            let place = match e.column {
                Some(c) => format!("{shown}:{}:{c}", e.line),
                None => format!("{shown}:{}", e.line),
            };
            ck.error_with_help(at, format!("{place}: {}", e.message), e.help);
            None
        }
    }
}

/// Resolves a path the scene names at `at` ([`data_files::locate`]);
/// `None` after reporting why it may not be read.
fn locate(named: &str, at: &str, ck: &mut Checker<'_>) -> Option<DataFile> {
    match data_files::locate(named, "", ck) {
        Ok(file) => Some(file),
        Err(message) => {
            ck.error(at, message);
            None
        }
    }
}

/// The text of `file`, its size budgeted (as matrix entries of
/// [`MIN_ENTRY_BYTES`]) before it is read.
fn read_text(file: &DataFile, at: &str, budget: &Budget, ck: &mut Checker<'_>) -> Option<String> {
    let (shown, size) = (&file.shown, file.size);
    if !budget.check(
        ck,
        at,
        "import_entries",
        &format!(
            "entries {shown} may hold ({size} bytes, {MIN_ENTRY_BYTES} bytes an entry at least)"
        ),
        (size as f64 / MIN_ENTRY_BYTES).ceil(),
    ) {
        return None;
    }
    match data_files::read_text(file, ck) {
        Ok(text) => Some(text),
        Err(message) => {
            ck.error(at, message);
            None
        }
    }
}

/// Reads a matrix file: Matrix Market by its banner, Abaqus by its comma
/// separated entry lines, a dense text matrix by its lines of numbers,
/// Harwell–Boeing by its header's type; any other is refused with the
/// formats vbi reads.
fn read_matrix(
    file: &DataFile,
    at: &str,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Option<MatrixFile> {
    let text = read_text(file, at, budget, ck)?;
    let shown = file.shown.clone();
    let bytes = text.len() as f64;
    let dofs_limit = budget_limit(budget, ck, at);
    let result = if text
        .trim_start()
        .to_ascii_lowercase()
        .starts_with("%%matrixmarket")
    {
        let mut sizes = |rows: u64, entries: u64| -> Result<(), String> {
            // A row count or entry count the file cannot hold is refused
            // before anything is allocated for it.
            if entries as f64 > bytes / 6.0 {
                return Err(format!(
                    "the size line declares {entries} entries but the file has only {bytes} bytes \
                     (6 bytes an entry at least): it is truncated or the count is wrong"
                ));
            }
            if rows as f64 > dofs_limit {
                return Err(format!(
                    "the size line declares {rows} rows, more than the {dofs_limit} DOFs `limits.dofs` \
                     allows an imported model (50 DOFs a unit); raise it or run with `--allow-large`"
                ));
            }
            Ok(())
        };
        matrix_market::parse(&text, &mut sizes)
    } else if looks_like_abaqus(&text) {
        abaqus::parse(&text)
    } else if dense::looks_dense(&text) {
        let mut sizes = |rows: u64, _: u64| -> Result<(), String> {
            if rows as f64 > dofs_limit {
                return Err(format!(
                    "its first row has {rows} numbers, more than the {dofs_limit} DOFs \
                     `limits.dofs` allows an imported model (50 DOFs a unit)"
                ));
            }
            Ok(())
        };
        dense::parse(&text, &mut sizes)
    } else if let Some(e) = not_harwell_boeing(&text) {
        Err(e)
    } else {
        let mut sizes = |rows: u64, entries: u64| -> Result<(), String> {
            // Harwell–Boeing writes an index and a value per entry, 2 bytes at least.
            if entries as f64 > bytes / 2.0 || rows as f64 > dofs_limit {
                return Err(format!(
                    "the header declares {rows} rows and {entries} entries: more than the file's \
                     {bytes} bytes can hold, or than the {dofs_limit} DOFs `limits.dofs` allows \
                     an imported model (50 DOFs a unit)"
                ));
            }
            Ok(())
        };
        harwell_boeing::parse(&text, &mut sizes)
    };
    let file = located(result, &shown, at, ck)?;
    if file.order as f64 > dofs_limit {
        ck.error(
            at,
            format!(
                "{shown}: {} DOFs is more than the {dofs_limit} `limits.dofs` allows an imported \
                 model (50 DOFs a unit)",
                file.order
            ),
        );
        return None;
    }
    Some(file)
}

/// Whether `text` is Abaqus coordinate output: its first line that is not
/// blank or a `*` keyword has 5 comma-separated fields (a Harwell–Boeing
/// file starts with a free title and a line of 5 fixed-width integers).
fn looks_like_abaqus(text: &str) -> bool {
    text.lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with('*'))
        .is_some_and(|l| l.split(',').count() == 5)
}

/// The error for a file that is none of the formats, when it is not a
/// Harwell–Boeing file either: its third line does not start with a
/// Harwell–Boeing type (three letters: real, complex or pattern; symmetric,
/// unsymmetric, Hermitian, skew or rectangular; assembled or elemental).
fn not_harwell_boeing(text: &str) -> Option<ReadError> {
    let third = text.lines().nth(2);
    let kind: Vec<char> = third.unwrap_or("").chars().take(3).collect();
    let typed = kind.len() == 3
        && "RCP".contains(kind[0].to_ascii_uppercase())
        && "SUHZR".contains(kind[1].to_ascii_uppercase())
        && "AE".contains(kind[2].to_ascii_uppercase());
    if typed {
        return None;
    }
    // Only the three characters where the type belongs are shown: the
    // line is the stranger's text (issue 39: no file content in messages).
    let shown: String = kind.iter().collect();
    let third = match third {
        Some(_) => format!(
            "its third line starts with `{}`, not with a Harwell–Boeing type (RSA, RUA)",
            crate::scenario::diagnostic::escaped(&shown)
        ),
        None => "it is shorter than a Harwell–Boeing header (4 lines)".to_string(),
    };
    Some(
        ReadError::new(
            1,
            None,
            format!(
                "this is not a matrix file vbi reads: it has no `%%MatrixMarket` banner, no \
                 Abaqus `node, dof, node, dof, value` lines, its lines are not all numbers (a \
                 dense text matrix), and {third}"
            ),
        )
        .with_help(Some(dense::FORMATS_HELP.to_string())),
    )
}

/// The most DOFs of an imported model the budget allows.
fn budget_limit(budget: &Budget, _ck: &Checker<'_>, _at: &str) -> f64 {
    budget.limit_of("dofs") * 50.0
}
