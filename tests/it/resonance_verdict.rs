//! The HSLM resonance check as an EN 1991-2 verdict, through the binary:
//! the speed grid reaches the maximum check speed 1.2 × the line speed
//! (EN 1991-2 6.4.6.2) and holds every resonance speed f₀·D/k, speeds print
//! as short decimals, each train gets a verdict, a failed check exits 3,
//! and the additional damping Δζ of EN 1991-2 6.4.6.3.1(3) is the code's
//! formula and acts as that much more modal damping.

use crate::support::{Scratch, vbi};

/// The check's exit status when it fails (docs/guide/commands.md, "Exit codes").
const EXIT_CHECK_FAILED: i32 = 3;

/// The km/h column of resonance.csv, as printed, for `train`.
fn km_h_column(csv: &str, train: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let at = header
        .iter()
        .position(|h| *h == "speed [km/h]")
        .expect("speed [km/h] column");
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|row| row[0] == train)
        .map(|row| row[at].to_owned())
        .collect()
}

/// Writes `scene` as `name`.yaml in `scratch`, runs it into `out-<name>`
/// and gives (exit status, stderr, resonance.csv, summary.json).
fn run_check(
    scratch: &Scratch,
    name: &str,
    scene: &str,
    quiet: bool,
) -> (i32, String, String, serde_json::Value) {
    let file = format!("{name}.yaml");
    let out_dir = format!("out-{name}");
    std::fs::write(scratch.path(&file), scene).unwrap();
    let mut args = vec!["run", file.as_str(), "--out", out_dir.as_str()];
    if quiet {
        args.push("--quiet");
    }
    let out = vbi(&args, scratch.dir());
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let read = |f: &str| {
        std::fs::read_to_string(scratch.path(&format!("{out_dir}/{f}")))
            .unwrap_or_else(|e| panic!("{f}: {e}: {stderr}"))
    };
    let csv = read("resonance.csv");
    let summary = serde_json::from_str(&read("summary.json")).unwrap();
    (out.status.code().unwrap_or(-1), stderr, csv, summary)
}

/// First natural frequency of the simply supported BRIDGE span, closed
/// form f₁ = π/(2L²)·√(EI/m) = 4.998243 Hz.
fn first_frequency() -> f64 {
    std::f64::consts::PI / (2.0 * 20.0 * 20.0) * (2.43e10_f64 / 15000.0).sqrt()
}

const BRIDGE: &str = "bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 2.43e10
  mass_per_length: 15000.0
  modes: {max_frequency: 40.0}
  damping: {type: modal, ratio: 0.01}
";

/// A 20 km/h step from the default 40 m/s (144 km/h) lands on 344 km/h,
/// not on the maximum check speed 1.2 × 300 = 360 km/h: the grid must
/// still end there (EN 1991-2 6.4.6.2(1)).
#[test]
fn the_grid_reaches_1_2_times_the_line_speed() {
    let scratch = Scratch::new("resonance_verdict", "grid_top");
    let scene = format!(
        "name: top\n{BRIDGE}vehicles: [{{type: hslm, model: A3, speed: 300 km/h}}]
study:
  type: resonance_check
  trains: [A3]
  line_speed: 300 km/h
  speeds: {{step: 20 km/h}}
"
    );
    std::fs::write(scratch.path("top.yaml"), scene).unwrap();
    let out = vbi(
        &["run", "top.yaml", "--out", "out", "--quiet"],
        scratch.dir(),
    );
    let csv = std::fs::read_to_string(scratch.path("out/resonance.csv"))
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let speeds = km_h_column(&csv, "HSLM-A3");
    assert_eq!(
        speeds.first().map(String::as_str),
        Some("144"),
        "{speeds:?}"
    );
    assert_eq!(speeds.last().map(String::as_str), Some("360"), "{speeds:?}");
}

