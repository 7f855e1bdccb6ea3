//! Plots of a run, as SVG and PNG (1000 x 800 pixels):
//!
//! - `trajectories`: every vessel's track in nautical miles (ownship bold
//!   black), start dots, a course triangle every few minutes, goal crosses,
//!   at each target's closest approach the two positions joined by a dashed
//!   line with the distance written and the `d_th` circle around ownship,
//!   traffic lanes as shaded strips, land filled, and a legend beside the
//!   chart.
//! - `distance`: distance from ownship to each target over time (minutes,
//!   metres), `d_th` as a horizontal line, each minimum marked and labelled.
//! - `speed`: every vessel's speed over time (minutes, knots), ownship bold
//!   black on top, its speed changes labelled.
//!
//! Ownship is drawn after every target, so no target hides it; labels are
//! placed so that none overlaps another ([`labels`]); targets get 20
//! distinct colours, then a ramp ([`palette`]). PNG text uses the bundled
//! font, drawn glyph by glyph with its bearings ([`crate::font`]). Decision 36.

use crate::font::{self, FAMILY, GlyphText};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord, TargetEvaluation};

mod distance;
mod labels;
mod land;
mod legend;
mod palette;
#[cfg(test)]
mod render_tests;
mod speed;
mod time_axes;
mod trajectories;

use distance::draw_distance;
use labels::{LabelPlacer, PixelBox};
pub(crate) use palette::target_colour;
use speed::draw_speed;
use trajectories::draw_trajectories;

/// A chart of both plots, on `f64` axes (east and north in nautical miles;
/// minutes and metres).
type Chart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// Size of every plot, pixels.
pub(crate) const SIZE: (u32, u32) = (1000, 800);

const METRES_PER_NM: f64 = 1852.0;

const OWNSHIP_COLOUR: RGBColor = RGBColor(0, 0, 0);
const CLEARANCE_COLOUR: RGBColor = RGBColor(200, 0, 0);
const LANE_COLOUR: RGBColor = RGBColor(150, 110, 200);

fn to_text<E: std::fmt::Display>(error: E) -> String {
    format!("cannot draw a plot: {error}")
}

/// One vessel's track, in nautical miles.
struct Track<'a> {
    name: &'a str,
    colour: RGBColor,
    points_nm: Vec<(f64, f64)>,
    courses_rad: Vec<f64>,
    speeds_kn: Vec<f64>,
    goal_nm: Option<(f64, f64)>,
    evaluation: Option<&'a TargetEvaluation>,
}

/// Everything a plot needs, in plot units.
struct PlotData<'a> {
    title: &'a str,
    d_th_m: f64,
    times_s: &'a [f64],
    ownship: Track<'a>,
    targets: Vec<Track<'a>>,
    lanes: Vec<LaneShape<'a>>,
    /// Land areas, each its outer ring then its holes, nautical miles.
    land: Vec<land::LandShape>,
}

/// A traffic lane as drawn.
struct LaneShape<'a> {
    name: &'a str,
    /// The lane's corners, nautical miles.
    corners_nm: Vec<(f64, f64)>,
    /// Direction of traffic flow, degrees.
    course_deg: f64,
}

fn knots(speed_mps: f64) -> f64 {
    vorrt_geometry::units::mps_to_knots(speed_mps)
}

fn nm(point_m: glam::DVec2) -> (f64, f64) {
    (point_m.x / METRES_PER_NM, point_m.y / METRES_PER_NM)
}

