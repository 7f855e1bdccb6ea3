//! Speed as a manoeuvre (rules 8(e), 17): where no alteration of course is
//! open, ownship gives way by slowing down, sails the plan's speed in closed
//! loop, resumes its service speed once the other vessel is past, and the
//! halving of its speed is judged readily apparent as observed. Without speed
//! manoeuvres the planner finds no compliant plan here and departs from the
//! rules (a fallback turn to port).

use vorrt_colregs::{Encounter, Role};
use vorrt_scenarios::{Scenario, evaluate, simulate};

/// Ownship north at 12 kn, 100 m long, bound 8 nm north. TS1 crosses from
/// starboard on a collision course (both at (0, 3) nm at 15 min): ownship
/// gives way. TS2 runs alongside 400 m to starboard at the same speed: any
/// turn to starboard closes it within `d_th` at once, and a turn to port is
/// forbidden in a crossing (rule 15). Only slowing down is left.
const SLOW_DOWN: &str = r#"Scenario(
    name: "slow_down",
    description: "Crossing give-way with a vessel alongside to starboard: only slowing down keeps clear.",
    ownship: Vessel(
        name: "ownship",
        start_nm: (0.0, 0.0),
        course_deg: 0.0,
        speed_kn: 12.0,
        length_m: 100.0,
        goal_nm: (0.0, 8.0),
    ),
    targets: [
        Vessel(
            name: "TS1",
            start_nm: (3.0, 3.0),
            course_deg: 270.0,
            speed_kn: 12.0,
            length_m: 150.0,
            goal_nm: (-6.0, 3.0),
            behaviour: ConstantToGoal,
        ),
        Vessel(
            name: "TS2",
            start_nm: (0.216, 0.0),
            course_deg: 0.0,
            speed_kn: 12.0,
            length_m: 100.0,
            goal_nm: (0.216, 20.0),
            behaviour: ConstantToGoal,
        ),
    ],
    seed: 1,
)"#;

fn scenario() -> Scenario {
    Scenario::from_ron_str(SLOW_DOWN, "slow_down.ron").expect("valid scenario")
}

#[test]
fn closed_loop_slows_down_to_half_speed_then_resumes_and_the_halving_is_readily_apparent_as_observed()
 {
    let scenario = scenario();
    let record = simulate(&scenario, 1).expect("valid settings");
    let service_mps = 12.0 * 1852.0 / 3600.0;
    let speeds: Vec<f64> = record.ownship.iter().map(|own| own.speed_mps).collect();
    let slowest = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    // Slowed to the manoeuvre search's reduced speed, 45 % of service.
    assert!(
        (slowest - 0.45 * service_mps).abs() < 1e-6,
        "slowest {slowest} m/s"
    );
    // Never faster than the service speed, never changing speed faster than
    // the rate from the stopping distance (v² / (2 · 15 L)).
    let rate_mps2 = service_mps * service_mps / (2.0 * 15.0 * 100.0);
    for pair in speeds.windows(2) {
        assert!((pair[1] - pair[0]).abs() <= rate_mps2 * record.time_step_s + 1e-9);
    }
    assert!(speeds.iter().all(|speed| *speed <= service_mps + 1e-9));
    // Back at service speed before the end.
    let last_moving = speeds[speeds.len() - 2];
    assert!((last_moving - service_mps).abs() < 1e-6, "{last_moving}");
    // The course never changes: the manoeuvre is the speed alone.
    assert!(record.ownship.iter().all(|own| {
        vorrt_geometry::angle::signed_turn(0.0, own.course_rad).abs() < 2f64.to_radians()
    }));
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal);
    assert!(evaluation.clearance_kept, "{} m", evaluation.min_distance_m);
    let crossing = &evaluation.targets[0];
    assert_eq!(crossing.encounter, Encounter::CrossingGiveWay);
    assert_eq!(crossing.role, Role::GiveWay);
    // Judged as observed: the action (the speed halved) was begun and is
    // readily apparent, and held until past.
    assert!(crossing.action_range_m.is_some());
    assert!(
        !crossing.findings.iter().any(|finding| matches!(
            finding.name(),
            "action_not_apparent" | "no_action" | "alteration_not_held"
        )),
        "{:?}",
        crossing.findings
    );
    assert_eq!(evaluation.rule_departures, 0);
}
