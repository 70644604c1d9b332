//! Fields on a 1-D mesh of Hermite-cubic beam elements.
//!
//! Each node carries, per component, a transverse value w and a rotation
//! θ = dw/dx. Between nodes the field is the Hermite cubic (Przemieniecki,
//! Theory of Matrix Structural Analysis, §11.3):
//! w(ξ) = N₁ wₐ + N₂ h θₐ + N₃ w_b + N₄ h θ_b, ξ = (x − xₐ)/h ∈ [0, 1],
//! N₁ = 1 − 3ξ² + 2ξ³, N₂ = ξ − 2ξ² + ξ³, N₃ = 3ξ² − 2ξ³, N₄ = −ξ² + ξ³.
//! Mode shapes (one component per mode) and static influence lines (one
//! component) are both stored this way, so evaluating n components at a
//! point costs 4n multiply–adds after an O(log nodes) element search.

/// Hermite shape functions and their x-derivatives at local coordinate ξ of an
/// element of length `h` (m): `(values, slopes)` for the dofs (wₐ, θₐ, w_b, θ_b).
#[inline]
pub fn shape_functions(xi: f64, h: f64) -> ([f64; 4], [f64; 4]) {
    let xi2 = xi * xi;
    let xi3 = xi2 * xi;
    let values = [
        1.0 - 3.0 * xi2 + 2.0 * xi3,
        h * (xi - 2.0 * xi2 + xi3),
        3.0 * xi2 - 2.0 * xi3,
        h * (-xi2 + xi3),
    ];
    let slopes = [
        (-6.0 * xi + 6.0 * xi2) / h,
        1.0 - 4.0 * xi + 3.0 * xi2,
        (6.0 * xi - 6.0 * xi2) / h,
        -2.0 * xi + 3.0 * xi2,
    ];
    (values, slopes)
}

/// Second x-derivatives of the Hermite shape functions (1/m² for the value
/// dofs, 1/m for the rotation dofs).
#[inline]
pub fn shape_curvatures(xi: f64, h: f64) -> [f64; 4] {
    [
        (-6.0 + 12.0 * xi) / (h * h),
        (-4.0 + 6.0 * xi) / h,
        (6.0 - 12.0 * xi) / (h * h),
        (-2.0 + 6.0 * xi) / h,
    ]
}

/// The common element length of a mesh whose elements agree to 1e-12
/// relative, else `None`.
fn uniform_spacing(node_x: &[f64]) -> Option<f64> {
    if node_x.len() < 2 {
        return None;
    }
    let h = (node_x[node_x.len() - 1] - node_x[0]) / (node_x.len() - 1) as f64;
    (h > 0.0
        && node_x
            .windows(2)
            .all(|w| ((w[1] - w[0]) - h).abs() <= 1e-12 * h))
    .then_some(h)
}

/// A field with `components` values per node on a beam mesh.
#[derive(Debug, Clone)]
pub struct HermiteField {
    /// Node positions along the bridge, m, strictly increasing.
    node_x: Vec<f64>,
    /// Number of components (e.g. modes).
    components: usize,
    /// Nodal data laid out `[node][w, θ][component]` so one point's
    /// evaluation reads two contiguous node blocks.
    nodal: Vec<f64>,
    /// The element length when the mesh is uniform (to 1e-12 relative), m:
    /// the element of a point is then found in O(1) instead of a binary search.
    spacing: Option<f64>,
}

impl HermiteField {
    /// Builds a field from node positions and a closure giving (w, θ) of
    /// component `c` at node `n`.
    pub fn from_fn(
        node_x: Vec<f64>,
        components: usize,
        mut value: impl FnMut(usize, usize) -> (f64, f64),
    ) -> Self {
        let mut nodal = vec![0.0; node_x.len() * 2 * components];
        for n in 0..node_x.len() {
            for c in 0..components {
                let (w, theta) = value(n, c);
                nodal[(2 * n) * components + c] = w;
                nodal[(2 * n + 1) * components + c] = theta;
            }
        }
        let spacing = uniform_spacing(&node_x);
        Self {
            node_x,
            components,
            nodal,
            spacing,
        }
    }

