//! Resource budgets: every size a run's time or memory grows with is
//! estimated while checking and compared with a limit before any work
//! starts, so that a hostile or mistyped file is refused in milliseconds
//! instead of exhausting the machine.
//!
//! The limits default to what a workstation does in minutes. A scene may
//! lower one in its `limits` section; it may raise one only for a user who
//! allows it on the command line (`--trust-limits`), so that a stranger's
//! file cannot lift the limits for whoever checks it. `--allow-large` lifts
//! them all. Every
//! estimate is computed in `f64` or with checked integer arithmetic, so no
//! user-given size can wrap around.

use super::checker::Checker;
use super::raw::{self, LimitsRaw};
use crate::scene::{Bridge, Limits, Surface};

/// How a scene is loaded: whether its budgets are enforced, where solved
/// modes are cached, and how many threads its eigen solve may use.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LoadOptions {
    /// Lift every resource limit (`--allow-large`); sizes are still checked
    /// for overflow.
    pub allow_large: bool,
    /// Let the file's own `limits` section raise limits above the defaults
    /// (`--trust-limits`). Without it a raised limit stays at its default
    /// (a lowered one always applies), and a refusal says the file asks for
    /// more. [`super::load_file`] and [`super::load_str`] trust the file: a
    /// program that loads a file chose it.
    pub trust_limits: bool,
    /// The folder of the modes cache ([`crate::bridge::eigen::cache`]):
    /// an imported model's modes are read from it when a valid file holds
    /// them, and written to it when solved. `None`: no cache (the library
    /// default; the command line's default is `<output folder>/.vbi-cache`).
    pub modes_cache: Option<std::path::PathBuf>,
    /// Where the files a scene names may be read from: its own folder tree
    /// and the `--data-dir` folders ([`super::data_files`]).
    pub data: super::data_files::DataAccess,
    /// The parallelism of the bridge's eigen solve (`Par::Seq`, the library
    /// default, or `Par::Rayon(threads)` on the current rayon pool; the
    /// command line's default is every core, `--threads`). The modes are
    /// bit-identical whatever it is ([`crate::bridge::eigen::parallel`]).
    pub par: faer::Par,
}

impl Default for LoadOptions {
    fn default() -> Self {
        Self {
            allow_large: false,
            trust_limits: false,
            modes_cache: None,
            data: Default::default(),
            par: faer::Par::Seq,
        }
    }
}

impl Default for Limits {
    /// Sized for a workstation: a bridge of 2000 units (a beam's DOFs count
    /// 1/50 each, [`bridge_dofs`]) checks in a few seconds; 1e7 steps of a small model take about a minute; 2e9 bytes
    /// of CSV fit any disk and editor-free pipeline.
    fn default() -> Self {
        Limits {
            dofs: 2000.0,
            modes: 500.0,
            eigen_work: 2e9,
            steps: 1e7,
            study_steps: 2e8,
            run_work: 2e9,
            wheels: 500.0,
            records: 500.0,
            study_points: 10_000.0,
            road_terms: 20_000.0,
            profile_points: 2_000_000.0,
            profile_work: 2e9,
            ground_points: 1e7,
            output_bytes: 2e9,
            import_entries: 2e7,
        }
    }
}

/// Sizes beyond this are refused even with `--allow-large`: they cannot be
/// counted in memory (a `usize` index) on any machine.
const ABSOLUTE: f64 = 1e15;

impl Limits {
    /// Whether every limit is the default (the resolved scene then omits the
    /// section).
    pub fn is_default(&self) -> bool {
        *self == Limits::default()
    }

