//! Robustness (issue 7): any [`PlannerConfig`] validates or is refused with
//! [`PlannerError::InvalidConfig`] naming its field; any [`PlanningProblem`]
//! (NaN positions, zero or negative speeds, huge target counts) planned with
//! a tiny time budget returns — a plan or a typed error — quickly and without
//! panicking.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use glam::DVec2;
use proptest::prelude::*;
use std::time::Instant;
use vorrt_colregs::VesselState;
use vorrt_jfs::TargetState;
use vorrt_planner::{NearestIndex, Planner, PlannerConfig, PlannerError, PlanningProblem};

/// Every field `PlannerConfig::validate` may name.
const FIELDS: [&str; 12] = [
    "step_m",
    "clearance_m",
    "goal_tolerance_m",
    "lookahead_s",
    "sampling_margin_m",
    "goal_bias",
    "phase_two_goal_bias",
    "max_turn_per_step_rad",
    "nodes_per_phase",
    "samples_per_phase",
    "max_restarts",
    "time_budget_s",
];

/// Any f64, weighted toward the values that break arithmetic.
fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(f64::MAX),
        Just(f64::MIN),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        Just(1e300),
        -1.0e6..1.0e6,
        -10.0..10.0f64,
        any::<f64>(),
    ]
}

fn any_count() -> impl Strategy<Value = usize> {
    prop_oneof![
        Just(0usize),
        Just(usize::MAX),
        0usize..10,
        0usize..1_000_000,
        any::<usize>()
    ]
}

fn any_config() -> impl Strategy<Value = PlannerConfig> {
    (
        (any_f64(), any_f64(), any_f64(), any_f64(), any_f64()),
        (any_f64(), any_f64(), any_f64()),
        (any_count(), any_count(), any_count()),
        (proptest::option::of(any_f64()), any::<bool>()),
    )
        .prop_map(
            |(
                (step, clearance, tolerance, bias, bias2),
                (turn, margin, lookahead),
                (nodes, samples, restarts),
                (budget, rtree),
            )| PlannerConfig {
                step_m: step,
                clearance_m: clearance,
                goal_tolerance_m: tolerance,
                goal_bias: bias,
                phase_two_goal_bias: bias2,
                nodes_per_phase: nodes,
                samples_per_phase: samples,
                max_restarts: restarts,
                max_turn_per_step_rad: turn,
                sampling_margin_m: margin,
                lookahead_s: lookahead,
                time_budget_s: budget,
                nearest_index: if rtree {
                    NearestIndex::RTree
                } else {
                    NearestIndex::Linear
                },
                ..PlannerConfig::default()
            },
        )
}

/// A plausible number most of the time, anything otherwise.
fn mostly(low: f64, high: f64) -> impl Strategy<Value = f64> {
    prop_oneof![4 => low..high, 1 => any_f64()]
}

fn any_vessel() -> impl Strategy<Value = VesselState> {
    (
        mostly(-5000.0, 5000.0),
        mostly(-5000.0, 5000.0),
        mostly(-7.0, 7.0),
        mostly(-1.0, 12.0),
        mostly(-10.0, 300.0),
    )
        .prop_map(|(x, y, course, speed, length)| {
            VesselState::new(DVec2::new(x, y), course, speed, length)
        })
}

fn any_target() -> impl Strategy<Value = TargetState> {
    (
        any_vessel(),
        proptest::option::of((mostly(-5000.0, 5000.0), mostly(-5000.0, 5000.0))),
    )
        .prop_map(|(vessel, goal)| match goal {
            Some((x, y)) => TargetState::toward_goal(vessel, DVec2::new(x, y)),
            None => TargetState::constant_velocity(vessel),
        })
}

