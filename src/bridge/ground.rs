//! What a uniform vertical support motion does to a modal bridge.
//!
//! Every support moving by u_g(t) moves the whole deck rigidly by δ u_g
//! (δ = 1 on every vertical translation, 0 on rotations); in coordinates
//! relative to that motion the deck carries the inertia load −M δ üg, so
//! each mode feels −Γᵢ üg with the participation factor Γᵢ = φᵢᵀ M δ
//! = ∫ m φᵢ dA (kg·(1/√kg) = √kg: the mode's share of the distributed mass;
//! Chopra, Dynamics of Structures, §13.1, Eqs. 13.1.4–13.1.5). The effective
//! modal mass Γᵢ² summed over the kept modes, divided by the total mass,
//! says how much of the excitation they carry (EN 1998-1 4.3.3.3.1(3): at
//! least 90 %).

use super::section::{SectionForces, SectionProbe};
use super::{BridgeError, ModalBridge, Shapes};
use crate::scene::Bridge;

/// Gauss–Legendre nodes and weights on [−1, 1], 2 points (exact for the
/// cubic Hermite shapes along x).
const GAUSS_2: [(f64, f64); 2] = [
    (-0.577_350_269_189_625_8, 1.0),
    (0.577_350_269_189_625_8, 1.0),
];

/// Points across a plate deck for ∫ φ dy (Gauss–Legendre, composite over
/// 8 strips of 4 points: the transverse functions are smooth, and 32
/// points integrate them to round-off).
const WIDTH_STRIPS: usize = 8;
const GAUSS_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

impl ModalBridge {
    /// Participation factors Γᵢ = ∫ m φᵢ dA of the kept modes for a
    /// vertical support motion, √kg, with the total mass (kg). `bridge` is
    /// the resolved description the modes were built from (for the mass
    /// per length or area). Cost O(elements · modes) (a plate: 32× that).
    pub fn vertical_participation(&self, bridge: &Bridge) -> (Vec<f64>, f64) {
        if let Shapes::Imported(imported) = &self.shapes {
            return imported_participation(imported);
        }
        let modes = self.mode_count();
        let mut participation = vec![0.0; modes];
        let mut values = vec![0.0; modes];
        let nodes = self.node_x().to_vec();
        let (density, across): (f64, Vec<(f64, f64)>) = match bridge {
            Bridge::Beam(beam) => (beam.mass_per_length, vec![(0.0, 1.0)]),
            Bridge::FeImport(_) => return (participation, 0.0),
            Bridge::Plate(plate) => {
                let strip = plate.width / WIDTH_STRIPS as f64;
                let points = (0..WIDTH_STRIPS)
                    .flat_map(|s| {
                        GAUSS_4.iter().map(move |&(g, w)| {
                            (strip * (s as f64 + 0.5 * (g + 1.0)), 0.5 * strip * w)
                        })
                    })
                    .collect();
                (plate.mass_per_area, points)
            }
        };
        for pair in nodes.windows(2) {
            let (x0, h) = (pair[0], pair[1] - pair[0]);
            for &(g, wx) in &GAUSS_2 {
                let x = x0 + 0.5 * h * (g + 1.0);
                for &(y, wy) in &across {
                    self.mode_values(x, y, &mut values);
                    let weight = density * 0.5 * h * wx * wy;
                    for (p, v) in participation.iter_mut().zip(&values) {
                        *p += weight * v;
                    }
                }
            }
        }
        let extent = match bridge {
            Bridge::Plate(plate) => plate.width,
            Bridge::Beam(_) | Bridge::FeImport(_) => 1.0,
        };
        (participation, density * self.length * extent)
    }

