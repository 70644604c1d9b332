//! Thin orthotropic plate deck over several spans: Rayleigh–Ritz modes.
//!
//! The deck is the thin Kirchhoff plate of the plate paper's Eq. (1),
//! x ∈ [0, L] along the bridge (L = Σ spans), y ∈ [0, b] across: simply
//! supported at x = 0 and x = L, rigid line supports (w = 0) across the deck
//! at every interior span end, longitudinal edges free or simply supported.
//! Its strain and kinetic energies are
//!
//! U = ½ ∫∫ [Dx w_xx² + 2 D1 w_xx w_yy + Dy w_yy² + 4 Dxy w_xy²] dA,
//! T = ½ ∫∫ ρh ẇ² dA,
//!
//! with D1 = ν_xy Dy (so H = D1 + 2 Dxy as in Eq. (1)); Dx, Dy, D1, Dxy in
//! N·m and ρh in kg/m².
//!
//! Rayleigh–Ritz with a product basis w = Σᵢⱼ qᵢⱼ Xᵢ(x) Yⱼ(y) (the modal
//! expansion of Eq. (2)). Every product couples with every other, so the
//! modes keep the intermodal coupling between longitudinal bending,
//! transverse bending and torsion that the paper insists on:
//! - Xᵢ, i < Nx: the lowest modes of the continuous Euler–Bernoulli beam over
//!   the same spans (unit EI, unit mass per length), Hermite-cubic finite
//!   elements (see [`super::beam`]). They vanish at every support, so each
//!   product satisfies the support conditions exactly, and they are C¹, so the
//!   integrals below are exact for these functions:
//!   A0 = ∫XᵢXₖ dx = ΦᵀMΦ (= I), A1 = ∫Xᵢ'Xₖ' dx = ΦᵀGΦ,
//!   A2 = ∫Xᵢ''Xₖ'' dx = ΦᵀKΦ (= diag ωᵢ²), and ∫Xᵢ''Xₖ dx = −A1
//!   (integration by parts; the boundary terms vanish as X = 0 at the supports).
//! - Yⱼ, j < Ny: Legendre polynomials Pⱼ(2y/b − 1) for free edges (the edge
//!   conditions are natural ones, so the polynomials need not satisfy them),
//!   or sin((j + 1)πy/b) for simply supported edges; each scaled to
//!   ∫₀ᵇ Yⱼ² dy = 1. B0 = ∫YⱼYₗ, B1 = ∫Yⱼ'Yₗ', B2 = ∫Yⱼ''Yₗ'',
//!   B02 = ∫YⱼYₗ'' dy (Gauss–Legendre quadrature, exact for the polynomial
//!   degree; closed forms for the sines).
//!
//! With the term index r = i·Ny + j the Ritz matrices are
//! M = ρh A0⊗B0 and
//! K = Dx A2⊗B0 + Dy A0⊗B2 − D1 A1⊗(B02 + B02ᵀ) + 4 Dxy A1⊗B1,
//! (M in kg/m², K in N/m³ for coordinates q in m², as each product XᵢYⱼ is
//! in 1/m), and K c = ω² M c gives the modes, mass-normalised (cᵀMc = 1, the
//! unit modal mass of Eq. (4.1), so Eq. (4.3)'s modal stiffness is ω²), so
//! φₘ = Σ cₘ,ᵢⱼ XᵢYⱼ is in 1/√kg as on the beam. The dense eigen problem is
//! solved inverted (lowest modes to full relative accuracy, see
//! `lowest_modes_first`) with the faer kernels of [`super::eigen`]
//! (sequential, deterministic, signs fixed).
//! Cost: the beam eigen problem O(beam dofs³) plus the dense Ritz eigen
//! problem O((Nx·Ny)³); the default 18 × 8 = 144 terms take milliseconds,
//! the largest basis the format allows (2,000 terms) some seconds.

use faer::Mat;
use faer::Par::Seq;

use super::beam::BeamModel;
use super::hermite::{HermiteField, shape_curvatures, shape_functions};
use super::{BridgeError, eigen};
use crate::bridge::eigen::kernels;
use crate::scene::{Beam, Damping, Modes, Plate, PlateEdges};

pub mod moments;
pub mod reactions;
mod transverse;

use self::transverse::TransverseBasis;

