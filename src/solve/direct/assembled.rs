//! The assembled bridge the direct solver steps: the sparse K (N/m,
//! N·m/rad) and M (kg, kg·m²) on the free DOFs of a plane beam or an
//! imported model, its Rayleigh damping C = c_M M + c_K K, and the
//! interpolation N(x) of a rail point's displacement from the nodal DOFs:
//! on a beam the Hermite cubics of [`crate::bridge::hermite`], on an
//! imported track its rails' Hermite (with ry / rz) or linear fields
//! ([`crate::bridge::fe_import::track`]), the very functions the modal
//! solver's mode values are interpolated with, so that φᵢ(x) = N(x)ᵀΦᵢ.

use crate::bridge::ModalBridge;
use crate::bridge::beam::BeamModel;
use crate::bridge::eigen::sparse::SymmetricSparse;
use crate::bridge::fe_import::modal::ImportedShapes;
use crate::bridge::hermite::{shape_curvatures, shape_functions};
use crate::contact::ContactDirection;
use crate::scene::imported::RailDofs;
use crate::solve::SolveError;

/// Most free DOFs one point's N touches: four per rail element, two rails.
pub const POINT_DOFS: usize = 8;

/// N(x) at one rail point: the free DOFs of the element(s) under x with
/// the value, slope ∂/∂x (1/m) and curvature ∂²/∂x² (1/m²) weights of the
/// displacement there; DOFs a support holds carry weight 0 (and index 0).
/// All zero off the deck.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinePoint {
    /// Free DOF indices.
    pub dofs: [usize; POINT_DOFS],
    /// w(x) = Σ values[a] u[dofs[a]] (dimensionless for displacement DOFs, m for rotations).
    pub values: [f64; POINT_DOFS],
    /// w′(x) weights, 1/m (displacement DOFs) or dimensionless (rotations).
    pub slopes: [f64; POINT_DOFS],
    /// w″(x) weights, 1/m² (displacement DOFs) or 1/m (rotations).
    pub curvatures: [f64; POINT_DOFS],
}

impl LinePoint {
    /// N(x)ᵀu: the displacement (m) of nodal DOFs `u` at the point.
    #[inline]
    pub fn value(&self, u: &[f64]) -> f64 {
        (0..POINT_DOFS)
            .map(|a| self.values[a] * u[self.dofs[a]])
            .sum()
    }

    /// The point of one free DOF itself: N = e_dof (an imported model's
    /// node record).
    pub fn of_dof(dof: usize) -> Self {
        let mut point = Self::default();
        point.dofs[0] = dof;
        point.values[0] = 1.0;
        point
    }

    /// N′(x)ᵀu, the slope of the displacement (rad).
    #[inline]
    pub fn slope(&self, u: &[f64]) -> f64 {
        (0..POINT_DOFS)
            .map(|a| self.slopes[a] * u[self.dofs[a]])
            .sum()
    }

    /// N″(x)ᵀu, the curvature of the displacement (1/m).
    #[inline]
    pub fn curvature(&self, u: &[f64]) -> f64 {
        (0..POINT_DOFS)
            .map(|a| self.curvatures[a] * u[self.dofs[a]])
            .sum()
    }

    /// Adds `force` (N, in the point's direction) · N(x) to the nodal load `f`.
    #[inline]
    pub fn spread(&self, force: f64, f: &mut [f64]) {
        for a in 0..POINT_DOFS {
            f[self.dofs[a]] += self.values[a] * force;
        }
    }

    /// Sets entry `a` to free DOF `dof` (if free) with weight `share` ×
    /// (value, slope, curvature).
    #[inline]
    fn set(&mut self, a: usize, dof: Option<usize>, share: f64, weights: [f64; 3]) {
        if let Some(dof) = dof {
            self.dofs[a] = dof;
            self.values[a] = share * weights[0];
            self.slopes[a] = share * weights[1];
            self.curvatures[a] = share * weights[2];
        }
    }
}

/// Where N(x) comes from.
#[derive(Debug, Clone, Copy)]
enum Line<'a> {
    Beam(&'a BeamModel),
    Imported(&'a ImportedShapes),
}

/// A bridge's assembled matrices and rail lines.
#[derive(Debug, Clone, Copy)]
pub struct AssembledBridge<'a> {
    line: Line<'a>,
    stiffness: &'a SymmetricSparse,
    mass: &'a SymmetricSparse,
    /// Rayleigh damping coefficients (c_M in 1/s, c_K in s): C = c_M M + c_K K.
    pub damping: (f64, f64),
}

/// Why the direct solver cannot hold the bridge.
fn refused(reason: &str) -> SolveError {
    SolveError::Direct {
        reason: reason.into(),
    }
}

