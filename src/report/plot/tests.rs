//! Unit tests of the parent module.

mod maps;

use super::*;
use std::fs;

const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// A fresh folder under the system temp dir, removed when dropped.
struct TestDir(PathBuf);

impl std::ops::Deref for TestDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for TestDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TestDir {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

fn test_dir(name: &str) -> TestDir {
    let dir = std::env::temp_dir().join(format!("helper_plot_{}_{name}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    TestDir(dir)
}

/// Checks signature and IHDR size; returns the decoded RGB pixels.
fn check_png(path: &Path) -> Vec<u8> {
    let bytes = fs::read(path).unwrap();
    assert!(bytes.len() > 33, "file too short");
    assert_eq!(bytes[..8], PNG_SIGNATURE);
    assert_eq!(&bytes[12..16], b"IHDR");
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((w, h), (WIDTH, HEIGHT));
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    buf.truncate(info.buffer_size());
    buf
}

fn pixel(rgb: &[u8], x: i32, y: i32) -> (u8, u8, u8) {
    let k = (y as usize * WIDTH as usize + x as usize) * 3;
    (rgb[k], rgb[k + 1], rgb[k + 2])
}

/// Pixel of a data point on a linear map chart.
fn to_pixel(g: &Geometry, x: f64, y: f64) -> (i32, i32) {
    let fx = (x - g.x.start) / (g.x.end - g.x.start);
    let fy = (y - g.y.start) / (g.y.end - g.y.start);
    let px = g.px_x.start as f64 + fx * (g.px_x.end - g.px_x.start) as f64;
    let py = g.px_y.end as f64 - fy * (g.px_y.end - g.px_y.start) as f64;
    (px.round() as i32, py.round() as i32)
}

fn colour_tuple(c: RGBColor) -> (u8, u8, u8) {
    (c.0, c.1, c.2)
}

fn leftovers(dir: &Path) -> Vec<PathBuf> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "tmp"))
        .collect()
}

#[test]
fn line_chart_writes_png() {
    let dir = test_dir("line");
    let x: Vec<f64> = (0..200).map(|k| k as f64 * 0.05).collect();
    let y1: Vec<f64> = x.iter().map(|t| t.sin()).collect();
    let y2: Vec<f64> = x.iter().map(|t| 0.5 * (2.0 * t).cos()).collect();
    let path = dir.join("line.png");
    line_chart(
        &path,
        "Midspan response",
        "time t [s]",
        "displacement w [mm]",
        &[
            Series {
                label: "sin",
                x: &x,
                y: &y1,
            },
            Series {
                label: "cos",
                x: &x,
                y: &y2,
            },
        ],
        false,
        false,
    )
    .unwrap();
    let rgb = check_png(&path);
    // First palette colour is present (the line was drawn).
    let blue = colour_tuple(PALETTE[0]);
    assert!(rgb.chunks(3).any(|p| (p[0], p[1], p[2]) == blue));
    assert!(leftovers(&dir).is_empty());
}

#[test]
fn line_chart_log_log() {
    let dir = test_dir("loglog");
    let f: Vec<f64> = (0..100).map(|k| 0.1 * 1.08f64.powi(k)).collect();
    let psd: Vec<f64> = f.iter().map(|f| 1e-3 / (1.0 + f * f)).collect();
    let path = dir.join("psd.png");
    line_chart(
        &path,
        "PSD",
        "f [Hz]",
        "S [m²/Hz]",
        &[Series {
            label: "S",
            x: &f,
            y: &psd,
        }],
        true,
        true,
    )
    .unwrap();
    check_png(&path);
}

