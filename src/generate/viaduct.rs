//! A multi-span railway viaduct in the layout of the EMBS paper's Alverca
//! viaduct (Table 1 of ../shared/papers/embs-seismic-vehicle-bridge.txt,
//! after Montenegro et al. and Malveiro et al.): N simply supported spans
//! on piers, each deck a 3D frame (6 DOFs per node) on two bearings per end,
//! ballast springs from the deck to monoblock sleepers (rigid masses, 6
//! DOFs), rail pads from the sleepers to two continuous UIC60 rails (3D
//! frames), and the track continued over an approach on the embankment at
//! both ends (ballast on rigid ground there). The ballast and the
//! non-structural mass (barriers, edge beams) are point masses on the deck
//! nodes, as in the paper. Rigid arms (the paper's rigid frame elements)
//! join each spring to its nodes: a spring acts between two points at
//! offsets from their nodes ([`super::frame::point_row`]).
//!
//! Coordinates: x along the track from the first abutment (m), y lateral
//! (left rail at +y), z vertical up, the deck centroid at z = 0.

use super::frame::{self, Section};

/// Everything that defines a generated viaduct. Defaults: Table 1 of the
/// EMBS paper where it gives a value; the rest (marked "chosen") are
/// standard values for a ballasted double-rail track on a 25 m single-cell
/// box girder, since the paper does not state them.
#[derive(Debug, Clone, PartialEq)]
pub struct ViaductParams {
    /// Number of simply supported spans.
    pub spans: usize,
    /// Span length, m (chosen default 25 m; the real viaduct has 16.5–21 m).
    pub span_length: f64,
    /// Pier height from the fixed base to the bearing seat, m (chosen 10 m;
    /// the real ones are 5–15 m).
    pub pier_height: f64,
    /// Track on the embankment before and after the viaduct, m (chosen 10 m).
    pub approach_length: f64,
    /// Nominal sleeper spacing, m (0.6 m standard); each span holds a whole
    /// number of sleepers, so the spacing on a span is L/round(L/s).
    pub sleeper_spacing: f64,
    /// Rail elements between two sleepers (the mesh refinement knob).
    pub rail_divisions: usize,
    /// Elements along each pier.
    pub pier_elements: usize,
    /// Deck section, homogenised to the prefabricated beams' concrete:
    /// E_c,beam = 48.08 GPa and ρ_c = 2590.4 kg/m³ (Table 1); A = 4.6 m²,
    /// I_vertical = 1.8 m⁴, I_lateral = 18 m⁴, J = 3.5 m⁴ chosen (first
    /// vertical bending mode of a 25 m span ≈ 5.7 Hz with the track mass).
    pub deck: Section,
    /// Non-structural mass on the deck (barriers, edge beams, cables),
    /// kg/m (chosen 2000 kg/m).
    pub non_structural_mass: f64,
    /// Ballast mass per metre of track: ρ_bal = 1995.9 kg/m³ (Table 1) times
    /// a chosen cross-section of 1.58 m² (25 cm under the sleepers over
    /// 4.4 m plus half the crib between sleepers), kg/m.
    pub ballast_mass: f64,
    /// Ballast stiffness per metre of track, longitudinal, transverse,
    /// vertical: 30, 7.5, 100 MN/m/m (Table 1), N/m².
    pub ballast_stiffness: [f64; 3],
    /// Sleeper mass, kg (chosen 300 kg, a B70-type monoblock); the sleeper
    /// is rigid (2.6 × 0.28 × 0.22 m for its rotary inertia), so Table 1's
    /// E_c,sleeper = 40.9 GPa does not enter.
    pub sleeper_mass: f64,
    /// Pad (fastener) stiffness per rail seat, longitudinal, transverse,
    /// vertical: 20, 20, 500 MN/m; and rotational about x 45 kN·m/rad
    /// (Table 1), N/m and N·m/rad.
    pub pad_stiffness: [f64; 4],
    /// Bearing stiffness per bearing (two per span end, at ±1.25 m),
    /// longitudinal 4.4 MN/m and vertical 5200 MN/m (Table 1); transverse
    /// chosen equal to the vertical one (the paper's bearings are fixed
    /// transversally), N/m.
    pub bearing_stiffness: [f64; 3],
    /// Rail section: UIC60 (A = 76.70 cm², I_vertical = 3038.3 cm⁴,
    /// I_lateral = 512.3 cm⁴, J = 210 cm⁴ chosen), steel E = 210 GPa,
    /// G = E/2.6, ρ = 7850 kg/m³ (60.2 kg/m).
    pub rail: Section,
    /// Lateral position of each rail (and of the rail seats), m: half of
    /// the Iberian gauge 1.668 m plus half a rail head, 0.88 m (chosen).
    pub rail_offset: f64,
    /// Pier section: 2 m (transverse) × 1 m (longitudinal) solid rectangle
    /// (the paper), E = E_c,slab = 33.48 GPa times 0.5 for cracking
    /// (effective stiffness, EN 1998-2 §2.3.4; the paper's exact factor is
    /// not given), ρ_c = 2590.4 kg/m³.
    pub pier: Section,
}

