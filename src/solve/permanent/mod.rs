//! The permanent-contact step shared by the `coupled` and `iterative`
//! solvers.
//!
//! A wheel at x(t) (and fixed transverse position y) on a deck with
//! deflection w = Σ φᵢ(x, y) qᵢ and roughness r(x) moves with
//! u_w = φ·q + r,  u̇_w = φ·q̇ + v(φ′·q + r′),
//! ü_w = φ·q̈ + 2v φ′·q̇ + v²(φ″·q + r″) + a(φ′·q + r′)
//! (′ = ∂/∂x along the path, v = ẋ, a = ẍ), as in the "traditional
//! permanent contact model" of the LCP separation paper (Section 2) and
//! Yang & Yau (1997) for constant speed (a = 0); the a-term is the chain
//! rule's d/dt of v(t) in u̇_w when the vehicle speeds up or brakes
//! ([`crate::vehicle::motion`]). v and a are taken at t_{n+1}, where the
//! step's wheel positions are. Within a Newmark step the bridge
//! gives q = q* − DΦᵀλ (D = diag((1+α)/k̂ᵢ), λ the contact forces,
//! compression positive), so each wheel's displacement, velocity and
//! acceleration are affine in λ; each vehicle's condensed wheel rows
//! ([`super::partition`]) give λ back from the wheel kinematics. The two
//! solvers differ only in how they close that loop: `coupled` solves the
//! linear system at once, `iterative` alternates the two subsystems.

use super::modal::ModalStep;
use super::newmark::Newmark;
use super::partition::Partition;
use super::residual_rates::{ResidualRates, ResidualStart};
use super::{SolveError, VehicleState};

mod geometry;
mod step;
use crate::contact::ContactDirection;
use crate::model::Model;
use crate::vehicle::WheelKind;
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, Par};
pub use step::PermanentStep;

/// A wheel that rides the surface through a vehicle DOF.
#[derive(Debug, Clone, Copy)]
pub struct ContactWheel {
    /// Flattened wheel index.
    pub wheel: usize,
    /// Vehicle index.
    pub vehicle: usize,
    /// The wheel's DOF in its vehicle.
    pub dof: usize,
    /// Transverse position on the deck, m.
    pub y: f64,
    /// The direction in which the wheel follows the bridge and its rail.
    pub direction: ContactDirection,
}

/// Mode shape data of one contact point at the current step.
#[derive(Debug, Clone)]
pub struct ContactShapes {
    /// φᵢ at the contact, 1/√kg.
    pub values: Vec<f64>,
    /// ∂φᵢ/∂x, 1/(m√kg).
    pub slopes: Vec<f64>,
    /// ∂²φᵢ/∂x², 1/(m²√kg).
    pub curvatures: Vec<f64>,
    /// (1+α)φ/k̂, elementwise: modal response to a unit contact force.
    pub scaled: Vec<f64>,
    /// P₁ = a₁φ + vφ′: the velocity row acting on q_{n+1}.
    pub velocity_row: Vec<f64>,
    /// P₂ = a₀φ + 2va₁φ′ + v²φ″ + aφ′: the acceleration row acting on q_{n+1}.
    pub acceleration_row: Vec<f64>,
}

impl ContactShapes {
    fn new(modes: usize) -> Self {
        Self {
            values: vec![0.0; modes],
            slopes: vec![0.0; modes],
            curvatures: vec![0.0; modes],
            scaled: vec![0.0; modes],
            velocity_row: vec![0.0; modes],
            acceleration_row: vec![0.0; modes],
        }
    }
}

