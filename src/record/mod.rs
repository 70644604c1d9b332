//! The record stage: samples the requested quantities at every step into
//! preallocated columns, and alongside each bridge displacement the static
//! response of the same load set crossing (the DAF reference).
//!
//! Every step feeds the running extremes ([`extremes`]), so the summary's
//! maxima, minima and DAFs are exact; only every `every`-th step
//! (`output.every`) is kept as a sample of the history, and none when the
//! history is not wanted (a study's runs).

pub mod extremes;
pub mod spill;

use self::extremes::ColumnExtremes;
use std::cell::RefCell;
use std::rc::Rc;

pub mod envelope;

use self::envelope::{Envelope, EnvelopeTracker};
use crate::bridge::BridgeError;
use crate::bridge::InfluenceLine;
use crate::bridge::section::{SectionLoads, SectionProbe};
use crate::model::Model;
use crate::scene::{Envelopes, Quantity, Record};
use crate::solve::{Observer, StepView};

/// What the summary reports as "position" of an extreme value: the position
/// of a wheel (its vehicle's front axle minus its offset) at that time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionRef {
    /// Vehicle index from 0.
    pub vehicle: usize,
    /// Distance behind the front axle, m.
    pub offset: f64,
    /// The wheel, numbered from 1 in its vehicle, when the record is that
    /// wheel's own (a contact force or gap); `None` for the vehicle's front
    /// axle as a reference (bridge and vehicle-body records).
    pub wheel: Option<usize>,
}

/// How a column is computed each step.
#[derive(Debug, Clone)]
enum Probe {
    /// φᵢ(x, y) at the point; w = Σ φᵢ qᵢ. With the static influence
    /// lines of the point for loads along each wheel's line (one per
    /// distinct wheel y) and, per flattened wheel, which one it uses.
    BridgeDisplacement {
        shape: Vec<f64>,
        statics: StaticProbe,
        /// φᵢ(x, y)/ωᵢ² (static correction), m per unit modal force.
        static_shape: Vec<f64>,
    },
    /// ẅ = Σ φᵢ q̈ᵢ.
    BridgeAcceleration { shape: Vec<f64> },
    /// The rails' lateral displacement v = Σ φᵢ qᵢ (φ the modes' lateral
    /// components at the point), or with `acceleration` v̈: a modal sum,
    /// plus under a lateral record the lateral static share of the modes
    /// left out (`Column::lateral_static`; the static crossing is vertical).
    Lateral { shape: Vec<f64>, acceleration: bool },
    /// A plate deck's moment per unit width at a point; `line_of[w]` is
    /// the probe's influence line of flattened wheel w.
    PlateMoment {
        probe: Box<crate::bridge::plate::moments::PlateMomentProbe>,
        line_of: Vec<usize>,
    },
    /// Bending moment (or, with `shear`, shear force) of a beam section.
    Section {
        section: Box<SectionProbe>,
        shear: bool,
    },
    /// Flattened wheel index.
    ContactForce { wheel: usize },
    /// Flattened wheel index.
    ContactGap { wheel: usize },
    /// Vehicle and DOF; displacement from static equilibrium.
    VehicleDisplacement { vehicle: usize, dof: usize },
    /// Vehicle and DOF.
    VehicleAcceleration { vehicle: usize, dof: usize },
}

/// The distinct transverse positions y of the wheels (m), in order of
/// first appearance, and the index of each flattened wheel's among them:
/// one static influence line per such line serves every wheel on it.
fn wheel_lines(model: &Model) -> (Vec<f64>, Vec<usize>) {
    let mut lines: Vec<f64> = Vec::new();
    let line_of = model
        .wheel_y
        .iter()
        .map(|&wheel_y| match lines.iter().position(|&l| l == wheel_y) {
            Some(index) => index,
            None => {
                lines.push(wheel_y);
                lines.len() - 1
            }
        })
        .collect();
    (lines, line_of)
}

/// The static influence lines of one bridge point for the loads of every
/// wheel: one line per distinct wheel y, and which one each flattened wheel uses.
#[derive(Debug, Clone)]
struct StaticProbe {
    influences: Vec<InfluenceLine>,
    wheel_influence: Vec<usize>,
}

impl StaticProbe {
    /// The probe of the point (x, y), m.
    fn new(model: &Model, x: f64, y: f64) -> Result<Self, BridgeError> {
        let (lines, wheel_influence) = wheel_lines(model);
        let influences = lines
            .iter()
            .map(|&line| model.bridge.influence_line(x, y, line))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self {
            influences,
            wheel_influence,
        })
    }

    /// The probe of free DOF `dof` of an imported model: one influence line
    /// along its track, which every wheel uses.
    fn of_dof(model: &Model, dof: usize) -> Result<Self, BridgeError> {
        Ok(Self {
            influences: vec![model.bridge.dof_influence_line(dof)?],
            wheel_influence: vec![0; model.wheel_y.len()],
        })
    }

    /// Static deflection at the point, m (upward positive), with every wheel
    /// carrying its static load at `positions`.
    /// Only the wheels `on_deck` (indices) are summed: the influence
    /// lines vanish off the deck.
    fn deflection(&self, positions: &[f64], loads: &[f64], on_deck: &[usize]) -> f64 {
        on_deck
            .iter()
            .map(|&w| -loads[w] * self.influences[self.wheel_influence[w]].value_at(positions[w]))
            .sum()
    }

    /// The influence line's value at each wheel `on_deck` (in that order),
    /// m/N, into `values`: [`Self::deflection`]'s factors, for several
    /// load sets at one step.
    fn values_at_wheels(&self, positions: &[f64], on_deck: &[usize], values: &mut Vec<f64>) {
        values.clear();
        values.extend(
            on_deck
                .iter()
                .map(|&w| self.influences[self.wheel_influence[w]].value_at(positions[w])),
        );
    }

    /// [`Self::deflection`] from the values of [`Self::values_at_wheels`].
    fn deflection_from(values: &[f64], loads: &[f64], on_deck: &[usize]) -> f64 {
        on_deck
            .iter()
            .zip(values)
            .map(|(&w, value)| -loads[w] * value)
            .sum()
    }
}

