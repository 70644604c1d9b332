//! Every advice id vbi makes, with its documentation: `docs/advice.md` is
//! generated from [`KINDS`]. An id is never renamed (scenes' `allow` lists
//! and users' tools name it); a new one is added here and to [`KINDS`].

use super::{Kind, Severity};

/// A bare-number speed faster than any wheeled vehicle in service.
pub const IMPLAUSIBLE_SPEED: Kind = Kind {
    id: "implausible-speed",
    severity: Severity::Warning,
    meaning: "a speed written as a bare number is faster than any wheeled vehicle in service \
              (130 m/s, 468 km/h)",
    why: "speeds are in m/s; a km/h value typed without its unit runs the vehicle 3.6 times \
          too fast, and the run looks valid",
    fix: "write the unit: `speed: 250 km/h`, or `speed: 238.9 m/s` if that speed is meant (a \
          speed with its unit is taken as meant and draws no warning)",
    example: "`vehicles: [{type: moving_force, loads: [100 kN], speed: 250}]`",
};

/// An acceleration along the path above what a vehicle on wheels reaches.
pub const IMPLAUSIBLE_ACCELERATION: Kind = Kind {
    id: "implausible-acceleration",
    severity: Severity::Warning,
    meaning: "a vehicle's acceleration along its path is above 10 m/s² (about 1 g of braking)",
    why: "no vehicle on wheels brakes or accelerates that hard; the value is probably in the \
          wrong unit",
    fix: "give `acceleration` in m/s² (trains brake at 1–2.5 m/s², cars at up to about 9 m/s²)",
    example: "`acceleration: -25` on a rail car",
};

/// An FRA track class run faster than it is maintained for.
pub const FRA_CLASS_TOO_SLOW: Kind = Kind {
    id: "fra-class-too-slow",
    severity: Severity::Warning,
    meaning: "a vehicle runs faster than the FRA track class's maximum speed (49 CFR 213.9(a), \
              213.307(a))",
    why: "the spectrum is that of a rougher line than such a train runs on: the response is \
          that of a line that would not be kept for the speed",
    fix: "take the class the speed needs (class 6 allows 110 mph), or the German low- and \
          high-interference spectra (`type: german`) for high-speed lines",
    example: "`surface: {type: fra, class: 4}` under a train at 200 km/h",
};

/// A spectrum's run-in fade that reaches onto the bridge.
pub const RUN_IN_ON_BRIDGE: Kind = Kind {
    id: "run-in-on-bridge",
    severity: Severity::Warning,
    meaning: "a vehicle starts inside the surface's run-in, so the roughness fades in on the \
              bridge",
    why: "the bridge's first metres carry less than the full roughness: the response is \
          below the spectrum's",
    fix: "start every vehicle at or before x = −run_in (leave `start_position` and \
          `entry_time` out to have it placed there)",
    example: "`start_position: 0` with `surface: {type: iso8608, class: B}`",
};

/// A measured profile with points closer than a wheel travels in one step.
pub const MEASURED_PROFILE_FINER_THAN_STEP: Kind = Kind {
    id: "measured-profile-finer-than-step",
    severity: Severity::Warning,
    meaning: "a measured profile's points are closer than a wheel travels in one time step",
    why: "the wheels see the profile only at the steps and miss the features between them",
    fix: "set `solver.time_step` to at most the spacing divided by the speed",
    example: "a profile sampled every 1 mm under a vehicle at 30 m/s with Δt = 1e-4 s",
};

/// An imported model lighter per metre than any bridge deck.
pub const IMPORT_MASS_PER_LENGTH_LOW: Kind = Kind {
    id: "import-mass-per-length-low",
    severity: Severity::Warning,
    meaning: "an imported model's vertical mass per metre of track is below 100 kg/m",
    why: "no bridge deck is so light (a steel footbridge carries some 500 kg/m, a railway \
          deck 10–30 t/m): the files are probably not in N, kg and m. A model in kN and t \
          reads 1000 times too light (its frequencies are right, its static deflections 1000 \
          times too large), one in N, mm and t 10⁶ times (its track 1000 times too long)",
    fix: "export the model in N, kg and m (kN and t: multiply K and M by 1000; mm: export \
          again in m); if the mass is meant, allow the id with the reason",
    example: "a girder exported from OpenSees in kN and t: 36 kg over its 20 m track",
};

/// An imported model that deflects more than a bridge does under its traffic.
pub const IMPORT_STATIC_DEFLECTION_LARGE: Kind = Kind {
    id: "import-static-deflection-large",
    severity: Severity::Warning,
    meaning: "an imported model's static deflection under the vehicles' total weight (at the \
              track's most flexible point) is more than 1/100 of the track's length",
    why: "a bridge deflects some span/500 to span/2000 under its traffic: a stiffness in kN/m \
          (kN·m/rad) read as N/m deflects 1000 times too much, and the vehicles ride a \
          model that is not the bridge",
    fix: "export K in N/m and N·m/rad and M in kg (a model in kN and t: multiply both by \
          1000); if the deflection is meant, allow the id with the reason",
    example: "a 20 m girder in kN and t under a 200 kN moving force: 10.3 m at mid-span",
};

