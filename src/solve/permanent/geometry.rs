//! Where the contacts are this step: the shape rows and contact columns at
//! the wheels' positions, the residual flexibility of the modes left out
//! (the mode-acceleration method on the contact flexibility) and the rates
//! of the residual deflection each wheel rides; shared between EMBS's two
//! orders by swapping the buffers.

use super::super::modal::ModalStep;
use super::super::newmark::Newmark;
use super::super::residual_rates::{ResidualRates, ResidualStart, residual_coupling, step_of};
use super::{PermanentContacts, dot};
use crate::model::Model;
use faer::linalg::matmul::matmul;
use faer::{Accum, Par};

impl PermanentContacts {
    /// The quasi-static deflection of the modes left out at contact `c`
    /// under the contact forces `forces` (N), s = −Σ_d R_cd λ_d, m; 0 without
    /// the contact correction. Cost O(contacts).
    #[inline]
    pub(super) fn residual_deflection(&self, c: usize, forces: &[f64]) -> f64 {
        if self.residual.is_empty() {
            return 0.0;
        }
        let nc = self.contacts.len();
        -dot(&self.residual[c * nc..(c + 1) * nc], forces)
    }

    /// Whether contact `c` is off the model this step: no residual
    /// flexibility to any contact (on the rigid approach, or without the
    /// contact correction). Its wheel rides no residual deflection, and s
    /// and its rates restart from rest when it enters.
    #[inline]
    pub(super) fn off_model(&self, c: usize) -> bool {
        let nc = self.contacts.len();
        self.residual.is_empty()
            || self.residual[c * nc..(c + 1) * nc]
                .iter()
                .all(|&r| r == 0.0)
    }

    pub(super) fn swap_geometry(&mut self, other: &mut Self) {
        debug_assert_eq!(self.contacts.len(), other.contacts.len());
        debug_assert_eq!(self.residual.len(), other.residual.len());
        std::mem::swap(&mut self.shapes, &mut other.shapes);
        std::mem::swap(&mut self.path, &mut other.path);
        std::mem::swap(&mut self.contact_columns, &mut other.contact_columns);
        std::mem::swap(&mut self.scaled_columns, &mut other.scaled_columns);
        std::mem::swap(&mut self.residual, &mut other.residual);
    }

