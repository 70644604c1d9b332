//! Random profiles by the spectral representation (trigonometric series).
//!
//! r(x) = Σᵢ aᵢ cos(Ωᵢ x + θᵢ), i = 1…N, over the band
//! [Ω_lo, Ω_hi] = [2π/λ_max, 2π/λ_min] split into N bins of equal width in
//! log Ω (bin i: [e_{i−1}, e_i], e_i = Ω_lo (Ω_hi/Ω_lo)^(i/N)). In each bin the
//! frequency Ωᵢ is uniform in the bin, the phase θᵢ uniform on [0, 2π), and
//! aᵢ = √(2 G(Ωᵢ) ΔΩᵢ) with G the one-sided PSD and ΔΩᵢ the bin width
//! (the spectral representation of Shinozuka & Deodatis 1991, Appl. Mech.
//! Rev. 44(4), with a random frequency inside each
//! bin). Then E[aᵢ²/2] = E[G(Ωᵢ)] ΔΩᵢ = ∫_bin G dΩ exactly: the ensemble
//! variance is ∫ G over the band and the ensemble PSD is G at every Ω in the
//! band (no discretisation bias even for the steep Ω⁻⁴ low end of the rail
//! spectra, and no period); log bins resolve that low end with few terms.
//! The draws come from one ChaCha8 stream per rail (stream 0 left, 1
//! right), seeded by the surface seed: per bin first the frequency, then
//! the phase, each from the top 53 bits of one 64-bit word.

use std::f64::consts::PI;

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};

use super::interp::Triple;
use crate::scene::Spectrum;

/// Uniform sample in [0, 1) from the top 53 bits of a 64-bit draw.
pub(super) fn uniform(rng: &mut ChaCha8Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// The terms of one sample of a random profile.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectralSeries {
    /// (Ωᵢ rad/m, aᵢ m, θᵢ rad) per term.
    terms: Vec<(f64, f64, f64)>,
}

impl SpectralSeries {
    /// Draws a sample of `spectrum` over wavelengths `shortest`…`longest`
    /// (m) with `terms` terms from ChaCha8 `seed`, `stream`.
    pub fn new(
        spectrum: &Spectrum,
        shortest: f64,
        longest: f64,
        terms: usize,
        seed: u64,
        stream: u64,
    ) -> Self {
        let (lo, hi) = (2.0 * PI / longest, 2.0 * PI / shortest);
        let ratio = hi / lo;
        let edge = |i: usize| lo * ratio.powf(i as f64 / terms as f64);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(stream);
        let terms = (0..terms)
            .map(|i| {
                let (a, b) = (edge(i), edge(i + 1));
                let omega = a + (b - a) * uniform(&mut rng);
                let phase = 2.0 * PI * uniform(&mut rng);
                let amplitude = (2.0 * spectrum.density(omega) * (b - a)).sqrt();
                (omega, amplitude, phase)
            })
            .collect();
        Self { terms }
    }

    /// A series of given terms (Ωᵢ rad/m, aᵢ m, θᵢ rad): r = Σ aᵢ cos(Ωᵢ x + θᵢ).
    pub fn from_terms(terms: Vec<(f64, f64, f64)>) -> Self {
        Self { terms }
    }

    /// (r, r′, r″) at `x` by summing every term: O(N), for checks.
    pub fn at(&self, x: f64) -> Triple {
        self.terms
            .iter()
            .fold((0.0, 0.0, 0.0), |(r, s, c), &(w, a, p)| {
                let (sin, cos) = (w * x + p).sin_cos();
                (r + a * cos, s - a * w * sin, c - a * w * w * cos)
            })
    }

    /// Σ aᵢ²/2: this sample's variance over an infinite line, m².
    pub fn variance(&self) -> f64 {
        self.terms.iter().map(|t| t.1 * t.1 / 2.0).sum()
    }

    /// (r, r′, r″) at x_j = start + j·spacing, j < count: each term's angle
    /// advanced by one complex rotation per node (re-anchored every 512
    /// nodes so round-off stays near 1e-13), O(N · count) multiply-adds.
    /// Terms go eight at a time, so eight independent rotations overlap in
    /// the pipeline (one alone is a serial chain of multiply-adds).
    /// Fails only if the memory for `count` nodes cannot be had.
    pub fn sample(
        &self,
        start: f64,
        spacing: f64,
        count: usize,
    ) -> Result<Vec<Triple>, std::collections::TryReserveError> {
        const ANCHOR: usize = 512;
        const LANES: usize = 8;
        let mut nodes = Vec::new();
        nodes.try_reserve_exact(count)?;
        nodes.resize(count, (0.0, 0.0, 0.0));
        for group in self.terms.chunks(LANES) {
            // Missing lanes of the last group carry a zero amplitude.
            let mut lane = [(0.0, 0.0, 0.0); LANES];
            lane[..group.len()].copy_from_slice(group);
            let step: [(f64, f64); LANES] = lane.map(|(w, _, _)| (w * spacing).sin_cos());
            let a = lane.map(|t| t.1);
            let aw = lane.map(|t| t.1 * t.0);
            let aww = lane.map(|t| t.1 * t.0 * t.0);
            for (block, chunk) in nodes.chunks_mut(ANCHOR).enumerate() {
                let x = start + (block * ANCHOR) as f64 * spacing;
                let mut rot: [(f64, f64); LANES] = lane.map(|(w, _, p)| (w * x + p).sin_cos());
                for node in chunk {
                    let (mut value, mut slope, mut curvature) = (0.0, 0.0, 0.0);
                    for k in 0..LANES {
                        let (sin, cos) = rot[k];
                        value += a[k] * cos;
                        slope += aw[k] * sin;
                        curvature += aww[k] * cos;
                        let (ss, sc) = step[k];
                        rot[k] = (sin * sc + cos * ss, cos * sc - sin * ss);
                    }
                    node.0 += value;
                    node.1 -= slope;
                    node.2 -= curvature;
                }
            }
        }
        Ok(nodes)
    }
}

pub use crate::scene::default_terms;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_sampling_equals_the_direct_sum() {
        let s = SpectralSeries::new(&Spectrum::Fra { class: 4 }, 1.0, 80.0, 190, 7, 0);
        let nodes = s.sample(0.0, 0.1, 1500).unwrap();
        for j in [0, 1, 511, 512, 513, 1499] {
            let (r, sl, c) = s.at(0.1 * j as f64);
            let (gr, gs, gc) = nodes[j];
            assert!((r - gr).abs() < 1e-12 && (sl - gs).abs() < 1e-11 && (c - gc).abs() < 1e-10);
        }
    }
}
