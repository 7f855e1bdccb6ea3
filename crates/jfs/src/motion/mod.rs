//! Ownship's motion: how it sails from a pose toward a point.
//!
//! A [`MotionModel`] turns "from here, on this course, head for that point"
//! into a [`Leg`]: a turn (an arc of constant radius, or an instantaneous
//! change of course) followed by a straight run on the new course, at
//! ownship's speed, or changing speed at a constant rate from the speed the
//! leg starts at ([`Leg::from_speed`], [`default_speed_change_mps2`]). Every consumer of ownship's motion goes through this one
//! model: the planner's joint forward step, its path simplifier, its validity
//! check, the closed loop that sails the plan and the evasive fallback. So
//! what is checked is what is sailed.
//!
//! Two models are given:
//! - [`InstantTurn`]: the paper's joint step (§III-D): the course changes at
//!   the node, by at most `max_turn_rad`, then ownship runs straight;
//! - [`RateLimitedTurn`]: the course changes at a bounded rate of turn, i.e.
//!   along an arc of radius `speed / rate`, then runs straight along the
//!   tangent to the point (a Dubins "turn then straight" path). A vessel whose
//!   rate of turn is limited sails exactly this curve when it steers for the
//!   point with its rudder at the limit until it faces it.
//!
//! The default rate of turn comes from the vessel's length and speed
//! ([`default_turn_rate_rad_s`]); `docs/decisions/0013-rate-of-turn.md` gives the sources.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

mod leg;
mod pieces;
mod poses;

pub use leg::{Leg, SpeedChange};
pub use pieces::Piece;
pub use poses::LegPoses;

/// A planned turn's radius in ship lengths when none is given: IMO MSC.137(76)
/// caps the hard-over tactical diameter at 5 lengths (radius 2.5 L) and
/// typical turning circles are 3-4 L; an alteration of course is made well
/// inside the hard-over limit, so 3 L is used for planning.
pub const DEFAULT_TURN_RADIUS_LENGTHS: f64 = 3.0;

/// The largest default rate of turn, radians per second (0.5°/s): ships
/// alter course at about 0.2-0.5°/s (an autopilot's rate-of-turn limit; the
/// practical rate 0.96 V / R °/min, V in kn and R in nm, is 0.48°/s at 15 kn on a 0.5 nm
/// radius), well inside their hard-over rates (about 0.5-1.5°/s for 100-200 m
/// ships); small craft could turn faster, but this is what other vessels and
/// evaluators expect of an alteration of course.
pub const MAX_DEFAULT_TURN_RATE_RAD_S: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// The smallest default turning radius, metres, for very short vessels.
pub const MIN_DEFAULT_TURN_RADIUS_M: f64 = 50.0;

/// How finely arcs are cut into chords when a leg is checked, radians (5°):
/// a chord is at most `R (1 - cos 2.5°)` (0.1 % of the radius) off the arc,
/// and [`Leg::chord_error_m`] reports that bound so checks can add it.
pub const CHORD_ANGLE_RAD: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// How long a piece of a leg may be while its speed changes, seconds: a
/// piece is checked at its mean velocity, and a vessel changing speed at `a`
/// is at most `a d² / 8` along its curve from where the mean velocity puts
/// it ([`Leg::timing_error_m`]), 0.3 m at 0.024 m/s².
pub const SPEED_PIECE_S: f64 = 10.0;

/// The distance, in ship lengths, in which ownship is taken to stop from its
/// service speed: IMO MSC.137(76) (standards for ship manoeuvrability) caps
/// the track reach of a full-astern crash stop at 15 lengths (20 for
/// low-powered large ships).
pub const STOPPING_REACH_LENGTHS: f64 = 15.0;

/// The default rate at which a vessel of `length_m` with service speed
/// `speed_mps` changes speed, m/s² (slowing down or speeding up): the
/// constant deceleration that stops it from that speed in
/// [`STOPPING_REACH_LENGTHS`] lengths, `v² / (2 · 15 L)`.
/// `docs/decisions/0019-speed-as-a-manoeuvre.md` gives the sources.
///
/// ```
/// use vorrt_jfs::motion::default_speed_change_mps2;
/// // A 50 m vessel at 6 m/s: 36 / 1500 = 0.024 m/s²; halving its speed
/// // takes 125 s.
/// let rate = default_speed_change_mps2(50.0, 6.0);
/// assert!((rate - 0.024).abs() < 1e-12);
/// // A 200 m ship at 15 kn: about 0.0099 m/s².
/// let rate = default_speed_change_mps2(200.0, 15.0 * 1852.0 / 3600.0);
/// assert!((rate - 0.0099).abs() < 1e-4);
/// ```
#[must_use]
pub fn default_speed_change_mps2(length_m: f64, speed_mps: f64) -> f64 {
    speed_mps * speed_mps / (2.0 * STOPPING_REACH_LENGTHS * length_m)
}

