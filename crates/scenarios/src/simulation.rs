//! Closed-loop simulation of a scenario with a fixed time step.
//!
//! Ownship plans with the VORRT planner and follows its plan at its speed;
//! every target moves by its [`Behaviour`] (constant motion, COLREGs-obeying,
//! noisy, or a sudden turn; noise drawn from a stream per target derived from
//! the run's seed, so a run is reproducible), while ownship predicts it from
//! what it announces (see [`Behaviour`]). Ownship replans when its plan stops
//! being valid, as the paper says (§III-D): when a target is more than
//! `replan_deviation_m` off the position the plan predicted for it, or when an
//! encounter arises that the plan did not foresee. When planning fails,
//! ownship keeps its previous plan if that still keeps the clearance from
//! every target as now predicted; otherwise it steers the evasive course
//! (`vorrt_planner::evasive_course`: its present course if that keeps the
//! clearance over the next [`EVASION_HORIZON_S`], else the smallest turn that
//! does, else the course that keeps farthest) and holds it; either way it
//! tries again after [`RETRY_AFTER_S`]. Every vessel's trajectory is recorded at every step, and
//! the encounters are latched from the true states as a bridge officer would.

use crate::error::ScenarioError;
use crate::scenario::{Behaviour, COLREGS_TURN_DEG, NOISE_TIME_CONSTANT_S, Scenario};
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use serde::{Deserialize, Serialize};
use std::time::Instant;
use vorrt_colregs::{EncounterLatch, Role, RuleParameters, VesselState, update_latch};
use vorrt_geometry::angle::signed_turn;
use vorrt_geometry::{angle, units};
use vorrt_jfs::{InstantTurn, Leg, OwnshipModel, RateLimitedTurn, TargetState};
use vorrt_planner::{
    Compliance, Plan, PlanStatistics, Planner, PlannerConfig, PlanningProblem, Waypoint,
    check_legs, evasive_leg,
};

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

/// After a failed plan, seconds until ownship tries again.
pub const RETRY_AFTER_S: f64 = 20.0;

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
    /// The COLREGs duties the plan that came back keeps: `full`, or a graded
    /// fallback (`directions`: a departure from rules 8 and 16; `safety_only`:
    /// from the steering rules, rules 2(b) and 17(b)). An evasive manoeuvre
    /// (failure) is `safety_only` too.
    #[serde(default)]
    pub compliance: Compliance,
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

/// One target as the simulation moves it.
#[derive(Debug, Clone)]
struct SimulatedTarget {
    /// Where it is now; `goal_m` is the goal it steers for (`None` once a
    /// [`Behaviour::SuddenTurn`] target has turned, or without a goal).
    state: TargetState,
    behaviour: Behaviour,
    /// The speed it announces and returns to, m/s.
    nominal_speed_mps: f64,
    /// The course it holds when it has no goal, radians.
    nominal_course_rad: f64,
    /// The noise stream of a [`Behaviour::Noisy`] target.
    noise: Option<ChaCha8Rng>,
    course_offset_rad: f64,
    speed_offset_mps: f64,
    /// A [`Behaviour::Colregs`] target's encounter with ownship, from its side.
    latch: Option<EncounterLatch>,
    /// The course a giving-way [`Behaviour::Colregs`] target holds.
    avoiding_course_rad: Option<f64>,
    /// Whether a [`Behaviour::SuddenTurn`] target has turned.
    turned: bool,
}

/// The seed of target `index`'s noise stream in a run seeded with `seed`.
fn noise_stream(seed: u64, index: usize) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6E6F_6973_795F_7467);
    rng.set_stream(index as u64);
    rng
}

