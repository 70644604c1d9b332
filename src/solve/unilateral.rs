//! Unilateral wheel contact as a linear complementarity problem per Newmark
//! step (the LCP separation paper, Sections 3–4).
//!
//! Bridge and vehicles are advanced as uncoupled subsystems whose end-of-step
//! states are affine in the contact forces λ (N, compression positive):
//! q = q* − DΦᵀλ (see [`super::modal`]) and u = u* + Hλ with
//! H = K̂ᵥ⁻¹E (E selects each wheel's DOF). The gap of wheel c,
//! g_c = u_wc − φ_c·q − r(x_c) (m, positive = lifted off), is therefore
//! g = g* + Wλ with the contact compliance W = EᵀH + ΦDΦᵀ (m/N, symmetric
//! positive definite). The contact law closes the step:
//! - rigid: λ ≥ 0, g ≥ 0, λ·g = 0 — LCP(W, g*) (the paper's Eq. for the rigid model);
//! - elastic, tensionless spring k: λ = k·max(0, −g), i.e. s = λ/k + g ≥ 0,
//!   λ ≥ 0, λ·s = 0 — LCP(W + I/k, g*) (its relaxation form, Section 4);
//! - Hertz, λ = C·max(0, −g)^1.5: Newton on the law linearised at the
//!   compression δₖ, λ ≈ Cδₖ^1.5 + bₖ(δ − δₖ) with bₖ = 1.5Cδₖ^0.5, which is
//!   LCP(W + I/bₖ, g* + δₖ/3), repeated until λ settles.
//!
//! One formulation covers every combination of wheels in and out of contact:
//! no trial and error over contact states. A wheel that lands again gets the
//! force the LCP gives, constant over that step; there is no impact model
//! (the paper's assumption). For rigid contact the landing is made perfectly
//! inelastic: the landed wheel's vertical velocity is set to the surface's,
//! so the step's impulse stops it instead of the trapezoidal rule bouncing it
//! back. Elastic and Hertz contact need no such rule: the spring carries the
//! landing, and being undamped it returns the energy (restitution 1). Cost per step: O(modes·wheels²) + O(Σ dofᵥ²) plus
//! the LCP (Lemke, O(wheels²) per pivot); nothing is allocated in the loop.

mod geometry;
mod landing;
mod vehicle_step;

use nalgebra::{DMatrix, DVector};

pub(super) use geometry::{ContactGeometry, ContactWheel, contact_wheels, vehicle_step_matrices};
use landing::{moreau_jean_finish, surface_motion};
use vehicle_step::VehicleStep;

use super::GroundStep;
use super::guard::Guard;
use super::impact::Impacts;
use super::lcp::{LcpWorkspace, solve_warm};
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::time_loop::Stepper;
use super::{SolveError, StepView, VehicleState, describe_positions};
use crate::contact::SEPARATION_GAP;
use crate::model::{ContactLaw, Model};

/// Newton iterations allowed per step for the Hertz law.
pub const HERTZ_MAX_ITERATIONS: usize = 50;
/// Relative change of the contact forces that ends the Hertz iterations.
pub const HERTZ_TOLERANCE: f64 = 1e-10;

