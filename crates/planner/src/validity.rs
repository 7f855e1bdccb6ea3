//! The one validity check of ownship's motion, and the encounter state it
//! carries along a branch.
//!
//! [`MotionValidator::validate`] judges a whole [`Leg`] (a turn then a
//! straight run, as [`vorrt_jfs::MotionModel`] makes it) and advances the
//! encounters in force to the leg's end, in one operation. The tree's growth,
//! the path simplifier ([`crate::simplify`]) and a closed loop's "is my plan
//! still valid" test all call it, so they can never judge differently.
//!
//! [`SafetyChecker`] is the planner's validator (paper, Algorithm 3, see
//! [`crate::safety`]). A leg is cut into pieces: the chords of its turn are
//! checked for clearance along the curve actually sailed (`d_th` plus the
//! chord's largest distance from the arc) and for the rules an observer sees
//! broken on the way (a stand-on vessel's course and speed, a turn to port);
//! so are the pieces along which the speed changes (`d_th` plus the timing
//! error of a piece sailed at its mean velocity). The pieces of its straight
//! run, on the settled course at the settled speed, get every check (velocity
//! obstacle, clearance, clearance ahead, COLREGs). A turn, or a change of
//! speed, is judged as a manoeuvre by the course and speed it settles on, as
//! an observer judges one (rule 8(b)): the headings and speeds passed through
//! on the way are transient. The encounters move on after every piece,
//! transient or not, as the closed loop moves them at every step.

use crate::constraint::{Constraint, NoConstraint, Segment};
use crate::plan::RejectionCause;
use crate::safety::{Move, SafetyChecker, StateVelocities};
use glam::DVec2;
use vorrt_colregs::risk::no_risk_while_steady;
use vorrt_colregs::rules::{
    STEADY_COURSE_WINDOW_S, acting_for_any, alteration_made, steady_course_rad,
};
use vorrt_colregs::{
    EncounterLatch, RuleParameters, VesselState, update_latch_judged, update_latch_seen_moving,
};
use vorrt_jfs::{Leg, LinearTrack};

pub(crate) mod key;
mod memo;
mod observed;
mod port_turns;
mod prefixes;
pub(crate) use memo::{Along, LegMemo, TurnGeometry};
use port_turns::PortTurns;
pub use port_turns::TurnSeen;
pub(crate) use prefixes::LegPrefixes;
use prefixes::{Carried, Keeping};

/// The encounters in force at one point of a branch: per target, the latch
/// (rules 13-17) and what ownship carries for it ([`alteration_made`]: for a
/// give-way encounter the largest alteration of course from its reference
/// made since it began, rule 16; for a stand-on one the course change it was
/// last free to make, rule 17), radians.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EncounterState {
    /// Each target's encounter in force, if any.
    pub latches: Vec<Option<EncounterLatch>>,
    /// Each target's alteration made, radians (0 without an encounter).
    pub alterations: Vec<f64>,
    /// A turn of an earlier leg that an observer still sees when this
    /// point is reached (decision 69), if any: the legs that follow are
    /// judged from the course held before it, as the turn's own leg is.
    pub turn_seen: Option<TurnSeen>,
}

impl EncounterState {
    /// A state with `latches` and `alterations` in force and no turn seen.
    #[must_use]
    pub fn new(latches: Vec<Option<EncounterLatch>>, alterations: Vec<f64>) -> Self {
        Self {
            latches,
            alterations,
            turn_seen: None,
        }
    }

    /// Copies `latches` and `alterations` in, reusing the buffers, with no
    /// turn seen (a tree's node keeps none: its legs are judged on their
    /// own, and the path extracted from it leg after leg).
    pub fn set(&mut self, latches: &[Option<EncounterLatch>], alterations: &[f64]) {
        self.turn_seen = None;
        self.latches.clear();
        self.latches.extend_from_slice(latches);
        self.alterations.clear();
        self.alterations.extend_from_slice(alterations);
    }

    /// Advances every encounter to ownship's state `own_then`, at `elapsed_s`
    /// after the tracks' time zero (`time_s` on the clock), with each target
    /// where its track puts it then: as [`advance_to`](Self::advance_to),
    /// for the planner's predicted tracks.
    pub fn advance(
        &mut self,
        own_then: &VesselState,
        steady_course_rad: f64,
        tracks: &[LinearTrack],
        elapsed_s: f64,
        time_s: f64,
        rules: &RuleParameters,
    ) {
        self.advance_with(
            own_then,
            steady_course_rad,
            (
                tracks.len(),
                |index: usize| tracks[index].position_at(elapsed_s),
                |index: usize| tracks[index].state_at(elapsed_s),
            ),
            (time_s, rules),
            None,
            |_| false,
        );
    }

