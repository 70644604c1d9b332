//! Studies: many runs derived from one scene. Separation maps and speed
//! sweeps run their points in parallel (rayon) and collect them in order, so
//! the result does not depend on the thread count; convergence ladders run
//! one after another so their wall times do not compete.

pub mod converge;
pub mod monte_carlo;
pub mod part_file;
pub mod resonance;
mod resonance_report;
pub mod separation_map;
pub mod shard;
pub mod speed_sweep;
pub mod statistics;

use crate::run::Outcome;
use monte_carlo::MonteCarloResults;
use separation_map::SeparationMap;
use speed_sweep::SweepResults;

/// What a scenario file produces: one scene, or a study.
#[derive(Debug, Clone)]
pub enum Results {
    /// A single scene.
    Scene(Box<Outcome>),
    /// A separation map.
    SeparationMap(SeparationMap),
    /// A speed sweep.
    SpeedSweep(SweepResults),
    /// A Monte Carlo study.
    MonteCarlo(MonteCarloResults),
    /// A railway resonance check.
    ResonanceCheck(resonance::ResonanceResults),
}

/// The run advice of one study point ([`crate::report::advice::run_advice`]):
/// its scene and what its run recorded, summarised as a single run is. The
/// study's scene advice is made once, from the study's own scene
/// ([`Results::advice`]).
pub(crate) fn point_advice(
    scenario: &crate::scene::Scenario,
    model: &crate::model::Model,
    history: &crate::record::History,
) -> Vec<crate::advice::Advice> {
    let summary = crate::report::summary::Summary::new(
        &scenario.name,
        model,
        history,
        &crate::solve::SolveStats::default(),
        0.0,
    );
    crate::report::advice::run_advice(scenario, &summary)
}

impl Results {
    /// Every piece of advice of these results: a scene's summary advice, or
    /// a study's own (from its scene, `scenario`) and its points' gathered
    /// by id ([`crate::advice::gather`]), each with the points it was made
    /// at.
    pub fn advice(&self, scenario: &crate::scene::Scenario) -> Vec<crate::advice::Advice> {
        match self {
            Results::Scene(outcome) => outcome.summary.advice.clone(),
            Results::SeparationMap(map) => map.advice(scenario),
            Results::SpeedSweep(sweep) => sweep.advice(scenario),
            Results::MonteCarlo(mc) => mc.advice(scenario),
            Results::ResonanceCheck(check) => check.advice(scenario),
        }
    }
}

impl SeparationMap {
    /// The map's advice: its scene's, then its points' by id.
    pub fn advice(&self, scenario: &crate::scene::Scenario) -> Vec<crate::advice::Advice> {
        crate::advice::gather(
            crate::plan::advice::scene_advice(scenario),
            self.points.iter().map(|p| {
                (
                    format!(
                        "velocity ratio {}, mass ratio {}",
                        p.velocity_ratio, p.mass_ratio
                    ),
                    p.advice.as_slice(),
                )
            }),
        )
    }
}

impl SweepResults {
    /// The sweep's advice: its scene's, then its points' by id.
    pub fn advice(&self, scenario: &crate::scene::Scenario) -> Vec<crate::advice::Advice> {
        crate::advice::gather(
            crate::plan::advice::scene_advice(scenario),
            self.points.iter().map(|p| {
                (
                    format!(
                        "{}, sample {}, {:.1} km/h",
                        self.roughness[p.roughness],
                        p.sample,
                        crate::report::km_h(p.speed)
                    ),
                    p.advice.as_slice(),
                )
            }),
        )
    }
}

impl MonteCarloResults {
    /// The study's advice: its scene's, then its samples' by id.
    pub fn advice(&self, scenario: &crate::scene::Scenario) -> Vec<crate::advice::Advice> {
        crate::advice::gather(
            crate::plan::advice::scene_advice(scenario),
            self.sample_results.iter().map(|s| {
                (
                    format!("{}, sample {}", self.labels[s.case], s.sample),
                    s.advice.as_slice(),
                )
            }),
        )
    }
}

impl resonance::ResonanceResults {
    /// The check's advice: its scene's, then its runs' by id.
    pub fn advice(&self, scenario: &crate::scene::Scenario) -> Vec<crate::advice::Advice> {
        crate::advice::gather(
            crate::plan::advice::scene_advice(scenario),
            self.points.iter().map(|p| {
                (
                    format!(
                        "{} at {:.1} km/h",
                        self.trains[p.train],
                        crate::report::km_h(p.speed)
                    ),
                    p.advice.as_slice(),
                )
            }),
        )
    }
}

/// A study's summary.json text: `summary` with its `advice` list
/// ([`Results::advice`]) last.
pub(crate) fn summary_json<T: serde::Serialize>(
    summary: &T,
    advice: Vec<crate::advice::Advice>,
) -> String {
    let mut value = serde_json::to_value(summary).expect("summary serialises");
    if let Some(object) = value.as_object_mut() {
        object.insert(
            "advice".into(),
            serde_json::to_value(advice).expect("advice serialises"),
        );
    }
    serde_json::to_string_pretty(&value).expect("summary serialises") + "\n"
}
