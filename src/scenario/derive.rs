//! The parts of resolving that need the resolved vehicles but no physics:
//! the contact model (an elastic stiffness from a ratio, a Hertz coefficient
//! from a wheel radius), the solver method the contact needs, and studies
//! (oscillators from dimensionless groups need f₁: `plan::derive`).

use super::checker::Checker;
use super::raw;
use crate::scene::*;

/// Relative difference below which a given value agrees with a derived one.
const AGREEMENT: f64 = 1e-9;

/// The contact model; an elastic stiffness from a ratio to the suspension
/// stiffness, a Hertz coefficient from the wheel radius.
pub(crate) fn resolve_contact(
    raw: Option<&raw::ContactRaw>,
    vehicles: &[Vehicle],
    ck: &mut Checker<'_>,
) -> Contact {
    match raw {
        None | Some(raw::ContactRaw::Permanent) => Contact::Permanent,
        Some(raw::ContactRaw::Rigid { restitution }) => {
            let restitution = restitution.unwrap_or(0.0);
            if !(0.0..=1.0).contains(&restitution) {
                ck.error(
                    "contact.restitution",
                    format!(
                        "the coefficient of restitution must be between 0 and 1 \
                         (0: the wheel stays on the surface, 1: it bounces back with its \
                         approach speed), got {restitution}"
                    ),
                );
            }
            Contact::Rigid { restitution }
        }
        Some(raw::ContactRaw::Elastic {
            stiffness,
            stiffness_ratio,
        }) => {
            let Some(ratio) = stiffness_ratio else {
                let Some(k) = stiffness else {
                    ck.error(
                        "contact",
                        "elastic contact needs `stiffness` (N/m) or `stiffness_ratio`",
                    );
                    return Contact::Elastic {
                        stiffness: 0.0,
                        stiffness_ratio: None,
                    };
                };
                ck.positive("contact.stiffness", *k, "contact stiffness");
                return Contact::Elastic {
                    stiffness: *k,
                    stiffness_ratio: None,
                };
            };
            ck.positive("contact.stiffness_ratio", *ratio, "contact stiffness ratio");
            let suspension: Vec<f64> = vehicles
                .iter()
                .filter_map(|v| match v {
                    Vehicle::Oscillator(o) => Some(o.stiffness),
                    _ => None,
                })
                .collect();
            if suspension.is_empty()
                || suspension.len() != vehicles.len()
                || suspension.iter().any(|&k| k != suspension[0])
            {
                ck.error(
                    "contact.stiffness_ratio",
                    "`stiffness_ratio` needs every vehicle to be an oscillator with the same suspension stiffness; give `stiffness` in N/m instead",
                );
                return Contact::Elastic {
                    stiffness: 0.0,
                    stiffness_ratio: None,
                };
            }
            let derived = ratio * suspension[0];
            if let Some(k) = stiffness
                && (k - derived).abs() > AGREEMENT * derived.abs()
            {
                ck.error(
                    "contact.stiffness",
                    format!("stiffness {k} disagrees with stiffness_ratio × suspension stiffness = {derived}; give one or the other"),
                );
            }
            Contact::Elastic {
                stiffness: derived,
                stiffness_ratio: Some(*ratio),
            }
        }
        Some(raw::ContactRaw::Hertz {
            coefficient,
            wheel_radius,
            profile,
        }) => {
            let coefficient = match (coefficient, wheel_radius) {
                (Some(c), None) => {
                    ck.positive("contact.coefficient", *c, "Hertz coefficient");
                    if profile.is_some() {
                        ck.error(
                            "contact.profile",
                            "`profile` only applies with `wheel_radius`",
                        );
                    }
                    *c
                }
                (None, Some(r)) => {
                    ck.positive("contact.wheel_radius", *r, "wheel radius");
                    hertz_coefficient(*r, profile.unwrap_or(raw::TreadProfile::Worn))
                }
                (Some(_), Some(_)) => {
                    ck.error(
                        "contact.wheel_radius",
                        "give `coefficient` or `wheel_radius`, not both",
                    );
                    0.0
                }
                (None, None) => {
                    ck.error(
                        "contact",
                        "Hertz contact needs `coefficient` (N/m^1.5) or `wheel_radius` (m)",
                    );
                    0.0
                }
            };
            Contact::Hertz { coefficient }
        }
    }
}

