//! The `fe_import` bridge: a finite-element model's matrices read from files.

use schemars::JsonSchema;
use serde::Deserialize;

use super::ModesRaw;
use crate::scene::NodeDof;
use crate::scene::imported::{Axes, RotationSign};

/// A bridge imported from a finite-element program: stiffness and mass
/// matrices (Matrix Market coordinate, Harwell–Boeing, Abaqus `*MATRIX
/// GENERATE` coordinate output or dense text, told apart by their content),
/// the DOF map and the rails the wheels run on. Paths are relative to the
/// scenario file. Coordinates: x along the track, y lateral, z vertical up
/// (`axes: y_up` reads a model with y up); SI units (N, kg, m).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FeImportRaw {
    /// Stiffness matrix K file (N/m, N·m/rad for rotations).
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub stiffness: String,
    /// Mass matrix M file (kg, kg·m² for rotations). Every free DOF needs a
    /// positive diagonal mass (massless DOFs are refused, not condensed).
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub mass: String,
    /// CSV `dof,node,direction` naming each matrix row (1-based) by node
    /// and direction (ux, uy, uz, rx, ry, rz). Not needed by an Abaqus
    /// file, which names its DOFs.
    #[serde(default)]
    pub dof_map: Option<String>,
    /// DOFs the matrices still hold but the supports fix: removed on import.
    #[serde(default)]
    pub constrained: Option<Vec<NodeDof>>,
    /// Damping: a modal ratio, Rayleigh, or a damping matrix file. Default:
    /// none (undamped).
    #[serde(default)]
    pub damping: Option<ImportDampingRaw>,
    /// The rails: each a list of nodes with their x along the track.
    pub rails: Vec<RailNodesRaw>,
    /// Names of the rails the vehicles run on: one, or two (a single-track
    /// 2D vehicle sees their average). Default: every rail, if one or two.
    #[serde(default)]
    pub track: Option<Vec<String>>,
    /// Which modes to keep. Default: chosen automatically, as for a beam,
    /// with at least {{MODES_PER_SPAN}} per span between the supports the
    /// track's rails find (rail nodes with no free uz: left out of the DOF
    /// map or listed under `constrained`; one span if fewer than two).
    #[serde(default)]
    pub modes: Option<ModesRaw>,
    /// Signs of the files' slope rotations against this program's
    /// right-handed ones (∂w/∂x = −ry, ∂v/∂x = +rz): `{ry: -1}` reads a
    /// textbook beam's θ = +∂w/∂x written as ry. Default `{ry: 1, rz: 1}`;
    /// a sign the stiffness contradicts along a rail is refused.
    #[serde(default)]
    pub rotation_sign: Option<RotationSign>,
    /// The files' axes: `z_up` (default; x along the track, y lateral, z
    /// up, vbi's own) or `y_up` (x along the track, y up, as an OpenSees 2D
    /// frame's `ux, uy, rz`): a y-up model's uy is read as uz, its uz as
    /// −uy, its ry as rz and its rz as −ry (the axes turned about x, so a
    /// right-handed rotation stays right-handed). The scene's own
    /// directions (`constrained`, records, `rotation_sign`) are vbi's.
    #[serde(default)]
    pub axes: Option<Axes>,
    /// Length over which a wheel's load passes from the rigid approach onto
    /// the model at a free rail end (and off it at the far end), m: the
    /// wheel couples to the rail with a weight rising from 0 at the rail
    /// end to 1 at this distance (quintic smoothstep), as a continuous rail
    /// takes a wheel's load before it arrives. Applies only where the
    /// track's end node is free to move vertically (not at a deck end held
    /// by its support). Default {{DEFAULT_ENTRY_LENGTH}} m (at most a quarter of the track); 0 puts
    /// the whole load on at once.
    #[serde(default)]
    #[schemars(range(min = 0.0))]
    #[schemars(extend("default" = crate::scenario::fe_import::DEFAULT_ENTRY_LENGTH))]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub entry_length: Option<f64>,
}

/// One rail: a CSV `node,x` file or the nodes inline.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RailNodesRaw {
    /// Rail name (for `track`).
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub name: String,
    /// CSV file with header `node,x` (x in m, strictly increasing).
    #[serde(default)]
    pub file: Option<String>,
    /// The nodes inline, in order along the rail.
    #[serde(default)]
    pub nodes: Option<Vec<RailNodeRaw>>,
}

/// A rail node inline.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "RailNode")]
pub struct RailNodeRaw {
    /// Node id.
    pub node: u64,
    /// Position along the track, m.
    #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub x: f64,
}

impl RailNodeRaw {
    /// The node as the resolved scene holds it (x in m).
    pub fn resolved(self) -> crate::scene::RailNode {
        crate::scene::RailNode {
            node: self.node,
            x: self.x,
        }
    }
}

/// Damping of an imported bridge.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum ImportDampingRaw {
    /// The same modal damping ratio ζ for every mode.
    Modal {
        /// Damping ratio ζ (fraction of critical, dimensionless).
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
    /// Rayleigh damping matched at two frequencies (Hz) with ratio ζ.
    Rayleigh {
        /// The two frequencies, Hz.
        #[schemars(transform = crate::scene::schema_rules::positive_items)]
        #[serde(deserialize_with = "crate::scenario::raw::units::frequency::pair")]
        #[schemars(schema_with = "crate::scenario::raw::units::frequency::pair_schema")]
        frequencies: [f64; 2],
        /// Damping ratio ζ at both (dimensionless).
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
    /// A damping matrix C (N·s/m) in the stiffness file's format and DOF
    /// numbering: mode i gets ζᵢ = φᵢᵀCφᵢ/(2ωᵢ) (its modal projection;
    /// the coupling terms φᵢᵀCφⱼ of a non-classical C are left out).
    Matrix {
        /// The damping matrix file.
        #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
        file: String,
    },
}
