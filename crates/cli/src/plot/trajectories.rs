//! The `trajectories` plot: tracks, closest approaches, lanes and the legend.

use super::{
    Chart, FAMILY, LANE_COLOUR, METRES_PER_NM, OWNSHIP_COLOUR, PlotData, Shift, Track, View,
    circle_points, clip_polygon, fit_view, format_distance, key_label, labelled,
    marker_interval_min, tick, to_text, triangle,
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
    let vessels: Vec<&Track<'_>> = std::iter::once(&data.ownship)
        .chain(data.targets.iter())
        .collect();
    let view = fit_view(
        vessels
            .iter()
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
    chart
        .configure_mesh()
        .x_desc("east (nm)")
        .y_desc("north (nm)")
        .x_labels(10)
        .y_labels(10)
        .x_label_formatter(&|value| tick(*value))
        .y_label_formatter(&|value| tick(*value))
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .bold_line_style(RGBColor(210, 210, 210))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(to_text)?;

    super::land::draw_land(&mut chart, &data.land, &view)?;
    draw_lanes(&mut chart, data, &view)?;
    draw_clearance_circles(&mut chart, data)?;
    // Targets first, ownship on top.
    for track in vessels.iter().rev() {
        let width = if track.evaluation.is_none() { 3 } else { 2 };
        chart
            .draw_series(LineSeries::new(
                track.points_nm.iter().copied(),
                track.colour.stroke_width(width),
            ))
            .map_err(to_text)?;
    }
    let interval_min = marker_interval_min(data.duration_s());
    draw_course_markers(&mut chart, data, &vessels, interval_min)?;
    draw_starts_and_goals(&mut chart, &vessels, &view)?;
    draw_closest_approaches(&mut chart, data)?;
    draw_legend(&right, data, interval_min)
}

/// Traffic lanes, clipped to the view, each labelled with its name and traffic direction.
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
        let top = clipped
            .iter()
            .map(|p| p.1)
            .fold(f64::NEG_INFINITY, f64::max);
        let label_at = (view.x0 + 0.02 * (view.x1 - view.x0), top);
        let colour = LANE_COLOUR;
        chart
            .draw_series(std::iter::once(
                EmptyElement::at(label_at)
                    + Text::new(
                        format!("TSS lane {}, traffic {:03.0}°", lane.name, lane.course_deg),
                        (0, 3),
                        (FAMILY, 13).into_font().color(&colour),
                    ),
            ))
            .map_err(to_text)?;
    }
    Ok(())
}

/// The `d_th` circle around ownship at each target's closest approach.
fn draw_clearance_circles<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
) -> Result<(), String> {
    let d_th_nm = data.d_th_m / METRES_PER_NM;
    for target in &data.targets {
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

/// Course triangles on every track every `interval_min` minutes, ownship's
/// labelled with the time.
fn draw_course_markers<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
    vessels: &[&Track<'_>],
    interval_min: f64,
) -> Result<(), String> {
    let mut marker_time_s = interval_min * 60.0;
    while marker_time_s < data.duration_s() {
        let step = data.step_at(marker_time_s);
        for track in vessels {
            let (Some(&point), Some(&course)) =
                (track.points_nm.get(step), track.courses_rad.get(step))
            else {
                continue;
            };
            let own = track.evaluation.is_none();
            let size = if own { 9.0 } else { 7.0 };
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(point)
                        + Polygon::new(triangle(course, size), track.colour.filled()),
                ))
                .map_err(to_text)?;
            if own {
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at(point)
                            + Text::new(
                                format!("{:.0} min", marker_time_s / 60.0),
                                (10, -6),
                                (FAMILY, 12).into_font().color(&OWNSHIP_COLOUR),
                            ),
                    ))
                    .map_err(to_text)?;
            }
        }
        marker_time_s += interval_min * 60.0;
    }
    Ok(())
}

/// Start dots with the vessels' names, and goal crosses within the view.
fn draw_starts_and_goals<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    vessels: &[&Track<'_>],
    view: &View,
) -> Result<(), String> {
    for track in vessels {
        let colour = track.colour;
        if let Some(&start) = track.points_nm.first() {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(start)
                        + Circle::new((0, 0), 5, colour.filled())
                        + Text::new(
                            track.name.to_owned(),
                            (8, 4),
                            (FAMILY, 14).into_font().color(&colour),
                        ),
                ))
                .map_err(to_text)?;
        }
        if let Some(goal) = track.goal_nm.filter(|goal| view.contains(*goal)) {
            let own = track.evaluation.is_none();
            let (size, width) = if own { (8, 3) } else { (5, 2) };
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(goal) + Cross::new((0, 0), size, colour.stroke_width(width)),
                ))
                .map_err(to_text)?;
            if own {
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at(goal)
                            + Text::new(
                                "goal".to_owned(),
                                (10, -6),
                                (FAMILY, 14).into_font().color(&colour),
                            ),
                    ))
                    .map_err(to_text)?;
            }
        }
    }
    Ok(())
}

