//! Independent brute-force reference for multi-wheel vehicles (multi-DOF
//! bodies on springs, dashpots and massless contact points) crossing a
//! simply supported beam or a plate simply supported on all four edges, each
//! wheel on its own tensionless contact `F = k_c·max(δ, 0)ⁿ` (n = 1: linear
//! spring, N/m; n = 1.5: Hertz, N/m^1.5). Std only; shares no code with vbi.
//!
//! Deck (vertical w positive upward, m): closed-form modes, no finite
//! elements and no Ritz basis:
//! - beam: `φ_j = sin(jπx/L)`, `ω_j = (jπ/L)²√(EI/m)`, modal mass mL/2;
//! - plate (Kirchhoff, isotropic, all four edges simply supported):
//!   `φ_mn = sin(mπx/L)·sin(nπy/B)`, `ω_mn = π²((m/L)² + (n/B)²)√(D/ρh)`
//!   (Leissa, Vibration of Plates, NASA SP-160, eq. 4.26), modal mass ρhLB/4;
//!   the lowest `modes` of them by frequency.
//!
//! Every mode obeys `M_j(q̈_j + 2ζω_j q̇_j + ω_j² q_j) = −Σ_w F_w φ_j(x_w, y_w)`
//! over the wheels on the deck (F compression positive).
//!
//! Vehicle: generalised coordinates u (m or rad), some with a mass or inertia
//! (kg, kg·m²), some massless (the truck's contact points). Its springs and
//! dashpots are force elements between two points, each point a linear
//! combination of coordinates (e.g. body bounce + d·pitch + e·roll); an
//! element of rate k, c whose ends move by a and b pushes them apart with
//! −k(a − b) − c(ȧ − ḃ) on `top` and the opposite on `bottom`, and generalised
//! forces follow by virtual work. A massless coordinate obeys Q = 0, which is
//! linear in its own velocity through its dashpots (each massless coordinate
//! must have one, and none may be joined to another massless one by a
//! dashpot): it is a first-order state. Wheel w acts on coordinate
//! `wheels[w].dof` with the compression `δ = w(x, y) + r(x) − u_dof` (w only on
//! the deck, 0 ≤ x ≤ L).
//!
//! Integration: classical RK4 at a fixed small step with the contact law
//! evaluated pointwise (no event location): the law is C⁰ (linear) or C¹
//! (Hertz) at δ = 0, so a switch costs O(h²) locally. Losses are sign changes
//! of δ between steps, located by linear interpolation.
//!
//! Rigid contact (`rigid: true`) for wheels on massless contact points (the
//! truck's): in contact the point moves with the surface, u = s = w + r and
//! u̇ = ṡ = Σφ_j q̇_j + v(Σφ′_j q_j + r′), and the contact force is what holds
//! it there, λ = −Q_c at u̇_c = ṡ (its tyre spring and dashpot); free, λ = 0
//! and Q_c = 0 gives u̇_c. The point has no mass, so a landing needs no
//! impact rule: u̇_c jumps to ṡ, λ jumps to c_t·(ṡ − u̇_free) > 0, nothing is
//! lost or restituted. Events are located exactly: a step in which some
//! wheel's λ turns negative (lift-off) or some free point falls below the
//! surface (landing) is redone up to the earliest event, found by bisection
//! on a single RK4 step of variable length (to 1e-15 s), the wheel switches
//! and the step is finished from there.
#![allow(dead_code)]
#![allow(clippy::needless_range_loop)]

use std::f64::consts::PI;

mod dynamics;
mod stepping;

/// Gravitational acceleration, m/s².
pub const GRAVITY: f64 = 9.81;

/// The deck.
#[derive(Clone, Debug)]
pub enum Deck {
    /// Simply supported Euler–Bernoulli beam.
    Beam {
        /// L, m.
        length: f64,
        /// EI, N·m².
        bending_stiffness: f64,
        /// m, kg/m.
        mass_per_length: f64,
        /// Number of sine modes.
        modes: usize,
    },
    /// Isotropic Kirchhoff plate simply supported on all four edges.
    Plate {
        /// L, m.
        length: f64,
        /// B, m.
        width: f64,
        /// D = Eh³/(12(1 − ν²)), N·m.
        rigidity: f64,
        /// ρh, kg/m².
        mass_per_area: f64,
        /// Number of modes kept (the lowest by frequency).
        modes: usize,
    },
}

