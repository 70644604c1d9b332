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
    /// Gravitational acceleration, m/s². Default 9.81.
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
}

/// The bridge model.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
#[schemars(tag = "type")]
pub enum BridgeRaw {
    /// Euler–Bernoulli beam, simply supported or continuous over pinned
    /// supports, discretised with Hermite-cubic finite elements and reduced to
    /// mass-normalised modes.
    Beam(BeamRaw),
    /// Thin orthotropic (or isotropic) plate deck, jointless over one or more
    /// spans: simply supported at both ends, rigid line supports across the
    /// deck between spans, longitudinal edges free (or simply supported).
    /// Modes by the Rayleigh–Ritz method with beam functions, keeping the
    /// coupling between the longitudinal and transverse families (the plate
    /// paper's intermodal coupling). y runs across the deck from the edge
    /// y = 0 (the right-hand edge for traffic in +x) to y = width.
    Plate(PlateRaw),
    /// A finite-element model imported from files (matrices, DOF map, rails).
    FeImport(FeImportRaw),
}

/// Plate deck.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlateRaw {
    /// Span lengths, m, from the entrance; rigid line supports between spans.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub spans: Vec<f64>,
    /// Deck width b, m.
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub width: f64,
    /// Plate thickness h, m. Needed by an isotropic `rigidity` and by `density`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub thickness: Option<f64>,
    /// Mass per unit area ρh, kg/m². Give this or `density`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass_per_area::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass_per_area::schema")]
    pub mass_per_area: Option<f64>,
    /// Density ρ, kg/m³ (with `thickness`). Give this or `mass_per_area`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::density::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::density::schema")]
    pub density: Option<f64>,
    /// Flexural and torsional rigidities.
    pub rigidity: RigidityRaw,
    /// Support of the two longitudinal edges: `free` (default, a bridge deck)
    /// or `simply_supported`.
    #[serde(default)]
    #[schemars(extend("default" = "free"))]
    pub edges: Option<PlateEdges>,
    /// Size of the Rayleigh–Ritz basis. Default: 6 longitudinal beam
    /// functions per span (at least 12) × 8 transverse functions.
    #[serde(default)]
    pub terms: Option<Terms>,
    /// Finite elements per span of the continuous beam whose modes are the
    /// longitudinal beam functions. Default 20.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::elements_per_span)]
    #[schemars(extend("default" = super::resolve::DEFAULT_ELEMENTS_PER_SPAN))]
    pub elements_per_span: Option<usize>,
    /// Which modes the modal superposition keeps. Default: automatic, as for
    /// the beam (every mode up to 4 × the highest excitation), and at least 5
    /// per span of each of the bending, torsion and transverse-bending families
    /// (15 per span).
    #[serde(default)]
    pub modes: Option<ModesRaw>,
    /// Structural damping. Default: 0 (undamped).
    #[serde(default)]
    pub damping: Option<DampingRaw>,
    /// Transverse positions y of the girder lines, m: the summary tabulates
    /// the DAF at the middle of every span on each line. Default: the deck's
    /// centre line.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub girder_lines: Option<Vec<f64>>,
}

/// Plate rigidities.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum RigidityRaw {
    /// Isotropic plate of the deck's `thickness`: D = E h³ / (12 (1 − ν²)),
    /// Dx = Dy = H = D.
    Isotropic {
        /// Young's modulus E, Pa.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::pressure::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::pressure::schema")]
        youngs_modulus: f64,
        /// Poisson's ratio ν (dimensionless). Default 0.2 (concrete).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::isotropic_poisson)]
        #[schemars(extend("default" = super::bridges::DEFAULT_ISOTROPIC_POISSON))]
        poisson_ratio: Option<f64>,
    },
    /// Orthotropic plate (the plate paper's Eq. 1): Dx, Dy, and the torsional
    /// rigidity Dxy = G h³/12 or the equivalent rigidity H = ν_xy Dy + 2 Dxy.
    Orthotropic {
        /// Flexural rigidity along the bridge Dx, N·m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        flexural_rigidity_x: f64,
        /// Flexural rigidity across the bridge Dy, N·m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        flexural_rigidity_y: f64,
        /// Torsional rigidity Dxy = G h³ / 12, N·m. Give this or `equivalent_rigidity`.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        torsional_rigidity: Option<f64>,
        /// Equivalent rigidity H = ν_xy Dy + 2 Dxy, N·m. Give this or `torsional_rigidity`.
        #[serde(default)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        equivalent_rigidity: Option<f64>,
        /// Poisson's ratio ν_xy (dimensionless); the coupling rigidity is
        /// D1 = ν_xy Dy. Default 0.3.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        #[schemars(extend("default" = super::bridges::DEFAULT_ORTHOTROPIC_POISSON))]
        poisson_ratio: Option<f64>,
    },
}

