//! Surface profiles (roughness) under the wheels.
//!
//! r(x) is the elevation of the running surface above the deck's neutral
//! line, m, positive upward, as a function of the position x along the bridge
//! (m). It starts at the entrance (x = 0) and continues past the exit; the
//! approach (x < 0) is smooth, except for measured and piecewise-linear
//! profiles and shapes, which are defined wherever their data say, and the
//! track and road spectra, which fade in over a run-in on the approach
//! ([`fade_start`]).
//!
//! Two rails: a wheel with lateral offset > 0 (to the left of travel) runs
//! on the [`Rail::Left`], < 0 on the [`Rail::Right`], and a wheel on the
//! vehicle's path line (single-track models: oscillators, moving forces)
//! on the left one. Profiles with one elevation give it to both rails.
//!
//! Evaluation is O(1) per wheel per step for every random spectrum (a
//! quintic Hermite grid sampled once; the plate paper's power-law `random`
//! over one period of its exactly periodic series), O(log n) for a measured
//! profile.

mod build;
pub mod interp;
pub mod shapes;
pub mod spectrum;
pub mod synth;

use std::f64::consts::PI;

use self::interp::{CubicSpline, QuinticGrid, Triple};
use self::shapes::Shape;

pub use crate::scene::{
    NODES_PER_WAVELENGTH, POWER_LAW_NODES_PER_WAVELENGTH, grid_nodes, power_law_grid_nodes,
};

/// Why a profile could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// The sampled grid does not fit in memory.
    #[error(
        "the sampled surface profile needs {nodes} grid nodes, more than this machine's memory holds"
    )]
    OutOfMemory {
        /// Nodes asked for.
        nodes: usize,
    },
}

/// The rail (wheel track) a wheel runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rail {
    /// Lateral offset ≥ 0 (left of travel, or on the path line).
    Left,
    /// Lateral offset < 0.
    Right,
}

impl Rail {
    /// The rail of a wheel at lateral offset `lateral` (m, + to the left).
    pub fn of_lateral(lateral: f64) -> Rail {
        if lateral < 0.0 {
            Rail::Right
        } else {
            Rail::Left
        }
    }
}

/// The profile (r, r′, r″) at ξ = (x + L)/L of a run-in of length `run_in` =
/// L, multiplied by the quintic smoothstep S(ξ) = 10ξ³ − 15ξ⁴ + 6ξ⁵ (S = 0,
/// S′ = S″ = 0 at ξ = 0; S = 1, S′ = S″ = 0 at ξ = 1), so the product and
/// its first two derivatives are continuous: (S r)″ = S″r + 2S′r′ + S r″.
fn fade_in((r, dr, ddr): Triple, xi: f64, run_in: f64) -> Triple {
    if xi >= 1.0 {
        return (r, dr, ddr);
    }
    let xi = xi.max(0.0);
    let s = xi * xi * xi * (10.0 + xi * (-15.0 + 6.0 * xi));
    let ds = 30.0 * xi * xi * (1.0 - xi) * (1.0 - xi) / run_in;
    let dds = 60.0 * xi * (1.0 - xi) * (1.0 - 2.0 * xi) / (run_in * run_in);
    (s * r, ds * r + s * dr, dds * r + 2.0 * ds * dr + s * ddr)
}

