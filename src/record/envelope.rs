//! Envelopes along the deck: at every point, the largest and smallest value
//! of each bridge quantity over the run, with when and where (the lead
//! vehicle's front axle) each occurred — VBI-2D's load-effect maxima —
//! tracked step by step without keeping histories; beside each, the same
//! extremes of the static crossing, the reference of the point's dynamic
//! factor.
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
//!
//! The points (issue 40.2): the requested grid (the mesh nodes by default),
//! plus every support, an interior support twice — its left-hand limit,
//! then its right-hand one, so that the shear's jump by the reaction is in
//! the envelope — plus, in every span, the section where each vehicle's
//! static moment envelope peaks ([`peak_sections`]), so that the envelope's
//! peak is not read low between two grid points.
//!
//! The static crossing (each wheel its static load at its position, full
//! stiffness, exact section forces) is evaluated at every step and also at
//! the instant a wheel passes each point, on both sides of it: a moment's
//! or a shear's influence line kinks or jumps under the load, so its static
//! extreme sits exactly there, between two steps.

use super::probe::{StaticProbe, filtered_shape, static_shape, static_share_beyond};
use super::unit_of;
use crate::bridge::BridgeError;
use crate::bridge::InfluenceLine;
use crate::bridge::hermite::HermiteField;
use crate::bridge::section::{NodalSection, SectionForces, SectionLoads, SectionProbe, Side};
use crate::model::Model;
use crate::scene::{Envelopes, Quantity};
use crate::solve::direct::assembled::{AssembledBridge, LinePoint};
use crate::solve::{NodalState, StepView};

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

    /// The larger magnitude of the two extremes.
    pub fn max_abs(&self) -> f64 {
        self.max.abs().max(self.min.abs())
    }
}

/// The smallest static magnitude, relative to the dynamic one, for which a
/// point gets a dynamic factor (as a record's DAF,
/// [`crate::report::summary::DAF_STATIC_SHARE`]): near an influence line's
/// zero there is nothing to divide by.
pub const POINT_DAF_STATIC_SHARE: f64 = 1e-3;

/// The smallest static magnitude, relative to the largest along the deck,
/// for which a point gets a dynamic factor (round-off sits some 1e-16
/// below the peak; a millionth is still a value).
pub const POINT_DAF_STATIC_FLOOR: f64 = 1e-6;

/// One enveloped quantity over all points.
#[derive(Debug, Clone)]
pub struct EnvelopeColumn {
    /// The quantity.
    pub quantity: Quantity,
    /// Unit of its values.
    pub unit: &'static str,
    /// Per point (empty until the first step).
    pub extremes: Vec<Extremes>,
    /// The static crossing's extremes per point (displacements, moments and
    /// shears; empty for accelerations, which have no static part).
    pub statics: Vec<Extremes>,
}

impl EnvelopeColumn {
    /// The dynamic factor at point `p`, max|E| / max|E_static| (none without
    /// a static envelope, or where the static one is below
    /// [`POINT_DAF_STATIC_SHARE`] of the dynamic one).
    /// A point whose static magnitude is below [`POINT_DAF_STATIC_FLOOR`] of
    /// the column's largest has none either: the moment at a pinned end is
    /// round-off (1e-11 N·m beside 1e6), and so would be its ratio. Cost
    /// O(points).
    pub fn daf(&self, p: usize) -> Option<f64> {
        let (e, s) = (self.extremes.get(p)?, self.statics.get(p)?);
        let (dynamic, statics) = (e.max_abs(), s.max_abs());
        let largest = self
            .statics
            .iter()
            .map(Extremes::max_abs)
            .fold(0.0, f64::max);
        (statics > 0.0
            && statics >= POINT_DAF_STATIC_SHARE * dynamic
            && statics >= POINT_DAF_STATIC_FLOOR * largest)
            .then(|| dynamic / statics)
    }
}

