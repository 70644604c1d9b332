//! The scenario format as written by the user: serde + schemars types.
//!
//! These are the "low" arguments (ripgrep's `lowargs`): optional fields stay
//! `Option`, nothing is checked beyond syntax and types. [`super::resolve`]
//! turns them into the validated [`crate::scene::Scenario`]. Every field's
//! doc comment becomes its description in the JSON Schema, so each states its
//! unit. Tagged unions are dispatched on a `type` key by our own deserializer
//! ([`super::de`]), which keeps source locations; `#[schemars(tag = "type")]`
//! makes the schema describe the same shape.

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::{PlateEdges, PlateMoment, Quantity, SolverMethod, Terms};

mod aashto;
mod bridge;
mod elements;
mod envelopes;
mod fe_import;
mod ground;
mod hslm;
mod limits;
mod output;
mod rail;
mod resonance;
mod speed;
mod study;
mod surface;
mod truck;
pub mod units;
mod vehicle;
pub use self::aashto::*;
pub use self::bridge::*;
pub use self::elements::*;
pub use self::envelopes::*;
pub use self::fe_import::*;
pub use self::ground::*;
pub use self::hslm::*;
pub use self::limits::*;
pub use self::output::*;
pub use self::rail::*;
pub use self::resonance::*;
pub use self::speed::*;
pub use self::study::*;
pub use self::surface::*;
pub use self::truck::*;
pub use self::vehicle::*;

/// One vehicle–bridge interaction scene: a bridge, the vehicles crossing it,
/// the surface they ride on, the contact model, the solver and what to record.
///
/// Conventions: SI units throughout. Vertical displacements, velocities and
/// accelerations are positive UPWARD (a sagging bridge has negative
/// deflection); roughness is positive upward (a bump); contact forces are
/// positive in compression (wheel pressing on the deck). x runs along the
/// bridge from the entrance (x = 0) to the exit.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ScenarioRaw {
    /// Short name of the scene, used in reports.
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub name: String,
    /// Free text describing the scene and its source.
    #[serde(default)]
    pub description: Option<String>,
    /// Gravitational acceleration, m/s². Default {{DEFAULT_GRAVITY}}.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[schemars(extend("default" = super::resolve::DEFAULT_GRAVITY))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub gravity: Option<f64>,
    /// The bridge.
    pub bridge: BridgeRaw,
    /// The vehicles crossing the bridge (at least one).
    #[schemars(transform = crate::scene::schema_rules::non_empty)]
    pub vehicles: Vec<VehicleRaw>,
    /// The road or rail surface profile. Default: smooth.
    #[serde(default)]
    pub surface: Option<SurfaceRaw>,
    /// The wheel–bridge contact model. Default: permanent contact.
    #[serde(default)]
    pub contact: Option<ContactRaw>,
    /// Time integration settings. Defaults: coupled solver, average-acceleration Newmark.
    #[serde(default)]
    pub solver: Option<SolverRaw>,
    /// What to record. Default: bridge displacement at the middle of every
    /// span and the contact force of every wheel.
    #[serde(default)]
    pub record: Option<Vec<RecordRaw>>,
    /// Earthquake ground motion: acceleration records, each in one
    /// direction, applied as a uniform support excitation. Default: none.
    #[serde(default)]
    pub ground_motion: Option<Vec<GroundMotionRaw>>,
    /// Maxima and minima of bridge quantities at every point along the deck
    /// (beams), written to `envelopes.csv`. Default: none.
    #[serde(default)]
    pub envelopes: Option<EnvelopesRaw>,
    /// How the recorded history is written: every N-th step or an interval
    /// in seconds, CSV and/or NPY. Default: every step, CSV.
    #[serde(default)]
    pub output: Option<OutputRaw>,
    /// A study over many variants of this scene instead of one run.
    #[serde(default)]
    pub study: Option<StudyRaw>,
    /// Resource budgets (DOFs, steps, wheels, records, study points, output
    /// size). Defaults suit a workstation; raise one here when a scene needs it.
    #[serde(default)]
    pub limits: Option<LimitsRaw>,
    /// Advice ids this scene leaves unheeded, each with the reason
    /// (docs/advice.md lists the ids): the advice is still made and kept in
    /// the outputs with the reason, and no longer counts as a warning
    /// (`--deny-warnings`). Default: none.
    #[serde(default)]
    pub allow: Option<Vec<AllowRaw>>,
}

