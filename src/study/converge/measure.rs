//! The measures of a convergence study: each quantity's relative errors
//! against the reference, the observed orders of accuracy, and the cheapest
//! run within tolerance (the norms are in the module documentation of
//! [`super`]).

use super::{Ladder, Order, QuantityError, RunReport};
use crate::record::History;

/// Relative errors of every column of `run` against the same column of
/// `reference`, comparing run sample i with reference sample i·`stride`
/// over the samples both have (see the module documentation for the norms).
/// Both histories must record the same quantities in the same order.
pub fn relative_errors(reference: &History, run: &History, stride: usize) -> Vec<QuantityError> {
    assert!(stride >= 1, "the stride is at least 1");
    let common = run
        .time
        .len()
        .min(reference.time.len().saturating_sub(1) / stride + 1);
    debug_assert!((0..common).all(|i| {
        let (t, t_ref) = (run.time[i], reference.time[i * stride]);
        (t - t_ref).abs() <= 1e-9 * t_ref.abs().max(1.0)
    }));
    reference
        .columns
        .iter()
        .zip(&run.columns)
        .map(|(r, c)| {
            debug_assert_eq!(r.name, c.name);
            let (mut e_max, mut r_max, mut e_sq, mut r_sq) = (0.0f64, 0.0f64, 0.0, 0.0);
            for i in 0..common {
                let u_ref = r.values[i * stride];
                let e = c.values[i] - u_ref;
                // NaN-propagating maximum: a non-finite run never looks accurate.
                if e.abs() > e_max || e.is_nan() {
                    e_max = e.abs();
                }
                r_max = r_max.max(u_ref.abs());
                e_sq += e * e;
                r_sq += u_ref * u_ref;
            }
            QuantityError {
                name: r.name.clone(),
                unit: r.unit,
                max_abs: ratio(e_max, r_max),
                rms: ratio(e_sq.sqrt(), r_sq.sqrt()),
            }
        })
        .collect()
}

/// a / b, with 0/0 = 0 and a/0 = +∞ for a > 0 (NaN stays NaN).
pub(super) fn ratio(a: f64, b: f64) -> f64 {
    if b > 0.0 {
        a / b
    } else if a == 0.0 {
        0.0
    } else {
        a / b.abs()
    }
}

/// Observed orders p = log₂(e(2h)/e(h)) for every pair of successful
/// time-step-ladder runs whose steps differ by a factor 2, per quantity,
/// skipping pairs where either max-abs error is zero or not finite.
pub fn observed_orders(runs: &[RunReport]) -> Vec<Order> {
    let ladder: Vec<&RunReport> = runs
        .iter()
        .filter(|r| r.ladder == Ladder::TimeStep)
        .collect();
    let mut orders = Vec::new();
    for fine in &ladder {
        let Some(coarse) = ladder
            .iter()
            .find(|c| (c.time_step / fine.time_step - 2.0).abs() < 1e-9)
        else {
            continue;
        };
        let (Ok(fine_errors), Ok(coarse_errors)) = (&fine.errors, &coarse.errors) else {
            continue;
        };
        for (f, c) in fine_errors.iter().zip(coarse_errors) {
            let usable = |e: f64| e.is_finite() && e > 0.0;
            if usable(f.max_abs) && usable(c.max_abs) {
                orders.push(Order {
                    quantity: f.name.clone(),
                    coarse_step: coarse.time_step,
                    fine_step: fine.time_step,
                    order: (c.max_abs / f.max_abs).log2(),
                });
            }
        }
    }
    orders
}

/// Median of finite values (mean of the middle two for an even count).
pub fn median(mut values: Vec<f64>) -> Option<f64> {
    values.retain(|v| v.is_finite());
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(values[n / 2]),
        _ => Some(0.5 * (values[n / 2 - 1] + values[n / 2])),
    }
}

/// Index of the successful run with the smallest wall time among those whose
/// worst max-abs relative error over the quantities not in `excluded` is at
/// most `tolerance` (first on ties); None if no run qualifies.
pub fn cheapest_within(runs: &[RunReport], tolerance: f64, excluded: &[String]) -> Option<usize> {
    runs.iter()
        .enumerate()
        .filter_map(|(i, r)| {
            let worst = r.worst_max_abs_except(excluded)?;
            (worst <= tolerance).then_some((i, r.wall_time?))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}
