//! The Monte Carlo study assembled one part at a time (`vbi merge`, issue
//! 27): memory bounded by one part plus the result, whatever the shard count.
//!
//! [`super::assemble`] collects every part's reduced nodes and evaluates each
//! case's fixed tree from the root down. Here the nodes arrive in flat order
//! (case by case, left to right: the parts in shard order, each part's
//! nodes as [`super::run_slice`] writes them) and are kept on a stack; two
//! adjacent nodes on top that are the two halves of one tree node
//! ([lo, mid) and [mid, hi) with mid = lo + (hi − lo)/2) are combined at
//! once by the same Chan update with the same operands in the same order.
//! Every tree node therefore gets the same floating-point value as in the
//! batch evaluation, so the envelopes are bit-identical, and at most one
//! node a tree level (≈ log₂ samples) is alive at any time.

use super::{
    AssembleError, Moments, MonteCarloPart, MonteCarloResults, SampleResult, cases, results,
};
use crate::scene::{MonteCarlo, Scenario};

/// A reduced node waiting for its sibling: samples [lo, hi) of the current case.
struct Pending {
    lo: usize,
    hi: usize,
    moments: Moments,
}

/// Running assembly of a Monte Carlo study from its parts in flat order.
pub struct EnvelopeFold {
    /// Samples per case.
    samples: usize,
    /// Cases of the study.
    cases: usize,
    /// The envelopes of the cases completed, in case order.
    envelopes: Vec<Moments>,
    /// Nodes of the case being folded (case `envelopes.len()`), left to right,
    /// none the sibling of the next.
    stack: Vec<Pending>,
    /// Every sample so far, in flat order.
    sample_results: Vec<SampleResult>,
}

/// Whether [lo, hi) is a node of the fixed tree over [0, samples).
fn is_tree_node(samples: usize, lo: usize, hi: usize) -> bool {
    let (mut a, mut b) = (0, samples);
    loop {
        if (a, b) == (lo, hi) {
            return true;
        }
        if b - a <= 1 {
            return false;
        }
        let mid = a + (b - a) / 2;
        if hi <= mid {
            b = mid;
        } else if lo >= mid {
            a = mid;
        } else {
            return false;
        }
    }
}

impl EnvelopeFold {
    /// An empty fold for the study `mc`.
    pub fn new(mc: &MonteCarlo) -> Self {
        Self {
            samples: mc.samples,
            cases: mc.cases(),
            envelopes: Vec::new(),
            stack: Vec::new(),
            sample_results: Vec::new(),
        }
    }

    /// The next sample index of the current case the fold waits for.
    fn next_sample(&self) -> usize {
        self.stack.last().map_or(0, |p| p.hi)
    }

    /// Folds in the next part (the parts in flat order; each part checked by
    /// [`MonteCarloPart::check`]). A node that does not start where the last
    /// one ended leaves a hole: [`AssembleError::Missing`].
    pub fn push(&mut self, part: MonteCarloPart) -> Result<(), AssembleError> {
        self.sample_results.extend(part.samples);
        for node in part.nodes {
            let case = self.envelopes.len();
            if node.case != case
                || node.lo != self.next_sample()
                || node.hi > self.samples
                || !is_tree_node(self.samples, node.lo, node.hi)
            {
                return Err(AssembleError::Missing {
                    case: case.min(self.cases),
                    sample: self.next_sample() + 1,
                });
            }
            self.stack.push(Pending {
                lo: node.lo,
                hi: node.hi,
                moments: node.moments,
            });
            self.collapse(case)?;
        }
        Ok(())
    }

    /// Combines the top two nodes while they are siblings; a complete case
    /// becomes its envelope.
    fn collapse(&mut self, case: usize) -> Result<(), AssembleError> {
        while self.stack.len() >= 2 {
            let (a, b) = (
                &self.stack[self.stack.len() - 2],
                &self.stack[self.stack.len() - 1],
            );
            let (lo, hi) = (a.lo, b.hi);
            if a.hi != lo + (hi - lo) / 2 || !is_tree_node(self.samples, lo, hi) {
                break;
            }
            if a.moments.names != b.moments.names || a.moments.time.len() != b.moments.time.len() {
                return Err(AssembleError::Shape { case });
            }
            let b = self.stack.pop().expect("two nodes");
            let a = self.stack.pop().expect("two nodes");
            self.stack.push(Pending {
                lo,
                hi,
                moments: Moments::combine(a.moments, &b.moments),
            });
        }
        if let [root] = self.stack.as_slice()
            && (root.lo, root.hi) == (0, self.samples)
        {
            let root = self.stack.pop().expect("the root");
            self.envelopes.push(root.moments);
        }
        Ok(())
    }

