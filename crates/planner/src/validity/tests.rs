//! Unit tests of the leg memo carried from piece to piece (decision 54).

use super::*;
use crate::PlannerConfig;
use vorrt_geometry::angle;
use vorrt_jfs::{MotionModel, TargetState};

/// The settled-turn predicate's velocities and gate kept in a leg's memo
/// are those worked out afresh, bit for bit, whichever of the course
/// turned to, the course before and the speed changes between two asks,
/// with more turns asked in turn than the memo keeps.
#[test]
fn turn_geometry_is_reused_only_for_the_same_bits() {
    let mut memo = LegMemo::default();
    let own = VesselState::new(DVec2::ZERO, 0.3, 6.0, 100.0);
    let fresh = |before_rad: f64, own: &VesselState| {
        let before = VesselState {
            course_rad: before_rad,
            ..*own
        };
        (
            own.velocity_mps(),
            before.velocity_mps(),
            vorrt_colregs::rules::PortTurnGate::new(before_rad, own.course_rad),
        )
    };
    let turned = |course_rad| VesselState { course_rad, ..own };
    let asks = [
        (1.2, own),
        (1.2, own),
        (1.3, own),
        (1.3, turned(0.4)),
        (
            1.3,
            VesselState {
                speed_mps: 5.0,
                ..own
            },
        ),
        (1.2, own),
        (1.4, turned(0.5)),
        (1.5, turned(0.6)),
        (1.6, turned(0.7)),
        (1.2, own),
        (1.3, turned(0.4)),
    ];
    let bits = |velocity: DVec2| velocity.to_array().map(f64::to_bits);
    for (before_rad, own) in asks {
        let geometry = memo.turn_geometry(before_rad, &own);
        let (want_own, want_before, want_gate) = fresh(before_rad, &own);
        assert_eq!(bits(geometry.own_mps), bits(want_own));
        assert_eq!(bits(geometry.before_mps), bits(want_before));
        assert_eq!(geometry.gate, want_gate);
    }
    // A target's velocity asked before the latch step sized the memo.
    let target = VesselState::new(DVec2::new(100.0, 0.0), 2.0, 4.0, 50.0);
    assert_eq!(memo.target_velocity(3, &target), target.velocity_mps());
    assert_eq!(memo.target_velocity(3, &target), target.velocity_mps());
}

/// A vessel 5 km to starboard on the reciprocal course passes clear: on
/// the straight run it is remembered as one no risk can reach, and the
/// memo is dropped on a piece not sailed at the velocity seen.
#[test]
fn a_target_passing_clear_is_remembered_on_the_straight_run() {
    let config = PlannerConfig::default();
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    let tracks = [TargetState::constant_velocity(VesselState::new(
        DVec2::new(5_000.0, 6_000.0),
        std::f64::consts::PI,
        6.0,
        100.0,
    ))
    .track()];
    let checker = SafetyChecker::new(&config, &tracks, own, DVec2::new(0.0, 20_000.0), 0.0);
    let mut state = EncounterState::new(vec![None], vec![0.0]);
    let mut memo = LegMemo::default();
    let north = DVec2::new(0.0, 6.0);
    for (elapsed_s, sailed_mps) in [(10.0, Some(north)), (20.0, Some(north))] {
        let own_then = VesselState {
            position_m: north * elapsed_s,
            ..own
        };
        state.advance_reusing(&own_then, 0.0, &checker, (elapsed_s, sailed_mps), &mut memo);
    }
    assert_eq!(memo.clear, [Some(0)]);
    assert_eq!(memo.seen_mps, Some(north));
    // A transient piece (a turn's chord): nothing is kept.
    let own_then = VesselState {
        position_m: north * 30.0,
        ..own
    };
    state.advance_reusing(&own_then, 0.0, &checker, (30.0, None), &mut memo);
    assert_eq!(memo.clear, [None]);
    assert_eq!(state.latches, [None]);
}

