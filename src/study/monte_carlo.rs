//! Monte Carlo study over random surface profiles (the LCP separation
//! paper, Section 5.2 and Figs. 7–9).
//!
//! The study is a list of runs: cases (surface × speed, surface-major) each
//! run `samples` times, flat index `case · samples + k`. Sample k (from 0)
//! of every case is the scene with its random surface reseeded by
//! [`sample_seed`]`(seed, k)`, so any sample re-runs alone (`vbi run
//! --sample K`) and the seeds do not depend on the thread count.
//!
//! Per case, the histories are reduced into running moments (count, mean,
//! sum of squared deviations; Chan, Golub & LeVeque's pairwise update) over a
//! fixed binary tree of the sample indices: node [lo, hi) combines [lo, mid)
//! and [mid, hi) with mid = lo + (hi − lo)/2. The tree depends only on the
//! sample count, so the floating-point result is the same whatever the
//! thread count, and a shard (a contiguous slice of the flat list) reduces
//! the largest whole nodes inside its slice: merging shards evaluates the
//! same tree and is bit-identical to the unsharded run. Per-sample scalars
//! (separation, largest gap) are kept per sample and reduced in sample order
//! when the report is written.

mod fold;
pub mod report;
mod tree;

use std::collections::HashMap;
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde::{Deserialize, Serialize};

use super::speed_sweep;
use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::run::RunError;
use crate::scenario::sweep;
use crate::scene::{MonteCarlo, Scenario, SweepRoughness};
use crate::solve;

use self::tree::{Reduced, cover, reduce, run_batch};

pub use self::fold::EnvelopeFold;
pub use self::report::write;

/// The seed of sample `index` (from 0): the (index + 1)-th output of
/// SplitMix64 started from `study_seed` (Steele, Lea & Flood, "Fast
/// splittable pseudorandom number generators", OOPSLA 2014; the generator of
/// `java.util.SplittableRandom`). Its output function is a bijective mixer,
/// so neighbouring samples get unrelated seeds and distinct indices distinct
/// seeds.
pub fn sample_seed(study_seed: u64, index: usize) -> u64 {
    let mut z = study_seed.wrapping_add((index as u64).wrapping_add(1).wrapping_mul(GOLDEN_GAMMA));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// SplitMix64's increment, ⌊2⁶⁴/φ⌋ (odd).
const GOLDEN_GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

/// One case of the study: a surface at a speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case {
    /// The surface (`None`: the scene's own random surface).
    pub entry: Option<SweepRoughness>,
    /// Index of the surface in the study's list (0 for the scene's own).
    pub roughness: usize,
    /// Speed of every vehicle, m/s (`None`: the scene's own speeds).
    pub speed: Option<f64>,
}

/// The cases of `mc`, surface by surface, speed by speed.
pub fn cases(mc: &MonteCarlo) -> Vec<Case> {
    let entries = sweep::entries_of(mc.roughness.as_deref());
    let speeds: Vec<Option<f64>> = match &mc.speeds {
        None => vec![None],
        Some(g) => g.values().into_iter().map(Some).collect(),
    };
    entries
        .iter()
        .enumerate()
        .flat_map(|(r, &entry)| {
            speeds.iter().map(move |&speed| Case {
                entry,
                roughness: r,
                speed,
            })
        })
        .collect()
}

/// The scene of sample `index` (from 0) of `case`: the vehicles at the
/// case's speed, the case's surface reseeded with [`sample_seed`], no study.
pub fn sample_scenario(
    base: &Scenario,
    bridge: &ModalBridge,
    mc: &MonteCarlo,
    case: Case,
    index: usize,
) -> Scenario {
    let mut scenario = match case.speed {
        Some(v) => speed_sweep::point_scenario(base, bridge, case.entry, 0, v),
        None => {
            let mut s = base.clone();
            s.study = None;
            s.surface = sweep::surface(&base.surface, case.entry, 0, base.bridge.length());
            s
        }
    };
    scenario.surface = scenario.surface.reseeded(sample_seed(mc.seed, index));
    scenario
}

/// Separation of one wheel in one sample.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WheelOutcome {
    /// Vehicle number from 1.
    pub vehicle: usize,
    /// Wheel number from 1.
    pub wheel: usize,
    /// Whether the wheel lost contact (zero contact force with a gap above
    /// [`crate::contact::SEPARATION_GAP`]) at any step.
    pub separated: bool,
    /// Largest gap between wheel and surface, m (0 if never separated).
    pub max_gap: f64,
}

