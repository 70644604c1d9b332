//! The `surface` section: the profile under the wheels.

use schemars::JsonSchema;
use serde::Deserialize;

use crate::scene::{Interference, IsoClass, Rails, RoughnessClass, TrackDirection};

/// Surface profile (roughness) under the wheels. It starts at the bridge
/// entrance and continues past the exit; the approach is smooth unless a
/// measured, piecewise-linear or shape profile says otherwise.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum SurfaceRaw {
    /// Perfectly smooth surface.
    Smooth,
    /// r(x) = amplitude · sin(2π x / wavelength + phase) for x ≥ 0, positive upward.
    Harmonic {
        /// Amplitude, m.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        amplitude: f64,
        /// Wavelength, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        wavelength: f64,
        /// Phase at the entrance, rad. Default 0.
        #[serde(default)]
        #[schemars(extend("default" = 0.0))]
        #[serde(deserialize_with = "crate::scenario::raw::units::angle::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::angle::schema")]
        phase: Option<f64>,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
    /// Random road profile, a stationary Gaussian process with the power
    /// spectral density S(Ω) = A_r (Ω/Ω₀)⁻², Ω₀ = 1/2π, sampled by the
    /// trigonometric series of the plate paper's Eq. 17 with random phases.
    /// It is shifted so that r(0) = 0 at the entrance. The same profile lies
    /// under every wheel track. Give `class` or `coefficient`.
    Random {
        /// Roughness class: `very_good`, `good`, `average`, `poor` or
        /// `very_poor` (A_r the geometric mean of the class's range).
        #[serde(default)]
        class: Option<RoughnessClass>,
        /// Roughness coefficient A_r, m³/cycle (e.g. 15e-6 for a road in good condition).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::non_negative)]
        #[serde(deserialize_with = "crate::scenario::raw::units::roughness_coefficient::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::roughness_coefficient::schema")]
        coefficient: Option<f64>,
        /// Length L_c the series repeats over, m. Default:
        /// {{DEFAULT_SAMPLING_LENGTHS}} × the bridge length.
        #[serde(default)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        sampling_length: Option<f64>,
        /// Number of terms N of the series. Default: enough for wavelengths
        /// down to {{DEFAULT_SHORTEST_WAVELENGTH}} m (N = L_c /
        /// {{DEFAULT_SHORTEST_WAVELENGTH}}).
        #[serde(default)]
        terms: Option<usize>,
        /// Seed of the random phases (ChaCha8). Default 1. The same seed gives
        /// the same profile on every machine.
        #[serde(default)]
        #[schemars(extend("default" = 1))]
        seed: Option<u64>,
    },
    /// Random vertical track profile from the US FRA spectrum of a track
    /// class: G(Ω) = k A_v Ω_c² / (Ω² (Ω² + Ω_c²)) (one-sided, m²/(rad/m),
    /// Ω in rad/m; k = 0.25, Ω_c = 0.8245 rad/m, A_v per class), sampled
    /// by the spectral representation over the wavelength band. Starts at 0
    /// at the entrance (the approach is smooth).
    Fra {
        /// Track class, 1 (worst) to 6 (best).
        #[schemars(range(min = 1, max = 6))]
        class: u8,
        /// Shortest wavelength sampled, m. Default: {{RAIL_BAND_SHORTEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::RAIL_BAND.0))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        shortest_wavelength: Option<f64>,
        /// Longest wavelength sampled, m. Default: {{RAIL_BAND_LONGEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::RAIL_BAND.1))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        longest_wavelength: Option<f64>,
        /// Number of terms N of the series (frequency bins of equal width in
        /// log Ω). Default: {{TERMS_PER_DECADE}} per decade of the wavelength
        /// band, at least {{MIN_BAND_TERMS}}.
        #[serde(default)]
        terms: Option<usize>,
        /// Seed of the random frequencies and phases (ChaCha8). Default 1.
        /// The same seed gives the same profile on every machine.
        #[serde(default)]
        #[schemars(extend("default" = 1))]
        seed: Option<u64>,
        /// Also sample the rails' alignment (lateral irregularity) from the
        /// same class's alignment spectrum (A_a in place of A_v), on its own
        /// random streams: what a `train_3d`'s wheelsets follow sideways (the
        /// mean of the two rails' alignment). Default false (straight rails).
        #[serde(default)]
        #[schemars(extend("default" = false))]
        alignment: Option<bool>,
        /// `identical`: both rails (wheel tracks) carry the same profile;
        /// `independent`: the left and right ones are independent samples.
        /// Default `identical`.
        #[serde(default)]
        rails: Option<Rails>,
        /// Length L of the run-in, m; default the band's longest wavelength
        /// ({{RAIL_BAND_LONGEST}} m for the rail band, {{ROAD_BAND_LONGEST}} m
        /// for the road band). The full
        /// profile lies on the bridge and is faded in over the last L m of
        /// the approach by a quintic smoothstep (r, r′, r″ zero at the fade's
        /// start and continuous, 0 before it), so no wheel meets a jump in
        /// elevation or slope. A vehicle without `entry_time` or
        /// `start_position` starts with its front axle at x = −L; if one is
        /// placed after x = −L, the fade starts under its front axle instead
        /// and reaches onto the bridge (a warning says how far). 0: the
        /// profile starts at the entrance, shifted so r(0) = 0, and its
        /// slope jumps there (a kick the wheels feel).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::non_negative)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        run_in: Option<f64>,
    },
    /// Random vertical track profile from the German high-speed spectrum:
    /// G(Ω) = A_v Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)) (one-sided, m²/(rad/m);
    /// Ω_c = 0.8246, Ω_r = 0.0206 rad/m; A_v = 4.032e-7 m·rad for low,
    /// 1.080e-6 for high interference). Starts at 0 at the entrance.
    German {
        /// `low` or `high` interference.
        interference: Interference,
        /// Shortest wavelength sampled, m. Default: {{RAIL_BAND_SHORTEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::RAIL_BAND.0))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        shortest_wavelength: Option<f64>,
        /// Longest wavelength sampled, m. Default: {{RAIL_BAND_LONGEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::RAIL_BAND.1))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        longest_wavelength: Option<f64>,
        /// Number of terms N of the series (frequency bins of equal width in
        /// log Ω). Default: {{TERMS_PER_DECADE}} per decade of the wavelength
        /// band, at least {{MIN_BAND_TERMS}}.
        #[serde(default)]
        terms: Option<usize>,
        /// Seed of the random frequencies and phases (ChaCha8). Default 1.
        /// The same seed gives the same profile on every machine.
        #[serde(default)]
        #[schemars(extend("default" = 1))]
        seed: Option<u64>,
        /// Also sample the rails' alignment (lateral irregularity) from the
        /// same class's alignment spectrum (A_a in place of A_v), on its own
        /// random streams: what a `train_3d`'s wheelsets follow sideways (the
        /// mean of the two rails' alignment). Default false (straight rails).
        #[serde(default)]
        #[schemars(extend("default" = false))]
        alignment: Option<bool>,
        /// `identical`: both rails (wheel tracks) carry the same profile;
        /// `independent`: the left and right ones are independent samples.
        /// Default `identical`.
        #[serde(default)]
        rails: Option<Rails>,
        /// Length L of the run-in, m; default the band's longest wavelength
        /// ({{RAIL_BAND_LONGEST}} m for the rail band, {{ROAD_BAND_LONGEST}} m
        /// for the road band). The full
        /// profile lies on the bridge and is faded in over the last L m of
        /// the approach by a quintic smoothstep (r, r′, r″ zero at the fade's
        /// start and continuous, 0 before it), so no wheel meets a jump in
        /// elevation or slope. A vehicle without `entry_time` or
        /// `start_position` starts with its front axle at x = −L; if one is
        /// placed after x = −L, the fade starts under its front axle instead
        /// and reaches onto the bridge (a warning says how far). 0: the
        /// profile starts at the entrance, shifted so r(0) = 0, and its
        /// slope jumps there (a kick the wheels feel).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::non_negative)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        run_in: Option<f64>,
    },
    /// Random road profile of an ISO 8608 class: G_d(n) = G_d(n₀)(n/n₀)⁻²,
    /// n₀ = 0.1 cycle/m, G_d(n₀) = 16e-6 m³ for class A, four times more per
    /// class up to H. Starts at 0 at the entrance.
    Iso8608 {
        /// Road class `A` (best) to `H`.
        class: IsoClass,
        /// Shortest wavelength sampled, m. Default: {{ROAD_BAND_SHORTEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::ROAD_BAND.0))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        shortest_wavelength: Option<f64>,
        /// Longest wavelength sampled, m. Default: {{ROAD_BAND_LONGEST}} m.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[schemars(extend("default" = crate::scenario::surfaces::ROAD_BAND.1))]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        longest_wavelength: Option<f64>,
        /// Number of terms N of the series (frequency bins of equal width in
        /// log Ω). Default: {{TERMS_PER_DECADE}} per decade of the wavelength
        /// band, at least {{MIN_BAND_TERMS}}.
        #[serde(default)]
        terms: Option<usize>,
        /// Seed of the random frequencies and phases (ChaCha8). Default 1.
        /// The same seed gives the same profile on every machine.
        #[serde(default)]
        #[schemars(extend("default" = 1))]
        seed: Option<u64>,
        /// `identical`: both rails (wheel tracks) carry the same profile;
        /// `independent`: the left and right ones are independent samples.
        /// Default `identical`.
        #[serde(default)]
        rails: Option<Rails>,
        /// Length L of the run-in, m; default the band's longest wavelength
        /// ({{RAIL_BAND_LONGEST}} m for the rail band, {{ROAD_BAND_LONGEST}} m
        /// for the road band). The full
        /// profile lies on the bridge and is faded in over the last L m of
        /// the approach by a quintic smoothstep (r, r′, r″ zero at the fade's
        /// start and continuous, 0 before it), so no wheel meets a jump in
        /// elevation or slope. A vehicle without `entry_time` or
        /// `start_position` starts with its front axle at x = −L; if one is
        /// placed after x = −L, the fade starts under its front axle instead
        /// and reaches onto the bridge (a warning says how far). 0: the
        /// profile starts at the entrance, shifted so r(0) = 0, and its
        /// slope jumps there (a kick the wheels feel).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::non_negative)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        run_in: Option<f64>,
    },
    /// A measured profile from a CSV file: rows `x, elevation` (one profile
    /// under every wheel), `x, left, right` (per rail; a wheel with
    /// lateral offset > 0 runs on the left rail, < 0 on the right, 0 on
    /// the left) or `x, left, right, left_lateral, right_lateral` (as
    /// recording cars deliver it: each rail's vertical and lateral
    /// position; a `train_3d`'s wheelsets follow the mean of the two
    /// lateral columns, the track's centre line), x in m from the bridge
    /// entrance (negative on the approach), strictly increasing,
    /// elevations in m, positive upward, lateral positions in m, + to the
    /// left of travel.
    /// Lines starting with `#` and a header line are skipped. Interpolated
    /// by a natural cubic spline; it must cover every position the wheels
    /// reach during the run.
    Measured {
        /// The CSV file, relative to the scenario file's folder.
        file: String,
    },
    /// r = 0 before `start`, rising linearly by `height` over `length`,
    /// then `height`.
    Ramp {
        /// Where the ramp starts, m from the entrance.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        start: f64,
        /// Horizontal length, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        length: f64,
        /// Rise, m (negative: a descent).
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        height: f64,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
    /// r = 0 before `position`, `height` from there on (a sudden change of
    /// level).
    Step {
        /// Where the step is, m from the entrance.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        position: f64,
        /// Change of level, m (negative: a step down).
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        height: f64,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
    /// A cosine bump: r = (height/2)(1 − cos(2π(x − start)/length)) over
    /// `length` from `start`, 0 elsewhere.
    Bump {
        /// Where the bump starts, m from the entrance.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        start: f64,
        /// Length, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        length: f64,
        /// Peak height, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        height: f64,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
    /// A cosine dip: r = −(depth/2)(1 − cos(2π(x − start)/length)) over
    /// `length` from `start`, 0 elsewhere.
    Dip {
        /// Where the dip starts, m from the entrance.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        start: f64,
        /// Length, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        length: f64,
        /// Deepest point below the level, m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
        depth: f64,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
    /// Straight lines between points `[x, r]` (x in m from the entrance,
    /// strictly increasing; r in m, positive upward), held at the end
    /// values before the first and after the last point.
    PiecewiseLinear {
        /// At least two `[x, r]` pairs, m.
        #[serde(deserialize_with = "crate::scenario::raw::units::length::pairs")]
        #[schemars(schema_with = "crate::scenario::raw::units::length::pairs_schema")]
        points: Vec<[f64; 2]>,
        /// `vertical` (default): the shape is the rails' elevation;
        /// `lateral`: it is the track's alignment, both rails displaced
        /// sideways (m, + to the left of travel), which a `train_3d`'s
        /// wheelsets follow (the vertical profile is then level).
        #[serde(default)]
        #[schemars(extend("default" = "vertical"))]
        direction: Option<TrackDirection>,
    },
}

impl TrackDirection {
    /// Whether it is the default (vertical): written only when lateral.
    pub fn is_vertical(&self) -> bool {
        *self == TrackDirection::Vertical
    }
}
