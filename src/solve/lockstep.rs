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
//! [`super::unilateral::run`] in the same order (the same Newmark/HHT
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

use nalgebra::{DMatrix, DVector};

use super::guard::Guard;
use super::lcp::{LcpWorkspace, SharedWarmStart};
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::unilateral::{ContactGeometry, block_inverse, contact_wheels, vehicle_step_matrices};
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

/// y += a · A x over a vehicle matrix's nonzero entries, lane by lane, with
/// the rounding of [`super::unilateral::block_gemv`]: nalgebra's
/// `(a·Aᵢⱼ)·xⱼ + yᵢ` for one block covering every DOF, `yᵢ + (a·xⱼ)·Aᵢⱼ`
/// block by block otherwise, each yᵢ taking its terms in ascending j as
/// both do (column by column), here row by row so that yᵢ stays in
/// registers.
#[derive(Debug, Clone)]
struct Product {
    /// One block covering every DOF (nalgebra's product).
    whole: bool,
    /// (row, column, Aᵢⱼ), row by row, columns ascending.
    entries: Vec<(usize, usize, f64)>,
    /// Each row that has entries: (row, its entries' range).
    rows: Vec<(usize, std::ops::Range<usize>)>,
}

impl Product {
    fn new(matrix: &DMatrix<f64>, blocks: &[std::ops::Range<usize>]) -> Self {
        let n = matrix.nrows();
        let whole = blocks.len() == 1 && blocks[0] == (0..n);
        let mut entries = Vec::new();
        let mut rows = Vec::new();
        let whole_block = std::iter::once(0..n).collect::<Vec<_>>();
        let blocks = if whole { &whole_block[..] } else { blocks };
        for block in blocks {
            for i in block.clone() {
                let start = entries.len();
                for j in block.clone() {
                    if matrix[(i, j)] != 0.0 {
                        entries.push((i, j, matrix[(i, j)]));
                    }
                }
                if entries.len() > start {
                    rows.push((i, start..entries.len()));
                }
            }
        }
        Self {
            whole,
            entries,
            rows,
        }
    }

    #[inline(always)]
    fn apply(&self, y: &mut [Lanes], a: f64, x: &[Lanes]) {
        for (i, range) in &self.rows {
            let mut sum = y[*i];
            if self.whole {
                for &(_, j, value) in &self.entries[range.clone()] {
                    let (scaled, xj) = (a * value, &x[j]);
                    for l in 0..LANES {
                        sum[l] += scaled * xj[l];
                    }
                }
            } else {
                for &(_, j, value) in &self.entries[range.clone()] {
                    let xj = &x[j];
                    for l in 0..LANES {
                        sum[l] += (a * xj[l]) * value;
                    }
                }
            }
            y[*i] = sum;
        }
    }
}

/// One vehicle's matrices and its lanes' state.
#[derive(Debug, Clone)]
struct VehicleLanes {
    mass: Product,
    damping: Product,
    stiffness: Product,
    effective_flexibility: Product,
    recovery: Product,
    gravity_load: Vec<f64>,
    /// Static equilibrium on level ground, m (the guard's reference).
    static_displacement: Vec<f64>,
    contact_response: DMatrix<f64>,
    displacement: Vec<Lanes>,
    velocity: Vec<Lanes>,
    acceleration: Vec<Lanes>,
    effective_load: Vec<Lanes>,
    inertia_history: Vec<Lanes>,
    damping_history: Vec<Lanes>,
    predictor: Vec<Lanes>,
    recovery_load: Vec<Lanes>,
    predicted_velocity: Vec<Lanes>,
    recovered_acceleration: Vec<Lanes>,
}

/// The bridge's lanes: modal state and this step's forces.
#[derive(Debug, Clone)]
struct ModalLanes {
    displacement: Vec<Lanes>,
    velocity: Vec<Lanes>,
    acceleration: Vec<Lanes>,
    predictor: Vec<Lanes>,
    current_force: Vec<Lanes>,
    previous_force: Vec<Lanes>,
}

