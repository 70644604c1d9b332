//! Stopping a run from outside (`vbi::solve::cancel`, used by the Python
//! package for Ctrl-C): a run under a cancelled token stops at its next
//! progress report with `SolveError::Cancelled`, a scene and a study alike;
//! without a token nothing changes (every other test).

use std::sync::atomic::{AtomicUsize, Ordering};

use vbi::execute::execute;
use vbi::run::RunError;
use vbi::solve::SolveError;
use vbi::solve::cancel::CancelToken;

/// The Yang & Yau beam under a moving force, 0.9 s at Δt = 1e-5 s
/// (90,000 steps), optionally as a speed sweep.
fn scene(study: &str) -> vbi::plan::Loaded {
    let yaml = format!(
        "name: cancel
bridge: {{type: beam, spans: [25.0], bending_stiffness: 8.323e9, mass_per_length: 2303.0,
         modes: {{count: 4}}, damping: {{type: modal, ratio: 0.02}}}}
vehicles: [{{type: moving_force, loads: [100.0e3], speed: 27.7778}}]
solver: {{time_step: 1.0e-5}}
record: [{{name: midspan, quantity: bridge_displacement, x: 12.5}}]
{study}"
    );
    vbi::plan::load_str(&yaml, "cancel.yaml").expect("valid scene")
}

fn cancelled(result: &Result<vbi::execute::Results, RunError>) -> bool {
    matches!(result, Err(RunError::Solve(SolveError::Cancelled)))
}

#[test]
fn a_scene_stops_at_the_first_report_after_cancel() {
    let token = CancelToken::new();
    let furthest = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    let result = token.scope(|| {
        execute(scene(""), &|done, steps| {
            furthest.fetch_max(done, Ordering::Relaxed);
            total.store(steps, Ordering::Relaxed);
            if done > 0 {
                token.cancel();
            }
        })
    });
    assert!(cancelled(&result), "{:?}", result.err());
    // It stopped at the first report after step 0, far before the end.
    let (furthest, total) = (furthest.into_inner(), total.into_inner());
    assert!(total >= 90_000, "{total} steps");
    assert!(furthest < total / 10, "ran to step {furthest} of {total}");
}

#[test]
fn a_study_stops_under_a_cancelled_token() {
    let token = CancelToken::new();
    token.cancel();
    let points = AtomicUsize::new(0);
    let result = token.scope(|| {
        execute(
            scene("study: {type: speed_sweep, speeds: {from: 10.0, to: 40.0, count: 4}}\n"),
            &|_, _| {
                points.fetch_add(1, Ordering::Relaxed);
            },
        )
    });
    assert!(cancelled(&result), "{:?}", result.err());
}

#[test]
fn without_a_token_a_cancelled_one_elsewhere_changes_nothing() {
    let token = CancelToken::new();
    token.cancel();
    // The token is not installed on this thread: the run completes.
    let result = execute(scene(""), &|_, _| {});
    assert!(result.is_ok(), "{:?}", result.err());
}
