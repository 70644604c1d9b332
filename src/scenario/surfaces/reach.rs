//! The surface against the vehicles, once they are known: where they start
//! behind a spectrum's run-in, the features their speed and the time step
//! resolve, the lateral followers, and whether the profile reaches every
//! position the wheels travel.

use super::*;

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
