//! Envelopes along the deck: at every point, the largest and smallest value
//! of each bridge quantity over the run, with when and where (the lead
//! vehicle's front axle) each occurred — VBI-2D's load-effect maxima —
//! tracked step by step without keeping histories.
//!
//! Each point's value is computed by the very formula of the matching
//! record (displacement with the static correction of the modes left out,
//! filtered acceleration, moment and shear in the mode-acceleration form of
//! [`crate::bridge::section`]), so an envelope equals the extremes of a
//! recorded history at the same point bit for bit. Cost per step
//! O(points × (modes + wheels)) per quantity: one row of the points × modes
//! mode matrix times q per point (kept row by row, not through a BLAS call,
//! so that the arithmetic is the record's), and each wheel through each
//! point's static influence lines.

use super::probe::{StaticProbe, corrected_displacement, dot, filtered_shape, static_shape};
use super::unit_of;
use crate::bridge::BridgeError;
use crate::bridge::section::{SectionLoads, SectionProbe};
use crate::model::Model;
use crate::scene::{Envelopes, Quantity};
use crate::solve::StepView;

/// The extremes of one quantity at one point.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Extremes {
    /// Largest value.
    pub max: f64,
    /// Time of the largest value, s.
    pub max_time: f64,
    /// Lead vehicle's front-axle position then, m.
    pub max_position: f64,
    /// Smallest value.
    pub min: f64,
    /// Time of the smallest value, s.
    pub min_time: f64,
    /// Lead vehicle's front-axle position then, m.
    pub min_position: f64,
}

impl Extremes {
    /// Both extremes at `value`, reached at `time` s with the lead vehicle at `position` m.
    pub fn new(value: f64, time: f64, position: f64) -> Self {
        Self {
            max: value,
            max_time: time,
            max_position: position,
            min: value,
            min_time: time,
            min_position: position,
        }
    }

    fn update(&mut self, value: f64, time: f64, position: f64) {
        if value > self.max {
            self.max = value;
            self.max_time = time;
            self.max_position = position;
        }
        if value < self.min {
            self.min = value;
            self.min_time = time;
            self.min_position = position;
        }
    }
}

/// One enveloped quantity over all points.
#[derive(Debug, Clone)]
pub struct EnvelopeColumn {
    /// The quantity.
    pub quantity: Quantity,
    /// Unit of its values.
    pub unit: &'static str,
    /// Per point (empty until the first step).
    pub extremes: Vec<Extremes>,
}

/// The envelopes of a run.
#[derive(Debug, Clone)]
pub struct Envelope {
    /// Point positions along the bridge, m.
    pub x: Vec<f64>,
    /// One column per quantity, in the scene's order.
    pub columns: Vec<EnvelopeColumn>,
}

/// What one point keeps to evaluate its quantities.
#[derive(Debug, Clone)]
struct PointProbe {
    shape: Vec<f64>,
    statics: StaticProbe,
    static_shape: Vec<f64>,
    acceleration_shape: Vec<f64>,
    section: Option<SectionProbe>,
}

/// Tracks the envelopes during the run.
#[derive(Debug, Clone)]
pub(super) struct EnvelopeTracker {
    envelope: Envelope,
    points: Vec<PointProbe>,
}

impl EnvelopeTracker {
    /// The probes of every point (resolved `envelopes` on a beam).
    pub(super) fn new(model: &Model, envelopes: &Envelopes) -> Result<Self, BridgeError> {
        let length = model.bridge.length;
        let x: Vec<f64> = match envelopes.points {
            Some(n) => (0..n).map(|i| length * i as f64 / (n - 1) as f64).collect(),
            None => model.bridge.node_x().to_vec(),
        };
        let sections = envelopes
            .quantities
            .iter()
            .any(|q| matches!(q, Quantity::BridgeMoment | Quantity::BridgeShear));
        let modes = model.bridge.mode_count();
        let mut points = Vec::with_capacity(x.len());
        for &at in &x {
            let mut shape = vec![0.0; modes];
            model.bridge.mode_values(at, 0.0, &mut shape);
            let section = if sections {
                model.bridge.section_probe(at, crate::scene::Side::Right)?
            } else {
                None
            };
            points.push(PointProbe {
                acceleration_shape: filtered_shape(model, &shape, envelopes.max_frequency),
                static_shape: static_shape(model, &shape),
                statics: StaticProbe::new(model, at, 0.0)?,
                shape,
                section,
            });
        }
        let columns = envelopes
            .quantities
            .iter()
            .map(|&quantity| EnvelopeColumn {
                quantity,
                unit: unit_of(quantity),
                extremes: Vec::with_capacity(x.len()),
            })
            .collect();
        Ok(Self {
            envelope: Envelope { x, columns },
            points,
        })
    }

    /// Whether the tracker needs the mode values at the wheels.
    pub(super) fn needs_wheel_modes(&self) -> bool {
        !self.points.is_empty()
    }

    pub(super) fn observe(
        &mut self,
        model: &Model,
        view: &StepView<'_>,
        wheel_modes: &[f64],
        on_deck: &[usize],
    ) {
        // Where the lead vehicle is: its first wheel plus that wheel's
        // distance behind the front axle.
        let position = match (view.wheel_positions.first(), model.wheels.first()) {
            (Some(&at), Some(r)) => at + model.vehicles[r.vehicle].wheels[r.wheel].offset,
            _ => f64::NAN,
        };
        let loads = SectionLoads {
            modal: view.modal_displacement,
            positions: view.wheel_positions,
            forces: view.contact_forces,
            wheel_modes,
            on_deck,
        };
        let corrected = model.bridge.static_correction;
        for (p, point) in self.points.iter().enumerate() {
            let section = point.section.as_ref().map(|s| s.forces(&loads, corrected));
            for column in &mut self.envelope.columns {
                let value = match column.quantity {
                    Quantity::BridgeDisplacement => corrected_displacement(
                        &point.shape,
                        &point.statics,
                        &point.static_shape,
                        wheel_modes,
                        view,
                        on_deck,
                    ),
                    Quantity::BridgeAcceleration => {
                        dot(&point.acceleration_shape, view.modal_acceleration)
                    }
                    Quantity::BridgeMoment => section.map_or(0.0, |s| s.moment),
                    Quantity::BridgeShear => section.map_or(0.0, |s| s.shear),
                    _ => 0.0,
                };
                match column.extremes.get_mut(p) {
                    Some(e) => e.update(value, view.time, position),
                    None => column
                        .extremes
                        .push(Extremes::new(value, view.time, position)),
                }
            }
        }
    }

    pub(super) fn finish(self) -> Envelope {
        self.envelope
    }
}
