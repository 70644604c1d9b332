//! The frequency content of a scene, for the automatic defaults: which bridge
//! modes to keep and which time step to take.
//!
//! A mode well above every excitation frequency responds quasi-statically, so
//! it only adds its static share. The excitation comes from the vehicles'
//! own natural frequencies (suspension; wheel hop on an elastic or Hertz
//! contact), the passing of axles (v / spacing), the crossing of each span
//! (v / 2L_span) and the roughness (v / λ). The default keeps every mode up to
//! [`SAFETY`] × the highest excitation frequency, and never fewer than
//! [`MODES_PER_SPAN`] per span, because the static deflection under a moving
//! point load converges like Σ 1/j⁴ over the modes of each span: 5 per span
//! leave Σ_{j>5} 1/j⁴ ≈ 0.1 % of the deflection under a wheel anywhere on the
//! span (3 would leave 0.6 %, felt in the vehicle's response); on a beam
//! whose static correction adds that share exactly and whose wheels have no
//! mass of their own, [`MODES_PER_SPAN_CORRECTED`] ([`floor_modes`]). The
//! default step resolves the highest frequency excited with
//! [`STEPS_PER_PERIOD`] steps ([`excited_mode_top`]: the modes kept only for
//! the quasi-static shape need no resolution) and keeps the phase of the
//! modes deck accelerations sum ([`phase_governing`]).

use std::f64::consts::PI;

use nalgebra::DMatrix;

use crate::bridge::ModalBridge;
use crate::scene::{Contact, Surface, Vehicle};
use crate::vehicle::{VehicleModel, WheelKind};

pub use crate::scene::automatic::{
    CROSSING_STEPS, HEAVY_WHEEL_RATIO, MODES_PER_SPAN, MODES_PER_SPAN_CORRECTED, PHASE_BUDGET,
    PLATE_FAMILIES, SAFETY, STEPS_PER_PERIOD,
};

/// Where a scene loads an imported bridge, for leaving out the modes it
/// cannot move (issue 40.6, [`crate::bridge::fe_import::excited`]): the
/// rails vertically always, sideways where a vehicle has a lateral contact
/// (a `train_3d`'s wheelsets), and the ground's inertia in each direction
/// a ground-motion record acts.
pub fn scene_loads(
    vehicles: &[Vehicle],
    ground_motion: &[crate::scene::GroundMotion],
    gravity: f64,
) -> crate::bridge::fe_import::excited::SceneLoads {
    use crate::contact::ContactDirection;
    let has = |d| ground_motion.iter().any(|g| g.direction == d);
    crate::bridge::fe_import::excited::SceneLoads {
        lateral_rails: vehicles.iter().any(|vehicle| {
            VehicleModel::build(vehicle, gravity)
                .wheels
                .iter()
                .any(|wheel| wheel.direction == ContactDirection::Lateral)
        }),
        vertical_ground: has(crate::scene::Direction::Vertical),
        lateral_ground: has(crate::scene::Direction::Lateral),
    }
}

/// Whether a wheel's own mass (the mass on its contact DOF: an oscillator's
/// unsprung mass, a rail car's wheelset; 0 for the truck's massless tyre
/// contact points and for moving forces) exceeds [`HEAVY_WHEEL_RATIO`] of
/// the lightest span's mass.
pub fn heavy_wheels(vehicles: &[Vehicle], bridge: &crate::scene::Bridge, gravity: f64) -> bool {
    let shortest = bridge.spans().iter().copied().fold(f64::INFINITY, f64::min);
    let limit = HEAVY_WHEEL_RATIO * bridge.mass_per_length() * shortest;
    vehicles.iter().any(|vehicle| {
        let model = VehicleModel::build(vehicle, gravity);
        model.wheels.iter().any(|wheel| match wheel.kind {
            WheelKind::Dof(dof) => model.mass[(dof, dof)] > limit,
            WheelKind::Load(_) => false,
        })
    })
}

/// One source of excitation and its frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct Excitation {
    /// What it is, in words.
    pub source: String,
    /// Frequency, Hz.
    pub frequency: f64,
}