    /// As [`advance`](Self::advance) along `checker`'s tracks, with its
    /// clock and rules, keeping in `memo` what carries from one piece of a
    /// leg to the next: each target's velocity for the course and speed it
    /// had when last worked out, reused while they stay the same (the same
    /// velocities, so the same encounters), and the targets no risk can
    /// reach while ownship and they hold their velocities (decision 54).
    /// `sailed_mps`: ownship's velocity over the piece just sailed, if it
    /// was on its settled course and speed (not a transient piece).
    pub(crate) fn advance_reusing<C: Constraint>(
        &mut self,
        own_then: &VesselState,
        steady_course_rad: f64,
        checker: &SafetyChecker<'_, C>,
        (elapsed_s, sailed_mps): (f64, Option<DVec2>),
        memo: &mut LegMemo,
    ) {
        let tracks = checker.tracks();
        let clock = (checker.start_time_s() + elapsed_s, &checker.config().rules);
        // A target out of reach of the leg has no encounter and carries no
        // alteration, and none can begin (it stays beyond MTD): it is
        // skipped (`SafetyChecker::within_reach`).
        self.advance_with(
            own_then,
            steady_course_rad,
            (
                tracks.len(),
                |index: usize| tracks[index].position_at(elapsed_s),
                |index: usize| tracks[index].state_at(elapsed_s),
            ),
            clock,
            Some(Along {
                memo,
                tracks,
                known: checker.state_velocities(),
                elapsed_s,
                sailed_mps: sailed_mps.filter(|_| checker.leg_memo()),
            }),
            |index| !checker.may_reach(index),
        );
    }

    /// Advances every encounter to ownship's state `own_then` at `time_s`,
    /// with the targets' states then, in target order (a closed loop's true
    /// present states): latches are updated from the new geometry (a new
    /// one judged on `steady_course_rad`, the course held before any recent
    /// turn: [`update_latch_steady`](vorrt_colregs::update_latch_steady)), and the alteration made grows to
    /// `own_then`'s course ([`alteration_made`]). The same operation as
    /// [`advance`](Self::advance) along a planner's branch, so a closed loop
    /// carries the encounters as the planner does.
    pub fn advance_to(
        &mut self,
        own_then: &VesselState,
        steady_course_rad: f64,
        targets_then: &[VesselState],
        time_s: f64,
        rules: &RuleParameters,
    ) {
        self.advance_with(
            own_then,
            steady_course_rad,
            (
                targets_then.len(),
                |index: usize| targets_then[index].position_m,
                |index: usize| targets_then[index],
            ),
            (time_s, rules),
            None,
            |_| false,
        );
    }

