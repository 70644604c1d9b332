//! The batch's state held lane by lane (`[f64; LANES]` per quantity) and
//! the per-lane Newmark/HHT steps of the bridge and the vehicles, each with
//! the floating-point operations of [`crate::solve::unilateral::Unilateral`] in
//! the same order.

use nalgebra::DMatrix;

use super::{LANES, Lanes};
use crate::solve::VehicleState;
use crate::solve::modal::ModalStep;
use crate::solve::newmark::Newmark;

/// y += a · A x over a vehicle matrix's nonzero entries, lane by lane, with
/// the rounding of [`crate::solve::unilateral::block_gemv`]: nalgebra's
/// `(a·Aᵢⱼ)·xⱼ + yᵢ` for one block covering every DOF, `yᵢ + (a·xⱼ)·Aᵢⱼ`
/// block by block otherwise, each yᵢ taking its terms in ascending j as
/// both do (column by column), here row by row so that yᵢ stays in
/// registers.
#[derive(Debug, Clone)]
pub(super) struct Product {
    /// One block covering every DOF (nalgebra's product).
    pub(super) whole: bool,
    /// (row, column, Aᵢⱼ), row by row, columns ascending.
    pub(super) entries: Vec<(usize, usize, f64)>,
    /// Each row that has entries: (row, its entries' range).
    pub(super) rows: Vec<(usize, std::ops::Range<usize>)>,
}

impl Product {
    pub(super) fn new(matrix: &DMatrix<f64>, blocks: &[std::ops::Range<usize>]) -> Self {
        let n = matrix.nrows();
        let whole = blocks.len() == 1 && blocks[0] == (0..n);
        let mut entries = Vec::new();
        let mut rows = Vec::new();
        let whole_block = std::iter::once(0..n).collect::<Vec<_>>();
        let blocks = if whole { &whole_block[..] } else { blocks };
        for block in blocks {
            for i in block.clone() {
                let start = entries.len();
                for j in block.clone() {
                    if matrix[(i, j)] != 0.0 {
                        entries.push((i, j, matrix[(i, j)]));
                    }
                }
                if entries.len() > start {
                    rows.push((i, start..entries.len()));
                }
            }
        }
        Self {
            whole,
            entries,
            rows,
        }
    }

    #[inline(always)]
    pub(super) fn apply(&self, y: &mut [Lanes], a: f64, x: &[Lanes]) {
        for (i, range) in &self.rows {
            let mut sum = y[*i];
            if self.whole {
                for &(_, j, value) in &self.entries[range.clone()] {
                    let (scaled, xj) = (a * value, &x[j]);
                    for l in 0..LANES {
                        sum[l] += scaled * xj[l];
                    }
                }
            } else {
                for &(_, j, value) in &self.entries[range.clone()] {
                    let xj = &x[j];
                    for l in 0..LANES {
                        sum[l] += (a * xj[l]) * value;
                    }
                }
            }
            y[*i] = sum;
        }
    }
}

/// One vehicle's matrices and its lanes' state.
#[derive(Debug, Clone)]
pub(super) struct VehicleLanes {
    pub(super) mass: Product,
    pub(super) damping: Product,
    pub(super) stiffness: Product,
    pub(super) effective_flexibility: Product,
    pub(super) recovery: Product,
    pub(super) gravity_load: Vec<f64>,
    /// Static equilibrium on level ground, m (the guard's reference).
    pub(super) static_displacement: Vec<f64>,
    pub(super) contact_response: DMatrix<f64>,
    pub(super) displacement: Vec<Lanes>,
    pub(super) velocity: Vec<Lanes>,
    pub(super) acceleration: Vec<Lanes>,
    pub(super) effective_load: Vec<Lanes>,
    pub(super) inertia_history: Vec<Lanes>,
    pub(super) damping_history: Vec<Lanes>,
    pub(super) predictor: Vec<Lanes>,
    pub(super) recovery_load: Vec<Lanes>,
    pub(super) predicted_velocity: Vec<Lanes>,
    pub(super) recovered_acceleration: Vec<Lanes>,
}

