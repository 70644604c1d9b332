//! The bridge of the scene: beam, plate or imported FE model, its modes and damping.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::*;

/// The bridge model.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Bridge {
    /// Euler–Bernoulli beam.
    Beam(Beam),
    /// Thin orthotropic plate deck.
    Plate(Plate),
    /// A finite-element model imported from files.
    FeImport(FeImport),
}

impl Bridge {
    /// Total length from the entrance to the exit, m.
    pub fn length(&self) -> f64 {
        self.spans().iter().sum()
    }

    /// Span lengths, m.
    pub fn spans(&self) -> &[f64] {
        match self {
            Bridge::Beam(beam) => &beam.spans,
            Bridge::Plate(plate) => &plate.spans,
            Bridge::FeImport(f) => &f.spans,
        }
    }

    /// Deck width, m (`None` for a beam, which has no transverse extent).
    pub fn width(&self) -> Option<f64> {
        match self {
            Bridge::Beam(_) | Bridge::FeImport(_) => None,
            Bridge::Plate(plate) => Some(plate.width),
        }
    }

    /// Mode selection.
    pub fn modes(&self) -> &Modes {
        match self {
            Bridge::Beam(beam) => &beam.modes,
            Bridge::Plate(plate) => &plate.modes,
            Bridge::FeImport(f) => &f.modes,
        }
    }

    /// Mode selection, to fill in.
    pub fn modes_mut(&mut self) -> &mut Modes {
        match self {
            Bridge::Beam(beam) => &mut beam.modes,
            Bridge::Plate(plate) => &mut plate.modes,
            Bridge::FeImport(f) => &mut f.modes,
        }
    }

    /// Mass per unit length along the bridge, kg/m (a plate: ρh × width).
    pub fn mass_per_length(&self) -> f64 {
        match self {
            Bridge::Beam(beam) => beam.mass_per_length,
            Bridge::Plate(plate) => plate.mass_per_area * plate.width,
            // The mass a rigid vertical translation moves, per deck length
            // (piers and all, when the model has them).
            Bridge::FeImport(f) => f.model.vertical_mass() / f.model.length,
        }
    }

    /// Transverse lines on which the summary tabulates DAFs, m (a beam: one line at 0).
    pub fn girder_lines(&self) -> Vec<f64> {
        match self {
            Bridge::Beam(_) | Bridge::FeImport(_) => vec![0.0],
            Bridge::Plate(plate) => plate.girder_lines.clone(),
        }
    }
}

/// Most elements per span of a beam (or of a plate's beam functions): the
/// stiffness of Hermite elements L/n long is conditioned as n⁴ (Strang &
/// Fix, §5.2), and beyond about 4,000 per span double precision no longer
/// resolves the modes to the eigen checks' 1e-8 residual (measured on a
/// 25 m span, 200 modes: 4,000 elements pass, 6,000 fail mode 46 at
/// 1.1e-8, 10,000 fail mode 112 at 1.5e-8). Far more than any span needs:
/// the default is 20.
pub const MAX_ELEMENTS_PER_SPAN: usize = 4_000;

/// `elements_per_span` as the format writes it: one number when every span
/// has the same count (as a scene that gave one number wrote it), else the
/// list.
fn one_or_each<S: serde::Serializer>(counts: &[usize], s: S) -> Result<S::Ok, S::Error> {
    match counts {
        [first, rest @ ..] if rest.iter().all(|n| n == first) => s.serialize_u64(*first as u64),
        _ => serde::Serialize::serialize(counts, s),
    }
}

impl Beam {
    /// Finite elements in all, over every span.
    pub fn elements(&self) -> usize {
        self.elements_per_span
            .iter()
            .fold(0, |sum, &n| sum.saturating_add(n))
    }
}

/// Thin plate deck.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Plate {
    /// Span lengths, m.
    pub spans: Vec<f64>,
    /// Width, m.
    pub width: f64,
    /// Thickness, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// Mass per unit area ρh, kg/m².
    pub mass_per_area: f64,
    /// Rigidities.
    pub rigidity: Rigidity,
    /// Longitudinal edge support.
    pub edges: PlateEdges,
    /// Rayleigh–Ritz basis size.
    pub terms: Terms,
    /// Finite elements per span of the longitudinal beam functions.
    pub elements_per_span: usize,
    /// Mode selection.
    pub modes: Modes,
    /// Structural damping.
    pub damping: Damping,
    /// Girder lines y, m.
    pub girder_lines: Vec<f64>,
}

/// Plate rigidities.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Rigidity {
    /// Isotropic: D = E h³ / (12(1 − ν²)).
    Isotropic {
        /// E, Pa.
        youngs_modulus: f64,
        /// ν, dimensionless.
        poisson_ratio: f64,
    },
    /// Orthotropic.
    Orthotropic {
        /// Dx, N·m.
        flexural_rigidity_x: f64,
        /// Dy, N·m.
        flexural_rigidity_y: f64,
        /// Dxy = G h³/12, N·m.
        torsional_rigidity: f64,
        /// H = ν_xy Dy + 2 Dxy, N·m.
        equivalent_rigidity: f64,
        /// ν_xy, dimensionless.
        poisson_ratio: f64,
    },
}

