//! The validated scenario with every default filled in (ripgrep's `hiargs`).
//!
//! Everything after loading sees only these types. They serialise to the same
//! shape as the input format, so the resolved scenario written next to the
//! results can be run again as it is.

use serde::Serialize;

pub mod aashto;
pub mod automatic;
mod bridge;
pub mod dof_names;
mod fe_import;
mod ground;
pub mod hslm;
pub mod imported;
mod limits;
pub mod motion;
mod output;
mod rail;
pub mod schema_rules;
mod solver;
mod spectrum;
mod study;
mod surface;
mod vehicle;
pub use self::bridge::*;
pub use self::fe_import::*;
pub use self::ground::*;
pub use self::limits::*;
pub use self::output::*;
pub use self::rail::*;
pub use self::solver::*;
pub use self::spectrum::*;
pub use self::study::*;
pub use self::surface::*;
pub use self::vehicle::*;

/// One data file a scene read: the path as the resolved scene names it
/// (absolute) and the SHA-256 of its bytes, lower-case hex.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DataRead {
    /// The absolute path, as the resolved scene writes it.
    pub path: String,
    /// SHA-256 of the file's bytes as read, 64 lower-case hex digits.
    pub sha256: String,
}

/// A validated scene. See [`crate::scenario::raw::ScenarioRaw`] for the meaning of each field.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Scenario {
    /// The scene file it was loaded from (its canonical path), when the
    /// command line says: not part of the resolved form, but written in
    /// `resolved.yaml`'s header to say whose results an output folder holds
    /// ([`crate::run::folder_owner`]).
    #[serde(skip)]
    pub source_file: Option<String>,
    /// The data files the scene read (FE matrices, DOF maps, rail lists,
    /// ground-motion records, measured profiles), each with the SHA-256 of
    /// the bytes read: not part of the resolved form, but written in
    /// `resolved.yaml`'s header so that the file reruns from any folder
    /// reading exactly these files ([`DataRead`]).
    #[serde(skip)]
    pub data_read: Vec<DataRead>,
    /// Short name of the scene.
    pub name: String,
    /// Free text describing the scene.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// Advice ids the scene leaves unheeded, with the reasons
    /// ([`crate::advice::Allow`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub allow: Vec<crate::advice::Allow>,
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// The bridge.
    pub bridge: Bridge,
    /// The vehicles, in input order.
    pub vehicles: Vec<Vehicle>,
    /// The surface profile.
    pub surface: Surface,
    /// The contact model.
    pub contact: Contact,
    /// Time integration settings.
    pub solver: Solver,
    /// Recorded quantities.
    pub record: Vec<Record>,
    /// Earthquake ground motion components (none: the ground is still).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub ground_motion: Vec<GroundMotion>,
    /// Envelopes along the deck.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub envelopes: Option<Envelopes>,
    /// How the history is written.
    pub output: Output,
    /// A study over variants of the scene.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub study: Option<Study>,
    /// Resource budgets; written only when the file raised one.
    #[serde(skip_serializing_if = "Limits::is_default")]
    pub limits: Limits,
    /// Per vehicle, whether the input wrote its speed with the unit (or
    /// derived it, as from an oscillator's velocity ratio): such a speed is
    /// meant as given and draws no "km/h typed as m/s" warning. Not part of
    /// the resolved scene.
    #[serde(skip)]
    pub speeds_stated: Vec<bool>,
}

/// How the history is written (see the raw format's `output`).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Output {
    /// Steps between written samples (1: every step).
    pub every: usize,
    /// File format of the history.
    pub format: HistoryFormat,
}

impl Default for Output {
    fn default() -> Self {
        Self {
            every: 1,
            format: HistoryFormat::Csv,
        }
    }
}

/// Dimensionless groups of an oscillator (see the raw format).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Dimensionless {
    /// v / (2 f₁ L).
    pub velocity_ratio: f64,
    /// (m_s + m_u) / (m L).
    pub mass_ratio: f64,
    /// m_u / m_s.
    pub unsprung_ratio: f64,
    /// f₁ / f_v.
    pub frequency_ratio: f64,
    /// c / (2√(k m_s)).
    pub damping_ratio: f64,
}

impl Dimensionless {
    /// Physical oscillator parameters for a bridge with first natural
    /// frequency `f1` (Hz), length `length` (m) and mass per length `mass`
    /// (kg/m): m_s + m_u = μ m L, m_u = r m_s, k = m_s (2π f₁/ρ_f)²,
    /// c = 2ζ√(k m_s), v = 2α f₁ L.
    pub fn derive(&self, f1: f64, length: f64, mass: f64, entry_time: f64) -> Oscillator {
        let total = self.mass_ratio * mass * length;
        let sprung_mass = total / (1.0 + self.unsprung_ratio);
        let vehicle_frequency = f1 / self.frequency_ratio;
        let stiffness = sprung_mass * (2.0 * std::f64::consts::PI * vehicle_frequency).powi(2);
        Oscillator {
            sprung_mass,
            unsprung_mass: self.unsprung_ratio * sprung_mass,
            stiffness,
            damping: 2.0 * self.damping_ratio * (stiffness * sprung_mass).sqrt(),
            speed: 2.0 * self.velocity_ratio * f1 * length,
            acceleration: 0.0,
            entry_time,
            lateral_position: None,
            dimensionless: Some(*self),
        }
    }
}