/// The bridge's lanes: modal state and this step's forces.
#[derive(Debug, Clone)]
pub(super) struct ModalLanes {
    pub(super) displacement: Vec<Lanes>,
    pub(super) velocity: Vec<Lanes>,
    pub(super) acceleration: Vec<Lanes>,
    pub(super) predictor: Vec<Lanes>,
    pub(super) current_force: Vec<Lanes>,
    pub(super) previous_force: Vec<Lanes>,
}

/// What one lane shows its observer and guard.
#[derive(Debug, Clone)]
pub(super) struct LaneView {
    pub(super) modal_displacement: Vec<f64>,
    pub(super) modal_acceleration: Vec<f64>,
    pub(super) states: Vec<VehicleState>,
    pub(super) contact_forces: Vec<f64>,
    pub(super) contact_gaps: Vec<f64>,
}

/// The guard's mechanical energy per lane, J: ½Σᵢ(q̇ᵢ² + ωᵢ²qᵢ²) +
/// Σᵥ[½u̇ᵀMu̇ + ½(u − u₀)ᵀK(u − u₀)] ([`Guard`](crate::solve::guard::Guard); summed in another order,
/// which only moves a divergence threshold by round-off).
#[inline(always)]
pub(super) fn mechanical_energy(
    bridge: &ModalLanes,
    modal: &ModalStep,
    vehicles: &[VehicleLanes],
) -> Lanes {
    let mut twice = [0.0; LANES];
    for ((q, v), k) in bridge
        .displacement
        .iter()
        .zip(&bridge.velocity)
        .zip(&modal.stiffness)
    {
        for l in 0..LANES {
            twice[l] += v[l] * v[l] + k * q[l] * q[l];
        }
    }
    for vehicle in vehicles {
        let (u, u0, v) = (
            &vehicle.displacement,
            &vehicle.static_displacement,
            &vehicle.velocity,
        );
        for &(i, j, m) in &vehicle.mass.entries {
            for l in 0..LANES {
                twice[l] += v[i][l] * m * v[j][l];
            }
        }
        for &(i, j, k) in &vehicle.stiffness.entries {
            for l in 0..LANES {
                twice[l] += (u[i][l] - u0[i]) * k * (u[j][l] - u0[j]);
            }
        }
    }
    twice.map(|e| 0.5 * e)
}

/// [`ModalStep::predict`] with no moving load and no ground motion, lane by
/// lane.
#[inline(always)]
pub(super) fn predict_bridge(lanes: &mut ModalLanes, modal: &ModalStep, nm: &Newmark) {
    let (w, alpha) = (nm.weight(), nm.alpha);
    lanes.current_force.fill([0.0; LANES]);
    for i in 0..lanes.predictor.len() {
        let (c, k, flexibility) = (
            modal.modal_damping[i],
            modal.stiffness[i],
            modal.flexibility[i],
        );
        let (q, v, a) = (
            lanes.displacement[i],
            lanes.velocity[i],
            lanes.acceleration[i],
        );
        let (current, previous) = (lanes.current_force[i], lanes.previous_force[i]);
        let predictor = &mut lanes.predictor[i];
        for l in 0..LANES {
            let inertia = nm.inertia_history(q[l], v[l], a[l]);
            let damping = nm.damping_history(q[l], v[l], a[l]);
            predictor[l] = (w * current[l] - alpha * previous[l]
                + inertia
                + w * c * damping
                + alpha * (c * v[l] + k * q[l]))
                * flexibility;
        }
    }
}

