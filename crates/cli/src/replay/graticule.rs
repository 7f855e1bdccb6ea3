//! Parallels and meridians of a geographic run, projected into its local
//! frame with the scenario's own projection (`LocalFrame::to_local_m`), so
//! that the replay's lat/lon grid is where the judged positions are.

use serde::{Deserialize, Serialize};
use vorrt_geometry::DVec2;
use vorrt_scenarios::LocalFrame;

/// Grid spacings tried, degrees: 1', 2', 5', 10', 15', 30', 1°, 2°, 5°, 10°.
const STEPS_DEG: [f64; 10] = [
    1.0 / 60.0,
    2.0 / 60.0,
    5.0 / 60.0,
    10.0 / 60.0,
    15.0 / 60.0,
    0.5,
    1.0,
    2.0,
    5.0,
    10.0,
];

/// At most this many lines across the run's extent in each direction.
const MAX_LINES: f64 = 6.0;

/// Points along each line.
const POINTS_PER_LINE: u32 = 24;

/// One parallel or meridian.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct GraticuleLine {
    /// `lat` (a parallel) or `lon` (a meridian).
    pub(crate) kind: String,
    /// Its latitude or longitude, degrees.
    pub(crate) value_deg: f64,
    /// The spacing of its grid, degrees: the coarse grid's lines, or the
    /// finer grid's (drawn when zoomed in) between them.
    pub(crate) step_deg: f64,
    /// Its label, degrees and minutes with the hemisphere (`50°12.0'N`).
    pub(crate) label: String,
    /// Points along it, `[east_m, north_m]` in the local frame.
    pub(crate) points_m: Vec<[f64; 2]>,
}

/// `value_deg` as degrees and minutes with its hemisphere letter.
#[must_use]
pub(crate) fn label(value_deg: f64, positive: char, negative: char) -> String {
    let hemisphere = if value_deg < 0.0 { negative } else { positive };
    let minutes_total = (value_deg.abs() * 60.0 * 10.0).round() / 10.0;
    let degrees = (minutes_total / 60.0).floor();
    let minutes = minutes_total - degrees * 60.0;
    format!("{degrees:.0}°{minutes:04.1}'{hemisphere}")
}

/// The smallest step of [`STEPS_DEG`] giving at most [`MAX_LINES`] lines over `span_deg`.
fn step_for(span_deg: f64) -> f64 {
    STEPS_DEG
        .iter()
        .copied()
        .find(|step| span_deg / step <= MAX_LINES)
        .unwrap_or(STEPS_DEG[STEPS_DEG.len() - 1])
}

/// The finer spacing under `coarse`: the largest of [`STEPS_DEG`] at most
/// a quarter of it (`None` under 1').
fn finer(coarse: f64) -> Option<f64> {
    STEPS_DEG
        .iter()
        .copied()
        .rev()
        .find(|step| *step <= coarse / 4.0 + 1e-12)
}

/// Multiples of `step` from below `low` to above `high`.
fn multiples(low: f64, high: f64, step: f64) -> Vec<f64> {
    let first = (low / step).floor();
    let last = (high / step).ceil();
    let mut values = Vec::new();
    let mut k = first;
    while k <= last && values.len() < 200 {
        values.push(k * step);
        k += 1.0;
    }
    values
}