#[test]
fn line_chart_edge_cases_do_not_panic() {
    let dir = test_dir("line_edges");
    let nan = f64::NAN;
    let inf = f64::INFINITY;
    let cases: Vec<(Vec<f64>, Vec<f64>)> = vec![
        (vec![], vec![]),
        (vec![1.0], vec![2.0]),
        (vec![1.0, 2.0, 3.0], vec![5.0, 5.0, 5.0]),
        (vec![nan, inf, -inf], vec![nan, 1.0, 2.0]),
        (
            vec![0.0, 1.0, 2.0, 3.0, 4.0],
            vec![1.0, nan, 3.0, -inf, 0.0],
        ),
        (vec![-1.0, 0.0, 1.0, 10.0], vec![-5.0, 0.0, 2.0, 20.0]),
        (vec![0.0, 0.0], vec![0.0, 0.0]),
        (vec![1e-310, 1e300, 1e308], vec![1e-310, -1e300, f64::MAX]),
        (vec![1.0, 1.0 + 1e-15], vec![3.0, 3.0 + 1e-15]),
    ];
    let mut k = 0;
    for (x, y) in &cases {
        for (log_x, log_y) in [(false, false), (true, false), (false, true), (true, true)] {
            let path = dir.join(format!("edge{k}.png"));
            k += 1;
            line_chart(
                &path,
                "edge",
                "x",
                "y",
                &[Series { label: "s", x, y }],
                log_x,
                log_y,
            )
            .unwrap();
            check_png(&path);
        }
    }
    // No series at all, and an unlabelled one, and an empty title.
    line_chart(&dir.join("none.png"), "", "", "", &[], true, false).unwrap();
    line_chart(
        &dir.join("nolabel.png"),
        "t",
        "x",
        "y",
        &[Series {
            label: "",
            x: &[1.0, 2.0],
            y: &[1.0, 2.0],
        }],
        false,
        false,
    )
    .unwrap();
    // Mismatched lengths: an error, no file.
    let bad = dir.join("bad.png");
    let err = line_chart(
        &bad,
        "t",
        "x",
        "y",
        &[Series {
            label: "s",
            x: &[1.0],
            y: &[],
        }],
        false,
        false,
    );
    assert!(matches!(err, Err(PlotError::InvalidInput(_))));
    assert!(!bad.exists());
}

#[test]
fn missing_folder_is_an_error_and_leaves_nothing() {
    let dir = test_dir("missing");
    let path = dir.join("no_such_folder").join("x.png");
    let e = line_chart(&path, "t", "x", "y", &[], false, false);
    assert!(matches!(e, Err(PlotError::Io { .. })), "{e:?}");
    let e = binary_map(&path, "t", "x", "y", &[1.0], &[1.0], &[true], "a", "b");
    assert!(matches!(e, Err(PlotError::Io { .. })));
    let e = heat_map(&path, "t", "x", "y", &[1.0], &[1.0], &[1.0], "v");
    assert!(matches!(e, Err(PlotError::Io { .. })));
    assert!(!path.exists());
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 0);
    // A path without a file name.
    let e = line_chart(Path::new("/"), "t", "x", "y", &[], false, false);
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
}

#[test]
fn failed_rename_removes_the_temporary_file() {
    let dir = test_dir("rename");
    // The target is a non-empty folder: the temporary file is written, but the
    // rename onto the folder fails.
    let target = dir.join("taken.png");
    fs::create_dir(&target).unwrap();
    fs::write(target.join("keep"), b"x").unwrap();
    let e = heat_map(&target, "t", "x", "y", &[1.0], &[1.0], &[1.0], "v");
    assert!(matches!(e, Err(PlotError::Io { .. })), "{e:?}");
    assert!(leftovers(&dir).is_empty());
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
    assert!(target.join("keep").exists());
}

#[test]
fn overwrites_existing_file_and_leaves_no_temporary() {
    let dir = test_dir("overwrite");
    let path = dir.join("a.png");
    fs::write(&path, b"old").unwrap();
    line_chart(&path, "t", "x", "y", &[], false, false).unwrap();
    check_png(&path);
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
}

#[test]
fn tick_labels_read_well() {
    let f = tick_formatter(&(0.0..1.0), false);
    assert_eq!(f(&0.2), "0.2");
    assert_eq!(f(&0.30000000000000004), "0.3");
    assert_eq!(f(&-1e-17), "0");
    let f = tick_formatter(&(0.0..200.0), false);
    assert_eq!(f(&150.0), "150");
    let f = tick_formatter(&(1e-4..5e-4), false);
    assert_eq!(f(&2e-4), "2e-4");
    let f = tick_formatter(&(1e-6..1e2), true);
    assert_eq!(f(&1e-6), "10⁻⁶");
    assert_eq!(f(&10.0), "10¹");
    assert_eq!(f(&1.0), "10⁰");
    assert_eq!(f(&2e-5), "2×10⁻⁵");
    let f = tick_formatter(&(0.01..1e3), true);
    assert_eq!(f(&0.01), "0.01");
    assert_eq!(f(&1000.0), "1000");
}

