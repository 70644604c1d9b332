//! Unit tests of the maps: the binary map's and heat map's cells and
//! colours, their edge cases, and the category axis.

use super::*;

#[test]
fn binary_map_cells_have_expected_colours() {
    let dir = test_dir("binary");
    // Non-uniform x spacing; only cell (1, 1) is separated.
    let xs = [10.0, 20.0, 40.0];
    let ys = [0.1, 0.2, 0.3];
    let mut state = vec![false; 9];
    state[ys.len() + 1] = true;
    let r = render_binary_map(
        "map",
        "v [m/s]",
        "r [-]",
        &xs,
        &ys,
        &state,
        "separated",
        "in contact",
    )
    .unwrap();
    let g = &r.geometry;
    // Cell (1, 1) spans x 15..30, y 0.15..0.25.
    let (px, py) = to_pixel(g, 22.5, 0.2);
    assert_eq!(pixel(&r.rgb, px, py), colour_tuple(TRUE_COLOUR));
    // Cell (2, 2) spans x 30..50, y 0.25..0.35: white.
    let (px, py) = to_pixel(g, 45.0, 0.32);
    assert_eq!(pixel(&r.rgb, px, py), colour_tuple(FALSE_COLOUR));
    // The edge between cells (0, 1) and (1, 1) is halfway (x = 15): just right of
    // it is grey, just left of it is white.
    let (px_edge, py) = to_pixel(g, 15.0, 0.2);
    assert_eq!(pixel(&r.rgb, px_edge + 3, py), colour_tuple(TRUE_COLOUR));
    assert_eq!(pixel(&r.rgb, px_edge - 3, py), colour_tuple(FALSE_COLOUR));

    // The file version decodes to the same pixels.
    let path = dir.join("binary.png");
    binary_map(
        &path,
        "map",
        "v [m/s]",
        "r [-]",
        &xs,
        &ys,
        &state,
        "separated",
        "in contact",
    )
    .unwrap();
    let rgb = check_png(&path);
    assert_eq!(rgb, r.rgb);
}

#[test]
fn binary_map_edge_cases() {
    let dir = test_dir("binary_edges");
    // Single cell, separated: the whole plotting area is grey in its middle.
    let r = render_binary_map("one", "x", "y", &[5.0], &[0.0], &[true], "sep", "").unwrap();
    let g = &r.geometry;
    let (px, py) = to_pixel(g, 5.0, 0.0);
    assert_eq!(pixel(&r.rgb, px, py), colour_tuple(TRUE_COLOUR));
    // Empty grid, decreasing axis, and errors.
    binary_map(
        &dir.join("empty.png"),
        "e",
        "x",
        "y",
        &[],
        &[],
        &[],
        "a",
        "b",
    )
    .unwrap();
    binary_map(
        &dir.join("dec.png"),
        "d",
        "x",
        "y",
        &[3.0, 2.0, 1.0],
        &[1.0],
        &[true, false, true],
        "a",
        "b",
    )
    .unwrap();
    check_png(&dir.join("dec.png"));
    let e = binary_map(
        &dir.join("x.png"),
        "t",
        "x",
        "y",
        &[1.0, 2.0],
        &[1.0],
        &[true],
        "a",
        "b",
    );
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
    let e = binary_map(
        &dir.join("x.png"),
        "t",
        "x",
        "y",
        &[1.0, f64::NAN],
        &[1.0],
        &[true, true],
        "a",
        "b",
    );
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
    let e = binary_map(
        &dir.join("x.png"),
        "t",
        "x",
        "y",
        &[1.0, 3.0, 2.0],
        &[1.0],
        &[true; 3],
        "a",
        "b",
    );
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
    let e = binary_map(
        &dir.join("x.png"),
        "t",
        "x",
        "y",
        &[1.0, 1.0],
        &[1.0],
        &[true; 2],
        "a",
        "b",
    );
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
    assert!(!dir.join("x.png").exists());
}

