//! The straight pieces a leg is checked by ([`Leg::pieces`]): [`Piece`], and
//! the walk that cuts a leg into them.

use super::leg::{Leg, SAME_POINT_M};
use super::{CHORD_ANGLE_RAD, SPEED_PIECE_S};
use glam::DVec2;
use vorrt_geometry::angle;

/// A straight piece of a leg, as the checks see it: an arc is cut into
/// chords, a change of speed into pieces of at most [`SPEED_PIECE_S`], each
/// sailed at its mean velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Where the piece starts, metres.
    pub start_m: DVec2,
    /// Course along the piece, radians.
    pub course_rad: f64,
    /// Mean velocity along the piece, m/s.
    pub velocity_mps: DVec2,
    /// Seconds from the leg's start to the piece's start.
    pub elapsed_s: f64,
    /// Duration of the piece, seconds.
    pub duration_s: f64,
    /// Whether the piece is a chord of the turn (true) or part of the settled
    /// straight run (false).
    pub turning: bool,
    /// Whether ownship's speed changes along the piece (it is part of the
    /// leg's change of speed, not yet at the settled speed).
    pub changing_speed: bool,
}

impl Piece {
    /// Whether the piece is part of the manoeuvre's transition (a chord of
    /// the turn, or the change of speed) rather than the settled motion.
    #[must_use]
    pub fn transient(&self) -> bool {
        self.turning || self.changing_speed
    }
}

impl Piece {
    /// Where the piece ends, metres.
    #[must_use]
    pub fn end_m(&self) -> DVec2 {
        self.start_m + self.velocity_mps * self.duration_s
    }
}

impl Leg {
    /// The leg as straight pieces, each sailed at its mean velocity: the arc
    /// cut into chords of at most [`CHORD_ANGLE_RAD`], the straight run into
    /// pieces of at most `max_piece_m` metres (a whole run when it is
    /// shorter), and the change of speed, where there is one, into pieces of
    /// at most [`SPEED_PIECE_S`] seconds. An instantaneous turn has no chord.
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a piece count: the ceiling of a non-negative ratio"
    )]
    #[expect(
        clippy::cast_sign_loss,
        reason = "a piece count: the ceiling of a non-negative ratio"
    )]
    pub fn pieces(&self, max_piece_m: f64) -> impl Iterator<Item = Piece> + '_ {
        let turn = self.turn_rad.abs();
        let chord_count = if self.turn_radius_m > 0.0 && turn > 0.0 {
            (turn / CHORD_ANGLE_RAD).ceil().max(1.0) as usize
        } else {
            0
        };
        let run_count = if self.straight_m > 0.0 {
            if max_piece_m > 0.0 && self.straight_m > max_piece_m {
                (self.straight_m / max_piece_m).ceil() as usize
            } else {
                1
            }
        } else {
            0
        };
        let change_s = self.speed_change_s();
        let change_count = if change_s > 0.0 {
            (change_s / SPEED_PIECE_S).ceil() as usize
        } else {
            0
        };
        Pieces {
            leg: self,
            index: 0,
            arc_m: self.arc_m(),
            length_m: self.length_m(),
            chords: (0, chord_count),
            runs: (0, run_count),
            changes: (0, change_count),
            change_s,
            change_m: self.speed_change_m(),
            from_m: 0.0,
            centre_m: self.arc_centre_m(),
            turn_end_m: self.turn_end_m(),
            unit: angle::course_to_unit(self.course_rad),
            last_to: None,
            last_chord_to: None,
        }
    }
}

/// The pieces of a leg: the union of three grids of distances along it (the
/// arc's chords, the straight run's pieces, the speed change's time steps),
/// walked in order.
pub(super) struct Pieces<'a> {
    pub(super) leg: &'a Leg,
    /// How many pieces have been given.
    pub(super) index: usize,
    pub(super) arc_m: f64,
    pub(super) length_m: f64,
    /// (next index, count) of each grid.
    pub(super) chords: (usize, usize),
    pub(super) runs: (usize, usize),
    pub(super) changes: (usize, usize),
    pub(super) change_s: f64,
    /// Metres sailed while the speed changes.
    pub(super) change_m: f64,
    /// Where the next piece starts, metres along the leg.
    pub(super) from_m: f64,
    /// The leg's turn end and the unit vector of its course, worked out
    /// once (`Leg::turn_end_m`, `angle::course_to_unit`).
    pub(super) turn_end_m: DVec2,
    pub(super) unit: DVec2,
    /// Where the last piece ended: (metres along the leg, position).
    pub(super) last_to: Option<(f64, DVec2)>,
    /// The centre of the turn's arc (`Leg::arc_centre_m`), worked out once.
    pub(super) centre_m: DVec2,
    /// The index of the last chord cut at one speed and where it ended: the
    /// next chord starts there (the same point, worked out once).
    pub(super) last_chord_to: Option<(usize, DVec2)>,
}

