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

/// Reads `"<number> km/h"` or `"<number> m/s"` (space optional) into m/s.
pub fn parse_speed(text: &str) -> Result<f64, String> {
    let text = text.trim();
    let (number, convert): (&str, fn(f64) -> f64) = if let Some(n) = text.strip_suffix("km/h") {
        (n, km_h_to_m_s)
    } else if let Some(n) = text.strip_suffix("m/s") {
        (n, |v| v)
    } else {
        return Err(format!(
            "a speed is a number in m/s or a string with its unit, e.g. `100 km/h` or `27.8 m/s`; got `{text}`"
        ));
    };
    let value: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{}` in `{text}` is not a number", number.trim()))?;
    Ok(convert(value))
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
}
