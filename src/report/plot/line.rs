//! Line charts: series, axes (linear or logarithmic), legend placement.

use super::*;

/// Series with at most this many points get a dot at each.
const MAX_MARKED_POINTS: usize = 60;

/// One series' band as runs of consecutive usable abscissae, each point
/// (x, low, high).
pub(super) type BandRuns = Vec<Vec<(f64, f64, f64)>>;

/// Opacity of a band's fill ([`Band`]): several overlapping bands stay
/// readable.
const BAND_OPACITY: f64 = 0.12;

#[allow(clippy::too_many_arguments)]
pub(super) fn render_line_chart(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    log_x: bool,
    log_y: bool,
    grey: usize,
    reference: usize,
    bands: &[Option<Band>],
) -> Result<Rendered, PlotError> {
    for (s, band) in series.iter().zip(bands) {
        if let Some(b) = band
            && (b.low.len() != s.x.len() || b.high.len() != s.x.len())
        {
            return Err(PlotError::InvalidInput(format!(
                "series '{}': {} points but its band has {} lower and {} upper ends",
                s.label,
                s.x.len(),
                b.low.len(),
                b.high.len()
            )));
        }
    }
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
            // A long run (a Monte Carlo envelope at every step) is drawn
            // as the minimum and maximum of each pixel column: every peak
            // kept, and no thousands of sub-pixel steep segments, which the
            // bitmap backend drew as broken dashes (issue 28.7).
            for run in runs.iter_mut().filter(|r| r.len() > 4 * WIDTH as usize) {
                let (x, y): (Vec<f64>, Vec<f64>) = run.iter().copied().unzip();
                *run = super::history::reduce(&x, &y, WIDTH as usize);
            }
            runs
        })
        .collect();
    // Per band, runs of consecutive abscissae where the series' x and both
    // ends are usable: (x, low, high).
    let band_runs: Vec<BandRuns> = series
        .iter()
        .zip(bands.iter().chain(std::iter::repeat(&None)))
        .map(|(s, band)| {
            let Some(b) = band else { return Vec::new() };
            let mut runs = Vec::new();
            let mut cur = Vec::new();
            for ((&x, &lo), &hi) in s.x.iter().zip(b.low).zip(b.high) {
                if ok_x(x) && ok_y(lo) && ok_y(hi) {
                    cur.push((x, lo, hi));
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
    let band_points = band_runs
        .iter()
        .flatten()
        .flatten()
        .flat_map(|&(x, lo, hi)| [(x, lo), (x, hi)]);
    let points = runs.iter().flatten().flatten().copied().chain(band_points);
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
        reference,
    };
    render(|root| match (log_x, log_y) {
        (false, false) => draw_line_chart(
            root,
            RangedCoordf64::from(x_range.clone()),
            RangedCoordf64::from(y_range.clone()),
            &labels,
            series,
            &runs,
            &band_runs,
            grey,
        ),
        (true, false) => draw_line_chart(
            root,
            LogCoord::from(x_range.clone().log_scale()),
            RangedCoordf64::from(y_range.clone()),
            &labels,
            series,
            &runs,
            &band_runs,
            grey,
        ),
        (false, true) => draw_line_chart(
            root,
            RangedCoordf64::from(x_range.clone()),
            LogCoord::from(y_range.clone().log_scale()),
            &labels,
            series,
            &runs,
            &band_runs,
            grey,
        ),
        (true, true) => draw_line_chart(
            root,
            LogCoord::from(x_range.clone().log_scale()),
            LogCoord::from(y_range.clone().log_scale()),
            &labels,
            series,
            &runs,
            &band_runs,
            grey,
        ),
    })
}

pub(super) struct LineChartText<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    log_x: bool,
    log_y: bool,
    /// The last `reference` series are reference lines (a limit): black,
    /// dashed, no markers.
    reference: usize,
}

#[allow(clippy::too_many_arguments)]
pub(super) fn draw_line_chart<X, Y>(
    root: &Area<'_>,
    x_coord: X,
    y_coord: Y,
    text: &LineChartText,
    series: &[Series],
    runs: &[Vec<Vec<(f64, f64)>>],
    band_runs: &[BandRuns],
    grey: usize,
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

    // Bands first, under every line: each series' interval as a
    // translucent polygon (lower ends forward, upper ends back) per run, in
    // the series' colour (the palette from its start, as the lines).
    for (k, runs) in band_runs.iter().enumerate() {
        let colour = PALETTE[k.saturating_sub(grey) % PALETTE.len()];
        for run in runs {
            let outline: Vec<(f64, f64)> = run
                .iter()
                .map(|&(x, lo, _)| (x, lo))
                .chain(run.iter().rev().map(|&(x, _, hi)| (x, hi)))
                .collect();
            chart
                .draw_series(std::iter::once(Polygon::new(
                    outline.clone(),
                    colour.mix(BAND_OPACITY).filled(),
                )))
                .map_err(draw_err)?;
            // A band of one abscissa (or of zero width) has no area: its
            // outline, 1 px, shows it.
            chart
                .draw_series(std::iter::once(PathElement::new(
                    outline,
                    colour.mix(0.5).stroke_width(1),
                )))
                .map_err(draw_err)?;
        }
    }
    let mut any_label = false;
    for (k, (s, runs)) in series.iter().zip(runs).enumerate() {
        // The first `grey` series are background samples (thin, grey, no
        // markers); the others take the palette from its start.
        let background = k < grey;
        let is_reference = k + text.reference >= series.len();
        let colour = if background {
            GREY_LINE
        } else if is_reference {
            BLACK
        } else {
            PALETTE[(k - grey) % PALETTE.len()]
        };
        let style = colour.stroke_width(if background { 1 } else { 2 });
        if !s.label.is_empty() {
            any_label = true;
            // An empty series carries the legend entry, so that series without any
            // valid point still appear in the legend.
            let entry = chart
                .draw_series(LineSeries::new(std::iter::empty(), style))
                .map_err(draw_err)?
                .label(s.label);
            if is_reference {
                // Two dashes, as the line is drawn.
                entry.legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (10, 0)], style)
                        + PathElement::new(vec![(14, 0), (24, 0)], style)
                });
            } else {
                entry.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            }
        }
        if is_reference {
            for run in runs {
                chart
                    .draw_series(DashedLineSeries::new(run.iter().copied(), 10, 6, style))
                    .map_err(draw_err)?;
            }
            continue;
        }
        // Few points are computed points (a sweep's speeds, a ladder's
        // runs): mark each, so that the line is not read as a continuum.
        let points: usize = runs.iter().map(Vec::len).sum();
        if points <= MAX_MARKED_POINTS && !background {
            chart
                .draw_series(
                    runs.iter()
                        .flatten()
                        .map(|&p| Circle::new(p, 4, colour.filled())),
                )
                .map_err(draw_err)?;
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
                // Segment by segment: a thick polyline's mitre joins spike
                // past the data at a dense run's acute corners (history.rs).
                chart
                    .draw_series(
                        run.windows(2)
                            .map(|pair| PathElement::new(vec![pair[0], pair[1]], style)),
                    )
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
        x: chart.x_range(),
        y: chart.y_range(),
    })
}

/// The plotting-area corner where the legend box covers the least of the lines.
pub(super) fn legend_position<DB: DrawingBackend, X, Y>(
    chart: &ChartContext<'_, DB, Cartesian2d<X, Y>>,
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
    // The four corners first (the tie-break prefers them, in this order);
    // then, for a plot whose every corner holds data (a limit line across
    // the top, curves along the bottom), the box at the left, middle and
    // right of five rows between them.
    let mut candidates = vec![
        (SeriesLabelPosition::UpperRight, aw - w - 5, 5),
        (SeriesLabelPosition::UpperLeft, 5, 5),
        (SeriesLabelPosition::LowerRight, aw - w - 5, ah - h - 5),
        (SeriesLabelPosition::LowerLeft, 5, ah - h - 5),
    ];
    for row in 1..=5 {
        let y = 5 + (ah - h - 10) * row / 6;
        for x in [aw - w - 5, 5, (aw - w) / 2] {
            candidates.push((SeriesLabelPosition::Coordinate(x, y), x, y));
        }
    }
    let mut hits = vec![0usize; candidates.len()];
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
