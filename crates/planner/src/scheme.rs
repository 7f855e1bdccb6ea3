//! Rule 10 as a planner [`Constraint`]: a traffic separation scheme
//! (`vorrt_colregs::rule10`) refuses every piece of ownship's motion in a
//! lane on a heading neither with its flow nor square across it (10(b)(i),
//! 10(c)), and every piece in a separation zone not square across it
//! (10(e)). The judge reads the same predicates on the track
//! ([`vorrt_colregs::rule10::judge_track`]).

use crate::constraint::{Constraint, ConstraintViolation, Segment};
use glam::DVec2;
use std::sync::Arc;
use vorrt_colregs::rule10::{LaneUse, Scheme};

/// A traffic separation scheme as a planner constraint, for a vessel on a
/// route from a start to a goal (which lanes it crosses and which it
/// follows: [`Scheme::lane_uses`]). Cheap to clone (the closed loop gives
/// one to each planner of its graded fallback); an empty scheme refuses
/// nothing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SchemeConstraint {
    scheme: Arc<Scheme>,
    uses: Arc<[LaneUse]>,
}

impl SchemeConstraint {
    /// The constraint of `scheme` on a route from `start_m` to `goal_m`
    /// (the scenario's: a replan from inside a lane still crosses it).
    ///
    /// ```
    /// use vorrt_planner::scheme::SchemeConstraint;
    /// use vorrt_planner::colregs::rule10::Scheme;
    /// use vorrt_planner::DVec2;
    /// let open_sea = SchemeConstraint::new(Scheme::default(), DVec2::ZERO, DVec2::Y);
    /// assert!(open_sea.scheme().is_empty());
    /// ```
    #[must_use]
    pub fn new(scheme: Scheme, start_m: DVec2, goal_m: DVec2) -> Self {
        let uses = scheme.lane_uses(start_m, goal_m).into();
        Self {
            scheme: Arc::new(scheme),
            uses,
        }
    }

    /// How the route uses each lane.
    #[must_use]
    pub fn lane_uses(&self) -> &[LaneUse] {
        &self.uses
    }

    /// The scheme it keeps.
    #[must_use]
    pub fn scheme(&self) -> &Scheme {
        &self.scheme
    }
}

impl Constraint for SchemeConstraint {
    #[inline]
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        if self.scheme.is_empty() {
            return Ok(());
        }
        // Every heading along the piece (a chord of a turn sweeps
        // `course_spread_rad` either way of its course): the judge of rule
        // 10 samples the heading anywhere in a lane.
        let spread_rad = segment.course_spread_rad;
        let headings = [0.0, -spread_rad, spread_rad];
        let count = if spread_rad > 0.0 { 3 } else { 1 };
        headings[..count].iter().try_for_each(|offset_rad| {
            self.scheme
                .check_segment(
                    &self.uses,
                    segment.start_m,
                    segment.end_m,
                    segment.margin_m,
                    segment.course_rad + offset_rad,
                )
                .map_err(|_| ConstraintViolation::TrafficLane)
        })
    }

    /// Every point: a lane or a zone may be crossed.
    #[inline]
    fn admits_point(&self, _point_m: DVec2) -> bool {
        true
    }

    /// A route that crosses a lane picks its gap by speed first
    /// ([`crate::crossing`]).
    fn prefers_speed_changes(&self) -> bool {
        self.uses.contains(&LaneUse::Crossing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vorrt_colregs::rule10::TrafficLane;

    fn segment(course_deg: f64) -> Segment {
        Segment {
            start_m: DVec2::new(0.0, -50.0),
            end_m: DVec2::new(0.0, 50.0),
            margin_m: 0.0,
            start_elapsed_s: 0.0,
            duration_s: 10.0,
            course_rad: course_deg.to_radians(),
            course_spread_rad: 0.0,
        }
    }

    #[test]
    fn a_lane_refuses_an_oblique_heading_and_the_open_sea_nothing() {
        let lane = TrafficLane {
            from_m: DVec2::new(5000.0, 0.0),
            to_m: DVec2::new(-5000.0, 0.0),
            width_m: 1852.0,
        };
        let constraint = SchemeConstraint::new(
            Scheme {
                lanes: vec![lane],
                ..Scheme::default()
            },
            DVec2::new(0.0, -5000.0),
            DVec2::new(0.0, 5000.0),
        );
        assert_eq!(constraint.lane_uses(), [LaneUse::Crossing]);
        assert!(constraint.prefers_speed_changes());
        assert!(!SchemeConstraint::default().prefers_speed_changes());
        // West-north-west with the flow: refused on a crossing.
        assert!(constraint.check_segment(&segment(290.0)).is_err());
        assert!(constraint.check_segment(&segment(0.0)).is_ok());
        assert_eq!(
            constraint.check_segment(&segment(45.0)),
            Err(ConstraintViolation::TrafficLane)
        );
        // A chord of a turn whose middle heading (12°) is square within
        // tolerance (15°) but which sweeps from 8° to 16°: the heading at
        // its end is not, and an observer sampling it in the lane sees it.
        let chord = segment(12.0).with_headings(8f64.to_radians(), 16f64.to_radians());
        assert!((chord.course_spread_rad.to_degrees() - 4.0).abs() < 1e-9);
        assert_eq!(
            constraint.check_segment(&chord),
            Err(ConstraintViolation::TrafficLane)
        );
        let inside = segment(10.0).with_headings(6f64.to_radians(), 14f64.to_radians());
        assert!(constraint.check_segment(&inside).is_ok());
        assert!(constraint.admits_point(DVec2::ZERO));
        assert!(
            SchemeConstraint::default()
                .check_segment(&segment(45.0))
                .is_ok()
        );
        assert_eq!(constraint.scheme().lanes.len(), 1);
    }
}
