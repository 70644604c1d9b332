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
