//! A scenario's static surroundings, land and no-go areas, as one
//! [`Constraint`] and as the one measure of a track's distance from land
//! (decision 29).
//!
//! [`ClosedLoop::new`](crate::ClosedLoop::new) builds a [`Chart`] from its
//! scenario, so every plan, replan, check of the plan in force and evasive
//! manoeuvre keeps off land, and [`evaluate`](crate::evaluate) measures the
//! sailed track with the same geometry. An empty chart (the open sea)
//! refuses nothing and costs one untaken branch per query.

use crate::error::ScenarioError;
use crate::scenario::Scenario;
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use vorrt_colregs::VesselState;
use vorrt_geometry::DVec2;
use vorrt_planner::constraint::{Constraint, ConstraintViolation, Segment};
use vorrt_planner::land::LandConstraint;

/// Land and no-go areas of a scenario, in its local frame (metres).
///
/// ```
/// use vorrt_scenarios::{Area, Chart, Scenario, VesselSpec};
/// use vorrt_scenarios::planner::constraint::Constraint;
/// use vorrt_scenarios::DVec2;
/// let mut scenario = Scenario::from_ron_str(
///     "(name: \"x\", ownship: Vessel(name: \"own\", start_nm: (0.0, 0.0), course_deg: 0.0, speed_kn: 12.0, length_m: 50.0, goal_nm: (0.0, 6.0)),
///       land: [Area(name: \"rock\", outer_nm: [(1.0, 2.0), (2.0, 2.0), (2.0, 3.0)])])",
///     "rock",
/// ).unwrap();
/// let chart = Chart::from_scenario(&scenario).unwrap();
/// assert!(!chart.is_empty());
/// assert!(chart.land_distance_m(DVec2::ZERO) > 3000.0);
/// // The planner keeps the clearance and half the ship's length.
/// assert_eq!(chart.planner_land_clearance_m(), scenario.land_clearance_m() + 25.0);
/// assert!(!chart.admits_point(DVec2::new(1852.0, 1852.0 * 2.0 - 10.0)));
/// ```
#[derive(Debug, Clone, Default)]
pub struct Chart {
    /// Land, kept the planner's clearance off (`None`: no land).
    land: Option<Arc<LandConstraint>>,
    /// No-go areas, kept half ownship's length off (`None`: none).
    no_go: Option<Arc<LandConstraint>>,
    /// Whether there is either: the open sea's queries test this alone.
    occupied: bool,
    /// The clearance the track is judged against, metres.
    land_clearance_m: f64,
    /// The clearance the planner keeps, metres.
    planner_land_clearance_m: f64,
}

impl Chart {
    /// The open sea: no land, no no-go area.
    #[must_use]
    pub fn open_sea() -> Self {
        Self::default()
    }

