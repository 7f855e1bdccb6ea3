//! End-to-end tests of the `vorrt` binary: exit codes, outputs and messages.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use vorrt_cli::report::{PlanOutput, Report};
use vorrt_scenarios::jfs::{MotionModel, Pose};
use vorrt_scenarios::{Scenario, evaluate, simulate};

fn vorrt(args: &[&str]) -> Output {
    // This crate's binary; the workspace root's `vorrt` binary is the same program.
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .output()
        .expect("the vorrt binary runs")
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// A bundled scenario file (vorrt-scenarios' `fixtures/`).
fn fixture(relative: &str) -> PathBuf {
    vorrt_scenarios::bundled_fixtures_dir().join(relative)
}

fn crossing() -> PathBuf {
    fixture("paper/crossing.ron")
}

fn path_str(path: &Path) -> &str {
    path.to_str().expect("test paths are UTF-8")
}

fn assert_close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
        "{what}: {a} vs {b}"
    );
}

/// A scenario small enough for debug builds, written into `dir`.
const SMALL: &str = r#"Scenario(
    name: "small crossing",
    description: "A short crossing <made> for the tests & the demo page.",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -1.0), course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.0)),
    targets: [
        Vessel(name: "TS1", start_nm: (1.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-1.5, 0.0)),
    ],
    seed: 3,
)
"#;

#[test]
fn simulate_writes_a_report_that_matches_the_library() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("run");
    let output = vorrt(&["simulate", path_str(&crossing()), "--out", path_str(&out)]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let printed = stdout(&output);
    for expected in [
        "TS1",
        "crossing_give_way",
        "reached goal",
        "min distance",
        "overhead",
        "straight at the service speed",
        "report.json",
    ] {
        assert!(
            printed.contains(expected),
            "summary lacks {expected}: {printed}"
        );
    }

    let text = std::fs::read_to_string(out.join("report.json")).unwrap();
    let report: Report = serde_json::from_str(&text).unwrap();
    assert_report_matches_the_library(&report);
    assert_report_field_names(&text);
    assert_plots_written(&out);
}

/// `report`, of the crossing fixture's run, is what the library computes.
fn assert_report_matches_the_library(report: &Report) {
    let scenario = Scenario::load(&crossing()).unwrap();
    let seed = scenario.seed.unwrap_or(1);
    let record = simulate(&scenario, seed).unwrap();
    let evaluation = evaluate(&scenario, &record);

    assert_eq!(report.scenario, evaluation.scenario);
    assert_eq!(report.seed, seed);
    assert_close(report.d_th_m, evaluation.clearance_m, "d_th");
    assert_eq!(report.reached_goal, evaluation.reached_goal);
    assert_eq!(report.arrival_time_s, record.arrival_time_s);
    assert_eq!(report.collision, evaluation.collision);
    assert_eq!(report.clearance_kept, evaluation.clearance_kept);
    assert_eq!(report.compliant, evaluation.compliant);
    assert_close(
        report.min_distance_m.unwrap(),
        evaluation.min_distance_m,
        "min distance",
    );
    assert_close(
        report.path_length_m,
        evaluation.path_length_m,
        "path length",
    );
    assert_close(
        report.path_overhead_pct,
        evaluation.path_overhead_pct,
        "overhead",
    );
    assert_close(
        report.straight_duration_s,
        evaluation.straight_duration_s,
        "straight duration",
    );
    assert_close(
        report.time_overhead_pct,
        evaluation.time_overhead_pct,
        "time overhead",
    );
    assert_eq!(report.planning.plans_made, evaluation.plans_made);
    assert_eq!(report.planning.replans, evaluation.replans);
    assert_eq!(report.planning.failed_plans, evaluation.failed_plans);
    assert!(report.planning.total_planning_time_s >= 0.0);
    assert_plan_events_match(report, &record);
    assert_eq!(report.targets.len(), evaluation.targets.len());
    for (reported, evaluated) in report.targets.iter().zip(&evaluation.targets) {
        assert_eq!(reported.name, evaluated.name);
        assert_eq!(reported.encounter, evaluated.encounter.name());
        assert_eq!(reported.role, evaluated.role.name());
        assert_close(
            reported.min_distance_m,
            evaluated.min_distance_m,
            "target min",
        );
        assert_close(
            reported.time_of_min_s,
            evaluated.time_of_min_s,
            "time of min",
        );
        assert_eq!(reported.compliant, evaluated.compliant);
        assert_eq!(reported.violations, evaluated.violations);
        assert_close(reported.score, evaluated.score, "score");
    }
    assert!(report.reached_goal_safely);
}