/// One column's per-step values that do not depend on the run's state
/// (bridge displacements; empty for other columns).
#[derive(Debug, Default)]
struct ColumnStatics {
    /// The influence line at each wheel on the deck, m/N.
    influence: Vec<f64>,
    /// The static crossing's deflection, m.
    static_w: f64,
    /// φ_s·φ_w (the column's static shape, each wheel's mode values) per
    /// wheel on the deck, m/N.
    wheel_dots: Vec<f64>,
}

impl Clone for ColumnStatics {
    fn clone(&self) -> Self {
        Self {
            influence: self.influence.clone(),
            static_w: self.static_w,
            wheel_dots: self.wheel_dots.clone(),
        }
    }

    /// In place, keeping the buffers: copied every step of every sample.
    fn clone_from(&mut self, source: &Self) {
        self.influence.clone_from(&source.influence);
        self.static_w = source.static_w;
        self.wheel_dots.clone_from(&source.wheel_dots);
    }
}

/// The per-step values the recorders of one lockstep batch share
/// ([`Recorder::sharing_statics`]).
#[derive(Debug, Default)]
pub struct SharedStatics {
    /// The step they belong to.
    step: Option<usize>,
    columns: Vec<ColumnStatics>,
}

/// The DAF at the middle of one span on one girder line.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GirderDaf {
    /// Span number from 1.
    pub span: usize,
    /// Girder line number from 1.
    pub girder: usize,
    /// Position along the bridge, m.
    pub x: f64,
    /// Position across the deck, m.
    pub y: f64,
    /// Largest |dynamic deflection|, m.
    pub dynamic_max_abs: f64,
    /// Largest |static deflection| of the same wheels crossing, m.
    pub static_max_abs: f64,
    /// dynamic_max_abs / static_max_abs (0 where the static one is 0).
    pub daf: f64,
}

/// Tracks one [`GirderDaf`] during the run.
#[derive(Debug, Clone)]
struct DafProbe {
    result: GirderDaf,
    shape: Vec<f64>,
    statics: StaticProbe,
    static_shape: Vec<f64>,
}

/// φᵢ/ωᵢ² of a point's mode values `shape` (the modal static flexibility).
fn static_shape(model: &Model, shape: &[f64]) -> Vec<f64> {
    shape
        .iter()
        .zip(&model.bridge.circular_frequencies)
        .map(|(phi, w)| phi / (w * w))
        .collect()
}

/// The static share of the modes left out at a point (m, upward
/// positive): the full static deflection under the current wheel forces
/// minus its modal part, Σ_w F_w [Σᵢ φᵢ(x)φᵢ(x_w)/ωᵢ² − G(x, x_w)]
/// (mode-acceleration method; Williams 1945; Cornwell, Craig & Johnson
/// 1983). `wheel_modes` holds the mode values at each wheel (wheel-major).
fn truncated_static_share(
    statics: &StaticProbe,
    static_shape: &[f64],
    wheel_modes: &[f64],
    view: &StepView<'_>,
    on_deck: &[usize],
) -> f64 {
    let full = statics.deflection(view.wheel_positions, view.contact_forces, on_deck);
    static_share_beyond(full, static_shape, wheel_modes, view, on_deck)
}

/// [`truncated_static_share`] with the full static deflection under the
/// current wheel forces, `full` (m), given.
fn static_share_beyond(
    full: f64,
    static_shape: &[f64],
    wheel_modes: &[f64],
    view: &StepView<'_>,
    on_deck: &[usize],
) -> f64 {
    let modes = static_shape.len();
    let modal: f64 = on_deck
        .iter()
        .map(|&w| {
            let values = &wheel_modes[w * modes..(w + 1) * modes];
            -view.contact_forces[w] * dot(static_shape, values)
        })
        .sum();
    full - modal
}

/// The unit a quantity's values are recorded in (SI; a vehicle's rotation
/// DOF is in rad, rad/s², under the same column unit as its translations).
pub fn unit_of(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::BridgeDisplacement | Quantity::ContactGap | Quantity::VehicleDisplacement => "m",
        Quantity::BridgeAcceleration | Quantity::VehicleAcceleration => "m/s^2",
        Quantity::BridgeMoment => "N*m",
        Quantity::BridgeShear | Quantity::ContactForce => "N",
    }
}

/// The deck-acceleration filter: the mode values `shape` with the modes
/// above the cut-off `max_frequency` (Hz) zeroed (a sharp modal low-pass,
/// EN 1990 A2.4.4.2.1(4)).
fn filtered_shape(model: &Model, shape: &[f64], max_frequency: Option<f64>) -> Vec<f64> {
    let mut shape = shape.to_vec();
    if let Some(cut) = max_frequency {
        let limit = 2.0 * std::f64::consts::PI * cut * (1.0 + 1e-12);
        for (value, omega) in shape.iter_mut().zip(&model.bridge.circular_frequencies) {
            if *omega > limit {
                *value = 0.0;
            }
        }
    }
    shape
}

/// A recorded bridge displacement (m, upward): the modal sum, plus the
/// static share of the modes left out when `wheel_modes` is filled (the
/// static correction is on).
fn corrected_displacement(
    shape: &[f64],
    statics: &StaticProbe,
    static_shape: &[f64],
    wheel_modes: &[f64],
    view: &StepView<'_>,
    on_deck: &[usize],
) -> f64 {
    let modal = dot(shape, view.modal_displacement);
    if wheel_modes.is_empty() {
        modal
    } else {
        modal + truncated_static_share(statics, static_shape, wheel_modes, view, on_deck)
    }
}

