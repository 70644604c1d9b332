//! Block shift-invert Lanczos for the lowest modes of a large assembled
//! pencil (an imported model), the fast path of [`super::Pencil`].
//!
//! Same operator as [`super::lanczos`]: S = K⁻¹M, self-adjoint in the
//! M-inner product, eigenvalues θ = 1/λ (Ericsson & Ruhe 1980). The basis
//! grows by blocks of [`BLOCK`] vectors (Golub & Underwood 1977; Grimes,
//! Lewis & Simon 1994, "A shifted block Lanczos algorithm for solving
//! sparse symmetric generalized eigenproblems", the algorithm of MSC and
//! NASTRAN): W = S V_j for a whole block (one multi-right-hand-side solve
//! with the LDLᵀ factor), then W is M-orthogonalised against the whole
//! basis twice (block classical Gram–Schmidt, CGS2: Giraud, Langou &
//! Rozložník 2005), and within the block by modified Gram–Schmidt with the
//! same second pass. Every coefficient goes into the projected matrix
//! H = VᵀMSV, so H is exact to rounding even where orthogonality of a
//! plain recurrence would be lost; it is symmetric in exact arithmetic and
//! symmetrised before its eigen solve. The Ritz pairs (θ, V y) of H have
//! the residual ‖Sφ − θφ‖_M = ‖R_last y_last‖ (R_last the coupling of the
//! newest block to the one before it, y_last the rows of y in the last
//! complete block), the convergence test.
//!
//! Why blocks: the re-orthogonalisation against the growing basis is the
//! dominant cost of a long Lanczos run (n × steps² work and, above all,
//! memory traffic: the basis of the 157,296-DOF viaduct is 290 MB). One
//! vector at a time it is two matrix–vector sweeps over the basis per
//! step; a block sweeps it four times (CGS2) for [`BLOCK`] vectors, as
//! matrix–matrix products, and the solves share one pass over the factor.
//! Seeded, and bit-identical whatever the thread count: the sweeps over the
//! basis and the M products use the threads `par` allows in parts fixed by
//! the sizes ([`super::parallel`]); the solves and the k × k work are
//! sequential.

use faer::linalg::matmul::matmul;
use faer::reborrow::{Reborrow, ReborrowMut};
use faer::{Accum, Mat, MatRef, Par};

use super::sparse::{Factor, SymmetricSparse, multiply};
use super::{kernels, parallel};
use crate::bridge::BridgeError;

/// Vectors per block. Eight keeps the basis sweeps to a quarter of the
/// single-vector method's while the basis grows by less than a block past
/// what the wanted pairs need.
pub const BLOCK: usize = 8;

/// Blocks per chunk added when the basis outgrows its first estimate
/// ([`Basis`]).
const GROWTH: usize = 4;

/// Relative residual ‖R y_last‖ / θ below which a Ritz pair is accepted
/// (as [`super::lanczos`]).
const RITZ_TOLERANCE: f64 = 1e-13;

/// A column of `matrix` whose norm falls below this share of its size before
/// orthogonalisation has no new direction (an invariant subspace).
const BREAKDOWN: f64 = 1e-12;

/// Eigenvalues λ (rad²/s²) ascending and their M-normalised vectors as
/// columns.
pub type Pairs = (Vec<f64>, Mat<f64>);

