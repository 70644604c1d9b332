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
//!   mapping.

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
}

impl de::Error for DeError {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        DeError {
            loc: None,
            message: msg.to_string(),
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
        }
    }

    fn invalid_type(&self, exp: &dyn Expected) -> DeError {
        de::Error::invalid_type(self.unexpected(), exp)
    }

    /// Text of any scalar, plain or quoted.
    fn text(&self, exp: &dyn Expected) -> Result<&'de str, DeError> {
        self.node.as_str().ok_or_else(|| self.invalid_type(exp))
    }

    /// A plain scalar with integer syntax, as an `i128`.
    fn integer(&self, exp: &dyn Expected) -> Result<i128, DeError> {
        match &self.node.kind {
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
        let NodeKind::Scalar { text, plain: true } = &self.node.kind else {
            return Err(self.invalid_type(exp));
        };
        let value = match resolve_plain(text) {
            Resolved::Int(i) => i as f64,
            Resolved::IntOverflow => text.parse().unwrap_or(f64::INFINITY),
            Resolved::Float(f) => f,
            _ => return Err(self.invalid_type(exp)),
        };
        if value.is_finite() {
            Ok(value)
        } else {
            Err(de::Error::custom(format_args!(
                "`{text}` is not a finite number"
            )))
        }
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
        };
        r.map_err(|e| e.at(self.node.loc))
    }

    fn deserialize_bool<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        let r = match &self.node.kind {
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
            NodeKind::Null => visitor.visit_unit(),
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
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, DeError> {
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

    /// The variant's content; a bare scalar has none.
    fn content(&self, kind: &str) -> Result<NodeDeserializer<'de>, DeError> {
        self.map.ok_or_else(|| {
            let name = self.name();
            DeError::located(
                self.tag.loc,
                format!(
                    "`{name}` is a {kind}: write it as a mapping with `type: {name}` and its fields"
                ),
            )
        })
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
        let map = self.content("variant with parameters")?;
        seed.deserialize(map)
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
        let map = self.content("variant with fields")?;
        de::Deserializer::deserialize_map(map, visitor)
    }
}

#[cfg(test)]
mod tests {
    use super::super::yaml::{Location, parse};
    use super::*;
    use serde::Deserialize;

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(deny_unknown_fields)]
    struct Scene {
        name: String,
        bridge: Bridge,
        vehicles: Vec<Vehicle>,
        #[serde(default)]
        note: Option<String>,
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(rename_all = "snake_case")]
    enum Bridge {
        Beam(Beam),
        Plate(Plate),
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(deny_unknown_fields)]
    struct Beam {
        spans: Vec<f64>,
        bending_stiffness: f64,
        #[serde(default)]
        modes: Option<Modes>,
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(deny_unknown_fields)]
    struct Plate {
        width: f64,
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(rename_all = "snake_case", deny_unknown_fields)]
    enum Vehicle {
        Oscillator { sprung_mass: f64, speed: f64 },
        MovingForce { loads: Vec<f64> },
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(untagged)]
    enum Modes {
        Count { count: usize },
        MaxFrequency { max_frequency: f64 },
    }

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(rename_all = "snake_case", deny_unknown_fields)]
    enum Support {
        Pinned,
        Fixed,
        Spring { k: f64 },
        Pair(f64, f64),
        Wrapped(Plate),
        Nested(Bridge),
    }

    fn at(line: usize, col: usize) -> Option<Location> {
        Some(Location { line, col })
    }

    fn load<T: de::DeserializeOwned>(src: &str) -> Result<T, DeError> {
        from_node(&parse(src).expect("valid YAML").expect("non-empty"))
    }

    /// Deserialize and expect an error; returns (location, message).
    fn fail<T: de::DeserializeOwned + std::fmt::Debug>(src: &str) -> (Option<Location>, String) {
        let e = load::<T>(src).expect_err("expected an error");
        (e.loc, e.message)
    }

    const GOOD: &str = "\
name: demo
bridge:
  spans: [20.0, 30]
  bending_stiffness: 1.0e9
  modes: {count: 4}
  type: beam
vehicles:
  - type: oscillator
    sprung_mass: 4000
    speed: .5
  - {type: moving_force, loads: [1e5, -3]}