/// Element of the node list `node_x` (m) holding `x`, its local coordinate
/// in [0, 1] and length (m); `None` off the mesh. The same convention as
/// [`HermiteField`] (at a node the element to the right), so a point value
/// here and on a [`PlateModes::line`] field agree to round-off.
#[inline]
fn locate(node_x: &[f64], x: f64) -> Option<(usize, f64, f64)> {
    let first = *node_x.first()?;
    let last = *node_x.last()?;
    if !(x >= first && x <= last) {
        return None;
    }
    let right = node_x.partition_point(|&nx| nx <= x);
    let element = right.clamp(1, node_x.len() - 1) - 1;
    let xa = node_x[element];
    let h = node_x[element + 1] - xa;
    Some((element, ((x - xa) / h).clamp(0.0, 1.0), h))
}

/// Hermite "geometric" element matrix ∫Nₐ'N_b' dx of an element of length
/// `h` (m), dofs (wₐ, θₐ, w_b, θ_b) (Przemieniecki, Theory of Matrix
/// Structural Analysis, §15.2: the stability matrix per unit axial force).
fn element_slope_products(h: f64) -> [[f64; 4]; 4] {
    let c = 1.0 / (30.0 * h);
    let h2 = h * h;
    [
        [36.0 * c, 3.0 * h * c, -36.0 * c, 3.0 * h * c],
        [3.0 * h * c, 4.0 * h2 * c, -3.0 * h * c, -h2 * c],
        [-36.0 * c, -3.0 * h * c, 36.0 * c, -3.0 * h * c],
        [3.0 * h * c, -h2 * c, -3.0 * h * c, 4.0 * h2 * c],
    ]
}

/// ΦᵀAΦ for a square `a` on the beam's free dofs and the `count` first
/// columns of `phi`, symmetrised against round-off.
fn project(a: &Mat<f64>, phi: &Mat<f64>, count: usize) -> Mat<f64> {
    let basis = phi.subcols(0, count);
    let projected = kernels::product(
        basis.transpose(),
        kernels::product(a.as_ref(), basis, Seq).as_ref(),
        Seq,
    );
    Mat::from_fn(count, count, |i, k| {
        0.5 * (projected[(i, k)] + projected[(k, i)])
    })
}

/// Every mode of K c = ω² M c (K, M symmetric positive definite): λ = ω²
/// (rad²/s²) ascending and the mass-normalised vectors (cᵀMc = 1) as
/// columns.
///
/// Solved by the dense inverted reduction of [`eigen::dense`]: the lowest
/// modes keep full relative accuracy even on a 5 cm strip, where
/// ω²_max/ω²_min ~ 10¹⁶. The kept ones are checked later like every
/// bridge's modes ([`PlateModes::check`]). Cost O(N³).
fn lowest_modes_first(
    stiffness: &Mat<f64>,
    mass: &Mat<f64>,
) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    eigen::dense::lowest_inverted(stiffness, mass)
}

/// Mass-normalised plate modes over the whole Ritz basis (or the kept ones
/// after [`PlateModes::truncate`]).
#[derive(Debug, Clone)]
pub struct PlateModes {
    /// Deck length, m.
    pub length: f64,
    /// Deck width, m.
    pub width: f64,
    /// The longitudinal functions Xᵢ (Nx components, ∫Xᵢ² dx = 1, 1/√m) as
    /// Hermite fields over the beam mesh.
    beam_functions: HermiteField,
    /// The transverse functions Yⱼ.
    transverse: TransverseBasis,
    /// Nx.
    longitudinal_terms: usize,
    /// Ny.
    transverse_terms: usize,
    /// Ritz coefficients c_{m,r} (m/√kg) laid out `[term r][mode m]` with
    /// stride N, so the kept modes of one term are contiguous.
    coefficients: Vec<f64>,
    /// ‖XᵢYⱼ‖ = √(A0ᵢᵢ B0ⱼⱼ) of each term r (≈ 1), for the mode character.
    term_norms: Vec<f64>,
    /// Number of modes kept for evaluation.
    kept: usize,
    /// Lower Cholesky factor L of the full Ritz stiffness K = LLᵀ (K in
    /// N/m³), for influence lines without modal truncation.
    stiffness_factor: Mat<f64>,
    /// The Ritz stiffness (N/m³ per basis product) and mass (kg), kept to
    /// check the modes a run keeps ([`PlateModes::check`]).
    ritz_stiffness: Mat<f64>,
    ritz_mass: Mat<f64>,
    /// ω² of every Ritz mode, rad²/s², ascending.
    eigenvalues: Vec<f64>,
    /// (Dx, Dy, D1, Dxy), N·m: the moments per unit width ([`moments`]).
    rigidities: (f64, f64, f64, f64),
    /// ρh, kg/m²: the inertia of the line reactions ([`reactions`]).
    mass_per_area: f64,
}

