//! Golden regression: every scenario in `scenarios/` is run and its summary and
//! a decimated time history (a study: its summary and its table of points)
//! are compared with the insta snapshots in `golden/`.
//!
//! Scenarios are discovered with `read_dir`, so a new file in `scenarios/` is
//! picked up automatically (its first run writes `golden/<stem>-*.snap.new`
//! and fails until the snapshot is accepted).
//!
//! Rounding, so that the snapshots move only when a result really moves:
//! - history: every column (time, each recorded quantity, each static
//!   crossing response) is rounded to a quantum of 6 significant digits of
//!   that column's largest |value|: `10^(floor(log10(max|col|)) - 5)`. A value
//!   at round-off level (1e-19 in a column that peaks at 1e-3) prints as 0.
//! - summary: `run.wall_time` is removed (and an EMBS comparison's solve
//!   times and speed-up). Each extreme's `value` is rounded
//!   with the same quantum as its column (the dynamic or the static column),
//!   its `time` to 6 significant digits of the run's end time and its
//!   `position` to 6 significant digits of the bridge length (so 1e-15 m at
//!   the entrance prints as 0). An extreme whose value rounds to 0 is
//!   round-off noise (or exactly 0, where any later noise would move it), so
//!   its `time` and `position` are replaced by a note instead of being
//!   compared. Every other float (DAF, frequencies, time step, ...) is
//!   rounded to 6 significant digits of its own; integers are kept as they
//!   are.
//!
//! Update after an intended change of results:
//! `INSTA_UPDATE=always cargo test --release --test golden` (or `cargo insta
//! review`), then review the diff of `golden/` before committing.

use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::support::max_abs_finite;
use vbi::execute::Results;
use vbi::record::History;
use vbi::run::Outcome;
use vbi::study::monte_carlo::MonteCarloResults;
use vbi::study::separation_map::SeparationMap;
use vbi::study::speed_sweep::SweepResults;

/// Significant digits kept in the snapshots.
const DIGITS: i32 = 6;
/// Written for the time and position of an extreme whose value rounds to 0.
const NOISE: &str = "not compared: the value rounds to 0";
/// Rows of the decimated history (the first and last sample included).
const HISTORY_ROWS: usize = 41;

fn scenarios_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios")
}

/// Every `*.yaml` / `*.yml` file in `scenarios/`, sorted by name.
fn scenario_files() -> Vec<PathBuf> {
    let dir = scenarios_dir();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| {
            p.is_file()
                && p.extension()
                    .is_some_and(|ext| ext == "yaml" || ext == "yml")
        })
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no scenarios found in {}", dir.display());
    files
}

fn stem(path: &Path) -> String {
    path.file_stem()
        .expect("scenario file has a name")
        .to_string_lossy()
        .into_owned()
}

fn run(path: &Path) -> Result<Outcome, String> {
    let loaded = vbi::plan::load_file(path).map_err(|e| format!("load failed: {e}"))?;
    vbi::run::simulate(loaded, &mut |_, _| {}).map_err(|e| format!("run failed: {e}"))
}

// ---------------------------------------------------------------------------
// Rounding
// ---------------------------------------------------------------------------

/// Decimal exponent of the quantum for 6 significant digits of `scale`
/// (`None` when the scale is zero or not finite: everything prints as 0).
fn quantum_exponent(scale: f64) -> Option<i32> {
    let scale = scale.abs();
    (scale.is_finite() && scale > 0.0).then(|| scale.log10().floor() as i32 - (DIGITS - 1))
}

