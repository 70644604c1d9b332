//! Vehicles in permanent contact with the direct solver's bridge: the
//! coupled method's physics ([`crate::solve::permanent`]) with the
//! assembled bridge in place of the modal one.
//!
//! **The math.** A wheel at x(t) on the deck rides
//! u_w = N·u + r, u̇_w = N·u̇ + v(N′·u + r′),
//! ü_w = N·ü + 2vN′·u̇ + v²(N″·u + r″) + a(N′·u + r′)
//! (N = N(x) of [`super::assembled::LinePoint`], r the surface; the modal
//! kinematics with φ → N, q → u). Within a step u = u* − Z Σ_d N_d λ_d,
//! Z = wK̂⁻¹ (w = 1 + α), so each wheel's kinematics is affine in the
//! contact forces λ with sensitivities −(N_c, P₁c, P₂c)ᵀ Z N_d, P₁ = a₁N +
//! vN′ and P₂ = a₀N + 2va₁N′ + v²N″ + aN′ the Newmark velocity and
//! acceleration rows; each vehicle's condensed wheel rows
//! ([`crate::solve::partition`], the coupled method's) close the small
//! dense system (I − A)λ = b, solved by LU.
//!
//! **Cost and memory.** Once: Z on the deck line's DOFs (every free DOF
//! of a plane beam, the rails' of an imported track,
//! [`super::line_flexibility`]): on a track where it decays within a
//! quarter of the line, a band found by coloured solves (a few hundred,
//! whatever the line's length) and kept within 1e-10 of K̂⁻¹ ([`super::line_flexibility::BAND_TOLERANCE`]); otherwise
//! n_R solves with K̂'s factor in blocks of [`SOLVE_BLOCK`] columns,
//! O(n_R·nnz(L)) time and n_R² × 8 bytes (a beam of 1,000 elements:
//! 2,000² × 8 B = 32 MB; refused above [`MAX_LINE_DOFS`]). Per step:
//! O(3·P² nc²) for the sensitivities (N has P ≤ 8 entries per contact, 4
//! on a beam or one rail: Z is read at P² entries per pair), the coupled
//! method's O(nc² · wheels per vehicle + Σ dofᵥ²) for the vehicles and
//! O(nc³) for the LU, and ONE extra solve with K̂'s factor for the
//! correction u* → u_{n+1} of all contacts together (O(nnz(L))): nothing
//! grows as contacts × model size. Nothing is allocated per step.

use super::assembled::{AssembledBridge, LinePoint, POINT_DOFS};
use super::line_flexibility::{self, LineFlexibility};
use super::step::DirectStep;
use crate::bridge::eigen::sparse::Factor;
use crate::model::Model;
use crate::solve::dense::lu_solve;
use crate::solve::newmark::Newmark;
use crate::solve::partition::Partition;
use crate::solve::permanent::{ContactWheel, WheelSplit, close_with_vehicles, vehicle_forces};
use crate::solve::{SolveError, VehicleState};

/// Columns of each block solve that forms the contact flexibility.
pub const SOLVE_BLOCK: usize = 32;

/// Most deck-line DOFs whose flexibility Z is kept densely (5,000² × 8 B =
/// 200 MB).
pub const MAX_LINE_DOFS: usize = 5_000;

/// The contact wheels, the vehicles' condensation and states, the contact
/// flexibility on the deck line's DOFs and the per-step work arrays.
#[derive(Debug, Clone)]
pub struct DirectContacts {
    /// Contact wheels in flattened order.
    pub contacts: Vec<ContactWheel>,
    /// Global contact indices of each vehicle's wheels.
    pub contact_of: Vec<Vec<usize>>,
    /// Each vehicle's condensation.
    pub partitions: Vec<Partition>,
    /// Each vehicle's state.
    pub states: Vec<VehicleState>,
    /// Index of each free DOF among the deck line's (0 off the line: such
    /// a DOF never carries weight in N).
    line_index: Vec<usize>,
    /// Z = wK̂⁻¹ on the deck line's DOFs, m/N, dense or banded.
    flexibility: LineFlexibility,
    /// N at each contact this step.
    points: Vec<LinePoint>,
    /// Each contact's line indices of its N's DOFs.
    line_points: Vec<[usize; POINT_DOFS]>,
    /// Each contact's rows [N, P₁, P₂] on its N's DOFs.
    rows: Vec<[[f64; POINT_DOFS]; 3]>,
    /// Each contact's speed (m/s) and acceleration (m/s²) at t_{n+1}.
    path: Vec<(f64, f64)>,
    /// The surface under each contact: r (m), r′, r″ (1/m).
    surface: Vec<(f64, f64, f64)>,
    /// Wheel kinematics at λ = 0: [u m, u̇ m/s, ü m/s²].
    base: Vec<[f64; 3]>,
    /// ∂(u, u̇, ü)_c/∂λ_d, row-major nc × nc.
    sens: Vec<[f64; 3]>,
    /// (I − A), row-major nc × nc.
    system: Vec<f64>,
    /// The step's contact forces λ, N (compression positive).
    pub lambda: Vec<f64>,
}

