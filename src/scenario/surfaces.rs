//! Resolving `surface`: the roughness class or coefficient and the
//! sampling of the power-law series, the spectra's bands, the measured
//! profile's file and the shapes' parameters; then, once the vehicles are
//! known, whether the profile reaches every position the wheels travel.

use std::sync::Arc;

use super::budget::Budget;
use super::checker::Checker;
use super::raw;
use crate::scene::default_terms;
use crate::scene::grid_nodes;
use crate::scene::{Rails, RoughnessClass};
use crate::scene::{Sampling, Surface, Vehicle};

mod measured;

/// Shortest wavelength the default series resolves, m.
pub const DEFAULT_SHORTEST_WAVELENGTH: f64 = 0.5;
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
        let sampling_length = sampling_length.unwrap_or(2.0 * bridge_length);
        ck.positive(
            "surface.sampling_length",
            sampling_length,
            "sampling length",
        );
    }
    let sampling_length = sampling_length.unwrap_or(2.0 * bridge_length);
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

/// Resolves the `surface` section (`None`: smooth). `bridge_length` in m.
pub(crate) fn resolve_surface(
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

/// The run-in (m) the vehicles must start behind: that of the scene's track
/// or road spectrum, and, when `study` sweeps FRA classes over a scene
/// without one, the run-in those take (the rail band's default,
/// [`RAIL_BAND`]'s longest wavelength); 0 if there is none.
pub(crate) fn placement_run_in(surface: &Surface, study: Option<&raw::StudyRaw>) -> f64 {
    let own = surface.spectrum().map_or(0.0, |(_, s)| s.run_in);
    let entries = match study {
        Some(raw::StudyRaw::MonteCarlo(m)) => m.roughness.as_deref(),
        Some(raw::StudyRaw::SpeedSweep(s)) => s.roughness.as_deref(),
        _ => None,
    };
    let sweeps_fra = entries.is_some_and(|e| e.iter().any(|r| r.fra_class().is_some()));
    if sweeps_fra && surface.spectrum().is_none() {
        own.max(RAIL_BAND.1)
    } else {
        own
    }
}

/// Places every vehicle the file does not place (neither `entry_time` nor
/// `start_position`) with its front axle at x = −`run_in` (m), as
/// `start_position: −run_in` would: every wheel starts on level track behind
/// the fade-in of a track or road spectrum and meets it smoothly. A braking
/// vehicle that would stop before covering the run-in keeps its place (the
/// fade then starts under its front axle, [`crate::surface::fade_start`]).
pub(crate) fn place_before_run_in(vehicles: &mut [Vehicle], run_in: f64, ck: &Checker<'_>) {
    if !(run_in > 0.0 && run_in.is_finite()) {
        return;
    }
    for (i, vehicle) in vehicles.iter_mut().enumerate() {
        let at = format!("vehicles[{i}]");
        if ck.has(&format!("{at}.entry_time")) || ck.has(&format!("{at}.start_position")) {
            continue;
        }
        if let Some(t) =
            crate::scene::motion::time_to_cover(vehicle.speed(), vehicle.acceleration(), run_in)
        {
            vehicle.set_entry_time(t);
        }
    }
}

/// Refuses surface features shorter than the distance `step_travel` (m) the
/// fastest wheel covers in one time step `time_step` (s) at `speed` (m/s):
/// the wheels see the surface only at the steps, so a bump or dip that
/// short is stepped over (the run equals a smooth surface), a ramp acts as
/// a step with a slope of up to height/length at a step inside it, and a
/// harmonic wave shorter than two steps' travel is seen as a longer alias
/// (Nyquist). Each is refused at its own key.
pub(crate) fn check_features(surface: &Surface, speed: f64, time_step: f64, ck: &mut Checker<'_>) {
    let step_travel = speed * time_step;
    if !(step_travel > 0.0 && step_travel.is_finite()) {
        return;
    }
    let advice = |needed: f64, length: f64| {
        format!(
            "the {step_travel:.4e} m a wheel travels in one time step ({speed:.4} m/s × \
             {time_step:e} s): the wheels, which see the surface only at the steps, would miss \
             it; lengthen it or set `solver.time_step` to at most {:.4e} s",
            length / (needed * speed)
        )
    };
    let mut short = |path: &str, what: String, length: f64, needed: f64| {
        if length > 0.0 && length < needed * step_travel {
            let times = if needed == 1.0 { "" } else { "twice " };
            ck.error(
                path,
                format!("{what} is shorter than {times}{}", advice(needed, length)),
            );
        }
    };
    match *surface {
        Surface::Bump { length, height, .. } => {
            let what = if height < 0.0 { "a dip" } else { "a bump" };
            short(
                "surface.length",
                format!("{what} {length:e} m long"),
                length,
                1.0,
            );
        }
        Surface::Ramp { length, .. } => short(
            "surface.length",
            format!("a ramp {length:e} m long"),
            length,
            1.0,
        ),
        Surface::Harmonic { wavelength, .. } => short(
            "surface.wavelength",
            format!("a wavelength of {wavelength:e} m"),
            wavelength,
            2.0,
        ),
        Surface::PiecewiseLinear { ref points, .. } => {
            if let Some(i) = (1..points.len()).find(|&i| {
                let d = points[i][0] - points[i - 1][0];
                d > 0.0 && d < step_travel
            }) {
                short(
                    &format!("surface.points[{i}]"),
                    format!(
                        "the segment from x = {} m to {} m ({:e} m; for a sudden change of level \
                         use `type: step`)",
                        points[i - 1][0],
                        points[i][0],
                        points[i][0] - points[i - 1][0]
                    ),
                    points[i][0] - points[i - 1][0],
                    1.0,
                );
            }
        }
        _ => {}
    }
}

/// Refuses lateral track geometry given explicitly (`direction: lateral`)
/// where no vehicle can follow it: only a `train_3d`'s wheelsets have a
/// lateral DOF at the rail, every other vehicle would run as on straight
/// track and the shape would be silently ignored.
pub(crate) fn check_lateral_followers(
    surface: &Surface,
    vehicles: &[Vehicle],
    ck: &mut Checker<'_>,
) {
    let explicit = !matches!(surface, Surface::Measured { .. }) && surface.spectrum().is_none();
    if explicit
        && surface.has_lateral_geometry()
        && !vehicles.iter().any(|v| matches!(v, Vehicle::Train3d(_)))
    {
        ck.error(
            "surface.direction",
            "a lateral profile is the track's alignment, which only a `train_3d`'s wheelsets \
             follow; no vehicle of this scene has a lateral DOF at the rail (use \
             `type: train_3d`, or `direction: vertical`)",
        );
    }
}

/// Where the wheels travel, m from the entrance, as
/// [`crate::model::Model`] will run it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Travel {
    /// The rearmost wheel at the start.
    pub start: f64,
    /// The farthest front axle at the end of the run (the last exit plus
    /// the free vibration).
    pub end: f64,
}

