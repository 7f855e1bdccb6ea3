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
//!
//! When no course keeps the clearance at service speed, the same courses
//! are tried at half speed, then stopping ([`EVASION_SPEED_FACTORS`]; rule
//! 8(e): slacken speed or stop; MOOS-IvP's all-stop when turning can no
//! longer avoid a collision). Ownship changes speed at the configured rate
//! (`PlannerConfig::speed_change_rate_mps2`) and, once stopped, lies still
//! to the horizon's end.

use crate::constraint::{Constraint, NoConstraint, Segment};
use crate::problem::PlanningProblem;
use crate::safety::min_distance_over;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::rules::contact_range_m;
use vorrt_geometry::angle;
use vorrt_jfs::{InstantTurn, Leg, LinearTrack, MotionModel, Pose, TargetState};

/// A course to steer and what it is expected to keep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EvasiveManeuver {
    /// The course, radians.
    pub course_rad: f64,
    /// The speed settled at, m/s: the service speed, half of it, or 0 (stop).
    #[serde(default)]
    pub speed_mps: f64,
    /// The smallest distance between the hulls of ownship and any target over
    /// the horizon on that course, metres (reference points less half the sum
    /// of the lengths, as `d_th` is measured).
    pub min_distance_m: f64,
}

/// The speeds the evasive manoeuvre tries, as fractions of the service
/// speed, in order: full speed, half speed, stop.
pub const EVASION_SPEED_FACTORS: [f64; 3] = [1.0, 0.5, 0.0];

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
    evasive_leg(
        problem,
        horizon_s,
        courses,
        clearance_m,
        &instant,
        f64::INFINITY,
    )
    .1
}

