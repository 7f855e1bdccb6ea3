//! The closed loop as a value: [`ClosedLoop`] holds one run at its present
//! moment and moves it on one time step at a time, so a caller (a binding, a
//! replay viewer, an external simulator) can step it, look at it between
//! steps, and take its record when done.

use super::planning::{
    ActivePlan, Asked, PlanCall, RetryTimer, follow, graded_planners, in_force_holds,
    late_arrival_due, past_and_clear_due, plan_if_sooner, plan_now, replan_trigger, retry_in_force,
};
use super::record::{PlanCheck, PlanTrigger, SimulationRecord, call_seed};
use super::recorded::RecordedMotion;
use super::target::{BehaviourTarget, TargetMotion};
use crate::chart::Chart;
use crate::error::ScenarioError;
use crate::scenario::{Behaviour, Scenario};
use crate::scheme::scenario_constraint;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::observed::TrackObservation;
use vorrt_colregs::rules::{STEADY_COURSE_WINDOW_S, steady_course_rad};
use vorrt_colregs::{EncounterLatch, VesselState};
use vorrt_jfs::{OwnshipModel, TargetState};
use vorrt_planner::scheme::SchemeConstraint;
use vorrt_planner::validity::EncounterState;
use vorrt_planner::{Constraint, Plan, Planner, PlannerConfig, PlanningProblem};

/// Ownship has arrived when it is this close to its goal, metres (the plan
/// ends on the goal; this absorbs rounding).
pub const ARRIVAL_TOLERANCE_M: f64 = 0.01;

/// Where a closed-loop run stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RunStatus {
    /// Still under way: [`ClosedLoop::step`] moves it on.
    Running,
    /// Ownship reached its goal (within [`ARRIVAL_TOLERANCE_M`]).
    ReachedGoal,
    /// The scenario's longest simulated time ran out first.
    OutOfTime,
}

impl RunStatus {
    /// Whether the run has ended.
    #[must_use]
    pub fn is_finished(self) -> bool {
        self != Self::Running
    }
}

/// What ownship decided at the start of a step, before sailing it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Decision {
    /// No replanning trigger fired: it sailed on with the plan in force.
    SailedOn,
    /// A trigger fired, but the rest of the plan in force passed the
    /// planner's validity check and was kept (recorded in
    /// [`SimulationRecord::plans_kept`]).
    KeptPlan(PlanTrigger),
    /// A trigger fired and the planner was called; the record's last
    /// [`PlanEvent`](super::PlanEvent) says what came of it.
    Planned(PlanTrigger),
}

/// What one [`ClosedLoop::step`] did.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepOutcome {
    /// When the step began and ownship decided, seconds.
    pub from_s: f64,
    /// The time the step reached, seconds: the present time after it.
    pub time_s: f64,
    /// What ownship decided at `from_s`.
    pub decision: Decision,
    /// Where the run stands at `time_s`.
    pub status: RunStatus,
}

/// A read-only view of a closed loop at its present moment
/// ([`ClosedLoop::state`]).
///
/// The vessels are where they truly are now and the encounters are the ones
/// latched from those states; the plan is the one ownship sailed into this
/// moment with (the next step first decides whether to keep it).
#[derive(Debug, Clone, Copy)]
pub struct LoopState<'a> {
    /// The present time, seconds since the run's start.
    pub time_s: f64,
    /// Time steps sailed so far.
    pub step: usize,
    /// Ownship now.
    pub ownship: VesselState,
    /// Every target's name, in the scenario's order.
    pub target_names: &'a [String],
    /// Every target now, in the same order.
    pub targets: &'a [VesselState],
    /// Each target's encounter with ownship in force now, if any (rules
    /// 13-17, latched as a bridge officer would).
    pub encounters: &'a [Option<EncounterLatch>],
    /// What ownship carries for each encounter, radians: the alteration of
    /// course it has made (rule 16) or was last free to make (rule 17), 0
    /// without one.
    pub alterations_rad: &'a [f64],
    /// The plan in force: its waypoints and legs (`None` before the first
    /// planner call).
    pub plan: Option<&'a Plan>,
    /// Whether the plan in force is the evasive manoeuvre (no plan could be
    /// found; rules 2(b) and 17(b)).
    pub evasive: bool,
    /// Where the run stands.
    pub status: RunStatus,
}

