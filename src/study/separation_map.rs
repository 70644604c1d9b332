//! Separation map over velocity ratio × vehicle-to-bridge mass ratio (the LCP
//! separation paper, Section 5.1.3 and Fig. 6).
//!
//! Each grid point re-derives the oscillator from its dimensionless groups
//! (velocity and mass ratio from the grid, the others fixed as in the scene),
//! runs the scene with unilateral contact, and records whether any wheel
//! lost contact. Points run in parallel; each is an independent,
//! deterministic run, so the map is the same whatever the thread count.

use std::path::Path;
use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::record::Recorder;
use crate::report;
use crate::run::RunError;
use crate::scene::{Contact, Grid, Quantity, Record, Scenario, Vehicle};
use crate::solve;

/// Result of one grid point.
#[derive(Debug, Clone, Serialize, serde::Deserialize, PartialEq)]
pub struct MapPoint {
    /// α = v / (2 f₁ L).
    pub velocity_ratio: f64,
    /// (m_s + m_u) / (m L).
    pub mass_ratio: f64,
    /// Derived speed, m/s.
    pub speed: f64,
    /// Derived sprung mass, kg.
    pub sprung_mass: f64,
    /// Derived unsprung mass, kg.
    pub unsprung_mass: f64,
    /// Derived suspension stiffness, N/m.
    pub stiffness: f64,
    /// Derived suspension damping, N·s/m.
    pub damping: f64,
    /// Contact stiffness, N/m (elastic contact; 0 otherwise).
    pub contact_stiffness: f64,
    /// Whether the wheel lost contact.
    pub separated: bool,
    /// Contact-loss episodes.
    pub episodes: usize,
    /// Wheel position at the first loss, m.
    pub first_loss_position: Option<f64>,
    /// Largest gap, m.
    pub max_gap: f64,
    /// Smallest contact force, N.
    pub min_contact_force: f64,
    /// What vbi knows about this point's run ([`crate::advice`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub advice: Vec<crate::advice::Advice>,
}

/// The whole map.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeparationMap {
    /// Velocity ratios (grid x).
    pub velocity_ratios: Vec<f64>,
    /// Mass ratios (grid y).
    pub mass_ratios: Vec<f64>,
    /// Points, velocity ratio major: point (i, j) at `i * mass_ratios.len() + j`.
    pub points: Vec<MapPoint>,
    /// Wall time of the whole map, s.
    pub wall_time: f64,
}

/// The scene of one grid point: the oscillator re-derived with the grid's
/// velocity and mass ratios, an elastic stiffness given as a ratio re-derived
/// from the new suspension stiffness.
pub fn point_scenario(
    base: &Scenario,
    bridge: &ModalBridge,
    velocity_ratio: f64,
    mass_ratio: f64,
) -> Scenario {
    let mut scenario = base.clone();
    scenario.study = None;
    let f1 = bridge.frequencies()[0];
    if let Some(Vehicle::Oscillator(o)) = scenario.vehicles.first_mut()
        && let Some(mut groups) = o.dimensionless
    {
        groups.velocity_ratio = velocity_ratio;
        groups.mass_ratio = mass_ratio;
        let lateral_position = o.lateral_position;
        *o = groups.derive(
            f1,
            bridge.length,
            base.bridge.mass_per_length(),
            o.entry_time,
        );
        o.lateral_position = lateral_position;
        if let Contact::Elastic {
            stiffness,
            stiffness_ratio: Some(ratio),
        } = &mut scenario.contact
        {
            *stiffness = *ratio * o.stiffness;
        }
    }
    scenario.record = vec![Record {
        name: "contact_force".into(),
        quantity: Quantity::ContactForce,
        node: None,
        direction: None,
        x: None,
        y: None,
        vehicle: Some(1),
        wheel: Some(1),
        dof: None,
        max_frequency: None,
        frame: Default::default(),
        component: None,
        side: None,
    }];
    scenario
}

fn run_point(
    base: &Scenario,
    bridge: &ModalBridge,
    velocity_ratio: f64,
    mass_ratio: f64,
) -> Result<MapPoint, RunError> {
    let scenario = point_scenario(base, bridge, velocity_ratio, mass_ratio);
    let model = Model::build(&scenario, bridge.clone())?;
    // A map writes no run's history: only extremes and statistics are kept.
    let mut recorder = Recorder::new(&model, &scenario.record)
        .map_err(crate::model::BuildError::from)?
        .without_samples();
    solve::run(&model, &mut recorder, &mut |_, _| {})?;
    let history = recorder.finish();
    let advice = super::point_advice(&scenario, &model, &history);
    let Vehicle::Oscillator(o) = &scenario.vehicles[0] else {
        unreachable!("a separation map has one oscillator")
    };
    let wheel = &history.separation[0];
    Ok(MapPoint {
        velocity_ratio,
        mass_ratio,
        speed: o.speed,
        sprung_mass: o.sprung_mass,
        unsprung_mass: o.unsprung_mass,
        stiffness: o.stiffness,
        damping: o.damping,
        contact_stiffness: match scenario.contact {
            Contact::Elastic { stiffness, .. } => stiffness,
            _ => 0.0,
        },
        separated: wheel.separated,
        episodes: wheel.episodes,
        first_loss_position: wheel.first_loss_position,
        max_gap: wheel.max_gap,
        // The contact force's smallest value over every step.
        min_contact_force: history.extremes[0]
            .all
            .min
            .map_or(f64::INFINITY, |m| m.value),
        advice,
    })
}

