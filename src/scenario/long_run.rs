//! Where to blame a run with too many time steps, and which value of that
//! field would fit. Steps = run duration / time step; the field blamed is
//! the one that makes either far larger than the rest of the scene asks:
//! a ground-motion record whose sampling sets the automatic step (its
//! interval in the file, or a start time so large that the shifted
//! samples lose their digits), a vehicle that waits most of the run, a
//! free vibration that is most of it, a train whose length is most of its
//! crossing, the file's own time step, else the slowest vehicle's speed.

use super::budget::Budget;
use super::checker::Checker;
use super::raw;
use crate::scene::{GroundMotion, Surface, Vehicle};

/// The run whose steps are budgeted.
pub(crate) struct LongRun<'a> {
    pub raw: &'a raw::ScenarioRaw,
    /// The vehicles of the longest run (a study's slowest point).
    pub slow: &'a [Vehicle],
    pub ground_motion: &'a [GroundMotion],
    /// The time step, s.
    pub time_step: f64,
    /// The step the scene asks for before any ground record shortens it, s
    /// (`None` when the file sets `solver.time_step`).
    pub step_without_ground: Option<f64>,
    /// The longest run's duration, s.
    pub duration: f64,
    /// Free vibration after the last exit, s.
    pub free_vibration: f64,
    /// The bridge's length, m.
    pub bridge_length: f64,
    /// A deck-acceleration record whose own `max_frequency` (above the
    /// EN 1990 filter) made the automatic choice keep the modes that set the
    /// step: its path in the file, its cut-off and the default filter, Hz.
    pub acceleration_record: Option<(String, f64, f64)>,
}

/// The field blamed and what would fit.
pub(crate) struct Cause {
    /// Its path in the file.
    pub path: String,
    /// Why it makes the run long and a value that fits `limit` steps.
    pub hint: String,
}

/// The step budget checked before any eigen solve (issue 23.3: the
/// cheapest checks first), when the run's length is known without the
/// modes: the file sets `solver.time_step`, there is no study (a study's
/// speeds and a separation map's slowest point need f₁), and no vehicle is
/// derived from the bridge's frequencies (`dimensionless`). The refusal is
/// the one the full check after the solve gives, word for word; `false`
/// when it refused.
#[allow(clippy::too_many_arguments)]
pub(crate) fn steps_fit_before_modes(
    raw: &raw::ScenarioRaw,
    vehicles: &[Vehicle],
    ground_motion: &[GroundMotion],
    surface: &Surface,
    bridge_length: f64,
    free_vibration: f64,
    budget: &Budget,
    ck: &mut Checker<'_>,
) -> bool {
    let Some(time_step) = raw.solver.as_ref().and_then(|s| s.time_step) else {
        return true;
    };
    let derived = raw
        .vehicles
        .iter()
        .any(|v| matches!(v, raw::VehicleRaw::Oscillator(o) if o.dimensionless.is_some()));
    if raw.study.is_some() || derived {
        return true;
    }
    // The vehicles as the full check sees them: placed behind a spectrum's
    // run-in when the file does not place them.
    let mut slow = vehicles.to_vec();
    super::surfaces::place_before_run_in(
        &mut slow,
        super::surfaces::placement_run_in(surface, None),
        ck,
    );
    let duration = slow
        .iter()
        .map(|v| v.exit_time(bridge_length))
        .fold(0.0, f64::max)
        + free_vibration;
    let steps = duration / time_step;
    let cause = LongRun {
        raw,
        slow: &slow,
        ground_motion,
        time_step,
        step_without_ground: None,
        duration,
        free_vibration,
        bridge_length,
        acceleration_record: None,
    }
    .cause(budget.limit_of("steps"));
    let what = format!(
        "time steps of {time_step:.3e} s over the {duration:.4e} s run (the last vehicle's exit plus free vibration)"
    );
    budget.check_because(ck, &cause.path, "steps", &what, steps, &cause.hint)
}

