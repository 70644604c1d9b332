//! Resolving `bridge`: the beam and the plate deck, with their checks and
//! defaults.

use super::checker::{Checker, check_ratio};
use super::raw;
use super::resolve::DEFAULT_ELEMENTS_PER_SPAN;
use crate::scene::*;

/// Default Ritz transverse functions.
pub const DEFAULT_TRANSVERSE_TERMS: usize = 8;
/// Default longitudinal beam functions per span (and the fewest in all).
pub const DEFAULT_LONGITUDINAL_TERMS_PER_SPAN: usize = 6;
/// Fewest default longitudinal beam functions.
pub const MIN_LONGITUDINAL_TERMS: usize = 12;
/// Default Poisson's ratio of an isotropic deck (concrete).
pub const DEFAULT_ISOTROPIC_POISSON: f64 = 0.2;
/// Default Poisson's ratio ν_xy of an orthotropic deck.
pub const DEFAULT_ORTHOTROPIC_POISSON: f64 = 0.3;
/// Largest Ritz basis the dense eigen solver takes.
pub const MAX_RITZ_TERMS: usize = 2_000;

/// Resolves the bridge description; `None` after reporting its problems.
pub(crate) fn resolve_bridge(
    raw: &raw::BridgeRaw,
    budget: &super::budget::Budget,
    ck: &mut Checker<'_>,
) -> Option<Bridge> {
    let before = ck.diagnostics.len();
    let bridge = match raw {
        raw::BridgeRaw::Beam(b) => {
            check_spans(ck, &b.spans);
            ck.positive(
                "bridge.bending_stiffness",
                b.bending_stiffness,
                "bending stiffness",
            );
            ck.positive(
                "bridge.mass_per_length",
                b.mass_per_length,
                "mass per length",
            );
            let elements_per_span = beam_elements(ck, b);
            Bridge::Beam(Beam {
                spans: b.spans.clone(),
                bending_stiffness: b.bending_stiffness,
                mass_per_length: b.mass_per_length,
                elements_per_span,
                modes: resolve_modes(ck, b.modes.as_ref()),
                damping: resolve_damping(ck, b.damping.as_ref()),
                sway: resolve_sway(ck, b),
            })
        }
        raw::BridgeRaw::Plate(p) => Bridge::Plate(resolve_plate(p, ck)),
        raw::BridgeRaw::FeImport(f) => Bridge::FeImport(super::fe_import::resolve(f, budget, ck)?),
    };
    (ck.diagnostics.len() == before).then_some(bridge)
}

/// A 3D beam's lateral bending and torsion: all three of
/// `lateral_bending_stiffness`, `torsional_stiffness` and `polar_mass`, or
/// none (and then no `rail_height`).
fn resolve_sway(ck: &mut Checker<'_>, b: &raw::BeamRaw) -> Option<BeamSway> {
    let given = [
        ("lateral_bending_stiffness", b.lateral_bending_stiffness),
        ("torsional_stiffness", b.torsional_stiffness),
        ("polar_mass", b.polar_mass),
    ];
    if given.iter().all(|(_, v)| v.is_none()) {
        if b.rail_height.is_some() {
            ck.error(
                "bridge.rail_height",
                "`rail_height` places the rails over a twisting section: it goes with \
                 `lateral_bending_stiffness`, `torsional_stiffness` and `polar_mass` (a 3D beam)",
            );
        }
        return None;
    }
    let missing: Vec<&str> = given
        .iter()
        .filter(|(_, v)| v.is_none())
        .map(|(n, _)| *n)
        .collect();
    if !missing.is_empty() {
        ck.error(
            "bridge",
            format!(
                "a 3D beam needs `lateral_bending_stiffness` (N·m²), `torsional_stiffness` \
                 (N·m²/rad) and `polar_mass` (kg·m²/m) together; missing: {}",
                missing.join(", ")
            ),
        );
        return None;
    }
    for (name, value) in given {
        ck.positive(&format!("bridge.{name}"), value.unwrap_or(0.0), name);
    }
    let rail_height = b.rail_height.unwrap_or(0.0);
    if !rail_height.is_finite() || rail_height.abs() > 100.0 {
        ck.error(
            "bridge.rail_height",
            format!("a rail height is a number within ±100 m, got {rail_height}"),
        );
    }
    Some(BeamSway {
        lateral_bending_stiffness: b.lateral_bending_stiffness.unwrap_or(0.0),
        torsional_stiffness: b.torsional_stiffness.unwrap_or(0.0),
        polar_mass: b.polar_mass.unwrap_or(0.0),
        rail_height,
    })
}

