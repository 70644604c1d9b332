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

/// Scratch space of the right-hand side.
struct Work {
    /// Mode values at one point, and under every wheel (wheel-major).
    shape: Vec<f64>,
    under: Vec<f64>,
    /// sin(kπx/L), sin(kπy/B) for k = 0, 1, …
    along: Vec<f64>,
    across: Vec<f64>,
    du: Vec<f64>,
    contact: Vec<f64>,
    q: Vec<f64>,
    /// ∂φ/∂x (1/m) and ∂²φ/∂x² (1/m²) at one point, and cos(kπx/L).
    slope: Vec<f64>,
    curvature: Vec<f64>,
    along_cos: Vec<f64>,
    /// Per wheel: ṡ (m/s), the part of s̈ not from the deck's modal
    /// accelerations, 2vΣφ′q̇ + v²(Σφ″q + r″) (m/s²), the contact force (N),
    /// whether in contact (rigid contact only).
    surface_rate: Vec<f64>,
    surface_transport: Vec<f64>,
    force: Vec<f64>,
    in_contact: Vec<bool>,
    /// Per vehicle, per coordinate: [`Vehicle::own_damping`].
    own_damping: Vec<Vec<f64>>,
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
fn sines(a: f64, out: &mut [f64]) {
    let c2 = 2.0 * a.cos();
    for k in 0..out.len() {
        out[k] = match k {
            0 => 0.0,
            1 => a.sin(),
            _ => c2 * out[k - 1] - out[k - 2],
        };
    }
}

struct Layout {
    /// First state index of each vehicle's u; its u̇ follows.
    offsets: Vec<usize>,
    dim: usize,
}

impl Case {
    fn modes(&self) -> Vec<Mode> {
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

    fn length(&self) -> f64 {
        match self.deck {
            Deck::Beam { length, .. } | Deck::Plate { length, .. } => length,
        }
    }

    fn shape(&self, mode: &Mode, x: f64, y: f64) -> f64 {
        let along = (mode.m as f64 * PI * x / self.length()).sin();
        match self.deck {
            Deck::Beam { .. } => along,
            Deck::Plate { width, .. } => along * (mode.n as f64 * PI * y / width).sin(),
        }
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

    fn layout(&self, modes: usize) -> Layout {
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
    fn shapes_at(&self, modes: &[Mode], x: f64, y: f64, work: &mut Work) {
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
    fn wheel_states(
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
    fn rhs(
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
    fn hold_wheels_with_mass(
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

    /// One RK4 step of length `h` from (t, y) into `out`.
    #[allow(clippy::too_many_arguments)]
    fn rk4(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        h: f64,
        out: &mut [f64],
        scratch: &mut Scratch,
        work: &mut Work,
    ) {
        let dim = y.len();
        let stages = [(0.0, 0usize), (0.5, 0), (0.5, 1), (1.0, 2)];
        for (s, &(c, from)) in stages.iter().enumerate() {
            if s == 0 {
                scratch.yt.copy_from_slice(y);
            } else {
                for m in 0..dim {
                    scratch.yt[m] = y[m] + c * h * scratch.k[from][m];
                }
            }
            let (_, tail) = scratch.k.split_at_mut(s);
            self.rhs(
                modes,
                layout,
                t + c * h,
                &scratch.yt,
                &mut tail[0],
                &mut scratch.delta,
                &mut scratch.position,
                work,
            );
        }
        let k = &scratch.k;
        for m in 0..dim {
            out[m] = y[m] + h / 6.0 * (k[0][m] + 2.0 * k[1][m] + 2.0 * k[2][m] + k[3][m]);
        }
    }

    /// Contact forces (into `work.force`), compressions and positions at (t, y).
    #[allow(clippy::too_many_arguments)]
    fn evaluate(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        scratch: &mut Scratch,
        work: &mut Work,
    ) {
        let mut dy = std::mem::take(&mut scratch.dy);
        self.rhs(
            modes,
            layout,
            t,
            y,
            &mut dy,
            &mut scratch.delta,
            &mut scratch.position,
            work,
        );
        scratch.dy = dy;
    }

    /// The rigid-contact event of wheel `c` at the current evaluation: how
    /// far past it the state is (> 0: a held wheel's force below 0, or a
    /// free point below the surface, m or N).
    fn event(&self, c: usize, scratch: &Scratch, work: &Work) -> f64 {
        if work.in_contact[c] {
            -work.force[c]
        } else {
            // Below the surface by more than 10 fm (round-off of s).
            scratch.delta[c] - 1e-14
        }
    }

    /// Integrates [0, t_end] with RK4 at step `h` and samples at `times`
    /// (multiples of h within 0.5h).
    pub fn run(&self, times: &[f64], t_end: f64, h: f64) -> History {
        let modes = self.modes();
        let nm = modes.len();
        let layout = self.layout(nm);
        let dim = layout.dim;
        let mut y = vec![0.0; dim];
        for (v, vehicle) in self.vehicles.iter().enumerate() {
            assert!(vehicle.entry_time >= 0.0 && vehicle.speed > 0.0);
            let u = vehicle.static_state(|p| {
                if self.rigid {
                    0.0
                } else {
                    (p / self.contact_coefficient).powf(1.0 / self.contact_exponent)
                }
            });
            let b = layout.offsets[v];
            y[b..b + vehicle.dofs()].copy_from_slice(&u);
            for (i, &m) in vehicle.masses.iter().enumerate() {
                assert!(m > 0.0 || vehicle.own_damping(i) > 0.0);
            }
        }
        let nw: usize = self.vehicles.iter().map(|v| v.wheels.len()).sum();
        // Which coordinate of the state each wheel's point is.
        let wheel_dofs: Vec<usize> = self
            .vehicles
            .iter()
            .enumerate()
            .flat_map(|(v, vehicle)| vehicle.wheels.iter().map(move |w| (v, w.dof)))
            .map(|(v, dof)| layout.offsets[v] + dof)
            .collect();
        // Each wheel's mass (0: a massless point) and velocity coordinate.
        let wheel_masses: Vec<(f64, usize)> = self
            .vehicles
            .iter()
            .enumerate()
            .flat_map(|(v, vehicle)| {
                let base = layout.offsets[v] + vehicle.dofs();
                vehicle
                    .wheels
                    .iter()
                    .map(move |w| (vehicle.masses[w.dof], base + w.dof))
            })
            .collect();
        let steps = (t_end / h).round() as usize;
        let mut scratch = Scratch {
            k: vec![vec![0.0; dim]; 4],
            yt: vec![0.0; dim],
            dy: vec![0.0; dim],
            delta: vec![0.0; nw],
            position: vec![0.0; nw],
        };
        let top = modes.iter().map(|m| m.m.max(m.n)).max().unwrap_or(0) + 1;
        let mut work = Work {
            shape: vec![0.0; nm],
            under: vec![0.0; nw * nm],
            along: vec![0.0; top],
            across: vec![0.0; top],
            du: Vec::new(),
            contact: Vec::new(),
            q: Vec::new(),
            slope: vec![0.0; nm],
            curvature: vec![0.0; nm],
            surface_transport: vec![0.0; nw],
            along_cos: vec![0.0; top],
            surface_rate: vec![0.0; nw],
            force: vec![0.0; nw],
            in_contact: vec![true; nw],
            own_damping: self
                .vehicles
                .iter()
                .map(|v| (0..v.dofs()).map(|i| v.own_damping(i)).collect())
                .collect(),
        };
        let mut out = History {
            contact_force: vec![Vec::new(); nw],
            wheels: vec![WheelStatistics::default(); nw],
            ..Default::default()
        };
        let probe = self.probe;
        let probe_shape: Vec<f64> = modes
            .iter()
            .map(|mode| self.shape(mode, probe.0, probe.1))
            .collect();
        let sample = |y: &[f64], force: &[f64], out: &mut History| {
            out.deflection
                .push(probe_shape.iter().zip(y).map(|(p, q)| p * q).sum());
            for (c, f) in force.iter().enumerate() {
                out.contact_force[c].push(*f);
            }
        };
        self.evaluate(&modes, &layout, 0.0, &y, &mut scratch, &mut work);
        let mut next = 0usize;
        while next < times.len() && times[next] <= 0.5 * h {
            sample(&y, &work.force, &mut out);
            next += 1;
        }
        let mut previous = scratch.delta.clone();
        let mut previous_position = scratch.position.clone();
        let (mut y_end, mut y_try) = (vec![0.0; dim], vec![0.0; dim]);
        // The contact forces of the two previous grid points, per wheel.
        let mut recent: Vec<[f64; 2]> = work.force.iter().map(|&f| [f, f]).collect();
        for i in 0..steps {
            let t = i as f64 * h;
            let t1 = (i + 1) as f64 * h;
            if self.rigid {
                // Step to t1, stopping at every event on the way.
                let mut tc = t;
                loop {
                    let rest = t1 - tc;
                    self.rk4(
                        &modes,
                        &layout,
                        tc,
                        &y,
                        rest,
                        &mut y_end,
                        &mut scratch,
                        &mut work,
                    );
                    self.evaluate(&modes, &layout, t1, &y_end, &mut scratch, &mut work);
                    let crossed: Vec<usize> = (0..nw)
                        .filter(|&c| self.event(c, &scratch, &work) > 0.0)
                        .collect();
                    if crossed.is_empty() {
                        y.copy_from_slice(&y_end);
                        break;
                    }
                    // Earliest event: bisection on the step length.
                    let mut earliest = (rest, crossed[0]);
                    for &c in &crossed {
                        let (mut lo, mut hi) = (0.0, rest);
                        while hi - lo > 1e-15 {
                            let mid = 0.5 * (lo + hi);
                            self.rk4(
                                &modes,
                                &layout,
                                tc,
                                &y,
                                mid,
                                &mut y_try,
                                &mut scratch,
                                &mut work,
                            );
                            self.evaluate(
                                &modes,
                                &layout,
                                tc + mid,
                                &y_try,
                                &mut scratch,
                                &mut work,
                            );
                            if self.event(c, &scratch, &work) > 0.0 {
                                hi = mid;
                            } else {
                                lo = mid;
                            }
                        }
                        if hi < earliest.0 {
                            earliest = (hi, c);
                        }
                    }
                    let (tau, c) = earliest;
                    self.rk4(
                        &modes,
                        &layout,
                        tc,
                        &y,
                        tau,
                        &mut y_end,
                        &mut scratch,
                        &mut work,
                    );
                    y.copy_from_slice(&y_end);
                    tc += tau;
                    self.evaluate(&modes, &layout, tc, &y, &mut scratch, &mut work);
                    // The point is on the surface at the event: put it there
                    // exactly (removes the 1e-15 s of the bracket).
                    y[wheel_dofs[c]] += scratch.delta[c];
                    let w = &mut out.wheels[c];
                    if work.in_contact[c] {
                        w.losses += 1;
                        if w.first_loss.is_none() {
                            w.first_loss = Some((tc, scratch.position[c]));
                        }
                    } else {
                        out.first_landing.get_or_insert(tc);
                        let (m, velocity) = wheel_masses[c];
                        if m > 0.0 {
                            // A wheel with mass lands: a plastic impact on this
                            // wheel alone, Λ = −(u̇ − ṡ)/(1/m + Σφ²/M) up on the
                            // wheel and down on the deck. (With other wheels
                            // held on the deck a full impact would be a
                            // multi-contact problem: compare only up to
                            // `first_landing`.)
                            let under = &work.under[c * nm..(c + 1) * nm];
                            let relative = y[velocity] - work.surface_rate[c];
                            let deck: f64 =
                                modes.iter().zip(under).map(|(mo, p)| p * p / mo.mass).sum();
                            let impulse = -relative / (1.0 / m + deck);
                            y[velocity] += impulse / m;
                            for (j, mode) in modes.iter().enumerate() {
                                y[nm + j] -= impulse * under[j] / mode.mass;
                            }
                        }
                    }
                    work.in_contact[c] = !work.in_contact[c];
                    if t1 - tc <= 1e-15 {
                        break;
                    }
                }
                // Held points stay on the surface (RK4 drift, 1e-16 m), and
                // held wheels with mass move with it.
                self.evaluate(&modes, &layout, t1, &y, &mut scratch, &mut work);
                for c in 0..nw {
                    if work.in_contact[c] {
                        y[wheel_dofs[c]] += scratch.delta[c];
                        if wheel_masses[c].0 > 0.0 {
                            y[wheel_masses[c].1] = work.surface_rate[c];
                        }
                    }
                }
            } else {
                self.rk4(
                    &modes,
                    &layout,
                    t,
                    &y,
                    h,
                    &mut y_end,
                    &mut scratch,
                    &mut work,
                );
                y.copy_from_slice(&y_end);
            }
            self.evaluate(&modes, &layout, t1, &y, &mut scratch, &mut work);
            let (delta, pos) = (&scratch.delta, &scratch.position);
            for c in 0..nw {
                let w = &mut out.wheels[c];
                let d = delta[c];
                let f = work.force[c];
                w.max_force = w.max_force.max(f);
                // A smooth peak between grid points: the vertex of the
                // parabola through the last three values (O(h³) instead of
                // the grid's O(h²)), where the correction is small (not at a
                // rigid landing's jump).
                let [f0, f1] = recent[c];
                let bend = 2.0 * f1 - f0 - f;
                if f1 >= f0 && f1 >= f && bend > 0.0 {
                    let correction = (f0 - f) * (f0 - f) / (8.0 * bend);
                    if correction < 1e-4 * f1 {
                        w.max_force = w.max_force.max(f1 + correction);
                    }
                }
                recent[c] = [f1, f];
                w.max_gap = w.max_gap.max(-d);
                if -d > 1e-9 && w.first_nanometre.is_none() {
                    w.first_nanometre = Some(t1);
                }
                if !self.rigid && previous[c] > 0.0 && d <= 0.0 {
                    w.losses += 1;
                    if w.first_loss.is_none() {
                        let s = previous[c] / (previous[c] - d);
                        w.first_loss = Some((
                            t + s * h,
                            previous_position[c] + s * (pos[c] - previous_position[c]),
                        ));
                    }
                }
            }
            previous.copy_from_slice(delta);
            previous_position.copy_from_slice(pos);
            while next < times.len() && (times[next] - t1).abs() <= 0.5 * h {
                sample(&y, &work.force, &mut out);
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

/// Scratch space of the stepping.
struct Scratch {
    k: Vec<Vec<f64>>,
    yt: Vec<f64>,
    dy: Vec<f64>,
    delta: Vec<f64>,
    position: Vec<f64>,
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
