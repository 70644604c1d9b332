//! Bending and twisting moments per unit width of the plate deck,
//! converging with the mode count by the mode-acceleration method.
//!
//! Kirchhoff's orthotropic plate (the plate paper's Eq. (1); Timoshenko &
//! Woinowsky-Krieger, *Theory of Plates and Shells*, §§ 21, 86) with w
//! upward and sagging positive, as the beam's moment
//! ([`crate::bridge::section`]):
//!
//! m_x = Dx w_xx + D1 w_yy,  m_y = Dy w_yy + D1 w_xx,  m_xy = −2 Dxy w_xy
//!
//! (N·m/m; m_xy with Timoshenko's sign, D(1 − ν) w_xy for w downward). Each
//! is a linear operator 𝓜 on w, so on the Ritz basis Ψ_r = XᵢYⱼ it is a
//! row b = 𝓜Ψ(x, y) and a mode's moment is Eⱼ = bᵀcⱼ. The effect at the
//! point is split as for the beam's sections (Williams 1945; Clough &
//! Penzien §13-6):
//!
//! E(t) = Σ_w F_w M(ξ_w, η_w) + Σⱼ Eⱼ (qⱼ − qⱼ,static),
//! qⱼ,static = −Σ_w φⱼ(ξ_w, η_w) F_w / ωⱼ²,
//!
//! with F_w the wheels' downward forces and M(ξ, η) = −Ψ(ξ, η)ᵀ K⁻¹ b the
//! moment at the point under a unit downward load at (ξ, η) from the full
//! Ritz stiffness (Müller-Breslau; no modal truncation).
//!
//! The longitudinal functions Xᵢ are Hermite-cubic finite-element modes:
//! their element curvature is linear and jumps at the nodes, so m_x and m_y
//! converge at first order in the element size (measured against Navier's
//! series: 6.1e-3, 2.8e-3, 1.3e-3 of the largest moment at 20, 40, 80
//! elements per span; nodal averaging, as on the beam's sections, was
//! worse here under point loads: 1.7e-2 at 20). Refine `elements_per_span`
//! for moments; displacements converge much faster. Under a load on the
//! point itself the exact plate moment is singular (logarithmically); the
//! Ritz basis gives a finite value that grows with the basis, so read
//! moments a little away from wheel paths or compare bases.

use super::PlateModes;
use crate::bridge::BridgeError;
use crate::bridge::hermite::{HermiteField, shape_curvatures, shape_functions};
use crate::scene::PlateMoment;

/// A moment per unit width at one point: its modal moments and, for the
/// static correction, its influence line along every wheel line.
#[derive(Debug, Clone)]
pub struct PlateMomentProbe {
    /// Eⱼ per kept mode, N·m/m per unit modal coordinate.
    pub modal: Vec<f64>,
    /// Eⱼ/ωⱼ², for the static modal part.
    pub static_modal: Vec<f64>,
    /// M(ξ) along each wheel line (N·m/m per N of downward load), in the
    /// order of `lines`.
    pub lines: Vec<HermiteField>,
    /// The wheel lines' y, m.
    pub line_y: Vec<f64>,
}

impl PlateModes {
    /// b = 𝓜Ψ(x, y): the moment of every Ritz basis product at (x, y),
    /// N·m/m per unit coefficient; zero off the deck. Cost O(Nx·Ny).
    fn moment_basis(&self, x: f64, y: f64, moment: PlateMoment) -> Vec<f64> {
        let (nx, ny) = (self.longitudinal_terms, self.transverse_terms);
        let mut basis = vec![0.0; nx * ny];
        let node_x = self.beam_functions.node_x();
        let Some((element, xi, h)) = super::locate(node_x, x).filter(|_| self.is_on(x, y)) else {
            return basis;
        };
        let (n, dn) = shape_functions(xi, h);
        let ddn = shape_curvatures(xi, h);
        // (Xᵢ, Xᵢ', Xᵢ'') at x.
        let longitudinal: Vec<[f64; 3]> = (0..nx)
            .map(|i| {
                let (wa, ta) = self.beam_functions.nodal(element, i);
                let (wb, tb) = self.beam_functions.nodal(element + 1, i);
                let dofs = [wa, ta, wb, tb];
                let dot = |s: &[f64; 4]| s.iter().zip(&dofs).map(|(a, b)| a * b).sum::<f64>();
                [dot(&n), dot(&dn), dot(&ddn)]
            })
            .collect();
        let (dx, dy, d1, dxy) = self.rigidities;
        self.transverse.for_each(self.width, ny, y, |j, yj| {
            for (i, xi) in longitudinal.iter().enumerate() {
                basis[i * ny + j] = match moment {
                    PlateMoment::Longitudinal => dx * xi[2] * yj[0] + d1 * xi[0] * yj[2],
                    PlateMoment::Transverse => dy * xi[0] * yj[2] + d1 * xi[2] * yj[0],
                    PlateMoment::Twisting => -2.0 * dxy * xi[1] * yj[1],
                };
            }
        });
        basis
    }

