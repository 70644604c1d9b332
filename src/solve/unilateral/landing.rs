//! The rigid-contact end of a step for wheels with mass: the hybrid
//! Moreau–Jean landing ([`crate::solve::impact`]) and the period-2 filter of
//! a wheel held on the surface by the displacement-level law.

use super::ContactGeometry;
use super::ContactWheel;
use crate::model::Model;
use crate::solve::VehicleState;
use crate::solve::impact::Impacts;
use crate::solve::modal::ModalStep;
use crate::solve::newmark::Newmark;

/// The surface's velocity and acceleration under contact wheel `contact`
/// at `x` (m) and time `t` (s): u̇ = φ·q̇ + v(φ′·q + r′),
/// ü = φ·q̈ + 2vφ′·q̇ + v²(φ″·q + r″) (+ a(φ′·q + r′) for a vehicle
/// accelerating along its path, see `permanent`); m/s and m/s².
/// `work` holds the mode values, slopes and curvatures.
pub(super) fn surface_motion(
    model: &Model,
    modal: &ModalStep,
    contact: &ContactWheel,
    x: f64,
    t: f64,
    work: [&mut [f64]; 3],
) -> (f64, f64) {
    let [values, slopes, curvatures] = work;
    model.bridge.contact_mode_values_slopes_curvatures(
        x,
        model.wheel_y[contact.wheel],
        values,
        slopes,
        curvatures,
    );
    let vehicle = &model.vehicles[contact.vehicle];
    let (v, a) = (vehicle.speed_at(t), vehicle.acceleration_at(t));
    let (_, dr, ddr) = model
        .profile
        .elevation_slope_curvature_on(model.wheel_rail[contact.wheel], x);
    let (mut velocity, mut acceleration) = (v * dr, v * v * ddr);
    if a != 0.0 {
        acceleration += a * dr;
    }
    for i in 0..values.len() {
        let (q, qd, qdd) = (
            modal.displacement[i],
            modal.velocity[i],
            modal.acceleration[i],
        );
        velocity += values[i] * qd + v * slopes[i] * q;
        acceleration += values[i] * qdd + 2.0 * v * slopes[i] * qd + v * v * curvatures[i] * q;
        if a != 0.0 {
            acceleration += a * slopes[i] * q;
        }
    }
    (velocity, acceleration)
}

