//! vbi — declarative vehicle–bridge interaction dynamics.
//!
//! A scene flows one way through layers that import only downward
//! (ARCHITECTURE.md has the map; `src/layers.rs` checks it): [`scene`] (the
//! resolved scene description, plain data) ← [`scenario`] (the format: YAML →
//! raw types → scene, every check that needs no physics, the JSON Schema) ←
//! the physics ([`contact`], [`ground`], [`surface`], [`vehicle`], [`bridge`])
//! ← [`plan`] (the modal bridge and every automatic choice) ← [`model`]
//! (the built system) ← [`solve`] ← [`record`] ← [`report`] (the only code
//! that writes results) ← [`run`] (one scene) ← [`study`] ← [`execute`]
//! (scene or study). Units are SI throughout; vertical quantities are
//! positive upward and contact forces positive in compression.
//!
//! # Using vbi as a library
//!
//! Three stages, three calls: load ([`scenario::load_str`],
//! [`scenario::load_file`], or [`scenario::load_value`] for data the caller
//! already parsed) reads and checks the scene and returns it described, as
//! owned data; plan ([`plan::plan`]) builds the bridge's modes and makes
//! every automatic choice (modes, time step, budgets, each with its reason)
//! and returns a [`plan::Loaded`]; run ([`execute::execute`], or
//! [`run::simulate`] for a scene) returns the results as data. Files are
//! written only when you hand the results to the report layer.
//! [`plan::load_file`] and [`plan::load_str`] do the first two in one call.
//!
//! ```
//! use vbi::execute::{Results, execute};
//!
//! let yaml = "
//! name: api-example
//! bridge: {type: beam, spans: [25.0], bending_stiffness: 8.323e9, mass_per_length: 2303.0,
//!          modes: {count: 4}, damping: {type: modal, ratio: 0.02}}
//! vehicles: [{type: moving_force, loads: [100.0e3], speed: 25.0}]
//! solver: {time_step: 1.0e-3}
//! record: [{name: midspan, quantity: bridge_displacement, x: 12.5}]
//! ";
//! // Load: the format's checks, every one that needs no physics.
//! let described = vbi::scenario::load_str(yaml, "api-example.yaml")?;
//! assert_eq!(described.name(), "api-example");
//! // Plan: the modal bridge and the automatic choices, each with its reason.
//! let loaded = vbi::plan::plan(described)?;
//! assert_eq!(loaded.scenario.solver.time_step_selection, "set in the file");
//! // Run.
//! let Results::Scene(outcome) = execute(loaded.clone(), &|_done, _total| {})? else {
//!     unreachable!("a scene without a study")
//! };
//! // The results as data: the midspan's largest downward deflection, m.
//! let midspan = &outcome.summary.quantities[0];
//! assert_eq!(midspan.name, "midspan");
//! assert!(midspan.min.value < 0.0);
//! // Files only through the report layer (summary.json, history.csv, …).
//! let out = std::env::temp_dir().join(format!("vbi-api-example-{}", std::process::id()));
//! vbi::run::write_results(&out, &loaded.scenario, &outcome)?;
//! assert!(out.join("summary.json").exists());
//! # std::fs::remove_dir_all(&out)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod advice;
pub mod atomic_file;
pub mod bridge;
pub mod contact;
pub mod execute;
pub mod export;
pub mod format_reference;
pub mod generate;
pub mod ground;
pub mod guarded_file;
pub mod init;
pub mod model;
pub mod plan;
pub mod record;
pub mod regress;
pub mod report;
pub mod run;
pub mod scenario;
pub mod scene;
pub mod solve;
pub mod study;
pub mod surface;
pub mod text_table;
pub mod timings;
pub mod vehicle;

#[cfg(test)]
mod layers;

/// The JSON Schema of the format; it lives with the format ([`scenario::schema`]).
pub use scenario::schema;