impl PlateModes {
    /// Builds the Ritz model of `plate` and solves for every mode of the basis.
    /// Returns the modes and their circular frequencies ω (rad/s), ascending.
    ///
    /// Errors: [`BridgeError::TooManyModes`] if the beam mesh offers fewer
    /// modes than `plate.terms.longitudinal`; the eigen solver's errors.
    /// Cost O(beam dofs³ + (Nx·Ny)³) time, O((Nx·Ny)²) memory.
    pub fn build(plate: &Plate) -> Result<(Self, Vec<f64>), BridgeError> {
        let length: f64 = plate.spans.iter().sum();
        let width = plate.width;
        let (nx, ny) = (plate.terms.longitudinal, plate.terms.transverse);
        let terms = nx.checked_mul(ny).ok_or(BridgeError::OutOfMemory)?;
        // The Ritz matrices, their factor and the modes: refuse a basis that
        // cannot be held instead of aborting in an allocation.
        eigen::dense::ensure_memory(terms, terms, 12)?;

        // Longitudinal functions: modes of the continuous unit beam.
        let unit_beam = Beam {
            spans: plate.spans.clone(),
            bending_stiffness: 1.0,
            mass_per_length: 1.0,
            elements_per_span: vec![plate.elements_per_span; plate.spans.len()],
            modes: Modes {
                count: None,
                max_frequency: None,
                static_correction: true,
            },
            damping: Damping::Modal { ratio: 0.0 },
            sway: None,
        };
        let beam = BeamModel::new(&unit_beam)?;
        if nx > beam.free_dofs() {
            return Err(BridgeError::TooManyModes {
                requested: nx,
                available: beam.free_dofs(),
            });
        }
        let phi = beam.modes(nx)?.vectors;
        let beam_functions = beam.shapes(&phi, nx);

        // ∫Nₐ'N_b' dx assembled on the beam's free dofs.
        let free = beam.free_dofs();
        let mut slope_products = Mat::<f64>::zeros(free, free);
        for e in 0..beam.node_x.len() - 1 {
            let ge = element_slope_products(beam.node_x[e + 1] - beam.node_x[e]);
            let dofs = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3];
            for (a, &ga) in dofs.iter().enumerate() {
                let Some(ia) = beam.free_index[ga] else {
                    continue;
                };
                for (b, &gb) in dofs.iter().enumerate() {
                    if let Some(ib) = beam.free_index[gb] {
                        slope_products[(ia, ib)] += ge[a][b];
                    }
                }
            }
        }
        let a0 = project(&beam.pencil.mass.to_dense(), &phi, nx);
        let a1 = project(&slope_products, &phi, nx);
        let a2 = project(&beam.pencil.stiffness.to_dense(), &phi, nx);

        let transverse = match plate.edges {
            PlateEdges::Free => TransverseBasis::Legendre,
            PlateEdges::SimplySupported => TransverseBasis::Sine,
        };
        let [b0, b1, b2, b02] = transverse.integrals(width, ny);

        let (dx, dy, d1, dxy) = plate.rigidity.rigidities(plate.thickness.unwrap_or(0.0));
        let rho_h = plate.mass_per_area;
        let mut stiffness = Mat::<f64>::zeros(terms, terms);
        let mut mass = Mat::<f64>::zeros(terms, terms);
        for i in 0..nx {
            for k in 0..nx {
                let (x0, x1, x2) = (a0[(i, k)], a1[(i, k)], a2[(i, k)]);
                for j in 0..ny {
                    for l in 0..ny {
                        let (jl, lj) = (j * ny + l, l * ny + j);
                        let (r, s) = (i * ny + j, k * ny + l);
                        stiffness[(r, s)] = dx * x2 * b0[jl] + dy * x0 * b2[jl]
                            - d1 * x1 * (b02[jl] + b02[lj])
                            + 4.0 * dxy * x1 * b1[jl];
                        mass[(r, s)] = rho_h * x0 * b0[jl];
                    }
                }
            }
        }

