//! Warnings about a scene that is valid but probably not what was meant, and
//! about results that probably miss their peak. They never stop a run; the
//! command line prints them on stderr as `warning: …`.

use crate::report::summary::Summary;
use crate::scenario::raw::{KM_H, km_h_to_m_s};
use crate::scene::{Quantity, Scenario, Study, Surface};
use crate::surface::fade_start;
use crate::surface::spectrum::{FRA_MAX_SPEED_MPH, fra_max_speed};

/// Speeds above this, m/s (468 km/h), are faster than any wheeled vehicle in
/// service: the fastest trains run at 350 km/h and an EN 1991-2 resonance
/// check goes to 1.2 × the line speed (420 km/h for 350 km/h). Such a speed
/// written as a bare number is most often a km/h value typed where m/s is
/// meant; written with its unit it is meant (a moving force at a stiff
/// beam's critical speed 2 f₁ L can be far faster than any train).
pub const IMPLAUSIBLE_SPEED: f64 = 130.0;

/// Largest plausible |acceleration| along the path, m/s²: a road vehicle's
/// emergency braking on dry asphalt reaches about 1 g; trains brake at
/// 1–1.5 m/s² (service) to about 2.5 m/s² (emergency with track brakes).
pub const IMPLAUSIBLE_ACCELERATION: f64 = 10.0;

/// Contact forces whose peak falls on an imported track's entry or exit
/// ramp: within `bridge.entry_length` of a free rail end the load passes
/// between the model and the rigid approach ([`crate::bridge::fe_import::entry`]),
/// and the free rail end, which a real line does not have, is the track's
/// most flexible point. Measured on the golden EMBS viaduct: the wheelset's
/// lateral force peaks at 78 kN 2.6 m from the exit end (x = 38.6 m of
/// 39 m); on a generated 2 × 20 m viaduct a rail car's wheel force peaked
/// at 121 kN on the exit ramp against 111 kN over the deck.
fn peaks_on_a_rail_end_ramp(scenario: &Scenario, summary: &Summary) -> Vec<String> {
    let crate::scene::Bridge::FeImport(fe) = &scenario.bridge else {
        return Vec::new();
    };
    let (start_free, end_free) = fe.model.free_rail_ends();
    let ramp = fe.entry_length;
    let end = fe.model.entry.end;
    if ramp <= 0.0 {
        return Vec::new();
    }
    summary
        .quantities
        .iter()
        .filter(|q| q.quantity == Quantity::ContactForce)
        .filter_map(|q| {
            let x = q.max_abs.position;
            let which = if start_free && (0.0..ramp).contains(&x) {
                "entry"
            } else if end_free && (end - ramp..=end).contains(&x) {
                "exit"
            } else {
                return None;
            };
            Some(format!(
                "`{}` is largest on the track's {which} ramp (x = {x:.4} m, within the {ramp} m \
                 of `bridge.entry_length` from the model's free rail end, where the load passes \
                 between the model and the rigid approach): the free rail end is the model's, \
                 not the line's, so read the peak away from the track's ends (history.csv), or \
                 extend the model's approach track",
                q.name
            ))
        })
        .collect()
}

