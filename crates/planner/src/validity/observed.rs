//! A leg's turn as an observer of course over ground sees it (decision 57).
//!
//! The evaluation judges a port turn toward a vessel
//! ([`is_port_turn_toward_vessel`](vorrt_colregs::rules::is_port_turn_toward_vessel))
//! on the observed states at the latch: ownship's course over ground over
//! the last observation window (the chord of the last minute, a heading
//! about half a window old in a turn), and the course before found by
//! [`steady_course_rad`](vorrt_colregs::rules::steady_course_rad) on those courses over ground, which looks back a
//! window and then at most [`STEADY_TURN_SEARCH_S`] through a turn. In a
//! long port turn (more than 120° at 0.5°/s) that search ends part way
//! round, and the lagging course over ground is still swinging when a
//! vessel comes within MTD: the steered course the planner checks is then
//! not the course judged. This works out the judged pair from the leg
//! itself, with the same [`steady_course_rad`](vorrt_colregs::rules::steady_course_rad).

use glam::DVec2;
use vorrt_colregs::rules::{STEADY_COURSE_WINDOW_S, STEADY_TURN_SEARCH_S, steady_course_rad_of};
use vorrt_geometry::angle;
use vorrt_jfs::motion::LegPoses;

/// How often the observer samples ownship's track, seconds: the step of
/// the campaigns' closed loop (`vorrt batch`, 5 s).
pub(crate) const OBSERVED_STEP_S: f64 = 5.0;

/// Ownship's position `elapsed_s` after `leg`'s start; before it, straight
/// back along the leg's start course at its start speed (the course held
/// before the leg).
fn position_at(poses: &LegPoses, elapsed_s: f64) -> DVec2 {
    let leg = poses.leg();
    if elapsed_s >= 0.0 {
        poses.pose_at(elapsed_s).position_m
    } else {
        leg.start_m + angle::velocity(leg.start_course_rad, leg.speed_at(0.0)) * elapsed_s
    }
}

/// Ownship's course over ground `elapsed_s` after `leg`'s start, over the
/// last observation window ([`STEADY_COURSE_WINDOW_S`]).
fn course_over_ground_rad(poses: &LegPoses, elapsed_s: f64) -> f64 {
    let chord =
        position_at(poses, elapsed_s) - position_at(poses, elapsed_s - STEADY_COURSE_WINDOW_S);
    if chord.length_squared() > 0.0 {
        angle::unit_to_course(chord.normalize())
    } else {
        poses.leg().course_at(elapsed_s)
    }
}

/// What an observer of `leg`'s track sees `elapsed_s` after its start:
/// ownship's course over ground then, and, once the turn search can no
/// longer reach back to the leg's start, the course it held before any
/// turn ([`steady_course_rad`](vorrt_colregs::rules::steady_course_rad) on the courses over ground sampled every
/// [`OBSERVED_STEP_S`] back over a window and the turn search), radians.
/// Before that the course before is the leg's start course (the course
/// held before it), which the caller judges from already.
pub(crate) fn observed_turn_rad(poses: &LegPoses<'_>, elapsed_s: f64) -> (f64, Option<f64>) {
    // `poses` are the leg's, asked at up to 146 times (decision 62's
    // samples) at every piece.
    let now_rad = course_over_ground_rad(poses, elapsed_s);
    // The search looks back a window, then through the turn at most
    // `STEADY_TURN_SEARCH_S`, and a course over ground lags by up to a
    // window more: within that span of the leg's start it reaches the
    // course held before the leg.
    let span_s = 2.0 * STEADY_COURSE_WINDOW_S + STEADY_TURN_SEARCH_S;
    if elapsed_s <= span_s - STEADY_COURSE_WINDOW_S {
        return (now_rad, None);
    }
    // Samples back to the furthest the steady course looks, oldest first,
    // each course over ground worked out only if the search reaches it
    // (most stop a step back, on a course held: decision 62).
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a small positive count of steps"
    )]
    let steps = (span_s / OBSERVED_STEP_S).ceil() as usize;
    let time_s = |index: usize| {
        #[expect(clippy::cast_precision_loss, reason = "a small count of steps")]
        let back_s = (steps - index) as f64 * OBSERVED_STEP_S;
        elapsed_s - back_s
    };
    // Courses over ground already carry the window's lag; the judge still
    // looks back a window on them (`judge_turn_into_encounter`).
    let before_rad = steady_course_rad_of(
        steps + 1,
        time_s,
        |index| course_over_ground_rad(poses, time_s(index)),
        STEADY_COURSE_WINDOW_S,
    );
    (now_rad, before_rad)
}

#[cfg(test)]
mod tests {
    use super::*;
    use vorrt_jfs::Leg;

    /// A 160° port turn at 0.5°/s lasts 320 s: the course over ground lags
    /// the heading by about half a window, and once the turn search no
    /// longer reaches the turn's start the observer's course before is
    /// part way round.
    #[test]
    fn a_long_turn_is_judged_from_part_way_round() {
        let speed_mps = 6.0;
        let from = vorrt_jfs::Pose {
            position_m: DVec2::ZERO,
            course_rad: 135f64.to_radians(),
        };
        // 0.5°/s at 6 m/s: a radius of v / ω.
        let radius_m = speed_mps / 0.5f64.to_radians();
        let leg = Leg::turning_onto(from, 335f64.to_radians(), radius_m, speed_mps, 6_000.0);
        let turn_s = leg.turn_duration_s();
        assert!((turn_s - 320.0).abs() < 1.0, "{turn_s}");
        let (now_rad, _) = observed_turn_rad(&LegPoses::new(&leg), turn_s);
        let heading_rad = leg.pose_at(turn_s).course_rad;
        let lag_deg = angle::normalize_pi(now_rad - heading_rad).to_degrees();
        assert!((lag_deg - 15.0).abs() < 2.0, "{lag_deg}");
        // Half a window after the turn's end the search, a window back and
        // then 240 s through the turn, ends about 50 s into it: the course
        // over ground there, some 10° round from 135°.
        let (_, before_rad) = observed_turn_rad(&LegPoses::new(&leg), turn_s + 30.0);
        let before_deg = before_rad.expect("past the search span").to_degrees();
        assert!(before_deg < 130.0 && before_deg > 115.0, "{before_deg}");
        // Long after the turn: the new course, steady.
        let (now_rad, before_rad) = observed_turn_rad(&LegPoses::new(&leg), turn_s + 400.0);
        assert!(angle::normalize_pi(now_rad - 335f64.to_radians()).abs() < 1e-6);
        let before_rad = before_rad.expect("past the search span");
        assert!(angle::normalize_pi(before_rad - 335f64.to_radians()).abs() < 1e-6);
        // Early in the turn the search reaches the leg's start: the caller's.
        assert_eq!(observed_turn_rad(&LegPoses::new(&leg), 100.0).1, None);
    }
}
