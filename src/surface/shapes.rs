//! Deterministic surface shapes engineers use for checks: a ramp, a step,
//! a cosine bump or dip, and a piecewise-linear profile. Each is r(x) in m
//! (positive upward) of the position x along the bridge (m, 0 at the
//! entrance), defined for every x; they are 0 before their start unless a
//! piecewise-linear profile says otherwise.

use serde::Serialize;

use super::interp::Triple;

/// A deterministic shape.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Shape {
    /// r = 0 for x < start, rising linearly by `height` over `length`, then
    /// `height`: r = height·(x − start)/length inside. Slope height/length
    /// inside, 0 outside; the curvature's impulses at the two kinks are not
    /// represented (the wheels see a step in vertical velocity).
    Ramp {
        /// Where the ramp starts, m.
        start: f64,
        /// Horizontal length, m (> 0).
        length: f64,
        /// Rise, m (negative: a descent).
        height: f64,
    },
    /// r = 0 for x < position, `height` from `position` on: a sudden
    /// change of level (a rail joint, a bridge-end step). Slope and
    /// curvature 0: the wheels meet the step within one time step.
    Step {
        /// Where the step is, m.
        position: f64,
        /// Change of level, m (negative: a step down).
        height: f64,
    },
    /// r = (height/2)(1 − cos(2π(x − start)/length)) for start ≤ x ≤
    /// start + length, 0 outside: a full cosine wave, smooth in r and r′
    /// (r″ jumps by ±2π²·height/length² at its ends). A dip is a bump with
    /// negative height.
    Bump {
        /// Where the bump starts, m.
        start: f64,
        /// Length, m (> 0).
        length: f64,
        /// Peak height, m (negative: a dip).
        height: f64,
    },
    /// Straight lines between (x, r) points (x strictly increasing), r held
    /// at the first point's value before it and the last's after it.
    PiecewiseLinear {
        /// (x m, r m).
        points: Vec<(f64, f64)>,
    },
}

impl Shape {
    /// (r, r′, r″) at `x`.
    pub fn at(&self, x: f64) -> Triple {
        match *self {
            Shape::Ramp {
                start,
                length,
                height,
            } => {
                if x < start {
                    (0.0, 0.0, 0.0)
                } else if x <= start + length {
                    (height * (x - start) / length, height / length, 0.0)
                } else {
                    (height, 0.0, 0.0)
                }
            }
            Shape::Step { position, height } => {
                if x < position {
                    (0.0, 0.0, 0.0)
                } else {
                    (height, 0.0, 0.0)
                }
            }
            Shape::Bump {
                start,
                length,
                height,
            } => {
                if x < start || x > start + length {
                    return (0.0, 0.0, 0.0);
                }
                let k = 2.0 * std::f64::consts::PI / length;
                let (s, c) = (k * (x - start)).sin_cos();
                (
                    0.5 * height * (1.0 - c),
                    0.5 * height * k * s,
                    0.5 * height * k * k * c,
                )
            }
            Shape::PiecewiseLinear { ref points } => {
                let (first, last) = (points[0], points[points.len() - 1]);
                if x <= first.0 {
                    return (first.1, 0.0, 0.0);
                }
                if x >= last.0 {
                    return (last.1, 0.0, 0.0);
                }
                let i = points.partition_point(|p| p.0 <= x) - 1;
                let (a, b) = (points[i], points[i + 1]);
                let slope = (b.1 - a.1) / (b.0 - a.0);
                (a.1 + slope * (x - a.0), slope, 0.0)
            }
        }
    }

    /// Largest |r′| (dimensionless).
    pub fn max_slope(&self) -> f64 {
        match self {
            Shape::Ramp { length, height, .. } => (height / length).abs(),
            Shape::Step { .. } => 0.0,
            Shape::Bump { length, height, .. } => {
                (0.5 * height * 2.0 * std::f64::consts::PI / length).abs()
            }
            Shape::PiecewiseLinear { points } => points
                .windows(2)
                .map(|w| ((w[1].1 - w[0].1) / (w[1].0 - w[0].0)).abs())
                .fold(0.0, f64::max),
        }
    }
}
