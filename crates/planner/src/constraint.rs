//! Constraints of the user's on ownship's motion: land, shallows, no-go
//! areas, traffic lanes.
//!
//! A [`Constraint`] is asked about every piece of ownship's motion the one
//! validity check judges (the chords of a turn, with the chord's distance
//! from the arc as a margin, and the pieces of the straight run), and about
//! every point the sampler draws. The planner composes it with its COLREGs
//! validator ([`SafetyChecker`](crate::safety::SafetyChecker)), so tree
//! growth, the manoeuvre search, the path simplifier, a closed loop's plan
//! check and the evasive fallback all keep it. The planner is generic over
//! it ([`Planner<C>`](crate::Planner)): no `dyn` in the inner loop, and
//! [`NoConstraint`], the default, costs nothing.
//!
//! ```
//! use vorrt_planner::constraint::{Constraint, ConstraintViolation, Segment};
//! use vorrt_planner::{Planner, PlannerConfig, PlanningProblem};
//! use vorrt_planner::colregs::VesselState;
//! use vorrt_planner::glam::DVec2;
//!
//! /// A circle ownship must keep out of (a wreck, an exercise area).
//! struct NoGoCircle { centre_m: DVec2, radius_m: f64 }
//!
//! impl Constraint for NoGoCircle {
//!     fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
//!         if segment.distance_to_m(self.centre_m) < self.radius_m + segment.margin_m {
//!             Err(ConstraintViolation::NoGoArea)
//!         } else {
//!             Ok(())
//!         }
//!     }
//!     fn admits_point(&self, point_m: DVec2) -> bool {
//!         point_m.distance(self.centre_m) >= self.radius_m
//!     }
//! }
//!
//! // No traffic, but a 1 km no-go circle on the straight route north.
//! let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
//! let problem = PlanningProblem::new(own, DVec2::new(0.0, 8000.0), vec![]);
//! let circle = NoGoCircle { centre_m: DVec2::new(0.0, 4000.0), radius_m: 1000.0 };
//! let mut planner = Planner::with_constraint(PlannerConfig::default(), circle).unwrap();
//! let plan = planner.plan(&problem, 7).unwrap();
//! assert_eq!(plan.waypoints.last().unwrap().position_m, DVec2::new(0.0, 8000.0));
//! // Every point sailed, along the arcs of the turns, is outside the circle.
//! let duration_s = plan.duration_s();
//! for step in 0..=(duration_s as usize) {
//!     let pose = plan.pose_at(step as f64).unwrap();
//!     assert!(pose.position_m.distance(DVec2::new(0.0, 4000.0)) >= 1000.0);
//! }
//! ```

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_jfs::{Leg, Piece};

/// What a piece of ownship's motion breaks, by a [`Constraint`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ConstraintViolation {
    /// Nearer land or shallow water than allowed (a grounding risk).
    Land,
    /// Inside an area ownship must keep out of.
    NoGoArea,
    /// Against the rule of a traffic lane or separation scheme (rule 10).
    TrafficLane,
}

impl ConstraintViolation {
    /// Every violation, in a fixed order.
    pub const ALL: [ConstraintViolation; 3] = [
        ConstraintViolation::Land,
        ConstraintViolation::NoGoArea,
        ConstraintViolation::TrafficLane,
    ];

    /// Its name in files (snake case, as serialised).
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            ConstraintViolation::Land => "land",
            ConstraintViolation::NoGoArea => "no_go_area",
            ConstraintViolation::TrafficLane => "traffic_lane",
        }
    }

    /// A short description, for messages.
    #[must_use]
    pub fn description(self) -> &'static str {
        match self {
            ConstraintViolation::Land => "too near land or shallow water",
            ConstraintViolation::NoGoArea => "inside a no-go area",
            ConstraintViolation::TrafficLane => "against a traffic lane's rule (rule 10)",
        }
    }
}

impl std::fmt::Display for ConstraintViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.description())
    }
}

/// One piece of ownship's motion, as the validity check asks a
/// [`Constraint`] about it: ownship sails within `margin_m` of the straight
/// segment from `start_m` to `end_m` (on a chord of a turn, the chord's
/// largest distance from the arc; while the speed changes, the timing
/// error), from `start_elapsed_s` after the plan's start for `duration_s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Where the piece starts, metres (x east, y north).
    pub start_m: DVec2,
    /// Where it ends, metres.
    pub end_m: DVec2,
    /// How far from the segment ownship may be along the curve it sails, metres.
    pub margin_m: f64,
    /// When the piece starts, seconds after the plan's start.
    pub start_elapsed_s: f64,
    /// How long it takes, seconds.
    pub duration_s: f64,
    /// Ownship's course along the piece, radians clockwise from north.
    pub course_rad: f64,
    /// How far either way of `course_rad` ownship's heading may be along
    /// the piece, radians: on a chord of a turn, half the angle it sweeps
    /// (the chord's course is the heading at its middle); 0 on a straight
    /// piece. A constraint that judges the heading judges every heading in
    /// `course_rad ± course_spread_rad`, as an observer sampling the heading
    /// anywhere along the piece sees one of them.
    pub course_spread_rad: f64,
}

