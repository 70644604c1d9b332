//! What an engineer checks first on an imported model: its translational
//! mass and its static deflection under the vehicles' weight
//! ([`ImportedTotals`]). The figures go into `summary.json` and `vbi
//! modes`; [`super::advice`] warns where no bridge could have them (a model
//! exported in kN and t deflects 1000 times too much, one in mm is 10⁶
//! times too light per metre).

use crate::bridge::{BridgeError, ModalBridge};
use crate::contact::ContactDirection;
use crate::scene::Vehicle;
use crate::scene::imported::{ImportedModel, ImportedTotals};
use crate::vehicle::VehicleModel;

/// Points evenly along the track, its ends included, at which the static
/// flexibility is measured: an odd count, so a single span's middle is one.
pub const STATIC_POINTS: usize = 101;

/// The vehicles' total static weight, N: the sum of their static vertical
/// wheel loads (a moving force's loads; a model's wheel forces in static
/// equilibrium on a rigid track); `None` without vehicles or if one has no
/// static equilibrium (the run says why).
pub fn static_weight(vehicles: &[Vehicle], gravity: f64) -> Option<f64> {
    if vehicles.is_empty() {
        return None;
    }
    let mut total = 0.0;
    for (i, vehicle) in vehicles.iter().enumerate() {
        let model = VehicleModel::build(vehicle, gravity);
        let (_, forces) = model.static_equilibrium(i + 1, &|_| 0.0).ok()?;
        total += model
            .wheels
            .iter()
            .zip(&forces)
            .filter(|(w, _)| w.direction == ContactDirection::Vertical)
            .map(|(_, f)| f)
            .sum::<f64>();
    }
    Some(total)
}

/// The totals of `model` with its static deflection under `weight` (N) at
/// the most flexible of [`STATIC_POINTS`] points along the track: one pass
/// of block solves with K's factor (4 blocks of 32 right-hand sides).
pub fn totals(
    model: &ImportedModel,
    modal: &ModalBridge,
    weight: Option<f64>,
) -> Result<ImportedTotals, BridgeError> {
    let mut totals = model.totals();
    let Some(weight) = weight.filter(|w| *w > 0.0) else {
        return Ok(totals);
    };
    let points: Vec<_> = (0..STATIC_POINTS)
        .map(|i| {
            let x = model.length * i as f64 / (STATIC_POINTS - 1) as f64;
            (ContactDirection::Vertical, x, 0.0)
        })
        .collect();
    let Some(flexibility) = modal.track_flexibility_at(&points) else {
        return Ok(totals);
    };
    let flexibility = flexibility?;
    let Some((i, g)) = flexibility
        .iter()
        .copied()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return Ok(totals);
    };
    totals.static_load = Some(weight);
    totals.static_load_x = Some(points[i].1);
    totals.static_deflection = Some(weight * g);
    Ok(totals)
}
