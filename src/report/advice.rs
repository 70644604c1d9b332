//! Advice about a finished run: results that probably miss their peak, or
//! that the model cannot converge ([`crate::advice`]). The run puts it in
//! its summary ([`Summary::advice`]) with the scene's own advice
//! ([`crate::plan::advice::scene_advice`]); only the front ends print it.

use crate::advice::{self, Advice};
use crate::record::DirectReading;
use crate::report::summary::Summary;
use crate::scene::{Quantity, Scenario, SolverMethod, Surface};

/// Every piece of advice about `scenario` and its run's `summary`: the
/// scene's (before it ran) then the run's, the scene's `allow` applied.
pub fn advice_of(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
    let mut out = crate::plan::advice::scene_advice(scenario);
    out.extend(run_advice(scenario, summary));
    out
}

/// Advice about a finished run, the scene's `allow` applied: a bridge
/// response whose largest value is its last recorded one was still growing
/// when the record ended, so its peak comes later (above the critical speed
/// the largest deflection comes after the load has left the span, in free
/// vibration); and the model's own limits where the run meets them.
pub fn run_advice(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
    let run = &summary.run;
    let mut out = Vec::new();
    if let Some(why) = &run.modes_cache_rejected {
        out.push(Advice::new(
            &advice::MODES_CACHE_REJECTED,
            format!(
                "the modes cache file of this model was not used ({}): the modes were solved \
                 afresh and the file rewritten",
                crate::scenario::diagnostic::escaped(why)
            ),
        ));
    }
    if let Some(embs) = &summary.embs {
        out.extend(embs.advice());
    }
    out.extend(unverified_entry(scenario, summary));
    out.extend(rails_left_out(summary));
    out.extend(accelerations_above_the_modes(scenario, summary));
    out.extend(ground_motion_after_the_run(scenario, summary));
    out.extend(entrance_kick(scenario, summary));
    out.extend(peaks_on_a_rail_end_ramp(scenario, summary));
    out.extend(peaks_at_the_end(scenario, summary));
    out.extend(direct_records_on_kept_modes(scenario, summary));
    advice::apply_allow(&mut out, &scenario.allow);
    out
}

/// An imported track whose free rail end takes the whole load at once
/// (`entry_length: 0`): the step rings track modes above the automatic
/// cut (measured on scenarios/viaduct-2span-axle-loads.yaml with the
/// entry removed; docs/guide/imports.md).
fn unverified_entry(scenario: &Scenario, summary: &Summary) -> Option<Advice> {
    let crate::scene::Bridge::FeImport(fe) = &scenario.bridge else {
        return None;
    };
    let (start, end) = fe.model.free_rail_ends();
    ((start || end)
        && fe.entry_length == 0.0
        && summary.run.modes_selection.starts_with("automatic"))
    .then(|| {
        Advice::new(
            &advice::AUTOMATIC_MODES_UNVERIFIED,
            "the automatic mode choice is not verified against its 0.5 % target here: with \
             `bridge.entry_length: 0` each axle puts its whole load on a free rail end in one \
             instant, which rings track modes above the cut (rail displacement 3.7 % off on \
             the shipped viaduct-2span-axle-loads, 0.35 % with the default 3 m entry)",
        )
        .at("bridge.entry_length")
        .help(
            "check this run with `vbi converge`, set `bridge.modes`, or let the load enter \
             over `bridge.entry_length`",
        )
    })
}

/// The kept modes leave out more of the rails' flexibility under a wheel
/// than the automatic choice allows (crate::plan::track_flexibility).
fn rails_left_out(summary: &Summary) -> Option<Advice> {
    let run = &summary.run;
    let rails = run.rails_flexibility?;
    if rails.left_out <= crate::plan::track_flexibility::TRACK_RESIDUAL_SHARE {
        return None;
    }
    let modes = run.modes_selection.trim_start_matches("automatic: ");
    if rails.limited {
        return Some(
            Advice::new(
                &advice::AUTOMATIC_MODES_AT_LIMITS,
                format!("the automatic modes stop at the limits: {modes}"),
            )
            .at("limits.modes")
            .help(
                "raise `limits.modes` and `limits.eigen_work` in the file and run with \
                 `--trust-limits` (or run with `--allow-large`), or set `bridge.modes` and \
                 check the run with `vbi converge`",
            )
            .figure("share_left_out", rails.left_out)
            .figure("modes_used", run.modes_used as f64),
        );
    }
    (!rails.static_correction).then(|| {
        Advice::new(
            &advice::RAILS_FLEXIBILITY_LEFT_OUT,
            format!(
                "the bridge modes leave out {:.0} % of the rails' static flexibility under a \
                 wheel at a typical rail point ({}{:.0} % by the automatic rule's measure, \
                 against the most flexible point), and the contacts carry no static \
                 correction for it: the wheels ride on rails stiffer than the model's by that \
                 share and their bounce on the track is not modelled, so the contact forces, \
                 the rail records and the accelerations are not converged at these modes (the \
                 shipped 30-span viaduct, 15 Hz against 30 Hz modes, neither carrying that \
                 share: rail displacement 17 %, deck accelerations 21-36 % apart; deck \
                 displacements within 0.8 %)",
                100.0 * rails.typical_left_out,
                if rails.every_node { "" } else { "at least " },
                100.0 * rails.left_out,
            ),
        )
        .at("bridge.modes")
        .help("keep more modes (`bridge.modes`) and check the run with `vbi converge`")
        .figure("typical_share_left_out", rails.typical_left_out)
        .figure("share_left_out", rails.left_out)
        .figure("modes_used", run.modes_used as f64)
    })
}