/// Checks that the profile serves the wheels' travel `(start, end)` (m):
/// a sampled grid's size fits the budget, a measured profile covers it.
pub(crate) fn check_reach(
    surface: &Surface,
    travel: Travel,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> bool {
    let Travel { start, end, .. } = travel;
    if let Some((_, sampling)) = surface.spectrum() {
        // The grid runs from the fade's start (at −run_in at the earliest).
        let nodes = grid_nodes(end + sampling.run_in, sampling.shortest_wavelength);
        let rails = if sampling.rails == Rails::Independent {
            2.0
        } else {
            1.0
        } * if sampling.alignment { 2.0 } else { 1.0 };
        let work = nodes * rails * sampling.terms as f64;
        // A run-in written longer than the ride is the cause of a large
        // grid; otherwise the grid's spacing is.
        let grid_path = if ck.has("surface.run_in") && sampling.run_in > end.max(0.0) {
            "surface.run_in"
        } else {
            "surface.shortest_wavelength"
        };
        return budget.check(
            ck,
            grid_path,
            "profile_points",
            &format!(
                "grid nodes of the sampled profile ({} per shortest wavelength over the {:.1} m \
                 from the run-in's start to where the wheels reach, per rail)",
                crate::scene::NODES_PER_WAVELENGTH,
                end + sampling.run_in
            ),
            nodes * rails,
        ) && budget.check(
            ck,
            if ck.has("surface.terms") {
                "surface.terms"
            } else {
                "surface.shortest_wavelength"
            },
            "profile_work",
            "multiply-adds of sampling the profile's series on its grid (terms × grid nodes × rails)",
            work,
        );
    }
    if let Surface::Random { terms, .. } = *surface {
        // The power-law series is sampled over one period (32 nodes per
        // shortest wavelength), whatever the wheels' travel.
        let nodes = crate::scene::power_law_grid_nodes(terms) as f64;
        let path = if ck.has("surface.terms") {
            "surface.terms"
        } else {
            "surface.sampling_length"
        };
        return budget.check(
            ck,
            path,
            "profile_points",
            "grid nodes of the power-law profile (32 per shortest wavelength over one period)",
            nodes,
        ) && budget.check(
            ck,
            path,
            "profile_work",
            "multiply-adds of sampling the power-law series over its period (terms × grid nodes)",
            nodes * terms as f64,
        );
    }
    if let Surface::Measured { file, profile } = surface {
        let (first, last) = (profile.x[0], profile.x[profile.x.len() - 1]);
        // A hair of slack for the rounding of start and end times.
        let slack = 1e-9 * (1.0 + end.abs() + start.abs());
        if first > start + slack || last < end - slack {
            ck.error(
                "surface.file",
                format!(
                    "{file} covers x = {first} … {last} m, but the wheels travel from x = {start:.4} m \
                     (the rearmost wheel at the start, on the approach) to x = {end:.4} m (the front \
                     axle at the end of the run, free vibration included): extend the measured \
                     profile or move the start, free vibration or speed"
                ),
            );
            return false;
        }
    }
    true
}
