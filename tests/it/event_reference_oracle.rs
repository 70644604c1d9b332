//! Self-tests of the tensionless-contact reference solution.
#![allow(clippy::needless_range_loop)]
use crate::support;
use support::event_reference::*;
use support::max_abs;

const G: f64 = GRAVITY;

/// Separating case of the brief (a = 3 mm already separates; see `separating_case_*`).
fn separating_case() -> TensionlessCase {
    TensionlessCase {
        length: 20.0,
        bending_stiffness: 3.2423e9,
        mass_per_length: 2000.0,
        damping_ratio: 0.02,
        sprung_mass: 4000.0,
        unsprung_mass: 1000.0,
        suspension_stiffness: 4e6,
        suspension_damping: 2.53e4,
        contact_stiffness: 1e8,
        contact_exponent: 1.0,
        speed: 25.0,
        start_position: 0.0,
        roughness_amplitude: 3e-3,
        roughness_wavelength: 1.5,
        roughness_phase: 0.0,
        modes: 10,
    }
}

fn grid(t_end: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| t_end * i as f64 / n as f64).collect()
}

fn contact_events(ev: &[ContactEvent]) -> Vec<ContactEvent> {
    ev.iter()
        .copied()
        .filter(|e| matches!(e.kind, EventKind::Loss | EventKind::Regain))
        .collect()
}

/// Beam free vibration (vehicle parked far off the beam): the dense output must match the
/// analytic damped modal solution, and tightening rtol must reduce the error.
#[test]
fn free_beam_vibration_matches_analytic_solution() {
    let mut c = separating_case();
    c.speed = 0.0;
    c.start_position = -100.0;
    c.roughness_amplitude = 0.0;
    c.modes = 5;
    let mut init = c.equilibrium_state();
    init.q = vec![2e-3, 5e-4, -3e-4, 1e-4, 4e-5];
    init.q_dot = vec![0.05, 0.0, 0.1, -0.02, 0.03];
    let t_end = 0.7;
    // Output times deliberately not aligned with anything.
    let times: Vec<f64> = (0..997)
        .map(|i| t_end * (i as f64 + 0.37) / 997.0)
        .collect();
    let exact = |t: f64| -> f64 {
        let mut w = 0.0;
        for j in 1..=c.modes {
            let om = c.natural_frequency(j);
            let z = c.damping_ratio;
            let od = om * (1.0 - z * z).sqrt();
            let (q0, v0) = (init.q[j - 1], init.q_dot[j - 1]);
            let q = (-z * om * t).exp()
                * (q0 * (od * t).cos() + (v0 + z * om * q0) / od * (od * t).sin());
            w += q * (j as f64 * std::f64::consts::PI / 2.0).sin();
        }
        w
    };
    let amp = max_abs(times.iter().map(|&t| exact(t)));
    let mut errs = Vec::new();
    for rtol in [1e-6, 1e-10] {
        let d = tensionless_from_state(&c, &init, &times, t_end, rtol);
        let err = max_abs(
            times
                .iter()
                .zip(&d.history.midspan_deflection)
                .map(|(&t, &w)| w - exact(t)),
        ) / amp;
        // The vehicle stays in static equilibrium on the ground.
        let p = c.static_load();
        for &f in &d.history.contact_force {
            assert!((f - p).abs() <= 1e-9 * p, "force {f} vs {p}");
        }
        assert!(contact_events(&d.history.events).is_empty());
        errs.push(err);
    }
    println!(
        "free vibration relative errors: rtol 1e-6 → {:e}, 1e-10 → {:e}",
        errs[0], errs[1]
    );
    assert!(errs[1] < 2e-9, "dense output error {:e}", errs[1]);
    assert!(
        errs[0] > 10.0 * errs[1],
        "error control ineffective: {errs:?}"
    );
}

