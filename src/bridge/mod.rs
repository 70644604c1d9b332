//! Bridges reduced to one modal model.
//!
//! Every bridge type (today the beam; the plate and imported FE models follow)
//! becomes a [`ModalBridge`]: natural frequencies, modal damping ratios and
//! mass-normalised mode shapes that can be evaluated (value and slope) at any
//! point. Solvers see only this; a bridge never knows which vehicle crosses it.

pub mod beam;
pub mod beam_3d;
mod build;
pub mod eigen;
pub mod fe_import;
pub mod ground;
pub mod hermite;
mod mode_values;
pub mod plate;
pub mod section;

use std::f64::consts::PI;

use thiserror::Error;

use crate::contact::ContactDirection;

use self::beam::BeamModel;
use self::fe_import::modal::{ImportedFlexibility, ImportedShapes};
use self::fe_import::track::TrackField;
use self::hermite::HermiteField;
use self::plate::PlateModes;
use crate::scene::Modes;

/// Errors while building a bridge model.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum BridgeError {
    /// The mass matrix is not positive definite (a non-positive mass).
    #[error("the bridge mass matrix is not positive definite")]
    MassNotPositive,
    /// The stiffness matrix is singular or indefinite.
    #[error("the bridge stiffness matrix is not positive definite (is the bridge supported?)")]
    StiffnessNotPositive,
    /// The eigen solver did not converge.
    #[error("the eigenvalue solver did not converge")]
    EigenFailed,
    /// More modes requested than the mesh has.
    #[error("{requested} modes requested but the mesh has only {available}")]
    TooManyModes {
        /// Requested count.
        requested: usize,
        /// Available modes (free dofs).
        available: usize,
    },
    /// A size taken from the input does not fit in memory.
    #[error("the bridge model does not fit in memory")]
    OutOfMemory,
    /// A shifted matrix K − σM is singular (σ on an eigenvalue).
    #[error(
        "a shifted bridge matrix K − σM is singular; the eigen solver cannot count modes there"
    )]
    SingularShift,
    /// A computed mode failed a check.
    #[error(
        "bridge mode {mode} failed its check: {what} = {value:.3e}, above the bound {bound:.0e} (the eigen solution cannot be trusted; report this model)"
    )]
    ModeCheckFailed {
        /// Mode number from 1.
        mode: usize,
        /// The quantity checked.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The bound it exceeded.
        bound: f64,
    },
    /// The inertia count disagrees with the modes found.
    #[error(
        "the eigen solver found {solved} modes below {below:.6} Hz but the Sturm (inertia) count of the model says {counted}: a mode would be missing"
    )]
    ModesMissing {
        /// The cut, Hz.
        below: f64,
        /// Modes the solver returned below it.
        solved: usize,
        /// Modes the inertia count finds below it.
        counted: usize,
    },
    /// No mode lies below the requested maximum frequency.
    #[error("no mode has a frequency at most {max_frequency} Hz; the first is {first:.4} Hz")]
    NoModeBelow {
        /// Requested cut-off, Hz.
        max_frequency: f64,
        /// Lowest natural frequency, Hz.
        first: f64,
    },
}

