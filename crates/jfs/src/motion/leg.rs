//! One leg of ownship's motion: its geometry (a turn on an arc, then a
//! straight run) and its speed profile (a constant rate of speed change from
//! the speed it starts at to the speed it settles at). The straight pieces
//! the checks judge it by are cut in the `pieces` module.

use super::{CHORD_ANGLE_RAD, Pose, SPEED_PIECE_S, starboard_unit};
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

/// Distances along a leg closer than this are one point, metres.
pub(super) const SAME_POINT_M: f64 = 1e-9;

/// A change of speed along a leg: the leg starts at `start_speed_mps` and
/// changes speed at `rate_mps2` (either way) until it reaches the leg's
/// settled [`speed_mps`](Leg::speed_mps), then holds it (`docs/decisions/0019-speed-as-a-manoeuvre.md`: a constant rate, from the stopping distance).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SpeedChange {
    /// Speed at the leg's start, m/s (at least 0).
    pub start_speed_mps: f64,
    /// How fast the speed changes, m/s² (positive, finite).
    pub rate_mps2: f64,
}

/// One leg of ownship's motion: a turn through `turn_rad` (positive to
/// starboard) on an arc of `turn_radius_m` (0: an instantaneous change of
/// course), then `straight_m` metres on `course_rad`; at `speed_mps`, or,
/// with a [`SpeedChange`], from its start speed toward `speed_mps` at a
/// constant rate. The geometry does not depend on the speed: the arc length
/// sailed after `t` seconds is `v0 t ± a t²/2` until the settled speed is
/// reached, then grows at the settled speed.
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
    /// The settled speed: the speed along the whole leg, or, with a
    /// `speed_change`, the speed it changes to, m/s (positive; 0 only for a
    /// leg that stops, whose length is at most its stopping distance).
    pub speed_mps: f64,
    /// How the speed changes from the leg's start, if it does (absent: the
    /// leg is sailed at `speed_mps` throughout).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_change: Option<SpeedChange>,
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
            speed_change: None,
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
            speed_change: None,
        }
    }

    /// The same curve sailed from `start_speed_mps`, changing speed at
    /// `rate_mps2` toward the leg's settled `speed_mps` (an infinite rate, or
    /// the same speed: no change at all). A leg that settles at rest is cut
    /// to its stopping distance: it ends where ownship stops.
    ///
    /// ```
    /// use vorrt_jfs::Leg;
    /// use glam::DVec2;
    /// // From 6 m/s down to 3 m/s at 0.05 m/s²: 60 s and 270 m, then 3 m/s.
    /// let leg = Leg::straight(DVec2::ZERO, 0.0, 1000.0, 3.0).from_speed(6.0, 0.05);
    /// assert!((leg.speed_change_s() - 60.0).abs() < 1e-9);
    /// assert!((leg.distance_at(60.0) - 270.0).abs() < 1e-9);
    /// assert!((leg.duration_s() - (60.0 + 730.0 / 3.0)).abs() < 1e-9);
    /// // Stopping from 6 m/s: 360 m, whatever the length asked for.
    /// let stop = Leg::straight(DVec2::ZERO, 0.0, 1000.0, 0.0).from_speed(6.0, 0.05);
    /// assert!((stop.length_m() - 360.0).abs() < 1e-9);
    /// assert!((stop.duration_s() - 120.0).abs() < 1e-9);
    /// assert_eq!(stop.speed_at(200.0), 0.0);
    /// ```
    #[must_use]
    #[expect(
        clippy::float_cmp,
        reason = "any difference of speed is a change of speed"
    )]
    pub fn from_speed(self, start_speed_mps: f64, rate_mps2: f64) -> Self {
        let start_speed_mps = start_speed_mps.max(0.0);
        let changes = start_speed_mps != self.speed_mps
            && rate_mps2.is_finite()
            && rate_mps2 > 0.0
            && start_speed_mps.is_finite();
        let mut leg = Self {
            speed_change: changes.then_some(SpeedChange {
                start_speed_mps,
                rate_mps2,
            }),
            ..self
        };
        if leg.speed_mps <= 0.0 {
            let reach_m = leg.speed_change_m();
            if leg.length_m() > reach_m {
                leg = leg.cut_to(reach_m);
            }
        }
        leg
    }

    /// The first `elapsed_s` seconds of the leg (all of it if it is shorter):
    /// the same curve and speed profile, cut where ownship is then.
    ///
    /// ```
    /// use vorrt_jfs::Leg;
    /// use glam::DVec2;
    /// let leg = Leg::straight(DVec2::ZERO, 0.0, 5000.0, 3.0).from_speed(6.0, 0.05);
    /// let first = leg.until(100.0);
    /// assert!((first.duration_s() - 100.0).abs() < 1e-9);
    /// assert!(first.end_m().distance(leg.pose_at(100.0).position_m) < 1e-9);
    /// ```
    #[must_use]
    pub fn until(self, elapsed_s: f64) -> Self {
        let length_m = self.distance_at(elapsed_s).min(self.length_m());
        self.cut_to(length_m)
    }

    /// The first `length_m` metres of the leg (at most all of it).
    fn cut_to(self, length_m: f64) -> Self {
        let arc_m = self.arc_m();
        if length_m >= arc_m {
            Self {
                straight_m: (length_m - arc_m).min(self.straight_m),
                ..self
            }
        } else {
            let swept = length_m / self.turn_radius_m;
            Self {
                course_rad: angle::normalize_2pi(
                    self.start_course_rad + self.turn_rad.signum() * swept,
                ),
                turn_rad: self.turn_rad.signum() * swept,
                straight_m: 0.0,
                ..self
            }
        }
    }

    /// Speed at the leg's start, m/s.
    #[must_use]
    pub fn start_speed_mps(&self) -> f64 {
        self.speed_change
            .map_or(self.speed_mps, |change| change.start_speed_mps)
    }

    /// The rate of speed change along the leg, m/s² (0 when it holds one
    /// speed).
    #[must_use]
    pub fn speed_change_rate_mps2(&self) -> f64 {
        self.speed_change.map_or(0.0, |change| change.rate_mps2)
    }

    /// Seconds the change of speed takes (0 without one).
    #[must_use]
    pub fn speed_change_s(&self) -> f64 {
        self.speed_change.map_or(0.0, |change| {
            (self.speed_mps - change.start_speed_mps).abs() / change.rate_mps2
        })
    }

    /// Metres sailed while the speed changes (0 without a change).
    #[must_use]
    pub fn speed_change_m(&self) -> f64 {
        0.5 * (self.start_speed_mps() + self.speed_mps) * self.speed_change_s()
    }

    /// Signed acceleration while the speed changes, m/s².
    fn acceleration_mps2(&self) -> f64 {
        self.speed_change.map_or(0.0, |change| {
            change
                .rate_mps2
                .copysign(self.speed_mps - change.start_speed_mps)
        })
    }

    /// Speed `elapsed_s` seconds into the leg, m/s (clamped to the leg's
    /// start; after its end, the settled speed).
    #[must_use]
    pub fn speed_at(&self, elapsed_s: f64) -> f64 {
        let change_s = self.speed_change_s();
        let elapsed_s = elapsed_s.max(0.0);
        if elapsed_s < change_s {
            self.start_speed_mps() + self.acceleration_mps2() * elapsed_s
        } else {
            self.speed_mps
        }
    }

    /// Metres sailed along the curve `elapsed_s` seconds into the leg (not
    /// clamped to the leg's length).
    #[must_use]
    pub fn distance_at(&self, elapsed_s: f64) -> f64 {
        let elapsed_s = elapsed_s.max(0.0);
        let change_s = self.speed_change_s();
        if elapsed_s < change_s {
            self.start_speed_mps() * elapsed_s
                + 0.5 * self.acceleration_mps2() * elapsed_s * elapsed_s
        } else {
            self.speed_change_m() + self.speed_mps * (elapsed_s - change_s)
        }
    }

    /// Seconds from the leg's start until `distance_m` metres have been
    /// sailed along it (infinite for a distance a stopping leg never reaches).
    #[must_use]
    pub fn time_at_distance(&self, distance_m: f64) -> f64 {
        let distance_m = distance_m.max(0.0);
        let change_m = self.speed_change_m();
        if self.speed_change.is_some() && distance_m <= change_m {
            // v0 t + a t²/2 = s, in the form that stays exact as a → 0 and
            // for a start from rest.
            let start = self.start_speed_mps();
            let root = (start * start + 2.0 * self.acceleration_mps2() * distance_m)
                .max(0.0)
                .sqrt();
            let sum = start + root;
            if sum > 0.0 {
                2.0 * distance_m / sum
            } else {
                0.0
            }
        } else if self.speed_mps > 0.0 {
            self.speed_change_s() + (distance_m - change_m).max(0.0) / self.speed_mps
        } else if distance_m <= change_m + SAME_POINT_M {
            self.speed_change_s()
        } else {
            f64::INFINITY
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
        if self.speed_change.is_none() {
            return at_one_speed_s(self.arc_m(), self.speed_mps);
        }
        self.time_at_distance(self.arc_m())
    }

    /// Seconds the straight run takes.
    #[must_use]
    pub fn straight_duration_s(&self) -> f64 {
        if self.speed_change.is_none() {
            return at_one_speed_s(self.straight_m, self.speed_mps);
        }
        self.duration_s() - self.turn_duration_s()
    }

    /// Seconds the leg takes.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        if self.speed_change.is_none() {
            // At one speed, in the form the planner has always timed legs
            // (its recorded plans are reproduced bit for bit).
            return self.turn_duration_s() + self.straight_duration_s();
        }
        self.time_at_distance(self.length_m())
    }

    /// The largest rate of turn along the arc, radians per second (0 for no
    /// turn, infinite for an instantaneous one): at the fastest speed sailed
    /// on it, which is at most the larger of the start and settled speeds.
    #[must_use]
    pub fn turn_rate_rad_s(&self) -> f64 {
        if self.turn_rad == 0.0 {
            0.0
        } else if self.turn_radius_m > 0.0 {
            let fastest = self
                .speed_at(0.0)
                .max(self.speed_at(self.turn_duration_s()));
            fastest / self.turn_radius_m
        } else {
            f64::INFINITY
        }
    }

    /// Velocity on the settled course at the settled speed, m/s.
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
        if self.speed_change.is_none() {
            return self.turn_end_m() + self.velocity_mps() * self.straight_duration_s();
        }
        self.turn_end_m() + angle::velocity(self.course_rad, self.straight_m)
    }

    /// Pose at the end of the leg.
    #[must_use]
    pub fn end_pose(&self) -> Pose {
        Pose {
            position_m: self.end_m(),
            course_rad: self.course_rad,
        }
    }

    /// Speed at the end of the leg, m/s.
    #[must_use]
    pub fn end_speed_mps(&self) -> f64 {
        self.speed_at(self.duration_s())
    }

    /// The position after turning through `swept_rad` (`0..=|turn_rad|`).
    pub(super) fn on_arc(&self, swept_rad: f64) -> DVec2 {
        self.on_arc_about(self.arc_centre_m(), swept_rad)
    }

    /// The centre of the turn's arc (for no turn, or an instantaneous one,
    /// a point [`on_arc_about`](Self::on_arc_about) never uses).
    pub(super) fn arc_centre_m(&self) -> DVec2 {
        let side = self.turn_rad.signum();
        self.start_m + side * self.turn_radius_m * starboard_unit(self.start_course_rad)
    }

    /// [`on_arc`](Self::on_arc) with the arc's centre given
    /// ([`arc_centre_m`](Self::arc_centre_m), worked out once by a caller
    /// that asks for many points: the same points).
    pub(super) fn on_arc_about(&self, centre_m: DVec2, swept_rad: f64) -> DVec2 {
        if self.turn_radius_m == 0.0 || swept_rad == 0.0 {
            return self.start_m;
        }
        let side = self.turn_rad.signum();
        centre_m
            - side * self.turn_radius_m * starboard_unit(self.start_course_rad + side * swept_rad)
    }

    /// The pose `distance_m` metres along the leg (clamped to it).
    pub(super) fn pose_along(&self, distance_m: f64) -> Pose {
        self.pose_along_from(
            distance_m,
            self.turn_end_m(),
            angle::course_to_unit(self.course_rad),
        )
    }

    /// [`pose_along`](Self::pose_along) with the leg's turn end and the unit
    /// vector of its course given (worked out once by a caller that asks
    /// for many poses: the same values, so the same poses).
    pub(super) fn pose_along_from(&self, distance_m: f64, turn_end_m: DVec2, unit: DVec2) -> Pose {
        self.pose_along_about(self.arc_centre_m(), distance_m, turn_end_m, unit)
    }

    /// [`pose_along_from`](Self::pose_along_from) with the arc's centre
    /// given too ([`arc_centre_m`](Self::arc_centre_m)): the same poses.
    pub(super) fn pose_along_about(
        &self,
        centre_m: DVec2,
        distance_m: f64,
        turn_end_m: DVec2,
        unit: DVec2,
    ) -> Pose {
        let distance_m = distance_m.clamp(0.0, self.length_m());
        let arc_m = self.arc_m();
        if distance_m < arc_m {
            let swept = distance_m / self.turn_radius_m;
            Pose {
                position_m: self.on_arc_about(centre_m, swept),
                course_rad: angle::normalize_2pi(
                    self.start_course_rad + self.turn_rad.signum() * swept,
                ),
            }
        } else {
            Pose {
                // angle::velocity(course, d) is course_to_unit(course) * d.
                position_m: turn_end_m + unit * (distance_m - arc_m),
                course_rad: self.course_rad,
            }
        }
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
    /// // The same curve sailed from rest, speeding up at 0.05 m/s²: the turn
    /// // is half done when half the arc is sailed, later than before.
    /// let slow = leg.from_speed(0.0, 0.05);
    /// let half_arc_s = slow.time_at_distance(slow.arc_m() / 2.0);
    /// assert!(half_arc_s > leg.turn_duration_s() / 2.0);
    /// assert!((slow.pose_at(half_arc_s).course_rad.to_degrees() - 45.0).abs() < 1e-6);
    /// assert!(slow.end_m().distance(leg.end_m()) < 1e-9);
    /// ```
    #[must_use]
    pub fn pose_at(&self, elapsed_s: f64) -> Pose {
        self.pose_at_from(
            elapsed_s,
            || self.arc_centre_m(),
            || self.turn_end_m(),
            || angle::course_to_unit(self.course_rad),
        )
    }

    /// [`pose_at`](Self::pose_at)'s one body, with the turn's centre
    /// ([`arc_centre_m`](Self::arc_centre_m)), its end and the unit vector
    /// of the settled course given, each asked for only where it is needed
    /// (a caller that asks for many poses works them out once:
    /// [`LegPoses`](super::LegPoses); the same poses).
    pub(super) fn pose_at_from(
        &self,
        elapsed_s: f64,
        centre_m: impl FnOnce() -> DVec2,
        turn_end_m: impl FnOnce() -> DVec2,
        unit: impl FnOnce() -> DVec2,
    ) -> Pose {
        if self.speed_change.is_none() {
            let turn_s = self.turn_duration_s();
            let elapsed_s = elapsed_s.clamp(0.0, self.duration_s());
            return if elapsed_s < turn_s {
                let swept = elapsed_s * self.speed_mps / self.turn_radius_m;
                Pose {
                    position_m: self.on_arc_about(centre_m(), swept),
                    course_rad: angle::normalize_2pi(
                        self.start_course_rad + self.turn_rad.signum() * swept,
                    ),
                }
            } else {
                // `velocity_mps` is the unit vector times the speed.
                Pose {
                    position_m: turn_end_m() + unit() * self.speed_mps * (elapsed_s - turn_s),
                    course_rad: self.course_rad,
                }
            };
        }
        self.pose_along_about(
            centre_m(),
            self.distance_at(elapsed_s),
            turn_end_m(),
            unit(),
        )
    }

    /// The course `elapsed_s` seconds into the leg: [`pose_at`](Self::pose_at)'s
    /// course, bit for bit, without working out the position.
    ///
    /// ```
    /// use vorrt_jfs::motion::{Leg, Pose};
    /// use glam::DVec2;
    /// let from = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
    /// let leg = Leg::turning_onto(from, 1.0, 400.0, 6.0, 2000.0).from_speed(3.0, 0.05);
    /// for elapsed_s in [0.0, 20.0, 60.0, 500.0] {
    ///     assert_eq!(leg.course_at(elapsed_s), leg.pose_at(elapsed_s).course_rad);
    /// }
    /// ```
    #[must_use]
    pub fn course_at(&self, elapsed_s: f64) -> f64 {
        let on_turn = |swept_rad: f64| {
            angle::normalize_2pi(self.start_course_rad + self.turn_rad.signum() * swept_rad)
        };
        if self.speed_change.is_none() {
            let elapsed_s = elapsed_s.clamp(0.0, self.duration_s());
            return if elapsed_s < self.turn_duration_s() {
                on_turn(elapsed_s * self.speed_mps / self.turn_radius_m)
            } else {
                self.course_rad
            };
        }
        let distance_m = self.distance_at(elapsed_s).clamp(0.0, self.length_m());
        if distance_m < self.arc_m() {
            on_turn(distance_m / self.turn_radius_m)
        } else {
            self.course_rad
        }
    }

    /// The rest of the leg from `elapsed_s` seconds in: the same curve and
    /// speed profile, as a leg of its own.
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
    /// // Slowing from 10 m/s to 5 m/s: 30 s in, 7 m/s and 40 s left to slow.
    /// let slowing = leg.from_speed(10.0, 0.1);
    /// let rest = slowing.remainder(30.0);
    /// assert!((rest.start_speed_mps() - 7.0).abs() < 1e-9);
    /// assert!((rest.speed_change_s() - 20.0).abs() < 1e-9);
    /// assert!((rest.duration_s() - (slowing.duration_s() - 30.0)).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn remainder(&self, elapsed_s: f64) -> Leg {
        if self.speed_change.is_none() {
            return self.remainder_at_one_speed(elapsed_s);
        }
        let elapsed_s = elapsed_s.clamp(0.0, self.duration_s());
        let sailed_m = self.distance_at(elapsed_s).min(self.length_m());
        let pose = self.pose_along(sailed_m);
        let speed_change = self.speed_change.and_then(|change| {
            (elapsed_s < self.speed_change_s()).then_some(SpeedChange {
                start_speed_mps: self.speed_at(elapsed_s),
                ..change
            })
        });
        let arc_m = self.arc_m();
        if sailed_m < arc_m {
            let swept = sailed_m / self.turn_radius_m;
            Leg {
                start_m: pose.position_m,
                start_course_rad: pose.course_rad,
                turn_rad: self.turn_rad - self.turn_rad.signum() * swept,
                speed_change,
                ..*self
            }
        } else {
            Leg {
                start_m: pose.position_m,
                start_course_rad: self.course_rad,
                turn_rad: 0.0,
                straight_m: (self.straight_m - (sailed_m - arc_m)).max(0.0),
                speed_change,
                ..*self
            }
        }
    }

    /// [`remainder`](Self::remainder) of a leg sailed at one speed, in the
    /// form the planner has always cut legs.
    fn remainder_at_one_speed(&self, elapsed_s: f64) -> Leg {
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

    /// How far a chord of [`pieces`](Self::pieces) may lie from the arc, metres.
    #[must_use]
    pub fn chord_error_m(&self) -> f64 {
        self.turn_radius_m * (1.0 - (CHORD_ANGLE_RAD / 2.0).cos())
    }

    /// How far ownship may be, along its curve, from where a piece sailed at
    /// its mean velocity puts it, metres: `a d² / 8` for a piece of `d`
    /// seconds (at most [`SPEED_PIECE_S`]) while the speed changes at `a`
    /// (0 without a change of speed).
    #[must_use]
    pub fn timing_error_m(&self) -> f64 {
        self.speed_change_rate_mps2() * SPEED_PIECE_S * SPEED_PIECE_S / 8.0
    }

    /// Everything a check must add to the clearance for a piece of this
    /// leg: [`chord_error_m`](Self::chord_error_m) plus
    /// [`timing_error_m`](Self::timing_error_m), metres.
    #[must_use]
    pub fn piece_error_m(&self) -> f64 {
        self.chord_error_m() + self.timing_error_m()
    }
}

/// Seconds to sail `distance_m` at `speed_mps`: none for no distance, also
/// at rest (a leg of a stopped ownship that stays stopped: 0/0 would make
/// every time on it NaN, and `pose_at` panic).
fn at_one_speed_s(distance_m: f64, speed_mps: f64) -> f64 {
    if distance_m == 0.0 {
        0.0
    } else {
        distance_m / speed_mps
    }
}
