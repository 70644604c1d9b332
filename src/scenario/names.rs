//! Names taken from the input that end up in file names or column headers:
//! the scene's `name` (the default output folder) and record names (CSV
//! columns). A name from someone else's file must never steer a write
//! outside the output folder, nor smuggle control characters into a
//! terminal or a CSV header.

use super::checker::Checker;

/// Longest scene or record name accepted, in characters.
pub const MAX_NAME_CHARS: usize = 200;

/// Checks the scene's `name`: not empty, no control characters, not
/// absurdly long. Separators and `..` are allowed in the name itself (it is
/// also a title); [`folder_name`] makes it safe as a folder.
pub(crate) fn check_name(ck: &mut Checker<'_>, name: &str) {
    if name.trim().is_empty() {
        ck.error("name", "`name` must not be empty");
    }
    check_text(ck, "name", "`name`", name);
}

/// Checks a record's name: a CSV column header, so the same rule as
/// `name` (no control characters, bounded length).
pub(crate) fn check_record_name(ck: &mut Checker<'_>, path: &str, name: &str) {
    check_text(ck, path, "a record name", name);
}

fn check_text(ck: &mut Checker<'_>, path: &str, what: &str, text: &str) {
    if let Some(c) = text.chars().find(|c| c.is_control()) {
        ck.error(
            path,
            format!(
                "{what} contains the control character U+{:04X}; use printable characters",
                c as u32
            ),
        );
    }
    let chars = text.chars().count();
    if chars > MAX_NAME_CHARS {
        ck.error(
            path,
            format!("{what} has {chars} characters; at most {MAX_NAME_CHARS} are accepted"),
        );
    }
}

/// A folder name made from a scene's `name`: letters, digits, `-`, `_` and
/// `.` are kept, every other character (separators, spaces, colons,
/// control characters) becomes `_`; leading dots are dropped, so the result
/// is never `.`, `..`, hidden or absolute, and it is never empty. At most
/// [`MAX_NAME_CHARS`] characters.
pub fn folder_name(name: &str) -> String {
    let mapped: String = name
        .chars()
        .take(MAX_NAME_CHARS)
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect();
    let trimmed = mapped.trim_start_matches('.');
    if trimmed.is_empty() {
        "scene".to_string()
    } else {
        trimmed.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::folder_name;
    use std::path::{Component, Path};

    /// Every folder name is one normal path component.
    fn single_component(name: &str) -> bool {
        let folder = folder_name(name);
        let mut components = Path::new(&folder).components();
        matches!(components.next(), Some(Component::Normal(_))) && components.next().is_none()
    }

    #[test]
    fn hostile_names_stay_one_folder() {
        for name in [
            "../../x",
            "..",
            ".",
            "/etc/passwd",
            "a/b\\c",
            "C:\\x",
            "\u{0}nul",
            "...",
            "",
            " ",
            "name\nwith\nlines",
            "~",
            "a/../../b",
        ] {
            assert!(single_component(name), "{name:?} -> {}", folder_name(name));
            assert!(!folder_name(name).starts_with('.'), "{name:?}");
            assert!(
                !folder_name(name).contains(['/', '\\', '\0', '\n']),
                "{name:?}"
            );
        }
    }

    #[test]
    fn ordinary_names_are_kept() {
        assert_eq!(folder_name("yang-yau-sprung-mass"), "yang-yau-sprung-mass");
        assert_eq!(folder_name("plate_case1.v2"), "plate_case1.v2");
        assert_eq!(folder_name("../../x"), "_.._x");
        assert_eq!(folder_name("my scene"), "my_scene");
        assert_eq!(folder_name(".."), "scene");
    }
}