/// Euler–Bernoulli beam bridge.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BeamRaw {
    /// Span lengths, m, from the entrance. One span = simply supported; several
    /// = continuous over pinned intermediate supports.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub spans: Vec<f64>,
    /// Bending stiffness EI, N·m².
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::bending_stiffness::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::bending_stiffness::schema")]
    pub bending_stiffness: f64,
    /// Mass per unit length m, kg/m.
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass_per_length::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass_per_length::schema")]
    pub mass_per_length: f64,
    /// Hermite-cubic finite elements per span. Default 20.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::elements_per_span)]
    #[schemars(extend("default" = super::resolve::DEFAULT_ELEMENTS_PER_SPAN))]
    pub elements_per_span: Option<usize>,
    /// Which modes the modal superposition keeps. Default: automatic — every
    /// mode up to 4 × the highest frequency the scene excites (vehicle natural
    /// frequencies incl. wheel hop on an elastic contact, axle passing v/d,
    /// span crossing v/2L, roughness v/λ), and at least 5 per span; the
    /// resolved scenario gives the modes kept as `count` with the cut-off as
    /// `max_frequency` and the summary says why.
    #[serde(default)]
    pub modes: Option<ModesRaw>,
    /// Structural damping. Default: 0 (undamped).
    #[serde(default)]
    pub damping: Option<DampingRaw>,
    /// Lateral bending stiffness EI_z, N·m². With `torsional_stiffness`
    /// and `polar_mass` it makes the beam 3D: lateral bending and torsion
    /// modes (doubly symmetric section, fork supports: no lateral
    /// displacement and no twist at any support) besides the vertical ones,
    /// so a `train_3d` follows the rails laterally and a lateral ground
    /// motion shakes the deck.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::bending_stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::bending_stiffness::schema")]
    pub lateral_bending_stiffness: Option<f64>,
    /// Torsional stiffness GJ, N·m²/rad (3D beam).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::torsional_stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::torsional_stiffness::schema")]
    pub torsional_stiffness: Option<f64>,
    /// Polar mass moment of inertia per length I_p, kg·m²/m (3D beam).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia_per_length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia_per_length::schema")]
    pub polar_mass: Option<f64>,
    /// Height of the rail heads above the section's shear centre, m (3D
    /// beam): a twist θ moves the rails sideways by −h θ and a rail at y
    /// across the centre line up by y θ. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub rail_height: Option<f64>,
}

/// Mode selection: by count, by maximum frequency, or both (the stricter wins).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ModesRaw {
    /// Keep the lowest `count` modes.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub count: Option<usize>,
    /// Keep every mode whose natural frequency is at most this, Hz (within
    /// a relative 1e-8: a frequency copied as printed keeps its mode). With
    /// `count`: the lowest `count`, none of them above this.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::frequency::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::frequency::schema")]
    pub max_frequency: Option<f64>,
    /// Add the quasi-static share of the modes left out to every recorded
    /// bridge displacement (the mode-acceleration method: the exact static
    /// deflection under the current wheel forces minus its modal part), so
    /// few modes give converged deflections. Default true.
    #[serde(default)]
    pub static_correction: Option<bool>,
}

