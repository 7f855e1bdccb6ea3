//! The axes that the plots over time (distance, speed) share: minutes
//! across, one quantity up, a caption; and the grid every plot shares.

use super::{Chart, FAMILY, Shift, tick, to_text};
use plotters::prelude::*;

/// Builds a chart on `root` with time in minutes (0 to `x_max`) across and
/// `y_desc` (0 to `y_max`) up, captioned `caption`, its grid drawn.
pub(super) fn time_chart<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    caption: String,
    y_desc: &str,
    x_max: f64,
    y_max: f64,
) -> Result<Chart<'a, DB>, String> {
    let mut chart = ChartBuilder::on(root)
        .caption(caption, (FAMILY, 24).into_font().style(FontStyle::Bold))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..x_max, 0.0..y_max)
        .map_err(to_text)?;
    draw_grid(&mut chart, "time (min)", y_desc, None)?;
    Ok(chart)
}

/// Draws the grid every plot shares on `chart`: axes named `x_desc` and
/// `y_desc`, ticks formatted by [`tick`], `labels` ticks an axis where
/// given (plotters' default otherwise), the same fonts and grey lines.
pub(super) fn draw_grid<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    x_desc: &str,
    y_desc: &str,
    labels: Option<usize>,
) -> Result<(), String> {
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_desc).y_desc(y_desc);
    if let Some(count) = labels {
        mesh.x_labels(count).y_labels(count);
    }
    mesh.x_label_formatter(&|value| tick(*value))
        .y_label_formatter(&|value| tick(*value))
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .bold_line_style(RGBColor(210, 210, 210))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(to_text)
}
