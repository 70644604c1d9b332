//! Coupled vehicle–bridge integration with permanent wheel contact.
//!
//! The wheel DOFs are eliminated by the contact kinematics, as in the
//! "traditional permanent contact model" of the LCP separation paper
//! (Section 2) and Yang & Yau (1997): a wheel at x(t) = v t + x₀ on a deck
//! with deflection w = Σ φᵢ(x) qᵢ and roughness r(x) moves with
//! u_w = φ·q + r,  u̇_w = φ·q̇ + v(φ′·q + r′),
//! ü_w = φ·q̈ + 2v φ′·q̇ + v²(φ″·q + r″).
//! Newmark (average acceleration by default) advances the modal coordinates q
//! and the vehicles' free DOFs together. Per step the unknowns are condensed
//! onto the contact forces λ (compression positive): the bridge gives
//! q = q* − DΦᵀλ with D = diag(1/k̂ᵢ), k̂ᵢ = ωᵢ² + a₀ + 2a₁ζᵢωᵢ, so every
//! wheel's kinematics is affine in λ; each vehicle's wheel rows
//! ([`super::partition`]) then close the system (I − A)λ = b, one small
//! dense solve per step. Cost per step: O(modes·wheels²) + O(Σ dofᵥ²) +
//! O(wheels³); nothing is allocated in the loop.

use super::dense::lu_solve;
use super::guard::Guard;
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::partition::Partition;
use super::{Observer, Progress, SolveError, StepView, VehicleState};
use crate::model::Model;
use crate::vehicle::WheelKind;

/// A wheel that rides the surface through a vehicle DOF.
#[derive(Debug, Clone, Copy)]
struct ContactWheel {
    /// Flattened wheel index.
    wheel: usize,
    /// Vehicle index.
    vehicle: usize,
    /// The wheel's DOF in its vehicle.
    dof: usize,
    /// Vehicle speed, m/s.
    speed: f64,
}

/// Mode shape data of one contact point at the current step.
#[derive(Debug, Clone)]
struct ContactShapes {
    values: Vec<f64>,
    slopes: Vec<f64>,
    curvatures: Vec<f64>,
    /// (1+α)φ/k̂, elementwise: modal response to a unit contact force.
    scaled: Vec<f64>,
    /// P₁ = a₁φ + vφ′ and P₂ = a₀φ + 2va₁φ′ + v²φ″: the velocity and
    /// acceleration rows acting on q_{n+1}.
    velocity_row: Vec<f64>,
    acceleration_row: Vec<f64>,
}

