//! Unit tests of the surface profiles.

use super::*;
use crate::scene::{Surface, TrackDirection};

/// The power-law period grid against the series summed exactly
/// (`random_at`) at 4000 points over two periods: the largest error of
/// r, r′ and r″, each relative to the largest |value| of the series.
/// Measured 2026-11-23 (N = 312, L_c = 156 m, the plate paper's
/// sampling): r 1.7e-11, r′ 5.6e-9, r″ 3.2e-7; bounds at 6× those.
#[test]
fn random_grid_follows_the_series() {
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
    let points: Vec<f64> = (0..4000)
        .map(|i| 2.0 * 156.0 * (i as f64 + 0.37) / 4000.0)
        .collect();
    let exact: Vec<Triple> = points
        .iter()
        .map(|&x| Profile::random_at(fundamental, terms, offset, x))
        .collect();
    let grid: Vec<Triple> = points
        .iter()
        .map(|&x| profile.elevation_slope_curvature(x))
        .collect();
    let relative = |pick: fn(&Triple) -> f64| {
        let scale = exact.iter().map(|t| pick(t).abs()).fold(0.0, f64::max);
        let error = exact
            .iter()
            .zip(&grid)
            .map(|(e, g)| (pick(e) - pick(g)).abs())
            .fold(0.0, f64::max);
        error / scale
    };
    let (r, slope, curvature) = (relative(|t| t.0), relative(|t| t.1), relative(|t| t.2));
    eprintln!("grid errors: r {r:.2e}, r' {slope:.2e}, r'' {curvature:.2e}");
    assert!(r <= 1e-10, "r {r:e}");
    assert!(slope <= 3.5e-8, "r' {slope:e}");
    assert!(curvature <= 2e-6, "r'' {curvature:e}");
}

#[test]
fn harmonic_profile_starts_at_entrance() {
    let p = Profile::build(
        &Surface::Harmonic {
            amplitude: 0.003,
            wavelength: 1.5,
            phase: 0.5,
            direction: TrackDirection::Vertical,
        },
        10.0,
    )
    .unwrap();
    let p = |x| p.elevation(x);
    assert_eq!(p(-1.0), 0.0);
    assert!((p(0.0) - 0.003 * 0.5f64.sin()).abs() < 1e-15);
    assert!((p(1.5) - p(0.0)).abs() < 1e-15);
    assert!((p(0.375 - 0.5 / (2.0 * PI) * 1.5) - 0.003).abs() < 1e-12);
}
