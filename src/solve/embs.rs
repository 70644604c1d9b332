//! The Extended Modified Bridge System (EMBS) method: the vehicle–bridge
//! problem with permanent contact decoupled by an asymptotic expansion in
//! ε = ω_p/ω_B (EMBS paper, Section 2, Eqs. 3–7).
//!
//! In the contact coordinates every wheel DOF follows its rail,
//! u_w = W_Bᵀ u_B + r_c (W_w = I). Eliminating the contact forces from the
//! wheels' equations M_ww ü_w + S_w = f_w + λ (S_w the suspension forces
//! on the wheels, about static equilibrium) gives the bridge equation
//! (Eq. 4); expanding in ε:
//!
//! 1. **Zero-order bridge (Eq. 5)**: the *modified bridge system* — the
//!    bridge carrying the wheel masses rigidly along the rails (with the
//!    convective terms 2v W_B′ᵀ u̇ and v² W_B″ᵀ u of a moving mass, and the
//!    wheels' inertia over the irregularity v² r″), loaded by the whole
//!    vehicle's static weight at the wheels and by the ground motion
//!    (−M_B δ üg on the bridge, −m_w δ üg on the wheels). No suspension
//!    force acts. Solved here exactly as a permanent-contact run of
//!    vehicles reduced to their wheel masses (the Woodbury form of the
//!    paper's W_B G⁻¹ … terms is the same equation).
//! 2. **Zero-order upper part (Eq. 6)**: m_u ü + c_u u̇ + k_u u = −m_u δ üg,
//!    the car body and bogies on wheels held still.
//! 3. **First-order bridge (Eq. 7)**: the same modified bridge system on a
//!    perfect track, loaded at the wheels by the zero-order suspension
//!    forces F₁ = c_w u̇_w⁽⁰⁾ + k_wu u_u⁽⁰⁾ + c_wu u̇_u⁽⁰⁾ (u̇_w⁽⁰⁾ = v r′ +
//!    W_Bᵀu̇_B⁽⁰⁾ + v W_B′ᵀu_B⁽⁰⁾, the zero-order wheel velocity). The
//!    primary springs' k_w u_w⁽⁰⁾ is O(ε²) (k_w/m_w = ω_p²) and left out, as
//!    in Eq. 7. Signs follow Eq. 4, from which Eq. 7 is the first-order
//!    part: the suspension forces enter as −W_B G⁻¹ m_w⁻¹ F₁ (our copy of
//!    Eq. 7 prints −k_wu u_u⁽⁰⁾ − c_wu u̇_u⁽⁰⁾ inside the bracket, against
//!    Eq. 4's +; we follow Eq. 4, and the tests confirm that zero plus
//!    first order beats zero order alone).
//! 4. **Vehicle (Eq. 3)**: the whole vehicle with its wheels prescribed to
//!    follow u_B⁽⁰⁾ + u_B⁽¹⁾ and the irregularities, under −m_u δ üg; its
//!    wheel rows give the contact forces.
//!
//! The three bridge-side passes step together: both bridge orders share
//! the step's condensed contact matrix (same positions, same wheel
//! masses), factored once and solved for two right-hand sides. The
//! recorded bridge response is u_B⁽⁰⁾ + u_B⁽¹⁾, the recorded vehicle the
//! Eq. 3 vehicle.

use nalgebra::DVector;

use super::dense::{lu_apply, lu_factor};
use super::guard::Guard;
use super::modal::ModalStep;
use super::newmark::Newmark;
use super::permanent::PermanentContacts;
use super::time_loop::Stepper;
use super::{GroundStep, SolveError, StepView};
use crate::contact::ContactDirection;
use crate::model::Model;
use crate::vehicle::{VehicleModel, WheelKind};

/// The small parameter of a scene in `direction`: ε = ω_p/ω_B,dir, the
/// highest wheelset frequency on the primary suspension over the lowest
/// bridge mode that moves the contacts in that direction
/// ([`super::embs_scale`]); `None` where no vehicle has such a contact.
pub fn small_parameter(model: &Model, direction: ContactDirection) -> Option<f64> {
    super::embs_scale::directional_scale(model, direction).map(|s| s.epsilon)
}

/// Above this ε the summary warns that the expansion is not accurate.
pub const SMALL_EPSILON: f64 = 0.3;

