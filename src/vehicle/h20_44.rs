//! The plate paper's two-axle truck with seven degrees of freedom (its
//! Section 2.2, Figs. 2–3 and Appendix A, after Marchesiello et al. 1999 and
//! Zhu & Law 2002). The paper calls it H20-44 "in accordance with AASHTO";
//! its preset ([`crate::scenario::truck::H20_44_PRESET`]) carries the static
//! wheel forces the paper states (Section 3.2: Fg1 = 58.81 kN per front
//! wheel, Fg3 = 32.42 kN per rear wheel, the empty truck), not AASHTO's
//! H20-44 axle loads of 8 and 32 kip ([`crate::scene::aashto`]).
//!
//! DOFs (vertical positive upward, from static equilibrium when recorded):
//! body bounce z_v (m), pitch θ_v (rad, nose up), roll φ_v (rad, left side
//! up); front axle bounce z₁ and roll φ₁; rear axle bounce z₂ and roll φ₂;
//! then four massless contact points u_c (m), one under each tyre. Wheels,
//! as in the paper's Eqs. 5.1–5.4: 1 front right, 2 front left, 3 rear
//! right, 4 rear left ("left" = +y, the left of the direction of travel).
//!
//! A point of the body at distance d ahead of the centre of gravity and e to
//! the left moves by z_v + d θ_v + e φ_v; a point of an axle at e to the left
//! by zₐ + e φₐ. Each suspension spring–dashpot joins the body to its axle at
//! e = ±s/2 (the paper's Eqs. 7.1–7.4); each tyre joins its axle at
//! e = ±s_t/2 to its contact point (Eqs. 5.1–5.4). Assembling every element
//! as K += k (a − b)(a − b)ᵀ, with a and b the kinematic rows of its two
//! ends, gives the paper's symmetric [K_v] and [C_v] (Appendix A, Eq. A.5–A.6)
//! without writing the 28 entries out by hand. The contact points carry the
//! interaction forces, so the tyre law F = k_t(…) + c_t(…) of Eq. 5 with the
//! contact displacement w + r of Eq. 6 is exactly what the solvers impose.

use nalgebra::{DMatrix, DVector};

use super::{VehicleModel, Wheel, WheelKind};
use crate::scene::{H20Truck, H20TruckParameters};

pub use crate::scene::dof_names::h20_44::DOF_NAMES;

/// Number of DOFs.
const DOFS: usize = 11;
/// Index of the first contact-point DOF.
const CONTACT: usize = 7;

/// Kinematic row of a point of the body `ahead` m ahead of the centre of
/// gravity and `left` m to the left.
fn body_point(ahead: f64, left: f64) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[0] = 1.0;
    row[1] = ahead;
    row[2] = left;
    row
}

/// Kinematic row of a point of axle `axle` (0 front, 1 rear) `left` m to the left.
fn axle_point(axle: usize, left: f64) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[3 + 2 * axle] = 1.0;
    row[4 + 2 * axle] = left;
    row
}

/// Kinematic row of contact point `wheel` (0–3).
fn contact_point(wheel: usize) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[CONTACT + wheel] = 1.0;
    row
}

/// Adds a spring (or dashpot) of rate `rate` between the points `a` and `b`.
fn add_element(matrix: &mut DMatrix<f64>, rate: f64, a: &[f64; DOFS], b: &[f64; DOFS]) {
    let d: [f64; DOFS] = std::array::from_fn(|i| a[i] - b[i]);
    for i in 0..DOFS {
        for j in 0..DOFS {
            matrix[(i, j)] += rate * d[i] * d[j];
        }
    }
}

/// Builds the 7-DOF truck (plus its four contact points).
pub fn build(v: &H20Truck, gravity: f64) -> VehicleModel {
    let p: &H20TruckParameters = &v.parameters;
    let mut mass = DMatrix::zeros(DOFS, DOFS);
    for (i, m) in [
        p.body_mass,
        p.body_pitch_inertia,
        p.body_roll_inertia,
        p.front_axle_mass,
        p.front_axle_roll_inertia,
        p.rear_axle_mass,
        p.rear_axle_roll_inertia,
    ]
    .into_iter()
    .enumerate()
    {
        mass[(i, i)] = m;
    }
    let mut stiffness = DMatrix::zeros(DOFS, DOFS);
    let mut damping = DMatrix::zeros(DOFS, DOFS);
    // Axle 0 (front) lies a₁ ahead of the centre of gravity, axle 1 (rear) a₂ behind.
    let axles = [
        (
            p.front_axle_to_centre,
            p.front_suspension_spacing,
            p.front_track,
            p.front_suspension_stiffness,
            p.front_suspension_damping,
            p.front_tyre_stiffness,
            p.front_tyre_damping,
        ),
        (
            -p.centre_to_rear_axle,
            p.rear_suspension_spacing,
            p.rear_track,
            p.rear_suspension_stiffness,
            p.rear_suspension_damping,
            p.rear_tyre_stiffness,
            p.rear_tyre_damping,
        ),
    ];
    let mut wheels = Vec::with_capacity(4);
    for (axle, &(ahead, spacing, track, ks, cs, kt, ct)) in axles.iter().enumerate() {
        // Right side (−) first, as wheels 1 and 3 are the right ones.
        for (side, sign) in [-1.0, 1.0].into_iter().enumerate() {
            let top = body_point(ahead, sign * spacing / 2.0);
            let seat = axle_point(axle, sign * spacing / 2.0);
            add_element(&mut stiffness, ks, &top, &seat);
            add_element(&mut damping, cs, &top, &seat);
            let wheel = 2 * axle + side;
            let hub = axle_point(axle, sign * track / 2.0);
            let ground = contact_point(wheel);
            add_element(&mut stiffness, kt, &hub, &ground);
            add_element(&mut damping, ct, &hub, &ground);
            wheels.push(Wheel {
                offset: if axle == 0 {
                    0.0
                } else {
                    p.front_axle_to_centre + p.centre_to_rear_axle
                },
                lateral: sign * track / 2.0,
                kind: WheelKind::Dof(CONTACT + wheel),
                direction: crate::contact::ContactDirection::Vertical,
            });
        }
    }
    let mut gravity_load = DVector::zeros(DOFS);
    gravity_load[0] = -p.body_mass * gravity;
    gravity_load[3] = -p.front_axle_mass * gravity;
    gravity_load[5] = -p.rear_axle_mass * gravity;
    VehicleModel {
        dof_names: DOF_NAMES.iter().map(|&n| n.to_owned()).collect(),
        mass,
        damping,
        stiffness,
        gravity_load,
        lateral_ground_load: DVector::zeros(0),
        blocks: std::iter::once(0..DOFS).collect(),
        wheels,
        speed: v.speed,
        acceleration: 0.0,
        entry_time: v.entry_time,
        path_y: v.lateral_position.unwrap_or(0.0),
    }
}

/// Static load of each wheel on level ground, N, front right first: the
/// body's weight shared between the axles by the lever rule, plus each
/// axle's own weight, halved between its wheels (the paper's Eq. 8).
pub fn static_wheel_loads(p: &H20TruckParameters, gravity: f64) -> [f64; 4] {
    let wheelbase = p.front_axle_to_centre + p.centre_to_rear_axle;
    let front = (p.front_axle_mass + p.body_mass * p.centre_to_rear_axle / wheelbase) * gravity;
    let rear = (p.rear_axle_mass + p.body_mass * p.front_axle_to_centre / wheelbase) * gravity;
    [front / 2.0, front / 2.0, rear / 2.0, rear / 2.0]
}
