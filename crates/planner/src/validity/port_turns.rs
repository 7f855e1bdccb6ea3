//! Which courses a leg's port turns are judged from, on which of its
//! pieces, and the turn a later leg inherits (decisions 28, 57, 69).

use super::{LegMemo, observed};
use crate::constraint::Constraint;
use crate::plan::RejectionCause;
use crate::safety::{Move, SafetyChecker};
use vorrt_colregs::rules::STEADY_COURSE_WINDOW_S;
use vorrt_jfs::Leg;
use vorrt_jfs::motion::LegPoses;

/// A turn an observer of course over ground still sees after the leg that
/// made it ends: a port turn onto a vessel is judged from the course held
/// before it for two windows after the turn ([`STEADY_COURSE_WINDOW_S`]),
/// whichever leg ownship is then on (decision 69).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnSeen {
    /// The course held before the turn, radians.
    pub course_before_rad: f64,
    /// Until when the turn is seen, seconds after the plan's start.
    pub until_elapsed_s: f64,
}

/// The port-turn judgement of one leg: the courses it is judged from, the
/// pieces it is judged on, and a turn of an earlier leg still seen.
pub(super) struct PortTurns<'l> {
    /// The courses this leg's own turn is judged from (decision 57).
    turn_from_rad: [Option<f64>; 2],
    /// A turn of an earlier leg still seen at this leg's start.
    carried: Option<TurnSeen>,
    /// The leg's poses, for the observer's courses over ground, where the
    /// leg turns to port.
    poses: Option<LegPoses<'l>>,
    /// When the leg starts, seconds after the plan's start.
    start_elapsed_s: f64,
    /// Until when an observer sees this leg's own turn.
    settled_until_s: f64,
    /// The course held before this leg, radians.
    before_course_rad: f64,
}

impl<'l> PortTurns<'l> {
    /// The judgement of `leg`, starting `start_elapsed_s` after the plan's
    /// start, `before_course_rad` the course held before it; on a plan's
    /// first leg `turning_at_start` says whether ownship was then part way
    /// round a turn; `turn_seen` is what the leg before it left.
    pub(super) fn new(
        leg: &'l Leg,
        (start_elapsed_s, before_course_rad): (f64, f64),
        turning_at_start: bool,
        turn_seen: Option<TurnSeen>,
    ) -> Self {
        // On a plan's first leg the observer's steady course still lags a
        // turn ended within the window before the plan (it is the course
        // before that turn); an encounter arising later in the leg's turn
        // is judged by the evaluation from the course held at the leg's
        // start (looking back a window into the turn, then to its start).
        // Both are asked, where ownship holds its course at the start (a
        // plan made part way round a turn is judged from the course before
        // it alone): a return to the old course soon after an alteration
        // is a port turn from the course then held.
        let turn_from_rad = [
            Some(before_course_rad),
            (start_elapsed_s <= 0.0
                && !turning_at_start
                && before_course_rad.to_bits() != leg.start_course_rad.to_bits())
            .then_some(leg.start_course_rad),
        ];
        // A port turn in this leg is also judged as an observer of course
        // over ground judges it at the piece's start: the course over the
        // last window, from the course its steady-course search reaches
        // (`observed::observed_turn_rad`; decision 57).
        let turns_to_port = leg.turn_rad < 0.0 || turn_from_rad[1].is_some();
        Self {
            turn_from_rad,
            // A turn of an earlier leg still seen at this leg's start: its
            // course before is asked too, on the pieces starting while it
            // is seen (decision 69). A return that ends in a small
            // correction (a return part of the way, then the goal) is still
            // the port turn before it to an observer, whichever leg it is
            // judged on.
            carried: turn_seen.filter(|seen| seen.until_elapsed_s >= start_elapsed_s),
            poses: turns_to_port.then(|| LegPoses::new(leg)),
            start_elapsed_s,
            // An observer judging course over ground over a window sees the
            // turn for a window after it ends, and a new encounter is
            // judged against the course a window before it arose: two
            // windows.
            settled_until_s: start_elapsed_s + leg.turn_duration_s() + 2.0 * STEADY_COURSE_WINDOW_S,
            before_course_rad,
        }
    }