/// One recorded time history.
#[derive(Debug, Clone)]
pub struct Column {
    /// Name from the scenario.
    pub name: String,
    /// The quantity.
    pub quantity: Quantity,
    /// Unit of the values.
    pub unit: &'static str,
    /// Sampled values, one per written step (t = 0 and every `every`-th
    /// step after it).
    pub values: Vec<f64>,
    /// For bridge displacements: the static crossing response at the same
    /// point, m (positive upward).
    pub static_values: Option<Vec<f64>>,
    /// Whose position the summary reports with each extreme.
    pub position: PositionRef,
    probe: Probe,
    /// Under ground motion: the upward deflection per unit upward ground
    /// acceleration that the kept modes leave out (bridge displacements on
    /// a beam with the static correction; [`crate::bridge::ModalBridge::ground_static_share`]),
    /// m/(m/s²); 0 otherwise.
    ground_static: f64,
    /// Under a lateral record, the lateral rail deflection per unit lateral
    /// ground acceleration that the kept modes leave out (lateral bridge
    /// displacements on a 3D beam or an imported model with the static
    /// correction;
    /// [`crate::bridge::ModalBridge::lateral_ground_static_share`]),
    /// m/(m/s²); 0 otherwise.
    lateral_static: f64,
    /// Under ground motion, an absolute record adds the ground's own
    /// displacement or acceleration.
    absolute: Option<GroundTerm>,
}

/// Which motion of the ground an absolute record adds.
#[derive(Debug, Clone, Copy, PartialEq)]
enum GroundTerm {
    Displacement,
    Acceleration,
    LateralDisplacement,
    LateralAcceleration,
}

/// All recorded columns with their common time axis.
#[derive(Debug, Clone, Default)]
pub struct History {
    /// Time of each sample, s.
    pub time: Vec<f64>,
    /// The columns in scenario order.
    pub columns: Vec<Column>,
    /// Each column's extremes over every step (not only the written ones).
    pub extremes: Vec<ColumnExtremes>,
    /// Steps between written samples (1: every step).
    pub every: usize,
    /// Separation statistics of every wheel with a DOF, under unilateral
    /// contact (empty under permanent contact).
    pub separation: Vec<WheelSeparation>,
    /// The DAF at the middle of every span on every girder line, span by
    /// span (a beam has one line, at y = 0).
    pub girder_dafs: Vec<GirderDaf>,
    /// Envelopes along the deck, when the scene asks for them.
    pub envelope: Option<Envelope>,
    /// The written rows when they were streamed to disk during the run
    /// ([`Recorder::spill_into`]): then `time` and the columns' values are
    /// empty and the history files are written from this.
    pub spilled: Option<std::sync::Arc<spill::SpilledRows>>,
}

impl History {
    /// Values per row of the history table: time, and each column's value
    /// and, for a bridge displacement, its static value.
    pub fn row_width(&self) -> usize {
        1 + self
            .columns
            .iter()
            .map(|c| 1 + usize::from(c.static_values.is_some()))
            .sum::<usize>()
    }
}

pub use crate::contact::SEPARATION_GAP;

/// Loss of contact of one wheel over a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct WheelSeparation {
    /// Vehicle number from 1.
    pub vehicle: usize,
    /// Wheel number from 1.
    pub wheel: usize,
    /// Whether the wheel ever lost contact (at least one episode).
    pub separated: bool,
    /// Number of contact-loss episodes: flights (zero contact force, gap
    /// above [`SEPARATION_GAP`]) whose gap passes the loss gap — 1 µm for
    /// rigid contact ([`crate::contact::RIGID_LOSS_GAP`]), [`SEPARATION_GAP`]
    /// for elastic and Hertz contact. Time separated and the largest gap
    /// are over these episodes.
    pub episodes: usize,
    /// Time of the first loss of contact, s.
    pub first_loss_time: Option<f64>,
    /// Position of the wheel at the first loss, m.
    pub first_loss_position: Option<f64>,
    /// Total time separated, s (steps separated × Δt).
    pub time_separated: f64,
    /// Largest gap between wheel and surface, m (0 if never separated).
    pub max_gap: f64,
    /// Time of the largest gap, s.
    pub max_gap_time: Option<f64>,
    /// Rigid contact: the gap a flight must pass to count as an episode, m
    /// ([`crate::contact::RIGID_LOSS_GAP`]; absent for elastic and Hertz
    /// contact, which count every flight above [`SEPARATION_GAP`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss_gap: Option<f64>,
    #[serde(skip)]
    flat: usize,
    #[serde(skip)]
    apart: bool,
    /// The flight under way (while `apart`): its start (time s, wheel
    /// position m), time so far (s), largest gap (m, with its time s), and
    /// whether it has become an episode (its gap passed the loss gap).
    #[serde(skip)]
    flight: Flight,
}

/// A flight of one wheel, counted as an episode once its gap passes the
/// contact law's loss gap ([`crate::contact::RIGID_LOSS_GAP`] for rigid
/// contact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Flight {
    start: (f64, f64),
    time: f64,
    max_gap: (f64, f64),
    counted: bool,
}

/// Samples columns each step; see [`History`].
#[derive(Debug)]
pub struct Recorder<'m> {
    model: &'m Model,
    history: History,
    daf_probes: Vec<DafProbe>,
    /// Mode values at every wheel this step (wheel-major), for the static
    /// correction; empty when it is off or nothing needs it.
    wheel_modes: Vec<f64>,
    /// Envelopes along the deck, when asked for.
    envelope: Option<EnvelopeTracker>,
    /// The wheels on the deck this step (indices): only they load it, so
    /// the static parts sum over them alone.
    on_deck: Vec<usize>,
    /// Per column, this step's values that do not depend on the state.
    statics: Vec<ColumnStatics>,
    /// The copy shared by the recorders of a lockstep batch, if any.
    shared: Option<Rc<RefCell<SharedStatics>>>,
    /// Whether samples are kept at all (else only the extremes).
    keep: bool,
    /// Whether a column adds the ground's displacement (then it is
    /// integrated each step).
    absolute_displacement: bool,
    /// Whether a record adds the lateral ground motion (absolute frame).
    absolute_lateral: bool,
    /// Where written rows go when streamed to disk.
    spill: Option<spill::SpillWriter>,
}

