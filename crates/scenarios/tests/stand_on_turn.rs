//! Decision 58: open-sea run 48 (8 COLREGs-obeying targets, seed 11).
//! Ownship stands on for TS4, crossing from port, and turns 35° then 70°
//! to starboard while it gives way to others. Part way round its 70° turn
//! the range to TS4 (4.3 km on the port quarter) opened for a moment, and
//! the closed loop and the planner let the stand-on encounter go; the
//! evaluation, on the observed courses, saw the range still closing. Once
//! free of the other vessels, ownship returned 16° and more to port toward
//! its goal with TS4 still beyond 2 nm and not yet past: `stand_on_course_changed`
//! and `stand_on_turned_to_port` (rule 17(a)(i), (c)). A stand-on vessel's
//! own turn no longer ends her encounter, so the planner keeps the course
//! it must keep, as the evaluation judges it.

use vorrt_colregs::ComplianceViolation;
use vorrt_scenarios::{OpenSeaSpec, TargetBehaviour, evaluate, simulate};

/// The run's seed in the campaign (`rows.csv`).
const RUN_48_SEED: u64 = 7_180_607_213_594_883_015;

#[test]
fn run_48_keeps_the_stand_on_course_for_the_vessel_from_port() {
    let spec = OpenSeaSpec::with_targets(8).with_behaviour(TargetBehaviour::Colregs);
    let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 48).expect("generated");
    let record = simulate(&scenario, RUN_48_SEED).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(!evaluation.collision);
    assert!(evaluation.clearance_kept);
    assert!(evaluation.reached_goal);
    let ts4 = evaluation
        .targets
        .iter()
        .find(|t| t.name == "TS4")
        .expect("TS4");
    assert!(
        !ts4.findings.iter().any(|f| matches!(
            f,
            ComplianceViolation::StandOnCourseChanged { .. }
                | ComplianceViolation::StandOnTurnedToPort { .. }
        )),
        "{:?}",
        ts4.findings
    );
}
