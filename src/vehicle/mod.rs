//! Vehicles reduced to one form: mass, damping and stiffness matrices over the
//! vehicle's degrees of freedom, and the wheels that touch the surface.
//!
//! A vehicle never knows which bridge it is on: the solver meets it only
//! through its wheels (position along the bridge and, for wheels with a
//! degree of freedom, which DOF follows the surface).

pub mod h20_44;
pub use crate::scene::hslm;
pub use crate::scene::motion;
pub mod moving_force;
pub mod oscillator;
pub mod rail_car;
pub mod train_3d;

use nalgebra::{DMatrix, DVector};
use thiserror::Error;

use crate::contact::ContactDirection;
use crate::scene::Vehicle;

/// Errors while building a vehicle model.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum VehicleError {
    /// The vehicle cannot stand in static equilibrium on its wheels.
    #[error("vehicle {vehicle}: no static equilibrium on level ground (is every body supported?)")]
    NoStaticEquilibrium {
        /// Vehicle number from 1.
        vehicle: usize,
    },
}

/// How a wheel interacts with the surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WheelKind {
    /// A constant downward load, N (moving force; no inertia).
    Load(f64),
    /// The vehicle DOF (index) that is the wheel's vertical displacement; its
    /// contact force is found by the contact model.
    Dof(usize),
}

/// One wheel (or axle) of a vehicle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wheel {
    /// Distance behind the vehicle's front axle, m (≥ 0).
    pub offset: f64,
    /// Transverse offset from the vehicle's path line, m (+y to the left of
    /// travel, i.e. toward larger deck y); 0 for single-track vehicles.
    pub lateral: f64,
    /// Load or degree of freedom.
    pub kind: WheelKind,
    /// The direction in which the wheel follows the rail (a load acts
    /// vertically): one vehicle DOF per contact direction, so a 3D wheelset
    /// has a vertical contact per rail and a lateral one.
    pub direction: ContactDirection,
}

/// A vehicle as the solvers see it.
///
/// Equations of motion, vertical DOFs positive upward:
/// M ü + C u̇ + K u = f_g + Σ_w e_w λ_w, where f_g are the gravity loads
/// (N, negative), λ_w the contact force of wheel w (N, compression positive,
/// pushing the wheel up) and e_w the unit vector of the wheel's DOF.
#[derive(Debug, Clone)]
pub struct VehicleModel {
    /// Names of the DOFs, as used by `record: … dof:`.
    pub dof_names: Vec<String>,
    /// Mass matrix, kg (kg·m² for rotations).
    pub mass: DMatrix<f64>,
    /// Damping matrix, N·s/m.
    pub damping: DMatrix<f64>,
    /// Stiffness matrix, N/m.
    pub stiffness: DMatrix<f64>,
    /// Gravity loads on the DOFs, N (negative: downward).
    pub gravity_load: DVector<f64>,
    /// −M δ_y: the load on each DOF per unit lateral ground acceleration,
    /// N/(m/s²) (δ_y is 1 on the DOFs that translate with a rigid lateral
    /// shift of the whole vehicle, 0 elsewhere), so a lateral record üg
    /// loads the vehicle with üg · this vector in relative coordinates
    /// (EMBS paper, Eq. 3 and 6). Empty for a vehicle without lateral DOFs
    /// (every model but `train_3d`): it has nothing to shake sideways.
    pub lateral_ground_load: DVector<f64>,
    /// Independent diagonal blocks of M, C and K (DOF ranges, in order,
    /// covering every DOF): the matrices are zero outside them. One block
    /// for a single vehicle; one per car for a train, whose cars are not
    /// coupled, so the solvers multiply by the blocks only.
    pub blocks: Vec<std::ops::Range<usize>>,
    /// Wheels, front first.
    pub wheels: Vec<Wheel>,
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration, m/s² (negative: braking to a stop; see
    /// [`motion::Motion`]).
    pub acceleration: f64,
    /// Time the front axle reaches the entrance x = 0, s.
    pub entry_time: f64,
    /// Transverse position y of the vehicle's path line on the deck, m
    /// (measured from the deck edge y = 0; ignored on a beam).
    pub path_y: f64,
}

impl VehicleModel {
    /// Builds the model of a resolved vehicle.
    pub fn build(vehicle: &Vehicle, gravity: f64) -> Self {
        let mut model = match vehicle {
            Vehicle::MovingForce(v) => moving_force::build(v),
            Vehicle::Oscillator(v) => oscillator::build(v, gravity),
            Vehicle::H20Truck(v) => h20_44::build(v, gravity),
            Vehicle::RailCar(v) => rail_car::build(v, gravity),
            Vehicle::Train(v) => rail_car::build_train(v, gravity),
            Vehicle::Train3d(v) => train_3d::build(v, gravity),
        };
        model.acceleration = vehicle.acceleration();
        model
    }

    /// How the vehicle travels.
    #[inline]
    pub fn motion(&self) -> motion::Motion {
        motion::Motion {
            speed: self.speed,
            acceleration: self.acceleration,
            entry_time: self.entry_time,
        }
    }

    /// Speed at time `t`, m/s.
    #[inline]
    pub fn speed_at(&self, t: f64) -> f64 {
        self.motion().speed_at(t)
    }

