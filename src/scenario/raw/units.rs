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

/// Whether a unit symbol takes an SI prefix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Prefixes {
    /// Never (`t`, `min`, `deg`, `cycle`).
    No,
    /// With or without one (`m`, `mm`, `km`; `N`, `kN`, `GN`).
    Optional,
    /// Always: the gram, whose bare `g` is standard gravity in this format
    /// (`kg`, `mg`, `Mg`, never `g`).
    Required,
}

/// A unit symbol the dimensions' forms are written in, and its size in SI.
struct Symbol {
    name: &'static str,
    scale: Scale,
    prefixes: Prefixes,
}

const fn symbol(name: &'static str, scale: Scale, prefixes: Prefixes) -> Symbol {
    Symbol {
        name,
        scale,
        prefixes,
    }
}

/// π/180: radians per degree (the f64 nearest to it).
const RADIANS_PER_DEGREE: f64 = std::f64::consts::PI / 180.0;

/// Every symbol of the forms.
const SYMBOLS: &[Symbol] = &[
    symbol("m", decimal(0), Prefixes::Optional),
    symbol("g", decimal(-3), Prefixes::Required),
    symbol("s", decimal(0), Prefixes::Optional),
    symbol("N", decimal(0), Prefixes::Optional),
    symbol("Pa", decimal(0), Prefixes::Optional),
    symbol("Hz", decimal(0), Prefixes::Optional),
    symbol("rad", decimal(0), Prefixes::Optional),
    symbol("t", decimal(3), Prefixes::No),
    symbol("min", exact(60, 0), Prefixes::No),
    symbol("deg", Scale::Irrational(RADIANS_PER_DEGREE), Prefixes::No),
    symbol("cycle", decimal(0), Prefixes::No),
];

/// The SI prefixes (BIPM, SI Brochure 2019, and the 2022 additions), as
/// powers of ten; `da` before `d`, so that the longest one is tried first.
/// Micro may be written `µ` (U+00B5), `μ` (U+03BC) or `u`.
const PREFIXES: &[(&str, i32)] = &[
    ("Q", 30),
    ("R", 27),
    ("Y", 24),
    ("Z", 21),
    ("E", 18),
    ("P", 15),
    ("T", 12),
    ("G", 9),
    ("M", 6),
    ("k", 3),
    ("h", 2),
    ("da", 1),
    ("d", -1),
    ("c", -2),
    ("m", -3),
    ("µ", -6),
    ("μ", -6),
    ("u", -6),
    ("n", -9),
    ("p", -12),
    ("f", -15),
    ("a", -18),
    ("z", -21),
    ("y", -24),
    ("r", -27),
    ("q", -30),
];

/// What the schema says of prefixes.
const PREFIXED: &str = "any SI prefix on m, g, s, N, Pa, Hz, rad";

/// One physical dimension of the format: its name in messages, the units
/// a message lists (the SI one first), and the forms it is written in:
/// products and quotients of [`SYMBOLS`] with exponents (`N*m^2/rad`), each
/// symbol with any SI prefix it takes (`kN/mm`, `GN/m`, `MN*m^2`, `µm`),
/// and whole-unit aliases (`g`, standard gravity, for an acceleration).
#[derive(Debug)]
pub struct Dimension {
    /// "a length", "a mass", … (messages).
    pub name: &'static str,
    /// The SI unit, as the JSON Schema describes a plain number.
    pub si: &'static str,
    /// The units messages list (the common ones; every prefix works).
    listed: &'static [&'static str],
    /// The forms, in [`SYMBOLS`] without prefixes.
    forms: &'static [&'static str],
    /// Whole units outside the forms, with their scale.
    aliases: &'static [(&'static str, Scale)],
}

mod dimensions;
pub use dimensions::*;

/// A unit as written, in the spelling of the forms: `·`, `×` and `⋅` as
/// `*`, `²`/`³` as `^2`/`^3`, `°` as `deg`, a prefixed `Ns/m` as `N*s/m`,
/// `m/s2` as `m/s^2`. White space is not allowed inside a unit (refused
/// before this).
fn canonical(unit: &str) -> String {
    let mut out = String::with_capacity(unit.len() + 2);
    for c in unit.chars() {
        match c {
            '·' | '×' | '⋅' => out.push('*'),
            '²' => out.push_str("^2"),
            '³' => out.push_str("^3"),
            '°' => out.push_str("deg"),
            c => out.push(c),
        }
    }
    if let Some(rest) = out.strip_suffix("Ns/m")
        && (rest.is_empty() || PREFIXES.iter().any(|(p, _)| *p == rest))
    {
        out = format!("{rest}N*s/m");
    }
    if out == "m/s2" {
        out = "m/s^2".into();
    }
    out
}

