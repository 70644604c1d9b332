//! The EMBS solver (EMBS paper, Section 2) against the coupled solution of
//! the same scene. Each test states its reference and tolerance.

mod support;

use vbi::report::embs::EmbsSummary;
use vbi::run::simulate;
use vbi::scenario::load_str;

/// Runs `yaml` (labelled as a file in `scenarios/`, so record paths
/// resolve there) and returns its EMBS summary.
fn embs(yaml: &str) -> EmbsSummary {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios/embs-test.yaml");
    let loaded = load_str(yaml, file).unwrap_or_else(|e| panic!("{e}"));
    let outcome = simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
    outcome
        .summary
        .embs
        .expect("an EMBS run has an embs summary")
}

/// The EMBS error of quantity `name`.
fn error(summary: &EmbsSummary, name: &str) -> f64 {
    summary
        .comparison
        .as_ref()
        .expect("compare: true")
        .quantities
        .iter()
        .find(|q| q.name == name)
        .unwrap_or_else(|| panic!("no quantity {name}"))
        .error
}

/// A 20 m 3D beam (f₁ = 6.5 Hz vertically, 10.3 Hz laterally), the 3D
/// car at 300 km/h on an FRA class 5 track with alignment, the primary suspension scaled by `scale` in stiffness
/// and √scale in damping (its damping ratio kept), `order` the EMBS
/// `first_order` setting.
fn scaled_scene(scale: f64, first_order: bool) -> String {
    format!(
        r#"
name: embs-order
bridge: {{type: beam, spans: [20.0], bending_stiffness: 4.0e10, mass_per_length: 15000.0,
  lateral_bending_stiffness: 1.0e11, torsional_stiffness: 4.0e9, polar_mass: 60000.0,
  rail_height: 1.0, elements_per_span: 20, damping: {{type: modal, ratio: 0.02}},
  modes: {{count: 12}}}}
vehicles:
  - type: train_3d
    speed: 300 km/h
    parameters: {{primary_longitudinal_stiffness: {kx}, primary_lateral_stiffness: {ky},
      primary_vertical_stiffness: {kz}, primary_longitudinal_damping: {cx},
      primary_lateral_damping: {cy}, primary_vertical_damping: {cz}}}
surface: {{type: fra, class: 5, alignment: true, rails: independent, seed: 3}}
contact: {{type: permanent}}
solver: {{method: embs, first_order: {first_order}, compare: true, time_step: 2.0e-4,
  free_vibration: 0.5}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 10.0}}
  - {{name: midspan_acc, quantity: bridge_acceleration, x: 10.0}}
  - {{name: midspan_lateral, quantity: bridge_displacement, x: 10.0, direction: uy}}
  - {{name: body_bounce, quantity: vehicle_displacement, dof: body_bounce}}
  - {{name: wheel1, quantity: contact_force, wheel: 1}}
"#,
        kx = 12.5e6 * scale,
        ky = 120e6 * scale,
        kz = 1.2e6 * scale,
        cx = 9e3 * scale.sqrt(),
        cy = 27.9e3 * scale.sqrt(),
        cz = 10e3 * scale.sqrt(),
    )
}

