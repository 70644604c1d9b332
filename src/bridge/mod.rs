//! Bridges reduced to one modal model.
//!
//! Every bridge type (today the beam; the plate and imported FE models follow)
//! becomes a [`ModalBridge`]: natural frequencies, modal damping ratios and
//! mass-normalised mode shapes that can be evaluated (value and slope) at any
//! point. Solvers see only this; a bridge never knows which vehicle crosses it.

pub mod beam;
pub mod beam_3d;
pub mod eigen;
pub mod fe_import;
pub mod ground;
pub mod hermite;
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
use crate::scene::{Bridge, Modes};

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
    /// The static flexibility between contact points, for the contact
    /// static correction ([`ModalBridge::prepare_contact_correction`]).
    contact_flexibility: Option<std::sync::Arc<Flexibility>>,
    /// The mode shapes of the bridge type.
    shapes: Shapes,
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

/// (2π f)², rad²/s².
fn eigenvalue_of(frequency: f64) -> f64 {
    (2.0 * PI * frequency).powi(2)
}

impl ModalBridge {
    /// Number of modes a bridge's discretisation offers, without solving:
    /// the beam's free dofs, or the plate's Ritz terms.
    pub fn available_of(bridge: &Bridge) -> usize {
        match bridge {
            Bridge::Beam(beam) => match beam.sway {
                None => BeamModel::free_dofs_of(beam),
                Some(_) => 2 * BeamModel::free_dofs_of(beam) + beam_3d::torsion_count(beam),
            },
            Bridge::Plate(plate) => plate.terms.longitudinal * plate.terms.transverse,
            Bridge::FeImport(f) => f.model.dofs.len(),
        }
    }

    /// How many modes a frequency cut-off (Hz) keeps, counted without
    /// solving where that is cheap: a beam's Sturm (inertia) count, one
    /// sparse factorisation; `None` for a plate (its Ritz problem is solved
    /// whole anyway).
    pub fn count_up_to(bridge: &Bridge, max_frequency: f64) -> Result<Option<usize>, BridgeError> {
        match bridge {
            Bridge::Beam(beam) => {
                let model = BeamModel::new(beam)?;
                let count = beam_count_below(
                    beam,
                    &model,
                    eigenvalue_of(max_frequency * (1.0 + CUT_OFF_TOLERANCE)),
                )?;
                Ok(Some(count))
            }
            Bridge::FeImport(f) => {
                let pencil = fe_import::modal::pencil(&f.model)?;
                let count =
                    pencil.count_below(eigenvalue_of(max_frequency * (1.0 + CUT_OFF_TOLERANCE)))?;
                Ok(Some(count))
            }
            Bridge::Plate(_) => Ok(None),
        }
    }

    /// Builds the modal model of a resolved bridge description with the
    /// modes its `modes:` section asks for (every mode the model offers when
    /// it names none).
    pub fn build(bridge: &Bridge) -> Result<Self, BridgeError> {
        let all = Self::available_of(bridge);
        Self::build_with(
            bridge,
            ModeRequest::of(bridge.modes(), ModeRequest::Lowest(all)),
        )
    }

    /// Builds the modal model of a resolved bridge description with the
    /// modes `request` asks for, each checked ([`eigen`]).
    ///
    /// Cost: assembling O(elements); a beam's modes by shift-invert Lanczos
    /// (O(modes · dofs) per step, [`eigen::lanczos`]) or densely when small;
    /// a frequency cut-off one extra sparse factorisation for its inertia
    /// count; a plate's Ritz problem O(terms³).
    pub fn build_with(bridge: &Bridge, request: ModeRequest) -> Result<Self, BridgeError> {
        Self::build_cached(bridge, request, None)
    }

