//! Resolving the `output` section: `every` or `interval` into a whole
//! number of steps between written samples, and the history's format.

use super::checker::Checker;
use super::raw::OutputRaw;
use crate::scene::HistoryFormat;
use crate::scene::Output;

/// Most steps between written samples (beyond it a history of a run within
/// the step budget would hold a handful of rows at most).
const MAX_EVERY: u64 = 1 << 40;

/// The resolved `output` for a run at `time_step` (s).
pub(crate) fn resolve_output(
    raw: Option<&OutputRaw>,
    time_step: f64,
    ck: &mut Checker<'_>,
) -> Output {
    let Some(raw) = raw else {
        return Output::default();
    };
    let every = match (raw.every, raw.interval) {
        (Some(_), Some(_)) => {
            ck.error("output.interval", "give `every` or `interval`, not both");
            1
        }
        (Some(n), None) => {
            if n == 0 || n > MAX_EVERY {
                ck.error(
                    "output.every",
                    format!("`every` is a whole number of steps from 1 to {MAX_EVERY}, got {n}"),
                );
                1
            } else {
                n as usize
            }
        }
        (None, Some(interval)) => {
            ck.positive("output.interval", interval, "an output interval");
            let steps = (interval / time_step).round();
            if !(interval > 0.0 && steps.is_finite()) || steps > MAX_EVERY as f64 {
                ck.error(
                    "output.interval",
                    format!(
                        "an output interval of {interval} s is {steps} time steps of {time_step} s; \
                         at most {MAX_EVERY}"
                    ),
                );
                1
            } else {
                (steps as usize).max(1)
            }
        }
        (None, None) => 1,
    };
    Output {
        every,
        format: raw.format.unwrap_or(HistoryFormat::Csv),
    }
}
