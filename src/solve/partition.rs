//! A vehicle's matrices split into wheel DOFs W (those that ride the surface)
//! and free DOFs F, with the free DOFs condensed for one HHT-α Newmark step
//! (w = 1 + α; constants in [`super::newmark`]).
//!
//! With ü = a₀u − hₐ and u̇ = a₁u − h_v at t_{n+1}, the free rows give
//! u_F = K̂_FF⁻¹ [R̂_F − M_FW ü_W − w(C_FW u̇_W + K_FW u_W)],
//! K̂ = a₀M + w(a₁C + K), R̂_F = f_g,F + M_FF hₐ,F + w C_FF h_v,F + α(C_F· u̇ₙ + K_F· uₙ),
//! and the wheel rows give the contact forces
//! w λ_W = λ⁰ + M̃ ü_W + C̃ u̇_W + K̃ u_W, with T = K̂_WF K̂_FF⁻¹,
//! M̃ = M_WW − T M_FW, C̃ = w(C_WW − T C_FW), K̃ = w(K_WW − T K_FW) and
//! λ⁰ = T R̂_F − M_WF hₐ,F − w C_WF h_v,F − α(C_W· u̇ₙ + K_W· uₙ) − f_g,W + α λₙ.
//! The stored M̃, C̃, K̃ and λ⁰ are divided by w, so they give λ_W directly.
//! All matrices are constant over the run; per step only vectors change.

use nalgebra::{DMatrix, DVector};

use super::newmark::Newmark;
use super::row_spans::{RowSpans, column_spans};
use crate::vehicle::VehicleModel;

/// Constant condensed matrices of one vehicle, and its step work vectors.
#[derive(Debug, Clone)]
pub struct Partition {
    /// Wheel DOF indices, in the vehicle's contact-wheel order.
    pub wheel_dofs: Vec<usize>,
    /// Free DOF indices.
    pub free_dofs: Vec<usize>,
    /// K̂_FF⁻¹, m/N.
    effective_flexibility: RowSpans,
    mass_ff: RowSpans,
    /// C_FF by columns (the recovery's loop) and by rows (the products).
    damping_ff: DMatrix<f64>,
    damping_ff_rows: RowSpans,
    /// For each column of the F × W blocks (M_FW, C_FW, K_FW together) and of
    /// C_FF, the span of free rows where it is nonzero: the loops of
    /// [`Partition::finish_step`] run over it only.
    wheel_column_spans: Vec<(usize, usize)>,
    free_column_spans: Vec<(usize, usize)>,
    mass_fw: DMatrix<f64>,
    damping_fw: DMatrix<f64>,
    stiffness_fw: DMatrix<f64>,
    mass_wf: RowSpans,
    damping_wf: RowSpans,
    /// Rows F (resp. W) of C and K over all DOFs, for the α terms.
    damping_f_all: RowSpans,
    stiffness_f_all: RowSpans,
    damping_w_all: RowSpans,
    stiffness_w_all: RowSpans,
    /// T = K̂_WF K̂_FF⁻¹.
    transfer: RowSpans,
    /// (M_FF + wγΔt C_FF)⁻¹, for recovering ü_F from the equations of
    /// motion ([`Partition::finish_step`]).
    recovery: RowSpans,
    /// α(C_F·u̇ₙ + K_F·uₙ) of the current step, N.
    alpha_terms: DVector<f64>,
    /// Work vector for the recovery, N.
    recovery_load: DVector<f64>,
    /// M̃/w: contact force per unit wheel acceleration, kg.
    pub condensed_mass: DMatrix<f64>,
    /// C̃/w, N·s/m.
    pub condensed_damping: DMatrix<f64>,
    /// K̃/w, N/m.
    pub condensed_stiffness: DMatrix<f64>,
    gravity_f: DVector<f64>,
    gravity_w: DVector<f64>,
    /// Rows F (resp. W) of the vehicle's lateral ground load −M δ_y,
    /// N/(m/s²); empty for a vehicle without lateral DOFs.
    lateral_f: DVector<f64>,
    lateral_w: DVector<f64>,
    /// This step's HHT-weighted lateral ground acceleration, m/s²: the
    /// external load is f_g (1 + gravity ratio) + (−M δ_y) · this. Set by
    /// the caller before [`Partition::begin_step`].
    pub lateral_ground: f64,
    /// This step's extra weight as a multiple of the gravity loads (ground
    /// motion), dimensionless.
    gravity_ratio: f64,
    weight: f64,
    alpha: f64,
    // Work vectors.
    inertia_history: DVector<f64>,
    damping_history: DVector<f64>,
    effective_load: DVector<f64>,
    coupling: DVector<f64>,
    /// λ⁰/w of the current step, N.
    pub base_forces: DVector<f64>,
    free_solution: DVector<f64>,
}

