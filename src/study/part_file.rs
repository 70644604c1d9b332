//! Reading a part file for `vbi merge` without trusting it (issue 23): a
//! part may be forged, so its size is read from the metadata and capped
//! before a byte is read, anything but a regular file (a device such as
//! `/dev/zero`, a FIFO, a folder) is refused before it is opened, and a file
//! that does not parse as a part is refused without quoting its content.

use std::io::Read;
use std::path::Path;

use serde::de::{DeserializeOwned, IgnoredAny};

use super::shard::{PART_FORMAT, Part, ShardError};

/// Largest part file read, bytes, unless `--allow-large`: a part of the
/// largest study the default budgets allow (10,000 runs, `limits.study_points`)
/// holds a few kB a run (a Monte Carlo sample's envelopes and reduced tree
/// nodes the most), far below this.
pub const MAX_PART_BYTES: u64 = 256 * 1024 * 1024;

/// Reads and parses the part file at `path`; `allow_large` lifts
/// [`MAX_PART_BYTES`].
pub fn read_part(path: &Path, allow_large: bool) -> Result<Part, ShardError> {
    read_as(path, allow_large)
}

/// Reads the part file at `path` as [`read_part`] does, but everything
/// except its results (checked to be JSON and skipped, not kept): what the
/// merge's first pass needs of every part.
pub fn read_stamp(path: &Path, allow_large: bool) -> Result<Part<IgnoredAny>, ShardError> {
    read_as(path, allow_large)
}

fn read_as<T: DeserializeOwned>(path: &Path, allow_large: bool) -> Result<T, ShardError> {
    let not_a_part = |message: String| ShardError::NotAPart {
        path: path.to_path_buf(),
        message,
    };
    let io = |source| ShardError::Read {
        path: path.to_path_buf(),
        source,
    };
    // The type and size first, from the metadata: nothing is opened yet.
    let meta = std::fs::metadata(path).map_err(io)?;
    if !meta.is_file() {
        return Err(not_a_part(
            "it is not a regular file (a folder, a device or a pipe)".into(),
        ));
    }
    let size = meta.len();
    if size > MAX_PART_BYTES && !allow_large {
        return Err(not_a_part(format!(
            "it has {size} bytes, more than the {MAX_PART_BYTES} a part file may have; \
             merge with `--allow-large` if it really is one"
        )));
    }
    let file = crate::guarded_file::open_regular(path).map_err(io)?;
    let mut bytes = Vec::new();
    file.take(size.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    let Ok(text) = String::from_utf8(bytes) else {
        return Err(not_a_part("it is not UTF-8 text".into()));
    };
    // The format tag alone first: a file that is not a part at all is
    // refused before its fields are looked at, and none of its text is
    // quoted (serde's messages quote the strings they met).
    #[derive(serde::Deserialize)]
    struct Tag {
        format: Option<serde_json::Value>,
    }
    let tag: Tag = serde_json::from_str(&text).map_err(|e| not_a_part(json_fault(&e, &text)))?;
    if tag.format.as_ref().and_then(|v| v.as_str()) != Some(PART_FORMAT) {
        return Err(not_a_part(format!(
            "its `format` is not `{PART_FORMAT}`, the part format this vbi reads"
        )));
    }
    serde_json::from_str(&text).map_err(|e| not_a_part(json_fault(&e, &text)))
}

/// Where and what kind a JSON error of `text` is, without the text serde
/// quotes. A syntax error on the text's last character is a cut file too
/// (a number cut short, "…e-6,5", is refused there as a syntax error,
/// not as an end of input).
fn json_fault(e: &serde_json::Error, text: &str) -> String {
    use serde_json::error::Category;
    let (last_line, last_column) = text
        .trim_end()
        .lines()
        .enumerate()
        .last()
        .map_or((1, 0), |(i, l)| (i + 1, l.chars().count()));
    let at_end = e.line() > last_line || (e.line() == last_line && e.column() >= last_column);
    let kind = match e.classify() {
        Category::Io => "cannot be read",
        Category::Syntax if at_end => "ends early",
        Category::Syntax => "is not valid JSON",
        Category::Data => "does not have a part's fields and types",
        Category::Eof => "ends early",
    };
    format!("it {kind} (line {}, column {})", e.line(), e.column())
}
