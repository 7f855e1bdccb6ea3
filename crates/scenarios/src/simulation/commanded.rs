//! A run whose ownship is steered from outside: each step it is given a
//! course and a speed to make (by a person, a learning agent, another
//! planner) instead of following vorrt's plan. The targets move as in the
//! closed loop ([`ClosedLoop::scenario_motions`]), ownship turns and changes
//! speed with the planner's own motion model, and the record is a
//! [`SimulationRecord`] that [`evaluate`](crate::evaluate) judges like any
//! other run (decision 34: the Gymnasium environment is built on it).

use super::closed_loop::{ClosedLoop, RunStatus};
use super::record::SimulationRecord;
use super::target::TargetMotion;
use crate::error::ScenarioError;
use crate::scenario::Scenario;
use crate::validate::MAX_SPEED_KN;
use glam::DVec2;
use vorrt_colregs::VesselState;
use vorrt_colregs::observed::TrackObservation;
use vorrt_geometry::units;
use vorrt_jfs::{MotionModel, OwnshipModel, Pose};
use vorrt_planner::PlannerConfig;

/// A commanded ownship has arrived when it is this close to its goal,
/// metres: the goal tolerance `vorrt judge` gives any planner's recorded
/// track (`--goal-tolerance-m`), since a course and speed chosen step by
/// step cannot end on the goal to the centimetre as a plan does.
pub const COMMANDED_GOAL_TOLERANCE_M: f64 = 100.0;

/// Why a command was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CommandError {
    /// The course is not a finite number.
    #[error("course_rad is {0}, expected a finite number")]
    Course(f64),
    /// The speed is not finite, negative, or above the format's limit.
    #[error("speed_mps is {0}, expected 0 to {max} m/s", max = units::knots_to_mps(MAX_SPEED_KN))]
    Speed(f64),
    /// The run has already finished.
    #[error("the run has finished")]
    Finished,
}

/// One run of a scenario with ownship steered by commands, held at its
/// present moment.
#[derive(Debug)]
pub struct CommandedRun {
    model: OwnshipModel,
    speed_change_mps2: f64,
    time_step_s: f64,
    max_duration_s: f64,
    goal_m: DVec2,
    goal_tolerance_m: f64,
    config: PlannerConfig,
    step: usize,
    time_s: f64,
    own: VesselState,
    targets: Vec<Box<dyn TargetMotion>>,
    target_states: Vec<VesselState>,
    status: RunStatus,
    record: SimulationRecord,
}

impl CommandedRun {
    /// A run of `scenario` at time 0; `seed` seeds the targets' behaviours
    /// as in [`ClosedLoop::new`]. Ownship has arrived within
    /// `goal_tolerance_m` of its goal.
    ///
    /// # Errors
    /// [`ScenarioError`] when the scenario's planner settings are invalid
    /// (they give ownship's motion model and the rule constants), or
    /// (field `goal_tolerance_m`) the tolerance is not a positive number.
    pub fn new(
        scenario: &Scenario,
        seed: u64,
        goal_tolerance_m: f64,
    ) -> Result<Self, ScenarioError> {
        if !(goal_tolerance_m.is_finite() && goal_tolerance_m > 0.0) {
            return Err(ScenarioError::Invalid {
                file: scenario.source.clone(),
                field: "goal_tolerance_m".into(),
                problem: format!("is {goal_tolerance_m}, expected a positive number of metres"),
            });
        }
        let config = scenario.planner_config()?;
        let own = scenario.ownship_state();
        let targets = ClosedLoop::scenario_motions(scenario, seed);
        let target_states: Vec<VesselState> =
            targets.iter().map(|motion| motion.vessel()).collect();
        let record = SimulationRecord {
            scenario: scenario.name.clone(),
            seed,
            time_step_s: scenario.simulation.time_step_s,
            times_s: Vec::new(),
            ownship: Vec::new(),
            target_names: scenario
                .targets
                .iter()
                .map(|spec| spec.name.clone())
                .collect(),
            targets: vec![Vec::new(); targets.len()],
            plans: Vec::new(),
            plans_kept: Vec::new(),
            config,
            max_turn_rate_rad_s: config
                .turning
                .max_turn_rate_rad_s(own.length_m, own.speed_mps),
            reached_goal: false,
            arrival_time_s: None,
            // Ownship's track is exact; each target's as its motion says.
            observations: std::iter::once(TrackObservation::exact())
                .chain(targets.iter().map(|motion| motion.observation()))
                .collect(),
        };
        let mut run = Self {
            // The one place a configuration becomes the model ownship
            // sails, as in the closed loop.
            model: config.turning.ownship_model(own.length_m, own.speed_mps),
            speed_change_mps2: config.speed_change_rate_mps2(own.length_m, own.speed_mps),
            time_step_s: scenario.simulation.time_step_s,
            max_duration_s: scenario.max_duration_s(),
            goal_m: scenario.ownship_goal_m(),
            goal_tolerance_m,
            config,
            step: 0,
            time_s: 0.0,
            own,
            targets,
            target_states,
            status: RunStatus::Running,
            record,
        };
        run.observe();
        Ok(run)
    }