impl LongRun<'_> {
    /// The cause of the steps of this run, with a value that fits `limit`
    /// steps.
    pub(crate) fn cause(&self, limit: f64) -> Cause {
        let (dt, duration) = (self.time_step, self.duration);
        // The run time `limit` steps of the current step cover, and the
        // excess to remove.
        let fits = limit * dt;
        let excess = duration - fits;
        if let Some(cause) = self.ground_cause(limit) {
            return cause;
        }
        if let Some((path, cut, default)) = &self.acceleration_record {
            // The step scales as the inverse of the highest kept frequency
            // (30 steps per period), so the steps as the cut-off.
            let fitting = cut * limit * dt / duration;
            return Cause {
                path: path.clone(),
                hint: format!(
                    "this deck-acceleration record sums the modes up to {} Hz, far above the \
                     EN 1990 filter of {} Hz, and its highest mode sets the time step; a \
                     `max_frequency` up to about {} Hz fits (or leave it out for the default)",
                    short(*cut),
                    short(*default),
                    down(fitting)
                ),
            };
        }
        let latest = self
            .slow
            .iter()
            .enumerate()
            .map(|(i, v)| (i, v.entry_time()))
            .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        if latest.1 > 0.5 * duration {
            let i = latest.0;
            // A vehicle the file does not place starts behind the surface's
            // run-in (placed there while resolving): that is the cause.
            if !self.placed_by_file(i) && self.raw.surface.is_some() {
                return Cause {
                    path: "surface".into(),
                    hint: format!(
                        "vehicle {} starts behind the surface's run-in and reaches the bridge \
                         only at t = {} s of the {} s run; shorten `run_in` (or place the \
                         vehicle with `start_position`)",
                        i + 1,
                        short(latest.1),
                        short(duration)
                    ),
                };
            }
            let field = if self.starts_by_position(i) {
                "start_position"
            } else {
                "entry_time"
            };
            let hint = if self.starts_by_position(i) {
                format!(
                    "vehicle {} reaches the bridge only at t = {} s of the {} s run; start it \
                     closer (it must reach the bridge by t = {} s)",
                    i + 1,
                    short(latest.1),
                    short(duration),
                    down((latest.1 - excess).max(0.0))
                )
            } else {
                format!(
                    "vehicle {} enters at t = {} s of the {} s run; an entry time up to {} s fits",
                    i + 1,
                    short(latest.1),
                    short(duration),
                    down((latest.1 - excess).max(0.0))
                )
            };
            return Cause {
                path: format!("vehicles[{i}].{field}"),
                hint,
            };
        }
        if self.free_vibration > 0.5 * duration {
            return Cause {
                path: "solver.free_vibration".into(),
                hint: format!(
                    "a free vibration of {} s is most of the {} s run; up to {} s fits",
                    short(self.free_vibration),
                    short(duration),
                    down((self.free_vibration - excess).max(0.0))
                ),
            };
        }
        // A train (or axle group) whose length is most of its crossing.
        let longest = self
            .slow
            .iter()
            .enumerate()
            .map(|(i, v)| (i, v.length() / v.speed(), v))
            .fold(None::<(usize, f64, &Vehicle)>, |a, b| match a {
                Some(a) if a.1 >= b.1 => Some(a),
                _ => Some(b),
            });
        if let Some((i, time, vehicle)) = longest
            && time > 0.5 * duration
            && let Some(path) = self.length_field(i)
        {
            let length = vehicle.length();
            return Cause {
                path,
                hint: format!(
                    "vehicle {} is {} m long, {} s of the {} s run at {} m/s; shorten it to at \
                     most {} m (its spacings) to fit",
                    i + 1,
                    short(length),
                    short(time),
                    short(duration),
                    short(vehicle.speed()),
                    down((length - excess * vehicle.speed()).max(0.0))
                ),
            };
        }
        if self.step_without_ground.is_none() {
            return Cause {
                path: "solver.time_step".into(),
                hint: format!(
                    "a time step of {dt:.3e} s over the {} s run; a step of at least {} s fits",
                    short(duration),
                    up(duration / limit)
                ),
            };
        }
        let slowest = self
            .slow
            .iter()
            .enumerate()
            .fold((0, f64::INFINITY), |a, (i, v)| {
                if v.speed() < a.1 { (i, v.speed()) } else { a }
            });
        let (i, speed) = slowest;
        let travel = self.slow.get(i).map_or(0.0, |v| v.length()) + self.bridge_length;
        let room = fits - self.free_vibration - self.slow.get(i).map_or(0.0, |v| v.entry_time());
        let hint = if room > 0.0 && travel / room <= super::plausible::SPEED.1 {
            format!(
                "at {} m/s vehicle {} crosses {} m in {} s; a speed of at least {} m/s fits",
                short(speed),
                i + 1,
                short(travel),
                short(travel / speed),
                up(travel / room)
            )
        } else {
            format!(
                "at {} m/s vehicle {} crosses {} m in {} s",
                short(speed),
                i + 1,
                short(travel),
                short(travel / speed)
            )
        };
        Cause {
            path: format!("vehicles[{i}].speed"),
            hint,
        }
    }

    /// A ground record that sets the automatic step far below what the
    /// rest of the scene asks.
    fn ground_cause(&self, limit: f64) -> Option<Cause> {
        let without = self.step_without_ground?;
        let (i, g, interval) = self
            .ground_motion
            .iter()
            .enumerate()
            .map(|(i, g)| (i, g, g.record.shortest_interval()))
            .fold(None::<(usize, &GroundMotion, f64)>, |a, b| match a {
                Some(a) if a.2 <= b.2 => Some(a),
                _ => Some(b),
            })?;
        if interval.is_nan() || interval >= without {
            return None;
        }
        let needed = self.duration / limit;
        // A start time of S s leaves the shifted samples only about
        // S × 2.2e-16 s of resolution: intervals within a thousand of those
        // units were made by the shift, not by the file.
        let resolution = (g.start_time.abs() + g.record.end_time().abs()) * f64::EPSILON;
        if interval <= 1e3 * resolution {
            return Some(Cause {
                path: format!("ground_motion[{i}].start_time"),
                hint: format!(
                    "a start time of {:e} s leaves the record's samples only {interval:.3e} s apart \
                     in floating point, which sets the automatic time step; start the record \
                     within the run (0 to {} s)",
                    g.start_time,
                    short(self.duration)
                ),
            });
        }
        Some(Cause {
            path: format!("ground_motion[{i}].file"),
            hint: format!(
                "the record's shortest interval between two samples, {interval:.3e} s, sets the \
                 automatic time step (a step no longer than it sees every peak); resample the \
                 record to intervals of at least {} s, or give `solver.time_step`",
                up(needed)
            ),
        })
    }

    /// Whether the file places vehicle `i` itself (`entry_time` or
    /// `start_position`), rather than leaving it to the surface's run-in.
    fn placed_by_file(&self, i: usize) -> bool {
        use raw::VehicleRaw as V;
        match self.raw.vehicles.get(i) {
            Some(V::MovingForce(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::Oscillator(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::H20Truck(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::RailCar(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::Train(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::Train3d(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::Hslm(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::AashtoH20(v)) => v.entry_time.or(v.start_position).is_some(),
            Some(V::AashtoHs20(v)) => v.entry_time.or(v.start_position).is_some(),
            None => true,
        }
    }

    fn starts_by_position(&self, i: usize) -> bool {
        use raw::VehicleRaw as V;
        match self.raw.vehicles.get(i) {
            Some(V::MovingForce(v)) => v.start_position.is_some(),
            Some(V::Oscillator(v)) => v.start_position.is_some(),
            Some(V::H20Truck(v)) => v.start_position.is_some(),
            Some(V::RailCar(v)) => v.start_position.is_some(),
            Some(V::Train(v)) => v.start_position.is_some(),
            Some(V::Train3d(v)) => v.start_position.is_some(),
            Some(V::Hslm(v)) => v.start_position.is_some(),
            Some(V::AashtoH20(v)) => v.start_position.is_some(),
            Some(V::AashtoHs20(v)) => v.start_position.is_some(),
            None => false,
        }
    }

    /// The field that makes vehicle `i` long: a train's `car_spacing` or
    /// its longest `cars[k].spacing`, a moving force's longest axle
    /// spacing.
    fn length_field(&self, i: usize) -> Option<String> {
        use raw::VehicleRaw as V;
        let longest = |spacings: &mut dyn Iterator<Item = Option<f64>>| {
            spacings
                .enumerate()
                .filter_map(|(k, s)| s.map(|s| (k, s)))
                .fold(None::<(usize, f64)>, |a, b| match a {
                    Some(a) if a.1 >= b.1 => Some(a),
                    _ => Some(b),
                })
                .map(|(k, _)| k)
        };
        let at = format!("vehicles[{i}]");
        match self.raw.vehicles.get(i)? {
            V::Train(t) if t.car_spacing.is_some() => Some(format!("{at}.car_spacing")),
            V::Train3d(t) if t.car_spacing.is_some() => Some(format!("{at}.car_spacing")),
            V::Train(t) => {
                let k = longest(&mut t.cars.as_ref()?.iter().map(|c| c.spacing))?;
                Some(format!("{at}.cars[{k}].spacing"))
            }
            V::Train3d(t) => {
                let k = longest(&mut t.cars.as_ref()?.iter().map(|c| c.spacing))?;
                Some(format!("{at}.cars[{k}].spacing"))
            }
            V::MovingForce(m) => match (&m.axle_spacings, &m.axle_positions) {
                (Some(s), _) => {
                    let k = longest(&mut s.iter().map(|&s| Some(s)))?;
                    Some(format!("{at}.axle_spacings[{k}]"))
                }
                (None, Some(_)) => Some(format!("{at}.axle_positions")),
                _ => None,
            },
            _ => None,
        }
    }
}

/// A time or length as people read it: four significant digits.
fn short(x: f64) -> String {
    if x.is_finite() && x != 0.0 && (x.abs() >= 1e6 || x.abs() < 1e-3) {
        format!("{x:.3e}")
    } else {
        let s = format!("{x:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_owned()
    }
}

/// `x` rounded up to three significant digits (a value that fits).
fn up(x: f64) -> String {
    round(x, f64::ceil)
}

/// `x` rounded down to three significant digits (a value that fits).
fn down(x: f64) -> String {
    round(x, f64::floor)
}

fn round(x: f64, to: fn(f64) -> f64) -> String {
    if !x.is_finite() || x <= 0.0 {
        return short(x.max(0.0));
    }
    let exponent = x.log10().floor() as i32 - 2;
    let rounded = to(x / 10f64.powi(exponent)) * 10f64.powi(exponent);
    if !(-3..6).contains(&(exponent + 2)) {
        format!("{rounded:.2e}")
    } else {
        format!("{rounded:.*}", (-exponent).max(0) as usize)
    }
}
