//! Advice as data: what vbi knows about a scene or a result that is valid
//! but probably not what was meant (a warning), or worth knowing (a note).
//!
//! Every warning the plan, a run or a study makes is an [`Advice`] value with
//! a stable [`Kind`] id, a severity, a location where one exists, the
//! message, a `help` that says what to change, and the measured figures as
//! fields. The library makes them and carries them in its results
//! (`summary.json`'s `advice`, each study point, regression records, the
//! convergence report); only the front ends print them. The ids are listed
//! in [`KINDS`], from which `docs/advice.md` is generated.
//!
//! A scene may silence an id with a reason (`allow: [{id, reason}]`): the
//! advice is still made and kept in the outputs, marked with the reason
//! ([`Advice::allowed`]), and no longer counts as a warning.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

mod kinds;
pub use kinds::*;

/// How much a piece of advice matters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    /// Worth knowing; never fails a run, even with `--deny-warnings`.
    Note,
    /// The result is probably not what was meant, or not converged: a run
    /// with `--deny-warnings` (Python: `strict=True`) fails on it.
    Warning,
}

impl Severity {
    /// The word the front ends print before the message.
    pub fn word(self) -> &'static str {
        match self {
            Severity::Note => "note",
            Severity::Warning => "warning",
        }
    }
}

/// One kind of advice: its id and its documentation (`docs/advice.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Kind {
    /// Stable kebab-case id (`acceleration-filter-above-modes`): what a
    /// scene's `allow` names and tools match on. Never renamed.
    pub id: &'static str,
    /// Its severity.
    pub severity: Severity,
    /// One line: what it says.
    pub meaning: &'static str,
    /// Why it matters for the result.
    pub why: &'static str,
    /// How to act on it.
    pub fix: &'static str,
    /// A scene (YAML) that draws it, or a description of one.
    pub example: &'static str,
}

/// One piece of advice about a scene or a result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Advice {
    /// The kind's stable id ([`Kind::id`]).
    pub id: String,
    /// Warning or note.
    pub severity: Severity,
    /// Where the cause is: `file:line:col`, or a key path
    /// (`record.midspan`, `vehicles[1].speed`), when one exists.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub location: Option<String>,
    /// What vbi found, in a sentence or two.
    pub message: String,
    /// What to change or type.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub help: Option<String>,
    /// The measured figures the message quotes, by name (SI units, the name
    /// saying which: `filter_hz`, `share_left_out`, `time_s`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub figures: BTreeMap<String, f64>,
    /// The scene's reason for allowing this id (`allow: [{id, reason}]`):
    /// set, the advice no longer counts as a warning.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub allowed: Option<String>,
    /// In a study's advice: the points (runs) it was made at, in study
    /// order, labelled as the study table labels them; the message and
    /// figures are those of the first. Empty for a single run.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<String>,
}

impl Advice {
    /// Advice of `kind` saying `message`.
    pub fn new(kind: &Kind, message: impl Into<String>) -> Advice {
        Advice {
            id: kind.id.to_string(),
            severity: kind.severity,
            location: None,
            message: message.into(),
            help: None,
            figures: BTreeMap::new(),
            allowed: None,
            points: Vec::new(),
        }
    }

    /// With what to change.
    pub fn help(mut self, help: impl Into<String>) -> Advice {
        self.help = Some(help.into());
        self
    }

    /// With where the cause is.
    pub fn at(mut self, location: impl Into<String>) -> Advice {
        self.location = Some(location.into());
        self
    }

    /// With a measured figure (non-finite figures are left out: JSON has
    /// no place for them).
    pub fn figure(mut self, name: &str, value: f64) -> Advice {
        if value.is_finite() {
            self.figures.insert(name.to_string(), value);
        }
        self
    }

    /// A warning that counts: not a note and not allowed by the scene.
    pub fn is_denied_warning(&self) -> bool {
        self.severity == Severity::Warning && self.allowed.is_none()
    }

    /// The message with its help, as the command line prints it after
    /// `warning: FILE: `.
    pub fn text(&self) -> String {
        let mut text = self.message.clone();
        if let Some(help) = &self.help {
            text.push_str("; ");
            text.push_str(help);
        }
        match self.points.as_slice() {
            [] => {}
            [one] => text.push_str(&format!(" (at {one})")),
            [first, rest @ ..] => text.push_str(&format!(
                " (at {first} and {} more point{}: summary.json lists them)",
                rest.len(),
                if rest.len() == 1 { "" } else { "s" }
            )),
        }
        text
    }
}

/// A scene's permission to leave one advice id unheeded, with its reason.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Allow {
    /// The advice id ([`Kind::id`]).
    pub id: String,
    /// Why the advice does not apply to this scene: kept in the outputs.
    pub reason: String,
}

