//! Plots that finish the story (issue 28, point 7), through the binary: a
//! run with `envelopes:` draws its deck envelopes (`envelopes.png`, one
//! panel per quantity) beside `envelopes.csv`.

use vbi::report::envelopes::envelope_plot_layout;
use vbi::report::history_plot::history_plot_layout;
use vbi::report::plot::{
    HistoryLayout, Marker, Panel, PeakLayout, PixelBox, Series, history_layout,
};

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

/// A run of a shipped scene in-process, for the layout of its plots.
fn simulate(scene: &str) -> (vbi::scene::Scenario, vbi::run::Outcome) {
    let loaded = vbi::plan::load_file(&manifest_dir().join(scene)).unwrap();
    let scenario = loaded.scenario.clone();
    let outcome = vbi::run::simulate(loaded, &mut |_, _| {}).unwrap();
    (scenario, outcome)
}

/// Whether the segment `a`–`b`, drawn `half` pixels either side of its
/// path, shares a pixel with `b`: sampled every quarter pixel, on its own
/// (not the placement's occupancy grid).
fn segment_hits(a: (i32, i32), z: (i32, i32), half: i32, b: &PixelBox) -> bool {
    let (dx, dy) = (f64::from(z.0 - a.0), f64::from(z.1 - a.1));
    let steps = (4.0 * dx.abs().max(dy.abs())).ceil().max(1.0) as i32;
    (0..=steps).any(|k| {
        let t = f64::from(k) / f64::from(steps);
        let (x, y) = (
            (f64::from(a.0) + dx * t).round() as i32,
            (f64::from(a.1) + dy * t).round() as i32,
        );
        x + half >= b.left && x - half < b.right && y + half >= b.top && y - half < b.bottom
    })
}

fn line_hits(line: &[(i32, i32)], half: i32, b: &PixelBox) -> bool {
    match line {
        [p] => segment_hits(*p, *p, half, b),
        _ => line.windows(2).any(|s| segment_hits(s[0], s[1], half, b)),
    }
}

/// Everything in a chart's layout that hides something else: a peak label
/// over a line (its 2-pixel stroke), a ring, a marker's label or another
/// peak label, or out of its plotting area; a legend over any of those or
/// over a marker line (the history's "enters"/"leaves", the envelope's
/// supports).
fn overlaps(layout: &HistoryLayout) -> Vec<String> {
    let mut found = Vec::new();
    for (n, panel) in layout.panels.iter().enumerate() {
        let rings: Vec<PixelBox> = panel
            .peaks
            .iter()
            .map(|p| PixelBox {
                left: p.ring.0 - 6,
                top: p.ring.1 - 6,
                right: p.ring.0 + 7,
                bottom: p.ring.1 + 7,
            })
            .collect();
        let marker_labels: Vec<PixelBox> = panel.markers.iter().filter_map(|m| m.label).collect();
        let labels: Vec<(&str, PixelBox)> = panel
            .peaks
            .iter()
            .filter_map(|p| p.label.map(|b| (p.text.as_str(), b)))
            .collect();
        for (i, (text, b)) in labels.iter().enumerate() {
            if !panel.plot.contains(b) {
                found.push(format!(
                    "panel {n}: '{text}' {b:?} leaves the plot {:?}",
                    panel.plot
                ));
            }
            for (k, line) in panel.lines.iter().enumerate() {
                if line_hits(line, 1, b) {
                    found.push(format!("panel {n}: '{text}' {b:?} is on line {k}"));
                }
            }
            for (k, r) in rings.iter().enumerate() {
                if r.intersects(b) {
                    found.push(format!("panel {n}: '{text}' {b:?} is on ring {k}"));
                }
            }
            for (other, o) in labels.iter().skip(i + 1) {
                if o.intersects(b) {
                    found.push(format!("panel {n}: '{text}' {b:?} is on '{other}' {o:?}"));
                }
            }
            for o in &marker_labels {
                if o.intersects(b) {
                    found.push(format!(
                        "panel {n}: '{text}' {b:?} is on a marker label {o:?}"
                    ));
                }
            }
        }
        if let Some(g) = panel.legend {
            let hidden = panel.lines.iter().any(|l| line_hits(l, 1, &g))
                || rings.iter().chain(&marker_labels).any(|r| r.intersects(&g))
                || labels.iter().any(|(_, b)| b.intersects(&g))
                || panel.markers.iter().any(|m| m.x >= g.left && m.x < g.right);
            if hidden {
                found.push(format!("panel {n}: the legend {g:?} hides something"));
            }
            if g.right > layout.width as i32 || g.bottom > layout.height as i32 {
                found.push(format!("panel {n}: the legend {g:?} leaves the image"));
            }
        }
    }
    found
}

