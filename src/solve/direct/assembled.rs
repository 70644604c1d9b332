//! The assembled bridge the direct solver steps: a plane beam's sparse K
//! (N/m, N·m/rad) and consistent M (kg, kg·m²) on its free DOFs, its
//! Rayleigh damping C = c_M M + c_K K, and the interpolation N(x) of the
//! deck's deflection from the nodal DOFs (the Hermite cubics of
//! [`crate::bridge::hermite`], the very functions the modal solver's mode
//! values are interpolated with, so that φᵢ(x) = N(x)ᵀΦᵢ).

use crate::bridge::ModalBridge;
use crate::bridge::beam::BeamModel;
use crate::bridge::eigen::sparse::SymmetricSparse;
use crate::bridge::hermite::{shape_curvatures, shape_functions};
use crate::contact::ContactDirection;
use crate::solve::SolveError;

/// N(x) at one point of the deck line: the (at most four) free DOFs of the
/// element under x with the value, slope ∂/∂x (1/m) and curvature ∂²/∂x²
/// (1/m²) weights of the deflection there; DOFs a support holds carry
/// weight 0 (and index 0). All zero off the deck.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinePoint {
    /// Free DOF indices.
    pub dofs: [usize; 4],
    /// w(x) = Σ values[a] u[dofs[a]] (dimensionless for w DOFs, m for θ).
    pub values: [f64; 4],
    /// w′(x) weights, 1/m (w DOFs) or dimensionless (θ).
    pub slopes: [f64; 4],
    /// w″(x) weights, 1/m² (w DOFs) or 1/m (θ).
    pub curvatures: [f64; 4],
}

impl LinePoint {
    /// N(x)ᵀu: the deflection (m) of nodal DOFs `u` at the point.
    #[inline]
    pub fn value(&self, u: &[f64]) -> f64 {
        (0..4).map(|a| self.values[a] * u[self.dofs[a]]).sum()
    }

    /// N′(x)ᵀu, the slope of the deflection (rad).
    #[inline]
    pub fn slope(&self, u: &[f64]) -> f64 {
        (0..4).map(|a| self.slopes[a] * u[self.dofs[a]]).sum()
    }

    /// N″(x)ᵀu, the curvature of the deflection (1/m).
    #[inline]
    pub fn curvature(&self, u: &[f64]) -> f64 {
        (0..4).map(|a| self.curvatures[a] * u[self.dofs[a]]).sum()
    }

    /// Adds `force` (N, upward) · N(x) to the nodal load vector `f`.
    #[inline]
    pub fn spread(&self, force: f64, f: &mut [f64]) {
        for a in 0..4 {
            f[self.dofs[a]] += self.values[a] * force;
        }
    }
}

/// A plane beam's assembled matrices and deck line.
#[derive(Debug, Clone)]
pub struct AssembledBeam<'a> {
    /// The finite-element model (K, M, mesh, free DOFs).
    pub model: &'a BeamModel,
    /// Rayleigh damping coefficients (c_M in 1/s, c_K in s): C = c_M M + c_K K.
    pub damping: (f64, f64),
}

impl<'a> AssembledBeam<'a> {
    /// The assembled model of `bridge`.
    ///
    /// # Errors
    ///
    /// [`SolveError::Direct`] for a bridge that is not a plane beam, or
    /// whose damping no sparse C stands for (a nonzero modal ratio).
    pub fn of(bridge: &'a ModalBridge) -> Result<Self, SolveError> {
        let model = bridge.beam_model().ok_or_else(|| SolveError::Direct {
            reason: "it steps a plane beam's assembled matrices (a 3D beam, a plate or an \
                     imported model is not supported yet)"
                .into(),
        })?;
        let damping = bridge.rayleigh_damping.ok_or_else(|| SolveError::Direct {
            reason: "a modal damping ratio has no sparse damping matrix; use Rayleigh damping \
                     or none"
                .into(),
        })?;
        Ok(Self { model, damping })
    }

    /// Number of free DOFs n.
    pub fn order(&self) -> usize {
        self.model.free_dofs()
    }

    /// K, sparse on the free DOFs.
    pub fn stiffness(&self) -> &SymmetricSparse {
        &self.model.pencil.stiffness
    }

    /// M, sparse on the free DOFs.
    pub fn mass(&self) -> &SymmetricSparse {
        &self.model.pencil.mass
    }

    /// N(x) of the rail point at `x` (m) in `direction`: the deck line's
    /// for a vertical contact, all zero for a lateral one (a plane beam
    /// does not move sideways). Cost O(log nodes).
    pub fn point_in(&self, direction: ContactDirection, x: f64) -> LinePoint {
        match direction {
            ContactDirection::Vertical => self.point(x),
            ContactDirection::Lateral => LinePoint::default(),
        }
    }

    /// The free DOFs any N(x) along the deck touches, ascending (for a
    /// plane beam: every free DOF).
    pub fn line_dofs(&self) -> Vec<usize> {
        (0..self.order()).collect()
    }

    /// N(x) at `x` (m) along the deck; all zero off it. Cost O(log nodes).
    pub fn point(&self, x: f64) -> LinePoint {
        let node_x = &self.model.node_x;
        let nodes = node_x.len();
        if !(node_x[0]..=node_x[nodes - 1]).contains(&x) {
            return LinePoint::default();
        }
        let right = node_x.partition_point(|&nx| nx <= x);
        let element = right.clamp(1, nodes - 1) - 1;
        let h = node_x[element + 1] - node_x[element];
        let xi = ((x - node_x[element]) / h).clamp(0.0, 1.0);
        let (values, slopes) = shape_functions(xi, h);
        let curvatures = shape_curvatures(xi, h);
        let mut point = LinePoint::default();
        for a in 0..4 {
            if let Some(dof) = self.model.free_index[2 * element + a] {
                point.dofs[a] = dof;
                point.values[a] = values[a];
                point.slopes[a] = slopes[a];
                point.curvatures[a] = curvatures[a];
            }
        }
        point
    }
}
