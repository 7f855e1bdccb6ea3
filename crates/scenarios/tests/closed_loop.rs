//! Closed-loop runs of bundled fixtures: ownship reaches its goal, keeps the
//! clearance and obeys the rules; runs are reproducible; the evaluation agrees
//! with the recorded trajectories.

use std::path::PathBuf;
use vorrt_colregs::{Encounter, Role};
use vorrt_scenarios::{Evaluation, PlanTrigger, Scenario, evaluate, simulate};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "fixtures", relative]
        .iter()
        .collect();
    Scenario::load(&path).expect("fixture loads")
}

#[test]
fn paper_two_vessel_scenarios_reach_the_goal_safely_and_compliantly() {
    for (name, encounter) in [
        ("paper/crossing.ron", Encounter::CrossingGiveWay),
        ("paper/head_on.ron", Encounter::HeadOn),
        ("paper/overtaking.ron", Encounter::Overtaking),
    ] {
        let scenario = fixture(name);
        let record = simulate(&scenario, 1).expect("valid settings");
        let evaluation = evaluate(&scenario, &record);
        assert!(evaluation.reached_goal, "{name}: goal not reached");
        assert!(
            evaluation.clearance_kept,
            "{name}: min {} m",
            evaluation.min_distance_m
        );
        assert!(!evaluation.collision, "{name}");
        assert_eq!(evaluation.targets[0].encounter, encounter, "{name}");
        assert_eq!(evaluation.targets[0].role, Role::GiveWay, "{name}");
        // Judged as observed, the overtaking run eases its alteration back
        // before it is past the overtaken vessel (issue 11, item 3).
        if encounter != Encounter::Overtaking {
            assert!(
                evaluation.compliant,
                "{name}: {:?}",
                evaluation.targets[0].violations
            );
        }
        assert!(evaluation.path_overhead_pct >= 0.0 && evaluation.path_overhead_pct < 50.0);
    }
}

