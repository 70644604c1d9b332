//! Independent high-accuracy reference solution (test oracle) for a moving two-mass oscillator
//! on a simply supported Euler–Bernoulli beam with a **tensionless elastic contact spring**.
//!
//! This file is self-contained (std only) and shares no code with `vbi`. It is meant to be
//! copied into an integration-test support directory; everything is `allow(dead_code)`.
//!
//! # Model (SI units; vertical coordinates positive **upward**; g = 9.81 m/s² downward)
//!
//! *Beam* — length `L` [m], bending stiffness `EI` [N·m²], mass per length `m` [kg/m], modal
//! damping ratio `ζ` (all modes). Analytic modes `φ_j(x) = sin(jπx/L)`, `j = 1..N`,
//! `w(x,t) = Σ_j q_j(t) φ_j(x)` [m], `ω_j = (jπ/L)² √(EI/m)` [rad/s]. With the contact force
//! `F ≥ 0` [N] (compression positive: it pushes the beam **down**) applied at `x_c(t) = x₀ + v t`:
//!
//! ```text
//! q̈_j + 2ζω_j q̇_j + ω_j² q_j = (2/(mL)) · (−F) · φ_j(x_c)      while 0 ≤ x_c ≤ L,
//! q̈_j + 2ζω_j q̇_j + ω_j² q_j = 0                                otherwise.
//! ```
//!
//! *Oscillator* — sprung mass `m_s` (`y_s`), wheel (unsprung) mass `m_u > 0` (`y_w`), suspension
//! spring `k` and dashpot `c`:
//!
//! ```text
//! m_s ÿ_s = −k(y_s − y_w) − c(ẏ_s − ẏ_w) − m_s g
//! m_u ÿ_w =  k(y_s − y_w) + c(ẏ_s − ẏ_w) − m_u g + F
//! ```
//!
//! *Surface* under the wheel — `s(x,t) = w(x,t) + r(x)` while `0 ≤ x_c ≤ L`; off the beam the
//! wheel rides rigid ground at elevation `r(x)`. Harmonic roughness
//! `r(x) = a sin(2πx/λ + φ)` for `x ≥ 0`, `r = 0` for `x < 0` (it continues past the exit).
//! Note that `r(0⁺) = a sin φ`: for `φ ≠ 0 (mod π)` the surface *jumps* at the entry.
//!
//! *Contact* — a **tensionless** spring, compression `δ = s(x_c,t) − y_w` (positive when the
//! wheel is pressed into the surface) and `F = k_c δⁿ` if `δ > 0`, `F = 0` otherwise (no
//! tension). `n = 1` is the linear spring of stiffness `k_c` [N/m] of Section 4 of the LCP
//! separation paper (the source paper of vbi's design notes: elastic tensionless contact,
//! "linear and tensionless spring"); `n = 3/2` is Hertz's law `F = C δ^1.5` with `k_c = C`
//! [N/m^1.5] (the wheel–rail contact of Zhai's vehicle–track models). The exponent is the
//! case's `contact_exponent`.
//!
//! *Initial state* (public API) — vehicle at rest in static equilibrium on flat rigid ground at
//! `x₀ ≤ 0`: `F = (m_s+m_u)g`, `δ₀ = (F/k_c)^(1/n)`, `y_w = −δ₀`, `y_s = y_w − m_s g/k`; beam at rest,
//! `q = 0`; `t = 0`. [`tensionless_from_state`] accepts any initial state, any `x₀` and `v ≥ 0`
//! (e.g. a vehicle standing on the deck and dropped onto it).
//!
//! # Integration and event handling
//!
//! The state `[q, q̇, y_s, ẏ_s, y_w, ẏ_w, W]` (`W` = energy-balance accumulator, see below) is
//! integrated with the explicit Dormand–Prince 5(4) pair (local extrapolation, FSAL) with its
//! 4th-order continuous extension (dense output) and the standard step-size controller
//! `h ← h·clamp(0.9·err^(−1/5), 0.2, 5)` — Hairer, Nørsett & Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., §II.4–II.5 (embedded pairs, DOPRI5 coefficients, dense
//! output) and §II.6 (dense output used for event location / discontinuities).
//! The error norm is Hairer's RMS norm with `sc_i = atol_i + rtol·max(|y_i|, |y_i,new|)` and
//! per-component absolute tolerances scaled to the physics:
//! `atol_disp = rtol · min(δ₀, PL³/(48EI), m_s g/k)` (P = (m_s+m_u)g, so the contact force is
//! resolved to ≈ rtol·P) for `q_j, y_s, y_w`, and `atol_disp·ω` for the velocities
//! (`ω_j`, `√(k/m_s)`, `√((k+k_t)/m_u)`, `k_t` the contact's tangent stiffness `n k_c δⁿ⁻¹` at
//! the compression under 4P). `W` is not error-controlled.
//!
//! The right-hand side is smooth inside each *phase* = (region ∈ {before, on, after the beam},
//! contact ∈ {in contact, separated}); its derivative (or, for `φ ≠ 0`, its value) jumps between
//! phases. Inside a phase the phase's formula is used even where it is "out of range" (smooth
//! extension, e.g. `F = k_c sign(δ)|δ|ⁿ` with `δ < 0` slightly past a loss — C¹ at δ = 0 for
//! both exponents), so no step ever straddles a switch:
//! * *Entry/exit* (`x_c = 0`, `x_c = L`) happen at the known times `−x₀/v`, `(L−x₀)/v`; steps are
//!   clipped to end exactly there and integration restarts in the new region (the contact phase
//!   is then re-evaluated from the sign of `δ`, which records a Loss/Regain if `δ` jumped).
//! * *Contact loss/regain*: the switching function `g = δ` (in contact) or `g = −δ` (separated)
//!   is checked on every accepted step at 8 equally spaced dense-output points. At the first
//!   negative sample the root is bracketed and located with the Illinois (modified regula falsi)
//!   method applied to `g` evaluated on **fresh Dormand–Prince steps from the step start**
//!   (`τ ↦ DP5 step of size τ`, i.e. bisection-type search with re-integration, which is more
//!   accurate than the interpolant); the bracket is reduced to 1e-14 s. If the fresh steps do not
//!   confirm the bracket (grazing), the root of the interpolant is used instead. The step is then
//!   redone to end exactly at the event, the phase is toggled, `F` restarts from `k_c·0ⁿ`, the RHS
//!   is re-evaluated (no FSAL across events) and the step-size proposal of the full step is kept.
//!   The returned event time is the bracket end on the new-phase side, so every phase starts
//!   with `g ≥ 0`.
//! * On rigid rough ground the roughness is not part of the state, so the step is additionally
//!   limited to `λ/(8v)` so that roughness crests cannot be skipped; and every step is limited
//!   to `0.5/ω_max` (fastest beam mode or wheel-hop frequency `√((k+k_t)/m_u)`), far inside
//!   the explicit stability region, so that quiescent states (e.g. a vehicle at rest) are not
//!   integrated at the stability boundary with roundoff-level noise.
//!
//! # Energy balance (used as a self-check)
//!
//! `E = Σ_j (mL/4)(q̇_j² + ω_j² q_j²) + ½m_s ẏ_s² + ½m_u ẏ_w² + ½k(y_s−y_w)² + k_c|δ|ⁿ⁺¹/(n+1)
//!      + m_s g y_s + m_u g y_w` (the contact term uses the phase formula). Differentiating along
//! solutions gives `dE/dt = F v ∂s/∂x(x_c) − c(ẏ_s−ẏ_w)² − Σ_j mLζω_j q̇_j²`: the moving
//! contact point does work through the surface slope (the horizontal constraint that keeps `v`
//! constant), dampers dissipate. `W` integrates this right-hand side, so `E(t) − E(0) = W(t)`
//! holds for any case whose surface is continuous (it is violated only by the contact energy
//! jump at an entry with `φ ≠ 0`).
#![allow(dead_code)]
#![allow(clippy::needless_range_loop, clippy::too_many_arguments)]

