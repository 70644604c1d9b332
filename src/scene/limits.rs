//! The resolved resource limits (the budgets: `crate::scenario::budget`).

use serde::Serialize;

/// The resolved `limits` section: each bound with its default filled in.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Limits {
    /// Degrees of freedom of the bridge's eigenproblem.
    pub dofs: f64,
    /// Bridge modes kept.
    pub modes: f64,
    /// DOFs × modes² of a beam's eigen solve (default 2e9: 100 modes of
    /// the 157,296-DOF generated viaduct, 1.6e9, take 12–22 s with the checks on
    /// a shared 2-core machine, BENCHMARKS.md; the fuzz input of 4e9 that
    /// took 18–30 s in `vbi check` stays refused).
    pub eigen_work: f64,
    /// Time steps of one run.
    pub steps: f64,
    /// Time steps over all runs of a study.
    pub study_steps: f64,
    /// Work of one run: time steps × wheels × (modes + the wheels' contact
    /// system), [`crate::scenario::budget::run_work`].
    pub run_work: f64,
    /// Wheels over all vehicles.
    pub wheels: f64,
    /// Recorded quantities.
    pub records: f64,
    /// Runs of a study.
    pub study_points: f64,
    /// Terms of a random road's series.
    pub road_terms: f64,
    /// Points of a surface profile: grid nodes of a sampled random track
    /// or road, rows of a measured profile's file.
    pub profile_points: f64,
    /// Multiply-adds of sampling a random profile's series on its grid
    /// (terms × grid nodes, per rail).
    pub profile_work: f64,
    /// Samples of a ground-motion record.
    pub ground_points: f64,
    /// Bytes of results written (estimate), bytes.
    pub output_bytes: f64,
    /// Matrix entries of an imported bridge's file.
    pub import_entries: f64,
}
