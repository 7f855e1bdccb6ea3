//! The user-constraint seam: every plan keeps out of what a constraint
//! refuses, along the curve sailed, over generated encounters; checked
//! independently by sampling the plan densely.
//!
//! The case count is small (24) so the debug-build test stays quick; set
//! `VORRT_HEAVY_TESTS=1` for a heavier run (256 cases).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use proptest::prelude::*;
use vorrt_planner::colregs::VesselState;
use vorrt_planner::glam::DVec2;
use vorrt_planner::jfs::TargetState;
use vorrt_planner::{
    Constraint, ConstraintViolation, EvasionSearch, PlanStatistics, Planner, PlannerConfig,
    PlannerError, PlanningProblem, RejectionCause, Segment, Turning, check_legs_with,
    evasive_leg_constrained,
};

fn cases() -> u32 {
    if std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1") {
        256
    } else {
        24
    }
}

/// A circle ownship must keep out of.
#[derive(Debug, Clone, Copy)]
struct NoGoCircle {
    centre_m: DVec2,
    radius_m: f64,
}

impl Constraint for NoGoCircle {
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        if segment.distance_to_m(self.centre_m) < self.radius_m + segment.margin_m {
            Err(ConstraintViolation::NoGoArea)
        } else {
            Ok(())
        }
    }

    fn admits_point(&self, point_m: DVec2) -> bool {
        point_m.distance(self.centre_m) >= self.radius_m
    }
}

/// The smallest distance from the circle's centre to ownship along `plan`,
/// sampled every second (a piece of a turn is never longer than a few
/// seconds' sailing), less the radius: negative inside.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_precision_loss,
    reason = "a plan's duration is finite and positive, a few thousand seconds"
)]
fn least_clearance_m(plan: &vorrt_planner::Plan, circle: &NoGoCircle) -> f64 {
    let start_s = plan.waypoints[0].time_s;
    let steps = plan.duration_s().ceil() as usize;
    (0..=steps)
        .filter_map(|step| plan.pose_at(start_s + step as f64))
        .map(|pose| pose.position_m.distance(circle.centre_m) - circle.radius_m)
        .fold(f64::INFINITY, f64::min)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// Ownship north from the origin to 10 km; a no-go circle of 300-1500 m
    /// somewhere across the route (never over the start or the goal); a
    /// target crossing or meeting, or none.
    #[test]
    fn every_plan_keeps_out_of_a_no_go_circle(
        along_m in 2500.0f64..7500.0,
        offset_m in -1200.0f64..1200.0,
        radius_m in 300.0f64..1500.0,
        target in prop::option::of((0.0f64..360.0, 3.0f64..8.0, 3000.0f64..9000.0, -3000.0f64..3000.0)),
        instant in any::<bool>(),
        seed in 0u64..1000,
    ) {
        let goal_m = DVec2::new(0.0, 10_000.0);
        let circle = NoGoCircle { centre_m: DVec2::new(offset_m, along_m), radius_m };
        prop_assume!(circle.admits_point(DVec2::ZERO) && circle.admits_point(goal_m));
        prop_assume!(DVec2::ZERO.distance(circle.centre_m) > radius_m + 400.0);
        prop_assume!(goal_m.distance(circle.centre_m) > radius_m + 400.0);
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 60.0);
        let targets = target
            .into_iter()
            .map(|(course_deg, speed_mps, y_m, x_m)| {
                TargetState::constant_velocity(VesselState::new(
                    DVec2::new(x_m, y_m),
                    f64::to_radians(course_deg),
                    speed_mps,
                    60.0,
                ))
            })
            .collect();
        let problem = PlanningProblem::new(own, goal_m, targets);
        let config = PlannerConfig {
            nodes_per_phase: 300,
            turning: if instant { Turning::Instant } else { Turning::FromLength },
            ..PlannerConfig::default()
        };
        let mut planner = Planner::with_constraint(config, circle).unwrap();
        match planner.plan(&problem, seed) {
            Ok(plan) => {
                let clearance_m = least_clearance_m(&plan, &circle);
                // Sampled poses lie on the curve sailed; a chord's error
                // is already counted by the validity check.
                prop_assert!(clearance_m >= -1e-6, "{clearance_m} m inside the circle");
                // Every piece the validity check judged keeps the circle
                // with its margin (the chord's error on a turn).
                for leg in &plan.legs {
                    let error_m = leg.piece_error_m().max(leg.timing_error_m());
                    for piece in leg.pieces(planner.config().step_m) {
                        let distance_m = Segment {
                            start_m: piece.start_m,
                            end_m: piece.end_m(),
                            margin_m: 0.0,
                            start_elapsed_s: 0.0,
                            duration_s: piece.duration_s,
                            course_rad: piece.course_rad,
                            course_spread_rad: 0.0,
                        }
                        .distance_to_m(circle.centre_m);
                        prop_assert!(distance_m >= radius_m - 1e-6, "{distance_m} m, error {error_m} m");
                    }
                }
            }
            Err(
                PlannerError::NoSafePath { .. }
                | PlannerError::BudgetExhausted { .. }
                | PlannerError::NodeBudgetTooSmall { .. },
            ) => {}
            Err(other) => prop_assert!(false, "{other}"),
        }
    }
}

