//! Resolving `record`: each recorded quantity checked against the bridge and
//! the vehicles, and the default set when the scene gives none.

use super::checker::Checker;
use super::raw;
use crate::scene::*;

use crate::scene::dof_names::{rail_car, train_3d};
use crate::scene::imported::Direction;

/// DOF names a record may give for a resolved vehicle, as the vehicle module
/// defines them (for a train: one car's names, picked with `car`).
fn dof_names(vehicle: &Vehicle) -> &'static [&'static str] {
    match vehicle {
        Vehicle::MovingForce(_) => &[],
        Vehicle::Oscillator(_) => &crate::scene::dof_names::oscillator::DOF_NAMES,
        Vehicle::H20Truck(_) => &crate::scene::dof_names::h20_44::DOF_NAMES,
        Vehicle::RailCar(_) | Vehicle::Train(_) => &rail_car::DOF_NAMES,
        Vehicle::Train3d(_) => &train_3d::DOF_NAMES,
    }
}

/// `car{k}_{rest}` split into k and rest (`None`: no such prefix).
fn split_car_prefix(name: &str) -> Option<(usize, &str)> {
    let tail = name.strip_prefix("car")?;
    let digits = tail.find(|c: char| !c.is_ascii_digit())?;
    let rest = tail[digits..].strip_prefix('_')?;
    Some((tail[..digits].parse().ok()?, rest))
}

/// Wheels of one car of a train (`None`: not a train).
fn wheels_per_car(vehicle: &Vehicle) -> Option<usize> {
    match vehicle {
        Vehicle::Train(_) => Some(rail_car::WHEELSETS),
        Vehicle::Train3d(_) => Some(train_3d::WHEELSETS * train_3d::CONTACTS_PER_WHEELSET),
        _ => None,
    }
}

/// Cars of a train (`None`: not a train).
fn car_count(vehicle: &Vehicle) -> Option<usize> {
    match vehicle {
        Vehicle::Train(t) => Some(t.cars.len()),
        Vehicle::Train3d(t) => Some(t.cars.len()),
        _ => None,
    }
}

/// Name of train wheel `w` (from 0, over the whole train) in the default
/// records: car and wheelset, and for a 3D car the contact.
fn train_wheel_name(vehicle: &Vehicle, w: usize) -> Option<String> {
    let per_car = wheels_per_car(vehicle)?;
    let (car, within) = (w / per_car + 1, w % per_car);
    Some(match vehicle {
        Vehicle::Train3d(_) => {
            let contact = ["left", "right", "lateral"][within % train_3d::CONTACTS_PER_WHEELSET];
            format!(
                "car{car}_wheelset{}_{contact}",
                within / train_3d::CONTACTS_PER_WHEELSET + 1
            )
        }
        _ => format!("car{car}_wheel{}", within + 1),
    })
}

/// Wheels of a resolved vehicle (of a train: over all its cars).
fn wheel_count(vehicle: &Vehicle) -> usize {
    match vehicle {
        Vehicle::MovingForce(v) => v.loads.len(),
        Vehicle::Oscillator(_) => 1,
        Vehicle::H20Truck(_) => 4,
        Vehicle::RailCar(_) => rail_car::WHEELSETS,
        Vehicle::Train(t) => rail_car::WHEELSETS * t.cars.len(),
        Vehicle::Train3d(t) => train_3d::WHEELSETS * train_3d::CONTACTS_PER_WHEELSET * t.cars.len(),
    }
}

/// The highest mode frequency any bridge acceleration record sums, Hz
/// (`None` without such records): its own `max_frequency`, else
/// `default_filter` (the planning stage's, from the bridge's own modes:
/// [`crate::plan`]); what the automatic mode choice must keep.
pub(crate) fn highest_acceleration_cutoff(
    raws: Option<&[raw::RecordRaw]>,
    default_filter: f64,
) -> Option<f64> {
    raws?
        .iter()
        .filter(|r| r.quantity == Quantity::BridgeAcceleration)
        .map(|r| {
            r.max_frequency
                .filter(|f| f.is_finite() && *f > 0.0)
                .unwrap_or(default_filter)
        })
        .reduce(f64::max)
}