/// A `direct` run with bridge records that its kept modes truncate: deck
/// accelerations (or the acceleration envelope) filtered above the kept
/// modes yet below the model's top, read from the nodal state's projection
/// q = ΦᵀMu onto the kept modes ([`crate::record::direct_reading`]); every
/// other bridge record reads the nodal state itself, exact in space.
fn direct_records_on_kept_modes(scenario: &Scenario, summary: &Summary) -> Option<Advice> {
    let run = &summary.run;
    if scenario.solver.method != SolverMethod::Direct || run.modes_used >= run.modes_available {
        return None;
    }
    let kept = crate::record::KeptModes {
        frequencies: &run.frequencies,
        available: run.modes_available,
        filter: run.modes_to_acceleration_filter,
    };
    // The truncated records' names and filters (Hz).
    let mut truncated: Vec<(String, f64)> = scenario
        .record
        .iter()
        .filter(|r| {
            is_bridge_quantity(r.quantity)
                && crate::record::direct_reading(r, &kept) == DirectReading::Truncated
        })
        .map(|r| {
            (
                format!("`{}`", r.name),
                r.max_frequency.unwrap_or(f64::INFINITY),
            )
        })
        .collect();
    if let Some(envelopes) = &scenario.envelopes
        && envelopes.quantities.iter().any(|&q| {
            crate::record::direct_envelope_reading(q, envelopes.max_frequency, &kept)
                == DirectReading::Truncated
        })
    {
        let cut = envelopes.max_frequency.unwrap_or(f64::INFINITY);
        truncated.push(("the acceleration envelope".to_owned(), cut));
    }
    let cut = truncated.iter().map(|t| t.1).reduce(f64::max)?;
    let names: Vec<&str> = truncated.iter().map(|t| t.0.as_str()).collect();
    let top = run.frequencies.last().copied().unwrap_or(0.0);
    Some(
        Advice::new(
            &advice::DIRECT_RECORDS_ON_KEPT_MODES,
            format!(
                "the direct solution is exact in space, but the deck accelerations filtered \
                 above the {} kept modes of the model's {} ({}) read it projected onto the kept \
                 modes: they miss the modes between the kept top ({} Hz) and their filter (up \
                 to {} Hz); the other bridge records read the nodal state itself, and the \
                 vehicle and contact records are the solution's own",
                run.modes_used,
                run.modes_available,
                names.join(", "),
                hz(top),
                hz(cut)
            ),
        )
        .at("bridge.modes")
        .help(format!(
            "keep the modes up to the filter (`bridge.modes: {{max_frequency: {}}}`), or every \
             mode (`bridge.modes: {{count: {}}}`)",
            (cut * 10.0).ceil() / 10.0,
            run.modes_available
        ))
        .figure("modes_used", run.modes_used as f64)
        .figure("modes_available", run.modes_available as f64)
        .figure("filter_hz", cut),
    )
}

/// Whether `quantity` is a response of the bridge (displacement,
/// acceleration, moment or shear), which goes on after the vehicles leave.
fn is_bridge_quantity(quantity: Quantity) -> bool {
    matches!(
        quantity,
        Quantity::BridgeDisplacement
            | Quantity::BridgeAcceleration
            | Quantity::BridgeMoment
            | Quantity::BridgeShear
            | Quantity::BridgeReaction
    )
}

