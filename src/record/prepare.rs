//! [`Recorder::new`]: the probe of every record, checked against the
//! model, with its ground-motion terms and preallocated columns.

use super::extremes::ColumnExtremes;
use super::ground::GroundTerm;
use super::ground::ground_terms;
use super::probe::{
    ColumnStatics, DafProbe, Probe, StaticProbe, filtered_shape, static_shape, wheel_lines,
};
use super::{Column, Flight, GirderDaf, History, PositionRef, Recorder, WheelSeparation};
use crate::bridge::BridgeError;
use crate::model::Model;
use crate::scene::{Quantity, Record, SolverMethod};
use crate::solve::direct::assembled::{AssembledBridge, LinePoint};

impl<'m> Recorder<'m> {
    /// Prepares the probes of `records` (already validated against the model).
    pub fn new(model: &'m Model, records: &[Record]) -> Result<Self, BridgeError> {
        let modes = model.bridge.mode_count();
        // A direct run's bridge records read its nodal state (issue 43.1):
        // the assembled bridge's interpolation N at each record's point.
        let assembled = nodal_bridge(model);
        let assembled = assembled.as_ref();
        let frequencies = model.bridge.frequencies();
        let kept = super::KeptModes {
            frequencies: &frequencies,
            available: model.bridge.available_modes,
            filter: model.bridge.acceleration_filter,
        };
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
        // The assembled bridge when a direct run reads `record` nodally.
        let nodal_for = |record: &Record| {
            assembled
                .filter(|_| super::direct_reading(record, &kept) == super::DirectReading::Nodal)
        };
        let mut columns = Vec::with_capacity(records.len());
        for record in records {
            let vehicle = record.vehicle.map_or(0, |v| v - 1);
            let (probe, unit, position) = match record.quantity {
                Quantity::BridgeDisplacement | Quantity::BridgeAcceleration => {
                    let x = record.x.unwrap_or(0.0);
                    let y = record.y.unwrap_or(0.0);
                    let mut shape = vec![0.0; modes];
                    // A direct run's nodal interpolation of the point (or
                    // the DOF), when the record can read it.
                    let nodal = nodal_for(record);
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
                        let nodal = nodal.map(|bridge| {
                            bridge.point_in(crate::contact::ContactDirection::Lateral, x, y)
                        });
                        let probe = Probe::Lateral {
                            shape,
                            acceleration,
                            nodal,
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
                    let nodal = nodal.map(|bridge| match dof {
                        Some(dof) => LinePoint::of_dof(dof),
                        None => bridge.point_in(crate::contact::ContactDirection::Vertical, x, y),
                    });
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
                            nodal,
                        };
                        (probe, "m", lead)
                    } else {
                        let shape = filtered_shape(model, &shape, record.max_frequency);
                        (Probe::BridgeAcceleration { shape, nodal }, "m/s^2", lead)
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
                        .section_probe(x, record.side.unwrap_or_default())?
                        .expect("moments and shears on a plate were refused when resolving");
                    let shear = record.quantity == Quantity::BridgeShear;
                    let unit = if shear { "N" } else { "N*m" };
                    let nodal = nodal_for(record)
                        .and_then(|_| model.bridge.nodal_section(&section))
                        .map(Box::new);
                    let probe = Probe::Section {
                        section: Box::new(section),
                        shear,
                        nodal,
                    };
                    (probe, unit, lead)
                }
                Quantity::BridgeReaction if record.node.is_some() => {
                    let node = record.node.expect("matched");
                    let direction = record.direction.unwrap_or_default();
                    let reaction = model
                        .bridge
                        .support_reaction(node, direction)?
                        .expect("reaction nodes were validated when resolving");
                    let unit = if direction.is_rotation() { "N*m" } else { "N" };
                    let probe = Probe::SupportReaction {
                        reaction: Box::new(reaction),
                        nodal: nodal_for(record).and(model.bridge.rayleigh_damping),
                    };
                    (probe, unit, lead)
                }
                Quantity::BridgeReaction if model.bridge.is_plate() => {
                    let (lines, line_of) = wheel_lines(model);
                    let probe = model
                        .bridge
                        .plate_reaction_probe(record.x.unwrap_or(0.0), &lines)?
                        .expect("plate reactions are at supports, checked when resolving");
                    let probe = Probe::PlateReaction {
                        probe: Box::new(probe),
                        line_of,
                    };
                    (probe, "N", lead)
                }
                Quantity::BridgeReaction => {
                    let probe = model
                        .bridge
                        .reaction_probe(record.x.unwrap_or(0.0))?
                        .expect("reactions on a plate were refused when resolving");
                    let nodal = nodal_for(record)
                        .and_then(|_| {
                            probe
                                .sides()
                                .map(|(_, side)| model.bridge.nodal_section(side))
                                .collect::<Option<Vec<_>>>()
                        })
                        .unwrap_or_default();
                    let probe = Probe::Reaction {
                        probe: Box::new(probe),
                        nodal,
                    };
                    (probe, "N", lead)
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
            let static_values = matches!(
                probe,
                Probe::BridgeDisplacement { .. }
                    | Probe::Section { .. }
                    | Probe::Reaction { .. }
                    | Probe::SupportReaction { .. }
                    | Probe::PlateReaction { .. }
            )
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
                    nodal: assembled.map(|bridge| {
                        bridge.point_in(crate::contact::ContactDirection::Vertical, x, y)
                    }),
                });
            }
        }
        // The mode values at the wheels serve the static correction of the
        // records that read modes (a direct run's nodal ones have none).
        let corrected = model.bridge.static_correction
            && (daf_probes.iter().any(|p| p.nodal.is_none())
                || columns.iter().any(|c| {
                    !c.probe.reads_nodal()
                        && matches!(
                            c.probe,
                            Probe::BridgeDisplacement { .. }
                                | Probe::Section { .. }
                                | Probe::Reaction { .. }
                                | Probe::SupportReaction { .. }
                                | Probe::PlateReaction { .. }
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
}

/// The assembled bridge of a direct run (its records read the nodal
/// state, [`super::direct_reading`]); `None` for a modal method.
fn nodal_bridge(model: &Model) -> Option<AssembledBridge<'_>> {
    if model.method != SolverMethod::Direct {
        return None;
    }
    AssembledBridge::of(&model.bridge).ok()
}
