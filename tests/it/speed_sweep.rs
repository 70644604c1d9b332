//! The `speed_sweep` study (the plate paper's Figs. 12, 13 and 17): every
//! point equals a single run of the scene at that speed and surface, bit for
//! bit; the sweep does not depend on the thread count; the automatic mode
//! cut-off and time step serve the whole sweep; a plate sweep tabulates every
//! girder line; and `vbi run` writes every output, or nothing on failure.

use crate::support;

use std::path::Path;
use std::process::{Command, Output};

use support::{Scratch, on_threads, run_yaml};
use vbi::execute::{Results, execute};
use vbi::plan::load_str;
use vbi::study::speed_sweep::SweepResults;

/// Runs the sweep of a scene given as YAML text, in a pool of `threads`
/// threads (rayon's global pool when `None`).
fn sweep(text: &str, threads: Option<usize>) -> SweepResults {
    let loaded = load_str(text, "sweep.yaml").unwrap_or_else(|e| panic!("{e}"));
    let run = || match execute(loaded, &|_, _| {}) {
        Ok(Results::SpeedSweep(results)) => results,
        Ok(_) => panic!("expected a speed sweep"),
        Err(e) => panic!("{e}"),
    };
    on_threads(threads, run)
}

/// A two-span beam (20 + 25 m) crossed by a two-axle moving load at `speed`
/// (m/s, as written), with the given `surface` and `study` lines.
fn beam_scene(speed: &str, extra: &str) -> String {
    format!(
        "name: sweep-beam
bridge: {{type: beam, spans: [20.0, 25.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, modes: {{count: 8}}, damping: {{type: modal, ratio: 0.02}}}}
vehicles:
  - {{type: moving_force, loads: [6.0e4, 1.4e5], axle_spacings: [4.3], speed: {speed}, start_position: -1.0}}
solver: {{time_step: 1.0e-3, free_vibration: 0.1}}
record:
  - {{name: mid1, quantity: bridge_displacement, x: 10.0}}
  - {{name: mid2, quantity: bridge_displacement, x: 32.5}}
  - {{name: quarter, quantity: bridge_displacement, x: 5.0}}
  - {{name: rear, quantity: contact_force, vehicle: 1, wheel: 2}}
{extra}"
    )
}

fn column(results: &SweepResults, name: &str) -> usize {
    results
        .daf_columns
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no column {name} in {:?}", results.daf_columns))
}

fn bits(v: Option<f64>) -> Option<u64> {
    v.map(f64::to_bits)
}

/// Test 1: on a beam under a moving load, each point's DAFs and largest
/// force are those of `vbi` run on the same scene at that speed, bit for bit;
/// the span-middle columns equal the records at the span middles; the DAF
/// changes with speed; and study.csv is the same with 1, 2 and all threads.
#[test]
fn beam_sweep_equals_single_runs_and_does_not_depend_on_threads() {
    let study = "study: {type: speed_sweep, speeds: {from: 5.0, to: 40.0, count: 6}}\n";
    let text = beam_scene("20.0", study);
    let results = sweep(&text, None);
    assert_eq!(results.points.len(), 6);
    assert_eq!(results.roughness, ["smooth"]);
    assert_eq!((results.runs.clone(), results.span), (vec![1], 2));
    assert_eq!(
        results.daf_columns,
        [
            "daf_span1_girder1",
            "daf_span2_girder1",
            "daf_mid1",
            "daf_mid2",
            "daf_quarter"
        ]
    );
    assert_eq!(results.force_records, ["rear"]);
    for (point, &speed) in results.points.iter().zip(&results.speeds) {
        assert_eq!(point.speed.to_bits(), speed.to_bits());
        assert_eq!((point.sample, point.seed), (1, None));
        let single = run_yaml(&beam_scene(&format!("{speed:?}"), ""));
        let quantity = |name: &str| {
            single
                .summary
                .quantities
                .iter()
                .find(|q| q.name == name)
                .expect("recorded")
        };
        for name in ["mid1", "mid2", "quarter"] {
            let daf = point.dafs[column(&results, &format!("daf_{name}"))];
            assert!(daf.is_some(), "{name} at {speed} m/s: no DAF");
            assert_eq!(bits(daf), bits(quantity(name).daf), "{name} at {speed} m/s");
        }
        for (span, record) in [(1, "mid1"), (2, "mid2")] {
            let daf = point.dafs[column(&results, &format!("daf_span{span}_girder1"))];
            assert_eq!(bits(daf), bits(quantity(record).daf), "span {span}");
        }
        assert_eq!(
            point.max_forces[0].to_bits(),
            quantity("rear").max.value.to_bits()
        );
    }
    let mid2 = column(&results, "daf_mid2");
    let first = results.points[0].dafs[mid2].unwrap();
    let last = results.points[5].dafs[mid2].unwrap();
    assert!((first - last).abs() > 1e-3, "DAF {first} vs {last}");

    let csv = results.to_csv();
    for threads in [1, 2] {
        assert_eq!(
            String::from_utf8(sweep(&text, Some(threads)).to_csv()).unwrap(),
            String::from_utf8(csv.clone()).unwrap(),
            "study.csv differs with {threads} thread(s)"
        );
    }
}

/// A scene left to the automatic mode cut-off and time step: the sweep's are
/// those of its top speed (roughness v/λ sets them here), not of the scene's
/// own speed, and so its top-speed point equals a single run at that speed.
#[test]
fn automatic_defaults_cover_the_whole_sweep() {
    let scene = |speed: &str, study: &str| {
        format!(
            "name: sweep-auto
bridge: {{type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0}}
vehicles: [{{type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: {speed}}}]
surface: {{type: harmonic, amplitude: 0.001, wavelength: 0.5}}
record: [{{name: mid, quantity: bridge_displacement, x: 10.0}}]
{study}"
        )
    };
    let study = "study: {type: speed_sweep, speeds: {from: 5.0, to: 40.0, count: 3}}\n";
    let resolve = |text: &str| {
        load_str(text, "auto.yaml")
            .unwrap_or_else(|e| panic!("{e}"))
            .scenario
    };
    let swept = resolve(&scene("10.0", study));
    let own = resolve(&scene("10.0", ""));
    let top = resolve(&scene("40.0", ""));
    assert_eq!(swept.solver.time_step, top.solver.time_step);
    assert_eq!(swept.bridge.modes(), top.bridge.modes());
    eprintln!(
        "time step {:e} s at the scene's 10 m/s, {:e} s for the sweep to 40 m/s; modes {:?} vs {:?}",
        own.solver.time_step,
        swept.solver.time_step,
        own.bridge.modes(),
        swept.bridge.modes()
    );
    assert!(swept.solver.time_step < own.solver.time_step);
    assert!(swept.bridge.modes().max_frequency > own.bridge.modes().max_frequency);

    let results = sweep(&scene("10.0", study), None);
    let single = run_yaml(&scene("40.0", ""));
    let last = results.points.last().expect("points");
    assert_eq!(last.speed, 40.0);
    assert_eq!(
        bits(last.dafs[column(&results, "daf_mid")]),
        bits(single.summary.quantities[0].daf)
    );
}

fn plate_scene() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/plate-orthotropic-case1.yaml"),
    )
    .expect("plate scenario")
}