/// One advice id the scene leaves unheeded.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AllowRaw {
    /// The advice id (docs/advice.md), e.g. `run-ends-at-peak`.
    pub id: String,
    /// Why the advice does not apply to this scene; kept in the outputs.
    pub reason: String,
}

/// Wheel–bridge contact model.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum ContactRaw {
    /// Every wheel follows the bridge surface at all times; the contact force
    /// may become negative (tension), which flags where separation would occur.
    /// Solved by `method: coupled`.
    Permanent,
    /// Rigid unilateral contact: at every wheel gap ≥ 0, force ≥ 0 and
    /// gap · force = 0 (`method: lcp`; the LCP separation paper, Section 3),
    /// stepped by Moreau–Jean: one linear complementarity problem per step for
    /// the contact impulses, with Newton's impact law at every landing.
    Rigid {
        /// Newton's coefficient of restitution e (dimensionless, 0 to 1): a
        /// landing wheel leaves with −e times its approach velocity relative
        /// to the surface. 0 (default): perfectly inelastic, the wheel stays
        /// on the surface (a steel wheel on a rail or a tyre on a deck, whose
        /// local compression is far stiffer and shorter than anything the
        /// vehicle and bridge resolve, dissipates nearly all of it); 1: an
        /// elastic bounce that keeps the energy.
        #[serde(default)]
        restitution: Option<f64>,
    },
    /// Elastic unilateral contact: a linear tensionless spring under each wheel,
    /// force = stiffness · compression when compressed, else 0 (the LCP paper's
    /// Section 4 relaxation form; `method: lcp`). Give `stiffness` or `stiffness_ratio`.
    Elastic {
        /// Contact spring stiffness per wheel, N/m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
        stiffness: Option<f64>,
        /// Contact-to-suspension stiffness ratio k_c / k_v (dimensionless); the
        /// stiffness is this times the suspension stiffness of the oscillator(s),
        /// which must then all have the same suspension stiffness.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        stiffness_ratio: Option<f64>,
    },
    /// Hertzian wheel–rail contact: force = C · compression^1.5 when compressed,
    /// else 0 (`method: lcp`, with Newton iterations on the linearised law per
    /// step). Give `coefficient`, or `wheel_radius` to compute it.
    Hertz {
        /// Hertz coefficient C, N/m^1.5.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::hertz_coefficient::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::hertz_coefficient::schema")]
        coefficient: Option<f64>,
        /// Wheel rolling radius, m; C = G^-1.5 with the contact constant
        /// G = 4.57e-8 R^-0.149 m/N^(2/3) for a worn (LM) tread or
        /// G = 3.86e-8 R^-0.115 for a conical tread (Zhai, Vehicle–Track Coupled
        /// Dynamics, 2020, §2.4.1).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        wheel_radius: Option<f64>,
        /// Tread profile for `wheel_radius`: `worn` (default) or `conical`.
        #[serde(default)]
        #[schemars(extend("default" = "worn"))]
        profile: Option<TreadProfile>,
    },
}

/// Wheel tread profile, for the Hertz contact constant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TreadProfile {
    /// Worn (LM) tread: G = 4.57e-8 R^-0.149.
    Worn,
    /// Conical tread: G = 3.86e-8 R^-0.115.
    Conical,
}

