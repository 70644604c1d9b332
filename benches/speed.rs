//! Speed benchmarks, printed as Markdown tables (see BENCHMARKS.md).
//!
//! ```sh
//! cargo bench --bench speed              # every section
//! cargo bench --bench speed -- step map  # only the sections whose name contains a word
//! ```
//!
//! Sections: `step` (per-step cost of the coupled and LCP solvers on the same
//! scene), `foundation` (the foundation scene end to end through the library)
//! `map` (40 × 40 separation maps, all threads and one thread) and `plate`
//! (the plate paper's orthotropic deck, 45 modes, one H20-44 truck, one crossing)
//! and `monte_carlo` (1000 random-surface samples of the Fig. 7-like oscillator
//! scene: per-sample against single-crossing cost, threads, shards + merge).
//!
//! Every case is run once to warm up, then repeated N times with N chosen from
//! the warm-up so that the case takes at least about `VBI_BENCH_SECONDS`
//! (default 1 s) and at least 3 repetitions; median and minimum are reported.

use std::path::{Path, PathBuf};
use std::time::Instant;

use vbi::execute::Results;
use vbi::plan::Loaded;
use vbi::run::Outcome;
use vbi::study::separation_map::SeparationMap;

fn main() {
    let filters: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let wanted = |section: &str| filters.is_empty() || filters.iter().any(|f| section.contains(f));
    let budget: f64 = std::env::var("VBI_BENCH_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);

    println!(
        "vbi {} speed benchmark; {} rayon threads by default; target ≥ {budget} s per case\n",
        env!("CARGO_PKG_VERSION"),
        rayon::current_num_threads(),
    );
    if wanted("step") {
        per_step(budget);
    }
    if wanted("foundation") {
        foundation(budget);
    }
    if wanted("map") {
        separation_maps(budget);
    }
    if wanted("plate") {
        plate(budget);
    }
    if wanted("eigen") {
        eigen(budget);
    }
    if wanted("monte_carlo") {
        monte_carlo(budget);
    }
    if wanted("train") {
        train(budget);
    }
}

/// 1000 samples of the Fig. 7-like scene (scenarios/lcp-fig7-monte-carlo.yaml:
/// the 2-DOF oscillator with elastic LCP contact at 300 km/h on the 32 m
/// beam over random surface samples), then the issue's target: 1000 samples
/// of the 10-DOF rail car over the 32 m beam at 300 km/h on FRA class 5
/// with elastic LCP contact (scenarios/lcp-fig9-rail-car-fra.yaml reduced to
/// that one case; Fox–Goodwin Newmark, β = 1/12, 17 modes, Δt = 2.072e-4 s,
/// whose accuracy is measured in BENCHMARKS.md). Each: one crossing, the
/// whole study on all threads and on one, the sample scenes one by one
/// (no lockstep batches), and the study in 4 shards (run one after another
/// here, each writing its part file) merged.
fn monte_carlo(budget: f64) {
    let oscillator =
        read_scenario("lcp-fig7-monte-carlo.yaml").replace("samples: 20", "samples: 1000");
    monte_carlo_of(budget, "the Fig. 7-like oscillator scene", &oscillator);
    let rail_car = read_scenario("lcp-fig9-rail-car-fra.yaml")
        .lines()
        .filter(|l| !l.contains("speeds:") && !l.contains("roughness:"))
        .map(|l| format!("{l}\n"))
        .collect::<String>()
        .replace("samples: 4", "samples: 1000")
        .replace(
            "solver: {free_vibration: 0.1}",
            "solver: {free_vibration: 0.1, time_step: 2.072e-4, newmark: {beta: 0.08333333333333333}}",
        )
        .replace(
            "  damping: {type: modal, ratio: 0.02}",
            "  damping: {type: modal, ratio: 0.02}\n  modes: {count: 17}",
        );
    monte_carlo_of(
        budget,
        "the rail car on FRA class 5 (the issue's target)",
        &rail_car,
    );
}

/// The Monte Carlo rows of one scene `text` with a 1000-sample study.
fn monte_carlo_of(budget: f64, label: &str, text: &str) {
    use vbi::study::shard::{self, Shard};
    println!("## Monte Carlo: 1000 samples of {label}\n");
    let loaded = load(text, "mc");
    let mut single = loaded.clone();
    single.scenario.study = None;
    let steps = simulate(&single).model.steps;
    let (one, _) = median_min(sample(budget, || {
        let start = Instant::now();
        simulate(&single);
        start.elapsed().as_secs_f64()
    }));
    // The same 1000 sample scenes one by one through `simulate`, without the
    // study's reduction: separates the physics of the samples (each surface
    // differs) from the study's own overhead.
    let Some(vbi::scenario::resolved::Study::MonteCarlo(mc)) = loaded.scenario.study.clone() else {
        panic!("a Monte Carlo study")
    };
    let case = vbi::study::monte_carlo::cases(&mc)[0];
    let scenes: Vec<Loaded> = (0..1000)
        .map(|k| Loaded {
            scenario: vbi::study::monte_carlo::sample_scenario(
                &loaded.scenario,
                &loaded.bridge,
                &mc,
                case,
                k,
            ),
            bridge: loaded.bridge.clone(),
        })
        .collect();
    let (one_by_one, _) = median_min(sample(budget, || {
        let start = Instant::now();
        for scene in &scenes {
            simulate(scene);
        }
        start.elapsed().as_secs_f64()
    }));
    let study = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        let times = sample(budget, || {
            let start = Instant::now();
            match pool.install(|| vbi::execute::execute(loaded.clone(), &|_, _| {})) {
                Ok(Results::MonteCarlo(_)) => {}
                _ => panic!("a Monte Carlo study"),
            }
            start.elapsed().as_secs_f64()
        });
        median_min(times).0
    };
    let threads = rayon::current_num_threads();
    let all = study(threads);
    let serial = study(1);
    let dir = std::env::temp_dir().join(format!("vbi-bench-mc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch folder");
    let (sharded, _) = median_min(sample(budget, || {
        let start = Instant::now();
        let mut parts = Vec::new();
        for k in 1..=4 {
            let shard = Shard { index: k, count: 4 };
            let part = shard::run_shard(
                &loaded,
                "mc.yaml",
                text,
                &Default::default(),
                shard,
                &|_, _| {},
            )
            .expect("shard");
            let path = dir.join(shard.file_name());
            std::fs::write(&path, shard::part_json(&part)).expect("part written");
            parts.push(path);
        }
        shard::merge(&parts, &Default::default()).expect("merge");
        start.elapsed().as_secs_f64()
    }));
    let _ = std::fs::remove_dir_all(&dir);
    println!("| case | wall (median) | per sample |");
    println!("|---|---|---|");
    println!("| one crossing ({steps} steps) | {:.2} ms | |", 1e3 * one);
    println!(
        "| 1000 samples, {threads} threads | {:.3} s | {:.3} ms |",
        all, all
    );
    println!(
        "| 1000 samples, 1 thread | {:.3} s | {:.3} ms ({:.2}× one crossing) |",
        serial,
        serial,
        serial / 1000.0 / one
    );
    println!(
        "| the 1000 sample scenes one by one (`simulate`), 1 thread | {:.3} s | {:.3} ms ({:.2}× one crossing) |",
        one_by_one,
        one_by_one,
        one_by_one / 1000.0 / one
    );
    println!(
        "| 1000 samples as 4 shards + merge, {threads} threads | {:.3} s | {:.3} ms ({:+.1} % against unsharded) |",
        sharded,
        sharded,
        100.0 * (sharded / all - 1.0)
    );
    println!();
}

/// An 8-car train (32 wheelsets, the LCP paper's Table 2 cars 25 m apart)
/// at 300 km/h over the 32 m beam of `lcp-rail-car-elastic.yaml`, elastic
/// LCP contact: the cost of a step against the cost of its contact problem,
/// a 32 × 32 LCP with every wheel in contact, solved once from the last
/// step's contact set (`solve_warm`, one Gaussian elimination, n³/3 ≈ 11k
/// multiply-adds, plus an O(n²) check) and once by Lemke from scratch
/// (n + 1 pivots of n(2n + 2) multiply-adds ≈ 70k, plus the cleanup).
fn train(budget: f64) {
    use vbi::solve::lcp::{LcpWorkspace, solve, solve_warm};
    println!("## 8-car train, elastic LCP: step against contact problem\n");
    let scene = read_scenario("lcp-rail-car-elastic.yaml").replace(
        "  - type: rail_car\n    speed: 300 km/h",
        "  - type: train\n    speed: 300 km/h\n    count: 8\n    car_spacing: 25.0",
    );
    let scene: String = scene
        .lines()
        .take_while(|l| !l.starts_with("record:"))
        .map(|l| format!("{l}\n"))
        .collect::<String>()
        + "record:\n  - {name: midspan, quantity: bridge_displacement, x: 16.0}\n";
    let loaded = load(&scene, "train8");
    let steps = simulate(&loaded).summary.run.steps;
    let per_step = sample(budget, || {
        let out = simulate(&loaded);
        out.summary.run.wall_time / out.summary.run.steps as f64 * 1e9
    });
    // A contact problem of the same size and shape: wheelset compliance
    // 1e-9 m/N on the diagonal (the 1e9 N/m contact spring), coupled by a
    // smaller symmetric positive definite part (the deck and the car), every
    // wheel pressed (q < 0).
    let n = 32;
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let d = (i as f64 - j as f64).abs();
            m[i * n + j] = 2e-10 * (-d / 4.0).exp();
        }
        m[i * n + i] += 1e-9;
    }
    let q: Vec<f64> = (0..n)
        .map(|i| -1e-4 * (1.0 + 0.1 * (i % 4) as f64))
        .collect();
    let mut z = vec![0.0; n];
    let mut work = LcpWorkspace::new(n);
    let reps = 2000;
    let lemke = sample(budget, || {
        let start = Instant::now();
        for _ in 0..reps {
            solve(&m, &q, &mut z, &mut work).expect("solves");
        }
        start.elapsed().as_secs_f64() / reps as f64 * 1e9
    });
    let previous = z.clone();
    let warm = sample(budget, || {
        let start = Instant::now();
        for _ in 0..reps {
            let pivots = solve_warm(&m, &q, &mut z, &mut work, &previous).expect("solves");
            assert_eq!(pivots, 0);
        }
        start.elapsed().as_secs_f64() / reps as f64 * 1e9
    });
    let (step_med, step_min) = median_min(per_step);
    let (lemke_med, lemke_min) = median_min(lemke);
    let (warm_med, warm_min) = median_min(warm);
    println!("| case | median ns | min ns | step / case (min / min) |");
    println!("|---|---:|---:|---:|");
    println!("| step of the train ({steps} steps) | {step_med:.0} | {step_min:.0} | 1 |");
    println!(
        "| 32 × 32 LCP, warm start (accepted) | {warm_med:.0} | {warm_min:.0} | {:.2}× |",
        step_min / warm_min
    );
    println!(
        "| 32 × 32 LCP, Lemke from scratch | {lemke_med:.0} | {lemke_min:.0} | {:.2}× |",
        step_min / lemke_min
    );
    println!();
}

