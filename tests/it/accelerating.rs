//! Vehicles that speed up and brake (issue 14, point 5), against an
//! independent reference computed here: the simply supported beam's exact
//! modes (φₙ = √(2/mL)·sin(nπx/L), ωₙ = (nπ/L)²√(EI/m); e.g. Frýba 1972,
//! ch. 1) integrated with a classical fourth-order Runge–Kutta scheme at a
//! quarter of vbi's step, with the vehicle at x(t) = v₀t + ½at² (stopped
//! for good once v = 0). Nothing of vbi's Newmark scheme, finite elements or
//! kinematics is used by the reference.

use crate::support;

use support::{column, max_abs, run_yaml};

const LENGTH: f64 = 25.0;
const EI: f64 = 8.323e9;
const MASS: f64 = 2303.0;
const MODES: usize = 12;
const GRAVITY: f64 = 9.81;

fn omega(n: usize) -> f64 {
    let k = n as f64 * std::f64::consts::PI / LENGTH;
    k * k * (EI / MASS).sqrt()
}

/// φₙ, φₙ′, φₙ″ at x (0 off the beam).
fn shape(n: usize, x: f64) -> (f64, f64, f64) {
    if !(0.0..=LENGTH).contains(&x) {
        return (0.0, 0.0, 0.0);
    }
    let a = (2.0 / (MASS * LENGTH)).sqrt();
    let k = n as f64 * std::f64::consts::PI / LENGTH;
    (
        a * (k * x).sin(),
        a * k * (k * x).cos(),
        -a * k * k * (k * x).sin(),
    )
}

/// x(t), v(t), a(t) of constant acceleration from v₀ at t = 0, x(0) = 0;
/// a braking vehicle stays where it stops.
fn kinematics(v0: f64, a: f64, t: f64) -> (f64, f64, f64) {
    let stop = if a < 0.0 { -v0 / a } else { f64::INFINITY };
    if t >= stop {
        (v0 * stop + 0.5 * a * stop * stop, 0.0, 0.0)
    } else {
        (v0 * t + 0.5 * a * t * t, v0 + a * t, a)
    }
}

/// A vehicle for the reference: a moving force P (N), or a two-mass
/// oscillator (sprung mass, unsprung mass, stiffness, damping) in permanent
/// contact with the deck.
#[derive(Clone, Copy)]
enum Vehicle {
    Force(f64),
    Oscillator {
        sprung: f64,
        unsprung: f64,
        stiffness: f64,
        damping: f64,
        /// Harmonic track r(x) = A sin(kx) for x ≥ 0 (0 before): (A m, k rad/m).
        track: (f64, f64),
    },
}

/// r, r′, r″ of the harmonic track (A, k) at x.
fn track_at((amplitude, k): (f64, f64), x: f64) -> (f64, f64, f64) {
    if x < 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let (s, c) = (k * x).sin_cos();
    (amplitude * s, amplitude * k * c, -amplitude * k * k * s)
}