    /// [`ModalBridge::build_with`] with an imported model's modes read
    /// from, or written to, the modes cache in `cache` (a folder;
    /// [`eigen::cache`]): a valid cached file gives bit-identical modes,
    /// re-checked, at about a tenth of the solve's cost.
    ///
    /// A count with a cut-off ([`ModeRequest::LowestUpTo`]) is capped by the
    /// solved frequencies, not by an inertia count at the cut-off: the count
    /// and cut-off an automatic choice writes back (the cut-off at least the
    /// last kept mode's own frequency) solve for the same modes again, bit
    /// for bit, whatever the rounding of a count near a mode.
    pub fn build_cached(
        bridge: &Bridge,
        request: ModeRequest,
        cache: Option<&std::path::Path>,
    ) -> Result<Self, BridgeError> {
        let ModeRequest::LowestUpTo(count, max_frequency) = request else {
            return Self::build_counted(bridge, request, cache);
        };
        let available = Self::available_of(bridge);
        if count > available {
            return Err(BridgeError::TooManyModes {
                requested: count,
                available,
            });
        }
        let limit = max_frequency * (1.0 + CUT_OFF_TOLERANCE);
        // Solve for no more than the cut-off can keep (the inertia count,
        // plus one in case it rounds a mode at the cut-off away).
        let counted = Self::count_up_to(bridge, max_frequency)?.map_or(count, |c| c + 1);
        let solved = count.min(counted).max(1);
        let mut modal = Self::build_counted(bridge, ModeRequest::Lowest(solved), cache)?;
        let within = modal
            .frequencies()
            .iter()
            .take_while(|&&f| f <= limit)
            .count();
        if within == 0 {
            return Err(BridgeError::NoModeBelow {
                max_frequency,
                first: modal.frequencies()[0],
            });
        }
        if within < solved {
            modal = Self::build_counted(bridge, ModeRequest::Lowest(within), cache)?;
        }
        modal.selection = format!("requested: the lowest {count} modes, up to {max_frequency} Hz");
        Ok(modal)
    }

