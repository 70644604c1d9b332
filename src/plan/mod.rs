//! The planning stage: a scene the format described ([`crate::scenario`])
//! becomes a plan to run, the bridge's modal model built and every
//! automatic choice that needs physics made, each with its reason:
//!
//! - the modes kept (a Sturm count before any solve where the cut-off alone
//!   decides; the excitations the vehicles and the surface bring; twice the
//!   minimum under heavy wheels; 90 % of the mass under ground motion), its
//!   reason in the bridge's `selection`;
//! - the default time step (steps per period of the highest frequency
//!   excited, steps per crossing, the phase drift of each mode deck
//!   accelerations sum over the run or its free vibration's decay, the
//!   ground records' sampling), its reason in `solver.time_step_selection`;
//! - the budgets that need a mode count or the eigen solve's size;
//! - oscillators given by dimensionless groups (they need f₁).
//!
//! Data flow: the format ([`crate::scenario::load_str`], `load_file` or
//! `load_value`: YAML or data → raw → the owned
//! [`Described`] scene, every check that needs no physics) → [`plan`]
//! → [`Loaded`], which [`crate::run`] runs. [`load_str`] and [`load_file`]
//! do both calls. Errors found here carry the file, line and column of the
//! key they blame (or its key path, for a scene given as data), as the
//! format's own, and come in one round with the type errors the format
//! went on past.

pub mod acceleration;
pub mod advice;
pub mod bridge_only;
mod budget;
mod choices;
pub mod content;
mod derive;
pub mod imported_check;
mod modes;
mod plausible;
mod sweep;
mod time_step;
pub mod track_flexibility;
mod travel;

use std::path::Path;

use crate::bridge::ModalBridge;
use crate::scenario::{Described, LoadError, LoadOptions, read_source, trusted};
use crate::scene::Scenario;

/// A scenario that passed every check, planned: the bridge's modal model
/// built and every automatic choice made.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The resolved scenario, the automatic choices written back.
    pub scenario: Scenario,
    /// The modal bridge.
    pub bridge: ModalBridge,
}

/// Plans a scene the format described: builds the bridge's modal model and
/// makes every automatic choice, each with its reason. The options are the
/// ones the scene was loaded with ([`Described::options`]).
///
/// Fails with every diagnostic of the plan and the type errors the format
/// went on past ([`Described::errors`]), in one round, located as the
/// format locates its own.
pub fn plan(described: Described) -> Result<Loaded, LoadError> {
    let _t = crate::timings::stage(|| "plan".into());
    described
        .plan_with(choices::plan)
        .map(|(scenario, bridge)| Loaded { scenario, bridge })
}

/// Reads, resolves and plans a scenario file with the default budgets, as
/// raised or lowered by the file's own `limits` (the caller chose the file).
pub fn load_file(path: &Path) -> Result<Loaded, LoadError> {
    load_file_with(path, trusted())
}

/// Reads, resolves and plans a scenario file.
pub fn load_file_with(path: &Path, options: LoadOptions) -> Result<Loaded, LoadError> {
    let (source, file) = read_source(path)?;
    load_str_with(&source, &file, options)
}

/// Reads a scenario file for `vbi modes`, which needs no vehicles
/// ([`bridge_only::load_for_modes`]).
pub fn load_file_for_modes(
    path: &Path,
    options: LoadOptions,
) -> Result<bridge_only::ModesScene, LoadError> {
    let (source, file) = read_source(path)?;
    bridge_only::load_for_modes(&source, &file, options)
}

/// Parses, resolves and plans a scenario from text with the default
/// budgets, as raised or lowered by its own `limits`; `file` labels
/// diagnostics.
pub fn load_str(source: &str, file: &str) -> Result<Loaded, LoadError> {
    load_str_with(source, file, trusted())
}

/// Parses, resolves and plans a scenario from text; `file` labels
/// diagnostics: [`crate::scenario::load_str_with`], then [`plan`]. Every
/// diagnostic of the format and of the plan comes in one round.
pub fn load_str_with(source: &str, file: &str, options: LoadOptions) -> Result<Loaded, LoadError> {
    plan(crate::scenario::load_str_with(source, file, options)?)
}

/// Checks and plans a scene the caller already parsed with the default
/// budgets, as raised or lowered by its own `limits`
/// ([`crate::scenario::load_value`], then [`plan`]); diagnostics name key
/// paths.
pub fn load_value(value: &serde_json::Value, file: &str) -> Result<Loaded, LoadError> {
    load_value_with(value, file, trusted())
}

/// Checks and plans a scene the caller already parsed
/// ([`crate::scenario::load_value_with`], then [`plan`]); diagnostics name
/// key paths.
pub fn load_value_with(
    value: &serde_json::Value,
    file: &str,
    options: LoadOptions,
) -> Result<Loaded, LoadError> {
    plan(crate::scenario::load_value_with(value, file, options)?)
}
