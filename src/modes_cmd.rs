//! `vbi modes`: the bridge's modes as a table or JSON, its mode shapes, and
//! each vehicle's own natural frequencies.

use std::path::Path;
use std::process::ExitCode;

use super::run_cmd::load_error;
use super::{EXIT_FAILED, emit};
use vbi::plan;
use vbi::scenario;

pub(super) fn modes(
    file: &Path,
    options: scenario::LoadOptions,
    shapes: Option<&Path>,
    json: bool,
) -> ExitCode {
    let _total = vbi::timings::stage(|| "vbi modes".into());
    let loaded = {
        let _t = vbi::timings::stage(|| "load and plan".into());
        plan::load_file_for_modes(file, options)
    };
    let vbi::plan::bridge_only::ModesScene {
        name,
        bridge,
        scenario,
        imported,
    } = match loaded {
        Ok(scene) => scene,
        Err(e) => return load_error(&e),
    };
    let _output = vbi::timings::stage(|| "output".into());
    let plate = bridge.width().is_some();
    // An imported mode's direction by its kinetic energy (`vertical 2 (99.7 %)`).
    let named = plate || bridge.is_imported();
    if json {
        outln!(
            "{}",
            modes_json(&name, &bridge, scenario.as_ref(), imported.as_ref())
        );
        return ExitCode::SUCCESS;
    }
    out!(
        "{}: {} modes used of {} available ({})\n{:>5} {:>14} {:>14} {:>12}{}\n",
        name,
        bridge.mode_count(),
        bridge.available_modes,
        bridge.selection,
        "mode",
        "frequency_Hz",
        "period_s",
        "damping",
        // A plate mode's (m, n): its dominant longitudinal and transverse
        // terms; an imported mode's direction and its share of the energy.
        if plate {
            "  (m, n)"
        } else if named {
            "  direction (kinetic energy share)"
        } else {
            ""
        }
    );
    for (i, (f, z)) in bridge
        .frequencies()
        .iter()
        .zip(&bridge.damping_ratios)
        .enumerate()
    {
        let character = if named {
            format!("  {}", bridge.mode_character(i))
        } else {
            String::new()
        };
        outln!(
            "{:>5} {:>14.6} {:>14.6} {:>12.4}{character}",
            i + 1,
            f,
            1.0 / f,
            z
        );
    }
    // What the plan left out of them (issue 40.6), so that the table still
    // shows every mode below the last kept one.
    if !bridge.left_out.is_empty() {
        outln!("left out (nothing in the scene moves them):");
        for mode in &bridge.left_out {
            outln!(
                "{:>5} {:>14.6} {:>14.6} {:>12}  {}",
                "-",
                mode.frequency,
                1.0 / mode.frequency,
                "",
                mode.direction
            );
        }
    }
    if let Some(scenario) = &scenario {
        print_vehicle_frequencies(scenario);
    }
    if let Some(totals) = &imported {
        print_imported_totals(totals);
        let advice = vbi::plan::advice::imported_model_advice(totals);
        super::print_advice_located(file, &advice);
    }
    if let Some(path) = shapes {
        let text = vbi::report::mode_shapes_csv(&bridge);
        if path == Path::new("-") {
            out!("{text}");
        } else {
            if let Err(e) = vbi::report::write_atomic(path, text.as_bytes()) {
                errln!("error: {e}");
                return ExitCode::from(EXIT_FAILED);
            }
            errln!("mode shapes written to {}", path.display());
        }
    }
    ExitCode::SUCCESS
}