/// A vehicle reduced to its wheel masses, with the same DOFs: the wheel
/// rows of M (the wheels carry no mass coupling to the upper part in any
/// vehicle here), no damping or stiffness on the wheels, and the upper
/// DOFs parked on unit springs with unit masses, untouched by any load, so
/// they stay at 0 and condense to nothing. With `loads`, the wheels keep
/// their own weight and their share of the lateral ground inertia;
/// without, nothing loads them (the first-order pass) and moving loads are
/// zero.
fn wheel_masses(vehicle: &VehicleModel, loads: bool) -> VehicleModel {
    let n = vehicle.dofs();
    let wheel_dofs: Vec<usize> = vehicle
        .wheels
        .iter()
        .filter_map(|w| match w.kind {
            WheelKind::Dof(d) => Some(d),
            WheelKind::Load(_) => None,
        })
        .collect();
    let mut reduced = vehicle.clone();
    reduced.mass.fill(0.0);
    reduced.damping.fill(0.0);
    reduced.stiffness.fill(0.0);
    reduced.gravity_load = DVector::zeros(n);
    if !reduced.lateral_ground_load.is_empty() {
        reduced.lateral_ground_load.fill(0.0);
    }
    for d in 0..n {
        if wheel_dofs.contains(&d) {
            for &e in &wheel_dofs {
                reduced.mass[(d, e)] = vehicle.mass[(d, e)];
            }
            if loads {
                reduced.gravity_load[d] = vehicle.gravity_load[d];
                if !vehicle.lateral_ground_load.is_empty() {
                    reduced.lateral_ground_load[d] = vehicle.lateral_ground_load[d];
                }
            }
        } else {
            reduced.mass[(d, d)] = 1.0;
            reduced.stiffness[(d, d)] = 1.0;
        }
    }
    if !loads {
        for w in &mut reduced.wheels {
            if let WheelKind::Load(_) = w.kind {
                w.kind = WheelKind::Load(0.0);
            }
        }
    }
    reduced
}

/// Sets every DOF of the reduced vehicles to rest at 0 (their upper DOFs
/// carry nothing; the wheels of permanent contact sit at 0 on level
/// ground).
fn at_zero(contacts: &mut PermanentContacts) {
    for state in &mut contacts.states {
        state.displacement.fill(0.0);
        state.velocity.fill(0.0);
        state.acceleration.fill(0.0);
        state.static_displacement.fill(0.0);
    }
}

/// An external force on the wheel rows (N, contact order, HHT-weighted
/// (1+α)F_{n+1} − αF_n): the wheel equation M ü = F + λ gives λ⁰ −= F,
/// stored divided by the weight w = 1 + α ([`super::partition`]).
fn load_wheels(contacts: &mut PermanentContacts, weighted: &[f64], weight: f64) {
    for (v, partition) in contacts.partitions.iter_mut().enumerate() {
        for (a, &c) in contacts.contact_of[v].iter().enumerate() {
            partition.base_forces[a] -= weighted[c] / weight;
        }
    }
}

/// Steps the Eq. 3 vehicle (`vehicle`, under the ground's `(gravity
/// ratio, lateral load)`) with each wheel prescribed to follow the sum of
/// the bridge `orders`' wheel motions (plus its rail, held in the static
/// displacement), and writes its contact forces (N, by flattened wheel).
fn drive_vehicle(
    vehicle: &mut PermanentContacts,
    nm: &Newmark,
    (ratio, lateral): (f64, f64),
    orders: &[&[super::VehicleState]],
    kinematics: &mut [[f64; 3]],
    lambda: &mut [f64],
    contact_forces: &mut [f64],
) {
    for (v, partition) in vehicle.partitions.iter_mut().enumerate() {
        let state = &vehicle.states[v];
        partition.lateral_ground = lateral;
        partition.begin_step(
            nm,
            ratio,
            &state.displacement,
            &state.velocity,
            &state.acceleration,
            vehicle.contact_of[v]
                .iter()
                .map(|&c| contact_forces[vehicle.contacts[c].wheel]),
        );
    }
    for (c, contact) in vehicle.contacts.iter().enumerate() {
        let (v, d) = (contact.vehicle, contact.dof);
        let mut wheel = [vehicle.states[v].static_displacement[d], 0.0, 0.0];
        for order in orders {
            let state = &order[v];
            wheel[0] += state.displacement[d];
            wheel[1] += state.velocity[d];
            wheel[2] += state.acceleration[d];
        }
        let state = &mut vehicle.states[v];
        (
            state.displacement[d],
            state.velocity[d],
            state.acceleration[d],
        ) = (wheel[0], wheel[1], wheel[2]);
        kinematics[c] = wheel;
    }
    for (v, partition) in vehicle.partitions.iter_mut().enumerate() {
        let state = &mut vehicle.states[v];
        partition.finish_step(
            nm,
            &mut state.displacement,
            &mut state.velocity,
            &mut state.acceleration,
        );
    }
    vehicle.vehicle_forces(kinematics, lambda);
    for (c, contact) in vehicle.contacts.iter().enumerate() {
        contact_forces[contact.wheel] = lambda[c];
    }
}

