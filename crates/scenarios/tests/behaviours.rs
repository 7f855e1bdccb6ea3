//! Target behaviours in closed loop: a sudden turn makes ownship replan and
//! it still keeps clear; noisy targets are reproducible per seed; a
//! COLREGs-obeying target gives way when it must and stands on when it must.

use std::path::PathBuf;
use vorrt_geometry::angle;
use vorrt_scenarios::{
    Behaviour, COLREGS_TURN_DEG, PlanTrigger, Scenario, SimulationRecord, evaluate, simulate,
};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "fixtures", relative]
        .iter()
        .collect();
    Scenario::load(&path).expect("fixture loads")
}

fn with_behaviour(relative: &str, behaviour: Behaviour) -> Scenario {
    let mut scenario = fixture(relative);
    scenario.targets[0].behaviour = behaviour;
    scenario.validate().expect("valid");
    scenario
}

fn courses_deg(record: &SimulationRecord) -> Vec<f64> {
    record.targets[0]
        .iter()
        .map(|state| state.course_rad.to_degrees())
        .collect()
}

#[test]
fn sudden_turn_triggers_a_replan_and_ownship_keeps_clear() {
    // The crossing target (from starboard, heading west) turns 60° to port
    // at 5 minutes: toward ownship's side of its track.
    let scenario = with_behaviour(
        "paper/crossing.ron",
        Behaviour::SuddenTurn {
            at_s: 300.0,
            turn_deg: -60.0,
        },
    );
    let record = simulate(&scenario, 1).expect("valid settings");
    let off_prediction: Vec<_> = record
        .triggers()
        .into_iter()
        .filter(|(_, trigger)| *trigger == PlanTrigger::TargetOffPrediction { target: 0 })
        .collect();
    assert!(!off_prediction.is_empty(), "{:?}", record.triggers());
    assert!(off_prediction[0].0 > 300.0);
    // The target holds 270 until the turn and 210 from it on.
    let courses = courses_deg(&record);
    for (time_s, course) in record.times_s.iter().zip(&courses) {
        let expected = if *time_s < 300.0 { 270.0 } else { 210.0 };
        assert!((course - expected).abs() < 1e-6, "{time_s}: {course}");
    }
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal);
    assert!(!evaluation.collision);
    assert!(
        evaluation.clearance_kept,
        "min distance {} m",
        evaluation.min_distance_m
    );
}

#[test]
fn sudden_turn_into_a_head_on_target_is_survived() {
    let scenario = with_behaviour(
        "paper/head_on.ron",
        Behaviour::SuddenTurn {
            at_s: 240.0,
            turn_deg: 40.0,
        },
    );
    let record = simulate(&scenario, 2).expect("valid settings");
    assert!(
        record
            .triggers()
            .iter()
            .any(|(_, trigger)| *trigger == PlanTrigger::TargetOffPrediction { target: 0 })
    );
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal && evaluation.clearance_kept);
}

#[test]
fn noisy_runs_are_reproducible_per_seed() {
    let scenario = with_behaviour(
        "paper/crossing.ron",
        Behaviour::Noisy {
            course_sigma_deg: 8.0,
            speed_sigma_kn: 1.0,
        },
    );
    let first = simulate(&scenario, 5).expect("valid settings");
    let again = simulate(&scenario, 5).expect("valid settings");
    assert_eq!(first.targets, again.targets);
    assert_eq!(first.ownship, again.ownship);
    assert_eq!(
        first.plans.iter().map(|p| p.trigger).collect::<Vec<_>>(),
        again.plans.iter().map(|p| p.trigger).collect::<Vec<_>>()
    );
    let other = simulate(&scenario, 6).expect("valid settings");
    assert_ne!(first.targets, other.targets);
    // The noise is there: the course wanders off the bearing of the goal.
    let wander = courses_deg(&first)
        .iter()
        .map(|course| angle::normalize_pi((course - 270.0).to_radians()).abs())
        .fold(0.0, f64::max);
    assert!(wander.to_degrees() > 2.0, "{}", wander.to_degrees());
    // Noise around the nominal: over the run the target still heads west.
    let track = &first.targets[0];
    let travelled = track.last().unwrap().position_m - track[0].position_m;
    assert!(travelled.x < 0.0 && travelled.y.abs() < 0.3 * travelled.x.abs());
    let evaluation = evaluate(&scenario, &first);
    assert!(evaluation.reached_goal && !evaluation.collision);
}