/// What one lane shows its observer and guard.
#[derive(Debug, Clone)]
struct LaneView {
    modal_displacement: Vec<f64>,
    modal_acceleration: Vec<f64>,
    states: Vec<VehicleState>,
    contact_forces: Vec<f64>,
    contact_gaps: Vec<f64>,
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

/// The batch itself ([`run`]), inlined into each instruction-set variant
/// together with the lane kernels it calls.
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
    let model = models[0];
    debug_assert!(eligible(model));
    let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
    let (w, alpha) = (nm.weight(), nm.alpha);
    let bridge = &model.bridge;
    let modes = bridge.mode_count();
    let modal = ModalStep::new(bridge, &nm);
    let (contacts, _, columns) = contact_wheels(model);
    let nc = contacts.len();
    let stiffness = match model.contact {
        ContactLaw::Elastic { stiffness } => stiffness,
        _ => unreachable!("lockstep runs elastic contact only"),
    };

    let mut vehicles = Vec::with_capacity(model.vehicles.len());
    for (v, vehicle) in model.vehicles.iter().enumerate() {
        let n = vehicle.dofs();
        let (effective_flexibility, contact_response) =
            vehicle_step_matrices(model, &nm, v, &contacts, &columns).map_err(|e| (0, e))?;
        let recovery = block_inverse(
            &(&vehicle.mass + &vehicle.damping * (nm.weight() * nm.a7)),
            &vehicle.blocks,
        )
        .expect("eligible: M + (1+α)γΔt C is invertible");
        let at_rest = VehicleState::at_rest(model, v);
        let spread = |x: &DVector<f64>| x.iter().map(|&u| [u; LANES]).collect::<Vec<Lanes>>();
        let zeros = vec![[0.0; LANES]; n];
        let blocks = &vehicle.blocks;
        vehicles.push(VehicleLanes {
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
        });
    }
    let zeros = vec![[0.0; LANES]; modes];
    let mut bridge_lanes = ModalLanes {
        displacement: zeros.clone(),
        velocity: zeros.clone(),
        acceleration: zeros.clone(),
        predictor: zeros.clone(),
        current_force: zeros.clone(),
        previous_force: zeros,
    };

    let mut geometry = ContactGeometry::new(nc, modes);
    // As in `unilateral`: every vehicle starts in static equilibrium, so the
    // force carried into the first HHT term is the static wheel load.
    let mut carried: Vec<Lanes> = contacts
        .iter()
        .map(|c| [model.static_wheel_loads[c.wheel]; LANES])
        .collect();
    let mut lambda: Vec<Lanes> = vec![[0.0; LANES]; nc];
    let mut free_gap: Vec<Lanes> = vec![[0.0; LANES]; nc];
    let mut lcp_matrix = vec![0.0; nc * nc];
    let (mut lane_gap, mut lane_force, mut lane_previous) =
        (vec![0.0; nc], vec![0.0; nc], vec![0.0; nc]);
    let mut workspace = LcpWorkspace::new(nc.max(1));
    let mut warm = SharedWarmStart::new(nc);
    let nw = model.wheels.len();
    let mut wheel_positions = vec![0.0; nw];
    model.wheel_positions(0.0, &mut wheel_positions);
    let guards: Vec<Guard> = models.iter().map(|m| Guard::new(m)).collect();

    let mut views: Vec<LaneView> = (0..lanes)
        .map(|_| {
            let mut contact_gaps = vec![0.0; nw];
            for c in &contacts {
                contact_gaps[c.wheel] =
                    -model.contact.compression(model.static_wheel_loads[c.wheel]);
            }
            LaneView {
                modal_displacement: vec![0.0; modes],
                modal_acceleration: vec![0.0; modes],
                states: (0..model.vehicles.len())
                    .map(|v| VehicleState::at_rest(model, v))
                    .collect(),
                contact_forces: model.static_wheel_loads.clone(),
                contact_gaps,
            }
        })
        .collect();
    for (view, observer) in views.iter().zip(observers.iter_mut()) {
        observer.observe(&StepView {
            step: 0,
            time: 0.0,
            modal_displacement: &view.modal_displacement,
            modal_acceleration: &view.modal_acceleration,
            vehicles: &view.states,
            contact_forces: &view.contact_forces,
            contact_gaps: &view.contact_gaps,
            wheel_positions: &wheel_positions,
            wheel_modes: None,
        });
    }

