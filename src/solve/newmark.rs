//! Newmark-β time integration constants (Newmark 1959; Bathe, Finite Element
//! Procedures, Table 9.3) with the Hilber–Hughes–Taylor α modification
//! (Hilber, Hughes & Taylor 1977; Hughes, The Finite Element Method, §9.3.3).
//!
//! HHT-α writes the equations of motion at t_{n+1+α} = t_{n+1} + αΔt,
//! α ∈ [−1/3, 0] (α = 0 is plain Newmark):
//! M ü_{n+1} + (1+α)(C u̇_{n+1} + K u_{n+1}) − α(C u̇ₙ + K uₙ) = (1+α)F_{n+1} − αFₙ,
//! with the Newmark relations ü_{n+1} = a₀u_{n+1} − hₐ, u̇_{n+1} = a₁u_{n+1} − h_v,
//! hₐ = a₀uₙ + a₂u̇ₙ + a₃üₙ, h_v = a₁uₙ + a₄u̇ₙ + a₅üₙ. Hence
//! K̂ = a₀M + (1+α)(a₁C + K) and
//! R̂ = (1+α)F_{n+1} − αFₙ + M hₐ + (1+α)C h_v + α(C u̇ₙ + K uₙ).
//! With β = (1−α)²/4, γ = 1/2 − α the scheme is second order, unconditionally
//! stable, and damps the highest frequencies (spectral radius (1+α)/(1−α) at
//! ωΔt → ∞), which quiets the ringing of constrained wheel DOFs.

/// The integration constants of one (β, γ, α, Δt).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Newmark {
    /// 1/(βΔt²), 1/s².
    pub a0: f64,
    /// γ/(βΔt), 1/s.
    pub a1: f64,
    /// 1/(βΔt), 1/s.
    pub a2: f64,
    /// 1/(2β) − 1.
    pub a3: f64,
    /// γ/β − 1.
    pub a4: f64,
    /// (Δt/2)(γ/β − 2), s.
    pub a5: f64,
    /// Δt(1 − γ), s.
    pub a6: f64,
    /// γΔt, s.
    pub a7: f64,
    /// HHT α (≤ 0; 0 = plain Newmark).
    pub alpha: f64,
}

impl Newmark {
    /// Constants for parameters `beta`, `gamma`, HHT `alpha` and step `dt` (s).
    pub fn new(beta: f64, gamma: f64, alpha: f64, dt: f64) -> Self {
        Self {
            a0: 1.0 / (beta * dt * dt),
            a1: gamma / (beta * dt),
            a2: 1.0 / (beta * dt),
            a3: 1.0 / (2.0 * beta) - 1.0,
            a4: gamma / beta - 1.0,
            a5: dt / 2.0 * (gamma / beta - 2.0),
            a6: dt * (1.0 - gamma),
            a7: gamma * dt,
            alpha,
        }
    }

    /// Weight 1 + α of the end-of-step elastic, damping and external forces.
    #[inline]
    pub fn weight(&self) -> f64 {
        1.0 + self.alpha
    }

    /// History part of the effective load's inertia term, a₀u + a₂u̇ + a₃ü.
    #[inline]
    pub fn inertia_history(&self, u: f64, v: f64, a: f64) -> f64 {
        self.a0 * u + self.a2 * v + self.a3 * a
    }

    /// History part of the effective load's damping term, a₁u + a₄u̇ + a₅ü.
    #[inline]
    pub fn damping_history(&self, u: f64, v: f64, a: f64) -> f64 {
        self.a1 * u + self.a4 * v + self.a5 * a
    }

    /// New acceleration from the new displacement.
    #[inline]
    pub fn acceleration(&self, u_new: f64, u: f64, v: f64, a: f64) -> f64 {
        self.a0 * (u_new - u) - self.a2 * v - self.a3 * a
    }

    /// New velocity from old and new accelerations.
    #[inline]
    pub fn velocity(&self, v: f64, a: f64, a_new: f64) -> f64 {
        v + self.a6 * a + self.a7 * a_new
    }
}