    /// Fills the defaults of the file's `limits` section and checks each
    /// given value is a positive whole number.
    pub(crate) fn resolve(raw: Option<&LimitsRaw>, ck: &mut Checker<'_>) -> Limits {
        let d = Limits::default();
        let Some(raw) = raw else { return d };
        let mut pick = |key: &str, given: Option<f64>, default: f64| match given {
            None => default,
            Some(v) if (1.0..=ABSOLUTE).contains(&v) && v.fract() == 0.0 => v,
            Some(v) => {
                ck.error(
                    &format!("limits.{key}"),
                    format!("a limit must be a whole number from 1 to {ABSOLUTE:e}, got {v}"),
                );
                default
            }
        };
        Limits {
            dofs: pick("dofs", raw.dofs, d.dofs),
            modes: pick("modes", raw.modes, d.modes),
            eigen_work: pick("eigen_work", raw.eigen_work, d.eigen_work),
            steps: pick("steps", raw.steps, d.steps),
            study_steps: pick("study_steps", raw.study_steps, d.study_steps),
            run_work: pick("run_work", raw.run_work, d.run_work),
            wheels: pick("wheels", raw.wheels, d.wheels),
            records: pick("records", raw.records, d.records),
            study_points: pick("study_points", raw.study_points, d.study_points),
            road_terms: pick("road_terms", raw.road_terms, d.road_terms),
            profile_points: pick("profile_points", raw.profile_points, d.profile_points),
            profile_work: pick("profile_work", raw.profile_work, d.profile_work),
            ground_points: pick("ground_points", raw.ground_points, d.ground_points),
            output_bytes: pick("output_bytes", raw.output_bytes, d.output_bytes),
            import_entries: pick("import_entries", raw.import_entries, d.import_entries),
        }
    }
}

/// Compares estimates with the limits and reports at the input that drives
/// each one.
#[derive(Debug, Clone)]
pub(crate) struct Budget {
    /// The limits that apply: the file's where it lowers them (or where the
    /// command line trusts it), else the defaults.
    limits: Limits,
    /// The file's own limits, defaults filled in.
    asked: Limits,
    allow_large: bool,
}

impl Budget {
    pub(crate) fn new(asked: Limits, options: &LoadOptions) -> Self {
        let mut limits = asked;
        if !options.trust_limits {
            let d = Limits::default();
            for key in Limits::KEYS {
                limits.set(key, asked.get(key).min(d.get(key)));
            }
        }
        Budget {
            limits,
            asked,
            allow_large: options.allow_large,
        }
    }

    /// Checks `asked` against the limit `key`; `what` names the quantity and
    /// `path` is where the input that drives it is written. Returns whether
    /// it fits.
    pub(crate) fn check(
        &self,
        ck: &mut Checker<'_>,
        path: &str,
        key: &str,
        what: &str,
        asked: f64,
    ) -> bool {
        self.check_because(ck, path, key, what, asked, "")
    }

    /// [`Budget::check`] with `because` (why the input at `path` asks for
    /// so much, and what would fit) added to a refusal.
    pub(crate) fn check_because(
        &self,
        ck: &mut Checker<'_>,
        path: &str,
        key: &str,
        what: &str,
        asked: f64,
        because: &str,
    ) -> bool {
        match self.refusal(key, what, asked) {
            None => true,
            Some(message) if because.is_empty() => {
                ck.error(path, message);
                false
            }
            Some(message) => {
                ck.error(path, format!("{message}; {because}"));
                false
            }
        }
    }

    /// Why `asked` of the quantity `what` does not fit the limit `key`, or
    /// `None` if it does.
    pub(crate) fn refusal(&self, key: &str, what: &str, asked: f64) -> Option<String> {
        let limit = self.limit(key);
        let fits = |bound: f64| asked.is_finite() && asked <= bound;
        if self.allow_large {
            if fits(ABSOLUTE) {
                return None;
            }
            return Some(format!(
                "{what}: {} is more than any machine can hold ({ABSOLUTE:e}), even with `--allow-large`",
                count(asked)
            ));
        }
        if fits(limit) {
            return None;
        }
        if !asked.is_finite() {
            return Some(format!(
                "{what}: {} is more than any limit (`limits.{key}`) allows, even \
                 `--allow-large`",
                count(asked)
            ));
        }
        let raised = self.asked.get(key);
        if raised > limit && fits(raised) {
            return Some(format!(
                "{what}: {} is more than the limit of {} (`limits.{key}`); the file raises the \
                 limit to {}, which applies only if you allow it: run with `--trust-limits` (the \
                 file's own limits) or `--allow-large` (no limits)",
                count(asked),
                count(limit),
                count(raised)
            ));
        }
        Some(format!(
            "{what}: {} is more than the limit of {} (`limits.{key}`); raise it in the file \
             (`limits: {{{key}: {}}}`, applied with `--trust-limits`) or run with `--allow-large`",
            count(asked),
            count(limit),
            count(suggest(asked))
        ))
    }