/// The `wanted` eigenpairs of K φ = λ M φ with the smallest λ, ascending,
/// M-normalised vectors as columns; `factor` is the LDLᵀ of K. `None` when
/// the run would need more than the whole space (the caller falls back to
/// the single-vector method). Cost per block: one solve with [`BLOCK`]
/// right-hand sides, 3 [`BLOCK`] sparse M products and O(n · m · [`BLOCK`])
/// for the orthogonalisation, m the basis size; about m ≈ 2 × wanted.
pub fn lowest(
    mass: &SymmetricSparse,
    factor: &Factor,
    wanted: usize,
    par: Par,
) -> Result<Option<Pairs>, BridgeError> {
    let n = mass.nrows();
    let p = BLOCK;
    if wanted == 0 || n < 4 * p || wanted + 2 * p > n / 2 {
        return Ok(None);
    }
    let mut workspace = factor.block_workspace(p)?;
    let mut solve_workspaces = [
        factor.block_workspace(SOLVE_COLUMNS)?,
        factor.block_workspace(SOLVE_COLUMNS)?,
    ];
    let symmetric = parallel::is_bitwise_symmetric(mass);
    let mut capacity = (2 * wanted + 20).div_ceil(p) * p + p;
    let mut basis = Basis::new(n, capacity)?;
    let mut projected = Mat::<f64>::zeros(capacity, capacity);
    let mut block = Mat::<f64>::zeros(n, p);
    let mut m_block = Mat::<f64>::zeros(n, p);
    let mut coefficients = Mat::<f64>::zeros(capacity, p);
    let mut column = vec![0.0; n];
    let mut m_column = vec![0.0; n];
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;

    // Start: S applied to a seeded pseudo-random block (in S's range).
    for c in 0..p {
        start_vector(&mut seed, &mut column);
        block
            .col_mut(c)
            .copy_from(faer::ColRef::from_slice(&column));
    }
    apply_operator(
        mass,
        factor,
        &mut block,
        &mut m_block,
        &mut solve_workspaces,
        par,
    );
    let mut within = Mat::<f64>::zeros(p, p);
    let ok = orthonormalise_block(
        mass,
        factor,
        (&basis, 0),
        &mut block,
        &mut within,
        &mut seed,
        &mut workspace,
        (par, symmetric),
    )?;
    if !ok {
        return Ok(None);
    }
    basis.block_mut(0, p).copy_from(&block);
    let mut columns = p;
    let mut check_at = wanted + p;
    loop {
        // The newest complete block: its image under S.
        let start = columns - p;
        block.copy_from(basis.block(start, p));
        apply_operator(
            mass,
            factor,
            &mut block,
            &mut m_block,
            &mut solve_workspaces,
            par,
        );
        // Block CGS2 against the whole basis; coefficients into H.
        for _pass in 0..2 {
            parallel::multiply_columns(par, mass, block.as_ref(), m_block.as_mut());
            let mut c = coefficients.as_mut().subrows_mut(0, columns);
            for (first, v) in basis.parts(columns) {
                let rows = c.rb_mut().subrows_mut(first, v.ncols());
                parallel::product_tn(rows, v, m_block.as_ref(), par);
            }
            for (first, v) in basis.parts(columns) {
                let rows = c.rb().subrows(first, v.ncols());
                parallel::product_nn(block.as_mut(), Accum::Add, v, rows, -1.0, par);
            }
            let mut h = projected.as_mut().submatrix_mut(0, start, columns, p);
            for j in 0..p {
                for i in 0..columns {
                    h[(i, j)] += coefficients[(i, j)];
                }
            }
        }
        if columns + p > n / 2 {
            return Ok(None);
        }
        let ok = orthonormalise_block(
            mass,
            factor,
            (&basis, columns),
            &mut block,
            &mut within,
            &mut seed,
            &mut workspace,
            (par, symmetric),
        )?;
        if !ok {
            return Ok(None);
        }
        // The coupling R of the new block to this one: H rows below.
        if columns + p > capacity {
            // A chunk of GROWTH blocks at a time: growing copies nothing, so
            // small steps cost nothing but keep the unused tail short.
            let grown = capacity + GROWTH * p;
            basis.grow(grown)?;
            projected.resize_with(grown, grown, |_, _| 0.0);
            coefficients.resize_with(grown, p, |_, _| 0.0);
            capacity = grown;
        }
        projected
            .as_mut()
            .submatrix_mut(columns, start, p, p)
            .copy_from(&within);
        basis.block_mut(columns, p).copy_from(&block);
        columns += p;

        // H over the complete blocks (all but the newest) is the projection.
        let complete = columns - p;
        if complete >= check_at {
            let (thetas, ritz) =
                projected_eigen(projected.as_ref().submatrix(0, 0, complete, complete))?;
            let coupling = projected.as_ref().submatrix(complete, complete - p, p, p);
            let converged = (0..wanted).all(|r| {
                let last = ritz.as_ref().submatrix(complete - p, r, p, 1);
                let residual = kernels::product(coupling, last, Par::Seq).norm_l2();
                residual <= RITZ_TOLERANCE * thetas[r].abs()
            });
            if converged {
                let mut vectors = basis.combine(complete, ritz.as_ref().subcols(0, wanted), par)?;
                let mut eigenvalues = Vec::with_capacity(wanted);
                for (c, &theta) in thetas.iter().take(wanted).enumerate() {
                    column.copy_from_slice(vectors.col(c).try_as_col_major().unwrap().as_slice());
                    multiply(mass, &column, &mut m_column);
                    let norm = dot(&column, &m_column).sqrt();
                    if !(norm > 0.0 && norm.is_finite() && theta > 0.0) {
                        return Err(BridgeError::EigenFailed);
                    }
                    for x in vectors.col_mut(c).iter_mut() {
                        *x /= norm;
                    }
                    eigenvalues.push(1.0 / theta);
                }
                return Ok(Some((eigenvalues, vectors)));
            }
            check_at = complete + p.max((complete / 10).div_ceil(p) * p);
        }
    }
}

