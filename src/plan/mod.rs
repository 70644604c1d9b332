//! The planning stage: a scene the format described ([`crate::scenario`])
//! becomes a plan to run, the bridge's modal model built and every
//! automatic choice that needs physics made, each with its reason:
//!
//! - the modes kept (a Sturm count before any solve where the cut-off alone
//!   decides; the excitations the vehicles and the surface bring; twice the
//!   minimum under heavy wheels; 90 % of the mass under ground motion), its
//!   reason in the bridge's `selection`;
//! - the default time step (steps per period of the highest frequency kept
//!   or excited, steps per crossing, the phase drift of deck accelerations,
//!   the ground records' sampling), its reason in `solver.time_step_selection`;
//! - the budgets that need a mode count or the eigen solve's size;
//! - oscillators given by dimensionless groups (they need f₁).
//!
//! Data flow: [`load_str`] → the format (`scenario::resolve_with`:
//! YAML → raw → the described scene, every check that needs no physics) →
//! `choices::plan` → [`Loaded`], which [`crate::run`] runs. Errors found
//! here carry the file, line and column of the key they blame, as the
//! format's own.

pub mod bridge_only;
mod budget;
mod choices;
pub mod content;
mod derive;
mod plausible;
mod sweep;
mod travel;

use std::path::Path;

use crate::bridge::ModalBridge;
use crate::scenario::{LoadError, LoadOptions, read_source, resolve_with, trusted};
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
/// diagnostics. Every diagnostic of the format and of the plan comes in
/// one round, as [`crate::scenario::resolve_with`] describes.
pub fn load_str_with(source: &str, file: &str, options: LoadOptions) -> Result<Loaded, LoadError> {
    resolve_with(source, file, options, choices::plan)
        .map(|(scenario, bridge)| Loaded { scenario, bridge })
}
