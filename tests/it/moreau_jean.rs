//! Rigid contact through impacts (issue 29): Moreau–Jean time stepping, so
//! the separation statistics after a landing have a limit as Δt → 0.
//!
//! The hopping surface of `hard_cases.rs` (the LCP paper's oscillator at
//! 30 m/s over a 3 mm, 1.5 m harmonic surface, 20 m beam): the wheel lands
//! and lifts repeatedly. Before Moreau–Jean, Δt = 1e-4, 5e-5, 2.5e-5 and
//! 1.25e-5 s gave 12, 10, 6 and 14 contact-loss episodes and 0.088, 0.083,
//! 0.070 and 0.096 s separated (no trend). Measured figures are printed with
//! `eprintln!` (`--nocapture` shows them).

use crate::support::run_yaml;
use vbi::run::Outcome;

// The LCP separation paper's bridge (20 m, f₁ ≈ 5.0 Hz).
const SPAN: f64 = 20.0;
const EI: f64 = 3.2423e9;
const MASS_PER_LENGTH: f64 = 2000.0;

fn hopping_scene(dt: f64, contact: &str) -> String {
    format!(
        "name: hopping\n\
         bridge: {{type: beam, spans: [{SPAN}], bending_stiffness: {EI}, \
         mass_per_length: {MASS_PER_LENGTH}, modes: {{count: 10}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
         stiffness: 4.0e6, damping: 2.53e4, speed: 30.0}}]\n\
         surface: {{type: harmonic, amplitude: 0.003, wavelength: 1.5}}\n\
         contact: {contact}\n\
         solver: {{time_step: {dt}, free_vibration: 0.2}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}, \
         {{name: force, quantity: contact_force}}, {{name: gap, quantity: contact_gap}}]\n"
    )
}

/// (episodes, time separated s, largest gap m, mid-span DAF).
fn statistics(outcome: &Outcome) -> (usize, f64, f64, f64) {
    let wheel = &outcome.summary.separation[0];
    let daf = outcome
        .summary
        .quantities
        .iter()
        .find(|q| q.name == "mid")
        .and_then(|q| q.daf)
        .expect("mid-span DAF");
    (wheel.episodes, wheel.time_separated, wheel.max_gap, daf)
}

/// Separation statistics on the hopping surface converge: the same number
/// of contact-loss episodes at the two finest steps, and the time separated
/// and the DAF change less from Δt/4 to Δt/8 than from Δt/2 to Δt/4 (the
/// differences of a first-order scheme halve).
#[test]
fn hopping_statistics_converge() {
    let base = 1.0e-4;
    let rows: Vec<_> = (1..4)
        .map(|level| {
            let dt = base / f64::from(1u32 << level);
            let s = statistics(&run_yaml(&hopping_scene(dt, "{type: rigid}")));
            eprintln!(
                "Δt {dt:.3e}: {} episodes, {:.5} s separated, max gap {:.4} mm, DAF {:.5}",
                s.0,
                s.1,
                s.2 * 1e3,
                s.3
            );
            s
        })
        .collect();
    assert_eq!(rows[1].0, rows[2].0, "episode counts at the two finest steps");
    let (d1, d2) = ((rows[1].1 - rows[0].1).abs(), (rows[2].1 - rows[1].1).abs());
    assert!(d2 < 0.75 * d1 + 1e-4, "time separated: changes {d1:.3e}, {d2:.3e}");
    let (d1, d2) = ((rows[1].3 - rows[0].3).abs(), (rows[2].3 - rows[1].3).abs());
    assert!(d2 < 0.75 * d1 + 1e-4, "DAF: changes {d1:.3e}, {d2:.3e}");
}
