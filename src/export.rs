//! `vbi export beam`: a `type: beam` bridge written as an imported FE
//! model (Matrix Market K and M, DOF map, rail CSV) and a scenario that
//! runs the same crossing on those files.
//!
//! The matrices are the beam's own Hermite elements on every node (DOFs uz
//! and ry per node, x along the beam, z up); the supports' uz DOFs are
//! listed under `constrained` rather than removed, so the model's vertical
//! mass is the beam's m L. The slope θ = dw/dx of the beam element is
//! written as ry = −θ (right-handed rotation about +y, [`crate::bridge::fe_import::track`]).

use std::path::Path;

use thiserror::Error;

use crate::bridge::BridgeError;
use crate::bridge::beam::BeamModel;
use crate::scenario::fe_import::matrix_market;
use crate::scene::{Bridge, Damping, Scenario};

/// Why an export failed.
#[derive(Debug, Error)]
pub enum ExportError {
    /// The scenario's bridge is not a beam.
    #[error("only a `type: beam` bridge can be exported, this scenario's is not")]
    NotABeam,
    /// The beam could not be assembled.
    #[error(transparent)]
    Bridge(#[from] BridgeError),
    /// Writing failed.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: String,
        /// The cause.
        source: std::io::Error,
    },
}

/// The exported files: (file name, contents).
pub fn beam_files(scenario: &Scenario) -> Result<Vec<(String, String)>, ExportError> {
    let Bridge::Beam(beam) = &scenario.bridge else {
        return Err(ExportError::NotABeam);
    };
    let model = BeamModel::new(beam)?;
    let (node_x, k, m) = model.full_matrices();
    let order = 2 * node_x.len();
    // ry = −θ: flip the sign of every entry with exactly one rotation index.
    let sign = |r: usize, c: usize| if (r + c) % 2 == 1 { -1.0 } else { 1.0 };
    let flip = |t: Vec<(usize, usize, f64)>| -> Vec<(usize, usize, f64)> {
        t.into_iter()
            .map(|(r, c, v)| (r, c, sign(r, c) * v))
            .collect()
    };
    let (k, m) = (flip(k), flip(m));
    let counts = &beam.elements_per_span;
    let elements = if counts.iter().all(|&n| n == counts[0]) {
        counts[0].to_string()
    } else {
        let each: Vec<String> = counts.iter().map(|n| n.to_string()).collect();
        format!("[{}]", each.join(", "))
    };
    let note = format!(
        "vbi export beam: {}; EI = {} N m^2, m = {} kg/m, {elements} elements per span; DOFs in dofs.csv",
        scenario.name, beam.bending_stiffness, beam.mass_per_length
    );
    let mut dofs = String::from("dof,node,direction\n");
    let mut rail = String::from("node,x\n");
    let mut buffer = ryu::Buffer::new();
    for (i, &x) in node_x.iter().enumerate() {
        dofs.push_str(&format!(
            "{},{},uz\n{},{},ry\n",
            2 * i + 1,
            i + 1,
            2 * i + 2,
            i + 1
        ));
        rail.push_str(&format!("{},{}\n", i + 1, buffer.format(x)));
    }
    let constrained: Vec<serde_json::Value> = (0..node_x.len())
        .filter(|&n| model.free_index[2 * n].is_none())
        .map(|n| serde_json::json!({"node": n + 1, "direction": "uz"}))
        .collect();
    let damping = match beam.damping {
        Damping::Modal { ratio } => serde_json::json!({"type": "modal", "ratio": ratio}),
        Damping::Rayleigh { frequencies, ratio } => {
            serde_json::json!({"type": "rayleigh", "frequencies": frequencies, "ratio": ratio})
        }
    };
    let mut value = serde_json::to_value(scenario).expect("scenario serialises");
    value["name"] = serde_json::Value::String(format!("{}-imported", scenario.name));
    value["bridge"] = serde_json::json!({
        "type": "fe_import",
        "stiffness": "K.mtx",
        "mass": "M.mtx",
        "dof_map": "dofs.csv",
        "constrained": constrained,
        "damping": damping,
        "rails": [{"name": "rail", "file": "rail.csv"}],
        "modes": serde_json::to_value(&beam.modes).expect("modes serialise"),
    });
    let yaml = format!(
        "# Exported by vbi {} from `{}`: the same crossing on the beam's exported matrices.\n{}{}",
        env!("CARGO_PKG_VERSION"),
        scenario.name,
        crate::report::folder::read_pins(scenario),
        crate::report::yaml::to_yaml(&value)
    );
    Ok(vec![
        (
            "K.mtx".into(),
            matrix_market::write_symmetric(order, &k, &note),
        ),
        (
            "M.mtx".into(),
            matrix_market::write_symmetric(order, &m, &note),
        ),
        ("dofs.csv".into(), dofs),
        ("rail.csv".into(), rail),
        ("scenario.yaml".into(), yaml),
    ])
}

/// Writes [`beam_files`] into `out` (created if needed): each file to a
/// temporary name first, renamed once all are written, so a failure leaves
/// none of them behind.
pub fn export_beam(scenario: &Scenario, out: &Path) -> Result<(), ExportError> {
    let files = beam_files(scenario)?;
    let fail = |path: &Path, source| ExportError::Write {
        path: path.display().to_string(),
        source,
    };
    std::fs::create_dir_all(out).map_err(|e| fail(out, e))?;
    let mut written = Vec::new();
    for (name, text) in &files {
        let temporary = out.join(format!(".{name}.partial"));
        if let Err(e) = std::fs::write(&temporary, text) {
            for t in &written {
                let _ = std::fs::remove_file(t);
            }
            let _ = std::fs::remove_file(&temporary);
            return Err(fail(&temporary, e));
        }
        written.push(temporary);
    }
    for ((name, _), temporary) in files.iter().zip(&written) {
        let target = out.join(name);
        std::fs::rename(temporary, &target).map_err(|e| fail(&target, e))?;
    }
    Ok(())
}