/// The EMBS method's state and work arrays, for
/// [`super::time_loop::drive`]: the two bridge orders, the Eq. 6 upper
/// part, the Eq. 3 vehicle and, when asked, the Eq. 3 vehicle on the zero
/// order alone.
///
/// Views: 0 is the summed bridge response u_B⁽⁰⁾ + u_B⁽¹⁾ with the Eq. 3
/// vehicles; with [`Self::new`]'s `zero_order`, 1 is the zero order alone,
/// the bridge u_B⁽⁰⁾ and an Eq. 3 vehicle on u_B⁽⁰⁾ (the a-posteriori check
/// of the expansion, [`crate::report::embs`], differences the two). The
/// guard watches the zero-order bridge with the Eq. 3 vehicles.
#[derive(Debug)]
pub struct Embs<'a> {
    model: &'a Model,
    nm: Newmark,
    first_order: bool,
    /// Whether the zero order alone is a view of its own.
    zero_view: bool,
    ground: GroundStep,
    modal0: ModalStep,
    modal1: ModalStep,
    /// The vehicles reduced to their wheel masses, loaded (zero order) and
    /// unloaded (first order).
    zero_order: Model,
    first: Model,
    bridge0: PermanentContacts,
    bridge1: PermanentContacts,
    upper: PermanentContacts,
    vehicle: PermanentContacts,
    vehicle0: PermanentContacts,
    /// The static suspension force on each wheel, −(λ_static + f_g,w): the
    /// vehicle's weight the modified bridge system carries (f_B,gravity).
    statics: Vec<f64>,
    /// Which of each vehicle's DOFs are wheel DOFs, looked up per DOF in
    /// the first-order load (a search of the wheel list there cost a fifth
    /// of an 8-car train's step).
    is_wheel_dof: Vec<Vec<bool>>,
    sens: Vec<[f64; 3]>,
    system: Vec<f64>,
    pivots: Vec<usize>,
    lambda0: Vec<f64>,
    lambda1: Vec<f64>,
    lambda: Vec<f64>,
    lambda_zero: Vec<f64>,
    suspension: Vec<f64>,
    suspension_previous: Vec<f64>,
    weighted: Vec<f64>,
    kinematics: Vec<[f64; 3]>,
    forces0: Vec<f64>,
    forces1: Vec<f64>,
    contact_forces: Vec<f64>,
    contact_forces0: Vec<f64>,
    contact_gaps: Vec<f64>,
    wheel_positions: Vec<f64>,
    /// The recorded bridge response u_B⁽⁰⁾ + u_B⁽¹⁾ and its acceleration.
    displacement: Vec<f64>,
    acceleration: Vec<f64>,
}

