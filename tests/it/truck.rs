//! The H20-44 seven-DOF truck, the random road profile and the `iterative`
//! solver (the plate paper's Sections 2.2–2.5). Each test states its source
//! and tolerance.

use crate::support;

use std::f64::consts::PI;

use support::{assert_histories_agree, run_yaml};
use vbi::scenario::resolved::{H20Truck, Surface};
use vbi::scenario::truck::H20_44_PRESET;
use vbi::surface::Profile;
use vbi::vehicle::h20_44;

/// The preset truck at 20 m/s on a beam (g = 9.81 m/s²).
fn preset_truck() -> vbi::vehicle::VehicleModel {
    let truck = H20Truck {
        speed: 20.0,
        acceleration: 0.0,
        entry_time: 0.0,
        lateral_position: None,
        parameters: H20_44_PRESET,
    };
    h20_44::build(&truck, 9.81)
}

/// The preset's static wheel loads are the plate paper's (Section 3.2, after
/// Eq. 8): 58.81 kN under each front wheel and 32.42 kN under each rear wheel
/// of the empty truck, to the paper's rounding (±5 N), both from the lever
/// rule and from the vehicle model's own static equilibrium.
#[test]
fn preset_static_wheel_loads_match_the_paper() {
    let loads = h20_44::static_wheel_loads(&H20_44_PRESET, 9.81);
    for (load, paper) in loads.iter().zip([58_810.0, 58_810.0, 32_420.0, 32_420.0]) {
        assert!((load - paper).abs() <= 5.0, "{load} N against {paper} N");
    }
    let model = preset_truck();
    let (_, forces) = model.static_equilibrium(1, &|_| 0.0).expect("equilibrium");
    for (force, load) in forces.iter().zip(loads) {
        assert!(
            (force - load).abs() <= 1e-6 * load,
            "equilibrium {force} N against lever rule {load} N"
        );
    }
}

/// The assembled matrices reproduce the truck's equations of motion written
/// out element by element (the plate paper's Eqs. 5, 7 and 12.1–12.7, in our
/// sign convention: up, nose up and left side up positive): for random
/// displacements and velocities, K u + C u̇ equals minus the generalised
/// spring and damper forces, to round-off (1e-12 of their scale). This
/// checks every one of the 2 × 28 independent matrix entries of Appendix A.
#[test]
fn matrices_match_the_equations_of_motion() {
    let p = H20_44_PRESET;
    let model = preset_truck();
    let mut seed = 12345u64;
    let mut random = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for _ in 0..20 {
        let u: Vec<f64> = (0..11).map(|_| 0.01 * random()).collect();
        let v: Vec<f64> = (0..11).map(|_| 0.1 * random()).collect();
        // Generalised forces of the springs and dampers on each DOF.
        let generalised = |x: &[f64], ks: [f64; 2], kt: [f64; 2]| -> Vec<f64> {
            let (zv, th, ph) = (x[0], x[1], x[2]);
            let axle = [(x[3], x[4]), (x[5], x[6])];
            let ahead = [p.front_axle_to_centre, -p.centre_to_rear_axle];
            let half_s = [
                p.front_suspension_spacing / 2.0,
                p.rear_suspension_spacing / 2.0,
            ];
            let half_t = [p.front_track / 2.0, p.rear_track / 2.0];
            let mut g = vec![0.0; 11];
            for a in 0..2 {
                for (side, e) in [(0, -1.0), (1, 1.0)] {
                    // Suspension force f (tension positive: pulls body down, axle up).
                    let body = zv + ahead[a] * th + e * half_s[a] * ph;
                    let seat = axle[a].0 + e * half_s[a] * axle[a].1;
                    let f = ks[a] * (body - seat);
                    g[0] -= f;
                    g[1] -= ahead[a] * f;
                    g[2] -= e * half_s[a] * f;
                    g[3 + 2 * a] += f;
                    g[4 + 2 * a] += e * half_s[a] * f;
                    // Tyre force F between the axle end and the contact point.
                    let wheel = 2 * a + side;
                    let hub = axle[a].0 + e * half_t[a] * axle[a].1;
                    let tyre = kt[a] * (hub - x[7 + wheel]);
                    g[3 + 2 * a] -= tyre;
                    g[4 + 2 * a] -= e * half_t[a] * tyre;
                    g[7 + wheel] += tyre;
                }
            }
            g
        };
        let spring = generalised(
            &u,
            [p.front_suspension_stiffness, p.rear_suspension_stiffness],
            [p.front_tyre_stiffness, p.rear_tyre_stiffness],
        );
        let damper = generalised(
            &v,
            [p.front_suspension_damping, p.rear_suspension_damping],
            [p.front_tyre_damping, p.rear_tyre_damping],
        );
        for i in 0..11 {
            let ku: f64 = (0..11).map(|j| model.stiffness[(i, j)] * u[j]).sum();
            let cv: f64 = (0..11).map(|j| model.damping[(i, j)] * v[j]).sum();
            let scale = 1e-12 * p.front_tyre_stiffness * 0.1;
            assert!(
                (ku + spring[i]).abs() <= scale,
                "K row {i}: {ku} vs {}",
                -spring[i]
            );
            assert!(
                (cv + damper[i]).abs() <= scale,
                "C row {i}: {cv} vs {}",
                -damper[i]
            );
        }
    }
    // Symmetric, as Appendix A states.
    assert_eq!(model.stiffness, model.stiffness.transpose());
    assert_eq!(model.damping, model.damping.transpose());
}

