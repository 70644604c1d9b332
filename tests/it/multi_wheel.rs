//! Unilateral contact with several wheels: oscillator sets whose wheels
//! separate, against an independent brute-force reference (itself checked
//! against the event-driven one), and the H20-44 truck on a beam and on a
//! plate, where no wheel lifts, against permanent contact — rigid, elastic
//! and Hertz contact each.

use crate::support;

use support::event_reference::{EventKind, TensionlessCase, extremes};
use support::multi_reference::{MultiCase, Oscillator};
use support::{column, max_abs, run_yaml};

/// Hertz coefficient, N/m^1.5 (Zhai's worn tread at R = 0.43 m, rounded).
const HERTZ_C: f64 = 8.5e10;
/// Linear contact stiffness, N/m.
const SPRING_K: f64 = 1.0e8;

fn oscillator(entry_time: f64) -> Oscillator {
    Oscillator {
        sprung_mass: 4000.0,
        unsprung_mass: 1000.0,
        stiffness: 4.0e6,
        damping: 2.53e4,
        speed: 25.0,
        entry_time,
    }
}

/// The LCP paper's oscillator over 3 mm, 1.5 m roughness on the 20 m beam.
fn beam_case(coefficient: f64, exponent: f64, vehicles: Vec<Oscillator>) -> MultiCase {
    MultiCase {
        length: 20.0,
        bending_stiffness: 3.2423e9,
        mass_per_length: 2000.0,
        damping_ratio: 0.02,
        modes: 10,
        roughness: (0.003, 1.5, 0.0),
        contact_coefficient: coefficient,
        contact_exponent: exponent,
        vehicles,
    }
}

/// The brute-force RK4 reference (h = 1 µs, no event location) agrees with
/// the event-driven one (Dormand–Prince, events located to 1e-14 s) on one
/// separating oscillator, linear and Hertz: same losses, first-loss
/// position, peak force and max gap within 1e-6, 5e-8 and 5e-9 m (measured:
/// linear 6e-10, 4e-9, 4e-10 m; Hertz 1.6e-7 — the peak sampled on the 1 µs
/// grid —, 8.8e-9, 5.8e-10 m).
#[test]
fn brute_force_reference_agrees_with_the_event_driven_one() {
    for (coefficient, exponent) in [(SPRING_K, 1.0), (HERTZ_C, 1.5)] {
        let single = TensionlessCase {
            length: 20.0,
            bending_stiffness: 3.2423e9,
            mass_per_length: 2000.0,
            damping_ratio: 0.02,
            sprung_mass: 4000.0,
            unsprung_mass: 1000.0,
            suspension_stiffness: 4.0e6,
            suspension_damping: 2.53e4,
            contact_stiffness: coefficient,
            contact_exponent: exponent,
            speed: 25.0,
            start_position: 0.0,
            roughness_amplitude: 0.003,
            roughness_wavelength: 1.5,
            roughness_phase: 0.0,
            modes: 10,
        };
        let (force, gap, events) = extremes(&single, 1.0, 1e-10);
        let losses: Vec<f64> = events
            .iter()
            .filter(|e| e.kind == EventKind::Loss)
            .map(|e| e.time * single.speed)
            .collect();
        let brute = beam_case(coefficient, exponent, vec![oscillator(0.0)]).run(&[], 1.0, 1e-6);
        let wheel = &brute.wheels[0];
        let errors = (
            (wheel.max_force - force).abs() / force,
            (wheel.max_gap - gap).abs() / gap,
            (wheel.first_loss_position.unwrap() - losses[0]).abs(),
        );
        eprintln!(
            "n = {exponent}: losses {} vs {}, force {:.3e}, gap {:.3e}, first loss {:.3e} m",
            wheel.losses,
            losses.len(),
            errors.0,
            errors.1,
            errors.2
        );
        assert_eq!(wheel.losses, losses.len());
        assert!(
            errors.0 < 1e-6 && errors.1 < 5e-8 && errors.2 < 5e-9,
            "n = {exponent}: {errors:?}"
        );
    }
}

