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
/// measured values × 1.5 so that a change shows. Measured 2026-11-27 with
/// the track faded in over the 40 m approach (full roughness on the whole
/// span; before, the profile started at the entrance shifted to 0 with a
/// slope jump, and the errors were 4.3e-2, 7.5e-2, 2.1e-1, 8.0e-1, 3.1e-4,
/// 6.3e-2): deck vertical 1.01e-1, its acceleration 1.90e-1, deck lateral
/// 2.10e-1, its acceleration 8.03e-1, body lateral 3.33e-4, its
/// acceleration 5.90e-2 — the vehicle is well predicted, the deck is not
/// (the zero order alone: deck vertical 1.32e-1, deck lateral 1.92e-1 — at
/// this ε the first order helps vertically only). The summary warns that ε
/// is not small.
#[test]
fn the_3d_beam_under_a_lateral_record_against_coupled() {
    let summary = embs(&quake_scene(true));
    let eps = (summary.epsilon.unwrap(), summary.epsilon_lateral.unwrap());
    eprintln!("ε = {:.3}, lateral {:.3}", eps.0, eps.1);
    assert_eq!(summary.warnings().len(), 2);
    let measured = [
        ("deck_vertical", 1.01e-1),
        ("deck_vertical_acc", 1.90e-1),
        ("deck_lateral", 2.10e-1),
        ("deck_lateral_acc", 8.03e-1),
        ("body_lateral", 3.33e-4),
        ("body_lateral_acc", 5.90e-2),
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
