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

/// The files' axes: which of their directions is vbi's vertical. vbi's
/// own are x along the track, y lateral (to the left of travel) and z up.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Axes {
    /// x along the track, y lateral, z up (vbi's own): the files' names are
    /// read as they are.
    #[default]
    ZUp,
    /// x along the track, y up, z = x × y (to the right of travel), as an
    /// OpenSees 2D frame writes its DOFs (ndm 2, ndf 3: ux, uy, rz) or a 3D
    /// model built with y up: read as vbi's axes turned about x, the files'
    /// uy as uz, their uz as −uy, their ry as rz and their rz as −ry
    /// (OpenSees' rz = +∂v/∂x is vbi's ry = −∂w/∂x). The scene's own
    /// directions (`constrained`, records) are vbi's.
    YUp,
}

impl Axes {
    /// vbi's direction of the files' `direction`, and the sign that turns
    /// the files' value into vbi's.
    pub fn read(self, direction: Direction) -> (Direction, f64) {
        use Direction::*;
        match self {
            Axes::ZUp => (direction, 1.0),
            Axes::YUp => match direction {
                Ux => (Ux, 1.0),
                Uy => (Uz, 1.0),
                Uz => (Uy, -1.0),
                Rx => (Rx, 1.0),
                Ry => (Rz, 1.0),
                Rz => (Ry, -1.0),
            },
        }
    }

    /// The files' direction that is read as vbi's `direction`.
    pub fn written(self, direction: Direction) -> Direction {
        Direction::ALL
            .into_iter()
            .find(|&d| self.read(d).0 == direction)
            .unwrap_or(direction)
    }

    /// Its name in the scene.
    pub fn name(self) -> &'static str {
        match self {
            Axes::ZUp => "z_up",
            Axes::YUp => "y_up",
        }
    }

    /// Whether it is the default (vbi's axes).
    pub fn is_default(&self) -> bool {
        *self == Self::ZUp
    }
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
    /// Mass moving with a rigid translation of every node in x, y and z:
    /// δᵀMδ with δ = 1 on every DOF of the map in that direction
    /// (constrained ones included; DOFs the export dropped are not in the
    /// files), kg.
    pub translational_mass: [f64; 3],
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
    /// The rows of K and M at each DOF listed under `constrained`, on the
    /// free columns: what a support's reaction is read from,
    /// R = K_cf u + M_cf ü (issue 40.1).
    pub supports: Vec<SupportRow>,
}

/// One constrained DOF's coupling with the free DOFs: its rows of the
/// stiffness and mass matrices restricted to the free columns, and its
/// share of the rigid-translation inertia, for the support reaction
/// R_c = K_cf u_f + M_cf ü_f (+ the ground's inertia at the support).
#[derive(Debug, Clone, PartialEq)]
pub struct SupportRow {
    /// The node.
    pub node: u64,
    /// The constrained direction (vbi's axes).
    pub direction: Direction,
    /// K_cf: (free DOF, entry), N/m or N·m/rad (per unit of the free DOF).
    pub stiffness: Vec<(usize, f64)>,
    /// M_cf: (free DOF, entry), kg or kg·m.
    pub mass: Vec<(usize, f64)>,
    /// (M δ_z)_c over the whole matrix (the constrained columns included:
    /// the supports move with the ground), kg: the inertia at the support
    /// under a unit vertical ground acceleration.
    pub vertical_inertia: f64,
    /// (M δ_y)_c likewise, lateral, kg.
    pub lateral_inertia: f64,
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

    /// The spans the track's supports make, m, from the entrance: the
    /// intervals between consecutive track rail nodes with no free uz (a
    /// DOF the map leaves out or the scene lists under `constrained`),
    /// positions within 10⁻⁶ of the track's length taken as one support.
    /// Empty with fewer than two supports (a deck carried by modelled
    /// piers, whose rail nodes all move vertically, has no support here).
    pub fn supported_spans(&self) -> Vec<f64> {
        let mut supports: Vec<f64> = self
            .track
            .iter()
            .flat_map(|&r| {
                let rail = &self.rails[r];
                rail.x
                    .iter()
                    .zip(&rail.displacement[0])
                    .filter(|(_, dof)| dof.is_none())
                    .map(|(&x, _)| x)
            })
            .collect();
        supports.sort_by(f64::total_cmp);
        let tolerance = 1e-6 * self.length;
        supports.dedup_by(|a, b| (*a - *b).abs() <= tolerance);
        supports.windows(2).map(|w| w[1] - w[0]).collect()
    }

    /// Mass moving with a rigid vertical translation of every node (all
    /// uz DOFs of the map, constrained ones included), kg.
    pub fn vertical_mass(&self) -> f64 {
        self.translational_mass[2]
    }

    /// Free DOF of (node, direction), if any.
    pub fn dof(&self, node: u64, direction: Direction) -> Option<usize> {
        self.dofs.iter().position(|&d| d == (node, direction))
    }
}

/// What an engineer checks first on an imported model, before its modes:
/// how heavy it is and how far it deflects under the traffic
/// (`summary.json`'s `imported_model`, `vbi modes`; the plan's advice
/// warns where a bridge could not be so: a model in kN and t, or in mm).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImportedTotals {
    /// The track's length, from the first rail node to the last, m.
    pub length: f64,
    /// Mass moving with a rigid translation of the whole model in x (along
    /// the track), y (lateral) and z (up): δᵀMδ with δ = 1 on every DOF
    /// of the map in that direction, constrained ones included; DOFs the
    /// export dropped are not in the files, so a girder whose supports'
    /// DOFs were dropped reports a little less than its mass (a consistent
    /// mass of n elements: about 1.26/n of it less), kg.
    pub mass: TranslationalMass,
    /// The vertical mass per metre of track, `mass.z / length`, kg/m.
    pub mass_per_length: f64,
    /// The vehicles' total static weight, the sum of their static wheel
    /// loads, N; absent without vehicles.
    pub static_load: Option<f64>,
    /// Where on the track that weight stands for `static_deflection`: the
    /// most flexible of 101 points evenly along the track's centre line
    /// (its ends included: the middle of a single span), m from its start.
    pub static_load_x: Option<f64>,
    /// The static deflection there under the whole weight, W · G(x, x)
    /// with G the model's exact static flexibility (K⁻¹), downward
    /// positive, m: the plausibility figure (a bridge under its traffic
    /// deflects some span/500 to span/2000; a model in kN read as N, 1000
    /// times that).
    pub static_deflection: Option<f64>,
}

/// Translational mass per direction, kg.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TranslationalMass {
    /// Along the track, kg.
    pub x: f64,
    /// Lateral, kg.
    pub y: f64,
    /// Vertical, kg.
    pub z: f64,
}

impl ImportedModel {
    /// The model's [`ImportedTotals`] without the vehicles' static load.
    pub fn totals(&self) -> ImportedTotals {
        let [x, y, z] = self.translational_mass;
        ImportedTotals {
            length: self.length,
            mass: TranslationalMass { x, y, z },
            mass_per_length: z / self.length,
            static_load: None,
            static_load_x: None,
            static_deflection: None,
        }
    }
}
