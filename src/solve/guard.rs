//! The divergence guard: stops a run whose state stops being finite or whose
//! mechanical energy grows without bound, with a message that says when,
//! where the vehicles were, and the likely cause.
//!
//! Energy: E = ½Σᵢ(q̇ᵢ² + ωᵢ²qᵢ²) (bridge, unit modal masses) +
//! Σᵥ[½u̇ᵀMu̇ + ½(u − u₀)ᵀK(u − u₀)] (vehicles, about their static
//! equilibrium), J. Its scale, E_ref = ½(ΣP)²·Σᵢ max|φᵢ|²/ωᵢ² (the largest
//! static modal strain energy the wheel loads P could store) + Σᵥ ½mᵥ(1 m/s)²
//! (a vehicle bouncing at 1 m/s) + ½Σ m_w (v a k)² (wheels following the
//! roughness and the alignment) + the ground motion's share
//! ([`ground_energy`]: the modal masses Γᵢ² moving at the peak ground
//! velocity and strained statically by the peak ground acceleration as a
//! body force, the vehicles' masses moving at the peak ground velocity),
//! bounds any physical response by a small factor; a run is stopped when E
//! exceeds [`ENERGY_LIMIT`] × E_ref. Cost O(modes + Σ dofᵥ²) per step.

use super::modal::ModalStep;
use super::{SolveError, VehicleState, describe_positions};
use crate::model::Model;

/// Multiple of the energy scale at which a run counts as diverged.
pub const ENERGY_LIMIT: f64 = 1e6;

/// The energy a prescribed support motion can put into the run, J (0
/// without ground motion). In relative coordinates (u = u_abs − δ u_g) a
/// record loads mode i with −Γᵢ üg (Chopra, Dynamics of Structures, §13.1),
/// so per direction with peak acceleration âg (m/s²) and peak velocity v̂g
/// (m/s):
/// - ½ Σᵢ Γᵢ² v̂g²: the modal masses moving at the ground's velocity (a
///   flexible mode stays put while the supports move: its relative velocity
///   is the ground's);
/// - ½ Σᵢ Γᵢ² âg²/ωᵢ²: the static strain energy of the body force −M δ âg
///   (a stiff mode follows the acceleration quasi-statically);
/// - ½ Σᵥ mᵥ v̂g²: every vehicle's mass moving at the ground's velocity
///   relative to its supports.
///
/// Resonance with the record raises the response energy by about (1/2ζ)²
/// (625 at 2 % damping), well inside [`ENERGY_LIMIT`].
pub fn ground_energy(model: &Model) -> f64 {
    let Some(ground) = &model.ground else {
        return 0.0;
    };
    let omegas = &model.bridge.circular_frequencies;
    let vehicle_mass: f64 = model
        .vehicles
        .iter()
        .map(|v| v.mass.diagonal().iter().sum::<f64>())
        .sum();
    let direction = |records: &[std::sync::Arc<crate::scene::GroundRecord>],
                     participation: &[f64]| {
        if records.is_empty() {
            return 0.0;
        }
        // Components in one direction add: their peaks bound the sum's.
        let acceleration: f64 = records.iter().map(|r| r.peak_acceleration()).sum();
        let velocity: f64 = records.iter().map(|r| r.peak_velocity()).sum();
        let modal: f64 = participation
            .iter()
            .zip(omegas)
            .map(|(g, w)| g * g * (velocity * velocity + (acceleration / w.max(1e-6)).powi(2)))
            .sum();
        0.5 * (modal + vehicle_mass * velocity * velocity)
    };
    direction(&ground.vertical, &ground.participation)
        + direction(&ground.lateral, &ground.lateral_participation)
}

/// Precomputed scale and stability facts of one model.
#[derive(Debug, Clone)]
pub struct Guard {
    energy_scale: f64,
    cause: String,
}

