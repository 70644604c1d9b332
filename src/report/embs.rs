//! The `embs` section of `summary.json`: the scene's small parameter ε,
//! and with `solver.compare` the EMBS error of every recorded quantity
//! against the coupled solution of the same scene, with the speed-up.

use serde::Serialize;

use crate::contact::ContactDirection;
use crate::model::Model;
use crate::record::History;
use crate::solve::embs::{SMALL_EPSILON, small_parameter};

/// What the summary says about an EMBS run.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct EmbsSummary {
    /// ε = ω_p/ω_B over the vertical contacts: the highest wheel frequency
    /// on the primary suspension, √(k/m) of a contact DOF, over the
    /// bridge's lowest kept frequency (dimensionless).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub epsilon: Option<f64>,
    /// The same over the lateral contacts (a `train_3d`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub epsilon_lateral: Option<f64>,
    /// Whether the first-order bridge response was added.
    pub first_order: bool,
    /// The comparison with `coupled` (`solver.compare: true`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub comparison: Option<EmbsComparison>,
}

/// EMBS against the coupled solution of the same scene.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct EmbsComparison {
    /// Wall time of the EMBS solve (bridge orders, upper part, vehicle;
    /// recording included), s.
    pub embs_solve_time: f64,
    /// Wall time of the coupled solve of the same model, s.
    pub coupled_solve_time: f64,
    /// coupled / EMBS solve time.
    pub speed_up: f64,
    /// Per recorded quantity, in scenario order.
    pub quantities: Vec<QuantityError>,
}

/// The EMBS error of one recorded quantity.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct QuantityError {
    /// Column name.
    pub name: String,
    /// max |EMBS − coupled| over the record / max |coupled|
    /// (dimensionless; 0 when the coupled record is identically 0 and
    /// EMBS agrees).
    pub error: f64,
    /// max |coupled| over the record, in the column's unit.
    pub coupled_peak: f64,
}

impl EmbsSummary {
    /// The summary of an EMBS run of `model`, compared with `coupled` when
    /// given as (coupled history, coupled solve time s, EMBS solve time s).
    pub fn new(model: &Model, embs: &History, coupled: Option<(&History, f64, f64)>) -> Self {
        let comparison = coupled.map(|(reference, coupled_time, embs_time)| {
            let quantities = embs
                .columns
                .iter()
                .zip(&reference.columns)
                .map(|(mine, theirs)| {
                    let peak = theirs.values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    let gap = mine
                        .values
                        .iter()
                        .zip(&theirs.values)
                        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
                    QuantityError {
                        name: mine.name.clone(),
                        error: if peak > 0.0 {
                            gap / peak
                        } else if gap == 0.0 {
                            0.0
                        } else {
                            f64::INFINITY
                        },
                        coupled_peak: peak,
                    }
                })
                .collect();
            EmbsComparison {
                embs_solve_time: embs_time,
                coupled_solve_time: coupled_time,
                speed_up: coupled_time / embs_time,
                quantities,
            }
        });
        Self {
            epsilon: small_parameter(model, ContactDirection::Vertical),
            epsilon_lateral: small_parameter(model, ContactDirection::Lateral),
            first_order: model.embs.is_none_or(|e| e.first_order),
            comparison,
        }
    }

    /// A warning where ε is not small (the expansion's error grows like
    /// ε² with the first order, ε without it).
    pub fn warnings(&self) -> Vec<String> {
        [("", self.epsilon), (" lateral", self.epsilon_lateral)]
            .into_iter()
            .filter_map(|(which, eps)| {
                let eps = eps?;
                (eps > SMALL_EPSILON).then(|| {
                    format!(
                        "the EMBS{which} small parameter ε = ω_p/ω_B = {eps:.3} is not small \
                         (> {SMALL_EPSILON}): the decoupled answer may be far from the coupled \
                         one; check with `solver.compare: true` or use `method: coupled`"
                    )
                })
            })
            .collect()
    }
}