fn any_problem() -> impl Strategy<Value = PlanningProblem> {
    (
        mostly(0.0, 1000.0),
        any_vessel(),
        (mostly(-8000.0, 8000.0), mostly(-8000.0, 8000.0)),
        proptest::collection::vec(any_target(), 0..6),
        prop_oneof![8 => Just(0usize), 1 => Just(1), 1 => Just(3)],
    )
        .prop_map(|(start, ownship, (gx, gy), targets, encounters)| {
            let mut problem = PlanningProblem::new(ownship, DVec2::new(gx, gy), targets);
            problem.start_time_s = start;
            problem.encounters = vec![None; encounters];
            problem
        })
}

/// A small, valid configuration with a tiny wall-clock budget.
fn tiny_config(nodes: usize, rtree: bool) -> PlannerConfig {
    PlannerConfig {
        nodes_per_phase: nodes,
        samples_per_phase: nodes * 10,
        max_restarts: 1,
        time_budget_s: Some(0.05),
        nearest_index: if rtree {
            NearestIndex::RTree
        } else {
            NearestIndex::Linear
        },
        ..PlannerConfig::default()
    }
}

fn assert_returns_quickly(planner: &mut Planner, problem: &PlanningProblem, seed: u64) {
    let started = Instant::now();
    let result = planner.plan(problem, seed);
    let elapsed = started.elapsed().as_secs_f64();
    // The budget is 0.05 s; allow for one slow sample in a debug build on a
    // shared machine.
    assert!(elapsed < 5.0, "plan took {elapsed} s");
    match result {
        Ok(plan) => {
            assert!(problem.validate().is_ok());
            assert!(!plan.waypoints.is_empty());
            for waypoint in &plan.waypoints {
                assert!(waypoint.position_m.is_finite(), "{waypoint:?}");
            }
        }
        Err(PlannerError::InvalidProblem { field, .. }) => assert!(!field.is_empty()),
        Err(
            PlannerError::NoSafePath { .. }
            | PlannerError::NodeBudgetTooSmall { .. }
            | PlannerError::BudgetExhausted { .. },
        ) => {
            assert!(problem.validate().is_ok());
        }
        Err(other) => panic!("unexpected error {other}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn any_config_validates_or_names_its_field(config in any_config()) {
        match config.validate() {
            Ok(()) => {
                prop_assert!(Planner::new(config).is_ok());
            }
            Err(PlannerError::InvalidConfig { field, .. }) => {
                prop_assert!(FIELDS.contains(&field), "unknown field {field}");
                let message = PlannerError::InvalidConfig {
                    field,
                    value: 0.0,
                    expected: "",
                }
                .to_string();
                prop_assert!(message.contains(field));
                prop_assert!(Planner::new(config).is_err());
            }
            Err(other) => prop_assert!(false, "unexpected error {other}"),
        }
    }

    #[test]
    fn any_problem_validates_or_names_its_field(problem in any_problem()) {
        match problem.validate() {
            Ok(()) => {}
            Err(PlannerError::InvalidProblem { field, .. }) => prop_assert!(!field.is_empty()),
            Err(other) => prop_assert!(false, "unexpected error {other}"),
        }
    }
}

proptest! {
    // Planning is the expensive part: fewer cases, each bounded by the budget.
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn any_problem_plans_or_errs_within_the_budget(
        problem in any_problem(),
        nodes in 1usize..60,
        rtree in any::<bool>(),
        seed in any::<u64>(),
    ) {
        let mut planner = Planner::new(tiny_config(nodes, rtree)).unwrap();
        assert_returns_quickly(&mut planner, &problem, seed);
        // The same planner is reused: no state from a failed plan leaks.
        assert_returns_quickly(&mut planner, &problem, seed.wrapping_add(1));
    }
}

#[test]
fn many_targets_plan_within_the_budget() {
    let own = VesselState::new(DVec2::new(0.0, -3000.0), 0.0, 6.0, 100.0);
    #[expect(
        clippy::cast_precision_loss,
        reason = "a target's index, below MAX_TARGETS"
    )]
    let targets: Vec<TargetState> = (0..vorrt_planner::problem::MAX_TARGETS)
        .map(|index| {
            let angle = index as f64 * 0.37;
            let position = DVec2::new(angle.cos(), angle.sin()) * (1000.0 + index as f64 * 5.0);
            TargetState::constant_velocity(VesselState::new(position, angle, 4.0, 50.0))
        })
        .collect();
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 3000.0), targets.clone());
    let mut planner = Planner::new(tiny_config(50, false)).unwrap();
    assert_returns_quickly(&mut planner, &problem, 7);

    let mut too_many = targets;
    too_many.push(too_many[0]);
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 3000.0), too_many);
    match planner.plan(&problem, 7) {
        Err(PlannerError::InvalidProblem { field, .. }) => assert_eq!(field, "targets"),
        other => panic!("expected InvalidProblem, got {other:?}"),
    }
}