/// The quantity's name as the format writes it.
pub fn quantity_name_of(q: Quantity) -> String {
    serde_json::to_value(q)
        .ok()
        .and_then(|v| v.as_str().map(String::from))
        .unwrap_or_default()
}

/// The checks of a record whose `quantity` has a type error (a
/// placeholder stands for it): those that do not depend on the quantity, a
/// position on the bridge or deck and a vehicle number that exist.
fn unknown_quantity(
    r: &raw::RecordRaw,
    at: &str,
    length: Option<f64>,
    width: Option<f64>,
    vehicles: usize,
    ck: &mut Checker<'_>,
) {
    if let (Some(x), Some(length)) = (r.x, length)
        && !(0.0..=length).contains(&x)
    {
        ck.error(
            &format!("{at}.x"),
            format!("x = {x} m is off the bridge, which runs from 0 to {length} m"),
        );
    }
    if let (Some(y), Some(width)) = (r.y, width)
        && !(0.0..=width).contains(&y)
    {
        ck.error(
            &format!("{at}.y"),
            format!("y = {y} m is off the deck, which spans 0 to {width} m"),
        );
    }
    if let Some(v) = r.vehicle
        && (v == 0 || v > vehicles)
    {
        let numbered = match vehicles {
            1 => "the scene has only vehicle 1".to_owned(),
            n => format!("vehicles are numbered 1 to {n}"),
        };
        ck.error(
            &format!("{at}.vehicle"),
            format!("vehicle {v} does not exist; {numbered}"),
        );
    }
}