/// Deck accelerations whose filter reaches above the modes kept, on a bridge
/// that has modes there: EN 1990 A2.4.4.2.1(4) sums every mode up to
/// max(30 Hz, 1.5 f₁, f₃), and the modes between the kept top and the
/// filter are missing from the sum, without a word, when `bridge.modes`
/// stops below it. Measured on the shipped 30-span viaduct (modes to
/// 15 Hz, 30 Hz filter): the deck accelerations are 21–36 % off the same
/// run with modes to 30 Hz.
fn accelerations_above_the_modes(scenario: &Scenario, summary: &Summary) -> Vec<String> {
    let run = &summary.run;
    let (Some(filter), Some(&top)) = (run.modes_to_acceleration_filter, run.frequencies.last())
    else {
        return Vec::new();
    };
    let above = |cut: f64| cut > top * (1.0 + crate::bridge::CUT_OFF_TOLERANCE);
    let mut names: Vec<String> = scenario
        .record
        .iter()
        .filter(|r| r.quantity == Quantity::BridgeAcceleration)
        .filter_map(|r| {
            r.max_frequency
                .filter(|&cut| above(cut))
                .map(|cut| format!("`{}` ({cut} Hz)", r.name))
        })
        .collect();
    if let Some(envelopes) = &scenario.envelopes
        && envelopes.quantities.contains(&Quantity::BridgeAcceleration)
        && let Some(cut) = envelopes.max_frequency.filter(|&cut| above(cut))
    {
        names.push(format!("the acceleration envelope ({cut} Hz)"));
    }
    if names.is_empty() {
        return Vec::new();
    }
    let one = names.len() == 1;
    vec![format!(
        "{} {} every mode up to {} (the deck-acceleration filter, EN 1990 A2.4.4.2.1), but the \
         bridge keeps {} modes, up to {top:.2} Hz, of the {} it has up to {} Hz: the modes \
         between are missing from {}; keep the modes up to the filter (`bridge.modes: \
         {{max_frequency: {}}}`, or leave `bridge.modes` out and the automatic choice keeps \
         them), or lower the record's `max_frequency` if a lower filter is meant",
        names.join(", "),
        if one { "sums" } else { "sum" },
        if one { "its cut-off" } else { "their cut-offs" },
        run.modes_used,
        filter.modes,
        filter.max_frequency,
        if one { "it" } else { "them" },
        filter.max_frequency,
    )]
}

/// Warnings about the scene itself, before it runs.
pub fn scene_warnings(scenario: &Scenario) -> Vec<String> {
    let mut out = Vec::new();
    for (i, vehicle) in scenario.vehicles.iter().enumerate() {
        // A speed written with its unit (`238.9 m/s`) is meant: a moving
        // force at a beam's critical speed 2 f₁ L is often far faster
        // than any train. Only a bare number can be a km/h value typed as
        // m/s.
        let stated = scenario.speeds_stated.get(i).copied().unwrap_or(false);
        if let Some(w) = implausible(&format!("vehicle {}", i + 1), vehicle.speed())
            && !stated
        {
            let v = vehicle.speed();
            out.push(format!("{w}; if {v} m/s is meant, write `speed: {v} m/s`"));
        }
        let a = vehicle.acceleration();
        if a.abs() > IMPLAUSIBLE_ACCELERATION {
            out.push(format!(
                "vehicle {}: an acceleration of {a} m/s² is more than a vehicle on wheels \
                 reaches ({IMPLAUSIBLE_ACCELERATION} m/s², about 1 g of braking); accelerations are in m/s²",
                i + 1
            ));
        }
    }
    if let Some(Study::SpeedSweep(sweep)) = &scenario.study
        && let Some(w) = implausible("the speed sweep's top speed", sweep.speeds.to)
    {
        out.push(w);
    }
    out.extend(track_class_too_slow(scenario));
    out.extend(fade_on_the_bridge(scenario));
    out.extend(measured_finer_than_a_step(scenario));
    out
}

/// A measured profile whose points are closer than a wheel's travel in one
/// time step: the wheels see the spline only at the steps, so its features
/// between them are missed (aliased). Not refused: dense profilometer data
/// are common and the spline between the points stays right.
fn measured_finer_than_a_step(scenario: &Scenario) -> Option<String> {
    let Surface::Measured { file, profile } = &scenario.surface else {
        return None;
    };
    let speed = scenario
        .vehicles
        .iter()
        .map(|v| v.speed())
        .fold(0.0, f64::max);
    let travel = speed * scenario.solver.time_step;
    let (i, spacing) = profile
        .x
        .windows(2)
        .map(|w| w[1] - w[0])
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(&b.1))?;
    (spacing < travel).then(|| {
        format!(
            "{file}: the points at x = {} m and {} m are {spacing:e} m apart, less than the \
             {travel:.4e} m a wheel travels in one time step ({speed:.4} m/s × {:e} s): the \
             wheels see the profile only at the steps and miss its features between them; \
             set `solver.time_step` to at most {:.4e} s to follow every point",
            profile.x[i],
            profile.x[i + 1],
            scenario.solver.time_step,
            spacing / speed
        )
    })
}