fn resolve_plate(p: &raw::PlateRaw, ck: &mut Checker<'_>) -> Plate {
    check_spans(ck, &p.spans);
    ck.positive("bridge.width", p.width, "deck width");
    use super::plausible::{DECK_WIDTH, DENSITY, PLATE_THICKNESS, within_because};
    within_because(
        ck,
        "bridge.width",
        "a deck width",
        p.width,
        DECK_WIDTH,
        "m",
        "a laboratory strip is a few centimetres wide, the widest decks about 60 m",
    );
    if let Some(h) = p.thickness {
        ck.positive("bridge.thickness", h, "plate thickness");
        within_because(
            ck,
            "bridge.thickness",
            "a plate thickness",
            h,
            PLATE_THICKNESS,
            "m",
            "from laboratory strips of a millimetre to box girders about 15 m deep",
        );
    }
    if let Some(rho) = p.density {
        within_because(
            ck,
            "bridge.density",
            "a density",
            rho,
            DENSITY,
            "kg/m³",
            "aerogels are about 2 kg/m³, osmium, the densest element, 22,590 kg/m³",
        );
    }
    let mass_per_area = match (p.mass_per_area, p.density) {
        (Some(_), Some(_)) => {
            ck.error(
                "bridge.density",
                "give `mass_per_area` or `density`, not both",
            );
            0.0
        }
        (Some(m), None) => {
            ck.positive("bridge.mass_per_area", m, "mass per area");
            m
        }
        (None, Some(rho)) => {
            ck.positive("bridge.density", rho, "density");
            match p.thickness {
                Some(h) => rho * h,
                None => {
                    ck.error(
                        "bridge",
                        "`density` needs `thickness` to give the mass per area ρh",
                    );
                    0.0
                }
            }
        }
        (None, None) => {
            ck.error(
                "bridge",
                "a plate needs `mass_per_area` (kg/m²) or `density` with `thickness`",
            );
            0.0
        }
    };
    let rigidity = match &p.rigidity {
        raw::RigidityRaw::Isotropic {
            youngs_modulus,
            poisson_ratio,
        } => {
            ck.positive(
                "bridge.rigidity.youngs_modulus",
                *youngs_modulus,
                "Young's modulus",
            );
            let nu = poisson_ratio.unwrap_or(DEFAULT_ISOTROPIC_POISSON);
            if !(0.0..0.5).contains(&nu) {
                ck.error(
                    "bridge.rigidity.poisson_ratio",
                    format!("Poisson's ratio must be in [0, 0.5), got {nu}"),
                );
            }
            if p.thickness.is_none() {
                ck.error(
                    "bridge",
                    "an isotropic `rigidity` needs the plate `thickness`",
                );
            }
            Rigidity::Isotropic {
                youngs_modulus: *youngs_modulus,
                poisson_ratio: nu,
            }
        }
        raw::RigidityRaw::Orthotropic {
            flexural_rigidity_x,
            flexural_rigidity_y,
            torsional_rigidity,
            equivalent_rigidity,
            poisson_ratio,
        } => {
            let at = "bridge.rigidity";
            ck.positive(
                &format!("{at}.flexural_rigidity_x"),
                *flexural_rigidity_x,
                "flexural rigidity Dx",
            );
            ck.positive(
                &format!("{at}.flexural_rigidity_y"),
                *flexural_rigidity_y,
                "flexural rigidity Dy",
            );
            let nu = poisson_ratio.unwrap_or(DEFAULT_ORTHOTROPIC_POISSON);
            if !(0.0..1.0).contains(&nu) {
                ck.error(
                    &format!("{at}.poisson_ratio"),
                    format!("Poisson's ratio ν_xy must be in [0, 1), got {nu}"),
                );
            }
            let coupling = nu * flexural_rigidity_y;
            let torsional = match (torsional_rigidity, equivalent_rigidity) {
                (Some(dxy), Some(h)) => {
                    if (coupling + 2.0 * dxy - h).abs() > 1e-9 * h.abs().max(dxy.abs()) {
                        ck.error(
                            &format!("{at}.equivalent_rigidity"),
                            format!(
                                "H = {h} N·m disagrees with ν_xy Dy + 2 Dxy = {} N·m; give one of \
                                 `torsional_rigidity` and `equivalent_rigidity`",
                                coupling + 2.0 * dxy
                            ),
                        );
                    }
                    *dxy
                }
                (Some(dxy), None) => *dxy,
                (None, Some(h)) => 0.5 * (h - coupling),
                (None, None) => {
                    ck.error(
                        at,
                        "an orthotropic plate needs `torsional_rigidity` (Dxy) or \
                         `equivalent_rigidity` (H)",
                    );
                    0.0
                }
            };
            if torsional_rigidity.is_some() || equivalent_rigidity.is_some() {
                let path = if torsional_rigidity.is_some() {
                    format!("{at}.torsional_rigidity")
                } else {
                    format!("{at}.equivalent_rigidity")
                };
                ck.positive(&path, torsional, "torsional rigidity Dxy = (H − ν_xy Dy)/2");
            }
            // Positive strain energy needs D1² < Dx Dy.
            if coupling * coupling >= flexural_rigidity_x * flexural_rigidity_y
                && *flexural_rigidity_x > 0.0
            {
                ck.error(
                    &format!("{at}.poisson_ratio"),
                    "ν_xy² Dy ≥ Dx: the plate's strain energy would not be positive",
                );
            }
            Rigidity::Orthotropic {
                flexural_rigidity_x: *flexural_rigidity_x,
                flexural_rigidity_y: *flexural_rigidity_y,
                torsional_rigidity: torsional,
                equivalent_rigidity: coupling + 2.0 * torsional,
                poisson_ratio: nu,
            }
        }
    };
    let spans = p.spans.len().max(1);
    let terms = p.terms.clone().unwrap_or(Terms {
        longitudinal: (DEFAULT_LONGITUDINAL_TERMS_PER_SPAN * spans).max(MIN_LONGITUDINAL_TERMS),
        transverse: DEFAULT_TRANSVERSE_TERMS,
    });
    if terms.longitudinal == 0 {
        ck.error(
            "bridge.terms.longitudinal",
            "at least one longitudinal term is needed",
        );
    }
    if terms.transverse == 0 {
        ck.error(
            "bridge.terms.transverse",
            "at least one transverse term is needed",
        );
    }
    // Saturating: term counts near usize::MAX must not wrap to a small basis.
    if terms.longitudinal.saturating_mul(terms.transverse) > MAX_RITZ_TERMS {
        ck.error(
            "bridge.terms",
            format!(
                "{} × {} = {} Ritz terms is more than the dense eigen solver takes ({MAX_RITZ_TERMS})",
                terms.longitudinal,
                terms.transverse,
                terms.longitudinal.saturating_mul(terms.transverse)
            ),
        );
    }
    let elements_per_span = elements(ck, p.elements_per_span, p.spans.len());
    // The continuous beam offers one mode per free dof: 2 per node less the
    // deflections fixed at the spans + 1 supports.
    let beam_modes = elements_per_span
        .saturating_mul(spans)
        .saturating_mul(2)
        .saturating_add(1)
        .saturating_sub(spans);
    if terms.longitudinal > beam_modes {
        ck.error(
            "bridge.terms.longitudinal",
            format!(
                "{} longitudinal beam functions need more than the {beam_modes} modes that {} \
                 elements per span give; raise `elements_per_span`",
                terms.longitudinal, elements_per_span
            ),
        );
    }
    let girder_lines = p.girder_lines.clone().unwrap_or(vec![p.width / 2.0]);
    if girder_lines.is_empty() {
        ck.error("bridge.girder_lines", "give at least one girder line");
    }
    for (i, &y) in girder_lines.iter().enumerate() {
        if !(0.0..=p.width).contains(&y) {
            ck.error(
                &format!("bridge.girder_lines[{i}]"),
                format!("y = {y} m is off the deck, which spans 0 to {} m", p.width),
            );
        }
    }
    Plate {
        spans: p.spans.clone(),
        width: p.width,
        thickness: p.thickness,
        mass_per_area,
        rigidity,
        edges: p.edges.unwrap_or(PlateEdges::Free),
        terms,
        elements_per_span,
        modes: resolve_modes(ck, p.modes.as_ref()),
        damping: resolve_damping(ck, p.damping.as_ref()),
        girder_lines,
    }
}

