//! Decision 61: open-sea run 15 (2 targets, seed 11). Ownship overtakes TS1
//! with 35° to starboard; heading for the goal once TS1 is past would turn
//! it to port onto TS2, crossing from port (decision 51's refusal), so the
//! alteration was held longer: 55° for 11.7 km, path overhead 55 %. A
//! smaller port turn, short of the goal's bearing, makes no vessel a risk:
//! ownship now comes back part of the way (005° held 6.4 km while TS2
//! crosses ahead), then heads for the goal, and sails 8 % more than the
//! straight route, keeping every rule but one that decision 73's judges
//! now see (`alteration_not_held`, the planner's next step).

use vorrt_colregs::ComplianceViolation;
use vorrt_scenarios::{OpenSeaSpec, TargetBehaviour, evaluate, simulate};

/// The run's seed in the campaign (`rows.csv`).
const RUN_15_SEED: u64 = 14_874_925_189_342_594_355;

#[test]
fn run_15_comes_back_part_of_the_way_and_keeps_every_rule() {
    for behaviour in [TargetBehaviour::Constant, TargetBehaviour::Colregs] {
        let spec = OpenSeaSpec::with_targets(2).with_behaviour(behaviour);
        let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 15).expect("generated");
        let record = simulate(&scenario, RUN_15_SEED).expect("valid settings");
        let evaluation = evaluate(&scenario, &record);
        assert!(!evaluation.collision, "{behaviour:?}");
        assert!(evaluation.clearance_kept, "{behaviour:?}");
        assert!(evaluation.reached_goal, "{behaviour:?}");
        // Every rule but one: since decision 73 the judges latch the
        // vessel the first alteration was made for while still beyond MTD,
        // and the return part of the way eases that alteration under 30°
        // before she is past (`alteration_not_held`), which the planner
        // only forbids within MTD. No other finding.
        let findings: Vec<_> = evaluation
            .targets
            .iter()
            .flat_map(|target| &target.findings)
            .collect();
        assert!(
            findings
                .iter()
                .all(|finding| matches!(finding, ComplianceViolation::AlterationNotHeld { .. })),
            "{behaviour:?}: {findings:?}"
        );
        // 55.3 % before (the alteration held until TS2 was clear of the
        // return), 8.4 % with the return short of the goal's bearing.
        assert!(
            evaluation.path_overhead_pct < 15.0,
            "{behaviour:?}: {:.1} %",
            evaluation.path_overhead_pct
        );
    }
}
