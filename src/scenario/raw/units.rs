//! Physical numbers as engineers write them (issue 28.2): a plain number is
//! in SI units as always (`spans: [25.0]`, metres); a string gives its unit
//! (`25 m`, `250 mm`, `40 t`, `1.6e6 N/m`, `170 kN`, `30 Hz`, `0.35 g`),
//! checked against the dimension of the key (`25 s` for a length: "expected
//! a length (m, mm, cm, km), found a time"). Everything after loading sees
//! SI numbers only, and resolved.yaml writes them.
//!
//! Each field opts in with `#[serde(deserialize_with = "units::length::one")]`
//! (or `::option`, `::list`) and the matching
//! `#[schemars(schema_with = "units::length::schema")]`, so that the raw
//! types keep plain `f64`s. Speeds have their own type ([`super::SpeedRaw`]).
//!
//! A decimal prefix (mm, kN, MN, GPa, …) shifts the written number's decimal
//! exponent before it is read (`250 mm` is read as `250e-3`), so the value is
//! the correctly rounded one, bit for bit what the SI number written out
//! (`0.25`) gives. The other factors are exact decimals too (`g` =
//! 9.80665 m/s², `min` = 60 s) and multiply the written digits exactly.

use std::fmt;

use schemars::{Schema, json_schema};
use serde::de::{self, DeserializeSeed, Deserializer, SeqAccess, Visitor};

/// Standard gravity g_n, m/s² (ISO 80000-3; CGPM 1901), the `g` of an
/// acceleration such as `0.35 g`. It is not the scene's `gravity`, which a
/// scene may set to a local value: `0.35 g` means the same in every scene.
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// How a unit turns a written number into SI.
#[derive(Debug, Clone, Copy)]
enum Scale {
    /// × `factor` × 10^`shift`, both exact decimals, so that the product
    /// is computed in decimal and read with one rounding (`0.35 g` is read
    /// as `0.35 × 980665e-5` = `3.4323275`, bit for bit what that SI number
    /// written out gives).
    Decimal { factor: u64, shift: i32 },
    /// × a factor that no decimal writes exactly (`deg` = π/180 rad): one
    /// floating-point multiplication, correctly rounded for that product.
    Irrational(f64),
}

/// × 10^k.
const fn decimal(shift: i32) -> Scale {
    Scale::Decimal { factor: 1, shift }
}

/// × `factor` × 10^`shift`.
const fn exact(factor: u64, shift: i32) -> Scale {
    Scale::Decimal { factor, shift }
}

/// One physical dimension of the format: its name in messages, and its
/// units (the SI one first).
#[derive(Debug)]
pub struct Dimension {
    /// "a length", "a mass", … (messages).
    pub name: &'static str,
    /// The SI unit, as the JSON Schema describes a plain number.
    pub si: &'static str,
    units: &'static [(&'static str, Scale)],
}

mod dimensions;
pub use dimensions::*;

/// A unit as written, in the spelling of the tables: `·` and `×` as `*`,
/// `²`/`³` as `^2`/`^3`, `Ns/m` as `N*s/m`, `m/s2` as `m/s^2`, no spaces.
fn canonical(unit: &str) -> String {
    let mut out = String::with_capacity(unit.len() + 2);
    for c in unit.chars() {
        match c {
            '·' | '×' | '⋅' => out.push('*'),
            '²' => out.push_str("^2"),
            '³' => out.push_str("^3"),
            '°' => out.push_str("deg"),
            c if c.is_whitespace() => {}
            c => out.push(c),
        }
    }
    if let Some(rest) = out.strip_suffix("s/m")
        && matches!(rest, "N" | "kN" | "MN")
    {
        out = format!("{rest}*s/m");
    }
    if out == "m/s2" {
        out = "m/s^2".into();
    }
    out
}

impl Dimension {
    /// The units as a message lists them: `m, mm, cm, km`.
    fn unit_list(&self) -> String {
        let names: Vec<&str> = self.units.iter().map(|u| u.0).collect();
        names.join(", ")
    }

