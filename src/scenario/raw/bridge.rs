//! The bridge as written in a scenario: the beam, the plate and their modes
//! and damping.

use schemars::JsonSchema;
use serde::Deserialize;

use super::*;

/// The bridge model.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
#[schemars(tag = "type")]
pub enum BridgeRaw {
    /// Euler–Bernoulli beam, simply supported or continuous over pinned
    /// supports, discretised with Hermite-cubic finite elements and reduced to
    /// mass-normalised modes.
    Beam(BeamRaw),
    /// Thin orthotropic (or isotropic) plate deck, jointless over one or more
    /// spans: simply supported at both ends, rigid line supports across the
    /// deck between spans, longitudinal edges free (or simply supported).
    /// Modes by the Rayleigh–Ritz method with beam functions, keeping the
    /// coupling between the longitudinal and transverse families (the plate
    /// paper's intermodal coupling). y runs across the deck from the edge
    /// y = 0 (the right-hand edge for traffic in +x) to y = width.
    Plate(PlateRaw),
    /// A finite-element model imported from files (matrices, DOF map, rails).
    FeImport(FeImportRaw),
}

/// Plate deck.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlateRaw {
    /// Span lengths, m, from the entrance; rigid line supports between spans.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub spans: Vec<f64>,
    /// Deck width b, m.
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub width: f64,
    /// Plate thickness h, m. Needed by an isotropic `rigidity` and by `density`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub thickness: Option<f64>,
    /// Mass per unit area ρh, kg/m². Give this or `density`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass_per_area::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass_per_area::schema")]
    pub mass_per_area: Option<f64>,
    /// Density ρ, kg/m³ (with `thickness`). Give this or `mass_per_area`.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::density::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::density::schema")]
    pub density: Option<f64>,
    /// Flexural and torsional rigidities.
    pub rigidity: RigidityRaw,
    /// Support of the two longitudinal edges: `free` (default, a bridge deck)
    /// or `simply_supported`.
    #[serde(default)]
    #[schemars(extend("default" = "free"))]
    pub edges: Option<PlateEdges>,
    /// Size of the Rayleigh–Ritz basis. Default:
    /// {{DEFAULT_LONGITUDINAL_TERMS_PER_SPAN}} longitudinal beam functions per
    /// span (at least {{MIN_LONGITUDINAL_TERMS}}) × {{DEFAULT_TRANSVERSE_TERMS}}
    /// transverse functions.
    #[serde(default)]
    pub terms: Option<Terms>,
    /// Finite elements per span of the continuous beam whose modes are the
    /// longitudinal beam functions. Default {{DEFAULT_ELEMENTS_PER_SPAN}}.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::elements_per_span)]
    #[schemars(extend("default" = crate::scenario::resolve::DEFAULT_ELEMENTS_PER_SPAN))]
    pub elements_per_span: Option<usize>,
    /// Which modes the modal superposition keeps. Default: automatic, as for
    /// the beam (every mode up to {{SAFETY}} × the highest excitation), and at
    /// least {{MODES_PER_SPAN}} per span of each of the {{PLATE_FAMILIES}}
    /// families, bending, torsion and transverse bending
    /// ({{PLATE_MODES_PER_SPAN}} per span).
    #[serde(default)]
    pub modes: Option<ModesRaw>,
    /// Structural damping. Default: none (undamped).
    #[serde(default)]
    pub damping: Option<DampingRaw>,
    /// Transverse positions y of the girder lines, m: the summary tabulates
    /// the DAF at the middle of every span on each line. Default: the deck's
    /// centre line.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::non_negative_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option_list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub girder_lines: Option<Vec<f64>>,
}

