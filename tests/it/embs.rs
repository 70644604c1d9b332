//! The EMBS solver (EMBS paper, Section 2) against the coupled solution of
//! the same scene. Each test states its reference and tolerance.

use vbi::plan::load_str;
use vbi::report::embs::EmbsSummary;
use vbi::run::simulate;

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
/// synthetic lateral record (0.2 g peak at 3.0 s of the record) shaking
/// it with its peak at 0.8 s of the run, while the car is on the span
/// (0.48–1.08 s), German low-interference track (fit for 300 km/h) with
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
surface: {{type: german, interference: low, alignment: true, rails: independent, seed: 11, run_in: 40.0}}
ground_motion: [{{file: records/synthetic-lateral.AT2, direction: lateral, start_time: -2.2}}]
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
/// not small here (vertical 1.3, lateral 6.9 against the lowest lateral
/// mode: the primary lateral springs of 120 MN/m per axle box hold the
/// wheelsets to their bogies), so the errors are those of a large ε, stated
/// per quantity and held at their measured values (2026-11-27, record
/// peak during the crossing, German low-interference track faded in over
/// the car's 40 m approach) × 1.5 so that a change shows. Measured: deck
/// vertical 3.24e-2, its acceleration 9.14e-2, deck lateral 3.73e-2, its
/// acceleration 1.34e-1, body lateral 2.97e-5, its acceleration 7.04e-3. The summary warns that ε is not
/// small in both directions.
#[test]
fn the_3d_beam_under_a_lateral_record_against_coupled() {
    let summary = embs(&quake_scene(true));
    let eps = (summary.epsilon.unwrap(), summary.epsilon_lateral.unwrap());
    eprintln!("ε = {:.3}, lateral {:.3}", eps.0, eps.1);
    let epsilon_warnings = summary
        .advice()
        .iter()
        .filter(|a| {
            a.id == vbi::advice::EMBS_EPSILON_NOT_SMALL.id && a.text().contains("small parameter")
        })
        .count();
    assert_eq!(epsilon_warnings, 2);
    let measured = [
        ("deck_vertical", 3.24e-2),
        ("deck_vertical_acc", 9.14e-2),
        ("deck_lateral", 3.73e-2),
        ("deck_lateral_acc", 1.34e-1),
        ("body_lateral", 2.97e-5),
        ("body_lateral_acc", 7.04e-3),
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
         ground_motion: [{{file: harmonic.csv, direction: lateral}}]\n\
         contact: {{type: permanent}}\n\
         solver: {{method: embs, time_step: 1.0e-4, allow_large_epsilon: true}}\n\
         record: [{{name: deck_lateral, quantity: bridge_displacement, x: 12.5, direction: uy}}]\n"
    );
    // The scene is a file of the record's folder: a scene reads only inside its own.
    let scene_file = dir.join("embs-ground.yaml");
    let loaded = load_str(&yaml, scene_file.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"));
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

/// The golden seismic scene is seismic: the strong phase of its lateral
/// record (scenarios/records/synthetic-lateral.AT2, 0.2 g peak at 3.0 s of
/// the record, strong phase 2–6 s by its envelope, make_synthetic.py)
/// overlaps the crossing. Reference: the record's own peak; the largest
/// |üg| at a step where some wheel is on the deck must reach 90 % of it
/// (the record shifted by `start_time` so that its peak falls while the
/// car is on the viaduct).
#[test]
fn the_golden_seismic_scene_shakes_the_bridge_during_the_crossing() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/embs-viaduct-ave-s103-quake.yaml"
    );
    let loaded = vbi::plan::load_file(std::path::Path::new(file)).unwrap_or_else(|e| panic!("{e}"));
    let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge).unwrap();
    let ground = model
        .ground
        .as_ref()
        .expect("the scene has a ground motion");
    let record_peak = ground
        .lateral
        .iter()
        .map(|r| r.peak_acceleration())
        .fold(0.0f64, f64::max);
    let mut positions = vec![0.0; model.wheels.len()];
    let mut on_bridge_peak = 0.0f64;
    for step in 0..=model.steps {
        let t = step as f64 * model.time_step;
        model.wheel_positions(t, &mut positions);
        if positions.iter().any(|&x| model.bridge.is_on(x)) {
            on_bridge_peak = on_bridge_peak.max(ground.lateral_acceleration(t).abs());
        }
    }
    let g = 9.80665;
    eprintln!(
        "record peak {:.3} g, while a wheel is on the deck {:.3} g",
        record_peak / g,
        on_bridge_peak / g
    );
    assert!(
        on_bridge_peak >= 0.9 * record_peak,
        "peak |üg| while a wheel is on the bridge {:.4} g against the record's {:.4} g",
        on_bridge_peak / g,
        record_peak / g
    );
}

