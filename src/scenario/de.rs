//! A serde `Deserializer` over the marked tree of `super::yaml`.
//!
//! Two things distinguish it from a generic YAML deserializer:
//!
//! * **Located errors.** Every `deserialize_*` call for a node stamps that
//!   node's location on an error that does not have one yet. The innermost node
//!   therefore wins: an unknown field points at its key (serde deserializes the
//!   field identifier from the key node), a missing field at the mapping that
//!   lacks it (serde raises it from `visit_map`), a type error at the value.
//! * **`type`-dispatched enums.** `deserialize_enum` reads the variant name from
//!   the mapping's `type` key and hands the *same* mapping, minus that entry,
//!   to the variant. Unlike `#[serde(tag = "type")]` this never buffers the
//!   content, so positions survive, and `type` may appear anywhere in the
//!   mapping. A variant whose fields all have defaults may be written as its
//!   bare name (`contact: rigid` for `contact: {type: rigid}`).
//! * **Placeholders.** A [`NodeKind::Placeholder`] (put by the type checker
//!   where a required field's value had a type error) reads as the simplest
//!   value of the type asked for, so that the rest of its mapping is read.

use super::yaml::{Location, Node, NodeKind, Resolved, resolve_plain};
use serde::de::{
    self, DeserializeSeed, EnumAccess, Expected, MapAccess, SeqAccess, Unexpected, VariantAccess,
    Visitor,
};

#[derive(Debug, Clone, thiserror::Error)]
#[error("{message}")]
pub struct DeError {
    pub loc: Option<Location>,
    pub message: String,
    /// What to write instead, as a `help:` line: the part of a custom
    /// message after `\nhelp: ` (a value's reader says it there).
    pub help: Option<String>,
}

impl de::Error for DeError {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        let text = msg.to_string();
        let (message, help) = match text.split_once("\nhelp: ") {
            Some((message, help)) => (message.to_owned(), Some(help.to_owned())),
            None => (text, None),
        };
        DeError {
            loc: None,
            message,
            help,
        }
    }
}

impl DeError {
    /// Attach `loc` unless an inner node already did.
    fn at(mut self, loc: Location) -> Self {
        self.loc.get_or_insert(loc);
        self
    }

    fn located(loc: Location, message: impl Into<String>) -> Self {
        DeError {
            loc: Some(loc),
            message: message.into(),
            help: None,
        }
    }
}

/// Deserialize `T` from `node`. The returned error always carries a location.
pub fn from_node<T: de::DeserializeOwned>(node: &Node) -> Result<T, DeError> {
    T::deserialize(NodeDeserializer::new(node)).map_err(|e| e.at(node.loc))
}

/// Deserializer for one node. `skip` hides one entry of a mapping: the `type`
/// key once it has selected an enum variant.
#[derive(Clone, Copy)]
pub struct NodeDeserializer<'de> {
    node: &'de Node,
    skip: Option<usize>,
}

impl<'de> NodeDeserializer<'de> {
    pub fn new(node: &'de Node) -> Self {
        NodeDeserializer { node, skip: None }
    }

