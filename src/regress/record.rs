//! The golden record of one scene (`vbi regress`, issue 30): what a run or
//! a study produced, compact and in a text that diffs well line by line
//! (tab-separated; shown here with spaces):
//!
//! ```text
//! # vbi regress golden record …
//! vbi_version  0.1.0
//! scene  moving-force-slow
//! scene_hash  fnv1a64:5f0c…
//! history_bins  200
//!
//! [scalars]
//! name  value  time [s]  position [m]
//! quantities.midspan.max.value  5.77186173e-4  1.09968e0  2.627056132e1
//! run.steps  77325
//!
//! [table history]
//! time_from [s]  time_to [s]  midspan_max [m]  midspan_min [m]  …
//! ```
//!
//! - `[scalars]`: every number and text of the run's or study's
//!   `summary.json`, one per line, named by its path (an element of a list
//!   of objects with a `name` by that name, else by its index), except wall
//!   times and the version. An extreme (an object with `value`, `time`,
//!   `position`) is one line with its time and position beside the value.
//!   Integers and texts are compared exactly, floats with the tolerances.
//! - `[table history]` (a single run): the time history in
//!   [`HistoryBins`](Record::history_bins) bins of consecutive samples, each
//!   with the largest and the smallest value of every column over its
//!   samples, so every peak of the full history is kept whatever the
//!   resolution (the min/max envelope decimation of oscilloscopes).
//! - `[table NAME]`: each table the run or study writes as CSV
//!   (`envelopes` of a run with `envelopes:`; a study's `study`,
//!   `resonance`, `separation`, …), row by row.
//! - `[table envelopes]` of a Monte Carlo study: its per-step envelopes
//!   (`envelopes.csv`: per case and step each record's mean, σ, mean ∓ 3σ)
//!   binned like the history ([`step_binned`]): per case, `history_bins`
//!   bins of consecutive steps, each with the largest and the smallest
//!   value of every column, so every peak is kept exactly while the record
//!   stays small (issue 40.7: 17 MB for 16 samples at every one of 96 000
//!   steps, some 60 kB binned). A record written before (a `time [s]`
//!   column) is binned when read, to the same cells.
//!
//! Floats are written with 10 significant digits (a relative rounding of
//! at most 5e-10, far below the default tolerance), so a change at
//! round-off level does not change the file. Tabs and line breaks inside a
//! text are written `\t`, `\n` (and a backslash `\\`).

use serde_json::Value;

use crate::execute::Results;
use crate::record::History;

/// Significant digits of a float in the record.
const DIGITS: usize = 10;

/// Default number of history bins.
pub const DEFAULT_HISTORY_BINS: usize = 200;

/// One cell of the record.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A float, compared with the tolerances.
    Number(f64),
    /// An integer, a flag or a text, compared exactly.
    Exact(String),
    /// Nothing (an empty CSV cell, a `null`).
    Empty,
}

impl Cell {
    /// The number, if a float.
    pub fn number(&self) -> Option<f64> {
        match self {
            Cell::Number(x) => Some(*x),
            _ => None,
        }
    }
}

/// A named scalar of the summary, with where it happened if an extreme.
#[derive(Debug, Clone, PartialEq)]
pub struct Scalar {
    /// Path in the summary, e.g. `quantities.midspan.max.value`.
    pub name: String,
    /// The value.
    pub value: Cell,
    /// Time of an extreme, s.
    pub time: Option<f64>,
    /// Position of an extreme (of the vehicle or axle it names), m.
    pub position: Option<f64>,
}

/// A table: a header and rows of cells.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Table {
    /// `history` or the name of the study's CSV file without extension.
    pub name: String,
    /// Column headers.
    pub header: Vec<String>,
    /// Rows, each as long as the header.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// The column `c` as floats (`None` for cells that are not floats).
    pub fn column(&self, c: usize) -> Vec<Option<f64>> {
        self.rows
            .iter()
            .map(|r| r.get(c).and_then(Cell::number))
            .collect()
    }
}

