//! The speeds of a resonance check (EN 1991-2 6.4.6.2) and the additional
//! damping of short spans (EN 1991-2 6.4.6.3.1(3)).
//!
//! Speeds are built in km/h, the unit of EN 1991-2 and of the user's input,
//! and each is rounded to 12 significant digits, so that a speed computed
//! from short decimals (40 m/s → 144 km/h, 1.2 × 300 km/h → 360 km/h,
//! 144 + 43 × 5 km/h) is that decimal exactly and prints without float
//! noise (no 359.00000000000006). A run's m/s value is the km/h value
//! converted as a `speed: … km/h` input is.

use crate::scene::ResonanceCheck;

/// km/h per m/s.
const KM_H_PER_M_S: f64 = 3.6;

/// Resonance speeds are rounded to this, km/h (far below the width of any
/// resonance peak, which is a few % of its speed).
const RESONANCE_ROUNDING: f64 = 0.01;

/// Refinement around each resonance speed: quarter steps, two each side.
const REFINEMENT: [f64; 4] = [-0.5, -0.25, 0.25, 0.5];

/// A refinement speed closer than this fraction of a step to a speed
/// already in the grid is left out.
const MIN_SPACING: f64 = 0.1;

/// `v` rounded to 12 significant digits: float noise from a unit
/// conversion or a sum of short decimals removed.
pub fn clean(v: f64) -> f64 {
    if !v.is_finite() || v == 0.0 {
        return v;
    }
    format!("{v:.11e}").parse().unwrap_or(v)
}

/// `v` m/s in km/h, cleaned ([`clean`]).
pub fn km_h(v: f64) -> f64 {
    clean(v * KM_H_PER_M_S)
}

/// `v` km/h in m/s, converted as a `speed: … km/h` input is.
pub fn m_s(v: f64) -> f64 {
    super::raw::km_h_to_m_s(v)
}

/// EN 1991-2:2003 6.4.6.3.1(3), eq. (6.13): the additional damping Δζ in %
/// of a span of `span` m, (0.0187 L − 0.00064 L²) / (1 − 0.0441 L − 0.0044
/// L² + 0.000255 L³), for L < 30 m (Figure 6.15); 0 from 30 m on, where
/// the code gives none (the numerator turns negative at 29.2 m). The total
/// damping is ζ + Δζ (eq. 6.14).
pub fn additional_damping_percent(span: f64) -> f64 {
    if !(span > 0.0 && span < 30.0) {
        return 0.0;
    }
    let l = span;
    let value =
        (0.0187 * l - 0.00064 * l * l) / (1.0 - 0.0441 * l - 0.0044 * l * l + 0.000255 * l * l * l);
    value.max(0.0)
}

impl ResonanceCheck {
    /// The maximum speed of the check, 1.2 × the line speed (EN 1991-2
    /// 6.4.6.2(1)), km/h.
    pub fn max_speed_km_h(&self) -> f64 {
        km_h(1.2 * self.line_speed)
    }

    /// The highest speed run, m/s: `speeds.to` or the maximum speed,
    /// whichever is higher.
    pub fn top_speed(&self) -> f64 {
        m_s(km_h(self.speeds.to).max(self.max_speed_km_h()))
    }

    /// f₀·D of `train` in km/h and the lowest and highest orders k of its
    /// resonance speeds f₀·D/k within the checked range, from
    /// `speeds.from` to the top speed (`None`: no resonance there).
    fn resonance_orders(&self, train: usize) -> Option<(f64, usize, usize)> {
        let coach = self.trains[train].train().coach_length;
        let first = self.first_frequency * coach * KM_H_PER_M_S;
        let (lo, hi) = (km_h(self.speeds.from), km_h(self.top_speed()));
        if !(first.is_finite() && first > 0.0 && lo > 0.0 && hi >= lo) {
            return None;
        }
        // Saturating casts: an absurd f₀ gives a huge count, refused by the
        // caller before any list is built.
        let k_lo = (first / hi).ceil().max(1.0) as usize;
        let k_hi = (first / lo).floor() as usize;
        (k_lo <= k_hi).then_some((first, k_lo, k_hi))
    }

    /// Number of resonance speeds of `train` in the checked range (at most
    /// one off [`Self::resonance_speeds_km_h`] at its ends, from rounding).
    pub fn resonance_count(&self, train: usize) -> usize {
        self.resonance_orders(train)
            .map_or(0, |(_, k_lo, k_hi)| (k_hi - k_lo).saturating_add(1))
    }

    /// The resonance speeds f₀·D/k of `train` (k = 1, 2, …) within the
    /// checked range, from `speeds.from` to the top speed, km/h, fastest
    /// first, each rounded to 0.01 km/h.
    pub fn resonance_speeds_km_h(&self, train: usize) -> Vec<f64> {
        let Some((first, k_lo, k_hi)) = self.resonance_orders(train) else {
            return Vec::new();
        };
        let (lo, hi) = (km_h(self.speeds.from), km_h(self.top_speed()));
        (k_lo..=k_hi)
            .map(|k| clean((first / k as f64 / RESONANCE_ROUNDING).round() * RESONANCE_ROUNDING))
            .filter(|&v| v >= lo && v <= hi)
            .collect()
    }

