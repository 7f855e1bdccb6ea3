//! Tests of whole plots of real runs, drawn on a backend that records what
//! is drawn, in order.

use super::legend::listed;
use super::speed::speed_changes;
use super::{OWNSHIP_COLOUR, PlotData, SIZE, draw_speed, draw_trajectories, write_plots};
use plotters::prelude::*;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
};
use std::cell::RefCell;
use std::rc::Rc;
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord, evaluate, simulate};

/// What was drawn: the colour, its opacity, the stroke width and the points
/// (the anchor of a text, the corners of a rectangle).
#[derive(Debug, Clone, PartialEq)]
enum Drawn {
    Shape {
        rgb: (u8, u8, u8),
        alpha: f64,
        width: u32,
        points: Vec<BackendCoord>,
    },
    Text(String),
}

/// A backend that draws nothing and records every shape and text.
struct Recorder {
    drawn: Rc<RefCell<Vec<Drawn>>>,
}

#[derive(Debug)]
struct NoError;

impl std::fmt::Display for NoError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("no error")
    }
}

impl std::error::Error for NoError {}

impl Recorder {
    fn shape<S: BackendStyle>(&mut self, style: &S, points: Vec<BackendCoord>) {
        let color = style.color();
        self.drawn.borrow_mut().push(Drawn::Shape {
            rgb: color.rgb,
            alpha: color.alpha,
            width: style.stroke_width(),
            points,
        });
    }
}

impl DrawingBackend for Recorder {
    type ErrorType = NoError;

    fn get_size(&self) -> (u32, u32) {
        SIZE
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<NoError>> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<NoError>> {
        Ok(())
    }

    fn draw_pixel(
        &mut self,
        _: BackendCoord,
        _: BackendColor,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.shape(style, vec![from, to]);
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        _: bool,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.shape(style, vec![upper_left, bottom_right]);
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.shape(style, path.into_iter().collect());
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        _: u32,
        style: &S,
        _: bool,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.shape(style, vec![center]);
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.shape(style, vert.into_iter().collect());
        Ok(())
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        _: &TStyle,
        _: BackendCoord,
    ) -> Result<(), DrawingErrorKind<NoError>> {
        self.drawn.borrow_mut().push(Drawn::Text(text.to_owned()));
        Ok(())
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<NoError>> {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a text box within a plot"
        )]
        let size = (
            crate::font::text_width_px(text, style.size()) as u32,
            crate::font::text_height_px(style.size()) as u32,
        );
        Ok(size)
    }
}

fn run(ron: &str) -> (Scenario, SimulationRecord, Evaluation) {
    let scenario = Scenario::from_ron_str(ron, "test.ron").unwrap();
    let record = simulate(&scenario, 1).unwrap();
    let evaluation = evaluate(&scenario, &record);
    (scenario, record, evaluation)
}

/// Ownship north at 12 kn for 3 nm; TS1 crosses ahead of it from starboard;
/// TS2, far off, stops at its goal 1 nm on after 5 min.
const SLOWING: &str = r#"Scenario(
    name: "slowing",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -1.5), course_deg: 0.0,
        speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.5)),
    targets: [
        Vessel(name: "TS1", start_nm: (1.5, 0.0), course_deg: 270.0, speed_kn: 12.0,
            length_m: 100.0, goal_nm: (-3.0, 0.0)),
        Vessel(name: "TS2", start_nm: (-3.0, -1.0), course_deg: 0.0, speed_kn: 12.0,
            length_m: 100.0, goal_nm: (-3.0, 0.0)),
    ],
    planner: (nodes_per_phase: 300),
)"#;

fn recorded(
    scenario: &Scenario,
    record: &SimulationRecord,
    evaluation: &Evaluation,
    speed: bool,
) -> Vec<Drawn> {
    crate::font::register();
    let data = PlotData::new(scenario, record, evaluation);
    let drawn = Rc::new(RefCell::new(Vec::new()));
    let root = Recorder {
        drawn: Rc::clone(&drawn),
    }
    .into_drawing_area();
    if speed {
        draw_speed(&root, &data).unwrap();
    } else {
        draw_trajectories(&root, &data).unwrap();
    }
    drop(root);
    Rc::try_unwrap(drawn).unwrap().into_inner()
}

