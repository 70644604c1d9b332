//! Time integration of the vehicle–bridge system.
//!
//! The solver meets bridge and vehicles only through the contact points:
//! at each step both subsystems are advanced by Newmark with the contact
//! forces as unknowns, the wheel-to-surface gaps are expressed through those
//! forces (the step's contact compliance), and the contact model closes the
//! system. [`coupled`] enforces permanent contact; [`direct`] does the
//! same on the bridge's assembled matrices instead of its modes.
//!
//! Every method is a [`time_loop::Stepper`] — its step and nothing else —
//! run by the one time loop [`time_loop::drive`], which owns the step
//! times, the divergence guard, the observer calls, the progress reports
//! and the cancellation check. [`run_method`] picks the stepper.

#![allow(clippy::needless_range_loop)] // numeric kernels index several arrays in step

pub mod cancel;
pub mod coupled;
pub mod dense;
pub mod direct;
pub mod embs;
pub mod embs_scale;
pub mod guard;
mod impact;
pub mod iterative;
pub mod lcp;
pub mod lockstep;
pub mod modal;
pub mod newmark;
pub mod partition;
pub mod permanent;
mod residual_rates;
pub mod row_spans;
pub mod time_loop;
pub mod unilateral;

use nalgebra::DVector;
use thiserror::Error;

use crate::model::Model;
use crate::scene::SolverMethod;

/// Errors of the solve stage.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SolveError {
    /// The state became non-finite.
    #[error("the solution diverged at t = {time:.6} s (step {step}; {positions}): {cause}")]
    Diverged {
        /// Time, s.
        time: f64,
        /// Step number.
        step: usize,
        /// Vehicle front positions, formatted.
        positions: String,
        /// Likely cause.
        cause: String,
    },
    /// The contact problem has no solution or did not converge.
    #[error("the contact problem failed at t = {time:.6} s ({positions}): {reason}")]
    Contact {
        /// Time, s.
        time: f64,
        /// Vehicle front positions, formatted.
        positions: String,
        /// Explanation.
        reason: String,
    },
    /// The iterative solver's vehicle–bridge iteration did not converge.
    #[error(
        "the vehicle–bridge iteration did not converge at t = {time:.6} s ({positions}) after {iterations} iteration(s): {reason}"
    )]
    NotConverged {
        /// Time, s.
        time: f64,
        /// Vehicle front positions, formatted.
        positions: String,
        /// Iterations done in that step.
        iterations: usize,
        /// Explanation.
        reason: String,
    },
    /// The contact compliance matrix is singular.
    #[error("the contact system is singular at t = {time:.6} s: {reason}")]
    SingularContact {
        /// Time, s.
        time: f64,
        /// Explanation.
        reason: String,
    },
    /// The direct solver cannot run this scene ([`direct`]).
    #[error("the direct solver cannot run this scene: {reason}")]
    Direct {
        /// Explanation.
        reason: String,
    },
    /// The run was stopped from outside ([`cancel`]), e.g. by Ctrl-C in
    /// the Python package.
    #[error("the run was cancelled")]
    Cancelled,
}

/// Dynamic state of one vehicle.
#[derive(Debug, Clone)]
pub struct VehicleState {
    /// Displacements, m (rad), absolute (including the static sag).
    pub displacement: DVector<f64>,
    /// Velocities, m/s.
    pub velocity: DVector<f64>,
    /// Accelerations, m/s².
    pub acceleration: DVector<f64>,
    /// Static equilibrium displacements on level ground, m: the reference
    /// from which recorded vehicle displacements are measured.
    pub static_displacement: DVector<f64>,
}

impl VehicleState {
    /// Vehicle `v` of `model` at rest in static equilibrium on level ground.
    pub fn at_rest(model: &Model, v: usize) -> Self {
        let (static_displacement, _) = model.static_state(v);
        let n = static_displacement.len();
        Self {
            displacement: static_displacement.clone(),
            velocity: DVector::zeros(n),
            acceleration: DVector::zeros(n),
            static_displacement,
        }
    }
}

