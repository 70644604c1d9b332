//! `vbi converge`: observed order of the time-step ladder, monotone errors,
//! the cheapest run within tolerance, failed runs, determinism, and the
//! command line (files written, bad tolerance).

use crate::support::{scratch_dir, vbi};

use vbi::plan::{self, Loaded};
use vbi::study::converge::{
    self, Convergence, Ladder, Options, QuantityError, RunReport, cheapest_within, parse_tolerance,
    plan,
};

/// The LCP paper's oscillator (with an unsprung mass) on a smooth, modally
/// damped beam, 2 modes (so the reference keeps 4, up to 80 Hz) and a
/// 0.25 ms step: the reference's highest mode has ωΔt = 0.03 and the ladder's
/// coarsest (1 ms) 0.5, inside Newmark's asymptotic range.
fn smooth_scene(time_step: f64, newmark: &str) -> String {
    format!(
        "name: smooth-two-modes
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2423e9
  mass_per_length: 2000.0
  modes: {{count: 2}}
  damping: {{type: modal, ratio: 0.02}}
vehicles:
  - type: oscillator
    sprung_mass: 4000.0
    unsprung_mass: 1000.0
    stiffness: 4.0e6
    damping: 2.53e4
    speed: 25.0
solver: {{method: coupled, time_step: {time_step}, free_vibration: 0.2{newmark}}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 10.0}}
  - {{name: midspan_acceleration, quantity: bridge_acceleration, x: 10.0}}
  - {{name: sprung, quantity: vehicle_displacement, dof: sprung}}
  - {{name: sprung_acceleration, quantity: vehicle_acceleration, dof: sprung}}
  - {{name: contact_force, quantity: contact_force, wheel: 1}}
"
    )
}

fn load(text: &str) -> Loaded {
    plan::load_str(text, "inline.yaml").expect("valid scene")
}

fn study(text: &str, levels: usize, tolerance: f64) -> Convergence {
    let options = Options {
        levels,
        tolerance,
        ..Options::default()
    };
    converge::converge(&load(text), &options, &mut |_, _, _| {}).expect("study runs")
}

fn time_step_runs(study: &Convergence) -> Vec<&RunReport> {
    study
        .runs
        .iter()
        .filter(|r| r.ladder == Ladder::TimeStep)
        .collect()
}

#[test]
fn plan_refines_the_reference_and_builds_both_ladders() {
    let (reference, ladder) = plan(1e-3, 10, 38, 3);
    assert_eq!(reference.time_step, 2.5e-4);
    assert_eq!(reference.modes, 20);
    let steps: Vec<(Ladder, f64, usize)> = ladder
        .iter()
        .map(|(l, r)| (*l, r.time_step, r.modes))
        .collect();
    assert_eq!(
        steps,
        [
            (Ladder::TimeStep, 1e-3, 20),
            (Ladder::TimeStep, 2e-3, 20),
            (Ladder::TimeStep, 4e-3, 20),
            (Ladder::Modes, 1e-3, 10),
            (Ladder::Modes, 1e-3, 5),
            (Ladder::Modes, 1e-3, 2),
        ]
    );
    // Every ladder step is an exact multiple of the reference step.
    for (_, r) in &ladder {
        let k = r.time_step / reference.time_step;
        assert_eq!(k, k.round(), "{}", r.label());
    }
    // All modes already used: the reference keeps them, no duplicate runs.
    let (reference, ladder) = plan(1e-4, 3, 3, 1);
    assert_eq!(reference.modes, 3);
    let modes: Vec<usize> = ladder.iter().map(|(_, r)| r.modes).collect();
    assert_eq!(modes, [3, 1]);
    assert_eq!(ladder[0].1.label(), "dt=1e-4 s, 3 modes");
    assert_eq!(ladder[1].1.label(), "dt=1e-4 s, 1 mode");
}