/// `value` rounded to a multiple of `10^exp`, as an exact decimal string
/// (no binary round-off in the printed digits, never "-0").
fn quantise(value: f64, exp: Option<i32>) -> String {
    if !value.is_finite() {
        return format!("{value}");
    }
    let Some(exp) = exp else {
        return if value == 0.0 {
            "0".into()
        } else {
            // Only reachable if the scale was not the column's maximum.
            format!("{:.*e}", (DIGITS - 1) as usize, value)
        };
    };
    let mantissa = (value / 10f64.powi(exp)).round();
    if mantissa.abs() >= 1e15 {
        // A value far above the scale: keep 6 significant digits of its own.
        return format!("{:.*e}", (DIGITS - 1) as usize, value);
    }
    let mantissa = mantissa as i64;
    let sign = if mantissa < 0 { "-" } else { "" };
    let digits = mantissa.unsigned_abs().to_string();
    if exp >= 0 {
        if mantissa == 0 {
            return "0".into();
        }
        return format!("{sign}{digits}{}", "0".repeat(exp as usize));
    }
    let decimals = (-exp) as usize;
    let digits = format!("{digits:0>width$}", width = decimals + 1);
    let (int, frac) = digits.split_at(digits.len() - decimals);
    format!("{sign}{int}.{frac}")
}

/// `value` rounded to 6 significant digits of its own magnitude.
fn significant(value: f64) -> f64 {
    if value.is_finite() && value != 0.0 {
        format!("{:.*e}", (DIGITS - 1) as usize, value)
            .parse()
            .expect("formatted float parses")
    } else {
        value
    }
}

fn json_number(text: &str) -> Value {
    let f: f64 = text.parse().expect("quantised value parses");
    serde_json::Number::from_f64(f).map_or_else(|| Value::String(text.into()), Value::Number)
}

/// Rounds every float in `value` to 6 significant digits of its own.
fn round_all(value: &mut Value) {
    match value {
        Value::Number(n) if n.is_f64() => {
            let f = significant(n.as_f64().expect("f64"));
            *value = serde_json::Number::from_f64(f).map_or(Value::Null, Value::Number);
        }
        Value::Array(items) => items.iter_mut().for_each(round_all),
        Value::Object(map) => map.values_mut().for_each(round_all),
        _ => {}
    }
}

/// The summary as pretty JSON, without `run.wall_time`, rounded (see the
/// module documentation).
fn summary_snapshot(outcome: &Outcome) -> String {
    let mut summary = serde_json::to_value(&outcome.summary).expect("summary serialises");
    let run = summary
        .get_mut("run")
        .and_then(Value::as_object_mut)
        .expect("summary has a `run` object");
    assert!(
        run.remove("wall_time").is_some(),
        "summary.run.wall_time is gone: update the golden harness"
    );
    // An EMBS comparison's solve times and their ratio are wall times too.
    if let Some(comparison) = summary
        .pointer_mut("/embs/comparison")
        .and_then(Value::as_object_mut)
    {
        for key in ["embs_solve_time", "coupled_solve_time", "speed_up"] {
            assert!(
                comparison.remove(key).is_some(),
                "summary.embs.comparison.{key} is gone: update the golden harness"
            );
        }
    }
    round_all(&mut summary);
    // Extremes: value, time and position against their scales, from the
    // unrounded numbers (no double rounding).
    let time_exp = quantum_exponent(outcome.model.end_time());
    let position_exp = quantum_exponent(outcome.model.bridge.length);
    let quantities = summary
        .get_mut("quantities")
        .and_then(Value::as_array_mut)
        .expect("summary has a `quantities` list");
    let columns = &outcome.history.columns;
    assert_eq!(quantities.len(), columns.len(), "one quantity per column");
    for ((json, typed), column) in quantities
        .iter_mut()
        .zip(&outcome.summary.quantities)
        .zip(columns)
    {
        let dynamic = quantum_exponent(max_abs_finite(&column.values));
        let fixed = column
            .static_values
            .as_deref()
            .and_then(|s| quantum_exponent(max_abs_finite(s)));
        for (key, extreme, value_exp) in [
            ("max", Some(&typed.max), dynamic),
            ("min", Some(&typed.min), dynamic),
            ("largest_magnitude", Some(&typed.max_abs), dynamic),
            (
                "static_largest_magnitude",
                typed.static_max_abs.as_ref(),
                fixed,
            ),
        ] {
            let Some(extreme) = extreme else { continue };
            let value = quantise(extreme.value, value_exp);
            let noise = value.parse::<f64>().is_ok_and(|v| v == 0.0);
            let quantised = |x: f64, exp| {
                if noise {
                    // Where a round-off-level extreme happens is noise too.
                    Value::from(NOISE)
                } else {
                    json_number(&quantise(x, exp))
                }
            };
            json[key] = serde_json::json!({
                "value": json_number(&value),
                "time": quantised(extreme.time, time_exp),
                "position": quantised(extreme.position, position_exp),
            });
        }
    }
    serde_json::to_string_pretty(&summary).expect("summary serialises") + "\n"
}

