//! The budget of the eigen solve, which needs the bridge's DOF count.

use crate::bridge::ModalBridge;
use crate::scenario::budget::{Budget, lanczos_vectors};
use crate::scenario::checker::Checker;
use crate::scene::Bridge;

/// Whether a beam's eigen solve for `modes` modes fits
/// `limits.eigen_work` (n m², the Lanczos basis's re-orthogonalisation,
/// m the vectors the solve needs: [`lanczos_vectors`]); a plate's Ritz
/// problem is bounded by `dofs` already. `path` is where the mode count
/// comes from.
pub(crate) fn eigen_fits(
    budget: &Budget,
    ck: &mut Checker<'_>,
    path: &str,
    bridge: &Bridge,
    modes: usize,
) -> bool {
    if matches!(bridge, Bridge::Plate(_)) {
        return true;
    }
    let dofs = ModalBridge::available_of(bridge) as f64;
    let vectors = lanczos_vectors(bridge, modes);
    let work = dofs * vectors.powi(2);
    if vectors <= modes as f64 {
        return budget.check(
            ck,
            path,
            "eigen_work",
            &format!("work of the eigen solve for {modes} modes of {dofs} DOFs (DOFs × modes²)"),
            work,
        );
    }
    // A many-span beam: the cost is set by its bands, not by the modes.
    let Bridge::Beam(beam) = bridge else {
        return true;
    };
    let spans = beam.spans.len() as f64;
    let families = if beam.sway.is_some() { 3.0 } else { 1.0 };
    // DOFs ≈ (DOFs per span) × spans and vectors ≈ families × spans, so
    // the work grows as spans³: the most spans that fit.
    let per_span = dofs / spans;
    let fitting = (budget.limit_of("eigen_work") / (per_span * families * families)).cbrt();
    budget.check_because(
        ck,
        "bridge.spans",
        "eigen_work",
        &format!(
            "work of the eigen solve for {modes} modes of {dofs} DOFs: {} spans put {} modes \
             in each frequency band (nearly equal frequencies), which the solver resolves \
             together, {} Lanczos vectors (DOFs × vectors²)",
            spans,
            spans * families,
            vectors
        ),
        work,
        &format!(
            "the solve's cost grows as the cube of the span count: at most {} spans of \
             this mesh fit",
            fitting.floor()
        ),
    )
}