/// `report.json`'s plan events are the record's planner calls: source,
/// compliance, waypoints and their speeds.
fn assert_plan_events_match(report: &Report, record: &vorrt_scenarios::SimulationRecord) {
    assert_eq!(report.plans.len(), record.plans.len());
    for (reported, event) in report.plans.iter().zip(&record.plans) {
        assert_close(reported.time_s, event.time_s, "plan time");
        assert_eq!(reported.succeeded, event.succeeded);
        assert_eq!(reported.source, event.statistics.source.key());
        assert_ne!(reported.source, "none", "a plan came back");
        assert_eq!(reported.compliance, "full");
        assert_eq!(reported.waypoints.len(), event.waypoints.len());
        for ((waypoint, planned), speed_mps) in reported
            .waypoints
            .iter()
            .zip(&event.waypoints)
            .zip(&event.speeds_mps)
        {
            assert_close(waypoint.east_m, planned.position_m.x, "east");
            assert_close(waypoint.speed_mps, *speed_mps, "speed");
            assert_close(waypoint.speed_kn, *speed_mps * 3600.0 / 1852.0, "kn");
        }
    }
    assert_eq!(report.plans[0].trigger, "initial");
}

/// The raw `report.json` has the documented field names.
fn assert_report_field_names(text: &str) {
    let value: serde_json::Value = serde_json::from_str(text).unwrap();
    for field in [
        "scenario",
        "seed",
        "d_th_m",
        "reached_goal",
        "collision",
        "min_distance_m",
        "planning",
        "path_length_m",
        "path_overhead_pct",
        "targets",
    ] {
        assert!(value.get(field).is_some(), "report.json lacks {field}");
    }
    for field in [
        "plans_made",
        "replans",
        "failed_plans",
        "total_planning_time_s",
    ] {
        assert!(
            value["planning"].get(field).is_some(),
            "planning lacks {field}"
        );
    }
}

/// The SVG and PNG plots in `out` are whole, titled and not empty.
fn assert_plots_written(out: &Path) {
    for name in ["trajectories.svg", "distance.svg", "speed.svg"] {
        let svg = std::fs::read_to_string(out.join(name)).unwrap();
        assert!(
            svg.trim_start().starts_with("<svg"),
            "{name} does not start with <svg"
        );
        assert!(
            svg.trim_end().ends_with("</svg>"),
            "{name} does not end with </svg>"
        );
        assert!(svg.contains("<text"), "{name} has no text");
        assert!(svg.contains("crossing"), "{name} lacks its title");
    }
    for name in ["trajectories.png", "distance.png", "speed.png"] {
        let png = std::fs::read(out.join(name)).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{name} is not a PNG");
        assert!(
            png.len() > 20_000,
            "{name} is suspiciously small: {} bytes",
            png.len()
        );
    }
}