    /// The counts read straight from the file: wheels and records. Returns
    /// whether they fit.
    pub(crate) fn counts(&self, raw: &raw::ScenarioRaw, ck: &mut Checker<'_>) -> bool {
        let wheels_fit = self.check(
            ck,
            "vehicles",
            "wheels",
            "wheels over all vehicles",
            raw_wheels(&raw.vehicles),
        );
        let records = raw.record.as_ref().map_or(0, Vec::len) as f64;
        let records_fit = self.check(ck, "record", "records", "recorded quantities", records);
        wheels_fit && records_fit
    }

    /// What building the model costs: the bridge's eigenproblem, its modes
    /// and a random road's series. Checked before the eigen solve, which is
    /// O(n³). Returns whether they fit.
    pub(crate) fn model(&self, bridge: &Bridge, surface: &Surface, ck: &mut Checker<'_>) -> bool {
        let (dofs_path, dofs_what) = match bridge {
            Bridge::Plate(_) if ck.has("bridge.terms") => (
                "bridge.terms",
                "degrees of freedom of the plate's eigenproblem (a Ritz term counts 1.5, a transverse function 2.5)",
            ),
            Bridge::Beam(_) if ck.has("bridge.element_length") => (
                "bridge.element_length",
                "degrees of freedom of the bridge's eigenproblem",
            ),
            _ => (
                "bridge.elements_per_span",
                "degrees of freedom of the bridge's eigenproblem",
            ),
        };
        let mut fits = self.check(ck, dofs_path, "dofs", dofs_what, bridge_dofs(bridge));
        if let Some(count) = bridge.modes().count {
            fits &= self.check(
                ck,
                "bridge.modes.count",
                "modes",
                "bridge modes",
                count as f64,
            );
        }
        let terms = match surface {
            Surface::Random { terms, .. } => Some(*terms),
            _ => surface.spectrum().map(|(_, s)| s.terms),
        };
        if let Some(terms) = terms {
            let path = if ck.has("surface.terms") {
                "surface.terms"
            } else if matches!(surface, Surface::Random { .. }) {
                "surface.sampling_length"
            } else {
                "surface.shortest_wavelength"
            };
            fits &= self.check(
                ck,
                path,
                "road_terms",
                "terms of the random profile's series",
                terms as f64,
            );
        }
        fits
    }

    /// The bound `key` enforces (effectively none under `--allow-large`).
    pub(crate) fn limit_of(&self, key: &str) -> f64 {
        if self.allow_large {
            ABSOLUTE
        } else {
            self.limit(key)
        }
    }

    fn limit(&self, key: &str) -> f64 {
        self.limits.get(key)
    }
}

impl Limits {
    /// Every key of the `limits` section.
    const KEYS: [&'static str; 15] = [
        "dofs",
        "modes",
        "eigen_work",
        "steps",
        "study_steps",
        "run_work",
        "wheels",
        "records",
        "study_points",
        "road_terms",
        "profile_points",
        "profile_work",
        "ground_points",
        "output_bytes",
        "import_entries",
    ];

    /// The bound of `key` (one of [`Limits::KEYS`]).
    fn get(&self, key: &str) -> f64 {
        let mut copy = *self;
        *copy.field_mut(key)
    }

    fn set(&mut self, key: &str, value: f64) {
        *self.field_mut(key) = value;
    }

    fn field_mut(&mut self, key: &str) -> &mut f64 {
        match key {
            "dofs" => &mut self.dofs,
            "modes" => &mut self.modes,
            "eigen_work" => &mut self.eigen_work,
            "steps" => &mut self.steps,
            "study_steps" => &mut self.study_steps,
            "run_work" => &mut self.run_work,
            "wheels" => &mut self.wheels,
            "records" => &mut self.records,
            "study_points" => &mut self.study_points,
            "road_terms" => &mut self.road_terms,
            "profile_points" => &mut self.profile_points,
            "profile_work" => &mut self.profile_work,
            "ground_points" => &mut self.ground_points,
            "import_entries" => &mut self.import_entries,
            _ => &mut self.output_bytes,
        }
    }
}