#[test]
fn ranges_are_sane() {
    assert_eq!(log_range(2.0, 5.0), 1.0..10.0);
    assert_eq!(log_range(10.0, 10.0), 1.0..100.0);
    assert_eq!(log_range(0.02, 300.0), 0.01..1000.0);
    assert_eq!(linear_range(f64::NAN, f64::NAN, 0.05), 0.0..1.0);
    let r = linear_range(5.0, 5.0, 0.05);
    assert!(r.start < 5.0 && r.end > 5.0);
    assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
    assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
    assert_eq!(viridis(f64::NAN), RGBColor(68, 1, 84));
}

/// Renders one sample of each chart to /tmp/plot_samples for a visual check.
#[test]
#[ignore = "writes sample images to /tmp/plot_samples"]
fn render_samples() {
    let dir = Path::new("/tmp/plot_samples");
    fs::create_dir_all(dir).unwrap();
    let t: Vec<f64> = (0..=500).map(|k| k as f64 * 0.004).collect();
    let w1: Vec<f64> = t
        .iter()
        .map(|t| -2.1 * (std::f64::consts::PI * t / 2.0).sin() * (1.0 + 0.1 * (40.0 * t).sin()))
        .collect();
    let w2: Vec<f64> = t
        .iter()
        .map(|t| -1.8 * (std::f64::consts::PI * t / 2.0).sin())
        .collect();
    line_chart(
        &dir.join("line.png"),
        "Midspan displacement, v = 25 m/s",
        "time t [s]",
        "displacement w [mm]",
        &[
            Series {
                label: "VBI (coupled)",
                x: &t,
                y: &w1,
            },
            Series {
                label: "moving force",
                x: &t,
                y: &w2,
            },
        ],
        false,
        false,
    )
    .unwrap();
    let f: Vec<f64> = (0..200).map(|k| 0.01 * 1.05f64.powi(k)).collect();
    let psd_a: Vec<f64> = f
        .iter()
        .map(|f| 1e-4 * (0.1f64 / f.max(1e-9)).powi(2))
        .collect();
    let psd_c: Vec<f64> = f
        .iter()
        .map(|f| 1.6e-5 * (0.1f64 / f.max(1e-9)).powi(2))
        .collect();
    line_chart(
        &dir.join("loglog.png"),
        "Road roughness PSD (ISO 8608)",
        "spatial frequency n [cycles/m]",
        "G_d(n) [m³]",
        &[
            Series {
                label: "class A",
                x: &f,
                y: &psd_c,
            },
            Series {
                label: "class C",
                x: &f,
                y: &psd_a,
            },
        ],
        true,
        true,
    )
    .unwrap();
    let speeds: Vec<f64> = (0..30).map(|k| 5.0 + 2.5 * k as f64).collect();
    let damping = [0.0, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1];
    let mut state = Vec::new();
    for &v in &speeds {
        for &z in &damping {
            state.push(v > 30.0 + 400.0 * z + 0.002 * (v - 40.0).powi(2));
        }
    }
    binary_map(
        &dir.join("binary.png"),
        "Wheel–bridge separation",
        "vehicle speed v [m/s]",
        "damping ratio ζ [-]",
        &speeds,
        &damping,
        &state,
        "separated",
        "in contact",
    )
    .unwrap();
    let classes = [1.0, 2.0, 3.0, 4.0, 5.0];
    let mut daf = Vec::new();
    for &v in &speeds {
        for &c in &classes {
            daf.push(1.0 + 0.004 * v + 0.05 * c * c * (v / 80.0));
        }
    }
    heat_map(
        &dir.join("heat.png"),
        "Dynamic amplification factor",
        "vehicle speed v [m/s]",
        "roughness class (1 = A … 5 = E)",
        &speeds,
        &classes,
        &daf,
        "DAF [-]",
    )
    .unwrap();
}