/// Time integration settings.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SolverRaw {
    /// Solution method. Default: `coupled` for permanent contact, `lcp` for
    /// unilateral contact (rigid, elastic, Hertz).
    #[serde(default)]
    pub method: Option<SolverMethod>,
    /// Time step, s. Default: 1 / ({{STEPS_PER_PERIOD}} f_max), f_max the
    /// highest frequency excited: the vehicles', axle passing, span crossing
    /// and roughness frequencies (see `bridge.modes`) and the bridge modes up
    /// to {{SAFETY}} × the highest of them (every mode kept under a wheel
    /// with a mass of its own held on the deck, ground motion or a recorded
    /// reaction or shear; the modes above, kept for the quasi-static shape,
    /// respond quasi-statically and need no resolution); at most
    /// 1/{{CROSSING_STEPS}} of the shortest crossing; with recorded deck
    /// accelerations, short enough that the phase of each mode they sum
    /// drifts less than {{PHASE_BUDGET}} rad (Newmark's period error
    /// (ωΔt)²/12) over the run or, where shorter, the decay time 1/(ζω) of
    /// its free vibration (the whole run under ground motion); under ground
    /// motion, at most the record's shortest sampling interval. The
    /// resolved scenario gives the step and the summary says which rule
    /// set it.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub time_step: Option<f64>,
    /// Newmark parameters. Default β = 1/4, γ = 1/2, α = 0 (average
    /// acceleration: unconditionally stable, second order, no numerical
    /// damping); with rigid contact α = {{DEFAULT_RIGID_ALPHA}} (HHT).
    #[serde(default)]
    pub newmark: Option<NewmarkRaw>,
    /// Free-vibration time recorded after the last axle leaves the bridge, s. Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub free_vibration: Option<f64>,
    /// `method: iterative` only: relative tolerance ε on the contact
    /// displacements between iterations, max|Δw| ≤ ε·max|w| (the plate paper's
    /// Eq. 32; dimensionless). Default {{DEFAULT_TOLERANCE}}.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::iteration_tolerance)]
    #[schemars(extend("default" = crate::scene::DEFAULT_TOLERANCE))]
    pub tolerance: Option<f64>,
    /// `method: iterative` only: most iterations allowed in one time step
    /// before the run stops with an error. Default {{DEFAULT_MAX_ITERATIONS}}.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::max_iterations)]
    #[schemars(extend("default" = crate::scene::DEFAULT_MAX_ITERATIONS))]
    pub max_iterations: Option<usize>,
    /// `method: embs` only: add the first-order bridge response (the EMBS
    /// paper's Eq. 7) to the zero-order one (Eq. 5). Default true; false
    /// gives the zero-order EMBS alone.
    #[serde(default)]
    #[schemars(extend("default" = true))]
    pub first_order: Option<bool>,
    /// `method: embs` only: also solve the same scene with `coupled` and
    /// report, per recorded quantity, the EMBS error against it (largest
    /// difference over the run relative to the coupled peak) and the
    /// speed-up, in `summary.json` (`embs.comparison`). Default false.
    #[serde(default)]
    #[schemars(extend("default" = false))]
    pub compare: Option<bool>,
    /// `method: embs` only: run even where ε = ω_p/ω_B ≥ 1 in a contact
    /// direction whose quantities are recorded (the expansion cannot
    /// converge there, and such a run is otherwise refused unless
    /// `compare` is set). Default false.
    #[serde(default)]
    #[schemars(extend("default" = false))]
    pub allow_large_epsilon: Option<bool>,
}

/// Newmark-β parameters, with the Hilber–Hughes–Taylor α for numerical
/// damping of the highest frequencies.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct NewmarkRaw {
    /// β (dimensionless). Default 0.25, or (1 − α)²/4 when `alpha` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub beta: Option<f64>,
    /// γ (dimensionless). Default 0.5, or 1/2 − α when `alpha` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::newmark_gamma)]
    pub gamma: Option<f64>,
    /// HHT α in [−1/3, 0] (dimensionless). Default 0 (plain Newmark), except
    /// {{DEFAULT_RIGID_ALPHA}} with rigid contact when β and γ are not given. A negative α keeps
    /// second order and unconditional stability and damps the highest modes,
    /// which quiets the ringing of wheels held to the surface (rigid contact).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::hht_alpha)]
    pub alpha: Option<f64>,
}

