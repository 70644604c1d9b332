//! The modal model of an imported bridge: its pencil, the kept modes along
//! the track, at any DOF, and its static flexibility.

use std::sync::Arc;

use faer::Mat;

use super::super::BridgeError;
use super::super::ContactPoint;
use super::super::eigen::Pencil;
use super::super::eigen::sparse::{multiply, symmetric_from_entries};
use super::track::{RailDirection, TrackField};
use crate::contact::ContactDirection;
use crate::scene::imported::ImportedModel;
use crate::scene::imported::RailDofs;

/// The pencil (K, M) of an imported model on its free DOFs.
pub fn pencil(model: &ImportedModel) -> Result<Pencil, BridgeError> {
    let n = model.dofs.len();
    Ok(Pencil::new(
        symmetric_from_entries(n, model.stiffness.iter().copied(), false)?,
        symmetric_from_entries(n, model.mass.iter().copied(), false)?,
    ))
}

/// Right-hand sides per pass over K's factor in
/// [`ImportedShapes::static_flexibility_at`]: enough to run the triangular
/// solves as matrix products, n × 32 × 8 B (12 MB at 48,516 DOFs) of work
/// space.
pub const FLEXIBILITY_BLOCK: usize = 32;

/// Kept modes of an imported bridge.
#[derive(Debug, Clone)]
pub struct ImportedShapes {
    /// The model.
    pub model: Arc<ImportedModel>,
    /// Its pencil (K factorised on first static use).
    pub pencil: Pencil,
    /// The kept modes on the free DOFs, one per column (1/√kg).
    pub vectors: Mat<f64>,
    /// The kept modes along the track (vertical).
    pub track: TrackField,
    /// The kept modes' lateral (uy) components along the track, the mean
    /// of its rails (zero where a rail node has no free uy): what a
    /// wheelset following its rails sideways meets (issue 13).
    pub lateral_track: TrackField,
    /// Each kept mode's kinetic-energy shares by direction
    /// ([`energy_shares`]), in the order of [`ModeDirection::ALL`].
    pub energy_shares: Vec<[f64; 4]>,
}

/// The direction a mode of an imported model moves in, named by where its
/// kinetic energy is ([`energy_shares`]): ux is `axial`, uy `lateral`, uz
/// `vertical`, rx `torsion`; a rotation ry (about the lateral axis) goes
/// with the vertical bending it belongs to and rz (about the vertical
/// axis) with the lateral bending.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModeDirection {
    /// Along the track: ux.
    Axial,
    /// Sideways: uy, and rz (lateral bending's rotation).
    Lateral,
    /// Up and down: uz, and ry (vertical bending's rotation).
    Vertical,
    /// Twist about the track: rx.
    Torsion,
}

impl ModeDirection {
    /// Every direction, in the order of [`ImportedShapes::energy_shares`].
    pub const ALL: [ModeDirection; 4] = [
        ModeDirection::Axial,
        ModeDirection::Lateral,
        ModeDirection::Vertical,
        ModeDirection::Torsion,
    ];

    /// The direction group of a DOF direction.
    pub fn of(direction: crate::scene::imported::Direction) -> Self {
        use crate::scene::imported::Direction::*;
        match direction {
            Ux => ModeDirection::Axial,
            Uy | Rz => ModeDirection::Lateral,
            Uz | Ry => ModeDirection::Vertical,
            Rx => ModeDirection::Torsion,
        }
    }

