//! Sharding a study across machines: `vbi run study.yaml --shard K/N` runs
//! a slice of the study's flat list of runs and writes a part file; `vbi
//! merge PARTS… --out DIR` checks the parts and writes exactly the files an
//! unsharded run writes.
//!
//! The flat list is the study's own run order (a separation map's grid
//! points velocity-ratio major; a speed sweep's surface by surface, sample
//! by sample, speed by speed; a Monte Carlo study's case by case, sample by
//! sample). Shard K of N (from 1) takes the contiguous slice
//! [⌊(K−1)·T/N⌋, ⌊K·T/N⌋) of the T runs, so the slices tile the list and
//! differ in size by at most one. Merging concatenates the points in order
//! and, for a Monte Carlo study, evaluates the same fixed reduction tree as
//! the unsharded run ([`super::monte_carlo`]): the files are byte for byte
//! those of the unsharded run, except `wall_time` in summary.json, which is
//! the sum of the parts' wall times.
//!
//! A part file (`part-K-of-N.json`) is self-describing: format version, the
//! scenario's text and file name, a hash of the resolved scenario, the study
//! type and size, K, N and the slice, the wall time and the slice's results
//! (floats written in shortest round-trip form and read back exactly).

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::monte_carlo::{self, MonteCarloPart};
use super::separation_map::{self, MapPoint};
use super::speed_sweep::{self, SweepPoint};
use crate::plan::Loaded;
use crate::run::RunError;
use crate::scenario::{self, LoadOptions};
use crate::scene::Study;

mod merge;

pub use merge::{Merged, merge};

/// Version tag of the part format.
pub const PART_FORMAT: &str = "vbi-part-2";

/// Which shard of how many: K of N, both from 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// This shard, 1 ≤ K ≤ N.
    pub index: usize,
    /// Shards in all.
    pub count: usize,
}

impl Shard {
    /// Reads `K/N` (1 ≤ K ≤ N).
    pub fn parse(text: &str) -> Result<Shard, String> {
        let (k, n) = text
            .split_once('/')
            .ok_or_else(|| format!("a shard is written K/N, e.g. 3/8; got `{text}`"))?;
        let parse = |s: &str, what: &str| {
            s.trim()
                .parse::<usize>()
                .map_err(|_| format!("{what} `{s}` in `{text}` is not a whole number"))
        };
        let (index, count) = (parse(k, "K")?, parse(n, "N")?);
        if count == 0 || index == 0 || index > count {
            return Err(format!(
                "a shard K/N needs 1 ≤ K ≤ N (counted from 1); got `{text}`"
            ));
        }
        Ok(Shard { index, count })
    }

    /// The slice of a study of `size` runs: [⌊(K−1)·T/N⌋, ⌊K·T/N⌋).
    pub fn range(self, size: usize) -> Range<usize> {
        let at = |k: usize| (k as u128 * size as u128 / self.count as u128) as usize;
        at(self.index - 1)..at(self.index)
    }

    /// The shard a part file's name (`part-K-of-N.json`) says it holds.
    pub fn from_file_name(path: &Path) -> Option<Shard> {
        let name = path.file_name()?.to_str()?;
        let (k, n) = name
            .strip_prefix("part-")?
            .strip_suffix(".json")?
            .split_once("-of-")?;
        let (index, count) = (k.parse().ok()?, n.parse().ok()?);
        (index >= 1 && index <= count).then_some(Shard { index, count })
    }

    /// The part file's name: `part-K-of-N.json`.
    pub fn file_name(self) -> String {
        format!("part-{}-of-{}.json", self.index, self.count)
    }
}

/// The results of one slice.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "study", rename_all = "snake_case")]
pub enum PartData {
    /// Separation-map points of the slice.
    SeparationMap {
        /// Points in grid order.
        points: Vec<MapPoint>,
    },
    /// Speed-sweep points of the slice.
    SpeedSweep {
        /// Points in sweep order.
        points: Vec<SweepPoint>,
    },
    /// Monte Carlo samples and reduced tree nodes of the slice.
    MonteCarlo(MonteCarloPart),
    /// Resonance-check runs of the slice.
    ResonanceCheck {
        /// Runs in study order.
        points: Vec<crate::study::resonance::ResonancePoint>,
    },
}

