//! Advice about a planned scene, before it runs: valid, but probably not
//! what was meant ([`crate::advice`]). The run carries it into its results
//! with the run's own advice ([`crate::report::advice`]).

use crate::advice::{self, Advice};
use crate::scenario::raw::{KM_H, km_h_to_m_s};
use crate::scene::imported::ImportedTotals;
use crate::scene::{Scenario, Study, Surface};
use crate::surface::fade_start;
use crate::surface::spectrum::{FRA_MAX_SPEED_MPH, fra_max_speed};

/// Speeds above this, m/s (468 km/h), are faster than any wheeled vehicle in
/// service: the fastest trains run at 350 km/h and an EN 1991-2 resonance
/// check goes to 1.2 × the line speed (420 km/h for 350 km/h). Such a speed
/// written as a bare number is most often a km/h value typed where m/s is
/// meant; written with its unit it is meant (a moving force at a stiff
/// beam's critical speed 2 f₁ L can be far faster than any train).
pub const IMPLAUSIBLE_SPEED: f64 = 130.0;

/// Largest plausible |acceleration| along the path, m/s²: a road vehicle's
/// emergency braking on dry asphalt reaches about 1 g; trains brake at
/// 1–1.5 m/s² (service) to about 2.5 m/s² (emergency with track brakes).
pub const IMPLAUSIBLE_ACCELERATION: f64 = 10.0;

/// Advice about the scene itself, before it runs, the scene's `allow`
/// applied.
pub fn scene_advice(scenario: &Scenario) -> Vec<Advice> {
    let mut out = Vec::new();
    for (i, vehicle) in scenario.vehicles.iter().enumerate() {
        // A speed written with its unit (`238.9 m/s`) is meant: a moving
        // force at a beam's critical speed 2 f₁ L is often far faster
        // than any train. Only a bare number can be a km/h value typed as
        // m/s.
        let stated = scenario.speeds_stated.get(i).copied().unwrap_or(false);
        let v = vehicle.speed();
        if let Some(a) = implausible(&format!("vehicle {}", i + 1), v)
            && !stated
        {
            let help = a.help.clone().unwrap_or_default();
            out.push(a.at(format!("vehicles[{i}].speed")).help(format!(
                "{help}; if {v} m/s is meant, write `speed: {v} m/s`"
            )));
        }
        let a = vehicle.acceleration();
        if a.abs() > IMPLAUSIBLE_ACCELERATION {
            out.push(
                Advice::new(
                    &advice::IMPLAUSIBLE_ACCELERATION,
                    format!(
                        "vehicle {}: an acceleration of {a} m/s² is more than a vehicle on wheels \
                         reaches ({IMPLAUSIBLE_ACCELERATION} m/s², about 1 g of braking)",
                        i + 1
                    ),
                )
                .at(format!("vehicles[{i}].acceleration"))
                .help("accelerations are in m/s²")
                .figure("acceleration_m_s2", a),
            );
        }
    }
    if let Some(Study::SpeedSweep(sweep)) = &scenario.study
        && let Some(a) = implausible("the speed sweep's top speed", sweep.speeds.to)
    {
        out.push(a.at("study.speeds.to"));
    }
    out.extend(track_class_too_slow(scenario));
    out.extend(fade_on_the_bridge(scenario));
    out.extend(measured_finer_than_a_step(scenario));
    if let crate::scene::Bridge::FeImport(fe) = &scenario.bridge
        && let Some(totals) = &fe.totals
    {
        out.extend(imported_model_advice(totals));
    }
    advice::apply_allow(&mut out, &scenario.allow);
    out
}

/// Lightest plausible vertical mass per metre of a bridge's track, kg/m: a
/// light steel footbridge carries some 500 kg/m, a railway deck 10–30 t/m;
/// a model in kN and t reads 1000 times below its own, one in N, mm and t
/// 10⁶ times.
pub const IMPORT_MASS_PER_LENGTH_MIN: f64 = 100.0;

/// Largest plausible static deflection under the vehicles' total weight,
/// as a share of the track's length: bridges deflect some span/500 to
/// span/2000 under their traffic (EN 1990 A2.4.4.3 limits a railway
/// deck's to span/600 and less); a stiffness in kN/m read as N/m makes it
/// 1000 times that.
pub const IMPORT_DEFLECTION_SHARE_MAX: f64 = 0.01;

