//! Every kind of malformed scenario gives the right error variant, naming the
//! file and the field (or line and column), and nothing panics.

use std::path::Path;
use vorrt_scenarios::{Scenario, ScenarioError};

/// A valid scenario; each test breaks one thing in it.
const VALID: &str = r#"
Scenario(
    name: "base",
    ownship: Vessel(
        name: "ownship",
        start_nm: (0.0, -3.0),
        course_deg: 0.0,
        speed_kn: 12.0,
        length_m: 100.0,
        goal_nm: (0.0, 3.0),
    ),
    targets: [
        Vessel(name: "TS1", start_nm: (3.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-4.0, 0.0)),
        Vessel(name: "TS2", start_nm: (-3.0, 0.0), course_deg: 90.0, speed_kn: 8.0,
               length_m: 120.0, goal_nm: (4.0, 0.0)),
        Vessel(name: "TS3", start_nm: (0.0, 3.5), course_deg: 180.0, speed_kn: 10.0,
               length_m: 200.0, goal_nm: (0.0, -4.5)),
    ],
    lanes: [Lane(name: "westbound", from_nm: (6.0, 0.0), to_nm: (-6.0, 0.0), width_nm: 1.0)],
)
"#;

fn with(from: &str, to: &str) -> String {
    assert!(VALID.contains(from), "test fixture lacks {from}");
    VALID.replacen(from, to, 1)
}

/// Loads `text` as `bad.ron` and returns (field, message) of the Invalid error.
fn invalid(text: &str) -> (String, String) {
    match Scenario::from_ron_str(text, "bad.ron") {
        Err(error @ ScenarioError::Invalid { .. }) => {
            let message = error.to_string();
            assert!(message.starts_with("bad.ron: "), "{message}");
            let ScenarioError::Invalid { file, field, .. } = error else {
                unreachable!()
            };
            assert_eq!(file, "bad.ron");
            (field, message)
        }
        other => panic!("expected Invalid, got {other:?}"),
    }
}

/// Loads `text` as `bad.ron` and returns (line, column, message) of the Syntax error.
fn syntax(text: &str) -> (usize, usize, String) {
    match Scenario::from_ron_str(text, "bad.ron") {
        Err(error @ ScenarioError::Syntax { .. }) => {
            let message = error.to_string();
            assert!(message.starts_with("bad.ron:"), "{message}");
            let ScenarioError::Syntax { line, column, .. } = error else {
                unreachable!()
            };
            (line, column, message)
        }
        other => panic!("expected Syntax, got {other:?}"),
    }
}

#[test]
fn the_base_is_valid() {
    let scenario = Scenario::from_ron_str(VALID, "base.ron").expect("valid");
    assert_eq!(scenario.targets.len(), 3);
    assert_eq!(scenario.source, "base.ron");
}

#[test]
fn syntax_error_has_line_and_column() {
    // Missing comma after `start_nm: (0.0, -3.0)` on line 6: found on line 7.
    let text = with("start_nm: (0.0, -3.0),", "start_nm: (0.0, -3.0)");
    let (line, column, message) = syntax(&text);
    assert_eq!(line, 7, "{message}");
    assert!(column > 0, "{message}");
    assert!(message.starts_with("bad.ron:7:"), "{message}");
}

#[test]
fn unknown_field_is_a_syntax_error_naming_it() {
    let text = with(
        "length_m: 100.0,",
        "length_m: 100.0,\n        draught_m: 8.0,",
    );
    let (line, _, message) = syntax(&text);
    assert_eq!(line, 10, "{message}");
    assert!(message.contains("draught_m"), "{message}");
}

#[test]
fn missing_field_and_wrong_type_and_unknown_behaviour_are_syntax_errors() {
    let (_, _, message) = syntax(&with("speed_kn: 12.0,\n        length_m", "length_m"));
    assert!(message.contains("speed_kn"), "{message}");
    let (_, _, message) = syntax(&with("speed_kn: 12.0,", "speed_kn: \"fast\","));
    assert!(message.starts_with("bad.ron:8:"), "{message}");
    let (_, _, message) = syntax(&with(
        "goal_nm: (-4.0, 0.0)),",
        "goal_nm: (-4.0, 0.0), behaviour: Erratic),",
    ));
    assert!(message.contains("Erratic"), "{message}");
    let (_, _, message) = syntax("");
    assert!(message.starts_with("bad.ron:1:"), "{message}");
}