/// Coupled wheels whose contact system costs as much per step as their
/// wheel–wheel products: the system's dense solve, w³/3 flops, against the
/// condensation's w² products of some 45 flops each (fitted on 20–160
/// wheels of rail-car trains, below).
const CONTACT_CUBE_WHEELS: f64 = 135.0;
/// How much less a moving-force axle costs per mode and step than a
/// coupled wheel (0.6 ns against about 31 ns measured): it is a load on
/// the modes, with no contact system.
const MOVING_FORCE_AXLE_WEIGHT: f64 = 1.0 / 50.0;

/// The work of one run, in units of about 30 ns on this project's 2-core
/// machine: per time step, coupled wheels × (modes + w(1 + w/135)) for the
/// w coupled wheels of every vehicle with DOFs (they share one dense
/// contact system per step), plus moving-force axles × modes / 50.
/// Measured with `vbi run` (permanent contact, the dearest; elastic, Hertz
/// and rigid contact cost a fifth to a half of it) on a 25 m beam: a train
/// of 5, 10, 20 and 40 rail cars (20–160 wheels) with 10 modes took 24, 81,
/// 332 and 1,841 µs a step, 36, 33, 30 and 32 ns a unit; 10 and 20 cars
/// with 100 modes 196 and 555 µs (32 and 31 ns); one oscillator with 400
/// modes 7.2 µs (18 ns); seven 3D cars (84 wheels) 485 µs (39 ns); 200
/// moving-force axles with 100 modes 15.6 µs. So the default limit of 2e9
/// is about a minute; a train of 20 cars over 17,000 steps (0.33e9) ran in
/// 5.8 s, one of 125 cars (4.4e11) would run for hours.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RunWork {
    pub steps: f64,
    pub modes: f64,
    /// Wheels of vehicles with DOFs (oscillators, trucks, rail cars, trains).
    pub coupled_wheels: f64,
    /// Axles of moving forces.
    pub axles: f64,
}

impl RunWork {
    pub(crate) fn of(steps: f64, modes: usize, vehicles: &[crate::scene::Vehicle]) -> Self {
        use crate::scene::Vehicle as V;
        let (mut coupled_wheels, mut axles) = (0.0, 0.0);
        for v in vehicles {
            match v {
                V::MovingForce(m) => axles += m.loads.len() as f64,
                V::Oscillator(_) => coupled_wheels += 1.0,
                V::H20Truck(_) | V::RailCar(_) => coupled_wheels += 4.0,
                V::Train(t) => coupled_wheels += 4.0 * t.cars.len() as f64,
                V::Train3d(t) => coupled_wheels += 12.0 * t.cars.len() as f64,
            }
        }
        RunWork {
            steps,
            modes: modes as f64,
            coupled_wheels,
            axles,
        }
    }

    /// The contact system's share of a step per coupled wheel.
    fn contact(wheels: f64) -> f64 {
        wheels * (1.0 + wheels / CONTACT_CUBE_WHEELS)
    }

    /// Work of one step.
    fn per_step(&self, coupled_wheels: f64, modes: f64) -> f64 {
        coupled_wheels * (modes + Self::contact(coupled_wheels))
            + self.axles * modes * MOVING_FORCE_AXLE_WEIGHT
    }

    /// The work of the run.
    pub(crate) fn work(&self) -> f64 {
        self.steps * self.per_step(self.coupled_wheels, self.modes)
    }

    /// The product and its factors, for a message.
    pub(crate) fn what(&self) -> String {
        let mut terms = Vec::new();
        if self.coupled_wheels > 0.0 {
            terms.push(format!(
                "{} wheels × ({} modes + {} for their contact system, w(1 + w/{CONTACT_CUBE_WHEELS}))",
                count(self.coupled_wheels),
                count(self.modes),
                count(Self::contact(self.coupled_wheels).round())
            ));
        }
        if self.axles > 0.0 {
            terms.push(format!(
                "{} moving-force axles × {} modes / 50",
                count(self.axles),
                count(self.modes)
            ));
        }
        format!(
            "work of the run (time steps × wheels × (modes + the wheels' contact system), about \
             30 ns a unit): {} steps × ({})",
            count(self.steps),
            terms.join(" + ")
        )
    }