/// The road or track surface r(x), m (0 before the entrance for harmonic).
#[derive(Clone, Copy, Debug)]
pub enum Road {
    /// a·sin(2πx/λ + φ) for x ≥ 0: amplitude a (m), wavelength λ (m), phase φ.
    Harmonic(f64, f64, f64),
    /// (h/2)(1 − cos(2π(x − s)/ℓ)) on [s, s + ℓ]: start s (m), length ℓ (m),
    /// height h (m, negative for a dip).
    Bump(f64, f64, f64),
}

impl Road {
    /// d²r/dx², 1/m.
    fn curvature(&self, x: f64) -> f64 {
        match *self {
            Road::Harmonic(a, lambda, phase) => {
                if x < 0.0 {
                    0.0
                } else {
                    let k = 2.0 * PI / lambda;
                    -a * k * k * (k * x + phase).sin()
                }
            }
            Road::Bump(start, length, height) => {
                if x < start || x > start + length {
                    0.0
                } else {
                    let k = 2.0 * PI / length;
                    0.5 * height * k * k * (k * (x - start)).cos()
                }
            }
        }
    }

    /// dr/dx, 1.
    fn slope(&self, x: f64) -> f64 {
        match *self {
            Road::Harmonic(a, lambda, phase) => {
                if x < 0.0 {
                    0.0
                } else {
                    a * 2.0 * PI / lambda * (2.0 * PI * x / lambda + phase).cos()
                }
            }
            Road::Bump(start, length, height) => {
                if x < start || x > start + length {
                    0.0
                } else {
                    0.5 * height * 2.0 * PI / length * (2.0 * PI * (x - start) / length).sin()
                }
            }
        }
    }

    fn at(&self, x: f64) -> f64 {
        match *self {
            Road::Harmonic(a, lambda, phase) => {
                if x < 0.0 {
                    0.0
                } else {
                    a * (2.0 * PI * x / lambda + phase).sin()
                }
            }
            Road::Bump(start, length, height) => {
                if x < start || x > start + length {
                    0.0
                } else {
                    0.5 * height * (1.0 - (2.0 * PI * (x - start) / length).cos())
                }
            }
        }
    }
}

/// A point of a vehicle: Σ coefficient·u[index].
pub type Point = Vec<(usize, f64)>;

/// A spring–dashpot pair between two points.
#[derive(Clone, Debug)]
pub struct Element {
    /// N/m.
    pub stiffness: f64,
    /// N·s/m.
    pub damping: f64,
    pub top: Point,
    pub bottom: Point,
}

/// One wheel.
#[derive(Clone, Copy, Debug)]
pub struct WheelAt {
    /// The coordinate the contact force acts on.
    pub dof: usize,
    /// Distance behind the vehicle's first wheel, m.
    pub behind: f64,
    /// Transverse position on the deck, m (ignored on a beam).
    pub y: f64,
    /// Static load on level rigid ground, N (the test's own statics); the
    /// starting state is solved with these and checked against them.
    pub static_load: f64,
}

/// A vehicle.
#[derive(Clone, Debug)]
pub struct Vehicle {
    /// Mass or inertia of each coordinate (0 = massless), kg or kg·m².
    pub masses: Vec<f64>,
    /// Weight on each coordinate (downward positive), N.
    pub weights: Vec<f64>,
    pub elements: Vec<Element>,
    pub wheels: Vec<WheelAt>,
    /// m/s.
    pub speed: f64,
    /// Time the first wheel reaches x = 0, s (≥ 0; every wheel starts off
    /// the deck and on level ground).
    pub entry_time: f64,
}

/// Deck, road, contact and vehicles.
#[derive(Clone, Debug)]
pub struct Case {
    pub deck: Deck,
    /// ζ of every mode.
    pub damping_ratio: f64,
    pub road: Road,
    /// k_c.
    pub contact_coefficient: f64,
    /// n.
    pub contact_exponent: f64,
    /// Rigid contact instead (coefficient and exponent unused).
    pub rigid: bool,
    pub vehicles: Vec<Vehicle>,
    /// Where the deck deflection is sampled, (x, y) m.
    pub probe: (f64, f64),
}

/// Per-wheel statistics over the run.
#[derive(Clone, Debug, Default)]
pub struct WheelStatistics {
    /// Contact losses (δ from > 0 to ≤ 0).
    pub losses: usize,
    /// Time and position of the first loss, s and m.
    pub first_loss: Option<(f64, f64)>,
    /// First time on the grid of h at which the gap exceeds 1 nm (vbi's
    /// definition of a wheel apart), s.
    pub first_nanometre: Option<f64>,
    /// Largest gap −δ, m.
    pub max_gap: f64,
    /// Largest contact force, N.
    pub max_force: f64,
}

