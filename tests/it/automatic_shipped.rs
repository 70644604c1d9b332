//! Issue 9, point 4: the automatic choices (modes, static correction, time
//! step) meet the stated tolerance on every shipped scenario.
//!
//! Each shipped single-run scene is loaded with its explicit mode count and
//! time step removed, so the planning stage chooses them, and measured with
//! `vbi converge` (reference Δt/4 and 2N modes). Every recorded quantity of
//! the automatic run must be within 0.5 % (max-abs error over the history,
//! relative to its peak) of the reference. The stated exceptions: under
//! rigid contact, contact forces and gaps (the force is the 1 ms average
//! of the impulses after an impact, the t = 0 kick included, and the gap
//! of a wheel that stays down is round-off: not yet measured against the
//! 0.5 % tolerance under the Moreau–Jean step of issue 29, whose separation
//! statistics converge at first order, tests/it/moreau_jean.rs; before it,
//! 138–14,000 % apart between Δt and Δt/4); and under elastic or
//! Hertz contact once a wheel loses contact (rail-fra5-oscillator: contact
//! force 3.3 %, vehicle acceleration 2.2 %, deck acceleration 1.0 %), where
//! only displacements are held to the tolerance and the summary must say so.
//!
//! Measured with the final code (worst quantity of the automatic run, %):
//! lcp-fig4-elastic 0.33, lcp-fig4-permanent 0.24, lcp-fig5-elastic 0.002,
//! lcp-oscillator-harmonic 0.08, -hertz 0.43, -smooth 0.29, moving-force
//! 0.02–0.04, plates 0.08–0.15, three-span-two-vehicles 0.04,
//! two-axle-moving-force 0.001, yang-yau-sprung-mass 0.40,
//! viaduct-2span-axle-loads 0.35 (its axles' loads enter the free rail ends
//! over the default 3 m `entry_length`; 3.7 % with the load put on at once,
//! which this file used to exempt; issue 24, point 4),
//! embs-viaduct-ave-s103-quake 0.465 (its wheelset lateral force; contact
//! force 0.36, deck and rail accelerations 0.22, every other quantity
//! below 0.15: the automatic 1,069 modes to 1.76 kHz carry 99.5 % of the
//! rails' static flexibility under a wheel, src/plan/track_flexibility.rs;
//! at the former 564 modes to 276 Hz, which this file exempted with a
//! bound of 6.4 %, the rail lateral acceleration was 5.3 % off, the
//! contact forces 4.2 %).

use std::fs;
use std::path::Path;

use vbi::plan;
use vbi::scenario::{self, resolved::Contact, resolved::Quantity};
use vbi::study::converge::{self, Options};

/// The tolerance the automatic choice aims at (summary's `accuracy_target`).
const TOLERANCE: f64 = 0.005;

/// The scene's text without an explicit mode count or time step.
fn automatic(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("modes:") || trimmed.starts_with("time_step:") {
            continue;
        }
        // `solver: {time_step: 5.0e-5, free_vibration: 0.1}`
        let line = match line.find("time_step:") {
            Some(start) => {
                let end = line[start..]
                    .find([',', '}'])
                    .map_or(line.len(), |e| start + e);
                let end = if line[end..].starts_with(',') {
                    end + 1
                } else {
                    end
                };
                format!("{}{}", &line[..start], line[end..].trim_start())
            }
            None => line.to_owned(),
        };
        out.push_str(&line);
        out.push('\n');
    }
    out
}

#[test]
fn automatic_choices_meet_the_stated_tolerance_on_every_shipped_scene() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut files: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    let mut failures = Vec::new();
    let mut measured = 0;
    for file in &files {
        let text = fs::read_to_string(file).unwrap();
        if text.contains("\nstudy:") {
            continue;
        }
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let text = automatic(&text);
        // Loaded from its own path: files it names (records) are relative to it.
        let loaded = plan::load_str(&text, &file.to_string_lossy())
            .unwrap_or_else(|e| panic!("{name} without its settings: {e}"));
        assert!(
            loaded.bridge.selection.starts_with("automatic"),
            "{name}: modes not automatic: {}",
            loaded.bridge.selection
        );
        let rigid = matches!(loaded.scenario.contact, Contact::Rigid { .. });
        let quantities: Vec<(String, Quantity)> = loaded
            .scenario
            .record
            .iter()
            .map(|r| (r.name.clone(), r.quantity))
            .collect();
        // Does a wheel lose contact? Then the summary must say which results
        // depend on the step.
        let single = vbi::run::simulate(loaded.clone(), &mut |_, _| {}).unwrap();
        let landings = single.summary.separation.iter().any(|w| w.separated);
        if landings {
            assert!(
                single.summary.run.step_dependent.is_some(),
                "{name}: a wheel separates but the summary does not say what depends on the step"
            );
        }
        let (time_step, modes) = (loaded.scenario.solver.time_step, loaded.bridge.mode_count());
        let options = Options {
            levels: 1,
            tolerance: TOLERANCE,
            ..Options::default()
        };
        let study = converge::converge(&loaded, &options, &mut |_, _, _| {}).unwrap();
        let run = study
            .runs
            .iter()
            .find(|r| r.time_step == time_step && r.modes == modes)
            .unwrap_or_else(|| panic!("{name}: no run at the automatic choice"));
        let errors = run.errors.as_ref().unwrap();
        for q in errors {
            let quantity = quantities
                .iter()
                .find(|(n, _)| *n == q.name)
                .map(|(_, quantity)| *quantity);
            let displacement = matches!(
                quantity,
                Some(Quantity::BridgeDisplacement | Quantity::VehicleDisplacement)
            );
            let impulsive = (rigid
                && matches!(
                    quantity,
                    Some(Quantity::ContactForce | Quantity::ContactGap)
                ))
                || (landings && !displacement);
            eprintln!(
                "{name}: {} {:.4} %{}",
                q.name,
                100.0 * q.max_abs,
                if impulsive {
                    " (step-dependent: landings)"
                } else {
                    ""
                }
            );
            if !impulsive && (q.max_abs.is_nan() || q.max_abs > TOLERANCE) {
                failures.push(format!(
                    "{name}: {} is {:.3} % from the converged answer ({})",
                    q.name,
                    100.0 * q.max_abs,
                    run.label
                ));
            }
        }
        measured += 1;
    }
    assert!(measured >= 15, "only {measured} scenes measured");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Every shipped scene's `resolved.yaml` loads again and resolves to itself:
/// the resolved form is a valid input with every choice written out. (A
/// power-law random surface given by `class` used to write both `class` and
/// `coefficient`, which the loader refused.)
#[test]
fn every_shipped_resolved_scene_loads_and_resolves_to_itself() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut files: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    assert!(files.len() >= 20);
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let loaded = plan::load_file(file).unwrap_or_else(|e| panic!("{name}: {e}"));
        let resolved = vbi::run::resolved_yaml(&loaded.scenario);
        // A data file's path is absolute in the resolved form, so the text
        // loads from anywhere the scenes' folder is allowed (`--data-dir`).
        let options = scenario::LoadOptions {
            data: scenario::DataAccess {
                data_dirs: vec![dir.clone()],
                confine_to: None,
            },
            ..Default::default()
        };
        let again = plan::load_str_with(&resolved, &format!("{name} resolved"), options)
            .unwrap_or_else(|e| panic!("{name}: its resolved form does not load: {e}"));
        assert_eq!(
            resolved,
            vbi::run::resolved_yaml(&again.scenario),
            "{name}: resolving the resolved form changed it"
        );
    }
}