/// Structural damping of the bridge.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum DampingRaw {
    /// The same modal damping ratio ζ for every mode.
    Modal {
        /// Damping ratio ζ (fraction of critical, dimensionless), e.g. 0.02.
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
    /// Rayleigh damping C = a₀M + a₁K with the given ratio at two frequencies;
    /// mode i then has ζᵢ = a₀/(2ωᵢ) + a₁ωᵢ/2.
    Rayleigh {
        /// The two frequencies where the damping ratio is matched, Hz.
        #[schemars(transform = crate::scene::schema_rules::positive_items)]
        #[serde(deserialize_with = "crate::scenario::raw::units::frequency::pair")]
        #[schemars(schema_with = "crate::scenario::raw::units::frequency::pair_schema")]
        frequencies: [f64; 2],
        /// Damping ratio ζ at both frequencies (dimensionless).
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
}

/// A vehicle crossing the bridge. Its reference point is its FRONT axle; the
/// other axles follow at their offsets behind it.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
#[schemars(tag = "type")]
// The truck's optional parameters make its variant large; a parse-time
// value made once per vehicle, so boxing would buy nothing.
#[allow(clippy::large_enum_variant)]
pub enum VehicleRaw {
    /// A set of constant vertical axle loads at fixed spacings (no inertia).
    MovingForce(MovingForceRaw),
    /// Moving oscillator: sprung mass on a spring–damper over a wheel mass
    /// (the LCP paper's Fig. 1). `unsprung_mass: 0` is the 1-DOF sprung mass
    /// on a massless wheel (Yang & Yau 1997).
    Oscillator(OscillatorRaw),
    /// AASHTO H20-44 two-axle truck with seven DOFs (body bounce, pitch and
    /// roll; each axle bounce and roll), a tyre spring–damper under each of
    /// its four wheels and a suspension spring–damper above it (the plate
    /// paper's Section 2.2 and Appendix A). Parameters default to the preset
    /// (see `parameters`).
    #[serde(rename = "h20_44")]
    H20Truck(H20TruckRaw),
    /// Four-axle rail car with ten DOFs: car body and two bogies (bounce
    /// and pitch each) over four wheelsets (bounce), a primary
    /// spring–dashpot between each wheelset and its bogie and a secondary
    /// one between each bogie and the body (the LCP separation paper's
    /// Section 5.2). The wheelsets ride the rail through the contact model.
    /// Parameters default to the paper's Table 2 (see `parameters`).
    RailCar(RailCarRaw),
    /// A train of rail cars at one speed: `count` identical cars at
    /// `car_spacing`, or a `cars` list. Resolved into one vehicle whose
    /// wheels are every car's wheelsets, numbered front to rear.
    Train(TrainRaw),
    /// A train of 3D high-speed cars, 27 DOFs each (the EMBS paper's
    /// AVE-S103): body and bogies with lateral, vertical, yaw, roll and
    /// pitch motion over wheelsets that follow their rails vertically and
    /// laterally (permanent contact; no creep, no flange contact).
    #[serde(rename = "train_3d")]
    Train3d(Train3dRaw),
    /// An HSLM-A train of EN 1991-2 Annex E (`model: A1` … `A10`) as moving
    /// axle forces; resolved into a `moving_force` with its axle positions.
    Hslm(HslmRaw),
}

impl VehicleRaw {
    /// The speed as written (`None`: an oscillator given by its
    /// dimensionless groups, its speed derived from the velocity ratio).
    pub fn speed(&self) -> Option<SpeedRaw> {
        match self {
            VehicleRaw::MovingForce(v) => Some(v.speed),
            VehicleRaw::Oscillator(v) => v.speed,
            VehicleRaw::H20Truck(v) => Some(v.speed),
            VehicleRaw::RailCar(v) => Some(v.speed),
            VehicleRaw::Train(v) => Some(v.speed),
            VehicleRaw::Train3d(v) => Some(v.speed),
            VehicleRaw::Hslm(v) => Some(v.speed),
        }
    }
}

/// Where and how fast a vehicle travels.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MovingForceRaw {
    /// Axle loads, N (downward, positive), front axle first.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::force::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::force::list_schema")]
    pub loads: Vec<f64>,
    /// Distances between consecutive axles, m; one fewer than `loads`.
    /// Give this or `axle_positions`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive_items)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub axle_spacings: Option<Vec<f64>>,
    /// Distance of each axle behind the front axle, m: 0 first, then
    /// increasing; one per load (an axle-load train such as an HSLM train).
    /// Give this or `axle_spacings`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub axle_positions: Option<Vec<f64>>,
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`100 km/h`).
    pub speed: SpeedRaw,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the front axle reaches the bridge entrance, s. Default 0.
    /// Give this or `start_position`, not both.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the front axle at t = 0, m (≤ 0: on the approach).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the loads on a plate deck, m. Default: the
    /// deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
}