/// The modes of `bridge` as JSON: every frequency at full precision
/// (shortest round-trip decimal), damping, character, and the checks the
/// modes passed ([`vbi::bridge::eigen::ModeCheck`]); and, when the scene
/// has vehicles, each vehicle's natural frequencies with its wheels on
/// rigid ground at full precision (the text output prints them to four
/// decimals).
pub(super) fn modes_json(
    name: &str,
    bridge: &vbi::bridge::ModalBridge,
    scenario: Option<&vbi::scenario::resolved::Scenario>,
    imported: Option<&vbi::scene::imported::ImportedTotals>,
) -> String {
    let check = bridge.check;
    let two_pi = 2.0 * std::f64::consts::PI;
    let modes: Vec<serde_json::Value> = bridge
        .frequencies()
        .iter()
        .zip(&bridge.circular_frequencies)
        .zip(&bridge.damping_ratios)
        .enumerate()
        .map(|(i, ((f, w), z))| {
            serde_json::json!({
                "mode": i + 1,
                "frequency_hz": f,
                "circular_frequency_rad_s": w,
                "period_s": 1.0 / f,
                "damping_ratio": z,
                "character": bridge.mode_character(i),
            })
        })
        .collect();
    let value = serde_json::json!({
        "scenario": name,
        "modes_used": bridge.mode_count(),
        "modes_available": bridge.available_modes,
        "selection": bridge.selection,
        "left_out": bridge.left_out,
        "check": {
            "solver": if check.dense { "dense inverted reduction" } else { "shift-invert Lanczos" },
            "largest_energy_residual": check.largest_residual,
            "largest_plain_residual": check.largest_plain_residual,
            "residual_bound": vbi::bridge::eigen::RESIDUAL_BOUND,
            "orthonormality_error": check.orthonormality_error,
            "orthonormality_bound": vbi::bridge::eigen::ORTHONORMALITY_BOUND,
            "sturm_count": check.inertia.map(|(shift, count)| serde_json::json!({
                "below_hz": shift.sqrt() / two_pi,
                "modes": count,
            })),
        },
        "modes": modes,
        "vehicles": scenario.map_or_else(Vec::new, vehicle_frequencies_json),
    });
    let mut value = value;
    if let Some(totals) = imported {
        value["imported_model"] = serde_json::to_value(totals).expect("numbers");
    }
    serde_json::to_string_pretty(&value).expect("JSON of numbers and strings")
}

/// Each vehicle's natural frequencies (Hz, wheels on rigid ground, massless
/// DOFs condensed out) as JSON objects `{vehicle, type, frequencies_hz}`,
/// every frequency in its shortest round-trip form.
pub(super) fn vehicle_frequencies_json(
    scenario: &vbi::scenario::resolved::Scenario,
) -> Vec<serde_json::Value> {
    use vbi::plan::content::vehicle_frequencies;
    use vbi::vehicle::VehicleModel;
    scenario
        .vehicles
        .iter()
        .enumerate()
        .map(|(i, vehicle)| {
            let model = VehicleModel::build(vehicle, scenario.gravity);
            serde_json::json!({
                "vehicle": i + 1,
                "type": vehicle.type_name(),
                "frequencies_hz": vehicle_frequencies(&model, None),
            })
        })
        .collect()
}

/// An imported model's mass and static deflection, what an engineer
/// checks before its modes.
fn print_imported_totals(totals: &vbi::scene::imported::ImportedTotals) {
    let m = totals.mass;
    outln!(
        "imported model: mass {:.6e} kg vertically (x {:.6e} kg, y {:.6e} kg), {:.6e} kg/m \
         over the {:.6} m track",
        m.z,
        m.x,
        m.y,
        totals.mass_per_length,
        totals.length
    );
    match (
        totals.static_deflection,
        totals.static_load,
        totals.static_load_x,
    ) {
        (Some(w), Some(load), Some(x)) => outln!(
            "imported model: static deflection {w:.6e} m (1/{:.0} of the track) under the \
             vehicles' total weight, {load:.6e} N, at x = {x:.6} m (the track's most flexible \
             point)",
            totals.length / w
        ),
        _ => outln!("imported model: static deflection not measured (no vehicles)"),
    }
}

/// Each vehicle's own natural frequencies with its wheels held on rigid
/// ground (massless DOFs condensed out), to set against the bridge's.
pub(super) fn print_vehicle_frequencies(scenario: &vbi::scene::Scenario) {
    use vbi::plan::content::vehicle_frequencies;
    use vbi::vehicle::VehicleModel;
    let hz = |f: &[f64]| {
        if f.is_empty() {
            "none (no mass on springs)".to_string()
        } else {
            f.iter()
                .map(|f| format!("{f:.4}"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    outln!("vehicle natural frequencies, Hz (wheels on rigid ground):");
    for (i, vehicle) in scenario.vehicles.iter().enumerate() {
        let model = VehicleModel::build(vehicle, scenario.gravity);
        outln!(
            "{:>5} {:<14} {}",
            i + 1,
            vehicle.type_name(),
            hz(&vehicle_frequencies(&model, None))
        );
    }
}
