//! Sparse symmetric matrices and their LDLᵀ factorisation (faer), the base of
//! the shift-invert eigen solver, the inertia (Sturm) count and static solves.
//!
//! A factorisation of A = K − σM is computed once with a fill-reducing
//! ordering (approximate minimum degree) and reused for every solve. Its
//! diagonal D gives the inertia: by Sylvester's law of inertia the number of
//! negative pivots equals the number of eigenvalues of K φ = λ M φ below σ
//! (Bathe, Finite Element Procedures, §11.4.3, the Sturm sequence check).
//! Everything runs sequentially (`Par::Seq`), so results are bit-identical
//! whatever the thread count.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::ldlt::factor::{LdltParams, LdltRegularization};
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, LdltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
    factorize_symbolic_cholesky, supernodal,
};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, MatMut, Par, Side, Spec};

use crate::bridge::BridgeError;

/// A symmetric sparse matrix stored in full (both triangles), compressed
/// columns, `usize` indices.
pub type SymmetricSparse = SparseColMat<usize, f64>;

/// Builds a symmetric sparse matrix of order `n` from (row, column, value)
/// entries of one triangle or both; duplicates are summed and every entry
/// off the diagonal is mirrored. Cost O(entries · log entries).
pub fn symmetric_from_entries(
    n: usize,
    entries: impl IntoIterator<Item = (usize, usize, f64)>,
    mirror: bool,
) -> Result<SymmetricSparse, BridgeError> {
    let mut triplets = Vec::new();
    for (row, col, value) in entries {
        triplets.push(Triplet::new(row, col, value));
        if mirror && row != col {
            triplets.push(Triplet::new(col, row, value));
        }
    }
    SparseColMat::try_new_from_triplets(n, n, &triplets).map_err(|_| BridgeError::OutOfMemory)
}

/// y = A x for a sparse A (sequential, deterministic). Cost O(nnz).
pub fn multiply(matrix: &SymmetricSparse, x: &[f64], y: &mut [f64]) {
    y.fill(0.0);
    let col_ptr = matrix.symbolic().col_ptr();
    let row_idx = matrix.symbolic().row_idx();
    let values = matrix.val();
    for (j, &xj) in x.iter().enumerate() {
        if xj == 0.0 {
            continue;
        }
        for p in col_ptr[j]..col_ptr[j + 1] {
            y[row_idx[p]] += values[p] * xj;
        }
    }
}

/// A − σB on the union of both patterns.
pub fn shifted(
    a: &SymmetricSparse,
    b: &SymmetricSparse,
    shift: f64,
) -> Result<SymmetricSparse, BridgeError> {
    combination(a, 1.0, b, -shift)
}

/// c_a A + c_b B on the union of both patterns (entries in A's then B's
/// order, summed where they meet). Cost O(nnz(A) + nnz(B)).
///
/// # Errors
///
/// [`BridgeError::OutOfMemory`] when the combined pattern cannot be held.
pub fn combination(
    a: &SymmetricSparse,
    scale_a: f64,
    b: &SymmetricSparse,
    scale_b: f64,
) -> Result<SymmetricSparse, BridgeError> {
    let n = a.nrows();
    let mut entries = Vec::with_capacity(a.compute_nnz() + b.compute_nnz());
    for (matrix, scale) in [(a, scale_a), (b, scale_b)] {
        let col_ptr = matrix.symbolic().col_ptr();
        let row_idx = matrix.symbolic().row_idx();
        let values = matrix.val();
        for j in 0..n {
            for p in col_ptr[j]..col_ptr[j + 1] {
                entries.push(Triplet::new(row_idx[p], j, scale * values[p]));
            }
        }
    }
    SparseColMat::try_new_from_triplets(n, n, &entries).map_err(|_| BridgeError::OutOfMemory)
}

/// An LDLᵀ factorisation of a sparse symmetric matrix, with its inertia.
#[derive(Debug)]
pub struct Factor {
    symbolic: SymbolicCholesky<usize>,
    values: Vec<f64>,
    /// Number of negative pivots of D.
    negative_pivots: usize,
    solve_scratch: faer::dyn_stack::StackReq,
}