fn check_spans(ck: &mut Checker<'_>, spans: &[f64]) {
    if spans.is_empty() {
        ck.error("bridge.spans", "`spans` needs at least one span length");
    }
    let longest = spans.iter().copied().fold(0.0, f64::max);
    for (i, &s) in spans.iter().enumerate() {
        ck.positive(&format!("bridge.spans[{i}]"), s, "a span length");
        if s > 0.0 && s < 1e-3 * longest {
            ck.error(
                &format!("bridge.spans[{i}]"),
                format!("a span of {s} m is less than 1/1000 of the longest ({longest} m); the model would be ill-conditioned"),
            );
        }
    }
    if longest > 1e5 {
        ck.error(
            "bridge.spans",
            format!("a span of {longest} m is longer than 100 km"),
        );
    }
}

/// Most degrees of freedom a beam model may have.
pub const MAX_BEAM_DOFS: usize = 1_000_000;

/// A plate's beam functions' elements per span: one count for all spans.
fn elements(ck: &mut Checker<'_>, given: Option<usize>, spans: usize) -> usize {
    let elements_per_span = given.unwrap_or(DEFAULT_ELEMENTS_PER_SPAN);
    check_count(ck, "bridge.elements_per_span", elements_per_span);
    check_beam_dofs(ck, spans.saturating_mul(elements_per_span));
    elements_per_span
}

