//! The `embs` section of `summary.json`: the scene's small parameter ε,
//! and with `solver.compare` the EMBS error of every recorded quantity
//! against the coupled solution of the same scene, with the speed-up.

use serde::Serialize;

use crate::advice::{self, Advice};
use crate::contact::ContactDirection;
use crate::model::Model;
use crate::record::History;
use crate::scene::Record;
use crate::solve::embs::SMALL_EPSILON;
use crate::solve::embs_scale::{
    DirectionalScale, FLEXIBILITY_SHARE, directional_scale, record_direction,
};

/// What the summary says about an EMBS run.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct EmbsSummary {
    /// ε = ω_p/ω_B,vertical: the highest wheelset frequency on the primary
    /// suspension, √(k/m) of a vertical contact DOF, over the lowest bridge
    /// mode that moves the vertical contacts (`scales`, dimensionless).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub epsilon: Option<f64>,
    /// The same over the lateral contacts (a `train_3d`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub epsilon_lateral: Option<f64>,
    /// How ε was found in each contact direction.
    pub scales: Vec<ScaleSummary>,
    /// Whether the first-order bridge response was added.
    pub first_order: bool,
    /// The a-posteriori check of the expansion, per recorded quantity in
    /// scenario order (with the first order only).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub orders: Vec<OrderCheck>,
    /// The comparison with `coupled` (`solver.compare: true`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub comparison: Option<EmbsComparison>,
}

/// The small parameter of one contact direction, with what it is made of
/// ([`crate::solve::embs_scale`]).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ScaleSummary {
    /// `vertical` or `lateral`.
    pub direction: &'static str,
    /// ε = ω_p/ω_B,dir, ω_p the wheelset on its primary suspension
    /// (dimensionless).
    pub epsilon: f64,
    /// ω_p/ω_B,dir with ω_p the sprung mass per wheel on the primary
    /// suspension (dimensionless).
    pub epsilon_sprung: f64,
    /// The wheelset on its primary suspension, √(k_w/m_w)/2π, Hz.
    pub wheelset_frequency: f64,
    /// The sprung mass per wheel on the primary suspension, √(k_w/m_s)/2π, Hz.
    pub sprung_frequency: f64,
    /// The bridge mode giving ω_B,dir: the lowest kept mode carrying at
    /// least `flexibility_threshold` of the contact points' static
    /// flexibility in this direction (numbered from 1).
    pub bridge_mode: usize,
    /// Its frequency, Hz.
    pub bridge_frequency: f64,
    /// Its share of that flexibility (dimensionless).
    pub flexibility_share: f64,
    /// The share a mode needs to set ω_B,dir (dimensionless).
    pub flexibility_threshold: f64,
    /// The lowest kept mode's frequency, Hz.
    pub lowest_mode_frequency: f64,
    /// The lowest kept mode's share of that flexibility (dimensionless).
    pub lowest_mode_share: f64,
}

impl From<&DirectionalScale> for ScaleSummary {
    fn from(s: &DirectionalScale) -> Self {
        Self {
            direction: s.direction.name(),
            epsilon: s.epsilon,
            epsilon_sprung: s.epsilon_sprung,
            wheelset_frequency: s.wheelset_frequency,
            sprung_frequency: s.sprung_frequency,
            bridge_mode: s.bridge_mode,
            bridge_frequency: s.bridge_frequency,
            flexibility_share: s.flexibility_share,
            flexibility_threshold: FLEXIBILITY_SHARE,
            lowest_mode_frequency: s.lowest_mode.0,
            lowest_mode_share: s.lowest_mode.1,
        }
    }
}

/// The a-posteriori check of one recorded quantity: how large the
/// first-order part is against the zero order's dynamics.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct OrderCheck {
    /// Column name.
    pub name: String,
    /// The contact direction whose dynamics it shows (`vertical`,
    /// `lateral`, or absent for neither).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub direction: Option<&'static str>,
    /// max |q⁽⁰⁾⁺⁽¹⁾ − q⁽⁰⁾| / max |q⁽⁰⁾ − q_static|: the first-order part
    /// over the dynamic part of the zero order (q_static the record's
    /// static crossing response where it has one, its value at t = 0
    /// otherwise); dimensionless, 0 when both vanish.
    pub first_order_ratio: f64,
}

/// Above this first-order ratio η a recorded quantity is flagged. η falls
/// as ε², like the error it indicates, but their ratio depends on the
/// scene: where ε < 1 in every direction the measured EMBS error against
/// `coupled` was 0.06–2.2 η on the golden viaduct (benches/embs_accuracy.sh)
/// and up to [`ERROR_PER_RATIO`] η on a 25 m 3D beam (tests/embs.rs), so a
/// flagged quantity may be several per cent off.
pub const FIRST_ORDER_RATIO_WARNING: f64 = 0.01;

/// Largest measured EMBS error over η where ε < 1 in every direction
/// (8.2: the body's bounce acceleration on the 25 m 3D beam at ε = 0.13
/// vertically and 0.69 laterally, tests/embs.rs).
pub const ERROR_PER_RATIO: f64 = 8.2;

/// Above this the first-order part exceeds the zero order's dynamics: the
/// series is not converging for that quantity.
pub const FIRST_ORDER_RATIO_DIVERGENT: f64 = 1.0;

