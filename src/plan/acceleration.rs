//! The deck-acceleration filter: which modes a bridge acceleration sums.
//!
//! EN 1990 A2.4.4.2.1(4) (and EN 1991-2 6.4.6.5(3)) takes the deck
//! acceleration up to "the greater of 30 Hz, 1.5 times the frequency of
//! the fundamental mode of the member being considered, and the frequency
//! of the third mode of vibration of the member". The f₁ and f₃ are the
//! bridge's own, not those of the modes a scene keeps: a `bridge.modes`
//! cap that keeps one mode must not lower the filter to the kept top (it
//! did, silently: the shipped railway example's HSLM-A1 peak came out 11 %
//! low at a 30 Hz filter on a span whose f₃ is 68.8 Hz).

use crate::bridge::{BridgeError, ModalBridge, ModeRequest};
use crate::scene::Bridge;

pub use crate::scene::automatic::{FLOOR_HZ, FUNDAMENTAL_FACTOR};

/// The default highest mode frequency of a bridge acceleration, Hz: the
/// greater of 30 Hz, 1.5 f₁ and f₃ (EN 1990 A2.4.4.2.1(4)), from the
/// bridge's lowest frequencies `lowest` (Hz, ascending; the highest one
/// stands in for f₃ when the bridge has fewer than three modes at all).
pub fn default_filter(lowest: &[f64]) -> f64 {
    let first = lowest.first().copied().unwrap_or(0.0);
    let third = lowest.get(2).or(lowest.last()).copied().unwrap_or(0.0);
    FLOOR_HZ.max(FUNDAMENTAL_FACTOR * first).max(third)
}

/// The bridge's own lowest three natural frequencies, Hz (fewer when its
/// model has fewer modes), whatever `modal` keeps: the kept modes' when
/// they are three or more (they are the lowest), else one extra eigen
/// solve of the lowest three (an imported model's through the modes cache
/// in `cache`).
pub fn lowest_three(
    bridge: &Bridge,
    modal: &ModalBridge,
    cache: Option<&std::path::Path>,
    par: faer::Par,
) -> Result<Vec<f64>, BridgeError> {
    let wanted = 3.min(ModalBridge::available_of(bridge));
    let kept = modal.frequencies();
    if kept.len() >= wanted {
        return Ok(kept[..wanted].to_vec());
    }
    Ok(ModalBridge::build_cached(bridge, ModeRequest::Lowest(wanted), cache, par)?.frequencies())
}

/// How many modes the bridge has up to `cut` (Hz): a Sturm count where
/// that is cheap (beam, imported model), else the plate's Ritz problem
/// solved (it is solved whole for any count anyway).
pub fn modes_up_to(
    bridge: &Bridge,
    cut: f64,
    cache: Option<&std::path::Path>,
    par: faer::Par,
) -> Result<usize, BridgeError> {
    match ModalBridge::count_up_to(bridge, cut)? {
        Some(count) => Ok(count),
        None => {
            Ok(ModalBridge::build_cached(bridge, ModeRequest::UpTo(cut), cache, par)?.mode_count())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// EN 1990 A2.4.4.2.1(4): the greater of the three; 30 Hz on a soft
    /// bridge, 1.5 f₁ only where f₃ < 1.5 f₁ (never on a simply supported
    /// beam, f₃ = 9 f₁).
    #[test]
    fn the_filter_is_the_greatest_of_30_hz_one_and_a_half_f1_and_f3() {
        assert_eq!(default_filter(&[2.0, 8.0, 18.0]), 30.0);
        assert_eq!(default_filter(&[7.65, 30.6, 68.85]), 68.85);
        // Closely spaced modes (a plate's transverse family): 1.5 f₁ wins.
        assert_eq!(default_filter(&[40.0, 45.0, 50.0]), 60.0);
        // Fewer than three modes in the whole model: the top one stands in.
        assert_eq!(default_filter(&[40.0, 70.0]), 70.0);
        assert_eq!(default_filter(&[]), 30.0);
    }
}