/// What stays the same for the whole run.
#[derive(Debug)]
struct Setup<C> {
    /// One planner per level of the graded fallback, all the rules first,
    /// each keeping the scenario's chart (land, no-go areas) and the run's
    /// constraint.
    planners: Vec<Planner<(Chart, C)>>,
    config: PlannerConfig,
    seed: u64,
    time_step_s: f64,
    max_duration_s: f64,
    replan_deviation_m: f64,
    goal_m: DVec2,
    /// Ownship's service speed: it may slow down (or stop) along a plan,
    /// and plans again from its present speed, speeding back up to this.
    service_speed_mps: f64,
    speed_change_mps2: f64,
    /// Ownship sails every plan, and every evasive turn, with the
    /// planner's own motion model, so the recorded track is the curve the
    /// planner checked.
    model: OwnshipModel,
}

/// One closed-loop run of a scenario, held at its present moment (see the
/// [module documentation](crate::simulation) for what happens in a step).
///
/// [`simulate`](super::simulate) is [`ClosedLoop::run`]; stepping by hand
/// gives the same [`SimulationRecord`]. Ownship's planner keeps a user
/// [`Constraint`] too ([`ClosedLoop::with_constraint`]; by default the
/// scenario's traffic separation scheme, [`scenario_constraint`], which
/// refuses nothing without lanes), beside the scenario's [`Chart`] (land,
/// no-go areas), which it always keeps: every plan, every check of the plan
/// in force and the evasive manoeuvre.
#[derive(Debug)]
pub struct ClosedLoop<C = SchemeConstraint> {
    setup: Setup<C>,
    step: usize,
    time_s: f64,
    own: VesselState,
    targets: Vec<Box<dyn TargetMotion>>,
    /// Every target's true state now (`targets[i].vessel()`).
    target_states: Vec<VesselState>,
    /// The encounters latched from the true states, and what ownship
    /// carries for each: the planner's own propagation
    /// ([`EncounterState::advance_to`]).
    encounters: EncounterState,
    /// The course an observer still sees steady now
    /// (`rules::steady_course_rad`).
    steady_course_rad: f64,
    /// Ownship's course at every recorded time, for that.
    own_courses_rad: Vec<f64>,
    active: Option<ActivePlan>,
    /// A reason to plan at the next decision already known (the first plan).
    pending: Option<PlanTrigger>,
    /// When ownship last asked for a sooner plan as the plan in force
    /// arrived too late ([`PlanTrigger::LateArrival`]), seconds.
    late_asked_s: f64,
    retry: RetryTimer,
    status: RunStatus,
    record: SimulationRecord,
}

impl ClosedLoop {
    /// A run of `scenario` with planner seed `seed`, its planner
    /// configuration from the scenario, at time 0.
    ///
    /// # Errors
    /// [`ScenarioError`] when the scenario's planner settings are invalid.
    pub fn new(scenario: &Scenario, seed: u64) -> Result<Self, ScenarioError> {
        let config = scenario.planner_config()?;
        Self::with_config(scenario, &config, seed)
    }