    /// Reads `"<number> <unit>"` into SI, or says why not.
    pub fn parse(&self, text: &str) -> Result<f64, String> {
        let text = text.trim();
        // The number: everything up to the first character that cannot
        // continue one (a unit never starts with a digit, `.`, `+`, `-`; an
        // `e` continues the number only if a digit or sign follows).
        let bytes = text.as_bytes();
        let mut end = 0;
        while end < bytes.len() {
            let b = bytes[end];
            let exponent = matches!(b, b'e' | b'E')
                && end > 0
                && bytes
                    .get(end + 1)
                    .is_some_and(|n| n.is_ascii_digit() || matches!(n, b'+' | b'-'));
            if b.is_ascii_digit() || matches!(b, b'.' | b'+' | b'-') || exponent {
                end += 1 + usize::from(exponent && matches!(bytes[end + 1], b'+' | b'-'));
            } else {
                break;
            }
        }
        let (number, unit) = (text[..end].trim(), text[end..].trim());
        let written: f64 = number.parse().map_err(|_| {
            format!(
                "`{text}` is not {}: write a number in {} or one with its unit ({})",
                self.name,
                self.si,
                self.unit_list()
            )
        })?;
        if unit.is_empty() {
            return Err(format!(
                "`{text}` has no unit; write {} as a plain number ({}) or with one of {}",
                self.name,
                self.si,
                self.unit_list()
            ));
        }
        let unit = canonical(unit);
        let Some(&(_, scale)) = self.units.iter().find(|u| u.0 == unit) else {
            let found = ALL
                .iter()
                .find(|d| d.units.iter().any(|u| u.0 == unit))
                .map_or_else(
                    || format!("the unknown unit `{unit}`"),
                    |d| format!("{} (`{unit}`)", d.name),
                );
            return Err(format!(
                "expected {} ({}), found {found} in `{text}`",
                self.name,
                self.unit_list()
            ));
        };
        let value = match scale {
            Scale::Decimal {
                factor: 1,
                shift: 0,
            } => written,
            // A number too long for exact decimal arithmetic (over 30
            // digits) is scaled in floating point.
            Scale::Decimal { factor, shift } => times_decimal(number, factor, shift)
                .unwrap_or(written * factor as f64 * 10f64.powi(shift)),
            Scale::Irrational(factor) => written * factor,
        };
        if value.is_finite() {
            Ok(value)
        } else {
            Err(format!("`{text}` is not a finite number"))
        }
    }

    /// The JSON Schema of a value of this dimension: a number (SI) or a
    /// string with one of its units.
    pub fn schema(&self) -> Schema {
        let alternatives: Vec<String> = self
            .units
            .iter()
            .map(|u| regex_escape(u.0))
            .chain(self.spellings())
            .collect();
        let pattern = format!(
            r"^\s*[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?\s*({})\s*$",
            alternatives.join("|")
        );
        let example = self.units.get(1).unwrap_or(&self.units[0]).0;
        json_schema!({
            "description": format!(
                "{}: a number in {} or a string with its unit ({})",
                self.name,
                self.si,
                self.unit_list()
            ),
            "anyOf": [
                {"type": "number", "description": self.si},
                {
                    "type": "string",
                    "pattern": pattern,
                    "description": format!("with its unit: {}", self.unit_list())
                }
            ],
            "examples": [format!("1 {example}")]
        })
    }

    /// Other spellings [`canonical`] accepts, as regular expressions.
    fn spellings(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (unit, _) in self.units {
            if unit.contains('*') || unit.contains('^') {
                // `·` for `*`, `²`/`³` for `^2`/`^3`.
                let pretty = unit.replace('*', "·").replace("^2", "²").replace("^3", "³");
                if pretty != *unit {
                    out.push(regex_escape(&pretty));
                }
            }
            if let Some(force) = unit.strip_suffix("*s/m") {
                out.push(format!("{force}s/m"));
            }
        }
        if self.si == "m/s^2" {
            out.push("m/s2".into());
        }
        if self.si == "rad" {
            out.push("°".into());
        }
        out
    }
}

