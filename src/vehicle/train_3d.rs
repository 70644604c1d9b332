//! The 3D high-speed car of the EMBS paper (Section 3.2, Eq. 8–9, Table 2:
//! the Siemens Velaro AVE-S103), and trains of such cars.
//!
//! A car is a body and two bogies, each with lateral y, vertical z, yaw ψ,
//! roll φ and pitch θ, over four wheelsets with lateral, vertical and roll
//! motion: 5 + 2·5 + 4·3 = 27 DOFs, in the paper's Eq. 9 order. Axes: x
//! forward, y to the left, z up; ψ > 0 turns the nose left, φ > 0 lifts
//! the left side, θ > 0 lifts the nose. A point at (rx, ry, rz) from a
//! body's centre of gravity moves by
//! u_x = −ψ ry − θ rz,  u_y = y + ψ rx − φ rz,  u_z = z + φ ry + θ rx
//! (small rotations). No body has a longitudinal DOF, so a longitudinal
//! spring acts only through the rotations of its two ends.
//!
//! **Wheelset coordinates.** A wheelset's DOFs are its *contact
//! coordinates*: the lateral displacement y and the vertical displacements
//! z_L, z_R of its left and right wheel–rail contacts, b₀ = contact half
//! spacing to either side of the centre. So the wheelset's bounce is
//! z = (z_L + z_R)/2 and its roll φ = (z_L − z_R)/(2 b₀). In these
//! coordinates each wheel–rail constraint of the EMBS formulation is one
//! DOF following its rail: z_L the left rail's vertical motion plus its
//! irregularity, z_R the right rail's, y the track's lateral motion plus
//! its alignment (the EMBS paper's Eq. 3: u_w = W_Bᵀ u_B + r_c with
//! W_w = I). The wheelset's mass matrix in them is
//! Tᵀ diag(m_w, m_w, I_wx) T with T the map (y, z_L, z_R) → (y, z, φ).
//!
//! **What is not modelled**, as in the EMBS formulation: no creep forces,
//! no flange contact, no wheel–rail geometry (conicity) — the wheelsets
//! follow the rails exactly in all three directions, so a wheelset has no
//! yaw (hunting) motion; the wheelset's yaw inertia of Table 2 has no DOF
//! to act on.
//!
//! **Suspensions.** Each axle box carries a primary spring–dashpot set
//! (longitudinal, lateral, vertical) between the wheelset at (0, ±d₁,
//! 0 from the axle) and the bogie at (±b, ±d₁, h_axle − h_bogie); each side
//! of a bogie a secondary set between the bogie at (0, ±d₂, h₂ − h_bogie)
//! and the body at (±a, ±d₂, h₂ − h_body). An element of rate k in
//! direction e between points p and q adds k (e·(P − Q))ᵀ(e·(P − Q)) to K,
//! P and Q the kinematic rows of the points (as for the H20 truck and the
//! rail car), so K and C are symmetric.
//!
//! A train is one model whose DOFs are its cars' DOFs one car after the
//! other (car k's DOF j is DOF 27 k + j), with no couplers between cars
//! (block-diagonal matrices), like the 2D `train`.

use nalgebra::{DMatrix, DVector};

use super::{VehicleModel, Wheel, WheelKind};
use crate::contact::ContactDirection;
use crate::scene::{Train3d, Train3dParameters};

pub use crate::scene::dof_names::train_3d::{CONTACTS_PER_WHEELSET, DOF_NAMES, DOFS, WHEELSETS};

/// Index of the first wheelset DOF within a car.
const WHEELSET: usize = 15;

/// A kinematic row over one car's DOFs.
type Row = [f64; DOFS];

/// The three displacement rows (x, y, z) of a point (rx, ry, rz) m from
/// the centre of gravity of the rigid body whose DOFs (y, z, ψ, φ, θ)
/// start at `first`.
fn body_point(first: usize, [rx, ry, rz]: [f64; 3]) -> [Row; 3] {
    let (y, z, yaw, roll, pitch) = (first, first + 1, first + 2, first + 3, first + 4);
    let mut rows = [[0.0; DOFS]; 3];
    rows[0][yaw] = -ry;
    rows[0][pitch] = -rz;
    rows[1][y] = 1.0;
    rows[1][yaw] = rx;
    rows[1][roll] = -rz;
    rows[2][z] = 1.0;
    rows[2][roll] = ry;
    rows[2][pitch] = rx;
    rows
}

