//! The uncoupled iterative scheme of the plate-deck paper (its Section 2.5
//! and Fig. 5, after Zhu & Law 2002): in every Newmark step the vehicles and
//! the bridge are solved separately and the interaction forces are iterated
//! until the contact displacements stop changing.
//!
//! Iteration k of a step, with the contact forces λ⁽ᵏ⁾ (N, compression
//! positive; λ⁽⁰⁾ = the previous step's forces):
//! 1. the bridge takes λ⁽ᵏ⁾: q = q* − DΦᵀλ⁽ᵏ⁾ (paper Eq. 30), giving the
//!    contact displacements w⁽ᵏ⁾ = φ·q + r and their velocities and
//!    accelerations by the moving-contact kinematics ([`super::permanent`]);
//! 2. the vehicles, with their wheels following that motion, give the
//!    interaction forces λ̃ (paper Eqs. 21–26, condensed onto the wheels);
//! 3. λ⁽ᵏ⁺¹⁾ = λ⁽ᵏ⁾ + ωₖ(λ̃ − λ⁽ᵏ⁾), with Aitken's Δ² relaxation for ωₖ
//!    (ω₀ = 1, so the first pass is the paper's plain substitution; Aitken
//!    keeps the iteration converging when a heavy vehicle on a light deck
//!    would make plain substitution overshoot — Küttler & Wall 2008, Eq. 44);
//! 4. stop when max_c |w_c⁽ᵏ⁺¹⁾ − w_c⁽ᵏ⁾| ≤ ε · max(max_c |w_c|, 1 nm)
//!    (paper Eq. 32, made relative; ε = `tolerance`) and also
//!    max_c |λ_c⁽ᵏ⁺¹⁾ − λ_c⁽ᵏ⁾| ≤ ε · max(max_c |λ_c|, 1 N).
//!
//! Why the force test too: within one step the deck barely moves in
//! response to a change of force — inertia dominates, Δw ≈ Σφᵢ²Δλ/a₀ with
//! a₀ = 1/(βΔt²) — so the paper's displacement test alone accepts force
//! errors of order 1e-4 of the wheel load (measured on the three-span beam
//! scene: 1e-5 relative differences from `coupled` in every history). With
//! both tests the step satisfies the same equations as `coupled` to the
//! tolerance, so the two agree to it. Cost per iteration O(modes·wheels) +
//! O(Σ wheelsᵥ²); nothing is allocated in the loop.

use super::GroundStep;
use super::guard::Guard;
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::permanent::PermanentContacts;
use super::{Observer, Progress, SolveError, SolveStats, StepView, describe_positions};
use crate::model::Model;

/// Smallest deflection scale of the convergence test, m: below a nanometre
/// the relative test would chase round-off.
pub const DISPLACEMENT_FLOOR: f64 = 1e-9;
/// Smallest force scale of the convergence test, N.
pub const FORCE_FLOOR: f64 = 1.0;