/// `default_filter` is a bridge acceleration's cut-off, Hz, where the record
/// gives none (the planning stage's EN 1990 filter; `None` where the
/// bridge's modes are not known, in the format's checks alone). Without a
/// `bridge` (the file's did not parse) the checks that need it are left
/// out and the rest made, so that a file's errors come in one round.
pub(crate) fn resolve_records(
    raws: Option<&[raw::RecordRaw]>,
    default_filter: Option<f64>,
    bridge: Option<&Bridge>,
    vehicles: &[Vehicle],
    contact: &Contact,
    ck: &mut Checker<'_>,
) -> Vec<Record> {
    let Some(raws) = raws else {
        return bridge.map_or_else(Vec::new, |b| default_records(b, vehicles, contact));
    };
    let length = bridge.map(Bridge::length);
    let width = bridge.and_then(Bridge::width);
    let mut out = Vec::with_capacity(raws.len());
    // Names seen so far: a set keeps duplicate detection linear.
    let mut seen = std::collections::HashSet::new();
    for (i, r) in raws.iter().enumerate() {
        let at = format!("record[{i}]");
        super::names::check_record_name(ck, &format!("{at}.name"), &r.name);
        if r.name.trim().is_empty() || r.name == "time" || r.name.ends_with("_static") {
            ck.error(
                &format!("{at}.name"),
                format!(
                    "`{}` cannot be a column name (empty, `time`, or ending in `_static`)",
                    r.name
                ),
            );
        }
        if !seen.insert(r.name.as_str()) {
            ck.error(
                &format!("{at}.name"),
                format!("duplicate record name `{}`", r.name),
            );
        }
        if ck.is_placeholder(&format!("{at}.quantity")) {
            unknown_quantity(r, &at, length, width, vehicles.len(), ck);
            continue;
        }
        let q = r.quantity;
        let is_bridge = matches!(
            q,
            Quantity::BridgeDisplacement
                | Quantity::BridgeAcceleration
                | Quantity::BridgeMoment
                | Quantity::BridgeShear
                | Quantity::BridgeReaction
        );
        let support_node = if q == Quantity::BridgeReaction {
            reaction_checks(r, &at, bridge, ck)
        } else {
            None
        };
        let side = match r.side {
            Some(_) if !matches!(q, Quantity::BridgeShear | Quantity::BridgeMoment) => {
                ck.error(
                    &format!("{at}.side"),
                    "`side` chooses the side of `x` a beam's `bridge_shear` or `bridge_moment` \
                     is taken on; a support's reaction is `bridge_reaction`",
                );
                None
            }
            Some(_) if matches!(bridge, Some(Bridge::Plate(_)) | Some(Bridge::FeImport(_))) => {
                ck.error(
                    &format!("{at}.side"),
                    "`side` is used by the shears and moments of a `type: beam` bridge",
                );
                None
            }
            Some(crate::scene::Side::Left) => Some(crate::scene::Side::Left),
            _ => None,
        };
        if q == Quantity::BridgeShear && matches!(bridge, Some(Bridge::Plate(_))) {
            ck.error(
                &format!("{at}.quantity"),
                "`bridge_shear` is computed for beam bridges only: a plate's shear per unit \
                 width needs third derivatives of its Ritz basis, whose longitudinal \
                 functions are cubic per element (their third derivative jumps at every \
                 node); record `bridge_moment` (with `component: mx|my|mxy`), \
                 `bridge_displacement` or `bridge_acceleration` on a plate deck",
            );
        }
        let on_plate = matches!(bridge, Some(Bridge::Plate(_)));
        let component = match r.component {
            Some(_) if !(q == Quantity::BridgeMoment && (on_plate || bridge.is_none())) => {
                ck.error(
                    &format!("{at}.component"),
                    "`component` chooses a plate deck's moment per unit width: it is used by \
                     `bridge_moment` on a plate only",
                );
                None
            }
            Some(c) => Some(c),
            None if q == Quantity::BridgeMoment && on_plate => {
                Some(crate::scene::PlateMoment::Longitudinal)
            }
            None => None,
        };
        let is_vehicle_dof = matches!(
            q,
            Quantity::VehicleDisplacement | Quantity::VehicleAcceleration
        );
        let quantity_name = quantity_name_of(q);
        let unused = |field: &str| format!("`{field}` is not used by `{quantity_name}`");
        let direction = r
            .node
            .map(|_| r.direction.unwrap_or(Direction::Uz))
            .or(r.direction);
        if let Some(node) = r.node {
            let direction = direction.unwrap_or(Direction::Uz);
            if !is_bridge {
                ck.error(&format!("{at}.node"), unused("node"));
            } else if r.x.is_some() {
                ck.error(&format!("{at}.x"), "give `x` or `node`, not both");
            } else {
                match bridge {
                    None => {}
                    // A reaction's node is a support: `reaction_checks`.
                    Some(Bridge::FeImport(_)) if q == Quantity::BridgeReaction => {}
                    Some(Bridge::FeImport(f)) => {
                        if f.model.dof(node, direction).is_none() {
                            ck.error(
                                &format!("{at}.node"),
                                format!(
                                    "node {node} has no free {} DOF in the imported model",
                                    direction.name()
                                ),
                            );
                        }
                    }
                    _ => ck.error(
                        &format!("{at}.node"),
                        "`node` names a node of an imported (`fe_import`) bridge",
                    ),
                }
            }
        } else if let Some(d) = r.direction {
            // Along the track: `uy` is the rails' lateral displacement, on
            // a bridge that moves sideways.
            let sideways = match bridge {
                None => true,
                Some(Bridge::Beam(b)) => b.sway.is_some(),
                Some(Bridge::FeImport(f)) => f.model.dofs.iter().any(|(_, d)| *d == Direction::Uy),
                Some(Bridge::Plate(_)) => false,
            };
            let along_track = matches!(
                q,
                Quantity::BridgeDisplacement | Quantity::BridgeAcceleration
            );
            let support_direction =
                q == Quantity::BridgeReaction && matches!(bridge, Some(Bridge::FeImport(_)) | None);
            let along = along_track && sideways && matches!(d, Direction::Uz | Direction::Uy);
            if !(support_direction || along) {
                ck.error(
                    &format!("{at}.direction"),
                    "`direction` goes with `node`, or, as `uz` or `uy` (the rails' lateral \
                     displacement), with a bridge displacement or acceleration at `x` on a bridge \
                     that moves sideways (a 3D beam, or an imported model with uy DOFs)",
                );
            }
        }
        if is_bridge && r.node.is_some() {
            if r.vehicle.is_some() {
                ck.error(&format!("{at}.vehicle"), unused("vehicle"));
            }
        } else if is_bridge {
            match r.x {
                None => ck.error(
                    &at,
                    format!("`{quantity_name}` needs `x`, the position along the bridge in m"),
                ),
                Some(x) => {
                    if let Some(length) = length
                        && !(0.0..=length).contains(&x)
                    {
                        ck.error(
                            &format!("{at}.x"),
                            format!("x = {x} m is off the bridge, which runs from 0 to {length} m"),
                        );
                    }
                }
            }
            if r.vehicle.is_some() {
                ck.error(&format!("{at}.vehicle"), unused("vehicle"));
            }
            match (r.y, width) {
                (Some(_), None) if bridge.is_none() => {}
                (Some(_), None) => ck.error(
                    &format!("{at}.y"),
                    "`y` is a position across a plate deck; a beam has no width",
                ),
                (Some(y), Some(width)) if !(0.0..=width).contains(&y) => ck.error(
                    &format!("{at}.y"),
                    format!("y = {y} m is off the deck, which spans 0 to {width} m"),
                ),
                _ => {}
            }
        } else {
            if r.x.is_some() {
                ck.error(&format!("{at}.x"), unused("x"));
            }
            if r.y.is_some() {
                ck.error(&format!("{at}.y"), unused("y"));
            }
        }
        let is_wheel = matches!(q, Quantity::ContactForce | Quantity::ContactGap);
        if !is_wheel && r.wheel.is_some() {
            ck.error(&format!("{at}.wheel"), unused("wheel"));
        }
        if !is_vehicle_dof && r.dof.is_some() {
            ck.error(&format!("{at}.dof"), unused("dof"));
        }
        // Contact forces and gaps are the same in both frames.
        if is_wheel && r.frame.is_some() {
            ck.error(&format!("{at}.frame"), unused("frame"));
        }
        let frame = r.frame.unwrap_or_default();
        let max_frequency = if q == Quantity::BridgeAcceleration {
            match r.max_frequency {
                Some(f) if !(f.is_finite() && f > 0.0) => {
                    ck.error(
                        &format!("{at}.max_frequency"),
                        format!(
                            "the acceleration cut-off must be a positive frequency in Hz, got {f}"
                        ),
                    );
                    None
                }
                Some(f) => Some(f),
                None => default_filter,
            }
        } else {
            if r.max_frequency.is_some() {
                ck.error(&format!("{at}.max_frequency"), unused("max_frequency"));
            }
            None
        };
        let mut vehicle = None;
        if !is_bridge {
            let v = r.vehicle.unwrap_or(1);
            if v == 0 || v > vehicles.len() {
                let numbered = match vehicles.len() {
                    1 => "the scene has only vehicle 1".to_owned(),
                    n => format!("vehicles are numbered 1 to {n}"),
                };
                ck.error(
                    &format!("{at}.vehicle"),
                    format!("vehicle {v} does not exist; {numbered}"),
                );
            } else {
                vehicle = Some(v);
            }
        }
        // A vehicle that lost an axle or car to a type error: its wheels
        // and cars are not counted against.
        let counted = vehicle.is_none_or(|v| !ck.uncertain(&format!("vehicles[{}]", v - 1)));
        // A train's car: wheels and DOFs are then the car's own.
        let mut car = None;
        if let Some(k) = r.car {
            match vehicle.map(|v| &vehicles[v - 1]) {
                _ if !is_wheel && !is_vehicle_dof => {
                    ck.error(&format!("{at}.car"), unused("car"));
                }
                Some(t) if car_count(t).is_some_and(|n| k >= 1 && k <= n) => car = Some(k),
                Some(t) if car_count(t).is_some() && !counted => ck.consequence(
                    &format!("vehicles[{}]", vehicle.unwrap_or(1) - 1),
                    format!("car {k} does not exist"),
                ),
                Some(t) if car_count(t).is_some() => ck.error(
                    &format!("{at}.car"),
                    format!(
                        "car {k} does not exist; the train (vehicle {}) has cars 1 to {}",
                        vehicle.unwrap_or(1),
                        car_count(t).unwrap_or(0)
                    ),
                ),
                Some(other) => ck.error(
                    &format!("{at}.car"),
                    format!(
                        "`car` picks a car of a train; vehicle {} is a {}",
                        vehicle.unwrap_or(1),
                        other.type_name()
                    ),
                ),
                None => {}
            }
        }
        // A train's DOF named whole, `car{k}_{dof}` (the form `run` writes
        // in the resolved scene): the car from the name.
        let mut dof = r.dof.clone();
        if let (None, Some(name), Some(t)) = (car, &r.dof, vehicle.map(|v| &vehicles[v - 1]))
            && let Some(n) = car_count(t)
            && let Some((k, plain)) = split_car_prefix(name)
            && dof_names(t).contains(&plain)
        {
            if r.car.is_some() {
                ck.error(
                    &format!("{at}.dof"),
                    format!("`{name}` names its car already: leave out `car`, or write `{plain}`"),
                );
            } else if k >= 1 && k <= n {
                car = Some(k);
                dof = Some(plain.to_owned());
            } else {
                ck.error(
                    &format!("{at}.dof"),
                    format!(
                        "car {k} does not exist; the train (vehicle {}) has cars 1 to {n}",
                        vehicle.unwrap_or(1)
                    ),
                );
                dof = Some(plain.to_owned());
            }
        }
        // A 3D train of one car: that car, unless another is named.
        if car.is_none()
            && (is_wheel || is_vehicle_dof)
            && let Some(Vehicle::Train3d(t)) = vehicle.map(|v| &vehicles[v - 1])
            && t.cars.len() == 1
        {
            car = Some(1);
        }
        let mut wheel = None;
        if is_wheel {
            let w = r.wheel.unwrap_or(1);
            if let Some(v) = vehicle {
                let n = if car.is_some() {
                    wheels_per_car(&vehicles[v - 1]).unwrap_or(1)
                } else {
                    wheel_count(&vehicles[v - 1])
                };
                if w == 0 || w > n {
                    let kind = vehicles[v - 1].type_name();
                    let wheels = match n {
                        1 => "only wheel 1".to_owned(),
                        n => format!("wheels 1 to {n}"),
                    };
                    let car_of = car.map_or(String::new(), |k| format!(" car {k}"));
                    let message = format!(
                        "wheel {w} does not exist; vehicle {v} ({kind}){car_of} has {wheels}"
                    );
                    if counted {
                        ck.error(&format!("{at}.wheel"), message);
                    } else {
                        // The vehicle lost a wheel to a type error.
                        ck.consequence(&format!("vehicles[{}]", v - 1), message);
                    }
                }
            }
            // Stored counted over the whole train.
            wheel = Some(car.map_or(w, |k| {
                vehicle
                    .and_then(|v| wheels_per_car(&vehicles[v - 1]))
                    .unwrap_or(1)
                    * (k - 1)
                    + w
            }));
        }
        if let (true, Some(v)) = (is_vehicle_dof, vehicle) {
            let names = dof_names(&vehicles[v - 1]);
            match &dof {
                None if names.is_empty() => ck.error(
                    &at,
                    format!(
                        "vehicle {v} ({}) has no degrees of freedom",
                        vehicles[v - 1].type_name()
                    ),
                ),
                None => ck.error(
                    &at,
                    format!("`{quantity_name}` needs `dof`, one of {}", names.join(", ")),
                ),
                Some(d) if !names.contains(&d.as_str()) => ck.error_with_help(
                    &format!("{at}.dof"),
                    if names.is_empty() {
                        format!(
                            "vehicle {v} ({}) has no degrees of freedom",
                            vehicles[v - 1].type_name()
                        )
                    } else {
                        format!(
                            "unknown DOF `{d}` of vehicle {v}; expected one of {}",
                            names.join(", ")
                        )
                    },
                    super::diagnostic::did_you_mean(d, names.iter().copied()),
                ),
                _ => {}
            }
            if car_count(&vehicles[v - 1]).is_some() && car.is_none() && dof.is_some() {
                ck.error(
                    &at,
                    format!("vehicle {v} is a train: pick the car with `car:` (from 1)"),
                );
            }
        }
        out.push(Record {
            name: r.name.clone(),
            quantity: q,
            // A reaction is taken at the support itself (the file's x may
            // be within a millimetre of it).
            x: match (q, bridge) {
                (Quantity::BridgeReaction, Some(Bridge::Beam(Beam { spans, .. })))
                | (Quantity::BridgeReaction, Some(Bridge::Plate(Plate { spans, .. }))) => {
                    r.x.map(|x| {
                        support_positions(spans).into_iter().fold(x, |best, s| {
                            if (s - x).abs() < (best - x).abs() {
                                s
                            } else {
                                best
                            }
                        })
                    })
                }
                _ => r.x,
            },
            node: support_node.or(r.node),
            direction,
            y: if is_bridge && r.node.is_none() {
                r.y.or(width.map(|w| w / 2.0))
            } else {
                None
            },
            vehicle,
            wheel,
            dof: match car {
                Some(k) => dof.as_deref().map(|d| rail_car::train_dof_name(k, d)),
                None => dof,
            },
            max_frequency,
            frame,
            component,
            side,
        });
    }
    out
}