/// The envelopes of a run.
#[derive(Debug, Clone)]
pub struct Envelope {
    /// Point positions along the bridge, m, ascending (an interior support
    /// appears twice).
    pub x: Vec<f64>,
    /// Which limit each point takes where a quantity jumps: `Left` for the
    /// first of an interior support's two points, else `Right`.
    pub side: Vec<Side>,
    /// Whether each point is a support.
    pub support: Vec<bool>,
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
    /// A direct run's nodal readings ([`super::direct_envelope_reading`]):
    /// N(x) of the deflection (for the displacement, and the acceleration
    /// when it reads nodally) and the section's nodal form.
    nodal_point: Option<LinePoint>,
    nodal_section: Option<NodalSection>,
}

/// Tracks the envelopes during the run.
#[derive(Debug, Clone)]
pub(super) struct EnvelopeTracker {
    envelope: Envelope,
    points: Vec<PointProbe>,
    /// The wheel positions of the previous step, m (empty before the first).
    previous_positions: Vec<f64>,
    /// The previous step's time, s, and lead-vehicle position, m.
    previous_time: f64,
    previous_lead: f64,
    /// Scratch: the wheel positions at the instant a wheel passes a point.
    passing: Vec<f64>,
    /// Every flattened wheel's index (the wheels a passing instant sums).
    all_wheels: Vec<usize>,
    /// This step's values at every point, computed for all points at once.
    sums: DeckSums,
    /// Whether every column's values are [`Self::sums`]' (displacements
    /// from stacked lines and accelerations, no section), so that the
    /// columns are tracked from them alone.
    from_sums: bool,
    /// A direct run's envelopes of displacement and of acceleration that
    /// read the nodal state (the sections do where they have a nodal form).
    nodal_displacement: bool,
    nodal_acceleration: bool,
}

/// `extremes` updated with this step's `values`, one per point (pushed at
/// the first step).
fn track(extremes: &mut Vec<Extremes>, values: impl Iterator<Item = f64>, time: f64, at: f64) {
    if extremes.is_empty() {
        extremes.extend(values.map(|v| Extremes::new(v, time, at)));
    } else {
        for (e, v) in extremes.iter_mut().zip(values) {
            e.update(v, time, at);
        }
    }
}

/// One step's per-point sums of every point at once, each in its probe's
/// formula, term for term and in its order (bit for bit what the point's
/// own `dot` and [`StaticProbe::deflections`] give): the loops are turned
/// inside out, modes (and wheels) outside, points inside, over shapes kept
/// mode-major, and the points' static influence lines are stacked into one
/// field per wheel line ([`HermiteField::stacked`]) when all are Hermite
/// fields on one mesh (a beam), so that each wheel's element is found
/// once for all points.
#[derive(Debug, Clone)]
struct DeckSums {
    /// Mode values φᵢ(x_p), the filtered ones of the acceleration and the
    /// static shapes φᵢ/ωᵢ², mode-major (`[i * points + p]`).
    shape: Vec<f64>,
    acceleration_shape: Vec<f64>,
    static_shape: Vec<f64>,
    /// Per wheel line (as [`StaticProbe::influences`]) the points' lines,
    /// and which line each flattened wheel uses; `None` when they do not
    /// stack (the points' own lines are used).
    lines: Option<(Vec<HermiteField>, Vec<usize>)>,
    /// Scratch: every point's line at one wheel, and φ_s·φ_w at one wheel.
    values: Vec<f64>,
    wheel_dots: Vec<f64>,
    /// This step's sums per point: Σ φᵢ qᵢ, Σ φᵢ q̈ᵢ (filtered), the full
    /// static deflection under the wheel forces, the static crossing's, and
    /// the modal part of the former (`static_share_beyond`'s).
    modal: Vec<f64>,
    acceleration: Vec<f64>,
    full: Vec<f64>,
    statics: Vec<f64>,
    modal_static: Vec<f64>,
}

/// `shapes` (one per point, each `modes` long) mode-major.
fn mode_major<'a>(shapes: impl Iterator<Item = &'a [f64]> + Clone, modes: usize) -> Vec<f64> {
    (0..modes)
        .flat_map(|i| {
            shapes
                .clone()
                .map(move |s| s.get(i).copied().unwrap_or(0.0))
        })
        .collect()
}