impl<'m> Recorder<'m> {
    /// Prepares the probes of `records` (already validated against the model).
    pub fn new(model: &'m Model, records: &[Record]) -> Result<Self, BridgeError> {
        let modes = model.bridge.mode_count();
        // Preallocate at most a million samples per column: the step count
        // comes from the input, and the budgets bound what a run may record,
        // but a history larger than that grows as it is recorded rather than
        // being reserved (and possibly refused by the allocator) up front.
        let capacity = model.steps.saturating_add(1).min(1 << 20);
        let lead = PositionRef {
            vehicle: 0,
            offset: 0.0,
            wheel: None,
        };
        let mut columns = Vec::with_capacity(records.len());
        for record in records {
            let vehicle = record.vehicle.map_or(0, |v| v - 1);
            let (probe, unit, position) = match record.quantity {
                Quantity::BridgeDisplacement | Quantity::BridgeAcceleration => {
                    let x = record.x.unwrap_or(0.0);
                    let y = record.y.unwrap_or(0.0);
                    let mut shape = vec![0.0; modes];
                    // A node's DOF of an imported model (validated when
                    // resolving), or a point along the track or deck.
                    if record.node.is_none()
                        && record.direction == Some(crate::scene::imported::Direction::Uy)
                    {
                        model.bridge.mode_values_in(
                            crate::contact::ContactDirection::Lateral,
                            x,
                            y,
                            &mut shape,
                        );
                        let acceleration = record.quantity == Quantity::BridgeAcceleration;
                        let (shape, unit) = if acceleration {
                            (filtered_shape(model, &shape, record.max_frequency), "m/s^2")
                        } else {
                            (shape, "m")
                        };
                        let probe = Probe::Lateral {
                            shape,
                            acceleration,
                        };
                        let (ground_static, lateral_static, absolute) =
                            ground_terms(model, record, &probe)?;
                        columns.push(Column {
                            name: record.name.clone(),
                            quantity: record.quantity,
                            unit,
                            values: Vec::with_capacity(capacity),
                            static_values: None,
                            position: lead,
                            probe,
                            ground_static,
                            lateral_static,
                            absolute,
                        });
                        continue;
                    }
                    let dof = match record.node {
                        Some(node) => {
                            let direction = record.direction.unwrap_or_default();
                            let dof = model
                                .bridge
                                .imported_dof(node, direction)
                                .ok()
                                .flatten()
                                .expect("record nodes were validated when resolving");
                            model.bridge.dof_mode_values(dof, &mut shape);
                            Some(dof)
                        }
                        None => {
                            model.bridge.mode_values(x, y, &mut shape);
                            None
                        }
                    };
                    if record.quantity == Quantity::BridgeDisplacement {
                        let statics = match dof {
                            Some(dof) => StaticProbe::of_dof(model, dof)?,
                            None => StaticProbe::new(model, x, y)?,
                        };
                        let static_shape = static_shape(model, &shape);
                        let probe = Probe::BridgeDisplacement {
                            shape,
                            statics,
                            static_shape,
                        };
                        (probe, "m", lead)
                    } else {
                        let shape = filtered_shape(model, &shape, record.max_frequency);
                        (Probe::BridgeAcceleration { shape }, "m/s^2", lead)
                    }
                }
                Quantity::BridgeMoment if record.component.is_some() => {
                    // A plate deck (moments per unit width).
                    let (x, y) = (record.x.unwrap_or(0.0), record.y.unwrap_or(0.0));
                    let (lines, line_of) = wheel_lines(model);
                    let component = record.component.expect("checked by the guard");
                    let probe = model
                        .bridge
                        .plate_moment_probe(x, y, component, &lines)?
                        .expect("a moment component is resolved for plates only");
                    let probe = Probe::PlateMoment {
                        probe: Box::new(probe),
                        line_of,
                    };
                    (probe, "N*m/m", lead)
                }
                Quantity::BridgeMoment | Quantity::BridgeShear => {
                    let x = record.x.unwrap_or(0.0);
                    let section = model
                        .bridge
                        .section_probe(x)?
                        .expect("moments and shears on a plate were refused when resolving");
                    let shear = record.quantity == Quantity::BridgeShear;
                    let unit = if shear { "N" } else { "N*m" };
                    let probe = Probe::Section {
                        section: Box::new(section),
                        shear,
                    };
                    (probe, unit, lead)
                }
                Quantity::ContactForce | Quantity::ContactGap => {
                    let wheel = record.wheel.map_or(0, |w| w - 1);
                    let flat = model
                        .wheel_index(vehicle, wheel)
                        .expect("wheel numbers were validated when resolving");
                    let offset = model.vehicles[vehicle].wheels[wheel].offset;
                    let position = PositionRef {
                        vehicle,
                        offset,
                        wheel: Some(wheel + 1),
                    };
                    if record.quantity == Quantity::ContactForce {
                        (Probe::ContactForce { wheel: flat }, "N", position)
                    } else {
                        (Probe::ContactGap { wheel: flat }, "m", position)
                    }
                }
                Quantity::VehicleDisplacement | Quantity::VehicleAcceleration => {
                    let dof = record
                        .dof
                        .as_deref()
                        .and_then(|d| {
                            model.vehicles[vehicle]
                                .dof_names
                                .iter()
                                .position(|n| n == d)
                        })
                        .expect("DOF names were validated when resolving");
                    let position = PositionRef {
                        vehicle,
                        offset: 0.0,
                        wheel: None,
                    };
                    if record.quantity == Quantity::VehicleDisplacement {
                        (Probe::VehicleDisplacement { vehicle, dof }, "m", position)
                    } else {
                        (
                            Probe::VehicleAcceleration { vehicle, dof },
                            "m/s^2",
                            position,
                        )
                    }
                }
            };
            let static_values = matches!(probe, Probe::BridgeDisplacement { .. })
                .then(|| Vec::with_capacity(capacity));
            let (ground_static, lateral_static, absolute) = ground_terms(model, record, &probe)?;
            columns.push(Column {
                name: record.name.clone(),
                quantity: record.quantity,
                unit,
                values: Vec::with_capacity(capacity),
                static_values,
                position,
                probe,
                ground_static,
                lateral_static,
                absolute,
            });
        }
        let separation = if model.contact.is_unilateral() {
            model
                .wheels
                .iter()
                .enumerate()
                .filter(|(_, r)| {
                    matches!(
                        model.vehicles[r.vehicle].wheels[r.wheel].kind,
                        crate::vehicle::WheelKind::Dof(_)
                    )
                })
                .map(|(flat, r)| WheelSeparation {
                    vehicle: r.vehicle + 1,
                    wheel: r.wheel + 1,
                    separated: false,
                    episodes: 0,
                    first_loss_time: None,
                    first_loss_position: None,
                    time_separated: 0.0,
                    max_gap: 0.0,
                    max_gap_time: None,
                    loss_gap: matches!(model.contact, crate::model::ContactLaw::Rigid { .. })
                        .then_some(crate::contact::RIGID_LOSS_GAP),
                    flat,
                    apart: false,
                    flight: Flight::default(),
                })
                .collect()
        } else {
            Vec::new()
        };
        let mut daf_probes = Vec::new();
        for (s, ends) in model.bridge.supports.windows(2).enumerate() {
            let x = 0.5 * (ends[0] + ends[1]);
            for (g, &y) in model.girder_lines.iter().enumerate() {
                let mut shape = vec![0.0; modes];
                model.bridge.mode_values(x, y, &mut shape);
                daf_probes.push(DafProbe {
                    result: GirderDaf {
                        span: s + 1,
                        girder: g + 1,
                        x,
                        y,
                        dynamic_max_abs: 0.0,
                        static_max_abs: 0.0,
                        daf: 0.0,
                    },
                    static_shape: static_shape(model, &shape),
                    shape,
                    statics: StaticProbe::new(model, x, y)?,
                });
            }
        }
        let corrected = model.bridge.static_correction
            && (!daf_probes.is_empty()
                || columns.iter().any(|c| {
                    matches!(
                        c.probe,
                        Probe::BridgeDisplacement { .. }
                            | Probe::Section { .. }
                            | Probe::PlateMoment { .. }
                    )
                }));
        let wheel_modes = if corrected {
            vec![0.0; model.wheels.len() * modes]
        } else {
            Vec::new()
        };
        let absolute_displacement = columns
            .iter()
            .any(|c| c.absolute == Some(GroundTerm::Displacement));
        let absolute_lateral = columns.iter().any(|c| {
            matches!(
                c.absolute,
                Some(GroundTerm::LateralDisplacement | GroundTerm::LateralAcceleration)
            )
        });
        Ok(Self {
            model,
            history: History {
                time: Vec::with_capacity(capacity),
                // One per column, however the columns came to be.
                extremes: vec![ColumnExtremes::default(); columns.len()],
                columns,
                every: 1,
                separation,
                girder_dafs: Vec::new(),
                envelope: None,
                spilled: None,
            },
            daf_probes,
            wheel_modes,
            envelope: None,
            on_deck: Vec::with_capacity(model.wheels.len()),
            statics: vec![ColumnStatics::default(); records.len()],
            shared: None,
            keep: true,
            absolute_displacement,
            absolute_lateral,
            spill: None,
        })
    }