    let mut bridge_moving = false;
    for step in 1..=model.steps {
        let t = step as f64 * model.time_step;
        model.wheel_positions(t, &mut wheel_positions);
        // The shared geometry first: until a wheel reaches the deck the
        // bridge is exactly at rest (no load, no ground motion), and its
        // Newmark step would return exact zeros, so it is skipped.
        geometry.locate(
            model,
            &modal.contact_flexibility,
            &contacts,
            &wheel_positions,
        );
        bridge_moving = bridge_moving || geometry.on_deck.iter().any(|&on| on);
        if bridge_moving {
            predict_bridge(&mut bridge_lanes, &modal, &nm);
        }
        for vehicle in vehicles.iter_mut() {
            predict_vehicle(vehicle, &nm);
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
            for l in 0..lanes {
                free_gap[c][l] = predicted[l] - deck[l] - models[l].profile.elevation_on(rail, x);
            }
        }
        geometry.assemble(model, &contacts, &wheel_positions, |v| {
            &vehicles[v].contact_response
        });
        let (shapes, on_deck, compliance) =
            (&geometry.shapes, &geometry.on_deck, &geometry.compliance);
        lcp_matrix.copy_from_slice(compliance);
        for c in 0..nc {
            lcp_matrix[c * nc + c] += 1.0 / stiffness;
        }

        // The contact law, lane by lane, warm-started from the lane's last
        // contact set (one elimination per set for the batch).
        warm.reset();
        for l in 0..lanes {
            for c in 0..nc {
                lane_gap[c] = free_gap[c][l];
                lane_previous[c] = lambda[c][l];
            }
            if nc > 0 {
                warm.solve(
                    &lcp_matrix,
                    &lane_gap,
                    &mut lane_force,
                    &mut workspace,
                    &lane_previous,
                )
                .map_err(|e| {
                    (
                        l,
                        SolveError::Contact {
                            time: t,
                            positions: describe_positions(models[l], t),
                            reason: e.to_string(),
                        },
                    )
                })?;
            }
            for c in 0..nc {
                lambda[c][l] = lane_force[c];
            }
        }

        // Gaps with the forces, then both subsystems finish the step.
        for (c, contact) in contacts.iter().enumerate() {
            let row = &compliance[c * nc..(c + 1) * nc];
            let force = lambda[c];
            for (l, view) in views.iter_mut().enumerate() {
                let mut sum = -0.0;
                for (w_cd, force_d) in row.iter().zip(&lambda) {
                    sum += w_cd * force_d[l];
                }
                view.contact_gaps[contact.wheel] = free_gap[c][l] + sum;
                view.contact_forces[contact.wheel] = force[l];
            }
            if on_deck[c] {
                let shape = &shapes[c * modes..(c + 1) * modes];
                let lanes = &mut bridge_lanes;
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
        if bridge_moving {
            finish_bridge(&mut bridge_lanes, &modal, &nm);
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
            recover_vehicle(vehicle, &nm);
        }
        carried.copy_from_slice(&lambda);

        // Each lane's guard, view and observer.
        let energy = mechanical_energy(&bridge_lanes, &modal, &vehicles);
        for (l, view) in views.iter_mut().enumerate() {
            for c in 0..nc {
                lane_force[c] = lambda[c][l];
            }
            guards[l]
                .check_energy(models[l], energy[l], &lane_force, t, step)
                .map_err(|e| (l, e))?;
            for i in 0..modes {
                view.modal_displacement[i] = bridge_lanes.displacement[i][l];
                view.modal_acceleration[i] = bridge_lanes.acceleration[i][l];
            }
            for (state, vehicle) in view.states.iter_mut().zip(&vehicles) {
                for k in 0..state.displacement.len() {
                    state.displacement[k] = vehicle.displacement[k][l];
                    state.velocity[k] = vehicle.velocity[k][l];
                    state.acceleration[k] = vehicle.acceleration[k][l];
                }
            }
        }
        for (view, observer) in views.iter().zip(observers.iter_mut()) {
            observer.observe(&StepView {
                step,
                time: t,
                modal_displacement: &view.modal_displacement,
                modal_acceleration: &view.modal_acceleration,
                vehicles: &view.states,
                contact_forces: &view.contact_forces,
                contact_gaps: &view.contact_gaps,
                wheel_positions: &wheel_positions,
                // Every wheel is a contact (eligible), in flattened order.
                wheel_modes: Some(&geometry.shapes),
            });
        }
    }
    Ok(())
}

/// The guard's mechanical energy per lane, J: ½Σᵢ(q̇ᵢ² + ωᵢ²qᵢ²) +
/// Σᵥ[½u̇ᵀMu̇ + ½(u − u₀)ᵀK(u − u₀)] ([`Guard`]; summed in another order,
/// which only moves a divergence threshold by round-off).
#[inline(always)]
fn mechanical_energy(bridge: &ModalLanes, modal: &ModalStep, vehicles: &[VehicleLanes]) -> Lanes {
    let mut twice = [0.0; LANES];
    for ((q, v), k) in bridge
        .displacement
        .iter()
        .zip(&bridge.velocity)
        .zip(&modal.stiffness)
    {
        for l in 0..LANES {
            twice[l] += v[l] * v[l] + k * q[l] * q[l];
        }
    }
    for vehicle in vehicles {
        let (u, u0, v) = (
            &vehicle.displacement,
            &vehicle.static_displacement,
            &vehicle.velocity,
        );
        for &(i, j, m) in &vehicle.mass.entries {
            for l in 0..LANES {
                twice[l] += v[i][l] * m * v[j][l];
            }
        }
        for &(i, j, k) in &vehicle.stiffness.entries {
            for l in 0..LANES {
                twice[l] += (u[i][l] - u0[i]) * k * (u[j][l] - u0[j]);
            }
        }
    }
    twice.map(|e| 0.5 * e)
}

/// [`ModalStep::predict`] with no moving load and no ground motion, lane by
/// lane.
#[inline(always)]
fn predict_bridge(lanes: &mut ModalLanes, modal: &ModalStep, nm: &Newmark) {
    let (w, alpha) = (nm.weight(), nm.alpha);
    lanes.current_force.fill([0.0; LANES]);
    for i in 0..lanes.predictor.len() {
        let (c, k, flexibility) = (
            modal.modal_damping[i],
            modal.stiffness[i],
            modal.flexibility[i],
        );
        let (q, v, a) = (
            lanes.displacement[i],
            lanes.velocity[i],
            lanes.acceleration[i],
        );
        let (current, previous) = (lanes.current_force[i], lanes.previous_force[i]);
        let predictor = &mut lanes.predictor[i];
        for l in 0..LANES {
            let inertia = nm.inertia_history(q[l], v[l], a[l]);
            let damping = nm.damping_history(q[l], v[l], a[l]);
            predictor[l] = (w * current[l] - alpha * previous[l]
                + inertia
                + w * c * damping
                + alpha * (c * v[l] + k * q[l]))
                * flexibility;
        }
    }
}

/// [`ModalStep::finish`], lane by lane.
#[inline(always)]
fn finish_bridge(lanes: &mut ModalLanes, modal: &ModalStep, nm: &Newmark) {
    let (w, alpha) = (nm.weight(), nm.alpha);
    for i in 0..lanes.predictor.len() {
        let (c, k) = (modal.modal_damping[i], modal.stiffness[i]);
        let (current, previous) = (lanes.current_force[i], lanes.previous_force[i]);
        let q = lanes.predictor[i];
        let (q_old, v_old, a_old) = (
            lanes.displacement[i],
            lanes.velocity[i],
            lanes.acceleration[i],
        );
        let mut a_new = [0.0; LANES];
        let mut v_new = [0.0; LANES];
        for l in 0..LANES {
            a_new[l] = (w * current[l]
                - alpha * previous[l]
                - w * c * (v_old[l] + nm.a6 * a_old[l])
                - w * k * q[l]
                + alpha * (c * v_old[l] + k * q_old[l]))
                / (1.0 + w * nm.a7 * c);
            v_new[l] = nm.velocity(v_old[l], a_old[l], a_new[l]);
        }
        lanes.displacement[i] = q;
        lanes.acceleration[i] = a_new;
        lanes.velocity[i] = v_new;
    }
    std::mem::swap(&mut lanes.previous_force, &mut lanes.current_force);
}

/// The vehicle predictor's load R̂ = f_g + M hₐ + (1+α)C h_v + α(C u̇ₙ + K uₙ)
/// (the −αEλₙ term is the caller's), as in `unilateral`.
#[inline(always)]
fn predict_vehicle(vehicle: &mut VehicleLanes, nm: &Newmark) {
    for k in 0..vehicle.displacement.len() {
        let (u, v, a) = (
            vehicle.displacement[k],
            vehicle.velocity[k],
            vehicle.acceleration[k],
        );
        for l in 0..LANES {
            vehicle.inertia_history[k][l] = nm.inertia_history(u[l], v[l], a[l]);
            vehicle.damping_history[k][l] = nm.damping_history(u[l], v[l], a[l]);
        }
        vehicle.effective_load[k] = [vehicle.gravity_load[k]; LANES];
    }
    let load = &mut vehicle.effective_load;
    vehicle.mass.apply(load, 1.0, &vehicle.inertia_history);
    vehicle
        .damping
        .apply(load, nm.weight(), &vehicle.damping_history);
    if nm.alpha != 0.0 {
        vehicle.damping.apply(load, nm.alpha, &vehicle.velocity);
        vehicle
            .stiffness
            .apply(load, nm.alpha, &vehicle.displacement);
    }
}

/// The vehicle's accelerations from the HHT equations of motion and its new
/// state, as in `unilateral` (`recovery_load` holds the contact share).
#[inline(always)]
fn recover_vehicle(vehicle: &mut VehicleLanes, nm: &Newmark) {
    let w = nm.weight();
    let n = vehicle.displacement.len();
    for k in 0..n {
        let gravity = vehicle.gravity_load[k];
        for l in 0..LANES {
            vehicle.recovery_load[k][l] += gravity;
        }
    }
    vehicle
        .stiffness
        .apply(&mut vehicle.recovery_load, -w, &vehicle.predictor);
    for k in 0..n {
        let (v, a) = (vehicle.velocity[k], vehicle.acceleration[k]);
        for l in 0..LANES {
            vehicle.predicted_velocity[k][l] = nm.a6 * a[l] + v[l];
        }
    }
    vehicle
        .damping
        .apply(&mut vehicle.recovery_load, -w, &vehicle.predicted_velocity);
    if nm.alpha != 0.0 {
        vehicle
            .damping
            .apply(&mut vehicle.recovery_load, nm.alpha, &vehicle.velocity);
        vehicle
            .stiffness
            .apply(&mut vehicle.recovery_load, nm.alpha, &vehicle.displacement);
    }
    vehicle.recovered_acceleration.fill([0.0; LANES]);
    vehicle.recovery.apply(
        &mut vehicle.recovered_acceleration,
        1.0,
        &vehicle.recovery_load,
    );
    for k in 0..n {
        let (v, a, a_new) = (
            vehicle.velocity[k],
            vehicle.acceleration[k],
            vehicle.recovered_acceleration[k],
        );
        for l in 0..LANES {
            vehicle.velocity[k][l] = nm.velocity(v[l], a[l], a_new[l]);
        }
        vehicle.acceleration[k] = a_new;
        vehicle.displacement[k] = vehicle.predictor[k];
    }
}
