//! Ownship's motion: how it sails from a pose toward a point.
//!
//! A [`MotionModel`] turns "from here, on this course, head for that point"
//! into a [`Leg`]: a turn (an arc of constant radius, or an instantaneous
//! change of course) followed by a straight run on the new course, all at
//! ownship's speed. Every consumer of ownship's motion goes through this one
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
//! ([`default_turn_rate_rad_s`]); `docs/architecture.md` gives the sources.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

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

/// One leg of ownship's motion: a turn through `turn_rad` (positive to
/// starboard) on an arc of `turn_radius_m` (0: an instantaneous change of
/// course), then `straight_m` metres on `course_rad`, at `speed_mps`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Leg {
    /// Where the leg starts, metres.
    pub start_m: DVec2,
    /// Course at the start, radians.
    pub start_course_rad: f64,
    /// The settled course after the turn, radians in `[0, 2π)`.
    pub course_rad: f64,
    /// The turn, radians, positive to starboard (clockwise).
    pub turn_rad: f64,
    /// Radius of the turn, metres; 0 for an instantaneous turn.
    pub turn_radius_m: f64,
    /// Length of the straight run after the turn, metres.
    pub straight_m: f64,
    /// Speed along the whole leg, m/s (positive).
    pub speed_mps: f64,
}

/// A straight piece of a leg, as the checks see it: an arc is cut into chords.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Where the piece starts, metres.
    pub start_m: DVec2,
    /// Course along the piece, radians.
    pub course_rad: f64,
    /// Velocity along the piece, m/s.
    pub velocity_mps: DVec2,
    /// Seconds from the leg's start to the piece's start.
    pub elapsed_s: f64,
    /// Duration of the piece, seconds.
    pub duration_s: f64,
    /// Whether the piece is a chord of the turn (true) or part of the settled
    /// straight run (false).
    pub turning: bool,
}

impl Piece {
    /// Where the piece ends, metres.
    #[must_use]
    pub fn end_m(&self) -> DVec2 {
        self.start_m + self.velocity_mps * self.duration_s
    }
}

/// Unit vector to starboard of a course (x east, y north).
fn starboard_unit(course_rad: f64) -> DVec2 {
    let (sin, cos) = course_rad.sin_cos();
    DVec2::new(cos, -sin)
}

impl Leg {
    /// A leg that only runs straight on `course_rad` for `length_m`.
    #[must_use]
    pub fn straight(start_m: DVec2, course_rad: f64, length_m: f64, speed_mps: f64) -> Self {
        Self {
            start_m,
            start_course_rad: course_rad,
            course_rad,
            turn_rad: 0.0,
            turn_radius_m: 0.0,
            straight_m: length_m,
            speed_mps,
        }
    }

    /// The leg that turns from `from` the shorter way onto `course_rad` on
    /// an arc of `turn_radius_m` (0: at once), then runs `straight_m`.
    #[must_use]
    pub fn turning_onto(
        from: Pose,
        course_rad: f64,
        turn_radius_m: f64,
        speed_mps: f64,
        straight_m: f64,
    ) -> Self {
        Self {
            start_m: from.position_m,
            start_course_rad: from.course_rad,
            course_rad: angle::normalize_2pi(course_rad),
            turn_rad: angle::signed_turn(from.course_rad, course_rad),
            turn_radius_m,
            straight_m,
            speed_mps,
        }
    }

    /// Length of the arc, metres.
    #[must_use]
    pub fn arc_m(&self) -> f64 {
        self.turn_radius_m * self.turn_rad.abs()
    }

    /// Length sailed, metres.
    #[must_use]
    pub fn length_m(&self) -> f64 {
        self.arc_m() + self.straight_m
    }

    /// Seconds the turn takes.
    #[must_use]
    pub fn turn_duration_s(&self) -> f64 {
        self.arc_m() / self.speed_mps
    }

    /// Seconds the straight run takes.
    #[must_use]
    pub fn straight_duration_s(&self) -> f64 {
        self.straight_m / self.speed_mps
    }