/// (1) Very stiff contact without separation: the penalty model approaches the permanent
/// (bilateral, rigid) contact model, and its force satisfies the wheel's equation of motion.
#[test]
fn stiff_contact_approaches_permanent_contact_reference() {
    let mut c = separating_case();
    c.contact_stiffness = 1e10;
    c.speed = 5.0;
    c.roughness_amplitude = 0.0;
    c.modes = 8;
    let t_end = 4.0; // exit at L/v = 4 s
    let times = grid(t_end, 4000);
    let rtol = 1e-10;
    let perm = permanent_contact_reference(&c, &times, t_end, rtol);
    let pen = tensionless_reference(&c, &times, t_end, rtol);
    assert!(
        contact_events(&pen.events).is_empty(),
        "unexpected separation"
    );
    assert_eq!(
        pen.events.iter().map(|e| e.kind).collect::<Vec<_>>(),
        vec![EventKind::Entry, EventKind::Exit]
    );
    let p = c.static_load();
    let wmax = max_abs(perm.midspan_deflection.iter().copied());
    let dw = max_abs(
        pen.midspan_deflection
            .iter()
            .zip(&perm.midspan_deflection)
            .map(|(a, b)| a - b),
    );
    let df = max_abs(
        pen.contact_force
            .iter()
            .zip(&perm.contact_force)
            .map(|(a, b)| a - b),
    );
    println!(
        "k_c = 1e10: max|Δw_mid|/max|w_mid| = {:e}, max|ΔF|/P = {:e}",
        dw / wmax,
        df / p
    );
    assert!(dw <= 1e-3 * wmax, "midspan mismatch {:e}", dw / wmax);
    assert!(df <= 1e-3 * p, "contact force mismatch {:e}", df / p);
    // Static deflection sanity: PL³/(48EI) at midspan, dynamic amplification small at 5 m/s.
    let w_static = p * c.length.powi(3) / (48.0 * c.bending_stiffness);
    assert!(
        (wmax / w_static - 1.0).abs() < 0.2,
        "wmax {wmax} vs static {w_static}"
    );

    // Consistency: F = m_u (g + ÿ_w) − k(y_s − y_w) − c(ẏ_s − ẏ_w) with derivatives by central
    // differences of the dense output (dt = 1e-5 s).
    let dt = 1e-5;
    let centres: Vec<f64> = (1..40).map(|i| i as f64 * 0.1 + 0.0123).collect();
    let mut t3 = Vec::new();
    for &tc in &centres {
        t3.extend([tc - dt, tc, tc + dt]);
    }
    let h = tensionless_reference(&c, &t3, t_end, rtol);
    let mut worst: f64 = 0.0;
    for i in 0..centres.len() {
        let (a, b, d) = (3 * i, 3 * i + 1, 3 * i + 2);
        let yw = &h.wheel_displacement;
        let ys = &h.sprung_displacement;
        let acc_w = (yw[d] - 2.0 * yw[b] + yw[a]) / (dt * dt);
        let vel_rel = ((ys[d] - yw[d]) - (ys[a] - yw[a])) / (2.0 * dt);
        let f_eq = c.unsprung_mass * (G + acc_w)
            - c.suspension_stiffness * (ys[b] - yw[b])
            - c.suspension_damping * vel_rel;
        worst = worst.max((f_eq - h.contact_force[b]).abs() / p);
    }
    println!("equation-of-motion consistency: max |F − m_u(g+ÿ_w) + f_susp|/P = {worst:e}");
    assert!(worst < 1e-5, "force/acceleration inconsistency {worst:e}");

    // Convergence in k_c: the midspan mismatch decreases as the contact stiffens.
    let mut prev = f64::INFINITY;
    for kc in [1e8, 1e9, 1e10] {
        let mut ck = c;
        ck.contact_stiffness = kc;
        let h = tensionless_reference(&ck, &times, t_end, 1e-9);
        let d = max_abs(
            h.midspan_deflection
                .iter()
                .zip(&perm.midspan_deflection)
                .map(|(a, b)| a - b),
        ) / wmax;
        println!("k_c = {kc:e}: midspan mismatch {d:e}");
        assert!(d < prev, "no convergence toward permanent contact");
        prev = d;
    }
}

/// (2) A vehicle standing (almost) still on flat ground keeps F = (m_s + m_u) g.
#[test]
fn standing_vehicle_keeps_its_weight() {
    let mut c = separating_case();
    c.speed = 1e-6;
    c.start_position = -1.0;
    let times = grid(1.0, 100);
    let h = tensionless_reference(&c, &times, 1.0, 1e-10);
    let p = c.static_load();
    let yw0 = -p / c.contact_stiffness;
    let ys0 = yw0 - c.sprung_mass * G / c.suspension_stiffness;
    for i in 0..times.len() {
        assert!(
            (h.contact_force[i] - p).abs() <= 1e-12 * p,
            "F = {}",
            h.contact_force[i]
        );
        assert!((h.wheel_displacement[i] - yw0).abs() <= 1e-15);
        assert!((h.sprung_displacement[i] - ys0).abs() <= 1e-15);
        assert_eq!(h.midspan_deflection[i], 0.0);
    }
    assert!(h.events.is_empty(), "{:?}", h.events);
}

