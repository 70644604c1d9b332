//! Semantic checks and defaults: [`ScenarioRaw`] → [`Scenario`].
//!
//! Every problem is reported with the location of the offending key (or, if
//! the key is absent, of the section that lacks it), and all problems found
//! are reported together, like a compiler.

use super::bridges::resolve_bridge;
use super::budget::{self, Budget, LoadOptions};
use super::checker::Checker;
use super::content;
use super::derive::{
    derive_dimensionless, resolve_contact, resolve_embs, resolve_iteration, resolve_method,
    resolve_study,
};
use super::plausible;
use super::raw::{self, ScenarioRaw};
use super::records::resolve_records;
use super::vehicles::resolve_vehicles;
use crate::bridge::{BridgeError, ModalBridge, ModeRequest};
use crate::scene::*;

/// Default finite elements per span.
pub const DEFAULT_ELEMENTS_PER_SPAN: usize = 20;
/// Default gravitational acceleration, m/s².
pub const DEFAULT_GRAVITY: f64 = 9.81;
/// HHT α used by default with rigid unilateral contact.
pub const DEFAULT_RIGID_ALPHA: f64 = -0.05;

/// Resolves a parsed scenario. Returns the scenario with every default filled
/// in and the modal bridge built on the way (mode selection and the default
/// time step depend on the natural frequencies).
pub(super) fn resolve(
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
        let cutoff = super::automatic_modes::choose(
            &mut modal,
            &bridge,
            &build,
            &excitations,
            record_cutoff,
            &vehicles,
            &ground_motion,
            minimum,
            gravity,
            &budget,
            ck,
        )?;
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