    /// Whether `candidate` is judged for a port turn, and if so whether for
    /// this leg's own turn (`Some(true)`: it is on the turn, `turning`, or
    /// starts within the window) or only for a turn carried in.
    pub(super) fn wanted(&self, candidate: &Move, turning: bool) -> Option<bool> {
        let own = turning || starts_by(candidate, self.settled_until_s);
        (own || self.carried_at(candidate).is_some()).then_some(own)
    }

    /// The carried turn, if `candidate` starts while it is seen.
    fn carried_at(&self, candidate: &Move) -> Option<TurnSeen> {
        self.carried
            .filter(|seen| starts_by(candidate, seen.until_elapsed_s))
    }

    /// Judges `candidate` for a port turn toward a vessel from every course
    /// it is judged from ([`wanted`](Self::wanted) says `own`).
    pub(super) fn check<C: Constraint>(
        &self,
        checker: &SafetyChecker<'_, C>,
        candidate: &Move,
        memo: &mut LegMemo,
        own: bool,
    ) -> Result<(), RejectionCause> {
        if let Some(seen) = self.carried_at(candidate) {
            checker.check_settled_turn_reusing(seen.course_before_rad, candidate, memo)?;
        }
        if !own {
            return Ok(());
        }
        let from_rad = self.turn_from_rad.iter().flatten();
        from_rad.clone().try_for_each(|&from_rad| {
            checker.check_settled_turn_reusing(from_rad, candidate, memo)
        })?;
        let Some(poses) = &self.poses else {
            return Ok(());
        };
        // No vessel within MTD: no course judged from makes a port turn
        // toward one, and the observer's courses are not worked out.
        if !checker.any_within_mtd(candidate) {
            return Ok(());
        }
        let (over_ground_rad, seen_before_rad) =
            observed::observed_turn_rad(poses, candidate.start_elapsed_s - self.start_elapsed_s);
        let seen = Move {
            course_rad: over_ground_rad,
            ..*candidate
        };
        from_rad
            .chain(&seen_before_rad)
            .try_for_each(|&from_rad| checker.check_settled_turn_reusing(from_rad, &seen, memo))
    }

    /// What the next leg inherits from `leg`, ending `end_elapsed_s` after
    /// the plan's start: the turn still seen then, the earlier one first
    /// (the course an observer holds steady is the one before the first
    /// turn of the window), else this leg's own where it ends within two
    /// windows of the turn and changed the course.
    pub(super) fn seen_after(&self, leg: &Leg, end_elapsed_s: f64) -> Option<TurnSeen> {
        self.carried
            .filter(|seen| seen.until_elapsed_s > end_elapsed_s)
            .or_else(|| {
                (self.settled_until_s > end_elapsed_s
                    && self.before_course_rad.to_bits() != leg.course_rad.to_bits())
                .then_some(TurnSeen {
                    course_before_rad: self.before_course_rad,
                    until_elapsed_s: self.settled_until_s,
                })
            })
    }
}