/// HSLM-A3 (D = 20 m) on the 20 m span resonates at f₀·D = 359.87 km/h and
/// f₀·D/2 = 179.93 km/h (f₀ from the closed form); both are in the grid
/// (rounded to 0.01 km/h), with quarter steps (±5, ±10 km/h for a 20 km/h
/// step) around them inside the range unless a regular speed is within
/// 2 km/h, and 1.2 × 300 = 360 km/h too. The
/// km/h column prints short decimals only (no float noise such as
/// 359.00000000000006): at most two decimals.
#[test]
fn the_grid_holds_every_resonance_speed() {
    let scratch = Scratch::new("resonance_verdict", "grid_resonances");
    let scene = format!(
        "name: a3\n{BRIDGE}vehicles: [{{type: hslm, model: A3, speed: 300 km/h}}]
study: {{type: resonance_check, trains: [A3], line_speed: 300 km/h, speeds: {{step: 20 km/h}}}}
"
    );
    let (_, stderr, csv, summary) = run_check(&scratch, "a3", &scene, true);
    let f0 = summary["first_frequency_hz"].as_f64().unwrap();
    // The model's beam modes against the closed form.
    assert!(
        (f0 - first_frequency()).abs() < 1e-6 * first_frequency(),
        "f0 {f0} vs {}",
        first_frequency()
    );
    let speeds = km_h_column(&csv, "HSLM-A3");
    for printed in &speeds {
        let decimals = printed.split('.').nth(1).map_or(0, str::len);
        assert!(decimals <= 2, "{printed} in {speeds:?}");
    }
    let values: Vec<f64> = speeds.iter().map(|s| s.parse().unwrap()).collect();
    let has = |v: f64| values.iter().any(|s| (s - v).abs() <= 0.005 + 1e-9);
    for k in [1.0, 2.0] {
        let resonance = first_frequency() * 20.0 * 3.6 / k;
        assert!(
            has(resonance),
            "f0 D/{k} = {resonance} km/h not in {values:?}"
        );
        // A quarter step is left out only where a regular speed lies
        // within a tenth of a step (2 km/h) of it.
        for q in [-10.0, -5.0, 5.0, 10.0] {
            let v = resonance + q;
            let near = values.iter().any(|s| (s - v).abs() < 2.0);
            if v <= 360.0 {
                assert!(has(v) || near, "{v} km/h not in {values:?}");
            }
        }
    }
    assert!(has(360.0) && has(144.0), "{values:?}");
    // f₀·D/3 = 119.96 km/h is below the 144 km/h start: not run.
    assert!(!values.iter().any(|&v| v < 144.0), "{values:?}");
    assert!(values.windows(2).all(|w| w[1] > w[0]), "{values:?}");
    let listed: Vec<f64> = summary["trains"][0]["resonance_speeds_km_h"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(listed.len(), 2, "{listed:?}; {stderr}");
}

/// Line speed 200 km/h, speeds 200 to 240 km/h (= 1.2 × 200): HSLM-A5 is
/// near its second resonance f₀·22/2 = 197.9 km/h at 200 km/h (5.8 m/s² on
/// the golden grid) and fails the 3.5 m/s² ballasted limit; HSLM-A1 runs
/// between its resonances (179.9 and 359.9 km/h, 1.3 to 1.9 m/s²) and
/// passes. Each gets its verdict in summary.json and in the printed table,
/// the overall verdict fails and the command exits 3, with `--quiet` too;
/// A1 alone passes and exits 0.
#[test]
fn each_train_has_a_verdict_and_a_failed_check_exits_3() {
    let scratch = Scratch::new("resonance_verdict", "verdicts");
    let scene = |trains: &str| {
        format!(
            "name: verdict\n{BRIDGE}vehicles: [{{type: hslm, model: A1, speed: 200 km/h}}]
study: {{type: resonance_check, trains: [{trains}], line_speed: 200 km/h, speeds: {{from: 200 km/h, step: 20 km/h}}}}
"
        )
    };
    let (code, stderr, csv, summary) = run_check(&scratch, "both", &scene("A1, A5"), false);
    assert_eq!(code, EXIT_CHECK_FAILED, "{stderr}");
    assert_eq!(km_h_column(&csv, "HSLM-A1"), ["200", "220", "240"]);
    assert_eq!(summary["passes"], false);
    assert_eq!(summary["max_speed_km_h"], 240.0);
    assert_eq!(summary["failing_trains"], serde_json::json!(["HSLM-A5"]));
    let trains = summary["trains"].as_array().unwrap();
    assert_eq!(trains[0]["train"], "HSLM-A1");
    assert_eq!(trains[0]["passes"], true);
    assert_eq!(trains[1]["train"], "HSLM-A5");
    assert_eq!(trains[1]["passes"], false);
    let a5 = &trains[1]["max_acceleration"];
    assert!(a5["value"].as_f64().unwrap() > 3.5, "{a5}");
    assert!(trains[0]["max_acceleration"]["value"].as_f64().unwrap() < 3.5);
    let row = |train: &str| {
        stderr
            .lines()
            .find(|l| l.starts_with(train))
            .unwrap_or_else(|| panic!("no {train} row: {stderr}"))
            .to_owned()
    };
    assert!(row("HSLM-A1 ").ends_with("pass"), "{stderr}");
    assert!(row("HSLM-A5 ").ends_with("FAIL"), "{stderr}");
    assert!(
        stderr.contains("FAILS (HSLM-A5 above 3.5 m/s^2)"),
        "{stderr}"
    );
    let (code, _, _, _) = run_check(&scratch, "quiet", &scene("A1, A5"), true);
    assert_eq!(code, EXIT_CHECK_FAILED);
    let (code, stderr, _, summary) = run_check(&scratch, "a1", &scene("A1"), false);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(summary["passes"], true);
    assert!(stderr.contains("check PASSES"), "{stderr}");
}

/// EN 1991-2:2003 6.4.6.3.1(3), eq. (6.13): Δζ = (0.0187 L − 0.00064 L²) /
/// (1 − 0.0441 L − 0.0044 L² + 0.000255 L³) %. By hand: L = 10 m,
/// 0.123 / 0.374 = 0.328877 %; L = 20 m, 0.118 / 0.398 = 0.296482 %. The
/// check with `additional_damping: true` reports Δζ and runs exactly as
/// the same check without it on a bridge damped ζ + Δζ = 1.296482 %
/// (eq. 6.14): same peaks to 1e-9.
#[test]
fn the_additional_damping_is_en_1991_2_eq_6_13() {
    let scratch = Scratch::new("resonance_verdict", "damping");
    let study = "study: {type: resonance_check, trains: [A1], line_speed: 150 km/h, \
                 speeds: {from: 170 km/h, step: 10 km/h}";
    let scene = |span: f64, ratio: &str, extra: bool| {
        format!(
            "name: d\nbridge:\n  type: beam\n  spans: [{span}]\n  bending_stiffness: 2.43e10\n  \
             mass_per_length: 15000.0\n  modes: {{max_frequency: 40.0}}\n  \
             damping: {{type: modal, ratio: {ratio}}}\n\
             vehicles: [{{type: hslm, model: A1, speed: 180 km/h}}]\n{study}, additional_damping: {extra}}}\n"
        )
    };
    for (span, percent) in [(10.0, 0.123 / 0.374), (20.0, 0.118 / 0.398)] {
        let name = format!("l{span}");
        let (_, stderr, _, summary) = run_check(&scratch, &name, &scene(span, "0.01", true), true);
        let taken = &summary["additional_damping"];
        assert_eq!(taken["span_m"], span, "{stderr}");
        let got = taken["additional_percent"].as_f64().unwrap();
        assert!(
            (got - percent).abs() < 1e-12,
            "L = {span}: {got} % vs {percent} %"
        );
    }
    // L = 20 m: with Δζ against ζ + Δζ given directly.
    let (_, _, with, _) = run_check(&scratch, "with", &scene(20.0, "0.01", true), true);
    let total = format!("{}", 0.01 + 0.118 / 0.398 / 100.0);
    let (_, _, direct, _) = run_check(&scratch, "direct", &scene(20.0, &total, false), true);
    let (_, _, without, _) = run_check(&scratch, "without", &scene(20.0, "0.01", false), true);
    let peaks = |csv: &str| -> Vec<f64> {
        csv.lines()
            .skip(1)
            .map(|l| l.split(',').nth(5).unwrap().parse().unwrap())
            .collect()
    };
    let (with, direct, without) = (peaks(&with), peaks(&direct), peaks(&without));
    assert_eq!(with.len(), direct.len());
    for (a, b) in with.iter().zip(&direct) {
        assert!((a - b).abs() <= 1e-9 * b, "{with:?} vs {direct:?}");
    }
    // More damping, lower peaks (A1 resonates at f₀·18/2 = 179.9 km/h).
    assert!(
        with.iter().zip(&without).all(|(a, b)| a < b),
        "{with:?} vs {without:?}"
    );
}

/// `additional_damping` on a two-span bridge is refused, located, exit 2.
#[test]
fn the_additional_damping_needs_one_span() {
    let scratch = Scratch::new("resonance_verdict", "two_spans");
    let scene = "name: two
bridge:
  type: beam
  spans: [20.0, 20.0]
  bending_stiffness: 2.43e10
  mass_per_length: 15000.0
  modes: {max_frequency: 40.0}
  damping: {type: modal, ratio: 0.01}
vehicles: [{type: hslm, model: A1, speed: 180 km/h}]
study:
  type: resonance_check
  line_speed: 300 km/h
  additional_damping: true
";
    std::fs::write(scratch.path("two.yaml"), scene).unwrap();
    let out = vbi(&["check", "two.yaml"], scratch.dir());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("two.yaml:13:"), "{stderr}");
    assert!(stderr.contains("single span"), "{stderr}");
}
