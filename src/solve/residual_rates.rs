//! The rates of the static correction's residual deflection under a
//! wheel ([`super::permanent`]): the modes left out deflect
//! quasi-statically, s = −Σ_d R_cd λ_d, but the wheel riding s has mass,
//! so s's velocity and acceleration enter the wheel's kinematics.

use super::newmark::Newmark;

/// Spectral radius at ωΔt → ∞ of the residual deflection's rates
/// ([`ResidualRates`]). The wheel on the residual spring has
/// ω_r = 1/√(m R), unbounded where R → 0 (at a simple support, and over an
/// imported track's entry ramps, where R falls as the load weight's
/// square): undamped there, the trapezoidal rule (ρ∞ = 1) gained energy
/// from the changing R and the contact forces diverged at the exit ramp of
/// the EMBS golden viaduct (8,000 % on the wheel force, notes/embs/NOTES.md).
/// 0.8 damps what the step cannot resolve (ω_rΔt → ∞) about as Newmark's
/// γ = 0.6 did there (ρ∞ ≈ 0.82), but keeps second order; it damps less
/// than γ = 0.6 at ω_rΔt ~ 1–10, as on the exit ramp, where that first-order
/// scheme's ξ ≈ (γ − ½)ωΔt/2 acted (measured on the EMBS golden scene at 564
/// modes: wheel force 22 % against 8.6 % with γ = 0.6 off the converged
/// answer there, notes/embs/NOTES.md).
const RESIDUAL_RHO_INFINITY: f64 = 0.8;

/// The step Δt (s) of a Newmark scheme: a₇ = γΔt and a₂/a₁ = 1/γ.
pub(super) fn step_of(nm: &Newmark) -> f64 {
    nm.a7 * nm.a2 / nm.a1
}

/// The rates of the residual deflection s = −Σ_d R_cd λ_d, an algebraic
/// function of the contact forces, by the WBZ-α method (Wood, Bossak &
/// Zienkiewicz 1980; the generalized-α method with α_f = 0, Chung &
/// Hulbert 1993, Eq. 25 ff.): Newmark's relations with γ = ½ − α_m,
/// β = ¼(1 − α_m)² give ṡₙ₊₁ and s̈ₙ₊₁ from sₙ₊₁, and the wheel's inertia
/// takes (1 − α_m)s̈ₙ₊₁ + α_m s̈ₙ. With α_m = (ρ∞ − 1)/(ρ∞ + 1) < 0 the scheme
/// damps the unresolved residual oscillation to [`RESIDUAL_RHO_INFINITY`]
/// per step, and remains second order: Newmark's s̈ₙ approximates
/// s̈(tₙ + α_mΔt) to second order (Erlicher, Bonaventura & Bursi 2002), so the
/// weighted sum approximates s̈(tₙ₊₁), where the vehicle's equation is
/// written, and ṡₙ₊₁ approximates ṡ(tₙ₊₁). (Newmark's γ = 0.6 alone, tried
/// first, is first order.)
///
/// The step on which a wheel enters the model starts s from a quadratic in
/// time, s = ½ s̈ τ² with τ = Δt (s, ṡ = 0 where it enters; at a simple
/// support R grows as the distance squared, so s̈ = −R″v²λ jumps there):
/// ṡ = 2s/Δt and s̈ = 2s/Δt². Started from rest instead, the Newmark
/// relations put an O(1) error on s̈, hence on the contact force, for the
/// steps after the entry at any Δt — the contact force's max-norm error
/// stopped converging (physics::newmark_converges_at_second_order: 88.8,
/// 31.4, 13.7, 11.3 N at Δt/1…/8, with γ = 0.6 as with WBZ-α). Exact when
/// the entry falls on a step, as there; on an imported track the load
/// enters through the entry ramp, where s and its rates start near 0.
#[derive(Debug, Clone, Copy)]
pub(super) struct ResidualRates {
    /// Newmark's relations with γ = ½ − α_m, β = ¼(1 − α_m)².
    scheme: Newmark,
    /// WBZ's α_m (≤ 0).
    alpha_m: f64,
    /// How s's rates are formed this step.
    start: ResidualStart,
}

