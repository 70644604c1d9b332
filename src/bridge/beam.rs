//! Euler–Bernoulli beam bridge: Hermite-cubic finite elements, pinned supports.
//!
//! Element matrices (Przemieniecki §11; Cook et al., Concepts and
//! Applications of FEA, eq. 2.3-5 and 11.3-5) for length h, dofs (wₐ, θₐ, w_b, θ_b):
//! K_e = EI/h³ [[12, 6h, −12, 6h], [6h, 4h², −6h, 2h²], [−12, −6h, 12, −6h], [6h, 2h², −6h, 4h²]],
//! M_e = m h/420 [[156, 22h, 54, −13h], [22h, 4h², 13h, −3h²], [54, 13h, 156, −22h], [−13h, −3h², −22h, 4h²]].
//! Supports fix w at the ends and between spans; rotations stay free.

use faer::Mat;

use super::hermite::HermiteField;
use super::{BridgeError, eigen};
use crate::scenario::resolved::Beam;

/// Assembled beam finite-element model with the support conditions applied.
#[derive(Debug, Clone)]
pub struct BeamModel {
    /// Node positions, m.
    pub node_x: Vec<f64>,
    /// For each global dof (2 per node: w then θ), its index among the free
    /// dofs, or `None` where a support fixes it.
    pub free_index: Vec<Option<usize>>,
    /// Stiffness on the free dofs, N/m (N·m/rad for rotations).
    pub stiffness: Mat<f64>,
    /// Consistent mass on the free dofs, kg.
    pub mass: Mat<f64>,
}

impl BeamModel {
    /// Meshes and assembles the beam. Cost O(dofs²) memory (dense storage is
    /// fine up to a few thousand dofs, i.e. ~50 spans of 20 elements).
    pub fn new(beam: &Beam) -> Self {
        let elements_per_span = beam.elements_per_span;
        let mut node_x = vec![0.0];
        let mut supported = vec![true];
        let mut start = 0.0;
        for &span in &beam.spans {
            for e in 1..=elements_per_span {
                node_x.push(start + span * e as f64 / elements_per_span as f64);
                supported.push(e == elements_per_span);
            }
            start += span;
        }
        let nodes = node_x.len();
        let mut free_index = vec![None; 2 * nodes];
        let mut free = 0;
        for n in 0..nodes {
            if !supported[n] {
                free_index[2 * n] = Some(free);
                free += 1;
            }
            free_index[2 * n + 1] = Some(free);
            free += 1;
        }
        let mut stiffness = Mat::<f64>::zeros(free, free);
        let mut mass = Mat::<f64>::zeros(free, free);
        let (ei, m) = (beam.bending_stiffness, beam.mass_per_length);
        for e in 0..nodes - 1 {
            let h = node_x[e + 1] - node_x[e];
            let ke = element_stiffness(ei, h);
            let me = element_mass(m, h);
            let dofs = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3];
            for (a, &ga) in dofs.iter().enumerate() {
                let Some(ia) = free_index[ga] else { continue };
                for (b, &gb) in dofs.iter().enumerate() {
                    let Some(ib) = free_index[gb] else { continue };
                    stiffness[(ia, ib)] += ke[a][b];
                    mass[(ia, ib)] += me[a][b];
                }
            }
        }
        Self {
            node_x,
            free_index,
            stiffness,
            mass,
        }
    }

    /// Number of free dofs, which is also the number of modes available.
    pub fn free_dofs(&self) -> usize {
        self.stiffness.nrows()
    }

    /// Number of free dofs for a beam without building it.
    pub fn free_dofs_of(beam: &Beam) -> usize {
        let nodes = beam.spans.len() * beam.elements_per_span + 1;
        2 * nodes - (beam.spans.len() + 1)
    }

    /// All natural modes: circular frequencies ω (rad/s, ascending) and the
    /// mass-normalised eigenvectors (φᵀMφ = 1) on the free dofs, one per column.
    pub fn eigen(&self) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
        let (eigenvalues, vectors) = eigen::generalized_symmetric(&self.stiffness, &self.mass)?;
        let omegas = eigenvalues.iter().map(|&l| l.max(0.0).sqrt()).collect();
        Ok((omegas, vectors))
    }

    /// The first `count` eigenvectors as Hermite fields over the mesh.
    pub fn shapes(&self, vectors: &Mat<f64>, count: usize) -> HermiteField {
        HermiteField::from_fn(self.node_x.clone(), count, |n, c| {
            let w = self.free_index[2 * n].map_or(0.0, |i| vectors[(i, c)]);
            let theta = self.free_index[2 * n + 1].map_or(0.0, |i| vectors[(i, c)]);
            (w, theta)
        })
    }

    /// Static deflection influence line of the point `x_point` (m): the field
    /// G(ξ) = deflection at `x_point` due to a unit downward load at ξ, m/N
    /// (positive = downward). By Maxwell's reciprocity it is the deflected
    /// shape under a unit load at `x_point`: u = K⁻¹ N(x_point), exact at the
    /// nodes for a uniform Euler–Bernoulli element.
    pub fn influence_line(&self, x_point: f64) -> Result<HermiteField, BridgeError> {
        let free = self.free_dofs();
        let mut load = Mat::<f64>::zeros(free, 1);
        // Consistent load vector of a unit point load: the element's shape
        // functions evaluated at the load point.
        let nodes = self.node_x.len();
        let right = self.node_x.partition_point(|&nx| nx <= x_point);
        let element = right.clamp(1, nodes - 1) - 1;
        let h = self.node_x[element + 1] - self.node_x[element];
        let xi = ((x_point - self.node_x[element]) / h).clamp(0.0, 1.0);
        let (n, _) = super::hermite::shape_functions(xi, h);
        for (a, &na) in n.iter().enumerate() {
            if let Some(i) = self.free_index[2 * element + a] {
                load[(i, 0)] += na;
            }
        }
        let solution = eigen::solve_spd(&self.stiffness, load)?;
        Ok(HermiteField::from_fn(self.node_x.clone(), 1, |n, _| {
            let w = self.free_index[2 * n].map_or(0.0, |i| solution[(i, 0)]);
            let theta = self.free_index[2 * n + 1].map_or(0.0, |i| solution[(i, 0)]);
            (w, theta)
        }))
    }
}

fn element_stiffness(ei: f64, h: f64) -> [[f64; 4]; 4] {
    let c = ei / (h * h * h);
    let h2 = h * h;
    [
        [12.0 * c, 6.0 * h * c, -12.0 * c, 6.0 * h * c],
        [6.0 * h * c, 4.0 * h2 * c, -6.0 * h * c, 2.0 * h2 * c],
        [-12.0 * c, -6.0 * h * c, 12.0 * c, -6.0 * h * c],
        [6.0 * h * c, 2.0 * h2 * c, -6.0 * h * c, 4.0 * h2 * c],
    ]
}

fn element_mass(m: f64, h: f64) -> [[f64; 4]; 4] {
    let c = m * h / 420.0;
    let h2 = h * h;
    [
        [156.0 * c, 22.0 * h * c, 54.0 * c, -13.0 * h * c],
        [22.0 * h * c, 4.0 * h2 * c, 13.0 * h * c, -3.0 * h2 * c],
        [54.0 * c, 13.0 * h * c, 156.0 * c, -22.0 * h * c],
        [-13.0 * h * c, -3.0 * h2 * c, -22.0 * h * c, 4.0 * h2 * c],
    ]
}
