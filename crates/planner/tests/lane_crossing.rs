//! The gap search of a lane crossing (rule 10(c), decisions 30 and 47): on
//! a synthetic westbound stream, ownship heading north across the lane
//! slows and crosses square through a gap where there is one, ahead of the
//! vessels that come later, with no path overhead; where the stream leaves
//! no gap it passes astern of every vessel.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use vorrt_planner::colregs::VesselState;
use vorrt_planner::colregs::rule10::{Scheme, TrafficLane};
use vorrt_planner::glam::DVec2;
use vorrt_planner::jfs::TargetState;
use vorrt_planner::scheme::SchemeConstraint;
use vorrt_planner::{Plan, Planner, PlannerConfig, PlanningProblem};

/// Ownship's service speed, m/s (12.4 kn, as a generated crossing's).
const OWN_SPEED_MPS: f64 = 6.38;
/// The stream's speed, m/s (about 9.7 kn), westbound.
const STREAM_SPEED_MPS: f64 = 5.0;
/// The stream's track, north metres: in the south half of the lane, so that
/// a vessel slowed short of it is still within 1 nm of the stream's closest
/// approach and 2.5 nm of its range (a reduction must count as the action).
const STREAM_NORTH_M: f64 = -600.0;
/// Ownship starts 3 nm south of the lane's centre line, its goal 3 nm north.
const START_M: DVec2 = DVec2::new(0.0, -5556.0);
const GOAL_M: DVec2 = DVec2::new(0.0, 5556.0);

/// The plan of ownship crossing a 1 nm westbound lane on y = 0 through a
/// stream of vessels on [`STREAM_NORTH_M`] that pass x = 0 at `passing_s`
/// (seconds from now),
/// with the lane's constraint, and the stream.
fn cross(passing_s: &[f64]) -> (Plan, Vec<TargetState>) {
    let own = VesselState::new(START_M, 0.0, OWN_SPEED_MPS, 100.0);
    let targets: Vec<TargetState> = passing_s
        .iter()
        .map(|time_s| {
            TargetState::constant_velocity(VesselState::new(
                DVec2::new(STREAM_SPEED_MPS * time_s, STREAM_NORTH_M),
                270f64.to_radians(),
                STREAM_SPEED_MPS,
                150.0,
            ))
        })
        .collect();
    let lane = TrafficLane {
        from_m: DVec2::new(30_000.0, 0.0),
        to_m: DVec2::new(-30_000.0, 0.0),
        width_m: 1852.0,
    };
    let scheme = Scheme {
        lanes: vec![lane],
        ..Scheme::default()
    };
    let constraint = SchemeConstraint::new(scheme, START_M, GOAL_M);
    let config = PlannerConfig {
        clearance_m: 100.0,
        // As a generated crossing's (`vorrt generate tss`).
        nodes_per_phase: 556,
        ..PlannerConfig::default()
    };
    let problem = PlanningProblem::new(own, GOAL_M, targets.clone());
    let mut planner = Planner::with_constraint(config, constraint).unwrap();
    (planner.plan(&problem, 11).unwrap(), targets)
}

/// When and where (east, metres) the plan first crosses the stream's track,
/// sampled every second.
fn crossing_point(plan: &Plan) -> (f64, f64) {
    let mut time_s = 0.0;
    while time_s <= plan.duration_s() {
        let position_m = plan.pose_at(time_s).unwrap().position_m;
        if position_m.y >= STREAM_NORTH_M {
            return (time_s, position_m.x);
        }
        time_s += 1.0;
    }
    panic!("the plan never crosses the stream");
}

/// How many vessels of the stream are still east of (upstream of) ownship
/// as it crosses their line: vessels it crosses ahead of.
fn crossed_ahead_of(plan: &Plan, targets: &[TargetState]) -> usize {
    let (time_s, east_m) = crossing_point(plan);
    targets
        .iter()
        .filter(|target| target.track().position_at(time_s).x > east_m)
        .count()
}

#[test]
fn a_crossing_slows_and_crosses_through_a_gap_in_the_stream() {
    // Two vessels 1500 m apart passing ahead of ownship's track at 700 s
    // and 1000 s (ownship at service speed reaches the stream at about
    // 780 s), the next 33 minutes later: a gap a mariner slows down for,
    // waiting near the stream while the second comes on, rather than
    // turning away (without the reduction counted as the action, decision
    // 47, the plan turned, 13 % longer).
    let (plan, targets) = cross(&[700.0, 1000.0, 3000.0]);
    assert_eq!(crossed_ahead_of(&plan, &targets), 1, "{plan:?}");
    // Through the gap on the course to the goal, square across the lane:
    // no path overhead, the gap bought with time.
    let straight_m = START_M.distance(GOAL_M);
    assert!(plan.length_m() < straight_m * 1.01, "{}", plan.length_m());
    let (time_s, east_m) = crossing_point(&plan);
    assert!(east_m.abs() < 1.0, "{east_m}");
    assert!(time_s > 1000.0, "{time_s}");
    let slowest_mps = plan
        .waypoint_speeds_mps()
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    assert!(slowest_mps <= 0.5 * OWN_SPEED_MPS, "{slowest_mps}");
}

#[test]
fn a_stream_without_a_gap_is_passed_astern() {
    // A vessel every 1500 m, passing x = 0 every 300 s: no gap a give-way
    // vessel may cross through (crossing ahead of a vessel within 1 nm of
    // her bow is rule 15's finding), so ownship lets the whole stream pass.
    let passing_s: Vec<f64> = (0..3)
        .map(|index| 700.0 + 300.0 * f64::from(index))
        .collect();
    let (plan, targets) = cross(&passing_s);
    assert_eq!(crossed_ahead_of(&plan, &targets), 0, "{plan:?}");
}
