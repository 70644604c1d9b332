//! Surface profiles (roughness) under the wheels.
//!
//! r(x) is the elevation of the running surface above the deck's neutral
//! line, m, positive upward, as a function of the position x along the bridge
//! (m). It starts at the entrance (x = 0) and continues past the exit; the
//! approach (x < 0) is smooth.

use std::f64::consts::PI;

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};

use crate::scenario::resolved::Surface;

/// Ω₀ of the road PSD S(Ω) = A_r (Ω/Ω₀)⁻², rad/m (the plate paper's Eq. 14:
/// the discontinuity frequency 1/2π).
pub const REFERENCE_WAVENUMBER: f64 = 1.0 / (2.0 * PI);

/// A surface profile ready to evaluate.
#[derive(Debug, Clone, PartialEq)]
pub enum Profile {
    /// r = 0.
    Smooth,
    /// r(x) = a sin(k x + φ) with k = 2π/wavelength (rad/m), for x ≥ 0.
    Harmonic {
        /// Amplitude a, m.
        amplitude: f64,
        /// Wavenumber k, rad/m.
        wavenumber: f64,
        /// Phase φ, rad.
        phase: f64,
    },
    /// The plate paper's Eq. 17: r(x) = Σᵢ aᵢ cos(i Ω₁ x − θᵢ) − r₀ for
    /// x ≥ 0, with Ω₁ = ΔΩ = 2π/L_c (rad/m), aᵢ = √(4 S(iΩ₁) ΔΩ),
    /// S(Ω) = A_r (Ω/Ω₀)⁻², θᵢ uniform on [0, 2π) from a ChaCha8 stream, and
    /// r₀ = Σ aᵢ cos θᵢ so the profile starts at 0 at the entrance (the
    /// approach is smooth). Periodic with period L_c.
    Random {
        /// Ω₁ = 2π/L_c, rad/m.
        fundamental: f64,
        /// (aᵢ cos θᵢ, aᵢ sin θᵢ) per term, m.
        terms: Vec<(f64, f64)>,
        /// r₀, m.
        offset: f64,
    },
}

