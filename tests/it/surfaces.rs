//! Surfaces: the track and road spectra against their sources and closed
//! forms, the random samples' statistics against the spectra, measured
//! profiles, the deterministic shapes against hand values, determinism, and
//! located errors for bad surface input.

use std::f64::consts::PI;

use crate::support::Scratch;

use vbi::scenario::resolved::{Rails, Sampling, Surface, TrackDirection};
use vbi::scene::{Interference, IsoClass, Spectrum};
use vbi::surface::spectrum::{
    fra_alignment, fra_vertical, german_alignment, german_vertical, iso8608,
};
use vbi::surface::synth::SpectralSeries;
use vbi::surface::{Profile, Rail};

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// ISO 8608 tabulates each class twice: by G_d(n₀ = 0.1 cycle/m) in
/// m²/(cycle/m) (geometric means 16, 64, …, 262144 × 1e-6 m³) and by
/// G_d(Ω₀ = 1 rad/m) in m²/(rad/m) (1, 4, …, 16384 × 1e-6 m³). Our function
/// takes the first and must give the second: (0.2π)²/(2π) · 16e-6 =
/// 1.005e-6 against the table's rounded 1e-6 (0.5 %).
#[test]
fn iso8608_matches_its_angular_table() {
    let classes = [
        IsoClass::A,
        IsoClass::B,
        IsoClass::C,
        IsoClass::D,
        IsoClass::E,
        IsoClass::F,
        IsoClass::G,
        IsoClass::H,
    ];
    for (i, class) in classes.into_iter().enumerate() {
        let table = 1e-6 * 4f64.powi(i as i32);
        assert!(close(iso8608(class, 1.0), table, 0.01), "{class:?}");
        // And its own definition at n₀: G(Ω₀) · 2π = G_d(n₀).
        let at_n0 = iso8608(class, 2.0 * PI * 0.1) * 2.0 * PI;
        assert!(close(at_n0, 16e-6 * 4f64.powi(i as i32), 1e-12));
        // Waviness w = 2: halving the wavenumber quadruples the density.
        assert!(close(iso8608(class, 0.5), 4.0 * iso8608(class, 1.0), 1e-12));
    }
}

/// FRA: k A Ω_c² / (Ω² (Ω² + Ω_c²)) with k = 0.25, Ω_c = 0.8245 rad/m and the
/// class table's A_v (cm²·rad/m): class 5 (A_v = 0.2095) at Ω = 1 rad/m by
/// hand: 0.25 · 0.2095e-4 · 0.67980 / 1.67980 = 2.1196e-6 m²/(rad/m); class
/// 6 alignment (A_a = 0.0339) at Ω = 2: 0.25 · 0.0339e-4 · 0.67980 /
/// (4 · 4.67980) = 3.0778e-8. Asymptotes: kA/Ω² far below Ω_c, kAΩ_c²/Ω⁴ far
/// above.
#[test]
fn fra_spectra_match_hand_values_and_asymptotes() {
    assert!(close(fra_vertical(5, 1.0), 2.1196e-6, 1e-4));
    assert!(close(fra_alignment(6, 2.0), 3.0778e-8, 1e-4));
    let a_v = [1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339];
    for (i, a) in a_v.iter().enumerate() {
        let class = i as u8 + 1;
        let low = 1e-4;
        assert!(close(
            fra_vertical(class, low),
            0.25 * a * 1e-4 / (low * low),
            1e-7
        ));
        let high = 1e3;
        assert!(close(
            fra_vertical(class, high),
            0.25 * a * 1e-4 * 0.8245f64.powi(2) / high.powi(4),
            1e-5
        ));
    }
    // Better classes are smoother at every wavenumber.
    for class in 1..6 {
        assert!(fra_vertical(class + 1, 0.7) < fra_vertical(class, 0.7));
    }
}

/// German high-speed: A Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)), Ω_c = 0.8246,
/// Ω_r = 0.0206 rad/m. By hand at Ω = Ω_c, low interference
/// (A_v = 4.032e-7): 4.032e-7 · 0.67996 / (0.68038 · 1.35992) = 2.9629e-7;
/// high interference alignment (A_a = 6.125e-7) at Ω = 0.1:
/// 6.125e-7 · 0.67996 / (0.010424 · 0.68996) = 5.7906e-5.
#[test]
fn german_spectra_match_hand_values() {
    assert!(close(
        german_vertical(Interference::Low, 0.8246),
        2.9629e-7,
        1e-4
    ));
    assert!(close(
        german_alignment(Interference::High, 0.1),
        5.7906e-5,
        1e-4
    ));
    assert!(
        german_vertical(Interference::High, 1.0) / german_vertical(Interference::Low, 1.0) > 2.67
    );
}