impl Default for ViaductParams {
    fn default() -> Self {
        let concrete_shear = |e: f64| e / (2.0 * 1.2);
        let deck_e = 48.08e9;
        let pier_e = 0.5 * 33.48e9;
        let steel_e = 210e9;
        Self {
            spans: 30,
            span_length: 25.0,
            pier_height: 10.0,
            approach_length: 10.0,
            sleeper_spacing: 0.6,
            rail_divisions: 2,
            pier_elements: 10,
            deck: Section {
                youngs_modulus: deck_e,
                shear_modulus: concrete_shear(deck_e),
                density: 2590.4,
                area: 4.6,
                inertia_y: 1.8,
                inertia_z: 18.0,
                torsion: 3.5,
            },
            non_structural_mass: 2000.0,
            ballast_mass: 1995.9 * 1.58,
            ballast_stiffness: [30e6, 7.5e6, 100e6],
            sleeper_mass: 300.0,
            pad_stiffness: [20e6, 20e6, 500e6, 45e3],
            bearing_stiffness: [4.4e6, 5200e6, 5200e6],
            rail: Section {
                youngs_modulus: steel_e,
                shear_modulus: steel_e / 2.6,
                density: 7850.0,
                area: 76.70e-4,
                inertia_y: 3038.3e-8,
                inertia_z: 512.3e-8,
                torsion: 210e-8,
            },
            rail_offset: 0.88,
            pier: Section {
                youngs_modulus: pier_e,
                shear_modulus: concrete_shear(pier_e),
                density: 2590.4,
                area: 2.0,
                // Local y' = global Y (2 m side), z' = −X (1 m side).
                inertia_y: 2.0 * 1.0f64.powi(3) / 12.0,
                inertia_z: 1.0 * 2.0f64.powi(3) / 12.0,
                // β a b³ with a/b = 2: β = 0.229 (Roark, Table 10.7).
                torsion: 0.229 * 2.0,
            },
        }
    }
}

/// Vertical geometry (m, from the deck centroid): deck top 0.9, bearing
/// seat 1.0 below; 0.25 m ballast; sleeper 0.22 m high; rail centroid
/// 0.08 m above its foot.
const DECK_TOP: f64 = 0.9;
const DECK_BOTTOM: f64 = -1.0;
const BALLAST_DEPTH: f64 = 0.25;
const SLEEPER_HEIGHT: f64 = 0.22;
const SLEEPER_LENGTH: f64 = 2.6;
const SLEEPER_WIDTH: f64 = 0.28;
const RAIL_FOOT_TO_CENTROID: f64 = 0.08;
/// Lateral position of the two bearings of a span end, m (chosen).
const BEARING_OFFSET: f64 = 1.25;

