//! A scene the caller already parsed (a `serde_json::Value`: JSON, a
//! Python dict) as the format's located tree, so that it goes through the
//! same type checks and semantic checks as a file.
//!
//! Such a scene has no text, hence no line or column: every node gets a
//! synthetic location of its own (its number in document order, as
//! `line`), and [`KeyPaths`] names each by its key path (`vehicles[0].speed`)
//! once the checks are done. Document order keeps everything that orders
//! or groups diagnostics by line (the type errors first sorted top to
//! bottom, the records' span of lines) working as for a file.

use serde_json::Value;

use super::LoadError;
use super::diagnostic::Diagnostic;
use super::yaml::{Location, MAX_DEPTH, MAX_NODES, Node, NodeKind};

/// The key path of every synthetic location of a tree built from data:
/// `paths[line - 1]` for the node numbered `line`.
#[derive(Debug, Clone)]
pub(crate) struct KeyPaths {
    paths: Vec<String>,
}

impl KeyPaths {
    /// The located tree of `value` and the key path of each of its nodes.
    /// A mapping, its keys and its values each get a location: a missing
    /// key is blamed on the mapping's path, an unknown one on its own.
    pub(crate) fn tree(value: &Value, file: &str) -> Result<(Node, KeyPaths), LoadError> {
        let mut paths = KeyPaths { paths: Vec::new() };
        match paths.node(value, String::new(), 0) {
            Ok(node) => Ok((node, paths)),
            Err((path, message)) => Err(LoadError::Invalid(vec![Diagnostic::at_path(
                file, path, message,
            )])),
        }
    }

    /// A new location named `path`.
    fn next(&mut self, path: &str) -> Result<Location, (String, String)> {
        if self.paths.len() >= MAX_NODES {
            return Err((
                path.to_owned(),
                format!("the scene has more than {MAX_NODES} values"),
            ));
        }
        self.paths.push(path.to_owned());
        Ok(Location {
            line: self.paths.len(),
            col: 1,
        })
    }

    fn node(
        &mut self,
        value: &Value,
        path: String,
        depth: usize,
    ) -> Result<Node, (String, String)> {
        if depth >= MAX_DEPTH {
            return Err((
                path,
                format!("nesting deeper than {MAX_DEPTH} levels is not supported"),
            ));
        }
        let loc = self.next(&path)?;
        let scalar = |text: String, plain: bool| NodeKind::Scalar { text, plain };
        let kind = match value {
            Value::Null => NodeKind::Null,
            Value::Bool(b) => scalar(b.to_string(), true),
            // The shortest text that reads back to the same number (ryu),
            // which the format reads as YAML would.
            Value::Number(n) => scalar(n.to_string(), true),
            // A string is a string, as quoted YAML is (a number with a
            // unit, "90 km/h", is read as the format reads it).
            Value::String(s) => scalar(s.clone(), false),
            Value::Array(items) => {
                let mut nodes = Vec::with_capacity(items.len());
                for (i, item) in items.iter().enumerate() {
                    nodes.push(self.node(item, format!("{path}[{i}]"), depth + 1)?);
                }
                NodeKind::Sequence(nodes)
            }
            Value::Object(entries) => {
                let mut nodes = Vec::with_capacity(entries.len());
                for (key, item) in entries {
                    let at = if path.is_empty() {
                        key.clone()
                    } else {
                        format!("{path}.{key}")
                    };
                    let key_node = Node {
                        kind: scalar(key.clone(), false),
                        loc: self.next(&at)?,
                    };
                    nodes.push((key_node, self.node(item, at, depth + 1)?));
                }
                NodeKind::Mapping(nodes)
            }
        };
        Ok(Node { kind, loc })
    }

    /// Names each diagnostic's place by its key path instead of the
    /// synthetic location (which is cleared: there is no line or column).
    pub(crate) fn relocate(&self, diagnostics: &mut [Diagnostic]) {
        for d in diagnostics {
            if d.path.is_some() {
                continue;
            }
            let path = d
                .loc
                .line
                .checked_sub(1)
                .and_then(|i| self.paths.get(i))
                .cloned()
                .unwrap_or_default();
            d.path = Some(path);
            d.loc = Location::default();
            d.source_line = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every node numbered in document order (a mapping before its keys, a
    /// key before its value), each named by its key path.
    #[test]
    fn nodes_are_numbered_in_document_order_and_named_by_key_path() {
        let value = serde_json::json!({"a": {"b": [1.5, "2 m"]}, "c": null});
        let (root, paths) = KeyPaths::tree(&value, "<data>").unwrap();
        assert_eq!(
            paths.paths,
            ["", "a", "a", "a.b", "a.b", "a.b[0]", "a.b[1]", "c", "c"]
        );
        let b = root.get("a").and_then(|a| a.get("b")).unwrap();
        let NodeKind::Sequence(items) = &b.kind else {
            panic!("a list");
        };
        assert_eq!(
            items[0].kind,
            NodeKind::Scalar {
                text: "1.5".into(),
                plain: true
            }
        );
        assert_eq!(
            items[1].kind,
            NodeKind::Scalar {
                text: "2 m".into(),
                plain: false
            }
        );
        assert_eq!(root.get("c").unwrap().kind, NodeKind::Null);
    }

    /// Nesting deeper than a file may have is refused, as in a file.
    #[test]
    fn deep_nesting_is_refused() {
        let mut value = serde_json::json!(1.0);
        for _ in 0..200 {
            value = serde_json::json!([value]);
        }
        let Err(LoadError::Invalid(d)) = KeyPaths::tree(&value, "<data>") else {
            panic!("refused");
        };
        assert!(d[0].message.contains("nesting deeper than"));
    }
}
