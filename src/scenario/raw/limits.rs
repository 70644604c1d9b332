//! The `limits` section: resource budgets a scene may raise.

use schemars::JsonSchema;
use serde::Deserialize;

/// Resource budgets checked before any work starts. Each bounds one size
/// that the run's time or memory grows with; the defaults suit a
/// workstation. Raise one here for a scene that really needs it, or lift
/// all of them with `vbi run --allow-large`.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LimitsRaw {
    /// Most degrees of freedom of the bridge's eigenproblem (beam free DOFs,
    /// or plate Ritz terms). Dense solve: time ∝ n³, memory ∝ n². Default {{limits.dofs}}.
    #[serde(default)]
    pub dofs: Option<f64>,
    /// Most bridge modes kept. Default {{limits.modes}}.
    #[serde(default)]
    pub modes: Option<f64>,
    /// Most work of a beam's eigen solve, DOFs × modes² (shift-invert
    /// Lanczos with full re-orthogonalisation: time ∝ n k²). Default {{limits.eigen_work}},
    /// some seconds (100 modes of 160,000 DOFs).
    #[serde(default)]
    pub eigen_work: Option<f64>,
    /// Most time steps of one run. Default {{limits.steps}}.
    #[serde(default)]
    pub steps: Option<f64>,
    /// Most time steps summed over all runs of a study. Default {{limits.study_steps}}.
    #[serde(default)]
    pub study_steps: Option<f64>,
    /// Most work of one run: time steps × coupled wheels × (modes + the
    /// wheels' contact system, w(1 + w/135) for w wheels), plus moving-force
    /// axles × modes / 50 a step. A unit is about 30 ns on a 2-core machine
    /// (permanent contact, the dearest); default {{limits.run_work}}, about a minute.
    #[serde(default)]
    pub run_work: Option<f64>,
    /// Most wheels (axles and wheel contacts) over all vehicles. Default {{limits.wheels}}.
    #[serde(default)]
    pub wheels: Option<f64>,
    /// Most recorded quantities. Default {{limits.records}}.
    #[serde(default)]
    pub records: Option<f64>,
    /// Most runs of a study (grid points × surfaces × samples). Default {{limits.study_points}}.
    #[serde(default)]
    pub study_points: Option<f64>,
    /// Most terms of a random road profile's series. Default {{limits.road_terms}}.
    #[serde(default)]
    pub road_terms: Option<f64>,
    /// Most points of a surface profile: grid nodes of a sampled random
    /// track or road (10 per shortest wavelength over the distance the
    /// wheels travel), or rows of a measured profile's file. Default {{limits.profile_points}}.
    #[serde(default)]
    pub profile_points: Option<f64>,
    /// Most multiply-adds of sampling a random profile's series on its
    /// grid: terms × grid nodes, per rail (about 1 ns each). Default {{limits.profile_work}}.
    #[serde(default)]
    pub profile_work: Option<f64>,
    /// Most samples of a ground-motion record (AT2 or CSV). Default {{limits.ground_points}}.
    #[serde(default)]
    pub ground_points: Option<f64>,
    /// Most bytes of results written (estimated), bytes. Default {{limits.output_bytes}}.
    #[serde(default)]
    pub output_bytes: Option<f64>,
    /// Most matrix entries an imported bridge's file may declare or hold
    /// (checked on the header, and on the file's size at 10 bytes an entry,
    /// before anything is read into memory). Default {{limits.import_entries}}.
    #[serde(default)]
    pub import_entries: Option<f64>,
}
