//! Several samples of one scene under elastic unilateral contact, stepped
//! together (a Monte Carlo study's batch).
//!
//! The samples of a Monte Carlo case differ only in their surface profile.
//! Where the wheels are at step n, and so the mode values at the contacts,
//! the residual flexibility and the contact compliance W (see
//! [`super::unilateral`]), is the same for all of them: it is worked out
//! once per step for the batch. Each sample's own state — modal and vehicle
//! displacements, velocities and accelerations, contact forces — is held
//! lane by lane (`[f64; LANES]` per quantity), so every per-sample product
//! runs over the lanes in the innermost loop, which the compiler turns into
//! vector instructions.
//!
//! Each lane performs exactly the floating-point operations of
//! [`super::unilateral::Unilateral`] in the same order (the same Newmark/HHT
//! formulas, nalgebra's `gemv` order for the vehicles' products, the same
//! warm-started LCP), so a sample stepped here is bit-identical to the same
//! scene run alone; `tests/monte_carlo.rs` checks it. Only exact zeros of
//! the vehicle matrices are skipped (adding ±0 changes no finite value).
//! On a processor with AVX2 the same code is compiled a second time for it
//! ([`run`] picks at run time): four lanes per instruction instead of two,
//! the same roundings (Rust never fuses a·b + c), so the same bits. The
//! bridge's step is skipped while no wheel has reached the deck (it is
//! exactly at rest then), and the recorders of a batch share what does not
//! depend on a sample's state ([`crate::record::Recorder::sharing_statics`]).
//!
//! Batch width: 16 lanes. Measured on the 1000-sample rail-car study of
//! BENCHMARKS.md (2 cores): 4 lanes 2.13 s, 8 lanes 1.80 s, 16 lanes 1.74 s,
//! 32 lanes 1.74 s (before the AVX2 variant); wider batches only leave
//! small studies fewer batches to share between threads.
//!
//! Scope: the `lcp` method with elastic contact, no ground motion, every
//! wheel on a DOF and every vehicle with an invertible M + (1+α)γΔt C
//! ([`eligible`]); anything else runs sample by sample. Cost per step:
//! the geometry once, O(nc·modes + nc²·modes), then per lane O(modes·nc +
//! Σ nnz(vehicle matrices) + nc³) and the recorder.

mod lanes;

use nalgebra::DVector;

use self::lanes::{
    LaneView, ModalLanes, Product, VehicleLanes, finish_bridge, mechanical_energy, predict_bridge,
    predict_vehicle, recover_vehicle,
};

use super::lcp::{LcpWorkspace, SharedWarmStart};
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::time_loop::{Stepper, drive};
use super::unilateral::{
    ContactGeometry, ContactWheel, block_inverse, contact_wheels, vehicle_step_matrices,
};
use super::{Observer, SolveError, StepView, VehicleState, describe_positions};
use crate::model::{ContactLaw, Model};
use crate::scene::SolverMethod;

/// Samples stepped together.
pub const LANES: usize = 16;

/// One value per lane.
type Lanes = [f64; LANES];

/// Whether `model` can be stepped in lockstep (see the module's scope).
pub fn eligible(model: &Model) -> bool {
    if model.method != SolverMethod::Lcp
        || !matches!(model.contact, ContactLaw::Elastic { .. })
        || model.ground.is_some()
    {
        return false;
    }
    let (_, loads, _) = contact_wheels(model);
    let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
    loads.is_empty()
        && model.vehicles.iter().all(|vehicle| {
            block_inverse(
                &(&vehicle.mass + &vehicle.damping * (nm.weight() * nm.a7)),
                &vehicle.blocks,
            )
            .is_some()
        })
}

/// Integrates `models` (one per lane, at most [`LANES`], all [`eligible`]
/// and alike but for their surface profiles) together, each reporting to
/// its own observer. The first failure (lowest step, then lowest lane)
/// stops the batch and is returned with its lane.
pub fn run(
    models: &[&Model],
    observers: &mut [&mut dyn Observer],
) -> Result<(), (usize, SolveError)> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { run_avx2(models, observers) };
    }
    run_lanes(models, observers)
}