/// Issue 40.7: in the history and envelope plots of shipped scenes — three
/// deflections and two vehicles' entry and exit markers in one, a road
/// bridge's four records and its three envelopes in the other — no peak
/// label lies on a drawn line, a ring or another label, and no legend
/// hides a line, a label or a marker ("enters", "leaves", a support).
/// Most labels find a place beside their ring (not the legend's line).
#[test]
fn peak_labels_and_legends_hide_nothing() {
    for scene in [
        "scenarios/three-span-two-vehicles.yaml",
        "examples/road-bridge-check.yaml",
    ] {
        let (scenario, outcome) = simulate(scene);
        let mut charts = vec![(
            "history",
            history_plot_layout(&scenario, &outcome.history)
                .unwrap()
                .unwrap(),
        )];
        if let Some(envelope) = &outcome.history.envelope {
            charts.push((
                "envelopes",
                envelope_plot_layout(&scenario, envelope).unwrap().unwrap(),
            ));
        }
        for (name, layout) in charts {
            let mut found = overlaps(&layout);
            // The markers' labels (one line at the top) are off the data too.
            for panel in &layout.panels {
                for b in panel.markers.iter().filter_map(|m| m.label) {
                    if panel.lines.iter().any(|l| line_hits(l, 1, &b)) {
                        found.push(format!("a marker label {b:?} is on a line"));
                    }
                }
            }
            assert!(found.is_empty(), "{scene} {name}:\n{}", found.join("\n"));
            let peaks: Vec<&PeakLayout> = layout.panels.iter().flat_map(|p| &p.peaks).collect();
            let beside = peaks.iter().filter(|p| p.label.is_some()).count();
            assert!(
                !peaks.is_empty() && 4 * beside >= 3 * peaks.len(),
                "{scene} {name}: {beside} of {} peak labels on the plot",
                peaks.len()
            );
        }
    }
}