/// `out[p]` = Σᵢ `shapes[i * points + p]` · `x[i]` over the first `terms`
/// modes, from −0.0 and in mode order: [`dot`] of point p's shape and `x`.
fn mode_sums(out: &mut [f64], shapes: &[f64], x: &[f64], terms: usize) {
    out.fill(-0.0);
    let points = out.len();
    if points == 0 {
        return;
    }
    for (row, &xi) in shapes.chunks_exact(points).zip(x).take(terms) {
        for (o, s) in out.iter_mut().zip(row) {
            *o += s * xi;
        }
    }
}

impl DeckSums {
    fn new(points: &[PointProbe], modes: usize) -> Self {
        let count = points.len();
        let lines = Self::stack(points);
        Self {
            shape: mode_major(points.iter().map(|p| p.shape.as_slice()), modes),
            acceleration_shape: mode_major(
                points.iter().map(|p| p.acceleration_shape.as_slice()),
                modes,
            ),
            static_shape: mode_major(points.iter().map(|p| p.static_shape.as_slice()), modes),
            lines,
            values: vec![0.0; count],
            wheel_dots: vec![0.0; count],
            modal: vec![0.0; count],
            acceleration: vec![0.0; count],
            full: vec![0.0; count],
            statics: vec![0.0; count],
            modal_static: vec![0.0; count],
        }
    }

    /// The points' lines stacked, one field per wheel line; `None` unless
    /// every line is a Hermite field on one mesh and every point's wheels
    /// use the same lines.
    fn stack(points: &[PointProbe]) -> Option<(Vec<HermiteField>, Vec<usize>)> {
        let first = &points.first()?.statics;
        if points
            .iter()
            .any(|p| p.statics.wheel_influence != first.wheel_influence)
        {
            return None;
        }
        let lines = (0..first.influences.len())
            .map(|l| {
                let fields = points
                    .iter()
                    .map(|p| match p.statics.influences.get(l) {
                        Some(InfluenceLine::Hermite(field)) => Some(field),
                        _ => None,
                    })
                    .collect::<Option<Vec<_>>>()?;
                HermiteField::stacked(&fields)
            })
            .collect::<Option<Vec<_>>>()?;
        Some((lines, first.wheel_influence.clone()))
    }

    /// This step's sums of the quantities enveloped (`displacement`,
    /// `acceleration`): the modal ones, and for displacements on stacked
    /// lines the static ones of the wheels `on_deck` with `wheel_modes`
    /// (wheel-major, `modes` a wheel; empty without static correction).
    #[allow(clippy::too_many_arguments)]
    fn evaluate(
        &mut self,
        view: &StepView<'_>,
        static_loads: &[f64],
        wheel_modes: &[f64],
        on_deck: &[usize],
        displacement: bool,
        acceleration: bool,
    ) {
        let modes = self.shape.len() / self.modal.len().max(1);
        // `dot`'s terms: the shorter of the shape (every mode) and q.
        if acceleration {
            mode_sums(
                &mut self.acceleration,
                &self.acceleration_shape,
                view.modal_acceleration,
                modes.min(view.modal_acceleration.len()),
            );
        }
        if !displacement {
            return;
        }
        mode_sums(
            &mut self.modal,
            &self.shape,
            view.modal_displacement,
            modes.min(view.modal_displacement.len()),
        );
        let Some((lines, wheel_line)) = self.lines.as_ref() else {
            return;
        };
        // From −0.0, as `Iterator::sum` and the folds start.
        self.full.fill(-0.0);
        self.statics.fill(-0.0);
        self.modal_static.fill(-0.0);
        for &w in on_deck {
            lines[wheel_line[w]].values_at(view.wheel_positions[w], &mut self.values);
            let (force, load) = (view.contact_forces[w], static_loads[w]);
            for ((full, statics), &g) in self
                .full
                .iter_mut()
                .zip(&mut self.statics)
                .zip(&self.values)
            {
                *full -= force * g;
                *statics -= load * g;
            }
            if !wheel_modes.is_empty() {
                let values = &wheel_modes[w * modes..(w + 1) * modes];
                mode_sums(&mut self.wheel_dots, &self.static_shape, values, modes);
                for (modal, &d) in self.modal_static.iter_mut().zip(&self.wheel_dots) {
                    *modal += -force * d;
                }
            }
        }
    }
}

