//! Hertz contact (F = C·δ^1.5, tensionless) verified independently: vbi's
//! LCP solver with the Newton-linearised Hertz law against the event-driven
//! reference of tests/it/support/event_reference.rs (Dormand–Prince 5(4), exact
//! event location at δ = 0, analytic sine modes), the reference itself
//! checked against closed forms (static settlement at (P/C)^(2/3), energy
//! conservation), and the law checked pointwise on vbi's histories.

use crate::support;

use support::event_reference::{
    EventKind, GRAVITY, TensionlessCase, extremes, tensionless_from_state, tensionless_reference,
};
use support::{column, max_abs, run_yaml};

/// Hertz coefficient of the tests, N/m^1.5: Zhai's worn-tread formula at a
/// wheel radius of 0.43 m, C = (4.57e-8 · 0.43^-0.149)^-1.5 (typed here as
/// a number, not taken from vbi).
const HERTZ_C: f64 = 8.5e10;

/// The LCP paper's oscillator (Section 5.1) at 25 m/s over 3 mm, 1.5 m
/// harmonic roughness on the 20 m beam: with Hertz contact the wheel loses
/// contact three times on the deck and after it.
fn separating_hertz_case() -> TensionlessCase {
    TensionlessCase {
        length: 20.0,
        bending_stiffness: 3.2423e9,
        mass_per_length: 2000.0,
        damping_ratio: 0.02,
        sprung_mass: 4000.0,
        unsprung_mass: 1000.0,
        suspension_stiffness: 4.0e6,
        suspension_damping: 2.53e4,
        contact_stiffness: HERTZ_C,
        contact_exponent: 1.5,
        speed: 25.0,
        start_position: 0.0,
        roughness_amplitude: 0.003,
        roughness_wavelength: 1.5,
        roughness_phase: 0.0,
        modes: 10,
    }
}

/// The same scene in vbi's format (40 elements so that the 10th FE mode is
/// within 1e-5 of the sine mode the reference uses; no static correction,
/// since the reference is the same 10-mode modal solution).
fn hertz_scene(dt: &str, coefficient: f64) -> String {
    format!(
        "name: hertz\n\
         bridge: {{type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, \
         elements_per_span: 40, modes: {{count: 10, static_correction: false}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, \
         damping: 2.53e4, speed: 25.0}}]\n\
         surface: {{type: harmonic, amplitude: 0.003, wavelength: 1.5, phase: 0.0}}\n\
         contact: {{type: hertz, coefficient: {coefficient:e}}}\n\
         solver: {{time_step: {dt}, free_vibration: 0.2, newmark: {{alpha: 0.0}}}}\n\
         record:\n\
         - {{name: midspan, quantity: bridge_displacement, x: 10.0}}\n\
         - {{name: force, quantity: contact_force}}\n\
         - {{name: gap, quantity: contact_gap}}\n"
    )
}

fn contact_losses(events: &[support::event_reference::ContactEvent]) -> Vec<f64> {
    events
        .iter()
        .filter(|e| e.kind == EventKind::Loss)
        .map(|e| e.time)
        .collect()
}

/// Reference self-check: a damped vehicle set down at rest at mid-span on
/// the undeflected beam settles to the static solution with a Hertz contact:
/// F = P, w(L/2) = −P Σ_j 2 sin²(jπ/2)/(mL ω_j²) (the modal static
/// deflection) and the wheel (P/C)^(2/3) below the deck (Hertz, the static
/// compression of the law). Measured after 30 s at 5 % damping: w within
/// 5e-16, F within 1.5e-14, y_w within 2e-16 and δ within 1e-14 relative
/// (round-off); tolerance 1e-13.
#[test]
fn reference_parked_hertz_wheel_settles_at_static_compression() {
    let mut c = separating_hertz_case();
    c.speed = 0.0;
    c.start_position = 0.5 * c.length;
    c.roughness_amplitude = 0.0;
    c.damping_ratio = 0.05;
    c.modes = 5;
    let t_end = 30.0;
    let d = tensionless_from_state(&c, &c.equilibrium_state(), &[t_end], t_end, 1e-10);
    let p = (c.sprung_mass + c.unsprung_mass) * GRAVITY;
    let mut w_static = 0.0;
    for j in 1..=c.modes {
        let om = c.natural_frequency(j);
        let s = (j as f64 * std::f64::consts::PI / 2.0).sin();
        w_static -= p * 2.0 * s * s / (c.mass_per_length * c.length * om * om);
    }
    let settlement = (p / HERTZ_C).powf(2.0 / 3.0);
    let h = &d.history;
    let w_error = ((h.midspan_deflection[0] - w_static) / w_static).abs();
    let f_error = (h.contact_force[0] / p - 1.0).abs();
    let wheel = w_static - settlement;
    let y_error = ((h.wheel_displacement[0] - wheel) / wheel).abs();
    let compression_error = ((h.compression[0] - settlement) / settlement).abs();
    eprintln!(
        "parked Hertz wheel: w {w_error:e}, F {f_error:e}, y_w {y_error:e}, δ {compression_error:e} \
         (δ = {:.6e} m vs (P/C)^(2/3) = {settlement:.6e} m)",
        h.compression[0]
    );
    assert!(
        w_error < 1e-13 && f_error < 1e-13 && y_error < 1e-13 && compression_error < 1e-13,
        "parked wheel off the static solution"
    );
}