/// Dot product.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Contact wheels, vehicle partitions and states, and the per-step work
/// arrays of a permanent-contact run. Nothing is allocated per step.
#[derive(Debug, Clone)]
pub struct PermanentContacts {
    /// Contact wheels in flattened order.
    pub contacts: Vec<ContactWheel>,
    /// Moving loads: (flattened wheel, load N).
    pub load_wheels: Vec<(usize, f64)>,
    /// Global contact indices of each vehicle's wheels.
    pub contact_of: Vec<Vec<usize>>,
    /// Each vehicle's condensation.
    pub partitions: Vec<Partition>,
    /// Each vehicle's state.
    pub states: Vec<VehicleState>,
    /// Shapes at each contact this step.
    pub shapes: Vec<ContactShapes>,
    /// Wheel kinematics at λ = 0: [displacement m, velocity m/s, acceleration m/s²].
    pub base: Vec<[f64; 3]>,
    /// The surface under each contact this step: elevation r (m), slope r′
    /// and curvature r″ (1/m); evaluated once in `begin_step` (a random
    /// profile costs O(terms)) and reused by `finish_step`.
    surface: Vec<(f64, f64, f64)>,
    /// Each contact's speed (m/s) and acceleration (m/s²) along its path
    /// this step, at t_{n+1}.
    path: Vec<(f64, f64)>,
    /// Modal correction −DΦᵀλ work vector.
    correction: Vec<f64>,
    /// This step's contact rows gathered for the contact system's matrix
    /// products: [φ, P₁, P₂] of every contact, each stored as a modes × nc
    /// matrix whose column c is contact c (written contiguously; the
    /// products use its transpose), and Dφ of every contact as the columns
    /// of a modes × nc matrix. Three products of these replace nc² separate dot products
    /// (the same sums, blocked and vectorised: on 96 contacts × 148 modes
    /// the step's contact system costs a fraction of what the dot products
    /// did).
    contact_columns: [Mat<f64>; 3],
    scaled_columns: Mat<f64>,
    /// [ΦDΦᵀ, P₁DΦᵀ, P₂DΦᵀ] between the contacts this step, nc × nc.
    contact_products: [Mat<f64>; 3],
    /// φᵢ/ωᵢ² of every contact as the columns of a modes × nc matrix, and
    /// the kept modes' flexibility ΦΩ⁻²Φᵀ between the contacts, nc × nc:
    /// the part of the static flexibility the residual leaves out (empty
    /// when the contact correction is off).
    modal_columns: Mat<f64>,
    modal_flexibility: Mat<f64>,
    /// Residual (static) flexibility between the contacts this step, m/N,
    /// row-major nc × nc ([`crate::bridge::ModalBridge::residual_flexibility`]);
    /// empty when the contact static correction is off.
    pub residual: Vec<f64>,
    /// Each contact's residual deflection s (m), its velocity ṡ (m/s) and
    /// its Newmark acceleration s̈ (m/s²) at tₙ ([`ResidualRates`]); zeros
    /// without the contact correction and while the wheel is off the model.
    residual_motion: Vec<[f64; 3]>,
    /// Each contact's WBZ-α relations that give its s a velocity and
    /// acceleration this step: ṡₙ₊₁ and the wheel's s̈ are affine in
    /// sₙ₊₁ = −Σ_d R_cd λ_d.
    residual_rates: Vec<ResidualRates>,
    /// Whether each contact is off the model ([`Self::off_model`]) at the
    /// step begun last (at tₙ when the next one begins, which compares);
    /// `None` before the first step.
    off_model_before: Vec<Option<bool>>,
    /// Each contact wheel's condensed mass on its contact DOF (kg): the
    /// mass that rides the residual deflection ([`residual_coupling`]).
    wheel_mass: Vec<f64>,
    /// The highest kept mode's circular frequency ω_N (rad/s).
    top_omega: f64,
    /// This step's vehicle loads as a multiple of their weights beyond 1:
    /// the HHT-weighted vertical ground acceleration over g (a vertical
    /// record acts on a vehicle as gravity g + üg). Set by the solver
    /// before [`Self::begin_step`]; 0 without ground motion.
    pub gravity_ratio: f64,
    /// This step's HHT-weighted lateral ground acceleration, m/s²
    /// ([`super::GroundStep::lateral_load`]); set with `gravity_ratio`.
    pub lateral_ground: f64,
    /// Whether the wheels follow the track's irregularities (true), or a
    /// perfect track (the EMBS first-order bridge, whose wheels carry no
    /// irregularity: [`super::embs`]).
    pub follow_irregularity: bool,
}

