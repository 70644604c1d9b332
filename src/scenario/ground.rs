//! Resolving the `ground_motion` section: each record read, checked and
//! put on the run's clock. Problems are reported at the component's field
//! (`ground_motion[i].file` for the file's own, with the file's line in
//! the message); the file's size and its declared sample count are budgeted
//! (`limits.ground_points`) before anything is allocated per sample.

mod at2;
mod table;

pub(super) use self::table::not_a_number;

use std::collections::HashMap;
use std::sync::Arc;

use super::budget::Budget;
use super::checker::Checker;
use super::data_files::DataFile;
use super::raw::GroundMotionRaw;
use crate::scene::{AccelerationUnit, Direction, GroundRecord};
use crate::scene::{Bridge, GroundMotion};

/// Plausible sampling interval of a ground-motion record, s: strong-motion
/// accelerographs sample at 50–1000 Hz (PEER NGA records: 0.005–0.02 s),
/// synthetic records a little finer; 1 µs to 1 s brackets them with room to
/// spare. A record sampled more coarsely than 1 s does not describe an
/// earthquake's 0.1–25 Hz shaking, and a 1e300 s interval is a typing slip.
pub const SAMPLING_INTERVAL: (f64, f64) = (1e-6, 1.0);

/// Longest plausible record, s (one day, as a vehicle's entry time).
pub const RECORD_DURATION: f64 = 86_400.0;

/// A record's samples as read: times (s), accelerations (in the units),
/// the units.
type Samples = Arc<(Vec<f64>, Vec<f64>, AccelerationUnit)>;

/// Fewest bytes a sample takes in a file (`0 ` or `0,0` and a break).
const MIN_SAMPLE_BYTES: f64 = 2.0;

