//! What a scenario file asks for, run: its single scene ([`crate::run`]) or
//! its study ([`crate::study`]). The one place that knows every study; it
//! sits above them, so neither `run` nor a study reaches up to it.

use std::path::Path;

use crate::plan::Loaded;
use crate::run::{self, RunError};
use crate::scene::Study;
pub use crate::study::Results;
use crate::study::{monte_carlo, separation_map, speed_sweep};

/// Runs the scenario's study if it has one, else the scene.
/// `progress` gets (done, total) in steps (scene) or grid points (study).
pub fn execute(
    loaded: Loaded,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Results, RunError> {
    match &loaded.scenario.study {
        Some(Study::SeparationMap {
            velocity_ratio,
            mass_ratio,
        }) => Ok(Results::SeparationMap(separation_map::run(
            &loaded.scenario,
            &loaded.bridge,
            velocity_ratio,
            mass_ratio,
            progress,
        )?)),
        Some(Study::SpeedSweep(sweep)) => Ok(Results::SpeedSweep(speed_sweep::run(
            &loaded.scenario,
            &loaded.bridge,
            sweep,
            progress,
        )?)),
        Some(Study::ResonanceCheck(check)) => Ok(Results::ResonanceCheck(
            crate::study::resonance::run(&loaded.scenario, &loaded.bridge, check, progress)?,
        )),
        Some(Study::MonteCarlo(mc)) => Ok(Results::MonteCarlo(monte_carlo::run(
            &loaded.scenario,
            &loaded.bridge,
            mc,
            progress,
        )?)),
        None => Ok(Results::Scene(Box::new(run::simulate(
            loaded,
            &mut |d, t| progress(d, t),
        )?))),
    }
}

/// [`execute`] with a single scene's rows streamed to the output folder
/// `out` ([`run::simulate_into`]); studies run as in [`execute`].
pub fn execute_into(
    loaded: Loaded,
    out: &Path,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Results, RunError> {
    if loaded.scenario.study.is_some() {
        return execute(loaded, progress);
    }
    Ok(Results::Scene(Box::new(run::simulate_into(
        loaded,
        out,
        &mut |d, t| progress(d, t),
    )?)))
}