/// A bridge response whose largest value is its last recorded one.
fn peaks_at_the_end(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
    let run = &summary.run;
    let last = run.end_time - 0.5 * run.time_step;
    let period = run.frequencies.first().map(|f| 1.0 / f);
    summary
        .quantities
        .iter()
        .filter(|q| {
            is_bridge_quantity(q.quantity) && q.max_abs.time >= last && q.max_abs.value != 0.0
        })
        .map(|q| {
            let a = Advice::new(
                &advice::RUN_ENDS_AT_PEAK,
                format!(
                    "`{}` is largest at the very end of the record (t = {:.4} s): its peak is \
                     probably later",
                    q.name, q.max_abs.time
                ),
            )
            .at(record_path(scenario, &q.name))
            .figure("time_s", q.max_abs.time)
            .figure("free_vibration_s", scenario.solver.free_vibration);
            match period {
                // The original wording joined its help with "; ".
                Some(t) => a
                    .help(format!(
                        "record longer with `solver.free_vibration` (now {} s; the first \
                         mode's period is {t:.4} s)",
                        scenario.solver.free_vibration
                    ))
                    .figure("first_period_s", t),
                None => a,
            }
        })
        .collect()
}

/// Contact forces whose peak falls on an imported track's entry or exit
/// ramp: within `bridge.entry_length` of a free rail end the load passes
/// between the model and the rigid approach ([`crate::bridge::fe_import::entry`]),
/// and the free rail end, which a real line does not have, is the track's
/// most flexible point. Measured on the golden EMBS viaduct: the wheelset's
/// lateral force peaks at 78 kN 2.6 m from the exit end (x = 38.6 m of
/// 39 m); on a generated 2 × 20 m viaduct a rail car's wheel force peaked
/// at 121 kN on the exit ramp against 111 kN over the deck.
fn peaks_on_a_rail_end_ramp(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
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
            Some(
                Advice::new(
                    &advice::CONTACT_PEAK_ON_RAIL_END,
                    format!(
                        "`{}` is largest on the track's {which} ramp (x = {x:.4} m, within the \
                         {ramp} m of `bridge.entry_length` from the model's free rail end, where \
                         the load passes between the model and the rigid approach): the free \
                         rail end is the model's, not the line's",
                        q.name
                    ),
                )
                .at(record_path(scenario, &q.name))
                .help(
                    "read the peak away from the track's ends (history.csv), or extend the \
                     model's approach track",
                )
                .figure("position_m", x)
                .figure("entry_length_m", ramp),
            )
        })
        .collect()
}

