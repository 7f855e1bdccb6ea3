//! The closed loop keeps a user constraint: ownship's planner, at every
//! level of the graded fallback, its check of the plan in force and its
//! evasive manoeuvre all keep it, so the track sailed does too.

use vorrt_scenarios::planner::glam::DVec2;
use vorrt_scenarios::planner::{Constraint, ConstraintViolation, Segment};
use vorrt_scenarios::{ClosedLoop, evaluate, fixtures};

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

#[test]
fn a_run_with_a_no_go_circle_on_its_route_sails_around_it() {
    let scenario = fixtures::find("paper/crossing")
        .expect("bundled")
        .load()
        .expect("loads");
    let config = scenario.planner_config().expect("valid");
    let start_m = scenario.ownship_state().position_m;
    let goal_m = scenario.ownship_goal_m();
    // A 500 m circle on the track the open-sea run sails, a third of the
    // way along it.
    let open = ClosedLoop::new(&scenario, 1).expect("valid").run();
    let circle = NoGoCircle {
        centre_m: open.ownship[open.ownship.len() / 3].position_m,
        radius_m: 500.0,
    };
    assert!(circle.admits_point(start_m) && circle.admits_point(goal_m));
    let least_m = |record: &vorrt_scenarios::SimulationRecord| {
        record
            .ownship
            .iter()
            .map(|own| own.position_m.distance(circle.centre_m) - circle.radius_m)
            .fold(f64::INFINITY, f64::min)
    };
    assert!(least_m(&open) < 0.0, "the open-sea run sails through it");

    let motions = ClosedLoop::scenario_motions(&scenario, 1);
    let record = ClosedLoop::with_constraint(&scenario, &config, 1, motions, circle)
        .expect("valid")
        .run();
    assert!(record.reached_goal);
    assert!(!record.plans.is_empty());
    assert!(least_m(&record) >= 0.0, "{} m inside", -least_m(&record));
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.success(), "{evaluation:?}");
}
