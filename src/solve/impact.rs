//! Moreau–Jean impacts for rigid contact (issue 29), used in a HYBRID step:
//! only at a landing (a wheel separated at the start of the step whose free
//! gap closes; also the t = 0 kick of a surface sloped under a wheel at rest,
//! a wheel rolling on or off the deck, and a quick return after a bounce) does
//! a wheel with mass meet the surface at the velocity level with Newton's
//! impact law; a wheel in contact at the start of the step keeps the
//! displacement-level law (gap ≥ 0 ⊥ force ≥ 0 at the end of the step), so a
//! run without lift-off is the plain rigid contact (= permanent contact). The
//! description below is of the landing rows. One LCP per
//! step for the contact impulses (Moreau 1988; Jean 1999; Acary & Brogliato,
//! *Numerical Methods for Nonsmooth Dynamical Systems*, 2008, §10.1).
//!
//! The smooth part keeps the solver's Newmark/HHT step (with β = 1/4,
//! γ = 1/2, α = 0 it is the θ-method with θ = 1/2 on q̇ = v, M v̇ = f): what
//! makes it Moreau–Jean is that the contact enters as an impulse P per step,
//! never as a force carried into the next step. A step's contact unknown λ
//! (the Newmark force) transmits the impulse P = γΔt(1+α)λ (N·s): the
//! velocities jump by M⁻¹EP and the positions by θΔt M⁻¹EP, θ = β/γ; the
//! stored accelerations are the smooth ones, M⁻¹(f − C u̇ − K u), with the
//! contact part stripped. Then:
//! - active set: wheel c takes part in the step's contact problem when its
//!   free end-of-step gap g*_c ≤ 0 (without contact it would penetrate);
//! - Newton's law on the active set: U_{n+1} + e Uₙ ≥ 0 ⊥ P ≥ 0, U being
//!   the wheel's velocity relative to the surface under it,
//!   U = u̇_w − φ·q̇ − v(φ′·q + r′) (m/s, positive = separating). U_{n+1} is
//!   affine in λ: Newmark's u̇ = a₁u − h_v makes every velocity change a₁
//!   times the displacement change, so U = U* + Vλ with
//!   V_cd = a₁(H + ΦDΦᵀ)_cd + v_c φ′_c·Dφ_d (the residual static flexibility
//!   is quasi-static: its velocity is neglected, as everywhere in vbi);
//! - a wheel that carried an impulse is put back on the surface (its
//!   displacement shifted by −g): the velocity-level law leaves an O(Δt²)
//!   drift of the gap under a rolling wheel and an O(Δt) one at a landing,
//!   which the projection removes (Acary & Brogliato's projected
//!   Moreau–Jean), so a wheel in contact has gap 0 and force > 0.
//!
//! - the residual (static-correction) flexibility R under a wheel with
//!   mass is quasi-static where the wheel on it, ω_r = 1/√(m R), would
//!   oscillate above the kept band (a beam at a few modes): it deflects
//!   under the contact forces without inertia, so the wheel follows it
//!   kinematically, not through its mass — the weight 1 − c of
//!   [`residual_coupling`], as in the permanent-contact solver. The
//!   displacement-level rows hold the gap with that share of the previous
//!   step's residual deflection, s = (1 − c)Rλₙ (a known offset,
//!   [`Impacts::residual_offset`]), and W − (1 − c)R as the compliance; at
//!   the end of the step a wheel in contact is moved by the change of s
//!   (its velocity and acceleration untouched), so its gap with the whole
//!   compliance W is the LCP's. Coupled through its mass instead, the wheel
//!   on the residual spring 1/R is a contact mode at √(1/(R m)) — 1.2 kHz
//!   for the 1 t wheel on a 20 m beam keeping 10 modes, far above the
//!   modes the correction stands for — which a landing (the force jumping
//!   from 0 to the wheel load) set ringing, and which each halving of Δt
//!   resolved further: the mid-span peak of the 4.5 mm hopping case grew by
//!   1.1, 2.6 and 6.8 µm per halving from Δt = 5e-5 s (issue 43, point 4).
//!
//! Positions and velocities converge at first order in Δt through impacts
//! and accumulations of impacts; with e = 1, θ = 1/2 and no damping the
//! impacts conserve energy. The reported contact force is the impulse
//! averaged over the last [`FORCE_WINDOW`] (which converges as Δt → 0),
//! never the impulse over one step (a landing's I/Δt spike).
//!
//! Only wheels whose vehicle block has an invertible mass matrix take
//! impacts; a massless contact point (the H20-44's, under a tyre
//! spring–dashpot) keeps the displacement-level law, which needs none.