/// Contact model.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Contact {
    /// Wheels always follow the surface.
    Permanent,
    /// Rigid unilateral contact (Moreau–Jean impacts).
    Rigid {
        /// Newton's coefficient of restitution, 0 to 1 (dimensionless).
        restitution: f64,
    },
    /// Tensionless linear spring per wheel.
    Elastic {
        /// N/m.
        stiffness: f64,
        /// k_c / k_v when the stiffness was derived from the suspension's.
        #[serde(skip_serializing_if = "Option::is_none")]
        stiffness_ratio: Option<f64>,
    },
    /// Hertz law force = C δ^1.5.
    Hertz {
        /// N/m^1.5.
        coefficient: f64,
    },
}

impl Contact {
    /// Whether wheels may separate.
    pub fn is_unilateral(&self) -> bool {
        !matches!(self, Contact::Permanent)
    }
}

/// Time integration settings.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Solver {
    /// Method.
    pub method: SolverMethod,
    /// Time step, s.
    pub time_step: f64,
    /// Newmark parameters.
    pub newmark: Newmark,
    /// Free vibration after the last axle leaves, s.
    pub free_vibration: f64,
    /// Convergence settings (`iterative` only).
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub iteration: Option<Iteration>,
    /// EMBS settings (`embs` only).
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub embs: Option<EmbsOptions>,
    /// How the time step was chosen, in words (the summary states it; not
    /// written to `resolved.yaml`, which gives the step itself).
    #[serde(skip)]
    pub time_step_selection: String,
}

/// Settings of the `embs` solver.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct EmbsOptions {
    /// Whether the first-order bridge response is added.
    pub first_order: bool,
    /// Whether the scene is also solved by `coupled` for comparison.
    pub compare: bool,
    /// Whether to run where ε ≥ 1 in a recorded direction
    /// ([`crate::solve::embs_scale::refusal`]).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub allow_large_epsilon: bool,
}

/// Convergence settings of the `iterative` solver.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Iteration {
    /// Relative tolerance on the contact displacements, dimensionless.
    pub tolerance: f64,
    /// Most iterations per step.
    pub max_iterations: usize,
}

/// The iterative solver's default relative tolerance ε (dimensionless).
pub const DEFAULT_TOLERANCE: f64 = 1e-8;
/// The iterative solver's default iteration limit per step.
pub const DEFAULT_MAX_ITERATIONS: usize = 100;

impl Default for Iteration {
    fn default() -> Self {
        Self {
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: DEFAULT_MAX_ITERATIONS,
        }
    }
}

/// Newmark-β parameters.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Newmark {
    /// β.
    pub beta: f64,
    /// γ.
    pub gamma: f64,
    /// HHT α (0 = plain Newmark).
    pub alpha: f64,
}

/// Envelopes along the deck (beams; see the raw format).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Envelopes {
    /// The bridge quantities enveloped, in output order.
    pub quantities: Vec<Quantity>,
    /// Evenly spaced points from entrance to exit; `None`: every mesh node.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<usize>,
    /// Highest mode frequency of the acceleration envelope, Hz.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_frequency: Option<f64>,
}

/// One recorded quantity.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Record {
    /// Column name.
    pub name: String,
    /// Quantity.
    pub quantity: Quantity,
    /// Position along the bridge, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub x: Option<f64>,
    /// Node of an imported bridge (instead of `x`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub node: Option<u64>,
    /// Direction of the node's DOF.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub direction: Option<imported::Direction>,
    /// Position across a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub y: Option<f64>,
    /// Vehicle number from 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vehicle: Option<usize>,
    /// Wheel number from 1 (on a train, counted over the whole train: car
    /// k's wheelsets are 4k−3 … 4k).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wheel: Option<usize>,
    /// Vehicle DOF name (on a train, `car{k}_` and the car's DOF name).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dof: Option<String>,
    /// Bridge accelerations: the highest mode frequency summed, Hz (modes
    /// above it are left out, the deck-acceleration filter of EN 1990
    /// A2.4.4.2.1(4)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_frequency: Option<f64>,
    /// Relative to the moving ground, or absolute (bridge and vehicle
    /// displacements and accelerations under ground motion).
    #[serde(skip_serializing_if = "Frame::is_relative")]
    pub frame: Frame,
    /// A plate's moment per unit width (`bridge_moment` on a plate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub component: Option<PlateMoment>,
    /// The side of `x` a beam's shear or moment is taken on (`None`: the
    /// right-hand limit; written only when the file asks for the left).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub side: Option<Side>,
}