    /// The whole study; every case must be complete.
    pub fn finish(
        self,
        base: &Scenario,
        mc: &MonteCarlo,
        wall_time: f64,
    ) -> Result<MonteCarloResults, AssembleError> {
        if self.envelopes.len() < self.cases {
            return Err(AssembleError::Missing {
                case: self.envelopes.len(),
                sample: self.next_sample() + 1,
            });
        }
        Ok(results(
            base,
            mc,
            cases(mc),
            self.sample_results,
            self.envelopes,
            wall_time,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Node, cover, evaluate};
    use super::*;
    use std::collections::HashMap;

    /// Moments of one sample with values that make rounding matter.
    fn leaf(case: usize, k: usize, steps: usize) -> Moments {
        let x = |i: usize| ((k * 7919 + i * 104_729 + case * 31) % 1000) as f64 / 7.0 + 0.1;
        Moments {
            count: 1,
            time: (0..steps).map(|i| i as f64 * 1e-3).collect(),
            names: vec!["a".into(), "b".into()],
            units: vec!["m".into(), "N".into()],
            mean: vec![
                (0..steps).map(x).collect(),
                (0..steps).map(|i| -x(i)).collect(),
            ],
            m2: vec![vec![0.0; steps], vec![0.0; steps]],
        }
    }

    /// The batch tree evaluated over the leaves of [lo, hi).
    fn tree(case: usize, lo: usize, hi: usize) -> Moments {
        if hi - lo == 1 {
            return leaf(case, lo, 3);
        }
        let mid = lo + (hi - lo) / 2;
        Moments::combine(tree(case, lo, mid), &tree(case, mid, hi))
    }

    /// The part a run of flat runs [a, b) writes (its samples left out).
    fn part(cases: usize, samples: usize, a: usize, b: usize) -> MonteCarloPart {
        let mut nodes = Vec::new();
        for case in 0..cases {
            let (lo, hi) = (a.max(case * samples), b.min((case + 1) * samples));
            if lo < hi {
                let mut out = Vec::new();
                cover(
                    0,
                    samples,
                    lo - case * samples,
                    hi - case * samples,
                    &mut out,
                );
                nodes.extend(out.into_iter().map(|(lo, hi)| Node {
                    case,
                    lo,
                    hi,
                    moments: tree(case, lo, hi),
                }));
            }
        }
        MonteCarloPart {
            samples: Vec::new(),
            nodes,
        }
    }

    #[test]
    fn tree_nodes_are_those_of_the_halving_tree() {
        assert!(is_tree_node(5, 0, 5));
        assert!(is_tree_node(5, 0, 2) && is_tree_node(5, 2, 5) && is_tree_node(5, 3, 5));
        assert!(!is_tree_node(5, 1, 3) && !is_tree_node(5, 0, 3) && !is_tree_node(5, 2, 4));
        assert!(is_tree_node(1, 0, 1) && is_tree_node(5, 4, 5) && is_tree_node(5, 1, 2));
    }

    /// For every split of a study into N contiguous shards, the streaming fold
    /// gives the batch evaluation's envelopes bit for bit, and a missing
    /// shard is reported as a hole.
    #[test]
    fn streaming_fold_equals_the_batch_tree_for_every_split() {
        for samples in [1, 2, 3, 7, 16, 33] {
            let cases = 2;
            let size = cases * samples;
            for shards in 1..=size.min(12) {
                let bounds: Vec<usize> = (0..=shards).map(|k| k * size / shards).collect();
                let parts: Vec<MonteCarloPart> = bounds
                    .windows(2)
                    .map(|w| part(cases, samples, w[0], w[1]))
                    .collect();
                // The batch evaluation, as `assemble` does it.
                let mut given = HashMap::new();
                for p in &parts {
                    for n in &p.nodes {
                        given.insert((n.case, n.lo, n.hi), n.moments.clone());
                    }
                }
                let batch: Vec<Moments> = (0..cases)
                    .map(|c| evaluate(c, 0, samples, &mut given).unwrap())
                    .collect();
                let mut fold = EnvelopeFold {
                    samples,
                    cases,
                    envelopes: Vec::new(),
                    stack: Vec::new(),
                    sample_results: Vec::new(),
                };
                let mut alive = 0;
                for p in parts.iter().cloned() {
                    fold.push(p).unwrap();
                    alive = alive.max(fold.stack.len());
                }
                assert!(fold.stack.is_empty());
                let bits = |m: &[Moments]| -> Vec<u64> {
                    m.iter()
                        .flat_map(|m| m.mean.iter().chain(&m.m2).flatten())
                        .map(|x| x.to_bits())
                        .collect()
                };
                assert_eq!(fold.envelopes.len(), cases);
                assert_eq!(
                    bits(&fold.envelopes),
                    bits(&batch),
                    "{samples} samples, {shards} shards"
                );
                assert_eq!(fold.envelopes, batch);
                // At most one pending node a tree level (plus the new one).
                let depth = (samples as f64).log2().ceil() as usize + 1;
                assert!(alive <= depth, "{alive} nodes alive for {samples} samples");
                if shards > 1 {
                    // A shard left out: the hole is found.
                    let mut fold = EnvelopeFold {
                        samples,
                        cases,
                        envelopes: Vec::new(),
                        stack: Vec::new(),
                        sample_results: Vec::new(),
                    };
                    let skipped = parts
                        .iter()
                        .cloned()
                        .enumerate()
                        .filter(|(k, _)| *k != 1)
                        .try_for_each(|(_, p)| fold.push(p));
                    assert!(
                        matches!(skipped, Err(AssembleError::Missing { .. }))
                            || fold.envelopes.len() < cases,
                        "{samples} samples, {shards} shards"
                    );
                }
            }
        }
    }
}