/// The end of a hybrid Moreau–Jean step ([`crate::solve::impact`]). A wheel that
/// landed with an impulse: its stored accelerations (vehicle and bridge)
/// become the smooth ones (the step's contact force stripped: it acted as
/// an impulse), nothing is carried into the next step's HHT term, and the
/// wheel is put back on the surface (gap 0). If it stays there — its
/// relative velocity after the impact plus a step of its smooth relative
/// acceleration does not open the gap — its acceleration becomes the
/// surface's, the one the constraint imposes from the next step on (a smooth
/// acceleration there would re-enter the trapezoidal velocity update and
/// make the next contact forces alternate). Then the relative velocities
/// U_{n+1} of every wheel with mass are taken (Uₙ of a landing's law).
#[allow(clippy::too_many_arguments)]
pub(super) fn moreau_jean_finish(
    model: &Model,
    nm: &Newmark,
    impacts: &mut Impacts,
    contacts: &[ContactWheel],
    geometry: &ContactGeometry,
    (lambda, was_apart): (&[f64], &[bool]),
    (wheel_positions, t): (&[f64], f64),
    modal: &mut ModalStep,
    states: &mut [VehicleState],
    contact_gaps: &mut [f64],
    work: [&mut [f64]; 3],
) {
    let modes = model.bridge.mode_count();
    let w = nm.weight();
    let [values, slopes, curvatures] = work;
    impacts.leaving.fill(false);
    impacts.was_on_deck.copy_from_slice(&geometry.on_deck);
    for (c, contact) in contacts.iter().enumerate() {
        if !impacts.landing[c] || lambda[c] == 0.0 {
            continue;
        }
        let Some(column) = &impacts.inverse_mass[c] else {
            continue;
        };
        let shape = &geometry.shapes[c * modes..(c + 1) * modes];
        let state = &mut states[contact.vehicle];
        state.acceleration.axpy(-w * lambda[c], column, 1.0);
        if geometry.on_deck[c] {
            for (a, phi) in modal.acceleration.iter_mut().zip(shape) {
                *a += w * phi * lambda[c];
            }
            modal.forget_contact(shape, lambda[c]);
        }
        state.displacement[contact.dof] -= contact_gaps[contact.wheel];
        contact_gaps[contact.wheel] = 0.0;
        let (surface_velocity, surface_acceleration) = surface_motion(
            model,
            modal,
            contact,
            wheel_positions[contact.wheel],
            t,
            [&mut *values, &mut *slopes, &mut *curvatures],
        );
        let state = &mut states[contact.vehicle];
        let separating = state.velocity[contact.dof] - surface_velocity
            + model.time_step * (state.acceleration[contact.dof] - surface_acceleration);
        if separating <= 0.0 {
            state.acceleration[contact.dof] = surface_acceleration;
        } else {
            // Leaving the surface after the impact (e > 0): in flight from
            // the next step on, so a quick return is another impact.
            impacts.leaving[c] = true;
        }
    }
    for (c, contact) in contacts.iter().enumerate() {
        if !impacts.takes_impacts(c) {
            continue;
        }
        let (surface_velocity, surface_acceleration) = surface_motion(
            model,
            modal,
            contact,
            wheel_positions[contact.wheel],
            t,
            [&mut *values, &mut *slopes, &mut *curvatures],
        );
        let state = &mut states[contact.vehicle];
        let k = contact.dof;
        if !was_apart[c] && !impacts.landing[c] && lambda[c] > 0.0 {
            // Held through the step by the displacement-level law: the
            // period-2 part of its velocity and acceleration is removed
            // (see `smoothed_held_motion`).
            let [velocity, acceleration] = smoothed_held_motion(
                impacts.held_start[c],
                [
                    state.velocity[k],
                    state.acceleration[k],
                    surface_velocity,
                    surface_acceleration,
                ],
            );
            state.velocity[k] = velocity;
            state.acceleration[k] = acceleration;
        }
        impacts.held_start[c] = [
            state.velocity[k],
            state.acceleration[k],
            surface_velocity,
            surface_acceleration,
        ];
    }
    for (c, contact) in contacts.iter().enumerate() {
        if impacts.takes_impacts(c) {
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
}

/// The velocity and acceleration (m/s, m/s²) a wheel held on the surface
/// through a step by the displacement-level law keeps at its end, from
/// `start` and `end` = [wheel velocity, wheel acceleration, surface velocity,
/// surface acceleration] at the step's start and end: the wheel's errors
/// against the surface's motion averaged over the two instants,
/// u̇ := s′ + ½[(u̇ − s′)ₙ₊₁ + (u̇ − s′)ₙ], likewise ü with s″.
///
/// Why: under a position constraint u = s the trapezoidal rule's velocity
/// error eₙ = u̇ₙ − s′ₙ obeys eₙ + eₙ₊₁ = −h²s‴/6, whose solutions are the
/// smooth −h²s‴/12 plus an undamped alternating part ±δ set by how the
/// contact started (a landing's velocity is the surface's exactly, so
/// δ = h²s‴/12). That part makes the acceleration error εₙ (the contact
/// force's, times the wheel mass) obey εₙ + εₙ₊₁ = ∓4δ/h, an alternating
/// force growing as m·s‴·t/3, which touched zero on alternate steps before
/// real lift-offs (spurious flights of 1–3 steps and 1–10 nm, issue 29).
/// The average of two consecutive errors keeps the smooth part (to
/// O(h³) a step) and cancels the alternating one; for the acceleration
/// likewise (εₙ + εₙ₊₁ = −h·s‴/3 − 4eₙ/h, 0 once eₙ is the smooth
/// error). Unlike a restart from the surface's motion (velocity s′,
/// acceleration s″, which biased the force by m·h·s‴/3 a step), the
/// smooth trapezoidal solution is a fixed point: its position is exact
/// and its contact force second order.
fn smoothed_held_motion(start: [f64; 4], end: [f64; 4]) -> [f64; 2] {
    let [v0, a0, s0, sa0] = start;
    let [v1, a1, s1, sa1] = end;
    [
        s1 + 0.5 * ((v1 - s1) + (v0 - s0)),
        sa1 + 0.5 * ((a1 - sa1) + (a0 - sa0)),
    ]
}