/// About 40 evenly spaced rows of every column, rounded per column, as an
/// aligned text table.
fn history_snapshot(history: &History) -> String {
    let n = history.time.len();
    assert!(n > 0, "empty history");
    let mut table: Vec<(String, &[f64])> = vec![("time [s]".into(), &history.time)];
    for c in &history.columns {
        assert_eq!(c.values.len(), n, "column {} has the wrong length", c.name);
        table.push((format!("{} [{}]", c.name, c.unit), &c.values));
        if let Some(s) = &c.static_values {
            assert_eq!(
                s.len(),
                n,
                "static column of {} has the wrong length",
                c.name
            );
            table.push((format!("{}_static [{}]", c.name, c.unit), s));
        }
    }
    let rows = HISTORY_ROWS.min(n);
    let span = (rows - 1).max(1);
    let picks: Vec<usize> = (0..rows).map(|k| k * (n - 1) / span).collect();
    let mut cells: Vec<Vec<String>> = Vec::with_capacity(table.len());
    for (name, values) in &table {
        let exp = quantum_exponent(max_abs_finite(values));
        let mut col = vec![
            name.clone(),
            exp.map_or_else(|| "0".into(), |e| format!("1e{e}")),
        ];
        col.extend(picks.iter().map(|&i| quantise(values[i], exp)));
        cells.push(col);
    }
    let widths: Vec<usize> = cells
        .iter()
        .map(|col| col.iter().map(|s| s.chars().count()).max().unwrap_or(0))
        .collect();
    let mut out = format!(
        "# {rows} of {n} samples (index k*{}/{span}, k = 0..{}); each column rounded to a \
         multiple of its quantum = 6 significant digits of the column's max |value|\n",
        n - 1,
        rows - 1,
    );
    for r in 0..cells[0].len() {
        let line: Vec<String> = cells
            .iter()
            .zip(&widths)
            .map(|(col, &w)| format!("{:>w$}", col[r]))
            .collect();
        let line = line.join("  ");
        if r == 1 {
            out.push_str(&format!("{}  <- quantum\n", line.trim_end()));
        } else {
            out.push_str(line.trim_end());
            out.push('\n');
        }
    }
    out
}

fn insta_settings() -> insta::Settings {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../golden");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings
}

/// Runs `f` and turns a panic (a failed snapshot assertion, a crashed run)
/// into its message, so that one failure does not hide the others.
/// Runs the study of a scenario that has one (None for plain scenes) and
/// gives its (summary, table) snapshots.
fn study(path: &Path) -> Option<Result<(String, String), String>> {
    let loaded = vbi::plan::load_file(path).ok()?;
    loaded.scenario.study.as_ref()?;
    Some(match catch(|| vbi::execute::execute(loaded, &|_, _| {})) {
        Ok(Ok(Results::SeparationMap(map))) => Ok(study_snapshots(&map)),
        Ok(Ok(Results::SpeedSweep(sweep))) => Ok(sweep_snapshots(&sweep)),
        Ok(Ok(Results::MonteCarlo(mc))) => Ok(monte_carlo_snapshots(&mc)),
        Ok(Ok(Results::ResonanceCheck(check))) => Ok(resonance_snapshots(&check)),
        Ok(Ok(Results::Scene(_))) => Err("a study scenario ran as a scene".into()),
        Ok(Err(e)) => Err(format!("study failed: {e}")),
        Err(e) => Err(e),
    })
}