/// The Lanczos basis in column chunks: the first as wide as the first
/// estimate of the basis size, then one more chunk each time it grows, so
/// that growing copies nothing (a single matrix grown by 1.5× held both
/// copies at once: 754 MB peak on the 157,296-DOF viaduct, a basis of 240
/// columns, 302 MB, and its 360-column copy). Every chunk's width is a
/// multiple of [`BLOCK`], so a block never straddles two. A run that does
/// not grow has one chunk: the products over it are those of one matrix.
struct Basis {
    n: usize,
    /// (first column, chunk).
    chunks: Vec<(usize, Mat<f64>)>,
    capacity: usize,
}

impl Basis {
    fn new(n: usize, capacity: usize) -> Result<Self, BridgeError> {
        let mut basis = Basis {
            n,
            chunks: Vec::new(),
            capacity: 0,
        };
        basis.grow(capacity)?;
        Ok(basis)
    }

    /// Adds a chunk so that `capacity` columns fit.
    fn grow(&mut self, capacity: usize) -> Result<(), BridgeError> {
        let width = capacity - self.capacity;
        super::dense::ensure_memory(self.n, width, 1)?;
        self.chunks
            .push((self.capacity, Mat::<f64>::zeros(self.n, width)));
        self.capacity = capacity;
        Ok(())
    }

    /// The chunk holding column `column`, and the column's place in it.
    fn locate(&self, column: usize) -> (usize, usize) {
        let k = self.chunks.partition_point(|(first, _)| *first <= column) - 1;
        (k, column - self.chunks[k].0)
    }