impl Segment {
    /// The segment of `piece`, one piece of a leg that starts
    /// `leg_start_elapsed_s` after the plan's start, with the margin its kind
    /// carries: on a turn the leg's chord error (`piece_error_m`), while the
    /// speed changes its timing error (`timing_error_m`), else none.
    ///
    /// ```
    /// use vorrt_planner::constraint::Segment;
    /// use vorrt_planner::{DVec2, Leg};
    /// let leg = Leg::straight(DVec2::ZERO, 0.0, 1000.0, 5.0);
    /// let piece = leg.pieces(100.0).nth(3).unwrap();
    /// let segment = Segment::of_piece(&piece, 60.0, leg.piece_error_m(), leg.timing_error_m());
    /// assert_eq!(segment.start_m, DVec2::new(0.0, 300.0));
    /// assert_eq!(segment.start_elapsed_s, 120.0);
    /// assert_eq!(segment.margin_m, 0.0);
    /// ```
    #[must_use]
    pub fn of_piece(
        piece: &Piece,
        leg_start_elapsed_s: f64,
        piece_error_m: f64,
        timing_error_m: f64,
    ) -> Self {
        let margin_m = if piece.turning {
            piece_error_m
        } else if piece.transient() {
            timing_error_m
        } else {
            0.0
        };
        Segment {
            start_m: piece.start_m,
            end_m: piece.end_m(),
            margin_m,
            start_elapsed_s: leg_start_elapsed_s + piece.elapsed_s,
            duration_s: piece.duration_s,
            course_rad: piece.course_rad,
            course_spread_rad: 0.0,
        }
    }

    /// The segment of `piece` of `leg` ([`of_piece`](Self::of_piece),
    /// with the leg's chord and timing errors) and the heading at the
    /// piece's end (on a turn, part way round): a chord of the turn sweeps
    /// from `start_heading_rad`, the heading at the last piece's end, to it
    /// ([`with_headings`](Self::with_headings)).
    ///
    /// ```
    /// use vorrt_planner::constraint::Segment;
    /// use vorrt_planner::{DVec2, Leg};
    /// use vorrt_jfs::Pose;
    /// let start = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
    /// let leg = Leg::turning_onto(start, 0.5, 700.0, 6.0, 1000.0);
    /// let piece = leg.pieces(100.0).next().unwrap();
    /// let (chord, heading_rad) = Segment::of_leg_piece(&leg, &piece, 0.0, 0.0);
    /// assert!(chord.course_spread_rad > 0.0 && heading_rad > chord.course_rad);
    /// ```
    #[must_use]
    pub fn of_leg_piece(
        leg: &Leg,
        piece: &Piece,
        leg_start_elapsed_s: f64,
        start_heading_rad: f64,
    ) -> (Self, f64) {
        let segment = Self::of_piece(
            piece,
            leg_start_elapsed_s,
            leg.piece_error_m(),
            leg.timing_error_m(),
        );
        if piece.turning {
            let end_rad = leg.course_at(piece.elapsed_s + piece.duration_s);
            (segment.with_headings(start_heading_rad, end_rad), end_rad)
        } else {
            (segment, piece.course_rad)
        }
    }

    /// The same segment with the headings sailed along it from
    /// `start_course_rad` to `end_course_rad` (a chord of a turn): its
    /// [`course_spread_rad`](Self::course_spread_rad) is the larger of their
    /// differences from its course.
    ///
    /// ```
    /// use vorrt_planner::constraint::Segment;
    /// use vorrt_planner::DVec2;
    /// let chord = Segment {
    ///     start_m: DVec2::ZERO, end_m: DVec2::new(10.0, 100.0), margin_m: 1.0,
    ///     start_elapsed_s: 0.0, duration_s: 20.0, course_rad: 0.1, course_spread_rad: 0.0,
    /// }
    /// .with_headings(0.05, 0.15);
    /// assert!((chord.course_spread_rad - 0.05).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn with_headings(mut self, start_course_rad: f64, end_course_rad: f64) -> Self {
        let off = |heading_rad: f64| {
            vorrt_geometry::angle::signed_turn(self.course_rad, heading_rad).abs()
        };
        self.course_spread_rad = off(start_course_rad).max(off(end_course_rad));
        self
    }

    /// The distance from `point_m` to the segment, metres.
    ///
    /// ```
    /// use vorrt_planner::constraint::Segment;
    /// use glam::DVec2;
    /// let segment = Segment {
    ///     start_m: DVec2::ZERO, end_m: DVec2::new(0.0, 100.0), margin_m: 0.0,
    ///     start_elapsed_s: 0.0, duration_s: 20.0, course_rad: 0.0, course_spread_rad: 0.0,
    /// };
    /// assert_eq!(segment.distance_to_m(DVec2::new(30.0, 50.0)), 30.0);
    /// assert_eq!(segment.distance_to_m(DVec2::new(0.0, 130.0)), 30.0);
    /// ```
    #[must_use]
    pub fn distance_to_m(&self, point_m: DVec2) -> f64 {
        let along = self.end_m - self.start_m;
        let length_sq = along.length_squared();
        let fraction = if length_sq > 0.0 {
            ((point_m - self.start_m).dot(along) / length_sq).clamp(0.0, 1.0)
        } else {
            0.0
        };
        point_m.distance(self.start_m + along * fraction)
    }
}

