//! The build stage: a resolved scenario becomes the numerical model the
//! solvers integrate — one modal bridge, the vehicle models, the surface
//! profile and the time grid.

use thiserror::Error;

use crate::bridge::{BridgeError, ModalBridge};
use crate::contact::ContactDirection;
use crate::scene::{Contact, Iteration, Scenario, SolverMethod};
use crate::surface::{Profile, Rail};
use crate::vehicle::{VehicleError, VehicleModel, WheelKind};

/// Errors of the build stage.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum BuildError {
    /// The bridge could not be built.
    #[error(transparent)]
    Bridge(#[from] BridgeError),
    /// A vehicle could not be built.
    #[error(transparent)]
    Vehicle(#[from] VehicleError),
    /// The surface profile could not be built.
    #[error(transparent)]
    Surface(#[from] crate::surface::SurfaceError),
}

/// Identifies one wheel: vehicle index and wheel index within it (from 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WheelRef {
    /// Vehicle index from 0.
    pub vehicle: usize,
    /// Wheel index within the vehicle from 0.
    pub wheel: usize,
}

/// The wheel–surface contact law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactLaw {
    /// Wheels held to the surface (bilateral).
    Permanent,
    /// Unilateral, rigid: gap ≥ 0, force ≥ 0, gap·force = 0, with Newton's
    /// impact law at landings.
    Rigid {
        /// Coefficient of restitution e, 0 to 1 (dimensionless).
        restitution: f64,
    },
    /// Unilateral, force = k δ for compression δ > 0.
    Elastic {
        /// k, N/m.
        stiffness: f64,
    },
    /// Unilateral, force = C δ^1.5 for compression δ > 0.
    Hertz {
        /// C, N/m^1.5.
        coefficient: f64,
    },
}

impl ContactLaw {
    /// Compression δ (m) that carries a force `force` (N ≥ 0).
    pub fn compression(&self, force: f64) -> f64 {
        match *self {
            ContactLaw::Permanent | ContactLaw::Rigid { .. } => 0.0,
            ContactLaw::Elastic { stiffness } => force / stiffness,
            ContactLaw::Hertz { coefficient } => (force.max(0.0) / coefficient).powf(2.0 / 3.0),
        }
    }

    /// Whether wheels may separate.
    pub fn is_unilateral(&self) -> bool {
        !matches!(self, ContactLaw::Permanent)
    }
}

/// Everything the time integration needs.
#[derive(Debug, Clone)]
pub struct Model {
    /// The modal bridge.
    pub bridge: ModalBridge,
    /// The vehicles, in scenario order.
    pub vehicles: Vec<VehicleModel>,
    /// The surface under the wheels.
    pub profile: Profile,
    /// How far from the entrance [`Model::profile`] was sampled, m: the
    /// farthest front axle at the last step. A Monte Carlo sample swaps
    /// the profile with `Profile::build_from(&surface.reseeded(seed), reach,
    /// front_start(&vehicles))`.
    pub profile_reach: f64,
    /// The contact law.
    pub contact: ContactLaw,
    /// Every wheel of every vehicle, flattened in vehicle order.
    pub wheels: Vec<WheelRef>,
    /// Transverse position y of every flattened wheel on the deck, m
    /// (constant: vehicles keep their lane).
    pub wheel_y: Vec<f64>,
    /// The rail (wheel track) of every flattened wheel ([`Rail::of_lateral`]).
    pub wheel_rail: Vec<Rail>,
    /// Static wheel loads on level ground, N, per flattened wheel: the load of
    /// a moving force, or the contact force of the vehicle's static equilibrium.
    pub static_wheel_loads: Vec<f64>,
    /// Time step, s.
    pub time_step: f64,
    /// How the time step was chosen, in words.
    pub time_step_selection: String,
    /// Number of steps.
    pub steps: usize,
    /// Newmark β.
    pub beta: f64,
    /// Newmark γ.
    pub gamma: f64,
    /// HHT α (0 = plain Newmark).
    pub alpha: f64,
    /// Solution method.
    pub method: SolverMethod,
    /// Convergence settings of the `iterative` method.
    pub iteration: Iteration,
    /// Settings of the `embs` method (`None` for any other).
    pub embs: Option<crate::scene::EmbsOptions>,
    /// Transverse positions y of the girder lines, m (a beam: one line): the
    /// recorder tabulates the DAF at every span's middle on each.
    pub girder_lines: Vec<f64>,
    /// Gravitational acceleration g, m/s² (> 0).
    pub gravity: f64,
    /// Earthquake ground motion (vertical support excitation), if any.
    pub ground: Option<crate::ground::GroundExcitation>,
}

