//! A Monte Carlo study's outputs: study.csv (one row per sample),
//! separation.csv (per case and wheel: probability of separation and
//! expected largest gap with their 95 % intervals and the sample count,
//! [`crate::study::statistics`]), envelopes.csv (per case, mean,
//! standard deviation and mean ± 3σ of every record at every step),
//! envelope_<record>.png (the first case, a few samples in grey as in the
//! LCP separation paper's Fig. 7), with several speeds
//! separation_probability.png and expected_gap.png (Figs. 8 and 9, the
//! intervals shaded),
//! resolved.yaml and, last, summary.json.

use std::path::Path;

use serde::Serialize;

use super::MonteCarloResults;
use crate::report::plot::{Band, Series, line_chart_over_samples, line_chart_with_bands};
use crate::report::{clean, heading, km_h, number, write_atomic};
use crate::run::RunError;
use crate::scene::Scenario;
use crate::study::statistics::{nonnegative_mean_interval, wilson_interval};

/// Separation statistics of one wheel in one case.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct WheelStatistics {
    /// Vehicle number from 1.
    pub vehicle: usize,
    /// Wheel number from 1.
    pub wheel: usize,
    /// Samples in which the wheel lost contact.
    pub separated: usize,
    /// Estimated probability of separation, separated / samples.
    pub probability: f64,
    /// 95 % interval of the probability, lower end
    /// ([`wilson_interval`]: Wilson's score interval, Brown, Cai & DasGupta's
    /// end for 1 or 2 (3 above 50 samples) separations).
    pub probability_low: f64,
    /// 95 % interval of the probability, upper end (0.194 for none of 16).
    pub probability_high: f64,
    /// Mean over the samples of the largest gap, m (a sample that never
    /// separates counts 0).
    pub expected_max_gap: f64,
    /// Standard error of that mean, s/√n, m (s the sample standard deviation).
    pub expected_max_gap_std_error: f64,
    /// 95 % interval of the mean, lower end, m ([`nonnegative_mean_interval`]:
    /// x̄ / e^{t s/(x̄√n)}, never below 0; 0 when the samples do not bound it).
    pub expected_max_gap_low: f64,
    /// 95 % interval of the mean, upper end, m (x̄ · e^{t s/(x̄√n)}; `null`
    /// when the samples do not bound it: no sample separated, or one
    /// sample).
    pub expected_max_gap_high: Option<f64>,
}

/// One case of summary.json.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct CaseSummary {
    /// Surface label.
    pub roughness: String,
    /// Speed, m/s (`null`: several vehicles at their own speeds).
    pub speed_m_s: Option<f64>,
    /// Per wheel.
    pub wheels: Vec<WheelStatistics>,
}

/// summary.json of a Monte Carlo study.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MonteCarloSummary {
    /// Study type.
    pub study: &'static str,
    /// Scenario name.
    pub scenario: String,
    /// vbi version.
    pub vbi_version: &'static str,
    /// Wall time of all runs, s (summed over the parts when merged).
    pub wall_time: f64,
    /// Runs.
    pub runs: usize,
    /// Samples per case.
    pub samples: usize,
    /// Study seed.
    pub seed: u64,
    /// How the intervals are computed.
    pub intervals: &'static str,
    /// Per case.
    pub cases: Vec<CaseSummary>,
}

const INTERVALS: &str = "95 % intervals over the samples of each case. probability: Wilson score interval (Wilson 1927) with the Poisson lower end at 1 or 2 separations (3 above 50 samples) of Brown, Cai & DasGupta 2001 (upper end mirrored), [0, 0.194] for none of 16; expected largest gap: mean / and * exp(t s / (mean sqrt(n))), t the 97.5 % point of Student's t with n - 1 degrees of freedom (the delta-method interval of log mean, never below 0); upper end null (unbounded) when no sample separated";

impl MonteCarloResults {
    /// The speed of case `c`, m/s: swept, or the first vehicle's own.
    pub fn speed(&self, c: usize) -> Option<f64> {
        self.cases[c].speed.or(self.own_speed)
    }