    fn unexpected(&self) -> Unexpected<'de> {
        match &self.node.kind {
            NodeKind::Null => Unexpected::Other("null"),
            NodeKind::Scalar { text, plain: false } => Unexpected::Str(text),
            NodeKind::Scalar { text, plain: true } => match resolve_plain(text) {
                Resolved::Bool(b) => Unexpected::Bool(b),
                Resolved::Int(i) => match i64::try_from(i) {
                    Ok(v) => Unexpected::Signed(v),
                    Err(_) => Unexpected::Other("integer"),
                },
                Resolved::IntOverflow => Unexpected::Other("integer"),
                Resolved::Float(f) => Unexpected::Float(f),
                Resolved::Null | Resolved::Str(_) => Unexpected::Str(text),
            },
            NodeKind::Sequence(_) => Unexpected::Seq,
            NodeKind::Mapping(_) => Unexpected::Map,
            NodeKind::Placeholder => Unexpected::Other("a placeholder"),
        }
    }

    fn is_placeholder(&self) -> bool {
        matches!(self.node.kind, NodeKind::Placeholder)
    }

    fn invalid_type(&self, exp: &dyn Expected) -> DeError {
        de::Error::invalid_type(self.unexpected(), exp)
    }

    /// Text of any scalar, plain or quoted.
    fn text(&self, exp: &dyn Expected) -> Result<&'de str, DeError> {
        if self.is_placeholder() {
            return Ok("");
        }
        self.node.as_str().ok_or_else(|| self.invalid_type(exp))
    }

    /// A plain scalar with integer syntax, as an `i128`.
    fn integer(&self, exp: &dyn Expected) -> Result<i128, DeError> {
        match &self.node.kind {
            NodeKind::Placeholder => Ok(1),
            NodeKind::Scalar { text, plain: true } => match resolve_plain(text) {
                Resolved::Int(i) => Ok(i),
                Resolved::IntOverflow => Err(de::Error::custom(format_args!(
                    "`{text}` is out of range for {exp}"
                ))),
                _ => Err(self.invalid_type(exp)),
            },
            _ => Err(self.invalid_type(exp)),
        }
    }

    /// A plain scalar with int or float syntax that evaluates to a finite f64.
    fn float(&self, exp: &dyn Expected) -> Result<f64, DeError> {
        if self.is_placeholder() {
            return Ok(1.0);
        }
        let NodeKind::Scalar { text, plain: true } = &self.node.kind else {
            return Err(self.invalid_type(exp));
        };
        let value = match resolve_plain(text) {
            Resolved::Int(i) => i as f64,
            Resolved::IntOverflow => text.parse().unwrap_or(f64::INFINITY),
            Resolved::Float(f) => f,
            _ => return Err(self.invalid_type(exp)),
        };
        let nonzero = super::raw::units::nonzero_digits(text);
        super::raw::units::normal(text, value, nonzero, "").map_err(de::Error::custom)
    }

    fn entries(&self) -> Option<MapDeserializer<'de>> {
        match &self.node.kind {
            NodeKind::Mapping(entries) => Some(MapDeserializer::new(entries, self.skip)),
            _ => None,
        }
    }
}

macro_rules! deserialize_int {
    ($($method:ident => $visit:ident($ty:ty)),* $(,)?) => {$(
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
            let r = self.integer(&visitor).and_then(|i| match <$ty>::try_from(i) {
                Ok(v) => visitor.$visit(v),
                Err(_) => Err(de::Error::custom(format_args!(
                    "`{i}` is out of range for {}",
                    &visitor as &dyn Expected
                ))),
            });
            r.map_err(|e| e.at(self.node.loc))
        }
    )*};
}