fn rgb(colour: RGBColor) -> (u8, u8, u8) {
    (colour.0, colour.1, colour.2)
}

/// In the chart (left of the legend), ownship's track is drawn after every
/// opaque shape of every target: no target hides it.
#[test]
fn ownship_is_drawn_after_every_target() {
    let (scenario, record, evaluation) = run(SLOWING);
    let drawn = recorded(&scenario, &record, &evaluation, false);
    let samples = record.ownship.len();
    let ownship_track = drawn
        .iter()
        .position(|d| {
            matches!(d, Drawn::Shape { rgb: c, width: 3, points, .. }
                if *c == rgb(OWNSHIP_COLOUR) && points.len() >= samples / 2)
        })
        .expect("ownship's track is drawn");
    let targets: Vec<(u8, u8, u8)> = (0..scenario.targets.len())
        .map(|i| rgb(super::target_colour(i)))
        .collect();
    let last_target = drawn
        .iter()
        .rposition(|d| {
            matches!(d, Drawn::Shape { rgb: c, alpha, points, .. }
                if targets.contains(c)
                    && (*alpha - 1.0).abs() < 1e-9
                    && points.iter().all(|p| p.0 < 760))
        })
        .expect("targets are drawn");
    assert!(
        ownship_track > last_target,
        "ownship's track is shape {ownship_track}, a target's shape {last_target} comes after"
    );
}

/// The slowing scenario's speed plot shows TS2 stopping: its change is
/// found and labelled, and the files are written.
#[test]
fn speed_plot_shows_a_stop() {
    let (scenario, record, evaluation) = run(SLOWING);
    let data = PlotData::new(&scenario, &record, &evaluation);
    let minutes: Vec<f64> = record.times_s.iter().map(|t| t / 60.0).collect();
    let stop = speed_changes(&minutes, &data.targets[1].speeds_kn);
    assert_eq!(stop.len(), 1, "{stop:?}");
    assert!((stop[0].from_kn - 12.0).abs() < 0.01 && stop[0].to_kn.abs() < 0.01);
    assert!((4.0..=6.0).contains(&stop[0].time_min), "{stop:?}");
    let drawn = recorded(&scenario, &record, &evaluation, true);
    assert!(
        drawn.iter().any(|d| matches!(d, Drawn::Text(text)
            if text.starts_with("TS2 12.0 → 0.0 kn at"))),
        "the stop is labelled"
    );
    let dir = tempfile::tempdir().unwrap();
    write_plots(&scenario, &record, &evaluation, dir.path()).unwrap();
    for name in super::PLOT_FILES {
        assert!(dir.path().join(name).is_file(), "{name}");
    }
}

/// The legend lists every target while they fit; else the nearest first,
/// and says how many are left out and how near the nearest of them came.
#[test]
fn legend_lists_the_nearest_when_not_all_fit() {
    let (scenario, record, evaluation) = run(SLOWING);
    let mut evaluations = Vec::new();
    for k in 0..30 {
        let mut one = evaluation.targets[0].clone();
        one.min_distance_m = f64::from(3000 - 50 * k);
        evaluations.push(one);
    }
    let mut data = PlotData::new(&scenario, &record, &evaluation);
    let template = data.targets.remove(0);
    data.targets = evaluations
        .iter()
        .map(|e| super::Track {
            evaluation: Some(e),
            points_nm: template.points_nm.clone(),
            courses_rad: template.courses_rad.clone(),
            speeds_kn: template.speeds_kn.clone(),
            ..template
        })
        .collect();
    let (all, rest) = listed(&data, 40);
    assert_eq!((all.len(), rest), (31, None));
    let (some, rest) = listed(&data, 10);
    assert_eq!(some.len(), 9, "ownship and eight targets, then the count");
    assert!(some[0].evaluation.is_none());
    let shown: Vec<f64> = some[1..]
        .iter()
        .map(|t| t.evaluation.unwrap().min_distance_m)
        .collect();
    assert_eq!(
        shown,
        (0..8).map(|k| f64::from(1550 + 50 * k)).collect::<Vec<_>>()
    );
    assert_eq!(rest, Some((22, 1950.0)));
}
