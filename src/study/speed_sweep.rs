//! Speed sweep: the DAF against vehicle speed, on one or more road surfaces
//! (the plate paper's Figs. 12, 13 and 17).
//!
//! Every point is the scene with every vehicle at one speed of the grid
//! (entry times kept) on one surface: the scene's own, `smooth`, or a random
//! profile of a roughness class, `samples` times with consecutive seeds.
//! Each point builds its model from the bridge built while resolving (the
//! automatic mode cut-off and time step already cover the whole sweep), so a
//! point is exactly the run of `resolved.yaml` with that speed and surface.
//! Points run in parallel and are collected in sweep order; each is an
//! independent, deterministic run, so the results are the same whatever the
//! thread count.

mod report;

use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

pub use self::report::{SweepSummary, write};
use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::record::Recorder;
use crate::report::summary::Summary;
use crate::run::RunError;
use crate::scenario::sweep;
use crate::scene::{Bridge, Quantity, Scenario, SpeedSweep, SweepRoughness, Vehicle};
use crate::solve;

/// Where a DAF column of the sweep is taken.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "at", rename_all = "snake_case")]
pub enum DafSource {
    /// The middle of a span on a girder line (a beam has line 1 only).
    SpanMiddle {
        /// Span from 1.
        span: usize,
        /// Girder line from 1.
        girder: usize,
    },
    /// A `bridge_displacement` record of the scene.
    Record {
        /// Record name.
        name: String,
    },
}

/// The names of the DAF columns in study.csv: `daf_span{s}_girder{g}` and
/// `daf_<record>`, or `daf_record_<record>` where a record's name would
/// repeat an earlier column's (a record named `span2_girder1`).
pub fn daf_columns(sources: &[DafSource]) -> Vec<String> {
    let mut names: Vec<String> = Vec::with_capacity(sources.len());
    for source in sources {
        let name = match source {
            DafSource::SpanMiddle { span, girder } => format!("daf_span{span}_girder{girder}"),
            DafSource::Record { name } => {
                let plain = format!("daf_{name}");
                if names.contains(&plain) {
                    format!("daf_record_{name}")
                } else {
                    plain
                }
            }
        };
        names.push(name);
    }
    names
}

/// One run of the sweep.
#[derive(Debug, Clone, Serialize, serde::Deserialize, PartialEq)]
pub struct SweepPoint {
    /// Surface: index into [`SweepResults::roughness`].
    pub roughness: usize,
    /// Sample number from 1.
    pub sample: usize,
    /// Seed of the random profile (`None` for a deterministic surface).
    pub seed: Option<u64>,
    /// Speed of every vehicle, m/s.
    pub speed: f64,
    /// DAF per [`SweepResults::daf_sources`] (`None` where the static
    /// response is 0).
    pub dafs: Vec<Option<f64>>,
    /// Largest contact force per [`SweepResults::force_records`], N.
    pub max_forces: Vec<f64>,
    /// Largest |value| of every record of the scene, in record order
    /// ([`SweepResults::records`]), in the record's unit (bridge
    /// accelerations filtered at the record's `max_frequency`).
    #[serde(default)]
    pub max_abs: Vec<f64>,
    /// What vbi knows about this point's run ([`crate::advice`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub advice: Vec<crate::advice::Advice>,
}

/// The whole sweep.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SweepResults {
    /// Speeds, m/s.
    pub speeds: Vec<f64>,
    /// Label of each surface.
    pub roughness: Vec<String>,
    /// Runs per speed of each surface (1 for smooth and harmonic ones).
    pub runs: Vec<usize>,
    /// Seeds of each surface's samples (empty for deterministic ones).
    pub seeds: Vec<Vec<u64>>,
    /// Samples per random surface.
    pub samples: usize,
    /// Whether the bridge is a plate deck (else a beam).
    pub plate: bool,
    /// Span of the plots, from 1.
    pub span: usize,
    /// Girder line of the roughness plot, from 1.
    pub girder: usize,
    /// Girder lines of the bridge (1 on a beam).
    pub girder_lines: usize,
    /// What each DAF column measures: every span's middle on every girder
    /// line, span by span, then every `bridge_displacement` record.
    pub daf_sources: Vec<DafSource>,
    /// The DAF columns' names in study.csv (see [`daf_columns`]).
    pub daf_columns: Vec<String>,
    /// Names of the `contact_force` records.
    pub force_records: Vec<String>,
    /// Every record of the scene: (name, unit), in record order.
    pub records: Vec<(String, String)>,
    /// Points: surface by surface, sample by sample, speed by speed.
    pub points: Vec<SweepPoint>,
    /// Wall time of all points, s.
    pub wall_time: f64,
}