/// A resonance check as (its governing runs and verdict; every run's peak
/// displacement and acceleration with where and the time step), each value
/// rounded to 6 significant digits.
fn resonance_snapshots(check: &vbi::study::resonance::ResonanceResults) -> (String, String) {
    let number = |v: f64| significant(v).to_string();
    let summary = check.summary("golden");
    let governing = |g: &Option<vbi::study::resonance::Governing>| {
        g.as_ref().map_or("-".to_string(), |g| {
            format!(
                "{} at {} km/h: {} at x = {} m",
                g.train,
                number(g.speed_km_h),
                number(g.value),
                number(g.x)
            )
        })
    };
    let text = format!(
        "runs: {}\ndeck: {} (limit {} m/s^2)\nmax_frequency_hz: {}\nline_speed_m_s: {}\n\
         governing acceleration: {}\ngoverning displacement: {}\npasses: {}\n",
        summary.runs,
        summary.deck,
        summary.acceleration_limit,
        number(summary.max_frequency),
        number(summary.line_speed_m_s),
        governing(&summary.governing_acceleration),
        governing(&summary.governing_displacement),
        summary.passes
    );
    // The verdict per train (EN 1991-2 6.4.6), with its resonance speeds.
    let mut text = text;
    for v in &summary.trains {
        let resonances: Vec<String> = v.resonance_speeds_km_h.iter().map(|&r| number(r)).collect();
        text.push_str(&format!(
            "{}: {} (resonances [{}] km/h; {} runs; largest acceleration {})\n",
            v.train,
            if v.passes { "pass" } else { "FAIL" },
            resonances.join(", "),
            v.runs,
            governing(&v.max_acceleration)
        ));
    }
    let mut table = String::from(
        "train speed_km_h max_displacement_m at_m max_acceleration_m/s^2 at_m time_step_s\n",
    );
    for p in &check.points {
        table.push_str(&format!(
            "{} {} {} {} {} {} {}\n",
            check.trains[p.train],
            number(p.speed * 3.6),
            number(p.max_displacement),
            number(p.displacement_at),
            number(p.max_acceleration),
            number(p.acceleration_at),
            number(p.time_step)
        ));
    }
    (text, table)
}

/// A speed sweep as (its surfaces, seeds and the mean DAF at its span and
/// girder line per surface and speed; every point's DAFs and largest forces),
/// each value rounded to 6 significant digits.
fn sweep_snapshots(sweep: &SweepResults) -> (String, String) {
    let number = |v: Option<f64>| v.map_or("-".to_string(), |v| significant(v).to_string());
    let mut summary = format!(
        "points: {}\nspan: {}\ngirder: {}\nspeeds_m_s: {}\n",
        sweep.points.len(),
        sweep.span,
        sweep.girder,
        sweep
            .speeds
            .iter()
            .map(|&v| number(Some(v)))
            .collect::<Vec<_>>()
            .join(" ")
    );
    let column = sweep.span_column(sweep.span, sweep.girder);
    for (r, label) in sweep.roughness.iter().enumerate() {
        let (mean, _) = sweep.daf_statistics(r, column);
        summary.push_str(&format!(
            "{label} (runs {}, seeds {:?}) mean DAF: {}\n",
            sweep.runs[r],
            sweep.seeds[r],
            mean.iter()
                .map(|&v| number(Some(v)))
                .collect::<Vec<_>>()
                .join(" ")
        ));
    }
    let mut table = format!(
        "roughness sample seed speed_m_s {} {}\n",
        sweep.daf_columns.join(" "),
        sweep
            .force_records
            .iter()
            .map(|n| format!("max_{n}_N"))
            .collect::<Vec<_>>()
            .join(" ")
    );
    for p in &sweep.points {
        let dafs: Vec<String> = p.dafs.iter().map(|&d| number(d)).collect();
        let forces: Vec<String> = p.max_forces.iter().map(|&f| number(Some(f))).collect();
        table.push_str(&format!(
            "{} {} {} {} {} {}\n",
            sweep.roughness[p.roughness],
            p.sample,
            p.seed.map_or("-".to_string(), |s| s.to_string()),
            number(Some(p.speed)),
            dafs.join(" "),
            forces.join(" ")
        ));
    }
    (summary, table)
}