/// A unit split into its factors: (divides, base, exponent as written).
fn factors(unit: &str) -> Option<Vec<(bool, &str, &str)>> {
    let mut out = Vec::new();
    let mut divides = false;
    let mut rest = unit;
    loop {
        let end = rest.find(['*', '/']).unwrap_or(rest.len());
        let piece = &rest[..end];
        let (base, exponent) = piece.split_once('^').unwrap_or((piece, "1"));
        if base.is_empty() || exponent.is_empty() {
            return None;
        }
        out.push((divides, base, exponent));
        if end == rest.len() {
            return Some(out);
        }
        divides = rest.as_bytes()[end] == b'/';
        rest = &rest[end + 1..];
    }
}

/// The power of ten of the prefix `prefix` of `symbol` (0 for none), if
/// the symbol takes it.
fn prefix_of(symbol: &Symbol, prefix: &str) -> Option<i32> {
    match (prefix.is_empty(), symbol.prefixes) {
        (true, Prefixes::Required) | (false, Prefixes::No) => None,
        (true, _) => Some(0),
        (false, _) => PREFIXES.iter().find(|(p, _)| *p == prefix).map(|p| p.1),
    }
}

/// The scale of `unit` (canonical) in `form`, if it is written in it.
fn scale_in(form: &str, unit: &str) -> Option<Scale> {
    let (form, unit) = (factors(form)?, factors(unit)?);
    if form.len() != unit.len() {
        return None;
    }
    // The power of ten, in halves (an exponent may be 1.5), the exact
    // integer factor, and what no decimal writes.
    let (mut halves, mut factor, mut other) = (0i64, 1u64, 1.0f64);
    for (&(divides, base, exponent), &(written_divides, written, written_exponent)) in
        form.iter().zip(&unit)
    {
        if divides != written_divides || exponent != written_exponent {
            return None;
        }
        let symbol = SYMBOLS.iter().find(|s| s.name == base)?;
        let prefix = written.strip_suffix(symbol.name)?;
        let power = i64::from(prefix_of(symbol, prefix)?);
        let e: f64 = exponent.parse().ok()?;
        let e2 = (2.0 * e).round();
        if e2 != 2.0 * e || e2.abs() > 16.0 {
            return None;
        }
        let e2 = if divides { -e2 as i64 } else { e2 as i64 };
        halves += power * e2;
        match symbol.scale {
            Scale::Decimal { factor: f, shift } => {
                halves += i64::from(shift) * e2;
                if f != 1 {
                    match (e2 > 0 && e2 % 2 == 0)
                        .then(|| f.checked_pow(u32::try_from(e2 / 2).ok()?))
                        .flatten()
                        .and_then(|p| factor.checked_mul(p))
                    {
                        Some(product) => factor = product,
                        None => other *= (f as f64).powf(e2 as f64 / 2.0),
                    }
                }
            }
            Scale::Irrational(x) => other *= if e2 == 2 { x } else { x.powf(e2 as f64 / 2.0) },
        }
    }
    if halves % 2 != 0 {
        other *= 10f64.sqrt();
        halves -= 1;
    }
    let shift = i32::try_from(halves / 2).ok()?;
    Some(if other == 1.0 {
        Scale::Decimal { factor, shift }
    } else {
        Scale::Irrational(other * factor as f64 * 10f64.powi(shift))
    })
}

/// The number a value's text starts with and the rest (the unit), both
/// trimmed: everything up to the first character that cannot continue a
/// number (a unit never starts with a digit, `.`, `+`, `-`; an `e`
/// continues the number only if a digit or sign follows).
pub(crate) fn split_number(text: &str) -> (&str, &str) {
    let text = text.trim();
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
    (text[..end].trim(), text[end..].trim())
}

/// The first word of `text` if it reads as a number that is not finite
/// (`NaN`, `inf`, `-infinity`: what Rust's number parser takes and no
/// scene means).
pub(crate) fn non_finite_word(text: &str) -> Option<&str> {
    let word = text.split_whitespace().next()?;
    word.parse::<f64>()
        .is_ok_and(|v| !v.is_finite())
        .then_some(word)
}