/// max |a − b| over two equally long records.
fn largest_gap(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

/// The a-posteriori checks of an EMBS run (`full`) against its zero order
/// alone (`zero`), column by column.
fn order_checks(
    model: &Model,
    records: &[Record],
    full: &History,
    zero: &History,
) -> Vec<OrderCheck> {
    full.columns
        .iter()
        .zip(&zero.columns)
        .map(|(mine, zero)| {
            let first = largest_gap(&mine.values, &zero.values);
            let dynamic = match &zero.static_values {
                Some(statics) => largest_gap(&zero.values, statics),
                None => {
                    let start = zero.values.first().copied().unwrap_or(0.0);
                    zero.values
                        .iter()
                        .fold(0.0f64, |m, v| m.max((v - start).abs()))
                }
            };
            let direction = records
                .iter()
                .find(|r| r.name == mine.name)
                .and_then(|r| record_direction(model, r))
                .map(ContactDirection::name);
            OrderCheck {
                name: mine.name.clone(),
                direction,
                first_order_ratio: if dynamic > 0.0 {
                    first / dynamic
                } else if first == 0.0 {
                    0.0
                } else {
                    f64::INFINITY
                },
            }
        })
        .collect()
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
    /// The summary of an EMBS run of `model` recording `records`, checked
    /// against its zero order alone when given (`zero_order`), compared
    /// with `coupled` when given as (coupled history, coupled solve time s,
    /// EMBS solve time s).
    pub fn new(
        model: &Model,
        records: &[Record],
        embs: &History,
        zero_order: Option<&History>,
        coupled: Option<(&History, f64, f64)>,
    ) -> Self {
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
        let scales: Vec<DirectionalScale> = [ContactDirection::Vertical, ContactDirection::Lateral]
            .into_iter()
            .filter_map(|d| directional_scale(model, d))
            .collect();
        let epsilon_in = |d| scales.iter().find(|s| s.direction == d).map(|s| s.epsilon);
        Self {
            epsilon: epsilon_in(ContactDirection::Vertical),
            epsilon_lateral: epsilon_in(ContactDirection::Lateral),
            scales: scales.iter().map(ScaleSummary::from).collect(),
            orders: zero_order
                .map(|zero| order_checks(model, records, embs, zero))
                .unwrap_or_default(),
            first_order: model.embs.is_none_or(|e| e.first_order),
            comparison,
        }
    }

    /// One warning naming the quantities whose first-order ratio η is
    /// above [`FIRST_ORDER_RATIO_WARNING`] (`divergent`: false) or above
    /// [`FIRST_ORDER_RATIO_DIVERGENT`] (true), with their η.
    fn order_advice(&self, divergent: bool) -> Option<Advice> {
        let flagged: Vec<&OrderCheck> = self
            .orders
            .iter()
            .filter(|o| {
                let over = o.first_order_ratio > FIRST_ORDER_RATIO_DIVERGENT;
                o.first_order_ratio > FIRST_ORDER_RATIO_WARNING && over == divergent
            })
            .collect();
        if flagged.is_empty() {
            return None;
        }
        let list = flagged
            .iter()
            .map(|o| format!("`{}` {:.2}", o.name, o.first_order_ratio))
            .collect::<Vec<_>>()
            .join(", ");
        let largest = flagged
            .iter()
            .map(|o| o.first_order_ratio)
            .fold(0.0, f64::max);
        let advice = if divergent {
            Advice::new(
                &advice::EMBS_FIRST_ORDER_LARGE,
                format!(
                    "EMBS a-posteriori check: the first-order part is larger than the zero \
                     order's dynamics (η > {FIRST_ORDER_RATIO_DIVERGENT}) for {list}: the \
                     expansion is not converging there and EMBS gives no answer for these \
                     quantities"
                ),
            )
            .help("use `method: coupled`")
        } else {
            Advice::new(
                &advice::EMBS_FIRST_ORDER_LARGE,
                format!(
                    "EMBS a-posteriori check: the first-order part against the zero order's \
                     dynamics η = max|q⁽¹⁾| / max|q⁽⁰⁾ − q_static| is above \
                     {FIRST_ORDER_RATIO_WARNING} for {list}; where ε < 1 in every direction the \
                     measured error against `coupled` reached {ERROR_PER_RATIO} η, where ε ≥ 1 η \
                     says nothing"
                ),
            )
            .help("check with `solver.compare: true` or use `method: coupled`")
        };
        Some(
            advice
                .at("solver.method")
                .figure("largest_first_order_ratio", largest),
        )
    }

    /// Advice where ε is not small in a direction (the expansion's error
    /// grows like ε² with the first order, ε without it), naming the
    /// frequencies it is made of, and where the a-posteriori check finds a
    /// large first order.
    pub fn advice(&self) -> Vec<Advice> {
        self.scales
            .iter()
            .filter(|s| s.epsilon > SMALL_EPSILON)
            .map(|s| {
                Advice::new(
                    &advice::EMBS_EPSILON_NOT_SMALL,
                    format!(
                        "the EMBS {} small parameter ε = ω_p/ω_B = {:.3} is not small (> \
                         {SMALL_EPSILON}): wheelset on its primary suspension {:.2} Hz (sprung \
                         mass per wheel {:.2} Hz) against bridge mode {} at {:.2} Hz, the lowest \
                         carrying ≥ {:.0} % of the contacts' {} static flexibility; the \
                         decoupled answer may be far from the coupled one",
                        s.direction,
                        s.epsilon,
                        s.wheelset_frequency,
                        s.sprung_frequency,
                        s.bridge_mode,
                        s.bridge_frequency,
                        100.0 * s.flexibility_threshold,
                        s.direction,
                    ),
                )
                .at("solver.method")
                .help("check with `solver.compare: true` or use `method: coupled`")
                .figure("epsilon", s.epsilon)
                .figure("wheelset_frequency_hz", s.wheelset_frequency)
                .figure("bridge_frequency_hz", s.bridge_frequency)
            })
            .chain(self.order_advice(false))
            .chain(self.order_advice(true))
            .collect()
    }
}
