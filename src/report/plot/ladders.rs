//! Side-by-side panels of one error axis: the convergence chart of `vbi
//! converge` (issue 28 point 7), where each ladder gets its own abscissa
//! (time step, modes kept) so that neither is squashed into a stroke.

use super::*;

/// Canvas of [`ladder_chart`], pixels: two panels side by side.
const LADDER_WIDTH: u32 = 1400;

/// One panel of a [`ladder_chart`].
#[derive(Debug, Clone)]
pub struct LadderPanel<'a> {
    /// Panel heading, e.g. `time-step ladder (8 modes)`.
    pub title: &'a str,
    /// Abscissa label with its unit.
    pub x_label: &'a str,
    /// Logarithmic abscissa; a linear one is labelled at whole numbers only.
    pub log_x: bool,
    /// Solid lines with a dot at each point, in the palette's colours.
    pub series: Vec<Series<'a>>,
    /// Dashed lines with a square at each point, after the solid ones in
    /// the palette.
    pub dashed: Vec<Series<'a>>,
    /// The chosen point on this panel, if any, and its label.
    pub chosen: Option<(f64, f64, &'a str)>,
}

/// Panels side by side sharing a logarithmic ordinate, a dashed black
/// horizontal line at `limit` (labelled `limit_label`) on each, and the
/// chosen point circled in red with its label.
pub fn ladder_chart(
    path: &Path,
    title: &str,
    y_label: &str,
    panels: &[LadderPanel],
    limit: f64,
    limit_label: &str,
) -> Result<(), PlotError> {
    if panels.is_empty() {
        return Err(PlotError::InvalidInput("no panels".into()));
    }
    for s in panels.iter().flat_map(|p| p.series.iter().chain(&p.dashed)) {
        if s.x.len() != s.y.len() {
            return Err(PlotError::InvalidInput(format!(
                "series '{}': x has {} points but y has {}",
                s.label,
                s.x.len(),
                s.y.len()
            )));
        }
    }
    let ys = panels
        .iter()
        .flat_map(|p| p.series.iter().chain(&p.dashed))
        .flat_map(|s| s.y.iter().copied())
        .chain(std::iter::once(limit))
        .filter(|&y| usable_log(y));
    let (y_lo, y_hi) = min_max(ys);
    let y_range = log_range(y_lo, y_hi);
    let rendered = render_sized(LADDER_WIDTH, HEIGHT, |root| {
        let area = with_title(root, title)?;
        let columns = area.split_evenly((1, panels.len()));
        for (column, panel) in columns.iter().zip(panels) {
            let ok_x = |x: f64| {
                if panel.log_x {
                    usable_log(x)
                } else {
                    usable(x)
                }
            };
            let xs = panel
                .series
                .iter()
                .chain(&panel.dashed)
                .flat_map(|s| s.x.iter().copied())
                .filter(|&x| ok_x(x));
            let (x_lo, x_hi) = min_max(xs);
            let y = LogCoord::from(y_range.clone().log_scale());
            if panel.log_x {
                // A little beyond the points rather than whole decades: a
                // ladder of factors of 2 spans about one decade.
                let range = if usable_log(x_lo) && x_hi >= x_lo {
                    (x_lo / 1.5)..(x_hi * 1.5)
                } else {
                    log_range(x_lo, x_hi)
                };
                let x = LogCoord::from(range.log_scale());
                draw_panel(column, x, y, panel, y_label, limit, limit_label)?;
            } else {
                // Whole numbers (mode counts) from 0, with room to the right.
                let hi = if x_hi.is_finite() { x_hi.max(1.0) } else { 1.0 };
                let x = RangedCoordf64::from(0.0..(hi * 1.08).ceil());
                draw_panel(column, x, y, panel, y_label, limit, limit_label)?;
            }
        }
        Ok(Geometry::default())
    })?;
    let bytes = encode_png_sized(&rendered.rgb, LADDER_WIDTH, HEIGHT)?;
    write_atomic(path, &bytes)
}