#[test]
fn nan_is_rejected_with_its_field() {
    let (field, message) = invalid(&with("speed_kn: 8.0", "speed_kn: NaN"));
    assert_eq!(field, "targets[1] \"TS2\".speed_kn", "{message}");
    assert!(message.contains("NaN"), "{message}");
    let (field, _) = invalid(&with("course_deg: 0.0", "course_deg: NaN"));
    assert_eq!(field, "ownship.course_deg");
    let (field, _) = invalid(&with("start_nm: (0.0, 3.5)", "start_nm: (0.0, inf)"));
    assert_eq!(field, "targets[2] \"TS3\".start_nm");
}

#[test]
fn negative_speed_is_rejected() {
    let (field, message) = invalid(&with("speed_kn: 10.0", "speed_kn: -1.0"));
    assert_eq!(field, "targets[2] \"TS3\".speed_kn");
    assert!(message.contains("negative"), "{message}");
}

#[test]
fn anchored_target_is_allowed_but_ownship_must_move() {
    Scenario::from_ron_str(&with("speed_kn: 10.0", "speed_kn: 0.0"), "anchored.ron")
        .expect("a target at anchor is allowed");
    let (field, message) = invalid(&with(
        "speed_kn: 12.0,\n        length_m: 100.0",
        "speed_kn: 0.0,\n        length_m: 100.0",
    ));
    assert_eq!(field, "ownship.speed_kn", "{message}");
}

#[test]
fn zero_length_is_rejected() {
    let (field, _) = invalid(&with("length_m: 120.0", "length_m: 0.0"));
    assert_eq!(field, "targets[1] \"TS2\".length_m");
    let (field, _) = invalid(&with("length_m: 100.0", "length_m: -5.0"));
    assert_eq!(field, "ownship.length_m");
}

#[test]
fn goal_at_start_is_rejected() {
    let (field, message) = invalid(&with("goal_nm: (0.0, 3.0)", "goal_nm: (0.0, -3.0)"));
    assert_eq!(field, "ownship.goal_nm", "{message}");
    // The same point in metres.
    let (field, _) = invalid(&with("goal_nm: (0.0, 3.0)", "goal_m: (0.0, -5556.0)"));
    assert_eq!(field, "ownship.goal_m");
}

#[test]
fn ownship_needs_a_goal() {
    let (field, _) = invalid(&with("goal_nm: (0.0, 3.0),", ""));
    assert_eq!(field, "ownship.goal_nm");
}

#[test]
fn duplicate_names_are_rejected() {
    let (field, message) = invalid(&with("name: \"TS3\"", "name: \"TS1\""));
    assert_eq!(field, "targets[2] \"TS1\".name");
    assert!(message.contains("targets[0]"), "{message}");
    let (field, _) = invalid(&with("name: \"TS2\"", "name: \"ownship\""));
    assert_eq!(field, "targets[1] \"ownship\".name");
}

#[test]
fn empty_names_are_rejected() {
    let (field, _) = invalid(&with("name: \"base\"", "name: \"  \""));
    assert_eq!(field, "name");
    let (field, _) = invalid(&with("name: \"TS2\"", "name: \"\""));
    assert_eq!(field, "targets[1] \"\".name");
}

#[test]
fn both_start_forms_are_rejected_and_one_is_required() {
    let (field, message) = invalid(&with(
        "start_nm: (3.0, 0.0),",
        "start_nm: (3.0, 0.0), start_m: (5556.0, 0.0),",
    ));
    assert_eq!(field, "targets[0] \"TS1\".start_nm");
    assert!(message.contains("start_m"), "{message}");
    let (field, _) = invalid(&with("start_nm: (3.0, 0.0),", ""));
    assert_eq!(field, "targets[0] \"TS1\".start_nm");
    let (field, _) = invalid(&with(
        "goal_nm: (-4.0, 0.0)",
        "goal_nm: (-4.0, 0.0), goal_m: (0.0, 0.0)",
    ));
    assert_eq!(field, "targets[0] \"TS1\".goal_nm");
}

#[test]
fn ownship_within_clearance_of_a_target_is_rejected() {
    // 0.1 nm = 185 m, inside the default 200 m clearance.
    let text = with("start_nm: (0.0, 3.5)", "start_nm: (0.1, -3.0)");
    let (field, message) = invalid(&text);
    assert_eq!(field, "targets[2] \"TS3\".start_nm");
    assert!(message.contains("200 m"), "{message}");
    // With a 100 m clearance the same start is fine.
    let text = text.replacen(
        "    lanes:",
        "    planner: (clearance_m: 100.0),\n    lanes:",
        1,
    );
    Scenario::from_ron_str(&text, "ok.ron").expect("outside a 100 m clearance");
    // Metres work too.
    let (field, _) = invalid(&with("start_nm: (0.0, 3.5)", "start_m: (50.0, -5556.0)"));
    assert_eq!(field, "targets[2] \"TS3\".start_m");
}

