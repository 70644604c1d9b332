//! A speed as engineers write it: `speed: 27.8` (m/s, the SI default) or
//! `speed: 100 km/h` (or `27.8 m/s`). Everything after loading sees m/s only
//! (the resolved scenario shows m/s).

use std::borrow::Cow;
use std::fmt;

use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde::de::{self, Deserialize, Deserializer, Visitor};

/// km/h in m/s (for messages; conversions use [`km_h_to_m_s`]).
pub const KM_H: f64 = 1000.0 / 3600.0;

/// `v` km/h in m/s with a single rounding (72 km/h is exactly 20 m/s).
pub fn km_h_to_m_s(v: f64) -> f64 {
    v * 1000.0 / 3600.0
}

/// A speed in m/s, read from a number (m/s) or a string with a unit; the
/// flag says whether the unit was written (`"83.3 m/s"`, `"300 km/h"`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedRaw(pub f64, pub bool);

impl SpeedRaw {
    /// The speed, m/s.
    pub fn meters_per_second(self) -> f64 {
        self.0
    }

    /// Whether the input wrote the unit: such a speed states its intent
    /// and is never taken for a km/h value typed as m/s.
    pub fn unit_written(self) -> bool {
        self.1
    }
}

/// Reads `"<number> km/h"` or `"<number> m/s"` (space optional) into m/s;
/// NaN, infinities, subnormal numbers and spaces inside the unit are
/// refused, each with what to write (a `help:` line after a line break).
pub fn parse_speed(text: &str) -> Result<f64, String> {
    use super::units::{non_finite_word, nonzero_digits, normal, spaced_unit, split_number};
    let text = text.trim();
    let shown = crate::scenario::diagnostic::escaped(text);
    let general = || {
        format!(
            "a speed is a number in m/s or a string with its unit, e.g. `100 km/h` or `27.8 m/s`; got `{shown}`"
        )
    };
    if let Some(word) = non_finite_word(text) {
        return Err(format!(
            "`{}` in `{shown}` is not a finite number\nhelp: write a speed as a number in m/s \
             or with its unit, e.g. `100 km/h` or `27.8 m/s`",
            crate::scenario::diagnostic::escaped(word),
        ));
    }
    let (number, unit) = split_number(text);
    if unit.contains(char::is_whitespace) && !number.is_empty() {
        let words: Vec<&str> = unit.split_whitespace().collect();
        let candidates: Vec<String> = [words.concat()]
            .into_iter()
            .filter(|u| u == "km/h" || u == "m/s")
            .collect();
        return Err(spaced_unit(text, unit, &candidates));
    }
    let convert: fn(f64) -> f64 = match unit {
        "km/h" => km_h_to_m_s,
        "m/s" => |v| v,
        _ if number.is_empty() && (text.ends_with("km/h") || text.ends_with("m/s")) => {
            let word = text.trim_end_matches("km/h").trim_end_matches("m/s").trim();
            return Err(format!(
                "`{}` in `{shown}` is not a number",
                crate::scenario::diagnostic::escaped(word)
            ));
        }
        _ => return Err(general()),
    };
    let value: f64 = number.parse().map_err(|_| {
        format!(
            "`{}` in `{shown}` is not a number",
            crate::scenario::diagnostic::escaped(number)
        )
    })?;
    normal(text, convert(value), nonzero_digits(number), "m/s")
}

impl<'de> Deserialize<'de> for SpeedRaw {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct SpeedVisitor;
        impl Visitor<'_> for SpeedVisitor {
            type Value = SpeedRaw;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a speed in m/s, or a string such as `100 km/h`")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<SpeedRaw, E> {
                Ok(SpeedRaw(v, false))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<SpeedRaw, E> {
                Ok(SpeedRaw(v as f64, false))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<SpeedRaw, E> {
                Ok(SpeedRaw(v as f64, false))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<SpeedRaw, E> {
                parse_speed(v).map(|v| SpeedRaw(v, true)).map_err(E::custom)
            }
        }
        deserializer.deserialize_any(SpeedVisitor)
    }
}

