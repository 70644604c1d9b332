//! The contact flexibility Z = w K̂⁻¹ on the deck line's DOFs, formed once
//! with K̂'s factor: densely for a short line, banded for a long track.
//!
//! **Why a band is exact enough.** K̂ = K + a₀M + wa₁C is the step's
//! effective stiffness: at the steps that resolve a track (Δt ≲ 1 ms) its
//! mass term a₀M = M/(βΔt²) dominates the bending of each beam along the
//! line, and an influence along a beam of bending stiffness EI and mass m
//! per metre decays as e^(−|x|/ℓ), ℓ ≈ (4EIβΔt²/m)^(1/4): 0.3 m for a
//! UIC60 rail (6.4 MN·m², 60 kg/m) at Δt = 0.5 ms, about 1 m for a deck
//! of 1e11 N·m² and 20 t/m, whose decay governs. So Z_ij is below any
//! round-off-sized fraction beyond a distance B along the line (both
//! rails), and Z is stored as a band: every column j keeps the rows within
//! B of it, in the line's x order. Measured (B where every entry has
//! fallen below 1e-12 of its column's largest): 31.6 m on the generated
//! 30-span viaduct at Δt = 0.5 ms, 12 m on a 16 × 3 m one at 0.2 ms.
//!
//! **How it is formed (probing).** DOFs more than 2B apart do not see each
//! other, so one solve K̂s = Σ_{j∈k} e_j with a *colour* k of such DOFs
//! gives every column of that colour within its band at once (Curtis,
//! Powell & Reid 1974's grouping of Jacobian columns; for inverses, Tang &
//! Saad 2012): a row i within B of j gets s_i = Z_ij + Σ_{j′≠j} Z_ij′, the
//! other terms being the influences of sources at least B away. Colours
//! are dealt greedily along x (about 2B × DOFs per metre of them), solved
//! [`super::contact::SOLVE_BLOCK`] at a time.
//!
//! **How B is chosen, and checked.** Eight columns spread along the line
//! are solved exactly; B is where each of them has fallen, for good, below
//! [`BAND_DECAY`] of its largest entry, with a margin; then the band is
//! formed and checked against eight *other* exact columns: every entry,
//! inside the band or out, within [`BAND_TOLERANCE`]·√(Z_ii Z_jj) (the
//! Cauchy–Schwarz bound of an SPD matrix, in each pair's own units). If
//! not, B doubles. A band wider than half the line (long steps,
//! a stiff substructure, a short model) falls back to the dense form where
//! that fits ([`super::contact::MAX_LINE_DOFS`]) and is refused otherwise.
//!
//! **Cost.** Dense: n_R solves, n_R² × 8 bytes. Banded: colours + 16
//! solves (O(nnz(L)) each) and Σ_j (band rows of j) × 8 bytes: 20,728
//! rail DOFs of the 30-span viaduct at Δt = 0.5 ms keep a few hundred rows
//! each (tens of MB) where the dense form needed 3.4 GB. A lookup is O(1).

use faer::MatMut;

use super::contact::{MAX_LINE_DOFS, SOLVE_BLOCK};
use crate::bridge::eigen::sparse::Factor;
use crate::solve::SolveError;

/// Relative size below which an influence counts as gone when B is chosen.
pub const BAND_DECAY: f64 = 1e-12;
/// Largest error of any entry of the banded Z, relative to √(Z_ii Z_jj).
pub const BAND_TOLERANCE: f64 = 1e-10;
/// Largest banded Z kept, bytes (1 GB).
pub const MAX_BAND_BYTES: usize = 1 << 30;
/// Columns solved exactly to choose B and to check the band.
const CHECK_COLUMNS: usize = 8;

/// Z = w K̂⁻¹ restricted to the deck line's DOFs, m/N (rad/N·m, … for the
/// rotations), in line indices.
#[derive(Debug, Clone)]
pub enum LineFlexibility {
    /// Every entry, column-major n_R × n_R.
    Dense {
        /// n_R.
        order: usize,
        /// Z, column-major.
        values: Vec<f64>,
    },
    /// The rows of each column j within the band (line indices sorted by
    /// x): rows `first[j]..first[j] + len`, stored from `offset[j]`.
    Banded {
        /// First row of each column's band.
        first: Vec<usize>,
        /// Where each column's band starts in `values`; one more entry
        /// at the end.
        offset: Vec<usize>,
        /// The bands, column after column.
        values: Vec<f64>,
        /// The band's half-width B along the line, m.
        band: f64,
    },
}

