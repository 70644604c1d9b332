//! Time histories as stacked panels sharing the time axis: one panel per
//! unit (deflections in m, accelerations in m/s², forces in N, …), vertical
//! lines where each vehicle enters and leaves the bridge.

use super::layout::*;
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
    /// The unit of the values, written after each peak's value (`m`, `N`).
    pub unit: String,
    /// The lines (same x for all panels: time); each one's peak (largest
    /// |value|) is marked and labelled with its value and time.
    pub series: Vec<Series<'a>>,
    /// Lines that belong to a series (e.g. its static response), drawn thin
    /// and dashed in its colour, each with its own legend entry (its label).
    pub references: Vec<Reference<'a>>,
}

/// A line drawn with a series of its panel (the static crossing response of
/// a deflection): `of` is the index of that series in the panel.
#[derive(Debug, Clone)]
pub struct Reference<'a> {
    /// Index of the series in [`Panel::series`] it belongs to.
    pub of: usize,
    /// The line (its label is its legend entry).
    pub line: Series<'a>,
}

/// A vertical line across every panel at `x`, labelled at the top.
#[derive(Debug, Clone)]
pub struct Marker {
    /// Abscissa.
    pub x: f64,
    /// Short label (e.g. `v1 in`).
    pub label: String,
}

/// Where one panel's parts landed in the image (pixels): what
/// [`history_layout`] reports, for checks that nothing hides anything.
#[derive(Debug, Clone, Default)]
pub struct PanelLayout {
    /// The plotting area.
    pub plot: PixelBox,
    /// Every line drawn (the static lines, then the series) as the pixels
    /// of its points, joined by straight segments.
    pub lines: Vec<Vec<(i32, i32)>>,
    /// Each series' peak, in the order of the series.
    pub peaks: Vec<PeakLayout>,
    /// The vertical markers in the panel.
    pub markers: Vec<MarkerLayout>,
    /// The legend box, if the panel has one.
    pub legend: Option<PixelBox>,
    /// The legend's lines, top to bottom.
    pub legend_entries: Vec<String>,
    /// Whether the legend fitted inside the plotting area without
    /// covering a line, a label or a marker (else it is drawn outside it).
    pub legend_inside: bool,
}

/// A peak's ring and its label.
#[derive(Debug, Clone, Default)]
pub struct PeakLayout {
    /// The label's text.
    pub text: String,
    /// The centre of the ring (radius 5 px).
    pub ring: (i32, i32),
    /// Where the label is; none when no free place was near enough and
    /// the text went into the series' legend line instead.
    pub label: Option<PixelBox>,
}

/// A vertical marker line in a panel.
#[derive(Debug, Clone, Default)]
pub struct MarkerLayout {
    /// Its column.
    pub x: i32,
    /// Its label's box (the first panel labels the markers).
    pub label: Option<PixelBox>,
}

/// Where the parts of a [`history_chart`] land.
#[derive(Debug, Clone, Default)]
pub struct HistoryLayout {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// One per panel, top to bottom.
    pub panels: Vec<PanelLayout>,
}

/// Stacked line charts over a common x axis (`x_label` under the last) with
/// vertical markers; the image grows with the number of panels. Long series
/// are reduced for drawing to the minimum and maximum in each pixel column,
/// so every peak stays visible. Each peak label is put in free space near
/// its ring and each legend where it hides nothing ([`history_layout`]).
pub fn history_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(), PlotError> {
    let (rgb, layout, _) = render_history_laid_out(title, x_label, panels, markers)?;
    let bytes = encode_png_sized(&rgb, WIDTH, layout.height)?;
    write_atomic(path, &bytes)
}