/// (3) Heavy oscillator at 25 m/s over 3 mm harmonic roughness: the wheel separates.
#[test]
fn separating_case_events_and_convergence() {
    let c = separating_case();
    let t_end = 1.0; // exit at 0.8 s, then rigid rough ground
    let (f8, g8, ev8) = extremes(&c, t_end, 1e-8);
    let (f10, g10, ev10) = extremes(&c, t_end, 1e-10);
    let ce = contact_events(&ev10);
    println!(
        "separating case: max F = {f10:.9e} N, max gap = {g10:.9e} m, {} loss / {} regain, \
         first loss at {:.12} s",
        ce.iter().filter(|e| e.kind == EventKind::Loss).count(),
        ce.iter().filter(|e| e.kind == EventKind::Regain).count(),
        ce[0].time
    );
    println!("events: {ev10:?}");
    assert!(!ce.is_empty(), "the case does not separate");
    // Loss/Regain alternate, starting with Loss.
    for (i, e) in ce.iter().enumerate() {
        let want = if i % 2 == 0 {
            EventKind::Loss
        } else {
            EventKind::Regain
        };
        assert_eq!(e.kind, want, "events out of order: {ce:?}");
    }
    assert_eq!(ce.len() % 2, 0, "wheel still airborne at t_end: {ce:?}");
    assert!(f10 > c.static_load() && g10 > 0.0);
    // Tightening rtol from 1e-8 to 1e-10.
    let rel_f = (f8 - f10).abs() / f10;
    let rel_g = (g8 - g10).abs() / g10;
    println!("rtol 1e-8 → 1e-10: Δ max F {rel_f:e}, Δ max gap {rel_g:e}");
    assert!(rel_f < 1e-6 && rel_g < 1e-6, "{rel_f:e} {rel_g:e}");
    assert_eq!(ev8.len(), ev10.len());
    for (a, b) in ev8.iter().zip(&ev10) {
        assert_eq!(a.kind, b.kind);
        assert!((a.time - b.time).abs() < 1e-8, "{a:?} vs {b:?}");
    }

    // Sampled history: F == 0 exactly strictly between Loss and Regain, δ < 0 there; F > 0
    // and δ > 0 strictly inside contact phases; the extremes bound the samples.
    let times = grid(t_end, 20000);
    let h = tensionless_reference(&c, &times, t_end, 1e-10);
    assert_eq!(h.events, ev10);
    let mut separated_samples = 0;
    for (i, &t) in times.iter().enumerate() {
        let inside = ce
            .chunks(2)
            .any(|p| t > p[0].time && p.get(1).is_none_or(|r| t < r.time));
        let near = ce.iter().any(|e| (t - e.time).abs() < 1e-9);
        if near {
            continue;
        }
        if inside {
            separated_samples += 1;
            assert_eq!(h.contact_force[i], 0.0, "F ≠ 0 while separated at t = {t}");
            assert!(h.compression[i] < 0.0);
        } else {
            assert!(
                h.contact_force[i] > 0.0 && h.compression[i] > 0.0,
                "t = {t}"
            );
            assert_eq!(h.contact_force[i], c.contact_stiffness * h.compression[i]);
        }
    }
    assert!(separated_samples > 10);
    let fmax_s = h.contact_force.iter().copied().fold(0.0, f64::max);
    let gmax_s = h.compression.iter().map(|d| -d).fold(0.0, f64::max);
    assert!(
        fmax_s <= f10 * (1.0 + 1e-9) && fmax_s > 0.99 * f10,
        "{fmax_s} vs {f10}"
    );
    assert!(
        gmax_s <= g10 * (1.0 + 1e-9) && gmax_s > 0.99 * g10,
        "{gmax_s} vs {g10}"
    );
}

