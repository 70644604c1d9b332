//! Semantic checks and defaults: [`ScenarioRaw`] → [`Scenario`].
//!
//! Every problem is reported with the location of the offending key (or, if
//! the key is absent, of the section that lacks it), and all problems found
//! are reported together, like a compiler.

use super::bridges::resolve_bridge;
use super::budget::{self, Budget, LoadOptions};
use super::content;
use super::derive::{
    derive_dimensionless, resolve_contact, resolve_embs, resolve_iteration, resolve_method,
    resolve_study,
};
use super::diagnostic::{Diagnostic, Lines};
use super::plausible;
use super::raw::{self, ScenarioRaw};
use super::records::resolve_records;
use super::yaml::{Location, Node, PathSeg};
use crate::bridge::{BridgeError, ModalBridge, ModeRequest};
use crate::scene::*;

/// Default finite elements per span.
pub const DEFAULT_ELEMENTS_PER_SPAN: usize = 20;
/// Default gravitational acceleration, m/s².
pub const DEFAULT_GRAVITY: f64 = 9.81;
/// HHT α used by default with rigid unilateral contact.
pub const DEFAULT_RIGID_ALPHA: f64 = -0.05;

/// Collects diagnostics while resolving one file.
pub(super) struct Checker<'a> {
    file: &'a str,
    source: &'a str,
    lines: Lines<'a>,
    root: &'a Node,
    /// Where the files the scene names may be read from.
    data: super::data_files::DataAccess,
    pub diagnostics: Vec<Diagnostic>,
    /// Whether the records were checked: an error that stops the
    /// resolution before them leaves them to [`cross_checks`].
    records_checked: bool,
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
    pub(super) fn new(file: &'a str, source: &'a str, root: &'a Node) -> Self {
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
    pub(super) fn set_data_access(&mut self, data: super::data_files::DataAccess) {
        self.data = data;
    }

    /// Where the files the scene names may be read from.
    pub(super) fn data_access(&self) -> &super::data_files::DataAccess {
        &self.data
    }

    fn location(&self, path: &str) -> Location {
        self.root.locate(&parse_path(path))
    }

    /// Records an error at `path`.
    pub(super) fn error(&mut self, path: &str, message: impl Into<String>) {
        let loc = self.location(path);
        let diagnostic = self.lines.diagnostic(self.file, loc, message);
        self.diagnostics.push(diagnostic);
    }

    /// Records an error at `path` with a `help:` line (a suggestion).
    pub(super) fn error_with_help(
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
    pub(super) fn file(&self) -> &str {
        self.file
    }

    pub(super) fn positive(&mut self, path: &str, value: f64, what: &str) {
        if value <= 0.0 {
            self.error(path, format!("{what} must be positive, got {value}"));
        }
    }

    /// Whether the file writes the key at `path` (defaults are blamed on the
    /// section that could set them instead).
    pub(super) fn has(&self, path: &str) -> bool {
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

    pub(super) fn non_negative(&mut self, path: &str, value: f64, what: &str) {
        if value < 0.0 {
            self.error(path, format!("{what} must not be negative, got {value}"));
        }
    }
}

/// Share of the bridge's mass the automatic modes carry under ground
/// motion (EN 1998-1 4.3.3.3.1(3)).
const GROUND_MASS_SHARE: f64 = 0.9;

/// Resolves a parsed scenario. Returns the scenario with every default filled
/// in and the modal bridge built on the way (mode selection and the default
/// time step depend on the natural frequencies).
///
/// An error that stops the resolution before the records (a vehicle or the
/// surface out of range, a budget) does not hide the records' own errors:
/// [`cross_checks`] checks them against the bridge and vehicles as written.
pub(super) fn resolve(
    raw: &ScenarioRaw,
    ck: &mut Checker<'_>,
    options: LoadOptions,
) -> Option<(Scenario, ModalBridge)> {
    let resolved = resolve_checked(raw, ck, options.clone());
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

/// [`resolve`], stopping at the first stage with errors.
fn resolve_checked(
    raw: &ScenarioRaw,
    ck: &mut Checker<'_>,
    options: LoadOptions,
) -> Option<(Scenario, ModalBridge)> {
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
    let rigid = matches!(raw.contact, Some(raw::ContactRaw::Rigid { .. }));
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
    let (mut bridge, mut vehicles) = (bridge?, vehicles?);
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
    let automatic = bridge.modes().count.is_none() && bridge.modes().max_frequency.is_none();
    let minimum = content::minimum_modes(&bridge);
    // The modes the solve will at least compute, before it starts.
    let (asked, asked_path) = match bridge.modes().count {
        Some(count) => (count, "bridge.modes.count"),
        None => (minimum, "bridge.spans"),
    };
    if (automatic || bridge.modes().count.is_some())
        && !(budget.check(ck, asked_path, "modes", "bridge modes kept", asked as f64)
            && budget.eigen(ck, asked_path, &bridge, asked))
    {
        return None;
    }
    // A frequency cut-off alone: count what it keeps before solving for it.
    let cut_off = match (bridge.modes().count, bridge.modes().max_frequency) {
        (None, Some(cut)) => ModalBridge::count_up_to(&bridge, cut).ok().flatten(),
        _ => None,
    };
    if let Some(kept) = cut_off
        && !(budget.check(
            ck,
            "bridge.modes",
            "modes",
            "bridge modes kept",
            kept as f64,
        ) && budget.eigen(ck, "bridge.modes", &bridge, kept))
    {
        return None;
    }

    let cache = options.modes_cache.as_deref();
    let build = |request| {
        ModalBridge::build_cached(&bridge, request, cache).map_err(|e| {
            let path = match e {
                BridgeError::TooManyModes { .. } => "bridge.modes.count",
                BridgeError::NoModeBelow { .. } => "bridge.modes.max_frequency",
                _ => "bridge",
            };
            (path, e.to_string())
        })
    };
    let mut modal = match build(ModeRequest::of(
        bridge.modes(),
        ModeRequest::Lowest(minimum),
    )) {
        Ok(m) => m,
        Err((path, message)) => {
            ck.error(path, message);
            return None;
        }
    };
    derive_dimensionless(&raw.vehicles, &mut vehicles, &bridge, &modal, ck);
    let contact = resolve_contact(raw.contact.as_ref(), &vehicles, ck);
    if contact.is_unilateral()
        && let Some(i) = vehicles
            .iter()
            .position(|v| matches!(v, Vehicle::Train3d(_)))
    {
        ck.error(
            "contact",
            format!(
                "vehicle {} is a `train_3d`, whose wheelsets follow their rails vertically and \
                 laterally at all times (the EMBS paper's wheel–rail coupling: no creep forces, \
                 no flange contact, no wheel lift); use `contact: {{type: permanent}}`",
                i + 1
            ),
        );
    }
    // Derived values too: dimensionless oscillators, ratio-given contacts.
    for (i, vehicle) in vehicles.iter().enumerate() {
        let at = format!("vehicles[{i}]");
        let entry_field = if ck.has(&format!("{at}.start_position")) {
            "start_position"
        } else {
            "entry_time"
        };
        plausible::check_vehicle(ck, &at, entry_field, vehicle);
    }
    plausible::check_contact(ck, &contact);
    if !ck.diagnostics.is_empty() {
        return None;
    }
    // Vehicles the file does not place start behind a spectrum's run-in.
    super::surfaces::place_before_run_in(
        &mut vehicles,
        super::surfaces::placement_run_in(&surface, raw.study.as_ref()),
        ck,
    );
    let travel = super::surfaces::travel(&vehicles, gravity, bridge.length(), free_vibration);
    if !super::surfaces::check_reach(&surface, travel, &budget, ck) {
        return None;
    }
    let study = resolve_study(
        raw.study.as_ref(),
        &bridge,
        &vehicles,
        &contact,
        &surface,
        &modal.frequencies(),
        ck,
    );
    let points = study
        .as_ref()
        .map_or(1.0, |s| super::sweep::study_points(s, &surface));
    if study.is_some() && !budget.check(ck, "study", "study_points", "runs of the study", points) {
        return None;
    }
    if let Some(study) = &study {
        super::plausible::check_study(ck, study, &vehicles, &contact, &modal, &bridge);
    }
    if !ck.diagnostics.is_empty() {
        return None;
    }
    // A speed sweep runs the scene at every speed of its grid: the automatic
    // choices must serve its fastest run.
    let excitations = match &study {
        Some(Study::SpeedSweep(sweep)) => super::sweep::excitations(
            Some(sweep.speed_range().1),
            &super::sweep::entries_of(sweep.roughness.as_deref()),
            &vehicles,
            &contact,
            &surface,
            &bridge,
            gravity,
        ),
        Some(Study::MonteCarlo(mc)) => super::sweep::excitations(
            mc.speed_range().map(|r| r.1),
            &super::sweep::entries_of(mc.roughness.as_deref()),
            &vehicles,
            &contact,
            &surface,
            &bridge,
            gravity,
        ),
        // Every train of a resonance check at its top speed.
        Some(Study::ResonanceCheck(check)) => {
            let trains: Vec<Vehicle> = check
                .trains
                .iter()
                .map(|&t| super::resonance::train_vehicle(t, check.top_speed()))
                .collect();
            content::excitations(&trains, &contact, &surface, bridge.spans(), gravity)
        }
        _ => content::excitations(&vehicles, &contact, &surface, bridge.spans(), gravity),
    };
    // The highest mode frequency any deck acceleration sums (it needs only
    // f₁ and f₃, which the minimum modes already give).
    let record_cutoff =
        super::records::highest_acceleration_cutoff(raw.record.as_deref(), &modal.frequencies());
    let record_cutoff = match (
        record_cutoff,
        super::envelopes::acceleration_cut(raw.envelopes.as_ref(), &modal.frequencies()),
    ) {
        (Some(a), Some(b)) => Some(a.max(b)),
        (a, b) => a.or(b),
    };
    if automatic {
        // Automatic: keep the modes this scene excites; write the cut-off back
        // so the resolved scenario reproduces the choice.
        let (mut cutoff, mut dynamic, top) = content::mode_cutoff(&modal, &excitations);
        // Deck accelerations sum every mode up to their own cut-off (30 Hz
        // or more, EN 1990 A2.4.4.2.1(4)): keep all of them, so that the
        // filtered acceleration is complete and converges with the step.
        let acceleration_cut = record_cutoff.filter(|&cut| cut > cutoff);
        if let Some(cut) = acceleration_cut {
            cutoff = cut;
            dynamic = true;
        }
        // Heavy wheels feel the bridge's acceleration under them, which a
        // few modes resolve poorly: keep twice the minimum.
        let heavy = content::heavy_wheels(&vehicles, &bridge, gravity);
        let floor = if heavy {
            (2 * minimum).min(ModalBridge::available_of(&bridge))
        } else {
            minimum
        };
        dynamic |= heavy;
        if dynamic {
            // The cut-off the excitation asks for may keep more modes than the
            // budget allows (a very long or very flexible span): count them
            // with one factorisation before solving for them.
            let kept = ModalBridge::count_up_to(&bridge, cutoff)
                .ok()
                .flatten()
                .map_or(floor, |n| n.max(floor));
            if !budget.check(
                ck,
                "bridge.spans",
                "modes",
                &format!("bridge modes up to the {cutoff:.4} Hz the vehicles excite"),
                kept as f64,
            ) || !budget.eigen(ck, "bridge.spans", &bridge, kept)
            {
                return None;
            }
            modal = match build(ModeRequest::AtLeastUpTo(floor, cutoff)) {
                Ok(m) => m,
                Err((path, message)) => {
                    ck.error(path, message);
                    return None;
                }
            };
        }
        // The cut-off written back must reproduce the modes kept.
        cutoff = cutoff.max(modal.frequencies().last().copied().unwrap_or(0.0));
        modal.selection = match acceleration_cut {
            _ if heavy => format!(
                "automatic: {} modes up to {cutoff:.2} Hz, at least twice the {minimum} of the \
                 minimum because a wheel's mass exceeds {} of a span's (its contact force \
                 follows the deck's acceleration under it)",
                modal.mode_count(),
                content::HEAVY_WHEEL_RATIO
            ),
            Some(cut) => format!(
                "automatic: {} modes, every one up to {cut:.2} Hz that the deck accelerations \
                 sum (EN 1990 A2.4.4.2.1: max(30 Hz, 1.5 f₁, f₃) unless the record sets \
                 `max_frequency`)",
                modal.mode_count()
            ),
            None => content::mode_reason(
                modal.mode_count(),
                cutoff,
                dynamic,
                &top,
                content::modes_per_span(&bridge),
            ),
        };
        // Ground motion: keep modes until they carry 90 % of the bridge's
        // mass (EN 1998-1 4.3.3.3.1(3)); the uniform inertia load of a
        // vertical record excites the symmetric modes, each less than the
        // last, so a few suffice.
        // A lateral record asks the same of the lateral modes (a bridge in
        // the vertical plane has no lateral mass to carry: skipped).
        if !ground_motion.is_empty() {
            let available = ModalBridge::available_of(&bridge);
            let has = |d| ground_motion.iter().any(|g| g.direction == d);
            let (vertical, lateral) = (
                has(crate::scene::Direction::Vertical),
                has(crate::scene::Direction::Lateral),
            );
            loop {
                let share = |(participation, mass): (Vec<f64>, f64)| {
                    if mass > 0.0 {
                        participation.iter().map(|g| g * g).sum::<f64>() / mass
                    } else {
                        1.0
                    }
                };
                let mut ratio = 1.0f64;
                if vertical {
                    ratio = ratio.min(share(modal.vertical_participation(&bridge)));
                }
                if lateral {
                    ratio = ratio.min(share(modal.lateral_participation(&bridge)));
                }
                let count = modal.mode_count();
                if ratio >= GROUND_MASS_SHARE || count >= available {
                    if ratio >= GROUND_MASS_SHARE {
                        modal.selection.push_str(&format!(
                            "; for the ground motion they carry {:.1} % of the bridge's mass (EN 1998-1 4.3.3.3.1: at least {:.0} %)",
                            100.0 * ratio,
                            100.0 * GROUND_MASS_SHARE
                        ));
                    }
                    break;
                }
                let more = (2 * count).min(available);
                if !budget.check(
                    ck,
                    "ground_motion",
                    "modes",
                    "bridge modes for 90 % of the mass under ground motion",
                    more as f64,
                ) || !budget.eigen(ck, "ground_motion", &bridge, more)
                {
                    return None;
                }
                modal = match build(ModeRequest::Lowest(more)) {
                    Ok(m) => m,
                    Err((path, message)) => {
                        ck.error(path, message);
                        return None;
                    }
                };
            }
            let top = modal.frequencies().last().copied().unwrap_or(0.0);
            cutoff = cutoff.max(top);
        }
        // Written back as the count kept and the cut-off (at least the
        // last kept mode's own frequency): the count cannot round a mode
        // away, the cut-off says why ([`ModalBridge::build_cached`]).
        bridge.modes_mut().count = Some(modal.mode_count());
        bridge.modes_mut().max_frequency = Some(cutoff);
    }
    // The modes kept, however chosen (a high `max_frequency` keeps many).
    let modes_path = if ck.has("bridge.modes") {
        "bridge.modes"
    } else {
        "bridge"
    };
    let kept = modal.mode_count() as f64;
    if !budget.check(ck, modes_path, "modes", "bridge modes kept", kept) {
        return None;
    }
    if !ck.diagnostics.is_empty() {
        return None;
    }
    // A braking vehicle started slower may stop before the bridge.
    let slowest = match &study {
        Some(Study::SpeedSweep(sweep)) => Some(sweep.speed_range().0),
        Some(Study::MonteCarlo(mc)) => mc.speed_range().map(|r| r.0),
        _ => None,
    };
    if let Some(speed) = slowest
        && let Some(i) = super::sweep::stops_before_entry(&vehicles, speed)
    {
        ck.error(
            "study.speeds",
            format!(
                "at the study's slowest speed, {speed} m/s, vehicle {} brakes to a stop before \
                 the bridge (acceleration {} m/s²): start it closer or sweep faster speeds",
                i + 1,
                vehicles[i].acceleration()
            ),
        );
        return None;
    }

    // Default step: resolve the highest frequency kept or excited. A speed
    // sweep's step serves its fastest run; its slowest run is the longest.
    let (fast, slow) = super::sweep::extreme_vehicles(study.as_ref(), &vehicles);
    let highest = modal.frequencies().last().copied().unwrap_or(1.0);
    let length = modal.length;
    let shortest_crossing = fast
        .iter()
        .map(|v| v.exit_time(length) - v.entry_time())
        .fold(f64::INFINITY, f64::min);
    let duration = |vehicles: &[Vehicle]| {
        let last_exit = vehicles
            .iter()
            .map(|v| v.exit_time(length))
            .fold(0.0, f64::max);
        last_exit + free_vibration
    };
    let (shortest_run, mut longest_run) = (duration(&fast), duration(&slow));
    // A separation map's slowest point (its smallest velocity ratio) runs
    // longest: v = 2 α f₁ L.
    if let (Some(Study::SeparationMap { velocity_ratio, .. }), Some(&f1), [vehicle]) =
        (&study, modal.frequencies().first(), vehicles.as_slice())
    {
        let slowest = 2.0 * velocity_ratio.from.min(velocity_ratio.to) * f1 * length;
        if slowest > 0.0 {
            longest_run = longest_run.max(vehicle.entry_time() + length / slowest + free_vibration);
        }
    }
    // Deck accelerations: their highest mode keeps its phase over the run.
    let acceleration_top = record_cutoff.map_or(0.0, |cut| cut.min(highest));
    let step_without_ground = solver_raw.time_step.is_none().then(|| {
        content::time_step(highest, &excitations, shortest_crossing)
            .min(content::phase_time_step(acceleration_top, longest_run))
    });
    // A ground-motion record is linear between its samples: a step no
    // longer than its shortest interval sees every peak.
    let time_step = solver_raw.time_step.unwrap_or_else(|| {
        ground_motion
            .iter()
            .map(|g| g.record.shortest_interval())
            .fold(step_without_ground.unwrap_or(f64::INFINITY), f64::min)
    });
    let time_step_selection = if solver_raw.time_step.is_some() {
        "set in the file".to_owned()
    } else {
        format!(
            "automatic: {} steps per period of the highest frequency kept or excited, at \
             least 200 steps over the shortest crossing, and for deck accelerations a phase \
             drift of their highest mode below {} rad over the run",
            content::STEPS_PER_PERIOD,
            content::PHASE_BUDGET
        )
    };
    let steps = shortest_run / time_step;
    if steps < 10.0 {
        ck.error(
            "solver.time_step",
            format!(
                "a time step of {time_step} s gives only {} step(s) over the {shortest_run:.4} s run; use at most a tenth of it",
                steps.ceil(),
            ),
        );
    }
    // The fastest any wheel goes over the study (an accelerating vehicle at
    // its exit): surface features shorter than its travel per step are
    // refused.
    let top_speed = fast
        .iter()
        .map(|v| v.speed().max(v.motion().speed_at(v.exit_time(length))))
        .fold(0.0, f64::max);
    super::surfaces::check_features(&surface, top_speed, time_step, ck);
    super::surfaces::check_lateral_followers(&surface, &vehicles, ck);
    let steps = longest_run / time_step;
    let cause = super::long_run::LongRun {
        raw,
        slow: &slow,
        ground_motion: &ground_motion,
        time_step,
        step_without_ground,
        duration: longest_run,
        free_vibration,
        bridge_length: length,
    }
    .cause(budget.limit_of("steps"));
    let steps_path = cause.path;
    let what = format!(
        "time steps of {time_step:.3e} s over the {longest_run:.4e} s run (the last vehicle's exit plus free vibration)"
    );
    if budget.check_because(ck, &steps_path, "steps", &what, steps, &cause.hint) && points > 1.0 {
        budget.check(
            ck,
            "study",
            "study_steps",
            &format!("time steps over the study's {points} runs"),
            steps * points,
        );
    }

    let method = resolve_method(solver_raw.method, &contact, ck);
    let iteration = resolve_iteration(&solver_raw, method, ck);
    let embs = resolve_embs(&solver_raw, method, ck);
    ck.records_checked = true;
    let record = resolve_records(
        raw.record.as_deref(),
        &modal.frequencies(),
        &bridge,
        &vehicles,
        &contact,
        ck,
    );
    let envelopes = super::envelopes::resolve_envelopes(
        raw.envelopes.as_ref(),
        &modal.frequencies(),
        &bridge,
        ck,
    );
    if !ck.diagnostics.is_empty() {
        return None;
    }
    // The records as resolved, defaults included (a contact force per
    // wheel), so that `resolved.yaml` passes the same budget.
    if raw.record.is_none() {
        budget.check(
            ck,
            "vehicles",
            "records",
            "recorded quantities (the default: each span's middle and each wheel's contact force)",
            record.len() as f64,
        );
    }
    let output = super::output::resolve_output(raw.output.as_ref(), time_step, ck);
    if study.is_none() {
        let columns: f64 = record
            .iter()
            .map(|r| {
                if r.quantity == Quantity::BridgeDisplacement {
                    2.0
                } else {
                    1.0
                }
            })
            .sum();
        let path = if raw.output.is_some() {
            "output"
        } else if raw.record.is_some() {
            "record"
        } else {
            steps_path.as_str()
        };
        // The rows written: t = 0 and every `every`-th step after it.
        let rows = (steps / output.every as f64).floor() + 1.0;
        budget.check(
            ck,
            path,
            "output_bytes",
            "bytes of the history files (estimated; thin them with `output: {every: N}`)",
            budget::history_bytes(rows, columns, output.format),
        );
        if !ck.diagnostics.is_empty() {
            return None;
        }
    }
    let scenario = Scenario {
        source_file: None,
        name: raw.name.clone(),
        description: raw.description.clone(),
        gravity,
        bridge,
        vehicles,
        surface,
        contact,
        solver: Solver {
            method,
            time_step,
            newmark,
            free_vibration,
            iteration,
            embs,
            time_step_selection,
        },
        record,
        ground_motion,
        envelopes,
        output,
        study,
        limits,
        speeds_stated: raw
            .vehicles
            .iter()
            .map(|v| v.speed().is_none_or(|s| s.unit_written()))
            .collect(),
    };
    Some((scenario, modal))
}

pub(super) fn check_ratio(ck: &mut Checker<'_>, path: &str, ratio: f64) {
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
pub(super) fn entry_time(
    ck: &mut Checker<'_>,
    at: &str,
    speed: f64,
    acceleration: f64,
    entry_time: Option<f64>,
    start_position: Option<f64>,
) -> f64 {
    let stop = crate::vehicle::motion::Motion {
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
            match crate::vehicle::motion::time_to_cover(speed, acceleration, (-x).max(0.0)) {
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
pub(super) fn check_acceleration(ck: &mut Checker<'_>, at: &str, acceleration: Option<f64>) -> f64 {
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

pub(super) fn check_speed(ck: &mut Checker<'_>, at: &str, speed: f64) {
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
pub(super) fn lateral(
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
