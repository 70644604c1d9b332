//! Railway resonance check (EN 1991-2 6.4.6 with Annex E): every HSLM-A
//! train of the study crosses the bridge alone, as moving axle forces, at
//! every speed of the grid; each run envelopes the whole deck
//! ([`crate::record::envelope`]) and keeps its largest |displacement| and
//! |acceleration| (the latter summed up to the study's cut-off frequency,
//! EN 1990 A2.4.4.2.1(4)), to be compared with the deck-acceleration limit
//! of EN 1990 A2.4.4.2.1(1): 3.5 m/s² on ballasted track, 5 m/s² with direct
//! fastening.
//!
//! The verdict is per train and overall (EN 1991-2 6.4.6.5(3) with EN 1990
//! A2.4.4.2.1): a train passes when no run of it exceeds the limit. The
//! speeds of each train are its own ([`ResonanceCheck::speeds_km_h`]): the
//! regular grid, 1.2 × line speed and its resonance speeds f₀·D/k refined.
//!
//! Runs are independent and deterministic; they run in parallel and are
//! collected in study order (train by train, speed by speed), so the results
//! do not depend on the thread count. No history is kept: a run costs
//! O(steps × nodes × (modes + axles)).

use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::record::Recorder;
use crate::run::RunError;
use crate::scenario::resonance::train_vehicle;
use crate::scenario::resonance_grid::km_h;
use crate::scene::{AdditionalDamping, Envelopes, Quantity, ResonanceCheck, Scenario};
use crate::solve;

pub use super::resonance_report::write;

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
    /// What vbi knows about this point's run ([`crate::advice`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub advice: Vec<crate::advice::Advice>,
}

/// The whole check.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResonanceResults {
    /// Train labels (`HSLM-A1` …), in study order.
    pub trains: Vec<String>,
    /// Coach length D of each train, m.
    pub coach_lengths: Vec<f64>,
    /// Resonance speeds f₀·D/k of each train in the checked range, km/h.
    pub resonance_speeds_km_h: Vec<Vec<f64>>,
    /// The bridge's first natural frequency f₀, Hz.
    pub first_frequency: f64,
    /// The maximum speed of the check, 1.2 × line speed, km/h.
    pub max_speed_km_h: f64,
    /// EN 1991-2 6.4.6.3.1(3) additional damping, when taken.
    pub additional_damping: Option<AdditionalDamping>,
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
    check.run_count()
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
    let advice = super::point_advice(&scenario, &model, &history);
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
        advice,
    })
}

/// The jobs (train index, speed in m/s) in study order.
fn jobs(check: &ResonanceCheck) -> Vec<(usize, f64)> {
    (0..check.trains.len())
        .flat_map(|t| check.speeds_m_s(t).into_iter().map(move |v| (t, v)))
        .collect()
}