    /// [`ModalBridge::build_cached`] with the count of modes taken from
    /// the request as it stands ([`select_count`]).
    fn build_counted(
        bridge: &Bridge,
        request: ModeRequest,
        cache: Option<&std::path::Path>,
    ) -> Result<Self, BridgeError> {
        let selection = match request {
            ModeRequest::Lowest(n) => format!("requested: the lowest {n} modes"),
            ModeRequest::UpTo(f) => format!("requested: every mode up to {f} Hz"),
            ModeRequest::LowestUpTo(n, f) => {
                format!("requested: the lowest {n} modes, up to {f} Hz")
            }
            ModeRequest::AtLeastUpTo(n, f) => {
                format!("every mode up to {f} Hz, and at least the lowest {n}")
            }
        };
        let mut supports = vec![0.0];
        let mut x = 0.0;
        for span in bridge.spans() {
            x += span;
            supports.push(x);
        }
        let available = Self::available_of(bridge);
        let mut from_cache = None;
        let mut cache_rejected = None;
        let (omegas, shapes, check) = match bridge {
            Bridge::Beam(beam) => {
                let model = BeamModel::new(beam)?;
                let count = select_count(
                    request,
                    available,
                    |f| beam_count_below(beam, &model, eigenvalue_of(f)),
                    || {
                        let lowest = model.modes(1)?.eigenvalues[0];
                        let lowest = match &beam.sway {
                            None => lowest,
                            Some(sway) => beam_3d::lowest(beam, sway, &[lowest], 1)[0].0,
                        };
                        Ok(lowest.sqrt() / (2.0 * PI))
                    },
                )?;
                match &beam.sway {
                    None => {
                        let modes = model.modes(count)?;
                        let shapes = model.shapes(&modes.vectors, count);
                        let omegas = modes.eigenvalues.iter().map(|l| l.sqrt()).collect();
                        (
                            omegas,
                            Shapes::Beam {
                                shapes,
                                model: Box::new(model),
                                sway: None,
                            },
                            modes.check,
                        )
                    }
                    Some(sway) => {
                        let modes = model.modes(count.min(model.free_dofs()))?;
                        let kept = beam_3d::lowest(beam, sway, &modes.eigenvalues, count);
                        let kinds: Vec<beam_3d::SwayMode> = kept.iter().map(|k| k.1).collect();
                        // Column `c` of a field: the vertical shape `i` where
                        // mode c is of the wanted kind, zero elsewhere.
                        let field = |pick: fn(beam_3d::SwayMode) -> Option<usize>| {
                            HermiteField::from_fn(model.node_x.clone(), count, |n, c| {
                                pick(kinds[c]).map_or((0.0, 0.0), |i| {
                                    let at = |dof: usize| {
                                        model.free_index[dof].map_or(0.0, |k| modes.vectors[(k, i)])
                                    };
                                    (at(2 * n), at(2 * n + 1))
                                })
                            })
                        };
                        let shapes = field(|k| match k {
                            beam_3d::SwayMode::Vertical(i) => Some(i),
                            _ => None,
                        });
                        let lateral = field(|k| match k {
                            beam_3d::SwayMode::Lateral(i) => Some(i),
                            _ => None,
                        });
                        let torsion = kinds
                            .iter()
                            .enumerate()
                            .filter_map(|(c, k)| match k {
                                beam_3d::SwayMode::Torsion(t) => Some((c, *t)),
                                _ => None,
                            })
                            .collect();
                        let omegas = kept.iter().map(|k| k.0.sqrt()).collect();
                        (
                            omegas,
                            Shapes::Beam {
                                shapes,
                                model: Box::new(model),
                                sway: Some(Box::new(beam_3d::SwayShapes {
                                    kinds,
                                    lateral,
                                    torsion,
                                    rail_height: sway.rail_height,
                                    flexibility_ratio: beam.bending_stiffness
                                        / sway.lateral_bending_stiffness,
                                })),
                            },
                            modes.check,
                        )
                    }
                }
            }
            Bridge::Plate(plate) => {
                let (mut plate_modes, mut omegas) = PlateModes::build(plate)?;
                let frequencies: Vec<f64> = omegas.iter().map(|w| w / (2.0 * PI)).collect();
                let count = select_count(
                    request,
                    available,
                    |f| Ok(frequencies.iter().take_while(|&&g| g < f).count()),
                    || Ok(frequencies[0]),
                )?;
                let check = plate_modes.check(count)?;
                plate_modes.truncate(count);
                omegas.truncate(count);
                let shapes = Shapes::Plate {
                    modes: Box::new(plate_modes),
                    lines: Vec::new(),
                };
                (omegas, shapes, check)
            }
            Bridge::FeImport(f) => {
                let pencil = fe_import::modal::pencil(&f.model)?;
                let count = select_count(
                    request,
                    available,
                    |g| pencil.count_below(eigenvalue_of(g)),
                    || Ok(pencil.lowest(1)?.eigenvalues[0].sqrt() / (2.0 * PI)),
                )?;
                let modes = match cache {
                    Some(folder) => {
                        let cache = eigen::cache::ModesCache {
                            folder: folder.to_path_buf(),
                            kind: "fe_import".into(),
                        };
                        let (modes, outcome) = pencil.lowest_cached(count, &cache)?;
                        from_cache = Some(outcome == eigen::cache::CacheOutcome::Hit);
                        if let eigen::cache::CacheOutcome::Rejected(why) = outcome {
                            cache_rejected = Some(why);
                        }
                        modes
                    }
                    None => pencil.lowest(count)?,
                };
                let omegas: Vec<f64> = modes.eigenvalues.iter().map(|l| l.sqrt()).collect();
                let shapes = ImportedShapes::new(f.model.clone(), pencil, modes.vectors);
                (
                    omegas,
                    Shapes::Imported(std::sync::Arc::new(shapes)),
                    modes.check,
                )
            }
        };
        let damping_ratios = match (bridge, &shapes) {
            (Bridge::Beam(beam), _) => omegas.iter().map(|&w| beam.damping.ratio_at(w)).collect(),
            (Bridge::Plate(plate), _) => {
                omegas.iter().map(|&w| plate.damping.ratio_at(w)).collect()
            }
            (Bridge::FeImport(f), Shapes::Imported(imported)) => {
                match (f.damping.rule(), &f.model.damping) {
                    (Some(rule), _) => omegas.iter().map(|&w| rule.ratio_at(w)).collect(),
                    (None, Some(matrix)) => imported.projected_damping(matrix, &omegas)?,
                    (None, None) => vec![0.0; omegas.len()],
                }
            }
            (Bridge::FeImport(_), _) => vec![0.0; omegas.len()],
        };
        Ok(Self {
            length: x,
            supports,
            circular_frequencies: omegas,
            damping_ratios,
            available_modes: available,
            selection,
            check,
            static_correction: bridge.modes().static_correction,
            modes_from_cache: from_cache,
            modes_cache_rejected: cache_rejected,
            contact_flexibility: None,
            shapes,
        })
    }

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
    /// number, or a plate mode's dominant (longitudinal, transverse) term.
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
            Shapes::Imported(_) => format!("mode {}", mode + 1),
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