impl<'a> AssembledBridge<'a> {
    /// The assembled model of `bridge`.
    ///
    /// # Errors
    ///
    /// [`SolveError::Direct`] for a 3D beam or a plate, or damping that no
    /// C = c_M M + c_K K stands for (a nonzero modal ratio, a damping
    /// matrix file).
    pub fn of(bridge: &'a ModalBridge) -> Result<Self, SolveError> {
        let line = match (bridge.beam_model(), bridge.imported_shapes()) {
            (Some(beam), _) => Line::Beam(beam),
            (None, Some(imported)) => Line::Imported(imported),
            (None, None) => {
                return Err(refused(
                    "it steps a plane beam's or an imported model's assembled matrices (a 3D \
                     beam or a plate is not supported yet)",
                ));
            }
        };
        let damping = bridge.rayleigh_damping.ok_or_else(|| {
            refused(
                "a modal damping ratio (or a damping matrix file) is not a Rayleigh damping \
                 c_M M + c_K K; use Rayleigh damping or none",
            )
        })?;
        let pencil = match line {
            Line::Beam(beam) => &beam.pencil,
            Line::Imported(imported) => &imported.pencil,
        };
        Ok(Self {
            line,
            stiffness: &pencil.stiffness,
            mass: &pencil.mass,
            damping,
        })
    }

    /// Number of free DOFs n.
    pub fn order(&self) -> usize {
        self.stiffness.nrows()
    }

    /// K, sparse on the free DOFs.
    pub fn stiffness(&self) -> &'a SymmetricSparse {
        self.stiffness
    }

    /// M, sparse on the free DOFs.
    pub fn mass(&self) -> &'a SymmetricSparse {
        self.mass
    }

    /// The free DOFs any N touches, ascending: every free DOF of a plane
    /// beam, the rails' displacement and rotation DOFs of an imported track.
    pub fn line_dofs(&self) -> Vec<usize> {
        self.line_dofs_along().0
    }

    /// [`Self::line_dofs`] with their positions along the line: a plane
    /// beam's in DOF order without positions (`None`); an imported track's
    /// rail DOFs sorted by their node's x (m; then by DOF), the order in
    /// which a banded contact flexibility keeps them
    /// ([`super::line_flexibility`]).
    pub fn line_dofs_along(&self) -> (Vec<usize>, Option<Vec<f64>>) {
        match self.line {
            Line::Beam(_) => ((0..self.order()).collect(), None),
            Line::Imported(imported) => {
                let model = &imported.model;
                let mut along: Vec<(f64, usize)> = model
                    .track
                    .iter()
                    .flat_map(|&r| {
                        let rail = &model.rails[r];
                        rail.displacement
                            .iter()
                            .chain(&rail.rotation)
                            .flat_map(move |dofs| {
                                dofs.iter()
                                    .zip(&rail.x)
                                    .filter_map(|(dof, &x)| dof.map(|d| (x, d)))
                            })
                    })
                    .collect();
                along.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
                let mut seen = vec![false; self.order()];
                along.retain(|&(_, d)| !std::mem::replace(&mut seen[d], true));
                let positions = along.iter().map(|a| a.0).collect();
                (along.into_iter().map(|a| a.1).collect(), Some(positions))
            }
        }
    }

    /// M δ on the free DOFs (kg): the inertia load per unit support
    /// acceleration in `direction` (δ = 1 on every DOF of that direction,
    /// the supports' included, as the modal participation factors
    /// Γ = Φᵀ M δ of [`crate::bridge::ground`]). A beam's vertical one is
    /// the consistent load of its weight per g, m ∫N dx, element by element
    /// m h [1/2, h/12, 1/2, −h/12] on (wₐ, θₐ, w_b, θ_b); a plane beam has
    /// no lateral one (zeros); an imported model's are its
    /// `vertical_inertia` and `lateral_inertia`.
    pub fn ground_inertia(&self, direction: ContactDirection) -> Vec<f64> {
        match (self.line, direction) {
            (Line::Beam(beam), ContactDirection::Vertical) => {
                let mut inertia = vec![0.0; self.order()];
                let m = beam.mass_per_length;
                for (e, pair) in beam.node_x.windows(2).enumerate() {
                    let h = pair[1] - pair[0];
                    let element = [
                        0.5 * m * h,
                        m * h * h / 12.0,
                        0.5 * m * h,
                        -m * h * h / 12.0,
                    ];
                    for (a, load) in element.into_iter().enumerate() {
                        if let Some(i) = beam.free_index[2 * e + a] {
                            inertia[i] += load;
                        }
                    }
                }
                inertia
            }
            (Line::Beam(_), ContactDirection::Lateral) => vec![0.0; self.order()],
            (Line::Imported(imported), ContactDirection::Vertical) => {
                imported.model.vertical_inertia.clone()
            }
            (Line::Imported(imported), ContactDirection::Lateral) => {
                imported.model.lateral_inertia.clone()
            }
        }
    }

    /// N of the rail point at `x` (m) along the deck and `y` (m) across it
    /// in `direction`, as the modal solver's mode values there: on a beam
    /// the deck line (all zero laterally: a plane beam does not move
    /// sideways); on an imported track a vertical contact off the centre
    /// line of a two-rail track on its own rail, any other the rails'
    /// average ([`crate::bridge::fe_import::modal::track_weights_at`]). All
    /// zero off the deck. Cost O(log nodes).
    pub fn point_in(&self, direction: ContactDirection, x: f64, y: f64) -> LinePoint {
        match self.line {
            Line::Beam(beam) => match direction {
                ContactDirection::Vertical => beam_point(beam, x),
                ContactDirection::Lateral => LinePoint::default(),
            },
            Line::Imported(imported) => {
                let model = &imported.model;
                let own_rail =
                    direction == ContactDirection::Vertical && model.track.len() == 2 && y != 0.0;
                let (rails, share): (&[usize], f64) = if own_rail {
                    let k = if y > 0.0 { 0 } else { 1 };
                    (&model.track[k..=k], 1.0)
                } else {
                    (&model.track, 1.0 / model.track.len() as f64)
                };
                let mut point = LinePoint::default();
                for (k, &r) in rails.iter().take(2).enumerate() {
                    rail_point(&model.rails[r], direction, x, share, 4 * k, &mut point);
                }
                point
            }
        }
    }

    /// N of the deck's vertical displacement at `x` (m) on the centre line
    /// (y = 0).
    pub fn point(&self, x: f64) -> LinePoint {
        self.point_in(ContactDirection::Vertical, x, 0.0)
    }

    /// [`Self::point_in`] as a wheel's contact (or a moving load) at (x, y)
    /// sees it: on an imported track with free rail ends, times the entry
    /// weight s(x) ([`crate::bridge::fe_import::entry`]: the weights of
    /// s·N, s·N′ + s′·N and s·N″ + 2s′·N′ + s″·N), as the modal solver's
    /// contact mode values; elsewhere the same.
    pub fn contact_point(&self, direction: ContactDirection, x: f64, y: f64) -> LinePoint {
        let mut point = self.point_in(direction, x, y);
        if let Line::Imported(imported) = self.line {
            let entry = &imported.model.entry;
            if entry.is_active() {
                let (s, ds, dds) = entry.weight(x);
                if !(s == 1.0 && ds == 0.0 && dds == 0.0) {
                    for a in 0..POINT_DOFS {
                        let (v, d, c) = (point.values[a], point.slopes[a], point.curvatures[a]);
                        point.curvatures[a] = s * c + 2.0 * ds * d + dds * v;
                        point.slopes[a] = s * d + ds * v;
                        point.values[a] = v * s;
                    }
                }
            }
        }
        point
    }
}

