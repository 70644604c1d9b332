//! The `monte_carlo` study (the LCP separation paper, Section 5.2): the
//! results do not depend on the thread count; sample k run alone is sample k
//! of the study, bit for bit; the envelopes equal a two-pass mean and
//! standard deviation of the samples; the separation probability is exact
//! where the answer is known (0 under a tiny roughness at walking pace, 1
//! far beyond the threshold); a scene with nothing random is refused with
//! its location and exit code 2.

use crate::support;

use support::vbi_here as vbi;
use support::{Scratch, on_threads};
use vbi::execute::{Results, execute};
use vbi::plan::Loaded;
use vbi::plan::load_str;
use vbi::run::simulate;
use vbi::scenario::resolved::Study;
use vbi::study::monte_carlo::{self, MonteCarloResults};

/// The 2-DOF oscillator with elastic contact on a 20 m beam, over a random
/// surface of coefficient `coefficient` (m³/cycle), at `speed` (m/s), with
/// the study line `study`.
fn scene(coefficient: f64, speed: f64, study: &str) -> String {
    format!(
        "name: mc
bridge: {{type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, elements_per_span: 10, modes: {{count: 4}}, damping: {{type: modal, ratio: 0.02}}}}
vehicles:
  - {{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: {speed}}}
contact: {{type: elastic, stiffness: 4.0e8}}
surface: {{type: random, coefficient: {coefficient:e}, sampling_length: 40.0, terms: 80, seed: 3}}
solver: {{method: lcp, time_step: 1.0e-3, free_vibration: 0.05}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 10.0}}
  - {{name: force, quantity: contact_force, wheel: 1}}
study: {study}
"
    )
}

fn load(text: &str) -> Loaded {
    load_str(text, "mc.yaml").unwrap_or_else(|e| panic!("{e}"))
}

fn study(loaded: Loaded, threads: Option<usize>) -> MonteCarloResults {
    on_threads(threads, || match execute(loaded, &|_, _| {}) {
        Ok(Results::MonteCarlo(mc)) => mc,
        Ok(_) => panic!("expected a Monte Carlo study"),
        Err(e) => panic!("{e}"),
    })
}