    /// Mode values φᵢ(x, y) (1/√kg) of every kept mode at `x` along the
    /// bridge and `y` across it (m; a beam ignores `y`); zero off the bridge.
    #[inline]
    pub fn mode_values(&self, x: f64, y: f64, values: &mut [f64]) {
        match &self.shapes {
            Shapes::Beam { shapes, sway, .. } => {
                shapes.values_at(x, values);
                // A 3D beam's twist lifts a point at y by y θ.
                if let Some(sway) = sway.as_deref().filter(|_| y != 0.0) {
                    for &(c, t) in &sway.torsion {
                        values[c] = y * t.at(x).0;
                    }
                }
            }
            Shapes::Imported(imported) => {
                imported.track.evaluate_at(x, y, values, &mut [], &mut [])
            }
            Shapes::Plate { modes, lines } => match lines.iter().find(|(ly, _)| *ly == y) {
                Some((_, line)) => line.values_at(x, values),
                None => modes.values_at(x, y, values),
            },
        }
    }

    /// Mode values, slopes ∂φᵢ/∂x and curvatures ∂²φᵢ/∂x² (1/(m²√kg)) at
    /// (x, y), derivatives along the bridge; zero off the bridge.
    #[inline]
    pub fn mode_values_slopes_curvatures(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        match &self.shapes {
            Shapes::Beam { shapes, sway, .. } => {
                shapes.values_slopes_curvatures_at(x, values, slopes, curvatures);
                if let Some(sway) = sway.as_deref().filter(|_| y != 0.0) {
                    for &(c, t) in &sway.torsion {
                        let (v, d, dd) = t.at(x);
                        (values[c], slopes[c], curvatures[c]) = (y * v, y * d, y * dd);
                    }
                }
            }
            // Along the track: Hermite with the ry DOFs, else linear with
            // zero curvature inside each element (fe_import::track).
            Shapes::Imported(imported) => {
                imported.track.evaluate_at(x, y, values, slopes, curvatures)
            }
            Shapes::Plate { modes, lines } => match lines.iter().find(|(ly, _)| *ly == y) {
                Some((_, line)) => line.values_slopes_curvatures_at(x, values, slopes, curvatures),
                None => modes.values_slopes_curvatures_at(x, y, values, slopes, curvatures),
            },
        }
    }

    /// Mode components in `direction` at (x, y) — values (1/√kg), slopes
    /// ∂/∂x (1/(m√kg)) and curvatures ∂²/∂x² (1/(m²√kg)) of every kept
    /// mode's displacement in that direction (+z up, +y left of travel)
    /// at the rail point x along the bridge, y across it; zero off the
    /// bridge. Vertical: [`ModalBridge::mode_values_slopes_curvatures`].
    /// Lateral: an imported model's uy components along its track (the mean
    /// of the track's rails; Hermite with rz where every node has it, as
    /// the vertical with ry); zero for a bridge modelled in the vertical
    /// plane (a plane beam, a plate: it does not move sideways, so a
    /// wheelset following its rails laterally only follows their alignment).
    #[inline]
    pub fn mode_components(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        match direction {
            ContactDirection::Vertical => {
                self.mode_values_slopes_curvatures(x, y, values, slopes, curvatures)
            }
            ContactDirection::Lateral => match &self.shapes {
                Shapes::Imported(imported) => imported
                    .lateral_track
                    .evaluate(x, values, slopes, curvatures),
                Shapes::Beam {
                    sway: Some(sway), ..
                } => {
                    sway.lateral
                        .values_slopes_curvatures_at(x, values, slopes, curvatures);
                    // The rails, h above the shear centre, move by −h θ.
                    let h = sway.rail_height;
                    for &(c, t) in &sway.torsion {
                        let (v, d, dd) = t.at(x);
                        (values[c], slopes[c], curvatures[c]) = (-h * v, -h * d, -h * dd);
                    }
                }
                _ => {
                    values.fill(0.0);
                    slopes.fill(0.0);
                    curvatures.fill(0.0);
                }
            },
        }
    }

