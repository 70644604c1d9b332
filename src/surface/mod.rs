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

pub mod interp;
pub mod shapes;
pub mod spectrum;
pub mod synth;

use std::f64::consts::PI;

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

use self::interp::{CubicSpline, QuinticGrid, Triple};
use self::shapes::Shape;
use self::synth::{SpectralSeries, uniform};
use crate::scene::Spectrum;
use crate::scene::{Rails, Sampling, Surface, TrackDirection};

/// Grid nodes per shortest wavelength of a sampled random profile: quintic
/// Hermite interpolation error 1.3e-6 of the shortest wave's amplitude
/// ([`QuinticGrid`]).
pub const NODES_PER_WAVELENGTH: f64 = 10.0;

/// Grid nodes per shortest wavelength of the plate paper's power-law series
/// (one period, so the grid costs 32·N nodes whatever the run's length):
/// finer than [`NODES_PER_WAVELENGTH`] because the plate paper's results are
/// reproduced to six digits, curvature included (the wheel's v²r″ term):
/// the quintic Hermite error of r is (2π/32)⁶/46080 = 1.3e-9 of the shortest
/// wave's amplitude, of r″ about (2π/32)⁴/384 = 3.9e-6 of its curvature
/// (`random_grid_follows_the_series` measures both).
pub const POWER_LAW_NODES_PER_WAVELENGTH: usize = 32;

/// Grid nodes of the power-law series' period grid for `terms` terms:
/// [`POWER_LAW_NODES_PER_WAVELENGTH`] per shortest wavelength over one
/// period, plus two (one interval past the period).
pub fn power_law_grid_nodes(terms: usize) -> usize {
    POWER_LAW_NODES_PER_WAVELENGTH * terms.max(1) + 2
}

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