#[test]
fn tolerance_accepts_percent_or_fraction() {
    assert_eq!(parse_tolerance("1%"), Ok(0.01));
    assert_eq!(parse_tolerance("0.01"), Ok(0.01));
    assert_eq!(parse_tolerance(" 2.5 % "), Ok(0.025));
    for bad in ["abc", "", "%", "-1%", "0", "nan", "inf"] {
        assert!(parse_tolerance(bad).is_err(), "{bad:?}");
    }
}

#[test]
fn newmark_average_acceleration_converges_at_second_order() {
    let study = study(&smooth_scene(2.5e-4, ""), 3, 0.01);
    assert_eq!(study.reference.label, "dt=6.25e-5 s, 4 modes");
    // Two halvings × five quantities, all in the asymptotic range.
    assert_eq!(study.orders.len(), 10, "{:#?}", study.orders);
    for order in &study.orders {
        assert!(
            (order.order - 2.0).abs() <= 0.3,
            "{} at {:e} -> {:e}: p = {:.3}",
            order.quantity,
            order.coarse_step,
            order.fine_step,
            order.order
        );
    }
    let median = study.median_order.expect("orders");
    assert!((median - 2.0).abs() <= 0.1, "median order {median}");
}

#[test]
fn errors_fall_monotonically_along_the_time_step_ladder() {
    let study = study(&smooth_scene(2.5e-4, ""), 4, 0.01);
    let ladder = time_step_runs(&study);
    assert_eq!(ladder.len(), 4);
    for pair in ladder.windows(2) {
        let (fine, coarse) = (pair[0], pair[1]);
        assert_eq!(coarse.time_step, 2.0 * fine.time_step);
        let fine_errors = fine.errors.as_ref().expect("run succeeded");
        let coarse_errors = coarse.errors.as_ref().expect("run succeeded");
        for (f, c) in fine_errors.iter().zip(coarse_errors) {
            assert!(
                f.max_abs < c.max_abs && f.rms < c.rms,
                "{}: {} gives {:e}/{:e}, {} gives {:e}/{:e}",
                f.name,
                fine.label,
                f.max_abs,
                f.rms,
                coarse.label,
                c.max_abs,
                c.rms
            );
            assert!(f.max_abs > 0.0, "{}: a coarser run differs", f.name);
        }
        assert!(fine.steps.unwrap() > coarse.steps.unwrap());
    }
    // The mode ladder's errors include modal truncation: 2 and 1 modes miss
    // modes 3 and 4 of the reference.
    assert!(
        study
            .runs
            .iter()
            .filter(|r| r.ladder == Ladder::Modes)
            .all(|r| r.worst_max_abs().unwrap() > ladder[0].worst_max_abs().unwrap())
    );
}

#[test]
fn cheapest_within_tolerance_is_the_largest_step_that_meets_it() {
    let first = study(&smooth_scene(2.5e-4, ""), 4, 1.0);
    let ladder = time_step_runs(&first);
    let worst: Vec<f64> = ladder.iter().map(|r| r.worst_max_abs().unwrap()).collect();
    // A tolerance between the errors of the 2nd and 3rd rung (geometric mean).
    let tolerance = (worst[1] * worst[2]).sqrt();
    let study = study(&smooth_scene(2.5e-4, ""), 4, tolerance);
    let expected = time_step_runs(&study)
        .into_iter()
        .filter(|r| r.worst_max_abs().unwrap() <= tolerance)
        .max_by(|a, b| a.time_step.total_cmp(&b.time_step))
        .expect("a run meets the tolerance");
    let chosen = study.cheapest_run().expect("a run meets the tolerance");
    // The choice is by measured wall time, so on a loaded machine the
    // millisecond runs can swap places: the chosen run meets the tolerance
    // and no qualifying run was measured faster. The largest qualifying
    // step is the expected winner (half the steps of the finer rung), which
    // only timing noise can overturn.
    assert!(chosen.worst_max_abs().unwrap() <= tolerance);
    let qualifying: Vec<&RunReport> = study
        .runs
        .iter()
        .filter(|r| r.worst_max_abs().is_some_and(|e| e <= tolerance))
        .collect();
    assert!(
        qualifying
            .iter()
            .all(|r| r.wall_time.unwrap() >= chosen.wall_time.unwrap()),
        "{} chosen, not the fastest qualifying run",
        chosen.label
    );
    assert_eq!(expected.label, "dt=5e-4 s, 4 modes");
    // Tighter than every run's error: nothing qualifies.
    let best = study
        .runs
        .iter()
        .filter_map(RunReport::worst_max_abs)
        .fold(f64::INFINITY, f64::min);
    assert_eq!(cheapest_within(&study.runs, 0.5 * best, &[]), None);
    let strict = converge::converge(
        &load(&smooth_scene(2.5e-4, "")),
        &Options {
            levels: 2,
            tolerance: 1e-12,
            ..Options::default()
        },
        &mut |_, _, _| {},
    )
    .unwrap();
    assert_eq!(strict.cheapest, None);
}