/// The golden record of one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// vbi version that wrote the record.
    pub vbi_version: String,
    /// The scene's key in the store (the file's stem).
    pub scene: String,
    /// Hash of the resolved scene ([`scene_hash`]).
    pub scene_hash: String,
    /// Bins of the decimated history.
    pub history_bins: usize,
    /// The summary's scalars.
    pub scalars: Vec<Scalar>,
    /// The history (a run) or the study's tables.
    pub tables: Vec<Table>,
}

/// Summary keys that are not results: wall times (and the EMBS speed-up,
/// a ratio of two), the version (stored in the header) and the scene
/// file's path.
const NOT_RESULTS: [&str; 7] = [
    "wall_time",
    "embs_solve_time",
    "coupled_solve_time",
    "speed_up",
    "vbi_version",
    "source_file",
    "scenario",
];

/// FNV-1a, 64 bit, of the resolved scene without its comment lines (the
/// header names the version and the file's absolute path, which are not
/// the scene): enough to tell whether the scene changed, not a security
/// hash.
pub fn scene_hash(resolved: &str) -> String {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for byte in strip_comments(resolved).bytes() {
        hash ^= u64::from(byte);
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("fnv1a64:{hash:016x}")
}

/// The resolved scene without its `#` header lines.
pub fn strip_comments(resolved: &str) -> String {
    resolved
        .lines()
        .filter(|l| !l.starts_with('#'))
        .flat_map(|l| [l, "\n"])
        .collect()
}

impl Record {
    /// The record of `results`, the scene's resolved YAML being `resolved`
    /// and its advice `advice` ([`Results::advice`]): one scalar
    /// `advice.<id>` per id, its severity (or `allowed: <reason>`) compared
    /// exactly, so that advice that appears or disappears is a change; the
    /// messages, whose figures move with the results, are not kept.
    pub fn new(
        scene: &str,
        resolved: &str,
        results: &Results,
        advice: &[crate::advice::Advice],
        history_bins: usize,
    ) -> Self {
        let (summary, tables) = match results {
            Results::Scene(outcome) => {
                let mut tables = vec![history_table(&outcome.history, history_bins)];
                if let Some(envelope) = &outcome.history.envelope {
                    let csv = crate::report::envelopes::envelope_csv(envelope);
                    tables.push(csv_table("envelopes", csv.as_bytes()));
                }
                (serde_json::to_value(&outcome.summary), tables)
            }
            Results::SeparationMap(map) => (
                serde_json::to_value(serde_json::json!({
                    "points": map.points.len(),
                    "separated": map.separated_count(),
                    "velocity_ratios": map.velocity_ratios,
                    "mass_ratios": map.mass_ratios,
                })),
                vec![csv_table("study", &map.to_csv())],
            ),
            Results::SpeedSweep(sweep) => (
                serde_json::to_value(crate::study::speed_sweep::SweepSummary::new(scene, sweep)),
                vec![csv_table("study", &sweep.to_csv())],
            ),
            Results::MonteCarlo(mc) => (
                serde_json::to_value(mc.summary(scene)),
                vec![
                    csv_table("study", &mc.samples_csv()),
                    csv_table("separation", &mc.separation_csv()),
                    step_binned(csv_table("envelopes", &mc.envelopes_csv()), history_bins),
                ],
            ),
            Results::ResonanceCheck(check) => (
                serde_json::to_value(check.summary(scene)),
                vec![
                    csv_table("resonance", &check.to_csv()),
                    csv_table("resonance_trains", &check.trains_csv()),
                ],
            ),
        };
        let mut summary = summary.unwrap_or(Value::Null);
        if let Some(object) = summary.as_object_mut() {
            object.remove("advice");
        }
        let mut scalars = Vec::new();
        flatten(&summary, String::new(), &mut scalars);
        let mut ids: Vec<(&str, String)> = advice
            .iter()
            .map(|a| {
                let state = match &a.allowed {
                    Some(reason) => format!("allowed: {reason}"),
                    None => a.severity.word().to_string(),
                };
                (a.id.as_str(), state)
            })
            .collect();
        ids.sort();
        ids.dedup_by(|a, b| a.0 == b.0);
        scalars.extend(ids.into_iter().map(|(id, state)| Scalar {
            name: format!("advice.{id}"),
            value: Cell::Exact(state),
            time: None,
            position: None,
        }));
        Record {
            vbi_version: env!("CARGO_PKG_VERSION").into(),
            scene: scene.into(),
            scene_hash: scene_hash(resolved),
            history_bins,
            scalars,
            tables,
        }
    }
}

fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.into()
    } else {
        format!("{prefix}.{key}")
    }
}