/// The order of the asymptotic expansion: with the primary suspension
/// scaled so that ε = ω_p/ω_B halves (stiffness ÷ 4: ε = 0.0084 → 0.0042
/// vertically), the error of the deck's mid-span deflection, acceleration
/// and lateral displacement falls ×4 with the first order (an O(ε²)
/// remainder: measured ×4.0, ×4.0, ×4.0) and ×2 with the zero order alone
/// (O(ε): measured ×2.0, ×2.0, ×2.3); bounds ≥ ×3.2 and ×1.6–2.6. Zero
/// plus first order is the better answer at both ε (vertically 30×,
/// laterally 2× at the smaller). A sign error in F₁ or a missing term
/// leaves the first order no better than the zero order, at order 1.
#[test]
fn the_error_falls_at_the_order_the_expansion_predicts() {
    let (coarse, fine) = (6.1e-5, 1.526e-5);
    let run = |scale, first| embs(&scaled_scene(scale, first));
    let (one_coarse, one_fine) = (run(coarse, true), run(fine, true));
    let (zero_coarse, zero_fine) = (run(coarse, false), run(fine, false));
    let (eps_coarse, eps_fine) = (one_coarse.epsilon.unwrap(), one_fine.epsilon.unwrap());
    eprintln!("ε = {eps_coarse:.4} → {eps_fine:.4}");
    assert!((eps_coarse / eps_fine - 2.0).abs() < 0.05);
    for name in ["midspan", "midspan_acc", "midspan_lateral"] {
        let first = error(&one_coarse, name) / error(&one_fine, name);
        let zero = error(&zero_coarse, name) / error(&zero_fine, name);
        eprintln!(
            "{name}: zero + first {:.2e} → {:.2e} (×{first:.2}), zero {:.2e} → {:.2e} (×{zero:.2})",
            error(&one_coarse, name),
            error(&one_fine, name),
            error(&zero_coarse, name),
            error(&zero_fine, name)
        );
        assert!(first >= 3.2, "{name}: zero + first order falls ×{first:.2}");
        assert!(
            (1.6..=2.6).contains(&zero),
            "{name}: zero order falls ×{zero:.2}"
        );
        for (one, zero) in [(&one_coarse, &zero_coarse), (&one_fine, &zero_fine)] {
            assert!(error(one, name) < error(zero, name), "{name}");
        }
    }
}

/// The scene of the paper's setting on a simply supported 3D beam: the
/// AVE-S103 preset at 300 km/h over a 25 m span with lateral modes, the
/// synthetic lateral record (0.2 g peak) shaking it, FRA class 5 with
/// alignment on independent rails, faded in over the 40 m the car starts
/// before the entrance (`run_in: 40`: the full track on the bridge).
fn quake_scene(first_order: bool) -> String {
    format!(
        r#"
name: embs-quake
bridge: {{type: beam, spans: [25.0], bending_stiffness: 8.0e10, mass_per_length: 18000.0,
  lateral_bending_stiffness: 2.0e11, torsional_stiffness: 6.0e10, polar_mass: 90000.0,
  rail_height: 1.2, elements_per_span: 20, damping: {{type: modal, ratio: 0.02}},
  modes: {{count: 12}}}}
vehicles: [{{type: train_3d, speed: 300 km/h, start_position: -40.0}}]
surface: {{type: fra, class: 5, alignment: true, rails: independent, seed: 11, run_in: 40.0}}
ground_motion: [{{file: records/synthetic-lateral.AT2, direction: lateral}}]
contact: {{type: permanent}}
solver: {{method: embs, first_order: {first_order}, compare: true, time_step: 2.0e-4,
  free_vibration: 0.3}}
record:
  - {{name: deck_vertical, quantity: bridge_displacement, x: 12.5}}
  - {{name: deck_vertical_acc, quantity: bridge_acceleration, x: 12.5}}
  - {{name: deck_lateral, quantity: bridge_displacement, x: 12.5, direction: uy}}
  - {{name: deck_lateral_acc, quantity: bridge_acceleration, x: 12.5, direction: uy}}
  - {{name: body_lateral, quantity: vehicle_displacement, dof: body_lateral}}
  - {{name: body_lateral_acc, quantity: vehicle_acceleration, dof: body_lateral}}
"#
    )
}