/// As [`evasive_course`], for a vessel that turns as `model` says and
/// changes speed at `speed_change_mps2`: each course and speed is judged
/// along the curve sailed to take it (the turn, then the straight run, with
/// the speed changing from the present one) for `horizon_s`, and the leg to
/// sail is returned with it.
///
/// ```
/// use vorrt_planner::{evasive_leg, PlanningProblem};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{RateLimitedTurn, TargetState};
/// use glam::DVec2;
/// // Boxed in: 16 vessels lying still on a ring of 600 m. No course keeps
/// // 200 m over 10 minutes at 6 m/s or at 3 m/s; stopping does.
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let targets = (0..16).map(|k| {
///     let bearing = f64::from(k) * std::f64::consts::TAU / 16.0;
///     let at = 600.0 * DVec2::new(bearing.sin(), bearing.cos());
///     TargetState::constant_velocity(VesselState::new(at, 0.0, 0.0, 50.0))
/// }).collect();
/// let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), targets);
/// let model = RateLimitedTurn { turn_radius_m: 150.0 };
/// let (leg, evasion) = evasive_leg(&problem, 600.0, 72, 200.0, &model, 0.1);
/// assert_eq!(evasion.speed_mps, 0.0);
/// assert!(evasion.min_distance_m >= 200.0);
/// assert!((leg.length_m() - 180.0).abs() < 1e-6); // 6² / (2 · 0.1)
/// ```
#[must_use]
pub fn evasive_leg<M: MotionModel>(
    problem: &PlanningProblem,
    horizon_s: f64,
    courses: usize,
    clearance_m: f64,
    model: &M,
    speed_change_mps2: f64,
) -> (Leg, EvasiveManeuver) {
    evasive_leg_holding(
        problem,
        horizon_s,
        courses,
        clearance_m,
        model,
        speed_change_mps2,
        None,
    )
}

/// How much farther (metres) another course must keep from every target
/// than the evasive manoeuvre in force before [`evasive_leg_holding`]
/// abandons it, when neither keeps the clearance: a vessel that swings from
/// one evasive course to another as the predictions wander (rule 8(b): a
/// succession of alterations is not readily apparent, rule 8(e)) gets closer
/// than one that holds a course that keeps nearly as far.
pub const EVASION_HOLD_MARGIN_M: f64 = 100.0;

/// Whether the manoeuvre under way, keeping `held_m` from every target (by
/// the evasive manoeuvre's measure, `EvasiveManeuver::min_distance_m`), is
/// held rather than replaced by another keeping `other_m`: it keeps the
/// clearance, or it is not expected to touch (more than 0 m between the
/// hulls) and the other neither keeps the clearance nor keeps
/// [`EVASION_HOLD_MARGIN_M`] farther (decision 24; rule 8(b): one readily
/// apparent action, not a succession). The one judgement for an evasive
/// manoeuvre in force and for a plan in force that no longer passes the
/// validity check (decision 56).
#[must_use]
pub fn holds_manoeuvre_in_force(held_m: f64, other_m: f64, clearance_m: f64) -> bool {
    held_m >= clearance_m
        || (held_m > 0.0 && other_m < clearance_m && other_m < held_m + EVASION_HOLD_MARGIN_M)
}

/// As [`evasive_leg`], with the evasive manoeuvre in force, `holding`, tried
/// first: it is kept if it still keeps the clearance, or if no other course
/// and speed keeps the clearance nor keeps [`EVASION_HOLD_MARGIN_M`] farther.
///
/// ```
/// use vorrt_planner::{evasive_leg, evasive_leg_holding, PlanningProblem};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{RateLimitedTurn, TargetState};
/// use glam::DVec2;
/// // Boxed in by vessels lying still on a ring of 600 m: nothing keeps 200 m
/// // at speed; holding a course whose pass is nearly as good is kept.
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let targets = (0..16).map(|k| {
///     let bearing = f64::from(k) * std::f64::consts::TAU / 16.0;
///     let at = 600.0 * DVec2::new(bearing.sin(), bearing.cos());
///     TargetState::constant_velocity(VesselState::new(at, 0.0, 0.0, 50.0))
/// }).collect();
/// let problem = PlanningProblem::new(own, DVec2::new(0.0, 5000.0), targets);
/// let model = RateLimitedTurn { turn_radius_m: 150.0 };
/// let (_, best) = evasive_leg(&problem, 600.0, 72, 1000.0, &model, 0.1);
/// let mut holding = best;
/// holding.course_rad += 5f64.to_radians();
/// let (_, kept) = evasive_leg_holding(&problem, 600.0, 72, 1000.0, &model, 0.1, Some(holding));
/// assert_eq!(kept.course_rad, holding.course_rad);
/// ```
#[must_use]
pub fn evasive_leg_holding<M: MotionModel>(
    problem: &PlanningProblem,
    horizon_s: f64,
    courses: usize,
    clearance_m: f64,
    model: &M,
    speed_change_mps2: f64,
    holding: Option<EvasiveManeuver>,
) -> (Leg, EvasiveManeuver) {
    let search = EvasionSearch {
        horizon_s,
        courses,
        clearance_m,
        model,
        speed_change_mps2,
    };
    evasive_leg_constrained(problem, &search, holding, &NoConstraint)
}

/// What the evasive manoeuvre searches: how far ahead it judges, among how
/// many courses, for which clearance, sailed how.
#[derive(Debug, Clone, Copy)]
pub struct EvasionSearch<'a, M> {
    /// How far ahead each course and speed is judged, seconds.
    pub horizon_s: f64,
    /// How many evenly spaced courses are tried (72: every 5°).
    pub courses: usize,
    /// The distance between hulls a course must keep from every target to
    /// be taken at once, metres.
    pub clearance_m: f64,
    /// How ownship turns.
    pub model: &'a M,
    /// How fast ownship changes speed, m/s².
    pub speed_change_mps2: f64,
}

/// As [`evasive_leg_holding`], among the legs that keep `constraint` (land,
/// a no-go area: every piece of the leg sailed is checked as the validity
/// check does); only when none does, the best of all.
#[must_use]
pub fn evasive_leg_constrained<M: MotionModel, C: Constraint>(
    problem: &PlanningProblem,
    search: &EvasionSearch<'_, M>,
    holding: Option<EvasiveManeuver>,
    constraint: &C,
) -> (Leg, EvasiveManeuver) {
    let EvasionSearch {
        horizon_s,
        courses,
        clearance_m,
        model,
        speed_change_mps2,
    } = *search;
    let own = problem.ownship;
    let service_mps = problem.service_speed_mps();
    let from = Pose {
        position_m: own.position_m,
        course_rad: own.course_rad,
    };
    let tracks: Vec<_> = problem.targets.iter().map(TargetState::track).collect();
    let leg_for = |course_rad: f64, speed_mps: f64| {
        // Long enough for the horizon at the faster speed, then cut to it
        // (a leg that stops ends where ownship stops).
        let reach_m = horizon_s * own.speed_mps.max(speed_mps);
        model
            .turn_onto(from, course_rad, speed_mps, reach_m)
            .from_speed(own.speed_mps, speed_change_mps2)
            .until(horizon_s)
    };
    let keep = |leg: &Leg| leg_min_distance_m(leg, &tracks, own.length_m, horizon_s);
    let admitted = |leg: &Leg| leg_keeps_constraint(leg, constraint);
    let turns = turns_rad(courses);
    // The manoeuvre in force, judged afresh, first; it stays the best unless
    // another keeps the clearance or keeps clearly farther.
    let mut held: Option<(Leg, EvasiveManeuver)> = None;
    if let Some(holding) = holding {
        let leg = leg_for(holding.course_rad, holding.speed_mps);
        let maneuver = EvasiveManeuver {
            min_distance_m: keep(&leg),
            ..holding
        };
        if admitted(&leg) {
            if maneuver.min_distance_m >= clearance_m {
                return (leg, maneuver);
            }
            held = Some((leg, maneuver));
        }
    }
    // The farthest-keeping leg that keeps the constraint, and the
    // farthest-keeping of all (taken only when no leg keeps it).
    let mut refused: Option<(Leg, EvasiveManeuver)> = None;
    let mut best: Option<(Leg, EvasiveManeuver)> = None;
    for factor in EVASION_SPEED_FACTORS {
        let speed_mps = factor * service_mps;
        for turn_rad in turns.clone() {
            let course_rad = angle::normalize_2pi(own.course_rad + turn_rad);
            let leg = leg_for(course_rad, speed_mps);
            let min_distance_m = keep(&leg);
            let maneuver = EvasiveManeuver {
                course_rad,
                speed_mps,
                min_distance_m,
            };
            if !admitted(&leg) {
                if keeps_farther(refused.as_ref(), min_distance_m) {
                    refused = Some((leg, maneuver));
                }
                continue;
            }
            if min_distance_m >= clearance_m {
                return (leg, maneuver);
            }
            if keeps_farther(best.as_ref(), min_distance_m) {
                best = Some((leg, maneuver));
            }
        }
    }
    if let Some((leg, maneuver)) = held
        && best.as_ref().is_none_or(|(_, other)| {
            holds_manoeuvre_in_force(maneuver.min_distance_m, other.min_distance_m, clearance_m)
        })
    {
        return (leg, maneuver);
    }
    best.or(refused).unwrap_or_else(|| {
        let leg = leg_for(own.course_rad, service_mps);
        let maneuver = EvasiveManeuver {
            course_rad: own.course_rad,
            speed_mps: service_mps,
            min_distance_m: keep(&leg),
        };
        (leg, maneuver)
    })
}

/// The turns from the present course to try, radians, among `courses`
/// evenly spaced courses (at least one): holding on, then turns in order of
/// size, starboard first.
fn turns_rad(courses: usize) -> impl Iterator<Item = f64> + Clone {
    let courses = courses.max(1);
    #[expect(
        clippy::cast_precision_loss,
        reason = "a count of courses, far below 2^52"
    )]
    let spacing = std::f64::consts::TAU / courses as f64;
    // Holding on, then turns in order of size, starboard first: +s, -s, +2s,
    // -2s, ...
    #[expect(
        clippy::cast_precision_loss,
        reason = "a count of course steps, far below 2^52"
    )]
    let turns = std::iter::once(0.0).chain(
        (1..=courses / 2)
            .flat_map(move |step| [1.0, -1.0].map(|sign| sign * spacing * step as f64)),
    );
    turns
}