    /// Acceleration along the path at time `t`, m/s².
    #[inline]
    pub fn acceleration_at(&self, t: f64) -> f64 {
        self.motion().acceleration_at(t)
    }

    /// Number of degrees of freedom.
    pub fn dofs(&self) -> usize {
        self.dof_names.len()
    }

    /// Front-axle position at time `t`, m.
    #[inline]
    pub fn front_position(&self, t: f64) -> f64 {
        self.motion().position(t)
    }

    /// Position of wheel `w` at time `t`, m.
    #[inline]
    pub fn wheel_position(&self, w: usize, t: f64) -> f64 {
        self.front_position(t) - self.wheels[w].offset
    }

    /// Transverse position y of wheel `w` on the deck, m.
    #[inline]
    pub fn wheel_y(&self, w: usize) -> f64 {
        self.path_y + self.wheels[w].lateral
    }

    /// Time at which the last wheel leaves a bridge of length `length`, s,
    /// or, for a vehicle that brakes to a stop first, the time it stops.
    pub fn exit_time(&self, length: f64) -> f64 {
        let rear = self.wheels.iter().map(|w| w.offset).fold(0.0, f64::max);
        let motion = self.motion();
        if self.acceleration == 0.0 {
            return self.entry_time + (length + rear) / self.speed;
        }
        motion
            .time_at(length + rear)
            .or(motion.stop_time())
            .unwrap_or(f64::INFINITY)
    }

    /// Static equilibrium on level ground: DOF displacements u₀ (m) and the
    /// wheel contact forces λ₀ (N). `compression(λ)` is the contact law's
    /// compression δ (m) under a force λ (0 for rigid or permanent contact);
    /// each contact wheel then sits at u_w = −δ(λ). Solves
    /// [K −E; Eᵀ F] [u₀; λ₀] = [f_g; 0] with the secant flexibility
    /// F = diag(δ(λ)/λ), iterated for a nonlinear law (Hertz: converges in a
    /// few passes; the vehicles here are statically determinate on their
    /// wheels, so λ₀ does not depend on F at all). Load wheels carry their
    /// load. `number` is the vehicle number for errors.
    pub fn static_equilibrium(
        &self,
        number: usize,
        compression: &dyn Fn(f64) -> f64,
    ) -> Result<(DVector<f64>, Vec<f64>), VehicleError> {
        let n = self.dofs();
        let mut forces: Vec<f64> = self
            .wheels
            .iter()
            .map(|w| match w.kind {
                WheelKind::Load(load) => load,
                WheelKind::Dof(_) => 0.0,
            })
            .collect();
        if n == 0 {
            return Ok((DVector::zeros(0), forces));
        }
        let contact_dofs: Vec<(usize, usize)> = self
            .wheels
            .iter()
            .enumerate()
            .filter_map(|(w, wheel)| match wheel.kind {
                WheelKind::Dof(d) => Some((w, d)),
                WheelKind::Load(_) => None,
            })
            .collect();
        let size = n + contact_dofs.len();
        let mut flexibility = vec![0.0; contact_dofs.len()];
        let mut displacement = DVector::zeros(n);
        for _pass in 0..50 {
            let mut system = DMatrix::<f64>::zeros(size, size);
            let mut rhs = DVector::<f64>::zeros(size);
            system.view_mut((0, 0), (n, n)).copy_from(&self.stiffness);
            rhs.rows_mut(0, n).copy_from(&self.gravity_load);
            for (k, &(_, dof)) in contact_dofs.iter().enumerate() {
                system[(dof, n + k)] = -1.0;
                system[(n + k, dof)] = 1.0;
                system[(n + k, n + k)] = flexibility[k];
            }
            let solution = system
                .lu()
                .solve(&rhs)
                .filter(|s| s.iter().all(|v| v.is_finite()))
                .ok_or(VehicleError::NoStaticEquilibrium { vehicle: number })?;
            displacement = solution.rows(0, n).into_owned();
            let mut change = 0.0f64;
            for (k, &(w, _)) in contact_dofs.iter().enumerate() {
                let force = solution[n + k];
                change = change.max((force - forces[w]).abs());
                forces[w] = force;
                // A lateral contact is bilateral and carries no weight.
                let lateral = self.wheels[w].direction == ContactDirection::Lateral;
                let updated = if force > 0.0 && !lateral {
                    compression(force) / force
                } else {
                    0.0
                };
                change = change.max((updated - flexibility[k]).abs() * force.abs());
                flexibility[k] = updated;
            }
            let scale = forces.iter().fold(0.0f64, |m, f| m.max(f.abs())).max(1.0);
            if change <= 1e-13 * scale {
                break;
            }
        }
        let scale = forces.iter().fold(0.0f64, |m, f| m.max(f.abs())).max(1.0);
        if contact_dofs.iter().any(|&(w, _)| {
            self.wheels[w].direction == ContactDirection::Vertical && forces[w] < 0.0
        }) {
            return Err(VehicleError::NoStaticEquilibrium { vehicle: number });
        }
        // A lateral contact of a symmetric vehicle carries 0 up to rounding.
        for &(w, _) in &contact_dofs {
            if self.wheels[w].direction == ContactDirection::Lateral
                && forces[w].abs() < 1e-12 * scale
            {
                forces[w] = 0.0;
            }
        }
        Ok((displacement, forces))
    }
}