impl<'a> PlotData<'a> {
    fn new(
        scenario: &'a Scenario,
        record: &'a SimulationRecord,
        evaluation: &'a Evaluation,
    ) -> Self {
        let ownship = Track {
            name: &scenario.ownship.name,
            colour: OWNSHIP_COLOUR,
            points_nm: record.ownship.iter().map(|s| nm(s.position_m)).collect(),
            courses_rad: record.ownship.iter().map(|s| s.course_rad).collect(),
            speeds_kn: record.ownship.iter().map(|s| knots(s.speed_mps)).collect(),
            goal_nm: Some(nm(scenario.ownship_goal_m())),
            evaluation: None,
        };
        let targets = record
            .targets
            .iter()
            .enumerate()
            .map(|(index, track)| Track {
                name: record
                    .target_names
                    .get(index)
                    .map_or("target", String::as_str),
                colour: target_colour(index),
                points_nm: track.iter().map(|s| nm(s.position_m)).collect(),
                courses_rad: track.iter().map(|s| s.course_rad).collect(),
                speeds_kn: track.iter().map(|s| knots(s.speed_mps)).collect(),
                goal_nm: scenario
                    .targets
                    .get(index)
                    .and_then(vorrt_scenarios::VesselSpec::goal_position_m)
                    .map(nm),
                evaluation: evaluation.targets.get(index),
            })
            .collect();
        let lanes = scenario
            .lanes
            .iter()
            .map(|lane| {
                let from = lane.from_m();
                let to = lane.to_m();
                let along = (to - from).normalize_or_zero();
                let across = glam::DVec2::new(-along.y, along.x) * (0.5 * lane.width_m());
                let corners = vec![
                    nm(from + across),
                    nm(to + across),
                    nm(to - across),
                    nm(from - across),
                ];
                LaneShape {
                    name: lane.name.as_str(),
                    corners_nm: corners,
                    course_deg: lane.traffic_course_rad().to_degrees().rem_euclid(360.0),
                }
            })
            .collect();
        Self {
            title: &scenario.name,
            d_th_m: evaluation.clearance_m,
            times_s: &record.times_s,
            ownship,
            targets,
            lanes,
            land: scenario
                .land_areas()
                .map(|area| {
                    area.rings_m
                        .iter()
                        .map(|ring| ring.iter().copied().map(nm).collect())
                        .collect()
                })
                .collect(),
        }
    }

    fn duration_s(&self) -> f64 {
        self.times_s.last().copied().unwrap_or(0.0)
    }

    /// Index of the recorded step nearest `time_s`.
    fn step_at(&self, time_s: f64) -> usize {
        let after = self.times_s.partition_point(|&t| t < time_s);
        if after == 0 {
            return 0;
        }
        if after >= self.times_s.len() {
            return self.times_s.len().saturating_sub(1);
        }
        if time_s - self.times_s[after - 1] <= self.times_s[after] - time_s {
            after - 1
        } else {
            after
        }
    }
}

/// Writes `trajectories.svg/.png`, `distance.svg/.png` and `speed.svg/.png`
/// into `dir`.
///
/// # Errors
/// A message when a file cannot be drawn or written.
pub(crate) fn write_plots(
    scenario: &Scenario,
    record: &SimulationRecord,
    evaluation: &Evaluation,
    dir: &Path,
) -> Result<(), String> {
    font::register();
    let data = PlotData::new(scenario, record, evaluation);
    for plot in Plot::ALL {
        let svg = dir.join(format!("{}.svg", plot.stem()));
        let root = SVGBackend::new(&svg, SIZE).into_drawing_area();
        plot.draw(&root, &data)?;
        root.present().map_err(to_text)?;
        let png = dir.join(format!("{}.png", plot.stem()));
        let root = GlyphText(BitMapBackend::new(&png, SIZE)).into_drawing_area();
        plot.draw(&root, &data)?;
        root.present().map_err(to_text)?;
    }
    Ok(())
}

/// The plots written beside `report.json`, each as SVG and PNG.
#[derive(Debug, Clone, Copy)]
enum Plot {
    /// Every vessel's track, closest approaches, `d_th` and lanes.
    Trajectories,
    /// Distance from ownship to each target over time.
    Distance,
    /// Every vessel's speed over time.
    Speed,
}

/// The file names of every plot [`write_plots`] writes, SVG then PNG.
pub(crate) const PLOT_FILES: [&str; 6] = [
    "trajectories.svg",
    "trajectories.png",
    "distance.svg",
    "distance.png",
    "speed.svg",
    "speed.png",
];

impl Plot {
    /// Every plot, in the order written.
    const ALL: [Plot; 3] = [Plot::Trajectories, Plot::Distance, Plot::Speed];

