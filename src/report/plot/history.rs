//! Time histories as stacked panels sharing the time axis: one panel per
//! unit (deflections in m, accelerations in m/s², forces in N, …), vertical
//! lines where each vehicle enters and leaves the bridge.

use super::*;

/// Height of one panel, pixels.
const PANEL_HEIGHT: u32 = 260;
/// Height of the title band, pixels.
const TITLE_BAND: u32 = 45;

/// One panel: the series that share a unit, and the axis label with it.
#[derive(Debug, Clone)]
pub struct Panel<'a> {
    /// Vertical axis label with the unit, e.g. `bridge displacement (m)`.
    pub y_label: String,
    /// The lines (same x for all panels: time).
    pub series: Vec<Series<'a>>,
    /// Lines drawn thin and grey (e.g. the static response), not in the legend.
    pub references: Vec<Series<'a>>,
}

/// A vertical line across every panel at `x`, labelled at the top.
#[derive(Debug, Clone)]
pub struct Marker {
    /// Abscissa.
    pub x: f64,
    /// Short label (e.g. `v1 in`).
    pub label: String,
}

/// Stacked line charts over a common x axis (`x_label` under the last) with
/// vertical markers; the image grows with the number of panels. Long series
/// are reduced for drawing to the minimum and maximum in each pixel column,
/// so every peak stays visible.
pub fn history_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(), PlotError> {
    let (rgb, height) = render_history(title, x_label, panels, markers)?;
    let bytes = encode_png_sized(&rgb, WIDTH, height)?;
    write_atomic(path, &bytes)
}

pub(super) fn render_history(
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(Vec<u8>, u32), PlotError> {
    if panels.is_empty() {
        return Err(PlotError::InvalidInput(
            "a history chart needs a panel".into(),
        ));
    }
    for s in panels
        .iter()
        .flat_map(|p| p.series.iter().chain(&p.references))
    {
        if s.x.len() != s.y.len() {
            return Err(PlotError::InvalidInput(format!(
                "series '{}': x has {} points but y has {}",
                s.label,
                s.x.len(),
                s.y.len()
            )));
        }
    }
    let x_range = x_range_of(panels);
    let height = history_height(panels);
    let rendered = render_sized(WIDTH, height, |root| {
        draw_history(root, title, x_label, panels, markers, &x_range)?;
        Ok(Geometry::default())
    })?;
    Ok((rendered.rgb, height))
}

/// The time axis: every series' finite abscissae.
fn x_range_of(panels: &[Panel]) -> Range<f64> {
    let (x_lo, x_hi) = min_max(
        panels
            .iter()
            .flat_map(|p| p.series.iter().chain(&p.references))
            .flat_map(|s| s.x.iter().copied())
            .filter(|&v| usable(v)),
    );
    linear_range(x_lo, x_hi, 0.0)
}

fn history_height(panels: &[Panel]) -> u32 {
    TITLE_BAND + PANEL_HEIGHT * panels.len() as u32 + 40
}

/// [`history_chart`] as SVG (vector, for reports): the same drawing.
pub fn history_chart_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(), PlotError> {
    // The same checks as the PNG (and the same picture, drawn as vectors).
    render_history(title, x_label, panels, markers)?;
    ensure_font()?;
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (WIDTH, history_height(panels))).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        draw_history(&root, title, x_label, panels, markers, &x_range_of(panels))?;
        root.present().map_err(draw_err)?;
    }
    write_atomic(path, svg.as_bytes())
}

fn draw_history<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
    x_range: &Range<f64>,
) -> Result<(), PlotError> {
    let body = root.titled(title, font(TITLE_SIZE)).map_err(draw_err)?;
    let rows = body.split_evenly((panels.len(), 1));
    for (k, (panel, area)) in panels.iter().zip(&rows).enumerate() {
        let last = k + 1 == panels.len();
        let x_label = if last { x_label } else { "" };
        draw_panel(area, panel, x_range, x_label, markers, k == 0)?;
    }
    Ok(())
}