impl Factor {
    /// Factorises the symmetric `matrix` as P A Pᵀ = L D Lᵀ (no pivoting
    /// beyond the fill-reducing P; an indefinite A is fine as long as no
    /// pivot vanishes). Cost: one symbolic analysis and one numeric
    /// factorisation, O(nnz(L)) memory.
    pub fn new(matrix: &SymmetricSparse) -> Result<Self, BridgeError> {
        let par = Par::Seq;
        let symbolic = factorize_symbolic_cholesky(
            matrix.symbolic(),
            Side::Lower,
            SymmetricOrdering::Amd,
            CholeskySymbolicParams::default(),
        )
        .map_err(|_| BridgeError::OutOfMemory)?;
        let mut values = Vec::new();
        values
            .try_reserve_exact(symbolic.len_val())
            .map_err(|_| BridgeError::OutOfMemory)?;
        values.resize(symbolic.len_val(), 0.0);
        let params: Spec<LdltParams, f64> = Default::default();
        let mut buffer =
            MemBuffer::try_new(symbolic.factorize_numeric_ldlt_scratch::<f64>(par, params))
                .map_err(|_| BridgeError::OutOfMemory)?;
        symbolic
            .factorize_numeric_ldlt(
                &mut values,
                matrix.as_ref(),
                Side::Lower,
                LdltRegularization::default(),
                par,
                MemStack::new(&mut buffer),
                params,
            )
            .map_err(|_| BridgeError::SingularShift)?;
        let pivots = pivots(&symbolic, &values);
        let negative_pivots = pivots.iter().filter(|&&d| d < 0.0).count();
        let largest = pivots.iter().fold(0.0f64, |m, d| m.max(d.abs()));
        let smallest = pivots.iter().fold(f64::INFINITY, |m, d| m.min(d.abs()));
        if !(largest.is_finite() && smallest > 0.0) {
            return Err(BridgeError::SingularShift);
        }
        let solve_scratch = symbolic.solve_in_place_scratch::<f64>(1, par);
        crate::timings::note(|| {
            format!(
                "order {}, nnz(A) {}, nnz(L) {}, {}",
                matrix.nrows(),
                matrix.compute_nnz(),
                symbolic.len_val(),
                match symbolic.raw() {
                    SymbolicCholeskyRaw::Simplicial(_) => "simplicial".to_string(),
                    SymbolicCholeskyRaw::Supernodal(s) =>
                        format!("{} supernodes", s.n_supernodes()),
                }
            )
        });
        Ok(Self {
            symbolic,
            values,
            negative_pivots,
            solve_scratch,
        })
    }

    /// Order of the matrix.
    pub fn order(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Number of negative pivots: eigenvalues of the pencil below the shift.
    pub fn negative_pivots(&self) -> usize {
        self.negative_pivots
    }

    /// A work buffer for [`Factor::solve_in_place`], made once per user.
    pub fn workspace(&self) -> Result<MemBuffer, BridgeError> {
        MemBuffer::try_new(self.solve_scratch).map_err(|_| BridgeError::OutOfMemory)
    }

    /// A work buffer for [`Factor::solve_block_in_place`] with up to
    /// `columns` right-hand sides.
    pub fn block_workspace(&self, columns: usize) -> Result<MemBuffer, BridgeError> {
        MemBuffer::try_new(
            self.symbolic
                .solve_in_place_scratch::<f64>(columns, Par::Seq),
        )
        .map_err(|_| BridgeError::OutOfMemory)
    }

    /// Solves A X = B in place for several right-hand sides at once (one
    /// pass over the factor for all of them), with a workspace from
    /// [`Factor::block_workspace`] for at least as many columns. Cost
    /// O(nnz(L) · columns).
    pub fn solve_block_in_place(&self, rhs: MatMut<'_, f64>, workspace: &mut MemBuffer) {
        LdltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            rhs,
            Par::Seq,
            MemStack::new(workspace),
        );
    }

    /// Solves A x = b in place (`rhs` holds b on entry, x on return); no
    /// allocation with a workspace from [`Factor::workspace`]. Cost O(nnz(L)).
    pub fn solve_in_place(&self, rhs: &mut [f64], workspace: &mut MemBuffer) {
        let n = rhs.len();
        let rhs = MatMut::from_column_major_slice_mut(rhs, n, 1);
        LdltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            rhs,
            Par::Seq,
            MemStack::new(workspace),
        );
    }
}

/// Work arrays of [`Factor::inverse_form`], made once per user: O(n).
#[derive(Debug)]
pub struct FormScratch {
    /// The forward solve's vector, zero outside the current reach.
    x: Vec<f64>,
    /// `stamp` where a column is in the current reach.
    mark: Vec<u32>,
    stamp: u32,
    /// The columns of the current reach.
    reach: Vec<usize>,
}

impl Factor {
    /// Whether the factor is simplicial (L column by column), the kind
    /// [`Factor::inverse_form`] takes; else supernodal.
    pub fn is_simplicial(&self) -> bool {
        matches!(self.symbolic.raw(), SymbolicCholeskyRaw::Simplicial(_))
    }

    /// Work arrays for [`Factor::inverse_form`].
    pub fn form_scratch(&self) -> FormScratch {
        let n = self.order();
        FormScratch {
            x: vec![0.0; n],
            mark: vec![0; n],
            stamp: 0,
            reach: Vec::new(),
        }
    }

