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
mod ground;
mod observe;
mod prepare;
mod probe;

pub use self::probe::SharedStatics;

use self::envelope::{Envelope, EnvelopeTracker};
use self::ground::GroundTerm;
use self::probe::{ColumnStatics, DafProbe, Probe};
use crate::bridge::BridgeError;
use crate::model::Model;
use crate::scene::{Envelopes, Quantity, Record};

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

/// The unit a quantity's values are recorded in (SI; a vehicle's rotation
/// DOF is in rad, rad/s², under the same column unit as its translations).
pub fn unit_of(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::BridgeDisplacement | Quantity::ContactGap | Quantity::VehicleDisplacement => "m",
        Quantity::BridgeAcceleration | Quantity::VehicleAcceleration => "m/s^2",
        Quantity::BridgeMoment => "N*m",
        Quantity::BridgeShear | Quantity::BridgeReaction | Quantity::ContactForce => "N",
    }
}

/// The modes a run keeps, as [`direct_reading`] weighs them: their
/// natural frequencies (Hz, ascending: the lowest of the model), the
/// model's own mode count, and the plan's count of the modes up to the
/// highest deck-acceleration filter when the kept modes stop below it
/// ([`crate::bridge::AccelerationFilter`]).
#[derive(Debug, Clone, Copy)]
pub struct KeptModes<'a> {
    /// Kept natural frequencies, Hz.
    pub frequencies: &'a [f64],
    /// The model's modes (its free DOFs).
    pub available: usize,
    /// The modes up to the acceleration filter, when more than are kept.
    pub filter: Option<crate::bridge::AccelerationFilter>,
}

impl KeptModes<'_> {
    /// Whether every mode of the model up to `cut` Hz is kept (the kept
    /// modes are the lowest): all of them, or the cut within the kept top
    /// (1e-8 relative, [`crate::bridge::CUT_OFF_TOLERANCE`]), or no mode
    /// counted between the kept top and the highest filter.
    fn hold_up_to(&self, cut: f64) -> bool {
        let top = self.frequencies.last().copied().unwrap_or(0.0);
        self.frequencies.len() >= self.available
            || cut <= top * (1.0 + crate::bridge::CUT_OFF_TOLERANCE)
            || self.filter.is_none()
    }

    /// Whether a filter at `cut` Hz passes every mode of the model.
    fn pass_all_at(&self, cut: f64) -> bool {
        let top = self.frequencies.last().copied().unwrap_or(0.0);
        let tolerance = 1.0 - crate::bridge::CUT_OFF_TOLERANCE;
        (self.frequencies.len() >= self.available && cut >= top * tolerance)
            || self
                .filter
                .is_some_and(|f| f.modes >= self.available && cut >= f.max_frequency * tolerance)
    }
}

/// How a direct run (`solver.method: direct`) reads a bridge record.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum DirectReading {
    /// From the nodal state on the assembled free DOFs
    /// ([`crate::solve::StepView::nodal`]): N(x)ᵀu, N(x)ᵀü, exact in space
    /// whatever the modes kept, with no static correction.
    Nodal,
    /// From the nodal state's projection onto the kept modes, q = ΦᵀMu,
    /// which holds every mode the record sums: a deck acceleration filtered
    /// at `max_frequency` (EN 1990 A2.4.4.2.1(4): the modes up to the
    /// filter, Σ φᵢ(x)φᵢᵀMü) with each of them kept. Exact in space too.
    Filtered,
    /// From that projection, but the record needs modes that are not kept:
    /// it carries their truncation as a modal run's would (the
    /// `direct-records-on-kept-modes` warning names it).
    Truncated,
}

/// How a direct run reads `record` with `modes` kept: bridge
/// displacements, a beam's moments, shears and reactions and an imported
/// model's support reactions nodally; a deck acceleration nodally when its filter passes every mode
/// of the model, else filtered on the kept modes (exact when they hold
/// every mode up to the filter). Vehicle and contact records are the direct solution's own
/// whatever this says.
pub fn direct_reading(record: &Record, modes: &KeptModes<'_>) -> DirectReading {
    match record.quantity {
        Quantity::BridgeDisplacement | Quantity::BridgeMoment | Quantity::BridgeShear => {
            DirectReading::Nodal
        }
        // A beam's support (its shear jump), an imported model's
        // constrained DOF (its rows of K and M).
        Quantity::BridgeReaction => DirectReading::Nodal,
        Quantity::BridgeAcceleration => acceleration_reading(record.max_frequency, modes),
        // The direct solution's own.
        Quantity::ContactForce
        | Quantity::ContactGap
        | Quantity::VehicleDisplacement
        | Quantity::VehicleAcceleration => DirectReading::Nodal,
    }
}

/// [`direct_reading`] of a deck acceleration filtered at `cut` Hz (`None`:
/// unfiltered).
fn acceleration_reading(cut: Option<f64>, modes: &KeptModes<'_>) -> DirectReading {
    match cut {
        None => DirectReading::Nodal,
        Some(cut) if modes.pass_all_at(cut) => DirectReading::Nodal,
        Some(cut) if modes.hold_up_to(cut) => DirectReading::Filtered,
        Some(_) => DirectReading::Truncated,
    }
}

/// How a direct run reads `quantity` of the envelopes (`max_frequency`
/// their acceleration filter): as the matching record
/// ([`direct_reading`]).
pub fn direct_envelope_reading(
    quantity: Quantity,
    max_frequency: Option<f64>,
    modes: &KeptModes<'_>,
) -> DirectReading {
    match quantity {
        Quantity::BridgeAcceleration => acceleration_reading(max_frequency, modes),
        _ => DirectReading::Nodal,
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