    /// Columns start..start + width (inside one chunk).
    fn block(&self, start: usize, width: usize) -> MatRef<'_, f64> {
        let (k, offset) = self.locate(start);
        self.chunks[k].1.as_ref().subcols(offset, width)
    }

    fn block_mut(&mut self, start: usize, width: usize) -> faer::MatMut<'_, f64> {
        let (k, offset) = self.locate(start);
        self.chunks[k].1.as_mut().subcols_mut(offset, width)
    }

    /// V Y for V the first `columns` columns and Y `columns` × k (k at most
    /// the first chunk's width), consuming the basis: row part by row part
    /// ([`parallel::ROWS`] rows, on the threads `par` allows), each part's
    /// rows of V Y computed from the same rows of V alone (the chunks' products
    /// added in chunk order) and written over them, so that no n × k matrix
    /// is needed beside the whole basis; the other chunks are then dropped
    /// before the result is copied out of the first.
    fn combine(
        mut self,
        columns: usize,
        y: MatRef<'_, f64>,
        par: Par,
    ) -> Result<Mat<f64>, BridgeError> {
        let k = y.ncols();
        let (head, rest) = self.chunks.split_first_mut().expect("a chunk");
        let width = head.1.ncols().min(columns);
        let others: Vec<(usize, MatRef<'_, f64>)> = rest
            .iter()
            .filter(|(first, _)| *first < columns)
            .map(|(first, chunk)| {
                (
                    *first,
                    chunk
                        .as_ref()
                        .subcols(0, chunk.ncols().min(columns - first)),
                )
            })
            .collect();
        let mut parts = Vec::new();
        let mut remaining = head.1.as_mut();
        let mut start = 0;
        while remaining.nrows() > 0 {
            let rows = parallel::ROWS.min(remaining.nrows());
            let (part, tail) = remaining.split_at_row_mut(rows);
            parts.push((start, part));
            start += rows;
            remaining = tail;
        }
        parallel::for_each(par, parts, |(start, part)| {
            let rows = part.nrows();
            let mut out = Mat::<f64>::zeros(rows, k);
            let v = part.rb().subcols(0, width);
            matmul(
                out.as_mut(),
                Accum::Replace,
                v,
                y.subrows(0, width),
                1.0,
                Par::Seq,
            );
            for (first, v) in &others {
                let v = v.subrows(start, rows);
                let y = y.subrows(*first, v.ncols());
                matmul(out.as_mut(), Accum::Add, v, y, 1.0, Par::Seq);
            }
            part.subcols_mut(0, k).copy_from(&out);
        });
        drop(others);
        self.chunks.truncate(1);
        super::dense::ensure_memory(self.n, k, 1)?;
        Ok(self.chunks[0].1.as_ref().subcols(0, k).to_owned())
    }

    /// The first `columns` columns, chunk by chunk: (first column, columns).
    fn parts(&self, columns: usize) -> Vec<(usize, MatRef<'_, f64>)> {
        self.chunks
            .iter()
            .filter(|(first, _)| *first < columns)
            .map(|(first, chunk)| {
                let width = chunk.ncols().min(columns - first);
                (*first, chunk.as_ref().subcols(0, width))
            })
            .collect()
    }
}

/// Right-hand sides per solve of [`apply_operator`]: the block's solve is
/// cut into halves, always, so that two threads can share it with the
/// same result as one.
const SOLVE_COLUMNS: usize = BLOCK / 2;

/// block ← S block = K⁻¹ M block (`scratch` receives M block first), the
/// solve in fixed parts of [`SOLVE_COLUMNS`] right-hand sides, one
/// workspace each.
fn apply_operator(
    mass: &SymmetricSparse,
    factor: &Factor,
    block: &mut Mat<f64>,
    scratch: &mut Mat<f64>,
    workspaces: &mut [faer::dyn_stack::MemBuffer; BLOCK / SOLVE_COLUMNS],
    par: Par,
) {
    parallel::multiply_columns(par, mass, block.as_ref(), scratch.as_mut());
    block.copy_from(&*scratch);
    let (first, second) = block.as_mut().split_at_col_mut(SOLVE_COLUMNS);
    let [a, b] = workspaces;
    parallel::for_each(par, vec![(first, a), (second, b)], |(part, workspace)| {
        factor.solve_block_in_place(part, workspace);
    });
}

