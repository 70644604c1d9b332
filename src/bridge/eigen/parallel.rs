//! Fixed-partition parallelism for the eigen solver's n × k work.
//!
//! Each loop here splits its work into parts fixed by the sizes alone — a
//! column of a solve or a sparse product, [`ROWS`] rows of a dense product —
//! computes each part with faer's sequential kernels, and combines the parts
//! in part order. So the result is bit-identical whatever the thread count;
//! the [`Par`] value decides only how many threads of the current rayon pool
//! run the parts (at most that many at once, each a contiguous run of parts).
//!
//! faer's own parallel kernels are not used: its column-major matrix–vector
//! product with `Par::Rayon(t)` splits the reduction into t partial sums
//! added at the end (faer 0.24, `linalg::matmul`), so its result depends on
//! t, and its sparse factorisation passes `par` down to such kernels.

use faer::dyn_stack::MemBuffer;
use faer::linalg::matmul::matmul;
use faer::reborrow::ReborrowMut;
use faer::{Accum, Mat, MatMut, MatRef, Par};
use rayon::prelude::*;

use super::sparse::{Factor, SymmetricSparse, multiply};
use crate::bridge::BridgeError;

/// Rows per part of a dense n × k product split by rows. A product of at
/// most this many rows is one part: exactly the sequential product.
pub const ROWS: usize = 8192;

/// The number of threads `par` allows.
pub fn threads(par: Par) -> usize {
    match par {
        Par::Seq => 1,
        Par::Rayon(t) => t.get(),
    }
}

/// `f(part)` for every part in 0..`parts`, the results in part order. At
/// most [`threads`] run at once, each over a contiguous run of parts.
pub fn map<T: Send>(par: Par, parts: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let groups = threads(par).min(parts);
    if groups <= 1 {
        return (0..parts).map(f).collect();
    }
    let per = parts.div_ceil(groups);
    let grouped: Vec<Vec<T>> = (0..groups)
        .into_par_iter()
        .map(|g| (g * per..((g + 1) * per).min(parts)).map(&f).collect())
        .collect();
    grouped.into_iter().flatten().collect()
}