#[test]
fn simulate_seed_option_is_used() {
    let dir = tempfile::tempdir().unwrap();
    let scenario_path = dir.path().join("small.ron");
    std::fs::write(&scenario_path, SMALL).unwrap();
    let out = dir.path().join("seeded");
    let output = vorrt(&[
        "simulate",
        path_str(&scenario_path),
        "--seed",
        "42",
        "--out",
        path_str(&out),
    ]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let report: Report =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(report.seed, 42);
    assert_eq!(report.scenario, "small crossing");

    let out = dir.path().join("default");
    let output = vorrt(&[
        "simulate",
        path_str(&scenario_path),
        "--out",
        path_str(&out),
    ]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let report: Report =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(report.seed, 3, "the scenario's own seed is the default");
}

#[test]
fn check_accepts_good_fixtures() {
    let output = vorrt(&[
        "check",
        path_str(&crossing()),
        path_str(&fixture("paper/tss.ron")),
    ]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let printed = stdout(&output);
    assert!(
        printed.contains("ok: ") && printed.contains("crossing.ron") && printed.contains("tss.ron")
    );
}

fn check_broken(text: &str, expected: &[&str]) {
    assert_ne!(text, SMALL, "the test must break the file");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("broken.ron");
    std::fs::write(&path, text).unwrap();
    let output = vorrt(&["check", path_str(&path)]);
    let message = stderr(&output);
    assert_eq!(output.status.code(), Some(2), "stderr: {message}");
    assert!(!message.contains("panicked"), "{message}");
    assert!(
        message.contains("broken.ron"),
        "the file is not named: {message}"
    );
    for word in expected {
        assert!(message.contains(word), "{word:?} not in {message}");
    }
}

#[test]
fn check_reports_a_syntax_error_with_its_line() {
    // Line 3 lacks the comma between two fields.
    check_broken(
        &SMALL.replacen("name: \"small crossing\",", "name: \"small crossing\"", 1),
        &["broken.ron:3:"],
    );
}

#[test]
fn check_reports_an_unknown_field() {
    check_broken(&SMALL.replacen("seed: 3,", "sede: 3,", 1), &["sede"]);
}

#[test]
fn check_reports_a_negative_speed_by_field() {
    check_broken(
        &SMALL.replacen(
            "course_deg: 270.0, speed_kn: 12.0",
            "course_deg: 270.0, speed_kn: -4.0",
            1,
        ),
        &["targets[0]", "speed_kn"],
    );
}

#[test]
fn check_of_a_missing_file_exits_2() {
    let output = vorrt(&["check", "/nonexistent/scenario.ron"]);
    assert_eq!(output.status.code(), Some(2));
    let message = stderr(&output);
    assert!(
        message.contains("/nonexistent/scenario.ron") && !message.contains("panicked"),
        "{message}"
    );
}

/// `vorrt plan` keeps the scenario's land as the closed loop does: the
/// plan across `coastal/island` rounds the island, every leg clear of it by
/// the land clearance.
#[test]
fn plan_keeps_off_land() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/fixtures/coastal/island.ron");
    let output = vorrt(&["plan", path_str(&path)]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let plan: PlanOutput = serde_json::from_str(&stdout(&output)).unwrap();
    let scenario = Scenario::load(&path).unwrap();
    let chart = vorrt_scenarios::Chart::from_scenario(&scenario).unwrap();
    assert!(
        plan.waypoints.len() > 2,
        "a straight plan runs over the island"
    );
    // Each leg as ownship sails it (a turn at its rate of turn from the
    // waypoint's course, then a straight run), sampled 400 times: the chord
    // between two waypoints cuts across the turn that begins the leg.
    let config = scenario.planner_config().unwrap();
    let speed_mps = scenario.ownship.speed_kn * 1852.0 / 3600.0;
    let model = config
        .turning
        .ownship_model(scenario.ownship.length_m, speed_mps);
    for leg in plan.waypoints.windows(2) {
        let start = Pose {
            position_m: vorrt_scenarios::DVec2::new(leg[0].east_m, leg[0].north_m),
            course_rad: leg[0].course_deg.to_radians(),
        };
        let end_m = vorrt_scenarios::DVec2::new(leg[1].east_m, leg[1].north_m);
        let sailed = model
            .steer(start, end_m, leg[1].speed_mps, f64::INFINITY)
            .expect("a leg");
        assert!(
            sailed.end_m().distance(end_m) < 1.0,
            "the leg ends at its waypoint"
        );
        let samples = 400u32;
        let points: Vec<_> = (0..=samples)
            .map(|k| {
                let elapsed_s = sailed.duration_s() * f64::from(k) / f64::from(samples);
                sailed.pose_at(elapsed_s).position_m
            })
            .collect();
        for pair in points.windows(2) {
            let distance_m = chart.segment_land_distance_m(pair[0], pair[1]);
            assert!(
                distance_m >= chart.land_clearance_m(),
                "{distance_m} m from land"
            );
        }
    }
}

#[test]
fn plan_prints_json_waypoints() {
    let output = vorrt(&["plan", path_str(&crossing())]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let plan: PlanOutput = serde_json::from_str(&stdout(&output)).unwrap();
    assert!(plan.waypoints.len() >= 2);
    let first = plan.waypoints.first().unwrap();
    let last = plan.waypoints.last().unwrap();
    assert_close(first.time_s, 0.0, "start time");
    assert_close(first.north_m, -3.0 * 1852.0, "start north");
    assert!(
        (last.north_m - 3.0 * 1852.0).abs() < 1.0 && last.east_m.abs() < 1.0,
        "ends at the goal"
    );
    assert!(
        plan.waypoints
            .windows(2)
            .all(|pair| pair[0].time_s < pair[1].time_s)
    );
    assert!(
        plan.waypoints
            .iter()
            .all(|w| (0.0..360.0).contains(&w.course_deg))
    );
    // The manoeuvre search finds this one at the root, before any sample.
    assert_eq!(plan.statistics.nodes, 1);
    assert_eq!(plan.source, "one_alteration");
    for waypoint in &plan.waypoints {
        // The crossing is sailed at the service speed, 12 kn.
        assert_close(waypoint.speed_kn, 12.0, "speed");
        assert_close(waypoint.speed_mps, 12.0 * 1852.0 / 3600.0, "speed m/s");
    }
    let value: serde_json::Value = serde_json::from_str(&stdout(&output)).unwrap();
    assert!(value["waypoints"][0].get("course_deg").is_some());
}

#[test]
fn plan_names_the_tree_when_the_tree_found_it() {
    // The paper's instantaneous turns: no manoeuvre search, the plan is
    // the tree's branch.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("instant.ron");
    std::fs::write(
        &path,
        SMALL.replace(
            "    seed: 3,",
            "    planner: Planner(instant_turns: true),\n    seed: 3,",
        ),
    )
    .unwrap();
    let output = vorrt(&["plan", path_str(&path)]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let plan: PlanOutput = serde_json::from_str(&stdout(&output)).unwrap();
    assert_eq!(plan.source, "tree");
    assert!(plan.statistics.nodes > 1, "{:?}", plan.statistics);
}

#[test]
fn a_vessel_at_anchor_on_the_goal_is_refused_by_check() {
    // Issue 24: `check` accepted it, `simulate` failed every plan and sailed
    // past the goal. Now every command refuses it, saying why (decision 33).
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("anchored.ron");
    std::fs::write(
        &path,
        r#"Scenario(
    name: "anchored",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -1.0), course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.0)),
    targets: [
        Vessel(name: "anchored", start_nm: (0.0, 1.0), course_deg: 0.0, speed_kn: 0.0, length_m: 100.0),
    ],
)"#,
    )
    .unwrap();
    for command in ["check", "plan", "simulate"] {
        let output = vorrt(&[command, path_str(&path)]);
        let message = stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{command}: {message}");
        assert!(
            message.contains("anchored.ron")
                && message.contains("targets[0] \"anchored\".start_nm")
                && message.contains("ownship.goal_nm")
                && message.contains("300 m"),
            "{command}: {message}"
        );
    }
}

#[test]
fn plan_without_a_safe_path_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("blocked.ron");
    // A vessel bound for ownship's goal, there long before ownship and
    // stopping on it: the goal itself breaks d_th.
    std::fs::write(
        &path,
        r#"Scenario(
    name: "blocked",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -1.0), course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.0)),
    targets: [
        Vessel(name: "arriving", start_nm: (0.0, 1.5), course_deg: 180.0, speed_kn: 12.0,
               length_m: 100.0, goal_nm: (0.0, 1.0)),
    ],
)"#,
    )
    .unwrap();
    let output = vorrt(&["plan", path_str(&path)]);
    let message = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "stderr: {message}");
    assert!(
        message.contains("no safe path") && message.contains("blocked.ron"),
        "{message}"
    );
    assert!(stdout(&output).is_empty());
    assert!(!message.contains("panicked"));
}

