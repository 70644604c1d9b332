//! Coupled vehicle–bridge integration with permanent wheel contact.
//!
//! Per Newmark step (constants in [`super::newmark`]):
//! 1. Predictors without contact forces: bridge q*ᵢ = R̂ᵢ/k̂ᵢ with the diagonal
//!    modal effective stiffness k̂ᵢ = ωᵢ² + a₀ + 2a₁ζᵢωᵢ and the moving loads in
//!    R̂; each vehicle u* = K̂ᵥ⁻¹ R̂ᵥ.
//! 2. With contact forces λ (compression positive) the end-of-step states are
//!    q = q* − D Φᵀλ (D = diag(1/k̂ᵢ), Φ the mode values at the wheels) and
//!    u = u* + Hλ (H = K̂ᵥ⁻¹E, E the wheel DOF selector), so the gaps
//!    g = u_w − Φq − r are affine in λ: g = g* + Wλ with the contact
//!    compliance W = EᵀH + ΦDΦᵀ (symmetric positive definite, m/N).
//! 3. Permanent contact: g = 0, i.e. Wλ = −g*, solved by Cholesky.
//! This is the Lagrange-multiplier form of the LCP separation paper's
//! uncoupled subsystems (its Section 3) with equality instead of
//! complementarity, so the unilateral models reuse steps 1–2 unchanged.
//! Cost per step: O(modes·wheels²) + O(Σ dofᵥ²) + O(wheels³); no allocation.

use nalgebra::{DMatrix, DVector};

use super::dense::cholesky_solve;
use super::newmark::Newmark;
use super::{Observer, Progress, SolveError, StepView, VehicleState, describe_positions};
use crate::model::Model;
use crate::vehicle::WheelKind;

/// A wheel whose contact force is an unknown of the step.
#[derive(Debug, Clone, Copy)]
struct ContactWheel {
    /// Flattened wheel index.
    wheel: usize,
    /// Vehicle index.
    vehicle: usize,
    /// The wheel's DOF in its vehicle.
    dof: usize,
    /// Column of this wheel in its vehicle's H.
    column: usize,
}

/// Per-vehicle constant step matrices.
#[derive(Debug, Clone)]
struct VehicleStep {
    /// K̂⁻¹, the inverse effective stiffness, m/N.
    effective_flexibility: DMatrix<f64>,
    /// H = K̂⁻¹E: DOF response to a unit contact force at each contact wheel, m/N.
    contact_response: DMatrix<f64>,
    /// Work vectors: effective load R̂ and the history combinations.
    effective_load: DVector<f64>,
    inertia_history: DVector<f64>,
    damping_history: DVector<f64>,
    /// Predictor u*.
    predictor: DVector<f64>,
}

