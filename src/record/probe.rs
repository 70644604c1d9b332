//! How each recorded column is computed each step: the probes (mode
//! values at a point, a section, a wheel, a vehicle DOF), the static
//! influence lines of the DAF reference, and the static share of the modes
//! left out (the static correction).

use super::GirderDaf;
use crate::bridge::BridgeError;
use crate::bridge::InfluenceLine;
use crate::bridge::section::{NodalSection, SectionProbe};
use crate::model::Model;
use crate::solve::StepView;
use crate::solve::direct::assembled::LinePoint;

/// How a column is computed each step.
#[derive(Debug, Clone)]
pub(super) enum Probe {
    /// φᵢ(x, y) at the point; w = Σ φᵢ qᵢ. With the static influence
    /// lines of the point for loads along each wheel's line (one per
    /// distinct wheel y) and, per flattened wheel, which one it uses.
    BridgeDisplacement {
        shape: Vec<f64>,
        statics: StaticProbe,
        /// φᵢ(x, y)/ωᵢ² (static correction), m per unit modal force.
        static_shape: Vec<f64>,
        /// N(x, y) on the assembled free DOFs, for a direct run: then
        /// w = N(x, y)ᵀu of the view's nodal state, exact in space, with no
        /// static correction ([`nodal_reading`]).
        nodal: Option<LinePoint>,
    },
    /// ẅ = Σ φᵢ q̈ᵢ, or N(x, y)ᵀü with `nodal` (as for displacements).
    BridgeAcceleration {
        shape: Vec<f64>,
        nodal: Option<LinePoint>,
    },
    /// The rails' lateral displacement v = Σ φᵢ qᵢ (φ the modes' lateral
    /// components at the point), or with `acceleration` v̈: a modal sum,
    /// plus under a lateral record the lateral static share of the modes
    /// left out (`Column::lateral_static`; the static crossing is vertical).
    /// With `nodal`, N(x)ᵀu (or N(x)ᵀü) of the rails' lateral
    /// interpolation in a direct run, and no static share.
    Lateral {
        shape: Vec<f64>,
        acceleration: bool,
        nodal: Option<LinePoint>,
    },
    /// A plate deck's moment per unit width at a point; `line_of[w]` is
    /// the probe's influence line of flattened wheel w.
    PlateMoment {
        probe: Box<crate::bridge::plate::moments::PlateMomentProbe>,
        line_of: Vec<usize>,
    },
    /// Bending moment (or, with `shear`, shear force) of a beam section.
    /// With `nodal`, from a direct run's nodal state ([`NodalSection`]).
    Section {
        section: Box<SectionProbe>,
        shear: bool,
        nodal: Option<Box<NodalSection>>,
    },
    /// A beam support's vertical reaction at `x`, N: the shear on its right
    /// (none at the exit) minus the shear on its left (none at the
    /// entrance), plus the wheels standing exactly on it.
    /// With `nodal` (one per side, [`ReactionProbe::sides`]' order), from a
    /// direct run's nodal state: the support's row of the equations of
    /// motion.
    Reaction {
        probe: Box<crate::bridge::section::ReactionProbe>,
        nodal: Vec<NodalSection>,
    },
    /// An imported model's support reaction at a constrained DOF, N (or
    /// N·m): read from its rows of K and M ([`crate::bridge::fe_import::reaction`]).
    /// With `nodal` (the Rayleigh coefficients c_M 1/s, c_K s), from a
    /// direct run's nodal state: its rows applied to it.
    SupportReaction {
        reaction: Box<crate::bridge::fe_import::reaction::SupportReaction>,
        nodal: Option<(f64, f64)>,
    },
    /// A plate deck's line reaction at a support, N; `line_of[w]` is the
    /// probe's influence line of flattened wheel w.
    PlateReaction {
        probe: Box<crate::bridge::plate::reactions::PlateReactionProbe>,
        line_of: Vec<usize>,
    },
    /// Flattened wheel index.
    ContactForce { wheel: usize },
    /// Flattened wheel index.
    ContactGap { wheel: usize },
    /// Vehicle and DOF; displacement from static equilibrium.
    VehicleDisplacement { vehicle: usize, dof: usize },
    /// Vehicle and DOF.
    VehicleAcceleration { vehicle: usize, dof: usize },
}
impl Probe {
    /// Whether the probe reads the modal coordinates: a bridge probe
    /// without a nodal reading (the vehicles' and contacts' own are read
    /// from the view directly).
    pub(super) fn reads_modes(&self) -> bool {
        match self {
            Self::ContactForce { .. }
            | Self::ContactGap { .. }
            | Self::VehicleDisplacement { .. }
            | Self::VehicleAcceleration { .. } => false,
            _ => !self.reads_nodal(),
        }
    }

