//! The bridge half of a direct Newmark/HHT step on the assembled system
//! M ü + C u̇ + K u = F (see the module doc of [`super`] for the math).

use faer::dyn_stack::MemBuffer;

use super::assembled::AssembledBridge;
use crate::bridge::eigen::sparse::{Factor, SymmetricSparse, multiply};
use crate::solve::SolveError;
use crate::solve::newmark::Newmark;

/// Nodal state, the two factors and the work vectors of the direct
/// bridge step; nothing is allocated per step.
pub struct DirectStep {
    stiffness: SymmetricSparse,
    mass: SymmetricSparse,
    /// Rayleigh coefficients (c_M 1/s, c_K s).
    damping: (f64, f64),
    /// LDLᵀ of K̂ = a₀M + (1+α)(a₁C + K).
    effective: Factor,
    /// LDLᵀ of M + (1+α)γΔt C, for the accelerations.
    inertia: Factor,
    workspace: MemBuffer,
    /// Displacements u (m, rad), velocities u̇, accelerations ü on the free DOFs.
    pub displacement: Vec<f64>,
    /// u̇, m/s (rad/s).
    pub velocity: Vec<f64>,
    /// ü, m/s² (rad/s²).
    pub acceleration: Vec<f64>,
    /// The step's predictor u* = K̂⁻¹R̂ (m), then the new u.
    pub predictor: Vec<f64>,
    /// hₐ = a₀uₙ + a₂u̇ₙ + a₃üₙ, 1/s² · m.
    pub inertia_history: Vec<f64>,
    /// h_v = a₁uₙ + a₄u̇ₙ + a₅üₙ, m/s.
    pub damping_history: Vec<f64>,
    /// The contacts' nodal load −Σ N(x_c)λ_c (N, N·m) of this step, set
    /// by the caller before [`Self::take_contact_load`].
    pub contact_load: Vec<f64>,
    /// Nodal load F_{n+1} (N, N·m) being assembled for this step.
    pub current_force: Vec<f64>,
    /// Fₙ, the previous step's nodal load.
    previous_force: Vec<f64>,
    /// Work vectors of the sparse products.
    work_mass: Vec<f64>,
    work_stiffness: Vec<f64>,
    product: Vec<f64>,
    /// ½(u̇ᵀMu̇ + uᵀKu) after the last step, J.
    energy: f64,
}

impl std::fmt::Debug for DirectStep {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DirectStep")
            .field("order", &self.order())
            .field("damping", &self.damping)
            .field("energy", &self.energy)
            .finish_non_exhaustive()
    }
}

/// c_a A + c_b B on the union of both patterns
/// ([`crate::bridge::eigen::sparse::combination`]).
fn combination(
    a: &SymmetricSparse,
    scale_a: f64,
    b: &SymmetricSparse,
    scale_b: f64,
) -> Result<SymmetricSparse, SolveError> {
    crate::bridge::eigen::sparse::combination(a, scale_a, b, scale_b).map_err(|_| {
        SolveError::Direct {
            reason: "the assembled matrices do not fit in memory".into(),
        }
    })
}

/// The factor of `matrix`, or why it has none.
fn factor(matrix: &SymmetricSparse, what: &str) -> Result<Factor, SolveError> {
    Factor::new(matrix).map_err(|e| SolveError::Direct {
        reason: format!("{what} could not be factorised ({e})"),
    })
}

impl DirectStep {
    /// The beam at rest, K̂ and M + (1+α)γΔtC factorised once. Cost: two
    /// sparse LDLᵀ factorisations, O(nnz(L)) memory each.
    ///
    /// # Errors
    ///
    /// [`SolveError::Direct`] if either matrix cannot be factorised.
    pub fn new(beam: &AssembledBridge<'_>, nm: &Newmark) -> Result<Self, SolveError> {
        let (k, m) = (beam.stiffness(), beam.mass());
        let (c_m, c_k) = beam.damping;
        let w = nm.weight();
        // K̂ = a₀M + w(a₁(c_M M + c_K K) + K).
        let effective = combination(k, w * (1.0 + nm.a1 * c_k), m, nm.a0 + w * nm.a1 * c_m)?;
        let effective = factor(&effective, "the effective stiffness K̂")?;
        // M + wγΔt C.
        let inertia = combination(k, w * nm.a7 * c_k, m, 1.0 + w * nm.a7 * c_m)?;
        let inertia = factor(&inertia, "the mass matrix M + (1+α)γΔtC")?;
        let workspace = effective.workspace().map_err(|_| SolveError::Direct {
            reason: "the solve's workspace does not fit in memory".into(),
        })?;
        let n = beam.order();
        Ok(Self {
            stiffness: k.clone(),
            mass: m.clone(),
            damping: beam.damping,
            effective,
            inertia,
            workspace,
            displacement: vec![0.0; n],
            velocity: vec![0.0; n],
            acceleration: vec![0.0; n],
            predictor: vec![0.0; n],
            inertia_history: vec![0.0; n],
            damping_history: vec![0.0; n],
            current_force: vec![0.0; n],
            contact_load: vec![0.0; n],
            previous_force: vec![0.0; n],
            work_mass: vec![0.0; n],
            work_stiffness: vec![0.0; n],
            product: vec![0.0; n],
            energy: 0.0,
        })
    }

    /// Number of free DOFs.
    pub fn order(&self) -> usize {
        self.displacement.len()
    }

