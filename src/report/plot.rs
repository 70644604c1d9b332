//! PNG charts for reports: x–y line charts, binary (two-state) maps and heat maps.
//!
//! Rendering uses `plotters`' bitmap backend into an in-memory RGB buffer, which is
//! encoded with the `png` crate and written atomically (temporary file in the same
//! folder, then rename). Text uses the embedded DejaVu Sans font, so output does not
//! depend on the fonts installed on the machine.
//!
//! Non-finite values (and values with magnitude above 1e300) are skipped, as are
//! non-positive values on a logarithmic axis. No function here panics on bad data:
//! inconsistent inputs give [`PlotError::InvalidInput`].

use std::ffi::OsString;
use std::fs::{self, File};
use std::io::Write;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

use plotters::coord::Shift;
use plotters::coord::cartesian::Cartesian2d;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Image width in pixels.
pub const WIDTH: u32 = 900;
/// Image height in pixels.
pub const HEIGHT: u32 = 650;

const FONT_FAMILY: &str = "sans-serif";
static FONT_BYTES: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/assets/DejaVuSans.ttf"
));

/// Values with a larger magnitude are treated like non-finite ones (skipped).
const MAX_ABS: f64 = 1e300;
/// Smallest positive value shown on a logarithmic axis.
const MIN_LOG: f64 = 1e-300;
/// Up to this many grid values, map axes put one tick on each cell centre.
const MAX_GRID_TICKS: usize = 12;

const TITLE_SIZE: f64 = 26.0;
const DESC_SIZE: f64 = 20.0;
const LABEL_SIZE: f64 = 16.0;
const LEGEND_SIZE: f64 = 17.0;

/// Fill of a `true` ("separated") cell in [`binary_map`].
const TRUE_COLOUR: RGBColor = RGBColor(150, 150, 150);
/// Fill of a `false` cell in [`binary_map`].
const FALSE_COLOUR: RGBColor = RGBColor(255, 255, 255);

/// Line colours, cycled (the "tab10" palette).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// `v` as `m×10ᵉ` with superscript exponent (`10ᵉ` when the mantissa is 1).
fn pow10(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return fixed(v, 0);
    }
    let s = format!("{v:.2e}");
    let Some((m, e)) = s.split_once('e') else {
        return s;
    };
    let m = trim_zeros(m);
    let sup: String = e
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect();
    match m {
        "1" => format!("10{sup}"),
        "-1" => format!("-10{sup}"),
        _ => format!("{m}×10{sup}"),
    }
}

/// Viridis colour map control points (equally spaced from 0 to 1).
const VIRIDIS: [(u8, u8, u8); 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// Why a chart could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The embedded font could not be parsed or registered.
    #[error("the embedded font could not be registered")]
    Font,
    /// The inputs are inconsistent (length mismatch, unordered grid, bad path, ...).
    #[error("invalid plot input: {0}")]
    InvalidInput(String),
    /// The drawing library reported an error.
    #[error("drawing the chart failed: {0}")]
    Draw(String),
    /// PNG encoding failed.
    #[error("encoding the PNG failed: {0}")]
    Encode(String),
    /// Writing the file failed: no temporary file is left, and a file already at
    /// `path` is unchanged.
    #[error("writing {}: {source}", path.display())]
    Io {
        /// The file that was to be written.
        path: PathBuf,
        /// The underlying I/O error.
        #[source]
        source: std::io::Error,
    },
}

/// One line on an x–y chart.
#[derive(Debug, Clone, Copy)]
pub struct Series<'a> {
    /// Legend entry; an empty label gives no legend entry.
    pub label: &'a str,
    /// Abscissae.
    pub x: &'a [f64],
    /// Ordinates, one per abscissa.
    pub y: &'a [f64],
}

/// Line chart: title, axis labels (with units), several series with a legend,
/// optional logarithmic axes.
///
/// Points with a non-finite coordinate (or a non-positive one on a log axis) are
/// skipped and break the line; an isolated valid point is drawn as a dot.
/// `x` and `y` of a series must have the same length.
#[allow(clippy::too_many_arguments)]
pub fn line_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    log_x: bool,
    log_y: bool,
) -> Result<(), PlotError> {
    let rendered = render_line_chart(title, x_label, y_label, series, log_x, log_y)?;
    write_png(path, &rendered.rgb)
}

