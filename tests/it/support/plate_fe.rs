//! Independent reference for the plate deck: conforming Bogner–Fox–Schmit
//! rectangular thin-plate finite elements (Bogner, Fox & Schmit, "The
//! generation of inter-element-compatible stiffness and mass matrices by the
//! use of interpolation formulas", 1965; Zienkiewicz & Taylor, The Finite
//! Element Method, vol. 2, §4.6).
//!
//! Each rectangular element carries 16 dofs (w, w_x, w_y, w_xy at its four
//! corners) and interpolates w by bicubic Hermite products, so w and its
//! normal slope are continuous across element edges (conforming; frequencies
//! converge from above). The element matrices integrate the orthotropic
//! Kirchhoff energy U = ½∫∫[Dx w_xx² + 2D1 w_xx w_yy + Dy w_yy² + 4Dxy w_xy²] dA
//! and T = ½∫∫ρh ẇ² dA by 4 × 4 Gauss points (exact for these polynomials).
//! Supports: w = 0 along a line x = const also fixes w_y there; w_x and w_xy
//! stay free (simple support). The longitudinal edges are free (natural
//! conditions, nothing imposed).
//!
//! It shares nothing with `vbi::bridge::plate` (no beam modes, no Legendre
//! polynomials, no faer): banded Cholesky of K and subspace iteration
//! (Bathe, Finite Element Procedures, §11.6) for the lowest modes, with
//! nalgebra for the small projected problems.

use nalgebra::{DMatrix, SymmetricEigen};

/// A multi-span plate deck meshed with BFS elements.
pub struct BfsPlate {
    /// Span lengths, m.
    pub spans: Vec<f64>,
    /// Width, m.
    pub width: f64,
    /// Mass per area ρh, kg/m².
    pub mass_per_area: f64,
    /// (Dx, Dy, D1, Dxy), N·m.
    pub rigidities: (f64, f64, f64, f64),
    /// Elements along each span.
    pub elements_along: Vec<usize>,
    /// Elements across the width.
    pub elements_across: usize,
}

/// Symmetric band matrix: row i stores columns i − band..=i at offsets
/// 0..=band (entries left of column 0 stay zero).
struct Band {
    size: usize,
    band: usize,
    data: Vec<f64>,
}

impl Band {
    fn new(size: usize, band: usize) -> Self {
        Self {
            size,
            band,
            data: vec![0.0; size * (band + 1)],
        }
    }

    fn index(&self, i: usize, j: usize) -> usize {
        debug_assert!(j <= i && i - j <= self.band);
        i * (self.band + 1) + j + self.band - i
    }

    fn add(&mut self, i: usize, j: usize, value: f64) {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        let k = self.index(i, j);
        self.data[k] += value;
    }

    /// y = A x.
    fn multiply(&self, x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        for i in 0..self.size {
            let first = i.saturating_sub(self.band);
            for j in first..=i {
                let a = self.data[self.index(i, j)];
                y[i] += a * x[j];
                if j != i {
                    y[j] += a * x[i];
                }
            }
        }
    }

    /// In-place Cholesky A = L Lᵀ (L in the same storage).
    fn factor(&mut self) {
        let band = self.band;
        for i in 0..self.size {
            let first = i.saturating_sub(band);
            for j in first..=i {
                let jfirst = j.saturating_sub(band).max(first);
                let mut sum = self.data[self.index(i, j)];
                for k in jfirst..j {
                    sum -= self.data[self.index(i, k)] * self.data[self.index(j, k)];
                }
                let ij = self.index(i, j);
                if i == j {
                    assert!(sum > 0.0, "reference stiffness not positive definite");
                    self.data[ij] = sum.sqrt();
                } else {
                    self.data[ij] = sum / self.data[self.index(j, j)];
                }
            }
        }
    }

    /// Solves L Lᵀ x = b in place with the factor from [`Band::factor`].
    fn solve(&self, x: &mut [f64]) {
        // Row i of L holds columns first..=i contiguously from `start`.
        let row = |i: usize| {
            let first = i.saturating_sub(self.band);
            (first, self.index(i, first))
        };
        for i in 0..self.size {
            let (first, start) = row(i);
            let l = &self.data[start..start + (i - first)];
            let sum: f64 = l.iter().zip(&x[first..i]).map(|(a, b)| a * b).sum();
            x[i] = (x[i] - sum) / self.data[self.index(i, i)];
        }
        for i in (0..self.size).rev() {
            x[i] /= self.data[self.index(i, i)];
            let (first, start) = row(i);
            let xi = x[i];
            let l = &self.data[start..start + (i - first)];
            for (xk, a) in x[first..i].iter_mut().zip(l) {
                *xk -= a * xi;
            }
        }
    }
}