/// Natural frequencies (Hz) of a vehicle with its wheels on springs of
/// stiffness `wheel_stiffness` (N/m), or held fixed when `None`. Massless
/// DOFs are condensed out statically; then K φ = ω² M φ by Cholesky of M.
pub fn vehicle_frequencies(vehicle: &VehicleModel, wheel_stiffness: Option<f64>) -> Vec<f64> {
    let n = vehicle.dofs();
    let wheel_dofs: Vec<usize> = vehicle
        .wheels
        .iter()
        .filter_map(|w| match w.kind {
            WheelKind::Dof(d) => Some(d),
            WheelKind::Load(_) => None,
        })
        .collect();
    let mut stiffness = vehicle.stiffness.clone();
    let mut keep: Vec<usize> = (0..n).collect();
    match wheel_stiffness {
        Some(k) => wheel_dofs.iter().for_each(|&d| stiffness[(d, d)] += k),
        None => keep.retain(|d| !wheel_dofs.contains(d)),
    }
    let massive: Vec<usize> = keep
        .iter()
        .copied()
        .filter(|&d| vehicle.mass[(d, d)] > 0.0)
        .collect();
    let massless: Vec<usize> = keep
        .iter()
        .copied()
        .filter(|&d| vehicle.mass[(d, d)] <= 0.0)
        .collect();
    if massive.is_empty() {
        return Vec::new();
    }
    let pick = |m: &DMatrix<f64>, r: &[usize], c: &[usize]| {
        DMatrix::from_fn(r.len(), c.len(), |i, j| m[(r[i], c[j])])
    };
    let mut k_mm = pick(&stiffness, &massive, &massive);
    if !massless.is_empty() {
        let k_00 = pick(&stiffness, &massless, &massless);
        let k_m0 = pick(&stiffness, &massive, &massless);
        if let Some(inverse) = k_00.try_inverse() {
            k_mm -= &k_m0 * inverse * k_m0.transpose();
        }
    }
    let m_mm = pick(&vehicle.mass, &massive, &massive);
    let Some(cholesky) = m_mm.cholesky() else {
        return Vec::new();
    };
    let l_inv = cholesky
        .l()
        .try_inverse()
        .unwrap_or_else(|| DMatrix::identity(massive.len(), massive.len()));
    let a = &l_inv * k_mm * l_inv.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let mut frequencies: Vec<f64> = a
        .symmetric_eigenvalues()
        .iter()
        .map(|&l| l.max(0.0).sqrt() / (2.0 * PI))
        .collect();
    frequencies.sort_by(f64::total_cmp);
    frequencies
}

/// Every excitation frequency of the scene on this bridge.
pub fn excitations(
    vehicles: &[Vehicle],
    contact: &Contact,
    surface: &Surface,
    spans: &[f64],
    gravity: f64,
) -> Vec<Excitation> {
    let mut out = Vec::new();
    for (i, vehicle) in vehicles.iter().enumerate() {
        let n = i + 1;
        let model = VehicleModel::build(vehicle, gravity);
        // An accelerating vehicle excites at its fastest on the bridge: the
        // larger of its speed at t = 0 and at its exit (or stop).
        let length: f64 = spans.iter().sum();
        let v = vehicle
            .motion()
            .top_speed(vehicle.exit_time(length).min(f64::MAX));
        let shortest = spans.iter().copied().fold(f64::INFINITY, f64::min);
        out.push(Excitation {
            source: format!("vehicle {n} crossing the shortest span (v / 2L)"),
            frequency: v / (2.0 * shortest),
        });
        let spacings = model
            .wheels
            .windows(2)
            .map(|w| w[1].offset - w[0].offset)
            .filter(|&d| d > 0.0);
        if let Some(spacing) =
            spacings.fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.min(d))))
        {
            out.push(Excitation {
                source: format!("vehicle {n} axle passing (v / spacing)"),
                frequency: v / spacing,
            });
        }
        let wheel_stiffness = match *contact {
            Contact::Permanent | Contact::Rigid { .. } => None,
            Contact::Elastic { stiffness, .. } => Some(stiffness),
            Contact::Hertz { coefficient } => {
                // Tangent stiffness at the static wheel load P: dF/dδ = 1.5 C^(2/3) P^(1/3).
                let load = model.gravity_load.iter().map(|f| -f).sum::<f64>()
                    / model.wheels.len().max(1) as f64;
                Some(1.5 * coefficient.powf(2.0 / 3.0) * load.max(0.0).powf(1.0 / 3.0))
            }
        };
        if let Some(&top) = vehicle_frequencies(&model, wheel_stiffness).last() {
            out.push(Excitation {
                source: format!(
                    "vehicle {n} highest natural frequency{}",
                    if wheel_stiffness.is_some() {
                        " (wheel hop on the contact spring)"
                    } else {
                        ""
                    }
                ),
                frequency: top,
            });
        }
        // A random profile (S ∝ Ω⁻²) puts its energy in the long waves; its
        // short waves reach the deck only through the tyres, whose hop
        // frequency is counted above, so it adds no excitation of its own.
        if let Surface::Harmonic { wavelength, .. } = *surface {
            out.push(Excitation {
                source: format!("vehicle {n} over the roughness (v / λ)"),
                frequency: v / wavelength,
            });
        }
    }
    out
}

