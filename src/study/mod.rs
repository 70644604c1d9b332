//! Studies: many runs derived from one scene, run in parallel (rayon) and
//! collected in grid order, so the results do not depend on the thread count.

pub mod converge;
pub mod separation_map;