/// The default largest rate of turn of a vessel of `length_m` at `speed_mps`,
/// radians per second: a turning radius of [`DEFAULT_TURN_RADIUS_LENGTHS`]
/// lengths (at least [`MIN_DEFAULT_TURN_RADIUS_M`]), and never above
/// [`MAX_DEFAULT_TURN_RATE_RAD_S`].
///
/// ```
/// use vorrt_jfs::motion::default_turn_rate_rad_s;
/// // A 300 m ship at 12 kn: radius 900 m, about 0.39°/s.
/// let rate = default_turn_rate_rad_s(300.0, 12.0 * 1852.0 / 3600.0);
/// assert!((rate.to_degrees() - 0.393).abs() < 0.01);
/// // A 150 m ship at 12 kn would turn at 0.79°/s on 3 lengths: capped.
/// let rate = default_turn_rate_rad_s(150.0, 12.0 * 1852.0 / 3600.0);
/// assert!((rate.to_degrees() - 0.5).abs() < 1e-9);
/// ```
#[must_use]
pub fn default_turn_rate_rad_s(length_m: f64, speed_mps: f64) -> f64 {
    let radius_m = (DEFAULT_TURN_RADIUS_LENGTHS * length_m).max(MIN_DEFAULT_TURN_RADIUS_M);
    (speed_mps / radius_m).min(MAX_DEFAULT_TURN_RATE_RAD_S)
}

/// Where ownship is and where it heads.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    /// Position, metres (x east, y north).
    pub position_m: DVec2,
    /// Course, radians clockwise from north.
    pub course_rad: f64,
}

/// Unit vector to starboard of a course (x east, y north).
pub(crate) fn starboard_unit(course_rad: f64) -> DVec2 {
    let (sin, cos) = course_rad.sin_cos();
    DVec2::new(cos, -sin)
}

/// How ownship moves from a pose toward a point: the seam through which the
/// planner, its simplifier, its validity check and the closed loop all move
/// ownship.
///
/// ```
/// use vorrt_jfs::motion::{InstantTurn, MotionModel, Pose};
/// use glam::DVec2;
/// let model = InstantTurn { max_turn_rad: 30f64.to_radians() };
/// let from = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
/// // A point dead abeam to starboard: the course changes by the bound, 30°.
/// let leg = model.steer(from, DVec2::new(1000.0, 0.0), 5.0, 100.0).unwrap();
/// assert!((leg.course_rad.to_degrees() - 30.0).abs() < 1e-9);
/// assert!((leg.length_m() - 100.0).abs() < 1e-9);
/// ```
pub trait MotionModel {
    /// The leg from `from` toward `toward_m` at `speed_mps`, at most
    /// `max_length_m` long (it ends on the point when the point is reached
    /// within that length). `None` when the point is where ownship is, or it
    /// cannot be reached this way (inside the turning circle, or only by
    /// turning through more than half a circle).
    fn steer(&self, from: Pose, toward_m: DVec2, speed_mps: f64, max_length_m: f64) -> Option<Leg>;

    /// The leg from `from` that turns onto `course_rad` and then runs
    /// `straight_m` metres on it.
    fn turn_onto(&self, from: Pose, course_rad: f64, speed_mps: f64, straight_m: f64) -> Leg;
}

/// The paper's joint step: an instantaneous change of course of at most
/// `max_turn_rad`, then a straight run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct InstantTurn {
    /// Largest change of course at once, radians.
    pub max_turn_rad: f64,
}

impl MotionModel for InstantTurn {
    fn steer(&self, from: Pose, toward_m: DVec2, speed_mps: f64, max_length_m: f64) -> Option<Leg> {
        let offset = toward_m - from.position_m;
        let distance = offset.length();
        if distance == 0.0 {
            return None;
        }
        let wanted = angle::unit_to_course(offset);
        let turn = angle::signed_turn(from.course_rad, wanted);
        let limit = self.max_turn_rad;
        let (course_rad, turn_rad, length_m) = if turn.abs() <= limit {
            (wanted, turn, distance.min(max_length_m))
        } else {
            let bounded = limit.copysign(turn);
            (
                angle::normalize_2pi(from.course_rad + bounded),
                bounded,
                max_length_m,
            )
        };
        Some(Leg {
            start_m: from.position_m,
            start_course_rad: from.course_rad,
            course_rad,
            turn_rad,
            turn_radius_m: 0.0,
            straight_m: length_m,
            speed_mps,
            speed_change: None,
        })
    }