/// Three oscillators 5 m apart (entry at 0, 0.2 and 0.4 s) cross the rough
/// beam together, every wheel leaving the surface several times while the
/// others load the deck; vbi (LCP per step, Δt = 2.5e-5 s) against the
/// brute-force reference for a linear and a Hertz contact: per wheel the
/// number of contact losses, the first-loss position, the peak force and the
/// max gap, and the mid-span deflection history. Errors measured (worst
/// wheel) and tolerances, 5–8× those:
///
/// | contact | losses per wheel | mid-span | peak force | max gap | first loss |
/// |---------|------------------|----------|------------|---------|------------|
/// | elastic 1e8 N/m | 2, 2, 1 (same) | 1.5e-6 (1e-5) | 4.7e-6 (3e-5) | 2.2e-5 (1.5e-4) | 4.3e-4 m |
/// | Hertz 8.5e10 N/m^1.5 | 9, 7, 4 (same) | 1.4e-5 (1e-4) | 8.0e-5 (5e-4) | 1.5e-4 (1e-3) | 4.1e-4 m |
///
/// The first loss is found on the step grid, so its bound is v·Δt = 0.63 mm.
#[test]
fn three_separating_oscillators_match_the_reference() {
    let entries = [0.0, 0.2, 0.4];
    for (contact, coefficient, exponent, tolerance) in [
        (
            format!("{{type: elastic, stiffness: {SPRING_K:e}}}"),
            SPRING_K,
            1.0,
            (1e-5, 3e-5, 1.5e-4),
        ),
        (
            format!("{{type: hertz, coefficient: {HERTZ_C:e}}}"),
            HERTZ_C,
            1.5,
            (1e-4, 5e-4, 1e-3),
        ),
    ] {
        let vehicles: String = entries
            .iter()
            .map(|t| {
                format!(
                    "- {{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, \
                     stiffness: 4.0e6, damping: 2.53e4, speed: 25.0, entry_time: {t}}}\n"
                )
            })
            .collect();
        let records: String = (1..=3)
            .map(|v| {
                format!(
                    "- {{name: force{v}, quantity: contact_force, vehicle: {v}}}\n\
                     - {{name: gap{v}, quantity: contact_gap, vehicle: {v}}}\n"
                )
            })
            .collect();
        // The reference is the same 10-mode modal solution: compare like with
        // like, without the static correction.
        let outcome = run_yaml(&format!(
            "name: three\n\
             bridge: {{type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, \
             elements_per_span: 40, modes: {{count: 10, static_correction: false}}, damping: {{type: modal, ratio: 0.02}}}}\n\
             vehicles:\n{vehicles}\
             surface: {{type: harmonic, amplitude: 0.003, wavelength: 1.5, phase: 0.0}}\n\
             contact: {contact}\n\
             solver: {{time_step: 2.5e-5, free_vibration: 0.2, newmark: {{alpha: 0.0}}}}\n\
             record:\n- {{name: midspan, quantity: bridge_displacement, x: 10.0}}\n{records}"
        ));
        let time = &outcome.history.time;
        let t_end = *time.last().unwrap();
        let case = beam_case(
            coefficient,
            exponent,
            entries.iter().map(|&t| oscillator(t)).collect(),
        );
        let reference = case.run(time, t_end, 1e-6);
        let deflection = column(&outcome, "midspan")
            .iter()
            .zip(&reference.midspan_deflection)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / max_abs(&reference.midspan_deflection);
        eprintln!("{contact}: mid-span history {deflection:.2e}");
        assert!(
            deflection < tolerance.0,
            "{contact}: mid-span {deflection:e}"
        );
        for (v, (wheel, want)) in outcome
            .summary
            .separation
            .iter()
            .zip(&reference.wheels)
            .enumerate()
        {
            let force = column(&outcome, &format!("force{}", v + 1))
                .iter()
                .copied()
                .fold(0.0, f64::max);
            let errors = (
                (force - want.max_force).abs() / want.max_force,
                (wheel.max_gap - want.max_gap).abs() / want.max_gap,
                (wheel.first_loss_position.unwrap() - want.first_loss_position.unwrap()).abs(),
            );
            eprintln!(
                "  wheel {}: losses {} vs {}, force {:.2e}, gap {:.2e}, first loss {:.2e} m",
                v + 1,
                wheel.episodes,
                want.losses,
                errors.0,
                errors.1,
                errors.2
            );
            assert_eq!(wheel.episodes, want.losses, "{contact}, wheel {}", v + 1);
            assert!(
                errors.0 < tolerance.1 && errors.1 < tolerance.2 && errors.2 < 25.0 * 2.5e-5,
                "{contact}, wheel {}: {errors:?}",
                v + 1
            );
        }
    }
}