    /// Its name: `axial`, `lateral`, `vertical` or `torsion`.
    pub fn name(self) -> &'static str {
        match self {
            ModeDirection::Axial => "axial",
            ModeDirection::Lateral => "lateral",
            ModeDirection::Vertical => "vertical",
            ModeDirection::Torsion => "torsion",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// The share of a mode's kinetic energy each direction group
/// ([`ModeDirection`]) carries: for a mass-normalised φ (φᵀMφ = 1) the
/// group g's share is Σ_{i∈g} φᵢ (Mφ)ᵢ, the part of φᵀMφ its DOFs' rows
/// sum (a consistent mass's coupling between two groups split evenly
/// between them by its symmetry), divided by φᵀMφ so that the four add
/// up to 1 for any scaling. Where a consistent mass couples two groups
/// (a pier element's ux with its ry) and they move against each other,
/// the coupling's share is negative: one group's share can then be a few
/// per cent below 0 and the largest a few above 1 (measured on the EMBS
/// viaduct: 103.3 % for its third axial mode). Cost one product with M
/// per mode.
pub fn energy_shares(model: &ImportedModel, pencil: &Pencil, vectors: &Mat<f64>) -> Vec<[f64; 4]> {
    let n = model.dofs.len();
    let mut m_phi = vec![0.0; n];
    (0..vectors.ncols())
        .map(|c| {
            let phi: Vec<f64> = vectors.col(c).iter().copied().collect();
            multiply(&pencil.mass, &phi, &mut m_phi);
            let mut shares = [0.0; 4];
            for (i, &(_, direction)) in model.dofs.iter().enumerate() {
                shares[ModeDirection::of(direction).index()] += phi[i] * m_phi[i];
            }
            let total: f64 = shares.iter().sum();
            if total > 0.0 {
                for s in &mut shares {
                    *s /= total;
                }
            }
            shares
        })
        .collect()
}

/// The direction of largest share in `shares` ([`energy_shares`]), and
/// that share.
pub fn dominant(shares: &[f64; 4]) -> (ModeDirection, f64) {
    let (i, &share) = shares
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .expect("four shares");
    (ModeDirection::ALL[i], share)
}

impl ImportedShapes {
    /// The kept `vectors` of `model`.
    pub fn new(model: Arc<ImportedModel>, pencil: Pencil, vectors: Mat<f64>) -> Self {
        let _t = crate::timings::stage(|| "the modes along the track, energy shares".into());
        let count = vectors.ncols();
        let track = track_field(&model, RailDirection::Vertical, count, |dof, c| {
            vectors[(dof, c)]
        });
        let lateral_track = track_field(&model, RailDirection::Lateral, count, |dof, c| {
            vectors[(dof, c)]
        });
        let energy_shares = energy_shares(&model, &pencil, &vectors);
        Self {
            model,
            pencil,
            vectors,
            track,
            lateral_track,
            energy_shares,
        }
    }

    /// Mode values at free DOF `dof`.
    pub fn dof_values(&self, dof: usize, values: &mut [f64]) {
        for (c, v) in values.iter_mut().enumerate() {
            *v = self.vectors[(dof, c)];
        }
    }

    /// Modal damping ratios ζᵢ = φᵢᵀCφᵢ/(2ωᵢ) of a damping matrix C.
    pub fn projected_damping(
        &self,
        damping: &[(usize, usize, f64)],
        omegas: &[f64],
    ) -> Result<Vec<f64>, BridgeError> {
        let n = self.model.dofs.len();
        let c = symmetric_from_entries(n, damping.iter().copied(), false)?;
        let mut product = vec![0.0; n];
        Ok(omegas
            .iter()
            .enumerate()
            .map(|(i, w)| {
                let phi: Vec<f64> = self.vectors.col(i).iter().copied().collect();
                multiply(&c, &phi, &mut product);
                let modal: f64 = phi.iter().zip(&product).map(|(a, b)| a * b).sum();
                modal / (2.0 * w)
            })
            .collect())
    }

    /// Deflection along the track under the unit load vector `load` (K u =
    /// load, by reciprocity the influence line of the point the load
    /// stands for), m/N.
    fn static_field(&self, load: Vec<f64>) -> Result<TrackField, BridgeError> {
        self.static_field_in(load, RailDirection::Vertical)
    }

    /// [`Self::static_field`] read along the rails in `direction` (uz or
    /// uy), m/N.
    fn static_field_in(
        &self,
        load: Vec<f64>,
        direction: RailDirection,
    ) -> Result<TrackField, BridgeError> {
        let solution = self.static_solution(load)?;
        Ok(track_field(&self.model, direction, 1, |dof, _| {
            solution[dof]
        }))
    }

    /// K⁻¹ `load` on the free DOFs (one solve with the cached factor).
    fn static_solution(&self, mut load: Vec<f64>) -> Result<Vec<f64>, BridgeError> {
        let factor = self.pencil.stiffness_factor()?;
        factor.solve_in_place(&mut load, &mut factor.workspace()?);
        Ok(load)
    }

    /// K⁻¹ M δ along the track: the static deflection under the inertia
    /// load of a unit vertical ground acceleration ([`ImportedModel::vertical_inertia`]),
    /// m/(m/s²), in the sense of the load.
    pub fn inertia_field(&self) -> Result<TrackField, BridgeError> {
        self.static_field(self.model.vertical_inertia.clone())
    }

    /// K⁻¹ M δ_y read laterally (uy, the mean of the track rails, as
    /// `lateral_track`): the rails' static lateral deflection under the
    /// inertia load of a unit lateral ground acceleration
    /// ([`ImportedModel::lateral_inertia`]), m/(m/s²), in the sense of the
    /// load.
    pub fn lateral_inertia_field(&self) -> Result<TrackField, BridgeError> {
        self.static_field_in(self.model.lateral_inertia.clone(), RailDirection::Lateral)
    }

    /// (K⁻¹ M δ, K⁻¹ M δ_y) at free DOF `dof`: its static displacement
    /// under the inertia loads of a unit vertical and a unit lateral ground
    /// acceleration, m/(m/s²), in the sense of the loads. Two solves.
    pub fn inertia_at_dof(&self, dof: usize) -> Result<(f64, f64), BridgeError> {
        let vertical = self.static_solution(self.model.vertical_inertia.clone())?;
        let lateral = self.static_solution(self.model.lateral_inertia.clone())?;
        Ok((vertical[dof], lateral[dof]))
    }

    /// Influence line G(ξ) of the track point `x` (m): the deflection at x
    /// under a unit downward load at ξ on the track, m/N, downward positive.
    pub fn influence_line(&self, x: f64) -> Result<TrackField, BridgeError> {
        let mut load = vec![0.0; self.model.dofs.len()];
        for (dof, w) in track_weights(&self.model, x) {
            load[dof] += w;
        }
        self.static_field(load)
    }

    /// Influence line of free DOF `dof` (its displacement under a unit
    /// downward load at ξ on the track, m/N, along the DOF's negative
    /// direction).
    pub fn dof_influence_line(&self, dof: usize) -> Result<TrackField, BridgeError> {
        let mut load = vec![0.0; self.model.dofs.len()];
        load[dof] = 1.0;
        self.static_field(load)
    }

    /// The static flexibility G(c, c) = N(c)ᵀK⁻¹N(c) at each track point
    /// c (direction, x along and y across the track, [`track_weights_at`]),
    /// m/N, times the square of the entry weight near a free rail end as
    /// [`ImportedFlexibility::green`] (what a wheel there meets), without
    /// forming K⁻¹: the points are solved in blocks of
    /// [`FLEXIBILITY_BLOCK`] right-hand sides, one pass over K's factor
    /// per block. Cost O(nnz(L) · points) time, O(n · block) memory: what
    /// a model too large for [`Self::flexibility`] affords at a sample of
    /// its rail nodes.
    pub fn static_flexibility_at(&self, points: &[ContactPoint]) -> Result<Vec<f64>, BridgeError> {
        let n = self.model.dofs.len();
        let factor = self.pencil.stiffness_factor()?;
        let _t = crate::timings::stage(|| format!("static flexibility at {} points", points.len()));
        let chunks: Vec<&[ContactPoint]> = points.chunks(FLEXIBILITY_BLOCK).collect();
        // A contact couples to the model with its entry weight at a
        // free rail end ([`super::entry`]), as in [`ImportedFlexibility::green`].
        let entry = &self.model.entry;
        let coupling = |point: &ContactPoint| {
            if entry.is_active() {
                entry.weight(point.1).0
            } else {
                1.0
            }
        };
        // Each chunk of points is solved on its own, the same whichever
        // thread runs it: the result does not depend on the thread count.
        let par = self.pencil.parallelism();
        // A simplicial factor: each point's G = N(c)ᵀK⁻¹N(c) by a forward
        // solve over the columns of L its few DOFs reach
        // ([`Factor::inverse_form`]), a tiny share of a full solve.
        if factor.is_simplicial() {
            let parts = super::super::eigen::parallel::map(par, chunks.len(), |c| {
                let mut scratch = factor.form_scratch();
                chunks[c]
                    .iter()
                    .map(|point @ &(direction, x, y)| {
                        let w = track_weights_at(&self.model, direction, x, y);
                        let g = factor
                            .inverse_form(w.as_slice(), &mut scratch)
                            .expect("a simplicial factor");
                        g * coupling(point) * coupling(point)
                    })
                    .collect::<Vec<f64>>()
            });
            return Ok(parts.concat());
        }
        let parts = super::super::eigen::parallel::map(par, chunks.len(), |c| {
            let chunk = chunks[c];
            let mut workspace = factor.block_workspace(FLEXIBILITY_BLOCK)?;
            let mut block = Mat::<f64>::zeros(n, FLEXIBILITY_BLOCK.min(points.len()));
            let weights: Vec<TrackWeights> = chunk
                .iter()
                .map(|&(direction, x, y)| track_weights_at(&self.model, direction, x, y))
                .collect();
            for (j, w) in weights.iter().enumerate() {
                for &(dof, weight) in w.as_slice() {
                    block[(dof, j)] += weight;
                }
            }
            let columns = chunk.len();
            factor.solve_block_in_place(block.as_mut().subcols_mut(0, columns), &mut workspace);
            let mut out = Vec::with_capacity(columns);
            for ((j, w), point) in weights.iter().enumerate().zip(chunk) {
                let g: f64 = w
                    .as_slice()
                    .iter()
                    .map(|&(dof, weight)| weight * block[(dof, j)])
                    .sum();
                out.push(g * coupling(point) * coupling(point));
            }
            Ok::<_, BridgeError>(out)
        });
        let mut out = Vec::with_capacity(points.len());
        for part in parts {
            out.extend(part?);
        }
        Ok(out)
    }

    /// K⁻¹ on the free DOFs (n solves; O(n²) memory), `None` above
    /// `limit` DOFs.
    pub fn flexibility(&self, limit: usize) -> Result<Option<ImportedFlexibility>, BridgeError> {
        let n = self.model.dofs.len();
        if n > limit {
            return Ok(None);
        }
        let factor = self.pencil.stiffness_factor()?;
        let mut workspace = factor.workspace()?;
        let mut inverse = vec![0.0; n * n];
        for (j, column) in inverse.chunks_mut(n).enumerate() {
            column[j] = 1.0;
            factor.solve_in_place(column, &mut workspace);
        }
        Ok(Some(ImportedFlexibility {
            model: self.model.clone(),
            inverse,
            order: n,
        }))
    }
}

/// Free DOFs and weights of the track point `x` (m) on the centre line:
/// each track rail's vertical interpolation weights, averaged over the
/// rails.
pub fn track_weights(model: &ImportedModel, x: f64) -> Vec<(usize, f64)> {
    track_weights_at(model, ContactDirection::Vertical, x, 0.0)
        .as_slice()
        .to_vec()
}

/// The field of `components` vectors along the track rails.
pub fn track_field(
    model: &ImportedModel,
    direction: RailDirection,
    components: usize,
    value: impl Fn(usize, usize) -> f64,
) -> TrackField {
    let rails: Vec<&RailDofs> = model.track.iter().map(|&r| &model.rails[r]).collect();
    TrackField::new(
        rails
            .into_iter()
            .map(|r| r.field(direction, components, &value))
            .collect(),
    )
}

/// Free DOFs and weights of a point on the track (at most two rails of
/// four weights each), held on the stack: what [`ImportedFlexibility::green`]
/// evaluates for every pair of contacts every step.
pub struct TrackWeights {
    entries: [(usize, f64); 8],
    len: usize,
}

impl TrackWeights {
    /// The (free DOF, weight) pairs.
    pub fn as_slice(&self) -> &[(usize, f64)] {
        &self.entries[..self.len]
    }
}

/// Free DOFs and weights of the point `x` (m) along the track at `y` (m)
/// across it, in `direction`: the rule of the kept modes' values there
/// ([`TrackField::evaluate_at`] vertically — on a track of two rails a
/// point left of the centre line (y > 0) is on the first rail, one right of
/// it on the second, a point on it and every point of a one-rail track sees
/// their average; laterally the average of the rails' uy, as
/// `lateral_track`), so that Σᵢ φᵢ(c)φᵢ(d)/ωᵢ² over every mode is
/// N(c)ᵀK⁻¹N(d) exactly. No allocation.
pub fn track_weights_at(
    model: &ImportedModel,
    direction: ContactDirection,
    x: f64,
    y: f64,
) -> TrackWeights {
    let rail_direction = match direction {
        ContactDirection::Vertical => RailDirection::Vertical,
        ContactDirection::Lateral => RailDirection::Lateral,
    };
    let own_rail = direction == ContactDirection::Vertical && model.track.len() == 2 && y != 0.0;
    let (rails, share): (&[usize], f64) = if own_rail {
        let k = if y > 0.0 { 0 } else { 1 };
        (&model.track[k..=k], 1.0)
    } else {
        (&model.track, 1.0 / model.track.len() as f64)
    };
    let mut out = TrackWeights {
        entries: [(0, 0.0); 8],
        len: 0,
    };
    // A track has one or two rails (checked when the scene is loaded).
    for &r in rails.iter().take(2) {
        let mut rail = [(0, 0.0); 4];
        let len = model.rails[r].weights_into(x, rail_direction, &mut rail);
        for &(dof, w) in &rail[..len] {
            out.entries[out.len] = (dof, share * w);
            out.len += 1;
        }
    }
    out
}

/// Static flexibility between two track points, G(c, d) = N(c)ᵀK⁻¹N(d),
/// m/N, each point a direction, x along and y across the track
/// ([`track_weights_at`]).
#[derive(Debug, Clone)]
pub struct ImportedFlexibility {
    model: Arc<ImportedModel>,
    /// K⁻¹, column-major n × n.
    inverse: Vec<f64>,
    order: usize,
}

impl ImportedFlexibility {
    /// G(c, d), m/N, between the points c = (direction, x, y) and d;
    /// 0 off the track. Cost O(weights²), no allocation.
    pub fn green(&self, c: ContactPoint, d: ContactPoint) -> f64 {
        let (at, load) = (
            track_weights_at(&self.model, c.0, c.1, c.2),
            track_weights_at(&self.model, d.0, d.1, d.2),
        );
        let n = self.order;
        let mut sum = 0.0;
        for &(i, wi) in at.as_slice() {
            for &(j, wj) in load.as_slice() {
                sum += wi * self.inverse[j * n + i] * wj;
            }
        }
        // Both points are contacts: each couples to the model with its
        // entry weight at a free rail end ([`super::entry`]).
        let entry = &self.model.entry;
        if entry.is_active() {
            sum *= entry.weight(c.1).0 * entry.weight(d.1).0;
        }
        sum
    }
}