/// With every run within tolerance, the combined ladder pairs each coarser
/// step with each smaller mode count (finest step, most modes first); runs
/// outside the tolerance on their own ladder are not combined.
#[test]
fn the_combined_ladder_pairs_coarser_steps_with_fewer_modes() {
    let study = study(&smooth_scene(2.5e-4, ""), 3, 1.0);
    let combined: Vec<&str> = study
        .runs
        .iter()
        .filter(|r| r.ladder == Ladder::Combined)
        .map(|r| r.label.as_str())
        .collect();
    assert_eq!(
        combined,
        [
            "dt=5e-4 s, 2 modes",
            "dt=5e-4 s, 1 mode",
            "dt=1e-3 s, 2 modes",
            "dt=1e-3 s, 1 mode"
        ]
    );
    // Each combined run is measured against the reference like the others.
    for run in study.runs.iter().filter(|r| r.ladder == Ladder::Combined) {
        assert!(run.worst_max_abs().unwrap() > 0.0, "{}", run.label);
    }
    // From the measured runs: only the halves within tolerance combine.
    let at = |ladder, time_step, modes, error| RunReport {
        ladder,
        time_step,
        modes,
        ..synthetic("", 1.0, error)
    };
    let runs = [
        at(Ladder::TimeStep, 1e-3, 8, 0.001),
        at(Ladder::TimeStep, 2e-3, 8, 0.005),
        at(Ladder::TimeStep, 4e-3, 8, 0.05),
        at(Ladder::Modes, 1e-3, 4, 0.002),
        at(Ladder::Modes, 1e-3, 2, 0.2),
    ];
    let pairs: Vec<(f64, usize)> = converge::combined_plan(&runs, 1e-3, 8, 0.01, &[])
        .iter()
        .map(|r| (r.time_step, r.modes))
        .collect();
    assert_eq!(pairs, [(2e-3, 4)]);
    assert!(converge::combined_plan(&runs, 1e-3, 8, 0.0001, &[]).is_empty());
}

fn synthetic(label: &str, wall_time: f64, error: f64) -> RunReport {
    RunReport {
        label: label.into(),
        ladder: Ladder::TimeStep,
        time_step: 1e-3,
        modes: 1,
        steps: Some(10),
        wall_time: Some(wall_time),
        advice: Vec::new(),
        errors: Ok(vec![QuantityError {
            name: "q".into(),
            unit: "m",
            max_abs: error,
            rms: error,
        }]),
    }
}

#[test]
fn cheapest_is_by_wall_time_and_ignores_failed_and_non_finite_runs() {
    let mut failed = synthetic("failed", 0.1, 0.0);
    failed.wall_time = None;
    failed.steps = None;
    failed.errors = Err("diverged".into());
    let runs = vec![
        synthetic("slow", 3.0, 0.001),
        synthetic("fast", 1.0, 0.009),
        synthetic("fastest but wrong", 0.5, 0.02),
        synthetic("nan", 0.2, f64::NAN),
        failed,
    ];
    assert_eq!(cheapest_within(&runs, 0.01, &[]), Some(1));
    assert_eq!(cheapest_within(&runs, 0.005, &[]), Some(0));
    assert_eq!(cheapest_within(&runs, 0.0005, &[]), None);
    assert_eq!(runs[3].worst_max_abs(), Some(f64::INFINITY));
    assert_eq!(runs[4].worst_max_abs(), None);
}