impl LineFlexibility {
    /// Z_ij (line indices), 0 outside the band.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> f64 {
        match self {
            Self::Dense { order, values } => values[j * order + i],
            Self::Banded {
                first,
                offset,
                values,
                ..
            } => {
                let len = offset[j + 1] - offset[j];
                match i.checked_sub(first[j]) {
                    Some(k) if k < len => values[offset[j] + k],
                    _ => 0.0,
                }
            }
        }
    }

    /// The band's half-width along the line, m (`None` when dense).
    pub fn band(&self) -> Option<f64> {
        match self {
            Self::Dense { .. } => None,
            Self::Banded { band, .. } => Some(*band),
        }
    }
}

/// Why the contact flexibility cannot be held.
fn refused(reason: String) -> SolveError {
    SolveError::Direct { reason }
}

fn memory() -> SolveError {
    refused("the contact flexibility does not fit in memory".into())
}

/// Z = w K̂⁻¹ on the line DOFs `line` (free-DOF indices) with K̂'s factor
/// `effective`: banded where the DOFs' positions along the line
/// `positions` (m, ascending, one per DOF) are given and Z decays within
/// a quarter of the line (the band is then at most half of it), else dense
/// up to [`MAX_LINE_DOFS`].
///
/// # Errors
///
/// [`SolveError::Direct`] for a line above [`MAX_LINE_DOFS`] without
/// positions or whose Z does not decay along it, a band above
/// [`MAX_BAND_BYTES`], or a workspace that does not fit in memory.
pub fn form(
    effective: &Factor,
    line: &[usize],
    positions: Option<&[f64]>,
    weight: f64,
) -> Result<LineFlexibility, SolveError> {
    let nr = line.len();
    if let Some(positions) = positions.filter(|_| nr > 2 * CHECK_COLUMNS) {
        match banded(effective, line, positions, weight)? {
            Some(z) => return Ok(z),
            None if nr <= MAX_LINE_DOFS => {}
            None => {
                return Err(refused(format!(
                    "the deck line has {nr} DOFs and its contact flexibility does not decay \
                     within a quarter of it at this time step; it is kept densely up to \
                     {MAX_LINE_DOFS} DOFs, and a shorter time step localises it"
                )));
            }
        }
    }
    if nr > MAX_LINE_DOFS {
        return Err(refused(format!(
            "the deck line has {nr} DOFs; its contact flexibility is kept densely up to \
             {MAX_LINE_DOFS}"
        )));
    }
    dense(effective, line, weight)
}

/// Every column, [`SOLVE_BLOCK`] solves at a time.
fn dense(effective: &Factor, line: &[usize], weight: f64) -> Result<LineFlexibility, SolveError> {
    let (n, nr) = (effective.order(), line.len());
    let mut values = Vec::new();
    values.try_reserve_exact(nr * nr).map_err(|_| memory())?;
    values.resize(nr * nr, 0.0);
    let columns: Vec<usize> = (0..nr).collect();
    let mut solver = Probe::new(effective, n)?;
    for group in columns.chunks(SOLVE_BLOCK) {
        let block = solver.solve(group.iter().map(|&j| vec![line[j]]));
        for (k, &j) in group.iter().enumerate() {
            let column = &mut values[j * nr..(j + 1) * nr];
            for (i, &dof) in line.iter().enumerate() {
                column[i] = weight * block[k * n + dof];
            }
        }
    }
    Ok(LineFlexibility::Dense { order: nr, values })
}

/// Block solves with K̂'s factor on unit loads (sums of them for a colour).
struct Probe<'f> {
    factor: &'f Factor,
    n: usize,
    block: Vec<f64>,
    workspace: faer::dyn_stack::MemBuffer,
}

impl<'f> Probe<'f> {
    fn new(factor: &'f Factor, n: usize) -> Result<Self, SolveError> {
        let workspace = factor.block_workspace(SOLVE_BLOCK).map_err(|_| memory())?;
        let mut block = Vec::new();
        block
            .try_reserve_exact(n * SOLVE_BLOCK)
            .map_err(|_| memory())?;
        block.resize(n * SOLVE_BLOCK, 0.0);
        Ok(Self {
            factor,
            n,
            block,
            workspace,
        })
    }

