//! The closed loop judged as observed: on the paper's head-on and crossing
//! encounters ownship's give-way alteration is readily apparent over ground,
//! to starboard, begun at 2 nm or more, and the run has no finding.

use std::path::PathBuf;
use vorrt_colregs::{Encounter, Role};
use vorrt_scenarios::{Scenario, evaluate, simulate};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "..", "..", "fixtures", relative]
        .iter()
        .collect();
    Scenario::load(&path).expect("fixture loads")
}

#[test]
fn head_on_and_crossing_give_way_early_readily_apparent_to_starboard_without_finding() {
    for (name, encounter) in [
        ("paper/head_on.ron", Encounter::HeadOn),
        ("paper/crossing.ron", Encounter::CrossingGiveWay),
    ] {
        let scenario = fixture(name);
        let record = simulate(&scenario, 1).expect("valid settings");
        let evaluation = evaluate(&scenario, &record);
        let target = &evaluation.targets[0];
        assert_eq!(target.encounter, encounter, "{name}");
        assert_eq!(target.role, Role::GiveWay, "{name}");
        let action_range_m = target.action_range_m.expect("action begun");
        assert!(action_range_m >= 2.0 * 1852.0, "{name}: {action_range_m} m");
        let first = target.first_alteration_deg.expect("altered");
        assert!(first > 0.0, "{name}: first alteration {first}°");
        let largest = target.max_alteration_deg.expect("assessed");
        assert!(
            largest >= 30.0 - 1e-6,
            "{name}: largest alteration {largest}°"
        );
        assert!(
            target.findings.is_empty() && evaluation.track_findings.is_empty(),
            "{name}: {:?} {:?}",
            target.violations,
            evaluation.track_findings
        );
        assert!(evaluation.compliant, "{name}");
        assert!(
            evaluation.turn_reversals <= 4,
            "{name}: {}",
            evaluation.turn_reversals
        );
        // The sailed rate of turn is the vessel's, never above its limit.
        let limit = evaluation
            .turn_rate_limit_deg_s
            .expect("rate-limited ownship");
        assert!(
            evaluation.max_turn_rate_deg_s <= limit * (1.0 + 1e-6),
            "{name}"
        );
    }
}
