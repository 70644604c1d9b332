//! Penalty numbers on a matrix's diagonal: a support exported with penalty
//! constraints (OpenSees' `constraints Penalty 1e20 1e20`, a "big spring"
//! of other programs) keeps the fixed DOF with α added on its diagonal, in
//! K and, for a mass matrix assembled the same way, in M. Read as they are,
//! such a DOF is a spring of α carrying a mass of α: spurious modes at
//! √(α/α)/2π = 0.159 Hz, and a rail node on it free to move (its vertical
//! DOF is there, so the rail end is taken as free, not held). The check
//! refuses them, located at the entry, with what to export instead.

use super::{AssemblyError, Direction, Source};

/// A diagonal entry more than this many times both the largest other
/// entry of its row and the median diagonal of its kind (translations or
/// rotations) is a penalty number. A structural DOF's diagonal is the sum
/// of the element and spring stiffnesses (masses) that meet there, so its
/// row's off-diagonal entries are of its own order (a beam element's
/// 12EI/h³ against −12EI/h³; a consistent mass's 156 against 54) and a
/// DOF held by a spring to the ground alone is of the order of the model's
/// other diagonals; stiff links 10³–10⁴ times a model's members stay far
/// below. OpenSees' usual α = 1e20 against a girder's 1e9–1e12 is 10⁸ and
/// more.
pub const PENALTY_RATIO: f64 = 1e6;

/// Most DOFs named in the message.
const NAMED: usize = 5;

/// Refuses penalty numbers on the diagonal of `entries` (both triangles, on
/// the free DOFs `dofs`), at the entry's (line, column) of `source`'s file
/// (`places`, per free DOF).
pub(super) fn check(
    entries: &[(usize, usize, f64)],
    dofs: &[(u64, Direction)],
    places: &[Option<(usize, usize)>],
    source: Source,
) -> Result<(), AssemblyError> {
    let n = dofs.len();
    let (mut diagonal, mut off) = (vec![0.0f64; n], vec![0.0f64; n]);
    for &(r, c, v) in entries {
        if r == c {
            diagonal[r] += v;
        } else {
            off[r] = off[r].max(v.abs());
        }
    }
    let median = |rotation: bool| {
        let mut values: Vec<f64> = (0..n)
            .filter(|&i| dofs[i].1.is_rotation() == rotation)
            .map(|i| diagonal[i].abs())
            .collect();
        values.sort_unstable_by(f64::total_cmp);
        values.get(values.len() / 2).copied().unwrap_or(0.0)
    };
    let medians = [median(false), median(true)];
    let reference = |i: usize| off[i].max(medians[dofs[i].1.is_rotation() as usize]);
    let penalised: Vec<usize> = (0..n)
        .filter(|&i| diagonal[i] > PENALTY_RATIO * reference(i))
        .collect();
    // The first in the file (by line), else the first row.
    let Some(&first) = penalised
        .iter()
        .min_by_key(|&&i| places[i].unwrap_or((usize::MAX, usize::MAX)))
    else {
        return Ok(());
    };
    let name = |i: usize| format!("node {} {}", dofs[i].0, dofs[i].1.name());
    let what = if source == Source::Mass {
        "mass"
    } else {
        "stiffness"
    };
    let kind = if dofs[first].1.is_rotation() {
        "rotations"
    } else {
        "translations"
    };
    let mut named: Vec<String> = penalised.iter().take(NAMED).map(|&i| name(i)).collect();
    if penalised.len() > NAMED {
        named.push(format!("{} more", penalised.len() - NAMED));
    }
    let listed: Vec<String> = penalised
        .iter()
        .take(NAMED)
        .map(|&i| format!("{{node: {}, direction: {}}}", dofs[i].0, dofs[i].1.name()))
        .collect();
    let message = format!(
        "{} has a diagonal {what} {:e}, at least {:.1e} times both the largest other entry of its row \
         ({:e}) and the median diagonal {what} of the model's {kind} ({:e}): a penalty number, \
         not a {what} — a support exported with penalty constraints (OpenSees `constraints \
         Penalty`), which vbi would run as a DOF on a spring of that size with a mass of that \
         size (spurious modes, and a rail node on it as a free rail end). {} DOF{} of the {what} \
         matrix {} one: {}",
        name(first),
        diagonal[first],
        diagonal[first] / reference(first),
        off[first],
        medians[dofs[first].1.is_rotation() as usize],
        penalised.len(),
        if penalised.len() == 1 { "" } else { "s" },
        if penalised.len() == 1 { "has" } else { "have" },
        named.join(", ")
    );
    let help = format!(
        "export with `constraints Transformation` or `constraints Plain`, which drop the fixed \
         DOFs (a rail node without its vertical DOF is a support), or list the penalised DOFs \
         under `bridge.constrained` to remove them on import: `constrained: [{}]`",
        listed.join(", ")
    );
    Err(AssemblyError {
        source_input: source,
        place: places[first],
        message,
        help: Some(help),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chain of three springs k between four DOFs (translations).
    fn chain(k: f64) -> Vec<(usize, usize, f64)> {
        let mut out = Vec::new();
        for e in 0..3 {
            for (a, b, s) in [
                (e, e, 1.0),
                (e + 1, e + 1, 1.0),
                (e, e + 1, -1.0),
                (e + 1, e, -1.0),
            ] {
                out.push((a, b, s * k));
            }
        }
        out
    }

    fn dofs() -> Vec<(u64, Direction)> {
        (1..=4).map(|n| (n, Direction::Uz)).collect()
    }

    #[test]
    fn a_penalty_on_the_diagonal_is_refused_at_its_entry() {
        let mut k = chain(1e9);
        k.push((0, 0, 1e20));
        let places = vec![Some((4, 7)), None, None, None];
        let e = check(&k, &dofs(), &places, Source::Stiffness).unwrap_err();
        assert_eq!(e.place, Some((4, 7)));
        assert!(e.message.contains("node 1 uz") && e.message.contains("penalty"));
        assert!(e.help.unwrap().contains("{node: 1, direction: uz}"));
    }

    #[test]
    fn stiff_but_structural_diagonals_pass() {
        // A link 10⁴ times stiffer, a grounded spring, a lumped mass matrix.
        let mut k = chain(1e9);
        k.extend([(2, 2, 1e13), (3, 3, 1e13), (2, 3, -1e13), (3, 2, -1e13)]);
        k.push((0, 0, 5e9));
        check(&k, &dofs(), &[None; 4], Source::Stiffness).unwrap();
        let lumped: Vec<_> = (0..4).map(|i| (i, i, 1e3 * (i + 1) as f64)).collect();
        check(&lumped, &dofs(), &[None; 4], Source::Mass).unwrap();
        let mut lumped = lumped;
        lumped.push((3, 3, 1e20));
        assert!(check(&lumped, &dofs(), &[None; 4], Source::Mass).is_err());
    }
}
