//! Fields along the rails of an imported model: a wheel at x lies between
//! two rail nodes, and a mode's vertical value there is interpolated from
//! the nodes' uz (and, when the DOF map has them, ry) values.
//!
//! - With ry: the Hermite cubic of the beam element ([`crate::bridge::hermite`]),
//!   slope θ = ∂w/∂x = −ry (a right-handed rotation about +y turns +z
//!   towards +x, so a positive ry lowers the deck ahead of the node). Value,
//!   slope and curvature are those of the cubic: exact for an Euler–Bernoulli
//!   beam element's own shape functions, the interpolation the exported
//!   beam's matrices were built with.
//! - Without ry: linear between the nodes. The slope is the chord's, constant
//!   on each element, and the curvature is 0 inside every element (the
//!   kinks at the nodes are point curvatures a piecewise-linear field cannot
//!   give as a function): a solver term in ∂²φ/∂x² (v²φ″ of a wheel that
//!   follows the deck) then drops out, which is why a model with rotations
//!   should export ry.
//!
//! The direction of the field (uz today) is a parameter, so the lateral
//! field (uy, with rz as its slope: ∂v/∂x = +rz) uses the same code.

use super::super::hermite::{shape_curvatures, shape_functions};
use crate::scene::imported::RailDofs;

/// Which displacement a rail field follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RailDirection {
    /// Vertical: uz, slope −ry.
    Vertical,
    /// Lateral: uy, slope +rz (for the 3D train, issue 13).
    Lateral,
}

impl RailDofs {
    fn index(direction: RailDirection) -> usize {
        match direction {
            RailDirection::Vertical => 0,
            RailDirection::Lateral => 1,
        }
    }

    /// Sign of the rotation as the slope: θ = −ry, ∂v/∂x = +rz.
    fn slope_sign(direction: RailDirection) -> f64 {
        match direction {
            RailDirection::Vertical => -1.0,
            RailDirection::Lateral => 1.0,
        }
    }

    /// Element and local coordinate of `x` (m); `None` off the rail.
    #[inline]
    fn locate(&self, x: f64) -> Option<(usize, f64, f64)> {
        let (first, last) = (self.x[0], *self.x.last()?);
        if !(first..=last).contains(&x) {
            return None;
        }
        let nodes = self.x.len();
        let right = self.x.partition_point(|&nx| nx <= x);
        let e = right.clamp(1, nodes - 1) - 1;
        let h = self.x[e + 1] - self.x[e];
        Some((e, ((x - self.x[e]) / h).clamp(0.0, 1.0), h))
    }

    /// The free DOFs and weights giving the displacement at `x`: u(x) =
    /// Σ weight · q[dof] (also the consistent load vector of a unit point
    /// load there, by virtual work). Empty off the rail.
    pub fn weights(&self, x: f64, direction: RailDirection) -> Vec<(usize, f64)> {
        let mut out = [(0, 0.0); 4];
        let len = self.weights_into(x, direction, &mut out);
        out[..len].to_vec()
    }

    /// [`Self::weights`] into `out` without allocating (for per-step use);
    /// returns how many it wrote (0 off the rail, at most 4).
    #[inline]
    pub fn weights_into(
        &self,
        x: f64,
        direction: RailDirection,
        out: &mut [(usize, f64); 4],
    ) -> usize {
        let Some((e, xi, h)) = self.locate(x) else {
            return 0;
        };
        let d = Self::index(direction);
        let dofs = if self.hermite[d] {
            let sign = Self::slope_sign(direction);
            let (n, _) = shape_functions(xi, h);
            [
                (self.displacement[d][e], n[0]),
                (self.rotation[d][e], sign * n[1]),
                (self.displacement[d][e + 1], n[2]),
                (self.rotation[d][e + 1], sign * n[3]),
            ]
        } else {
            [
                (self.displacement[d][e], 1.0 - xi),
                (self.displacement[d][e + 1], xi),
                (None, 0.0),
                (None, 0.0),
            ]
        };
        let mut len = 0;
        for (dof, w) in dofs {
            if let Some(dof) = dof {
                out[len] = (dof, w);
                len += 1;
            }
        }
        len
    }

    /// The field of `components` vectors along this rail: `value(dof, c)`
    /// reads component c at free DOF `dof`.
    pub fn field(
        &self,
        direction: RailDirection,
        components: usize,
        value: impl Fn(usize, usize) -> f64,
    ) -> RailField {
        self.field_with_constrained(direction, components, value, |_, _| 0.0)
    }

    /// [`Self::field`] with `constrained(node, slot)` the value at a
    /// node's DOF that is not free (slot 0 the displacement, 1 the
    /// rotation, before the slope's sign), 0 in [`Self::field`]: a
    /// support reaction's influence line is 1 at its own constrained DOF.
    pub fn field_with_constrained(
        &self,
        direction: RailDirection,
        components: usize,
        value: impl Fn(usize, usize) -> f64,
        constrained: impl Fn(u64, usize) -> f64,
    ) -> RailField {
        let d = Self::index(direction);
        let sign = Self::slope_sign(direction);
        let nodes = self.x.len();
        let mut nodal = vec![0.0; nodes * 2 * components];
        for n in 0..nodes {
            let node = self.nodes[n];
            for c in 0..components {
                nodal[2 * n * components + c] =
                    self.displacement[d][n].map_or_else(|| constrained(node, 0), |i| value(i, c));
                nodal[(2 * n + 1) * components + c] = sign
                    * self.rotation[d][n].map_or_else(|| constrained(node, 1), |i| value(i, c));
            }
        }
        RailField {
            x: self.x.clone(),
            components,
            hermite: self.hermite[d],
            nodal,
        }
    }
}

