//! Semantic checks and defaults: [`ScenarioRaw`] → [`Scenario`].
//!
//! Every problem is reported with the location of the offending key (or, if
//! the key is absent, of the section that lacks it), and all problems found
//! are reported together, like a compiler.

use super::bridges::resolve_bridge;
use super::budget::{Budget, LoadOptions};
use super::derive::resolve_contact;
use super::diagnostic::{Diagnostic, Lines};
use super::plausible;
use super::raw::{self, ScenarioRaw};
use super::records::resolve_records;
use super::yaml::{Location, Node, PathSeg};
use crate::scene::*;

/// Default finite elements per span.
pub const DEFAULT_ELEMENTS_PER_SPAN: usize = 20;
/// Default gravitational acceleration, m/s².
pub const DEFAULT_GRAVITY: f64 = 9.81;
/// HHT α used by default with rigid unilateral contact.
pub const DEFAULT_RIGID_ALPHA: f64 = -0.05;

/// Collects diagnostics while resolving one file.
pub(crate) struct Checker<'a> {
    file: &'a str,
    source: &'a str,
    lines: Lines<'a>,
    root: &'a Node,
    /// Where the files the scene names may be read from.
    data: super::data_files::DataAccess,
    pub diagnostics: Vec<Diagnostic>,
    /// Whether the records were checked: an error that stops the
    /// resolution before them leaves them to [`cross_checks`].
    pub(crate) records_checked: bool,
}

/// Parses "vehicles[0].speed" into path segments.
fn parse_path(path: &str) -> Vec<PathSeg<'_>> {
    let mut segs = Vec::new();
    for part in path.split('.') {
        let (key, rest) = part.split_once('[').unwrap_or((part, ""));
        if !key.is_empty() {
            segs.push(PathSeg::Key(key));
        }
        for idx in rest.split('[') {
            if let Ok(i) = idx.trim_end_matches(']').parse() {
                segs.push(PathSeg::Index(i));
            }
        }
    }
    segs
}

impl<'a> Checker<'a> {
    pub(crate) fn new(file: &'a str, source: &'a str, root: &'a Node) -> Self {
        Self {
            file,
            source,
            lines: Lines::new(source),
            root,
            data: Default::default(),
            diagnostics: Vec::new(),
            records_checked: false,
        }
    }

    /// Sets where the files the scene names may be read from.
    pub(crate) fn set_data_access(&mut self, data: super::data_files::DataAccess) {
        self.data = data;
    }

    /// Where the files the scene names may be read from.
    pub(crate) fn data_access(&self) -> &super::data_files::DataAccess {
        &self.data
    }

    fn location(&self, path: &str) -> Location {
        self.root.locate(&parse_path(path))
    }

    /// Records an error at `path`.
    pub(crate) fn error(&mut self, path: &str, message: impl Into<String>) {
        let loc = self.location(path);
        let diagnostic = self.lines.diagnostic(self.file, loc, message);
        self.diagnostics.push(diagnostic);
    }

    /// Records an error at `path` with a `help:` line (a suggestion).
    pub(crate) fn error_with_help(
        &mut self,
        path: &str,
        message: impl Into<String>,
        help: Option<String>,
    ) {
        let loc = self.location(path);
        let diagnostic = self
            .lines
            .diagnostic(self.file, loc, message)
            .with_help(help);
        self.diagnostics.push(diagnostic);
    }

    /// The scenario file's name as given (relative paths in the scene are
    /// relative to its folder).
    pub(crate) fn file(&self) -> &str {
        self.file
    }

    pub(crate) fn positive(&mut self, path: &str, value: f64, what: &str) {
        if value <= 0.0 {
            self.error(path, format!("{what} must be positive, got {value}"));
        }
    }

    /// Whether the file writes the key at `path` (defaults are blamed on the
    /// section that could set them instead).
    pub(crate) fn has(&self, path: &str) -> bool {
        let segs = parse_path(path);
        let (last, parent) = match segs.split_last() {
            Some((PathSeg::Key(k), parent)) => (*k, parent),
            _ => return false,
        };
        let mut node = self.root;
        for seg in parent {
            let next = match seg {
                PathSeg::Key(k) => node.get(k),
                PathSeg::Index(i) => match &node.kind {
                    super::yaml::NodeKind::Sequence(items) => items.get(*i),
                    _ => None,
                },
            };
            match next {
                Some(n) => node = n,
                None => return false,
            }
        }
        node.get(last).is_some()
    }

