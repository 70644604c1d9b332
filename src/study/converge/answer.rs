//! The cheapest run within tolerance, handed over as the YAML a user pastes
//! into the scene (issue 28 point 8).
//!
//! Every run of a study is the scene with two settings replaced
//! ([`super::at_resolution`]): `solver.time_step` and `bridge.modes` (the
//! lowest `count` modes, no frequency cut-off, the scene's
//! `static_correction` kept). Those two keys, with the step written in
//! Rust's shortest round-trip form, are exactly what makes the scene that
//! run: pasted in place of the scene's own, the scene integrates the chosen
//! run bit for bit.

use super::Convergence;

impl Convergence {
    /// The YAML block that sets the cheapest run's resolution, a comment
    /// line first (`None` when no run is within tolerance):
    ///
    /// ```yaml
    /// # vbi converge: cheapest within 1 % is dt=5e-4 s, 4 modes; replace these keys in the scene
    /// solver:
    ///   time_step: 0.0005
    /// bridge:
    ///   modes: {count: 4}
    /// ```
    pub fn cheapest_yaml(&self) -> Option<String> {
        let run = self.cheapest_run()?;
        let correction = if self.static_correction {
            ", static_correction: true"
        } else {
            ""
        };
        Some(format!(
            "# vbi converge: cheapest within {} % is {}; replace these keys in the scene\n\
             solver:\n  time_step: {}\n\
             bridge:\n  modes: {{count: {}{correction}}}\n",
            super::percent(self.tolerance),
            run.label,
            crate::report::number(run.time_step),
            run.modes,
        ))
    }
}
