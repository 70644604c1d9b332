//! Independent event-driven reference for **rigid** unilateral contact with
//! Newton's impact law (issue 29): a two-mass oscillator (sprung mass on a
//! spring–dashpot over a wheel with mass) crossing a simply supported
//! Euler–Bernoulli beam with a harmonic surface, the wheel held to the
//! surface while the contact pushes, flying while it would pull, and
//! landing with Newton's law. Self-contained (std only); shares no code
//! with vbi.
//!
//! # Model (SI; vertical coordinates positive upward; g downward)
//! Beam: modes φ_j = sin(jπx/L), modal mass mL/2, ω_j = (jπ/L)²√(EI/m),
//! damping ratio ζ: q̈_j + 2ζω_j q̇_j + ω_j²q_j = −(2/(mL)) F φ_j(x_c).
//! Vehicle: m_s ÿ_s = −k(y_s − y_w) − c(ẏ_s − ẏ_w) − m_s g,
//! m_u ÿ_w = k(y_s − y_w) + c(ẏ_s − ẏ_w) − m_u g + F. The wheel at
//! x_c = v t (on the beam from t = 0 to L/v), the surface
//! s = Σφ_j q_j + r(x_c) with r = a sin(2πx/λ) (x ≥ 0), gap g = y_w − s,
//! relative velocity U = ẏ_w − Σφ_j q̇_j − v(Σφ′_j q_j + r′).
//!
//! # Phases and events
//! * Contact: y_w follows s (ÿ_w = s̈), the multiplier
//!   F = (m_u B − A)/(1 + m_u S) with A = k(y_s−y_w) + c(ẏ_s−ẏ_w) − m_u g,
//!   S = Σ 2φ_j²/(mL), B = s̈ without F. Lift-off where F crosses 0.
//! * Flight: F = 0. Landing where g crosses 0 downward: the impulse
//!   P = −(1+e)U⁻/(1/m_u + S) makes U⁺ = −e U⁻ (Newton's law); then flight
//!   again (e > 0) or contact (e = 0, or an approach slower than
//!   [`ZENO_VELOCITY`]: the accumulation of a chattering sequence, ended as
//!   the sum of its geometric series of bounces would end it), unless the
//!   contact would pull at once (then flight with U = 0).
//! * t = 0: the wheel stands at the entrance on flat ground, so the surface
//!   slope r′(0⁺) = 2πa/λ makes an impact at once.
//!
//! Classical RK4 with a fixed step that divides the output interval; events
//! located by bisection on re-integrated sub-steps to 1e-13 s (so the
//! reference's error is O(h⁴) between events and ~1e-13 s in event times).
#![allow(dead_code)]
#![allow(clippy::needless_range_loop)]

use std::f64::consts::PI;

/// m/s².
pub const GRAVITY: f64 = 9.81;
/// Approach velocity below which a landing is plastic whatever e (m/s):
/// the end of an accumulation of impacts.
pub const ZENO_VELOCITY: f64 = 1e-6;
/// Gap below which a flight that begins at a landing counts as touching, m.
const GAP_TOLERANCE: f64 = 1e-10;

/// One case, SI units.
#[derive(Clone, Copy, Debug)]
pub struct RigidCase {
    pub length: f64,
    pub bending_stiffness: f64,
    pub mass_per_length: f64,
    pub damping_ratio: f64,
    pub sprung_mass: f64,
    pub unsprung_mass: f64,
    pub stiffness: f64,
    pub damping: f64,
    pub speed: f64,
    pub amplitude: f64,
    pub wavelength: f64,
    pub modes: usize,
    pub restitution: f64,
}

/// Sampled history at multiples of the output interval.
#[derive(Clone, Debug, Default)]
pub struct RigidHistory {
    pub time: Vec<f64>,
    /// Gap g, m (0 in contact).
    pub gap: Vec<f64>,
    pub wheel: Vec<f64>,
    pub sprung: Vec<f64>,
    /// w(L/2), m.
    pub midspan: Vec<f64>,
    /// Landings: (time s, impulse N·s).
    pub landings: Vec<(f64, f64)>,
    /// Lift-off times, s.
    pub losses: Vec<f64>,
}

struct Model {
    c: RigidCase,
    omega: Vec<f64>,
    kappa: f64,
    modal_factor: f64,
}

