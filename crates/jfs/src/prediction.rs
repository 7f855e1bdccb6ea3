//! Predicting where a target will be (notes, erratum 9).
//!
//! A target either holds its course and speed for ever, or steers straight for
//! its goal at constant speed and stops there, or holds its present course for
//! a while and then steers for its goal (a give-way vessel holding its
//! alteration until it is past, rule 8(d), then returning to its route). All
//! three predictions are in closed form and memoryless: predicting `a + b`
//! seconds ahead equals predicting `a` and then `b`, so a planner may keep only
//! the targets' states at its root and predict them at any node's time.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;
use vorrt_geometry::angle;

/// How well the moment a target turns onto the second leg of its
/// prediction is known, seconds: a vessel returning to its route once past
/// turns when it judges itself past, which an observer estimates from both
/// vessels' present motion, to within this. The second leg is kept as much
/// farther off as the target sails in this time
/// ([`LinearTrack::then_margin_m`]).
pub const TURN_TIMING_UNCERTAINTY_S: f64 = 10.0;

/// A target vessel: its state and, when it has one, the goal it steers for.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TargetState {
    /// Position, course, speed and length now.
    pub vessel: VesselState,
    /// Where it is bound, metres; `None` holds course and speed for ever.
    pub goal_m: Option<DVec2>,
    /// With a goal: seconds it holds its present course and speed before it
    /// steers for the goal (a vessel holding an alteration until it is past
    /// and clear, rule 8(d)); `None` steers for the goal at once.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub holds_course_for_s: Option<f64>,
}

impl TargetState {
    /// A target that holds its course and speed.
    #[must_use]
    pub fn constant_velocity(vessel: VesselState) -> Self {
        Self {
            vessel,
            goal_m: None,
            holds_course_for_s: None,
        }
    }

    /// A target bound for `goal_m` at its present speed. Its course is set
    /// toward the goal at once (it steers for it).
    #[must_use]
    pub fn toward_goal(vessel: VesselState, goal_m: DVec2) -> Self {
        let mut vessel = vessel;
        let to_goal = goal_m - vessel.position_m;
        if to_goal != DVec2::ZERO {
            vessel.course_rad = angle::unit_to_course(to_goal);
        }
        Self {
            vessel,
            goal_m: Some(goal_m),
            holds_course_for_s: None,
        }
    }

    /// A target that holds its present course and speed for `hold_s`
    /// seconds, then steers for `goal_m` at the same speed: a vessel seen
    /// off the course to its destination, giving way, that returns to its
    /// route once past. A non-positive (or NaN) `hold_s` steers for the goal
    /// at once ([`toward_goal`](Self::toward_goal)).
    ///
    /// ```
    /// use vorrt_jfs::TargetState;
    /// use vorrt_colregs::VesselState;
    /// use glam::DVec2;
    /// // Heading east at 5 m/s for 100 s, then north to (500, 1000).
    /// let target = TargetState::holding_course_then_toward_goal(
    ///     VesselState::new(DVec2::ZERO, std::f64::consts::FRAC_PI_2, 5.0, 50.0),
    ///     DVec2::new(500.0, 1000.0),
    ///     100.0,
    /// );
    /// assert!(target.predict(100.0).vessel.position_m.distance(DVec2::new(500.0, 0.0)) < 1e-9);
    /// assert!(target.predict(200.0).vessel.position_m.distance(DVec2::new(500.0, 500.0)) < 1e-9);
    /// assert_eq!(target.time_to_goal_s(), Some(300.0));
    /// ```
    #[must_use]
    pub fn holding_course_then_toward_goal(
        vessel: VesselState,
        goal_m: DVec2,
        hold_s: f64,
    ) -> Self {
        if hold_s > 0.0 {
            Self {
                vessel,
                goal_m: Some(goal_m),
                holds_course_for_s: Some(hold_s),
            }
        } else {
            Self::toward_goal(vessel, goal_m)
        }
    }

    /// Seconds it still holds its present course before it steers for its
    /// goal (zero without a goal or a hold).
    fn hold_s(&self) -> f64 {
        match (self.goal_m, self.holds_course_for_s) {
            (Some(_), Some(hold_s)) if hold_s > 0.0 => hold_s,
            _ => 0.0,
        }
    }

