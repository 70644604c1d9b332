//! `vbi init`: writes a starter scene and the schema beside it.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::{EXIT_FAILED, EXIT_INVALID, emit};

/// `vbi init`: the starter scene, and `vbi.schema.json` beside it so the
/// modeline (a path relative to the scene) works wherever the folder is.
pub(super) fn init(
    bridge: vbi::init::StarterBridge,
    vehicle: vbi::init::StarterVehicle,
    file: &Path,
    force: bool,
) -> ExitCode {
    const SCHEMA_FILE: &str = "vbi.schema.json";
    let text = match vbi::init::starter(bridge, vehicle, SCHEMA_FILE) {
        Ok(text) => text,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(EXIT_INVALID);
        }
    };
    if file.exists() && !force {
        errln!(
            "error: {} exists: choose another file name or add --force to replace it",
            file.display()
        );
        return ExitCode::from(EXIT_INVALID);
    }
    let folder = match file.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let schema_path = folder.join(SCHEMA_FILE);
    let written = std::fs::create_dir_all(&folder)
        .and_then(|()| vbi::report::atomic::write_atomic(file, text.as_bytes()))
        .and_then(|()| {
            vbi::report::atomic::write_atomic(&schema_path, vbi::schema::schema_json().as_bytes())
        });
    match written {
        Ok(()) => {
            errln!(
                "wrote {} (and {} for the editor); next: vbi check {0}, then vbi run {0}",
                file.display(),
                schema_path.display()
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            errln!("error: {}: {e}", file.display());
            ExitCode::from(EXIT_FAILED)
        }
    }
}