/// A direct run's envelopes ([`super::direct_envelope_reading`]): the
/// assembled bridge when its sections read the nodal state, and whether
/// the displacement and the acceleration do; nothing for a modal method.
fn nodal_envelopes<'m>(
    model: &'m Model,
    envelopes: &Envelopes,
) -> (Option<AssembledBridge<'m>>, bool, bool) {
    if model.method != crate::scene::SolverMethod::Direct {
        return (None, false, false);
    }
    let Ok(bridge) = AssembledBridge::of(&model.bridge) else {
        return (None, false, false);
    };
    let frequencies = model.bridge.frequencies();
    let kept = super::KeptModes {
        frequencies: &frequencies,
        available: model.bridge.available_modes,
        filter: model.bridge.acceleration_filter,
    };
    let nodal = |quantity| {
        envelopes.quantities.contains(&quantity)
            && super::direct_envelope_reading(quantity, envelopes.max_frequency, &kept)
                == super::DirectReading::Nodal
    };
    let (displacement, acceleration) = (
        nodal(Quantity::BridgeDisplacement),
        nodal(Quantity::BridgeAcceleration),
    );
    (Some(bridge), displacement, acceleration)
}

/// A section's forces from the nodal state, with the ground's inertia
/// share at `ground` (the vertical ground acceleration, m/s², under ground
/// motion) as the matching record adds it.
fn nodal_forces(
    nodal: &NodalSection,
    section: &SectionProbe,
    state: &NodalState<'_>,
    view: &StepView<'_>,
    on_deck: &[usize],
    ground: Option<f64>,
) -> SectionForces {
    let forces = nodal.forces(
        section,
        state,
        view.wheel_positions,
        view.contact_forces,
        on_deck,
    );
    match ground {
        None => forces,
        Some(acceleration) => SectionForces {
            moment: forces.moment + nodal.ground.moment * acceleration,
            shear: forces.shear + nodal.ground.shear * acceleration,
        },
    }
}

/// Two positions within this distance (m) are one envelope point.
const SAME_POINT: f64 = 1e-9;

/// Envelope points (m, ascending), the side of each, and whether each is a
/// support.
type PointSet = (Vec<f64>, Vec<Side>, Vec<bool>);

/// The points of the envelope: the grid, the supports and the peak
/// sections, ascending, with each one's side and whether it is a support.
fn envelope_points(
    model: &Model,
    envelopes: &Envelopes,
    sections: bool,
) -> Result<PointSet, BridgeError> {
    let length = model.bridge.length;
    let mut x: Vec<f64> = match envelopes.points {
        Some(n) => (0..n).map(|i| length * i as f64 / (n - 1) as f64).collect(),
        None => model.bridge.node_x().to_vec(),
    };
    x.extend(model.bridge.supports.iter().copied());
    if envelopes.quantities.contains(&Quantity::BridgeMoment) {
        x.extend(peak_sections(model)?);
    }
    // Snap onto the supports (a grid point a round-off away is the
    // support), then one point per position.
    for s in &model.bridge.supports {
        for p in x.iter_mut() {
            if (*p - s).abs() <= SAME_POINT * (1.0 + length) {
                *p = *s;
            }
        }
    }
    x.sort_by(f64::total_cmp);
    x.dedup_by(|b, a| (*b - *a).abs() <= SAME_POINT * (1.0 + length));
    let mut points = Vec::with_capacity(x.len() + model.bridge.supports.len());
    let mut sides = Vec::with_capacity(points.capacity());
    let mut support = Vec::with_capacity(points.capacity());
    for p in x {
        let on_support = model.bridge.supports.contains(&p);
        let interior = p > 0.0 && p < length;
        if sections && on_support && interior {
            points.push(p);
            sides.push(Side::Left);
            support.push(true);
        }
        points.push(p);
        sides.push(Side::Right);
        support.push(on_support);
    }
    Ok((points, sides, support))
}