    pub(crate) fn non_negative(&mut self, path: &str, value: f64, what: &str) {
        if value < 0.0 {
            self.error(path, format!("{what} must not be negative, got {value}"));
        }
    }
}

/// Resolves a parsed scenario: the format's checks ([`describe`]), then
/// `plan`, the planning stage, which builds the bridge's modal model and
/// makes the automatic choices (mode selection and the default time step
/// depend on the natural frequencies).
///
/// An error that stops the resolution before the records (a vehicle or the
/// surface out of range, a budget) does not hide the records' own errors:
/// [`cross_checks`] checks them against the bridge and vehicles as written.
pub(crate) fn resolve<T>(
    raw: &ScenarioRaw,
    ck: &mut Checker<'_>,
    options: LoadOptions,
    plan: impl FnOnce(Described<'_>, &mut Checker<'_>) -> Option<T>,
) -> Option<T> {
    let resolved = describe(raw, ck, options.clone()).and_then(|described| plan(described, ck));
    if resolved.is_none() && !ck.records_checked {
        cross_checks(raw, ck, &options);
    }
    resolved
}

/// The records and envelopes checked against the bridge and the vehicles as
/// the file writes them, when an earlier error stopped the resolution
/// before them (so that a file's mistakes come in one round, issue 28.1).
/// The bridge and vehicles are resolved again into a scratch checker (their
/// own errors are already reported); without a valid bridge nothing is
/// checked. Defaults that need the bridge's frequencies are not needed for
/// checking and get none.
fn cross_checks(raw: &ScenarioRaw, ck: &mut Checker<'_>, options: &LoadOptions) {
    let mut scratch = Checker::new(ck.file, ck.source, ck.root);
    scratch.set_data_access(options.data.clone());
    let limits = Limits::resolve(raw.limits.as_ref(), &mut scratch);
    let budget = Budget::new(limits, options);
    if !budget.counts(raw, &mut scratch) {
        return;
    }
    let Some(bridge) = resolve_bridge(&raw.bridge, &budget, &mut scratch) else {
        return;
    };
    let vehicles = vehicles_as_written(&raw.vehicles, bridge.width(), &mut scratch);
    let contact = resolve_contact(raw.contact.as_ref(), &vehicles, &mut scratch);
    resolve_records(raw.record.as_deref(), &[], &bridge, &vehicles, &contact, ck);
    super::envelopes::resolve_envelopes(raw.envelopes.as_ref(), &[], &bridge, ck);
}

/// A scene as the format leaves it for the planning stage
/// ([`crate::plan`]): the sections checked without physics, the file's raw
/// form for the rest (records, study, contact, output), and the budgets.
pub(crate) struct Described<'r> {
    /// The file as parsed.
    pub raw: &'r ScenarioRaw,
    /// How the file was loaded.
    pub options: LoadOptions,
    /// The budgets the file asked for.
    pub limits: Limits,
    /// The budgets in force.
    pub budget: Budget,
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// The bridge, without its modes chosen.
    pub bridge: Bridge,
    /// The vehicles as written (dimensionless groups not yet derived).
    pub vehicles: Vec<Vehicle>,
    /// The surface profile.
    pub surface: Surface,
    /// The ground-motion records.
    pub ground_motion: Vec<GroundMotion>,
    /// The `solver` section as written.
    pub solver_raw: raw::SolverRaw,
    /// The Newmark parameters, defaults filled in.
    pub newmark: Newmark,
    /// Free-vibration time after the last exit, s.
    pub free_vibration: f64,
}