/// Where [`history_chart`] puts each panel's lines, peak labels, markers
/// and legend, without writing the picture.
pub fn history_layout(
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<HistoryLayout, PlotError> {
    Ok(render_history_laid_out(title, x_label, panels, markers)?.1)
}

#[cfg(test)]
pub(super) fn render_history(
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(Vec<u8>, u32), PlotError> {
    let (rgb, layout, _) = render_history_laid_out(title, x_label, panels, markers)?;
    Ok((rgb, layout.height))
}

/// The pixels, the layout, and the columns kept for legends outside the
/// plotting areas (none when every legend fits inside its panel).
pub(super) fn render_history_laid_out(
    title: &str,
    x_label: &str,
    panels: &[Panel],
    markers: &[Marker],
) -> Result<(Vec<u8>, HistoryLayout, Option<i32>), PlotError> {
    if panels.is_empty() {
        return Err(PlotError::InvalidInput(
            "a history chart needs a panel".into(),
        ));
    }
    for s in panels
        .iter()
        .flat_map(|p| p.series.iter().chain(p.references.iter().map(|r| &r.line)))
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
    let draw = |outside: Option<i32>| {
        let mut layouts = Vec::new();
        let rendered = render_sized(WIDTH, height, |root| {
            layouts = draw_history(root, title, x_label, panels, markers, &x_range, outside)?;
            Ok(Geometry::default())
        })?;
        Ok::<_, PlotError>((rendered.rgb, layouts))
    };
    let (mut rgb, mut layouts) = draw(None)?;
    let mut outside = None;
    if layouts.iter().any(|l| !l.legend_inside) {
        // Some legend would hide a line, a label or a marker: every
        // panel's legend goes right of its plotting area.
        let widest = layouts
            .iter()
            .filter_map(|l| l.legend)
            .map(|b| b.right - b.left)
            .max()
            .unwrap_or(0);
        outside = Some(widest + 12);
        (rgb, layouts) = draw(outside)?;
    }
    let layout = HistoryLayout {
        width: WIDTH,
        height,
        panels: layouts,
    };
    Ok((rgb, layout, outside))
}
/// The time axis: every series' finite abscissae.
fn x_range_of(panels: &[Panel]) -> Range<f64> {
    let (x_lo, x_hi) = min_max(
        panels
            .iter()
            .flat_map(|p| p.series.iter().chain(p.references.iter().map(|r| &r.line)))
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
    // The same checks as the PNG, and the same picture, drawn as vectors
    // (the legends where the PNG has them).
    let (_, _, outside) = render_history_laid_out(title, x_label, panels, markers)?;
    ensure_font()?;
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (WIDTH, history_height(panels))).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        draw_history(
            &root,
            title,
            x_label,
            panels,
            markers,
            &x_range_of(panels),
            outside,
        )?;
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
    legend_outside: Option<i32>,
) -> Result<Vec<PanelLayout>, PlotError> {
    let body = root
        .titled(title, title_font(root, title))
        .map_err(draw_err)?;
    let rows = body.split_evenly((panels.len(), 1));
    // The unit of x for the peak labels: `time (s)` → `s`.
    let x_unit = x_label
        .rsplit_once('(')
        .and_then(|(_, u)| u.strip_suffix(')'))
        .unwrap_or("")
        .to_string();
    let mut layouts = Vec::with_capacity(panels.len());
    for (k, (panel, area)) in panels.iter().zip(&rows).enumerate() {
        let last = k + 1 == panels.len();
        let frame = PanelFrame {
            x_range,
            x_label: if last { x_label } else { "" },
            x_unit: &x_unit,
            markers,
            label_markers: k == 0,
            legend_outside,
        };
        layouts.push(draw_panel(area, panel, &frame)?);
    }
    Ok(layouts)
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

/// What one panel's drawing needs besides its data.
struct PanelFrame<'a> {
    x_range: &'a Range<f64>,
    x_label: &'a str,
    x_unit: &'a str,
    markers: &'a [Marker],
    /// The first panel labels the markers.
    label_markers: bool,
    /// Columns kept right of the plotting area for a legend drawn outside
    /// it (every panel the same, so the time axes stay aligned).
    legend_outside: Option<i32>,
}

/// Margin right of each panel's plotting area, pixels.
const RIGHT_MARGIN: i32 = 30;
/// Rows kept beyond the data for a label beside a peak's ring: the ring's
/// clearance and a line of text.
const PEAK_LABEL_ROOM: i32 = 30;
/// Legend box padding, pixels.
const LEGEND_PAD: i32 = 6;
/// Width of a legend entry's sample line and the gap after it, pixels.
const LEGEND_SAMPLE: i32 = 30;

/// How a legend entry's sample is drawn.
#[derive(Clone, Copy)]
enum Sample {
    Solid(RGBColor),
    Dashed(RGBColor),
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    frame: &PanelFrame,
) -> Result<PanelLayout, PlotError> {
    let x_range = frame.x_range;
    let buckets = WIDTH as usize;
    let lines: Vec<Vec<(f64, f64)>> = panel
        .series
        .iter()
        .map(|s| reduce(s.x, s.y, buckets))
        .collect();
    let references: Vec<Vec<(f64, f64)>> = panel
        .references
        .iter()
        .map(|r| reduce(r.line.x, r.line.y, buckets))
        .collect();
    let (y_lo, y_hi) = min_max(lines.iter().chain(&references).flatten().map(|p| p.1));
    let x_label_area = if frame.x_label.is_empty() { 28 } else { 55 };
    // Room for a peak's label beyond the data: above the lines when a
    // series peaks at a maximum (or markers are labelled), below them when
    // one peaks at a minimum.
    let plot_height = area.dim_in_pixel().1 as i32 - 16 - x_label_area;
    let peaks: Vec<Option<(f64, f64)>> = panel.series.iter().map(|s| peak(s.x, s.y)).collect();
    let room = |wanted: bool| {
        let label = f64::from(PEAK_LABEL_ROOM) / f64::from(plot_height.max(4 * PEAK_LABEL_ROOM));
        if wanted { label.max(0.07) } else { 0.07 }
    };
    // The first panel's top line holds the markers' labels, off the data.
    let marker_labels_here = frame.label_markers
        && frame
            .markers
            .iter()
            .any(|m| m.x >= x_range.start && m.x <= x_range.end);
    let above = room(marker_labels_here || peaks.iter().flatten().any(|p| p.1 >= 0.0));
    let below = room(peaks.iter().flatten().any(|p| p.1 < 0.0));
    let y_range = linear_range(y_lo, y_hi, 0.0);
    let y_range = {
        let total = (y_range.end - y_range.start) / (1.0 - above - below);
        (y_range.start - below * total)..(y_range.end + above * total)
    };
    let x_fmt = tick_formatter(x_range, false);
    let y_fmt = tick_formatter(&y_range, false);
    let right_margin = RIGHT_MARGIN + frame.legend_outside.unwrap_or(0);
    let mut chart = ChartBuilder::on(area)
        .margin(8)
        .margin_right(right_margin.max(0) as u32)
        .x_label_area_size(x_label_area as u32)
        .y_label_area_size(95)
        .build_cartesian_2d(x_range.clone(), y_range.clone())
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .x_desc(frame.x_label)
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
    let base = area.get_base_pixel();
    let plot = PixelBox::of_ranges(chart.plotting_area().get_pixel_range());
    let text_size = |text: &str, style: &TextStyle| {
        area.estimate_text_size(text, style)
            .map_or((8 * text.len() as i32, 18), |(w, h)| (w as i32, h as i32))
    };
    // Entry and exit lines under the data.
    let marker_style = RGBColor(120, 120, 120).stroke_width(1);
    // A vehicle that leaves as the record ends (no free vibration) still
    // gets its line, at the right edge (up to rounding of its exit time).
    let slack = 1e-9 * (x_range.end - x_range.start);
    let mut marker_layouts: Vec<MarkerLayout> = Vec::new();
    for m in frame
        .markers
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
        let at = chart.backend_coord(&(x, y_range.end));
        let mut label = None;
        if frame.label_markers {
            // Right of the line, or left of it near the right edge; a line
            // lower than a marker label it would overlap.
            let style = font(LABEL_SIZE - 2.0).color(&RGBColor(90, 90, 90));
            let (w, h) = text_size(&m.label, &style);
            let near_end = x > x_range.start + 0.9 * (x_range.end - x_range.start);
            let left = if near_end { at.0 - 3 - w } else { at.0 + 3 };
            let mut b = PixelBox {
                left,
                top: at.1 + 2,
                right: left + w,
                bottom: at.1 + 2 + h,
            };
            while marker_layouts
                .iter()
                .filter_map(|l| l.label)
                .any(|o| o.grown(1).intersects(&b))
            {
                b.top += h + 1;
                b.bottom += h + 1;
            }
            area.draw(&Text::new(
                m.label.clone(),
                (b.left - base.0, b.top - base.1),
                style,
            ))
            .map_err(draw_err)?;
            label = Some(b);
        }
        marker_layouts.push(MarkerLayout { x: at.0, label });
    }
    let colour = |k: usize| PALETTE[k % PALETTE.len()];
    let mut pixel_lines: Vec<Vec<(i32, i32)>> = Vec::new();
    for (r, line) in panel.references.iter().zip(&references) {
        // A lighter, dashed line in its series' colour: which static
        // response belongs to which record, when several share a panel.
        let style = colour(r.of).mix(0.55).stroke_width(2);
        chart
            .draw_series(DashedLineSeries::new(line.iter().copied(), 8, 5, style))
            .map_err(draw_err)?;
        pixel_lines.push(line.iter().map(|p| chart.backend_coord(p)).collect());
    }
    for (k, line) in lines.iter().enumerate() {
        let style = colour(k).stroke_width(2);
        // Each segment on its own: a 2-pixel polyline through a dense
        // record's min–max zigzag (one up-and-down a pixel column) gets
        // mitre joins at its acute corners, spikes far past the data (a
        // ±96 kN lateral contact force drawn reaching past ±190 kN, into the
        // neighbouring panels). Separate segments have no joins.
        chart
            .draw_series(
                line.windows(2)
                    .map(|pair| PathElement::new(vec![pair[0], pair[1]], style)),
            )
            .map_err(draw_err)?;
        if let [single] = line.as_slice() {
            chart
                .draw_series(std::iter::once(Circle::new(*single, 1, style.filled())))
                .map_err(draw_err)?;
        }
        pixel_lines.push(line.iter().map(|p| chart.backend_coord(p)).collect());
    }
    // Peaks over the lines: a ring, and `value unit at t` in free space
    // beside it.
    let mut occupancy = Occupancy::new(plot);
    for line in &pixel_lines {
        occupancy.mark_polyline(line, LINE_CLEARANCE);
    }
    let mut rings = Vec::new();
    for (k, p) in peaks.iter().enumerate() {
        if let Some((t, v)) = *p {
            chart
                .draw_series(std::iter::once(Circle::new(
                    (t, v),
                    5,
                    colour(k).stroke_width(2),
                )))
                .map_err(draw_err)?;
            let ring = chart.backend_coord(&(t, v));
            occupancy.mark_polyline(&[ring], RING_CLEARANCE);
            rings.push((k, ring, v));
        }
    }
    for b in marker_layouts.iter().filter_map(|m| m.label) {
        occupancy.mark_box(&b.grown(2));
    }
    occupancy.seal();
    let marker_columns: Vec<i32> = marker_layouts.iter().map(|m| m.x).collect();
    let label_style = font(LABEL_SIZE - 1.0);
    let mut placed: Vec<PixelBox> = Vec::new();
    let mut peak_layouts: Vec<PeakLayout> = Vec::new();
    // Peak labels that found no place: written in the legend instead.
    let mut in_legend: Vec<Option<String>> = vec![None; panel.series.len()];
    for &(k, ring, v) in &rings {
        let Some((t, _)) = peaks[k] else { continue };
        let text = peak_label(v, &panel.unit, t, frame.x_unit);
        let (w, h) = text_size(&text, &label_style);
        let label = place_label(
            &occupancy,
            &placed,
            &marker_columns,
            ring,
            (w + 2, h + 2),
            v >= 0.0,
        );
        match label {
            Some(b) => placed.push(b),
            None => in_legend[k] = Some(text.clone()),
        }
        peak_layouts.push(PeakLayout { text, ring, label });
    }
    // The legend: the series, then the static lines.
    let mut entries: Vec<(Sample, String)> = Vec::new();
    for (k, s) in panel.series.iter().enumerate() {
        let text = match (&in_legend[k], s.label.is_empty()) {
            (Some(peak), false) => format!("{}: peak {peak}", s.label),
            (Some(peak), true) => format!("peak {peak}"),
            (None, false) => s.label.to_string(),
            (None, true) => continue,
        };
        entries.push((Sample::Solid(colour(k)), text));
    }
    for r in panel.references.iter().filter(|r| !r.line.label.is_empty()) {
        entries.push((Sample::Dashed(colour(r.of)), r.line.label.to_string()));
    }
    let legend_style = font(LEGEND_SIZE - 2.0);
    let line_height = text_size("Ag", &legend_style).1 + 3;
    let text_width = entries
        .iter()
        .map(|(_, t)| text_size(t, &legend_style).0)
        .max()
        .unwrap_or(0);
    let legend_size = (
        text_width + LEGEND_SAMPLE + 2 * LEGEND_PAD,
        line_height * entries.len() as i32 + 2 * LEGEND_PAD,
    );
    let marker_labels: Vec<PixelBox> = marker_layouts.iter().filter_map(|m| m.label).collect();
    let avoid: Vec<PixelBox> = placed.iter().chain(&marker_labels).copied().collect();
    let (legend, legend_inside) = if entries.is_empty() {
        (None, true)
    } else if frame.legend_outside.is_some() {
        let left = plot.right + 12;
        let b = PixelBox {
            left,
            top: plot.top,
            right: left + legend_size.0,
            bottom: plot.top + legend_size.1,
        };
        (Some(b), false)
    } else {
        match place_legend(&occupancy, &avoid, &marker_columns, legend_size) {
            Some(b) => (Some(b), true),
            // No free place: the caller draws the chart again with the
            // legend outside; this drawing is only measured.
            None => (
                Some(PixelBox {
                    left: plot.right - 5 - legend_size.0,
                    top: plot.top + 5,
                    right: plot.right - 5,
                    bottom: plot.top + 5 + legend_size.1,
                }),
                false,
            ),
        }
    };
    if let Some(b) = legend {
        let rel = |(x, y): (i32, i32)| (x - base.0, y - base.1);
        area.draw(&Rectangle::new(
            [rel((b.left, b.top)), rel((b.right - 1, b.bottom - 1))],
            WHITE.filled(),
        ))
        .map_err(draw_err)?;
        area.draw(&Rectangle::new(
            [rel((b.left, b.top)), rel((b.right - 1, b.bottom - 1))],
            BLACK.stroke_width(1),
        ))
        .map_err(draw_err)?;
        for (i, (sample, text)) in entries.iter().enumerate() {
            let top = b.top + LEGEND_PAD + i as i32 * line_height;
            let mid = top + line_height / 2;
            let x0 = b.left + LEGEND_PAD;
            match *sample {
                Sample::Solid(c) => area
                    .draw(&PathElement::new(
                        vec![rel((x0, mid)), rel((x0 + 24, mid))],
                        c.stroke_width(2),
                    ))
                    .map_err(draw_err)?,
                Sample::Dashed(c) => {
                    for (a, z) in [(0, 10), (14, 24)] {
                        area.draw(&PathElement::new(
                            vec![rel((x0 + a, mid)), rel((x0 + z, mid))],
                            c.mix(0.55).stroke_width(2),
                        ))
                        .map_err(draw_err)?;
                    }
                }
            }
            area.draw(&Text::new(
                text.clone(),
                rel((x0 + LEGEND_SAMPLE, top + 1)),
                legend_style.clone(),
            ))
            .map_err(draw_err)?;
        }
    }
    // Labels last, each with a thin leader line when it had to go further
    // than beside its ring.
    for (p, &(k, _, _)) in peak_layouts.iter().zip(&rings) {
        let Some(b) = p.label else { continue };
        let c = colour(k);
        if b.distance_to(p.ring) > LEADER_DISTANCE {
            let to = b.nearest_to(p.ring);
            let (dx, dy) = (f64::from(to.0 - p.ring.0), f64::from(to.1 - p.ring.1));
            let n = dx.hypot(dy).max(1.0);
            let from = (
                p.ring.0 + (7.0 * dx / n).round() as i32,
                p.ring.1 + (7.0 * dy / n).round() as i32,
            );
            area.draw(&PathElement::new(
                vec![
                    (from.0 - base.0, from.1 - base.1),
                    (to.0 - base.0, to.1 - base.1),
                ],
                c.mix(0.7).stroke_width(1),
            ))
            .map_err(draw_err)?;
        }
        area.draw(&Text::new(
            p.text.clone(),
            (b.left + 1 - base.0, b.top + 1 - base.1),
            label_style.color(&c),
        ))
        .map_err(draw_err)?;
    }
    Ok(PanelLayout {
        plot,
        lines: pixel_lines,
        peaks: peak_layouts,
        markers: marker_layouts,
        legend,
        legend_inside,
        legend_entries: entries.into_iter().map(|(_, t)| t).collect(),
    })
}

/// The sample of largest |y| (the first of equals), as (x, y).
pub(super) fn peak(x: &[f64], y: &[f64]) -> Option<(f64, f64)> {
    x.iter()
        .zip(y)
        .filter(|&(&a, &b)| usable(a) && usable(b))
        .fold(None, |best: Option<(f64, f64)>, (&a, &b)| match best {
            Some((_, v)) if v.abs() >= b.abs() => best,
            _ => Some((a, b)),
        })
}

/// A peak's label: the value to 4 significant digits with its unit, and
/// where, its abscissa to 3 decimals in `x_unit` (`-5.772×10⁻⁴ m at 1.100 s`).
pub(super) fn peak_label(value: f64, unit: &str, time: f64, x_unit: &str) -> String {
    let magnitude = value.abs();
    let value = if magnitude == 0.0 || (1e-2..1e5).contains(&magnitude) {
        let decimals = (3 - magnitude.log10().floor() as i32).clamp(0, 6) as usize;
        format!("{value:.decimals$}")
    } else {
        pow10_digits(value, 4)
    };
    let value = value.replacen('-', "−", 1);
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    let x_unit = if x_unit.is_empty() {
        String::new()
    } else {
        format!(" {x_unit}")
    };
    format!("{value}{unit} at {time:.3}{x_unit}")
}