/// The reference's state derivative; returns the wheel's acceleration
/// (m/s²). State: q (MODES), q̇ (MODES), z, ż (sprung mass displacement
/// from static equilibrium, m, and its velocity). For the oscillator the
/// unsprung mass follows the deck and track, u = Σφq + r(x), so
/// ü = Σ(φq̈ + 2vφ′q̇ + v²φ″q + aφ′q) + v²r″ + ar′, and the contact force
/// λ = (m_s + m_u)g − k(z − u) − c(ż − u̇) + m_u ü couples with
/// q̈ₙ = −2ζωₙq̇ₙ − ωₙ²qₙ − λφₙ; solved for λ in closed form:
/// λ = (λ₀ + m_u Σφₙfₙ) / (1 + m_u Σφₙ²), fₙ the modal accelerations at λ = 0.
fn derivative(
    vehicle: Vehicle,
    zeta: f64,
    v0: f64,
    a0: f64,
    t: f64,
    y: &[f64],
    out: &mut [f64],
) -> f64 {
    let (x, v, a) = kinematics(v0, a0, t);
    let (q, qd) = (&y[..MODES], &y[MODES..2 * MODES]);
    let mut phi = [0.0; MODES];
    let (mut u, mut ud, mut convective, mut phi2, mut phi_f) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut free = [0.0; MODES];
    for n in 0..MODES {
        let (p, dp, ddp) = shape(n + 1, x);
        let w = omega(n + 1);
        phi[n] = p;
        free[n] = -2.0 * zeta * w * qd[n] - w * w * q[n];
        u += p * q[n];
        ud += p * qd[n] + v * dp * q[n];
        convective += 2.0 * v * dp * qd[n] + v * v * ddp * q[n] + a * dp * q[n];
        phi2 += p * p;
        phi_f += p * free[n];
    }
    let force = match vehicle {
        Vehicle::Force(p) => {
            out[2 * MODES] = 0.0;
            out[2 * MODES + 1] = 0.0;
            p
        }
        Vehicle::Oscillator {
            sprung,
            unsprung,
            stiffness,
            damping,
            track,
        } => {
            let (r, dr, ddr) = track_at(track, x);
            u += r;
            ud += v * dr;
            convective += v * v * ddr + a * dr;
            let (z, zd) = (y[2 * MODES], y[2 * MODES + 1]);
            let spring = stiffness * (z - u) + damping * (zd - ud);
            out[2 * MODES] = zd;
            out[2 * MODES + 1] = -spring / sprung;
            let base = (sprung + unsprung) * GRAVITY - spring + unsprung * convective;
            (base + unsprung * phi_f) / (1.0 + unsprung * phi2)
        }
    };
    let mut wheel = convective;
    for n in 0..MODES {
        out[n] = qd[n];
        out[MODES + n] = free[n] - force * phi[n];
        wheel += phi[n] * out[MODES + n];
    }
    wheel
}

