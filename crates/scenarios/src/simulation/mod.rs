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
//! it is seen on.
//!
//! A replanning trigger (a target more than `replan_deviation_m` off its
//! prediction, or an encounter the plan did not foresee; paper §III-D) first
//! asks the planner's own validity check whether the rest of the plan in
//! force still holds; only if not does ownship plan again, from its real
//! state. When no plan keeps every rule, the graded fallback plans with fewer
//! duties (directions only, then safety only: rules 2(b), 17(b)), each
//! departure recorded; when even that fails, ownship keeps the plan in force
//! if it still holds, else turns (at its rate of turn) onto the evasive course
//! (`vorrt_planner::evasive_leg`). While ownship sails a fallback plan or
//! the evasive manoeuvre it tries again for a fully compliant plan after
//! [`RETRY_AFTER_S`], or at once when the encounters in force change; a
//! retry grows the planner's trees in the first, goal-biased phase only
//! (`vorrt_planner::SearchEffort::FirstPhase`), since it is one draw of many,
//! except at the last level (safety only), which always searches in full.
//! Every vessel's state is recorded at every step, and the encounters are
//! latched from the true states as a bridge officer would.

use crate::error::ScenarioError;
use crate::scenario::Scenario;
use serde::{Deserialize, Serialize};
use vorrt_colregs::rules::{STEADY_COURSE_WINDOW_S, steady_course_rad};
use vorrt_colregs::rules::{acting_for_any, alteration_made};
use vorrt_colregs::{EncounterLatch, VesselState, update_latch_steady};
use vorrt_jfs::{InstantTurn, OwnshipModel, RateLimitedTurn, TargetState};
use vorrt_planner::{
    Compliance, PlanStatistics, Planner, PlannerConfig, PlanningProblem, Waypoint, check_legs,
};

mod planning;
mod target;

use planning::{
    ActivePlan, PlanCall, RetryTimer, follow, plan_now, remaining_legs, replan_trigger,
};
use target::SimulatedTarget;

/// Ownship has arrived when it is this close to its goal, metres (the plan
/// ends on the goal; this absorbs rounding).
pub const ARRIVAL_TOLERANCE_M: f64 = 0.01;

/// A latched encounter is the one the plan foresaw when their reference
/// courses agree within this, radians (4°).
pub const REFERENCE_MATCH_RAD: f64 = 4.0 * std::f64::consts::PI / 180.0;

/// A target whose course over ground is this far off the course to its
/// announced destination is predicted on the course it is seen on, radians
/// (10°, twice the course noise of a `noisy` target).
pub const OBSERVED_TURN_RAD: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// After a failed plan (or a fallback plan), seconds until ownship tries
/// again for a plan that keeps every rule, unless the encounters in force
/// change first.
pub const RETRY_AFTER_S: f64 = 20.0;

/// A target's predicted return to its route that moves by more than this
/// from the one the plan in force assumed asks whether that plan still
/// holds, seconds: the uncertainty its prediction allows for
/// (`vorrt_jfs::TURN_TIMING_UNCERTAINTY_S`).
pub const RETURN_MOVED_S: f64 = vorrt_jfs::TURN_TIMING_UNCERTAINTY_S;

/// How far ahead the evasive course is judged, seconds.
pub const EVASION_HORIZON_S: f64 = 600.0;

/// How many evenly spaced courses the evasive manoeuvre chooses from (5°).
pub const EVASION_COURSES: usize = 72;

/// Why ownship planned.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum PlanTrigger {
    /// The first plan, at the start.
    Initial,
    /// A target was off the plan's prediction by more than the threshold.
    TargetOffPrediction {
        /// Index of the target.
        target: usize,
    },
    /// An encounter arose that the plan did not foresee (none, or another type).
    NewEncounter {
        /// Index of the target.
        target: usize,
    },
    /// A target's predicted return to its route (decision 25 in
    /// `docs/architecture.md`) appeared, vanished or moved by more than
    /// [`RETURN_MOVED_S`] since the plan's prediction.
    PredictionChanged {
        /// Index of the target.
        target: usize,
    },
    /// The previous attempt failed; trying again.
    Retry,
}

