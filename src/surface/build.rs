//! Building a [`Profile`] from a resolved surface: the deterministic
//! profiles as given or laid sideways, and a random spectrum sampled once
//! onto a grid (over one period for the power law).

use std::f64::consts::PI;

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

use super::interp::{CubicSpline, QuinticGrid};
use super::shapes::Shape;
use super::synth::{SpectralSeries, uniform};
use super::{
    NODES_PER_WAVELENGTH, Profile, REFERENCE_WAVENUMBER, SurfaceError, fade_in, fade_start,
    grid_nodes, power_law_grid_nodes,
};
use crate::scene::Spectrum;
use crate::scene::{Rails, Sampling, Surface, TrackDirection};

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
}