/// The checked eigen path on large beams: the lowest 100 modes of a 30-span
/// viaduct (30 m spans) at 200 and 350 elements per span (11,971 and 20,971
/// DOFs), then the static influence lines of every span middle and quarter
/// point (90 lines, one sparse factorisation), and the same crossing's
/// per-step cost with and without the static correction of recorded
/// displacements.
fn eigen(budget: f64) {
    use vbi::bridge::{ModalBridge, ModeRequest};
    use vbi::scenario::resolved::{Beam, Bridge, Damping, Modes};
    println!("## Eigen path: lowest 100 modes of a 30-span beam\n");
    println!(
        "| elements per span | DOFs | modes (median) | 90 influence lines | residual (max) | |ΦᵀMΦ − I| (max) |"
    );
    println!("|---|---|---|---|---|---|");
    for elements in [200usize, 350] {
        let bridge = Bridge::Beam(Beam {
            spans: vec![30.0; 30],
            bending_stiffness: 8.323e9,
            mass_per_length: 2303.0,
            elements_per_span: vec![elements; 30],
            modes: Modes {
                count: None,
                max_frequency: None,
                static_correction: true,
            },
            damping: Damping::Modal { ratio: 0.0 },
            sway: None,
        });
        let mut last = None;
        let times = sample(budget, || {
            let start = Instant::now();
            let modal = ModalBridge::build_with(&bridge, ModeRequest::Lowest(100)).expect("modes");
            let elapsed = start.elapsed().as_secs_f64();
            last = Some(modal);
            elapsed
        });
        let modal = last.expect("one run");
        let (median, _) = median_min(times);
        let lines = sample(budget, || {
            let start = Instant::now();
            for span in 0..30 {
                for quarter in 1..=3 {
                    let x = 30.0 * span as f64 + 7.5 * quarter as f64;
                    modal.influence_line(x, 0.0, 0.0).expect("influence line");
                }
            }
            start.elapsed().as_secs_f64()
        });
        let (lines_median, _) = median_min(lines);
        println!(
            "| {elements} | {} | {:.3} s | {:.3} s | {:.1e} | {:.1e} |",
            ModalBridge::available_of(&bridge),
            median,
            lines_median,
            modal.check.largest_residual,
            modal.check.orthonormality_error
        );
    }
    println!();
    println!("### Static correction: per-step cost of the Yang & Yau crossing (5 records)\n");
    println!("| modes | static correction | per step (median) |");
    println!("|---|---|---|");
    let text = read_scenario("yang-yau-sprung-mass.yaml");
    for modes in [5usize, 10, 40] {
        for correction in [false, true] {
            let scene = text.replace(
                "modes: {count: 10}",
                &format!("modes: {{count: {modes}, static_correction: {correction}}}"),
            );
            let loaded = load(&scene, "yang-yau");
            let steps = simulate(&loaded).model.steps as f64;
            let times = sample(budget, || {
                let start = Instant::now();
                simulate(&loaded);
                start.elapsed().as_secs_f64()
            });
            let (median, _) = median_min(times);
            println!(
                "| {modes} | {correction} | {:.2} µs |",
                1e6 * median / steps
            );
        }
    }
    println!();
}