impl<'de> de::Deserializer<'de> for NodeDeserializer<'de> {
    type Error = DeError;

    deserialize_int! {
        deserialize_i8 => visit_i8(i8),
        deserialize_i16 => visit_i16(i16),
        deserialize_i32 => visit_i32(i32),
        deserialize_i64 => visit_i64(i64),
        deserialize_i128 => visit_i128(i128),
        deserialize_u8 => visit_u8(u8),
        deserialize_u16 => visit_u16(u16),
        deserialize_u32 => visit_u32(u32),
        deserialize_u64 => visit_u64(u64),
        deserialize_u128 => visit_u128(u128),
    }

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match &self.node.kind {
            NodeKind::Null => visitor.visit_unit(),
            NodeKind::Scalar { text, plain: false } => visitor.visit_borrowed_str(text),
            NodeKind::Scalar { text, plain: true } => match resolve_plain(text) {
                Resolved::Null => visitor.visit_unit(),
                Resolved::Bool(b) => visitor.visit_bool(b),
                Resolved::Int(i) => match (i64::try_from(i), u64::try_from(i)) {
                    (Ok(v), _) => visitor.visit_i64(v),
                    (_, Ok(v)) => visitor.visit_u64(v),
                    _ => visitor.visit_i128(i),
                },
                // Non-finite numbers are rejected here too, so that untagged
                // enums cannot smuggle a NaN past `deserialize_f64`.
                Resolved::IntOverflow | Resolved::Float(_) => {
                    self.float(&"a number").and_then(|f| visitor.visit_f64(f))
                }
                Resolved::Str(s) => visitor.visit_borrowed_str(s),
            },
            NodeKind::Sequence(_) => return self.deserialize_seq(visitor),
            NodeKind::Mapping(_) => return self.deserialize_map(visitor),
            NodeKind::Placeholder => visitor.visit_u64(1),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_bool<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match &self.node.kind {
            NodeKind::Placeholder => visitor.visit_bool(false),
            NodeKind::Scalar { text, plain: true } => match resolve_plain(text) {
                Resolved::Bool(b) => visitor.visit_bool(b),
                _ => Err(self.invalid_type(&visitor)),
            },
            _ => Err(self.invalid_type(&visitor)),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_f32<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = self.float(&visitor).and_then(|f| {
            let narrow = f as f32;
            if narrow.is_finite() {
                visitor.visit_f32(narrow)
            } else {
                let text = self.node.as_str().unwrap_or_default();
                Err(de::Error::custom(format_args!(
                    "`{text}` is out of range for f32"
                )))
            }
        });
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_f64<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = self.float(&visitor).and_then(|f| visitor.visit_f64(f));
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_char<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = self.text(&visitor).and_then(|s| {
            let mut chars = s.chars();
            match (chars.next(), chars.next()) {
                (Some(c), None) => visitor.visit_char(c),
                _ => Err(de::Error::invalid_value(Unexpected::Str(s), &visitor)),
            }
        });
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_str<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = self
            .text(&visitor)
            .and_then(|s| visitor.visit_borrowed_str(s));
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_string<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        self.deserialize_str(visitor)
    }

    fn deserialize_bytes<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = self
            .text(&visitor)
            .and_then(|s| visitor.visit_borrowed_bytes(s.as_bytes()));
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_byte_buf<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        self.deserialize_bytes(visitor)
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match self.node.kind {
            NodeKind::Null => visitor.visit_none(),
            _ => visitor.visit_some(self),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_unit<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match self.node.kind {
            NodeKind::Null | NodeKind::Placeholder => visitor.visit_unit(),
            _ => Err(self.invalid_type(&visitor)),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_unit_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, DeError> {
        self.deserialize_unit(visitor)
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        visitor: V,
    ) -> Result<V::Value, DeError> {
        // A count or a list of counts (`elements_per_span`): the list to
        // `visit_seq`, anything else read as the count field it is.
        if name == super::raw::COUNT_OR_LIST && matches!(self.node.kind, NodeKind::Sequence(_)) {
            return self.deserialize_seq(visitor);
        }
        visitor
            .visit_newtype_struct(self)
            .map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_seq<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match &self.node.kind {
            NodeKind::Sequence(items) => {
                let mut seq = SeqDeserializer {
                    items: items.iter(),
                    count: 0,
                };
                visitor
                    .visit_seq(&mut seq)
                    .and_then(|v| seq.end().map(|()| v))
            }
            _ => Err(self.invalid_type(&visitor)),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_tuple<V: Visitor<'de>>(
        self,
        _len: usize,
        visitor: V,
    ) -> Result<V::Value, DeError> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _len: usize,
        visitor: V,
    ) -> Result<V::Value, DeError> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_map<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match self.entries() {
            Some(mut map) => visitor
                .visit_map(&mut map)
                .and_then(|v| map.end().map(|()| v)),
            None => Err(self.invalid_type(&visitor)),
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, DeError> {
        self.deserialize_map(visitor)
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, DeError> {
        let node = self.node;
        let r = match &node.kind {
            // The first variant; one with fields makes the placeholder fail
            // (the type checker then drops it, and its mapping).
            NodeKind::Placeholder => visitor.visit_enum(PlaceholderVariant {
                name: variants.first().copied().unwrap_or_default(),
            }),
            NodeKind::Scalar { .. } => visitor.visit_enum(EnumDeserializer {
                tag: node,
                map: None,
            }),
            NodeKind::Mapping(entries) => {
                let found = entries
                    .iter()
                    .enumerate()
                    .find(|(i, (k, _))| Some(*i) != self.skip && k.as_str() == Some("type"));
                match found {
                    None => Err(DeError::located(
                        node.loc,
                        format!("missing `type`; expected one of {}", one_of(variants)),
                    )),
                    Some((_, (_, tag))) if tag.as_str().is_none() => Err(DeError::located(
                        tag.loc,
                        format!(
                            "`type` must name a variant; expected one of {}",
                            one_of(variants)
                        ),
                    )),
                    Some((i, (_, tag))) => {
                        let map = NodeDeserializer {
                            node,
                            skip: Some(i),
                        };
                        visitor.visit_enum(EnumDeserializer {
                            tag,
                            map: Some(map),
                        })
                    }
                }
            }
            _ => Err(self.invalid_type(&visitor)),
        };
        r.map_err(|e| e.at(node.loc))
    }

    fn deserialize_identifier<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        self.deserialize_str(visitor)
    }

    fn deserialize_ignored_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        visitor.visit_unit()
    }
}

fn one_of(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    quoted.join(", ")
}

struct SeqDeserializer<'de> {
    items: std::slice::Iter<'de, Node>,
    count: usize,
}

impl SeqDeserializer<'_> {
    /// Reject elements the visitor did not consume (e.g. a too-long tuple).
    fn end(&mut self) -> Result<(), DeError> {
        match self.items.next() {
            None => Ok(()),
            Some(extra) => Err(DeError::located(
                extra.loc,
                format!(
                    "unexpected extra element; expected {} element(s)",
                    self.count
                ),
            )),
        }
    }
}

