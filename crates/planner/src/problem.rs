//! The planning problem: where ownship is and is bound, and the targets.

use crate::error::PlannerError;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::{EncounterLatch, VesselState};
use vorrt_jfs::TargetState;

/// Largest number of targets one problem may hold: bounds the per-node memory.
pub const MAX_TARGETS: usize = 1024;

/// Everything the planner needs to know about the world at planning time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanningProblem {
    /// The clock at the start, seconds.
    pub start_time_s: f64,
    /// Ownship now. Its speed is held along the plan.
    pub ownship: VesselState,
    /// Where ownship is bound, metres.
    pub goal_m: DVec2,
    /// The other vessels now, with their predicted motion.
    pub targets: Vec<TargetState>,
    /// Encounters already in force, one entry per target (a closed loop keeps
    /// them across replans). Empty: the planner latches from the start state.
    pub encounters: Vec<Option<EncounterLatch>>,
}

impl PlanningProblem {
    /// A problem with no encounter in force yet.
    #[must_use]
    pub fn new(ownship: VesselState, goal_m: DVec2, targets: Vec<TargetState>) -> Self {
        Self {
            start_time_s: 0.0,
            ownship,
            goal_m,
            targets,
            encounters: Vec::new(),
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
        check_vessel("ownship", &self.ownship)?;
        if self.ownship.speed_mps <= 0.0 {
            return bad(
                "ownship.speed_mps".into(),
                "must be greater than 0 for ownship to move",
            );
        }
        if !self.goal_m.is_finite() {
            return bad("goal_m".into(), "is not finite");
        }
        if self.targets.len() > MAX_TARGETS {
            return bad("targets".into(), "holds more than 1024 vessels");
        }
        for (index, target) in self.targets.iter().enumerate() {
            check_vessel(&format!("targets[{index}]"), &target.vessel)?;
            if target.goal_m.is_some_and(|goal| !goal.is_finite()) {
                return bad(format!("targets[{index}].goal_m"), "is not finite");
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
    if vessel.speed_mps < 0.0 {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.speed_mps"),
            problem: "is negative".into(),
        });
    }
    if vessel.length_m <= 0.0 {
        return Err(PlannerError::InvalidProblem {
            field: format!("{name}.length_m"),
            problem: "must be greater than 0".into(),
        });
    }
    Ok(())
}
