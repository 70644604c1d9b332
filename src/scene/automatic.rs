//! The numbers of the automatic choices (modes, time step, deck-acceleration
//! filter) that the format documents: the planning stage
//! ([`crate::plan::content`], [`crate::plan::acceleration`]) makes the
//! choices with them, and the schema's descriptions are written from them
//! ([`crate::scenario::schema`]), so the two cannot drift (issue 40.3). Here,
//! at the bottom, because both layers read them.

/// Cut-off frequency over the highest excitation frequency: the automatic
/// mode choice keeps every mode up to this multiple of the highest
/// frequency the scene excites.
pub const SAFETY: f64 = 4.0;
/// Fewest modes kept per span.
pub const MODES_PER_SPAN: usize = 5;
/// Fewest modes kept per span of a beam whose wheels and records get the
/// static (mode-acceleration) correction and whose wheels have no mass of
/// their own (moving forces, a sprung mass or a truck's tyres on the
/// deck): the correction adds the quasi-static share of the modes left
/// out, so the floor only has to hold the modes a moving load drives near
/// their frequency (the second of a span is forced at 2 v / 2L, a quarter
/// of its own frequency at v = f₁ L). Measured on two-axle-moving-force:
/// 1 mode within 0.04 % of 10.
pub const MODES_PER_SPAN_CORRECTED: usize = 2;
/// Mode families a plate deck's automatic cut-off keeps at least
/// [`MODES_PER_SPAN`] per span of: bending, torsion, transverse bending.
pub const PLATE_FAMILIES: usize = 3;
/// A wheel (unsprung) mass above this share of the lightest span's mass
/// makes the automatic choice keep twice the fewest modes. Measured on the
/// shipped lcp-fig4-permanent scene (wheel mass 0.2 m L): its contact force
/// was 0.64 % from the converged answer with 5 modes and 0.25 % with 10; the
/// lcp-oscillator scenes (0.025 m L) are within 0.3 % with 5.
pub const HEAVY_WHEEL_RATIO: f64 = 0.1;

/// Steps per period of the highest frequency, for the default time step.
/// Newmark's average acceleration errs by about (ωΔt)²/12 in a mode's
/// period; measured with `vbi converge` on every shipped scene (issue 9),
/// 20 steps left deck accelerations, Hertz forces and plate accelerations
/// 0.5–0.84 % from the converged answer (second order in Δt); 30 puts every
/// quantity but the impulsive rigid-contact ones within the 0.5 % target.
pub const STEPS_PER_PERIOD: f64 = 30.0;

/// Fewest steps the default time step takes over the shortest crossing (a
/// slow vehicle on a stiff, light bridge would otherwise cross in a few
/// steps of its top mode's period).
pub const CROSSING_STEPS: f64 = 200.0;

/// Phase error, rad, the automatic step allows a deck acceleration's highest
/// mode to accumulate over a run ([`crate::plan::content::phase_time_step`]).
pub const PHASE_BUDGET: f64 = 0.02;

/// The floor of the deck-acceleration filter, Hz (EN 1990 A2.4.4.2.1(4)).
pub const FLOOR_HZ: f64 = 30.0;
/// The filter's multiple of the fundamental frequency f₁ (EN 1990
/// A2.4.4.2.1(4): "1.5 times the frequency of the fundamental mode").
pub const FUNDAMENTAL_FACTOR: f64 = 1.5;