    /// Mode values in `direction` at (x, y), 1/√kg
    /// ([`ModalBridge::mode_components`]).
    #[inline]
    pub fn mode_values_in(&self, direction: ContactDirection, x: f64, y: f64, values: &mut [f64]) {
        match direction {
            ContactDirection::Vertical => self.mode_values(x, y, values),
            ContactDirection::Lateral => match &self.shapes {
                Shapes::Imported(imported) => {
                    imported.lateral_track.evaluate(x, values, &mut [], &mut [])
                }
                Shapes::Beam {
                    sway: Some(sway), ..
                } => {
                    sway.lateral.values_at(x, values);
                    for &(c, t) in &sway.torsion {
                        values[c] = -sway.rail_height * t.at(x).0;
                    }
                }
                _ => values.fill(0.0),
            },
        }
    }

    /// The entry weight of a contact at `x` on an imported track with free
    /// rail ends ([`fe_import::entry`]); `None` where loads enter at once.
    #[inline]
    fn contact_entry(&self) -> Option<&crate::scene::imported::RailEntry> {
        match &self.shapes {
            Shapes::Imported(imported) if imported.model.entry.is_active() => {
                Some(&imported.model.entry)
            }
            _ => None,
        }
    }

    /// [`ModalBridge::mode_values`] as a wheel's contact at (x, y) sees
    /// them: on an imported track with free rail ends, times the entry
    /// weight s(x) ([`fe_import::entry`]); elsewhere the same.
    #[inline]
    pub fn contact_mode_values(&self, x: f64, y: f64, values: &mut [f64]) {
        self.mode_values(x, y, values);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, &mut [], &mut []);
        }
    }

    /// [`ModalBridge::mode_values_slopes_curvatures`] as a contact sees
    /// them (values, slopes and curvatures of s·φ).
    #[inline]
    pub fn contact_mode_values_slopes_curvatures(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        self.mode_values_slopes_curvatures(x, y, values, slopes, curvatures);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, slopes, curvatures);
        }
    }

    /// [`ModalBridge::mode_components`] as a contact sees them.
    #[inline]
    pub fn contact_mode_components(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        self.mode_components(direction, x, y, values, slopes, curvatures);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, slopes, curvatures);
        }
    }

    /// [`ModalBridge::mode_values_in`] as a contact sees them.
    #[inline]
    pub fn contact_mode_values_in(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
    ) {
        self.mode_values_in(direction, x, y, values);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, &mut [], &mut []);
        }
    }

    /// Static deflection influence line of the point (`x_point`, `y_point`)
    /// for loads travelling along the line `y_load` (m; a beam ignores both
    /// y): G(ξ), m/N, the downward deflection at the point due to a unit
    /// downward load at ξ, from the full stiffness (beam finite elements, or
    /// the whole plate Ritz basis; no modal truncation).
    pub fn influence_line(
        &self,
        x_point: f64,
        y_point: f64,
        y_load: f64,
    ) -> Result<InfluenceLine, BridgeError> {
        match &self.shapes {
            Shapes::Beam { model, .. } => model.influence_line(x_point).map(InfluenceLine::Hermite),
            Shapes::Plate { modes, .. } => modes
                .influence_line(x_point, y_point, y_load)
                .map(InfluenceLine::Hermite),
            Shapes::Imported(imported) => imported
                .influence_line(x_point)
                .map(|f| InfluenceLine::Track(f, imported.model.entry)),
        }
    }

    /// The probe of a plate deck's moment per unit width `moment` at (x,
    /// y) (m) for wheels along the lines `line_y` (m)
    /// ([`plate::moments`]); `None` for any other bridge.
    pub fn plate_moment_probe(
        &self,
        x: f64,
        y: f64,
        moment: crate::scene::PlateMoment,
        line_y: &[f64],
    ) -> Result<Option<plate::moments::PlateMomentProbe>, BridgeError> {
        match &self.shapes {
            Shapes::Plate { modes, .. } => modes
                .moment_probe(x, y, moment, &self.circular_frequencies, line_y)
                .map(Some),
            _ => Ok(None),
        }
    }

    /// The free DOF of an imported model's (node, direction), if the
    /// bridge is imported and the DOF free; `Err` with the reason otherwise.
    pub fn imported_dof(
        &self,
        node: u64,
        direction: crate::scene::imported::Direction,
    ) -> Result<Option<usize>, String> {
        match &self.shapes {
            Shapes::Imported(imported) => Ok(imported.model.dof(node, direction)),
            _ => Err("only an imported (fe_import) bridge has nodes".into()),
        }
    }

    /// Mode values (1/√kg) at free DOF `dof` of an imported model; zeros
    /// for any other bridge.
    pub fn dof_mode_values(&self, dof: usize, values: &mut [f64]) {
        values.fill(0.0);
        if let Shapes::Imported(imported) = &self.shapes {
            imported.dof_values(dof, values);
        }
    }

    /// Static influence line of free DOF `dof` of an imported model for
    /// loads along its track, m/N (the DOF's displacement opposite to its
    /// direction under a unit downward load).
    pub fn dof_influence_line(&self, dof: usize) -> Result<InfluenceLine, BridgeError> {
        match &self.shapes {
            Shapes::Imported(imported) => imported
                .dof_influence_line(dof)
                .map(|f| InfluenceLine::Track(f, imported.model.entry)),
            _ => Err(BridgeError::EigenFailed),
        }
    }

    /// Node positions of the mesh along the bridge, m.
    pub fn node_x(&self) -> &[f64] {
        match &self.shapes {
            Shapes::Beam { shapes, .. } => shapes.node_x(),
            Shapes::Plate { modes, .. } => modes.node_x(),
            Shapes::Imported(imported) => imported.track.node_x(),
        }
    }
}