impl Rigidity {
    /// (Dx, Dy, D1, Dxy), N·m, for a plate of thickness `thickness` (m; used
    /// by the isotropic form only): isotropic Dx = Dy = D, D1 = νD,
    /// Dxy = D(1 − ν)/2; orthotropic D1 = ν_xy Dy.
    pub fn rigidities(&self, thickness: f64) -> (f64, f64, f64, f64) {
        match *self {
            Rigidity::Isotropic {
                youngs_modulus,
                poisson_ratio,
            } => {
                let d = youngs_modulus * thickness.powi(3)
                    / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
                (d, d, poisson_ratio * d, 0.5 * d * (1.0 - poisson_ratio))
            }
            Rigidity::Orthotropic {
                flexural_rigidity_x,
                flexural_rigidity_y,
                torsional_rigidity,
                poisson_ratio,
                ..
            } => (
                flexural_rigidity_x,
                flexural_rigidity_y,
                poisson_ratio * flexural_rigidity_y,
                torsional_rigidity,
            ),
        }
    }
}

/// Euler–Bernoulli beam bridge.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Beam {
    /// Span lengths, m.
    pub spans: Vec<f64>,
    /// Bending stiffness EI, N·m².
    pub bending_stiffness: f64,
    /// Mass per unit length, kg/m.
    pub mass_per_length: f64,
    /// Finite elements on each span, one count per span (of equal length
    /// within a span); written as one number when all are equal.
    #[serde(serialize_with = "one_or_each")]
    pub elements_per_span: Vec<usize>,
    /// Mode selection.
    pub modes: Modes,
    /// Structural damping.
    pub damping: Damping,
    /// Lateral bending and torsion (a 3D beam); `None` for a beam that
    /// moves in the vertical plane only.
    #[serde(skip_serializing_if = "Option::is_none", flatten)]
    pub sway: Option<BeamSway>,
}

/// What makes a beam 3D: lateral bending and torsion of a doubly symmetric
/// section (shear centre at the centroid, so the three motions are
/// uncoupled), with fork supports (no lateral displacement and no twist at
/// any support).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct BeamSway {
    /// Lateral bending stiffness EI_z, N·m².
    pub lateral_bending_stiffness: f64,
    /// Torsional stiffness GJ, N·m²/rad.
    pub torsional_stiffness: f64,
    /// Polar mass moment of inertia per length I_p, kg·m²/m.
    pub polar_mass: f64,
    /// Height of the rail heads above the shear centre h, m: a twist θ
    /// moves the rails sideways by −h θ.
    pub rail_height: f64,
}

/// Mode selection; at least one is set.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Modes {
    /// Keep the lowest `count` modes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<usize>,
    /// Keep modes up to this frequency, Hz.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_frequency: Option<f64>,
    /// Add the quasi-static share of the modes left out to recorded bridge
    /// displacements (mode-acceleration method).
    pub static_correction: bool,
}

/// Structural damping.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Damping {
    /// Same ratio for every mode.
    Modal {
        /// Damping ratio, dimensionless.
        ratio: f64,
    },
    /// Rayleigh damping matched at two frequencies.
    Rayleigh {
        /// Frequencies, Hz.
        frequencies: [f64; 2],
        /// Damping ratio at both, dimensionless.
        ratio: f64,
    },
}

impl Damping {
    /// The damping matrix C = c_M M + c_K K this damping stands for on an
    /// assembled model, `(c_M, c_K)` in (1/s, s): Rayleigh's a₀ = 2ζω₁ω₂/(ω₁+ω₂),
    /// a₁ = 2ζ/(ω₁+ω₂) (as [`Self::ratio_at`]), `(0, 0)` for a zero modal
    /// ratio; `None` for a nonzero modal ratio, which no sparse matrix
    /// holds (C = MΦ diag(2ζω) ΦᵀM is full).
    pub fn rayleigh_coefficients(&self) -> Option<(f64, f64)> {
        match *self {
            Damping::Modal { ratio } => (ratio == 0.0).then_some((0.0, 0.0)),
            Damping::Rayleigh { frequencies, ratio } => {
                let w1 = 2.0 * std::f64::consts::PI * frequencies[0];
                let w2 = 2.0 * std::f64::consts::PI * frequencies[1];
                Some((2.0 * ratio * w1 * w2 / (w1 + w2), 2.0 * ratio / (w1 + w2)))
            }
        }
    }

    /// Damping ratio of a mode with circular frequency `omega` (rad/s).
    ///
    /// Rayleigh: ζ(ω) = a₀/(2ω) + a₁ω/2 with a₀, a₁ solved so that ζ(ω₁) =
    /// ζ(ω₂) = ζ: a₀ = 2ζω₁ω₂/(ω₁+ω₂), a₁ = 2ζ/(ω₁+ω₂) (Chopra, Dynamics of
    /// Structures, eq. 11.4.9).
    pub fn ratio_at(&self, omega: f64) -> f64 {
        match *self {
            Damping::Modal { ratio } => ratio,
            Damping::Rayleigh { frequencies, ratio } => {
                let w1 = 2.0 * std::f64::consts::PI * frequencies[0];
                let w2 = 2.0 * std::f64::consts::PI * frequencies[1];
                let a0 = 2.0 * ratio * w1 * w2 / (w1 + w2);
                let a1 = 2.0 * ratio / (w1 + w2);
                a0 / (2.0 * omega) + a1 * omega / 2.0
            }
        }
    }
}

/// Support of the plate's longitudinal edges.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum PlateEdges {
    /// Free edges (a bridge deck).
    Free,
    /// Simply supported edges (w = 0 along y = 0 and y = width).
    SimplySupported,
}

/// Rayleigh–Ritz basis size.
#[derive(Debug, Clone, Deserialize, JsonSchema, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Terms {
    /// Longitudinal beam functions (modes of the continuous beam over the same spans).
    #[schemars(transform = super::schema_rules::at_least_one)]
    pub longitudinal: usize,
    /// Transverse functions (Legendre polynomials for free edges, sines for
    /// simply supported edges).
    #[schemars(transform = super::schema_rules::at_least_one)]
    pub transverse: usize,
}