/// M-orthonormalises the columns of `block` (already M-orthogonal to
/// `basis`) by modified Gram–Schmidt, each column twice, so that
/// block_in = Q R with R upper triangular (returned in `within`). A column
/// without a new direction (norm below [`BREAKDOWN`] of its size) is
/// replaced by S applied to a fresh seeded vector, M-orthogonalised
/// against the basis and the block, with R's diagonal entry 0 (T stays the
/// exact projection; the Krylov space restarts there). Returns false if
/// even that fails.
#[allow(clippy::too_many_arguments)]
fn orthonormalise_block(
    mass: &SymmetricSparse,
    factor: &Factor,
    (basis, columns): (&Basis, usize),
    block: &mut Mat<f64>,
    within: &mut Mat<f64>,
    seed: &mut u64,
    workspace: &mut faer::dyn_stack::MemBuffer,
    (par, symmetric): (Par, bool),
) -> Result<bool, BridgeError> {
    let (n, p) = (block.nrows(), block.ncols());
    within.fill(0.0);
    let mut m_q = Mat::<f64>::zeros(n, p);
    let mut w = vec![0.0; n];
    let mut mw = vec![0.0; n];
    for c in 0..p {
        w.copy_from_slice(block.col(c).try_as_col_major().unwrap().as_slice());
        parallel::multiply_symmetric(par, mass, symmetric, &w, &mut mw);
        let size = dot(&w, &mw).sqrt();
        for _pass in 0..2 {
            for i in 0..c {
                let coeff = dot(m_q.col(i).try_as_col_major().unwrap().as_slice(), &w);
                within[(i, c)] += coeff;
                for (x, q) in w.iter_mut().zip(block.col(i).iter()) {
                    *x -= coeff * q;
                }
            }
        }
        parallel::multiply_symmetric(par, mass, symmetric, &w, &mut mw);
        let mut norm = dot(&w, &mw).sqrt();
        if !(norm > BREAKDOWN * size && norm.is_finite()) {
            // A fresh direction: S r, orthogonal to the basis and the block.
            start_vector(seed, &mut w);
            multiply(mass, &w, &mut mw);
            w.copy_from_slice(&mw);
            let mut one = faer::MatMut::from_column_major_slice_mut(&mut w, n, 1);
            factor.solve_block_in_place(one.rb_mut(), workspace);
            for _pass in 0..2 {
                multiply(mass, &w, &mut mw);
                for k in 0..columns {
                    let q = basis.block(k, 1).col(0);
                    let coeff = dot(q.try_as_col_major().unwrap().as_slice(), &mw);
                    for (x, q) in w.iter_mut().zip(q.iter()) {
                        *x -= coeff * q;
                    }
                }
                for i in 0..c {
                    let coeff = dot(m_q.col(i).try_as_col_major().unwrap().as_slice(), &w);
                    for (x, q) in w.iter_mut().zip(block.col(i).iter()) {
                        *x -= coeff * q;
                    }
                }
            }
            multiply(mass, &w, &mut mw);
            norm = dot(&w, &mw).sqrt();
            if !(norm > 0.0 && norm.is_finite()) {
                return Ok(false);
            }
            within[(c, c)] = 0.0;
        } else {
            within[(c, c)] = norm;
        }
        for i in 0..n {
            block[(i, c)] = w[i] / norm;
            m_q[(i, c)] = mw[i] / norm;
        }
    }
    Ok(true)
}

/// Eigen decomposition of the symmetrised projected matrix: θ descending
/// and the matching eigenvectors as columns.
fn projected_eigen(h: MatRef<'_, f64>) -> Result<(Vec<f64>, Mat<f64>), BridgeError> {
    let m = h.nrows();
    let t = Mat::from_fn(m, m, |i, j| 0.5 * (h[(i, j)] + h[(j, i)]));
    let (values, u) =
        kernels::symmetric_eigen(t.as_ref(), Par::Seq).ok_or(BridgeError::EigenFailed)?;
    let thetas = (0..m).rev().map(|i| values[i]).collect();
    let vectors = Mat::from_fn(m, m, |i, j| u[(i, m - 1 - j)]);
    Ok((thetas, vectors))
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Fills `out` with a reproducible pseudo-random vector in [−1, 1]
/// (SplitMix64), advancing `seed`.
fn start_vector(seed: &mut u64, out: &mut [f64]) {
    for x in out.iter_mut() {
        *seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = *seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        *x = (z >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
    }
}