/// A model's wheels split by how they meet the surface: the contact wheels
/// (a vehicle DOF rides it) and the moving loads, with each vehicle's
/// wheel DOFs and contact indices (shared by the permanent-contact modal
/// steppers and the direct one).
#[derive(Debug, Clone)]
pub struct WheelSplit {
    /// Contact wheels in flattened order.
    pub contacts: Vec<ContactWheel>,
    /// Moving loads: (flattened wheel, load N).
    pub load_wheels: Vec<(usize, f64)>,
    /// Each vehicle's wheel DOFs, in contact order.
    pub wheel_dofs: Vec<Vec<usize>>,
    /// Each vehicle's contact indices.
    pub contact_of: Vec<Vec<usize>>,
}

impl WheelSplit {
    /// Vehicle `v`'s partition (`vehicle`, its wheel DOFs `wheel_dofs`)
    /// for the Newmark scheme `nm`.
    ///
    /// # Errors
    ///
    /// [`SolveError::SingularContact`] when its free DOFs cannot be
    /// condensed once its wheels are held.
    pub fn partition(
        vehicle: &crate::vehicle::VehicleModel,
        v: usize,
        wheel_dofs: &[usize],
        nm: &Newmark,
    ) -> Result<Partition, SolveError> {
        Partition::new(vehicle, wheel_dofs.to_vec(), nm).ok_or_else(|| {
            SolveError::SingularContact {
                time: 0.0,
                reason: format!(
                    "vehicle {} has a singular effective stiffness once its wheels are held",
                    v + 1
                ),
            }
        })
    }

    /// The split of `model`'s flattened wheels. Cost O(wheels · vehicles).
    pub fn of(model: &Model) -> Self {
        let mut contacts = Vec::new();
        let mut load_wheels = Vec::new();
        let mut wheel_dofs: Vec<Vec<usize>> = vec![Vec::new(); model.vehicles.len()];
        for (flat, r) in model.wheels.iter().enumerate() {
            let vehicle = &model.vehicles[r.vehicle];
            match vehicle.wheels[r.wheel].kind {
                WheelKind::Dof(dof) => {
                    contacts.push(ContactWheel {
                        wheel: flat,
                        vehicle: r.vehicle,
                        dof,
                        y: model.wheel_y[flat],
                        direction: vehicle.wheels[r.wheel].direction,
                    });
                    wheel_dofs[r.vehicle].push(dof);
                }
                WheelKind::Load(load) => load_wheels.push((flat, load)),
            }
        }
        let nc = contacts.len();
        let contact_of: Vec<Vec<usize>> = (0..model.vehicles.len())
            .map(|v| (0..nc).filter(|&c| contacts[c].vehicle == v).collect())
            .collect();
        Self {
            contacts,
            load_wheels,
            wheel_dofs,
            contact_of,
        }
    }
}