/// Positions of a beam's supports, m: the entrance, every pier, the exit.
pub fn support_positions(spans: &[f64]) -> Vec<f64> {
    let mut at = vec![0.0];
    for span in spans {
        at.push(at.last().copied().unwrap_or(0.0) + span);
    }
    at
}

/// A `bridge_reaction` needs a beam bridge and `x` at one of its supports
/// (within a millimetre; the reaction is taken at the support itself).
fn reaction_checks(
    r: &raw::RecordRaw,
    at: &str,
    bridge: Option<&Bridge>,
    ck: &mut Checker<'_>,
) -> Option<u64> {
    match bridge {
        None => None,
        Some(Bridge::Beam(beam)) => {
            let supports = support_positions(&beam.spans);
            if let Some(x) = r.x
                && !supports.iter().any(|s| (s - x).abs() <= 1e-3)
            {
                let listed: Vec<String> = supports.iter().map(|s| format!("{s}")).collect();
                ck.error_with_help(
                    &format!("{at}.x"),
                    format!("x = {x} m is not a support of the bridge"),
                    Some(format!(
                        "a `bridge_reaction` is taken at a support: x is one of {} (m)",
                        listed.join(", ")
                    )),
                );
            }
            None
        }
        Some(Bridge::FeImport(f)) => imported_support(r, at, f, ck),
        Some(Bridge::Plate(plate)) => {
            if plate.edges != PlateEdges::Free {
                ck.error(
                    &format!("{at}.quantity"),
                    "`bridge_reaction` on a plate is the line reaction of a support across a \
                     deck with free longitudinal edges; simply supported edges carry part of the \
                     load themselves",
                );
            } else if r.y.is_some() {
                ck.error(
                    &format!("{at}.y"),
                    "a plate's `bridge_reaction` is the whole support line's force (N), taken \
                     across the width: give `x` only",
                );
            } else if let Some(x) = r.x {
                let supports = support_positions(&plate.spans);
                if !supports.iter().any(|s| (s - x).abs() <= 1e-3) {
                    let listed: Vec<String> = supports.iter().map(|s| format!("{s}")).collect();
                    ck.error_with_help(
                        &format!("{at}.x"),
                        format!("x = {x} m is not a support of the deck"),
                        Some(format!(
                            "a `bridge_reaction` is taken at a support line: x is one of {} (m)",
                            listed.join(", ")
                        )),
                    );
                }
            }
            None
        }
    }
}