    /// The static deflection at `x` (m, upward) per unit upward ground
    /// acceleration that the kept modes leave out, m/(m/s²):
    /// −[∫ G(x, ξ) m dξ − Σᵢ φᵢ(x) Γᵢ / ωᵢ²] (the inertia load −m üg is
    /// downward for üg > 0). `None` where no full-stiffness influence line
    /// exists along the deck (a plate), so records there are modal sums.
    /// `mass_per_length` is the beam's m, kg/m.
    pub fn ground_static_share(
        &self,
        mass_per_length: f64,
        x: f64,
        participation: &[f64],
    ) -> Result<Option<f64>, BridgeError> {
        if let Shapes::Imported(imported) = &self.shapes {
            // K⁻¹ M δ at the track point, minus the modes' share of it.
            let full = imported.inertia_field()?.value_at(x);
            return Ok(Some(-(full - self.modal_static_at(x, participation))));
        }
        let Shapes::Beam { .. } = &self.shapes else {
            return Ok(None);
        };
        let full = self.inertia_deflection(mass_per_length, x)?;
        let modal = self.modal_static_at(x, participation);
        // G is the downward deflection per downward load; the load per unit
        // upward üg is m downward, so the upward deflection is −(full), and
        // the modal part q = −Γ/ω² gives −Σφ Γ/ω².
        Ok(Some(-(full - modal)))
    }

    /// ∫ G(x, ξ) m dξ: a beam's static deflection at `x` (m, in the sense
    /// of the load) under its own distributed mass `mass_per_length` (kg/m)
    /// as a unit-acceleration load, m/(m/s²); 2-point Gauss per element
    /// on the FE influence line (exact for its cubic pieces).
    fn inertia_deflection(&self, mass_per_length: f64, x: f64) -> Result<f64, BridgeError> {
        let line = self.influence_line(x, 0.0, 0.0)?;
        let nodes = self.node_x().to_vec();
        let mut full = 0.0;
        for pair in nodes.windows(2) {
            let (x0, h) = (pair[0], pair[1] - pair[0]);
            for &(p, w) in &GAUSS_2 {
                full += mass_per_length * 0.5 * h * w * line.value_at(x0 + 0.5 * h * (p + 1.0));
            }
        }
        Ok(full)
    }

    /// The lateral static deflection of the rails at (`x`, `y`) (m, +y)
    /// per unit lateral ground acceleration (+y) that the kept modes leave
    /// out, m/(m/s²), for a 3D beam: the lateral analogue of
    /// [`ModalBridge::ground_static_share`]. The inertia load −m üg acts
    /// along the shear centre (it twists nothing: the section is doubly
    /// symmetric), so the full deflection is the vertical one scaled by
    /// EI/EI_z (same mesh and supports); the kept modes' share is
    /// Σᵢ φᵢ(x, y) Γᵢ/ωᵢ² with φᵢ the modes' lateral components at the rails
    /// (v − hθ) and Γᵢ the lateral participation factors. An imported
    /// model: K⁻¹ M δ_y read laterally along the track rails (their mean,
    /// as the kept modes' lateral values there) in place of the scaled
    /// beam deflection (`mass_per_length` unused). `None` for a bridge
    /// without lateral DOFs.
    pub fn lateral_ground_static_share(
        &self,
        mass_per_length: f64,
        x: f64,
        y: f64,
        participation: &[f64],
    ) -> Result<Option<f64>, BridgeError> {
        if let Shapes::Imported(imported) = &self.shapes {
            let full = imported.lateral_inertia_field()?.value_at(x);
            let modal = self.modal_static_in(
                crate::contact::ContactDirection::Lateral,
                x,
                y,
                participation,
            );
            return Ok(Some(-(full - modal)));
        }
        let Shapes::Beam {
            sway: Some(sway), ..
        } = &self.shapes
        else {
            return Ok(None);
        };
        let full = sway.flexibility_ratio * self.inertia_deflection(mass_per_length, x)?;
        let modal = self.modal_static_in(
            crate::contact::ContactDirection::Lateral,
            x,
            y,
            participation,
        );
        Ok(Some(-(full - modal)))
    }