    /// Also tracks the envelopes along the deck of `envelopes` (resolved,
    /// on a beam).
    pub fn with_envelopes(mut self, envelopes: Option<&Envelopes>) -> Result<Self, BridgeError> {
        let Some(envelopes) = envelopes else {
            return Ok(self);
        };
        let tracker = EnvelopeTracker::new(self.model, envelopes)?;
        let model = self.model;
        if model.bridge.static_correction
            && tracker.needs_wheel_modes()
            && self.wheel_modes.is_empty()
        {
            self.wheel_modes = vec![0.0; model.wheels.len() * model.bridge.mode_count()];
        }
        self.envelope = Some(tracker);
        Ok(self)
    }

    /// Keeps only every `every`-th step's sample (t = 0 first); the extremes
    /// still see every step.
    pub fn every(mut self, every: usize) -> Self {
        let every = every.max(1);
        self.history.every = every;
        let capacity = (self.model.steps / every).saturating_add(1).min(1 << 20);
        self.history.time = Vec::with_capacity(capacity);
        for c in &mut self.history.columns {
            c.values = Vec::with_capacity(capacity);
            c.static_values = c
                .static_values
                .as_ref()
                .map(|_| Vec::with_capacity(capacity));
        }
        self
    }

    /// Streams the written rows to a file in `folder` (the output folder)
    /// instead of keeping them: memory stays flat whatever the step count
    /// ([`spill`]). Call after [`Recorder::every`].
    pub fn spill_into(mut self, folder: &std::path::Path) -> std::io::Result<Self> {
        let width = self.row_width();
        self.spill = Some(spill::SpillWriter::create(folder, width)?);
        self.history.time = Vec::with_capacity(1);
        for c in &mut self.history.columns {
            c.values = Vec::with_capacity(1);
            c.static_values = c.static_values.as_ref().map(|_| Vec::with_capacity(1));
        }
        Ok(self)
    }

    /// Values per written row ([`History::row_width`]).
    pub fn row_width(&self) -> usize {
        self.history.row_width()
    }

    /// [`Recorder::finish`] of a spilling recorder: the history with its
    /// rows on disk, or the first write error (the file then removed).
    pub fn finish_spilled(mut self) -> std::io::Result<History> {
        let writer = self.spill.take();
        let mut history = self.finish();
        if let Some(writer) = writer {
            history.spilled = Some(std::sync::Arc::new(writer.finish()?));
        }
        Ok(history)
    }

    /// Keeps no samples at all, only the extremes and statistics (a study's
    /// run whose history nobody writes).
    pub fn without_samples(mut self) -> Self {
        self.keep = false;
        self.history.time = Vec::new();
        for c in &mut self.history.columns {
            c.values = Vec::new();
            c.static_values = c.static_values.as_ref().map(|_| Vec::new());
        }
        self
    }

