//! Decision 64: a retry while a fallback plan is sailed is for a plan that
//! keeps more rules. Open-sea runs 111, 636, 666 and 948 (2 constant
//! targets, seed 11) each sailed a `safety_only` plan for some minutes
//! (run 666 no longer does: since decision 72 it holds its alteration
//! instead of turning 36° to port, astern of TS2, onto a fallback);
//! every retry, 20 s apart, put a fresh `safety_only` plan in force, the
//! same manoeuvre to within a few seconds (run 111: 35 plans, 11 % path
//! overhead). A fallback plan is now judged by its own level's check, and a
//! retry replaces it only with a stricter plan or a clearly sooner one.
//! Since decision 74 runs 111 and 948 keep every rule from their first plan.

use vorrt_planner::Compliance;
use vorrt_scenarios::simulation::PAST_AND_CLEAR_GAIN_S;
use vorrt_scenarios::{
    OpenSeaSpec, PlanEvent, PlanTrigger, SimulationRecord, TargetBehaviour, evaluate, simulate,
};

/// How many duties a level keeps: a retry's plan must keep more, or arrive
/// sooner.
fn duties(compliance: Compliance) -> u8 {
    match compliance {
        Compliance::Full => 2,
        Compliance::Directions => 1,
        Compliance::SafetyOnly => 0,
    }
}

/// When a plan reaches the goal, seconds.
fn arrival_s(event: &PlanEvent) -> f64 {
    event
        .waypoints
        .last()
        .map_or(f64::INFINITY, |end| end.time_s)
}

/// Every retry that put a plan in force found one that keeps more rules
/// than the plan it replaced, or one at the same level that arrives at
/// least [`PAST_AND_CLEAR_GAIN_S`] sooner, unless the plan in force had
/// stopped holding (then the retry plans afresh, as any trigger does: not
/// told apart here, so only runs where it does not happen are asked).
/// Returns the retries kept as checks of the plan in force.
fn retries_only_for_better_plans(record: &SimulationRecord, run: u64) -> usize {
    let plans = &record.plans;
    for pair in plans.windows(2) {
        let (in_force, retry) = (&pair[0], &pair[1]);
        if retry.trigger != PlanTrigger::Retry || !in_force.succeeded || !retry.succeeded {
            continue;
        }
        assert!(
            duties(retry.compliance) > duties(in_force.compliance)
                || arrival_s(retry) <= arrival_s(in_force) - PAST_AND_CLEAR_GAIN_S,
            "run {run}: the retry at {} s replaced a {:?} plan with a {:?} one arriving at {} s against {} s",
            retry.time_s,
            in_force.compliance,
            retry.compliance,
            arrival_s(retry),
            arrival_s(in_force)
        );
    }
    let kept: Vec<_> = record
        .plans_kept
        .iter()
        .filter(|check| check.trigger == PlanTrigger::Retry)
        .collect();
    // A kept retry searched (the levels up to the plan in force's), and
    // its search time counts in the run's planning time.
    assert!(
        kept.iter().all(|check| check.search_time_s > 0.0),
        "run {run}"
    );
    let searched_s: f64 = kept.iter().map(|check| check.search_time_s).sum();
    assert!(record.planning_time_s() >= searched_s, "run {run}");
    kept.len()
}

#[test]
fn a_retry_keeps_the_fallback_plan_in_force_unless_a_better_one_is_found() {
    // Runs 111 and 948 no longer sail a fallback plan: since decision 74
    // the first plan holds its alteration for the vessel met beyond MTD,
    // and keeps every rule (`first_plans_keep_every_rule_since_decision_74`).
    let runs = [(636, 283_519_718_206_295_765, 3)];
    for (index, seed, most_plans) in runs {
        let spec = OpenSeaSpec::with_targets(2).with_behaviour(TargetBehaviour::Constant);
        let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, index).expect("generated");
        let record = simulate(&scenario, seed).expect("valid settings");
        let kept = retries_only_for_better_plans(&record, index);
        assert!(
            kept >= 1,
            "run {index}: a retry found no better plan and kept the one in force"
        );
        assert!(
            record.plans.len() <= most_plans,
            "run {index}: {} plans",
            record.plans.len()
        );
        assert!(
            record
                .plans
                .iter()
                .any(|event| event.compliance != Compliance::Full),
            "run {index}: a fallback plan was sailed"
        );
        let evaluation = evaluate(&scenario, &record);
        assert!(
            evaluation.reached_goal && evaluation.clearance_kept && !evaluation.collision,
            "run {index}"
        );
    }
}

/// Runs 111 and 948 sailed a `safety_only` plan for minutes and retried
/// (decision 64); since decision 74 their first plan keeps every rule and
/// is the only one.
#[test]
fn first_plans_keep_every_rule_since_decision_74() {
    for (index, seed) in [
        (111, 4_654_229_725_192_512_665),
        (948, 13_243_016_833_840_574_873),
    ] {
        let spec = OpenSeaSpec::with_targets(2).with_behaviour(TargetBehaviour::Constant);
        let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, index).expect("generated");
        let record = simulate(&scenario, seed).expect("valid settings");
        assert_eq!(record.plans.len(), 1, "run {index}");
        assert_eq!(record.plans[0].compliance, Compliance::Full, "run {index}");
        let evaluation = evaluate(&scenario, &record);
        assert!(
            evaluation.reached_goal && evaluation.clearance_kept && evaluation.compliant,
            "run {index}: {:?}",
            evaluation.targets
        );
    }
}
