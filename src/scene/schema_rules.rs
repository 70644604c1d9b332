//! Value rules for `#[schemars(transform = …)]`: each the JSON Schema side
//! of a check of the format (`src/scenario`, named in its doc). Here, below
//! the format, because the scene's shared types (grids, Ritz terms, rotation
//! signs) carry them too.

use schemars::Schema;
use serde_json::{Map, Value};

pub(crate) fn set(schema: &mut Schema, key: &str, value: impl Into<Value>) {
    schema.insert(key.into(), value.into());
}

/// The items of an array schema (`"items"`), created if absent.
fn items(schema: &mut Schema) -> &mut Map<String, Value> {
    let items = schema
        .ensure_object()
        .entry("items")
        .or_insert_with(|| Value::Object(Map::new()));
    if !items.is_object() {
        *items = Value::Object(Map::new());
    }
    items.as_object_mut().expect("an object was just put there")
}

/// A number > 0 (`Checker::positive`).
pub fn positive(schema: &mut Schema) {
    set(schema, "exclusiveMinimum", 0.0);
}

/// A number ≥ 0 (`Checker::non_negative`).
pub fn non_negative(schema: &mut Schema) {
    set(schema, "minimum", 0.0);
}

/// A number ≤ 0 (a start position on the approach).
pub fn non_positive(schema: &mut Schema) {
    set(schema, "maximum", 0.0);
}

/// A ratio in [0, 1) (`check_ratio`: damping ratios).
pub fn ratio(schema: &mut Schema) {
    set(schema, "minimum", 0.0);
    set(schema, "exclusiveMaximum", 1.0);
}

/// A count ≥ 1 (modes, elements, terms, grid points, samples, spans…).
pub fn at_least_one(schema: &mut Schema) {
    set(schema, "minimum", 1);
}

/// A count ≥ 2 (envelope points: both deck ends).
pub fn at_least_two(schema: &mut Schema) {
    set(schema, "minimum", 2);
}

/// A list with at least one entry.
pub fn non_empty(schema: &mut Schema) {
    set(schema, "minItems", 1);
}

/// A list with at least one entry, each > 0 (spans, axle loads).
pub fn positive_list(schema: &mut Schema) {
    non_empty(schema);
    items(schema).insert("exclusiveMinimum".into(), 0.0.into());
}

/// A list whose entries are each > 0 (axle spacings, Rayleigh frequencies).
pub fn positive_items(schema: &mut Schema) {
    items(schema).insert("exclusiveMinimum".into(), 0.0.into());
}

/// A list with at least one entry, each ≥ 0 (girder lines).
pub fn non_negative_list(schema: &mut Schema) {
    non_empty(schema);
    items(schema).insert("minimum".into(), 0.0.into());
}

/// A non-empty name (`name`, record names).
pub fn non_empty_string(schema: &mut Schema) {
    set(schema, "minLength", 1);
}

/// A sign: −1 or +1 (`rotation_sign`).
pub fn sign(schema: &mut Schema) {
    set(schema, "enum", vec![Value::from(-1), Value::from(1)]);
}

/// Elements per span: 1 to [`super::MAX_ELEMENTS_PER_SPAN`] (`bridges::elements`).
pub fn elements_per_span(schema: &mut Schema) {
    at_least_one(schema);
    set(schema, "maximum", super::MAX_ELEMENTS_PER_SPAN);
}

/// An isotropic plate's Poisson ratio, in [0, 0.5).
pub fn isotropic_poisson(schema: &mut Schema) {
    set(schema, "minimum", 0.0);
    set(schema, "exclusiveMaximum", 0.5);
}

/// The iterative solver's tolerance, in (0, 1).
pub fn iteration_tolerance(schema: &mut Schema) {
    positive(schema);
    set(schema, "exclusiveMaximum", 1.0);
}

/// The iterative solver's iteration limit, 1 to 100 000.
pub fn max_iterations(schema: &mut Schema) {
    at_least_one(schema);
    set(schema, "maximum", 100_000);
}

/// Newmark γ ≥ 1/2 (below it the scheme amplifies every mode).
pub fn newmark_gamma(schema: &mut Schema) {
    set(schema, "minimum", 0.5);
}

/// HHT α in [−1/3, 0].
pub fn hht_alpha(schema: &mut Schema) {
    set(schema, "minimum", -1.0 / 3.0);
    set(schema, "maximum", 0.0);
}

/// Values of a study grid: 1 to 500.
pub fn grid_count(schema: &mut Schema) {
    at_least_one(schema);
    set(schema, "maximum", 500);
}

/// The HS20-44 rear axle spacing V, 14 ft to 30 ft (AASHTO Fig. 3.7.7A;
/// `scenario::vehicles`, the `aashto_hs20_44` check).
pub fn hs20_44_rear_spacing(schema: &mut Schema) {
    set(schema, "minimum", super::aashto::HS20_44_REAR_SPACING_MIN);
    set(schema, "maximum", super::aashto::HS20_44_REAR_SPACING_MAX);
}