    /// One field holding `fields` (each of one component, all on the same
    /// nodes) as its components, in order, so that one [`Self::values_at`]
    /// gives every field's [`Self::value_at`], bit for bit (the same element,
    /// shape functions and sums), from one element search. `None` when the
    /// nodes differ or a field has more than one component.
    pub fn stacked(fields: &[&HermiteField]) -> Option<HermiteField> {
        let first = fields.first()?;
        if fields
            .iter()
            .any(|f| f.components != 1 || f.node_x != first.node_x || f.spacing != first.spacing)
        {
            return None;
        }
        let components = fields.len();
        let mut nodal = vec![0.0; first.nodal.len() * components];
        for (c, field) in fields.iter().enumerate() {
            for (slot, &value) in field.nodal.iter().enumerate() {
                nodal[slot * components + c] = value;
            }
        }
        Some(Self {
            node_x: first.node_x.clone(),
            components,
            nodal,
            spacing: first.spacing,
        })
    }

    /// Number of components.
    pub fn components(&self) -> usize {
        self.components
    }

    /// Length of the mesh, m.
    pub fn length(&self) -> f64 {
        self.node_x.last().copied().unwrap_or(0.0) - self.node_x[0]
    }

    /// Node positions, m.
    pub fn node_x(&self) -> &[f64] {
        &self.node_x
    }

    /// Value and rotation of component `c` at node `n`.
    pub fn nodal(&self, n: usize, c: usize) -> (f64, f64) {
        (
            self.nodal[(2 * n) * self.components + c],
            self.nodal[(2 * n + 1) * self.components + c],
        )
    }

    /// Element index and local coordinate of `x`; `None` off the mesh.
    #[inline]
    fn locate(&self, x: f64) -> Option<(usize, f64, f64)> {
        let first = self.node_x[0];
        let last = *self.node_x.last()?;
        if !(x >= first && x <= last) {
            return None;
        }
        // The last element starting at or left of x (the last element for
        // x at the end): a guess from a uniform spacing, corrected to the
        // exact answer of the binary search, or the binary search itself.
        let nodes = self.node_x.len();
        let element = match self.spacing {
            Some(h) => {
                let mut e = (((x - first) / h) as usize).min(nodes - 2);
                while e > 0 && self.node_x[e] > x {
                    e -= 1;
                }
                while e + 2 < nodes && self.node_x[e + 1] <= x {
                    e += 1;
                }
                e
            }
            None => {
                // partition_point gives the first node strictly right of x.
                let right = self.node_x.partition_point(|&nx| nx <= x);
                right.clamp(1, nodes - 1) - 1
            }
        };
        let xa = self.node_x[element];
        let h = self.node_x[element + 1] - xa;
        Some((element, ((x - xa) / h).clamp(0.0, 1.0), h))
    }

    /// Writes every component's value at `x` into `values`; zeros off the mesh.
    #[inline]
    pub fn values_at(&self, x: f64, values: &mut [f64]) {
        debug_assert_eq!(values.len(), self.components);
        let Some((element, xi, h)) = self.locate(x) else {
            values.fill(0.0);
            return;
        };
        let (n, _) = shape_functions(xi, h);
        let base = 2 * element * self.components;
        let block = &self.nodal[base..base + 4 * self.components];
        let (wa, rest) = block.split_at(self.components);
        let (ta, rest) = rest.split_at(self.components);
        let (wb, tb) = rest.split_at(self.components);
        for c in 0..self.components {
            values[c] = n[0] * wa[c] + n[1] * ta[c] + n[2] * wb[c] + n[3] * tb[c];
        }
    }