#[test]
fn a_diverging_run_is_reported_as_failed() {
    // β = 0.1, γ = 0.5 is stable only for ωΔt ≤ 2.58; the reference's
    // 80 Hz mode (ω = 503 rad/s) breaks that from Δt = 8 ms on.
    let text = smooth_scene(2.0e-3, ", newmark: {beta: 0.1, gamma: 0.5}");
    let study = study(&text, 4, 0.01);
    let ladder = time_step_runs(&study);
    assert!(ladder[0].errors.is_ok(), "{:?}", ladder[0].errors);
    let failed: Vec<&&RunReport> = ladder.iter().filter(|r| r.errors.is_err()).collect();
    assert!(!failed.is_empty(), "the 8 and 16 ms runs should diverge");
    for run in failed {
        assert!(run.time_step >= 8e-3, "{}", run.label);
        assert!(run.wall_time.is_none() && run.steps.is_none());
        let message = run.errors.as_ref().unwrap_err();
        assert!(message.contains("diverged"), "{message}");
    }
    let csv = String::from_utf8(study.to_csv()).unwrap();
    assert!(csv.contains("diverged"), "{csv}");
}

#[test]
fn the_table_is_deterministic_apart_from_wall_times() {
    // The cheapest run is chosen by measured wall time (by design: the
    // fastest within tolerance), so under a loaded machine it may differ
    // between two runs; everything else must not.
    let strip = |mut s: Convergence| {
        s.reference.wall_time = None;
        for run in &mut s.runs {
            run.wall_time = None;
        }
        s.cheapest = None;
        for (_, cheapest) in &mut s.cheapest_per_quantity {
            *cheapest = None;
        }
        s
    };
    let text = smooth_scene(5.0e-4, "");
    let a = strip(study(&text, 3, 0.01));
    let b = strip(study(&text, 3, 0.01));
    assert_eq!(a, b);
}