/// The surfaces of a sweep: `None` is the scene's own.
pub fn entries(sweep: &SpeedSweep) -> Vec<Option<SweepRoughness>> {
    match &sweep.roughness {
        None => vec![None],
        Some(list) => list.iter().copied().map(Some).collect(),
    }
}

/// The scene of one point: every vehicle at `speed` (m/s; entry times kept,
/// an oscillator's dimensionless velocity ratio updated) on the surface of
/// `entry` for sample `k` (from 0), without the study.
pub fn point_scenario(
    base: &Scenario,
    bridge: &ModalBridge,
    entry: Option<SweepRoughness>,
    k: usize,
    speed: f64,
) -> Scenario {
    let mut scenario = base.clone();
    scenario.study = None;
    scenario.vehicles = sweep::with_speed(&base.vehicles, speed);
    let f1 = bridge.frequencies()[0];
    for vehicle in &mut scenario.vehicles {
        if let Vehicle::Oscillator(o) = vehicle
            && let Some(groups) = &mut o.dimensionless
        {
            groups.velocity_ratio = speed / (2.0 * f1 * bridge.length);
        }
    }
    scenario.surface = sweep::surface(&base.surface, entry, k, base.bridge.length());
    scenario
}

fn run_point(
    base: &Scenario,
    bridge: &ModalBridge,
    sources: &[DafSource],
    (roughness, entry, k, speed): (usize, Option<SweepRoughness>, usize, f64),
) -> Result<SweepPoint, RunError> {
    let scenario = point_scenario(base, bridge, entry, k, speed);
    let model = Model::build(&scenario, bridge.clone())?;
    // A sweep writes no run's history: only the extremes are kept.
    let mut recorder = Recorder::new(&model, &scenario.record)
        .map_err(crate::model::BuildError::from)?
        .without_samples();
    let stats = solve::run(&model, &mut recorder, &mut |_, _| {})?;
    let history = recorder.finish();
    let summary = Summary::new(&scenario.name, &model, &history, &stats, 0.0);
    let dafs = sources
        .iter()
        .map(|source| match source {
            DafSource::SpanMiddle { span, girder } => history
                .girder_dafs
                .iter()
                .find(|d| d.span == *span && d.girder == *girder)
                .filter(|d| d.static_max_abs > 0.0)
                .map(|d| d.daf),
            DafSource::Record { name } => summary
                .quantities
                .iter()
                .find(|q| q.name == *name)
                .and_then(|q| q.daf),
        })
        .collect();
    let max_forces = summary
        .quantities
        .iter()
        .filter(|q| q.quantity == Quantity::ContactForce)
        .map(|q| q.max.value)
        .collect();
    let seed = match scenario.surface {
        crate::scene::Surface::Random { seed, .. } => Some(seed),
        _ => None,
    };
    // From the running extremes: a sweep's runs keep no samples.
    let max_abs = history
        .extremes
        .iter()
        .map(|e| e.all.max_abs.map_or(0.0, |s| s.value.abs()))
        .collect();
    Ok(SweepPoint {
        roughness,
        sample: k + 1,
        seed,
        speed,
        dafs,
        max_forces,
        max_abs,
        advice: crate::report::advice::run_advice(&scenario, &summary),
    })
}

