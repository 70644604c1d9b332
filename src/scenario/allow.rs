//! The scene's `allow` list: advice ids it leaves unheeded, each with the
//! reason ([`crate::advice::Allow`]). Physics-free: the ids are checked
//! against the registry ([`crate::advice::KINDS`]).

use super::checker::Checker;
use super::diagnostic::did_you_mean;
use super::raw::AllowRaw;
use crate::advice::{Allow, KINDS, kind};

/// The resolved `allow` list; an unknown id or an empty reason is an error
/// at its entry.
pub(crate) fn resolve(raws: Option<&[AllowRaw]>, ck: &mut Checker<'_>) -> Vec<Allow> {
    let mut out: Vec<Allow> = Vec::new();
    for (i, raw) in raws.unwrap_or_default().iter().enumerate() {
        let path = format!("allow[{i}]");
        if kind(&raw.id).is_none() {
            let help = did_you_mean(&raw.id, KINDS.iter().map(|k| k.id)).or_else(|| {
                Some("the ids are listed in docs/advice.md (`vbi advice`)".to_string())
            });
            ck.error_with_help(
                &format!("{path}.id"),
                format!(
                    "`{}` is not an advice id",
                    super::diagnostic::escaped(&raw.id)
                ),
                help,
            );
            continue;
        }
        if raw.reason.trim().is_empty() {
            ck.error_with_help(
                &format!("{path}.reason"),
                format!("allowing `{}` needs a reason", raw.id),
                Some(
                    "say why the advice does not apply to this scene: it is kept in the outputs"
                        .into(),
                ),
            );
            continue;
        }
        if out.iter().any(|a| a.id == raw.id) {
            ck.error(
                &format!("{path}.id"),
                format!("`{}` is allowed twice", raw.id),
            );
            continue;
        }
        out.push(Allow {
            id: raw.id.clone(),
            reason: raw.reason.clone(),
        });
    }
    out
}
