//! summary.json: extremes of every recorded quantity and run metadata.

use serde::Serialize;

use crate::model::Model;
use crate::record::extremes::{Running, Sample};
use crate::record::{Column, GirderDaf, History, WheelSeparation};
use crate::scene::{Quantity, SolverMethod};
use crate::solve::SolveStats;
use crate::solve::iterative::IterationStats;

/// An extreme value and where it happened.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Extreme {
    /// The value, in the column's unit.
    pub value: f64,
    /// Time, s.
    pub time: f64,
    /// Position along the bridge of the reference wheel at that time, m (see
    /// `position_of`).
    pub position: f64,
}

/// Largest, smallest and largest absolute value over a part of the record.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Extremes {
    /// Largest value.
    pub max: Extreme,
    /// Smallest value.
    pub min: Extreme,
    /// The value of largest magnitude, signed (|value| is the largest
    /// absolute value): `largest_magnitude` in summary.json, a name that
    /// does not promise an absolute value (issue 26.5).
    #[serde(rename = "largest_magnitude")]
    pub max_abs: Extreme,
}

/// Statistics of one recorded quantity.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct QuantitySummary {
    /// Column name.
    pub name: String,
    /// Quantity.
    pub quantity: Quantity,
    /// Unit.
    pub unit: &'static str,
    /// What `position` refers to.
    pub position_of: String,
    /// Largest value over the whole record.
    pub max: Extreme,
    /// Smallest value over the whole record.
    pub min: Extreme,
    /// The value of largest magnitude over the whole record, signed
    /// (`largest_magnitude` in summary.json).
    #[serde(rename = "largest_magnitude")]
    pub max_abs: Extreme,
    /// The same three extremes restricted to the samples at which at least
    /// one axle is on the bridge (absent if none is).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub on_bridge: Option<Extremes>,
    /// Bridge displacements, moments, shears and reactions: the static
    /// crossing response of largest magnitude at the same point, signed, in
    /// the column's unit (`static_largest_magnitude` in summary.json).
    #[serde(
        rename = "static_largest_magnitude",
        skip_serializing_if = "Option::is_none"
    )]
    pub static_max_abs: Option<Extreme>,
    /// Bridge displacements, moments, shears and reactions: dynamic
    /// amplification factor max|E_dynamic| / max|E_static| at this point
    /// (dimensionless); none where the static crossing barely moves it
    /// ([`DAF_STATIC_SHARE`], [`DAF_STATIC_FLOOR`],
    /// [`DAF_STATIC_FORCE_FLOOR`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub daf: Option<f64>,
}

/// Metadata of the run.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunInfo {
    /// vbi version.
    pub vbi_version: &'static str,
    /// Solver method.
    pub solver: &'static str,
    /// Contact model.
    pub contact: &'static str,
    /// Wall time of build + solve + record, s.
    pub wall_time: f64,
    /// Number of time steps.
    pub steps: usize,
    /// Time step, s.
    pub time_step: f64,
    /// Simulated duration, s.
    pub end_time: f64,
    /// Bridge modes used.
    pub modes_used: usize,
    /// Modes the bridge discretisation offers.
    pub modes_available: usize,
    /// Whether an imported model's modes were read from the modes cache
    /// (true) or solved and written to it (false); absent without a cache.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modes_from_cache: Option<bool>,
    /// Why a modes cache file that was there was not used (it failed a
    /// re-check; the modes were solved afresh); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modes_cache_rejected: Option<String>,
    /// How the modes were chosen and why.
    pub modes_selection: String,
    /// On an imported track under wheels with mass, where the plan measured
    /// it: the largest share of the rails' static flexibility under a wheel
    /// the kept modes leave out, and how it is carried
    /// ([`crate::plan::track_flexibility`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rails_flexibility: Option<crate::bridge::RailsFlexibility>,
    /// Where a deck acceleration's filter reaches above the kept modes: the
    /// filter, Hz, and how many of the bridge's modes lie up to it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modes_to_acceleration_filter: Option<crate::bridge::AccelerationFilter>,
    /// How the time step was chosen.
    pub time_step_selection: String,
    /// The accuracy the choices of modes and time step aim at.
    pub accuracy_target: String,
    /// Natural frequencies of the modes used, Hz.
    pub frequencies: Vec<f64>,
    /// On an imported model: each mode's direction by the share of its
    /// kinetic energy (`axial`, `lateral`, `vertical` or `torsion`, ry
    /// counted with the vertical and rz with the lateral bending), numbered
    /// within its direction, with that share (`vertical 2 (99.7 %)`), in
    /// the order of `frequencies`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode_directions: Option<Vec<String>>,
    /// On an imported model: the modes the solve found that nothing in the
    /// scene moves (still at the loaded rails, no ground participation),
    /// left out of `frequencies` and of the count (issue 40.6), each with
    /// its frequency (Hz) and direction.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub modes_left_out: Vec<crate::bridge::UnexcitedMode>,
    /// How the DAF's static reference is computed.
    pub static_reference: &'static str,
    /// `iterative` solver: vehicle–bridge iterations per time step.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iterations: Option<IterationStats>,
    /// After a loss of contact: which results depend on the time step.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step_dependent: Option<&'static str>,
}

