//! Closed-loop simulation of a scenario with a fixed time step.
//!
//! Ownship plans with the VORRT planner and follows its plan at its speed;
//! every target moves by its [`Behaviour`]. Ownship replans when its plan stops
//! being valid, as the paper says (§III-D): when a target is more than
//! `replan_deviation_m` off the position the plan predicted for it, or when an
//! encounter arises that the plan did not foresee. A failed replan keeps the
//! previous plan (or, with none, the present course) and is retried after
//! [`RETRY_AFTER_S`]. Every vessel's trajectory is recorded at every step, and
//! the encounters are latched from the true states as a bridge officer would.

use crate::error::ScenarioError;
use crate::scenario::{Behaviour, Scenario};
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::time::Instant;
use vorrt_colregs::{EncounterLatch, VesselState, update_latch};
use vorrt_jfs::TargetState;
use vorrt_planner::{Plan, PlanStatistics, Planner, PlannerConfig, PlanningProblem, Waypoint};

/// Ownship has arrived when it is this close to its goal, metres (the plan
/// ends on the goal; this absorbs rounding).
pub const ARRIVAL_TOLERANCE_M: f64 = 0.01;

/// After a failed plan, seconds until ownship tries again.
pub const RETRY_AFTER_S: f64 = 30.0;

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
    /// An encounter arose that the plan did not foresee.
    NewEncounter {
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
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// When it did, seconds.
    pub arrival_time_s: Option<f64>,
}

impl SimulationRecord {
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

/// How a target is predicted by ownship: from what it broadcasts (AIS: course,
/// speed, destination), whatever it really does.
fn announced(state: &VesselState, goal_m: Option<DVec2>, behaviour: Behaviour) -> TargetState {
    match (behaviour, goal_m) {
        (Behaviour::ConstantVelocity, _) | (_, None) => TargetState::constant_velocity(*state),
        (_, Some(goal)) => TargetState {
            vessel: *state,
            goal_m: Some(goal),
        },
    }
}

/// One target as the simulation moves it.
#[derive(Debug, Clone)]
struct SimulatedTarget {
    state: TargetState,
    behaviour: Behaviour,
}

impl SimulatedTarget {
    fn advance(&mut self, duration_s: f64) {
        self.state = self.state.predict(duration_s);
    }