#[test]
fn heat_map_writes_png_with_colours() {
    let dir = test_dir("heat");
    let xs: Vec<f64> = (0..8).map(|k| 10.0 + 5.0 * k as f64).collect();
    let ys = [1.0, 2.0, 3.0, 4.0, 5.0];
    let values: Vec<f64> = (0..xs.len() * ys.len())
        .map(|k| 1.0 + 0.01 * k as f64)
        .collect();
    let path = dir.join("heat.png");
    heat_map(
        &path,
        "DAF",
        "speed [m/s]",
        "roughness class",
        &xs,
        &ys,
        &values,
        "DAF [-]",
    )
    .unwrap();
    let rgb = check_png(&path);
    let r = render_heat_map(
        "DAF",
        "speed [m/s]",
        "roughness class",
        &xs,
        &ys,
        &values,
        "DAF [-]",
    )
    .unwrap();
    assert_eq!(rgb, r.rgb);
    // Lowest value (cell (0, 0)) is the start of the colour map, highest the end.
    let (px, py) = to_pixel(&r.geometry, xs[0], ys[0]);
    assert_eq!(pixel(&rgb, px, py), (68, 1, 84));
    let (px, py) = to_pixel(&r.geometry, xs[7], ys[4]);
    assert_eq!(pixel(&rgb, px, py), (253, 231, 37));
}

#[test]
fn heat_map_edge_cases() {
    let dir = test_dir("heat_edges");
    let nan = f64::NAN;
    // All equal, all NaN, single cell, mixed non-finite, empty.
    heat_map(
        &dir.join("eq.png"),
        "t",
        "x",
        "y",
        &[1.0, 2.0],
        &[1.0, 2.0],
        &[3.0; 4],
        "v",
    )
    .unwrap();
    let r = render_heat_map("t", "x", "y", &[1.0, 2.0], &[1.0], &[nan, nan], "v").unwrap();
    let (px, py) = to_pixel(&r.geometry, 1.0, 1.0);
    assert_eq!(pixel(&r.rgb, px, py), (255, 255, 255));
    heat_map(
        &dir.join("one.png"),
        "t",
        "x",
        "y",
        &[7.0],
        &[0.5],
        &[1.2],
        "v",
    )
    .unwrap();
    heat_map(
        &dir.join("mixed.png"),
        "t",
        "x",
        "y",
        &[1.0, 2.0, 4.0],
        &[1.0],
        &[f64::INFINITY, 2.0, -f64::INFINITY],
        "v",
    )
    .unwrap();
    heat_map(&dir.join("empty.png"), "t", "x", "y", &[], &[1.0], &[], "v").unwrap();
    for f in ["eq.png", "one.png", "mixed.png", "empty.png"] {
        check_png(&dir.join(f));
    }
    let e = heat_map(
        &dir.join("bad.png"),
        "t",
        "x",
        "y",
        &[1.0],
        &[1.0],
        &[1.0, 2.0],
        "v",
    );
    assert!(matches!(e, Err(PlotError::InvalidInput(_))));
}

#[test]
fn category_axis_names_its_ticks_and_cells_sit_on_them() {
    let names: Vec<String> = ["smooth", "good", "poor"].map(String::from).to_vec();
    let axis = category_axis(&names).unwrap();
    assert_eq!(axis.ticks, [0.0, 1.0, 2.0]);
    assert_eq!(axis.labels.as_deref(), Some(&names[..]));
    let xs = [10.0, 20.0];
    let values = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    let r = render_category_heat_map("t", "speed", "surface", &xs, &names, &values, "v").unwrap();
    // Row j sits at y = j: the lowest value (x 10, smooth) and the highest
    // (x 20, poor) take the ends of the colour map.
    let (px, py) = to_pixel(&r.geometry, 10.0, 0.0);
    assert_eq!(pixel(&r.rgb, px, py), (68, 1, 84));
    let (px, py) = to_pixel(&r.geometry, 20.0, 2.0);
    assert_eq!(pixel(&r.rgb, px, py), (253, 231, 37));
    assert!(render_category_heat_map("t", "x", "y", &xs, &names, &values[..5], "v").is_err());
}
