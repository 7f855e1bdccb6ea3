//! Tests of the planner's search.

use super::*;
use crate::{Compliance, PlanSource};
use vorrt_colregs::VesselState;
use vorrt_jfs::TargetState;

/// The smallest distance between hulls along `plan`, sampled every 2 s,
/// to a target on `track`.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_precision_loss,
    reason = "a plan's duration is finite and positive, a few thousand 2 s steps"
)]
fn min_hull_distance_m(plan: &Plan, track: &LinearTrack, own_length_m: f64) -> f64 {
    let contact_m = vorrt_colregs::rules::contact_range_m(own_length_m, track.vessel.length_m);
    let steps = (plan.duration_s() / 2.0).ceil() as usize;
    (0..=steps)
        .filter_map(|step| {
            let elapsed_s = step as f64 * 2.0;
            let pose = plan.pose_at(elapsed_s)?;
            Some(pose.position_m.distance(track.position_at(elapsed_s)) - contact_m)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn the_manoeuvre_passes_at_the_preferred_distance_where_sea_room_allows() {
    // A vessel lying still 330 m east of ownship's route north, its hull
    // 255 m off ownship's: d_th (200 m) is kept on the route itself.
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    let target =
        TargetState::constant_velocity(VesselState::new(DVec2::new(330.0, 6000.0), 0.0, 0.0, 50.0));
    let track = target.track();
    let problem = PlanningProblem::new(own, DVec2::new(0.0, 12_000.0), vec![target]);
    let pass_m = |factor: f64| {
        let config = PlannerConfig {
            preferred_clearance_factor: factor,
            ..PlannerConfig::default()
        };
        let plan = Planner::new(config).unwrap().plan(&problem, 7).unwrap();
        min_hull_distance_m(&plan, &track, own.length_m)
    };
    let (preferred, floor) = (pass_m(2.0), pass_m(1.0));
    let clearance_m = PlannerConfig::default().clearance_m;
    // The chords of the turns are within a few metres of the arcs.
    assert!(preferred >= 2.0 * clearance_m - 5.0, "{preferred} m");
    assert!(floor >= clearance_m - 5.0, "{floor} m");
    assert!(floor < preferred, "{floor} m vs {preferred} m");
}

/// A goal no path reaches (a vessel lies stopped on it), with phases
/// that end on their sample budget.
fn blocked() -> (PlanningProblem, PlannerConfig) {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let goal_m = DVec2::new(0.0, 3000.0);
    let blocker = TargetState::constant_velocity(VesselState::new(goal_m, 0.0, 0.0, 50.0));
    let config = PlannerConfig {
        nodes_per_phase: 40,
        samples_per_phase: 40,
        nodes_per_route_step: 0.0,
        max_restarts: 1,
        ..PlannerConfig::default()
    };
    (PlanningProblem::new(own, goal_m, vec![blocker]), config)
}

fn samples_of(result: Result<Plan, PlannerError>) -> u64 {
    result
        .expect_err("the goal is blocked")
        .statistics()
        .expect("a failed search says what it did")
        .samples
}

#[test]
fn first_phase_effort_skips_phase_two_and_keeps_the_restarts() {
    let (problem, config) = blocked();
    let mut planner = Planner::new(config).expect("valid");
    let full = samples_of(planner.plan(&problem, 3));
    let first = samples_of(planner.plan_with(&problem, 3, SearchEffort::FirstPhase));
    // Two attempts (one restart) of two phases, or of one, 40 samples each.
    assert_eq!(full, 2 * 2 * 40);
    assert_eq!(first, 2 * 40);
    // The default effort is the full search, as `plan` runs it.
    assert_eq!(
        samples_of(planner.plan_with(&problem, 3, SearchEffort::default())),
        full
    );
}

/// A circle ownship must keep out of.
struct NoGoCircle {
    centre_m: DVec2,
    radius_m: f64,
}

impl Constraint for NoGoCircle {
    fn check_segment(
        &self,
        segment: &crate::constraint::Segment,
    ) -> Result<(), crate::constraint::ConstraintViolation> {
        if segment.distance_to_m(self.centre_m) < self.radius_m + segment.margin_m {
            Err(crate::constraint::ConstraintViolation::NoGoArea)
        } else {
            Ok(())
        }
    }

    fn admits_point(&self, point_m: DVec2) -> bool {
        point_m.distance(self.centre_m) >= self.radius_m
    }
}

#[test]
fn a_search_where_constrained_grows_a_tree_only_where_the_constraint_refused() {
    let (problem, config) = blocked();
    // Traffic alone refuses the manoeuvres from the root: no tree.
    let mut open = Planner::new(config).expect("valid");
    assert_eq!(
        samples_of(open.plan_with(&problem, 3, SearchEffort::FullWhereConstrained)),
        0
    );
    assert_eq!(
        samples_of(open.plan_with(&problem, 3, SearchEffort::FirstPhaseWhereConstrained)),
        0
    );
    assert_eq!(samples_of(open.plan(&problem, 3)), 2 * 2 * 40);
    // With instantaneous turns there is no search from the root: the tree
    // is the search.
    let instant = PlannerConfig {
        turning: Turning::Instant,
        ..config
    };
    let mut paper = Planner::new(instant).expect("valid");
    assert_eq!(
        samples_of(paper.plan_with(&problem, 3, SearchEffort::FullWhereConstrained)),
        2 * 2 * 40
    );
    // A no-go circle beside the route refuses some of them too: the tree
    // is the one the effort that always grows it grows.
    let circle = || NoGoCircle {
        centre_m: DVec2::new(-600.0, 1500.0),
        radius_m: 400.0,
    };
    let mut near_land = Planner::with_constraint(config, circle()).expect("valid");
    let grown = near_land.plan_with(&problem, 3, SearchEffort::FullWhereConstrained);
    let rejections = grown
        .as_ref()
        .expect_err("blocked")
        .statistics()
        .expect("statistics")
        .rejections;
    assert!(
        rejections.get(RejectionCause::Constraint(
            crate::constraint::ConstraintViolation::NoGoArea
        )) > 0
    );
    assert_eq!(samples_of(grown), 2 * 2 * 40);
    assert_eq!(
        samples_of(near_land.plan_with(&problem, 3, SearchEffort::FirstPhaseWhereConstrained)),
        2 * 40
    );
}

#[test]
fn a_full_search_replays_a_stricter_one_that_grew_no_tree() {
    let (problem, config) = crossing_onto_a_blocked_goal();
    let mut strict = Planner::new(config).expect("valid");
    assert!(
        strict
            .plan_with(&problem, 3, SearchEffort::FullWhereConstrained)
            .is_err()
    );
    let weaker = PlannerConfig {
        compliance: Compliance::SafetyOnly,
        ..config
    };
    let statistics = |result: Result<Plan, PlannerError>| {
        *result
            .expect_err("blocked")
            .statistics()
            .expect("statistics")
    };
    let alone = statistics(Planner::new(weaker).expect("valid").plan(&problem, 3));
    let mut after = Planner::new(weaker).expect("valid");
    let replayed = statistics(after.plan_after(&problem, 3, SearchEffort::Full, &strict));
    // The search that always grows the tree, bit for bit, for less judging.
    assert_eq!(alone.samples, replayed.samples);
    assert_eq!(alone.nodes, replayed.nodes);
    assert_eq!(alone.rejections, replayed.rejections);
    assert!(after.verdicts_replayed() > 0);
    // Only that way round: an earlier search that always grew its tree is
    // not replayed by one that may not (the graded fallback asks the
    // lighter search first).
    let mut full_first = Planner::new(config).expect("valid");
    assert!(full_first.plan(&problem, 3).is_err());
    let mut lighter = Planner::new(weaker).expect("valid");
    assert!(
        lighter
            .plan_after(&problem, 3, SearchEffort::FullWhereConstrained, &full_first)
            .is_err()
    );
    assert_eq!(lighter.verdicts_replayed(), 0);
}

/// A crossing from starboard whose goal lies beyond a vessel lying stopped
/// on it: every level fails, the full one with refusals of every kind.
fn crossing_onto_a_blocked_goal() -> (PlanningProblem, PlannerConfig) {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let goal_m = DVec2::new(0.0, 3000.0);
    let blocker = TargetState::constant_velocity(VesselState::new(goal_m, 0.0, 0.0, 50.0));
    let crossing = TargetState::constant_velocity(VesselState::new(
        DVec2::new(1500.0, 1500.0),
        270f64.to_radians(),
        6.0,
        50.0,
    ));
    let config = PlannerConfig {
        nodes_per_phase: 60,
        samples_per_phase: 300,
        nodes_per_route_step: 0.0,
        max_restarts: 1,
        ..PlannerConfig::default()
    };
    (
        PlanningProblem::new(own, goal_m, vec![blocker, crossing]),
        config,
    )
}

#[test]
fn a_weaker_level_after_a_failed_one_replays_its_verdicts_and_fails_the_same() {
    let (problem, config) = crossing_onto_a_blocked_goal();
    let mut full = Planner::new(config).expect("valid");
    assert!(full.plan(&problem, 3).is_err());
    for compliance in [
        Compliance::Full,
        Compliance::Directions,
        Compliance::SafetyOnly,
    ] {
        let weaker = PlannerConfig {
            compliance,
            ..config
        };
        let alone = Planner::new(weaker).expect("valid").plan(&problem, 3);
        let mut after = Planner::new(weaker).expect("valid");
        let replayed = after.plan_after(&problem, 3, SearchEffort::Full, &full);
        // The same failure, the same samples, nodes and refusals by cause.
        let statistics = |result: &Result<Plan, PlannerError>| {
            *result
                .as_ref()
                .expect_err("blocked")
                .statistics()
                .expect("statistics")
        };
        let (alone, replayed) = (statistics(&alone), statistics(&replayed));
        assert_eq!(alone.samples, replayed.samples, "{compliance:?}");
        assert_eq!(alone.nodes, replayed.nodes, "{compliance:?}");
        assert_eq!(alone.rejections, replayed.rejections, "{compliance:?}");
        // With less judging: refusals of the full search were taken from it.
        assert!(after.verdicts_replayed() > 0, "{compliance:?}");
    }
    // Another seed is another search: nothing is replayed.
    let mut other = Planner::new(config).expect("valid");
    assert!(
        other
            .plan_after(&problem, 4, SearchEffort::Full, &full)
            .is_err()
    );
    assert_eq!(other.verdicts_replayed(), 0);
}

/// A generated open-sea encounter (`vorrt generate open-sea --targets 4
/// --seed 11 --behaviour constant`, scenario 61): ownship north 8.2 nm at
/// 13.7 kn among a vessel crossing from port, one head-on and two it
/// overtakes.
fn long_detour() -> PlanningProblem {
    const NM_M: f64 = 1852.0;
    const KN_MPS: f64 = 1852.0 / 3600.0;
    let vessel = |(east_nm, north_nm): (f64, f64), course_deg: f64, speed_kn: f64, length_m| {
        VesselState::new(
            DVec2::new(east_nm, north_nm) * NM_M,
            f64::to_radians(course_deg),
            speed_kn * KN_MPS,
            length_m,
        )
    };
    let own = vessel((0.0, 0.0), 0.0, 13.7, 100.0);
    let targets = [
        vessel((-1.2827, 2.7287), 111.220_322_308_141_85, 8.7, 91.0),
        vessel((0.2944, 0.7312), 347.049_489_551_384_7, 8.4, 198.0),
        vessel((0.079, 8.6423), 178.530_182_957_030_52, 10.22, 216.0),
        vessel((-0.2241, 3.0952), 10.948_156_940_375_286, 5.65, 213.0),
    ]
    .map(TargetState::constant_velocity)
    .to_vec();
    PlanningProblem::new(own, DVec2::new(0.0, 8.2 * NM_M), targets)
}

#[test]
fn a_long_detour_of_one_alteration_is_compared_with_two_alterations() {
    let problem = long_detour();
    let straight_m = problem.ownship.position_m.distance(problem.goal_m);
    let plan = Planner::new(PlannerConfig::default())
        .unwrap()
        .plan(&problem, 1)
        .unwrap();
    // The one alteration that keeps every rule sailed 24.9 km of a 15.2 km
    // route (64 % more); keeping the course, then acting, sailed 16.8 km.
    // Since decision 74 the action after the course kept is a turn that
    // latches the vessel met head-on 8.6 nm off as well, to be held until
    // she is past: no shorter than one alteration, which now wins, 26.1 km
    // (72 % more). Both are still searched and compared: the plan is one
    // of the two, and no longer than the one alteration.
    assert!(
        matches!(
            plan.statistics.source,
            PlanSource::OneAlteration | PlanSource::TwoAlterations
        ),
        "{:?}",
        plan.statistics.source
    );
    assert!(
        plan.length_m() < 1.75 * straight_m,
        "{} m of {straight_m} m",
        plan.length_m()
    );
    // It keeps d_th from every vessel (between hulls, sampled every 2 s).
    for target in &problem.targets {
        let pass_m = min_hull_distance_m(&plan, &target.track(), problem.ownship.length_m);
        assert!(
            pass_m >= PlannerConfig::default().clearance_m - 5.0,
            "{pass_m} m"
        );
    }
}
