//! Surface profiles (roughness) under the wheels.
//!
//! r(x) is the elevation of the running surface above the deck's neutral
//! line, m, positive upward, as a function of the position x along the bridge
//! (m). It starts at the entrance (x = 0) and continues past the exit; the
//! approach (x < 0) is smooth.

use std::f64::consts::PI;

use crate::scenario::resolved::Surface;

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