/// Where, in every span, each vehicle's static sagging-moment envelope
/// peaks, m: the section of the absolute maximum moment (for a simply
/// supported span and a group of point loads, Barré's theorem puts it under
/// an axle, the axle and the loads' resultant symmetric about mid-span; on
/// a continuous beam it moves off mid-span). Found by scanning the mesh
/// nodes of the span and a golden-section search between the best node's
/// neighbours on the static envelope M*(x) = max over the vehicle's
/// positions of Σ_w P_w M(x; ξ_w) ([`static_peak_at`]). Two sparse solves
/// and O(wheels × 2000) influence values per section tried, at most
/// [`PEAK_CANDIDATES`] + 40 per span and vehicle.
fn peak_sections(model: &Model) -> Result<Vec<f64>, BridgeError> {
    let nodes = model.bridge.node_x().to_vec();
    let supports = &model.bridge.supports;
    let mut found = Vec::new();
    for group in vehicle_groups(model) {
        if group.is_empty() {
            continue;
        }
        for span in supports.windows(2) {
            let (a, b) = (span[0], span[1]);
            // At most PEAK_CANDIDATES nodes of the span are tried (a fine
            // mesh's every k-th), the search then between the best one's
            // neighbours among them.
            let all: Vec<f64> = nodes.iter().copied().filter(|&n| n > a && n < b).collect();
            let every = all.len().div_ceil(PEAK_CANDIDATES).max(1);
            let inside: Vec<f64> = all.iter().copied().step_by(every).collect();
            let mut best: Option<(usize, f64)> = None;
            for (k, &n) in inside.iter().enumerate() {
                let value = static_peak_at(model, n, &group, &nodes)?;
                if best.is_none_or(|(_, v)| value > v) {
                    best = Some((k, value));
                }
            }
            let Some((k, _)) = best else { continue };
            let lo = if k == 0 { a } else { inside[k - 1] };
            let hi = inside.get(k + 1).copied().unwrap_or(b);
            let peak = golden_max(lo, hi, |x| static_peak_at(model, x, &group, &nodes))?;
            // Within the search's tolerance of a node the node is the peak
            // (a flat maximum there: mid-span under one load).
            let tolerance = 1e-5 * (hi - lo);
            let peak = inside
                .iter()
                .copied()
                .find(|n| (n - peak).abs() <= tolerance)
                .unwrap_or(peak);
            found.push(peak);
        }
    }
    Ok(found)
}

/// Most nodes of a span at which [`peak_sections`] evaluates the static
/// envelope before its golden-section search.
const PEAK_CANDIDATES: usize = 48;

/// Most front-axle positions of [`static_peak_at`]'s sweep.
const PEAK_SWEEP: f64 = 2000.0;

/// Each vehicle's wheels as (distance behind its front axle m, static load
/// N), a rigid group of point loads.
fn vehicle_groups(model: &Model) -> Vec<Vec<(f64, f64)>> {
    let mut groups = vec![Vec::new(); model.vehicles.len()];
    for (flat, r) in model.wheels.iter().enumerate() {
        let offset = model.vehicles[r.vehicle].wheels[r.wheel].offset;
        groups[r.vehicle].push((offset, model.static_wheel_loads[flat]));
    }
    groups
}