#[test]
fn largest_configuration_with_a_budget_returns() {
    // The largest node and sample counts the configuration accepts, with
    // a budget: the tree is not allocated for all of them up front.
    let config = PlannerConfig {
        nodes_per_phase: vorrt_planner::config::MAX_NODES_PER_PHASE,
        samples_per_phase: vorrt_planner::config::MAX_SAMPLES_PER_PHASE,
        max_restarts: vorrt_planner::config::MAX_RESTARTS,
        time_budget_s: Some(0.1),
        ..PlannerConfig::default()
    };
    let mut planner = Planner::new(config).unwrap();
    let own = VesselState::new(DVec2::new(0.0, -3000.0), 0.0, 6.0, 100.0);
    let targets = (0..8)
        .map(|index| {
            TargetState::constant_velocity(VesselState::new(
                DVec2::new(300.0 * f64::from(index) - 1200.0, 0.0),
                0.0,
                0.0,
                50.0,
            ))
        })
        .collect();
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 3000.0), targets);
    assert_returns_quickly(&mut planner, &problem, 1);
}

/// A target's hold before it steers for its goal must be a finite,
/// non-negative number of seconds: NaN, infinite or negative is named.
#[test]
fn a_bad_hold_is_refused_with_its_field() {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let target = VesselState::new(DVec2::new(1000.0, 2000.0), 4.0, 5.0, 50.0);
    let mut planner = Planner::new(tiny_config(50, false)).unwrap();
    for hold_s in [f64::NAN, f64::INFINITY, -5.0] {
        let mut holding =
            TargetState::holding_course_then_toward_goal(target, DVec2::new(0.0, 5000.0), 60.0);
        holding.holds_course_for_s = Some(hold_s);
        let problem = PlanningProblem::new(own, DVec2::new(0.0, 3000.0), vec![holding]);
        match planner.plan(&problem, 7) {
            Err(PlannerError::InvalidProblem { field, .. }) => {
                assert_eq!(field, "targets[0].holds_course_for_s");
            }
            other => panic!("expected InvalidProblem for {hold_s}, got {other:?}"),
        }
    }
    // A valid hold plans.
    let holding =
        TargetState::holding_course_then_toward_goal(target, DVec2::new(0.0, 5000.0), 60.0);
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 3000.0), vec![holding]);
    assert!(planner.plan(&problem, 7).is_ok());
}

#[test]
fn a_route_hundreds_of_kilometres_long_ends_within_the_budget() {
    // Like a generated case that once ran for over half an hour in a debug
    // build: a 775 km route whose goal a vessel lies on. Every manoeuvre of
    // the search before any tree (one, then two alterations, each leg cut
    // into `d'` pieces) is refused only at its end, and that search draws no
    // sample, so the budget read between samples never stopped it; it now
    // ends at the deadline too.
    let own = VesselState::new(DVec2::new(774_754.8, 0.0), 5.257, 8.67, 131.3);
    let target = TargetState::constant_velocity(VesselState::new(DVec2::ZERO, 0.0, 0.0, 120.0));
    let problem = PlanningProblem::new(own, DVec2::ZERO, vec![target]);
    for nodes in [5, 40] {
        let mut planner = Planner::new(tiny_config(nodes, false)).unwrap();
        assert_returns_quickly(&mut planner, &problem, 444_243);
    }
}