/// Path of a file in the crate's `scenarios/` folder.
fn scenario_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios")
        .join(name)
}

fn read_scenario(name: &str) -> String {
    let path = scenario_path(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Median and minimum of a sample.
fn median_min(mut xs: Vec<f64>) -> (f64, f64) {
    assert!(!xs.is_empty());
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    let median = if n % 2 == 1 {
        xs[n / 2]
    } else {
        0.5 * (xs[n / 2 - 1] + xs[n / 2])
    };
    (median, xs[0])
}

/// Repetitions for a case whose warm-up took `warmup` seconds.
fn repetitions(warmup: f64, budget: f64) -> usize {
    ((budget / warmup.max(1e-9)).ceil() as usize).clamp(3, 100_000)
}

/// Runs `f` once to warm up, then N times; returns the N values `f` reports
/// (its own measure, in whatever unit).
fn sample(budget: f64, mut f: impl FnMut() -> f64) -> Vec<f64> {
    let start = Instant::now();
    f();
    let n = repetitions(start.elapsed().as_secs_f64(), budget);
    (0..n).map(|_| f()).collect()
}

/// The scene text with its `contact:` line replaced by `contact` and any
/// explicit `method:` in the solver line removed (the default follows the contact).
fn with_contact(text: &str, contact: &str) -> String {
    let mut replaced = false;
    let out: Vec<String> = text
        .lines()
        .map(|line| {
            if line.starts_with("contact:") {
                replaced = true;
                format!("contact: {contact}")
            } else if line.starts_with("solver:") {
                line.replace("method: coupled, ", "")
                    .replace("method: lcp, ", "")
            } else {
                line.to_string()
            }
        })
        .collect();
    assert!(replaced, "no `contact:` line");
    out.join("\n") + "\n"
}

fn load(text: &str, label: &str) -> Loaded {
    vbi::plan::load_str(text, label).unwrap_or_else(|e| panic!("{label}: {e}"))
}

fn simulate(loaded: &Loaded) -> Outcome {
    vbi::run::simulate(loaded.clone(), &mut |_, _| {}).expect("simulation runs")
}

// ---------------------------------------------------------------------------
// a. Per-step cost, coupled vs LCP on the same scene

fn per_step(budget: f64) {
    println!("## Unilateral contact (LCP) vs coupled, per step\n");
    println!(
        "Per-step cost = `summary.run.wall_time` (build + solve + record) / `steps`, \
         library call `vbi::run::simulate` on a pre-loaded scene. The four contact variants \
         of a scene run interleaved (one of each per round), so load from other work that \
         varies over time affects them alike; the ratio is taken within each round \
         (median over rounds), and as min / min.\n"
    );
    println!(
        "| scene | contact | solver | steps | reps | median ns/step | min ns/step | \
         lcp / coupled (median per round) | lcp / coupled (min / min) | contact-loss episodes |"
    );
    println!("|---|---|---|---:|---:|---:|---:|---:|---:|---:|");
    let contacts = [
        "{type: permanent}",
        "{type: rigid}",
        "{type: elastic, stiffness_ratio: 100.0}",
        "{type: hertz, coefficient: 1.0e11}",
    ];
    for (file, label) in [
        ("lcp-fig4-rigid.yaml", "fig4 (separates)"),
        (
            "lcp-oscillator-smooth.yaml",
            "oscillator-smooth (no separation)",
        ),
    ] {
        let text = read_scenario(file);
        let loaded: Vec<Loaded> = contacts
            .iter()
            .map(|c| load(&with_contact(&text, c), file))
            .collect();
        // Warm-up: one run of each; it also gives the run facts.
        let mut fastest = f64::INFINITY;
        let facts: Vec<(usize, &'static str, usize)> = loaded
            .iter()
            .map(|l| {
                let start = Instant::now();
                let out = simulate(l);
                fastest = fastest.min(start.elapsed().as_secs_f64());
                let run = &out.summary.run;
                let episodes = out.summary.separation.iter().map(|s| s.episodes).sum();
                (run.steps, run.solver, episodes)
            })
            .collect();
        // Every variant gets at least the budget.
        let reps = repetitions(fastest, budget);
        let mut samples = vec![Vec::with_capacity(reps); loaded.len()];
        for _ in 0..reps {
            for (l, sample) in loaded.iter().zip(&mut samples) {
                let out = simulate(l);
                sample.push(out.summary.run.wall_time / out.summary.run.steps as f64 * 1e9);
            }
        }
        // Ratio per round (same moment, same machine state), then its median.
        let round_ratios: Vec<f64> = samples
            .iter()
            .map(|s| {
                let ratios = s.iter().zip(&samples[0]).map(|(x, r)| x / r).collect();
                median_min(ratios).0
            })
            .collect();
        let stats: Vec<(f64, f64)> = samples.into_iter().map(median_min).collect();
        assert_eq!(facts[0].1, "coupled", "the first variant is the reference");
        let ref_min = stats[0].1;
        for (((contact, (steps, solver, episodes)), (median, min)), round_ratio) in
            contacts.iter().zip(facts).zip(stats).zip(round_ratios)
        {
            let (ratio_rounds, ratio_min, episodes) = if solver == "coupled" {
                (
                    "1 (reference)".to_string(),
                    "1".to_string(),
                    "—".to_string(),
                )
            } else {
                (
                    format!("{round_ratio:.2}×"),
                    format!("{:.2}×", min / ref_min),
                    episodes.to_string(),
                )
            };
            println!(
                "| {label} | `{contact}` | {solver} | {steps} | {reps} | {median:.0} | {min:.0} | \
                 {ratio_rounds} | {ratio_min} | {episodes} |"
            );
        }
    }
    println!();
}

// ---------------------------------------------------------------------------
// b. Foundation scene end to end through the library

fn foundation(budget: f64) {
    println!("## Foundation scene end to end (library)\n");
    let path = scenario_path("lcp-oscillator-smooth.yaml");
    let out = std::env::temp_dir().join(format!("vbi-bench-foundation-{}", std::process::id()));
    let mut run_wall = Vec::new();
    let total = sample(budget, || {
        let start = Instant::now();
        let loaded = vbi::plan::load_file(&path).expect("scene loads");
        let scenario = loaded.scenario.clone();
        let outcome = vbi::run::simulate(loaded, &mut |_, _| {}).expect("scene runs");
        vbi::run::write_results(&out, &scenario, &outcome).expect("results written");
        run_wall.push(outcome.summary.run.wall_time * 1e3);
        start.elapsed().as_secs_f64() * 1e3
    });
    let _ = std::fs::remove_dir_all(&out);
    run_wall.remove(0); // the warm-up
    let reps = total.len();
    let (median, min) = median_min(total);
    let (run_median, run_min) = median_min(run_wall);
    println!(
        "`scenarios/lcp-oscillator-smooth.yaml`: load_file + simulate + write_results into a temp dir.\n"
    );
    println!("| part | reps | median ms | min ms |");
    println!("|---|---:|---:|---:|");
    println!("| load + simulate + write (whole) | {reps} | {median:.2} | {min:.2} |");
    println!(
        "| `run.wall_time` (build + solve + record) | {reps} | {run_median:.2} | {run_min:.2} |"
    );
    println!();
    println!("Whole CLI process:\n");
    println!("```sh");
    println!("cargo build --release");
    println!(
        "hyperfine -N --warmup 5 --runs 50 \\\n  'target/release/vbi run scenarios/lcp-oscillator-smooth.yaml --out /tmp/bench-osc --quiet'"
    );
    println!("```\n");
}

// ---------------------------------------------------------------------------
// c. Separation maps 40 × 40

fn execute_map(loaded: &Loaded) -> SeparationMap {
    match vbi::execute::execute(loaded.clone(), &|_, _| {}).expect("study runs") {
        Results::SeparationMap(map) => map,
        _ => panic!("expected a separation map"),
    }
}

/// Whether two maps agree point by point: (same `separated` everywhere,
/// every point bit-identical).
fn compare(a: &SeparationMap, b: &SeparationMap) -> (bool, bool) {
    assert_eq!(a.points.len(), b.points.len());
    let separated = a
        .points
        .iter()
        .zip(&b.points)
        .all(|(p, q)| p.separated == q.separated);
    (separated, a.points == b.points)
}

fn separation_maps(budget: f64) {
    println!("## Separation map 40 × 40\n");
    let threads = rayon::current_num_threads();
    let single = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("one-thread pool");
    println!(
        "`vbi::execute::execute` on a pre-loaded scene (both grids `count: 20` → `count: 40`); \
         wall time of the whole map (`map.wall_time`).\n"
    );
    println!(
        "| scene | points | separated | threads | reps | median s | min s | ms / point (median) | \
         speed-up |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut agreements = Vec::new();
    for file in ["lcp-fig6-smooth.yaml", "lcp-fig6-harmonic.yaml"] {
        let text = read_scenario(file).replace("count: 20", "count: 40");
        let loaded = load(&text, file);
        let mut multi_map = None;
        let multi = sample(budget, || {
            let map = execute_map(&loaded);
            let t = map.wall_time;
            multi_map = Some(map);
            t
        });
        let mut one_map = None;
        let one = single.install(|| {
            sample(budget, || {
                let map = execute_map(&loaded);
                let t = map.wall_time;
                one_map = Some(map);
                t
            })
        });
        let (multi_map, one_map) = (multi_map.unwrap(), one_map.unwrap());
        let points = multi_map.points.len();
        let separated = multi_map.separated_count();
        let (multi_median, multi_min) = median_min(multi.clone());
        let (one_median, one_min) = median_min(one.clone());
        let name = file.trim_end_matches(".yaml");
        for (n, reps, median, min, speedup) in [
            (
                threads,
                multi.len(),
                multi_median,
                multi_min,
                one_median / multi_median,
            ),
            (1, one.len(), one_median, one_min, 1.0),
        ] {
            println!(
                "| {name} 40×40 | {points} | {separated} | {n} | {reps} | {median:.2} | {min:.2} | \
                 {:.2} | {speedup:.2}× |",
                median / points as f64 * 1e3
            );
        }
        agreements.push((name, compare(&multi_map, &one_map)));
    }
    println!();
    for (name, (separated, identical)) in agreements {
        println!(
            "- {name}: {threads}-thread and 1-thread maps: `separated` {} at every point; \
             all point fields {}.",
            if separated { "identical" } else { "DIFFERS" },
            if identical {
                "bit-identical"
            } else {
                "not bit-identical"
            },
        );
    }
    println!();
}

// ---------------------------------------------------------------------------
// d. Plate deck and truck

/// The orthotropic three-span deck of the plate paper with 45 modes and one
/// H20-44 truck at 108 km/h on a good road, Δt = 3.12e-3 s, `iterative`
/// solver to 1e-8: loading (which solves the Ritz eigenproblem) and the run
/// (build + solve + record), separately.
fn plate(budget: f64) {
    println!("## Plate deck and truck, one crossing\n");
    for name in ["plate-orthotropic-case1.yaml", "plate-isotropic-32.5.yaml"] {
        let path = scenario_path(name);
        let mut run_wall = Vec::new();
        let mut steps = 0;
        let mut iterations = 0.0;
        let loads = sample(budget, || {
            let start = Instant::now();
            let loaded = vbi::plan::load_file(&path).expect("scene loads");
            let load_ms = start.elapsed().as_secs_f64() * 1e3;
            let outcome = simulate(&loaded);
            steps = outcome.summary.run.steps;
            iterations = outcome.summary.run.iterations.map_or(0.0, |i| i.mean);
            run_wall.push(outcome.summary.run.wall_time * 1e3);
            load_ms
        });
        run_wall.remove(0); // the warm-up
        let reps = loads.len();
        let (load_median, load_min) = median_min(loads);
        let (run_median, run_min) = median_min(run_wall);
        println!("`scenarios/{name}`: {steps} steps, {iterations:.2} iterations per step.\n");
        println!("| part | reps | median ms | min ms |");
        println!("|---|---:|---:|---:|");
        println!("| load (parse, check, Ritz eigen) | {reps} | {load_median:.2} | {load_min:.2} |");
        println!(
            "| `run.wall_time` (build + solve + record) | {reps} | {run_median:.2} | {run_min:.2} |"
        );
        println!();
    }
}