/// The golden viaduct's model (scenarios/viaduct-2span, modes to 80 Hz)
/// and the scene's 3D car, built without running.
fn golden_model() -> vbi::model::Model {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/embs-viaduct-ave-s103-quake.yaml"
    );
    let loaded = vbi::plan::load_file(std::path::Path::new(file)).unwrap_or_else(|e| panic!("{e}"));
    vbi::model::Model::build(&loaded.scenario, loaded.bridge).unwrap()
}

/// ε per direction on a model whose first mode moves no contact: the
/// generated two-span viaduct's 2.03 Hz mode is the decks sliding
/// longitudinally on their bearings. ε must divide by the lowest mode
/// that moves the rails in each direction — the 11.54 Hz vertical
/// bending of the spans, the 5.56 Hz lateral sway — not by that one.
/// The wheelset frequencies are hand-computed from the AVE-S103 preset
/// (EMBS paper, Table 2; rail_3d.rs) with b₀ = 0.88 m and d₁ = 1.0 m:
/// vertically the contact coordinate z_L has m = m_w/4 + I_wx/(4b₀²) =
/// 450 + 1000/3.0976 = 772.83 kg and k = k_z[(½ + d₁/2b₀)² + (½ −
/// d₁/2b₀)²] = 1.2e6 × 1.14568 N/m (the two axle-box springs), so
/// f_w = 6.713 Hz; laterally m = 1800 kg on 2 × 120 MN/m, f_w = 58.12 Hz.
/// The sprung mass per vertical wheel is (47 800 + 2 × 3 500)/8 = 6 850 kg
/// (f_s = 2.255 Hz), per lateral contact 54 800/4 = 13 700 kg (f_s =
/// 21.06 Hz). Tolerance 1e-9 relative on the closed forms (round-off).
#[test]
fn epsilon_is_taken_per_direction_against_the_modes_that_move_the_contacts() {
    use vbi::contact::ContactDirection::{Lateral, Vertical};
    use vbi::solve::embs_scale::directional_scale;
    let model = golden_model();
    let f = model.bridge.frequencies();
    let tau = std::f64::consts::TAU;
    let b0: f64 = 0.88;
    let m_v = 450.0 + 1000.0 / (4.0 * b0 * b0);
    let k_v = 1.2e6 * ((0.5 + 1.0 / (2.0 * b0)).powi(2) + (0.5 - 1.0 / (2.0 * b0)).powi(2));
    let hand = [
        (
            Vertical,
            (k_v / m_v).sqrt() / tau,
            (k_v / 6850.0).sqrt() / tau,
            4,
        ),
        (
            Lateral,
            (240e6f64 / 1800.0).sqrt() / tau,
            (240e6f64 / 13700.0).sqrt() / tau,
            3,
        ),
    ];
    for (d, wheelset, sprung, mode) in hand {
        let s = directional_scale(&model, d).expect("the car has contacts both ways");
        eprintln!("{s:?}");
        assert_eq!(s.bridge_mode, mode, "{d:?}");
        assert!((s.bridge_frequency - f[mode - 1]).abs() < 1e-12);
        assert!(
            (s.wheelset_frequency / wheelset - 1.0).abs() < 1e-9,
            "{d:?}"
        );
        assert!((s.sprung_frequency / sprung - 1.0).abs() < 1e-9, "{d:?}");
        assert!((s.epsilon - wheelset / f[mode - 1]).abs() < 1e-9 * s.epsilon);
        assert!((s.epsilon_sprung - sprung / f[mode - 1]).abs() < 1e-9 * s.epsilon);
        // The first mode (2.03 Hz) hardly moves the contacts: measured
        // shares 3.2e-5 vertically (the bearings' tilt), 2e-33 laterally.
        assert!(s.lowest_mode.1 < 1e-4, "{d:?}: {:?}", s.lowest_mode);
        assert!((s.lowest_mode.0 - f[0]).abs() < 1e-12);
    }
}

