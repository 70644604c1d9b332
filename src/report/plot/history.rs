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
    for (k, (panel, area)) in panels.iter().zip(&rows).enumerate() {
        let last = k + 1 == panels.len();
        let x_label = if last { x_label } else { "" };
        draw_panel(area, panel, x_range, x_label, &x_unit, markers, k == 0)?;
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
    x_unit: &str,
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
        .map(|r| reduce(r.line.x, r.line.y, buckets))
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
    let colour = |k: usize| PALETTE[k % PALETTE.len()];
    for (r, line) in panel.references.iter().zip(&references) {
        // A lighter, dashed line in its series' colour: which static
        // response belongs to which record, when several share a panel.
        let style = colour(r.of).mix(0.55).stroke_width(2);
        chart
            .draw_series(DashedLineSeries::new(line.iter().copied(), 8, 5, style))
            .map_err(draw_err)?;
        if !r.line.label.is_empty() {
            chart
                .draw_series(LineSeries::new(std::iter::empty(), style))
                .map_err(draw_err)?
                .label(r.line.label)
                .legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (10, 0)], style)
                        + PathElement::new(vec![(14, 0), (24, 0)], style)
                });
        }
    }
    for (k, (s, line)) in panel.series.iter().zip(&lines).enumerate() {
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
        chart
            .draw_series(LineSeries::new(std::iter::empty(), style))
            .map_err(draw_err)?
            .label(s.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
    }
    // Peaks over the lines: a ring and `value unit at t` beside it.
    let base = area.get_base_pixel();
    let (px_x, px_y) = chart.plotting_area().get_pixel_range();
    let step = (LABEL_SIZE as i32) + 2;
    // The marker labels take the first line of the first panel.
    let top = px_y.start + 2 + if label_markers { step } else { 0 };
    let mut labels = Vec::new();
    for (k, s) in panel.series.iter().enumerate() {
        let Some((t, v)) = peak(s.x, s.y) else {
            continue;
        };
        let c = colour(k);
        chart
            .draw_series(std::iter::once(Circle::new((t, v), 5, c.stroke_width(2))))
            .map_err(draw_err)?;
        let at = chart.backend_coord(&(t, v));
        // Right of the ring, or left of it in the right third; above a
        // maximum and below a minimum (away from the line), one line
        // further per series so that neighbouring peaks' labels do not
        // sit on each other; inside the plotting area.
        let right_third = at.0 > px_x.start + 2 * (px_x.end - px_x.start) / 3;
        let text = peak_label(v, &panel.unit, t, x_unit);
        let width = area
            .estimate_text_size(&text, &font(LABEL_SIZE - 1.0))
            .map_or(200, |(w, _)| w as i32);
        let left = if right_third {
            at.0 - 9 - width
        } else {
            at.0 + 9
        };
        let dy = if v >= 0.0 {
            -step - step * k as i32
        } else {
            4 + step * k as i32
        };
        let y = (at.1 + dy).clamp(top, (px_y.end - step).max(top));
        labels.push((text, k, (left, y), width));
    }
    let labelled: Vec<Series> = panel
        .series
        .iter()
        .chain(panel.references.iter().map(|r| &r.line))
        .copied()
        .collect();
    if labelled.iter().any(|s| !s.label.is_empty()) {
        // The legend avoids the lines and the peak labels (each label's
        // outline, in data coordinates, counts as a line).
        let to_data = |(px, py): (i32, i32)| {
            let fx = f64::from(px - px_x.start) / f64::from((px_x.end - px_x.start).max(1));
            let fy = f64::from(py - px_y.start) / f64::from((px_y.end - px_y.start).max(1));
            (
                x_range.start + fx * (x_range.end - x_range.start),
                y_range.end - fy * (y_range.end - y_range.start),
            )
        };
        let runs: Vec<Vec<Vec<(f64, f64)>>> = lines
            .iter()
            .chain(&references)
            .map(|l| vec![l.clone()])
            .chain(labels.iter().map(|(_, _, (x, y), w)| {
                let corners = [
                    (*x, *y),
                    (x + w, *y),
                    (x + w, y + step),
                    (*x, y + step),
                    (*x, *y),
                ];
                vec![corners.into_iter().map(to_data).collect()]
            }))
            .collect();
        let position = legend_position(&chart, &labelled, &runs)?;
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
    // Labels last: over the legend box if it could go nowhere else.
    for (text, k, (x, y), _) in labels {
        let c = colour(k);
        let style = font(LABEL_SIZE - 1.0).color(&c);
        area.draw(&Text::new(text, (x - base.0, y - base.1), style))
            .map_err(draw_err)?;
    }
    Ok(())
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