/// One call of the planner during a run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanEvent {
    /// Simulation time of the call, seconds.
    pub time_s: f64,
    /// Why ownship planned.
    pub trigger: PlanTrigger,
    /// The planner's seed for this call.
    pub seed: u64,
    /// Whether a plan came back.
    pub succeeded: bool,
    /// The planner's error, when it failed.
    pub error: Option<String>,
    /// Search statistics (on failure, those the error carried where it had them).
    pub statistics: PlanStatistics,
    /// The plan's waypoints (empty on failure).
    pub waypoints: Vec<Waypoint>,
    /// On failure, the evasive course ownship turned to, degrees (`None` when
    /// it kept its previous plan, still safe).
    pub evasive_course_deg: Option<f64>,
    /// On failure, the speed the evasive manoeuvre settles at, m/s: the
    /// service speed, half of it or 0 (stop); `None` as for the course.
    #[serde(default)]
    pub evasive_speed_mps: Option<f64>,
    /// The COLREGs duties the plan that came back keeps: `full`, or a graded
    /// fallback (`directions`: a departure from rules 8 and 16; `safety_only`:
    /// from the steering rules, rules 2(b) and 17(b)). An evasive manoeuvre
    /// (failure) is `safety_only` too.
    #[serde(default)]
    pub compliance: Compliance,
    /// Random samples drawn by every search of this call, over every level
    /// of the graded fallback tried (`statistics` holds only the search
    /// whose plan came back): the call's work, independent of the machine.
    #[serde(default)]
    pub samples_drawn: u64,
}

impl PlanEvent {
    /// Whether ownship departed from the rules after this call (a fallback
    /// plan or the evasive manoeuvre), as rules 2(b) and 17(b) allow to avoid
    /// immediate danger.
    #[must_use]
    pub fn departs_from_rules(&self) -> bool {
        self.compliance != Compliance::Full
    }
}

/// A replanning trigger after which the plan in force passed the planner's
/// validity check again and was kept.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PlanCheck {
    /// Simulation time of the check, seconds.
    pub time_s: f64,
    /// What triggered it.
    pub trigger: PlanTrigger,
}

/// Everything that happened in one closed-loop run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimulationRecord {
    /// The scenario's name.
    pub scenario: String,
    /// The seed the run was made with.
    pub seed: u64,
    /// The time step, seconds.
    pub time_step_s: f64,
    /// The time of every recorded step, seconds.
    pub times_s: Vec<f64>,
    /// Ownship at every step.
    pub ownship: Vec<VesselState>,
    /// Name of every target.
    pub target_names: Vec<String>,
    /// Every target at every step: `targets[target][step]`.
    pub targets: Vec<Vec<VesselState>>,
    /// Every planner call.
    pub plans: Vec<PlanEvent>,
    /// Every time a replanning trigger fired but the plan in force still
    /// passed the planner's validity check, so ownship kept it.
    #[serde(default)]
    pub plans_kept: Vec<PlanCheck>,
    /// The planner configuration the run was made with (d_th and the rules
    /// that judge it come from here).
    pub config: PlannerConfig,
    /// Ownship's largest rate of turn, radians per second (`None`:
    /// instantaneous turns, the paper's model).
    #[serde(default)]
    pub max_turn_rate_rad_s: Option<f64>,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// When it did, seconds.
    pub arrival_time_s: Option<f64>,
}