/// 1-D Hermite cubics on an element of length `h` at local t ∈ [0, 1]:
/// [value, d/dx, d²/dx²] for (w₀, w₀', w₁, w₁').
fn hermite(t: f64, h: f64) -> [[f64; 4]; 3] {
    let (t2, t3) = (t * t, t * t * t);
    [
        [
            1.0 - 3.0 * t2 + 2.0 * t3,
            h * (t - 2.0 * t2 + t3),
            3.0 * t2 - 2.0 * t3,
            h * (t3 - t2),
        ],
        [
            (-6.0 * t + 6.0 * t2) / h,
            1.0 - 4.0 * t + 3.0 * t2,
            (6.0 * t - 6.0 * t2) / h,
            3.0 * t2 - 2.0 * t,
        ],
        [
            (-6.0 + 12.0 * t) / (h * h),
            (-4.0 + 6.0 * t) / h,
            (6.0 - 12.0 * t) / (h * h),
            (6.0 * t - 2.0) / h,
        ],
    ]
}

/// Stiffness and mass of one BFS element a × b (m). Local dof
/// (corner (p, q), kind d) at 4(2q + p) + d, d = w, w_x, w_y, w_xy.
fn element(
    a: f64,
    b: f64,
    mass_per_area: f64,
    (dx, dy, d1, dxy): (f64, f64, f64, f64),
) -> ([[f64; 16]; 16], [[f64; 16]; 16]) {
    const GAUSS: [(f64, f64); 4] = [
        (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
        (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    ];
    let mut stiffness = [[0.0; 16]; 16];
    let mut mass = [[0.0; 16]; 16];
    for &(gx, wx) in &GAUSS {
        for &(gy, wy) in &GAUSS {
            let hx = hermite(0.5 * (gx + 1.0), a);
            let hy = hermite(0.5 * (gy + 1.0), b);
            let weight = 0.25 * wx * wy * a * b;
            let (mut n, mut nxx, mut nyy, mut nxy) = ([0.0; 16], [0.0; 16], [0.0; 16], [0.0; 16]);
            for q in 0..2 {
                for p in 0..2 {
                    for d in 0..4 {
                        // x factor: value function of corner p for w and w_y,
                        // slope function for w_x and w_xy; y likewise.
                        let ix = 2 * p + usize::from(d == 1 || d == 3);
                        let iy = 2 * q + usize::from(d == 2 || d == 3);
                        let k = 4 * (2 * q + p) + d;
                        n[k] = hx[0][ix] * hy[0][iy];
                        nxx[k] = hx[2][ix] * hy[0][iy];
                        nyy[k] = hx[0][ix] * hy[2][iy];
                        nxy[k] = hx[1][ix] * hy[1][iy];
                    }
                }
            }
            for r in 0..16 {
                for s in 0..16 {
                    stiffness[r][s] += weight
                        * (dx * nxx[r] * nxx[s]
                            + dy * nyy[r] * nyy[s]
                            + d1 * (nxx[r] * nyy[s] + nyy[r] * nxx[s])
                            + 4.0 * dxy * nxy[r] * nxy[s]);
                    mass[r][s] += weight * mass_per_area * n[r] * n[s];
                }
            }
        }
    }
    (stiffness, mass)
}

impl BfsPlate {
    /// Number of free dofs of the mesh.
    pub fn dofs(&self) -> usize {
        self.assemble().0.size
    }

    /// Node abscissae along the deck, the node rows across it, the free index
    /// of every global dof (w and w_y vanish on support lines) and the number
    /// of free dofs. Nodes are numbered across the width first.
    fn layout(&self) -> (Vec<f64>, usize, Vec<Option<usize>>, usize) {
        let mut node_x = vec![0.0];
        let mut supported = vec![true];
        let mut start = 0.0;
        for (&span, &count) in self.spans.iter().zip(&self.elements_along) {
            for e in 1..=count {
                node_x.push(start + span * e as f64 / count as f64);
                supported.push(e == count);
            }
            start += span;
        }
        let across = self.elements_across;
        let rows = across + 1;
        let nodes = node_x.len() * rows;
        // Free index of each global dof; w and w_y vanish on support lines.
        let mut free_index = vec![None; 4 * nodes];
        let mut free = 0;
        for (ix, &on_support) in supported.iter().enumerate() {
            for iy in 0..rows {
                for d in 0..4 {
                    if on_support && (d == 0 || d == 2) {
                        continue;
                    }
                    free_index[4 * (ix * rows + iy) + d] = Some(free);
                    free += 1;
                }
            }
        }
        (node_x, rows, free_index, free)
    }

    /// Assembles (K, M) on the free dofs, nodes numbered across the width
    /// first so the half-bandwidth is about 4(elements_across + 2).
    fn assemble(&self) -> (Band, Band) {
        let (node_x, rows, free_index, free) = self.layout();
        let across = self.elements_across;
        let element_dofs = |ix: usize, iy: usize| {
            let mut dofs = [None; 16];
            for q in 0..2 {
                for p in 0..2 {
                    let node = (ix + p) * rows + iy + q;
                    for d in 0..4 {
                        dofs[4 * (2 * q + p) + d] = free_index[4 * node + d];
                    }
                }
            }
            dofs
        };
        let mut band = 0;
        for ix in 0..node_x.len() - 1 {
            for iy in 0..across {
                let dofs: Vec<usize> = element_dofs(ix, iy).iter().flatten().copied().collect();
                let (lo, hi) = (dofs.iter().min().unwrap(), dofs.iter().max().unwrap());
                band = band.max(hi - lo);
            }
        }
        let mut stiffness = Band::new(free, band);
        let mut mass = Band::new(free, band);
        let b = self.width / across as f64;
        for ix in 0..node_x.len() - 1 {
            let a = node_x[ix + 1] - node_x[ix];
            let (ke, me) = element(a, b, self.mass_per_area, self.rigidities);
            for iy in 0..across {
                let dofs = element_dofs(ix, iy);
                for r in 0..16 {
                    let Some(gr) = dofs[r] else { continue };
                    for s in 0..=r {
                        let Some(gs) = dofs[s] else { continue };
                        // add() mirrors into the lower triangle; add each
                        // unordered pair once (the diagonal once too).
                        stiffness.add(gr, gs, ke[r][s]);
                        mass.add(gr, gs, me[r][s]);
                    }
                }
            }
        }
        (stiffness, mass)
    }

    /// The lowest `count` natural frequencies, Hz, ascending, by subspace
    /// iteration on K⁻¹M with 2·count + 8 vectors until every wanted
    /// eigenvalue changes by less than 1e-12 relative between iterations.
    pub fn lowest_frequencies(&self, count: usize) -> Vec<f64> {
        let (mut stiffness, mass) = self.assemble();
        stiffness.factor();
        let n = stiffness.size;
        let p = (2 * count + 8).min(n);
        // Deterministic, well-spread start vectors.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut x: Vec<Vec<f64>> = (0..p).map(|_| (0..n).map(|_| next()).collect()).collect();
        let mut previous = vec![f64::INFINITY; count];
        let mut y = vec![0.0; n];
        for _ in 0..500 {
            // X̄ = K⁻¹ M X; K̂ = X̄ᵀ M X (= X̄ᵀ K X̄), M̂ = X̄ᵀ M X̄.
            let mut mx: Vec<Vec<f64>> = Vec::with_capacity(p);
            for v in &mut x {
                mass.multiply(v, &mut y);
                mx.push(y.clone());
                v.copy_from_slice(&y);
                stiffness.solve(v);
            }
            let mut mxbar: Vec<Vec<f64>> = Vec::with_capacity(p);
            for v in &x {
                mass.multiply(v, &mut y);
                mxbar.push(y.clone());
            }
            let dot = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(a, b)| a * b).sum::<f64>();
            let k_hat =
                DMatrix::from_fn(p, p, |i, j| 0.5 * (dot(&x[i], &mx[j]) + dot(&x[j], &mx[i])));
            let m_hat = DMatrix::from_fn(p, p, |i, j| {
                0.5 * (dot(&x[i], &mxbar[j]) + dot(&x[j], &mxbar[i]))
            });
            let (values, q) = generalized_small(&k_hat, &m_hat);
            x = (0..p)
                .map(|c| {
                    let mut v = vec![0.0; n];
                    for (r, xr) in x.iter().enumerate() {
                        let w = q[(r, c)];
                        for (vi, xi) in v.iter_mut().zip(xr) {
                            *vi += w * xi;
                        }
                    }
                    v
                })
                .collect();
            let converged = values[..count]
                .iter()
                .zip(&previous)
                .all(|(l, p)| ((l - p) / l).abs() < 1e-12);
            previous.copy_from_slice(&values[..count]);
            if converged {
                break;
            }
        }
        previous
            .iter()
            .map(|l| l.sqrt() / (2.0 * std::f64::consts::PI))
            .collect()
    }
}

/// K q = λ M q for small dense symmetric K and SPD M: eigenvalues ascending
/// and M-orthonormal vectors (columns).
fn generalized_small(k: &DMatrix<f64>, m: &DMatrix<f64>) -> (Vec<f64>, DMatrix<f64>) {
    let l = m
        .clone()
        .cholesky()
        .expect("projected mass positive definite")
        .l();
    let l_inv = l
        .clone()
        .try_inverse()
        .expect("projected mass factor invertible");
    let a = &l_inv * k * l_inv.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let size = a.nrows();
    let eigen = SymmetricEigen::new(a);
    let mut order: Vec<usize> = (0..eigen.eigenvalues.len()).collect();
    order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
    let values = order.iter().map(|&i| eigen.eigenvalues[i]).collect();
    let u = DMatrix::from_fn(size, order.len(), |r, c| eigen.eigenvectors[(r, order[c])]);
    (values, l_inv.transpose() * u)
}

/// The deflection field of a BFS plate under one static point load.
pub struct StaticField {
    node_x: Vec<f64>,
    rows: usize,
    element_width: f64,
    free_index: Vec<Option<usize>>,
    /// Free-dof displacements, m.
    solution: Vec<f64>,
}

/// Element (ix, iy), its size (a, b) and the 16 bicubic Hermite shape
/// values at (x, y); local dof numbering as in [`element`].
fn shape_at(
    node_x: &[f64],
    element_width: f64,
    across: usize,
    x: f64,
    y: f64,
) -> (usize, usize, [f64; 16]) {
    let ix = node_x
        .partition_point(|&n| n <= x)
        .saturating_sub(1)
        .min(node_x.len() - 2);
    let iy = ((y / element_width).floor() as usize).min(across - 1);
    let a = node_x[ix + 1] - node_x[ix];
    let hx = hermite((x - node_x[ix]) / a, a);
    let hy = hermite(
        (y - iy as f64 * element_width) / element_width,
        element_width,
    );
    let mut n = [0.0; 16];
    for q in 0..2 {
        for p in 0..2 {
            for d in 0..4 {
                let jx = 2 * p + usize::from(d == 1 || d == 3);
                let jy = 2 * q + usize::from(d == 2 || d == 3);
                n[4 * (2 * q + p) + d] = hx[0][jx] * hy[0][jy];
            }
        }
    }
    (ix, iy, n)
}

impl StaticField {
    /// Deflection at (x, y), m, downward positive (the load's direction).
    pub fn deflection(&self, x: f64, y: f64) -> f64 {
        let across = self.rows - 1;
        let (ix, iy, n) = shape_at(&self.node_x, self.element_width, across, x, y);
        let mut w = 0.0;
        for q in 0..2 {
            for p in 0..2 {
                let node = (ix + p) * self.rows + iy + q;
                for d in 0..4 {
                    if let Some(g) = self.free_index[4 * node + d] {
                        w += n[4 * (2 * q + p) + d] * self.solution[g];
                    }
                }
            }
        }
        w
    }
}

impl BfsPlate {
    /// Static deflection field under a downward unit point load (1 N) at
    /// (x₀, y₀): K w = Nᵀ(x₀, y₀), the load's consistent nodal vector. By
    /// reciprocity (K symmetric) its value at (x, y) is also the deflection at
    /// (x₀, y₀) under a unit load at (x, y): the influence surface of the
    /// point (x₀, y₀).
    pub fn unit_load_field(&self, x0: f64, y0: f64) -> StaticField {
        let (node_x, rows, free_index, free) = self.layout();
        let (mut stiffness, _) = self.assemble();
        stiffness.factor();
        let element_width = self.width / self.elements_across as f64;
        let (ix, iy, n) = shape_at(&node_x, element_width, self.elements_across, x0, y0);
        let mut solution = vec![0.0; free];
        for q in 0..2 {
            for p in 0..2 {
                let node = (ix + p) * rows + iy + q;
                for d in 0..4 {
                    if let Some(g) = free_index[4 * node + d] {
                        solution[g] += n[4 * (2 * q + p) + d];
                    }
                }
            }
        }
        stiffness.solve(&mut solution);
        StaticField {
            node_x,
            rows,
            element_width,
            free_index,
            solution,
        }
    }
}
