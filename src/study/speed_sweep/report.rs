//! A speed sweep's outputs: study.csv, the three plots, resolved.yaml and
//! summary.json (last: its presence means the results are complete).

use std::path::Path;

use serde::Serialize;

use super::{DafSource, SweepResults};
use crate::report::km_h;
use crate::report::plot::{Band, Series, category_heat_map, line_chart_with_bands};
use crate::report::{self, write_atomic};
use crate::run::RunError;
use crate::scene::Scenario;

const DAF_LABEL: &str = "DAF = max |w dynamic| / max |w static|";
const SPEED_LABEL: &str = "speed (km/h)";

/// DAF statistics of one surface at the sweep's span and girder line.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RoughnessDaf {
    /// Surface label.
    pub roughness: String,
    /// Runs per speed (samples; 1 for a deterministic surface).
    pub runs: usize,
    /// Seeds of the samples (empty for a deterministic surface).
    pub seeds: Vec<u64>,
    /// Mean DAF over the samples at each speed (null where undefined).
    pub mean_daf: Vec<Option<f64>>,
    /// 95 % interval of the mean DAF over the `runs` samples at each speed,
    /// lower end ([`crate::study::statistics::nonnegative_mean_interval`]:
    /// x̄ / e^{t s/(x̄√n)}, never below 0); null with one run (nothing
    /// sampled) or where a sample has no DAF.
    pub mean_daf_low: Vec<Option<f64>>,
    /// Upper end of that interval (x̄ · e^{t s/(x̄√n)}; both ends the DAF
    /// where every sample gives the same, as a moving force over any
    /// roughness); null as the lower end.
    pub mean_daf_high: Vec<Option<f64>>,
    /// Largest DAF over the samples at each speed (null where undefined).
    pub max_daf: Vec<Option<f64>>,
}

/// The largest DAF of the sweep and where it occurred.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct LargestDaf {
    /// The DAF.
    pub daf: f64,
    /// Its column in study.csv.
    pub column: String,
    /// Where on the bridge.
    pub location: DafSource,
    /// Surface label.
    pub roughness: String,
    /// Sample number from 1.
    pub sample: usize,
    /// Seed of the random profile.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Speed, m/s.
    pub speed_m_s: f64,
    /// Speed, km/h.
    pub speed_km_h: f64,
}

/// summary.json of a speed sweep.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SweepSummary {
    /// Study type.
    pub study: &'static str,
    /// Scenario name.
    pub scenario: String,
    /// vbi version.
    pub vbi_version: &'static str,
    /// Wall time of all points, s.
    pub wall_time: f64,
    /// Number of runs.
    pub points: usize,
    /// Speeds, m/s.
    pub speeds_m_s: Vec<f64>,
    /// Speeds, km/h.
    pub speeds_km_h: Vec<f64>,
    /// Surface labels.
    pub roughness: Vec<String>,
    /// Samples per random surface.
    pub samples: usize,
    /// Span of the per-surface statistics, from 1.
    pub span: usize,
    /// Girder line of the per-surface statistics, from 1.
    pub girder: usize,
    /// Per surface, the DAF at the middle of `span` on `girder` at each speed.
    pub daf_by_roughness: Vec<RoughnessDaf>,
    /// The largest DAF over every column and point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub largest_daf: Option<LargestDaf>,
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