    /// Seconds until it reaches its goal: `None` without a goal or when it
    /// cannot get there (zero speed), `Some(0)` when it is there already.
    #[must_use]
    pub fn time_to_goal_s(&self) -> Option<f64> {
        let goal = self.goal_m?;
        let hold_s = self.hold_s();
        if hold_s > 0.0 {
            if self.vessel.speed_mps <= 0.0 {
                return None;
            }
            let turned = self.vessel.advanced(hold_s).position_m;
            return Some(hold_s + turned.distance(goal) / self.vessel.speed_mps);
        }
        let distance = self.vessel.position_m.distance(goal);
        if distance == 0.0 {
            Some(0.0)
        } else if self.vessel.speed_mps > 0.0 {
            Some(distance / self.vessel.speed_mps)
        } else {
            None
        }
    }

    /// Whether it has arrived and stopped.
    #[must_use]
    pub fn has_arrived(&self) -> bool {
        self.goal_m
            .is_some_and(|goal| goal == self.vessel.position_m)
    }

    /// The state `duration_s` seconds on (closed form). A goal-bound target
    /// moves along the straight line to its goal at its speed, never past it,
    /// and once there stops (speed 0, last course kept); one that holds its
    /// course first sails on it for its hold, then does the same. Negative
    /// durations are treated as zero.
    ///
    /// ```
    /// use vorrt_jfs::TargetState;
    /// use vorrt_colregs::VesselState;
    /// use glam::DVec2;
    /// let target = TargetState::toward_goal(
    ///     VesselState::new(DVec2::ZERO, 0.0, 5.0, 50.0), DVec2::new(0.0, 1000.0));
    /// assert_eq!(target.predict(100.0).vessel.position_m, DVec2::new(0.0, 500.0));
    /// let arrived = target.predict(1000.0);
    /// assert_eq!(arrived.vessel.position_m, DVec2::new(0.0, 1000.0));
    /// assert_eq!(arrived.vessel.speed_mps, 0.0);
    /// ```
    #[must_use]
    pub fn predict(&self, duration_s: f64) -> TargetState {
        let duration_s = if duration_s > 0.0 { duration_s } else { 0.0 };
        let Some(goal) = self.goal_m else {
            return TargetState {
                vessel: self.vessel.advanced(duration_s),
                goal_m: None,
                holds_course_for_s: None,
            };
        };
        let hold_s = self.hold_s();
        if hold_s > 0.0 {
            if duration_s < hold_s {
                return TargetState {
                    vessel: self.vessel.advanced(duration_s),
                    goal_m: self.goal_m,
                    holds_course_for_s: Some(hold_s - duration_s),
                };
            }
            let turned = TargetState {
                vessel: self.vessel.advanced(hold_s),
                goal_m: self.goal_m,
                holds_course_for_s: None,
            };
            return turned.predict(duration_s - hold_s);
        }
        let to_goal = goal - self.vessel.position_m;
        let remaining_m = to_goal.length();
        let travel_m = self.vessel.speed_mps * duration_s;
        let mut vessel = self.vessel;
        if remaining_m == 0.0 || travel_m >= remaining_m {
            vessel.position_m = goal;
            vessel.speed_mps = 0.0;
            if remaining_m > 0.0 {
                vessel.course_rad = angle::unit_to_course(to_goal);
            }
        } else {
            vessel.course_rad = angle::unit_to_course(to_goal);
            vessel.position_m += to_goal * (travel_m / remaining_m);
        }
        TargetState {
            vessel,
            goal_m: self.goal_m,
            holds_course_for_s: None,
        }
    }
}