/// Where the fade-in of a run-in of `run_in` m starts (m from the
/// entrance) when the front-most wheel starts at `front_start` (m, ≤ 0): at
/// x = −run_in if every wheel starts there or behind it, else under that
/// front axle, so that every wheel starts on level track (r = r′ = r″ = 0)
/// and meets the profile through the fade, never through a jump. 0 without
/// a run-in.
pub fn fade_start(run_in: f64, front_start: f64) -> f64 {
    if run_in > 0.0 {
        // A vehicle placed at −L through its entry time (t = L/v) starts
        // within rounding of −L: that is −L.
        if front_start <= -run_in * (1.0 - 1e-12) {
            return -run_in;
        }
        front_start.min(0.0)
    } else {
        0.0
    }
}

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
    ///
    /// Evaluated in O(1) from `period_grid`, the series sampled exactly
    /// (r, r′, r″ at each node, [`Profile::random_at`]) once over one
    /// period and interpolated by quintic Hermite polynomials.
    Random {
        /// Ω₁ = 2π/L_c, rad/m.
        fundamental: f64,
        /// (aᵢ cos θᵢ, aᵢ sin θᵢ) per term, m.
        terms: Vec<(f64, f64)>,
        /// r₀, m.
        offset: f64,
        /// r − r₀ over [0, L_c + h] ([`POWER_LAW_NODES_PER_WAVELENGTH`]
        /// nodes per shortest wavelength L_c/N), m.
        period_grid: QuinticGrid,
    },
    /// A random sample on a grid, with a run-in of L m unshifted and faded
    /// in over [x_f, x_f + L] ([`fade_start`]: x_f = −L unless a wheel
    /// starts after it), 0 before; without a run-in (L = 0) from the
    /// entrance on, shifted so r(0) = 0, 0 for x < 0.
    Sampled {
        /// The left rail (and every wheel if `right` is `None`).
        left: QuinticGrid,
        /// The right rail, if independent.
        right: Option<QuinticGrid>,
        /// The rails' alignment (left, and right if independent), if
        /// sampled: random streams 2 and 3 of the seed, so the vertical
        /// profile is the same with or without it.
        alignment: Option<(QuinticGrid, Option<QuinticGrid>)>,
    },
    /// A measured profile.
    Measured {
        /// The left rail (and every wheel if `right` is `None`).
        left: CubicSpline,
        /// The right rail, if measured.
        right: Option<CubicSpline>,
        /// The track's alignment, if measured: the spline of the mean of
        /// the two rails' lateral positions (the mean of the two rails'
        /// natural splines, the spline being linear in its data).
        alignment: Option<CubicSpline>,
    },
    /// A deterministic shape.
    Shape(Shape),
    /// A deterministic profile (a harmonic or a shape) laid sideways: the
    /// rails are level and the inner profile is the track's alignment, m
    /// (+ to the left of travel), both rails displaced alike.
    Alignment(Box<Profile>),
}

impl Profile {
    /// The power-law profile at x ≥ 0 from its period grid.
    #[inline]
    fn random_from_grid(fundamental: f64, grid: &QuinticGrid, x: f64) -> Triple {
        let period = 2.0 * PI / fundamental;
        grid.at(x - (x / period).floor() * period)
    }