    /// The one propagation behind [`advance`](Self::advance) and
    /// [`advance_to`](Self::advance_to), with the number of targets and
    /// each one's position then (by index), and its state then (by index,
    /// asked only for a target within MTD or with an encounter): the ranges
    /// need only positions, which a track gives for less than its state;
    /// `clock` is `time_s` and the rules; `along` the memo of
    /// [`advance_reusing`](Self::advance_reusing) (`None`: none kept);
    /// `out_of_reach(index)`: that target has no encounter, carries no
    /// alteration and cannot latch one (its state is not used).
    fn advance_with(
        &mut self,
        own_then: &VesselState,
        steady_course_rad: f64,
        targets_then: (
            usize,
            impl Fn(usize) -> DVec2,
            impl Fn(usize) -> VesselState,
        ),
        clock: (f64, &RuleParameters),
        mut along: Option<Along<'_>>,
        out_of_reach: impl Fn(usize) -> bool,
    ) {
        let (time_s, rules) = clock;
        let (count, position_then, state_then) = targets_then;
        // Whether ownship was acting for some vessel up to now (giving way,
        // or free to act within the action range): a stand-on encounter
        // then carries the course it was free to take.
        let acting_for_others = acting_for_any(
            self.latches
                .iter()
                .take(count)
                .enumerate()
                .filter_map(|(index, latch)| {
                    latch
                        .as_ref()
                        .map(|latch| (latch, own_then.position_m.distance(position_then(index))))
                }),
            rules,
        );
        // Ownship's velocity, and as a new encounter sees it (its steady
        // course at its speed), worked out once for every target (decision
        // 54): the velocities `update_latch_steady` works out for each.
        // Along a leg, kept from piece to piece while the course and speed
        // stay the same bits.
        let (own_velocity_mps, seen_mps) = if let Some(along) = along.as_mut() {
            along.own_velocities(own_then, steady_course_rad)
        } else {
            let own_velocity_mps = own_then.velocity_mps();
            let seen_mps = if steady_course_rad.to_bits() == own_then.course_rad.to_bits() {
                own_velocity_mps
            } else {
                VesselState {
                    course_rad: steady_course_rad,
                    ..*own_then
                }
                .velocity_mps()
            };
            (own_velocity_mps, seen_mps)
        };
        // Whether a readily apparent turn of ownship to starboard shows: a
        // vessel beyond MTD it is made for is latched then (decision 74).
        let turning_to_starboard =
            shows_early_latch_turn(steady_course_rad, own_then.course_rad, rules);
        // Whether the memo may be kept at this piece (decision 54).
        let steady = along
            .as_mut()
            .is_some_and(|along| along.settle(seen_mps, self.latches.len()));
        for (index, (latch, altered)) in self
            .latches
            .iter_mut()
            .zip(self.alterations.iter_mut())
            .take(count)
            .enumerate()
        {
            if out_of_reach(index) {
                continue;
            }
            let before = *latch;
            if before.is_none() && steady && along.as_ref().is_some_and(|along| along.clear(index))
            {
                // No encounter, and no risk can arise while ownship and the
                // target hold the velocities they had when that was found
                // (`no_risk_while_steady`): none begins.
                *altered = alteration_made(None, None, *altered, own_then.course_rad, false);
                continue;
            }
            if before.is_none() {
                let range_m = own_then.position_m.distance(position_then(index));
                if !vorrt_colregs::rules::within_mtd(range_m, rules) {
                    // Beyond MTD an encounter begins only as the judges
                    // latch one: for a vessel ownship's turn to starboard
                    // is made for, within the early-action range (decision
                    // 74). Otherwise none begins (the latch's first test,
                    // on the same range): the state is not needed.
                    *latch = (turning_to_starboard && range_m < rules.early_action_range_m)
                        .then(|| state_then(index))
                        .and_then(|target| {
                            update_latch_judged(
                                None,
                                own_then,
                                steady_course_rad,
                                &target,
                                time_s,
                                rules,
                            )
                        });
                    *altered = alteration_made(None, *latch, *altered, own_then.course_rad, false);
                    continue;
                }
            }
            let target = state_then(index);
            let target_mps = along.as_mut().map_or_else(
                || target.velocity_mps(),
                |along| along.velocity(index, &target),
            );
            *latch = update_latch_seen_moving(
                before,
                own_then,
                (own_velocity_mps, target_mps),
                (steady_course_rad, seen_mps),
                &target,
                time_s,
                rules,
            );
            if let (None, None, true, Some(along)) = (before, *latch, steady, along.as_mut()) {
                along.remember(
                    index,
                    (own_then.position_m, seen_mps),
                    &target,
                    target_mps,
                    // The pair's distance (decision 50), as the latch judges it.
                    rules.risk_distance_m(own_then.length_m, target.length_m),
                );
            }
            *altered = alteration_made(
                before,
                *latch,
                *altered,
                own_then.course_rad,
                acting_for_others,
            );
        }
    }
}

/// The fewest pieces of `step_m` a leg must be longer than for
/// [`SafetyChecker::within_reach`] to be worked out for it.
const PRUNE_PIECES: f64 = 4.0;

/// How near the goal, metres, a leg must end to be taken for one to the
/// goal: nothing is sailed on from its end, so it is not kept for longer
/// legs ([`LegPrefixes`]).
const GOAL_REACHED_M: f64 = 1.0;

/// The fewest targets for which [`SafetyChecker::within_reach`] is worked
/// out: with fewer, the few it could skip spared less than it cost
/// (callgrind, `profile_tss 20 1`, 16 targets).
const PRUNE_TARGETS: usize = 32;

