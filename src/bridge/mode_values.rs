//! The mode values of a [`ModalBridge`] at a point: at the deck, at a
//! rail's contact, along a direction, at an imported model's DOF, with
//! slopes and curvatures, and the static influence lines.

use crate::contact::ContactDirection;

use super::{BridgeError, InfluenceLine, ModalBridge, Shapes, plate};

impl ModalBridge {
    /// Mode values φᵢ(x, y) (1/√kg) of every kept mode at `x` along the
    /// bridge and `y` across it (m; a beam ignores `y`); zero off the bridge.
    #[inline]
    pub fn mode_values(&self, x: f64, y: f64, values: &mut [f64]) {
        match &self.shapes {
            Shapes::Beam { shapes, sway, .. } => {
                shapes.values_at(x, values);
                // A 3D beam's twist lifts a point at y by y θ.
                if let Some(sway) = sway.as_deref().filter(|_| y != 0.0) {
                    for &(c, t) in &sway.torsion {
                        values[c] = y * t.at(x).0;
                    }
                }
            }
            Shapes::Imported(imported) => {
                imported.track.evaluate_at(x, y, values, &mut [], &mut [])
            }
            Shapes::Plate { modes, lines } => match lines.iter().find(|(ly, _)| *ly == y) {
                Some((_, line)) => line.values_at(x, values),
                None => modes.values_at(x, y, values),
            },
        }
    }

    /// Mode values, slopes ∂φᵢ/∂x and curvatures ∂²φᵢ/∂x² (1/(m²√kg)) at
    /// (x, y), derivatives along the bridge; zero off the bridge.
    #[inline]
    pub fn mode_values_slopes_curvatures(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        match &self.shapes {
            Shapes::Beam { shapes, sway, .. } => {
                shapes.values_slopes_curvatures_at(x, values, slopes, curvatures);
                if let Some(sway) = sway.as_deref().filter(|_| y != 0.0) {
                    for &(c, t) in &sway.torsion {
                        let (v, d, dd) = t.at(x);
                        (values[c], slopes[c], curvatures[c]) = (y * v, y * d, y * dd);
                    }
                }
            }
            // Along the track: Hermite with the ry DOFs, else linear with
            // zero curvature inside each element (fe_import::track).
            Shapes::Imported(imported) => {
                imported.track.evaluate_at(x, y, values, slopes, curvatures)
            }
            Shapes::Plate { modes, lines } => match lines.iter().find(|(ly, _)| *ly == y) {
                Some((_, line)) => line.values_slopes_curvatures_at(x, values, slopes, curvatures),
                None => modes.values_slopes_curvatures_at(x, y, values, slopes, curvatures),
            },
        }
    }

    /// Mode components in `direction` at (x, y) — values (1/√kg), slopes
    /// ∂/∂x (1/(m√kg)) and curvatures ∂²/∂x² (1/(m²√kg)) of every kept
    /// mode's displacement in that direction (+z up, +y left of travel)
    /// at the rail point x along the bridge, y across it; zero off the
    /// bridge. Vertical: [`ModalBridge::mode_values_slopes_curvatures`].
    /// Lateral: an imported model's uy components along its track (the mean
    /// of the track's rails; Hermite with rz where every node has it, as
    /// the vertical with ry); zero for a bridge modelled in the vertical
    /// plane (a plane beam, a plate: it does not move sideways, so a
    /// wheelset following its rails laterally only follows their alignment).
    #[inline]
    pub fn mode_components(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        match direction {
            ContactDirection::Vertical => {
                self.mode_values_slopes_curvatures(x, y, values, slopes, curvatures)
            }
            ContactDirection::Lateral => match &self.shapes {
                Shapes::Imported(imported) => imported
                    .lateral_track
                    .evaluate(x, values, slopes, curvatures),
                Shapes::Beam {
                    sway: Some(sway), ..
                } => {
                    sway.lateral
                        .values_slopes_curvatures_at(x, values, slopes, curvatures);
                    // The rails, h above the shear centre, move by −h θ.
                    let h = sway.rail_height;
                    for &(c, t) in &sway.torsion {
                        let (v, d, dd) = t.at(x);
                        (values[c], slopes[c], curvatures[c]) = (-h * v, -h * d, -h * dd);
                    }
                }
                _ => {
                    values.fill(0.0);
                    slopes.fill(0.0);
                    curvatures.fill(0.0);
                }
            },
        }
    }

