//! Resolving `surface`: the roughness class or coefficient and the
//! sampling of the power-law series, the spectra's bands, the measured
//! profile's file and the shapes' parameters; then, once the vehicles are
//! known, whether the profile reaches every position the wheels travel
//! ([`reach`]).

use std::sync::Arc;

use super::budget::Budget;
use super::checker::Checker;
use super::raw;
use crate::scene::default_terms;
use crate::scene::grid_nodes;
use crate::scene::{Rails, RoughnessClass};
use crate::scene::{Sampling, Surface, Vehicle};

mod measured;
mod plausible;
mod reach;
pub(crate) use self::plausible::check_lengths;
pub(crate) use self::reach::*;

/// Shortest wavelength the default series resolves, m.
pub const DEFAULT_SHORTEST_WAVELENGTH: f64 = 0.5;
/// Default sampling length L_c of the plate paper's random road, in bridge
/// lengths (the series repeats with period L_c).
pub const DEFAULT_SAMPLING_LENGTHS: f64 = 2.0;
/// Largest number of series terms.
pub const MAX_TERMS: usize = 1_000_000;

impl RoughnessClass {
    /// A_r of the class, m³/cycle: the geometric mean of its range (the plate
    /// paper's Table 5 after its ref. [31]: very good 2–8, good 8–32, average
    /// 32–128, poor 128–512, very poor 512–2048, all × 1e-6 m³/cycle).
    pub fn coefficient(self) -> f64 {
        match self {
            RoughnessClass::VeryGood => 4e-6,
            RoughnessClass::Good => 16e-6,
            RoughnessClass::Average => 64e-6,
            RoughnessClass::Poor => 256e-6,
            RoughnessClass::VeryPoor => 1024e-6,
        }
    }

    /// The class's name as written in the format.
    pub fn name(self) -> &'static str {
        match self {
            RoughnessClass::VeryGood => "very_good",
            RoughnessClass::Good => "good",
            RoughnessClass::Average => "average",
            RoughnessClass::Poor => "poor",
            RoughnessClass::VeryPoor => "very_poor",
        }
    }
}

/// Resolves a random profile over a bridge of length `bridge_length` (m).
pub(crate) fn resolve_random(
    class: Option<RoughnessClass>,
    coefficient: Option<f64>,
    sampling_length: Option<f64>,
    terms: Option<usize>,
    seed: Option<u64>,
    bridge_length: f64,
    ck: &mut Checker<'_>,
) -> Surface {
    let coefficient = match (class, coefficient) {
        // The resolved scenario writes both; they must agree.
        (Some(c), Some(a)) if a == c.coefficient() => a,
        (Some(c), Some(a)) => {
            ck.error(
                "surface.coefficient",
                format!(
                    "give the roughness `class` or its `coefficient`, not both: class `{}` has \
                     A_r = {:e} m³/cycle, not {a:e}",
                    c.name(),
                    c.coefficient()
                ),
            );
            0.0
        }
        (Some(c), None) => c.coefficient(),
        (None, Some(a)) => {
            ck.non_negative("surface.coefficient", a, "roughness coefficient");
            a
        }
        (None, None) => {
            ck.error(
                "surface",
                "a random surface needs a roughness `class` (very_good … very_poor) or a \
                 `coefficient` A_r (m³/cycle)",
            );
            0.0
        }
    };
    // The default needs the bridge's length: not checked without a bridge.
    if sampling_length.is_some() || !ck.bridge_unknown {
        let sampling_length = sampling_length.unwrap_or(DEFAULT_SAMPLING_LENGTHS * bridge_length);
        ck.positive(
            "surface.sampling_length",
            sampling_length,
            "sampling length",
        );
    }
    let sampling_length = sampling_length.unwrap_or(DEFAULT_SAMPLING_LENGTHS * bridge_length);
    let terms = terms.unwrap_or_else(|| {
        ((sampling_length / DEFAULT_SHORTEST_WAVELENGTH).round() as usize).clamp(1, MAX_TERMS)
    });
    if !(1..=MAX_TERMS).contains(&terms) {
        ck.error(
            "surface.terms",
            format!("the series needs between 1 and {MAX_TERMS} terms, got {terms}"),
        );
    }
    Surface::Random {
        class,
        coefficient,
        sampling_length,
        terms,
        seed: seed.unwrap_or(1),
    }
}

