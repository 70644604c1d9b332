//! Where the contact wheels are and what the step's contact problem owes to
//! it: the contact wheels of a model, each vehicle's step matrices (K̂⁻¹ and
//! H) and the contact compliance W of the wheels' positions.

use nalgebra::DMatrix;

use super::block_inverse;
use crate::contact::ContactDirection;
use crate::model::Model;
use crate::solve::SolveError;
use crate::solve::newmark::Newmark;
use crate::vehicle::WheelKind;

/// A wheel whose vertical DOF meets the surface through the contact law.
#[derive(Debug, Clone, Copy)]
pub(in crate::solve) struct ContactWheel {
    /// Flattened wheel index.
    pub wheel: usize,
    /// Its vehicle.
    pub vehicle: usize,
    /// Its DOF in the vehicle.
    pub dof: usize,
    /// Column of this wheel in its vehicle's H.
    pub column: usize,
    /// The vehicle's diagonal block that holds `dof`: first DOF and size.
    pub block: (usize, usize),
}

/// The contact wheels of `model` in flattened order, the moving loads
/// (flattened index, N), and each vehicle's count of contact wheels (the
/// columns of its H).
pub(in crate::solve) fn contact_wheels(
    model: &Model,
) -> (Vec<ContactWheel>, Vec<(usize, f64)>, Vec<usize>) {
    let mut contacts: Vec<ContactWheel> = Vec::new();
    let mut load_wheels = Vec::new();
    let mut columns = vec![0usize; model.vehicles.len()];
    for (flat, r) in model.wheels.iter().enumerate() {
        match model.vehicles[r.vehicle].wheels[r.wheel].kind {
            WheelKind::Dof(dof) => {
                let vehicle = &model.vehicles[r.vehicle];
                let block = vehicle
                    .blocks
                    .iter()
                    .find(|b| b.contains(&dof))
                    .map_or((0, vehicle.dofs()), |b| (b.start, b.len()));
                contacts.push(ContactWheel {
                    wheel: flat,
                    vehicle: r.vehicle,
                    dof,
                    column: columns[r.vehicle],
                    block,
                });
                columns[r.vehicle] += 1;
            }
            WheelKind::Load(load) => load_wheels.push((flat, load)),
        }
    }
    (contacts, load_wheels, columns)
}

/// Vehicle `v`'s effective flexibility K̂⁻¹, K̂ = a₀M + (1+α)(a₁C + K)
/// (inverted block by block: a train's cars), and its contact response
/// H = (1+α)K̂⁻¹E, one column per contact wheel of the vehicle (m/N).
pub(in crate::solve) fn vehicle_step_matrices(
    model: &Model,
    nm: &Newmark,
    v: usize,
    contacts: &[ContactWheel],
    columns: &[usize],
) -> Result<(DMatrix<f64>, DMatrix<f64>), SolveError> {
    let vehicle = &model.vehicles[v];
    let effective =
        &vehicle.mass * nm.a0 + (&vehicle.damping * nm.a1 + &vehicle.stiffness) * nm.weight();
    let effective_flexibility =
        block_inverse(&effective, &vehicle.blocks).ok_or_else(|| SolveError::SingularContact {
            time: 0.0,
            reason: format!("vehicle {} has a singular effective stiffness", v + 1),
        })?;
    let mut contact_response = DMatrix::zeros(vehicle.dofs(), columns[v]);
    for c in contacts.iter().filter(|c| c.vehicle == v) {
        contact_response.set_column(
            c.column,
            &(effective_flexibility.column(c.dof) * nm.weight()),
        );
    }
    Ok((effective_flexibility, contact_response))
}

/// What the contact problem of a step owes to where the wheels are, not to
/// the state: the same for every sample of a scene at a given step.
#[derive(Debug, Clone)]
pub(in crate::solve) struct ContactGeometry {
    /// Whether each contact wheel is on the deck.
    pub on_deck: Vec<bool>,
    /// Mode values φ_c at each contact (0 off the deck), contact-major.
    pub shapes: Vec<f64>,
    /// φ_c scaled by the modal contact flexibility, (1+α)φ_c/k̂.
    pub scaled: Vec<f64>,
    /// The contact compliance W = EᵀH + ΦDΦᵀ + residual flexibility, m/N,
    /// row-major nc × nc.
    pub compliance: Vec<f64>,
    /// Its residual (static-correction) part R, m/N, row-major nc × nc.
    pub residual: Vec<f64>,
}

