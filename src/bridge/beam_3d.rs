//! The 3D beam: lateral bending and torsion added to the vertical beam
//! (the setting in which the EMBS method was first demonstrated: a simply
//! supported bridge with vertical and lateral modes, EMBS paper §1).
//!
//! The section is doubly symmetric (shear centre at the centroid), so the
//! vertical bending w, the lateral bending v and the twist θ are
//! uncoupled, each with its own modes:
//! - vertical: the Hermite beam of [`super::beam`] (EI, m);
//! - lateral: the same mesh, mass and supports with EI_z, so the pencil is
//!   (EI_z/EI) K and M: the same mass-normalised vectors at ω = ω_vert
//!   √(EI_z/EI) (Rayleigh's quotient scales exactly);
//! - torsion: GJ θ″ = I_p θ̈ with fork supports (θ = 0 at every support),
//!   so the spans twist independently, each in the closed-form modes
//!   θₙ = √(2/(I_p L_s)) sin(nπ(x − x_s)/L_s), ωₙ = (nπ/L_s)√(GJ/I_p)
//!   (mass-normalised: ∫ I_p θₙ² dx = 1). They are evaluated exactly (a
//!   Hermite field cannot hold the slope jump of a twist mode at a
//!   support), at most `elements_per_span` per span so the count stays
//!   tied to the mesh.
//!
//! All kept modes are ordered by frequency into one modal set. A rail
//! point at y across the centre line, h = `rail_height` above the shear
//! centre, moves up by w + y θ and sideways by v − h θ (θ > 0 lifts the
//! left side, +y to the left): these are the mode components the
//! contacts see ([`super::ModalBridge::mode_components`]).

use std::f64::consts::PI;

use super::hermite::HermiteField;
use crate::scene::{Beam, BeamSway};

/// Which motion a kept mode of a 3D beam is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SwayMode {
    /// The `n`-th vertical bending mode (from 0).
    Vertical(usize),
    /// The `n`-th lateral bending mode (from 0; the vertical shape `n`).
    Lateral(usize),
    /// Twist of one span.
    Torsion(TorsionMode),
}

/// A closed-form twist mode of one span.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorsionMode {
    /// Span number from 0.
    pub span: usize,
    /// Half-waves along the span, from 1.
    pub order: usize,
    /// Where the span starts, m.
    pub start: f64,
    /// Span length, m.
    pub length: f64,
    /// √(2/(I_p L)), 1/√(kg·m²).
    pub amplitude: f64,
}

impl TorsionMode {
    /// Twist (rad/√(kg·m²)), its slope and its curvature along x at `x`;
    /// zero outside the span.
    #[inline]
    pub fn at(&self, x: f64) -> (f64, f64, f64) {
        let local = x - self.start;
        if !(0.0..=self.length).contains(&local) {
            return (0.0, 0.0, 0.0);
        }
        let k = self.order as f64 * PI / self.length;
        let (sin, cos) = (k * local).sin_cos();
        (
            self.amplitude * sin,
            self.amplitude * k * cos,
            -self.amplitude * k * k * sin,
        )
    }
}

/// The lateral and torsional shapes of a 3D beam's kept modes.
#[derive(Debug, Clone)]
pub struct SwayShapes {
    /// What each kept mode is.
    pub kinds: Vec<SwayMode>,
    /// Lateral displacement v of each kept mode on the beam's axis (zero
    /// columns for the vertical and twist modes), 1/√kg.
    pub lateral: HermiteField,
    /// The twist modes among the kept ones: (mode index, shape).
    pub torsion: Vec<(usize, TorsionMode)>,
    /// Height of the rails above the shear centre, m.
    pub rail_height: f64,
    /// EI/EI_z: the lateral static deflection under a load along the
    /// axis over the vertical one under the same load (same mesh and
    /// supports), dimensionless.
    pub flexibility_ratio: f64,
}

/// √(EI_z/EI): lateral over vertical frequency of the same shape.
pub fn lateral_ratio(beam: &Beam, sway: &BeamSway) -> f64 {
    (sway.lateral_bending_stiffness / beam.bending_stiffness).sqrt()
}

/// Every twist mode the beam offers (`elements_per_span` per span), with
/// its ω² (rad²/s²).
pub fn torsion_modes(beam: &Beam, sway: &BeamSway) -> Vec<(f64, TorsionMode)> {
    let speed = (sway.torsional_stiffness / sway.polar_mass).sqrt();
    let mut out = Vec::with_capacity(beam.elements());
    let mut start = 0.0;
    for (span, (&length, &elements)) in beam.spans.iter().zip(&beam.elements_per_span).enumerate() {
        for order in 1..=elements {
            let omega = order as f64 * PI / length * speed;
            out.push((
                omega * omega,
                TorsionMode {
                    span,
                    order,
                    start,
                    length,
                    amplitude: (2.0 / (sway.polar_mass * length)).sqrt(),
                },
            ));
        }
        start += length;
    }
    out
}

/// Number of twist modes the beam offers.
pub fn torsion_count(beam: &Beam) -> usize {
    beam.elements()
}

/// The lowest `count` modes of the 3D beam from its lowest vertical
/// eigenvalues `vertical` (rad²/s², ascending, at least as many as the
/// lateral and vertical modes among the `count`): (ω², kind), ascending;
/// ties keep vertical before lateral before twist.
pub fn lowest(
    beam: &Beam,
    sway: &BeamSway,
    vertical: &[f64],
    count: usize,
) -> Vec<(f64, SwayMode)> {
    let ratio2 = sway.lateral_bending_stiffness / beam.bending_stiffness;
    let mut all: Vec<(f64, SwayMode)> = vertical
        .iter()
        .enumerate()
        .map(|(i, &l)| (l, SwayMode::Vertical(i)))
        .chain(
            vertical
                .iter()
                .enumerate()
                .map(|(i, &l)| (l * ratio2, SwayMode::Lateral(i))),
        )
        .chain(
            torsion_modes(beam, sway)
                .into_iter()
                .map(|(l, t)| (l, SwayMode::Torsion(t))),
        )
        .collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    all.truncate(count);
    all
}