/// The random profile is the plate paper's Eq. 17: at sample points
/// the period grid equals the series summed term by term with its own
/// cosines (1e-10 of the summed amplitudes), r(0) = 0, the slope and curvature are
/// the series' derivatives (central differences, 1e-6 relative), the same
/// seed gives the same profile and another seed another one.
#[test]
fn random_profile_is_the_papers_series() {
    let surface = Surface::Random {
        class: None,
        coefficient: 16e-6,
        sampling_length: 156.0,
        terms: 312,
        seed: 7,
    };
    let profile = Profile::build(&surface, 100.0).unwrap();
    let Profile::Random {
        fundamental,
        ref terms,
        offset,
        ..
    } = profile
    else {
        panic!("a random profile");
    };
    // Eq. 16–17 amplitudes: aᵢ = √(4 A_r (iΔΩ/Ω₀)⁻² ΔΩ), ΔΩ = 2π/L_c, Ω₀ = 1/2π.
    for (i, &(c, s)) in terms.iter().enumerate() {
        let k = (i + 1) as f64 * 2.0 * PI / 156.0;
        let expected = (4.0 * 16e-6 * (k * 2.0 * PI).powi(-2) * (2.0 * PI / 156.0)).sqrt();
        assert!(((c * c + s * s).sqrt() - expected).abs() <= 1e-14);
    }
    let direct = |x: f64| -> f64 {
        terms
            .iter()
            .enumerate()
            .map(|(i, &(c, s))| {
                let phase = s.atan2(c);
                let amplitude = (c * c + s * s).sqrt();
                amplitude * ((i + 1) as f64 * fundamental * x - phase).cos()
            })
            .sum::<f64>()
            - offset
    };
    let scale: f64 = terms.iter().map(|&(c, s)| (c * c + s * s).sqrt()).sum();
    assert!(profile.elevation(0.0).abs() <= 1e-15);
    assert_eq!(profile.elevation(-3.0), 0.0);
    for &x in &[0.37, 12.9, 55.5, 101.25, 155.0] {
        let (r, slope, curvature) = profile.elevation_slope_curvature(x);
        // The period grid interpolates the series (quintic Hermite, 32
        // nodes per shortest wave): measured 1.7e-11 of the largest |r|.
        assert!((r - direct(x)).abs() <= 1e-10 * scale, "x = {x}");
        let h = 1e-4;
        let fd_slope = (direct(x + h) - direct(x - h)) / (2.0 * h);
        let (slope_plus, slope_minus) = (
            profile.elevation_slope_curvature(x + h).1,
            profile.elevation_slope_curvature(x - h).1,
        );
        let fd_curvature = (slope_plus - slope_minus) / (2.0 * h);
        assert!(
            (slope - fd_slope).abs() <= 1e-6 * slope.abs().max(1e-3),
            "slope at {x}"
        );
        assert!(
            (curvature - fd_curvature).abs() <= 1e-5 * curvature.abs().max(1e-2),
            "curvature at {x}"
        );
    }
    assert_eq!(Profile::build(&surface, 100.0).unwrap(), profile);
    let other = Profile::build(
        &Surface::Random {
            class: None,
            coefficient: 16e-6,
            sampling_length: 156.0,
            terms: 312,
            seed: 8,
        },
        100.0,
    )
    .unwrap();
    assert!((other.elevation(30.0) - profile.elevation(30.0)).abs() > 1e-6);
}