#[test]
fn cli_writes_csv_and_png() {
    let dir = scratch_dir("converge", "cli");
    std::fs::write(dir.join("scene.yaml"), smooth_scene(1.0e-3, "")).unwrap();
    let out = vbi(
        &[
            "converge",
            "scene.yaml",
            "--tolerance",
            "5%",
            "--levels",
            "3",
            "--out",
            "conv",
            "--quiet",
        ],
        &dir,
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stdout}\n{stderr}");
    assert!(
        stdout.contains("dt=2.5e-4 s, 4 modes (reference)"),
        "{stdout}"
    );
    assert!(stdout.contains("median observed order"), "{stdout}");
    assert!(stdout.contains("cheapest within 5 %: "), "{stdout}");
    let csv = std::fs::read_to_string(dir.join("conv/converge.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some(
            "label,time_step [s],modes,steps,wall_time [s],quantity,max_abs_error,rms_error,failure,advice"
        )
    );
    // 3 time-step runs + 2 mode runs (2 and 1 modes), then the combined
    // ladder's runs (a coarser step with fewer modes, each half within the
    // tolerance on its own ladder), 5 quantities each.
    let rows = csv_rows(&csv);
    assert_eq!(rows.len() % 5, 0);
    let labels: Vec<&str> = rows.iter().step_by(5).map(|r| r[0].as_str()).collect();
    assert_eq!(
        labels[..5],
        [
            "dt=1e-3 s, 4 modes",
            "dt=2e-3 s, 4 modes",
            "dt=4e-3 s, 4 modes",
            "dt=1e-3 s, 2 modes",
            "dt=1e-3 s, 1 mode"
        ]
    );
    for row in rows.iter().skip(25).step_by(5) {
        let (step, modes): (f64, usize) = (row[1].parse().unwrap(), row[2].parse().unwrap());
        assert!(step > 1e-3 && modes < 4, "{row:?}");
    }
    let png = std::fs::read(dir.join("conv/converge.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn cli_rejects_a_bad_tolerance() {
    let dir = scratch_dir("converge", "bad");
    std::fs::write(dir.join("scene.yaml"), smooth_scene(1.0e-3, "")).unwrap();
    for bad in ["abc", "-1%", "0"] {
        let out = vbi(&["converge", "scene.yaml", "--tolerance", bad], &dir);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{bad}: {stderr}");
        assert!(stderr.contains("tolerance"), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    assert!(!dir.join("results").exists(), "nothing written");
    let out = vbi(&["converge", "missing.yaml"], &dir);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Each quantity is judged on its own: the per-quantity cheapest run is
/// within the tolerance on that quantity and no cheaper run is; excluding a
/// quantity leaves it out of the overall choice (which then is at least as
/// cheap), and an unknown name is refused.
#[test]
fn quantities_are_judged_on_their_own_and_can_be_left_out() {
    let loaded = load(&smooth_scene(2.5e-4, ""));
    let options = Options {
        levels: 3,
        tolerance: 0.01,
        ..Options::default()
    };
    let study = converge::converge(&loaded, &options, &mut |_, _, _| {}).unwrap();
    let names = study
        .quantities()
        .iter()
        .map(|n| n.to_string())
        .collect::<Vec<_>>();
    assert_eq!(study.cheapest_per_quantity.len(), names.len());
    for (q, (name, cheapest)) in study.cheapest_per_quantity.iter().enumerate() {
        assert_eq!(name, &names[q]);
        let error = |run: &RunReport| run.errors.as_ref().ok().map(|e| e[q].max_abs);
        if let Some(i) = cheapest {
            let chosen = &study.runs[*i];
            assert!(error(chosen).unwrap() <= 0.01);
            for run in &study.runs {
                if run.wall_time < chosen.wall_time {
                    assert!(
                        error(run).is_none_or(|e| e > 0.01),
                        "{name}: a cheaper run qualifies"
                    );
                }
            }
        }
    }
    let excluded = Options {
        exclude: vec![names[0].clone()],
        ..options.clone()
    };
    let study_without = converge::converge(&loaded, &excluded, &mut |_, _, _| {}).unwrap();
    assert_eq!(study_without.excluded, vec![names[0].clone()]);
    let unknown = Options {
        exclude: vec!["no-such-record".into()],
        ..options
    };
    let error = converge::converge(&loaded, &unknown, &mut |_, _, _| {}).unwrap_err();
    assert!(error.to_string().contains("no-such-record"), "{error}");
}

/// The records of converge.csv after its header.
fn csv_rows(text: &str) -> Vec<Vec<String>> {
    csv::Reader::from_reader(text.as_bytes())
        .records()
        .map(|r| r.unwrap().iter().map(str::to_string).collect())
        .collect()
}

/// The smooth scene in block style, as a user writes it, with keys a pasted
/// setting must replace (`time_step` inside `solver:`, `modes` inside
/// `bridge:`) and keys it must leave alone.
fn block_scene() -> String {
    "name: smooth-block
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2423e9
  mass_per_length: 2000.0
  modes: {count: 4}
  damping: {type: modal, ratio: 0.02}
vehicles:
  - type: oscillator
    sprung_mass: 4000.0
    unsprung_mass: 1000.0
    stiffness: 4.0e6
    damping: 2.53e4
    speed: 25.0
solver:
  method: coupled
  time_step: 2.5e-4
  free_vibration: 0.2
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
  - {name: sprung_acceleration, quantity: vehicle_acceleration, dof: sprung}
  - {name: contact_force, quantity: contact_force, wheel: 1}
"
    .to_string()
}

/// Pastes a block of `parent:` / `  key: value` lines into `scene`: each
/// `key` line replaces the line of the same key directly under the same
/// top-level `parent` (as a user replaces a setting in an editor).
fn paste(scene: &str, block: &str) -> String {
    let mut lines: Vec<String> = scene.lines().map(str::to_string).collect();
    let mut parent = String::new();
    for line in block.lines().filter(|l| !l.trim_start().starts_with('#')) {
        if line.trim().is_empty() {
            continue;
        }
        if !line.starts_with(' ') {
            parent = line.trim_end_matches(':').trim().to_string();
            assert!(line.trim_end().ends_with(':'), "a parent line: {line:?}");
            continue;
        }
        let key = line.trim_start().split(':').next().unwrap().to_string();
        let start = lines
            .iter()
            .position(|l| *l == format!("{parent}:"))
            .unwrap_or_else(|| panic!("no `{parent}:` in the scene"));
        let end = lines[start + 1..]
            .iter()
            .position(|l| !l.starts_with(' '))
            .map_or(lines.len(), |e| start + 1 + e);
        let at = (start + 1..end)
            .find(|&i| lines[i].trim_start().starts_with(&format!("{key}:")))
            .unwrap_or_else(|| panic!("no `{key}` under `{parent}:`"));
        lines[at] = line.to_string();
    }
    lines.join("\n") + "\n"
}

/// `vbi converge` hands over its answer: the YAML it prints (and writes to
/// `cheapest.yaml`), pasted into the scene, runs, and the run is the chosen
/// run of the study bit for bit (every recorded sample, compared by bits).
#[test]
fn printed_yaml_pasted_into_the_scene_reproduces_the_chosen_run() {
    let dir = scratch_dir("converge", "paste");
    let scene = block_scene();
    std::fs::write(dir.join("scene.yaml"), &scene).unwrap();
    let out = vbi(
        &[
            "converge",
            "scene.yaml",
            "--tolerance",
            "5%",
            "--levels",
            "3",
            "--out",
            "conv",
            "--quiet",
        ],
        &dir,
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    let block = std::fs::read_to_string(dir.join("conv/cheapest.yaml"))
        .expect("converge writes cheapest.yaml");
    let yaml: String = block
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect();
    assert!(stdout.contains(&yaml), "stdout lacks\n{yaml}\n{stdout}");
    assert!(yaml.contains("solver:\n  time_step: "), "{yaml}");
    assert!(yaml.contains("bridge:\n  modes: {count: "), "{yaml}");
    // The chosen run, named by the summary line, and its resolution from
    // converge.csv.
    let label = stdout
        .lines()
        .find_map(|l| l.strip_prefix("cheapest within 5 %: "))
        .expect("a cheapest run")
        .trim();
    let csv = std::fs::read_to_string(dir.join("conv/converge.csv")).unwrap();
    let row = csv_rows(&csv)
        .into_iter()
        .find(|r| r[0] == label)
        .unwrap_or_else(|| panic!("{label} in {csv}"));
    let resolution = converge::Resolution {
        time_step: row[1].parse().unwrap(),
        modes: row[2].parse().unwrap(),
    };
    let pasted = paste(&scene, &block);
    std::fs::write(dir.join("pasted.yaml"), &pasted).unwrap();
    let run = vbi(&["run", "pasted.yaml", "--out", "run", "--quiet"], &dir);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let chosen = converge::at_resolution(&load(&scene), resolution).unwrap();
    let expected = vbi::run::simulate(chosen, &mut |_, _| {}).unwrap().history;
    let got = vbi::run::simulate(load(&pasted), &mut |_, _| {})
        .unwrap()
        .history;
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&got.time), bits(&expected.time), "{pasted}");
    assert_eq!(got.columns.len(), expected.columns.len());
    for (g, e) in got.columns.iter().zip(&expected.columns) {
        assert_eq!(g.name, e.name);
        assert!(bits(&g.values) == bits(&e.values), "{} differs", g.name);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