/// At most two points (the min and the max, in time order) per `buckets`th
/// of the x range: what a pixel column can show anyway.
pub(super) fn reduce(x: &[f64], y: &[f64], buckets: usize) -> Vec<(f64, f64)> {
    let points: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .map(|(&a, &b)| (a, b))
        .filter(|&(a, b)| usable(a) && usable(b))
        .collect();
    if points.len() <= 4 * buckets {
        return points;
    }
    let per = points.len().div_ceil(buckets);
    let mut out = Vec::with_capacity(2 * buckets + 2);
    for chunk in points.chunks(per) {
        let lo = chunk.iter().min_by(|a, b| a.1.total_cmp(&b.1));
        let hi = chunk.iter().max_by(|a, b| a.1.total_cmp(&b.1));
        if let (Some(&lo), Some(&hi)) = (lo, hi) {
            if lo.0 <= hi.0 {
                out.extend([lo, hi]);
            } else {
                out.extend([hi, lo]);
            }
        }
    }
    out
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    x_range: &Range<f64>,
    x_label: &str,
    markers: &[Marker],
    label_markers: bool,
) -> Result<(), PlotError> {
    let buckets = WIDTH as usize;
    let lines: Vec<Vec<(f64, f64)>> = panel
        .series
        .iter()
        .map(|s| reduce(s.x, s.y, buckets))
        .collect();
    let references: Vec<Vec<(f64, f64)>> = panel
        .references
        .iter()
        .map(|s| reduce(s.x, s.y, buckets))
        .collect();
    let (y_lo, y_hi) = min_max(lines.iter().chain(&references).flatten().map(|p| p.1));
    let y_range = linear_range(y_lo, y_hi, 0.08);
    let x_fmt = tick_formatter(x_range, false);
    let y_fmt = tick_formatter(&y_range, false);
    let mut chart = ChartBuilder::on(area)
        .margin(8)
        .margin_right(30)
        .x_label_area_size(if x_label.is_empty() { 28 } else { 55 })
        .y_label_area_size(95)
        .build_cartesian_2d(x_range.clone(), y_range.clone())
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(panel.y_label.as_str())
        .x_labels(10)
        .y_labels(6)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(font(LABEL_SIZE))
        .axis_desc_style(font(DESC_SIZE - 2.0))
        .bold_line_style(RGBColor(200, 200, 200).stroke_width(1))
        .light_line_style(RGBColor(235, 235, 235).stroke_width(1))
        .draw()
        .map_err(draw_err)?;
    // Entry and exit lines under the data.
    let marker_style = RGBColor(120, 120, 120).stroke_width(1);
    // A vehicle that leaves as the record ends (no free vibration) still
    // gets its line, at the right edge (up to rounding of its exit time).
    let slack = 1e-9 * (x_range.end - x_range.start);
    for m in markers
        .iter()
        .filter(|m| m.x >= x_range.start - slack && m.x <= x_range.end + slack)
    {
        let x = m.x.clamp(x_range.start, x_range.end);
        chart
            .draw_series(DashedLineSeries::new(
                [(x, y_range.start), (x, y_range.end)],
                6,
                4,
                marker_style,
            ))
            .map_err(draw_err)?;
        if label_markers {
            let at = chart.backend_coord(&(x, y_range.end));
            // Right of the line, or left of it near the right edge.
            let near_end = x > x_range.start + 0.9 * (x_range.end - x_range.start);
            let style = font(LABEL_SIZE - 2.0).color(&RGBColor(90, 90, 90));
            let style = if near_end {
                style.pos(Pos::new(HPos::Right, VPos::Top))
            } else {
                style
            };
            let dx = if near_end { -3 } else { 3 };
            area.draw(&Text::new(
                m.label.clone(),
                (
                    at.0 + dx - area.get_base_pixel().0,
                    at.1 + 2 - area.get_base_pixel().1,
                ),
                style,
            ))
            .map_err(draw_err)?;
        }
    }
    for line in &references {
        chart
            .draw_series(LineSeries::new(
                line.iter().copied(),
                RGBColor(150, 150, 150).stroke_width(1),
            ))
            .map_err(draw_err)?;
    }
    for (k, (s, line)) in panel.series.iter().zip(&lines).enumerate() {
        let style = PALETTE[k % PALETTE.len()].stroke_width(2);
        chart
            .draw_series(LineSeries::new(line.iter().copied(), style))
            .map_err(draw_err)?
            .label(s.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
    }
    if panel.series.iter().any(|s| !s.label.is_empty()) {
        let runs: Vec<Vec<Vec<(f64, f64)>>> = lines.iter().map(|l| vec![l.clone()]).collect();
        let position = legend_position(&chart, &panel.series, &runs)?;
        chart
            .configure_series_labels()
            .position(position)
            .label_font(font(LEGEND_SIZE - 2.0))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .margin(6)
            .draw()
            .map_err(draw_err)?;
    }
    Ok(())
}
