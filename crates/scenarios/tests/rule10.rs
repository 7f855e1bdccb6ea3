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
