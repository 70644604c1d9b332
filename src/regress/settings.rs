//! `regress.yaml` in the store: the tolerances of `vbi regress check`, for
//! every scene, per scene and per quantity, and the history resolution of
//! `approve`. The scene files are not touched: a store is the user's, the
//! scenes may be shared.
//!
//! ```yaml
//! relative: 1.0e-5        # of the quantity's peak (default 1e-5)
//! absolute: 1.0e-12       # in the quantity's SI unit (default 1e-12)
//! history_bins: 200       # bins of the recorded history (approve)
//! quantities:             # for every scene
//!   midspan_acceleration: { relative: 1.0e-4 }
//! scenes:
//!   my-viaduct:           # the scene file's stem
//!     relative: 1.0e-4
//!     quantities:
//!       deck_acceleration: { relative: 1.0e-3, absolute: 1.0e-6 }
//! ```
//!
//! A quantity key names a record (`midspan`: its history columns and every
//! scalar under `quantities.midspan`), a study table's column (`daf_span1`)
//! or a whole scalar path (`run.frequencies.0`). The most specific setting
//! wins: scene quantity, scene, quantity, file default, built-in default.

use std::path::Path;

use crate::scenario::yaml::{self, Node, NodeKind, Resolved};

/// Built-in relative tolerance: 1e-5 of the quantity's peak. Round-off
/// differences between machines and compilers move results by about
/// 1e-12 relative (1e-9 on long or contact runs); a 0.1 % change of a
/// stiffness or mass moves a response by some 1e-4 to 1e-3.
pub const DEFAULT_RELATIVE: f64 = 1e-5;
/// Built-in absolute floor, in the quantity's SI unit: a quantity that is
/// zero in the record passes a round-off value.
pub const DEFAULT_ABSOLUTE: f64 = 1e-12;
/// The file's name in the store.
pub const FILE_NAME: &str = "regress.yaml";

/// A tolerance: a difference passes when
/// `|new − old| ≤ max(relative × peak, absolute)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Fraction of the quantity's peak |value| (old or new).
    pub relative: f64,
    /// Floor, in the quantity's SI unit.
    pub absolute: f64,
}

impl Default for Tolerance {
    fn default() -> Self {
        Tolerance {
            relative: DEFAULT_RELATIVE,
            absolute: DEFAULT_ABSOLUTE,
        }
    }
}

impl Tolerance {
    /// Whether `old` and `new` agree, the quantity's peak being `peak`.
    pub fn accepts(&self, old: f64, new: f64, peak: f64) -> bool {
        if old.is_nan() || new.is_nan() {
            return old.is_nan() && new.is_nan();
        }
        if old == new {
            return true;
        }
        // An infinite value matches only itself: its tolerance, relative to
        // an infinite peak, would pass anything (issue 39: a forged `inf`
        // golden scalar passed every new value).
        if !old.is_finite() || !new.is_finite() || !peak.is_finite() {
            return false;
        }
        (new - old).abs() <= (self.relative * peak).max(self.absolute)
    }
}

/// An override: either part may be left to the less specific setting.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Partial {
    relative: Option<f64>,
    absolute: Option<f64>,
}

impl Partial {
    fn apply(&self, to: &mut Tolerance) {
        if let Some(r) = self.relative {
            to.relative = r;
        }
        if let Some(a) = self.absolute {
            to.absolute = a;
        }
    }
}

#[derive(Debug, Clone, Default, PartialEq)]
struct SceneSettings {
    tolerance: Partial,
    quantities: Vec<(String, Partial)>,
}

/// The settings of a store.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    default: Tolerance,
    quantities: Vec<(String, Partial)>,
    scenes: Vec<(String, SceneSettings)>,
    /// Bins of the decimated history in a record.
    pub history_bins: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            default: Tolerance::default(),
            quantities: Vec::new(),
            scenes: Vec::new(),
            history_bins: super::record::DEFAULT_HISTORY_BINS,
        }
    }
}

/// Whether the quantity key `key` names the item known by `names` (its
/// scalar path or its column header): the whole name, one of its
/// `.`-separated parts, or the header without its unit and `max`/`min`.
pub fn names(key: &str, name: &str) -> bool {
    if name == key || name.split('.').any(|part| part == key) {
        return true;
    }
    // A table column `midspan [m]`, or a history bin's `midspan_max [m]`
    // and `midspan_min [m]`, belongs to the record `midspan`.
    let base = name.split(" [").next().unwrap_or(name);
    base == key
        || base
            .strip_suffix("_max")
            .or_else(|| base.strip_suffix("_min"))
            == Some(key)
}

/// The largest `regress.yaml` read, bytes (a settings file is a few
/// hundred; a link to `/dev/zero` or a huge file is refused unread).
pub const MAX_SETTINGS_BYTES: u64 = 1 << 20;

impl Settings {
    /// The tolerance of the item `name` of scene `scene`.
    pub fn tolerance(&self, scene: &str, name: &str) -> Tolerance {
        let mut tol = self.default;
        let apply_keyed = |list: &[(String, Partial)], tol: &mut Tolerance| {
            for (key, partial) in list {
                if names(key, name) {
                    partial.apply(tol);
                }
            }
        };
        apply_keyed(&self.quantities, &mut tol);
        if let Some((_, s)) = self.scenes.iter().find(|(k, _)| k == scene) {
            s.tolerance.apply(&mut tol);
            apply_keyed(&s.quantities, &mut tol);
        }
        tol
    }

