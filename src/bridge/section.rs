//! Bending moment and shear force at a section of a beam bridge, converging
//! with the mode count by the mode-acceleration method.
//!
//! Sign conventions: the moment M is positive sagging (N·m), the shear
//! V = dM/dx (N) is the resultant of the upward forces left of the section.
//! Where a point load or a support sits exactly on the section V jumps;
//! the right-hand limit V(x⁺) is reported, or the left-hand one V(x⁻) for
//! [`Side::Left`].
//!
//! The effect E (M or V) at x is split as in the mode-acceleration method
//! (Williams 1945; Clough & Penzien, *Dynamics of Structures*, 2nd ed.,
//! §13-6; Chopra, *Dynamics of Structures*, §12.11):
//!
//! E(x, t) = E_static(x; F(t)) + Σⱼ Eⱼ(x) (qⱼ − qⱼ,static),
//! qⱼ,static = Σ_w φⱼ(ξ_w) f_w / ωⱼ²,
//!
//! where F(t) are the current wheel forces at positions ξ_w (f_w = −F_w
//! upward on the deck) and Eⱼ the modal moment EI φⱼ″ (shear EI φⱼ‴) of a
//! unit modal coordinate. The quasi-static part comes from the full
//! stiffness, so the modes left out are accounted for and the modal sum only
//! carries the (fast-converging) dynamic remainder. Without the static
//! correction the plain modal sum Σⱼ Eⱼ qⱼ is used.
//!
//! The static part is exact for point loads on the Hermite-cubic mesh of a
//! uniform Euler–Bernoulli beam: the finite-element nodal displacements are
//! exact for consistent point loads (Tong 1969), so in an element with no
//! load inside it the cubic, and its EI w″ and EI w‴, are exact; a load
//! inside the section's own element adds the fixed–fixed particular solution
//! of that element (the load between clamped ends: M_A = −P a b²/h²,
//! R_A = P b²(3a + b)/h³; Roark's Formulas, Table 8.1 case 1d).
//!
//! The modal part Eⱼ(x) is the section force of the static problem whose
//! solution is the mode itself: Kφⱼ = ωⱼ²Mφⱼ, i.e. the beam under the
//! distributed load ωⱼ² m φⱼ(x) (the consistent inertia of the mode). In
//! the section's element the exact solution is the Hermite cubic of the
//! nodal values plus the clamped–clamped particular solution of that load
//! (as for a point load above), so
//!
//! Eⱼ(x) = EI φⱼ″(x) − ωⱼ² m ∫₀ʰ φⱼ(a) G(x; a) da,
//!
//! G the clamped–clamped moment (shear) under a unit load at a, integrated
//! by Gauss–Legendre on each side of x (exact: the integrand is a
//! polynomial of degree 6 on each side). At the element's ends this is the
//! element end force (Kₑ − ωⱼ²Mₑ)φₑ, so the shears of the two elements at
//! an interior support differ by the support's modal reaction: the
//! reaction (the shear jump) carries the beam's inertia, and Σ reactions =
//! Σ loads + the deck's inertia and modal damping forces to round-off
//! (issue 40: nodal averaging of φ‴ had made the jump static only, off by
//! 30 % of the load). A section at a node belongs to the element on its
//! right (`Side::Right`, the right-hand limit) or on its left
//! (`Side::Left`, the left-hand limit, without a load exactly there).

use super::hermite::{HermiteField, shape_curvatures, shape_functions};

use super::{BridgeError, ModalBridge, Shapes};
pub use crate::scene::Side;

/// The moment and shear of one beam section.
#[derive(Debug, Clone)]
pub struct SectionProbe {
    /// Section position, m.
    pub x: f64,
    /// Start of the section's element, m.
    element_start: f64,
    /// Length of the section's element, m.
    element_length: f64,
    /// The section's element (index along the mesh).
    element: usize,
    /// The left-hand limit at a node (the element on the left; a load
    /// exactly at the section is not yet passed).
    left: bool,
    /// M at x under a unit downward load at ξ from the finite-element
    /// displacements (N·m/N), exact for ξ outside the element.
    moment_line: HermiteField,
    /// V at x under a unit downward load at ξ (N/N), likewise.
    shear_line: HermiteField,
    /// EI φⱼ″(x) per mode, N·m per unit modal coordinate.
    modal_moment: Vec<f64>,
    /// EI φⱼ‴(x) per mode, N per unit modal coordinate.
    modal_shear: Vec<f64>,
    /// EI φⱼ″(x)/ωⱼ², for the static modal part.
    static_modal_moment: Vec<f64>,
    /// EI φⱼ‴(x)/ωⱼ².
    static_modal_shear: Vec<f64>,
}