/// A frequency in Hz to 0.01 Hz, without trailing zeros (`30`, `68.83`):
/// a filter the file gives reads as written, a computed f₃ stays short.
fn hz(f: f64) -> String {
    let text = format!("{f:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// Deck accelerations whose filter reaches above the modes kept, on a bridge
/// that has modes there: EN 1990 A2.4.4.2.1(4) sums every mode up to
/// max(30 Hz, 1.5 f₁, f₃), and the modes between the kept top and the
/// filter are missing from the sum, without a word, when `bridge.modes`
/// stops below it. Measured on the shipped 30-span viaduct (modes to
/// 15 Hz, 30 Hz filter): the deck accelerations are 21–36 % off the same
/// run with modes to 30 Hz.
fn accelerations_above_the_modes(scenario: &Scenario, summary: &Summary) -> Option<Advice> {
    let run = &summary.run;
    let (Some(filter), Some(&top)) = (run.modes_to_acceleration_filter, run.frequencies.last())
    else {
        return None;
    };
    let above = |cut: f64| cut > top * (1.0 + crate::bridge::CUT_OFF_TOLERANCE);
    let mut names: Vec<String> = scenario
        .record
        .iter()
        .filter(|r| r.quantity == Quantity::BridgeAcceleration)
        .filter_map(|r| {
            r.max_frequency
                .filter(|&cut| above(cut))
                .map(|cut| format!("`{}` ({} Hz)", r.name, hz(cut)))
        })
        .collect();
    if let Some(envelopes) = &scenario.envelopes
        && envelopes.quantities.contains(&Quantity::BridgeAcceleration)
        && let Some(cut) = envelopes.max_frequency.filter(|&cut| above(cut))
    {
        names.push(format!("the acceleration envelope ({} Hz)", hz(cut)));
    }
    if names.is_empty() {
        return None;
    }
    let one = names.len() == 1;
    // A cap that keeps the filter's modes, rounded up to 0.1 Hz (the
    // default filter is a computed f₃).
    let cap = (filter.max_frequency * 10.0).ceil() / 10.0;
    Some(
        Advice::new(
            &advice::ACCELERATION_FILTER_ABOVE_MODES,
            format!(
                "{} {} every mode up to {} (the deck-acceleration filter, EN 1990 \
                 A2.4.4.2.1(4): by default the greater of 30 Hz, 1.5 f₁ and f₃ of the \
                 bridge), but `bridge.modes` keeps {} modes, up to {top:.2} Hz, of the {} it \
                 has up to {} Hz: the modes between are missing from {}",
                names.join(", "),
                if one { "sums" } else { "sum" },
                if one { "its cut-off" } else { "their cut-offs" },
                run.modes_used,
                filter.modes,
                hz(filter.max_frequency),
                if one { "it" } else { "them" },
            ),
        )
        .at("bridge.modes")
        .help(format!(
            "keep the modes up to the filter (`bridge.modes: {{max_frequency: {cap}}}`, or \
             leave `bridge.modes` out and the automatic choice keeps them), or lower the \
             record's `max_frequency` if a lower filter is meant",
        ))
        .figure("filter_hz", filter.max_frequency)
        .figure("modes_to_filter", filter.modes as f64)
        .figure("modes_used", run.modes_used as f64)
        .figure("top_kept_hz", top),
    )
}

/// A ground-motion record that still shakes when the run ends: its largest
/// |üg| after the end is at least half of its largest during the run, so
/// the bridge's response to it (and every absolute acceleration) may peak
/// after the run, which stops `solver.free_vibration` after the last axle
/// leaves (measured on examples/seismic-crossing.yaml: 0.098 g after the
/// end against 0.100 g during the run, the deck's absolute acceleration
/// largest 4 ms before the end).
fn ground_motion_after_the_run(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
    let end = summary.run.end_time;
    let bridge_recorded = summary
        .quantities
        .iter()
        .any(|q| is_bridge_quantity(q.quantity));
    if !bridge_recorded {
        return Vec::new();
    }
    scenario
        .ground_motion
        .iter()
        .enumerate()
        .filter_map(|(i, motion)| {
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
            let name = std::path::Path::new(&motion.file)
                .file_name()
                .map_or(motion.file.as_str(), |n| n.to_str().unwrap_or(""));
            (after > 0.0 && after >= 0.5 * during).then(|| {
                Advice::new(
                    &advice::GROUND_MOTION_AFTER_RUN,
                    format!(
                        "the {} record `{}` still shakes when the run ends at t = {end:.4} s: \
                         its largest |üg| afterwards is {:.3} m/s² against {:.3} m/s² during \
                         the run, so the bridge's response to it may peak later",
                        motion.direction.name(),
                        crate::scenario::diagnostic::escaped(name),
                        after,
                        during,
                    ),
                )
                .at(format!("ground_motion[{i}]"))
                .help(format!(
                    "to cover the record, set `solver.free_vibration` so the run lasts to t = \
                     {record_end:.2} s"
                ))
                .figure("run_end_s", end)
                .figure("record_end_s", record_end)
                .figure("after_m_s2", after)
                .figure("during_m_s2", during)
            })
        })
        .collect()
}

/// A contact force whose largest value is the entrance's kick: a vertical
/// harmonic surface r = a·sin(2πx/λ + φ) starts at the entrance at
/// r(0) = a·sin φ above the flat approach, with slope r′(0) = (2πa/λ)·cos φ
/// (docs/guide/conventions.md, "Surface"), so each wheel meets a step in elevation, in slope,
/// or both, as it enters: an impact under rigid contact, a spike under
/// elastic contact. Said when a `contact_force` record peaks within the
/// first tenth of a wavelength past the entrance. Measured on a 300 kg
/// wheel at 25 m/s over a 4 mm, 1.5 m surface (static load 23 kN): φ = 0
/// (slope step 0.017) under rigid contact, 205 kN at x = 7.5 mm; φ = 90°
/// (a 4 mm step), 53 MN under rigid and 4.0 MN under elastic contact, the
/// wheel then thrown 0.64 m and 0.08 m into the air.
fn entrance_kick(scenario: &Scenario, summary: &Summary) -> Vec<Advice> {
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
            Advice::new(
                &advice::HARMONIC_ENTRANCE_KICK,
                format!(
                    "`{}` is largest at the entrance (x = {:.4} m): the harmonic surface {level}; \
                     that kick, not the crossing, is this peak",
                    q.name, q.max_abs.position
                ),
            )
            .at("surface.phase")
            .figure("position_m", q.max_abs.position)
            .figure("start_step_m", start)
            .figure("start_slope", slope)
        })
        .collect()
}

/// The key path of the record named `name` (`record[2]`), or `record`
/// for a default record the file does not write.
fn record_path(scenario: &Scenario, name: &str) -> String {
    match scenario.record.iter().position(|r| r.name == name) {
        Some(i) => format!("record[{i}]"),
        None => "record".to_string(),
    }
}
