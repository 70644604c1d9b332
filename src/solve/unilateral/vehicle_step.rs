//! The vehicles' half of an LCP step ([`super::run`]): each vehicle is
//! advanced by Newmark/HHT as a subsystem loaded by its contact forces,
//! u = u* + Hλ, the predictor u* found before the contact problem and the
//! end-of-step state recovered after it.

use nalgebra::{DMatrix, DVector};

use super::{block_gemv, block_inverse};
use crate::solve::VehicleState;
use crate::solve::newmark::Newmark;
use crate::vehicle::VehicleModel;

#[derive(Debug, Clone)]
pub(super) struct VehicleStep {
    pub(super) effective_flexibility: DMatrix<f64>,
    pub(super) contact_response: DMatrix<f64>,
    pub(super) effective_load: DVector<f64>,
    pub(super) inertia_history: DVector<f64>,
    pub(super) damping_history: DVector<f64>,
    pub(super) predictor: DVector<f64>,
    /// (M + wγΔt C)⁻¹ where it exists (no massless undamped DOF): the
    /// accelerations then come from the equations of motion (see the step's
    /// end), else from Newmark's displacement difference.
    pub(super) recovery: Option<DMatrix<f64>>,
    /// External force of the step, f_g + wEλ_{n+1} − αEλₙ, N; then the
    /// recovery load.
    pub(super) recovery_load: DVector<f64>,
    /// Previous state, for the α terms of the recovery.
    pub(super) previous_velocity: DVector<f64>,
    pub(super) previous_acceleration: DVector<f64>,
    pub(super) previous_displacement: DVector<f64>,
    /// u̇ₙ + (1−γ)Δt üₙ, m/s, and the recovered ü_{n+1}, m/s².
    pub(super) predicted_velocity: DVector<f64>,
    pub(super) recovered_acceleration: DVector<f64>,
}

impl VehicleStep {
    /// The step of `vehicle` with its effective flexibility K̂⁻¹ and contact
    /// response H (see [`super::vehicle_step_matrices`]).
    pub(super) fn new(
        vehicle: &VehicleModel,
        nm: &Newmark,
        effective_flexibility: DMatrix<f64>,
        contact_response: DMatrix<f64>,
    ) -> Self {
        let n = vehicle.dofs();
        Self {
            effective_flexibility,
            contact_response,
            effective_load: DVector::zeros(n),
            inertia_history: DVector::zeros(n),
            damping_history: DVector::zeros(n),
            predictor: DVector::zeros(n),
            recovery: block_inverse(
                &(&vehicle.mass + &vehicle.damping * (nm.weight() * nm.a7)),
                &vehicle.blocks,
            ),
            recovery_load: DVector::zeros(n),
            previous_velocity: DVector::zeros(n),
            previous_acceleration: DVector::zeros(n),
            previous_displacement: DVector::zeros(n),
            predicted_velocity: DVector::zeros(n),
            recovered_acceleration: DVector::zeros(n),
        }
    }

    /// The effective load without the contact forces,
    /// R̂ = f_g + M hₐ + (1+α)C h_v + α(C u̇ₙ + K uₙ), from `state` at the
    /// step's start; `gravity_ratio` and `lateral_load` are the ground
    /// motion's (see `GroundStep`). The caller adds −αEλₙ.
    pub(super) fn load(
        &mut self,
        vehicle: &VehicleModel,
        state: &VehicleState,
        nm: &Newmark,
        gravity_ratio: f64,
        lateral_load: f64,
    ) {
        for k in 0..vehicle.dofs() {
            let (u, v, a) = (
                state.displacement[k],
                state.velocity[k],
                state.acceleration[k],
            );
            self.inertia_history[k] = nm.inertia_history(u, v, a);
            self.damping_history[k] = nm.damping_history(u, v, a);
        }
        let blocks = &vehicle.blocks;
        self.effective_load.copy_from(&vehicle.gravity_load);
        if gravity_ratio != 0.0 {
            self.effective_load
                .axpy(gravity_ratio, &vehicle.gravity_load, 1.0);
        }
        if lateral_load != 0.0 && !vehicle.lateral_ground_load.is_empty() {
            self.effective_load
                .axpy(lateral_load, &vehicle.lateral_ground_load, 1.0);
        }
        block_gemv(
            &mut self.effective_load,
            1.0,
            &vehicle.mass,
            &self.inertia_history,
            blocks,
        );
        block_gemv(
            &mut self.effective_load,
            nm.weight(),
            &vehicle.damping,
            &self.damping_history,
            blocks,
        );
        if nm.alpha != 0.0 {
            block_gemv(
                &mut self.effective_load,
                nm.alpha,
                &vehicle.damping,
                &state.velocity,
                blocks,
            );
            block_gemv(
                &mut self.effective_load,
                nm.alpha,
                &vehicle.stiffness,
                &state.displacement,
                blocks,
            );
        }
    }