    /// Seconds the leg takes.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        self.turn_duration_s() + self.straight_duration_s()
    }

    /// Rate of turn along the arc, radians per second (0 for no turn,
    /// infinite for an instantaneous one).
    #[must_use]
    pub fn turn_rate_rad_s(&self) -> f64 {
        if self.turn_rad == 0.0 {
            0.0
        } else if self.turn_radius_m > 0.0 {
            self.speed_mps / self.turn_radius_m
        } else {
            f64::INFINITY
        }
    }

    /// Velocity on the settled course, m/s.
    #[must_use]
    pub fn velocity_mps(&self) -> DVec2 {
        angle::velocity(self.course_rad, self.speed_mps)
    }

    /// Where the turn ends and the straight run begins, metres.
    #[must_use]
    pub fn turn_end_m(&self) -> DVec2 {
        self.on_arc(self.turn_rad.abs())
    }

    /// Where the leg ends, metres.
    #[must_use]
    pub fn end_m(&self) -> DVec2 {
        self.turn_end_m() + self.velocity_mps() * self.straight_duration_s()
    }

    /// Pose at the end of the leg.
    #[must_use]
    pub fn end_pose(&self) -> Pose {
        Pose {
            position_m: self.end_m(),
            course_rad: self.course_rad,
        }
    }

    /// The position after turning through `swept_rad` (`0..=|turn_rad|`).
    fn on_arc(&self, swept_rad: f64) -> DVec2 {
        if self.turn_radius_m == 0.0 || swept_rad == 0.0 {
            return self.start_m;
        }
        let side = self.turn_rad.signum();
        let centre =
            self.start_m + side * self.turn_radius_m * starboard_unit(self.start_course_rad);
        centre
            - side * self.turn_radius_m * starboard_unit(self.start_course_rad + side * swept_rad)
    }

    /// Pose `elapsed_s` seconds into the leg (clamped to the leg).
    ///
    /// ```
    /// use vorrt_jfs::motion::{MotionModel, Pose, RateLimitedTurn};
    /// use glam::DVec2;
    /// // A 90° starboard turn on a 500 m radius, then east to (1500, 500).
    /// let model = RateLimitedTurn { turn_radius_m: 500.0 };
    /// let from = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
    /// let leg = model.steer(from, DVec2::new(1500.0, 500.0), 5.0, f64::INFINITY).unwrap();
    /// assert!((leg.turn_rad.to_degrees() - 90.0).abs() < 1e-6);
    /// assert!(leg.end_m().distance(DVec2::new(1500.0, 500.0)) < 1e-6);
    /// let half = leg.pose_at(leg.turn_duration_s() / 2.0);
    /// assert!((half.course_rad.to_degrees() - 45.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn pose_at(&self, elapsed_s: f64) -> Pose {
        let turn_s = self.turn_duration_s();
        let elapsed_s = elapsed_s.clamp(0.0, self.duration_s());
        if elapsed_s < turn_s {
            let swept = elapsed_s * self.speed_mps / self.turn_radius_m;
            Pose {
                position_m: self.on_arc(swept),
                course_rad: angle::normalize_2pi(
                    self.start_course_rad + self.turn_rad.signum() * swept,
                ),
            }
        } else {
            Pose {
                position_m: self.turn_end_m() + self.velocity_mps() * (elapsed_s - turn_s),
                course_rad: self.course_rad,
            }
        }
    }

    /// The rest of the leg from `elapsed_s` seconds in: the same curve, as a
    /// leg of its own.
    ///
    /// ```
    /// use vorrt_jfs::motion::{MotionModel, Pose, RateLimitedTurn};
    /// use glam::DVec2;
    /// let model = RateLimitedTurn { turn_radius_m: 400.0 };
    /// let from = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
    /// let leg = model.steer(from, DVec2::new(2000.0, 300.0), 5.0, f64::INFINITY).unwrap();
    /// let rest = leg.remainder(30.0);
    /// assert!(rest.end_m().distance(leg.end_m()) < 1e-6);
    /// assert!((rest.duration_s() - (leg.duration_s() - 30.0)).abs() < 1e-9);
    /// ```
    #[must_use]
    pub fn remainder(&self, elapsed_s: f64) -> Leg {
        let pose = self.pose_at(elapsed_s);
        let turn_s = self.turn_duration_s();
        let elapsed_s = elapsed_s.clamp(0.0, self.duration_s());
        if elapsed_s < turn_s {
            let swept = elapsed_s * self.speed_mps / self.turn_radius_m;
            Leg {
                start_m: pose.position_m,
                start_course_rad: pose.course_rad,
                turn_rad: self.turn_rad - self.turn_rad.signum() * swept,
                ..*self
            }
        } else {
            Leg {
                start_m: pose.position_m,
                start_course_rad: self.course_rad,
                turn_rad: 0.0,
                straight_m: (self.straight_m - (elapsed_s - turn_s) * self.speed_mps).max(0.0),
                ..*self
            }
        }
    }

    /// How far a chord of [`chords`](Self::pieces) may lie from the arc, metres.
    #[must_use]
    pub fn chord_error_m(&self) -> f64 {
        self.turn_radius_m * (1.0 - (CHORD_ANGLE_RAD / 2.0).cos())
    }

    /// The leg as straight pieces: the arc cut into chords of at most
    /// [`CHORD_ANGLE_RAD`], then the straight run cut into pieces of at most
    /// `max_piece_m` metres (a whole run when it is shorter). An
    /// instantaneous turn has no chord.
    pub fn pieces(&self, max_piece_m: f64) -> impl Iterator<Item = Piece> + '_ {
        let turn = self.turn_rad.abs();
        let chords = if self.turn_radius_m > 0.0 && turn > 0.0 {
            (turn / CHORD_ANGLE_RAD).ceil().max(1.0) as usize
        } else {
            0
        };
        let chord_s = if chords > 0 {
            self.turn_duration_s() / chords as f64
        } else {
            0.0
        };
        let runs = if self.straight_m > 0.0 {
            if max_piece_m > 0.0 && self.straight_m > max_piece_m {
                (self.straight_m / max_piece_m).ceil() as usize
            } else {
                1
            }
        } else {
            0
        };
        let turn_s = self.turn_duration_s();
        let run_s = if runs > 0 {
            self.straight_duration_s() / runs as f64
        } else {
            0.0
        };
        let velocity = self.velocity_mps();
        let turn_end = self.turn_end_m();
        let side = self.turn_rad.signum();
        (0..chords + runs).map(move |index| {
            if index < chords {
                let from = self.on_arc(turn * index as f64 / chords as f64);
                let to = self.on_arc(turn * (index + 1) as f64 / chords as f64);
                let course_rad = angle::normalize_2pi(
                    self.start_course_rad + side * turn * (index as f64 + 0.5) / chords as f64,
                );
                Piece {
                    start_m: from,
                    course_rad,
                    velocity_mps: (to - from) / chord_s,
                    elapsed_s: chord_s * index as f64,
                    duration_s: chord_s,
                    turning: true,
                }
            } else {
                let run = index - chords;
                let (start_m, duration_s) = if runs == 1 {
                    (turn_end, self.straight_duration_s())
                } else {
                    (turn_end + velocity * (run_s * run as f64), run_s)
                };
                Piece {
                    start_m,
                    course_rad: self.course_rad,
                    velocity_mps: velocity,
                    elapsed_s: turn_s + run_s * run as f64,
                    duration_s,
                    turning: false,
                }
            }
        })
    }
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
mod tests {
    use super::*;