impl SimulationRecord {
    /// Every replanning trigger of the run with its time, whether it led to
    /// a planner call or the plan in force was kept, in time order.
    #[must_use]
    pub fn triggers(&self) -> Vec<(f64, PlanTrigger)> {
        let mut all: Vec<(f64, PlanTrigger)> = self
            .plans
            .iter()
            .map(|event| (event.time_s, event.trigger))
            .chain(
                self.plans_kept
                    .iter()
                    .map(|kept| (kept.time_s, kept.trigger)),
            )
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0));
        all
    }

    /// Planner calls that returned a plan.
    #[must_use]
    pub fn plans_made(&self) -> usize {
        self.plans.iter().filter(|event| event.succeeded).count()
    }

    /// Planner calls after the first.
    #[must_use]
    pub fn replans(&self) -> usize {
        self.plans.len().saturating_sub(1)
    }

    /// Planner calls after which ownship departed from the rules (a graded
    /// fallback plan or the evasive manoeuvre).
    #[must_use]
    pub fn rule_departures(&self) -> usize {
        self.plans
            .iter()
            .filter(|event| event.departs_from_rules())
            .count()
    }

    /// Planner calls that failed.
    #[must_use]
    pub fn failed_plans(&self) -> usize {
        self.plans.iter().filter(|event| !event.succeeded).count()
    }

    /// Wall-clock time spent planning, seconds.
    #[must_use]
    pub fn planning_time_s(&self) -> f64 {
        self.plans
            .iter()
            .map(|event| event.statistics.elapsed_s)
            .sum()
    }

    /// Length of ownship's sailed track, metres.
    #[must_use]
    pub fn path_length_m(&self) -> f64 {
        self.ownship
            .windows(2)
            .map(|pair| pair[0].position_m.distance(pair[1].position_m))
            .sum()
    }
}