/// The grid points, velocity ratio major.
fn grid(velocity_ratio: &Grid, mass_ratio: &Grid) -> Vec<(f64, f64)> {
    let mass_ratios = mass_ratio.values();
    velocity_ratio
        .values()
        .into_iter()
        .flat_map(|a| mass_ratios.iter().map(move |&m| (a, m)))
        .collect()
}

/// Points of the map.
pub fn size(velocity_ratio: &Grid, mass_ratio: &Grid) -> usize {
    velocity_ratio.count.max(1) * mass_ratio.count.max(1)
}

/// Runs the points `range` of the grid (in parallel) and collects them in
/// grid order. `progress` is called with (points done, points in the range)
/// as points finish.
pub fn run_slice(
    base: &Scenario,
    bridge: &ModalBridge,
    velocity_ratio: &Grid,
    mass_ratio: &Grid,
    range: std::ops::Range<usize>,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<MapPoint>, RunError> {
    let grid = grid(velocity_ratio, mass_ratio);
    let total = range.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let token = crate::solve::cancel::current();
    grid[range]
        .par_iter()
        .map(|&(a, m)| {
            let point =
                crate::solve::cancel::in_scope(token.as_ref(), || run_point(base, bridge, a, m));
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(n, total);
            point
        })
        .collect()
}

/// The map from all its points in grid order.
pub fn assemble(
    velocity_ratio: &Grid,
    mass_ratio: &Grid,
    points: Vec<MapPoint>,
    wall_time: f64,
) -> SeparationMap {
    SeparationMap {
        velocity_ratios: velocity_ratio.values(),
        mass_ratios: mass_ratio.values(),
        points,
        wall_time,
    }
}

/// Runs every grid point (in parallel) and collects them in grid order.
/// `progress` is called with (points done, total) as points finish.
pub fn run(
    base: &Scenario,
    bridge: &ModalBridge,
    velocity_ratio: &Grid,
    mass_ratio: &Grid,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<SeparationMap, RunError> {
    let start = Instant::now();
    let all = 0..size(velocity_ratio, mass_ratio);
    let points = run_slice(base, bridge, velocity_ratio, mass_ratio, all, progress)?;
    Ok(assemble(
        velocity_ratio,
        mass_ratio,
        points,
        start.elapsed().as_secs_f64(),
    ))
}

impl SeparationMap {
    /// The map as CSV, one row per grid point with the derived parameters.
    pub fn to_csv(&self) -> Vec<u8> {
        let mut out = csv::Writer::from_writer(Vec::new());
        out.write_record([
            "velocity_ratio",
            "mass_ratio",
            "speed [m/s]",
            "sprung_mass [kg]",
            "unsprung_mass [kg]",
            "stiffness [N/m]",
            "damping [N*s/m]",
            "contact_stiffness [N/m]",
            "separated",
            "episodes",
            "first_loss_position [m]",
            "max_gap [m]",
            "min_contact_force [N]",
        ])
        .expect("writing to memory");
        let number = crate::report::number;
        for p in &self.points {
            out.write_record([
                number(p.velocity_ratio),
                number(p.mass_ratio),
                number(p.speed),
                number(p.sprung_mass),
                number(p.unsprung_mass),
                number(p.stiffness),
                number(p.damping),
                number(p.contact_stiffness),
                p.separated.to_string(),
                p.episodes.to_string(),
                p.first_loss_position.map(number).unwrap_or_default(),
                number(p.max_gap),
                number(p.min_contact_force),
            ])
            .expect("writing to memory");
        }
        out.into_inner().expect("writing to memory")
    }

    /// Number of separated points.
    pub fn separated_count(&self) -> usize {
        self.points.iter().filter(|p| p.separated).count()
    }
}

/// Summary of a separation-map study.
#[derive(Debug, Clone, serde::Serialize)]
pub struct StudySummary {
    /// Scenario name.
    pub scenario: String,
    /// Study type.
    pub study: &'static str,
    /// vbi version.
    pub vbi_version: &'static str,
    /// Wall time of all points, s.
    pub wall_time: f64,
    /// Number of grid points.
    pub points: usize,
    /// Points where the wheel lost contact.
    pub separated: usize,
    /// Velocity ratios swept.
    pub velocity_ratios: Vec<f64>,
    /// Mass ratios swept.
    pub mass_ratios: Vec<f64>,
}

/// Writes a study's `summary.json`, `study.csv`, `separation_map.png` and
/// `resolved.yaml` into `out`.
pub fn write(out: &Path, scenario: &Scenario, map: &SeparationMap) -> Result<(), RunError> {
    report::folder::create_out(out)?;
    let summary = StudySummary {
        scenario: scenario.name.clone(),
        study: "separation_map",
        vbi_version: env!("CARGO_PKG_VERSION"),
        wall_time: map.wall_time,
        points: map.points.len(),
        separated: map.separated_count(),
        velocity_ratios: map.velocity_ratios.clone(),
        mass_ratios: map.mass_ratios.clone(),
    };
    report::write_atomic(&out.join("study.csv"), &map.to_csv())?;
    let state: Vec<bool> = map.points.iter().map(|p| p.separated).collect();
    report::plot::binary_map(
        &out.join("separation_map.png"),
        &format!("{}: wheel–bridge separation", scenario.name),
        "velocity ratio v / (2 f1 L)",
        "vehicle-to-bridge mass ratio (ms + mu) / (m L)",
        &map.velocity_ratios,
        &map.mass_ratios,
        &state,
        "separated",
        "no separation",
    )?;
    report::write_atomic(
        &out.join("resolved.yaml"),
        report::folder::resolved_yaml(scenario).as_bytes(),
    )?;
    let text = crate::study::summary_json(&summary, map.advice(scenario));
    report::write_atomic(&out.join("summary.json"), text.as_bytes())?;
    Ok(())
}