    fn pose(x: f64, y: f64, course_deg: f64) -> Pose {
        Pose {
            position_m: DVec2::new(x, y),
            course_rad: course_deg.to_radians(),
        }
    }

    #[test]
    fn rate_limited_leg_ends_on_the_point_facing_away_from_the_tangent_point() {
        let model = RateLimitedTurn {
            turn_radius_m: 300.0,
        };
        for (x, y) in [
            (2000.0, 100.0),
            (-1500.0, -800.0),
            (10.0, 5000.0),
            (900.0, -50.0),
        ] {
            let leg = model
                .steer(pose(0.0, 0.0, 20.0), DVec2::new(x, y), 6.0, f64::INFINITY)
                .unwrap();
            assert!(leg.end_m().distance(DVec2::new(x, y)) < 1e-6, "{x} {y}");
            let bearing = angle::unit_to_course(DVec2::new(x, y) - leg.turn_end_m());
            assert!(angle::signed_turn(leg.course_rad, bearing).abs() < 1e-6);
        }
    }

    #[test]
    fn point_inside_the_turning_circle_is_unreachable() {
        let model = RateLimitedTurn {
            turn_radius_m: 500.0,
        };
        assert!(
            model
                .steer(
                    pose(0.0, 0.0, 0.0),
                    DVec2::new(400.0, 0.0),
                    6.0,
                    f64::INFINITY
                )
                .is_none()
        );
    }

    #[test]
    fn pieces_cover_the_leg_continuously() {
        let model = RateLimitedTurn {
            turn_radius_m: 400.0,
        };
        let leg = model
            .steer(
                pose(0.0, 0.0, 0.0),
                DVec2::new(-3000.0, -200.0),
                5.0,
                f64::INFINITY,
            )
            .unwrap();
        let pieces: Vec<Piece> = leg.pieces(100.0).collect();
        let mut at = leg.start_m;
        let mut elapsed = 0.0;
        for piece in &pieces {
            assert!(piece.start_m.distance(at) < 1e-6);
            assert!((piece.elapsed_s - elapsed).abs() < 1e-6);
            at = piece.end_m();
            elapsed += piece.duration_s;
        }
        assert!(at.distance(leg.end_m()) < 1e-6);
        assert!((elapsed - leg.duration_s()).abs() < 1e-6);
        assert!(pieces.iter().filter(|piece| !piece.turning).count() >= 20);
    }

    #[test]
    fn max_length_cuts_the_arc() {
        let model = RateLimitedTurn {
            turn_radius_m: 400.0,
        };
        let leg = model
            .steer(pose(0.0, 0.0, 0.0), DVec2::new(-3000.0, -100.0), 5.0, 100.0)
            .unwrap();
        assert!((leg.length_m() - 100.0).abs() < 1e-9);
        assert_eq!(leg.straight_m, 0.0);
        assert!((leg.turn_rad.abs() - 0.25).abs() < 1e-12);
    }

    #[test]
    fn default_rate_is_capped_and_from_length() {
        assert!((default_turn_rate_rad_s(10.0, 10.0) - MAX_DEFAULT_TURN_RATE_RAD_S).abs() < 1e-15);
        assert!((default_turn_rate_rad_s(400.0, 6.0) - 6.0 / 1200.0).abs() < 1e-15);
    }
}
