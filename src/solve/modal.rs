//! The bridge half of every Newmark step, shared by the solvers.
//!
//! Modal equations with unit modal masses, q̈ᵢ + 2ζᵢωᵢq̇ᵢ + ωᵢ²qᵢ = Fᵢ, are
//! uncoupled, so the effective stiffness is diagonal and constant:
//! k̂ᵢ = ωᵢ² + a₀ + 2a₁ζᵢωᵢ. A step is: predictor q* = (hₐ + 2ζω h_v + F)/k̂
//! with the moving loads in F, then the contact forces λ (compression
//! positive, pushing the deck down) subtract D φ_c λ_c, D = diag(1/k̂), and
//! Newmark gives q̈ = a₀q − hₐ, q̇ = a₁q − h_v. Cost O(modes) per step plus
//! O(modes) per load or contact; no allocation.

use super::newmark::Newmark;
use crate::bridge::ModalBridge;

/// Modal state and work arrays.
#[derive(Debug, Clone)]
pub struct ModalStep {
    /// 2ζᵢωᵢ, 1/s.
    pub(crate) modal_damping: Vec<f64>,
    /// ωᵢ², 1/s².
    pub(crate) stiffness: Vec<f64>,
    /// (1+α)/k̂ᵢ: modal displacement per unit modal contact force.
    pub contact_flexibility: Vec<f64>,
    /// 1/k̂ᵢ.
    pub(crate) flexibility: Vec<f64>,
    /// Modal force of the previous step (loads and contacts), Fₙ.
    previous_force: Vec<f64>,
    /// Modal force being assembled for this step, F_{n+1}.
    current_force: Vec<f64>,
    /// Modal displacements q.
    pub displacement: Vec<f64>,
    /// Modal velocities q̇.
    pub velocity: Vec<f64>,
    /// Modal accelerations q̈.
    pub acceleration: Vec<f64>,
    /// Predictor q*, corrected in place into the new q.
    pub predictor: Vec<f64>,
    /// hₐ = a₀q + a₂q̇ + a₃q̈ at tₙ.
    pub inertia_history: Vec<f64>,
    /// h_v = a₁q + a₄q̇ + a₅q̈ at tₙ.
    pub damping_history: Vec<f64>,
    shape_work: Vec<f64>,
    /// Participation factors Γᵢ of a vertical support motion, √kg (empty
    /// without ground motion; [`crate::ground`]).
    ground_participation: Vec<f64>,
    /// Vertical ground acceleration at the end of the step being formed,
    /// m/s² (set by the solver before [`Self::predict`]).
    pub ground_acceleration: f64,
    /// Participation factors of a lateral support motion, √kg (empty
    /// without a lateral record).
    lateral_participation: Vec<f64>,
    /// Lateral ground acceleration at the end of the step being formed, m/s².
    pub lateral_ground_acceleration: f64,
}

impl ModalStep {
    /// A bridge at rest.
    pub fn new(bridge: &ModalBridge, nm: &Newmark) -> Self {
        let modes = bridge.mode_count();
        let modal_damping: Vec<f64> = bridge
            .circular_frequencies
            .iter()
            .zip(&bridge.damping_ratios)
            .map(|(w, z)| 2.0 * z * w)
            .collect();
        let stiffness: Vec<f64> = bridge.circular_frequencies.iter().map(|w| w * w).collect();
        let flexibility: Vec<f64> = stiffness
            .iter()
            .zip(&modal_damping)
            .map(|(k, c)| 1.0 / (nm.a0 + nm.weight() * (nm.a1 * c + k)))
            .collect();
        let contact_flexibility = flexibility.iter().map(|f| nm.weight() * f).collect();
        Self {
            modal_damping,
            stiffness,
            contact_flexibility,
            flexibility,
            previous_force: vec![0.0; modes],
            current_force: vec![0.0; modes],
            displacement: vec![0.0; modes],
            velocity: vec![0.0; modes],
            acceleration: vec![0.0; modes],
            predictor: vec![0.0; modes],
            inertia_history: vec![0.0; modes],
            damping_history: vec![0.0; modes],
            shape_work: vec![0.0; modes],
            ground_participation: Vec::new(),
            ground_acceleration: 0.0,
            lateral_participation: Vec::new(),
            lateral_ground_acceleration: 0.0,
        }
    }

    /// The same step with the modal forces −Γᵢ üg of a vertical support
    /// motion added to every step's loads (`participation` empty: none).
    pub fn with_ground(mut self, participation: &[f64]) -> Self {
        self.ground_participation = participation.to_vec();
        self
    }

    /// The same step with the modal forces −Γᵢ üg,y of a lateral support
    /// motion added (`participation` empty: none).
    pub fn with_lateral_ground(mut self, participation: &[f64]) -> Self {
        self.lateral_participation = participation.to_vec();
        self
    }

