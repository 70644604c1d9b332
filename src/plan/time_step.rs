//! The default time step and the rule that governed it.

use crate::bridge::ModalBridge;
use crate::scene::{GroundMotion, Study, Vehicle};

use super::content::{self, Excitation};

/// The step of the run, s: `given` (the file's) or the smallest of the
/// automatic rules — [`content::STEPS_PER_PERIOD`] steps per period of the
/// highest frequency excited (`highest`, Hz: the highest excited mode,
/// [`content::excited_mode_top`], or an excitation's), at least
/// [`content::CROSSING_STEPS`] over the `shortest_crossing` (s), the phase
/// of each of the kept `modes` (frequency, Hz, and damping ratio) the
/// recorded accelerations sum (up to `history_cutoff`, Hz) over the
/// `longest_run` (s) or its free vibration's decay time
/// ([`content::phase_governing`]), and each
/// ground-motion record's shortest sample interval. Returns the step, the
/// automatic step before the ground motion's rule (`None` when given) and
/// the selection's words with the governing rule.
pub(super) fn choose(
    given: Option<f64>,
    (highest, modes): (f64, &[(f64, f64)]),
    excitations: &[Excitation],
    history_cutoff: Option<f64>,
    shortest_crossing: f64,
    longest_run: f64,
    ground_motion: &[GroundMotion],
) -> (f64, Option<f64>, String) {
    // Recorded deck accelerations: each mode they sum keeps its phase over
    // the run, or over the decay of its free vibration where that is
    // shorter (a history; a resonance check keeps only peaks).
    let kept_top = modes.last().map_or(1.0, |m| m.0);
    let acceleration_top = history_cutoff.map_or(0.0, |cut| cut.min(kept_top));
    // Under ground motion, over the whole run: measured on the shipped
    // quake-vertical-rail-car scene, its absolute body acceleration
    // converges at first order in the step (0.72 % at the decay time's
    // step of 4.2e-4 s, 1.5 % at twice it), which the phase error does
    // not price.
    let decays = ground_motion.is_empty();
    let (phase_step, phase_mode, phase_time) =
        content::phase_governing(modes, acceleration_top, longest_run, decays);
    // The modes they sum are excited and resolved too.
    let highest = highest.max(acceleration_top);
    let step_without_ground = given
        .is_none()
        .then(|| content::time_step(highest, excitations, shortest_crossing).min(phase_step));
    // A ground-motion record is linear between its samples: a step no
    // longer than its shortest interval sees every peak.
    let time_step = given.unwrap_or_else(|| {
        ground_motion
            .iter()
            .map(|g| g.record.shortest_interval())
            .fold(step_without_ground.unwrap_or(f64::INFINITY), f64::min)
    });
    let selection = if given.is_some() {
        "set in the file".to_owned()
    } else {
        // Which rule gave the step (the smallest candidate), so that the
        // summary says what to change to make the run cheaper.
        let top = excitations
            .iter()
            .map(|e| e.frequency)
            .fold(highest, f64::max);
        let mut rules = vec![
            (
                1.0 / (content::STEPS_PER_PERIOD * top),
                format!(
                    "{} steps per period of {top:.4} Hz, the highest frequency excited",
                    content::STEPS_PER_PERIOD
                ),
            ),
            (
                shortest_crossing / content::CROSSING_STEPS,
                format!(
                    "{} steps over the shortest crossing ({shortest_crossing:.4} s)",
                    content::CROSSING_STEPS
                ),
            ),
            (
                phase_step,
                if phase_time < longest_run {
                    format!(
                        "the phase of the recorded accelerations' mode at {phase_mode:.4} Hz over \
                         {phase_time:.4} s, the decay time 1/(ζω) of its free vibration (the run: \
                         {longest_run:.4} s)"
                    )
                } else {
                    format!(
                        "the phase of the recorded accelerations' mode at {phase_mode:.4} Hz over \
                         the {longest_run:.4} s run"
                    )
                },
            ),
        ];
        if let Some(g) = ground_motion
            .iter()
            .map(|g| g.record.shortest_interval())
            .reduce(f64::min)
        {
            rules.push((
                g,
                "the ground-motion record's shortest sample interval".into(),
            ));
        }
        let governing = rules
            .iter()
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map_or(String::new(), |(_, why)| format!("; governed by {why}"));
        format!(
            "automatic: {} steps per period of the highest frequency excited, at \
             least {} steps over the shortest crossing, and for deck accelerations a phase \
             drift of each mode they sum below {} rad over the run or the decay of its free \
             vibration{governing}",
            content::STEPS_PER_PERIOD,
            content::CROSSING_STEPS,
            content::PHASE_BUDGET
        )
    };
    (time_step, step_without_ground, selection)
}

/// The run lengths the step rules and budgets read, s: the shortest
/// crossing of the `fast` vehicles (entry to exit), the shortest run (the
/// fast vehicles' last exit plus `free_vibration`) and the longest (the
/// `slow` ones', or a separation map's slowest point, v = 2 α f₁ L, if
/// longer). `fast` and `slow` are a study's extreme runs
/// (`scenario::sweep::extreme_vehicles`), `vehicles` the scene's.
pub(super) fn run_lengths(
    study: Option<&Study>,
    vehicles: &[Vehicle],
    (fast, slow): (&[Vehicle], &[Vehicle]),
    modal: &ModalBridge,
    free_vibration: f64,
) -> (f64, f64, f64) {
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
    let (shortest_run, mut longest_run) = (duration(fast), duration(slow));
    // A separation map's slowest point (its smallest velocity ratio) runs
    // longest: v = 2 α f₁ L.
    if let (Some(Study::SeparationMap { velocity_ratio, .. }), Some(&f1), [vehicle]) =
        (study, modal.frequencies().first(), vehicles)
    {
        let slowest = 2.0 * velocity_ratio.from.min(velocity_ratio.to) * f1 * length;
        if slowest > 0.0 {
            longest_run = longest_run.max(vehicle.entry_time() + length / slowest + free_vibration);
        }
    }
    (shortest_crossing, shortest_run, longest_run)
}