impl JsonSchema for SpeedRaw {
    fn schema_name() -> Cow<'static, str> {
        "SpeedRaw".into()
    }

    fn inline_schema() -> bool {
        true
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "anyOf": [
                {
                    "type": "number",
                    "exclusiveMinimum": 0.0,
                    "maximum": super::super::vehicles::MAX_SPEED,
                    "description": "m/s"
                },
                {
                    "type": "string",
                    "pattern": r"^\s*[0-9]*\.?[0-9]+([eE][+-]?[0-9]+)?\s*(km/h|m/s)\s*$",
                    "description": "with its unit: `100 km/h` or `27.8 m/s`"
                }
            ],
            "examples": [27.8, "100 km/h"]
        })
    }
}

/// Evenly spaced speeds from `from` to `to` inclusive.
#[derive(Debug, Clone, serde::Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SpeedGridRaw {
    /// First speed: m/s, or with its unit (`100 km/h`).
    pub from: SpeedRaw,
    /// Last speed: m/s, or with its unit (`420 km/h`).
    pub to: SpeedRaw,
    /// Number of speeds (≥ 1; 1 gives `from` only).
    #[schemars(transform = crate::scene::schema_rules::grid_count)]
    pub count: usize,
}

impl SpeedGridRaw {
    /// The grid in m/s.
    pub fn in_m_s(&self) -> crate::scene::Grid {
        crate::scene::Grid {
            from: self.from.0,
            to: self.to.0,
            count: self.count,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_convert_to_metres_per_second() {
        assert_eq!(parse_speed("300 km/h").unwrap(), 250.0 / 3.0);
        assert_eq!(parse_speed("72 km/h").unwrap(), 20.0);
        assert_eq!(parse_speed(" 36km/h ").unwrap(), 10.0);
        assert_eq!(parse_speed("27.5 m/s").unwrap(), 27.5);
        assert!(parse_speed("300").unwrap_err().contains("km/h"));
        assert!(parse_speed("300 mph").is_err());
        assert!(
            parse_speed("fast km/h")
                .unwrap_err()
                .contains("not a number")
        );
    }

    #[test]
    fn nan_infinite_and_subnormal_speeds_are_refused() {
        for text in [
            "NaN km/h",
            "nan m/s",
            "inf km/h",
            "-infinity m/s",
            "1e999 km/h",
        ] {
            let e = parse_speed(text).unwrap_err();
            assert!(e.contains("is not a finite number"), "{text}: {e}");
        }
        // 1e-320 is subnormal, and so is it in m/s; 1e-400 underflows to 0.
        let e = parse_speed("1e-320 km/h").unwrap_err();
        assert!(e.contains("subnormal"), "{e}");
        let e = parse_speed("1e-400 m/s").unwrap_err();
        assert!(e.contains("would be read as 0"), "{e}");
        // The smallest normal speed is still one.
        assert_eq!(parse_speed("2.3e-308 m/s").unwrap(), 2.3e-308);
        assert_eq!(parse_speed("0 km/h").unwrap(), 0.0);
    }

    #[test]
    fn a_space_inside_the_unit_is_refused() {
        let e = parse_speed("80 km / h").unwrap_err();
        assert!(e.contains("has a space inside its unit `km / h`"), "{e}");
        assert!(
            e.contains("help: write the unit without spaces: `km/h`"),
            "{e}"
        );
        let e = parse_speed("80 k m/h").unwrap_err();
        assert!(e.contains("has a space inside its unit"), "{e}");
        // Between the number and its unit a space is the usual spelling.
        assert_eq!(parse_speed("72 km/h").unwrap(), 20.0);
        assert!(
            parse_speed("80 km")
                .unwrap_err()
                .contains("a speed is a number in m/s")
        );
    }
}