/// A bridge as the solvers see it: modal coordinates q with
/// q̈ᵢ + 2ζᵢωᵢ q̇ᵢ + ωᵢ² qᵢ = Σ_c φᵢ(x_c) f_c (unit modal masses), where f_c
/// are upward point forces at the contact points.
#[derive(Debug, Clone)]
pub struct ModalBridge {
    /// Total length from entrance to exit, m.
    pub length: f64,
    /// Support positions, m (span ends).
    pub supports: Vec<f64>,
    /// Natural circular frequencies ωᵢ of the kept modes, rad/s, ascending.
    pub circular_frequencies: Vec<f64>,
    /// Modal damping ratios ζᵢ, dimensionless.
    pub damping_ratios: Vec<f64>,
    /// The damping of the assembled model as C = c_M M + c_K K, `(c_M,
    /// c_K)` in (1/s, s), for the direct solver ([`crate::solve::direct`]):
    /// a beam's or an imported model's Rayleigh damping, or (0, 0)
    /// without damping; `None` where no such C stands for the modal ratios
    /// (a nonzero modal ratio, a plate, an imported damping matrix).
    pub rayleigh_damping: Option<(f64, f64)>,
    /// Number of modes the discretisation offers.
    pub available_modes: usize,
    /// How the kept modes were chosen, in words (for the summary).
    pub selection: String,
    /// How the kept modes were verified (residuals, orthonormality, inertia).
    pub check: eigen::ModeCheck,
    /// Whether recorded displacements get the static share of the modes
    /// left out ([`crate::record`]).
    pub static_correction: bool,
    /// Whether the modes were read from the modes cache (`Some(true)`),
    /// solved and written to it (`Some(false)`), or solved without a
    /// cache (`None`: no cache folder, or a bridge the cache does not
    /// serve — beams and plates solve in milliseconds).
    pub modes_from_cache: Option<bool>,
    /// Why a modes cache file that was there was not used (it failed a
    /// check: [`eigen::cache::Pencil::recheck`]); the modes were solved
    /// afresh and the file rewritten.
    pub modes_cache_rejected: Option<&'static str>,
    /// On an imported track under wheels with mass: what the kept modes
    /// leave out of the rails' static flexibility under a wheel
    /// ([`crate::plan::track_flexibility`]); `None` where the plan did not
    /// measure it.
    pub rails_flexibility: Option<RailsFlexibility>,
    /// Where a deck acceleration's filter reaches above the kept modes and
    /// the bridge has modes there: the filter and how many modes lie up to
    /// it (a Sturm count; [`crate::report::advice`] warns).
    pub acceleration_filter: Option<AccelerationFilter>,
    /// Modes an imported bridge's solve found that nothing in the scene
    /// moves (no motion at the loaded rails, no ground participation:
    /// [`fe_import::excited`]), left out of the kept ones and of `count`;
    /// empty for beams, plates and a solve without the scene's loads.
    pub left_out: Vec<UnexcitedMode>,
    /// The static flexibility between contact points, for the contact
    /// static correction ([`ModalBridge::prepare_contact_correction`]).
    contact_flexibility: Option<std::sync::Arc<Flexibility>>,
    /// The mode shapes of the bridge type.
    shapes: Shapes,
}

/// A mode an imported bridge's solve left out because the scene cannot
/// move it ([`ModalBridge::left_out`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct UnexcitedMode {
    /// Its natural frequency, Hz.
    pub frequency: f64,
    /// The direction it moves in, by its kinetic energy
    /// ([`fe_import::modal::ModeDirection`]): `axial`, `lateral`,
    /// `vertical` or `torsion`.
    pub direction: &'static str,
}

/// What the kept modes of an imported track leave out of the rails' static
/// flexibility under a wheel, ρ = max_c R(c, c) / max_c G(c, c) over rail
/// points c in each direction the wheels hold, R = G − Σᵢ φᵢ(c)²/ωᵢ²
/// ([`crate::plan::track_flexibility`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RailsFlexibility {
    /// The largest share left out, ρ (dimensionless, 0–1).
    pub left_out: f64,
    /// The share left out at a typical rail point: the median over the
    /// points of R(c, c) / G(c, c) (dimensionless, 0–1). ρ is set by the
    /// track's most flexible point (a free rail end, whose flexibility no
    /// low mode carries); this one says what a wheel over the deck meets.
    pub typical_left_out: f64,
    /// Rail points measured.
    pub points: usize,
    /// Whether every rail node was measured; `false`: a sample of them, so
    /// `left_out` is a lower bound of the largest share.
    pub every_node: bool,
    /// Whether the contacts carry the share left out as the static
    /// correction's massless spring; `false`: the rails' deflection under a
    /// wheel misses it (a model of over [`CONTACT_CORRECTION_DOFS`] DOFs,
    /// or `modes.static_correction: false`).
    pub static_correction: bool,
    /// Whether the limits on modes stopped the automatic choice short of
    /// its target.
    pub limited: bool,
}

