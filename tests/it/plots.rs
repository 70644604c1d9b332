//! Plots that finish the story (issue 28, point 7), through the binary: a
//! run with `envelopes:` draws its deck envelopes (`envelopes.png`, one
//! panel per quantity) beside `envelopes.csv`.

use crate::support::{assert_exit, manifest_dir, vbi};

/// Width and height of a PNG, from its IHDR chunk.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    (be(16), be(20))
}

#[test]
fn a_run_with_envelopes_draws_them_along_the_deck() {
    let out = std::env::temp_dir().join(format!("vbi-plots-{}-envelopes", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let run = vbi(
        &[
            "run",
            "examples/road-bridge-check.yaml",
            "--quiet",
            "--out",
            out.to_str().unwrap(),
        ],
        manifest_dir(),
    );
    assert_exit(&run, 0);
    let csv = std::fs::read_to_string(out.join("envelopes.csv")).unwrap();
    // The scene's three quantities: displacement, moment, shear.
    let header = csv.lines().next().unwrap();
    for q in [
        "bridge_displacement_max [m]",
        "bridge_moment_max [N*m]",
        "bridge_shear_max [N]",
    ] {
        assert!(header.split(',').any(|h| h == q), "{q} in {header}");
    }
    let png = std::fs::read(out.join("envelopes.png")).expect("envelopes.png is written");
    // One 260 px panel per quantity under a 45 px title band, 40 px axis
    // (the history chart's layout, src/report/plot/history.rs).
    assert_eq!(png_size(&png), (900, 45 + 3 * 260 + 40));
    assert!(
        png.len() > 20_000,
        "a drawn chart, not a blank one: {} bytes",
        png.len()
    );
    let _ = std::fs::remove_dir_all(&out);
}
