//! Independent brute-force reference for several two-mass oscillators crossing a
//! simply supported beam, each on its own tensionless contact `F = k_c·max(δ, 0)ⁿ`
//! (n = 1: linear spring, N/m; n = 1.5: Hertz, N/m^1.5). Std only; shares no code
//! with vbi.
//!
//! Model (SI, vertical positive upward, g = 9.81 m/s²): analytic sine modes
//! `φ_j = sin(jπx/L)`, `q̈_j + 2ζω_j q̇_j + ω_j² q_j = −(2/(mL)) Σ_v F_v φ_j(x_v)` over the
//! wheels on the deck; vehicle v: `m_s ÿ_s = −k(y_s−y_w) − c(ẏ_s−ẏ_w) − m_s g`,
//! `m_u ÿ_w = k(y_s−y_w) + c(ẏ_s−ẏ_w) − m_u g + F_v`, with the compression
//! `δ_v = w(x_v) + r(x_v) − y_w` (w only while 0 ≤ x_v ≤ L; r = a·sin(2πx/λ + φ) for
//! x ≥ 0, 0 before). Vehicle v is at `x_v = v_v (t − t_v)` (t_v its entry time) and
//! starts at rest in static equilibrium on the flat approach.
//!
//! Integration: classical fourth-order Runge–Kutta at a fixed, small step with the
//! contact law evaluated pointwise (no event location at all): the law is C⁰ (linear)
//! or C¹ (Hertz) at δ = 0, so the error near a switch is O(h²) locally, and with
//! h = 1 µs it is far below the errors of the code under test (checked against the
//! event-driven reference in `tests/it/multi_wheel.rs`). Contact losses and landings are
//! found as sign changes of δ between steps, located by linear interpolation.
#![allow(dead_code)]
#![allow(clippy::needless_range_loop)]

use std::f64::consts::PI;

/// Gravitational acceleration, m/s².
pub const GRAVITY: f64 = 9.81;

/// One oscillator.
#[derive(Clone, Copy, Debug)]
pub struct Oscillator {
    /// m_s, kg.
    pub sprung_mass: f64,
    /// m_u, kg (> 0).
    pub unsprung_mass: f64,
    /// k, N/m.
    pub stiffness: f64,
    /// c, N·s/m.
    pub damping: f64,
    /// Speed, m/s (> 0).
    pub speed: f64,
    /// Time at which the wheel reaches x = 0, s (≥ 0).
    pub entry_time: f64,
}

/// Beam, surface, contact and vehicles.
#[derive(Clone, Debug)]
pub struct MultiCase {
    /// L, m.
    pub length: f64,
    /// EI, N·m².
    pub bending_stiffness: f64,
    /// m, kg/m.
    pub mass_per_length: f64,
    /// ζ of every mode.
    pub damping_ratio: f64,
    /// Number of sine modes.
    pub modes: usize,
    /// Roughness a (m), λ (m), φ (rad).
    pub roughness: (f64, f64, f64),
    /// k_c (N/m for n = 1, N/m^1.5 for n = 1.5).
    pub contact_coefficient: f64,
    /// n.
    pub contact_exponent: f64,
    pub vehicles: Vec<Oscillator>,
}

/// Per-wheel statistics over the whole run.
#[derive(Clone, Debug, Default)]
pub struct WheelStatistics {
    /// Number of contact losses (δ going from > 0 to ≤ 0).
    pub losses: usize,
    /// Position of the first loss, m (None if the wheel never separates).
    pub first_loss_position: Option<f64>,
    /// Largest gap −δ while separated, m.
    pub max_gap: f64,
    /// Largest contact force, N.
    pub max_force: f64,
}

/// Samples at the requested times and the per-wheel statistics.
#[derive(Clone, Debug, Default)]
pub struct MultiHistory {
    pub time: Vec<f64>,
    /// w(L/2), m.
    pub midspan_deflection: Vec<f64>,
    /// Per wheel, per sample: contact force, N.
    pub contact_force: Vec<Vec<f64>>,
    pub wheels: Vec<WheelStatistics>,
}

impl MultiCase {
    fn omega(&self, j: usize) -> f64 {
        let k = j as f64 * PI / self.length;
        k * k * (self.bending_stiffness / self.mass_per_length).sqrt()
    }

