//! The Imazu fixtures match the published table (Sawada et al. 2021, table 4,
//! as transcribed in the paper notes).

use glam::DVec2;
use vorrt_scenarios::{Scenario, bundled_fixtures_dir};

const NM: f64 = 1852.0;

/// The table: per case, each target's (X north, Y east, psi) in nm and degrees.
const TABLE: [&[(f64, f64, f64)]; 22] = [
    &[(6.0, 0.0, 180.0)],
    &[(0.0, 6.0, -90.0)],
    &[(-4.2, 0.0, 0.0)],
    &[(-4.243, -4.243, 45.0)],
    &[(6.0, 0.0, 180.0), (0.0, 6.0, -90.0)],
    &[(-5.909, 1.042, -10.0), (-4.243, 4.243, -45.0)],
    &[(-4.2, 0.0, 0.0), (-4.243, 4.243, -45.0)],
    &[(6.0, 0.0, 180.0), (0.0, 6.0, -90.0)],
    &[(-5.196, 3.0, -30.0), (0.0, 6.0, -90.0)],
    &[(0.0, 6.0, -90.0), (-5.796, -1.553, 15.0)],
    &[(0.0, -6.0, 90.0), (-5.196, 3.0, -30.0)],
    &[(-4.243, 4.243, -45.0), (-5.909, 1.042, -10.0)],
    &[
        (6.0, 0.0, 180.0),
        (-5.909, -1.042, 10.0),
        (-4.243, -4.243, 45.0),
    ],
    &[
        (-5.909, 1.042, -10.0),
        (-4.243, 4.243, -45.0),
        (0.0, 6.0, -90.0),
    ],
    &[(-4.2, 0.0, 0.0), (-4.243, 4.243, -45.0), (0.0, 6.0, -90.0)],
    &[(-2.97, -2.97, 45.0), (0.0, -6.0, 90.0), (0.0, 6.0, -90.0)],
    &[
        (-4.2, 0.0, 0.0),
        (-5.909, -1.042, 10.0),
        (-4.243, 4.243, -45.0),
    ],
    &[
        (4.243, 4.243, -135.0),
        (-5.796, 1.553, -15.0),
        (-5.196, 3.0, -30.0),
    ],
    &[
        (-5.796, -1.553, 15.0),
        (-5.796, 1.553, -15.0),
        (4.243, 4.243, -135.0),
    ],
    &[(-4.2, 0.0, 0.0), (-5.796, 1.553, -15.0), (0.0, 6.0, -90.0)],
    &[
        (-5.796, 1.553, -15.0),
        (-5.796, -1.553, 15.0),
        (0.0, 6.0, -90.0),
    ],
    &[(-4.2, 0.0, 0.0), (-4.243, 4.243, -45.0), (0.0, 6.0, -90.0)],
];

fn case(number: usize) -> Scenario {
    let path = bundled_fixtures_dir()
        .join("imazu")
        .join(format!("imazu_{number:02}.ron"));
    Scenario::load(&path).expect("imazu fixture")
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn every_case_matches_the_table() {
    for (index, targets) in TABLE.iter().enumerate() {
        let number = index + 1;
        let scenario = case(number);
        assert_eq!(scenario.ownship.start_nm, Some((0.0, -6.0)), "{number}");
        assert_eq!(scenario.ownship.goal_nm, Some((0.0, 6.0)), "{number}");
        assert_eq!(scenario.ownship.course_deg, 0.0, "{number}");
        assert_eq!(scenario.ownship.speed_kn, 12.0, "{number}");
        assert_eq!(scenario.ownship.length_m, 100.0, "{number}");
        assert_eq!(scenario.targets.len(), targets.len(), "{number}");
        let config = scenario.planner_config().expect("config");
        assert_eq!(config.nodes_per_phase, 600, "{number}");
        let expected_planner = vorrt_scenarios::PlannerSettings {
            nodes_per_phase: Some(600),
            ..Default::default()
        };
        assert_eq!(scenario.planner, expected_planner, "{number}");
        for (target, &(x, y, psi)) in scenario.targets.iter().zip(targets.iter()) {
            let context = format!("case {number} {}", target.name);
            assert_eq!(target.start_nm, Some((y, x)), "{context}");
            assert_eq!(target.goal_nm, Some((-y, -x)), "{context}");
            assert_eq!(target.course_deg, psi.rem_euclid(360.0), "{context}");
            assert_eq!(target.length_m, 100.0, "{context}");
            let distance_nm = x.hypot(y);
            assert!(
                (target.speed_kn - distance_nm / 0.5).abs() < 1e-6,
                "{context}"
            );
        }
    }
}

#[test]
fn every_target_passes_the_origin_at_thirty_minutes() {
    for number in 1..=22 {
        let scenario = case(number);
        for target in scenario.target_states() {
            let at_half_hour = target.predict(1800.0).vessel.position_m;
            assert!(
                at_half_hour.length() < 1.0,
                "case {number}: {at_half_hour} m from the origin"
            );
            // And carries on to its goal, reached at t = 60 min.
            let goal = target.goal_m.expect("goal");
            assert!((target.time_to_goal_s().expect("moves") - 3600.0).abs() < 1e-3);
            assert_eq!(target.predict(3600.5).vessel.position_m, goal);
        }
    }
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn spot_checks_in_si() {
    // Case 1: head-on, target 6 nm dead ahead at 12 kn.
    let problem = case(1).planning_problem();
    assert_eq!(problem.ownship.position_m, DVec2::new(0.0, -6.0 * NM));
    assert_eq!(problem.goal_m, DVec2::new(0.0, 6.0 * NM));
    let target = problem.targets[0];
    assert_eq!(target.vessel.position_m, DVec2::new(0.0, 6.0 * NM));
    assert!((target.vessel.course_rad - std::f64::consts::PI).abs() < 1e-12);
    assert!((target.vessel.speed_mps - 12.0 * NM / 3600.0).abs() < 1e-9);

    // Case 3: overtaking, target 4.2 nm out (1.8 nm ahead of ownship) at 8.4 kn.
    let scenario = case(3);
    assert_eq!(scenario.targets[0].start_nm, Some((0.0, -4.2)));
    assert!((scenario.targets[0].speed_kn - 8.4).abs() < 1e-9);

    // Case 6, TS1: (X, Y, psi) = (-5.909, 1.042, -10): east 1.042, north -5.909.
    let scenario = case(6);
    let ts1 = &scenario.targets[0];
    assert_eq!(ts1.start_nm, Some((1.042, -5.909)));
    assert_eq!(ts1.course_deg, 350.0);
    let steered = ts1.target_state().vessel.course_rad.to_degrees();
    assert!((steered - 350.0).abs() < 0.01, "{steered}");

    // Case 16, TS1: 4.2 nm out on the port quarter at 8.4 kn.
    let scenario = case(16);
    let ts1 = &scenario.targets[0];
    assert_eq!(ts1.start_nm, Some((-2.97, -2.97)));
    assert!((ts1.speed_kn - 2.0 * 2.97f64.hypot(2.97)).abs() < 1e-6);

    // Case 18, TS1: from the starboard bow, course -135 = 225.
    let scenario = case(18);
    assert_eq!(scenario.targets[0].start_nm, Some((4.243, 4.243)));
    assert_eq!(scenario.targets[0].course_deg, 225.0);
}

#[test]
fn published_duplicates_are_kept() {
    assert_eq!(case(5).targets, case(8).targets);
    assert_eq!(case(15).targets, case(22).targets);
}
