//! Earthquake ground motion: acceleration records and the uniform support
//! excitation they impose.
//!
//! A record is a time series of ground acceleration üg(t) (m/s²) in one
//! direction, read from a PEER NGA `.AT2` file or a CSV table (the format reads
//! both: `scenario::ground`), scaled and shifted to start at a given time of the run.
//! Between samples üg is linear in time, so its integrals, the ground
//! velocity and displacement, are exact cubic and quadratic polynomials
//! ([`GroundRecord::velocity_displacement`]); before the record starts and
//! after it ends üg = 0.
//!
//! The motion acts as a uniform support excitation in relative coordinates
//! (EMBS paper, Eqs. 3 and 6; Chopra, Dynamics of Structures, §9.4): with
//! u = u_abs − δ u_g every structure obeys M ü + C u̇ + K u = f − M δ üg,
//! δ the rigid-body displacement of every DOF for a unit ground motion. A
//! vertical record thus acts on the vehicles exactly as a change of gravity
//! from g to g + üg, and on the bridge as the modal forces −Γᵢ üg with
//! Γᵢ = φᵢᵀ M δ (kg^½, the modal participation factors).

pub use crate::scene::STANDARD_GRAVITY;

use crate::scene::GroundRecord;

impl GroundRecord {
    /// Shortest sampling interval, s.
    pub fn shortest_interval(&self) -> f64 {
        self.time
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min)
    }

    /// Time of the last sample on the run's clock, s.
    pub fn end_time(&self) -> f64 {
        self.time.last().copied().unwrap_or(0.0)
    }

    /// Largest |üg|, m/s².
    pub fn peak_acceleration(&self) -> f64 {
        self.acceleration.iter().fold(0.0, |m, a| m.max(a.abs()))
    }

    /// Largest |ġg| over the record and after it, m/s: the velocity is
    /// quadratic between samples, so besides the samples its extremes lie
    /// where the linear acceleration crosses zero.
    pub fn peak_velocity(&self) -> f64 {
        let mut peak = self.velocity.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for k in 1..self.time.len() {
            let (a0, a1) = (self.acceleration[k - 1], self.acceleration[k]);
            if a0 * a1 < 0.0 {
                // ġg(τ) = v₀ + a₀τ + ½(a₁ − a₀)τ²/h at τ = −a₀h/(a₁ − a₀).
                let h = self.time[k] - self.time[k - 1];
                let tau = -a0 * h / (a1 - a0);
                let v = self.velocity[k - 1] + a0 * tau + 0.5 * (a1 - a0) / h * tau * tau;
                peak = peak.max(v.abs());
            }
        }
        peak
    }

    /// The interval k with time[k] ≤ t < time[k+1], if t is inside.
    #[inline]
    fn interval(&self, t: f64) -> Option<usize> {
        let n = self.time.len();
        if n < 2 || t.is_nan() || t < self.time[0] || t > self.time[n - 1] {
            return None;
        }
        Some(self.time.partition_point(|&s| s <= t).clamp(1, n - 1) - 1)
    }

    /// Ground acceleration at run time `t` (s), m/s²: linear between
    /// samples, 0 outside the record. O(log n).
    #[inline]
    pub fn acceleration_at(&self, t: f64) -> f64 {
        let Some(k) = self.interval(t) else {
            return 0.0;
        };
        let (t0, t1) = (self.time[k], self.time[k + 1]);
        let s = (t - t0) / (t1 - t0);
        self.acceleration[k] + s * (self.acceleration[k + 1] - self.acceleration[k])
    }

    /// Ground velocity (m/s) and displacement (m) at run time `t` (s): the
    /// exact integrals of the piecewise-linear acceleration from rest at the
    /// record's start; after its end the ground keeps its last velocity (no
    /// baseline correction: PEER records come corrected). O(log n).
    pub fn velocity_displacement(&self, t: f64) -> (f64, f64) {
        let n = self.time.len();
        if n == 0 || t.is_nan() || t <= self.time[0] {
            return (0.0, 0.0);
        }
        if t >= self.time[n - 1] {
            let tau = t - self.time[n - 1];
            return (
                self.velocity[n - 1],
                self.displacement[n - 1] + self.velocity[n - 1] * tau,
            );
        }
        let k = self.interval(t).unwrap_or(0);
        let (t0, t1) = (self.time[k], self.time[k + 1]);
        let (h, tau) = (t1 - t0, t - t0);
        let (a0, a1) = (self.acceleration[k], self.acceleration[k + 1]);
        let slope = (a1 - a0) / h;
        let velocity = self.velocity[k] + a0 * tau + 0.5 * slope * tau * tau;
        let displacement = self.displacement[k]
            + self.velocity[k] * tau
            + 0.5 * a0 * tau * tau
            + slope * tau * tau * tau / 6.0;
        (velocity, displacement)
    }
}