    /// Forms the predictor q* for a step with the given moving loads
    /// (position x along and y across the deck in m, downward load in N;
    /// loads off the deck are ignored).
    pub fn predict(
        &mut self,
        nm: &Newmark,
        bridge: &ModalBridge,
        loads: impl Iterator<Item = (f64, f64, f64)>,
    ) {
        self.current_force.fill(0.0);
        for (x, y, load) in loads {
            if bridge.is_on(x) {
                bridge.contact_mode_values(x, y, &mut self.shape_work);
                for (f, phi) in self.current_force.iter_mut().zip(&self.shape_work) {
                    *f -= load * phi;
                }
            }
        }
        // Uniform support motion: the deck's inertia −M δ üg in modal form.
        for (f, gamma) in self
            .current_force
            .iter_mut()
            .zip(&self.ground_participation)
        {
            *f -= gamma * self.ground_acceleration;
        }
        for (f, gamma) in self
            .current_force
            .iter_mut()
            .zip(&self.lateral_participation)
        {
            *f -= gamma * self.lateral_ground_acceleration;
        }
        let (w, alpha) = (nm.weight(), nm.alpha);
        for i in 0..self.predictor.len() {
            let (q, v, a) = (self.displacement[i], self.velocity[i], self.acceleration[i]);
            let c = self.modal_damping[i];
            self.inertia_history[i] = nm.inertia_history(q, v, a);
            self.damping_history[i] = nm.damping_history(q, v, a);
            self.predictor[i] = (w * self.current_force[i] - alpha * self.previous_force[i]
                + self.inertia_history[i]
                + w * c * self.damping_history[i]
                + alpha * (c * v + self.stiffness[i] * q))
                * self.flexibility[i];
        }
    }

    /// Applies a contact force `force` (N, compression) at a point with mode
    /// values `shape`.
    #[inline]
    pub fn apply_contact(&mut self, shape: &[f64], force: f64) {
        for i in 0..self.predictor.len() {
            self.predictor[i] -= self.contact_flexibility[i] * shape[i] * force;
            self.current_force[i] -= shape[i] * force;
        }
    }

    /// Removes a contact force applied this step from the force carried into
    /// the next step's HHT term −αFₙ (used for landing impulses). Call after
    /// [`Self::finish`].
    pub fn forget_contact(&mut self, shape: &[f64], force: f64) {
        for (f, s) in self.previous_force.iter_mut().zip(shape) {
            *f += s * force;
        }
    }

    /// Accepts the corrected predictor as q_{n+1} and updates q̇, q̈.
    ///
    /// q̈ is recovered from the HHT equation of motion itself,
    /// (1 + wγΔt c) q̈_{n+1} = wF_{n+1} − αFₙ − w c (q̇ₙ + (1−γ)Δt q̈ₙ)
    /// − w k q_{n+1} + α(c q̇ₙ + k qₙ) (w = 1+α, c = 2ζω, k = ω²), and q̇
    /// from Newmark's velocity update, instead of from a₀(q_{n+1} − qₙ) − …:
    /// that difference cancels |q| down to |q̈|Δt², so its round-off grows
    /// like ε|q|/Δt² and swamps accelerations at small steps. Both forms are
    /// the same scheme in exact arithmetic.
    pub fn finish(&mut self, nm: &Newmark) {
        let (w, alpha) = (nm.weight(), nm.alpha);
        for i in 0..self.predictor.len() {
            let q = self.predictor[i];
            let (q_old, v_old, a_old) =
                (self.displacement[i], self.velocity[i], self.acceleration[i]);
            let (c, k) = (self.modal_damping[i], self.stiffness[i]);
            let a_new = (w * self.current_force[i]
                - alpha * self.previous_force[i]
                - w * c * (v_old + nm.a6 * a_old)
                - w * k * q
                + alpha * (c * v_old + k * q_old))
                / (1.0 + w * nm.a7 * c);
            self.displacement[i] = q;
            self.acceleration[i] = a_new;
            self.velocity[i] = nm.velocity(v_old, a_old, a_new);
        }
        std::mem::swap(&mut self.previous_force, &mut self.current_force);
    }

    /// Modal energy ½Σ(q̇² + ω²q²), J (unit modal masses).
    pub fn energy(&self) -> f64 {
        Self::energy_of(&self.velocity, &self.displacement, &self.stiffness)
    }

    /// Modal energy ½Σ(q̇ᵢ² + ωᵢ²qᵢ²), J, of velocities `velocity`,
    /// displacements `displacement` and squared circular frequencies
    /// `stiffness` (unit modal masses).
    pub fn energy_of(velocity: &[f64], displacement: &[f64], stiffness: &[f64]) -> f64 {
        0.5 * velocity
            .iter()
            .zip(displacement)
            .zip(stiffness)
            .map(|((v, q), k)| v * v + k * q * q)
            .sum::<f64>()
    }

    /// Sum of the state, for a cheap finiteness check.
    pub fn health(&self) -> f64 {
        self.displacement.iter().sum::<f64>() + self.velocity.iter().sum::<f64>()
    }
}