    /// File name without extension.
    fn stem(self) -> &'static str {
        match self {
            Plot::Trajectories => "trajectories",
            Plot::Distance => "distance",
            Plot::Speed => "speed",
        }
    }

    fn draw<DB: DrawingBackend>(
        self,
        root: &DrawingArea<DB, Shift>,
        data: &PlotData<'_>,
    ) -> Result<(), String> {
        match self {
            Plot::Trajectories => draw_trajectories(root, data),
            Plot::Distance => draw_distance(root, data),
            Plot::Speed => draw_speed(root, data),
        }
    }
}

/// A rectangle of the data plane.
#[derive(Debug, Clone, Copy, PartialEq)]
struct View {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl View {
    fn contains(&self, (x, y): (f64, f64)) -> bool {
        (self.x0..=self.x1).contains(&x) && (self.y0..=self.y1).contains(&y)
    }
}

/// The smallest view holding `points`, padded, with `width_px / height_px`
/// as its aspect ratio so that one nautical mile is as long east as north.
fn fit_view(points: impl Iterator<Item = (f64, f64)>, width_px: f64, height_px: f64) -> View {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for (x, y) in points.filter(|(x, y)| x.is_finite() && y.is_finite()) {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !x0.is_finite() {
        (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
    }
    let span = (x1 - x0).max(y1 - y0).max(0.5);
    let pad = 0.06 * span;
    let (mut x0, mut x1, mut y0, mut y1) = (x0 - pad, x1 + pad, y0 - pad, y1 + pad);
    let aspect = (width_px / height_px.max(1.0)).max(0.1);
    let (width, height) = (x1 - x0, y1 - y0);
    if width / height < aspect {
        let extra = 0.5 * (height * aspect - width);
        x0 -= extra;
        x1 += extra;
    } else {
        let extra = 0.5 * (width / aspect - height);
        y0 -= extra;
        y1 += extra;
    }
    View { x0, x1, y0, y1 }
}

/// Clips a convex polygon to `view` (Sutherland-Hodgman).
fn clip_polygon(polygon: &[(f64, f64)], view: &View) -> Vec<(f64, f64)> {
    type Inside = fn(&View, (f64, f64)) -> bool;
    type Cross = fn(&View, (f64, f64), (f64, f64)) -> (f64, f64);
    let edges: [(Inside, Cross); 4] = [
        (
            |v, p| p.0 >= v.x0,
            |v, a, b| {
                let t = (v.x0 - a.0) / (b.0 - a.0);
                (v.x0, a.1 + t * (b.1 - a.1))
            },
        ),
        (
            |v, p| p.0 <= v.x1,
            |v, a, b| {
                let t = (v.x1 - a.0) / (b.0 - a.0);
                (v.x1, a.1 + t * (b.1 - a.1))
            },
        ),
        (
            |v, p| p.1 >= v.y0,
            |v, a, b| {
                let t = (v.y0 - a.1) / (b.1 - a.1);
                (a.0 + t * (b.0 - a.0), v.y0)
            },
        ),
        (
            |v, p| p.1 <= v.y1,
            |v, a, b| {
                let t = (v.y1 - a.1) / (b.1 - a.1);
                (a.0 + t * (b.0 - a.0), v.y1)
            },
        ),
    ];
    let mut output = polygon.to_vec();
    for (inside, cross) in edges {
        let input = std::mem::take(&mut output);
        let Some(&last) = input.last() else {
            break;
        };
        let mut previous = last;
        for &point in &input {
            match (inside(view, point), inside(view, previous)) {
                (true, true) => output.push(point),
                (true, false) => {
                    output.push(cross(view, previous, point));
                    output.push(point);
                }
                (false, true) => output.push(cross(view, previous, point)),
                (false, false) => {}
            }
            previous = point;
        }
    }
    output
}

/// Splits a polyline into the runs that lie below `y_max`, cutting segments
/// at the line.
fn clip_below(points: &[(f64, f64)], y_max: f64) -> Vec<Vec<(f64, f64)>> {
    let mut runs = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let crossing = |a: (f64, f64), b: (f64, f64)| {
            let t = (y_max - a.1) / (b.1 - a.1);
            (a.0 + t * (b.0 - a.0), y_max)
        };
        match (a.1 <= y_max, b.1 <= y_max) {
            (true, true) => {
                if run.is_empty() {
                    run.push(a);
                }
                run.push(b);
            }
            (true, false) => {
                if run.is_empty() {
                    run.push(a);
                }
                run.push(crossing(a, b));
                runs.push(std::mem::take(&mut run));
            }
            (false, true) => {
                run.push(crossing(a, b));
                run.push(b);
            }
            (false, false) => {}
        }
    }
    if points.len() == 1 && points[0].1 <= y_max {
        run.push(points[0]);
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs
}

/// Minutes between course markers: a round number giving about eight markers.
fn marker_interval_min(duration_s: f64) -> f64 {
    let wanted = duration_s / 60.0 / 8.0;
    [1.0, 2.0, 5.0, 10.0, 15.0, 20.0, 30.0, 60.0, 120.0, 240.0]
        .into_iter()
        .find(|&step| step >= wanted)
        .unwrap_or(480.0)
}

/// A triangle pointing along `course_rad`, in pixel offsets (y down).
fn triangle(course_rad: f64, size: f64) -> Vec<(i32, i32)> {
    let (dx, dy) = (course_rad.sin(), -course_rad.cos());
    let (px, py) = (-dy, dx);
    #[expect(
        clippy::cast_possible_truncation,
        reason = "pixel offsets of a marker a few pixels in size"
    )]
    let point = |along: f64, side: f64| {
        (
            (along * dx + side * px).round() as i32,
            (along * dy + side * py).round() as i32,
        )
    };
    vec![
        point(size, 0.0),
        point(-0.6 * size, 0.6 * size),
        point(-0.6 * size, -0.6 * size),
    ]
}

fn circle_points(centre: (f64, f64), radius: f64) -> Vec<(f64, f64)> {
    (0..=72)
        .map(|i| {
            let angle = f64::from(i) * std::f64::consts::TAU / 72.0;
            (
                centre.0 + radius * angle.cos(),
                centre.1 + radius * angle.sin(),
            )
        })
        .collect()
}

/// Most closest approaches labelled in a plot; with more targets only the
/// closest ones are labelled.
const MAX_LABELS: usize = 6;

/// Most closest approaches marked (the two positions joined, `d_th` around
/// ownship) in the trajectories plot: with more targets the marks of the
/// far ones would hide the near ones.
const MAX_MARKED: usize = 12;

/// How many of `targets` targets are named in a chart (at their start, in a
/// series legend): all up to the 20 with colours of their own, else the
/// [`MAX_MARKED`] closest.
fn named_count(targets: usize) -> usize {
    if targets <= 20 { targets } else { MAX_MARKED }
}

/// Whether each target is among the `count` with the closest approaches.
fn closest(targets: &[Track<'_>], count: usize) -> Vec<bool> {
    let mut order: Vec<(usize, f64)> = targets
        .iter()
        .enumerate()
        .map(|(index, target)| {
            (
                index,
                target
                    .evaluation
                    .map_or(f64::INFINITY, |e| e.min_distance_m),
            )
        })
        .collect();
    order.sort_by(|a, b| a.1.total_cmp(&b.1));
    let mut chosen = vec![false; targets.len()];
    for (index, _) in order.into_iter().take(count) {
        chosen[index] = true;
    }
    chosen
}

/// Whether each target's closest approach gets a label: the [`MAX_LABELS`]
/// closest ones.
fn labelled(targets: &[Track<'_>]) -> Vec<bool> {
    closest(targets, MAX_LABELS)
}

/// A label to place: its text, at a point of the chart.
struct Label {
    text: String,
    /// The point it names, in chart units.
    at: (f64, f64),
    colour: RGBColor,
    size_px: u32,
}

/// A placer for labels in the plotting area of `chart`.
fn placer_for<DB: DrawingBackend>(chart: &Chart<'_, DB>) -> LabelPlacer {
    let (x, y) = chart.plotting_area().get_pixel_range();
    LabelPlacer::new(PixelBox {
        x0: f64::from(x.start),
        y0: f64::from(y.start),
        x1: f64::from(x.end),
        y1: f64::from(y.end),
    })
}

/// Places `labels` in order with `placer` and draws those that fit, each on
/// a faint white box, with a thin leader line when it sits away from its
/// point. Returns how many were drawn.
fn draw_labels<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    placer: &mut LabelPlacer,
    labels: &[Label],
) -> Result<usize, String> {
    let mut drawn = 0;
    for label in labels {
        let anchor = chart.backend_coord(&label.at);
        let anchor_px = (f64::from(anchor.0), f64::from(anchor.1));
        let size = f64::from(label.size_px);
        // A little slack: an SVG viewer's sans-serif may be wider than ours.
        let box_px = (
            1.06 * font::text_width_px(&label.text, size) + 2.0,
            font::text_height_px(size) + 2.0,
        );
        let Some(placement) = placer.place(anchor_px, box_px) else {
            continue;
        };
        #[expect(
            clippy::cast_possible_truncation,
            reason = "pixel offsets within a plot"
        )]
        let offset = |x: f64, y: f64| ((x - anchor_px.0) as i32, (y - anchor_px.1) as i32);
        let (left, top) = placement.top_left_px;
        let corner = offset(left, top);
        let far = offset(left + box_px.0, top + box_px.1);
        if placement.leader {
            let near = offset(
                anchor_px.0.clamp(left, left + box_px.0),
                anchor_px.1.clamp(top, top + box_px.1),
            );
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(label.at)
                        + PathElement::new(vec![(0, 0), near], label.colour.mix(0.7)),
                ))
                .map_err(to_text)?;
        }
        chart
            .draw_series(std::iter::once(
                EmptyElement::at(label.at)
                    + Rectangle::new([corner, far], WHITE.mix(0.75).filled())
                    + Text::new(
                        label.text.clone(),
                        (corner.0 + 1, corner.1 + 1),
                        (FAMILY, label.size_px).into_font().color(&label.colour),
                    ),
            ))
            .map_err(to_text)?;
        drawn += 1;
    }
    Ok(drawn)
}

