//! `vbi merge`: the parts checked and folded one at a time (issue 27), so
//! the memory is one part plus the merged result whatever the shard count.
//!
//! Two passes over the part files. The first reads each part without its
//! results ([`read_stamp`]: the JSON is checked, the results skipped) and
//! makes every check on what the parts claim: all of one scene and one
//! split, the scene loaded again under the caller's budgets and its hash
//! compared, the shard count budgeted, every slice the right one, none
//! twice, none missing. The second reads the parts again in shard order,
//! checks that each still says what it said in the first pass (a file that
//! changed in between is refused), checks its results against its slice
//! and folds them in: points appended, a Monte Carlo part's reduced nodes
//! combined as they come ([`EnvelopeFold`]), which gives the unsharded
//! run's envelopes bit for bit.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::de::IgnoredAny;

use super::super::part_file::{read_part, read_stamp};
use super::{
    Part, PartData, Shard, ShardError, check_count, rerun_command, scenario_hash, study_size,
};
use crate::plan::Loaded;
use crate::scenario::{self, LoadOptions};
use crate::scene::{MonteCarlo, Study};
use crate::study::Results;
use crate::study::monte_carlo::EnvelopeFold;
use crate::study::resonance::{self, ResonancePoint};
use crate::study::separation_map::{self, MapPoint};
use crate::study::speed_sweep::{self, SweepPoint};

/// The merged study and the scene it belongs to.
#[derive(Debug)]
pub struct Merged {
    /// The scenario file as the parts name it (as given to `vbi run`).
    pub scenario_file: String,
    /// The scene, loaded again from the parts' scenario text.
    pub loaded: Loaded,
    /// The study's results, as an unsharded run gives them.
    pub results: Results,
}

/// What the first pass keeps of a part besides the first part's stamp:
/// where it is and what it claimed that may differ from the first part.
struct Slot {
    path: PathBuf,
    shard: usize,
    first: usize,
    end: usize,
    wall_time: f64,
    vbi_version: String,
    data_digest: String,
}

