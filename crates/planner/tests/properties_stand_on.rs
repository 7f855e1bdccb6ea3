//! Property tests of the planner when ownship stands on or changes speed.
//!
//! A crossing in which ownship stands on: it keeps its course and speed
//! until it may act (rule 17), and plans are found for it. A crossing in
//! which turning is blocked: ownship slows down or stops within its rate of
//! speed change and still keeps the clearance. As in `properties.rs`, every
//! plan is checked independently of the planner's own checker, with the
//! helpers in `common`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

mod common;

use common::*;
use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::{Encounter, VesselState};
use vorrt_geometry::angle;
use vorrt_jfs::TargetState;
use vorrt_planner::{Plan, Planner, PlanningProblem};

/// A give-way crossing in which turning is blocked: ownship (100 m) north
/// at its service speed `own_kn`, or slower (`start_factor` of it, as after
/// slowing down, replanning from its real state); a vessel alongside
/// `abeam_m` to starboard at the service speed (any starboard alteration
/// closes it); a crossing vessel from starboard on a collision course at
/// `range_nm`, `miss_m` off.
fn blocked_crossing() -> impl Strategy<Value = PlanningProblem> {
    (
        10.0f64..14.0,    // service speed, knots
        0.3f64..1.0,      // present speed as a fraction of it
        330.0f64..450.0,  // the vessel alongside, metres to starboard
        2.5f64..4.0,      // crossing vessel's range, nautical miles
        -150.0f64..150.0, // miss distance, metres
    )
        .prop_map(|(own_kn, start_factor, abeam_m, range_nm, miss_m)| {
            let service = own_kn * KNOT;
            let crossing_velocity = DVec2::new(-service, 0.0);
            let meet_s = range_nm * NM / (2f64.sqrt() * service);
            let meeting = DVec2::new(miss_m, service * meet_s);
            let crossing = TargetState::constant_velocity(VesselState::new(
                meeting - crossing_velocity * meet_s,
                1.5 * std::f64::consts::PI,
                service,
                150.0,
            ));
            let alongside = TargetState::constant_velocity(VesselState::new(
                DVec2::new(abeam_m, 0.0),
                0.0,
                service,
                100.0,
            ));
            let own = VesselState::new(DVec2::ZERO, 0.0, start_factor * service, 100.0);
            PlanningProblem {
                service_speed_mps: Some(service),
                ..PlanningProblem::new(
                    own,
                    DVec2::new(0.0, meeting.y + 3.0 * NM),
                    vec![crossing, alongside],
                )
            }
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases() / 2, ..ProptestConfig::default() })]

    /// Where turning is blocked and ownship may be slow already: every plan
    /// keeps the clearance between hulls from every target when sampled
    /// every second along its legs as sailed, never exceeds the service
    /// speed, never changes speed faster than the rate, and never turns
    /// faster than the limit.
    #[test]
    fn speed_changes_keep_the_limits_and_the_clearance(problem in blocked_crossing(), seed in 0u64..1000) {
        let mut planner = Planner::new(config()).unwrap();
        let Ok(plan) = planner.plan(&problem, seed) else {
            return Ok(());
        };
        let service = problem.service_speed_mps();
        let config = planner.config();
        let rate_mps2 = config.speed_change_rate_mps2(problem.ownship.length_m, service);
        if let Err(message) = speed_profile_kept(&plan, service, rate_mps2) {
            return Err(TestCaseError::fail(message));
        }
        prop_assert!((plan.speed_at(problem.start_time_s).unwrap() - problem.ownship.speed_mps).abs() < 1e-9);
        for target in &problem.targets {
            let required = config.clearance_m
                + vorrt_colregs::rules::contact_range_m(problem.ownship.length_m, target.vessel.length_m);
            let clearance = min_clearance(&plan, target, problem.start_time_s);
            prop_assert!(clearance >= required - 0.01, "clearance {} < {}", clearance, required);
        }
        let limit = config.turning.max_turn_rate_rad_s(problem.ownship.length_m, service).unwrap();
        prop_assert!(max_turn_rate(&plan) <= limit * (1.0 + 1e-6));
    }
}