/// Every leaf of `value` as a scalar (see the module documentation).
fn flatten(value: &Value, path: String, out: &mut Vec<Scalar>) {
    match value {
        Value::Object(map) => {
            // An extreme: one line with its place.
            if let (Some(v), Some(t)) = (map.get("value"), map.get("time"))
                && v.is_number()
                && t.is_number()
            {
                out.push(Scalar {
                    name: join(&path, "value"),
                    value: json_cell(v),
                    time: t.as_f64(),
                    position: map.get("position").and_then(Value::as_f64),
                });
                for (key, item) in map {
                    if !["value", "time", "position"].contains(&key.as_str()) {
                        flatten(item, join(&path, key), out);
                    }
                }
                return;
            }
            for (key, item) in map {
                if !NOT_RESULTS.contains(&key.as_str()) {
                    flatten(item, join(&path, key), out);
                }
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                let key = item
                    .get("name")
                    .or_else(|| item.get("train"))
                    .and_then(Value::as_str)
                    .map_or_else(|| i.to_string(), |n| escape(n).replace('.', "_"));
                flatten(item, join(&path, &key), out);
            }
        }
        leaf => out.push(Scalar {
            name: path,
            value: json_cell(leaf),
            time: None,
            position: None,
        }),
    }
}

fn json_cell(value: &Value) -> Cell {
    match value {
        Value::Null => Cell::Empty,
        Value::Number(n) if n.is_f64() => Cell::Number(n.as_f64().unwrap_or(f64::NAN)),
        Value::Number(n) => Cell::Exact(n.to_string()),
        Value::Bool(b) => Cell::Exact(b.to_string()),
        Value::String(s) => Cell::Exact(s.clone()),
        other => Cell::Exact(other.to_string()),
    }
}

/// A CSV table the study writes, its numbers as floats.
fn csv_table(name: &str, csv_bytes: &[u8]) -> Table {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(true)
        .from_reader(csv_bytes);
    let header: Vec<String> = reader
        .headers()
        .map(|h| h.iter().map(str::to_string).collect())
        .unwrap_or_default();
    let rows = reader
        .records()
        .filter_map(Result::ok)
        .map(|r| r.iter().map(text_cell).collect())
        .collect();
    Table {
        name: name.into(),
        header,
        rows,
    }
}

/// A CSV cell: a float if it reads as one, else the text.
fn text_cell(text: &str) -> Cell {
    if text.is_empty() {
        Cell::Empty
    } else if let Ok(x) = text.parse::<f64>()
        && !matches!(text, "true" | "false")
    {
        Cell::Number(x)
    } else {
        Cell::Exact(text.into())
    }
}

