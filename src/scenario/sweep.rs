//! A speed sweep's scenes: the vehicles at a speed, the surface of each
//! roughness entry and sample, the checks of the `study` section, and the
//! excitation the automatic defaults must cover over the whole sweep.

use super::checker::Checker;
use super::raw::{MonteCarloRaw, SpeedSweepRaw};
use super::surfaces::{DEFAULT_SHORTEST_WAVELENGTH, MAX_TERMS, RAIL_BAND};
use super::vehicles::MAX_SPEED;
use crate::scene::default_terms;
use crate::scene::{
    Bridge, MonteCarlo, Sampling, SpeedSweep, Study, Surface, SweepRoughness, Vehicle,
};

/// Most values on the speed grid.
pub const MAX_SPEEDS: usize = 500;

/// `vehicles` with every speed set to `speed` (m/s); start positions and
/// accelerations are kept. A vehicle that accelerates or brakes takes
/// `speed` as its speed at t = 0 and keeps its acceleration, so a sweep of
/// a braking train sweeps the speed it starts braking from. One that would
/// stop before the entrance at `speed` keeps its old entry time
/// ([`stops_before_entry`] refuses such a sweep when resolving).
pub fn with_speed(vehicles: &[Vehicle], speed: f64) -> Vec<Vehicle> {
    // Each vehicle keeps its start position x₀ (a vehicle placed before a
    // track's run-in must stay there at every speed), so its entry time
    // follows the speed.
    fn set(vehicle_speed: &mut f64, entry_time: &mut f64, acceleration: f64, speed: f64) {
        if *vehicle_speed > 0.0 && speed > 0.0 {
            if acceleration == 0.0 {
                // The start position first, as resolution computes the
                // entry time from it (t = −x₀ / v), so a point equals the
                // single run.
                let start = -*entry_time * *vehicle_speed;
                *entry_time = -start / speed;
            } else {
                let start = crate::scene::motion::Motion {
                    speed: *vehicle_speed,
                    acceleration,
                    entry_time: *entry_time,
                }
                .position(0.0);
                if let Some(t) =
                    crate::scene::motion::time_to_cover(speed, acceleration, (-start).max(0.0))
                {
                    *entry_time = t;
                }
            }
        }
        *vehicle_speed = speed;
    }
    let mut out = vehicles.to_vec();
    for vehicle in &mut out {
        match vehicle {
            Vehicle::MovingForce(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
            Vehicle::Oscillator(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
            Vehicle::H20Truck(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
            Vehicle::RailCar(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
            Vehicle::Train(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
            Vehicle::Train3d(v) => set(&mut v.speed, &mut v.entry_time, v.acceleration, speed),
        }
    }
    out
}

/// Whether every vehicle, started at `speed` (m/s) from its start position
/// with its own acceleration, reaches the bridge entrance (a braking one may
/// stop before at a low speed). `Some(vehicle index)` of the first that
/// does not.
pub fn stops_before_entry(vehicles: &[Vehicle], speed: f64) -> Option<usize> {
    vehicles.iter().position(|v| {
        let a = v.acceleration();
        if a >= 0.0 {
            return false;
        }
        let start = v.motion().position(0.0);
        crate::scene::motion::time_to_cover(speed, a, (-start).max(0.0)).is_none()
    })
}

/// The vehicles of the sweep's fastest and slowest runs (the scene's own
/// vehicles twice when `study` is not a speed sweep).
pub(crate) fn extreme_vehicles(
    study: Option<&Study>,
    vehicles: &[Vehicle],
) -> (Vec<Vehicle>, Vec<Vehicle>) {
    match study {
        Some(Study::SpeedSweep(sweep)) => {
            let (slow, fast) = sweep.speed_range();
            (with_speed(vehicles, fast), with_speed(vehicles, slow))
        }
        Some(Study::MonteCarlo(mc)) if mc.speeds.is_some() => {
            let (slow, fast) = mc.speed_range().expect("speeds given");
            (with_speed(vehicles, fast), with_speed(vehicles, slow))
        }
        _ => (vehicles.to_vec(), vehicles.to_vec()),
    }
}

/// Whether the surface of `entry` (`None`: the scene's own) is random.
pub fn is_random(base: &Surface, entry: Option<SweepRoughness>) -> bool {
    match entry {
        None => base.is_random(),
        Some(e) => e.is_random(),
    }
}

/// The label of `entry` in tables and plots: its name, or for the scene's
/// own surface `smooth`, `harmonic`, its class or `random`.
pub fn label(base: &Surface, entry: Option<SweepRoughness>) -> String {
    match (entry, base) {
        (Some(e), _) => e.name().to_string(),
        (None, base) => base.label(),
    }
}

/// The surface of roughness entry `entry` (`None`: the scene's own) for
/// sample `k` (from 0) over a bridge of length `bridge_length` (m): a random
/// profile's seed is advanced by `k`; a class takes the sampling length,
/// terms and seed of the scene's random surface, or the defaults (twice the
/// bridge length, one term per 0.5 m, seed 1).
pub fn surface(
    base: &Surface,
    entry: Option<SweepRoughness>,
    k: usize,
    bridge_length: f64,
) -> Surface {
    let advance = |seed: u64| seed.wrapping_add(k as u64);
    let Some(entry) = entry else {
        return match base.seed() {
            Some(seed) => base.reseeded(advance(seed)),
            None => base.clone(),
        };
    };
    if let Some(class) = entry.fra_class() {
        // The scene's own spectral sampling (band, terms, rails, run-in) if
        // it has one, else the rail defaults; the seed advanced by `k`.
        let mut sampling = base.spectrum().map_or(
            Sampling {
                shortest_wavelength: RAIL_BAND.0,
                longest_wavelength: RAIL_BAND.1,
                terms: default_terms(RAIL_BAND.0, RAIL_BAND.1).min(MAX_TERMS),
                seed: 1,
                rails: crate::scene::Rails::Identical,
                // The default run-in: the band's longest wavelength.
                run_in: RAIL_BAND.1,
                alignment: false,
            },
            |(_, sampling)| sampling,
        );
        sampling.seed = advance(sampling.seed);
        return Surface::Fra { class, sampling };
    }
    let Some(class) = entry.class() else {
        return Surface::Smooth;
    };
    let (sampling_length, terms, seed) = match *base {
        Surface::Random {
            sampling_length,
            terms,
            seed,
            ..
        } => (sampling_length, terms, seed),
        _ => {
            let length = 2.0 * bridge_length;
            let terms =
                ((length / DEFAULT_SHORTEST_WAVELENGTH).round() as usize).clamp(1, MAX_TERMS);
            (length, terms, 1)
        }
    };
    Surface::Random {
        class: Some(class),
        coefficient: class.coefficient(),
        sampling_length,
        terms,
        seed: advance(seed),
    }
}

/// The surfaces of a `roughness` list (`None`: the scene's own only).
pub fn entries_of(list: Option<&[SweepRoughness]>) -> Vec<Option<SweepRoughness>> {
    match list {
        None => vec![None],
        Some(list) => list.iter().copied().map(Some).collect(),
    }
}

/// Most sample histories a Monte Carlo plot draws in grey.
pub const MAX_SHOWN: usize = 20;
/// Sample histories a Monte Carlo plot draws in grey by default.
pub const DEFAULT_SHOWN: usize = 5;

/// Checks the `study` section of a Monte Carlo study and fills its
/// defaults; refuses a study with nothing random to sample.
pub(crate) fn resolve_monte_carlo(
    raw: &MonteCarloRaw,
    surface: &Surface,
    ck: &mut Checker<'_>,
) -> MonteCarlo {
    if raw.samples == 0 {
        ck.error("study.samples", "`samples` must be at least 1, got 0");
    }
    let speeds = raw.speeds.as_ref().map(|g| g.in_m_s());
    if let Some(grid) = &speeds {
        check_speeds(ck, grid);
    }
    check_roughness(ck, raw.roughness.as_deref());
    match &raw.roughness {
        None if !surface.is_random() => ck.error(
            "study",
            "a Monte Carlo study samples a random surface, but the scene's `surface` is not random; give `surface: {type: random, ...}` or a `roughness` list of classes in the study",
        ),
        None => {}
        Some(list) => {
            for (i, entry) in list.iter().enumerate() {
                if !entry.is_random() {
                    ck.error(
                        &format!("study.roughness[{i}]"),
                        format!(
                            "`{}` is not random: a Monte Carlo study samples random surfaces only",
                            entry.name()
                        ),
                    );
                }
            }
        }
    }
    let show = raw.show.unwrap_or(DEFAULT_SHOWN);
    if show > MAX_SHOWN {
        ck.error(
            "study.show",
            format!("`show` draws at most {MAX_SHOWN} sample histories, got {show}"),
        );
    }
    MonteCarlo {
        samples: raw.samples,
        seed: raw.seed.unwrap_or(1),
        speeds,
        roughness: raw.roughness.clone(),
        show: show.min(raw.samples),
    }
}

/// Checks the `study` section of a speed sweep and fills its defaults.
pub(crate) fn resolve(
    raw: &SpeedSweepRaw,
    bridge: &Bridge,
    surface: &Surface,
    ck: &mut Checker<'_>,
) -> SpeedSweep {
    let grid = &raw.speeds.in_m_s();
    check_speeds(ck, grid);
    check_roughness(ck, raw.roughness.as_deref());
    let entries: Vec<Option<SweepRoughness>> = match &raw.roughness {
        None => vec![None],
        Some(list) => list.iter().copied().map(Some).collect(),
    };
    let samples = raw.samples.unwrap_or(1);
    if samples == 0 {
        ck.error("study.samples", "`samples` must be at least 1, got 0");
    } else if samples > 1 && !entries.iter().any(|&e| is_random(surface, e)) {
        ck.error(
            "study.samples",
            format!(
                "{samples} samples of a deterministic surface are the same run; `samples` applies to random surfaces (a roughness class)"
            ),
        );
    }
    // The number of runs is checked against `limits.study_points` once the
    // study is resolved (see `study_points`).
    let spans = bridge.spans();
    let longest = spans
        .iter()
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |best, (i, &l)| {
            if l > best.1 { (i, l) } else { best }
        })
        .0;
    let span = raw.span.unwrap_or(longest + 1);
    if !(1..=spans.len()).contains(&span) {
        ck.error(
            "study.span",
            format!(
                "span {span} does not exist; the bridge has {} span{} (counted from 1)",
                spans.len(),
                if spans.len() == 1 { "" } else { "s" }
            ),
        );
    }
    let girder = raw.girder.unwrap_or(1);
    let lines = match bridge {
        Bridge::Beam(_) | Bridge::FeImport(_) => 1,
        Bridge::Plate(p) => p.girder_lines.len(),
    };
    if !(1..=lines).contains(&girder) {
        let message = match bridge {
            Bridge::Beam(_) | Bridge::FeImport(_) => {
                format!("girder line {girder} does not exist; a beam or track has only line 1")
            }
            Bridge::Plate(_) => format!(
                "girder line {girder} does not exist; the deck has {lines} (`bridge.girder_lines`, counted from 1)"
            ),
        };
        ck.error("study.girder", message);
    }
    SpeedSweep {
        speeds: grid.clone(),
        roughness: raw.roughness.clone(),
        samples,
        span,
        girder,
    }
}

/// Checks a study's speed grid (m/s): positive, ordered, below the speed
/// limit, 1 to [`MAX_SPEEDS`] values.
fn check_speeds(ck: &mut Checker<'_>, grid: &crate::scene::Grid) {
    if grid.from <= 0.0 {
        ck.error(
            "study.speeds.from",
            format!("the sweep's speeds must be positive, got {}", grid.from),
        );
    }
    if grid.to < grid.from {
        ck.error(
            "study.speeds.to",
            format!("`to` ({}) is below `from` ({})", grid.to, grid.from),
        );
    } else if grid.to == grid.from && grid.count > 1 {
        ck.error(
            "study.speeds.to",
            format!(
                "{} speeds from {} to {} are all the same; raise `to` or use `count: 1`",
                grid.count, grid.from, grid.to
            ),
        );
    }
    if grid.to > MAX_SPEED {
        ck.error(
            "study.speeds.to",
            format!("a speed of {} m/s is above {MAX_SPEED} m/s", grid.to),
        );
    }
    if !(1..=MAX_SPEEDS).contains(&grid.count) {
        ck.error(
            "study.speeds.count",
            format!(
                "a speed sweep needs 1 to {MAX_SPEEDS} speeds, got {}",
                grid.count
            ),
        );
    }
}

/// Checks a study's `roughness` list: not empty, no entry twice.
fn check_roughness(ck: &mut Checker<'_>, list: Option<&[SweepRoughness]>) {
    if let Some(list) = list {
        if list.is_empty() {
            ck.error(
                "study.roughness",
                "`roughness` needs at least one surface (or leave it out to sweep the scene's own)",
            );
        }
        // A set of the names seen keeps this linear in the list's length.
        let mut seen = std::collections::HashSet::new();
        for (i, entry) in list.iter().enumerate() {
            if !seen.insert(*entry) {
                ck.error(
                    &format!("study.roughness[{i}]"),
                    format!("`{}` is listed twice", entry.name()),
                );
            }
        }
    }
}

/// Runs a study makes: speeds × (samples per random surface, one per
/// deterministic one) for a sweep, the grid's points for a separation map.
/// In `f64`, so no count can wrap.
pub fn study_points(study: &Study, base: &Surface) -> f64 {
    match study {
        Study::SpeedSweep(sweep) => {
            let entries: Vec<Option<SweepRoughness>> = match &sweep.roughness {
                None => vec![None],
                Some(list) => list.iter().copied().map(Some).collect(),
            };
            let per_speed: f64 = entries
                .iter()
                .map(|&e| {
                    if is_random(base, e) {
                        sweep.samples as f64
                    } else {
                        1.0
                    }
                })
                .sum();
            per_speed * sweep.speeds.count as f64
        }
        Study::SeparationMap {
            velocity_ratio,
            mass_ratio,
        } => velocity_ratio.count as f64 * mass_ratio.count as f64,
        Study::ResonanceCheck(check) => check.run_bound(),
        Study::MonteCarlo(mc) => {
            mc.roughness.as_ref().map_or(1.0, |l| l.len() as f64)
                * mc.speeds.as_ref().map_or(1.0, |g| g.count as f64)
                * mc.samples as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Rails;

    /// One label per FRA class (issue 40.5): a study over the scene's own
    /// `{type: fra, class: 4}` and one over `roughness: [fra4]` label their
    /// cases alike, as the `roughness` list spells the class.
    #[test]
    fn an_fra_class_has_one_label() {
        for (class, entry) in [
            (1, SweepRoughness::Fra1),
            (4, SweepRoughness::Fra4),
            (6, SweepRoughness::Fra6),
        ] {
            let own = Surface::Fra {
                class,
                sampling: Sampling {
                    shortest_wavelength: 1.0,
                    longest_wavelength: 80.0,
                    terms: 100,
                    seed: 1,
                    rails: Rails::Identical,
                    run_in: 0.0,
                    alignment: false,
                },
            };
            assert_eq!(label(&own, None), format!("fra{class}"));
            assert_eq!(label(&own, Some(entry)), label(&own, None));
        }
    }
}
