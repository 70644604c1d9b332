//! The validated scenario with every default filled in (ripgrep's `hiargs`).
//!
//! Everything after loading sees only these types. They serialise to the same
//! shape as the input format, so the resolved scenario written next to the
//! results can be run again as it is.

use serde::Serialize;

mod fe_import;
mod ground;
mod rail;
mod study;
mod surface;
pub use self::fe_import::*;
pub use self::ground::*;
pub use self::rail::*;
pub use self::study::*;
pub use self::surface::*;
pub use crate::scenario::budget::Limits;

pub use crate::scenario::raw::{
    GridRaw as Grid, PlateEdgesRaw as PlateEdges, Quantity, SolverMethod, TermsRaw as Terms,
};

/// A validated scene. See [`crate::scenario::raw::ScenarioRaw`] for the meaning of each field.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Scenario {
    /// The scene file it was loaded from (its canonical path), when the
    /// command line says: not part of the resolved form, but written in
    /// `resolved.yaml`'s header to say whose results an output folder holds
    /// ([`crate::run::folder_owner`]).
    #[serde(skip)]
    pub source_file: Option<String>,
    /// Short name of the scene.
    pub name: String,
    /// Free text describing the scene.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
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
    pub format: crate::scenario::raw::HistoryFormat,
}

impl Default for Output {
    fn default() -> Self {
        Self {
            every: 1,
            format: crate::scenario::raw::HistoryFormat::Csv,
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

/// The bridge model.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Bridge {
    /// Euler–Bernoulli beam.
    Beam(Beam),
    /// Thin orthotropic plate deck.
    Plate(Plate),
    /// A finite-element model imported from files.
    FeImport(FeImport),
}

impl Bridge {
    /// Total length from the entrance to the exit, m.
    pub fn length(&self) -> f64 {
        self.spans().iter().sum()
    }

    /// Span lengths, m.
    pub fn spans(&self) -> &[f64] {
        match self {
            Bridge::Beam(beam) => &beam.spans,
            Bridge::Plate(plate) => &plate.spans,
            Bridge::FeImport(f) => &f.spans,
        }
    }

    /// Deck width, m (`None` for a beam, which has no transverse extent).
    pub fn width(&self) -> Option<f64> {
        match self {
            Bridge::Beam(_) | Bridge::FeImport(_) => None,
            Bridge::Plate(plate) => Some(plate.width),
        }
    }

    /// Mode selection.
    pub fn modes(&self) -> &Modes {
        match self {
            Bridge::Beam(beam) => &beam.modes,
            Bridge::Plate(plate) => &plate.modes,
            Bridge::FeImport(f) => &f.modes,
        }
    }

    /// Mode selection, to fill in.
    pub fn modes_mut(&mut self) -> &mut Modes {
        match self {
            Bridge::Beam(beam) => &mut beam.modes,
            Bridge::Plate(plate) => &mut plate.modes,
            Bridge::FeImport(f) => &mut f.modes,
        }
    }

    /// Mass per unit length along the bridge, kg/m (a plate: ρh × width).
    pub fn mass_per_length(&self) -> f64 {
        match self {
            Bridge::Beam(beam) => beam.mass_per_length,
            Bridge::Plate(plate) => plate.mass_per_area * plate.width,
            // The mass a rigid vertical translation moves, per deck length
            // (piers and all, when the model has them).
            Bridge::FeImport(f) => f.model.vertical_mass / f.model.length,
        }
    }

    /// Transverse lines on which the summary tabulates DAFs, m (a beam: one line at 0).
    pub fn girder_lines(&self) -> Vec<f64> {
        match self {
            Bridge::Beam(_) | Bridge::FeImport(_) => vec![0.0],
            Bridge::Plate(plate) => plate.girder_lines.clone(),
        }
    }
}

/// Thin plate deck.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Plate {
    /// Span lengths, m.
    pub spans: Vec<f64>,
    /// Width, m.
    pub width: f64,
    /// Thickness, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// Mass per unit area ρh, kg/m².
    pub mass_per_area: f64,
    /// Rigidities.
    pub rigidity: Rigidity,
    /// Longitudinal edge support.
    pub edges: PlateEdges,
    /// Rayleigh–Ritz basis size.
    pub terms: Terms,
    /// Finite elements per span of the longitudinal beam functions.
    pub elements_per_span: usize,
    /// Mode selection.
    pub modes: Modes,
    /// Structural damping.
    pub damping: Damping,
    /// Girder lines y, m.
    pub girder_lines: Vec<f64>,
}

/// Plate rigidities.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Rigidity {
    /// Isotropic: D = E h³ / (12(1 − ν²)).
    Isotropic {
        /// E, Pa.
        youngs_modulus: f64,
        /// ν, dimensionless.
        poisson_ratio: f64,
    },
    /// Orthotropic.
    Orthotropic {
        /// Dx, N·m.
        flexural_rigidity_x: f64,
        /// Dy, N·m.
        flexural_rigidity_y: f64,
        /// Dxy = G h³/12, N·m.
        torsional_rigidity: f64,
        /// H = ν_xy Dy + 2 Dxy, N·m.
        equivalent_rigidity: f64,
        /// ν_xy, dimensionless.
        poisson_ratio: f64,
    },
}