/// The largest static moment at `x` (N·m, sagging positive) as the group
/// of point loads `group` crosses: over the front-axle positions that put
/// each axle just either side of `x` (where the moment's influence line
/// kinks) and a sweep at an eighth of the smallest element.
fn static_peak_at(
    model: &Model,
    x: f64,
    group: &[(f64, f64)],
    nodes: &[f64],
) -> Result<f64, BridgeError> {
    let Some(section) = model.bridge.section_probe(x, Side::Right)? else {
        return Ok(f64::NEG_INFINITY);
    };
    let length = model.bridge.length;
    let longest = group.iter().map(|g| g.0).fold(0.0, f64::max);
    // An eighth of the smallest element, or of the crossing over
    // PEAK_SWEEP positions on a fine mesh (between them only a smooth
    // maximum, no kink, is missed: its error is quadratic in the step).
    let step = (nodes
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min)
        / 8.0)
        .max((length + longest) / PEAK_SWEEP);
    let positions_of = |front: f64| -> Vec<f64> { group.iter().map(|g| front - g.0).collect() };
    let loads: Vec<f64> = group.iter().map(|g| g.1).collect();
    let wheels: Vec<usize> = (0..group.len()).collect();
    let moment_at = |front: f64| {
        section
            .static_forces(&positions_of(front), &loads, &wheels)
            .moment
    };
    let mut best = f64::NEG_INFINITY;
    let eps = 1e-12 * (1.0 + length);
    for g in group {
        for side in [-eps, eps] {
            best = best.max(moment_at(x + g.0 + side));
        }
    }
    let sweeps = ((length + longest) / step).ceil().min(PEAK_SWEEP) as usize;
    for i in 0..=sweeps {
        best = best.max(moment_at(i as f64 * step));
    }
    Ok(best)
}

/// The x in [lo, hi] where `f` is largest, by golden-section search to
/// 1e-6 of the interval (f unimodal there: the envelope near its peak).
fn golden_max(
    lo: f64,
    hi: f64,
    mut f: impl FnMut(f64) -> Result<f64, BridgeError>,
) -> Result<f64, BridgeError> {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    while (b - a) > 1e-6 * (hi - lo).max(f64::MIN_POSITIVE) {
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = f(d)?;
        }
    }
    Ok(if fc >= fd { c } else { d })
}

impl EnvelopeTracker {
    /// The probes of every point (resolved `envelopes` on a beam).
    pub(super) fn new(model: &Model, envelopes: &Envelopes) -> Result<Self, BridgeError> {
        let sections = envelopes
            .quantities
            .iter()
            .any(|q| matches!(q, Quantity::BridgeMoment | Quantity::BridgeShear));
        let (x, side, support) = envelope_points(model, envelopes, sections)?;
        let modes = model.bridge.mode_count();
        let (nodal, nodal_displacement, nodal_acceleration) = nodal_envelopes(model, envelopes);
        let mut points = Vec::with_capacity(x.len());
        for (&at, &side) in x.iter().zip(&side) {
            let mut shape = vec![0.0; modes];
            model.bridge.mode_values(at, 0.0, &mut shape);
            let section = if sections {
                model.bridge.section_probe(at, side)?
            } else {
                None
            };
            let nodal_section = section
                .as_ref()
                .filter(|_| nodal.is_some())
                .and_then(|s| model.bridge.nodal_section(s));
            points.push(PointProbe {
                acceleration_shape: filtered_shape(model, &shape, envelopes.max_frequency),
                static_shape: static_shape(model, &shape),
                statics: StaticProbe::new(model, at, 0.0)?,
                shape,
                section,
                nodal_point: nodal.map(|bridge| bridge.point(at)),
                nodal_section,
            });
        }
        let columns = envelopes
            .quantities
            .iter()
            .map(|&quantity| EnvelopeColumn {
                quantity,
                unit: unit_of(quantity),
                extremes: Vec::with_capacity(x.len()),
                statics: Vec::with_capacity(x.len()),
            })
            .collect();
        let wheels = model.wheels.len();
        let sums = DeckSums::new(&points, modes);
        let from_sums = points.iter().all(|p| p.section.is_none())
            && !nodal_displacement
            && !nodal_acceleration
            && envelopes.quantities.iter().all(|q| match q {
                Quantity::BridgeDisplacement => sums.lines.is_some(),
                Quantity::BridgeAcceleration => true,
                _ => false,
            });
        Ok(Self {
            envelope: Envelope {
                x,
                side,
                support,
                columns,
            },
            points,
            previous_positions: Vec::with_capacity(wheels),
            previous_time: 0.0,
            previous_lead: 0.0,
            passing: Vec::with_capacity(wheels),
            all_wheels: (0..wheels).collect(),
            sums,
            from_sums,
            nodal_displacement,
            nodal_acceleration,
        })
    }

