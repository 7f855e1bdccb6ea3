//! The bundled fixtures load, validate, round-trip, convert to SI, and are as
//! demanding as their comments say.

use std::path::{Path, PathBuf};
use vorrt_geometry::{closest_point_of_approach_within, units};
use vorrt_scenarios::{Behaviour, Scenario, VesselSpec, bundled_fixtures_dir, load_dir};

const NM: f64 = 1852.0;

fn dir(name: &str) -> PathBuf {
    bundled_fixtures_dir().join(name)
}

fn paper(name: &str) -> Scenario {
    Scenario::load(&dir("paper").join(format!("{name}.ron"))).expect(name)
}

fn all_fixtures() -> Vec<(PathBuf, Scenario)> {
    let mut all = load_dir(&dir("paper")).expect("paper fixtures");
    all.extend(load_dir(&dir("imazu")).expect("imazu fixtures"));
    all
}

/// CPA distance (m) of `target` if ownship held its course and speed for the
/// time ownship needs to reach its goal, targets moving as the planner predicts.
fn cpa_if_ownship_holds_course(scenario: &Scenario, target: &VesselSpec) -> f64 {
    let own = scenario.ownship_state();
    let target = target.target_state();
    let horizon = scenario.straight_line_time_s();
    let horizon = horizon.min(target.time_to_goal_s().unwrap_or(f64::INFINITY));
    closest_point_of_approach_within(
        own.position_m,
        own.velocity_mps(),
        target.vessel.position_m,
        target.vessel.velocity_mps(),
        horizon,
    )
    .distance_m
}

#[test]
fn every_bundled_fixture_loads_sorted_by_name() {
    let paper = load_dir(&dir("paper")).expect("paper fixtures");
    let names: Vec<&str> = paper.iter().map(|(_, s)| s.name.as_str()).collect();
    assert_eq!(
        names,
        ["crossing", "head_on", "multi_vessel", "overtaking", "tss"]
    );
    let imazu = load_dir(&dir("imazu")).expect("imazu fixtures");
    assert_eq!(imazu.len(), 22);
    for (index, (path, scenario)) in imazu.iter().enumerate() {
        let expected = format!("imazu_{:02}", index + 1);
        assert_eq!(scenario.name, expected);
        assert_eq!(
            path.file_stem().and_then(|s| s.to_str()),
            Some(expected.as_str())
        );
    }
}

