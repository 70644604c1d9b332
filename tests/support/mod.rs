//! Independent reference solutions shared by the physics tests.

pub mod event_reference;
pub mod reference;