/// Bending moment (N·m, sagging positive) and shear (N, right-hand limit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionForces {
    /// Bending moment, N·m.
    pub moment: f64,
    /// Shear force, N.
    pub shear: f64,
}

/// The load state of one step as the section sees it.
#[derive(Debug, Clone, Copy)]
pub struct SectionLoads<'a> {
    /// Modal displacements q, kept modes.
    pub modal: &'a [f64],
    /// Wheel positions along the bridge, m.
    pub positions: &'a [f64],
    /// Wheel forces on the deck, N, positive downward (compression).
    pub forces: &'a [f64],
    /// Mode values at every wheel, wheel-major; empty without the static
    /// correction. Read only for the wheels `on_deck`.
    pub wheel_modes: &'a [f64],
    /// The wheels on the deck (indices): only they load it.
    pub on_deck: &'a [usize],
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl ModalBridge {
    /// The section probe at `x` (m) on `side` of it, `None` on a plate deck
    /// (moments and shears are beam quantities here). Two sparse solves.
    pub fn section_probe(&self, x: f64, side: Side) -> Result<Option<SectionProbe>, BridgeError> {
        let Shapes::Beam { shapes, model, .. } = &self.shapes else {
            return Ok(None);
        };
        let nodes = &model.node_x;
        let left = side == Side::Left;
        let right = nodes.partition_point(|&nx| nx <= x);
        let mut element = right.clamp(1, nodes.len() - 1) - 1;
        // The left-hand limit at a node (an interior one: at the entrance
        // there is no element on the left).
        if left && element > 0 && x <= nodes[element] {
            element -= 1;
        }
        let start = nodes[element];
        let h = nodes[element + 1] - start;
        let xi = ((x - start) / h).clamp(0.0, 1.0);
        let ei = model.bending_stiffness;
        // Müller-Breslau in finite elements: M(x; ξ) = N(ξ)ᵀ K⁻¹ g with
        // g = −EI B(x) on the element's dofs (w positive downward, so
        // sagging is −EI w″), and g = −EI B′(x) for V = dM/dx.
        let curvature = shape_curvatures(xi, h);
        let third = shape_thirds(h);
        let moment_line = model.kink_line(element, curvature.map(|b| -ei * b))?;
        let shear_line = model.kink_line(element, third.map(|b| -ei * b))?;
        let (modal_moment, modal_shear) = consistent_modal_forces(
            shapes,
            &self.circular_frequencies,
            element,
            xi,
            ei,
            model.mass_per_length,
        );
        let per_stiffness = |values: &[f64]| -> Vec<f64> {
            values
                .iter()
                .zip(&self.circular_frequencies)
                .map(|(v, w)| v / (w * w))
                .collect()
        };
        Ok(Some(SectionProbe {
            x,
            element_start: start,
            element_length: h,
            element,
            left,
            static_modal_moment: per_stiffness(&modal_moment),
            static_modal_shear: per_stiffness(&modal_shear),
            moment_line,
            shear_line,
            modal_moment,
            modal_shear,
        }))
    }
}

/// The third derivatives of the Hermite shape functions on an element of
/// length `h` (constant along it), 1/m³ and 1/m² (rotations).
fn shape_thirds(h: f64) -> [f64; 4] {
    [
        12.0 / (h * h * h),
        6.0 / (h * h),
        -12.0 / (h * h * h),
        6.0 / (h * h),
    ]
}

/// The clamped–clamped moment (sagging positive, N·m) and shear (N) at `s`
/// of an element of length `h` under a unit downward load at `a` (Roark's
/// Formulas, Table 8.1 case 1d); `left` puts a load exactly at `s` on the
/// far side of the section.
fn clamped_unit_load(s: f64, a: f64, h: f64, left: bool) -> (f64, f64) {
    let b = h - a;
    let end_moment = -a * b * b / (h * h);
    let reaction = b * b * (3.0 * a + b) / (h * h * h);
    let beyond = if left { s > a } else { s >= a };
    let moment = end_moment + reaction * s - if beyond { s - a } else { 0.0 };
    let shear = reaction - if beyond { 1.0 } else { 0.0 };
    (moment, shear)
}