/// An imported model whose mass or static deflection no bridge has: the
/// files are probably in kN and t, or in mm ([`crate::plan::imported_check`]).
pub fn imported_model_advice(totals: &ImportedTotals) -> Vec<Advice> {
    let mut out = Vec::new();
    let per_metre = totals.mass_per_length;
    if per_metre < IMPORT_MASS_PER_LENGTH_MIN {
        // 10⁻³: kN and t; 10⁻⁶: N, mm and t (mass 10⁻³, length 10³).
        let guess = if per_metre < 1e-1 {
            "as a model in N, mm and t reads (its mass 1000 times small, its track 1000 times \
             long)"
        } else {
            "as a model in kN and t reads (its mass 1000 times small)"
        };
        out.push(
            Advice::new(
                &advice::IMPORT_MASS_PER_LENGTH_LOW,
                format!(
                    "the imported model's vertical mass is {:.4} kg over its {:.4} m track, \
                     {per_metre:.4} kg/m: lighter than any bridge deck (a footbridge's is some \
                     500 kg/m, a railway deck's 10–30 t/m), {guess}",
                    totals.mass.z, totals.length
                ),
            )
            .at("bridge.mass")
            .help(
                "export the model in N, kg and m (from kN and t: multiply K and M by 1000); if \
                 the mass is meant, allow `import-mass-per-length-low` with the reason",
            )
            .figure("mass_per_length_kg_m", per_metre)
            .figure("vertical_mass_kg", totals.mass.z)
            .figure("length_m", totals.length),
        );
    }
    if let (Some(w), Some(load), Some(x)) = (
        totals.static_deflection,
        totals.static_load,
        totals.static_load_x,
    ) && w > IMPORT_DEFLECTION_SHARE_MAX * totals.length
    {
        out.push(
            Advice::new(
                &advice::IMPORT_STATIC_DEFLECTION_LARGE,
                format!(
                    "the imported model deflects {w:.4} m under the vehicles' total weight \
                     ({:.4} kN at x = {x:.4} m, the track's most flexible point), 1/{:.0} of \
                     its {:.4} m track: no bridge deflects so under its traffic (span/500 to \
                     span/2000); a stiffness in kN/m read as N/m deflects 1000 times too much",
                    load / 1e3,
                    totals.length / w,
                    totals.length
                ),
            )
            .at("bridge.stiffness")
            .help(
                "export K in N/m (N·m/rad) and M in kg (from kN and t: multiply both by 1000); \
                 if the deflection is meant, allow `import-static-deflection-large` with the \
                 reason",
            )
            .figure("static_deflection_m", w)
            .figure("static_load_n", load)
            .figure("length_m", totals.length),
        );
    }
    out
}

/// A measured profile whose points are closer than a wheel's travel in one
/// time step: the wheels see the spline only at the steps, so its features
/// between them are missed (aliased). Not refused: dense profilometer data
/// are common and the spline between the points stays right.
fn measured_finer_than_a_step(scenario: &Scenario) -> Option<Advice> {
    let Surface::Measured { file, profile } = &scenario.surface else {
        return None;
    };
    let speed = scenario
        .vehicles
        .iter()
        .map(|v| v.speed())
        .fold(0.0, f64::max);
    let travel = speed * scenario.solver.time_step;
    let (i, spacing) = profile
        .x
        .windows(2)
        .map(|w| w[1] - w[0])
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(&b.1))?;
    (spacing < travel).then(|| {
        Advice::new(
            &advice::MEASURED_PROFILE_FINER_THAN_STEP,
            format!(
                "{}: the points at x = {} m and {} m are {spacing:e} m apart, less than the \
                 {travel:.4e} m a wheel travels in one time step ({speed:.4} m/s × {:e} s): the \
                 wheels see the profile only at the steps and miss its features between them",
                crate::scenario::diagnostic::escaped(file),
                profile.x[i],
                profile.x[i + 1],
                scenario.solver.time_step,
            ),
        )
        .at("surface.file")
        .help(format!(
            "set `solver.time_step` to at most {:.4e} s to follow every point",
            spacing / speed
        ))
        .figure("spacing_m", spacing)
        .figure("travel_per_step_m", travel)
    })
}

