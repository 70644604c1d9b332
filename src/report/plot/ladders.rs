//! Side-by-side panels of one error axis: the convergence chart of `vbi
//! converge` (issue 28 point 7), where each ladder gets its own abscissa
//! (time step, modes kept) so that neither is squashed into a stroke.

use super::layout::{LEADER_DISTANCE, LINE_CLEARANCE, Occupancy, PixelBox, place_label};
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
    let (rgb, _) = render_ladder(title, y_label, panels, limit, limit_label)?;
    let bytes = encode_png_sized(&rgb, LADDER_WIDTH, HEIGHT)?;
    write_atomic(path, &bytes)
}

/// Where one panel of a [`ladder_chart`] put its plotting area and its
/// abscissa's tick labels (image pixels).
#[derive(Debug, Clone, Default)]
pub struct LadderPanelLayout {
    /// The plotting area.
    pub plot: PixelBox,
    /// Each abscissa tick label and its box, left to right.
    pub x_ticks: Vec<(String, PixelBox)>,
    /// Every drawn line (the ladders and the limit) in pixels.
    pub lines: Vec<Vec<(i32, i32)>>,
    /// The chosen run's label, where it was put (off every line).
    pub chosen_label: Option<PixelBox>,
}

/// Where [`ladder_chart`] puts each panel's parts, without writing it.
pub fn ladder_layout(
    title: &str,
    y_label: &str,
    panels: &[LadderPanel],
    limit: f64,
    limit_label: &str,
) -> Result<(u32, u32, Vec<LadderPanelLayout>), PlotError> {
    let (_, layouts) = render_ladder(title, y_label, panels, limit, limit_label)?;
    Ok((LADDER_WIDTH, HEIGHT, layouts))
}

fn render_ladder(
    title: &str,
    y_label: &str,
    panels: &[LadderPanel],
    limit: f64,
    limit_label: &str,
) -> Result<(Vec<u8>, Vec<LadderPanelLayout>), PlotError> {
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
    let mut layouts = Vec::new();
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
                // Ticks a label each, as many as fit apart (issue 40.7: a
                // decade's 2×10⁻³ … 6×10⁻³ ran into each other).
                let width = column.dim_in_pixel().0 as i32 - PANEL_SIDES;
                let measure = |text: &str| {
                    column
                        .estimate_text_size(text, &font(LABEL_SIZE))
                        .map_or(10 * text.len() as i32, |(w, _)| w as i32)
                };
                let x = TickedLog::new(range, width, &measure);
                layouts.push(draw_panel(
                    column,
                    x,
                    y,
                    panel,
                    y_label,
                    limit,
                    limit_label,
                )?);
            } else {
                // Whole numbers (mode counts) from 0, with room to the right.
                let hi = if x_hi.is_finite() { x_hi.max(1.0) } else { 1.0 };
                let x = RangedCoordf64::from(0.0..(hi * 1.08).ceil());
                layouts.push(draw_panel(
                    column,
                    x,
                    y,
                    panel,
                    y_label,
                    limit,
                    limit_label,
                )?);
            }
        }
        Ok(Geometry::default())
    })?;
    Ok((rendered.rgb, layouts))
}

/// Columns of a panel outside its plotting area: the margins (15 left,
/// 25 right) and the ordinate's label area (95).
const PANEL_SIDES: i32 = 15 + 25 + 95;
/// Least blank space between two abscissa tick labels, pixels.
const TICK_GAP: i32 = 14;

/// A logarithmic abscissa labelled at round values (`1e-3`, `2e-3`,
/// `5e-3`) no closer than [`TICK_GAP`] apart, grid lines at every
/// 1…9 × 10ᵉ between them.
pub(super) struct TickedLog {
    coord: LogCoord<f64>,
    ticks: Vec<(f64, String)>,
    grid: Vec<f64>,
}