/// Resolves every component; those with errors are reported and left out.
pub(crate) fn resolve(
    raw: Option<&[GroundMotionRaw]>,
    bridge: Option<&Bridge>,
    vehicles_move_sideways: bool,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Vec<GroundMotion> {
    let mut out = Vec::new();
    // Each distinct file is read once; every component counts its samples
    // against `limits.ground_points`, a repeated record as often as it is
    // listed (each gets its own integrated copy).
    let mut read_once: HashMap<(std::path::PathBuf, Option<&'static str>), Samples> =
        HashMap::new();
    let mut total = 0.0;
    for (i, component) in raw.unwrap_or_default().iter().enumerate() {
        let at = format!("ground_motion[{i}]");
        let direction = component.direction.unwrap_or(Direction::Vertical);
        match direction {
            Direction::Vertical => {}
            // Without a valid bridge its lateral modes are not known.
            Direction::Lateral
                if bridge.is_none() || moves_sideways(bridge) || vehicles_move_sideways => {}
            Direction::Lateral => {
                let kind = match bridge {
                    Some(Bridge::Plate(_)) => "plate",
                    Some(Bridge::FeImport(_)) => "imported model without lateral (uy) DOFs",
                    _ => "beam (without `lateral_bending_stiffness`)",
                };
                ck.error(
                    &format!("{at}.direction"),
                    format!(
                        "a lateral ground motion needs lateral bridge modes or vehicles that move \
                         sideways (`train_3d`); the {kind} bridge is used here as a vertical model \
                         (its modes are followed up and down only) and no vehicle has lateral \
                         DOFs, so the record would have no effect"
                    ),
                );
                continue;
            }
            Direction::Longitudinal => {
                ck.error(
                    &format!("{at}.direction"),
                    "a longitudinal ground motion has no effect on these bridge models (they have \
                     no longitudinal degrees of freedom, and the supports moving together along \
                     the track only carry the vehicles with them); leave it out",
                );
                continue;
            }
        }
        let scale = component.scale.unwrap_or(1.0);
        if !scale.is_finite() {
            ck.error(
                &format!("{at}.scale"),
                format!("the scale must be a finite number, got {scale}"),
            );
            continue;
        }
        let start_time = component.start_time.unwrap_or(0.0);
        if !start_time.is_finite() {
            ck.error(
                &format!("{at}.start_time"),
                format!("the start time must be a finite number of seconds, got {start_time}"),
            );
            continue;
        }
        let data = match super::data_files::locate(&component.file, "the ground-motion record", ck)
        {
            Ok(data) => data,
            Err(message) => {
                ck.error(&format!("{at}.file"), message);
                continue;
            }
        };
        // A file listed twice is read once (its samples still count twice
        // in the budget below).
        let key = (
            data.real.clone(),
            component.units.map(AccelerationUnit::name),
        );
        let samples = match read_once.get(&key) {
            Some(samples) => samples.clone(),
            None => {
                let Some(samples) = read(&data, component.units, &at, budget, ck) else {
                    continue;
                };
                let samples = Arc::new(samples);
                read_once.insert(key, samples.clone());
                samples
            }
        };
        total += samples.0.len() as f64;
        if !budget.check(
            ck,
            &format!("{at}.file"),
            "ground_points",
            &format!(
                "samples over the ground-motion records up to ground_motion[{i}] (a record \
                 listed twice counts twice)"
            ),
            total,
        ) {
            break;
        }
        let (time, acceleration, units) = (&samples.0, &samples.1, samples.2);
        let si: Vec<f64> = acceleration.iter().map(|a| a * units.in_si()).collect();
        out.push(GroundMotion {
            file: data.shown,
            direction,
            scale,
            start_time,
            units,
            record: Arc::new(GroundRecord::new(time, &si, scale, start_time)),
        });
    }
    out
}

/// Whether the bridge has lateral degrees of freedom a lateral record can
/// shake: an imported model with uy DOFs.
fn moves_sideways(bridge: Option<&Bridge>) -> bool {
    match bridge {
        Some(Bridge::Beam(b)) => b.sway.is_some(),
        Some(Bridge::FeImport(f)) => f
            .model
            .dofs
            .iter()
            .any(|(_, d)| *d == crate::scene::imported::Direction::Uy),
        _ => false,
    }
}

/// Reads a record file: (times s, accelerations in `units`, units).
fn read(
    data: &DataFile,
    given: Option<AccelerationUnit>,
    at: &str,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> Option<(Vec<f64>, Vec<f64>, AccelerationUnit)> {
    let field = format!("{at}.file");
    let (shown, size, path) = (&data.shown, data.size, data.path());
    let most = (size as f64 / MIN_SAMPLE_BYTES).ceil();
    if !budget.check(
        ck,
        &field,
        "ground_points",
        &format!("samples the ground-motion record {shown} may hold ({size} bytes)"),
        most,
    ) {
        return None;
    }
    let text = match super::data_files::read_text(data, ck) {
        Ok(text) => text,
        Err(message) => {
            ck.error(&field, message);
            return None;
        }
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let is_at2 = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("at2"));
    let located = |ck: &mut Checker<'_>, (line, message): (usize, String)| {
        ck.error(&field, format!("{shown}:{line}: {message}"));
    };
    if is_at2 {
        // The size bound above already caps the samples; NPTS is checked
        // against it again inside the parser before it allocates.
        let max_points = most.min(budget.limit_of("ground_points")) as usize;
        let record = match at2::parse(text, max_points) {
            Ok(r) => r,
            Err(e) => {
                located(ck, e);
                return None;
            }
        };
        if let Some(g) = given
            && g != record.unit
        {
            ck.error(
                &format!("{at}.units"),
                format!(
                    "`units: {}` disagrees with {shown}, whose header states {}",
                    g.name(),
                    record.unit.name()
                ),
            );
            return None;
        }
        let time = (0..record.acceleration.len())
            .map(|k| k as f64 * record.interval)
            .collect();
        return Some((time, record.acceleration, record.unit));
    }
    let table = match table::parse(text) {
        Ok(t) => t,
        Err(e) => {
            located(ck, e);
            return None;
        }
    };
    let units = match (table.unit, given) {
        (Some(a), Some(b)) if a != b => {
            ck.error(
                &format!("{at}.units"),
                format!(
                    "`units: {}` disagrees with {shown}, whose header states {}",
                    b.name(),
                    a.name()
                ),
            );
            return None;
        }
        (Some(u), _) | (None, Some(u)) => u,
        (None, None) => {
            ck.error(
                &field,
                format!(
                    "{shown} does not state the units of its accelerations: give a header \
                     `time [s], acceleration [g]` (or [m/s^2], [cm/s^2]) or `units:` here"
                ),
            );
            return None;
        }
    };
    Some((table.time, table.acceleration, units))
}