/// [`ModalStep::finish`], lane by lane.
#[inline(always)]
pub(super) fn finish_bridge(lanes: &mut ModalLanes, modal: &ModalStep, nm: &Newmark) {
    let (w, alpha) = (nm.weight(), nm.alpha);
    for i in 0..lanes.predictor.len() {
        let (c, k) = (modal.modal_damping[i], modal.stiffness[i]);
        let (current, previous) = (lanes.current_force[i], lanes.previous_force[i]);
        let q = lanes.predictor[i];
        let (q_old, v_old, a_old) = (
            lanes.displacement[i],
            lanes.velocity[i],
            lanes.acceleration[i],
        );
        let mut a_new = [0.0; LANES];
        let mut v_new = [0.0; LANES];
        for l in 0..LANES {
            a_new[l] = (w * current[l]
                - alpha * previous[l]
                - w * c * (v_old[l] + nm.a6 * a_old[l])
                - w * k * q[l]
                + alpha * (c * v_old[l] + k * q_old[l]))
                / (1.0 + w * nm.a7 * c);
            v_new[l] = nm.velocity(v_old[l], a_old[l], a_new[l]);
        }
        lanes.displacement[i] = q;
        lanes.acceleration[i] = a_new;
        lanes.velocity[i] = v_new;
    }
    std::mem::swap(&mut lanes.previous_force, &mut lanes.current_force);
}

/// The vehicle predictor's load R̂ = f_g + M hₐ + (1+α)C h_v + α(C u̇ₙ + K uₙ)
/// (the −αEλₙ term is the caller's), as in `unilateral`.
#[inline(always)]
pub(super) fn predict_vehicle(vehicle: &mut VehicleLanes, nm: &Newmark) {
    for k in 0..vehicle.displacement.len() {
        let (u, v, a) = (
            vehicle.displacement[k],
            vehicle.velocity[k],
            vehicle.acceleration[k],
        );
        for l in 0..LANES {
            vehicle.inertia_history[k][l] = nm.inertia_history(u[l], v[l], a[l]);
            vehicle.damping_history[k][l] = nm.damping_history(u[l], v[l], a[l]);
        }
        vehicle.effective_load[k] = [vehicle.gravity_load[k]; LANES];
    }
    let load = &mut vehicle.effective_load;
    vehicle.mass.apply(load, 1.0, &vehicle.inertia_history);
    vehicle
        .damping
        .apply(load, nm.weight(), &vehicle.damping_history);
    if nm.alpha != 0.0 {
        vehicle.damping.apply(load, nm.alpha, &vehicle.velocity);
        vehicle
            .stiffness
            .apply(load, nm.alpha, &vehicle.displacement);
    }
}

/// The vehicle's accelerations from the HHT equations of motion and its new
/// state, as in `unilateral` (`recovery_load` holds the contact share).
#[inline(always)]
pub(super) fn recover_vehicle(vehicle: &mut VehicleLanes, nm: &Newmark) {
    let w = nm.weight();
    let n = vehicle.displacement.len();
    for k in 0..n {
        let gravity = vehicle.gravity_load[k];
        for l in 0..LANES {
            vehicle.recovery_load[k][l] += gravity;
        }
    }
    vehicle
        .stiffness
        .apply(&mut vehicle.recovery_load, -w, &vehicle.predictor);
    for k in 0..n {
        let (v, a) = (vehicle.velocity[k], vehicle.acceleration[k]);
        for l in 0..LANES {
            vehicle.predicted_velocity[k][l] = nm.a6 * a[l] + v[l];
        }
    }
    vehicle
        .damping
        .apply(&mut vehicle.recovery_load, -w, &vehicle.predicted_velocity);
    if nm.alpha != 0.0 {
        vehicle
            .damping
            .apply(&mut vehicle.recovery_load, nm.alpha, &vehicle.velocity);
        vehicle
            .stiffness
            .apply(&mut vehicle.recovery_load, nm.alpha, &vehicle.displacement);
    }
    vehicle.recovered_acceleration.fill([0.0; LANES]);
    vehicle.recovery.apply(
        &mut vehicle.recovered_acceleration,
        1.0,
        &vehicle.recovery_load,
    );
    for k in 0..n {
        let (v, a, a_new) = (
            vehicle.velocity[k],
            vehicle.acceleration[k],
            vehicle.recovered_acceleration[k],
        );
        for l in 0..LANES {
            vehicle.velocity[k][l] = nm.velocity(v[l], a[l], a_new[l]);
        }
        vehicle.acceleration[k] = a_new;
        vehicle.displacement[k] = vehicle.predictor[k];
    }
}