/// The H20-44 truck at 30 m/s on a good random road over a deck: the
/// three-span beam of tests/it/truck.rs or the plate paper's orthotropic deck.
fn truck_scene(deck: &str, contact: &str, tyres: &str, time_step: f64) -> String {
    let bridge = if deck == "beam" {
        "bridge: {type: beam, spans: [24.0, 30.0, 24.0], bending_stiffness: 3.3e10, \
         mass_per_length: 9500.0, damping: {type: modal, ratio: 0.02}}\n"
            .to_string()
    } else {
        "bridge: {type: plate, spans: [24.0, 30.0, 24.0], width: 13.715, thickness: 0.212, \
         density: 3265.29, rigidity: {type: orthotropic, flexural_rigidity_x: 2.41e9, \
         flexural_rigidity_y: 2.18e7, torsional_rigidity: 1.14e8, poisson_ratio: 0.3}, \
         modes: {count: 45}, damping: {type: modal, ratio: 0.02}}\n"
            .to_string()
    };
    let lateral = if deck == "beam" {
        ""
    } else {
        ", lateral_position: 4.0"
    };
    format!(
        "name: truck-{deck}\n{bridge}\
         vehicles: [{{type: h20_44, speed: 30.0{lateral}, parameters: {{{tyres}}}}}]\n\
         surface: {{type: random, class: good, seed: 3}}\n\
         contact: {contact}\n\
         solver: {{time_step: {time_step:e}, newmark: {{alpha: -0.05}}}}\n\
         record:\n\
         - {{name: mid2, quantity: bridge_displacement, x: 39.0{y}}}\n\
         - {{name: f1, quantity: contact_force, wheel: 1}}\n\
         - {{name: f2, quantity: contact_force, wheel: 2}}\n\
         - {{name: f3, quantity: contact_force, wheel: 3}}\n\
         - {{name: f4, quantity: contact_force, wheel: 4}}\n\
         - {{name: pitch, quantity: vehicle_displacement, dof: body_pitch}}\n\
         - {{name: gap1, quantity: contact_gap, wheel: 1}}\n\
         - {{name: gap4, quantity: contact_gap, wheel: 4}}\n",
        y = if deck == "beam" { "" } else { ", y: 4.0" }
    )
}

const TRUCK_RECORDS: [&str; 6] = ["mid2", "f1", "f2", "f3", "f4", "pitch"];

/// Largest difference of the truck's records between two runs, relative to
/// each record's peak in `reference`.
fn truck_difference(run: &vbi::run::Outcome, reference: &vbi::run::Outcome) -> f64 {
    TRUCK_RECORDS
        .iter()
        .map(|name| {
            let (a, b) = (column(run, name), column(reference, name));
            a.iter()
                .zip(b)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
                / max_abs(b)
        })
        .fold(0.0, f64::max)
}