/// The port-turn judgement's first test, asked alone (`any_within_mtd`):
/// where it says no vessel is within MTD, no port turn from any course onto
/// any course is refused; where it says one is, some port turn is. Vessels
/// on a ring of bearings either side of MTD (5 nm), crossing or meeting.
#[test]
fn no_port_turn_is_toward_a_vessel_beyond_mtd() {
    let config = PlannerConfig::default();
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    let mtd_m = config.rules.mtd_m;
    let (mut within, mut refused_within) = (0, 0);
    for range_m in [0.5 * mtd_m, 0.9 * mtd_m, 1.01 * mtd_m, 1.5 * mtd_m] {
        for bearing_deg in (0..360).step_by(30) {
            for course_deg in [90.0f64, 180.0, 270.0] {
                let bearing_rad = f64::from(bearing_deg).to_radians();
                let start_m = DVec2::new(bearing_rad.sin(), bearing_rad.cos()) * range_m;
                let vessel = VesselState::new(start_m, course_deg.to_radians(), 6.0, 100.0);
                let tracks = [TargetState::constant_velocity(vessel).track()];
                let checker =
                    SafetyChecker::new(&config, &tracks, own, DVec2::new(0.0, 20_000.0), 0.0);
                let mut any_refused = false;
                for turn_deg in [-35.0f64, -60.0, -90.0] {
                    for before_deg in [0.0f64, 45.0, 90.0] {
                        let course_rad = (before_deg + turn_deg).to_radians();
                        let candidate = Move {
                            start_m: DVec2::ZERO,
                            start_elapsed_s: 0.0,
                            course_rad,
                            velocity_mps: angle::velocity(course_rad, 6.0),
                            duration_s: 10.0,
                        };
                        let refused = checker
                            .check_settled_turn(before_deg.to_radians(), &candidate)
                            .is_err();
                        let near = checker.any_within_mtd(&candidate);
                        assert!(
                            near || !refused,
                            "refused beyond MTD: {range_m} m, {bearing_deg}°, {course_deg}°"
                        );
                        assert_eq!(near, range_m < mtd_m);
                        any_refused |= refused;
                    }
                }
                if range_m < mtd_m {
                    within += 1;
                    refused_within += usize::from(any_refused);
                }
            }
        }
    }
    // The test would pass vacuously if no turn were ever refused.
    assert!(
        within > 0 && refused_within > 0,
        "{refused_within} of {within}"
    );
}

/// A vessel met head-on 8 nm off, beyond MTD: a leg that turns 35° to
/// starboard latches her as the judges do (decision 74), on the course held
/// before the turn, and a leg back toward her course while she is still
/// closing is refused as an alteration not held; a leg held on the course
/// latches nothing.
#[test]
fn a_turn_to_starboard_latches_a_vessel_beyond_mtd_it_is_made_for() {
    let config = PlannerConfig::default();
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    let range_m = 8.0 * 1852.0;
    assert!(range_m > config.rules.mtd_m && range_m < config.rules.early_action_range_m);
    let tracks = [TargetState::constant_velocity(VesselState::new(
        DVec2::new(0.0, range_m),
        std::f64::consts::PI,
        6.0,
        100.0,
    ))
    .track()];
    let checker = SafetyChecker::new(&config, &tracks, own, DVec2::new(0.0, 40_000.0), 0.0);
    let model = vorrt_jfs::RateLimitedTurn {
        turn_radius_m: 700.0,
    };
    let start = vorrt_jfs::Pose {
        position_m: DVec2::ZERO,
        course_rad: 0.0,
    };
    // Held on: nothing latched beyond MTD.
    let mut state = EncounterState::new(vec![None], vec![0.0]);
    let north = Leg::straight(DVec2::ZERO, 0.0, 1000.0, 6.0);
    checker.validate(&north, 0.0, &mut state).unwrap();
    assert_eq!(state.latches, [None]);
    // Turned 35° to starboard: latched head-on, from the course held.
    let mut state = EncounterState::new(vec![None], vec![0.0]);
    let turn = model.turn_onto(start, 35f64.to_radians(), 6.0, 1000.0);
    checker.validate(&turn, 0.0, &mut state).unwrap();
    let latch = state.latches[0].expect("latched early");
    assert_eq!(latch.encounter, vorrt_colregs::Encounter::HeadOn);
    assert!(angle::normalize_pi(latch.reference_course_rad).abs() < 1e-9);
    assert!(state.alterations[0] > config.rules.apparent_turn_rad);
    // Back to 10° while she closes: not held.
    let back = model.turn_onto(turn.end_pose(), 10f64.to_radians(), 6.0, 1000.0);
    assert_eq!(
        checker.validate(&back, turn.duration_s(), &mut state.clone()),
        Err(RejectionCause::Colregs(
            vorrt_colregs::ManeuverViolation::AlterationNotHeld
        ))
    );
}