/// Whether a leg keeping `min_distance_m` keeps farther than the one in
/// `kept`, if any.
fn keeps_farther(kept: Option<&(Leg, EvasiveManeuver)>, min_distance_m: f64) -> bool {
    kept.is_none_or(|(_, kept)| min_distance_m > kept.min_distance_m)
}

/// The smallest distance between the hulls of ownship sailing `leg` (then
/// lying still to `horizon_s` if it stops short) and any of `tracks`,
/// metres, less the leg's own error where it turns or changes speed.
fn leg_min_distance_m(leg: &Leg, tracks: &[LinearTrack], own_length_m: f64, horizon_s: f64) -> f64 {
    // The leg is cut to the horizon already: every piece of it counts.
    let sailed = legs_min_distance_m(
        std::slice::from_ref(leg),
        tracks,
        own_length_m,
        f64::INFINITY,
    );
    // Stopped short of the horizon: lying still for the rest of it.
    let still_s = horizon_s - leg.duration_s();
    let lying = if still_s > 0.0 {
        tracks
            .iter()
            .map(|track| {
                min_distance_over(leg.end_m(), DVec2::ZERO, track, leg.duration_s(), still_s)
                    - contact_range_m(own_length_m, track.vessel.length_m)
            })
            .fold(f64::INFINITY, f64::min)
    } else {
        f64::INFINITY
    };
    sailed.min(lying)
}