/// The graticule over the box `low`..`high` of the local frame, widened by
/// the box's own size on every side so that panning keeps a grid in view.
#[must_use]
pub(crate) fn graticule(frame: &LocalFrame, low: DVec2, high: DVec2) -> Vec<GraticuleLine> {
    let size = (high - low).max(DVec2::splat(1_000.0));
    let (low, high) = (low - size, high + size);
    let corners = [
        low,
        high,
        DVec2::new(low.x, high.y),
        DVec2::new(high.x, low.y),
    ]
    .map(|corner| frame.to_lat_lon_deg(corner));
    let fold = |pick: fn(&(f64, f64)) -> f64| {
        corners
            .iter()
            .map(pick)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            })
    };
    let (lat_low, lat_high) = fold(|c| c.0);
    let (lon_low, lon_high) = fold(|c| c.1);
    // Spacing from the run's own extent (a third of the widened box).
    let lat_step = step_for((lat_high - lat_low) / 3.0);
    let lon_step = step_for((lon_high - lon_low) / 3.0);
    let along = |from: f64, to: f64| {
        (0..=POINTS_PER_LINE)
            .map(move |i| from + (to - from) * f64::from(i) / f64::from(POINTS_PER_LINE))
    };
    let round = |p: DVec2| [(p.x * 10.0).round() / 10.0, (p.y * 10.0).round() / 10.0];
    let mut lines = Vec::new();
    let mut add = |kind: &str, value_deg: f64, step_deg: f64| {
        let points_m = if kind == "lat" {
            along(lon_low, lon_high)
                .map(|lon_deg| round(frame.to_local_m(value_deg, lon_deg)))
                .collect()
        } else {
            along(lat_low, lat_high)
                .map(|lat_deg| round(frame.to_local_m(lat_deg, value_deg)))
                .collect()
        };
        let label = if kind == "lat" {
            label(value_deg, 'N', 'S')
        } else {
            label(value_deg, 'E', 'W')
        };
        lines.push(GraticuleLine {
            kind: kind.to_owned(),
            value_deg,
            step_deg,
            label,
            points_m,
        });
    };
    for (kind, low, high, step) in [
        ("lat", lat_low, lat_high, lat_step),
        ("lon", lon_low, lon_high, lon_step),
    ] {
        for value in multiples(low, high, step) {
            add(kind, value, step);
        }
        // The finer grid's lines between the coarse ones.
        if let Some(fine) = finer(step) {
            for value in multiples(low, high, fine) {
                let on_coarse = ((value / step) - (value / step).round()).abs() < 1e-6;
                if !on_coarse {
                    add(kind, value, fine);
                }
            }
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_are_degrees_and_minutes_with_the_hemisphere() {
        assert_eq!(label(50.2, 'N', 'S'), "50°12.0'N");
        assert_eq!(label(-0.75, 'E', 'W'), "0°45.0'W");
        assert_eq!(label(10.0 - 1e-9, 'N', 'S'), "10°00.0'N");
    }

    #[test]
    fn the_graticule_crosses_the_run_on_round_values_where_the_projection_puts_them() {
        let frame = LocalFrame::new(50.0, -1.0);
        let lines = graticule(
            &frame,
            DVec2::new(-15_000.0, -15_000.0),
            DVec2::new(15_000.0, 15_000.0),
        );
        let coarse_deg = 5.0 / 60.0;
        let coarse = |line: &&GraticuleLine| (line.step_deg - coarse_deg).abs() < 1e-12;
        let parallels: Vec<&GraticuleLine> = lines
            .iter()
            .filter(|l| l.kind == "lat")
            .filter(coarse)
            .collect();
        let meridians: Vec<&GraticuleLine> = lines
            .iter()
            .filter(|l| l.kind == "lon")
            .filter(coarse)
            .collect();
        assert!(parallels.len() >= 3 && meridians.len() >= 3, "{lines:?}");
        let origin = parallels
            .iter()
            .find(|line| (line.value_deg - 50.0).abs() < 1e-9)
            .expect("the 50°N parallel");
        assert_eq!(origin.label, "50°00.0'N");
        // Every point of the 50°N parallel is where the frame puts 50°N.
        for point in &origin.points_m {
            let (lat_deg, _) = frame.to_lat_lon_deg(DVec2::new(point[0], point[1]));
            assert!((lat_deg - 50.0).abs() < 1e-5, "{point:?} at {lat_deg}");
        }
        // The finer grid (1') lies between the coarse lines, never on one.
        let fine: Vec<&GraticuleLine> = lines
            .iter()
            .filter(|l| (l.step_deg - 1.0 / 60.0).abs() < 1e-12)
            .collect();
        assert!(fine.len() >= 4 * parallels.len());
        for line in fine {
            let on_coarse = lines
                .iter()
                .filter(coarse)
                .any(|c| c.kind == line.kind && (c.value_deg - line.value_deg).abs() < 1e-9);
            assert!(!on_coarse, "{}", line.label);
        }
    }

    #[test]
    fn the_finer_grid_is_a_quarter_or_less_of_the_coarse() {
        assert_eq!(finer(5.0 / 60.0), Some(1.0 / 60.0));
        assert_eq!(finer(1.0), Some(15.0 / 60.0));
        assert_eq!(finer(1.0 / 60.0), None);
    }
}
