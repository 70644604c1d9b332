//! The one time loop every solver method runs through.
//!
//! A method is a [`Stepper`]: it owns the state of its scene (or of a
//! batch of alike scenes, the lockstep lanes) and advances it by one
//! Newmark/HHT step at a time. [`drive`] owns everything around the step
//! that is the same for every method — the step times tₙ = nΔt, the
//! divergence guard ([`super::guard`]), the observer calls at t = 0 and
//! after every step, the progress reports and the cancellation check
//! ([`super::cancel`]) — so that a new method (e.g. a sparse direct FE
//! stepper) writes only its step.

use super::guard::Guard;
use super::{Observer, Progress, SolveError, SolveStats, StepView};
use crate::model::Model;

/// Progress is reported (and cancellation checked) this many times over a
/// run, and after the last step.
pub const REPORTS_PER_RUN: usize = 200;

/// One solver method's step: the state of one scene, or of a batch of
/// scenes alike but for their surface profiles (the lockstep lanes), and
/// how to advance it from tₙ₋₁ to tₙ.
///
/// **The math.** Each step solves the vehicle–bridge system at tₙ = nΔt
/// (s): the bridge's modal coordinates q (√kg·m) and the vehicles' DOFs u
/// (m, rad) by Newmark/HHT, closed by the contact model through the
/// contact forces λ (N, compression positive). What closes it — a dense
/// condensed solve, a fixed-point iteration, an LCP, an asymptotic
/// expansion — is the method's; the loop only sees the state afterwards.
///
/// **Cost.** [`Self::advance`] is the hot path, called `steps` times: it
/// must allocate nothing (preallocate every work array in the
/// constructor). Its cost per step is the method's and documented there
/// (e.g. `coupled`: O(modes·wheels²) + O(Σ dofᵥ²) + O(wheels³)). The loop
/// adds the guard's O(modes + Σ dofᵥ²) per lane and the observers.
///
/// **Views.** A stepper shows [`Self::views`] views per step, view `i` to
/// observer `i` of [`drive`]: first one per lane (each guarded), then any
/// by-products of the same scene (EMBS's zero order alone), not guarded.
pub trait Stepper {
    /// What a step's failure is: a [`SolveError`], or with the lane it
    /// happened in for a batch.
    type Error: From<SolveError>;

    /// The scenes stepped, one per lane (all with the same step count and
    /// time step); their guards are built from them.
    fn models(&self) -> &[&Model];

    /// Views shown per step (see the trait's doc): the lanes by default.
    fn views(&self) -> usize {
        self.models().len()
    }

    /// Advances the state from step `step − 1` to step `step`, at time
    /// `t` = step·Δt (s).
    ///
    /// # Errors
    ///
    /// The method's own failures: a singular contact system, an LCP
    /// without solution, a vehicle–bridge iteration that did not converge.
    /// Divergence is the guard's, checked by [`drive`] after this returns.
    fn advance(&mut self, step: usize, t: f64) -> Result<(), Self::Error>;

    /// What the guard checks of `lane` after a step: the mechanical energy
    /// of its state (J, [`Guard::energy`]) and its contact forces (N).
    fn guarded(&self, lane: usize) -> (f64, &[f64]);

    /// View `index` of the state after step `step` (0: the initial state)
    /// at time `t` (s).
    fn view(&self, index: usize, step: usize, t: f64) -> StepView<'_>;

    /// The failure `error` (the guard's, or the cancellation) of `lane`.
    fn lane_error(lane: usize, error: SolveError) -> Self::Error {
        let _ = lane;
        error.into()
    }

    /// What the method reports about its own work, once the run is over.
    fn stats(&self) -> SolveStats {
        SolveStats::default()
    }
}

/// Runs `stepper` from t = 0 to its models' last step: shows view `i` to
/// `observers[i]` at t = 0 and after every step, checks every lane's
/// state with the divergence guard after each step, and every
/// `steps / `[`REPORTS_PER_RUN`] steps (and after the last) calls
/// `progress(step, steps)` and checks for cancellation.
///
/// Inlined so that the lockstep batch's instruction-set variants
/// ([`super::lockstep`]) compile the whole loop, step kernels included,
/// for their processor. Allocates only the guards, before the loop.
///
/// # Errors
///
/// The stepper's failure, the guard's [`SolveError::Diverged`] (lowest
/// lane first) or [`SolveError::Cancelled`]; the run stops at the first.
///
/// # Panics
///
/// If `observers` does not hold one observer per view.
#[inline(always)]
pub fn drive<S: Stepper>(
    stepper: &mut S,
    observers: &mut [&mut dyn Observer],
    progress: Progress<'_>,
) -> Result<(), S::Error> {
    assert_eq!(
        observers.len(),
        stepper.views(),
        "time_loop::drive: one observer per view"
    );
    let guards: Vec<Guard> = stepper.models().iter().map(|m| Guard::new(m)).collect();
    let (steps, time_step) = {
        let first = stepper.models()[0];
        (first.steps, first.time_step)
    };
    for (i, observer) in observers.iter_mut().enumerate() {
        observer.observe(&stepper.view(i, 0, 0.0));
    }
    let report_every = (steps / REPORTS_PER_RUN).max(1);
    for step in 1..=steps {
        let t = step as f64 * time_step;
        stepper.advance(step, t)?;
        for (lane, guard) in guards.iter().enumerate() {
            let (energy, forces) = stepper.guarded(lane);
            guard
                .check_energy(stepper.models()[lane], energy, forces, t, step)
                .map_err(|e| S::lane_error(lane, e))?;
        }
        for (i, observer) in observers.iter_mut().enumerate() {
            observer.observe(&stepper.view(i, step, t));
        }
        if step % report_every == 0 || step == steps {
            progress(step, steps);
            super::cancel::check().map_err(|e| S::lane_error(0, e))?;
        }
    }
    Ok(())
}
