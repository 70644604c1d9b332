//! Maps on a regular (possibly non-uniform) grid: binary maps and heat maps with a colour bar.

use super::*;
/// One axis of a map grid.
pub(super) struct GridAxis {
    /// `n + 1` cell edges (same order as the values).
    edges: Vec<f64>,
    range: Range<f64>,
    pub(super) ticks: Vec<f64>,
    /// Names of the grid values (a categorical axis): tick `k` reads `labels[k]`.
    pub(super) labels: Option<Vec<String>>,
}

/// A categorical axis: cells at 0, 1, …, one per name, each tick its name.
pub(super) fn category_axis(names: &[String]) -> Result<GridAxis, PlotError> {
    let values: Vec<f64> = (0..names.len()).map(|k| k as f64).collect();
    let mut axis = grid_axis("categories", &values)?;
    axis.ticks = values;
    axis.labels = Some(names.to_vec());
    Ok(axis)
}

pub(super) fn grid_axis(name: &str, values: &[f64]) -> Result<GridAxis, PlotError> {
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
        labels: None,
    })
}

/// A linear axis whose ticks are given explicitly (the grid values when few).
pub(super) struct GridCoord {
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

pub(super) fn check_grid_len(
    what: &str,
    len: usize,
    nx: usize,
    ny: usize,
) -> Result<(), PlotError> {
    match nx.checked_mul(ny) {
        Some(n) if n == len => Ok(()),
        _ => Err(PlotError::InvalidInput(format!(
            "{what} has {len} entries but the grid is {nx} × {ny}"
        ))),
    }
}

/// Sets up a map chart (axes, ticks at grid values) on `area`, draws `cell_colour`
/// for every cell that has one, and frames the grid.
pub(super) fn draw_grid_chart(
    area: &Area<'_>,
    x_label: &str,
    y_label: &str,
    xa: &GridAxis,
    ya: &GridAxis,
    cell_colour: impl Fn(usize, usize) -> Option<RGBColor>,
) -> Result<Geometry, PlotError> {
    let x_fmt = tick_formatter(&xa.range, false);
    let y_numbers = tick_formatter(&ya.range, false);
    let y_fmt = |v: &f64| match &ya.labels {
        Some(labels) => labels
            .get(v.round().max(0.0) as usize)
            .cloned()
            .unwrap_or_default(),
        None => y_numbers(v),
    };
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
pub(super) fn render_binary_map(
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
pub(super) fn draw_swatch_legend(
    area: &Area<'_>,
    entries: &[(&str, RGBColor)],
) -> Result<(), PlotError> {
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

pub(super) fn render_heat_map(
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    y_values: &[f64],
    values: &[f64],
    value_label: &str,
) -> Result<Rendered, PlotError> {
    check_grid_len("values", values.len(), x_values.len(), y_values.len())?;
    let xa = grid_axis("x_values", x_values)?;
    let ya = grid_axis("y_values", y_values)?;
    render_heat_map_on(title, x_label, y_label, &xa, &ya, values, value_label)
}

/// [`render_heat_map`] with its y axis the names `categories`.
#[allow(clippy::too_many_arguments)]
pub(super) fn render_category_heat_map(
    title: &str,
    x_label: &str,
    y_label: &str,
    x_values: &[f64],
    categories: &[String],
    values: &[f64],
    value_label: &str,
) -> Result<Rendered, PlotError> {
    check_grid_len("values", values.len(), x_values.len(), categories.len())?;
    let xa = grid_axis("x_values", x_values)?;
    let ya = category_axis(categories)?;
    render_heat_map_on(title, x_label, y_label, &xa, &ya, values, value_label)
}

fn render_heat_map_on(
    title: &str,
    x_label: &str,
    y_label: &str,
    xa: &GridAxis,
    ya: &GridAxis,
    values: &[f64],
    value_label: &str,
) -> Result<Rendered, PlotError> {
    const BAR_PANEL: u32 = 150;
    let ny = ya.edges.len().saturating_sub(1);
    let (lo, hi) = min_max(values.iter().copied().filter(|v| usable(*v)));
    let v_range = linear_range(lo, hi, 0.0);
    let colour_of = |v: f64| {
        let t = (v - v_range.start) / (v_range.end - v_range.start);
        viridis(t)
    };
    render(|root| {
        let area = with_title(root, title)?;
        let (main, bar) = area.split_horizontally(WIDTH - BAR_PANEL);
        let geometry = draw_grid_chart(&main, x_label, y_label, xa, ya, |i, j| {
            let v = values[i * ny + j];
            usable(v).then(|| colour_of(v))
        })?;
        draw_colour_bar(&bar, &v_range, value_label, colour_of)?;
        Ok(geometry)
    })
}

pub(super) fn draw_colour_bar(
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