/// A deck acceleration's filter above the kept modes: EN 1990 A2.4.4.2.1(4)
/// sums every mode up to it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AccelerationFilter {
    /// The highest filter of the deck accelerations recorded, Hz.
    pub max_frequency: f64,
    /// The bridge's modes up to it (an inertia count), more than are kept.
    pub modes: usize,
}

/// The static flexibility between contact points of a beam or an imported model.
#[derive(Debug, Clone)]
enum Flexibility {
    Beam(beam::BeamFlexibility),
    Imported(ImportedFlexibility),
}

/// A contact point for the static correction: its direction, x along the
/// track and y across it, m.
pub type ContactPoint = (ContactDirection, f64, f64);

impl Flexibility {
    /// G between the points c and d, m/N; a plane beam has no y and is
    /// rigid sideways (0 for a lateral point).
    #[inline]
    fn green(&self, c: ContactPoint, d: ContactPoint) -> f64 {
        match self {
            Flexibility::Beam(f) => {
                if c.0 == ContactDirection::Vertical && d.0 == ContactDirection::Vertical {
                    f.green(c.1, d.1)
                } else {
                    0.0
                }
            }
            Flexibility::Imported(f) => f.green(c, d),
        }
    }
}

/// A static influence line: along a beam or plate line (Hermite), or along
/// an imported model's track.
#[derive(Debug, Clone)]
pub enum InfluenceLine {
    /// A Hermite field.
    Hermite(HermiteField),
    /// An imported model's track, and how a load enters it at its ends
    /// (the load at ξ couples with its entry weight, [`fe_import::entry`]).
    Track(TrackField, crate::scene::imported::RailEntry),
}

impl InfluenceLine {
    /// G at the load position `x` (m), m/N.
    #[inline]
    pub fn value_at(&self, x: f64) -> f64 {
        match self {
            InfluenceLine::Hermite(f) => f.value_at(x),
            InfluenceLine::Track(f, entry) => {
                let g = f.value_at(x);
                if entry.is_active() {
                    g * entry.weight(x).0
                } else {
                    g
                }
            }
        }
    }
}

/// Mode shapes of each bridge type.
#[derive(Debug, Clone)]
enum Shapes {
    /// A beam: the kept modes as one Hermite field (1/√kg), and the
    /// finite-element model for static influence lines.
    Beam {
        shapes: HermiteField,
        model: Box<BeamModel>,
        /// A 3D beam's lateral and twist shapes (`shapes` then holds the
        /// vertical displacement of every kept mode, zero for the lateral
        /// and twist ones).
        sway: Option<Box<beam_3d::SwayShapes>>,
    },
    /// A plate: the Ritz modes, and the kept modes along the lines the
    /// wheels and records use (exact y match), so a point on such a line
    /// costs what a beam point costs.
    Plate {
        modes: Box<PlateModes>,
        lines: Vec<(f64, HermiteField)>,
    },
    /// An imported finite-element model: the kept modes on its DOFs and
    /// along its track.
    Imported(std::sync::Arc<ImportedShapes>),
}

/// Most free dofs of a beam whose contacts get the static correction (K⁻¹
/// is kept densely: 2,500² × 8 B = 50 MB).
pub const CONTACT_CORRECTION_DOFS: usize = 2_500;

/// Relative tolerance of a frequency cut-off: a mode at most
/// f·(1 + 1e-8) counts as at most f. It covers a cut-off copied from a
/// mode's printed frequency (15 significant digits) and the disagreement
/// between an inertia (Sturm) count at the cut-off and the eigensolver's
/// frequency, whose residuals are held to [`eigen::RESIDUAL_BOUND`] = 1e-8
/// (a 25 m beam's third mode given as printed, 47.6876464074312 Hz, was
/// counted out at the former 1e-12).
pub const CUT_OFF_TOLERANCE: f64 = 1e-8;