impl DirectContacts {
    /// Splits `model`'s wheels and vehicles for Newmark `nm` and forms Z
    /// with K̂'s factor `effective` (skipped without contacts), `dense`ly
    /// whatever its decay if asked.
    ///
    /// # Errors
    ///
    /// [`SolveError::SingularContact`] for a vehicle whose free DOFs cannot
    /// be condensed; [`SolveError::Direct`] above [`MAX_LINE_DOFS`] or when
    /// a workspace does not fit in memory.
    pub fn new(
        model: &Model,
        beam: &AssembledBridge<'_>,
        nm: &Newmark,
        effective: &Factor,
        dense: bool,
    ) -> Result<Self, SolveError> {
        // The moving loads are the stepper's own (`super::step`).
        let WheelSplit {
            contacts,
            wheel_dofs,
            contact_of,
            ..
        } = WheelSplit::of(model);
        let nc = contacts.len();
        let mut partitions = Vec::with_capacity(model.vehicles.len());
        for (v, vehicle) in model.vehicles.iter().enumerate() {
            partitions.push(WheelSplit::partition(vehicle, v, &wheel_dofs[v], nm)?);
        }
        let (line, positions) = beam.line_dofs_along();
        let mut line_index = vec![0; beam.order()];
        for (i, &dof) in line.iter().enumerate() {
            line_index[dof] = i;
        }
        let flexibility = if nc == 0 {
            LineFlexibility::Dense {
                order: 0,
                values: Vec::new(),
            }
        } else {
            line_flexibility::form(
                effective,
                &line,
                positions.as_deref().filter(|_| !dense),
                nm.weight(),
            )?
        };
        Ok(Self {
            states: (0..model.vehicles.len())
                .map(|v| VehicleState::at_rest(model, v))
                .collect(),
            line_index,
            flexibility,
            points: vec![LinePoint::default(); nc],
            line_points: vec![[0; POINT_DOFS]; nc],
            rows: vec![[[0.0; POINT_DOFS]; 3]; nc],
            path: vec![(0.0, 0.0); nc],
            surface: vec![(0.0, 0.0, 0.0); nc],
            base: vec![[0.0; 3]; nc],
            sens: vec![[0.0; 3]; nc * nc],
            system: vec![0.0; nc * nc],
            lambda: vec![0.0; nc],
            contacts,
            contact_of,
            partitions,
        })
    }

    /// Number of contact wheels.
    pub fn count(&self) -> usize {
        self.contacts.len()
    }

    /// The banded flexibility's half-width along the line, m (`None`: dense).
    pub fn band(&self) -> Option<f64> {
        self.flexibility.band()
    }
}

