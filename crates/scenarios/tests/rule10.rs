//! Rule 10 end to end: the planner keeps it in closed loop, and the judge
//! sees it (decision 30).

use vorrt_scenarios::colregs::rule10::Rule10Clause;
use vorrt_scenarios::generator::tss;
use vorrt_scenarios::{TargetBehaviour, TssDirection, TssSpec, evaluate, fixtures, simulate};

/// Generated crossings per direction: a few in a debug run, more with
/// `VORRT_HEAVY_TESTS=1`.
fn cases() -> u64 {
    if std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|v| v == "1") {
        40
    } else {
        3
    }
}

#[test]
fn the_paper_tss_crossing_is_square_and_safe() {
    let scenario = fixtures::find("paper/tss")
        .expect("bundled")
        .load()
        .expect("valid");
    let record = simulate(&scenario, scenario.seed.unwrap_or(1)).expect("runs");
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.success(), "{}", evaluation.table());
    assert_eq!(
        evaluation.rule10.crossings.len(),
        1,
        "{}",
        evaluation.table()
    );
    assert!(evaluation.rule10.is_clean(), "{}", evaluation.table());
}

#[test]
fn generated_crossings_keep_the_heading_rule_and_stay_out_of_the_zone() {
    for direction in [TssDirection::Westbound, TssDirection::TwoWay] {
        let spec = TssSpec {
            direction,
            ..TssSpec::with_density(1.0).with_behaviour(TargetBehaviour::Constant)
        };
        let lanes = if direction == TssDirection::TwoWay {
            2
        } else {
            1
        };
        for index in 0..cases() {
            let scenario = tss(&spec, 7, index).expect("generates");
            let record = simulate(&scenario, scenario.seed.unwrap_or(1)).expect("runs");
            let evaluation = evaluate(&scenario, &record);
            let table = evaluation.table();
            assert!(!evaluation.collision, "{}: {table}", scenario.name);
            if evaluation.reached_goal {
                assert_eq!(
                    evaluation.rule10.crossings.len(),
                    lanes,
                    "{}: {table}",
                    scenario.name
                );
            }
            for clause in [
                Rule10Clause::CrossingNotSquare,
                Rule10Clause::SeparationZone,
                Rule10Clause::AgainstFlow,
            ] {
                assert_eq!(
                    evaluation.rule10.count(clause),
                    0,
                    "{}: {table}",
                    scenario.name
                );
            }
        }
    }
}

/// Two-way crossing 32 (seed 7, constant targets): ownship began its
/// return to port while still in the second lane, and the judge, sampling
/// the heading at the lane's edge, saw 16.1° off square where the chord it
/// was on had a middle heading within the 15° allowed. The planner now
/// judges every heading a chord of a turn sweeps through in a lane.
#[test]
fn a_turn_begun_in_a_lane_is_square_at_every_heading_sampled() {
    let spec = TssSpec {
        direction: TssDirection::TwoWay,
        ..TssSpec::with_density(1.0).with_behaviour(TargetBehaviour::Constant)
    };
    let scenario = tss(&spec, 7, 32).expect("generates");
    let record = simulate(&scenario, scenario.seed.unwrap_or(1)).expect("runs");
    let evaluation = evaluate(&scenario, &record);
    let table = evaluation.table();
    assert!(evaluation.reached_goal && !evaluation.collision, "{table}");
    assert_eq!(evaluation.rule10.crossings.len(), 2, "{table}");
    assert_eq!(
        evaluation.rule10.count(Rule10Clause::CrossingNotSquare),
        0,
        "{table}"
    );
}