/// The sweep's layout without its points (`points` empty, `wall_time` 0)
/// and its jobs: (surface index, surface, sample from 0, speed) in sweep
/// order.
#[allow(clippy::type_complexity)]
fn layout(
    base: &Scenario,
    study: &SpeedSweep,
) -> (
    SweepResults,
    Vec<(usize, Option<SweepRoughness>, usize, f64)>,
) {
    let speeds = study.speed_values();
    let entries = entries(study);
    let runs: Vec<usize> = entries
        .iter()
        .map(|&e| {
            if sweep::is_random(&base.surface, e) {
                study.samples
            } else {
                1
            }
        })
        .collect();
    let length = base.bridge.length();
    let seeds: Vec<Vec<u64>> = entries
        .iter()
        .zip(&runs)
        .map(|(&e, &n)| {
            (0..n)
                .filter_map(|k| match sweep::surface(&base.surface, e, k, length) {
                    crate::scene::Surface::Random { seed, .. } => Some(seed),
                    _ => None,
                })
                .collect()
        })
        .collect();
    let lines = match &base.bridge {
        Bridge::Beam(_) | Bridge::FeImport(_) => 1,
        Bridge::Plate(p) => p.girder_lines.len(),
    };
    let mut daf_sources: Vec<DafSource> = (1..=base.bridge.spans().len())
        .flat_map(|span| (1..=lines).map(move |girder| DafSource::SpanMiddle { span, girder }))
        .collect();
    daf_sources.extend(
        base.record
            .iter()
            .filter(|r| r.quantity == Quantity::BridgeDisplacement)
            .map(|r| DafSource::Record {
                name: r.name.clone(),
            }),
    );
    let force_records = base
        .record
        .iter()
        .filter(|r| r.quantity == Quantity::ContactForce)
        .map(|r| r.name.clone())
        .collect();
    let jobs: Vec<(usize, Option<SweepRoughness>, usize, f64)> = entries
        .iter()
        .zip(&runs)
        .enumerate()
        .flat_map(|(i, (&e, &n))| {
            let speeds = &speeds;
            (0..n).flat_map(move |k| speeds.iter().map(move |&v| (i, e, k, v)))
        })
        .collect();
    let results = SweepResults {
        speeds,
        roughness: entries
            .iter()
            .map(|&e| sweep::label(&base.surface, e))
            .collect(),
        runs,
        seeds,
        samples: study.samples,
        plate: matches!(base.bridge, Bridge::Plate(_)),
        span: study.span,
        girder: study.girder,
        girder_lines: lines,
        daf_columns: daf_columns(&daf_sources),
        daf_sources,
        force_records,
        records: base
            .record
            .iter()
            .map(|r| {
                (
                    r.name.clone(),
                    crate::record::unit_of(r.quantity).to_owned(),
                )
            })
            .collect(),
        points: Vec::new(),
        wall_time: 0.0,
    };
    (results, jobs)
}

/// Runs of the sweep.
pub fn size(base: &Scenario, study: &SpeedSweep) -> usize {
    layout(base, study).1.len()
}