impl Pieces<'_> {
    /// The next point of each grid beyond `from_m`, skipping points on or
    /// before it.
    #[expect(
        clippy::cast_precision_loss,
        reason = "piece counts and indices are small, so exact in f64"
    )]
    fn next_point(&mut self) -> Option<f64> {
        let (leg, arc_m, straight_m) = (self.leg, self.arc_m, self.leg.straight_m);
        let change_s = self.change_s;
        let from_m = self.from_m;
        let (chord_count, run_count, change_count) = (self.chords.1, self.runs.1, self.changes.1);
        let mut best = f64::INFINITY;
        let mut visit = |grid: &mut (usize, usize), point: &dyn Fn(usize) -> f64| {
            while grid.0 < grid.1 {
                let at = point(grid.0 + 1);
                if at > from_m + SAME_POINT_M {
                    best = best.min(at);
                    return;
                }
                grid.0 += 1;
            }
        };
        visit(&mut self.chords, &|k| arc_m * k as f64 / chord_count as f64);
        visit(&mut self.runs, &|k| {
            arc_m + straight_m * k as f64 / run_count as f64
        });
        visit(&mut self.changes, &|k| {
            leg.distance_at(change_s * k as f64 / change_count as f64)
        });
        (best.is_finite()).then(|| best.min(self.length_m))
    }
}

impl Pieces<'_> {
    /// The `index`-th piece of a leg sailed at one speed: chords of equal
    /// angle, then runs of equal length, in the form the planner has always
    /// cut legs (its recorded plans are reproduced bit for bit).
    #[expect(
        clippy::cast_precision_loss,
        reason = "piece counts and indices are small, so exact in f64"
    )]
    fn at_one_speed(&mut self, index: usize) -> Option<Piece> {
        let leg = self.leg;
        let (chord_count, run_count) = (self.chords.1, self.runs.1);
        if index >= chord_count + run_count {
            return None;
        }
        let turn = leg.turn_rad.abs();
        let turn_s = leg.turn_duration_s();
        if index < chord_count {
            let chord_s = turn_s / chord_count as f64;
            let from = match self.last_chord_to {
                Some((last, to_m)) if last + 1 == index => to_m,
                _ => leg.on_arc_about(self.centre_m, turn * index as f64 / chord_count as f64),
            };
            let to = leg.on_arc_about(
                self.centre_m,
                turn * (index + 1) as f64 / chord_count as f64,
            );
            self.last_chord_to = Some((index, to));
            let course_rad = angle::normalize_2pi(
                leg.start_course_rad
                    + leg.turn_rad.signum() * turn * (index as f64 + 0.5) / chord_count as f64,
            );
            return Some(Piece {
                start_m: from,
                course_rad,
                velocity_mps: (to - from) / chord_s,
                elapsed_s: chord_s * index as f64,
                duration_s: chord_s,
                turning: true,
                changing_speed: false,
            });
        }
        let run = index - chord_count;
        let run_s = leg.straight_duration_s() / run_count as f64;
        // Leg::velocity_mps is course_to_unit(course) * speed.
        let velocity = self.unit * leg.speed_mps;
        let (start_m, duration_s) = if run_count == 1 {
            (self.turn_end_m, leg.straight_duration_s())
        } else {
            (self.turn_end_m + velocity * (run_s * run as f64), run_s)
        };
        Some(Piece {
            start_m,
            course_rad: leg.course_rad,
            velocity_mps: velocity,
            elapsed_s: turn_s + run_s * run as f64,
            duration_s,
            turning: false,
            changing_speed: false,
        })
    }
}

impl Iterator for Pieces<'_> {
    type Item = Piece;

    #[expect(
        clippy::float_cmp,
        reason = "the last end is reused only for the very same distance"
    )]
    fn next(&mut self) -> Option<Piece> {
        if self.leg.speed_change.is_none() {
            let piece = self.at_one_speed(self.index);
            self.index += 1;
            return piece;
        }
        if self.from_m >= self.length_m - SAME_POINT_M {
            return None;
        }
        let to_m = self.next_point()?;
        let leg = self.leg;
        let (from_m, arc_m) = (self.from_m, self.arc_m);
        self.from_m = to_m;
        let start_s = leg.time_at_distance(from_m);
        let duration_s = leg.time_at_distance(to_m) - start_s;
        let along = |distance_m: f64| {
            leg.pose_along_about(self.centre_m, distance_m, self.turn_end_m, self.unit)
                .position_m
        };
        // A piece starts where the last one ended.
        let from = match self.last_to {
            Some((at_m, position_m)) if at_m == from_m => position_m,
            _ => along(from_m),
        };
        let to = along(to_m);
        self.last_to = Some((to_m, to));
        let turning = to_m <= arc_m + SAME_POINT_M && arc_m > 0.0;
        let course_rad = if turning {
            let swept = 0.5 * (from_m + to_m) / leg.turn_radius_m;
            angle::normalize_2pi(leg.start_course_rad + leg.turn_rad.signum() * swept)
        } else {
            leg.course_rad
        };
        let velocity_mps = if duration_s > 0.0 && duration_s.is_finite() {
            (to - from) / duration_s
        } else {
            DVec2::ZERO
        };
        Some(Piece {
            start_m: from,
            course_rad,
            velocity_mps,
            elapsed_s: start_s,
            duration_s: if duration_s.is_finite() {
                duration_s
            } else {
                0.0
            },
            turning,
            changing_speed: from_m < self.change_m - SAME_POINT_M,
        })
    }
}