    /// Mode values in `direction` at (x, y), 1/√kg
    /// ([`ModalBridge::mode_components`]).
    #[inline]
    pub fn mode_values_in(&self, direction: ContactDirection, x: f64, y: f64, values: &mut [f64]) {
        match direction {
            ContactDirection::Vertical => self.mode_values(x, y, values),
            ContactDirection::Lateral => match &self.shapes {
                Shapes::Imported(imported) => {
                    imported.lateral_track.evaluate(x, values, &mut [], &mut [])
                }
                Shapes::Beam {
                    sway: Some(sway), ..
                } => {
                    sway.lateral.values_at(x, values);
                    for &(c, t) in &sway.torsion {
                        values[c] = -sway.rail_height * t.at(x).0;
                    }
                }
                _ => values.fill(0.0),
            },
        }
    }

    /// The entry weight of a contact at `x` on an imported track with free
    /// rail ends ([`super::fe_import::entry`]); `None` where loads enter at once.
    #[inline]
    fn contact_entry(&self) -> Option<&crate::scene::imported::RailEntry> {
        match &self.shapes {
            Shapes::Imported(imported) if imported.model.entry.is_active() => {
                Some(&imported.model.entry)
            }
            _ => None,
        }
    }

    /// [`ModalBridge::mode_values`] as a wheel's contact at (x, y) sees
    /// them: on an imported track with free rail ends, times the entry
    /// weight s(x) ([`super::fe_import::entry`]); elsewhere the same.
    #[inline]
    pub fn contact_mode_values(&self, x: f64, y: f64, values: &mut [f64]) {
        self.mode_values(x, y, values);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, &mut [], &mut []);
        }
    }

    /// [`ModalBridge::mode_values_slopes_curvatures`] as a contact sees
    /// them (values, slopes and curvatures of s·φ).
    #[inline]
    pub fn contact_mode_values_slopes_curvatures(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        self.mode_values_slopes_curvatures(x, y, values, slopes, curvatures);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, slopes, curvatures);
        }
    }

    /// [`ModalBridge::mode_components`] as a contact sees them.
    #[inline]
    pub fn contact_mode_components(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        self.mode_components(direction, x, y, values, slopes, curvatures);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, slopes, curvatures);
        }
    }

    /// [`ModalBridge::mode_values_in`] as a contact sees them.
    #[inline]
    pub fn contact_mode_values_in(
        &self,
        direction: ContactDirection,
        x: f64,
        y: f64,
        values: &mut [f64],
    ) {
        self.mode_values_in(direction, x, y, values);
        if let Some(entry) = self.contact_entry() {
            entry.apply(x, values, &mut [], &mut []);
        }
    }

    /// Static deflection influence line of the point (`x_point`, `y_point`)
    /// for loads travelling along the line `y_load` (m; a beam ignores both
    /// y): G(ξ), m/N, the downward deflection at the point due to a unit
    /// downward load at ξ, from the full stiffness (beam finite elements, or
    /// the whole plate Ritz basis; no modal truncation).
    pub fn influence_line(
        &self,
        x_point: f64,
        y_point: f64,
        y_load: f64,
    ) -> Result<InfluenceLine, BridgeError> {
        match &self.shapes {
            Shapes::Beam { model, .. } => model.influence_line(x_point).map(InfluenceLine::Hermite),
            Shapes::Plate { modes, .. } => modes
                .influence_line(x_point, y_point, y_load)
                .map(InfluenceLine::Hermite),
            Shapes::Imported(imported) => imported
                .influence_line(x_point)
                .map(|f| InfluenceLine::Track(f, imported.model.entry)),
        }
    }

    /// The probe of a plate deck's moment per unit width `moment` at (x,
    /// y) (m) for wheels along the lines `line_y` (m)
    /// ([`plate::moments`]); `None` for any other bridge.
    pub fn plate_moment_probe(
        &self,
        x: f64,
        y: f64,
        moment: crate::scene::PlateMoment,
        line_y: &[f64],
    ) -> Result<Option<plate::moments::PlateMomentProbe>, BridgeError> {
        match &self.shapes {
            Shapes::Plate { modes, .. } => modes
                .moment_probe(x, y, moment, &self.circular_frequencies, line_y)
                .map(Some),
            _ => Ok(None),
        }
    }

    /// The line reaction probe of a plate deck's support at `x` (m) for
    /// wheels along `line_y` (m) ([`plate::reactions`]); `None` on another
    /// bridge or off a support. One solve per wheel line.
    pub fn plate_reaction_probe(
        &self,
        x: f64,
        line_y: &[f64],
    ) -> Result<Option<plate::reactions::PlateReactionProbe>, BridgeError> {
        match &self.shapes {
            Shapes::Plate { modes, .. } => {
                modes.reaction_probe(x, &self.supports, &self.circular_frequencies, line_y)
            }
            _ => Ok(None),
        }
    }

    /// The free DOF of an imported model's (node, direction), if the
    /// bridge is imported and the DOF free; `Err` with the reason otherwise.
    pub fn imported_dof(
        &self,
        node: u64,
        direction: crate::scene::imported::Direction,
    ) -> Result<Option<usize>, String> {
        match &self.shapes {
            Shapes::Imported(imported) => Ok(imported.model.dof(node, direction)),
            _ => Err("only an imported (fe_import) bridge has nodes".into()),
        }
    }

    /// The reaction of an imported model's constrained DOF (node,
    /// direction) ([`super::fe_import::reaction`]); `None` if the bridge is
    /// not imported or the DOF is not listed under `constrained`. Two
    /// solves with K's factor.
    pub fn support_reaction(
        &self,
        node: u64,
        direction: crate::scene::imported::Direction,
    ) -> Result<Option<super::fe_import::reaction::SupportReaction>, BridgeError> {
        let Shapes::Imported(imported) = &self.shapes else {
            return Ok(None);
        };
        let Some(support) = imported
            .model
            .supports
            .iter()
            .position(|s| s.node == node && s.direction == direction)
        else {
            return Ok(None);
        };
        imported
            .support_reaction(support, &self.circular_frequencies)
            .map(Some)
    }

    /// Mode values (1/√kg) at free DOF `dof` of an imported model; zeros
    /// for any other bridge.
    pub fn dof_mode_values(&self, dof: usize, values: &mut [f64]) {
        values.fill(0.0);
        if let Shapes::Imported(imported) = &self.shapes {
            imported.dof_values(dof, values);
        }
    }

    /// Static influence line of free DOF `dof` of an imported model for
    /// loads along its track, m/N (the DOF's displacement opposite to its
    /// direction under a unit downward load).
    pub fn dof_influence_line(&self, dof: usize) -> Result<InfluenceLine, BridgeError> {
        match &self.shapes {
            Shapes::Imported(imported) => imported
                .dof_influence_line(dof)
                .map(|f| InfluenceLine::Track(f, imported.model.entry)),
            _ => Err(BridgeError::EigenFailed),
        }
    }

    /// Node positions of the mesh along the bridge, m.
    pub fn node_x(&self) -> &[f64] {
        match &self.shapes {
            Shapes::Beam { shapes, .. } => shapes.node_x(),
            Shapes::Plate { modes, .. } => modes.node_x(),
            Shapes::Imported(imported) => imported.track.node_x(),
        }
    }
}