/// Gauss–Legendre points and weights on [0, 1], 4 points (exact to degree 7).
const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// Eⱼ for the moment (N·m) and shear (N) of a unit modal coordinate of
/// every mode at local coordinate `xi` of `element` (module doc): the
/// element's cubic EI φ″, EI φ‴ plus the clamped–clamped solution of the
/// mode's inertia load ωⱼ² m φⱼ. Cost O(modes).
fn consistent_modal_forces(
    shapes: &HermiteField,
    circular_frequencies: &[f64],
    element: usize,
    xi: f64,
    ei: f64,
    mass_per_length: f64,
) -> (Vec<f64>, Vec<f64>) {
    let nodes = shapes.node_x();
    let h = nodes[element + 1] - nodes[element];
    let s = xi * h;
    let curvature = shape_curvatures(xi, h);
    let third = shape_thirds(h);
    // Quadrature points on [0, s] and [s, h] (the kernel kinks at a = s),
    // with their weights and shape functions, shared by every mode.
    let points = kinked_quadrature(s, h);
    let left_side = xi >= 1.0;
    let kernels: Vec<(f64, f64)> = points
        .iter()
        .map(|&(a, _, _)| clamped_unit_load(s, a, h, left_side))
        .collect();
    let modes = shapes.components();
    let mut moments = vec![0.0; modes];
    let mut shears = vec![0.0; modes];
    for c in 0..modes {
        let (wa, ta) = shapes.nodal(element, c);
        let (wb, tb) = shapes.nodal(element + 1, c);
        let dofs = [wa, ta, wb, tb];
        let (mut moment_load, mut shear_load) = (0.0, 0.0);
        for (&(_, weight, n), &(gm, gv)) in points.iter().zip(&kernels) {
            let phi = dot(&n, &dofs);
            moment_load += weight * phi * gm;
            shear_load += weight * phi * gv;
        }
        let load = circular_frequencies.get(c).map_or(0.0, |w| w * w) * mass_per_length;
        moments[c] = ei * dot(&curvature, &dofs) - load * moment_load;
        shears[c] = ei * dot(&third, &dofs) - load * shear_load;
    }
    (moments, shears)
}

impl super::beam::BeamModel {
    /// K⁻¹ g for an element load vector `g` on `element`'s dofs, as a
    /// Hermite field over the mesh (the influence line of the section
    /// quantity g represents, by reciprocity). One sparse solve.
    fn kink_line(&self, element: usize, g: [f64; 4]) -> Result<HermiteField, BridgeError> {
        let mut load = vec![0.0; self.free_dofs()];
        for (a, value) in g.into_iter().enumerate() {
            if let Some(i) = self.free_index[2 * element + a] {
                load[i] += value;
            }
        }
        let factor = self.pencil.stiffness_factor()?;
        factor.solve_in_place(&mut load, &mut factor.workspace()?);
        Ok(HermiteField::from_fn(self.node_x.clone(), 1, |n, _| {
            let w = self.free_index[2 * n].map_or(0.0, |i| load[i]);
            let theta = self.free_index[2 * n + 1].map_or(0.0, |i| load[i]);
            (w, theta)
        }))
    }
}