    /// Number of speeds on the regular grid from `speeds.from` in steps of
    /// `speeds.step` up to `speeds.to` (within 1e-9 of a step, so that
    /// 5 km/h steps land on a round top speed).
    pub fn regular_count(&self) -> usize {
        let s = &self.speeds;
        ((s.to - s.from) / s.step + 1e-9).floor() as usize + 1
    }

    /// The speeds of `train`, km/h, ascending: the regular grid, the top
    /// `speeds.to` when the step misses it, the maximum speed 1.2 × line
    /// speed, each resonance speed, and quarter steps within half a step
    /// of each resonance speed (EN 1991-2 6.4.6.2 asks for smaller steps
    /// near resonance).
    pub fn speeds_km_h(&self, train: usize) -> Vec<f64> {
        let (from, to, step) = (
            km_h(self.speeds.from),
            km_h(self.speeds.to),
            km_h(self.speeds.step),
        );
        let top = km_h(self.top_speed());
        let mut speeds: Vec<f64> = (0..self.regular_count())
            .map(|i| clean(from + i as f64 * step))
            .collect();
        speeds.push(to);
        speeds.push(self.max_speed_km_h());
        let resonances = self.resonance_speeds_km_h(train);
        speeds.extend(&resonances);
        speeds.sort_by(f64::total_cmp);
        speeds.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * step);
        for r in resonances {
            for q in REFINEMENT {
                let v = clean(r + q * step);
                let free = speeds.iter().all(|s| (s - v).abs() >= MIN_SPACING * step);
                if v >= from && v <= top && free {
                    let at = speeds.partition_point(|s| *s < v);
                    speeds.insert(at, v);
                }
            }
        }
        speeds
    }

    /// The speeds of `train`, m/s, ascending ([`Self::speeds_km_h`]).
    pub fn speeds_m_s(&self, train: usize) -> Vec<f64> {
        self.speeds_km_h(train).into_iter().map(m_s).collect()
    }

    /// An upper bound of [`Self::run_count`] in `f64`, computed without
    /// building any grid (for the run budget, before the speeds are known
    /// to be sane): per train the regular grid, `to`, the maximum speed and
    /// five speeds per resonance.
    pub fn run_bound(&self) -> f64 {
        let s = &self.speeds;
        let regular = ((s.to - s.from) / s.step + 1.0).max(1.0);
        (0..self.trains.len())
            .map(|t| regular + 2.0 + 5.0 * self.resonance_count(t) as f64)
            .sum()
    }

    /// Number of runs: every train at each of its speeds.
    pub fn run_count(&self) -> usize {
        (0..self.trains.len())
            .map(|t| self.speeds_km_h(t).len())
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::ResonanceSpeeds;
    use crate::scene::{Deck, HslmModel};

    /// HSLM-A1 (D = 18 m) at speeds in km/h over a bridge of f₀ Hz.
    fn check(from: f64, to: f64, step: f64, line: f64, f0: f64) -> ResonanceCheck {
        ResonanceCheck {
            trains: vec![HslmModel::A1],
            line_speed: m_s(line),
            speeds: ResonanceSpeeds {
                from: m_s(from),
                to: m_s(to),
                step: m_s(step),
            },
            deck: Deck::Ballasted,
            max_frequency: 30.0,
            first_frequency: f0,
            additional_damping: None,
        }
    }

    /// 200 to 250 km/h in 20 km/h steps misses 250 and stops below the
    /// maximum 1.2 × 300 = 360 km/h: both are added; f₀·D = 5 × 18 × 3.6
    /// = 324 km/h is added with ±5 and ±10 km/h around it; f₀·D/2 = 162
    /// km/h is below the range.
    #[test]
    fn the_grid_keeps_the_top_the_maximum_and_each_resonance() {
        let c = check(200.0, 250.0, 20.0, 300.0, 5.0);
        assert_eq!(c.resonance_speeds_km_h(0), [324.0]);
        assert_eq!(
            c.speeds_km_h(0),
            [
                200.0, 220.0, 240.0, 250.0, 314.0, 319.0, 324.0, 329.0, 334.0, 360.0
            ]
        );
        assert_eq!(c.run_count(), 10);
        assert!(c.run_bound() >= 10.0);
        assert_eq!(c.top_speed(), m_s(360.0));
    }

    /// Eq. (6.13) by hand at 10 m (0.123 / 0.374 %), none from 30 m on.
    #[test]
    fn the_additional_damping_follows_eq_6_13() {
        assert!((additional_damping_percent(10.0) - 0.123 / 0.374).abs() < 1e-12);
        assert_eq!(additional_damping_percent(30.0), 0.0);
        assert_eq!(additional_damping_percent(45.0), 0.0);
    }

    #[test]
    fn cleaning_removes_conversion_noise() {
        assert_eq!(clean(359.00000000000006), 359.0);
        assert_eq!(km_h(40.0), 144.0);
        assert_eq!(km_h(1.2 * (300.0 * 1000.0 / 3600.0)), 360.0);
        assert_eq!(clean(0.1 + 0.2), 0.3);
        assert_eq!(clean(324.07), 324.07);
    }
}