    /// The chart of a validated `scenario`: its land (the `land` areas and
    /// the `land_geojson` polygons) kept `land_clearance_m` plus half
    /// ownship's length off by the planner, and its no-go areas kept half
    /// ownship's length off.
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`] (field `land`) when an area has not been
    /// validated (its rings not projected) or a clearance is out of range.
    pub fn from_scenario(scenario: &Scenario) -> Result<Self, ScenarioError> {
        let invalid = |field: &str, problem: String| ScenarioError::Invalid {
            file: scenario.source.clone(),
            field: field.into(),
            problem,
        };
        let half_length_m = scenario.ownship.length_m / 2.0;
        let land_clearance_m = scenario.land_clearance_m();
        let planner_land_clearance_m = land_clearance_m + half_length_m;
        let land: Vec<_> = scenario.land_areas().map(crate::Area::polygon_m).collect();
        let no_go: Vec<_> = scenario.no_go.iter().map(crate::Area::polygon_m).collect();
        let build = |polygons: &[::geo::Polygon<f64>],
                     clearance_m: f64,
                     field: &str,
                     no_go: bool| {
            if polygons.is_empty() {
                return Ok(None);
            }
            let built = if no_go {
                LandConstraint::no_go(polygons, clearance_m)
            } else {
                LandConstraint::new(polygons, clearance_m)
            };
            built
                .map(|constraint| Some(Arc::new(constraint)))
                .map_err(|error| invalid(field, format!("{error} (validate the scenario first)")))
        };
        let land = build(&land, planner_land_clearance_m, "land", false)?;
        let no_go = build(&no_go, half_length_m, "no_go", true)?;
        Ok(Self {
            occupied: land.is_some() || no_go.is_some(),
            land,
            no_go,
            land_clearance_m,
            planner_land_clearance_m,
        })
    }

    /// Whether there is neither land nor a no-go area.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        !self.occupied
    }

    /// Whether there is land.
    #[must_use]
    pub fn has_land(&self) -> bool {
        self.land.is_some()
    }

    /// The distance ownship's track is judged to keep from land, metres.
    #[must_use]
    pub fn land_clearance_m(&self) -> f64 {
        self.land_clearance_m
    }

    /// The distance the planner keeps from land, metres: the judged
    /// clearance and half ownship's length.
    #[must_use]
    pub fn planner_land_clearance_m(&self) -> f64 {
        self.planner_land_clearance_m
    }

    /// The distance from `point_m` to land, metres: 0 on land, infinite
    /// with no land.
    #[must_use]
    pub fn land_distance_m(&self, point_m: DVec2) -> f64 {
        self.land
            .as_ref()
            .map_or(f64::INFINITY, |land| land.distance_m(point_m))
    }

    /// The least distance from the segment `start_m`-`end_m` to land,
    /// metres: 0 where it crosses or lies on land, infinite with no land.
    #[must_use]
    pub fn segment_land_distance_m(&self, start_m: DVec2, end_m: DVec2) -> f64 {
        self.land.as_ref().map_or(f64::INFINITY, |land| {
            land.segment_distance_m(start_m, end_m)
        })
    }

    /// Whether `point_m` lies inside a no-go area.
    #[must_use]
    pub fn in_no_go(&self, point_m: DVec2) -> bool {
        self.no_go
            .as_ref()
            .is_some_and(|no_go| no_go.contains(point_m))
    }
}

/// How ownship's track passed land: the one judgement of grounding
/// (decision 29), read by the evaluation, batch rows and `vorrt judge`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LandPassage {
    /// The least distance from the curve sailed to land, metres: a lower
    /// bound within a metre or so (see [`Chart::judge_track`]); 0 when the
    /// track touched or crossed land.
    pub min_distance_m: f64,
    /// When the track came nearest, seconds: the start of that step.
    pub time_s: f64,
    /// The clearance judged against (`land_clearance_m`), metres.
    pub clearance_m: f64,
    /// The track touched or crossed land (`min_distance_m` is 0): a
    /// safety failure beside a collision.
    pub grounding: bool,
    /// The track kept `clearance_m` from land (a clearance finding when not,
    /// as `d_th` is for targets).
    pub clearance_kept: bool,
}

impl Chart {
    /// Judges a track (ownship's `states` at `times_s`) against the land:
    /// `None` with no land or no state. Each step between two samples is
    /// measured as the segment between them (the exact distance from the
    /// R-tree of the coast, not only at the samples), less the farthest the
    /// curve sailed can stray from that chord: a curve of length `s`
    /// between points `c` apart lies within `sqrt(s² - c²) / 2` of their
    /// segment (it lies inside the ellipse with those foci), and with a
    /// rate-of-turn limit `ω` at speed `v` within the sagitta
    /// `v/ω (1 - cos(ω dt / 2))`; `s` is the larger speed of the two
    /// samples times the step.
    #[must_use]
    pub fn judge_track(
        &self,
        times_s: &[f64],
        states: &[VesselState],
        max_turn_rate_rad_s: Option<f64>,
    ) -> Option<LandPassage> {
        let land = self.land.as_ref()?;
        let first = states.first()?;
        let mut nearest = (
            land.distance_m(first.position_m),
            times_s.first().copied().unwrap_or(0.0),
        );
        for (index, pair) in states.windows(2).enumerate() {
            let (from, to) = (pair[0].position_m, pair[1].position_m);
            let step_s = match (times_s.get(index), times_s.get(index + 1)) {
                (Some(start), Some(end)) => end - start,
                _ => 0.0,
            };
            let chord_m = from.distance(to);
            let sailed_m = (pair[0].speed_mps.max(pair[1].speed_mps) * step_s).max(chord_m);
            let mut stray_m = (sailed_m * sailed_m - chord_m * chord_m).max(0.0).sqrt() / 2.0;
            if let Some(rate) = max_turn_rate_rad_s.filter(|rate| *rate > 0.0) {
                let speed_mps = if step_s > 0.0 { sailed_m / step_s } else { 0.0 };
                let half_angle = (rate * step_s / 2.0).min(std::f64::consts::FRAC_PI_2);
                stray_m = stray_m.min(speed_mps / rate * (1.0 - half_angle.cos()));
            }
            let distance_m = (land.segment_distance_m(from, to) - stray_m).max(0.0);
            if distance_m < nearest.0 {
                nearest = (distance_m, times_s.get(index).copied().unwrap_or(0.0));
            }
        }
        Some(LandPassage {
            min_distance_m: nearest.0,
            time_s: nearest.1,
            clearance_m: self.land_clearance_m,
            grounding: nearest.0 <= 0.0,
            // A grounding breaks even a clearance of 0.
            clearance_kept: nearest.0 > 0.0 && nearest.0 >= self.land_clearance_m,
        })
    }
}

impl Constraint for Chart {
    #[inline]
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        if !self.occupied {
            return Ok(());
        }
        if let Some(land) = &self.land {
            land.check_segment(segment)?;
        }
        if let Some(no_go) = &self.no_go {
            no_go.check_segment(segment)?;
        }
        Ok(())
    }

    #[inline]
    fn admits_point(&self, point_m: DVec2) -> bool {
        if !self.occupied {
            return true;
        }
        self.land
            .as_ref()
            .is_none_or(|land| land.admits_point(point_m))
            && self
                .no_go
                .as_ref()
                .is_none_or(|no_go| no_go.admits_point(point_m))
    }
}

/// The checks of a vessel's position against the chart, for validation:
/// ownship's start and goal keep the planner's land clearance and lie
/// outside every no-go area, and no target starts on land.
pub(crate) fn check_off_land(scenario: &Scenario) -> Result<(), (String, String)> {
    let chart = Chart::from_scenario(scenario).map_err(|error| {
        (
            error.field().unwrap_or("land").to_owned(),
            error.to_string(),
        )
    })?;
    if chart.is_empty() {
        return Ok(());
    }
    let ownship = &scenario.ownship;
    let start_field = crate::validate::start_field(ownship);
    let goal_field = if ownship.goal_nm.is_some() {
        "goal_nm"
    } else if ownship.goal_m.is_some() {
        "goal_m"
    } else {
        "goal_lat_lon"
    };
    for (field, position_m) in [
        (start_field, scenario.ownship_state().position_m),
        (goal_field, scenario.ownship_goal_m()),
    ] {
        let distance_m = chart.land_distance_m(position_m);
        if distance_m < chart.planner_land_clearance_m() {
            let problem = if distance_m == 0.0 {
                "is on land".to_owned()
            } else {
                format!(
                    "is {distance_m:.0} m from land, within the {:.0} m the planner keeps (land_clearance_m {:.0} m and half ownship's length)",
                    chart.planner_land_clearance_m(),
                    chart.land_clearance_m()
                )
            };
            return Err((format!("ownship.{field}"), problem));
        }
        if chart.in_no_go(position_m) {
            return Err((format!("ownship.{field}"), "is inside a no-go area".into()));
        }
    }
    for (index, target) in scenario.targets.iter().enumerate() {
        if chart.land_distance_m(target.state().position_m) == 0.0 {
            return Err((
                format!(
                    "targets[{index}] {:?}.{}",
                    target.name,
                    crate::validate::start_field(target)
                ),
                "is on land".into(),
            ));
        }
    }
    Ok(())
}

/// Everything a plan of `scenario` keeps beside the COLREGs: its [`Chart`]
/// (land, no-go areas) and its traffic separation scheme
/// ([`crate::scenario_constraint`]). The one place `vorrt plan`, the Python
/// package's `plan` and the closed loop ([`crate::ClosedLoop`], which pairs
/// the chart with the constraint it is given) get them from.
///
/// # Errors
/// As [`Chart::from_scenario`].
pub fn planning_constraint(
    scenario: &Scenario,
) -> Result<(Chart, vorrt_planner::scheme::SchemeConstraint), ScenarioError> {
    Ok((
        Chart::from_scenario(scenario)?,
        crate::scenario_constraint(scenario),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Area;

    fn scenario_with(land: Vec<Area>) -> Result<Scenario, ScenarioError> {
        let mut scenario = crate::fixtures::find("paper/crossing")
            .expect("bundled")
            .load()
            .expect("loads");
        scenario.land = land;
        scenario.validate()?;
        Ok(scenario)
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "no land is exactly infinitely far")]
    fn an_empty_chart_refuses_nothing() {
        let chart = Chart::open_sea();
        assert!(chart.is_empty() && !chart.has_land());
        let far = DVec2::splat(1e7);
        assert!(chart.admits_point(far));
        assert_eq!(chart.land_distance_m(far), f64::INFINITY);
        assert_eq!(chart.segment_land_distance_m(far, -far), f64::INFINITY);
        assert!(!chart.in_no_go(far));
    }

    #[test]
    fn a_track_cutting_a_corner_is_a_grounding() {
        let mut scenario = scenario_with(Vec::new()).expect("valid");
        // A headland east of x = 1 km, its tip at y = 3 km.
        let mut headland = Area::from_nm("headland", Vec::new());
        headland.outer_nm = None;
        headland.outer_m = Some(vec![
            (1000.0, -9000.0),
            (9000.0, -9000.0),
            (9000.0, 3000.0),
            (1000.0, 3000.0),
        ]);
        scenario.land = vec![headland];
        scenario.land_clearance_m = Some(0.0);
        scenario.ownship.start_nm = Some((0.0, 0.0));
        scenario.ownship.goal_nm = Some((3.0, 3.0));
        scenario.targets.clear();
        scenario.validate().expect("valid");
        let chart = Chart::from_scenario(&scenario).unwrap();
        let state = |x: f64, y: f64| VesselState::new(DVec2::new(x, y), 0.0, 5.0, 50.0);
        // Round the tip 500 m off, then cut across it.
        let rounding = [state(0.0, 0.0), state(0.0, 3500.0), state(5000.0, 3500.0)];
        let times = [0.0, 700.0, 1700.0];
        let passage = chart.judge_track(&times, &rounding, Some(0.02)).unwrap();
        assert!(
            !passage.grounding && (passage.min_distance_m - 500.0).abs() < 1.0,
            "{passage:?}"
        );
        let cutting = [state(0.0, 0.0), state(5000.0, 3500.0)];
        let passage = chart.judge_track(&times[..2], &cutting, None).unwrap();
        assert!(passage.grounding && !passage.clearance_kept, "{passage:?}");
        assert!(
            Chart::open_sea()
                .judge_track(&times, &rounding, None)
                .is_none()
        );
    }

    #[test]
    fn ownship_and_targets_must_start_off_land() {
        let scenario = scenario_with(Vec::new()).expect("valid");
        let start = scenario.ownship_state().position_m / 1852.0;
        let square = |centre: DVec2, half: f64| {
            Area::from_nm(
                "rock",
                vec![
                    (centre.x - half, centre.y - half),
                    (centre.x + half, centre.y - half),
                    (centre.x + half, centre.y + half),
                    (centre.x - half, centre.y + half),
                ],
            )
        };
        let error = scenario_with(vec![square(start, 0.1)]).unwrap_err();
        assert_eq!(error.field(), Some("ownship.start_nm"), "{error}");
        assert!(error.to_string().contains("is on land"), "{error}");
        let near = scenario_with(vec![square(start + DVec2::new(0.3, 0.0), 0.1)]).unwrap_err();
        assert!(near.to_string().contains("within the"), "{near}");
        let target = scenario.targets[0].state().position_m / 1852.0;
        let error = scenario_with(vec![square(target, 0.05)]).unwrap_err();
        assert!(error.field().unwrap().starts_with("targets[0]"), "{error}");
        let far = scenario_with(vec![square(DVec2::new(50.0, 50.0), 1.0)]).expect("valid");
        let chart = Chart::from_scenario(&far).unwrap();
        assert!(chart.has_land());
        assert!(chart.land_distance_m(DVec2::ZERO) > 40.0 * 1852.0);
    }

    /// The planning constraint refuses a leg over the island fixture's
    /// island (land) and keeps nothing from a leg far off it.
    #[test]
    fn the_planning_constraint_keeps_the_land() {
        let scenario = crate::fixtures::find("coastal/island")
            .expect("bundled")
            .load()
            .unwrap();
        let constraint = planning_constraint(&scenario).unwrap();
        let leg = |east_m: f64| Segment {
            start_m: DVec2::new(east_m, -5000.0),
            end_m: DVec2::new(east_m, 5000.0),
            margin_m: 0.0,
            start_elapsed_s: 0.0,
            duration_s: 1600.0,
            course_rad: 0.0,
            course_spread_rad: 0.0,
        };
        assert_eq!(
            constraint.check_segment(&leg(0.0)),
            Err(ConstraintViolation::Land)
        );
        assert_eq!(constraint.check_segment(&leg(20_000.0)), Ok(()));
    }
}
