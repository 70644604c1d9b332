//! Warm starts shared between the lanes of a lockstep study: the
//! eliminations of the last few contact sets, replayed for every sample
//! whose previous solution had the same set.

#![allow(clippy::needless_range_loop)]

use super::dense::{eliminate, substitute};
use super::{ACCEPT_TOL, LcpError, LcpWorkspace, max_abs, solve, violation};

/// Sets whose eliminations [`SharedWarmStart`] keeps at once.
const SHARED_SETS: usize = 8;

/// One contact set's elimination.
#[derive(Debug, Clone, Default)]
struct SetFactor {
    /// The contact set A.
    active: Vec<usize>,
    /// Whether M_AA was numerically nonsingular.
    regular: bool,
    /// Row exchanged with row c at column c.
    pivots: Vec<usize>,
    /// The eliminated M_AA: multipliers below the diagonal, U above.
    factors: Vec<f64>,
}

/// The warm start of [`super::solve_warm`] for many right-hand sides `q` with one
/// matrix `M` (the lanes of [`crate::solve::lockstep`]): the elimination of M_AA
/// for a contact set A is done once per set and replayed on each `q`, with
/// exactly the operations [`super::dense::gauss_solve`] performs on its right-hand side,
/// so the result is bit-identical to [`super::solve_warm`]'s. Up to
/// [`SHARED_SETS`] sets are kept (lanes that separate differ in their
/// sets). Call [`Self::reset`] whenever `M` changes.
#[derive(Debug, Clone)]
pub struct SharedWarmStart {
    /// Whether `scale`, `finite` and the sets belong to the current `M`.
    valid: bool,
    /// max|Mᵢⱼ| (1 if M = 0), and whether M is finite.
    scale: f64,
    finite: bool,
    /// The eliminations of the current `M`: the first `used` are valid.
    sets: Vec<SetFactor>,
    used: usize,
    /// The slot the next new set replaces once all are used.
    next: usize,
    /// Scratch: this call's contact set and right-hand side.
    set: Vec<usize>,
    rhs: Vec<f64>,
}

impl SharedWarmStart {
    /// Storage for LCPs up to size `n`.
    pub fn new(n: usize) -> Self {
        Self {
            valid: false,
            scale: 1.0,
            finite: true,
            sets: (0..SHARED_SETS)
                .map(|_| SetFactor {
                    active: Vec::with_capacity(n),
                    regular: false,
                    pivots: vec![0; n],
                    factors: vec![0.0; n * n],
                })
                .collect(),
            used: 0,
            next: 0,
            set: Vec::with_capacity(n),
            rhs: vec![0.0; n],
        }
    }

    /// Forgets the eliminations: `M` is about to change.
    pub fn reset(&mut self) {
        self.valid = false;
        self.used = 0;
        self.next = 0;
    }

    /// [`super::solve_warm`] with the elimination of each contact set shared
    /// between calls of the same `m`.
    pub fn solve(
        &mut self,
        m: &[f64],
        q: &[f64],
        z: &mut [f64],
        work: &mut LcpWorkspace,
        previous: &[f64],
    ) -> Result<usize, LcpError> {
        let n = q.len();
        assert_eq!(m.len(), n * n, "lcp: m must be n×n row-major");
        assert_eq!(z.len(), n, "lcp: z must have length n");
        assert_eq!(previous.len(), n, "lcp: previous must have length n");
        if self.rhs.len() < n {
            // Larger than the size it was made for: grow once.
            self.rhs.resize(n, 0.0);
        }
        if !self.valid {
            self.valid = true;
            self.finite = m.iter().all(|x| x.is_finite());
            self.scale = match max_abs(m) {
                a if a > 0.0 => a,
                _ => 1.0,
            };
        }
        if !(self.finite && q.iter().all(|x| x.is_finite())) {
            return Err(LcpError::NonFinite);
        }
        if q.iter().any(|&v| v < 0.0) && previous.iter().any(|&v| v > 0.0) {
            self.set.clear();
            self.set.extend((0..n).filter(|&i| previous[i] > 0.0));
            let slot = match self.sets[..self.used]
                .iter()
                .position(|f| f.active == self.set)
            {
                Some(slot) => slot,
                None => {
                    let slot = if self.used < SHARED_SETS {
                        self.used += 1;
                        self.used - 1
                    } else {
                        let slot = self.next;
                        self.next = (self.next + 1) % SHARED_SETS;
                        slot
                    };
                    let factor = &mut self.sets[slot];
                    factor.active.clone_from(&self.set);
                    factor.eliminate(m, n);
                    slot
                }
            };
            let factor = &self.sets[slot];
            if factor.regular {
                let k = factor.active.len();
                let b = &mut self.rhs[..k];
                for (r, &i) in factor.active.iter().enumerate() {
                    b[r] = -q[i];
                }
                factor.replay(b);
                z.fill(0.0);
                for (r, &i) in factor.active.iter().enumerate() {
                    z[i] = b[r].max(0.0);
                }
                if violation(m, q, z, self.scale) <= ACCEPT_TOL {
                    return Ok(0);
                }
            }
        }
        solve(m, q, z, work)
    }
}

impl SetFactor {
    /// Eliminates M_AA as [`super::dense::gauss_solve`] does, keeping the multipliers
    /// and the row exchanges.
    fn eliminate(&mut self, m: &[f64], n: usize) {
        let k = self.active.len();
        self.pivots.resize(k.max(self.pivots.len()), 0);
        self.factors.resize((k * k).max(self.factors.len()), 0.0);
        let a = &mut self.factors[..k * k];
        for (r, &i) in self.active.iter().enumerate() {
            for (c, &j) in self.active.iter().enumerate() {
                a[r * k + c] = m[i * n + j];
            }
        }
        self.regular = eliminate(a, k, &mut self.pivots);
    }

    /// `gauss_solve`'s operations on the right-hand side `b` (length |A|),
    /// which becomes the solution.
    fn replay(&self, b: &mut [f64]) {
        let k = b.len();
        substitute(&self.factors[..k * k], k, &self.pivots, b);
    }
}