/// Fewest modes the automatic choice keeps: [`MODES_PER_SPAN`] per span
/// ([`floor_spans`]: an imported model's between its track's supports), of
/// each of [`PLATE_FAMILIES`] on a plate deck (a plate deck's quasi-static
/// shape under an eccentric wheel needs the torsional and first
/// transverse-bending families as well as bending: 45 on a three-span deck,
/// the count the plate paper uses); at most what the model offers.
pub fn minimum_modes(bridge: &crate::scene::Bridge) -> usize {
    (modes_per_span(bridge) * floor_spans(bridge))
        .min(ModalBridge::available_of(bridge))
        .max(1)
}

/// Fewest modes the automatic choice keeps for a scene's `vehicles`:
/// [`MODES_PER_SPAN_CORRECTED`] per span on a beam in the vertical plane
/// whose static correction reaches both the records and the wheels (at
/// most [`crate::bridge::CONTACT_CORRECTION_DOFS`] free DOFs, or moving
/// forces alone, which feel no flexibility) when no wheel has a mass of its
/// own (`wheel_mass`), else [`minimum_modes`]; at most what the model offers. A wheel's
/// mass on the deck is coupled to the modes left out, which the
/// correction's massless spring does not hold: measured on the shipped
/// lcp-oscillator-smooth scene (unsprung mass 2.5 % of the span's), 3
/// modes put its body acceleration 0.67 % from 6. A plate (its moments and
/// contact flexibility are modal), a 3D beam (its twist) and an imported
/// model (its track's supports) keep [`minimum_modes`].
pub fn floor_modes(bridge: &crate::scene::Bridge, vehicles: &[Vehicle], wheel_mass: bool) -> usize {
    let corrected = match bridge {
        crate::scene::Bridge::Beam(beam) => {
            !wheel_mass
                && beam.sway.is_none()
                && bridge.modes().static_correction
                && (ModalBridge::available_of(bridge) <= crate::bridge::CONTACT_CORRECTION_DOFS
                    || vehicles
                        .iter()
                        .all(|v| matches!(v, Vehicle::MovingForce(_))))
        }
        _ => false,
    };
    if corrected {
        (MODES_PER_SPAN_CORRECTED * floor_spans(bridge))
            .min(ModalBridge::available_of(bridge))
            .max(1)
    } else {
        minimum_modes(bridge)
    }
}

/// The spans [`minimum_modes`] counts: a beam's and a plate's own; an
/// imported model's between the supports its track finds
/// ([`crate::scene::imported::ImportedModel::supported_spans`]), at least
/// one.
pub fn floor_spans(bridge: &crate::scene::Bridge) -> usize {
    match bridge {
        crate::scene::Bridge::FeImport(f) => f.model.supported_spans().len().max(1),
        _ => bridge.spans().len(),
    }
}

/// Fewest modes per span the automatic choice keeps ([`minimum_modes`]).
pub fn modes_per_span(bridge: &crate::scene::Bridge) -> usize {
    match bridge {
        crate::scene::Bridge::Plate(_) => MODES_PER_SPAN * PLATE_FAMILIES,
        crate::scene::Bridge::Beam(_) | crate::scene::Bridge::FeImport(_) => MODES_PER_SPAN,
    }
}

/// The automatic mode cut-off given the bridge built with its
/// [`minimum_modes`]: the cut-off frequency (Hz), whether the excitation
/// (rather than the quasi-static minimum) sets it, and the top excitation.
pub fn mode_cutoff(bridge: &ModalBridge, excitations: &[Excitation]) -> (f64, bool, Excitation) {
    let top = excitations
        .iter()
        .max_by(|a, b| a.frequency.total_cmp(&b.frequency))
        .cloned()
        .unwrap_or(Excitation {
            source: "none".into(),
            frequency: 0.0,
        });
    let dynamic_cut = SAFETY * top.frequency;
    let shape_cut = bridge.frequencies().last().copied().unwrap_or(0.0);
    (dynamic_cut.max(shape_cut), dynamic_cut > shape_cut, top)
}

/// The automatic choice's reason, in words.
pub fn mode_reason(
    count: usize,
    cut: f64,
    dynamic: bool,
    top: &Excitation,
    per_span: usize,
) -> String {
    if dynamic {
        format!(
            "automatic: {count} modes up to {cut:.2} Hz = {SAFETY} × {:.2} Hz, the highest excitation ({})",
            top.frequency, top.source
        )
    } else {
        format!(
            "automatic: {count} modes, at least {per_span} per span for the quasi-static shape \
             (up to {cut:.2} Hz; {SAFETY} × the highest excitation, {:.2} Hz from {}, needs fewer)",
            top.frequency, top.source
        )
    }
}