    /// Per wheel separation statistics of case `c`, sums in sample order.
    pub fn wheel_statistics(&self, c: usize) -> Vec<WheelStatistics> {
        let n = self.samples;
        let rows = &self.sample_results[c * n..(c + 1) * n];
        let Some(first) = rows.first() else {
            return Vec::new();
        };
        (0..first.wheels.len())
            .map(|w| {
                let separated = rows.iter().filter(|r| r.wheels[w].separated).count();
                let (low, high) = wilson_interval(separated, n);
                let gaps: Vec<f64> = rows.iter().map(|r| r.wheels[w].max_gap).collect();
                let mean = gaps.iter().sum::<f64>() / n as f64;
                let std_error = if n > 1 {
                    let var =
                        gaps.iter().map(|g| (g - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0);
                    (var / n as f64).sqrt()
                } else {
                    0.0
                };
                let (gap_low, gap_high) = nonnegative_mean_interval(&gaps);
                WheelStatistics {
                    vehicle: first.wheels[w].vehicle,
                    wheel: first.wheels[w].wheel,
                    separated,
                    probability: separated as f64 / n as f64,
                    probability_low: low,
                    probability_high: high,
                    expected_max_gap: mean,
                    expected_max_gap_std_error: std_error,
                    expected_max_gap_low: gap_low,
                    expected_max_gap_high: gap_high,
                }
            })
            .collect()
    }

    /// The summary of the study of scene `name`.
    pub fn summary(&self, name: &str) -> MonteCarloSummary {
        MonteCarloSummary {
            study: "monte_carlo",
            scenario: name.to_string(),
            vbi_version: env!("CARGO_PKG_VERSION"),
            wall_time: self.wall_time,
            runs: self.sample_results.len(),
            samples: self.samples,
            seed: self.seed,
            intervals: INTERVALS,
            cases: (0..self.cases.len())
                .map(|c| CaseSummary {
                    roughness: self.labels[c].clone(),
                    speed_m_s: self.speed(c),
                    wheels: self.wheel_statistics(c),
                })
                .collect(),
        }
    }

    fn case_cells(&self, c: usize) -> [String; 3] {
        let speed = self.speed(c);
        [
            self.labels[c].clone(),
            speed.map(number).unwrap_or_default(),
            speed.map(|v| number(km_h(v))).unwrap_or_default(),
        ]
    }

    /// study.csv: one row per sample (flat order) with its seed, and per
    /// wheel whether it separated and its largest gap (`max_gap_vV_wW [m]`).
    pub fn samples_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        let mut header: Vec<String> =
            ["roughness", "speed [m/s]", "speed [km/h]", "sample", "seed"]
                .map(String::from)
                .to_vec();
        if let Some(first) = self.sample_results.first() {
            for w in &first.wheels {
                header.push(format!("separated_v{}_w{}", w.vehicle, w.wheel));
                header.push(format!("max_gap_v{}_w{} [m]", w.vehicle, w.wheel));
            }
        }
        out.write_record(&header).expect("writing to memory");
        for r in &self.sample_results {
            let mut row = self.case_cells(r.case).to_vec();
            row.push(r.sample.to_string());
            row.push(r.seed.to_string());
            for w in &r.wheels {
                row.push(w.separated.to_string());
                row.push(number(w.max_gap));
            }
            out.write_record(&row).expect("writing to memory");
        }
        out.into_inner().expect("writing to memory")
    }