impl ContactGeometry {
    /// Storage for `contacts` wheels and `modes` modes.
    pub fn new(contacts: usize, modes: usize) -> Self {
        Self {
            on_deck: vec![false; contacts],
            shapes: vec![0.0; contacts * modes],
            scaled: vec![0.0; contacts * modes],
            compliance: vec![0.0; contacts * contacts],
            residual: vec![0.0; contacts * contacts],
        }
    }

    /// Mode values of every contact at `wheel_positions` (m).
    pub fn locate(
        &mut self,
        model: &Model,
        contact_flexibility: &[f64],
        contacts: &[ContactWheel],
        wheel_positions: &[f64],
    ) {
        let bridge = &model.bridge;
        let modes = bridge.mode_count();
        for (c, contact) in contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            self.on_deck[c] = bridge.is_on(x);
            let phi = &mut self.shapes[c * modes..(c + 1) * modes];
            let scaled_c = &mut self.scaled[c * modes..(c + 1) * modes];
            // Off the deck every mode value is 0: no lookup needed.
            if self.on_deck[c] {
                bridge.contact_mode_values(x, model.wheel_y[contact.wheel], phi);
                for i in 0..modes {
                    scaled_c[i] = phi[i] * contact_flexibility[i];
                }
            } else {
                phi.fill(0.0);
                scaled_c.fill(0.0);
            }
        }
    }

    /// The contact compliance W after [`Self::locate`]; `contact_response`
    /// gives each vehicle's H.
    pub fn assemble<'a>(
        &mut self,
        model: &Model,
        contacts: &[ContactWheel],
        wheel_positions: &[f64],
        contact_response: impl Fn(usize) -> &'a DMatrix<f64>,
    ) {
        let (bridge, nc) = (&model.bridge, contacts.len());
        let modes = bridge.mode_count();
        let (on_deck, shapes, scaled) = (&self.on_deck, &self.shapes, &self.scaled);
        let (compliance, residual) = (&mut self.compliance, &mut self.residual);
        for a in 0..nc {
            for b in 0..=a {
                let (ca, cb) = (contacts[a], contacts[b]);
                // A wheel off the deck has no mode values and no residual
                // flexibility (both exactly 0): skip the O(modes) work, which
                // dominates long trains with most wheels off the bridge.
                let mut w = 0.0;
                let mut r = 0.0;
                if on_deck[a] && on_deck[b] {
                    let pa = &shapes[a * modes..(a + 1) * modes];
                    let sb = &scaled[b * modes..(b + 1) * modes];
                    w = pa.iter().zip(sb).map(|(p, s)| p * s).sum();
                    // The modes left out add their static flexibility between the
                    // two contacts (contact static correction; 0 when off).
                    // Unilateral contacts are vertical.
                    r = bridge.residual_flexibility(
                        (
                            ContactDirection::Vertical,
                            wheel_positions[ca.wheel],
                            model.wheel_y[ca.wheel],
                        ),
                        (
                            ContactDirection::Vertical,
                            wheel_positions[cb.wheel],
                            model.wheel_y[cb.wheel],
                        ),
                        pa,
                        &shapes[b * modes..(b + 1) * modes],
                    );
                    w += r;
                } else if ca.vehicle != cb.vehicle {
                    compliance[a * nc + b] = 0.0;
                    compliance[b * nc + a] = 0.0;
                    residual[a * nc + b] = 0.0;
                    residual[b * nc + a] = 0.0;
                    continue;
                }
                residual[a * nc + b] = r;
                residual[b * nc + a] = r;
                if ca.vehicle == cb.vehicle {
                    w += contact_response(ca.vehicle)[(ca.dof, cb.column)];
                }
                compliance[a * nc + b] = w;
                compliance[b * nc + a] = w;
            }
        }
    }
}
