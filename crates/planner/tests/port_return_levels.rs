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
    let own = VesselState::new(DVec2::ZERO, 35f64.to_radians(), SPEED_MPS, 100.0);
    let crossing = VesselState::new(
        DVec2::new(-4000.0, 3300.0),
        90f64.to_radians(),
        SPEED_MPS,
        100.0,
    );
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