/// Where no wheel lifts, unilateral contact is permanent contact. The truck
/// (four contact points, massless, under tyre springs) on a good road over a
/// beam and over a plate, HHT α = −0.05 throughout, histories of the
/// mid-span deflection, the four contact forces and the body pitch:
/// - rigid contact with undamped tyres is permanent contact (`coupled`):
///   the same algebra, measured 1.3e-11 (tolerance 1e-10);
/// - with the preset's tyre dashpots they differ where an axle rolls onto
///   the rough deck: the road's slope jumps from 0 to r′(0) there, which
///   permanent contact feeds to the dashpot as an exact velocity step v·r′
///   and the rigid LCP as the trapezoidal rule's velocity of the massless
///   contact point (overshoot, then HHT-damped ringing); measured 1.0e-3 of
///   the peak force in the steps right after each entry, the same at Δt =
///   1 ms and 0.5 ms (a velocity step does not converge pointwise), while
///   the deflection and the pitch stay within 8e-6; tolerance 5e-3;
/// - an elastic contact spring k_c in series with the tyre k_t (undamped)
///   is permanent contact with the series tyre k_t·k_c/(k_t + k_c) (the
///   massless contact point carries the same force through both springs):
///   measured 3.3e-11 (tolerance 3e-10);
/// - Hertz contact approaches permanent contact as C grows, the difference
///   falling as the compression, C^(−2/3): ×4 for C × 8 (measured 4.01 on
///   both decks; tolerance ±0.1), and F = C·max(0, −g)^1.5 holds at every
///   step on a front and a rear wheel (round-off; tolerance 1e-12).
///
/// No wheel separates in any of them. (Before the first step's HHT term
/// carried the static wheel loads, rigid and elastic runs differed from
/// permanent contact by 4 % in the first step's contact forces.)
#[test]
fn truck_without_lift_off_equals_permanent_contact() {
    let (tyre, contact_k) = (1.75e6, 2.0e7);
    let series = tyre * contact_k / (tyre + contact_k);
    let undamped = "front_tyre_damping: 0.0, rear_tyre_damping: 0.0".to_string();
    let series_tyres =
        format!("{undamped}, front_tyre_stiffness: {series:e}, rear_tyre_stiffness: {series:e}");
    for deck in ["beam", "plate"] {
        let scene = |contact: &str, tyres: &str| run_yaml(&truck_scene(deck, contact, tyres, 1e-3));
        let permanent = scene("{type: permanent}", "");
        let rigid = scene("{type: rigid}", "");
        let rigid_undamped = scene("{type: rigid}", &undamped);
        let permanent_undamped = scene("{type: permanent}", &undamped);
        let rigid_fine = run_yaml(&truck_scene(deck, "{type: rigid}", "", 5e-4));
        let permanent_fine = run_yaml(&truck_scene(deck, "{type: permanent}", "", 5e-4));
        let elastic = scene(
            &format!("{{type: elastic, stiffness: {contact_k:e}}}"),
            &undamped,
        );
        let permanent_series = scene("{type: permanent}", &series_tyres);
        let coefficients = [1.0e9, 8.0e9];
        let hertz: Vec<_> = coefficients
            .iter()
            .map(|c| scene(&format!("{{type: hertz, coefficient: {c:e}}}"), ""))
            .collect();
        // The Hertz law at every step on two wheels, F = C·max(0, −g)^1.5
        // (measured to round-off, 1e-15 of the peak force).
        for (outcome, c) in hertz.iter().zip(coefficients) {
            for (force, gap) in [("f1", "gap1"), ("f4", "gap4")] {
                let f = column(outcome, force);
                let law = f
                    .iter()
                    .zip(column(outcome, gap))
                    .fold(0.0f64, |m, (f, g)| {
                        m.max((f - c * (-g).max(0.0).powf(1.5)).abs())
                    })
                    / max_abs(f);
                assert!(
                    law < 1e-12,
                    "{deck}, C = {c:e}, {force}: law residual {law:e}"
                );
            }
        }
        for outcome in [
            &rigid,
            &rigid_undamped,
            &rigid_fine,
            &elastic,
            &hertz[0],
            &hertz[1],
        ] {
            assert_eq!(outcome.summary.separation.len(), 4);
            assert!(
                outcome.summary.separation.iter().all(|w| !w.separated),
                "{deck}: a wheel lifted: {:?}",
                outcome.summary.separation
            );
        }
        let exact_rigid = truck_difference(&rigid_undamped, &permanent_undamped);
        let rigid_difference = truck_difference(&rigid, &permanent);
        let rigid_fine_difference = truck_difference(&rigid_fine, &permanent_fine);
        let elastic_difference = truck_difference(&elastic, &permanent_series);
        let hertz_ratio =
            truck_difference(&hertz[0], &permanent) / truck_difference(&hertz[1], &permanent);
        eprintln!(
            "{deck}: rigid undamped {exact_rigid:.2e}, rigid {rigid_difference:.2e} → \
             {rigid_fine_difference:.2e} at Δt/2, elastic (series tyre) {elastic_difference:.2e}, \
             Hertz ratio {hertz_ratio:.3}"
        );
        assert!(exact_rigid < 1e-10, "{deck}: rigid {exact_rigid:e}");
        assert!(
            rigid_difference < 5e-3 && rigid_fine_difference < 5e-3,
            "{deck}: rigid with tyre dashpots {rigid_difference:e}, {rigid_fine_difference:e}"
        );
        assert!(
            elastic_difference < 3e-10,
            "{deck}: elastic {elastic_difference:e}"
        );
        assert!(
            (hertz_ratio - 4.0).abs() < 0.1,
            "{deck}: Hertz ratio {hertz_ratio}"
        );
    }
}