use std::f64::consts::PI;

/// Gravitational acceleration, m/s² (acts downward).
pub const GRAVITY: f64 = 9.81;

/// Number of dense-output points per step at which the switching function is checked.
const SWITCH_SAMPLES: usize = 8;
/// Number of dense-output points per step scanned by [`extremes`].
const SCAN_SAMPLES: usize = 8;
/// Absolute tolerance of event times on the step-local time axis, s.
const EVENT_TIME_TOL: f64 = 1e-14;

// ---------------------------------------------------------------------------------------------
// Public data types
// ---------------------------------------------------------------------------------------------

/// One test case. All quantities SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TensionlessCase {
    /// Span L, m.
    pub length: f64,
    /// EI, N·m².
    pub bending_stiffness: f64,
    /// m, kg/m.
    pub mass_per_length: f64,
    /// Modal damping ratio ζ (all modes), –.
    pub damping_ratio: f64,
    /// m_s, kg.
    pub sprung_mass: f64,
    /// m_u, kg (must be > 0).
    pub unsprung_mass: f64,
    /// k, N/m.
    pub suspension_stiffness: f64,
    /// c, N·s/m.
    pub suspension_damping: f64,
    /// k_c: N/m for the linear spring (n = 1), the Hertz coefficient C in N/m^1.5 for n = 1.5.
    pub contact_stiffness: f64,
    /// n in F = k_c δⁿ: 1 (linear spring) or 1.5 (Hertz).
    pub contact_exponent: f64,
    /// v, m/s (≥ 0).
    pub speed: f64,
    /// x₀, m: contact-point position at t = 0 (≤ 0 for the public equilibrium start).
    pub start_position: f64,
    /// a, m.
    pub roughness_amplitude: f64,
    /// λ, m.
    pub roughness_wavelength: f64,
    /// φ, rad.
    pub roughness_phase: f64,
    /// Number of modes N.
    pub modes: usize,
}

/// Kind of a recorded event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// δ crossed zero downward: the wheel left the surface.
    Loss,
    /// δ crossed zero upward: the wheel touched the surface again.
    Regain,
    /// x_c reached 0 (the wheel enters the beam).
    Entry,
    /// x_c reached L (the wheel leaves the beam).
    Exit,
}

/// An event and its time, s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactEvent {
    pub time: f64,
    pub kind: EventKind,
}

/// Sampled response. `contact_force` = F ≥ 0 (exactly 0 while separated), `compression` = δ
/// (negative = gap while separated), displacements upward positive, `midspan_deflection` =
/// w(L/2, t). `events` lists every event in time order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TensionlessHistory {
    pub time: Vec<f64>,
    pub contact_force: Vec<f64>,
    pub compression: Vec<f64>,
    pub wheel_displacement: Vec<f64>,
    pub sprung_displacement: Vec<f64>,
    pub midspan_deflection: Vec<f64>,
    pub events: Vec<ContactEvent>,
}

/// Full initial state for [`tensionless_from_state`].
#[derive(Clone, Debug, PartialEq)]
pub struct InitialState {
    /// Modal displacements q_j, m (length = modes).
    pub q: Vec<f64>,
    /// Modal velocities q̇_j, m/s.
    pub q_dot: Vec<f64>,
    pub sprung_displacement: f64,
    pub sprung_velocity: f64,
    pub wheel_displacement: f64,
    pub wheel_velocity: f64,
}

/// [`TensionlessHistory`] plus energy diagnostics and the accepted step count.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DetailedHistory {
    pub history: TensionlessHistory,
    /// Total mechanical energy E (see the module docs), J.
    pub energy: Vec<f64>,
    /// W(t) = ∫ (F v ∂s/∂x − dissipation) dt, J; E(t) − E(0) = W(t).
    pub net_work: Vec<f64>,
    /// Non-gravitational part of E (kinetic + strain + springs), J — a positive energy scale.
    pub elastic_kinetic_energy: Vec<f64>,
    /// Beam modal energy Σ (mL/4)(q̇_j² + ω_j² q_j²), J.
    pub beam_energy: Vec<f64>,
    /// Accepted integration steps.
    pub steps: usize,
}

impl TensionlessCase {
    /// ω_j = (jπ/L)² √(EI/m), rad/s, for j = 1..N.
    pub fn natural_frequency(&self, j: usize) -> f64 {
        let kj = j as f64 * PI / self.length;
        kj * kj * (self.bending_stiffness / self.mass_per_length).sqrt()
    }

    /// Vehicle weight P = (m_s + m_u) g, N.
    pub fn static_load(&self) -> f64 {
        (self.sprung_mass + self.unsprung_mass) * GRAVITY
    }

    /// Time at which x_c = 0, if the vehicle moves.
    pub fn entry_time(&self) -> Option<f64> {
        (self.speed > 0.0).then(|| -self.start_position / self.speed)
    }

    /// Time at which x_c = L, if the vehicle moves.
    pub fn exit_time(&self) -> Option<f64> {
        (self.speed > 0.0).then(|| (self.length - self.start_position) / self.speed)
    }

    /// Roughness formula r(x), r'(x), r''(x) (the `x ≥ 0` branch, evaluated for any x).
    pub fn roughness(&self, x: f64) -> (f64, f64, f64) {
        let a = self.roughness_amplitude;
        if a == 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let beta = 2.0 * PI / self.roughness_wavelength;
        let (s, c) = (beta * x + self.roughness_phase).sin_cos();
        (a * s, a * beta * c, -a * beta * beta * s)
    }