impl PermanentContacts {
    /// Splits the model's wheels and vehicles for a Newmark scheme `nm`.
    pub fn new(model: &Model, nm: &Newmark) -> Result<Self, SolveError> {
        let modes = model.bridge.mode_count();
        let WheelSplit {
            contacts,
            load_wheels,
            wheel_dofs,
            contact_of,
        } = WheelSplit::of(model);
        let nc = contacts.len();
        let mut states = Vec::with_capacity(model.vehicles.len());
        let mut partitions = Vec::with_capacity(model.vehicles.len());
        for (v, vehicle) in model.vehicles.iter().enumerate() {
            let partition = WheelSplit::partition(vehicle, v, &wheel_dofs[v], nm)?;
            states.push(VehicleState::at_rest(model, v));
            partitions.push(partition);
        }
        let mut wheel_mass = vec![0.0; nc];
        for (v, local) in contact_of.iter().enumerate() {
            for (a, &c) in local.iter().enumerate() {
                wheel_mass[c] = partitions[v].condensed_mass[(a, a)].abs();
            }
        }
        let top_omega = model
            .bridge
            .circular_frequencies
            .iter()
            .fold(0.0, |top: f64, &w| top.max(w));
        Ok(Self {
            wheel_mass,
            top_omega,
            gravity_ratio: 0.0,
            lateral_ground: 0.0,
            follow_irregularity: true,
            shapes: (0..nc).map(|_| ContactShapes::new(modes)).collect(),
            base: vec![[0.0; 3]; nc],
            surface: vec![(0.0, 0.0, 0.0); nc],
            path: vec![(0.0, 0.0); nc],
            correction: vec![0.0; modes],
            contact_columns: std::array::from_fn(|_| Mat::zeros(modes, nc)),
            scaled_columns: Mat::zeros(modes, nc),
            contact_products: std::array::from_fn(|_| Mat::zeros(nc, nc)),
            modal_columns: if model.bridge.corrects_contacts() {
                Mat::zeros(modes, nc)
            } else {
                Mat::zeros(0, 0)
            },
            modal_flexibility: if model.bridge.corrects_contacts() {
                Mat::zeros(nc, nc)
            } else {
                Mat::zeros(0, 0)
            },
            residual: if model.bridge.corrects_contacts() {
                vec![0.0; nc * nc]
            } else {
                Vec::new()
            },
            residual_motion: vec![[0.0; 3]; nc],
            residual_rates: vec![ResidualRates::new(nm, ResidualStart::Running, 0.0); nc],
            off_model_before: vec![None; nc],
            contacts,
            load_wheels,
            contact_of,
            partitions,
            states,
        })
    }

    /// Number of contact wheels.
    pub fn count(&self) -> usize {
        self.contacts.len()
    }

    /// Begins the step to time `t` (s) at the given wheel positions: the bridge predictor with
    /// the moving loads, each contact's shape rows and λ = 0 kinematics, and
    /// each vehicle's condensed wheel rows from its state at tₙ and the
    /// previous contact forces. Cost O(modes·(loads + contacts)) + O(Σ dofᵥ²).
    pub fn begin_step(
        &mut self,
        model: &Model,
        nm: &Newmark,
        modal: &mut ModalStep,
        t: f64,
        wheel_positions: &[f64],
        contact_forces: &[f64],
    ) {
        self.predict_loads(model, nm, modal, wheel_positions);
        self.locate(model, nm, modal, t, wheel_positions);
        self.predict_wheels(model, modal, wheel_positions);
        self.begin_residual_rates(model, nm, wheel_positions);
        self.begin_partitions(nm, contact_forces);
    }

    /// [`Self::begin_step`] with the contacts' geometry of this step (shape
    /// rows, contact columns, residual flexibility) taken from `located`,
    /// which began the same step at the same wheel positions over the same
    /// bridge and [`ModalStep::contact_flexibility`] (EMBS's zero- and
    /// first-order bridges). The buffers are swapped, not copied: `located`
    /// gets them back from [`Self::return_geometry`]. Bit for bit what
    /// `begin_step` computes; it saves the O(modes·contacts²) of forming the
    /// geometry a second time.
    #[allow(clippy::too_many_arguments)]
    pub fn begin_step_located(
        &mut self,
        located: &mut Self,
        model: &Model,
        nm: &Newmark,
        modal: &mut ModalStep,
        wheel_positions: &[f64],
        contact_forces: &[f64],
    ) {
        self.swap_geometry(located);
        self.predict_loads(model, nm, modal, wheel_positions);
        self.predict_wheels(model, modal, wheel_positions);
        self.begin_residual_rates(model, nm, wheel_positions);
        self.begin_partitions(nm, contact_forces);
    }

