//! The `trajectories` plot: tracks, closest approaches, lanes and the legend.
//!
//! Drawn in layers: lanes, the `d_th` circles, every target (track, course
//! markers, closest-approach marks, start and goal), then ownship in the
//! same order, so that no target hides it; then every label, placed so that
//! none covers another (decision 36).

use super::legend::draw_legend;
use super::{
    Chart, FAMILY, LANE_COLOUR, Label, MAX_MARKED, METRES_PER_NM, OWNSHIP_COLOUR, PlotData, Shift,
    Track, View, circle_points, clip_polygon, closest, draw_labels, fit_view, format_distance,
    labelled, marker_interval_min, named_count, placer_for, to_text, triangle,
};
use plotters::prelude::*;

/// Draws the trajectories plot of `data` on `root`: the chart on the left,
/// the legend on the right.
pub(super) fn draw_trajectories<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(to_text)?;
    let (left, right) = root.split_horizontally(760);
    let area = left
        .margin(8, 0, 0, 0)
        .titled(data.title, (FAMILY, 26).into_font().style(FontStyle::Bold))
        .map_err(to_text)?;
    let (margin, x_label, y_label) = (12u32, 45u32, 60u32);
    let (width, height) = area.dim_in_pixel();
    let plot_w = f64::from(width.saturating_sub(2 * margin + y_label));
    let plot_h = f64::from(height.saturating_sub(2 * margin + x_label));
    let view = fit_view(
        std::iter::once(&data.ownship)
            .chain(data.targets.iter())
            .flat_map(|track| track.points_nm.iter().copied())
            .chain(data.ownship.goal_nm),
        plot_w,
        plot_h,
    );
    let mut chart = ChartBuilder::on(&area)
        .margin(margin)
        .x_label_area_size(x_label)
        .y_label_area_size(y_label)
        .build_cartesian_2d(view.x0..view.x1, view.y0..view.y1)
        .map_err(to_text)?;
    super::time_axes::draw_grid(&mut chart, "east (nm)", "north (nm)", Some(10))?;

    super::land::draw_land(&mut chart, &data.land, &view)?;
    let marked = closest(&data.targets, MAX_MARKED);
    draw_lanes(&mut chart, data, &view)?;
    draw_clearance_circles(&mut chart, data, &marked)?;
    let interval_min = marker_interval_min(data.duration_s());
    for (target, &mark) in data.targets.iter().zip(&marked) {
        draw_vessel(&mut chart, data, target, interval_min, &view)?;
        if mark {
            draw_closest_approach(&mut chart, data, target)?;
        }
    }
    // Ownship last: on top of every target.
    draw_vessel(&mut chart, data, &data.ownship, interval_min, &view)?;
    let mut placer = placer_for(&chart);
    draw_labels(&mut chart, &mut placer, &labels(data, &view, interval_min))?;
    draw_legend(&right, data, interval_min)
}

/// One vessel: its track, course markers every `interval_min` minutes, its
/// start dot and its goal cross (when in view). Ownship's are bolder.
fn draw_vessel<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    track: &Track<'_>,
    interval_min: f64,
    view: &View,
) -> Result<(), String> {
    let own = track.evaluation.is_none();
    let colour = track.colour;
    chart
        .draw_series(LineSeries::new(
            track.points_nm.iter().copied(),
            colour.stroke_width(if own { 3 } else { 2 }),
        ))
        .map_err(to_text)?;
    let size = if own { 9.0 } else { 7.0 };
    let mut marker_time_s = interval_min * 60.0;
    while marker_time_s < data.duration_s() {
        let step = data.step_at(marker_time_s);
        if let (Some(&point), Some(&course)) =
            (track.points_nm.get(step), track.courses_rad.get(step))
        {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(point) + Polygon::new(triangle(course, size), colour.filled()),
                ))
                .map_err(to_text)?;
        }
        marker_time_s += interval_min * 60.0;
    }
    if let Some(&start) = track.points_nm.first() {
        chart
            .draw_series(std::iter::once(Circle::new(start, 5, colour.filled())))
            .map_err(to_text)?;
    }
    if let Some(goal) = track.goal_nm.filter(|goal| view.contains(*goal)) {
        let (size, width) = if own { (8, 3) } else { (5, 2) };
        chart
            .draw_series(std::iter::once(
                EmptyElement::at(goal) + Cross::new((0, 0), size, colour.stroke_width(width)),
            ))
            .map_err(to_text)?;
    }
    Ok(())
}