/// A standard normal draw (Box-Muller) from `rng`.
fn standard_normal(rng: &mut ChaCha8Rng) -> f64 {
    // 53 random bits in (0, 1].
    let unit = |rng: &mut ChaCha8Rng| ((rng.next_u64() >> 11) as f64 + 1.0) / (1u64 << 53) as f64;
    let (u1, u2) = (unit(rng), unit(rng));
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

impl SimulatedTarget {
    fn new(spec: &crate::VesselSpec, index: usize, seed: u64) -> Self {
        let state = match spec.behaviour {
            Behaviour::ConstantVelocity => TargetState::constant_velocity(spec.state()),
            _ => spec.target_state(),
        };
        let noise =
            matches!(spec.behaviour, Behaviour::Noisy { .. }).then(|| noise_stream(seed, index));
        Self {
            state,
            behaviour: spec.behaviour,
            nominal_speed_mps: spec.speed_mps(),
            nominal_course_rad: state.vessel.course_rad,
            noise,
            course_offset_rad: 0.0,
            speed_offset_mps: 0.0,
            latch: None,
            avoiding_course_rad: None,
            turned: false,
        }
    }

    /// Moves the target from `time_s` on by `duration_s`; `own` is ownship at
    /// `time_s`.
    fn advance(&mut self, duration_s: f64, time_s: f64, own: &VesselState, rules: &RuleParameters) {
        match self.behaviour {
            Behaviour::SuddenTurn { at_s, turn_deg } => {
                if !self.turned && time_s + duration_s >= at_s {
                    let before_s = (at_s - time_s).max(0.0);
                    self.state = self.state.predict(before_s);
                    let mut vessel = self.state.vessel;
                    vessel.course_rad =
                        angle::normalize_2pi(vessel.course_rad + turn_deg.to_radians());
                    self.state = TargetState::constant_velocity(vessel);
                    self.turned = true;
                    self.state = self.state.predict(duration_s - before_s);
                } else {
                    self.state = self.state.predict(duration_s);
                }
            }
            Behaviour::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            } => {
                if let Some(rng) = self.noise.as_mut() {
                    let decay = (-duration_s / NOISE_TIME_CONSTANT_S).exp();
                    let spread = (1.0 - decay * decay).max(0.0).sqrt();
                    let course_sigma = course_sigma_deg.to_radians();
                    let speed_sigma = units::knots_to_mps(speed_sigma_kn);
                    self.course_offset_rad = decay * self.course_offset_rad
                        + course_sigma * spread * standard_normal(rng);
                    self.speed_offset_mps =
                        decay * self.speed_offset_mps + speed_sigma * spread * standard_normal(rng);
                }
                let course = self.intended_course_rad() + self.course_offset_rad;
                let speed = (self.nominal_speed_mps + self.speed_offset_mps).max(0.0);
                self.steer(course, speed, duration_s);
            }
            Behaviour::Colregs => {
                self.latch = update_latch(self.latch, &self.state.vessel, own, time_s, rules);
                match self.latch {
                    Some(latch) if latch.encounter.role() == Role::GiveWay => {
                        if self.avoiding_course_rad.is_none() {
                            self.avoiding_course_rad = Some(angle::normalize_2pi(
                                latch.reference_course_rad + COLREGS_TURN_DEG.to_radians(),
                            ));
                        }
                    }
                    _ => self.avoiding_course_rad = None,
                }
                let course = self
                    .avoiding_course_rad
                    .unwrap_or_else(|| self.intended_course_rad());
                self.steer(course, self.nominal_speed_mps, duration_s);
            }
            _ => self.state = self.state.predict(duration_s),
        }
    }

    /// The course the target would steer undisturbed: for its goal, or its
    /// nominal course without one.
    fn intended_course_rad(&self) -> f64 {
        match self.state.goal_m {
            Some(goal) if goal != self.state.vessel.position_m => {
                angle::unit_to_course(goal - self.state.vessel.position_m)
            }
            Some(_) => self.state.vessel.course_rad,
            None => self.nominal_course_rad,
        }
    }

    /// Sails `duration_s` at `course_rad` and `speed_mps`, stopping on the
    /// goal if it comes within reach.
    fn steer(&mut self, course_rad: f64, speed_mps: f64, duration_s: f64) {
        let vessel = &mut self.state.vessel;
        if self.state.goal_m == Some(vessel.position_m) {
            vessel.speed_mps = 0.0;
            return;
        }
        vessel.course_rad = angle::normalize_2pi(course_rad);
        vessel.speed_mps = speed_mps;
        let travel_m = speed_mps * duration_s;
        match self.state.goal_m {
            Some(goal) if vessel.position_m.distance(goal) <= travel_m => {
                vessel.position_m = goal;
                vessel.speed_mps = 0.0;
            }
            _ => vessel.position_m += angle::velocity(vessel.course_rad, speed_mps) * duration_s,
        }
    }

    /// How ownship predicts the target: from what it broadcasts (AIS: course,
    /// speed, destination) and what it is seen doing. A goal-bound target is
    /// predicted steering for its goal at its nominal speed, unless it is
    /// seen more than [`OBSERVED_TURN_RAD`] off that course: then it is
    /// predicted holding the course it is on. Any other target holds its
    /// course at its nominal speed (its present course and speed for the
    /// constant-motion behaviours).
    fn announced(&self) -> TargetState {
        let vessel = self.state.vessel;
        match self.behaviour {
            Behaviour::ConstantToGoal | Behaviour::ConstantVelocity => match self.state.goal_m {
                Some(goal) => TargetState {
                    vessel,
                    goal_m: Some(goal),
                },
                None => TargetState::constant_velocity(vessel),
            },
            _ => match self.state.goal_m {
                // A turn seen over ground updates the prediction: a target
                // well off the course to its destination is predicted to hold
                // the course it is seen on (it is giving way, or has changed
                // its mind), as AIS and radar show it.
                Some(goal)
                    if !self.state.has_arrived()
                        && signed_turn(
                            angle::unit_to_course(goal - vessel.position_m),
                            vessel.course_rad,
                        )
                        .abs()
                            > OBSERVED_TURN_RAD =>
                {
                    TargetState::constant_velocity(VesselState {
                        speed_mps: self.nominal_speed_mps,
                        ..vessel
                    })
                }
                Some(goal) => {
                    let speed_mps = if self.state.has_arrived() {
                        0.0
                    } else {
                        self.nominal_speed_mps
                    };
                    TargetState::toward_goal(
                        VesselState {
                            speed_mps,
                            ..vessel
                        },
                        goal,
                    )
                }
                None if self.turned => TargetState::constant_velocity(vessel),
                None => TargetState::constant_velocity(VesselState {
                    course_rad: self.nominal_course_rad,
                    speed_mps: self.nominal_speed_mps,
                    ..vessel
                }),
            },
        }
    }
}