impl<'a> Embs<'a> {
    /// `model` at rest at t = 0, every work array allocated; with
    /// `zero_order`, the zero order alone is stepped and shown too.
    ///
    /// # Errors
    ///
    /// [`PermanentContacts::new`]'s, for the full or the reduced vehicles.
    pub fn new(model: &'a Model, zero_order: bool) -> Result<Self, SolveError> {
        let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
        let bridge = &model.bridge;
        let modal0 = ModalStep::new(bridge, &nm)
            .with_ground(model.ground_participation())
            .with_lateral_ground(model.lateral_ground_participation());
        let modal1 = ModalStep::new(bridge, &nm);
        let reduced = Model {
            vehicles: model
                .vehicles
                .iter()
                .map(|v| wheel_masses(v, true))
                .collect(),
            ..model.clone()
        };
        let first = Model {
            vehicles: model
                .vehicles
                .iter()
                .map(|v| wheel_masses(v, false))
                .collect(),
            ground: None,
            ..model.clone()
        };
        let mut bridge0 = PermanentContacts::new(&reduced, &nm)?;
        let mut bridge1 = PermanentContacts::new(&first, &nm)?;
        bridge1.follow_irregularity = false;
        at_zero(&mut bridge0);
        at_zero(&mut bridge1);
        // The Eq. 6 upper part on held wheels, and the Eq. 3 vehicle.
        let upper = PermanentContacts::new(model, &nm)?;
        let vehicle = PermanentContacts::new(model, &nm)?;
        // The Eq. 3 vehicle on the zero-order bridge alone.
        let vehicle0 = PermanentContacts::new(model, &nm)?;
        let nc = bridge0.count();
        let statics: Vec<f64> = bridge0
            .contacts
            .iter()
            .map(|c| {
                -(model.static_wheel_loads[c.wheel] + model.vehicles[c.vehicle].gravity_load[c.dof])
            })
            .collect();
        let is_wheel_dof: Vec<Vec<bool>> = upper
            .partitions
            .iter()
            .zip(&model.vehicles)
            .map(|(partition, vehicle)| {
                let mut mask = vec![false; vehicle.dofs()];
                for &d in &partition.wheel_dofs {
                    mask[d] = true;
                }
                mask
            })
            .collect();
        let nw = model.wheels.len();
        let mut wheel_positions = vec![0.0; nw];
        model.wheel_positions(0.0, &mut wheel_positions);
        // At t = 0 the view is the zero-order bridge (the first order
        // starts at rest).
        let (displacement, acceleration) =
            (modal0.displacement.clone(), modal0.acceleration.clone());
        Ok(Self {
            model,
            ground: GroundStep::new(model, &nm),
            nm,
            first_order: model.embs.is_none_or(|e| e.first_order),
            zero_view: zero_order,
            modal0,
            modal1,
            zero_order: reduced,
            first,
            bridge0,
            bridge1,
            upper,
            vehicle,
            vehicle0,
            statics,
            is_wheel_dof,
            sens: vec![[0.0f64; 3]; nc * nc],
            system: vec![0.0; nc * nc],
            pivots: vec![0; nc],
            lambda0: vec![0.0; nc],
            lambda1: vec![0.0; nc],
            lambda: vec![0.0; nc],
            lambda_zero: vec![0.0; nc],
            suspension: vec![0.0; nc],
            suspension_previous: vec![0.0; nc],
            weighted: vec![0.0; nc],
            kinematics: vec![[0.0f64; 3]; nc],
            forces0: model.static_wheel_loads.clone(),
            forces1: vec![0.0; nw],
            contact_forces: model.static_wheel_loads.clone(),
            contact_forces0: model.static_wheel_loads.clone(),
            contact_gaps: vec![0.0; nw],
            wheel_positions,
            displacement,
            acceleration,
        })
    }

    /// Eq. 6: the upper part on wheels held at rest, under the ground's
    /// `(gravity ratio, lateral load)`.
    fn step_upper(&mut self, (ratio, lateral): (f64, f64)) {
        let (nm, upper) = (&self.nm, &mut self.upper);
        for (v, partition) in upper.partitions.iter_mut().enumerate() {
            let state = &mut upper.states[v];
            partition.lateral_ground = lateral;
            partition.begin_step(
                nm,
                ratio,
                &state.displacement,
                &state.velocity,
                &state.acceleration,
                std::iter::empty(),
            );
            partition.finish_step(
                nm,
                &mut state.displacement,
                &mut state.velocity,
                &mut state.acceleration,
            );
        }
    }

    /// Eq. 5: the zero-order modified bridge system at `t` (s); leaves the
    /// step's condensed contact matrix factored in `system`.
    fn step_zero_order(&mut self, t: f64, (ratio, lateral): (f64, f64)) -> Result<(), SolveError> {
        let nc = self.bridge0.count();
        let Self {
            nm,
            modal0,
            zero_order,
            bridge0,
            statics,
            sens,
            system,
            pivots,
            lambda0,
            forces0,
            wheel_positions,
            ..
        } = self;
        bridge0.gravity_ratio = ratio;
        bridge0.lateral_ground = lateral;
        bridge0.begin_step(zero_order, nm, modal0, t, wheel_positions, forces0);
        load_wheels(bridge0, statics, nm.weight());
        bridge0.contact_system(sens, system);
        if nc > 0 && !lu_factor(system, pivots, nc) {
            return Err(SolveError::SingularContact {
                time: t,
                reason: "the modified bridge system's contact matrix is singular".into(),
            });
        }
        bridge0.vehicle_forces(&bridge0.base, lambda0);
        lu_apply(system, pivots, lambda0, nc);
        bridge0.finish_step(nm, modal0, lambda0, forces0);
        Ok(())
    }