/// A generated encounter (`vorrt batch --generate open-sea --targets 2
/// --behaviour sudden-turn --count 12 --seed 3`, run 6) that ownship sails
/// to its goal safely but not compliantly: both targets turn unannounced,
/// and ownship, stand-on for TS1, changes course and turns to port.
const SAFE_WITH_FINDINGS: &str = r#"Scenario(
    name: "safe with findings",
    ownship: Vessel(name: "ownship", start_nm: (0.0, 0.0), course_deg: 0.0, speed_kn: 10.2,
                    length_m: 100.0, goal_nm: (0.0, 9.22)),
    targets: [
        Vessel(name: "TS1", start_nm: (0.3245, 6.5451), course_deg: 183.70944596246204,
               speed_kn: 14.29, length_m: 182.0, goal_nm: (-1.772, -25.792),
               behaviour: SuddenTurn(at_s: 309.0, turn_deg: -78.0)),
        Vessel(name: "TS2", start_nm: (-1.5938000000000003, 0.591), course_deg: 59.58948456918453,
               speed_kn: 13.86, length_m: 245.0, goal_nm: (23.947, 15.582),
               behaviour: SuddenTurn(at_s: 362.0, turn_deg: -85.0)),
    ],
    planner: Planner(nodes_per_phase: 854),
    seed: 258636510711751834,
)"#;