/// Which modes a bridge keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModeRequest {
    /// The lowest `count`.
    Lowest(usize),
    /// Every mode up to a frequency, Hz.
    UpTo(f64),
    /// The lowest `count`, but none above a frequency (Hz).
    LowestUpTo(usize, f64),
    /// Every mode up to a frequency (Hz), and at least the lowest `count`.
    AtLeastUpTo(usize, f64),
}

impl ModeRequest {
    /// The request a resolved `modes:` section makes; `fallback` when it
    /// names neither a count nor a frequency.
    pub fn of(modes: &Modes, fallback: ModeRequest) -> Self {
        match (modes.count, modes.max_frequency) {
            (Some(n), None) => ModeRequest::Lowest(n),
            (None, Some(f)) => ModeRequest::UpTo(f),
            (Some(n), Some(f)) => ModeRequest::LowestUpTo(n, f),
            (None, None) => fallback,
        }
    }
}

impl ModalBridge {
    /// Prepares the static correction of the contacts (a beam of at most
    /// [`CONTACT_CORRECTION_DOFS`] free dofs with `static_correction` on):
    /// K⁻¹ once, so that the flexibility between two wheels costs O(1).
    /// Plates and larger beams keep the modal contact flexibility (their
    /// recorded displacements are still corrected).
    pub fn prepare_contact_correction(&mut self) -> Result<(), BridgeError> {
        if !self.static_correction || self.contact_flexibility.is_some() {
            return Ok(());
        }
        match &self.shapes {
            // A 3D beam keeps the modal contact flexibility: its rails sit
            // off the axis, where the twist adds a static flexibility the
            // bending Green's function does not hold (its recorded
            // displacements on the axis are still corrected).
            Shapes::Beam { sway: Some(_), .. } => {}
            Shapes::Beam { model, .. } => {
                self.contact_flexibility = model
                    .flexibility(CONTACT_CORRECTION_DOFS)?
                    .map(|f| std::sync::Arc::new(Flexibility::Beam(f)));
            }
            Shapes::Imported(imported) => {
                self.contact_flexibility = imported
                    .flexibility(CONTACT_CORRECTION_DOFS)?
                    .map(|f| std::sync::Arc::new(Flexibility::Imported(f)));
            }
            Shapes::Plate { .. } => {}
        }
        Ok(())
    }

    /// The full model's static flexibility G(c, c) at each of an imported
    /// model's track points, m/N, by sparse solves with K's factor (any
    /// size: [`fe_import::modal::ImportedShapes::static_flexibility_at`]); `None`
    /// for other bridges.
    pub fn track_flexibility_at(
        &self,
        points: &[ContactPoint],
    ) -> Option<Result<Vec<f64>, BridgeError>> {
        match &self.shapes {
            Shapes::Imported(imported) => Some(imported.static_flexibility_at(points)),
            _ => None,
        }
    }

    /// The assembled finite-element model of a plane beam (its sparse K
    /// and M on the free DOFs and the mesh), for the direct solver
    /// ([`crate::solve::direct`]); `None` for a 3D beam, a plate or an
    /// imported model.
    pub fn beam_model(&self) -> Option<&BeamModel> {
        match &self.shapes {
            Shapes::Beam {
                model, sway: None, ..
            } => Some(model),
            _ => None,
        }
    }

    /// An imported model's shapes (its model, pencil and kept mode
    /// vectors), for the direct solver ([`crate::solve::direct`]); `None`
    /// for any other bridge.
    pub fn imported_shapes(&self) -> Option<&ImportedShapes> {
        match &self.shapes {
            Shapes::Imported(imported) => Some(imported),
            _ => None,
        }
    }