    fn turn_onto(&self, from: Pose, course_rad: f64, speed_mps: f64, straight_m: f64) -> Leg {
        Leg::turning_onto(from, course_rad, 0.0, speed_mps, straight_m)
    }
}

/// A rate-limited turn: an arc of `turn_radius_m` (speed / largest rate of
/// turn), then the tangent to the point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RateLimitedTurn {
    /// Radius of every turn, metres (positive).
    pub turn_radius_m: f64,
}

impl RateLimitedTurn {
    /// The model of a vessel at `speed_mps` whose rate of turn is at most
    /// `max_turn_rate_rad_s`.
    #[must_use]
    pub fn from_rate(speed_mps: f64, max_turn_rate_rad_s: f64) -> Self {
        Self {
            turn_radius_m: speed_mps / max_turn_rate_rad_s,
        }
    }
}

/// Turns below this are no turn at all (rounding of a course toward a point
/// ownship already faces), radians.
const NO_TURN_RAD: f64 = 1e-12;

impl MotionModel for RateLimitedTurn {
    fn steer(&self, from: Pose, toward_m: DVec2, speed_mps: f64, max_length_m: f64) -> Option<Leg> {
        let offset = toward_m - from.position_m;
        let distance = offset.length();
        if distance == 0.0 {
            return None;
        }
        let wanted = angle::unit_to_course(offset);
        let turn = angle::signed_turn(from.course_rad, wanted);
        let radius = self.turn_radius_m;
        if turn.abs() <= NO_TURN_RAD {
            return Some(Leg {
                course_rad: wanted,
                ..Leg::straight(
                    from.position_m,
                    from.course_rad,
                    distance.min(max_length_m),
                    speed_mps,
                )
            });
        }
        let side = turn.signum();
        let centre = from.position_m + side * radius * starboard_unit(from.course_rad);
        let to_point = toward_m - centre;
        let centre_distance = to_point.length();
        if centre_distance <= radius {
            return None;
        }
        // The tangent from the turning circle to the point leaves at the
        // course that is asin(R/d) off the centre-to-point bearing.
        let tangent_course =
            angle::unit_to_course(to_point) + side * (radius / centre_distance).asin();
        let swept = angle::normalize_2pi(side * (tangent_course - from.course_rad));
        if swept > std::f64::consts::PI {
            // A point behind, close on the turning side: reached only by
            // looping round, which no one steers (nor reads as an alteration).
            return None;
        }
        let tangent_m = (centre_distance * centre_distance - radius * radius).sqrt();
        let arc_m = radius * swept;
        let (swept, straight_m) = if arc_m >= max_length_m {
            (max_length_m / radius, 0.0)
        } else {
            (swept, tangent_m.min(max_length_m - arc_m))
        };
        Some(Leg {
            start_m: from.position_m,
            start_course_rad: from.course_rad,
            course_rad: angle::normalize_2pi(from.course_rad + side * swept),
            turn_rad: side * swept,
            turn_radius_m: radius,
            straight_m,
            speed_mps,
            speed_change: None,
        })
    }

    fn turn_onto(&self, from: Pose, course_rad: f64, speed_mps: f64, straight_m: f64) -> Leg {
        Leg::turning_onto(from, course_rad, self.turn_radius_m, speed_mps, straight_m)
    }
}

/// Either model, chosen at run time (a configuration picks one), dispatched
/// by a match so the planner's inner loop stays monomorphic.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum OwnshipModel {
    /// [`InstantTurn`].
    Instant(InstantTurn),
    /// [`RateLimitedTurn`].
    RateLimited(RateLimitedTurn),
}

impl MotionModel for OwnshipModel {
    fn steer(&self, from: Pose, toward_m: DVec2, speed_mps: f64, max_length_m: f64) -> Option<Leg> {
        match self {
            OwnshipModel::Instant(model) => model.steer(from, toward_m, speed_mps, max_length_m),
            OwnshipModel::RateLimited(model) => {
                model.steer(from, toward_m, speed_mps, max_length_m)
            }
        }
    }

    fn turn_onto(&self, from: Pose, course_rad: f64, speed_mps: f64, straight_m: f64) -> Leg {
        match self {
            OwnshipModel::Instant(model) => {
                model.turn_onto(from, course_rad, speed_mps, straight_m)
            }
            OwnshipModel::RateLimited(model) => {
                model.turn_onto(from, course_rad, speed_mps, straight_m)
            }
        }
    }
}

#[cfg(test)]
mod tests;