use nalgebra::DVector;

use super::newmark::Newmark;
use super::residual_rates::residual_coupling;
use super::unilateral::{ContactWheel, block_inverse};
use crate::model::{ContactLaw, Model};

/// Window over which a rigid-contact force is averaged for reporting, s:
/// short against every vehicle and bridge period of interest (a 1 kHz
/// low-pass), long against the steps that resolve them.
pub const FORCE_WINDOW: f64 = 1.0e-3;

/// The Moreau–Jean state of a rigid-contact run.
#[derive(Debug, Clone)]
pub(super) struct Impacts {
    /// Newton's coefficient of restitution e.
    pub restitution: f64,
    /// Per contact wheel: M⁻¹ column at its DOF (zero outside its block),
    /// `None` for a wheel without mass (displacement-level law).
    pub inverse_mass: Vec<Option<DVector<f64>>>,
    /// Relative normal velocity Uₙ of each contact wheel, m/s.
    pub relative_velocity: Vec<f64>,
    /// Free relative velocity U*_{n+1}, m/s.
    pub free_velocity: Vec<f64>,
    /// Mode slopes φ′ at each contact, contact-major (0 off the deck), 1/m.
    pub slopes: Vec<f64>,
    /// Surface slope r′ and path speed v at each contact.
    pub surface_slope: Vec<f64>,
    pub speed: Vec<f64>,
    /// The step's impulse per contact, N·s.
    pub impulse: Vec<f64>,
    /// Whether contact `c` lands this step (separated at its start, its free
    /// gap closing): Newton's law at the velocity level.
    pub landing: Vec<bool>,
    /// Whether contact `c` left the surface after this step's impact (e > 0).
    pub leaving: Vec<bool>,
    /// Whether contact `c` was on the deck at the start of the step.
    pub was_on_deck: Vec<bool>,
    /// Per contact at the start of the step (the end of the previous one):
    /// the wheel's velocity (m/s) and acceleration (m/s²) and the surface's
    /// under it, u̇ and ü (see `unilateral::landing::surface_motion`), for the
    /// period-2 filter of a held wheel (`unilateral::landing::smoothed_held_motion`).
    pub held_start: Vec<[f64; 4]>,
    /// Steps since contact `c`'s last landing (`usize::MAX`: none yet).
    since_landing: Vec<usize>,
    /// Impulses of the last `window` steps, ring buffer, step-major.
    history: Vec<f64>,
    window: usize,
    cursor: usize,
    /// Free modal velocities q̇* = a₁q* − h_v of the step, 1/s·(modal units).
    pub free_modal_velocity: Vec<f64>,
    /// The quasi-static residual deflection under each contact at the end
    /// of the last step, m: s_c = (1 − c_c) Σ_d R_cd λ_d over the contacts
    /// d held by the displacement-level law (a landing's multiplier is an
    /// impulse and deflects no residual), 0 off the surface.
    pub residual_offset: Vec<f64>,
    /// The quasi-static share 1 − c_c of each contact's residual this step
    /// ([`Impacts::weigh_residual`]).
    pub quasi_static: Vec<f64>,
    /// Each contact's DOF in its vehicle (the row of `inverse_mass`).
    dof: Vec<usize>,
    /// Work arrays for the mode values and curvatures.
    values: Vec<f64>,
    curvatures: Vec<f64>,
}

