//! The HSLM resonance check as an EN 1991-2 verdict, through the binary:
//! the speed grid reaches the maximum check speed 1.2 × the line speed
//! (EN 1991-2 6.4.6.2) and holds every resonance speed f₀·D/k.

mod support;

use std::path::Path;
use std::process::{Command, Output};

use support::Scratch;

fn vbi(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run vbi")
}

/// The km/h column of resonance.csv, as printed, for `train`.
fn km_h_column(csv: &str, train: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let at = header
        .iter()
        .position(|h| *h == "speed_km_h")
        .expect("speed_km_h column");
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|row| row[0] == train)
        .map(|row| row[at].to_owned())
        .collect()
}

const BRIDGE: &str = "bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 2.43e10
  mass_per_length: 15000.0
  modes: {max_frequency: 40.0}
  damping: {type: modal, ratio: 0.01}
";

/// A 20 km/h step from the default 40 m/s (144 km/h) lands on 344 km/h,
/// not on the maximum check speed 1.2 × 300 = 360 km/h: the grid must
/// still end there (EN 1991-2 6.4.6.2(1)).
#[test]
fn the_grid_reaches_1_2_times_the_line_speed() {
    let scratch = Scratch::new("resonance_verdict", "grid_top");
    let scene = format!(
        "name: top\n{BRIDGE}vehicles: [{{type: hslm, model: A3, speed: 300 km/h}}]
study:
  type: resonance_check
  trains: [A3]
  line_speed: 300 km/h
  speeds: {{step: 20 km/h}}
"
    );
    std::fs::write(scratch.path("top.yaml"), scene).unwrap();
    let out = vbi(&["run", "top.yaml", "--out", "out", "--quiet"], scratch.dir());
    let csv = std::fs::read_to_string(scratch.path("out/resonance.csv"))
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let speeds = km_h_column(&csv, "HSLM-A3");
    assert_eq!(speeds.first().map(String::as_str), Some("144"), "{speeds:?}");
    assert_eq!(speeds.last().map(String::as_str), Some("360"), "{speeds:?}");
}
