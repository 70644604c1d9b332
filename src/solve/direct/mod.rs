//! The direct solver: Newmark/HHT-α on the assembled finite-element
//! system of the bridge, exact in space (no modal truncation).
//!
//! **The math.** The bridge's free DOFs u (m, rad) obey
//! M ü + C u̇ + K u = F(t) − Σ_c N(x_c) λ_c,
//! K (N/m) and M (kg) assembled on the free DOFs of a plane beam
//! ([`crate::bridge::beam::BeamModel`]) or an imported model
//! ([`crate::bridge::fe_import`]), Rayleigh damping C = c_M M + c_K K
//! (the only damping with a sparse C that the modal solver's ratios
//! ζ(ω) = c_M/(2ω) + c_K ω/2 stand for), N(x) the interpolation of a rail
//! point's displacement from its element's DOFs ([`assembled::LinePoint`]:
//! Hermite on a beam or a rail with rotations, linear on a rail without,
//! times the entry weight at free rail ends;
//! the very functions the modal solver's mode values φᵢ(x) = N(x)ᵀΦᵢ are
//! interpolated with), F the moving forces'
//! nodal loads −P N(x) (P downward, N) and λ the contact forces
//! (compression positive). HHT-α with Newmark (β, γ) exactly as
//! [`super::newmark`] (w = 1 + α):
//! K̂ u_{n+1} = R̂, K̂ = a₀M + w(a₁C + K),
//! R̂ = wF_{n+1} − αFₙ + M hₐ + wC h_v + α(C u̇ₙ + K uₙ),
//! and ü_{n+1} from the equation of motion, (M + wγΔt C) ü_{n+1} = wF_{n+1}
//! − αFₙ − wC(u̇ₙ + (1−γ)Δt üₙ) − wK u_{n+1} + α(C u̇ₙ + K uₙ), u̇ by
//! Newmark ([`step::DirectStep`]). With every mode kept, the modal solver
//! integrates the same discrete system in other coordinates, so the two
//! agree to round-off (tests/it/direct.rs).
//!
//! **Cost.** Once: two sparse LDLᵀ factorisations (faer, approximate
//! minimum degree ordering, `Par::Seq`) of K̂ and of M + wγΔtC, O(nnz(L))
//! memory each (a beam's band: O(n)). Per step: four sparse products with
//! K or M (O(nnz(K) + nnz(M))), one solve with each factor (O(nnz(L))),
//! the loads' O(log nodes) element searches, two products for the energy
//! the divergence guard checks and the modal projection (below): O(n)
//! for a beam; each load adds O(1). Nothing is allocated in the step.
//!
//! **Errors.** [`SolveError::Direct`] for a 3D beam or a plate, damping
//! that is not Rayleigh's (a nonzero modal ratio, a damping matrix file),
//! a matrix that cannot be factorised, or a deck
//! line too long for the contacts' flexibility (dense, or banded where it
//! decays along a track: [`line_flexibility`])
//! ([`contact::MAX_LINE_DOFS`]); [`SolveError::SingularContact`] as the
//! coupled method's.
//!
//! **Ground motion** in relative coordinates, as the modal solver: the
//! supports' acceleration üg loads the deck by −M δ üg (δ = 1 on every DOF
//! of its direction; [`assembled::AssembledBridge::ground_inertia`]) and
//! the vehicles by their weight's share ([`super::GroundStep`]).
//!
//! **Records.** The view ([`super::StepView`]) carries the nodal state u,
//! u̇, ü itself ([`super::NodalState`]), and the bridge records read it,
//! exact in space whatever the modes kept, with no static correction
//! ([`crate::record::direct_reading`]): N(x)ᵀu at a point, a beam
//! section's forces from its element
//! ([`crate::bridge::section::NodalSection`]), a support's row of the
//! equations of motion. It also carries the projection of that state onto
//! the scene's kept modes, q = ΦᵀM u and q̈ = ΦᵀM ü (O(n·modes) per step),
//! for a deck acceleration's filter (the modes up to it, exact when they
//! are all kept) and any observer that reads modes.
//! **Vehicles** in permanent contact ([`contact`]): the coupled method's
//! physics and vehicle condensation ([`super::partition`]) with N(x) for
//! the mode values, the contact forces from one small dense system per
//! step whose flexibility G = N(x_c)ᵀ wK̂⁻¹ N(x_d) is read from K̂⁻¹ on
//! the deck line's DOFs, formed once; the correction of u for all contacts
//! together is one more solve with K̂'s factor.

pub mod assembled;
pub mod contact;
pub mod line_flexibility;
pub mod step;

use self::assembled::{AssembledBridge, LinePoint};
use self::contact::DirectContacts;
use self::step::DirectStep;
use super::guard::Guard;
use super::newmark::Newmark;
use super::time_loop::Stepper;
use super::{GroundStep, SolveError, StepView};
use crate::contact::ContactDirection::{Lateral, Vertical};
use crate::model::Model;
use crate::vehicle::WheelKind;