/// The history in `bins` bins of consecutive samples, each with the
/// largest and smallest value of every column (see the module docs).
pub fn history_table(history: &History, bins: usize) -> Table {
    let labels = crate::report::history_files::column_labels(history);
    let mut rows_all: Vec<Vec<f64>> = Vec::new();
    // A streamed history is read back from its file; a read error leaves
    // the rows read so far.
    let _ = crate::report::history_files::each_row(history, |row| rows_all.push(row.to_vec()));
    let samples = rows_all.len();
    let bins = bins.clamp(1, samples.max(1));
    let mut header = vec!["time_from [s]".to_string(), "time_to [s]".to_string()];
    for label in labels.iter().skip(1) {
        // `midspan [m]` → `midspan_max [m]`, `midspan_min [m]`: the one
        // header style of every file (issue 26.5).
        let (name, unit) = label.split_once(" [").unwrap_or((label, ""));
        let unit = unit.strip_suffix(']').unwrap_or(unit);
        header.push(crate::report::heading(&format!("{name}_max"), unit));
        header.push(crate::report::heading(&format!("{name}_min"), unit));
    }
    let mut rows = Vec::with_capacity(bins);
    for b in 0..bins {
        let (from, to) = (b * samples / bins, (b + 1) * samples / bins);
        if from >= to {
            continue;
        }
        let slice = &rows_all[from..to];
        let mut row = vec![
            Cell::Number(slice[0][0]),
            Cell::Number(slice[to - from - 1][0]),
        ];
        for c in 1..labels.len() {
            let (hi, lo) = slice
                .iter()
                .fold((f64::NEG_INFINITY, f64::INFINITY), |(h, l), r| {
                    (h.max(r[c]), l.min(r[c]))
                });
            row.push(Cell::Number(hi));
            row.push(Cell::Number(lo));
        }
        rows.push(row);
    }
    Table {
        name: "history".into(),
        header,
        rows,
    }
}

/// The name of the per-step column of a table that [`step_binned`] bins.
const STEP_COLUMN: &str = "time [s]";

/// A per-step table (a Monte Carlo study's `envelopes`: the case's cells,
/// then `time [s]`, then the quantities at that step) in at most `bins`
/// bins of consecutive steps per case, like [`history_table`]: the case's
/// cells, `time_from [s]`, `time_to [s]` (the first and last step of the
/// bin), then for each quantity column `…_max` and `…_min` over the bin's
/// steps. The global extremes of every column are thus the extremes of its
/// bins, exactly. A NaN in a bin makes both its cells NaN (a regression
/// must see it, not have `max` skip it); a bin with no number in a column
/// (a hand-made record) has empty cells there. A table without a
/// `time [s]` column is returned as it is.
pub fn step_binned(table: Table, bins: usize) -> Table {
    let Some(t) = table.header.iter().position(|h| h == STEP_COLUMN) else {
        return table;
    };
    let mut header: Vec<String> = table.header[..t].to_vec();
    header.push("time_from [s]".into());
    header.push("time_to [s]".into());
    for label in &table.header[t + 1..] {
        let (name, unit) = label.split_once(" [").unwrap_or((label, ""));
        let unit = unit.strip_suffix(']').unwrap_or(unit);
        header.push(crate::report::heading(&format!("{name}_max"), unit));
        header.push(crate::report::heading(&format!("{name}_min"), unit));
    }
    let width = table.header.len();
    let mut rows = Vec::new();
    let mut start = 0;
    while start < table.rows.len() {
        // One case: the consecutive rows with the same cells before the time.
        let key = &table.rows[start][..t.min(table.rows[start].len())];
        let end = start
            + table.rows[start..]
                .iter()
                .take_while(|r| r.get(..t) == Some(key))
                .count()
                .max(1);
        let case = &table.rows[start..end];
        let n = case.len();
        let bins = bins.clamp(1, n);
        for b in 0..bins {
            let (from, to) = (b * n / bins, (b + 1) * n / bins);
            if from >= to {
                continue;
            }
            let slice = &case[from..to];
            let mut row: Vec<Cell> = key.to_vec();
            row.resize(t, Cell::Empty);
            let time = |r: &Vec<Cell>| r.get(t).cloned().unwrap_or(Cell::Empty);
            row.push(time(&slice[0]));
            row.push(time(&slice[slice.len() - 1]));
            for c in t + 1..width {
                let (mut hi, mut lo, mut any, mut nan) =
                    (f64::NEG_INFINITY, f64::INFINITY, false, false);
                for x in slice.iter().filter_map(|r| r.get(c).and_then(Cell::number)) {
                    any = true;
                    nan |= x.is_nan();
                    hi = hi.max(x);
                    lo = lo.min(x);
                }
                let (hi, lo) = match (any, nan) {
                    (false, _) => (Cell::Empty, Cell::Empty),
                    (true, true) => (Cell::Number(f64::NAN), Cell::Number(f64::NAN)),
                    (true, false) => (Cell::Number(hi), Cell::Number(lo)),
                };
                row.push(hi);
                row.push(lo);
            }
            rows.push(row);
        }
        start = end;
    }
    Table {
        name: table.name,
        header,
        rows,
    }
}