#[test]
fn every_fixture_round_trips_through_ron() {
    for (path, scenario) in all_fixtures() {
        let text = scenario.to_ron_string().expect("serialises");
        let back = Scenario::from_ron_str(&text, "<round trip>")
            .unwrap_or_else(|error| panic!("{}: {error}\n{text}", path.display()));
        assert_eq!(back, scenario, "{}", path.display());
        assert_eq!(
            back.to_ron_string().expect("serialises"),
            text,
            "{}",
            path.display()
        );
    }
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn every_fixture_is_fully_specified() {
    for (path, scenario) in all_fixtures() {
        let path = path.display();
        assert!(scenario.description.is_some(), "{path}");
        assert_eq!(scenario.ownship.speed_kn, 12.0, "{path}");
        assert!(scenario.ownship.goal_nm.is_some(), "{path}");
        for target in &scenario.targets {
            assert!(target.goal_nm.is_some(), "{path}: {}", target.name);
            assert_eq!(target.behaviour, Behaviour::ConstantToGoal);
            // The goal lies ahead: the target passes through and beyond.
            let state = target.target_state();
            let course_given = target.course_deg.to_radians();
            let course_to_goal = state.vessel.course_rad;
            let turn = vorrt_geometry::angle::signed_turn(course_given, course_to_goal);
            assert!(
                turn.abs() < 0.01_f64.to_radians(),
                "{path}: {} course {} vs goal bearing {}",
                target.name,
                target.course_deg,
                course_to_goal.to_degrees()
            );
        }
        scenario.planner_config().expect("planner settings valid");
        let problem = scenario.planning_problem();
        problem.validate().expect("planning problem valid");
    }
}

#[test]
#[expect(clippy::cast_precision_loss, reason = "a node count, far below 2^52")]
fn paper_fixtures_are_sized_as_promised() {
    for (path, scenario) in load_dir(&dir("paper")).expect("paper") {
        let path = path.display();
        let route_nm = scenario.straight_line_time_s() * scenario.ownship.speed_mps() / NM;
        assert!((6.0..=8.0).contains(&route_nm), "{path}: {route_nm}");
        for vessel in std::iter::once(&scenario.ownship).chain(&scenario.targets) {
            assert!((50.0..=200.0).contains(&vessel.length_m), "{path}");
        }
        // Enough nodes per phase for 1.5 x the straight route.
        let config = scenario.planner_config().expect("config");
        let steps = route_nm * NM / config.step_m;
        assert!(config.nodes_per_phase as f64 >= 1.5 * steps, "{path}");
    }
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn two_vessel_paper_fixtures_collide_if_ownship_holds_course() {
    for name in ["crossing", "head_on", "overtaking"] {
        let scenario = paper(name);
        assert_eq!(scenario.targets.len(), 1, "{name}");
        let cpa = cpa_if_ownship_holds_course(&scenario, &scenario.targets[0]);
        assert!(cpa < 1.0, "{name}: CPA {cpa} m");
    }
    let overtaking = paper("overtaking");
    let target = &overtaking.targets[0];
    assert_eq!(target.course_deg, overtaking.ownship.course_deg);
    assert!(target.speed_kn < overtaking.ownship.speed_kn);
}

#[test]
fn multi_vessel_has_three_targets_on_collision_courses() {
    let scenario = paper("multi_vessel");
    assert_eq!(scenario.targets.len(), 3);
    let clearance = scenario.planner_config().expect("config").clearance_m;
    for target in &scenario.targets {
        let cpa = cpa_if_ownship_holds_course(&scenario, target);
        assert!(cpa < clearance, "{}: CPA {cpa} m", target.name);
    }
}

/// The report agrees with the fixture's description: ownship alters at
/// once, TS1 and TS3 still beyond MTD, and the judges take that alteration
/// as its action for all three (decision 73).
#[test]
fn multi_vessel_report_agrees_with_its_description() {
    let scenario = paper("multi_vessel");
    let record = vorrt_scenarios::simulate(&scenario, 1).expect("runs");
    let evaluation = vorrt_scenarios::evaluate(&scenario, &record);
    let classes: Vec<_> = evaluation
        .targets
        .iter()
        .map(|target| target.encounter)
        .collect();
    assert_eq!(
        classes,
        [
            vorrt_colregs::Encounter::HeadOn,
            vorrt_colregs::Encounter::CrossingGiveWay,
            vorrt_colregs::Encounter::CrossingGiveWay
        ]
    );
    let description = scenario.description.expect("described");
    assert!(description.contains("TS1 as head_on and TS2 and TS3 as crossing_give_way"));
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn tss_fixture_is_a_busy_westbound_lane() {
    let scenario = paper("tss");
    let config = scenario.planner_config().expect("config");
    assert_eq!(config.clearance_m, 100.0);
    assert_eq!(scenario.lanes.len(), 1);
    let lane = &scenario.lanes[0];
    assert_eq!(lane.width_nm, 1.0);
    assert!((lane.traffic_course_rad().to_degrees() - 270.0).abs() < 1e-9);
    assert!(scenario.targets.len() >= 15);
    let mut collision = 0;
    let mut risk = 0;
    for target in &scenario.targets {
        assert!((8.0..=15.0).contains(&target.speed_kn), "{}", target.name);
        assert_eq!(target.course_deg, 270.0, "{}", target.name);
        assert!(
            lane.contains_m(target.start_position_m()),
            "{}",
            target.name
        );
        let cpa = cpa_if_ownship_holds_course(&scenario, target);
        if cpa < config.clearance_m {
            collision += 1;
        }
        if cpa < NM {
            risk += 1;
        }
    }
    assert_eq!(collision, 5);
    assert_eq!(risk, 14);
    // Ownship crosses the lane south to north.
    assert!(!lane.contains_m(scenario.ownship_state().position_m));
    assert!(!lane.contains_m(scenario.ownship_goal_m()));
    assert_eq!(scenario.ownship.course_deg, 0.0);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn conversion_to_planning_problem_is_in_si() {
    let scenario = paper("crossing");
    let problem = scenario.planning_problem();
    let own = problem.ownship;
    assert_eq!(own.position_m, glam::DVec2::new(0.0, -3.0 * NM));
    assert_eq!(own.course_rad, 0.0);
    assert!((own.speed_mps - 12.0 * 1852.0 / 3600.0).abs() < 1e-12);
    assert_eq!(own.length_m, 100.0);
    assert_eq!(problem.goal_m, glam::DVec2::new(0.0, 3.0 * NM));
    assert_eq!(problem.start_time_s, 0.0);
    assert!(problem.encounters.is_empty());
    let target = problem.targets[0];
    assert_eq!(target.vessel.position_m, glam::DVec2::new(3.0 * NM, 0.0));
    assert!((target.vessel.course_rad - 270f64.to_radians()).abs() < 1e-12);
    assert!((target.vessel.speed_mps - units::knots_to_mps(12.0)).abs() < 1e-12);
    assert_eq!(target.goal_m, Some(glam::DVec2::new(-4.0 * NM, 0.0)));
    assert_eq!(problem.targets, scenario.target_states());
    assert_eq!(own, scenario.ownship_state());
    assert_eq!(problem.goal_m, scenario.ownship_goal_m());
    // 6 nm at 12 kn: 30 min; default simulation length is three times that.
    assert!((scenario.straight_line_time_s() - 1800.0).abs() < 1e-9);
    assert!((scenario.max_duration_s() - 5400.0).abs() < 1e-9);
}

#[test]
fn behaviours_and_metre_positions_convert() {
    let mut scenario = paper("crossing");
    let target = &mut scenario.targets[0];
    target.behaviour = Behaviour::ConstantVelocity;
    target.start_nm = None;
    target.start_m = Some((5556.0, 10.0));
    target.course_deg = 265.0;
    scenario.validate().expect("valid");
    let state = scenario.target_states()[0];
    assert_eq!(state.goal_m, None);
    assert_eq!(state.vessel.position_m, glam::DVec2::new(5556.0, 10.0));
    assert!((state.vessel.course_rad - 265f64.to_radians()).abs() < 1e-12);
    // A target without a goal holds its course and speed too.
    let mut scenario = paper("crossing");
    scenario.targets[0].goal_nm = None;
    scenario.validate().expect("valid");
    assert_eq!(scenario.target_states()[0].goal_m, None);
}

#[test]
fn docs_example_is_the_crossing_fixture() {
    let doc_path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario-format.md");
    let doc = std::fs::read_to_string(&doc_path).expect("docs/scenario-format.md");
    let example = doc
        .split("## Complete example")
        .nth(1)
        .and_then(|rest| rest.split("```ron\n").nth(1))
        .and_then(|block| block.split("```").next())
        .expect("a ron block under Complete example");
    let scenario = Scenario::from_ron_str(example, "docs example").expect("docs example loads");
    assert_eq!(scenario, paper("crossing"));
}

#[test]
fn explicit_some_and_anonymous_structs_are_accepted() {
    let text = r#"(
        name: "plain",
        ownship: (name: "own", start_m: (0.0, 0.0), course_deg: 0.0, speed_kn: 10.0,
                  length_m: 60.0, goal_m: Some((0.0, 5000.0))),
        targets: [(name: "anchored", start_m: (500.0, 2500.0), course_deg: 0.0,
                   speed_kn: 0.0, length_m: 80.0)],
        seed: Some(7),
    )"#;
    let scenario = Scenario::from_ron_str(text, "plain.ron").expect("loads");
    assert_eq!(scenario.ownship.goal_m, Some((0.0, 5000.0)));
    assert_eq!(scenario.seed, Some(7));
    assert_eq!(scenario.planning_problem().targets[0].goal_m, None);
}
