//! Comparing a new record with the golden one: every scalar and every
//! table cell against its tolerance ([`super::settings`]), each relative
//! to its quantity's peak, and whether the scene itself changed.

use super::record::{Cell, Record, Table};
use super::settings::Settings;

/// One quantity that moved beyond its tolerance (the worst cell of a
/// column; every failing scalar).
#[derive(Debug, Clone, PartialEq)]
pub struct Difference {
    /// The quantity: a summary path (`quantities.midspan.max.value`) or a
    /// table's column (`history: midspan [m] max`).
    pub quantity: String,
    /// The golden value, as text.
    pub old: String,
    /// The new value, as text.
    pub new: String,
    /// |new − old| / the quantity's peak (`None` for exact items).
    pub relative: Option<f64>,
    /// Where: the time and position of an extreme, the time span of a
    /// history bin, the row of a study table (its speed).
    pub place: String,
    /// Cells of the column beyond tolerance (1 for a scalar).
    pub cells: usize,
}

/// A changed column of a table, for its plot of old against new.
#[derive(Debug, Clone, PartialEq)]
pub struct ChangedColumn {
    /// Table name.
    pub table: String,
    /// Column index in both tables.
    pub column: usize,
}

/// The outcome of comparing one scene.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Comparison {
    /// The resolved scene differs from the approved one.
    pub scene_changed: bool,
    /// The vbi versions (old, new) when they differ.
    pub version_changed: Option<(String, String)>,
    /// Quantities beyond tolerance, in record order.
    pub differences: Vec<Difference>,
    /// Changed table columns (for the plots).
    pub changed_columns: Vec<ChangedColumn>,
}

impl Comparison {
    /// Whether the results agree within tolerance.
    pub fn results_pass(&self) -> bool {
        self.differences.is_empty()
    }
}

fn show(cell: Option<&Cell>) -> String {
    match cell {
        Some(Cell::Number(x)) => format!("{x:.6e}"),
        Some(Cell::Exact(s)) => s.clone(),
        Some(Cell::Empty) => "(empty)".into(),
        None => "(absent)".into(),
    }
}

/// The group of a scalar that shares one peak: the extremes of one record
/// (`quantities.midspan.*.value`) are measured against its largest one.
fn peak_group(name: &str) -> Option<String> {
    name.ends_with(".value")
        .then(|| name.split('.').take(2).collect::<Vec<_>>().join("."))
}

/// Compares `new` with the golden `old` of scene `scene`.
pub fn compare(scene: &str, old: &Record, new: &Record, settings: &Settings) -> Comparison {
    let mut out = Comparison {
        scene_changed: old.scene_hash != new.scene_hash,
        version_changed: (old.vbi_version != new.vbi_version)
            .then(|| (old.vbi_version.clone(), new.vbi_version.clone())),
        ..Comparison::default()
    };
    compare_scalars(scene, old, new, settings, &mut out);
    for table in &old.tables {
        match new.tables.iter().find(|t| t.name == table.name) {
            Some(new_table) => compare_table(scene, table, new_table, settings, &mut out),
            None => out.differences.push(Difference {
                quantity: format!("table {}", table.name),
                old: format!("{} rows", table.rows.len()),
                new: "(absent)".into(),
                relative: None,
                place: String::new(),
                cells: 1,
            }),
        }
    }
    for table in &new.tables {
        if !old.tables.iter().any(|t| t.name == table.name) {
            out.differences.push(Difference {
                quantity: format!("table {}", table.name),
                old: "(absent)".into(),
                new: format!("{} rows", table.rows.len()),
                relative: None,
                place: String::new(),
                cells: 1,
            });
        }
    }
    out
}