#[test]
fn history_panels_stack_and_keep_every_peak() {
    let t: Vec<f64> = (0..200_000).map(|i| i as f64 * 1e-5).collect();
    // A sine with one sharp spike one sample wide: the reduced line keeps it.
    let mut y: Vec<f64> = t.iter().map(|t| (10.0 * t).sin()).collect();
    y[123_457] = 5.0;
    let reduced = history::reduce(&t, &y, 900);
    assert!(reduced.len() <= 2 * 900 + 2, "{}", reduced.len());
    assert!(reduced.iter().any(|p| p.1 == 5.0), "the spike survives");
    assert!(
        reduced.windows(2).all(|w| w[0].0 <= w[1].0),
        "in time order"
    );
    let panels = [
        Panel {
            y_label: "a (m)".into(),
            unit: "m".into(),
            series: vec![Series {
                label: "a",
                x: &t,
                y: &y,
            }],
            references: vec![],
        },
        Panel {
            y_label: "b (N)".into(),
            unit: "N".into(),
            series: vec![Series {
                label: "b",
                x: &t,
                y: &y,
            }],
            references: vec![Reference {
                of: 0,
                line: Series {
                    label: "b static",
                    x: &t,
                    y: &y,
                },
            }],
        },
    ];
    let markers = [Marker {
        x: 0.5,
        label: "enters".into(),
    }];
    let (rgb, height) = history::render_history("h", "time (s)", &panels, &markers).unwrap();
    assert_eq!(height, 45 + 2 * 260 + 40);
    assert_eq!(rgb.len(), (WIDTH * height * 3) as usize);
    let blue = rgb.chunks(3).filter(|p| *p == [31, 119, 180]).count();
    assert!(blue > 2_000, "{blue}");
    assert!(history::render_history("h", "t", &[], &markers).is_err());
    let dir = test_dir("history");
    history_chart(&dir.join("h.png"), "h", "time (s)", &panels, &markers).unwrap();
    check_png_any_size(&dir.join("h.png"));
}

fn check_png_any_size(path: &Path) {
    let bytes = fs::read(path).unwrap();
    assert_eq!(bytes[..8], PNG_SIGNATURE);
    assert!(bytes.len() > 10_000);
}

#[test]
fn history_peaks_are_the_largest_magnitude_and_read_value_unit_and_time() {
    let t = [0.0, 0.5, 1.0, 1.5];
    // The minimum is the larger in magnitude: the peak is the signed value.
    assert_eq!(
        history::peak(&t, &[0.1, 0.3, -0.4, f64::NAN]),
        Some((1.0, -0.4))
    );
    assert_eq!(history::peak(&t, &[f64::NAN; 4]), None);
    assert_eq!(
        history::peak_label(-5.7718e-4, "m", 1.09968, "s"),
        "−5.772×10⁻⁴ m at 1.100 s"
    );
    assert_eq!(
        history::peak_label(123456.0, "N*m", 12.5, "m"),
        "1.235×10⁵ N*m at 12.500 m"
    );
    assert_eq!(
        history::peak_label(1.2346, "m/s^2", 0.25, "s"),
        "1.235 m/s^2 at 0.250 s"
    );
}

#[test]
fn a_dense_record_stays_inside_its_panel() {
    // Full-scale contact forces: a record that swings through most of its
    // range within every pixel column. Drawn as one thick polyline, the
    // min–max zigzag's mitre joins spiked far past the data, into the
    // title and the neighbouring panels; every pixel of the series must lie
    // between the rows of its own panel.
    let t: Vec<f64> = (0..50_000).map(|i| i as f64 * 1e-4).collect();
    let y: Vec<f64> = t
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let swing = 0.6 + 0.4 * (37.0 * t).sin().abs();
            if i % 2 == 0 { swing } else { -swing }
        })
        .collect();
    let panels = [Panel {
        y_label: "f (N)".into(),
        unit: "N".into(),
        series: vec![Series {
            label: "f",
            x: &t,
            y: &y,
        }],
        references: vec![],
    }];
    let (rgb, height) = history::render_history("h", "time (s)", &panels, &[]).unwrap();
    let blue_rows: Vec<u32> = (0..height)
        .filter(|&row| (0..WIDTH).any(|col| pixel(&rgb, col as i32, row as i32) == (31, 119, 180)))
        .collect();
    let (top, bottom) = (blue_rows[0], *blue_rows.last().unwrap());
    // The title takes the first 45 rows, the x axis the last 40 and more.
    assert!(
        top >= 45 && bottom < height - 40,
        "blue rows {top}..{bottom} of {height}"
    );
}