/// Three oscillators (different masses, springs and speeds, on three lanes)
/// over the orthotropic plate deck on a smooth road: no wheel lifts, and,
/// on the deck deflection under each lane and each body's displacement,
/// - rigid contact agrees with permanent contact (`coupled`; both HHT
///   α = −0.05): the wheel is a Newmark DOF held by a multiplier in one and
///   eliminated kinematically in the other, so they differ by the
///   discretisation, measured 5.5e-5 of each history's peak (tolerance
///   3e-4);
/// - elastic and Hertz contact approach permanent contact as the contact
///   stiffens, the difference falling as the static compression: ×10 for
///   k × 10 (measured 9.96; tolerance ±0.4) and ×4 for C × 8 (measured
///   4.01; tolerance ±0.1).
///
/// The contact forces are not compared pointwise: where a wheel rolls onto
/// a deck already sloped by another vehicle its path has a kink, which the
/// rigid LCP meets with a force dip over a few steps and permanent contact
/// with a one-step spike (measured up to 57 % of the force in those steps,
/// not shrinking with the step).
#[test]
fn oscillator_set_on_a_plate_without_lift_off_equals_permanent_contact() {
    let scene = |contact: &str| {
        format!(
            "name: set\n\
             bridge: {{type: plate, spans: [24.0, 30.0, 24.0], width: 13.715, thickness: 0.212, \
             density: 3265.29, rigidity: {{type: orthotropic, flexural_rigidity_x: 2.41e9, \
             flexural_rigidity_y: 2.18e7, torsional_rigidity: 1.14e8, poisson_ratio: 0.3}}, \
             modes: {{count: 30}}, damping: {{type: modal, ratio: 0.02}}}}\n\
             vehicles:\n\
             - {{type: oscillator, sprung_mass: 15000.0, unsprung_mass: 1500.0, stiffness: 1.2e6, damping: 3.0e4, speed: 20.0, lateral_position: 3.0}}\n\
             - {{type: oscillator, sprung_mass: 8000.0, unsprung_mass: 800.0, stiffness: 6.0e5, damping: 1.5e4, speed: 25.0, entry_time: 0.5, lateral_position: 6.8575}}\n\
             - {{type: oscillator, sprung_mass: 12000.0, unsprung_mass: 1000.0, stiffness: 9.0e5, damping: 2.0e4, speed: 18.0, entry_time: 1.0, lateral_position: 10.5}}\n\
             contact: {contact}\n\
             solver: {{time_step: 5.0e-4, free_vibration: 0.5, newmark: {{alpha: -0.05}}}}\n\
             record:\n\
             - {{name: mid1, quantity: bridge_displacement, x: 12.0, y: 3.0}}\n\
             - {{name: mid2, quantity: bridge_displacement, x: 39.0, y: 6.8575}}\n\
             - {{name: mid3, quantity: bridge_displacement, x: 66.0, y: 10.5}}\n\
             - {{name: s1, quantity: vehicle_displacement, vehicle: 1, dof: sprung}}\n\
             - {{name: s2, quantity: vehicle_displacement, vehicle: 2, dof: sprung}}\n\
             - {{name: s3, quantity: vehicle_displacement, vehicle: 3, dof: sprung}}\n"
        )
    };
    let names = ["mid1", "mid2", "mid3", "s1", "s2", "s3"];
    let difference = |a: &vbi::run::Outcome, b: &vbi::run::Outcome| {
        names
            .iter()
            .map(|n| {
                let (x, y) = (column(a, n), column(b, n));
                x.iter()
                    .zip(y)
                    .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()))
                    / max_abs(y)
            })
            .fold(0.0, f64::max)
    };
    let permanent = run_yaml(&scene("{type: permanent}"));
    let mut runs = Vec::new();
    for contact in [
        "{type: rigid}",
        "{type: elastic, stiffness: 1.0e9}",
        "{type: elastic, stiffness: 1.0e10}",
        "{type: hertz, coefficient: 1.0e10}",
        "{type: hertz, coefficient: 8.0e10}",
    ] {
        let outcome = run_yaml(&scene(contact));
        assert_eq!(outcome.summary.separation.len(), 3);
        assert!(
            outcome.summary.separation.iter().all(|w| !w.separated),
            "{contact}: {:?}",
            outcome.summary.separation
        );
        runs.push(difference(&outcome, &permanent));
    }
    eprintln!(
        "oscillator set on the plate: rigid {:.2e}, elastic {:.2e} → {:.2e} (×{:.2}), Hertz {:.2e} → {:.2e} (×{:.2})",
        runs[0],
        runs[1],
        runs[2],
        runs[1] / runs[2],
        runs[3],
        runs[4],
        runs[3] / runs[4]
    );
    assert!(runs[0] < 3e-4, "rigid {:e}", runs[0]);
    assert!((runs[1] / runs[2] - 10.0).abs() < 0.4, "elastic {runs:?}");
    assert!((runs[3] / runs[4] - 4.0).abs() < 0.1, "Hertz {runs:?}");
}