/// Direction names of the six DOFs of a node, in order.
pub const DIRECTIONS: [&str; 6] = ["ux", "uy", "uz", "rx", "ry", "rz"];

/// The assembled model before the constrained DOFs are removed.
#[derive(Debug, Clone)]
pub struct Assembled {
    /// Node coordinates (m); node id = index + 1.
    pub nodes: Vec<[f64; 3]>,
    /// Nodes whose six DOFs are fixed (the ground, pier bases).
    pub fixed: Vec<bool>,
    /// Stiffness entries (row ≥ column, full DOF numbering 6·node + dir,
    /// duplicates to be summed), N/m, N·m/rad.
    pub stiffness: Vec<(usize, usize, f64)>,
    /// Mass entries likewise, kg, kg·m².
    pub mass: Vec<(usize, usize, f64)>,
    /// Left (+y) and right rail nodes, ascending x.
    pub rails: [Vec<usize>; 2],
    /// Mass of each component (name, kg), whole model including what sits
    /// on fixed nodes.
    pub component_masses: Vec<(&'static str, f64)>,
}

/// Largest generated order (DOFs), checked before anything is allocated.
pub const MAX_DOFS: usize = 3_000_000;

/// Errors of a generator request.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum GenerateError {
    /// A parameter out of its range.
    #[error("{name} = {value} is out of range ({range})")]
    OutOfRange {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range.
        range: &'static str,
    },
    /// The model would be too large.
    #[error(
        "the viaduct would have about {dofs} DOFs, above the limit of {MAX_DOFS} (fewer spans or rail divisions)"
    )]
    TooLarge {
        /// Estimated DOFs.
        dofs: usize,
    },
}

impl ViaductParams {
    /// Checks every parameter and the model size (before any allocation).
    pub fn validate(&self) -> Result<(), GenerateError> {
        let range = |name, value: f64, lo: f64, hi: f64, text| {
            if value.is_finite() && value >= lo && value <= hi {
                Ok(())
            } else {
                Err(GenerateError::OutOfRange {
                    name,
                    value,
                    range: text,
                })
            }
        };
        range("spans", self.spans as f64, 1.0, 1000.0, "1 to 1000")?;
        range("span_length", self.span_length, 2.0, 200.0, "2 to 200 m")?;
        range("pier_height", self.pier_height, 0.5, 200.0, "0.5 to 200 m")?;
        range(
            "approach_length",
            self.approach_length,
            0.0,
            1000.0,
            "0 to 1000 m",
        )?;
        range(
            "sleeper_spacing",
            self.sleeper_spacing,
            0.3,
            1.0,
            "0.3 to 1 m",
        )?;
        range(
            "rail_divisions",
            self.rail_divisions as f64,
            1.0,
            64.0,
            "1 to 64",
        )?;
        range(
            "pier_elements",
            self.pier_elements as f64,
            1.0,
            200.0,
            "1 to 200",
        )?;
        let dofs = self.estimated_dofs();
        if dofs > MAX_DOFS {
            return Err(GenerateError::TooLarge { dofs });
        }
        Ok(())
    }

    /// Sleepers per span.
    fn sleepers_per_span(&self) -> usize {
        ((self.span_length / self.sleeper_spacing).round() as usize).max(1)
    }

    /// Sleepers on each approach.
    fn approach_sleepers(&self) -> usize {
        (self.approach_length / self.sleeper_spacing).round() as usize
    }

    /// Upper estimate of the free DOFs (used before allocating).
    pub fn estimated_dofs(&self) -> usize {
        let sleepers = self.spans * self.sleepers_per_span() + 2 * self.approach_sleepers();
        let rail_nodes = (sleepers + 1) * self.rail_divisions + 1;
        let deck_nodes = self.spans * (self.sleepers_per_span() + 2);
        let pier_nodes = (self.spans - 1) * self.pier_elements;
        6 * (sleepers + 2 * rail_nodes + deck_nodes + pier_nodes)
    }
}

