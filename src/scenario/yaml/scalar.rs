//! Plain scalars resolved with the YAML 1.2 core schema (null, booleans,
//! integers, floats, strings), and a float as JSON.

use super::Resolved;

pub(super) fn float_json(f: f64, text: &str) -> serde_json::Value {
    serde_json::Number::from_f64(f)
        .map(serde_json::Value::Number)
        .unwrap_or_else(|| serde_json::Value::String(text.to_owned()))
}

/// Resolve a plain scalar's text with the YAML 1.2 core schema (spec 10.3.2).
pub fn resolve_plain(text: &str) -> Resolved<'_> {
    match text {
        "" | "~" | "null" | "Null" | "NULL" => return Resolved::Null,
        "true" | "True" | "TRUE" => return Resolved::Bool(true),
        "false" | "False" | "FALSE" => return Resolved::Bool(false),
        ".nan" | ".NaN" | ".NAN" => return Resolved::Float(f64::NAN),
        _ => {}
    }
    let (neg, unsigned) = match text.as_bytes()[0] {
        b'-' => (true, &text[1..]),
        b'+' => (false, &text[1..]),
        _ => (false, text),
    };
    if matches!(unsigned, ".inf" | ".Inf" | ".INF") {
        return Resolved::Float(if neg {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        });
    }
    let radix = |digits: &str, radix: u32| {
        if !digits.is_empty() && digits.chars().all(|c| c.is_digit(radix)) {
            Some(i128::from_str_radix(digits, radix).map_or(Resolved::IntOverflow, Resolved::Int))
        } else {
            None
        }
    };
    // Core schema: hex and octal ints carry no sign.
    let based = if let Some(d) = text.strip_prefix("0x") {
        radix(d, 16)
    } else if let Some(d) = text.strip_prefix("0o") {
        radix(d, 8)
    } else {
        None
    };
    if let Some(r) = based {
        return r;
    }
    if !unsigned.is_empty() && unsigned.bytes().all(|b| b.is_ascii_digit()) {
        return text.parse().map_or(Resolved::IntOverflow, Resolved::Int);
    }
    if is_core_float(unsigned) {
        // Our grammar is a subset of what `f64::from_str` accepts.
        if let Ok(f) = text.parse::<f64>() {
            return Resolved::Float(f);
        }
    }
    Resolved::Str(text)
}

/// `( \. [0-9]+ | [0-9]+ ( \. [0-9]* )? ) ( [eE] [-+]? [0-9]+ )?` (sign stripped).
fn is_core_float(s: &str) -> bool {
    let b = s.as_bytes();
    let digits = |mut i: usize| {
        let start = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        (i, i - start)
    };
    let (mut i, int_digits) = digits(0);
    if i < b.len() && b[i] == b'.' {
        let (j, frac_digits) = digits(i + 1);
        if int_digits == 0 && frac_digits == 0 {
            return false;
        }
        i = j;
    } else if int_digits == 0 {
        return false;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
            i += 1;
        }
        let (j, exp_digits) = digits(i);
        if exp_digits == 0 {
            return false;
        }
        i = j;
    }
    i == b.len()
}
