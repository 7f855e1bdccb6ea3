//! A sooner plan (decisions 52 and 63): asked for once the vessels are
//! past and clear, or while the plan in force would arrive after the run
//! ends, and put in force only where it arrives clearly sooner.

use super::{
    ActivePlan, Attempts, Compliance, Constraint, EncounterLatch, Instant, LATE_ARRIVAL_ASK_S,
    PAST_AND_CLEAR_GAIN_S, Plan, PlanCall, PlanEvent, PlanStatistics, Planner, PlanningProblem,
    RetryTimer, SearchEffort, VesselState, put_in_force,
};

/// Whether the vessels the plan in force was made (or held) for are past and
/// clear, while it still holds ownship off the straight line to the goal
/// (`goal_m`, at `speed_mps`) by more than [`PAST_AND_CLEAR_GAIN_S`]: an
/// encounter was in force since the plan was made, none is now (each was
/// released by `colregs::has_passed`, the latch's one judgement), and the
/// plan keeps every rule (no retry pending). Rule 8(d) asks for the action
/// to be held until the other vessel is finally past and clear; a hold
/// chosen for how the vessels were predicted (COLREGs-obeying vessels act,
/// and the prediction of decision 18 may hold them on course longer) can
/// outlast that by an hour.
pub(in crate::simulation) fn past_and_clear_due(
    active: Option<&ActivePlan>,
    latches: &[Option<EncounterLatch>],
    retry: &RetryTimer,
    own: &VesselState,
    goal_m: glam::DVec2,
    speed_mps: f64,
) -> bool {
    let Some(active) = active.filter(|active| !active.evasive && active.encounters_seen) else {
        return false;
    };
    if !retry.is_idle() || latches.iter().any(Option::is_some) || speed_mps <= 0.0 {
        return false;
    }
    let arrival_s = arrival_s(&active.plan).unwrap_or(0.0);
    let straight_s = own.position_m.distance(goal_m) / speed_mps;
    arrival_s - straight_s > PAST_AND_CLEAR_GAIN_S
}

/// Whether ownship should ask for a plan that arrives sooner because the
/// plan in force (not the evasive manoeuvre, no retry pending) reaches the
/// goal only after `end_s`, the end of the run: sailed out, it would not
/// arrive. Asked at most every [`LATE_ARRIVAL_ASK_S`] after `asked_s`, the
/// last ask. Long alterations held at reduced speed among vessels whose
/// encounters stay in force (so [`past_and_clear_due`] never asks) ran
/// out of time in 3 of 1000 open-sea runs with 16 COLREGs-obeying targets
/// (decision 63).
pub(in crate::simulation) fn late_arrival_due(
    active: Option<&ActivePlan>,
    retry: &RetryTimer,
    (now_s, asked_s): (f64, f64),
    end_s: f64,
) -> bool {
    let Some(active) = active.filter(|active| !active.evasive) else {
        return false;
    };
    retry.is_idle()
        && now_s >= asked_s + LATE_ARRIVAL_ASK_S
        && arrival_s(&active.plan).is_some_and(|arrival_s| arrival_s > end_s)
}

/// When `plan` reaches the goal (its last waypoint), seconds of simulated
/// time; `None` for a plan with no waypoint.
pub(in crate::simulation) fn arrival_s(plan: &Plan) -> Option<f64> {
    plan.waypoints.last().map(|end| end.time_s)
}

/// What came of a search for a better plan than the one in force
/// ([`plan_if_sooner`], [`retry_in_force`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::simulation) enum Asked {
    /// A plan was found and put in force (and recorded).
    Planned,
    /// The plan in force is kept (the caller records the check); the
    /// search, if one ran, took `search_time_s` of wall-clock time.
    Kept {
        /// Seconds spent searching (0 where no search ran).
        search_time_s: f64,
    },
}

/// Asked once the vessels are past and clear
/// ([`PlanTrigger::PastAndClear`]): searches at full compliance (the first
/// phase only, as a retry) and puts the plan found in force only where it
/// reaches the goal at least [`PAST_AND_CLEAR_GAIN_S`] sooner than the plan
/// in force. Otherwise the plan in force is kept (the caller records the
/// check) and nothing is recorded here.
pub(in crate::simulation) fn plan_if_sooner<C: Constraint>(
    planners: &mut [Planner<C>],
    problem: &PlanningProblem,
    call: &PlanCall,
    active: &mut Option<ActivePlan>,
    plans: &mut Vec<PlanEvent>,
) -> Asked {
    let kept = |started: Option<Instant>| Asked::Kept {
        search_time_s: started.map_or(0.0, |started| started.elapsed().as_secs_f64()),
    };
    let Some(in_force) = active.as_ref() else {
        return kept(None);
    };
    let arrives_s = |plan: &Plan| arrival_s(plan).unwrap_or(f64::INFINITY);
    let in_force_s = arrives_s(&in_force.plan);
    let Some(planner) = planners.first_mut() else {
        return kept(None);
    };
    if planner.config().compliance != Compliance::Full {
        return kept(None);
    }
    let started = Instant::now();
    // A stricter level's search (decision 66): the tree only where the
    // user constraint refused the manoeuvres from the root.
    let Ok(plan) = planner.plan_with(problem, call.seed, SearchEffort::FirstPhaseWhereConstrained)
    else {
        return kept(Some(started));
    };
    if arrives_s(&plan) > in_force_s - PAST_AND_CLEAR_GAIN_S {
        return kept(Some(started));
    }
    let attempts = Attempts {
        first_error: None,
        spent: PlanStatistics::default(),
        samples_drawn: plan.statistics.samples,
    };
    put_in_force(
        plan,
        Compliance::Full,
        &attempts,
        problem,
        call,
        active,
        plans,
    );
    Asked::Planned
}