    /// The kept modes on the free DOFs of a plane beam or an imported
    /// model (1/√kg), column-major n × modes (column i is Φᵢ, with
    /// ΦᵢᵀMΦᵢ = 1): a beam's read back from the nodal values of its mode
    /// shapes; `None` for a 3D beam or a plate. Cost O(n·modes).
    pub fn assembled_mode_vectors(&self) -> Option<Vec<f64>> {
        if let Shapes::Imported(imported) = &self.shapes {
            let vectors = &imported.vectors;
            let (n, modes) = (vectors.nrows(), vectors.ncols());
            let mut out = vec![0.0; n * modes];
            for c in 0..modes {
                out[c * n..(c + 1) * n].copy_from_slice(vectors.col_as_slice(c));
            }
            return Some(out);
        }
        let Shapes::Beam {
            shapes,
            model,
            sway: None,
        } = &self.shapes
        else {
            return None;
        };
        let (n, modes) = (model.free_dofs(), self.mode_count());
        let mut vectors = vec![0.0; n * modes];
        for node in 0..model.node_x.len() {
            for c in 0..modes {
                let (w, theta) = shapes.nodal(node, c);
                for (dof, value) in [(2 * node, w), (2 * node + 1, theta)] {
                    if let Some(i) = model.free_index[dof] {
                        vectors[c * n + i] = value;
                    }
                }
            }
        }
        Some(vectors)
    }

    /// Whether the modes are an imported finite-element model's.
    pub fn is_imported(&self) -> bool {
        matches!(self.shapes, Shapes::Imported(_))
    }

    /// Whether the modes are a plate deck's.
    pub fn is_plate(&self) -> bool {
        matches!(self.shapes, Shapes::Plate { .. })
    }

    /// Whether contact points get the static correction.
    pub fn corrects_contacts(&self) -> bool {
        self.contact_flexibility.is_some()
    }

    /// The full model's static flexibility G(c, d) between two contact
    /// points, m/N; `None` when the contact correction is off. The residual
    /// flexibility is G(c, d) − Σᵢ φᵢ(c)φᵢ(d)/ωᵢ² ([`Self::residual_flexibility`]);
    /// a solver holding many contacts forms the modal sum for all pairs at
    /// once as one matrix product.
    pub fn static_flexibility(&self, c: ContactPoint, d: ContactPoint) -> Option<f64> {
        self.contact_flexibility
            .as_ref()
            .map(|flexibility| flexibility.green(c, d))
    }

    /// Residual (static) flexibility between two contact points c and d
    /// (direction, x along and y across the track, m), m/N: the full static
    /// Green's function minus its modal part, R = G(c, d) −
    /// Σᵢ φᵢ(c)φᵢ(d)/ωᵢ², from the mode values at the two points in their
    /// directions (`values_c`, `values_d`, kept modes, taken by the same
    /// rule: on an imported track of two rails a vertical contact off the
    /// centre line is on its own rail, a lateral one sees the rails'
    /// average, [`fe_import::modal::track_weights_at`]). The quasi-static
    /// deflection of the modes left out at c under downward forces F_d is
    /// −Σ_d R_cd F_d (the mode-acceleration method applied to the contact
    /// flexibility). 0 when the contact correction is off. Cost O(modes).
    #[inline]
    pub fn residual_flexibility(
        &self,
        c: ContactPoint,
        d: ContactPoint,
        values_c: &[f64],
        values_d: &[f64],
    ) -> f64 {
        let Some(flexibility) = &self.contact_flexibility else {
            return 0.0;
        };
        let modal: f64 = values_c
            .iter()
            .zip(values_d)
            .zip(&self.circular_frequencies)
            .map(|((a, b), w)| a * b / (w * w))
            .sum();
        flexibility.green(c, d) - modal
    }

