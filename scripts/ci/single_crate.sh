#!/usr/bin/env bash
# Checks that one dependency is enough: a scratch project outside the
# workspace whose only dependency is vorrt-planner (a path dependency on this
# checkout) plans a crossing through `vorrt_planner::...` paths alone and
# checks that the plan ends on the goal. The workspace's Cargo.lock is copied
# in so that the scratch build uses the versions the workspace is tested
# with (cargo then drops the entries it does not need).
#   scripts/ci/single_crate.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

mkdir -p "$scratch/src"
cat >"$scratch/Cargo.toml" <<EOF
[package]
name = "vorrt-single-crate-check"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
vorrt-planner = { path = "$root/crates/planner" }

# A workspace of its own, so that no manifest above the scratch folder claims it.
[workspace]
EOF
cp "$root/Cargo.lock" "$scratch/Cargo.lock"

cat >"$scratch/src/main.rs" <<'EOF'
//! A crossing planned with vorrt-planner as the only dependency.

use vorrt_planner::colregs::{Encounter, classify};
use vorrt_planner::geometry::angle::signed_turn;
use vorrt_planner::glam::DVec2;
use vorrt_planner::{Planner, PlannerConfig, PlanningProblem, RuleParameters, TargetState, VesselState};

fn main() {
    // Ownship heads north at 6 m/s for a goal 8 km ahead; the target, 4 km
    // east and 4 km north, heads west at 6 m/s: both reach (0, 4000) together.
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let target = TargetState::toward_goal(
        VesselState::new(DVec2::new(4000.0, 4000.0), 270f64.to_radians(), 6.0, 80.0),
        DVec2::new(-4000.0, 4000.0),
    );
    assert_eq!(
        classify(&own, &target.vessel, &RuleParameters::default()),
        Encounter::CrossingGiveWay
    );
    let goal_m = DVec2::new(0.0, 8000.0);
    let problem = PlanningProblem::new(own, goal_m, vec![target]);
    let config = PlannerConfig {
        nodes_per_phase: 400,
        ..PlannerConfig::default()
    };
    let plan = Planner::new(config)
        .expect("valid configuration")
        .plan(&problem, 1)
        .expect("a safe plan");
    let last = plan.waypoints.last().expect("waypoints");
    assert_eq!(last.position_m, goal_m, "the plan ends on the goal");
    // The give-way vessel's first alteration is to starboard (rule 15-16).
    let first_turn = plan
        .waypoints
        .iter()
        .skip(1)
        .map(|waypoint| waypoint.course_rad)
        .find(|course| signed_turn(0.0, *course).abs() > 1e-9)
        .expect("an alteration");
    assert!(signed_turn(0.0, first_turn) > 0.0, "first turn to starboard");
    println!(
        "single-crate check: {} waypoints, goal reached at {:.0} s",
        plan.waypoints.len(),
        last.time_s
    );
}
EOF

# A target folder of its own under the checkout's target/, kept between runs
# (the scratch project is deleted) and apart from the workspace's builds.
CARGO_TARGET_DIR="$root/target/single-crate" \
    cargo run --quiet --manifest-path "$scratch/Cargo.toml"