/// The course an observer sees steady at the end of a piece
/// ([`steady_course_rad`] over [`STEADY_COURSE_WINDOW_S`]): `times_s` are
/// just before the leg, its start, the end of its turn (or of the piece,
/// if sooner) and the piece's end; `courses_rad` the course before the
/// leg, at its start, and at the piece's end (held from the turn's end).
fn steady_through_turn(times_s: [f64; 4], courses_rad: [f64; 3]) -> f64 {
    let [before_rad, start_rad, now_rad] = courses_rad;
    steady_course_rad(
        &times_s,
        &[before_rad, start_rad, now_rad, now_rad],
        STEADY_COURSE_WINDOW_S,
    )
    .unwrap_or(now_rad)
}

/// The turn to starboard of the course an observer sees held at which the
/// planner latches a vessel beyond MTD that the turn is made for
/// ([`update_latch_judged`]; decision 74): a readily apparent alteration
/// ([`RuleParameters::apparent_turn_rad`]). The judges latch her at any
/// turn they can see; the planner holds only an alteration an observer
/// reads as action (rule 8(b)) until she is past. A drift of a few degrees
/// that a stand-on vessel may make (decision 46) latches nothing, and an
/// alteration of 35° latches her part way round, from the same held course.
#[must_use]
fn early_latch_turn_rad(rules: &RuleParameters) -> f64 {
    rules.apparent_turn_rad.max(rules.turn_tolerance_rad)
}

/// Whether ownship on `course_rad`, seen to have held `steady_course_rad`,
/// shows the turn to starboard at which the planner latches a vessel
/// beyond MTD ([`early_latch_turn_rad`]).
fn shows_early_latch_turn(steady_course_rad: f64, course_rad: f64, rules: &RuleParameters) -> bool {
    vorrt_colregs::rules::course_change_rad(steady_course_rad, course_rad)
        >= early_latch_turn_rad(rules)
}

/// Whether the turn at which the planner latches a vessel beyond MTD
/// ([`shows_early_latch_turn`]) may show along `leg` (the steady course an
/// observer sees at a piece is the course before the leg,
/// `before_course_rad`, or its start course, while the turn is in view;
/// the courses passed through lie between its start and its settled
/// course; decision 74).
pub(crate) fn may_show_starboard_turn(
    leg: &Leg,
    before_course_rad: f64,
    rules: &RuleParameters,
) -> bool {
    shows_early_latch_turn(before_course_rad, leg.course_rad, rules)
        || shows_early_latch_turn(leg.start_course_rad, leg.course_rad, rules)
        || shows_early_latch_turn(before_course_rad, leg.start_course_rad, rules)
}

/// Whether [`SafetyChecker::within_reach`] is worth working out for `leg`:
/// only on a leg of many pieces among many targets. On the short legs of a
/// tree (one or two pieces) it cost more than it spared (`vorrt simulate`
/// of a generated 100-target encounter: +20 % CPU).
fn worth_pruning<C: Constraint>(checker: &SafetyChecker<'_, C>, leg: &Leg) -> bool {
    checker.tracks().len() >= PRUNE_TARGETS
        && leg.length_m() > PRUNE_PIECES * checker.config().step_m
}

/// Judges ownship's motion: the seam shared by tree growth, path
/// simplification and a closed loop's plan check.
///
/// ```
/// use vorrt_planner::validity::{EncounterState, MotionValidator};
/// use vorrt_planner::safety::SafetyChecker;
/// use vorrt_planner::PlannerConfig;
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{Leg, TargetState};
/// use glam::DVec2;
///
/// let config = PlannerConfig::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// // A target lying still 150 m east of the line north.
/// let tracks = [TargetState::constant_velocity(
///     VesselState::new(DVec2::new(150.0, 1000.0), 0.0, 0.0, 50.0)).track()];
/// let checker = SafetyChecker::new(&config, &tracks, own, DVec2::new(0.0, 5000.0), 0.0);
/// let mut state = EncounterState::new(vec![None], vec![0.0]);
/// let north = Leg::straight(DVec2::ZERO, 0.0, 2000.0, 6.0);
/// assert!(checker.validate(&north, 0.0, &mut state).is_err()); // within d_th
/// let west = Leg::straight(DVec2::ZERO, 270f64.to_radians(), 2000.0, 6.0);
/// let mut state = EncounterState::new(vec![None], vec![0.0]);
/// assert!(checker.validate(&west, 0.0, &mut state).is_ok());
/// ```
pub trait MotionValidator {
    /// Checks `leg`, which starts `start_elapsed_s` seconds after the plan's
    /// start with the encounters `state` in force, and advances `state` to
    /// the leg's end. On an error `state` is left part way and must not be
    /// used.
    ///
    /// # Errors
    /// The first [`RejectionCause`] the leg runs into.
    fn validate(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
    ) -> Result<(), RejectionCause>;
}