/// The direct method's state, for [`super::time_loop::drive`].
#[derive(Debug)]
pub struct Direct<'a> {
    model: &'a Model,
    nm: Newmark,
    assembled: AssembledBridge<'a>,
    bridge: DirectStep,
    /// Moving forces: (flattened wheel, downward load N).
    loads: Vec<(usize, f64)>,
    /// The wheels in permanent contact and the vehicles' states.
    contacts: DirectContacts,
    /// The ground motion's step (its weighting and the vehicles' share).
    ground: GroundStep,
    /// M δ (kg) of a vertical and a lateral support motion on the free
    /// DOFs; empty without ground motion in that direction.
    ground_inertia: [Vec<f64>; 2],
    wheel_positions: Vec<f64>,
    contact_forces: Vec<f64>,
    contact_gaps: Vec<f64>,
    /// MΦ of the kept modes, column-major n × modes (√kg): the projection
    /// q = ΦᵀM u of the nodal state onto them, for the records.
    projection: Vec<f64>,
    /// Whether the projection is formed each step (an observer reads the
    /// modal coordinates: [`Self::projecting`]).
    project: bool,
    /// q = ΦᵀM u and q̈ = ΦᵀM ü of the state after the last step (√kg·m,
    /// √kg·m/s²).
    modal_displacement: Vec<f64>,
    modal_acceleration: Vec<f64>,
}

impl<'a> Direct<'a> {
    /// `model` at rest at t = 0, K̂ factorised.
    ///
    /// # Errors
    ///
    /// [`SolveError::Direct`]: see the module doc.
    pub fn new(model: &'a Model) -> Result<Self, SolveError> {
        Self::with_contact_form(model, false)
    }

    /// [`Self::new`] with the contacts' flexibility formed densely whatever
    /// its decay along the track: the reference the banded form
    /// ([`line_flexibility`]) is checked against.
    ///
    /// # Errors
    ///
    /// As [`Self::new`], and above [`contact::MAX_LINE_DOFS`] line DOFs.
    pub fn with_dense_contacts(model: &'a Model) -> Result<Self, SolveError> {
        Self::with_contact_form(model, true)
    }

    fn with_contact_form(model: &'a Model, dense: bool) -> Result<Self, SolveError> {
        let assembled = AssembledBridge::of(&model.bridge)?;
        let nm = Newmark::new(model.beta, model.gamma, model.alpha, model.time_step);
        let bridge = DirectStep::new(&assembled, &nm)?;
        let mut loads = Vec::new();
        for (flat, r) in model.wheels.iter().enumerate() {
            if let WheelKind::Load(load) = model.vehicles[r.vehicle].wheels[r.wheel].kind {
                loads.push((flat, load));
            }
        }
        let contacts =
            DirectContacts::new(model, &assembled, &nm, bridge.effective_factor(), dense)?;
        let projection = mass_times_modes(&model.bridge, &assembled)?;
        let ground_inertia = [Vertical, Lateral].map(|direction| {
            let moves = model.ground.as_ref().is_some_and(|g| match direction {
                Vertical => !g.vertical.is_empty(),
                Lateral => !g.lateral.is_empty(),
            });
            if moves {
                assembled.ground_inertia(direction)
            } else {
                Vec::new()
            }
        });
        let modes = model.bridge.mode_count();
        let nw = model.wheels.len();
        let mut wheel_positions = vec![0.0; nw];
        model.wheel_positions(0.0, &mut wheel_positions);
        Ok(Self {
            contacts,
            ground: GroundStep::new(model, &nm),
            ground_inertia,
            projection,
            project: true,
            modal_displacement: vec![0.0; modes],
            modal_acceleration: vec![0.0; modes],
            contact_forces: model.static_wheel_loads.clone(),
            contact_gaps: vec![0.0; nw],
            wheel_positions,
            loads,
            bridge,
            assembled,
            nm,
            model,
        })
    }

    /// q = ΦᵀM u and q̈ = ΦᵀM ü of the state after a step, for the
    /// records. Cost O(n·modes).
    fn project_onto_modes(&mut self) {
        let n = self.bridge.order();
        for (i, column) in self.projection.chunks_exact(n).enumerate() {
            self.modal_displacement[i] = dot(column, &self.bridge.displacement);
            self.modal_acceleration[i] = dot(column, &self.bridge.acceleration);
        }
    }

    /// The bridge's free-DOF displacements u after the last step (m, rad).
    pub fn displacement(&self) -> &[f64] {
        &self.bridge.displacement
    }

    /// The bridge's free-DOF velocities u̇ after the last step (m/s, rad/s).
    pub fn velocity(&self) -> &[f64] {
        &self.bridge.velocity
    }

    /// The bridge's free-DOF accelerations ü after the last step (m/s², rad/s²).
    pub fn acceleration(&self) -> &[f64] {
        &self.bridge.acceleration
    }

    /// N(x) of the deck at `x` (m).
    pub fn point(&self, x: f64) -> LinePoint {
        self.assembled.point(x)
    }

    /// The vehicles' states after the last step.
    pub fn vehicles(&self) -> &[super::VehicleState] {
        &self.contacts.states
    }