/// One recorded quantity (a column of the time history).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RecordRaw {
    /// Column name in the CSV and key in summary.json.
    #[schemars(transform = crate::scene::schema_rules::non_empty_string)]
    pub name: String,
    /// What is recorded.
    pub quantity: Quantity,
    /// Position along the bridge, m (bridge quantities).
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub x: Option<f64>,
    /// Node of an imported (`fe_import`) bridge, instead of `x`: the
    /// quantity at that node's DOF `direction`.
    #[serde(default)]
    pub node: Option<u64>,
    /// Direction of the node's DOF (ux, uy, uz, rx, ry, rz). Default uz.
    #[serde(default)]
    pub direction: Option<crate::scene::imported::Direction>,
    /// Position across a plate deck, m (bridge quantities on a plate).
    /// Default: the deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub y: Option<f64>,
    /// Vehicle number, counted from 1 in the order of `vehicles` (vehicle
    /// quantities and contact forces). Default 1.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    #[schemars(extend("default" = 1))]
    pub vehicle: Option<usize>,
    /// Wheel number within the vehicle, counted from 1 front to rear
    /// (contact forces); on a train, over the whole train, or within `car`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub wheel: Option<usize>,
    /// Car of a train, counted from 1 front to rear: `wheel` then counts
    /// that car's wheelsets (1–4) and `dof` names that car's DOF.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub car: Option<usize>,
    /// Vehicle degree of freedom by name, e.g. `sprung` or `wheel` for the
    /// oscillator, `body_bounce` or `wheelset3` for a rail car (of a train:
    /// with `car`) (vehicle quantities).
    #[serde(default)]
    #[schemars(transform = crate::scenario::schema::dof_name)]
    pub dof: Option<String>,
    /// Highest mode frequency a bridge acceleration includes, Hz
    /// (`bridge_acceleration` only). Default, as EN 1990 A2.4.4.2.1(4) and
    /// EN 1991-2 6.4.6.5(3) ask for the deck-acceleration check: the greater
    /// of {{FLOOR_HZ}} Hz, {{FUNDAMENTAL_FACTOR}} f₁ and f₃, the bridge's own first and third natural
    /// frequencies whatever `bridge.modes` keeps. The automatic mode choice
    /// keeps every mode up to it; a `bridge.modes` that keeps fewer draws
    /// the warning `acceleration-filter-above-modes`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::frequency::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::frequency::schema")]
    pub max_frequency: Option<f64>,
    /// Under ground motion: `relative` to the moving ground (the default:
    /// deflections, what loads the structure) or `absolute` (adds the
    /// ground's own displacement or acceleration; what passengers feel).
    /// Bridge and vehicle displacements and accelerations only.
    #[serde(default)]
    #[schemars(extend("default" = "relative"))]
    pub frame: Option<crate::scene::Frame>,
    /// Which moment per unit width a `bridge_moment` on a plate deck
    /// records (N·m/m, sagging positive): `mx` longitudinal bending (the
    /// default), `my` transverse bending, `mxy` twisting.
    #[serde(default)]
    #[schemars(extend("default" = "mx"))]
    pub component: Option<PlateMoment>,
    /// Which side of `x` a beam's `bridge_shear` or `bridge_moment` is
    /// taken on: `right` (the right-hand limit, the default) or `left`. At
    /// a support the two shears differ by its reaction (`bridge_reaction`),
    /// where a wheel stands by its force.
    #[serde(default)]
    #[schemars(extend("default" = "right"))]
    pub side: Option<crate::scene::Side>,
}
