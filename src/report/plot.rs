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

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

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

/// Colour of background sample lines in [`line_chart_over_samples`].
const GREY_LINE: RGBColor = RGBColor(190, 190, 190);

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
    pow10_digits(v, 3)
}

/// [`pow10`] with `digits` significant digits (trailing zeros dropped).
fn pow10_digits(v: f64, digits: usize) -> String {
    if !v.is_finite() || v == 0.0 {
        return fixed(v, 0);
    }
    let precision = digits.saturating_sub(1);
    let s = format!("{v:.precision$e}");
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

/// A shaded band around one series of [`line_chart_with_bands`]: at each
/// abscissa of the series, an interval [`low`, `high`] (a confidence
/// interval); a point where either end is not finite (an interval without
/// an upper end) is left out and breaks the band.
#[derive(Debug, Clone, Copy)]
pub struct Band<'a> {
    /// Lower ends, one per abscissa of the series.
    pub low: &'a [f64],
    /// Upper ends, one per abscissa of the series.
    pub high: &'a [f64],
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
    let rendered = render_line_chart(title, x_label, y_label, series, log_x, log_y, 0, 0, &[])?;
    write_png(path, &rendered.rgb)
}

/// [`line_chart`] on linear axes with a reference line (a limit) drawn
/// black and dashed over the series, its own legend entry, not in the
/// palette's colours.
pub fn line_chart_with_reference(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    reference: &Series,
) -> Result<(), PlotError> {
    let mut all = series.to_vec();
    all.push(*reference);
    let rendered = render_line_chart(title, x_label, y_label, &all, false, false, 0, 1, &[])?;
    write_png(path, &rendered.rgb)
}

/// [`line_chart`] with the first `grey` series drawn thin and grey behind
/// the others (sample histories behind a Monte Carlo study's envelopes, as
/// in the LCP separation paper's Fig. 7), linear axes.
pub fn line_chart_over_samples(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    grey: usize,
) -> Result<(), PlotError> {
    let rendered = render_line_chart(title, x_label, y_label, series, false, false, grey, 0, &[])?;
    write_png(path, &rendered.rgb)
}

/// [`line_chart`] on linear axes with `bands[i]` shaded behind `series[i]`
/// in its colour, translucent (confidence intervals of estimates at a few
/// speeds); the axes take in the bands. `bands` has one entry per series
/// (`None`: no band), each as long as its series.
pub fn line_chart_with_bands(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    bands: &[Option<Band>],
) -> Result<(), PlotError> {
    if bands.len() != series.len() {
        return Err(PlotError::InvalidInput(format!(
            "{} bands for {} series",
            bands.len(),
            series.len()
        )));
    }
    let rendered = render_line_chart(title, x_label, y_label, series, false, false, 0, 0, bands)?;
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

/// A heat map like [`heat_map`] whose rows are named categories (e.g. road
/// surfaces): row `j` is `categories[j]`, and the y ticks read the names.
#[allow(clippy::too_many_arguments)]
pub fn category_heat_map(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    categories: &[String],
    values: &[f64],
    value_label: &str,
) -> Result<(), PlotError> {
    let rendered = render_category_heat_map(
        title,
        x_label,
        y_label,
        x_values,
        categories,
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
    render_sized(WIDTH, HEIGHT, draw)
}

/// Draws onto a white `width × height` canvas and returns the pixels.
fn render_sized(
    width: u32,
    height: u32,
    draw: impl FnOnce(&Area<'_>) -> Result<Geometry, PlotError>,
) -> Result<Rendered, PlotError> {
    ensure_font()?;
    let mut rgb = vec![255u8; width as usize * height as usize * 3];
    let geometry = {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
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
        root.titled(title, title_font(root, title))
            .map_err(draw_err)
    }
}

/// Smallest title font size, points: below it a title is left to overflow.
const MIN_TITLE_SIZE: f64 = 11.0;

/// The title's font: [`TITLE_SIZE`], or as much smaller as a long title
/// needs to fit the image's width with 20 px each side. A centred title
/// wider than the image is cut at both edges (the Monte Carlo plots' long
/// titles lost their scene name).
fn title_font<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
) -> TextStyle<'static> {
    let room = f64::from(root.dim_in_pixel().0) - 40.0;
    let mut size = TITLE_SIZE;
    while size > MIN_TITLE_SIZE {
        match root.estimate_text_size(title, &font(size)) {
            Ok((width, _)) if f64::from(width) > room => size -= 1.0,
            _ => break,
        }
    }
    font(size)
}

// ---------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------

fn encode_png(rgb: &[u8]) -> Result<Vec<u8>, PlotError> {
    encode_png_sized(rgb, WIDTH, HEIGHT)
}

fn encode_png_sized(rgb: &[u8], width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    let enc_err = |e: png::EncodingError| PlotError::Encode(e.to_string());
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
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

/// Writes `bytes` whole or not at all ([`super::atomic::write_atomic`]).
fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    if path.file_name().is_none() {
        return Err(PlotError::InvalidInput(format!(
            "output path '{}' has no file name",
            path.display()
        )));
    }
    super::atomic::write_atomic(path, bytes).map_err(|source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    })
}

mod grid;
mod history;
mod ladders;
mod layout;
mod line;
mod scale;

use grid::*;
pub use history::{
    HistoryLayout, Marker, MarkerLayout, Panel, PanelLayout, PeakLayout, Reference, history_chart,
    history_chart_svg, history_layout,
};
pub use ladders::{LadderPanel, LadderPanelLayout, ladder_chart, ladder_layout};
pub use layout::PixelBox;
use line::*;
use scale::*;

#[cfg(test)]
mod tests;