/// A two-state map on a regular (possibly non-uniform) grid: cell `(i, j)` is centred
/// at `(x_values[i], y_values[j])` and `state[i * y_values.len() + j]` is `true`
/// (drawn grey, legend `true_label`) or `false` (white, legend `false_label`).
///
/// Grid values must be finite and strictly monotonic; cell edges lie halfway between
/// neighbouring values.
#[allow(clippy::too_many_arguments)]
pub fn binary_map(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    y_values: &[f64],
    state: &[bool],
    true_label: &str,
    false_label: &str,
) -> Result<(), PlotError> {
    let rendered = render_binary_map(
        title,
        x_label,
        y_label,
        x_values,
        y_values,
        state,
        true_label,
        false_label,
    )?;
    write_png(path, &rendered.rgb)
}

/// A heat map of a scalar on the same kind of grid as [`binary_map`]
/// (`values[i * y_values.len() + j]` at `(x_values[i], y_values[j])`), with a colour
/// bar labelled `value_label`. Non-finite values are left blank (white).
#[allow(clippy::too_many_arguments)]
pub fn heat_map(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    y_values: &[f64],
    values: &[f64],
    value_label: &str,
) -> Result<(), PlotError> {
    let rendered = render_heat_map(
        title,
        x_label,
        y_label,
        x_values,
        y_values,
        values,
        value_label,
    )?;
    write_png(path, &rendered.rgb)
}

// ---------------------------------------------------------------------------
// Rendering
// ---------------------------------------------------------------------------

type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// Where the data rectangle of a chart ended up (pixels) and what it shows (data
/// units, linear axes). Used by the tests to find a cell's pixel.
#[cfg_attr(not(test), allow(dead_code))]
#[derive(Debug, Clone, Default)]
struct Geometry {
    px_x: Range<i32>,
    px_y: Range<i32>,
    x: Range<f64>,
    y: Range<f64>,
}

#[cfg_attr(not(test), allow(dead_code))]
struct Rendered {
    /// RGB, 3 bytes per pixel, row-major, `WIDTH × HEIGHT`.
    rgb: Vec<u8>,
    geometry: Geometry,
}

fn draw_err<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}

fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT_FAMILY, FontStyle::Normal, FONT_BYTES).is_ok()
    });
    if ok { Ok(()) } else { Err(PlotError::Font) }
}

fn font(size: f64) -> TextStyle<'static> {
    TextStyle::from((FONT_FAMILY, size).into_font()).color(&BLACK)
}

/// Draws onto a white `WIDTH × HEIGHT` canvas and returns the pixels.
fn render(
    draw: impl FnOnce(&Area<'_>) -> Result<Geometry, PlotError>,
) -> Result<Rendered, PlotError> {
    ensure_font()?;
    let mut rgb = vec![255u8; WIDTH as usize * HEIGHT as usize * 3];
    let geometry = {
        let root = BitMapBackend::with_buffer(&mut rgb, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let geometry = draw(&root)?;
        root.present().map_err(draw_err)?;
        geometry
    };
    Ok(Rendered { rgb, geometry })
}

/// Draws the title (if any) and returns the area below it.
fn with_title<'a>(root: &Area<'a>, title: &str) -> Result<Area<'a>, PlotError> {
    if title.is_empty() {
        Ok(root.clone().margin(10, 0, 0, 0))
    } else {
        root.titled(title, font(TITLE_SIZE)).map_err(draw_err)
    }
}

