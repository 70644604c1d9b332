//! What `vbi regress check` tells its reader: the text report (which
//! scenes passed; for each failure the quantity, old and new value,
//! relative change and where), the plots of old against new for each
//! changed column, and JUnit XML for CI dashboards.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::compare::ChangedColumn;
use super::record::{Record, Table};
use super::{SceneCheck, Verdict};
use crate::report::plot::{Panel, PlotError, Series, history_chart};

/// Differences listed per scene in the text report (the JUnit failure
/// text lists the same).
const LISTED: usize = 25;

/// Counts of the verdicts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tally {
    /// Scenes that passed.
    pub passed: usize,
    /// Scenes whose scene or results changed.
    pub changed: usize,
    /// Scenes that could not run.
    pub could_not_run: usize,
}

impl Tally {
    /// The counts of `checks`.
    pub fn of(checks: &[SceneCheck]) -> Self {
        let mut t = Tally::default();
        for c in checks {
            match c.verdict {
                Verdict::Pass => t.passed += 1,
                Verdict::Changed => t.changed += 1,
                Verdict::CouldNotRun(_) => t.could_not_run += 1,
            }
        }
        t
    }
}

/// One line saying what changed in a changed scene.
pub fn headline(check: &SceneCheck) -> String {
    let Some(c) = &check.comparison else {
        return String::new();
    };
    let results = if c.results_pass() {
        "results within tolerance"
    } else {
        "results changed"
    };
    let mut line = if c.scene_changed {
        format!("the scene changed (its resolved diff first), {results}")
    } else {
        format!("{results}, the scene is unchanged")
    };
    if let Some((old, new)) = &c.version_changed {
        let _ = write!(line, "; vbi {old} → {new}");
    }
    line
}

/// The details of one scene's failure: the scene's resolved diff (the
/// cause, when the scene changed), then its differences.
pub fn details(check: &SceneCheck) -> Vec<String> {
    let mut lines = Vec::new();
    match &check.verdict {
        Verdict::Pass => {}
        Verdict::CouldNotRun(why) => lines.push(why.clone()),
        Verdict::Changed => {
            let Some(c) = &check.comparison else {
                return lines;
            };
            // The cause first (issue 40.7): a changed scene explains the
            // quantities that follow, so its diff is not buried under them.
            if !check.scene_diff.is_empty() {
                lines.push("resolved scene, approved (-) against now (+):".into());
                lines.extend(check.scene_diff.iter().map(|l| format!("  {l}")));
            }
            for d in c.differences.iter().take(LISTED) {
                let mut line = format!("{}: {} → {}", d.quantity, d.old, d.new);
                if let Some(r) = d.relative {
                    let _ = write!(line, " ({:+.3e} of its peak)", signed(d, r));
                }
                if !d.place.is_empty() {
                    let _ = write!(line, " at {}", d.place);
                }
                if d.cells > 1 {
                    let _ = write!(line, " [{} cells beyond tolerance]", d.cells);
                }
                lines.push(line);
            }
            if c.differences.len() > LISTED {
                lines.push(format!(
                    "… and {} more quantities",
                    c.differences.len() - LISTED
                ));
            }
        }
    }
    lines
}

/// The relative change with the sign of new − old.
fn signed(d: &super::compare::Difference, r: f64) -> f64 {
    match (d.old.parse::<f64>(), d.new.parse::<f64>()) {
        (Ok(a), Ok(b)) if b < a => -r,
        _ => r,
    }
}

/// The text report of `checks`, with the plots `plots` named under each
/// scene.
pub fn text(checks: &[SceneCheck], plots: &[(String, PathBuf)]) -> String {
    let mut out = String::new();
    for check in checks {
        let (tag, head) = match &check.verdict {
            Verdict::Pass => ("PASS ", String::new()),
            Verdict::Changed => ("FAIL ", format!(": {}", headline(check))),
            Verdict::CouldNotRun(_) => ("ERROR", ": could not run".into()),
        };
        let _ = writeln!(out, "{tag} {}{head}", check.key);
        for line in details(check) {
            let _ = writeln!(out, "      {line}");
        }
        for (key, path) in plots {
            if *key == check.key {
                let _ = writeln!(out, "      plot: {}", path.display());
            }
        }
    }
    let t = Tally::of(checks);
    let _ = writeln!(
        out,
        "{} scene{}: {} passed, {} changed, {} could not run",
        checks.len(),
        if checks.len() == 1 { "" } else { "s" },
        t.passed,
        t.changed,
        t.could_not_run
    );
    // Names and values come from scene files and stored records, which may
    // be someone else's: no control character reaches the terminal.
    crate::guarded_file::escape_controls(&out)
}

