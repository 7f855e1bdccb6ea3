//! Decision 69: a port turn is judged from the course held before it for as
//! long as an observer still sees it, whichever leg of the plan ownship is
//! then on. A return part of the way (to 350) followed at once by a small
//! correction toward the goal (351) is, to an observer of course over
//! ground, one port turn from 035.
//!
//! Ownship, on 035 at 6 m/s, comes back to 350 and, 60 m on, to 351; a
//! vessel crossing from port at 8 m/s, just beyond the minimum threshold
//! distance (5 nm) when the return begins, comes within it ten seconds
//! later, on the second leg, and the new course would cross about 150 m
//! astern of it: a risk of collision the return makes (held on 035 it
//! passes more than 1 nm off). (Open sea, 8 COLREGs-obeying targets, seed
//! 11, run 8200 of 10 000: the evaluation found a 44° port turn toward the
//! vessel.)

use glam::DVec2;
use vorrt_colregs::{ManeuverViolation, VesselState};
use vorrt_jfs::{Leg, Pose, TargetState};
use vorrt_planner::validity::check_legs;
use vorrt_planner::{PlannerConfig, PlanningProblem, RejectionCause};

const SPEED_MPS: f64 = 6.0;

fn problem() -> PlanningProblem {
    let own = VesselState::new(DVec2::ZERO, 35f64.to_radians(), SPEED_MPS, 100.0);
    let crossing = VesselState::new(DVec2::new(-7737.0, 5317.0), 90f64.to_radians(), 8.0, 100.0);
    let mut problem = PlanningProblem::new(
        own,
        DVec2::new(0.0, 20_000.0),
        vec![TargetState::constant_velocity(crossing)],
    );
    problem.steady_course_rad = Some(35f64.to_radians());
    problem
}

/// From 035 at once onto `course_deg`, then `straight_m` on.
fn return_onto(course_deg: f64, straight_m: f64) -> Leg {
    let from = Pose {
        position_m: DVec2::ZERO,
        course_rad: 35f64.to_radians(),
    };
    Leg::turning_onto(from, course_deg.to_radians(), 0.0, SPEED_MPS, straight_m)
}

/// The correction after `first`: onto 351 at once, then 3 km on.
fn correction_after(first: &Leg) -> Leg {
    let from = Pose {
        position_m: first.end_m(),
        course_rad: first.course_rad,
    };
    Leg::turning_onto(from, 351f64.to_radians(), 0.0, SPEED_MPS, 3_000.0)
}

fn is_port_return(verdict: Result<(), RejectionCause>) -> bool {
    matches!(
        verdict,
        Err(RejectionCause::Colregs(
            ManeuverViolation::PortTurnTowardVessel
        ))
    )
}

#[test]
fn a_return_followed_by_a_correction_is_judged_from_the_course_before_both() {
    let config = PlannerConfig::default();
    let problem = problem();
    let first = return_onto(350.0, 60.0);
    // On the first leg alone the vessel is still beyond MTD: no finding.
    assert_eq!(check_legs(&config, &problem, &[first]), Ok(()));
    // One leg straight onto 351: refused.
    assert!(is_port_return(check_legs(
        &config,
        &problem,
        &[return_onto(351.0, 3_060.0)]
    )));
    // The same track sailed as two legs: refused too. Judged from the
    // second leg's own start course (350, a turn to starboard) it was not.
    assert!(is_port_return(check_legs(
        &config,
        &problem,
        &[first, correction_after(&first)]
    )));
}

/// Once the observer no longer sees the return (two windows after it), a
/// later leg is judged from its own start course again: the same vessel,
/// first within MTD on a leg that starts three minutes after the return,
/// is not one the return turned toward.
#[test]
fn a_turn_is_seen_for_two_windows_only() {
    let config = PlannerConfig::default();
    let problem = problem();
    // 1 km on 350 first: 167 s, beyond the 120 s the return is seen.
    let first = return_onto(350.0, 1_000.0);
    let far = VesselState::new(DVec2::new(-9800.0, 5800.0), 90f64.to_radians(), 8.0, 100.0);
    // Judged from 035 the second leg would be refused: 215 s in, the vessel
    // is within MTD, and the course of 351 makes it a risk that 035 did not.
    let correction = correction_after(&first);
    let elapsed_s = 215.0;
    let own_then = VesselState::new(
        correction.start_m
            + vorrt_geometry::angle::velocity(correction.course_rad, SPEED_MPS)
                * (elapsed_s - first.duration_s()),
        correction.course_rad,
        SPEED_MPS,
        100.0,
    );
    let far_then = VesselState {
        position_m: far.position_m + far.velocity_mps() * elapsed_s,
        ..far
    };
    assert!(vorrt_colregs::rules::is_port_turn_toward_vessel(
        35f64.to_radians(),
        &own_then,
        &far_then,
        &config.rules
    ));
    let problem = PlanningProblem {
        targets: vec![TargetState::constant_velocity(far)],
        ..problem
    };
    assert_eq!(check_legs(&config, &problem, &[first, correction]), Ok(()));
}