/// Samples at the requested times and the statistics of every wheel
/// (vehicles in order, wheels in order).
#[derive(Clone, Debug, Default)]
pub struct History {
    /// Deck deflection at the probe, m.
    pub deflection: Vec<f64>,
    /// Per wheel, per sample, N.
    pub contact_force: Vec<Vec<f64>>,
    pub wheels: Vec<WheelStatistics>,
    /// Rigid contact: the first landing of any wheel, s.
    pub first_landing: Option<f64>,
}

/// One deck mode: ω (rad/s), modal mass (kg), half-waves (m, n).
#[derive(Clone, Copy, Debug)]
struct Mode {
    omega: f64,
    mass: f64,
    m: usize,
    n: usize,
}

/// Solves A x = b (dense, partial pivoting).
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for k in 0..n {
        let p = (k..n)
            .max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))
            .unwrap();
        a.swap(k, p);
        b.swap(k, p);
        assert!(a[k][k].abs() > 1e-300, "singular static system");
        for i in k + 1..n {
            let f = a[i][k] / a[k][k];
            for j in k..n {
                a[i][j] -= f * a[k][j];
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        let s: f64 = (k + 1..n).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    x
}

fn point_value(p: &Point, u: &[f64]) -> f64 {
    p.iter().map(|&(i, c)| c * u[i]).sum()
}

impl Vehicle {
    fn dofs(&self) -> usize {
        self.masses.len()
    }

    /// Generalised forces of the springs, dashpots and weights at (u, u̇).
    fn forces(&self, u: &[f64], du: &[f64], q: &mut [f64]) {
        for (qi, w) in q.iter_mut().zip(&self.weights) {
            *qi = -w;
        }
        for e in &self.elements {
            let f = -e.stiffness * (point_value(&e.top, u) - point_value(&e.bottom, u))
                - e.damping * (point_value(&e.top, du) - point_value(&e.bottom, du));
            for &(i, c) in &e.top {
                q[i] += c * f;
            }
            for &(i, c) in &e.bottom {
                q[i] -= c * f;
            }
        }
    }

    /// Σ c·(coefficient of `i`)² over the dashpots: how Q_i depends on u̇_i.
    fn own_damping(&self, i: usize) -> f64 {
        self.elements
            .iter()
            .map(|e| {
                let d = e.top.iter().filter(|p| p.0 == i).map(|p| p.1).sum::<f64>()
                    - e.bottom
                        .iter()
                        .filter(|p| p.0 == i)
                        .map(|p| p.1)
                        .sum::<f64>();
                e.damping * d * d
            })
            .sum()
    }

    /// Static state on level rigid-surface ground with each wheel at the
    /// compression of its static load, (P/k_c)^(1/n) below 0: the coordinates
    /// other than the wheels' from K u = −weights − K_w u_w, then the wheels'
    /// equilibrium checked against the static loads (1e-9 relative).
    fn static_state(&self, compression: impl Fn(f64) -> f64) -> Vec<f64> {
        let n = self.dofs();
        let mut u = vec![0.0; n];
        let fixed: Vec<usize> = self.wheels.iter().map(|w| w.dof).collect();
        for w in &self.wheels {
            u[w.dof] = -compression(w.static_load);
        }
        let free: Vec<usize> = (0..n).filter(|i| !fixed.contains(i)).collect();
        // Columns of K by unit displacements (the forces are linear in u).
        let zero = vec![0.0; n];
        let mut base = vec![0.0; n];
        self.forces(&u, &zero, &mut base);
        let mut a = vec![vec![0.0; free.len()]; free.len()];
        for (c, &j) in free.iter().enumerate() {
            let mut unit = u.clone();
            unit[j] += 1.0;
            let mut q = vec![0.0; n];
            self.forces(&unit, &zero, &mut q);
            for (r, &i) in free.iter().enumerate() {
                a[r][c] = base[i] - q[i];
            }
        }
        let rhs: Vec<f64> = free.iter().map(|&i| base[i]).collect();
        let x = solve(a, rhs);
        for (c, &j) in free.iter().enumerate() {
            u[j] += x[c];
        }
        let mut q = vec![0.0; n];
        self.forces(&u, &zero, &mut q);
        for w in &self.wheels {
            // The wheel's coordinate needs +P from the ground.
            let reaction = -q[w.dof];
            assert!(
                (reaction - w.static_load).abs() < 1e-9 * w.static_load,
                "static load {} N, statics give {reaction} N",
                w.static_load
            );
        }
        u
    }
}
