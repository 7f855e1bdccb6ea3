//! Predicting where a target will be (notes, erratum 9).
//!
//! A target either holds its course and speed for ever, or steers straight for
//! its goal at constant speed and stops there. Both predictions are in closed
//! form and memoryless: predicting `a + b` seconds ahead equals predicting `a`
//! and then `b`, so a planner may keep only the targets' states at its root and
//! predict them at any node's time.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;
use vorrt_geometry::angle;

/// A target vessel: its state and, when it has one, the goal it steers for.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TargetState {
    /// Position, course, speed and length now.
    pub vessel: VesselState,
    /// Where it is bound, metres; `None` holds course and speed for ever.
    pub goal_m: Option<DVec2>,
}

impl TargetState {
    /// A target that holds its course and speed.
    #[must_use]
    pub fn constant_velocity(vessel: VesselState) -> Self {
        Self {
            vessel,
            goal_m: None,
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
        }
    }

    /// Seconds until it reaches its goal: `None` without a goal or when it
    /// cannot get there (zero speed), `Some(0)` when it is there already.
    #[must_use]
    pub fn time_to_goal_s(&self) -> Option<f64> {
        let goal = self.goal_m?;
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
    /// and once there stops (speed 0, last course kept). Negative durations
    /// are treated as zero.
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
            };
        };
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
        }
    }
}

/// A target's predicted motion in closed form: constant velocity from
/// `start_m` for `moving_for_s` seconds (for ever without a goal), then at rest.
/// The same motion as [`TargetState::predict`], precomputed so that a planner
/// evaluates it with a multiply-add.
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
    /// Velocity while moving, m/s.
    pub velocity_mps: DVec2,
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
        self.start_m + self.velocity_mps * moving_s
    }

    /// Velocity `elapsed_s` after time zero: zero once it has stopped.
    #[inline]
    #[must_use]
    pub fn velocity_at(&self, elapsed_s: f64) -> DVec2 {
        if elapsed_s < self.moving_for_s {
            self.velocity_mps
        } else {
            DVec2::ZERO
        }
    }

    /// The full vessel state `elapsed_s` after time zero.
    #[must_use]
    pub fn state_at(&self, elapsed_s: f64) -> VesselState {
        let moving = elapsed_s < self.moving_for_s;
        VesselState {
            position_m: self.position_at(elapsed_s),
            speed_mps: if moving { self.vessel.speed_mps } else { 0.0 },
            ..self.vessel
        }
    }
}

impl TargetState {
    /// This target's motion as a [`LinearTrack`] starting now.
    #[must_use]
    pub fn track(&self) -> LinearTrack {
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
}