/// The profile's variance over one period is Σ aᵢ²/2 (Parseval), which is
/// 2 Σ S(Ωᵢ) ΔΩ: the discrete two-sided PSD the paper's Eq. 15 samples.
/// Measured on 20 000 points of one period of a fresh seed: within 1e-9.
#[test]
fn random_profile_variance_is_the_spectrum_integral() {
    let (coefficient, length, terms) = (64e-6, 100.0, 200);
    let profile = Profile::build(
        &Surface::Random {
            class: None,
            coefficient,
            sampling_length: length,
            terms,
            seed: 11,
        },
        100.0,
    )
    .unwrap();
    let n = 20_000;
    let samples: Vec<f64> = (0..n)
        .map(|i| profile.elevation(length * i as f64 / n as f64))
        .collect();
    let mean = samples.iter().sum::<f64>() / n as f64;
    let variance = samples.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / n as f64;
    let d_omega = 2.0 * PI / length;
    let spectral: f64 = (1..=terms)
        .map(|i| {
            let omega = i as f64 * d_omega;
            2.0 * coefficient * (omega * 2.0 * PI).powi(-2) * d_omega
        })
        .sum();
    assert!(
        (variance - spectral).abs() <= 1e-9 * spectral,
        "variance {variance} against 2ΣSΔΩ = {spectral}"
    );
}

/// A three-span beam crossed by the truck on a rough road: the `iterative`
/// solver (the paper's uncoupled scheme, tolerance 1e-10) and `coupled`
/// (the same equations solved together) agree to 1e-11 of each history's
/// peak (measured 2.3e-12 at most, the pitch), and the iteration converges
/// in a few passes (the paper: about two).
#[test]
fn iterative_agrees_with_coupled_for_the_truck() {
    let scene = |method: &str| {
        format!(
            r#"
name: truck-{method}
bridge:
  type: beam
  spans: [24.0, 30.0, 24.0]
  bending_stiffness: 3.3e10
  mass_per_length: 9500.0
  damping: {{type: modal, ratio: 0.02}}
vehicles:
  - type: h20_44
    speed: 30.0
surface: {{type: random, class: good, seed: 3}}
solver: {{method: {method}, time_step: 3.12e-3{extra}}}
record:
  - {{name: mid2, quantity: bridge_displacement, x: 39.0}}
  - {{name: acc2, quantity: bridge_acceleration, x: 39.0}}
  - {{name: f1, quantity: contact_force, vehicle: 1, wheel: 1}}
  - {{name: f4, quantity: contact_force, vehicle: 1, wheel: 4}}
  - {{name: pitch, quantity: vehicle_displacement, vehicle: 1, dof: body_pitch}}
"#,
            extra = if method == "iterative" {
                ", tolerance: 1.0e-10"
            } else {
                ""
            }
        )
    };
    let iterative = run_yaml(&scene("iterative"));
    let coupled = run_yaml(&scene("coupled"));
    assert_histories_agree(
        &iterative,
        &coupled,
        &["mid2", "acc2", "f1", "f4", "pitch"],
        1e-11,
    );
    let stats = iterative.summary.run.iterations.expect("iteration counts");
    assert!(stats.mean <= 4.0 && stats.max <= 6, "{stats:?}");
}

/// A very slow crossing on a smooth deck is the static influence line: the
/// truck at 1 m/s over the three-span beam gives a mid-span DAF of 1 within
/// 1e-3 (measured 1.7e-4 and 1.5e-4 at the middles of spans 1 and 2; the
/// rest is modal truncation and the truck's own slow pitch).
#[test]
fn slow_truck_crossing_is_static() {
    let outcome = run_yaml(
        r#"
name: slow-truck
bridge:
  type: beam
  spans: [24.0, 30.0, 24.0]
  bending_stiffness: 3.3e10
  mass_per_length: 9500.0
  damping: {type: modal, ratio: 0.02}
vehicles:
  - type: h20_44
    speed: 1.0
solver: {method: iterative, time_step: 0.01}
record:
  - {name: mid1, quantity: bridge_displacement, x: 12.0}
  - {name: mid2, quantity: bridge_displacement, x: 39.0}
"#,
    );
    for q in &outcome.summary.quantities {
        let daf = q.daf.expect("a DAF");
        eprintln!("{}: DAF {daf:.6}", q.name);
        assert!((daf - 1.0).abs() <= 1e-3, "{}: DAF {daf}", q.name);
    }
}
