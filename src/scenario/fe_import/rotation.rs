//! The sign convention of an imported model's slope rotations, told from its
//! stiffness along the rails.
//!
//! This program reads ry as a right-handed rotation about +y, so the
//! vertical slope is ∂w/∂x = −ry, and rz as one about +z, ∂v/∂x = +rz
//! (`crate::bridge::fe_import::track`). A 2D textbook beam writes θ = +∂w/∂x instead; labelled
//! ry, its Hermite interpolation then bends every element the wrong way
//! (issue 22: the same beam's deck acceleration 2.3 times too large), while
//! modes and static deflections barely change. The files do not say which
//! convention they use, but the stiffness does.
//!
//! **Criterion.** Take two consecutive rail nodes i, j (h = xⱼ − xᵢ > 0),
//! with translation u (uz or uy) and rotation r (ry or rz). A rigid rotation
//! of the segment by φ about its middle is u = ∓φh/2 at i, j and r = σφ at
//! both, where σ = +1 if the file's rotation is the slope +∂u/∂x and −1 if it
//! is −∂u/∂x. A two-node element that strains nothing under rigid
//! translation and rigid rotation and is mirror-symmetric (any prismatic
//! Euler–Bernoulli or Timoshenko element) satisfies, from the rows of uᵢ and
//! uⱼ of K·(rigid rotation) = 0 and K·(rigid translation) = 0:
//!
//! ```text
//! K[uⱼ, rᵢ] − K[uᵢ, rⱼ] = σ · h · K[uᵢ, uⱼ]
//! ```
//!
//! (the textbook element, θ = +∂w/∂x: −6EI/h² − 6EI/h² = (+1)·h·(−12EI/h³);
//! a Timoshenko element divides all three by 1 + Φ). These
//! are the terms coupling node i to node j, which only the elements joining
//! the two nodes contribute: springs to sleepers or piers, neighbouring
//! elements of other lengths and the rest of the model do not enter. So
//! σ̂ = (K[uⱼ, rᵢ] − K[uᵢ, rⱼ]) / (h K[uᵢ, uⱼ]) is ±1 on every segment a beam
//! element spans, and the sign of the rotation is read off it.
//!
//! **Margin.** A segment votes when |σ̂| ≥ [`VOTE_THRESHOLD`], half a beam
//! element's exact 1 (measured: ±1.000 on every free segment of an exported
//! beam and of a generated viaduct's rails, both planes; a spring joining
//! the two nodes' translations only adds to K[uᵢ, uⱼ], shrinking |σ̂|
//! without changing its sign); segments with K[uᵢ, uⱼ] = 0 (nodes not joined
//! by an element) or a fixed DOF do not vote. A rail whose
//! segments vote against the declared convention is refused, with the
//! count and the first such segment.

use std::collections::HashMap;

use super::{AssemblyError, Source, fail};
use crate::scene::imported::RailDofs;
use crate::scene::imported::{Direction, RotationSign};

/// |σ̂| from which a rail segment counts as evidence: half the exact ±1 of
/// a mirror-symmetric beam element.
pub const VOTE_THRESHOLD: f64 = 0.5;

/// The evidence of one rail and one plane (vertical: uz with ry; lateral:
/// uy with rz).
#[derive(Debug, Clone, PartialEq)]
pub struct Evidence {
    /// Segments whose σ̂ says the rotation is the slope (σ = +1).
    pub slope: usize,
    /// Segments whose σ̂ says the rotation is minus the slope (σ = −1).
    pub minus_slope: usize,
    /// Segments that cannot tell (|σ̂| below the threshold, not joined, or fixed).
    pub silent: usize,
    /// The first segment of each vote: (node i, node j, σ̂).
    pub first_slope: Option<(u64, u64, f64)>,
    /// The first segment voting σ = −1.
    pub first_minus_slope: Option<(u64, u64, f64)>,
}

impl Evidence {
    /// The segments voting for σ = `sigma` (±1) and their first.
    pub fn votes(&self, sigma: f64) -> (usize, Option<(u64, u64, f64)>) {
        if sigma > 0.0 {
            (self.slope, self.first_slope)
        } else {
            (self.minus_slope, self.first_minus_slope)
        }
    }
}

/// The rotation paired with `plane`'s displacement: ry for the vertical
/// (index 0), rz for the lateral (1).
pub fn rotation_of(plane: usize) -> Direction {
    [Direction::Ry, Direction::Rz][plane]
}

/// σ of this program's convention in `plane`: ∂w/∂x = −ry, ∂v/∂x = +rz.
pub fn program_sigma(plane: usize) -> f64 {
    [-1.0, 1.0][plane]
}