/// FRA track classes run faster than the speed they are maintained for
/// (49 CFR 213.9(a), 213.307(a)): the spectrum is that of a slower,
/// rougher line than such a train would run on.
fn track_class_too_slow(scenario: &Scenario) -> Vec<String> {
    let (entries, study_top) = match &scenario.study {
        Some(Study::MonteCarlo(mc)) => (
            mc.roughness.as_deref(),
            mc.speed_range().map_or(0.0, |r| r.1),
        ),
        Some(Study::SpeedSweep(sweep)) => (sweep.roughness.as_deref(), sweep.speed_range().1),
        _ => (None, 0.0),
    };
    let top = scenario
        .vehicles
        .iter()
        .map(|v| v.speed())
        .fold(study_top, f64::max);
    let mut classes: Vec<u8> = match &scenario.surface {
        Surface::Fra { class, .. } => vec![*class],
        _ => Vec::new(),
    };
    classes.extend(entries.into_iter().flatten().filter_map(|e| e.fra_class()));
    classes.sort_unstable();
    classes.dedup();
    classes
        .into_iter()
        .filter(|&class| top > fra_max_speed(class))
        .map(|class| {
            let (freight, passenger) = FRA_MAX_SPEED_MPH[usize::from(class.clamp(1, 6)) - 1];
            let rule = if class >= 6 { "213.307(a)" } else { "213.9(a)" };
            format!(
                "FRA track class {class} is maintained for at most {freight} mph freight and \
                 {passenger} mph passenger trains ({:.0} km/h; 49 CFR {rule}), but a vehicle runs at \
                 {:.0} km/h: its irregularities are those of a line kept for far lower speeds \
                 (FRA class 6 allows 110 mph; the German low- and high-interference spectra, \
                 `type: german`, are for high-speed lines)",
                fra_max_speed(class) / KM_H,
                top / KM_H
            )
        })
        .collect()
}

/// A vehicle placed after the start of a spectrum's run-in: the fade then
/// starts under its front axle and reaches onto the bridge.
fn fade_on_the_bridge(scenario: &Scenario) -> Option<String> {
    let (_, sampling) = scenario.surface.spectrum()?;
    let front = scenario
        .vehicles
        .iter()
        .map(|v| v.motion().position(0.0))
        .fold(f64::NEG_INFINITY, f64::max);
    let start = fade_start(sampling.run_in, front);
    let end = start + sampling.run_in;
    (sampling.run_in > 0.0 && end > 0.0).then(|| {
        format!(
            "a vehicle starts at x = {front:.4} m, inside the surface's {} m run-in: the profile \
             fades in from under its front axle to x = {end:.4} m, so the bridge's first {end:.4} m \
             are below full roughness; start every vehicle at or before x = {} m (leave \
             `start_position` and `entry_time` out to have it placed there)",
            sampling.run_in, -sampling.run_in
        )
    })
}

fn implausible(what: &str, speed: f64) -> Option<String> {
    (speed > IMPLAUSIBLE_SPEED).then(|| {
        format!(
            "{what}: {speed} m/s is {:.0} km/h, faster than any wheeled vehicle in service; \
             speeds are in m/s — for {speed} km/h write `speed: {speed} km/h` ({:.4} m/s)",
            speed / KM_H,
            km_h_to_m_s(speed)
        )
    })
}