/// The LCP method's state and work arrays, for
/// [`super::time_loop::drive`].
#[derive(Debug)]
pub struct Unilateral<'a> {
    model: &'a Model,
    nm: Newmark,
    modal: ModalStep,
    ground: GroundStep,
    /// The step's vehicle weight ratio from the ground motion
    /// ([`GroundStep::step_of`]), set by the predictor, used by the finish.
    gravity_ratio: f64,
    contacts: Vec<ContactWheel>,
    /// Wheels that are moving loads: (flattened wheel, load N).
    load_wheels: Vec<(usize, f64)>,
    states: Vec<VehicleState>,
    steps: Vec<VehicleStep>,
    geometry: ContactGeometry,
    /// Mode values, slopes and curvatures under a landing wheel.
    landing: [Vec<f64>; 3],
    /// Contact forces carried into the next step's HHT term −αλₙ (a
    /// landing impulse is not carried: it has done its work within its
    /// step).
    carried: Vec<f64>,
    /// Moreau–Jean impacts for rigid contact (wheels with mass).
    impacts: Option<Impacts>,
    /// The highest kept mode's circular frequency ω_N, rad/s: where the
    /// residual flexibility turns quasi-static ([`Impacts::weigh_residual`]).
    top_omega: f64,
    rows: Vec<usize>,
    row_lambda: Vec<f64>,
    /// Whether each contact wheel was off the surface after the previous
    /// step.
    was_apart: Vec<bool>,
    free_gap: Vec<f64>,
    lcp_matrix: Vec<f64>,
    lcp_vector: Vec<f64>,
    lambda: Vec<f64>,
    previous: Vec<f64>,
    workspace: LcpWorkspace,
    /// Smallest compression a Hertz linearisation may use, per contact
    /// wheel, m.
    hertz_floor: Vec<f64>,
    contact_forces: Vec<f64>,
    contact_gaps: Vec<f64>,
    wheel_positions: Vec<f64>,
}

/// The contact problem's failure at `t` (s).
fn contact_failure(model: &Model, t: f64, reason: String) -> SolveError {
    SolveError::Contact {
        time: t,
        positions: describe_positions(model, t),
        reason,
    }
}

impl<'a> Unilateral<'a> {
    /// `model` at rest at t = 0 in static equilibrium, every work array
    /// allocated.
    ///
    /// # Errors
    ///
    /// A vehicle whose step matrices cannot be formed
    /// ([`vehicle_step_matrices`]).
    pub fn new(model: &'a Model) -> Result<Self, SolveError> {
        let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
        let modes = model.bridge.mode_count();
        let modal = ModalStep::new(&model.bridge, &nm)
            .with_ground(model.ground_participation())
            .with_lateral_ground(model.lateral_ground_participation());
        let (contacts, load_wheels, columns) = contact_wheels(model);
        let nc = contacts.len();
        let mut states = Vec::with_capacity(model.vehicles.len());
        let mut steps = Vec::with_capacity(model.vehicles.len());
        for (v, vehicle) in model.vehicles.iter().enumerate() {
            let (effective_flexibility, contact_response) =
                vehicle_step_matrices(model, &nm, v, &contacts, &columns)?;
            states.push(VehicleState::at_rest(model, v));
            steps.push(VehicleStep::new(
                vehicle,
                &nm,
                effective_flexibility,
                contact_response,
            ));
        }
        // Every vehicle starts in static equilibrium, so λ₀ is its static
        // wheel load: starting from 0 instead put an impulse α·P on every
        // wheel in the first step (a 5 % force spike on the H20-44 at
        // α = −0.05).
        let carried: Vec<f64> = contacts
            .iter()
            .map(|c| model.static_wheel_loads[c.wheel])
            .collect();
        let impacts = Impacts::new(model, &contacts, &carried);
        let hertz_floor: Vec<f64> = contacts
            .iter()
            .map(|c| {
                (1e-3 * model.contact.compression(model.static_wheel_loads[c.wheel])).max(1e-12)
            })
            .collect();
        let nw = model.wheels.len();
        let contact_forces = model.static_wheel_loads.clone();
        let mut contact_gaps = vec![0.0; nw];
        for c in &contacts {
            contact_gaps[c.wheel] = -model.contact.compression(contact_forces[c.wheel]);
        }
        let mut wheel_positions = vec![0.0; nw];
        model.wheel_positions(0.0, &mut wheel_positions);
        let mut stepper = Self {
            model,
            ground: GroundStep::new(model, &nm),
            nm,
            modal,
            gravity_ratio: 0.0,
            load_wheels,
            states,
            steps,
            geometry: ContactGeometry::new(nc, modes),
            landing: [vec![0.0; modes], vec![0.0; modes], vec![0.0; modes]],
            carried,
            impacts,
            top_omega: model
                .bridge
                .circular_frequencies
                .iter()
                .fold(0.0, |top: f64, &w| top.max(w)),
            rows: Vec::with_capacity(nc),
            row_lambda: vec![0.0; nc],
            was_apart: vec![false; nc],
            free_gap: vec![0.0; nc],
            lcp_matrix: vec![0.0; nc * nc],
            lcp_vector: vec![0.0; nc],
            lambda: vec![0.0; nc],
            previous: vec![0.0; nc],
            workspace: LcpWorkspace::new(nc.max(1)),
            hertz_floor,
            contact_forces,
            contact_gaps,
            wheel_positions,
            contacts,
        };
        stepper.start_impacts();
        Ok(stepper)
    }

