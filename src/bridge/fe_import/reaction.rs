//! Support reactions of an imported model, read from its own equations at
//! the constrained DOFs (issue 40.1).
//!
//! A DOF c listed under `constrained` keeps its rows of K and M (the free
//! columns, [`SupportRow`]); its row of the full equations of motion, with
//! u_c = 0, is
//!
//! K_cf u_f + M_cf ü_f = F_c + R_c,
//!
//! so the force the support exerts on the structure is
//! R_c = K_cf u_f + M_cf ü_f − F_c (F_c: a load standing on the
//! constrained DOF itself).
//!
//! With the kept modes and the mode-acceleration form (the static response
//! to the loads exact, the modes carrying only what is dynamic),
//! u_f = K_ff⁻¹F_f + Φ(q − q_s), q_s = Ω⁻²ΦᵀF, and each mode's equation
//! q̈ⱼ + 2ζⱼωⱼq̇ⱼ + ωⱼ²qⱼ = φⱼᵀF gives qⱼ − q_s,ⱼ + (2ζⱼ/ωⱼ)q̇ⱼ = −q̈ⱼ/ωⱼ².
//! Taking the modal damping as stiffness-like at the support rows (mode by
//! mode (2ζⱼ/ωⱼ) K φⱼ, which the free rows' 2ζⱼωⱼ M φⱼ equals there), so
//! that it is internal (δᵀK = 0 for a rigid translation δ, hence it sums to
//! nothing over the supports, as a damper inside the structure does):
//!
//! R_c = ρ_c(F) + Σⱼ (M_cf φⱼ − K_cf φⱼ/ωⱼ²) q̈ⱼ,
//!
//! with ρ_c the exact static reaction under the loads: per unit downward
//! load at a track point of weights N, ρ_c = N_c − N_fᵀ K_ff⁻¹ K_fc (the
//! share standing on the support itself minus what the free DOFs pass to
//! it), one solve with K's factor per support.
//!
//! Force balance follows exactly, whatever modes are kept: summing over
//! every vertical support, δᵀK = 0 gives Σ_c K_cf φⱼ = −ω²Σ_f (Mφⱼ)_f
//! minus nothing, so Σ_c R_c = Σ_w F_w + Σⱼ (δᵀMφⱼ) q̈ⱼ: the reactions carry
//! the loads on the deck plus the deck's inertia force ∫m ü, to round-off.
//! (A model with springs to the ground, K δ ≠ 0, passes part of its load
//! through them: those are supports this sum does not list.)

use super::super::BridgeError;
use super::modal::ImportedShapes;
use super::track::{RailDirection, TrackField};
use crate::scene::imported::{Direction, RailEntry};

/// One support's reaction: its modal coefficients and its static
/// influence line along the track.
#[derive(Debug, Clone)]
pub struct SupportReaction {
    /// The constrained node.
    pub node: u64,
    /// The constrained direction.
    pub direction: Direction,
    /// K_cf φⱼ per kept mode, N·√kg… per unit modal displacement (the
    /// plain modal reaction, without the static correction).
    pub stiffness_modal: Vec<f64>,
    /// M_cf φⱼ per kept mode, per unit modal acceleration.
    pub mass_modal: Vec<f64>,
    /// M_cf φⱼ − K_cf φⱼ/ωⱼ² per kept mode: the mode-acceleration form's
    /// coefficient of q̈ⱼ (module doc).
    pub corrected_modal: Vec<f64>,
    /// ρ_c along the track: the static reaction per unit downward load at
    /// each track point, dimensionless (1 with the load on the support).
    pub influence: TrackField,
    /// N_c along the track: the share of a unit load standing on the
    /// constrained DOF itself (the plain modal form's F_c).
    pub direct: TrackField,
    /// How a load enters the track at its ends (its coupling weight).
    pub entry: RailEntry,
    /// The static reaction per unit vertical ground acceleration (the
    /// supports moving with the ground: −ρ_c of the inertia load M δ plus
    /// the support row's own (M δ)_c), kg; with `lateral_ground` for a
    /// lateral one. Without the static correction only the rows' own
    /// inertia.
    pub vertical_ground: f64,
    /// As `vertical_ground`, for a unit lateral ground acceleration, kg.
    pub lateral_ground: f64,
    /// The same two without the static share (the plain modal form), kg.
    pub plain_ground: [f64; 2],
    /// The support's rows K_cf and M_cf: (free DOF, entry), for the
    /// reaction from a nodal state ([`Self::nodal_reaction`]).
    stiffness_row: Vec<(usize, f64)>,
    mass_row: Vec<(usize, f64)>,
}

