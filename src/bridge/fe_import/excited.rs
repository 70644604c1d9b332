//! Which modes of an imported model a scene can move at all (issue 40.6).
//!
//! The vehicles load the bridge only through the rails they run on
//! (vertically, and sideways where a wheelset follows its rails), and
//! ground motion only through the inertia load M δ of its directions. A
//! mode whose shape is still at every loaded rail DOF and whose
//! participation in every ground direction vanishes has a generalised
//! force φᵀF(t) ≡ 0: started at rest, its modal coordinate stays 0 and it
//! adds nothing to any record (its share of a static correction's
//! residual, φφᵀF/ω², vanishes with φᵀF). Such a mode — a deck's axial
//! mode under vertical wheels, a lateral pier mode with no lateral load —
//! only costs a slot in `count` and, as the highest kept mode, the time
//! step. [`excited_modes`] finds them; the modal build leaves them out
//! and solves on until `count` modes that the scene moves are kept.

use faer::Mat;

use crate::scene::imported::ImportedModel;

/// Below this share of a mode's largest translation (its motion at the
/// loaded rail DOFs), or of its kinetic energy (its ground participation:
/// Γ²/(φᵀMφ · M_total) below the square), a scene cannot move the mode.
/// Measured on the golden viaduct (`viaduct-2span-axle-loads`, 402 modes
/// to 133 Hz): the ratio is at most 7.6e-11 for the 26 lateral modes a
/// symmetric cross-section keeps still at its rails (round-off of an exact
/// zero) and at least 1.7e-3 for every other mode — its axial modes
/// included, which move the rails vertically through their piers' bending
/// and so stay; 10⁻⁶ sits in the gap, and a mode below it answers a wheel
/// with at most 10⁻¹² of what it would at its largest motion.
pub const UNEXCITED_SHARE: f64 = 1e-6;

/// What loads an imported bridge in a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SceneLoads {
    /// Wheels push the rails sideways (a `train_3d`'s wheelsets follow
    /// their rails laterally): the rails' uy (and rz) DOFs are loaded.
    pub lateral_rails: bool,
    /// Ground motion acts vertically: the inertia load M δ_z.
    pub vertical_ground: bool,
    /// Ground motion acts laterally: the inertia load M δ_y.
    pub lateral_ground: bool,
}

/// For each column of `vectors` (mass-normalised modes of `model`,
/// 1/√kg), whether the scene's loads ([`SceneLoads`]) reach it: its largest
/// value at a loaded rail DOF is at least [`UNEXCITED_SHARE`] of its largest
/// translation anywhere (a rotation DOF of a Hermite rail counts times the
/// rail's longest node spacing: the load between two nodes reaches it
/// through that lever), or its participation in a ground direction
/// carries at least [`UNEXCITED_SHARE`]² of the bridge's mass in it.
///
/// The vertical rail DOFs are always loaded (every vehicle weighs on the
/// rails). Cost O(modes · DOFs).
pub fn excited_modes(model: &ImportedModel, vectors: &Mat<f64>, loads: SceneLoads) -> Vec<bool> {
    use crate::scene::imported::Direction as Dof;
    let mut rail_dofs: Vec<(usize, f64)> = Vec::new();
    let directions: &[usize] = if loads.lateral_rails { &[0, 1] } else { &[0] };
    for &r in &model.track {
        let rail = &model.rails[r];
        let lever = rail
            .x
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(0.0f64, f64::max);
        for &d in directions {
            rail_dofs.extend(rail.displacement[d].iter().flatten().map(|&i| (i, 1.0)));
            rail_dofs.extend(rail.rotation[d].iter().flatten().map(|&i| (i, lever)));
        }
    }
    let ground: Vec<(&[f64], f64)> = [
        (
            loads.vertical_ground,
            &model.vertical_inertia,
            model.translational_mass[2],
        ),
        (
            loads.lateral_ground,
            &model.lateral_inertia,
            model.translational_mass[1],
        ),
    ]
    .into_iter()
    .filter(|&(on, _, mass)| on && mass > 0.0)
    .map(|(_, inertia, mass)| (inertia.as_slice(), mass))
    .collect();
    let translation: Vec<bool> = model
        .dofs
        .iter()
        .map(|(_, d)| matches!(d, Dof::Ux | Dof::Uy | Dof::Uz))
        .collect();
    (0..vectors.ncols())
        .map(|c| {
            let phi = vectors.col(c);
            let largest = (0..phi.nrows())
                .filter(|&i| translation[i])
                .map(|i| phi[i].abs())
                .fold(0.0f64, f64::max);
            // A mode with no translation (a pure twist of the rail
            // nodes) is measured against its largest rotation instead.
            let largest = if largest > 0.0 {
                largest
            } else {
                (0..phi.nrows())
                    .map(|i| phi[i].abs())
                    .fold(0.0f64, f64::max)
            };
            let at_rails = rail_dofs
                .iter()
                .map(|&(i, lever)| phi[i].abs() * lever)
                .fold(0.0f64, f64::max);
            // φᵀMφ = 1 for a mass-normalised mode: Γ²/M is the share of
            // the mass it carries in that direction.
            let carries = ground.iter().any(|&(inertia, mass)| {
                let gamma: f64 = (0..phi.nrows()).map(|i| phi[i] * inertia[i]).sum();
                gamma * gamma / mass >= UNEXCITED_SHARE * UNEXCITED_SHARE
            });
            carries || at_rails >= UNEXCITED_SHARE * largest
        })
        .collect()
}