/// A beam's elements on each span, from `elements_per_span` (one count or
/// one per span) or `element_length` (ceil(span / element_length), a ratio
/// within a relative [`WHOLE_RATIO`] of a whole number taken as that
/// number), never both; the default count on every span if neither.
fn beam_elements(ck: &mut Checker<'_>, b: &raw::BeamRaw) -> Vec<usize> {
    let spans = b.spans.len();
    let counts =
        match (&b.elements_per_span, b.element_length) {
            (Some(_), Some(_)) => {
                ck.error(
                    "bridge.element_length",
                    "give `elements_per_span` or `element_length`, not both: each sets the mesh",
                );
                return vec![DEFAULT_ELEMENTS_PER_SPAN; spans];
            }
            (None, None) => vec![DEFAULT_ELEMENTS_PER_SPAN; spans],
            (Some(raw::ElementsPerSpanRaw::All(n)), None) => {
                check_count(ck, "bridge.elements_per_span", *n);
                vec![*n; spans]
            }
            (Some(raw::ElementsPerSpanRaw::PerSpan(counts)), None) => {
                for (i, &n) in counts.iter().enumerate() {
                    check_count(ck, &format!("bridge.elements_per_span[{i}]"), n);
                }
                // A list or spans that lost an entry to a type error (already
                // reported) is not compared.
                if counts.len() != spans
                    && !ck.uncertain("bridge.spans")
                    && !ck.uncertain("bridge.elements_per_span")
                {
                    ck.error(
                    "bridge.elements_per_span",
                    format!(
                        "`elements_per_span` lists {} count{} for {spans} span{}; give one count \
                         per span, or one number for every span",
                        counts.len(),
                        if counts.len() == 1 { "" } else { "s" },
                        if spans == 1 { "" } else { "s" },
                    ),
                );
                }
                if counts.len() != spans {
                    return vec![DEFAULT_ELEMENTS_PER_SPAN; spans];
                }
                counts.clone()
            }
            (None, Some(length)) => {
                ck.positive("bridge.element_length", length, "an element length");
                if !(length > 0.0 && length.is_finite()) {
                    return vec![DEFAULT_ELEMENTS_PER_SPAN; spans];
                }
                let most = crate::scene::MAX_ELEMENTS_PER_SPAN;
                let counts: Vec<usize> = b
                    .spans
                    .iter()
                    .map(|&span| elements_for_length(span, length))
                    .collect();
                if let Some((i, (&span, &n))) = b
                    .spans
                    .iter()
                    .zip(&counts)
                    .enumerate()
                    .find(|(_, (_, n))| **n > most)
                {
                    // 1e-300 written out would take a line of zeros.
                    let shown = if (1e-4..1e7).contains(&length) {
                        format!("{length}")
                    } else {
                        format!("{length:e}")
                    };
                    ck.error_with_help(
                    "bridge.element_length",
                    format!(
                        "an element length of {shown} m makes {} elements on span {} ({span} m), \
                         more than the {most} a span takes",
                        if n == usize::MAX { "too many".to_owned() } else { n.to_string() },
                        i + 1
                    ),
                    Some(format!(
                        "beyond {most} elements a span's stiffness is too ill-conditioned for its \
                         modes to pass their checks in double precision; 20 to 100 per span is \
                         what a span needs"
                    )),
                );
                }
                counts
            }
        };
    let path = if b.element_length.is_some() {
        "bridge.element_length"
    } else {
        "bridge.elements_per_span"
    };
    let total = counts.iter().fold(0usize, |sum, &n| sum.saturating_add(n));
    check_beam_dofs_at(ck, path, total);
    counts
}