impl<'de> SeqAccess<'de> for SeqDeserializer<'de> {
    type Error = DeError;

    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, DeError> {
        match self.items.next() {
            None => Ok(None),
            Some(item) => {
                self.count += 1;
                seed.deserialize(NodeDeserializer::new(item)).map(Some)
            }
        }
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.items.len())
    }
}

/// Walks a mapping's entries, hiding the one at `skip`.
struct MapDeserializer<'de> {
    entries: std::iter::Enumerate<std::slice::Iter<'de, (Node, Node)>>,
    skip: Option<usize>,
    value: Option<&'de Node>,
}

impl<'de> MapDeserializer<'de> {
    fn new(entries: &'de [(Node, Node)], skip: Option<usize>) -> Self {
        MapDeserializer {
            entries: entries.iter().enumerate(),
            skip,
            value: None,
        }
    }

    fn next_entry_ref(&mut self) -> Option<&'de (Node, Node)> {
        let skip = self.skip;
        self.entries
            .by_ref()
            .find(|(i, _)| Some(*i) != skip)
            .map(|(_, e)| e)
    }

    /// Reject entries the visitor did not consume.
    fn end(&mut self) -> Result<(), DeError> {
        match self.next_entry_ref() {
            None => Ok(()),
            Some((k, _)) => Err(DeError::located(k.loc, "unexpected extra key")),
        }
    }
}

impl<'de> MapAccess<'de> for MapDeserializer<'de> {
    type Error = DeError;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, DeError> {
        match self.next_entry_ref() {
            None => Ok(None),
            Some((k, v)) => {
                self.value = Some(v);
                seed.deserialize(NodeDeserializer::new(k)).map(Some)
            }
        }
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, DeError> {
        match self.value.take() {
            Some(v) => seed.deserialize(NodeDeserializer::new(v)),
            None => Err(de::Error::custom("next_value called before next_key")),
        }
    }

    fn size_hint(&self) -> Option<usize> {
        let (_, upper) = self.entries.size_hint();
        upper
    }
}

/// Enum access: `tag` names the variant (a scalar, or a mapping's `type`
/// value); `map` is the mapping minus `type`, absent for a bare scalar.
struct EnumDeserializer<'de> {
    tag: &'de Node,
    map: Option<NodeDeserializer<'de>>,
}

impl<'de> EnumAccess<'de> for EnumDeserializer<'de> {
    type Error = DeError;
    type Variant = Self;

    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self), DeError> {
        let v = seed.deserialize(NodeDeserializer::new(self.tag))?;
        Ok((v, self))
    }
}

