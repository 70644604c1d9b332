//! Coupled vehicle–bridge integration with permanent wheel contact.
//!
//! The wheel DOFs are eliminated by the contact kinematics
//! ([`super::permanent`]). Newmark (average acceleration by default)
//! advances the modal coordinates q and the vehicles' free DOFs together.
//! Per step the unknowns are condensed onto the contact forces λ
//! (compression positive): every wheel's kinematics is affine in λ, and each
//! vehicle's wheel rows ([`super::partition`]) then close the system
//! (I − A)λ = b, one small dense solve per step. Cost per step:
//! O(modes·wheels²) + O(Σ dofᵥ²) + O(wheels³); nothing is allocated in the
//! loop.

use super::GroundStep;
use super::dense::lu_solve;
use super::guard::Guard;
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::permanent::PermanentContacts;
use super::{Observer, Progress, SolveError, StepView};
use crate::model::Model;

/// Integrates the model with permanent contact, calling `observer` at t = 0
/// and after every step.
pub fn run(
    model: &Model,
    observer: &mut dyn Observer,
    progress: Progress<'_>,
) -> Result<(), SolveError> {
    let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
    let bridge = &model.bridge;
    let mut modal = ModalStep::new(bridge, &nm)
        .with_ground(model.ground_participation())
        .with_lateral_ground(model.lateral_ground_participation());
    let mut step_state = PermanentContacts::new(model, &nm)?;
    let nc = step_state.count();

    // Work arrays.
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
        &step_state.states,
        &contact_forces,
        &contact_gaps,
        &wheel_positions,
    ));

    let guard = Guard::new(model);
    let mut ground = GroundStep::new(model, &nm);
    let report_every = (model.steps / 200).max(1);
    for step in 1..=model.steps {
        let t = step as f64 * model.time_step;
        model.wheel_positions(t, &mut wheel_positions);
        step_state.gravity_ratio = ground.step_of(model, &mut modal, t);
        step_state.lateral_ground = ground.lateral_load;
        step_state.begin_step(model, &nm, &mut modal, t, &wheel_positions, &contact_forces);

        // (I − A)λ = b from the wheels' sensitivities and the vehicles' rows.
        step_state.contact_system(&mut sens, &mut system);
        step_state.vehicle_forces(&step_state.base, &mut lambda);
        if nc > 0 && !lu_solve(&mut system, &mut lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the condensed contact system is singular".into(),
            });
        }
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
    Ok(())
}
