//! Decision 57: the planner refuses what the evaluation calls a port return
//! onto a port-side vessel (`is_port_turn_toward_vessel`) at every level of
//! the graded fallback, and judges it from every course an observer may
//! take as the course before.
//!
//! Ownship, on 035, comes back to 000 toward its goal; a vessel 2.8 nm off
//! the port bow heads east across the new course and would be crossed
//! about 600 m ahead: a risk of collision the return makes (held on 035 it
//! passes more than 1 nm off).

use glam::DVec2;
use vorrt_colregs::{ManeuverViolation, VesselState};
use vorrt_jfs::{Leg, Pose, TargetState};
use vorrt_planner::validity::check_legs;
use vorrt_planner::{Compliance, PlannerConfig, PlanningProblem, RejectionCause};

const SPEED_MPS: f64 = 6.0;

fn problem(steady_course_deg: f64) -> PlanningProblem {
    crossing_problem(SPEED_MPS, DVec2::new(-4000.0, 3300.0), steady_course_deg)
}

/// Ownship on 035 at `own_speed_mps`, its steady course `steady_course_deg`,
/// bound north; one vessel at `crossing_m` heading east at [`SPEED_MPS`].
fn crossing_problem(
    own_speed_mps: f64,
    crossing_m: DVec2,
    steady_course_deg: f64,
) -> PlanningProblem {
    let own = VesselState::new(DVec2::ZERO, 35f64.to_radians(), own_speed_mps, 100.0);
    let crossing = VesselState::new(crossing_m, 90f64.to_radians(), SPEED_MPS, 100.0);
    let mut problem = PlanningProblem::new(
        own,
        DVec2::new(0.0, 20_000.0),
        vec![TargetState::constant_velocity(crossing)],
    );
    problem.steady_course_rad = Some(steady_course_deg.to_radians());
    problem
}

/// The return: from 035 to 000 at once, then 3 km on.
fn return_leg() -> Leg {
    let from = Pose {
        position_m: DVec2::ZERO,
        course_rad: 35f64.to_radians(),
    };
    Leg::turning_onto(from, 0.0, 0.0, SPEED_MPS, 3_000.0)
}

fn refused_as_port_return(config: &PlannerConfig, problem: &PlanningProblem) -> bool {
    matches!(
        check_legs(config, problem, &[return_leg()]),
        Err(RejectionCause::Colregs(
            ManeuverViolation::PortTurnTowardVessel
        ))
    )
}

/// A fallback plan that keeps clearance only (`safety_only`) may depart
/// from the steering rules to avoid immediate danger (rules 2(b), 17(b));
/// a port turn that makes a vessel a risk creates one, and is refused
/// there too (open sea, 2 constant targets, seed 11, run 111).
#[test]
fn a_safety_only_plan_makes_no_port_return() {
    let problem = problem(35.0);
    for compliance in [
        Compliance::Full,
        Compliance::Directions,
        Compliance::SafetyOnly,
    ] {
        let config = PlannerConfig {
            compliance,
            ..PlannerConfig::default()
        };
        assert!(refused_as_port_return(&config, &problem), "{compliance:?}");
    }
}

/// Ownship came round to 035 less than a window before the plan, so an
/// observer's steady course is still 000 and the return to 000 is no turn
/// from it; but a vessel latched later in the leg is judged from 035, the
/// course then held (open sea, 2 constant targets, seed 11, run 185).
#[test]
fn a_return_soon_after_an_alteration_is_judged_from_the_course_held() {
    let config = PlannerConfig::default();
    assert!(refused_as_port_return(&config, &problem(0.0)));
    // Without the vessel the same return is valid: the refusal is the
    // port return's.
    let mut open_water = problem(0.0);
    open_water.targets.clear();
    let valid = check_legs(&config, &open_water, &[return_leg()]);
    assert_eq!(valid, Ok(()), "{valid:?}");
}

/// Part way round a turn (a plan made while turning), an observer judges
/// a new turn from the course before the one under way alone: coming
/// back to 000, the course before it, is no port turn.
#[test]
fn a_plan_made_part_way_round_is_judged_from_the_course_before() {
    let mut turning = problem(0.0);
    turning.turning_at_start = true;
    assert!(!refused_as_port_return(&PlannerConfig::default(), &turning));
}

/// Decision 62: a return from a reduced-speed hold gathers way on the new
/// course after the turn, and a vessel from port may be a risk at a speed
/// short of the settled one. Ownship on 035 at 3 m/s comes back to 000 and
/// speeds up to 7 m/s (0.02 m/s², 200 s); a vessel 4.7 nm off the port bow
/// heads east at 6 m/s. Sailed at 7 m/s from the start the return passes
/// clear of the risk CPA; gathering way it comes within it, and the
/// evaluation latches the vessel as one the turn made a risk (open sea, 8
/// COLREGs-obeying targets, seed 11, runs 216 and 716).
#[test]
fn a_return_that_gathers_way_is_judged_at_every_speed_on_the_way() {
    const SLOW_MPS: f64 = 3.0;
    const FAST_MPS: f64 = 7.0;
    let config = PlannerConfig::default();
    let problem_at =
        |speed_mps: f64| crossing_problem(speed_mps, DVec2::new(-8750.0, 3000.0), 35.0);
    let from = Pose {
        position_m: DVec2::ZERO,
        course_rad: 35f64.to_radians(),
    };
    let steady = Leg::turning_onto(from, 0.0, 0.0, FAST_MPS, 6_000.0);
    let at_speed = check_legs(&config, &problem_at(FAST_MPS), &[steady]);
    assert_eq!(at_speed, Ok(()), "{at_speed:?}");
    let gathering = check_legs(
        &config,
        &problem_at(SLOW_MPS),
        &[steady.from_speed(SLOW_MPS, 0.02)],
    );
    assert_eq!(
        gathering,
        Err(RejectionCause::Colregs(
            ManeuverViolation::PortTurnTowardVessel
        ))
    );
}