/// Text safe inside an XML attribute or element: the five entities
/// escaped, control characters other than tab and line break and the
/// non-characters U+FFFE/U+FFFF written as escapes (XML 1.0 forbids them).
pub fn xml_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' => out.push(c),
            // Shown as Rust writes them (`\u{1b}`): XML 1.0 forbids the C0
            // controls and U+FFFE/U+FFFF, and the others repaint a terminal
            // that shows the log.
            c if c.is_control() || matches!(c, '\u{fffe}' | '\u{ffff}') => {
                out.extend(c.escape_debug());
            }
            c => out.push(c),
        }
    }
    out
}

/// The checks as JUnit XML (the Ant/Jenkins layout that GitHub, GitLab
/// and Jenkins read): one `testsuite` "vbi regress", one `testcase` per
/// scene; a changed scene holds a `failure`, a scene that could not run an
/// `error`, each with a `message` and the details as text.
pub fn junit(checks: &[SceneCheck]) -> String {
    let t = Tally::of(checks);
    let total: f64 = checks.iter().map(|c| c.seconds).sum();
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let counts = format!(
        "tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{total:.3}\"",
        checks.len(),
        t.changed,
        t.could_not_run
    );
    let _ = writeln!(out, "<testsuites name=\"vbi regress\" {counts}>");
    let _ = writeln!(
        out,
        "  <testsuite name=\"vbi regress\" {counts} skipped=\"0\">"
    );
    for check in checks {
        let open = format!(
            "    <testcase classname=\"vbi.regress\" name=\"{}\" file=\"{}\" time=\"{:.3}\"",
            xml_escape(&check.key),
            xml_escape(&check.file.display().to_string()),
            check.seconds
        );
        let body = xml_escape(&details(check).join("\n"));
        match &check.verdict {
            Verdict::Pass => {
                let _ = writeln!(out, "{open}/>");
            }
            Verdict::Changed => {
                let _ = writeln!(
                    out,
                    "{open}>\n      <failure type=\"changed\" message=\"{}\">{body}</failure>\n    </testcase>",
                    xml_escape(&headline(check))
                );
            }
            Verdict::CouldNotRun(why) => {
                let first = why.lines().next().unwrap_or_default();
                let _ = writeln!(
                    out,
                    "{open}>\n      <error type=\"could-not-run\" message=\"{}\">{body}</error>\n    </testcase>",
                    xml_escape(first)
                );
            }
        }
    }
    out.push_str("  </testsuite>\n</testsuites>\n");
    out
}

/// A file name made of `text`: letters, digits, `-` and `.` kept, every
/// run of other characters one `_`.
fn file_name(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let c = if c.is_ascii_alphanumeric() || matches!(c, '-' | '.') {
            c
        } else {
            '_'
        };
        if !(c == '_' && out.ends_with('_')) {
            out.push(c);
        }
    }
    out.trim_matches('_').to_string()
}

/// The x axis of a table's plot: a history or envelope bin's mid time
/// (each case of a study's envelopes in turn), a study row's
/// speed (the first column with `speed` in its name), else the first
/// numeric column, else the row number.
fn abscissa(table: &Table) -> (String, Vec<f64>) {
    if let Some((from, to)) = super::compare::bin_span(table) {
        let x = table
            .rows
            .iter()
            .map(|r| match (r[from].number(), r[to].number()) {
                (Some(a), Some(b)) => 0.5 * (a + b),
                _ => f64::NAN,
            })
            .collect();
        return ("time (s)".into(), x);
    }
    let numeric = |c: usize| table.column(c).iter().all(Option::is_some);
    let pick = table
        .header
        .iter()
        .enumerate()
        .find(|(c, h)| h.contains("speed") && numeric(*c))
        .or_else(|| table.header.iter().enumerate().find(|(c, _)| numeric(*c)));
    match pick {
        Some((c, h)) => (
            h.clone(),
            table
                .column(c)
                .into_iter()
                .map(|v| v.unwrap_or(f64::NAN))
                .collect(),
        ),
        None => (
            "row".into(),
            (1..=table.rows.len()).map(|r| r as f64).collect(),
        ),
    }
}