/// Marks every piece of `advice` whose id `allow` names with its reason.
pub fn apply_allow(advice: &mut [Advice], allow: &[Allow]) {
    for a in advice {
        if let Some(rule) = allow.iter().find(|rule| rule.id == a.id) {
            a.allowed = Some(rule.reason.clone());
        }
    }
}

/// The kind of this id, if it is one.
pub fn kind(id: &str) -> Option<&'static Kind> {
    KINDS.iter().find(|k| k.id == id)
}

/// How many pieces of `advice` are warnings that count
/// ([`Advice::is_denied_warning`]).
pub fn denied_warnings(advice: &[Advice]) -> usize {
    advice.iter().filter(|a| a.is_denied_warning()).count()
}

/// A study's advice from its points' (label, advice) in study order, after
/// the study's own (`scene`, made once for the whole study): one entry per
/// id, the first point's message and figures, every point it was made at
/// in [`Advice::points`].
pub fn gather<'a>(
    scene: Vec<Advice>,
    points: impl IntoIterator<Item = (String, &'a [Advice])>,
) -> Vec<Advice> {
    let mut out = scene;
    let own = out.len();
    for (label, advice) in points {
        for a in advice {
            match out[own..].iter_mut().find(|o| o.id == a.id) {
                Some(o) => o.points.push(label.clone()),
                None => {
                    let mut first = a.clone();
                    first.points = vec![label.clone()];
                    out.push(first);
                }
            }
        }
    }
    out
}

/// Each piece of `advice` as the command line prints it ([`Advice::text`]).
pub fn texts(advice: &[Advice]) -> Vec<String> {
    advice.iter().map(Advice::text).collect()
}

/// `docs/advice.md`: every advice id with its meaning, why it matters, how
/// to fix it and an example (generated; a test keeps the committed file
/// equal).
pub fn reference_markdown() -> String {
    let mut out = String::from(
        "# Advice reference\n\n\
         <!-- Generated from src/advice/kinds.rs by `vbi advice --markdown`; \
         tests/it/advice.rs keeps it equal. -->\n\n\
         Every warning and note vbi makes has a stable id. The ids appear in `summary.json` \
         (`advice`), in Python (`result.advice`, and as `vbi.VbiWarning`), in each study \
         point, in regression records and in `vbi converge`'s report. A warning fails the \
         run under `--deny-warnings` (exit code 4; Python `strict=True`) unless the scene \
         allows it with a reason:\n\n\
         ```yaml\nallow:\n  - {id: run-ends-at-peak, reason: \"free vibration is not of interest here\"}\n```\n\n\
         | id | severity | what it says |\n|---|---|---|\n",
    );
    let mut kinds: Vec<&Kind> = KINDS.iter().collect();
    kinds.sort_by_key(|k| k.id);
    for k in &kinds {
        out.push_str(&format!(
            "| [`{}`](#{}) | {} | {} |\n",
            k.id,
            k.id,
            k.severity.word(),
            k.meaning
        ));
    }
    for k in kinds {
        out.push_str(&format!(
            "\n## {}\n\n**{}.** {}\n\n**Why it matters.** {}\n\n**How to fix it.** {}\n\n\
             **Example.** {}\n",
            k.id,
            k.severity.word(),
            k.meaning,
            k.why,
            k.fix,
            k.example
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_kebab_case_and_documented() {
        let mut seen = std::collections::BTreeSet::new();
        for k in KINDS {
            assert!(seen.insert(k.id), "{} twice", k.id);
            assert!(
                k.id.chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
                    && !k.id.starts_with('-')
                    && !k.id.ends_with('-'),
                "{} is not kebab-case",
                k.id
            );
            for text in [k.meaning, k.why, k.fix, k.example] {
                assert!(!text.trim().is_empty(), "{} lacks a text", k.id);
            }
        }
    }

    #[test]
    fn an_allowed_warning_no_longer_counts() {
        let mut advice = vec![
            Advice::new(&RUN_ENDS_AT_PEAK, "a"),
            Advice::new(&IMPLAUSIBLE_SPEED, "b"),
        ];
        assert_eq!(denied_warnings(&advice), 2);
        apply_allow(
            &mut advice,
            &[Allow {
                id: RUN_ENDS_AT_PEAK.id.into(),
                reason: "free vibration not of interest".into(),
            }],
        );
        assert_eq!(denied_warnings(&advice), 1);
        assert_eq!(
            advice[0].allowed.as_deref(),
            Some("free vibration not of interest")
        );
    }

    #[test]
    fn non_finite_figures_are_left_out() {
        let a = Advice::new(&RUN_ENDS_AT_PEAK, "a")
            .figure("time_s", f64::NAN)
            .figure("x_m", 1.5);
        assert_eq!(a.figures.len(), 1);
        let json = serde_json::to_string(&a).unwrap();
        assert!(json.contains("\"x_m\":1.5"), "{json}");
    }
}