impl Guard {
    /// Prepares the guard for `model`.
    pub fn new(model: &Model) -> Self {
        let bridge = &model.bridge;
        let total_load: f64 = model.static_wheel_loads.iter().map(|p| p.abs()).sum();
        // Largest |φᵢ| over the mesh nodes (mode shapes peak near nodes of a
        // fine mesh; this is a scale, not an exact bound).
        let modes = bridge.mode_count();
        let mut peak = vec![0.0f64; modes];
        let mut values = vec![0.0; modes];
        for (x, y) in bridge.sample_points() {
            bridge.mode_values(x, y, &mut values);
            for (p, v) in peak.iter_mut().zip(&values) {
                *p = p.max(v.abs());
            }
        }
        let static_energy: f64 = peak
            .iter()
            .zip(&bridge.circular_frequencies)
            .map(|(p, w)| p * p / (w * w).max(1e-12))
            .sum::<f64>()
            * 0.5
            * total_load
            * total_load;
        // Prescribed motion of the wheels: the vertical profile and the
        // track's alignment (a `train_3d` follows it sideways).
        let slope = model
            .profile
            .slope_scale()
            .hypot(model.profile.alignment_slope_scale());
        let vehicle_energy: f64 = model
            .vehicles
            .iter()
            .map(|v| {
                let mass: f64 = v.mass.diagonal().iter().sum();
                // The fastest the vehicle goes during the run.
                let rough = v.motion().top_speed(model.end_time()) * slope;
                0.5 * mass * (1.0 + rough * rough)
            })
            .sum();
        let (beta, gamma, alpha) = (model.beta, model.gamma, model.alpha);
        let cause = if 2.0 * beta >= gamma {
            format!(
                "the Newmark parameters (β = {beta}, γ = {gamma}, α = {alpha}) are unconditionally \
                 stable, so look for a contact stiffness or Hertz law the time step of {} s cannot \
                 follow, or a physically unstable scene",
                model.time_step
            )
        } else {
            let limit = 1.0 / (0.5 * gamma - beta).sqrt();
            let highest = bridge.circular_frequencies.last().copied().unwrap_or(0.0);
            format!(
                "β = {beta}, γ = {gamma} is only conditionally stable (ωΔt ≤ {limit:.3}); the highest \
                 bridge mode has ωΔt = {:.3}: reduce the time step below {:.3e} s or use β ≥ γ/2",
                highest * model.time_step,
                limit / highest.max(1e-12)
            )
        };
        Self {
            energy_scale: (static_energy + vehicle_energy + ground_energy(model))
                .max(f64::MIN_POSITIVE),
            cause,
        }
    }

    /// The energy scale E_ref, J: a physical response stays within a
    /// small multiple of it.
    pub fn energy_scale(&self) -> f64 {
        self.energy_scale
    }

    /// Mechanical energy of the current state, J.
    pub fn energy(model: &Model, modal: &ModalStep, states: &[VehicleState]) -> f64 {
        Self::vehicle_energy(model, modal.energy(), states)
    }

    /// `bridge_energy` (J) plus the vehicles' energy about their static
    /// equilibrium, J.
    pub fn vehicle_energy(model: &Model, bridge_energy: f64, states: &[VehicleState]) -> f64 {
        let mut energy = bridge_energy;
        for (vehicle, state) in model.vehicles.iter().zip(states) {
            // Over the diagonal blocks only (a train's cars), column by
            // column on the column-major storage.
            let n = vehicle.dofs();
            let (mass, stiffness) = (vehicle.mass.as_slice(), vehicle.stiffness.as_slice());
            let (u, u0, v) = (
                state.displacement.as_slice(),
                state.static_displacement.as_slice(),
                state.velocity.as_slice(),
            );
            for block in &vehicle.blocks {
                for j in block.clone() {
                    let (dj, vj) = (u[j] - u0[j], v[j]);
                    let column = j * n + block.start..j * n + block.end;
                    let (mass, stiffness) = (&mass[column.clone()], &stiffness[column]);
                    let rows = block.clone();
                    let (ub, u0b, vb) = (&u[rows.clone()], &u0[rows.clone()], &v[rows]);
                    // Two short independent sums per column rather than one
                    // long dependent chain over the whole block.
                    let (mut momentum, mut force) = (0.0, 0.0);
                    for i in 0..block.len() {
                        momentum += vb[i] * mass[i];
                        force += (ub[i] - u0b[i]) * stiffness[i];
                    }
                    energy += 0.5 * (momentum * vj + force * dj);
                }
            }
        }
        energy
    }

    /// Checks the state after step `step` at time `t` (s).
    pub fn check(
        &self,
        model: &Model,
        modal: &ModalStep,
        states: &[VehicleState],
        forces: &[f64],
        t: f64,
        step: usize,
    ) -> Result<(), SolveError> {
        self.check_energy(model, Self::energy(model, modal, states), forces, t, step)
    }

    /// [`Self::check`] with the state's mechanical `energy` (J) given.
    pub fn check_energy(
        &self,
        model: &Model,
        energy: f64,
        forces: &[f64],
        t: f64,
        step: usize,
    ) -> Result<(), SolveError> {
        let finite = energy.is_finite() && forces.iter().all(|f| f.is_finite());
        if finite && energy <= ENERGY_LIMIT * self.energy_scale {
            return Ok(());
        }
        let what = if finite {
            format!(
                "the mechanical energy grew to {energy:.3e} J, {:.1e} times its physical scale of {:.3e} J",
                energy / self.energy_scale,
                self.energy_scale
            )
        } else {
            "the state is no longer finite".to_string()
        };
        Err(SolveError::Diverged {
            time: t,
            step,
            positions: describe_positions(model, t),
            cause: format!("{what}; {}", self.cause),
        })
    }
}