/// A modes cache file that was not used.
pub const MODES_CACHE_REJECTED: Kind = Kind {
    id: "modes-cache-rejected",
    severity: Severity::Note,
    meaning: "the model's modes cache file was not used and the modes were solved afresh",
    why: "the result is right (the modes were solved again); the run only took longer",
    fix: "nothing to do: the cache was rewritten; if this repeats, the cache folder is shared \
          by models that differ",
    example: "a cache file edited by hand",
};

/// The EMBS small parameter ε is not small.
pub const EMBS_EPSILON_NOT_SMALL: Kind = Kind {
    id: "embs-epsilon-not-small",
    severity: Severity::Warning,
    meaning: "the EMBS expansion's small parameter ε = ω_p/ω_B is above 0.5 in a direction",
    why: "the decoupled answer's error grows like ε² (first order) or ε (zero order): it may \
          be far from the coupled one",
    fix: "check with `solver.compare: true`, or use `method: coupled`",
    example: "a light bridge under a heavy train with `method: embs`",
};

/// The EMBS a-posteriori check finds a large first-order part.
pub const EMBS_FIRST_ORDER_LARGE: Kind = Kind {
    id: "embs-first-order-large",
    severity: Severity::Warning,
    meaning: "the EMBS first-order part is large against the zero order's dynamics for some \
              quantities",
    why: "the measured error against `coupled` grows with that ratio η; above 1 the expansion \
          does not converge",
    fix: "check with `solver.compare: true`, or use `method: coupled`",
    example: "`method: embs` where ε is near 1",
};

/// The automatic mode choice is not verified with a zero entry length.
pub const AUTOMATIC_MODES_UNVERIFIED: Kind = Kind {
    id: "automatic-modes-unverified",
    severity: Severity::Warning,
    meaning: "the automatic mode choice is not verified against its 0.5 % target with \
              `bridge.entry_length: 0`",
    why: "each axle puts its whole load on a free rail end in one instant, which rings track \
          modes above the cut (rail displacement 3.7 % off on the shipped \
          viaduct-2span-axle-loads)",
    fix: "check the run with `vbi converge`, set `bridge.modes`, or let the load enter over \
          `bridge.entry_length` (leave it out for its default, docs/format.md)",
    example: "an imported viaduct with `entry_length: 0`",
};

/// The automatic modes stopped at the limits.
pub const AUTOMATIC_MODES_AT_LIMITS: Kind = Kind {
    id: "automatic-modes-at-limits",
    severity: Severity::Warning,
    meaning: "the automatic modes stop at `limits.modes` or `limits.eigen_work` before they \
              carry the rails' flexibility under the wheels",
    why: "the contact forces, rail records and accelerations are not converged at the kept \
          modes",
    fix: "raise `limits.modes` and `limits.eigen_work` and run with `--trust-limits` (or \
          `--allow-large`), or set `bridge.modes` and check with `vbi converge`",
    example: "`vbi generate viaduct --spans 2` under a `rail_car` with nothing else set",
};

/// The kept modes leave out the rails' flexibility and nothing corrects it.
pub const RAILS_FLEXIBILITY_LEFT_OUT: Kind = Kind {
    id: "rails-flexibility-left-out",
    severity: Severity::Warning,
    meaning: "the bridge modes leave out a share of the rails' static flexibility under a \
              wheel, and the contacts carry no static correction for it",
    why: "the wheels ride on rails stiffer than the model's: contact forces, rail records and \
          accelerations are not converged",
    fix: "keep more modes (`bridge.modes`) and check with `vbi converge`",
    example: "scenarios/full-scale/embs-viaduct-30span-ave-s103-train.yaml (modes to 15 Hz)",
};

/// A deck-acceleration filter above the kept modes.
pub const ACCELERATION_FILTER_ABOVE_MODES: Kind = Kind {
    id: "acceleration-filter-above-modes",
    severity: Severity::Warning,
    meaning: "a deck acceleration (a record, the envelope, a resonance check's) sums every \
              mode up to its cut-off (EN 1990 A2.4.4.2.1(4): unless set, the greater of 30 Hz, \
              1.5 f₁ and f₃ of the bridge itself), but `bridge.modes` keeps fewer modes than \
              the bridge has below the cut-off",
    why: "the modes between the kept top and the filter are missing from the sum: the peak \
          acceleration is too low (10.9 % on HSLM-A1 over a 15 m span with one mode kept \
          and the filter at its f₃ = 68.8 Hz)",
    fix: "keep the modes up to the filter (`bridge.modes: {max_frequency: F}` with F the \
          filter, or leave `bridge.modes` out), or lower the record's `max_frequency` if a \
          lower filter is meant",
    example: "`modes: {max_frequency: 30}` on a bridge whose third mode is at 69 Hz, with a \
              `bridge_acceleration` record",
};