/// An axis tick: whole numbers without decimals, others with up to two.
fn tick(value: f64) -> String {
    if value.abs() < 1e-9 {
        "0".to_owned()
    } else if (value - value.round()).abs() < 1e-6 {
        format!("{value:.0}")
    } else if (value * 10.0 - (value * 10.0).round()).abs() < 1e-6 {
        format!("{value:.1}")
    } else {
        format!("{value:.2}")
    }
}

fn format_distance(distance_m: f64) -> String {
    if distance_m >= 10_000.0 {
        format!("{:.1} km", distance_m / 1000.0)
    } else {
        format!("{distance_m:.0} m")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn view_keeps_aspect_and_points() {
        let view = fit_view(
            [(0.0, -3.0), (0.0, 3.0), (3.0, 0.0)].into_iter(),
            800.0,
            600.0,
        );
        assert!(((view.x1 - view.x0) / (view.y1 - view.y0) - 800.0 / 600.0).abs() < 1e-9);
        assert!(view.contains((0.0, -3.0)) && view.contains((3.0, 0.0)));
    }

    #[test]
    fn polygon_clipped_to_view() {
        let view = View {
            x0: -1.0,
            x1: 1.0,
            y0: -1.0,
            y1: 1.0,
        };
        let lane = [(-8.0, 0.5), (8.0, 0.5), (8.0, -0.5), (-8.0, -0.5)];
        let clipped = clip_polygon(&lane, &view);
        assert!(
            clipped
                .iter()
                .all(|p| p.0.abs() <= 1.0 && p.1.abs() <= 0.5 + 1e-12)
        );
        assert_eq!(clipped.len(), 4);
    }

    #[test]
    fn polyline_cut_at_top() {
        let runs = clip_below(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], 1.0);
        assert_eq!(runs.len(), 2);
        assert_eq!(runs[0], vec![(0.0, 0.0), (0.5, 1.0)]);
        assert_eq!(runs[1], vec![(1.5, 1.0), (2.0, 0.0)]);
    }

    #[test]
    fn marker_interval_is_round() {
        #![expect(clippy::float_cmp, reason = "the intervals are exact round numbers")]
        assert_eq!(marker_interval_min(30.0 * 60.0), 5.0);
        assert_eq!(marker_interval_min(60.0), 1.0);
    }
}
