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

use super::permanent::PermanentStep;
use super::time_loop::Stepper;
use super::{SolveError, SolveStats, StepView, describe_positions};
use crate::model::Model;

/// Smallest deflection scale of the convergence test, m: below a nanometre
/// the relative test would chase round-off.
pub const DISPLACEMENT_FLOOR: f64 = 1e-9;
/// Smallest force scale of the convergence test, N.
pub const FORCE_FLOOR: f64 = 1.0;

/// The iterative method's state and work arrays, for
/// [`super::time_loop::drive`].
#[derive(Debug)]
pub struct Iterative<'a> {
    state: PermanentStep<'a>,
    // Work arrays: forces, their update, residuals, wheel kinematics.
    lambda: Vec<f64>,
    answer: Vec<f64>,
    residual: Vec<f64>,
    previous_residual: Vec<f64>,
    kinematics: Vec<[f64; 3]>,
    previous_displacement: Vec<f64>,
    total_iterations: usize,
    most_iterations: usize,
}

impl<'a> Iterative<'a> {
    /// `model` at rest at t = 0, every work array allocated; the first
    /// step's iteration starts from the static wheel loads.
    ///
    /// # Errors
    ///
    /// [`PermanentStep::new`]'s.
    pub fn new(model: &'a Model) -> Result<Self, SolveError> {
        let state = PermanentStep::new(model)?;
        let nc = state.contacts.count();
        let mut lambda = vec![0.0; nc];
        for (c, contact) in state.contacts.contacts.iter().enumerate() {
            lambda[c] = state.contact_forces[contact.wheel];
        }
        Ok(Self {
            state,
            lambda,
            answer: vec![0.0; nc],
            residual: vec![0.0; nc],
            previous_residual: vec![0.0; nc],
            kinematics: vec![[0.0f64; 3]; nc],
            previous_displacement: vec![0.0; nc],
            total_iterations: 0,
            most_iterations: 0,
        })
    }

    /// The vehicle–bridge iteration of the step ending at `t` (s) (the
    /// module's steps 1–4), from the contact forces in `lambda`; returns
    /// the iterations it took.
    fn iterate(&mut self, t: f64) -> Result<usize, SolveError> {
        let model = self.state.model;
        let (tolerance, max_iterations) =
            (model.iteration.tolerance, model.iteration.max_iterations);
        let Self {
            state:
                PermanentStep {
                    contacts: step_state,
                    ..
                },
            lambda,
            answer,
            residual,
            previous_residual,
            kinematics,
            previous_displacement,
            ..
        } = self;
        let nc = step_state.count();
        let mut relaxation = 1.0;
        let mut iterations = 0;
        step_state.bridge_kinematics(lambda, kinematics);
        for (w, k) in previous_displacement.iter_mut().zip(kinematics.iter()) {
            *w = k[0];
        }
        loop {
            iterations += 1;
            step_state.vehicle_forces(kinematics, answer);
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
            previous_residual.copy_from_slice(residual);
            step_state.bridge_kinematics(lambda, kinematics);
            let (mut change, mut scale) = (0.0f64, DISPLACEMENT_FLOOR);
            for (w, k) in previous_displacement.iter_mut().zip(kinematics.iter()) {
                change = change.max((k[0] - *w).abs());
                scale = scale.max(k[0].abs());
                *w = k[0];
            }
            let (mut force_change, mut force_scale) = (0.0f64, FORCE_FLOOR);
            for (r, f) in residual.iter().zip(lambda.iter()) {
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
                return Ok(iterations);
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
}

impl Stepper for Iterative<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.state.model)
    }

    fn advance(&mut self, _step: usize, t: f64) -> Result<(), SolveError> {
        self.state.begin(t);
        let iterations = if self.state.contacts.count() > 0 {
            self.iterate(t)?
        } else {
            0
        };
        self.total_iterations += iterations;
        self.most_iterations = self.most_iterations.max(iterations);
        self.state.finish(&self.lambda);
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        (self.state.energy(), &self.lambda)
    }

    fn view(&self, _index: usize, step: usize, t: f64) -> StepView<'_> {
        self.state.view(step, t)
    }

    fn stats(&self) -> SolveStats {
        SolveStats {
            iterations: Some(IterationStats {
                mean: self.total_iterations as f64 / self.state.model.steps.max(1) as f64,
                max: self.most_iterations,
            }),
        }
    }
}

/// Iteration counts of the `iterative` solver over a run.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IterationStats {
    /// Mean number of vehicle–bridge iterations per time step.
    pub mean: f64,
    /// Largest number in any step.
    pub max: usize,
}