#[test]
fn success_needs_the_goal_and_safety_and_safe_and_compliant_needs_no_goal() {
    let scenario = fixture("paper/crossing.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    let run = evaluate(&scenario, &record);
    assert!(run.success() && run.safe_and_compliant(), "{}", run.table());
    let short = Evaluation {
        reached_goal: false,
        ..run.clone()
    };
    assert!(!short.success() && short.safe_and_compliant());
    let touched = Evaluation {
        collision: true,
        ..run.clone()
    };
    assert!(!touched.success() && !touched.safe_and_compliant());
    let close = Evaluation {
        clearance_kept: false,
        ..run.clone()
    };
    assert!(!close.success() && !close.safe_and_compliant());
    let violated = Evaluation {
        compliant: false,
        ..run
    };
    assert!(violated.success() && !violated.safe_and_compliant());
}

#[test]
fn same_seed_gives_the_same_run() {
    let scenario = fixture("paper/crossing.ron");
    let first = simulate(&scenario, 7).expect("valid settings");
    let second = simulate(&scenario, 7).expect("valid settings");
    assert_eq!(first.ownship, second.ownship);
    assert_eq!(first.targets, second.targets);
    assert_eq!(first.plans.len(), second.plans.len());
    for (a, b) in first.plans.iter().zip(&second.plans) {
        assert_eq!(a.waypoints, b.waypoints);
        assert_eq!(a.seed, b.seed);
    }
}

#[test]
fn record_is_complete_and_evaluation_matches_it() {
    let scenario = fixture("paper/head_on.ron");
    let record = simulate(&scenario, 3).expect("valid settings");
    let steps = record.times_s.len();
    assert_eq!(record.ownship.len(), steps);
    assert!(record.targets.iter().all(|track| track.len() == steps));
    assert_eq!(record.plans[0].trigger, PlanTrigger::Initial);
    // Fixed time step.
    for pair in record.times_s.windows(2) {
        assert!((pair[1] - pair[0] - record.time_step_s).abs() < 1e-9);
    }
    // Ownship holds its speed and ends on its goal.
    let last = record.ownship.last().expect("steps");
    assert!(last.position_m.distance(scenario.ownship_goal_m()) < 0.01);
    let evaluation = evaluate(&scenario, &record);
    let sampled_min = record
        .ownship
        .iter()
        .zip(&record.targets[0])
        .map(|(own, target)| own.position_m.distance(target.position_m))
        .fold(f64::INFINITY, f64::min);
    // The evaluation interpolates between samples, so it may only be lower.
    assert!(evaluation.targets[0].min_distance_m <= sampled_min + 1e-9);
    assert!(evaluation.targets[0].min_distance_m > sampled_min - 100.0);
    assert!((evaluation.path_length_m - record.path_length_m()).abs() < 1e-9);
    assert_eq!(evaluation.plans_made, record.plans_made());
}

#[test]
fn a_target_predicted_as_it_moves_needs_no_replan() {
    // ConstantToGoal targets are predicted exactly (the prediction is their own
    // motion model), so the first plan stays valid to the goal.
    let scenario = fixture("paper/crossing.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    assert_eq!(
        record.replans(),
        0,
        "{:?}",
        record.plans.iter().map(|p| p.trigger).collect::<Vec<_>>()
    );
    // So does a target holding course and speed, announced as such.
    let mut scenario = scenario;
    scenario.targets[0].behaviour = vorrt_scenarios::Behaviour::ConstantVelocity;
    let record = simulate(&scenario, 1).expect("valid settings");
    assert_eq!(record.replans(), 0);
    assert!(record.reached_goal);
    assert!(evaluate(&scenario, &record).clearance_kept);
}

#[test]
fn when_planning_fails_ownship_evades_instead_of_holding_course() {
    // A planner that cannot succeed (one node per phase, no restart) facing a
    // head-on target on a collision course: every plan fails, so ownship must
    // fall back on the evasive course, which keeps the clearance.
    let mut scenario = fixture("paper/head_on.ron");
    scenario.planner.nodes_per_phase = Some(1);
    scenario.planner.samples_per_phase = Some(1);
    scenario.planner.max_restarts = Some(0);
    // Budgets that do not grow with the route, and the tree alone (the
    // manoeuvre search that precedes it with rate-limited turns would find
    // this one).
    scenario.planner.nodes_per_route_step = Some(0.0);
    scenario.planner.instant_turns = Some(true);
    let record = simulate(&scenario, 1).expect("valid settings");
    assert!(record.plans.iter().all(|event| !event.succeeded));
    let evasions: Vec<f64> = record
        .plans
        .iter()
        .filter_map(|event| event.evasive_course_deg)
        .collect();
    assert!(!evasions.is_empty());
    let evaluation = evaluate(&scenario, &record);
    assert!(!evaluation.reached_goal);
    assert!(
        evaluation.clearance_kept,
        "min {} m",
        evaluation.min_distance_m
    );
    // Holding course would have met the target head-on.
    assert!(evaluation.min_distance_m >= scenario.planner_config().expect("valid").clearance_m);
}

#[test]
fn retries_search_the_first_phase_only_and_the_run_stays_safe() {
    // As above: every plan fails, at every level of the graded fallback, so
    // ownship evades and retries every RETRY_AFTER_S. A call other than a
    // retry draws both phases of both attempts at each of the three levels;
    // a retry draws the first phase only at the two levels that keep rules,
    // and both at the last, safety only. A level whose search would only
    // repeat the failed search of a stricter one is not asked.
    let mut scenario = fixture("paper/head_on.ron");
    scenario.planner.nodes_per_phase = Some(10);
    scenario.planner.samples_per_phase = Some(10);
    scenario.planner.max_restarts = Some(1);
    scenario.planner.nodes_per_route_step = Some(0.0);
    scenario.planner.instant_turns = Some(true);
    let record = simulate(&scenario, 1).expect("valid settings");
    let (levels, attempts, samples_per_phase) = (3, 2, 10);
    let retries: Vec<_> = record
        .plans
        .iter()
        .filter(|event| event.trigger == PlanTrigger::Retry)
        .collect();
    assert!(retries.len() >= 3, "{} retries", retries.len());
    for event in &record.plans {
        assert!(!event.succeeded);
        // The first level (full compliance) grows the first phase only on a
        // retry, both phases otherwise; its search is the call's statistics.
        let phases = if event.trigger == PlanTrigger::Retry {
            1
        } else {
            2
        };
        let first = attempts * phases * samples_per_phase;
        assert_eq!(
            event.statistics.samples, first,
            "{:?} at {} s",
            event.trigger, event.time_s
        );
        // The middle level searches as the first does, unless its search
        // would only repeat the first's (Planner::would_repeat); on a retry
        // the last, safety only, always grows both phases.
        let both = attempts * 2 * samples_per_phase;
        let allowed = if event.trigger == PlanTrigger::Retry {
            vec![first + first + both, first + both]
        } else {
            (1..=levels).map(|searched| searched * both).collect()
        };
        assert!(
            allowed.contains(&event.samples_drawn),
            "{:?} at {} s: {} samples, expected one of {allowed:?}",
            event.trigger,
            event.time_s,
            event.samples_drawn
        );
    }
    let evaluation = evaluate(&scenario, &record);
    assert!(
        evaluation.clearance_kept,
        "min {} m",
        evaluation.min_distance_m
    );
}

/// The run's first plan keeps every rule and was found with no tree (no
/// samples drawn: by the manoeuvre search from the root).
fn first_plan_keeps_every_rule_with_no_tree(record: &vorrt_scenarios::SimulationRecord) {
    let first = &record.plans[0];
    assert_eq!(first.compliance, vorrt_planner::Compliance::Full);
    assert_eq!(first.samples_drawn, 0, "found by the manoeuvre search");
}

#[test]
fn a_stand_on_vessel_holds_its_course_then_acts_from_the_first_plan() {
    // Imazu 04: one vessel crossing from the port side, which keeps its
    // course. The first plan keeps every rule, with no tree (no samples):
    // the course held until the give-way vessel is within the stand-on
    // action range, then one action (simplify::hold_then_alter). Before,
    // no such plan was found until a retry 40 s in, and the first 40 s
    // were sailed on a plan that broke rule 17(a)(i).
    let scenario = fixture("imazu/imazu_04.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    first_plan_keeps_every_rule_with_no_tree(&record);
    assert!(
        record
            .plans
            .iter()
            .all(|event| event.compliance == vorrt_planner::Compliance::Full),
        "a plan below full compliance was sailed"
    );
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal && evaluation.clearance_kept);
    assert_eq!(evaluation.targets[0].role, Role::StandOn);
    assert!(
        evaluation.compliant,
        "{:?}",
        evaluation.targets[0].violations
    );
    // Course and speed kept (within rule 17's tolerances) while the
    // give-way vessel is beyond the action range.
    let rules = scenario.planner_config().expect("valid").rules;
    let own_start = record.ownship[0];
    for (own, target) in record.ownship.iter().zip(&record.targets[0]) {
        if own.position_m.distance(target.position_m) <= rules.stand_on_action_range_m {
            break;
        }
        let turn = vorrt_geometry::angle::signed_turn(own_start.course_rad, own.course_rad);
        assert!(
            turn.abs() <= rules.stand_on_course_tolerance_rad,
            "{}°",
            turn.to_degrees()
        );
        assert!((own.speed_mps - own_start.speed_mps).abs() <= rules.stand_on_speed_tolerance_mps);
    }
}

#[test]
fn two_alterations_are_planned_where_one_cannot_be_sailed() {
    // Imazu 17: overtaking a vessel ahead, another crossing from starboard,
    // a third close on the port beam. No single alteration held, then the
    // goal, keeps every rule; an alteration to starboard held until the
    // others are past, then a second course, then the goal, does. Before,
    // 14 retries over 265 s sailed a plan below full compliance until a
    // tree found one. The plan found at t = 0 until decision 51 came back
    // 35° to port onto the course held before, which brought TS2, crossing
    // from port, onto a collision course (passed 380 m off, ownship
    // astern); it is refused now, and after three retries in 45 s two
    // alterations keep every rule, with no tree (TS2 passed 1.5 km off;
    // 744 m since the return comes back part of the way, decision 61).
    let scenario = fixture("imazu/imazu_17.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    let full = record
        .plans
        .iter()
        .find(|event| event.compliance == vorrt_planner::Compliance::Full)
        .expect("a plan that keeps every rule");
    assert!(full.time_s <= 60.0, "found at {} s", full.time_s);
    assert_eq!(full.samples_drawn, 0, "found by the manoeuvre search");
    // Three legs, or four where the return comes back part of the way
    // first (decision 61).
    assert!(
        (4..=5).contains(&full.waypoints.len()),
        "{} waypoints",
        full.waypoints.len()
    );
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal && evaluation.clearance_kept && !evaluation.collision);
    assert!(evaluation.compliant, "{:?}", evaluation.targets);
    // TS2, crossing from port, is never brought onto a collision course:
    // passed wide of the preferred clearance (2 d_th).
    assert!(
        evaluation.targets[1].min_distance_m > 600.0,
        "{} m",
        evaluation.targets[1].min_distance_m
    );
}

#[test]
fn a_stand_on_course_inside_a_velocity_obstacle_drifts_with_no_tree() {
    // Imazu 13 and 16: the present course of a stand-on vessel is inside a
    // velocity obstacle from the start. The hold drifts 5° or 10° to
    // starboard, within rule 17(a)(i)'s tolerance (decision 46), at t = 0.
    // Before, a tree of 32 000 samples failed, a safety-only plan was
    // sailed and a retry 20 s in found the drifted hold. Since decision 58
    // imazu 13's first plan is one 90° alteration to starboard at t = 0,
    // which rule 17(a)(ii) allows with TS2, crossing from port, 1.9 km off
    // (within 2 nm): still no tree and no retry, and compliant.
    for name in ["imazu/imazu_13.ron", "imazu/imazu_16.ron"] {
        let scenario = fixture(name);
        let record = simulate(&scenario, 1).expect("valid settings");
        first_plan_keeps_every_rule_with_no_tree(&record);
        let rules = scenario.planner_config().expect("valid").rules;
        let first_course_rad = record.plans[0].waypoints[1].course_rad;
        let drift =
            vorrt_geometry::angle::signed_turn(record.ownship[0].course_rad, first_course_rad);
        let within_tolerance = drift <= rules.stand_on_course_tolerance_rad;
        assert!(
            drift > 0.0 && (within_tolerance || name == "imazu/imazu_13.ron"),
            "{name}: {}°",
            drift.to_degrees()
        );
        assert!(
            !record
                .plans
                .iter()
                .any(|event| event.trigger == PlanTrigger::Retry),
            "{name}: no retry is needed"
        );
        let evaluation = evaluate(&scenario, &record);
        assert!(
            evaluation.reached_goal && evaluation.clearance_kept && evaluation.compliant,
            "{name}"
        );
    }
}

#[test]
fn a_closed_loop_run_records_its_tracks_as_exact_and_is_judged_as_if_estimated() {
    let scenario = fixture("paper/multi_vessel.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    // Ownship first, then every target: simulated, so exact.
    assert_eq!(record.observations.len(), 1 + scenario.targets.len());
    assert!(
        record
            .observations
            .iter()
            .all(|observation| *observation == vorrt_colregs::observed::TrackObservation::exact())
    );
    // The jitter estimated from exact positions is none but for rounding,
    // with the published window and thresholds: the same judgement.
    let mut estimated = record.clone();
    estimated.observations.clear();
    let (mut exact, estimated) = (
        evaluate(&scenario, &record),
        evaluate(&scenario, &estimated),
    );
    for (known, guessed) in exact.noise.iter().zip(&estimated.noise) {
        assert!(known.position_noise_m.to_bits() == 0 && guessed.position_noise_m < 1e-9);
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        assert!(same(known.window_s, guessed.window_s));
        assert!(same(known.turn_tolerance_rad, guessed.turn_tolerance_rad));
        assert!(same(
            known.action_detection_rad,
            guessed.action_detection_rad
        ));
    }
    exact.noise.clone_from(&estimated.noise);
    assert_eq!(exact, estimated);
}
