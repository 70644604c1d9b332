//! A scene read for its bridge alone: `vbi modes` lists a bridge's natural
//! frequencies before any vehicle is written, so a file with `name` and
//! `bridge` and no `vehicles` is enough there. Every other key is read and
//! checked as usual when present (a file with vehicles goes through
//! [`super::load_str`] whole).

use serde::Deserialize;

use super::budget::eigen_fits;
use super::content;
use crate::bridge::{ModalBridge, ModeRequest};
use crate::scenario::budget::{Budget, LoadOptions};
use crate::scenario::checker::Checker;
use crate::scenario::raw::{BridgeRaw, LimitsRaw};
use crate::scenario::{LoadError, bridges, de, parse_raw};
use crate::scene::Scenario;

/// The scene as `vbi modes` sees it.
#[derive(Debug, Clone)]
pub struct ModesScene {
    /// The scene's `name`.
    pub name: String,
    /// The modal bridge; without vehicles and without `modes`, the automatic
    /// minimum for the quasi-static shape (nothing excites it).
    pub bridge: ModalBridge,
    /// The whole resolved scene, when the file has vehicles.
    pub scenario: Option<Scenario>,
    /// An imported model's mass and, with vehicles, its static deflection
    /// under their weight ([`super::imported_check`]).
    pub imported: Option<crate::scene::imported::ImportedTotals>,
}

/// Only the keys a bridge needs; the others are not looked at.
#[derive(Deserialize)]
struct BridgeSceneRaw {
    name: String,
    bridge: BridgeRaw,
    #[serde(default)]
    limits: Option<LimitsRaw>,
}

/// Loads `source` for `vbi modes`: the whole scene when it has `vehicles`,
/// else its name and bridge; the files it names are read as
/// `options.data` allows.
/// `options` are the command line's, as for any command (`--allow-large`,
/// `--trust-limits`).
pub fn load_for_modes(
    source: &str,
    file: &str,
    options: LoadOptions,
) -> Result<ModesScene, LoadError> {
    let has_vehicles = crate::scenario::yaml::parse(source)
        .ok()
        .flatten()
        .is_none_or(|node| node.get("vehicles").is_some());
    if has_vehicles {
        return super::load_str_with(source, file, options).map(|loaded| ModesScene {
            name: loaded.scenario.name.clone(),
            bridge: loaded.bridge,
            imported: match &loaded.scenario.bridge {
                crate::scene::Bridge::FeImport(fe) => fe.totals,
                _ => None,
            },
            scenario: Some(loaded.scenario),
        });
    }
    // The whole scene's syntax and types are still checked, apart from the
    // missing `vehicles`.
    let node = match parse_raw(source, file) {
        Ok((_, node)) => node,
        Err(LoadError::Invalid(d))
            if d.len() == 1 && d[0].to_string().contains("missing field `vehicles`") =>
        {
            crate::scenario::yaml::parse(source)
                .ok()
                .flatten()
                .ok_or(LoadError::Invalid(d))?
        }
        Err(e) => return Err(e),
    };
    let raw: BridgeSceneRaw = de::from_node(&node).map_err(|e| {
        LoadError::Invalid(vec![crate::scenario::Diagnostic::new(
            file,
            source,
            e.loc.unwrap_or(node.loc),
            e.message,
        )])
    })?;
    let mut ck = Checker::new(file, source, &node);
    ck.set_data_access(options.data.clone());
    let limits = crate::scene::Limits::resolve(raw.limits.as_ref(), &mut ck);
    let budget = Budget::new(limits, &options);
    let Some(mut bridge) = bridges::resolve_bridge(&raw.bridge, &budget, &mut ck) else {
        return Err(LoadError::Invalid(ck.diagnostics));
    };
    if !ck.diagnostics.is_empty() {
        return Err(LoadError::Invalid(ck.diagnostics));
    }
    // No vehicle excites anything: the automatic choice is its minimum for
    // the quasi-static deflection shape. The eigenproblem and the modes
    // asked are budgeted before the solve, as for a whole scene.
    let minimum = content::minimum_modes(&bridge);
    let (asked, asked_path) = match bridge.modes().count {
        Some(count) => (count, "bridge.modes.count"),
        None => (minimum, "bridge.spans"),
    };
    let fits = budget.model(&bridge, &crate::scene::Surface::Smooth, &mut ck)
        && budget.check(
            &mut ck,
            asked_path,
            "modes",
            "bridge modes kept",
            asked as f64,
        )
        && eigen_fits(&budget, &mut ck, asked_path, &bridge, asked);
    if !fits {
        return Err(LoadError::Invalid(ck.diagnostics));
    }
    let request = ModeRequest::of(bridge.modes(), ModeRequest::Lowest(minimum));
    let automatic = bridge.modes().count.is_none() && bridge.modes().max_frequency.is_none();
    let mut modal =
        ModalBridge::build_cached(&bridge, request, None, options.par).map_err(|e| {
            ck.error("bridge", e.to_string());
            LoadError::Invalid(std::mem::take(&mut ck.diagnostics))
        })?;
    if automatic {
        let count = modal.mode_count();
        modal.selection = format!(
            "automatic without vehicles: {count} modes, the minimum kept for the quasi-static shape"
        );
        bridge.modes_mut().count = Some(count);
        bridge.modes_mut().max_frequency = modal.frequencies().last().copied();
    }
    Ok(ModesScene {
        name: raw.name,
        bridge: modal,
        scenario: None,
        imported: match &bridge {
            crate::scene::Bridge::FeImport(fe) => fe.totals,
            _ => None,
        },
    })
}
