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
/// the EMBS golden viaduct (8,000 % on the wheel force; docs/methods.md, "Why WBZ-α").
/// 0.8 damps what the step cannot resolve (ω_rΔt → ∞) about as Newmark's
/// γ = 0.6 did there (ρ∞ ≈ 0.82), but keeps second order; it damps less
/// than γ = 0.6 at ω_rΔt ~ 1–10, as on the exit ramp, where that first-order
/// scheme's ξ ≈ (γ − ½)ωΔt/2 acted (measured on the EMBS golden scene at 564
/// modes: wheel force 22 % against 8.6 % with γ = 0.6 off the converged
/// answer there; docs/methods.md, "Why WBZ-α"). The ramps no longer rely on it: the
/// wheel rides s's rates only where ω_r lies below the kept band
/// ([`residual_coupling`]: 4.2 % there).
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
    /// The share c ∈ [0, 1] of s's rates the wheel rides
    /// ([`residual_coupling`]).
    coupling: f64,
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
    pub(super) fn new(nm: &Newmark, start: ResidualStart, coupling: f64) -> Self {
        let dt = step_of(nm);
        let alpha_m = (RESIDUAL_RHO_INFINITY - 1.0) / (RESIDUAL_RHO_INFINITY + 1.0);
        let gamma = 0.5 - alpha_m;
        let beta = 0.25 * (1.0 - alpha_m).powi(2);
        Self {
            scheme: Newmark::new(beta, gamma, 0.0, dt),
            alpha_m,
            start,
            coupling,
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
    /// Both scaled by the coupling c.
    pub(super) fn slopes(&self) -> [f64; 2] {
        let c = self.coupling;
        if self.start != ResidualStart::Running {
            return self.start_slopes().map(|k| c * k);
        }
        [
            c * self.scheme.a1,
            c * (1.0 - self.alpha_m) * self.scheme.a0,
        ]
    }

    /// The parts of ṡₙ₊₁ (m/s) and of the wheel's s̈ (m/s²) that do not
    /// depend on sₙ₊₁, from s, ṡ, s̈ at tₙ (`motion`), scaled by the
    /// coupling c.
    pub(super) fn history(&self, [s, velocity, acceleration]: [f64; 3]) -> [f64; 2] {
        if self.start != ResidualStart::Running || self.coupling == 0.0 {
            return [0.0; 2];
        }
        let nm = &self.scheme;
        [
            -self.coupling * nm.damping_history(s, velocity, acceleration),
            self.coupling
                * (-(1.0 - self.alpha_m) * nm.inertia_history(s, velocity, acceleration)
                    + self.alpha_m * acceleration),
        ]
    }

    /// s, ṡ and Newmark's s̈ at tₙ₊₁ from those at tₙ (`motion`) and sₙ₊₁ =
    /// `residual` (m), and the velocity (m/s) and acceleration (m/s²) the
    /// wheel rides (the coupling c times s's).
    pub(super) fn advance(&self, motion: [f64; 3], residual: f64) -> ([f64; 3], [f64; 2]) {
        if self.start != ResidualStart::Running {
            // s̈ constant on the quadratic: Newmark's s̈ₙ (an estimate of
            // s̈(tₙ + α_mΔt)) is the same value.
            let [velocity, acceleration] = self.start_slopes().map(|k| k * residual);
            let c = self.coupling;
            return (
                [residual, velocity, acceleration],
                [c * velocity, c * acceleration],
            );
        }
        let nm = &self.scheme;
        let [s, velocity, acceleration] = motion;
        let new_acceleration = nm.acceleration(residual, s, velocity, acceleration);
        let new_velocity = nm.velocity(velocity, acceleration, new_acceleration);
        let wheel_acceleration =
            (1.0 - self.alpha_m) * new_acceleration + self.alpha_m * acceleration;
        (
            [residual, new_velocity, new_acceleration],
            [
                self.coupling * new_velocity,
                self.coupling * wheel_acceleration,
            ],
        )
    }
}

/// The share c ∈ [0, 1] of the residual deflection's rates a wheel of mass
/// `wheel_mass` (kg, its condensed mass on the contact DOF) rides, on a
/// residual flexibility `residual` (m/N, R_cc) below kept modes whose top
/// circular frequency is `top_omega` (rad/s).
///
/// The static correction stands for the modes left out, all above the kept
/// band's top ω_N, responding quasi-statically: a model of them only at
/// frequencies below ω_N. The wheel on the residual spring oscillates at
/// ω_r = 1/√(m R). Where ω_r ≪ ω_N (a heavy wheel on a track's pads and
/// ballast whose local compliance sits in a dense band of high modes: the
/// EMBS viaduct at 564 modes, ω_r/2π ≈ 181 Hz under a 277 Hz top) the wheel's
/// mass riding s is the physics the truncation lost. Where ω_r ≳ ω_N it is
/// not: on a beam at 5–7 modes the modes left out carry modal masses large
/// against the wheel's (ω_r ≈ √(M/2m)·ω_{N+1} for a beam of mass M), so a
/// wheel on them would oscillate below ω_{N+1}, not at ω_r on a massless
/// spring; and on an imported track's exit ramp R falls as the load
/// weight's square, ω_r → ∞ and the wheel, rung on a stiffening spring the
/// step cannot resolve, pumps (docs/methods.md, "Why the weight"). There
/// the quasi-static limit (c = 0: a mass on an infinitely stiff spring
/// follows it) is the right one. A smooth cut between the two,
/// c = y⁸/(1 + y⁸) with y = (ω_N/ω_r)² = ω_N² m R, i.e. 1/(1 + (ω_r/ω_N)¹⁶):
/// ½ at ω_r = ω_N, 0.97 at 0.8 ω_N, 0.05 at 1.2 ω_N; c → 1 as the kept band
/// grows past ω_r (R → 0 there anyway). Measured on the EMBS viaduct at
/// its automatic 564 modes against 1,128 modes and Δt/4 (docs/methods.md,
/// "Why the weight"): the sharper cut (power 16) beat power 8 (contact forces 4.2 % and
/// 4.1 % against 3.5 % and 4.2 %, but deck acceleration 2.5 % against 3.3 %,
/// rail lateral acceleration 5.3 % against 5.6 %); c = 1 everywhere left the
/// exit ramp's 22 % / 15 %, c = 0 (no residual inertia) the deck
/// acceleration's 21 %. On the beam scenes (quake-vertical-rail-car 7
/// modes, rail-car-braking 5: ω_r/2π ≥ 680 and 430 Hz against 80 and 41 Hz)
/// c < 1e-14, and their automatic settings are within 0.4 % and 0.14 % of
/// the converged answer again (0.87 % and 1.05 % with c = 1).
pub(super) fn residual_coupling(wheel_mass: f64, residual: f64, top_omega: f64) -> f64 {
    let y = top_omega * top_omega * wheel_mass.abs() * residual.max(0.0);
    let y8 = y.powi(8);
    if y8.is_finite() { y8 / (1.0 + y8) } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::residual_coupling;

    /// c = 1/(1 + (ω_r/ω_N)¹⁶) with ω_r = 1/√(m R): a 773 kg wheel on the
    /// residual flexibility that puts ω_r at a given multiple of ω_N.
    #[test]
    fn coupling_cuts_at_the_kept_band_top() {
        let (m, top) = (773.0, std::f64::consts::TAU * 276.1);
        let at = |ratio: f64| {
            let omega_r = ratio * top;
            residual_coupling(m, 1.0 / (m * omega_r * omega_r), top)
        };
        for (ratio, expected) in [(1.0, 0.5), (0.8, 0.972_6), (1.2, 0.051_3), (0.5, 1.0)] {
            assert!(
                (at(ratio) - expected).abs() < 1e-4,
                "ω_r = {ratio} ω_N: c = {}, expected {expected}",
                at(ratio)
            );
        }
        // R = 0 (off the model, or at a simple support): no inertia.
        assert_eq!(residual_coupling(m, 0.0, top), 0.0);
        assert_eq!(residual_coupling(m, -1e-12, top), 0.0);
        // The beam scenes: ω_r ≈ 10 ω_N.
        assert!(at(10.0) < 1e-15);
        // Monotone in R.
        let mut last = 0.0;
        for k in 0..200 {
            let c = residual_coupling(m, 1e-12 * 1.1f64.powi(k), top);
            assert!(c >= last);
            last = c;
        }
    }
}
