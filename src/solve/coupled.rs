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
use super::time_loop::Stepper;
use super::{SolveError, StepView};
use crate::model::Model;

/// The coupled method's state and work arrays, for [`super::time_loop::drive`].
#[derive(Debug)]
pub struct Coupled<'a> {
    model: &'a Model,
    nm: Newmark,
    modal: ModalStep,
    contacts: PermanentContacts,
    ground: GroundStep,
    sens: Vec<[f64; 3]>,
    system: Vec<f64>,
    lambda: Vec<f64>,
    contact_forces: Vec<f64>,
    contact_gaps: Vec<f64>,
    wheel_positions: Vec<f64>,
}

impl<'a> Coupled<'a> {
    /// `model` at rest at t = 0, every work array allocated.
    ///
    /// # Errors
    ///
    /// [`PermanentContacts::new`]'s: a vehicle whose free DOFs cannot be
    /// condensed.
    pub fn new(model: &'a Model) -> Result<Self, SolveError> {
        let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
        let modal = ModalStep::new(&model.bridge, &nm)
            .with_ground(model.ground_participation())
            .with_lateral_ground(model.lateral_ground_participation());
        let contacts = PermanentContacts::new(model, &nm)?;
        let nc = contacts.count();
        let nw = model.wheels.len();
        let mut wheel_positions = vec![0.0; nw];
        model.wheel_positions(0.0, &mut wheel_positions);
        Ok(Self {
            model,
            ground: GroundStep::new(model, &nm),
            nm,
            modal,
            contacts,
            sens: vec![[0.0f64; 3]; nc * nc],
            system: vec![0.0; nc * nc],
            lambda: vec![0.0; nc],
            contact_forces: model.static_wheel_loads.clone(),
            contact_gaps: vec![0.0; nw],
            wheel_positions,
        })
    }
}

impl Stepper for Coupled<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.model)
    }

    fn advance(&mut self, _step: usize, t: f64) -> Result<(), SolveError> {
        let (model, nm) = (self.model, &self.nm);
        let step_state = &mut self.contacts;
        let nc = step_state.count();
        model.wheel_positions(t, &mut self.wheel_positions);
        step_state.gravity_ratio = self.ground.step_of(model, &mut self.modal, t);
        step_state.lateral_ground = self.ground.lateral_load;
        step_state.begin_step(
            model,
            nm,
            &mut self.modal,
            t,
            &self.wheel_positions,
            &self.contact_forces,
        );

        // (I − A)λ = b from the wheels' sensitivities and the vehicles' rows.
        step_state.contact_system(&mut self.sens, &mut self.system);
        step_state.vehicle_forces(&step_state.base, &mut self.lambda);
        if nc > 0 && !lu_solve(&mut self.system, &mut self.lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the condensed contact system is singular".into(),
            });
        }
        step_state.finish_step(nm, &mut self.modal, &self.lambda, &mut self.contact_forces);
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        let energy = Guard::energy(self.model, &self.modal, &self.contacts.states);
        (energy, &self.lambda)
    }

    fn view(&self, _index: usize, step: usize, t: f64) -> StepView<'_> {
        StepView::of(
            step,
            t,
            &self.modal,
            &self.contacts.states,
            &self.contact_forces,
            &self.contact_gaps,
            &self.wheel_positions,
        )
    }
}