impl Impacts {
    /// `None` unless the contact is rigid. Every vehicle starts in static
    /// equilibrium and in contact (the displacement-level law), so the force
    /// window starts full of the static wheel load's impulses.
    pub fn new(model: &Model, contacts: &[ContactWheel], static_loads: &[f64]) -> Option<Self> {
        let ContactLaw::Rigid { restitution } = model.contact else {
            return None;
        };
        let inverses: Vec<_> = model
            .vehicles
            .iter()
            .map(|v| block_inverse(&v.mass, &v.blocks))
            .collect();
        let inverse_mass: Vec<Option<DVector<f64>>> = contacts
            .iter()
            .map(|c| {
                let vehicle = &model.vehicles[c.vehicle];
                if vehicle.mass[(c.dof, c.dof)] <= 0.0 {
                    return None;
                }
                inverses[c.vehicle]
                    .as_ref()
                    .map(|inv| inv.column(c.dof).into_owned())
            })
            .collect();
        let (nc, modes) = (contacts.len(), model.bridge.mode_count());
        let window = ((FORCE_WINDOW / model.time_step).round() as usize).max(1);
        let mut history = vec![0.0; window * nc];
        for (c, column) in inverse_mass.iter().enumerate() {
            if column.is_some() {
                for k in 0..window {
                    history[k * nc + c] = static_loads[c] * model.time_step;
                }
            }
        }
        Some(Self {
            restitution,
            inverse_mass,
            relative_velocity: vec![0.0; nc],
            free_velocity: vec![0.0; nc],
            slopes: vec![0.0; nc * modes],
            surface_slope: vec![0.0; nc],
            speed: vec![0.0; nc],
            impulse: vec![0.0; nc],
            landing: vec![false; nc],
            leaving: vec![false; nc],
            was_on_deck: vec![false; nc],
            held_start: vec![[0.0; 4]; nc],
            since_landing: vec![usize::MAX; nc],
            history,
            free_modal_velocity: vec![0.0; modes],
            window,
            cursor: 0,
            residual_offset: vec![0.0; nc],
            quasi_static: vec![0.0; nc],
            dof: contacts.iter().map(|c| c.dof).collect(),
            values: vec![0.0; modes],
            curvatures: vec![0.0; modes],
        })
    }

    /// The quasi-static share 1 − c of each contact's residual flexibility
    /// this step (see the module doc), c = [`residual_coupling`] of its
    /// wheel's effective mass 1/(M⁻¹)_cc, its residual flexibility R_cc and
    /// the highest kept mode ω_N (rad/s) — the weight with which the
    /// permanent-contact solver lets a wheel's mass ride the residual, so
    /// that the two agree: 1 on beams at a few modes (ω_r far above ω_N),
    /// 0 where the residual is a track's compliance below the kept band;
    /// 0 for a wheel without mass. `residual` is R, row-major nc × nc, m/N.
    pub fn weigh_residual(&mut self, residual: &[f64], top_omega: f64) {
        let nc = self.quasi_static.len();
        for c in 0..nc {
            self.quasi_static[c] = match &self.inverse_mass[c] {
                Some(column) => {
                    let mass = 1.0 / column[self.dof[c]];
                    1.0 - residual_coupling(mass, residual[c * nc + c], top_omega)
                }
                None => 0.0,
            };
        }
    }

    /// Whether contact `c` takes Newton's law (its wheel has mass).
    #[inline]
    pub fn takes_impacts(&self, c: usize) -> bool {
        self.inverse_mass[c].is_some()
    }

