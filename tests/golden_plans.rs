//! Golden outputs of the planner: for each paper fixture, a few Imazu cases
//! and seeds 1 to 3, the plan's waypoints (position, time, course) must equal
//! the ones recorded in `tests/golden/plans.ron` bit for bit, so that an
//! optimisation of the planner cannot change what it plans unnoticed.
//!
//! After a change that is meant to alter the plans, record them again with
//! `VORRT_BLESS=1 cargo test --test golden_plans` and commit the file with
//! the change (see `docs/performance.md`).

use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use vorrt::planner::{Planner, PlannerConfig, PlannerError, Turning};
use vorrt::scenarios::fixtures;

/// The fixtures planned, as names for `vorrt::scenarios::fixtures::find`.
const FIXTURES: [&str; 10] = [
    "paper/crossing",
    "paper/head_on",
    "paper/overtaking",
    "paper/multi_vessel",
    "paper/tss",
    "imazu/imazu_01",
    "imazu/imazu_05",
    "imazu/imazu_10",
    "imazu/imazu_14",
    "imazu/imazu_22",
];

/// The seeds each fixture is planned with.
const SEEDS: [u64; 3] = [1, 2, 3];

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct GoldenFile {
    note: String,
    cases: Vec<GoldenCase>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct GoldenCase {
    fixture: String,
    seed: u64,
    outcome: Outcome,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
enum Outcome {
    /// The waypoints of the plan, in order.
    Plan(Vec<GoldenWaypoint>),
    /// The planner found no plan; the error's kind.
    Failed(String),
}

/// One waypoint. RON writes each `f64` in the shortest decimal form that
/// reads back to the same value, so the file is exact; the test compares the
/// values' bit patterns (`f64::to_bits`), and checks that the file format
/// round-trips them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct GoldenWaypoint {
    east_m: f64,
    north_m: f64,
    time_s: f64,
    course_rad: f64,
}

impl GoldenWaypoint {
    fn bits(&self) -> [u64; 4] {
        [
            self.east_m.to_bits(),
            self.north_m.to_bits(),
            self.time_s.to_bits(),
            self.course_rad.to_bits(),
        ]
    }
}

fn golden_path() -> PathBuf {
    [env!("CARGO_MANIFEST_DIR"), "tests", "golden", "plans.ron"]
        .iter()
        .collect()
}

fn error_kind(error: &PlannerError) -> String {
    match error {
        PlannerError::InvalidConfig { .. } => "InvalidConfig",
        PlannerError::InvalidRules(_) => "InvalidRules",
        PlannerError::InvalidProblem { .. } => "InvalidProblem",
        PlannerError::NoSafePath { .. } => "NoSafePath",
        PlannerError::NodeBudgetTooSmall { .. } => "NodeBudgetTooSmall",
        PlannerError::BudgetExhausted { .. } => "BudgetExhausted",
    }
    .to_owned()
}

fn compute() -> Vec<GoldenCase> {
    let mut cases = Vec::new();
    for fixture in FIXTURES {
        let scenario = fixtures::find(fixture)
            .unwrap_or_else(|| panic!("{fixture}: not bundled"))
            .load()
            .unwrap_or_else(|error| panic!("{fixture}: {error}"));
        // The tree's own branch, with the paper's instantaneous turns: this is
        // the search the golden outputs were recorded from. The default,
        // rate-limited plans simplify this branch (`vorrt_planner::simplify`)
        // and are checked by the planner's property tests.
        let config = PlannerConfig {
            turning: Turning::Instant,
            ..scenario
                .planner_config()
                .unwrap_or_else(|error| panic!("{fixture}: {error}"))
        };
        let problem = scenario.planning_problem();
        for seed in SEEDS {
            // The scenario's traffic separation scheme, as the closed loop
            // keeps it (an empty one, refusing nothing, off a scheme).
            let constraint = vorrt::scenarios::scenario_constraint(&scenario);
            let mut planner =
                Planner::with_constraint(config, constraint).expect("valid configuration");
            let outcome = match planner.plan(&problem, seed) {
                Ok(plan) => Outcome::Plan(
                    plan.waypoints
                        .iter()
                        .map(|waypoint| GoldenWaypoint {
                            east_m: waypoint.position_m.x,
                            north_m: waypoint.position_m.y,
                            time_s: waypoint.time_s,
                            course_rad: waypoint.course_rad,
                        })
                        .collect(),
                ),
                Err(error) => Outcome::Failed(error_kind(&error)),
            };
            cases.push(GoldenCase {
                fixture: fixture.to_owned(),
                seed,
                outcome,
            });
        }
    }
    cases
}

/// Where two outcomes first differ, in words.
fn first_difference(expected: &Outcome, actual: &Outcome) -> String {
    match (expected, actual) {
        (Outcome::Plan(want), Outcome::Plan(got)) => {
            for (index, (w, g)) in want.iter().zip(got).enumerate() {
                if w.bits() != g.bits() {
                    return format!(
                        "waypoint {index}: recorded {:?}, planned {:?}",
                        (w.east_m, w.north_m, w.time_s, w.course_rad),
                        (g.east_m, g.north_m, g.time_s, g.course_rad)
                    );
                }
            }
            format!("{} waypoints recorded, {} planned", want.len(), got.len())
        }
        _ => format!("recorded {expected:?}, planned {actual:?}"),
    }
}

#[test]
fn plans_match_the_recorded_golden_outputs() {
    let cases = compute();
    let path = golden_path();
    if std::env::var_os("VORRT_BLESS").is_some_and(|value| !value.is_empty() && value != "0") {
        let file = GoldenFile {
            note: "Planner outputs recorded by tests/golden_plans.rs; regenerate with \
                   `VORRT_BLESS=1 cargo test --test golden_plans`. Every f64 is written \
                   in the shortest form that reads back to the same bits."
                .to_owned(),
            cases,
        };
        let text = serialise(&file);
        std::fs::create_dir_all(path.parent().expect("parent")).expect("create tests/golden");
        std::fs::write(&path, text + "\n").expect("write golden plans");
        return;
    }
    let text = std::fs::read_to_string(&path).unwrap_or_else(|error| {
        panic!(
            "{}: {error}; record it with `VORRT_BLESS=1 cargo test --test golden_plans`",
            path.display()
        )
    });
    let recorded: GoldenFile = ron::from_str(&text).expect("parse golden plans");
    assert_eq!(
        recorded.cases.len(),
        cases.len(),
        "the recorded file holds another set of cases; bless it again"
    );
    let mut differences = Vec::new();
    for (expected, actual) in recorded.cases.iter().zip(&cases) {
        assert_eq!(
            (&expected.fixture, expected.seed),
            (&actual.fixture, actual.seed),
            "the recorded file holds another set of cases; bless it again"
        );
        let same = match (&expected.outcome, &actual.outcome) {
            (Outcome::Plan(want), Outcome::Plan(got)) => {
                want.len() == got.len() && want.iter().zip(got).all(|(w, g)| w.bits() == g.bits())
            }
            (want, got) => want == got,
        };
        if !same {
            differences.push(format!(
                "{} seed {}: {}",
                expected.fixture,
                expected.seed,
                first_difference(&expected.outcome, &actual.outcome)
            ));
        }
    }
    assert!(
        differences.is_empty(),
        "the planner's output changed for {} of {} cases:\n{}\n\
         If the change is intended, run `VORRT_BLESS=1 cargo test --test golden_plans`.",
        differences.len(),
        cases.len(),
        differences.join("\n")
    );
}

fn serialise(file: &GoldenFile) -> String {
    ron::ser::to_string_pretty(
        file,
        ron::ser::PrettyConfig::new()
            .depth_limit(4)
            .indentor("  ".to_owned()),
    )
    .expect("serialise golden plans")
}

/// The file format keeps every bit: planned waypoints written as RON and
/// read back have the same bit patterns.
#[test]
fn the_file_format_round_trips_every_bit() {
    let cases = compute();
    let file = GoldenFile {
        note: String::new(),
        cases,
    };
    let read: GoldenFile = ron::from_str(&serialise(&file)).expect("parse");
    for (written, read) in file.cases.iter().zip(&read.cases) {
        match (&written.outcome, &read.outcome) {
            (Outcome::Plan(want), Outcome::Plan(got)) => {
                assert_eq!(want.len(), got.len());
                for (w, g) in want.iter().zip(got) {
                    assert_eq!(
                        w.bits(),
                        g.bits(),
                        "{} seed {}",
                        written.fixture,
                        written.seed
                    );
                }
            }
            (want, got) => assert_eq!(want, got),
        }
    }
}