fn regex_escape(unit: &str) -> String {
    let mut out = String::new();
    for c in unit.chars() {
        if matches!(c, '*' | '^' | '.' | '/' | '+' | '(' | ')') {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// `number` × `factor` × 10^`shift` in decimal, read with one rounding: the digits of
/// the written number (at most 30) times the integer factor, with the
/// decimal exponents summed (`250` mm → `250e-3`). `None` if the text is
/// not a plain decimal number or too long.
fn times_decimal(number: &str, factor: u64, shift: i32) -> Option<f64> {
    let (sign, unsigned) = match number.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", number.strip_prefix('+').unwrap_or(number)),
    };
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(i) => (&unsigned[..i], unsigned[i + 1..].parse::<i32>().ok()?),
        None => (unsigned, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if !(whole.bytes().chain(fraction.bytes())).all(|b| b.is_ascii_digit()) {
        return None;
    }
    let digits = format!("{whole}{fraction}");
    let digits = digits.trim_start_matches('0');
    if digits.len() > 30 {
        return None;
    }
    let value: u128 = if digits.is_empty() {
        0
    } else {
        digits.parse().ok()?
    };
    let product = value.checked_mul(u128::from(factor))?;
    let places = i32::try_from(fraction.len()).ok()?;
    let exponent = exponent.checked_sub(places)?.checked_add(shift)?;
    format!("{sign}{product}e{exponent}").parse().ok()
}

/// One value of `dimension`: a number (SI) or a string with a unit.
struct Quantity<'d>(&'d Dimension);

impl<'de> Visitor<'de> for Quantity<'_> {
    type Value = f64;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // "expected a number" first, as for any plain number field.
        write!(
            f,
            "a number ({} in {}) or a string with its unit ({})",
            self.0.name,
            self.0.si,
            self.0.unit_list()
        )
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<f64, E> {
        Ok(v)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_i128<E: de::Error>(self, v: i128) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<f64, E> {
        // Text that does not even start like a number is a wrong type, as
        // serde words it for any number (`"fast"` for a length).
        let starts_numeric = v
            .trim_start()
            .starts_with(|c: char| c.is_ascii_digit() || matches!(c, '.' | '+' | '-'));
        if !starts_numeric {
            return Err(E::invalid_type(de::Unexpected::Str(v), &self));
        }
        self.0.parse(v).map_err(E::custom)
    }
}

impl<'de> DeserializeSeed<'de> for Quantity<'_> {
    type Value = f64;
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<f64, D::Error> {
        deserializer.deserialize_any(self)
    }
}

/// A list of values of one dimension.
struct QuantityList<'d>(&'d Dimension);

impl<'de> Visitor<'de> for QuantityList<'_> {
    type Value = Vec<f64>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "a list of {} values", self.0.si)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<f64>, A::Error> {
        // No capacity from the input: the tree's own length bounds it.
        let mut out = Vec::new();
        while let Some(v) = seq.next_element_seed(Quantity(self.0))? {
            out.push(v);
        }
        Ok(out)
    }
}

/// Two values of one dimension, `[a, b]` (a Rayleigh pair of frequencies,
/// a profile point `[x, r]`).
#[derive(Clone, Copy)]
struct QuantityPair<'d>(&'d Dimension);

impl<'de> Visitor<'de> for QuantityPair<'_> {
    type Value = [f64; 2];

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "a list of two {} values", self.0.si)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[f64; 2], A::Error> {
        let mut out = [0.0; 2];
        for (i, v) in out.iter_mut().enumerate() {
            *v = seq
                .next_element_seed(Quantity(self.0))?
                .ok_or_else(|| de::Error::invalid_length(i, &self))?;
        }
        Ok(out)
    }
}

impl<'de> DeserializeSeed<'de> for QuantityPair<'_> {
    type Value = [f64; 2];
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<[f64; 2], D::Error> {
        deserializer.deserialize_tuple(2, self)
    }
}

/// A list of pairs of one dimension.
struct QuantityPairs<'d>(&'d Dimension);

impl<'de> Visitor<'de> for QuantityPairs<'_> {
    type Value = Vec<[f64; 2]>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "a list of pairs of {} values", self.0.si)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<[f64; 2]>, A::Error> {
        // No capacity from the input: the tree's own length bounds it.
        let mut out = Vec::new();
        while let Some(v) = seq.next_element_seed(QuantityPair(self.0))? {
            out.push(v);
        }
        Ok(out)
    }
}

/// Deserialises one value of `dimension`.
pub fn one<'de, D: Deserializer<'de>>(d: D, dimension: &Dimension) -> Result<f64, D::Error> {
    d.deserialize_any(Quantity(dimension))
}

/// Deserialises a list of values of `dimension`.
pub fn list<'de, D: Deserializer<'de>>(d: D, dimension: &Dimension) -> Result<Vec<f64>, D::Error> {
    d.deserialize_seq(QuantityList(dimension))
}

/// Deserialises a pair of values of `dimension`.
pub fn pair<'de, D: Deserializer<'de>>(d: D, dimension: &Dimension) -> Result<[f64; 2], D::Error> {
    QuantityPair(dimension).deserialize(d)
}

