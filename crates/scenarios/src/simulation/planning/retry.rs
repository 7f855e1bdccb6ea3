//! A retry while a fallback plan is sailed (decision 64): for a plan that
//! keeps more rules, not for another draw at the same level.

use super::{
    ActivePlan, Asked, Compliance, Constraint, PAST_AND_CLEAR_GAIN_S, PlanCall, PlanEvent, Planner,
    PlanningProblem, RetryTimer, arrival_s, level_of, put_in_force, remaining_legs, search,
};
use std::time::Instant;

/// A retry ([`PlanTrigger::Retry`](super::PlanTrigger::Retry)) while the
/// plan in force keeps a weaker level than full compliance and still passes
/// that level's validity check: the levels stricter than the plan in force
/// are searched as a retry searches them, and the level in force too (the
/// vessels have moved on); a plan that keeps more rules is put in force,
/// one at the same level only where it reaches the goal at least
/// [`PAST_AND_CLEAR_GAIN_S`] sooner. Otherwise the plan in force is kept:
/// another draw at the same level is no reason to change a course an
/// observer has seen steady (rule 8(b)), and in dense traffic a retry falls
/// due at almost every new encounter.
///
/// Returns `None` where this does not apply (no such plan in force, or it
/// no longer passes its level's check: the caller plans afresh), else what
/// came of it; where the plan in force is kept the caller records the
/// check, and the next retry is timed from now.
pub(in crate::simulation) fn retry_in_force<C: Constraint>(
    planners: &mut [Planner<C>],
    problem: &PlanningProblem,
    call: &PlanCall,
    (active, plans): (&mut Option<ActivePlan>, &mut Vec<PlanEvent>),
    retry: &mut RetryTimer,
) -> Option<Asked> {
    let in_force = active
        .as_ref()
        .filter(|active| !active.evasive && active.compliance != Compliance::Full)?;
    let level = level_of(planners, in_force.compliance)?;
    if !in_force_holds(planners, problem, in_force) {
        return None;
    }
    let in_force_s = arrival_s(&in_force.plan).unwrap_or(f64::INFINITY);
    let started = Instant::now();
    let (found, attempts) = search(&mut planners[..=level], problem, call);
    match found {
        Some((plan, compliance))
            if compliance != in_force.compliance
                || arrival_s(&plan)
                    .is_some_and(|arrives_s| arrives_s <= in_force_s - PAST_AND_CLEAR_GAIN_S) =>
        {
            retry.put_in_force(compliance, problem.start_time_s, &problem.encounters);
            put_in_force(plan, compliance, &attempts, problem, call, active, plans);
            Some(Asked::Planned)
        }
        _ => {
            retry.kept(problem.start_time_s, &problem.encounters);
            Some(Asked::Kept {
                search_time_s: started.elapsed().as_secs_f64(),
            })
        }
    }
}

/// Whether the rest of the plan in force (at `problem`'s start) still
/// passes the validity check of the level it was found at (decision 64): a
/// fallback plan is judged by the duties its level keeps, as when it was
/// found; whether a stricter plan exists is the retry's question
/// ([`retry_in_force`]). The evasive manoeuvre is judged at the strictest
/// level.
pub(in crate::simulation) fn in_force_holds<C: Constraint>(
    planners: &[Planner<C>],
    problem: &PlanningProblem,
    active: &ActivePlan,
) -> bool {
    let level = if active.evasive {
        0
    } else {
        level_of(planners, active.compliance).unwrap_or(0)
    };
    let legs = remaining_legs(&active.plan, problem.start_time_s);
    planners
        .get(level)
        .is_some_and(|planner| planner.check_legs(problem, &legs).is_ok())
}
