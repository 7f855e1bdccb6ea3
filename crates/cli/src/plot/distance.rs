//! The `distance` plot: distance from ownship to each target over time.

use super::{
    CLEARANCE_COLOUR, Chart, FAMILY, METRES_PER_NM, PlotData, Shift, clip_below, format_distance,
    labelled, tick, to_text,
};
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
    let mut chart = ChartBuilder::on(root)
        .caption(
            format!("{}: distance from ownship to each target", data.title),
            (FAMILY, 24).into_font().style(FontStyle::Bold),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..x_max, 0.0..y_max)
        .map_err(to_text)?;
    chart
        .configure_mesh()
        .x_desc("time (min)")
        .y_desc("distance (m)")
        .x_label_formatter(&|value| tick(*value))
        .y_label_formatter(&|value| tick(*value))
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .bold_line_style(RGBColor(210, 210, 210))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(to_text)?;
    draw_clearance_line(&mut chart, data, x_max, y_max)?;
    draw_target_distances(&mut chart, data, &series, y_max)?;
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

/// The dashed `d_th` line across the plot, in the series legend and labelled.
fn draw_clearance_line<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    x_max: f64,
    y_max: f64,
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
    chart
        .draw_series(std::iter::once(Text::new(
            format!("d_th = {:.0} m", data.d_th_m),
            (0.01 * x_max, data.d_th_m + 0.015 * y_max),
            (FAMILY, 13).into_font().color(&clearance),
        )))
        .map_err(to_text)?;
    Ok(())
}

/// Each target's distance line (clipped at `y_max`), its closest approach
/// marked, and labelled for the targets [`labelled`] picks.
fn draw_target_distances<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    series: &[Vec<(f64, f64)>],
    y_max: f64,
) -> Result<(), String> {
    let labels = labelled(&data.targets);
    for (index, (target, points)) in data.targets.iter().zip(series).enumerate() {
        let colour = target.colour;
        let runs = clip_below(points, y_max);
        for (run_index, run) in runs.into_iter().enumerate() {
            let drawn = chart
                .draw_series(LineSeries::new(run, colour.stroke_width(2)))
                .map_err(to_text)?;
            if run_index == 0 {
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
            if point.1 <= y_max && labels[index] {
                // Alternate the label above and below to keep neighbours apart.
                let dy = if index % 2 == 0 { -22 } else { 8 };
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at(point)
                            + Text::new(
                                format!(
                                    "{} {} at {:.1} min",
                                    target.name,
                                    format_distance(evaluation.min_distance_m),
                                    point.0
                                ),
                                (7, dy),
                                (FAMILY, 13).into_font().color(&colour),
                            ),
                    ))
                    .map_err(to_text)?;
            }
        }
    }
    Ok(())
}