/// Uniform sample in [0, 1) from the top 53 bits of a 64-bit draw.
fn uniform(rng: &mut ChaCha8Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

impl Profile {
    /// Builds the profile of a resolved surface.
    pub fn build(surface: &Surface) -> Self {
        match *surface {
            Surface::Smooth => Profile::Smooth,
            Surface::Harmonic {
                amplitude,
                wavelength,
                phase,
            } => Profile::Harmonic {
                amplitude,
                wavenumber: 2.0 * PI / wavelength,
                phase,
            },
            Surface::Random {
                coefficient,
                sampling_length,
                terms,
                seed,
                ..
            } => {
                let fundamental = 2.0 * PI / sampling_length;
                let mut rng = ChaCha8Rng::seed_from_u64(seed);
                let series: Vec<(f64, f64)> = (1..=terms)
                    .map(|i| {
                        let wavenumber = i as f64 * fundamental;
                        let density = coefficient * (wavenumber / REFERENCE_WAVENUMBER).powi(-2);
                        let amplitude = (4.0 * density * fundamental).sqrt();
                        let (sin, cos) = (2.0 * PI * uniform(&mut rng)).sin_cos();
                        (amplitude * cos, amplitude * sin)
                    })
                    .collect();
                let offset = series.iter().map(|t| t.0).sum();
                Profile::Random {
                    fundamental,
                    terms: series,
                    offset,
                }
            }
        }
    }

    /// Elevation, slope and curvature of the random series at x ≥ 0: with
    /// cos(iΩ₁x − θᵢ) = cos(iΩ₁x) cos θᵢ + sin(iΩ₁x) sin θᵢ and the angle
    /// iΩ₁x advanced by one complex rotation per term (no trigonometric call
    /// per term; round-off grows like i·ε, negligible for N ≤ 1e6). O(N).
    fn random_at(fundamental: f64, terms: &[(f64, f64)], offset: f64, x: f64) -> (f64, f64, f64) {
        let (step_sin, step_cos) = (fundamental * x).sin_cos();
        let (mut sin, mut cos) = (step_sin, step_cos);
        let (mut value, mut slope, mut curvature) = (0.0, 0.0, 0.0);
        for (i, &(a_cos, a_sin)) in terms.iter().enumerate() {
            let k = (i + 1) as f64 * fundamental;
            // aᵢ cos(kx − θ) and its derivative −k aᵢ sin(kx − θ).
            let c = cos * a_cos + sin * a_sin;
            let s = sin * a_cos - cos * a_sin;
            value += c;
            slope -= k * s;
            curvature -= k * k * c;
            let next_cos = cos * step_cos - sin * step_sin;
            sin = sin * step_cos + cos * step_sin;
            cos = next_cos;
        }
        (value - offset, slope, curvature)
    }

    /// A scale of the profile's slope (dimensionless): a·k for a harmonic
    /// profile, the RMS slope √(Σ (k aᵢ)²/2) for a random one.
    pub fn slope_scale(&self) -> f64 {
        match self {
            Profile::Smooth => 0.0,
            Profile::Harmonic {
                amplitude,
                wavenumber,
                ..
            } => amplitude * wavenumber,
            Profile::Random {
                fundamental, terms, ..
            } => (terms
                .iter()
                .enumerate()
                .map(|(i, &(c, s))| ((i + 1) as f64 * fundamental).powi(2) * (c * c + s * s))
                .sum::<f64>()
                / 2.0)
                .sqrt(),
        }
    }

    /// Elevation at `x`, m.
    #[inline]
    pub fn elevation(&self, x: f64) -> f64 {
        match *self {
            Profile::Smooth => 0.0,
            Profile::Harmonic { .. } if x < 0.0 => 0.0,
            Profile::Harmonic {
                amplitude,
                wavenumber,
                phase,
            } => amplitude * (wavenumber * x + phase).sin(),
            Profile::Random { .. } if x < 0.0 => 0.0,
            Profile::Random {
                fundamental,
                ref terms,
                offset,
            } => Self::random_at(fundamental, terms, offset, x).0,
        }
    }

    /// Elevation r (m), slope dr/dx (dimensionless) and curvature d²r/dx²
    /// (1/m) at `x`. The harmonic profile's slope jumps at the entrance unless
    /// its phase is ±π/2: a kink the wheels feel as a step in vertical velocity.
    #[inline]
    pub fn elevation_slope_curvature(&self, x: f64) -> (f64, f64, f64) {
        match *self {
            Profile::Smooth => (0.0, 0.0, 0.0),
            Profile::Harmonic { .. } if x < 0.0 => (0.0, 0.0, 0.0),
            Profile::Harmonic {
                amplitude,
                wavenumber,
                phase,
            } => {
                let (s, c) = (wavenumber * x + phase).sin_cos();
                (
                    amplitude * s,
                    amplitude * wavenumber * c,
                    -amplitude * wavenumber * wavenumber * s,
                )
            }
            Profile::Random { .. } if x < 0.0 => (0.0, 0.0, 0.0),
            Profile::Random {
                fundamental,
                ref terms,
                offset,
            } => Self::random_at(fundamental, terms, offset, x),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harmonic_profile_starts_at_entrance() {
        let p = Profile::build(&Surface::Harmonic {
            amplitude: 0.003,
            wavelength: 1.5,
            phase: 0.5,
        });
        assert_eq!(p.elevation(-1.0), 0.0);
        assert!((p.elevation(0.0) - 0.003 * 0.5f64.sin()).abs() < 1e-15);
        assert!((p.elevation(1.5) - p.elevation(0.0)).abs() < 1e-15);
        assert!((p.elevation(0.375 - 0.5 / (2.0 * PI) * 1.5) - 0.003).abs() < 1e-12);
    }
}