/// The bridge of the runs: with the additional damping Δζ of EN 1991-2
/// 6.4.6.3.1(3) added to every mode's ratio when asked for (ζ_total = ζ +
/// Δζ, eq. 6.14).
fn damped(bridge: &ModalBridge, check: &ResonanceCheck) -> ModalBridge {
    let mut bridge = bridge.clone();
    if let Some(extra) = check.additional_damping {
        for ratio in &mut bridge.damping_ratios {
            *ratio += extra.ratio;
        }
    }
    bridge
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
    let bridge = &damped(bridge, check);
    let total = range.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let token = crate::solve::cancel::current();
    jobs[range]
        .par_iter()
        .map(|&job| {
            let point = crate::solve::cancel::in_scope(token.as_ref(), || {
                run_point(base, bridge, check, job)
            });
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
        coach_lengths: check
            .trains
            .iter()
            .map(|t| t.train().coach_length)
            .collect(),
        resonance_speeds_km_h: (0..check.trains.len())
            .map(|t| check.resonance_speeds_km_h(t))
            .collect(),
        first_frequency: check.first_frequency,
        max_speed_km_h: check.max_speed_km_h(),
        additional_damping: check.additional_damping,
        limit: check.deck.acceleration_limit(),
        deck: match check.deck {
            crate::scene::Deck::Ballasted => "ballasted".into(),
            crate::scene::Deck::DirectFastening => "direct_fastening".into(),
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

/// The verdict on one train.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct TrainVerdict {
    /// Train label.
    pub train: String,
    /// Coach length D, m.
    pub coach_length_m: f64,
    /// Its resonance speeds f₀·D/k in the checked range, km/h.
    pub resonance_speeds_km_h: Vec<f64>,
    /// Runs of this train.
    pub runs: usize,
    /// Its run with the largest deck acceleration (m/s²).
    pub max_acceleration: Option<Governing>,
    /// Whether every run of it keeps the deck acceleration within the limit.
    pub passes: bool,
}

/// The additional damping taken, in summary.json.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct DampingTaken {
    /// Span length L, m.
    pub span_m: f64,
    /// Δζ, % (EN 1991-2 6.4.6.3.1(3), eq. 6.13).
    pub additional_percent: f64,
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
    /// Maximum line speed, m/s.
    pub line_speed_m_s: f64,
    /// The maximum speed checked, 1.2 × line speed (EN 1991-2 6.4.6.2(1)),
    /// km/h; always in the grid.
    pub max_speed_km_h: f64,
    /// The bridge's first natural frequency f₀, Hz (resonance at f₀·D/k).
    pub first_frequency_hz: f64,
    /// The additional damping Δζ of spans below 30 m, when taken.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub additional_damping: Option<DampingTaken>,
    /// The run with the largest deck acceleration.
    pub governing_acceleration: Option<Governing>,
    /// The run with the largest deck displacement.
    pub governing_displacement: Option<Governing>,
    /// The verdict per train, in study order.
    pub trains: Vec<TrainVerdict>,
    /// Trains that fail, in study order.
    pub failing_trains: Vec<String>,
    /// Whether every run keeps the deck acceleration within the limit: the
    /// overall verdict (`vbi run` exits 3 when false).
    pub passes: bool,
}

impl ResonanceResults {
    fn governing<'a>(
        &self,
        points: impl Iterator<Item = &'a ResonancePoint>,
        value: impl Fn(&ResonancePoint) -> (f64, f64),
    ) -> Option<Governing> {
        let best = points.fold(None::<&ResonancePoint>, |best, p| match best {
            Some(b) if value(b).0 >= value(p).0 => Some(b),
            _ => Some(p),
        })?;
        let (v, x) = value(best);
        Some(Governing {
            train: self.trains[best.train].clone(),
            speed_m_s: best.speed,
            speed_km_h: km_h(best.speed),
            value: v,
            x,
        })
    }

    /// The verdict on each train, in study order.
    pub fn verdicts(&self) -> Vec<TrainVerdict> {
        (0..self.trains.len())
            .map(|t| {
                let runs = || self.points.iter().filter(move |p| p.train == t);
                let max_acceleration =
                    self.governing(runs(), |p| (p.max_acceleration, p.acceleration_at));
                TrainVerdict {
                    train: self.trains[t].clone(),
                    coach_length_m: self.coach_lengths[t],
                    resonance_speeds_km_h: self.resonance_speeds_km_h[t].clone(),
                    runs: runs().count(),
                    passes: runs().all(|p| p.max_acceleration <= self.limit),
                    max_acceleration,
                }
            })
            .collect()
    }

    /// Whether every run keeps the deck acceleration within the limit.
    pub fn passes(&self) -> bool {
        self.points.iter().all(|p| p.max_acceleration <= self.limit)
    }

    /// The summary.
    pub fn summary(&self, name: &str) -> ResonanceSummary {
        let trains = self.verdicts();
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
            max_speed_km_h: self.max_speed_km_h,
            first_frequency_hz: self.first_frequency,
            additional_damping: self.additional_damping.map(|d| DampingTaken {
                span_m: d.span,
                additional_percent: d.ratio * 100.0,
            }),
            governing_acceleration: self.governing(self.points.iter(), |p| {
                (p.max_acceleration, p.acceleration_at)
            }),
            governing_displacement: self.governing(self.points.iter(), |p| {
                (p.max_displacement, p.displacement_at)
            }),
            failing_trains: trains
                .iter()
                .filter(|t| !t.passes)
                .map(|t| t.train.clone())
                .collect(),
            trains,
            passes: self.passes(),
        }
    }
}
