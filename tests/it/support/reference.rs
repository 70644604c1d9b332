//! Independent reference solutions ("oracles") for vehicle–bridge interaction tests.
//!
//! Everything in this file is written from textbook mathematics and uses only `std`;
//! it deliberately shares no code with the simulator under test.  All quantities are
//! SI: metres, seconds, kilograms, newtons, N·m² for bending stiffness `EI`, kg/m for
//! the mass per unit length `m`, hertz for frequencies returned as `f`, rad/s for
//! circular frequencies `ω`.
//!
//! Contents
//!
//! 1. [`continuous_beam_frequencies`] — exact natural frequencies of a uniform
//!    Euler–Bernoulli beam continuous over any number of pinned supports
//!    (transcendental frequency determinant, scanned and bisected).
//! 2. [`moving_force_deflection`], [`moving_force_max_midspan`] — closed-form modal
//!    solution for a constant force crossing a simply supported beam
//!    (Frýba, *Vibration of Solids and Structures under Moving Loads*, 3rd ed., 1999,
//!    ch. 1 "moving constant force", generalised to modal damping).
//! 3. [`sprung_mass_reference`] — a sprung mass (single-DOF vehicle) crossing a simply
//!    supported beam, analytic sine modes integrated with classical RK4
//!    (model of Yang & Yau, *J. Struct. Eng.* 123(11), 1997, pp. 1512–1518,
//!    example case in [`yang_yau_1997`]).
//!
//! Sign conventions differ between parts 2 and 3 on purpose (they follow the briefs
//! of each oracle): part 2 reports deflection **positive downward**, part 3 reports all
//! vertical coordinates **positive upward**.  Each function's documentation repeats
//! its convention.

use std::f64::consts::PI;

/// Acceleration of gravity used by the sprung-mass oracle, m/s².
#[allow(dead_code)]
pub const GRAVITY: f64 = 9.81;

// ---------------------------------------------------------------------------------
// Small dense linear algebra
// ---------------------------------------------------------------------------------

/// Determinant of a dense row-major `n × n` matrix by Gaussian elimination with
/// partial pivoting (LU).  The matrix is overwritten.
///
/// det A = (−1)^(number of row swaps) · Π U_kk.
#[allow(dead_code)]
pub fn determinant(a: &mut [f64], n: usize) -> f64 {
    assert_eq!(a.len(), n * n, "determinant: matrix must be n×n");
    let mut det = 1.0;
    for k in 0..n {
        // Pivot: largest magnitude in column k at or below the diagonal.
        let mut p = k;
        let mut best = a[k * n + k].abs();
        for r in (k + 1)..n {
            let v = a[r * n + k].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        if best == 0.0 {
            return 0.0;
        }
        if p != k {
            for c in 0..n {
                a.swap(k * n + c, p * n + c);
            }
            det = -det;
        }
        let pivot = a[k * n + k];
        det *= pivot;
        for r in (k + 1)..n {
            let factor = a[r * n + k] / pivot;
            if factor != 0.0 {
                for c in (k + 1)..n {
                    a[r * n + c] -= factor * a[k * n + c];
                }
            }
        }
    }
    det
}

// ---------------------------------------------------------------------------------
// Part 1: continuous beams on pinned supports
// ---------------------------------------------------------------------------------

/// Circular frequency ω_j (rad/s) of mode `j` (1-based) of a simply supported
/// Euler–Bernoulli beam: ω_j = (jπ/L)² √(EI/m).
///
/// Source: any vibration textbook, e.g. Clough & Penzien, *Dynamics of Structures*,
/// ch. on distributed-parameter systems; Frýba (1999) ch. 1.
#[allow(dead_code)]
pub fn simply_supported_circular_frequency(
    j: usize,
    length: f64,
    bending_stiffness: f64,
    mass_per_length: f64,
) -> f64 {
    let k = j as f64 * PI / length;
    k * k * (bending_stiffness / mass_per_length).sqrt()
}

/// Static midspan deflection of a simply supported beam under a central point load,
/// `P L³ / (48 EI)` (m, in the direction of the load).
#[allow(dead_code)]
pub fn static_midspan_deflection(force: f64, length: f64, bending_stiffness: f64) -> f64 {
    force * length.powi(3) / (48.0 * bending_stiffness)
}

/// One row of the span basis evaluated at local coordinate `xi ∈ [0, L]`.
///
/// The span basis is {sin βξ, cos βξ, e^{−βξ}, e^{−β(L−ξ)}}, which spans the same space
/// as {sin, cos, sinh, cosh} for β > 0 but is bounded by 1 for any βL (no overflow).
/// `deriv` = 0, 1, 2 returns w, w'/β, w''/β² (rows scaled by positive factors, which
/// does not move the zeros or change the sign pattern of the determinant).
#[allow(dead_code)]
fn span_basis_row(beta: f64, length: f64, xi: f64, deriv: usize) -> [f64; 4] {
    let (s, c) = (beta * xi).sin_cos();
    let e0 = (-beta * xi).exp();
    let e1 = (-beta * (length - xi)).exp();
    match deriv {
        0 => [s, c, e0, e1],
        1 => [c, -s, -e0, e1],
        2 => [-s, -c, e0, e1],
        _ => unreachable!("only w, w', w'' are needed"),
    }
}

/// Frequency determinant of the continuous beam as a function of the wavenumber β
/// (1/m), with β⁴ = ω² m / EI.  Real, continuous for β > 0, and zero exactly at the
/// natural frequencies.
#[allow(dead_code)]
fn continuous_beam_determinant(spans: &[f64], beta: f64, work: &mut Vec<f64>) -> f64 {
    let n = spans.len();
    let dim = 4 * n;
    work.clear();
    work.resize(dim * dim, 0.0);
    let mut row = 0;
    let put = |work: &mut Vec<f64>, row: usize, span: usize, vals: [f64; 4], sign: f64| {
        for (k, v) in vals.iter().enumerate() {
            work[row * dim + 4 * span + k] += sign * v;
        }
    };
    // Zero deflection at both ends of every span.
    for (i, &l) in spans.iter().enumerate() {
        put(work, row, i, span_basis_row(beta, l, 0.0, 0), 1.0);
        row += 1;
        put(work, row, i, span_basis_row(beta, l, l, 0), 1.0);
        row += 1;
    }
    // Zero moment at the two outer ends.
    put(work, row, 0, span_basis_row(beta, spans[0], 0.0, 2), 1.0);
    row += 1;
    let last = n - 1;
    put(
        work,
        row,
        last,
        span_basis_row(beta, spans[last], spans[last], 2),
        1.0,
    );
    row += 1;
    // Continuity of slope and moment at interior supports.
    for i in 0..last {
        let (l, r) = (spans[i], spans[i + 1]);
        for deriv in [1, 2] {
            put(work, row, i, span_basis_row(beta, l, l, deriv), 1.0);
            put(work, row, i + 1, span_basis_row(beta, r, 0.0, deriv), -1.0);
            row += 1;
        }
    }
    debug_assert_eq!(row, dim);
    determinant(work, dim)
}

/// First `count` natural frequencies (Hz, sorted ascending) of a uniform
/// Euler–Bernoulli beam continuous over pinned supports.
///
/// * `spans` — span lengths L_1 … L_n (m), n ≥ 1; supports at both outer ends and
///   between consecutive spans.
/// * `bending_stiffness` — EI (N·m²); `mass_per_length` — m (kg/m).
///
/// Boundary/continuity conditions: w = 0 at every support; at interior supports the
/// slope w' and the bending moment −EI w'' are continuous (rotation free); w'' = 0 at
/// the two outer ends.
///
/// Method (classical transcendental "frequency determinant", e.g. Blevins, *Formulas
/// for Natural Frequency and Mode Shape*, ch. on beams; Gorman, *Free Vibration Analysis of
/// Beams and Shafts*, ch. 1): in every span w(ξ) = A sin βξ + B cos βξ + C sinh βξ +
/// D cosh βξ with β⁴ = ω² m/EI.  The 4n conditions above give a 4n × 4n homogeneous
/// system whose determinant vanishes at the natural frequencies.  To keep all
/// entries O(1) for any βL the hyperbolic pair is replaced by the equivalent
/// {e^{−βξ}, e^{−β(L−ξ)}}; slope rows are divided by β and moment rows by β².  The
/// determinant is then a bounded continuous function of β > 0 without poles.
///
/// It is scanned from β = 0.5π/L_max (below the lowest root: by the Rayleigh
/// quotient the fundamental is not lower than the simply supported frequency of the
/// longest span) with step Δβ = 10⁻⁴ π/L_max; every sign change is refined by
/// bisection to |Δβ| ≤ 10⁻¹⁴ β (≈ 2·10⁻¹⁴ relative in f since f ∝ β²).
/// Then f = β² √(EI/m) / (2π).
///
/// Limitation: two roots closer than Δβ would be missed; for realistic span ratios
/// the root spacing is orders of magnitude larger (n equal spans give clusters of n
/// roots spread over Δ(βL) ≈ 1.6).
#[allow(dead_code)]
pub fn continuous_beam_frequencies(
    spans: &[f64],
    bending_stiffness: f64,
    mass_per_length: f64,
    count: usize,
) -> Vec<f64> {
    assert!(!spans.is_empty(), "at least one span is required");
    assert!(
        spans.iter().all(|&l| l > 0.0 && l.is_finite()),
        "span lengths must be positive"
    );
    assert!(bending_stiffness > 0.0 && mass_per_length > 0.0);
    if count == 0 {
        return Vec::new();
    }
    let l_max = spans.iter().cloned().fold(0.0, f64::max);
    let l_min = spans.iter().cloned().fold(f64::INFINITY, f64::min);
    let step = 1e-4 * PI / l_max;
    // Upper bound for the count-th root: adding clamps at every support only raises
    // frequencies; the count-th clamped-clamped root of the shortest span satisfies
    // βL < (count + 1)π.  A generous margin is added.
    let beta_cap = (count as f64 + 2.0) * PI / l_min;

    let mut work = Vec::new();
    let mut det = |b: f64| continuous_beam_determinant(spans, b, &mut work);

    let mut betas = Vec::with_capacity(count);
    let mut b_prev = 0.5 * PI / l_max;
    let mut f_prev = det(b_prev);
    let mut k: u64 = 1;
    while betas.len() < count {
        let b = 0.5 * PI / l_max + k as f64 * step;
        assert!(
            b <= beta_cap,
            "continuous_beam_frequencies: root search exceeded its bound"
        );
        let f = det(b);
        if f_prev == 0.0 {
            // root already recorded at b_prev
        } else if f == 0.0 {
            betas.push(b);
        } else if (f_prev < 0.0) != (f < 0.0) {
            // Bisection on [b_prev, b].
            let (mut lo, mut hi, mut f_lo) = (b_prev, b, f_prev);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if hi - lo <= 1e-14 * hi || mid <= lo || mid >= hi {
                    break;
                }
                let fm = det(mid);
                if fm == 0.0 {
                    lo = mid;
                    hi = mid;
                    break;
                }
                if (fm < 0.0) == (f_lo < 0.0) {
                    lo = mid;
                    f_lo = fm;
                } else {
                    hi = mid;
                }
            }
            betas.push(0.5 * (lo + hi));
        }
        b_prev = b;
        f_prev = f;
        k += 1;
    }
    let c = (bending_stiffness / mass_per_length).sqrt() / (2.0 * PI);
    betas.iter().map(|b| b * b * c).collect()
}