/// Plate rigidities.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum RigidityRaw {
    /// Isotropic plate of the deck's `thickness`: D = E h³ / (12 (1 − ν²)),
    /// Dx = Dy = H = D.
    Isotropic {
        /// Young's modulus E, Pa.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::pressure::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::pressure::schema")]
        youngs_modulus: f64,
        /// Poisson's ratio ν (dimensionless). Default {{DEFAULT_ISOTROPIC_POISSON}} (concrete).
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::isotropic_poisson)]
        #[schemars(extend("default" = crate::scenario::bridges::DEFAULT_ISOTROPIC_POISSON))]
        poisson_ratio: Option<f64>,
    },
    /// Orthotropic plate (the plate paper's Eq. 1): Dx, Dy, and the torsional
    /// rigidity Dxy = G h³/12 or the equivalent rigidity H = ν_xy Dy + 2 Dxy.
    Orthotropic {
        /// Flexural rigidity along the bridge Dx, N·m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        flexural_rigidity_x: f64,
        /// Flexural rigidity across the bridge Dy, N·m.
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::one")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        flexural_rigidity_y: f64,
        /// Torsional rigidity Dxy = G h³ / 12, N·m. Give this or `equivalent_rigidity`.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::positive)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        torsional_rigidity: Option<f64>,
        /// Equivalent rigidity H = ν_xy Dy + 2 Dxy, N·m. Give this or `torsional_rigidity`.
        #[serde(default)]
        #[serde(deserialize_with = "crate::scenario::raw::units::plate_rigidity::option")]
        #[schemars(schema_with = "crate::scenario::raw::units::plate_rigidity::schema")]
        equivalent_rigidity: Option<f64>,
        /// Poisson's ratio ν_xy (dimensionless); the coupling rigidity is
        /// D1 = ν_xy Dy. Default {{DEFAULT_ORTHOTROPIC_POISSON}}.
        #[serde(default)]
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        #[schemars(extend("default" = crate::scenario::bridges::DEFAULT_ORTHOTROPIC_POISSON))]
        poisson_ratio: Option<f64>,
    },
}

/// Euler–Bernoulli beam bridge.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BeamRaw {
    /// Span lengths, m, from the entrance. One span = simply supported; several
    /// = continuous over pinned intermediate supports.
    #[schemars(transform = crate::scene::schema_rules::positive_list)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::list")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::list_schema")]
    pub spans: Vec<f64>,
    /// Bending stiffness EI, N·m².
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::bending_stiffness::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::bending_stiffness::schema")]
    pub bending_stiffness: f64,
    /// Mass per unit length m, kg/m.
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::mass_per_length::one")]
    #[schemars(schema_with = "crate::scenario::raw::units::mass_per_length::schema")]
    pub mass_per_length: f64,
    /// Hermite-cubic finite elements per span: one count for every span
    /// (`20`), or a list with one count per span from the entrance
    /// (`[8, 10, 8]`), each 1 to {{MAX_ELEMENTS_PER_SPAN}}; a span's
    /// elements are of equal length. Give this or `element_length`.
    /// Default {{DEFAULT_ELEMENTS_PER_SPAN}} on every span.
    #[serde(default)]
    #[schemars(extend("default" = crate::scenario::resolve::DEFAULT_ELEMENTS_PER_SPAN))]
    pub elements_per_span: Option<ElementsPerSpanRaw>,
    /// Longest finite element, m, instead of `elements_per_span`: each span
    /// gets ceil(span / element_length) elements of equal length, the
    /// fewest no longer than `element_length` (a ratio within a relative
    /// 10⁻⁹ of a whole number counts as that number, so 25 m at 2.5 m is
    /// 10 elements, not 11). The resolved scenario gives the counts.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub element_length: Option<f64>,
    /// Which modes the modal superposition keeps. Default: automatic — every
    /// mode up to {{SAFETY}} × the highest frequency the scene excites
    /// (vehicle natural frequencies incl. wheel hop on an elastic contact,
    /// axle passing v/d, span crossing v/2L, roughness v/λ), and at least
    /// {{MODES_PER_SPAN}} per span (twice that under wheels heavier than
    /// {{HEAVY_WHEEL_RATIO}} × the lightest span's mass; {{MODES_PER_SPAN_CORRECTED}}
    /// on a beam with the static correction whose wheels have no mass of
    /// their own: moving forces, a sprung mass or tyres on the deck); the
    /// resolved scenario gives the modes kept as `count` with the cut-off as
    /// `max_frequency` and the summary says why.
    #[serde(default)]
    pub modes: Option<ModesRaw>,
    /// Structural damping. Default: none (undamped).
    #[serde(default)]
    pub damping: Option<DampingRaw>,
    /// Lateral bending stiffness EI_z, N·m². With `torsional_stiffness`
    /// and `polar_mass` it makes the beam 3D: lateral bending and torsion
    /// modes (doubly symmetric section, fork supports: no lateral
    /// displacement and no twist at any support) besides the vertical ones,
    /// so a `train_3d` follows the rails laterally and a lateral ground
    /// motion shakes the deck.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::bending_stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::bending_stiffness::schema")]
    pub lateral_bending_stiffness: Option<f64>,
    /// Torsional stiffness GJ, N·m²/rad (3D beam).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::torsional_stiffness::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::torsional_stiffness::schema")]
    pub torsional_stiffness: Option<f64>,
    /// Polar mass moment of inertia per length I_p, kg·m²/m (3D beam).
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::inertia_per_length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::inertia_per_length::schema")]
    pub polar_mass: Option<f64>,
    /// Height of the rail heads above the section's shear centre, m (3D
    /// beam): a twist θ moves the rails sideways by −h θ and a rail at y
    /// across the centre line up by y θ. Default 0.
    #[serde(default)]
    #[schemars(extend("default" = 0.0))]
    #[serde(deserialize_with = "crate::scenario::raw::units::length::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::length::schema")]
    pub rail_height: Option<f64>,
}

