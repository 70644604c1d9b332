//! Bridges imported from a finite-element program: stiffness and mass
//! matrices, the map from matrix rows to (node, direction), and the rails
//! the wheels run on.
//!
//! The readers, one per format, and the assembly that checks what they read
//! against each other are the format's (`scenario::fe_import`): this module
//! reduces the model to its modes ([`modal`]), those the scene moves
//! ([`excited`]); [`track`] interpolates
//! along the rails. Coordinates: x along the track, y lateral, z up; SI
//! units (K in N/m and N·m/rad, M in kg and kg·m², C in N·s/m).

pub mod entry;
pub mod excited;
pub mod modal;
pub mod reaction;
pub mod track;