/// Checks that the parts at `paths` are the N distinct shards of one study
/// and assembles them. Nothing in a part is trusted beyond what is derived
/// again: the scene is loaded from the parts' text under the caller's
/// `options` (its budgets, its `--allow-large`, its data folders; the
/// scene's own files are confined to the current folder's tree, since the
/// part's file name is not trusted to say which folder may be read), its
/// hash is compared first, then the shard count is budgeted against the
/// study's run count, and only then are the results read and folded, one
/// part at a time.
pub fn merge(paths: &[PathBuf], options: &LoadOptions) -> Result<Merged, ShardError> {
    // Pass 1: every part's stamp; only the first one's is kept whole.
    let shown = |p: &Path| p.display().to_string();
    let mut first: Option<(PathBuf, Part<IgnoredAny>)> = None;
    let mut unusable = None;
    let mut mismatch = None;
    let mut slots: Vec<Slot> = Vec::with_capacity(paths.len());
    for path in paths {
        let part = match read_stamp(path, options.allow_large) {
            Ok(part) => part,
            Err(e) => {
                unusable.get_or_insert((path.clone(), e));
                continue;
            }
        };
        if let Some((first_path, first)) = &first
            && mismatch.is_none()
        {
            if part.scenario_hash != first.scenario_hash
                || part.scenario_source != first.scenario_source
                || part.scenario_file != first.scenario_file
            {
                mismatch = Some(ShardError::Mismatch(format!(
                    "{} is from another scenario than {}",
                    shown(path),
                    shown(first_path),
                )));
            } else if part.shards != first.shards
                || part.size != first.size
                || part.study != first.study
                || part.allow_large != first.allow_large
                || part.trust_limits != first.trust_limits
            {
                mismatch = Some(ShardError::Mismatch(format!(
                    "{} and {} are parts of different splits of the study (shard counts, run \
                     counts, study types or `--allow-large` differ)",
                    shown(path),
                    shown(first_path),
                )));
            }
        }
        slots.push(Slot {
            path: path.clone(),
            shard: part.shard,
            first: part.first,
            end: part.end,
            wall_time: part.wall_time,
            vbi_version: part.vbi_version.clone(),
            data_digest: part.data_digest.clone(),
        });
        first.get_or_insert((path.clone(), part));
    }
    // A part that cannot be read is named with its shard (from its file
    // name, the only thing left to trust) and the command that writes it
    // again; the scene's file is taken from a part that did read.
    if let Some((path, error)) = unusable {
        let scene = first.as_ref().map(|(_, p)| p.scenario_file.as_str());
        return Err(unusable_error(&path, error, scene));
    }
    let Some((first_path, first)) = first else {
        return Err(ShardError::Mismatch("no part files given".into()));
    };
    if let Some(e) = mismatch {
        return Err(e);
    }
    // A part run with `--allow-large` needs the user's own to merge: the
    // flag in the file is not trusted to lift the budgets.
    if first.allow_large && !options.allow_large {
        return Err(ShardError::Mismatch(format!(
            "{} was run with `--allow-large`; merge with `--allow-large` too",
            shown(&first_path)
        )));
    }
    // Likewise a part run with `--trust-limits`: the file's own raised
    // limits apply only where the merging user allows them too.
    if first.trust_limits && !options.trust_limits {
        return Err(ShardError::Mismatch(format!(
            "{} was run with `--trust-limits`; merge with `--trust-limits` too",
            shown(&first_path)
        )));
    }
    // The scene hash first: the scene is loaded again under the caller's
    // budgets, and its hash must be the parts' before any count in them is
    // believed.
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    let options = LoadOptions {
        modes_cache: None,
        data: scenario::DataAccess {
            data_dirs: options.data.data_dirs.clone(),
            confine_to: Some(cwd),
        },
        ..options.clone()
    };
    let allow_large = options.allow_large;
    let first_file = first.scenario_file.clone();
    let loaded = crate::plan::load_str_with(&first.scenario_source, &first.scenario_file, options)?;
    let hash = scenario_hash(&loaded);
    if hash != first.scenario_hash {
        return Err(ShardError::Mismatch(format!(
            "the parts' scenario resolves differently with this vbi {} (hash {hash}); their hash \
             does not match: merge with the vbi that ran them, or the parts were altered",
            env!("CARGO_PKG_VERSION"),
        )));
    }
    let study = loaded
        .scenario
        .study
        .clone()
        .ok_or_else(|| ShardError::NoStudy {
            file: first.scenario_file.clone(),
        })?;
    // Then the counts, against the study as derived again.
    let (name, size) = study_size(&loaded, &study);
    let count = first.shards;
    if first.study != name || first.size != size {
        return Err(ShardError::Mismatch(format!(
            "{} claims a {}-run study, the scene's study has {size} runs",
            shown(&first_path),
            first.size
        )));
    }
    check_count(count, size, &loaded, allow_large)
        .map_err(|e| ShardError::Mismatch(format!("{}: {e}", shown(&first_path))))?;
    let mut by_index: BTreeMap<usize, Slot> = BTreeMap::new();
    for slot in slots {
        let index = slot.shard;
        let shard = Shard { index, count };
        if index == 0 || index > count || shard.range(size) != (slot.first..slot.end) {
            return Err(ShardError::Mismatch(format!(
                "{}: not a shard of {count} of this study (shard {index}, runs {}..{})",
                shown(&slot.path),
                slot.first,
                slot.end
            )));
        }
        if let Some(other) = by_index.get(&index) {
            return Err(ShardError::Mismatch(format!(
                "shard {index} of {count} is given twice: {} and {}",
                shown(&other.path),
                shown(&slot.path)
            )));
        }
        by_index.insert(index, slot);
    }
    if by_index.len() < count {
        return Err(missing_error(
            &by_index,
            count,
            size,
            &first_file,
            &paths[0],
        ));
    }
    // The wall time in shard order, as the batch merge summed it.
    let wall_time: f64 = by_index
        .values()
        .map(|s| s.wall_time)
        .filter(|t| t.is_finite() && *t >= 0.0)
        .sum();

    // Pass 2: each part read again whole, in shard order, and folded in.
    let rerun = |index: usize| rerun_command(Some(&first_file), Shard { index, count }, &paths[0]);
    let mut fold = Fold::new(&loaded, &study);
    for slot in by_index.values() {
        let part = read_part(&slot.path, allow_large)
            .map_err(|e| unusable_error(&slot.path, e, Some(&first_file)))?;
        let claimed = Part {
            shard: slot.shard,
            first: slot.first,
            end: slot.end,
            wall_time: slot.wall_time,
            vbi_version: slot.vbi_version.clone(),
            data_digest: slot.data_digest.clone(),
            ..first.clone()
        };
        if super::data_digest(&part.data) != part.data_digest {
            return Err(ShardError::Mismatch(format!(
                "{}'s results do not match their digest (the file was damaged or edited after \
                 its run); run shard {} again: `{}`",
                shown(&slot.path),
                slot.shard,
                rerun(slot.shard)
            )));
        }
        if !part.same_stamp(&claimed) {
            return Err(ShardError::Mismatch(format!(
                "{} changed while it was being merged (it no longer says what it said when first \
                 read); merge again once nothing writes it",
                shown(&slot.path)
            )));
        }
        fold.push(part, count, &rerun)?;
    }
    let results = fold.finish(&loaded, &study, wall_time)?;
    Ok(Merged {
        scenario_file: first_file,
        loaded,
        results,
    })
}