    /// As [`new`](Self::new), with a planner configuration given by the
    /// caller.
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`]: field `planner` when `config` is
    /// invalid, a target's `behaviour` when it is `Recorded` and has no
    /// track in [`Scenario::recorded`].
    pub fn with_config(
        scenario: &Scenario,
        config: &PlannerConfig,
        seed: u64,
    ) -> Result<Self, ScenarioError> {
        scenario.check_recorded()?;
        Self::with_motions(
            scenario,
            config,
            seed,
            Self::scenario_motions(scenario, seed),
        )
    }

    /// The scenario's targets as a run seeded with `seed` moves them, each
    /// by its [`Behaviour`](crate::Behaviour), in the scenario's order (a
    /// `Recorded` one by a [`RecordedMotion`] on its track in
    /// [`Scenario::recorded`]; without one, on its course and speed): the
    /// motions [`with_config`](Self::with_config) uses, to replace some
    /// (with a [`RecordedMotion`](super::RecordedMotion), say) before
    /// [`with_motions`](Self::with_motions).
    #[must_use]
    pub fn scenario_motions(scenario: &Scenario, seed: u64) -> Vec<Box<dyn TargetMotion>> {
        scenario
            .targets
            .iter()
            .enumerate()
            .map(|(index, spec)| {
                let recorded = (spec.behaviour == Behaviour::Recorded)
                    .then(|| scenario.recorded.track(&spec.name))
                    .flatten()
                    .and_then(|states| RecordedMotion::new(states.to_vec()).ok());
                match recorded {
                    Some(motion) => Box::new(motion) as Box<dyn TargetMotion>,
                    None => Box::new(BehaviourTarget::new(spec, index, seed)),
                }
            })
            .collect()
    }

    /// As [`with_config`](Self::with_config), with every target moved by
    /// `motions` (one per scenario target, in its order, each at time 0)
    /// instead of its behaviour; the targets keep the scenario's names.
    /// Ownship's planner keeps the scenario's traffic separation scheme
    /// ([`scenario_constraint`]).
    ///
    /// ```
    /// use vorrt_scenarios::{ClosedLoop, RecordedMotion, Scenario, TimedState};
    /// let scenario = vorrt_scenarios::fixtures::find("paper/head_on").unwrap().load().unwrap();
    /// let config = scenario.planner_config().unwrap();
    /// // The head-on target lies stopped where it starts.
    /// let mut still = scenario.targets[0].state();
    /// still.speed_mps = 0.0;
    /// let mut motions = ClosedLoop::scenario_motions(&scenario, 1);
    /// motions[0] = Box::new(RecordedMotion::new(vec![TimedState { time_s: 0.0, vessel: still }]).unwrap());
    /// let mut run = ClosedLoop::with_motions(&scenario, &config, 1, motions).unwrap();
    /// run.step();
    /// assert_eq!(run.state().targets[0].position_m, still.position_m);
    /// ```
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`]: field `planner` when `config` is invalid,
    /// field `targets` when there is not one motion per target.
    pub fn with_motions(
        scenario: &Scenario,
        config: &PlannerConfig,
        seed: u64,
        motions: Vec<Box<dyn TargetMotion>>,
    ) -> Result<Self, ScenarioError> {
        ClosedLoop::with_constraint(
            scenario,
            config,
            seed,
            motions,
            scenario_constraint(scenario),
        )
    }
}

impl<C: Constraint + Clone> ClosedLoop<C> {
    /// As [`with_motions`](ClosedLoop::with_motions), with ownship's
    /// planner keeping `constraint` (a no-go area, a lane) at every
    /// level of the graded fallback, in its check of the plan in force and
    /// in the evasive manoeuvre, beside the scenario's own [`Chart`] (its
    /// land and no-go areas), which every run keeps.
    ///
    /// # Errors
    /// As [`with_motions`](ClosedLoop::with_motions); field `land` when the
    /// scenario's areas were not validated.
    pub fn with_constraint(
        scenario: &Scenario,
        config: &PlannerConfig,
        seed: u64,
        motions: Vec<Box<dyn TargetMotion>>,
        constraint: C,
    ) -> Result<Self, ScenarioError> {
        let invalid = |field: &str, problem: String| ScenarioError::Invalid {
            file: scenario.source.clone(),
            field: field.into(),
            problem,
        };
        let chart = Chart::from_scenario(scenario)?;
        let planners = graded_planners(config, &(chart, constraint))
            .map_err(|error| invalid("planner", error.to_string()))?;
        if motions.len() != scenario.targets.len() {
            return Err(invalid(
                "targets",
                format!(
                    "has {} targets, but {} motions were given",
                    scenario.targets.len(),
                    motions.len()
                ),
            ));
        }
        let own = scenario.ownship_state();
        let max_turn_rate_rad_s = config
            .turning
            .max_turn_rate_rad_s(own.length_m, own.speed_mps);
        let setup = Setup {
            planners,
            config: *config,
            seed,
            time_step_s: scenario.simulation.time_step_s,
            max_duration_s: scenario.max_duration_s(),
            replan_deviation_m: scenario.simulation.replan_deviation_m,
            goal_m: scenario.ownship_goal_m(),
            service_speed_mps: own.speed_mps,
            speed_change_mps2: config.speed_change_rate_mps2(own.length_m, own.speed_mps),
            // The one place a configuration becomes the model ownship sails.
            model: config.turning.ownship_model(own.length_m, own.speed_mps),
        };
        let record = SimulationRecord {
            scenario: scenario.name.clone(),
            seed,
            time_step_s: setup.time_step_s,
            times_s: Vec::new(),
            ownship: Vec::new(),
            target_names: scenario
                .targets
                .iter()
                .map(|spec| spec.name.clone())
                .collect(),
            targets: vec![Vec::new(); motions.len()],
            plans: Vec::new(),
            plans_kept: Vec::new(),
            config: *config,
            max_turn_rate_rad_s,
            // Ownship's track is exact; each target's as its motion says.
            observations: std::iter::once(TrackObservation::exact())
                .chain(motions.iter().map(|motion| motion.observation()))
                .collect(),
            reached_goal: false,
            arrival_time_s: None,
        };
        let mut run = Self {
            setup,
            step: 0,
            time_s: 0.0,
            own,
            target_states: motions.iter().map(|motion| motion.vessel()).collect(),
            encounters: EncounterState::new(vec![None; motions.len()], vec![0.0; motions.len()]),
            targets: motions,
            steady_course_rad: own.course_rad,
            own_courses_rad: Vec::new(),
            active: None,
            pending: Some(PlanTrigger::Initial),
            late_asked_s: f64::NEG_INFINITY,
            retry: RetryTimer::idle(),
            status: RunStatus::Running,
            record,
        };
        run.observe();
        Ok(run)
    }

    /// Advances the run by exactly one time step: ownship decides whether to
    /// plan (at the present time, from the present states), sails one step
    /// of the plan in force while every target moves, and the new moment is
    /// observed and recorded. `None`, and nothing done, once the run has
    /// finished.
    ///
    /// ```
    /// use vorrt_scenarios::{ClosedLoop, Decision, PlanTrigger, RunStatus, Scenario};
    /// let scenario = vorrt_scenarios::fixtures::find("paper/head_on").unwrap().load().unwrap();
    /// let mut run = ClosedLoop::new(&scenario, 1).unwrap();
    /// assert_eq!(run.state().time_s, 0.0);
    /// assert!(run.state().plan.is_none());
    /// let first = run.step().unwrap();
    /// assert_eq!(first.decision, Decision::Planned(PlanTrigger::Initial));
    /// assert_eq!(first.time_s, scenario.simulation.time_step_s);
    /// assert!(run.state().plan.is_some());
    /// while let Some(outcome) = run.step() {
    ///     // The present moment, between steps.
    ///     assert_eq!(run.state().time_s, outcome.time_s);
    /// }
    /// assert_eq!(run.state().status, RunStatus::ReachedGoal);
    /// assert!(run.step().is_none());
    /// assert!(run.finish().reached_goal);
    /// ```
    pub fn step(&mut self) -> Option<StepOutcome> {
        if self.status.is_finished() {
            return None;
        }
        let from_s = self.time_s;
        let decision = self.decide();
        self.sail();
        self.observe();
        Some(StepOutcome {
            from_s,
            time_s: self.time_s,
            decision,
            status: self.status,
        })
    }

