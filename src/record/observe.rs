//! The recorder's step: every column's value, the running extremes, the
//! girder DAFs, envelopes and wheel separation, and the written samples.

use super::ground::GroundTerm;
use super::probe::{Probe, StaticProbe, dot, nodal_reading, static_share_beyond};
use super::{Flight, Recorder, SEPARATION_GAP};
use crate::bridge::section::SectionLoads;
use crate::solve::{Observer, StepView};

impl Observer for Recorder<'_> {
    fn reads_modal_coordinates(&self) -> bool {
        self.history.columns.iter().any(|c| c.probe.reads_modes())
            || self.daf_probes.iter().any(|p| p.nodal.is_none())
            || self.envelope.as_ref().is_some_and(|e| e.reads_modes())
    }

    fn observe(&mut self, view: &StepView<'_>) {
        let sampled = self.keep && view.step.is_multiple_of(self.history.every);
        if sampled {
            self.history.time.push(view.time);
        }
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
        // Whether at least one axle is on the deck (the summary's `on_bridge`).
        let any_on_deck = !on_deck.is_empty();
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
            let nodal = nodal_reading(probe.nodal.as_ref(), view, false);
            let mut dynamic = nodal.unwrap_or_else(|| dot(&probe.shape, view.modal_displacement));
            // The full deflection under the wheel forces (the static
            // correction's) and the static crossing's, each influence value
            // read once.
            let (full, statics) = probe.statics.deflections(
                view.wheel_positions,
                view.contact_forces,
                &model.static_wheel_loads,
                on_deck,
            );
            if nodal.is_none() && !self.wheel_modes.is_empty() {
                dynamic += static_share_beyond(
                    full,
                    &probe.static_shape,
                    &self.wheel_modes,
                    view,
                    on_deck,
                );
            }
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
        // What a beam section (or support) sees this step, shared by every
        // moment, shear and reaction column.
        let section_loads = SectionLoads {
            modal: view.modal_displacement,
            positions: view.wheel_positions,
            forces: view.contact_forces,
            wheel_modes: &self.wheel_modes,
            on_deck,
        };
        for (index, (column, extremes)) in self
            .history
            .columns
            .iter_mut()
            .zip(&mut self.history.extremes)
            .enumerate()
        {
            // The static crossing's value this step, for the columns that
            // have one (the reference of their dynamic factor).
            let mut reference = None;
            let value = match &column.probe {
                Probe::BridgeDisplacement {
                    shape,
                    statics,
                    static_shape,
                    nodal,
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
                    reference = Some(static_w);
                    let modal = dot(shape, view.modal_displacement);
                    if let Some(exact) = nodal_reading(nodal.as_ref(), view, false) {
                        // A direct run's N(x)ᵀu: nothing is left out, so no
                        // static correction.
                        exact
                    } else if self.wheel_modes.is_empty() {
                        modal
                    } else {
                        // Σ_w F_w [G(x, x_w) − Σᵢ φᵢ(x)φᵢ(x_w)/ωᵢ²], as
                        // `static_share_beyond`, term by term.
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
                Probe::BridgeAcceleration { shape, nodal } => {
                    nodal_reading(nodal.as_ref(), view, true)
                        .unwrap_or_else(|| dot(shape, view.modal_acceleration))
                }
                Probe::Lateral {
                    shape,
                    acceleration,
                    nodal,
                } => nodal_reading(nodal.as_ref(), view, *acceleration).unwrap_or_else(|| {
                    dot(
                        shape,
                        if *acceleration {
                            view.modal_acceleration
                        } else {
                            view.modal_displacement
                        },
                    )
                }),
                Probe::PlateMoment { probe, line_of } => probe.moment(
                    view.modal_displacement,
                    model.bridge.static_correction,
                    view.wheel_positions,
                    view.contact_forces,
                    line_of,
                    &self.wheel_modes,
                    on_deck,
                ),
                // The static crossing of the same wheels (each its static
                // load at its current position, full stiffness, exact
                // section forces): the reference of the dynamic factor, as
                // for displacements (issue 40.1).
                Probe::Section {
                    section,
                    shear,
                    nodal,
                } => {
                    let statics = section.static_forces(
                        view.wheel_positions,
                        &model.static_wheel_loads,
                        on_deck,
                    );
                    let static_value = if *shear {
                        statics.shear
                    } else {
                        statics.moment
                    };
                    reference = Some(static_value);
                    let forces = match (nodal, &view.nodal) {
                        (Some(nodal), Some(state)) => nodal.forces(
                            section,
                            state,
                            view.wheel_positions,
                            view.contact_forces,
                            on_deck,
                        ),
                        _ => section.forces(&section_loads, model.bridge.static_correction),
                    };
                    if *shear { forces.shear } else { forces.moment }
                }
                Probe::Reaction { probe, nodal } => {
                    let static_value = probe.static_reaction(
                        view.wheel_positions,
                        &model.static_wheel_loads,
                        on_deck,
                    );
                    reference = Some(static_value);
                    match &view.nodal {
                        Some(state) if !nodal.is_empty() => probe.nodal_reaction(
                            nodal,
                            state,
                            view.wheel_positions,
                            view.contact_forces,
                            on_deck,
                        ),
                        _ => probe.reaction(&section_loads, model.bridge.static_correction),
                    }
                }
                Probe::SupportReaction { reaction, nodal } => {
                    let static_value = reaction.static_reaction(
                        view.wheel_positions,
                        &model.wheel_y,
                        &model.static_wheel_loads,
                        on_deck,
                    );
                    reference = Some(static_value);
                    if let (Some(damping), Some(state)) = (nodal, &view.nodal) {
                        // The rows on the nodal state, and the load standing
                        // on the support.
                        reaction.nodal_reaction(state, *damping)
                            + reaction.direct_load(
                                view.wheel_positions,
                                &model.wheel_y,
                                view.contact_forces,
                                on_deck,
                            )
                    } else if model.bridge.static_correction {
                        // The mode-acceleration form: exact statics plus
                        // the modes' dynamic share (reaction module doc).
                        reaction.static_reaction(
                            view.wheel_positions,
                            &model.wheel_y,
                            view.contact_forces,
                            on_deck,
                        ) + dot(&reaction.corrected_modal, view.modal_acceleration)
                    } else {
                        // Plain modal: K_cf Φ q + M_cf Φ q̈, and the load
                        // standing on the support (no damping share).
                        let on_support: f64 = reaction.direct_load(
                            view.wheel_positions,
                            &model.wheel_y,
                            view.contact_forces,
                            on_deck,
                        );
                        dot(&reaction.stiffness_modal, view.modal_displacement)
                            + dot(&reaction.mass_modal, view.modal_acceleration)
                            + on_support
                    }
                }
                Probe::PlateReaction { probe, line_of } => {
                    let static_value = probe.static_reaction(
                        view.wheel_positions,
                        &model.static_wheel_loads,
                        line_of,
                        on_deck,
                    );
                    reference = Some(static_value);
                    // a(w, v_c) as a moment (its own static correction),
                    // the inertia and the loads' share through v_c.
                    let elastic = probe.elastic.moment(
                        view.modal_displacement,
                        model.bridge.static_correction,
                        view.wheel_positions,
                        view.contact_forces,
                        line_of,
                        &self.wheel_modes,
                        on_deck,
                    );
                    let loads: f64 = on_deck
                        .iter()
                        .map(|&w| view.contact_forces[w] * probe.hat_at(view.wheel_positions[w]))
                        .sum();
                    elastic + dot(&probe.inertia, view.modal_acceleration) + loads
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
            if let Some(r) = reference {
                keep_static(extremes, &mut column.static_values, sampled, view, r);
            }
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

/// A column's static reference this step: into its extremes, and into its
/// samples when the step is sampled.
fn keep_static(
    extremes: &mut super::extremes::ColumnExtremes,
    samples: &mut Option<Vec<f64>>,
    sampled: bool,
    view: &StepView<'_>,
    value: f64,
) {
    extremes.statics.push(view.step, view.time, value);
    if sampled && let Some(s) = samples.as_mut() {
        s.push(value);
    }
}
