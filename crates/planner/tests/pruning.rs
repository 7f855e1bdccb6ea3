//! Targets out of reach of a leg (`SafetyChecker::within_reach`, decision
//! 33): the ones skipped really are beyond every range a check looks at, at
//! every piece of the leg, and skipping them changes no verdict and no
//! encounter.
//!
//! The case count is kept small (64) so the debug-build test stays quick;
//! set `VORRT_HEAVY_TESTS=1` for a heavier run (1024 cases).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::{Encounter, EncounterLatch, VesselState};
use vorrt_jfs::{Leg, LinearTrack, Pose, TargetState};
use vorrt_planner::PlannerConfig;
use vorrt_planner::safety::{SafetyChecker, min_distance_over};
use vorrt_planner::validity::{EncounterState, MotionValidator};

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

fn still(x_m: f64, y_m: f64) -> LinearTrack {
    TargetState::constant_velocity(VesselState::new(DVec2::new(x_m, y_m), 0.0, 0.0, 100.0)).track()
}

#[test]
fn near_and_latched_targets_are_in_reach_and_far_ones_are_not() {
    let config = PlannerConfig::default();
    let goal = DVec2::new(0.0, 20_000.0);
    let tracks = [
        // 5 km ahead: inside MTD (9260 m).
        still(0.0, 5_000.0),
        // 30 km east, at rest: a 1000 m leg closes 1000 m of it.
        still(30_000.0, 0.0),
        // 30 km east, but steaming west at 10 m/s: 10 km closer by the leg's end
        // (a 1000 m leg at 6 m/s lasts 167 s), still out of reach.
        TargetState::constant_velocity(VesselState::new(
            DVec2::new(30_000.0, 0.0),
            270f64.to_radians(),
            10.0,
            100.0,
        ))
        .track(),
        // 12 km east: 10 km after the leg's 1 km, plus MTD, do not fit.
        still(11_000.0, 0.0),
    ];
    let checker = SafetyChecker::new(&config, &tracks, own(), goal, 0.0);
    let leg = Leg::straight(DVec2::ZERO, 0.0, 1_000.0, 6.0);
    let none = vec![None; tracks.len()];
    let zeros = vec![0.0; tracks.len()];
    assert_eq!(
        checker.within_reach(&leg, 0.0, &none, &zeros),
        [true, false, false, false]
    );
    // A longer leg brings the last one within reach.
    let long = Leg::straight(DVec2::ZERO, 0.0, 3_000.0, 6.0);
    assert_eq!(
        checker.within_reach(&long, 0.0, &none, &zeros),
        [true, false, false, true]
    );
    // A leg that turns to starboard may latch a vessel it is made for
    // within the early-action range (decision 74): the last one is kept.
    let starboard = Leg::turning_onto(
        Pose {
            position_m: DVec2::ZERO,
            course_rad: 0.0,
        },
        35f64.to_radians(),
        500.0,
        6.0,
        1_000.0,
    );
    assert_eq!(
        checker.within_reach(&starboard, 0.0, &none, &zeros),
        [true, false, false, true]
    );
    // The reach: MTD, which is wider than d_th (200 m) plus half the two
    // lengths (100 m) plus the margin.
    assert!((checker.reach_m(&tracks[0], 50.0) - config.rules.mtd_m).abs() < 1e-9);
    assert!((checker.required_distance_m(&tracks[0]) - 300.0).abs() < 1e-9);
    let wide = PlannerConfig {
        clearance_m: 10_000.0,
        ..PlannerConfig::default()
    };
    let wide_checker = SafetyChecker::new(&wide, &tracks, own(), goal, 0.0);
    assert!((wide_checker.reach_m(&tracks[0], 50.0) - 10_150.0).abs() < 1e-9);
    // The checker that judges only the targets in reach.
    let mask = checker.within_reach(&leg, 0.0, &none, &zeros);
    let only = checker.only_within(&mask);
    let judged: Vec<bool> = (0..tracks.len())
        .map(|index| only.may_reach(index))
        .collect();
    assert_eq!(judged, mask);
    assert!((0..tracks.len()).all(|index| checker.may_reach(index)));
    // An encounter in force, or an alteration carried, keeps a target in reach.
    let latch = EncounterLatch::new(Encounter::HeadOn, &own(), 0.0);
    let latched = [None, Some(latch), None, None];
    assert_eq!(
        checker.within_reach(&leg, 0.0, &latched, &zeros),
        [true, true, false, false]
    );
    assert_eq!(
        checker.within_reach(&leg, 0.0, &none, &[0.0, 0.0, 0.1, 0.0]),
        [true, false, true, false]
    );
}