/// Builder state: nodes and entries.
struct Builder {
    nodes: Vec<[f64; 3]>,
    fixed: Vec<bool>,
    stiffness: Vec<(usize, usize, f64)>,
    mass: Vec<(usize, usize, f64)>,
}

impl Builder {
    fn node(&mut self, at: [f64; 3], fixed: bool) -> usize {
        self.nodes.push(at);
        self.fixed.push(fixed);
        self.nodes.len() - 1
    }

    /// Adds a 12 × 12 element matrix on nodes (a, b), lower triangle.
    fn element(target: &mut Vec<(usize, usize, f64)>, a: usize, b: usize, e: &frame::Element) {
        let dof = |i: usize| if i < 6 { 6 * a + i } else { 6 * b + i - 6 };
        for (i, row) in e.iter().enumerate() {
            for (j, &value) in row.iter().enumerate() {
                let (r, c) = (dof(i), dof(j));
                if r >= c && value != 0.0 {
                    target.push((r, c, value));
                }
            }
        }
    }

    /// A frame element between two nodes; returns its mass (kg).
    fn frame(&mut self, a: usize, b: usize, section: &Section) -> f64 {
        let (pa, pb) = (self.nodes[a], self.nodes[b]);
        let length =
            ((pb[0] - pa[0]).powi(2) + (pb[1] - pa[1]).powi(2) + (pb[2] - pa[2]).powi(2)).sqrt();
        let (k, m) = frame::local_matrices(section, length);
        let axes = frame::axes(pa, pb);
        Self::element(&mut self.stiffness, a, b, &frame::to_global(&k, &axes));
        Self::element(&mut self.mass, a, b, &frame::to_global(&m, &axes));
        section.density * section.area * length
    }

    /// A spring of stiffness k (N/m) along global `axis` between the point
    /// at `offset_a` from node a and the point at `offset_b` from node b.
    fn spring(
        &mut self,
        a: usize,
        offset_a: [f64; 3],
        b: usize,
        offset_b: [f64; 3],
        axis: usize,
        k: f64,
    ) {
        let ga = frame::point_row(axis, offset_a);
        let gb = frame::point_row(axis, offset_b);
        let mut g = [0.0; 12];
        for i in 0..6 {
            g[i] = -ga[i];
            g[i + 6] = gb[i];
        }
        let mut e = [[0.0; 12]; 12];
        for i in 0..12 {
            for j in 0..12 {
                e[i][j] = k * g[i] * g[j];
            }
        }
        Self::element(&mut self.stiffness, a, b, &e);
    }

    /// A rotational spring (N·m/rad) about global axis `axis` (3..6 index).
    fn rotational_spring(&mut self, a: usize, b: usize, dof: usize, k: f64) {
        let (ra, rb) = (6 * a + dof, 6 * b + dof);
        self.stiffness.push((ra, ra, k));
        self.stiffness.push((rb, rb, k));
        self.stiffness.push((ra.max(rb), ra.min(rb), -k));
    }

    /// A point mass (kg) on the three translations of a node.
    fn point_mass(&mut self, node: usize, mass: f64) {
        for d in 0..3 {
            self.mass.push((6 * node + d, 6 * node + d, mass));
        }
    }
}