/// Integrates the model with permanent contact, calling `observer` at t = 0
/// and after every step.
pub fn run(
    model: &Model,
    observer: &mut dyn Observer,
    progress: Progress<'_>,
) -> Result<(), SolveError> {
    let nm = Newmark::new(model.beta, model.gamma, model.time_step);
    let bridge = &model.bridge;
    let modes = bridge.mode_count();

    // Bridge modal effective stiffness and damping coefficients 2ζω.
    let modal_damping: Vec<f64> = bridge
        .circular_frequencies
        .iter()
        .zip(&bridge.damping_ratios)
        .map(|(w, z)| 2.0 * z * w)
        .collect();
    let modal_flexibility: Vec<f64> = bridge
        .circular_frequencies
        .iter()
        .zip(&modal_damping)
        .map(|(w, c)| 1.0 / (w * w + nm.a0 + nm.a1 * c))
        .collect();

    // Contact wheels and load wheels.
    let mut contacts = Vec::new();
    let mut load_wheels = Vec::new();
    for (flat, r) in model.wheels.iter().enumerate() {
        match model.vehicles[r.vehicle].wheels[r.wheel].kind {
            WheelKind::Dof(dof) => {
                let column = contacts
                    .iter()
                    .filter(|c: &&ContactWheel| c.vehicle == r.vehicle)
                    .count();
                contacts.push(ContactWheel {
                    wheel: flat,
                    vehicle: r.vehicle,
                    dof,
                    column,
                });
            }
            WheelKind::Load(load) => load_wheels.push((flat, load)),
        }
    }
    let nc = contacts.len();

    // Vehicle states (static equilibrium on level ground) and step matrices.
    let mut states = Vec::with_capacity(model.vehicles.len());
    let mut steps = Vec::with_capacity(model.vehicles.len());
    for (v, vehicle) in model.vehicles.iter().enumerate() {
        let n = vehicle.dofs();
        let (static_displacement, _) = vehicle
            .static_equilibrium(v + 1)
            .expect("static equilibrium was checked when the model was built");
        let effective = &vehicle.stiffness + &vehicle.mass * nm.a0 + &vehicle.damping * nm.a1;
        let effective_flexibility =
            effective
                .try_inverse()
                .ok_or_else(|| SolveError::SingularContact {
                    time: 0.0,
                    reason: format!("vehicle {} has a singular effective stiffness", v + 1),
                })?;
        let vehicle_contacts: Vec<&ContactWheel> =
            contacts.iter().filter(|c| c.vehicle == v).collect();
        let mut contact_response = DMatrix::zeros(n, vehicle_contacts.len());
        for c in &vehicle_contacts {
            contact_response.set_column(c.column, &effective_flexibility.column(c.dof));
        }
        states.push(VehicleState {
            displacement: static_displacement.clone(),
            velocity: DVector::zeros(n),
            acceleration: DVector::zeros(n),
            static_displacement,
        });
        steps.push(VehicleStep {
            effective_flexibility,
            contact_response,
            effective_load: DVector::zeros(n),
            inertia_history: DVector::zeros(n),
            damping_history: DVector::zeros(n),
            predictor: DVector::zeros(n),
        });
    }

    // Bridge state and work arrays.
    let mut q = vec![0.0; modes];
    let mut qd = vec![0.0; modes];
    let mut qdd = vec![0.0; modes];
    let mut q_star = vec![0.0; modes];
    let mut phi_work = vec![0.0; modes];
    let mut phi_contacts = vec![0.0; nc * modes];
    let mut compliance = vec![0.0; nc * nc];
    let mut lambda = vec![0.0; nc];
    let nw = model.wheels.len();
    let mut contact_forces = model.static_wheel_loads.clone();
    let mut wheel_positions: Vec<f64> = (0..nw).map(|w| model.wheel_position(w, 0.0)).collect();

    observer.observe(&StepView {
        step: 0,
        time: 0.0,
        modal_displacement: &q,
        modal_acceleration: &qdd,
        vehicles: &states,
        contact_forces: &contact_forces,
        wheel_positions: &wheel_positions,
    });

    let report_every = (model.steps / 200).max(1);
    for step in 1..=model.steps {
        let t = step as f64 * model.time_step;
        for (w, x) in wheel_positions.iter_mut().enumerate() {
            *x = model.wheel_position(w, t);
        }

        // 1. Bridge predictor: R̂ = F + inertia and damping history; F from loads.
        for i in 0..modes {
            q_star[i] = nm.inertia_history(q[i], qd[i], qdd[i])
                + modal_damping[i] * nm.damping_history(q[i], qd[i], qdd[i]);
        }
        for &(flat, load) in &load_wheels {
            let x = wheel_positions[flat];
            if bridge.is_on(x) {
                bridge.mode_values(x, &mut phi_work);
                for i in 0..modes {
                    q_star[i] -= load * phi_work[i];
                }
            }
        }
        for i in 0..modes {
            q_star[i] *= modal_flexibility[i];
        }

        // Vehicle predictors u* = K̂⁻¹ (f_g + M h_m + C h_c).
        for ((vehicle, state), vs) in model.vehicles.iter().zip(&states).zip(steps.iter_mut()) {
            for k in 0..vehicle.dofs() {
                let (u, v, a) = (
                    state.displacement[k],
                    state.velocity[k],
                    state.acceleration[k],
                );
                vs.inertia_history[k] = nm.inertia_history(u, v, a);
                vs.damping_history[k] = nm.damping_history(u, v, a);
            }
            vs.effective_load.copy_from(&vehicle.gravity_load);
            vs.effective_load
                .gemv(1.0, &vehicle.mass, &vs.inertia_history, 1.0);
            vs.effective_load
                .gemv(1.0, &vehicle.damping, &vs.damping_history, 1.0);
            vs.predictor
                .gemv(1.0, &vs.effective_flexibility, &vs.effective_load, 0.0);
        }

        // 2. Gaps without contact forces and the contact compliance W.
        for (c, contact) in contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let phi = &mut phi_contacts[c * modes..(c + 1) * modes];
            bridge.mode_values(x, phi);
            let bridge_w: f64 = phi.iter().zip(&q_star).map(|(p, q)| p * q).sum();
            lambda[c] = -(steps[contact.vehicle].predictor[contact.dof]
                - bridge_w
                - model.profile.elevation(x));
        }
        for a in 0..nc {
            for b in 0..=a {
                let pa = &phi_contacts[a * modes..(a + 1) * modes];
                let pb = &phi_contacts[b * modes..(b + 1) * modes];
                let mut w: f64 = (0..modes)
                    .map(|i| pa[i] * pb[i] * modal_flexibility[i])
                    .sum();
                let (ca, cb) = (contacts[a], contacts[b]);
                if ca.vehicle == cb.vehicle {
                    w += steps[ca.vehicle].contact_response[(ca.dof, cb.column)];
                }
                compliance[a * nc + b] = w;
                compliance[b * nc + a] = w;
            }
        }

        // 3. Permanent contact: W λ = −g*.
        if nc > 0 && !cholesky_solve(&mut compliance, &mut lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the contact compliance matrix is not positive definite".into(),
            });
        }

        // Correct the predictors and finish the Newmark step.
        for c in 0..nc {
            let phi = &phi_contacts[c * modes..(c + 1) * modes];
            for i in 0..modes {
                q_star[i] -= modal_flexibility[i] * phi[i] * lambda[c];
            }
        }
        for i in 0..modes {
            let a_new = nm.acceleration(q_star[i], q[i], qd[i], qdd[i]);
            qd[i] = nm.velocity(qd[i], qdd[i], a_new);
            qdd[i] = a_new;
            q[i] = q_star[i];
        }
        for (c, contact) in contacts.iter().enumerate() {
            let vs = &mut steps[contact.vehicle];
            vs.predictor
                .axpy(lambda[c], &vs.contact_response.column(contact.column), 1.0);
        }
        for (state, vs) in states.iter_mut().zip(&steps) {
            for k in 0..state.displacement.len() {
                let (u, vel, acc) = (
                    state.displacement[k],
                    state.velocity[k],
                    state.acceleration[k],
                );
                let a_new = nm.acceleration(vs.predictor[k], u, vel, acc);
                state.velocity[k] = nm.velocity(vel, acc, a_new);
                state.acceleration[k] = a_new;
                state.displacement[k] = vs.predictor[k];
            }
        }
        for (c, contact) in contacts.iter().enumerate() {
            contact_forces[contact.wheel] = lambda[c];
        }

        let health: f64 = q.iter().sum::<f64>() + lambda.iter().sum::<f64>();
        if !health.is_finite() {
            return Err(SolveError::Diverged {
                time: t,
                step,
                positions: describe_positions(model, t),
                cause: "the state is no longer finite; the time step may be too large or the Newmark parameters unstable (β < γ/2)".into(),
            });
        }

        observer.observe(&StepView {
            step,
            time: t,
            modal_displacement: &q,
            modal_acceleration: &qdd,
            vehicles: &states,
            contact_forces: &contact_forces,
            wheel_positions: &wheel_positions,
        });
        if step % report_every == 0 || step == model.steps {
            progress(step, model.steps);
        }
    }
    Ok(())
}