/// Warnings about a finished run: a bridge response whose largest value is
/// its last recorded one was still growing when the record ended, so its
/// peak comes later (above the critical speed the largest deflection comes
/// after the load has left the span, in free vibration).
pub fn run_warnings(scenario: &Scenario, summary: &Summary) -> Vec<String> {
    let run = &summary.run;
    let last = run.end_time - 0.5 * run.time_step;
    let period = run.frequencies.first().map(|f| 1.0 / f);
    let mut out = Vec::new();
    if let Some(why) = &run.modes_cache_rejected {
        out.push(format!(
            "the modes cache file of this model was not used ({why}): the modes were solved \
             afresh and the file rewritten"
        ));
    }
    if let Some(embs) = &summary.embs {
        out.extend(embs.warnings());
    }
    // An imported track whose free rail end takes the whole load at once
    // (`entry_length: 0`): the step rings track modes above the automatic
    // cut (measured on scenarios/viaduct-2span-axle-loads.yaml with the
    // entry removed; README, "Imported FE models").
    if let crate::scene::Bridge::FeImport(fe) = &scenario.bridge {
        let (start, end) = fe.model.free_rail_ends();
        if (start || end) && fe.entry_length == 0.0 && run.modes_selection.starts_with("automatic")
        {
            out.push(
                "the automatic mode choice is not verified against its 0.5 % target here: with \
                 `bridge.entry_length: 0` each axle puts its whole load on a free rail end in one \
                 instant, which rings track modes above the cut (rail displacement 3.7 % off on \
                 the shipped viaduct-2span-axle-loads, 0.35 % with the default 3 m entry); \
                 check this run with `vbi converge`, set `bridge.modes`, or let the load enter \
                 over `bridge.entry_length`"
                    .to_string(),
            );
        }
    }
    // The kept modes leave out more of the rails' flexibility under a wheel
    // than the automatic choice allows (crate::plan::track_flexibility).
    if let Some(rails) = summary.run.rails_flexibility
        && rails.left_out > crate::plan::track_flexibility::TRACK_RESIDUAL_SHARE
    {
        let modes = run.modes_selection.trim_start_matches("automatic: ");
        if rails.limited {
            out.push(format!(
                "the automatic modes stop at the limits: {modes}; raise `limits.modes` and \
                 `limits.eigen_work` in the file and run with `--trust-limits` (or run with \
                 `--allow-large`), or set `bridge.modes` and check the run with `vbi converge`"
            ));
        } else if !rails.static_correction {
            out.push(format!(
                "the bridge modes leave out {:.0} % of the rails' static flexibility under a \
                 wheel at a typical rail point ({}{:.0} % by the automatic rule's measure, \
                 against the most flexible point), and the contacts carry no static \
                 correction for it: the wheels ride on rails stiffer than the model's by that \
                 share and their bounce on the track is not modelled, so the contact forces, \
                 the rail records and the accelerations are not converged at these modes (the \
                 shipped 30-span viaduct, 15 Hz against 30 Hz modes, neither carrying that \
                 share: rail displacement 17 %, deck accelerations 21-36 % apart; deck \
                 displacements within 0.8 %); keep more modes (`bridge.modes`) and check the \
                 run with `vbi converge`",
                100.0 * rails.typical_left_out,
                if rails.every_node { "" } else { "at least " },
                100.0 * rails.left_out,
            ));
        }
    }
    out.extend(accelerations_above_the_modes(scenario, summary));
    out.extend(ground_motion_after_the_run(scenario, summary));
    out.extend(entrance_kick(scenario, summary));
    out.extend(peaks_on_a_rail_end_ramp(scenario, summary));
    out.extend(summary
        .quantities
        .iter()
        .filter(|q| {
            matches!(
                q.quantity,
                Quantity::BridgeDisplacement
                    | Quantity::BridgeAcceleration
                    | Quantity::BridgeMoment
                    | Quantity::BridgeShear
            ) && q.max_abs.time >= last
                && q.max_abs.value != 0.0
        })
        .map(|q| {
            let advice = match period {
                Some(t) => format!(
                    "; record longer with `solver.free_vibration` (now {} s; the first mode's period is {t:.4} s)",
                    scenario.solver.free_vibration
                ),
                None => String::new(),
            };
            format!(
                "`{}` is largest at the very end of the record (t = {:.4} s): its peak is \
                 probably later{advice}",
                q.name, q.max_abs.time
            )
        })
        .collect::<Vec<_>>(),
    );
    out
}

