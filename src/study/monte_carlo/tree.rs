//! One case's samples: run in batches (stepped together when the scene
//! allows it) and reduced over the fixed binary tree of their indices (see
//! the module documentation of [`super`]).

use std::ops::Range;

use super::{Case, Moments, SampleResult, WheelOutcome, sample_scenario, sample_seed};
use crate::bridge::ModalBridge;
use crate::model::Model;
use crate::record::{Recorder, SharedStatics};
use crate::run::RunError;
use crate::scenario::sweep;
use crate::scene::{MonteCarlo, Scenario};
use crate::solve;

/// Runs `flats` (consecutive runs of one case, at most
/// [`solve::lockstep::LANES`]) stepped together when the scene allows it
/// ([`solve::lockstep::eligible`]), else one by one; bit-identical either
/// way (see [`solve::lockstep`]). The results come back in order.
pub(super) fn run_batch(
    base: &Scenario,
    bridge: &ModalBridge,
    mc: &MonteCarlo,
    cases: &[Case],
    flats: Range<usize>,
) -> Result<Vec<(Moments, SampleResult)>, RunError> {
    let mut scenarios = Vec::with_capacity(flats.len());
    let mut models = Vec::with_capacity(flats.len());
    for flat in flats.clone() {
        let (case, index) = (flat / mc.samples, flat % mc.samples);
        let scenario = sample_scenario(base, bridge, mc, cases[case], index);
        models.push(Model::build(&scenario, bridge.clone())?);
        scenarios.push(scenario);
    }
    let first = &models[0];
    let together = models.len() > 1
        && solve::lockstep::eligible(first)
        && models.iter().all(|m| {
            m.steps == first.steps
                && m.time_step == first.time_step
                && m.wheels.len() == first.wheels.len()
                && m.vehicles.len() == first.vehicles.len()
        });
    let mut recorders = Vec::with_capacity(models.len());
    // The batch's recorders share what does not depend on a sample's state.
    let shared = std::rc::Rc::new(std::cell::RefCell::new(SharedStatics::default()));
    for (model, scenario) in models.iter().zip(&scenarios) {
        // A sample's summary is not written: no girder DAFs to track.
        let recorder = Recorder::new(model, &scenario.record)
            .map_err(crate::model::BuildError::from)?
            .without_girder_dafs();
        recorders.push(if together {
            recorder.sharing_statics(shared.clone())
        } else {
            recorder
        });
    }
    if together {
        let refs: Vec<&Model> = models.iter().collect();
        let mut observers: Vec<&mut dyn solve::Observer> = recorders
            .iter_mut()
            .map(|r| r as &mut dyn solve::Observer)
            .collect();
        solve::lockstep::run(&refs, &mut observers)
            .map_err(|(lane, e)| failed_sample(base, mc, cases, flats.start + lane, e.into()))?;
    } else {
        for ((model, recorder), flat) in models.iter().zip(recorders.iter_mut()).zip(flats.clone())
        {
            solve::run(model, recorder, &mut |_, _| {})
                .map_err(|e| failed_sample(base, mc, cases, flat, e.into()))?;
        }
    }
    Ok(recorders
        .into_iter()
        .zip(models.iter().zip(&scenarios))
        .zip(flats)
        .map(|((recorder, (model, scenario)), flat)| {
            let history = recorder.finish();
            let advice = super::super::point_advice(scenario, model, &history);
            outcome(history, advice, mc, flat / mc.samples, flat % mc.samples)
        })
        .collect())
}

/// Run `flat`'s failure `error`, said with its sample, its case and, for
/// the first case, how to run it alone (`--sample`).
pub(super) fn failed_sample(
    base: &Scenario,
    mc: &MonteCarlo,
    cases: &[Case],
    flat: usize,
    error: RunError,
) -> RunError {
    let (case, index) = (flat / mc.samples, flat % mc.samples);
    let mut label = sweep::label(&base.surface, cases[case].entry);
    if let Some(speed) = cases[case].speed {
        label += &format!(", {:.1} km/h", crate::report::km_h(speed));
    }
    RunError::Sample {
        sample: index + 1,
        case: label,
        rerun: if case == 0 {
            format!(" (run it alone with `vbi run FILE --sample {}`)", index + 1)
        } else {
            String::new()
        },
        source: Box::new(error),
    }
}