/// Two oscillators in a row and a two-axle moving load on the 24–30–24 m
/// continuous beam (the scene of separation.rs'
/// `several_vehicles_on_a_continuous_beam`, smooth deck): no wheel lifts,
/// and Hertz contact approaches permanent contact (`coupled`, both HHT
/// α = −0.05) as C grows, on the deck deflection in each span and both
/// bodies' displacements, the difference falling as the static compression
/// (P/C)^(2/3): ×4 for C × 8 (measured 4.02: 1.01e-2 → 2.50e-3 of the
/// peaks; tolerance ±0.1). (Rigid and
/// elastic contact on this scene are compared with permanent contact there.)
#[test]
fn oscillators_in_a_row_on_a_beam_approach_permanent_contact_with_hertz() {
    let scene = |contact: &str| {
        format!(
            "name: row\n\
             bridge: {{type: beam, spans: [24.0, 30.0, 24.0], bending_stiffness: 3.0e10, \
             mass_per_length: 12000.0, modes: {{max_frequency: 60.0, static_correction: false}}, \
             damping: {{type: rayleigh, frequencies: [3.0, 20.0], ratio: 0.02}}}}\n\
             vehicles:\n\
             - {{type: moving_force, loads: [80.0e3, 80.0e3], axle_spacings: [6.0], speed: 22.0, entry_time: 0.8}}\n\
             - {{type: oscillator, sprung_mass: 15000.0, unsprung_mass: 1500.0, stiffness: 1.2e6, damping: 3.0e4, speed: 20.0}}\n\
             - {{type: oscillator, sprung_mass: 8000.0, unsprung_mass: 800.0, stiffness: 6.0e5, damping: 1.5e4, speed: 25.0, entry_time: 1.5}}\n\
             contact: {contact}\n\
             solver: {{time_step: 2.5e-4, free_vibration: 1.0, newmark: {{alpha: -0.05}}}}\n\
             record:\n\
             - {{name: span1, quantity: bridge_displacement, x: 12.0}}\n\
             - {{name: span2, quantity: bridge_displacement, x: 39.0}}\n\
             - {{name: span3, quantity: bridge_displacement, x: 66.0}}\n\
             - {{name: s1, quantity: vehicle_displacement, vehicle: 2, dof: sprung}}\n\
             - {{name: s2, quantity: vehicle_displacement, vehicle: 3, dof: sprung}}\n"
        )
    };
    let names = ["span1", "span2", "span3", "s1", "s2"];
    let permanent = run_yaml(&scene("{type: permanent}"));
    let differences: Vec<f64> = [1.0e9, 8.0e9]
        .iter()
        .map(|c| {
            let outcome = run_yaml(&scene(&format!("{{type: hertz, coefficient: {c:e}}}")));
            assert!(
                outcome.summary.separation.iter().all(|w| !w.separated),
                "C = {c:e}: {:?}",
                outcome.summary.separation
            );
            names
                .iter()
                .map(|n| {
                    let (x, y) = (column(&outcome, n), column(&permanent, n));
                    x.iter()
                        .zip(y)
                        .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()))
                        / max_abs(y)
                })
                .fold(0.0, f64::max)
        })
        .collect();
    let ratio = differences[0] / differences[1];
    eprintln!(
        "oscillators in a row, Hertz: {:.3e} → {:.3e}, ratio {ratio:.3}",
        differences[0], differences[1]
    );
    assert!((ratio - 4.0).abs() < 0.1, "{differences:?}");
}