    /// The probe of `moment` at (`x`, `y`) for wheels along the lines
    /// `line_y` (m): modal moments of the kept modes (ω² from
    /// `circular_frequencies`, rad/s) and the full-stiffness influence line
    /// along each wheel line. Cost O(N²) per line with K factored once.
    pub fn moment_probe(
        &self,
        x: f64,
        y: f64,
        moment: PlateMoment,
        circular_frequencies: &[f64],
        line_y: &[f64],
    ) -> Result<PlateMomentProbe, BridgeError> {
        let basis = self.moment_basis(x, y, moment);
        self.functional_probe(&basis, circular_frequencies, line_y)
    }

    /// Σ_r b_r c_{r,m} per kept mode m: a linear functional b of the Ritz
    /// coefficients (a moment's 𝓜Ψ, a line reaction's a(Ψ, v)) on each
    /// kept mode. Cost O(N · kept).
    pub(super) fn modal_values(&self, basis: &[f64]) -> Vec<f64> {
        let terms = self.available();
        (0..self.kept)
            .map(|m| {
                (0..basis.len())
                    .map(|r| basis[r] * self.coefficients[r * terms + m])
                    .sum()
            })
            .collect()
    }

    /// The mode-acceleration probe of the linear functional `basis` (b on
    /// the Ritz coefficients): its modal values, their static part
    /// (÷ ω², `circular_frequencies` in rad/s) and its full-stiffness
    /// influence line −Ψ(ξ, η)ᵀ K⁻¹ b along each wheel line `line_y` (m).
    /// Cost O(N²) per line with K factored once.
    pub(super) fn functional_probe(
        &self,
        basis: &[f64],
        circular_frequencies: &[f64],
        line_y: &[f64],
    ) -> Result<PlateMomentProbe, BridgeError> {
        let modal = self.modal_values(basis);
        let static_modal = modal
            .iter()
            .zip(circular_frequencies)
            .map(|(e, w)| e / (w * w))
            .collect();
        // u = K⁻¹ b; M(ξ, η) = −Ψ(ξ, η)ᵀ u.
        let solution = self.solve_stiffness(basis)?;
        let lines = line_y
            .iter()
            .map(|&line| self.along_load_line(&solution, line, -1.0))
            .collect();
        Ok(PlateMomentProbe {
            modal,
            static_modal,
            lines,
            line_y: line_y.to_vec(),
        })
    }
}

impl PlateMomentProbe {
    /// The moment (N·m/m) for modal displacements `modal_displacement`, and
    /// with `static_correction` the wheels' static share: `forces` (N,
    /// downward) at `positions` (m) on line `line_of[w]` of the probe, with
    /// their mode values `wheel_modes` (wheel-major, kept modes per wheel);
    /// only the wheels `on_deck` count.
    #[allow(clippy::too_many_arguments)]
    pub fn moment(
        &self,
        modal_displacement: &[f64],
        static_correction: bool,
        positions: &[f64],
        forces: &[f64],
        line_of: &[usize],
        wheel_modes: &[f64],
        on_deck: &[usize],
    ) -> f64 {
        let dynamic: f64 = self
            .modal
            .iter()
            .zip(modal_displacement)
            .map(|(e, q)| e * q)
            .sum();
        if !static_correction {
            return dynamic;
        }
        let modes = self.modal.len();
        let mut value = [0.0];
        let mut full = 0.0;
        let mut modal_static = 0.0;
        for &w in on_deck {
            self.lines[line_of[w]].values_at(positions[w], &mut value);
            full += forces[w] * value[0];
            let phi = &wheel_modes[w * modes..(w + 1) * modes];
            // qⱼ,static = −φⱼ F / ωⱼ².
            let q: f64 = self.static_modal.iter().zip(phi).map(|(e, p)| e * p).sum();
            modal_static -= forces[w] * q;
        }
        dynamic + full - modal_static
    }
}