fn select(m: &DMatrix<f64>, rows: &[usize], cols: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), cols.len(), |i, j| m[(rows[i], cols[j])])
}

impl Partition {
    /// Splits `vehicle` with the given wheel DOFs; `None` if K̂_FF is singular.
    pub fn new(vehicle: &VehicleModel, wheel_dofs: Vec<usize>, nm: &Newmark) -> Option<Self> {
        let n = vehicle.dofs();
        let all: Vec<usize> = (0..n).collect();
        let free_dofs: Vec<usize> = (0..n).filter(|d| !wheel_dofs.contains(d)).collect();
        let (w, f) = (&wheel_dofs[..], &free_dofs[..]);
        let weight = nm.weight();
        let effective =
            &vehicle.mass * nm.a0 + (&vehicle.damping * nm.a1 + &vehicle.stiffness) * weight;
        let effective_flexibility = select(&effective, f, f).try_inverse()?;
        let recovery = (select(&vehicle.mass, f, f)
            + select(&vehicle.damping, f, f) * (weight * nm.a7))
            .try_inverse()?;
        let transfer = select(&effective, w, f) * &effective_flexibility;
        let mass_fw = select(&vehicle.mass, f, w);
        let damping_fw = select(&vehicle.damping, f, w);
        let stiffness_fw = select(&vehicle.stiffness, f, w);
        let condensed_mass = (select(&vehicle.mass, w, w) - &transfer * &mass_fw) / weight;
        let condensed_damping = select(&vehicle.damping, w, w) - &transfer * &damping_fw;
        let condensed_stiffness = select(&vehicle.stiffness, w, w) - &transfer * &stiffness_fw;
        let pick = |v: &DVector<f64>, idx: &[usize]| DVector::from_fn(idx.len(), |i, _| v[idx[i]]);
        let damping_ff = select(&vehicle.damping, f, f);
        Some(Self {
            mass_ff: RowSpans::new(&select(&vehicle.mass, f, f)),
            wheel_column_spans: column_spans(&[&mass_fw, &damping_fw, &stiffness_fw]),
            free_column_spans: column_spans(&[&damping_ff]),
            damping_ff_rows: RowSpans::new(&damping_ff),
            damping_ff,
            mass_wf: RowSpans::new(&select(&vehicle.mass, w, f)),
            damping_wf: RowSpans::new(&select(&vehicle.damping, w, f)),
            damping_f_all: RowSpans::new(&select(&vehicle.damping, f, &all)),
            stiffness_f_all: RowSpans::new(&select(&vehicle.stiffness, f, &all)),
            recovery: RowSpans::new(&recovery),
            alpha_terms: DVector::zeros(f.len()),
            recovery_load: DVector::zeros(f.len()),
            damping_w_all: RowSpans::new(&select(&vehicle.damping, w, &all)),
            stiffness_w_all: RowSpans::new(&select(&vehicle.stiffness, w, &all)),
            gravity_f: pick(&vehicle.gravity_load, f),
            gravity_w: pick(&vehicle.gravity_load, w),
            lateral_f: if vehicle.lateral_ground_load.is_empty() {
                DVector::zeros(0)
            } else {
                pick(&vehicle.lateral_ground_load, f)
            },
            lateral_w: if vehicle.lateral_ground_load.is_empty() {
                DVector::zeros(0)
            } else {
                pick(&vehicle.lateral_ground_load, w)
            },
            lateral_ground: 0.0,
            gravity_ratio: 0.0,
            weight,
            alpha: nm.alpha,
            inertia_history: DVector::zeros(f.len()),
            damping_history: DVector::zeros(f.len()),
            effective_load: DVector::zeros(f.len()),
            coupling: DVector::zeros(f.len()),
            base_forces: DVector::zeros(w.len()),
            free_solution: DVector::zeros(f.len()),
            effective_flexibility: RowSpans::new(&effective_flexibility),
            mass_fw,
            damping_fw,
            stiffness_fw,
            transfer: RowSpans::new(&transfer),
            condensed_mass,
            condensed_damping,
            condensed_stiffness,
            wheel_dofs,
            free_dofs,
        })
    }