/// The highest bridge mode the default step resolves with
/// [`STEPS_PER_PERIOD`] steps per period, Hz: the highest of the kept
/// `frequencies` that the scene excites (up to [`SAFETY`] × its highest
/// excitation frequency, the mode cut-off's own reasoning), and at least the
/// first. The modes above, kept only for the quasi-static shape (the
/// [`MODES_PER_SPAN`] floor), respond quasi-statically: Newmark's average
/// acceleration is unconditionally stable and its error for a mode driven
/// well below its frequency is set by the forcing's frequency (the
/// trapezoidal rule's Ω̃ = (2/Δt) tan(ΩΔt/2)), not the mode's, so they need
/// no resolution. Every kept mode is resolved (`every_mode`) when a result
/// reads the deck's acceleration through them or a wheel's mass is held on
/// the deck (the planning stage's `reads_every_mode`).
pub fn excited_mode_top(frequencies: &[f64], excitations: &[Excitation], every_mode: bool) -> f64 {
    let first = frequencies.first().copied().unwrap_or(1.0);
    let top_excitation = excitations.iter().map(|e| e.frequency).fold(0.0, f64::max);
    let cut = SAFETY * top_excitation * (1.0 + crate::bridge::CUT_OFF_TOLERANCE);
    frequencies
        .iter()
        .copied()
        .filter(|&f| every_mode || f <= cut)
        .fold(first, f64::max)
}

/// The automatic time step: [`STEPS_PER_PERIOD`] steps per period of the
/// highest frequency excited (`highest_mode`, [`excited_mode_top`], or an
/// excitation's), and at least [`CROSSING_STEPS`] steps over the shortest
/// crossing, s.
pub fn time_step(highest_mode: f64, excitations: &[Excitation], shortest_crossing: f64) -> f64 {
    let top = excitations
        .iter()
        .map(|e| e.frequency)
        .fold(highest_mode, f64::max);
    (1.0 / (STEPS_PER_PERIOD * top)).min(shortest_crossing / CROSSING_STEPS)
}

/// The phase rule's step over the kept `modes` (frequency, Hz, and damping
/// ratio ζ) up to `top` (Hz, the recorded accelerations' cut-off; 0 without
/// one) and the run of `duration` (s): the smallest
/// [`phase_time_step`] over each mode's time, the run or the decay time
/// 1/(ζω) of its free vibration where that is shorter. A mode's free
/// vibration (the entry and exit transients of each axle) carries its phase
/// error only while it lasts, and a resonance's amplitude is off by the
/// same (ωΔt)²/(12ζ) that its detuning by Newmark's period error gives.
/// Without `decays`, every mode over the whole run. Returns the step, the
/// governing mode's frequency and its time (s); an infinite step without
/// accelerations; `top` itself, undamped, where no kept mode lies below it.
pub fn phase_governing(
    modes: &[(f64, f64)],
    top: f64,
    duration: f64,
    decays: bool,
) -> (f64, f64, f64) {
    if top <= 0.0 {
        return (f64::INFINITY, 0.0, duration);
    }
    let limit = top * (1.0 + crate::bridge::CUT_OFF_TOLERANCE);
    let mut summed: Vec<(f64, f64)> = modes
        .iter()
        .copied()
        .filter(|&(f, _)| f > 0.0 && f <= limit)
        .collect();
    if summed.is_empty() {
        summed.push((top, 0.0));
    }
    summed
        .into_iter()
        .map(|(f, ratio)| {
            let decay = 1.0 / (ratio.max(0.0) * 2.0 * PI * f);
            let time = if decays {
                duration.min(decay)
            } else {
                duration
            };
            (phase_time_step(f, time), f, time)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((f64::INFINITY, 0.0, duration))
}

/// The step that keeps the phase of a mode of `frequency` (Hz) accurate over
/// a run of `duration` (s), s. Newmark's average acceleration lengthens a
/// mode's period by (ωΔt)²/12 (Hughes 1987, §9.3), so its phase drifts by
/// 2π f T (ωΔt)²/12 over the run; keeping that below [`PHASE_BUDGET`] gives
/// ωΔt = √(12 · PHASE_BUDGET / (2π f T)). Deck accelerations need it: they
/// carry their top modes (up to 30 Hz and more) at a sizeable share of the
/// peak for the whole crossing. Measured on the shipped Yang & Yau scene
/// (f₃ = 43 Hz over 0.9 s), 30 steps per period of the highest mode left the
/// mid-span acceleration 2.3 % from the converged answer, from this drift.
pub fn phase_time_step(frequency: f64, duration: f64) -> f64 {
    let omega = 2.0 * std::f64::consts::PI * frequency;
    let cycles = frequency * duration;
    if !(omega > 0.0 && cycles > 0.0) {
        return f64::INFINITY;
    }
    (12.0 * PHASE_BUDGET / (2.0 * std::f64::consts::PI * cycles)).sqrt() / omega
}
