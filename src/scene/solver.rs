//! The solution method a scene asks for.

use schemars::JsonSchema;
use serde::Deserialize;

/// Solution method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SolverMethod {
    /// Permanent contact: vehicle and modal bridge equations solved together at
    /// every step, the wheel DOFs eliminated by the contact kinematics.
    Coupled,
    /// Unilateral contact: bridge and vehicles advanced as uncoupled subsystems,
    /// the contact forces found from a linear complementarity problem per step
    /// (Lemke's method).
    Lcp,
    /// Permanent contact by the uncoupled scheme of the plate-deck paper
    /// (Section 2.5): in every step the vehicles and the bridge are solved
    /// separately and the interaction forces iterated (with Aitken
    /// relaxation) until the contact displacements change by less than
    /// `tolerance`. Converges to the `coupled` solution; the summary reports
    /// the iterations per step.
    Iterative,
    /// Permanent contact decoupled by the Extended Modified Bridge System
    /// (EMBS paper, Section 2): the bridge carrying the wheel masses alone
    /// (zero order, Eq. 5), the vehicle's upper part under the ground
    /// motion alone (Eq. 6), the first-order bridge loaded by the
    /// zero-order suspension forces (Eq. 7), then the vehicle driven by the
    /// summed bridge response through its wheels (Eq. 3). Accurate while
    /// ε = ω_p/ω_B (primary suspension over first bridge frequency) is
    /// small; the summary states ε.
    Embs,
    /// Permanent contact on the bridge's assembled finite-element matrices
    /// instead of its modes: Newmark/HHT on M ü + C u̇ + K u = f, the
    /// effective stiffness factorised once, exact in space (no modal
    /// truncation); the vehicles as in `coupled`. A plane `type: beam` or
    /// a `type: fe_import` model, with Rayleigh damping or none. Bridge records are taken from the nodal state's projection
    /// onto the kept modes (exact with every mode kept); vehicle and
    /// contact records are the direct solution's.
    Direct,
}
