//! The planning stage's choices: the bridge's modal model built and every
//! automatic choice that needs its frequencies or the vehicles' (the modes
//! kept and why, the default time step and why, the budgets that need a
//! mode count), with the format's remaining sections (contact, study,
//! records, envelopes, output) resolved against them. Error messages and
//! their locations are the format's: the checks report through its
//! [`Checker`].

use crate::bridge::{BridgeError, ModalBridge, ModeRequest};
use crate::scenario::budget;
use crate::scenario::checker::Checker;
use crate::scenario::derive::{
    resolve_contact, resolve_embs, resolve_iteration, resolve_method, resolve_study,
};
use crate::scenario::plausible;
use crate::scenario::raw::ScenarioRaw;
use crate::scenario::records::resolve_records;
use crate::scenario::resolve::Sections;
use crate::scene::*;

use super::budget::eigen_fits;
use super::content;
use super::derive::derive_dimensionless;
use super::modes;
use super::time_step;
use super::track_flexibility;

/// Whether the default step resolves every kept mode, not only the excited
/// ones ([`content::excited_mode_top`]): when a result reads the deck's
/// acceleration (or a slowly converging modal sum) through all of them —
/// ground motion (its inertia load drives every mode that carries mass), a
/// support reaction (the deck's inertia) or a shear (recorded or
/// enveloped) — or when a wheel with a mass of its own is held on the deck
/// (`wheel_mass` under permanent or rigid contact): its contact force
/// follows the deck's acceleration under it, and its mass landing on the
/// deck at the entry kicks every mode. Measured on the shipped
/// fe-import-lcp-fig4-rigid scene with only the excited modes resolved
/// (30 steps per period of 20 Hz, against 502 Hz): its support rotation
/// `node1_ry` was 0.52 % from the converged answer.
fn reads_every_mode(raw: &ScenarioRaw, contact: &Contact, wheel_mass: bool, ground: bool) -> bool {
    let recorded = |q: Quantity| {
        raw.record
            .as_deref()
            .is_some_and(|records| records.iter().any(|r| r.quantity == q))
    };
    let enveloped = |q: Quantity| {
        raw.envelopes.as_ref().is_some_and(|e| {
            e.quantities
                .as_deref()
                .unwrap_or(&crate::scenario::envelopes::ENVELOPE_QUANTITIES)
                .contains(&q)
        })
    };
    let held = matches!(contact, Contact::Permanent | Contact::Rigid { .. });
    ground
        || recorded(Quantity::BridgeReaction)
        || recorded(Quantity::BridgeShear)
        || enveloped(Quantity::BridgeShear)
        || (wheel_mass && held)
}