/// A float with [`DIGITS`] significant digits, always in exponent notation
/// (so that it reads back as a float, not an integer).
pub fn format_number(x: f64) -> String {
    if x == 0.0 {
        return "0e0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let rounded: f64 = format!("{:.*e}", DIGITS - 1, x).parse().unwrap_or(x);
    format!("{rounded:e}")
}

fn escape(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('\t', "\\t")
        .replace('\n', "\\n")
        .replace('\r', "\\r")
}

fn unescape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            match chars.next() {
                Some('t') => out.push('\t'),
                Some('n') => out.push('\n'),
                Some('r') => out.push('\r'),
                Some(other) => out.push(other),
                None => out.push('\\'),
            }
        } else {
            out.push(c);
        }
    }
    out
}

fn write_cell(cell: &Cell) -> String {
    match cell {
        Cell::Number(x) => format_number(*x),
        Cell::Exact(s) => escape(s),
        Cell::Empty => String::new(),
    }
}

/// A cell read back: a float is written with an exponent (or is `inf`,
/// `NaN`), an integer without.
fn read_cell(text: &str) -> Cell {
    if text.is_empty() {
        return Cell::Empty;
    }
    let special = matches!(text, "inf" | "-inf" | "NaN");
    let exponent = text.contains(['e', 'E'])
        && text
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+'));
    match text.parse::<f64>() {
        Ok(x) if special || exponent => Cell::Number(x),
        _ => Cell::Exact(unescape(text)),
    }
}

/// The header line of every record file.
const MAGIC: &str = "# vbi regress golden record";

impl Record {
    /// The record as text (see the module documentation).
    pub fn to_text(&self) -> String {
        let mut out = format!(
            "{MAGIC}: written by `vbi regress approve`, checked by `vbi regress check`; \
             review its diff, do not edit it by hand.\n"
        );
        out.push_str(&format!("vbi_version\t{}\n", self.vbi_version));
        out.push_str(&format!("scene\t{}\n", escape(&self.scene)));
        out.push_str(&format!("scene_hash\t{}\n", self.scene_hash));
        out.push_str(&format!("history_bins\t{}\n", self.history_bins));
        out.push_str("\n[scalars]\nname\tvalue\ttime [s]\tposition [m]\n");
        for s in &self.scalars {
            let place = |v: Option<f64>| v.map(format_number).unwrap_or_default();
            let line = format!(
                "{}\t{}\t{}\t{}",
                escape(&s.name),
                write_cell(&s.value),
                place(s.time),
                place(s.position)
            );
            out.push_str(line.trim_end_matches('\t'));
            out.push('\n');
        }
        for table in &self.tables {
            out.push_str(&format!("\n[table {}]\n", escape(&table.name)));
            let header: Vec<String> = table.header.iter().map(|h| escape(h)).collect();
            out.push_str(&header.join("\t"));
            out.push('\n');
            for row in &table.rows {
                let cells: Vec<String> = row.iter().map(write_cell).collect();
                out.push_str(&cells.join("\t"));
                out.push('\n');
            }
        }
        out
    }