/// A target's predicted motion in closed form: from `start_m` at
/// `velocity_mps` until `turns_at_s`, then at `then_velocity_mps` until
/// `moving_for_s` (for ever without a goal), then at rest. The same motion as
/// [`TargetState::predict`], precomputed so that a planner evaluates it with a
/// multiply-add. A target that steers for its goal at once has one leg
/// (`turns_at_s == moving_for_s`).
///
/// ```
/// use vorrt_jfs::TargetState;
/// use vorrt_colregs::VesselState;
/// use glam::DVec2;
/// let target = TargetState::toward_goal(
///     VesselState::new(DVec2::ZERO, 0.0, 5.0, 50.0), DVec2::new(0.0, 1000.0));
/// let track = target.track();
/// assert_eq!(track.moving_for_s, 200.0);
/// assert_eq!(track.position_at(100.0), target.predict(100.0).vessel.position_m);
/// assert_eq!(track.velocity_at(300.0), DVec2::ZERO);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LinearTrack {
    /// Position at the track's time zero, metres.
    pub start_m: DVec2,
    /// Velocity on the first leg, m/s.
    pub velocity_mps: DVec2,
    /// When the first leg ends and the second begins, seconds after time
    /// zero (`moving_for_s` when there is one leg).
    pub turns_at_s: f64,
    /// Velocity on the second leg, m/s (`velocity_mps` when there is one leg).
    pub then_velocity_mps: DVec2,
    /// How much nearer than the second leg the target may be, metres: its
    /// speed times [`TURN_TIMING_UNCERTAINTY_S`] (0 when there is one leg).
    pub then_margin_m: f64,
    /// How long it moves before it stops, seconds (`f64::INFINITY` without a goal).
    pub moving_for_s: f64,
    /// The vessel at time zero (course, speed and length).
    pub vessel: VesselState,
}

impl LinearTrack {
    /// Position `elapsed_s` after time zero (negative times are taken as zero).
    #[inline]
    #[must_use]
    pub fn position_at(&self, elapsed_s: f64) -> DVec2 {
        let moving_s = elapsed_s.clamp(0.0, self.moving_for_s);
        if moving_s <= self.turns_at_s {
            self.start_m + self.velocity_mps * moving_s
        } else {
            self.start_m
                + self.velocity_mps * self.turns_at_s
                + self.then_velocity_mps * (moving_s - self.turns_at_s)
        }
    }

    /// Velocity `elapsed_s` after time zero: zero once it has stopped.
    #[inline]
    #[must_use]
    pub fn velocity_at(&self, elapsed_s: f64) -> DVec2 {
        if elapsed_s < self.turns_at_s {
            self.velocity_mps
        } else if elapsed_s < self.moving_for_s {
            self.then_velocity_mps
        } else {
            DVec2::ZERO
        }
    }

    /// Which stretch of the track `elapsed_s` lies on: 0 the first leg, 1
    /// the second, 2 at rest once stopped; `None` before time zero (where
    /// the position is held but the state moves). Within one stretch
    /// [`velocity_at`](Self::velocity_at) and the course and speed of
    /// [`state_at`](Self::state_at) are each one value, and
    /// [`position_at`](Self::position_at) moves at `velocity_at` (to
    /// rounding): what a caller needs to carry a judgement from one time to
    /// a later one on the same stretch (decision 54).
    #[inline]
    #[must_use]
    pub fn stretch_at(&self, elapsed_s: f64) -> Option<u8> {
        if elapsed_s.is_nan() || elapsed_s < 0.0 {
            None
        } else if elapsed_s < self.turns_at_s.min(self.moving_for_s) {
            Some(0)
        } else if elapsed_s < self.moving_for_s {
            Some(1)
        } else {
            Some(2)
        }
    }

    /// The full vessel state `elapsed_s` after time zero: on the second leg
    /// it has the second leg's course; once stopped, speed 0 and the last
    /// course kept.
    #[must_use]
    pub fn state_at(&self, elapsed_s: f64) -> VesselState {
        let moving = elapsed_s < self.moving_for_s;
        let course_rad = if elapsed_s >= self.turns_at_s
            && self.turns_at_s < self.moving_for_s
            && self.then_velocity_mps != DVec2::ZERO
        {
            angle::unit_to_course(self.then_velocity_mps)
        } else {
            self.vessel.course_rad
        };
        VesselState {
            position_m: self.position_at(elapsed_s),
            speed_mps: if moving { self.vessel.speed_mps } else { 0.0 },
            course_rad,
            ..self.vessel
        }
    }
}

