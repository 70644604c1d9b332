//! Axis ranges, tick labels and the colour scale.

use super::*;
// ---------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------

pub(super) fn usable(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_ABS
}

pub(super) fn usable_log(v: f64) -> bool {
    usable(v) && v >= MIN_LOG
}

/// Minimum and maximum of the values; `(NaN, NaN)` when there are none.
pub(super) fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::NAN, f64::NAN), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// A finite, non-degenerate range covering `[lo, hi]`, widened by `pad` × span on
/// each side. Degenerate inputs (no data, all equal) get a sensible default.
pub(super) fn linear_range(lo: f64, hi: f64, pad: f64) -> Range<f64> {
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return 0.0..1.0;
    }
    let span = hi - lo;
    let mag = lo.abs().max(hi.abs());
    if span <= mag * 1e-9 || span < 1e-200 {
        let c = 0.5 * (lo + hi);
        let h = if c.abs() < 1e-200 { 1.0 } else { 0.1 * c.abs() };
        return (c - h)..(c + h);
    }
    (lo - pad * span)..(hi + pad * span)
}

/// Whole decades covering `[lo, hi]` (both positive), at least one decade wide.
pub(super) fn log_range(lo: f64, hi: f64) -> Range<f64> {
    if !(lo >= MIN_LOG && hi >= lo && hi <= MAX_ABS) {
        return 1.0..10.0;
    }
    let mut a = lo.log10().floor();
    let mut b = hi.log10().ceil();
    if b <= a {
        a -= 1.0;
        b += 1.0;
    }
    10f64.powf(a)..10f64.powf(b)
}

/// Tick label formatter: plain decimals for moderate magnitudes, otherwise
/// scientific notation, with trailing zeros trimmed.
pub(super) fn tick_formatter(range: &Range<f64>, log: bool) -> impl Fn(&f64) -> String + use<> {
    let range = range.clone();
    let span = (range.end - range.start).abs();
    let mag = range.start.abs().max(range.end.abs());
    move |&v: &f64| {
        if log {
            // Plain numbers while the whole axis stays in a readable window,
            // otherwise powers of ten written as 10⁻³ (and 2×10⁻³ between decades).
            return if (1e-3..=1e5).contains(&range.start.min(range.end))
                && (1e-3..=1e5).contains(&mag)
            {
                fixed(v, 6)
            } else {
                pow10(v)
            };
        }
        if !v.is_finite() {
            return String::new();
        }
        if v.abs() <= span * 1e-9 {
            return "0".to_string();
        }
        let span_exp = span.log10().floor();
        if !(1e-3..1e5).contains(&mag) {
            let prec = (mag.log10().floor() - span_exp + 1.0).clamp(0.0, 6.0) as usize;
            sci(v, prec)
        } else {
            let decimals = (3.0 - span_exp).clamp(0.0, 8.0) as usize;
            fixed(v, decimals)
        }
    }
}

pub(super) fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

pub(super) fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    let t = trim_zeros(&s);
    if t == "-0" { "0".into() } else { t.into() }
}

pub(super) fn sci(v: f64, prec: usize) -> String {
    let s = format!("{v:.prec$e}");
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{}", trim_zeros(m), e),
        None => s,
    }
}

/// Viridis colour for `t` in [0, 1] (clamped).
pub(super) fn viridis(t: f64) -> RGBColor {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let scaled = t * (VIRIDIS.len() - 1) as f64;
    let k = (scaled.floor() as usize).min(VIRIDIS.len() - 2);
    let f = scaled - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + (f64::from(q) - f64::from(p)) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}