/// Resolves the `surface` section (`None`: smooth) and checks its
/// elevations ([`plausible::check_elevations`]; its lengths are checked
/// once the grid and the time step are: [`check_lengths`]). `bridge_length`
/// in m.
pub(crate) fn resolve_surface(
    raw: Option<&raw::SurfaceRaw>,
    bridge_length: f64,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Surface {
    let surface = resolve_kind(raw, bridge_length, budget, ck);
    plausible::check_elevations(&surface, ck);
    surface
}

/// The surface of the section as written, defaults filled in.
fn resolve_kind(
    raw: Option<&raw::SurfaceRaw>,
    bridge_length: f64,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Surface {
    use raw::SurfaceRaw as R;
    let Some(raw) = raw else {
        return Surface::Smooth;
    };
    match raw {
        R::Smooth => Surface::Smooth,
        R::Harmonic {
            amplitude,
            wavelength,
            phase,
            direction,
        } => {
            ck.non_negative("surface.amplitude", *amplitude, "roughness amplitude");
            ck.positive("surface.wavelength", *wavelength, "roughness wavelength");
            Surface::Harmonic {
                amplitude: *amplitude,
                wavelength: *wavelength,
                phase: phase.unwrap_or(0.0),
                direction: direction.unwrap_or_default(),
            }
        }
        R::Random {
            class,
            coefficient,
            sampling_length,
            terms,
            seed,
        } => resolve_random(
            *class,
            *coefficient,
            *sampling_length,
            *terms,
            *seed,
            bridge_length,
            ck,
        ),
        R::Fra {
            class,
            shortest_wavelength,
            longest_wavelength,
            terms,
            seed,
            alignment,
            rails,
            run_in,
        } => {
            if !(1..=6).contains(class) {
                ck.error(
                    "surface.class",
                    format!("FRA track classes are 1 (worst) to 6 (best), got {class}"),
                );
            }
            let mut sampling = resolve_sampling(
                (*shortest_wavelength, *longest_wavelength),
                RAIL_BAND,
                *terms,
                *seed,
                *rails,
                *run_in,
                ck,
            );
            sampling.alignment = alignment.unwrap_or(false);
            Surface::Fra {
                class: *class,
                sampling,
            }
        }
        R::German {
            interference,
            shortest_wavelength,
            longest_wavelength,
            terms,
            seed,
            alignment,
            rails,
            run_in,
        } => Surface::German {
            interference: *interference,
            sampling: Sampling {
                alignment: alignment.unwrap_or(false),
                ..resolve_sampling(
                    (*shortest_wavelength, *longest_wavelength),
                    RAIL_BAND,
                    *terms,
                    *seed,
                    *rails,
                    *run_in,
                    ck,
                )
            },
        },
        R::Iso8608 {
            class,
            shortest_wavelength,
            longest_wavelength,
            terms,
            seed,
            rails,
            run_in,
        } => Surface::Iso8608 {
            class: *class,
            sampling: resolve_sampling(
                (*shortest_wavelength, *longest_wavelength),
                ROAD_BAND,
                *terms,
                *seed,
                *rails,
                *run_in,
                ck,
            ),
        },
        R::Measured { file } => {
            let data = match super::data_files::locate(file, "the measured profile", ck) {
                Ok(data) => data,
                Err(message) => {
                    ck.error("surface.file", message);
                    return Surface::Smooth;
                }
            };
            match measured::read(&data, budget, ck) {
                Some(profile) => Surface::Measured {
                    file: data.shown,
                    profile: Arc::new(profile),
                },
                None => Surface::Smooth,
            }
        }
        R::Ramp {
            start,
            length,
            height,
            direction,
        } => {
            ck.positive("surface.length", *length, "ramp length");
            Surface::Ramp {
                start: *start,
                length: *length,
                height: *height,
                direction: direction.unwrap_or_default(),
            }
        }
        R::Step {
            position,
            height,
            direction,
        } => Surface::Step {
            position: *position,
            height: *height,
            direction: direction.unwrap_or_default(),
        },
        R::Bump {
            start,
            length,
            height,
            direction,
        } => {
            ck.positive("surface.length", *length, "bump length");
            ck.positive(
                "surface.height",
                *height,
                "bump height (use `type: dip` for a depression)",
            );
            Surface::Bump {
                start: *start,
                length: *length,
                height: *height,
                direction: direction.unwrap_or_default(),
            }
        }
        R::Dip {
            start,
            length,
            depth,
            direction,
        } => {
            ck.positive("surface.length", *length, "dip length");
            ck.positive("surface.depth", *depth, "dip depth");
            Surface::Bump {
                start: *start,
                length: *length,
                height: -*depth,
                direction: direction.unwrap_or_default(),
            }
        }
        R::PiecewiseLinear { points, direction } => {
            if points.len() < 2 {
                ck.error(
                    "surface.points",
                    format!(
                        "a piecewise-linear profile needs at least two [x, r] points, got {}",
                        points.len()
                    ),
                );
            }
            for (i, w) in points.windows(2).enumerate() {
                if w[1][0] <= w[0][0] {
                    ck.error(
                        &format!("surface.points[{}]", i + 1),
                        format!(
                            "x must increase strictly along the points: {} follows {}",
                            w[1][0], w[0][0]
                        ),
                    );
                    break;
                }
            }
            Surface::PiecewiseLinear {
                points: points.clone(),
                direction: direction.unwrap_or_default(),
            }
        }
    }
}

/// Default wavelength band of the rail spectra, m: 1–80 m, the waves a rail
/// car's suspension and the bridge respond to (shorter ones are filtered by
/// the contact patch and rail bending, longer ones pass as quasi-static
/// gradients).
pub const RAIL_BAND: (f64, f64) = (1.0, 80.0);
/// Default wavelength band of ISO 8608 roads, m: 0.5–100 m (ISO 8608 needs
/// no lower spatial frequency than 0.01 cycle/m for on-road vehicles; waves
/// below 0.5 m are enveloped by the tyre).
pub const ROAD_BAND: (f64, f64) = (0.5, 100.0);

/// Band, terms, seed and rails of a spectral profile.
fn resolve_sampling(
    (shortest, longest): (Option<f64>, Option<f64>),
    (default_short, default_long): (f64, f64),
    terms: Option<usize>,
    seed: Option<u64>,
    rails: Option<Rails>,
    run_in: Option<f64>,
    ck: &mut Checker<'_>,
) -> Sampling {
    let shortest = shortest.unwrap_or(default_short);
    let longest = longest.unwrap_or(default_long);
    // The default run-in is the band's longest wavelength: the fade's own
    // slope, at most 1.875 r/L for the quintic smoothstep, then stays below
    // 0.3 × the slope 2π r/λ_max of the longest wave it fades in, so the
    // fade adds no excitation the track does not already carry.
    let run_in = run_in.unwrap_or(if longest.is_finite() && longest > 0.0 {
        longest
    } else {
        0.0
    });
    ck.non_negative("surface.run_in", run_in, "run-in length");
    ck.positive(
        "surface.shortest_wavelength",
        shortest,
        "shortest wavelength",
    );
    ck.positive("surface.longest_wavelength", longest, "longest wavelength");
    let band_ok = shortest > 0.0 && longest > shortest;
    if shortest > 0.0 && longest > 0.0 && !band_ok {
        let at = if ck.has("surface.longest_wavelength") {
            "surface.longest_wavelength"
        } else {
            "surface.shortest_wavelength"
        };
        ck.error(
            at,
            format!(
                "the wavelength band is empty: the longest wavelength ({longest} m) must exceed \
                 the shortest ({shortest} m)"
            ),
        );
    }
    let terms = terms.unwrap_or_else(|| {
        if band_ok {
            default_terms(shortest, longest).min(MAX_TERMS)
        } else {
            1
        }
    });
    if !(1..=MAX_TERMS).contains(&terms) {
        ck.error(
            "surface.terms",
            format!("the series needs between 1 and {MAX_TERMS} terms, got {terms}"),
        );
    }
    Sampling {
        shortest_wavelength: shortest,
        longest_wavelength: longest,
        terms,
        seed: seed.unwrap_or(1),
        rails: rails.unwrap_or(Rails::Identical),
        run_in,
        alignment: false,
    }
}