/// The format's part of [`resolve`]: every check that needs no physics on
/// the sections the planning stage starts from, stopping at the first stage
/// with errors.
fn describe<'r>(
    raw: &'r ScenarioRaw,
    ck: &mut Checker<'_>,
    options: LoadOptions,
) -> Option<Described<'r>> {
    ck.set_data_access(options.data.clone());
    super::names::check_name(ck, &raw.name);
    let limits = Limits::resolve(raw.limits.as_ref(), ck);
    let budget = Budget::new(limits, &options);
    // Counts read straight from the file come first: a file with 10⁵ axles
    // or records is refused before anything is done per axle or record.
    if !budget.counts(raw, ck) {
        return None;
    }
    let gravity = raw.gravity.unwrap_or(DEFAULT_GRAVITY);
    ck.positive("gravity", gravity, "gravity");
    plausible::within(
        ck,
        "gravity",
        "a gravitational acceleration",
        gravity,
        plausible::GRAVITY,
        "m/s²",
    );

    let bridge = resolve_bridge(&raw.bridge, &budget, ck);
    if let Some(bridge) = &bridge {
        plausible::check_bridge(ck, bridge);
    }
    let width = bridge.as_ref().and_then(Bridge::width);
    let vehicles = resolve_vehicles(&raw.vehicles, width, ck);
    let bridge_length = bridge.as_ref().map_or(0.0, Bridge::length);
    let surface =
        super::surfaces::resolve_surface(raw.surface.as_ref(), bridge_length, &budget, ck);
    let ground_motion = super::ground::resolve(
        raw.ground_motion.as_deref(),
        bridge.as_ref(),
        raw.vehicles
            .iter()
            .any(|v| matches!(v, raw::VehicleRaw::Train3d(_))),
        &budget,
        ck,
    );
    let solver_raw = raw.solver.clone().unwrap_or_default();
    let newmark_raw = solver_raw.newmark.clone().unwrap_or(raw::NewmarkRaw {
        beta: None,
        gamma: None,
        alpha: None,
    });
    // Rigid contact holds wheel DOFs to the surface through multipliers, which
    // average-acceleration Newmark leaves ringing (a persistent alternating
    // error in the wheel acceleration and force); a little HHT damping
    // removes it at second order. Every other model defaults to α = 0.
    let rigid = matches!(raw.contact, Some(raw::ContactRaw::Rigid));
    let default_alpha = if rigid && newmark_raw.beta.is_none() && newmark_raw.gamma.is_none() {
        DEFAULT_RIGID_ALPHA
    } else {
        0.0
    };
    let alpha = newmark_raw.alpha.unwrap_or(default_alpha);
    if !(-1.0 / 3.0..=0.0).contains(&alpha) {
        ck.error(
            "solver.newmark.alpha",
            format!("HHT α must be in [−1/3, 0], got {alpha}"),
        );
    }
    let newmark = Newmark {
        beta: newmark_raw.beta.unwrap_or((1.0 - alpha).powi(2) / 4.0),
        gamma: newmark_raw.gamma.unwrap_or(0.5 - alpha),
        alpha,
    };
    ck.positive("solver.newmark.beta", newmark.beta, "Newmark β");
    if newmark.gamma < 0.5 {
        ck.error(
            "solver.newmark.gamma",
            format!(
                "Newmark γ must be at least 0.5 (below it the scheme amplifies every mode), got {}",
                newmark.gamma
            ),
        );
    }
    let free_vibration = solver_raw.free_vibration.unwrap_or(0.0);
    ck.non_negative(
        "solver.free_vibration",
        free_vibration,
        "free-vibration time",
    );
    if let Some(dt) = solver_raw.time_step {
        ck.positive("solver.time_step", dt, "time step");
        super::plausible::within_because(
            ck,
            "solver.time_step",
            "a time step",
            dt,
            super::plausible::TIME_STEP,
            "s",
            "a nanosecond is far below what the stiffest wheel contact needs; a second \
             resolves nothing above 0.5 Hz, below the first mode of almost any bridge",
        );
    }

    // The bridge is built only from a valid description, and only if its
    // eigenproblem fits the budget: the dense solve is O(n³).
    let (bridge, vehicles) = (bridge?, vehicles?);
    if !ck.diagnostics.is_empty() {
        return None;
    }
    if !budget.model(&bridge, &surface, ck) {
        return None;
    }
    // The cheapest budget before the dearest work: a step count set by the
    // file is refused before any eigen solve (issue 23.3).
    if !super::long_run::steps_fit_before_modes(
        raw,
        &vehicles,
        &ground_motion,
        &surface,
        bridge.length(),
        free_vibration,
        &budget,
        ck,
    ) {
        return None;
    }
    Some(Described {
        raw,
        options,
        limits,
        budget,
        gravity,
        bridge,
        vehicles,
        surface,
        ground_motion,
        solver_raw,
        newmark,
        free_vibration,
    })
}