impl Rigidity {
    /// (Dx, Dy, D1, Dxy), N·m, for a plate of thickness `thickness` (m; used
    /// by the isotropic form only): isotropic Dx = Dy = D, D1 = νD,
    /// Dxy = D(1 − ν)/2; orthotropic D1 = ν_xy Dy.
    pub fn rigidities(&self, thickness: f64) -> (f64, f64, f64, f64) {
        match *self {
            Rigidity::Isotropic {
                youngs_modulus,
                poisson_ratio,
            } => {
                let d = youngs_modulus * thickness.powi(3)
                    / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
                (d, d, poisson_ratio * d, 0.5 * d * (1.0 - poisson_ratio))
            }
            Rigidity::Orthotropic {
                flexural_rigidity_x,
                flexural_rigidity_y,
                torsional_rigidity,
                poisson_ratio,
                ..
            } => (
                flexural_rigidity_x,
                flexural_rigidity_y,
                poisson_ratio * flexural_rigidity_y,
                torsional_rigidity,
            ),
        }
    }
}

/// Euler–Bernoulli beam bridge.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Beam {
    /// Span lengths, m.
    pub spans: Vec<f64>,
    /// Bending stiffness EI, N·m².
    pub bending_stiffness: f64,
    /// Mass per unit length, kg/m.
    pub mass_per_length: f64,
    /// Finite elements per span.
    pub elements_per_span: usize,
    /// Mode selection.
    pub modes: Modes,
    /// Structural damping.
    pub damping: Damping,
    /// Lateral bending and torsion (a 3D beam); `None` for a beam that
    /// moves in the vertical plane only.
    #[serde(skip_serializing_if = "Option::is_none", flatten)]
    pub sway: Option<BeamSway>,
}

/// What makes a beam 3D: lateral bending and torsion of a doubly symmetric
/// section (shear centre at the centroid, so the three motions are
/// uncoupled), with fork supports (no lateral displacement and no twist at
/// any support).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct BeamSway {
    /// Lateral bending stiffness EI_z, N·m².
    pub lateral_bending_stiffness: f64,
    /// Torsional stiffness GJ, N·m²/rad.
    pub torsional_stiffness: f64,
    /// Polar mass moment of inertia per length I_p, kg·m²/m.
    pub polar_mass: f64,
    /// Height of the rail heads above the shear centre h, m: a twist θ
    /// moves the rails sideways by −h θ.
    pub rail_height: f64,
}