/// A ground-motion record that still shakes when the run ends: its largest
/// |üg| after the end is at least half of its largest during the run, so
/// the bridge's response to it (and every absolute acceleration) may peak
/// after the run, which stops `solver.free_vibration` after the last axle
/// leaves (measured on examples/seismic-crossing.yaml: 0.098 g after the
/// end against 0.100 g during the run, the deck's absolute acceleration
/// largest 4 ms before the end).
fn ground_motion_after_the_run(scenario: &Scenario, summary: &Summary) -> Vec<String> {
    let end = summary.run.end_time;
    let bridge_recorded = summary.quantities.iter().any(|q| {
        matches!(
            q.quantity,
            Quantity::BridgeDisplacement
                | Quantity::BridgeAcceleration
                | Quantity::BridgeMoment
                | Quantity::BridgeShear
        )
    });
    if !bridge_recorded {
        return Vec::new();
    }
    scenario
        .ground_motion
        .iter()
        .filter_map(|motion| {
            let record = &motion.record;
            let largest = |after: bool| {
                record
                    .time
                    .iter()
                    .zip(&record.acceleration)
                    .filter(|&(&t, _)| (t > end) == after && (after || t >= 0.0))
                    .fold(0.0f64, |m, (_, a)| m.max(a.abs()))
            };
            let (during, after) = (largest(false), largest(true));
            let record_end = *record.time.last()?;
            (after > 0.0 && after >= 0.5 * during).then(|| {
                format!(
                    "the {} record `{}` still shakes when the run ends at t = {end:.4} s: its \
                     largest |üg| afterwards is {:.3} m/s² against {:.3} m/s² during the run, \
                     so the bridge's response to it may peak later; to cover the record, set \
                     `solver.free_vibration` so the run lasts to t = {record_end:.2} s",
                    motion.direction.name(),
                    std::path::Path::new(&motion.file)
                        .file_name()
                        .map_or(motion.file.as_str(), |n| n.to_str().unwrap_or("")),
                    after,
                    during,
                )
            })
        })
        .collect()
}

/// A contact force whose largest value is the entrance's kick: a vertical
/// harmonic surface r = a·sin(2πx/λ + φ) starts at the entrance at
/// r(0) = a·sin φ above the flat approach, with slope r′(0) = (2πa/λ)·cos φ
/// (README, "Surface"), so each wheel meets a step in elevation, in slope,
/// or both, as it enters: an impact under rigid contact, a spike under
/// elastic contact. Said when a `contact_force` record peaks within the
/// first tenth of a wavelength past the entrance. Measured on a 300 kg
/// wheel at 25 m/s over a 4 mm, 1.5 m surface (static load 23 kN): φ = 0
/// (slope step 0.017) under rigid contact, 205 kN at x = 7.5 mm; φ = 90°
/// (a 4 mm step), 53 MN under rigid and 4.0 MN under elastic contact, the
/// wheel then thrown 0.64 m and 0.08 m into the air.
fn entrance_kick(scenario: &Scenario, summary: &Summary) -> Vec<String> {
    let Surface::Harmonic {
        amplitude,
        wavelength,
        phase,
        direction,
    } = &scenario.surface
    else {
        return Vec::new();
    };
    let start = amplitude * phase.sin();
    let slope = 2.0 * std::f64::consts::PI * amplitude / wavelength * phase.cos();
    // sin π is 1.2e-16, not 0: a start below a nanometre is level.
    if !direction.is_vertical() || (start.abs() < 1e-9 && slope.abs() < 1e-9) {
        return Vec::new();
    }
    summary
        .quantities
        .iter()
        .filter(|q| {
            q.quantity == Quantity::ContactForce
                && (0.0..=0.1 * wavelength).contains(&q.max_abs.position)
        })
        .map(|q| {
            let level = if start.abs() >= 1e-9 {
                format!(
                    "starts {:.3} mm {} the flat approach (phase {phase:.4} rad), a step every \
                     wheel hits as it enters; phase 0 or 180 deg starts it level",
                    start.abs() * 1e3,
                    if start > 0.0 { "above" } else { "below" }
                )
            } else {
                format!(
                    "starts level with slope {slope:.4}, so each wheel's vertical velocity steps \
                     by speed × slope as it enters"
                )
            };
            format!(
                "`{}` is largest at the entrance (x = {:.4} m): the harmonic surface {level}; \
                 that kick, not the crossing, is this peak",
                q.name, q.max_abs.position
            )
        })
        .collect()
}
