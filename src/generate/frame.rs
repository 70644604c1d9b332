//! The 3D Euler–Bernoulli frame element and the offset spring, the two
//! building blocks of the generated models.
//!
//! DOF order per node: ux, uy, uz, rx, ry, rz (m, rad). Local axes: x' along
//! the element, bending in the x'–y' plane about z' (I_z), in the x'–z'
//! plane about y' (I_y), with θ_y' = −dw/dx' (right-handed), hence the sign
//! pattern of the x'–z' blocks. Stiffness and consistent mass after
//! Przemieniecki, Theory of Matrix Structural Analysis (1968), eqs. 5.116 and
//! 11.31; torsional inertia ρ·I_p·L/6·[2 1; 1 2] with I_p = I_y + I_z.

/// A prismatic section and its material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// Young's modulus E, Pa.
    pub youngs_modulus: f64,
    /// Shear modulus G, Pa.
    pub shear_modulus: f64,
    /// Density ρ, kg/m³.
    pub density: f64,
    /// Area A, m².
    pub area: f64,
    /// Second moment about local y' (bending in the x'–z' plane), m⁴.
    pub inertia_y: f64,
    /// Second moment about local z' (bending in the x'–y' plane), m⁴.
    pub inertia_z: f64,
    /// Saint-Venant torsion constant J, m⁴.
    pub torsion: f64,
}

/// A 12 × 12 element matrix (two nodes, six DOFs each).
pub type Element = [[f64; 12]; 12];

/// Local stiffness and consistent mass of a frame element of length
/// `length` (m): (N/m, N·m/rad; kg, kg·m²).
pub fn local_matrices(section: &Section, length: f64) -> (Element, Element) {
    let l = length;
    let mut k = [[0.0; 12]; 12];
    let mut m = [[0.0; 12]; 12];
    let s = section;
    // Axial (0, 6) and torsion (3, 9): two-node bars.
    let pairs = [
        (0, s.youngs_modulus * s.area / l, s.density * s.area * l),
        (3, s.shear_modulus * s.torsion / l, {
            s.density * (s.inertia_y + s.inertia_z) * l
        }),
    ];
    for (i, stiff, mass) in pairs {
        let j = i + 6;
        k[i][i] = stiff;
        k[j][j] = stiff;
        k[i][j] = -stiff;
        k[j][i] = -stiff;
        m[i][i] = mass / 3.0;
        m[j][j] = mass / 3.0;
        m[i][j] = mass / 6.0;
        m[j][i] = mass / 6.0;
    }
    // Bending: (translation, rotation) indices and the sign of the coupling
    // (+1 in x'–y' with θ_z' = dv/dx', −1 in x'–z' with θ_y' = −dw/dx').
    let planes = [
        ([1, 5, 7, 11], 1.0, s.youngs_modulus * s.inertia_z),
        ([2, 4, 8, 10], -1.0, s.youngs_modulus * s.inertia_y),
    ];
    let total = s.density * s.area * l;
    for (idx, sign, ei) in planes {
        let c = ei / (l * l * l);
        let kb = [
            [12.0, 6.0 * l * sign, -12.0, 6.0 * l * sign],
            [6.0 * l * sign, 4.0 * l * l, -6.0 * l * sign, 2.0 * l * l],
            [-12.0, -6.0 * l * sign, 12.0, -6.0 * l * sign],
            [6.0 * l * sign, 2.0 * l * l, -6.0 * l * sign, 4.0 * l * l],
        ];
        let mb = [
            [156.0, 22.0 * l * sign, 54.0, -13.0 * l * sign],
            [22.0 * l * sign, 4.0 * l * l, 13.0 * l * sign, -3.0 * l * l],
            [54.0, 13.0 * l * sign, 156.0, -22.0 * l * sign],
            [
                -13.0 * l * sign,
                -3.0 * l * l,
                -22.0 * l * sign,
                4.0 * l * l,
            ],
        ];
        for a in 0..4 {
            for b in 0..4 {
                k[idx[a]][idx[b]] = c * kb[a][b];
                m[idx[a]][idx[b]] = total / 420.0 * mb[a][b];
            }
        }
    }
    (k, m)
}

/// Local axes of an element from node `a` to node `b` (global coordinates,
/// m): rows x' (along), y', z'. Horizontal elements keep z' vertical;
/// vertical ones take y' = global Y (so z' = −X).
pub fn axes(a: [f64; 3], b: [f64; 3]) -> [[f64; 3]; 3] {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let x = [d[0] / len, d[1] / len, d[2] / len];
    let horizontal = (x[0] * x[0] + x[1] * x[1]).sqrt();
    let y = if horizontal > 1e-9 {
        // y' = Z × x' normalised: horizontal, to the left of the axis.
        [-x[1] / horizontal, x[0] / horizontal, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let z = [
        x[1] * y[2] - x[2] * y[1],
        x[2] * y[0] - x[0] * y[2],
        x[0] * y[1] - x[1] * y[0],
    ];
    [x, y, z]
}

/// Tᵀ A T with T = diag(R, R, R, R), R the rows of `axes` (u' = R u).
pub fn to_global(local: &Element, axes: &[[f64; 3]; 3]) -> Element {
    let mut t = [[0.0; 12]; 12];
    for block in 0..4 {
        for r in 0..3 {
            for c in 0..3 {
                t[3 * block + r][3 * block + c] = axes[r][c];
            }
        }
    }
    let mut at = [[0.0; 12]; 12];
    for i in 0..12 {
        for j in 0..12 {
            at[i][j] = (0..12).map(|p| local[i][p] * t[p][j]).sum();
        }
    }
    let mut out = [[0.0; 12]; 12];
    for i in 0..12 {
        for j in 0..12 {
            out[i][j] = (0..12).map(|p| t[p][i] * at[p][j]).sum();
        }
    }
    out
}

/// Coefficients g (six per node) of the displacement along global axis
/// `axis` (0 = x, 1 = y, 2 = z) of a point rigidly attached to a node at
/// `offset` (m): u_p = u + θ × r.
pub fn point_row(axis: usize, offset: [f64; 3]) -> [f64; 6] {
    let [rx, ry, rz] = offset;
    let mut g = [0.0; 6];
    g[axis] = 1.0;
    // (θ × r)_x = θy rz − θz ry, (θ × r)_y = θz rx − θx rz, (θ × r)_z = θx ry − θy rx.
    match axis {
        0 => {
            g[4] = rz;
            g[5] = -ry;
        }
        1 => {
            g[5] = rx;
            g[3] = -rz;
        }
        _ => {
            g[3] = ry;
            g[4] = -rx;
        }
    }
    g
}
