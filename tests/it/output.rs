//! Lean outputs (issue 14, point 2): `output: {every | interval, format}`
//! thins what is written, never what is computed; history.npy holds the
//! CSV's values; every CSV header carries its unit; a run that would write
//! more than `limits.output_bytes` is refused before it starts.

use crate::support;

use std::process::Command;

use support::Scratch;
use vbi::plan::load_str;
use vbi::run::{Outcome, simulate, write_results};

/// The Yang & Yau sprung mass with a 300 kg wheel on an elastic contact over
/// a short-wave harmonic track (the wheel hops: 92 Hz at 27.5 m/s), braking,
/// every quantity type recorded.
fn scene(output: &str) -> String {
    format!(
        "name: lean\n\
         bridge: {{type: beam, spans: [25], bending_stiffness: 8.323e9, mass_per_length: 2303, \
         modes: {{count: 6}}, damping: {{type: modal, ratio: 0.02}}}}\n\
         vehicles: [{{type: oscillator, sprung_mass: 5750, unsprung_mass: 300, stiffness: 1.595e6, \
         speed: 27.5, acceleration: -2}}]\n\
         surface: {{type: harmonic, amplitude: 0.001, wavelength: 0.3, phase: 0}}\n\
         contact: {{type: elastic, stiffness: 2.0e8}}\n\
         solver: {{method: lcp, time_step: 1.0e-4, free_vibration: 0.2}}\n\
         record:\n\
         \x20 - {{name: mid, quantity: bridge_displacement, x: 12.5}}\n\
         \x20 - {{name: mid_acc, quantity: bridge_acceleration, x: 12.5}}\n\
         \x20 - {{name: body, quantity: vehicle_displacement, vehicle: 1, dof: sprung}}\n\
         \x20 - {{name: body_acc, quantity: vehicle_acceleration, vehicle: 1, dof: sprung}}\n\
         \x20 - {{name: force, quantity: contact_force, vehicle: 1, wheel: 1}}\n\
         \x20 - {{name: gap, quantity: contact_gap, vehicle: 1, wheel: 1}}\n\
         {output}"
    )
}

/// Runs `yaml` and writes its results into `out`.
fn run_into(yaml: &str, out: &std::path::Path) -> Outcome {
    let loaded = load_str(yaml, "lean.yaml").unwrap_or_else(|e| panic!("{e}"));
    let scenario = loaded.scenario.clone();
    let outcome = simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
    write_results(out, &scenario, &outcome).unwrap_or_else(|e| panic!("{e}"));
    outcome
}

/// The rows of a CSV file after its header.
fn rows(path: &std::path::Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines().skip(1).map(str::to_owned).collect()
}

/// A decimated run: its summary's extremes (values, times, positions,
/// on-bridge extremes, static maxima, DAFs) and separation statistics equal
/// the full run's exactly, and its CSV rows are every N-th row of the full
/// CSV, byte for byte; `interval` gives the same as the `every` it rounds to.
#[test]
fn decimation_thins_the_history_not_the_extremes() {
    let scratch = Scratch::new("output", "decimate");
    let full = run_into(&scene(""), &scratch.path("full"));
    let every = 7;
    let thin = run_into(
        &scene(&format!("output: {{every: {every}}}\n")),
        &scratch.path("thin"),
    );
    assert!(
        full.summary.separation.iter().any(|w| w.separated),
        "the scene should lose contact, so separation statistics are compared"
    );
    assert_eq!(thin.summary.quantities, full.summary.quantities);
    assert_eq!(thin.summary.separation, full.summary.separation);
    assert_eq!(thin.summary.run.steps, full.summary.run.steps);
    let (full_rows, thin_rows) = (
        rows(&scratch.path("full/history.csv")),
        rows(&scratch.path("thin/history.csv")),
    );
    assert_eq!(full_rows.len(), full.summary.run.steps + 1);
    let expected: Vec<&String> = full_rows.iter().step_by(every).collect();
    assert_eq!(thin_rows.iter().collect::<Vec<_>>(), expected);
    // An extreme that falls between written rows is still found: at least
    // one of the summary's max_abs times is not a written time.
    let written: Vec<f64> = thin.history.time.clone();
    assert!(
        full.summary
            .quantities
            .iter()
            .any(|q| !written.contains(&q.max_abs.time)),
        "no extreme between written rows: the test would not see a decimated scan"
    );
    // 0.7 ms at 0.1 ms steps is every 7th step.
    let by_interval = run_into(
        &scene("output: {interval: 0.0007}\n"),
        &scratch.path("interval"),
    );
    assert_eq!(by_interval.summary.quantities, full.summary.quantities);
    assert_eq!(rows(&scratch.path("interval/history.csv")), thin_rows);
}