impl TickedLog {
    /// For an axis `width` pixels long whose label `text` is `measure(text)` wide.
    pub(super) fn new(range: Range<f64>, width: i32, measure: &dyn Fn(&str) -> i32) -> Self {
        let (lo, hi) = (range.start.min(range.end), range.start.max(range.end));
        let at = |m: u32, e: i32| f64::from(m) * 10f64.powi(e);
        let decades = (lo.log10().floor() as i32)..=(hi.log10().ceil() as i32);
        let inside = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
        // One notation along the axis: `5e-3` beside `1e-2`, not `0.01`.
        let scientific = *decades.start() < -2 || *decades.end() > 3;
        let values = |mantissas: &[u32], every: i32| -> Vec<(f64, String)> {
            decades
                .clone()
                .filter(|e| e.rem_euclid(every) == 0)
                .flat_map(|e| mantissas.iter().map(move |&m| (m, e)))
                .filter(|&(m, e)| inside(at(m, e)))
                .map(|(m, e)| (at(m, e), log_tick_label(m, e, scientific)))
                .collect()
        };
        let grid = values(&[1, 2, 3, 4, 5, 6, 7, 8, 9], 1)
            .into_iter()
            .map(|(v, _)| v)
            .collect();
        let span = (hi / lo).ln().max(f64::MIN_POSITIVE);
        let pixel = |v: f64| f64::from(width) * (v / lo).ln() / span;
        let fits = |ticks: &[(f64, String)]| {
            ticks.windows(2).all(|pair| {
                let half = |(v, t): &(f64, String)| (pixel(*v), f64::from(measure(t)) / 2.0);
                let ((a, wa), (b, wb)) = (half(&pair[0]), half(&pair[1]));
                b - wb - (a + wa) >= f64::from(TICK_GAP)
            })
        };
        let choices: Vec<Vec<(f64, String)>> = vec![
            values(&[1, 2, 3, 4, 5, 6, 7, 8, 9], 1),
            values(&[1, 2, 3, 5], 1),
            values(&[1, 2, 5], 1),
            values(&[1, 5], 1),
            values(&[1], 1),
            values(&[1], 2),
            values(&[1], 5),
        ];
        // The densest that fits with two ticks or more; else the sparsest.
        let ticks = choices
            .iter()
            .find(|t| t.len() >= 2 && fits(t))
            .or_else(|| choices.iter().rev().find(|t| fits(t)))
            .cloned()
            .unwrap_or_default();
        TickedLog {
            coord: LogCoord::from(range.log_scale()),
            ticks,
            grid,
        }
    }
}

/// `m × 10ᵉ` as a tick reads: `5e-5`, `1e-4`, `2e0` when `scientific`,
/// else `0.02`, `3`, `200`.
pub(super) fn log_tick_label(m: u32, e: i32, scientific: bool) -> String {
    if !scientific {
        fixed(f64::from(m) * 10f64.powi(e), 2)
    } else {
        format!("{m}e{e}")
    }
}

impl Ranged for TickedLog {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.coord.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.grid.clone()
        } else {
            self.ticks.iter().map(|(v, _)| *v).collect()
        }
    }

    fn range(&self) -> Range<f64> {
        self.coord.range()
    }
}

/// The abscissa's ticks of a panel: (value, label).
pub(super) trait XTicks {
    fn x_ticks(&self) -> Vec<(f64, String)>;
}

impl XTicks for TickedLog {
    fn x_ticks(&self) -> Vec<(f64, String)> {
        self.ticks.clone()
    }
}

impl XTicks for RangedCoordf64 {
    fn x_ticks(&self) -> Vec<(f64, String)> {
        Vec::new()
    }
}