// ---------------------------------------------------------------------------------
// Minimal complex arithmetic (for the closed-form Duhamel integrals of part 2)
// ---------------------------------------------------------------------------------

#[allow(dead_code)]
#[derive(Clone, Copy, Debug)]
struct Cx {
    re: f64,
    im: f64,
}

#[allow(dead_code)]
impl Cx {
    fn new(re: f64, im: f64) -> Self {
        Cx { re, im }
    }
    fn add(self, o: Cx) -> Cx {
        Cx::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: Cx) -> Cx {
        Cx::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: Cx) -> Cx {
        Cx::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn scale(self, k: f64) -> Cx {
        Cx::new(self.re * k, self.im * k)
    }
    fn div(self, o: Cx) -> Cx {
        let d = o.re * o.re + o.im * o.im;
        Cx::new(
            (self.re * o.re + self.im * o.im) / d,
            (self.im * o.re - self.re * o.im) / d,
        )
    }
    fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }
    fn exp(self) -> Cx {
        let r = self.re.exp();
        let (s, c) = self.im.sin_cos();
        Cx::new(r * c, r * s)
    }
}

/// I(s, p, t) = ∫₀ᵗ e^{s(t−τ)} e^{pτ} dτ = (e^{pt} − e^{st}) / (p − s), evaluated
/// without cancellation: for |z| = |(p − s)t| < 1/2 as t e^{st} Σ_k z^k/(k+1)!.
#[allow(dead_code)]
fn exp_convolution(s: Cx, p: Cx, t: f64) -> Cx {
    let d = p.sub(s);
    let z = d.scale(t);
    if z.abs() < 0.5 {
        // φ₁(z) = (e^z − 1)/z = Σ_{k≥0} z^k/(k+1)!; 25 terms ⇒ error < 0.5²⁵/26! .
        let mut term = Cx::new(1.0, 0.0);
        let mut sum = term;
        for k in 1..25 {
            term = term.mul(z).scale(1.0 / (k as f64 + 1.0));
            sum = sum.add(term);
        }
        s.scale(t).exp().mul(sum).scale(t)
    } else {
        p.scale(t).exp().sub(s.scale(t).exp()).div(d)
    }
}

/// Exact response (q, q̇) at time t ≥ 0 of q̈ + 2ζωq̇ + ω²q = f₀ sin(Ωt), q(0) = q̇(0) = 0.
///
/// Duhamel: q(t) = ∫₀ᵗ h(t−τ) f₀ sin Ωτ dτ with h(u) = e^{−ζωu} sin(ω_d u)/ω_d,
/// ω_d = ω√(1−ζ²).  Writing s = −ζω + iω_d, h(u) = Im e^{su}/ω_d and
/// sin Ωτ = Im e^{iΩτ} gives
///   q = −f₀/(2ω_d) · Re[I(s, iΩ, t) − I(s, −iΩ, t)],
///   q̇ = −f₀/(2ω_d) · Re[s (I(s, iΩ, t) − I(s, −iΩ, t))]   (h(0) = 0),
/// with I from [`exp_convolution`].  This is algebraically identical to the textbook
/// "steady-state particular solution + homogeneous solution fitted to zero initial
/// conditions" (Frýba 1999 ch. 1 for ζ = 0; Clough & Penzien, harmonic loading of a
/// damped SDOF system),
/// but stays exact at and near resonance (Ω = ω_d, ζ = 0).  Requires 0 ≤ ζ < 1.
#[allow(dead_code)]
fn sdof_sine_response(omega: f64, zeta: f64, big_omega: f64, f0: f64, t: f64) -> (f64, f64) {
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let s = Cx::new(-zeta * omega, wd);
    let d = exp_convolution(s, Cx::new(0.0, big_omega), t).sub(exp_convolution(
        s,
        Cx::new(0.0, -big_omega),
        t,
    ));
    let k = -f0 / (2.0 * wd);
    (k * d.re, k * s.mul(d).re)
}

/// Exact damped free vibration: state after time `tau` ≥ 0 starting from (q₀, q̇₀):
/// q = e^{−ζωτ}[q₀ cos ω_dτ + (q̇₀ + ζωq₀)/ω_d sin ω_dτ]  (damped free vibration, Clough & Penzien).
#[allow(dead_code)]
fn sdof_free_response(omega: f64, zeta: f64, q0: f64, v0: f64, tau: f64) -> f64 {
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let (s, c) = (wd * tau).sin_cos();
    (-zeta * omega * tau).exp() * (q0 * c + (v0 + zeta * omega * q0) / wd * s)
}