/// Crowded panels through the library: three records peaking together
/// under the markers' labels, and a marker line ("v1 leaves") through the
/// corner that is otherwise free of data, where a legend used to go; a
/// second panel of six lines swinging over its whole height and peaking
/// at one instant, without room near the rings for six labels: those
/// that find none go into their series' legend lines, and every legend
/// goes right of its plotting area, clear of the data.
#[test]
fn crowded_panels_keep_their_labels_and_legends_clear() {
    let t: Vec<f64> = (0..2001).map(|i| f64::from(i) * 5e-4).collect();
    let bump = |scale: f64, at: f64| -> Vec<f64> {
        t.iter()
            .map(|&t| scale * (-((t - at) / 0.08).powi(2)).exp())
            .collect()
    };
    let (a, b, c) = (bump(1.0, 0.30), bump(0.96, 0.31), bump(0.92, 0.29));
    let dense: Vec<Vec<f64>> = (0..6)
        .map(|k| {
            let scale = 1.0 - 0.01 * f64::from(k);
            t.iter().map(|&t| scale * (300.0 * t).sin()).collect()
        })
        .collect();
    let names = ["w1", "w2", "w3", "w4", "w5", "w6"];
    let panels = [
        Panel {
            y_label: "deflection (m)".into(),
            unit: "m".into(),
            series: vec![
                Series {
                    label: "span1",
                    x: &t,
                    y: &a,
                },
                Series {
                    label: "span2",
                    x: &t,
                    y: &b,
                },
                Series {
                    label: "span3",
                    x: &t,
                    y: &c,
                },
            ],
            references: vec![],
        },
        Panel {
            y_label: "force (N)".into(),
            unit: "N".into(),
            series: dense
                .iter()
                .zip(names)
                .map(|(y, label)| Series { label, x: &t, y })
                .collect(),
            references: vec![],
        },
    ];
    let markers = [
        Marker {
            x: 0.3,
            label: "v1 enters".into(),
        },
        Marker {
            x: 0.31,
            label: "v2 enters".into(),
        },
        Marker {
            x: 0.93,
            label: "v1 leaves".into(),
        },
    ];
    let layout = history_layout("crowded", "time (s)", &panels, &markers).unwrap();
    let found = overlaps(&layout);
    assert!(found.is_empty(), "{}", found.join("\n"));
    let [first, second] = &layout.panels[..] else {
        panic!("two panels")
    };
    // The bumps' labels are beside their rings; some of the swings' are in
    // their legend lines, each peak once, on the plot or in the legend.
    assert!(
        first.peaks.iter().all(|p| p.label.is_some()),
        "{:?}",
        first.peaks
    );
    let moved: Vec<&PeakLayout> = second.peaks.iter().filter(|p| p.label.is_none()).collect();
    assert!(!moved.is_empty(), "{:?}", second.peaks);
    for p in &second.peaks {
        let listed = second
            .legend_entries
            .iter()
            .filter(|e| e.contains(&p.text))
            .count();
        assert_eq!(
            listed,
            usize::from(p.label.is_none()),
            "{p:?} {:?}",
            second.legend_entries
        );
    }
    for panel in [first, second] {
        let legend = panel.legend.expect("a legend");
        assert!(
            !panel.legend_inside && legend.left >= panel.plot.right,
            "{legend:?}"
        );
    }
    // The markers' labels do not sit on each other either.
    let labels: Vec<PixelBox> = first.markers.iter().filter_map(|m| m.label).collect();
    assert_eq!(labels.len(), 3);
    assert!(!labels[0].intersects(&labels[1]), "{labels:?}");
}

/// The LCP paper's oscillator on a smooth two-mode beam (the scene of
/// tests/it/converge.rs), 1 ms step: a quick convergence study.
const SMOOTH_SCENE: &str = "name: smooth-two-modes
bridge:
  type: beam
  spans: [20.0]
  bending_stiffness: 3.2423e9
  mass_per_length: 2000.0
  modes: {count: 2}
  damping: {type: modal, ratio: 0.02}
vehicles:
  - type: oscillator
    sprung_mass: 4000.0
    unsprung_mass: 1000.0
    stiffness: 4.0e6
    damping: 2.53e4
    speed: 25.0
solver: {method: coupled, time_step: 1.0e-3, free_vibration: 0.2}
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
  - {name: contact_force, quantity: contact_force, wheel: 1}
";

/// A PNG's RGB pixels and width.
fn decode_png(bytes: &[u8]) -> (Vec<u8>, usize) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut rgb).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    rgb.truncate(info.buffer_size());
    (rgb, info.width as usize)
}