    /// Writes values, slopes (1/m) and curvatures (d²/dx², 1/m²) at `x`;
    /// zeros off the mesh. The curvature of a Hermite cubic is linear within
    /// an element and may jump at nodes; at a node the element to the right is used.
    #[inline]
    pub fn values_slopes_curvatures_at(
        &self,
        x: f64,
        values: &mut [f64],
        slopes: &mut [f64],
        curvatures: &mut [f64],
    ) {
        let Some((element, xi, h)) = self.locate(x) else {
            values.fill(0.0);
            slopes.fill(0.0);
            curvatures.fill(0.0);
            return;
        };
        let (n, dn) = shape_functions(xi, h);
        let ddn = shape_curvatures(xi, h);
        let k = self.components;
        let base = 2 * element * k;
        for c in 0..k {
            let dofs = [
                self.nodal[base + c],
                self.nodal[base + k + c],
                self.nodal[base + 2 * k + c],
                self.nodal[base + 3 * k + c],
            ];
            values[c] = n[0] * dofs[0] + n[1] * dofs[1] + n[2] * dofs[2] + n[3] * dofs[3];
            slopes[c] = dn[0] * dofs[0] + dn[1] * dofs[1] + dn[2] * dofs[2] + dn[3] * dofs[3];
            curvatures[c] =
                ddn[0] * dofs[0] + ddn[1] * dofs[1] + ddn[2] * dofs[2] + ddn[3] * dofs[3];
        }
    }

    /// Value of a single-component field at `x` (0 off the mesh).
    #[inline]
    pub fn value_at(&self, x: f64) -> f64 {
        debug_assert_eq!(self.components, 1);
        let mut v = [0.0];
        self.values_at(x, &mut v);
        v[0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic is reproduced exactly by Hermite interpolation.
    #[test]
    fn cubic_is_exact() {
        let ddf = |x: f64| 1.8 * x - 4.0;
        let f = |x: f64| 0.3 * x * x * x - 2.0 * x * x + x - 4.0;
        let df = |x: f64| 0.9 * x * x - 4.0 * x + 1.0;
        let field = HermiteField::from_fn(vec![0.0, 1.5, 2.0, 4.0], 1, |n, _| {
            let x = [0.0, 1.5, 2.0, 4.0][n];
            (f(x), df(x))
        });
        for i in 0..=40 {
            let x = 4.0 * i as f64 / 40.0;
            let (mut v, mut s, mut c) = ([0.0], [0.0], [0.0]);
            field.values_slopes_curvatures_at(x, &mut v, &mut s, &mut c);
            assert!((v[0] - f(x)).abs() < 1e-12, "x={x}");
            assert!((s[0] - df(x)).abs() < 1e-12, "x={x}");
            assert!((field.value_at(x) - f(x)).abs() < 1e-12, "x={x}");
            assert!((c[0] - ddf(x)).abs() < 1e-11, "x={x}");
        }
        assert_eq!(field.value_at(-0.1), 0.0);
        assert_eq!(field.value_at(4.1), 0.0);
    }

    /// A stack of one-component fields gives each field's value bit for
    /// bit, off the mesh too; fields on other nodes do not stack.
    #[test]
    fn stacked_fields_give_each_value_exactly() {
        let nodes = vec![0.0, 0.75, 1.5, 2.25, 3.0];
        let fields: Vec<HermiteField> = (0..3)
            .map(|k| {
                HermiteField::from_fn(nodes.clone(), 1, |n, _| {
                    let x = nodes[n] + 0.1 * k as f64;
                    (x.sin() / 3.0, (1.7 * x).cos() * 1e-3)
                })
            })
            .collect();
        let refs: Vec<&HermiteField> = fields.iter().collect();
        let stack = HermiteField::stacked(&refs).expect("same nodes");
        assert_eq!(stack.components(), 3);
        let mut values = [0.0; 3];
        for i in -3..=33 {
            let x = 0.1 * i as f64 - 0.0123;
            stack.values_at(x, &mut values);
            for (v, f) in values.iter().zip(&fields) {
                assert_eq!(v.to_bits(), f.value_at(x).to_bits(), "x = {x}");
            }
        }
        let other = HermiteField::from_fn(vec![0.0, 1.0, 3.0], 1, |_, _| (1.0, 0.0));
        assert!(HermiteField::stacked(&[&fields[0], &other]).is_none());
        assert!(HermiteField::stacked(&[&stack]).is_none());
        assert!(HermiteField::stacked(&[]).is_none());
    }
}