/// Assembles the viaduct (validated first).
pub fn assemble(p: &ViaductParams) -> Result<Assembled, GenerateError> {
    p.validate()?;
    let estimate = p.estimated_dofs() / 6;
    let mut b = Builder {
        nodes: Vec::with_capacity(estimate + 64),
        fixed: Vec::with_capacity(estimate + 64),
        stiffness: Vec::new(),
        mass: Vec::new(),
    };
    let mut masses = vec![
        ("deck", 0.0),
        ("piers", 0.0),
        ("rails", 0.0),
        ("sleepers", 0.0),
        ("ballast", 0.0),
        ("non_structural", 0.0),
    ];
    let ground = b.node([0.0, 0.0, DECK_BOTTOM - p.pier_height], true);

    // Sleeper positions (x, on which span or None on an approach).
    let total = p.spans as f64 * p.span_length;
    let s = p.sleeper_spacing;
    let n_approach = p.approach_sleepers();
    let n_span = p.sleepers_per_span();
    let s_span = p.span_length / n_span as f64;
    let mut sleepers: Vec<(f64, Option<usize>)> = Vec::new();
    for k in (0..n_approach).rev() {
        sleepers.push((-(k as f64 + 0.5) * s, None));
    }
    for span in 0..p.spans {
        for k in 0..n_span {
            sleepers.push((
                span as f64 * p.span_length + (k as f64 + 0.5) * s_span,
                Some(span),
            ));
        }
    }
    for k in 0..n_approach {
        sleepers.push((total + (k as f64 + 0.5) * s, None));
    }

    // Deck: per span, nodes at both ends and under every sleeper.
    let mut deck_under_sleeper = vec![usize::MAX; sleepers.len()];
    let mut span_ends = Vec::with_capacity(p.spans);
    for span in 0..p.spans {
        let x0 = span as f64 * p.span_length;
        let mut nodes = vec![b.node([x0, 0.0, 0.0], false)];
        for (i, &(x, on)) in sleepers.iter().enumerate() {
            if on == Some(span) {
                let n = b.node([x, 0.0, 0.0], false);
                deck_under_sleeper[i] = n;
                nodes.push(n);
            }
        }
        nodes.push(b.node([x0 + p.span_length, 0.0, 0.0], false));
        for w in nodes.windows(2) {
            masses[0].1 += b.frame(w[0], w[1], &p.deck);
            let length = b.nodes[w[1]][0] - b.nodes[w[0]][0];
            // Ballast and non-structural mass lumped by tributary length.
            for &n in w {
                b.point_mass(n, 0.5 * length * (p.ballast_mass + p.non_structural_mass));
            }
            masses[4].1 += length * p.ballast_mass;
            masses[5].1 += length * p.non_structural_mass;
        }
        span_ends.push((nodes[0], *nodes.last().expect("two nodes at least")));
    }

    // Piers between spans, abutments (ground) at both ends; bearings.
    let seat_z = DECK_BOTTOM;
    let mut seats = vec![ground];
    for i in 1..p.spans {
        let x = i as f64 * p.span_length;
        let base = b.node([x, 0.0, seat_z - p.pier_height], true);
        let mut below = base;
        for e in 1..=p.pier_elements {
            let z = seat_z - p.pier_height * (1.0 - e as f64 / p.pier_elements as f64);
            let n = b.node([x, 0.0, z], false);
            masses[1].1 += b.frame(below, n, &p.pier);
            below = n;
        }
        seats.push(below);
    }
    seats.push(ground);
    for (span, &(start, end)) in span_ends.iter().enumerate() {
        for (deck_node, seat) in [(start, seats[span]), (end, seats[span + 1])] {
            for side in [-1.0, 1.0] {
                let y = side * BEARING_OFFSET;
                for axis in 0..3 {
                    b.spring(
                        deck_node,
                        [0.0, y, DECK_BOTTOM],
                        seat,
                        [0.0, y, 0.0],
                        axis,
                        p.bearing_stiffness[axis],
                    );
                }
            }
        }
    }

    // Sleepers (rigid masses), ballast under each rail seat.
    let sleeper_z = DECK_TOP + BALLAST_DEPTH + 0.5 * SLEEPER_HEIGHT;
    let mut sleeper_nodes = Vec::with_capacity(sleepers.len());
    for (i, &(x, _)) in sleepers.iter().enumerate() {
        let n = b.node([x, 0.0, sleeper_z], false);
        sleeper_nodes.push(n);
        let m = p.sleeper_mass;
        b.point_mass(n, m);
        let inertia = [
            m * (SLEEPER_LENGTH.powi(2) + SLEEPER_HEIGHT.powi(2)) / 12.0,
            m * (SLEEPER_WIDTH.powi(2) + SLEEPER_HEIGHT.powi(2)) / 12.0,
            m * (SLEEPER_LENGTH.powi(2) + SLEEPER_WIDTH.powi(2)) / 12.0,
        ];
        for (d, j) in inertia.into_iter().enumerate() {
            b.mass.push((6 * n + 3 + d, 6 * n + 3 + d, j));
        }
        masses[3].1 += m;
        // Tributary length of the sleeper.
        let length = if sleepers[i].1.is_some() { s_span } else { s };
        let support = deck_under_sleeper[i];
        let (below, below_offset_z) = if support == usize::MAX {
            (ground, 0.0)
        } else {
            (support, DECK_TOP)
        };
        // Under each rail seat; the vertical spring split over the
        // sleeper's width (its front and back edges), so that the ballast
        // resists the sleeper's pitch as the real bed does.
        for side in [-1.0, 1.0] {
            let y = side * p.rail_offset;
            for axis in 0..2 {
                b.spring(
                    below,
                    [0.0, y, below_offset_z],
                    n,
                    [0.0, y, -0.5 * SLEEPER_HEIGHT],
                    axis,
                    0.5 * p.ballast_stiffness[axis] * length,
                );
            }
            for edge in [-0.5, 0.5] {
                let x = edge * SLEEPER_WIDTH;
                b.spring(
                    below,
                    [x, y, below_offset_z],
                    n,
                    [x, y, -0.5 * SLEEPER_HEIGHT],
                    2,
                    0.25 * p.ballast_stiffness[2] * length,
                );
            }
        }
    }

    // Rails: nodes at the ends, every sleeper, and between them.
    let rail_z = sleeper_z + 0.5 * SLEEPER_HEIGHT + RAIL_FOOT_TO_CENTROID;
    // The rail ends half a sleeper spacing beyond the last sleepers.
    let half = 0.5 * if n_approach > 0 { s } else { s_span };
    let first = sleepers.first().map_or(0.0, |s| s.0 - half);
    let last = sleepers.last().map_or(total, |s| s.0 + half);
    let mut stations: Vec<(f64, Option<usize>)> = vec![(first, None)];
    for (i, &(x, _)) in sleepers.iter().enumerate() {
        let prev = stations.last().expect("a station").0;
        for d in 1..p.rail_divisions {
            stations.push((prev + (x - prev) * d as f64 / p.rail_divisions as f64, None));
        }
        stations.push((x, Some(i)));
    }
    let prev = stations.last().expect("a station").0;
    for d in 1..=p.rail_divisions {
        stations.push((
            prev + (last - prev) * d as f64 / p.rail_divisions as f64,
            None,
        ));
    }
    let mut rails = [Vec::new(), Vec::new()];
    for (r, side) in [1.0, -1.0].into_iter().enumerate() {
        let y = side * p.rail_offset;
        for &(x, sleeper) in &stations {
            let n = b.node([x, y, rail_z], false);
            if let Some(&prev) = rails[r].last() {
                masses[2].1 += b.frame(prev, n, &p.rail);
            }
            rails[r].push(n);
            if let Some(i) = sleeper {
                let sl = sleeper_nodes[i];
                for axis in 0..3 {
                    b.spring(
                        sl,
                        [0.0, y, 0.5 * SLEEPER_HEIGHT],
                        n,
                        [0.0, 0.0, -RAIL_FOOT_TO_CENTROID],
                        axis,
                        p.pad_stiffness[axis],
                    );
                }
                b.rotational_spring(sl, n, 3, p.pad_stiffness[3]);
            }
        }
    }
    Ok(Assembled {
        nodes: b.nodes,
        fixed: b.fixed,
        stiffness: b.stiffness,
        mass: b.mass,
        rails,
        component_masses: masses,
    })
}