    /// separation.csv: per case and wheel, the sample count and the
    /// statistics of [`WheelStatistics`]; an interval's missing upper end
    /// (the samples do not bound it) is an empty cell.
    pub fn separation_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        out.write_record([
            "roughness",
            "speed [m/s]",
            "speed [km/h]",
            "vehicle",
            "wheel",
            "samples",
            "separated",
            "probability",
            "probability_low",
            "probability_high",
            "expected_max_gap [m]",
            "expected_max_gap_std_error [m]",
            "expected_max_gap_low [m]",
            "expected_max_gap_high [m]",
        ])
        .expect("writing to memory");
        for c in 0..self.cases.len() {
            for w in self.wheel_statistics(c) {
                let mut row = self.case_cells(c).to_vec();
                row.extend([
                    w.vehicle.to_string(),
                    w.wheel.to_string(),
                    self.samples.to_string(),
                    w.separated.to_string(),
                    number(w.probability),
                    number(w.probability_low),
                    number(w.probability_high),
                    number(w.expected_max_gap),
                    number(w.expected_max_gap_std_error),
                    number(w.expected_max_gap_low),
                    w.expected_max_gap_high.map(number).unwrap_or_default(),
                ]);
                out.write_record(&row).expect("writing to memory");
            }
        }
        out.into_inner().expect("writing to memory")
    }

    /// envelopes.csv: per case and step, each record's mean, standard
    /// deviation σ and mean ∓ 3σ (`<record>_mean`, `_std`, `_lower`, `_upper`).
    pub fn envelopes_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        let mut header: Vec<String> = ["roughness", "speed [m/s]", "speed [km/h]", "time [s]"]
            .map(String::from)
            .to_vec();
        if let Some(first) = self.envelopes.first() {
            for (name, unit) in first.names.iter().zip(&first.units) {
                for what in ["mean", "std", "lower", "upper"] {
                    header.push(heading(&format!("{name}_{what}"), unit));
                }
            }
        }
        out.write_record(&header).expect("writing to memory");
        for (c, m) in self.envelopes.iter().enumerate() {
            let std = m.std_dev();
            let cells = self.case_cells(c);
            for (i, &t) in m.time.iter().enumerate() {
                let mut row = cells.to_vec();
                // k·Δt without its float noise (0.018, not 0.018000000000000002).
                row.push(number(clean(t)));
                for (mean, s) in m.mean.iter().zip(&std) {
                    let (mu, sigma) = (mean[i], s[i]);
                    row.extend([
                        number(mu),
                        number(sigma),
                        number(mu - 3.0 * sigma),
                        number(mu + 3.0 * sigma),
                    ]);
                }
                out.write_record(&row).expect("writing to memory");
            }
        }
        out.into_inner().expect("writing to memory")
    }
}

/// envelope_<record>.png for every record of the first case: the first
/// `show` samples in grey, the mean and mean ± 3σ over them.
fn plot_envelopes(out: &Path, name: &str, results: &MonteCarloResults) -> Result<(), RunError> {
    let Some(m) = results.envelopes.first() else {
        return Ok(());
    };
    let std = m.std_dev();
    let shown: Vec<&Vec<Vec<f64>>> = results.sample_results[..results.samples]
        .iter()
        .filter_map(|r| r.histories.as_ref())
        .collect();
    let case = match results.speed(0) {
        Some(v) => format!("{}, {:.1} km/h", results.labels[0], km_h(v)),
        None => results.labels[0].clone(),
    };
    // One chart per record, drawn and compressed in parallel (each file is
    // the same whatever the thread count).
    use rayon::prelude::*;
    (0..m.names.len()).into_par_iter().try_for_each(|r| {
        let (record, unit) = (&m.names[r], &m.units[r]);
        let lower: Vec<f64> = m.mean[r]
            .iter()
            .zip(&std[r])
            .map(|(mu, s)| mu - 3.0 * s)
            .collect();
        let upper: Vec<f64> = m.mean[r]
            .iter()
            .zip(&std[r])
            .map(|(mu, s)| mu + 3.0 * s)
            .collect();
        // Every line in the legend: the grey samples under one entry.
        let samples_label = format!("{} of {} samples", shown.len(), m.count);
        let mut series: Vec<Series> = shown
            .iter()
            .enumerate()
            .map(|(k, h)| Series {
                label: if k == 0 { &samples_label } else { "" },
                x: &m.time,
                y: &h[r],
            })
            .collect();
        let grey = series.len();
        series.push(Series {
            label: "mean",
            x: &m.time,
            y: &m.mean[r],
        });
        series.push(Series {
            label: "mean - 3σ",
            x: &m.time,
            y: &lower,
        });
        series.push(Series {
            label: "mean + 3σ",
            x: &m.time,
            y: &upper,
        });
        let file = format!(
            "envelope_{}.png",
            crate::scenario::names::folder_name(record)
        );
        line_chart_over_samples(
            &out.join(file),
            &format!("{name}: {record} over {} samples ({case})", m.count),
            "time (s)",
            &format!("{record} ({unit})"),
            &series,
            grey,
        )
        .map_err(RunError::from)
    })
}

