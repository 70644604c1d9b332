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
    modal_damping: Vec<f64>,
    /// 1/k̂ᵢ.
    pub flexibility: Vec<f64>,
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
        let flexibility = bridge
            .circular_frequencies
            .iter()
            .zip(&modal_damping)
            .map(|(w, c)| 1.0 / (w * w + nm.a0 + nm.a1 * c))
            .collect();
        Self {
            modal_damping,
            flexibility,
            displacement: vec![0.0; modes],
            velocity: vec![0.0; modes],
            acceleration: vec![0.0; modes],
            predictor: vec![0.0; modes],
            inertia_history: vec![0.0; modes],
            damping_history: vec![0.0; modes],
            shape_work: vec![0.0; modes],
        }
    }

    /// Forms the predictor q* for a step with the given moving loads
    /// (position x in m, downward load in N; loads off the deck are ignored).
    pub fn predict(
        &mut self,
        nm: &Newmark,
        bridge: &ModalBridge,
        loads: impl Iterator<Item = (f64, f64)>,
    ) {
        for i in 0..self.predictor.len() {
            let (q, v, a) = (self.displacement[i], self.velocity[i], self.acceleration[i]);
            self.inertia_history[i] = nm.inertia_history(q, v, a);
            self.damping_history[i] = nm.damping_history(q, v, a);
            self.predictor[i] =
                self.inertia_history[i] + self.modal_damping[i] * self.damping_history[i];
        }
        for (x, load) in loads {
            if bridge.is_on(x) {
                bridge.mode_values(x, &mut self.shape_work);
                for (p, phi) in self.predictor.iter_mut().zip(&self.shape_work) {
                    *p -= load * phi;
                }
            }
        }
        for (p, f) in self.predictor.iter_mut().zip(&self.flexibility) {
            *p *= f;
        }
    }

    /// Applies a contact force `force` (N, compression) at a point whose mode
    /// values divided by k̂ are `scaled_shape`.
    #[inline]
    pub fn apply_contact(&mut self, scaled_shape: &[f64], force: f64) {
        for (p, s) in self.predictor.iter_mut().zip(scaled_shape) {
            *p -= s * force;
        }
    }

    /// Accepts the corrected predictor as q_{n+1} and updates q̇, q̈.
    pub fn finish(&mut self, nm: &Newmark) {
        for i in 0..self.predictor.len() {
            let q = self.predictor[i];
            self.displacement[i] = q;
            self.acceleration[i] = nm.a0 * q - self.inertia_history[i];
            self.velocity[i] = nm.a1 * q - self.damping_history[i];
        }
    }

    /// Sum of the state, for a cheap finiteness check.
    pub fn health(&self) -> f64 {
        self.displacement.iter().sum::<f64>() + self.velocity.iter().sum::<f64>()
    }
}