/// FRA track classes run faster than the speed they are maintained for
/// (49 CFR 213.9(a), 213.307(a)): the spectrum is that of a slower,
/// rougher line than such a train would run on.
fn track_class_too_slow(scenario: &Scenario) -> Vec<Advice> {
    let (entries, study_top) = match &scenario.study {
        Some(Study::MonteCarlo(mc)) => (
            mc.roughness.as_deref(),
            mc.speed_range().map_or(0.0, |r| r.1),
        ),
        Some(Study::SpeedSweep(sweep)) => (sweep.roughness.as_deref(), sweep.speed_range().1),
        _ => (None, 0.0),
    };
    let top = scenario
        .vehicles
        .iter()
        .map(|v| v.speed())
        .fold(study_top, f64::max);
    let mut classes: Vec<u8> = match &scenario.surface {
        Surface::Fra { class, .. } => vec![*class],
        _ => Vec::new(),
    };
    classes.extend(entries.into_iter().flatten().filter_map(|e| e.fra_class()));
    classes.sort_unstable();
    classes.dedup();
    classes
        .into_iter()
        .filter(|&class| top > fra_max_speed(class))
        .map(|class| {
            let (freight, passenger) = FRA_MAX_SPEED_MPH[usize::from(class.clamp(1, 6)) - 1];
            let rule = if class >= 6 { "213.307(a)" } else { "213.9(a)" };
            Advice::new(
                &advice::FRA_CLASS_TOO_SLOW,
                format!(
                    "FRA track class {class} is maintained for at most {freight} mph freight and \
                     {passenger} mph passenger trains ({:.0} km/h; 49 CFR {rule}), but a vehicle \
                     runs at {:.0} km/h: its irregularities are those of a line kept for far \
                     lower speeds (FRA class 6 allows 110 mph; the German low- and \
                     high-interference spectra, `type: german`, are for high-speed lines)",
                    fra_max_speed(class) / KM_H,
                    top / KM_H
                ),
            )
            .at("surface")
            .figure("class", f64::from(class))
            .figure("class_max_speed_m_s", fra_max_speed(class))
            .figure("speed_m_s", top)
        })
        .collect()
}

/// A vehicle placed after the start of a spectrum's run-in: the fade then
/// starts under its front axle and reaches onto the bridge.
fn fade_on_the_bridge(scenario: &Scenario) -> Option<Advice> {
    let (_, sampling) = scenario.surface.spectrum()?;
    let front = scenario
        .vehicles
        .iter()
        .map(|v| v.motion().position(0.0))
        .fold(f64::NEG_INFINITY, f64::max);
    let start = fade_start(sampling.run_in, front);
    let end = start + sampling.run_in;
    (sampling.run_in > 0.0 && end > 0.0).then(|| {
        Advice::new(
            &advice::RUN_IN_ON_BRIDGE,
            format!(
                "a vehicle starts at x = {front:.4} m, inside the surface's {} m run-in: the \
                 profile fades in from under its front axle to x = {end:.4} m, so the bridge's \
                 first {end:.4} m are below full roughness",
                sampling.run_in
            ),
        )
        .at("surface.run_in")
        .help(format!(
            "start every vehicle at or before x = {} m (leave `start_position` and \
             `entry_time` out to have it placed there)",
            -sampling.run_in
        ))
        .figure("front_axle_m", front)
        .figure("full_roughness_from_m", end)
    })
}

fn implausible(what: &str, speed: f64) -> Option<Advice> {
    (speed > IMPLAUSIBLE_SPEED).then(|| {
        Advice::new(
            &advice::IMPLAUSIBLE_SPEED,
            format!(
                "{what}: {speed} m/s is {:.0} km/h, faster than any wheeled vehicle in service",
                speed / KM_H,
            ),
        )
        .help(format!(
            "speeds are in m/s — for {speed} km/h write `speed: {speed} km/h` ({:.4} m/s)",
            km_h_to_m_s(speed)
        ))
        .figure("speed_m_s", speed)
    })
}
