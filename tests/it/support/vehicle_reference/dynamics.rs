//! The deck's closed-form modes and the right-hand side of the coupled
//! equations (see the parent module for the model).
#![allow(clippy::needless_range_loop)]

use std::f64::consts::PI;

use super::{Case, Deck, Mode, solve};

/// Scratch space of the right-hand side.
pub(super) struct Work {
    /// Mode values at one point, and under every wheel (wheel-major).
    pub(super) shape: Vec<f64>,
    pub(super) under: Vec<f64>,
    /// sin(kπx/L), sin(kπy/B) for k = 0, 1, …
    pub(super) along: Vec<f64>,
    pub(super) across: Vec<f64>,
    pub(super) du: Vec<f64>,
    pub(super) contact: Vec<f64>,
    pub(super) q: Vec<f64>,
    /// ∂φ/∂x (1/m) and ∂²φ/∂x² (1/m²) at one point, and cos(kπx/L).
    pub(super) slope: Vec<f64>,
    pub(super) curvature: Vec<f64>,
    pub(super) along_cos: Vec<f64>,
    /// Per wheel: ṡ (m/s), the part of s̈ not from the deck's modal
    /// accelerations, 2vΣφ′q̇ + v²(Σφ″q + r″) (m/s²), the contact force (N),
    /// whether in contact (rigid contact only).
    pub(super) surface_rate: Vec<f64>,
    pub(super) surface_transport: Vec<f64>,
    pub(super) force: Vec<f64>,
    pub(super) in_contact: Vec<bool>,
    /// Per vehicle, per coordinate: [`Vehicle::own_damping`].
    pub(super) own_damping: Vec<Vec<f64>>,
}

/// cos(k·a) for k = 0 … out.len() − 1, by the same recurrence.
fn cosines(a: f64, out: &mut [f64]) {
    let c2 = 2.0 * a.cos();
    for k in 0..out.len() {
        out[k] = match k {
            0 => 1.0,
            1 => a.cos(),
            _ => c2 * out[k - 1] - out[k - 2],
        };
    }
}

/// sin(k·a) for k = 0 … out.len() − 1.
pub(super) fn sines(a: f64, out: &mut [f64]) {
    let c2 = 2.0 * a.cos();
    for k in 0..out.len() {
        out[k] = match k {
            0 => 0.0,
            1 => a.sin(),
            _ => c2 * out[k - 1] - out[k - 2],
        };
    }
}

pub(super) struct Layout {
    /// First state index of each vehicle's u; its u̇ follows.
    pub(super) offsets: Vec<usize>,
    pub(super) dim: usize,
}

impl Case {
    pub(super) fn modes(&self) -> Vec<Mode> {
        match self.deck {
            Deck::Beam {
                length,
                bending_stiffness,
                mass_per_length,
                modes,
            } => (1..=modes)
                .map(|j| {
                    let k = j as f64 * PI / length;
                    Mode {
                        omega: k * k * (bending_stiffness / mass_per_length).sqrt(),
                        mass: mass_per_length * length / 2.0,
                        m: j,
                        n: 0,
                    }
                })
                .collect(),
            Deck::Plate {
                length,
                width,
                rigidity,
                mass_per_area,
                modes,
            } => {
                let mut all: Vec<Mode> = (1..=40)
                    .flat_map(|m| (1..=40).map(move |n| (m, n)))
                    .map(|(m, n)| {
                        let (a, b) = (m as f64 / length, n as f64 / width);
                        Mode {
                            omega: PI * PI * (a * a + b * b) * (rigidity / mass_per_area).sqrt(),
                            mass: mass_per_area * length * width / 4.0,
                            m,
                            n,
                        }
                    })
                    .collect();
                all.sort_by(|p, q| p.omega.total_cmp(&q.omega));
                let gap = all[modes].omega / all[modes - 1].omega - 1.0;
                assert!(gap > 1e-3, "the mode cut-off splits a near-degenerate pair");
                all.truncate(modes);
                all
            }
        }
    }

    pub(super) fn length(&self) -> f64 {
        match self.deck {
            Deck::Beam { length, .. } | Deck::Plate { length, .. } => length,
        }
    }

    pub(super) fn shape(&self, mode: &Mode, x: f64, y: f64) -> f64 {
        let along = (mode.m as f64 * PI * x / self.length()).sin();
        match self.deck {
            Deck::Beam { .. } => along,
            Deck::Plate { width, .. } => along * (mode.n as f64 * PI * y / width).sin(),
        }
    }

