//! Railway resonance check (EN 1991-2 6.4.6 with Annex E): every HSLM-A
//! train of the study crosses the bridge alone, as moving axle forces, at
//! every speed of the grid; each run envelopes the whole deck
//! ([`crate::record::envelope`]) and keeps its largest |displacement| and
//! |acceleration| (the latter summed up to the study's cut-off frequency,
//! EN 1990 A2.4.4.2.1(4)), to be compared with the deck-acceleration limit
//! of EN 1990 A2.4.4.2.1(1): 3.5 m/s² on ballasted track, 5 m/s² with direct
//! fastening.
//!
//! Runs are independent and deterministic; they run in parallel and are
//! collected in study order (train by train, speed by speed), so the results
//! do not depend on the thread count. No history is kept: a run costs
//! O(steps × nodes × (modes + axles)).

use std::path::Path;
use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::record::Recorder;
use crate::report::plot::{Series, line_chart};
use crate::report::{number, write_atomic};
use crate::run::RunError;
use crate::scenario::resolved::{Envelopes, Quantity, ResonanceCheck, Scenario};
use crate::scenario::resonance::train_vehicle;
use crate::solve;

/// km/h per m/s.
const KM_H: f64 = 3.6;

/// One run: a train at a speed.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct ResonancePoint {
    /// Train: index into [`ResonanceResults::trains`].
    pub train: usize,
    /// Speed, m/s.
    pub speed: f64,
    /// Largest |deck displacement|, m.
    pub max_displacement: f64,
    /// Where along the deck, m.
    pub displacement_at: f64,
    /// Largest |deck acceleration| (filtered), m/s².
    pub max_acceleration: f64,
    /// Where along the deck, m.
    pub acceleration_at: f64,
    /// Time step of the run, s.
    pub time_step: f64,
}

/// The whole check.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResonanceResults {
    /// Train labels (`HSLM-A1` …), in study order.
    pub trains: Vec<String>,
    /// Speeds, m/s.
    pub speeds: Vec<f64>,
    /// Deck-acceleration limit, m/s².
    pub limit: f64,
    /// The track, in words.
    pub deck: String,
    /// Maximum line speed, m/s.
    pub line_speed: f64,
    /// Cut-off frequency of the deck acceleration, Hz.
    pub max_frequency: f64,
    /// Runs, train by train, speed by speed.
    pub points: Vec<ResonancePoint>,
    /// Wall time of all runs, s.
    pub wall_time: f64,
}

/// Number of runs.
pub fn size(check: &ResonanceCheck) -> usize {
    check.trains.len() * check.speeds.count()
}

/// The scene of one run: `train` alone at `speed`, enveloped along the
/// deck, no history records.
fn run_scenario(base: &Scenario, check: &ResonanceCheck, train: usize, speed: f64) -> Scenario {
    let mut scenario = base.clone();
    scenario.study = None;
    scenario.vehicles = vec![train_vehicle(check.trains[train], speed)];
    scenario.record = Vec::new();
    scenario.envelopes = Some(Envelopes {
        quantities: vec![Quantity::BridgeDisplacement, Quantity::BridgeAcceleration],
        points: None,
        max_frequency: Some(check.max_frequency),
    });
    scenario
}

/// Largest |value| over the deck and where: (value, x).
fn peak(envelope: &crate::record::envelope::Envelope, column: usize) -> (f64, f64) {
    let extremes = &envelope.columns[column].extremes;
    extremes
        .iter()
        .zip(&envelope.x)
        .map(|(e, &x)| (e.max.abs().max(e.min.abs()), x))
        .fold((0.0, 0.0), |best, p| if p.0 > best.0 { p } else { best })
}

fn run_point(
    base: &Scenario,
    bridge: &ModalBridge,
    check: &ResonanceCheck,
    (train, speed): (usize, f64),
) -> Result<ResonancePoint, RunError> {
    let scenario = run_scenario(base, check, train, speed);
    let model = Model::build(&scenario, bridge.clone())?;
    let mut recorder = Recorder::new(&model, &[])
        .and_then(|r| r.with_envelopes(scenario.envelopes.as_ref()))
        .map_err(crate::model::BuildError::from)?;
    solve::run(&model, &mut recorder, &mut |_, _| {})?;
    let history = recorder.finish();
    let envelope = history
        .envelope
        .as_ref()
        .expect("the run envelopes the deck");
    let (max_displacement, displacement_at) = peak(envelope, 0);
    let (max_acceleration, acceleration_at) = peak(envelope, 1);
    Ok(ResonancePoint {
        train,
        speed,
        max_displacement,
        displacement_at,
        max_acceleration,
        acceleration_at,
        time_step: model.time_step,
    })
}