/// The constrained node of an imported model's `bridge_reaction`: `node`
/// as given, or the track's rail node at `x` (within 1 mm) whose DOF in
/// `direction` (default uz) is listed under `constrained`. A DOF that is
/// not listed (free, or dropped by the export) has no row to read a
/// reaction from: refused, with the supports that have one.
fn imported_support(
    r: &raw::RecordRaw,
    at: &str,
    f: &crate::scene::FeImport,
    ck: &mut Checker<'_>,
) -> Option<u64> {
    let direction = r.direction.unwrap_or(Direction::Uz);
    let model = &f.model;
    let listed = || -> String {
        let mut names: Vec<String> = model
            .supports
            .iter()
            .take(12)
            .map(|s| format!("node {} {}", s.node, s.direction.name()))
            .collect();
        if model.supports.len() > 12 {
            names.push(format!("… ({} in all)", model.supports.len()));
        }
        if names.is_empty() {
            "none: the model lists no `constrained` DOF".into()
        } else {
            names.join(", ")
        }
    };
    let help = || {
        Some(format!(
            "a reaction is read from the rows of K and M at a DOF listed under \
             `bridge.constrained` (a DOF the export removed from the matrices has none); \
             constrained DOFs: {}",
            listed()
        ))
    };
    let node = match (r.node, r.x) {
        (Some(node), _) => node,
        (None, Some(x)) => {
            let found = model
                .track
                .iter()
                .flat_map(|&t| {
                    let rail = &model.rails[t];
                    rail.nodes.iter().zip(&rail.x)
                })
                .filter(|&(_, &nx)| (nx - x).abs() <= 1e-3)
                .map(|(&node, _)| node)
                .find(|&node| {
                    model
                        .supports
                        .iter()
                        .any(|s| s.node == node && s.direction == direction)
                });
            match found {
                Some(node) => node,
                None => {
                    ck.error_with_help(
                        &format!("{at}.x"),
                        format!(
                            "no track node at x = {x} m has its {} constrained",
                            direction.name()
                        ),
                        help(),
                    );
                    return None;
                }
            }
        }
        (None, None) => return None,
    };
    if !model
        .supports
        .iter()
        .any(|s| s.node == node && s.direction == direction)
    {
        ck.error_with_help(
            &format!("{at}.node"),
            format!(
                "node {node} {} is not a constrained DOF of the imported model",
                direction.name()
            ),
            help(),
        );
        return None;
    }
    Some(node)
}