fn compare_scalars(
    scene: &str,
    old: &Record,
    new: &Record,
    settings: &Settings,
    out: &mut Comparison,
) {
    use std::collections::BTreeMap;
    let mut peaks: BTreeMap<String, f64> = BTreeMap::new();
    for s in old.scalars.iter().chain(&new.scalars) {
        if let (Some(group), Some(x)) = (peak_group(&s.name), s.value.number())
            && x.is_finite()
        {
            let peak = peaks.entry(group).or_insert(0.0);
            *peak = peak.max(x.abs());
        }
    }
    let new_by_name: BTreeMap<&str, &super::record::Scalar> =
        new.scalars.iter().map(|s| (s.name.as_str(), s)).collect();
    for s in &old.scalars {
        let found = new_by_name.get(s.name.as_str());
        let place = |time: Option<f64>, position: Option<f64>| {
            let mut parts = Vec::new();
            if let Some(t) = time {
                parts.push(format!("t = {t:.6} s"));
            }
            if let Some(x) = position {
                parts.push(format!("x = {x:.4} m"));
            }
            parts.join(", ")
        };
        let Some(n) = found else {
            out.differences.push(Difference {
                quantity: s.name.clone(),
                old: show(Some(&s.value)),
                new: "(absent)".into(),
                relative: None,
                place: String::new(),
                cells: 1,
            });
            continue;
        };
        let (pass, relative) = match (&s.value, &n.value) {
            (Cell::Number(a), Cell::Number(b)) => {
                let peak = peak_group(&s.name)
                    .and_then(|g| peaks.get(&g).copied())
                    .unwrap_or(0.0)
                    .max(a.abs())
                    .max(b.abs());
                let tol = settings.tolerance(scene, &s.name);
                (tol.accepts(*a, *b, peak), relative_change(*a, *b, peak))
            }
            (a, b) => (a == b, None),
        };
        if !pass {
            out.differences.push(Difference {
                quantity: s.name.clone(),
                old: show(Some(&s.value)),
                new: show(Some(&n.value)),
                relative,
                place: {
                    let (now, then) = (place(n.time, n.position), place(s.time, s.position));
                    if now == then || then.is_empty() {
                        now
                    } else {
                        format!("{now} (golden: {then})")
                    }
                },
                cells: 1,
            });
        }
    }
    let old_names: std::collections::BTreeSet<&str> =
        old.scalars.iter().map(|s| s.name.as_str()).collect();
    for n in &new.scalars {
        if !old_names.contains(n.name.as_str()) {
            out.differences.push(Difference {
                quantity: n.name.clone(),
                old: "(absent)".into(),
                new: show(Some(&n.value)),
                relative: None,
                place: String::new(),
                cells: 1,
            });
        }
    }
}

fn relative_change(old: f64, new: f64, peak: f64) -> Option<f64> {
    (peak > 0.0 && peak.is_finite()).then(|| (new - old).abs() / peak)
}

/// The header of a history column without its `_max` / `_min` suffix
/// (`midspan_max [m]` → `midspan [m]`): the two columns of one record
/// share a peak.
fn column_base(header: &str) -> String {
    let (name, unit) = match header.split_once(" [") {
        Some((name, unit)) => (name, Some(unit)),
        None => (header, None),
    };
    let base = name
        .strip_suffix("_max")
        .or_else(|| name.strip_suffix("_min"))
        .unwrap_or(name);
    match unit {
        Some(unit) => format!("{base} [{unit}"),
        None => base.to_string(),
    }
}

/// Where row `r` of `table` is: a history bin's time span, else the
/// row's first cell, its speed and its texts.
pub fn row_place(table: &Table, r: usize) -> String {
    let Some(row) = table.rows.get(r) else {
        return String::new();
    };
    if table.name == "history"
        && let (Some(a), Some(b)) = (row[0].number(), row.get(1).and_then(Cell::number))
    {
        return format!("t = {a:.6} … {b:.6} s");
    }
    let mut parts = vec![format!("row {}", r + 1)];
    // A binned study envelope: its case, then its bin's time span.
    let span = bin_span(table);
    for (c, (h, cell)) in table.header.iter().zip(row).enumerate() {
        if span.is_some_and(|(a, b)| c == a || c == b) {
            continue;
        }
        let key = c == 0 || h.contains("speed") || matches!(cell, Cell::Exact(_));
        if key && !matches!(cell, Cell::Empty) {
            let value = match cell {
                Cell::Number(x) => crate::report::number(*x),
                other => show(Some(other)),
            };
            parts.push(format!("{h} = {value}"));
        }
    }
    if let Some((a, b)) = span
        && let (Some(a), Some(b)) = (row[a].number(), row.get(b).and_then(Cell::number))
    {
        parts.push(format!("t = {a:.6} … {b:.6} s"));
    }
    parts.join(", ")
}

/// The columns `time_from [s]` and `time_to [s]` of a table binned in
/// time (the history, a study's envelopes), if it has both.
pub fn bin_span(table: &Table) -> Option<(usize, usize)> {
    let at = |name: &str| table.header.iter().position(|h| h == name);
    Some((at("time_from [s]")?, at("time_to [s]")?))
}