    /// The same recorder reading and writing the per-step values that do
    /// not depend on the run's state (influence values at the wheels, the
    /// static crossing, the modal shares of the static correction) in
    /// `shared`, with the other recorders of a lockstep batch: the first to
    /// observe a step makes them, the others copy them. Every recorder that
    /// shares must have the same records on the same bridge, wheels and
    /// time steps (the samples of one Monte Carlo case); the values are then
    /// the ones each would make, bit for bit.
    pub fn sharing_statics(mut self, shared: Rc<RefCell<SharedStatics>>) -> Self {
        self.shared = Some(shared);
        self
    }

    /// The same recorder without the girder DAF tracking (the summary's
    /// `girder_dafs`, empty then), for runs whose summary is not written:
    /// a study's samples. The recorded columns are unchanged.
    pub fn without_girder_dafs(mut self) -> Self {
        self.daf_probes.clear();
        self
    }

    /// The recorded history.
    pub fn finish(mut self) -> History {
        self.history.envelope = self.envelope.take().map(EnvelopeTracker::finish);
        self.history.girder_dafs = self
            .daf_probes
            .into_iter()
            .map(|mut probe| {
                let r = &mut probe.result;
                r.daf = if r.static_max_abs > 0.0 {
                    r.dynamic_max_abs / r.static_max_abs
                } else {
                    0.0
                };
                probe.result
            })
            .collect();
        self.history
    }
}

/// The ground-motion terms of a record's column: the static share of the
/// modes left out per unit vertical and per unit lateral ground
/// acceleration, and what an absolute record adds. All vanish without
/// ground motion; rotations and contact quantities are the same in both
/// frames.
fn ground_terms(
    model: &Model,
    record: &Record,
    probe: &Probe,
) -> Result<(f64, f64, Option<GroundTerm>), BridgeError> {
    let Some(ground) = &model.ground else {
        return Ok((0.0, 0.0, None));
    };
    let (mut vertical, absolute) = vertical_ground_terms(model, ground, record, probe)?;
    // Lateral rail displacements on a 3D beam or an imported model: the
    // lateral static share (mode-acceleration method, as for vertical
    // displacements).
    let mut lateral = match probe {
        Probe::Lateral {
            acceleration: false,
            ..
        } if model.bridge.static_correction && !ground.lateral.is_empty() => model
            .bridge
            .lateral_ground_static_share(
                ground.lateral_mass / model.bridge.length,
                record.x.unwrap_or(0.0),
                record.y.unwrap_or(0.0),
                &ground.lateral_participation,
            )?
            .unwrap_or(0.0),
        _ => 0.0,
    };
    // A node's DOF of an imported model: both static shares at the DOF
    // itself (K⁻¹ M δ there), whatever its direction.
    if let (Probe::BridgeDisplacement { .. }, Some(node), true) =
        (probe, record.node, model.bridge.static_correction)
        && let Ok(Some(dof)) = model
            .bridge
            .imported_dof(node, record.direction.unwrap_or_default())
    {
        let participation = |records: bool, factors: &[f64]| -> Vec<f64> {
            if records {
                factors.to_vec()
            } else {
                Vec::new()
            }
        };
        if let Some((v, l)) = model.bridge.dof_ground_static_shares(
            dof,
            &participation(!ground.vertical.is_empty(), &ground.participation),
            &participation(!ground.lateral.is_empty(), &ground.lateral_participation),
        )? {
            (vertical, lateral) = (v, l);
        }
    }
    Ok((vertical, lateral, absolute))
}