/// The seed of the `call`-th planner call of a run seeded with `seed`: a
/// fixed mix, so that every call draws a different but reproducible stream.
#[must_use]
pub fn call_seed(seed: u64, call: usize) -> u64 {
    seed ^ (call as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
}

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
    let invalid = |error: vorrt_planner::PlannerError| ScenarioError::Invalid {
        file: scenario.source.clone(),
        field: "planner".into(),
        problem: error.to_string(),
    };
    // One planner per level of the graded fallback, from all the rules down.
    let mut planners = Vec::new();
    let mut level = Some(config.compliance);
    while let Some(compliance) = level {
        planners.push(
            Planner::new(PlannerConfig {
                compliance,
                ..*config
            })
            .map_err(invalid)?,
        );
        level = compliance.relaxed();
    }
    let settings = scenario.simulation;
    let dt = settings.time_step_s;
    let max_duration_s = scenario.max_duration_s();
    let goal_m = scenario.ownship_goal_m();
    let mut own = scenario.ownship_state();
    // Ownship's service speed: it may slow down (or stop) along a plan, and
    // plans again from its present speed, speeding back up to this one.
    let service_speed_mps = own.speed_mps;
    let speed_change_mps2 = config.speed_change_rate_mps2(own.length_m, service_speed_mps);
    let max_turn_rate_rad_s = config
        .turning
        .max_turn_rate_rad_s(own.length_m, own.speed_mps);
    // Ownship sails every plan, and every evasive turn, with the planner's
    // own motion model, so the recorded track is the curve the planner
    // checked.
    let model = match max_turn_rate_rad_s {
        Some(rate) => OwnshipModel::RateLimited(RateLimitedTurn::from_rate(own.speed_mps, rate)),
        None => OwnshipModel::Instant(InstantTurn {
            max_turn_rad: std::f64::consts::PI,
        }),
    };
    let mut targets: Vec<SimulatedTarget> = scenario
        .targets
        .iter()
        .enumerate()
        .map(|(index, spec)| SimulatedTarget::new(spec, index, seed))
        .collect();
    let mut latches: Vec<Option<EncounterLatch>> = vec![None; targets.len()];
    let mut alterations: Vec<f64> = vec![0.0; targets.len()];
    let mut record = SimulationRecord {
        scenario: scenario.name.clone(),
        seed,
        time_step_s: dt,
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
        config: *config,
        max_turn_rate_rad_s,
        reached_goal: false,
        arrival_time_s: None,
    };
    let mut active: Option<ActivePlan> = None;
    let mut trigger = Some(PlanTrigger::Initial);
    let mut retry = RetryTimer::idle();
    let mut time_s = 0.0;
    let mut step = 0usize;
    // Ownship's courses so far, for the course an observer still sees
    // steady (rules::steady_course_rad).
    let mut own_courses_rad: Vec<f64> = Vec::new();
    loop {
        own_courses_rad.push(own.course_rad);
        record.times_s.push(time_s);
        let steady_course_rad =
            steady_course_rad(&record.times_s, &own_courses_rad, STEADY_COURSE_WINDOW_S)
                .unwrap_or(own.course_rad);
        let acting_for_others = acting_for_any(
            latches.iter().zip(&targets).filter_map(|(latch, target)| {
                let range_m = own.range_to(&target.state.vessel);
                latch.as_ref().map(|latch| (latch, range_m))
            }),
            &config.rules,
        );
        for ((latch, altered), target) in latches.iter_mut().zip(&mut alterations).zip(&targets) {
            let before = *latch;
            *latch = update_latch_steady(
                before,
                &own,
                steady_course_rad,
                &target.state.vessel,
                time_s,
                &config.rules,
            );
            // What ownship carries for an encounter, as the planner counts
            // it along a branch (rules 16, 17).
            *altered = alteration_made(before, *latch, *altered, own.course_rad, acting_for_others);
        }
        record.ownship.push(own);
        for (track, target) in record.targets.iter_mut().zip(&targets) {
            track.push(target.state.vessel);
        }
        if own.position_m.distance(goal_m) <= ARRIVAL_TOLERANCE_M {
            record.reached_goal = true;
            record.arrival_time_s = Some(time_s);
            break;
        }
        if time_s >= max_duration_s {
            break;
        }
        // How ownship predicts the targets now (what it would plan with).
        let predicted: Vec<TargetState> = targets
            .iter()
            .zip(&latches)
            .map(|(target, latch)| {
                target.announced(&own, latch.map(|latch| latch.encounter), &config.rules)
            })
            .collect();
        if trigger.is_none() {
            trigger = replan_trigger(
                active.as_ref(),
                &targets,
                &predicted,
                &latches,
                time_s,
                settings.replan_deviation_m,
            );
        }
        if trigger.is_none() && retry.due(time_s, &latches) {
            trigger = Some(PlanTrigger::Retry);
        }
        if let Some(why) = trigger.take() {
            let problem = PlanningProblem {
                start_time_s: time_s,
                ownship: own,
                service_speed_mps: Some(service_speed_mps),
                goal_m,
                targets: predicted.clone(),
                encounters: latches.clone(),
                alterations: alterations.clone(),
                steady_course_rad: Some(steady_course_rad),
            };
            // The plan in force is kept while the planner's own validity
            // check still accepts the rest of it, as the targets are now
            // predicted and with the encounters now in force: a new plan
            // would only be a different random branch, and changing course
            // without need is what rule 8(b) warns against.
            let still_valid = why != PlanTrigger::Retry
                && active.as_ref().is_some_and(|active| {
                    check_legs(config, &problem, &remaining_legs(&active.plan, time_s)).is_ok()
                });
            if still_valid {
                if let Some(active) = active.as_mut() {
                    active.predicted = predicted;
                    active.predicted_at_s = time_s;
                    for (expected, latch) in active.anticipated.iter_mut().zip(&latches) {
                        if let Some(latch) = latch
                            && !expected.contains(latch)
                        {
                            expected.push(*latch);
                        }
                    }
                }
                record.plans_kept.push(PlanCheck {
                    time_s,
                    trigger: why,
                });
            } else {
                plan_now(
                    &mut planners,
                    &problem,
                    &model,
                    PlanCall {
                        why,
                        seed: call_seed(seed, record.plans.len()),
                        clearance_m: config.clearance_m,
                        speed_change_mps2,
                    },
                    &mut active,
                    &mut record.plans,
                    &mut retry,
                );
            }
        }
        // Advance one step.
        step += 1;
        let next_time_s = step as f64 * dt;
        let step_s = next_time_s - time_s;
        let own_now = own;
        own = match &active {
            Some(active) => follow(&active.plan, &own, next_time_s),
            None => own.advanced(step_s),
        };
        for target in &mut targets {
            target.advance(step_s, time_s, &own_now, &config.rules);
        }
        time_s = next_time_s;
    }
    Ok(record)
}