/// One sample's scalar results.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SampleResult {
    /// Case index.
    pub case: usize,
    /// Sample number from 1.
    pub sample: usize,
    /// Seed of the sample's profile.
    pub seed: u64,
    /// Per wheel with a DOF, under unilateral contact (empty under
    /// permanent contact).
    pub wheels: Vec<WheelOutcome>,
    /// The recorded histories, for the first `show` samples of the first case only
    /// (drawn in grey behind the envelopes).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub histories: Option<Vec<Vec<f64>>>,
    /// What vbi knows about this point's run ([`crate::advice`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub advice: Vec<crate::advice::Advice>,
}

/// Running moments of every recorded history over a set of samples.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Moments {
    /// Samples combined.
    pub count: usize,
    /// Time axis, s (the same for every sample of a case).
    pub time: Vec<f64>,
    /// Record names.
    pub names: Vec<String>,
    /// Units of the records.
    pub units: Vec<String>,
    /// Mean per record per step.
    pub mean: Vec<Vec<f64>>,
    /// Sum of squared deviations from the mean per record per step.
    pub m2: Vec<Vec<f64>>,
}

impl Moments {
    /// Combines two disjoint sets (Chan, Golub & LeVeque 1979):
    /// δ = x̄_b − x̄_a, x̄ = x̄_a + δ n_b/n, M₂ = M₂a + M₂b + δ² n_a n_b / n.
    fn combine(a: Moments, b: &Moments) -> Moments {
        let (na, nb) = (a.count as f64, b.count as f64);
        let n = na + nb;
        let (wb, wab) = (nb / n, na * nb / n);
        let mut out = a;
        for (c, (mean, m2)) in out.mean.iter_mut().zip(&mut out.m2).enumerate() {
            for (i, (m, s)) in mean.iter_mut().zip(m2.iter_mut()).enumerate() {
                let (mb, sb) = (b.mean[c][i], b.m2[c][i]);
                let delta = mb - *m;
                *m += delta * wb;
                *s += sb + delta * delta * wab;
            }
        }
        out.count += b.count;
        out
    }

    /// Sample standard deviation per record per step, √(M₂/(n − 1)) (0 for
    /// one sample).
    pub fn std_dev(&self) -> Vec<Vec<f64>> {
        let n = self.count as f64;
        self.m2
            .iter()
            .map(|c| {
                c.iter()
                    .map(|&s| if n > 1.0 { (s / (n - 1.0)).sqrt() } else { 0.0 })
                    .collect()
            })
            .collect()
    }
}

/// A reduced node of a case's tree: samples [lo, hi) (indices from 0).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Node {
    /// Case index.
    pub case: usize,
    /// First sample index.
    pub lo: usize,
    /// One past the last sample index.
    pub hi: usize,
    /// The moments over the node's samples.
    pub moments: Moments,
}

/// What a slice of the study produces: its samples in flat order and the
/// whole tree nodes it covers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MonteCarloPart {
    /// Samples in flat order.
    pub samples: Vec<SampleResult>,
    /// Largest whole tree nodes inside the slice, case by case.
    pub nodes: Vec<Node>,
}

/// The whole study.
#[derive(Debug, Clone, PartialEq)]
pub struct MonteCarloResults {
    /// The cases.
    pub cases: Vec<Case>,
    /// Label of each case's surface.
    pub labels: Vec<String>,
    /// The scene's speed per case, m/s, when no `speeds` are swept: the first
    /// vehicle's (`None` with no vehicle).
    pub own_speed: Option<f64>,
    /// Samples per case.
    pub samples: usize,
    /// Study seed.
    pub seed: u64,
    /// Sample histories drawn in grey.
    pub show: usize,
    /// Every sample, in flat order.
    pub sample_results: Vec<SampleResult>,
    /// Per case, the moments over all its samples.
    pub envelopes: Vec<Moments>,
    /// Wall time of all runs, s (summed over shards when merged).
    pub wall_time: f64,
}

/// Why the parts of a study do not make the whole study.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AssembleError {
    /// Two parts reduced different records or time axes for one case.
    #[error("the parts disagree on the records or time steps of case {case}")]
    Shape {
        /// Case index.
        case: usize,
    },
    /// A sample is in no part.
    #[error("sample {sample} of case {case} is in no part")]
    Missing {
        /// Case index.
        case: usize,
        /// Sample number from 1.
        sample: usize,
    },
}

/// Total runs of the study: cases × samples.
pub fn size(mc: &MonteCarlo) -> usize {
    mc.cases().saturating_mul(mc.samples)
}