/// The plan ownship is following, with what it assumed about the targets.
#[derive(Debug)]
struct ActivePlan {
    plan: Plan,
    /// When `predicted` was taken, seconds.
    predicted_at_s: f64,
    predicted: Vec<TargetState>,
    /// Per target, every encounter the plan expects to have with it.
    anticipated: Vec<Vec<EncounterLatch>>,
    /// Whether this is the evasive manoeuvre (judged against nothing; only
    /// the retry timer ends it).
    evasive: bool,
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
    let mut retry_at_s = f64::INFINITY;
    let mut time_s = 0.0;
    let mut step = 0usize;
    loop {
        for ((latch, altered), target) in latches.iter_mut().zip(&mut alterations).zip(&targets) {
            let before = *latch;
            *latch = update_latch(before, &own, &target.state.vessel, time_s, &config.rules);
            // The alteration made for an encounter, as the planner counts it
            // along a branch (rule 16).
            *altered = match (*latch, before) {
                (Some(now), Some(was)) if now == was => {
                    altered.max(signed_turn(now.reference_course_rad, own.course_rad).abs())
                }
                _ => 0.0,
            };
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
        if let Some(why) = trigger.take() {
            let predicted: Vec<TargetState> =
                targets.iter().map(SimulatedTarget::announced).collect();
            let problem = PlanningProblem {
                start_time_s: time_s,
                ownship: own,
                goal_m,
                targets: predicted.clone(),
                encounters: latches.clone(),
                alterations: alterations.clone(),
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
                    },
                    &mut active,
                    &mut record.plans,
                    &mut retry_at_s,
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

/// What one planner call is for.
struct PlanCall {
    why: PlanTrigger,
    seed: u64,
    clearance_m: f64,
}

/// Calls the planners on `problem`, from all the rules down the graded
/// fallback, and puts what comes of it in force: the first plan found, or on
/// failure the previous plan if the planner's validity check still accepts
/// it, or else the evasive leg (sailed with `model`).
fn plan_now(
    planners: &mut [Planner],
    problem: &PlanningProblem,
    model: &OwnshipModel,
    call: PlanCall,
    active: &mut Option<ActivePlan>,
    plans: &mut Vec<PlanEvent>,
    retry_at_s: &mut f64,
) {
    let time_s = problem.start_time_s;
    let started = Instant::now();
    let mut first_error = None;
    let mut spent = PlanStatistics::default();
    for planner in planners.iter_mut() {
        let compliance = planner.config().compliance;
        match planner.plan(problem, call.seed) {
            Ok(plan) => {
                *retry_at_s = if compliance == Compliance::Full {
                    f64::INFINITY
                } else {
                    // A fallback plan is sailed until a compliant one exists.
                    time_s + RETRY_AFTER_S
                };
                let mut statistics = plan.statistics;
                statistics.elapsed_s += spent.elapsed_s;
                plans.push(PlanEvent {
                    time_s,
                    trigger: call.why,
                    seed: call.seed,
                    succeeded: true,
                    error: first_error.map(|error: vorrt_planner::PlannerError| error.to_string()),
                    statistics,
                    waypoints: plan.waypoints.clone(),
                    evasive_course_deg: None,
                    compliance,
                });
                let anticipated = plan.anticipated_encounters();
                *active = Some(ActivePlan {
                    plan,
                    predicted_at_s: time_s,
                    predicted: problem.targets.clone(),
                    anticipated,
                    evasive: false,
                });
                return;
            }
            Err(error) => {
                if let Some(statistics) = error.statistics() {
                    spent.elapsed_s += statistics.elapsed_s;
                    if first_error.is_none() {
                        let elapsed_s = spent.elapsed_s;
                        spent = *statistics;
                        spent.elapsed_s = elapsed_s;
                    }
                }
                if first_error.is_none() {
                    first_error = Some(error);
                }
            }
        }
    }
    *retry_at_s = time_s + RETRY_AFTER_S;
    if spent.elapsed_s == 0.0 {
        spent.elapsed_s = started.elapsed().as_secs_f64();
    }
    let keep_plan = active.as_ref().is_some_and(|active| {
        !active.evasive
            && planners.first().is_some_and(|planner| {
                check_legs(
                    planner.config(),
                    problem,
                    &remaining_legs(&active.plan, time_s),
                )
                .is_ok()
            })
    });
    let evasive_course_deg = if keep_plan {
        None
    } else {
        let (leg, evasion) = evasive_leg(
            problem,
            EVASION_HORIZON_S,
            EVASION_COURSES,
            call.clearance_m,
            model,
        );
        *active = Some(ActivePlan {
            plan: leg_plan(leg, time_s),
            predicted_at_s: time_s,
            predicted: problem.targets.clone(),
            anticipated: vec![Vec::new(); problem.targets.len()],
            evasive: true,
        });
        Some(evasion.course_rad.to_degrees())
    };
    plans.push(PlanEvent {
        time_s,
        trigger: call.why,
        seed: call.seed,
        succeeded: false,
        error: first_error.map(|error| error.to_string()),
        statistics: spent,
        waypoints: Vec::new(),
        evasive_course_deg,
        compliance: if keep_plan {
            Compliance::Full
        } else {
            Compliance::SafetyOnly
        },
    });
}

/// A plan of one leg starting at `time_s` (the evasive manoeuvre).
fn leg_plan(leg: Leg, time_s: f64) -> Plan {
    Plan {
        waypoints: vec![
            Waypoint {
                position_m: leg.start_m,
                time_s,
                course_rad: leg.start_course_rad,
            },
            Waypoint {
                position_m: leg.end_m(),
                time_s: time_s + leg.duration_s(),
                course_rad: leg.course_rad,
            },
        ],
        legs: vec![leg],
        target_states: Vec::new(),
        encounters: Vec::new(),
        statistics: PlanStatistics::default(),
    }
}

/// The legs of `plan` still to sail from `time_s` on, the one under way cut
/// at ownship's present pose.
fn remaining_legs(plan: &Plan, time_s: f64) -> Vec<Leg> {
    let mut legs = Vec::new();
    for (index, leg) in plan.legs.iter().enumerate() {
        let (start_s, end_s) = (
            plan.waypoints[index].time_s,
            plan.waypoints[index + 1].time_s,
        );
        if end_s <= time_s {
            continue;
        }
        if start_s < time_s {
            legs.push(leg.remainder(time_s - start_s));
        } else {
            legs.push(*leg);
        }
    }
    legs
}

/// Ownship's state at `time_s` along `plan` (at its end once the plan ends).
fn follow(plan: &Plan, own: &VesselState, time_s: f64) -> VesselState {
    match plan.pose_at(time_s) {
        Some(pose) => VesselState {
            position_m: pose.position_m,
            course_rad: pose.course_rad,
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
    let active = active.filter(|active| !active.evasive)?;
    let elapsed_s = time_s - active.predicted_at_s;
    for (index, (target, predicted)) in targets.iter().zip(&active.predicted).enumerate() {
        let expected = predicted.predict(elapsed_s).vessel.position_m;
        if expected.distance(target.state.vessel.position_m) > deviation_m {
            return Some(PlanTrigger::TargetOffPrediction { target: index });
        }
    }
    for (index, latch) in latches.iter().enumerate() {
        // Foreseen: the plan latched the same type against (nearly) the same
        // reference course, so its COLREGs checks are the ones in force.
        let foreseen = |actual: &EncounterLatch| {
            active.anticipated.get(index).is_none_or(|expected| {
                expected.iter().any(|planned| {
                    planned.encounter == actual.encounter
                        && signed_turn(planned.reference_course_rad, actual.reference_course_rad)
                            .abs()
                            <= REFERENCE_MATCH_RAD
                })
            })
        };
        if let Some(latch) = latch
            && !foreseen(latch)
        {
            return Some(PlanTrigger::NewEncounter { target: index });
        }
    }
    None
}