#[test]
fn a_vessel_at_rest_on_ownships_goal_is_rejected() {
    // TS3 lies at anchor 0.05 nm (93 m) from ownship's goal: ownship must keep
    // 200 m + (100 + 200) / 2 m = 350 m from it, so no plan can end there.
    let anchored = "Vessel(name: \"TS3\", start_nm: (0.05, 3.0), course_deg: 180.0, speed_kn: 0.0,\n               length_m: 200.0, goal_nm: (0.0, -4.5))";
    let original = "Vessel(name: \"TS3\", start_nm: (0.0, 3.5), course_deg: 180.0, speed_kn: 10.0,\n               length_m: 200.0, goal_nm: (0.0, -4.5))";
    let (field, message) = invalid(&with(original, anchored));
    assert_eq!(field, "targets[2] \"TS3\".start_nm");
    assert!(message.contains("ownship.goal_nm"), "{message}");
    assert!(message.contains("350 m"), "{message}");
    // Its goal where it starts: it never moves either.
    let (field, _) = invalid(&with(
        original,
        &anchored
            .replace("speed_kn: 0.0", "speed_kn: 10.0")
            .replace("goal_nm: (0.0, -4.5)", "goal_nm: (0.05, 3.0)"),
    ));
    assert_eq!(field, "targets[2] \"TS3\".start_nm");
    // At rest 0.2 nm (370 m) off the goal, it can be passed at d_th.
    Scenario::from_ron_str(
        &with(original, &anchored.replace("(0.05, 3.0)", "(0.2, 3.0)")),
        "ok.ron",
    )
    .expect("370 m from the goal, beyond the 350 m kept");
    // A moving target that only passes near the goal is no obstacle to it.
    Scenario::from_ron_str(
        &with(
            original,
            &anchored.replace("speed_kn: 0.0", "speed_kn: 10.0"),
        ),
        "ok.ron",
    )
    .expect("moves on");
}

#[test]
fn bad_lanes_are_rejected() {
    let (field, _) = invalid(&with("width_nm: 1.0", "width_nm: 0.0"));
    assert_eq!(field, "lanes[0] \"westbound\".width_nm");
    let (field, _) = invalid(&with("to_nm: (-6.0, 0.0)", "to_nm: (6.0, 0.0)"));
    assert_eq!(field, "lanes[0] \"westbound\".to_nm");
    let (field, _) = invalid(&with("from_nm: (6.0, 0.0)", "from_nm: (NaN, 0.0)"));
    assert_eq!(field, "lanes[0] \"westbound\".from_nm");
}

#[test]
fn bad_planner_settings_name_the_field_in_file_units() {
    let planner = |settings: &str| {
        with(
            "    lanes:",
            &format!("    planner: ({settings}),\n    lanes:"),
        )
    };
    let (field, message) = invalid(&planner("step_m: 0.0"));
    assert_eq!(field, "planner.step_m", "{message}");
    let (field, message) = invalid(&planner("max_turn_per_step_deg: 270.0"));
    assert_eq!(field, "planner.max_turn_per_step_deg");
    assert!(message.contains("270"), "{message}");
    let (field, message) = invalid(&planner("mtd_nm: -1.0"));
    assert_eq!(field, "planner.mtd_nm");
    assert!(message.contains("is -1,"), "{message}");
    let (field, _) = invalid(&planner("goal_bias: 1.5"));
    assert_eq!(field, "planner.goal_bias");
    let (field, _) = invalid(&planner("nodes_per_phase: 0"));
    assert_eq!(field, "planner.nodes_per_phase");
    let (field, _) = invalid(&planner("head_on_half_width_deg: 100.0"));
    assert_eq!(field, "planner.head_on_half_width_deg");
    let (field, _) = invalid(&planner("risk_cpa_nm: NaN"));
    assert_eq!(field, "planner.risk_cpa_nm");
    let (field, _) = invalid(&planner("stand_on_speed_tolerance_kn: -1.0"));
    assert_eq!(field, "planner.stand_on_speed_tolerance_kn");
    let (field, _) = invalid(&planner("time_budget_s: 0.0"));
    assert_eq!(field, "planner.time_budget_s");
    // A negative count is not a whole number: a syntax error at its position.
    let (line, _, _) = syntax(&planner("max_restarts: -1"));
    assert!(line > 0);
}