/// A target 2 to 40 km from ownship, at up to 15 m/s, on any course, some
/// bound for a goal (where they stop).
fn target() -> impl Strategy<Value = TargetState> {
    (
        2_000.0f64..40_000.0,
        0.0f64..360.0,
        0.0f64..360.0,
        0.0f64..15.0,
        proptest::option::of(0.0f64..20_000.0),
    )
        .prop_map(|(range_m, bearing_deg, course_deg, speed_mps, goal_m)| {
            let bearing = bearing_deg.to_radians();
            let start = DVec2::new(bearing.sin(), bearing.cos()) * range_m;
            let course = course_deg.to_radians();
            let vessel = VesselState::new(start, course, speed_mps, 150.0);
            match goal_m {
                Some(distance_m) => TargetState::toward_goal(
                    vessel,
                    start + DVec2::new(course.sin(), course.cos()) * distance_m,
                ),
                None => TargetState::constant_velocity(vessel),
            }
        })
}

/// A leg from the origin heading north: a turn of up to 90° either way on a
/// 500 m radius (or at once), then up to 6 km straight, maybe slowing down.
fn leg() -> impl Strategy<Value = Leg> {
    (
        -90.0f64..90.0,
        prop_oneof![Just(0.0), Just(500.0)],
        0.0f64..6_000.0,
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
    fn targets_out_of_reach_stay_beyond_every_check_and_change_nothing(
        targets in proptest::collection::vec(target(), 1..12),
        leg in leg(),
        start_elapsed_s in 0.0f64..600.0,
    ) {
        let config = PlannerConfig::default();
        let goal = DVec2::new(0.0, 30_000.0);
        let tracks: Vec<LinearTrack> = targets.iter().map(TargetState::track).collect();
        let checker = SafetyChecker::new(&config, &tracks, own(), goal, 0.0);
        let count = tracks.len();
        let in_reach = checker.within_reach(&leg, start_elapsed_s, &vec![None; count], &vec![0.0; count]);
        let margin_m = leg.piece_error_m() + leg.timing_error_m();
        // Every target skipped stays beyond MTD at each piece's start and end,
        // and beyond `d_th` with every margin along each piece.
        for (track, _) in tracks.iter().zip(&in_reach).filter(|(_, kept)| !**kept) {
            for piece in leg.pieces(config.step_m) {
                let from_s = start_elapsed_s + piece.elapsed_s;
                let to_s = from_s + piece.duration_s;
                // Beyond the early-action range where the leg turns to
                // starboard and the turn still shows (up to the window
                // past its end), as a vessel it is made for may be latched
                // early then (decision 74).
                let turns_to_starboard = vorrt_geometry::angle::normalize_pi(leg.course_rad)
                    >= config.rules.apparent_turn_rad;
                let shows = piece.elapsed_s + piece.duration_s
                    <= leg.turn_duration_s() + vorrt_colregs::rules::STEADY_COURSE_WINDOW_S;
                let floor_m = if turns_to_starboard && shows {
                    config.rules.early_action_range_m
                } else {
                    config.rules.mtd_m
                };
                for (own_m, at_s) in [(piece.start_m, from_s), (piece.end_m(), to_s)] {
                    let range_m = own_m.distance(track.position_at(at_s));
                    prop_assert!(range_m >= floor_m, "{range_m}");
                }
                let during_m = min_distance_over(piece.start_m, piece.velocity_mps, track, from_s, piece.duration_s);
                prop_assert!(
                    during_m >= checker.required_distance_m(track) + margin_m,
                    "{during_m}"
                );
            }
        }
        // The same verdict and the same encounters as with the targets kept alone.
        let kept: Vec<LinearTrack> = tracks
            .iter()
            .zip(&in_reach)
            .filter_map(|(track, kept)| kept.then_some(*track))
            .collect();
        let alone = SafetyChecker::new(&config, &kept, own(), goal, 0.0);
        let fresh = |count: usize| EncounterState::new(vec![None; count], vec![0.0; count]);
        let (mut all_state, mut kept_state) = (fresh(count), fresh(kept.len()));
        let verdict = checker.validate(&leg, start_elapsed_s, &mut all_state);
        prop_assert_eq!(verdict, alone.validate(&leg, start_elapsed_s, &mut kept_state));
        if verdict.is_ok() {
            let kept_latches: Vec<_> = all_state
                .latches
                .iter()
                .zip(&in_reach)
                .filter_map(|(latch, kept)| kept.then_some(*latch))
                .collect();
            prop_assert_eq!(kept_latches, kept_state.latches);
            for (latch, kept) in all_state.latches.iter().zip(&in_reach) {
                prop_assert!(*kept || latch.is_none());
            }
        }
    }
}