/// A band (issue 40.5: the probability plot's 95 % intervals) is shaded
/// under its line in a light tint of the line's colour; an interval
/// without an upper end draws nothing; a band of the wrong length is an
/// error, not a panic.
#[test]
fn bands_shade_their_interval() {
    let x = [100.0, 200.0, 300.0];
    let y = [0.0, 0.25, 1.0];
    let low = [0.0, 0.0128, 0.51];
    let high = [0.49, 0.70, 1.0];
    let series = [Series {
        label: "fra4, vehicle 1 wheel 1",
        x: &x,
        y: &y,
    }];
    let band = Band {
        low: &low,
        high: &high,
    };
    let render = |bands: &[Option<Band>]| {
        render_line_chart("t", "speed (km/h)", "p", &series, false, false, 0, 0, bands)
            .unwrap()
            .rgb
    };
    let plain = render(&[None]);
    let shaded = render(&[Some(band)]);
    // Light, bluish pixels (the first palette colour, 31/119/180, over
    // white at low opacity) cover a good part of the chart with the band;
    // without it only the line's anti-aliased edges are that light.
    let tinted = |rgb: &[u8]| {
        rgb.chunks(3)
            .filter(|p| p[0] > 200 && p[0] < 250 && p[2] > p[0] + 8 && p[1] > p[0])
            .count()
    };
    let (plain_tint, shaded_tint) = (tinted(&plain), tinted(&shaded));
    assert!(plain_tint < 1_000, "{plain_tint}");
    assert!(shaded_tint > plain_tint + 20_000, "{shaded_tint}");
    // No upper ends: no band, the chart as without one.
    let unbounded = [f64::NAN; 3];
    let open = Band {
        low: &low,
        high: &unbounded,
    };
    assert_eq!(render(&[Some(open)]), plain);
    // Lengths must agree.
    let dir = test_dir("bands");
    let short = Band {
        low: &low[..2],
        high: &high,
    };
    let err = line_chart_with_bands(&dir.join("b.png"), "t", "x", "y", &series, &[Some(short)]);
    assert!(matches!(err, Err(PlotError::InvalidInput(_))), "{err:?}");
    let err = line_chart_with_bands(&dir.join("b.png"), "t", "x", "y", &series, &[]);
    assert!(matches!(err, Err(PlotError::InvalidInput(_))), "{err:?}");
    line_chart_with_bands(&dir.join("b.png"), "t", "x", "y", &series, &[Some(band)]).unwrap();
    check_png(&dir.join("b.png"));
    assert!(leftovers(&dir).is_empty());
}

/// A legend with every corner taken — a limit line across the top (the
/// resonance check's 3.5 m/s²) and curves along the bottom at both ends —
/// goes between them, and every drawn sample of both lines stays visible
/// (it sat in the upper-right corner over the limit line and the curves
/// before the interior candidates of `legend_position`).
#[test]
fn a_legend_with_every_corner_taken_hides_no_line() {
    let x: Vec<f64> = (0..=100).map(|k| f64::from(k) * 0.1).collect();
    let limit = vec![3.5; x.len()];
    // Three responses apart (none drawn over another), low at both ends,
    // where the lower corners are.
    let curves: Vec<Vec<f64>> = (0..3)
        .map(|k| {
            let k = f64::from(k);
            x.iter()
                .map(|x| 0.3 + 0.4 * k + 0.7 * (1.0 - (std::f64::consts::TAU * x / 10.0).cos()))
                .collect()
        })
        .collect();
    let series = [
        Series {
            label: "response 1",
            x: &x,
            y: &curves[0],
        },
        Series {
            label: "response 2",
            x: &x,
            y: &curves[1],
        },
        Series {
            label: "response 3",
            x: &x,
            y: &curves[2],
        },
        Series {
            label: "limit 3.5 m/s^2 (ballasted, EN 1990 A2.4.4.2.1)",
            x: &x,
            y: &limit,
        },
    ];
    let rendered =
        render_line_chart("t", "x", "y", &series, false, false, 0, 0, &[None; 4]).unwrap();
    let g = &rendered.geometry;
    for (s, colour) in series.iter().zip(PALETTE) {
        // Interior samples: the range's ends map onto the area's edges.
        for (&x, &y) in s.x.iter().zip(s.y).skip(1).take(s.x.len() - 2) {
            let (px, py) = to_pixel(g, x, y);
            // Drawn: the line's own colour within a pixel of the sample
            // (anti-aliasing shades the exact pixel on steep stretches).
            let drawn = (-1..=1).any(|dx| {
                (-1..=1).any(|dy| pixel(&rendered.rgb, px + dx, py + dy) == colour_tuple(colour))
            });
            assert!(drawn, "{}: the sample at x = {x} is hidden", s.label);
        }
    }
}