/// The 25 m 3D beam of [`quake_scene`] with the primary suspension's
/// stiffness and damping scaled by `s` (ε ∝ √s), recording vertical and
/// lateral quantities, compared with `coupled`.
fn suspension_scene(s: f64, compare: bool, extra: &str) -> String {
    format!(
        r#"
name: embs-suspension
bridge: {{type: beam, spans: [25.0], bending_stiffness: 8.0e10, mass_per_length: 18000.0,
  lateral_bending_stiffness: 2.0e11, torsional_stiffness: 6.0e10, polar_mass: 90000.0,
  rail_height: 1.2, elements_per_span: 20, damping: {{type: modal, ratio: 0.02}},
  modes: {{count: 12}}}}
vehicles:
  - type: train_3d
    speed: 300 km/h
    start_position: -5.0
    parameters: {{primary_longitudinal_stiffness: {kx}, primary_lateral_stiffness: {ky},
      primary_vertical_stiffness: {kz}, primary_longitudinal_damping: {cx},
      primary_lateral_damping: {cy}, primary_vertical_damping: {cz}}}
surface: {{type: german, interference: low, alignment: true, rails: independent, seed: 11}}
ground_motion: [{{file: records/synthetic-lateral.AT2, direction: lateral, start_time: -2.6}}]
contact: {{type: permanent}}
solver: {{method: embs, compare: {compare}, time_step: 2.0e-4, free_vibration: 0.2{extra}}}
record:
  - {{name: deck_vertical, quantity: bridge_displacement, x: 12.5}}
  - {{name: deck_vertical_acc, quantity: bridge_acceleration, x: 12.5}}
  - {{name: wheel1_force, quantity: contact_force, wheel: 1}}
  - {{name: body_bounce_acc, quantity: vehicle_acceleration, dof: body_bounce}}
  - {{name: deck_lateral, quantity: bridge_displacement, x: 12.5, direction: uy}}
  - {{name: body_lateral_acc, quantity: vehicle_acceleration, dof: body_lateral}}
"#,
        kx = 12.5e6 * s,
        ky = 120e6 * s,
        kz = 1.2e6 * s,
        cx = 9e3 * s,
        cy = 27.9e3 * s,
        cz = 10e3 * s,
    )
}

/// The first-order ratio η of a quantity (summary `embs.orders`).
fn first_order_ratio(summary: &EmbsSummary, name: &str) -> f64 {
    summary
        .orders
        .iter()
        .find(|o| o.name == name)
        .unwrap_or_else(|| panic!("no quantity {name}"))
        .first_order_ratio
}

