//! Physical plausibility of the surface ([`crate::scenario::plausible`]'s
//! surface ranges): a road or track irregularity is millimetres to
//! centimetres high over wavelengths of millimetres to a few hundred metres
//! (ISO 8608, EN 13848). A harmonic of 10 km amplitude otherwise runs to
//! a mid-span of −4,758 m and contact forces of −3.4e10 N.
//!
//! Two stages. The elevations (amplitudes, heights, depths, the points of a
//! piecewise-linear profile, the roughness coefficient) drive no budget and
//! are checked while the section is resolved ([`check_elevations`]); a
//! measured profile's values are checked as its file is read, at its line.
//! The lengths along the surface (wavelengths, bands, shape lengths, run-in,
//! sampling length) also set the grid, the series and the time step, whose
//! budgets and step checks say more (which limit, which step would resolve
//! a short bump): they are checked after those ([`check_lengths`]), at the
//! keys those left unblamed, so that `--allow-large` lifts a budget but not
//! a wavelength of a nanometre.

use super::super::checker::Checker;
use super::super::plausible::{
    ROUGHNESS_COEFFICIENT, SURFACE_LENGTH, SURFACE_LENGTH_SOURCE, surface_elevation, within_help,
};
use crate::scene::{Surface, TrackDirection};

/// Checks the elevations of the resolved surface against
/// [`super::super::plausible::SURFACE_ELEVATION`] and a written roughness
/// coefficient against [`ROUGHNESS_COEFFICIENT`].
pub(crate) fn check_elevations(surface: &Surface, ck: &mut Checker<'_>) {
    match *surface {
        Surface::Harmonic {
            amplitude,
            direction,
            ..
        } => {
            let what = match direction {
                TrackDirection::Vertical => "a harmonic amplitude",
                TrackDirection::Lateral => "a harmonic alignment amplitude",
            };
            surface_elevation(
                ck,
                "surface.amplitude",
                what,
                (amplitude, false),
                "the amplitude is in metres: 5 mm is `amplitude: 0.005` or `amplitude: 5 mm`"
                    .into(),
            );
        }
        Surface::Bump { height, .. } => {
            if ck.has("surface.depth") {
                surface_elevation(
                    ck,
                    "surface.depth",
                    "a dip depth",
                    (-height, false),
                    "the depth is in metres: a 30 mm dip is `depth: 0.03` or `depth: 30 mm`".into(),
                );
            } else {
                surface_elevation(
                    ck,
                    "surface.height",
                    "a bump height",
                    (height, false),
                    "the height is in metres: a 50 mm bump is `height: 0.05` or `height: 50 mm`"
                        .into(),
                );
            }
        }
        Surface::Ramp { height, .. } => {
            surface_elevation(
                ck,
                "surface.height",
                "a ramp's rise",
                (height, true),
                "the rise is in metres: a 20 mm change of level is `height: 0.02` or \
                 `height: 20 mm` (a grade is the road's geometry, not its surface)"
                    .into(),
            );
        }
        Surface::Step { height, .. } => {
            surface_elevation(
                ck,
                "surface.height",
                "a step's height",
                (height, true),
                "the height is in metres: a 10 mm step is `height: 0.01` or `height: 10 mm`".into(),
            );
        }
        Surface::PiecewiseLinear { ref points, .. } => {
            // One message: the first point out of range.
            if let Some(i) = points.iter().position(|p| {
                p[1].is_nan() || p[1].abs() > super::super::plausible::SURFACE_ELEVATION
            }) {
                surface_elevation(
                    ck,
                    &format!("surface.points[{i}]"),
                    &format!("point {}'s elevation r", i + 1),
                    (points[i][1], true),
                    format!(
                        "each point is `[x, r]` in metres: 20 mm at x = {} m is `[{}, 0.02]`",
                        points[i][0], points[i][0]
                    ),
                );
            }
        }
        Surface::Random { coefficient, .. } if ck.has("surface.coefficient") => {
            within_help(
                ck,
                "surface.coefficient",
                "a roughness coefficient",
                coefficient,
                ROUGHNESS_COEFFICIENT,
                "m³/cycle",
                "ISO 8608's roughest class, H, is about 0.1 m³/cycle in this spectrum's \
                 normalisation; the plate paper's very poor class ends at 2.048e-3",
                "A_r is in m³/cycle: a road in good condition is `coefficient: 16e-6` (or \
                 `class: good`)"
                    .into(),
            );
        }
        _ => {}
    }
}

/// Checks the lengths along the resolved surface against
/// [`SURFACE_LENGTH`], skipping a key `blamed` says already has an error
/// (a bump shorter than a step's travel is refused for that, with the step
/// that resolves it).
pub(crate) fn check_lengths(
    surface: &Surface,
    ck: &mut Checker<'_>,
    blamed: &dyn Fn(&Checker<'_>, &str) -> bool,
) {
    let length = |ck: &mut Checker<'_>, path: &str, what: &str, value: f64, help: &str| {
        if !blamed(ck, path) {
            within_help(
                ck,
                path,
                what,
                value,
                SURFACE_LENGTH,
                "m",
                SURFACE_LENGTH_SOURCE,
                help.to_owned(),
            );
        }
    };
    match *surface {
        Surface::Harmonic { wavelength, .. } => length(
            ck,
            "surface.wavelength",
            "a wavelength",
            wavelength,
            "the wavelength is in metres: a 5 m wave is `wavelength: 5.0`, a 50 mm one \
             `wavelength: 50 mm`",
        ),
        Surface::Bump {
            length: l, height, ..
        } => {
            let (what, help) = if height < 0.0 {
                (
                    "a dip length",
                    "the length is in metres: a 1 m long dip is `length: 1.0`",
                )
            } else {
                (
                    "a bump length",
                    "the length is in metres: a 1 m long bump is `length: 1.0`",
                )
            };
            length(ck, "surface.length", what, l, help);
        }
        Surface::Ramp { length: l, .. } => length(
            ck,
            "surface.length",
            "a ramp length",
            l,
            "the length is in metres: a ramp over 5 m is `length: 5.0`",
        ),
        Surface::Random {
            sampling_length, ..
        } if ck.has("surface.sampling_length") => length(
            ck,
            "surface.sampling_length",
            "a sampling length (the longest wavelength of the series)",
            sampling_length,
            "the series repeats over `sampling_length` metres (`sampling_length: 64.0`); \
             leave it out for twice the bridge's length",
        ),
        _ => {}
    }
    if let Some((_, sampling)) = surface.spectrum() {
        for (key, what, value) in [
            (
                "surface.shortest_wavelength",
                "a shortest wavelength",
                sampling.shortest_wavelength,
            ),
            (
                "surface.longest_wavelength",
                "a longest wavelength",
                sampling.longest_wavelength,
            ),
        ] {
            length(
                ck,
                key,
                what,
                value,
                "the band is in metres; leave it out for the default: 1–80 m for track \
                 spectra (`shortest_wavelength: 1.0`, `longest_wavelength: 80.0`), 0.5–100 m \
                 for ISO 8608 roads",
            );
        }
        // Any run-in up to the longest length: a short one is a jump, as
        // `run_in: 0` is.
        if ck.has("surface.run_in") && !blamed(ck, "surface.run_in") {
            within_help(
                ck,
                "surface.run_in",
                "a run-in",
                sampling.run_in,
                (0.0, SURFACE_LENGTH.1),
                "m",
                SURFACE_LENGTH_SOURCE,
                "the run-in is the length in metres the profile fades in over on the \
                 approach; leave it out for the band's longest wavelength, or `run_in: 0` for \
                 none"
                    .into(),
            );
        }
    }
}