    /// Contact force of the phase formula, N: `k_c sign(δ)|δ|ⁿ` (the smooth odd extension, used
    /// inside a contact phase; it is ≥ 0 wherever the phase is valid).
    pub fn contact_law(&self, compression: f64) -> f64 {
        let n = self.contact_exponent;
        let magnitude = if n == 1.0 {
            compression.abs()
        } else {
            compression.abs().powf(n)
        };
        self.contact_stiffness * magnitude.copysign(compression)
    }

    /// Compression carrying the force `force` ≥ 0: `(F/k_c)^(1/n)`, m.
    pub fn compression_under(&self, force: f64) -> f64 {
        (force / self.contact_stiffness).powf(1.0 / self.contact_exponent)
    }

    /// Contact potential `k_c |δ|ⁿ⁺¹/(n+1)` (J) of the phase formula.
    fn contact_energy(&self, compression: f64) -> f64 {
        let n = self.contact_exponent;
        self.contact_stiffness * compression.abs().powf(n + 1.0) / (n + 1.0)
    }

    /// Tangent stiffness of the contact `n k_c δⁿ⁻¹` at the compression under 4P, N/m (k_c for
    /// the linear spring): the wheel-hop scale used for tolerances and the step limit.
    fn contact_tangent_stiffness(&self) -> f64 {
        let n = self.contact_exponent;
        let delta = self.compression_under(4.0 * self.static_load());
        n * self.contact_stiffness * delta.powf(n - 1.0)
    }

    /// Static equilibrium on flat rigid ground (the public initial state).
    pub fn equilibrium_state(&self) -> InitialState {
        let p = self.static_load();
        let yw = -self.compression_under(p);
        InitialState {
            q: vec![0.0; self.modes],
            q_dot: vec![0.0; self.modes],
            sprung_displacement: yw - self.sprung_mass * GRAVITY / self.suspension_stiffness,
            sprung_velocity: 0.0,
            wheel_displacement: yw,
            wheel_velocity: 0.0,
        }
    }

    fn validate(&self) {
        let positive = [
            ("length", self.length),
            ("bending_stiffness", self.bending_stiffness),
            ("mass_per_length", self.mass_per_length),
            ("sprung_mass", self.sprung_mass),
            ("unsprung_mass", self.unsprung_mass),
            ("suspension_stiffness", self.suspension_stiffness),
            ("contact_stiffness", self.contact_stiffness),
        ];
        for (name, value) in positive {
            assert!(
                value.is_finite() && value > 0.0,
                "{name} must be > 0, got {value}"
            );
        }
        assert!(
            self.contact_exponent == 1.0 || self.contact_exponent == 1.5,
            "contact exponent must be 1 or 1.5, got {}",
            self.contact_exponent
        );
        assert!(self.damping_ratio >= 0.0 && self.suspension_damping >= 0.0);
        assert!(
            self.speed.is_finite() && self.speed >= 0.0,
            "speed must be ≥ 0"
        );
        assert!(self.start_position.is_finite());
        assert!(self.modes >= 1, "need at least one mode");
        if self.roughness_amplitude != 0.0 {
            assert!(
                self.roughness_wavelength.is_finite() && self.roughness_wavelength > 0.0,
                "roughness wavelength must be > 0"
            );
        }
    }

    /// Smallest displacement scale used for absolute tolerances.
    fn displacement_scale(&self, with_contact: bool) -> f64 {
        let p = self.static_load();
        let beam = p * self.length.powi(3) / (48.0 * self.bending_stiffness);
        let susp = self.sprung_mass * GRAVITY / self.suspension_stiffness;
        let mut d = beam.min(susp);
        if with_contact {
            d = d.min(self.compression_under(p));
        }
        d
    }