/// Every label of the chart, most important first (the placer drops the
/// last ones when room runs out): the closest approaches, closest first;
/// ownship's name and goal; the lanes; ownship's times; the targets' names,
/// those that came closest first ([`named_count`] of them).
fn labels(data: &PlotData<'_>, view: &View, interval_min: f64) -> Vec<Label> {
    let mut labels = Vec::new();
    let shown = labelled(&data.targets);
    let mut by_distance: Vec<(usize, &Track<'_>)> = data.targets.iter().enumerate().collect();
    by_distance.sort_by(|a, b| min_distance(a.1).total_cmp(&min_distance(b.1)));
    for &(index, target) in &by_distance {
        let Some(evaluation) = target.evaluation.filter(|_| shown[index]) else {
            continue;
        };
        let step = data.step_at(evaluation.time_of_min_s);
        let (Some(&own), Some(&other)) =
            (data.ownship.points_nm.get(step), target.points_nm.get(step))
        else {
            continue;
        };
        labels.push(Label {
            text: format!(
                "{} {}",
                target.name,
                format_distance(evaluation.min_distance_m)
            ),
            at: (0.5 * (own.0 + other.0), 0.5 * (own.1 + other.1)),
            colour: target.colour,
            size_px: 13,
        });
    }
    if let Some(&start) = data.ownship.points_nm.first() {
        labels.push(Label {
            text: data.ownship.name.to_owned(),
            at: start,
            colour: OWNSHIP_COLOUR,
            size_px: 14,
        });
    }
    if let Some(goal) = data.ownship.goal_nm.filter(|goal| view.contains(*goal)) {
        labels.push(Label {
            text: "goal".to_owned(),
            at: goal,
            colour: OWNSHIP_COLOUR,
            size_px: 14,
        });
    }
    labels.extend(lane_labels(data, view));
    let mut marker_time_s = interval_min * 60.0;
    while marker_time_s < data.duration_s() {
        if let Some(&point) = data.ownship.points_nm.get(data.step_at(marker_time_s)) {
            labels.push(Label {
                text: format!("{:.0} min", marker_time_s / 60.0),
                at: point,
                colour: OWNSHIP_COLOUR,
                size_px: 12,
            });
        }
        marker_time_s += interval_min * 60.0;
    }
    // With many targets only the nearest are named at their start (all are
    // in the legend, nearest first).
    let named = named_count(data.targets.len());
    for (_, target) in by_distance.into_iter().take(named) {
        if let Some(&start) = target.points_nm.first() {
            labels.push(Label {
                text: target.name.to_owned(),
                at: start,
                colour: target.colour,
                size_px: 13,
            });
        }
    }
    labels
}

fn min_distance(track: &Track<'_>) -> f64 {
    track.evaluation.map_or(f64::INFINITY, |e| e.min_distance_m)
}

/// Each lane's name and traffic direction, at the top left of its part in view.
fn lane_labels(data: &PlotData<'_>, view: &View) -> Vec<Label> {
    data.lanes
        .iter()
        .filter_map(|lane| {
            let clipped = clip_polygon(&lane.corners_nm, view);
            let top = clipped.iter().map(|p| p.1).reduce(f64::max)?;
            let left = clipped.iter().map(|p| p.0).reduce(f64::min)?;
            Some(Label {
                text: format!("TSS lane {}, traffic {:03.0}°", lane.name, lane.course_deg),
                at: (left, top),
                colour: LANE_COLOUR,
                size_px: 13,
            })
        })
        .collect()
}

/// Traffic lanes, clipped to the view, as shaded strips.
fn draw_lanes<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    view: &View,
) -> Result<(), String> {
    for lane in &data.lanes {
        let clipped = clip_polygon(&lane.corners_nm, view);
        if clipped.len() < 3 {
            continue;
        }
        chart
            .draw_series(std::iter::once(Polygon::new(
                clipped.clone(),
                LANE_COLOUR.mix(0.15).filled(),
            )))
            .map_err(to_text)?;
        let mut outline = clipped.clone();
        outline.push(clipped[0]);
        chart
            .draw_series(std::iter::once(PathElement::new(
                outline,
                LANE_COLOUR.mix(0.6).stroke_width(1),
            )))
            .map_err(to_text)?;
    }
    Ok(())
}

/// The `d_th` circle around ownship at each `marked` target's closest approach.
fn draw_clearance_circles<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    marked: &[bool],
) -> Result<(), String> {
    let d_th_nm = data.d_th_m / METRES_PER_NM;
    for (target, _) in data.targets.iter().zip(marked).filter(|(_, mark)| **mark) {
        let Some(evaluation) = target.evaluation else {
            continue;
        };
        let step = data.step_at(evaluation.time_of_min_s);
        let Some(&own) = data.ownship.points_nm.get(step) else {
            continue;
        };
        chart
            .draw_series(std::iter::once(Polygon::new(
                circle_points(own, d_th_nm),
                target.colour.mix(0.08).filled(),
            )))
            .map_err(to_text)?;
        chart
            .draw_series(std::iter::once(PathElement::new(
                circle_points(own, d_th_nm),
                target.colour.mix(0.7).stroke_width(1),
            )))
            .map_err(to_text)?;
    }
    Ok(())
}

/// A target's closest approach: its and ownship's positions then, joined by
/// a dashed line.
fn draw_closest_approach<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    target: &Track<'_>,
) -> Result<(), String> {
    let Some(evaluation) = target.evaluation else {
        return Ok(());
    };
    let step = data.step_at(evaluation.time_of_min_s);
    let (Some(&own), Some(&other)) = (data.ownship.points_nm.get(step), target.points_nm.get(step))
    else {
        return Ok(());
    };
    let colour = target.colour;
    chart
        .draw_series(DashedLineSeries::new(
            vec![own, other],
            5,
            4,
            colour.stroke_width(2),
        ))
        .map_err(to_text)?;
    chart
        .draw_series(
            [own, other]
                .into_iter()
                .map(|point| Circle::new(point, 4, colour.stroke_width(2))),
        )
        .map_err(to_text)?;
    Ok(())
}
