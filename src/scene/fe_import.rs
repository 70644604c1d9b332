//! The resolved `fe_import` bridge: absolute paths, the rails and track
//! named, and the model read and checked.

use std::sync::Arc;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::imported::{Axes, Direction, ImportedModel, RotationSign};
use super::{Damping, Modes};

/// An imported finite-element bridge.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct FeImport {
    /// Stiffness file, absolute path.
    pub stiffness: String,
    /// Mass file, absolute path.
    pub mass: String,
    /// DOF map file, absolute path (absent for Abaqus files).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dof_map: Option<String>,
    /// DOFs removed on import.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub constrained: Vec<NodeDof>,
    /// Damping.
    pub damping: ImportDamping,
    /// The rails.
    pub rails: Vec<RailInput>,
    /// The rails the vehicles run on.
    pub track: Vec<String>,
    /// Mode selection.
    pub modes: Modes,
    /// Signs of the files' slope rotations (ry here = sign × ry in the files).
    #[serde(skip_serializing_if = "RotationSign::is_default")]
    pub rotation_sign: RotationSign,
    /// The files' axes (y up: read turned into vbi's, z up).
    #[serde(skip_serializing_if = "Axes::is_default")]
    pub axes: Axes,
    /// Length over which a wheel's load enters the model at each free rail
    /// end, m (0: at once; [`crate::bridge::fe_import::entry`]).
    pub entry_length: f64,
    /// One span: the deck length from the first rail node to the last, m
    /// (the supports of an imported model are not known by position).
    #[serde(skip)]
    pub spans: Vec<f64>,
    /// The model read from the files.
    #[serde(skip)]
    pub model: Arc<ImportedModel>,
    /// Its mass and its static deflection under the vehicles, as the plan
    /// measured them (`None` before the plan).
    #[serde(skip)]
    pub totals: Option<super::imported::ImportedTotals>,
}

/// A rail as given.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RailInput {
    /// Name.
    pub name: String,
    /// CSV file, absolute path.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// Inline nodes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nodes: Option<Vec<RailNode>>,
}

/// Damping of an imported bridge.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum ImportDamping {
    /// Same ratio for every mode.
    Modal {
        /// Damping ratio, dimensionless.
        ratio: f64,
    },
    /// Rayleigh damping matched at two frequencies.
    Rayleigh {
        /// Frequencies, Hz.
        frequencies: [f64; 2],
        /// Damping ratio at both, dimensionless.
        ratio: f64,
    },
    /// A damping matrix, projected on each mode.
    Matrix {
        /// File, absolute path.
        file: String,
    },
}

impl ImportDamping {
    /// The ratio rule, when not a matrix.
    pub fn rule(&self) -> Option<Damping> {
        match *self {
            ImportDamping::Modal { ratio } => Some(Damping::Modal { ratio }),
            ImportDamping::Rayleigh { frequencies, ratio } => {
                Some(Damping::Rayleigh { frequencies, ratio })
            }
            ImportDamping::Matrix { .. } => None,
        }
    }
}

/// A node's DOF.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NodeDof {
    /// Node id.
    pub node: u64,
    /// Direction.
    pub direction: Direction,
}

/// A rail node inline.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RailNode {
    /// Node id.
    pub node: u64,
    /// Position along the track, m.
    pub x: f64,
}