impl<C: Constraint> MotionValidator for SafetyChecker<'_, C> {
    fn validate(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        self.validate_pieces(leg, start_elapsed_s, state, &mut false, None)
    }
}

impl<C: Constraint> SafetyChecker<'_, C> {
    /// Whether the verdicts of [`validate_pieces`](Self::validate_pieces)
    /// on a chord of a leg's turn are those of every leg with the same turn
    /// whatever its straight run: the targets within reach are not worked
    /// out per leg ([`worth_pruning`] is false for every leg).
    pub(crate) fn turn_verdicts_shared(&self) -> bool {
        self.tracks().len() < PRUNE_TARGETS
    }

    /// [`MotionValidator::validate`], saying in `on_turn` whether the piece
    /// judged last (the one refused, on an error) is a chord of the leg's
    /// turn: the chords, and everything judged on them, depend on the
    /// leg's start, turn, speeds and start time, and not on its straight
    /// run (where [`turn_verdicts_shared`](Self::turn_verdicts_shared)).
    /// With `prefixes` (and the clearance judged at), a leg resumes where a
    /// shorter one with the same start ended, and is kept for longer ones
    /// (decision 70): the same verdict and encounters.
    pub(crate) fn validate_pieces(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
        on_turn: &mut bool,
        prefixes: Option<(&LegPrefixes, f64)>,
    ) -> Result<(), RejectionCause> {
        // The targets that may come within reach of this leg, worked out
        // once: the others can change no verdict (decision 33).
        let before_s = start_elapsed_s - 1e-3;
        let before_course_rad = self.course_before(leg, start_elapsed_s);
        let in_reach = worth_pruning(self, leg)
            .then(|| self.within_reach(leg, start_elapsed_s, &state.latches, &state.alterations));
        let checker = self.only_within(in_reach.as_deref().unwrap_or(&[]));
        // The courses a port turn of this leg is judged from, and on which
        // pieces (decisions 28, 57, 69).
        let port_turns = PortTurns::new(
            leg,
            (start_elapsed_s, before_course_rad),
            self.turning_at_start,
            state.turn_seen,
        );
        // Each target's velocity, reused along the leg while its course and
        // speed stay the same, and the targets no risk can reach while the
        // velocities hold (decision 54).
        let mut memo = LegMemo::default();
        // The heading at the last piece's end (on a turn, part way round).
        let mut heading_rad = leg.start_course_rad;
        let step_m = self.config().step_m;
        // Only a long leg judged against every target is kept (a leg's
        // targets within reach depend on its length; a leg to the goal is
        // not sailed on).
        let prefixes = prefixes.filter(|_| {
            in_reach.is_none()
                && leg.straight_m > PRUNE_PIECES * step_m
                && leg.end_m().distance(self.goal_m()) > GOAL_REACHED_M
        });
        let carried = Carried {
            state,
            memo: &mut memo,
            heading_rad: &mut heading_rad,
            on_turn,
        };
        let (pieces, mut kept) = Keeping::start(prefixes, (leg, start_elapsed_s), step_m, carried);
        for piece in pieces {
            kept.sailed(piece);
            *on_turn = piece.turning;
            let candidate = Move {
                start_m: piece.start_m,
                start_elapsed_s: start_elapsed_s + piece.elapsed_s,
                course_rad: piece.course_rad,
                velocity_mps: piece.velocity_mps,
                duration_s: piece.duration_s,
            };
            // The user's constraint (land, a no-go area, a lane) on the
            // curve sailed, at every heading of a chord of the turn.
            let (segment, course_rad) =
                Segment::of_leg_piece(leg, &piece, start_elapsed_s, heading_rad);
            heading_rad = course_rad;
            self.constraint()
                .check_segment(&segment)
                .map_err(RejectionCause::Constraint)?;
            if piece.transient() {
                // A turn, or a change of speed, is judged as a manoeuvre by
                // the course and speed it settles on (rule 8(b)); but a
                // stand-on vessel's course and speed, and a turn to port, are
                // seen on the way (check_turning), and the encounters move on
                // as the manoeuvre is sailed, as the closed loop moves them at
                // every step. While the speed changes, ownship is up to the
                // timing error off the piece sailed at its mean velocity.
                checker.check_turning(
                    &candidate,
                    &state.latches,
                    &state.alterations,
                    segment.margin_m,
                )?;
                // A port turn is seen on the way too: a vessel from port
                // brought onto a collision course by a course the swing
                // passes through is latched there by the evaluation (its
                // course over ground part way round), and a vessel that
                // acts answers it (decision 51); so is gathering way after it,
                // short of the speed settled on (decision 62).
                if let Some(own) = port_turns.wanted(&candidate, piece.turning) {
                    port_turns.check(&checker, &candidate, &mut memo, own)?;
                }
            } else {
                if let Some(own) = port_turns.wanted(&candidate, false) {
                    // The course the leg's turn settles on, judged against
                    // every vessel while an observer still sees the turn
                    // (decision 28), on every piece that starts within the
                    // window and on the first after it: a vessel that comes
                    // within MTD part way through the window's last piece
                    // is latched there by the evaluation, and is seen at the
                    // next piece's start (decision 51).
                    port_turns.check(&checker, &candidate, &mut memo, own)?;
                }
                checker.check(&candidate, &state.latches, &state.alterations)?;
            }
            let end_elapsed_s = candidate.start_elapsed_s + candidate.duration_s;
            // The course an observer still sees steady: the one before this
            // leg's turn (or, on a plan's first leg, before the turn it
            // starts in) while that turn is within the window.
            let turn_end_s = (start_elapsed_s + leg.turn_duration_s()).min(end_elapsed_s);
            let steady_course_rad = steady_through_turn(
                [before_s, start_elapsed_s, turn_end_s, end_elapsed_s],
                [before_course_rad, leg.start_course_rad, course_rad],
            );
            let own_then = VesselState {
                position_m: piece.end_m(),
                course_rad,
                speed_mps: piece.velocity_mps.length(),
                ..*self.ownship()
            };
            state.advance_reusing(
                &own_then,
                steady_course_rad,
                &checker,
                (
                    end_elapsed_s,
                    (!piece.transient()).then_some(piece.velocity_mps),
                ),
                &mut memo,
            );
        }
        kept.keep(leg, (state, &memo, heading_rad));
        // What the next leg inherits (decision 69).
        state.turn_seen = port_turns.seen_after(leg, start_elapsed_s + leg.duration_s());
        Ok(())
    }
}

