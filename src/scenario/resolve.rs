//! Semantic checks and defaults: [`ScenarioRaw`] → the described
//! [`Sections`] the planning stage starts from ([`describe`]), and the
//! records' checks that still run when an error stopped either stage
//! ([`cross_checks`]). The stages are driven by [`super::load`].
//!
//! Every problem is reported with the location of the offending key (or, if
//! the key is absent, of the section that lacks it), and all problems found
//! are reported together, like a compiler.

use super::bridges::resolve_bridge;
use super::budget::{Budget, LoadOptions};
use super::checker::Checker;
use super::derive::resolve_contact;
use super::plausible;
use super::raw::{self, ScenarioRaw};
use super::records::resolve_records;
use super::vehicles::{resolve_vehicles, vehicles_as_written};
use crate::scene::*;

/// Default finite elements per span.
pub const DEFAULT_ELEMENTS_PER_SPAN: usize = 20;
/// Default gravitational acceleration, m/s².
pub const DEFAULT_GRAVITY: f64 = 9.81;
/// HHT α used by default with rigid unilateral contact.
pub const DEFAULT_RIGID_ALPHA: f64 = -0.05;

/// The records and envelopes checked against the bridge and the vehicles as
/// the file writes them, when an earlier error stopped the resolution
/// before them (so that a file's mistakes come in one round, issue 28.1).
/// The bridge and vehicles are resolved again into a scratch checker (their
/// own errors are already reported); without a valid bridge what needs it
/// (a position on the deck, a node, the envelopes) is not checked. Defaults that need the bridge's frequencies are not needed for
/// checking and get none.
pub(crate) fn cross_checks(raw: &ScenarioRaw, ck: &mut Checker<'_>, options: &LoadOptions) {
    let mut scratch = Checker::new(ck.file, ck.source, ck.root);
    scratch.set_data_access(options.data.clone());
    let limits = Limits::resolve(raw.limits.as_ref(), &mut scratch);
    let budget = Budget::new(limits, options);
    if !budget.counts(raw, &mut scratch) {
        return;
    }
    // A bridge that did not parse or has errors of its own: the records
    // are checked against the vehicles alone.
    let bridge = if ck.bridge_unreadable {
        None
    } else {
        resolve_bridge(&raw.bridge, &budget, &mut scratch)
    }
    .filter(|_| !ck.uncertain("bridge"));
    scratch.bridge_unknown = bridge.is_none();
    let width = bridge.as_ref().and_then(Bridge::width);
    let vehicles = vehicles_as_written(&raw.vehicles, width, &mut scratch);
    let contact = resolve_contact(raw.contact.as_ref(), &vehicles, &mut scratch);
    let records = raw.record.as_deref();
    resolve_records(records, None, bridge.as_ref(), &vehicles, &contact, ck);
    if let Some(bridge) = &bridge {
        super::envelopes::resolve_envelopes(raw.envelopes.as_ref(), None, bridge, ck);
    }
}

/// A scene as the format leaves it for the planning stage
/// ([`crate::plan`]): the sections checked without physics and the budgets;
/// the file's raw form (for the rest: records, study, contact, output)
/// travels beside it.
#[derive(Debug, Clone)]
pub(crate) struct Sections {
    /// How the file was loaded.
    pub options: LoadOptions,
    /// The budgets the file asked for.
    pub limits: Limits,
    /// The budgets in force.
    pub budget: Budget,
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// The bridge, without its modes chosen.
    pub bridge: Bridge,
    /// The vehicles as written (dimensionless groups not yet derived).
    pub vehicles: Vec<Vehicle>,
    /// The surface profile.
    pub surface: Surface,
    /// The ground-motion records.
    pub ground_motion: Vec<GroundMotion>,
    /// The `solver` section as written.
    pub solver_raw: raw::SolverRaw,
    /// The Newmark parameters, defaults filled in.
    pub newmark: Newmark,
    /// Free-vibration time after the last exit, s.
    pub free_vibration: f64,
    /// The advice ids the scene leaves unheeded, with reasons.
    pub allow: Vec<crate::advice::Allow>,
    /// The data files read, with their content hashes.
    pub data_read: Vec<crate::scene::DataRead>,
}