/// The displacement rows of a point (0, ry, rz) m from the axle centre of
/// wheelset `w` (0–3), in contact coordinates (y, z_L, z_R):
/// u_y = y − φ rz, u_z = z + φ ry, with z = (z_L + z_R)/2 and
/// φ = (z_L − z_R)/(2 b₀); a wheelset has no yaw, so u_x = 0.
fn wheelset_point(w: usize, b0: f64, [ry, rz]: [f64; 2]) -> [Row; 3] {
    let (y, left, right) = wheelset_dofs(w);
    let mut rows = [[0.0; DOFS]; 3];
    rows[1][y] = 1.0;
    rows[1][left] = -rz / (2.0 * b0);
    rows[1][right] = rz / (2.0 * b0);
    rows[2][left] = 0.5 + ry / (2.0 * b0);
    rows[2][right] = 0.5 - ry / (2.0 * b0);
    rows
}

/// The DOFs (lateral, left, right) of wheelset `w` (0–3) within a car.
pub fn wheelset_dofs(w: usize) -> (usize, usize, usize) {
    let first = WHEELSET + CONTACTS_PER_WHEELSET * w;
    (first, first + 1, first + 2)
}

/// First DOF of bogie `bogie` (0 front, 1 rear).
fn bogie(bogie: usize) -> usize {
    5 + 5 * bogie
}

/// Adds, for each direction d, an element of rate `rates[d]` between the
/// points with rows `p` and `q` to the car block at `first`.
fn add_elements(
    matrix: &mut DMatrix<f64>,
    first: usize,
    rates: [f64; 3],
    p: &[Row; 3],
    q: &[Row; 3],
) {
    for d in 0..3 {
        if rates[d] == 0.0 {
            continue;
        }
        let diff: Row = std::array::from_fn(|i| p[d][i] - q[d][i]);
        for i in 0..DOFS {
            if diff[i] == 0.0 {
                continue;
            }
            for j in 0..DOFS {
                // rate·(dᵢdⱼ): the product commutes, so K is symmetric bit for bit.
                matrix[(first + i, first + j)] += rates[d] * (diff[i] * diff[j]);
            }
        }
    }
}

/// Distance of each wheelset behind the car's front wheelset, m.
pub fn wheelset_offsets(p: &Train3dParameters) -> [f64; WHEELSETS] {
    let (a, b) = (p.half_bogie_spacing, p.half_wheelbase);
    [0.0, 2.0 * b, 2.0 * a, 2.0 * a + 2.0 * b]
}

/// Name of DOF `dof` of car `car` (from 1) of a train.
pub fn train_dof_name(car: usize, dof: &str) -> String {
    format!("car{car}_{dof}")
}

/// Adds one car's mass, stiffness, damping and gravity at DOF `first`.
fn assemble_car(
    p: &Train3dParameters,
    first: usize,
    gravity: f64,
    mass: &mut DMatrix<f64>,
    stiffness: &mut DMatrix<f64>,
    damping: &mut DMatrix<f64>,
    gravity_load: &mut DVector<f64>,
) {
    // Body and bogies: diagonal about their centres of gravity.
    let bodies = [
        (
            0,
            p.body_mass,
            [
                p.body_yaw_inertia,
                p.body_roll_inertia,
                p.body_pitch_inertia,
            ],
        ),
        (
            bogie(0),
            p.bogie_mass,
            [
                p.bogie_yaw_inertia,
                p.bogie_roll_inertia,
                p.bogie_pitch_inertia,
            ],
        ),
        (
            bogie(1),
            p.bogie_mass,
            [
                p.bogie_yaw_inertia,
                p.bogie_roll_inertia,
                p.bogie_pitch_inertia,
            ],
        ),
    ];
    for (start, m, inertia) in bodies {
        let diagonal = [m, m, inertia[0], inertia[1], inertia[2]];
        for (i, value) in diagonal.into_iter().enumerate() {
            mass[(first + start + i, first + start + i)] = value;
        }
        gravity_load[first + start + 1] = -m * gravity;
    }
    // Wheelsets: Tᵀ diag(m_w, m_w, I_wx) T in (y, z_L, z_R).
    let b0 = p.contact_half_spacing;
    let (m, roll) = (p.wheelset_mass, p.wheelset_roll_inertia / (4.0 * b0 * b0));
    for w in 0..WHEELSETS {
        let (y, left, right) = wheelset_dofs(w);
        let (y, left, right) = (first + y, first + left, first + right);
        mass[(y, y)] = m;
        mass[(left, left)] = m / 4.0 + roll;
        mass[(right, right)] = m / 4.0 + roll;
        mass[(left, right)] = m / 4.0 - roll;
        mass[(right, left)] = m / 4.0 - roll;
        // The weight m_w g at z = (z_L + z_R)/2: half on each contact coordinate.
        gravity_load[left] = -m * gravity / 2.0;
        gravity_load[right] = -m * gravity / 2.0;
    }
    let (a, b) = (p.half_bogie_spacing, p.half_wheelbase);
    let (d1, d2) = (p.primary_half_spacing, p.secondary_half_spacing);
    for (k, ahead) in [a, -a].into_iter().enumerate() {
        let frame = bogie(k);
        for side in [1.0, -1.0] {
            // Secondary: bogie (0, ±d₂, h₂ − h_b) to body (±a, ±d₂, h₂ − h_c).
            let on_bogie = body_point(frame, [0.0, side * d2, p.secondary_height - p.bogie_height]);
            let on_body = body_point(0, [ahead, side * d2, p.secondary_height - p.body_height]);
            add_elements(stiffness, first, p.secondary_stiffness, &on_body, &on_bogie);
            add_elements(damping, first, p.secondary_damping, &on_body, &on_bogie);
            // Primary: wheelset (0, ±d₁, 0) to bogie (±b, ±d₁, R₀ − h_b).
            for (j, e) in [b, -b].into_iter().enumerate() {
                let seat = body_point(frame, [e, side * d1, p.wheel_radius - p.bogie_height]);
                let axle = wheelset_point(2 * k + j, b0, [side * d1, 0.0]);
                add_elements(stiffness, first, p.primary_stiffness, &seat, &axle);
                add_elements(damping, first, p.primary_damping, &seat, &axle);
            }
        }
    }
}