/// Nodal values (and slopes) of some components along one rail.
#[derive(Debug, Clone)]
pub struct RailField {
    x: Vec<f64>,
    components: usize,
    hermite: bool,
    /// `[node][w, θ][component]`.
    nodal: Vec<f64>,
}

impl RailField {
    /// Node positions, m.
    pub fn node_x(&self) -> &[f64] {
        &self.x
    }

    /// Adds `weight` × (value, slope, curvature) of every component at `x`
    /// (m) to the outputs (`slopes`/`curvatures` may be empty to skip them);
    /// nothing off the rail.
    #[inline]
    pub fn accumulate(
        &self,
        x: f64,
        weight: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        let nodes = self.x.len();
        if !(self.x[0]..=self.x[nodes - 1]).contains(&x) {
            return;
        }
        let right = self.x.partition_point(|&nx| nx <= x);
        let e = right.clamp(1, nodes - 1) - 1;
        let h = self.x[e + 1] - self.x[e];
        let xi = ((x - self.x[e]) / h).clamp(0.0, 1.0);
        let k = self.components;
        let block = &self.nodal[2 * e * k..2 * (e + 2) * k];
        let (wa, ta, wb, tb) = (
            &block[..k],
            &block[k..2 * k],
            &block[2 * k..3 * k],
            &block[3 * k..],
        );
        if self.hermite {
            let (n, s) = shape_functions(xi, h);
            let c = shape_curvatures(xi, h);
            for i in 0..k {
                values[i] += weight * (n[0] * wa[i] + n[1] * ta[i] + n[2] * wb[i] + n[3] * tb[i]);
            }
            for (i, out) in slopes.iter_mut().enumerate() {
                *out += weight * (s[0] * wa[i] + s[1] * ta[i] + s[2] * wb[i] + s[3] * tb[i]);
            }
            for (i, out) in curvatures.iter_mut().enumerate() {
                *out += weight * (c[0] * wa[i] + c[1] * ta[i] + c[2] * wb[i] + c[3] * tb[i]);
            }
        } else {
            for i in 0..k {
                values[i] += weight * ((1.0 - xi) * wa[i] + xi * wb[i]);
            }
            for (i, out) in slopes.iter_mut().enumerate() {
                *out += weight * (wb[i] - wa[i]) / h;
            }
            // Curvature 0 inside a linear element (module doc).
        }
    }
}

/// What the vehicles see: the average of the rails they run on (one rail,
/// or the two rails of a single-track 2D vehicle, each carrying half).
#[derive(Debug, Clone)]
pub struct TrackField {
    rails: Vec<RailField>,
}

impl TrackField {
    /// The average of `rails`.
    pub fn new(rails: Vec<RailField>) -> Self {
        Self { rails }
    }

    /// Node positions of the first rail, m.
    pub fn node_x(&self) -> &[f64] {
        self.rails[0].node_x()
    }

    /// Value, slope and curvature of every component at `x` (m); the
    /// outputs are overwritten (zero off the track). `slopes` and
    /// `curvatures` may be empty.
    #[inline]
    pub fn evaluate(&self, x: f64, values: &mut [f64], slopes: &mut [f64], curvatures: &mut [f64]) {
        values.fill(0.0);
        slopes.fill(0.0);
        curvatures.fill(0.0);
        let weight = 1.0 / self.rails.len() as f64;
        for rail in &self.rails {
            rail.accumulate(x, weight, values, slopes, curvatures);
        }
    }

    /// [`Self::evaluate`] for a point `y` (m) across the track: on a track
    /// of two rails, the first (`track[0]`) is the left one (+y), the second
    /// the right one, so a wheel off the centre line (a `train_3d`'s
    /// vertical contact, a truck's wheel) follows its own rail; a point on
    /// the centre line (y = 0: a single-track vehicle, a record) sees the
    /// average, as does every point of a one-rail track.
    #[inline]
    pub fn evaluate_at(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        if self.rails.len() != 2 || y == 0.0 {
            return self.evaluate(x, values, slopes, curvatures);
        }
        values.fill(0.0);
        slopes.fill(0.0);
        curvatures.fill(0.0);
        let rail = if y > 0.0 { 0 } else { 1 };
        self.rails[rail].accumulate(x, 1.0, values, slopes, curvatures);
    }

    /// Whether points off the centre line see other values than the
    /// centre line's (two rails).
    pub fn has_two_rails(&self) -> bool {
        self.rails.len() == 2
    }

    /// Value of component 0 at `x` (m).
    pub fn value_at(&self, x: f64) -> f64 {
        let mut v = [0.0];
        self.evaluate(x, &mut v, &mut [], &mut []);
        v[0]
    }
}