/// The support excitation of a run: its records and what they do to the
/// kept modes.
#[derive(Debug, Clone)]
pub struct GroundExcitation {
    /// The vertical components (their accelerations add up).
    pub vertical: Vec<std::sync::Arc<GroundRecord>>,
    /// Participation factors Γᵢ = φᵢᵀ M δ of the kept modes for a vertical
    /// support motion, √kg.
    pub participation: Vec<f64>,
    /// Total mass of the bridge, kg.
    pub total_mass: f64,
    /// The lateral components (their accelerations add up).
    pub lateral: Vec<std::sync::Arc<GroundRecord>>,
    /// Participation factors Γᵢ = φᵢᵀ M δ_y of the kept modes for a
    /// lateral support motion (δ_y = 1 on every lateral translation), √kg;
    /// empty without a lateral record, zero for a bridge modelled in the
    /// vertical plane (it moves rigidly with the ground sideways).
    pub lateral_participation: Vec<f64>,
    /// The bridge mass moving with a rigid lateral shift, kg (Σ Γ² tends to it).
    pub lateral_mass: f64,
}

impl GroundExcitation {
    /// Vertical ground acceleration at run time `t` (s), m/s².
    #[inline]
    pub fn vertical_acceleration(&self, t: f64) -> f64 {
        self.vertical.iter().map(|r| r.acceleration_at(t)).sum()
    }

    /// Vertical ground velocity (m/s) and displacement (m) at `t` (s).
    pub fn vertical_motion(&self, t: f64) -> (f64, f64) {
        self.vertical
            .iter()
            .map(|r| r.velocity_displacement(t))
            .fold((0.0, 0.0), |(v, u), (dv, du)| (v + dv, u + du))
    }

    /// Lateral ground acceleration at run time `t` (s), m/s² (+y left of travel).
    #[inline]
    pub fn lateral_acceleration(&self, t: f64) -> f64 {
        self.lateral.iter().map(|r| r.acceleration_at(t)).sum()
    }

    /// Lateral ground velocity (m/s) and displacement (m) at `t` (s).
    pub fn lateral_motion(&self, t: f64) -> (f64, f64) {
        self.lateral
            .iter()
            .map(|r| r.velocity_displacement(t))
            .fold((0.0, 0.0), |(v, u), (dv, du)| (v + dv, u + du))
    }

    /// Σ Γᵢ² / total mass: the share of the bridge's mass the kept modes
    /// move under a vertical support motion (dimensionless, ≤ 1).
    pub fn effective_mass_ratio(&self) -> f64 {
        self.participation.iter().map(|g| g * g).sum::<f64>() / self.total_mass
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant acceleration a from t = 1 s: v = a(t − 1), u = a(t − 1)²/2
    /// exactly; a ramp a = t: v = t²/2, u = t³/6.
    #[test]
    fn integrals_are_exact_for_linear_acceleration() {
        let r = GroundRecord::new(&[0.0, 0.5, 2.0], &[2.0, 2.0, 2.0], 1.5, 1.0);
        assert_eq!(r.acceleration_at(0.5), 0.0);
        assert_eq!(r.acceleration_at(2.0), 3.0);
        let (v, u) = r.velocity_displacement(2.2);
        assert!((v - 3.0 * 1.2).abs() < 1e-14 && (u - 1.5 * 1.44).abs() < 1e-14);
        let r = GroundRecord::new(&[0.0, 0.3, 1.0, 1.7], &[0.0, 0.3, 1.0, 1.7], 1.0, 0.0);
        for t in [0.1, 0.3, 0.77, 1.5] {
            let (v, u) = r.velocity_displacement(t);
            assert!((r.acceleration_at(t) - t).abs() < 1e-15);
            assert!((v - t * t / 2.0).abs() < 1e-15, "v at {t}");
            assert!((u - t * t * t / 6.0).abs() < 1e-15, "u at {t}");
        }
        // After the end: the last velocity is kept.
        let (v, u) = r.velocity_displacement(2.7);
        assert!((v - 1.445).abs() < 1e-14);
        assert!((u - (1.7f64.powi(3) / 6.0 + 1.445)).abs() < 1e-13);
    }

    /// üg = 1 − 2t on [0, 1] s: ġg = t − t², largest 0.25 m/s at t = 0.5 s,
    /// between the samples (both at 0 m/s); a sine A sin Ωt sampled finely
    /// peaks at ġg = 2A/Ω (ġg = (A/Ω)(1 − cos Ωt)).
    #[test]
    fn peak_velocity_is_found_between_samples() {
        let r = GroundRecord::new(&[0.0, 1.0], &[1.0, -1.0], 1.0, 0.0);
        assert!((r.peak_velocity() - 0.25).abs() < 1e-15);
        let omega = 2.0 * std::f64::consts::PI * 2.0;
        let time: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-3).collect();
        let acceleration: Vec<f64> = time.iter().map(|t| 3.0 * (omega * t).sin()).collect();
        let r = GroundRecord::new(&time, &acceleration, 1.0, 0.0);
        // Linear interpolation of the sine: relative error (ΩΔ)²/24 = 6.6e-6.
        assert!((r.peak_velocity() / (6.0 / omega) - 1.0).abs() < 2e-5);
    }
}