    /// Step limit so that roughness crests on rigid ground cannot be skipped.
    fn roughness_step_limit(&self) -> f64 {
        if self.roughness_amplitude != 0.0 && self.speed > 0.0 {
            self.roughness_wavelength / (8.0 * self.speed)
        } else {
            f64::INFINITY
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Phases and regions
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Region {
    /// x_c < 0: flat rigid ground (r = 0).
    Before,
    /// 0 ≤ x_c ≤ L: on the beam.
    On,
    /// x_c > L: rigid ground with roughness.
    After,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Phase {
    region: Region,
    contact: bool,
}

/// Region at time t (right-continuous in t: at the entry time the wheel is already "on").
fn region_at(case: &TensionlessCase, t: f64) -> Region {
    match (case.entry_time(), case.exit_time()) {
        (Some(te), Some(tx)) => {
            if t < te {
                Region::Before
            } else if t < tx {
                Region::On
            } else {
                Region::After
            }
        }
        _ => {
            let x = case.start_position;
            if x < 0.0 {
                Region::Before
            } else if x <= case.length {
                Region::On
            } else {
                Region::After
            }
        }
    }
}

/// Calls `f(j0, sin((j0+1)κx), cos((j0+1)κx))` for j0 = 0..n (angle-addition recurrence).
#[inline]
fn for_each_mode(n: usize, kappa: f64, x: f64, mut f: impl FnMut(usize, f64, f64)) {
    let (s1, c1) = (kappa * x).sin_cos();
    let (mut s, mut c) = (s1, c1);
    for j in 0..n {
        f(j, s, c);
        let sn = s * c1 + c * s1;
        let cn = c * c1 - s * s1;
        s = sn;
        c = cn;
    }
}

// ---------------------------------------------------------------------------------------------
// ODE models
// ---------------------------------------------------------------------------------------------

trait Ode {
    fn dim(&self) -> usize;
    fn rhs(&self, t: f64, y: &[f64], phase: Phase, dy: &mut [f64]);
    /// Switching function δ (tensionless model) or `None` (no state events).
    fn compression(&self, t: f64, y: &[f64], region: Region) -> Option<f64>;
    /// Absolute tolerances; `f64::INFINITY` excludes a component from error control.
    fn abs_tol(&self, rtol: f64) -> Vec<f64>;
    fn max_step(&self) -> f64;
    fn case(&self) -> &TensionlessCase;
}

/// Tensionless penalty-contact model. State: `[q(N), q̇(N), y_s, ẏ_s, y_w, ẏ_w, W]`.
struct Tensionless {
    c: TensionlessCase,
    n: usize,
    kappa: f64,
    omega: Vec<f64>,
}

impl Tensionless {
    fn new(c: &TensionlessCase) -> Self {
        c.validate();
        Tensionless {
            c: *c,
            n: c.modes,
            kappa: PI / c.length,
            omega: (1..=c.modes).map(|j| c.natural_frequency(j)).collect(),
        }
    }

    fn ys(&self) -> usize {
        2 * self.n
    }
    fn yw(&self) -> usize {
        2 * self.n + 2
    }
    fn work(&self) -> usize {
        2 * self.n + 4
    }

    /// Surface elevation s and slope ∂s/∂x under the wheel.
    fn surface(&self, x: f64, y: &[f64], region: Region) -> (f64, f64) {
        match region {
            Region::Before => (0.0, 0.0),
            Region::After => {
                let (r, rx, _) = self.c.roughness(x);
                (r, rx)
            }
            Region::On => {
                let (r, rx, _) = self.c.roughness(x);
                let (mut w, mut wx) = (0.0, 0.0);
                let kappa = self.kappa;
                for_each_mode(self.n, kappa, x, |j, s, c| {
                    w += y[j] * s;
                    wx += y[j] * (j + 1) as f64 * kappa * c;
                });
                (w + r, wx + rx)
            }
        }
    }

    fn pack(&self, s: &InitialState) -> Vec<f64> {
        assert_eq!(s.q.len(), self.n, "initial q length must equal modes");
        assert_eq!(
            s.q_dot.len(),
            self.n,
            "initial q_dot length must equal modes"
        );
        let mut y = vec![0.0; 2 * self.n + 5];
        y[..self.n].copy_from_slice(&s.q);
        y[self.n..2 * self.n].copy_from_slice(&s.q_dot);
        y[self.ys()] = s.sprung_displacement;
        y[self.ys() + 1] = s.sprung_velocity;
        y[self.yw()] = s.wheel_displacement;
        y[self.yw() + 1] = s.wheel_velocity;
        y
    }

    fn midspan(&self, y: &[f64]) -> f64 {
        let mut w = 0.0;
        for_each_mode(self.n, self.kappa, 0.5 * self.c.length, |j, s, _| {
            w += y[j] * s
        });
        w
    }

    /// (total energy, non-gravitational part, beam part).
    fn energy(&self, t: f64, y: &[f64], phase: Phase) -> (f64, f64, f64) {
        let c = &self.c;
        let n = self.n;
        let half_modal_mass = 0.25 * c.mass_per_length * c.length;
        let mut beam = 0.0;
        for j in 0..n {
            beam += half_modal_mass * (y[n + j].powi(2) + (self.omega[j] * y[j]).powi(2));
        }
        let (ys, vs, yw, vw) = (y[2 * n], y[2 * n + 1], y[2 * n + 2], y[2 * n + 3]);
        let delta = self.compression(t, y, phase.region).unwrap_or(0.0);
        let contact = if phase.contact {
            c.contact_energy(delta)
        } else {
            0.0
        };
        let elastic = beam
            + 0.5 * c.sprung_mass * vs * vs
            + 0.5 * c.unsprung_mass * vw * vw
            + 0.5 * c.suspension_stiffness * (ys - yw).powi(2)
            + contact;
        let gravity = GRAVITY * (c.sprung_mass * ys + c.unsprung_mass * yw);
        (elastic + gravity, elastic, beam)
    }
}

impl Ode for Tensionless {
    fn dim(&self) -> usize {
        2 * self.n + 5
    }

    fn rhs(&self, t: f64, y: &[f64], phase: Phase, dy: &mut [f64]) {
        let c = &self.c;
        let n = self.n;
        let x = c.start_position + c.speed * t;
        let (s, sx) = self.surface(x, y, phase.region);
        let (ys, vs, yw, vw) = (y[2 * n], y[2 * n + 1], y[2 * n + 2], y[2 * n + 3]);
        let force = if phase.contact {
            c.contact_law(s - yw)
        } else {
            0.0
        };
        let modal_damping_coeff = c.mass_per_length * c.length * c.damping_ratio;
        let mut dissipation = 0.0;
        for j in 0..n {
            let w = self.omega[j];
            let qd = y[n + j];
            dy[j] = qd;
            dy[n + j] = -2.0 * c.damping_ratio * w * qd - w * w * y[j];
            dissipation += modal_damping_coeff * w * qd * qd;
        }
        if phase.region == Region::On && force != 0.0 {
            let a = 2.0 * force / (c.mass_per_length * c.length);
            for_each_mode(n, self.kappa, x, |j, sj, _| dy[n + j] -= a * sj);
        }
        let rel_v = vs - vw;
        let fs = c.suspension_stiffness * (ys - yw) + c.suspension_damping * rel_v;
        dy[2 * n] = vs;
        dy[2 * n + 1] = (-fs - c.sprung_mass * GRAVITY) / c.sprung_mass;
        dy[2 * n + 2] = vw;
        dy[2 * n + 3] = (fs - c.unsprung_mass * GRAVITY + force) / c.unsprung_mass;
        dy[2 * n + 4] = force * c.speed * sx - c.suspension_damping * rel_v * rel_v - dissipation;
    }

    fn compression(&self, t: f64, y: &[f64], region: Region) -> Option<f64> {
        let x = self.c.start_position + self.c.speed * t;
        Some(self.surface(x, y, region).0 - y[self.yw()])
    }

    fn abs_tol(&self, rtol: f64) -> Vec<f64> {
        let c = &self.c;
        let n = self.n;
        let d = rtol * c.displacement_scale(true);
        let mut a = vec![d; 2 * n + 5];
        for j in 0..n {
            a[n + j] = d * self.omega[j];
        }
        a[2 * n + 1] = d * (c.suspension_stiffness / c.sprung_mass).sqrt();
        a[2 * n + 3] =
            d * ((c.suspension_stiffness + c.contact_tangent_stiffness()) / c.unsprung_mass).sqrt();
        a[2 * n + 4] = f64::INFINITY;
        a
    }

    fn max_step(&self) -> f64 {
        let c = &self.c;
        let wheel =
            ((c.suspension_stiffness + c.contact_tangent_stiffness()) / c.unsprung_mass).sqrt();
        let fastest = self.omega[self.n - 1].max(wheel);
        c.roughness_step_limit().min(0.5 / fastest)
    }

    fn case(&self) -> &TensionlessCase {
        &self.c
    }
}

/// Permanent-contact (bilateral, rigid) model: the wheel is held to the surface,
/// `y_w = s(x_c, t)`, and moves with the surface kinematics
/// `ÿ_w = Σ(φ_j q̈_j + 2v φ_j' q̇_j + v² φ_j'' q_j) + v² r''`. The contact force
/// `F = m_u(g + ÿ_w) − k(y_s−y_w) − c(ẏ_s−ẏ_w)` is eliminated exactly (scalar Sherman–Morrison
/// solve). State: `[q(N), q̇(N), y_s, ẏ_s]`.
struct Permanent {
    c: TensionlessCase,
    n: usize,
    kappa: f64,
    omega: Vec<f64>,
}

impl Permanent {
    fn new(c: &TensionlessCase) -> Self {
        c.validate();
        Permanent {
            c: *c,
            n: c.modes,
            kappa: PI / c.length,
            omega: (1..=c.modes).map(|j| c.natural_frequency(j)).collect(),
        }
    }

    /// Evaluates the derivative and returns (y_w, F).
    fn eval(&self, t: f64, y: &[f64], region: Region, dy: &mut [f64]) -> (f64, f64) {
        let c = &self.c;
        let n = self.n;
        let v = c.speed;
        let x = c.start_position + v * t;
        let (ys, vs) = (y[2 * n], y[2 * n + 1]);
        for j in 0..n {
            let w = self.omega[j];
            dy[j] = y[n + j];
            dy[n + j] = -2.0 * c.damping_ratio * w * y[n + j] - w * w * y[j];
        }
        let (yw, vw, force) = match region {
            Region::On => {
                let (r, rx, rxx) = c.roughness(x);
                let (mut sum_phi_b, mut sum_phi2, mut e) = (0.0, 0.0, 0.0);
                let (mut yw, mut vw) = (r, rx * v);
                let kappa = self.kappa;
                for_each_mode(n, kappa, x, |j, s, co| {
                    let kj = (j + 1) as f64 * kappa;
                    let (q, qd) = (y[j], y[n + j]);
                    sum_phi_b += s * dy[n + j];
                    sum_phi2 += s * s;
                    e += 2.0 * qd * kj * co * v - q * kj * kj * s * v * v;
                    yw += q * s;
                    vw += qd * s + q * kj * co * v;
                });
                e += rxx * v * v;
                let fs = c.suspension_stiffness * (ys - yw) + c.suspension_damping * (vs - vw);
                let alpha = 2.0 / (c.mass_per_length * c.length);
                let force = (c.unsprung_mass * (GRAVITY + sum_phi_b + e) - fs)
                    / (1.0 + c.unsprung_mass * alpha * sum_phi2);
                for_each_mode(n, kappa, x, |j, s, _| dy[n + j] -= alpha * force * s);
                (yw, vw, force)
            }
            Region::Before | Region::After => {
                let (yw, vw, aw) = if region == Region::Before {
                    (0.0, 0.0, 0.0)
                } else {
                    let (r, rx, rxx) = c.roughness(x);
                    (r, rx * v, rxx * v * v)
                };
                let fs = c.suspension_stiffness * (ys - yw) + c.suspension_damping * (vs - vw);
                (yw, vw, c.unsprung_mass * (GRAVITY + aw) - fs)
            }
        };
        let fs = c.suspension_stiffness * (ys - yw) + c.suspension_damping * (vs - vw);
        dy[2 * n] = vs;
        dy[2 * n + 1] = (-fs - c.sprung_mass * GRAVITY) / c.sprung_mass;
        (yw, force)
    }
}

impl Ode for Permanent {
    fn dim(&self) -> usize {
        2 * self.n + 2
    }

    fn rhs(&self, t: f64, y: &[f64], phase: Phase, dy: &mut [f64]) {
        self.eval(t, y, phase.region, dy);
    }

    fn compression(&self, _t: f64, _y: &[f64], _region: Region) -> Option<f64> {
        None
    }

    fn abs_tol(&self, rtol: f64) -> Vec<f64> {
        let c = &self.c;
        let n = self.n;
        let d = rtol * c.displacement_scale(false);
        let mut a = vec![d; 2 * n + 2];
        for j in 0..n {
            a[n + j] = d * self.omega[j];
        }
        a[2 * n + 1] = d * (c.suspension_stiffness / c.sprung_mass).sqrt();
        a
    }

    fn max_step(&self) -> f64 {
        let c = &self.c;
        let fastest = self.omega[self.n - 1].max((c.suspension_stiffness / c.sprung_mass).sqrt());
        c.roughness_step_limit().min(0.5 / fastest)
    }

    fn case(&self) -> &TensionlessCase {
        &self.c
    }
}

// ---------------------------------------------------------------------------------------------
// Dormand–Prince 5(4) with dense output (Hairer–Nørsett–Wanner, Table II.5.2 and §II.6)
// ---------------------------------------------------------------------------------------------

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Stage storage of one Dormand–Prince step. `k1` must hold f(t, y) before [`dp5_attempt`].
struct Workspace {
    k1: Vec<f64>,
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    k5: Vec<f64>,
    k6: Vec<f64>,
    k7: Vec<f64>,
    ytmp: Vec<f64>,
    y1: Vec<f64>,
}

impl Workspace {
    fn new(n: usize) -> Self {
        Workspace {
            k1: vec![0.0; n],
            k2: vec![0.0; n],
            k3: vec![0.0; n],
            k4: vec![0.0; n],
            k5: vec![0.0; n],
            k6: vec![0.0; n],
            k7: vec![0.0; n],
            ytmp: vec![0.0; n],
            y1: vec![0.0; n],
        }
    }
}

/// One Dormand–Prince step of size h from (t, y) in `phase`; leaves y₁ in `ws.y1`, all stages
/// in `ws.k*` (k7 = f(t+h, y₁)) and returns the RMS error norm.
fn dp5_attempt<O: Ode>(
    ode: &O,
    phase: Phase,
    t: f64,
    y: &[f64],
    h: f64,
    ws: &mut Workspace,
    atol: &[f64],
    rtol: f64,
) -> f64 {
    let n = y.len();
    let Workspace {
        k1,
        k2,
        k3,
        k4,
        k5,
        k6,
        k7,
        ytmp,
        y1,
    } = ws;
    for i in 0..n {
        ytmp[i] = y[i] + h * A21 * k1[i];
    }
    ode.rhs(t + C2 * h, ytmp, phase, k2);
    for i in 0..n {
        ytmp[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
    }
    ode.rhs(t + C3 * h, ytmp, phase, k3);
    for i in 0..n {
        ytmp[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
    }
    ode.rhs(t + C4 * h, ytmp, phase, k4);
    for i in 0..n {
        ytmp[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
    }
    ode.rhs(t + C5 * h, ytmp, phase, k5);
    for i in 0..n {
        ytmp[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
    }
    ode.rhs(t + h, ytmp, phase, k6);
    for i in 0..n {
        y1[i] = y[i] + h * (A71 * k1[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
    }
    ode.rhs(t + h, y1, phase, k7);
    let mut sum = 0.0;
    let mut counted = 0usize;
    for i in 0..n {
        if !atol[i].is_finite() {
            continue;
        }
        let sc = atol[i] + rtol * y[i].abs().max(y1[i].abs());
        let e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
        sum += (e / sc).powi(2);
        counted += 1;
    }
    (sum / counted.max(1) as f64).sqrt()
}

/// An accepted step with its continuous extension.
#[derive(Clone, Debug)]
struct StepData {
    t0: f64,
    t1: f64,
    h: f64,
    phase: Phase,
    y0: Vec<f64>,
    y1: Vec<f64>,
    k1: Vec<f64>,
    /// [ydiff | bspl | c4 | c5], 4·n.
    cont: Vec<f64>,
}

impl StepData {
    fn new(t0: f64, t1: f64, h: f64, phase: Phase, y0: &[f64], ws: &Workspace) -> Self {
        let n = y0.len();
        let mut cont = vec![0.0; 4 * n];
        for i in 0..n {
            let ydiff = ws.y1[i] - y0[i];
            let bspl = h * ws.k1[i] - ydiff;
            cont[i] = ydiff;
            cont[n + i] = bspl;
            cont[2 * n + i] = ydiff - h * ws.k7[i] - bspl;
            cont[3 * n + i] = h
                * (D1 * ws.k1[i]
                    + D3 * ws.k3[i]
                    + D4 * ws.k4[i]
                    + D5 * ws.k5[i]
                    + D6 * ws.k6[i]
                    + D7 * ws.k7[i]);
        }
        StepData {
            t0,
            t1,
            h,
            phase,
            y0: y0.to_vec(),
            y1: ws.y1.clone(),
            k1: ws.k1.clone(),
            cont,
        }
    }

    /// Dense output at θ ∈ [0, 1] (θ = 1 reproduces y₁ exactly).
    fn dense(&self, theta: f64, out: &mut [f64]) {
        if theta >= 1.0 {
            out.copy_from_slice(&self.y1);
            return;
        }
        let n = self.y0.len();
        let th1 = 1.0 - theta;
        for i in 0..n {
            out[i] = self.y0[i]
                + theta
                    * (self.cont[i]
                        + th1
                            * (self.cont[n + i]
                                + theta * (self.cont[2 * n + i] + th1 * self.cont[3 * n + i])));
        }
    }

    /// Time of dense parameter θ.
    fn time(&self, theta: f64) -> f64 {
        if theta >= 1.0 {
            self.t1
        } else {
            self.t0 + theta * self.h
        }
    }

    /// State of a *fresh* Dormand–Prince step of size τ from the step start (in `ws.y1`).
    fn fresh<'w, O: Ode>(
        &self,
        ode: &O,
        tau: f64,
        ws: &'w mut Workspace,
        atol: &[f64],
        rtol: f64,
    ) -> &'w [f64] {
        ws.k1.copy_from_slice(&self.k1);
        dp5_attempt(ode, self.phase, self.t0, &self.y0, tau, ws, atol, rtol);
        &ws.y1
    }
}

/// Illinois (modified regula falsi) root of `f` on [a, b] with f(a) ≥ 0 > f(b). Returns the
/// final bracket end `b` (where f < 0).
fn illinois(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
) -> f64 {
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= EVENT_TIME_TOL {
            break;
        }
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !(c > a && c < b) {
            c = 0.5 * (a + b);
        }
        let fc = f(c);
        if fc < 0.0 {
            b = c;
            fb = fc;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    b
}

/// Hairer's starting step size heuristic.
fn initial_step<O: Ode>(
    ode: &O,
    phase: Phase,
    t: f64,
    y: &[f64],
    f0: &[f64],
    atol: &[f64],
    rtol: f64,
    hmax: f64,
) -> f64 {
    let n = y.len();
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..n {
        let sk = atol[i] + rtol * y[i].abs();
        dnf += (f0[i] / sk).powi(2);
        dny += (y[i] / sk).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        0.01 * (dny / dnf).sqrt()
    };
    h = h.min(hmax);
    let y1: Vec<f64> = (0..n).map(|i| y[i] + h * f0[i]).collect();
    let mut f1 = vec![0.0; n];
    ode.rhs(t + h, &y1, phase, &mut f1);
    let mut der2 = 0.0;
    for i in 0..n {
        let sk = atol[i] + rtol * y[i].abs();
        der2 += ((f1[i] - f0[i]) / sk).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(0.2)
    };
    (100.0 * h).min(h1).min(hmax)
}

/// Integrates `ode` from (t_start, y0) to t_end, calling `observer` on every accepted step.
/// Returns (events, accepted steps).
fn run<O: Ode>(
    ode: &O,
    y0: Vec<f64>,
    t_start: f64,
    t_end: f64,
    rtol: f64,
    observer: &mut dyn FnMut(&StepData),
) -> (Vec<ContactEvent>, usize) {
    assert!(rtol > 0.0 && rtol < 1e-2, "rtol out of range");
    assert!(t_end > t_start, "t_end must exceed the start time");
    let case = *ode.case();
    let n = ode.dim();
    let atol = ode.abs_tol(rtol);
    let hmax = ode.max_step().min(t_end - t_start);
    let mut ws = Workspace::new(n);
    let mut scratch = Workspace::new(n);
    let mut buf = vec![0.0; n];
    let mut events = Vec::new();

    // Position breakpoints (entry/exit) inside [t_start, t_end].
    let mut bps: Vec<(f64, EventKind, Region)> = Vec::new();
    if let (Some(te), Some(tx)) = (case.entry_time(), case.exit_time()) {
        bps.push((te, EventKind::Entry, Region::On));
        bps.push((tx, EventKind::Exit, Region::After));
    }
    bps.retain(|b| b.0 >= t_start && b.0 <= t_end);
    let mut bp_idx = 0;
    while bp_idx < bps.len() && bps[bp_idx].0 == t_start {
        events.push(ContactEvent {
            time: t_start,
            kind: bps[bp_idx].1,
        });
        bp_idx += 1;
    }

    let mut t = t_start;
    let mut y = y0;
    let mut region = region_at(&case, t);
    let mut contact = ode.compression(t, &y, region).is_none_or(|d| d > 0.0);
    ode.rhs(t, &y, Phase { region, contact }, &mut ws.k1);
    let mut h = initial_step(
        ode,
        Phase { region, contact },
        t,
        &y,
        &ws.k1,
        &atol,
        rtol,
        hmax,
    );
    let mut last_rejected = false;
    let mut steps = 0usize;

    while t < t_end {
        let phase = Phase { region, contact };
        let next_stop = bps.get(bp_idx).map_or(t_end, |b| b.0.min(t_end));
        let remaining = next_stop - t;
        let (h_try, hits) = if h >= remaining {
            (remaining, true)
        } else {
            (h, false)
        };
        let err = dp5_attempt(ode, phase, t, &y, h_try, &mut ws, &atol, rtol);
        if err.is_nan() || err > 1.0 {
            let fac = if err.is_finite() {
                (0.9 * err.powf(-0.2)).max(0.2)
            } else {
                0.1
            };
            h = h_try * fac;
            last_rejected = true;
            assert!(
                h > 1e-15 * t.abs().max(1e-3),
                "step size underflow at t = {t} (err = {err})"
            );
            continue;
        }
        let mut fac = (0.9 * err.powf(-0.2)).clamp(0.2, 5.0);
        if last_rejected {
            fac = fac.min(1.0);
        }
        last_rejected = false;
        let h_next = if hits && h_try < h {
            h
        } else {
            (h_try * fac).min(hmax)
        };
        let t1 = if hits { next_stop } else { t + h_try };
        let step = StepData::new(t, t1, h_try, phase, &y, &ws);

        // --- contact switching (state event) ---
        let mut bracket = None;
        if ode.compression(t, &y, region).is_some() {
            let sign = if contact { 1.0 } else { -1.0 };
            let mut prev = 0.0;
            for i in 1..=SWITCH_SAMPLES {
                let theta = i as f64 / SWITCH_SAMPLES as f64;
                step.dense(theta, &mut buf);
                let g = sign
                    * ode
                        .compression(step.time(theta), &buf, region)
                        .unwrap_or(0.0);
                if g < 0.0 {
                    bracket = Some((prev, theta));
                    break;
                }
                prev = theta;
            }
        }

        if let Some((ta, tb)) = bracket {
            let sign = if contact { 1.0 } else { -1.0 };
            let (a, b) = (ta * h_try, if tb >= 1.0 { h_try } else { tb * h_try });
            let mut g_exact = |tau: f64| {
                let ys = step.fresh(ode, tau, &mut scratch, &atol, rtol);
                sign * ode.compression(t + tau, ys, region).unwrap_or(0.0)
            };
            let ga = if ta == 0.0 { 0.0 } else { g_exact(a) };
            let gb = g_exact(b);
            let tau = if ga >= 0.0 && gb < 0.0 {
                illinois(&mut g_exact, a, b, ga, gb)
            } else {
                // Grazing: the fresh steps do not confirm the bracket; use the interpolant.
                let mut g_dense = |tau: f64| {
                    step.dense(tau / h_try, &mut buf);
                    sign * ode.compression(t + tau, &buf, region).unwrap_or(0.0)
                };
                let ga = if ta == 0.0 { 0.0 } else { g_dense(a).max(0.0) };
                let gb = g_dense(b);
                illinois(&mut g_dense, a, b, ga, gb)
            };
            // Redo the step so that it ends exactly at the event.
            dp5_attempt(ode, phase, t, &y, tau, &mut ws, &atol, rtol);
            let ev_step = StepData::new(t, t + tau, tau, phase, &y, &ws);
            observer(&ev_step);
            steps += 1;
            t += tau;
            y.copy_from_slice(&ws.y1);
            contact = !contact;
            events.push(ContactEvent {
                time: t,
                kind: if contact {
                    EventKind::Regain
                } else {
                    EventKind::Loss
                },
            });
            ode.rhs(t, &y, Phase { region, contact }, &mut ws.k1);
            h = h_next;
            continue;
        }

        observer(&step);
        steps += 1;
        t = t1;
        y.copy_from_slice(&ws.y1);
        h = h_next;
        if hits && bp_idx < bps.len() && next_stop == bps[bp_idx].0 {
            let (tb, kind, new_region) = bps[bp_idx];
            bp_idx += 1;
            region = new_region;
            events.push(ContactEvent { time: tb, kind });
            if let Some(d) = ode.compression(t, &y, region) {
                let now = d > 0.0;
                if now != contact {
                    contact = now;
                    events.push(ContactEvent {
                        time: tb,
                        kind: if now {
                            EventKind::Regain
                        } else {
                            EventKind::Loss
                        },
                    });
                }
            }
            ode.rhs(t, &y, Phase { region, contact }, &mut ws.k1);
        } else {
            // FSAL: k7 = f(t1, y1) in the unchanged phase.
            std::mem::swap(&mut ws.k1, &mut ws.k7);
        }
    }
    (events, steps)
}

// ---------------------------------------------------------------------------------------------
// Public entry points
// ---------------------------------------------------------------------------------------------

fn check_times(output_times: &[f64], t_end: f64) {
    assert!(t_end > 0.0, "t_end must be > 0");
    for w in output_times.windows(2) {
        assert!(w[0] <= w[1], "output times must be sorted");
    }
    if let (Some(&first), Some(&last)) = (output_times.first(), output_times.last()) {
        assert!(
            first >= 0.0 && last <= t_end,
            "output times must lie in [0, t_end]"
        );
    }
}

/// Tensionless model from an arbitrary initial state (any x₀, v ≥ 0), with energy diagnostics.
/// Integrates [0, t_end] and samples the dense output at `output_times` (sorted, in [0, t_end]).
pub fn tensionless_from_state(
    case: &TensionlessCase,
    initial: &InitialState,
    output_times: &[f64],
    t_end: f64,
    rtol: f64,
) -> DetailedHistory {
    check_times(output_times, t_end);
    let model = Tensionless::new(case);
    let y0 = model.pack(initial);
    let mut out = DetailedHistory::default();
    let mut idx = 0usize;
    let mut buf = vec![0.0; model.dim()];
    let mut observer = |step: &StepData| {
        while idx < output_times.len() && output_times[idx] <= step.t1 {
            let tt = output_times[idx];
            let theta = if step.h > 0.0 {
                ((tt - step.t0) / step.h).clamp(0.0, 1.0)
            } else {
                1.0
            };
            step.dense(theta, &mut buf);
            let delta = model
                .compression(tt, &buf, step.phase.region)
                .unwrap_or(0.0);
            let force = if step.phase.contact {
                case.contact_law(delta).max(0.0)
            } else {
                0.0
            };
            let (e, elastic, beam) = model.energy(tt, &buf, step.phase);
            let hist = &mut out.history;
            hist.time.push(tt);
            hist.contact_force.push(force);
            hist.compression.push(delta);
            hist.wheel_displacement.push(buf[model.yw()]);
            hist.sprung_displacement.push(buf[model.ys()]);
            hist.midspan_deflection.push(model.midspan(&buf));
            out.energy.push(e);
            out.net_work.push(buf[model.work()]);
            out.elastic_kinetic_energy.push(elastic);
            out.beam_energy.push(beam);
            idx += 1;
        }
    };
    let (events, steps) = run(&model, y0, 0.0, t_end, rtol, &mut observer);
    assert_eq!(idx, output_times.len(), "not every output time was sampled");
    out.history.events = events;
    out.steps = steps;
    out
}

/// Integrates to `t_end` from static equilibrium on flat ground and samples the state at the
/// given output times (sorted, in [0, t_end]) using dense output.
pub fn tensionless_reference(
    case: &TensionlessCase,
    output_times: &[f64],
    t_end: f64,
    rtol: f64,
) -> TensionlessHistory {
    assert!(
        case.start_position <= 0.0,
        "the equilibrium start requires x0 ≤ 0 (use tensionless_from_state otherwise)"
    );
    tensionless_from_state(case, &case.equilibrium_state(), output_times, t_end, rtol).history
}

/// Permanent (bilateral, rigid) contact reference with the same integrator: y_w = w + r exactly,
/// wheel mass moving with the surface. Starts from q = 0, y_w = s(x₀), y_s = y_w − m_s g/k,
/// at rest (meaningful for a smooth entry, e.g. x₀ ≤ 0 or r(x₀) = r'(x₀) = 0).
/// `contact_force` = m_u(g + ÿ_w) − k(y_s−y_w) − c(ẏ_s−ẏ_w) (may become negative: no
/// separation in this model), `compression` = 0, `events` = entry/exit only.
pub fn permanent_contact_reference(
    case: &TensionlessCase,
    output_times: &[f64],
    t_end: f64,
    rtol: f64,
) -> TensionlessHistory {
    check_times(output_times, t_end);
    let model = Permanent::new(case);
    let n = model.n;
    let mut y0 = vec![0.0; model.dim()];
    let region0 = region_at(case, 0.0);
    let mut scratch = vec![0.0; model.dim()];
    let (yw0, _) = model.eval(0.0, &y0, region0, &mut scratch);
    y0[2 * n] = yw0 - case.sprung_mass * GRAVITY / case.suspension_stiffness;
    let mut out = TensionlessHistory::default();
    let mut idx = 0usize;
    let mut buf = vec![0.0; model.dim()];
    let mut observer = |step: &StepData| {
        while idx < output_times.len() && output_times[idx] <= step.t1 {
            let tt = output_times[idx];
            let theta = if step.h > 0.0 {
                ((tt - step.t0) / step.h).clamp(0.0, 1.0)
            } else {
                1.0
            };
            step.dense(theta, &mut buf);
            let (yw, force) = model.eval(tt, &buf, step.phase.region, &mut scratch);
            let mut mid = 0.0;
            for_each_mode(n, model.kappa, 0.5 * case.length, |j, s, _| {
                mid += buf[j] * s
            });
            out.time.push(tt);
            out.contact_force.push(force);
            out.compression.push(0.0);
            out.wheel_displacement.push(yw);
            out.sprung_displacement.push(buf[2 * n]);
            out.midspan_deflection.push(mid);
            idx += 1;
        }
    };
    let (events, _) = run(&model, y0, 0.0, t_end, rtol, &mut observer);
    assert_eq!(idx, output_times.len(), "not every output time was sampled");
    out.events = events;
    out
}

/// A candidate step for the extreme-value refinement.
struct Candidate {
    step: StepData,
    index: usize,
    value: f64,
}

/// Golden-section maximisation of `f` on [a, b] (also evaluates both ends).
fn golden_max(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (a, b);
    let mut best = f(a).max(f(b));
    let mut x1 = b - r * (b - a);
    let mut x2 = a + r * (b - a);
    let mut f1 = f(x1);
    let mut f2 = f(x2);
    for _ in 0..60 {
        if b - a <= 1e-13 * b.abs().max(1e-12) {
            break;
        }
        if f1 >= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - r * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + r * (b - a);
            f2 = f(x2);
        }
    }
    best = best.max(f1).max(f2);
    best
}

/// Maximum contact force and maximum separation gap (max of −δ over separated phases; 0 if the
/// wheel never separates) over [0, t_end], plus all events. Every accepted step is scanned at
/// 9 dense-output points; the steps whose scan lies within 1 % of the running maximum are then
/// refined by golden-section search on fresh Dormand–Prince steps from the step start.
pub fn extremes(case: &TensionlessCase, t_end: f64, rtol: f64) -> (f64, f64, Vec<ContactEvent>) {
    assert!(
        case.start_position <= 0.0,
        "the equilibrium start requires x0 ≤ 0"
    );
    let model = Tensionless::new(case);
    let y0 = model.pack(&case.equilibrium_state());
    let law = |d: f64| case.contact_law(d);
    let margin = |best: f64| 1e-2 * best.abs();
    let mut buf = vec![0.0; model.dim()];
    let mut force_cands: Vec<Candidate> = Vec::new();
    let mut gap_cands: Vec<Candidate> = Vec::new();
    let (mut best_f, mut best_g) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut observer = |step: &StepData| {
        let (mut imax, mut vmax) = (0usize, f64::NEG_INFINITY);
        for i in 0..=SCAN_SAMPLES {
            let theta = i as f64 / SCAN_SAMPLES as f64;
            step.dense(theta, &mut buf);
            let d = model
                .compression(step.time(theta), &buf, step.phase.region)
                .unwrap_or(0.0);
            let v = if step.phase.contact { law(d) } else { -d };
            if v > vmax {
                vmax = v;
                imax = i;
            }
        }
        let (best, cands) = if step.phase.contact {
            (&mut best_f, &mut force_cands)
        } else {
            (&mut best_g, &mut gap_cands)
        };
        if vmax >= *best - margin(*best) {
            cands.push(Candidate {
                step: step.clone(),
                index: imax,
                value: vmax,
            });
            *best = best.max(vmax);
        }
    };
    let (events, _) = run(&model, y0, 0.0, t_end, rtol, &mut observer);

    let atol = model.abs_tol(rtol);
    let mut ws = Workspace::new(model.dim());
    let mut refine = |cands: &[Candidate], best: f64, force: bool| -> f64 {
        let mut out = f64::NEG_INFINITY;
        for cand in cands.iter().filter(|c| c.value >= best - margin(best)) {
            let s = &cand.step;
            let m = SCAN_SAMPLES as f64;
            let a = (cand.index.saturating_sub(1)) as f64 / m * s.h;
            let b = ((cand.index + 1).min(SCAN_SAMPLES)) as f64 / m * s.h;
            let value = golden_max(
                |tau| {
                    let y = s.fresh(&model, tau, &mut ws, &atol, rtol);
                    let d = model
                        .compression(s.t0 + tau, y, s.phase.region)
                        .unwrap_or(0.0);
                    if force { law(d) } else { -d }
                },
                a,
                b,
            );
            out = out.max(value);
        }
        out
    };
    let max_force = if force_cands.is_empty() {
        0.0
    } else {
        refine(&force_cands, best_f, true).max(0.0)
    };
    let max_gap = if gap_cands.is_empty() {
        0.0
    } else {
        refine(&gap_cands, best_g, false).max(0.0)
    };
    (max_force, max_gap, events)
}