pub(crate) fn check_ratio(ck: &mut Checker<'_>, path: &str, ratio: f64) {
    if !(0.0..1.0).contains(&ratio) {
        ck.error(
            path,
            format!("a damping ratio must be in [0, 1), got {ratio}"),
        );
    }
}

/// Entry time from `entry_time` / `start_position` (front axle at t = 0),
/// for a vehicle at `speed` (m/s, at t = 0) with constant `acceleration`
/// (m/s²). A braking vehicle must still be moving when it reaches the
/// entrance: one that stops before gets a located error.
pub(crate) fn entry_time(
    ck: &mut Checker<'_>,
    at: &str,
    speed: f64,
    acceleration: f64,
    entry_time: Option<f64>,
    start_position: Option<f64>,
) -> f64 {
    let stop = crate::scene::motion::Motion {
        speed,
        acceleration,
        entry_time: 0.0,
    }
    .stop_time();
    match (entry_time, start_position) {
        (Some(_), Some(_)) => {
            ck.error(
                &format!("{at}.start_position"),
                "give `entry_time` or `start_position`, not both",
            );
            0.0
        }
        (Some(t), None) => {
            ck.non_negative(&format!("{at}.entry_time"), t, "entry time");
            if let Some(stop) = stop.filter(|&stop| t >= stop && speed > 0.0) {
                ck.error(
                    &format!("{at}.entry_time"),
                    format!(
                        "braking at {acceleration} m/s² from {speed} m/s, the vehicle stops at \
                         t = {stop:.4} s, before its entry time of {t} s"
                    ),
                );
            }
            t
        }
        (None, Some(x)) => {
            if x > 0.0 {
                ck.error(
                    &format!("{at}.start_position"),
                    format!("the vehicle must start on the approach (start_position ≤ 0), got {x}"),
                );
            }
            if speed <= 0.0 || !acceleration.is_finite() {
                return 0.0;
            }
            match crate::scene::motion::time_to_cover(speed, acceleration, (-x).max(0.0)) {
                Some(t) => t,
                None => {
                    let reach = speed * speed / (-2.0 * acceleration);
                    ck.error(
                        &format!("{at}.acceleration"),
                        format!(
                            "braking at {acceleration} m/s² from {speed} m/s, the vehicle stops \
                             after {reach:.4} m, {:.4} m before the bridge (start_position {x})",
                            -x - reach
                        ),
                    );
                    0.0
                }
            }
        }
        (None, None) => 0.0,
    }
}

/// Largest |acceleration| accepted, m/s² (ten times what any train or road
/// vehicle brakes at; beyond it the input is surely a unit mistake).
pub const MAX_ACCELERATION: f64 = 100.0;

/// Checks a vehicle's acceleration (`None`: 0) and returns it, m/s².
pub(crate) fn check_acceleration(ck: &mut Checker<'_>, at: &str, acceleration: Option<f64>) -> f64 {
    let a = acceleration.unwrap_or(0.0);
    if !a.is_finite() || a.abs() > MAX_ACCELERATION {
        ck.error(
            &format!("{at}.acceleration"),
            format!("an acceleration must be a number within ±{MAX_ACCELERATION} m/s², got {a}"),
        );
        return 0.0;
    }
    a
}

/// Highest vehicle speed accepted, m/s (beyond any vehicle; keeps the time
/// grid and the contact kinematics meaningful).
pub const MAX_SPEED: f64 = 1000.0;

pub(crate) fn check_speed(ck: &mut Checker<'_>, at: &str, speed: f64) {
    ck.positive(&format!("{at}.speed"), speed, "speed");
    if speed > MAX_SPEED {
        ck.error(
            &format!("{at}.speed"),
            format!("a speed of {speed} m/s is above {MAX_SPEED} m/s"),
        );
    }
}