    /// Whether the tracker reads the modal coordinates (anything it tracks
    /// not read from a direct run's nodal state).
    pub(super) fn reads_modes(&self) -> bool {
        let modal_sections = self
            .points
            .iter()
            .any(|p| p.section.is_some() && p.nodal_section.is_none());
        !self.points.is_empty()
            && (!self.nodal_displacement || !self.nodal_acceleration || modal_sections)
    }

    /// Whether the tracker needs the mode values at the wheels (for the
    /// static correction of a displacement or a section that reads modes).
    pub(super) fn needs_wheel_modes(&self) -> bool {
        let modal_sections = self
            .points
            .iter()
            .any(|p| p.section.is_some() && p.nodal_section.is_none());
        !self.points.is_empty() && (!self.nodal_displacement || modal_sections)
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
        let static_loads = &model.static_wheel_loads;
        let has = |q| self.envelope.columns.iter().any(|c| c.quantity == q);
        let (displacement, acceleration) = (
            has(Quantity::BridgeDisplacement),
            has(Quantity::BridgeAcceleration),
        );
        // A direct run's nodal envelopes need no modal sums (the static
        // crossing's displacement still comes from the stacked lines).
        let nodal_state = view.nodal.as_ref();
        let nodal = |on: bool| on && nodal_state.is_some();
        let (nodal_displacement, nodal_acceleration) = (
            nodal(self.nodal_displacement),
            nodal(self.nodal_acceleration),
        );
        self.sums.evaluate(
            view,
            static_loads,
            if nodal_displacement { &[] } else { wheel_modes },
            on_deck,
            displacement,
            acceleration && !nodal_acceleration,
        );
        let sums = &self.sums;
        if self.from_sums {
            // Column by column, point by point: the same values as below.
            let time = view.time;
            for column in &mut self.envelope.columns {
                match column.quantity {
                    Quantity::BridgeDisplacement => {
                        let values = sums.modal.iter().enumerate().map(|(p, &modal)| {
                            if wheel_modes.is_empty() {
                                modal
                            } else {
                                modal + (sums.full[p] - sums.modal_static[p])
                            }
                        });
                        track(&mut column.extremes, values, time, position);
                        let statics = sums.statics.iter().copied();
                        track(&mut column.statics, statics, time, position);
                    }
                    _ => {
                        let values = sums.acceleration.iter().copied();
                        track(&mut column.extremes, values, time, position);
                    }
                }
            }
        }
        let ground = model
            .ground
            .as_ref()
            .map(|g| g.vertical_acceleration(view.time));
        for (p, point) in self.points.iter().enumerate().filter(|_| !self.from_sums) {
            let section =
                point
                    .section
                    .as_ref()
                    .map(|s| match (&point.nodal_section, nodal_state) {
                        (Some(n), Some(state)) => nodal_forces(n, s, state, view, on_deck, ground),
                        _ => s.forces(&loads, corrected),
                    });
            let nodal_value = |acceleration: bool| {
                let (point, state) = (point.nodal_point.as_ref()?, nodal_state?);
                Some(if acceleration {
                    point.value(state.acceleration)
                } else {
                    point.value(state.displacement)
                })
            };
            let static_section = point
                .section
                .as_ref()
                .map(|s| s.static_forces(view.wheel_positions, static_loads, on_deck));
            for column in &mut self.envelope.columns {
                let (value, static_value) = match column.quantity {
                    Quantity::BridgeDisplacement if nodal_displacement => {
                        // N(x)ᵀu, no static correction (the record's).
                        let statics = match sums.lines {
                            Some(_) => sums.statics[p],
                            None => {
                                point
                                    .statics
                                    .deflections(
                                        view.wheel_positions,
                                        view.contact_forces,
                                        static_loads,
                                        on_deck,
                                    )
                                    .1
                            }
                        };
                        (nodal_value(false).unwrap_or(0.0), Some(statics))
                    }
                    Quantity::BridgeAcceleration if nodal_acceleration => {
                        (nodal_value(true).unwrap_or(0.0), None)
                    }
                    Quantity::BridgeDisplacement => {
                        let modal = sums.modal[p];
                        // The record's formula (`corrected_displacement`).
                        if sums.lines.is_some() {
                            let value = if wheel_modes.is_empty() {
                                modal
                            } else {
                                // `static_share_beyond`'s difference.
                                modal + (sums.full[p] - sums.modal_static[p])
                            };
                            (value, Some(sums.statics[p]))
                        } else {
                            let (full, statics) = point.statics.deflections(
                                view.wheel_positions,
                                view.contact_forces,
                                static_loads,
                                on_deck,
                            );
                            let value = if wheel_modes.is_empty() {
                                modal
                            } else {
                                modal
                                    + static_share_beyond(
                                        full,
                                        &point.static_shape,
                                        wheel_modes,
                                        view,
                                        on_deck,
                                    )
                            };
                            (value, Some(statics))
                        }
                    }
                    Quantity::BridgeAcceleration => (sums.acceleration[p], None),
                    Quantity::BridgeMoment => (
                        section.map_or(0.0, |s| s.moment),
                        static_section.map(|s| s.moment),
                    ),
                    Quantity::BridgeShear => (
                        section.map_or(0.0, |s| s.shear),
                        static_section.map(|s| s.shear),
                    ),
                    _ => (0.0, None),
                };
                match column.extremes.get_mut(p) {
                    Some(e) => e.update(value, view.time, position),
                    None => column
                        .extremes
                        .push(Extremes::new(value, view.time, position)),
                }
                if let Some(s) = static_value {
                    match column.statics.get_mut(p) {
                        Some(e) => e.update(s, view.time, position),
                        None => column.statics.push(Extremes::new(s, view.time, position)),
                    }
                }
            }
        }
        self.observe_passing(model, view, position);
        self.previous_positions.clear();
        self.previous_positions
            .extend_from_slice(view.wheel_positions);
        self.previous_time = view.time;
        self.previous_lead = position;
    }