        let stiffness_factor = kernels::cholesky_lower(stiffness.as_ref(), Seq)
            .ok_or(BridgeError::StiffnessNotPositive)?;
        let (eigenvalues, vectors) = lowest_modes_first(&stiffness, &mass)?;
        let omegas: Vec<f64> = eigenvalues.iter().map(|l| l.sqrt()).collect();
        let mut coefficients = vec![0.0; terms * terms];
        for mode in 0..terms {
            for r in 0..terms {
                coefficients[r * terms + mode] = vectors[(r, mode)];
            }
        }

        let term_norms = (0..terms)
            .map(|r| (a0[(r / ny, r / ny)] * b0[(r % ny) * ny + r % ny]).sqrt())
            .collect();
        let modes = Self {
            length,
            width,
            beam_functions,
            transverse,
            longitudinal_terms: nx,
            transverse_terms: ny,
            coefficients,
            term_norms,
            kept: terms,
            stiffness_factor,
            ritz_stiffness: stiffness,
            ritz_mass: mass,
            eigenvalues,
            rigidities: plate.rigidity.rigidities(plate.thickness.unwrap_or(0.0)),
            mass_per_area: rho_h,
        };
        Ok((modes, omegas))
    }

    /// Checks the lowest `count` modes like every bridge's
    /// ([`eigen::check_dense`]): residuals, M-orthonormality, inertia count.
    pub fn check(&self, count: usize) -> Result<eigen::ModeCheck, BridgeError> {
        let terms = self.available();
        let vectors = Mat::from_fn(terms, count.min(terms), |r, mode| {
            self.coefficients[r * terms + mode]
        });
        eigen::check_dense(
            &self.ritz_stiffness,
            &self.ritz_mass,
            &self.eigenvalues,
            &vectors,
            count,
        )
    }

    /// Number of Ritz functions (= modes available).
    pub fn available(&self) -> usize {
        self.longitudinal_terms * self.transverse_terms
    }

    /// Number of modes kept for evaluation.
    pub fn kept(&self) -> usize {
        self.kept
    }

    /// Keeps only the lowest `count` modes for evaluation (the influence
    /// lines still use the full basis).
    pub fn truncate(&mut self, count: usize) {
        self.kept = count.min(self.available());
    }

    /// Whether (x, y) (m) lies on the deck.
    #[inline]
    fn is_on(&self, x: f64, y: f64) -> bool {
        (0.0..=self.length).contains(&x) && (0.0..=self.width).contains(&y)
    }

    /// Mode values φᵢ(x, y) (1/√kg) of the kept modes; zero off the deck.
    ///
    /// φₘ(x, y) = Σᵢⱼ c_{m,ij} Xᵢ(x) Yⱼ(y). `values.len()` must be the kept
    /// count. Cost O(kept · Nx · Ny), no allocation; for many points along
    /// one line, [`PlateModes::line`] is far cheaper.
    pub fn values_at(&self, x: f64, y: f64, values: &mut [f64]) {
        debug_assert_eq!(values.len(), self.kept);
        values.fill(0.0);
        let node_x = self.beam_functions.node_x();
        let Some((element, xi, h)) = locate(node_x, x).filter(|_| self.is_on(x, y)) else {
            return;
        };
        let (n, _) = shape_functions(xi, h);
        self.accumulate(
            y,
            |i| {
                let (wa, ta) = self.beam_functions.nodal(element, i);
                let (wb, tb) = self.beam_functions.nodal(element + 1, i);
                [n[0] * wa + n[1] * ta + n[2] * wb + n[3] * tb, 0.0, 0.0]
            },
            |m, xy| values[m] += xy[0],
        );
    }

    /// Mode values, slopes ∂φᵢ/∂x (1/(m√kg)) and curvatures ∂²φᵢ/∂x²
    /// (1/(m²√kg)) of the kept modes at (x, y); zero off the deck.
    ///
    /// At a mesh node the curvature is the right element's (it may jump
    /// there, as on the beam). Cost O(kept · Nx · Ny), no allocation.
    pub fn values_slopes_curvatures_at(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        debug_assert_eq!(values.len(), self.kept);
        debug_assert_eq!(slopes.len(), self.kept);
        debug_assert_eq!(curvatures.len(), self.kept);
        values.fill(0.0);
        slopes.fill(0.0);
        curvatures.fill(0.0);
        let node_x = self.beam_functions.node_x();
        let Some((element, xi, h)) = locate(node_x, x).filter(|_| self.is_on(x, y)) else {
            return;
        };
        let (n, dn) = shape_functions(xi, h);
        let ddn = shape_curvatures(xi, h);
        self.accumulate(
            y,
            |i| {
                let (wa, ta) = self.beam_functions.nodal(element, i);
                let (wb, tb) = self.beam_functions.nodal(element + 1, i);
                let dofs = [wa, ta, wb, tb];
                let dot = |s: &[f64; 4]| s.iter().zip(&dofs).map(|(a, b)| a * b).sum::<f64>();
                [dot(&n), dot(&dn), dot(&ddn)]
            },
            |m, xy| {
                values[m] += xy[0];
                slopes[m] += xy[1];
                curvatures[m] += xy[2];
            },
        );
    }

    /// Sums c_{m,ij} Yⱼ(y) (Xᵢ, Xᵢ', Xᵢ'') over the terms for every kept mode
    /// m: `beam(i)` gives (Xᵢ, Xᵢ', Xᵢ'') at the point, `add(m, …)` receives
    /// each term's contribution.
    #[inline]
    fn accumulate(
        &self,
        y: f64,
        beam: impl Fn(usize) -> [f64; 3],
        mut add: impl FnMut(usize, [f64; 3]),
    ) {
        let (nx, ny, terms) = (
            self.longitudinal_terms,
            self.transverse_terms,
            self.available(),
        );
        self.transverse.for_each(self.width, ny, y, |j, yj| {
            for i in 0..nx {
                let x_terms = beam(i);
                let r = i * ny + j;
                let row = &self.coefficients[r * terms..r * terms + self.kept];
                for (m, &c) in row.iter().enumerate() {
                    let cy = c * yj[0];
                    add(m, [cy * x_terms[0], cy * x_terms[1], cy * x_terms[2]]);
                }
            }
        });
    }

    /// Node positions of the longitudinal mesh, m.
    pub fn node_x(&self) -> &[f64] {
        self.beam_functions.node_x()
    }

    /// The kept modes along the line `y` (m) as a Hermite field in x: values,
    /// slopes ∂/∂x and curvatures ∂²/∂x² anywhere on that line.
    ///
    /// Along a fixed y each mode is φₘ(x, y) = Σᵢ Dₘᵢ(y) Xᵢ(x) with
    /// Dₘᵢ(y) = Σⱼ c_{m,ij} Yⱼ(y), a combination of Hermite fields on the same
    /// mesh and so itself one, exactly: nodal (w, θ) = Σᵢ Dₘᵢ (wᵢ, θᵢ). A
    /// line off the deck (y ∉ [0, b]) gives zero modes. Cost
    /// O(kept · Nx · (Ny + nodes)) once; each later point costs 4 multiply–adds
    /// per mode, as on a beam.
    pub fn line(&self, y: f64) -> HermiteField {
        let (nx, ny, terms, kept) = (
            self.longitudinal_terms,
            self.transverse_terms,
            self.available(),
            self.kept,
        );
        // weights[m·Nx + i] = Dₘᵢ(y).
        let mut weights = vec![0.0; kept * nx];
        if (0.0..=self.width).contains(&y) {
            self.transverse.for_each(self.width, ny, y, |j, yj| {
                for i in 0..nx {
                    let r = i * ny + j;
                    let row = &self.coefficients[r * terms..r * terms + kept];
                    for (m, &c) in row.iter().enumerate() {
                        weights[m * nx + i] += c * yj[0];
                    }
                }
            });
        }
        self.combine(&weights, kept)
    }

    /// The Hermite field with `components` components whose component m is
    /// Σᵢ weights[m·Nx + i] Xᵢ(x).
    fn combine(&self, weights: &[f64], components: usize) -> HermiteField {
        let nx = self.longitudinal_terms;
        HermiteField::from_fn(self.node_x().to_vec(), components, |node, m| {
            let mut nodal = (0.0, 0.0);
            for (i, &d) in weights[m * nx..(m + 1) * nx].iter().enumerate() {
                let (w, theta) = self.beam_functions.nodal(node, i);
                nodal.0 += d * w;
                nodal.1 += d * theta;
            }
            nodal
        })
    }

    /// Ritz basis values Ψ_r = Xᵢ(x) Yⱼ(y) (1/m) at (x, y), zero off the deck.
    fn basis_values(&self, x: f64, y: f64) -> Vec<f64> {
        let (nx, ny) = (self.longitudinal_terms, self.transverse_terms);
        let mut psi = vec![0.0; nx * ny];
        if !self.is_on(x, y) {
            return psi;
        }
        let mut x_values = vec![0.0; nx];
        self.beam_functions.values_at(x, &mut x_values);
        self.transverse.for_each(self.width, ny, y, |j, yj| {
            for (i, xi) in x_values.iter().enumerate() {
                psi[i * ny + j] = xi * yj[0];
            }
        });
        psi
    }

    /// Static influence line: G(ξ) = downward deflection (m/N) at
    /// (`x_point`, `y_point`) under a unit downward load at (ξ, `y_load`),
    /// from the full Ritz stiffness (no modal truncation), as a one-component
    /// Hermite field in ξ.
    ///
    /// By Maxwell's reciprocity G(ξ) = Ψ(ξ, y_load)ᵀ K⁻¹ Ψ(x_point, y_point):
    /// the Ritz deflection u = K⁻¹Ψ(point) under a unit load at the point,
    /// read along the load line, whose nodal (w, θ) are
    /// Σᵢ (wᵢ, θᵢ) Σⱼ Yⱼ(y_load) uᵢⱼ. Symmetric in the two points to
    /// round-off. Cost O(N²) with the stiffness factored once in `build`.
    pub fn influence_line(
        &self,
        x_point: f64,
        y_point: f64,
        y_load: f64,
    ) -> Result<HermiteField, BridgeError> {
        let deflection = self.solve_stiffness(&self.basis_values(x_point, y_point))?;
        Ok(self.along_load_line(&deflection, y_load, 1.0))
    }

    /// K⁻¹ `rhs` with the full Ritz stiffness (factored once in `build`).
    /// Cost O(N²).
    fn solve_stiffness(&self, rhs: &[f64]) -> Result<Mat<f64>, BridgeError> {
        let mut solution = Mat::from_fn(rhs.len(), 1, |r, _| rhs[r]);
        let lower = self.stiffness_factor.as_ref();
        kernels::solve_lower(lower, solution.as_mut(), Seq);
        kernels::solve_upper(lower.transpose(), solution.as_mut(), Seq);
        if solution.col(0).iter().any(|u| !u.is_finite()) {
            return Err(BridgeError::StiffnessNotPositive);
        }
        Ok(solution)
    }

    /// `scale` · Ψ(ξ, y_load)ᵀ u as a one-component Hermite field in ξ, for
    /// Ritz coefficients u (one column): its nodal (w, θ) are
    /// Σᵢ (wᵢ, θᵢ) Σⱼ Yⱼ(y_load) uᵢⱼ. Zero off the deck.
    fn along_load_line(&self, u: &Mat<f64>, y_load: f64, scale: f64) -> HermiteField {
        let (nx, ny) = (self.longitudinal_terms, self.transverse_terms);
        let mut weights = vec![0.0; nx];
        if (0.0..=self.width).contains(&y_load) {
            self.transverse.for_each(self.width, ny, y_load, |j, yj| {
                for (i, weight) in weights.iter_mut().enumerate() {
                    *weight += scale * yj[0] * u[(i * ny + j, 0)];
                }
            });
        }
        self.combine(&weights, 1)
    }

    /// Character of kept mode `mode` (from 0): the (longitudinal, transverse)
    /// indices (from 1) of its dominant Ritz term.
    ///
    /// The term XᵢYⱼ with the largest |c_{m,ij}|·‖XᵢYⱼ‖ gives (i + 1, j + 1):
    /// i + 1 is the continuous beam's mode number; j + 1 is the number of
    /// half-waves across for simply supported edges, and the Legendre degree
    /// plus one for free edges (1 = uniform across, 2 = linear, i.e. torsion).
    pub fn character(&self, mode: usize) -> (usize, usize) {
        let terms = self.available();
        let dominant = (0..terms)
            .max_by(|&r, &s| {
                let size =
                    |t: usize| (self.coefficients[t * terms + mode] * self.term_norms[t]).abs();
                size(r).total_cmp(&size(s))
            })
            .unwrap_or(0);
        (
            dominant / self.transverse_terms + 1,
            dominant % self.transverse_terms + 1,
        )
    }
}
