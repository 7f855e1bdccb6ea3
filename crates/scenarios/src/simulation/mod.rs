//! Closed-loop simulation of a scenario with a fixed time step.
//!
//! Ownship plans with the VORRT planner and sails its plan's legs with the
//! planner's own motion model (arcs at its rate of turn, then straight runs,
//! and the legs' speed profiles: its recorded speed is the plan's), so the
//! recorded track is the curve the planner checked. It plans again from its
//! present speed, with the scenario's speed as its service speed. Every target moves
//! by its [`Behaviour`](crate::Behaviour) (constant motion, COLREGs-obeying,
//! noisy, or a sudden turn; noise from a stream per target derived from the
//! run's seed, so a run is reproducible). Ownship predicts a target from what
//! it announces (course, speed, destination), or, when it is seen more than
//! [`OBSERVED_TURN_RAD`] off the course to its destination, holding the course
//! it is seen on. Every target is behind one seam, [`TargetMotion`], so a
//! target can also follow a recorded track ([`RecordedMotion`]).
//!
//! A replanning trigger (a target more than `replan_deviation_m` off its
//! prediction, or an encounter the plan did not foresee; paper §III-D) first
//! asks the planner's own validity check whether the rest of the plan in
//! force still holds; only if not does ownship plan again, from its real
//! state. When no plan keeps every rule, the graded fallback plans with fewer
//! duties (directions only, then safety only: rules 2(b), 17(b)), each
//! departure recorded; when even that fails, ownship keeps the plan in force
//! if it still holds, else turns (at its rate of turn) onto the evasive course
//! (`vorrt_planner::evasive_leg`), unless no evasive course keeps the
//! clearance or keeps clearly farther than the rest of the plan in force:
//! then that plan is held as the manoeuvre under way
//! (`vorrt_planner::holds_manoeuvre_in_force`, decision 56). While ownship sails a fallback plan or
//! the evasive manoeuvre it tries again for a fully compliant plan after
//! [`RETRY_AFTER_S`] (doubled after each retry in a row that keeps the plan
//! in force, up to [`RETRY_DOUBLINGS`] times: decision 76), or at once when
//! the encounters in force change; a
//! retry grows the planner's trees in the first, goal-biased phase only
//! (`vorrt_planner::SearchEffort::FirstPhase`), since it is one draw of many,
//! except at the last level (safety only), which always searches in full.
//! A fallback plan in force is judged by its own level's check, and a retry
//! replaces it only with a plan that keeps more rules or, at the same
//! level, arrives at least [`PAST_AND_CLEAR_GAIN_S`] sooner (decision 64);
//! otherwise the retry is recorded as a check of the plan in force, with
//! the time its search took ([`PlanCheck::search_time_s`]).
//! Every vessel's state is recorded at every step, and the encounters are
//! latched from the true states as a bridge officer would, with the
//! planner's own propagation (`vorrt_planner::validity::EncounterState`).
//!
//! The run is a value, [`ClosedLoop`]: [`ClosedLoop::step`] moves it on one
//! time step and [`ClosedLoop::state`] shows the present moment;
//! [`simulate`] steps it to the end.

use crate::error::ScenarioError;
use crate::scenario::Scenario;
use vorrt_planner::PlannerConfig;

mod closed_loop;
mod commanded;
mod planning;
mod record;
mod recorded;
mod target;

pub use closed_loop::{
    ARRIVAL_TOLERANCE_M, ClosedLoop, Decision, LoopState, RunStatus, StepOutcome,
};
pub use commanded::{COMMANDED_GOAL_TOLERANCE_M, CommandError, CommandedRun};
pub use planning::{
    EVASION_COURSES, EVASION_HORIZON_S, LATE_ARRIVAL_ASK_S, PAST_AND_CLEAR_GAIN_S,
    REFERENCE_MATCH_RAD, RETRY_AFTER_S, RETRY_DOUBLINGS, RETURN_MOVED_S,
};
pub use record::{PlanCheck, PlanEvent, PlanTrigger, SimulationRecord, call_seed};
pub use recorded::{RecordedMotion, RecordedMotionError, TimedState};
pub use target::{OBSERVED_TURN_RAD, TargetMotion};

/// Runs `scenario` in closed loop with planner seed `seed`.
///
/// ```
/// use vorrt_scenarios::{fixtures, simulate};
/// let scenario = fixtures::find("paper/head_on").unwrap().load().unwrap();
/// let record = simulate(&scenario, 1).unwrap();
/// assert!(record.reached_goal);
/// ```
///
/// # Errors
/// [`ScenarioError`] when the scenario's planner settings are invalid.
pub fn simulate(scenario: &Scenario, seed: u64) -> Result<SimulationRecord, ScenarioError> {
    let config = scenario.planner_config()?;
    simulate_with(scenario, &config, seed)
}

/// As [`simulate`], with a planner configuration given by the caller.
///
/// # Errors
/// [`ScenarioError::Invalid`] (field `planner`) when `config` is invalid.
pub fn simulate_with(
    scenario: &Scenario,
    config: &PlannerConfig,
    seed: u64,
) -> Result<SimulationRecord, ScenarioError> {
    Ok(ClosedLoop::with_config(scenario, config, seed)?.run())
}