/// Builds the bridge's modal model and makes the automatic choices of a
/// scene the format described; `None` once an error is reported.
pub(crate) fn plan(
    described: Sections,
    raw: &ScenarioRaw,
    ck: &mut Checker<'_>,
) -> Option<(Scenario, ModalBridge)> {
    let Sections {
        options,
        limits,
        budget,
        gravity,
        mut bridge,
        mut vehicles,
        surface,
        ground_motion,
        solver_raw,
        newmark,
        free_vibration,
        allow,
        data_read,
    } = described;
    let automatic = bridge.modes().count.is_none() && bridge.modes().max_frequency.is_none();
    // Wheels with a mass of their own, an oscillator given by its groups
    // (derived from the bridge below) included.
    let wheel_mass = {
        let (vertical, lateral) = track_flexibility::wheels_with_mass(&vehicles, gravity);
        vertical
            || lateral
            || raw.vehicles.iter().any(|v| {
                matches!(v, crate::scenario::raw::VehicleRaw::Oscillator(o)
                    if o.dimensionless.as_ref().is_some_and(|d| d.unsprung_ratio.unwrap_or(0.0) > 0.0))
            })
    };
    let minimum = content::floor_modes(&bridge, &vehicles, wheel_mass);
    // The modes the solve will at least compute, before it starts.
    let (asked, asked_path) = match bridge.modes().count {
        Some(count) => (count, "bridge.modes.count"),
        None => (minimum, "bridge.spans"),
    };
    if (automatic || bridge.modes().count.is_some())
        && !(budget.check(ck, asked_path, "modes", "bridge modes kept", asked as f64)
            && eigen_fits(&budget, ck, asked_path, &bridge, asked))
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
        ) && eigen_fits(&budget, ck, "bridge.modes", &bridge, kept))
    {
        return None;
    }

    let cache = options.modes_cache.as_deref();
    // Modes of an imported model that nothing in the scene moves are left
    // out of the kept ones and of `count` (issue 40.6).
    let loads = content::scene_loads(&vehicles, &ground_motion, gravity);
    let build = |request| {
        ModalBridge::build_excited(&bridge, request, cache, options.par, Some(loads)).map_err(|e| {
            let path = match e {
                BridgeError::TooManyModes { .. } => "bridge.modes.count",
                BridgeError::NoModeBelow { .. } => "bridge.modes.max_frequency",
                _ => "bridge",
            };
            (path, e.to_string())
        })
    };
    let modal_built = crate::timings::stage(|| "the modal bridge".into());
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
    drop(modal_built);
    // The deck-acceleration filter of EN 1990 A2.4.4.2.1(4) is the
    // bridge's own max(30 Hz, 1.5 f₁, f₃), whatever `bridge.modes` keeps
    // (a cap that keeps one mode must not lower it to the kept top).
    let lowest = match super::acceleration::lowest_three(&bridge, &modal, cache, options.par) {
        Ok(f) => f,
        Err(e) => {
            ck.error("bridge", e.to_string());
            return None;
        }
    };
    let default_filter = super::acceleration::default_filter(&lowest);
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
    crate::scenario::surfaces::place_before_run_in(
        &mut vehicles,
        crate::scenario::surfaces::placement_run_in(&surface, raw.study.as_ref()),
        ck,
    );
    let travel = super::travel::travel(&vehicles, gravity, bridge.length(), free_vibration);
    if !crate::scenario::surfaces::check_reach(&surface, travel, &budget, ck) {
        return None;
    }
    let study = resolve_study(
        raw.study.as_ref(),
        &bridge,
        &vehicles,
        &contact,
        &surface,
        lowest.first().copied().unwrap_or(f64::NAN),
        default_filter,
        ck,
    );
    let points = study
        .as_ref()
        .map_or(1.0, |s| crate::scenario::sweep::study_points(s, &surface));
    if study.is_some() && !budget.check(ck, "study", "study_points", "runs of the study", points) {
        return None;
    }
    if let Some(study) = &study {
        super::plausible::check_study(ck, study, &vehicles, &contact, &modal, &bridge);
    }
    if !ck.diagnostics.is_empty() {
        return None;
    }
    let excitations = study_excitations(
        study.as_ref(),
        &vehicles,
        &contact,
        &surface,
        &bridge,
        gravity,
    );
    // The highest mode frequency any deck acceleration the runs record
    // sums: the records' and the envelope's; a resonance check's runs
    // record neither (they envelope the deck themselves, peaks only).
    let resonance_filter = match &study {
        Some(Study::ResonanceCheck(check)) => Some(check.max_frequency),
        _ => None,
    };
    let history_cutoff = match resonance_filter {
        Some(_) => None,
        None => [
            crate::scenario::records::highest_acceleration_cutoff(
                raw.record.as_deref(),
                default_filter,
            ),
            crate::scenario::envelopes::acceleration_cut(raw.envelopes.as_ref(), default_filter),
        ]
        .into_iter()
        .flatten()
        .reduce(f64::max),
    };
    // The modes they need, or a resonance check's, whose verdict reads the
    // deck acceleration.
    let record_cutoff = resonance_filter.or(history_cutoff);
    // Which contacts wheels with a mass of their own hold: what the rails'
    // flexibility under a wheel matters for ([`track_flexibility`]).
    let (vertical_mass, lateral_mass) = track_flexibility::wheels_with_mass(&vehicles, gravity);
    if automatic {
        let needs = modes::Needs {
            excitations: &excitations,
            record_cutoff,
            vehicles: &vehicles,
            ground_motion: &ground_motion,
            gravity,
            minimum,
            vertical_mass,
            lateral_mass,
        };
        let cutoff;
        (modal, cutoff) = modes::automatic(modal, &bridge, &needs, &budget, ck, &build)?;
        // Written back as the count kept and the cut-off (at least the
        // last kept mode's own frequency): the count cannot round a mode
        // away, the cut-off says why ([`ModalBridge::build_cached`]).
        bridge.modes_mut().count = Some(modal.mode_count());
        bridge.modes_mut().max_frequency = Some(cutoff);
    }
    if let Some(reason) = modal.left_out_reason() {
        modal.selection.push_str(&reason);
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
    // An imported track whose contacts get no static correction, under
    // wheels with mass: the share of the rails' flexibility the modes
    // leave out is missing, not a spring; measure it, however the modes
    // were chosen, so the run can say so ([`track_flexibility`]).
    if modal.is_imported()
        && (vertical_mass || lateral_mass)
        && (!modal.static_correction
            || ModalBridge::available_of(&bridge) > crate::bridge::CONTACT_CORRECTION_DOFS)
        && let Err(e) = {
            let _t = crate::timings::stage(|| "the rails' flexibility measured".into());
            track_flexibility::measure_without_correction(&mut modal, &bridge, lateral_mass)
        }
    {
        ck.error("bridge", e.to_string());
        return None;
    }
    // Deck accelerations sum every mode up to their filter: where the kept
    // modes stop below it (a `bridge.modes` the file sets), count the
    // bridge's modes there (one factorisation) so the run can say what the
    // sum misses.
    if let (Some(cut), Some(&top)) = (record_cutoff, modal.frequencies().last())
        && cut > top * (1.0 + crate::bridge::CUT_OFF_TOLERANCE)
        && let Ok(count) = super::acceleration::modes_up_to(&bridge, cut, cache, options.par)
        && count > modal.mode_count()
    {
        modal.acceleration_filter = Some(crate::bridge::AccelerationFilter {
            max_frequency: cut,
            modes: count,
        });
    }
    // A braking vehicle started slower may stop before the bridge.
    let slowest = match &study {
        Some(Study::SpeedSweep(sweep)) => Some(sweep.speed_range().0),
        Some(Study::MonteCarlo(mc)) => mc.speed_range().map(|r| r.0),
        _ => None,
    };
    if let Some(speed) = slowest
        && let Some(i) = crate::scenario::sweep::stops_before_entry(&vehicles, speed)
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

    // Default step: resolve the highest frequency excited. A speed sweep's
    // step serves its fastest run; its slowest run is the longest.
    let (fast, slow) = crate::scenario::sweep::extreme_vehicles(study.as_ref(), &vehicles);
    let frequencies = modal.frequencies();
    let modes_and_damping: Vec<(f64, f64)> = frequencies
        .iter()
        .copied()
        .zip(
            modal
                .damping_ratios
                .iter()
                .copied()
                .chain(std::iter::repeat(0.0)),
        )
        .collect();
    let every_mode = reads_every_mode(
        raw,
        &contact,
        vertical_mass || lateral_mass,
        !ground_motion.is_empty(),
    );
    let highest = content::excited_mode_top(&frequencies, &excitations, every_mode);
    let length = modal.length;
    let (shortest_crossing, shortest_run, longest_run) = time_step::run_lengths(
        study.as_ref(),
        &vehicles,
        (&fast, &slow),
        &modal,
        free_vibration,
    );
    let (time_step, step_without_ground, time_step_selection) = time_step::choose(
        solver_raw.time_step,
        (highest, &modes_and_damping),
        &excitations,
        history_cutoff,
        shortest_crossing,
        longest_run,
        &ground_motion,
    );
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
    let before_features = ck.diagnostics.len();
    crate::scenario::surfaces::check_features(&surface, top_speed, time_step, ck);
    crate::scenario::surfaces::check_lateral_followers(&surface, &vehicles, ck);
    // The surface's lengths once the grid's budgets and the features'
    // step checks have had their say (a key they refused is not refused
    // twice).
    crate::scenario::surfaces::check_lengths(&surface, ck, &|ck, path| {
        ck.blamed_since(before_features, path)
    });
    let steps = longest_run / time_step;
    let cause = crate::scenario::long_run::LongRun {
        raw,
        slow: &slow,
        ground_motion: &ground_motion,
        time_step,
        step_without_ground,
        duration: longest_run,
        free_vibration,
        bridge_length: length,
        acceleration_record: step_without_ground
            .and(history_cutoff)
            .and_then(|cut| raised_acceleration_record(raw, cut, default_filter)),
    }
    .cause(budget.limit_of("steps"));
    let steps_path = cause.path;
    let what = format!(
        "time steps of {time_step:.3e} s over the {longest_run:.4e} s run (the last vehicle's exit plus free vibration)"
    );
    if budget.check_because(ck, &steps_path, "steps", &what, steps, &cause.hint) {
        if points > 1.0 {
            budget.check(
                ck,
                "study",
                "study_steps",
                &format!("time steps over the study's {points} runs"),
                steps * points,
            );
        }
        let work = budget::RunWork::of(steps, modal.frequencies().len(), &slow);
        let (path, hint) =
            run_work_cause(&work, budget.limit_of("run_work"), &slow, &steps_path, ck);
        budget.check_because(ck, &path, "run_work", &work.what(), work.work(), &hint);
    }

    let method = resolve_method(solver_raw.method, &contact, ck);
    if method == SolverMethod::Direct {
        direct_supported(&modal, ck);
    }
    let iteration = resolve_iteration(&solver_raw, method, ck);
    let embs = resolve_embs(&solver_raw, method, ck);
    ck.records_checked = true;
    let record = resolve_records(
        raw.record.as_deref(),
        Some(default_filter),
        Some(&bridge),
        &vehicles,
        &contact,
        ck,
    );
    let envelopes = crate::scenario::envelopes::resolve_envelopes(
        raw.envelopes.as_ref(),
        Some(default_filter),
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
    let output = crate::scenario::output::resolve_output(raw.output.as_ref(), time_step, ck);
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
    // An imported model's mass and static deflection under the vehicles'
    // weight: what an engineer checks first ([`super::imported_check`]).
    if let Bridge::FeImport(fe) = &mut bridge {
        let _t = crate::timings::stage(|| "the imported model's totals".into());
        let weight = super::imported_check::static_weight(&vehicles, gravity);
        match super::imported_check::totals(&fe.model, &modal, weight) {
            Ok(totals) => fe.totals = Some(totals),
            Err(e) => {
                ck.error("bridge", e.to_string());
                return None;
            }
        }
    }
    let scenario = Scenario {
        source_file: None,
        data_read: data_read
            .into_iter()
            .chain(ck.data_read())
            .fold(Vec::new(), |mut all, r| {
                if !all
                    .iter()
                    .any(|a: &crate::scene::DataRead| a.path == r.path)
                {
                    all.push(r);
                }
                all
            }),
        name: raw.name.clone(),
        description: raw.description.clone(),
        allow,
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

/// What `method: direct` cannot step, refused when the scene is checked
/// (exit 2, at the key to change) rather than when the run starts: a
/// bridge that is neither a plane beam nor an imported model, and damping
/// that no C = c_M M + c_K K stands for (`solve::direct::assembled`).
fn direct_supported(modal: &ModalBridge, ck: &mut Checker<'_>) {
    if modal.beam_model().is_none() && modal.imported_shapes().is_none() {
        ck.error(
            "solver.method",
            "`method: direct` steps a plane beam's or an imported model's assembled matrices; \
             a 3D beam or a plate is not supported yet: use `method: coupled`",
        );
    } else if modal.rayleigh_damping.is_none() {
        let path = if ck.has("bridge.damping") {
            "bridge.damping"
        } else {
            "bridge"
        };
        ck.error(
            path,
            "`method: direct` needs a damping matrix C = c_M M + c_K K: a modal damping ratio \
             (or a damping matrix file) has none; use `damping: {type: rayleigh, ratio: ζ, \
             frequencies: [f₁, f₂]}`, or `method: coupled`",
        );
    }
}

/// The frequencies the scene's runs excite (each vehicle's axle passings,
/// body modes and surface features): a speed sweep's or Monte Carlo study's
/// at its fastest speed, every train of a resonance check at its top speed,
/// since the automatic choices must serve the study's fastest run.
fn study_excitations(
    study: Option<&Study>,
    vehicles: &[Vehicle],
    contact: &Contact,
    surface: &Surface,
    bridge: &Bridge,
    gravity: f64,
) -> Vec<content::Excitation> {
    match study {
        Some(Study::SpeedSweep(sweep)) => super::sweep::excitations(
            Some(sweep.speed_range().1),
            &crate::scenario::sweep::entries_of(sweep.roughness.as_deref()),
            vehicles,
            contact,
            surface,
            bridge,
            gravity,
        ),
        Some(Study::MonteCarlo(mc)) => super::sweep::excitations(
            mc.speed_range().map(|r| r.1),
            &crate::scenario::sweep::entries_of(mc.roughness.as_deref()),
            vehicles,
            contact,
            surface,
            bridge,
            gravity,
        ),
        // Every train of a resonance check at its top speed.
        Some(Study::ResonanceCheck(check)) => {
            let trains: Vec<Vehicle> = check
                .trains
                .iter()
                .map(|&t| crate::scenario::resonance::train_vehicle(t, check.top_speed()))
                .collect();
            content::excitations(&trains, contact, surface, bridge.spans(), gravity)
        }
        _ => content::excitations(vehicles, contact, surface, bridge.spans(), gravity),
    }
}

/// The deck-acceleration record whose own `max_frequency`, above the
/// EN 1990 filter `default_filter` (Hz), is the highest cut-off `cut` (Hz)
/// the automatic modes were kept to: its path in the file, the cut-off and
/// the filter (the cause named where the step budget is hit, issue 38).
fn raised_acceleration_record(
    raw: &ScenarioRaw,
    cut: f64,
    default_filter: f64,
) -> Option<(String, f64, f64)> {
    let records = raw.record.as_deref()?;
    records.iter().enumerate().find_map(|(i, r)| {
        let own = r.max_frequency.filter(|f| f.is_finite())?;
        (r.quantity == crate::scene::Quantity::BridgeAcceleration
            && own == cut
            && own > default_filter * 1.5)
            .then(|| (format!("record[{i}].max_frequency"), own, default_filter))
    })
}

/// Where to blame a run whose work ([`budget::RunWork`]) exceeds `limit`,
/// and what would fit: the vehicle with the most wheels when their contact
/// system makes most of a step, else the bridge's modes; either way also
/// the steps that fit (`steps_path`, where the run's length comes from,
/// is blamed for the modes the file leaves automatic).
fn run_work_cause(
    work: &budget::RunWork,
    limit: f64,
    vehicles: &[Vehicle],
    steps_path: &str,
    ck: &Checker<'_>,
) -> (String, String) {
    let steps = work.steps_fitting(limit);
    let shorter = format!("or keep them and make the run at most {steps} steps long");
    if work.wheels_dominate() {
        let wheels_of = |v: &Vehicle| match v {
            Vehicle::MovingForce(_) => 0,
            Vehicle::Oscillator(_) => 1,
            Vehicle::H20Truck(_) | Vehicle::RailCar(_) => 4,
            Vehicle::Train(t) => 4 * t.cars.len(),
            Vehicle::Train3d(t) => 12 * t.cars.len(),
        };
        let (i, most) = vehicles
            .iter()
            .enumerate()
            .map(|(i, v)| (i, wheels_of(v)))
            .fold((0, 0), |a, b| if b.1 > a.1 { b } else { a });
        let at = format!("vehicles[{i}]");
        let path = [format!("{at}.count"), format!("{at}.cars")]
            .into_iter()
            .find(|p| ck.has(p))
            .unwrap_or(at);
        let fitting = work.wheels_fitting(limit);
        let per_car = match vehicles.get(i) {
            Some(Vehicle::Train(_)) => Some(4.0),
            Some(Vehicle::Train3d(_)) => Some(12.0),
            _ => None,
        };
        let cars = per_car.map_or(String::new(), |w| {
            let others = work.coupled_wheels - most as f64;
            let cars = ((fitting - others) / w).floor().max(0.0);
            if path.ends_with(".count") {
                format!(" (this train: `count: {cars}`)")
            } else {
                format!(" (this train: at most {cars} cars)")
            }
        });
        let hint = format!(
            "vehicle {} has {most} of the {} wheels; over these {} steps at most {fitting} \
             wheels fit{cars}, {shorter}",
            i + 1,
            work.coupled_wheels,
            work.steps.ceil(),
        );
        return (path, hint);
    }
    let path = ["bridge.modes.count", "bridge.modes"]
        .into_iter()
        .find(|p| ck.has(p))
        .unwrap_or(steps_path)
        .to_owned();
    let modes = work.modes_fitting(limit);
    let hint = format!(
        "over these {} steps at most {modes} modes fit (`bridge.modes: {{count: {modes}}}`), \
         {shorter}",
        work.steps.ceil(),
    );
    (path, hint)
}
