//! The memo a leg's check keeps from piece to piece (decision 54): the
//! targets no risk can reach while ownship and they hold their velocities
//! are not judged again on the same stretch of their tracks. With it and
//! without it (`SafetyChecker::without_leg_memo`), and with each target's
//! velocities worked out once (`SafetyChecker::with_state_velocities`) or
//! not, every leg gets the same
//! verdict and leaves the same encounters and alterations, on generated
//! encounters: targets near ownship on any course, some holding their course
//! for a while before they turn for a goal (a track of two stretches), legs
//! that turn, slow down and run straight.
//!
//! The case count is kept small (64) so the debug-build test stays quick;
//! set `VORRT_HEAVY_TESTS=1` for a heavier run (1024 cases).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::VesselState;
use vorrt_jfs::{Leg, LinearTrack, Pose, TargetState};
use vorrt_planner::safety::{SafetyChecker, StateVelocities};
use vorrt_planner::validity::{EncounterState, MotionValidator};
use vorrt_planner::{Compliance, PlannerConfig};

fn cases() -> u32 {
    if std::env::var_os("VORRT_HEAVY_TESTS").is_some() {
        1024
    } else {
        64
    }
}

fn own() -> VesselState {
    VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0)
}

/// A target 1 to 14 km from ownship (within MTD or just beyond it), at 2 to
/// 12 m/s on any course; some bound for a goal, some holding their course
/// for up to 20 minutes first.
fn target() -> impl Strategy<Value = TargetState> {
    (
        1_000.0f64..14_000.0,
        0.0f64..360.0,
        0.0f64..360.0,
        2.0f64..12.0,
        proptest::option::of((-90.0f64..90.0, 2_000.0f64..20_000.0)),
        prop_oneof![Just(0.0), 0.0f64..1_200.0],
    )
        .prop_map(
            |(range_m, bearing_deg, course_deg, speed_mps, goal, hold_s)| {
                let bearing = bearing_deg.to_radians();
                let start = DVec2::new(bearing.sin(), bearing.cos()) * range_m;
                let course = course_deg.to_radians();
                let vessel = VesselState::new(start, course, speed_mps, 150.0);
                match goal {
                    Some((off_deg, distance_m)) => {
                        let towards = course + off_deg.to_radians();
                        let goal_m = start + DVec2::new(towards.sin(), towards.cos()) * distance_m;
                        TargetState::holding_course_then_toward_goal(vessel, goal_m, hold_s)
                    }
                    None => TargetState::constant_velocity(vessel),
                }
            },
        )
}

/// A leg from the origin heading north: a turn of up to 90° either way on a
/// 500 m radius (or at once), then up to 8 km straight, maybe slowing down.
fn leg() -> impl Strategy<Value = Leg> {
    (
        -90.0f64..90.0,
        prop_oneof![Just(0.0), Just(500.0)],
        0.0f64..8_000.0,
        prop_oneof![Just(6.0), Just(3.0)],
    )
        .prop_map(|(turn_deg, radius_m, straight_m, speed_mps)| {
            Leg::turning_onto(
                Pose {
                    position_m: DVec2::ZERO,
                    course_rad: 0.0,
                },
                turn_deg.to_radians(),
                radius_m,
                speed_mps,
                straight_m,
            )
            .from_speed(6.0, 0.05)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn the_memo_changes_no_verdict_and_no_encounter(
        targets in proptest::collection::vec(target(), 1..12),
        legs in proptest::collection::vec(leg(), 1..3),
        start_elapsed_s in 0.0f64..600.0,
        (clearance_m, compliance) in prop_oneof![
            Just((200.0, Compliance::Full)),
            Just((20.0, Compliance::SafetyOnly)),
        ],
    ) {
        // A small d_th and only the safety checks as well, so that most legs
        // pass and their encounters are compared (the latches are stepped
        // at every compliance).
        let config = PlannerConfig { clearance_m, compliance, ..PlannerConfig::default() };
        let goal = DVec2::new(0.0, 30_000.0);
        let tracks: Vec<LinearTrack> = targets.iter().map(TargetState::track).collect();
        // With the memo and each target's velocities worked out once, and
        // with neither.
        let velocities: Vec<StateVelocities> = tracks.iter().map(StateVelocities::of).collect();
        let with = SafetyChecker::new(&config, &tracks, own(), goal, 0.0)
            .with_state_velocities(&velocities);
        prop_assert!(with.leg_memo());
        prop_assert_eq!(with.state_velocities().len(), tracks.len());
        let without = SafetyChecker::new(&config, &tracks, own(), goal, 0.0).without_leg_memo();
        prop_assert!(!without.leg_memo());
        prop_assert!(without.state_velocities().is_empty());
        let count = tracks.len();
        let fresh = || EncounterState::new(vec![None; count], vec![0.0; count]);
        let (mut remembered, mut afresh) = (fresh(), fresh());
        let mut elapsed_s = start_elapsed_s;
        for leg in &legs {
            // Each leg from the origin again, later on the clock.
            let verdict = with.validate(leg, elapsed_s, &mut remembered);
            prop_assert_eq!(verdict, without.validate(leg, elapsed_s, &mut afresh));
            if verdict.is_err() {
                break;
            }
            prop_assert_eq!(&remembered, &afresh);
            elapsed_s += leg.duration_s();
        }
    }
}