/// The closed-form band variances against a Simpson integral of the
/// densities (20 000 intervals in log Ω): within 1e-6.
#[test]
fn band_variance_closed_forms_match_quadrature() {
    let spectra = [
        Spectrum::Fra { class: 1 },
        Spectrum::Fra { class: 5 },
        Spectrum::German {
            interference: Interference::Low,
        },
        Spectrum::Iso8608 { class: IsoClass::C },
        Spectrum::FraAlignment { class: 2 },
        Spectrum::GermanAlignment {
            interference: Interference::High,
        },
    ];
    let (lo, hi) = (2.0 * PI / 80.0, 2.0 * PI);
    for s in spectra {
        let n = 20_000;
        let (a, b) = (lo.ln(), hi.ln());
        let h = (b - a) / n as f64;
        // ∫ G dΩ = ∫ G(e^u) e^u du.
        let f = |u: f64| s.density(u.exp()) * u.exp();
        let mut sum = f(a) + f(b);
        for i in 1..n {
            sum += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        let quadrature = sum * h / 3.0;
        assert!(
            close(s.band_variance(lo, hi), quadrature, 1e-6),
            "{s:?}: {} vs {quadrature}",
            s.band_variance(lo, hi)
        );
    }
}

/// The mean over samples of each sample's mean square (at 4 000 points
/// 0.5 m apart: 2 km, so that each sample holds many of the longest waves)
/// against ∫ G over the band: within 2 % for every kind of
/// spectrum (400 samples, seeds 1…400, rail band 1–80 m, road 0.5–100 m).
/// Measured: 0.9993 (FRA 5), 0.9994 (German high), 0.9985 (ISO B), the
/// FRA 5 alignment as its vertical profile (same shape, A_a for A_v). The
/// mean of each sample's Σaᵢ²/2 is checked within 1 % (measured 1.0000:
/// with a random frequency per bin it is unbiased).
#[test]
fn mean_sample_variance_is_the_band_integral() {
    let cases = [
        (Spectrum::Fra { class: 5 }, 1.0, 80.0),
        (
            Spectrum::German {
                interference: Interference::High,
            },
            1.0,
            80.0,
        ),
        (Spectrum::Iso8608 { class: IsoClass::B }, 0.5, 100.0),
        (Spectrum::FraAlignment { class: 5 }, 1.0, 80.0),
    ];
    for (spectrum, short, long) in cases {
        let terms = vbi::surface::synth::default_terms(short, long);
        let target = spectrum.band_variance(2.0 * PI / long, 2.0 * PI / short);
        let samples = 400;
        let mut mean = 0.0;
        let mut lines = 0.0;
        for seed in 1..=samples {
            let series = SpectralSeries::new(&spectrum, short, long, terms, seed, 0);
            let nodes = series.sample(0.0, 0.5, 4000).unwrap();
            mean += nodes.iter().map(|n| n.0 * n.0).sum::<f64>() / nodes.len() as f64;
            lines += series.variance();
        }
        mean /= samples as f64;
        lines /= samples as f64;
        eprintln!(
            "{}: mean sample variance / band integral = {:.4}, mean Σa²/2 / band integral = {:.4}",
            spectrum.label(),
            mean / target,
            lines / target
        );
        assert!(close(mean, target, 0.02), "{}", spectrum.label());
        assert!(close(lines, target, 0.01), "{}", spectrum.label());
    }
}

/// A Welch estimate (Hann window over 102.4 m, 800 samples averaged, each
/// estimate averaged over the 7 DFT bins within ±0.18 rad/m) follows the FRA
/// class 4 density within 10 % at Ω = 1, 1.5, 2, 3 and 4 rad/m (wavelengths
/// 1.6–6.3 m, inside the 1–80 m band and clear of its edges). With one-sided
/// G: Ĝ(Ω) = h |Σ w_j r_j e^{−iΩx_j}|² / (π Σ w_j²). Measured: ratios
/// 1.031, 0.988, 1.037, 1.030, 0.998 (the sampling error of 800 × 7
/// correlated periodogram bins is about 2 %).
#[test]
fn welch_estimate_follows_the_fra_density() {
    let spectrum = Spectrum::Fra { class: 4 };
    let (h, n) = (0.1, 1024);
    let length = h * n as f64;
    let window: Vec<f64> = (0..n)
        .map(|j| 0.5 - 0.5 * (2.0 * PI * j as f64 / n as f64).cos())
        .collect();
    let norm: f64 = window.iter().map(|w| w * w).sum();
    let samples = 800;
    let series: Vec<Vec<f64>> = (1..=samples)
        .map(|seed| {
            SpectralSeries::new(&spectrum, 1.0, 80.0, 190, seed, 0)
                .sample(0.0, h, n)
                .unwrap()
                .into_iter()
                .map(|t| t.0)
                .collect()
        })
        .collect();
    let bin = 2.0 * PI / length;
    for omega in [1.0, 1.5, 2.0, 3.0, 4.0] {
        let mut estimate = 0.0;
        let mut target = 0.0;
        let centre = (omega / bin).round() as i64;
        for k in centre - 3..=centre + 3 {
            let w = k as f64 * bin;
            target += spectrum.density(w);
            for r in &series {
                let (mut re, mut im) = (0.0, 0.0);
                for (j, (x, win)) in r.iter().zip(&window).enumerate() {
                    let (s, c) = (w * h * j as f64).sin_cos();
                    re += win * x * c;
                    im -= win * x * s;
                }
                estimate += h * (re * re + im * im) / (PI * norm);
            }
        }
        estimate /= samples as f64;
        eprintln!("Ω = {omega}: Welch / target = {:.4}", estimate / target);
        assert!(
            close(estimate, target, 0.10),
            "Ω = {omega}: {estimate} vs {target}"
        );
    }
}

fn fra(class: u8, seed: u64, rails: Rails) -> Surface {
    Surface::Fra {
        class,
        sampling: Sampling {
            shortest_wavelength: 1.0,
            longest_wavelength: 80.0,
            terms: 190,
            seed,
            rails,
            run_in: 0.0,
            alignment: false,
        },
    }
}

/// The rails' alignment (`alignment: true`) is sampled from the class's
/// alignment spectrum on random streams 2 (left) and 3 (right) of the
/// seed, so the vertical profile is bit-identical with or without it; a
/// wheelset follows the mean of its two rails' alignment (the track's
/// centre line), which at the grid nodes is exactly the mean of the two
/// series shifted to start at 0 (identical rails: stream 2 alone); without
/// `alignment` it is 0.
#[test]
fn alignment_is_sampled_on_its_own_streams() {
    for rails in [Rails::Identical, Rails::Independent] {
        let plain = fra(5, 9, rails);
        let Surface::Fra { class, sampling } = plain.clone() else {
            unreachable!()
        };
        let aligned = Surface::Fra {
            class,
            sampling: Sampling {
                alignment: true,
                ..sampling
            },
        };
        let (a, b) = (
            Profile::build(&plain, 400.0).unwrap(),
            Profile::build(&aligned, 400.0).unwrap(),
        );
        let stream = |k| {
            SpectralSeries::new(&Spectrum::FraAlignment { class: 5 }, 1.0, 80.0, 190, 9, k)
                .sample(0.0, 0.1, 4001)
                .unwrap()
        };
        let left = stream(2);
        let right = if rails == Rails::Independent {
            stream(3)
        } else {
            left.clone()
        };
        let mut rms = 0.0;
        for j in 0..4001 {
            let x = j as f64 * 0.1;
            for rail in [Rail::Left, Rail::Right] {
                assert_eq!(
                    a.elevation_slope_curvature_on(rail, x),
                    b.elevation_slope_curvature_on(rail, x)
                );
            }
            assert_eq!(a.alignment_at(x), (0.0, 0.0, 0.0));
            let expected = 0.5 * ((left[j].0 - left[0].0) + (right[j].0 - right[0].0));
            let got = b.alignment_at(x).0;
            rms += expected * expected;
            assert!(
                (got - expected).abs() <= 1e-12,
                "x = {x}: {got} against {expected}"
            );
        }
        assert!(rms > 0.0);
    }
}

/// The grid the solvers evaluate equals the series it samples (shifted to
/// start at 0) between its nodes: r within 1e-5 of the profile's RMS, slope
/// within 1e-4 of its RMS and curvature within 1e-2 of its RMS (quintic
/// Hermite at 10 nodes per shortest wavelength; measured 1.7e-8, 2.6e-6,
/// 1.0e-4); and it is 0 on the approach.
#[test]
fn sampled_grid_interpolates_the_series() {
    let surface = fra(3, 42, Rails::Identical);
    let profile = Profile::build(&surface, 60.0).unwrap();
    let series = SpectralSeries::new(&Spectrum::Fra { class: 3 }, 1.0, 80.0, 190, 42, 0);
    let r0 = series.at(0.0).0;
    let (mut e, mut rms) = ([0.0f64; 3], [0.0f64; 3]);
    let n = 5_000;
    for i in 0..n {
        let x = 59.9 * (i as f64 + 0.37) / n as f64;
        let exact = series.at(x);
        let got = profile.elevation_slope_curvature(x);
        for (k, (g, t)) in [(got.0, exact.0 - r0), (got.1, exact.1), (got.2, exact.2)]
            .into_iter()
            .enumerate()
        {
            e[k] = e[k].max((g - t).abs());
            rms[k] += t * t / n as f64;
        }
    }
    let rms = rms.map(f64::sqrt);
    eprintln!(
        "grid error / RMS: r {:.2e}, slope {:.2e}, curvature {:.2e}",
        e[0] / rms[0],
        e[1] / rms[1],
        e[2] / rms[2]
    );
    assert!(e[0] < 1e-5 * rms[0] && e[1] < 1e-4 * rms[1] && e[2] < 1e-2 * rms[2]);
    assert_eq!(profile.elevation_slope_curvature(-2.0), (0.0, 0.0, 0.0));
    assert_eq!(profile.elevation(0.0), 0.0);
}

/// A run-in of 30 m: 0 with zero slope and curvature before x = −30 m, the
/// unshifted series from the entrance on (within the grid's error), and
/// r, r′, r″ continuous through the fade (no jump larger than the change
/// over a thousandth of the run-in).
#[test]
fn run_in_fades_the_profile_in_on_the_approach() {
    let Surface::Fra {
        class,
        mut sampling,
    } = fra(4, 5, Rails::Identical)
    else {
        unreachable!()
    };
    sampling.run_in = 30.0;
    let profile = Profile::build(&Surface::Fra { class, sampling }, 40.0).unwrap();
    let series = SpectralSeries::new(&Spectrum::Fra { class: 4 }, 1.0, 80.0, 190, 5, 0);
    assert_eq!(profile.elevation_slope_curvature(-30.0), (0.0, 0.0, 0.0));
    assert_eq!(profile.elevation_slope_curvature(-45.0), (0.0, 0.0, 0.0));
    let rms = (series.variance()).sqrt();
    for x in [0.0, 0.05, 3.3, 17.71, 39.0] {
        assert!(
            (profile.elevation(x) - series.at(x).0).abs() < 1e-6 * rms,
            "{x}"
        );
    }
    let mut previous = profile.elevation_slope_curvature(-30.0);
    let step = 0.03;
    for i in 1..=1000 {
        let now = profile.elevation_slope_curvature(-30.0 + step * i as f64);
        assert!((now.0 - previous.0).abs() < 0.05 * rms);
        previous = now;
    }
    // Halfway, S(1/2) = 1/2.
    let half = profile.elevation(-15.0);
    assert!((half - 0.5 * series.at(-15.0).0).abs() < 1e-6 * rms);
}

/// The same seed gives a bit-identical profile; another seed, or the other
/// rail of independent rails, another one; identical rails are one profile.
#[test]
fn seeds_and_rails() {
    let a = Profile::build(&fra(5, 9, Rails::Independent), 50.0).unwrap();
    let b = Profile::build(&fra(5, 9, Rails::Independent), 50.0).unwrap();
    assert_eq!(a, b);
    for x in [0.3, 7.7, 31.2] {
        assert_eq!(
            a.elevation_on(Rail::Right, x).to_bits(),
            b.elevation_on(Rail::Right, x).to_bits()
        );
        assert_ne!(
            a.elevation_on(Rail::Left, x),
            a.elevation_on(Rail::Right, x)
        );
    }
    let c = Profile::build(&fra(5, 10, Rails::Independent), 50.0).unwrap();
    assert_ne!(a.elevation(20.0), c.elevation(20.0));
    let same = Profile::build(&fra(5, 9, Rails::Identical), 50.0).unwrap();
    assert_eq!(
        same.elevation_on(Rail::Left, 12.0),
        same.elevation_on(Rail::Right, 12.0)
    );
    assert_eq!(
        same.elevation_on(Rail::Left, 12.0),
        a.elevation_on(Rail::Left, 12.0)
    );
    assert_eq!(Rail::of_lateral(0.75), Rail::Left);
    assert_eq!(Rail::of_lateral(-0.75), Rail::Right);
    assert_eq!(Rail::of_lateral(0.0), Rail::Left);
}

#[test]
fn reseeding() {
    let s = fra(2, 1, Rails::Identical);
    assert!(s.is_random());
    assert_eq!(s.reseeded(77), fra(2, 77, Rails::Identical));
    let ramp = Surface::Ramp {
        start: 1.0,
        length: 2.0,
        height: 0.01,
        direction: TrackDirection::Vertical,
    };
    assert!(!ramp.is_random());
    assert_eq!(ramp.reseeded(5), ramp);
    let random = Surface::Random {
        class: None,
        coefficient: 1e-6,
        sampling_length: 10.0,
        terms: 20,
        seed: 3,
    };
    assert!(random.is_random());
    assert!(matches!(
        random.reseeded(4),
        Surface::Random { seed: 4, .. }
    ));
}

/// Ramp, step, bump and dip against values by hand.
#[test]
fn shapes_by_hand() {
    let ramp = Profile::build(
        &Surface::Ramp {
            start: 2.0,
            length: 4.0,
            height: 0.02,
            direction: TrackDirection::Vertical,
        },
        20.0,
    )
    .unwrap();
    assert_eq!(ramp.elevation_slope_curvature(1.0), (0.0, 0.0, 0.0));
    assert_eq!(ramp.elevation_slope_curvature(3.0), (0.005, 0.005, 0.0));
    assert_eq!(ramp.elevation_slope_curvature(9.0), (0.02, 0.0, 0.0));
    let step = Profile::build(
        &Surface::Step {
            position: 5.0,
            height: -0.003,
            direction: TrackDirection::Vertical,
        },
        20.0,
    )
    .unwrap();
    assert_eq!(step.elevation(4.999), 0.0);
    assert_eq!(step.elevation(5.0), -0.003);
    // Bump 10 mm over 2 m from x = 3: peak at 4 m; at 3.5 m r = h/2, slope
    // (h/2)(2π/L) = 0.005 π, curvature 0.
    let bump = Surface::Bump {
        start: 3.0,
        length: 2.0,
        height: 0.01,
        direction: TrackDirection::Vertical,
    };
    let p = Profile::build(&bump, 20.0).unwrap();
    assert!((p.elevation(4.0) - 0.01).abs() < 1e-15);
    let (r, s, c) = p.elevation_slope_curvature(3.5);
    assert!((r - 0.005).abs() < 1e-15 && (s - 0.005 * PI).abs() < 1e-15 && c.abs() < 1e-15);
    // At the peak the curvature is −h/2 (2π/L)² = −0.005 π².
    assert!((p.elevation_slope_curvature(4.0).2 + 0.005 * PI * PI).abs() < 1e-14);
    assert_eq!(p.elevation(2.9), 0.0);
    assert_eq!(p.elevation(5.1), 0.0);
    let pl = Profile::build(
        &Surface::PiecewiseLinear {
            points: vec![[0.0, 0.0], [2.0, 0.004], [5.0, -0.002]],
            direction: TrackDirection::Vertical,
        },
        20.0,
    )
    .unwrap();
    assert_eq!(pl.elevation_slope_curvature(1.0), (0.002, 0.002, 0.0));
    assert!((pl.elevation(3.5) - 0.001).abs() < 1e-15);
    assert_eq!(pl.elevation(-1.0), 0.0);
    // Laid sideways (issue 24.6): the rails are level and the shape is the
    // track's alignment, value, slope and curvature alike.
    let lateral = Profile::build(
        &Surface::Bump {
            start: 3.0,
            length: 2.0,
            height: 0.01,
            direction: TrackDirection::Lateral,
        },
        20.0,
    )
    .unwrap();
    for x in [2.0, 3.5, 4.0, 4.7, 6.0] {
        assert_eq!(lateral.elevation_slope_curvature(x), (0.0, 0.0, 0.0));
        assert_eq!(lateral.alignment_at(x), p.elevation_slope_curvature(x));
    }
    assert_eq!(lateral.slope_scale(), 0.0);
    assert_eq!(lateral.alignment_slope_scale(), p.slope_scale());
    assert_eq!(pl.elevation(8.0), -0.002);
}

/// An oscillator crossing a 20 m beam from x = −2 m at 25 m/s with 0.2 s of
/// free vibration: the wheel travels x = −2 … 23 m.
fn scene(surface: &str) -> String {
    format!(
        "name: surface-test
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2423e9
  mass_per_length: 2000.0
  elements_per_span: 20
  modes: {{count: 4}}
vehicles:
  - type: oscillator
    sprung_mass: 4000.0
    unsprung_mass: 1000.0
    stiffness: 4.0e6
    damping: 2.53e4
    speed: 25.0
    start_position: -2.0
surface: {surface}
contact: {{type: permanent}}
solver: {{method: coupled, time_step: 1.0e-3, free_vibration: 0.04}}
"
    )
}

/// Writes `files` into a scratch folder and loads `scene.yaml` from it.
fn load(
    name: &str,
    surface: &str,
    files: &[(&str, &str)],
) -> (
    Scratch,
    String,
    Result<vbi::plan::Loaded, vbi::scenario::LoadError>,
) {
    let dir = Scratch::new("surfaces", name);
    for (file, text) in files {
        std::fs::write(dir.path(file), text).unwrap();
    }
    let path = dir.path("scene.yaml");
    std::fs::write(&path, scene(surface)).unwrap();
    let loaded = vbi::plan::load_file(&path);
    (dir, path.display().to_string(), loaded)
}

/// A measured two-rail profile reproduces itself at its points, each rail
/// its own column, and the whole run goes through.
#[test]
fn measured_profile_reproduces_its_points() {
    let mut csv = String::from("# x, left, right (m)\nx,left,right\n");
    let points: Vec<(f64, f64, f64)> = (0..=60)
        .map(|i| {
            let x = -3.0 + 0.5 * i as f64 + if i % 3 == 1 { 0.1 } else { 0.0 };
            (x, 1e-3 * (0.7 * x).sin(), -5e-4 * (0.3 * x).cos())
        })
        .collect();
    for (x, l, r) in &points {
        csv.push_str(&format!("{x},{l},{r}\n"));
    }
    let (_dir, _, loaded) = load(
        "measured",
        "{type: measured, file: track.csv}",
        &[("track.csv", &csv)],
    );
    let loaded = loaded.unwrap_or_else(|e| panic!("{e}"));
    let profile = Profile::build(&loaded.scenario.surface, 30.0).unwrap();
    for (x, l, r) in &points {
        assert!((profile.elevation_on(Rail::Left, *x) - l).abs() < 1e-15);
        assert!((profile.elevation_on(Rail::Right, *x) - r).abs() < 1e-15);
    }
    let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge).unwrap();
    assert_eq!(model.wheel_rail, vec![Rail::Left]);
}