/// Where ownship must give way to a crossing vessel and a vessel alongside
/// to starboard blocks every alteration to starboard (a turn to port is
/// forbidden, rule 15), the plan is to slow down: it holds its course at a
/// reduced speed until the crossing vessel is past, then resumes its
/// service speed. Without speed manoeuvres no compliant plan exists here.
#[test]
fn only_slowing_down_gives_way_when_turning_is_blocked() {
    let service = 12.0 * KNOT;
    let crossing = TargetState::constant_velocity(VesselState::new(
        DVec2::new(3.0 * NM, 3.0 * NM),
        1.5 * std::f64::consts::PI,
        service,
        150.0,
    ));
    let alongside = TargetState::constant_velocity(VesselState::new(
        DVec2::new(400.0, 0.0),
        0.0,
        service,
        100.0,
    ));
    let own = VesselState::new(DVec2::ZERO, 0.0, service, 100.0);
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 8.0 * NM), vec![crossing, alongside]);
    let plan = Planner::new(config()).unwrap().plan(&problem, 1).unwrap();
    // No course alteration at all.
    assert!(
        plan.legs.iter().all(|leg| leg.turn_rad.abs() < 1e-9),
        "{:?}",
        plan.legs
    );
    // Slower, then back to the service speed.
    let reduced = vorrt_planner::simplify::SPEED_FACTORS[1] * service;
    assert!((plan.legs[0].speed_mps - reduced).abs() < 1e-9);
    assert!(plan.legs[0].duration_s() > plan.legs[0].speed_change_s());
    let last = plan.legs.last().unwrap();
    assert!((last.speed_mps - service).abs() < 1e-9);
    assert!(
        (plan
            .speed_at(plan.waypoints.last().unwrap().time_s)
            .unwrap()
            - service)
            .abs()
            < 1e-9
    );
    // The crossing vessel passes ahead, at least d_th between the hulls.
    let required = 200.0 + vorrt_colregs::rules::contact_range_m(100.0, 150.0);
    assert!(min_clearance(&plan, &problem.targets[0], 0.0) >= required - 0.01);
    assert!(!crosses_ahead_anywhere(&plan, &problem.targets[0]));
}

/// A crossing in which ownship stands on: ownship at the origin heading
/// north, the target coming from the port side on a collision course (it
/// would pass within `miss_m` of ownship), inside MTD and beyond the
/// stand-on action range, and keeping its course and speed: it does not
/// give way.
fn stand_on_crossing() -> impl Strategy<Value = PlanningProblem> {
    (
        8.0f64..14.0,   // ownship speed, knots
        0.8f64..1.2,    // target speed, times ownship's
        50.0f64..130.0, // target course, degrees (from the port side)
        3.0f64..4.5,    // closing distance, nautical miles
        -60.0f64..60.0, // miss distance, metres
    )
        .prop_map(|(own_kn, speed_factor, course_deg, range_nm, miss_m)| {
            let own_speed = own_kn * KNOT;
            collision_course(
                own_speed,
                course_deg,
                own_speed * speed_factor,
                range_nm,
                miss_m,
            )
        })
}