/// What an observer sees after each step (and at t = 0).
#[derive(Debug)]
pub struct StepView<'a> {
    /// Step number, 0 for the initial state.
    pub step: usize,
    /// Time, s.
    pub time: f64,
    /// Modal displacements q, √kg·m.
    pub modal_displacement: &'a [f64],
    /// Modal accelerations q̈.
    pub modal_acceleration: &'a [f64],
    /// Vehicle states.
    pub vehicles: &'a [VehicleState],
    /// Contact force per flattened wheel, N, compression positive.
    pub contact_forces: &'a [f64],
    /// Wheel-to-surface gap per flattened wheel, m: positive = lifted off,
    /// negative = contact compression; 0 for loads and permanent contact.
    pub contact_gaps: &'a [f64],
    /// Position of each flattened wheel, m.
    pub wheel_positions: &'a [f64],
    /// Mode values at every flattened wheel on the deck (wheel-major,
    /// `modes` per wheel), when the solver already has them this step; the
    /// recorder works them out itself otherwise.
    pub wheel_modes: Option<&'a [f64]>,
    /// The bridge's own nodal state on its assembled free DOFs, when the
    /// solver steps them ([`direct`]): the bridge records read it, exact in
    /// space, rather than the modal coordinates; `None` for a modal method.
    pub nodal: Option<NodalState<'a>>,
}

pub use crate::bridge::NodalState;

impl<'a> StepView<'a> {
    /// The view of a state: modal coordinates from `modal`, the rest as given.
    pub(crate) fn of(
        step: usize,
        time: f64,
        modal: &'a modal::ModalStep,
        vehicles: &'a [VehicleState],
        contact_forces: &'a [f64],
        contact_gaps: &'a [f64],
        wheel_positions: &'a [f64],
    ) -> Self {
        Self {
            step,
            time,
            modal_displacement: &modal.displacement,
            modal_acceleration: &modal.acceleration,
            vehicles,
            contact_forces,
            contact_gaps,
            wheel_positions,
            wheel_modes: None,
            nodal: None,
        }
    }
}

/// Receives every step's state (the record stage).
pub trait Observer {
    /// Called at t = 0 and after every step.
    fn observe(&mut self, view: &StepView<'_>);

    /// Whether it reads the view's modal coordinates (a direct run forms
    /// them, q = ΦᵀM u, only if so: [`direct::Direct::projecting`]).
    fn reads_modal_coordinates(&self) -> bool {
        true
    }
}

/// What a solver reports about its own work over a run.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SolveStats {
    /// Vehicle–bridge iterations per step (the `iterative` solver only).
    pub iterations: Option<iterative::IterationStats>,
}

/// Integrates the model with its solver method, calling `observer` at
/// t = 0 and after every step.
///
/// # Errors
///
/// The method's failure, divergence, or cancellation ([`time_loop::drive`]).
pub fn run(
    model: &Model,
    observer: &mut dyn Observer,
    progress: Progress<'_>,
) -> Result<SolveStats, SolveError> {
    run_method(model, model.method, observer, None, progress)
}

/// The one dispatch from a solver method to its [`time_loop::Stepper`]:
/// integrates `model` with `method`, calling `observer` at t = 0 and after
/// every step, and `zero_order` (when given) at the same instants with the
/// zero order of an expansion alone (EMBS: [`embs::Embs`];
/// the other methods have no expansion and leave it unobserved).
///
/// # Errors
///
/// As [`run`].
pub fn run_method(
    model: &Model,
    method: SolverMethod,
    observer: &mut dyn Observer,
    zero_order: Option<&mut dyn Observer>,
    progress: Progress<'_>,
) -> Result<SolveStats, SolveError> {
    match method {
        SolverMethod::Coupled => drive_one(
            &mut coupled::Coupled::new(model)?,
            &mut [observer],
            progress,
        ),
        SolverMethod::Iterative => drive_one(
            &mut iterative::Iterative::new(model)?,
            &mut [observer],
            progress,
        ),
        SolverMethod::Lcp => drive_one(
            &mut unilateral::Unilateral::new(model)?,
            &mut [observer],
            progress,
        ),
        SolverMethod::Direct => {
            let projecting = observer.reads_modal_coordinates();
            let mut stepper = direct::Direct::new(model)?.projecting(projecting);
            drive_one(&mut stepper, &mut [observer], progress)
        }
        SolverMethod::Embs => {
            let mut stepper = embs::Embs::new(model, zero_order.is_some())?;
            match zero_order {
                Some(zero) => drive_one(&mut stepper, &mut [observer, zero], progress),
                None => drive_one(&mut stepper, &mut [observer], progress),
            }
        }
    }
}