/// What `run.step_dependent` says when a wheel lost contact under elastic
/// or Hertz contact. Measured on the shipped rail-fra5-oscillator scene
/// (FRA class 5 at 300 km/h, elastic contact, the wheel hops on the bridge
/// and leaves it airborne) with the automatic step 6.1e-5 s against a
/// quarter of it, same modes, while on the bridge.
pub const LANDING_STEP_DEPENDENCE: &str = "a wheel lost contact: its landings fall on the step \
grid (no event location), so contact forces, gaps and the accelerations a landing drives converge \
only as the step shrinks (FRA class 5 at 300 km/h, Δt = 6.1e-5 s against Δt/4: contact force 3.3 %, \
vehicle acceleration 2.2 %, deck acceleration 1.0 % of their peaks; displacements within 0.03 %); \
refine solver.time_step until they stop changing";

/// The whole summary.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Summary {
    /// Scenario name.
    pub scenario: String,
    /// Run metadata.
    pub run: RunInfo,
    /// One entry per recorded quantity, in scenario order.
    pub quantities: Vec<QuantitySummary>,
    /// Under unilateral contact: loss of contact of every wheel with a DOF
    /// (a wheel counts as separated while its force is 0 and its gap exceeds
    /// 1e-9 m).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub separation: Vec<WheelSeparation>,
    /// On a plate deck: the DAF at the middle of every span on every girder
    /// line (`bridge.girder_lines`), span by span.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub girder_dafs: Vec<GirderDaf>,
    /// With `envelopes`: where each enveloped quantity peaks along the deck
    /// (value, point, side, time, lead position, static value and the
    /// point's DAF; issue 40.2), the numbers `envelopes.png` marks.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub envelope_peaks: Vec<super::envelopes::EnvelopePeak>,
    /// With `method: embs`: the small parameter ε and, with
    /// `solver.compare`, the errors against `coupled` and the speed-up.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub embs: Option<super::embs::EmbsSummary>,
    /// On an imported model: its translational mass per direction and its
    /// static deflection under the vehicles' total weight, what an
    /// engineer checks first ([`crate::scene::imported::ImportedTotals`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub imported_model: Option<crate::scene::imported::ImportedTotals>,
    /// What vbi knows about this scene and its result: every warning and
    /// note of the plan and the run ([`crate::advice`], docs/advice.md),
    /// those the scene allows marked with its reason.
    pub advice: Vec<crate::advice::Advice>,
}

/// The smallest static peak, as a share of the dynamic one, for which a
/// displacement record gets a DAF. The static crossing loads the bridge
/// vertically: a lateral DOF of a symmetric imported deck moves by
/// round-off under it (measured: 2.1e-19 m against a 1.4 mm dynamic peak
/// on embs-viaduct-ave-s103-quake's deck node, which printed
/// "DAF 6809192219746858"), and a point near an influence line's zero has
/// no static deflection worth dividing by. Above 1,000 a ratio says only
/// that the record is not driven by the static loads.
pub const DAF_STATIC_SHARE: f64 = 1e-3;

/// The smallest static peak, m, for which a displacement record gets a DAF:
/// a nanometre is far below any bridge's static deflection, and a static
/// column below it is round-off (measured: a deck node's lateral DOF of the
/// generated two-span viaduct under vertical axle loads, static 2.3e-19 m and
/// dynamic 7.7e-18 m, a "DAF" of 33.7 between two round-offs).
pub const DAF_STATIC_FLOOR: f64 = 1e-9;