/// Runs the runs `range` of the flat list (the whole study: `0..size`) in
/// parallel. `progress` gets (runs done, runs in the range).
pub fn run_slice(
    base: &Scenario,
    bridge: &ModalBridge,
    mc: &MonteCarlo,
    range: Range<usize>,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<MonteCarloPart, RunError> {
    let cases = cases(mc);
    let s = mc.samples;
    let mut jobs = Vec::new();
    for case in 0..cases.len() {
        let (a, b) = (
            range.start.max(case * s) - case * s,
            range.end.min((case + 1) * s).saturating_sub(case * s),
        );
        if a < b {
            let mut nodes = Vec::new();
            cover(0, s, a, b, &mut nodes);
            jobs.extend(nodes.into_iter().map(|(lo, hi)| (case, lo, hi)));
        }
    }
    let total = range.len();
    let done = AtomicUsize::new(0);
    let token = crate::solve::cancel::current();
    let reduced: Vec<(usize, usize, usize, Reduced)> = {
        use rayon::prelude::*;
        jobs.par_iter()
            .map(|&(case, lo, hi)| {
                let batch = |ks: Range<usize>| {
                    let count = ks.len();
                    let r = crate::solve::cancel::in_scope(token.as_ref(), || {
                        crate::solve::cancel::check()?;
                        run_batch(
                            base,
                            bridge,
                            mc,
                            &cases,
                            case * s + ks.start..case * s + ks.end,
                        )
                    });
                    progress(done.fetch_add(count, Ordering::Relaxed) + count, total);
                    r
                };
                // Batches only where the samples step in lockstep: a scene
                // run sample by sample keeps one sample per task, so every
                // thread has work even in a small study.
                let width = match Model::build(
                    &sample_scenario(base, bridge, mc, cases[case], lo),
                    bridge.clone(),
                ) {
                    Ok(model) if solve::lockstep::eligible(&model) => solve::lockstep::LANES,
                    _ => 1,
                };
                reduce(lo, hi, width, &batch).map(|r| (case, lo, hi, r))
            })
            .collect::<Result<_, _>>()?
    };
    let mut part = MonteCarloPart {
        samples: Vec::new(),
        nodes: Vec::with_capacity(reduced.len()),
    };
    for (case, lo, hi, (moments, samples)) in reduced {
        part.samples.extend(samples);
        part.nodes.push(Node {
            case,
            lo,
            hi,
            moments,
        });
    }
    Ok(part)
}

impl MonteCarloPart {
    /// Checks that the part holds what a run of the slice `range` of `mc`
    /// writes: one sample per index in order, every node whole inside the
    /// slice and of one shape (records × steps), the same wheels in every
    /// sample. A part file is input: nothing downstream indexes past what
    /// this checks.
    pub fn check(&self, mc: &MonteCarlo, range: Range<usize>) -> Result<(), String> {
        let s = mc.samples.max(1);
        if self.samples.len() != range.len() {
            return Err(format!(
                "it holds {} samples for the {} runs {}..{}",
                self.samples.len(),
                range.len(),
                range.start,
                range.end
            ));
        }
        let wheels: Vec<(usize, usize)> = self
            .samples
            .first()
            .map(|r| r.wheels.iter().map(|w| (w.vehicle, w.wheel)).collect())
            .unwrap_or_default();
        for (flat, r) in range.clone().zip(&self.samples) {
            if (r.case, r.sample) != (flat / s, flat % s + 1) {
                return Err(format!(
                    "run {flat} should be sample {} of case {}, it is sample {} of case {}",
                    flat % s + 1,
                    flat / s,
                    r.sample,
                    r.case
                ));
            }
            let these: Vec<(usize, usize)> =
                r.wheels.iter().map(|w| (w.vehicle, w.wheel)).collect();
            if these != wheels {
                return Err(format!(
                    "run {flat} has other wheels than the part's first run"
                ));
            }
        }
        for node in &self.nodes {
            let (a, b) = (node.case * s + node.lo, node.case * s + node.hi);
            let m = &node.moments;
            let shaped = |rows: &Vec<Vec<f64>>| {
                rows.len() == m.names.len() && rows.iter().all(|r| r.len() == m.time.len())
            };
            if node.lo >= node.hi
                || node.hi > s
                || a < range.start
                || b > range.end
                || m.count != node.hi - node.lo
                || m.units.len() != m.names.len()
                || !shaped(&m.mean)
                || !shaped(&m.m2)
            {
                return Err(format!(
                    "its reduction node (case {}, samples {}..{}) does not fit its slice or its shape",
                    node.case, node.lo, node.hi
                ));
            }
        }
        // Exactly the nodes a run of the slice reduces, in order: the merge
        // folds them as they come (`EnvelopeFold`).
        let mut expected = Vec::new();
        if !range.is_empty() {
            for case in range.start / s..=(range.end - 1) / s {
                let (a, b) = (range.start.max(case * s), range.end.min((case + 1) * s));
                let mut nodes = Vec::new();
                cover(0, s, a - case * s, b - case * s, &mut nodes);
                expected.extend(nodes.into_iter().map(|(lo, hi)| (case, lo, hi)));
            }
        }
        let given = self.nodes.iter().map(|n| (n.case, n.lo, n.hi));
        if !given.eq(expected.iter().copied()) {
            return Err(format!(
                "its reduction nodes are not the {} whole tree nodes of runs {}..{}",
                expected.len(),
                range.start,
                range.end
            ));
        }
        Ok(())
    }
}

/// Evaluates the tree of one case from the given nodes.
fn evaluate(
    case: usize,
    lo: usize,
    hi: usize,
    given: &mut HashMap<(usize, usize, usize), Moments>,
) -> Result<Moments, AssembleError> {
    if let Some(m) = given.remove(&(case, lo, hi)) {
        return Ok(m);
    }
    if hi - lo <= 1 {
        return Err(AssembleError::Missing {
            case,
            sample: lo + 1,
        });
    }
    let mid = lo + (hi - lo) / 2;
    let a = evaluate(case, lo, mid, given)?;
    let b = evaluate(case, mid, hi, given)?;
    if a.names != b.names || a.time.len() != b.time.len() {
        return Err(AssembleError::Shape { case });
    }
    Ok(Moments::combine(a, &b))
}

/// The whole study from its parts in flat order (one part: the unsharded
/// run). The parts must cover every sample once (checked by the caller's
/// index bookkeeping; a hole gives [`AssembleError::Missing`]).
pub fn assemble(
    base: &Scenario,
    mc: &MonteCarlo,
    parts: Vec<MonteCarloPart>,
    wall_time: f64,
) -> Result<MonteCarloResults, AssembleError> {
    let cases = cases(mc);
    let mut given = HashMap::new();
    let mut sample_results = Vec::new();
    for part in parts {
        sample_results.extend(part.samples);
        for node in part.nodes {
            given.insert((node.case, node.lo, node.hi), node.moments);
        }
    }
    let envelopes = (0..cases.len())
        .map(|c| evaluate(c, 0, mc.samples, &mut given))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(results(
        base,
        mc,
        cases,
        sample_results,
        envelopes,
        wall_time,
    ))
}

/// The study's results from its cases, every sample's result and each
/// case's envelope moments (the batch [`assemble`] and the streaming
/// [`fold::EnvelopeFold`] end here alike).
fn results(
    base: &Scenario,
    mc: &MonteCarlo,
    cases: Vec<Case>,
    sample_results: Vec<SampleResult>,
    envelopes: Vec<Moments>,
    wall_time: f64,
) -> MonteCarloResults {
    let labels = cases
        .iter()
        .map(|c| sweep::label(&base.surface, c.entry))
        .collect();
    MonteCarloResults {
        labels,
        own_speed: base.vehicles.first().map(|v| v.speed()),
        cases,
        samples: mc.samples,
        seed: mc.seed,
        show: mc.show,
        sample_results,
        envelopes,
        wall_time,
    }
}

/// Runs the whole study (in parallel) and assembles it.
pub fn run(
    base: &Scenario,
    bridge: &ModalBridge,
    mc: &MonteCarlo,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<MonteCarloResults, RunError> {
    let start = std::time::Instant::now();
    let part = run_slice(base, bridge, mc, 0..size(mc), progress)?;
    let wall_time = start.elapsed().as_secs_f64();
    Ok(assemble(base, mc, vec![part], wall_time).expect("the whole study covers every sample"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_are_splitmix64_outputs() {
        // SplitMix64 from state 0: first outputs as printed by the reference
        // C implementation (Vigna, prng.di.unimi.it/splitmix64.c).
        assert_eq!(sample_seed(0, 0), 0xE220_A839_7B1D_CDAF);
        assert_eq!(sample_seed(0, 1), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(sample_seed(0, 2), 0x06C4_5D18_8009_454F);
    }

    #[test]
    fn cover_tiles_the_slice_with_whole_nodes() {
        for n in 1..40 {
            for a in 0..n {
                for b in a + 1..=n {
                    let mut nodes = Vec::new();
                    cover(0, n, a, b, &mut nodes);
                    let mut at = a;
                    for &(lo, hi) in &nodes {
                        assert_eq!(lo, at);
                        at = hi;
                    }
                    assert_eq!(at, b);
                }
            }
        }
    }

    #[test]
    fn chan_update_matches_two_pass_moments() {
        let xs = [1.0, 4.0, 2.5, -3.0, 7.25];
        let leaf = |x: f64| Moments {
            count: 1,
            time: vec![0.0],
            names: vec!["a".into()],
            units: vec!["m".into()],
            mean: vec![vec![x]],
            m2: vec![vec![0.0]],
        };
        let mut m = leaf(xs[0]);
        for &x in &xs[1..] {
            m = Moments::combine(m, &leaf(x));
        }
        let mean = xs.iter().sum::<f64>() / 5.0;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 4.0;
        assert!((m.mean[0][0] - mean).abs() < 1e-14);
        assert!((m.std_dev()[0][0] - var.sqrt()).abs() < 1e-13);
    }
}
