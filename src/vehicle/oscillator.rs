//! Moving oscillator: sprung mass m_s on a spring k and dashpot c over a wheel
//! mass m_u (LCP separation paper, Fig. 1 and its Eq. 1–2).
//!
//! DOFs (upward positive): `sprung` = y_s, `wheel` = y_w.
//! m_s ÿ_s + c (ẏ_s − ẏ_w) + k (y_s − y_w) = −m_s g
//! m_u ÿ_w − c (ẏ_s − ẏ_w) − k (y_s − y_w) = −m_u g + λ
//! With m_u = 0 the wheel DOF is massless and simply transmits the suspension
//! force: the 1-DOF sprung mass of Yang & Yau (1997).

use nalgebra::{DMatrix, DVector};

use super::{VehicleModel, Wheel, WheelKind};
use crate::scene::Oscillator;

pub use crate::scene::dof_names::oscillator::DOF_NAMES;

/// Builds the 2-DOF model.
pub fn build(v: &Oscillator, gravity: f64) -> VehicleModel {
    let (k, c) = (v.stiffness, v.damping);
    VehicleModel {
        dof_names: DOF_NAMES.iter().map(|&n| n.to_owned()).collect(),
        mass: DMatrix::from_row_slice(2, 2, &[v.sprung_mass, 0.0, 0.0, v.unsprung_mass]),
        damping: DMatrix::from_row_slice(2, 2, &[c, -c, -c, c]),
        stiffness: DMatrix::from_row_slice(2, 2, &[k, -k, -k, k]),
        gravity_load: DVector::from_row_slice(&[
            -v.sprung_mass * gravity,
            -v.unsprung_mass * gravity,
        ]),
        lateral_ground_load: DVector::zeros(0),
        blocks: std::iter::once(0..2).collect(),
        wheels: vec![Wheel {
            offset: 0.0,
            lateral: 0.0,
            kind: WheelKind::Dof(1),
            direction: crate::contact::ContactDirection::Vertical,
        }],
        speed: v.speed,
        acceleration: 0.0,
        entry_time: v.entry_time,
        path_y: v.lateral_position.unwrap_or(0.0),
    }
}
