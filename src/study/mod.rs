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