/// Closest approaches: the two positions joined, the distance written
/// (for the targets [`labelled`] picks).
fn draw_closest_approaches<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    data: &PlotData<'_>,
) -> Result<(), String> {
    let labels = labelled(&data.targets);
    for (target, label) in data.targets.iter().zip(labels) {
        let Some(evaluation) = target.evaluation else {
            continue;
        };
        let step = data.step_at(evaluation.time_of_min_s);
        let (Some(&own), Some(&other)) =
            (data.ownship.points_nm.get(step), target.points_nm.get(step))
        else {
            continue;
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
        if !label {
            continue;
        }
        let middle = (0.5 * (own.0 + other.0), 0.5 * (own.1 + other.1));
        chart
            .draw_series(std::iter::once(
                EmptyElement::at(middle)
                    + Text::new(
                        format!(
                            "{} {}",
                            target.name,
                            format_distance(evaluation.min_distance_m)
                        ),
                        (6, -16),
                        (FAMILY, 13).into_font().color(&colour),
                    ),
            ))
            .map_err(to_text)?;
    }
    Ok(())
}

/// The legend: every vessel with its encounter and closest approach, then
/// the key to the symbols at the bottom.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
    interval_min: f64,
) -> Result<(), String> {
    let black = RGBColor(0, 0, 0);
    let grey = RGBColor(90, 90, 90);
    let (_, height) = area.dim_in_pixel();
    let bottom = i32::try_from(height).unwrap_or(i32::MAX) - 150;
    let x = 8;
    let mut y = 60;
    area.draw(&Text::new(
        "Legend",
        (x, y),
        (FAMILY, 18).into_font().color(&black),
    ))
    .map_err(to_text)?;
    y += 28;
    let vessels: Vec<&Track<'_>> = std::iter::once(&data.ownship)
        .chain(data.targets.iter())
        .collect();
    let two_lines = vessels.len() <= 16;
    let line_height = if two_lines { 34 } else { 18 };
    for (shown, track) in vessels.iter().enumerate() {
        if y + line_height > bottom {
            let rest = vessels.len() - shown;
            area.draw(&Text::new(
                format!("... and {rest} more"),
                (x, y),
                (FAMILY, 13).into_font().color(&grey),
            ))
            .map_err(to_text)?;
            break;
        }
        let own = track.evaluation.is_none();
        area.draw(&PathElement::new(
            vec![(x, y + 7), (x + 28, y + 7)],
            track.colour.stroke_width(if own { 3 } else { 2 }),
        ))
        .map_err(to_text)?;
        let headline = match track.evaluation {
            Some(evaluation) => format!("{}  {}", track.name, evaluation.encounter),
            None if track.name == "ownship" => "ownship".to_owned(),
            None => format!("{} (ownship)", track.name),
        };
        area.draw(&Text::new(
            headline,
            (x + 36, y),
            (FAMILY, 14).into_font().color(&black),
        ))
        .map_err(to_text)?;
        if two_lines && let Some(evaluation) = track.evaluation {
            let verdict = if evaluation.compliant {
                "ok"
            } else {
                "violation"
            };
            area.draw(&Text::new(
                format!(
                    "min {} at {:.1} min, {verdict}",
                    format_distance(evaluation.min_distance_m),
                    evaluation.time_of_min_s / 60.0
                ),
                (x + 36, y + 16),
                (FAMILY, 12).into_font().color(&grey),
            ))
            .map_err(to_text)?;
        }
        y += line_height;
    }
    draw_symbol_key(area, data, (x, bottom), interval_min)
}

/// The key to the chart's symbols, from `(x, bottom)` down: start, course
/// marker, goal, closest approach, `d_th`, and traffic lanes when there are any.
fn draw_symbol_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
    (x, bottom): (i32, i32),
    interval_min: f64,
) -> Result<(), String> {
    let black = RGBColor(0, 0, 0);
    let grey = RGBColor(90, 90, 90);
    let mut y = bottom + 10;
    let step = 22;
    let symbol_x = x + 14;
    area.draw(&(EmptyElement::at((symbol_x, y + 7)) + Circle::new((0, 0), 5, black.filled())))
        .map_err(to_text)?;
    key_label(area, "start", (x + 36, y))?;
    y += step;
    area.draw(
        &(EmptyElement::at((symbol_x, y + 7))
            + Polygon::new(triangle(std::f64::consts::FRAC_PI_2, 8.0), black.filled())),
    )
    .map_err(to_text)?;
    key_label(
        area,
        format!("course, every {interval_min:.0} min"),
        (x + 36, y),
    )?;
    y += step;
    area.draw(
        &(EmptyElement::at((symbol_x, y + 7)) + Cross::new((0, 0), 6, black.stroke_width(2))),
    )
    .map_err(to_text)?;
    key_label(area, "goal", (x + 36, y))?;
    y += step;
    area.draw(&PathElement::new(
        vec![(x, y + 7), (x + 8, y + 7)],
        black.stroke_width(2),
    ))
    .map_err(to_text)?;
    area.draw(&PathElement::new(
        vec![(x + 13, y + 7), (x + 21, y + 7)],
        black.stroke_width(2),
    ))
    .map_err(to_text)?;
    key_label(area, "closest approach", (x + 36, y))?;
    y += step;
    area.draw(
        &(EmptyElement::at((symbol_x, y + 7)) + Circle::new((0, 0), 8, grey.stroke_width(1))),
    )
    .map_err(to_text)?;
    key_label(
        area,
        format!("d_th = {:.0} m around ownship", data.d_th_m),
        (x + 36, y),
    )?;
    if !data.lanes.is_empty() {
        y += step;
        area.draw(&Rectangle::new(
            [(x, y), (x + 28, y + 14)],
            LANE_COLOUR.mix(0.3).filled(),
        ))
        .map_err(to_text)?;
        area.draw(&Text::new(
            "traffic lane (TSS)",
            (x + 36, y),
            (FAMILY, 13).into_font().color(&black),
        ))
        .map_err(to_text)?;
    }
    Ok(())
}