/// Parses an NPY 1.0 file of little-endian float64 in C order: the shape
/// and the values, independently of vbi's writer.
fn read_npy(bytes: &[u8]) -> ((usize, usize), Vec<f64>) {
    assert_eq!(&bytes[..6], b"\x93NUMPY", "magic");
    assert_eq!((bytes[6], bytes[7]), (1, 0), "version 1.0");
    let length = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    assert_eq!((10 + length) % 64, 0, "data aligned to 64 bytes");
    let header = std::str::from_utf8(&bytes[10..10 + length]).unwrap();
    assert!(header.contains("'descr': '<f8'"), "{header}");
    assert!(header.contains("'fortran_order': False"), "{header}");
    assert!(header.ends_with('\n'), "{header:?}");
    let shape = header.split("'shape': (").nth(1).unwrap();
    let shape = &shape[..shape.find(')').unwrap()];
    let dims: Vec<usize> = shape
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().unwrap())
        .collect();
    let data = &bytes[10 + length..];
    assert_eq!(data.len(), dims[0] * dims[1] * 8);
    let values = data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    ((dims[0], dims[1]), values)
}

/// `format: both` writes history.npy with the CSV's values bit for bit
/// (time stamps included), and history_columns.txt with the CSV's header;
/// `format: npy` writes no CSV.
#[test]
fn npy_holds_the_csv_values() {
    let scratch = Scratch::new("output", "npy");
    let out = scratch.path("both");
    run_into(&scene("output: {every: 3, format: both}\n"), &out);
    let csv = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let table: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    let ((rows, columns), values) = read_npy(&std::fs::read(out.join("history.npy")).unwrap());
    assert_eq!((rows, columns), (table.len(), header.len()));
    for (r, row) in table.iter().enumerate() {
        for (c, &v) in row.iter().enumerate() {
            // Equal values (the CSV writes −0 as 0; every other value is
            // its exact shortest round-trip text).
            assert_eq!(values[r * columns + c], v, "row {r} column {c}");
        }
    }
    let names = std::fs::read_to_string(out.join("history_columns.txt")).unwrap();
    assert_eq!(names.lines().collect::<Vec<_>>(), header);

    let only = scratch.path("npy");
    run_into(&scene("output: {format: npy}\n"), &only);
    assert!(only.join("history.npy").exists() && !only.join("history.csv").exists());
}

/// Every CSV column names its unit; time stamps are k·Δt without
/// floating-point artefacts (3000 steps of 1e-4 s print as 0.3).
#[test]
fn headers_carry_units_and_time_stamps_are_clean() {
    let scratch = Scratch::new("output", "units");
    let out = scratch.path("run");
    run_into(&scene(""), &out);
    let csv = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "time [s],mid [m],mid_static [m],mid_acc [m/s^2],body [m],body_acc [m/s^2],force [N],gap [m]"
    );
    for (k, line) in lines.enumerate() {
        let time = line.split(',').next().unwrap();
        // The decimal k/10⁴ itself, written with at most 4 decimals.
        let decimal: f64 = format!("{:.4}", k as f64 / 1e4).parse().unwrap();
        assert_eq!(time.parse::<f64>().unwrap(), decimal, "row {k}: {time}");
        let decimals = time.split('.').nth(1).map_or(0, str::len);
        assert!(decimals <= 4, "row {k}: {time}");
    }
}