/// Displacement at the middle of every span (on a plate, on every girder
/// line) and every wheel's contact force (and, with unilateral contact,
/// every contact wheel's gap).
fn default_records(bridge: &Bridge, vehicles: &[Vehicle], contact: &Contact) -> Vec<Record> {
    let mut out = Vec::new();
    let mut start = 0.0;
    for (i, span) in bridge.spans().iter().enumerate() {
        let x = Some(start + span / 2.0);
        match bridge {
            Bridge::Beam(_) | Bridge::FeImport(_) => out.push(Record {
                name: format!("span{}_midspan", i + 1),
                quantity: Quantity::BridgeDisplacement,
                node: None,
                direction: None,
                x,
                y: None,
                vehicle: None,
                wheel: None,
                dof: None,
                max_frequency: None,
                frame: Frame::Relative,
                component: None,
                side: None,
            }),
            Bridge::Plate(plate) => {
                for (g, &y) in plate.girder_lines.iter().enumerate() {
                    out.push(Record {
                        name: format!("span{}_girder{}", i + 1, g + 1),
                        quantity: Quantity::BridgeDisplacement,
                        node: None,
                        direction: None,
                        x,
                        y: Some(y),
                        vehicle: None,
                        wheel: None,
                        dof: None,
                        max_frequency: None,
                        frame: Frame::Relative,
                        component: None,
                        side: None,
                    });
                }
            }
        }
        start += span;
    }
    for (v, vehicle) in vehicles.iter().enumerate() {
        for w in 0..wheel_count(vehicle) {
            // A train's wheels are named by car and wheelset within the car.
            let wheel_name =
                train_wheel_name(vehicle, w).unwrap_or_else(|| format!("wheel{}", w + 1));
            out.push(Record {
                name: format!("vehicle{}_{wheel_name}_force", v + 1),
                quantity: Quantity::ContactForce,
                node: None,
                direction: None,
                x: None,
                y: None,
                vehicle: Some(v + 1),
                wheel: Some(w + 1),
                dof: None,
                max_frequency: None,
                frame: Frame::Relative,
                component: None,
                side: None,
            });
            if contact.is_unilateral() && !matches!(vehicle, Vehicle::MovingForce(_)) {
                out.push(Record {
                    name: format!("vehicle{}_{wheel_name}_gap", v + 1),
                    quantity: Quantity::ContactGap,
                    node: None,
                    direction: None,
                    x: None,
                    y: None,
                    vehicle: Some(v + 1),
                    wheel: Some(w + 1),
                    dof: None,
                    max_frequency: None,
                    frame: Frame::Relative,
                    component: None,
                    side: None,
                });
            }
        }
    }
    out
}
