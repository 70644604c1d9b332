//! The line reactions of the plate deck's supports (issue 40.1): the whole
//! force a support line across the deck carries, N, from virtual work.
//!
//! Let v_c(x) be the Hermite interpolant, on the longitudinal mesh, of the
//! piecewise-linear "hat" that is 1 at support c and 0 at every other
//! support (at a support node its slope is the mean of the hat's slopes
//! either side), taken uniform across the deck. It is admissible but for
//! its value at c, so virtual work with δw = v_c gives the reaction of
//! line c exactly:
//!
//! R_c = a(w, v_c) + ∫∫ ρh ẅ v_c dA + Σ_w F_w v_c(ξ_w),
//!
//! with a(w, v) = ∫∫ [Dx w_xx v_xx + D1 w_yy v_xx] dA the strain energy's
//! bilinear form (v_yy = v_xy = 0) and F_w the wheels' downward forces. On
//! the Ritz basis XᵢYⱼ, a(Ψ_r, v_c) = Dx (∫Xᵢ'' v_c'' dx)(∫Yⱼ dy)
//! − D1 (∫Xᵢ' v_c' dx)(∫Yⱼ'' dy) (∫Xᵢ v'' = −∫Xᵢ' v' as Xᵢ = 0 at the deck
//! ends), the x integrals exact from the element matrices (v_c and Xᵢ are
//! both Hermite cubics on the mesh). a(w, v_c) is a linear functional of w
//! like a moment, so it gets the same mode-acceleration split as
//! [`super::moments`] (exact Ritz statics plus the modes' dynamic share).
//!
//! The hats sum to 1, so Σ_c v_c = 1 exactly and a(w, Σ v_c) = 0 for every
//! w: Σ_c R_c = Σ_w F_w + ∫∫ ρh ẅ dA to round-off, whatever modes are kept.
//! Simply supported longitudinal edges carry part of the load themselves,
//! which a uniform v_c would mix in: reactions are given for free edges.

use super::PlateModes;
use super::element_slope_products;
use super::moments::PlateMomentProbe;
use crate::bridge::BridgeError;
use crate::bridge::beam::{element_mass, element_stiffness};
use crate::bridge::hermite::shape_functions;

/// One support line's reaction.
#[derive(Debug, Clone)]
pub struct PlateReactionProbe {
    /// a(w, v_c) as a moment-like functional: its modal values, static
    /// modal part and full-stiffness influence lines.
    pub elastic: PlateMomentProbe,
    /// ∫∫ ρh φₘ v_c dA per kept mode, kg/√kg: the inertia share per unit
    /// modal acceleration.
    pub inertia: Vec<f64>,
    /// v_c's nodal (w, θ) on the longitudinal mesh.
    hat: Vec<(f64, f64)>,
    /// The mesh, m.
    node_x: Vec<f64>,
}

impl PlateModes {
    /// The reaction probe of the support line at `x` (m) among `supports`
    /// (every support position, m, ascending), for wheels along `line_y`
    /// (m) and the kept modes' `circular_frequencies` (rad/s). `None` if x
    /// is not a support node. Cost O(N²) per wheel line (one solve).
    pub fn reaction_probe(
        &self,
        x: f64,
        supports: &[f64],
        circular_frequencies: &[f64],
        line_y: &[f64],
    ) -> Result<Option<PlateReactionProbe>, BridgeError> {
        let node_x = self.node_x().to_vec();
        let tolerance = 1e-9 * (1.0 + self.length);
        let Some(c) = supports.iter().position(|s| (s - x).abs() <= tolerance) else {
            return Ok(None);
        };
        let hat = hat_nodal(&node_x, supports, c);
        let (nx, ny, terms) = (
            self.longitudinal_terms,
            self.transverse_terms,
            self.available(),
        );
        // x integrals of each Xᵢ against v_c: ∫Xᵢ''v'', ∫Xᵢ'v', ∫Xᵢv.
        let mut x_integrals = vec![[0.0; 3]; nx];
        for e in 0..node_x.len() - 1 {
            let v = [hat[e].0, hat[e].1, hat[e + 1].0, hat[e + 1].1];
            if v.iter().all(|&a| a == 0.0) {
                continue;
            }
            let h = node_x[e + 1] - node_x[e];
            let matrices = [
                element_stiffness(1.0, h),
                element_slope_products(h),
                element_mass(1.0, h),
            ];
            for (i, out) in x_integrals.iter_mut().enumerate() {
                let (wa, ta) = self.beam_functions.nodal(e, i);
                let (wb, tb) = self.beam_functions.nodal(e + 1, i);
                let phi = [wa, ta, wb, tb];
                for (k, matrix) in matrices.iter().enumerate() {
                    let mut sum = 0.0;
                    for a in 0..4 {
                        for b in 0..4 {
                            sum += phi[a] * matrix[a][b] * v[b];
                        }
                    }
                    out[k] += sum;
                }
            }
        }
        // y integrals ∫Yⱼ dy (Gauss–Legendre, exact for the basis) and
        // ∫Yⱼ'' dy = Yⱼ'(b) − Yⱼ'(0).
        let (y_integral, y_curvature) = self.transverse_integrals();
        let (dx, _, d1, _) = self.rigidities;
        let mut basis = vec![0.0; terms];
        let mut inertia_basis = vec![0.0; terms];
        for (i, x) in x_integrals.iter().enumerate() {
            for j in 0..ny {
                let r = i * ny + j;
                basis[r] = dx * x[0] * y_integral[j] - d1 * x[1] * y_curvature[j];
                inertia_basis[r] = self.mass_per_area * x[2] * y_integral[j];
            }
        }
        Ok(Some(PlateReactionProbe {
            elastic: self.functional_probe(&basis, circular_frequencies, line_y)?,
            inertia: self.modal_values(&inertia_basis),
            hat,
            node_x,
        }))
    }