fn render_line_chart(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    log_x: bool,
    log_y: bool,
) -> Result<Rendered, PlotError> {
    for s in series {
        if s.x.len() != s.y.len() {
            return Err(PlotError::InvalidInput(format!(
                "series '{}': x has {} points but y has {}",
                s.label,
                s.x.len(),
                s.y.len()
            )));
        }
    }
    let ok_x = |v: f64| if log_x { usable_log(v) } else { usable(v) };
    let ok_y = |v: f64| if log_y { usable_log(v) } else { usable(v) };
    // Runs of consecutive valid points, per series.
    let runs: Vec<Vec<Vec<(f64, f64)>>> = series
        .iter()
        .map(|s| {
            let mut runs = Vec::new();
            let mut cur = Vec::new();
            for (&x, &y) in s.x.iter().zip(s.y) {
                if ok_x(x) && ok_y(y) {
                    cur.push((x, y));
                } else if !cur.is_empty() {
                    runs.push(std::mem::take(&mut cur));
                }
            }
            if !cur.is_empty() {
                runs.push(cur);
            }
            runs
        })
        .collect();
    let points = runs.iter().flatten().flatten();
    let (x_lo, x_hi) = min_max(points.clone().map(|p| p.0));
    let (y_lo, y_hi) = min_max(points.map(|p| p.1));

    let x_range = if log_x {
        log_range(x_lo, x_hi)
    } else {
        linear_range(x_lo, x_hi, 0.0)
    };
    let y_range = if log_y {
        log_range(y_lo, y_hi)
    } else {
        linear_range(y_lo, y_hi, 0.05)
    };
    let labels = LineChartText {
        title,
        x_label,
        y_label,
        log_x,
        log_y,
    };
    render(|root| match (log_x, log_y) {
        (false, false) => draw_line_chart(
            root,
            RangedCoordf64::from(x_range.clone()),
            RangedCoordf64::from(y_range.clone()),
            &labels,
            series,
            &runs,
        ),
        (true, false) => draw_line_chart(
            root,
            LogCoord::from(x_range.clone().log_scale()),
            RangedCoordf64::from(y_range.clone()),
            &labels,
            series,
            &runs,
        ),
        (false, true) => draw_line_chart(
            root,
            RangedCoordf64::from(x_range.clone()),
            LogCoord::from(y_range.clone().log_scale()),
            &labels,
            series,
            &runs,
        ),
        (true, true) => draw_line_chart(
            root,
            LogCoord::from(x_range.clone().log_scale()),
            LogCoord::from(y_range.clone().log_scale()),
            &labels,
            series,
            &runs,
        ),
    })
}

struct LineChartText<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    log_x: bool,
    log_y: bool,
}

fn draw_line_chart<X, Y>(
    root: &Area<'_>,
    x_coord: X,
    y_coord: Y,
    text: &LineChartText,
    series: &[Series],
    runs: &[Vec<Vec<(f64, f64)>>],
) -> Result<Geometry, PlotError>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let x_fmt = tick_formatter(&x_coord.range(), text.log_x);
    let y_fmt = tick_formatter(&y_coord.range(), text.log_y);
    let area = with_title(root, text.title)?;
    let mut chart = ChartBuilder::on(&area)
        .margin(15)
        .margin_right(30)
        .x_label_area_size(60)
        .y_label_area_size(95)
        .build_cartesian_2d(x_coord, y_coord)
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .x_desc(text.x_label)
        .y_desc(text.y_label)
        .x_labels(10)
        .y_labels(10)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(font(LABEL_SIZE))
        .axis_desc_style(font(DESC_SIZE))
        .bold_line_style(RGBColor(200, 200, 200).stroke_width(1))
        .light_line_style(RGBColor(235, 235, 235).stroke_width(1))
        .draw()
        .map_err(draw_err)?;

    let mut any_label = false;
    for (k, (s, runs)) in series.iter().zip(runs).enumerate() {
        let colour = PALETTE[k % PALETTE.len()];
        let style = colour.stroke_width(2);
        if !s.label.is_empty() {
            any_label = true;
            // An empty series carries the legend entry, so that series without any
            // valid point still appear in the legend.
            chart
                .draw_series(LineSeries::new(std::iter::empty(), style))
                .map_err(draw_err)?
                .label(s.label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        }
        for run in runs {
            // A run that lands on one pixel (a single point, or points closer than a
            // pixel) would be invisible as a line: draw it as a dot.
            let Some(&p0) = run.first() else { continue };
            let first = chart.backend_coord(&p0);
            if run.iter().all(|p| chart.backend_coord(p) == first) {
                chart
                    .draw_series(std::iter::once(Circle::new(p0, 3, colour.filled())))
                    .map_err(draw_err)?;
            } else {
                chart
                    .draw_series(LineSeries::new(run.iter().copied(), style))
                    .map_err(draw_err)?;
            }
        }
    }
    if any_label {
        let position = legend_position(&chart, series, runs)?;
        chart
            .configure_series_labels()
            .position(position)
            .label_font(font(LEGEND_SIZE))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .margin(10)
            .draw()
            .map_err(draw_err)?;
    }
    let (px_x, px_y) = chart.plotting_area().get_pixel_range();
    Ok(Geometry {
        px_x,
        px_y,
        ..Geometry::default()
    })
}