/// Writes one PNG per changed column of a changed scene into
/// `out/<scene>/`: the golden values and the new ones against time (a
/// history) or the row's speed (a study table), and under them their
/// difference, new − golden, in the column's unit. The paths written, with
/// their scene's key.
pub fn write_plots(checks: &[SceneCheck], out: &Path) -> Result<Vec<(String, PathBuf)>, PlotError> {
    let mut written = Vec::new();
    for check in checks {
        let (Some(c), Some((old, new))) = (&check.comparison, &check.records) else {
            continue;
        };
        for changed in &c.changed_columns {
            if let Some(path) = plot_column(out, &check.key, old, new, changed)? {
                written.push((check.key.clone(), path));
            }
        }
    }
    Ok(written)
}

fn plot_column(
    out: &Path,
    key: &str,
    old: &Record,
    new: &Record,
    changed: &ChangedColumn,
) -> Result<Option<PathBuf>, PlotError> {
    let find = |r: &Record| r.tables.iter().find(|t| t.name == changed.table).cloned();
    let (Some(old_t), Some(new_t)) = (find(old), find(new)) else {
        return Ok(None);
    };
    let header = &old_t.header[changed.column];
    let Some(new_c) = new_t.header.iter().position(|h| h == header) else {
        return Ok(None);
    };
    let values = |t: &Table, c: usize| -> Vec<f64> {
        t.column(c)
            .into_iter()
            .map(|v| v.unwrap_or(f64::NAN))
            .collect()
    };
    let (old_y, new_y) = (values(&old_t, changed.column), values(&new_t, new_c));
    if old_y.iter().all(|v| v.is_nan()) && new_y.iter().all(|v| v.is_nan()) {
        return Ok(None);
    }
    let (x_label, old_x) = abscissa(&old_t);
    let (_, new_x) = abscissa(&new_t);
    let folder = out.join(file_name(key));
    std::fs::create_dir_all(&folder).map_err(|source| PlotError::Io {
        path: folder.clone(),
        source,
    })?;
    let path = folder.join(format!(
        "{}-{}.png",
        file_name(&changed.table),
        file_name(header)
    ));
    // The difference new − old on a panel of its own under the two
    // curves (issue 40.7): curves that agree lie on top of each other, so
    // without it a change below a line width is invisible and a pass looks
    // like a missing line. Row by row, so only when the rows align (the
    // comparison reports a changed row count by itself).
    let difference: Option<Vec<f64>> = (old_y.len() == new_y.len()
        && old_x.len() == new_x.len()
        && old_x
            .iter()
            .zip(&new_x)
            .all(|(a, b)| a == b || (a.is_nan() && b.is_nan())))
    .then(|| old_y.iter().zip(&new_y).map(|(a, b)| b - a).collect());
    let unit = header
        .split_once(" [")
        .and_then(|(_, u)| u.strip_suffix(']'))
        .unwrap_or("");
    let mut panels = vec![Panel {
        y_label: header.clone(),
        unit: unit.into(),
        series: vec![
            Series {
                label: "golden (approved)",
                x: &old_x,
                y: &old_y,
            },
            Series {
                label: "new",
                x: &new_x,
                y: &new_y,
            },
        ],
        references: Vec::new(),
    }];
    if let Some(d) = &difference {
        panels.push(Panel {
            y_label: if unit.is_empty() {
                "new − golden".into()
            } else {
                format!("new − golden [{unit}]")
            },
            unit: unit.into(),
            series: vec![Series {
                label: "difference (new − golden)",
                x: &old_x,
                y: d,
            }],
            references: Vec::new(),
        });
    }
    history_chart(&path, &format!("{key}: {header}"), &x_label, &panels, &[])?;
    Ok(Some(path))
}
