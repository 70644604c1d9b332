//! Ground motion in a record: the static share of the modes left out per
//! unit ground acceleration, and what an absolute record adds.

use super::probe::Probe;
use crate::bridge::BridgeError;
use crate::model::Model;
use crate::scene::Record;

/// Which motion of the ground an absolute record adds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum GroundTerm {
    Displacement,
    Acceleration,
    LateralDisplacement,
    LateralAcceleration,
}
/// The ground-motion terms of a record's column: the static share of the
/// modes left out per unit vertical and per unit lateral ground
/// acceleration, and what an absolute record adds. All vanish without
/// ground motion; rotations and contact quantities are the same in both
/// frames.
pub(super) fn ground_terms(
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
    if let Probe::SupportReaction { reaction, .. } = probe
        && !ground.lateral.is_empty()
    {
        lateral = if model.bridge.static_correction {
            reaction.lateral_ground
        } else {
            reaction.plain_ground[1]
        };
    }
    if let Probe::SupportReaction { .. } = probe
        && ground.vertical.is_empty()
    {
        vertical = 0.0;
    }
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
    if probe.reads_nodal() {
        (vertical, lateral) = nodal_ground_terms(ground, probe);
    }
    Ok((vertical, lateral, absolute))
}

/// A direct run's nodal reading under ground motion: no static share of
/// modes left out (none is), only the inertia of the ground's own motion
/// where the record is a force: a section's clamped share of m üg
/// ([`crate::bridge::section::NodalSection::ground`]), a support's jump of
/// it, an imported support row's (M δ)_c. Per unit vertical and lateral
/// ground acceleration.
fn nodal_ground_terms(ground: &crate::ground::GroundExcitation, probe: &Probe) -> (f64, f64) {
    match probe {
        Probe::Section {
            nodal: Some(nodal),
            shear,
            ..
        } => {
            let share = if *shear {
                nodal.ground.shear
            } else {
                nodal.ground.moment
            };
            (share, 0.0)
        }
        Probe::Reaction { probe, nodal } => {
            let jump = probe
                .sides()
                .zip(nodal)
                .map(|((sign, _), n)| sign * n.ground.shear)
                .sum();
            (jump, 0.0)
        }
        Probe::SupportReaction { reaction, .. } => {
            let [vertical, lateral] = reaction.plain_ground;
            let vertical = if ground.vertical.is_empty() {
                0.0
            } else {
                vertical
            };
            let lateral = if ground.lateral.is_empty() {
                0.0
            } else {
                lateral
            };
            (vertical, lateral)
        }
        _ => (0.0, 0.0),
    }
}

/// [`ground_terms`]' vertical static share and absolute term.
pub(super) fn vertical_ground_terms(
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
        Probe::PlateMoment { .. } | Probe::PlateReaction { .. } => (0.0, None),
        Probe::Section {
            ref section, shear, ..
        } => {
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
        Probe::Reaction { ref probe, .. } => {
            // The shear jump of the ground's inertia share, as for shears.
            let share = if model.bridge.static_correction {
                probe
                    .sides()
                    .map(|(sign, section)| {
                        sign * model
                            .bridge
                            .ground_section_share(
                                section,
                                ground.total_mass / model.bridge.length,
                                &ground.participation,
                            )
                            .shear
                    })
                    .sum()
            } else {
                0.0
            };
            (share, None)
        }
        // The ground's inertia load's static share through the support,
        // and the support rows' own inertia as they move with the ground
        // (reaction module doc): frame-independent forces.
        Probe::SupportReaction { ref reaction, .. } => {
            let share = if model.bridge.static_correction {
                reaction.vertical_ground
            } else {
                reaction.plain_ground[0]
            };
            (share, None)
        }
        Probe::ContactForce { .. } | Probe::ContactGap { .. } => (0.0, None),
    })
}