    /// Whether the probe reads a direct run's nodal state (its value then
    /// carries no static share of modes left out).
    pub(super) fn reads_nodal(&self) -> bool {
        match self {
            Self::BridgeDisplacement { nodal, .. }
            | Self::BridgeAcceleration { nodal, .. }
            | Self::Lateral { nodal, .. } => nodal.is_some(),
            Self::Section { nodal, .. } => nodal.is_some(),
            Self::Reaction { nodal, .. } => !nodal.is_empty(),
            Self::SupportReaction { nodal, .. } => nodal.is_some(),
            _ => false,
        }
    }
}

/// The distinct transverse positions y of the wheels (m), in order of
/// first appearance, and the index of each flattened wheel's among them:
/// one static influence line per such line serves every wheel on it.
pub(super) fn wheel_lines(model: &Model) -> (Vec<f64>, Vec<usize>) {
    let mut lines: Vec<f64> = Vec::new();
    let line_of = model
        .wheel_y
        .iter()
        .map(|&wheel_y| match lines.iter().position(|&l| l == wheel_y) {
            Some(index) => index,
            None => {
                lines.push(wheel_y);
                lines.len() - 1
            }
        })
        .collect();
    (lines, line_of)
}

/// The static influence lines of one bridge point for the loads of every
/// wheel: one line per distinct wheel y, and which one each flattened wheel uses.
#[derive(Debug, Clone)]
pub(super) struct StaticProbe {
    pub(super) influences: Vec<InfluenceLine>,
    pub(super) wheel_influence: Vec<usize>,
}

impl StaticProbe {
    /// The probe of the point (x, y), m.
    pub(super) fn new(model: &Model, x: f64, y: f64) -> Result<Self, BridgeError> {
        let (lines, wheel_influence) = wheel_lines(model);
        let influences = lines
            .iter()
            .map(|&line| model.bridge.influence_line(x, y, line))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self {
            influences,
            wheel_influence,
        })
    }

    /// The probe of free DOF `dof` of an imported model: one influence line
    /// along its track, which every wheel uses.
    pub(super) fn of_dof(model: &Model, dof: usize) -> Result<Self, BridgeError> {
        Ok(Self {
            influences: vec![model.bridge.dof_influence_line(dof)?],
            wheel_influence: vec![0; model.wheel_y.len()],
        })
    }

    /// Static deflection at the point, m (upward positive), under two load
    /// sets at once, `loads` and `static_loads` (N, downward), each wheel's
    /// at `positions`, each influence value read once: the full deflection
    /// of the static correction and the static crossing's. Only the wheels
    /// `on_deck` (indices) are summed: the influence lines vanish off the
    /// deck.
    pub(super) fn deflections(
        &self,
        positions: &[f64],
        loads: &[f64],
        static_loads: &[f64],
        on_deck: &[usize],
    ) -> (f64, f64) {
        // From −0.0, as `Iterator::sum` starts (`deflection_from`'s bits).
        on_deck.iter().fold((-0.0, -0.0), |(a, b), &w| {
            let g = self.influences[self.wheel_influence[w]].value_at(positions[w]);
            (a - loads[w] * g, b - static_loads[w] * g)
        })
    }

    /// The influence line's value at each wheel `on_deck` (in that order),
    /// m/N, into `values`: [`Self::deflections`]' factors, for several
    /// load sets at one step.
    pub(super) fn values_at_wheels(
        &self,
        positions: &[f64],
        on_deck: &[usize],
        values: &mut Vec<f64>,
    ) {
        values.clear();
        values.extend(
            on_deck
                .iter()
                .map(|&w| self.influences[self.wheel_influence[w]].value_at(positions[w])),
        );
    }

    /// One deflection of [`Self::deflections`] from the values of
    /// [`Self::values_at_wheels`].
    pub(super) fn deflection_from(values: &[f64], loads: &[f64], on_deck: &[usize]) -> f64 {
        on_deck
            .iter()
            .zip(values)
            .map(|(&w, value)| -loads[w] * value)
            .sum()
    }
}