    /// The impacts' starting relative velocities: vehicles at rest, the
    /// bridge at rest, the surface moving under the wheels.
    fn start_impacts(&mut self) {
        let model = self.model;
        let modes = model.bridge.mode_count();
        let Self {
            impacts: Some(impacts),
            geometry,
            modal,
            contacts,
            states,
            wheel_positions,
            landing: [values, slopes, curvatures],
            ..
        } = self
        else {
            return;
        };
        geometry.locate(model, &modal.contact_flexibility, contacts, wheel_positions);
        impacts.locate(model, contacts, &geometry.on_deck, wheel_positions, 0.0);
        impacts.was_on_deck.copy_from_slice(&geometry.on_deck);
        for (c, contact) in contacts.iter().enumerate() {
            let (surface_velocity, surface_acceleration) = surface_motion(
                model,
                modal,
                contact,
                wheel_positions[contact.wheel],
                0.0,
                [values, slopes, curvatures],
            );
            let state = &states[contact.vehicle];
            impacts.held_start[c] = [
                state.velocity[contact.dof],
                state.acceleration[contact.dof],
                surface_velocity,
                surface_acceleration,
            ];
            impacts.relative_velocity[c] = impacts.relative(
                c,
                modes,
                states[contact.vehicle].velocity[contact.dof],
                &geometry.shapes[c * modes..(c + 1) * modes],
                &modal.displacement,
                &modal.velocity,
            );
        }
    }