fn resolve_vehicles(
    raws: &[raw::VehicleRaw],
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Option<Vec<Vehicle>> {
    let before = ck.diagnostics.len();
    let out = vehicles_as_written(raws, width, ck);
    (ck.diagnostics.len() == before).then_some(out)
}

/// The vehicles as the file writes them, checked; one per entry even where
/// an entry has errors (its values then are placeholders), so that records
/// can still be checked against their kinds, wheels and cars.
fn vehicles_as_written(
    raws: &[raw::VehicleRaw],
    width: Option<f64>,
    ck: &mut Checker<'_>,
) -> Vec<Vehicle> {
    if raws.is_empty() {
        ck.error("vehicles", "`vehicles` needs at least one vehicle");
    }
    let mut out = Vec::with_capacity(raws.len());
    for (i, raw) in raws.iter().enumerate() {
        let at = format!("vehicles[{i}]");
        // An HSLM train is its table's moving forces.
        let hslm;
        let raw = match raw {
            raw::VehicleRaw::Hslm(h) => {
                hslm = raw::VehicleRaw::MovingForce(h.moving_force());
                &hslm
            }
            other => other,
        };
        match raw {
            raw::VehicleRaw::MovingForce(v) => {
                check_speed(ck, &at, v.speed.0);
                if v.loads.is_empty() {
                    ck.error(
                        &format!("{at}.loads"),
                        "`loads` needs at least one axle load",
                    );
                }
                for (k, &p) in v.loads.iter().enumerate() {
                    ck.positive(&format!("{at}.loads[{k}]"), p, "an axle load");
                }
                let spacings = match (&v.axle_positions, &v.axle_spacings) {
                    (Some(positions), given) => {
                        if given.is_some() {
                            ck.error(
                                &format!("{at}.axle_positions"),
                                "give `axle_spacings` or `axle_positions`, not both",
                            );
                        }
                        axle_positions_to_spacings(ck, &at, positions, v.loads.len())
                    }
                    (None, given) => given.clone().unwrap_or_default(),
                };
                if v.axle_positions.is_none() && spacings.len() + 1 != v.loads.len().max(1) {
                    let path = if v.axle_spacings.is_some() {
                        format!("{at}.axle_spacings")
                    } else {
                        at.clone()
                    };
                    ck.error(
                        &path,
                        format!(
                            "{} axle loads need {} axle spacings, found {}",
                            v.loads.len(),
                            v.loads.len().saturating_sub(1),
                            spacings.len()
                        ),
                    );
                }
                for (k, &s) in spacings.iter().enumerate() {
                    ck.positive(&format!("{at}.axle_spacings[{k}]"), s, "an axle spacing");
                }
                let acceleration = check_acceleration(ck, &at, v.acceleration);
                let entry = entry_time(
                    ck,
                    &at,
                    v.speed.0,
                    acceleration,
                    v.entry_time,
                    v.start_position,
                );
                out.push(Vehicle::MovingForce(MovingForce {
                    loads: v.loads.clone(),
                    axle_spacings: spacings,
                    speed: v.speed.0,
                    acceleration,
                    entry_time: entry,
                    lateral_position: lateral(ck, &at, v.lateral_position, width, 0.0),
                }));
            }
            raw::VehicleRaw::Oscillator(v) => {
                let unsprung = v.unsprung_mass.unwrap_or(0.0);
                let lateral_position = lateral(ck, &at, v.lateral_position, width, 0.0);
                let damping = v.damping.unwrap_or(0.0);
                if v.dimensionless.is_some() {
                    // Derived once the bridge's first frequency is known.
                    out.push(Vehicle::Oscillator(Oscillator {
                        sprung_mass: 0.0,
                        unsprung_mass: 0.0,
                        stiffness: 0.0,
                        damping: 0.0,
                        speed: 0.0,
                        acceleration: 0.0,
                        entry_time: 0.0,
                        lateral_position,
                        dimensionless: None,
                    }));
                    continue;
                }
                let mut required = |field: &str, value: Option<f64>| {
                    value.unwrap_or_else(|| {
                        ck.error(
                            &at,
                            format!("an oscillator needs `{field}` (or `dimensionless`)"),
                        );
                        0.0
                    })
                };
                let (sprung, stiffness, speed) = (
                    required("sprung_mass", v.sprung_mass),
                    required("stiffness", v.stiffness),
                    required("speed", v.speed.map(|s| s.0)),
                );
                check_speed(ck, &at, speed);
                ck.positive(&format!("{at}.sprung_mass"), sprung, "sprung mass");
                ck.non_negative(&format!("{at}.unsprung_mass"), unsprung, "unsprung mass");
                ck.positive(
                    &format!("{at}.stiffness"),
                    stiffness,
                    "suspension stiffness",
                );
                ck.non_negative(&format!("{at}.damping"), damping, "suspension damping");
                let acceleration = check_acceleration(ck, &at, v.acceleration);
                let entry =
                    entry_time(ck, &at, speed, acceleration, v.entry_time, v.start_position);
                out.push(Vehicle::Oscillator(Oscillator {
                    sprung_mass: sprung,
                    unsprung_mass: unsprung,
                    stiffness,
                    damping,
                    speed,
                    acceleration,
                    entry_time: entry,
                    lateral_position,
                    dimensionless: None,
                }));
            }
            raw::VehicleRaw::H20Truck(v) => {
                out.push(super::truck::resolve_h20(v, &at, width, ck));
            }
            raw::VehicleRaw::RailCar(v) => {
                out.push(super::rail::resolve_rail_car(v, &at, width, ck));
            }
            // Turned into moving forces above.
            raw::VehicleRaw::Hslm(_) => {}
            raw::VehicleRaw::Train(v) => {
                out.push(super::rail::resolve_train(v, &at, width, ck));
            }
            raw::VehicleRaw::Train3d(v) => {
                out.push(super::rail_3d::resolve_train_3d(v, &at, width, ck));
            }
        }
    }
    out
}

/// An axle-load train's axle positions behind its front axle (0 first,
/// strictly increasing, one per load) as the spacings between consecutive
/// axles, m; errors at `{at}.axle_positions`.
fn axle_positions_to_spacings(
    ck: &mut Checker<'_>,
    at: &str,
    positions: &[f64],
    loads: usize,
) -> Vec<f64> {
    let path = format!("{at}.axle_positions");
    if positions.len() != loads {
        ck.error(
            &path,
            format!(
                "{loads} axle loads need {loads} axle positions, found {}",
                positions.len()
            ),
        );
        return Vec::new();
    }
    if let Some(&first) = positions.first()
        && first != 0.0
    {
        ck.error(
            &format!("{path}[0]"),
            format!("the front axle is the reference: its position must be 0, got {first}"),
        );
    }
    let mut spacings = Vec::with_capacity(positions.len().saturating_sub(1));
    for (k, pair) in positions.windows(2).enumerate() {
        let spacing = pair[1] - pair[0];
        if spacing <= 0.0 {
            ck.error(
                &format!("{path}[{}]", k + 1),
                format!(
                    "axle positions must increase from front to rear: {} m follows {} m",
                    pair[1], pair[0]
                ),
            );
        }
        spacings.push(spacing);
    }
    spacings
}

/// The transverse position of a vehicle's path: only on a plate (default
/// its centre line), with every wheel at `half_track` either side on the deck.
pub(crate) fn lateral(
    ck: &mut Checker<'_>,
    at: &str,
    given: Option<f64>,
    width: Option<f64>,
    half_track: f64,
) -> Option<f64> {
    match (given, width) {
        (Some(_), None) => {
            ck.error(
                &format!("{at}.lateral_position"),
                "`lateral_position` places a vehicle across a plate deck; a beam has no width",
            );
            None
        }
        (None, None) => None,
        (given, Some(width)) => {
            let y = given.unwrap_or(width / 2.0);
            if y - half_track < 0.0 || y + half_track > width {
                let path = if given.is_some() {
                    format!("{at}.lateral_position")
                } else {
                    at.to_owned()
                };
                ck.error(
                    &path,
                    format!(
                        "wheels at y = {:.4} to {:.4} m fall off the deck, which spans 0 to {width} m",
                        y - half_track,
                        y + half_track
                    ),
                );
            }
            Some(y)
        }
    }
}
