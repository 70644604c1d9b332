//! Resolving `surface: {type: random}`: the roughness class or coefficient
//! and the sampling of the series.

use super::raw::RoughnessClassRaw;
use super::resolve::Checker;
use super::resolved::Surface;

/// Shortest wavelength the default series resolves, m.
pub const DEFAULT_SHORTEST_WAVELENGTH: f64 = 0.5;
/// Largest number of series terms.
pub const MAX_TERMS: usize = 1_000_000;

impl RoughnessClassRaw {
    /// A_r of the class, m³/cycle: the geometric mean of its range (the plate
    /// paper's Table 5 after its ref. [31]: very good 2–8, good 8–32, average
    /// 32–128, poor 128–512, very poor 512–2048, all × 1e-6 m³/cycle).
    pub fn coefficient(self) -> f64 {
        match self {
            RoughnessClassRaw::VeryGood => 4e-6,
            RoughnessClassRaw::Good => 16e-6,
            RoughnessClassRaw::Average => 64e-6,
            RoughnessClassRaw::Poor => 256e-6,
            RoughnessClassRaw::VeryPoor => 1024e-6,
        }
    }

    /// The class's name as written in the format.
    pub fn name(self) -> &'static str {
        match self {
            RoughnessClassRaw::VeryGood => "very_good",
            RoughnessClassRaw::Good => "good",
            RoughnessClassRaw::Average => "average",
            RoughnessClassRaw::Poor => "poor",
            RoughnessClassRaw::VeryPoor => "very_poor",
        }
    }
}

/// Resolves a random profile over a bridge of length `bridge_length` (m).
pub(super) fn resolve_random(
    class: Option<RoughnessClassRaw>,
    coefficient: Option<f64>,
    sampling_length: Option<f64>,
    terms: Option<usize>,
    seed: Option<u64>,
    bridge_length: f64,
    ck: &mut Checker<'_>,
) -> Surface {
    let coefficient = match (class, coefficient) {
        (Some(_), Some(_)) => {
            ck.error(
                "surface.coefficient",
                "give the roughness `class` or its `coefficient`, not both",
            );
            0.0
        }
        (Some(c), None) => c.coefficient(),
        (None, Some(a)) => {
            ck.non_negative("surface.coefficient", a, "roughness coefficient");
            a
        }
        (None, None) => {
            ck.error(
                "surface",
                "a random surface needs a roughness `class` (very_good … very_poor) or a \
                 `coefficient` A_r (m³/cycle)",
            );
            0.0
        }
    };
    let sampling_length = sampling_length.unwrap_or(2.0 * bridge_length);
    ck.positive(
        "surface.sampling_length",
        sampling_length,
        "sampling length",
    );
    let terms = terms.unwrap_or_else(|| {
        ((sampling_length / DEFAULT_SHORTEST_WAVELENGTH).round() as usize).clamp(1, MAX_TERMS)
    });
    if !(1..=MAX_TERMS).contains(&terms) {
        ck.error(
            "surface.terms",
            format!("the series needs between 1 and {MAX_TERMS} terms, got {terms}"),
        );
    }
    Surface::Random {
        class,
        coefficient,
        sampling_length,
        terms,
        seed: seed.unwrap_or(1),
    }
}