    fn announced(&self) -> TargetState {
        announced(&self.state.vessel, self.state.goal_m, self.behaviour)
    }
}

/// The plan ownship is following, with what it assumed about the targets.
#[derive(Debug)]
struct ActivePlan {
    plan: Plan,
    start_time_s: f64,
    predicted: Vec<TargetState>,
    anticipated: Vec<bool>,
}

/// Runs `scenario` in closed loop with planner seed `seed`.
///
/// ```
/// use vorrt_scenarios::{Scenario, simulate};
/// let scenario = Scenario::load(std::path::Path::new(concat!(
///     env!("CARGO_MANIFEST_DIR"), "/../../fixtures/paper/head_on.ron"))).unwrap();
/// let record = simulate(&scenario, 1).unwrap();
/// assert!(record.reached_goal);
/// ```
///
/// # Errors
/// [`ScenarioError`] when the scenario's planner settings are invalid.
pub fn simulate(scenario: &Scenario, seed: u64) -> Result<SimulationRecord, ScenarioError> {
    let config = scenario.planner_config()?;
    Ok(simulate_with(scenario, &config, seed))
}

/// As [`simulate`], with a planner configuration given by the caller.
#[must_use]
pub fn simulate_with(scenario: &Scenario, config: &PlannerConfig, seed: u64) -> SimulationRecord {
    let settings = scenario.simulation;
    let dt = settings.time_step_s;
    let max_duration_s = scenario.max_duration_s();
    let goal_m = scenario.ownship_goal_m();
    let mut own = scenario.ownship_state();
    let mut targets: Vec<SimulatedTarget> = scenario
        .targets
        .iter()
        .map(|spec| {
            let state = match spec.behaviour {
                Behaviour::ConstantVelocity => TargetState::constant_velocity(spec.state()),
                _ => spec.target_state(),
            };
            SimulatedTarget {
                state,
                behaviour: spec.behaviour,
            }
        })
        .collect();
    let mut latches: Vec<Option<EncounterLatch>> = vec![None; targets.len()];
    let mut planner = Planner::new(*config).ok();
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
        reached_goal: false,
        arrival_time_s: None,
    };
    let mut active: Option<ActivePlan> = None;
    let mut trigger = Some(PlanTrigger::Initial);
    let mut retry_at_s = f64::INFINITY;
    let mut time_s = 0.0;
    let mut step = 0usize;
    loop {
        for (latch, target) in latches.iter_mut().zip(&targets) {
            *latch = update_latch(*latch, &own, &target.state.vessel, time_s, &config.rules);
        }
        record.times_s.push(time_s);
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
        if trigger.is_none() {
            trigger = replan_trigger(
                active.as_ref(),
                &targets,
                &latches,
                time_s,
                settings.replan_deviation_m,
            );
        }
        if trigger.is_none() && time_s >= retry_at_s {
            trigger = Some(PlanTrigger::Retry);
        }
        if let (Some(why), Some(planner)) = (trigger.take(), planner.as_mut()) {
            let predicted: Vec<TargetState> =
                targets.iter().map(SimulatedTarget::announced).collect();
            let problem = PlanningProblem {
                start_time_s: time_s,
                ownship: own,
                goal_m,
                targets: predicted.clone(),
                encounters: latches.clone(),
            };
            let seed_now = call_seed(seed, record.plans.len());
            let started = Instant::now();
            match planner.plan(&problem, seed_now) {
                Ok(plan) => {
                    retry_at_s = f64::INFINITY;
                    record.plans.push(PlanEvent {
                        time_s,
                        trigger: why,
                        seed: seed_now,
                        succeeded: true,
                        error: None,
                        statistics: plan.statistics,
                        waypoints: plan.waypoints.clone(),
                    });
                    let anticipated = plan
                        .anticipated_encounters()
                        .iter()
                        .map(Option::is_some)
                        .collect();
                    active = Some(ActivePlan {
                        plan,
                        start_time_s: time_s,
                        predicted,
                        anticipated,
                    });
                }
                Err(error) => {
                    retry_at_s = time_s + RETRY_AFTER_S;
                    let statistics = match &error {
                        vorrt_planner::PlannerError::NoSafePath { statistics }
                        | vorrt_planner::PlannerError::BudgetExhausted { statistics, .. } => {
                            **statistics
                        }
                        _ => PlanStatistics {
                            elapsed_s: started.elapsed().as_secs_f64(),
                            ..PlanStatistics::default()
                        },
                    };
                    record.plans.push(PlanEvent {
                        time_s,
                        trigger: why,
                        seed: seed_now,
                        succeeded: false,
                        error: Some(error.to_string()),
                        statistics,
                        waypoints: Vec::new(),
                    });
                }
            }
        }
        // Advance one step.
        step += 1;
        let next_time_s = step as f64 * dt;
        let step_s = next_time_s - time_s;
        own = match &active {
            Some(active) => follow(&active.plan, &own, next_time_s),
            None => own.advanced(step_s),
        };
        for target in &mut targets {
            target.advance(step_s);
        }
        time_s = next_time_s;
    }
    record
}

/// Ownship's state at `time_s` along `plan` (at the goal once the plan ends).
fn follow(plan: &Plan, own: &VesselState, time_s: f64) -> VesselState {
    match plan.position_at(time_s) {
        Some((position_m, course_rad)) => VesselState {
            position_m,
            course_rad,
            ..*own
        },
        None => own.advanced(0.0),
    }
}

/// Whether the plan in force has stopped being valid, and why.
fn replan_trigger(
    active: Option<&ActivePlan>,
    targets: &[SimulatedTarget],
    latches: &[Option<EncounterLatch>],
    time_s: f64,
    deviation_m: f64,
) -> Option<PlanTrigger> {
    let active = active?;
    let elapsed_s = time_s - active.start_time_s;
    for (index, (target, predicted)) in targets.iter().zip(&active.predicted).enumerate() {
        let expected = predicted.predict(elapsed_s).vessel.position_m;
        if expected.distance(target.state.vessel.position_m) > deviation_m {
            return Some(PlanTrigger::TargetOffPrediction { target: index });
        }
    }
    for (index, latch) in latches.iter().enumerate() {
        if latch.is_some() && !active.anticipated.get(index).copied().unwrap_or(true) {
            return Some(PlanTrigger::NewEncounter { target: index });
        }
    }
    None
}
