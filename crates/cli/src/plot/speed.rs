//! The `speed` plot: every vessel's speed over time, so that a speed
//! manoeuvre (ownship slowing for a target, a target stopping at its goal)
//! shows, which the track plot cannot (decision 36).

use super::time_axes::time_chart;
use super::{
    Chart, FAMILY, Label, MAX_LABELS, MAX_MARKED, OWNSHIP_COLOUR, PixelBox, PlotData, Shift, Track,
    closest, draw_labels, placer_for, to_text,
};
use crate::font;
use plotters::prelude::*;

/// A speed change smaller than this, knots, is not labelled (a noisy
/// target's wander, the rounding of a record).
pub(super) const SPEED_CHANGE_KN: f64 = 0.5;

/// Consecutive samples closer than this, knots, are steady.
const STEADY_KN: f64 = 0.05;

/// One change of a vessel's speed: from one steady speed to the next.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SpeedChange {
    /// When the speed began to change, minutes.
    pub(super) time_min: f64,
    /// The speed before, knots.
    pub(super) from_kn: f64,
    /// The speed after, knots.
    pub(super) to_kn: f64,
}

/// The changes of `speeds_kn` (sampled at `minutes`): each run of samples
/// moving the same way, from where it began to where it settled, when it
/// moved by at least [`SPEED_CHANGE_KN`].
#[must_use]
pub(super) fn speed_changes(minutes: &[f64], speeds_kn: &[f64]) -> Vec<SpeedChange> {
    let mut changes = Vec::new();
    let mut start: Option<(usize, f64)> = None;
    let count = speeds_kn.len().min(minutes.len());
    for k in 1..count {
        let step = speeds_kn[k] - speeds_kn[k - 1];
        let moving = step.abs() > STEADY_KN;
        let same_way = start.is_none_or(|(first, _)| {
            let first_step = speeds_kn[first + 1] - speeds_kn[first];
            first_step.signum() == step.signum()
        });
        match start {
            Some((first, from)) if !moving || !same_way => {
                let to = speeds_kn[k - 1];
                if (to - from).abs() >= SPEED_CHANGE_KN {
                    changes.push(SpeedChange {
                        time_min: minutes[first],
                        from_kn: from,
                        to_kn: to,
                    });
                }
                start = moving.then_some((k - 1, speeds_kn[k - 1]));
            }
            None if moving => start = Some((k - 1, speeds_kn[k - 1])),
            _ => {}
        }
    }
    if let Some((first, from)) = start {
        let to = speeds_kn[count - 1];
        if (to - from).abs() >= SPEED_CHANGE_KN {
            changes.push(SpeedChange {
                time_min: minutes[first],
                from_kn: from,
                to_kn: to,
            });
        }
    }
    changes
}

/// Draws the speed plot of `data` on `root`: one line per vessel, ownship
/// bold on top, every change of ownship's speed labelled, and those of the
/// targets that came closest.
pub(super) fn draw_speed<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(to_text)?;
    let minutes: Vec<f64> = data.times_s.iter().map(|t| t / 60.0).collect();
    let x_max = minutes.last().copied().unwrap_or(0.0).max(1.0);
    let fastest = std::iter::once(&data.ownship)
        .chain(&data.targets)
        .flat_map(|track| track.speeds_kn.iter().copied())
        .fold(0.0_f64, f64::max);
    let y_max = (1.15 * fastest).max(1.0);
    let mut chart = time_chart(
        root,
        format!("{}: speed of every vessel", data.title),
        "speed (kn)",
        x_max,
        y_max,
    )?;
    let changes: Vec<Vec<SpeedChange>> = data
        .targets
        .iter()
        .map(|target| speed_changes(&minutes, &target.speeds_kn))
        .collect();
    let near = closest(&data.targets, MAX_MARKED);
    let named: Vec<bool> = changes
        .iter()
        .zip(&near)
        .map(|(changes, &near)| near && !changes.is_empty())
        .collect();
    for (target, &named) in data.targets.iter().zip(&named) {
        draw_speed_line(&mut chart, target, &minutes, named)?;
    }
    // Ownship last: on top of every target.
    draw_speed_line(&mut chart, &data.ownship, &minutes, true)?;
    let mut placer = placer_for(&chart);
    placer.block(legend_box(&chart, data, &named));
    draw_labels(&mut chart, &mut placer, &labels(data, &minutes, &changes))?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(160, 160, 160))
        .label_font((FAMILY, 13))
        .draw()
        .map_err(to_text)?;
    Ok(())
}

