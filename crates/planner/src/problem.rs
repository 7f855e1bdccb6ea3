//! The planning problem: where ownship is and is bound, and the targets.

use crate::error::PlannerError;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::{EncounterLatch, VesselState};
use vorrt_jfs::TargetState;

/// Largest number of targets one problem may hold: bounds the per-node memory.
pub const MAX_TARGETS: usize = 1024;

/// The slowest ownship the planner accepts, m/s (about 0.002 kn): slower,
/// the time of one step overflows to infinity and node positions become NaN.
pub const MIN_OWNSHIP_SPEED_MPS: f64 = 1e-3;

/// Positions and goals must lie within this distance of the origin, metres,
/// and speeds, lengths and the start time under the bounds below: keeps every
/// distance, time and area the planner computes finite (an overflow to
/// infinity turns into NaN, which the R*-tree cannot order).
pub const MAX_EXTENT_M: f64 = 1e8;
/// The fastest vessel a problem may hold, m/s.
pub const MAX_SPEED_MPS: f64 = 1e3;
/// The longest vessel a problem may hold, metres.
pub const MAX_LENGTH_M: f64 = 1e5;
/// The largest start time a problem may have, in magnitude, seconds.
pub const MAX_START_TIME_S: f64 = 1e12;

/// Everything the planner needs to know about the world at planning time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanningProblem {
    /// The clock at the start, seconds.
    pub start_time_s: f64,
    /// Ownship now, at its present speed (which may be below its service
    /// speed, after slowing down or stopping).
    pub ownship: VesselState,
    /// The speed ownship sails at when it is not slowing down for a
    /// manoeuvre, m/s; `None` (the default): its present speed. A plan
    /// starts at the present speed and changes speed toward this one at the
    /// configured rate (`PlannerConfig::speed_change_rate_mps2`).
    #[serde(default)]
    pub service_speed_mps: Option<f64>,
    /// Where ownship is bound, metres.
    pub goal_m: DVec2,
    /// The other vessels now, with their predicted motion.
    pub targets: Vec<TargetState>,
    /// Encounters already in force, one entry per target (a closed loop keeps
    /// them across replans). Empty: the planner latches from the start state.
    pub encounters: Vec<Option<EncounterLatch>>,
    /// For each encounter carried over in `encounters`, the alteration of
    /// course from its reference already made, radians (rule 16); empty or
    /// missing entries count as none.
    #[serde(default)]
    pub alterations: Vec<f64>,
    /// The course ownship held steadily before the turn it is in, if it is
    /// turning at the start (`vorrt_colregs::rules::steady_course_rad` of its
    /// history, as a closed loop knows it), radians; `None` (the default):
    /// its present course. An encounter that begins within an observation
    /// window is judged against it, as the closed loop and the evaluation
    /// judge it.
    #[serde(default)]
    pub steady_course_rad: Option<f64>,
    /// Whether ownship is turning at the start (its course changed over
    /// the last step faster than
    /// [`STEADY_TURN_RATE_RAD_S`](vorrt_colregs::rules::STEADY_TURN_RATE_RAD_S)),
    /// as a closed loop knows it; `false` (the default): holding its
    /// course. Holding a course it came round to within the last window,
    /// an observer judges a turn begun now from that course as well as
    /// from `steady_course_rad` (decision 57).
    #[serde(default)]
    pub turning_at_start: bool,
}

impl PlanningProblem {
    /// A problem with no encounter in force yet.
    #[must_use]
    pub fn new(ownship: VesselState, goal_m: DVec2, targets: Vec<TargetState>) -> Self {
        Self {
            start_time_s: 0.0,
            ownship,
            service_speed_mps: None,
            goal_m,
            targets,
            encounters: Vec::new(),
            alterations: Vec::new(),
            steady_course_rad: None,
            turning_at_start: false,
        }
    }

    /// The speed ownship sails at when not slowing down, m/s: the service
    /// speed when given, else the present speed.
    #[must_use]
    pub fn service_speed_mps(&self) -> f64 {
        self.service_speed_mps.unwrap_or(self.ownship.speed_mps)
    }

    /// Ownship now, at its service speed: the state the planner's checks
    /// start from (every move carries its own velocity).
    #[must_use]
    pub fn ownship_at_service_speed(&self) -> VesselState {
        VesselState {
            speed_mps: self.service_speed_mps(),
            ..self.ownship
        }
    }

