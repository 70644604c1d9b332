//! The excitations a study's runs bring, for the automatic choices that
//! must serve every run.

use super::content::{self, Excitation};
use crate::scenario::sweep::{surface, with_speed};
use crate::scene::{Bridge, Contact, Surface, SweepRoughness, Vehicle};

/// Excitations over the whole study: every vehicle at the top speed (`None`:
/// the scene's own speeds) on each swept surface (`None` entry: the scene's
/// own), so that the automatic mode cut-off and time step serve every run.
pub(crate) fn excitations(
    top: Option<f64>,
    entries: &[Option<SweepRoughness>],
    vehicles: &[Vehicle],
    contact: &Contact,
    base: &Surface,
    bridge: &Bridge,
    gravity: f64,
) -> Vec<Excitation> {
    let fast = match top {
        Some(top) => with_speed(vehicles, top),
        None => vehicles.to_vec(),
    };
    let mut out = Vec::new();
    for &entry in entries {
        let surface = surface(base, entry, 0, bridge.length());
        for mut e in content::excitations(&fast, contact, &surface, bridge.spans(), gravity) {
            if let Some(top) = top
                && e.source.contains("(v /")
            {
                e.source = format!("{} at the study's top speed, {top} m/s", e.source);
            }
            if !out.contains(&e) {
                out.push(e);
            }
        }
    }
    out
}