/// An unreadable part, named with its shard (from its file name) and the
/// command that writes it again, when its name gives the shard.
fn unusable_error(path: &Path, error: ShardError, scene: Option<&str>) -> ShardError {
    let Some(shard) = Shard::from_file_name(path) else {
        return error;
    };
    ShardError::Unusable {
        error: Box::new(error),
        shard: shard.index,
        count: shard.count,
        command: rerun_command(scene, shard, path),
    }
}

/// The shards missing from `by_index`: at most a few named (the count is
/// budgeted, so the scan is bounded by the study's run count) and the
/// command that runs the first of them.
fn missing_error(
    by_index: &BTreeMap<usize, Slot>,
    count: usize,
    size: usize,
    scene: &str,
    part: &Path,
) -> ShardError {
    const NAMED: usize = 8;
    let missing = count - by_index.len();
    let named: Vec<String> = (1..=count)
        .filter(|k| !by_index.contains_key(k))
        .take(NAMED)
        .map(|k| {
            let r = Shard { index: k, count }.range(size);
            format!("{k} (runs {}..{})", r.start, r.end)
        })
        .collect();
    let more = if missing > NAMED {
        format!(" and {} more", missing - NAMED)
    } else {
        String::new()
    };
    let first_missing = (1..=count).find(|k| !by_index.contains_key(k)).unwrap_or(1);
    let command = rerun_command(
        Some(scene),
        Shard {
            index: first_missing,
            count,
        },
        part,
    );
    ShardError::Mismatch(format!(
        "{missing} of {count} shards missing: {}{more}; run each again, e.g. shard \
         {first_missing}: `{command}`",
        named.join(", ")
    ))
}

fn short(shard: usize, got: usize, want: usize, command: String) -> ShardError {
    ShardError::Mismatch(format!(
        "shard {shard} holds {got} points of another shape or count than the {want} of its slice; \
         run it again: `{command}`"
    ))
}

/// The shape every speed-sweep point must have: its DAF and force columns,
/// a surface of the sweep.
struct SweepShape {
    dafs: usize,
    forces: usize,
    records: usize,
    surfaces: usize,
}

/// The results folded so far: a point study's points (they are its result),
/// a Monte Carlo study's samples and pending tree nodes.
enum Fold {
    SeparationMap(Vec<MapPoint>),
    SpeedSweep(Vec<SweepPoint>, SweepShape),
    ResonanceCheck(Vec<ResonancePoint>, usize),
    MonteCarlo(EnvelopeFold, MonteCarlo),
}