/// The plotting-area corner where the legend box covers the least of the lines.
fn legend_position<X, Y>(
    chart: &ChartContext<'_, BitMapBackend<'_>, Cartesian2d<X, Y>>,
    series: &[Series],
    runs: &[Vec<Vec<(f64, f64)>>],
) -> Result<SeriesLabelPosition, PlotError>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    // Same box size as plotters' legend: text block + 30 px sample + 2 × margin (10).
    let style = font(LEGEND_SIZE);
    let mut text = MultiLineText::<_, &str>::new((0, 0), &style);
    for s in series.iter().filter(|s| !s.label.is_empty()) {
        text.push_line(s.label);
    }
    let (tw, th) = text.estimate_dimension().map_err(draw_err)?;
    let (w, h) = (tw + 30 + 20, th + 20);
    let (px_x, px_y) = chart.plotting_area().get_pixel_range();
    let (aw, ah) = (px_x.end - px_x.start, px_y.end - px_y.start);
    let candidates = [
        (SeriesLabelPosition::UpperRight, aw - w - 5, 5),
        (SeriesLabelPosition::UpperLeft, 5, 5),
        (SeriesLabelPosition::LowerRight, aw - w - 5, ah - h - 5),
        (SeriesLabelPosition::LowerLeft, 5, ah - h - 5),
    ];
    let mut hits = [0usize; 4];
    let mut count = |p: (i32, i32)| {
        let (x, y) = (p.0 - px_x.start, p.1 - px_y.start);
        for (hit, (_, cx, cy)) in hits.iter_mut().zip(&candidates) {
            if x >= *cx && x <= cx + w && y >= *cy && y <= cy + h {
                *hit += 1;
            }
        }
    };
    for run in runs.iter().flatten() {
        let pixels: Vec<(i32, i32)> = run.iter().map(|p| chart.backend_coord(p)).collect();
        if let [p] = pixels[..] {
            count(p);
        }
        // Sample each segment every few pixels so that long straight segments count.
        for seg in pixels.windows(2) {
            let (a, b) = (seg[0], seg[1]);
            let len = f64::from((b.0 - a.0).abs().max((b.1 - a.1).abs()));
            let steps = ((len / 4.0).ceil() as i32).clamp(1, 400);
            for k in 0..steps {
                let t = f64::from(k) / f64::from(steps);
                count((
                    a.0 + (f64::from(b.0 - a.0) * t).round() as i32,
                    a.1 + (f64::from(b.1 - a.1) * t).round() as i32,
                ));
            }
        }
    }
    let best = (0..candidates.len())
        .min_by_key(|&k| (hits[k], k))
        .unwrap_or(0);
    Ok(candidates[best].0.clone())
}

/// One axis of a map grid.
struct GridAxis {
    /// `n + 1` cell edges (same order as the values).
    edges: Vec<f64>,
    range: Range<f64>,
    ticks: Vec<f64>,
}

fn grid_axis(name: &str, values: &[f64]) -> Result<GridAxis, PlotError> {
    if let Some(v) = values.iter().find(|v| !usable(**v)) {
        return Err(PlotError::InvalidInput(format!(
            "{name} contains the value {v}, grid values must be finite"
        )));
    }
    let increasing = values.windows(2).all(|w| w[1] > w[0]);
    let decreasing = values.windows(2).all(|w| w[1] < w[0]);
    if !increasing && !decreasing {
        return Err(PlotError::InvalidInput(format!(
            "{name} must be strictly increasing or strictly decreasing"
        )));
    }
    let n = values.len();
    let edges = match n {
        0 => vec![],
        1 => {
            let v = values[0];
            let h = if v.abs() < 1e-200 { 0.5 } else { 0.1 * v.abs() };
            vec![v - h, v + h]
        }
        _ => {
            let mut e = Vec::with_capacity(n + 1);
            e.push(values[0] - 0.5 * (values[1] - values[0]));
            e.extend(values.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            e.push(values[n - 1] + 0.5 * (values[n - 1] - values[n - 2]));
            e
        }
    };
    let range = match (edges.first(), edges.last()) {
        (Some(&a), Some(&b)) if a.is_finite() && b.is_finite() && a != b => a.min(b)..a.max(b),
        _ => 0.0..1.0,
    };
    let ticks = if (1..=MAX_GRID_TICKS).contains(&n) {
        values.to_vec()
    } else {
        RangedCoordf64::from(range.clone()).key_points(10)
    };
    Ok(GridAxis {
        edges,
        range,
        ticks,
    })
}

/// A linear axis whose ticks are given explicitly (the grid values when few).
struct GridCoord {
    inner: RangedCoordf64,
    ticks: Vec<f64>,
}

impl GridCoord {
    fn new(axis: &GridAxis) -> Self {
        Self {
            inner: axis.range.clone().into(),
            ticks: axis.ticks.clone(),
        }
    }
}

impl Ranged for GridCoord {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.inner.range()
    }
}

