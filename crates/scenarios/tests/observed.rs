//! The closed loop judged as observed: on the paper's head-on and crossing
//! encounters ownship's give-way alteration is readily apparent over ground,
//! to starboard, begun at 2 nm or more, and the run has no finding.

use std::path::PathBuf;
use vorrt_colregs::{Encounter, Role};
use vorrt_scenarios::{Scenario, evaluate, simulate};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "fixtures", relative]
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

/// A one-target open-sea scenario (the generator's format), ownship north.
fn one_target(speed_kn: f64, goal_nm: f64, target: &str) -> Scenario {
    let text = format!(
        r#"Scenario(
    name: "case",
    ownship: Vessel(name: "ownship", start_nm: (0.0, 0.0), course_deg: 0.0,
        speed_kn: {speed_kn}, length_m: 100.0, goal_nm: (0.0, {goal_nm})),
    targets: [{target}],
)"#
    );
    Scenario::from_ron_str(&text, "case.ron").expect("valid scenario")
}

/// A head-on vessel just beyond the range at which risk is judged: the
/// alteration ownship begins before the encounter is latched is the action
/// for it (the encounter is judged against the course held steadily before
/// the turn: `rules::steady_course_rad`), so it is readily apparent as
/// observed, not a small alteration made before the encounter began.
#[test]
fn alteration_begun_just_before_risk_counts_as_the_action() {
    let scenario = one_target(
        12.0,
        8.24,
        r#"Vessel(name: "TS1", start_nm: (-0.0726, 5.2007), course_deg: 177.69,
            speed_kn: 11.75, length_m: 242.0, goal_nm: (0.978, -20.851))"#,
    );
    let record = simulate(&scenario, 1).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    let target = &evaluation.targets[0];
    assert_eq!(target.encounter, Encounter::HeadOn);
    let largest = target.max_alteration_deg.expect("assessed");
    assert!(largest >= 30.0, "largest alteration {largest}°");
    assert!(evaluation.compliant, "{:?}", target.violations);
}

/// A stand-on vessel in a crossing from port, far off, and one overtaking
/// from the starboard quarter within reach of the action range: ownship's
/// turns (whenever they are made, and the headings swept through on the way)
/// break neither rule 17(a)(i) nor 17(c) as observed.
#[test]
fn stand_on_turns_keep_rule_17_along_the_whole_turn() {
    for (speed_kn, goal_nm, target) in [
        (
            11.9,
            10.26,
            r#"Vessel(name: "TS1", start_nm: (-5.4342, 7.2311), course_deg: 118.0,
            speed_kn: 17.69, length_m: 180.0, goal_nm: (31.337, -12.32))"#,
        ),
        (
            12.4,
            11.15,
            r#"Vessel(name: "TS1", start_nm: (0.8531, -2.1363), course_deg: 352.98,
            speed_kn: 20.19, length_m: 120.0, goal_nm: (-4.788, 43.672))"#,
        ),
    ] {
        let scenario = one_target(speed_kn, goal_nm, target);
        let record = simulate(&scenario, 1).expect("valid settings");
        let evaluation = evaluate(&scenario, &record);
        let judged = &evaluation.targets[0];
        // The first is no encounter since decision 51: the return to port
        // that made TS1, crossing from port, one ownship stood on for
        // (latched at 700 s) is refused, and the alteration is held until
        // the return makes it no risk.
        assert!(
            matches!(judged.role, Role::StandOn | Role::None),
            "{target}: {:?}",
            judged.role
        );
        assert!(!judged.collision && judged.clearance_kept, "{target}");
        assert!(evaluation.compliant, "{target}: {:?}", judged.violations);
    }
}

/// Ownship gives way to a head-on vessel while another overtakes it from
/// far astern: the course it altered to is the one it then keeps for the
/// overtaking vessel (rule 17(a)(i) yields to the duty to keep out of the
/// way), and it does not turn back while that vessel is beyond the action
/// range, so the run has no finding.
#[test]
fn stand_on_keeps_the_course_taken_while_giving_way_to_another() {
    let text = r#"Scenario(
    name: "overtaken-and-head-on",
    ownship: Vessel(name: "ownship", start_nm: (0.0, 0.0), course_deg: 0.0,
        speed_kn: 11.0, length_m: 100.0, goal_nm: (0.0, 10.12)),
    targets: [
        Vessel(name: "TS1", start_nm: (-0.4035, -4.0249), course_deg: 4.64,
            speed_kn: 20.94, length_m: 206.0, goal_nm: (3.667, 46.13)),
        Vessel(name: "TS2", start_nm: (0.145, 4.6997), course_deg: 185.39,
            speed_kn: 16.66, length_m: 241.0, goal_nm: (-3.251, -31.295)),
    ],
)"#;
    let scenario = Scenario::from_ron_str(text, "case.ron").expect("valid scenario");
    let record = simulate(&scenario, 1).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert_eq!(evaluation.targets[0].role, Role::StandOn);
    assert_eq!(evaluation.targets[1].encounter, Encounter::HeadOn);
    for target in &evaluation.targets {
        assert!(target.clearance_kept, "{}", target.name);
    }
    assert!(
        evaluation.compliant,
        "{:?}",
        evaluation
            .targets
            .iter()
            .map(|t| &t.violations)
            .collect::<Vec<_>>()
    );
}

/// Imazu problem 20 (three vessels): with an action for one vessel freeing
/// ownship from rule 17(a)(i) for the others, whether it gives way to it or
/// stands on for it within the action range (`rules::acting_for_any`), the
/// first plan holds, fully compliant; before, a fully compliant plan was
/// found only after 15 planner calls, 12 of them retries.
#[test]
fn acting_for_a_near_stand_on_vessel_frees_the_course_for_the_others() {
    let scenario = fixture("imazu/imazu_20.ron");
    let record = simulate(&scenario, 1).expect("valid settings");
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal && evaluation.clearance_kept);
    assert!(
        evaluation.compliant,
        "{:?}",
        evaluation
            .targets
            .iter()
            .map(|t| &t.violations)
            .collect::<Vec<_>>()
    );
    assert_eq!(record.plans.len(), 1, "one plan, no replanning");
}