impl SupportReaction {
    /// The exact static reaction under downward forces `forces` (N) of the
    /// wheels `on_deck` at `positions` (m) along the track and `y` (m)
    /// across it, N, upward on the structure. Cost O(wheels).
    pub fn static_reaction(
        &self,
        positions: &[f64],
        y: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> f64 {
        self.along(&self.influence, positions, y, forces, on_deck)
    }

    /// The share of the loads standing on the constrained DOF itself, N:
    /// what passes into the support without loading a free DOF (the plain
    /// modal reaction's −F_c). Cost O(wheels).
    pub fn direct_load(
        &self,
        positions: &[f64],
        y: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> f64 {
        self.along(&self.direct, positions, y, forces, on_deck)
    }

    /// The reaction's rows applied to a nodal state (a direct run's, exact
    /// in space): K_cf (u + c_K u̇) + M_cf (ü + c_M u̇), N (or N·m), with
    /// the Rayleigh coefficients `damping` (c_M 1/s, c_K s): the support's
    /// row of M ü + C u̇ + K u, as a beam support's shear jump
    /// ([`crate::bridge::section::NodalSection`]). Without the loads
    /// standing on the DOF ([`Self::direct_load`]) and the row's own
    /// inertia under ground motion (`plain_ground`). Cost O(row entries).
    pub fn nodal_reaction(
        &self,
        state: &crate::bridge::NodalState<'_>,
        damping: (f64, f64),
    ) -> f64 {
        let (c_m, c_k) = damping;
        let elastic: f64 = self
            .stiffness_row
            .iter()
            .map(|&(f, k)| k * (state.displacement[f] + c_k * state.velocity[f]))
            .sum();
        let inertia: f64 = self
            .mass_row
            .iter()
            .map(|&(f, m)| m * (state.acceleration[f] + c_m * state.velocity[f]))
            .sum();
        elastic + inertia
    }

    /// Σ_w F_w e_w f(x_w, y_w) for a field f along the track, e_w the entry
    /// weight.
    fn along(
        &self,
        field: &TrackField,
        positions: &[f64],
        y: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> f64 {
        let mut value = [0.0];
        on_deck
            .iter()
            .map(|&w| {
                field.evaluate_at(positions[w], y[w], &mut value, &mut [], &mut []);
                let coupling = if self.entry.is_active() {
                    self.entry.weight(positions[w]).0
                } else {
                    1.0
                };
                forces[w] * coupling * value[0]
            })
            .sum()
    }
}

impl ImportedShapes {
    /// The reaction of support `support` (an index into the model's
    /// `supports`), given the kept modes' circular frequencies `omegas`
    /// (rad/s). Two solves with K's factor (the influence line and the
    /// inertia loads' shares). Errors if K cannot be factorised.
    pub fn support_reaction(
        &self,
        support: usize,
        omegas: &[f64],
    ) -> Result<SupportReaction, BridgeError> {
        let model = &self.model;
        let row = &model.supports[support];
        let modes = self.vectors.ncols();
        let project = |entries: &[(usize, f64)]| -> Vec<f64> {
            (0..modes)
                .map(|j| entries.iter().map(|&(f, v)| v * self.vectors[(f, j)]).sum())
                .collect()
        };
        let stiffness_modal = project(&row.stiffness);
        let mass_modal = project(&row.mass);
        let corrected_modal = (0..modes)
            .map(|j| mass_modal[j] - stiffness_modal[j] / (omegas[j] * omegas[j]))
            .collect();
        // g = K_ff⁻¹ K_fc: the free DOFs' static response to the support's
        // column; ρ_c = N_c − N_fᵀ g.
        let mut load = vec![0.0; model.dofs.len()];
        for &(f, v) in &row.stiffness {
            load[f] += v;
        }
        let factor = self.pencil.stiffness_factor()?;
        factor.solve_in_place(&mut load, &mut factor.workspace()?);
        let g = load;
        let own_slot = match row.direction {
            Direction::Uz => Some(0),
            Direction::Ry => Some(1),
            _ => None,
        };
        let own = |node: u64, slot: usize| {
            if node == row.node && own_slot == Some(slot) {
                1.0
            } else {
                0.0
            }
        };
        let along = |free: &dyn Fn(usize) -> f64| {
            TrackField::new(
                model
                    .track
                    .iter()
                    .map(|&r| {
                        model.rails[r].field_with_constrained(
                            RailDirection::Vertical,
                            1,
                            |f, _| free(f),
                            own,
                        )
                    })
                    .collect(),
            )
        };
        let influence = along(&|f| -g[f]);
        let direct = along(&|_| 0.0);
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        Ok(SupportReaction {
            node: row.node,
            direction: row.direction,
            stiffness_modal,
            mass_modal,
            corrected_modal,
            influence,
            direct,
            entry: model.entry,
            vertical_ground: row.vertical_inertia - dot(&g, &model.vertical_inertia),
            lateral_ground: row.lateral_inertia - dot(&g, &model.lateral_inertia),
            plain_ground: [row.vertical_inertia, row.lateral_inertia],
            stiffness_row: row.stiffness.clone(),
            mass_row: row.mass.clone(),
        })
    }
}