/// How a contact's residual rates are formed this step ([`ResidualRates`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum ResidualStart {
    /// WBZ-α's relations from the rates at tₙ.
    Running,
    /// The wheel enters the model: ṡ = 2s/Δt, s̈ = 2s/Δt².
    Entering,
    /// The run's first step with the wheel already on the model: s starts
    /// static, ṡ = s̈ = 0.
    AtRest,
}

impl ResidualRates {
    /// The rates at the step of the main scheme `nm`, formed as `start` says.
    pub(super) fn new(nm: &Newmark, start: ResidualStart) -> Self {
        let dt = step_of(nm);
        let alpha_m = (RESIDUAL_RHO_INFINITY - 1.0) / (RESIDUAL_RHO_INFINITY + 1.0);
        let gamma = 0.5 - alpha_m;
        let beta = 0.25 * (1.0 - alpha_m).powi(2);
        Self {
            scheme: Newmark::new(beta, gamma, 0.0, dt),
            alpha_m,
            start,
        }
    }

    /// The start's slopes: ṡ = 2s/Δt, s̈ = 2s/Δt² on entry, 0 at rest
    /// ([`ResidualRates`]).
    fn start_slopes(&self) -> [f64; 2] {
        let dt = step_of(&self.scheme);
        match self.start {
            ResidualStart::AtRest => [0.0; 2],
            _ => [2.0 / dt, 2.0 / (dt * dt)],
        }
    }

    /// ∂ṡₙ₊₁/∂sₙ₊₁ (1/s) and ∂(wheel's s̈)/∂sₙ₊₁ (1/s²).
    pub(super) fn slopes(&self) -> [f64; 2] {
        if self.start != ResidualStart::Running {
            return self.start_slopes();
        }
        [self.scheme.a1, (1.0 - self.alpha_m) * self.scheme.a0]
    }

    /// The parts of ṡₙ₊₁ (m/s) and of the wheel's s̈ (m/s²) that do not
    /// depend on sₙ₊₁, from s, ṡ, s̈ at tₙ (`motion`).
    pub(super) fn history(&self, [s, velocity, acceleration]: [f64; 3]) -> [f64; 2] {
        if self.start != ResidualStart::Running {
            return [0.0; 2];
        }
        let nm = &self.scheme;
        [
            -nm.damping_history(s, velocity, acceleration),
            -(1.0 - self.alpha_m) * nm.inertia_history(s, velocity, acceleration)
                + self.alpha_m * acceleration,
        ]
    }

    /// s, ṡ and Newmark's s̈ at tₙ₊₁ from those at tₙ (`motion`) and sₙ₊₁ =
    /// `residual` (m), and the velocity (m/s) and acceleration (m/s²) the
    /// wheel rides.
    pub(super) fn advance(&self, motion: [f64; 3], residual: f64) -> ([f64; 3], [f64; 2]) {
        if self.start != ResidualStart::Running {
            // s̈ constant on the quadratic: Newmark's s̈ₙ (an estimate of
            // s̈(tₙ + α_mΔt)) is the same value.
            let [velocity, acceleration] = self.start_slopes().map(|k| k * residual);
            return ([residual, velocity, acceleration], [velocity, acceleration]);
        }
        let nm = &self.scheme;
        let [s, velocity, acceleration] = motion;
        let new_acceleration = nm.acceleration(residual, s, velocity, acceleration);
        let new_velocity = nm.velocity(velocity, acceleration, new_acceleration);
        let wheel_acceleration =
            (1.0 - self.alpha_m) * new_acceleration + self.alpha_m * acceleration;
        (
            [residual, new_velocity, new_acceleration],
            [new_velocity, wheel_acceleration],
        )
    }
}