    /// Elevation, slope and curvature of the random series at x ≥ 0: with
    /// cos(iΩ₁x − θᵢ) = cos(iΩ₁x) cos θᵢ + sin(iΩ₁x) sin θᵢ and the angle
    /// iΩ₁x advanced by one complex rotation per term (no trigonometric call
    /// per term; round-off grows like i·ε, negligible for N ≤ 1e6). O(N).
    pub fn random_at(
        fundamental: f64,
        terms: &[(f64, f64)],
        offset: f64,
        x: f64,
    ) -> (f64, f64, f64) {
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
    /// profile, the RMS slope √(Σ (k aᵢ)²/2) for the power-law random one,
    /// the largest slope at the grid nodes or data points for the others.
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
            Profile::Sampled { left, right, .. } => left
                .max_slope()
                .max(right.as_ref().map_or(0.0, QuinticGrid::max_slope)),
            Profile::Measured { left, right, .. } => left
                .max_slope()
                .max(right.as_ref().map_or(0.0, CubicSpline::max_slope)),
            Profile::Shape(shape) => shape.max_slope(),
            Profile::Alignment(_) => 0.0,
        }
    }

    /// The largest slope of the track's alignment (dimensionless; 0 where
    /// the surface samples none): the lateral counterpart of
    /// [`Profile::slope_scale`].
    pub fn alignment_slope_scale(&self) -> f64 {
        match self {
            Profile::Sampled {
                alignment: Some((left, right)),
                ..
            } => left
                .max_slope()
                .max(right.as_ref().map_or(0.0, QuinticGrid::max_slope)),
            Profile::Measured {
                alignment: Some(alignment),
                ..
            } => alignment.max_slope(),
            Profile::Alignment(inner) => inner.slope_scale(),
            _ => 0.0,
        }
    }

    /// Elevation at `x` (m) under the left rail (or the one profile), m.
    #[inline]
    pub fn elevation(&self, x: f64) -> f64 {
        self.elevation_on(Rail::Left, x)
    }

    /// Elevation, slope and curvature at `x` (m) under the left rail (or
    /// the one profile): [`Profile::elevation_slope_curvature_on`].
    #[inline]
    pub fn elevation_slope_curvature(&self, x: f64) -> Triple {
        self.elevation_slope_curvature_on(Rail::Left, x)
    }

    /// Elevation at `x` (m) under `rail`, m.
    #[inline]
    pub fn elevation_on(&self, rail: Rail, x: f64) -> f64 {
        match *self {
            Profile::Smooth | Profile::Alignment(_) => 0.0,
            Profile::Harmonic { .. } | Profile::Random { .. } if x < 0.0 => 0.0,
            Profile::Harmonic {
                amplitude,
                wavenumber,
                phase,
            } => amplitude * (wavenumber * x + phase).sin(),
            Profile::Random {
                fundamental,
                ref period_grid,
                ..
            } => Self::random_from_grid(fundamental, period_grid, x).0,
            Profile::Sampled {
                ref left,
                ref right,
                ..
            } => match (rail, right) {
                (Rail::Right, Some(r)) => r.value_at(x),
                _ => left.value_at(x),
            },
            _ => self.elevation_slope_curvature_on(rail, x).0,
        }
    }

    /// Elevation r (m), slope dr/dx (dimensionless) and curvature d²r/dx²
    /// (1/m) at `x` under `rail`. The harmonic profile's slope jumps at the
    /// entrance unless its phase is ±π/2, and a random one's at the
    /// entrance: a kink the wheels feel as a step in vertical velocity.
    #[inline]
    pub fn elevation_slope_curvature_on(&self, rail: Rail, x: f64) -> Triple {
        match *self {
            Profile::Smooth | Profile::Alignment(_) => (0.0, 0.0, 0.0),
            Profile::Harmonic { .. } | Profile::Random { .. } if x < 0.0 => (0.0, 0.0, 0.0),
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
            Profile::Random {
                fundamental,
                ref period_grid,
                ..
            } => Self::random_from_grid(fundamental, period_grid, x),
            Profile::Sampled {
                ref left,
                ref right,
                ..
            } => match (rail, right) {
                (Rail::Right, Some(r)) => r.at(x),
                _ => left.at(x),
            },
            Profile::Measured {
                ref left,
                ref right,
                ..
            } => match (rail, right) {
                (Rail::Right, Some(r)) => r.at(x),
                _ => left.at(x),
            },
            Profile::Shape(ref shape) => shape.at(x),
        }
    }

    /// The track's alignment at `x` (m): the lateral irregularity (m, +y
    /// to the left), its slope and curvature (1/m) that a wheelset
    /// following both rails sideways takes — the mean of the left and right
    /// rails' alignment (the track centre line); zero where the surface
    /// samples none. A spectrum with `alignment: true` samples it, a
    /// measured profile with lateral columns gives it (their mean), and a
    /// harmonic or shape with `direction: lateral` is it.
    #[inline]
    pub fn alignment_at(&self, x: f64) -> Triple {
        match self {
            Profile::Sampled {
                alignment: Some((left, right)),
                ..
            } => match right {
                Some(right) => {
                    let (a, b) = (left.at(x), right.at(x));
                    (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1), 0.5 * (a.2 + b.2))
                }
                None => left.at(x),
            },
            Profile::Measured {
                alignment: Some(alignment),
                ..
            } => alignment.at(x),
            Profile::Alignment(inner) => inner.elevation_slope_curvature_on(Rail::Left, x),
            _ => (0.0, 0.0, 0.0),
        }
    }
}

#[cfg(test)]
mod tests;