impl ContactShapes {
    fn new(modes: usize) -> Self {
        Self {
            values: vec![0.0; modes],
            slopes: vec![0.0; modes],
            curvatures: vec![0.0; modes],
            scaled: vec![0.0; modes],
            velocity_row: vec![0.0; modes],
            acceleration_row: vec![0.0; modes],
        }
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Integrates the model with permanent contact, calling `observer` at t = 0
/// and after every step.
pub fn run(
    model: &Model,
    observer: &mut dyn Observer,
    progress: Progress<'_>,
) -> Result<(), SolveError> {
    let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
    let bridge = &model.bridge;
    let modes = bridge.mode_count();

    let mut modal = ModalStep::new(bridge, &nm);

    // Contact wheels, load wheels, and each vehicle's partition.
    let mut contacts: Vec<ContactWheel> = Vec::new();
    let mut load_wheels = Vec::new();
    let mut wheel_dofs: Vec<Vec<usize>> = vec![Vec::new(); model.vehicles.len()];
    for (flat, r) in model.wheels.iter().enumerate() {
        let vehicle = &model.vehicles[r.vehicle];
        match vehicle.wheels[r.wheel].kind {
            WheelKind::Dof(dof) => {
                contacts.push(ContactWheel {
                    wheel: flat,
                    vehicle: r.vehicle,
                    dof,
                    speed: vehicle.speed,
                });
                wheel_dofs[r.vehicle].push(dof);
            }
            WheelKind::Load(load) => load_wheels.push((flat, load)),
        }
    }
    let nc = contacts.len();
    // Global contact index of each vehicle's local wheels.
    let contact_of: Vec<Vec<usize>> = (0..model.vehicles.len())
        .map(|v| (0..nc).filter(|&c| contacts[c].vehicle == v).collect())
        .collect();

    let mut states = Vec::with_capacity(model.vehicles.len());
    let mut partitions = Vec::with_capacity(model.vehicles.len());
    for (v, vehicle) in model.vehicles.iter().enumerate() {
        let partition = Partition::new(vehicle, wheel_dofs[v].clone(), &nm).ok_or_else(|| {
            SolveError::SingularContact {
                time: 0.0,
                reason: format!(
                    "vehicle {} has a singular effective stiffness once its wheels are held",
                    v + 1
                ),
            }
        })?;
        states.push(VehicleState::at_rest(model, v));
        partitions.push(partition);
    }

    // Work arrays.
    let mut shapes: Vec<ContactShapes> = (0..nc).map(|_| ContactShapes::new(modes)).collect();
    // Wheel kinematics b + Sλ: displacement, velocity, acceleration.
    let mut base = vec![[0.0f64; 3]; nc];
    let mut sens = vec![[0.0f64; 3]; nc * nc];
    let mut system = vec![0.0; nc * nc];
    let mut lambda = vec![0.0; nc];
    let nw = model.wheels.len();
    let mut contact_forces = model.static_wheel_loads.clone();
    let contact_gaps = vec![0.0; nw];
    let mut wheel_positions = vec![0.0; nw];
    model.wheel_positions(0.0, &mut wheel_positions);

    observer.observe(&StepView::of(
        0,
        0.0,
        &modal,
        &states,
        &contact_forces,
        &contact_gaps,
        &wheel_positions,
    ));

    let guard = Guard::new(model);
    let report_every = (model.steps / 200).max(1);
    for step in 1..=model.steps {
        let t = step as f64 * model.time_step;
        model.wheel_positions(t, &mut wheel_positions);

        modal.predict(
            &nm,
            bridge,
            load_wheels
                .iter()
                .map(|&(flat, load)| (wheel_positions[flat], load)),
        );
        let (q_star, inertia_history, damping_history) = (
            &modal.predictor,
            &modal.inertia_history,
            &modal.damping_history,
        );

        // Wheel kinematics at λ = 0 and their sensitivities to λ.
        for (c, contact) in contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let v = contact.speed;
            let s = &mut shapes[c];
            bridge.mode_values_slopes_curvatures(
                x,
                &mut s.values,
                &mut s.slopes,
                &mut s.curvatures,
            );
            for i in 0..modes {
                s.scaled[i] = s.values[i] * modal.contact_flexibility[i];
                s.velocity_row[i] = nm.a1 * s.values[i] + v * s.slopes[i];
                s.acceleration_row[i] =
                    nm.a0 * s.values[i] + 2.0 * v * nm.a1 * s.slopes[i] + v * v * s.curvatures[i];
            }
            let (r, dr, ddr) = model.profile.elevation_slope_curvature(x);
            base[c] = [
                dot(&s.values, q_star) + r,
                dot(&s.velocity_row, q_star) - dot(&s.values, damping_history) + v * dr,
                dot(&s.acceleration_row, q_star)
                    - dot(&s.values, inertia_history)
                    - 2.0 * v * dot(&s.slopes, damping_history)
                    + v * v * ddr,
            ];
        }
        for c in 0..nc {
            for d in 0..nc {
                let (sc, sd) = (&shapes[c], &shapes[d]);
                sens[c * nc + d] = [
                    -dot(&sc.values, &sd.scaled),
                    -dot(&sc.velocity_row, &sd.scaled),
                    -dot(&sc.acceleration_row, &sd.scaled),
                ];
            }
        }

        // Wheel rows of each vehicle: λ = λ⁰ + M̃ü_W + C̃u̇_W + K̃u_W → (I − A)λ = b.
        for (v, partition) in partitions.iter_mut().enumerate() {
            let state = &states[v];
            partition.begin_step(
                &nm,
                &state.displacement,
                &state.velocity,
                &state.acceleration,
                contact_of[v]
                    .iter()
                    .map(|&c| contact_forces[contacts[c].wheel]),
            );
            for (a, &c) in contact_of[v].iter().enumerate() {
                let mut rhs = partition.base_forces[a];
                for (b, &cb) in contact_of[v].iter().enumerate() {
                    let (m, k, u) = (
                        partition.condensed_mass[(a, b)],
                        partition.condensed_damping[(a, b)],
                        partition.condensed_stiffness[(a, b)],
                    );
                    rhs += m * base[cb][2] + k * base[cb][1] + u * base[cb][0];
                }
                lambda[c] = rhs;
                for d in 0..nc {
                    let mut a_cd = 0.0;
                    for (b, &cb) in contact_of[v].iter().enumerate() {
                        let s = sens[cb * nc + d];
                        a_cd += partition.condensed_mass[(a, b)] * s[2]
                            + partition.condensed_damping[(a, b)] * s[1]
                            + partition.condensed_stiffness[(a, b)] * s[0];
                    }
                    system[c * nc + d] = if c == d { 1.0 - a_cd } else { -a_cd };
                }
            }
        }
        if nc > 0 && !lu_solve(&mut system, &mut lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the condensed contact system is singular".into(),
            });
        }

        // Bridge: q = q* − DΦᵀλ, then Newmark velocity and acceleration.
        for (c, s) in shapes.iter().enumerate() {
            modal.apply_contact(&s.values, lambda[c]);
        }
        modal.finish(&nm);
        let (q, qd, qdd) = (&modal.displacement, &modal.velocity, &modal.acceleration);
        // Wheels follow the surface exactly; then the free DOFs.
        for (c, contact) in contacts.iter().enumerate() {
            let s = &shapes[c];
            let x = wheel_positions[contact.wheel];
            let v = contact.speed;
            let (r, dr, ddr) = model.profile.elevation_slope_curvature(x);
            let (w, wx, wxx) = (dot(&s.values, q), dot(&s.slopes, q), dot(&s.curvatures, q));
            let state = &mut states[contact.vehicle];
            state.displacement[contact.dof] = w + r;
            state.velocity[contact.dof] = dot(&s.values, qd) + v * (wx + dr);
            state.acceleration[contact.dof] =
                dot(&s.values, qdd) + 2.0 * v * dot(&s.slopes, qd) + v * v * (wxx + ddr);
            contact_forces[contact.wheel] = lambda[c];
        }
        for (state, partition) in states.iter_mut().zip(partitions.iter_mut()) {
            partition.finish_step(
                &nm,
                &mut state.displacement,
                &mut state.velocity,
                &mut state.acceleration,
            );
        }

        guard.check(model, &modal, &states, &lambda, t, step)?;

        observer.observe(&StepView::of(
            step,
            t,
            &modal,
            &states,
            &contact_forces,
            &contact_gaps,
            &wheel_positions,
        ));
        if step % report_every == 0 || step == model.steps {
            progress(step, model.steps);
        }
    }
    Ok(())
}