/// The votes of `rail`'s segments in `plane` (0 vertical, 1 lateral), from
/// the stiffness `k` (both triangles, free DOFs).
pub fn rail_evidence(k: &[(usize, usize, f64)], rail: &RailDofs, plane: usize) -> Evidence {
    let (u, r) = (&rail.displacement[plane], &rail.rotation[plane]);
    // The rail's free DOFs (a mask over the DOFs: K has millions of
    // entries, each looked at twice), and the entries of K among them.
    let dofs = u.iter().chain(r.iter()).flatten();
    let mut on_rail = vec![false; dofs.clone().max().map_or(0, |&d| d + 1)];
    for &dof in dofs {
        on_rail[dof] = true;
    }
    let on = |d: usize| on_rail.get(d).copied().unwrap_or(false);
    let mut entries: HashMap<(usize, usize), f64> = HashMap::new();
    for &(a, b, v) in k {
        if on(a) && on(b) {
            *entries.entry((a, b)).or_insert(0.0) += v;
        }
    }
    let at = |a: usize, b: usize| entries.get(&(a, b)).copied().unwrap_or(0.0);
    let mut evidence = Evidence {
        slope: 0,
        minus_slope: 0,
        silent: 0,
        first_slope: None,
        first_minus_slope: None,
    };
    for i in 0..rail.x.len().saturating_sub(1) {
        let j = i + 1;
        let h = rail.x[j] - rail.x[i];
        let (Some(ui), Some(uj), Some(ri), Some(rj)) = (u[i], u[j], r[i], r[j]) else {
            evidence.silent += 1;
            continue;
        };
        let translation = at(ui, uj);
        let sigma = (at(uj, ri) - at(ui, rj)) / (h * translation);
        let segment = (rail.nodes[i], rail.nodes[j], sigma);
        if !sigma.is_finite() || sigma.abs() < VOTE_THRESHOLD {
            evidence.silent += 1;
        } else if sigma > 0.0 {
            evidence.slope += 1;
            evidence.first_slope.get_or_insert(segment);
        } else {
            evidence.minus_slope += 1;
            evidence.first_minus_slope.get_or_insert(segment);
        }
    }
    evidence
}

/// Refuses a rail whose stiffness says its slope rotations in `plane`
/// have the other sign than the one `declared` (`k` as read, after the
/// declared signs are applied), and a rail whose stiffness cannot tell
/// (no segment votes: its nodes are not joined by elements, or every
/// segment has a fixed DOF) unless the scene wrote `rotation_sign`
/// (`written`): its Hermite interpolation would rest on an unverified sign.
pub(super) fn check(
    k: &[(usize, usize, f64)],
    rail: &RailDofs,
    plane: usize,
    declared: RotationSign,
    written: bool,
) -> Result<(), AssemblyError> {
    let evidence = rail_evidence(k, rail, plane);
    let program = program_sigma(plane);
    let (against, first) = evidence.votes(-program);
    if evidence.slope + evidence.minus_slope == 0 && !written {
        return refuse_silent(rail, plane, &evidence);
    }
    let Some((i, j, sigma_hat)) = first else {
        return Ok(());
    };
    let (u, r) = (["uz", "uy"][plane], rotation_of(plane));
    let (w, axis) = (["w", "v"][plane], ["y", "z"][plane]);
    let sign = declared.of(r);
    // Relations between the slope and the file's rotation.
    let relation = |sigma: i64| {
        let s = if sigma > 0 { '+' } else { '−' };
        format!("∂{w}/∂x = {s}{}", r.name())
    };
    let program = program as i64;
    // As read, the evidence says σ = −program; in the file's terms that is
    // −program·sign, while the scene assumes program·sign.
    let found = relation(-program * sign);
    let assumed = relation(program * sign);
    let textbook = if plane == 0 && -program * sign > 0 {
        " (a textbook beam's θ)"
    } else {
        ""
    };
    let how = if sign == 1 {
        format!(
            "the default: {} a right-handed rotation about +{axis}",
            r.name()
        )
    } else {
        format!("with `rotation_sign: {{{}: -1}}`", r.name())
    };
    let segments = evidence.slope + evidence.minus_slope + evidence.silent;
    let (agree, _) = evidence.votes(program as f64);
    let fix = if agree == 0 {
        let with = if sign == 1 {
            format!(
                "declare `rotation_sign: {{{}: -1}}` under `bridge`",
                r.name()
            )
        } else {
            "remove `rotation_sign`".to_string()
        };
        format!(
            "{with} (vbi then reads the file's {r} as {}{r}), or flip the sign of every K, M and C \
             entry with exactly one {r} index",
            if sign == 1 { "−" } else { "+" },
            r = r.name()
        )
    } else {
        format!(
            "{agree} other segments agree with {assumed}: the model mixes the two conventions; \
             write it with one"
        )
    };
    fail(
        Source::RotationSign(r),
        format!(
            "rail `{name}`: the stiffness says {found}{textbook} on {against} of its {segments} \
             segments, but the scene reads {assumed} ({how}). Evidence: between nodes {i} and {j}, \
             (K[{u}ⱼ,{r}ᵢ] − K[{u}ᵢ,{r}ⱼ]) / (h·K[{u}ᵢ,{u}ⱼ]) = {sigma_hat:+.3} as read, where a beam \
             element joining them gives exactly {exact} (a rigid rotation of the segment strains \
             it only with the wrong sign). Fix: {fix}",
            name = rail.name,
            r = r.name(),
            exact = if program > 0 { "+1" } else { "−1" },
        ),
    )
}

/// Refuses a rail with slope rotations in `plane` none of whose segments
/// can tell their sign (see [`check`]).
fn refuse_silent(rail: &RailDofs, plane: usize, evidence: &Evidence) -> Result<(), AssemblyError> {
    let (u, r) = (["uz", "uy"][plane], rotation_of(plane).name());
    let relation = ["∂w/∂x = −ry", "∂v/∂x = +rz"][plane];
    fail(
        Source::RotationSign(rotation_of(plane)),
        format!(
            "rail `{name}`: the sign convention of its {r} rotations cannot be checked: none of \
             its {segments} segments is spanned by an element (K[{u}ᵢ,{u}ⱼ] between consecutive rail \
             nodes is 0, or a DOF of the segment is fixed), so the stiffness gives no evidence, \
             and the wheels' Hermite interpolation between the nodes uses {r} as the slope. \
             List the rail's nodes as its elements join them (every node of the beam that models \
             the rail), or confirm the convention by writing it under `bridge`: \
             `rotation_sign: {{{r}: 1}}` when the file's {r} is this program's ({relation}), \
             `{{{r}: -1}}` when it is the opposite",
            name = rail.name,
            segments = evidence.silent,
        ),
    )
}