// ---------------------------------------------------------------------------------
// Part 2: moving constant force on a simply supported beam (Frýba)
// ---------------------------------------------------------------------------------

/// Simply supported beam crossed by a constant force (Frýba's problem).
#[allow(dead_code)]
#[derive(Clone, Copy, Debug)]
pub struct MovingForceBeam {
    /// Span length L (m).
    pub length: f64,
    /// Bending stiffness EI (N·m²).
    pub bending_stiffness: f64,
    /// Mass per unit length m (kg/m).
    pub mass_per_length: f64,
    /// Modal damping ratio ζ (–), identical for all modes, 0 ≤ ζ < 1.
    pub damping_ratio: f64,
    /// Force magnitude P (N), acting downward.
    pub force: f64,
    /// Constant speed v (m/s) > 0; the force enters at x = 0 at t = 0.
    pub speed: f64,
}

#[allow(dead_code)]
impl MovingForceBeam {
    /// Time at which the force leaves the beam, L/v (s).
    pub fn crossing_time(&self) -> f64 {
        self.length / self.speed
    }
    /// First natural frequency f₁ = (π/L)² √(EI/m) / (2π) (Hz).
    pub fn first_frequency(&self) -> f64 {
        simply_supported_circular_frequency(
            1,
            self.length,
            self.bending_stiffness,
            self.mass_per_length,
        ) / (2.0 * PI)
    }
    /// Speed parameter α = ω/ω₁ with ω = πv/L (Frýba 1999 ch. 1), i.e. α = v/(2 f₁ L).
    pub fn speed_parameter(&self) -> f64 {
        self.speed / (2.0 * self.first_frequency() * self.length)
    }
    /// Static midspan deflection under P at midspan, P L³/(48 EI) (m).
    pub fn static_midspan_deflection(&self) -> f64 {
        static_midspan_deflection(self.force, self.length, self.bending_stiffness)
    }
}

/// Modal coordinate q_j(t) (m, positive downward) of the moving-force problem.
#[allow(dead_code)]
fn moving_force_modal_coordinate(j: usize, t: f64, p: &MovingForceBeam) -> f64 {
    if t <= 0.0 {
        return 0.0;
    }
    let l = p.length;
    let omega = simply_supported_circular_frequency(j, l, p.bending_stiffness, p.mass_per_length);
    let big_omega = j as f64 * PI * p.speed / l;
    let f0 = 2.0 * p.force / (p.mass_per_length * l);
    let t_exit = l / p.speed;
    if t <= t_exit {
        sdof_sine_response(omega, p.damping_ratio, big_omega, f0, t).0
    } else {
        let (q0, v0) = sdof_sine_response(omega, p.damping_ratio, big_omega, f0, t_exit);
        sdof_free_response(omega, p.damping_ratio, q0, v0, t - t_exit)
    }
}

/// Deflection w(x, t) (m, **positive downward**, i.e. in the direction of the force)
/// of a simply supported beam traversed by a constant force, by exact modal
/// superposition over the first `modes` sine modes.
///
/// Model (Frýba, *Vibration of Solids and Structures under Moving Loads*, 3rd ed.
/// 1999, ch. 1):
/// EI w'''' + m ẅ + 2mω_b ẇ = δ(x − vt) P for 0 ≤ vt ≤ L, replaced here by modal
/// damping ζ (same in every mode):
///
/// w(x,t) = Σ_j q_j(t) sin(jπx/L),  ω_j = (jπ/L)² √(EI/m),
/// q̈_j + 2ζω_j q̇_j + ω_j² q_j = (2P/(mL)) sin(jπvt/L)  for 0 ≤ t ≤ L/v, 0 afterwards,
/// q_j(0) = q̇_j(0) = 0.
///
/// Each mode is solved in closed form (`sdof_sine_response` during the crossing,
/// exact damped free vibration from the exit state afterwards).  Valid for
/// x ∈ [0, L], any t (w = 0 for t ≤ 0), 0 ≤ ζ < 1.
#[allow(dead_code)]
pub fn moving_force_deflection(x: f64, t: f64, p: &MovingForceBeam, modes: usize) -> f64 {
    assert!(p.length > 0.0 && p.speed > 0.0 && p.bending_stiffness > 0.0);
    assert!(p.mass_per_length > 0.0);
    assert!(
        (0.0..1.0).contains(&p.damping_ratio),
        "damping ratio must satisfy 0 ≤ ζ < 1"
    );
    (1..=modes)
        .map(|j| moving_force_modal_coordinate(j, t, p) * (j as f64 * PI * x / p.length).sin())
        .sum()
}

/// Modal displacement, velocity and acceleration (q_j, q̇_j, q̈_j) of the moving-force
/// problem: during the crossing the closed-form forced response and its derivative,
/// afterwards the damped free vibration from the exit state and its derivative; q̈_j
/// then follows from the modal equation itself, q̈ = (2P/(mL)) sin(jπvt/L) − 2ζωq̇ − ω²q
/// (the force term only while 0 < t < L/v) — the second time derivative of the
/// closed form, without differencing.
#[allow(dead_code)]
fn moving_force_modal_state(j: usize, t: f64, p: &MovingForceBeam) -> (f64, f64, f64) {
    if t <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let l = p.length;
    let zeta = p.damping_ratio;
    let omega = simply_supported_circular_frequency(j, l, p.bending_stiffness, p.mass_per_length);
    let big_omega = j as f64 * PI * p.speed / l;
    let f0 = 2.0 * p.force / (p.mass_per_length * l);
    let t_exit = l / p.speed;
    let (q, v, force) = if t < t_exit {
        let (q, v) = sdof_sine_response(omega, zeta, big_omega, f0, t);
        (q, v, f0 * (big_omega * t).sin())
    } else {
        let (q0, v0) = sdof_sine_response(omega, zeta, big_omega, f0, t_exit);
        let tau = t - t_exit;
        let wd = omega * (1.0 - zeta * zeta).sqrt();
        let (s, c) = (wd * tau).sin_cos();
        let b = (v0 + zeta * omega * q0) / wd;
        let decay = (-zeta * omega * tau).exp();
        let q = decay * (q0 * c + b * s);
        let v = decay * (-zeta * omega * (q0 * c + b * s) + wd * (b * c - q0 * s));
        (q, v, 0.0)
    };
    (q, v, force - 2.0 * zeta * omega * v - omega * omega * q)
}

/// Acceleration ẅ(x, t) (m/s², **positive downward**) of the moving-force problem of
/// [`moving_force_deflection`], over the first `modes` sine modes.
#[allow(dead_code)]
pub fn moving_force_acceleration(x: f64, t: f64, p: &MovingForceBeam, modes: usize) -> f64 {
    (1..=modes)
        .map(|j| moving_force_modal_state(j, t, p).2 * (j as f64 * PI * x / p.length).sin())
        .sum()
}