/// The jobs (train index, speed) in study order.
fn jobs(check: &ResonanceCheck) -> Vec<(usize, f64)> {
    let speeds = check.speeds.values();
    (0..check.trains.len())
        .flat_map(|t| speeds.iter().map(move |&v| (t, v)))
        .collect()
}

/// Runs the runs `range` (in parallel), collected in study order;
/// `progress` gets (runs done, runs in the range).
pub fn run_slice(
    base: &Scenario,
    bridge: &ModalBridge,
    check: &ResonanceCheck,
    range: std::ops::Range<usize>,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<ResonancePoint>, RunError> {
    let jobs = jobs(check);
    let total = range.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    jobs[range]
        .par_iter()
        .map(|&job| {
            let point = run_point(base, bridge, check, job);
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(n, total);
            point
        })
        .collect()
}

/// The check from all its runs in study order.
pub fn assemble(
    check: &ResonanceCheck,
    points: Vec<ResonancePoint>,
    wall_time: f64,
) -> ResonanceResults {
    ResonanceResults {
        trains: check.trains.iter().map(|t| t.label()).collect(),
        speeds: check.speeds.values(),
        limit: check.deck.acceleration_limit(),
        deck: match check.deck {
            crate::scenario::raw::DeckRaw::Ballasted => "ballasted".into(),
            crate::scenario::raw::DeckRaw::DirectFastening => "direct_fastening".into(),
        },
        line_speed: check.line_speed,
        max_frequency: check.max_frequency,
        points,
        wall_time,
    }
}

/// Runs the whole check.
pub fn run(
    base: &Scenario,
    bridge: &ModalBridge,
    check: &ResonanceCheck,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<ResonanceResults, RunError> {
    let start = Instant::now();
    let points = run_slice(base, bridge, check, 0..size(check), progress)?;
    Ok(assemble(check, points, start.elapsed().as_secs_f64()))
}

/// The governing run of one quantity.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Governing {
    /// Train label.
    pub train: String,
    /// Speed, m/s.
    pub speed_m_s: f64,
    /// Speed, km/h.
    pub speed_km_h: f64,
    /// The value (m or m/s²).
    pub value: f64,
    /// Where along the deck, m.
    pub x: f64,
}

/// summary.json of a resonance check.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResonanceSummary {
    /// Study type.
    pub study: &'static str,
    /// Scenario name.
    pub scenario: String,
    /// vbi version.
    pub vbi_version: &'static str,
    /// Runs.
    pub runs: usize,
    /// Wall time of all runs, s.
    pub wall_time: f64,
    /// The track.
    pub deck: String,
    /// Deck-acceleration limit, m/s² (EN 1990 A2.4.4.2.1(1)).
    pub acceleration_limit: f64,
    /// Cut-off frequency of the deck acceleration, Hz.
    pub max_frequency: f64,
    /// Maximum line speed, m/s; the check runs to 1.2 × it by default.
    pub line_speed_m_s: f64,
    /// The run with the largest deck acceleration.
    pub governing_acceleration: Option<Governing>,
    /// The run with the largest deck displacement.
    pub governing_displacement: Option<Governing>,
    /// Whether every run keeps the deck acceleration within the limit.
    pub passes: bool,
}

impl ResonanceResults {
    fn governing(&self, value: impl Fn(&ResonancePoint) -> (f64, f64)) -> Option<Governing> {
        let best = self
            .points
            .iter()
            .fold(None::<&ResonancePoint>, |best, p| match best {
                Some(b) if value(b).0 >= value(p).0 => Some(b),
                _ => Some(p),
            })?;
        let (v, x) = value(best);
        Some(Governing {
            train: self.trains[best.train].clone(),
            speed_m_s: best.speed,
            speed_km_h: best.speed * KM_H,
            value: v,
            x,
        })
    }