impl Model {
    /// Builds the model. `bridge` is the modal bridge made while resolving
    /// (modes must be known to fill defaults), so it is not built twice.
    pub fn build(scenario: &Scenario, mut bridge: ModalBridge) -> Result<Self, BuildError> {
        let vehicles: Vec<VehicleModel> = scenario
            .vehicles
            .iter()
            .map(|v| VehicleModel::build(v, scenario.gravity))
            .collect();
        let contact = match scenario.contact {
            Contact::Permanent => ContactLaw::Permanent,
            Contact::Rigid { restitution } => ContactLaw::Rigid { restitution },
            Contact::Elastic { stiffness, .. } => ContactLaw::Elastic { stiffness },
            Contact::Hertz { coefficient } => ContactLaw::Hertz { coefficient },
        };
        let mut wheels = Vec::new();
        let mut static_wheel_loads = Vec::new();
        let mut wheel_y = Vec::new();
        let mut wheel_rail = Vec::new();
        for (v, vehicle) in vehicles.iter().enumerate() {
            let (_, forces) = vehicle.static_equilibrium(v + 1, &|f| contact.compression(f))?;
            for (w, wheel) in vehicle.wheels.iter().enumerate() {
                wheels.push(WheelRef {
                    vehicle: v,
                    wheel: w,
                });
                wheel_y.push(vehicle.wheel_y(w));
                wheel_rail.push(Rail::of_lateral(wheel.lateral));
                static_wheel_loads.push(match wheel.kind {
                    WheelKind::Load(load) => load,
                    WheelKind::Dof(_) => forces[w],
                });
            }
        }
        // Wheels keep their lanes: evaluate the plate's modes along them as
        // cheaply as along a beam.
        bridge.prepare_lines(&wheel_y);
        // The contacts' static correction needs K⁻¹ once (beams).
        bridge.prepare_contact_correction()?;
        // Ground motion loads the modes through their participation
        // factors (computed once, from the kept modes).
        let bridge_participation = if scenario.ground_motion.is_empty() {
            (Vec::new(), 0.0)
        } else {
            bridge.vertical_participation(&scenario.bridge)
        };
        let lateral_participation = if scenario
            .ground_motion
            .iter()
            .any(|g| g.direction == crate::scene::Direction::Lateral)
        {
            bridge.lateral_participation(&scenario.bridge)
        } else {
            (Vec::new(), 0.0)
        };
        let end_time = end_time(scenario, &vehicles, bridge.length);
        let time_step = scenario.solver.time_step;
        // A step count that reaches the end time; the last step may overshoot
        // by less than one step.
        let steps = (end_time / time_step - 1e-9).ceil().max(1.0) as usize;
        // The farthest any wheel goes: the front axles at the last step.
        let reach = vehicles
            .iter()
            .map(|v| v.front_position(steps as f64 * time_step))
            .fold(0.0, f64::max);
        let profile = Profile::build_from(&scenario.surface, reach, front_start(&vehicles))?;
        Ok(Self {
            bridge,
            vehicles,
            profile,
            profile_reach: reach,
            contact,
            wheels,
            wheel_y,
            wheel_rail,
            static_wheel_loads,
            time_step,
            time_step_selection: scenario.solver.time_step_selection.clone(),
            steps,
            beta: scenario.solver.newmark.beta,
            gamma: scenario.solver.newmark.gamma,
            alpha: scenario.solver.newmark.alpha,
            method: scenario.solver.method,
            iteration: scenario.solver.iteration.unwrap_or_default(),
            embs: scenario.solver.embs,
            girder_lines: scenario.bridge.girder_lines(),
            gravity: scenario.gravity,
            ground: ground_excitation(scenario, &bridge_participation, lateral_participation),
        })
    }

    /// The track irregularity a contact in `direction` follows at `x` (m)
    /// on `rail`: (value m, slope, curvature 1/m). Vertical: the surface
    /// profile ([`Profile::elevation_slope_curvature_on`]); lateral: the
    /// track's alignment ([`Profile::alignment_at`]), zero where the
    /// surface samples none.
    #[inline]
    pub fn irregularity(&self, direction: ContactDirection, rail: Rail, x: f64) -> (f64, f64, f64) {
        match direction {
            ContactDirection::Vertical => self.profile.elevation_slope_curvature_on(rail, x),
            ContactDirection::Lateral => self.profile.alignment_at(x),
        }
    }

