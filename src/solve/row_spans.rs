//! Dense matrices stored with the span of columns each row is nonzero on.
//!
//! A train of uncoupled cars (`count:` in a scene) is one vehicle whose
//! matrices are block diagonal, one 27 × 27 block per car: an 8-car set's
//! 216 DOFs leave seven eighths of every row zero. Its condensation
//! ([`super::partition`]) keeps those exact zeros (an LU of a block-diagonal
//! matrix only pivots and eliminates within a block), so each row's nonzeros
//! lie in one contiguous span of columns, and a product over that span does
//! the work of the blocks only. A single vehicle's rows span every column:
//! nothing is skipped and nothing changes.

use nalgebra::{DMatrix, DVector};

/// A dense matrix, row by row, with each row's span of nonzero columns.
#[derive(Debug, Clone)]
pub struct RowSpans {
    /// The matrix transposed: column i holds row i, so a row is contiguous.
    rows: DMatrix<f64>,
    /// Half-open column range [first, last + 1) of each row's nonzeros
    /// (empty for a zero row).
    spans: Vec<(usize, usize)>,
}

/// The half-open range of indices where `values` is nonzero, (0, 0) if none.
fn nonzero_span(values: impl Iterator<Item = f64>) -> (usize, usize) {
    let mut span: Option<(usize, usize)> = None;
    for (j, value) in values.enumerate() {
        if value != 0.0 {
            span = Some(span.map_or((j, j + 1), |(first, _)| (first, j + 1)));
        }
    }
    span.unwrap_or((0, 0))
}

impl RowSpans {
    /// Stores `matrix` with its rows' spans. Cost O(rows · columns), once.
    pub fn new(matrix: &DMatrix<f64>) -> Self {
        let spans = (0..matrix.nrows())
            .map(|i| nonzero_span(matrix.row(i).iter().copied()))
            .collect();
        Self {
            rows: matrix.transpose(),
            spans,
        }
    }

    /// y ← α A x + β y. Per entry the same products, summed in the same
    /// column order, as nalgebra's `gemv` (`y_i = (αA_ij)x_j + y_i` for
    /// ascending j, starting from βy_i), less the terms of exact zeros, which
    /// could only change the sign of a zero result. Cost O(Σ span lengths).
    pub fn gemv(&self, y: &mut DVector<f64>, alpha: f64, x: &DVector<f64>, beta: f64) {
        for (i, &(first, end)) in self.spans.iter().enumerate() {
            let row = self.rows.column(i);
            let mut sum = if beta == 0.0 { 0.0 } else { beta * y[i] };
            for j in first..end {
                sum += alpha * row[j] * x[j];
            }
            y[i] = sum;
        }
    }
}

/// The span of nonzero rows of each column of `matrices` taken together
/// (half-open, (0, 0) for a column that is zero in all of them). Cost
/// O(rows · columns) per matrix, once.
pub fn column_spans(matrices: &[&DMatrix<f64>]) -> Vec<(usize, usize)> {
    let columns = matrices.first().map_or(0, |m| m.ncols());
    (0..columns)
        .map(|j| {
            let rows = matrices.first().map_or(0, |m| m.nrows());
            nonzero_span((0..rows).map(|i| {
                if matrices.iter().any(|m| m[(i, j)] != 0.0) {
                    1.0
                } else {
                    0.0
                }
            }))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Block-diagonal and full matrices give nalgebra's gemv bit for bit.
    #[test]
    fn products_equal_nalgebra_bit_for_bit() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let full = DMatrix::from_fn(7, 9, |_, _| next());
        let blocks = DMatrix::from_fn(8, 8, |i, j| if i / 3 == j / 3 { next() } else { 0.0 });
        for matrix in [full, blocks] {
            let x = DVector::from_fn(matrix.ncols(), |_, _| next());
            let y0 = DVector::from_fn(matrix.nrows(), |_, _| next());
            for (alpha, beta) in [(1.0, 0.0), (-0.7, 1.0), (1.3, -1.0)] {
                let mut expected = y0.clone();
                expected.gemv(alpha, &matrix, &x, beta);
                let mut got = y0.clone();
                RowSpans::new(&matrix).gemv(&mut got, alpha, &x, beta);
                for (e, g) in expected.iter().zip(got.iter()) {
                    assert_eq!(e.to_bits(), g.to_bits(), "{e} against {g}");
                }
            }
        }
    }

    #[test]
    fn spans_of_blocks() {
        let blocks = DMatrix::from_fn(6, 6, |i, j| if i / 3 == j / 3 { 1.0 } else { 0.0 });
        assert_eq!(RowSpans::new(&blocks).spans[4], (3, 6));
        assert_eq!(column_spans(&[&blocks])[1], (0, 3));
        assert_eq!(column_spans(&[&DMatrix::zeros(2, 2)])[0], (0, 0));
    }
}