/// `text` with its vehicle at `speed` and the given surface line.
fn plate_variant(text: &str, speed: f64, surface: &str) -> String {
    let replace_line = |text: &str, start: &str, with: &str| {
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(start))
            .unwrap_or_else(|| panic!("no line {start}"));
        text.replace(line, with)
    };
    let text = replace_line(text, "speed:", &format!("    speed: {speed:?}"));
    replace_line(&text, "surface:", surface)
}

/// Test 2 (the plate paper's case 1 deck and truck): the DAF at the middle
/// of every span on every girder line, each equal to a single run's DAF
/// table at that speed and surface (a class keeps the scene's random
/// settings and advances its seed per sample); the span-middle DAF equals a
/// record at the same point; a rough road raises the DAF (Fig. 17).
#[test]
fn plate_sweep_tabulates_every_girder_and_matches_single_runs() {
    let text = plate_scene()
        + "study: {type: speed_sweep, speeds: {from: 16.667, to: 30.0, count: 2}, roughness: [smooth, good], samples: 2}\n";
    let results = sweep(&text, None);
    assert!(results.plate);
    assert_eq!(
        (results.span, results.girder, results.girder_lines),
        (2, 1, 5)
    );
    assert_eq!(results.roughness, ["smooth", "good"]);
    assert_eq!(results.runs, [1, 2]);
    assert_eq!(results.seeds, [vec![], vec![1, 2]]);
    assert_eq!(results.points.len(), 6);
    assert_eq!(results.daf_columns.len(), 3 * 5 + 2);
    assert_eq!(results.daf_columns[7], "daf_span2_girder3");
    assert_eq!(results.daf_columns[15], "daf_record_span2_girder1");

    for point in &results.points {
        let surface = match point.seed {
            None => "surface: {type: smooth}".to_string(),
            Some(seed) => format!("surface: {{type: random, class: good, seed: {seed}}}"),
        };
        let single = run_yaml(&plate_variant(&plate_scene(), point.speed, &surface));
        let table = &single.summary.girder_dafs;
        assert_eq!(table.len(), 15);
        for row in table {
            let c = column(
                &results,
                &format!("daf_span{}_girder{}", row.span, row.girder),
            );
            assert!(row.static_max_abs > 0.0);
            assert_eq!(
                bits(point.dafs[c]),
                Some(row.daf.to_bits()),
                "span {} girder {} at {} m/s, seed {:?}",
                row.span,
                row.girder,
                point.speed,
                point.seed
            );
        }
        let middle = point.dafs[column(&results, "daf_span2_girder1")];
        let record = point.dafs[column(&results, "daf_record_span2_girder1")];
        assert_eq!(bits(middle), bits(record));
    }
    let c = results.span_column(2, 1);
    let (smooth, _) = results.daf_statistics(0, c);
    let (good, good_max) = results.daf_statistics(1, c);
    let intervals = results.daf_mean_intervals(1, c);
    for i in 0..2 {
        assert!(good[i] > smooth[i], "{good:?} vs {smooth:?}");
        assert!(good_max[i] >= good[i]);
        // The mean of the 2 rough-road samples has a 95 % interval around
        // it, above 0 (issue 40.5); the smooth road's single run none.
        let Some((low, Some(high))) = intervals[i] else {
            panic!("{intervals:?}")
        };
        assert!(
            0.0 < low && low < good[i] && good[i] < high,
            "{intervals:?}"
        );
    }
    assert!(results.daf_mean_intervals(0, c).iter().all(Option::is_none));
}