/// Reference self-check: undamped Hertz chatter (vehicle dropped from 5 mm
/// onto the beam at L/3) conserves the closed-form first integral of the
/// equations with F = Cδ^1.5, E = Σ(mL/4)(q̇² + ω²q²) + kinetic +
/// ½k(y_s−y_w)² + (2/5)Cδ^2.5 + gravity. Measured drift 1.3e-8 of the energy scale at rtol 1e-11
/// (75 landings); tolerance 1e-7.
#[test]
fn reference_hertz_drop_conserves_energy() {
    let mut c = separating_hertz_case();
    c.damping_ratio = 0.0;
    c.suspension_damping = 0.0;
    c.speed = 0.0;
    c.start_position = c.length / 3.0;
    c.roughness_amplitude = 0.0;
    let mut init = c.equilibrium_state();
    init.wheel_displacement = 5e-3;
    init.sprung_displacement = 5e-3 - c.sprung_mass * GRAVITY / c.suspension_stiffness;
    let times: Vec<f64> = (0..=2000).map(|i| i as f64 * 5e-4).collect();
    let d = tensionless_from_state(&c, &init, &times, 1.0, 1e-11);
    let regains = d
        .history
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Regain)
        .count();
    let scale = d.elastic_kinetic_energy.iter().copied().fold(0.0, f64::max);
    let drift = d
        .energy
        .iter()
        .fold(0.0f64, |m, e| m.max((e - d.energy[0]).abs()))
        / scale;
    eprintln!("Hertz drop: {regains} landings, energy drift {drift:e}");
    assert!(regains >= 2, "no chatter");
    assert!(drift < 1e-7, "energy drift {drift:e}");
}

/// Hertz contact against the event-driven reference on the separating
/// oscillator: number of contact losses, first-loss position, maximum gap,
/// peak contact force and the whole mid-span deflection history, with
/// average-acceleration Newmark at Δt = 5e-5, 2.5e-5 and 1.25e-5 s. Errors
/// fall with the step and at 1.25e-5 s are within the tolerances below,
/// each 5–10× the error measured there:
///
/// | Δt (s)  | losses | first loss (m) | peak force | max gap | mid-span history |
/// |---------|--------|----------------|------------|---------|------------------|
/// | 5e-5    | 5 (5)  | 4.1e-4         | 6.7e-4     | 5.8e-4  | 1.6e-4           |
/// | 2.5e-5  | 5 (5)  | 4.1e-4         | 5.9e-5     | 1.4e-4  | 3.2e-5           |
/// | 1.25e-5 | 5 (5)  | 9.7e-5         | 2.5e-5     | 3.5e-5  | 5.6e-6           |
///
/// (relative to the reference's value, the history to its peak; the
/// first loss is found on the step grid, so its error is below v·Δt). The
/// law itself holds at every step: F = C·max(0, −g)^1.5 within 1e-12 of the
/// peak force (measured 5e-16: Newton converges quadratically past its
/// 1e-10 stopping change).
#[test]
fn hertz_matches_event_driven_reference() {
    let case = separating_hertz_case();
    let t_end = 1.0;
    let (reference_force, reference_gap, events) = extremes(&case, t_end, 1e-10);
    let losses = contact_losses(&events);
    let reference_first_loss = case.speed * losses[0];
    let mut last = None;
    let mut previous_error = f64::INFINITY;
    for dt in ["5.0e-5", "2.5e-5", "1.25e-5"] {
        let outcome = run_yaml(&hertz_scene(dt, HERTZ_C));
        let time = &outcome.history.time;
        let reference = tensionless_reference(&case, time, t_end, 1e-10);
        let deflection_error = column(&outcome, "midspan")
            .iter()
            .zip(&reference.midspan_deflection)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / max_abs(&reference.midspan_deflection);
        let wheel = &outcome.summary.separation[0];
        let force = column(&outcome, "force")
            .iter()
            .copied()
            .fold(0.0, f64::max);
        let force_error = (force - reference_force).abs() / reference_force;
        let gap_error = (wheel.max_gap - reference_gap).abs() / reference_gap;
        let first_loss = wheel.first_loss_position.expect("the wheel separates");
        let position_error = (first_loss - reference_first_loss).abs();
        eprintln!(
            "Δt = {dt}: losses {} (ref {}), first loss {first_loss:.5} m (ref {reference_first_loss:.5}, \
             error {position_error:.2e} m), max force {force:.1} N (ref {reference_force:.1}, {force_error:.2e}), \
             max gap {:.5e} m (ref {reference_gap:.5e}, {gap_error:.2e}), mid-span history {deflection_error:.2e}",
            wheel.episodes,
            losses.len(),
            wheel.max_gap,
        );
        assert_eq!(wheel.episodes, losses.len(), "Δt = {dt}: contact losses");
        let law_error = column(&outcome, "force")
            .iter()
            .zip(column(&outcome, "gap"))
            .fold(0.0f64, |m, (f, g)| {
                m.max((f - HERTZ_C * (-g).max(0.0).powf(1.5)).abs())
            })
            / force;
        eprintln!("Δt = {dt}: law residual {law_error:.2e} of the peak force");
        assert!(law_error < 1e-12, "Δt = {dt}: F ≠ Cδ^1.5 by {law_error:e}");
        let error = deflection_error.max(force_error).max(gap_error);
        assert!(error < previous_error, "Δt = {dt}: no convergence");
        previous_error = error;
        last = Some((
            deflection_error,
            force_error,
            gap_error,
            position_error,
            outcome.model.time_step,
        ));
    }
    let (deflection_error, force_error, gap_error, position_error, dt) = last.unwrap();
    assert!(deflection_error < 4e-5, "mid-span {deflection_error:e}");
    assert!(force_error < 2e-4, "peak force {force_error:e}");
    assert!(gap_error < 2.5e-4, "max gap {gap_error:e}");
    // The first loss is found on the step grid: within v·Δt = 0.31 mm.
    assert!(position_error < case.speed * dt, "{position_error:e}");
}