/// Hertz coefficient C = G^-1.5 (N/m^1.5) of a wheel of rolling radius
/// `radius` (m) on a rail, from the contact constant G (m/N^(2/3)) of Zhai,
/// Vehicle–Track Coupled Dynamics (2020), §2.4.1: worn tread
/// G = 4.57e-8 R^-0.149, conical tread G = 3.86e-8 R^-0.115.
pub fn hertz_coefficient(radius: f64, profile: raw::TreadProfile) -> f64 {
    let g = match profile {
        raw::TreadProfile::Worn => 4.57e-8 * radius.powf(-0.149),
        raw::TreadProfile::Conical => 3.86e-8 * radius.powf(-0.115),
    };
    g.powf(-1.5)
}

/// The solution method: by default the one the contact model needs.
pub(crate) fn resolve_method(
    method: Option<SolverMethod>,
    contact: &Contact,
    ck: &mut Checker<'_>,
) -> SolverMethod {
    let needed = if contact.is_unilateral() {
        SolverMethod::Lcp
    } else {
        SolverMethod::Coupled
    };
    match method {
        None => needed,
        Some(m) if m == needed => m,
        Some(SolverMethod::Iterative) if !contact.is_unilateral() => SolverMethod::Iterative,
        Some(SolverMethod::Embs) if !contact.is_unilateral() => SolverMethod::Embs,
        Some(SolverMethod::Direct) if !contact.is_unilateral() => SolverMethod::Direct,
        Some(SolverMethod::Direct) => {
            ck.error(
                "solver.method",
                "`method: direct` keeps every wheel in permanent contact; unilateral contact \
                 (rigid, elastic, hertz) needs `method: lcp`",
            );
            needed
        }
        Some(SolverMethod::Embs) => {
            ck.error(
                "solver.method",
                "`method: embs` decouples permanent contact (the wheels follow the rails); \
                 unilateral contact (rigid, elastic, hertz) needs `method: lcp`",
            );
            needed
        }
        Some(SolverMethod::Coupled | SolverMethod::Iterative) => {
            ck.error(
                "solver.method",
                "`method: coupled` and `method: iterative` keep every wheel in permanent contact; unilateral contact (rigid, elastic, hertz) needs `method: lcp`",
            );
            needed
        }
        Some(SolverMethod::Lcp) => {
            ck.error(
                "solver.method",
                "`method: lcp` solves unilateral contact; with `contact: {type: permanent}` use `method: coupled` or `method: iterative`",
            );
            needed
        }
    }
}

/// EMBS settings: only for `method: embs`.
pub(crate) fn resolve_embs(
    solver: &raw::SolverRaw,
    method: SolverMethod,
    ck: &mut Checker<'_>,
) -> Option<EmbsOptions> {
    if method != SolverMethod::Embs {
        for (key, given) in [
            ("first_order", solver.first_order.is_some()),
            ("compare", solver.compare.is_some()),
            ("allow_large_epsilon", solver.allow_large_epsilon.is_some()),
        ] {
            if given {
                ck.error(
                    &format!("solver.{key}"),
                    format!("`{key}` applies to `method: embs` only"),
                );
            }
        }
        return None;
    }
    Some(EmbsOptions {
        first_order: solver.first_order.unwrap_or(true),
        compare: solver.compare.unwrap_or(false),
        allow_large_epsilon: solver.allow_large_epsilon.unwrap_or(false),
    })
}