/// EMBS against coupled on the 3D beam under a lateral record, the
/// paper's Fig. 4 quantities: with the AVE-S103's real suspension ε is
/// not small here (vertical 1.3, lateral 11: the primary lateral springs
/// of 120 MN/m per axle box hold the wheelsets to their bogies), so the
/// errors are those of a large ε, stated per quantity and held at their
/// measured values (2026-11-24) × 1.5 so that a change shows. Measured:
/// deck vertical 4.3e-2, its acceleration 7.5e-2, deck lateral 2.1e-1, its
/// acceleration 8.0e-1, body lateral 3.1e-4, its acceleration 6.3e-2 —
/// the vehicle is well predicted, the deck's lateral motion is not (the
/// zero order alone: deck vertical 7.4e-2, deck lateral 2.0e-1 — at this
/// ε the first order helps vertically only). The summary warns that ε is
/// not small.
#[test]
fn the_3d_beam_under_a_lateral_record_against_coupled() {
    let summary = embs(&quake_scene(true));
    let eps = (summary.epsilon.unwrap(), summary.epsilon_lateral.unwrap());
    eprintln!("ε = {:.3}, lateral {:.3}", eps.0, eps.1);
    assert_eq!(summary.warnings().len(), 2);
    let measured = [
        ("deck_vertical", 4.25e-2),
        ("deck_vertical_acc", 7.49e-2),
        ("deck_lateral", 2.14e-1),
        ("deck_lateral_acc", 8.00e-1),
        ("body_lateral", 3.09e-4),
        ("body_lateral_acc", 6.28e-2),
    ];
    for (name, _) in measured {
        eprintln!("{name}: {:.2e}", error(&summary, name));
    }
    for (name, bound) in measured {
        let e = error(&summary, name);
        assert!(
            e <= 1.5 * bound,
            "{name}: {e:.3e} against {bound:.1e} measured"
        );
    }
}

/// `method: embs` solves permanent contact only; its settings belong to it.
#[test]
fn embs_settings_are_checked() {
    let base = scaled_scene(1.0, true);
    for (edit, words) in [
        (
            base.replace("contact: {type: permanent}", "contact: {type: rigid}"),
            "use `contact: {type: permanent}`",
        ),
        (
            base.replace(
                "method: embs, first_order: true, compare: true,",
                "method: coupled, compare: true,",
            ),
            "`compare` applies to `method: embs` only",
        ),
    ] {
        let error = load_str(&edit, "t.yaml").unwrap_err().to_string();
        assert!(error.contains(words), "{error}");
    }
}