/// Integrates the model with permanent contact by per-step iteration.
pub fn run(
    model: &Model,
    observer: &mut dyn Observer,
    progress: Progress<'_>,
) -> Result<SolveStats, SolveError> {
    let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
    let bridge = &model.bridge;
    let mut modal = ModalStep::new(bridge, &nm)
        .with_ground(model.ground_participation())
        .with_lateral_ground(model.lateral_ground_participation());
    let mut step_state = PermanentContacts::new(model, &nm)?;
    let nc = step_state.count();
    let (tolerance, max_iterations) = (model.iteration.tolerance, model.iteration.max_iterations);

    let nw = model.wheels.len();
    let mut contact_forces = model.static_wheel_loads.clone();
    let contact_gaps = vec![0.0; nw];
    let mut wheel_positions = vec![0.0; nw];
    model.wheel_positions(0.0, &mut wheel_positions);
    // Work arrays: forces, their update, residuals, wheel kinematics.
    let mut lambda = vec![0.0; nc];
    let mut answer = vec![0.0; nc];
    let mut residual = vec![0.0; nc];
    let mut previous_residual = vec![0.0; nc];
    let mut kinematics = vec![[0.0f64; 3]; nc];
    let mut previous_displacement = vec![0.0; nc];
    for (c, contact) in step_state.contacts.iter().enumerate() {
        lambda[c] = contact_forces[contact.wheel];
    }

    observer.observe(&StepView::of(
        0,
        0.0,
        &modal,
        &step_state.states,
        &contact_forces,
        &contact_gaps,
        &wheel_positions,
    ));

    let guard = Guard::new(model);
    let mut ground = GroundStep::new(model, &nm);
    let report_every = (model.steps / 200).max(1);
    let (mut total_iterations, mut most_iterations) = (0usize, 0usize);
    for step in 1..=model.steps {
        let t = step as f64 * model.time_step;
        model.wheel_positions(t, &mut wheel_positions);
        step_state.gravity_ratio = ground.step_of(model, &mut modal, t);
        step_state.lateral_ground = ground.lateral_load;
        step_state.begin_step(model, &nm, &mut modal, t, &wheel_positions, &contact_forces);

        let mut relaxation = 1.0;
        let mut iterations = 0;
        if nc > 0 {
            step_state.bridge_kinematics(&lambda, &mut kinematics);
            for (w, k) in previous_displacement.iter_mut().zip(&kinematics) {
                *w = k[0];
            }
            loop {
                iterations += 1;
                step_state.vehicle_forces(&kinematics, &mut answer);
                for c in 0..nc {
                    residual[c] = answer[c] - lambda[c];
                }
                if iterations > 1 {
                    // Aitken: ω ← −ω r_{k−1}·(r_k − r_{k−1}) / |r_k − r_{k−1}|².
                    let (mut numerator, mut denominator) = (0.0, 0.0);
                    for c in 0..nc {
                        let change = residual[c] - previous_residual[c];
                        numerator += previous_residual[c] * change;
                        denominator += change * change;
                    }
                    if denominator > 0.0 {
                        relaxation = -relaxation * numerator / denominator;
                    }
                }
                for c in 0..nc {
                    lambda[c] += relaxation * residual[c];
                }
                previous_residual.copy_from_slice(&residual);
                step_state.bridge_kinematics(&lambda, &mut kinematics);
                let (mut change, mut scale) = (0.0f64, DISPLACEMENT_FLOOR);
                for (w, k) in previous_displacement.iter_mut().zip(&kinematics) {
                    change = change.max((k[0] - *w).abs());
                    scale = scale.max(k[0].abs());
                    *w = k[0];
                }
                let (mut force_change, mut force_scale) = (0.0f64, FORCE_FLOOR);
                for (r, f) in residual.iter().zip(&lambda) {
                    force_change = force_change.max((relaxation * r).abs());
                    force_scale = force_scale.max(f.abs());
                }
                if !(change.is_finite() && lambda.iter().all(|f| f.is_finite())) {
                    return Err(SolveError::NotConverged {
                        time: t,
                        positions: describe_positions(model, t),
                        iterations,
                        reason: "the interaction forces became non-finite".into(),
                    });
                }
                if change <= tolerance * scale && force_change <= tolerance * force_scale {
                    break;
                }
                if iterations >= max_iterations {
                    return Err(SolveError::NotConverged {
                        time: t,
                        positions: describe_positions(model, t),
                        iterations,
                        reason: format!(
                            "the contact displacements still change by {:.3e} and the forces by \
                             {:.3e} of their size (tolerance {tolerance:.1e}); raise \
                             `max_iterations`, shorten the time step, or use `method: coupled`",
                            change / scale,
                            force_change / force_scale
                        ),
                    });
                }
            }
        }
        total_iterations += iterations;
        most_iterations = most_iterations.max(iterations);
        step_state.finish_step(&nm, &mut modal, &lambda, &mut contact_forces);

        guard.check(model, &modal, &step_state.states, &lambda, t, step)?;

        observer.observe(&StepView::of(
            step,
            t,
            &modal,
            &step_state.states,
            &contact_forces,
            &contact_gaps,
            &wheel_positions,
        ));
        if step % report_every == 0 || step == model.steps {
            progress(step, model.steps);
            super::cancel::check()?;
        }
    }
    Ok(SolveStats {
        iterations: Some(IterationStats {
            mean: total_iterations as f64 / model.steps.max(1) as f64,
            max: most_iterations,
        }),
    })
}

/// Iteration counts of the `iterative` solver over a run.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IterationStats {
    /// Mean number of vehicle–bridge iterations per time step.
    pub mean: f64,
    /// Largest number in any step.
    pub max: usize,
}