    /// The lateral ground acceleration that loads this vehicle this step,
    /// m/s² (0 for a vehicle without lateral DOFs).
    #[inline]
    fn lateral_acceleration(&self) -> f64 {
        if self.lateral_f.is_empty() && self.lateral_w.is_empty() {
            0.0
        } else {
            self.lateral_ground
        }
    }

    /// Starts a step from the state at tₙ and the wheels' contact forces λₙ
    /// (N, in wheel order): forms R̂_F and λ⁰/w.
    pub fn begin_step(
        &mut self,
        nm: &Newmark,
        gravity_ratio: f64,
        displacement: &DVector<f64>,
        velocity: &DVector<f64>,
        acceleration: &DVector<f64>,
        previous_forces: impl Iterator<Item = f64>,
    ) {
        for (k, &d) in self.free_dofs.iter().enumerate() {
            let (u, v, a) = (displacement[d], velocity[d], acceleration[d]);
            self.inertia_history[k] = nm.inertia_history(u, v, a);
            self.damping_history[k] = nm.damping_history(u, v, a);
        }
        let (w, alpha) = (self.weight, self.alpha);
        self.gravity_ratio = gravity_ratio;
        self.effective_load.copy_from(&self.gravity_f);
        if gravity_ratio != 0.0 {
            self.effective_load
                .axpy(gravity_ratio, &self.gravity_f, 1.0);
        }
        let lateral = self.lateral_acceleration();
        if lateral != 0.0 {
            self.effective_load.axpy(lateral, &self.lateral_f, 1.0);
        }
        self.mass_ff
            .gemv(&mut self.effective_load, 1.0, &self.inertia_history, 1.0);
        self.damping_ff_rows
            .gemv(&mut self.effective_load, w, &self.damping_history, 1.0);
        self.alpha_terms.fill(0.0);
        if alpha != 0.0 {
            self.damping_f_all
                .gemv(&mut self.alpha_terms, alpha, velocity, 1.0);
            self.stiffness_f_all
                .gemv(&mut self.alpha_terms, alpha, displacement, 1.0);
            self.effective_load += &self.alpha_terms;
        }
        // λ⁰ = T R̂_F − M_WF hₐ − w C_WF h_v − α(C_W·u̇ₙ + K_W·uₙ) − f_g,W + αλₙ.
        self.base_forces.copy_from(&self.gravity_w);
        if gravity_ratio != 0.0 {
            self.base_forces.axpy(gravity_ratio, &self.gravity_w, 1.0);
        }
        if lateral != 0.0 {
            self.base_forces.axpy(lateral, &self.lateral_w, 1.0);
        }
        self.transfer
            .gemv(&mut self.base_forces, 1.0, &self.effective_load, -1.0);
        self.mass_wf
            .gemv(&mut self.base_forces, -1.0, &self.inertia_history, 1.0);
        self.damping_wf
            .gemv(&mut self.base_forces, -w, &self.damping_history, 1.0);
        if alpha != 0.0 {
            self.damping_w_all
                .gemv(&mut self.base_forces, -alpha, velocity, 1.0);
            self.stiffness_w_all
                .gemv(&mut self.base_forces, -alpha, displacement, 1.0);
            for (b, force) in self.base_forces.iter_mut().zip(previous_forces) {
                *b += alpha * force;
            }
        }
        self.base_forces /= w;
    }