impl SectionProbe {
    /// Exact static moment and shear at the section under downward point
    /// forces `forces` (N) at `positions` (m); loads off the deck count for
    /// nothing.
    /// Only the wheels `on_deck` (indices) are summed.
    pub fn static_forces(
        &self,
        positions: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> SectionForces {
        let mut moment = 0.0;
        let mut shear = 0.0;
        let h = self.element_length;
        let s = self.x - self.element_start;
        for &w in on_deck {
            let (at, p) = (positions[w], forces[w]);
            moment += p * self.moment_line.value_at(at);
            shear += p * self.shear_line.value_at(at);
            let a = at - self.element_start;
            if (0.0..=h).contains(&a) {
                // The load between the element's clamped ends (module doc).
                let (m, v) = clamped_unit_load(s, a, h, self.left);
                moment += p * m;
                shear += p * v;
            }
        }
        SectionForces { moment, shear }
    }

    /// The static modal part Σⱼ (EIφⱼ″(x), EIφⱼ‴(x))/ωⱼ² · vⱼ for a modal
    /// load vector `v` (per mode, N·√kg… the units of Γ or φ·F).
    pub fn static_modal(&self, v: &[f64]) -> SectionForces {
        SectionForces {
            moment: dot(&self.static_modal_moment, v),
            shear: dot(&self.static_modal_shear, v),
        }
    }

    /// Moment and shear this step; `corrected` selects the mode-acceleration
    /// form (module doc), else the plain modal sum. Cost O(modes × wheels).
    pub fn forces(&self, loads: &SectionLoads<'_>, corrected: bool) -> SectionForces {
        let mut moment = dot(&self.modal_moment, loads.modal);
        let mut shear = dot(&self.modal_shear, loads.modal);
        if corrected {
            let statics = self.static_forces(loads.positions, loads.forces, loads.on_deck);
            moment += statics.moment;
            shear += statics.shear;
            let modes = self.modal_moment.len();
            if modes > 0 {
                // − Σⱼ Eⱼ qⱼ,static with qⱼ,static = −Σ_w φⱼ(ξ_w) F_w/ωⱼ².
                for &w in loads.on_deck {
                    let values = &loads.wheel_modes[w * modes..(w + 1) * modes];
                    let force = loads.forces[w];
                    moment += force * dot(&self.static_modal_moment, values);
                    shear += force * dot(&self.static_modal_shear, values);
                }
            }
        }
        SectionForces { moment, shear }
    }
}

/// A beam support's vertical reaction (N, upward on the deck) at `x`: the
/// shear on its right minus the shear on its left (V is the resultant of
/// the upward forces left of a section), plus the wheels standing exactly
/// on it. No element on the left at the entrance, none on the right at the
/// exit.
#[derive(Debug, Clone)]
pub struct ReactionProbe {
    /// Support position, m.
    pub x: f64,
    /// The left-hand section (none at the entrance).
    pub left: Option<SectionProbe>,
    /// The right-hand section (none at the exit).
    pub right: Option<SectionProbe>,
}

impl ModalBridge {
    /// The reaction probe of the support at `x` (m), `None` on a plate deck.
    /// Up to four sparse solves.
    pub fn reaction_probe(&self, x: f64) -> Result<Option<ReactionProbe>, BridgeError> {
        let length = self.length;
        let right = if x < length * (1.0 - 1e-12) {
            self.section_probe(x, Side::Right)?
        } else {
            None
        };
        let left = if x > length * 1e-12 {
            self.section_probe(x, Side::Left)?
        } else {
            None
        };
        if left.is_none() && right.is_none() {
            return Ok(None);
        }
        Ok(Some(ReactionProbe { x, left, right }))
    }
}

impl ReactionProbe {
    /// The reaction this step, N; `corrected` as for [`SectionProbe::forces`].
    /// Cost O(modes × wheels).
    pub fn reaction(&self, loads: &SectionLoads<'_>, corrected: bool) -> f64 {
        let shear =
            |p: &Option<SectionProbe>| p.as_ref().map_or(0.0, |s| s.forces(loads, corrected).shear);
        shear(&self.right) - shear(&self.left)
            + self.on_support(loads.positions, loads.forces, loads.on_deck)
    }

    /// The exact static reaction, N, under downward point forces `forces`
    /// (N) at `positions` (m), the wheels `on_deck` only: the static shear
    /// jump ([`SectionProbe::static_forces`] on each side) plus the loads
    /// standing on the support — the reference of the reaction's dynamic
    /// factor. Cost O(wheels).
    pub fn static_reaction(&self, positions: &[f64], forces: &[f64], on_deck: &[usize]) -> f64 {
        let shear = |p: &Option<SectionProbe>| {
            p.as_ref()
                .map_or(0.0, |s| s.static_forces(positions, forces, on_deck).shear)
        };
        shear(&self.right) - shear(&self.left) + self.on_support(positions, forces, on_deck)
    }

    /// The forces of the wheels standing exactly on the support, N: they
    /// pass into it without shearing either side.
    fn on_support(&self, positions: &[f64], forces: &[f64], on_deck: &[usize]) -> f64 {
        let x = self.x;
        on_deck
            .iter()
            .filter(|&&w| (positions[w] - x).abs() <= 1e-12 * (1.0 + x.abs()))
            .map(|&w| forces[w])
            .sum()
    }