/// Issue 40.7: `converge.png`'s time-step axis (logarithmic, a ladder of
/// factors of 2) is labelled at a few round steps written `1e-3`, `2e-3`,
/// `5e-3`, whose boxes are apart; and in the picture, the ink under the
/// axis falls in those boxes only, in groups no wider than one label (the
/// 2×10⁻³ … 6×10⁻³ of a decade had run into each other).
#[test]
fn converge_time_step_ticks_are_apart_and_read_as_numbers() {
    for levels in [3, 6] {
        let loaded = vbi::plan::load_str(SMOOTH_SCENE, "smooth.yaml").unwrap();
        let options = vbi::study::converge::Options {
            levels,
            tolerance: 0.05,
            ..Default::default()
        };
        let study = vbi::study::converge::converge(&loaded, &options, &mut |_, _, _| {}).unwrap();
        let (_, height, panels) = study.plot_layout().unwrap();
        let steps = &panels[0];
        let ticks = &steps.x_ticks;
        assert!(ticks.len() >= 2, "levels {levels}: {ticks:?}");
        for (text, _) in ticks {
            let (m, e) = text.split_once('e').unwrap_or((text, "0"));
            assert!(
                m.len() == 1 && m.parse::<u32>().is_ok_and(|m| m > 0) && e.parse::<i32>().is_ok(),
                "levels {levels}: tick '{text}'"
            );
        }
        for pair in ticks.windows(2) {
            let ((a, x), (b, y)) = (&pair[0], &pair[1]);
            assert!(
                x.right + 8 <= y.left,
                "levels {levels}: '{a}' {x:?} and '{b}' {y:?}"
            );
        }
        // The picture: dark pixels in the tick labels' rows.
        let out = std::env::temp_dir().join(format!(
            "vbi-plots-{}-converge-{levels}.png",
            std::process::id()
        ));
        study.plot(&out).unwrap();
        let (rgb, width) = decode_png(&std::fs::read(&out).unwrap());
        let _ = std::fs::remove_file(&out);
        let plot = steps.plot;
        let rows = (plot.bottom + 3)..(plot.bottom + 26).min(height as i32);
        let dark = |col: i32| {
            rows.clone().any(|row| {
                let at = 3 * (row as usize * width + col as usize);
                rgb[at..at + 3].iter().all(|&c| c < 140)
            })
        };
        let columns = (plot.left - 30)..(plot.right + 30);
        let inked: Vec<i32> = columns.filter(|&c| dark(c)).collect();
        // Runs of inked columns, split at 4 blank ones.
        let mut groups: Vec<(i32, i32)> = Vec::new();
        for &c in &inked {
            match groups.last_mut() {
                Some(g) if c - g.1 <= 4 => g.1 = c,
                _ => groups.push((c, c)),
            }
        }
        let widest = ticks.iter().map(|(_, b)| b.right - b.left).max().unwrap();
        for &(a, z) in &groups {
            assert!(
                z - a < widest + 2,
                "levels {levels}: ink {a}..={z} wider than a label"
            );
            assert!(
                ticks
                    .iter()
                    .any(|(_, b)| a >= b.left - 2 && z < b.right + 2),
                "levels {levels}: ink {a}..={z} outside every tick label {ticks:?}"
            );
        }
        for (text, b) in ticks {
            assert!(
                groups
                    .iter()
                    .any(|&(a, z)| a >= b.left - 2 && z < b.right + 2),
                "levels {levels}: no ink for '{text}' {b:?}"
            );
        }
        // The cheapest run's red label is off every drawn line (its 2 px
        // stroke sampled along each segment), on whichever panel holds it.
        let labels: Vec<_> = panels
            .iter()
            .filter_map(|p| p.chosen_label.map(|b| (p, b)))
            .collect();
        assert!(!labels.is_empty(), "levels {levels}: no cheapest label");
        for (panel, b) in labels {
            for line in &panel.lines {
                for pair in line.windows(2) {
                    let (a, z) = (pair[0], pair[1]);
                    let steps = (z.0 - a.0).abs().max((z.1 - a.1).abs()).max(1);
                    for k in 0..=steps {
                        let t = f64::from(k) / f64::from(steps);
                        let x = f64::from(a.0) + f64::from(z.0 - a.0) * t;
                        let y = f64::from(a.1) + f64::from(z.1 - a.1) * t;
                        let inside = x >= f64::from(b.left - 2)
                            && x <= f64::from(b.right + 2)
                            && y >= f64::from(b.top - 2)
                            && y <= f64::from(b.bottom + 2);
                        assert!(
                            !inside,
                            "levels {levels}: the cheapest label {b:?} is on a line at ({x}, {y})"
                        );
                    }
                }
            }
        }
    }
}