/// Whether `candidate` starts (less a piece's length: the first piece
/// after the window is judged too, decision 51) by `until_s`.
fn starts_by(candidate: &Move, until_s: f64) -> bool {
    candidate.start_elapsed_s - candidate.duration_s <= until_s
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use vorrt_jfs::Pose;

    const SPEED_MPS: f64 = 6.0;

    /// From 035 at once onto `course_deg`, then `straight_m` on.
    fn return_onto(course_deg: f64, straight_m: f64) -> Leg {
        let from = Pose {
            position_m: DVec2::ZERO,
            course_rad: 35f64.to_radians(),
        };
        Leg::turning_onto(from, course_deg.to_radians(), 0.0, SPEED_MPS, straight_m)
    }

    /// A piece of 10 s starting `start_elapsed_s` after the plan's start.
    fn piece_at(start_elapsed_s: f64) -> Move {
        Move {
            start_m: DVec2::ZERO,
            start_elapsed_s,
            course_rad: 0.0,
            velocity_mps: DVec2::new(0.0, SPEED_MPS),
            duration_s: 10.0,
        }
    }

    #[test]
    fn a_leg_ending_within_two_windows_of_its_turn_leaves_the_course_before() {
        let before_rad = 35f64.to_radians();
        // 60 m at 6 m/s: the leg ends 10 s after its turn (made at once).
        let short = return_onto(350.0, 60.0);
        let turns = PortTurns::new(&short, (0.0, before_rad), false, None);
        let seen = turns.seen_after(&short, short.duration_s());
        assert_eq!(
            seen,
            Some(TurnSeen {
                course_before_rad: before_rad,
                until_elapsed_s: 2.0 * STEADY_COURSE_WINDOW_S,
            })
        );
        // 1 km: the leg outlasts the two windows; nothing is left.
        let long = return_onto(350.0, 1000.0);
        let turns = PortTurns::new(&long, (0.0, before_rad), false, None);
        assert_eq!(turns.seen_after(&long, long.duration_s()), None);
        // No change of course: nothing to see.
        let on = return_onto(35.0, 60.0);
        let turns = PortTurns::new(&on, (0.0, before_rad), false, None);
        assert_eq!(turns.seen_after(&on, on.duration_s()), None);
    }

    #[test]
    fn a_turn_carried_in_is_kept_before_the_legs_own_and_asked_while_seen() {
        let carried = TurnSeen {
            course_before_rad: 35f64.to_radians(),
            until_elapsed_s: 120.0,
        };
        // A correction leg from 350 to 351 starting 10 s into the plan.
        let from = Pose {
            position_m: DVec2::ZERO,
            course_rad: 350f64.to_radians(),
        };
        let correction = Leg::turning_onto(from, 351f64.to_radians(), 0.0, SPEED_MPS, 60.0);
        let start_s = 10.0;
        let turns = PortTurns::new(
            &correction,
            (start_s, 350f64.to_radians()),
            false,
            Some(carried),
        );
        // The earlier turn first: it is still seen when this leg ends.
        assert_eq!(
            turns.seen_after(&correction, start_s + correction.duration_s()),
            Some(carried)
        );
        // Its own window (a turn at once, then two windows) reaches 130 s,
        // the carried one 120 s: pieces starting at 125 s and at 139 s
        // (129 s less their 10 s) are judged for the leg's own turn, one
        // at 200 s not at all unless it is on the turn.
        assert_eq!(turns.wanted(&piece_at(125.0), false), Some(true));
        assert_eq!(turns.wanted(&piece_at(139.0), false), Some(true));
        assert_eq!(turns.wanted(&piece_at(200.0), false), None);
        assert_eq!(turns.wanted(&piece_at(200.0), true), Some(true));
        // A carried turn seen no longer when the leg starts is dropped.
        let late = PortTurns::new(
            &correction,
            (130.0, 350f64.to_radians()),
            false,
            Some(carried),
        );
        assert!(late.carried.is_none());
    }

    #[test]
    fn a_piece_after_the_legs_own_window_is_asked_only_for_the_turn_carried_in() {
        let carried = TurnSeen {
            course_before_rad: 35f64.to_radians(),
            until_elapsed_s: 400.0,
        };
        let leg = Leg::straight(DVec2::ZERO, 351f64.to_radians(), 3000.0, SPEED_MPS);
        let turns = PortTurns::new(&leg, (100.0, 351f64.to_radians()), false, Some(carried));
        // The leg's own window: 100 s + 0 (no turn) + 120 s.
        assert_eq!(turns.wanted(&piece_at(200.0), false), Some(true));
        assert_eq!(turns.wanted(&piece_at(300.0), false), Some(false));
        assert_eq!(turns.wanted(&piece_at(420.0), false), None);
    }
}