/// Mode selection; at least one is set.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Modes {
    /// Keep the lowest `count` modes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<usize>,
    /// Keep modes up to this frequency, Hz.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_frequency: Option<f64>,
    /// Add the quasi-static share of the modes left out to recorded bridge
    /// displacements (mode-acceleration method).
    pub static_correction: bool,
}

/// Structural damping.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Damping {
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
}

impl Damping {
    /// Damping ratio of a mode with circular frequency `omega` (rad/s).
    ///
    /// Rayleigh: ζ(ω) = a₀/(2ω) + a₁ω/2 with a₀, a₁ solved so that ζ(ω₁) =
    /// ζ(ω₂) = ζ: a₀ = 2ζω₁ω₂/(ω₁+ω₂), a₁ = 2ζ/(ω₁+ω₂) (Chopra, Dynamics of
    /// Structures, eq. 11.4.9).
    pub fn ratio_at(&self, omega: f64) -> f64 {
        match *self {
            Damping::Modal { ratio } => ratio,
            Damping::Rayleigh { frequencies, ratio } => {
                let w1 = 2.0 * std::f64::consts::PI * frequencies[0];
                let w2 = 2.0 * std::f64::consts::PI * frequencies[1];
                let a0 = 2.0 * ratio * w1 * w2 / (w1 + w2);
                let a1 = 2.0 * ratio / (w1 + w2);
                a0 / (2.0 * omega) + a1 * omega / 2.0
            }
        }
    }
}

/// A vehicle.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Vehicle {
    /// Constant axle loads.
    MovingForce(MovingForce),
    /// Two-mass oscillator.
    Oscillator(Oscillator),
    /// H20-44 seven-DOF truck.
    #[serde(rename = "h20_44")]
    H20Truck(H20Truck),
    /// Four-axle 10-DOF rail car.
    RailCar(RailCar),
    /// A train of rail cars.
    Train(Train),
    /// A train of 27-DOF 3D cars.
    #[serde(rename = "train_3d")]
    Train3d(Train3d),
}

impl Vehicle {
    /// Transverse position of the vehicle's path on a plate deck, m.
    pub fn lateral_position(&self) -> Option<f64> {
        match self {
            Vehicle::MovingForce(v) => v.lateral_position,
            Vehicle::Oscillator(v) => v.lateral_position,
            Vehicle::H20Truck(v) => v.lateral_position,
            Vehicle::RailCar(v) => v.lateral_position,
            Vehicle::Train(v) => v.lateral_position,
            Vehicle::Train3d(v) => v.lateral_position,
        }
    }

    /// Constant acceleration, m/s².
    pub fn acceleration(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.acceleration,
            Vehicle::Oscillator(v) => v.acceleration,
            Vehicle::H20Truck(v) => v.acceleration,
            Vehicle::RailCar(v) => v.acceleration,
            Vehicle::Train(v) => v.acceleration,
            Vehicle::Train3d(v) => v.acceleration,
        }
    }

    /// Speed at t = 0, m/s.
    pub fn speed(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.speed,
            Vehicle::Oscillator(v) => v.speed,
            Vehicle::H20Truck(v) => v.speed,
            Vehicle::RailCar(v) => v.speed,
            Vehicle::Train(v) => v.speed,
            Vehicle::Train3d(v) => v.speed,
        }
    }
    /// Time at which the front axle reaches the entrance, s.
    pub fn entry_time(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.entry_time,
            Vehicle::Oscillator(v) => v.entry_time,
            Vehicle::H20Truck(v) => v.entry_time,
            Vehicle::RailCar(v) => v.entry_time,
            Vehicle::Train(v) => v.entry_time,
            Vehicle::Train3d(v) => v.entry_time,
        }
    }
    /// Sets the time at which the front axle reaches the entrance, s.
    pub fn set_entry_time(&mut self, t: f64) {
        match self {
            Vehicle::MovingForce(v) => v.entry_time = t,
            Vehicle::Oscillator(v) => v.entry_time = t,
            Vehicle::H20Truck(v) => v.entry_time = t,
            Vehicle::RailCar(v) => v.entry_time = t,
            Vehicle::Train(v) => v.entry_time = t,
            Vehicle::Train3d(v) => v.entry_time = t,
        }
    }
    /// Distance from the front axle back to the rear axle, m.
    pub fn length(&self) -> f64 {
        match self {
            Vehicle::MovingForce(v) => v.axle_spacings.iter().sum(),
            Vehicle::Oscillator(_) => 0.0,
            Vehicle::H20Truck(v) => {
                v.parameters.front_axle_to_centre + v.parameters.centre_to_rear_axle
            }
            Vehicle::RailCar(v) => wheelset_span(&v.parameters),
            Vehicle::Train(v) => v.length(),
            Vehicle::Train3d(v) => v.length(),
        }
    }
    /// Type name as written in the format.
    pub fn type_name(&self) -> &'static str {
        match self {
            Vehicle::MovingForce(_) => "moving_force",
            Vehicle::Oscillator(_) => "oscillator",
            Vehicle::H20Truck(_) => "h20_44",
            Vehicle::RailCar(_) => "rail_car",
            Vehicle::Train(_) => "train",
            Vehicle::Train3d(_) => "train_3d",
        }
    }
}