    /// The static displacement of free DOF `dof` of an imported model (m,
    /// along the DOF's direction) per unit upward and per unit lateral
    /// ground acceleration that the kept modes leave out, m/(m/s²):
    /// −[(K⁻¹ M δ)_dof − Σᵢ φᵢ,dof Γᵢ/ωᵢ²] for δ vertical (`vertical`, the
    /// vertical participation factors Γ) and for δ_y lateral (`lateral`),
    /// the mode-acceleration method of [`ModalBridge::ground_static_share`]
    /// at a node. Both, whatever the DOF's direction: in a model that
    /// couples the directions a lateral record also moves a uz DOF
    /// statically. An empty participation list (no record in that
    /// direction) gives 0 for it. `None` for any other bridge.
    pub fn dof_ground_static_shares(
        &self,
        dof: usize,
        vertical: &[f64],
        lateral: &[f64],
    ) -> Result<Option<(f64, f64)>, BridgeError> {
        let Shapes::Imported(imported) = &self.shapes else {
            return Ok(None);
        };
        let (full_vertical, full_lateral) = imported.inertia_at_dof(dof)?;
        let mut values = vec![0.0; self.mode_count()];
        imported.dof_values(dof, &mut values);
        let share = |full: f64, participation: &[f64]| {
            if participation.is_empty() {
                return 0.0;
            }
            let modal: f64 = values
                .iter()
                .zip(participation)
                .zip(&self.circular_frequencies)
                .map(|((phi, gamma), w)| phi * gamma / (w * w))
                .sum();
            -(full - modal)
        };
        Ok(Some((
            share(full_vertical, vertical),
            share(full_lateral, lateral),
        )))
    }

    /// Σᵢ φᵢ(x, y) Γᵢ / ωᵢ² in `direction`: the kept modes' static
    /// displacement at a track point under the inertia load of a unit
    /// ground acceleration, m/(m/s²).
    fn modal_static_in(
        &self,
        direction: crate::contact::ContactDirection,
        x: f64,
        y: f64,
        participation: &[f64],
    ) -> f64 {
        let mut values = vec![0.0; self.mode_count()];
        self.mode_values_in(direction, x, y, &mut values);
        values
            .iter()
            .zip(participation)
            .zip(&self.circular_frequencies)
            .map(|((phi, gamma), w)| phi * gamma / (w * w))
            .sum()
    }

    /// Σᵢ φᵢ(x) Γᵢ / ωᵢ²: the kept modes' static deflection at `x` (m)
    /// under the inertia load of a unit ground acceleration, m/(m/s²).
    fn modal_static_at(&self, x: f64, participation: &[f64]) -> f64 {
        let mut values = vec![0.0; self.mode_count()];
        self.mode_values(x, 0.0, &mut values);
        values
            .iter()
            .zip(participation)
            .zip(&self.circular_frequencies)
            .map(|((phi, gamma), w)| phi * gamma / (w * w))
            .sum()
    }

    /// The moment (N·m) and shear (N) at a beam section per unit upward
    /// ground acceleration that the kept modes leave out: the exact static
    /// section forces of the downward inertia load m per unit üg (the
    /// section's point-load solution integrated by 4-point Gauss over every
    /// element, the section's own element split at the section, where the
    /// point-load solution has its kink) plus Σⱼ EIφⱼ″Γⱼ/ωⱼ² (the modal
    /// static part it replaces). `mass_per_length` in kg/m. Cost
    /// O(elements) once.
    pub fn ground_section_share(
        &self,
        probe: &SectionProbe,
        mass_per_length: f64,
        participation: &[f64],
    ) -> SectionForces {
        let nodes = self.node_x().to_vec();
        let (mut positions, mut forces) = (Vec::new(), Vec::new());
        for pair in nodes.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let pieces: &[(f64, f64)] = if probe.x > a && probe.x < b {
                &[(a, probe.x), (probe.x, b)]
            } else {
                &[(a, b)]
            };
            for &(lo, hi) in pieces {
                let h = hi - lo;
                for &(g, w) in &GAUSS_4 {
                    positions.push(lo + 0.5 * h * (g + 1.0));
                    forces.push(mass_per_length * 0.5 * h * w);
                }
            }
        }
        let all: Vec<usize> = (0..positions.len()).collect();
        let full = probe.static_forces(&positions, &forces, &all);
        let modal = probe.static_modal(participation);
        SectionForces {
            moment: full.moment + modal.moment,
            shear: full.shear + modal.shear,
        }
    }
}

