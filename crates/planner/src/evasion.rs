//! The course to steer when no safe path is found: the evasive fallback.
//!
//! VORRT can fail (every phase of every restart rejected), and a closed loop
//! must still steer something until it plans again. Holding course into a
//! target is the worst choice; [`evasive_course`] instead tries every course
//! at a fixed spacing and keeps the one whose closest approach to any target
//! over a horizon is largest — a collision-avoidance manoeuvre that ignores
//! the goal and the COLREGs preferences except one: among equally good
//! courses, the smallest turn wins, and a starboard turn before a port one
//! (rules 8 and 17(b): any action that best aids to avoid collision).

use crate::problem::PlanningProblem;
use crate::safety::min_distance_over;
use serde::{Deserialize, Serialize};
use vorrt_colregs::rules::contact_range_m;
use vorrt_geometry::angle;
use vorrt_jfs::{InstantTurn, Leg, MotionModel, Pose};

/// A course to steer and what it is expected to keep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EvasiveManeuver {
    /// The course, radians.
    pub course_rad: f64,
    /// The smallest distance between the hulls of ownship and any target over
    /// the horizon on that course, metres (reference points less half the sum
    /// of the lengths, as `d_th` is measured).
    pub min_distance_m: f64,
}

/// Among `courses` evenly spaced courses (e.g. 72 for 5°), tried in order of
/// the turn from the present course (0, +5°, -5°, +10°, ...), the first that
/// keeps at least `clearance_m` from every target over `horizon_s` — ownship
/// holding it at its speed, the targets moving as predicted — or, if none
/// does, the one that keeps farthest. With no target, the present course.
///
/// ```
/// use vorrt_planner::{evasive_course, PlanningProblem};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::TargetState;
/// use glam::DVec2;
/// // A target dead ahead coming straight at ownship: turning away beats holding on.
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let target = TargetState::constant_velocity(
///     VesselState::new(DVec2::new(0.0, 1500.0), std::f64::consts::PI, 6.0, 50.0));
/// let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), vec![target]);
/// let evasion = evasive_course(&problem, 600.0, 72, 200.0);
/// assert!(evasion.min_distance_m >= 200.0);
/// assert!(vorrt_geometry::angle::signed_turn(0.0, evasion.course_rad) > 0.0); // to starboard
/// ```
#[must_use]
pub fn evasive_course(
    problem: &PlanningProblem,
    horizon_s: f64,
    courses: usize,
    clearance_m: f64,
) -> EvasiveManeuver {
    let instant = InstantTurn {
        max_turn_rad: std::f64::consts::PI,
    };
    evasive_leg(problem, horizon_s, courses, clearance_m, &instant).1
}

/// As [`evasive_course`], for a vessel that turns as `model` says: each
/// course is judged along the curve sailed to take it (the turn, then the
/// straight run) for `horizon_s`, and the leg to sail is returned with it.
#[must_use]
pub fn evasive_leg<M: MotionModel>(
    problem: &PlanningProblem,
    horizon_s: f64,
    courses: usize,
    clearance_m: f64,
    model: &M,
) -> (Leg, EvasiveManeuver) {
    let own = problem.ownship;
    let from = Pose {
        position_m: own.position_m,
        course_rad: own.course_rad,
    };
    let tracks: Vec<_> = problem
        .targets
        .iter()
        .map(|target| target.track())
        .collect();
    let leg_for = |course_rad: f64| {
        let mut leg = model.turn_onto(from, course_rad, own.speed_mps, 0.0);
        leg.straight_m = ((horizon_s - leg.turn_duration_s()).max(0.0)) * own.speed_mps;
        leg
    };
    let keep = |leg: &Leg| {
        let margin_m = leg.chord_error_m();
        leg.pieces(0.0)
            .map(|piece| {
                tracks
                    .iter()
                    .map(|track| {
                        min_distance_over(
                            piece.start_m,
                            piece.velocity_mps,
                            track,
                            piece.elapsed_s,
                            piece.duration_s,
                        ) - contact_range_m(own.length_m, track.vessel.length_m)
                            - if piece.turning { margin_m } else { 0.0 }
                    })
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let hold = leg_for(own.course_rad);
    let mut best = (
        hold,
        EvasiveManeuver {
            course_rad: own.course_rad,
            min_distance_m: keep(&hold),
        },
    );
    if best.1.min_distance_m >= clearance_m {
        return best;
    }
    let courses = courses.max(1);
    let spacing = std::f64::consts::TAU / courses as f64;
    // Turns in order of size, starboard first: +s, -s, +2s, -2s, ...
    for step in 1..=courses / 2 {
        for sign in [1.0, -1.0] {
            let course_rad = angle::normalize_2pi(own.course_rad + sign * spacing * step as f64);
            let leg = leg_for(course_rad);
            let min_distance_m = keep(&leg);
            let maneuver = EvasiveManeuver {
                course_rad,
                min_distance_m,
            };
            if min_distance_m >= clearance_m {
                return (leg, maneuver);
            }
            if min_distance_m > best.1.min_distance_m {
                best = (leg, maneuver);
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use vorrt_colregs::VesselState;
    use vorrt_jfs::TargetState;

    #[test]
    fn no_target_holds_course() {
        let own = VesselState::new(DVec2::ZERO, 1.0, 6.0, 50.0);
        let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), vec![]);
        let evasion = evasive_course(&problem, 600.0, 72, 200.0);
        assert_eq!(evasion.course_rad, 1.0);
        assert!(evasion.min_distance_m.is_infinite());
    }

    #[test]
    fn evasion_never_keeps_less_than_holding_course() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let crossing = TargetState::constant_velocity(VesselState::new(
            DVec2::new(1200.0, 1200.0),
            1.5 * std::f64::consts::PI,
            6.0,
            50.0,
        ));
        let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), vec![crossing]);
        let hold = min_distance_over(
            own.position_m,
            own.velocity_mps(),
            &problem.targets[0].track(),
            0.0,
            600.0,
        );
        let evasion = evasive_course(&problem, 600.0, 72, 200.0);
        assert!(evasion.min_distance_m >= hold - contact_range_m(50.0, 50.0));
        assert!(evasion.min_distance_m >= 200.0, "{evasion:?}");
        // Asking for more clearance than any course gives: the farthest one.
        let farthest = evasive_course(&problem, 600.0, 72, 1e9);
        assert!(farthest.min_distance_m >= evasion.min_distance_m);
    }
}