    /// The factor of K̂ (for the contact flexibility columns).
    pub fn effective_factor(&self) -> &Factor {
        &self.effective
    }

    /// Clears the step's load F_{n+1} before the loads are spread into
    /// [`Self::current_force`].
    pub fn clear_force(&mut self) {
        self.current_force.fill(0.0);
    }

    /// M·`work_mass` into `product` and K·`work_stiffness` into
    /// `predictor` (the two products of every half step).
    fn mass_and_stiffness_products(&mut self) {
        multiply(&self.mass, &self.work_mass, &mut self.product);
        multiply(&self.stiffness, &self.work_stiffness, &mut self.predictor);
    }

    /// Forms the predictor u* = K̂⁻¹R̂ from the load in
    /// [`Self::current_force`], R̂ = wF_{n+1} − αFₙ + M hₐ + wC h_v +
    /// α(C u̇ₙ + K uₙ), with C = c_M M + c_K K: one product with M, one with
    /// K, one solve. Cost O(nnz(K) + nnz(M) + nnz(L)).
    pub fn predict(&mut self, nm: &Newmark) {
        let (w, alpha) = (nm.weight(), nm.alpha);
        let (c_m, c_k) = self.damping;
        for i in 0..self.order() {
            let (u, v, a) = (self.displacement[i], self.velocity[i], self.acceleration[i]);
            let (ha, hv) = (nm.inertia_history(u, v, a), nm.damping_history(u, v, a));
            self.inertia_history[i] = ha;
            self.damping_history[i] = hv;
            self.work_mass[i] = ha + c_m * (w * hv + alpha * v);
            self.work_stiffness[i] = c_k * (w * hv + alpha * v) + alpha * u;
        }
        self.mass_and_stiffness_products();
        for i in 0..self.order() {
            self.predictor[i] +=
                self.product[i] + w * self.current_force[i] - alpha * self.previous_force[i];
        }
        self.effective
            .solve_in_place(&mut self.predictor, &mut self.workspace);
    }

    /// Adds the contacts' load in [`Self::contact_load`] to the step: to
    /// F_{n+1}, and to the predictor as u_{n+1} = u* + w K̂⁻¹(−Σ N λ), one
    /// solve with K̂'s factor whatever the number of contacts
    /// (`contact_load` is left holding K̂⁻¹ of it). Cost O(n + nnz(L)).
    pub fn take_contact_load(&mut self, nm: &Newmark) {
        let w = nm.weight();
        for (f, g) in self.current_force.iter_mut().zip(&self.contact_load) {
            *f += g;
        }
        self.effective
            .solve_in_place(&mut self.contact_load, &mut self.workspace);
        for (u, du) in self.predictor.iter_mut().zip(&self.contact_load) {
            *u += w * du;
        }
    }

    /// Accepts [`Self::predictor`] as u_{n+1} with the step's whole load in
    /// [`Self::current_force`], and updates ü from the HHT equation of
    /// motion, (M + wγΔtC) ü_{n+1} = wF_{n+1} − αFₙ − wC(u̇ₙ + (1−γ)Δt üₙ)
    /// − wK u_{n+1} + α(C u̇ₙ + K uₙ) (as the modal step does, rather than
    /// a₀(u_{n+1} − uₙ) − …, whose round-off grows like ε|u|/Δt²), and u̇
    /// by Newmark. Cost two products and one solve.
    pub fn finish(&mut self, nm: &Newmark) {
        let (w, alpha) = (nm.weight(), nm.alpha);
        let (c_m, c_k) = self.damping;
        for i in 0..self.order() {
            let (u_old, v, a) = (self.displacement[i], self.velocity[i], self.acceleration[i]);
            let p = v + nm.a6 * a;
            self.work_mass[i] = c_m * (alpha * v - w * p);
            self.work_stiffness[i] =
                c_k * (alpha * v - w * p) + alpha * u_old - w * self.predictor[i];
        }
        std::mem::swap(&mut self.displacement, &mut self.predictor);
        self.mass_and_stiffness_products();
        // `predictor` now holds K·(…); the new acceleration's right side:
        for i in 0..self.order() {
            self.predictor[i] +=
                self.product[i] + w * self.current_force[i] - alpha * self.previous_force[i];
        }
        self.inertia
            .solve_in_place(&mut self.predictor, &mut self.workspace);
        for i in 0..self.order() {
            let a_new = self.predictor[i];
            self.velocity[i] = nm.velocity(self.velocity[i], self.acceleration[i], a_new);
            self.acceleration[i] = a_new;
        }
        std::mem::swap(&mut self.previous_force, &mut self.current_force);
        self.energy = self.energy_of_state();
    }

    /// The bridge's kinetic plus strain energy after the last step, J.
    pub fn energy(&self) -> f64 {
        self.energy
    }

    /// Kinetic plus strain energy ½(u̇ᵀMu̇ + uᵀKu), J. Cost two products.
    fn energy_of_state(&mut self) -> f64 {
        multiply(&self.mass, &self.velocity, &mut self.product);
        let kinetic: f64 = self
            .velocity
            .iter()
            .zip(&self.product)
            .map(|(a, b)| a * b)
            .sum();
        multiply(&self.stiffness, &self.displacement, &mut self.product);
        let strain: f64 = self
            .displacement
            .iter()
            .zip(&self.product)
            .map(|(a, b)| a * b)
            .sum();
        0.5 * (kinetic + strain)
    }
}