/// Sample `k` (from 0) of the study's first case, run alone through
/// `simulate`.
fn run_alone(
    loaded: &Loaded,
    mc: &vbi::scenario::resolved::MonteCarlo,
    k: usize,
) -> vbi::run::Outcome {
    let case = monte_carlo::cases(mc)[0];
    let scenario = monte_carlo::sample_scenario(&loaded.scenario, &loaded.bridge, mc, case, k);
    simulate(
        Loaded {
            scenario,
            bridge: loaded.bridge.clone(),
        },
        &mut |_, _| {},
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

const STUDY: &str = "{type: monte_carlo, samples: 9, seed: 11, show: 9}";

#[test]
fn one_and_two_threads_give_the_same_bytes() {
    let text = scene(256e-6, 30.0, STUDY);
    let one = study(load(&text), Some(1));
    let two = study(load(&text), Some(2));
    assert_eq!(one.samples_csv(), two.samples_csv());
    assert_eq!(one.separation_csv(), two.separation_csv());
    assert_eq!(one.envelopes_csv(), two.envelopes_csv());
    // The case is not trivial: some samples separate, some gaps differ.
    let stats = one.wheel_statistics(0);
    assert!(stats[0].expected_max_gap > 0.0, "{stats:?}");
}

#[test]
fn a_sample_run_alone_is_that_sample_of_the_study() {
    let text = scene(256e-6, 30.0, STUDY);
    let loaded = load(&text);
    let Some(Study::MonteCarlo(mc)) = loaded.scenario.study.clone() else {
        panic!("a Monte Carlo study")
    };
    let results = study(loaded.clone(), None);
    let case = monte_carlo::cases(&mc)[0];
    for k in [0, 4, 8] {
        let scenario = monte_carlo::sample_scenario(&loaded.scenario, &loaded.bridge, &mc, case, k);
        let seed = match scenario.surface {
            vbi::scenario::resolved::Surface::Random { seed, .. } => seed,
            _ => panic!("a random surface"),
        };
        assert_eq!(seed, monte_carlo::sample_seed(11, k));
        let alone = run_alone(&loaded, &mc, k);
        let in_study = &results.sample_results[k];
        assert_eq!(in_study.sample, k + 1);
        assert_eq!(in_study.seed, seed);
        let histories = in_study
            .histories
            .as_ref()
            .expect("shown samples keep histories");
        for (column, values) in alone.history.columns.iter().zip(histories) {
            let a: Vec<u64> = column.values.iter().map(|v| v.to_bits()).collect();
            let b: Vec<u64> = values.iter().map(|v| v.to_bits()).collect();
            assert_eq!(a, b, "sample {} column {}", k + 1, column.name);
        }
        let sep = &alone.history.separation[0];
        assert_eq!(in_study.wheels[0].separated, sep.separated);
        assert_eq!(in_study.wheels[0].max_gap.to_bits(), sep.max_gap.to_bits());
    }
}

#[test]
fn envelopes_equal_a_two_pass_mean_and_deviation_of_the_samples() {
    // Independent reference: the textbook two-pass mean and (n − 1)
    // standard deviation of the 9 kept histories, against the tree of
    // pairwise (Chan) updates; agreement to round-off (1e-12 of the
    // column's peak).
    let results = study(load(&scene(256e-6, 30.0, STUDY)), None);
    let m = &results.envelopes[0];
    let std = m.std_dev();
    let histories: Vec<&Vec<Vec<f64>>> = results
        .sample_results
        .iter()
        .map(|r| r.histories.as_ref().unwrap())
        .collect();
    let n = histories.len() as f64;
    assert_eq!(m.count, 9);
    for r in 0..m.names.len() {
        let peak = m.mean[r].iter().fold(0.0f64, |a, v| a.max(v.abs()));
        for i in 0..m.time.len() {
            let mean = histories.iter().map(|h| h[r][i]).sum::<f64>() / n;
            let var = histories
                .iter()
                .map(|h| (h[r][i] - mean).powi(2))
                .sum::<f64>()
                / (n - 1.0);
            assert!((m.mean[r][i] - mean).abs() <= 1e-12 * peak);
            assert!((std[r][i] - var.sqrt()).abs() <= 1e-9 * peak.max(1e-30));
        }
    }
}

#[test]
fn separation_probability_is_exact_where_the_answer_is_known() {
    // A roughness of A_r = 1e-12 m³/cycle (amplitudes of micrometres) at
    // 2 m/s: the static wheel load (5000 kg × g = 49 kN) is never lifted, so
    // no sample separates: probability exactly 0, Wilson upper end
    // z²/(n + z²).
    let calm = study(
        load(&scene(
            1e-12,
            2.0,
            "{type: monte_carlo, samples: 12, seed: 5}",
        )),
        None,
    );
    let w = &calm.wheel_statistics(0)[0];
    assert_eq!(w.separated, 0);
    assert_eq!(w.probability, 0.0);
    assert_eq!(w.expected_max_gap, 0.0);
    let z2 = vbi::study::statistics::Z95.powi(2);
    assert!((w.probability_high - z2 / (12.0 + z2)).abs() < 1e-15);
    // No gap opened: the samples do not bound the expected gap from above.
    assert_eq!(
        (w.expected_max_gap_low, w.expected_max_gap_high),
        (0.0, None)
    );
    // A very poor road (A_r = 1024e-6 m³/cycle) at 40 m/s with a stiff
    // contact: every sample lifts the wheel.
    let rough = study(
        load(&scene(
            1024e-6,
            40.0,
            "{type: monte_carlo, samples: 12, seed: 5}",
        )),
        None,
    );
    let w = &rough.wheel_statistics(0)[0];
    assert_eq!(w.separated, 12);
    assert_eq!(w.probability, 1.0);
    assert!(w.expected_max_gap > 0.0);
    // Every sample separated: the interval of the expected gap is
    // positive, around the mean.
    let high = w.expected_max_gap_high.expect("the samples bound the mean");
    assert!(0.0 < w.expected_max_gap_low && w.expected_max_gap_low < w.expected_max_gap);
    assert!(w.expected_max_gap < high);
}

/// Issue 40.5, honest intervals: a 16-sample study through `vbi run`, at a
/// speed where no sample separates and one where some do. The console gives
/// the highest probability with its interval and count; separation.csv and
/// summary.json give 0 of 16 as 0 with the Wilson interval [0, 0.194], not a
/// bare 0, and the expected largest gap an interval that never goes below 0
/// (the normal interval mean ∓ 1.96 SE went to −1.34e-5 m) and, where no
/// sample separated, no upper end; both plots are drawn.
#[test]
fn a_16_sample_study_reports_honest_intervals() {
    let scratch = Scratch::new("monte_carlo", "honest-intervals");
    let path = scratch.path("mc.yaml");
    let study =
        "{type: monte_carlo, samples: 16, seed: 11, show: 2, speeds: {from: 2, to: 30, count: 2}}";
    std::fs::write(&path, scene(256e-6, 30.0, study)).unwrap();
    let out_dir = scratch.path("out");
    let out = vbi(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let console = stderr
        .lines()
        .find(|l| l.contains("highest probability of separation"))
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!(
        console.contains("95 % interval") && console.contains(" of 16 samples"),
        "{console}"
    );

    let z2 = vbi::study::statistics::Z95.powi(2);
    let csv = std::fs::read_to_string(out_dir.join("separation.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name} in {header:?}"))
    };
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2, "{csv}");
    let (calm, fast) = (&rows[0], &rows[1]);
    assert_eq!(calm[column("samples")], "16");
    assert_eq!(calm[column("separated")], "0");
    let high: f64 = calm[column("probability_high")].parse().unwrap();
    assert!(
        (high - z2 / (16.0 + z2)).abs() < 1e-12 && (high - 0.1936).abs() < 1e-4,
        "{high}"
    );
    assert_eq!(calm[column("expected_max_gap_low [m]")], "0");
    assert_eq!(
        calm[column("expected_max_gap_high [m]")],
        "",
        "no sample separated: unbounded"
    );
    let separated: usize = fast[column("separated")].parse().unwrap();
    assert!(separated > 0, "{csv}");
    let mean: f64 = fast[column("expected_max_gap [m]")].parse().unwrap();
    let low: f64 = fast[column("expected_max_gap_low [m]")].parse().unwrap();
    let high: f64 = fast[column("expected_max_gap_high [m]")].parse().unwrap();
    assert!(
        0.0 < low && low < mean && mean < high,
        "{low} {mean} {high}"
    );

    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out_dir.join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(summary["samples"], 16);
    assert!(summary["intervals"].as_str().unwrap().contains("Wilson"));
    let calm = &summary["cases"][0]["wheels"][0];
    assert_eq!(calm["probability"], 0.0);
    assert!(calm["probability_high"].as_f64().unwrap() > 0.19);
    assert!(calm["expected_max_gap_high"].is_null(), "{calm}");
    let fast = &summary["cases"][1]["wheels"][0];
    assert!(
        fast["expected_max_gap_low"].as_f64().unwrap() > 0.0,
        "{fast}"
    );
    for png in ["separation_probability.png", "expected_gap.png"] {
        assert!(out_dir.join(png).is_file(), "{png}");
    }
}

#[test]
fn speeds_and_classes_make_cases_in_order() {
    let text = scene(
        16e-6,
        20.0,
        "{type: monte_carlo, samples: 3, speeds: {from: 10, to: 30, count: 3}, roughness: [good, poor]}",
    );
    let results = study(load(&text), None);
    assert_eq!(results.cases.len(), 6);
    assert_eq!(
        results.labels,
        ["good", "good", "good", "poor", "poor", "poor"]
    );
    let speeds: Vec<f64> = (0..6).map(|c| results.speed(c).unwrap()).collect();
    assert_eq!(speeds, [10.0, 20.0, 30.0, 10.0, 20.0, 30.0]);
    // The same k-th seed on every case (common random numbers).
    for c in 0..6 {
        for k in 0..3 {
            assert_eq!(
                results.sample_results[c * 3 + k].seed,
                monte_carlo::sample_seed(1, k)
            );
        }
    }
    // A rougher class separates at least as much at each speed here.
    for s in 0..3 {
        let good = results.wheel_statistics(s)[0].expected_max_gap;
        let poor = results.wheel_statistics(3 + s)[0].expected_max_gap;
        assert!(poor >= good, "speed {s}: {poor} < {good}");
    }
}

#[test]
fn a_scene_without_a_random_surface_is_refused_with_its_location() {
    let scratch = Scratch::new("monte_carlo", "refused");
    let smooth = scene(16e-6, 20.0, "{type: monte_carlo, samples: 3}").replace(
        "surface: {type: random, coefficient: 1.6e-5, sampling_length: 40.0, terms: 80, seed: 3}",
        "surface: {type: smooth}",
    );
    assert!(smooth.contains("type: smooth"));
    let path = scratch.path("smooth.yaml");
    std::fs::write(&path, &smooth).unwrap();
    let out = vbi(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        scratch.path("out").to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("smooth.yaml:11:"), "{stderr}");
    assert!(stderr.contains("not random"), "{stderr}");
    assert!(!scratch.path("out").exists());
    // `smooth` in a roughness list is refused at its entry.
    let listed = scene(
        16e-6,
        20.0,
        "{type: monte_carlo, samples: 3, roughness: [good, smooth]}",
    );
    let err = load_str(&listed, "listed.yaml").unwrap_err().to_string();
    assert!(
        err.contains("listed.yaml:11:") && err.contains("`smooth` is not random"),
        "{err}"
    );
}

#[test]
fn sample_flag_runs_one_sample_as_a_scene() {
    let scratch = Scratch::new("monte_carlo", "sample-flag");
    let path = scratch.path("mc.yaml");
    std::fs::write(&path, scene(256e-6, 30.0, STUDY)).unwrap();
    let out_dir = scratch.path("s5");
    let out = vbi(&[
        "run",
        path.to_str().unwrap(),
        "--sample",
        "5",
        "-q",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let resolved = std::fs::read_to_string(out_dir.join("resolved.yaml")).unwrap();
    let seed = monte_carlo::sample_seed(11, 4);
    assert!(resolved.contains(&format!("seed: {seed}")), "{resolved}");
    // No study left (the header line naming the scene file, whose folder
    // here is named after this test binary, aside).
    assert!(
        !resolved
            .lines()
            .filter(|l| !l.starts_with(vbi::run::FROM))
            .any(|l| l.contains("monte_carlo"))
    );
    let out = vbi(&["run", path.to_str().unwrap(), "--sample", "10", "-q"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("9 samples"));
}

/// A vehicle placed before a track's run-in (`start_position: -40`) stays
/// there at every swept speed: a speed case scales its entry time. (It used
/// to keep the entry time of the scene's own speed, so at a third of it the
/// rail car started 13 m from the entrance, inside the faded-in track, and
/// every front wheelset "separated" by 5 cm at 100 km/h.)
#[test]
fn swept_speeds_keep_the_start_position() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios/lcp-fig9-rail-car-fra.yaml");
    let loaded = vbi::plan::load_file(&path).expect("shipped scene loads");
    let Some(vbi::scenario::resolved::Study::MonteCarlo(mc)) = &loaded.scenario.study else {
        panic!("a Monte Carlo study");
    };
    let cases = vbi::study::monte_carlo::cases(mc);
    assert_eq!(cases.len(), 9);
    for case in cases {
        let scene =
            vbi::study::monte_carlo::sample_scenario(&loaded.scenario, &loaded.bridge, mc, case, 0);
        let vehicle = &scene.vehicles[0];
        let start = -vehicle.speed() * vehicle.entry_time();
        assert!(
            (start + 40.0).abs() < 1e-9,
            "{:?}: the car starts at {start} m, not -40 m",
            case.speed
        );
    }
}

/// Every sample of a study stepped in lockstep batches
/// (`vbi::solve::lockstep`, 8 samples per batch) equals the same sample
/// run alone through the `lcp` solver, bit for bit: every recorded history
/// (bridge displacement with its static correction, a vehicle
/// acceleration, contact forces and gaps) and the per-wheel separation.
/// Two vehicles cover both product orders of the vehicle matrices: the
/// 10-DOF rail car (one block: nalgebra's order) over FRA class 5 at
/// 300 km/h, where every sample separates, so the lanes' contact sets
/// differ step by step; and a two-car train (two blocks) under HHT
/// α = −0.1, which adds the α terms. 11 samples: batches of 5 and 6 (the
/// reduction tree's nodes), so some lanes are idle.
#[test]
fn lockstep_batches_equal_each_sample_run_alone() {
    let rail_car = "name: lockstep-rail-car
bridge: {type: beam, spans: [32.0], bending_stiffness: 1.3448174e10, mass_per_length: 12000.0, elements_per_span: 20, damping: {type: modal, ratio: 0.02}, modes: {count: 12}}
vehicles: [{type: rail_car, speed: 300 km/h, start_position: -10.0}]
surface: {type: fra, class: 5, run_in: 10.0}
contact: {type: elastic, stiffness: 1.0e9}
solver: {free_vibration: 0.05, time_step: 2.0e-4, newmark: {beta: 0.08333333333333333}}
record:
  - {name: midspan, quantity: bridge_displacement, x: 16.0}
  - {name: body, quantity: vehicle_acceleration, dof: body_bounce}
  - {name: force4, quantity: contact_force, wheel: 4}
  - {name: gap1, quantity: contact_gap, wheel: 1}
study: {type: monte_carlo, samples: 11, seed: 5, show: 11}
";
    let train = "name: lockstep-train
bridge: {type: beam, spans: [32.0], bending_stiffness: 1.3448174e10, mass_per_length: 12000.0, elements_per_span: 20, damping: {type: modal, ratio: 0.02}, modes: {count: 10}}
vehicles: [{type: train, count: 2, car_spacing: 25.0, speed: 250 km/h, start_position: -5.0}]
surface: {type: fra, class: 4, run_in: 5.0}
contact: {type: elastic, stiffness: 1.0e9}
solver: {method: lcp, free_vibration: 0.02, time_step: 2.0e-4, newmark: {alpha: -0.1}}
record:
  - {name: midspan, quantity: bridge_displacement, x: 16.0}
  - {name: body2, quantity: vehicle_acceleration, vehicle: 1, dof: car2_body_bounce}
  - {name: force8, quantity: contact_force, wheel: 8}
study: {type: monte_carlo, samples: 11, seed: 9, show: 11}
";
    for text in [rail_car, train] {
        let loaded = load(text);
        let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge.clone())
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(
            vbi::solve::lockstep::eligible(&model),
            "{}",
            loaded.scenario.name
        );
        let Some(Study::MonteCarlo(mc)) = loaded.scenario.study.clone() else {
            panic!("a Monte Carlo study")
        };
        let results = study(loaded.clone(), None);
        let mut separated = 0;
        for k in 0..11 {
            let alone = run_alone(&loaded, &mc, k);
            let in_study = &results.sample_results[k];
            let histories = in_study.histories.as_ref().expect("every sample shown");
            assert_eq!(alone.history.columns.len(), histories.len());
            for (column, values) in alone.history.columns.iter().zip(histories) {
                let a: Vec<u64> = column.values.iter().map(|v| v.to_bits()).collect();
                let b: Vec<u64> = values.iter().map(|v| v.to_bits()).collect();
                assert_eq!(a, b, "{}: sample {} column {}", mc.seed, k + 1, column.name);
            }
            for (w, sep) in in_study.wheels.iter().zip(&alone.history.separation) {
                assert_eq!(w.separated, sep.separated);
                assert_eq!(w.max_gap.to_bits(), sep.max_gap.to_bits());
                separated += usize::from(sep.separated);
            }
        }
        if text == rail_car {
            // The lanes do part: contact sets differ between samples.
            assert!(separated > 0, "some wheel of some sample separates");
        }
    }
}

/// Full and partly filled lockstep batches ([`vbi::solve::lockstep::LANES`]
/// = 16 lanes) equal each sample run alone, bit for bit: 16 samples fill
/// one batch (every lane busy; every history compared), 31 split 15 + 16
/// (the histories of the first 20, which a study shows at most, and every
/// sample's per-wheel separation and largest gap, the full batch's last
/// lane, sample 31, included).
/// (An off-by-one planted in the lanes, lane 15 reading lane 14's surface,
/// passed the 11-sample test above, whose batches never reach lane 15.)
#[test]
fn full_and_partly_filled_lockstep_batches_equal_samples_run_alone() {
    assert_eq!(
        vbi::solve::lockstep::LANES,
        16,
        "the sample counts below fill 16 lanes"
    );
    let scene = |samples: usize| {
        format!(
            "name: lockstep-full
bridge: {{type: beam, spans: [32.0], bending_stiffness: 1.3448174e10, mass_per_length: 12000.0, elements_per_span: 20, damping: {{type: modal, ratio: 0.02}}, modes: {{count: 8}}}}
vehicles: [{{type: rail_car, speed: 300 km/h, start_position: -10.0}}]
surface: {{type: fra, class: 5, run_in: 10.0}}
contact: {{type: elastic, stiffness: 1.0e9}}
solver: {{free_vibration: 0.02, time_step: 4.0e-4}}
record:
  - {{name: midspan, quantity: bridge_displacement, x: 16.0}}
  - {{name: force8, quantity: contact_force, wheel: 4}}
study: {{type: monte_carlo, samples: {samples}, seed: 3, show: {}}}
",
            samples.min(20)
        )
    };
    for samples in [16, 31] {
        let loaded = load(&scene(samples));
        let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge.clone())
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(vbi::solve::lockstep::eligible(&model), "steps in lockstep");
        let Some(Study::MonteCarlo(mc)) = loaded.scenario.study.clone() else {
            panic!("a Monte Carlo study")
        };
        let results = study(loaded.clone(), None);
        let mut separated = 0;
        for k in 0..samples {
            let alone = run_alone(&loaded, &mc, k);
            let in_study = &results.sample_results[k];
            // Histories of the first 20 (at most `show`), every sample's
            // per-wheel separation (the last lane of the 31's full batch
            // is sample 31).
            if let Some(histories) = &in_study.histories {
                for (column, values) in alone.history.columns.iter().zip(histories) {
                    let a: Vec<u64> = column.values.iter().map(|v| v.to_bits()).collect();
                    let b: Vec<u64> = values.iter().map(|v| v.to_bits()).collect();
                    assert_eq!(
                        a,
                        b,
                        "{samples} samples: sample {} column {}",
                        k + 1,
                        column.name
                    );
                }
            } else {
                assert!(k >= 20, "sample {} shown", k + 1);
            }
            assert_eq!(in_study.wheels.len(), alone.history.separation.len());
            for (w, sep) in in_study.wheels.iter().zip(&alone.history.separation) {
                assert_eq!(
                    w.separated,
                    sep.separated,
                    "{samples} samples: sample {}",
                    k + 1
                );
                assert_eq!(
                    w.max_gap.to_bits(),
                    sep.max_gap.to_bits(),
                    "{samples} samples: sample {} max gap",
                    k + 1
                );
                separated += usize::from(sep.separated && k + 1 == samples);
            }
        }
        assert!(
            separated > 0,
            "the last sample's wheels separate (its gaps are compared)"
        );
    }
}

/// A sample that fails stops the study with its number, its case and how
/// to run it alone: here every sample diverges (Fox–Goodwin β = 1/12
/// beyond its stability limit, ωΔt = 4.4 > √6 for the 34th mode), and the
/// study reports the first to do so, in a lockstep batch, as the run of
/// that sample alone reports it.
#[test]
fn a_failing_sample_is_named_with_its_case_and_rerun() {
    let text = "name: diverging
bridge: {type: beam, spans: [32.0], bending_stiffness: 1.3448174e10, mass_per_length: 12000.0, elements_per_span: 20, damping: {type: modal, ratio: 0.02}, modes: {count: 34}}
vehicles: [{type: rail_car, speed: 300 km/h, start_position: -10.0}]
surface: {type: fra, class: 5, run_in: 10.0}
contact: {type: elastic, stiffness: 1.0e9}
solver: {free_vibration: 0.05, time_step: 2.763e-4, newmark: {beta: 0.08333333333333333}}
record:
  - {name: midspan, quantity: bridge_displacement, x: 16.0}
study: {type: monte_carlo, samples: 3, seed: 5}
";
    let loaded = load(text);
    let Some(Study::MonteCarlo(mc)) = loaded.scenario.study.clone() else {
        panic!("a Monte Carlo study")
    };
    let error = match execute(loaded.clone(), &|_, _| {}) {
        Err(e) => e,
        Ok(_) => panic!("the study should fail"),
    };
    let message = error.to_string();
    let vbi::run::RunError::Sample { sample, source, .. } = error else {
        panic!("expected a failed sample, got {message}")
    };
    assert!((1..=3).contains(&sample), "{message}");
    assert!(
        message.contains(&format!("sample {sample} of case fra5"))
            && message.contains(&format!("--sample {sample}"))
            && message.contains("diverged"),
        "{message}"
    );
    // The sample run alone fails the same way.
    let alone = simulate(
        Loaded {
            scenario: monte_carlo::sample_scenario(
                &loaded.scenario,
                &loaded.bridge,
                &mc,
                monte_carlo::cases(&mc)[0],
                sample - 1,
            ),
            bridge: loaded.bridge.clone(),
        },
        &mut |_, _| {},
    );
    match alone {
        Err(e) => assert_eq!(e.to_string(), source.to_string()),
        Ok(_) => panic!("sample {sample} alone should diverge"),
    }
}