    /// The contacts' geometry at this step's wheel positions: speed and
    /// acceleration along the path, the shape rows φ, φ′, φ″ and the Newmark
    /// velocity and acceleration rows, the contact columns, and the residual
    /// flexibility R = G − ΦΩ⁻²Φᵀ when the contacts are corrected.
    /// Cost O(modes·contacts) + O(modes·contacts²) with the correction.
    pub(super) fn locate(
        &mut self,
        model: &Model,
        nm: &Newmark,
        modal: &ModalStep,
        t: f64,
        wheel_positions: &[f64],
    ) {
        let bridge = &model.bridge;
        for (c, contact) in self.contacts.iter().enumerate() {
            let x = wheel_positions[contact.wheel];
            let vehicle = &model.vehicles[contact.vehicle];
            let (v, a) = (vehicle.speed_at(t), vehicle.acceleration_at(t));
            self.path[c] = (v, a);
            let s = &mut self.shapes[c];
            bridge.contact_mode_components(
                contact.direction,
                x,
                contact.y,
                &mut s.values,
                &mut s.slopes,
                &mut s.curvatures,
            );
            for i in 0..s.values.len() {
                s.scaled[i] = s.values[i] * modal.contact_flexibility[i];
                s.velocity_row[i] = nm.a1 * s.values[i] + v * s.slopes[i];
                s.acceleration_row[i] =
                    nm.a0 * s.values[i] + 2.0 * v * nm.a1 * s.slopes[i] + v * v * s.curvatures[i];
            }
            // The a-terms only where the vehicle accelerates, so a scene at
            // constant speed computes exactly what it did before.
            if a != 0.0 {
                for (row, slope) in s.acceleration_row.iter_mut().zip(&s.slopes) {
                    *row += a * slope;
                }
            }
            self.contact_columns[0]
                .col_as_slice_mut(c)
                .copy_from_slice(&s.values);
            self.contact_columns[1]
                .col_as_slice_mut(c)
                .copy_from_slice(&s.velocity_row);
            self.contact_columns[2]
                .col_as_slice_mut(c)
                .copy_from_slice(&s.acceleration_row);
            self.scaled_columns
                .col_as_slice_mut(c)
                .copy_from_slice(&s.scaled);
        }
        if !self.residual.is_empty() {
            // The modes left out deflect quasi-statically under the contact
            // forces: the wheel rides s = −Σ_d R_cd λ_d on top of φ·q
            // (mode-acceleration method applied to the contact flexibility).
            // The modes left out carry no mass, but the wheel riding s does:
            // its velocity and acceleration enter the wheel's kinematics
            // ([`ResidualRates`]), so the wheel's mass bounces on the
            // residual spring as on the kept modes. On an imported ballasted
            // track the residual is the pads' and ballast's local compliance
            // (7 % of the contact flexibility at the 564 automatic modes of
            // the EMBS golden viaduct): leaving s̈ out took the wheel's
            // inertia off it and shifted the wheel–track (P2-type, 30–50 Hz)
            // response by 9 % of the wheel force and 22 % of the deck
            // acceleration against twice the modes (issue 24.4,
            // docs/methods.md, "Why the wheel's mass rides the residual"). Only where the wheel's oscillation on the
            // residual lies below the kept band does the wheel ride s's
            // rates ([`residual_coupling`]): above it (beams at few modes,
            // the load weight's ramps) the residual stays quasi-static.
            let nc = self.contacts.len();
            for c in 0..nc {
                let values = &self.shapes[c].values;
                for (i, omega) in bridge.circular_frequencies.iter().enumerate() {
                    self.modal_columns[(i, c)] = values[i] / (omega * omega);
                }
            }
            matmul(
                self.modal_flexibility.as_mut(),
                Accum::Replace,
                self.contact_columns[0].as_ref().transpose(),
                self.modal_columns.as_ref(),
                1.0,
                Par::Seq,
            );
            let point = |k: usize| {
                let contact = &self.contacts[k];
                (contact.direction, wheel_positions[contact.wheel], contact.y)
            };
            for c in 0..nc {
                for d in 0..=c {
                    let green = bridge.static_flexibility(point(c), point(d)).unwrap_or(0.0);
                    let r = green - self.modal_flexibility[(c, d)];
                    self.residual[c * nc + d] = r;
                    self.residual[d * nc + c] = r;
                }
            }
        }
    }

    /// The residual deflection's rates for this step ([`ResidualRates`]):
    /// each contact's WBZ-α relations from its motion at tₙ, restarted where
    /// the wheel enters the model, and their history terms added to the
    /// λ = 0 kinematics ([`Self::base`]). After [`Self::predict_wheels`];
    /// nothing without the contact correction.
    pub(super) fn begin_residual_rates(
        &mut self,
        model: &Model,
        nm: &Newmark,
        wheel_positions: &[f64],
    ) {
        if self.residual.is_empty() {
            return;
        }
        let bridge = &model.bridge;
        let nc = self.contacts.len();
        for c in 0..nc {
            let off_model = self.off_model(c);
            let start = if off_model {
                ResidualStart::Running
            } else {
                match self.off_model_before[c] {
                    Some(true) => ResidualStart::Entering,
                    Some(false) => ResidualStart::Running,
                    // The first step: a wheel on the model at t₀ starts
                    // at rest (s static); one at a support or off the
                    // model then enters. Its place at t₀ from its speed.
                    None => {
                        let contact = &self.contacts[c];
                        let x0 = wheel_positions[contact.wheel] - self.path[c].0 * step_of(nm);
                        let point = (contact.direction, x0, contact.y);
                        match bridge.static_flexibility(point, point) {
                            Some(g) if g != 0.0 => ResidualStart::AtRest,
                            _ => ResidualStart::Entering,
                        }
                    }
                }
            };
            let coupling = residual_coupling(
                self.wheel_mass[c],
                self.residual[c * nc + c],
                self.top_omega,
            );
            self.residual_rates[c] = ResidualRates::new(nm, start, coupling);
            if off_model {
                self.residual_motion[c] = [0.0; 3];
            }
            self.off_model_before[c] = Some(off_model);
            let [velocity, acceleration] = self.residual_rates[c].history(self.residual_motion[c]);
            self.base[c][1] += velocity;
            self.base[c][2] += acceleration;
        }
    }
}
