//! Four-axle rail car with ten degrees of freedom, and trains of such cars
//! (the LCP separation paper's Section 5.2 and its Table 2; the classic
//! 10-DOF vertical car model of e.g. Zhai, Vehicle–Track Coupled Dynamics,
//! 2020, §2.2, without the track).
//!
//! DOFs of one car (vertical positive upward, from static equilibrium when
//! recorded): body bounce z_c (m) and pitch θ_c (rad, nose up); front bogie
//! bounce z_b1 and pitch θ_b1; rear bogie bounce z_b2 and pitch θ_b2; then
//! the four wheelset bounces z_w1…z_w4 (m), front to rear. The wheelsets are
//! the contact DOFs: each carries its mass and follows the rail through the
//! contact model (permanent, rigid, elastic or Hertz).
//!
//! Geometry: the bogie centres lie a = `half_bogie_spacing` ahead of and
//! behind the body's centre; the wheelsets b = `half_wheelbase` ahead of and
//! behind their bogie's centre. A point d ahead of the body centre moves by
//! z_c + d θ_c, a point e ahead of bogie i by z_bi + e θ_bi. Each secondary
//! spring–dashpot joins the body at ±a to its bogie's centre; each primary
//! spring–dashpot joins its bogie at ±b to its wheelset. Assembling every
//! element as K += k (p − q)(p − q)ᵀ, with p and q the kinematic rows of its
//! two ends (as for the H20 truck), gives the symmetric K and C of the
//! standard model.
//!
//! A train is one model whose DOFs are its cars' DOFs one car after the
//! other (car k's DOF j is DOF 10 k + j) and whose wheels are the cars'
//! wheelsets, numbered front to rear over the whole train. The cars run at
//! the train's speed, their front wheelsets at fixed distances behind the
//! train's first wheelset; they are not joined by coupler springs (the
//! vertical coupler forces of passenger cars are small, and the paper's car
//! is alone), so the matrices are block-diagonal.

use nalgebra::{DMatrix, DVector};

use super::{VehicleModel, Wheel, WheelKind};
use crate::scene::{RailCar, RailCarParameters, Train};

pub use crate::scene::dof_names::rail_car::{DOF_NAMES, WHEELSETS, train_dof_name};

/// DOFs of one car.
pub const DOFS: usize = 10;
/// Index of the first wheelset DOF within a car.
const WHEELSET: usize = 6;

/// Kinematic row (over one car's DOFs) of a point `ahead` m ahead of the
/// body's centre.
fn body_point(ahead: f64) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[0] = 1.0;
    row[1] = ahead;
    row
}

/// Kinematic row of a point `ahead` m ahead of the centre of bogie `bogie`
/// (0 front, 1 rear).
fn bogie_point(bogie: usize, ahead: f64) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[2 + 2 * bogie] = 1.0;
    row[3 + 2 * bogie] = ahead;
    row
}

/// Kinematic row of wheelset `w` (0–3, front to rear).
fn wheelset(w: usize) -> [f64; DOFS] {
    let mut row = [0.0; DOFS];
    row[WHEELSET + w] = 1.0;
    row
}

/// Adds an element of rate `rate` between the points `p` and `q` of the car
/// whose DOFs start at `first`.
fn add_element(
    matrix: &mut DMatrix<f64>,
    first: usize,
    rate: f64,
    p: &[f64; DOFS],
    q: &[f64; DOFS],
) {
    let d: [f64; DOFS] = std::array::from_fn(|i| p[i] - q[i]);
    for i in 0..DOFS {
        for j in 0..DOFS {
            matrix[(first + i, first + j)] += rate * d[i] * d[j];
        }
    }
}

/// Distance of each wheelset behind the car's front wheelset, m.
pub fn wheelset_offsets(p: &RailCarParameters) -> [f64; WHEELSETS] {
    let (a, b) = (p.half_bogie_spacing, p.half_wheelbase);
    [0.0, 2.0 * b, 2.0 * a, 2.0 * a + 2.0 * b]
}

pub use crate::scene::wheelset_span;