fn compare_table(scene: &str, old: &Table, new: &Table, settings: &Settings, out: &mut Comparison) {
    let label = |h: &str| format!("{}: {h}", old.name);
    for h in &old.header {
        if !new.header.contains(h) {
            out.differences.push(Difference {
                quantity: label(h),
                old: "column".into(),
                new: "(absent)".into(),
                relative: None,
                place: String::new(),
                cells: 1,
            });
        }
    }
    for h in &new.header {
        if !old.header.contains(h) {
            out.differences.push(Difference {
                quantity: label(h),
                old: "(absent)".into(),
                new: "column".into(),
                relative: None,
                place: String::new(),
                cells: 1,
            });
        }
    }
    if old.rows.len() != new.rows.len() {
        out.differences.push(Difference {
            quantity: format!("table {}", old.name),
            old: format!("{} rows", old.rows.len()),
            new: format!("{} rows", new.rows.len()),
            relative: None,
            place: String::new(),
            cells: 1,
        });
        return;
    }
    // Peak of each column group (a history record's max and min columns
    // together), over old and new.
    let peak_of = |base: &String| -> f64 {
        let mut peak: f64 = 0.0;
        for t in [old, new] {
            for (c, h) in t.header.iter().enumerate() {
                if column_base(h) == *base {
                    for x in t.column(c).into_iter().flatten() {
                        if x.is_finite() {
                            peak = peak.max(x.abs());
                        }
                    }
                }
            }
        }
        peak
    };
    for (c, h) in old.header.iter().enumerate() {
        let Some(nc) = new.header.iter().position(|n| n == h) else {
            continue;
        };
        let peak = peak_of(&column_base(h));
        let tol = settings.tolerance(scene, h);
        // The worst failing cell: the largest change beyond tolerance.
        let mut worst: Option<(usize, f64)> = None;
        let mut failing = 0;
        for (r, (orow, nrow)) in old.rows.iter().zip(&new.rows).enumerate() {
            let (a, b) = (&orow[c], &nrow[nc]);
            let (pass, size) = match (a, b) {
                (Cell::Number(x), Cell::Number(y)) => (tol.accepts(*x, *y, peak), (y - x).abs()),
                (x, y) => (x == y, f64::INFINITY),
            };
            if !pass {
                failing += 1;
                if worst.is_none_or(|(_, w)| size > w || w.is_nan()) {
                    worst = Some((r, size));
                }
            }
        }
        if let Some((r, _)) = worst {
            let (a, b) = (&old.rows[r][c], &new.rows[r][nc]);
            out.differences.push(Difference {
                quantity: label(h),
                old: show(Some(a)),
                new: show(Some(b)),
                relative: match (a, b) {
                    (Cell::Number(x), Cell::Number(y)) => relative_change(*x, *y, peak),
                    _ => None,
                },
                place: row_place(new, r),
                cells: failing,
            });
            out.changed_columns.push(ChangedColumn {
                table: old.name.clone(),
                column: c,
            });
        }
    }
}

/// A line diff of two texts (longest common subsequence), as `-`/`+`
/// lines with two lines of context around each change; at most
/// `max_lines` lines are returned. Texts of more than 4000 lines are
/// compared line by line at the same index instead.
pub fn line_diff(old: &str, new: &str, max_lines: usize) -> Vec<String> {
    let a: Vec<&str> = old.lines().collect();
    let b: Vec<&str> = new.lines().collect();
    // (tag, line): ' ' same, '-' removed, '+' added.
    let mut ops: Vec<(char, &str)> = Vec::new();
    if a.len() > 4000 || b.len() > 4000 {
        for i in 0..a.len().max(b.len()) {
            match (a.get(i).copied(), b.get(i).copied()) {
                (Some(x), Some(y)) if x == y => ops.push((' ', x)),
                (x, y) => {
                    if let Some(x) = x {
                        ops.push(('-', x));
                    }
                    if let Some(y) = y {
                        ops.push(('+', y));
                    }
                }
            }
        }
    } else {
        let (n, m) = (a.len(), b.len());
        let mut lcs = vec![0u32; (n + 1) * (m + 1)];
        let at = |i: usize, j: usize| i * (m + 1) + j;
        for i in (0..n).rev() {
            for j in (0..m).rev() {
                lcs[at(i, j)] = if a[i] == b[j] {
                    lcs[at(i + 1, j + 1)] + 1
                } else {
                    lcs[at(i + 1, j)].max(lcs[at(i, j + 1)])
                };
            }
        }
        let (mut i, mut j) = (0, 0);
        while i < n || j < m {
            if i < n && j < m && a[i] == b[j] {
                ops.push((' ', a[i]));
                i += 1;
                j += 1;
            } else if i < n && (j == m || lcs[at(i + 1, j)] >= lcs[at(i, j + 1)]) {
                ops.push(('-', a[i]));
                i += 1;
            } else {
                ops.push(('+', b[j]));
                j += 1;
            }
        }
    }
    let near_change = |k: usize| {
        let lo = k.saturating_sub(2);
        let hi = (k + 3).min(ops.len());
        ops[lo..hi].iter().any(|(t, _)| *t != ' ')
    };
    let mut out = Vec::new();
    let mut gap = false;
    for (k, (tag, line)) in ops.iter().enumerate() {
        if near_change(k) {
            if gap && !out.is_empty() {
                out.push("  …".to_string());
            }
            gap = false;
            out.push(format!("{tag} {line}"));
        } else {
            gap = true;
        }
        if out.len() >= max_lines {
            out.push("  … (diff cut)".into());
            break;
        }
    }
    out
}