    /// The right-hand and left-hand sections with the sign they enter the
    /// reaction with (+1 right, −1 left).
    pub fn sides(&self) -> impl Iterator<Item = (f64, &SectionProbe)> {
        self.right
            .iter()
            .map(|s| (1.0, s))
            .chain(self.left.iter().map(|s| (-1.0, s)))
    }
}

/// A beam section's moment and shear from the nodal state of the assembled
/// beam (a direct run, [`crate::solve::direct`]): exact in space, no modal
/// sum and no static correction.
///
/// The section's element carries its nodal values and, inside it, the
/// loads of the equations of motion M ü + C u̇ + K u = F − Mδ üg with
/// C = c_M M + c_K K: the distributed inertia and mass-proportional damping
/// −m(ü + c_M u̇ + üg) (upward, consistent with M) and the wheels' point
/// loads. Its exact solution is the Hermite cubic of the nodal values plus
/// the clamped–clamped solution of those loads (the module doc), the
/// stiffness-proportional damping acting with the stiffness (the element's
/// forces are those of u + c_K u̇, a Kelvin–Voigt material):
///
/// M(x) = EI (w + c_K ẇ)″(x) + m ∫₀ʰ (ü + c_M u̇)(a) G_M(s; a) da
///        + Σ_w P_w G_M(s; a_w) + üg m ∫₀ʰ G_M(s; a) da,
///
/// V likewise with w‴ and G_V, w and ü interpolated by the element's
/// Hermite functions N(a) and G the clamped moment (shear) under a unit
/// downward load. At the element's ends these are its end forces
/// Kₑ(uₑ + c_K u̇ₑ) + Mₑ(üₑ + c_M u̇ₑ + δ üg) − Fₑ, so a support's reaction
/// (the shear jump) is its row of the equations of motion, and the forces
/// balance the loads and the deck's inertia at every step. With every mode
/// kept and c_K = 0 this is the modal mode-acceleration form's value (the
/// modes' inertia load Σ ωⱼ² m φⱼ qⱼ is then m(M⁻¹(F − Cu̇) − ü), the
/// static correction trading M⁻¹F for the point loads); with c_K ≠ 0 the
/// modal sum puts the stiffness damping inside the element as the load
/// c_K m M⁻¹K u̇ where this puts it in the stiffness.
///
/// Cost per step O(1) plus the wheels on the deck (those inside the
/// element add their clamped term); nothing is allocated.
#[derive(Debug, Clone)]
pub struct NodalSection {
    /// Free DOF of each of the element's (wₐ, θₐ, w_b, θ_b), `None` where a
    /// support holds it.
    dofs: [Option<usize>; 4],
    /// EI B(x) and EI B‴ (N·m and N per unit DOF).
    moment: [f64; 4],
    shear: [f64; 4],
    /// m ∫ Nₖ(a) G(s; a) da for the moment (kg·m) and the shear (kg).
    moment_inertia: [f64; 4],
    shear_inertia: [f64; 4],
    /// Rayleigh coefficients (c_M 1/s, c_K s).
    damping: (f64, f64),
    /// The section forces per unit upward ground acceleration,
    /// m ∫ G(s; a) da (N·m and N per m/s²).
    pub ground: SectionForces,
}

impl ModalBridge {
    /// The nodal form of `section` ([`NodalSection`]) on this plane beam
    /// with its Rayleigh damping; `None` on any other bridge, or damping
    /// that no C = c_M M + c_K K stands for. Cost O(1).
    pub fn nodal_section(&self, section: &SectionProbe) -> Option<NodalSection> {
        let model = self.beam_model()?;
        let damping = self.rayleigh_damping?;
        let e = section.element;
        let h = section.element_length;
        let s = section.x - section.element_start;
        let xi = (s / h).clamp(0.0, 1.0);
        let ei = model.bending_stiffness;
        let m = model.mass_per_length;
        let (moment_inertia, shear_inertia) = clamped_shape_integrals(s, h);
        let dofs = std::array::from_fn(|a| model.free_index[2 * e + a]);
        let ground = SectionForces {
            moment: m * (moment_inertia[0] + moment_inertia[2]),
            shear: m * (shear_inertia[0] + shear_inertia[2]),
        };
        Some(NodalSection {
            dofs,
            moment: shape_curvatures(xi, h).map(|b| ei * b),
            shear: shape_thirds(h).map(|b| ei * b),
            moment_inertia: moment_inertia.map(|v| m * v),
            shear_inertia: shear_inertia.map(|v| m * v),
            damping,
            ground,
        })
    }
}

/// ∫₀ʰ Nₖ(a) G(s; a) da of the element's four Hermite functions against
/// the clamped moment and shear kernels at `s` (m) of an element of length
/// `h` (m) ([`clamped_unit_load`]), by four-point Gauss–Legendre on each
/// side of s (exact: degree 6 on each side), as the modal forces'
/// ([`consistent_modal_forces`]): m·m and m.
fn clamped_shape_integrals(s: f64, h: f64) -> ([f64; 4], [f64; 4]) {
    let left_side = s >= h;
    let (mut moment, mut shear) = ([0.0; 4], [0.0; 4]);
    for (a, weight, n) in kinked_quadrature(s, h) {
        let (gm, gv) = clamped_unit_load(s, a, h, left_side);
        for k in 0..4 {
            moment[k] += weight * n[k] * gm;
            shear[k] += weight * n[k] * gv;
        }
    }
    (moment, shear)
}

/// Four-point Gauss on [0, s] and on [s, h] of an element of length `h`
/// (m), the section at `s` where a clamped element's kernel kinks: each
/// point's position a (m), weight (m) and Hermite shape functions N(a).
fn kinked_quadrature(s: f64, h: f64) -> Vec<(f64, f64, [f64; 4])> {
    let mut points = Vec::with_capacity(8);
    for (from, to) in [(0.0, s), (s, h)] {
        let length = to - from;
        if length <= 0.0 {
            continue;
        }
        for (g, w) in GAUSS4 {
            let a = from + g * length;
            let (n, _) = shape_functions(a / h, h);
            points.push((a, w * length, n));
        }
    }
    points
}

impl NodalSection {
    /// The moment and shear of `section` this step from the nodal state
    /// `state` and the wheel forces `forces` (N, downward) at `positions`
    /// (m) of the wheels `on_deck`, without the ground's share
    /// ([`Self::ground`], per unit ground acceleration). Cost O(1) + the
    /// wheels on the deck.
    pub fn forces(
        &self,
        section: &SectionProbe,
        state: &crate::bridge::NodalState<'_>,
        positions: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> SectionForces {
        let (c_m, c_k) = self.damping;
        let (mut moment, mut shear) = (0.0, 0.0);
        for (k, dof) in self.dofs.iter().enumerate() {
            let Some(i) = *dof else { continue };
            let elastic = state.displacement[i] + c_k * state.velocity[i];
            let inertia = state.acceleration[i] + c_m * state.velocity[i];
            moment += self.moment[k] * elastic + self.moment_inertia[k] * inertia;
            shear += self.shear[k] * elastic + self.shear_inertia[k] * inertia;
        }
        let loads = section.element_loads(positions, forces, on_deck);
        SectionForces {
            moment: moment + loads.moment,
            shear: shear + loads.shear,
        }
    }
}

impl SectionProbe {
    /// The clamped–clamped section forces of the downward point forces
    /// `forces` (N) of the wheels `on_deck` at `positions` (m) inside the
    /// section's element (the share [`Self::static_forces`] adds to its
    /// influence lines). Cost O(wheels on the deck).
    pub fn element_loads(
        &self,
        positions: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> SectionForces {
        let (mut moment, mut shear) = (0.0, 0.0);
        let h = self.element_length;
        let s = self.x - self.element_start;
        for &w in on_deck {
            let a = positions[w] - self.element_start;
            if (0.0..=h).contains(&a) {
                let (m, v) = clamped_unit_load(s, a, h, self.left);
                moment += forces[w] * m;
                shear += forces[w] * v;
            }
        }
        SectionForces { moment, shear }
    }
}

impl ReactionProbe {
    /// The reaction from the nodal sections `nodal` of [`Self::sides`]
    /// (in that order) and the nodal state: the shear jump plus the loads
    /// standing on the support, without the ground's share (N). Cost O(1)
    /// + the wheels on the deck.
    pub fn nodal_reaction(
        &self,
        nodal: &[NodalSection],
        state: &crate::bridge::NodalState<'_>,
        positions: &[f64],
        forces: &[f64],
        on_deck: &[usize],
    ) -> f64 {
        let jump: f64 = self
            .sides()
            .zip(nodal)
            .map(|((sign, section), n)| {
                sign * n.forces(section, state, positions, forces, on_deck).shear
            })
            .sum();
        jump + self.on_support(positions, forces, on_deck)
    }
}