impl SweepSummary {
    /// The summary of `results` for the scene `name`.
    pub fn new(name: &str, results: &SweepResults) -> Self {
        let column = results.span_column(results.span, results.girder);
        let daf_by_roughness = (0..results.roughness.len())
            .map(|r| {
                let (mean, max) = results.daf_statistics(r, column);
                let intervals = results.daf_mean_intervals(r, column);
                RoughnessDaf {
                    roughness: results.roughness[r].clone(),
                    runs: results.runs[r],
                    seeds: results.seeds[r].clone(),
                    mean_daf: mean.into_iter().map(finite).collect(),
                    mean_daf_low: intervals.iter().map(|i| i.map(|(low, _)| low)).collect(),
                    mean_daf_high: intervals
                        .iter()
                        .map(|i| i.and_then(|(_, high)| high))
                        .collect(),
                    max_daf: max.into_iter().map(finite).collect(),
                }
            })
            .collect();
        let largest_daf = results.largest_daf().map(|(p, c, daf)| {
            let point = &results.points[p];
            LargestDaf {
                daf,
                column: results.daf_columns[c].clone(),
                location: results.daf_sources[c].clone(),
                roughness: results.roughness[point.roughness].clone(),
                sample: point.sample,
                seed: point.seed,
                speed_m_s: point.speed,
                speed_km_h: km_h(point.speed),
            }
        });
        Self {
            study: "speed_sweep",
            scenario: name.to_string(),
            vbi_version: env!("CARGO_PKG_VERSION"),
            wall_time: results.wall_time,
            points: results.points.len(),
            speeds_m_s: results.speeds.clone(),
            speeds_km_h: results.speeds.iter().map(|&v| km_h(v)).collect(),
            roughness: results.roughness.clone(),
            samples: results.samples,
            span: results.span,
            girder: results.girder,
            daf_by_roughness,
            largest_daf,
        }
    }
}

/// " (mean of n samples)" when a surface has several.
fn mean_note(runs: usize) -> String {
    if runs > 1 {
        format!(" (mean of {runs} samples)")
    } else {
        String::new()
    }
}

/// The lower and upper ends of [`SweepResults::daf_mean_intervals`] as
/// band values (NaN where there is none: no band there).
fn band_ends(results: &SweepResults, roughness: usize, column: usize) -> (Vec<f64>, Vec<f64>) {
    results
        .daf_mean_intervals(roughness, column)
        .into_iter()
        .map(|i| match i {
            Some((low, Some(high))) => (low, high),
            _ => (f64::NAN, f64::NAN),
        })
        .unzip()
}

/// The title's note of the bands, where there are any.
fn band_note(banded: bool) -> &'static str {
    if banded {
        "; band: 95 % interval of the mean"
    } else {
        ""
    }
}

/// daf_speed.png (Figs. 12–13): DAF against speed at the middle of the
/// sweep's span, one line per girder line (a beam: per displacement record,
/// or the span middle if it has none), on the first surface.
fn plot_daf_speed(
    path: &Path,
    name: &str,
    girder_lines: &[f64],
    results: &SweepResults,
) -> Result<(), RunError> {
    let km_h: Vec<f64> = results.speeds.iter().map(|&v| km_h(v)).collect();
    let records: Vec<usize> = (0..results.daf_sources.len())
        .filter(|&c| matches!(results.daf_sources[c], DafSource::Record { .. }))
        .collect();
    let by_record = !results.plate && !records.is_empty();
    let columns: Vec<(usize, String)> = if by_record {
        records
            .into_iter()
            .map(|c| match &results.daf_sources[c] {
                DafSource::Record { name } => (c, name.clone()),
                DafSource::SpanMiddle { .. } => unreachable!("filtered to records"),
            })
            .collect()
    } else {
        (1..=results.girder_lines)
            .map(|g| {
                // The legend says where the line is across the deck.
                let at = girder_lines
                    .get(g - 1)
                    .map(|y| format!(" (y = {y:.3} m)"))
                    .unwrap_or_default();
                (
                    results.span_column(results.span, g),
                    format!("girder {g}{at}"),
                )
            })
            .collect()
    };
    let means: Vec<Vec<f64>> = columns
        .iter()
        .map(|(c, _)| results.daf_statistics(0, *c).0)
        .collect();
    let series: Vec<Series> = columns
        .iter()
        .zip(&means)
        .map(|((_, label), y)| Series { label, x: &km_h, y })
        .collect();
    // Several samples: each line's 95 % interval of the mean shaded.
    let banded = results.runs[0] > 1;
    let ends: Vec<(Vec<f64>, Vec<f64>)> = columns
        .iter()
        .map(|(c, _)| band_ends(results, 0, *c))
        .collect();
    let bands: Vec<Option<Band>> = ends
        .iter()
        .map(|(low, high)| banded.then_some(Band { low, high }))
        .collect();
    let at = if by_record {
        "DAF per displacement record".to_string()
    } else {
        format!("DAF at mid-span {}", results.span)
    };
    let title = format!(
        "{name}: {at}, {}{}{}",
        results.roughness[0],
        mean_note(results.runs[0]),
        band_note(banded)
    );
    line_chart_with_bands(path, &title, SPEED_LABEL, DAF_LABEL, &series, &bands)?;
    Ok(())
}