/// Mid-span deflection (m, upward), the sprung mass's displacement (m) and
/// the wheel's acceleration (m/s²) at each of `times` (s), by RK4 at
/// `substeps` steps per interval.
fn reference(
    vehicle: Vehicle,
    zeta: f64,
    v0: f64,
    a: f64,
    times: &[f64],
    substeps: usize,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let size = 2 * MODES + 2;
    let mut y = vec![0.0; size];
    let (mut k1, mut k2, mut k3, mut k4, mut tmp) = (
        vec![0.0; size],
        vec![0.0; size],
        vec![0.0; size],
        vec![0.0; size],
        vec![0.0; size],
    );
    let midspan = |y: &[f64]| -> f64 {
        (0..MODES)
            .map(|n| shape(n + 1, 0.5 * LENGTH).0 * y[n])
            .sum()
    };
    let (mut mid, mut body, mut wheel) = (vec![midspan(&y)], vec![0.0], vec![0.0]);
    for pair in times.windows(2) {
        let h = (pair[1] - pair[0]) / substeps as f64;
        for s in 0..substeps {
            let t = pair[0] + s as f64 * h;
            derivative(vehicle, zeta, v0, a, t, &y, &mut k1);
            for i in 0..size {
                tmp[i] = y[i] + 0.5 * h * k1[i];
            }
            derivative(vehicle, zeta, v0, a, t + 0.5 * h, &tmp, &mut k2);
            for i in 0..size {
                tmp[i] = y[i] + 0.5 * h * k2[i];
            }
            derivative(vehicle, zeta, v0, a, t + 0.5 * h, &tmp, &mut k3);
            for i in 0..size {
                tmp[i] = y[i] + h * k3[i];
            }
            derivative(vehicle, zeta, v0, a, t + h, &tmp, &mut k4);
            for i in 0..size {
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
        mid.push(midspan(&y));
        body.push(y[2 * MODES]);
        wheel.push(derivative(vehicle, zeta, v0, a, pair[1], &y, &mut tmp));
    }
    (mid, body, wheel)
}

/// Largest difference of two histories over the peak of the second.
fn relative_error(run: &[f64], reference: &[f64]) -> f64 {
    assert_eq!(run.len(), reference.len());
    let worst = run
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    worst / max_abs(reference)
}

fn beam_yaml(zeta: f64) -> String {
    format!(
        "bridge: {{type: beam, spans: [{LENGTH}], bending_stiffness: {EI}, mass_per_length: {MASS}, \
         modes: {{count: {MODES}}}, damping: {{type: modal, ratio: {zeta}}}}}\n"
    )
}

/// Tolerance of the history comparisons, relative to the reference's peak.
/// Measured largest errors: accelerating force 8.7e-5, braking force 9.1e-5,
/// accelerating oscillator 8.7e-5 (deck) and 1.3e-4 (body); 1e-3 is 8–11×
/// those. (The a·φ′·q term of the wheel's acceleration is far below these
/// on a real deck, a few mm/s²: the harmonic-track test below is the one
/// that sees the path acceleration's term.)
const TOLERANCE: f64 = 1e-3;

/// A 100 kN force accelerating from 20 m/s at 8 m/s² across the Yang & Yau
/// beam (it leaves at √(20² + 2·8·25) = 28.3 m/s), 2 % damping: mid-span deflection at every
/// step against the RK4 modal reference.
#[test]
fn accelerating_force_matches_modal_reference() {
    let (v0, a, zeta) = (20.0, 8.0, 0.02);
    let outcome = run_yaml(&format!(
        "name: accelerating\n{}vehicles: [{{type: moving_force, loads: [1.0e5], speed: {v0}, \
         acceleration: {a}}}]\nsolver: {{time_step: 1.0e-4, free_vibration: 0.3}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 12.5}}]\n",
        beam_yaml(zeta)
    ));
    let times = &outcome.history.time;
    // Exit when v₀t + ½at² = 25 m, t = (√(v₀² + 2aL) − v₀)/a, then 0.3 s
    // free; the last step may overshoot by less than one step.
    let exit = ((v0 * v0 + 2.0 * a * LENGTH).sqrt() - v0) / a;
    let end = times.last().unwrap() - (exit + 0.3);
    assert!((0.0..1.0e-4).contains(&end), "{:?}", times.last());
    let (mid, _, _) = reference(Vehicle::Force(1.0e5), zeta, v0, a, times, 4);
    let error = relative_error(column(&outcome, "mid"), &mid);
    eprintln!("accelerating force: mid-span error {error:.2e} of the peak");
    assert!(error < TOLERANCE, "{error}");
}

/// A force braking from 15 m/s at −6 m/s² stops at t = 2.5 s, 18.75 m
/// along the beam, and stays there: the deflection against the reference,
/// and the deck settles to the static deflection under the parked load
/// (P x²(L − x)²/(3EIL) at the load, the beam formula; here checked at the
/// load point's influence on mid-span: P b x (L² − b² − x²)/(6EIL)).
#[test]
fn braking_force_stops_and_stays() {
    let (v0, a, zeta) = (15.0, -6.0, 0.05);
    let outcome = run_yaml(&format!(
        "name: braking\n{}vehicles: [{{type: moving_force, loads: [1.0e5], speed: {v0}, \
         acceleration: {a}}}]\nsolver: {{time_step: 1.0e-4, free_vibration: 2.0}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 12.5}}]\n",
        beam_yaml(zeta)
    ));
    let times = &outcome.history.time;
    // The run ends 2 s after the stop (t = 2.5 s).
    let end = times.last().unwrap() - 4.5;
    assert!((-1e-9..1.0e-4).contains(&end), "{:?}", times.last());
    let (mid, _, _) = reference(Vehicle::Force(1.0e5), zeta, v0, a, times, 4);
    let run = column(&outcome, "mid");
    let error = relative_error(run, &mid);
    eprintln!("braking force: mid-span error {error:.2e} of the peak");
    assert!(error < TOLERANCE, "{error}");
    // Static mid-span deflection under P at x = 18.75 m (b = L − x from the
    // far support, mid-span left of the load): P b x_m (L² − b² − x_m²)/(6EIL).
    let (b, xm) = (LENGTH - 18.75, 12.5);
    let statics = -1.0e5 * b * xm * (LENGTH * LENGTH - b * b - xm * xm) / (6.0 * EI * LENGTH);
    let end = *run.last().unwrap();
    eprintln!("parked: {end:.6e} m vs static {statics:.6e} m");
    // 2 s of 5 % damping at f₁ = 4.78 Hz decay the free vibration by
    // e^(−2π·0.05·4.78·2) ≈ 5e-2 of its start; 1 % of the static value.
    assert!(
        (end - statics).abs() < 1e-2 * statics.abs(),
        "{end} vs {statics}"
    );
}

/// The two-mass oscillator of Yang & Yau (5750 kg on 1595 kN/m) with a
/// 500 kg wheel and 10 kN·s/m suspension damping, accelerating from 15 m/s
/// at 6 m/s², under permanent contact (coupled solver): mid-span deflection
/// and body displacement against the reference, whose wheel acceleration
/// carries the a·φ′·q term.
#[test]
fn accelerating_oscillator_matches_modal_reference() {
    let (v0, a, zeta) = (15.0, 6.0, 0.02);
    let vehicle = Vehicle::Oscillator {
        sprung: 5750.0,
        unsprung: 500.0,
        stiffness: 1.595e6,
        damping: 1.0e4,
        track: (0.0, 1.0),
    };
    let outcome = run_yaml(&format!(
        "name: accelerating-oscillator\n{}gravity: {GRAVITY}\nvehicles: [{{type: oscillator, \
         sprung_mass: 5750, unsprung_mass: 500, stiffness: 1.595e6, damping: 1.0e4, \
         speed: {v0}, acceleration: {a}}}]\n\
         solver: {{method: coupled, time_step: 1.0e-4, free_vibration: 0.3}}\n\
         record: [{{name: mid, quantity: bridge_displacement, x: 12.5}}, \
         {{name: body, quantity: vehicle_displacement, vehicle: 1, dof: sprung}}]\n",
        beam_yaml(zeta)
    ));
    let times = &outcome.history.time;
    let (mid, body, _) = reference(vehicle, zeta, v0, a, times, 4);
    let deck = relative_error(column(&outcome, "mid"), &mid);
    let sprung = relative_error(column(&outcome, "body"), &body);
    eprintln!("accelerating oscillator: deck error {deck:.2e}, body error {sprung:.2e}");
    assert!(deck < TOLERANCE && sprung < TOLERANCE, "{deck} {sprung}");
}

/// The same oscillator accelerating from 8 m/s at 4 m/s² over a harmonic
/// track (5 mm, 25 m wavelength): the wheel's vertical acceleration
/// ü = … + v²r″ + a·r′ carries the path acceleration's term a·r′ (a tenth
/// of the track's share here), against the reference's.
#[test]
fn wheel_acceleration_carries_the_path_acceleration_term() {
    let (v0, a, zeta) = (8.0, 4.0, 0.02);
    let (amplitude, wavelength) = (0.005, 25.0);
    let vehicle = Vehicle::Oscillator {
        sprung: 5750.0,
        unsprung: 500.0,
        stiffness: 1.595e6,
        damping: 1.0e4,
        track: (amplitude, 2.0 * std::f64::consts::PI / wavelength),
    };
    let outcome = run_yaml(&format!(
        "name: accelerating-track\n{}gravity: {GRAVITY}\nvehicles: [{{type: oscillator, \
         sprung_mass: 5750, unsprung_mass: 500, stiffness: 1.595e6, damping: 1.0e4, \
         speed: {v0}, acceleration: {a}}}]\n\
         surface: {{type: harmonic, amplitude: {amplitude}, wavelength: {wavelength}, phase: 0}}\n\
         solver: {{method: coupled, time_step: 1.0e-4, free_vibration: 0.1}}\n\
         record: [{{name: wheel, quantity: vehicle_acceleration, vehicle: 1, dof: wheel}}, \
         {{name: body, quantity: vehicle_displacement, vehicle: 1, dof: sprung}}]\n",
        beam_yaml(zeta)
    ));
    let times = &outcome.history.time;
    let (_, body, wheel) = reference(vehicle, zeta, v0, a, times, 4);
    // The first steps after the entrance are left out: the track's slope
    // jumps there (phase 0), which both schemes resolve only to O(Δt).
    let skip = 100;
    let wheel_error = relative_error(&column(&outcome, "wheel")[skip..], &wheel[skip..]);
    let body_error = relative_error(column(&outcome, "body"), &body);
    eprintln!("harmonic track: wheel acceleration error {wheel_error:.2e}, body {body_error:.2e}");
    // Measured: wheel 4.6e-3 (the Newmark phase error of the deck's higher
    // modes in the deck's share of ü; largest where the wheel leaves the
    // deck), body 5.9e-5. The a·r′ term alone is 4 × 0.005 × 2π/25 =
    // 5.0e-3 m/s², 5 % of the wheel's peak (0.1 m/s²): leaving it out fails
    // the 1e-2 bound (measured 6.0e-2).
    assert!(
        wheel_error < 1e-2 && body_error < TOLERANCE,
        "{wheel_error} {body_error}"
    );
}

/// `acceleration: 0` is the constant-speed run, bit for bit (the shipped
/// goldens, unchanged by the acceleration's arrival, hold the same for
/// every solver).
#[test]
fn zero_acceleration_is_constant_speed_bit_for_bit() {
    let scene = |extra: &str| {
        run_yaml(&format!(
            "name: a0\n{}vehicles: [{{type: oscillator, sprung_mass: 5750, stiffness: 1.595e6, \
             speed: 27.7{extra}}}]\nsolver: {{method: coupled, time_step: 2.0e-4}}\n\
             record: [{{name: mid, quantity: bridge_displacement, x: 12.5}}, \
             {{name: force, quantity: contact_force, vehicle: 1, wheel: 1}}]\n",
            beam_yaml(0.02)
        ))
    };
    let (with, without) = (scene(", acceleration: 0"), scene(""));
    for name in ["mid", "force"] {
        let bits = |o: &vbi::run::Outcome| -> Vec<u64> {
            column(o, name).iter().map(|v| v.to_bits()).collect()
        };
        assert_eq!(bits(&with), bits(&without), "{name}");
    }
}

/// A braking vehicle that would stop before the bridge is refused, located.
#[test]
fn stopping_before_the_bridge_is_refused() {
    let yaml = format!(
        "name: short\n{}vehicles:\n  - type: moving_force\n    loads: [1.0e5]\n    speed: 10\n    \
         acceleration: -1\n    start_position: -60\n",
        beam_yaml(0.0)
    );
    let Err(error) = vbi::plan::load_str(&yaml, "short.yaml") else {
        panic!("a vehicle stopping before the bridge was accepted");
    };
    let error = error.to_string();
    assert!(
        error.contains("short.yaml:7:") && error.contains("stops"),
        "{error}"
    );
}

/// A speed sweep sets each vehicle's speed at t = 0 and keeps its
/// acceleration and start position: a braking vehicle that the sweep's
/// slowest speed would stop before the bridge is refused, at `study.speeds`
/// (10 m/s braking at 1 m/s² covers 50 m, not the 60 m to the entrance);
/// from 12 m/s (72 m) the sweep is accepted.
#[test]
fn a_sweep_too_slow_for_a_braking_vehicle_is_refused() {
    let sweep = |from: f64| {
        format!(
            "name: sweep\n{}vehicles:\n  - type: moving_force\n    loads: [1.0e5]\n    speed: 20\n    \
             acceleration: -1\n    start_position: -60\n\
             study:\n  type: speed_sweep\n  speeds: {{from: {from}, to: 20, count: 3}}\n",
            beam_yaml(0.0)
        )
    };
    let Err(error) = vbi::plan::load_str(&sweep(10.0), "sweep.yaml") else {
        panic!("a sweep that stops the vehicle before the bridge was accepted");
    };
    let error = error.to_string();
    assert!(
        error.contains("sweep.yaml:11:") && error.contains("brakes to a stop before"),
        "{error}"
    );
    assert!(vbi::plan::load_str(&sweep(12.0), "sweep.yaml").is_ok());
}