/// The message for a unit with white space inside (`25 m m`): `mm` and
/// `m*m` differ, so neither is guessed.
pub(crate) fn spaced_unit(text: &str, unit: &str, units: &[String]) -> String {
    let words: Vec<&str> = unit.split_whitespace().collect();
    let joined = words.concat();
    let product = words.join("*");
    let fits: Vec<&String> = units
        .iter()
        .filter(|u| **u == joined || **u == product)
        .collect();
    let shown = super::super::diagnostic::escaped(text);
    let unit = super::super::diagnostic::escaped(unit);
    let help = match fits.as_slice() {
        [one] => format!("write the unit without spaces: `{one}`"),
        _ => format!(
            "write the unit without spaces (`{}` and `{}` are different units)",
            super::super::diagnostic::escaped(&joined),
            super::super::diagnostic::escaped(&product)
        ),
    };
    format!(
        "`{shown}` has a space inside its unit `{unit}`; a unit is written without spaces\nhelp: {help}"
    )
}

/// `value` (in `si`, read from `text`; `si` empty for a plain number) if
/// it is a normal number or zero: NaN, infinities, subnormal numbers
/// (nonzero, below f64::MIN_POSITIVE ≈ 2.2e-308 in magnitude, which lose
/// precision and overflow when divided by) and a nonzero number that
/// underflows to 0 are refused.
pub(crate) fn normal(
    text: &str,
    value: f64,
    written_nonzero: bool,
    si: &str,
) -> Result<f64, String> {
    let shown = super::super::diagnostic::escaped(text);
    if !value.is_finite() {
        return Err(format!("`{shown}` is not a finite number"));
    }
    if value != 0.0 && value.abs() < f64::MIN_POSITIVE {
        let is = if si.is_empty() {
            " is".to_owned()
        } else {
            format!(" is {value:e} {si},")
        };
        return Err(format!(
            "`{shown}`{is} a subnormal number (nonzero, below {:e} in magnitude): too small \
             to compute with\nhelp: write 0, or check the exponent",
            f64::MIN_POSITIVE
        ));
    }
    if value == 0.0 && written_nonzero {
        return Err(format!(
            "`{shown}` is too small to be represented: it would be read as 0\nhelp: write 0, \
             or check the exponent"
        ));
    }
    Ok(value)
}

/// Whether the mantissa of a number as written has a nonzero digit.
pub(crate) fn nonzero_digits(number: &str) -> bool {
    number
        .split(['e', 'E'])
        .next()
        .is_some_and(|m| m.bytes().any(|b| (b'1'..=b'9').contains(&b)))
}

impl Dimension {
    /// The units as a message lists them: `m, mm, cm, km`.
    fn unit_list(&self) -> String {
        self.listed.join(", ")
    }

    /// The scale of `unit` (canonical) if it is a unit of this dimension.
    fn scale(&self, unit: &str) -> Option<Scale> {
        if let Some(&(_, scale)) = self.aliases.iter().find(|a| a.0 == unit) {
            return Some(scale);
        }
        self.forms.iter().find_map(|form| scale_in(form, unit))
    }