/// The smallest static peak, N or N·m, for which a moment, shear or
/// reaction record gets a DAF: a micronewton is round-off beside any axle
/// load (issue 40.1: section forces and reactions have a static reference
/// too).
pub const DAF_STATIC_FORCE_FLOOR: f64 = 1e-6;

/// The static floor of `quantity`'s DAF in its unit.
fn daf_static_floor(quantity: Quantity) -> f64 {
    match quantity {
        Quantity::BridgeMoment | Quantity::BridgeShear | Quantity::BridgeReaction => {
            DAF_STATIC_FORCE_FLOOR
        }
        _ => DAF_STATIC_FLOOR,
    }
}

/// Static reference used for DAFs.
pub const STATIC_REFERENCE: &str = "quasi-static crossing of the same wheels with their static \
loads on level ground (moving-force loads, or the vehicle's static contact forces), deflection \
from the full finite-element stiffness via influence lines (no inertia, no modal truncation), \
and bending moments, shears and support reactions exact for point loads on the beam's mesh, at \
the same point and times";

/// Static reference used for DAFs on a plate deck.
pub const STATIC_REFERENCE_PLATE: &str = "quasi-static crossing of the same wheels with their \
static loads on level ground (moving-force loads, or the vehicle's static contact forces), each \
along its own line across the deck, deflection from the whole Ritz stiffness via influence lines \
(no inertia, no modal truncation), at the same point and times";

/// The extreme `sample` of `column`: its value, time and the reference
/// wheel's position then.
fn extreme_of(model: &Model, column: &Column, sample: Sample) -> Extreme {
    let p = column.position;
    Extreme {
        value: sample.value,
        time: sample.time,
        position: model.vehicles[p.vehicle].front_position(sample.time) - p.offset,
    }
}

/// The three extremes of `running`, `None` if it saw no step.
fn extremes_of(model: &Model, column: &Column, running: &Running) -> Option<Extremes> {
    Some(Extremes {
        max: extreme_of(model, column, running.max?),
        min: extreme_of(model, column, running.min?),
        max_abs: extreme_of(model, column, running.max_abs?),
    })
}

/// The error the automatic choices aim at: each recorded quantity's
/// max-abs error over its history, relative to its peak, against the
/// converged answer (what `vbi converge` measures).
pub const AUTOMATIC_TOLERANCE: &str = "0.5 %";

/// What `run.accuracy_target` says: the automatic modes and time step aim
/// at [`AUTOMATIC_TOLERANCE`] for every recorded quantity, measured on every
/// shipped scene with `vbi converge` (issue 9); choices set in the file aim
/// at nothing vbi can state.
fn accuracy_target(model: &Model) -> String {
    let automatic_modes = model.bridge.selection.starts_with("automatic");
    let automatic_step = model.time_step_selection.starts_with("automatic");
    let what = match (automatic_modes, automatic_step) {
        (true, true) => "the automatic modes and time step aim",
        (true, false) => "the automatic modes aim (the time step is set in the file)",
        (false, true) => "the automatic time step aims (the modes are set in the file)",
        (false, false) => {
            return "modes and time step are set in the file: `vbi converge` measures their error"
                .to_owned();
        }
    };
    let mut text = format!(
        "{what} at {AUTOMATIC_TOLERANCE} of the converged answer for every recorded quantity \
         (max-abs error over the history, relative to its peak; bridge accelerations as \
         filtered to their `max_frequency`); `vbi converge` measures it"
    );
    if model.contact != crate::model::ContactLaw::Permanent {
        text.push_str(
            "; except, once a wheel loses contact, contact forces, gaps and accelerations around \
             its landings, which depend on the step (see step_dependent when it happens)",
        );
    }
    text
}