/// One vessel's speed line, named in the series legend when `named`.
fn draw_speed_line<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    track: &Track<'_>,
    minutes: &[f64],
    named: bool,
) -> Result<(), String> {
    let own = track.evaluation.is_none();
    let colour = track.colour;
    let width = if own { 3 } else { 2 };
    let drawn = chart
        .draw_series(LineSeries::new(
            minutes.iter().copied().zip(track.speeds_kn.iter().copied()),
            colour.stroke_width(width),
        ))
        .map_err(to_text)?;
    if named {
        drawn.label(track.name.to_owned()).legend(move |(x, y)| {
            PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(width))
        });
    }
    Ok(())
}

/// The labels, most important first: ownship's speed changes, then those of
/// the [`MAX_LABELS`] targets with the closest approaches.
fn labels(data: &PlotData<'_>, minutes: &[f64], changes: &[Vec<SpeedChange>]) -> Vec<Label> {
    let label = |track: &Track<'_>, change: &SpeedChange, own: bool| Label {
        text: format!(
            "{}{:.1} → {:.1} kn at {:.1} min",
            if own {
                String::new()
            } else {
                format!("{} ", track.name)
            },
            change.from_kn,
            change.to_kn,
            change.time_min
        ),
        at: (change.time_min, change.from_kn),
        colour: if own { OWNSHIP_COLOUR } else { track.colour },
        size_px: 13,
    };
    let mut labels: Vec<Label> = speed_changes(minutes, &data.ownship.speeds_kn)
        .iter()
        .map(|change| label(&data.ownship, change, true))
        .collect();
    let shown = closest(&data.targets, MAX_LABELS);
    for ((target, changes), shown) in data.targets.iter().zip(changes).zip(shown) {
        if shown {
            labels.extend(changes.iter().map(|change| label(target, change, false)));
        }
    }
    labels
}

/// Where plotters draws the series legend (lower right), a little larger.
fn legend_box<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    data: &PlotData<'_>,
    named: &[bool],
) -> PixelBox {
    let (x, y) = chart.plotting_area().get_pixel_range();
    let texts: Vec<&str> = std::iter::once(data.ownship.name)
        .chain(
            data.targets
                .iter()
                .zip(named)
                .filter(|(_, named)| **named)
                .map(|(target, _)| target.name),
        )
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
        y0: f64::from(y.end) - height,
        x1: f64::from(x.end),
        y1: f64::from(y.end),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slowdown_is_one_change() {
        let minutes: Vec<f64> = (0..10).map(f64::from).collect();
        let speeds = [12.0, 12.0, 12.0, 10.0, 8.0, 6.0, 6.0, 6.0, 6.02, 6.0];
        assert_eq!(
            speed_changes(&minutes, &speeds),
            vec![SpeedChange {
                time_min: 2.0,
                from_kn: 12.0,
                to_kn: 6.0
            }]
        );
    }

    #[test]
    fn small_wander_is_no_change_and_a_change_at_the_end_counts() {
        let minutes: Vec<f64> = (0..6).map(f64::from).collect();
        assert!(speed_changes(&minutes, &[10.0, 10.2, 10.0, 9.8, 10.0, 10.1]).is_empty());
        let stop = speed_changes(&minutes, &[10.0, 10.0, 10.0, 10.0, 10.0, 0.0]);
        assert_eq!(stop.len(), 1);
        assert!((stop[0].to_kn).abs() < 1e-12 && (stop[0].time_min - 4.0).abs() < 1e-12);
        let up_down = speed_changes(&minutes, &[5.0, 7.0, 9.0, 7.0, 5.0, 5.0]);
        assert_eq!(up_down.len(), 2, "{up_down:?}");
    }
}