/// [`run_lanes`] compiled for AVX2: the lane loops take four values per
/// instruction instead of SSE2's two; additions, multiplications,
/// divisions and maxima stay separate operations lane by lane (nothing is
/// contracted into a fused multiply-add), so the results are bit-identical
/// to the baseline build's.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_avx2(
    models: &[&Model],
    observers: &mut [&mut dyn Observer],
) -> Result<(), (usize, SolveError)> {
    run_lanes(models, observers)
}

/// The batch itself ([`run`]): [`Batch`] through the one time loop,
/// inlined into each instruction-set variant together with the lane
/// kernels it calls.
#[inline(always)]
fn run_lanes(
    models: &[&Model],
    observers: &mut [&mut dyn Observer],
) -> Result<(), (usize, SolveError)> {
    let lanes = models.len();
    assert!(
        (1..=LANES).contains(&lanes) && observers.len() == lanes,
        "lockstep::run: 1 to {LANES} models, one observer each"
    );
    let mut batch = Batch::new(models).map_err(|e| (e.lane, e.error))?;
    drive(&mut batch, observers, &mut |_, _| {}).map_err(|e| (e.lane, e.error))
}

/// A batch's failure: its lane, and what failed.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneFailure {
    /// The lane (0 for a failure of the whole batch: cancellation).
    pub lane: usize,
    /// What failed.
    pub error: SolveError,
}

impl From<SolveError> for LaneFailure {
    fn from(error: SolveError) -> Self {
        Self { lane: 0, error }
    }
}

/// The lockstep batch's state and work arrays, for [`drive`]: one lane per
/// model, each lane's guard and view its model's.
#[derive(Debug)]
struct Batch<'a> {
    models: &'a [&'a Model],
    nm: Newmark,
    modal: ModalStep,
    stiffness: f64,
    contacts: Vec<ContactWheel>,
    vehicles: Vec<VehicleLanes>,
    bridge_lanes: ModalLanes,
    /// Until a wheel reaches the deck the bridge is exactly at rest (no
    /// load, no ground motion) and its step is skipped.
    bridge_moving: bool,
    geometry: ContactGeometry,
    /// As in `unilateral`: every vehicle starts in static equilibrium, so
    /// the force carried into the first HHT term is the static wheel load.
    carried: Vec<Lanes>,
    lambda: Vec<Lanes>,
    free_gap: Vec<Lanes>,
    lcp_matrix: Vec<f64>,
    lane_gap: Vec<f64>,
    lane_force: Vec<f64>,
    lane_previous: Vec<f64>,
    workspace: LcpWorkspace,
    warm: SharedWarmStart,
    wheel_positions: Vec<f64>,
    views: Vec<LaneView>,
    /// Each lane's mechanical energy after the step, J (the guard's).
    energy: Lanes,
}

/// Vehicle `v` of `model` at rest, its matrices as sparse lane products.
fn vehicle_lanes(
    model: &Model,
    nm: &Newmark,
    v: usize,
    contacts: &[ContactWheel],
    columns: &[usize],
) -> Result<VehicleLanes, SolveError> {
    let vehicle = &model.vehicles[v];
    let n = vehicle.dofs();
    let (effective_flexibility, contact_response) =
        vehicle_step_matrices(model, nm, v, contacts, columns)?;
    let recovery = block_inverse(
        &(&vehicle.mass + &vehicle.damping * (nm.weight() * nm.a7)),
        &vehicle.blocks,
    )
    .expect("eligible: M + (1+α)γΔt C is invertible");
    let at_rest = VehicleState::at_rest(model, v);
    let spread = |x: &DVector<f64>| x.iter().map(|&u| [u; LANES]).collect::<Vec<Lanes>>();
    let zeros = vec![[0.0; LANES]; n];
    let blocks = &vehicle.blocks;
    Ok(VehicleLanes {
        mass: Product::new(&vehicle.mass, blocks),
        damping: Product::new(&vehicle.damping, blocks),
        stiffness: Product::new(&vehicle.stiffness, blocks),
        effective_flexibility: Product::new(&effective_flexibility, blocks),
        recovery: Product::new(&recovery, blocks),
        gravity_load: vehicle.gravity_load.iter().copied().collect(),
        static_displacement: at_rest.static_displacement.iter().copied().collect(),
        contact_response,
        displacement: spread(&at_rest.displacement),
        velocity: spread(&at_rest.velocity),
        acceleration: spread(&at_rest.acceleration),
        effective_load: zeros.clone(),
        inertia_history: zeros.clone(),
        damping_history: zeros.clone(),
        predictor: zeros.clone(),
        recovery_load: zeros.clone(),
        predicted_velocity: zeros.clone(),
        recovered_acceleration: zeros,
    })
}