/// (4a) Energy conservation with contact chatter, undamped, on smooth rigid ground and on the
/// flexible beam (vehicle standing still, dropped from 5 mm): E(t) = E(0). The drift is
/// proportional to rtol (≈ 2e-8 at 1e-10, 2e-9 at 1e-11 on the beam); rtol = 1e-11 is used.
#[test]
fn undamped_drop_conserves_energy() {
    for (x0, label) in [(-50.0, "rigid ground"), (20.0 / 3.0, "beam at L/3")] {
        let mut c = separating_case();
        c.damping_ratio = 0.0;
        c.suspension_damping = 0.0;
        c.speed = 0.0;
        c.start_position = x0;
        c.roughness_amplitude = 0.0;
        let mut init = c.equilibrium_state();
        init.wheel_displacement = 5e-3;
        init.sprung_displacement = 5e-3 - c.sprung_mass * G / c.suspension_stiffness;
        let t_end = 1.0;
        let times = grid(t_end, 5000);
        let d = tensionless_from_state(&c, &init, &times, t_end, 1e-11);
        let ce = contact_events(&d.history.events);
        let scale = d.elastic_kinetic_energy.iter().copied().fold(0.0, f64::max);
        let drift = max_abs(d.energy.iter().map(|e| e - d.energy[0])) / scale;
        println!(
            "{label}: {} contact events, {} steps, energy drift {drift:e} (scale {scale:.3} J)",
            ce.len(),
            d.steps
        );
        assert!(ce.len() >= 4, "no chatter on {label}: {ce:?}");
        assert_eq!(ce[0].kind, EventKind::Regain); // starts in the air
        assert!(d.net_work.iter().all(|&w| w == 0.0));
        assert!(drift < 1e-7, "energy drift {drift:e} on {label}");
    }
}

/// (4b) Energy balance of the damped, moving, separating case: E(t) − E(0) = W(t), where W
/// integrates the work of the moving contact through the surface slope minus dissipation.
#[test]
fn moving_separating_case_energy_balance() {
    let c = separating_case();
    let times = grid(1.0, 2000);
    let d = tensionless_from_state(&c, &c.equilibrium_state(), &times, 1.0, 1e-10);
    let scale = d.elastic_kinetic_energy.iter().copied().fold(0.0, f64::max);
    let worst =
        max_abs((0..times.len()).map(|i| d.energy[i] - d.energy[0] - d.net_work[i])) / scale;
    println!(
        "energy balance error {worst:e} of {scale:.3} J, W(1 s) = {:.6} J",
        d.net_work.last().unwrap()
    );
    assert!(worst < 1e-7, "energy balance error {worst:e}");
    assert!(d.net_work.last().unwrap().abs() > 1.0, "case too trivial");
}

/// Damped vehicle placed on the beam at midspan (at rest, beam undeflected) settles to the
/// static solution: w(L/2) = −P Σ_j 2 sin²(jπ/2)/(mL ω_j²), F = P, y_w = w(L/2) − P/k_c.
/// Checks the modal load normalisation 2/(mL) and its sign independently of the other tests.
#[test]
fn stationary_vehicle_settles_to_static_deflection() {
    let mut c = separating_case();
    c.speed = 0.0;
    c.start_position = 0.5 * c.length;
    c.roughness_amplitude = 0.0;
    c.damping_ratio = 0.05;
    c.modes = 5;
    let t_end = 30.0;
    let d = tensionless_from_state(&c, &c.equilibrium_state(), &[t_end], t_end, 1e-10);
    let p = c.static_load();
    let mut w_static = 0.0;
    for j in 1..=c.modes {
        let om = c.natural_frequency(j);
        let s = (j as f64 * std::f64::consts::PI / 2.0).sin();
        w_static -= p * 2.0 * s * s / (c.mass_per_length * c.length * om * om);
    }
    let h = &d.history;
    println!(
        "static: w_mid = {:.12e} (modal static {w_static:.12e}), F/P − 1 = {:e}",
        h.midspan_deflection[0],
        h.contact_force[0] / p - 1.0
    );
    assert!(((h.midspan_deflection[0] - w_static) / w_static).abs() < 1e-6);
    assert!((h.contact_force[0] / p - 1.0).abs() < 1e-6);
    let yw = w_static - p / c.contact_stiffness;
    assert!((h.wheel_displacement[0] - yw).abs() < 1e-6 * yw.abs());
    assert!(contact_events(&h.events).is_empty());
}