    /// Finishes the step: with the wheel DOFs' new displacement, velocity and
    /// acceleration already in the state, solves the free DOFs and writes
    /// their velocity and acceleration.
    ///
    /// ü_F is recovered from the HHT equations of motion of the free rows,
    /// (M_FF + wγΔt C_FF) ü_F = f_g,F − M_FW ü_W − w[C_FF(u̇ₙ + (1−γ)Δt üₙ)_F
    /// plus C_FW u̇_W plus K_F· u_{n+1}] + α(C_F·u̇ₙ + K_F·uₙ), and u̇_F from
    /// Newmark's velocity update; not as a₀(u_{n+1} − uₙ) − …, whose
    /// round-off grows like ε|u|/Δt² (u is measured from the springs' free
    /// lengths, so |u| is the static sag). The same scheme in exact arithmetic.
    pub fn finish_step(
        &mut self,
        nm: &Newmark,
        displacement: &mut DVector<f64>,
        velocity: &mut DVector<f64>,
        acceleration: &mut DVector<f64>,
    ) {
        let w = self.weight;
        self.coupling.copy_from(&self.effective_load);
        for (j, &d) in self.wheel_dofs.iter().enumerate() {
            let (u, v, a) = (displacement[d], velocity[d], acceleration[d]);
            let (first, end) = self.wheel_column_spans[j];
            for i in first..end {
                self.coupling[i] -= self.mass_fw[(i, j)] * a
                    + w * (self.damping_fw[(i, j)] * v + self.stiffness_fw[(i, j)] * u);
            }
        }
        self.effective_flexibility
            .gemv(&mut self.free_solution, 1.0, &self.coupling, 0.0);
        // Recovery load: every term but the free DOFs' new velocity's
        // unknown part; the wheel DOFs are already at t_{n+1}.
        self.recovery_load.copy_from(&self.gravity_f);
        if self.gravity_ratio != 0.0 {
            self.recovery_load
                .axpy(self.gravity_ratio, &self.gravity_f, 1.0);
        }
        let lateral = self.lateral_acceleration();
        if lateral != 0.0 {
            self.recovery_load.axpy(lateral, &self.lateral_f, 1.0);
        }
        self.recovery_load += &self.alpha_terms;
        for (k, &d) in self.free_dofs.iter().enumerate() {
            displacement[d] = self.free_solution[k];
        }
        self.stiffness_f_all
            .gemv(&mut self.recovery_load, -w, displacement, 1.0);
        for (j, &d) in self.wheel_dofs.iter().enumerate() {
            let (first, end) = self.wheel_column_spans[j];
            for i in first..end {
                self.recovery_load[i] -= self.mass_fw[(i, j)] * acceleration[d]
                    + w * self.damping_fw[(i, j)] * velocity[d];
            }
        }
        for (k, &dk) in self.free_dofs.iter().enumerate() {
            let predicted_velocity = velocity[dk] + nm.a6 * acceleration[dk];
            let (first, end) = self.free_column_spans[k];
            for i in first..end {
                self.recovery_load[i] -= w * self.damping_ff[(i, k)] * predicted_velocity;
            }
        }
        self.recovery
            .gemv(&mut self.coupling, 1.0, &self.recovery_load, 0.0);
        for (k, &d) in self.free_dofs.iter().enumerate() {
            let a_new = self.coupling[k];
            velocity[d] = nm.velocity(velocity[d], acceleration[d], a_new);
            acceleration[d] = a_new;
        }
    }
}
