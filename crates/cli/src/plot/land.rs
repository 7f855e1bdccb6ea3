//! Land in the `trajectories` plot: each area filled, its holes (water)
//! cut out in the background colour, clipped to the view (decision 29).
//! Self-contained: its colours are its own.

use super::{Chart, View, clip_polygon, to_text};
use plotters::prelude::*;

/// Land's fill: a chart's buff.
const LAND_FILL: RGBColor = RGBColor(235, 220, 180);
/// Land's outline.
const LAND_EDGE: RGBColor = RGBColor(150, 125, 80);

/// One land area as drawn: its outer ring then its holes, nautical miles.
pub(super) type LandShape = Vec<Vec<(f64, f64)>>;

/// Fills every area of `land`, then cuts its holes out in white.
pub(super) fn draw_land<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    land: &[LandShape],
    view: &View,
) -> Result<(), String> {
    for rings in land {
        for (index, ring) in rings.iter().enumerate() {
            let clipped = clip_polygon(ring, view);
            if clipped.len() < 3 {
                continue;
            }
            let fill = if index == 0 { LAND_FILL } else { WHITE };
            chart
                .draw_series(std::iter::once(Polygon::new(
                    clipped.clone(),
                    fill.filled(),
                )))
                .map_err(to_text)?;
            let mut outline = clipped.clone();
            outline.push(clipped[0]);
            chart
                .draw_series(std::iter::once(PathElement::new(
                    outline,
                    LAND_EDGE.stroke_width(1),
                )))
                .map_err(to_text)?;
        }
    }
    Ok(())
}