impl Model {
    fn n(&self) -> usize {
        self.c.modes
    }
    /// φ, φ′, φ″ at x (0 off the beam).
    fn shapes(&self, x: f64, phi: &mut [f64], dphi: &mut [f64], ddphi: &mut [f64]) {
        for j in 0..self.n() {
            if (0.0..=self.c.length).contains(&x) {
                let k = (j + 1) as f64 * self.kappa;
                let (s, co) = (k * x).sin_cos();
                phi[j] = s;
                dphi[j] = k * co;
                ddphi[j] = -k * k * s;
            } else {
                phi[j] = 0.0;
                dphi[j] = 0.0;
                ddphi[j] = 0.0;
            }
        }
    }
    fn roughness(&self, x: f64) -> (f64, f64, f64) {
        if x < 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let b = 2.0 * PI / self.c.wavelength;
        let (s, co) = (b * x).sin_cos();
        let a = self.c.amplitude;
        (a * s, a * b * co, -a * b * b * s)
    }
    /// (gap, relative velocity, S, B, A) at (t, y).
    fn kinematics(&self, t: f64, y: &[f64]) -> (f64, f64, f64, f64, f64) {
        let n = self.n();
        let (v, x) = (self.c.speed, self.c.speed * t);
        let mut phi = [0.0; 32];
        let mut dphi = [0.0; 32];
        let mut ddphi = [0.0; 32];
        self.shapes(x, &mut phi[..n], &mut dphi[..n], &mut ddphi[..n]);
        let (r, dr, ddr) = self.roughness(x);
        let (mut s, mut sd, mut big_s, mut b) = (r, v * dr, 0.0, v * v * ddr);
        for j in 0..n {
            let (q, qd) = (y[j], y[n + j]);
            let w = self.omega[j];
            s += phi[j] * q;
            sd += phi[j] * qd + v * dphi[j] * q;
            big_s += self.modal_factor * phi[j] * phi[j];
            b += phi[j] * (-2.0 * self.c.damping_ratio * w * qd - w * w * q)
                + 2.0 * v * dphi[j] * qd
                + v * v * ddphi[j] * q;
        }
        let (ys, yd_s, yw, yd_w) = (y[2 * n], y[2 * n + 1], y[2 * n + 2], y[2 * n + 3]);
        let a = self.c.stiffness * (ys - yw) + self.c.damping * (yd_s - yd_w)
            - self.c.unsprung_mass * GRAVITY;
        (yw - s, yd_w - sd, big_s, b, a)
    }
    /// Contact force the constraint needs, N.
    fn constraint_force(&self, t: f64, y: &[f64]) -> f64 {
        let (_, _, s, b, a) = self.kinematics(t, y);
        let mu = self.c.unsprung_mass;
        (mu * b - a) / (1.0 + mu * s)
    }
    fn rhs(&self, t: f64, y: &[f64], contact: bool, dy: &mut [f64]) {
        let n = self.n();
        let x = self.c.speed * t;
        let force = if contact {
            self.constraint_force(t, y)
        } else {
            0.0
        };
        let mut phi = [0.0; 32];
        let mut dphi = [0.0; 32];
        let mut ddphi = [0.0; 32];
        self.shapes(x, &mut phi[..n], &mut dphi[..n], &mut ddphi[..n]);
        for j in 0..n {
            let w = self.omega[j];
            dy[j] = y[n + j];
            dy[n + j] = -2.0 * self.c.damping_ratio * w * y[n + j]
                - w * w * y[j]
                - self.modal_factor * force * phi[j];
        }
        let (ys, yd_s, yw, yd_w) = (y[2 * n], y[2 * n + 1], y[2 * n + 2], y[2 * n + 3]);
        let spring = self.c.stiffness * (ys - yw) + self.c.damping * (yd_s - yd_w);
        dy[2 * n] = yd_s;
        dy[2 * n + 1] = (-spring - self.c.sprung_mass * GRAVITY) / self.c.sprung_mass;
        dy[2 * n + 2] = yd_w;
        dy[2 * n + 3] = (spring - self.c.unsprung_mass * GRAVITY + force) / self.c.unsprung_mass;
    }
    fn rk4(&self, t: f64, y: &[f64], h: f64, contact: bool, out: &mut [f64]) {
        let d = y.len();
        let (mut k1, mut k2, mut k3, mut k4, mut tmp) = (
            vec![0.0; d],
            vec![0.0; d],
            vec![0.0; d],
            vec![0.0; d],
            vec![0.0; d],
        );
        self.rhs(t, y, contact, &mut k1);
        for i in 0..d {
            tmp[i] = y[i] + 0.5 * h * k1[i];
        }
        self.rhs(t + 0.5 * h, &tmp, contact, &mut k2);
        for i in 0..d {
            tmp[i] = y[i] + 0.5 * h * k2[i];
        }
        self.rhs(t + 0.5 * h, &tmp, contact, &mut k3);
        for i in 0..d {
            tmp[i] = y[i] + h * k3[i];
        }
        self.rhs(t + h, &tmp, contact, &mut k4);
        for i in 0..d {
            out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    /// Switching function: the gap in flight, the force in contact.
    fn switching(&self, t: f64, y: &[f64], contact: bool) -> f64 {
        if contact {
            self.constraint_force(t, y)
        } else {
            self.kinematics(t, y).0
        }
    }
    /// Newton's law at a landing; returns the impulse and whether the wheel
    /// stays in contact.
    fn impact(&self, t: f64, y: &mut [f64]) -> (f64, bool) {
        let n = self.n();
        let (_, u, s, _, _) = self.kinematics(t, y);
        if u >= 0.0 {
            return (0.0, self.constraint_force(t, y) > 0.0);
        }
        let e = if -u < ZENO_VELOCITY {
            0.0
        } else {
            self.c.restitution
        };
        let impulse = -(1.0 + e) * u / (1.0 / self.c.unsprung_mass + s);
        let mut phi = [0.0; 32];
        let mut dphi = [0.0; 32];
        let mut ddphi = [0.0; 32];
        self.shapes(
            self.c.speed * t,
            &mut phi[..n],
            &mut dphi[..n],
            &mut ddphi[..n],
        );
        y[2 * n + 3] += impulse / self.c.unsprung_mass;
        for j in 0..n {
            y[n + j] -= self.modal_factor * impulse * phi[j];
        }
        let stays = e == 0.0 && self.constraint_force(t, y) > 0.0;
        (impulse, stays)
    }
}

/// Integrates `case` to `t_end`, sampling every `output` seconds with
/// `substeps` RK4 steps per sample.
pub fn rigid_reference(case: &RigidCase, t_end: f64, output: f64, substeps: usize) -> RigidHistory {
    assert!(case.modes <= 32 && case.unsprung_mass > 0.0);
    let model = Model {
        c: *case,
        omega: (1..=case.modes)
            .map(|j| {
                let k = j as f64 * PI / case.length;
                k * k * (case.bending_stiffness / case.mass_per_length).sqrt()
            })
            .collect(),
        kappa: PI / case.length,
        modal_factor: 2.0 / (case.mass_per_length * case.length),
    };
    let n = case.modes;
    let mut y = vec![0.0; 2 * n + 4];
    // Static equilibrium on flat ground.
    y[2 * n] = -case.sprung_mass * GRAVITY / case.stiffness;
    let mut history = RigidHistory::default();
    let (impulse, mut contact) = model.impact(0.0, &mut y);
    if impulse > 0.0 {
        history.landings.push((0.0, impulse));
    }
    let record = |h: &mut RigidHistory, t: f64, y: &[f64], contact: bool| {
        let (gap, ..) = model.kinematics(t, y);
        h.time.push(t);
        h.gap.push(if contact { 0.0 } else { gap });
        h.wheel.push(y[2 * n + 2]);
        h.sprung.push(y[2 * n]);
        let mid: f64 = (0..n)
            .map(|j| y[j] * ((j + 1) as f64 * PI / 2.0).sin())
            .sum();
        h.midspan.push(mid);
    };
    record(&mut history, 0.0, &y, contact);
    let samples = (t_end / output).round() as usize;
    let h = output / substeps as f64;
    let mut next = y.clone();
    let mut trial = y.clone();
    for sample in 1..=samples {
        for sub in 0..substeps {
            let mut t = (sample - 1) as f64 * output + sub as f64 * h;
            let t_step_end = t + h;
            // Up to a few events inside one step (a chattering wheel).
            for _ in 0..64 {
                let remaining = t_step_end - t;
                if remaining <= 1e-15 {
                    break;
                }
                model.rk4(t, &y, remaining, contact, &mut next);
                let g0 = model.switching(t, &y, contact);
                let g1 = model.switching(t_step_end, &next, contact);
                // An event: the switching function goes from ≥ 0 to < 0. A
                // flight that starts at a landing starts at g = 0 up to
                // round-off (GAP_TOLERANCE).
                let start = if contact { 0.0 } else { -GAP_TOLERANCE };
                let crossed = g1 < 0.0 && g0 >= start;
                if !crossed {
                    y.copy_from_slice(&next);
                    break;
                }
                let (mut lo, mut hi) = (0.0, remaining);
                while hi - lo > 1e-13 {
                    let mid = 0.5 * (lo + hi);
                    model.rk4(t, &y, mid, contact, &mut trial);
                    if model.switching(t + mid, &trial, contact) < 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                model.rk4(t, &y, hi, contact, &mut trial);
                y.copy_from_slice(&trial);
                t += hi;
                if contact {
                    history.losses.push(t);
                    contact = false;
                } else {
                    let (impulse, stays) = model.impact(t, &mut y);
                    history.landings.push((t, impulse));
                    contact = stays;
                }
            }
        }
        record(&mut history, sample as f64 * output, &y, contact);
    }
    history
}
