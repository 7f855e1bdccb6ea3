//! Vessels that act: generated open-sea encounters whose targets obey the
//! COLREGs themselves (turn 35° to starboard when they give way) or wander
//! (course and speed noise), run in closed loop; ownship never touches a
//! target's hull.
//!
//! 8 cases in a debug run; `VORRT_HEAVY_TESTS=1` runs 128. Targets that turn
//! suddenly and unannounced are left out of the property: no open-sea
//! campaign row with them collides now, but a sudden turn can leave no
//! room (`docs/evaluation.md`).

use proptest::prelude::*;
use vorrt_scenarios::{OpenSeaSpec, PlanTrigger, TargetBehaviour, evaluate, simulate};

fn cases() -> u32 {
    if std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1") {
        128
    } else {
        8
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn acting_targets_are_never_touched(
        seed in 0u64..1_000_000,
        targets in 1usize..=3,
        noisy in any::<bool>(),
    ) {
        let behaviour = if noisy {
            TargetBehaviour::Noisy { course_sigma_deg: 5.0, speed_sigma_kn: 0.5 }
        } else {
            TargetBehaviour::Colregs
        };
        let spec = OpenSeaSpec::with_targets(targets).with_behaviour(behaviour);
        let scenario = vorrt_scenarios::generator::open_sea(&spec, seed, 0)
            .map_err(|error| TestCaseError::fail(error.to_string()))?;
        let record = simulate(&scenario, seed).map_err(|error| TestCaseError::fail(error.to_string()))?;
        let evaluation = evaluate(&scenario, &record);
        prop_assert!(!evaluation.collision, "contact at {:.1} m", evaluation.min_distance_m);
        // The sailed track stays within ownship's rate of turn.
        let limit = record.max_turn_rate_rad_s.unwrap_or(f64::INFINITY).to_degrees();
        prop_assert!(evaluation.max_turn_rate_deg_s <= limit * (1.0 + 1e-9));
    }
}

/// Run 231 of the 1000-run campaign with 8 noisy targets (seed 11): after a
/// string of failed plans, the evasive manoeuvre used to swing from course
/// to course every retry while a noisy vessel overtook from the starboard
/// quarter, and the hulls touched. The manoeuvre in force is now held unless
/// another is clearly better (`vorrt_planner::evasive_leg_holding`).
#[test]
fn evasive_manoeuvre_is_held_while_overtaken_by_a_wandering_vessel() {
    let behaviour = TargetBehaviour::Noisy {
        course_sigma_deg: 5.0,
        speed_sigma_kn: 0.5,
    };
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(behaviour);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 231).expect("generated");
    let record = simulate(&scenario, 11_777_205_761_601_432_594).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        !evaluation.collision,
        "contact at {:.1} m",
        evaluation.min_distance_m
    );
}

/// Run 283 of the campaign with 8 COLREGs-obeying targets (seed 11): TS5
/// overtakes ownship on its avoiding course, 35° to starboard, and once
/// past steers back for its destination across ownship's bow. Predicted on
/// its avoiding course for ever, it came within 198 m of ownship (`d_th`
/// broken between the hulls); predicted to return to its route once past
/// (`holding_course_then_toward_goal`), it is kept clear of.
#[test]
fn an_overtaking_vessel_returning_to_its_route_is_foreseen() {
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 283).expect("generated");
    let record = simulate(&scenario, 14_356_413_915_108_752_105).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        evaluation.clearance_kept,
        "{:.1} m between reference points",
        evaluation.min_distance_m
    );
    assert!(evaluation.reached_goal);
}

/// Run 243 of the same campaign: TS4 overtakes while ownship gives way to
/// another vessel; its return to its route comes within the prediction's
/// horizon only minutes after the last plan, with no other reason to plan
/// again. The prediction changing asks whether the plan still holds
/// (`PlanTrigger::PredictionChanged`), and ownship keeps clear of the return.
#[test]
fn a_return_foreseen_after_the_last_plan_is_planned_for() {
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 243).expect("generated");
    let record = simulate(&scenario, 8_970_548_677_156_690_869).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        record
            .plans
            .iter()
            .any(|event| event.trigger == PlanTrigger::PredictionChanged { target: 3 }),
        "the plan was made again for TS4's return"
    );
    assert!(
        evaluation.clearance_kept,
        "{:.1} m between reference points",
        evaluation.min_distance_m
    );
}

/// Run 511 of the campaign with 16 COLREGs-obeying targets (seed 11), the one
/// run of its 1000 that ended in hull contact: a vessel from the quarter on
/// nearly the same course, overtaking, while most replans failed. With the
/// overtaking vessels' return to their routes foreseen, every plan succeeds
/// and `d_th` is kept.
#[test]
fn sixteen_acting_vessels_of_run_511_are_kept_clear_of() {
    let spec = OpenSeaSpec::with_targets(16).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 511).expect("generated");
    let record = simulate(&scenario, 1_326_621_031_047_636_798).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        !evaluation.collision,
        "contact at {:.1} m",
        evaluation.min_distance_m
    );
    assert!(
        evaluation.clearance_kept,
        "{:.1} m",
        evaluation.min_distance_m
    );
}