    /// Checks that every number is finite, ownship moves, sizes are positive
    /// and the encounter list (if given) has one entry per target.
    ///
    /// # Errors
    /// [`PlannerError::InvalidProblem`] naming the field.
    pub fn validate(&self) -> Result<(), PlannerError> {
        let bad = |field: String, problem: &str| {
            Err(PlannerError::InvalidProblem {
                field,
                problem: problem.to_owned(),
            })
        };
        if !self.start_time_s.is_finite() {
            return bad("start_time_s".into(), "is not finite");
        }
        if self.start_time_s.abs() > MAX_START_TIME_S {
            return bad("start_time_s".into(), "is more than 1e12 s from 0");
        }
        check_vessel("ownship", &self.ownship)?;
        if self
            .steady_course_rad
            .is_some_and(|course| !course.is_finite())
        {
            return bad("steady_course_rad".into(), "is not a finite number");
        }
        match self.service_speed_mps {
            None if self.ownship.speed_mps < MIN_OWNSHIP_SPEED_MPS => {
                return bad(
                    "ownship.speed_mps".into(),
                    "must be at least 0.001 m/s for ownship to move",
                );
            }
            Some(speed) if !speed.is_finite() => {
                return bad("service_speed_mps".into(), "is not a finite number");
            }
            Some(speed) if !(MIN_OWNSHIP_SPEED_MPS..=MAX_SPEED_MPS).contains(&speed) => {
                return bad(
                    "service_speed_mps".into(),
                    "must be from 0.001 m/s (for ownship to move) to 1000 m/s",
                );
            }
            _ => {}
        }
        if !self.goal_m.is_finite() {
            return bad("goal_m".into(), "is not finite");
        }
        if self.goal_m.length() > MAX_EXTENT_M {
            return bad("goal_m".into(), "is more than 1e8 m from the origin");
        }
        if self.targets.len() > MAX_TARGETS {
            return bad("targets".into(), "holds more than 1024 vessels");
        }
        for (index, target) in self.targets.iter().enumerate() {
            check_vessel(&format!("targets[{index}]"), &target.vessel)?;
            if target.goal_m.is_some_and(|goal| !goal.is_finite()) {
                return bad(format!("targets[{index}].goal_m"), "is not finite");
            }
            if target
                .goal_m
                .is_some_and(|goal| goal.length() > MAX_EXTENT_M)
            {
                return bad(
                    format!("targets[{index}].goal_m"),
                    "is more than 1e8 m from the origin",
                );
            }
            if target
                .holds_course_for_s
                .is_some_and(|hold_s| !(0.0..=MAX_START_TIME_S).contains(&hold_s))
            {
                return bad(
                    format!("targets[{index}].holds_course_for_s"),
                    "must be a number of seconds from 0 to 1e12",
                );
            }
        }
        if !self.encounters.is_empty() && self.encounters.len() != self.targets.len() {
            return bad(
                "encounters".into(),
                "must be empty or hold exactly one entry per target",
            );
        }
        Ok(())
    }
}

fn check_vessel(name: &str, vessel: &VesselState) -> Result<(), PlannerError> {
    let fields = [
        ("position_m", vessel.position_m.x),
        ("position_m", vessel.position_m.y),
        ("course_rad", vessel.course_rad),
        ("speed_mps", vessel.speed_mps),
        ("length_m", vessel.length_m),
    ];
    for (field, value) in fields {
        if !value.is_finite() {
            return Err(PlannerError::InvalidProblem {
                field: format!("{name}.{field}"),
                problem: format!("is {value}, not a finite number"),
            });
        }
    }
    if vessel.position_m.length() > MAX_EXTENT_M {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.position_m"),
            problem: "is more than 1e8 m from the origin".into(),
        });
    }
    if vessel.speed_mps < 0.0 {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.speed_mps"),
            problem: "is negative".into(),
        });
    }
    if vessel.speed_mps > MAX_SPEED_MPS {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.speed_mps"),
            problem: "is more than 1000 m/s".into(),
        });
    }
    if vessel.length_m <= 0.0 {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.length_m"),
            problem: "must be greater than 0".into(),
        });
    }
    if vessel.length_m > MAX_LENGTH_M {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.length_m"),
            problem: "is more than 1e5 m".into(),
        });
    }
    Ok(())
}
