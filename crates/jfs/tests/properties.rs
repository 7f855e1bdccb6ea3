//! Property tests of the joint forward simulation: target prediction (notes,
//! erratum 9) and the joint step (paper §III-D, Algorithm 2 line 5).

use proptest::prelude::*;
use std::f64::consts::TAU;
use vorrt_colregs::VesselState;
use vorrt_geometry::{DVec2, angle};
use vorrt_jfs::{JointState, TargetState, step_ownship};

const LENGTH_M: f64 = 60.0;

fn position() -> impl Strategy<Value = DVec2> {
    (-20_000.0..20_000.0f64, -20_000.0..20_000.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

fn speed() -> impl Strategy<Value = f64> {
    0.5..15.0f64
}

fn duration() -> impl Strategy<Value = f64> {
    0.0..5_000.0f64
}

fn vessel() -> impl Strategy<Value = VesselState> {
    (position(), 0.0..TAU, speed())
        .prop_map(|(position, course, speed)| VesselState::new(position, course, speed, LENGTH_M))
}

/// A target that holds course and speed, one bound for a goal, or one that
/// holds its course for a while and then steers for its goal.
fn target() -> impl Strategy<Value = TargetState> {
    prop_oneof![
        vessel().prop_map(TargetState::constant_velocity),
        (vessel(), position()).prop_map(|(vessel, goal)| TargetState::toward_goal(vessel, goal)),
        (vessel(), position(), duration()).prop_map(|(vessel, goal, hold_s)| {
            TargetState::holding_course_then_toward_goal(vessel, goal, hold_s)
        }),
    ]
}

/// Positions agree to a millimetre-scale tolerance relative to their size.
fn near(a: DVec2, b: DVec2) -> bool {
    a.distance(b) <= 1e-9 * (1.0 + a.length().max(b.length()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A target without a goal holds course and speed: after t seconds it is
    /// at P + V t, with course and speed unchanged.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn constant_velocity_target_moves_speed_times_time(vessel in vessel(), duration_s in duration()) {
        let predicted = TargetState::constant_velocity(vessel).predict(duration_s);
        let expected = vessel.position_m + vessel.velocity_mps() * duration_s;
        prop_assert!(near(predicted.vessel.position_m, expected));
        prop_assert_eq!(predicted.vessel.course_rad, vessel.course_rad);
        prop_assert_eq!(predicted.vessel.speed_mps, vessel.speed_mps);
    }

    /// Before it arrives, a goal-bound target covers speed x time along the
    /// straight line to its goal.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn goal_bound_target_moves_speed_times_time_before_arrival(
        vessel in vessel(), goal in position(), fraction in 0.0..0.999f64,
    ) {
        let target = TargetState::toward_goal(vessel, goal);
        prop_assume!(vessel.position_m.distance(goal) > 1.0);
        let arrival_s = target.time_to_goal_s().expect("moving target reaches its goal");
        let duration_s = fraction * arrival_s;
        let predicted = target.predict(duration_s);
        let travelled = vessel.speed_mps * duration_s;
        let expected = vessel.position_m + (goal - vessel.position_m).normalize() * travelled;
        prop_assert!(near(predicted.vessel.position_m, expected));
        prop_assert!(
            (predicted.vessel.position_m.distance(vessel.position_m) - travelled).abs()
                <= 1e-9 * (1.0 + travelled)
        );
        prop_assert_eq!(predicted.vessel.speed_mps, vessel.speed_mps);
        prop_assert!(!predicted.has_arrived());
    }

    /// Erratum 9: a target stops at its goal. After any duration it lies on
    /// the segment start -> goal, its distance to the goal never grows with
    /// time, and once the arrival time has passed it is at the goal, stopped.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn goal_bound_target_never_overshoots(
        vessel in vessel(), goal in position(), first_s in duration(), extra_s in duration(),
    ) {
        let target = TargetState::toward_goal(vessel, goal);
        let start = vessel.position_m;
        let track = goal - start;
        let scale = 1e-9 * (1.0 + start.length().max(goal.length()));
        let earlier = target.predict(first_s);
        let later = target.predict(first_s + extra_s);
        for predicted in [&earlier, &later] {
            let offset = predicted.vessel.position_m - start;
            // On the line through start and goal ...
            prop_assert!(track.perp_dot(offset).abs() <= scale * (1.0 + track.length()));
            // ... and between them.
            prop_assert!(offset.dot(track) >= -scale * (1.0 + track.length()));
            prop_assert!(offset.length() <= track.length() + scale);
        }
        prop_assert!(
            later.vessel.position_m.distance(goal) <= earlier.vessel.position_m.distance(goal) + scale
        );
        if let Some(arrival_s) = target.time_to_goal_s()
            && first_s + extra_s >= arrival_s
        {
            prop_assert_eq!(later.vessel.position_m, goal);
            prop_assert_eq!(later.vessel.speed_mps, 0.0);
        }
    }

    /// Prediction is memoryless: predicting a + b seconds equals predicting a
    /// and then b (the planner predicts targets from its root to any node).
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn prediction_composes(target in target(), first_s in duration(), second_s in duration()) {
        let at_once = target.predict(first_s + second_s);
        let in_two = target.predict(first_s).predict(second_s);
        let tolerance = 1e-6;
        prop_assert!(
            at_once.vessel.position_m.distance(in_two.vessel.position_m) <= tolerance,
            "{:?} vs {:?}", at_once.vessel.position_m, in_two.vessel.position_m
        );
        prop_assert_eq!(at_once.goal_m, in_two.goal_m);
        // Speeds agree too, except within rounding of the arrival instant,
        // where one path may have stopped and the other not quite.
        let at_arrival = at_once
            .goal_m
            .is_some_and(|goal| at_once.vessel.position_m.distance(goal) <= tolerance);
        if !at_arrival {
            prop_assert_eq!(at_once.vessel.speed_mps, in_two.vessel.speed_mps);
        }
    }

    /// The planner's linear track of a target is the same motion as its
    /// closed-form prediction: same position, and zero velocity once stopped.
    #[test]
    fn linear_track_follows_prediction(target in target(), elapsed_s in duration()) {
        let track = target.track();
        let predicted = target.predict(elapsed_s);
        prop_assert!(near(track.position_at(elapsed_s), predicted.vessel.position_m),
            "{:?} vs {:?}", track.position_at(elapsed_s), predicted.vessel.position_m);
        if predicted.vessel.speed_mps == 0.0 {
            prop_assert!(track.position_at(elapsed_s + 100.0).distance(predicted.vessel.position_m) <= 1e-6);
        } else {
            prop_assert!(
                (track.velocity_at(elapsed_s) - predicted.vessel.velocity_mps()).length() <= 1e-9
            );
        }
    }

    /// The JFS step (Algorithm 2, line 5): ownship moves exactly d' toward the
    /// sample, or onto it when it is nearer, on the course toward it, in
    /// distance / speed seconds.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn ownship_step_moves_exactly_the_step_length(
        own in vessel(), point in position(), step_m in 1.0..1_000.0f64,
    ) {
        let step = step_ownship(&own, point, step_m).expect("valid step");
        let distance = own.position_m.distance(point);
        let moved = step.ownship.position_m.distance(own.position_m);
        if distance <= step_m {
            prop_assert_eq!(step.ownship.position_m, point);
        } else {
            prop_assert!((moved - step_m).abs() <= 1e-9 * (1.0 + own.position_m.length()));
            // Still on the way to the point, by the remaining distance.
            prop_assert!(
                (step.ownship.position_m.distance(point) - (distance - step_m)).abs()
                    <= 1e-9 * (1.0 + own.position_m.length() + point.length())
            );
        }
        prop_assert!((step.duration_s - distance.min(step_m) / own.speed_mps).abs() <= 1e-9);
        prop_assert_eq!(step.ownship.speed_mps, own.speed_mps);
        if distance > 0.0 {
            let heading = angle::course_to_unit(step.ownship.course_rad);
            prop_assert!((heading - (point - own.position_m) / distance).length() <= 1e-9);
        }
    }

    /// Joint step: every target moves for the same duration as ownship, and
    /// the joint state's clock advances by it.
    #[test]
    fn targets_move_for_the_ownship_step_duration(
        time_s in 0.0..10_000.0f64, own in vessel(),
        targets in prop::collection::vec(target(), 0..5),
        point in position(), step_m in 1.0..1_000.0f64,
    ) {
        let state = JointState::new(time_s, own, targets.clone());
        let next = state.step_toward(point, step_m).expect("valid step");
        let step = step_ownship(&own, point, step_m).expect("valid step");
        prop_assert_eq!(next.ownship, step.ownship);
        prop_assert!((next.time_s - (time_s + step.duration_s)).abs() <= 1e-9 * (1.0 + time_s));
        prop_assert_eq!(next.targets.len(), targets.len());
        for (before, after) in targets.iter().zip(&next.targets) {
            prop_assert_eq!(*after, before.predict(step.duration_s));
            if before.goal_m.is_none() {
                let expected = before.vessel.position_m + before.vessel.velocity_mps() * step.duration_s;
                prop_assert!(near(after.vessel.position_m, expected));
            }
        }
    }
}
