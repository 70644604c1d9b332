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
    let folder = match file.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let schema_path = folder.join(SCHEMA_FILE);
    let schema = vbi::schema::schema_json();
    let shown = vbi::guarded_file::shown;
    if file.file_name().is_some_and(|n| n == SCHEMA_FILE) {
        errln!(
            "error: {}: the scene cannot be named {SCHEMA_FILE}, the name of the schema `vbi \
             init` writes beside it\n  = help: name the scene `.yaml`, e.g. `vbi init scene.yaml`",
            shown(file)
        );
        return ExitCode::from(EXIT_INVALID);
    }
    // Every target is checked before anything is written (issue 39.4): a
    // refusal leaves the folder as it was. The schema beside the scene is
    // left alone when it is this vbi's already (a second scene in the same
    // folder), and otherwise replaced only with --force, as the scene is.
    let schema_current =
        vbi::guarded_file::read_text_bounded(&schema_path, 1 << 24).is_ok_and(|t| t == schema);
    let refused = vbi::guarded_file::writable(file, force).err().or_else(|| {
        (!schema_current)
            .then(|| vbi::guarded_file::writable(&schema_path, force).err())
            .flatten()
    });
    if let Some(e) = refused {
        let help = match e {
            vbi::guarded_file::GuardError::Exists { .. } => {
                "choose another file name or folder, or add --force to replace it"
            }
            _ => "choose another file name or folder",
        };
        errln!("error: {e}\n  = help: {help}");
        return ExitCode::from(EXIT_INVALID);
    }
    let write = |path: &Path, bytes: &[u8]| -> Result<(), String> {
        if force {
            vbi::report::atomic::write_atomic(path, bytes)
                .map_err(|e| format!("{}: {e}", shown(path)))
        } else {
            // Created exclusively: a file or link made since the check is
            // not replaced.
            vbi::guarded_file::create_new(path, bytes).map_err(|e| e.to_string())
        }
    };
    let written = std::fs::create_dir_all(&folder)
        .map_err(|e| format!("{}: {e}", shown(&folder)))
        .and_then(|()| write(file, text.as_bytes()))
        .and_then(|()| {
            if schema_current {
                Ok(())
            } else {
                write(&schema_path, schema.as_bytes()).inspect_err(|_| {
                    // Nothing partial: the scene goes with the schema.
                    let _ = std::fs::remove_file(file);
                })
            }
        });
    match written {
        Ok(()) => {
            errln!(
                "wrote {} (and {} for the editor); next: vbi check {0}, then vbi run {0}",
                shown(file),
                shown(&schema_path)
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            errln!("error: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}