/// [`ground_terms`]' vertical static share and absolute term.
fn vertical_ground_terms(
    model: &Model,
    ground: &crate::ground::GroundExcitation,
    record: &Record,
    probe: &Probe,
) -> Result<(f64, Option<GroundTerm>), BridgeError> {
    let absolute = record.frame == crate::scene::Frame::Absolute;
    let lateral_node =
        record.node.is_some() && record.direction == Some(crate::scene::imported::Direction::Uy);
    Ok(match *probe {
        Probe::Lateral { acceleration, .. } => {
            let term = if acceleration {
                GroundTerm::LateralAcceleration
            } else {
                GroundTerm::LateralDisplacement
            };
            (0.0, absolute.then_some(term))
        }
        // An imported model's lateral DOF: relative to the lateral ground
        // motion (the vertical static share is not its).
        Probe::BridgeDisplacement { .. } if lateral_node => {
            (0.0, absolute.then_some(GroundTerm::LateralDisplacement))
        }
        Probe::BridgeAcceleration { .. } if lateral_node => {
            (0.0, absolute.then_some(GroundTerm::LateralAcceleration))
        }
        Probe::BridgeDisplacement { .. } => {
            let share = if model.bridge.static_correction {
                model
                    .bridge
                    .ground_static_share(
                        ground.total_mass / model.bridge.length,
                        record.x.unwrap_or(0.0),
                        &ground.participation,
                    )?
                    .unwrap_or(0.0)
            } else {
                0.0
            };
            (share, absolute.then_some(GroundTerm::Displacement))
        }
        Probe::BridgeAcceleration { .. } => (0.0, absolute.then_some(GroundTerm::Acceleration)),
        Probe::VehicleDisplacement { vehicle, dof }
        | Probe::VehicleAcceleration { vehicle, dof } => {
            // Only translations move with the ground: vertically the DOFs
            // that carry weight, laterally those a rigid lateral shift
            // moves (a `train_3d`'s lateral DOFs).
            let v = &model.vehicles[vehicle];
            let vertical = v.gravity_load[dof] != 0.0;
            let lateral = v.lateral_ground_load.get(dof).is_some_and(|l| *l != 0.0);
            let displacement = matches!(probe, Probe::VehicleDisplacement { .. });
            let term = match (vertical, lateral, displacement) {
                (true, _, true) => Some(GroundTerm::Displacement),
                (true, _, false) => Some(GroundTerm::Acceleration),
                (false, true, true) => Some(GroundTerm::LateralDisplacement),
                (false, true, false) => Some(GroundTerm::LateralAcceleration),
                (false, false, _) => None,
            };
            (0.0, term.filter(|_| absolute))
        }
        // A plate's records under ground motion are modal sums (no
        // full-stiffness share of the inertia load; as its displacements).
        Probe::PlateMoment { .. } => (0.0, None),
        Probe::Section { ref section, shear } => {
            // Moments and shears are frame-independent (relative motion).
            let share = if model.bridge.static_correction {
                let forces = model.bridge.ground_section_share(
                    section,
                    ground.total_mass / model.bridge.length,
                    &ground.participation,
                );
                if shear { forces.shear } else { forces.moment }
            } else {
                0.0
            };
            (share, None)
        }
        Probe::ContactForce { .. } | Probe::ContactGap { .. } => (0.0, None),
    })
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl Observer for Recorder<'_> {
    fn observe(&mut self, view: &StepView<'_>) {
        let sampled = self.keep && view.step.is_multiple_of(self.history.every);
        if sampled {
            self.history.time.push(view.time);
        }
        // Whether at least one axle is on the deck (the summary's `on_bridge`).
        let any_on_deck = view
            .wheel_positions
            .iter()
            .any(|&x| self.model.bridge.is_on(x));
        let dt = self.model.time_step;
        // A flight (zero force, gap above SEPARATION_GAP) is a contact-loss
        // episode once its gap passes the loss gap (see RIGID_LOSS_GAP);
        // then its whole time and largest gap count.
        for wheel in &mut self.history.separation {
            let loss_gap = wheel.loss_gap.unwrap_or(SEPARATION_GAP);
            let gap = view.contact_gaps[wheel.flat];
            // A rigid wheel with a gap carries no force; its recorded force
            // is averaged over 1 ms after a landing (a bounce's flight has a
            // positive average), so the gap alone tells a flight.
            let apart = gap > SEPARATION_GAP
                && (wheel.loss_gap.is_some() || view.contact_forces[wheel.flat] <= 0.0);
            if apart {
                let flight = &mut wheel.flight;
                if !wheel.apart {
                    *flight = Flight {
                        start: (view.time, view.wheel_positions[wheel.flat]),
                        ..Flight::default()
                    };
                }
                if view.step > 0 {
                    flight.time += dt;
                }
                if gap > flight.max_gap.0 {
                    flight.max_gap = (gap, view.time);
                }
                if !flight.counted && gap > loss_gap {
                    flight.counted = true;
                    wheel.episodes += 1;
                    wheel.separated = true;
                    if wheel.first_loss_time.is_none() {
                        wheel.first_loss_time = Some(flight.start.0);
                        wheel.first_loss_position = Some(flight.start.1);
                    }
                    // The flight's time so far (this step's included).
                    wheel.time_separated += flight.time;
                } else if flight.counted && view.step > 0 {
                    wheel.time_separated += dt;
                }
                if flight.counted && flight.max_gap.0 > wheel.max_gap {
                    wheel.max_gap = flight.max_gap.0;
                    wheel.max_gap_time = Some(flight.max_gap.1);
                }
            }
            wheel.apart = apart;
        }
        let model = self.model;
        // Mode-acceleration (static) correction of recorded displacements:
        // the modes left out respond quasi-statically, so their share is the
        // exact static deflection under the current wheel forces minus its
        // modal part, w_c = Σ_w F_w [G(x_w) − Σᵢ φᵢ(x)φᵢ(x_w)/ωᵢ²]
        // (Williams 1945; Cornwell, Craig & Johnson 1983; F_w downward).
        let modes = model.bridge.mode_count();
        self.on_deck.clear();
        self.on_deck.extend(
            (0..view.wheel_positions.len())
                .filter(|&w| model.bridge.is_on(view.wheel_positions[w])),
        );
        let on_deck = &self.on_deck;
        if !self.wheel_modes.is_empty() {
            for &w in on_deck {
                let values = &mut self.wheel_modes[w * modes..(w + 1) * modes];
                match view.wheel_modes {
                    Some(given) => values.copy_from_slice(&given[w * modes..(w + 1) * modes]),
                    None => model.bridge.contact_mode_values(
                        view.wheel_positions[w],
                        model.wheel_y[w],
                        values,
                    ),
                }
            }
        }
        if let Some(envelope) = &mut self.envelope {
            envelope.observe(model, view, &self.wheel_modes, on_deck);
        }
        for probe in &mut self.daf_probes {
            let mut dynamic = dot(&probe.shape, view.modal_displacement);
            if !self.wheel_modes.is_empty() {
                dynamic += truncated_static_share(
                    &probe.statics,
                    &probe.static_shape,
                    &self.wheel_modes,
                    view,
                    on_deck,
                );
            }
            let statics =
                probe
                    .statics
                    .deflection(view.wheel_positions, &model.static_wheel_loads, on_deck);
            let r = &mut probe.result;
            r.dynamic_max_abs = r.dynamic_max_abs.max(dynamic.abs());
            r.static_max_abs = r.static_max_abs.max(statics.abs());
        }
        // The ground's motion this step (0 without ground motion), once for
        // every column: acceleration, and displacement only if a record
        // asks for it.
        let (ground_acceleration, ground_displacement) = match &model.ground {
            None => (0.0, 0.0),
            Some(ground) => (
                ground.vertical_acceleration(view.time),
                if self.absolute_displacement {
                    ground.vertical_motion(view.time).1
                } else {
                    0.0
                },
            ),
        };
        // Laterally: the acceleration for the lateral static share and
        // absolute records, the displacement only for absolute ones.
        let (lateral_acceleration, lateral_displacement) = match &model.ground {
            Some(ground) if !ground.lateral.is_empty() => (
                ground.lateral_acceleration(view.time),
                if self.absolute_lateral {
                    ground.lateral_motion(view.time).1
                } else {
                    0.0
                },
            ),
            _ => (0.0, 0.0),
        };
        let reuse = self
            .shared
            .as_ref()
            .is_some_and(|shared| shared.borrow().step == Some(view.step));
        if reuse && let Some(shared) = &self.shared {
            self.statics.clone_from(&shared.borrow().columns);
        }
        for (index, (column, extremes)) in self
            .history
            .columns
            .iter_mut()
            .zip(&mut self.history.extremes)
            .enumerate()
        {
            let value = match &column.probe {
                Probe::BridgeDisplacement {
                    shape,
                    statics,
                    static_shape,
                } => {
                    // What does not depend on the run's state: the influence
                    // values at the wheels (for the static crossing — each
                    // wheel's static load at its current position through
                    // the influence line of its lane, full stiffness, no
                    // modal truncation — and for the correction's full
                    // deflection) and the modal shares φ_s·φ_w of the
                    // correction; from the batch's shared copy when another
                    // recorder of a lockstep batch already made them.
                    let part = &mut self.statics[index];
                    if !reuse {
                        statics.values_at_wheels(
                            view.wheel_positions,
                            on_deck,
                            &mut part.influence,
                        );
                        part.static_w = StaticProbe::deflection_from(
                            &part.influence,
                            &model.static_wheel_loads,
                            on_deck,
                        );
                        part.wheel_dots.clear();
                        if !self.wheel_modes.is_empty() {
                            part.wheel_dots.extend(on_deck.iter().map(|&w| {
                                dot(static_shape, &self.wheel_modes[w * modes..(w + 1) * modes])
                            }));
                        }
                    }
                    let static_w = part.static_w;
                    extremes.statics.push(view.step, view.time, static_w);
                    if sampled && let Some(s) = column.static_values.as_mut() {
                        s.push(static_w);
                    }
                    let modal = dot(shape, view.modal_displacement);
                    if self.wheel_modes.is_empty() {
                        modal
                    } else {
                        // Σ_w F_w [G(x, x_w) − Σᵢ φᵢ(x)φᵢ(x_w)/ωᵢ²], as
                        // `truncated_static_share`, term by term.
                        let full = StaticProbe::deflection_from(
                            &part.influence,
                            view.contact_forces,
                            on_deck,
                        );
                        let modal_share: f64 = on_deck
                            .iter()
                            .zip(&part.wheel_dots)
                            .map(|(&w, d)| -view.contact_forces[w] * d)
                            .sum();
                        modal + (full - modal_share)
                    }
                }
                Probe::BridgeAcceleration { shape } => dot(shape, view.modal_acceleration),
                Probe::Lateral {
                    shape,
                    acceleration,
                } => dot(
                    shape,
                    if *acceleration {
                        view.modal_acceleration
                    } else {
                        view.modal_displacement
                    },
                ),
                Probe::PlateMoment { probe, line_of } => probe.moment(
                    view.modal_displacement,
                    model.bridge.static_correction,
                    view.wheel_positions,
                    view.contact_forces,
                    line_of,
                    &self.wheel_modes,
                    on_deck,
                ),
                Probe::Section { section, shear } => {
                    let loads = SectionLoads {
                        modal: view.modal_displacement,
                        positions: view.wheel_positions,
                        forces: view.contact_forces,
                        wheel_modes: &self.wheel_modes,
                        on_deck,
                    };
                    let forces = section.forces(&loads, model.bridge.static_correction);
                    if *shear { forces.shear } else { forces.moment }
                }
                Probe::ContactForce { wheel } => view.contact_forces[*wheel],
                Probe::ContactGap { wheel } => view.contact_gaps[*wheel],
                Probe::VehicleDisplacement { vehicle, dof } => {
                    let state = &view.vehicles[*vehicle];
                    state.displacement[*dof] - state.static_displacement[*dof]
                }
                Probe::VehicleAcceleration { vehicle, dof } => {
                    view.vehicles[*vehicle].acceleration[*dof]
                }
            };
            let value = match column.absolute {
                _ if model.ground.is_none() => value,
                None if column.lateral_static != 0.0 && column.ground_static == 0.0 => {
                    value + column.lateral_static * lateral_acceleration
                }
                // Both shares: a node of an imported model under records
                // in both directions, or coupled directions.
                None if column.lateral_static != 0.0 => {
                    value
                        + column.ground_static * ground_acceleration
                        + column.lateral_static * lateral_acceleration
                }
                None => value + column.ground_static * ground_acceleration,
                Some(GroundTerm::Acceleration) => {
                    value + column.ground_static * ground_acceleration + ground_acceleration
                }
                Some(GroundTerm::Displacement) if column.lateral_static != 0.0 => {
                    value
                        + column.ground_static * ground_acceleration
                        + column.lateral_static * lateral_acceleration
                        + ground_displacement
                }
                Some(GroundTerm::Displacement) => {
                    value + column.ground_static * ground_acceleration + ground_displacement
                }
                Some(GroundTerm::LateralAcceleration) => value + lateral_acceleration,
                Some(GroundTerm::LateralDisplacement) if column.ground_static != 0.0 => {
                    value
                        + column.ground_static * ground_acceleration
                        + column.lateral_static * lateral_acceleration
                        + lateral_displacement
                }
                Some(GroundTerm::LateralDisplacement) => {
                    value + column.lateral_static * lateral_acceleration + lateral_displacement
                }
            };
            extremes.all.push(view.step, view.time, value);
            if any_on_deck {
                extremes.on_bridge.push(view.step, view.time, value);
            }
            if sampled {
                column.values.push(value);
            }
        }
        if !reuse && let Some(shared) = &self.shared {
            let mut shared = shared.borrow_mut();
            shared.step = Some(view.step);
            shared.columns.clone_from(&self.statics);
        }
        // Streaming: the row just sampled goes to the file, the vectors
        // stay empty.
        if sampled && let Some(spill) = &mut self.spill {
            let history = &mut self.history;
            let time = history.time.pop();
            let values = history.columns.iter_mut().flat_map(|c| {
                let value = c.values.pop();
                let statics = c.static_values.as_mut().map(|s| s.pop());
                std::iter::once(value).chain(statics)
            });
            spill.push(
                std::iter::once(time)
                    .chain(values)
                    .map(|v| v.expect("one sample per column this step")),
            );
        }
    }
}