    /// The static section forces at the instants between the last step and
    /// this one when a wheel passes a section point, with that wheel just
    /// before and just past it (the influence line's kink or jump) and the
    /// others where they were then (positions linear in time over a step).
    fn observe_passing(&mut self, model: &Model, view: &StepView<'_>, position: f64) {
        let now = view.wheel_positions;
        if self.previous_positions.len() != now.len() {
            return;
        }
        let eps = 1e-12 * (1.0 + model.bridge.length);
        let static_loads = &model.static_wheel_loads;
        for (p, point) in self.points.iter().enumerate() {
            let Some(section) = &point.section else {
                continue;
            };
            let x = self.envelope.x[p];
            for w in 0..now.len() {
                let (before, after) = (self.previous_positions[w], now[w]);
                // Passed x in (before, after]: ahead of it before, not after.
                if !(before < x && after >= x) || after == before {
                    continue;
                }
                let s = (x - before) / (after - before);
                self.passing.clear();
                self.passing.extend(
                    self.previous_positions
                        .iter()
                        .zip(now)
                        .map(|(a, b)| a + s * (b - a)),
                );
                let time = self.previous_time + s * (view.time - self.previous_time);
                let lead = self.previous_lead + s * (position - self.previous_lead);
                for side in [-eps, eps] {
                    self.passing[w] = x + side;
                    let forces =
                        section.static_forces(&self.passing, static_loads, &self.all_wheels);
                    for column in &mut self.envelope.columns {
                        let value = match column.quantity {
                            Quantity::BridgeMoment => forces.moment,
                            Quantity::BridgeShear => forces.shear,
                            _ => continue,
                        };
                        if let Some(e) = column.statics.get_mut(p) {
                            e.update(value, time, lead);
                        }
                    }
                }
            }
        }
    }

    pub(super) fn finish(self) -> Envelope {
        self.envelope
    }
}