/// One finished sample's moments (count 1) and scalar results.
pub(super) fn outcome(
    history: crate::record::History,
    advice: Vec<crate::advice::Advice>,
    mc: &MonteCarlo,
    case: usize,
    index: usize,
) -> (Moments, SampleResult) {
    let wheels = history
        .separation
        .iter()
        .map(|w| WheelOutcome {
            vehicle: w.vehicle,
            wheel: w.wheel,
            separated: w.separated,
            max_gap: w.max_gap,
        })
        .collect();
    let values: Vec<Vec<f64>> = history.columns.iter().map(|c| c.values.clone()).collect();
    let moments = Moments {
        count: 1,
        time: history.time.clone(),
        names: history.columns.iter().map(|c| c.name.clone()).collect(),
        units: history.columns.iter().map(|c| c.unit.to_string()).collect(),
        m2: values.iter().map(|v| vec![0.0; v.len()]).collect(),
        mean: values.clone(),
    };
    // Only the first case is plotted: other cases keep no histories.
    let histories = (case == 0 && index < mc.show).then_some(values);
    let seed = sample_seed(mc.seed, index);
    (
        moments,
        SampleResult {
            case,
            sample: index + 1,
            seed,
            wheels,
            histories,
            advice,
        },
    )
}

pub(super) type Reduced = (Moments, Vec<SampleResult>);

/// Reduces samples [lo, hi) of `case` over the fixed tree, halves in
/// parallel; a node of at most `width` samples runs as one batch and is
/// reduced over the same tree. The samples come back in index order.
pub(super) fn reduce(
    lo: usize,
    hi: usize,
    width: usize,
    batch: &(dyn Fn(Range<usize>) -> Result<Vec<(Moments, SampleResult)>, RunError> + Sync),
) -> Result<Reduced, RunError> {
    if hi - lo <= width {
        let mut leaves = batch(lo..hi)?.into_iter();
        return Ok(reduce_leaves(lo, hi, &mut leaves));
    }
    let mid = lo + (hi - lo) / 2;
    let (a, b) = rayon::join(
        || reduce(lo, mid, width, batch),
        || reduce(mid, hi, width, batch),
    );
    let ((ma, mut sa), (mb, sb)) = (a?, b?);
    sa.extend(sb);
    Ok((Moments::combine(ma, &mb), sa))
}

/// The tree of [lo, hi) over its leaves, given in index order.
pub(super) fn reduce_leaves(
    lo: usize,
    hi: usize,
    leaves: &mut impl Iterator<Item = (Moments, SampleResult)>,
) -> Reduced {
    if hi - lo == 1 {
        let (m, s) = leaves.next().expect("one leaf per sample of the batch");
        return (m, vec![s]);
    }
    let mid = lo + (hi - lo) / 2;
    let (ma, mut sa) = reduce_leaves(lo, mid, leaves);
    let (mb, sb) = reduce_leaves(mid, hi, leaves);
    sa.extend(sb);
    (Moments::combine(ma, &mb), sa)
}

/// The largest whole tree nodes of [lo, hi) inside [a, b), in order.
pub(super) fn cover(lo: usize, hi: usize, a: usize, b: usize, out: &mut Vec<(usize, usize)>) {
    if hi <= a || b <= lo || lo >= hi {
        return;
    }
    if a <= lo && hi <= b {
        out.push((lo, hi));
        return;
    }
    let mid = lo + (hi - lo) / 2;
    cover(lo, mid, a, b, out);
    cover(mid, hi, a, b, out);
}