/// How close to a whole number span / element_length must come to count
/// as that number (relative): round-off in a ratio of decimals (25 / 2.5)
/// must not add an element.
pub const WHOLE_RATIO: f64 = 1e-9;

/// Elements of a span `span` m long no longer than `length` m:
/// ceil(span / length), a ratio within a relative [`WHOLE_RATIO`] of a
/// whole number taken as that number; at least 1, `usize::MAX` for a count
/// no integer holds.
pub fn elements_for_length(span: f64, length: f64) -> usize {
    let ratio = span / length;
    let count = (ratio * (1.0 - WHOLE_RATIO)).ceil().max(1.0);
    if count.is_finite() && count < usize::MAX as f64 {
        count as usize
    } else {
        usize::MAX
    }
}

/// A count of elements on one span: 1 to [`crate::scene::MAX_ELEMENTS_PER_SPAN`].
fn check_count(ck: &mut Checker<'_>, path: &str, elements_per_span: usize) {
    let most = crate::scene::MAX_ELEMENTS_PER_SPAN;
    if !(1..=most).contains(&elements_per_span) {
        ck.error_with_help(
            path,
            format!("elements per span must be between 1 and {most}, got {elements_per_span}"),
            (elements_per_span > most).then(|| {
                format!(
                    "beyond {most} elements a span's stiffness is too ill-conditioned for its \
                     modes to pass their checks in double precision; 20 to 100 is what a span needs"
                )
            }),
        );
    }
}

/// `elements` elements in all: at most [`MAX_BEAM_DOFS`] degrees of freedom.
fn check_beam_dofs(ck: &mut Checker<'_>, elements: usize) {
    check_beam_dofs_at(ck, "bridge.elements_per_span", elements);
}

fn check_beam_dofs_at(ck: &mut Checker<'_>, path: &str, elements: usize) {
    // The sparse eigen solver's memory is linear in the DOFs (a Lanczos
    // basis of a few hundred vectors): 10⁶ DOFs is ~2 GB for 100 modes.
    let total_dofs = elements.saturating_mul(2);
    if total_dofs > MAX_BEAM_DOFS {
        ck.error(
            path,
            format!(
                "{total_dofs} degrees of freedom is more than a beam model takes ({MAX_BEAM_DOFS}); use fewer elements per span"
            ),
        );
    }
}

pub(crate) fn resolve_modes(ck: &mut Checker<'_>, raw: Option<&raw::ModesRaw>) -> Modes {
    match raw {
        None => Modes {
            count: None,
            max_frequency: None,
            static_correction: true,
        },
        Some(m) => {
            if m.count.is_none() && m.max_frequency.is_none() && m.static_correction.is_none() {
                ck.error(
                    "bridge.modes",
                    "`modes` needs `count`, `max_frequency`, `static_correction` or a combination",
                );
            }
            if m.count == Some(0) {
                ck.error("bridge.modes.count", "at least one mode is needed");
            }
            if let Some(f) = m.max_frequency {
                ck.positive("bridge.modes.max_frequency", f, "maximum frequency");
            }
            Modes {
                count: m.count,
                max_frequency: m.max_frequency,
                static_correction: m.static_correction.unwrap_or(true),
            }
        }
    }
}

fn resolve_damping(ck: &mut Checker<'_>, raw: Option<&raw::DampingRaw>) -> Damping {
    match raw {
        None => Damping::Modal { ratio: 0.0 },
        Some(raw::DampingRaw::Modal { ratio }) => {
            check_ratio(ck, "bridge.damping.ratio", *ratio);
            Damping::Modal { ratio: *ratio }
        }
        Some(raw::DampingRaw::Rayleigh { frequencies, ratio }) => {
            check_ratio(ck, "bridge.damping.ratio", *ratio);
            for (i, &f) in frequencies.iter().enumerate() {
                let at = format!("bridge.damping.frequencies[{i}]");
                ck.positive(&at, f, "a Rayleigh frequency");
                super::plausible::within_because(
                    ck,
                    &at,
                    "a Rayleigh frequency",
                    f,
                    super::plausible::RAYLEIGH_FREQUENCY,
                    "Hz",
                    "the longest suspension bridges' first mode is about 0.05 Hz; laboratory \
                     models reach a few kHz",
                );
            }
            if frequencies[0] == frequencies[1] {
                ck.error(
                    "bridge.damping.frequencies",
                    "the two Rayleigh frequencies must differ",
                );
            }
            Damping::Rayleigh {
                frequencies: *frequencies,
                ratio: *ratio,
            }
        }
    }
}