    /// The run at its present moment.
    #[must_use]
    pub fn state(&self) -> LoopState<'_> {
        let active = self.active.as_ref();
        LoopState {
            time_s: self.time_s,
            step: self.step,
            ownship: self.own,
            target_names: &self.record.target_names,
            targets: &self.target_states,
            encounters: &self.encounters.latches,
            alterations_rad: &self.encounters.alterations,
            plan: active.map(|active| &active.plan),
            evasive: active.is_some_and(|active| active.evasive),
            status: self.status,
        }
    }

    /// Where the run stands.
    #[must_use]
    pub fn status(&self) -> RunStatus {
        self.status
    }

    /// Whether the run has finished (goal reached or time out): further
    /// steps do nothing.
    #[must_use]
    pub fn is_finished(&self) -> bool {
        self.status.is_finished()
    }

    /// The record so far: every moment up to the present, every planner
    /// call and every plan kept.
    #[must_use]
    pub fn record(&self) -> &SimulationRecord {
        &self.record
    }

    /// Ends the run here and gives its record (a run stopped before it
    /// finished has not reached its goal).
    #[must_use]
    pub fn finish(self) -> SimulationRecord {
        self.record
    }

    /// Steps the run until it finishes, and gives its record.
    #[must_use]
    pub fn run(mut self) -> SimulationRecord {
        while self.step().is_some() {}
        self.finish()
    }

    /// Whether ownship's course changed over the last step faster than a
    /// course held wanders (`rules::STEADY_TURN_RATE_RAD_S`, the rate
    /// `steady_course_rad` tells a turn by): it is turning now.
    fn turning_now(&self) -> bool {
        let (times_s, courses_rad) = (&self.record.times_s, &self.own_courses_rad);
        match (
            times_s.len().checked_sub(2),
            courses_rad.len().checked_sub(2),
        ) {
            (Some(t), Some(c)) => {
                let step_s = times_s[t + 1] - times_s[t];
                let turned = vorrt_geometry::angle::signed_turn(courses_rad[c], courses_rad[c + 1]);
                turned.abs() > vorrt_colregs::rules::STEADY_TURN_RATE_RAD_S * step_s + 1e-9
            }
            _ => false,
        }
    }

    /// Observes the present moment: the encounters move on from the true
    /// states, every vessel is recorded, and the run ends if ownship has
    /// arrived or the time is up.
    fn observe(&mut self) {
        let own = self.own;
        self.own_courses_rad.push(own.course_rad);
        self.record.times_s.push(self.time_s);
        self.steady_course_rad = steady_course_rad(
            &self.record.times_s,
            &self.own_courses_rad,
            STEADY_COURSE_WINDOW_S,
        )
        .unwrap_or(own.course_rad);
        self.encounters.advance_to(
            &own,
            self.steady_course_rad,
            &self.target_states,
            self.time_s,
            &self.setup.config.rules,
        );
        self.record.ownship.push(own);
        for (track, state) in self.record.targets.iter_mut().zip(&self.target_states) {
            track.push(*state);
        }
        if own.position_m.distance(self.setup.goal_m) <= ARRIVAL_TOLERANCE_M {
            self.record.reached_goal = true;
            self.record.arrival_time_s = Some(self.time_s);
            self.status = RunStatus::ReachedGoal;
        } else if self.time_s >= self.setup.max_duration_s {
            self.status = RunStatus::OutOfTime;
        }
    }

    /// Whether to ask for a plan that arrives sooner: all past and clear
    /// (decision 52), or the plan in force late for the run's end (63).
    fn sooner_plan_due(&mut self) -> Option<PlanTrigger> {
        let latches = &self.encounters.latches;
        if let Some(active) = self.active.as_mut() {
            active.encounters_seen |= latches.iter().any(Option::is_some);
        }
        if self.pending.is_some() {
            return None;
        }
        if past_and_clear_due(
            self.active.as_ref(),
            latches,
            &self.retry,
            &self.own,
            self.setup.goal_m,
            self.setup.service_speed_mps,
        ) {
            return Some(PlanTrigger::PastAndClear);
        }
        let end_s = self.setup.max_duration_s;
        let late = (self.time_s, self.late_asked_s);
        late_arrival_due(self.active.as_ref(), &self.retry, late, end_s).then(|| {
            self.late_asked_s = self.time_s;
            PlanTrigger::LateArrival
        })
    }

    /// Decides at the present moment whether to plan, and does: a trigger
    /// first asks whether the rest of the plan in force still holds.
    fn decide(&mut self) -> Decision {
        let turning_at_start = self.turning_now();
        let setup = &mut self.setup;
        let (time_s, latches) = (self.time_s, &self.encounters.latches);
        // How ownship predicts the targets now (what it would plan with).
        let predicted: Vec<TargetState> = self
            .targets
            .iter()
            .zip(latches)
            .map(|(target, latch)| {
                let encounter = latch.map(|latch| latch.encounter);
                target.announced(&self.own, encounter, &setup.config.rules)
            })
            .collect();
        if self.pending.is_none() {
            self.pending = replan_trigger(
                self.active.as_ref(),
                &self.target_states,
                &predicted,
                latches,
                time_s,
                setup.replan_deviation_m,
            );
        }
        if self.pending.is_none() && self.retry.due(time_s, latches) {
            self.pending = Some(PlanTrigger::Retry);
        }
        let sooner = self.sooner_plan_due();
        self.pending = self.pending.or(sooner);
        let (setup, latches) = (&mut self.setup, &self.encounters.latches);
        let Some(why) = self.pending.take() else {
            return Decision::SailedOn;
        };
        let problem = PlanningProblem {
            start_time_s: time_s,
            ownship: self.own,
            service_speed_mps: Some(setup.service_speed_mps),
            goal_m: setup.goal_m,
            targets: predicted.clone(),
            encounters: latches.clone(),
            alterations: self.encounters.alterations.clone(),
            steady_course_rad: Some(self.steady_course_rad),
            turning_at_start,
        };
        // The plan in force is kept while the planner's own validity check
        // still accepts the rest of it, as the targets are now predicted and
        // with the encounters now in force: a new plan would only be a
        // different random branch, and changing course without need is what
        // rule 8(b) warns against.
        let call = PlanCall {
            why,
            seed: call_seed(setup.seed, self.record.plans.len()),
            clearance_m: setup.config.clearance_m,
            speed_change_mps2: setup.speed_change_mps2,
        };
        if matches!(why, PlanTrigger::PastAndClear | PlanTrigger::LateArrival) {
            return self.ask_for_a_sooner_plan(&problem, &call);
        }
        let retried = match why {
            PlanTrigger::Retry => retry_in_force(
                &mut setup.planners,
                &problem,
                &call,
                (&mut self.active, &mut self.record.plans),
                &mut self.retry,
            ),
            _ => None,
        };
        let search_time_s = match retried {
            Some(Asked::Planned) => return Decision::Planned(why),
            Some(Asked::Kept { search_time_s }) => Some(search_time_s),
            None => None,
        };
        let still_valid = search_time_s.is_some()
            || why != PlanTrigger::Retry
                && self
                    .active
                    .as_ref()
                    .is_some_and(|active| in_force_holds(&setup.planners, &problem, active));
        if still_valid && let Some(active) = self.active.as_mut() {
            active.kept(predicted, time_s, latches);
            self.record.plans_kept.push(PlanCheck {
                time_s,
                trigger: why,
                search_time_s: search_time_s.unwrap_or(0.0),
            });
            return Decision::KeptPlan(why);
        }
        plan_now(
            &mut setup.planners,
            &problem,
            &setup.model,
            &call,
            &mut self.active,
            &mut self.record.plans,
            &mut self.retry,
        );
        Decision::Planned(why)
    }

    /// Asked once per release of every encounter
    /// ([`PlanTrigger::PastAndClear`]): the plan in force stays unless a
    /// sooner one keeps every rule (decision 52). Nothing else about the
    /// plan in force changes: its predictions stay those it was checked
    /// against.
    fn ask_for_a_sooner_plan(&mut self, problem: &PlanningProblem, call: &PlanCall) -> Decision {
        let asked = plan_if_sooner(
            &mut self.setup.planners,
            problem,
            call,
            &mut self.active,
            &mut self.record.plans,
        );
        let Asked::Kept { search_time_s } = asked else {
            return Decision::Planned(call.why);
        };
        // Past and clear is asked once per release of every encounter; a
        // late arrival again after `LATE_ARRIVAL_ASK_S`.
        if call.why == PlanTrigger::PastAndClear
            && let Some(active) = self.active.as_mut()
        {
            active.encounters_seen = false;
        }
        self.record.plans_kept.push(PlanCheck {
            time_s: problem.start_time_s,
            trigger: call.why,
            search_time_s,
        });
        Decision::KeptPlan(call.why)
    }

    /// Sails one time step: ownship along the plan in force (straight on
    /// without one), every target by its motion, seeing ownship where it
    /// was at the step's start.
    fn sail(&mut self) {
        self.step += 1;
        #[expect(clippy::cast_precision_loss, reason = "a step count, far below 2^52")]
        let next_time_s = self.step as f64 * self.setup.time_step_s;
        let own_now = self.own;
        self.own = match &self.active {
            Some(active) => follow(&active.plan, &own_now, next_time_s),
            None => own_now.advanced(next_time_s - self.time_s),
        };
        for (target, state) in self.targets.iter_mut().zip(&mut self.target_states) {
            target.advance(self.time_s, next_time_s, &own_now, &self.setup.config.rules);
            *state = target.vessel();
        }
        self.time_s = next_time_s;
    }
}