fn check_grid_len(what: &str, len: usize, nx: usize, ny: usize) -> Result<(), PlotError> {
    match nx.checked_mul(ny) {
        Some(n) if n == len => Ok(()),
        _ => Err(PlotError::InvalidInput(format!(
            "{what} has {len} entries but the grid is {nx} × {ny}"
        ))),
    }
}

/// Sets up a map chart (axes, ticks at grid values) on `area`, draws `cell_colour`
/// for every cell that has one, and frames the grid.
fn draw_grid_chart(
    area: &Area<'_>,
    x_label: &str,
    y_label: &str,
    xa: &GridAxis,
    ya: &GridAxis,
    cell_colour: impl Fn(usize, usize) -> Option<RGBColor>,
) -> Result<Geometry, PlotError> {
    let x_fmt = tick_formatter(&xa.range, false);
    let y_fmt = tick_formatter(&ya.range, false);
    let mut chart = ChartBuilder::on(area)
        .margin(15)
        .margin_right(30)
        .x_label_area_size(60)
        .y_label_area_size(95)
        .build_cartesian_2d(GridCoord::new(xa), GridCoord::new(ya))
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(font(LABEL_SIZE))
        .axis_desc_style(font(DESC_SIZE))
        .draw()
        .map_err(draw_err)?;
    let ny = ya.edges.len().saturating_sub(1);
    let nx = xa.edges.len().saturating_sub(1);
    let cells = (0..nx).flat_map(|i| (0..ny).map(move |j| (i, j)));
    chart
        .draw_series(cells.filter_map(|(i, j)| {
            cell_colour(i, j).map(|c| {
                Rectangle::new(
                    [
                        (xa.edges[i], ya.edges[j]),
                        (xa.edges[i + 1], ya.edges[j + 1]),
                    ],
                    c.filled(),
                )
            })
        }))
        .map_err(draw_err)?;
    chart
        .draw_series(std::iter::once(Rectangle::new(
            [
                (xa.range.start, ya.range.start),
                (xa.range.end, ya.range.end),
            ],
            BLACK.stroke_width(1),
        )))
        .map_err(draw_err)?;
    let (px_x, px_y) = chart.plotting_area().get_pixel_range();
    Ok(Geometry {
        px_x,
        px_y,
        x: xa.range.clone(),
        y: ya.range.clone(),
    })
}

#[allow(clippy::too_many_arguments)]
fn render_binary_map(
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    y_values: &[f64],
    state: &[bool],
    true_label: &str,
    false_label: &str,
) -> Result<Rendered, PlotError> {
    check_grid_len("state", state.len(), x_values.len(), y_values.len())?;
    let xa = grid_axis("x_values", x_values)?;
    let ya = grid_axis("y_values", y_values)?;
    let ny = y_values.len();
    render(|root| {
        let area = with_title(root, title)?;
        let (legend, chart_area) = area.split_vertically(36);
        let entries: Vec<(&str, RGBColor)> =
            [(true_label, TRUE_COLOUR), (false_label, FALSE_COLOUR)]
                .into_iter()
                .filter(|(l, _)| !l.is_empty())
                .collect();
        draw_swatch_legend(&legend, &entries)?;
        draw_grid_chart(&chart_area, x_label, y_label, &xa, &ya, |i, j| {
            Some(if state[i * ny + j] {
                TRUE_COLOUR
            } else {
                FALSE_COLOUR
            })
        })
    })
}