    fn law(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            0.0
        } else if self.contact_exponent == 1.0 {
            self.contact_coefficient * delta
        } else {
            self.contact_coefficient * delta.powf(self.contact_exponent)
        }
    }

    fn roughness_at(&self, x: f64) -> f64 {
        let (a, lambda, phase) = self.roughness;
        if x < 0.0 || a == 0.0 {
            0.0
        } else {
            a * (2.0 * PI * x / lambda + phase).sin()
        }
    }

    /// Compression of every wheel, and its position, at time t for state y.
    fn compressions(&self, t: f64, y: &[f64], delta: &mut [f64], position: &mut [f64]) {
        let n = self.modes;
        for (v, veh) in self.vehicles.iter().enumerate() {
            let x = veh.speed * (t - veh.entry_time);
            position[v] = x;
            let mut s = self.roughness_at(x);
            if (0.0..=self.length).contains(&x) {
                for j in 0..n {
                    s += y[j] * ((j + 1) as f64 * PI * x / self.length).sin();
                }
            }
            delta[v] = s - y[2 * n + 4 * v + 2];
        }
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64], delta: &mut [f64], pos: &mut [f64]) {
        let n = self.modes;
        self.compressions(t, y, delta, pos);
        let modal = 2.0 / (self.mass_per_length * self.length);
        for j in 0..n {
            let w = self.omega(j + 1);
            dy[j] = y[n + j];
            dy[n + j] = -2.0 * self.damping_ratio * w * y[n + j] - w * w * y[j];
        }
        for (v, veh) in self.vehicles.iter().enumerate() {
            let f = self.law(delta[v]);
            let x = pos[v];
            if f != 0.0 && (0.0..=self.length).contains(&x) {
                for j in 0..n {
                    dy[n + j] -= modal * f * ((j + 1) as f64 * PI * x / self.length).sin();
                }
            }
            let b = 2 * n + 4 * v;
            let (ys, vs, yw, vw) = (y[b], y[b + 1], y[b + 2], y[b + 3]);
            let fs = veh.stiffness * (ys - yw) + veh.damping * (vs - vw);
            dy[b] = vs;
            dy[b + 1] = -fs / veh.sprung_mass - GRAVITY;
            dy[b + 2] = vw;
            dy[b + 3] = (fs + f) / veh.unsprung_mass - GRAVITY;
        }
    }

    /// Integrates [0, t_end] with RK4 at step `h` (which must divide the spacing of
    /// `times`, themselves multiples of h) and samples at `times`.
    pub fn run(&self, times: &[f64], t_end: f64, h: f64) -> MultiHistory {
        let n = self.modes;
        let nv = self.vehicles.len();
        let dim = 2 * n + 4 * nv;
        let mut y = vec![0.0; dim];
        for (v, veh) in self.vehicles.iter().enumerate() {
            assert!(veh.entry_time >= 0.0 && veh.speed > 0.0 && veh.unsprung_mass > 0.0);
            let p = (veh.sprung_mass + veh.unsprung_mass) * GRAVITY;
            let static_compression =
                (p / self.contact_coefficient).powf(1.0 / self.contact_exponent);
            let b = 2 * n + 4 * v;
            y[b + 2] = -static_compression;
            y[b] = y[b + 2] - veh.sprung_mass * GRAVITY / veh.stiffness;
        }
        let steps = (t_end / h).round() as usize;
        let (mut k1, mut k2, mut k3, mut k4, mut yt) = (
            vec![0.0; dim],
            vec![0.0; dim],
            vec![0.0; dim],
            vec![0.0; dim],
            vec![0.0; dim],
        );
        let (mut delta, mut pos) = (vec![0.0; nv], vec![0.0; nv]);
        let mut out = MultiHistory {
            contact_force: vec![Vec::new(); nv],
            wheels: vec![WheelStatistics::default(); nv],
            ..Default::default()
        };
        let sample =
            |t: f64, y: &[f64], out: &mut MultiHistory, delta: &mut [f64], pos: &mut [f64]| {
                self.compressions(t, y, delta, pos);
                let mut mid = 0.0;
                for j in 0..n {
                    mid += y[j] * ((j + 1) as f64 * PI / 2.0).sin();
                }
                out.time.push(t);
                out.midspan_deflection.push(mid);
                for v in 0..nv {
                    out.contact_force[v].push(self.law(delta[v]));
                }
            };
        let mut next = 0usize;
        while next < times.len() && times[next] <= 0.5 * h {
            sample(0.0, &y, &mut out, &mut delta, &mut pos);
            next += 1;
        }
        self.compressions(0.0, &y, &mut delta, &mut pos);
        let mut previous = delta.clone();
        let mut previous_position = pos.clone();
        for i in 0..steps {
            let t = i as f64 * h;
            self.rhs(t, &y, &mut k1, &mut delta, &mut pos);
            for m in 0..dim {
                yt[m] = y[m] + 0.5 * h * k1[m];
            }
            self.rhs(t + 0.5 * h, &yt, &mut k2, &mut delta, &mut pos);
            for m in 0..dim {
                yt[m] = y[m] + 0.5 * h * k2[m];
            }
            self.rhs(t + 0.5 * h, &yt, &mut k3, &mut delta, &mut pos);
            for m in 0..dim {
                yt[m] = y[m] + h * k3[m];
            }
            self.rhs(t + h, &yt, &mut k4, &mut delta, &mut pos);
            for m in 0..dim {
                y[m] += h / 6.0 * (k1[m] + 2.0 * k2[m] + 2.0 * k3[m] + k4[m]);
            }
            let t1 = (i + 1) as f64 * h;
            self.compressions(t1, &y, &mut delta, &mut pos);
            for v in 0..nv {
                let w = &mut out.wheels[v];
                let d = delta[v];
                w.max_force = w.max_force.max(self.law(d));
                if d <= 0.0 {
                    w.max_gap = w.max_gap.max(-d);
                }
                if previous[v] > 0.0 && d <= 0.0 {
                    w.losses += 1;
                    if w.first_loss_position.is_none() {
                        let s = previous[v] / (previous[v] - d);
                        w.first_loss_position =
                            Some(previous_position[v] + s * (pos[v] - previous_position[v]));
                    }
                }
            }
            previous.copy_from_slice(&delta);
            previous_position.copy_from_slice(&pos);
            while next < times.len() && (times[next] - t1).abs() <= 0.5 * h {
                sample(t1, &y, &mut out, &mut delta, &mut pos);
                next += 1;
            }
        }
        assert_eq!(
            next,
            times.len(),
            "output times must be multiples of h in [0, t_end]"
        );
        out
    }
}
