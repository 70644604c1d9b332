//! The record stage: samples the requested quantities at every step into
//! preallocated columns, and alongside each bridge displacement the static
//! response of the same load set crossing (the DAF reference).

use crate::bridge::BridgeError;
use crate::bridge::InfluenceLine;
use crate::model::Model;
use crate::scenario::resolved::{Quantity, Record};
use crate::solve::{Observer, StepView};

/// What the summary reports as "position" of an extreme value: the position
/// of a wheel (its vehicle's front axle minus its offset) at that time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionRef {
    /// Vehicle index from 0.
    pub vehicle: usize,
    /// Distance behind the front axle, m.
    pub offset: f64,
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
    /// Flattened wheel index.
    ContactForce { wheel: usize },
    /// Flattened wheel index.
    ContactGap { wheel: usize },
    /// Vehicle and DOF; displacement from static equilibrium.
    VehicleDisplacement { vehicle: usize, dof: usize },
    /// Vehicle and DOF.
    VehicleAcceleration { vehicle: usize, dof: usize },
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
        let mut lines: Vec<f64> = Vec::new();
        let mut wheel_influence = Vec::with_capacity(model.wheel_y.len());
        for &wheel_y in &model.wheel_y {
            let index = match lines.iter().position(|&l| l == wheel_y) {
                Some(index) => index,
                None => {
                    lines.push(wheel_y);
                    lines.len() - 1
                }
            };
            wheel_influence.push(index);
        }
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
    fn deflection(&self, positions: &[f64], loads: &[f64]) -> f64 {
        positions
            .iter()
            .zip(loads)
            .zip(&self.wheel_influence)
            .map(|((&x, &load), &line)| -load * self.influences[line].value_at(x))
            .sum()
    }
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
) -> f64 {
    let modes = static_shape.len();
    let full = statics.deflection(view.wheel_positions, view.contact_forces);
    let modal: f64 = wheel_modes
        .chunks(modes)
        .zip(view.contact_forces)
        .map(|(values, force)| -force * dot(static_shape, values))
        .sum();
    full - modal
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
    /// Sampled values, one per step (including t = 0).
    pub values: Vec<f64>,
    /// For bridge displacements: the static crossing response at the same
    /// point, m (positive upward).
    pub static_values: Option<Vec<f64>>,
    /// Whose position the summary reports with each extreme.
    pub position: PositionRef,
    probe: Probe,
}

/// All recorded columns with their common time axis.
#[derive(Debug, Clone, Default)]
pub struct History {
    /// Time of each sample, s.
    pub time: Vec<f64>,
    /// The columns in scenario order.
    pub columns: Vec<Column>,
    /// Separation statistics of every wheel with a DOF, under unilateral
    /// contact (empty under permanent contact).
    pub separation: Vec<WheelSeparation>,
    /// The DAF at the middle of every span on every girder line, span by
    /// span (a beam has one line, at y = 0).
    pub girder_dafs: Vec<GirderDaf>,
}

/// Gap above which a wheel with zero contact force counts as separated, m.
/// Rigid LCP contact leaves round-off gaps of ~1e-15 m at touching wheels.
pub const SEPARATION_GAP: f64 = 1e-9;