impl Summary {
    /// Builds the summary of a finished run.
    pub fn new(
        name: &str,
        model: &Model,
        history: &History,
        stats: &SolveStats,
        wall_time: f64,
    ) -> Self {
        // Every step's extremes, tracked during the run (exact whatever
        // `output.every` wrote).
        let quantities = history
            .columns
            .iter()
            .zip(&history.extremes)
            .map(|(column, extremes)| {
                let all = extremes_of(model, column, &extremes.all)
                    .expect("every run records t = 0 at least");
                let (max, min, max_abs) = (all.max, all.min, all.max_abs);
                let on_bridge = extremes_of(model, column, &extremes.on_bridge);
                let static_max_abs = column
                    .static_values
                    .as_ref()
                    .and(extremes.statics.max_abs)
                    .map(|s| extreme_of(model, column, s));
                let daf = static_max_abs
                    .as_ref()
                    .filter(|s| {
                        s.value.abs() >= DAF_STATIC_SHARE * max_abs.value.abs()
                            && s.value.abs() >= daf_static_floor(column.quantity)
                    })
                    .filter(|s| s.value != 0.0)
                    .map(|s| max_abs.value.abs() / s.value.abs());
                let p = column.position;
                let position_of = position_of(p);
                QuantitySummary {
                    name: column.name.clone(),
                    quantity: column.quantity,
                    unit: column.unit,
                    position_of,
                    max,
                    min,
                    max_abs,
                    on_bridge,
                    static_max_abs,
                    daf,
                }
            })
            .collect();
        Self {
            scenario: name.to_string(),
            run: RunInfo {
                vbi_version: env!("CARGO_PKG_VERSION"),
                solver: match model.method {
                    SolverMethod::Coupled => "coupled",
                    SolverMethod::Iterative => "iterative",
                    SolverMethod::Lcp => "lcp",
                    SolverMethod::Embs => "embs",
                    SolverMethod::Direct => "direct",
                },
                contact: match model.contact {
                    crate::model::ContactLaw::Permanent => "permanent",
                    crate::model::ContactLaw::Rigid { .. } => "rigid",
                    crate::model::ContactLaw::Elastic { .. } => "elastic",
                    crate::model::ContactLaw::Hertz { .. } => "hertz",
                },
                wall_time,
                steps: model.steps,
                time_step: model.time_step,
                end_time: model.end_time(),
                modes_used: model.bridge.mode_count(),
                modes_from_cache: model.bridge.modes_from_cache,
                modes_cache_rejected: model.bridge.modes_cache_rejected.map(String::from),
                modes_available: model.bridge.available_modes,
                modes_selection: model.bridge.selection.clone(),
                rails_flexibility: model.bridge.rails_flexibility,
                modes_to_acceleration_filter: model.bridge.acceleration_filter,
                time_step_selection: model.time_step_selection.clone(),
                accuracy_target: accuracy_target(model),
                frequencies: model.bridge.frequencies(),
                mode_directions: model.bridge.is_imported().then(|| {
                    (0..model.bridge.mode_count())
                        .map(|i| model.bridge.mode_character(i))
                        .collect()
                }),
                modes_left_out: model.bridge.left_out.clone(),
                static_reference: if model.bridge.width().is_some() {
                    STATIC_REFERENCE_PLATE
                } else {
                    STATIC_REFERENCE
                },
                iterations: stats.iterations,
                // Rigid contact steps impacts by Moreau–Jean (first order through
                // landings, tests/it/moreau_jean.rs): no carve-out.
                step_dependent: if history.separation.iter().any(|w| w.separated) {
                    Some(LANDING_STEP_DEPENDENCE)
                } else {
                    None
                },
            },
            quantities,
            separation: history.separation.clone(),
            // A beam's span middles are in `quantities` already when recorded.
            girder_dafs: if model.bridge.width().is_some() {
                history.girder_dafs.clone()
            } else {
                Vec::new()
            },
            envelope_peaks: history
                .envelope
                .as_ref()
                .map(super::envelopes::envelope_peaks)
                .unwrap_or_default(),
            embs: None,
            imported_model: None,
            advice: Vec::new(),
        }
    }
}

/// What `position` refers to, in words: the recorded wheel itself for a
/// contact force or gap (`wheel 3 of vehicle 1, 4.300 m behind its front
/// axle`), else the front axle of the vehicle the position follows.
fn position_of(p: crate::record::PositionRef) -> String {
    let vehicle = p.vehicle + 1;
    match p.wheel {
        Some(wheel) if p.offset == 0.0 => {
            format!("wheel {wheel} of vehicle {vehicle}, on its front axle")
        }
        Some(wheel) => format!(
            "wheel {wheel} of vehicle {vehicle}, {:.3} m behind its front axle",
            p.offset
        ),
        None if p.offset == 0.0 => format!("front axle of vehicle {vehicle}"),
        None => format!(
            "wheel {:.3} m behind the front axle of vehicle {vehicle}",
            p.offset
        ),
    }
}