    /// Mode slopes, surface slope and speed at each contact at time `t`.
    pub fn locate(
        &mut self,
        model: &Model,
        contacts: &[ContactWheel],
        on_deck: &[bool],
        wheel_positions: &[f64],
        t: f64,
    ) {
        let modes = model.bridge.mode_count();
        for (c, contact) in contacts.iter().enumerate() {
            if !self.takes_impacts(c) {
                continue;
            }
            let x = wheel_positions[contact.wheel];
            let slopes = &mut self.slopes[c * modes..(c + 1) * modes];
            if on_deck[c] {
                model.bridge.contact_mode_values_slopes_curvatures(
                    x,
                    model.wheel_y[contact.wheel],
                    &mut self.values,
                    slopes,
                    &mut self.curvatures,
                );
            } else {
                slopes.fill(0.0);
            }
            self.surface_slope[c] = model
                .profile
                .elevation_slope_curvature_on(model.wheel_rail[contact.wheel], x)
                .1;
            self.speed[c] = model.vehicles[contact.vehicle].speed_at(t);
        }
    }

    /// U = u̇_w − φ·q̇ − v(φ′·q + r′) of contact `c` for wheel velocity
    /// `wheel_velocity` (m/s), modal displacements `q` and velocities `qd`,
    /// mode values `shape` (after [`Self::locate`]).
    pub fn relative(
        &self,
        c: usize,
        modes: usize,
        wheel_velocity: f64,
        shape: &[f64],
        q: &[f64],
        qd: &[f64],
    ) -> f64 {
        let slopes = &self.slopes[c * modes..(c + 1) * modes];
        let mut surface = self.speed[c] * self.surface_slope[c];
        for i in 0..modes {
            surface += shape[i] * qd[i] + self.speed[c] * slopes[i] * q[i];
        }
        wheel_velocity - surface
    }

    /// Row `a`, column `b` of V (see the module doc): `compliance_less_residual`
    /// is (H + ΦDΦᵀ)_ab, `scaled_b` is Dφ_b.
    #[inline]
    pub fn velocity_row_entry(
        &self,
        nm: &Newmark,
        a: usize,
        modes: usize,
        compliance_less_residual: f64,
        scaled_b: &[f64],
    ) -> f64 {
        let slopes = &self.slopes[a * modes..(a + 1) * modes];
        let coupling: f64 = slopes.iter().zip(scaled_b).map(|(s, d)| s * d).sum();
        nm.a1 * compliance_less_residual + self.speed[a] * coupling
    }

    /// Records the step's impulses: P = γΔt(1+α)λ for a landing, λΔt for a
    /// wheel under the displacement-level law (λ its force over the step).
    pub fn record(&mut self, nm: &Newmark, lambda: &[f64], dt: f64) {
        let nc = self.impulse.len();
        for (c, l) in lambda.iter().enumerate() {
            self.impulse[c] = if !self.takes_impacts(c) {
                0.0
            } else if self.landing[c] {
                nm.a7 * nm.weight() * l
            } else {
                l * dt
            };
            self.since_landing[c] = if self.landing[c] && *l > 0.0 {
                0
            } else {
                self.since_landing[c].saturating_add(1)
            };
        }
        let row = &mut self.history[self.cursor * nc..(self.cursor + 1) * nc];
        row.copy_from_slice(&self.impulse);
        self.cursor = (self.cursor + 1) % self.window;
    }

    /// The force reported for contact `c`, N: within [`FORCE_WINDOW`] after
    /// a landing the impulse over the last window divided by it (the landing
    /// impulse spread over the window, which converges as Δt → 0, instead of
    /// its step's P/Δt spike); otherwise the step's force `lambda`.
    pub fn reported_force(&self, c: usize, lambda: f64, dt: f64) -> f64 {
        if self.takes_impacts(c) && self.since_landing[c] < self.window {
            self.averaged_force(c, dt)
        } else {
            lambda
        }
    }

    /// The impulse of contact `c` over the last window divided by it, N.
    pub fn averaged_force(&self, c: usize, dt: f64) -> f64 {
        let nc = self.impulse.len();
        let sum: f64 = (0..self.window).map(|k| self.history[k * nc + c]).sum();
        sum / (self.window as f64 * dt)
    }
}
