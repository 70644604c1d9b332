//! Independent reference solutions shared by the physics tests.

pub mod reference;