    /// Both subsystems' predictors for the step ending at `t` (s), then
    /// the free gaps g* and the contact compliance W.
    fn predict(&mut self, t: f64) {
        let model = self.model;
        let modes = model.bridge.mode_count();
        let Self {
            nm,
            modal,
            ground,
            gravity_ratio,
            contacts,
            load_wheels,
            states,
            steps,
            geometry,
            carried,
            free_gap,
            wheel_positions,
            ..
        } = self;
        model.wheel_positions(t, wheel_positions);
        *gravity_ratio = ground.step_of(model, modal, t);
        modal.predict(
            nm,
            &model.bridge,
            load_wheels
                .iter()
                .map(|&(flat, load)| (wheel_positions[flat], model.wheel_y[flat], load)),
        );
        // Vehicle predictors u* = K̂⁻¹R̂ with
        // R̂ = f_g − αEλₙ + M hₐ + (1+α)C h_v + α(C u̇ₙ + K uₙ).
        for ((vehicle, state), vs) in model
            .vehicles
            .iter()
            .zip(states.iter())
            .zip(steps.iter_mut())
        {
            vs.load(vehicle, state, nm, *gravity_ratio, ground.lateral_load);
        }
        if nm.alpha != 0.0 {
            for (c, contact) in contacts.iter().enumerate() {
                steps[contact.vehicle].effective_load[contact.dof] -= nm.alpha * carried[c];
            }
        }
        for (vs, vehicle) in steps.iter_mut().zip(&model.vehicles) {
            vs.predict(vehicle);
        }

        // Free gaps g* and the contact compliance W.
        geometry.locate(model, &modal.contact_flexibility, contacts, wheel_positions);
        for (c, contact) in contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let mut deck = 0.0;
            if geometry.on_deck[c] {
                let phi = &geometry.shapes[c * modes..(c + 1) * modes];
                deck = phi.iter().zip(&modal.predictor).map(|(p, q)| p * q).sum();
            }
            free_gap[c] = steps[contact.vehicle].predictor[contact.dof]
                - deck
                - model
                    .profile
                    .elevation_on(model.wheel_rail[contact.wheel], x);
        }
        let steps = &*steps;
        geometry.assemble(model, contacts, wheel_positions, |v| {
            &steps[v].contact_response
        });
    }

    /// The contact law: the step's forces `lambda` from the free gaps and
    /// the compliance (there is at least one contact).
    fn contact_law(&mut self, step: usize, t: f64) -> Result<(), SolveError> {
        match self.model.contact {
            ContactLaw::Rigid { .. } if self.impacts.is_some() => self.impact_step(step, t),
            ContactLaw::Rigid { .. } | ContactLaw::Elastic { .. } => self.plain_step(t),
            ContactLaw::Hertz { coefficient } => self.hertz_step(coefficient, t),
            ContactLaw::Permanent => unreachable!("permanent contact uses the coupled solver"),
        }
    }

    /// Rigid contact with impacts (a hybrid Moreau–Jean step): which rows
    /// take Newton's law, then their LCP.
    fn impact_step(&mut self, step: usize, t: f64) -> Result<(), SolveError> {
        let any_landing = self.impact_rows(step, t);
        let model = self.model;
        let (modes, nc) = (model.bridge.mode_count(), self.contacts.len());
        let Self {
            nm,
            impacts: Some(impacts),
            geometry,
            rows,
            row_lambda,
            free_gap,
            lcp_matrix,
            lcp_vector,
            lambda,
            previous,
            workspace,
            top_omega,
            ..
        } = self
        else {
            unreachable!("rigid contact with impacts");
        };
        impacts.weigh_residual(&geometry.residual, *top_omega);
        let compliance = &geometry.compliance;
        // With a landing in the problem, the gap rows are scaled by a₁
        // (1/s) to the velocity rows' size: the same LCP solution, a
        // better-scaled tableau.
        let gap_scale = if any_landing { nm.a1 } else { 1.0 };
        let m = rows.len();
        for (ra, &a) in rows.iter().enumerate() {
            for (rb, &b) in rows.iter().enumerate() {
                let w = compliance[a * nc + b];
                lcp_matrix[ra * m + rb] = if impacts.landing[a] {
                    impacts.velocity_row_entry(
                        nm,
                        a,
                        modes,
                        w - geometry.residual[a * nc + b],
                        &geometry.scaled[b * modes..(b + 1) * modes],
                    )
                } else if impacts.quasi_static[a] > 0.0 {
                    // The residual deflection's quasi-static share is the
                    // offset below, not a spring the wheel's mass rides on
                    // (impact.rs).
                    gap_scale * (w - impacts.quasi_static[a] * geometry.residual[a * nc + b])
                } else {
                    gap_scale * w
                };
            }
            lcp_vector[ra] = if impacts.landing[a] {
                // Newton's law restitutes an approach only.
                impacts.free_velocity[a]
                    + impacts.restitution * impacts.relative_velocity[a].min(0.0)
            } else {
                gap_scale * (free_gap[a] + impacts.residual_offset[a])
            };
            previous[ra] = lambda[a];
        }
        solve_warm(
            &lcp_matrix[..m * m],
            &lcp_vector[..m],
            &mut row_lambda[..m],
            workspace,
            &previous[..m],
        )
        .map_err(|e| contact_failure(model, t, e.to_string()))?;
        lambda.fill(0.0);
        for (ra, &a) in rows.iter().enumerate() {
            lambda[a] = row_lambda[ra];
        }
        Ok(())
    }

    /// The rows of the step's contact problem (a hybrid Moreau–Jean
    /// step): a wheel with mass that was off the surface at the start of
    /// the step and whose free end-of-step gap closes LANDS: Newton's law
    /// at the velocity level, U_{n+1} + eUₙ ≥ 0 ⊥ P ≥ 0. Every other wheel
    /// in contact at the start keeps the displacement-level law,
    /// g_{n+1} ≥ 0 ⊥ λ ≥ 0, so a run without lift-off is the plain rigid
    /// contact (= permanent contact) and lift-offs are located by the gap
    /// as before. A separated wheel whose free gap stays open takes no
    /// force. Returns whether any wheel lands.
    fn impact_rows(&mut self, step: usize, t: f64) -> bool {
        let model = self.model;
        let modes = model.bridge.mode_count();
        let Self {
            nm,
            modal,
            contacts,
            steps,
            geometry,
            impacts: Some(impacts),
            rows,
            was_apart,
            free_gap,
            wheel_positions,
            ..
        } = self
        else {
            unreachable!("rigid contact with impacts");
        };
        let (shapes, on_deck) = (&geometry.shapes, &geometry.on_deck);
        impacts.locate(model, contacts, on_deck, wheel_positions, t);
        for i in 0..modes {
            impacts.free_modal_velocity[i] = nm.a1 * modal.predictor[i] - modal.damping_history[i];
        }
        rows.clear();
        let mut any_landing = false;
        for (c, contact) in contacts.iter().enumerate() {
            impacts.landing[c] = false;
            // The first step is an impact too for a wheel the surface
            // under it approaches at t = 0 (vehicles start at rest: a
            // surface sloped under the wheel moves into it at v·r′, a
            // velocity jump). So is a step in which a wheel in contact
            // rolls on or off the deck: the deck's slope under it jumps
            // there (v·φ′·q, a kink in the surface), and the
            // displacement-level law would hand the jump back as a
            // trapezoidal rebound.
            let kicked = (step == 1 && impacts.relative_velocity[c] < 0.0)
                || on_deck[c] != impacts.was_on_deck[c];
            if impacts.takes_impacts(c)
                && (was_apart[c] || kicked)
                && (free_gap[c] <= 0.0 || was_apart[c])
            {
                if free_gap[c] > 0.0 {
                    continue;
                }
                let vs = &steps[contact.vehicle];
                let wheel = nm.a1 * vs.predictor[contact.dof] - vs.damping_history[contact.dof];
                impacts.free_velocity[c] = impacts.relative(
                    c,
                    modes,
                    wheel,
                    &shapes[c * modes..(c + 1) * modes],
                    &modal.predictor,
                    &impacts.free_modal_velocity,
                );
                impacts.landing[c] = true;
                any_landing = true;
            }
            rows.push(c);
        }
        any_landing
    }

    /// Rigid contact without impacts, or a tensionless spring: one LCP.
    fn plain_step(&mut self, t: f64) -> Result<(), SolveError> {
        let (model, nc) = (self.model, self.contacts.len());
        let Self {
            geometry,
            free_gap,
            lcp_matrix,
            lambda,
            previous,
            workspace,
            ..
        } = self;
        lcp_matrix.copy_from_slice(&geometry.compliance);
        if let ContactLaw::Elastic { stiffness } = model.contact {
            for c in 0..nc {
                lcp_matrix[c * nc + c] += 1.0 / stiffness;
            }
        }
        // Warm start from the last step's contact set.
        previous.copy_from_slice(lambda);
        solve_warm(lcp_matrix, free_gap, lambda, workspace, previous)
            .map_err(|e| contact_failure(model, t, e.to_string()))?;
        Ok(())
    }

    /// The Hertz law: Newton on the law linearised at the current
    /// compression, one LCP per iteration.
    fn hertz_step(&mut self, coefficient: f64, t: f64) -> Result<(), SolveError> {
        let (model, nc) = (self.model, self.contacts.len());
        let Self {
            geometry,
            free_gap,
            lcp_matrix,
            lcp_vector,
            lambda,
            previous,
            workspace,
            hertz_floor,
            ..
        } = self;
        previous.copy_from_slice(lambda);
        for _ in 0..HERTZ_MAX_ITERATIONS {
            lcp_matrix.copy_from_slice(&geometry.compliance);
            for c in 0..nc {
                // Linearise at the compression of the current iterate,
                // δ = (λ/C)^(2/3), floored at a small fraction of the
                // static one so the tangent stiffness never vanishes.
                let ratio = previous[c].max(0.0) / coefficient;
                let delta = (ratio * ratio).cbrt().max(hertz_floor[c]);
                let tangent = 1.5 * coefficient * delta.sqrt();
                lcp_matrix[c * nc + c] += 1.0 / tangent;
                lcp_vector[c] = free_gap[c] + delta / 3.0;
            }
            // Warm start from the current iterate's contact set.
            solve_warm(lcp_matrix, lcp_vector, lambda, workspace, previous)
                .map_err(|e| contact_failure(model, t, e.to_string()))?;
            let scale = lambda
                .iter()
                .chain(previous.iter())
                .fold(1.0f64, |m, f| m.max(f.abs()));
            let change = lambda
                .iter()
                .zip(previous.iter())
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            previous.copy_from_slice(lambda);
            if change <= HERTZ_TOLERANCE * scale {
                return Ok(());
            }
        }
        Err(contact_failure(
            model,
            t,
            format!(
                "the Hertz contact iterations did not converge in {HERTZ_MAX_ITERATIONS} steps; \
                 reduce the time step"
            ),
        ))
    }

    /// The gaps and reported forces with the step's forces, and both
    /// subsystems' end-of-step states.
    fn finish(&mut self) {
        let model = self.model;
        let (modes, nc) = (model.bridge.mode_count(), self.contacts.len());
        let Self {
            nm,
            modal,
            ground,
            contacts,
            states,
            steps,
            geometry,
            gravity_ratio,
            carried,
            impacts,
            free_gap,
            lambda,
            contact_forces,
            contact_gaps,
            ..
        } = self;
        let (shapes, on_deck, compliance) =
            (&geometry.shapes, &geometry.on_deck, &geometry.compliance);
        if let Some(impacts) = impacts.as_mut() {
            impacts.record(nm, lambda, model.time_step);
        }
        for (c, contact) in contacts.iter().enumerate() {
            let row = &compliance[c * nc..(c + 1) * nc];
            contact_gaps[contact.wheel] = free_gap[c]
                + row
                    .iter()
                    .zip(lambda.iter())
                    .map(|(w, l)| w * l)
                    .sum::<f64>();
            if let Some(impacts) = impacts.as_ref() {
                // A landing's multiplier is an impulse over the step, not a
                // force: the residual (quasi-static) flexibility does not
                // deflect under it (its velocity is neglected in Newton's
                // law too), so its part comes out of every gap.
                let residual = &geometry.residual[c * nc..(c + 1) * nc];
                for d in 0..nc {
                    if impacts.landing[d] {
                        contact_gaps[contact.wheel] -= residual[d] * lambda[d];
                    }
                }
            }
            contact_forces[contact.wheel] = match impacts.as_ref() {
                Some(impacts) => impacts.reported_force(c, lambda[c], model.time_step),
                None => lambda[c],
            };
            if on_deck[c] {
                modal.apply_contact(&shapes[c * modes..(c + 1) * modes], lambda[c]);
            }
            let vs = &mut steps[contact.vehicle];
            // The response is zero outside the wheel's block (its car).
            let (start, len) = contact.block;
            vs.predictor.rows_mut(start, len).axpy(
                lambda[c],
                &vs.contact_response.column(contact.column).rows(start, len),
                1.0,
            );
        }
        modal.finish(nm);
        // The external forces of the step on each vehicle: f_g + wEλ_{n+1} − αEλₙ.
        for vs in steps.iter_mut() {
            vs.recovery_load.fill(0.0);
        }
        for (c, contact) in contacts.iter().enumerate() {
            steps[contact.vehicle].recovery_load[contact.dof] +=
                nm.weight() * lambda[c] - nm.alpha * carried[c];
        }
        for ((state, vs), vehicle) in states.iter_mut().zip(steps.iter_mut()).zip(&model.vehicles) {
            vs.finish(vehicle, state, nm, *gravity_ratio, ground.lateral_load);
        }
        if let Some(impacts) = impacts.as_mut() {
            follow_residual(
                impacts,
                contacts,
                &geometry.residual,
                lambda,
                states,
                contact_gaps,
            );
        }
    }

    /// Rigid landing is perfectly inelastic: a wheel that was off the
    /// surface and carries force again leaves the step moving with the
    /// surface, u̇ = φ·q̇ + v(φ′·q + r′), ü = φ·q̈ + 2vφ′·q̇ + v²(φ″·q + r″),
    /// and its landing impulse is not carried into the next step's HHT
    /// term. Without this the displacement-level constraint and the
    /// trapezoidal rule hand the landing velocity back as a rebound (and
    /// the landing step's acceleration spike re-enters the next velocity
    /// update), so a wheel chatters for ever after one kink in the
    /// profile. Then each wheel's force carried into the next step and
    /// whether it is apart.
    fn land(&mut self, t: f64) {
        let model = self.model;
        let modes = model.bridge.mode_count();
        let Self {
            nm,
            modal,
            contacts,
            states,
            geometry,
            landing: [values, slopes, curvatures],
            carried,
            impacts,
            was_apart,
            lambda,
            contact_gaps,
            wheel_positions,
            ..
        } = self;
        if let Some(impacts) = impacts.as_mut() {
            moreau_jean_finish(
                model,
                nm,
                impacts,
                contacts,
                geometry,
                (lambda, was_apart),
                (wheel_positions, t),
                modal,
                states,
                contact_gaps,
                [values, slopes, curvatures],
            );
        }
        for (c, contact) in contacts.iter().enumerate() {
            let apart = lambda[c] <= 0.0 && contact_gaps[contact.wheel] > SEPARATION_GAP;
            if let Some(impacts) = impacts.as_ref().filter(|i| i.takes_impacts(c)) {
                // A landing impulse has done its work within its step.
                carried[c] = if impacts.landing[c] { 0.0 } else { lambda[c] };
                was_apart[c] = apart || impacts.leaving[c];
                continue;
            }
            carried[c] = lambda[c];
            if matches!(model.contact, ContactLaw::Rigid { .. }) && was_apart[c] && lambda[c] > 0.0
            {
                let (velocity, acceleration) = surface_motion(
                    model,
                    modal,
                    contact,
                    wheel_positions[contact.wheel],
                    t,
                    [values, slopes, curvatures],
                );
                let state = &mut states[contact.vehicle];
                state.velocity[contact.dof] = velocity;
                state.acceleration[contact.dof] = acceleration;
                carried[c] = 0.0;
                modal.forget_contact(&geometry.shapes[c * modes..(c + 1) * modes], lambda[c]);
            }
            was_apart[c] = apart;
        }
    }
}