/// Builds a train of 3D cars: every car's 27 DOFs, car after car, named as
/// `car{k}_` and a name of [`DOF_NAMES`] (as the 2D `train`); three
/// wheels per wheelset, front to rear: the left contact (vertical, DOF z_L,
/// at +b₀), the right contact (vertical, z_R, at −b₀) and the lateral
/// contact (lateral, y, on the track's centre line).
pub fn build(v: &Train3d, gravity: f64) -> VehicleModel {
    let cars = v.cars.len();
    let n = DOFS * cars;
    let mut mass = DMatrix::zeros(n, n);
    let mut stiffness = DMatrix::zeros(n, n);
    let mut damping = DMatrix::zeros(n, n);
    let mut gravity_load = DVector::zeros(n);
    let mut lateral_shift = DVector::zeros(n);
    let mut wheels = Vec::with_capacity(WHEELSETS * CONTACTS_PER_WHEELSET * cars);
    for (car, c) in v.cars.iter().enumerate() {
        let first = DOFS * car;
        let p = &c.parameters;
        assemble_car(
            p,
            first,
            gravity,
            &mut mass,
            &mut stiffness,
            &mut damping,
            &mut gravity_load,
        );
        // δ_y: a rigid lateral shift moves every lateral DOF by 1.
        for start in [0, bogie(0), bogie(1)] {
            lateral_shift[first + start] = 1.0;
        }
        for (w, offset) in wheelset_offsets(p).into_iter().enumerate() {
            let (y, left, right) = wheelset_dofs(w);
            lateral_shift[first + y] = 1.0;
            let b0 = p.contact_half_spacing;
            for (dof, lateral, direction) in [
                (left, b0, ContactDirection::Vertical),
                (right, -b0, ContactDirection::Vertical),
                (y, 0.0, ContactDirection::Lateral),
            ] {
                wheels.push(Wheel {
                    offset: c.offset + offset,
                    lateral,
                    kind: WheelKind::Dof(first + dof),
                    direction,
                });
            }
        }
    }
    let names = (1..=cars)
        .flat_map(|k| DOF_NAMES.iter().map(move |d| train_dof_name(k, d)))
        .collect();
    let lateral_ground_load = -(&mass * lateral_shift);
    VehicleModel {
        dof_names: names,
        mass,
        damping,
        stiffness,
        gravity_load,
        lateral_ground_load,
        blocks: (0..cars).map(|k| DOFS * k..DOFS * (k + 1)).collect(),
        wheels,
        speed: v.speed,
        acceleration: 0.0,
        entry_time: v.entry_time,
        path_y: v.lateral_position.unwrap_or(0.0),
    }
}

/// Static load of each rail contact of a car on level ground, N: the car's
/// weight over its eight contacts, (m_c + 2 m_b + 4 m_w) g / 8 (by the car's
/// symmetry fore–aft and left–right).
pub fn static_contact_load(p: &Train3dParameters, gravity: f64) -> f64 {
    (p.body_mass + 2.0 * p.bogie_mass + 4.0 * p.wheelset_mass) * gravity / 8.0
}