/// A constraint on ownship's motion beside the COLREGs: the seam where land,
/// no-go areas and traffic lanes plug into the planner (module
/// documentation).
pub trait Constraint {
    /// Checks one piece of ownship's motion.
    ///
    /// # Errors
    /// The [`ConstraintViolation`] the piece runs into.
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation>;

    /// Whether the sampler may draw `point_m` (for land: whether it is in
    /// water). The default admits every point.
    fn admits_point(&self, point_m: DVec2) -> bool {
        let _ = point_m;
        true
    }

    /// Whether the search from the root tries a change of speed on the
    /// course to the goal before any alteration of course
    /// ([`ManeuverShape::SpeedOnCourse`](crate::vorrt::ManeuverShape::SpeedOnCourse)):
    /// a route that crosses a traffic lane, whose heading rule 10(c) fixes.
    /// Then a readily apparent reduction of speed held also counts as a
    /// give-way action (`vorrt_colregs::check_action`: holding short of the
    /// stream, decision 47). The default is no.
    fn prefers_speed_changes(&self) -> bool {
        false
    }
}

/// No constraint beside the COLREGs: the open sea.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NoConstraint;

impl Constraint for NoConstraint {
    #[inline]
    fn check_segment(&self, _segment: &Segment) -> Result<(), ConstraintViolation> {
        Ok(())
    }

    #[inline]
    fn admits_point(&self, _point_m: DVec2) -> bool {
        true
    }
}

/// Both constraints: the first violation of either (the first one's first).
impl<A: Constraint, B: Constraint> Constraint for (A, B) {
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        self.0.check_segment(segment)?;
        self.1.check_segment(segment)
    }

    fn admits_point(&self, point_m: DVec2) -> bool {
        self.0.admits_point(point_m) && self.1.admits_point(point_m)
    }

    fn prefers_speed_changes(&self) -> bool {
        self.0.prefers_speed_changes() || self.1.prefers_speed_changes()
    }
}

impl<C: Constraint + ?Sized> Constraint for &C {
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        (**self).check_segment(segment)
    }

    fn admits_point(&self, point_m: DVec2) -> bool {
        (**self).admits_point(point_m)
    }

    fn prefers_speed_changes(&self) -> bool {
        (**self).prefers_speed_changes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct West;
    impl Constraint for West {
        fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
            if segment.start_m.x < 0.0 || segment.end_m.x < 0.0 {
                Err(ConstraintViolation::Land)
            } else {
                Ok(())
            }
        }
        fn admits_point(&self, point_m: DVec2) -> bool {
            point_m.x >= 0.0
        }
    }

    fn segment(start_m: DVec2, end_m: DVec2) -> Segment {
        Segment {
            start_m,
            end_m,
            margin_m: 0.0,
            start_elapsed_s: 0.0,
            duration_s: 1.0,
            course_rad: 0.0,
            course_spread_rad: 0.0,
        }
    }

    #[test]
    fn no_constraint_admits_everything() {
        let far = DVec2::new(-1e9, 1e9);
        assert!(NoConstraint.check_segment(&segment(far, -far)).is_ok());
        assert!(NoConstraint.admits_point(far));
        assert!(!NoConstraint.prefers_speed_changes());
        assert!(!(NoConstraint, West).prefers_speed_changes());
    }

    #[test]
    fn a_pair_refuses_what_either_refuses() {
        let pair = (NoConstraint, West);
        let east = segment(DVec2::ZERO, DVec2::new(10.0, 0.0));
        let west = segment(DVec2::ZERO, DVec2::new(-10.0, 0.0));
        assert!(pair.check_segment(&east).is_ok());
        assert_eq!(pair.check_segment(&west), Err(ConstraintViolation::Land));
        assert!(!pair.admits_point(DVec2::new(-1.0, 0.0)));
        let by_reference = &pair;
        assert!(by_reference.admits_point(DVec2::new(1.0, 0.0)));
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the 3-4-5 triangle's hypotenuse is exact")]
    fn a_degenerate_segment_measures_from_its_point() {
        let point = segment(DVec2::new(3.0, 4.0), DVec2::new(3.0, 4.0));
        assert_eq!(point.distance_to_m(DVec2::ZERO), 5.0);
    }

    #[test]
    fn every_violation_has_a_distinct_key() {
        let keys: std::collections::HashSet<_> =
            ConstraintViolation::ALL.iter().map(|v| v.key()).collect();
        assert_eq!(keys.len(), ConstraintViolation::ALL.len());
    }
}