/// Nodes of the grid a sampled profile needs to reach `reach` (m from the
/// entrance) with the given shortest wavelength (m); f64 so a hostile size
/// cannot wrap (budgeted while resolving).
pub fn grid_nodes(reach: f64, shortest_wavelength: f64) -> f64 {
    (reach.max(0.0) / (shortest_wavelength / NODES_PER_WAVELENGTH)).ceil() + 2.0
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
    /// Builds the profile of a resolved surface for wheels that all start
    /// at or behind a spectrum's run-in: [`Profile::build_from`] with the
    /// fade over [−L, 0].
    pub fn build(surface: &Surface, reach: f64) -> Result<Self, SurfaceError> {
        Self::build_from(surface, reach, f64::NEG_INFINITY)
    }

    /// Builds the profile of a resolved surface; a random spectrum is
    /// sampled from its fade's start ([`fade_start`] of the run-in and
    /// `front_start`, the front-most wheel's position at t = 0, m) to
    /// `reach` (m), the farthest any wheel goes during the run (past it r is
    /// held).
    pub fn build_from(
        surface: &Surface,
        reach: f64,
        front_start: f64,
    ) -> Result<Self, SurfaceError> {
        Ok(match *surface {
            Surface::Smooth => Profile::Smooth,
            Surface::Harmonic {
                amplitude,
                wavelength,
                phase,
                direction,
            } => Profile::Harmonic {
                amplitude,
                wavenumber: 2.0 * PI / wavelength,
                phase,
            }
            .laid(direction),
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
                let period_grid = Self::period_grid(fundamental, &series, offset, sampling_length)?;
                Profile::Random {
                    fundamental,
                    terms: series,
                    offset,
                    period_grid,
                }
            }
            Surface::Measured { ref profile, .. } => Profile::Measured {
                left: CubicSpline::new(profile.x.clone(), profile.left.clone()),
                right: profile
                    .right
                    .as_ref()
                    .map(|r| CubicSpline::new(profile.x.clone(), r.clone())),
                alignment: profile.lateral.as_ref().map(|(left, right)| {
                    let centre = left.iter().zip(right).map(|(l, r)| 0.5 * (l + r)).collect();
                    CubicSpline::new(profile.x.clone(), centre)
                }),
            },
            Surface::Ramp {
                start,
                length,
                height,
                direction,
            } => Profile::Shape(Shape::Ramp {
                start,
                length,
                height,
            })
            .laid(direction),
            Surface::Step {
                position,
                height,
                direction,
            } => Profile::Shape(Shape::Step { position, height }).laid(direction),
            Surface::Bump {
                start,
                length,
                height,
                direction,
            } => Profile::Shape(Shape::Bump {
                start,
                length,
                height,
            })
            .laid(direction),
            Surface::PiecewiseLinear {
                ref points,
                direction,
            } => Profile::Shape(Shape::PiecewiseLinear {
                points: points.iter().map(|p| (p[0], p[1])).collect(),
            })
            .laid(direction),
            Surface::Fra { class, sampling } => {
                Self::sampled(Spectrum::Fra { class }, sampling, reach, front_start)?
            }
            Surface::German {
                interference,
                sampling,
            } => Self::sampled(
                Spectrum::German { interference },
                sampling,
                reach,
                front_start,
            )?,
            Surface::Iso8608 { class, sampling } => {
                Self::sampled(Spectrum::Iso8608 { class }, sampling, reach, front_start)?
            }
        })
    }

    /// A deterministic profile in `direction`: itself (vertical), or laid
    /// sideways as the track's alignment ([`Profile::Alignment`]).
    fn laid(self, direction: TrackDirection) -> Self {
        match direction {
            TrackDirection::Vertical => self,
            TrackDirection::Lateral => Profile::Alignment(Box::new(self)),
        }
    }

    /// A random sample of `spectrum` on a grid from its fade's start
    /// ([`fade_start`]) to `reach` (m). The series is the same function of
    /// x whatever the fade (same seed, same profile past the fade).
    fn sampled(
        spectrum: Spectrum,
        sampling: Sampling,
        reach: f64,
        front_start: f64,
    ) -> Result<Self, SurfaceError> {
        let spacing = sampling.shortest_wavelength / NODES_PER_WAVELENGTH;
        let run_in = sampling.run_in;
        let start = fade_start(run_in, front_start);
        let count = grid_nodes(reach - start, sampling.shortest_wavelength) as usize;
        let grid = |spectrum: &Spectrum, stream| {
            let series = SpectralSeries::new(
                spectrum,
                sampling.shortest_wavelength,
                sampling.longest_wavelength,
                sampling.terms,
                sampling.seed,
                stream,
            );
            let oom = |_| SurfaceError::OutOfMemory { nodes: count };
            let mut nodes = series.sample(start, spacing, count).map_err(oom)?;
            if run_in > 0.0 {
                for (j, n) in nodes.iter_mut().enumerate() {
                    *n = fade_in(*n, (j as f64 * spacing) / run_in, run_in);
                }
            } else {
                let r0 = nodes[0].0;
                for n in &mut nodes {
                    n.0 -= r0;
                }
            }
            QuinticGrid::new(start, spacing, &nodes).map_err(oom)
        };
        let alignment = match spectrum.alignment().filter(|_| sampling.alignment) {
            Some(lateral) => Some((
                grid(&lateral, 2)?,
                match sampling.rails {
                    Rails::Independent => Some(grid(&lateral, 3)?),
                    Rails::Identical => None,
                },
            )),
            None => None,
        };
        Ok(Profile::Sampled {
            left: grid(&spectrum, 0)?,
            right: match sampling.rails {
                Rails::Independent => Some(grid(&spectrum, 1)?),
                Rails::Identical => None,
            },
            alignment,
        })
    }

    /// The power-law series sampled over one period [0, L_c] plus one
    /// interval (so x mod L_c rounded up to L_c still interpolates), with
    /// the spacing dividing L_c exactly: aᵢ cos(iΩ₁x − θᵢ) − r₀ by the
    /// rotation sampler of [`SpectralSeries::sample`]. Cost 32 N² multiply-adds
    /// once (`limits.profile_work` bounds it).
    fn period_grid(
        fundamental: f64,
        terms: &[(f64, f64)],
        offset: f64,
        period: f64,
    ) -> Result<QuinticGrid, SurfaceError> {
        let count = power_law_grid_nodes(terms.len());
        let oom = |_| SurfaceError::OutOfMemory { nodes: count };
        let spacing = period / (count - 2) as f64;
        let series = SpectralSeries::from_terms(
            terms
                .iter()
                .enumerate()
                .map(|(i, &(a_cos, a_sin))| {
                    let amplitude = a_cos.hypot(a_sin);
                    ((i + 1) as f64 * fundamental, amplitude, -a_sin.atan2(a_cos))
                })
                .collect(),
        );
        let mut nodes = series.sample(0.0, spacing, count).map_err(oom)?;
        for node in &mut nodes {
            node.0 -= offset;
        }
        QuinticGrid::new(0.0, spacing, &nodes).map_err(oom)
    }

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
mod tests {
    use super::*;