/// Convergence settings: only for `method: iterative`.
pub(crate) fn resolve_iteration(
    solver: &raw::SolverRaw,
    method: SolverMethod,
    ck: &mut Checker<'_>,
) -> Option<Iteration> {
    if method != SolverMethod::Iterative {
        for (key, given) in [
            ("tolerance", solver.tolerance.is_some()),
            ("max_iterations", solver.max_iterations.is_some()),
        ] {
            if given {
                ck.error(
                    &format!("solver.{key}"),
                    format!("`{key}` applies to `method: iterative` only"),
                );
            }
        }
        return None;
    }
    let defaults = Iteration::default();
    let tolerance = solver.tolerance.unwrap_or(defaults.tolerance);
    if !(tolerance > 0.0 && tolerance < 1.0) {
        ck.error(
            "solver.tolerance",
            format!("the iteration tolerance must be in (0, 1), got {tolerance}"),
        );
    }
    let max_iterations = solver.max_iterations.unwrap_or(defaults.max_iterations);
    if !(1..=100_000).contains(&max_iterations) {
        ck.error(
            "solver.max_iterations",
            format!("`max_iterations` must be between 1 and 100000, got {max_iterations}"),
        );
    }
    Some(Iteration {
        tolerance,
        max_iterations,
    })
}

fn check_grid(ck: &mut Checker<'_>, path: &str, grid: &crate::scene::Grid) {
    ck.positive(&format!("{path}.from"), grid.from, "a grid start");
    ck.positive(&format!("{path}.to"), grid.to, "a grid end");
    if grid.to < grid.from {
        ck.error(
            &format!("{path}.to"),
            format!("`to` ({}) is below `from` ({})", grid.to, grid.from),
        );
    }
    if !(1..=500).contains(&grid.count) {
        ck.error(
            &format!("{path}.count"),
            format!("a grid needs 1 to 500 values, got {}", grid.count),
        );
    }
}

/// A study and its requirements on the scene. `first_frequency` is the
/// bridge's f₁ (Hz), `default_filter` the planning stage's deck-acceleration
/// cut-off (Hz) for a study that gives none.
#[allow(clippy::too_many_arguments)]
pub(crate) fn resolve_study(
    raw: Option<&raw::StudyRaw>,
    bridge: &Bridge,
    vehicles: &[Vehicle],
    contact: &Contact,
    surface: &Surface,
    first_frequency: f64,
    default_filter: f64,
    ck: &mut Checker<'_>,
) -> Option<Study> {
    match raw? {
        raw::StudyRaw::ResonanceCheck(check) => Some(Study::ResonanceCheck(
            super::resonance::resolve_resonance(check, bridge, first_frequency, default_filter, ck),
        )),
        raw::StudyRaw::SpeedSweep(sweep) => Some(Study::SpeedSweep(super::sweep::resolve(
            sweep, bridge, surface, ck,
        ))),
        raw::StudyRaw::MonteCarlo(mc) => Some(Study::MonteCarlo(
            super::sweep::resolve_monte_carlo(mc, surface, ck),
        )),
        raw::StudyRaw::SeparationMap(map) => {
            check_grid(ck, "study.velocity_ratio", &map.velocity_ratio);
            check_grid(ck, "study.mass_ratio", &map.mass_ratio);
            let dimensionless_oscillator = matches!(
                vehicles,
                [Vehicle::Oscillator(Oscillator {
                    dimensionless: Some(_),
                    ..
                })]
            );
            if !dimensionless_oscillator {
                ck.error(
                    "vehicles",
                    "a separation map needs exactly one vehicle: an oscillator given with `dimensionless`",
                );
            }
            if !contact.is_unilateral() {
                ck.error(
                    "study",
                    "a separation map needs unilateral contact: `contact: {type: rigid}`, `elastic` or `hertz`",
                );
            }
            Some(Study::SeparationMap {
                velocity_ratio: map.velocity_ratio.clone(),
                mass_ratio: map.mass_ratio.clone(),
            })
        }
    }
}