/// A centred row of "■ label" entries (square with a black border).
fn draw_swatch_legend(area: &Area<'_>, entries: &[(&str, RGBColor)]) -> Result<(), PlotError> {
    const BOX: i32 = 18;
    const GAP: i32 = 8;
    const SPACING: i32 = 36;
    if entries.is_empty() {
        return Ok(());
    }
    let style = font(LEGEND_SIZE);
    let mut widths = Vec::with_capacity(entries.len());
    for (label, _) in entries {
        let (w, _) = area.estimate_text_size(label, &style).map_err(draw_err)?;
        widths.push(i32::try_from(w).unwrap_or(i32::MAX / 4));
    }
    let total: i32 =
        widths.iter().map(|w| BOX + GAP + w).sum::<i32>() + SPACING * (entries.len() as i32 - 1);
    let (aw, ah) = area.dim_in_pixel();
    let mut x = ((aw as i32 - total) / 2).max(5);
    let y = ah as i32 / 2;
    let text_style = style.pos(Pos::new(HPos::Left, VPos::Center));
    for ((label, colour), w) in entries.iter().zip(widths) {
        let corners = [(x, y - BOX / 2), (x + BOX, y + BOX / 2)];
        area.draw(&Rectangle::new(corners, colour.filled()))
            .map_err(draw_err)?;
        area.draw(&Rectangle::new(corners, BLACK.stroke_width(1)))
            .map_err(draw_err)?;
        area.draw(&Text::new(*label, (x + BOX + GAP, y), text_style.clone()))
            .map_err(draw_err)?;
        x += BOX + GAP + w + SPACING;
    }
    Ok(())
}

fn render_heat_map(
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    y_values: &[f64],
    values: &[f64],
    value_label: &str,
) -> Result<Rendered, PlotError> {
    const BAR_PANEL: u32 = 150;
    check_grid_len("values", values.len(), x_values.len(), y_values.len())?;
    let xa = grid_axis("x_values", x_values)?;
    let ya = grid_axis("y_values", y_values)?;
    let ny = y_values.len();
    let (lo, hi) = min_max(values.iter().copied().filter(|v| usable(*v)));
    let v_range = linear_range(lo, hi, 0.0);
    let colour_of = |v: f64| {
        let t = (v - v_range.start) / (v_range.end - v_range.start);
        viridis(t)
    };
    render(|root| {
        let area = with_title(root, title)?;
        let (main, bar) = area.split_horizontally(WIDTH - BAR_PANEL);
        let geometry = draw_grid_chart(&main, x_label, y_label, &xa, &ya, |i, j| {
            let v = values[i * ny + j];
            usable(v).then(|| colour_of(v))
        })?;
        draw_colour_bar(&bar, &v_range, value_label, colour_of)?;
        Ok(geometry)
    })
}

fn draw_colour_bar(
    area: &Area<'_>,
    range: &Range<f64>,
    label: &str,
    colour_of: impl Fn(f64) -> RGBColor,
) -> Result<(), PlotError> {
    const STEPS: usize = 128;
    let fmt = tick_formatter(range, false);
    // Same vertical layout as the map chart so that the bar lines up with it.
    let mut chart = ChartBuilder::on(area)
        .margin_top(15)
        .margin_bottom(15)
        .margin_left(0)
        .margin_right(10)
        .x_label_area_size(60)
        .right_y_label_area_size(100)
        .build_cartesian_2d(0.0..1.0, range.clone())
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .set_all_tick_mark_size(6)
        .y_desc(label)
        .y_labels(8)
        .y_label_formatter(&fmt)
        .label_style(font(LABEL_SIZE))
        .axis_desc_style(font(DESC_SIZE))
        .draw()
        .map_err(draw_err)?;
    let step = (range.end - range.start) / STEPS as f64;
    chart
        .draw_series((0..STEPS).map(|k| {
            let a = range.start + step * k as f64;
            let b = if k + 1 == STEPS { range.end } else { a + step };
            Rectangle::new([(0.0, a), (1.0, b)], colour_of(0.5 * (a + b)).filled())
        }))
        .map_err(draw_err)?;
    chart
        .draw_series(std::iter::once(Rectangle::new(
            [(0.0, range.start), (1.0, range.end)],
            BLACK.stroke_width(1),
        )))
        .map_err(draw_err)?;
    Ok(())
}

// ---------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------

fn usable(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_ABS
}

fn usable_log(v: f64) -> bool {
    usable(v) && v >= MIN_LOG
}