#[test]
fn a_circle_on_the_route_is_passed_around() {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 60.0);
    let goal_m = DVec2::new(0.0, 10_000.0);
    let problem = PlanningProblem::new(own, goal_m, vec![]);
    let circle = NoGoCircle {
        centre_m: DVec2::new(0.0, 5000.0),
        radius_m: 1000.0,
    };
    // Without the constraint: straight through it.
    let free = Planner::new(PlannerConfig::default())
        .unwrap()
        .plan(&problem, 3)
        .unwrap();
    assert!(least_clearance_m(&free, &circle) < 0.0);
    assert!(check_legs_with(&PlannerConfig::default(), &problem, &free.legs, &circle).is_err());
    let mut planner = Planner::with_constraint(PlannerConfig::default(), circle).unwrap();
    let plan = planner.plan(&problem, 3).unwrap();
    assert!(least_clearance_m(&plan, &circle) >= 0.0);
    assert!(planner.check_legs(&problem, &plan.legs).is_ok());
}

#[test]
fn a_goal_walled_off_fails_on_the_constraint() {
    /// Everything north of y = 4 km is closed.
    struct Wall;
    impl Constraint for Wall {
        fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
            if segment.start_m.y.max(segment.end_m.y) + segment.margin_m > 4000.0 {
                Err(ConstraintViolation::Land)
            } else {
                Ok(())
            }
        }
        fn admits_point(&self, point_m: DVec2) -> bool {
            point_m.y <= 4000.0
        }
    }
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 60.0);
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 6000.0), vec![]);
    let config = PlannerConfig {
        nodes_per_phase: 60,
        samples_per_phase: 200,
        max_restarts: 0,
        ..PlannerConfig::default()
    };
    let error = Planner::with_constraint(config, Wall)
        .unwrap()
        .plan(&problem, 1)
        .expect_err("no path crosses the wall");
    let statistics: &PlanStatistics = error.statistics().expect("a failed search says why");
    assert_eq!(
        statistics.rejections.dominant_cause(),
        Some(RejectionCause::Constraint(ConstraintViolation::Land))
    );
}

#[test]
fn the_evasive_manoeuvre_keeps_the_constraint() {
    // A vessel coming straight at ownship; the sea to starboard (east of
    // x = 50 m) is closed, so the evasive turn is to port.
    struct EastClosed;
    impl Constraint for EastClosed {
        fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
            if segment.start_m.x.max(segment.end_m.x) + segment.margin_m > 50.0 {
                Err(ConstraintViolation::Land)
            } else {
                Ok(())
            }
        }
    }
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let target = TargetState::constant_velocity(VesselState::new(
        DVec2::new(0.0, 1500.0),
        std::f64::consts::PI,
        6.0,
        50.0,
    ));
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), vec![target]);
    let model = vorrt_planner::jfs::RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let search = EvasionSearch {
        horizon_s: 600.0,
        courses: 72,
        clearance_m: 200.0,
        model: &model,
        speed_change_mps2: 0.02,
    };
    let (open_leg, open) =
        evasive_leg_constrained(&problem, &search, None, &vorrt_planner::NoConstraint);
    assert!(vorrt_planner::geometry::angle::signed_turn(0.0, open.course_rad) > 0.0);
    assert!(
        open_leg.end_m().x > 50.0,
        "in open sea it turns to starboard"
    );
    let (leg, closed) = evasive_leg_constrained(&problem, &search, None, &EastClosed);
    assert!(
        leg.pieces(0.0)
            .all(|piece| piece.start_m.x <= 50.0 && piece.end_m().x <= 50.0),
        "{closed:?}"
    );
}

#[test]
fn most_circles_across_the_route_are_planned_around() {
    // So that the property above cannot pass on failures alone.
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 60.0);
    let goal_m = DVec2::new(0.0, 10_000.0);
    let problem = PlanningProblem::new(own, goal_m, vec![]);
    let mut found = 0;
    let mut tried = 0;
    for along_m in [3000.0, 5000.0, 7000.0] {
        for offset_m in [-600.0, 0.0, 600.0] {
            for radius_m in [400.0, 900.0] {
                tried += 1;
                let circle = NoGoCircle {
                    centre_m: DVec2::new(offset_m, along_m),
                    radius_m,
                };
                let mut planner =
                    Planner::with_constraint(PlannerConfig::default(), circle).unwrap();
                if let Ok(plan) = planner.plan(&problem, tried) {
                    assert!(least_clearance_m(&plan, &circle) >= -1e-6);
                    found += 1;
                }
            }
        }
    }
    assert!(found * 10 >= tried * 9, "{found} of {tried}");
}