    /// The most coupled wheels whose work fits `limit` with these steps and
    /// modes (0 if none does).
    pub(crate) fn wheels_fitting(&self, limit: f64) -> f64 {
        let fits = |w: f64| self.steps * self.per_step(w, self.modes) <= limit;
        let (mut lo, mut hi) = (0.0f64, self.coupled_wheels.max(1.0));
        if !fits(lo) {
            return 0.0;
        }
        while hi - lo > 1.0 {
            let mid = ((lo + hi) / 2.0).floor();
            if fits(mid) { lo = mid } else { hi = mid }
        }
        lo
    }

    /// The most modes that fit `limit` with these steps and wheels (0 if
    /// none does).
    pub(crate) fn modes_fitting(&self, limit: f64) -> f64 {
        let per_mode = self.coupled_wheels + self.axles * MOVING_FORCE_AXLE_WEIGHT;
        let fixed = self.coupled_wheels * Self::contact(self.coupled_wheels);
        if per_mode <= 0.0 || self.steps.is_nan() || self.steps <= 0.0 {
            return self.modes;
        }
        ((limit / self.steps - fixed) / per_mode).floor().max(0.0)
    }

    /// The most steps that fit `limit`.
    pub(crate) fn steps_fitting(&self, limit: f64) -> f64 {
        let per = self.per_step(self.coupled_wheels, self.modes);
        if per > 0.0 {
            (limit / per).floor()
        } else {
            self.steps
        }
    }

    /// Whether the contact system, not the modes, makes most of a step.
    pub(crate) fn wheels_dominate(&self) -> bool {
        self.coupled_wheels > 1.0
            && self.coupled_wheels * Self::contact(self.coupled_wheels)
                > self.coupled_wheels * self.modes
                    + self.axles * self.modes * MOVING_FORCE_AXLE_WEIGHT
    }
}

/// Lanczos vectors a beam's eigen solve for `modes` modes needs, as the
/// measure of its cost (n m²). A continuous beam over S spans has S modes
/// in each frequency band (S for each of the vertical, lateral and
/// torsional families of a 3D beam), between the span's simply-supported
/// and clamped frequencies: on identical spans their relative gaps are of
/// order 1/S², so Krylov methods separate the lowest of a band only once
/// the basis holds the whole band (measured on 10 m spans × 2 elements,
/// 10 modes: `vbi check` 1.9 s at 1,000 spans, 16.7 s at 2,000, 53 s at
/// 3,000, cubic). So m = max(k, S): beyond S modes the bands above are
/// resolved in turn, and more than a band's worth of modes costs what the
/// modes cost (limits.modes bounds k). m = k for other bridges.
pub(crate) fn lanczos_vectors(bridge: &Bridge, modes: usize) -> f64 {
    let Bridge::Beam(beam) = bridge else {
        return modes as f64;
    };
    let families = if beam.sway.is_some() { 3.0 } else { 1.0 };
    let band = families * beam.spans.len() as f64;
    band.max(modes as f64)
}

/// A round number at or above `asked` to suggest as the new limit.
fn suggest(asked: f64) -> f64 {
    if !asked.is_finite() || asked <= 1.0 {
        return asked.max(1.0);
    }
    let scale = 10f64.powf(asked.log10().floor());
    (asked / scale).ceil() * scale
}

/// A count as a whole number while short, else in scientific notation.
fn count(x: f64) -> String {
    if x.is_finite() && x.abs() < 1e7 {
        format!("{}", x.ceil())
    } else {
        format!("{x:.3e}")
    }
}

