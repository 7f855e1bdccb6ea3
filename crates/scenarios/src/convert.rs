//! From file units to the planner's SI types.
//!
//! The conversions assume a validated scenario (every loader validates). On a
//! scenario built in code and not validated, a vessel with no start position
//! is placed at `(NaN, NaN)`, which [`PlanningProblem::validate`] rejects;
//! nothing here panics.

use crate::scenario::{DEFAULT_DURATION_FACTOR, Lane, Scenario, VesselSpec};
use vorrt_colregs::VesselState;
use vorrt_geometry::{DVec2, angle, units};
use vorrt_jfs::TargetState;
use vorrt_planner::PlanningProblem;

fn from_nm((east, north): (f64, f64)) -> DVec2 {
    DVec2::new(
        units::nautical_miles_to_m(east),
        units::nautical_miles_to_m(north),
    )
}

fn either_m(nautical: Option<(f64, f64)>, metres: Option<(f64, f64)>) -> Option<DVec2> {
    nautical.map(from_nm).or(metres.map(DVec2::from))
}

impl VesselSpec {
    /// Start position `(east, north)` in metres (`start_nm`, `start_m`, or
    /// `start_lat_lon` as projected by validation).
    #[must_use]
    pub fn start_position_m(&self) -> DVec2 {
        either_m(self.start_nm, self.start_m)
            .or(self.projected.start_m)
            .unwrap_or(DVec2::NAN)
    }

    /// Goal `(east, north)` in metres, if it has one.
    #[must_use]
    pub fn goal_position_m(&self) -> Option<DVec2> {
        either_m(self.goal_nm, self.goal_m).or(self.projected.goal_m)
    }

    /// Course in radians, clockwise from north.
    #[must_use]
    pub fn course_rad(&self) -> f64 {
        self.course_deg.to_radians()
    }

    /// Speed in metres per second.
    #[must_use]
    pub fn speed_mps(&self) -> f64 {
        units::knots_to_mps(self.speed_kn)
    }

    /// The vessel's state at the start, in SI, with the course as given.
    #[must_use]
    pub fn state(&self) -> VesselState {
        VesselState::new(
            self.start_position_m(),
            self.course_rad(),
            self.speed_mps(),
            self.length_m,
        )
    }

    /// The vessel as a planner target, as it announces itself:
    /// [`TargetState::toward_goal`] when it has a goal and its behaviour
    /// announces one (every behaviour but [`Behaviour::ConstantVelocity`](crate::Behaviour::ConstantVelocity);
    /// its course is then the bearing of its goal), else
    /// [`TargetState::constant_velocity`].
    #[must_use]
    pub fn target_state(&self) -> TargetState {
        match self.goal_position_m() {
            Some(goal) if self.behaviour.announces_goal() => {
                TargetState::toward_goal(self.state(), goal)
            }
            _ => TargetState::constant_velocity(self.state()),
        }
    }
}

impl Scenario {
    /// Ownship at the start, in SI.
    #[must_use]
    pub fn ownship_state(&self) -> VesselState {
        self.ownship.state()
    }

    /// Ownship's goal in metres (`(NaN, NaN)` if an unvalidated scenario has
    /// none).
    #[must_use]
    pub fn ownship_goal_m(&self) -> DVec2 {
        self.ownship.goal_position_m().unwrap_or(DVec2::NAN)
    }

    /// Every target at the start, in SI, with its predicted motion (see
    /// [`VesselSpec::target_state`]).
    #[must_use]
    pub fn target_states(&self) -> Vec<TargetState> {
        self.targets.iter().map(VesselSpec::target_state).collect()
    }

    /// The planning problem at time 0, in SI, with no encounter in force yet.
    #[must_use]
    pub fn planning_problem(&self) -> PlanningProblem {
        PlanningProblem::new(
            self.ownship_state(),
            self.ownship_goal_m(),
            self.target_states(),
        )
    }

    /// Seconds ownship needs to sail straight to its goal at its speed.
    #[must_use]
    pub fn straight_line_time_s(&self) -> f64 {
        self.ownship
            .start_position_m()
            .distance(self.ownship_goal_m())
            / self.ownship.speed_mps()
    }

    /// The longest simulated time, seconds: `simulation.max_duration_s`, or
    /// by default [`DEFAULT_DURATION_FACTOR`] times
    /// [`straight_line_time_s`](Self::straight_line_time_s).
    #[must_use]
    pub fn max_duration_s(&self) -> f64 {
        self.simulation
            .max_duration_s
            .unwrap_or_else(|| DEFAULT_DURATION_FACTOR * self.straight_line_time_s())
    }
}

impl Lane {
    /// Upstream end of the centre line, metres.
    #[must_use]
    pub fn from_m(&self) -> DVec2 {
        self.from_nm
            .map(from_nm)
            .or(self.projected.start_m)
            .unwrap_or(DVec2::NAN)
    }

    /// Downstream end of the centre line, metres.
    #[must_use]
    pub fn to_m(&self) -> DVec2 {
        self.to_nm
            .map(from_nm)
            .or(self.projected.goal_m)
            .unwrap_or(DVec2::NAN)
    }

    /// Full width, metres.
    #[must_use]
    pub fn width_m(&self) -> f64 {
        units::nautical_miles_to_m(self.width_nm)
    }

    /// The direction of traffic flow as a course, radians clockwise from north.
    #[must_use]
    pub fn traffic_course_rad(&self) -> f64 {
        angle::unit_to_course(self.to_m() - self.from_m())
    }

    /// Whether `point_m` lies inside the lane: within half the width of the
    /// centre line, between its two ends.
    #[must_use]
    pub fn contains_m(&self, point_m: DVec2) -> bool {
        let from = self.from_m();
        let along = self.to_m() - from;
        let length_sq = along.length_squared();
        if length_sq == 0.0 {
            return false;
        }
        let offset = point_m - from;
        let fraction = offset.dot(along) / length_sq;
        let across = offset.perp_dot(along).abs() / length_sq.sqrt();
        (0.0..=1.0).contains(&fraction) && across <= 0.5 * self.width_m()
    }
}