";

    #[test]
    fn good_scene_with_type_last_and_flow_vehicle() {
        let scene: Scene = load(GOOD).unwrap();
        let want = Scene {
            name: "demo".into(),
            bridge: Bridge::Beam(Beam {
                spans: vec![20.0, 30.0],
                bending_stiffness: 1e9,
                modes: Some(Modes::Count { count: 4 }),
            }),
            vehicles: vec![
                Vehicle::Oscillator {
                    sprung_mass: 4000.0,
                    speed: 0.5,
                },
                Vehicle::MovingForce {
                    loads: vec![1e5, -3.0],
                },
            ],
            note: None,
        };
        assert_eq!(scene, want);
    }

    #[test]
    fn flow_style_bridge_and_untagged_modes() {
        let src = "name: x\nbridge: {type: beam, spans: [20.0], bending_stiffness: 2, modes: {max_frequency: 50}}\nvehicles: []\nnote: hi\n";
        let scene: Scene = load(src).unwrap();
        let Bridge::Beam(beam) = &scene.bridge else {
            panic!("{scene:?}")
        };
        assert_eq!(beam.spans, vec![20.0]);
        assert_eq!(
            beam.modes,
            Some(Modes::MaxFrequency {
                max_frequency: 50.0
            })
        );
        assert_eq!(scene.note.as_deref(), Some("hi"));
        let src = "name: x\nbridge: {type: beam, spans: [1], bending_stiffness: 2, modes: {count: -1}}\nvehicles: []\n";
        let (loc, msg) = fail::<Scene>(src);
        assert_eq!(loc, at(2, 63));
        assert_eq!(msg, "data did not match any variant of untagged enum Modes");
    }

    #[test]
    fn unknown_key_in_newtype_variant_with_type_last() {
        let src = "name: demo\nbridge:\n  spans: [20.0]\n  bending_stifness: 1.0e9\n  type: beam\nvehicles: []\n";
        let (loc, msg) = fail::<Scene>(src);
        assert_eq!(loc, at(4, 3));
        assert_eq!(
            msg,
            "unknown field `bending_stifness`, expected one of `spans`, `bending_stiffness`, `modes`"
        );
    }

    #[test]
    fn unknown_key_in_struct_variant() {
        let src = GOOD.replace("    sprung_mass: 4000", "    sprung_mas: 4000");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(9, 5));
        assert_eq!(
            msg,
            "unknown field `sprung_mas`, expected `sprung_mass` or `speed`"
        );
    }

    #[test]
    fn wrong_type_deep_in_vehicle() {
        let src = GOOD.replace("speed: .5", "speed: \"fast\"");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(10, 12));
        assert_eq!(msg, "invalid type: string \"fast\", expected f64");
        let src = GOOD.replace("loads: [1e5, -3]", "loads: [1e5, abc]");
        assert_eq!(fail::<Scene>(&src).0, at(11, 39));
    }

    #[test]
    fn missing_field_points_at_mapping() {
        let src = GOOD.replace("    speed: .5\n", "");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(8, 5));
        assert_eq!(msg, "missing field `speed`");
        let src = GOOD.replace("  bending_stiffness: 1.0e9\n", "");
        assert_eq!(
            fail::<Scene>(&src),
            (at(3, 3), "missing field `bending_stiffness`".into())
        );
        assert_eq!(
            fail::<Scene>("name: x\nvehicles: []\n"),
            (at(1, 1), "missing field `bridge`".into())
        );
    }

    #[test]
    fn missing_type() {
        let src = GOOD.replace("  type: beam\n", "");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(3, 3));
        assert_eq!(msg, "missing `type`; expected one of `beam`, `plate`");
    }

    #[test]
    fn unknown_type_value() {
        let src = GOOD.replace("type: beam", "type: bem");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(6, 9));
        assert_eq!(msg, "unknown variant `bem`, expected `beam` or `plate`");
        let src = GOOD.replace("type: beam", "type: [beam]");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(6, 9));
        assert_eq!(
            msg,
            "`type` must name a variant; expected one of `beam`, `plate`"
        );
        let src = GOOD.replace("type: moving_force", "type: truck");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(11, 12));
        assert_eq!(
            msg,
            "unknown variant `truck`, expected `oscillator` or `moving_force`"
        );
    }

    #[test]
    fn non_finite_numbers_are_rejected() {
        for (text, col) in [(".nan", 12), ("1e400", 12), ("-.inf", 12), ("-1e999", 12)] {
            let src = GOOD.replace("speed: .5", &format!("speed: {text}"));
            let (loc, msg) = fail::<Scene>(&src);
            assert_eq!(
                (loc, msg),
                (at(10, col), format!("`{text}` is not a finite number"))
            );
        }
        // Also through `deserialize_any`, so untagged enums cannot sneak a NaN in.
        // (serde buffers untagged content with `deserialize_any` first, so
        // the error even survives the untagged enum and points at the value.)
        let src = GOOD.replace("{count: 4}", "{max_frequency: .nan}");
        assert_eq!(
            fail::<Scene>(&src),
            (at(5, 26), "`.nan` is not a finite number".into())
        );
        assert_eq!(
            fail::<serde_json::Value>("[.nan]"),
            (at(1, 2), "`.nan` is not a finite number".into())
        );
        assert_eq!(
            fail::<f32>("1e39"),
            (at(1, 1), "`1e39` is out of range for f32".into())
        );
    }

    #[test]
    fn numbers() {
        assert_eq!(
            load::<Vec<f64>>("[12, -3, 1.5, 1e5, 1.0e-4, .5, +1, 0x1F, 0o10]").unwrap(),
            [12.0, -3.0, 1.5, 1e5, 1e-4, 0.5, 1.0, 31.0, 8.0]
        );
        assert_eq!(load::<f32>("2.5").unwrap(), 2.5);
        assert_eq!(load::<Vec<u8>>("[0, 255, 0x10]").unwrap(), [0, 255, 16]);
        assert_eq!(
            load::<Vec<i64>>("[-9223372036854775808, +7]").unwrap(),
            [i64::MIN, 7]
        );
        assert_eq!(load::<usize>("42").unwrap(), 42);
        assert_eq!(
            load::<u128>("0xFFFFFFFFFFFFFFFFFFFF").unwrap(),
            0xFFFF_FFFF_FFFF_FFFF_FFFF
        );
        assert_eq!(
            fail::<Vec<u8>>("[1, 256]"),
            (at(1, 5), "`256` is out of range for u8".into())
        );
        assert_eq!(fail::<i8>("-129").1, "`-129` is out of range for i8");
        assert_eq!(fail::<u32>("-1").1, "`-1` is out of range for u32");
        assert_eq!(
            fail::<u64>("999999999999999999999999999999999999999999").1,
            "`999999999999999999999999999999999999999999` is out of range for u64"
        );
        assert_eq!(
            fail::<usize>("2.0").1,
            "invalid type: floating point `2.0`, expected usize"
        );
        assert_eq!(
            fail::<i32>("'3'").1,
            "invalid type: string \"3\", expected i32"
        );
        assert_eq!(
            fail::<f64>("\"abc\"").1,
            "invalid type: string \"abc\", expected f64"
        );
        assert_eq!(
            fail::<f64>("'1.5'").1,
            "invalid type: string \"1.5\", expected f64"
        );
        assert_eq!(
            fail::<f64>("true").1,
            "invalid type: boolean `true`, expected f64"
        );
        assert_eq!(fail::<f64>("~").1, "invalid type: null, expected f64");
        assert_eq!(fail::<f64>("[1]").1, "invalid type: sequence, expected f64");
    }

    #[test]
    fn bools_strings_options_units() {
        assert_eq!(
            load::<Vec<bool>>("[true, True, TRUE, false, False, FALSE]").unwrap(),
            [true, true, true, false, false, false]
        );
        assert_eq!(
            fail::<bool>("yes").1,
            "invalid type: string \"yes\", expected a boolean"
        );
        assert_eq!(
            fail::<bool>("'true'").1,
            "invalid type: string \"true\", expected a boolean"
        );
        assert_eq!(
            load::<Vec<String>>("- 123\n- 'q'\n- true\n- 1.5\n- \"\"\n- |\n  b\n").unwrap(),
            ["123", "q", "true", "1.5", "", "b\n"]
        );
        assert_eq!(
            fail::<String>("~").1,
            "invalid type: null, expected a string"
        );
        assert_eq!(
            fail::<String>("{a: 1}").1,
            "invalid type: map, expected a string"
        );
        assert_eq!(
            load::<Vec<Option<u8>>>("[~, 3, null, ]").unwrap(),
            [None, Some(3), None]
        );
        assert_eq!(load::<Vec<()>>("[~, null]").unwrap(), [(), ()]);
        assert_eq!(
            fail::<()>("0").1,
            "invalid type: integer `0`, expected unit"
        );
        assert_eq!(load::<char>("x").unwrap(), 'x');
        assert_eq!(
            fail::<char>("xy").1,
            "invalid value: string \"xy\", expected a character"
        );
    }

    #[test]
    fn sequences_tuples_maps() {
        assert_eq!(
            load::<(u8, String)>("[1, a]").unwrap(),
            (1, "a".to_string())
        );
        assert_eq!(
            fail::<(u8, u8)>("[1, 2, 3]"),
            (
                at(1, 8),
                "unexpected extra element; expected 2 element(s)".into()
            )
        );
        assert_eq!(
            fail::<(u8, u8)>("[1]").1,
            "invalid length 1, expected a tuple of size 2"
        );
        let m: std::collections::BTreeMap<String, f64> = load("{a: 1, b: 2.5}").unwrap();
        assert_eq!(
            m.into_iter().collect::<Vec<_>>(),
            [("a".into(), 1.0), ("b".into(), 2.5)]
        );
        assert_eq!(
            fail::<Vec<f64>>("x: 1").1,
            "invalid type: map, expected a sequence"
        );
        #[derive(Deserialize, Debug)]
        struct Meters(f64);
        assert_eq!(load::<Meters>("3").unwrap().0, 3.0);
        assert_eq!(
            fail::<Meters>("a"),
            (at(1, 1), "invalid type: string \"a\", expected f64".into())
        );
    }

    #[test]
    fn deserialize_any_follows_core_schema() {
        let v: serde_json::Value =
            load("{a: ~, b: True, c: -3, d: 18446744073709551615, e: 1.5, f: '7', g: [x]}")
                .unwrap();
        let want = serde_json::json!({"a": null, "b": true, "c": -3, "d": 18446744073709551615u64,
                                      "e": 1.5, "f": "7", "g": ["x"]});
        assert_eq!(v, want);
    }

    #[test]
    fn unit_struct_tuple_and_scalar_variants() {
        assert_eq!(load::<Support>("pinned").unwrap(), Support::Pinned);
        assert_eq!(load::<Support>("'fixed'").unwrap(), Support::Fixed);
        assert_eq!(load::<Support>("{type: pinned}").unwrap(), Support::Pinned);
        assert_eq!(
            load::<Support>("k: 2\ntype: spring").unwrap(),
            Support::Spring { k: 2.0 }
        );
        assert_eq!(
            load::<Support>("{type: wrapped, width: 3}").unwrap(),
            Support::Wrapped(Plate { width: 3.0 })
        );
        let (loc, msg) = fail::<Support>("type: fixed\nk: 1\n");
        assert_eq!(
            (loc, msg.as_str()),
            (at(2, 1), "unexpected key `k` for `type: fixed`")
        );
        let (loc, msg) = fail::<Support>("x: 1\ny: 2\n");
        let want = "missing `type`; expected one of `pinned`, `fixed`, `spring`, `pair`, `wrapped`, `nested`";
        assert_eq!((loc, msg.as_str()), (at(1, 1), want));
        let (loc, msg) = fail::<Vec<Support>>("- pinned\n- pinnned\n");
        assert_eq!(loc, at(2, 3));
        assert!(
            msg.starts_with("unknown variant `pinnned`, expected one of `pinned`"),
            "{msg}"
        );
        let (loc, msg) = fail::<Support>("spring");
        assert_eq!(loc, at(1, 1));
        assert_eq!(
            msg,
            "`spring` is a variant with fields: write it as a mapping with `type: spring` and its fields"
        );
        let (loc, msg) = fail::<Support>("{type: pair}");
        assert_eq!(
            (loc, msg.as_str()),
            (
                at(1, 1),
                "variant `pair` is a tuple variant, which is not supported"
            )
        );
        assert_eq!(
            fail::<Support>("[1]").1,
            "invalid type: sequence, expected enum Support"
        );
        assert_eq!(
            fail::<Support>("~").1,
            "invalid type: null, expected enum Support"
        );
        let (loc, msg) = fail::<Support>("{type: spring, k: 1, type2: 3}");
        assert_eq!(
            (loc, msg.as_str()),
            (at(1, 22), "unknown field `type2`, expected `k`")
        );
        // `type` is consumed by dispatch: an enum nested in the same mapping sees none.
        let (loc, msg) = fail::<Support>("{type: nested, spans: [1]}");
        assert_eq!(
            (loc, msg.as_str()),
            (at(1, 1), "missing `type`; expected one of `beam`, `plate`")
        );
    }

    #[test]
    fn aliases_deserialize() {
        let src = "name: a\nbridge: {type: plate, width: 4}\nvehicles:\n  - &v {type: oscillator, sprung_mass: 1, speed: 2}\n  - *v\n";
        let scene: Scene = load(src).unwrap();
        assert_eq!(scene.vehicles.len(), 2);
        assert_eq!(scene.vehicles[0], scene.vehicles[1]);
        // An error in an aliased node's root points at the alias.
        let src = "name: a\nbridge: &b {type: plate}\nvehicles:\n  - *b\n";
        let (loc, msg) = fail::<Scene>(src);
        assert_eq!((loc, msg.as_str()), (at(2, 12), "missing field `width`"));
        let src = "name: a\nbridge: {type: plate, width: 1}\nvehicles:\n  - *missing\n";
        assert!(parse(src).is_err());
    }

    #[test]
    fn root_errors_and_note() {
        assert_eq!(
            fail::<Scene>("[1]"),
            (
                at(1, 1),
                "invalid type: sequence, expected struct Scene".into()
            )
        );
        let src = GOOD.replace("name: demo", "name: demo\nnote: ~\nextra: 1");
        let (loc, msg) = fail::<Scene>(&src);
        assert_eq!(loc, at(3, 1));
        assert!(msg.starts_with("unknown field `extra`"), "{msg}");
    }
}