/// Bad surface input: each gets a located error (file:line:col of the
/// field, and the CSV's line for a bad row).
#[test]
fn bad_surfaces_are_located() {
    let good_csv = "0,0\n10,0.001\n";
    let far_csv = "-2,0\n30,0.001\n";
    // (name, surface, files, the text the error must point at, message).
    type Case<'a> = (&'a str, &'a str, &'a [(&'a str, &'a str)], &'a str, &'a str);
    let cases: &[Case] = &[
        (
            "class7",
            "{type: fra, class: 7}",
            &[],
            "7}",
            "FRA track classes are 1 (worst) to 6 (best), got 7",
        ),
        (
            "negative-band",
            "{type: fra, class: 5, shortest_wavelength: -1.0}",
            &[],
            "-1.0",
            "shortest wavelength must be positive, got -1",
        ),
        (
            "empty-band",
            "{type: german, interference: low, shortest_wavelength: 5.0, longest_wavelength: 2.0}",
            &[],
            "2.0}",
            "the wavelength band is empty",
        ),
        (
            "missing-csv",
            "{type: measured, file: nowhere.csv}",
            &[],
            "nowhere",
            "cannot read the measured profile",
        ),
        (
            "csv-short",
            "{type: measured, file: p.csv}",
            &[("p.csv", good_csv)],
            "p.csv",
            "covers x = 0 … 10 m, but the wheels travel from x = -2.0000 m",
        ),
        (
            "csv-nan",
            "{type: measured, file: p.csv}",
            &[("p.csv", "x,r\n-2,0\n5,NaN\n30,0\n")],
            "p.csv",
            "p.csv:3: column 2: `NaN` is not a finite number",
        ),
        (
            "csv-order",
            "{type: measured, file: p.csv}",
            &[("p.csv", "-2,0\n5,0\n4,0\n30,0\n")],
            "p.csv",
            "p.csv:3: column 1: x = 4 does not exceed the previous row's 5",
        ),
        // Issue 23: features shorter than a step's travel (25 m/s × 1e-3 s
        // = 0.025 m) are missed between steps.
        (
            "bump-shorter-than-step",
            "{type: bump, start: 1.0, length: 1.0e-300, height: 0.01}",
            &[],
            "1.0e-300,",
            "a bump 1e-300 m long is shorter than the 2.5000e-2 m a wheel travels in one time step",
        ),
        (
            "harmonic-aliased",
            "{type: harmonic, amplitude: 0.001, wavelength: 0.04}",
            &[],
            "0.04}",
            "a wavelength of 4e-2 m is shorter than twice the 2.5000e-2 m",
        ),
        (
            "piecewise-segment-shorter-than-step",
            "{type: piecewise_linear, points: [[0, 0], [5, 0], [5.01, 0.01], [30, 0.01]]}",
            &[],
            "[5.01,",
            "use `type: step`",
        ),
        (
            "bump-length",
            "{type: bump, start: 1.0, length: 0.0, height: 0.01}",
            &[],
            "0.0,",
            "bump length must be positive",
        ),
        (
            "points-order",
            "{type: piecewise_linear, points: [[0, 0], [3, 0.01], [2, 0]]}",
            &[],
            "[2, 0]",
            "x must increase strictly",
        ),
        // Issue 24.6: lateral track geometry.
        (
            "lateral-without-train-3d",
            "{type: harmonic, amplitude: 0.001, wavelength: 10.0, direction: lateral}",
            &[],
            "lateral}",
            "only a `train_3d`'s wheelsets follow",
        ),
        (
            "csv-four-columns",
            "{type: measured, file: p.csv}",
            &[("p.csv", "x,l,r,y\n-2,0,0,0\n30,0,0,0\n")],
            "p.csv",
            "p.csv:2: a row has 2 columns (x, elevation), 3 (x, left, right) or 5 (x, left, \
             right, left_lateral, right_lateral), this one has 4",
        ),
        (
            "csv-lateral-infinite",
            "{type: measured, file: p.csv}",
            &[("p.csv", "-2,0,0,0,0\n5,0,0,0,inf\n30,0,0,0,0\n")],
            "p.csv",
            "p.csv:2: column 5: `inf` is not a finite number",
        ),
        (
            "csv-lateral-dropped",
            "{type: measured, file: p.csv}",
            &[("p.csv", "-2,0,0,0,0\n5,0,0\n30,0,0,0,0\n")],
            "p.csv",
            "p.csv:2: this row has 3 columns, the rows above have 5",
        ),
    ];
    for (name, surface, files, at, want) in cases {
        let (_dir, path, loaded) = load(name, surface, files);
        let message = match loaded {
            Ok(_) => panic!("{name}: accepted"),
            Err(e) => e.to_string(),
        };
        // `surface: ` is 9 columns: the surface text starts at column 10.
        let col = 10 + surface.find(at).unwrap();
        let located = format!("{path}:17:{col}: ");
        assert!(
            message.contains(&located),
            "{name}: want `{located}` in\n{message}"
        );
        assert!(
            message.contains(want),
            "{name}: want `{want}` in\n{message}"
        );
    }
    // The control: a profile that covers the travel loads.
    let (_dir, _, loaded) = load(
        "csv-good",
        "{type: measured, file: p.csv}",
        &[("p.csv", far_csv)],
    );
    loaded.unwrap_or_else(|e| panic!("{e}"));
}