/// Maximum over t ∈ [0, t_end] of the midspan deflection (positive downward, m) of the
/// moving-force problem, and the time (s) at which it occurs: `(w_max, t_max)`.
///
/// Search: uniform grid of N + 1 samples with N = max(20 000, ⌈20 f₁ t_end⌉) (capped at
/// 2·10⁶), then golden-section maximisation on the two grid intervals around the best
/// sample until the bracket is below 10⁻¹⁰ · max(t, t_end·10⁻³).  Because the maximum is
/// flat, the returned time is only accurate to ≈ √ε relative; the value is accurate to
/// rounding.
#[allow(dead_code)]
pub fn moving_force_max_midspan(p: &MovingForceBeam, modes: usize, t_end: f64) -> (f64, f64) {
    assert!(t_end > 0.0, "t_end must be positive");
    let x = 0.5 * p.length;
    let f = |t: f64| moving_force_deflection(x, t, p, modes);
    let n = ((20.0 * p.first_frequency() * t_end).ceil() as usize).clamp(20_000, 2_000_000);
    let dt = t_end / n as f64;
    let (mut best_i, mut best_v) = (0usize, f(0.0));
    for i in 1..=n {
        let v = f(i as f64 * dt);
        if v > best_v {
            best_v = v;
            best_i = i;
        }
    }
    let mut a = best_i.saturating_sub(1) as f64 * dt;
    let mut b = ((best_i + 1).min(n)) as f64 * dt;
    let g = 0.5 * (5f64.sqrt() - 1.0); // 0.618…
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    let tol_floor = 1e-3 * t_end;
    for _ in 0..300 {
        if b - a <= 1e-10 * (0.5 * (a + b)).max(tol_floor) {
            break;
        }
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    let tm = 0.5 * (a + b);
    let vm = f(tm);
    // Never return something worse than the best grid sample (e.g. endpoint maxima).
    if vm >= best_v {
        (vm, tm)
    } else {
        (best_v, best_i as f64 * dt)
    }
}

// ---------------------------------------------------------------------------------
// Part 3: sprung mass crossing a simply supported beam (Yang & Yau 1997)
// ---------------------------------------------------------------------------------

/// Sprung-mass (one-DOF vehicle) crossing a simply supported beam.
#[allow(dead_code)]
#[derive(Clone, Copy, Debug)]
pub struct SprungMassCase {
    /// Span length L (m).
    pub length: f64,
    /// Bending stiffness EI (N·m²).
    pub bending_stiffness: f64,
    /// Beam mass per unit length m (kg/m).
    pub mass_per_length: f64,
    /// Modal damping ratio ζ of the beam (–), same for all modes.
    pub damping_ratio: f64,
    /// Sprung mass M_v (kg).
    pub vehicle_mass: f64,
    /// Suspension spring stiffness k_v (N/m).
    pub vehicle_stiffness: f64,
    /// Suspension dashpot c_v (N·s/m).
    pub vehicle_damping: f64,
    /// Constant speed v (m/s) > 0; the wheel is at x = 0 at t = 0.
    pub speed: f64,
}

#[allow(dead_code)]
impl SprungMassCase {
    /// Time at which the wheel leaves the beam, L/v (s).
    pub fn crossing_time(&self) -> f64 {
        self.length / self.speed
    }
}

/// Time histories produced by [`sprung_mass_reference`].  All vectors have the same
/// length; entry 0 is t = 0.  Vertical quantities are **positive upward**.
#[allow(dead_code)]
#[derive(Clone, Debug, Default)]
pub struct SprungMassHistory {
    /// Sample times (s).
    pub time: Vec<f64>,
    /// Beam deflection at x = L/2 (m, positive upward; negative when sagging).
    pub midspan_deflection: Vec<f64>,
    /// Beam deflection under the wheel w_c = w(vt, t) (m, positive upward); 0 after the
    /// exit (rigid ground).
    pub contact_deflection: Vec<f64>,
    /// Sprung-mass displacement y from its static equilibrium on rigid ground (m, up).
    pub vehicle_displacement: Vec<f64>,
    /// Sprung-mass acceleration ÿ (m/s², up).
    pub vehicle_acceleration: Vec<f64>,
    /// Wheel contact force F = M_v g + k_v(w_c − y) + c_v(ẇ_c − ẏ) = M_v (g + ÿ) (N,
    /// compression positive).  While 0 ≤ t ≤ L/v it is the force pushing down on the
    /// beam; after the exit it is the force on the rigid ground (w_c = 0).
    pub contact_force: Vec<f64>,
}

/// Yang & Yau (1997) benchmark: L = 25 m, E = 2.87 GPa, I = 2.9 m⁴ (EI = 8.323·10⁹ N·m²),
/// m = 2303 kg/m, M_v = 5750 kg, k_v = 1595 kN/m, c_v = 0, v = 100 km/h, ζ = 0.
///
/// Source: Y.B. Yang, J.D. Yau, "Vehicle-bridge interaction element for dynamic
/// analysis", *J. Struct. Eng.* 123(11):1512–1518, 1997 (also Yang, Yau & Wu,
/// *Vehicle–Bridge Interaction Dynamics*, World Scientific 2004, §2).
#[allow(dead_code)]
pub fn yang_yau_1997() -> SprungMassCase {
    SprungMassCase {
        length: 25.0,
        bending_stiffness: 2.87e9 * 2.9,
        mass_per_length: 2303.0,
        damping_ratio: 0.0,
        vehicle_mass: 5750.0,
        vehicle_stiffness: 1595e3,
        vehicle_damping: 0.0,
        speed: 100.0 / 3.6,
    }
}

/// Precomputed modal data for the sprung-mass right-hand side.
#[allow(dead_code)]
struct SprungMassModel {
    case: SprungMassCase,
    omega: Vec<f64>,
    /// jπ/L
    wavenumber: Vec<f64>,
}

/// Interaction quantities at the contact point for a given state.
#[allow(dead_code)]
struct ContactState {
    /// w_c (m)
    deflection: f64,
    /// ÿ (m/s²)
    vehicle_acceleration: f64,
    /// F (N), compression positive
    contact_force: f64,
}

#[allow(dead_code)]
impl SprungMassModel {
    fn new(case: &SprungMassCase, modes: usize) -> Self {
        let omega = (1..=modes)
            .map(|j| {
                simply_supported_circular_frequency(
                    j,
                    case.length,
                    case.bending_stiffness,
                    case.mass_per_length,
                )
            })
            .collect();
        let wavenumber = (1..=modes).map(|j| j as f64 * PI / case.length).collect();
        SprungMassModel {
            case: *case,
            omega,
            wavenumber,
        }
    }

    fn modes(&self) -> usize {
        self.omega.len()
    }

    /// Contact quantities.  `on_bridge` selects the interaction phase; off the bridge
    /// the wheel rides rigid ground (w_c = ẇ_c = 0).  `shapes` receives sin(jπx_v/L).
    fn contact(&self, t: f64, state: &[f64], on_bridge: bool, shapes: &mut [f64]) -> ContactState {
        let n = self.modes();
        let c = &self.case;
        let (y, yd) = (state[2 * n], state[2 * n + 1]);
        let (mut wc, mut wcd) = (0.0, 0.0);
        if on_bridge {
            let xv = c.speed * t;
            for j in 0..n {
                let (s, co) = (self.wavenumber[j] * xv).sin_cos();
                shapes[j] = s;
                let (q, qd) = (state[j], state[n + j]);
                wc += q * s;
                // total derivative: ∂w/∂t + v ∂w/∂x
                wcd += qd * s + q * self.wavenumber[j] * c.speed * co;
            }
        } else {
            shapes.iter_mut().for_each(|s| *s = 0.0);
        }
        let rel = c.vehicle_stiffness * (wc - y) + c.vehicle_damping * (wcd - yd);
        ContactState {
            deflection: wc,
            vehicle_acceleration: rel / c.vehicle_mass,
            contact_force: c.vehicle_mass * GRAVITY + rel,
        }
    }

    /// State derivative. State layout: [q_1..q_N, q̇_1..q̇_N, y, ẏ].
    fn rhs(&self, t: f64, state: &[f64], on_bridge: bool, shapes: &mut [f64], out: &mut [f64]) {
        let n = self.modes();
        let c = &self.case;
        let cs = self.contact(t, state, on_bridge, shapes);
        let beam_force = if on_bridge { cs.contact_force } else { 0.0 };
        let modal_load = 2.0 / (c.mass_per_length * c.length);
        for j in 0..n {
            let (q, qd) = (state[j], state[n + j]);
            let w = self.omega[j];
            out[j] = qd;
            out[n + j] =
                -2.0 * c.damping_ratio * w * qd - w * w * q - modal_load * beam_force * shapes[j];
        }
        out[2 * n] = state[2 * n + 1];
        out[2 * n + 1] = cs.vehicle_acceleration;
    }
}

/// Midspan value Σ q_j sin(jπ/2), using exact sin(jπ/2) ∈ {0, ±1}.
#[allow(dead_code)]
fn midspan_from_modes(q: &[f64]) -> f64 {
    q.iter()
        .enumerate()
        .map(|(i, &qj)| match (i + 1) % 4 {
            1 => qj,
            3 => -qj,
            _ => 0.0,
        })
        .sum()
}

/// Reference time histories for a sprung mass crossing a simply supported beam.
///
/// Model (Yang & Yau 1997; Yang, Yau & Wu 2004, ch. 2), coordinates **positive
/// upward**, beam w(x,t) = Σ_{j=1}^{N} q_j(t) sin(jπx/L), ω_j = (jπ/L)²√(EI/m),
/// contact point x_v = vt, w_c = w(x_v,t), ẇ_c = ∂w/∂t + v ∂w/∂x at x_v:
///
/// * M_v ÿ = k_v (w_c − y) + c_v (ẇ_c − ẏ)           (y from static equilibrium)
/// * F = M_v g + k_v (w_c − y) + c_v (ẇ_c − ẏ)         (contact force, compression +)
/// * q̈_j + 2ζω_j q̇_j + ω_j² q_j = −(2/(mL)) F sin(jπx_v/L)
///
/// for 0 ≤ t ≤ L/v, with zero initial state (the vehicle starts in static
/// equilibrium over the left support, g = [`GRAVITY`]).  For t > L/v the wheel rides
/// rigid ground (w_c = ẇ_c = 0) and the beam vibrates freely.
///
/// Integration: classical fourth-order Runge–Kutta with constant step
/// h = (L/v)/⌈(L/v)/dt⌉ ≤ dt, so that a step ends exactly at the exit time L/v; after
/// the exit the same h is used and the last step is shortened to land on `t_end`.
/// Every step is recorded.  At t = L/v the recorded acceleration/force are the
/// on-bridge (left) limits.  RK4 is stable for ω_N h < 2.78; for accuracy keep
/// ω_N h ≲ 0.5 (N = `modes`).
#[allow(dead_code)]
pub fn sprung_mass_reference(
    case: &SprungMassCase,
    modes: usize,
    dt: f64,
    t_end: f64,
) -> SprungMassHistory {
    assert!(modes >= 1 && dt > 0.0 && t_end >= 0.0);
    assert!(case.length > 0.0 && case.speed > 0.0 && case.vehicle_mass > 0.0);
    assert!(case.bending_stiffness > 0.0 && case.mass_per_length > 0.0);
    let model = SprungMassModel::new(case, modes);
    let n = modes;
    let dim = 2 * n + 2;
    let t_exit = case.crossing_time();
    let ratio = t_exit / dt;
    let steps_on = if (ratio - ratio.round()).abs() < 1e-9 * ratio.max(1.0) {
        ratio.round()
    } else {
        ratio.ceil()
    }
    .max(1.0) as usize;
    let h = t_exit / steps_on as f64;

    let mut state = vec![0.0; dim];
    let mut shapes = vec![0.0; n];
    let mut k1 = vec![0.0; dim];
    let mut k2 = vec![0.0; dim];
    let mut k3 = vec![0.0; dim];
    let mut k4 = vec![0.0; dim];
    let mut tmp = vec![0.0; dim];
    let mut hist = SprungMassHistory::default();

    let record = |hist: &mut SprungMassHistory, t: f64, state: &[f64], on: bool| {
        let mut sh = vec![0.0; n];
        let cs = model.contact(t, state, on, &mut sh);
        let (acc, force) = if on {
            (cs.vehicle_acceleration, cs.contact_force)
        } else {
            // rigid ground: same expressions with w_c = ẇ_c = 0
            (
                cs.vehicle_acceleration,
                case.vehicle_mass * (GRAVITY + cs.vehicle_acceleration),
            )
        };
        hist.time.push(t);
        hist.midspan_deflection
            .push(midspan_from_modes(&state[..n]));
        hist.contact_deflection.push(cs.deflection);
        hist.vehicle_displacement.push(state[2 * n]);
        hist.vehicle_acceleration.push(acc);
        hist.contact_force.push(force);
    };

    let mut rk4 = |t: f64, hh: f64, on: bool, state: &mut Vec<f64>| {
        model.rhs(t, state, on, &mut shapes, &mut k1);
        for i in 0..dim {
            tmp[i] = state[i] + 0.5 * hh * k1[i];
        }
        model.rhs(t + 0.5 * hh, &tmp, on, &mut shapes, &mut k2);
        for i in 0..dim {
            tmp[i] = state[i] + 0.5 * hh * k2[i];
        }
        model.rhs(t + 0.5 * hh, &tmp, on, &mut shapes, &mut k3);
        for i in 0..dim {
            tmp[i] = state[i] + hh * k3[i];
        }
        model.rhs(t + hh, &tmp, on, &mut shapes, &mut k4);
        for i in 0..dim {
            state[i] += hh / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    };

    record(&mut hist, 0.0, &state, true);
    let eps_t = 1e-9 * h;
    // Phase 1: wheel on the beam.
    for i in 0..steps_on {
        let t0 = i as f64 * h;
        if t0 >= t_end - eps_t {
            return hist;
        }
        let t1 = if i + 1 == steps_on {
            t_exit
        } else {
            (i + 1) as f64 * h
        };
        let t1 = t1.min(t_end);
        rk4(t0, t1 - t0, true, &mut state);
        record(&mut hist, t1, &state, true);
    }
    // Phase 2: wheel on rigid ground, beam in free vibration.
    let mut k: usize = 0;
    loop {
        let t0 = t_exit + k as f64 * h;
        if t0 >= t_end - eps_t {
            break;
        }
        let t1 = (t_exit + (k + 1) as f64 * h).min(t_end);
        rk4(t0, t1 - t0, false, &mut state);
        record(&mut hist, t1, &state, false);
        k += 1;
    }
    hist
}

// ---------------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------------

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
        let mut flo = f(lo);
        assert!(flo * f(hi) < 0.0, "bisect: no bracket");
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let fm = f(mid);
            if (fm < 0.0) == (flo < 0.0) {
                lo = mid;
                flo = fm;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    // ----- linear algebra -----

    #[test]
    fn determinant_small_matrices() {
        let mut a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        // det = 0*(1*1-0*0) - 2*(1*1-0*3) + 1*(1*0-1*3) = -2 - 3 = -5
        assert!((determinant(&mut a, 3) + 5.0).abs() < 1e-14);
        let mut s = vec![1.0, 2.0, 2.0, 4.0];
        assert_eq!(determinant(&mut s, 2), 0.0);
    }

    // ----- part 1 -----

    const EI: f64 = 1e10;
    const M: f64 = 1e4;

    fn ss_freq(j: usize, l: f64) -> f64 {
        simply_supported_circular_frequency(j, l, EI, M) / (2.0 * PI)
    }

    fn beta_l_to_freq(bl: f64, l: f64) -> f64 {
        (bl / l).powi(2) * (EI / M).sqrt() / (2.0 * PI)
    }

    #[test]
    fn single_span_matches_simply_supported_formula() {
        for &l in &[7.5, 30.0] {
            let f = continuous_beam_frequencies(&[l], EI, M, 8);
            assert_eq!(f.len(), 8);
            for (j, fj) in f.iter().enumerate() {
                let exact = ss_freq(j + 1, l);
                assert!(rel(*fj, exact) < 1e-12, "j={} got {fj} want {exact}", j + 1);
            }
        }
    }

    #[test]
    fn two_equal_spans_ss_and_propped_cantilever() {
        // propped cantilever root: tan x = tanh x
        let bl_pc = bisect(|x| x.tan() - x.tanh(), 3.8, 3.95);
        assert!((bl_pc - 3.926_602_312_047_9).abs() < 1e-11);
        let l = 30.0;
        let f = continuous_beam_frequencies(&[l, l], EI, M, 4);
        assert!(rel(f[0], ss_freq(1, l)) < 1e-10);
        assert!(rel(f[1], beta_l_to_freq(bl_pc, l)) < 1e-10);
        // third: second SS mode of one span (2π), fourth: second propped-cantilever root
        let bl_pc2 = bisect(|x| x.tan() - x.tanh(), 7.0, 7.2);
        assert!(rel(f[2], ss_freq(2, l)) < 1e-10);
        assert!(rel(f[3], beta_l_to_freq(bl_pc2, l)) < 1e-10);
    }

    /// n equal spans: periodic-structure result (Miles 1956; Lin 1962).  With the
    /// dynamic rotational stiffnesses a (near end) and b (far end) of a pinned–pinned
    /// span, joint equilibrium gives a/b = −cos(kπ/n), k = 1..n−1, plus the single-span
    /// roots βL = jπ.  a/b = (cosh λ sin λ − sinh λ cos λ)/(sinh λ − sin λ), λ = βL.
    fn equal_span_reference(n: usize, l: f64, count: usize) -> Vec<f64> {
        let ratio = |x: f64| (x.cosh() * x.sin() - x.sinh() * x.cos()) / (x.sinh() - x.sin());
        let mut roots: Vec<f64> = (1..=count).map(|j| j as f64 * PI).collect();
        let x_max = (count as f64 + 1.0) * PI;
        for k in 1..n {
            let target = -(k as f64 * PI / n as f64).cos();
            let g = |x: f64| ratio(x) - target;
            let mut x0 = 0.5;
            let dx = 1e-3;
            while x0 < x_max {
                let x1 = x0 + dx;
                if g(x0) * g(x1) < 0.0 {
                    roots.push(bisect(g, x0, x1));
                }
                x0 = x1;
            }
        }
        roots.sort_by(|a, b| a.partial_cmp(b).unwrap());
        roots
            .into_iter()
            .take(count)
            .map(|bl| beta_l_to_freq(bl, l))
            .collect()
    }

    #[test]
    fn five_equal_spans_match_periodic_structure_theory() {
        let l = 30.0;
        let f = continuous_beam_frequencies(&[l; 5], EI, M, 10);
        let r = equal_span_reference(5, l, 10);
        for (a, b) in f.iter().zip(&r) {
            assert!(rel(*a, *b) < 1e-12, "got {a} want {b}");
        }
        // first cluster of 5 lies in [SS, clamped-clamped) of one span
        let cc = beta_l_to_freq(4.730_040_744_862_704, l);
        for fi in &f[..5] {
            assert!(*fi >= ss_freq(1, l) * (1.0 - 1e-12) && *fi < cc);
        }
        assert!(f[5] > cc);
        // three equal spans too
        let f3 = continuous_beam_frequencies(&[l; 3], EI, M, 6);
        let r3 = equal_span_reference(3, l, 6);
        for (a, b) in f3.iter().zip(&r3) {
            assert!(rel(*a, *b) < 1e-12, "got {a} want {b}");
        }
    }

    fn check_sorted_and_bounded(spans: &[f64], count: usize) {
        let f = continuous_beam_frequencies(spans, EI, M, count);
        assert_eq!(f.len(), count);
        for w in f.windows(2) {
            assert!(w[1] > w[0] * (1.0 + 1e-9), "not strictly increasing: {f:?}");
        }
        let l_max = spans.iter().cloned().fold(0.0, f64::max);
        let lo = ss_freq(1, l_max);
        let hi = beta_l_to_freq(4.730_040_744_862_704, l_max);
        assert!(
            f[0] >= lo * (1.0 - 1e-12) && f[0] < hi,
            "f1 = {} not in [{lo}, {hi})",
            f[0]
        );
    }

    #[test]
    fn three_and_five_spans_sorted_and_bounded() {
        check_sorted_and_bounded(&[24.0, 30.0, 24.0], 6);
        check_sorted_and_bounded(&[30.0; 5], 12);
        check_sorted_and_bounded(&[30.0, 30.0], 6);
    }

    /// Independent cross-check: Hermite-cubic finite elements (consistent mass),
    /// Cholesky reduction to a standard symmetric problem and cyclic Jacobi.
    fn fe_frequencies(spans: &[f64], elements_per_metre: f64, count: usize) -> Vec<f64> {
        // nodes
        let mut x_nodes = vec![0.0];
        let mut support_nodes = vec![0];
        for &l in spans {
            let ne = (l * elements_per_metre).round() as usize;
            let x0 = *x_nodes.last().unwrap();
            for e in 1..=ne {
                x_nodes.push(x0 + l * e as f64 / ne as f64);
            }
            support_nodes.push(x_nodes.len() - 1);
        }
        let nn = x_nodes.len();
        let ndof = 2 * nn;
        let mut kg = vec![0.0; ndof * ndof];
        let mut mg = vec![0.0; ndof * ndof];
        for e in 0..nn - 1 {
            let h = x_nodes[e + 1] - x_nodes[e];
            let ke = [
                [12.0, 6.0 * h, -12.0, 6.0 * h],
                [6.0 * h, 4.0 * h * h, -6.0 * h, 2.0 * h * h],
                [-12.0, -6.0 * h, 12.0, -6.0 * h],
                [6.0 * h, 2.0 * h * h, -6.0 * h, 4.0 * h * h],
            ];
            let me = [
                [156.0, 22.0 * h, 54.0, -13.0 * h],
                [22.0 * h, 4.0 * h * h, 13.0 * h, -3.0 * h * h],
                [54.0, 13.0 * h, 156.0, -22.0 * h],
                [-13.0 * h, -3.0 * h * h, -22.0 * h, 4.0 * h * h],
            ];
            let kf = EI / h.powi(3);
            let mf = M * h / 420.0;
            for a in 0..4 {
                for b in 0..4 {
                    let (ga, gb) = (2 * e + a, 2 * e + b);
                    kg[ga * ndof + gb] += kf * ke[a][b];
                    mg[ga * ndof + gb] += mf * me[a][b];
                }
            }
        }
        let fixed: Vec<usize> = support_nodes.iter().map(|&n| 2 * n).collect();
        let free: Vec<usize> = (0..ndof).filter(|d| !fixed.contains(d)).collect();
        let n = free.len();
        let mut k = vec![0.0; n * n];
        let mut m = vec![0.0; n * n];
        for (i, &gi) in free.iter().enumerate() {
            for (j, &gj) in free.iter().enumerate() {
                k[i * n + j] = kg[gi * ndof + gj];
                m[i * n + j] = mg[gi * ndof + gj];
            }
        }
        // Cholesky M = L Lᵀ (lower, in place)
        for j in 0..n {
            let mut d = m[j * n + j];
            for p in 0..j {
                d -= m[j * n + p] * m[j * n + p];
            }
            let d = d.sqrt();
            m[j * n + j] = d;
            for i in (j + 1)..n {
                let mut s = m[i * n + j];
                for p in 0..j {
                    s -= m[i * n + p] * m[j * n + p];
                }
                m[i * n + j] = s / d;
            }
        }
        // Y = L⁻¹ K (forward substitution, column by column)
        let fwd = |b: &mut [f64], col: usize| {
            for i in 0..n {
                let mut s = b[i * n + col];
                for p in 0..i {
                    s -= m[i * n + p] * b[p * n + col];
                }
                b[i * n + col] = s / m[i * n + i];
            }
        };
        for c in 0..n {
            fwd(&mut k, c);
        }
        // A = L⁻¹ Yᵀ
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = k[j * n + i];
            }
        }
        for c in 0..n {
            fwd(&mut a, c);
        }
        // symmetrise round-off
        for i in 0..n {
            for j in (i + 1)..n {
                let v = 0.5 * (a[i * n + j] + a[j * n + i]);
                a[i * n + j] = v;
                a[j * n + i] = v;
            }
        }
        // cyclic Jacobi
        for _sweep in 0..100 {
            let mut off = 0.0;
            let mut diag = 0.0;
            for i in 0..n {
                diag += a[i * n + i] * a[i * n + i];
                for j in (i + 1)..n {
                    off += a[i * n + j] * a[i * n + j];
                }
            }
            if off <= 1e-30 * diag {
                break;
            }
            for p in 0..n {
                for q in (p + 1)..n {
                    let apq = a[p * n + q];
                    if apq.abs() < 1e-300 {
                        continue;
                    }
                    let theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
                    let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                    let c = 1.0 / (t * t + 1.0).sqrt();
                    let s = t * c;
                    for r in 0..n {
                        let (arp, arq) = (a[r * n + p], a[r * n + q]);
                        a[r * n + p] = c * arp - s * arq;
                        a[r * n + q] = s * arp + c * arq;
                    }
                    for r in 0..n {
                        let (apr, aqr) = (a[p * n + r], a[q * n + r]);
                        a[p * n + r] = c * apr - s * aqr;
                        a[q * n + r] = s * apr + c * aqr;
                    }
                }
            }
        }
        let mut ev: Vec<f64> = (0..n).map(|i| a[i * n + i]).collect();
        ev.sort_by(|x, y| x.partial_cmp(y).unwrap());
        ev.into_iter()
            .take(count)
            .map(|l| l.sqrt() / (2.0 * PI))
            .collect()
    }

    #[test]
    fn unequal_spans_agree_with_fine_finite_elements() {
        let spans = [24.0, 30.0, 24.0];
        let exact = continuous_beam_frequencies(&spans, EI, M, 6);
        let coarse = fe_frequencies(&spans, 1.0, 6); // h = 1 m
        let fine = fe_frequencies(&spans, 1.5, 6); // h = 2/3 m
        let r4 = 1.5f64.powi(4);
        for i in 0..6 {
            let (e, c, f) = (exact[i], coarse[i], fine[i]);
            // cubic Hermite elements converge from above with error O(h⁴) …
            assert!(
                f >= e * (1.0 - 1e-12) && c > f,
                "FE not monotone: {c} {f} {e}"
            );
            assert!(rel(c, e) < 1e-5, "exact {e} vs FE {c}");
            let ratio = (c - e) / (f - e);
            assert!(
                (ratio / r4 - 1.0).abs() < 0.1,
                "mode {i}: error ratio {ratio}"
            );
            // … so Richardson extrapolation must land on the exact value.
            let extrapolated = (r4 * f - c) / (r4 - 1.0);
            assert!(
                rel(extrapolated, e) < 5e-9,
                "mode {i}: {extrapolated} vs {e}"
            );
        }
    }

    // ----- part 2 -----

    fn test_beam(speed: f64, zeta: f64) -> MovingForceBeam {
        MovingForceBeam {
            length: 20.0,
            bending_stiffness: 1.2e9,
            mass_per_length: 4800.0,
            damping_ratio: zeta,
            force: 1.0e5,
            speed,
        }
    }

    #[test]
    fn slow_force_gives_static_deflection() {
        for zeta in [0.0, 0.02] {
            let mut p = test_beam(1.0, zeta);
            // α = v/(2 f₁ L) = 1e-4
            p.speed = 1e-4 * 2.0 * p.first_frequency() * p.length;
            let (wmax, tmax) = moving_force_max_midspan(&p, 50, p.crossing_time());
            let daf = wmax / p.static_midspan_deflection();
            assert!((daf - 1.0).abs() < 1e-3, "ζ={zeta}: DAF {daf}");
            assert!(
                (tmax / p.crossing_time() - 0.5).abs() < 0.02,
                "t_max {tmax}"
            );
        }
    }

    /// Single-mode ODE integrated by classical RK4 with a fine step.
    fn rk4_single_mode(p: &MovingForceBeam, t_end: f64, steps: usize) -> Vec<(f64, f64)> {
        let l = p.length;
        let w = simply_supported_circular_frequency(1, l, p.bending_stiffness, p.mass_per_length);
        let big = PI * p.speed / l;
        let f0 = 2.0 * p.force / (p.mass_per_length * l);
        let t_exit = l / p.speed;
        let z = p.damping_ratio;
        let force = |t: f64| {
            if t <= t_exit {
                f0 * (big * t).sin()
            } else {
                0.0
            }
        };
        let acc = |t: f64, q: f64, v: f64| force(t) - 2.0 * z * w * v - w * w * q;
        let h = t_end / steps as f64;
        let (mut q, mut v) = (0.0, 0.0);
        let mut out = vec![(0.0, 0.0)];
        for i in 0..steps {
            let t = i as f64 * h;
            let (k1q, k1v) = (v, acc(t, q, v));
            let (k2q, k2v) = (
                v + 0.5 * h * k1v,
                acc(t + 0.5 * h, q + 0.5 * h * k1q, v + 0.5 * h * k1v),
            );
            let (k3q, k3v) = (
                v + 0.5 * h * k2v,
                acc(t + 0.5 * h, q + 0.5 * h * k2q, v + 0.5 * h * k2v),
            );
            let (k4q, k4v) = (v + h * k3v, acc(t + h, q + h * k3q, v + h * k3v));
            q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            out.push(((i + 1) as f64 * h, q));
        }
        out
    }

    #[test]
    fn single_mode_closed_form_matches_rk4() {
        // α = 0.5 (classic), α = 1 (undamped resonance Ω₁ = ω₁), damped and undamped
        for (alpha, zeta) in [(0.5, 0.0), (0.5, 0.05), (1.0, 0.0), (0.2, 0.02)] {
            let mut p = test_beam(1.0, zeta);
            p.speed = alpha * 2.0 * p.first_frequency() * p.length;
            let t_exit = p.crossing_time();
            // exit time lands on a grid point: 2·t_exit split into 400 000 steps
            let hist = rk4_single_mode(&p, 2.0 * t_exit, 400_000);
            let scale = hist.iter().map(|s| s.1.abs()).fold(0.0, f64::max);
            let mut worst: f64 = 0.0;
            for &(t, q) in hist.iter().step_by(97) {
                let w = moving_force_deflection(0.5 * p.length, t, &p, 1);
                worst = worst.max((w - q).abs() / scale);
            }
            assert!(worst < 1e-10, "α={alpha} ζ={zeta}: rel err {worst}");
        }
    }

    #[test]
    fn response_continuous_across_exit_time() {
        let p = test_beam(30.0, 0.03);
        let te = p.crossing_time();
        for x in [0.25 * p.length, 0.5 * p.length] {
            let h = 1e-6 * te;
            let w0 = moving_force_deflection(x, te, &p, 20);
            let wm = moving_force_deflection(x, te - h, &p, 20);
            let wp = moving_force_deflection(x, te + h, &p, 20);
            let scale = p.static_midspan_deflection();
            // displacement continuity
            assert!((wp - wm).abs() < 1e-5 * scale);
            // velocity continuity: one-sided difference quotients agree
            let vl = (w0 - wm) / h;
            let vr = (wp - w0) / h;
            let vscale = scale / te;
            assert!((vl - vr).abs() < 1e-4 * vscale, "vl {vl} vr {vr}");
        }
    }

    #[test]
    fn moving_force_at_midspan_after_long_time_slow_is_static_profile() {
        // quasi-static: at t = L/(2v) the modal sum equals the static series
        // 2P/(mL) Σ sin²(jπ/2)/ω_j² which → PL³/(48EI)
        let mut p = test_beam(1.0, 0.05);
        p.speed = 1e-5 * 2.0 * p.first_frequency() * p.length;
        let w = moving_force_deflection(0.5 * p.length, 0.5 * p.crossing_time(), &p, 101);
        assert!(rel(w, p.static_midspan_deflection()) < 1e-6);
    }

    // ----- part 3 -----

    #[test]
    fn stiff_light_vehicle_reduces_to_moving_force() {
        let mut c = yang_yau_1997();
        c.vehicle_mass = 1.0;
        c.vehicle_stiffness = 1e7;
        c.damping_ratio = 0.02;
        let modes = 20;
        let te = c.crossing_time();
        let hist = sprung_mass_reference(&c, modes, 1e-5, 1.5 * te);
        let p = MovingForceBeam {
            length: c.length,
            bending_stiffness: c.bending_stiffness,
            mass_per_length: c.mass_per_length,
            damping_ratio: c.damping_ratio,
            force: c.vehicle_mass * GRAVITY,
            speed: c.speed,
        };
        let scale = p.static_midspan_deflection();
        let mut worst: f64 = 0.0;
        for i in (0..hist.time.len()).step_by(37) {
            let wf = moving_force_deflection(0.5 * c.length, hist.time[i], &p, modes);
            // sign: sprung mass is positive upward, moving force positive downward
            worst = worst.max((hist.midspan_deflection[i] + wf).abs() / scale);
        }
        assert!(worst < 1e-4, "worst relative difference {worst}");
        // and the sprung-mass deflection is a sag (negative) at midpass
        let mid = hist.time.iter().position(|&t| t >= 0.5 * te).unwrap();
        assert!(hist.midspan_deflection[mid] < 0.0);
    }

    fn max_abs(v: &[f64]) -> f64 {
        v.iter().fold(0.0, |a, &b| a.max(b.abs()))
    }

    /// Largest pointwise difference between a history and one with half the step,
    /// compared at the common time points, relative to the maximum magnitude.
    fn halving_difference(a: &[f64], b: &[f64]) -> f64 {
        assert_eq!(b.len(), 2 * a.len() - 1);
        let scale = max_abs(b);
        a.iter()
            .zip(b.iter().step_by(2))
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
            / scale
    }

    #[test]
    fn rk4_step_halving_converges() {
        let c = yang_yau_1997();
        let te = c.crossing_time();
        // Reference configuration: 40 modes, ω₄₀·dt ≈ 0.24 → 0.12.
        let a = sprung_mass_reference(&c, 40, 5e-6, te);
        let b = sprung_mass_reference(&c, 40, 2.5e-6, te);
        assert_eq!(*a.time.last().unwrap(), te);
        assert_eq!(*b.time.last().unwrap(), te);
        for (va, vb) in [
            (&a.midspan_deflection, &b.midspan_deflection),
            (&a.vehicle_acceleration, &b.vehicle_acceleration),
            (&a.vehicle_displacement, &b.vehicle_displacement),
            (&a.contact_force, &b.contact_force),
        ] {
            let (ma, mb) = (max_abs(va), max_abs(vb));
            assert!(rel(ma, mb) < 1e-8, "maxima {ma} vs {mb}");
            assert!(halving_difference(va, vb) < 1e-7);
        }
    }

    #[test]
    fn rk4_is_fourth_order() {
        // With few modes (ω_N·dt ≤ 0.08) the asymptotic regime is reached: halving the
        // step must divide the error by ≈ 2⁴ = 16.
        let c = yang_yau_1997();
        let te = c.crossing_time();
        let h1 = sprung_mass_reference(&c, 8, 2e-5, te);
        let h2 = sprung_mass_reference(&c, 8, 1e-5, te);
        let h3 = sprung_mass_reference(&c, 8, 0.5e-5, te);
        for (x1, x2, x3) in [
            (
                &h1.midspan_deflection,
                &h2.midspan_deflection,
                &h3.midspan_deflection,
            ),
            (
                &h1.vehicle_acceleration,
                &h2.vehicle_acceleration,
                &h3.vehicle_acceleration,
            ),
        ] {
            let d12 = halving_difference(x1, x2);
            let d23 = halving_difference(x2, x3);
            let order = (d12 / d23).log2();
            assert!(
                (order - 4.0).abs() < 0.3,
                "observed order {order} ({d12:e}, {d23:e})"
            );
        }
    }

    #[test]
    fn slow_vehicle_is_quasi_static() {
        let mut c = yang_yau_1997();
        c.speed = 0.05;
        c.damping_ratio = 0.02;
        let modes = 10;
        let te = c.crossing_time();
        let hist = sprung_mass_reference(&c, modes, 5e-4, 0.5 * te);
        let mg = c.vehicle_mass * GRAVITY;
        let worst = hist
            .contact_force
            .iter()
            .fold(0.0f64, |m, f| m.max((f / mg - 1.0).abs()));
        assert!(worst < 1e-5, "contact force deviates by {worst}");
        // at midpass the midspan deflection equals the static truncated modal series
        // −(2 M g/(mL)) Σ sin²(jπ/2)/ω_j²
        let stat: f64 = (1..=modes)
            .step_by(2)
            .map(|j| {
                let w = simply_supported_circular_frequency(
                    j,
                    c.length,
                    c.bending_stiffness,
                    c.mass_per_length,
                );
                2.0 * mg / (c.mass_per_length * c.length) / (w * w)
            })
            .sum();
        let w_mid = *hist.midspan_deflection.last().unwrap();
        assert!(rel(-w_mid, stat) < 1e-5, "w {w_mid} static {stat}");
        // and the truncated series is close to PL³/(48EI)
        assert!(
            rel(
                stat,
                static_midspan_deflection(mg, c.length, c.bending_stiffness)
            ) < 1e-3
        );
    }

    #[test]
    fn dashpot_force_uses_total_derivative_of_contact_deflection() {
        // With c_v ≠ 0 the recorded force must satisfy
        // F − M g − k(w_c − y) = c (dw_c/dt − dy/dt), where the rates are taken by
        // central differences of the recorded histories (dw_c/dt is then the total
        // derivative along the moving contact point, including v ∂w/∂x).
        let mut c = yang_yau_1997();
        c.vehicle_damping = 2.0e4;
        c.damping_ratio = 0.01;
        let te = c.crossing_time();
        let h = sprung_mass_reference(&c, 12, 2e-5, te);
        let mg = c.vehicle_mass * GRAVITY;
        let mut worst: f64 = 0.0;
        let mut scale: f64 = 0.0;
        for i in 1..h.time.len() - 1 {
            let dt2 = h.time[i + 1] - h.time[i - 1];
            let wcd = (h.contact_deflection[i + 1] - h.contact_deflection[i - 1]) / dt2;
            let yd = (h.vehicle_displacement[i + 1] - h.vehicle_displacement[i - 1]) / dt2;
            let damper = h.contact_force[i]
                - mg
                - c.vehicle_stiffness * (h.contact_deflection[i] - h.vehicle_displacement[i]);
            worst = worst.max((damper - c.vehicle_damping * (wcd - yd)).abs());
            scale = scale.max(damper.abs());
        }
        assert!(scale > 10.0, "dashpot force too small to test: {scale}");
        assert!(worst < 1e-5 * scale, "mismatch {worst} vs {scale}");
        // and F = M(g + ÿ) for the massless wheel
        for (f, a) in h.contact_force.iter().zip(&h.vehicle_acceleration) {
            assert!((f - c.vehicle_mass * (GRAVITY + a)).abs() < 1e-9 * mg);
        }
    }

    #[test]
    fn exit_lands_on_grid_and_free_phase_runs() {
        let c = yang_yau_1997();
        let te = c.crossing_time();
        let h = sprung_mass_reference(&c, 10, 3e-5, 1.3 * te);
        assert!(h.time.contains(&te));
        assert!((h.time.last().unwrap() - 1.3 * te).abs() < 1e-12);
        // after exit: contact force on ground = M(g + ÿ) and ÿ = −k y / M (c_v = 0)
        let last = h.time.len() - 1;
        let acc = -c.vehicle_stiffness * h.vehicle_displacement[last] / c.vehicle_mass;
        assert!((h.vehicle_acceleration[last] - acc).abs() < 1e-12 * (1.0 + acc.abs()));
        let ground = c.vehicle_mass * (GRAVITY + acc);
        assert!((h.contact_force[last] - ground).abs() < 1e-9 * ground);
        assert_eq!(h.contact_deflection[last], 0.0);
        // the beam keeps vibrating freely after the exit
        let free_amplitude = h
            .time
            .iter()
            .zip(&h.midspan_deflection)
            .filter(|(t, _)| **t > te)
            .fold(0.0f64, |m, (_, w)| m.max(w.abs()));
        assert!(
            free_amplitude > 1e-5,
            "free vibration amplitude {free_amplitude}"
        );
        // initial contact force is the weight
        assert!(rel(h.contact_force[0], c.vehicle_mass * GRAVITY) < 1e-15);
    }
}
