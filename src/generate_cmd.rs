//! `vbi generate viaduct`: writes a generated model's files.

use std::process::ExitCode;

use super::cli::Generate;
use super::{EXIT_FAILED, EXIT_INVALID, emit};

pub(super) fn generate(what: Generate) -> ExitCode {
    let Generate::Viaduct {
        spans,
        span_length,
        pier_height,
        approach_length,
        sleeper_spacing,
        rail_divisions,
        pier_elements,
        out,
    } = what;
    let params = vbi::generate::viaduct::ViaductParams {
        spans,
        span_length,
        pier_height,
        approach_length,
        sleeper_spacing,
        rail_divisions,
        pier_elements,
        ..Default::default()
    };
    match vbi::generate::write_viaduct(&params, &out) {
        Ok(reduced) => {
            outln!(
                "wrote {} ({} DOFs, {} + {} stored entries in K and M)",
                out.display(),
                reduced.order,
                reduced.stiffness.len(),
                reduced.mass.len()
            );
            ExitCode::SUCCESS
        }
        Err(e @ vbi::generate::WriteError::Params(_)) => {
            errln!("error: {e}");
            ExitCode::from(EXIT_INVALID)
        }
        Err(e) => {
            errln!("error: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}