/// Builds the model of cars `cars` (each with the distance of its front
/// wheelset behind the first car's, m), running at `speed` (m/s).
fn assemble(
    cars: &[(f64, RailCarParameters)],
    names: Vec<String>,
    speed: f64,
    entry_time: f64,
    path_y: f64,
    gravity: f64,
) -> VehicleModel {
    let n = DOFS * cars.len();
    let mut mass = DMatrix::zeros(n, n);
    let mut stiffness = DMatrix::zeros(n, n);
    let mut damping = DMatrix::zeros(n, n);
    let mut gravity_load = DVector::zeros(n);
    let mut wheels = Vec::with_capacity(WHEELSETS * cars.len());
    for (car, (front, p)) in cars.iter().enumerate() {
        let first = DOFS * car;
        let diagonal = [
            p.body_mass,
            p.body_pitch_inertia,
            p.bogie_mass,
            p.bogie_pitch_inertia,
            p.bogie_mass,
            p.bogie_pitch_inertia,
            p.wheelset_mass,
            p.wheelset_mass,
            p.wheelset_mass,
            p.wheelset_mass,
        ];
        for (i, m) in diagonal.into_iter().enumerate() {
            mass[(first + i, first + i)] = m;
        }
        // Gravity acts on the bounce DOFs only (the centres of mass are at
        // the body's and the bogies' centres).
        for (i, m) in [
            (0, p.body_mass),
            (2, p.bogie_mass),
            (4, p.bogie_mass),
            (6, p.wheelset_mass),
            (7, p.wheelset_mass),
            (8, p.wheelset_mass),
            (9, p.wheelset_mass),
        ] {
            gravity_load[first + i] = -m * gravity;
        }
        let (a, b) = (p.half_bogie_spacing, p.half_wheelbase);
        for (bogie, ahead) in [a, -a].into_iter().enumerate() {
            // Secondary suspension: body at ±a to the bogie's centre.
            let top = body_point(ahead);
            let centre = bogie_point(bogie, 0.0);
            add_element(&mut stiffness, first, p.secondary_stiffness, &top, &centre);
            add_element(&mut damping, first, p.secondary_damping, &top, &centre);
            // Primary suspension: bogie at ±b to each of its wheelsets.
            for (side, e) in [b, -b].into_iter().enumerate() {
                let seat = bogie_point(bogie, e);
                let axle = wheelset(2 * bogie + side);
                add_element(&mut stiffness, first, p.primary_stiffness, &seat, &axle);
                add_element(&mut damping, first, p.primary_damping, &seat, &axle);
            }
        }
        for (w, offset) in wheelset_offsets(p).into_iter().enumerate() {
            wheels.push(Wheel {
                offset: front + offset,
                lateral: 0.0,
                kind: WheelKind::Dof(first + WHEELSET + w),
                direction: crate::contact::ContactDirection::Vertical,
            });
        }
    }
    VehicleModel {
        dof_names: names,
        mass,
        damping,
        stiffness,
        gravity_load,
        lateral_ground_load: DVector::zeros(0),
        blocks: (0..cars.len()).map(|k| DOFS * k..DOFS * (k + 1)).collect(),
        wheels,
        speed,
        acceleration: 0.0,
        entry_time,
        path_y,
    }
}

/// Builds the 10-DOF car.
pub fn build(v: &RailCar, gravity: f64) -> VehicleModel {
    assemble(
        &[(0.0, v.parameters)],
        DOF_NAMES.iter().map(|&s| s.to_owned()).collect(),
        v.speed,
        v.entry_time,
        v.lateral_position.unwrap_or(0.0),
        gravity,
    )
}

/// Builds a train: every car's ten DOFs, car after car, with DOF names
/// `car{k}_{name}` (k from 1).
pub fn build_train(v: &Train, gravity: f64) -> VehicleModel {
    let cars: Vec<(f64, RailCarParameters)> =
        v.cars.iter().map(|c| (c.offset, c.parameters)).collect();
    let names = (1..=cars.len())
        .flat_map(|k| DOF_NAMES.iter().map(move |d| train_dof_name(k, d)))
        .collect();
    assemble(
        &cars,
        names,
        v.speed,
        v.entry_time,
        v.lateral_position.unwrap_or(0.0),
        gravity,
    )
}

/// Static load of each wheelset on level ground, N: by symmetry each
/// carries a quarter of the body, half its bogie and itself,
/// (M_c/4 + M_b/2 + M_w) g.
pub fn static_wheelset_load(p: &RailCarParameters, gravity: f64) -> f64 {
    (p.body_mass / 4.0 + p.bogie_mass / 2.0 + p.wheelset_mass) * gravity
}