fn draw_panel<X>(
    area: &Area<'_>,
    x_coord: X,
    y_coord: LogCoord<f64>,
    panel: &LadderPanel,
    y_label: &str,
    limit: f64,
    limit_label: &str,
) -> Result<LadderPanelLayout, PlotError>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64> + XTicks,
{
    let x_range = x_coord.range();
    let ticks = x_coord.x_ticks();
    let x_fmt = |v: &f64| {
        ticks
            .iter()
            .find(|(t, _)| (t - v).abs() <= 1e-9 * t.abs())
            .map(|(_, s)| s.clone())
            .unwrap_or_default()
    };
    let whole = |v: &f64| {
        if (v - v.round()).abs() < 1e-9 {
            fixed(*v, 0)
        } else {
            String::new()
        }
    };
    let y_fmt = tick_formatter(&y_coord.range(), true);
    let y_start = y_coord.range().start;
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
    let plot = PixelBox::of_ranges(chart.plotting_area().get_pixel_range());
    let lines: Vec<Vec<(i32, i32)>> = all_runs
        .iter()
        .flatten()
        .map(|run| run.iter().map(|p| chart.backend_coord(p)).collect())
        .collect();
    let mut chosen_label = None;
    if let Some((x, y, label)) = panel.chosen
        && usable_point(&(x, y))
    {
        // Ring and label; the label in the free place nearest the ring,
        // off every line (as a history's peak labels), else beside it on
        // the side with room.
        let (px, py) = chart.backend_coord(&(x, y));
        let (w, h) = area
            .estimate_text_size(label, &font(LEGEND_SIZE))
            .map_or((0, 0), |(w, h)| (w as i32, h as i32));
        let mut occupancy = Occupancy::new(plot);
        for line in &lines {
            occupancy.mark_polyline(line, LINE_CLEARANCE);
        }
        occupancy.mark_polyline(&[(px, py)], 14);
        occupancy.seal();
        let upper = py - plot.top < plot.bottom - py;
        let red = RGBColor(220, 0, 0);
        let ring = EmptyElement::at((x, y)) + Circle::new((0, 0), 10, red.stroke_width(3));
        chart.draw_series(std::iter::once(ring)).map_err(draw_err)?;
        let style = font(LEGEND_SIZE)
            .color(&red)
            .pos(Pos::new(HPos::Left, VPos::Top));
        // The panel's area draws in its own coordinates; the layout's are
        // the image's.
        let base = area.get_base_pixel();
        let local = |(x, y): (i32, i32)| (x - base.0, y - base.1);
        match place_label(&occupancy, &[], &[], (px, py), (w, h), !upper) {
            Some(b) => {
                if b.distance_to((px, py)) > LEADER_DISTANCE {
                    let end = b.nearest_to((px, py));
                    area.draw(&PathElement::new(
                        vec![local((px, py)), local(end)],
                        red.stroke_width(1),
                    ))
                    .map_err(draw_err)?;
                }
                area.draw(&Text::new(label.to_string(), local((b.left, b.top)), style))
                    .map_err(draw_err)?;
                chosen_label = Some(b);
            }
            None => {
                let to_left = px - plot.left > plot.right - px;
                let left = if to_left { px - 12 - w } else { px + 12 };
                let top = if upper { py + 12 } else { py - 12 - h };
                area.draw(&Text::new(label.to_string(), local((left, top)), style))
                    .map_err(draw_err)?;
                chosen_label = Some(PixelBox {
                    left,
                    top,
                    right: left + w,
                    bottom: top + h,
                });
            }
        }
    }
    // Each tick label centred under its tick (as the mesh draws it).
    let x_ticks = ticks
        .iter()
        .map(|(v, text)| {
            let x = chart.backend_coord(&(*v, y_start)).0;
            let (w, h) = area
                .estimate_text_size(text, &font(LABEL_SIZE))
                .map_or((0, 0), |(w, h)| (w as i32, h as i32));
            let top = plot.bottom + 5;
            let b = PixelBox {
                left: x - w / 2,
                top,
                right: x - w / 2 + w,
                bottom: top + h,
            };
            (text.clone(), b)
        })
        .collect();
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
    Ok(LadderPanelLayout {
        plot,
        x_ticks,
        lines,
        chosen_label,
    })
}