    /// Gives the geometry taken by [`Self::begin_step_located`] back to
    /// `located` (O(1)).
    pub fn return_geometry(&mut self, located: &mut Self) {
        self.swap_geometry(located);
    }

    /// The bridge's predictor q* under the moving loads (wheels without a
    /// DOF).
    fn predict_loads(
        &self,
        model: &Model,
        nm: &Newmark,
        modal: &mut ModalStep,
        wheel_positions: &[f64],
    ) {
        modal.predict(
            nm,
            &model.bridge,
            self.load_wheels
                .iter()
                .map(|&(flat, load)| (wheel_positions[flat], model.wheel_y[flat], load)),
        );
    }

    /// Each contact's λ = 0 kinematics (the bridge's predictor seen by the
    /// wheel, plus the surface when `follow_irregularity`), from the located
    /// geometry.
    fn predict_wheels(&mut self, model: &Model, modal: &ModalStep, wheel_positions: &[f64]) {
        let (q_star, inertia_history, damping_history) = (
            &modal.predictor,
            &modal.inertia_history,
            &modal.damping_history,
        );
        for (c, contact) in self.contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let (v, a) = self.path[c];
            let s = &self.shapes[c];
            let (r, dr, ddr) = if self.follow_irregularity {
                model.irregularity(contact.direction, model.wheel_rail[contact.wheel], x)
            } else {
                (0.0, 0.0, 0.0)
            };
            self.surface[c] = (r, dr, ddr);
            self.base[c] = [
                dot(&s.values, q_star) + r,
                dot(&s.velocity_row, q_star) - dot(&s.values, damping_history) + v * dr,
                dot(&s.acceleration_row, q_star)
                    - dot(&s.values, inertia_history)
                    - 2.0 * v * dot(&s.slopes, damping_history)
                    + v * v * ddr
                    + if a != 0.0 { a * dr } else { 0.0 },
            ];
        }
    }

    /// Each vehicle's condensed wheel rows from its state at tₙ and the
    /// previous contact forces (N, by flattened wheel).
    fn begin_partitions(&mut self, nm: &Newmark, contact_forces: &[f64]) {
        for (v, partition) in self.partitions.iter_mut().enumerate() {
            let state = &self.states[v];
            partition.lateral_ground = self.lateral_ground;
            partition.begin_step(
                nm,
                self.gravity_ratio,
                &state.displacement,
                &state.velocity,
                &state.acceleration,
                self.contact_of[v]
                    .iter()
                    .map(|&c| contact_forces[self.contacts[c].wheel]),
            );
        }
    }

    /// The step's condensed contact system (I − A) λ = b, row-major nc × nc
    /// into `system` (b is [`Self::vehicle_forces`] of [`Self::base`]):
    /// each wheel's kinematics is affine in λ with sensitivities
    /// ∂(u, u̇, ü)_c/∂λ_d = −(φ_c·D φ_d + R_cd, P₁c·Dφ_d, P₂c·Dφ_d) (R the
    /// residual flexibility when the contact correction is on), written to
    /// `sens`, and each vehicle's wheel rows λ = λ⁰ + M̃ü_W + C̃u̇_W + K̃u_W
    /// close it. Cost O(modes·contacts²) + O(contacts²·wheels per vehicle).
    pub fn contact_system(&mut self, sens: &mut [[f64; 3]], system: &mut [f64]) {
        let nc = self.contacts.len();
        for (product, columns) in self.contact_products.iter_mut().zip(&self.contact_columns) {
            matmul(
                product.as_mut(),
                Accum::Replace,
                columns.as_ref().transpose(),
                self.scaled_columns.as_ref(),
                1.0,
                Par::Seq,
            );
        }
        let [flexibility, velocity, acceleration] = &self.contact_products;
        for c in 0..nc {
            let [velocity_slope, acceleration_slope] = self.residual_rates[c].slopes();
            for d in 0..nc {
                let r = self.residual.get(c * nc + d).copied().unwrap_or(0.0);
                sens[c * nc + d] = [
                    -flexibility[(c, d)] - r,
                    -velocity[(c, d)] - velocity_slope * r,
                    -acceleration[(c, d)] - acceleration_slope * r,
                ];
            }
        }
        close_with_vehicles(&self.partitions, &self.contact_of, nc, sens, system);
    }

    /// The vehicles' answer to prescribed wheel kinematics: the contact force
    /// of each wheel, λ = λ⁰ + M̃ü_W + C̃u̇_W + K̃u_W (N), written to `forces`.
    /// Cost O(Σ wheelsᵥ²).
    pub fn vehicle_forces(&self, kinematics: &[[f64; 3]], forces: &mut [f64]) {
        vehicle_forces(&self.partitions, &self.contact_of, kinematics, forces);
    }

    /// The bridge's answer to contact forces `forces` (N): each wheel's
    /// displacement, velocity and acceleration at t_{n+1}, written to
    /// `kinematics`, through q = q* − DΦᵀλ. Cost O(modes·contacts).
    pub fn bridge_kinematics(&mut self, forces: &[f64], kinematics: &mut [[f64; 3]]) {
        self.correction.fill(0.0);
        for (s, &force) in self.shapes.iter().zip(forces) {
            for (dq, scaled) in self.correction.iter_mut().zip(&s.scaled) {
                *dq -= scaled * force;
            }
        }
        for (c, s) in self.shapes.iter().enumerate() {
            let [velocity_slope, acceleration_slope] = self.residual_rates[c].slopes();
            let base = self.base[c];
            let residual = self.residual_deflection(c, forces);
            kinematics[c] = [
                base[0] + dot(&s.values, &self.correction) + residual,
                base[1] + dot(&s.velocity_row, &self.correction) + velocity_slope * residual,
                base[2]
                    + dot(&s.acceleration_row, &self.correction)
                    + acceleration_slope * residual,
            ];
        }
    }

    /// Ends the step begun by `begin_step` (same wheel positions) with
    /// contact forces `forces` (N, contact order): the bridge takes them,
    /// the wheels follow the surface exactly, the free
    /// vehicle DOFs are solved, and `contact_forces` (flattened wheels) is
    /// updated.
    pub fn finish_step(
        &mut self,
        nm: &Newmark,
        modal: &mut ModalStep,
        forces: &[f64],
        contact_forces: &mut [f64],
    ) {
        for (c, s) in self.shapes.iter().enumerate() {
            modal.apply_contact(&s.values, forces[c]);
        }
        modal.finish(nm);
        let (q, qd, qdd) = (&modal.displacement, &modal.velocity, &modal.acceleration);
        for (c, contact) in self.contacts.iter().enumerate() {
            let s = &self.shapes[c];
            let (v, a) = self.path[c];
            let (r, dr, ddr) = self.surface[c];
            let (w, wx, wxx) = (dot(&s.values, q), dot(&s.slopes, q), dot(&s.curvatures, q));
            let residual = self.residual_deflection(c, forces);
            // s's rates (see `begin_step`, which told whether the wheel is
            // off the model this step).
            let off_model = self.residual.is_empty() || self.off_model_before[c] == Some(true);
            let (motion, [residual_velocity, residual_acceleration]) = if off_model {
                ([0.0; 3], [0.0; 2])
            } else {
                self.residual_rates[c].advance(self.residual_motion[c], residual)
            };
            self.residual_motion[c] = motion;
            let state = &mut self.states[contact.vehicle];
            state.displacement[contact.dof] = w + r + residual;
            state.velocity[contact.dof] = dot(&s.values, qd) + v * (wx + dr) + residual_velocity;
            state.acceleration[contact.dof] = dot(&s.values, qdd)
                + 2.0 * v * dot(&s.slopes, qd)
                + v * v * (wxx + ddr)
                + residual_acceleration;
            if a != 0.0 {
                state.acceleration[contact.dof] += a * (wx + dr);
            }
            contact_forces[contact.wheel] = forces[c];
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

/// Closes the condensed contact system (I − A)λ = b: row c of each
/// vehicle's wheel c gets A_c· = Σ_b (M̃ S₂ + C̃ S₁ + K̃ S₀)_{cb,·} from the
/// wheels' sensitivities `sens` (row-major `nc` × `nc`, [∂u, ∂u̇, ∂ü]/∂λ) and
/// each vehicle's condensed rows (`partitions`, with the global contact
/// indices `contact_of` of each vehicle's wheels), written row-major into
/// `system`. Shared by the modal permanent-contact methods and the direct
/// solver ([`super::direct`]). Cost O(contacts²·wheels per vehicle).
pub fn close_with_vehicles(
    partitions: &[Partition],
    contact_of: &[Vec<usize>],
    nc: usize,
    sens: &[[f64; 3]],
    system: &mut [f64],
) {
    // Row c of (I − A) for each vehicle's wheel c: A_c· = Σ_b (M̃ S₂ + C̃ S₁
    // + K̃ S₀)_{cb,·}, accumulated along whole rows so the inner loop runs
    // over contiguous memory. 0 − x₁ − x₂ … rounds exactly as −(x₁ + x₂ …)
    // and 1 is added last, as 1 − Σ was: the same bits as the sum per entry.
    for (v, partition) in partitions.iter().enumerate() {
        let local = &contact_of[v];
        for (a, &c) in local.iter().enumerate() {
            let row = &mut system[c * nc..(c + 1) * nc];
            row.fill(0.0);
            let (first, end) = partition.condensed_spans[a];
            for (b, &cb) in local.iter().enumerate().take(end).skip(first) {
                let mass = partition.condensed_mass[(a, b)];
                let damping = partition.condensed_damping[(a, b)];
                let stiffness = partition.condensed_stiffness[(a, b)];
                // Cars without couplers (a `count:` train) condense to
                // blocks: the zero blocks between cars add nothing
                // (−0·s leaves every entry's value as it was).
                if mass == 0.0 && damping == 0.0 && stiffness == 0.0 {
                    continue;
                }
                for (entry, s) in row.iter_mut().zip(&sens[cb * nc..(cb + 1) * nc]) {
                    *entry -= mass * s[2] + damping * s[1] + stiffness * s[0];
                }
            }
            row[c] += 1.0;
        }
    }
}

/// The vehicles' answer to prescribed wheel kinematics `kinematics`
/// ([u m, u̇ m/s, ü m/s²] per contact): each wheel's contact force,
/// λ = λ⁰ + M̃ü_W + C̃u̇_W + K̃u_W (N), written to `forces` (see
/// [`close_with_vehicles`] for the arguments). Cost O(Σ wheelsᵥ²).
pub fn vehicle_forces(
    partitions: &[Partition],
    contact_of: &[Vec<usize>],
    kinematics: &[[f64; 3]],
    forces: &mut [f64],
) {
    for (v, partition) in partitions.iter().enumerate() {
        for (a, &c) in contact_of[v].iter().enumerate() {
            let mut force = partition.base_forces[a];
            let (first, end) = partition.condensed_spans[a];
            for (b, &cb) in contact_of[v].iter().enumerate().take(end).skip(first) {
                // The zero blocks between uncoupled cars add nothing.
                if partition.condensed_mass[(a, b)] == 0.0
                    && partition.condensed_damping[(a, b)] == 0.0
                    && partition.condensed_stiffness[(a, b)] == 0.0
                {
                    continue;
                }
                force += partition.condensed_mass[(a, b)] * kinematics[cb][2]
                    + partition.condensed_damping[(a, b)] * kinematics[cb][1]
                    + partition.condensed_stiffness[(a, b)] * kinematics[cb][0];
            }
            forces[c] = force;
        }
    }
}