    /// Vertical ground acceleration at run time `t` (s), m/s² (0 without
    /// ground motion).
    #[inline]
    pub fn ground_acceleration(&self, t: f64) -> f64 {
        self.ground
            .as_ref()
            .map_or(0.0, |g| g.vertical_acceleration(t))
    }

    /// Lateral ground acceleration at run time `t` (s), m/s² (0 without a
    /// lateral record).
    #[inline]
    pub fn lateral_ground_acceleration(&self, t: f64) -> f64 {
        self.ground
            .as_ref()
            .map_or(0.0, |g| g.lateral_acceleration(t))
    }

    /// Participation factors of a lateral support motion (empty without a
    /// lateral record), √kg.
    pub fn lateral_ground_participation(&self) -> &[f64] {
        self.ground
            .as_ref()
            .map_or(&[], |g| g.lateral_participation.as_slice())
    }

    /// Participation factors of a vertical support motion (empty without
    /// ground motion), √kg.
    pub fn ground_participation(&self) -> &[f64] {
        self.ground
            .as_ref()
            .map_or(&[], |g| g.participation.as_slice())
    }

    /// Position of a flattened wheel at time `t`, m.
    #[inline]
    pub fn wheel_position(&self, wheel: usize, t: f64) -> f64 {
        let r = self.wheels[wheel];
        self.vehicles[r.vehicle].wheel_position(r.wheel, t)
    }

    /// Writes every flattened wheel's position at time `t` into `positions`,
    /// m: [`Self::wheel_position`] of each, each vehicle's front axle found
    /// once for its wheels (a train's dozens of axles; the same values).
    #[inline]
    pub fn wheel_positions(&self, t: f64, positions: &mut [f64]) {
        let mut front = (usize::MAX, 0.0);
        for (x, r) in positions.iter_mut().zip(&self.wheels) {
            let vehicle = &self.vehicles[r.vehicle];
            if front.0 != r.vehicle {
                front = (r.vehicle, vehicle.front_position(t));
            }
            *x = front.1 - vehicle.wheels[r.wheel].offset;
        }
    }

    /// Flattened index of (vehicle, wheel), both from 0.
    pub fn wheel_index(&self, vehicle: usize, wheel: usize) -> Option<usize> {
        self.wheels
            .iter()
            .position(|r| r.vehicle == vehicle && r.wheel == wheel)
    }

    /// Static equilibrium of vehicle `v` under this model's contact law.
    pub fn static_state(&self, v: usize) -> (nalgebra::DVector<f64>, Vec<f64>) {
        self.vehicles[v]
            .static_equilibrium(v + 1, &|f| self.contact.compression(f))
            .expect("static equilibrium was checked when the model was built")
    }

    /// Simulated duration, s.
    pub fn end_time(&self) -> f64 {
        self.steps as f64 * self.time_step
    }
}

/// The front-most front axle at t = 0, m from the entrance (≤ 0; −∞
/// without vehicles): a track spectrum's fade-in starts there at the
/// latest ([`crate::surface::fade_start`]).
pub fn front_start(vehicles: &[VehicleModel]) -> f64 {
    vehicles
        .iter()
        .map(|v| v.front_position(0.0))
        .fold(f64::NEG_INFINITY, f64::max)
}

/// Time when the last axle of the last vehicle leaves the bridge, plus the
/// requested free vibration, s.
pub fn end_time(scenario: &Scenario, vehicles: &[VehicleModel], length: f64) -> f64 {
    let last_exit = vehicles
        .iter()
        .map(|v| v.exit_time(length))
        .fold(0.0, f64::max);
    last_exit + scenario.solver.free_vibration
}

/// The support excitation of `scenario`, if it has ground motion.
fn ground_excitation(
    scenario: &Scenario,
    (participation, total_mass): &(Vec<f64>, f64),
    (lateral_participation, lateral_mass): (Vec<f64>, f64),
) -> Option<crate::ground::GroundExcitation> {
    if scenario.ground_motion.is_empty() {
        return None;
    }
    let records = |direction| {
        scenario
            .ground_motion
            .iter()
            .filter(|g| g.direction == direction)
            .map(|g| g.record.clone())
            .collect()
    };
    Some(crate::ground::GroundExcitation {
        vertical: records(crate::scene::Direction::Vertical),
        participation: participation.clone(),
        total_mass: *total_mass,
        lateral: records(crate::scene::Direction::Lateral),
        lateral_participation,
        lateral_mass,
    })
}