impl<'de> EnumDeserializer<'de> {
    fn name(&self) -> &'de str {
        self.tag.as_str().unwrap_or_default()
    }

    /// A bare tag read as the variant with no fields given: fine if they
    /// all have defaults, else the message says to write the mapping.
    fn bare<T>(&self, kind: &str, read: Result<T, DeError>) -> Result<T, DeError> {
        read.map_err(|e| {
            let name = self.name();
            if e.message.starts_with("missing field") || e.message.starts_with("missing `type`") {
                DeError::located(
                    self.tag.loc,
                    format!(
                        "`{name}` is a {kind}: write it as a mapping with `type: {name}` and its \
                         fields"
                    ),
                )
            } else {
                e.at(self.tag.loc)
            }
        })
    }
}

/// A mapping with no entries, at `loc`: the content of a variant written as
/// its bare tag.
struct EmptyMapping {
    loc: super::yaml::Location,
}

impl<'de> de::Deserializer<'de> for EmptyMapping {
    type Error = DeError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let mut map = MapDeserializer::new(&[], None);
        visitor.visit_map(&mut map).map_err(|e| e.at(self.loc))
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        variants: &'static [&'static str],
        _visitor: V,
    ) -> Result<V::Value, DeError> {
        Err(DeError::located(
            self.loc,
            format!("missing `type`; expected one of {}", one_of(variants)),
        ))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map struct identifier ignored_any
    }
}

/// The variant a placeholder reads as: `name`, with no content.
struct PlaceholderVariant {
    name: &'static str,
}

impl<'de> EnumAccess<'de> for PlaceholderVariant {
    type Error = DeError;
    type Variant = Self;

    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self), DeError> {
        let name: de::value::StrDeserializer<'_, DeError> =
            de::IntoDeserializer::into_deserializer(self.name);
        let v = seed.deserialize(name)?;
        Ok((v, self))
    }
}

impl<'de> VariantAccess<'de> for PlaceholderVariant {
    type Error = DeError;

    fn unit_variant(self) -> Result<(), DeError> {
        Ok(())
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, _seed: T) -> Result<T::Value, DeError> {
        Err(de::Error::custom("a placeholder has no fields"))
    }

    fn tuple_variant<V: Visitor<'de>>(self, _len: usize, _visitor: V) -> Result<V::Value, DeError> {
        Err(de::Error::custom("a placeholder has no fields"))
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        _visitor: V,
    ) -> Result<V::Value, DeError> {
        Err(de::Error::custom("a placeholder has no fields"))
    }
}

impl<'de> VariantAccess<'de> for EnumDeserializer<'de> {
    type Error = DeError;

    fn unit_variant(self) -> Result<(), DeError> {
        let Some(map) = self.map else { return Ok(()) };
        match map.entries().and_then(|mut m| m.next_entry_ref()) {
            None => Ok(()),
            Some((k, _)) => Err(DeError::located(
                k.loc,
                format!(
                    "unexpected key `{}` for `type: {}`",
                    k.as_str().unwrap_or("null"),
                    self.name()
                ),
            )),
        }
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, DeError> {
        match self.map {
            Some(map) => seed.deserialize(map),
            None => {
                let read = seed.deserialize(EmptyMapping { loc: self.tag.loc });
                self.bare("variant with parameters", read)
            }
        }
    }

    fn tuple_variant<V: Visitor<'de>>(self, _len: usize, _visitor: V) -> Result<V::Value, DeError> {
        let loc = self.map.map_or(self.tag.loc, |m| m.node.loc);
        Err(DeError::located(
            loc,
            format!(
                "variant `{}` is a tuple variant, which is not supported",
                self.name()
            ),
        ))
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, DeError> {
        match self.map {
            Some(map) => de::Deserializer::deserialize_map(map, visitor),
            None => {
                let read =
                    de::Deserializer::deserialize_map(EmptyMapping { loc: self.tag.loc }, visitor);
                self.bare("variant with fields", read)
            }
        }
    }
}

#[cfg(test)]
mod tests;