/// Moving oscillator parameters: physical, or derived from the LCP separation
/// paper's dimensionless groups with `dimensionless`.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OscillatorRaw {
    /// Sprung (body) mass, kg. Required unless `dimensionless` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub sprung_mass: Option<f64>,
    /// Unsprung (wheel) mass, kg. Default 0: a massless wheel.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass::schema")]
    pub unsprung_mass: Option<f64>,
    /// Suspension stiffness, N/m. Required unless `dimensionless` is given.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::stiffness::schema")]
    pub stiffness: Option<f64>,
    /// Suspension damping, N·s/m. Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::damping::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::damping::schema")]
    pub damping: Option<f64>,
    /// Speed at t = 0 (constant unless `acceleration` is given): m/s, or with its unit (`100 km/h`). Required unless
    /// `dimensionless` is given.
    #[serde(default)]
    pub speed: Option<SpeedRaw>,
    /// Constant acceleration along the path, m/s² (negative: braking). The
    /// speed changes from `speed` at t = 0 as v(t) = v₀ + a·t; a braking
    /// vehicle that comes to a stop stays stopped. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::acceleration::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::acceleration::schema")]
    pub acceleration: Option<f64>,
    /// Time at which the wheel reaches the bridge entrance, s. Default 0.
    /// Give this or `start_position`, not both.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub entry_time: Option<f64>,
    /// Position of the wheel at t = 0, m (≤ 0: on the approach).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub start_position: Option<f64>,
    /// Transverse position y of the wheel on a plate deck, m. Default: the
    /// deck's centre line.
    #[serde(default)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub lateral_position: Option<f64>,
    /// Derive masses, stiffness, damping and speed from dimensionless groups
    /// relative to the bridge (its first natural frequency f₁, length L and
    /// mass per length m). Physical fields given as well must agree with the
    /// derived values (the resolved scenario lists both).
    #[serde(default)]
    pub dimensionless: Option<DimensionlessRaw>,
}

/// The dimensionless groups of the LCP separation paper's Table 1 (standard
/// definitions; its formulas were lost in extraction).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DimensionlessRaw {
    /// Velocity ratio α = v / (2 f₁ L) (dimensionless; 1 = the critical speed
    /// of the moving-force resonance).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub velocity_ratio: f64,
    /// Vehicle-to-bridge mass ratio (m_s + m_u) / (m L) (dimensionless).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub mass_ratio: f64,
    /// Unsprung-to-sprung mass ratio m_u / m_s (dimensionless). Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative)]
    #[schemars(extend("default" = 0.0))]
    pub unsprung_ratio: Option<f64>,
    /// Bridge-to-vehicle frequency ratio f₁ / f_v with f_v = √(k/m_s) / 2π
    /// (dimensionless).
    #[schemars(transform = crate::scene::schema_rules::positive)]
    pub frequency_ratio: f64,
    /// Vehicle damping ratio ζ_v = c / (2√(k m_s)) (dimensionless). Default 0.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::ratio)]
    #[schemars(extend("default" = 0.0))]
    pub damping_ratio: Option<f64>,
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
    /// Time step, s. Default: 1 / (20 f_max), f_max the highest bridge mode kept
    /// or frequency excited (see `bridge.modes`), and at most 1/200 of the
    /// shortest crossing.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::time::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::time::schema")]
    pub time_step: Option<f64>,
    /// Newmark parameters. Default β = 1/4, γ = 1/2, α = 0 (average
    /// acceleration: unconditionally stable, second order, no numerical
    /// damping); with rigid contact α = −0.05 (HHT).
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
    /// Eq. 32; dimensionless). Default 1e-8.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::iteration_tolerance)]
    pub tolerance: Option<f64>,
    /// `method: iterative` only: most iterations allowed in one time step
    /// before the run stops with an error. Default 100.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::max_iterations)]
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
    /// −0.05 with rigid contact when β and γ are not given. A negative α keeps
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
    /// of 30 Hz, 1.5 f₁ and f₃. The automatic mode choice keeps every mode up
    /// to it.
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
}