/// A two-track vehicle on independent rails: the H20-44's left wheels
/// (lateral +track/2) run on the left rail, its right wheels on the right,
/// and the run goes through with elastic LCP contact; with identical rails
/// the same scene has both rails equal.
#[test]
fn two_track_vehicle_runs_on_both_rails() {
    let scene = |rails: &str| {
        format!(
            "name: rails
bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
  modes: {{count: 4}}
vehicles:
  - type: h20_44
    speed: 20.0
surface: {{type: iso8608, class: B, rails: {rails}, seed: 4}}
contact: {{type: elastic, stiffness: 1.0e8}}
solver: {{method: lcp, time_step: 1.0e-3}}
"
        )
    };
    let loaded =
        vbi::plan::load_str(&scene("independent"), "rails.yaml").unwrap_or_else(|e| panic!("{e}"));
    let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge.clone()).unwrap();
    let left = model
        .wheel_rail
        .iter()
        .filter(|&&r| r == Rail::Left)
        .count();
    let right = model
        .wheel_rail
        .iter()
        .filter(|&&r| r == Rail::Right)
        .count();
    assert_eq!((left, right), (2, 2), "{:?}", model.wheel_rail);
    assert_ne!(
        model.profile.elevation_on(Rail::Left, 10.0),
        model.profile.elevation_on(Rail::Right, 10.0)
    );
    // A Monte Carlo sample swaps the profile: the same as building the
    // model of the reseeded scene.
    let mut reseeded = loaded.scenario.clone();
    reseeded.surface = reseeded.surface.reseeded(9);
    let swapped = Profile::build(&reseeded.surface, model.profile_reach).unwrap();
    let rebuilt = vbi::model::Model::build(&reseeded, loaded.bridge.clone()).unwrap();
    assert_eq!(swapped, rebuilt.profile);
    assert_ne!(swapped, model.profile);
    vbi::run::simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
    let loaded = vbi::plan::load_str(&scene("identical"), "rails.yaml").unwrap();
    let model = vbi::model::Model::build(&loaded.scenario, loaded.bridge).unwrap();
    assert_eq!(
        model.profile.elevation_on(Rail::Left, 10.0),
        model.profile.elevation_on(Rail::Right, 10.0)
    );
}