    /// K̂⁻¹ Σ_{d∈group} e_d for each group (at most [`SOLVE_BLOCK`] of
    /// them), column after column of the returned block.
    fn solve(&mut self, groups: impl Iterator<Item = Vec<usize>>) -> &[f64] {
        let n = self.n;
        self.block.fill(0.0);
        let mut width = 0;
        for (k, group) in groups.enumerate() {
            for dof in group {
                self.block[k * n + dof] = 1.0;
            }
            width = k + 1;
        }
        let rhs = MatMut::from_column_major_slice_mut(&mut self.block[..n * width], n, width);
        self.factor.solve_block_in_place(rhs, &mut self.workspace);
        &self.block[..n * width]
    }
}

/// The banded form: B from exact columns, the band by probing, checked
/// against other exact columns; B doubles until the check passes. `None`
/// when B reaches a quarter of the line (the band half of it: the dense
/// form costs at most twice as much).
fn banded(
    effective: &Factor,
    line: &[usize],
    positions: &[f64],
    weight: f64,
) -> Result<Option<LineFlexibility>, SolveError> {
    let (n, nr) = (effective.order(), line.len());
    let length = positions[nr - 1] - positions[0];
    let mut probe = Probe::new(effective, n)?;
    let exact = |probe: &mut Probe<'_>, shift: usize| -> Vec<(usize, Vec<f64>)> {
        let picks: Vec<usize> = (0..CHECK_COLUMNS)
            .map(|k| ((2 * k + 1) * nr / (2 * CHECK_COLUMNS) + shift).min(nr - 1))
            .collect();
        let block = probe.solve(picks.iter().map(|&j| vec![line[j]]));
        picks
            .iter()
            .enumerate()
            .map(|(k, &j)| {
                let column = line
                    .iter()
                    .map(|&dof| weight * block[k * n + dof])
                    .collect();
                (j, column)
            })
            .collect()
    };
    // B: where every chosen column has fallen below BAND_DECAY for good.
    let mut band = exact(&mut probe, 0)
        .iter()
        .map(|(j, column)| {
            let top = column.iter().fold(0.0f64, |m, z| m.max(z.abs()));
            column
                .iter()
                .zip(positions)
                .filter(|(z, _)| z.abs() > BAND_DECAY * top)
                .map(|(_, x)| (x - positions[*j]).abs())
                .fold(0.0f64, f64::max)
        })
        .fold(0.0f64, f64::max)
        * 1.25;
    let checks = exact(&mut probe, nr / (4 * CHECK_COLUMNS));
    loop {
        if 4.0 * band >= length {
            return Ok(None);
        }
        let z = probed(&mut probe, line, positions, weight, band)?;
        if check(&z, &checks) {
            return Ok(Some(z));
        }
        band *= 2.0;
    }
}

/// The band of half-width `band` (m) by coloured solves.
fn probed(
    probe: &mut Probe<'_>,
    line: &[usize],
    positions: &[f64],
    weight: f64,
    band: f64,
) -> Result<LineFlexibility, SolveError> {
    let (n, nr) = (probe.n, line.len());
    // Each column's rows within the band.
    let mut first = Vec::with_capacity(nr);
    let mut offset = Vec::with_capacity(nr + 1);
    let (mut lo, mut hi, mut total) = (0usize, 0usize, 0usize);
    for j in 0..nr {
        while positions[lo] < positions[j] - band {
            lo += 1;
        }
        while hi + 1 < nr && positions[hi + 1] <= positions[j] + band {
            hi += 1;
        }
        first.push(lo);
        offset.push(total);
        total += hi - lo + 1;
    }
    offset.push(total);
    if total.saturating_mul(8) > MAX_BAND_BYTES {
        return Err(refused(format!(
            "the banded contact flexibility of {nr} line DOFs would need {} MB (band {band:.1} \
             m), above {} MB",
            (total * 8) >> 20,
            MAX_BAND_BYTES >> 20
        )));
    }
    let mut values = Vec::new();
    values.try_reserve_exact(total).map_err(|_| memory())?;
    values.resize(total, 0.0);
    // Greedy colours along x: a DOF joins the first colour whose last
    // member is more than 2B behind it.
    let mut last: Vec<f64> = Vec::new();
    let mut colours: Vec<Vec<usize>> = Vec::new();
    for j in 0..nr {
        let x = positions[j];
        match last.iter().position(|&l| x - l > 2.0 * band) {
            Some(k) => {
                last[k] = x;
                colours[k].push(j);
            }
            None => {
                last.push(x);
                colours.push(vec![j]);
            }
        }
    }
    for group in colours.chunks(SOLVE_BLOCK) {
        let block = probe.solve(
            group
                .iter()
                .map(|members| members.iter().map(|&j| line[j]).collect()),
        );
        for (k, members) in group.iter().enumerate() {
            let column = &block[k * n..(k + 1) * n];
            for &j in members {
                let len = offset[j + 1] - offset[j];
                for r in 0..len {
                    values[offset[j] + r] = weight * column[line[first[j] + r]];
                }
            }
        }
    }
    Ok(LineFlexibility::Banded {
        first,
        offset,
        values,
        band,
    })
}