/// One lane's view of `model` at rest in static equilibrium.
fn lane_view(model: &Model, contacts: &[ContactWheel]) -> LaneView {
    let mut contact_gaps = vec![0.0; model.wheels.len()];
    for c in contacts {
        contact_gaps[c.wheel] = -model.contact.compression(model.static_wheel_loads[c.wheel]);
    }
    LaneView {
        modal_displacement: vec![0.0; model.bridge.mode_count()],
        modal_acceleration: vec![0.0; model.bridge.mode_count()],
        states: (0..model.vehicles.len())
            .map(|v| VehicleState::at_rest(model, v))
            .collect(),
        contact_forces: model.static_wheel_loads.clone(),
        contact_gaps,
    }
}

impl<'a> Batch<'a> {
    /// `models` (see [`run`]) at rest at t = 0, every work array
    /// allocated.
    fn new(models: &'a [&'a Model]) -> Result<Self, LaneFailure> {
        let model = models[0];
        debug_assert!(eligible(model));
        let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
        let modes = model.bridge.mode_count();
        let modal = ModalStep::new(&model.bridge, &nm);
        let (contacts, _, columns) = contact_wheels(model);
        let nc = contacts.len();
        let stiffness = match model.contact {
            ContactLaw::Elastic { stiffness } => stiffness,
            _ => unreachable!("lockstep runs elastic contact only"),
        };
        let vehicles = (0..model.vehicles.len())
            .map(|v| vehicle_lanes(model, &nm, v, &contacts, &columns))
            .collect::<Result<Vec<_>, _>>()?;
        let zeros = vec![[0.0; LANES]; modes];
        let bridge_lanes = ModalLanes {
            displacement: zeros.clone(),
            velocity: zeros.clone(),
            acceleration: zeros.clone(),
            predictor: zeros.clone(),
            current_force: zeros.clone(),
            previous_force: zeros,
        };
        let carried: Vec<Lanes> = contacts
            .iter()
            .map(|c| [model.static_wheel_loads[c.wheel]; LANES])
            .collect();
        let mut wheel_positions = vec![0.0; model.wheels.len()];
        model.wheel_positions(0.0, &mut wheel_positions);
        let views = (0..models.len())
            .map(|_| lane_view(model, &contacts))
            .collect();
        Ok(Self {
            models,
            nm,
            modal,
            stiffness,
            vehicles,
            bridge_lanes,
            bridge_moving: false,
            geometry: ContactGeometry::new(nc, modes),
            carried,
            lambda: vec![[0.0; LANES]; nc],
            free_gap: vec![[0.0; LANES]; nc],
            lcp_matrix: vec![0.0; nc * nc],
            lane_gap: vec![0.0; nc],
            lane_force: vec![0.0; nc],
            lane_previous: vec![0.0; nc],
            workspace: LcpWorkspace::new(nc.max(1)),
            warm: SharedWarmStart::new(nc),
            wheel_positions,
            views,
            energy: [0.0; LANES],
            contacts,
        })
    }

    /// The shared geometry at `t` (s), both subsystems' predictors, each
    /// lane's free gaps g* and the batch's LCP matrix W + I/k.
    #[inline(always)]
    fn predict(&mut self, t: f64) {
        let (models, model) = (self.models, self.models[0]);
        let modes = model.bridge.mode_count();
        let nc = self.contacts.len();
        let Self {
            nm,
            modal,
            contacts,
            vehicles,
            bridge_lanes,
            bridge_moving,
            geometry,
            carried,
            free_gap,
            lcp_matrix,
            wheel_positions,
            ..
        } = self;
        let alpha = nm.alpha;
        model.wheel_positions(t, wheel_positions);
        // The shared geometry first: until a wheel reaches the deck the
        // bridge is exactly at rest (no load, no ground motion), and its
        // Newmark step would return exact zeros, so it is skipped.
        geometry.locate(model, &modal.contact_flexibility, contacts, wheel_positions);
        *bridge_moving = *bridge_moving || geometry.on_deck.iter().any(|&on| on);
        if *bridge_moving {
            predict_bridge(bridge_lanes, modal, nm);
        }
        for vehicle in vehicles.iter_mut() {
            predict_vehicle(vehicle, nm);
        }
        if alpha != 0.0 {
            for (c, contact) in contacts.iter().enumerate() {
                let load = &mut vehicles[contact.vehicle].effective_load[contact.dof];
                for l in 0..LANES {
                    load[l] -= alpha * carried[c][l];
                }
            }
        }
        for vehicle in vehicles.iter_mut() {
            vehicle.predictor.fill([0.0; LANES]);
            vehicle.effective_flexibility.apply(
                &mut vehicle.predictor,
                1.0,
                &vehicle.effective_load,
            );
        }

        // Each lane's free gaps g*.
        for (c, contact) in contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let mut deck = [-0.0; LANES];
            if geometry.on_deck[c] {
                let phi = &geometry.shapes[c * modes..(c + 1) * modes];
                for (p, q) in phi.iter().zip(&bridge_lanes.predictor) {
                    for l in 0..LANES {
                        deck[l] += p * q[l];
                    }
                }
            } else {
                deck = [0.0; LANES];
            }
            let predicted = vehicles[contact.vehicle].predictor[contact.dof];
            let rail = model.wheel_rail[contact.wheel];
            for l in 0..models.len() {
                free_gap[c][l] = predicted[l] - deck[l] - models[l].profile.elevation_on(rail, x);
            }
        }
        let vehicles = &*vehicles;
        geometry.assemble(model, contacts, wheel_positions, |v| {
            &vehicles[v].contact_response
        });
        lcp_matrix.copy_from_slice(&geometry.compliance);
        for c in 0..nc {
            lcp_matrix[c * nc + c] += 1.0 / self.stiffness;
        }
    }

    /// The contact law, lane by lane, warm-started from the lane's last
    /// contact set (one elimination per set for the batch).
    #[inline(always)]
    fn contact_law(&mut self, t: f64) -> Result<(), LaneFailure> {
        let models = self.models;
        let nc = self.contacts.len();
        let Self {
            lambda,
            free_gap,
            lcp_matrix,
            lane_gap,
            lane_force,
            lane_previous,
            workspace,
            warm,
            ..
        } = self;
        warm.reset();
        for l in 0..models.len() {
            for c in 0..nc {
                lane_gap[c] = free_gap[c][l];
                lane_previous[c] = lambda[c][l];
            }
            if nc > 0 {
                warm.solve(lcp_matrix, lane_gap, lane_force, workspace, lane_previous)
                    .map_err(|e| LaneFailure {
                        lane: l,
                        error: SolveError::Contact {
                            time: t,
                            positions: describe_positions(models[l], t),
                            reason: e.to_string(),
                        },
                    })?;
            }
            for c in 0..nc {
                lambda[c][l] = lane_force[c];
            }
        }
        Ok(())
    }

    /// Gaps with the forces, then both subsystems finish the step.
    #[inline(always)]
    fn finish(&mut self) {
        let modes = self.models[0].bridge.mode_count();
        let nc = self.contacts.len();
        let Self {
            nm,
            modal,
            contacts,
            vehicles,
            bridge_lanes,
            bridge_moving,
            geometry,
            carried,
            lambda,
            free_gap,
            views,
            ..
        } = self;
        let (w, alpha) = (nm.weight(), nm.alpha);
        let (shapes, on_deck, compliance) =
            (&geometry.shapes, &geometry.on_deck, &geometry.compliance);
        for (c, contact) in contacts.iter().enumerate() {
            let row = &compliance[c * nc..(c + 1) * nc];
            let force = lambda[c];
            for (l, view) in views.iter_mut().enumerate() {
                let mut sum = -0.0;
                for (w_cd, force_d) in row.iter().zip(lambda.iter()) {
                    sum += w_cd * force_d[l];
                }
                view.contact_gaps[contact.wheel] = free_gap[c][l] + sum;
                view.contact_forces[contact.wheel] = force[l];
            }
            if on_deck[c] {
                let shape = &shapes[c * modes..(c + 1) * modes];
                let lanes = &mut *bridge_lanes;
                for i in 0..modes {
                    let scaled = modal.contact_flexibility[i] * shape[i];
                    for l in 0..LANES {
                        lanes.predictor[i][l] -= scaled * force[l];
                        lanes.current_force[i][l] -= shape[i] * force[l];
                    }
                }
            }
            let vehicle = &mut vehicles[contact.vehicle];
            let (start, len) = contact.block;
            for k in start..start + len {
                let response = vehicle.contact_response[(k, contact.column)];
                for l in 0..LANES {
                    vehicle.predictor[k][l] += force[l] * response;
                }
            }
        }
        if *bridge_moving {
            finish_bridge(bridge_lanes, modal, nm);
        }
        for vehicle in vehicles.iter_mut() {
            vehicle.recovery_load.fill([0.0; LANES]);
        }
        for (c, contact) in contacts.iter().enumerate() {
            let load = &mut vehicles[contact.vehicle].recovery_load[contact.dof];
            for l in 0..LANES {
                load[l] += w * lambda[c][l] - alpha * carried[c][l];
            }
        }
        for vehicle in vehicles.iter_mut() {
            recover_vehicle(vehicle, nm);
        }
        carried.copy_from_slice(lambda);
    }

    /// Each lane's energy for the guard and its view for the observer.
    #[inline(always)]
    fn settle(&mut self) {
        let Self {
            modal,
            vehicles,
            bridge_lanes,
            views,
            energy,
            ..
        } = self;
        *energy = mechanical_energy(bridge_lanes, modal, vehicles);
        for (l, view) in views.iter_mut().enumerate() {
            for i in 0..view.modal_displacement.len() {
                view.modal_displacement[i] = bridge_lanes.displacement[i][l];
                view.modal_acceleration[i] = bridge_lanes.acceleration[i][l];
            }
            for (state, vehicle) in view.states.iter_mut().zip(vehicles.iter()) {
                for k in 0..state.displacement.len() {
                    state.displacement[k] = vehicle.displacement[k][l];
                    state.velocity[k] = vehicle.velocity[k][l];
                    state.acceleration[k] = vehicle.acceleration[k][l];
                }
            }
        }
    }
}