/// Runs the points `range` of the sweep (in parallel) and collects them in
/// sweep order. `progress` is called with (points done, points in the
/// range) as points finish.
pub fn run_slice(
    base: &Scenario,
    bridge: &ModalBridge,
    study: &SpeedSweep,
    range: std::ops::Range<usize>,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<SweepPoint>, RunError> {
    let (layout, jobs) = layout(base, study);
    let total = range.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let token = crate::solve::cancel::current();
    jobs[range]
        .par_iter()
        .map(|&job| {
            let point = crate::solve::cancel::in_scope(token.as_ref(), || {
                run_point(base, bridge, &layout.daf_sources, job)
            });
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(n, total);
            point
        })
        .collect()
}

/// The sweep from all its points in sweep order.
pub fn assemble(
    base: &Scenario,
    study: &SpeedSweep,
    points: Vec<SweepPoint>,
    wall_time: f64,
) -> SweepResults {
    let mut results = layout(base, study).0;
    results.points = points;
    results.wall_time = wall_time;
    results
}

/// Runs every point of the sweep (in parallel) and collects them in sweep
/// order. `progress` is called with (points done, total) as points finish.
pub fn run(
    base: &Scenario,
    bridge: &ModalBridge,
    study: &SpeedSweep,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<SweepResults, RunError> {
    let start = Instant::now();
    let all = 0..size(base, study);
    let points = run_slice(base, bridge, study, all, progress)?;
    Ok(assemble(base, study, points, start.elapsed().as_secs_f64()))
}

impl SweepResults {
    /// Index of the DAF column at the middle of `span` on `girder` (from 1).
    pub fn span_column(&self, span: usize, girder: usize) -> usize {
        (span - 1) * self.girder_lines + girder - 1
    }

    /// The points of surface `roughness`, sample by sample (each a run of
    /// every speed in order).
    pub fn samples_of(&self, roughness: usize) -> Vec<&[SweepPoint]> {
        let n = self.speeds.len();
        let start: usize = self.runs[..roughness].iter().sum::<usize>() * n;
        (0..self.runs[roughness])
            .map(|k| &self.points[start + k * n..start + (k + 1) * n])
            .collect()
    }

    /// Per speed, the 95 % interval of the mean DAF of `column` over the
    /// samples of surface `roughness`
    /// ([`crate::study::statistics::nonnegative_mean_interval`]: never below
    /// 0; the value itself where every sample gives the same), or
    /// `None` with one run (a deterministic surface: nothing sampled) or
    /// where a sample has no DAF.
    pub fn daf_mean_intervals(
        &self,
        roughness: usize,
        column: usize,
    ) -> Vec<Option<(f64, Option<f64>)>> {
        let samples = self.samples_of(roughness);
        (0..self.speeds.len())
            .map(|i| {
                let values: Option<Vec<f64>> = samples
                    .iter()
                    .map(|s| s[i].dafs[column].filter(|d| d.is_finite()))
                    .collect();
                values
                    .filter(|v| v.len() > 1)
                    .map(|v| crate::study::statistics::nonnegative_mean_interval(&v))
            })
            .collect()
    }

    /// Per speed, the mean and the largest DAF of `column` over the samples
    /// of surface `roughness` (NaN where a sample has none).
    pub fn daf_statistics(&self, roughness: usize, column: usize) -> (Vec<f64>, Vec<f64>) {
        let samples = self.samples_of(roughness);
        (0..self.speeds.len())
            .map(|i| {
                let values: Vec<f64> = samples
                    .iter()
                    .map(|s| s[i].dafs[column].unwrap_or(f64::NAN))
                    .collect();
                let mean = values.iter().sum::<f64>() / values.len() as f64;
                let max = values.iter().copied().fold(f64::NEG_INFINITY, |m, v| {
                    if v.is_nan() || m.is_nan() {
                        f64::NAN
                    } else {
                        m.max(v)
                    }
                });
                (mean, max)
            })
            .unzip()
    }

    /// The largest DAF of any column at any point: (point, column, DAF).
    pub fn largest_daf(&self) -> Option<(usize, usize, f64)> {
        let mut best: Option<(usize, usize, f64)> = None;
        for (p, point) in self.points.iter().enumerate() {
            for (c, daf) in point.dafs.iter().enumerate() {
                if let Some(d) = *daf
                    && best.is_none_or(|b| d > b.2)
                {
                    best = Some((p, c, d));
                }
            }
        }
        best
    }

    /// The sweep as CSV: one row per (surface, sample, speed) with
    /// `roughness,sample,seed,speed [m/s],speed [km/h]`, a `daf_…` column per
    /// DAF source, a `max_<record> [N]` column per contact force record, and a
    /// `max_abs_<record> [unit]` column per record (every quantity).
    pub fn to_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        let mut header: Vec<String> =
            ["roughness", "sample", "seed", "speed [m/s]", "speed [km/h]"]
                .map(String::from)
                .to_vec();
        header.extend(self.daf_columns.iter().cloned());
        header.extend(
            self.force_records
                .iter()
                .map(|n| crate::report::heading(&format!("max_{n}"), "N")),
        );
        header.extend(
            self.records
                .iter()
                .map(|(name, unit)| crate::report::heading(&format!("max_abs_{name}"), unit)),
        );
        out.write_record(&header).expect("writing to memory");
        let number = crate::report::number;
        for p in &self.points {
            let mut row = vec![
                self.roughness[p.roughness].clone(),
                p.sample.to_string(),
                p.seed.map(|s| s.to_string()).unwrap_or_default(),
                number(p.speed),
                number(crate::report::km_h(p.speed)),
            ];
            row.extend(p.dafs.iter().map(|d| d.map(number).unwrap_or_default()));
            row.extend(p.max_forces.iter().copied().map(number));
            row.extend(p.max_abs.iter().copied().map(number));
            out.write_record(&row).expect("writing to memory");
        }
        out.into_inner().expect("writing to memory")
    }
}