/// The a-posteriori check falls as ε²: with the primary suspension's
/// stiffness and damping scaled by s = 1, 0.1, 0.01 (ε ∝ √s, so ε² ∝ s)
/// the first-order forcing F₁ = c_w u̇_w⁽⁰⁾ + k_wu u_u⁽⁰⁾ + c_wu u̇_u⁽⁰⁾
/// scales with s, and so does η = max|first-order part| / max|zero
/// order's dynamic part| of the deck's vertical deflection and
/// acceleration: measured ×10.00 per step (η 4.64e-2, 4.64e-3, 4.64e-4 and
/// 3.78e-2, 3.78e-3, 3.78e-4), asserted within ×9–11; the EMBS error
/// against coupled falls with it (2.0e-2 → 2.0e-3 for the acceleration at
/// s = 0.1 → 0.01, 5.2 η). The vehicle's quantities fall more irregularly
/// (the wheel force ×8.6 then ×6.8, with ε_lat 6.9 → 2.2 → 0.69 sharing
/// the roll), and are printed only.
#[test]
fn the_first_order_ratio_falls_as_epsilon_squared() {
    let runs: Vec<EmbsSummary> = [1.0, 0.1, 0.01]
        .iter()
        .map(|&s| embs(&suspension_scene(s, true, "")))
        .collect();
    let vertical = ["deck_vertical", "deck_vertical_acc"];
    for (run, s) in runs.iter().zip([1.0, 0.1, 0.01]) {
        eprintln!(
            "s = {s}: ε vertical {:.3}, lateral {:.3}",
            run.epsilon.unwrap(),
            run.epsilon_lateral.unwrap()
        );
        for o in &run.orders {
            eprintln!(
                "  {:18} η {:.3e} error {:.3e}",
                o.name,
                o.first_order_ratio,
                error(run, &o.name)
            );
        }
    }
    for name in vertical {
        let eta: Vec<f64> = runs.iter().map(|r| first_order_ratio(r, name)).collect();
        for pair in eta.windows(2) {
            let fall = pair[0] / pair[1];
            assert!(
                (9.0..=11.0).contains(&fall),
                "{name}: η falls ×{fall:.2} for s ×0.1"
            );
        }
        assert!(error(&runs[2], name) < error(&runs[1], name), "{name}");
    }
}

/// Where ε ≥ 1 in a direction whose quantities are recorded the series
/// cannot converge, and a run without `compare` is refused with the
/// frequencies and the records named; `allow_large_epsilon: true` runs
/// it, and a scene recording only the directions where ε < 1 runs.
/// Here (the 25 m 3D beam, suspension ×0.1): ε = 0.41 vertically,
/// 2.19 laterally.
#[test]
fn embs_is_refused_where_epsilon_reaches_one_in_a_recorded_direction() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios/embs-test.yaml");
    let run = |yaml: &str| {
        let loaded = load_str(yaml, file).unwrap_or_else(|e| panic!("{e}"));
        simulate(loaded, &mut |_, _| {})
    };
    let Err(refused) = run(&suspension_scene(0.1, false, "")) else {
        panic!("refused")
    };
    let refused = refused.to_string();
    eprintln!("{refused}");
    for words in [
        "lateral",
        "deck_lateral, body_lateral_acc",
        "allow_large_epsilon",
        "method: coupled",
    ] {
        assert!(refused.contains(words), "{words}: {refused}");
    }
    assert!(!refused.contains("deck_vertical"), "{refused}");
    let allowed = run(&suspension_scene(0.1, false, ", allow_large_epsilon: true"))
        .unwrap_or_else(|e| panic!("{e}"));
    let summary = allowed.summary.embs.expect("an EMBS summary");
    assert!(
        summary
            .advice()
            .iter()
            .any(|a| a.text().contains("lateral small parameter"))
    );
    // Only vertical records: runs, ε_v = 0.41 < 1.
    let vertical_only: String = suspension_scene(0.1, false, "")
        .lines()
        .filter(|l| !(l.starts_with("  - {name:") && l.contains("lateral")))
        .collect::<Vec<_>>()
        .join("\n");
    run(&vertical_only).unwrap_or_else(|e| panic!("{e}"));
    let Err(bad) = load_str(
        &suspension_scene(0.1, false, "")
            .replace("method: embs,", "method: coupled,")
            .replace("compare: false,", "allow_large_epsilon: true,"),
        file,
    ) else {
        panic!("refused")
    };
    let bad = bad.to_string();
    assert!(
        bad.contains("`allow_large_epsilon` applies to `method: embs` only"),
        "{bad}"
    );
}