/// Constant axle loads.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MovingForce {
    /// Axle loads, N, front first.
    pub loads: Vec<f64>,
    /// Spacings between consecutive axles, m.
    pub axle_spacings: Vec<f64>,
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front axle reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
}

/// H20-44 truck.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct H20Truck {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front axle reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// Every parameter, preset values filled in.
    pub parameters: H20TruckParameters,
}

/// H20-44 parameters (see the raw format for each meaning); SI units.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct H20TruckParameters {
    /// kg.
    pub body_mass: f64,
    /// kg·m².
    pub body_pitch_inertia: f64,
    /// kg·m².
    pub body_roll_inertia: f64,
    /// kg.
    pub front_axle_mass: f64,
    /// kg.
    pub rear_axle_mass: f64,
    /// kg·m².
    pub front_axle_roll_inertia: f64,
    /// kg·m².
    pub rear_axle_roll_inertia: f64,
    /// m.
    pub front_axle_to_centre: f64,
    /// m.
    pub centre_to_rear_axle: f64,
    /// m.
    pub front_track: f64,
    /// m.
    pub rear_track: f64,
    /// m.
    pub front_suspension_spacing: f64,
    /// m.
    pub rear_suspension_spacing: f64,
    /// N/m.
    pub front_suspension_stiffness: f64,
    /// N/m.
    pub rear_suspension_stiffness: f64,
    /// N·s/m.
    pub front_suspension_damping: f64,
    /// N·s/m.
    pub rear_suspension_damping: f64,
    /// N/m.
    pub front_tyre_stiffness: f64,
    /// N/m.
    pub rear_tyre_stiffness: f64,
    /// N·s/m.
    pub front_tyre_damping: f64,
    /// N·s/m.
    pub rear_tyre_damping: f64,
}

/// Two-mass oscillator.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Oscillator {
    /// Sprung mass, kg.
    pub sprung_mass: f64,
    /// Unsprung mass, kg.
    pub unsprung_mass: f64,
    /// Suspension stiffness, N/m.
    pub stiffness: f64,
    /// Suspension damping, N·s/m.
    pub damping: f64,
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the wheel reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// The dimensionless groups these values were derived from, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dimensionless: Option<Dimensionless>,
}

/// Contact model.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Contact {
    /// Wheels always follow the surface.
    Permanent,
    /// Rigid unilateral contact.
    Rigid,
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

impl Default for Iteration {
    fn default() -> Self {
        Self {
            tolerance: 1e-8,
            max_iterations: 100,
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
    pub direction: Option<crate::bridge::fe_import::Direction>,
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
    pub component: Option<crate::bridge::plate::moments::PlateMoment>,
}