impl TargetState {
    /// This target's motion as a [`LinearTrack`] starting now.
    #[must_use]
    pub fn track(&self) -> LinearTrack {
        let hold_s = self.hold_s();
        if hold_s > 0.0 {
            // Its present course first, then the line from where the hold
            // ends to the goal.
            let turned = self.predict(hold_s);
            let second = turned.track();
            let moving_for_s = hold_s + second.moving_for_s;
            return LinearTrack {
                start_m: self.vessel.position_m,
                velocity_mps: self.vessel.velocity_mps(),
                turns_at_s: if moving_for_s > hold_s {
                    hold_s
                } else {
                    moving_for_s
                },
                then_velocity_mps: second.velocity_mps,
                then_margin_m: self.vessel.speed_mps * TURN_TIMING_UNCERTAINTY_S,
                moving_for_s,
                vessel: self.vessel,
            };
        }
        let mut vessel = self.vessel;
        let moving_for_s = match self.goal_m {
            None => f64::INFINITY,
            Some(goal) => {
                let to_goal = goal - vessel.position_m;
                if to_goal != DVec2::ZERO {
                    vessel.course_rad = angle::unit_to_course(to_goal);
                }
                self.time_to_goal_s().unwrap_or(f64::INFINITY)
            }
        };
        let velocity_mps = if moving_for_s > 0.0 {
            vessel.velocity_mps()
        } else {
            DVec2::ZERO
        };
        LinearTrack {
            start_m: vessel.position_m,
            velocity_mps,
            turns_at_s: moving_for_s,
            then_velocity_mps: velocity_mps,
            then_margin_m: 0.0,
            moving_for_s,
            vessel,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_velocity_prediction_is_linear() {
        let target = TargetState::constant_velocity(VesselState::new(
            DVec2::ZERO,
            std::f64::consts::FRAC_PI_2,
            4.0,
            30.0,
        ));
        let later = target.predict(10.0);
        assert!((later.vessel.position_m - DVec2::new(40.0, 0.0)).length() < 1e-9);
    }

    #[test]
    fn goal_bound_target_steers_for_goal() {
        let target = TargetState::toward_goal(
            VesselState::new(DVec2::ZERO, 0.0, 4.0, 30.0),
            DVec2::new(400.0, 0.0),
        );
        assert!((target.vessel.course_rad - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert_eq!(target.time_to_goal_s(), Some(100.0));
        assert!(target.predict(100.0).has_arrived());
    }

    #[test]
    fn stationary_target_without_goal_reach() {
        let target = TargetState::toward_goal(
            VesselState::new(DVec2::ZERO, 0.0, 0.0, 30.0),
            DVec2::new(10.0, 0.0),
        );
        assert_eq!(target.time_to_goal_s(), None);
        assert_eq!(target.predict(50.0).vessel.position_m, DVec2::ZERO);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn holding_target_turns_for_its_goal_after_its_hold() {
        // East at 5 m/s for 100 s, then north for (500, 1000): 1000 m more.
        let target = TargetState::holding_course_then_toward_goal(
            VesselState::new(DVec2::ZERO, std::f64::consts::FRAC_PI_2, 5.0, 50.0),
            DVec2::new(500.0, 1000.0),
            100.0,
        );
        let track = target.track();
        assert_eq!(track.turns_at_s, 100.0);
        assert!((track.moving_for_s - 300.0).abs() < 1e-9);
        for elapsed_s in [0.0, 50.0, 100.0, 150.0, 299.0, 300.0, 400.0] {
            let predicted = target.predict(elapsed_s);
            assert!(
                track
                    .position_at(elapsed_s)
                    .distance(predicted.vessel.position_m)
                    < 1e-9,
                "{elapsed_s}"
            );
            let state = track.state_at(elapsed_s);
            assert!(
                (state.course_rad - predicted.vessel.course_rad).abs() < 1e-9,
                "{elapsed_s}"
            );
        }
        assert!((track.velocity_at(150.0) - DVec2::new(0.0, 5.0)).length() < 1e-9);
        assert_eq!(track.velocity_at(300.0), DVec2::ZERO);
        // Memoryless across the turn.
        let in_two = target.predict(60.0).predict(90.0);
        assert!(
            in_two
                .vessel
                .position_m
                .distance(target.predict(150.0).vessel.position_m)
                < 1e-9
        );
        assert_eq!(in_two.holds_course_for_s, None);
    }

    #[test]
    fn a_hold_of_zero_steers_for_the_goal_at_once() {
        let vessel = VesselState::new(DVec2::ZERO, 1.0, 5.0, 50.0);
        let goal = DVec2::new(0.0, 1000.0);
        assert_eq!(
            TargetState::holding_course_then_toward_goal(vessel, goal, 0.0),
            TargetState::toward_goal(vessel, goal)
        );
    }
}