/// The `train_3d` car's roll–lateral coupling through the secondary
/// suspension's height, against the matrix assembled by hand (issue 22:
/// a flipped secondary-height sign passed every EMBS test, which compare
/// EMBS with coupled on the same matrices). The secondary lateral spring
/// k₂y of each of the 4 sets joins the body at rz_c = h₂ − h_c and the
/// bogie at rz_b = h₂ − h_b (u_y = y − φ rz), the vertical one k₂z at
/// ry = ±d₂ (u_z = z + φ ry), so with K = Σ k (P − Q)ᵀ(P − Q):
/// K[y_c, φ_c] = −4 k₂y rz_c, K[φ_c, φ_c] = 4 k₂y rz_c² + 4 k₂z d₂²,
/// K[y_c, φ_b] = 2 k₂y rz_b, K[φ_c, φ_b] = −2 k₂y rz_c rz_b − 2 k₂z d₂²
/// (front bogie). And the lateral ground load −M δ_y (δ_y = 1 on every
/// lateral DOF) by hand: −m_c, −m_b, −m_w on the lateral DOFs, 0 elsewhere.
/// Relative 1e-12 (round-off of the sums).
#[test]
fn train_3d_secondary_coupling_and_ground_load_by_hand() {
    let yaml = "name: hand\nbridge: {type: beam, spans: [25.0], bending_stiffness: 8.0e10, \
                mass_per_length: 18000.0, modes: {count: 4}}\n\
                vehicles: [{type: train_3d, speed: 300 km/h}]\ncontact: {type: permanent}\n";
    let loaded = load_str(yaml, "hand.yaml").unwrap_or_else(|e| panic!("{e}"));
    let vbi::scenario::resolved::Vehicle::Train3d(train) = &loaded.scenario.vehicles[0] else {
        panic!("a train_3d")
    };
    let p = train.cars[0].parameters;
    let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge.clone())
        .unwrap_or_else(|e| panic!("{e}"));
    let car = &model.vehicles[0];
    // A train's DOFs are named per car: `car1_body_lateral`, ….
    let dof = |name: &str| {
        let name = format!("car1_{name}");
        car.dof_names
            .iter()
            .position(|n| *n == name)
            .unwrap_or_else(|| panic!("no DOF {name} in {:?}", car.dof_names))
    };
    let (y_c, roll_c, roll_b) = (
        dof("body_lateral"),
        dof("body_roll"),
        dof("front_bogie_roll"),
    );
    let (k_y, k_z, d2) = (
        p.secondary_stiffness[1],
        p.secondary_stiffness[2],
        p.secondary_half_spacing,
    );
    let (rz_c, rz_b) = (
        p.secondary_height - p.body_height,
        p.secondary_height - p.bogie_height,
    );
    assert!(rz_c.abs() > 0.1 && rz_b.abs() > 0.1, "heights that couple");
    let k = &car.stiffness;
    let close = |a: f64, b: f64, what: &str| {
        assert!(
            (a - b).abs() <= 1e-12 * b.abs(),
            "{what}: {a:e} vs hand {b:e}"
        );
    };
    close(k[(y_c, roll_c)], -4.0 * k_y * rz_c, "K[body y, body roll]");
    close(k[(roll_c, y_c)], -4.0 * k_y * rz_c, "K[body roll, body y]");
    close(
        k[(roll_c, roll_c)],
        4.0 * k_y * rz_c * rz_c + 4.0 * k_z * d2 * d2,
        "K[body roll, body roll]",
    );
    close(k[(y_c, roll_b)], 2.0 * k_y * rz_b, "K[body y, bogie roll]");
    close(
        k[(roll_c, roll_b)],
        -2.0 * k_y * rz_c * rz_b - 2.0 * k_z * d2 * d2,
        "K[body roll, bogie roll]",
    );
    // −M δ_y by hand.
    let mut lateral = vec![0.0; car.dofs()];
    lateral[y_c] = -p.body_mass;
    for bogie in ["front_bogie_lateral", "rear_bogie_lateral"] {
        lateral[dof(bogie)] = -p.bogie_mass;
    }
    for w in 1..=4 {
        lateral[dof(&format!("wheelset{w}_lateral"))] = -p.wheelset_mass;
    }
    for (i, (got, hand)) in car.lateral_ground_load.iter().zip(&lateral).enumerate() {
        assert!(
            (got - hand).abs() <= 1e-12 * hand.abs(),
            "lateral ground load of {}: {got} vs hand {hand}",
            car.dof_names[i]
        );
    }
}

/// Response from rest of q̈ + 2ζωq̇ + ω²q = F sin Ωt (closed form: the
/// steady state plus the free vibration that cancels it at t = 0).
fn forced_sdof(omega: f64, zeta: f64, force: f64, big_omega: f64, t: f64) -> f64 {
    let (w2, o2) = (omega * omega, big_omega * big_omega);
    let denominator = (w2 - o2).powi(2) + (2.0 * zeta * omega * big_omega).powi(2);
    let c = force * (w2 - o2) / denominator;
    let d = -force * 2.0 * zeta * omega * big_omega / denominator;
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let a = -d;
    let b = (zeta * omega * a - c * big_omega) / wd;
    (-zeta * omega * t).exp() * (a * (wd * t).cos() + b * (wd * t).sin())
        + c * (big_omega * t).sin()
        + d * (big_omega * t).cos()
}