#[test]
fn bad_simulation_settings_are_rejected() {
    let simulation = |settings: &str| {
        with(
            "    lanes:",
            &format!("    simulation: ({settings}),\n    lanes:"),
        )
    };
    let (field, _) = invalid(&simulation("time_step_s: 0.0"));
    assert_eq!(field, "simulation.time_step_s");
    let (field, _) = invalid(&simulation("max_duration_s: -1.0"));
    assert_eq!(field, "simulation.max_duration_s");
    let (field, _) = invalid(&simulation("replan_deviation_m: inf"));
    assert_eq!(field, "simulation.replan_deviation_m");
    let (field, _) = invalid(&simulation("time_step_s: 1e-9"));
    assert_eq!(field, "simulation.time_step_s");
}

#[test]
#[expect(clippy::cast_precision_loss, reason = "target indices, far below 2^52")]
fn too_many_targets_are_rejected() {
    let target = |i: usize| {
        format!(
            "Vessel(name: \"T{i}\", start_nm: ({}, 5.0), course_deg: 0.0, speed_kn: 5.0, length_m: 50.0),",
            i as f64 * 0.2
        )
    };
    let many: String = (0..=vorrt_scenarios::MAX_TARGETS).map(target).collect();
    let text = with("targets: [", &format!("targets: [{many}"));
    let (field, message) = invalid(&text);
    assert_eq!(field, "targets", "{message}");
}

#[test]
fn absurd_magnitudes_are_rejected() {
    let (field, _) = invalid(&with("start_nm: (3.0, 0.0)", "start_nm: (3.0e300, 0.0)"));
    assert_eq!(field, "targets[0] \"TS1\".start_nm");
    let (field, _) = invalid(&with("speed_kn: 8.0", "speed_kn: 1e6"));
    assert_eq!(field, "targets[1] \"TS2\".speed_kn");
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn out_of_range_courses_are_normalised() {
    let text = with("course_deg: 270.0", "course_deg: -90.0");
    let text = text.replacen("course_deg: 90.0", "course_deg: 810.0", 1);
    let scenario = Scenario::from_ron_str(&text, "courses.ron").expect("valid");
    assert_eq!(scenario.targets[0].course_deg, 270.0);
    assert_eq!(scenario.targets[1].course_deg, 90.0);
}

#[test]
fn io_errors_name_the_path() {
    let missing = Path::new("/nonexistent/vorrt/scenario.ron");
    match Scenario::load(missing) {
        Err(error @ ScenarioError::Io { .. }) => {
            assert!(
                error
                    .to_string()
                    .contains("/nonexistent/vorrt/scenario.ron")
            );
        }
        other => panic!("expected Io, got {other:?}"),
    }
    assert!(matches!(
        vorrt_scenarios::load_dir(Path::new("/nonexistent/vorrt")),
        Err(ScenarioError::Io { .. })
    ));
}

#[test]
fn garbage_never_panics() {
    let inputs = [
        "(",
        "Scenario(",
        "Scenario(name: \"x\")",
        "Scenario(name: 1)",
        "[1, 2, 3]",
        "\u{0}\u{1}",
        "Scenario(name: \"x\", ownship: Vessel(name: \"o\", start_nm: (0.0), course_deg: 0.0, speed_kn: 1.0, length_m: 1.0))",
        "Scenario(name: \"x\", ownship: Vessel(name: \"o\", start_nm: (0.0, 0.0, 0.0), course_deg: 0.0, speed_kn: 1.0, length_m: 1.0))",
        "Scenario(name: \"x\", ownship: Vessel(name: \"o\", start_nm: (0.0, 0.0), course_deg: 0.0, speed_kn: 1.0, length_m: 1.0), seed: -1)",
    ];
    for input in inputs {
        assert!(
            Scenario::from_ron_str(input, "garbage.ron").is_err(),
            "{input}"
        );
    }
    let deep = format!("{}{}", "[".repeat(10_000), "]".repeat(10_000));
    assert!(Scenario::from_ron_str(&deep, "deep.ron").is_err());
    let mut text = VALID.to_owned();
    while !text.is_empty() {
        let _ = Scenario::from_ron_str(&text, "cut.ron");
        let cut = text.len() / 2;
        let cut = (0..=cut)
            .rev()
            .find(|&i| text.is_char_boundary(i))
            .unwrap_or(0);
        text.truncate(cut);
    }
}