/// The element under `x` (m) of nodes at `node_x` and its local
/// coordinate ξ and length h (m); `None` off the nodes. The element search
/// of [`crate::bridge::hermite`] and of the rails' fields.
fn locate(node_x: &[f64], x: f64) -> Option<(usize, f64, f64)> {
    let nodes = node_x.len();
    if !(node_x[0]..=node_x[nodes - 1]).contains(&x) {
        return None;
    }
    let right = node_x.partition_point(|&nx| nx <= x);
    let e = right.clamp(1, nodes - 1) - 1;
    let h = node_x[e + 1] - node_x[e];
    Some((e, ((x - node_x[e]) / h).clamp(0.0, 1.0), h))
}

/// The Hermite (value, slope, curvature) weights at ξ of an element of
/// length `h` (m), for (wₐ, θₐ, w_b, θ_b).
fn hermite_weights(xi: f64, h: f64) -> [[f64; 3]; 4] {
    let (n, s) = shape_functions(xi, h);
    let c = shape_curvatures(xi, h);
    std::array::from_fn(|a| [n[a], s[a], c[a]])
}

/// N of a plane beam's deflection at `x` (m).
fn beam_point(beam: &BeamModel, x: f64) -> LinePoint {
    let mut point = LinePoint::default();
    let Some((e, xi, h)) = locate(&beam.node_x, x) else {
        return point;
    };
    for (a, weights) in hermite_weights(xi, h).into_iter().enumerate() {
        point.set(a, beam.free_index[2 * e + a], 1.0, weights);
    }
    point
}

/// Adds `rail`'s N at `x` (m) in `direction`, times `share`, into entries
/// `first..first + 4` of `point`: Hermite with the slope rotation (θ = −ry
/// vertically, +rz laterally), else linear (curvature 0 inside an element),
/// as [`crate::bridge::fe_import::track`].
fn rail_point(
    rail: &RailDofs,
    direction: ContactDirection,
    x: f64,
    share: f64,
    first: usize,
    point: &mut LinePoint,
) {
    let Some((e, xi, h)) = locate(&rail.x, x) else {
        return;
    };
    let (d, sign) = match direction {
        ContactDirection::Vertical => (0, -1.0),
        ContactDirection::Lateral => (1, 1.0),
    };
    let (u, r) = (&rail.displacement[d], &rail.rotation[d]);
    if rail.hermite[d] {
        let [wa, ta, wb, tb] = hermite_weights(xi, h);
        let signed = |w: [f64; 3]| w.map(|v| sign * v);
        point.set(first, u[e], share, wa);
        point.set(first + 1, r[e], share, signed(ta));
        point.set(first + 2, u[e + 1], share, wb);
        point.set(first + 3, r[e + 1], share, signed(tb));
    } else {
        point.set(first, u[e], share, [1.0 - xi, -1.0 / h, 0.0]);
        point.set(first + 2, u[e + 1], share, [xi, 1.0 / h, 0.0]);
    }
}