/// Whether `model`'s method shows the zero order of its expansion alone
/// as a view of its own (the `zero_order` observer of [`run_method`]):
/// EMBS with its first order.
pub fn shows_zero_order(model: &Model) -> bool {
    model.method == SolverMethod::Embs && model.embs.is_some_and(|e| e.first_order)
}

/// The method a run of `model` is compared with, when the scene asks for
/// a comparison: `coupled`, the exact permanent contact, for EMBS with
/// `compare` ([`crate::report::embs`] differences the two).
pub fn reference_method(model: &Model) -> Option<SolverMethod> {
    (model.method == SolverMethod::Embs && model.embs.is_some_and(|e| e.compare))
        .then_some(SolverMethod::Coupled)
}

/// [`time_loop::drive`] for one scene, then the stepper's own report.
fn drive_one<S: time_loop::Stepper<Error = SolveError>>(
    stepper: &mut S,
    observers: &mut [&mut dyn Observer],
    progress: Progress<'_>,
) -> Result<SolveStats, SolveError> {
    time_loop::drive(stepper, observers, progress)?;
    Ok(stepper.stats())
}

/// Progress reporting: called with (steps done, total steps) now and then.
pub type Progress<'a> = &'a mut dyn FnMut(usize, usize);

/// Formats vehicle front positions at time `t` for error messages.
pub(crate) fn describe_positions(model: &Model, t: f64) -> String {
    model
        .vehicles
        .iter()
        .enumerate()
        .map(|(i, v)| {
            format!(
                "vehicle {} front at x = {:.3} m",
                i + 1,
                v.front_position(t)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The ground motion's share of each step: sets the bridge's vertical and
/// lateral ground accelerations at t_{n+1} and returns the vehicles' extra
/// weight ratio (1+α)üg(t_{n+1}) − α üg(tₙ), over g — HHT weights the
/// external loads as it weights the contact forces — and keeps the same
/// weighting of the lateral acceleration in [`GroundStep::lateral_load`].
/// Without ground motion every value is exactly 0 and nothing changes.
#[derive(Debug, Clone, Copy)]
pub struct GroundStep {
    weight: f64,
    alpha: f64,
    gravity: f64,
    previous: f64,
    lateral_previous: f64,
    active: bool,
    /// (1+α)üg,y(t_{n+1}) − α üg,y(tₙ) of the step last advanced to, m/s²:
    /// the multiplier of each vehicle's [`crate::vehicle::VehicleModel::lateral_ground_load`].
    pub lateral_load: f64,
}

impl GroundStep {
    /// At rest at t = 0 (the record's acceleration there is taken as the
    /// previous step's).
    pub fn new(model: &Model, nm: &newmark::Newmark) -> Self {
        Self {
            weight: nm.weight(),
            alpha: nm.alpha,
            gravity: model.gravity,
            previous: model.ground_acceleration(0.0),
            lateral_previous: model.lateral_ground_acceleration(0.0),
            active: model.ground.is_some(),
            lateral_load: 0.0,
        }
    }

    /// Advances to the step ending at `t` (s) of `model`.
    #[inline]
    pub fn step_of(&mut self, model: &Model, modal: &mut modal::ModalStep, t: f64) -> f64 {
        let (ratio, vertical, lateral) = self.advance_to(model, t);
        if self.active {
            modal.ground_acceleration = vertical;
            modal.lateral_ground_acceleration = lateral;
        }
        ratio
    }

    /// Advances to the step ending at `t` (s) of `model` (whatever the
    /// bridge's coordinates: [`Self::step_of`] for modal ones, the direct
    /// solver's nodal ones): the vehicles' extra weight ratio, and the
    /// vertical and lateral ground accelerations at `t` (m/s²); all 0
    /// without ground motion.
    #[inline]
    pub fn advance_to(&mut self, model: &Model, t: f64) -> (f64, f64, f64) {
        if !self.active {
            return (0.0, 0.0, 0.0);
        }
        let now = model.ground_acceleration(t);
        let ratio = (self.weight * now - self.alpha * self.previous) / self.gravity;
        self.previous = now;
        let lateral = model.lateral_ground_acceleration(t);
        self.lateral_load = self.weight * lateral - self.alpha * self.lateral_previous;
        self.lateral_previous = lateral;
        (ratio, now, lateral)
    }
}