/// Loss of contact of one wheel over a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct WheelSeparation {
    /// Vehicle number from 1.
    pub vehicle: usize,
    /// Wheel number from 1.
    pub wheel: usize,
    /// Whether the wheel ever lost contact.
    pub separated: bool,
    /// Number of contact-loss episodes.
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
    #[serde(skip)]
    flat: usize,
    #[serde(skip)]
    apart: bool,
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
                        // The deck-acceleration filter: modes above the
                        // record's cut-off do not contribute (a sharp modal
                        // low-pass, EN 1990 A2.4.4.2.1(4)).
                        if let Some(cut) = record.max_frequency {
                            let limit = 2.0 * std::f64::consts::PI * cut * (1.0 + 1e-12);
                            for (value, omega) in
                                shape.iter_mut().zip(&model.bridge.circular_frequencies)
                            {
                                if *omega > limit {
                                    *value = 0.0;
                                }
                            }
                        }
                        (Probe::BridgeAcceleration { shape }, "m/s^2", lead)
                    }
                }
                Quantity::ContactForce | Quantity::ContactGap => {
                    let wheel = record.wheel.map_or(0, |w| w - 1);
                    let flat = model
                        .wheel_index(vehicle, wheel)
                        .expect("wheel numbers were validated when resolving");
                    let offset = model.vehicles[vehicle].wheels[wheel].offset;
                    let position = PositionRef { vehicle, offset };
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
            columns.push(Column {
                name: record.name.clone(),
                quantity: record.quantity,
                unit,
                values: Vec::with_capacity(capacity),
                static_values,
                position,
                probe,
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
                    flat,
                    apart: false,
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
                || columns
                    .iter()
                    .any(|c| matches!(c.probe, Probe::BridgeDisplacement { .. })));
        let wheel_modes = if corrected {
            vec![0.0; model.wheels.len() * modes]
        } else {
            Vec::new()
        };
        Ok(Self {
            model,
            history: History {
                time: Vec::with_capacity(capacity),
                columns,
                separation,
                girder_dafs: Vec::new(),
            },
            daf_probes,
            wheel_modes,
        })
    }

    /// The recorded history.
    pub fn finish(mut self) -> History {
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

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl Observer for Recorder<'_> {
    fn observe(&mut self, view: &StepView<'_>) {
        self.history.time.push(view.time);
        let dt = self.model.time_step;
        for wheel in &mut self.history.separation {
            let gap = view.contact_gaps[wheel.flat];
            let apart = view.contact_forces[wheel.flat] <= 0.0 && gap > SEPARATION_GAP;
            if apart {
                if !wheel.apart {
                    wheel.episodes += 1;
                    if wheel.first_loss_time.is_none() {
                        wheel.first_loss_time = Some(view.time);
                        wheel.first_loss_position = Some(view.wheel_positions[wheel.flat]);
                    }
                }
                wheel.separated = true;
                if view.step > 0 {
                    wheel.time_separated += dt;
                }
                if gap > wheel.max_gap {
                    wheel.max_gap = gap;
                    wheel.max_gap_time = Some(view.time);
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
        if !self.wheel_modes.is_empty() {
            for (w, values) in self.wheel_modes.chunks_mut(modes).enumerate() {
                model
                    .bridge
                    .mode_values(view.wheel_positions[w], model.wheel_y[w], values);
            }
        }
        for probe in &mut self.daf_probes {
            let mut dynamic = dot(&probe.shape, view.modal_displacement);
            if !self.wheel_modes.is_empty() {
                dynamic += truncated_static_share(
                    &probe.statics,
                    &probe.static_shape,
                    &self.wheel_modes,
                    view,
                );
            }
            let statics = probe
                .statics
                .deflection(view.wheel_positions, &model.static_wheel_loads);
            let r = &mut probe.result;
            r.dynamic_max_abs = r.dynamic_max_abs.max(dynamic.abs());
            r.static_max_abs = r.static_max_abs.max(statics.abs());
        }
        for column in &mut self.history.columns {
            let value = match &column.probe {
                Probe::BridgeDisplacement {
                    shape,
                    statics,
                    static_shape,
                } => {
                    // Static crossing: each wheel's static load at its
                    // current position through the influence line of its
                    // lane (full stiffness, no modal truncation).
                    let static_w =
                        statics.deflection(view.wheel_positions, &model.static_wheel_loads);
                    if let Some(s) = column.static_values.as_mut() {
                        s.push(static_w);
                    }
                    let modal = dot(shape, view.modal_displacement);
                    if self.wheel_modes.is_empty() {
                        modal
                    } else {
                        modal
                            + truncated_static_share(statics, static_shape, &self.wheel_modes, view)
                    }
                }
                Probe::BridgeAcceleration { shape } => dot(shape, view.modal_acceleration),
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
            column.values.push(value);
        }
    }
}
