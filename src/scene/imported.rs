//! An imported finite-element model as read and checked: its free DOFs,
//! matrices and rails (the readers and the modal reduction:
//! `crate::bridge::fe_import`).

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A displacement or rotation direction of a node.
#[derive(
    Debug,
    Clone,
    Copy,
    Default,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
    Serialize,
    Deserialize,
    JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// Along the track, m.
    Ux,
    /// Lateral, m.
    Uy,
    /// Vertical, up, m.
    #[default]
    Uz,
    /// Rotation about x, rad.
    Rx,
    /// Rotation about y (lateral axis), rad.
    Ry,
    /// Rotation about z, rad.
    Rz,
}

/// How the file's slope rotations turn into this program's right-handed
/// ones (∂w/∂x = −ry, ∂v/∂x = +rz): ry here = `ry` × ry in the file, and the
/// same for rz. A 2D textbook beam's θ = +∂w/∂x written as ry needs
/// `ry: -1`. The files' K, M and C are read with the sign of every entry
/// with exactly one such rotation index flipped (θ = −ry is a change of
/// variable: frequencies unchanged, mode shapes' rotations negated), and a
/// record of the rotation reports the right-handed value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RotationSign {
    /// Sign of the file's ry (−1 or +1; default +1): −1 when the file's ry
    /// is the slope +∂w/∂x.
    #[serde(default = "plus_one")]
    #[schemars(transform = super::schema_rules::sign)]
    pub ry: i64,
    /// Sign of the file's rz (−1 or +1; default +1): −1 when the file's rz
    /// is −∂v/∂x.
    #[serde(default = "plus_one")]
    #[schemars(transform = super::schema_rules::sign)]
    pub rz: i64,
}

fn plus_one() -> i64 {
    1
}

/// An imported model on its free DOFs, with its rails.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportedModel {
    /// (node, direction) of each free DOF.
    pub dofs: Vec<(u64, Direction)>,
    /// Stiffness, both triangles, on the free DOFs (N/m, N·m/rad).
    pub stiffness: Vec<(usize, usize, f64)>,
    /// Mass, both triangles, on the free DOFs (kg, kg·m²).
    pub mass: Vec<(usize, usize, f64)>,
    /// Damping, both triangles, on the free DOFs (N·s/m), if given.
    pub damping: Option<Vec<(usize, usize, f64)>>,
    /// The rails, x from the deck entrance.
    pub rails: Vec<RailDofs>,
    /// Indices of the rails the vehicles run on (their average).
    pub track: Vec<usize>,
    /// Deck length: from the first rail node to the last, m.
    pub length: f64,
    /// Mass moving with a rigid vertical translation of every node (all
    /// uz DOFs, constrained ones included), kg.
    pub vertical_mass: f64,
    /// M δ on the free DOFs, δ = 1 on every uz DOF (constrained ones
    /// included: the supports move with the ground), kg: the inertia load
    /// of a unit vertical ground acceleration ([`crate::ground`]).
    pub vertical_inertia: Vec<f64>,
    /// M δ on the free DOFs, δ = 1 on every uy DOF (constrained ones
    /// included), kg: the inertia load of a unit lateral ground
    /// acceleration; all zero for a model without lateral DOFs.
    pub lateral_inertia: Vec<f64>,
    /// How a wheel's load passes onto the track at its ends ([`entry`]);
    /// none unless the scene sets it.
    pub entry: RailEntry,
}

/// One rail: its nodes along the track and where their DOFs sit among the
/// free DOFs of the imported model.
#[derive(Debug, Clone, PartialEq)]
pub struct RailDofs {
    /// Rail name.
    pub name: String,
    /// Node ids along the rail.
    pub nodes: Vec<u64>,
    /// Node positions from the deck entrance, m, strictly increasing.
    pub x: Vec<f64>,
    /// Free DOF of each node's displacement (None: constrained, 0), per direction:
    /// [vertical, lateral].
    pub displacement: [Vec<Option<usize>>; 2],
    /// Free DOF of each node's slope rotation (None: constrained or absent),
    /// per direction: [ry, rz].
    pub rotation: [Vec<Option<usize>>; 2],
    /// Whether every node has the slope rotation (Hermite), per direction.
    pub hermite: [bool; 2],
}

/// The entry weights at both ends of a track: x of the first and last rail
/// node (the deck's ends, m) and the entry length at each (m; 0: the load
/// enters at once, as on a beam whose end node is held by its support).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RailEntry {
    /// x of the track's first node, m.
    pub start: f64,
    /// x of the track's last node, m.
    pub end: f64,
    /// Entry length at the first node, m (0: none).
    pub entry: f64,
    /// Exit length at the last node, m (0: none).
    pub exit: f64,
}

impl Direction {
    /// In Abaqus's order, DOF 1 … 6.
    pub const ALL: [Direction; 6] = [
        Direction::Ux,
        Direction::Uy,
        Direction::Uz,
        Direction::Rx,
        Direction::Ry,
        Direction::Rz,
    ];

    /// Its name in files.
    pub fn name(self) -> &'static str {
        ["ux", "uy", "uz", "rx", "ry", "rz"][self.abaqus() as usize - 1]
    }

    /// Abaqus's DOF number, 1 … 6.
    pub fn abaqus(self) -> u8 {
        Self::ALL.iter().position(|&d| d == self).unwrap_or(0) as u8 + 1
    }

    /// Parses a name (case-insensitive).
    pub fn parse(s: &str) -> Option<Self> {
        let s = s.trim().to_ascii_lowercase();
        Self::ALL.into_iter().find(|d| d.name() == s)
    }

    /// Whether it is a rotation.
    pub fn is_rotation(self) -> bool {
        matches!(self, Direction::Rx | Direction::Ry | Direction::Rz)
    }
}

impl Default for RotationSign {
    fn default() -> Self {
        Self { ry: 1, rz: 1 }
    }
}

impl RotationSign {
    /// The sign of `direction` (1 for a translation or rx).
    pub fn of(&self, direction: Direction) -> i64 {
        match direction {
            Direction::Ry => self.ry,
            Direction::Rz => self.rz,
            _ => 1,
        }
    }

    /// Whether it is the default (nothing flipped).
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

impl ImportedModel {
    /// Whether the track's rail ends are free to move vertically, (first
    /// node, last node): a rail end on pads and sleepers rather than a deck
    /// end held by its support (whose constrained uz takes the load as it
    /// enters, so no entry length is needed there).
    pub fn free_rail_ends(&self) -> (bool, bool) {
        let free = |last: bool| {
            self.track.iter().any(|&r| {
                let uz = &self.rails[r].displacement[0];
                let node = if last { uz.last() } else { uz.first() };
                node.is_some_and(|d| d.is_some())
            })
        };
        (free(false), free(true))
    }

    /// Free DOF of (node, direction), if any.
    pub fn dof(&self, node: u64, direction: Direction) -> Option<usize> {
        self.dofs.iter().position(|&d| d == (node, direction))
    }
}
