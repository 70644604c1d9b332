//! Thin orthotropic plate deck over several spans: Rayleigh–Ritz modes.
//!
//! (Interface fixed; the implementation is being written.)

use super::BridgeError;
use super::hermite::HermiteField;
use crate::scenario::resolved::Plate;

/// Mass-normalised plate modes over the whole Ritz basis (or the kept ones
/// after [`PlateModes::truncate`]).
#[derive(Debug, Clone)]
pub struct PlateModes {
    /// Deck length, m.
    pub length: f64,
    /// Deck width, m.
    pub width: f64,
}

impl PlateModes {
    /// Builds the Ritz model of `plate` and solves for every mode of the basis.
    /// Returns the modes and their circular frequencies ω (rad/s), ascending.
    pub fn build(plate: &Plate) -> Result<(Self, Vec<f64>), BridgeError> {
        let _ = plate;
        Err(BridgeError::EigenFailed)
    }

    /// Number of Ritz functions (= modes available).
    pub fn available(&self) -> usize {
        0
    }

    /// Keeps only the lowest `count` modes for evaluation (the influence
    /// lines still use the full basis).
    pub fn truncate(&mut self, count: usize) {
        let _ = count;
    }

    /// Mode values φᵢ(x, y) (1/√kg) of the kept modes; zero off the deck.
    pub fn values_at(&self, x: f64, y: f64, values: &mut [f64]) {
        let _ = (x, y);
        values.fill(0.0);
    }

    /// Mode values, slopes ∂φᵢ/∂x (1/(m√kg)) and curvatures ∂²φᵢ/∂x²
    /// (1/(m²√kg)) of the kept modes at (x, y); zero off the deck.
    pub fn values_slopes_curvatures_at(
        &self,
        x: f64,
        y: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        let _ = (x, y);
        values.fill(0.0);
        slopes.fill(0.0);
        curvatures.fill(0.0);
    }

    /// Node positions of the longitudinal mesh, m.
    pub fn node_x(&self) -> &[f64] {
        &[]
    }

    /// The kept modes along the line `y` (m) as a Hermite field in x: values,
    /// slopes ∂/∂x and curvatures ∂²/∂x² anywhere on that line.
    pub fn line(&self, y: f64) -> HermiteField {
        let _ = y;
        HermiteField::from_fn(vec![0.0, self.length], 0, |_, _| (0.0, 0.0))
    }

    /// Static influence line: G(ξ) = downward deflection (m/N) at
    /// (`x_point`, `y_point`) under a unit downward load at (ξ, `y_load`),
    /// from the full Ritz stiffness (no modal truncation), as a one-component
    /// Hermite field in ξ.
    pub fn influence_line(
        &self,
        x_point: f64,
        y_point: f64,
        y_load: f64,
    ) -> Result<HermiteField, BridgeError> {
        let _ = (x_point, y_point, y_load);
        Err(BridgeError::EigenFailed)
    }

    /// Character of kept mode `mode` (from 0): the (longitudinal, transverse)
    /// indices (from 1) of its dominant Ritz term.
    pub fn character(&self, mode: usize) -> (usize, usize) {
        let _ = mode;
        (1, 1)
    }
}
