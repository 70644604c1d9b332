//! Modes of an imported model that the scene cannot move are left out of
//! the kept ones and of `count`, with the reason (issue 40.6).
//!
//! The golden viaduct (`scenarios/viaduct-2span-axle-loads.yaml`: a
//! symmetric deck, its two rails loaded vertically) has lateral modes that
//! keep its rails still vertically to round-off (7.6e-11 of their largest
//! motion, against at least 1.7e-3 for every other mode): a vertical wheel
//! load does no work on them, so their modal coordinates stay 0. The tests
//! check the count's meaning against an unfiltered solve of the same model
//! and, the physics, that adding the left-out modes back changes no
//! record (to 1e-9 of its peak; their generalised forces are 1e-11 of
//! their largest motion at most) and loses none of the ground's
//! participation.

use crate::support::{column, manifest_dir, max_abs};
use vbi::bridge::{ModalBridge, ModeRequest};
use vbi::plan::{Loaded, load_str};
use vbi::run::simulate;

/// The golden viaduct scene with `modes` set and `extra` appended.
fn viaduct(modes: &str, extra: &str) -> Loaded {
    let path = manifest_dir().join("scenarios/viaduct-2span-axle-loads.yaml");
    let source = std::fs::read_to_string(&path).unwrap();
    let source = source.replace(
        "  damping: {type: modal, ratio: 0.02}\n",
        &format!("  damping: {{type: modal, ratio: 0.02}}\n  modes: {modes}\n"),
    ) + extra;
    let label = manifest_dir().join("scenarios/modes-left-out.yaml");
    load_str(&source, label.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"))
}

/// Frequencies of the lowest `count` modes, none left out.
fn unfiltered(loaded: &Loaded, count: usize) -> Vec<f64> {
    ModalBridge::build_with(&loaded.scenario.bridge, ModeRequest::Lowest(count))
        .unwrap()
        .frequencies()
}

#[test]
fn count_counts_the_modes_the_scene_moves() {
    let loaded = viaduct("{count: 200}", "");
    let bridge = &loaded.bridge;
    assert_eq!(bridge.mode_count(), 200, "{}", bridge.selection);
    let left_out = &bridge.left_out;
    assert!(!left_out.is_empty(), "{}", bridge.selection);
    assert!(
        left_out.iter().all(|m| m.direction == "lateral"),
        "{left_out:?}"
    );
    let top = *bridge.frequencies().last().unwrap();
    assert!(left_out.iter().all(|m| m.frequency < top), "{left_out:?}");
    // Kept and left out together are the lowest 200 + k of the model.
    let mut together: Vec<f64> = bridge
        .frequencies()
        .into_iter()
        .chain(left_out.iter().map(|m| m.frequency))
        .collect();
    together.sort_by(f64::total_cmp);
    let all = unfiltered(&loaded, together.len());
    for (a, b) in together.iter().zip(&all) {
        assert!((a - b).abs() <= 1e-9 * b, "{a} Hz against {b} Hz");
    }
    // The reason says what was left out and why.
    assert!(
        bridge.selection.contains(&format!(
            "{} modes left out of them and of the count ({} lateral at",
            left_out.len(),
            left_out.len()
        )) && bridge.selection.contains("the scene cannot move them"),
        "{}",
        bridge.selection
    );
    // A cut-off keeps every moved mode up to it and no left-out one.
    let cut = viaduct(&format!("{{max_frequency: {top}}}"), "");
    let near = |a: &[f64], b: &[f64]| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-9 * y)
    };
    assert!(near(&cut.bridge.frequencies(), &bridge.frequencies()));
    let left = |b: &ModalBridge| -> Vec<f64> { b.left_out.iter().map(|m| m.frequency).collect() };
    assert!(near(&left(&cut.bridge), &left(bridge)));
}

/// Every mode up to 59 Hz: inside a 1.4 Hz gap of the spectrum (58.17 to
/// 59.61 Hz, `vbi modes`), so the kept modes and their left-out
/// neighbours span whole eigenspaces whichever solve finds them.
const GAP: &str = "{max_frequency: 59.0}";

#[test]
fn left_out_modes_change_no_record() {
    let filtered = viaduct(GAP, "");
    let k = filtered.bridge.left_out.len();
    assert!(k >= 5, "{:?}", filtered.bridge.left_out);
    let mut every = viaduct(GAP, "");
    every.bridge =
        ModalBridge::build_with(&every.scenario.bridge, ModeRequest::UpTo(59.0)).unwrap();
    assert_eq!(every.bridge.mode_count(), filtered.bridge.mode_count() + k);
    let a = simulate(filtered, &mut |_, _| {}).unwrap();
    let b = simulate(every, &mut |_, _| {}).unwrap();
    for name in ["span1_mid", "span1_mid_acc", "span2_mid"] {
        let (x, y) = (column(&a, name), column(&b, name));
        let peak = max_abs(y);
        let worst = x
            .iter()
            .zip(y)
            .map(|(p, q)| (p - q).abs())
            .fold(0.0, f64::max);
        assert!(
            peak > 0.0 && worst <= 1e-9 * peak,
            "{name}: {worst:e} of {peak:e}"
        );
    }
}

#[test]
fn ground_motion_keeps_the_modes_it_drives() {
    // Under a lateral record the kept modes carry all the lateral
    // participation Σ Γ² that every mode up to the cut does: what is left
    // out (the rails moving sideways against each other) has none.
    let quake = "ground_motion:\n  - {file: records/synthetic-lateral.AT2, direction: lateral}\n";
    let loaded = viaduct(GAP, quake);
    let every = ModalBridge::build_with(&loaded.scenario.bridge, ModeRequest::UpTo(59.0)).unwrap();
    let carried = |bridge: &ModalBridge| -> f64 {
        let (gamma, _) = bridge.lateral_participation(&loaded.scenario.bridge);
        gamma.iter().map(|g| g * g).sum()
    };
    let (kept, all) = (carried(&loaded.bridge), carried(&every));
    assert!(
        all > 0.0 && (all - kept).abs() <= 1e-12 * all,
        "{kept} of {all}"
    );
    // The rule itself: a shape still at the vertical rails is moved by a
    // lateral record exactly when it has lateral participation (here the
    // unit lateral translation, M-normalised), and by nothing else.
    let vbi::scenario::resolved::Bridge::FeImport(fe) = &loaded.scenario.bridge else {
        panic!("an imported bridge");
    };
    let model = &fe.model;
    let lateral: Vec<f64> = model
        .dofs
        .iter()
        .map(|(_, d)| f64::from(u8::from(*d == vbi::scene::imported::Direction::Uy)))
        .collect();
    let scale = 1.0 / model.translational_mass[1].sqrt();
    let shape = faer::Mat::from_fn(lateral.len(), 1, |i, _| scale * lateral[i]);
    use vbi::bridge::fe_import::excited::{SceneLoads, excited_modes};
    let ground = SceneLoads {
        lateral_ground: true,
        ..SceneLoads::default()
    };
    assert_eq!(excited_modes(model, &shape, ground), [true]);
    assert_eq!(excited_modes(model, &shape, SceneLoads::default()), [false]);
}
