//! Building a [`ModalBridge`]: how many modes a bridge offers or has below
//! a frequency (inertia counts, without solving), and the eigen solve of
//! the kept ones, through the modes cache when one is given.

use std::f64::consts::PI;

use super::beam::BeamModel;
use super::fe_import::modal::ImportedShapes;
use super::hermite::HermiteField;
use super::plate::PlateModes;
use super::{
    BridgeError, CUT_OFF_TOLERANCE, ModalBridge, ModeRequest, Shapes, UnexcitedMode, beam_3d,
    eigen, fe_import,
};
use crate::scene::Bridge;
use faer::Mat;

/// (2π f)², rad²/s².
pub(super) fn eigenvalue_of(frequency: f64) -> f64 {
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
        Self::build_cached(bridge, request, None, faer::Par::Seq)
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
    ///
    /// `par`: the parallelism of an imported model's eigen solve
    /// ([`eigen::Pencil::with_parallelism`]); the modes are bit-identical
    /// whatever it is.
    pub fn build_cached(
        bridge: &Bridge,
        request: ModeRequest,
        cache: Option<&std::path::Path>,
        par: faer::Par,
    ) -> Result<Self, BridgeError> {
        Self::build_excited(bridge, request, cache, par, None)
    }

    /// [`ModalBridge::build_cached`] for a scene whose loads are
    /// `loads`: an imported model's modes that those loads cannot
    /// move ([`fe_import::excited`]) are left out, and a count means modes
    /// kept, so the solve goes on until it has that many the scene moves
    /// (each left out listed in [`ModalBridge::left_out`]). `None`: every
    /// mode is kept (a bridge without its vehicles, `vbi modes`). Beams and
    /// plates keep every mode either way.
    pub fn build_excited(
        bridge: &Bridge,
        request: ModeRequest,
        cache: Option<&std::path::Path>,
        par: faer::Par,
        loads: Option<fe_import::excited::SceneLoads>,
    ) -> Result<Self, BridgeError> {
        let ModeRequest::LowestUpTo(count, max_frequency) = request else {
            return Self::build_counted(bridge, request, cache, par, loads);
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
        let mut modal =
            Self::build_counted(bridge, ModeRequest::Lowest(solved), cache, par, loads)?;
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
            modal = Self::build_counted(bridge, ModeRequest::Lowest(within), cache, par, loads)?;
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
        par: faer::Par,
        loads: Option<fe_import::excited::SceneLoads>,
    ) -> Result<Self, BridgeError> {
        let _t = crate::timings::stage(|| format!("modal bridge ({request:?})"));
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
        let mut left_out = Vec::new();
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
                let pencil = {
                    let _t = crate::timings::stage(|| "the pencil (K, M compressed)".into());
                    fe_import::modal::pencil(&f.model)?.with_parallelism(par)
                };
                let count = select_count(
                    request,
                    available,
                    |g| pencil.count_below(eigenvalue_of(g)),
                    || Ok(pencil.lowest(1)?.eigenvalues[0].sqrt() / (2.0 * PI)),
                )?;
                let solve = |count: usize| {
                    let _t = crate::timings::stage(|| format!("eigen solve, {count} modes"));
                    match cache {
                        Some(folder) => {
                            let cache = eigen::cache::ModesCache {
                                folder: folder.to_path_buf(),
                                kind: "fe_import".into(),
                            };
                            let (modes, outcome) = pencil.lowest_cached(count, &cache)?;
                            Ok((modes, Some(outcome)))
                        }
                        None => Ok::<_, BridgeError>((pencil.lowest(count)?, None)),
                    }
                };
                let (modes, outcome, kept) = match loads {
                    None => {
                        let (modes, outcome) = solve(count)?;
                        let kept = (0..modes.eigenvalues.len()).collect();
                        (modes, outcome, kept)
                    }
                    Some(loads) => {
                        solve_excited(&f.model, request, count, available, loads, solve)?
                    }
                };
                if let Some(outcome) = outcome {
                    from_cache = Some(outcome == eigen::cache::CacheOutcome::Hit);
                    if let eigen::cache::CacheOutcome::Rejected(why) = outcome {
                        cache_rejected = Some(why);
                    }
                }
                let solved = modes.eigenvalues.len();
                let vectors = Mat::from_fn(modes.vectors.nrows(), kept.len(), |i, c| {
                    modes.vectors[(i, kept[c])]
                });
                let omegas: Vec<f64> = kept.iter().map(|&c| modes.eigenvalues[c].sqrt()).collect();
                if kept.len() < solved {
                    let shares = fe_import::modal::energy_shares(&f.model, &pencil, &modes.vectors);
                    let mut is_kept = vec![false; solved];
                    for &c in &kept {
                        is_kept[c] = true;
                    }
                    // Left out of the count: the unmoved modes below the
                    // last kept one (those above were solved past it),
                    // every one solved when the model has fewer moved
                    // modes than the count asks for.
                    let last = if kept.len() < moved_wanted(request) {
                        solved
                    } else {
                        kept.last().map_or(0, |&c| c + 1)
                    };
                    left_out = (0..last)
                        .filter(|&c| !is_kept[c])
                        .map(|c| UnexcitedMode {
                            frequency: modes.eigenvalues[c].sqrt() / (2.0 * PI),
                            direction: fe_import::modal::dominant(&shares[c]).0.name(),
                        })
                        .collect();
                }
                let shapes = ImportedShapes::new(f.model.clone(), pencil, vectors);
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
        let rayleigh_damping = match bridge {
            Bridge::Beam(beam) => beam.damping.rayleigh_coefficients(),
            Bridge::FeImport(f) => match (f.damping.rule(), &f.model.damping) {
                (Some(rule), _) => rule.rayleigh_coefficients(),
                (None, Some(_)) => None,
                (None, None) => Some((0.0, 0.0)),
            },
            Bridge::Plate(_) => None,
        };
        Ok(Self {
            rayleigh_damping,
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
            rails_flexibility: None,
            acceleration_filter: None,
            left_out,
            contact_flexibility: None,
            shapes,
        })
    }
}

/// Modes of a beam with ω² below `eigenvalue` (rad²/s²): an inertia count
/// of the vertical pencil, and for a 3D beam the lateral ones (the same
/// pencil at eigenvalue·EI/EI_z) and the twist ones (closed form). Cost
/// one or two sparse factorisations.
pub(super) fn beam_count_below(
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
pub(super) fn select_count(
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

/// How many moved modes a request's count asks for (0: a cut-off alone,
/// or [`ModeRequest::LowestUpTo`], which [`ModalBridge::build_excited`]
/// turns into counts).
fn moved_wanted(request: ModeRequest) -> usize {
    match request {
        ModeRequest::Lowest(n) | ModeRequest::AtLeastUpTo(n, _) => n,
        ModeRequest::UpTo(_) | ModeRequest::LowestUpTo(..) => 0,
    }
}

/// The modes of an imported model a request keeps among those the scene
/// moves ([`fe_import::excited::excited_modes`]): `count` (the request's
/// own count, [`select_count`]) solved first; a request with a count
/// ([`ModeRequest::Lowest`], [`ModeRequest::AtLeastUpTo`]) solves more,
/// doubling what is missing each time, until it keeps that many moved
/// modes or the model has no more; a solve that went past the last kept
/// mode is repeated for exactly the modes up to it. Returns the solve, its
/// cache outcome and the kept columns, ascending; every solved mode when
/// the scene moves none (nothing to choose by).
fn solve_excited(
    model: &crate::scene::imported::ImportedModel,
    request: ModeRequest,
    count: usize,
    available: usize,
    loads: fe_import::excited::SceneLoads,
    solve: impl Fn(
        usize,
    ) -> Result<(eigen::Eigenpairs, Option<eigen::cache::CacheOutcome>), BridgeError>,
) -> Result<
    (
        eigen::Eigenpairs,
        Option<eigen::cache::CacheOutcome>,
        Vec<usize>,
    ),
    BridgeError,
> {
    let wanted = moved_wanted(request);
    let mut solved = count;
    let mut settled = false;
    loop {
        let (modes, outcome) = solve(solved)?;
        let moved: Vec<usize> = fe_import::excited::excited_modes(model, &modes.vectors, loads)
            .iter()
            .enumerate()
            .filter_map(|(c, &m)| m.then_some(c))
            .collect();
        if !settled && moved.len() < wanted && solved < available {
            solved = (solved + 2 * (wanted - moved.len())).min(available);
            continue;
        }
        if moved.is_empty() {
            let all = (0..modes.eigenvalues.len()).collect();
            return Ok((modes, outcome, all));
        }
        // Beyond the count: only what a cut-off of the request keeps.
        let limit = match request {
            ModeRequest::AtLeastUpTo(_, f) => eigenvalue_of(f * (1.0 + CUT_OFF_TOLERANCE)),
            _ => f64::NEG_INFINITY,
        };
        let kept = match request {
            ModeRequest::UpTo(_) | ModeRequest::LowestUpTo(..) => moved,
            _ => moved
                .into_iter()
                .enumerate()
                .filter(|&(rank, c)| rank < wanted || modes.eigenvalues[c] <= limit)
                .map(|(_, c)| c)
                .collect(),
        };
        // Solved past the last kept mode (a count grown, a cut-off's
        // top modes unmoved): solve again for exactly the modes up to
        // it, so that every route to these modes — the automatic choice,
        // and the count and cut-off it writes back — ends in the same
        // solve, bit for bit.
        let last = kept.last().map_or(0, |&c| c + 1);
        if !settled && last < solved && kept.len() >= wanted {
            solved = last;
            settled = true;
            continue;
        }
        return Ok((modes, outcome, kept));
    }
}

impl ModalBridge {
    /// The left-out modes in words, for the selection's reason: how many of
    /// each direction and their frequency range; `None` when none was.
    pub fn left_out_reason(&self) -> Option<String> {
        if self.left_out.is_empty() {
            return None;
        }
        let mut groups: Vec<(&str, usize, f64, f64)> = Vec::new();
        for mode in &self.left_out {
            match groups.iter_mut().find(|g| g.0 == mode.direction) {
                Some(g) => {
                    g.1 += 1;
                    g.2 = g.2.min(mode.frequency);
                    g.3 = g.3.max(mode.frequency);
                }
                None => groups.push((mode.direction, 1, mode.frequency, mode.frequency)),
            }
        }
        let listed: Vec<String> = groups
            .iter()
            .map(|&(direction, n, low, high)| {
                if n == 1 {
                    format!("1 {direction} at {low:.2} Hz")
                } else {
                    format!("{n} {direction} at {low:.2}–{high:.2} Hz")
                }
            })
            .collect();
        let count = match self.left_out.len() {
            1 => "1 mode".to_string(),
            n => format!("{n} modes"),
        };
        Some(format!(
            "; {count} left out of them and of the count ({}): the scene cannot move them \
             (at the rails the vehicles load they move less than {:e} of their largest motion, \
             and no ground motion drives them)",
            listed.join(", "),
            fe_import::excited::UNEXCITED_SHARE
        ))
    }
}