/// A part file; `D` is its results, [`serde::de::IgnoredAny`] when only
/// the rest is read (the merge's first pass).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Part<D = PartData> {
    /// [`PART_FORMAT`].
    pub format: String,
    /// vbi version that wrote it.
    pub vbi_version: String,
    /// FNV-1a 64 of the resolved scenario (resolved.yaml), hex.
    pub scenario_hash: String,
    /// The scenario file as given to `vbi run`.
    pub scenario_file: String,
    /// Its text.
    pub scenario_source: String,
    /// Whether the run lifted the resource limits (`--allow-large`).
    pub allow_large: bool,
    /// Whether the run let the file raise its own limits (`--trust-limits`).
    #[serde(default)]
    pub trust_limits: bool,
    /// Study type.
    pub study: String,
    /// Runs in the whole study.
    pub size: usize,
    /// This shard, from 1.
    pub shard: usize,
    /// Shards in all.
    pub shards: usize,
    /// First run index of the slice (from 0).
    pub first: usize,
    /// One past the last run index.
    pub end: usize,
    /// Wall time of the slice, s.
    pub wall_time: f64,
    /// FNV-1a 64 of the results as written ([`data_digest`]), hex: a part
    /// damaged or edited after its run (a bit flipped, a number changed by
    /// hand) is refused at the merge instead of folded in (issue 39.6:
    /// 1,437 of 9,757 mutated parts had merged). It guards against damage,
    /// not against a forger who recomputes it: only running the shard again
    /// re-derives its results.
    pub data_digest: String,
    /// The slice's results.
    pub data: D,
}

/// The digest of a part's results: FNV-1a 64 of their JSON text (serde's
/// shortest round-trip numbers, so the same values give the same text
/// whichever way the file wrote them), hex.
pub fn data_digest(data: &PartData) -> String {
    fnv1a(
        serde_json::to_string(data)
            .expect("a part's results serialise")
            .as_bytes(),
    )
}

impl<D> Part<D> {
    /// Whether everything but the results is the same in both (the same
    /// part file read twice).
    pub fn same_stamp<E>(&self, other: &Part<E>) -> bool {
        self.format == other.format
            && self.vbi_version == other.vbi_version
            && self.scenario_hash == other.scenario_hash
            && self.scenario_file == other.scenario_file
            && self.scenario_source == other.scenario_source
            && self.allow_large == other.allow_large
            && self.trust_limits == other.trust_limits
            && self.study == other.study
            && self.size == other.size
            && self.shard == other.shard
            && self.shards == other.shards
            && self.first == other.first
            && self.end == other.end
            && self.wall_time.to_bits() == other.wall_time.to_bits()
            && self.data_digest == other.data_digest
    }
}