/// One column's per-step values that do not depend on the run's state
/// (bridge displacements; empty for other columns).
#[derive(Debug, Default)]
pub(super) struct ColumnStatics {
    /// The influence line at each wheel on the deck, m/N.
    pub(super) influence: Vec<f64>,
    /// The static crossing's deflection, m.
    pub(super) static_w: f64,
    /// φ_s·φ_w (the column's static shape, each wheel's mode values) per
    /// wheel on the deck, m/N.
    pub(super) wheel_dots: Vec<f64>,
}

impl Clone for ColumnStatics {
    fn clone(&self) -> Self {
        Self {
            influence: self.influence.clone(),
            static_w: self.static_w,
            wheel_dots: self.wheel_dots.clone(),
        }
    }

    /// In place, keeping the buffers: copied every step of every sample.
    fn clone_from(&mut self, source: &Self) {
        self.influence.clone_from(&source.influence);
        self.static_w = source.static_w;
        self.wheel_dots.clone_from(&source.wheel_dots);
    }
}

/// The per-step values the recorders of one lockstep batch share
/// ([`super::Recorder::sharing_statics`]).
#[derive(Debug, Default)]
pub struct SharedStatics {
    /// The step they belong to.
    pub(super) step: Option<usize>,
    pub(super) columns: Vec<ColumnStatics>,
}
/// Tracks one [`GirderDaf`] during the run.
#[derive(Debug, Clone)]
pub(super) struct DafProbe {
    pub(super) result: GirderDaf,
    pub(super) shape: Vec<f64>,
    pub(super) statics: StaticProbe,
    pub(super) static_shape: Vec<f64>,
    /// N(x, y) for a direct run's nodal deflection ([`Probe::BridgeDisplacement`]).
    pub(super) nodal: Option<LinePoint>,
}

/// The value of a probe's `point` in the view's nodal state, `acceleration`
/// selecting ü over u: N(x)ᵀu or N(x)ᵀü (m or m/s²), when the probe has a
/// point (a direct run's) and the view a nodal state; `None` otherwise, and
/// the record reads the modal coordinates. Cost O(1) (at most
/// [`crate::solve::direct::assembled::POINT_DOFS`] products).
#[inline]
pub(super) fn nodal_reading(
    point: Option<&LinePoint>,
    view: &StepView<'_>,
    acceleration: bool,
) -> Option<f64> {
    let (point, state) = (point?, view.nodal.as_ref()?);
    Some(if acceleration {
        point.value(state.acceleration)
    } else {
        point.value(state.displacement)
    })
}

/// φᵢ/ωᵢ² of a point's mode values `shape` (the modal static flexibility).
pub(super) fn static_shape(model: &Model, shape: &[f64]) -> Vec<f64> {
    shape
        .iter()
        .zip(&model.bridge.circular_frequencies)
        .map(|(phi, w)| phi / (w * w))
        .collect()
}

/// The static share of the modes left out at a point (m, upward
/// positive): the full static deflection under the current wheel forces,
/// `full` (m, [`StaticProbe::deflections`] under the contact forces), minus
/// its modal part, Σ_w F_w [Σᵢ φᵢ(x)φᵢ(x_w)/ωᵢ² − G(x, x_w)]
/// (mode-acceleration method; Williams 1945; Cornwell, Craig & Johnson
/// 1983). `wheel_modes` holds the mode values at each wheel (wheel-major).
pub(super) fn static_share_beyond(
    full: f64,
    static_shape: &[f64],
    wheel_modes: &[f64],
    view: &StepView<'_>,
    on_deck: &[usize],
) -> f64 {
    let modes = static_shape.len();
    let modal: f64 = on_deck
        .iter()
        .map(|&w| {
            let values = &wheel_modes[w * modes..(w + 1) * modes];
            -view.contact_forces[w] * dot(static_shape, values)
        })
        .sum();
    full - modal
}
/// The deck-acceleration filter: the mode values `shape` with the modes
/// above the cut-off `max_frequency` (Hz) zeroed (a sharp modal low-pass,
/// EN 1990 A2.4.4.2.1(4)).
pub(super) fn filtered_shape(model: &Model, shape: &[f64], max_frequency: Option<f64>) -> Vec<f64> {
    let mut shape = shape.to_vec();
    if let Some(cut) = max_frequency {
        let limit = 2.0 * std::f64::consts::PI * cut * (1.0 + 1e-12);
        for (value, omega) in shape.iter_mut().zip(&model.bridge.circular_frequencies) {
            if *omega > limit {
                *value = 0.0;
            }
        }
    }
    shape
}

pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