    /// Eq. 7: the first-order bridge under the zero-order suspension
    /// forces F₁ = C_ww u̇_w⁽⁰⁾ + K_wu u_u⁽⁰⁾ + C_wu u̇_u⁽⁰⁾, with the zero
    /// order's factored contact matrix.
    fn step_first_order(&mut self) {
        let model = self.model;
        let nc = self.bridge0.count();
        let Self {
            nm,
            modal1,
            first,
            bridge0,
            bridge1,
            upper,
            is_wheel_dof,
            system,
            pivots,
            lambda1,
            suspension,
            suspension_previous,
            weighted,
            forces1,
            wheel_positions,
            ..
        } = self;
        let weight = nm.weight();
        for (c, contact) in bridge0.contacts.iter().enumerate() {
            let full = &model.vehicles[contact.vehicle];
            let (zero, held) = (
                &bridge0.states[contact.vehicle],
                &upper.states[contact.vehicle],
            );
            let wheel_dof = &is_wheel_dof[contact.vehicle];
            let mut force = 0.0;
            for j in 0..full.dofs() {
                if wheel_dof[j] {
                    force += full.damping[(contact.dof, j)] * zero.velocity[j];
                } else {
                    let moved = held.displacement[j] - held.static_displacement[j];
                    force += full.stiffness[(contact.dof, j)] * moved
                        + full.damping[(contact.dof, j)] * held.velocity[j];
                }
            }
            suspension[c] = force;
            // M ü = −F₁ + λ: the load is −F₁, HHT-weighted.
            weighted[c] = -(weight * force - nm.alpha * suspension_previous[c]);
        }
        suspension_previous.copy_from_slice(suspension);
        // The same wheel positions over the same bridge: the zero order's
        // contact geometry (shape rows, residual flexibility) serves the
        // first order too, as its LU does.
        bridge1.begin_step_located(bridge0, first, nm, modal1, wheel_positions, forces1);
        load_wheels(bridge1, weighted, weight);
        bridge1.vehicle_forces(&bridge1.base, lambda1);
        lu_apply(system, pivots, lambda1, nc);
        bridge1.finish_step(nm, modal1, lambda1, forces1);
        bridge1.return_geometry(bridge0);
    }
}

impl Stepper for Embs<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.model)
    }

    fn views(&self) -> usize {
        1 + usize::from(self.zero_view)
    }

    fn advance(&mut self, _step: usize, t: f64) -> Result<(), SolveError> {
        let model = self.model;
        model.wheel_positions(t, &mut self.wheel_positions);
        let ratio = self.ground.step_of(model, &mut self.modal0, t);
        let ground = (ratio, self.ground.lateral_load);
        self.step_upper(ground);
        self.step_zero_order(t, ground)?;
        if self.first_order {
            self.step_first_order();
        }
        // Eq. 3: the vehicle with its wheels on u_B⁽⁰⁾ + u_B⁽¹⁾ + r.
        let orders = [&self.bridge0.states[..], &self.bridge1.states[..]];
        drive_vehicle(
            &mut self.vehicle,
            &self.nm,
            ground,
            &orders,
            &mut self.kinematics,
            &mut self.lambda,
            &mut self.contact_forces,
        );
        if self.zero_view {
            drive_vehicle(
                &mut self.vehicle0,
                &self.nm,
                ground,
                &[&self.bridge0.states[..]],
                &mut self.kinematics,
                &mut self.lambda_zero,
                &mut self.contact_forces0,
            );
        }
        let (modal0, modal1) = (&self.modal0, &self.modal1);
        for i in 0..self.displacement.len() {
            self.displacement[i] = modal0.displacement[i] + modal1.displacement[i];
            self.acceleration[i] = modal0.acceleration[i] + modal1.acceleration[i];
        }
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        let energy = Guard::energy(self.model, &self.modal0, &self.vehicle.states);
        (energy, &self.lambda)
    }

    fn view(&self, index: usize, step: usize, t: f64) -> StepView<'_> {
        if index == 1 {
            return StepView::of(
                step,
                t,
                &self.modal0,
                &self.vehicle0.states,
                &self.contact_forces0,
                &self.contact_gaps,
                &self.wheel_positions,
            );
        }
        StepView {
            step,
            time: t,
            modal_displacement: &self.displacement,
            modal_acceleration: &self.acceleration,
            vehicles: &self.vehicle.states,
            contact_forces: &self.contact_forces,
            contact_gaps: &self.contact_gaps,
            wheel_positions: &self.wheel_positions,
            wheel_modes: None,
            nodal: None,
        }
    }
}
