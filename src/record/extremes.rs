//! Extremes of a recorded quantity tracked at every step while the run goes,
//! so that they stay exact however sparsely the history is written
//! (`output.every`) or whether it is kept at all.

/// The step (its index and time, s) and value of one running extreme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Step index from 0 (t = 0).
    pub step: usize,
    /// Time, s.
    pub time: f64,
    /// The value, in the column's unit.
    pub value: f64,
}

/// Largest, smallest and largest-absolute value seen so far; the first step
/// wins a tie, as a scan over the whole history would pick it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Running {
    /// Largest value.
    pub max: Option<Sample>,
    /// Smallest value.
    pub min: Option<Sample>,
    /// Largest |value|.
    pub max_abs: Option<Sample>,
}

impl Running {
    /// Takes the value of one step.
    #[inline]
    pub fn push(&mut self, step: usize, time: f64, value: f64) {
        let sample = Sample { step, time, value };
        if self.max.is_none_or(|m| value > m.value) {
            self.max = Some(sample);
        }
        if self.min.is_none_or(|m| value < m.value) {
            self.min = Some(sample);
        }
        if self.max_abs.is_none_or(|m| value.abs() > m.value.abs()) {
            self.max_abs = Some(sample);
        }
    }
}

/// Every running extreme of one column.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ColumnExtremes {
    /// Over the whole run.
    pub all: Running,
    /// Over the steps at which at least one axle is on the bridge.
    pub on_bridge: Running,
    /// Of the static crossing response (bridge displacements only).
    pub statics: Running,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_of_equal_extremes_wins() {
        let mut r = Running::default();
        for (k, v) in [1.0, -3.0, 3.0, -3.0, 2.0].into_iter().enumerate() {
            r.push(k, k as f64, v);
        }
        assert_eq!(r.max.unwrap().step, 2);
        assert_eq!(r.min.unwrap().step, 1);
        assert_eq!(r.max_abs.unwrap().step, 1);
    }
}