impl Stepper for Batch<'_> {
    type Error = LaneFailure;

    fn models(&self) -> &[&Model] {
        self.models
    }

    #[inline(always)]
    fn advance(&mut self, _step: usize, t: f64) -> Result<(), LaneFailure> {
        self.predict(t);
        self.contact_law(t)?;
        self.finish();
        self.settle();
        Ok(())
    }

    /// The lane's energy and its contact forces (every wheel is a contact,
    /// [`eligible`]: the view's forces are the lane's λ).
    fn guarded(&self, lane: usize) -> (f64, &[f64]) {
        (self.energy[lane], &self.views[lane].contact_forces)
    }

    fn view(&self, index: usize, step: usize, t: f64) -> StepView<'_> {
        let view = &self.views[index];
        StepView {
            step,
            time: t,
            modal_displacement: &view.modal_displacement,
            modal_acceleration: &view.modal_acceleration,
            vehicles: &view.states,
            contact_forces: &view.contact_forces,
            contact_gaps: &view.contact_gaps,
            wheel_positions: &self.wheel_positions,
            // Every wheel is a contact (eligible), in flattened order; at
            // t = 0 the geometry is not located yet.
            wheel_modes: (step > 0).then_some(&self.geometry.shapes[..]),
            nodal: None,
        }
    }

    fn lane_error(lane: usize, error: SolveError) -> LaneFailure {
        LaneFailure { lane, error }
    }
}