    /// Reads `"<number> <unit>"` into SI, or says why not (a `help:` line
    /// after a line break, if there is one).
    pub fn parse(&self, text: &str) -> Result<f64, String> {
        let text = text.trim();
        let shown = super::super::diagnostic::escaped(text);
        if let Some(word) = non_finite_word(text) {
            return Err(format!(
                "`{}` in `{shown}` is not a finite number\nhelp: write {} as a number in {} or \
                 with its unit ({})",
                super::super::diagnostic::escaped(word),
                self.name,
                self.si,
                self.unit_list()
            ));
        }
        let (number, unit) = split_number(text);
        let written: f64 = number.parse().map_err(|_| {
            format!(
                "`{shown}` is not {}: write a number in {} or one with its unit ({})",
                self.name,
                self.si,
                self.unit_list()
            )
        })?;
        if unit.is_empty() {
            return Err(format!(
                "`{shown}` has no unit; write {} as a plain number ({}) or with one of {}",
                self.name,
                self.si,
                self.unit_list()
            ));
        }
        if unit.contains(char::is_whitespace) {
            let words: Vec<&str> = unit.split_whitespace().collect();
            let candidates: Vec<String> = [words.concat(), words.join("*")]
                .into_iter()
                .filter(|u| self.scale(&canonical(u)).is_some())
                .collect();
            return Err(spaced_unit(text, unit, &candidates));
        }
        let unit = canonical(unit);
        let Some(scale) = self.scale(&unit) else {
            let escaped_unit = super::super::diagnostic::escaped(&unit);
            let found = ALL.iter().find(|d| d.scale(&unit).is_some()).map_or_else(
                || format!("the unknown unit `{escaped_unit}`"),
                |d| format!("{} (`{escaped_unit}`)", d.name),
            );
            // A bare `g` as a gram: say why it is not one.
            let gram = factors(&unit).is_some_and(|f| f.iter().any(|&(_, base, _)| base == "g"));
            let help = if gram {
                "\nhelp: write the gram with a prefix (`kg`, `mg`): a bare `g` is standard \
                 gravity, 9.80665 m/s²"
            } else {
                ""
            };
            return Err(format!(
                "expected {} ({}), found {found} in `{shown}`{help}",
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
        normal(text, value, nonzero_digits(number), self.si)
    }

    /// The JSON Schema of a value of this dimension: a number (SI) or a
    /// string with one of its units.
    pub fn schema(&self) -> Schema {
        // The units listed first, as written (readable), then every
        // spelling the forms take.
        let mut alternatives: Vec<String> = Vec::new();
        for alternative in self
            .listed
            .iter()
            .map(|u| regex_escape(u))
            .chain(self.aliases.iter().map(|a| regex_escape(a.0)))
            .chain(self.forms.iter().map(|f| form_pattern(f)))
            .chain(self.spellings())
        {
            if !alternatives.contains(&alternative) {
                alternatives.push(alternative);
            }
        }
        let pattern = format!(
            r"^\s*[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?\s*({})\s*$",
            alternatives.join("|")
        );
        let example = self.listed.get(1).unwrap_or(&self.listed[0]);
        json_schema!({
            "description": format!(
                "{}: a number in {} or a string with its unit ({}; {PREFIXED})",
                self.name,
                self.si,
                self.unit_list()
            ),
            "anyOf": [
                {"type": "number", "description": self.si},
                {
                    "type": "string",
                    "pattern": pattern,
                    "description": format!("with its unit: {} ({PREFIXED})", self.unit_list())
                }
            ],
            "examples": [format!("1 {example}")]
        })
    }

    /// Spellings [`canonical`] accepts beyond the forms, as regular
    /// expressions: `Ns/m` for `N*s/m`, `m/s2`, `°`.
    fn spellings(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.forms.contains(&"N*s/m") {
            out.push(format!("{}?Ns\\/m", prefix_pattern()));
        }
        if self.forms.contains(&"m/s^2") {
            out.push("m\\/s2".into());
        }
        if self.forms.contains(&"deg") {
            out.push("°".into());
        }
        out
    }
}

/// The SI prefixes as a regular expression group.
fn prefix_pattern() -> String {
    let names: Vec<&str> = PREFIXES.iter().map(|p| p.0).collect();
    format!("({})", names.join("|"))
}

/// A form as a regular expression: each symbol with its prefixes, `*` in
/// any of its spellings, `^2`/`^3` also as `²`/`³`.
fn form_pattern(form: &str) -> String {
    let mut out = String::new();
    for (i, (divides, base, exponent)) in factors(form).unwrap_or_default().into_iter().enumerate()
    {
        if i > 0 {
            out.push_str(if divides { "\\/" } else { "(\\*|·|×|⋅)" });
        }
        let symbol = SYMBOLS.iter().find(|s| s.name == base);
        match symbol.map(|s| s.prefixes) {
            Some(Prefixes::Optional) => out.push_str(&format!("{}?", prefix_pattern())),
            Some(Prefixes::Required) => out.push_str(&prefix_pattern()),
            _ => {}
        }
        out.push_str(&regex_escape(base));
        match exponent {
            "1" => {}
            "2" => out.push_str("(\\^2|²)"),
            "3" => out.push_str("(\\^3|³)"),
            e => out.push_str(&format!("\\^{}", regex_escape(e))),
        }
    }
    out
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
        if non_finite_word(v).is_some() {
            return self.0.parse(v).map_err(E::custom);
        }
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