/// A Monte Carlo study as (per case and wheel the probability of separation
/// with its interval and the expected largest gap with its standard error
/// and interval, `[0, ∞)` where the samples do not bound it; every sample's seed,
/// separation and largest gap, then each record's mean and standard
/// deviation at 11 evenly spaced steps of each case), rounded to 6
/// significant digits.
fn monte_carlo_snapshots(mc: &MonteCarloResults) -> (String, String) {
    let mut summary = format!(
        "runs: {}\ncases: {}\nsamples: {}\nseed: {}\n",
        mc.sample_results.len(),
        mc.cases.len(),
        mc.samples,
        mc.seed
    );
    for c in 0..mc.cases.len() {
        for w in mc.wheel_statistics(c) {
            summary.push_str(&format!(
                "{} {} v{} w{}: separated {} p {} [{}, {}] E[max gap] {} ± {} [{}, {}\n",
                mc.labels[c],
                mc.speed(c)
                    .map_or("-".into(), |v| significant(v).to_string()),
                w.vehicle,
                w.wheel,
                w.separated,
                significant(w.probability),
                significant(w.probability_low),
                significant(w.probability_high),
                significant(w.expected_max_gap),
                significant(w.expected_max_gap_std_error),
                significant(w.expected_max_gap_low),
                w.expected_max_gap_high
                    .map_or("∞)".into(), |h| format!("{}]", significant(h))),
            ));
        }
    }
    let mut table = String::from("case sample seed separated max_gap\n");
    for r in &mc.sample_results {
        let wheels: Vec<String> = r
            .wheels
            .iter()
            .map(|w| format!("{} {}", w.separated, significant(w.max_gap)))
            .collect();
        table.push_str(&format!(
            "{} {} {} {}\n",
            r.case,
            r.sample,
            r.seed,
            wheels.join(" ")
        ));
    }
    for (c, m) in mc.envelopes.iter().enumerate() {
        let std = m.std_dev();
        let n = m.time.len();
        for k in 0..=10 {
            let i = k * (n - 1) / 10;
            let cells: Vec<String> = (0..m.names.len())
                .map(|r| {
                    let exp = quantum_exponent(max_abs_finite(&m.mean[r]));
                    let sexp = quantum_exponent(max_abs_finite(&std[r]));
                    format!(
                        "{}={} ±{}",
                        m.names[r],
                        quantise(m.mean[r][i], exp),
                        quantise(std[r][i], sexp)
                    )
                })
                .collect();
            table.push_str(&format!(
                "case {c} t {} {}\n",
                significant(m.time[i]),
                cells.join(" ")
            ));
        }
    }
    (summary, table)
}

