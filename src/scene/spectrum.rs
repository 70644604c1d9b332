//! The spectra a random track or road profile is sampled from (their
//! densities: `crate::surface::spectrum`).

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Interference level of the German high-speed spectra.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Interference {
    /// Low interference (good track): A_v = 4.032e-7, A_a = 2.119e-7 m·rad.
    Low,
    /// High interference: A_v = 1.080e-6, A_a = 6.125e-7 m·rad.
    High,
}

/// ISO 8608 road classes A (best) to H.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
pub enum IsoClass {
    /// G_d(n₀) = 16e-6 m³.
    A,
    /// 64e-6 m³.
    B,
    /// 256e-6 m³.
    C,
    /// 1024e-6 m³.
    D,
    /// 4096e-6 m³.
    E,
    /// 16384e-6 m³.
    F,
    /// 65536e-6 m³.
    G,
    /// 262144e-6 m³.
    H,
}

/// A spectrum a random track or road profile is sampled from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "spectrum", rename_all = "snake_case")]
pub enum Spectrum {
    /// FRA vertical profile, class 1–6 ([`fra_vertical`]).
    Fra {
        /// Track class 1 (worst) to 6 (best).
        class: u8,
    },
    /// German high-speed vertical profile ([`german_vertical`]).
    German {
        /// Interference level.
        interference: Interference,
    },
    /// ISO 8608 road class ([`iso8608`]).
    Iso8608 {
        /// Road class A–H.
        class: IsoClass,
    },
    /// FRA alignment (lateral), class 1–6 ([`fra_alignment`]).
    FraAlignment {
        /// Track class 1 (worst) to 6 (best).
        class: u8,
    },
    /// German high-speed alignment ([`german_alignment`]).
    GermanAlignment {
        /// Interference level.
        interference: Interference,
    },
}