#[test]
fn colregs_target_gives_way_head_on_and_stands_on_when_crossed() {
    // Head-on: the target must give way too, and turns to starboard.
    let scenario = with_behaviour("paper/head_on.ron", Behaviour::Colregs);
    let record = simulate(&scenario, 1).expect("valid settings");
    let courses = courses_deg(&record);
    assert!((courses[0] - 180.0).abs() < 1e-9);
    let turned = courses
        .iter()
        .position(|course| (course - (180.0 + COLREGS_TURN_DEG)).abs() < 1e-6)
        .expect("turns 35° to starboard");
    // ... then resumes toward its goal once passed.
    let last_course = *courses.last().unwrap();
    assert!(
        courses[turned..]
            .iter()
            .any(|course| (course - 180.0 - COLREGS_TURN_DEG).abs() > 1.0),
        "resumes: last course {last_course}"
    );
    assert!(
        record
            .triggers()
            .iter()
            .any(|(_, trigger)| *trigger == PlanTrigger::TargetOffPrediction { target: 0 })
    );
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.reached_goal && evaluation.clearance_kept);

    // Crossing from ownship's starboard side: ownship is on the target's port
    // side, so the target stands on and keeps its course.
    let scenario = with_behaviour("paper/crossing.ron", Behaviour::Colregs);
    let record = simulate(&scenario, 1).expect("valid settings");
    assert!(
        courses_deg(&record)
            .iter()
            .all(|course| (course - 270.0).abs() < 1e-6)
    );
    assert_eq!(record.replans(), 0);
}

#[test]
fn behaviours_round_trip_and_bad_values_are_refused() {
    let mut scenario = fixture("paper/multi_vessel.ron");
    let behaviours = [
        Behaviour::Colregs,
        Behaviour::Noisy {
            course_sigma_deg: 3.5,
            speed_sigma_kn: 0.25,
        },
        Behaviour::SuddenTurn {
            at_s: 420.0,
            turn_deg: -45.0,
        },
    ];
    for (target, behaviour) in scenario.targets.iter_mut().zip(behaviours) {
        target.behaviour = behaviour;
    }
    let text = scenario.to_ron_string().unwrap();
    assert!(text.contains("behaviour: Colregs"), "{text}");
    assert!(text.contains("Noisy("), "{text}");
    let back = Scenario::from_ron_str(&text, "behaviours").unwrap();
    assert_eq!(back, scenario);

    let written = r#"Scenario(name: "x",
        ownship: Vessel(name: "own", start_nm: (0.0, 0.0), course_deg: 0.0, speed_kn: 10.0,
                        length_m: 50.0, goal_nm: (0.0, 5.0)),
        targets: [Vessel(name: "t", start_nm: (2.0, 2.0), course_deg: 270.0, speed_kn: 10.0,
                         length_m: 50.0, behaviour: BEHAVIOUR)])"#;
    let parsed = Scenario::from_ron_str(
        &written.replace("BEHAVIOUR", "SuddenTurn(at_s: 60.0, turn_deg: 90.0)"),
        "ok.ron",
    )
    .unwrap();
    assert_eq!(
        parsed.targets[0].behaviour,
        Behaviour::SuddenTurn {
            at_s: 60.0,
            turn_deg: 90.0
        }
    );
    for (bad, field) in [
        (
            "Noisy(course_sigma_deg: -1.0, speed_sigma_kn: 0.5)",
            "behaviour.course_sigma_deg",
        ),
        (
            "SuddenTurn(at_s: 60.0, turn_deg: 270.0)",
            "behaviour.turn_deg",
        ),
        ("SuddenTurn(at_s: -1.0, turn_deg: 20.0)", "behaviour.at_s"),
    ] {
        let error =
            Scenario::from_ron_str(&written.replace("BEHAVIOUR", bad), "bad.ron").expect_err(bad);
        assert!(
            error.field().is_some_and(|f| f.ends_with(field)),
            "{bad}: {error}"
        );
    }
}
