//! A small YAML emitter for the resolved scenario (block mappings, flow
//! sequences of scalars, JSON-quoted strings), enough to write back what the
//! loader reads. serde_json's number formatting round-trips f64 exactly.

use std::fmt::Write;

use serde_json::Value;

/// Renders a JSON value tree as a YAML document.
pub fn to_yaml(value: &Value) -> String {
    let mut out = String::new();
    emit_block(value, 0, &mut out);
    out
}

fn is_scalar(value: &Value) -> bool {
    !matches!(value, Value::Array(_) | Value::Object(_))
}

fn scalar(value: &Value) -> String {
    match value {
        Value::Null => "null".into(),
        Value::Bool(b) => b.to_string(),
        // serde_json writes f64 in shortest round-trip form, 20.0 as "20.0".
        Value::Number(n) => n.to_string(),
        Value::String(s) => serde_json::to_string(s).expect("strings serialise"),
        Value::Array(a) if a.is_empty() => "[]".into(),
        Value::Object(o) if o.is_empty() => "{}".into(),
        Value::Array(a) => format!("[{}]", a.iter().map(scalar).collect::<Vec<_>>().join(", ")),
        Value::Object(_) => unreachable!("objects are emitted in block style"),
    }
}

fn key(k: &str) -> String {
    let plain = k
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if plain {
        k.to_string()
    } else {
        serde_json::to_string(k).expect("strings serialise")
    }
}

fn inline(value: &Value) -> bool {
    match value {
        Value::Array(a) => a.iter().all(is_scalar),
        Value::Object(o) => o.is_empty(),
        _ => true,
    }
}

fn emit_block(value: &Value, indent: usize, out: &mut String) {
    let pad = " ".repeat(indent);
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                if inline(v) {
                    let _ = writeln!(out, "{pad}{}: {}", key(k), scalar(v));
                } else {
                    let _ = writeln!(out, "{pad}{}:", key(k));
                    emit_block(v, indent + 2, out);
                }
            }
        }
        Value::Array(items) => {
            for item in items {
                if inline(item) {
                    let _ = writeln!(out, "{pad}- {}", scalar(item));
                } else {
                    // "- " then the first line of the nested block on the same line.
                    let mut nested = String::new();
                    emit_block(item, indent + 2, &mut nested);
                    let trimmed = nested.trim_start_matches(' ');
                    let _ = write!(out, "{pad}- {trimmed}");
                }
            }
        }
        other => {
            let _ = writeln!(out, "{pad}{}", scalar(other));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn emits_nested_structures() {
        let v = serde_json::json!({
            "name": "a: b",
            "spans": [20.0, 30.5],
            "bridge": {"type": "beam", "modes": {"count": 10}},
            "record": [{"name": "m", "x": 10.0}, {"name": "n"}],
            "empty": []
        });
        let text = to_yaml(&v);
        assert_eq!(
            text,
            "name: \"a: b\"\nspans: [20.0, 30.5]\nbridge:\n  type: \"beam\"\n  modes:\n    count: 10\n\
             record:\n  - name: \"m\"\n    x: 10.0\n  - name: \"n\"\nempty: []\n"
        );
    }
}