impl Stepper for Unilateral<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.model)
    }

    fn advance(&mut self, step: usize, t: f64) -> Result<(), SolveError> {
        self.predict(t);
        if !self.contacts.is_empty() {
            self.contact_law(step, t)?;
        }
        // Gaps with the forces, then both subsystems finish the step.
        self.finish();
        self.land(t);
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        let energy = Guard::energy(self.model, &self.modal, &self.states);
        (energy, &self.lambda)
    }

    fn view(&self, _index: usize, step: usize, t: f64) -> StepView<'_> {
        StepView::of(
            step,
            t,
            &self.modal,
            &self.states,
            &self.contact_forces,
            &self.contact_gaps,
            &self.wheel_positions,
        )
    }
}

/// The quasi-static residual deflection at the end of a rigid-contact step
/// (see [`super::impact`]). A wheel with mass in contact (λ_a > 0) takes
/// the offset s_a = (1 − c_a) Σ_b R_ab λ_b over the contacts b held by the
/// displacement-level law (a landing's impulse deflects no residual), one
/// off the surface none; the wheel is moved by the change, −(s_a − sₐ,ₙ)
/// (the residual deflects the deck down under compression, which opens the
/// gap), position only, so that its gap with the whole compliance W is the
/// LCP's. At a lift-off the offset returns to 0 and the wheel leaves from
/// the unloaded surface (left behind, it would start its flight inside the
/// deck and the next step's contact force would push it out, a feedback
/// that grew 27-fold every two steps). A landing wheel is put on the
/// surface by the landing itself.
fn follow_residual(
    impacts: &mut Impacts,
    contacts: &[ContactWheel],
    residual: &[f64],
    lambda: &[f64],
    states: &mut [VehicleState],
    contact_gaps: &mut [f64],
) {
    let nc = contacts.len();
    for (a, contact) in contacts.iter().enumerate() {
        if !impacts.takes_impacts(a) {
            continue;
        }
        let offset: f64 = if lambda[a] > 0.0 {
            impacts.quasi_static[a]
                * (0..nc)
                    .filter(|&b| !impacts.landing[b])
                    .map(|b| residual[a * nc + b] * lambda[b])
                    .sum::<f64>()
        } else {
            0.0
        };
        let change = offset - impacts.residual_offset[a];
        impacts.residual_offset[a] = offset;
        if !impacts.landing[a] {
            states[contact.vehicle].displacement[contact.dof] -= change;
            contact_gaps[contact.wheel] -= change;
        }
    }
}