/// Run 64 of the campaign with 8 COLREGs-obeying targets (seed 11): a
/// vessel overtaking ownship turned 35° away, which released its latch, and
/// steered back at once, which latched it again, every 5 s for minutes;
/// ownship planned 58 times, 50 of them between 655 s and 955 s. Holding
/// its alteration while its return would bring risk back (decision 43),
/// the target no longer swings, and ownship plans a handful of times.
/// Since decision 51's stricter port-return check, full compliance is not
/// found from 1815 s to 2055 s and the plan of the safety-only level is
/// retried every 20 s (decision 17): 22 calls in all, 11 of them those
/// retries; the swing's 58 stay far off.
#[test]
fn a_vessel_that_gives_way_and_swings_back_does_not_make_ownship_replan_every_step() {
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 64).expect("generated");
    let record = simulate(&scenario, 4_163_828_970_110_336_130).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        record.plans.len() <= 24,
        "{} planner calls",
        record.plans.len()
    );
    assert!(evaluation.reached_goal && evaluation.clearance_kept && !evaluation.collision);
}

/// Run 891 of the campaign with 8 COLREGs-obeying targets (seed 11): at
/// 660 s ownship planned 105° at reduced speed held for an hour, for how
/// the vessels were predicted; every encounter was released by 1085 s, but
/// nothing asked again (the plan stayed valid), and the run ran out of time
/// 22 km from its goal. Once the vessels are past and clear the closed
/// loop asks for a plan that arrives sooner (`PlanTrigger::PastAndClear`,
/// decision 52). Since decision 51 the long hold no longer arises in this
/// run (it reaches its goal without that trigger); run 64 gave the sooner
/// plan at 955 s until decision 56 held its plan at 810 s instead of the
/// evasive manoeuvre, and the trigger no longer fires there: both runs are
/// kept to reaching the goal safely (the trigger itself wants a new run).
#[test]
fn once_past_and_clear_a_long_hold_is_cut_short() {
    for index in [891, 64] {
        safe_at_the_goal(8, index);
    }
}

/// Run `index` of the open-sea campaign (seed 11) with `targets`
/// COLREGs-obeying targets, asserted to reach its goal with no collision
/// and `d_th` kept; its record.
fn safe_at_the_goal(targets: usize, index: u64) -> vorrt_scenarios::SimulationRecord {
    let spec = OpenSeaSpec::with_targets(targets).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, index).expect("generated");
    let seed = scenario
        .seed
        .expect("a generated scenario carries its seed");
    let record = simulate(&scenario, seed).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal, "run {index}");
    assert!(
        !evaluation.collision && evaluation.clearance_kept,
        "run {index}"
    );
    record
}

/// Run 704 of the campaign with 8 COLREGs-obeying targets (seed 11): TS1
/// overtakes from the starboard quarter at 22 kn while ownship holds a 45°
/// alteration at reduced speed for other vessels. The plan in force stopped
/// passing the check (TS1's return to its route, foreseen after the closest
/// approach, counted with its margin), every level failed, and the evasive
/// manoeuvre (course 109°, stop), chosen by the same measure a few metres
/// farther, passed TS1 at 181 m between the hulls where the plan would have
/// kept 212 m. The plan under way is now held against the evasive
/// manoeuvre as an evasive one in force is (decision 56).
#[test]
fn a_plan_under_way_is_held_against_an_evasive_manoeuvre_no_better() {
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 704).expect("generated");
    let record = simulate(&scenario, 5_750_672_814_916_719_370).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        evaluation.clearance_kept,
        "{:.1} m between reference points",
        evaluation.min_distance_m
    );
    assert!(evaluation.reached_goal);
}

/// Run 300 of the campaign with 16 COLREGs-obeying targets (seed 11): the
/// same seam with TS15 overtaking from the starboard quarter at 20 kn (the
/// evasive stop passed it at 186 m between the hulls; the plan held keeps
/// `d_th`).
#[test]
fn sixteen_acting_vessels_of_run_300_are_kept_clear_of() {
    let spec = OpenSeaSpec::with_targets(16).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 300).expect("generated");
    let record = simulate(&scenario, 7_303_027_727_954_214_312).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(
        evaluation.clearance_kept,
        "{:.1} m between reference points",
        evaluation.min_distance_m
    );
}

/// Decision 63: runs 552 and 709 of the campaign with 16 COLREGs-obeying
/// targets (seed 11) ran out of time. Each sailed a plan that would reach
/// the goal only after the run's end (run 552: 80° to starboard at 45 % of
/// the service speed, held almost an hour, planned at 30 s), while stand-on
/// encounters stayed in force alongside, so the past-and-clear question
/// (decision 52) was never asked. Ownship now asks for a sooner plan while
/// the plan in force arrives too late, and reaches the goal. Since
/// decision 67 run 709's plans are shorter (a long detour of one alteration
/// is compared with two) and none arrives too late; run 552 still asks.
#[test]
fn a_plan_that_would_arrive_after_the_run_ends_is_replaced() {
    for index in [552, 709] {
        let record = safe_at_the_goal(16, index);
        let late = record
            .triggers()
            .iter()
            .any(|(_, trigger)| *trigger == PlanTrigger::LateArrival);
        assert_eq!(late, index == 552, "run {index}: {:?}", record.triggers());
    }
}