/// The format's part of a scene's resolution: every check that needs no
/// physics on the sections the planning stage starts from, stopping at the
/// first stage with errors ([`super::load`] drives it, then the plan).
pub(crate) fn describe(
    raw: &ScenarioRaw,
    ck: &mut Checker<'_>,
    options: LoadOptions,
) -> Option<Sections> {
    ck.set_data_access(options.data.clone());
    super::names::check_name(ck, &raw.name);
    let allow = super::allow::resolve(raw.allow.as_deref(), ck);
    let limits = Limits::resolve(raw.limits.as_ref(), ck);
    let budget = Budget::new(limits, &options);
    // Counts read straight from the file come first: a file with 10⁵ axles
    // or records is refused before anything is done per axle or record.
    if !budget.counts(raw, ck) {
        return None;
    }
    let gravity = raw.gravity.unwrap_or(DEFAULT_GRAVITY);
    ck.positive("gravity", gravity, "gravity");
    plausible::within(
        ck,
        "gravity",
        "a gravitational acceleration",
        gravity,
        plausible::GRAVITY,
        "m/s²",
    );

    let bridge = if ck.bridge_unreadable {
        None
    } else {
        resolve_bridge(&raw.bridge, &budget, ck)
    };
    if let Some(bridge) = &bridge {
        plausible::check_bridge(ck, bridge);
    }
    // A bridge with a placeholder or a lost span is checked, but is no
    // reference for the other sections (its length or width may not be
    // the file's).
    let bridge = bridge.filter(|_| !ck.uncertain("bridge"));
    ck.bridge_unknown = bridge.is_none();
    let width = bridge.as_ref().and_then(Bridge::width);
    let vehicles = resolve_vehicles(&raw.vehicles, width, ck);
    let bridge_length = bridge.as_ref().map_or(0.0, Bridge::length);
    let surface =
        super::surfaces::resolve_surface(raw.surface.as_ref(), bridge_length, &budget, ck);
    let ground_motion = super::ground::resolve(
        raw.ground_motion.as_deref(),
        bridge.as_ref(),
        raw.vehicles
            .iter()
            .any(|v| matches!(v, raw::VehicleRaw::Train3d(_))),
        &budget,
        ck,
    );
    let solver_raw = raw.solver.clone().unwrap_or_default();
    let newmark_raw = solver_raw.newmark.clone().unwrap_or(raw::NewmarkRaw {
        beta: None,
        gamma: None,
        alpha: None,
    });
    // Rigid contact holds wheel DOFs to the surface through multipliers, which
    // average-acceleration Newmark leaves ringing (a persistent alternating
    // error in the wheel acceleration and force); a little HHT damping
    // removes it at second order. Every other model defaults to α = 0.
    let rigid = matches!(raw.contact, Some(raw::ContactRaw::Rigid { .. }));
    let default_alpha = if rigid && newmark_raw.beta.is_none() && newmark_raw.gamma.is_none() {
        DEFAULT_RIGID_ALPHA
    } else {
        0.0
    };
    let alpha = newmark_raw.alpha.unwrap_or(default_alpha);
    if !(-1.0 / 3.0..=0.0).contains(&alpha) {
        ck.error(
            "solver.newmark.alpha",
            format!("HHT α must be in [−1/3, 0], got {alpha}"),
        );
    }
    let newmark = Newmark {
        beta: newmark_raw.beta.unwrap_or((1.0 - alpha).powi(2) / 4.0),
        gamma: newmark_raw.gamma.unwrap_or(0.5 - alpha),
        alpha,
    };
    ck.positive("solver.newmark.beta", newmark.beta, "Newmark β");
    if newmark.gamma < 0.5 {
        ck.error(
            "solver.newmark.gamma",
            format!(
                "Newmark γ must be at least 0.5 (below it the scheme amplifies every mode), got {}",
                newmark.gamma
            ),
        );
    }
    let free_vibration = solver_raw.free_vibration.unwrap_or(0.0);
    ck.non_negative(
        "solver.free_vibration",
        free_vibration,
        "free-vibration time",
    );
    super::plausible::within(
        ck,
        "solver.free_vibration",
        "a free-vibration time",
        free_vibration,
        super::plausible::FREE_VIBRATION,
        "s",
    );
    if let Some(dt) = solver_raw.time_step {
        ck.positive("solver.time_step", dt, "time step");
        super::plausible::within_because(
            ck,
            "solver.time_step",
            "a time step",
            dt,
            super::plausible::TIME_STEP,
            "s",
            "a nanosecond is far below what the stiffest wheel contact needs; a second \
             resolves nothing above 0.5 Hz, below the first mode of almost any bridge",
        );
    }

    // The bridge is built only from a valid description, and only if its
    // eigenproblem fits the budget: the dense solve is O(n³).
    let (bridge, vehicles) = (bridge?, vehicles?);
    // Placeholders' physics is not the scene's: no plan.
    if !ck.diagnostics.is_empty() || ck.placeheld {
        return None;
    }
    // Vehicles the file gives in full are judged before any budget reads
    // their lengths (issue 39.5: a spacing of 1e308 m was blamed on the
    // speed, "over the inf s run"); oscillators derived from the bridge's
    // frequencies are judged once derived, in the plan.
    for (i, vehicle) in vehicles.iter().enumerate() {
        let derived = matches!(raw.vehicles.get(i),
            Some(raw::VehicleRaw::Oscillator(o)) if o.dimensionless.is_some());
        if derived {
            continue;
        }
        let at = format!("vehicles[{i}]");
        let entry_field = if ck.has(&format!("{at}.start_position")) {
            "start_position"
        } else {
            "entry_time"
        };
        super::plausible::check_vehicle(ck, &at, entry_field, vehicle);
    }
    if !ck.diagnostics.is_empty() {
        return None;
    }
    if !budget.model(&bridge, &surface, ck) {
        return None;
    }
    // The cheapest budget before the dearest work: a step count set by the
    // file is refused before any eigen solve (issue 23.3).
    if !super::long_run::steps_fit_before_modes(
        raw,
        &vehicles,
        &ground_motion,
        &surface,
        bridge.length(),
        free_vibration,
        &budget,
        ck,
    ) {
        return None;
    }
    Some(Sections {
        options,
        limits,
        budget,
        gravity,
        bridge,
        vehicles,
        surface,
        ground_motion,
        solver_raw,
        newmark,
        free_vibration,
        allow,
        data_read: ck.data_read(),
    })
}