    /// bᵀ A⁻¹ b for a sparse b given as (index, value) pairs (an index
    /// repeated adds its values, in the order given), by the forward solve
    /// alone: with P A Pᵀ = L D Lᵀ, bᵀA⁻¹b = yᵀD⁻¹y for y = L⁻¹ P b, and y
    /// is nonzero only on the columns of L that b's nonzeros reach up the
    /// elimination tree (Gilbert's theorem), so the cost is the nonzeros of
    /// L in those columns, not O(nnz(L)) as a full solve. `None` for a
    /// supernodal factor (the caller solves in full). The sums run in a
    /// fixed order (the reach's columns ascending, each column's entries in
    /// storage order), so the result depends on nothing but A and b.
    pub fn inverse_form(&self, b: &[(usize, f64)], scratch: &mut FormScratch) -> Option<f64> {
        let SymbolicCholeskyRaw::Simplicial(s) = self.symbolic.raw() else {
            return None;
        };
        let col_ptr = s.col_ptr();
        let row_idx = s.row_idx();
        let inverse = self.symbolic.perm().map(|p| p.arrays().1);
        let FormScratch {
            x,
            mark,
            stamp,
            reach,
        } = scratch;
        if *stamp == u32::MAX {
            mark.fill(0);
            *stamp = 0;
        }
        *stamp += 1;
        let stamp = *stamp;
        reach.clear();
        for &(index, value) in b {
            let mut j = inverse.map_or(index, |inv| inv[index]);
            x[j] += value;
            // Up the elimination tree (a column's parent is the first row
            // below its diagonal in L) until a column already reached.
            while mark[j] != stamp {
                mark[j] = stamp;
                reach.push(j);
                let below = &row_idx[col_ptr[j] + 1..col_ptr[j + 1]];
                match below.iter().min() {
                    Some(&parent) => j = parent,
                    None => break,
                }
            }
        }
        reach.sort_unstable();
        let mut form = 0.0;
        for &j in reach.iter() {
            let xj = x[j];
            x[j] = 0.0;
            let start = col_ptr[j];
            // The column's first entry holds D's pivot, the others L's.
            for p in start + 1..col_ptr[j + 1] {
                x[row_idx[p]] -= self.values[p] * xj;
            }
            form += xj * xj / self.values[start];
        }
        Some(form)
    }
}

/// The diagonal D of an LDLᵀ factor, in the factor's (permuted) order.
fn pivots(symbolic: &SymbolicCholesky<usize>, values: &[f64]) -> Vec<f64> {
    match symbolic.raw() {
        SymbolicCholeskyRaw::Simplicial(s) => {
            // Each column of L starts with its diagonal entry, which holds D.
            let col_ptr = s.col_ptr();
            let row_idx = s.row_idx();
            (0..s.nrows())
                .map(|j| {
                    let p = col_ptr[j];
                    debug_assert_eq!(row_idx[p], j);
                    values[p]
                })
                .collect()
        }
        SymbolicCholeskyRaw::Supernodal(s) => {
            // Each supernode's top square block is unit-lower L with D on its diagonal.
            let factor = supernodal::SupernodalLdltRef::new(s, values);
            let mut d = Vec::with_capacity(s.nrows());
            for node in 0..s.n_supernodes() {
                let block = factor.supernode(node).val();
                for k in 0..block.ncols() {
                    d.push(block[(k, k)]);
                }
            }
            d
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A symmetric positive definite sparse matrix of order n: a chain
    /// (tridiagonal) with extra couplings, both triangles stored.
    fn spd(n: usize, simplicial: bool) -> SymmetricSparse {
        let mut entries = Vec::new();
        for i in 0..n {
            entries.push((i, i, 100.0 + (i % 7) as f64));
            if i + 1 < n {
                entries.push((i + 1, i, -1.0 - (i % 3) as f64 * 0.1));
            }
            if simplicial {
                if i + 5 < n {
                    entries.push((i + 5, i, -0.5));
                }
            } else {
                // A full band: faer chooses its supernodal factor.
                for k in 2..80.min(n - i) {
                    entries.push((i + k, i, -0.5 / k as f64));
                }
            }
        }
        symmetric_from_entries(n, entries, true).unwrap()
    }

    #[test]
    fn the_eigen_inverse_form_equals_a_full_solve() {
        let n = 400;
        let matrix = spd(n, true);
        let factor = Factor::new(&matrix).unwrap();
        assert!(factor.is_simplicial());
        let mut scratch = factor.form_scratch();
        let mut workspace = factor.workspace().unwrap();
        for b in [
            vec![(0, 1.0)],
            vec![(n - 1, 2.5)],
            vec![(17, 0.25), (18, 0.75), (17, 0.5)],
            vec![(200, 1.0), (3, -1.0), (399, 0.5)],
        ] {
            let form = factor.inverse_form(&b, &mut scratch).unwrap();
            let mut x = vec![0.0; n];
            for &(i, v) in &b {
                x[i] += v;
            }
            let rhs = x.clone();
            factor.solve_in_place(&mut x, &mut workspace);
            let full: f64 = rhs.iter().zip(&x).map(|(a, b)| a * b).sum();
            assert!((form - full).abs() <= 1e-13 * full.abs(), "{form} {full}");
            // The scratch is left clean for the next form.
            assert!(scratch.x.iter().all(|&v| v == 0.0));
        }
    }

    #[test]
    fn the_eigen_inverse_form_declines_a_supernodal_factor() {
        let factor = Factor::new(&spd(2000, false)).unwrap();
        assert!(!factor.is_simplicial());
        let mut scratch = factor.form_scratch();
        assert!(factor.inverse_form(&[(0, 1.0)], &mut scratch).is_none());
    }
}