    /// (∫₀ᵇ Yⱼ dy, ∫₀ᵇ Yⱼ'' dy) for j < Ny: Gauss–Legendre with Ny + 1
    /// points on each of 4 panels (exact for the Legendre basis; the sines
    /// to round-off).
    fn transverse_integrals(&self) -> (Vec<f64>, Vec<f64>) {
        let ny = self.transverse_terms;
        let mut integral = vec![0.0; ny];
        let (points, weights) = super::transverse::gauss_legendre(ny + 1);
        let panels = 4;
        let panel = self.width / panels as f64;
        for p in 0..panels {
            for (t, w) in points.iter().zip(&weights) {
                let y = panel * (p as f64 + 0.5 * (t + 1.0));
                self.transverse.for_each(self.width, ny, y, |j, yj| {
                    integral[j] += 0.5 * panel * w * yj[0];
                });
            }
        }
        let mut curvature = vec![0.0; ny];
        self.transverse
            .for_each(self.width, ny, self.width, |j, yj| curvature[j] += yj[1]);
        self.transverse
            .for_each(self.width, ny, 0.0, |j, yj| curvature[j] -= yj[1]);
        (integral, curvature)
    }
}

/// The nodal (w, θ) of support `c`'s hat on the mesh `node_x` (module
/// doc): on the span ending at c it rises linearly to 1, on the span
/// starting there it falls to 0, elsewhere it is 0; at a support node the
/// slope is the mean of the two sides (one-sided at the deck's ends), so
/// that the hats of all supports sum to 1 in value and slope at every node.
fn hat_nodal(node_x: &[f64], supports: &[f64], c: usize) -> Vec<(f64, f64)> {
    let s = supports;
    let last = s.len() - 1;
    // (value, slope) of the hat restricted to span k = [s[k], s[k + 1]].
    let in_span = |k: usize, x: f64| -> (f64, f64) {
        let l = s[k + 1] - s[k];
        if k + 1 == c {
            ((x - s[k]) / l, 1.0 / l)
        } else if k == c {
            ((s[k + 1] - x) / l, -1.0 / l)
        } else {
            (0.0, 0.0)
        }
    };
    let tolerance = 1e-9 * (1.0 + s[last].abs());
    node_x
        .iter()
        .map(
            |&x| match s.iter().position(|&p| (p - x).abs() <= tolerance) {
                Some(j) => {
                    let left = (j > 0).then(|| in_span(j - 1, s[j]));
                    let right = (j < last).then(|| in_span(j, s[j]));
                    match (left, right) {
                        (Some(a), Some(b)) => (a.0, 0.5 * (a.1 + b.1)),
                        (Some(a), None) => a,
                        (None, Some(b)) => b,
                        (None, None) => (0.0, 0.0),
                    }
                }
                None => {
                    let k = s.partition_point(|&p| p <= x).clamp(1, last) - 1;
                    in_span(k, x)
                }
            },
        )
        .collect()
}

impl PlateReactionProbe {
    /// v_c at `x` (m): the share of a load there that the line takes
    /// without bending (the statics of its two spans).
    pub fn hat_at(&self, x: f64) -> f64 {
        let n = self.node_x.len();
        if !(self.node_x[0]..=self.node_x[n - 1]).contains(&x) {
            return 0.0;
        }
        let right = self.node_x.partition_point(|&nx| nx <= x);
        let e = right.clamp(1, n - 1) - 1;
        let h = self.node_x[e + 1] - self.node_x[e];
        let (s, _) = shape_functions(((x - self.node_x[e]) / h).clamp(0.0, 1.0), h);
        s[0] * self.hat[e].0
            + s[1] * self.hat[e].1
            + s[2] * self.hat[e + 1].0
            + s[3] * self.hat[e + 1].1
    }

    /// The exact (full Ritz stiffness) static reaction, N, under downward
    /// `forces` (N) of the wheels `on_deck` at `positions` (m) on the wheel
    /// lines `line_of`. Cost O(wheels).
    pub fn static_reaction(
        &self,
        positions: &[f64],
        forces: &[f64],
        line_of: &[usize],
        on_deck: &[usize],
    ) -> f64 {
        let mut value = [0.0];
        on_deck
            .iter()
            .map(|&w| {
                self.elastic.lines[line_of[w]].values_at(positions[w], &mut value);
                forces[w] * (value[0] + self.hat_at(positions[w]))
            })
            .sum()
    }
}