impl ModalBridge {
    /// Participation factors Γᵢ = φᵢᵀ M δ_y of the kept modes for a
    /// lateral support motion (δ_y = 1 on every lateral translation), √kg,
    /// with the mass moving with a rigid lateral shift (kg). An imported
    /// model: δ_y on its uy DOFs. A bridge modelled in the vertical plane
    /// (plane beam, plate) has no lateral DOFs: it moves rigidly with the
    /// ground, so in relative coordinates nothing loads it (zeros).
    /// Cost O(n · modes).
    pub fn lateral_participation(&self, bridge: &Bridge) -> (Vec<f64>, f64) {
        match &self.shapes {
            Shapes::Beam {
                sway: Some(sway), ..
            } => {
                // Γ = ∫ m v dx over the lateral shapes (a twist about the
                // centroid carries no lateral inertia); Gauss 2 per element
                // is exact for the cubic shapes.
                let Bridge::Beam(beam) = bridge else {
                    return (vec![0.0; self.mode_count()], 0.0);
                };
                let mut participation = vec![0.0; self.mode_count()];
                let mut values = vec![0.0; self.mode_count()];
                for pair in self.node_x().windows(2) {
                    let (x0, h) = (pair[0], pair[1] - pair[0]);
                    for &(g, w) in &GAUSS_2 {
                        sway.lateral
                            .values_at(x0 + 0.5 * h * (g + 1.0), &mut values);
                        for (p, v) in participation.iter_mut().zip(&values) {
                            *p += beam.mass_per_length * 0.5 * h * w * v;
                        }
                    }
                }
                (participation, beam.mass_per_length * self.length)
            }
            Shapes::Imported(imported) => imported_inertia_participation(
                imported,
                &imported.model.lateral_inertia,
                crate::scene::imported::Direction::Uy,
            ),
            _ => (vec![0.0; self.mode_count()], 0.0),
        }
    }
}

/// Γ = Φᵀ (M δ) of an imported model for the inertia vector `inertia`
/// (M δ on the free DOFs, kg, δ = 1 on every DOF in `direction`), with
/// the mass δᵀ M δ over the free DOFs in that direction (kg). Cost
/// O(n · modes).
fn imported_inertia_participation(
    imported: &super::fe_import::modal::ImportedShapes,
    inertia: &[f64],
    direction: crate::scene::imported::Direction,
) -> (Vec<f64>, f64) {
    let model = &imported.model;
    let n = model.dofs.len();
    let total: f64 = (0..n)
        .filter(|&i| model.dofs[i].1 == direction)
        .map(|i| inertia[i])
        .sum();
    let modes = imported.vectors.ncols();
    let participation = (0..modes)
        .map(|c| (0..n).map(|i| imported.vectors[(i, c)] * inertia[i]).sum())
        .collect();
    (participation, total)
}

/// Γ = Φᵀ M δ of an imported model, δ = 1 on every vertical (uz) DOF —
/// the constrained ones too when the file lists them (their mass coupling
/// M_fs δ_s is kept: [`super::fe_import::ImportedModel::vertical_inertia`]);
/// supports already removed from the matrices take that coupling with them
/// (none for a lumped mass). Returns Γ and the free vertical mass δᵀ M δ
/// (kg) that Σ Γ² tends to. Cost O(n · modes).
fn imported_participation(imported: &super::fe_import::modal::ImportedShapes) -> (Vec<f64>, f64) {
    use crate::scene::imported::Direction as Dof;
    let model = &imported.model;
    let n = model.dofs.len();
    let vertical: Vec<f64> = model
        .dofs
        .iter()
        .map(|(_, d)| if *d == Dof::Uz { 1.0 } else { 0.0 })
        .collect();
    let mut mass_delta = vec![0.0; n];
    for &(i, j, m) in &model.mass {
        mass_delta[i] += m * vertical[j];
    }
    let total: f64 = vertical.iter().zip(&mass_delta).map(|(d, m)| d * m).sum();
    let inertia = &model.vertical_inertia;
    let modes = imported.vectors.ncols();
    let participation = (0..modes)
        .map(|c| (0..n).map(|i| imported.vectors[(i, c)] * inertia[i]).sum())
        .collect();
    (participation, total)
}