impl Fold {
    fn new(loaded: &Loaded, study: &Study) -> Fold {
        match study {
            Study::SeparationMap { .. } => Fold::SeparationMap(Vec::new()),
            Study::SpeedSweep(sweep) => {
                let layout = speed_sweep::assemble(&loaded.scenario, sweep, Vec::new(), 0.0);
                let shape = SweepShape {
                    dafs: layout.daf_sources.len(),
                    forces: layout.force_records.len(),
                    records: layout.records.len(),
                    surfaces: layout.roughness.len(),
                };
                Fold::SpeedSweep(Vec::new(), shape)
            }
            Study::ResonanceCheck(check) => Fold::ResonanceCheck(Vec::new(), check.trains.len()),
            Study::MonteCarlo(mc) => Fold::MonteCarlo(EnvelopeFold::new(mc), mc.clone()),
        }
    }

    /// Checks `part`'s results against its slice and folds them in.
    fn push(
        &mut self,
        part: Part,
        count: usize,
        rerun: &dyn Fn(usize) -> String,
    ) -> Result<(), ShardError> {
        let runs = part.end - part.first;
        let shard = part.shard;
        match (self, part.data) {
            (Fold::SeparationMap(points), PartData::SeparationMap { points: more }) => {
                if more.len() != runs {
                    return Err(short(shard, more.len(), runs, rerun(shard)));
                }
                points.extend(more);
            }
            (Fold::SpeedSweep(points, shape), PartData::SpeedSweep { points: more }) => {
                let fits = |q: &SweepPoint| {
                    q.dafs.len() == shape.dafs
                        && q.max_forces.len() == shape.forces
                        && q.max_abs.len() == shape.records
                        && q.roughness < shape.surfaces
                };
                if more.len() != runs || !more.iter().all(fits) {
                    return Err(short(shard, more.len(), runs, rerun(shard)));
                }
                points.extend(more);
            }
            (Fold::ResonanceCheck(points, trains), PartData::ResonanceCheck { points: more }) => {
                if more.len() != runs || !more.iter().all(|q| q.train < *trains) {
                    return Err(short(shard, more.len(), runs, rerun(shard)));
                }
                points.extend(more);
            }
            (Fold::MonteCarlo(fold, mc), PartData::MonteCarlo(slice)) => {
                let bad = |e: String| {
                    ShardError::Mismatch(format!(
                        "shard {shard} of {count}: {e}; run it again: `{}`",
                        rerun(shard)
                    ))
                };
                slice.check(mc, part.first..part.end).map_err(bad)?;
                fold.push(slice)
                    .map_err(|e| ShardError::Mismatch(e.to_string()))?;
            }
            _ => {
                return Err(ShardError::Mismatch(
                    "a part's results do not match its study type".into(),
                ));
            }
        }
        Ok(())
    }

    /// The merged study, as an unsharded run assembles it.
    fn finish(self, loaded: &Loaded, study: &Study, wall_time: f64) -> Result<Results, ShardError> {
        Ok(match (self, study) {
            (
                Fold::SeparationMap(points),
                Study::SeparationMap {
                    velocity_ratio,
                    mass_ratio,
                },
            ) => Results::SeparationMap(separation_map::assemble(
                velocity_ratio,
                mass_ratio,
                points,
                wall_time,
            )),
            (Fold::SpeedSweep(points, _), Study::SpeedSweep(sweep)) => Results::SpeedSweep(
                speed_sweep::assemble(&loaded.scenario, sweep, points, wall_time),
            ),
            (Fold::ResonanceCheck(points, _), Study::ResonanceCheck(check)) => {
                Results::ResonanceCheck(resonance::assemble(check, points, wall_time))
            }
            (Fold::MonteCarlo(fold, mc), Study::MonteCarlo(_)) => Results::MonteCarlo(
                fold.finish(&loaded.scenario, &mc, wall_time)
                    .map_err(|e| ShardError::Mismatch(e.to_string()))?,
            ),
            _ => {
                return Err(ShardError::Mismatch(
                    "a part's results do not match its study type".into(),
                ));
            }
        })
    }
}