    /// The summary.
    pub fn summary(&self, name: &str) -> ResonanceSummary {
        let acceleration = self.governing(|p| (p.max_acceleration, p.acceleration_at));
        ResonanceSummary {
            study: "resonance_check",
            scenario: name.to_owned(),
            vbi_version: env!("CARGO_PKG_VERSION"),
            runs: self.points.len(),
            wall_time: self.wall_time,
            deck: self.deck.clone(),
            acceleration_limit: self.limit,
            max_frequency: self.max_frequency,
            line_speed_m_s: self.line_speed,
            passes: acceleration.as_ref().is_none_or(|g| g.value <= self.limit),
            governing_acceleration: acceleration,
            governing_displacement: self.governing(|p| (p.max_displacement, p.displacement_at)),
        }
    }

    /// resonance.csv: one row per run.
    pub fn to_csv(&self) -> Vec<u8> {
        let mut out = String::from(
            "train,speed_m_s,speed_km_h,max_displacement_m,displacement_at_m,\
             max_acceleration_m/s^2,acceleration_at_m,time_step_s\n",
        );
        for p in &self.points {
            let row = [
                self.trains[p.train].clone(),
                number(p.speed),
                number(p.speed * KM_H),
                number(p.max_displacement),
                number(p.displacement_at),
                number(p.max_acceleration),
                number(p.acceleration_at),
                number(p.time_step),
            ];
            out.push_str(&row.join(","));
            out.push('\n');
        }
        out.into_bytes()
    }

    /// Per train, its runs' (km/h, value) in speed order.
    fn curves(&self, value: impl Fn(&ResonancePoint) -> f64) -> Vec<(Vec<f64>, Vec<f64>)> {
        (0..self.trains.len())
            .map(|t| {
                self.points
                    .iter()
                    .filter(|p| p.train == t)
                    .map(|p| (p.speed * KM_H, value(p)))
                    .unzip()
            })
            .collect()
    }
}

/// Writes resonance.csv, resonance.png (deck acceleration against speed
/// per train, with the limit line), resonance_displacement.png,
/// resolved.yaml and, last, summary.json into `out`.
pub fn write(out: &Path, scenario: &Scenario, results: &ResonanceResults) -> Result<(), RunError> {
    crate::run::create_out(out)?;
    write_atomic(&out.join("resonance.csv"), &results.to_csv())?;
    let speed_label = "speed (km/h)";
    let accelerations = results.curves(|p| p.max_acceleration);
    let mut series: Vec<Series> = results
        .trains
        .iter()
        .zip(&accelerations)
        .map(|(label, (x, y))| Series { label, x, y })
        .collect();
    let (lo, hi) = results
        .speeds
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v * KM_H), b.max(v * KM_H))
        });
    let limit_x = [lo, hi];
    let limit_y = [results.limit; 2];
    let limit_label = format!(
        "limit {} m/s^2 ({}, EN 1990 A2.4.4.2.1)",
        results.limit,
        results.deck.replace('_', " ")
    );
    series.push(Series {
        label: &limit_label,
        x: &limit_x,
        y: &limit_y,
    });
    line_chart(
        &out.join("resonance.png"),
        &format!(
            "{}: peak deck acceleration (modes up to {:.1} Hz)",
            scenario.name, results.max_frequency
        ),
        speed_label,
        "max |deck acceleration| (m/s^2)",
        &series,
        false,
        false,
    )?;
    let displacements = results.curves(|p| p.max_displacement * 1e3);
    let series: Vec<Series> = results
        .trains
        .iter()
        .zip(&displacements)
        .map(|(label, (x, y))| Series { label, x, y })
        .collect();
    line_chart(
        &out.join("resonance_displacement.png"),
        &format!("{}: peak deck displacement", scenario.name),
        speed_label,
        "max |deck displacement| (mm)",
        &series,
        false,
        false,
    )?;
    write_atomic(
        &out.join("resolved.yaml"),
        crate::run::resolved_yaml(scenario).as_bytes(),
    )?;
    let summary = results.summary(&scenario.name);
    let text = serde_json::to_string_pretty(&summary).expect("summary serialises") + "\n";
    write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}