    /// Reads `regress.yaml` from the store `store`; the defaults when the
    /// file does not exist.
    pub fn load(store: &Path) -> Result<Self, String> {
        use crate::guarded_file as guarded;
        let path = store.join(FILE_NAME);
        let text = match guarded::no_link(&path)
            .and_then(|()| guarded::read_text_bounded(&path, MAX_SETTINGS_BYTES))
        {
            Ok(t) => t,
            Err(e) if e.is_not_found() => return Ok(Settings::default()),
            Err(e) => return Err(e.to_string()),
        };
        Self::parse(&text).map_err(|(loc, m)| format!("{}:{loc}: {m}", guarded::shown(&path)))
    }

    /// Parses the text of a `regress.yaml`; the error carries line:column.
    pub fn parse(text: &str) -> Result<Self, (yaml::Location, String)> {
        let mut settings = Settings::default();
        let Some(root) = yaml::parse(text).map_err(|e| (e.loc, e.message))? else {
            return Ok(settings);
        };
        for (key, (at, value)) in mapping(&root)? {
            match key {
                "relative" => settings.default.relative = tolerance_value(value)?,
                "absolute" => settings.default.absolute = tolerance_value(value)?,
                "history_bins" => settings.history_bins = bins(value)?,
                "quantities" => settings.quantities = quantities(value)?,
                "scenes" => {
                    for (scene, (_, body)) in mapping(value)? {
                        let mut s = SceneSettings::default();
                        for (k, (k_at, v)) in mapping(body)? {
                            match k {
                                "quantities" => s.quantities = quantities(v)?,
                                _ => partial_key(&mut s.tolerance, k, v, k_at)?,
                            }
                        }
                        settings.scenes.push((scene.to_string(), s));
                    }
                }
                other => {
                    return Err((
                        at,
                        format!(
                            "unknown key `{}` (expected relative, absolute, history_bins, \
                             quantities, scenes)",
                            crate::guarded_file::excerpt(other, 40)
                        ),
                    ));
                }
            }
        }
        Ok(settings)
    }
}

type Located = (yaml::Location, String);
type Keyed<'a> = (yaml::Location, &'a Node);

/// The (key, value) pairs of a mapping with text keys, each value given as
/// the key node's location and the value node.
fn mapping(node: &Node) -> Result<Vec<(&str, Keyed<'_>)>, Located> {
    let NodeKind::Mapping(pairs) = &node.kind else {
        return Err((node.loc, "expected a mapping".into()));
    };
    pairs
        .iter()
        .map(|(k, v)| match &k.kind {
            NodeKind::Scalar { text, .. } => Ok((text.as_str(), (k.loc, v))),
            _ => Err((k.loc, "expected a text key".into())),
        })
        .collect()
}

fn number(node: &Node) -> Option<f64> {
    match &node.kind {
        NodeKind::Scalar { text, plain: true } => match yaml::resolve_plain(text) {
            Resolved::Float(x) => Some(x),
            Resolved::Int(i) => Some(i as f64),
            _ => None,
        },
        _ => None,
    }
}

fn tolerance_value(node: &Node) -> Result<f64, Located> {
    match number(node) {
        Some(x) if x.is_finite() && x >= 0.0 => Ok(x),
        _ => Err((node.loc, "expected a number ≥ 0".into())),
    }
}

fn bins(node: &Node) -> Result<usize, Located> {
    match number(node) {
        Some(x) if x.fract() == 0.0 && (2.0..=100_000.0).contains(&x) => Ok(x as usize),
        _ => Err((
            node.loc,
            "history_bins: expected a whole number from 2 to 100000".into(),
        )),
    }
}

fn partial_key(
    p: &mut Partial,
    key: &str,
    value: &Node,
    at: yaml::Location,
) -> Result<(), Located> {
    match key {
        "relative" => p.relative = Some(tolerance_value(value)?),
        "absolute" => p.absolute = Some(tolerance_value(value)?),
        other => {
            return Err((
                at,
                format!(
                    "unknown key `{}` (expected relative, absolute)",
                    crate::guarded_file::excerpt(other, 40)
                ),
            ));
        }
    }
    Ok(())
}

fn quantities(node: &Node) -> Result<Vec<(String, Partial)>, Located> {
    mapping(node)?
        .into_iter()
        .map(|(key, (_, body))| {
            let mut p = Partial::default();
            for (k, (k_at, v)) in mapping(body)? {
                partial_key(&mut p, k, v, k_at)?;
            }
            Ok((key.to_string(), p))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn most_specific_setting_wins() {
        let s = Settings::parse(
            "relative: 1.0e-6\nquantities:\n  midspan: {relative: 1.0e-4}\n\
             scenes:\n  a:\n    absolute: 0.5\n    quantities:\n      midspan: {relative: 0.01}\n",
        )
        .expect("parses");
        assert_eq!(s.tolerance("b", "run.steps").relative, 1e-6);
        assert_eq!(
            s.tolerance("b", "quantities.midspan.max.value").relative,
            1e-4
        );
        assert_eq!(s.tolerance("b", "midspan_max [m]").relative, 1e-4);
        let a = s.tolerance("a", "midspan_min [m]");
        assert_eq!((a.relative, a.absolute), (0.01, 0.5));
        assert_eq!(s.tolerance("a", "other_min [m]").relative, 1e-6);
    }

    #[test]
    fn bad_key_is_located() {
        let (loc, message) = Settings::parse("relative: 1.0e-6\nscenes:\n  a:\n    relativ: 1\n")
            .expect_err("unknown key");
        assert_eq!(loc.line, 4, "{message}");
        assert!(message.contains("relativ"), "{message}");
    }
}