/// Modes of a beam with ω² below `eigenvalue` (rad²/s²): an inertia count
/// of the vertical pencil, and for a 3D beam the lateral ones (the same
/// pencil at eigenvalue·EI/EI_z) and the twist ones (closed form). Cost
/// one or two sparse factorisations.
fn beam_count_below(
    beam: &crate::scene::Beam,
    model: &BeamModel,
    eigenvalue: f64,
) -> Result<usize, BridgeError> {
    let vertical = model.pencil.count_below(eigenvalue)?;
    let Some(sway) = &beam.sway else {
        return Ok(vertical);
    };
    let ratio2 = sway.lateral_bending_stiffness / beam.bending_stiffness;
    let lateral = model.pencil.count_below(eigenvalue / ratio2)?;
    let torsion = beam_3d::torsion_modes(beam, sway)
        .iter()
        .filter(|t| t.0 < eigenvalue)
        .count();
    Ok(vertical + lateral + torsion)
}

/// Number of modes kept under a request: `count_below(f)` counts the
/// modes below f Hz (an inertia count), `first()` gives the lowest
/// frequency (Hz) for the message when none lies below a cut-off.
fn select_count(
    request: ModeRequest,
    available: usize,
    count_below: impl Fn(f64) -> Result<usize, BridgeError>,
    first: impl Fn() -> Result<f64, BridgeError>,
) -> Result<usize, BridgeError> {
    let lowest = |requested: usize| {
        if requested > available {
            Err(BridgeError::TooManyModes {
                requested,
                available,
            })
        } else {
            Ok(requested)
        }
    };
    // Modes at most f: count below f nudged up by CUT_OFF_TOLERANCE (a
    // mode at the cut-off, as printed or as the eigensolver found it, is
    // kept).
    let up_to = |f: f64| -> Result<usize, BridgeError> {
        let below = count_below(f * (1.0 + CUT_OFF_TOLERANCE))?;
        if below == 0 {
            return Err(BridgeError::NoModeBelow {
                max_frequency: f,
                first: first()?,
            });
        }
        Ok(below)
    };
    match request {
        ModeRequest::Lowest(n) => lowest(n),
        ModeRequest::UpTo(f) => up_to(f),
        ModeRequest::LowestUpTo(n, f) => Ok(lowest(n)?.min(up_to(f)?)),
        ModeRequest::AtLeastUpTo(n, f) => {
            let below = count_below(f * (1.0 + CUT_OFF_TOLERANCE))?;
            Ok(below.max(n.min(available)).max(1))
        }
    }
}