#[test]
fn simulate_exits_1_on_a_colregs_finding_as_judge_does() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("findings.ron");
    std::fs::write(&path, SAFE_WITH_FINDINGS).unwrap();
    let out = dir.path().join("run");
    let output = vorrt(&["simulate", path_str(&path), "--out", path_str(&out)]);
    let report: Report =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    // The premise: a success with a finding.
    assert!(
        report.reached_goal_safely && !report.compliant,
        "{}",
        stdout(&output)
    );
    assert_eq!(output.status.code(), Some(1), "stderr: {}", stderr(&output));
    assert!(
        stderr(&output).contains("did not obey COLREGs"),
        "{}",
        stderr(&output)
    );
    let judged = vorrt(&[
        "judge",
        path_str(&out.join("trajectory.csv")),
        "--scenario",
        path_str(&path),
        "--out",
        path_str(&dir.path().join("judged")),
    ]);
    assert_eq!(judged.status.code(), Some(1), "stderr: {}", stderr(&judged));
}

#[test]
fn usage_errors_exit_2_without_panicking() {
    for args in [
        &["simulate"][..],
        &["frobnicate"],
        &["simulate", "x.ron", "--seed", "minus-one"],
        &["check"],
        &[],
    ] {
        let output = vorrt(args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "vorrt {args:?}: {}",
            stderr(&output)
        );
        assert!(!stderr(&output).contains("panicked"));
    }
}

#[test]
fn help_documents_the_exit_codes() {
    let output = vorrt(&["--help"]);
    assert_eq!(output.status.code(), Some(0));
    let help = stdout(&output);
    for expected in [
        "simulate",
        "plan",
        "check",
        "demo",
        "Exit codes",
        "0  success",
        "1  ",
        "2  bad input",
    ] {
        assert!(
            help.contains(expected),
            "{expected:?} not in --help: {help}"
        );
    }
    let output = vorrt(&["simulate", "--help"]);
    assert_eq!(output.status.code(), Some(0));
    assert!(stdout(&output).contains("--seed") && stdout(&output).contains("--out"));
}

#[test]
fn simulate_into_an_unwritable_place_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let blocker = dir.path().join("a-file");
    std::fs::write(&blocker, "not a folder").unwrap();
    let output = vorrt(&[
        "simulate",
        path_str(&crossing()),
        "--out",
        path_str(&blocker.join("run")),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(!stderr(&output).contains("panicked"));
}

#[test]
fn demo_writes_an_index_of_every_scenario() {
    let dir = tempfile::tempdir().unwrap();
    let fixtures = dir.path().join("fixtures");
    std::fs::create_dir_all(fixtures.join("paper")).unwrap();
    std::fs::write(fixtures.join("paper/small.ron"), SMALL).unwrap();
    std::fs::copy(crossing(), fixtures.join("paper/crossing.ron")).unwrap();
    let out = dir.path().join("demo");
    let output = vorrt(&[
        "demo",
        "--fixtures",
        path_str(&fixtures),
        "--out",
        path_str(&out),
        "--only",
        "small",
    ]);
    assert_eq!(
        output.status.code(),
        Some(0),
        "stdout: {}\nstderr: {}",
        stdout(&output),
        stderr(&output)
    );
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(index.starts_with("<!DOCTYPE html>") && index.contains("</html>"));
    assert!(index.contains("small crossing"));
    assert!(index.contains("<th>time overhead</th>"), "{index}");
    assert!(
        index.contains("min straight at the service speed"),
        "{index}"
    );
    assert!(
        stdout(&output).contains("overhead path"),
        "{}",
        stdout(&output)
    );
    assert!(!index.contains("<made>"), "descriptions are escaped");
    assert!(
        !index.contains(">crossing<"),
        "--only left the other scenario out"
    );
    for file in [
        "paper/small/trajectories.png",
        "paper/small/distance.png",
        "paper/small/report.json",
    ] {
        assert!(index.contains(file), "index does not link {file}");
        assert!(out.join(file).is_file(), "{file} not written");
    }
    assert!(index.contains("<img src=\"paper/small/trajectories.png\""));

    let output = vorrt(&[
        "demo",
        "--fixtures",
        path_str(&fixtures),
        "--out",
        path_str(&out),
        "--only",
        "nothing",
    ]);
    assert_eq!(output.status.code(), Some(2));
    let output = vorrt(&[
        "demo",
        "--fixtures",
        "/nonexistent/fixtures",
        "--out",
        path_str(&out),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(!stderr(&output).contains("panicked"));
}