    /// Makes evaluation along the deck lines `ys` (m) as cheap as on a beam
    /// (a plate caches the kept modes along each line; a beam ignores this).
    pub fn prepare_lines(&mut self, ys: &[f64]) {
        if let Shapes::Plate { modes, lines } = &mut self.shapes {
            for &y in ys {
                if !lines.iter().any(|(line_y, _)| *line_y == y) {
                    lines.push((y, modes.line(y)));
                }
            }
        }
    }

    /// Deck width, m (`None` for a beam).
    pub fn width(&self) -> Option<f64> {
        match &self.shapes {
            Shapes::Beam { .. } | Shapes::Imported(_) => None,
            Shapes::Plate { modes, .. } => Some(modes.width),
        }
    }

    /// Character of kept mode `mode` (from 0), in words: a beam mode's
    /// number, a plate mode's dominant (longitudinal, transverse) term, or
    /// an imported mode's direction by its kinetic energy
    /// ([`fe_import::modal::energy_shares`]: `axial`, `lateral`, `vertical`
    /// or `torsion`, ry counted with the vertical and rz with the lateral
    /// bending), numbered within its direction, with its share
    /// (`vertical 2 (99.7 %)`).
    pub fn mode_character(&self, mode: usize) -> String {
        match &self.shapes {
            Shapes::Beam { sway: None, .. } => format!("bending {}", mode + 1),
            Shapes::Beam {
                sway: Some(sway), ..
            } => match sway.kinds[mode] {
                beam_3d::SwayMode::Vertical(i) => format!("vertical bending {}", i + 1),
                beam_3d::SwayMode::Lateral(i) => format!("lateral bending {}", i + 1),
                beam_3d::SwayMode::Torsion(t) => {
                    format!("torsion {} of span {}", t.order, t.span + 1)
                }
            },
            Shapes::Imported(imported) => {
                use fe_import::modal::dominant;
                let shares = &imported.energy_shares;
                let (direction, share) = dominant(&shares[mode]);
                let order = shares[..=mode]
                    .iter()
                    .filter(|s| dominant(s).0 == direction)
                    .count();
                format!("{} {order} ({:.1} %)", direction.name(), 100.0 * share)
            }
            Shapes::Plate { modes, .. } => {
                let (m, n) = modes.character(mode);
                format!("({m}, {n})")
            }
        }
    }

    /// Points (x, y), m, at which the mode shapes reach about their peaks:
    /// the mesh nodes, on a plate along both edges and the centre line.
    pub fn sample_points(&self) -> Vec<(f64, f64)> {
        let ys = match self.width() {
            None => vec![0.0],
            Some(b) => vec![0.0, 0.5 * b, b],
        };
        self.node_x()
            .iter()
            .flat_map(|&x| ys.iter().map(move |&y| (x, y)))
            .collect()
    }

    /// Number of kept modes.
    pub fn mode_count(&self) -> usize {
        self.circular_frequencies.len()
    }

    /// Natural frequencies of the kept modes, Hz.
    pub fn frequencies(&self) -> Vec<f64> {
        self.circular_frequencies
            .iter()
            .map(|w| w / (2.0 * PI))
            .collect()
    }

    /// Whether `x` (m) lies on the deck.
    #[inline]
    pub fn is_on(&self, x: f64) -> bool {
        (0.0..=self.length).contains(&x)
    }
}

/// The nodal state u, u̇, ü of an assembled bridge after a step, on its free
/// DOFs in the order of its assembled K and M (the direct solver's,
/// `crate::solve::direct::assembled::AssembledBridge`): plain data the
/// section and reaction readers of this layer take.
#[derive(Debug, Clone, Copy)]
pub struct NodalState<'a> {
    /// u, m (rad).
    pub displacement: &'a [f64],
    /// u̇, m/s (rad/s).
    pub velocity: &'a [f64],
    /// ü, m/s² (rad/s²), relative to the ground's motion.
    pub acceleration: &'a [f64],
}