/// The smallest distance between the hulls of ownship sailing `legs` one
/// after the other from the problem's start and any of `tracks` (the
/// targets as predicted), metres, over the first `horizon_s` seconds, less
/// each leg's own error where it turns or changes speed: the measure the
/// evasive manoeuvre keeps farthest, for a plan of several legs (the plan in
/// force, [`legs_min_distance`]).
fn legs_min_distance_m(
    legs: &[Leg],
    tracks: &[LinearTrack],
    own_length_m: f64,
    horizon_s: f64,
) -> f64 {
    let mut best = f64::INFINITY;
    let mut leg_start_s = 0.0;
    for leg in legs {
        if leg_start_s >= horizon_s {
            break;
        }
        let (piece_error_m, timing_error_m) = (leg.piece_error_m(), leg.timing_error_m());
        for piece in leg.pieces(0.0) {
            let from_s = leg_start_s + piece.elapsed_s;
            let duration_s = piece.duration_s.min(horizon_s - from_s);
            if duration_s <= 0.0 {
                break;
            }
            let error_m = if piece.turning {
                piece_error_m
            } else {
                timing_error_m
            };
            for track in tracks {
                let distance_m =
                    min_distance_over(piece.start_m, piece.velocity_mps, track, from_s, duration_s)
                        - contact_range_m(own_length_m, track.vessel.length_m)
                        - error_m;
                best = best.min(distance_m);
            }
        }
        leg_start_s += leg.duration_s();
    }
    best
}

/// The smallest distance between the hulls of ownship sailing `legs` from
/// `problem`'s start and any of its targets as predicted, over
/// `horizon_s`, metres: the measure [`evasive_leg_holding`] judges its
/// courses by (`EvasiveManeuver::min_distance_m`), for the rest of a plan.
#[must_use]
pub fn legs_min_distance(problem: &PlanningProblem, legs: &[Leg], horizon_s: f64) -> f64 {
    let tracks: Vec<_> = problem.targets.iter().map(TargetState::track).collect();
    legs_min_distance_m(legs, &tracks, problem.ownship.length_m, horizon_s)
}

/// Whether `leg` keeps `constraint` along the curve sailed.
fn leg_keeps_constraint<C: Constraint>(leg: &Leg, constraint: &C) -> bool {
    let (piece_error_m, timing_error_m) = (leg.piece_error_m(), leg.timing_error_m());
    leg.pieces(0.0).all(|piece| {
        constraint
            .check_segment(&Segment::of_piece(
                &piece,
                0.0,
                piece_error_m,
                timing_error_m,
            ))
            .is_ok()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use vorrt_colregs::VesselState;
    use vorrt_jfs::TargetState;

    #[test]
    #[expect(
        clippy::float_cmp,
        reason = "holding course returns the present course itself, unchanged"
    )]
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