/// A run whose history would pass `limits.output_bytes` is refused before
/// it starts: exit 2, the file, line and column of `output`, the limit's
/// name; thinning it with `every` lets it run.
#[test]
fn a_too_large_history_is_refused_before_the_run() {
    let scratch = Scratch::new("output", "refuse");
    // 1.6e4 steps × 9 columns × 24 bytes ≈ 3.5 MB against a 1 MB limit.
    let big = scene("output: {format: csv}\nlimits: {output_bytes: 1.0e6}\n");
    let file = scratch.path("big.yaml");
    std::fs::write(&file, &big).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(["run", "--quiet", "--out"])
        .arg(scratch.path("big-out"))
        .arg(&file)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let line = big.lines().position(|l| l.starts_with("output:")).unwrap() + 1;
    assert!(
        stderr.contains(&format!("big.yaml:{line}:")) && stderr.contains("output_bytes"),
        "{stderr}"
    );
    assert!(!scratch.path("big-out").exists(), "nothing written");
    // Every 10th step: ~0.35 MB.
    let thin = scene("output: {every: 10}\nlimits: {output_bytes: 1.0e6}\n");
    assert!(load_str(&thin, "thin.yaml").is_ok());
}

/// The files in `dir`, sorted.
fn listing(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A run streamed to disk as it goes (`vbi run`'s path above 32 MB of
/// samples: rows spilled to a file in the output folder,
/// `run::simulate_into`; forced here) writes history.csv and
/// history.npy byte-identical to the run held in memory, the same summary
/// extremes, draws its plot from the file (over 8,192 rows: min/max
/// buckets), leaves no spill file behind, and neither does a run that
/// diverges (a conditionally stable Newmark variant beyond its limit).
#[test]
fn streamed_runs_write_what_runs_in_memory_write() {
    let scratch = Scratch::new("output", "streamed");
    let yaml = scene("output: {format: both}\n");
    let held = scratch.path("held");
    run_into(&yaml, &held);
    let streamed = scratch.path("streamed");
    let loaded = load_str(&yaml, "lean.yaml").unwrap();
    let scenario = loaded.scenario.clone();
    let outcome =
        vbi::run::simulate_streaming_above(loaded, &streamed, &mut |_, _| {}, 0.0).unwrap();
    assert!(outcome.history.spilled.is_some() && outcome.history.time.is_empty());
    let rows = outcome.history.spilled.as_ref().unwrap().rows;
    assert!(
        rows > 8192,
        "{rows} rows: the plot's bucket path is exercised"
    );
    vbi::run::write_results_with(&streamed, &scenario, &outcome, false).unwrap();
    for file in ["history.csv", "history.npy", "history_columns.txt"] {
        let (a, b) = (
            std::fs::read(held.join(file)).unwrap(),
            std::fs::read(streamed.join(file)).unwrap(),
        );
        assert!(a == b, "{file} differs");
    }
    let (a, b) = (
        std::fs::read_to_string(held.join("summary.json")).unwrap(),
        std::fs::read_to_string(streamed.join("summary.json")).unwrap(),
    );
    let strip = |s: &str| {
        s.lines()
            .filter(|l| !l.contains("wall_time"))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(strip(&a), strip(&b));
    drop(outcome);
    assert_eq!(
        listing(&streamed),
        listing(&held),
        "nothing but the results"
    );

    // A diverging run: β = 0.01 at twice its stability limit.
    let diverging = "name: diverging\n\
         bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, \
         modes: {count: 10}}\n\
         vehicles: [{type: moving_force, loads: [1.0e5], speed: 25.0}]\n\
         solver: {time_step: 1.3e-3, free_vibration: 0.5, newmark: {beta: 0.01, gamma: 0.5}}\n\
         record: [{name: mid, quantity: bridge_displacement, x: 10.0}]\n";
    let failed = scratch.path("failed");
    let loaded = load_str(diverging, "diverging.yaml").unwrap();
    assert!(vbi::run::simulate_streaming_above(loaded, &failed, &mut |_, _| {}, 0.0).is_err());
    assert!(listing(&failed).is_empty(), "{:?}", listing(&failed));
}