    /// The power-law period grid against the series summed exactly
    /// (`random_at`) at 4000 points over two periods: the largest error of
    /// r, r′ and r″, each relative to the largest |value| of the series.
    /// Measured 2026-11-23 (N = 312, L_c = 156 m, the plate paper's
    /// sampling): r 1.7e-11, r′ 5.6e-9, r″ 3.2e-7; bounds at 6× those.
    #[test]
    fn random_grid_follows_the_series() {
        let surface = Surface::Random {
            class: None,
            coefficient: 16e-6,
            sampling_length: 156.0,
            terms: 312,
            seed: 7,
        };
        let profile = Profile::build(&surface, 100.0).unwrap();
        let Profile::Random {
            fundamental,
            ref terms,
            offset,
            ..
        } = profile
        else {
            panic!("a random profile");
        };
        let points: Vec<f64> = (0..4000)
            .map(|i| 2.0 * 156.0 * (i as f64 + 0.37) / 4000.0)
            .collect();
        let exact: Vec<Triple> = points
            .iter()
            .map(|&x| Profile::random_at(fundamental, terms, offset, x))
            .collect();
        let grid: Vec<Triple> = points
            .iter()
            .map(|&x| profile.elevation_slope_curvature(x))
            .collect();
        let relative = |pick: fn(&Triple) -> f64| {
            let scale = exact.iter().map(|t| pick(t).abs()).fold(0.0, f64::max);
            let error = exact
                .iter()
                .zip(&grid)
                .map(|(e, g)| (pick(e) - pick(g)).abs())
                .fold(0.0, f64::max);
            error / scale
        };
        let (r, slope, curvature) = (relative(|t| t.0), relative(|t| t.1), relative(|t| t.2));
        eprintln!("grid errors: r {r:.2e}, r' {slope:.2e}, r'' {curvature:.2e}");
        assert!(r <= 1e-10, "r {r:e}");
        assert!(slope <= 3.5e-8, "r' {slope:e}");
        assert!(curvature <= 2e-6, "r'' {curvature:e}");
    }

    #[test]
    fn harmonic_profile_starts_at_entrance() {
        let p = Profile::build(
            &Surface::Harmonic {
                amplitude: 0.003,
                wavelength: 1.5,
                phase: 0.5,
                direction: TrackDirection::Vertical,
            },
            10.0,
        )
        .unwrap();
        let p = |x| p.elevation(x);
        assert_eq!(p(-1.0), 0.0);
        assert!((p(0.0) - 0.003 * 0.5f64.sin()).abs() < 1e-15);
        assert!((p(1.5) - p(0.0)).abs() < 1e-15);
        assert!((p(0.375 - 0.5 / (2.0 * PI) * 1.5) - 0.003).abs() < 1e-12);
    }
}
