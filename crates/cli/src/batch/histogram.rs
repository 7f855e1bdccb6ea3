//! The batch's SVG histograms: minimum distance and planning time per run.

use crate::font;
use plotters::prelude::*;
use std::path::Path;
use vorrt_scenarios::batch::BatchRow;

/// Writes `min_distance.svg` and `planning_time.svg`.
///
/// # Errors
/// A message when a file cannot be drawn or written.
pub(crate) fn write_histograms(rows: &[BatchRow], dir: &Path) -> Result<(), String> {
    font::register();
    let clearance = rows
        .iter()
        .map(|row| row.clearance_m)
        .find(|value| value.is_finite());
    let distances: Vec<f64> = rows
        .iter()
        .map(|row| row.min_distance_m)
        .filter(|value| value.is_finite())
        .collect();
    histogram(
        &dir.join("min_distance.svg"),
        "Minimum distance to any target per run",
        "minimum distance (m)",
        &distances,
        clearance,
    )?;
    let times: Vec<f64> = rows
        .iter()
        .filter(|row| row.error.is_empty())
        .map(|row| row.planning_time_ms)
        .collect();
    histogram(
        &dir.join("planning_time.svg"),
        "Planning time per run (all planner calls)",
        "planning time (ms)",
        &times,
        None,
    )
}

const BINS: usize = 40;

fn histogram(
    path: &Path,
    title: &str,
    x_label: &str,
    values: &[f64],
    marker: Option<f64>,
) -> Result<(), String> {
    let text = |error: &dyn std::fmt::Display| format!("{}: {error}", path.display());
    let high = values.iter().copied().fold(0.0, f64::max).max(1.0) * 1.0001;
    let high = marker.map_or(high, |m| high.max(m * 1.1));
    #[expect(clippy::cast_precision_loss, reason = "BINS is a small constant")]
    let width = high / BINS as f64;
    let mut counts = [0u32; BINS];
    for value in values {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "floored at 0 and capped at BINS - 1: a bin index"
        )]
        let bin = ((value / width).floor().max(0.0) as usize).min(BINS - 1);
        counts[bin] += 1;
    }
    let top = counts.iter().copied().max().unwrap_or(0).max(1);
    let root = SVGBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| text(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("{title} ({} runs)", values.len()),
            (font::FAMILY, 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..high, 0u32..(top + top / 10 + 1))
        .map_err(|e| text(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc("runs")
        .label_style((font::FAMILY, 14))
        .draw()
        .map_err(|e| text(&e))?;
    chart
        .draw_series(
            counts
                .iter()
                .enumerate()
                .filter(|(_, c)| **c > 0)
                .map(|(bin, count)| {
                    #[expect(clippy::cast_precision_loss, reason = "a bin index below BINS")]
                    let x0 = bin as f64 * width;
                    Rectangle::new([(x0, 0), (x0 + width, *count)], BLUE.mix(0.6).filled())
                }),
        )
        .map_err(|e| text(&e))?;
    if let Some(marker) = marker {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(marker, 0), (marker, top + top / 10 + 1)],
                RED.stroke_width(2),
            )))
            .map_err(|e| text(&e))?
            .label(format!("d_th = {marker:.0} m"))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED.stroke_width(2)));
        chart
            .configure_series_labels()
            .label_font((font::FAMILY, 14))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| text(&e))?;
    }
    root.present().map_err(|e| text(&e))
}
