//! The `distance` plot: distance from ownship to each target over time.

use super::time_axes::time_chart;
use super::{
    CLEARANCE_COLOUR, Chart, FAMILY, Label, METRES_PER_NM, PixelBox, PlotData, Shift, clip_below,
    closest, draw_labels, format_distance, labelled, named_count, placer_for, to_text,
};
use crate::font;
use plotters::prelude::*;

/// Draws the distance plot of `data` on `root`: one line per target, the
/// `d_th` line, and each closest approach marked.
pub(super) fn draw_distance<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(to_text)?;
    let minutes: Vec<f64> = data.times_s.iter().map(|t| t / 60.0).collect();
    let series = distance_series(data, &minutes);
    let y_max = y_max_m(data, &series);
    let x_max = minutes.last().copied().unwrap_or(0.0).max(1.0);
    let mut chart = time_chart(
        root,
        format!("{}: distance from ownship to each target", data.title),
        "distance (m)",
        x_max,
        y_max,
    )?;
    draw_clearance_line(&mut chart, data, x_max)?;
    let in_legend = closest(&data.targets, named_count(data.targets.len()));
    draw_target_distances(&mut chart, data, &series, y_max, &in_legend)?;
    let mut placer = placer_for(&chart);
    placer.block(legend_box(&chart, data, &in_legend));
    draw_labels(&mut chart, &mut placer, &labels(data, y_max))?;
    if data.targets.is_empty() {
        chart
            .draw_series(std::iter::once(Text::new(
                "no targets".to_owned(),
                (0.45 * x_max, 0.5 * y_max),
                (FAMILY, 18).into_font(),
            )))
            .map_err(to_text)?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(160, 160, 160))
        .label_font((FAMILY, 13))
        .draw()
        .map_err(to_text)?;
    Ok(())
}

/// Per target, `(minute, distance from ownship in metres)` at every sample.
fn distance_series(data: &PlotData<'_>, minutes: &[f64]) -> Vec<Vec<(f64, f64)>> {
    data.targets
        .iter()
        .map(|target| {
            target
                .points_nm
                .iter()
                .zip(&data.ownship.points_nm)
                .zip(minutes)
                .map(|((other, own), minute)| {
                    let distance_m = METRES_PER_NM * (other.0 - own.0).hypot(other.1 - own.1);
                    (*minute, distance_m)
                })
                .collect()
        })
        .collect()
}

/// The top of the distance axis, metres: the largest distance, but no more
/// than five times `d_th` or twice the largest closest approach (so that the
/// approaches stay readable), and at least 1.5 `d_th`.
fn y_max_m(data: &PlotData<'_>, series: &[Vec<(f64, f64)>]) -> f64 {
    let largest = series.iter().flatten().map(|p| p.1).fold(0.0_f64, f64::max);
    let largest_min = data
        .targets
        .iter()
        .filter_map(|target| target.evaluation.map(|e| e.min_distance_m))
        .fold(0.0_f64, f64::max);
    (largest.min((5.0 * data.d_th_m).max(2.0 * largest_min)) * 1.1)
        .max(1.5 * data.d_th_m)
        .max(1.0)
}

/// The dashed `d_th` line across the plot, in the series legend.
fn draw_clearance_line<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    x_max: f64,
) -> Result<(), String> {
    let clearance = CLEARANCE_COLOUR;
    chart
        .draw_series(DashedLineSeries::new(
            vec![(0.0, data.d_th_m), (x_max, data.d_th_m)],
            8,
            5,
            clearance.stroke_width(2),
        ))
        .map_err(to_text)?
        .label(format!("d_th = {:.0} m", data.d_th_m))
        .legend(move |(x, y)| {
            PathElement::new(vec![(x, y), (x + 20, y)], clearance.stroke_width(2))
        });
    Ok(())
}

/// Each target's distance line (clipped at `y_max`) and its closest
/// approach marked; the targets `in_legend` are named in the series legend.
fn draw_target_distances<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    series: &[Vec<(f64, f64)>],
    y_max: f64,
    in_legend: &[bool],
) -> Result<(), String> {
    for ((target, points), &named) in data.targets.iter().zip(series).zip(in_legend) {
        let colour = target.colour;
        let runs = clip_below(points, y_max);
        for (run_index, run) in runs.into_iter().enumerate() {
            let drawn = chart
                .draw_series(LineSeries::new(run, colour.stroke_width(2)))
                .map_err(to_text)?;
            if run_index == 0 && named {
                drawn.label(target.name.to_owned()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
            }
        }
        if let Some(evaluation) = target.evaluation {
            let point = (evaluation.time_of_min_s / 60.0, evaluation.min_distance_m);
            if point.1 <= y_max {
                chart
                    .draw_series(std::iter::once(Circle::new(point, 5, colour.filled())))
                    .map_err(to_text)?;
            }
        }
    }
    Ok(())
}

/// The labels of the plot, most important first: the closest approaches
/// ([`labelled`]), closest first, then the `d_th` line's.
fn labels(data: &PlotData<'_>, y_max: f64) -> Vec<Label> {
    let shown = labelled(&data.targets);
    let mut labels: Vec<(f64, Label)> = data
        .targets
        .iter()
        .zip(shown)
        .filter(|(_, shown)| *shown)
        .filter_map(|(target, _)| {
            let evaluation = target.evaluation?;
            let point = (evaluation.time_of_min_s / 60.0, evaluation.min_distance_m);
            (point.1 <= y_max).then(|| {
                (
                    evaluation.min_distance_m,
                    Label {
                        text: format!(
                            "{} {} at {:.1} min",
                            target.name,
                            format_distance(evaluation.min_distance_m),
                            point.0
                        ),
                        at: point,
                        colour: target.colour,
                        size_px: 13,
                    },
                )
            })
        })
        .collect();
    labels.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut labels: Vec<Label> = labels.into_iter().map(|(_, label)| label).collect();
    labels.push(Label {
        text: format!("d_th = {:.0} m", data.d_th_m),
        at: (0.0, data.d_th_m),
        colour: CLEARANCE_COLOUR,
        size_px: 13,
    });
    labels
}

/// Where plotters draws the series legend (upper right): a box a little
/// larger than its entries, so that no label goes under it.
fn legend_box<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    data: &PlotData<'_>,
    in_legend: &[bool],
) -> PixelBox {
    let (x, y) = chart.plotting_area().get_pixel_range();
    let names = data
        .targets
        .iter()
        .zip(in_legend)
        .filter(|(_, named)| **named)
        .map(|(target, _)| target.name.to_owned());
    let texts: Vec<String> = std::iter::once(format!("d_th = {:.0} m", data.d_th_m))
        .chain(names)
        .collect();
    let widest = texts
        .iter()
        .map(|text| font::text_width_px(text, 13.0))
        .fold(0.0, f64::max);
    #[expect(
        clippy::cast_precision_loss,
        reason = "a legend of a few dozen entries"
    )]
    let height = texts.len() as f64 * (font::text_height_px(13.0) + 6.0) + 20.0;
    PixelBox {
        x0: f64::from(x.end) - widest - 60.0,
        y0: f64::from(y.start),
        x1: f64::from(x.end),
        y1: f64::from(y.start) + height,
    }
}
