//! `elements_per_span` of a beam: one count for every span, or a list with
//! one count per span.

use std::borrow::Cow;
use std::fmt;

use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde::de::{Deserialize, Deserializer, SeqAccess, Visitor};

/// Finite elements per span as written: one count for all spans
/// (`elements_per_span: 20`) or one per span (`[8, 10, 8]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ElementsPerSpanRaw {
    /// The same count on every span.
    All(usize),
    /// One count per span, from the entrance.
    PerSpan(Vec<usize>),
}

/// The newtype name by which the format's deserializer
/// ([`crate::scenario::de`]) knows a count-or-list: it hands a sequence to
/// `visit_seq` and anything else to `visit_newtype_struct`, where the count
/// is read as a plain `usize` field reads it, so that a bad count (`-1`,
/// `2.5`, 2^64) gets the very message and location it gets today. Another
/// deserializer calls `visit_newtype_struct` for every value and reads the
/// integer form only (scenarios are read by the format's deserializer).
pub const COUNT_OR_LIST: &str = "$vbi::count_or_list";

struct CountOrList;

impl<'de> Visitor<'de> for CountOrList {
    type Value = ElementsPerSpanRaw;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a whole number, or a list of whole numbers (one per span)")
    }

    fn visit_newtype_struct<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        usize::deserialize(d).map(ElementsPerSpanRaw::All)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut counts = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(1024));
        while let Some(n) = seq.next_element::<usize>()? {
            counts.push(n);
        }
        Ok(ElementsPerSpanRaw::PerSpan(counts))
    }
}

impl<'de> Deserialize<'de> for ElementsPerSpanRaw {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_newtype_struct(COUNT_OR_LIST, CountOrList)
    }
}

impl JsonSchema for ElementsPerSpanRaw {
    fn schema_name() -> Cow<'static, str> {
        "ElementsPerSpanRaw".into()
    }

    fn inline_schema() -> bool {
        true
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let most = crate::scene::MAX_ELEMENTS_PER_SPAN;
        json_schema!({
            "anyOf": [
                {
                    "type": "integer",
                    "minimum": 1,
                    "maximum": most,
                    "description": "the same count on every span"
                },
                {
                    "type": "array",
                    "items": {"type": "integer", "minimum": 1, "maximum": most},
                    "minItems": 1,
                    "description": "one count per span, from the entrance"
                }
            ],
            "examples": [20, [8, 10, 8]]
        })
    }
}