/// `f(first, part)` for consecutive column blocks of `out`, each `width`
/// columns wide (the last one narrower), `first` the block's first column.
pub fn for_column_blocks(
    par: Par,
    out: MatMut<'_, f64>,
    width: usize,
    f: impl Fn(usize, MatMut<'_, f64>) + Sync,
) {
    let mut blocks = Vec::new();
    let mut rest = out;
    let mut first = 0;
    while rest.ncols() > 0 {
        let w = width.min(rest.ncols());
        let (head, tail) = rest.split_at_col_mut(w);
        blocks.push((first, head));
        first += w;
        rest = tail;
    }
    for_each(par, blocks, |(first, block)| f(first, block));
}

/// `f(item)` for every item, at most [`threads`] at once, each over a
/// contiguous run of items.
pub fn for_each<T: Send>(par: Par, items: Vec<T>, f: impl Fn(T) + Sync) {
    let groups = threads(par).min(items.len());
    if groups <= 1 {
        items.into_iter().for_each(f);
        return;
    }
    let per = items.len().div_ceil(groups);
    let mut grouped: Vec<Vec<T>> = Vec::with_capacity(groups);
    let mut items = items.into_iter();
    for _ in 0..groups {
        grouped.push(items.by_ref().take(per).collect());
    }
    grouped
        .into_par_iter()
        .for_each(|group| group.into_iter().for_each(&f));
}

/// out ← aᵀ b (a n × m, b n × p, out m × p): the rows cut into parts of
/// [`ROWS`], each part's aᵀb sequential, the partial products added in part
/// order. Cost O(n·m·p).
pub fn product_tn(mut out: MatMut<'_, f64>, a: MatRef<'_, f64>, b: MatRef<'_, f64>, par: Par) {
    let n = a.nrows();
    let parts = n.div_ceil(ROWS).max(1);
    if parts == 1 {
        matmul(out, Accum::Replace, a.transpose(), b, 1.0, Par::Seq);
        return;
    }
    let partial = map(par, parts, |r| {
        let (start, rows) = (r * ROWS, ROWS.min(n - r * ROWS));
        let mut p = Mat::<f64>::zeros(a.ncols(), b.ncols());
        matmul(
            p.as_mut(),
            Accum::Replace,
            a.subrows(start, rows).transpose(),
            b.subrows(start, rows),
            1.0,
            Par::Seq,
        );
        p
    });
    out.copy_from(&partial[0]);
    for p in &partial[1..] {
        for j in 0..out.ncols() {
            for i in 0..out.nrows() {
                out[(i, j)] += p[(i, j)];
            }
        }
    }
}

/// out ← a b (`Accum::Replace`) or out + alpha a b (`Accum::Add`) (a n × m,
/// b m × p): each part of [`ROWS`] rows of out computed sequentially. Cost
/// O(n·m·p).
pub fn product_nn(
    out: MatMut<'_, f64>,
    accum: Accum,
    a: MatRef<'_, f64>,
    b: MatRef<'_, f64>,
    alpha: f64,
    par: Par,
) {
    let n = a.nrows();
    if n <= ROWS {
        matmul(out, accum, a, b, alpha, Par::Seq);
        return;
    }
    let mut parts = Vec::with_capacity(n.div_ceil(ROWS));
    let mut rest = out;
    let mut start = 0;
    while rest.nrows() > 0 {
        let rows = ROWS.min(rest.nrows());
        let (head, tail) = rest.split_at_row_mut(rows);
        parts.push((start, head));
        start += rows;
        rest = tail;
    }
    for_each(par, parts, |(start, part)| {
        matmul(
            part,
            accum,
            a.subrows(start, part_rows(n, start)),
            b,
            alpha,
            Par::Seq,
        );
    });
}

fn part_rows(n: usize, start: usize) -> usize {
    ROWS.min(n - start)
}

/// Whether a sparse matrix equals its transpose bit for bit (both triangles
/// stored, each entry's mirror holding the same f64). Cost O(nnz · log of
/// the column length).
pub fn is_bitwise_symmetric(matrix: &SymmetricSparse) -> bool {
    let col_ptr = matrix.symbolic().col_ptr();
    let row_idx = matrix.symbolic().row_idx();
    let values = matrix.val();
    (0..matrix.ncols()).all(|j| {
        (col_ptr[j]..col_ptr[j + 1]).all(|p| {
            let i = row_idx[p];
            let column = &row_idx[col_ptr[i]..col_ptr[i + 1]];
            column
                .binary_search(&j)
                .is_ok_and(|q| values[col_ptr[i] + q].to_bits() == values[p].to_bits())
        })
    })
}

/// y = A x for a sparse A, the rows in parts of [`ROWS`] on the threads
/// `par` allows when A is bitwise symmetric (`symmetric`, from
/// [`is_bitwise_symmetric`]): row i is then column i, so yᵢ = Σⱼ Aⱼᵢ xⱼ
/// over column i in ascending j, the very sums, in the very order, of the
/// sequential [`multiply`] (which adds column j's contributions for
/// ascending j; the products it skips, of an xⱼ = 0, add a zero, which
/// leaves a sum unchanged since it is never −0). Else [`multiply`].
/// Cost O(nnz).
pub fn multiply_symmetric(
    par: Par,
    matrix: &SymmetricSparse,
    symmetric: bool,
    x: &[f64],
    y: &mut [f64],
) {
    if !symmetric || threads(par) == 1 || y.len() <= ROWS {
        multiply(matrix, x, y);
        return;
    }
    let col_ptr = matrix.symbolic().col_ptr();
    let row_idx = matrix.symbolic().row_idx();
    let values = matrix.val();
    let parts: Vec<(usize, &mut [f64])> = y
        .chunks_mut(ROWS)
        .enumerate()
        .map(|(k, part)| (k * ROWS, part))
        .collect();
    for_each(par, parts, |(start, part)| {
        for (k, out) in part.iter_mut().enumerate() {
            let i = start + k;
            let mut sum = 0.0;
            for p in col_ptr[i]..col_ptr[i + 1] {
                sum += values[p] * x[row_idx[p]];
            }
            *out = sum;
        }
    });
}

/// out ← A x column by column for a sparse A (columns in parallel, each
/// the sequential [`multiply`]).
pub fn multiply_columns(
    par: Par,
    matrix: &SymmetricSparse,
    x: MatRef<'_, f64>,
    out: MatMut<'_, f64>,
) {
    for_column_blocks(par, out, 1, |c, mut col| {
        let xc = x.col(c).try_as_col_major().unwrap().as_slice();
        let yc = col
            .rb_mut()
            .col_mut(0)
            .try_as_col_major_mut()
            .unwrap()
            .as_slice_mut();
        multiply(matrix, xc, yc);
    });
}

/// Three n-vectors of scratch, made once per thread's run of columns.
pub type Scratch = [Vec<f64>; 3];

/// `f(column, workspace, scratch)` for every column of `out` in parallel,
/// each with a solve workspace of `factor` and [`Scratch`] made once per
/// thread's run of columns.
pub fn for_columns_with_solves(
    par: Par,
    factor: &Factor,
    out: MatMut<'_, f64>,
    f: impl Fn(usize, &mut [f64], &mut MemBuffer, &mut Scratch) + Sync,
) -> Result<(), BridgeError> {
    let rows = out.nrows();
    let n = out.ncols();
    let groups = threads(par).min(n).max(1);
    let width = n.div_ceil(groups).max(1);
    let failed = std::sync::atomic::AtomicBool::new(false);
    for_column_blocks(par, out, width, |first, mut block| {
        let Ok(mut workspace) = factor.workspace() else {
            failed.store(true, std::sync::atomic::Ordering::Relaxed);
            return;
        };
        let mut scratch = [vec![0.0; rows], vec![0.0; rows], vec![0.0; rows]];
        for c in 0..block.ncols() {
            let column = block
                .rb_mut()
                .col_mut(c)
                .try_as_col_major_mut()
                .unwrap()
                .as_slice_mut();
            f(first + c, column, &mut workspace, &mut scratch);
        }
    });
    if failed.into_inner() {
        return Err(BridgeError::OutOfMemory);
    }
    Ok(())
}
