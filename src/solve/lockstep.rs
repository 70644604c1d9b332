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

mod lanes;

use nalgebra::DVector;

use self::lanes::{
    LaneView, ModalLanes, Product, VehicleLanes, finish_bridge, mechanical_energy, predict_bridge,
    predict_vehicle, recover_vehicle,
};

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