fn draw_panel<X>(
    area: &Area<'_>,
    x_coord: X,
    y_coord: LogCoord<f64>,
    panel: &LadderPanel,
    y_label: &str,
    limit: f64,
    limit_label: &str,
) -> Result<(), PlotError>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let x_range = x_coord.range();
    let x_fmt = tick_formatter(&x_range, panel.log_x);
    let whole = |v: &f64| {
        if (v - v.round()).abs() < 1e-9 {
            fixed(*v, 0)
        } else {
            String::new()
        }
    };
    let y_fmt = tick_formatter(&y_coord.range(), true);
    let area = area
        .titled(panel.title, font(DESC_SIZE))
        .map_err(draw_err)?;
    let mut chart = ChartBuilder::on(&area)
        .margin(15)
        .margin_right(25)
        .x_label_area_size(60)
        .y_label_area_size(95)
        .build_cartesian_2d(x_coord, y_coord)
        .map_err(draw_err)?;
    let x_labels = if panel.log_x {
        10
    } else {
        // One label a whole number while they fit.
        ((x_range.end - x_range.start) as usize + 1).min(11)
    };
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(panel.x_label)
        .y_desc(y_label)
        .x_labels(x_labels)
        .y_labels(10)
        .y_label_formatter(&y_fmt)
        .label_style(font(LABEL_SIZE))
        .axis_desc_style(font(DESC_SIZE))
        .bold_line_style(RGBColor(200, 200, 200).stroke_width(1))
        .light_line_style(RGBColor(235, 235, 235).stroke_width(1));
    if panel.log_x {
        mesh.x_label_formatter(&x_fmt);
    } else {
        mesh.x_label_formatter(&whole);
    }
    mesh.draw().map_err(draw_err)?;

    let usable_point = |&(x, y): &(f64, f64)| {
        (if panel.log_x {
            usable_log(x)
        } else {
            usable(x)
        }) && usable_log(y)
    };
    let mut all_runs: Vec<Vec<Vec<(f64, f64)>>> = Vec::new();
    let mut legend: Vec<Series> = Vec::new();
    let lines = panel.series.iter().map(|s| (s, false));
    let dashed = panel.dashed.iter().map(|s| (s, true));
    for (k, (s, is_dashed)) in lines.chain(dashed).enumerate() {
        let colour = PALETTE[k % PALETTE.len()];
        let style = colour.stroke_width(2);
        let points: Vec<(f64, f64)> =
            s.x.iter()
                .copied()
                .zip(s.y.iter().copied())
                .filter(usable_point)
                .collect();
        if !s.label.is_empty() {
            let entry = chart
                .draw_series(LineSeries::new(std::iter::empty(), style))
                .map_err(draw_err)?
                .label(s.label);
            if is_dashed {
                entry.legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (8, 0)], style)
                        + PathElement::new(vec![(14, 0), (22, 0)], style)
                        + Rectangle::new([(8, -3), (14, 3)], colour.filled())
                });
            } else {
                entry.legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (22, 0)], style)
                        + Circle::new((11, 0), 4, colour.filled())
                });
            }
            legend.push(*s);
        }
        if is_dashed {
            chart
                .draw_series(DashedLineSeries::new(points.iter().copied(), 8, 5, style))
                .map_err(draw_err)?;
            chart
                .draw_series(points.iter().map(|&p| {
                    EmptyElement::at(p) + Rectangle::new([(-4, -4), (4, 4)], colour.filled())
                }))
                .map_err(draw_err)?;
        } else {
            chart
                .draw_series(LineSeries::new(points.iter().copied(), style))
                .map_err(draw_err)?;
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 4, colour.filled())))
                .map_err(draw_err)?;
        }
        all_runs.push(vec![points]);
    }
    // The limit across the panel, dashed black.
    let limit_style = BLACK.stroke_width(2);
    let across = vec![(x_range.start, limit), (x_range.end, limit)];
    if usable_log(limit) {
        chart
            .draw_series(DashedLineSeries::new(
                across.iter().copied(),
                10,
                6,
                limit_style,
            ))
            .map_err(draw_err)?
            .label(limit_label)
            .legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (10, 0)], limit_style)
                    + PathElement::new(vec![(14, 0), (24, 0)], limit_style)
            });
        legend.push(Series {
            label: limit_label,
            x: &[],
            y: &[],
        });
        all_runs.push(vec![across]);
    }
    if let Some((x, y, label)) = panel.chosen
        && usable_point(&(x, y))
    {
        // Ring and label; the label on the side with room, below the ring
        // in the upper half (where the tolerance line usually is), else above.
        let (px, py) = chart.backend_coord(&(x, y));
        let (xs, ys) = area.get_pixel_range();
        let (left, right) = (xs.start, xs.end);
        let upper = py - ys.start < ys.end - py;
        let to_left = px - left > right - px;
        let h = if to_left { HPos::Right } else { HPos::Left };
        let v = if upper { VPos::Top } else { VPos::Bottom };
        let anchor = Pos::new(h, v);
        let dx = if to_left { -12 } else { 12 };
        let dy = if upper { 12 } else { -12 };
        let red = RGBColor(220, 0, 0);
        chart
            .draw_series(std::iter::once(
                EmptyElement::at((x, y))
                    + Circle::new((0, 0), 10, red.stroke_width(3))
                    + Text::new(
                        label.to_string(),
                        (dx, dy),
                        font(LEGEND_SIZE).color(&red).pos(anchor),
                    ),
            ))
            .map_err(draw_err)?;
    }
    if !legend.is_empty() {
        let position = legend_position(&chart, &legend, &all_runs)?;
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
    Ok(())
}