/// Minimum and maximum of the values; `(NaN, NaN)` when there are none.
fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::NAN, f64::NAN), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// A finite, non-degenerate range covering `[lo, hi]`, widened by `pad` × span on
/// each side. Degenerate inputs (no data, all equal) get a sensible default.
fn linear_range(lo: f64, hi: f64, pad: f64) -> Range<f64> {
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return 0.0..1.0;
    }
    let span = hi - lo;
    let mag = lo.abs().max(hi.abs());
    if span <= mag * 1e-9 || span < 1e-200 {
        let c = 0.5 * (lo + hi);
        let h = if c.abs() < 1e-200 { 1.0 } else { 0.1 * c.abs() };
        return (c - h)..(c + h);
    }
    (lo - pad * span)..(hi + pad * span)
}

/// Whole decades covering `[lo, hi]` (both positive), at least one decade wide.
fn log_range(lo: f64, hi: f64) -> Range<f64> {
    if !(lo >= MIN_LOG && hi >= lo && hi <= MAX_ABS) {
        return 1.0..10.0;
    }
    let mut a = lo.log10().floor();
    let mut b = hi.log10().ceil();
    if b <= a {
        a -= 1.0;
        b += 1.0;
    }
    10f64.powf(a)..10f64.powf(b)
}

/// Tick label formatter: plain decimals for moderate magnitudes, otherwise
/// scientific notation, with trailing zeros trimmed.
fn tick_formatter(range: &Range<f64>, log: bool) -> impl Fn(&f64) -> String + use<> {
    let range = range.clone();
    let span = (range.end - range.start).abs();
    let mag = range.start.abs().max(range.end.abs());
    move |&v: &f64| {
        if log {
            // Plain numbers while the whole axis stays in a readable window,
            // otherwise powers of ten written as 10⁻³ (and 2×10⁻³ between decades).
            return if (1e-3..=1e5).contains(&range.start.min(range.end))
                && (1e-3..=1e5).contains(&mag)
            {
                fixed(v, 6)
            } else {
                pow10(v)
            };
        }
        if !v.is_finite() {
            return String::new();
        }
        if v.abs() <= span * 1e-9 {
            return "0".to_string();
        }
        let span_exp = span.log10().floor();
        if !(1e-3..1e5).contains(&mag) {
            let prec = (mag.log10().floor() - span_exp + 1.0).clamp(0.0, 6.0) as usize;
            sci(v, prec)
        } else {
            let decimals = (3.0 - span_exp).clamp(0.0, 8.0) as usize;
            fixed(v, decimals)
        }
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    let t = trim_zeros(&s);
    if t == "-0" { "0".into() } else { t.into() }
}

fn sci(v: f64, prec: usize) -> String {
    let s = format!("{v:.prec$e}");
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{}", trim_zeros(m), e),
        None => s,
    }
}

/// Viridis colour for `t` in [0, 1] (clamped).
fn viridis(t: f64) -> RGBColor {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let scaled = t * (VIRIDIS.len() - 1) as f64;
    let k = (scaled.floor() as usize).min(VIRIDIS.len() - 2);
    let f = scaled - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + (f64::from(q) - f64::from(p)) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

// ---------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------

fn encode_png(rgb: &[u8]) -> Result<Vec<u8>, PlotError> {
    let enc_err = |e: png::EncodingError| PlotError::Encode(e.to_string());
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, WIDTH, HEIGHT);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(enc_err)?;
    writer.write_image_data(rgb).map_err(enc_err)?;
    writer.finish().map_err(enc_err)?;
    Ok(out)
}

fn write_png(path: &Path, rgb: &[u8]) -> Result<(), PlotError> {
    let bytes = encode_png(rgb)?;
    write_atomic(path, &bytes)
}

/// Writes `bytes` to a temporary file next to `path`, then renames it to `path`.
/// On failure the temporary file is removed.
fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let file_name = path.file_name().ok_or_else(|| {
        PlotError::InvalidInput(format!("output path '{}' has no file name", path.display()))
    })?;
    let mut tmp_name = OsString::from(".");
    tmp_name.push(file_name);
    tmp_name.push(format!(
        ".{}-{}.tmp",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let tmp = path.with_file_name(tmp_name);
    let io_err = |source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut file = File::create_new(&tmp).map_err(io_err)?;
    let written = file
        .write_all(bytes)
        .and_then(|()| file.sync_all())
        .and_then(|()| {
            drop(file);
            fs::rename(&tmp, path)
        });
    if let Err(e) = written {
        let _ = fs::remove_file(&tmp);
        return Err(io_err(e));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