/// Checks `legs`, sailed one after the other from `problem`'s start with its
/// encounters (and alterations made) in force, with the planner's own
/// validator and no user constraint: how a closed loop asks whether the rest
/// of its plan is still valid as the targets are now predicted.
/// [`Planner::check_legs`](crate::Planner::check_legs) asks the same with the
/// planner's constraint.
///
/// # Errors
/// The first [`RejectionCause`] a leg runs into.
pub fn check_legs(
    config: &crate::PlannerConfig,
    problem: &crate::PlanningProblem,
    legs: &[Leg],
) -> Result<(), RejectionCause> {
    check_legs_with(config, problem, legs, &NoConstraint)
}

/// As [`check_legs`], keeping `constraint` as well.
///
/// # Errors
/// The first [`RejectionCause`] a leg runs into.
pub fn check_legs_with<C: Constraint>(
    config: &crate::PlannerConfig,
    problem: &crate::PlanningProblem,
    legs: &[Leg],
    constraint: &C,
) -> Result<(), RejectionCause> {
    let tracks: Vec<LinearTrack> = problem
        .targets
        .iter()
        .map(vorrt_jfs::TargetState::track)
        .collect();
    let velocities: Vec<StateVelocities> = tracks.iter().map(StateVelocities::of).collect();
    let checker = SafetyChecker::new(
        config,
        &tracks,
        problem.ownship_at_service_speed(),
        problem.goal_m,
        problem.start_time_s,
    )
    .with_steady_course(problem.steady_course_rad)
    .with_turning_at_start(problem.turning_at_start)
    .with_state_velocities(&velocities)
    .with_constraint(constraint);
    let targets = tracks.len();
    let mut state = EncounterState::new(
        (0..targets)
            .map(|index| problem.encounters.get(index).copied().flatten())
            .collect(),
        (0..targets)
            .map(|index| problem.alterations.get(index).copied().unwrap_or(0.0))
            .collect(),
    );
    let mut elapsed_s = 0.0;
    for leg in legs {
        checker.validate(leg, elapsed_s, &mut state)?;
        elapsed_s += leg.duration_s();
    }
    Ok(())
}

#[cfg(test)]
mod tests;