    /// Each flattened wheel's contact force after the last step, N
    /// (compression positive; a moving force's load).
    pub fn contact_forces(&self) -> &[f64] {
        &self.contact_forces
    }

    /// Each flattened wheel's position after the last step, m.
    pub fn wheel_positions(&self) -> &[f64] {
        &self.wheel_positions
    }

    /// Whether the view's modal coordinates are the nodal state's
    /// projection onto the kept modes, q = ΦᵀM u (`true`, the default,
    /// O(n·modes) a step), or zeros (`false`: no observer reads them — a
    /// recorder all of whose records read the nodal state,
    /// [`super::Observer::reads_modal_coordinates`]; 58 % of the step on
    /// the 30-span viaduct at its 148 modes).
    pub fn projecting(mut self, on: bool) -> Self {
        self.project = on;
        self
    }

    /// The half-width along the line (m) of the contacts' banded
    /// flexibility ([`line_flexibility`]), `None` when it is dense (or there
    /// are no contacts).
    pub fn contact_band(&self) -> Option<f64> {
        self.contacts.band()
    }

    /// The deck's deflection at `x` (m, upward positive) after the last step.
    pub fn deflection_at(&self, x: f64) -> f64 {
        self.assembled.point(x).value(&self.bridge.displacement)
    }
}

impl Stepper for Direct<'_> {
    type Error = SolveError;

    fn models(&self) -> &[&Model] {
        std::slice::from_ref(&self.model)
    }

    fn advance(&mut self, _step: usize, t: f64) -> Result<(), SolveError> {
        self.model.wheel_positions(t, &mut self.wheel_positions);
        self.bridge.clear_force();
        for &(flat, load) in &self.loads {
            let point = self.assembled.contact_point(
                Vertical,
                self.wheel_positions[flat],
                self.model.wheel_y[flat],
            );
            point.spread(-load, &mut self.bridge.current_force);
        }
        let (gravity_ratio, vertical, lateral) = self.ground.advance_to(self.model, t);
        // Relative coordinates: the supports' motion loads the deck by
        // −M δ üg (weighted by HHT with the other loads).
        for (inertia, acceleration) in self.ground_inertia.iter().zip([vertical, lateral]) {
            for (f, m) in self.bridge.current_force.iter_mut().zip(inertia) {
                *f -= m * acceleration;
            }
        }
        self.bridge.predict(&self.nm);
        if self.contacts.count() == 0 {
            self.bridge.finish(&self.nm);
            if self.project {
                self.project_onto_modes();
            }
            return Ok(());
        }
        let contacts = &mut self.contacts;
        contacts.locate(
            self.model,
            &self.assembled,
            &self.nm,
            t,
            &self.wheel_positions,
        );
        contacts.predict_wheels(&self.bridge);
        let ground = (gravity_ratio, self.ground.lateral_load);
        contacts.begin_vehicles(&self.nm, ground, &self.contact_forces);
        self.contacts.solve(t)?;
        self.contacts
            .finish_step(&self.nm, &mut self.bridge, &mut self.contact_forces);
        if self.project {
            self.project_onto_modes();
        }
        Ok(())
    }

    fn guarded(&self, _lane: usize) -> (f64, &[f64]) {
        let energy = Guard::vehicle_energy(self.model, self.bridge.energy(), &self.contacts.states);
        (energy, &self.contact_forces)
    }

    fn view(&self, _index: usize, step: usize, t: f64) -> StepView<'_> {
        // The bridge records read the nodal state; the modal coordinates are
        // its projection onto the kept modes, for the records that still
        // read modes (the module doc's "Records").
        StepView {
            step,
            time: t,
            modal_displacement: &self.modal_displacement,
            modal_acceleration: &self.modal_acceleration,
            vehicles: &self.contacts.states,
            contact_forces: &self.contact_forces,
            contact_gaps: &self.contact_gaps,
            wheel_positions: &self.wheel_positions,
            wheel_modes: None,
            nodal: Some(super::NodalState {
                displacement: &self.bridge.displacement,
                velocity: &self.bridge.velocity,
                acceleration: &self.bridge.acceleration,
            }),
        }
    }
}

/// Dot product.
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// MΦ of `bridge`'s kept modes on `beam`'s free DOFs, column-major
/// n × modes (√kg). Cost O(modes·nnz(M)).
fn mass_times_modes(
    bridge: &crate::bridge::ModalBridge,
    beam: &AssembledBridge<'_>,
) -> Result<Vec<f64>, SolveError> {
    let vectors = bridge
        .assembled_mode_vectors()
        .ok_or_else(|| SolveError::Direct {
            reason: "the bridge's modes are not a plane beam's".into(),
        })?;
    let n = beam.order();
    let mut projection = vec![0.0; vectors.len()];
    for (phi, column) in vectors.chunks_exact(n).zip(projection.chunks_exact_mut(n)) {
        crate::bridge::eigen::sparse::multiply(beam.mass(), phi, column);
    }
    Ok(projection)
}