/// The lateral ground load through the EMBS solver, against a hand
/// computation (issue 22: a 1 % error in the ground load passed every EMBS
/// test). A 3D beam (rails on the shear centre, h = 0) under the harmonic
/// lateral record üg = 1.5 sin(2π·3 t) m/s², before the train arrives
/// (t ≤ 0.45 s; its front wheelset enters at 0.48 s): each kept mode obeys
/// q̈ + 2ζωq̇ + ω²q = −Γ üg with Γ = ∫ m φ dx, the projection of −M r üg on
/// the mode computed here by Simpson's rule over 2000 intervals of the
/// modes' own lateral shapes, so the mid-span lateral displacement is
/// Σ φ(12.5) q(t) with q the closed form above. Measured 2026-11-27:
/// largest difference 8.75e-6 of the peak at Δt = 1e-4 s (Newmark's period
/// error); bound 4e-5 (4.6× measured), which a 1 % ground load exceeds.
#[test]
fn the_lateral_ground_load_reaches_the_deck_as_computed_by_hand() {
    use std::f64::consts::PI;
    let dir = std::env::temp_dir().join(format!("vbi-embs-ground-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (amplitude, big_omega) = (1.5, 2.0 * PI * 3.0);
    let mut text = String::from("time [s], acceleration [m/s^2]\n");
    for k in 0..=10_000 {
        let t = k as f64 * 1e-4;
        text.push_str(&format!("{t}, {}\n", amplitude * (big_omega * t).sin()));
    }
    let csv = dir.join("harmonic.csv");
    std::fs::write(&csv, text).unwrap();
    let (length, mass) = (25.0, 18000.0);
    let yaml = format!(
        "name: embs-ground\n\
         bridge: {{type: beam, spans: [{length}], bending_stiffness: 8.0e10, mass_per_length: {mass},\n\
         \x20 lateral_bending_stiffness: 2.0e11, torsional_stiffness: 6.0e10, polar_mass: 90000.0,\n\
         \x20 rail_height: 0.0, damping: {{type: modal, ratio: 0.02}},\n\
         \x20 modes: {{count: 12, static_correction: false}}}}\n\
         vehicles: [{{type: train_3d, speed: 300 km/h, start_position: -40.0}}]\n\
         ground_motion: [{{file: \"{}\", direction: lateral}}]\n\
         contact: {{type: permanent}}\n\
         solver: {{method: embs, time_step: 1.0e-4}}\n\
         record: [{{name: deck_lateral, quantity: bridge_displacement, x: 12.5, direction: uy}}]\n",
        csv.display()
    );
    let loaded = load_str(&yaml, "embs-ground.yaml").unwrap_or_else(|e| panic!("{e}"));
    let bridge = loaded.bridge.clone();
    let modes = bridge.mode_count();
    let lateral = |x: f64| {
        let mut values = vec![0.0; modes];
        bridge.mode_values_in(vbi::contact::ContactDirection::Lateral, x, 0.0, &mut values);
        values
    };
    // Γ = ∫ m φ dx by Simpson's rule.
    let intervals = 2000;
    let h = length / intervals as f64;
    let mut gamma = vec![0.0; modes];
    for k in 0..=intervals {
        let weight = if k == 0 || k == intervals {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        };
        for (g, phi) in gamma.iter_mut().zip(lateral(k as f64 * h)) {
            *g += mass * h / 3.0 * weight * phi;
        }
    }
    assert!(gamma.iter().any(|g| g.abs() > 1.0), "lateral modes kept");
    let at_mid = lateral(12.5);
    let omegas: Vec<f64> = bridge.frequencies().iter().map(|f| 2.0 * PI * f).collect();
    let outcome = simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
    let column = outcome
        .history
        .columns
        .iter()
        .find(|c| c.name == "deck_lateral")
        .unwrap();
    let (mut worst, mut peak) = (0.0f64, 0.0f64);
    for (&t, &value) in outcome.history.time.iter().zip(&column.values) {
        if t > 0.45 {
            break;
        }
        let reference: f64 = (0..modes)
            .map(|i| at_mid[i] * forced_sdof(omegas[i], 0.02, -gamma[i] * amplitude, big_omega, t))
            .sum();
        worst = worst.max((value - reference).abs());
        peak = peak.max(reference.abs());
    }
    eprintln!(
        "lateral ground load through EMBS: {:.2e} of the peak {peak:.3e} m",
        worst / peak
    );
    assert!(peak > 1e-5, "the record shakes the deck: {peak:e} m");
    assert!(worst < 4e-5 * peak, "{:e} of the peak", worst / peak);
}
