//! What every permanent-contact method steps alike: the bridge's modal
//! state, the contacts, the ground motion and the arrays the observer
//! reads. `coupled` and `iterative` differ only in how they find the
//! step's contact forces λ between [`PermanentStep::begin`] and
//! [`PermanentStep::finish`].

use super::PermanentContacts;
use crate::model::Model;
use crate::solve::guard::Guard;
use crate::solve::modal::ModalStep;
use crate::solve::newmark::Newmark;
use crate::solve::{GroundStep, SolveError, StepView};

/// A permanent-contact scene's state between steps, every array allocated
/// once (nothing is allocated per step).
#[derive(Debug)]
pub struct PermanentStep<'a> {
    /// The scene.
    pub model: &'a Model,
    /// The integrator's constants.
    pub nm: Newmark,
    /// The bridge's modal coordinates and their predictors.
    pub modal: ModalStep,
    /// The contacts: wheel kinematics, vehicles' condensed rows.
    pub contacts: PermanentContacts,
    /// The ground motion's step.
    pub ground: GroundStep,
    /// Each wheel's contact force after the step, N (compression positive).
    pub contact_forces: Vec<f64>,
    /// Each wheel's gap, m: 0 under permanent contact.
    pub contact_gaps: Vec<f64>,
    /// Each wheel's position along the bridge, m.
    pub wheel_positions: Vec<f64>,
}

impl<'a> PermanentStep<'a> {
    /// `model` at rest at t = 0 under its static wheel loads.
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
        let nw = model.wheels.len();
        let mut wheel_positions = vec![0.0; nw];
        model.wheel_positions(0.0, &mut wheel_positions);
        Ok(Self {
            model,
            ground: GroundStep::new(model, &nm),
            nm,
            modal,
            contacts,
            contact_forces: model.static_wheel_loads.clone(),
            contact_gaps: vec![0.0; nw],
            wheel_positions,
        })
    }

    /// Opens the step ending at `t` (s): the wheels' positions, the ground
    /// motion's load, and the predictors of bridge and wheels from the
    /// previous step's contact forces.
    pub fn begin(&mut self, t: f64) {
        let model = self.model;
        model.wheel_positions(t, &mut self.wheel_positions);
        self.contacts.gravity_ratio = self.ground.step_of(model, &mut self.modal, t);
        self.contacts.lateral_ground = self.ground.lateral_load;
        self.contacts.begin_step(
            model,
            &self.nm,
            &mut self.modal,
            t,
            &self.wheel_positions,
            &self.contact_forces,
        );
    }

    /// Closes the step with the contact forces `lambda` (N, one per
    /// contact): bridge and vehicles corrected, the wheels' forces kept.
    pub fn finish(&mut self, lambda: &[f64]) {
        self.contacts
            .finish_step(&self.nm, &mut self.modal, lambda, &mut self.contact_forces);
    }

    /// The mechanical energy the divergence guard checks, J.
    pub fn energy(&self) -> f64 {
        Guard::energy(self.model, &self.modal, &self.contacts.states)
    }

    /// The state after step `step` at time `t` (s), for the observer.
    pub fn view(&self, step: usize, t: f64) -> StepView<'_> {
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
