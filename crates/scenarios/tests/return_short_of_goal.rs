//! Decision 61: open-sea run 15 (2 targets, seed 11). Ownship overtakes TS1
//! with 35° to starboard; heading for the goal once TS1 is past would turn
//! it to port onto TS2, crossing from port (decision 51's refusal), so the
//! alteration was held longer: 55° for 11.7 km, path overhead 55 %. A
//! smaller port turn, short of the goal's bearing, makes no vessel a risk:
//! ownship now comes back part of the way (005° held 6.4 km while TS2
//! crosses ahead), then heads for the goal, and sails 8 % more than the
//! straight route, keeping every rule but one that decision 73's judges
//! see (`alteration_not_held`). Since decision 74 the planner latches the
//! vessel its alteration is made for as the judges do and holds the
//! alteration until she is past: every rule kept, 56.5 % overhead.

use vorrt_scenarios::{OpenSeaSpec, TargetBehaviour, evaluate, simulate};

/// The run's seed in the campaign (`rows.csv`).
const RUN_15_SEED: u64 = 14_874_925_189_342_594_355;

#[test]
fn run_15_keeps_every_rule() {
    for behaviour in [TargetBehaviour::Constant, TargetBehaviour::Colregs] {
        let spec = OpenSeaSpec::with_targets(2).with_behaviour(behaviour);
        let scenario = vorrt_scenarios::generator::open_sea(&spec, 11, 15).expect("generated");
        let record = simulate(&scenario, RUN_15_SEED).expect("valid settings");
        let evaluation = evaluate(&scenario, &record);
        assert!(!evaluation.collision, "{behaviour:?}");
        assert!(evaluation.clearance_kept, "{behaviour:?}");
        assert!(evaluation.reached_goal, "{behaviour:?}");
        // Every rule: decision 73's judges latch the vessel the first
        // alteration was made for while still beyond MTD, and since
        // decision 74 so does the planner, which holds that alteration
        // until she is past. No finding.
        assert!(
            evaluation.compliant,
            "{behaviour:?}: {:?}",
            evaluation.targets
        );
        // 55.3 % before decision 61 (the alteration held until TS2 was
        // clear of the return), 8.4 % with the return short of the goal's
        // bearing, which eased the alteration before the vessel it was made
        // for was past (`alteration_not_held`); 56.5 % since decision 74:
        // the return part of the way is no longer begun while she closes.
        assert!(
            evaluation.path_overhead_pct < 60.0,
            "{behaviour:?}: {:.1} %",
            evaluation.path_overhead_pct
        );
    }
}