/// separation_probability.png and expected_gap.png against speed, one line
/// per surface and wheel (Figs. 8 and 9), each shaded with its 95 %
/// interval ([`WheelStatistics`]); an expected gap whose interval has no
/// upper end (no sample separated) has no band there.
fn plot_against_speed(out: &Path, name: &str, results: &MonteCarloResults) -> Result<(), RunError> {
    if results.cases.iter().all(|c| c.speed.is_none()) {
        return Ok(());
    }
    // Cases are surface-major: each surface has the same run of speeds.
    let surfaces = results.cases.last().map_or(0, |c| c.roughness + 1);
    let n_speeds = results.cases.len() / surfaces.max(1);
    let stats: Vec<Vec<WheelStatistics>> = (0..results.cases.len())
        .map(|c| results.wheel_statistics(c))
        .collect();
    // Per line: label, speeds (km/h), then per chart the estimates and
    // their lower and upper ends.
    struct Line {
        label: String,
        km_h: Vec<f64>,
        charts: [[Vec<f64>; 3]; 2],
    }
    let mut lines = Vec::new();
    for s in 0..surfaces {
        let cases: Vec<usize> = (s * n_speeds..(s + 1) * n_speeds).collect();
        let km_h: Vec<f64> = cases
            .iter()
            .map(|&c| km_h(results.speed(c).unwrap_or(f64::NAN)))
            .collect();
        for (w, first) in stats[cases[0]].iter().enumerate() {
            let of = |f: &dyn Fn(&WheelStatistics) -> f64| -> Vec<f64> {
                cases.iter().map(|&c| f(&stats[c][w])).collect()
            };
            lines.push(Line {
                label: format!(
                    "{}, vehicle {} wheel {}",
                    results.labels[cases[0]], first.vehicle, first.wheel
                ),
                km_h: km_h.clone(),
                charts: [
                    [
                        of(&|w| w.probability),
                        of(&|w| w.probability_low),
                        of(&|w| w.probability_high),
                    ],
                    // In mm; an interval without an upper end is NaN (no band).
                    [
                        of(&|w| w.expected_max_gap * 1e3),
                        of(&|w| w.expected_max_gap_low * 1e3),
                        of(&|w| w.expected_max_gap_high.map_or(f64::NAN, |h| h * 1e3)),
                    ],
                ],
            });
        }
    }
    let n = results.samples;
    // Where no sample separated the gap's interval has no upper end, and
    // no band: the title says why.
    let unbounded = lines
        .iter()
        .any(|l| l.charts[1][2].iter().any(|h| h.is_nan()));
    for (chart, (file, title, y_label)) in [
        (
            "separation_probability.png",
            format!("probability of separation, n = {n} samples"),
            "probability of separation (band: 95 % Wilson interval)",
        ),
        (
            "expected_gap.png",
            format!(
                "expected largest separation, n = {n} samples{}",
                if unbounded {
                    " (no band: no sample separated, unbounded)"
                } else {
                    ""
                }
            ),
            "expected largest gap (mm; band: 95 % interval)",
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let series: Vec<Series> = lines
            .iter()
            .map(|l| Series {
                label: &l.label,
                x: &l.km_h,
                y: &l.charts[chart][0],
            })
            .collect();
        let bands: Vec<Option<Band>> = lines
            .iter()
            .map(|l| {
                Some(Band {
                    low: &l.charts[chart][1],
                    high: &l.charts[chart][2],
                })
            })
            .collect();
        line_chart_with_bands(
            &out.join(file),
            &format!("{name}: {title}"),
            "speed (km/h)",
            y_label,
            &series,
            &bands,
        )?;
    }
    Ok(())
}

/// Writes every output of the study into `out`, summary.json last.
pub fn write(out: &Path, scenario: &Scenario, results: &MonteCarloResults) -> Result<(), RunError> {
    crate::report::folder::create_out(out)?;
    // The tables and the charts are independent files: written side by side.
    let (tables, charts) = rayon::join(
        || -> Result<(), RunError> {
            write_atomic(&out.join("study.csv"), &results.samples_csv())?;
            write_atomic(&out.join("separation.csv"), &results.separation_csv())?;
            write_atomic(&out.join("envelopes.csv"), &results.envelopes_csv())?;
            Ok(())
        },
        || -> Result<(), RunError> {
            plot_envelopes(out, &scenario.name, results)?;
            plot_against_speed(out, &scenario.name, results)
        },
    );
    tables?;
    charts?;
    write_atomic(
        &out.join("resolved.yaml"),
        crate::report::folder::resolved_yaml(scenario).as_bytes(),
    )?;
    let text =
        crate::study::summary_json(&results.summary(&scenario.name), results.advice(scenario));
    write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}