/// Mode selection: by count, by maximum frequency, or both (the stricter wins).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ModesRaw {
    /// Keep the lowest `count` modes.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::at_least_one)]
    pub count: Option<usize>,
    /// Keep every mode whose natural frequency is at most this, Hz (within
    /// a relative 1e-8: a frequency copied as printed keeps its mode). With
    /// `count`: the lowest `count`, none of them above this.
    #[serde(default)]
    #[schemars(transform = crate::scene::schema_rules::positive)]
    #[serde(deserialize_with = "crate::scenario::raw::units::frequency::option")]
    #[schemars(schema_with = "crate::scenario::raw::units::frequency::schema")]
    pub max_frequency: Option<f64>,
    /// Add the quasi-static share of the modes left out to every recorded
    /// bridge displacement (the mode-acceleration method: the exact static
    /// deflection under the current wheel forces minus its modal part), so
    /// few modes give converged deflections. Default true.
    #[serde(default)]
    pub static_correction: Option<bool>,
}

/// Structural damping of the bridge.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[schemars(tag = "type")]
pub enum DampingRaw {
    /// The same modal damping ratio ζ for every mode.
    Modal {
        /// Damping ratio ζ (fraction of critical, dimensionless), e.g. 0.02.
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
    /// Rayleigh damping C = a₀M + a₁K with the given ratio at two frequencies;
    /// mode i then has ζᵢ = a₀/(2ωᵢ) + a₁ωᵢ/2.
    Rayleigh {
        /// The two frequencies where the damping ratio is matched, Hz.
        #[schemars(transform = crate::scene::schema_rules::positive_items)]
        #[serde(deserialize_with = "crate::scenario::raw::units::frequency::pair")]
        #[schemars(schema_with = "crate::scenario::raw::units::frequency::pair_schema")]
        frequencies: [f64; 2],
        /// Damping ratio ζ at both frequencies (dimensionless).
        #[schemars(transform = crate::scene::schema_rules::ratio)]
        ratio: f64,
    },
}