/// Wheels over the raw vehicles (axle loads, one per oscillator, four per
/// truck or rail car, four per car of a train), counted before anything is resolved.
pub(crate) fn raw_wheels(vehicles: &[raw::VehicleRaw]) -> f64 {
    vehicles
        .iter()
        .map(|v| match v {
            raw::VehicleRaw::MovingForce(m) => m.loads.len().max(1) as f64,
            raw::VehicleRaw::Oscillator(_) => 1.0,
            raw::VehicleRaw::H20Truck(_) => 4.0,
            raw::VehicleRaw::RailCar(_) => 4.0,
            raw::VehicleRaw::Hslm(h) => h.model.train().axle_count() as f64,
            raw::VehicleRaw::AashtoH20(_) => 2.0,
            raw::VehicleRaw::AashtoHs20(_) => 3.0,
            raw::VehicleRaw::Train(t) => {
                let cars = t.cars.as_ref().map_or(0, Vec::len) as f64;
                4.0 * (t.count.map_or(0.0, |n| n as f64) + cars).max(1.0)
            }
            raw::VehicleRaw::Train3d(t) => {
                let cars = t.cars.as_ref().map_or(0, Vec::len) as f64;
                12.0 * (t.count.map_or(0.0, |n| n as f64) + cars).max(1.0)
            }
        })
        .sum()
}

/// Degrees of freedom of the bridge's eigenproblems, as the cost of
/// building and solving them: the beam's free DOFs (two per node less one
/// deflection per support) counted 1/50 each, since its modes come from
/// sparse shift-invert Lanczos (11,971 DOFs and 100 modes in 0.45 s, linear
/// in the DOFs; the mode count is budgeted on its own); for a plate the largest of the continuous
/// beam that gives its longitudinal functions, its Ritz basis counted 1.5
/// per term, and its transverse functions counted 2.5 each. The weights
/// make equal counts cost about the same time: measured on this project's
/// 2-core machine, a 2000-DOF beam checks in 5 s, a 2000-term plate Ritz
/// basis in 15 s (its matrices are integrated term by term) and 1000
/// transverse functions in 6 s (their integrals grow as the cube of the
/// count). In `f64`, so no element or term count can wrap.
pub fn bridge_dofs(bridge: &Bridge) -> f64 {
    /// Beam DOFs that cost what one dense unit costs.
    const SPARSE_BEAM_DOFS_PER_UNIT: f64 = 50.0;
    let beam = |spans: usize, elements: f64| {
        let spans = spans as f64;
        2.0 * (elements + 1.0) - (spans + 1.0)
    };
    match bridge {
        Bridge::Beam(b) => {
            let elements: f64 = b.elements_per_span.iter().map(|&n| n as f64).sum();
            beam(b.spans.len(), elements) / SPARSE_BEAM_DOFS_PER_UNIT
        }
        // The same sparse Lanczos path as a beam (its bandwidth is larger,
        // but so is its budget's weight in practice small next to the read).
        Bridge::FeImport(f) => f.model.dofs.len() as f64 / SPARSE_BEAM_DOFS_PER_UNIT,
        Bridge::Plate(p) => {
            let ritz = p.terms.longitudinal as f64 * p.terms.transverse as f64;
            (1.5 * ritz).max(2.5 * p.terms.transverse as f64).max(beam(
                p.spans.len(),
                p.spans.len() as f64 * p.elements_per_span as f64,
            ))
        }
    }
}

/// Bytes of the history files for `rows` written rows: a time column and
/// one column per record (two for a bridge displacement, which also gets its
/// static part); in CSV each value at most 24 characters (ryu's longest f64
/// and a separator), in NPY 8 bytes.
pub(crate) fn history_bytes(rows: f64, columns: f64, format: crate::scene::HistoryFormat) -> f64 {
    let per_value = if format.csv() { 24.0 } else { 0.0 } + if format.npy() { 8.0 } else { 0.0 };
    rows * (columns + 1.0) * per_value
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggestions_are_round_and_not_below_the_request() {
        assert_eq!(suggest(3.2e7), 4e7);
        assert_eq!(suggest(2001.0), 3000.0);
        assert_eq!(suggest(1e9), 1e9);
        assert!(suggest(123_456.0) >= 123_456.0);
    }

    #[test]
    fn counts_print_whole_or_scientific() {
        assert_eq!(count(2000.0), "2000");
        assert_eq!(count(3.2e7), "3.200e7");
        assert_eq!(count(f64::INFINITY), "inf");
    }
}
