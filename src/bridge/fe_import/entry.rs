//! How a wheel's load passes onto an imported track model at a free rail
//! end (issue 24, point 4).
//!
//! An imported track model is cut out of a continuous line: its rails end
//! at the first and last rail node, often half a sleeper bay beyond the last
//! sleeper, free to move. In the vbi convention the vehicle rides a rigid
//! approach up to x = 0, so at the rail end a wheel's full load would fall
//! in one instant on a free cantilever of rail, a step in time that rings
//! every track mode (rails on pads, sleepers on ballast, up to kHz) and
//! that a real line does not have: its rail continues, and a wheel already
//! bends the rail some metres ahead of it (the deflection line of a rail on
//! an elastic foundation, Zimmermann's e^(−x/L)(cos x/L + sin x/L), reaches
//! its first zero 3π/4 · L from the load, L = (4EI/k)^(1/4) = 0.71–0.90 m
//! for a UIC60 rail, EI = 6.4 MN·m², on k = 40–100 MN/m²: 1.7–2.1 m; e.g.
//! Esveld, *Modern Railway Track*, 2001).
//!
//! The model therefore receives the load over an entry length L at each
//! free rail end: a wheel at x couples to the model's rail with the weight
//! s(x), which rises from 0 at the rail end to 1 at L from it as the quintic
//! smoothstep S(u) = u³(10 − 15u + 6u²) (S, S′ and S″ vanish at both ends of
//! the ramp, so the load, its rate and the rate's rate start from zero), the
//! share 1 − s being carried by the rigid approach. The coupling stays
//! symmetric: the wheel's displacement is s·w(x) and the force on the model
//! s·F, so the work the contact does is the same on both sides; the
//! kinematics of a wheel that follows the deck use the slope and curvature
//! of s·w (product rule). Records at a point of the track are the model's
//! own displacements (no weight).

use crate::scene::imported::RailEntry;

/// S(u), S′(u), S″(u) of the quintic smoothstep, u in [0, 1] (clamped).
#[inline]
fn smoothstep(u: f64) -> (f64, f64, f64) {
    if u <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    if u >= 1.0 {
        return (1.0, 0.0, 0.0);
    }
    let v = 1.0 - u;
    (
        u * u * u * (10.0 - 15.0 * u + 6.0 * u * u),
        30.0 * u * u * v * v,
        60.0 * u * v * (v - u),
    )
}

impl RailEntry {
    /// Whether any end has an entry length.
    pub fn is_active(&self) -> bool {
        self.entry > 0.0 || self.exit > 0.0
    }

    /// The weight s(x) and its derivatives s′ (1/m), s″ (1/m²) at `x` (m).
    #[inline]
    pub fn weight(&self, x: f64) -> (f64, f64, f64) {
        let mut out = (1.0, 0.0, 0.0);
        if self.entry > 0.0 {
            let (s, d, dd) = smoothstep((x - self.start) / self.entry);
            let l = self.entry;
            out = (s, d / l, dd / (l * l));
        }
        if self.exit > 0.0 {
            let (s, d, dd) = smoothstep((self.end - x) / self.exit);
            let l = self.exit;
            let (t, dt, ddt) = (s, -d / l, dd / (l * l));
            // Both ends on one short track: the product of the two ramps.
            out = (
                out.0 * t,
                out.1 * t + out.0 * dt,
                out.2 * t + 2.0 * out.1 * dt + out.0 * ddt,
            );
        }
        out
    }

    /// Applies the weight at `x` to a field's values, slopes and curvatures
    /// there, in place: s·w, s·w′ + s′·w, s·w″ + 2s′·w′ + s″·w (`slopes`
    /// and `curvatures` may be empty; curvatures need the slopes).
    #[inline]
    pub fn apply(&self, x: f64, values: &mut [f64], slopes: &mut [f64], curvatures: &mut [f64]) {
        if !self.is_active() {
            return;
        }
        let (s, ds, dds) = self.weight(x);
        if s == 1.0 && ds == 0.0 && dds == 0.0 {
            return;
        }
        debug_assert!(curvatures.is_empty() || slopes.len() == curvatures.len());
        for (i, c) in curvatures.iter_mut().enumerate() {
            *c = s * *c + 2.0 * ds * slopes[i] + dds * values[i];
        }
        for (i, d) in slopes.iter_mut().enumerate() {
            *d = s * *d + ds * values[i];
        }
        for v in values.iter_mut() {
            *v *= s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ramp's derivatives against central differences of s itself.
    #[test]
    fn weight_derivatives_match_finite_differences() {
        let entry = RailEntry {
            start: 0.0,
            end: 5.0,
            entry: 3.0,
            exit: 2.5,
        };
        let h = 1e-4;
        // The smoothstep is C² with a jump of 60/l³ in s‴ where a ramp starts
        // or ends: a central difference straddling such a knot is only O(h)
        // accurate there (h/4 × the jump ≈ 1e-4), so the points within 2h
        // of a knot are left out; everywhere else it is O(h²).
        let knots = [0.0, 2.5, 3.0, 5.0];
        for k in 1..100 {
            let x = 0.05 * k as f64;
            if knots.iter().any(|knot| (x - knot).abs() < 2.0 * h) {
                continue;
            }
            let (_, d, dd) = entry.weight(x);
            let (sp, dp, _) = entry.weight(x + h);
            let (sm, dm, _) = entry.weight(x - h);
            assert!((d - (sp - sm) / (2.0 * h)).abs() < 1e-6, "s' at {x}");
            assert!((dd - (dp - dm) / (2.0 * h)).abs() < 1e-5, "s'' at {x}");
        }
        assert_eq!(entry.weight(0.0), (0.0, 0.0, 0.0));
        assert_eq!(entry.weight(5.0).0, 0.0);
        // Half-way up the entry ramp: S(1/2) = 1/2, S'(1/2) = 15/8.
        let (s, d, _) = RailEntry { exit: 0.0, ..entry }.weight(1.5);
        assert!((s - 0.5).abs() < 1e-15 && (d - 15.0 / 8.0 / 3.0).abs() < 1e-15);
    }
}