/// A separation map as (the map drawn in text with its counts, a table of
/// every point rounded to 6 significant digits).
fn study_snapshots(map: &SeparationMap) -> (String, String) {
    let mut summary = format!(
        "points: {}\nseparated: {}\nrows: velocity ratio (top = first); columns: mass ratio (left = first); X = separated\n",
        map.points.len(),
        map.separated_count()
    );
    let columns = map.mass_ratios.len();
    for (i, a) in map.velocity_ratios.iter().enumerate() {
        let row: String = map.points[i * columns..(i + 1) * columns]
            .iter()
            .map(|p| if p.separated { 'X' } else { '.' })
            .collect();
        summary.push_str(&format!("{:>10} {row}\n", significant(*a)));
    }
    let gap_exp = quantum_exponent(map.points.iter().fold(0.0f64, |m, p| m.max(p.max_gap)));
    let force_exp = quantum_exponent(
        map.points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.min_contact_force.abs())),
    );
    let mut table = String::from(
        "velocity_ratio mass_ratio separated episodes first_loss_position max_gap min_contact_force\n",
    );
    for p in &map.points {
        table.push_str(&format!(
            "{} {} {} {} {} {} {}\n",
            significant(p.velocity_ratio),
            significant(p.mass_ratio),
            p.separated,
            p.episodes,
            p.first_loss_position
                .map(|x| significant(x).to_string())
                .unwrap_or_else(|| "-".into()),
            quantise(p.max_gap, gap_exp),
            quantise(p.min_contact_force, force_exp),
        ));
    }
    (summary, table)
}

fn catch<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).map_err(|payload| {
        payload
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
            .unwrap_or_else(|| "panicked".into())
    })
}