/// A contact force that peaks at the entrance of a harmonic surface is
/// named as the entrance's kick, with what kicks: the slope step of
/// phase 0, the 4 mm elevation step of phase 90° (the rigid wheel then
/// takes 53 MN and flies 0.64 m: a scene that almost surely does not mean
/// it). A level, slope-free entrance (a smooth surface) draws nothing.
#[test]
fn a_contact_force_peak_at_a_harmonic_entrance_is_named() {
    let scene = |surface: &str| {
        format!(
            "name: hop
bridge: {{type: beam, spans: [20.0], bending_stiffness: 2.0e9, mass_per_length: 1500.0,
         damping: {{type: modal, ratio: 0.01}}}}
vehicles: [{{type: oscillator, sprung_mass: 2000, unsprung_mass: 300, stiffness: 1.0e6,
            damping: 1.0e4, speed: 25.0}}]
surface: {surface}
contact: {{type: rigid, restitution: 0.3}}
record: [{{name: force, quantity: contact_force}}]
"
        )
    };
    let warnings_of = |yaml: &str| {
        let loaded = vbi::plan::load_str(yaml, "hop.yaml").unwrap_or_else(|e| panic!("{e}"));
        let outcome = vbi::run::simulate(loaded, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e}"));
        vbi::advice::texts(&outcome.summary.advice)
    };
    let kicks = |warnings: &[String]| {
        warnings
            .iter()
            .filter(|w| w.contains("is largest at the entrance"))
            .cloned()
            .collect::<Vec<_>>()
    };
    let slope = kicks(&warnings_of(&scene(
        "{type: harmonic, amplitude: 4 mm, wavelength: 1.5 m}",
    )));
    assert_eq!(slope.len(), 1, "{slope:?}");
    assert!(
        slope[0].contains("starts level with slope 0.0168"),
        "{slope:?}"
    );
    let step = kicks(&warnings_of(&scene(
        "{type: harmonic, amplitude: 4 mm, wavelength: 1.5 m, phase: 90 deg}",
    )));
    assert_eq!(step.len(), 1, "{step:?}");
    assert!(
        step[0].contains("starts 4.000 mm above the flat approach"),
        "{step:?}"
    );
    let smooth = kicks(&warnings_of(&scene("{type: smooth}")));
    assert!(smooth.is_empty(), "{smooth:?}");
}