// ---------------------------------------------------------------------------
// The command line

fn vbi_run(scenario: &Path, out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(["run".as_ref(), scenario.as_os_str(), "--out".as_ref()])
        .arg(out)
        .arg("--quiet")
        .output()
        .expect("run vbi")
}

fn file_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Test 4: `vbi run` on a sweep writes study.csv, the three plots,
/// resolved.yaml and summary.json, and running resolved.yaml again gives
/// the same study.csv; a sweep whose runs diverge, or an output folder that
/// cannot be made, exits 1 and leaves nothing behind.
#[test]
fn run_writes_every_output_and_nothing_on_failure() {
    let scratch = Scratch::new("sweep", "cli");
    let scene = scratch.path("sweep.yaml");
    let study = "surface: {type: harmonic, amplitude: 0.002, wavelength: 5.0}\n\
                 study: {type: speed_sweep, speeds: {from: 10.0, to: 30.0, count: 4}, roughness: [smooth, good], samples: 2, span: 1}\n";
    std::fs::write(&scene, beam_scene("20.0", study)).unwrap();
    let out = scratch.path("out");
    let run = vbi_run(&scene, &out);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert_eq!(
        file_names(&out),
        [
            "daf_map.png",
            "daf_speed.png",
            "daf_speed_roughness.png",
            "resolved.yaml",
            "study.csv",
            "summary.json"
        ]
    );
    for png in ["daf_map.png", "daf_speed.png", "daf_speed_roughness.png"] {
        let bytes = std::fs::read(out.join(png)).unwrap();
        assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{png}");
    }
    let csv = std::fs::read_to_string(out.join("study.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + (1 + 2) * 4, "{csv}");
    assert_eq!(
        lines[0],
        "roughness,sample,seed,speed [m/s],speed [km/h],daf_span1_girder1,daf_span2_girder1,\
         daf_mid1,daf_mid2,daf_quarter,max_rear [N],max_abs_mid1 [m],max_abs_mid2 [m],\
         max_abs_quarter [m],max_abs_rear [N]"
    );
    assert!(lines[1].starts_with("smooth,1,,10,36,"), "{}", lines[1]);
    assert!(lines[5].starts_with("good,1,1,10,36,"), "{}", lines[5]);
    assert!(lines[9].starts_with("good,2,2,10,36,"), "{}", lines[9]);

    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["study"], "speed_sweep");
    assert_eq!(summary["scenario"], "sweep-beam");
    assert_eq!(summary["points"], 12);
    assert_eq!(summary["samples"], 2);
    assert_eq!(
        (summary["span"].clone(), summary["girder"].clone()),
        (1.into(), 1.into())
    );
    assert_eq!(summary["speeds_km_h"][3], 108.0);
    assert_eq!(summary["roughness"], serde_json::json!(["smooth", "good"]));
    let by = summary["daf_by_roughness"].as_array().unwrap();
    assert_eq!(by.len(), 2);
    assert_eq!(by[1]["seeds"], serde_json::json!([1, 2]));
    assert_eq!(by[1]["mean_daf"].as_array().unwrap().len(), 4);
    // The mean DAF of the 2 samples has its 95 % interval (issue 40.5): a
    // moving force does not feel the roughness, both samples give the same
    // DAF, and the interval is that value; the smooth surface, run once,
    // has none.
    for i in 0..4 {
        let mean = &by[1]["mean_daf"][i];
        assert!(mean.as_f64().is_some_and(|m| m > 1.0), "{}", by[1]);
        assert_eq!(
            (&by[1]["mean_daf_low"][i], &by[1]["mean_daf_high"][i]),
            (mean, mean),
            "{}",
            by[1]
        );
        assert!(by[0]["mean_daf_low"][i].is_null() && by[0]["mean_daf_high"][i].is_null());
    }
    let largest = &summary["largest_daf"];
    let all_dafs = csv.lines().skip(1).flat_map(|l| {
        l.split(',')
            .skip(5)
            .take(5)
            .map(|v| v.parse::<f64>().unwrap())
            .collect::<Vec<_>>()
    });
    assert_eq!(largest["daf"].as_f64(), all_dafs.reduce(f64::max));

    // The resolved scene reproduces the sweep.
    let again = scratch.path("again");
    let run = vbi_run(&out.join("resolved.yaml"), &again);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert_eq!(
        std::fs::read_to_string(again.join("study.csv")).unwrap(),
        csv
    );

    // Every run diverges: β = 0.01 with a step far beyond its limit.
    let diverging = scratch.path("diverging.yaml");
    let text = beam_scene("20.0", study).replace(
        "time_step: 1.0e-3,",
        "time_step: 2.0e-2, newmark: {beta: 0.01, gamma: 0.5},",
    );
    std::fs::write(&diverging, text).unwrap();
    let failed = scratch.path("failed");
    let run = vbi_run(&diverging, &failed);
    assert_eq!(run.status.code(), Some(1), "{}", stderr(&run));
    assert!(stderr(&run).contains("diverged"), "{}", stderr(&run));
    assert!(!failed.exists(), "left behind {:?}", file_names(&failed));

    // The output folder cannot be made: a file is in the way.
    let blocked = scratch.path("blocked");
    std::fs::write(&blocked, "keep").unwrap();
    let run = vbi_run(&scene, &blocked.join("out"));
    assert_eq!(run.status.code(), Some(1), "{}", stderr(&run));
    assert_eq!(std::fs::read_to_string(&blocked).unwrap(), "keep");
    assert!(!stderr(&run).contains("panicked"));
}

/// Every recorded quantity survives a sweep (a deck acceleration filtered at
/// its record's `max_frequency`, a moment, a shear, a contact force): each
/// point's largest |value| per record equals the single run's bit for bit,
/// and study.csv gives each with its unit in the header.
#[test]
fn a_sweep_keeps_every_recorded_quantity() {
    let records = "  - {name: acc, quantity: bridge_acceleration, x: 10.0, max_frequency: 20.0}
  - {name: moment, quantity: bridge_moment, x: 10.0}
  - {name: shear, quantity: bridge_shear, x: 2.0}
";
    let study = "study: {type: speed_sweep, speeds: {from: 10.0, to: 30.0, count: 3}}\n";
    let results = sweep(&beam_scene("20.0", &format!("{records}{study}")), Some(1));
    let names: Vec<&str> = results.records.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["mid1", "mid2", "quarter", "rear", "acc", "moment", "shear"]
    );
    for (point, &speed) in results.points.iter().zip(&results.speeds) {
        let single = run_yaml(&beam_scene(&format!("{speed:?}"), records));
        for (i, name) in names.iter().enumerate() {
            let peak = support::max_abs(support::column(&single, name));
            assert_eq!(
                point.max_abs[i].to_bits(),
                peak.to_bits(),
                "{name} at {speed} m/s"
            );
            assert!(peak > 0.0, "{name} at {speed} m/s is 0");
        }
    }
    let csv = String::from_utf8(results.to_csv()).unwrap();
    let header = csv.lines().next().unwrap();
    for column in [
        "max_abs_acc [m/s^2]",
        "max_abs_moment [N*m]",
        "max_abs_shear [N]",
        "max_abs_mid1 [m]",
        "max_abs_rear [N]",
    ] {
        assert!(
            header.split(',').any(|c| c == column),
            "{column} in {header}"
        );
    }
}