    /// The predictor u* = K̂⁻¹R̂.
    pub(super) fn predict(&mut self, vehicle: &VehicleModel) {
        self.predictor.fill(0.0);
        block_gemv(
            &mut self.predictor,
            1.0,
            &self.effective_flexibility,
            &self.effective_load,
            &vehicle.blocks,
        );
    }

    /// The end-of-step state of `vehicle` into `state`, once the predictor
    /// holds u_{n+1} and `recovery_load` the step's contact forces
    /// wEλ_{n+1} − αEλₙ.
    pub(super) fn finish(
        &mut self,
        vehicle: &VehicleModel,
        state: &mut VehicleState,
        nm: &Newmark,
        gravity_ratio: f64,
        lateral_load: f64,
    ) {
        let Some(recovery) = &self.recovery else {
            for k in 0..state.displacement.len() {
                let u_new = self.predictor[k];
                let a_new = nm.a0 * u_new - self.inertia_history[k];
                state.velocity[k] = nm.a1 * u_new - self.damping_history[k];
                state.acceleration[k] = a_new;
                state.displacement[k] = u_new;
            }
            return;
        };
        // (M + wγΔt C) ü_{n+1} = f_g + wEλ_{n+1} − αEλₙ − w[C(u̇ₙ + (1−γ)Δt üₙ)
        // + K u_{n+1}] + α(C u̇ₙ + K uₙ): the HHT equations of motion, free
        // of the ε|u|/Δt² round-off of a₀(u_{n+1} − uₙ) − … (u includes
        // the static sag). The same scheme in exact arithmetic.
        let w = nm.weight();
        self.previous_velocity.copy_from(&state.velocity);
        self.previous_acceleration.copy_from(&state.acceleration);
        self.previous_displacement.copy_from(&state.displacement);
        let blocks = &vehicle.blocks;
        self.recovery_load += &vehicle.gravity_load;
        if gravity_ratio != 0.0 {
            self.recovery_load
                .axpy(gravity_ratio, &vehicle.gravity_load, 1.0);
        }
        if lateral_load != 0.0 && !vehicle.lateral_ground_load.is_empty() {
            self.recovery_load
                .axpy(lateral_load, &vehicle.lateral_ground_load, 1.0);
        }
        block_gemv(
            &mut self.recovery_load,
            -w,
            &vehicle.stiffness,
            &self.predictor,
            blocks,
        );
        self.predicted_velocity.copy_from(&self.previous_velocity);
        self.predicted_velocity
            .axpy(nm.a6, &self.previous_acceleration, 1.0);
        block_gemv(
            &mut self.recovery_load,
            -w,
            &vehicle.damping,
            &self.predicted_velocity,
            blocks,
        );
        if nm.alpha != 0.0 {
            block_gemv(
                &mut self.recovery_load,
                nm.alpha,
                &vehicle.damping,
                &self.previous_velocity,
                blocks,
            );
            block_gemv(
                &mut self.recovery_load,
                nm.alpha,
                &vehicle.stiffness,
                &self.previous_displacement,
                blocks,
            );
        }
        self.recovered_acceleration.fill(0.0);
        block_gemv(
            &mut self.recovered_acceleration,
            1.0,
            recovery,
            &self.recovery_load,
            blocks,
        );
        for k in 0..state.displacement.len() {
            let a_new = self.recovered_acceleration[k];
            state.velocity[k] = nm.velocity(
                self.previous_velocity[k],
                self.previous_acceleration[k],
                a_new,
            );
            state.acceleration[k] = a_new;
            state.displacement[k] = self.predictor[k];
        }
    }
}