/// Ground motion that still shakes when the run ends.
pub const GROUND_MOTION_AFTER_RUN: Kind = Kind {
    id: "ground-motion-after-run",
    severity: Severity::Warning,
    meaning: "a ground-motion record still shakes when the run ends",
    why: "the bridge's response to it, and every absolute acceleration, may peak after the run",
    fix: "set `solver.free_vibration` so the run lasts to the record's end",
    example: "examples/seismic-crossing.yaml",
};

/// A contact force that peaks at a harmonic surface's entrance kick.
pub const HARMONIC_ENTRANCE_KICK: Kind = Kind {
    id: "harmonic-entrance-kick",
    severity: Severity::Warning,
    meaning: "a contact force is largest at the entrance of a harmonic surface that starts \
              with a step in elevation or slope",
    why: "that kick, not the crossing, is the peak",
    fix: "start the surface level and flat (phase 0 or 180° starts it level; a step in slope \
          remains), or read the peak past the entrance",
    example: "`surface: {type: harmonic, amplitude: 4 mm, wavelength: 1.5, phase: 90 deg}`",
};

/// A contact force that peaks on an imported track's entry or exit ramp.
pub const CONTACT_PEAK_ON_RAIL_END: Kind = Kind {
    id: "contact-peak-on-rail-end",
    severity: Severity::Warning,
    meaning: "a contact force is largest on an imported track's entry or exit ramp, within \
              `bridge.entry_length` of the model's free rail end",
    why: "the free rail end is the model's, not the line's: the peak is an artefact of the \
          model's end",
    fix: "read the peak away from the track's ends (history.csv), or extend the model's \
          approach track",
    example: "tests/golden: embs-viaduct-ave-s103-quake (lateral force at x = 38.6 m of 39 m)",
};

/// A bridge response largest at the very end of its record.
pub const RUN_ENDS_AT_PEAK: Kind = Kind {
    id: "run-ends-at-peak",
    severity: Severity::Warning,
    meaning: "a bridge response is largest at the very end of the record",
    why: "it was still growing when the record ended, so its peak comes later (above the \
          critical speed the largest deflection comes in free vibration)",
    fix: "record longer with `solver.free_vibration`",
    example: "a moving force above a beam's critical speed with `free_vibration: 0`",
};

/// A direct run whose deck-acceleration filter reaches above its kept modes.
pub const DIRECT_RECORDS_ON_KEPT_MODES: Kind = Kind {
    id: "direct-records-on-kept-modes",
    severity: Severity::Warning,
    meaning: "`solver.method: direct` steps the assembled model, exact in space, and its \
              bridge records read the nodal state itself (displacements, moments, shears, \
              reactions, rail records, envelopes), but a deck acceleration filtered at \
              `max_frequency` sums the modes up to the filter, read from the nodal state \
              projected onto the kept modes, and the filter lies above the kept modes (below \
              the model's highest)",
    why: "that acceleration misses the modes between the kept top and its filter, as a modal \
          run's would; the other records, the vehicles and the contact forces are exact in \
          space whatever the modes kept",
    fix: "keep the modes up to the filter (`bridge.modes: {max_frequency: F}`, or the \
          automatic choice), or lower the record's `max_frequency` to the kept modes",
    example: "scenarios/yang-yau-sprung-mass.yaml with `solver: {method: direct}` and a \
              `bridge_acceleration` with `max_frequency: 1000` (10 of its 40 modes kept, up \
              to 480 Hz)",
};

/// Every kind, in the order of the pipeline (scene, plan, run).
pub const KINDS: &[Kind] = &[
    IMPLAUSIBLE_SPEED,
    IMPLAUSIBLE_ACCELERATION,
    FRA_CLASS_TOO_SLOW,
    RUN_IN_ON_BRIDGE,
    MEASURED_PROFILE_FINER_THAN_STEP,
    IMPORT_MASS_PER_LENGTH_LOW,
    IMPORT_STATIC_DEFLECTION_LARGE,
    MODES_CACHE_REJECTED,
    EMBS_EPSILON_NOT_SMALL,
    EMBS_FIRST_ORDER_LARGE,
    AUTOMATIC_MODES_UNVERIFIED,
    AUTOMATIC_MODES_AT_LIMITS,
    RAILS_FLEXIBILITY_LEFT_OUT,
    ACCELERATION_FILTER_ABOVE_MODES,
    GROUND_MOTION_AFTER_RUN,
    HARMONIC_ENTRANCE_KICK,
    CONTACT_PEAK_ON_RAIL_END,
    RUN_ENDS_AT_PEAK,
    DIRECT_RECORDS_ON_KEPT_MODES,
];