/// Ownship's range to the target at `time_s` along `plan`.
fn range_at(plan: &Plan, target: &TargetState, time_s: f64) -> f64 {
    let (position, _) = plan.position_at(time_s).unwrap();
    let elapsed_s = time_s - plan.waypoints[0].time_s;
    position.distance(target.predict(elapsed_s).vessel.position_m)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// Rule 17: a stand-on vessel whose give-way vessel does not act keeps
    /// its course and speed until the give-way vessel is within the
    /// stand-on action range (17(a)(i)), then acts (17(a)(ii), 17(b)) and
    /// keeps d_th, never turning to port of its course for a vessel on its
    /// port side while the encounter is in force (17(c)). A failed plan is
    /// allowed here; `stand_on_plans_are_found` counts them.
    #[test]
    fn a_stand_on_vessel_keeps_its_course_until_it_may_act(problem in stand_on_crossing(), seed in 0u64..1000) {
        let mut planner = Planner::new(config()).unwrap();
        let Ok(plan) = planner.plan(&problem, seed) else {
            return Ok(());
        };
        let target = &problem.targets[0];
        prop_assume!(plan.encounters[0][0].map(|latch| latch.encounter) == Some(Encounter::CrossingStandOn));
        let rules = planner.config().rules;
        let clearance = min_clearance(&plan, target, problem.start_time_s);
        prop_assert!(clearance >= planner.config().clearance_m - 1e-6, "clearance {}", clearance);
        let own = problem.ownship;
        let path = sailed(&plan);
        // The validator judges a turn or a change of speed by each piece
        // (at most d' long) from where the piece starts: within a piece,
        // the heading may run on by half a chord's angle and the speed by
        // one piece's change.
        let config = planner.config();
        let rate_rad_s = config.turning.max_turn_rate_rad_s(own.length_m, own.speed_mps).unwrap();
        let piece_s = config.step_m / own.speed_mps;
        let course_slack = 0.5 * rate_rad_s * piece_s;
        let speed_slack = config.speed_change_rate_mps2(own.length_m, own.speed_mps) * piece_s;
        // Until the action range: course and speed kept.
        for &(time, _, course) in path
            .iter()
            .take_while(|(time, _, _)| range_at(&plan, target, *time) > rules.stand_on_action_range_m)
        {
            prop_assert!(
                angle::signed_turn(own.course_rad, course).abs() <= rules.stand_on_course_tolerance_rad + course_slack,
                "course {:.1}° at {:.0} s, before the action range", course.to_degrees(), time
            );
            let speed = plan.speed_at(time).unwrap();
            prop_assert!(
                (speed - own.speed_mps).abs() <= rules.stand_on_speed_tolerance_mps + speed_slack,
                "speed {:.2} m/s at {:.0} s, before the action range", speed, time
            );
        }
        // Once it may act, and while the encounter is in force (along every
        // leg that ends with it still latched), no course to port of the
        // one held while the target is on the port side (before, the
        // course is kept, as above).
        let latched = plan.encounters[0][0];
        let in_force_until_s = plan
            .waypoints
            .iter()
            .zip(&plan.encounters)
            .take_while(|(_, encounters)| encounters[0] == latched)
            .last()
            .map_or(problem.start_time_s, |(waypoint, _)| waypoint.time_s);
        for &(time, position, course) in path.iter().take_while(|(time, _, _)| *time <= in_force_until_s) {
            let target_then = target.predict(time - problem.start_time_s).vessel.position_m;
            // Judged by pieces (as above): within the action range since
            // the start of the piece.
            let may_act = range_at(&plan, target, (time - piece_s).max(problem.start_time_s))
                <= rules.stand_on_action_range_m;
            if may_act && vorrt_colregs::rules::is_on_port_side(position, own.course_rad, target_then) {
                prop_assert!(
                    angle::signed_turn(own.course_rad, course) >= -rules.turn_tolerance_rad - 1e-9,
                    "course {:.1}° to port at {:.0} s, the target on the port side", course.to_degrees(), time
                );
            }
        }
    }
}

/// A plan keeping every rule is found for most stand-on crossings whose
/// give-way vessel does not act: the course held until the action range,
/// then one alteration (`simplify::hold_then_alter`), where the tree alone
/// rarely finds the narrow band of courses a stand-on vessel may sail.
#[test]
fn stand_on_plans_are_found() {
    let total = cases();
    let mut planner = Planner::new(config()).unwrap();
    let (mut failures, mut held_first) = (0u32, 0u32);
    for (seed, problem) in (0u64..).zip(fixed_sample(&stand_on_crossing(), 11)) {
        match planner.plan(&problem, seed) {
            // Three legs from the start, the first on the present course.
            Ok(plan) => {
                if plan.legs.len() == 3 && plan.legs[0].turn_rad.abs() < 1e-9 {
                    held_first += 1;
                }
            }
            Err(_) => failures += 1,
        }
    }
    eprintln!("{failures} of {total} found no plan; {held_first} held the course, then altered");
    assert!(
        f64::from(failures) <= 0.2 * f64::from(total),
        "{failures} of {total} stand-on crossings found no plan keeping every rule"
    );
    assert!(
        held_first * 2 >= total,
        "only {held_first} of {total} plans held the course, then altered"
    );
}
