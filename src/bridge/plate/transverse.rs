//! The transverse Ritz functions of the plate deck, Yⱼ(y) across the width,
//! and their integrals B0, B1, B2, B02 (see the parent module).

/// The transverse Ritz functions Yⱼ(y), each scaled so that ∫₀ᵇ Yⱼ² dy = 1
/// (so Yⱼ is in 1/√m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum TransverseBasis {
    /// Free longitudinal edges: Yⱼ = √((2j + 1)/b) Pⱼ(2y/b − 1).
    Legendre,
    /// Simply supported longitudinal edges: Yⱼ = √(2/b) sin((j + 1)πy/b).
    Sine,
}

impl TransverseBasis {
    /// Calls `visit(j, [Yⱼ, dYⱼ/dy, d²Yⱼ/dy²])` for j = 0..`count` at `y`
    /// (m) across a deck of width `width` (m). Units 1/√m, 1/m^(3/2),
    /// 1/m^(5/2). No allocation: the Legendre values come from the
    /// three-term recurrences, O(count).
    #[inline]
    pub(super) fn for_each(
        self,
        width: f64,
        count: usize,
        y: f64,
        mut visit: impl FnMut(usize, [f64; 3]),
    ) {
        match self {
            TransverseBasis::Legendre => {
                let xi = 2.0 * y / width - 1.0;
                let dxi_dy = 2.0 / width;
                // (P, P', P'') of degree n − 1 and n, derivatives in ξ.
                let mut previous = [0.0; 3];
                let mut current = [1.0, 0.0, 0.0];
                for j in 0..count {
                    let scale = ((2 * j + 1) as f64 / width).sqrt();
                    visit(
                        j,
                        [
                            scale * current[0],
                            scale * dxi_dy * current[1],
                            scale * dxi_dy * dxi_dy * current[2],
                        ],
                    );
                    // Bonnet: (n+1)P_{n+1} = (2n+1)ξPₙ − nP_{n−1}; and the
                    // derivative identity P'_{n+1} − P'_{n−1} = (2n+1)Pₙ
                    // (differentiated once more for P''), which stay exact at
                    // the edges ξ = ±1 where other forms divide by 1 − ξ².
                    let n = j as f64;
                    let next = [
                        ((2.0 * n + 1.0) * xi * current[0] - n * previous[0]) / (n + 1.0),
                        previous[1] + (2.0 * n + 1.0) * current[0],
                        previous[2] + (2.0 * n + 1.0) * current[1],
                    ];
                    previous = current;
                    current = next;
                }
            }
            TransverseBasis::Sine => {
                let scale = (2.0 / width).sqrt();
                for j in 0..count {
                    let k = (j + 1) as f64 * std::f64::consts::PI / width;
                    let (s, c) = (k * y).sin_cos();
                    visit(j, [scale * s, scale * k * c, -scale * k * k * s]);
                }
            }
        }
    }

    /// The transverse integrals (B0, B1, B2, B02), each `count` × `count`,
    /// row-major: B0 = ∫YⱼYₗ dy (dimensionless), B1 = ∫Yⱼ'Yₗ' dy (1/m²),
    /// B2 = ∫Yⱼ''Yₗ'' dy (1/m⁴), B02 = ∫Yⱼ Yₗ'' dy (1/m², not symmetric for
    /// the Legendre basis).
    pub(super) fn integrals(self, width: f64, count: usize) -> [Vec<f64>; 4] {
        let mut b0 = vec![0.0; count * count];
        let mut b1 = vec![0.0; count * count];
        let mut b2 = vec![0.0; count * count];
        let mut b02 = vec![0.0; count * count];
        match self {
            TransverseBasis::Legendre => {
                // Products have degree ≤ 2(count − 1); `count + 1` Gauss
                // points integrate degree 2·count + 1 exactly.
                let (points, weights) = gauss_legendre(count + 1);
                let mut at = vec![[0.0; 3]; count];
                for (&xi, &weight) in points.iter().zip(&weights) {
                    let y = 0.5 * width * (xi + 1.0);
                    let w = 0.5 * width * weight;
                    self.for_each(width, count, y, |j, v| at[j] = v);
                    for j in 0..count {
                        for l in 0..count {
                            let jl = j * count + l;
                            b0[jl] += w * at[j][0] * at[l][0];
                            b1[jl] += w * at[j][1] * at[l][1];
                            b2[jl] += w * at[j][2] * at[l][2];
                            b02[jl] += w * at[j][0] * at[l][2];
                        }
                    }
                }
            }
            TransverseBasis::Sine => {
                // Orthonormal sines: every integral is diagonal.
                for j in 0..count {
                    let k = (j + 1) as f64 * std::f64::consts::PI / width;
                    let jj = j * count + j;
                    b0[jj] = 1.0;
                    b1[jj] = k * k;
                    b2[jj] = k * k * k * k;
                    b02[jj] = -k * k;
                }
            }
        }
        [b0, b1, b2, b02]
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1] with `count` points, exact
/// for polynomials of degree ≤ 2·count − 1 (Newton on Pₙ from Chebyshev
/// guesses; Abramowitz & Stegun 25.4.29).
pub(super) fn gauss_legendre(count: usize) -> (Vec<f64>, Vec<f64>) {
    let n = count as f64;
    let mut points = Vec::with_capacity(count);
    let mut weights = Vec::with_capacity(count);
    for k in 0..count {
        let mut x = (std::f64::consts::PI * (k as f64 + 0.75) / (n + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            // Pₙ(x) and Pₙ'(x) by the Bonnet recurrence.
            let (mut p_prev, mut p) = (1.0, x);
            for m in 1..count {
                let m = m as f64;
                let next = ((2.0 * m + 1.0) * x * p - m * p_prev) / (m + 1.0);
                p_prev = p;
                p = next;
            }
            derivative = n * (x * p - p_prev) / (x * x - 1.0);
            let step = p / derivative;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        points.push(x);
        weights.push(2.0 / ((1.0 - x * x) * derivative * derivative));
    }
    (points, weights)
}