/// Why a shard cannot run or parts cannot be merged.
#[derive(Debug, Error)]
pub enum ShardError {
    /// The scene has no study to shard.
    #[error("{file}: --shard and --sample apply to a study; this scene has no `study` section")]
    NoStudy {
        /// The scenario file.
        file: String,
    },
    /// A part file could not be read.
    #[error("{}: cannot read: {source}", path.display())]
    Read {
        /// The part file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A part file is not a part.
    #[error("{}: not a vbi part file: {message}", path.display())]
    NotAPart {
        /// The part file.
        path: PathBuf,
        /// What failed.
        message: String,
    },
    /// A shard count the study cannot take.
    #[error("{file}: --shard: {message}")]
    Shards {
        /// The scenario file.
        file: String,
        /// What is wrong.
        message: String,
    },
    /// A part file named as shard K of N cannot be read or is no part.
    #[error("{error}; shard {shard} of {count} is unusable: run it again with `{command}`")]
    Unusable {
        /// Why it cannot be used.
        error: Box<ShardError>,
        /// K.
        shard: usize,
        /// N.
        count: usize,
        /// The command that writes it again.
        command: String,
    },
    /// Parts disagree or do not tile the study.
    #[error("{0}")]
    Mismatch(String),
    /// The scenario in the parts no longer loads.
    #[error(transparent)]
    Load(#[from] scenario::LoadError),
    /// Running the slice failed.
    #[error(transparent)]
    Run(#[from] RunError),
}

/// FNV-1a 64-bit hash (Fowler, Noll & Vo), hex: identifies the resolved
/// scenario of a part (a check against mixing parts of different studies,
/// not a cryptographic digest).
pub fn fnv1a(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// The hash of a loaded scenario.
pub fn scenario_hash(loaded: &Loaded) -> String {
    fnv1a(crate::report::folder::resolved_yaml(&loaded.scenario).as_bytes())
}

/// Study type name and number of runs.
pub(crate) fn study_size(loaded: &Loaded, study: &Study) -> (&'static str, usize) {
    match study {
        Study::SeparationMap {
            velocity_ratio,
            mass_ratio,
        } => (
            "separation_map",
            separation_map::size(velocity_ratio, mass_ratio),
        ),
        Study::SpeedSweep(sweep) => ("speed_sweep", speed_sweep::size(&loaded.scenario, sweep)),
        Study::MonteCarlo(mc) => ("monte_carlo", monte_carlo::size(mc)),
        Study::ResonanceCheck(check) => ("resonance_check", crate::study::resonance::size(check)),
    }
}

/// Whether the study of `loaded` (read from `file`) splits into `count`
/// shards: the study's type name and run count if it does (what `vbi check
/// --shards N` tells a job script before it submits N tasks).
pub fn check_shards(
    loaded: &Loaded,
    file: &str,
    count: usize,
    allow_large: bool,
) -> Result<(&'static str, usize), ShardError> {
    let study = loaded
        .scenario
        .study
        .as_ref()
        .ok_or_else(|| ShardError::NoStudy {
            file: file.to_string(),
        })?;
    let (name, size) = study_size(loaded, study);
    check_count(count, size, loaded, allow_large).map_err(|message| ShardError::Shards {
        file: file.to_string(),
        message,
    })?;
    Ok((name, size))
}

/// Runs shard `shard` of the study of `loaded` (read from `file`, whose
/// text is `source`) and returns its part.
pub fn run_shard(
    loaded: &Loaded,
    file: &str,
    source: &str,
    options: &LoadOptions,
    shard: Shard,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Part, ShardError> {
    let study = loaded
        .scenario
        .study
        .as_ref()
        .ok_or_else(|| ShardError::NoStudy {
            file: file.to_string(),
        })?;
    let (name, size) = study_size(loaded, study);
    check_count(shard.count, size, loaded, options.allow_large).map_err(|message| {
        ShardError::Shards {
            file: file.to_string(),
            message,
        }
    })?;
    let range = shard.range(size);
    let start = Instant::now();
    let (base, bridge) = (&loaded.scenario, &loaded.bridge);
    let data = match study {
        Study::SeparationMap {
            velocity_ratio,
            mass_ratio,
        } => PartData::SeparationMap {
            points: separation_map::run_slice(
                base,
                bridge,
                velocity_ratio,
                mass_ratio,
                range.clone(),
                progress,
            )?,
        },
        Study::SpeedSweep(sweep) => PartData::SpeedSweep {
            points: speed_sweep::run_slice(base, bridge, sweep, range.clone(), progress)?,
        },
        Study::ResonanceCheck(check) => PartData::ResonanceCheck {
            points: crate::study::resonance::run_slice(
                base,
                bridge,
                check,
                range.clone(),
                progress,
            )?,
        },
        Study::MonteCarlo(mc) => PartData::MonteCarlo(monte_carlo::run_slice(
            base,
            bridge,
            mc,
            range.clone(),
            progress,
        )?),
    };
    Ok(Part {
        format: PART_FORMAT.into(),
        vbi_version: env!("CARGO_PKG_VERSION").into(),
        scenario_hash: scenario_hash(loaded),
        scenario_file: file.to_string(),
        scenario_source: source.to_string(),
        allow_large: options.allow_large,
        trust_limits: options.trust_limits,
        study: name.into(),
        size,
        shard: shard.index,
        shards: shard.count,
        first: range.start,
        end: range.end,
        wall_time: start.elapsed().as_secs_f64(),
        data_digest: data_digest(&data),
        data,
    })
}

/// The part as JSON text.
pub fn part_json(part: &Part) -> String {
    serde_json::to_string(part).expect("a part serialises") + "\n"
}

/// Reads a part file ([`super::part_file::read_part`], default caps).
pub fn read_part(path: &Path) -> Result<Part, ShardError> {
    super::part_file::read_part(path, false)
}

/// The command that writes shard `shard`'s part again: `vbi run SCENE
/// --shard K/N --out DIR`, the scene as the parts name it (`SCENE` when no
/// part could be read) and DIR the folder of `part` (a part's path).
pub fn rerun_command(scene: Option<&str>, shard: Shard, part: &Path) -> String {
    let dir = match part.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.display().to_string(),
        _ => ".".into(),
    };
    // The scene's name comes from a part: one with control characters (a
    // forged part's terminal escapes) or of unreasonable length is not
    // echoed.
    let printable = |s: &&str| s.len() <= 4096 && !s.chars().any(char::is_control);
    format!(
        "vbi run {} --shard {}/{} --out {}",
        scene
            .filter(printable)
            .map_or_else(|| "SCENE".into(), shell_word),
        shard.index,
        shard.count,
        shell_word(&dir)
    )
}

/// `text` as one shell word: as is when it holds only characters no shell
/// treats specially, else in single quotes.
fn shell_word(text: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./+,:@%=".contains(c);
    if !text.is_empty() && text.chars().all(plain) {
        text.into()
    } else {
        format!("'{}'", text.replace('\'', "'\\''"))
    }
}

/// Whether `count` shards suit a study of `size` runs: at most one shard a
/// run, and at most `limits.study_points` (lifted by `--allow-large`, which
/// the scene's budget knows).
pub fn check_count(
    count: usize,
    size: usize,
    loaded: &Loaded,
    allow_large: bool,
) -> Result<(), String> {
    if count > size {
        return Err(format!(
            "{count} shards of a study of {size} runs: give at most one shard a run (N ≤ {size})"
        ));
    }
    let limit = loaded.scenario.limits.study_points;
    if count as f64 > limit && !allow_large {
        return Err(format!(
            "{count} shards is more than the {limit} `limits.study_points` allows; raise it in \
             the scene or run with `--allow-large`"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slices_tile_the_study() {
        for size in [0, 1, 5, 7, 100, 1001] {
            for count in 1..=9 {
                let mut at = 0;
                for index in 1..=count {
                    let r = Shard { index, count }.range(size);
                    assert_eq!(r.start, at);
                    assert!(r.len() <= size / count + 1);
                    at = r.end;
                }
                assert_eq!(at, size);
            }
        }
    }

    #[test]
    fn shard_syntax() {
        assert_eq!(Shard::parse("3/8"), Ok(Shard { index: 3, count: 8 }));
        assert!(Shard::parse("0/8").is_err());
        assert!(Shard::parse("9/8").is_err());
        assert!(Shard::parse("3").is_err());
        assert!(Shard::parse("a/2").is_err());
    }

    #[test]
    fn fnv1a_reference_values() {
        // Published FNV-1a 64 test vectors (Fowler/Noll/Vo reference code).
        assert_eq!(fnv1a(b""), "cbf29ce484222325");
        assert_eq!(fnv1a(b"a"), "af63dc4c8601ec8c");
        assert_eq!(fnv1a(b"foobar"), "85944171f73967e8");
    }
}