/// y += a · A x over the diagonal blocks `blocks` of A (zero outside them:
/// a train's cars), so a train of N cars costs N small products instead
/// of one N²-times larger dense one: column by column on the column-major
/// storage, y += (a xⱼ) A[:, j]. One block covering every DOF (every
/// vehicle but a train) keeps nalgebra's dense product.
pub(in crate::solve) fn block_gemv(
    y: &mut DVector<f64>,
    a: f64,
    matrix: &DMatrix<f64>,
    x: &DVector<f64>,
    blocks: &[std::ops::Range<usize>],
) {
    let n = matrix.nrows();
    if blocks.len() == 1 && blocks[0] == (0..n) {
        // One vehicle: nalgebra's product, whose rounding the golden
        // snapshots of rigid contact (chattering wheels) are sensitive to.
        y.gemv(a, matrix, x, 1.0);
        return;
    }
    let (data, x, y) = (matrix.as_slice(), x.as_slice(), y.as_mut_slice());
    for block in blocks {
        let y = &mut y[block.clone()];
        for j in block.clone() {
            let factor = a * x[j];
            let column = &data[j * n + block.start..j * n + block.end];
            for (yi, aij) in y.iter_mut().zip(column) {
                *yi += factor * aij;
            }
        }
    }
}

/// Inverse of a matrix that is zero outside its diagonal blocks `blocks`,
/// block by block (so the inverse is exactly zero outside them too); the
/// plain inverse for one block covering every DOF. `None` if a block is
/// singular.
pub(in crate::solve) fn block_inverse(
    matrix: &DMatrix<f64>,
    blocks: &[std::ops::Range<usize>],
) -> Option<DMatrix<f64>> {
    let n = matrix.nrows();
    if blocks.len() == 1 && blocks[0] == (0..n) {
        return matrix.clone().try_inverse();
    }
    let mut inverse = DMatrix::zeros(n, n);
    for block in blocks {
        let (start, len) = (block.start, block.len());
        let part = matrix
            .view((start, start), (len, len))
            .into_owned()
            .try_inverse()?;
        inverse
            .view_mut((start, start), (len, len))
            .copy_from(&part);
    }
    Some(inverse)
}