impl DirectContacts {
    /// Where the contacts are this step (ending at `t`, s): each contact's
    /// speed and acceleration along its path, N and its Newmark rows
    /// [N, P₁, P₂], and the surface under it. Cost O(contacts · log nodes).
    pub fn locate(
        &mut self,
        model: &Model,
        beam: &AssembledBridge<'_>,
        nm: &Newmark,
        t: f64,
        wheel_positions: &[f64],
    ) {
        for (c, contact) in self.contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let vehicle = &model.vehicles[contact.vehicle];
            let (v, a) = (vehicle.speed_at(t), vehicle.acceleration_at(t));
            self.path[c] = (v, a);
            let point = beam.contact_point(contact.direction, x, contact.y);
            let rows = &mut self.rows[c];
            for k in 0..POINT_DOFS {
                let (n, n1, n2) = (point.values[k], point.slopes[k], point.curvatures[k]);
                rows[0][k] = n;
                rows[1][k] = nm.a1 * n + v * n1;
                rows[2][k] = nm.a0 * n + 2.0 * v * nm.a1 * n1 + v * v * n2;
                if a != 0.0 {
                    rows[2][k] += a * n1;
                }
                self.line_points[c][k] = self.line_index[point.dofs[k]];
            }
            self.points[c] = point;
            self.surface[c] =
                model.irregularity(contact.direction, model.wheel_rail[contact.wheel], x);
        }
    }

    /// Each contact's λ = 0 kinematics from the bridge's predictor u*
    /// ([`DirectStep::predict`], after [`Self::locate`]):
    /// [N·u* + r, P₁·u* − N·h_v + vr′, P₂·u* − N·hₐ − 2vN′·h_v + v²r″ + ar′].
    /// Cost O(contacts).
    pub fn predict_wheels(&mut self, bridge: &DirectStep) {
        let u_star = &bridge.predictor;
        for c in 0..self.count() {
            let (point, rows) = (&self.points[c], &self.rows[c]);
            let row = |k: usize| -> f64 {
                (0..POINT_DOFS)
                    .map(|j| rows[k][j] * u_star[point.dofs[j]])
                    .sum()
            };
            let (v, a) = self.path[c];
            let (r, dr, ddr) = self.surface[c];
            self.base[c] = [
                point.value(u_star) + r,
                row(1) - point.value(&bridge.damping_history) + v * dr,
                row(2)
                    - point.value(&bridge.inertia_history)
                    - 2.0 * v * point.slope(&bridge.damping_history)
                    + v * v * ddr
                    + if a != 0.0 { a * dr } else { 0.0 },
            ];
        }
    }

    /// Each vehicle's condensed wheel rows from its state at tₙ and the
    /// previous contact forces (N, by flattened wheel), under the ground
    /// motion's HHT-weighted extra weight ratio `gravity_ratio` and lateral
    /// acceleration `lateral_ground` (m/s²; [`crate::solve::GroundStep`]).
    /// Cost O(Σ dofᵥ²).
    pub fn begin_vehicles(
        &mut self,
        nm: &Newmark,
        (gravity_ratio, lateral_ground): (f64, f64),
        contact_forces: &[f64],
    ) {
        for (v, partition) in self.partitions.iter_mut().enumerate() {
            let state = &self.states[v];
            partition.lateral_ground = lateral_ground;
            partition.begin_step(
                nm,
                gravity_ratio,
                &state.displacement,
                &state.velocity,
                &state.acceleration,
                self.contact_of[v]
                    .iter()
                    .map(|&c| contact_forces[self.contacts[c].wheel]),
            );
        }
    }

    /// The step's contact forces [`Self::lambda`] (N): the sensitivities
    /// −(N_c, P₁c, P₂c)ᵀ Z N_d, the vehicles' rows, one LU solve.
    ///
    /// # Errors
    ///
    /// [`SolveError::SingularContact`] if the condensed system is singular.
    pub fn solve(&mut self, t: f64) -> Result<(), SolveError> {
        let nc = self.count();
        for c in 0..nc {
            for d in 0..nc {
                let mut sums = [0.0; 3];
                for (b, &j) in self.line_points[d].iter().enumerate() {
                    let weight = self.points[d].values[b];
                    if weight == 0.0 {
                        continue;
                    }
                    for (a, &i) in self.line_points[c].iter().enumerate() {
                        let z = self.flexibility.get(i, j) * weight;
                        for k in 0..3 {
                            sums[k] += self.rows[c][k][a] * z;
                        }
                    }
                }
                self.sens[c * nc + d] = [-sums[0], -sums[1], -sums[2]];
            }
        }
        close_with_vehicles(
            &self.partitions,
            &self.contact_of,
            nc,
            &self.sens,
            &mut self.system,
        );
        vehicle_forces(
            &self.partitions,
            &self.contact_of,
            &self.base,
            &mut self.lambda,
        );
        if nc > 0 && !lu_solve(&mut self.system, &mut self.lambda, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the condensed contact system is singular".into(),
            });
        }
        Ok(())
    }

    /// Closes the step with [`Self::lambda`]: the bridge takes the contact
    /// loads (one solve, [`DirectStep::take_contact_load`]) and finishes,
    /// the wheels follow the deck and the surface, the vehicles' free DOFs
    /// are solved, and `contact_forces` (by flattened wheel) is updated.
    pub fn finish_step(
        &mut self,
        nm: &Newmark,
        bridge: &mut DirectStep,
        contact_forces: &mut [f64],
    ) {
        bridge.contact_load.fill(0.0);
        for (point, &force) in self.points.iter().zip(&self.lambda) {
            point.spread(-force, &mut bridge.contact_load);
        }
        bridge.take_contact_load(nm);
        bridge.finish(nm);
        let (u, ud, udd) = (&bridge.displacement, &bridge.velocity, &bridge.acceleration);
        for (c, contact) in self.contacts.iter().enumerate() {
            let point = &self.points[c];
            let (v, a) = self.path[c];
            let (r, dr, ddr) = self.surface[c];
            let (w, wx, wxx) = (point.value(u), point.slope(u), point.curvature(u));
            let state = &mut self.states[contact.vehicle];
            state.displacement[contact.dof] = w + r;
            state.velocity[contact.dof] = point.value(ud) + v * (wx + dr);
            state.acceleration[contact.dof] =
                point.value(udd) + 2.0 * v * point.slope(ud) + v * v * (wxx + ddr);
            if a != 0.0 {
                state.acceleration[contact.dof] += a * (wx + dr);
            }
            contact_forces[contact.wheel] = self.lambda[c];
        }
        for (state, partition) in self.states.iter_mut().zip(self.partitions.iter_mut()) {
            partition.finish_step(
                nm,
                &mut state.displacement,
                &mut state.velocity,
                &mut state.acceleration,
            );
        }
    }
}