/// daf_speed_roughness.png (Fig. 17) and daf_map.png: the DAF at the
/// sweep's span and girder line against speed, per surface (mean over
/// samples).
fn plot_roughness(out: &Path, name: &str, results: &SweepResults) -> Result<(), RunError> {
    let km_h: Vec<f64> = results.speeds.iter().map(|&v| km_h(v)).collect();
    let column = results.span_column(results.span, results.girder);
    let means: Vec<Vec<f64>> = (0..results.roughness.len())
        .map(|r| results.daf_statistics(r, column).0)
        .collect();
    let labels: Vec<String> = results
        .roughness
        .iter()
        .zip(&results.runs)
        .map(|(label, &runs)| format!("{label}{}", mean_note(runs)))
        .collect();
    let series: Vec<Series> = labels
        .iter()
        .zip(&means)
        .map(|(label, y)| Series { label, x: &km_h, y })
        .collect();
    // A sampled surface's line has its 95 % interval of the mean shaded.
    let ends: Vec<(Vec<f64>, Vec<f64>)> = (0..results.roughness.len())
        .map(|r| band_ends(results, r, column))
        .collect();
    let bands: Vec<Option<Band>> = ends
        .iter()
        .zip(&results.runs)
        .map(|((low, high), &runs)| (runs > 1).then_some(Band { low, high }))
        .collect();
    let banded = bands.iter().any(Option::is_some);
    let at = format!("mid-span {}, girder {}", results.span, results.girder);
    line_chart_with_bands(
        &out.join("daf_speed_roughness.png"),
        &format!("{name}: DAF at {at} by road surface{}", band_note(banded)),
        SPEED_LABEL,
        DAF_LABEL,
        &series,
        &bands,
    )?;
    // The map's rows are the surfaces in sweep order, named on the axis.
    let rows = results.roughness.len();
    let mut values = vec![f64::NAN; km_h.len() * rows];
    for (r, mean) in means.iter().enumerate() {
        for (i, &v) in mean.iter().enumerate() {
            values[i * rows + r] = v;
        }
    }
    category_heat_map(
        &out.join("daf_map.png"),
        &format!("{name}: DAF at {at}"),
        SPEED_LABEL,
        "surface",
        &km_h,
        &results.roughness,
        &values,
        "DAF (mean over samples)",
    )?;
    Ok(())
}

/// Writes `study.csv`, `daf_speed.png`, `daf_speed_roughness.png`,
/// `daf_map.png`, `resolved.yaml` and, last, `summary.json` into `out`.
pub fn write(out: &Path, scenario: &Scenario, results: &SweepResults) -> Result<(), RunError> {
    crate::report::folder::create_out(out)?;
    write_atomic(&out.join("study.csv"), &results.to_csv())?;
    plot_daf_speed(
        &out.join("daf_speed.png"),
        &scenario.name,
        &scenario.bridge.girder_lines(),
        results,
    )?;
    plot_roughness(out, &scenario.name, results)?;
    write_atomic(
        &out.join("resolved.yaml"),
        crate::report::folder::resolved_yaml(scenario).as_bytes(),
    )?;
    let summary = SweepSummary::new(&scenario.name, results);
    let text = crate::study::summary_json(&summary, results.advice(scenario));
    report::write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}