    /// Sails one time step making `course_rad` (radians clockwise from
    /// north) and `speed_mps`: ownship turns toward the course and changes
    /// speed at the motion model's rates, every target moves by its
    /// behaviour, and the new moment is recorded. Gives the status after
    /// the step.
    ///
    /// # Errors
    /// [`CommandError`] for a course or speed out of range, or when the run
    /// has finished; nothing is done then.
    pub fn step(&mut self, course_rad: f64, speed_mps: f64) -> Result<RunStatus, CommandError> {
        if self.status.is_finished() {
            return Err(CommandError::Finished);
        }
        if !course_rad.is_finite() {
            return Err(CommandError::Course(course_rad));
        }
        if !(speed_mps.is_finite()
            && (0.0..=units::knots_to_mps(MAX_SPEED_KN)).contains(&speed_mps))
        {
            return Err(CommandError::Speed(speed_mps));
        }
        self.step += 1;
        #[expect(clippy::cast_precision_loss, reason = "a step count, far below 2^52")]
        let next_time_s = self.step as f64 * self.time_step_s;
        let elapsed_s = next_time_s - self.time_s;
        let own_now = self.own;
        let pose = Pose {
            position_m: own_now.position_m,
            course_rad: own_now.course_rad,
        };
        // Long enough that ownship is still on the leg at the step's end.
        let straight_m = own_now.speed_mps.max(speed_mps) * elapsed_s + 1.0;
        let leg = self
            .model
            .turn_onto(pose, course_rad, speed_mps, straight_m)
            .from_speed(own_now.speed_mps, self.speed_change_mps2);
        let at = leg.pose_at(elapsed_s);
        self.own = VesselState {
            position_m: at.position_m,
            course_rad: at.course_rad,
            speed_mps: leg.speed_at(elapsed_s),
            ..own_now
        };
        for (target, state) in self.targets.iter_mut().zip(&mut self.target_states) {
            target.advance(self.time_s, next_time_s, &own_now, &self.config.rules);
            *state = target.vessel();
        }
        self.time_s = next_time_s;
        self.observe();
        Ok(self.status)
    }

    /// Records the present moment and ends the run on arrival or time out.
    fn observe(&mut self) {
        self.record.times_s.push(self.time_s);
        self.record.ownship.push(self.own);
        for (track, state) in self.record.targets.iter_mut().zip(&self.target_states) {
            track.push(*state);
        }
        if self.own.position_m.distance(self.goal_m) <= self.goal_tolerance_m {
            self.record.reached_goal = true;
            self.record.arrival_time_s = Some(self.time_s);
            self.status = RunStatus::ReachedGoal;
        } else if self.time_s >= self.max_duration_s {
            self.status = RunStatus::OutOfTime;
        }
    }

    /// The present time, seconds.
    #[must_use]
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Ownship now.
    #[must_use]
    pub fn ownship(&self) -> VesselState {
        self.own
    }

    /// Every target now, in the scenario's order.
    #[must_use]
    pub fn targets(&self) -> &[VesselState] {
        &self.target_states
    }

    /// Ownship's goal, metres.
    #[must_use]
    pub fn goal_m(&self) -> DVec2 {
        self.goal_m
    }

    /// Where the run stands.
    #[must_use]
    pub fn status(&self) -> RunStatus {
        self.status
    }

    /// The record so far.
    #[must_use]
    pub fn record(&self) -> &SimulationRecord {
        &self.record
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate;
    use vorrt_geometry::angle;

    fn head_on() -> Scenario {
        crate::fixtures::find("paper/head_on")
            .expect("fixture")
            .load()
            .expect("valid")
    }

    #[test]
    fn steering_for_the_goal_arrives_and_is_judged() {
        let scenario = head_on();
        let mut run = CommandedRun::new(&scenario, 1, COMMANDED_GOAL_TOLERANCE_M).expect("run");
        let speed_mps = run.ownship().speed_mps;
        let mut steps = 0;
        while run.status() == RunStatus::Running {
            let to_goal = run.goal_m() - run.ownship().position_m;
            run.step(angle::unit_to_course(to_goal), speed_mps)
                .expect("in range");
            steps += 1;
        }
        assert_eq!(run.status(), RunStatus::ReachedGoal);
        assert!(steps > 10);
        #[expect(clippy::cast_precision_loss, reason = "a step count")]
        let end_s = steps as f64 * scenario.simulation.time_step_s;
        assert!((run.time_s() - end_s).abs() < 1e-9);
        assert_eq!(run.targets().len(), scenario.targets.len());
        assert_eq!(
            run.targets()[0],
            *run.record().targets[0].last().expect("recorded")
        );
        assert_eq!(run.record().times_s.len(), steps + 1);
        assert_eq!(run.step(0.0, 1.0), Err(CommandError::Finished));
        // Straight at a head-on target: the one evaluation finds it.
        let evaluation = evaluate(&scenario, run.record());
        assert!(evaluation.reached_goal);
        assert!(!evaluation.safe_and_compliant(), "{}", evaluation.table());
    }

    #[test]
    fn turns_at_the_models_rate_and_refuses_bad_commands() {
        let scenario = head_on();
        let mut run = CommandedRun::new(&scenario, 1, COMMANDED_GOAL_TOLERANCE_M).expect("run");
        let before = run.ownship().course_rad;
        run.step(before + std::f64::consts::FRAC_PI_2, 3.0)
            .expect("in range");
        let turned = angle::signed_turn(before, run.ownship().course_rad);
        let limit = run.record().max_turn_rate_rad_s.expect("rate-limited");
        assert!(turned > 0.0 && turned <= limit * scenario.simulation.time_step_s + 1e-9);
        assert!(run.ownship().speed_mps < units::knots_to_mps(12.0));
        assert!(matches!(
            run.step(f64::NAN, 1.0),
            Err(CommandError::Course(_))
        ));
        assert!(matches!(run.step(0.0, -1.0), Err(CommandError::Speed(_))));
        assert!(CommandedRun::new(&scenario, 1, 0.0).is_err());
    }
}