    /// Reads a record written by [`Record::to_text`]; the error says which
    /// line is wrong.
    pub fn from_text(text: &str) -> Result<Self, String> {
        let mut lines = text.lines().enumerate().peekable();
        match lines.next() {
            Some((_, l)) if l.starts_with(MAGIC) => {}
            _ => return Err("line 1: not a vbi regress golden record".into()),
        }
        let mut record = Record {
            vbi_version: String::new(),
            scene: String::new(),
            scene_hash: String::new(),
            history_bins: DEFAULT_HISTORY_BINS,
            scalars: Vec::new(),
            tables: Vec::new(),
        };
        #[derive(PartialEq)]
        enum Section {
            Header,
            Scalars,
            Table,
        }
        let mut section = Section::Header;
        let mut expect_header = false;
        for (i, line) in lines {
            let at = |m: &str| format!("line {}: {m}", i + 1);
            if line.is_empty() {
                continue;
            }
            if let Some(name) = line
                .strip_prefix("[table ")
                .and_then(|l| l.strip_suffix(']'))
            {
                record.tables.push(Table {
                    name: unescape(name),
                    header: Vec::new(),
                    rows: Vec::new(),
                });
                section = Section::Table;
                expect_header = true;
                continue;
            }
            if line == "[scalars]" {
                section = Section::Scalars;
                expect_header = true;
                continue;
            }
            let fields: Vec<&str> = line.split('\t').collect();
            match section {
                Section::Header => {
                    let value = fields.get(1).copied().unwrap_or_default();
                    match fields[0] {
                        "vbi_version" => record.vbi_version = value.into(),
                        "scene" => record.scene = unescape(value),
                        "scene_hash" => record.scene_hash = value.into(),
                        "history_bins" => {
                            record.history_bins = value
                                .parse()
                                .ok()
                                .filter(|b| (2..=100_000).contains(b))
                                .ok_or_else(|| {
                                    at("history_bins: not a whole number from 2 to 100000")
                                })?;
                        }
                        other => {
                            return Err(at(&format!(
                                "unknown header key `{}`",
                                crate::guarded_file::excerpt(other, 40)
                            )));
                        }
                    }
                }
                Section::Scalars if expect_header => expect_header = false,
                Section::Scalars => {
                    // A summary scalar is a JSON number, always finite: a
                    // stored `inf` or `NaN` is forged, and would widen the
                    // tolerance into a pass (issue 39.2).
                    let value = read_cell(fields.get(1).copied().unwrap_or_default());
                    if value.number().is_some_and(|x| !x.is_finite()) {
                        return Err(at(&format!(
                            "the value of `{}` is not a finite number; vbi writes none \
                             other (approve the scene again)",
                            crate::guarded_file::excerpt(&unescape(fields[0]), 40)
                        )));
                    }
                    let place = |k: usize| -> Result<Option<f64>, String> {
                        match fields.get(k).filter(|f| !f.is_empty()) {
                            None => Ok(None),
                            Some(f) => match f.parse::<f64>() {
                                Ok(x) if x.is_finite() => Ok(Some(x)),
                                _ => Err(at("a time or position that is not a finite number")),
                            },
                        }
                    };
                    record.scalars.push(Scalar {
                        name: unescape(fields[0]),
                        value,
                        time: place(2)?,
                        position: place(3)?,
                    });
                }
                Section::Table => {
                    let table = record.tables.last_mut().expect("a table was opened");
                    if expect_header {
                        table.header = fields.iter().map(|f| unescape(f)).collect();
                        expect_header = false;
                    } else {
                        if fields.len() != table.header.len() {
                            return Err(at(&format!(
                                "{} cells in a row of table `{}` of {} columns",
                                fields.len(),
                                crate::guarded_file::excerpt(&table.name, 40),
                                table.header.len()
                            )));
                        }
                        table
                            .rows
                            .push(fields.iter().map(|f| read_cell(f)).collect());
                    }
                }
            }
        }
        // A study's envelopes stored at every step (before issue 40.7):
        // binned now as `approve` bins them, so the check compares like with
        // like (rounding to DIGITS is monotone: the bins' extremes are those
        // a new approve writes).
        let bins = record.history_bins;
        for table in &mut record.tables {
            if table.name == "envelopes" {
                *table = step_binned(std::mem::take(table), bins);
            }
        }
        Ok(record)
    }
}