    pub(super) fn law(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            0.0
        } else if self.contact_exponent == 1.0 {
            self.contact_coefficient * delta
        } else {
            self.contact_coefficient * delta.powf(self.contact_exponent)
        }
    }

    pub(super) fn layout(&self, modes: usize) -> Layout {
        let mut offsets = Vec::new();
        let mut at = 2 * modes;
        for v in &self.vehicles {
            offsets.push(at);
            at += 2 * v.dofs();
        }
        Layout { offsets, dim: at }
    }

    /// Every mode's value at (x, y) into `out` (0 off the deck), by the
    /// Chebyshev recurrence sin((k+1)a) = 2cos(a)·sin(ka) − sin((k−1)a)
    /// (checked against `sin` in the tests of this module).
    pub(super) fn shapes_at(&self, modes: &[Mode], x: f64, y: f64, work: &mut Work) {
        let out = &mut work.shape;
        if !(0.0..=self.length()).contains(&x) {
            out.fill(0.0);
            work.slope.fill(0.0);
            work.curvature.fill(0.0);
            return;
        }
        let l = self.length();
        sines(PI * x / l, &mut work.along);
        cosines(PI * x / l, &mut work.along_cos);
        match self.deck {
            Deck::Beam { .. } => {
                for (j, mode) in modes.iter().enumerate() {
                    let k = mode.m as f64 * PI / l;
                    out[j] = work.along[mode.m];
                    work.slope[j] = k * work.along_cos[mode.m];
                    work.curvature[j] = -k * k * out[j];
                }
            }
            Deck::Plate { width, .. } => {
                sines(PI * y / width, &mut work.across);
                for (j, mode) in modes.iter().enumerate() {
                    let k = mode.m as f64 * PI / l;
                    out[j] = work.along[mode.m] * work.across[mode.n];
                    work.slope[j] = k * work.along_cos[mode.m] * work.across[mode.n];
                    work.curvature[j] = -k * k * out[j];
                }
            }
        }
    }

    /// Compression and position of every wheel at (t, y), and the mode
    /// values under each wheel in `work.under`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn wheel_states(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        delta: &mut [f64],
        position: &mut [f64],
        work: &mut Work,
    ) {
        let nm = modes.len();
        let mut w = 0;
        for (v, vehicle) in self.vehicles.iter().enumerate() {
            for wheel in &vehicle.wheels {
                let x = vehicle.speed * (t - vehicle.entry_time) - wheel.behind;
                position[w] = x;
                self.shapes_at(modes, x, wheel.y, work);
                work.under[w * nm..(w + 1) * nm].copy_from_slice(&work.shape);
                let deck: f64 = work.shape.iter().zip(y).map(|(p, q)| p * q).sum();
                delta[w] = self.road.at(x) + deck - y[layout.offsets[v] + wheel.dof];
                let deck_rate: f64 = work.shape.iter().zip(&y[nm..]).map(|(p, q)| p * q).sum();
                let deck_slope: f64 = work.slope.iter().zip(y).map(|(p, q)| p * q).sum();
                work.surface_rate[w] =
                    deck_rate + vehicle.speed * (deck_slope + self.road.slope(x));
                let slope_rate: f64 = work.slope.iter().zip(&y[nm..]).map(|(p, q)| p * q).sum();
                let deck_curvature: f64 = work.curvature.iter().zip(y).map(|(p, q)| p * q).sum();
                let v = vehicle.speed;
                work.surface_transport[w] =
                    2.0 * v * slope_rate + v * v * (deck_curvature + self.road.curvature(x));
                w += 1;
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn rhs(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        delta: &mut [f64],
        position: &mut [f64],
        work: &mut Work,
    ) {
        let nm = modes.len();
        self.wheel_states(modes, layout, t, y, delta, position, work);
        for (j, mode) in modes.iter().enumerate() {
            dy[j] = y[nm + j];
            dy[nm + j] =
                -2.0 * self.damping_ratio * mode.omega * y[nm + j] - mode.omega * mode.omega * y[j];
        }
        let mut w = 0;
        for (v, vehicle) in self.vehicles.iter().enumerate() {
            let n = vehicle.dofs();
            let b = layout.offsets[v];
            let (du, contact, q) = (&mut work.du, &mut work.contact, &mut work.q);
            du.clear();
            du.extend_from_slice(&y[b + n..b + 2 * n]);
            contact.clear();
            contact.resize(n, 0.0);
            q.resize(n, 0.0);
            let u = &y[b..b + n];
            let first = w;
            for wheel in &vehicle.wheels {
                if !self.rigid {
                    contact[wheel.dof] += self.law(delta[w]);
                }
                w += 1;
            }
            // Massless coordinates first: Q_i(u̇_i) = 0 is linear in u̇_i;
            // a rigidly held one moves with the surface.
            for i in 0..n {
                if vehicle.masses[i] == 0.0 {
                    du[i] = 0.0;
                }
            }
            vehicle.forces(u, du, q);
            for i in 0..n {
                if vehicle.masses[i] == 0.0 {
                    du[i] = (q[i] + contact[i]) / work.own_damping[v][i];
                }
            }
            if self.rigid {
                for (k, wheel) in vehicle.wheels.iter().enumerate() {
                    if work.in_contact[first + k] {
                        du[wheel.dof] = work.surface_rate[first + k];
                    }
                }
            }
            vehicle.forces(u, du, q);
            for (k, wheel) in vehicle.wheels.iter().enumerate() {
                let c = first + k;
                if self.rigid && vehicle.masses[wheel.dof] == 0.0 {
                    // λ = −Q_c holds the point (0 when free: Q_c = 0 then).
                    let f = if work.in_contact[c] {
                        -q[wheel.dof]
                    } else {
                        0.0
                    };
                    contact[wheel.dof] += f;
                }
                let f = contact[wheel.dof];
                work.force[c] = f;
                if f != 0.0 {
                    let under = &work.under[c * nm..(c + 1) * nm];
                    for (j, mode) in modes.iter().enumerate() {
                        dy[nm + j] -= f * under[j] / mode.mass;
                    }
                }
            }
            for i in 0..n {
                dy[b + i] = du[i];
                dy[b + n + i] = if vehicle.masses[i] == 0.0 {
                    0.0
                } else {
                    (q[i] + contact[i]) / vehicle.masses[i]
                };
            }
        }
        if self.rigid {
            self.hold_wheels_with_mass(modes, layout, dy, work);
        }
    }

    /// Rigid contact of the wheels with mass that are in contact: their
    /// accelerations must equal the surface's, ü_c = s̈_c =
    /// Σφ_j(x_c) q̈_j + 2vΣφ′_j q̇_j + v²(Σφ″_j q_j + r″), with
    /// ü_c = ü⁰_c + λ_c/m_c and q̈_j = q̈⁰_j − Σ_d λ_d φ_j(x_d)/M_j (⁰: without
    /// these forces, as `dy` holds them): a linear system for the λ's of all
    /// such wheels at once (they couple through the deck),
    /// λ_c/m_c + Σ_d (Σ_j φ_j(x_c)φ_j(x_d)/M_j) λ_d = Σφ_j(x_c)q̈⁰_j + transport_c − ü⁰_c.
    pub(super) fn hold_wheels_with_mass(
        &self,
        modes: &[Mode],
        layout: &Layout,
        dy: &mut [f64],
        work: &mut Work,
    ) {
        let nm = modes.len();
        let mut held = Vec::new();
        let mut c = 0;
        for (v, vehicle) in self.vehicles.iter().enumerate() {
            for wheel in &vehicle.wheels {
                let m = vehicle.masses[wheel.dof];
                if m > 0.0 && work.in_contact[c] {
                    held.push((c, layout.offsets[v] + vehicle.dofs() + wheel.dof, m));
                }
                c += 1;
            }
        }
        if held.is_empty() {
            return;
        }
        let k = held.len();
        let mut a = vec![vec![0.0; k]; k];
        let mut b = vec![0.0; k];
        for (r, &(c, acc, m)) in held.iter().enumerate() {
            let uc = &work.under[c * nm..(c + 1) * nm];
            for (s, &(d, _, _)) in held.iter().enumerate() {
                let ud = &work.under[d * nm..(d + 1) * nm];
                a[r][s] = modes
                    .iter()
                    .enumerate()
                    .map(|(j, mode)| uc[j] * ud[j] / mode.mass)
                    .sum();
            }
            a[r][r] += 1.0 / m;
            let deck: f64 = (0..nm).map(|j| uc[j] * dy[nm + j]).sum();
            b[r] = deck + work.surface_transport[c] - dy[acc];
        }
        let lambda = solve(a, b);
        for (&(c, acc, m), &l) in held.iter().zip(&lambda) {
            dy[acc] += l / m;
            work.force[c] = l;
            let uc = &work.under[c * nm..(c + 1) * nm];
            for (j, mode) in modes.iter().enumerate() {
                dy[nm + j] -= l * uc[j] / mode.mass;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::sines;

    /// The recurrence against `sin` over the deck (40 terms: 1e-13).
    #[test]
    fn sine_recurrence_matches_sin() {
        let mut out = vec![0.0; 41];
        for i in 0..=200 {
            let a = std::f64::consts::PI * i as f64 / 200.0;
            sines(a, &mut out);
            for (k, s) in out.iter().enumerate() {
                assert!((s - (k as f64 * a).sin()).abs() < 1e-13, "k = {k}, a = {a}");
            }
        }
    }
}