/// Deserialises a list of pairs of values of `dimension`.
pub fn pairs<'de, D: Deserializer<'de>>(
    d: D,
    dimension: &Dimension,
) -> Result<Vec<[f64; 2]>, D::Error> {
    d.deserialize_seq(QuantityPairs(dimension))
}

/// The field functions of one dimension, for `deserialize_with` and
/// `schema_with`: `one` (f64), `option` (Option<f64>, with
/// `#[serde(default)]`), `list` (Vec<f64>), `option_list`
/// (Option<Vec<f64>>), `pair` ([f64; 2]), `pairs` (Vec<[f64; 2]>), and
/// their schemas, which refer to the dimension's
/// one definition in the schema's `$defs` (`#/$defs/Length`) instead of
/// repeating it at every field.
macro_rules! field_functions {
    ($($module:ident => $dimension:ident as $name:literal),* $(,)?) => {$(
        #[allow(dead_code)]
        #[doc = concat!("Field functions of ", stringify!($dimension), ".")]
        pub mod $module {
            use std::borrow::Cow;

            use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
            use serde::Deserializer;

            /// The dimension's entry of the schema's `$defs`.
            pub struct Definition;

            impl JsonSchema for Definition {
                fn schema_name() -> Cow<'static, str> {
                    $name.into()
                }
                fn json_schema(_: &mut SchemaGenerator) -> Schema {
                    super::$dimension.schema()
                }
            }

            /// One value.
            pub fn one<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
                super::one(d, &super::$dimension)
            }
            /// An optional value (with `#[serde(default)]`).
            pub fn option<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
                super::one(d, &super::$dimension).map(Some)
            }
            /// A list.
            pub fn list<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
                super::list(d, &super::$dimension)
            }
            /// An optional list.
            pub fn option_list<'de, D: Deserializer<'de>>(
                d: D,
            ) -> Result<Option<Vec<f64>>, D::Error> {
                super::list(d, &super::$dimension).map(Some)
            }
            /// The schema of one value.
            pub fn schema(generator: &mut SchemaGenerator) -> Schema {
                generator.subschema_for::<Definition>()
            }
            /// The schema of a list.
            pub fn list_schema(generator: &mut SchemaGenerator) -> Schema {
                let items = generator.subschema_for::<Definition>();
                json_schema!({"type": "array", "items": items})
            }
            /// A pair `[a, b]`.
            pub fn pair<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
                super::pair(d, &super::$dimension)
            }
            /// A list of pairs.
            pub fn pairs<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<[f64; 2]>, D::Error> {
                super::pairs(d, &super::$dimension)
            }
            /// The schema of a pair.
            pub fn pair_schema(generator: &mut SchemaGenerator) -> Schema {
                let items = generator.subschema_for::<Definition>();
                json_schema!({"type": "array", "items": items, "minItems": 2, "maxItems": 2})
            }
            /// The schema of a list of pairs.
            pub fn pairs_schema(generator: &mut SchemaGenerator) -> Schema {
                let pair = pair_schema(generator);
                json_schema!({"type": "array", "items": pair})
            }
        }
    )*};
}

field_functions! {
    length => LENGTH as "Length",
    mass => MASS as "Mass",
    force => FORCE as "Force",
    stiffness => STIFFNESS as "Stiffness",
    damping => DAMPING as "DampingCoefficient",
    time => TIME as "Time",
    frequency => FREQUENCY as "Frequency",
    acceleration => ACCELERATION as "Acceleration",
    bending_stiffness => BENDING_STIFFNESS as "BendingStiffness",
    mass_per_length => MASS_PER_LENGTH as "MassPerLength",
    mass_per_area => MASS_PER_AREA as "MassPerArea",
    density => DENSITY as "Density",
    pressure => PRESSURE as "Modulus",
    inertia => INERTIA as "MomentOfInertia",
    plate_rigidity => PLATE_RIGIDITY as "PlateRigidity",
    torsional_stiffness => TORSIONAL_STIFFNESS as "TorsionalStiffness",
    inertia_per_length => INERTIA_PER_LENGTH as "MomentOfInertiaPerLength",
    hertz_coefficient => HERTZ_COEFFICIENT as "HertzCoefficient",
    roughness_coefficient => ROUGHNESS_COEFFICIENT as "RoughnessCoefficient",
    angle => ANGLE as "Angle",
}

#[cfg(test)]
mod tests;
