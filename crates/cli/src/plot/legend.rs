//! The legend beside the trajectories plot: every vessel with its encounter
//! and closest approach (the closest first when not all fit), names
//! shortened to the panel, then the key to the symbols.

use super::{FAMILY, LANE_COLOUR, PlotData, Shift, Track, format_distance, to_text, triangle};
use crate::font;
use plotters::prelude::*;

/// The legend: every vessel with its encounter and closest approach, then
/// the key to the symbols at the bottom. When not every vessel fits, ownship
/// and the targets with the closest approaches are listed, and the rest
/// counted with the closest of them.
pub(super) fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    data: &PlotData<'_>,
    interval_min: f64,
) -> Result<(), String> {
    let black = RGBColor(0, 0, 0);
    let grey = RGBColor(90, 90, 90);
    let (width, height) = area.dim_in_pixel();
    let bottom = i32::try_from(height).unwrap_or(i32::MAX) - 150;
    let x = 8;
    let text_width_px = f64::from(width) - f64::from(x + 36) - 6.0;
    let mut y = 60;
    area.draw(&Text::new(
        "Legend",
        (x, y),
        (FAMILY, 18).into_font().color(&black),
    ))
    .map_err(to_text)?;
    y += 28;
    let two_lines = data.targets.len() < 16;
    let line_height = if two_lines { 34 } else { 18 };
    let room = usize::try_from((bottom - y) / line_height).unwrap_or(0);
    let (vessels, rest) = listed(data, room);
    for track in &vessels {
        let own = track.evaluation.is_none();
        area.draw(&PathElement::new(
            vec![(x, y + 7), (x + 28, y + 7)],
            track.colour.stroke_width(if own { 3 } else { 2 }),
        ))
        .map_err(to_text)?;
        let headline = match track.evaluation {
            Some(evaluation) if !two_lines => format!(
                "{}  {}  {}",
                track.name,
                format_distance(evaluation.min_distance_m),
                evaluation.encounter
            ),
            Some(evaluation) => format!("{}  {}", track.name, evaluation.encounter),
            None if track.name == "ownship" => "ownship".to_owned(),
            None => format!("{} (ownship)", track.name),
        };
        area.draw(&Text::new(
            shorten(&headline, 14.0, text_width_px),
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
    if let Some((count, nearest_m)) = rest {
        area.draw(&Text::new(
            shorten(
                &format!("and {count} more, ≥ {}", format_distance(nearest_m)),
                13.0,
                f64::from(width) - f64::from(x) - 6.0,
            ),
            (x, y),
            (FAMILY, 13).into_font().color(&grey),
        ))
        .map_err(to_text)?;
    }
    draw_symbol_key(area, data, (x, bottom), interval_min)
}

/// The vessels the legend lists when it has `room` lines: ownship, then
/// every target in order when all fit; else the targets with the closest
/// approaches (in order of distance) in all but the last line, which says
/// how many are left out and how close the closest of them came.
pub(super) fn listed<'d, 'a>(
    data: &'d PlotData<'a>,
    room: usize,
) -> (Vec<&'d Track<'a>>, Option<(usize, f64)>) {
    let mut vessels = vec![&data.ownship];
    if data.targets.len() < room {
        vessels.extend(data.targets.iter());
        return (vessels, None);
    }
    let mut targets: Vec<&Track<'a>> = data.targets.iter().collect();
    targets.sort_by(|a, b| min_distance_m(a).total_cmp(&min_distance_m(b)));
    let shown = room.saturating_sub(2).min(targets.len());
    let left_out = &targets[shown..];
    let nearest_m = left_out
        .first()
        .map_or(f64::INFINITY, |t| min_distance_m(t));
    vessels.extend(&targets[..shown]);
    (vessels, Some((left_out.len(), nearest_m)))
}

fn min_distance_m(track: &Track<'_>) -> f64 {
    track
        .evaluation
        .map_or(f64::INFINITY, |evaluation| evaluation.min_distance_m)
}

/// `text` cut to fit `max_width_px` at `size_px`, ending in "…" when cut.
fn shorten(text: &str, size_px: f64, max_width_px: f64) -> String {
    if font::text_width_px(text, size_px) <= max_width_px {
        return text.to_owned();
    }
    let mut kept: String = text.to_owned();
    while !kept.is_empty() {
        kept.pop();
        let candidate = format!("{}…", kept.trim_end());
        if font::text_width_px(&candidate, size_px) <= max_width_px {
            return candidate;
        }
    }
    "…".to_owned()
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

/// One label of the key to the symbols, in the legend panel.
fn key_label<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    label: impl Into<String>,
    at: (i32, i32),
) -> Result<(), String> {
    area.draw(&Text::new(
        label.into(),
        at,
        (FAMILY, 13).into_font().color(&BLACK),
    ))
    .map_err(to_text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_names_are_shortened_to_the_panel() {
        let name = "MV Very Long Vessel Name Of The Coastal Trader  crossing_give_way";
        let short = shorten(name, 14.0, 196.0);
        assert!(short.ends_with('…'), "{short}");
        assert!(font::text_width_px(&short, 14.0) <= 196.0);
        assert!(short.starts_with("MV Very"));
        assert_eq!(shorten("TS1  head_on", 14.0, 196.0), "TS1  head_on");
    }
}