#[test]
fn golden_scenarios() {
    // INSTA_FORCE_PASS turns every mismatch into a pass: never a legitimate
    // way to run this test (to accept a change, update and review the diff).
    assert!(
        std::env::var_os("INSTA_FORCE_PASS").is_none(),
        "INSTA_FORCE_PASS is set: the golden comparison would pass whatever the results"
    );
    let files = scenario_files();
    let settings = insta_settings();
    let mut failures = Vec::new();
    for path in &files {
        let name = stem(path);
        if let Some(snapshots) = study(path) {
            let (summary, table) = match snapshots {
                Ok(snapshots) => snapshots,
                Err(e) => {
                    failures.push(format!("{name}: {e}"));
                    continue;
                }
            };
            settings.bind(|| {
                if let Err(e) =
                    catch(|| insta::assert_snapshot!(format!("{name}-summary"), summary))
                {
                    failures.push(format!("{name}-summary: {e}"));
                }
                if let Err(e) = catch(|| insta::assert_snapshot!(format!("{name}-history"), table))
                {
                    failures.push(format!("{name}-history: {e}"));
                }
            });
            continue;
        }
        let outcome = match catch(|| run(path)).and_then(|r| r) {
            Ok(outcome) => outcome,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let summary = summary_snapshot(&outcome);
        let history = history_snapshot(&outcome.history);
        settings.bind(|| {
            if let Err(e) = catch(|| insta::assert_snapshot!(format!("{name}-summary"), summary)) {
                failures.push(format!("{name}-summary: {e}"));
            }
            if let Err(e) = catch(|| insta::assert_snapshot!(format!("{name}-history"), history)) {
                failures.push(format!("{name}-history: {e}"));
            }
        });
    }
    // A snapshot without a scenario is stale (a renamed or removed scenario).
    let golden = Path::new(env!("CARGO_MANIFEST_DIR")).join("golden");
    let names: Vec<String> = files.iter().map(|p| stem(p)).collect();
    if let Ok(entries) = std::fs::read_dir(&golden) {
        for entry in entries.flatten() {
            let file = entry.file_name().to_string_lossy().into_owned();
            let Some(base) = file.strip_suffix(".snap") else {
                continue;
            };
            let scenario = base
                .strip_suffix("-summary")
                .or_else(|| base.strip_suffix("-history"));
            if !scenario.is_some_and(|s| names.iter().any(|n| n == s)) {
                failures.push(format!(
                    "golden/{file} belongs to no scenario in scenarios/: delete it"
                ));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} golden failure(s):\n  {}\n(review with `cargo insta review`, or accept all with \
         `INSTA_UPDATE=always cargo test --release --test golden`)",
        failures.len(),
        failures.join("\n  ")
    );
}

// ---------------------------------------------------------------------------
// Determinism
// ---------------------------------------------------------------------------

/// The scenario run repeatedly by the determinism tests: the richest one
/// (three spans, two vehicles, rough surface, Rayleigh damping).
const DETERMINISM_SCENARIO: &str = "three-span-two-vehicles.yaml";

fn bits(history: &History) -> Vec<(String, Vec<u64>)> {
    let mut out = vec![(
        "time".to_string(),
        history.time.iter().map(|v| v.to_bits()).collect(),
    )];
    for c in &history.columns {
        out.push((
            c.name.clone(),
            c.values.iter().map(|v| v.to_bits()).collect(),
        ));
        if let Some(s) = &c.static_values {
            out.push((
                format!("{}_static", c.name),
                s.iter().map(|v| v.to_bits()).collect(),
            ));
        }
    }
    out
}

fn assert_identical(a: &History, b: &History, what: &str) {
    let (a, b) = (bits(a), bits(b));
    assert_eq!(a.len(), b.len(), "{what}: different column counts");
    for ((name_a, va), (name_b, vb)) in a.iter().zip(&b) {
        assert_eq!(name_a, name_b, "{what}: different columns");
        assert_eq!(va.len(), vb.len(), "{what}: column {name_a} lengths differ");
        if let Some(i) = va.iter().zip(vb).position(|(x, y)| x != y) {
            panic!(
                "{what}: column {name_a} differs first at sample {i}: {:e} vs {:e}",
                f64::from_bits(va[i]),
                f64::from_bits(vb[i])
            );
        }
    }
}

fn determinism_scenario() -> PathBuf {
    let path = scenarios_dir().join(DETERMINISM_SCENARIO);
    assert!(
        path.is_file(),
        "{} is gone: point DETERMINISM_SCENARIO at another scenario",
        path.display()
    );
    path
}

#[test]
fn repeated_runs_are_bit_identical() {
    let path = determinism_scenario();
    let first = run(&path).expect("first run");
    let second = run(&path).expect("second run");
    assert_identical(&first.history, &second.history, "two sequential runs");
    let mut a = serde_json::to_value(&first.summary).expect("summary serialises");
    let mut b = serde_json::to_value(&second.summary).expect("summary serialises");
    a["run"]["wall_time"] = Value::Null;
    b["run"]["wall_time"] = Value::Null;
    assert_eq!(a, b, "two sequential runs: summaries differ");
}

#[test]
fn runs_on_different_threads_are_bit_identical() {
    let path = determinism_scenario();
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(|| run(&path));
        let b = s.spawn(|| run(&path));
        (
            a.join().expect("thread 1").expect("run on thread 1"),
            b.join().expect("thread 2").expect("run on thread 2"),
        )
    });
    assert_identical(&a.history, &b.history, "two concurrent runs");
}

#[test]
fn quantise_rounds_to_the_column_scale() {
    let e = quantum_exponent(1.234_567_89e-3);
    assert_eq!(e, Some(-8));
    assert_eq!(quantise(-1.234_567_89e-3, e), "-0.00123457");
    assert_eq!(quantise(1e-19, e), "0.00000000");
    assert_eq!(quantise(-1e-19, e), "0.00000000");
    assert_eq!(quantise(4.9e-9, e), "0.00000000");
    assert_eq!(quantise(5.1e-9, e), "0.00000001");
    let e = quantum_exponent(98_765_432.1);
    assert_eq!(e, Some(2));
    assert_eq!(quantise(98_765_432.1, e), "98765400");
    assert_eq!(quantise(-49.0, e), "0");
    assert_eq!(quantise(0.0, None), "0");
    assert_eq!(quantise(f64::NAN, e), "NaN");
    assert_eq!(significant(0.123_456_789), 0.123_457);
    assert_eq!(significant(-9.999_999e-7), -1e-6);
}