/// Brute-force cross-check of the event machinery: a fixed-step classical RK4 of the same
/// equations with F = k_c·max(δ, 0) evaluated pointwise (no event location at all, coded
/// independently here), dt = 1 µs, must agree with the reference on the first two separations.
#[test]
fn brute_force_rk4_agrees_on_first_separations() {
    let c = separating_case();
    let t_end: f64 = 0.12;
    let n = c.modes;
    let pi = std::f64::consts::PI;
    let om: Vec<f64> = (1..=n).map(|j| c.natural_frequency(j)).collect();
    let delta_of = |t: f64, y: &[f64]| -> f64 {
        let x = c.start_position + c.speed * t;
        let mut s = 0.0;
        if (0.0..=c.length).contains(&x) {
            for j in 0..n {
                s += y[j] * ((j + 1) as f64 * pi * x / c.length).sin();
            }
        }
        if x >= 0.0 {
            s += c.roughness_amplitude
                * (2.0 * pi * x / c.roughness_wavelength + c.roughness_phase).sin();
        }
        s - y[2 * n + 2]
    };
    let rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
        let x = c.start_position + c.speed * t;
        let f = c.contact_stiffness * delta_of(t, y).max(0.0);
        for j in 0..n {
            dy[j] = y[n + j];
            dy[n + j] = -2.0 * c.damping_ratio * om[j] * y[n + j] - om[j] * om[j] * y[j];
            if (0.0..=c.length).contains(&x) {
                dy[n + j] -= 2.0 * f / (c.mass_per_length * c.length)
                    * ((j + 1) as f64 * pi * x / c.length).sin();
            }
        }
        let (ys, vs, yw, vw) = (y[2 * n], y[2 * n + 1], y[2 * n + 2], y[2 * n + 3]);
        let fs = c.suspension_stiffness * (ys - yw) + c.suspension_damping * (vs - vw);
        dy[2 * n] = vs;
        dy[2 * n + 1] = -fs / c.sprung_mass - G;
        dy[2 * n + 2] = vw;
        dy[2 * n + 3] = (fs + f) / c.unsprung_mass - G;
    };
    let p = c.static_load();
    let mut y = vec![0.0; 2 * n + 4];
    y[2 * n + 2] = -p / c.contact_stiffness;
    y[2 * n] = y[2 * n + 2] - c.sprung_mass * G / c.suspension_stiffness;
    let dt = 1e-6;
    let steps = (t_end / dt).round() as usize;
    let dim = y.len();
    let (mut k1, mut k2, mut k3, mut k4, mut yt) = (
        vec![0.0; dim],
        vec![0.0; dim],
        vec![0.0; dim],
        vec![0.0; dim],
        vec![0.0; dim],
    );
    let (mut fmax, mut gmax) = (0.0f64, 0.0f64);
    let mut crossings = Vec::new();
    let mut prev_delta = delta_of(0.0, &y);
    for i in 0..steps {
        let t = i as f64 * dt;
        rhs(t, &y, &mut k1);
        for m in 0..dim {
            yt[m] = y[m] + 0.5 * dt * k1[m];
        }
        rhs(t + 0.5 * dt, &yt, &mut k2);
        for m in 0..dim {
            yt[m] = y[m] + 0.5 * dt * k2[m];
        }
        rhs(t + 0.5 * dt, &yt, &mut k3);
        for m in 0..dim {
            yt[m] = y[m] + dt * k3[m];
        }
        rhs(t + dt, &yt, &mut k4);
        for m in 0..dim {
            y[m] += dt / 6.0 * (k1[m] + 2.0 * k2[m] + 2.0 * k3[m] + k4[m]);
        }
        let d = delta_of(t + dt, &y);
        fmax = fmax.max(c.contact_stiffness * d);
        gmax = gmax.max(-d);
        if (d > 0.0) != (prev_delta > 0.0) {
            // linear interpolation of the crossing inside the step
            crossings.push(t + dt * prev_delta / (prev_delta - d));
        }
        prev_delta = d;
    }
    let (f_ref, g_ref, ev) = extremes(&c, t_end, 1e-10);
    let ce = contact_events(&ev);
    println!(
        "RK4 brute force: max F {fmax:.9e} (ref {f_ref:.9e}), max gap {gmax:.9e} (ref {g_ref:.9e})"
    );
    println!("crossings RK4 {crossings:?}");
    println!(
        "crossings ref {:?}",
        ce.iter().map(|e| e.time).collect::<Vec<_>>()
    );
    assert_eq!(crossings.len(), ce.len());
    for (a, e) in crossings.iter().zip(&ce) {
        assert!((a - e.time).abs() < 1e-8, "{a} vs {e:?}");
    }
    assert!((fmax - f_ref).abs() < 1e-6 * f_ref, "{fmax} vs {f_ref}");
    assert!((gmax - g_ref).abs() < 1e-5 * g_ref, "{gmax} vs {g_ref}");
}