/// Whether every entry of the exact `checks` columns is within
/// [`BAND_TOLERANCE`]·√(Z_ii Z_jj) of the band's (0 outside it).
fn check(z: &LineFlexibility, checks: &[(usize, Vec<f64>)]) -> bool {
    checks.iter().all(|(j, column)| {
        let zjj = column[*j].abs();
        column.iter().enumerate().all(|(i, &exact)| {
            let scale = (z.get(i, i).abs() * zjj).sqrt();
            (exact - z.get(i, *j)).abs() <= BAND_TOLERANCE * scale
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bridge::eigen::sparse::symmetric_from_entries;

    /// Two chains ("rails", `nodes` each, 0.5 m apart along x) of springs
    /// k between neighbours, tied at every station by k_c and to the
    /// ground by k_g, with the mass term a₀m of a step: K̂ on 2·nodes DOFs,
    /// interleaved (rail 0, rail 1) station by station.
    fn chains(nodes: usize, mass_term: f64, kg: f64) -> (Factor, Vec<usize>, Vec<f64>) {
        let (k, kc) = (1.0e8, 2.0e7);
        let n = 2 * nodes;
        let mut entries = Vec::new();
        for p in 0..nodes {
            for r in 0..2 {
                let i = 2 * p + r;
                let neighbours = if p == 0 || p + 1 == nodes { 1.0 } else { 2.0 };
                entries.push((i, i, neighbours * k + kc + kg + mass_term));
                if p + 1 < nodes {
                    entries.push((i + 2, i, -k));
                }
            }
            entries.push((2 * p + 1, 2 * p, -kc));
        }
        let matrix = symmetric_from_entries(n, entries, true).expect("matrix");
        let factor = Factor::new(&matrix).expect("factor");
        let positions = (0..n).map(|i| 0.5 * (i / 2) as f64).collect();
        (factor, (0..n).collect(), positions)
    }

    /// The banded Z against exact columns K̂⁻¹e_j (solved one at a time):
    /// every entry of 40 columns along the line within BAND_TOLERANCE ·
    /// √(Z_ii Z_jj), 0 outside the band included, on 12,000 DOFs (above the
    /// dense limit); and the band far narrower than the line.
    #[test]
    fn banded_flexibility_equals_the_inverse() {
        let (factor, line, positions) = chains(6_000, 4.0e9, 1.0e6);
        let z = form(&factor, &line, Some(&positions), 1.05).expect("banded");
        let band = z.band().expect("banded above the dense limit");
        assert!(band < 100.0, "band {band} m of a 3,000 m line");
        let n = line.len();
        let mut workspace = factor.workspace().expect("workspace");
        let mut worst = 0.0f64;
        for j in (0..n).step_by(n / 40 + 1).chain([0, 1, n - 2, n - 1]) {
            let mut column = vec![0.0; n];
            column[j] = 1.0;
            factor.solve_in_place(&mut column, &mut workspace);
            for (i, exact) in column.iter().map(|v| 1.05 * v).enumerate() {
                let scale = (z.get(i, i) * z.get(j, j)).sqrt();
                worst = worst.max((exact - z.get(i, j)).abs() / scale);
            }
        }
        assert!(worst <= BAND_TOLERANCE, "worst relative error {worst:e}");
    }

    /// Where Z does not decay within a quarter of the line (no ground
    /// springs and a light mass term: long steps on a free track), a short
    /// line is kept dense — exact — and a long one is refused with the
    /// reason.
    #[test]
    fn slow_decay_falls_back_to_dense_or_is_refused() {
        let (factor, line, positions) = chains(400, 1.0e3, 0.0);
        let z = form(&factor, &line, Some(&positions), 1.0).expect("dense");
        assert!(z.band().is_none());
        let (factor, line, positions) = chains(3_000, 1.0e3, 0.0);
        match form(&factor, &line, Some(&positions), 1.0) {
            Err(error) => assert!(error.to_string().contains("does not decay"), "{error}"),
            Ok(z) => panic!("not refused: band {:?}", z.band()),
        }
    }
}
