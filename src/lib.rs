//! vbi — declarative vehicle–bridge interaction dynamics.
//!
//! A scene flows one way through the stages: load ([`scenario`]) → build
//! ([`model`], [`bridge`], [`vehicle`], [`surface`]) → solve ([`solve`]) →
//! record ([`record`]) → report ([`report`]). [`run`] strings them together.
//! Units are SI throughout; vertical quantities are positive upward and
//! contact forces positive in compression.

#![warn(missing_docs)]

pub mod atomic_file;
pub mod bridge;
pub mod contact;
pub mod execute;
pub mod export;
pub mod generate;
pub mod ground;
pub mod model;
pub mod record;
pub mod report;
pub mod run;
pub mod scenario;
pub mod scene;
pub mod solve;
pub mod study;
pub mod surface;
pub mod text_table;
pub mod vehicle;

#[cfg(test)]
mod layers;

/// The JSON Schema of the format; it lives with the format ([`scenario::schema`]).
pub use scenario::schema;
