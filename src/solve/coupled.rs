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

use super::dense::lu_solve;
use super::permanent::PermanentStep;
use super::time_loop::Stepper;
use super::{SolveError, StepView};
use crate::model::Model;

/// The coupled method's state and work arrays, for [`super::time_loop::drive`].
#[derive(Debug)]
pub struct Coupled<'a> {
    state: PermanentStep<'a>,
    sens: Vec<[f64; 3]>,
    system: Vec<f64>,
    lambda: Vec<f64>,
}

impl<'a> Coupled<'a> {
    /// `model` at rest at t = 0, every work array allocated.
    ///
    /// # Errors
    ///
    /// [`PermanentStep::new`]'s: a vehicle whose free DOFs cannot be
    /// condensed.
    pub fn new(model: &'a Model) -> Result<Self, SolveError> {
        let state = PermanentStep::new(model)?;
        let nc = state.contacts.count();
        Ok(Self {
            state,
            sens: vec![[0.0f64; 3]; nc * nc],
            system: vec![0.0; nc * nc],
            lambda: vec![0.0; nc],
        })
    }
}

impl Stepper for Coupled<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.state.model)
    }

    fn advance(&mut self, _step: usize, t: f64) -> Result<(), SolveError> {
        self.state.begin(t);
        let contacts = &mut self.state.contacts;
        let nc = contacts.count();
        // (I − A)λ = b from the wheels' sensitivities and the vehicles' rows.
        contacts.contact_system(&mut self.sens, &mut self.system);
        contacts.vehicle_forces(&contacts.base, &mut self.lambda);
        if nc > 0 && !lu_solve(&mut self.system, &mut self.lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the condensed contact system is singular".into(),
            });
        }
        self.state.finish(&self.lambda);
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        (self.state.energy(), &self.lambda)
    }

    fn view(&self, _index: usize, step: usize, t: f64) -> StepView<'_> {
        self.state.view(step, t)
    }
}
