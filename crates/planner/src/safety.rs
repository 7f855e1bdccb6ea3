//! The checks a move must pass to join the tree (paper, Algorithm 3, with
//! errata 2, 3 and 6 applied).
//!
//! For a move from a parent node along a new velocity, in this order:
//! 1. **velocity obstacle** — for every target within MTD, the new velocity
//!    must lie outside `VO_B^A(V_B)` with disc radii equal to the lengths
//!    (erratum 7);
//! 2. **clearance** — every target stays at least `d_th` away during the
//!    segment (CPA restricted to the segment's time, erratum 6), with the
//!    target's predicted motion (it may stop at its goal mid-segment);
//! 3. **clearance ahead** — for every target within MTD, `d_th` also holds
//!    if ownship kept the new velocity after the segment, for up to
//!    `lookahead_s` or until it would reach its goal;
//! 4. **COLREGs** — for every encounter in force, `vorrt_colregs::check_maneuver`,
//!    and for a give-way vessel `vorrt_colregs::check_alteration`: until the
//!    branch has altered course by a readily apparent amount (30°), any
//!    alteration must be at least that large (rules 8(b), 16).
//!
//! A stand-on vessel whose give-way vessel is still beyond the stand-on action
//! range keeps its course (rule 17(a)(i)), so for that target checks 1 and 3
//! are waived: the give-way vessel is expected to act. Check 2 always holds.
//! When ownship must give way to any target, it is acting, and so it also
//! keeps clear of the vessels it would otherwise stand on for (checks 1 and 3
//! apply to them; rule 17(c) still forbids a port turn for a port-side vessel).

use crate::config::{Compliance, PlannerConfig};
use crate::constraint::{Constraint, NoConstraint};
use crate::plan::RejectionCause;
use crate::validity::{LegMemo, TurnGeometry};
use glam::DVec2;
use vorrt_colregs::rules::{
    acting_for_any, course_change_rad, is_port_turn, is_port_turn_toward_vessel_moving, may_act,
};
use vorrt_colregs::{
    CandidateMotion, EncounterLatch, ManeuverViolation, Role, VesselState, check_action,
    check_alteration, check_heading, check_motion,
};
use vorrt_geometry::VelocityObstacle;
use vorrt_jfs::LinearTrack;

mod distance;
mod reach;
mod velocities;
use distance::beyond_reach;
pub use distance::min_distance_over;
pub use velocities::StateVelocities;
pub(crate) use velocities::known_velocity;

/// One candidate move out of a parent node.
#[derive(Debug, Clone, Copy)]
pub struct Move {
    /// Ownship's position at the parent, metres.
    pub start_m: DVec2,
    /// Seconds from the plan's start to the parent's time.
    pub start_elapsed_s: f64,
    /// Course of the move, radians.
    pub course_rad: f64,
    /// Ownship's velocity along the move, m/s.
    pub velocity_mps: DVec2,
    /// Duration of the move, seconds.
    pub duration_s: f64,
}

/// Checks moves against the targets of one problem, and against a user
/// [`Constraint`] (none by default: [`NoConstraint`]).
#[derive(Debug)]
pub struct SafetyChecker<'a, C = NoConstraint> {
    config: &'a PlannerConfig,
    tracks: &'a [LinearTrack],
    ownship: VesselState,
    goal_m: DVec2,
    start_time_s: f64,
    steady_course_rad: f64,
    /// Whether ownship is turning at the plan's start (decision 57).
    pub(crate) turning_at_start: bool,
    constraint: &'a C,
    /// Per target, whether it may come within reach of the leg being
    /// judged ([`SafetyChecker::within_reach`]); `None`: every target.
    in_reach: Option<&'a [bool]>,
    /// Whether a leg's check keeps its memo (decision 54; `validity`).
    pub(crate) leg_memo: bool,
    /// Per target, the velocities of its track's states, worked out once
    /// ([`with_state_velocities`](Self::with_state_velocities)); empty:
    /// each leg works them out.
    pub(crate) state_velocities: &'a [StateVelocities],
}

impl<'a> SafetyChecker<'a> {
    /// A checker for one problem: `tracks`, each target's predicted motion
    /// from the plan's start; `ownship` at the plan's start at its service
    /// speed (its length holds along the plan; each move carries its own
    /// velocity); the goal; the clock at the plan's start, seconds (time
    /// stamps of new latches). Ownship's steady course is its present one
    /// until [`with_steady_course`](Self::with_steady_course) says otherwise.
    #[must_use]
    pub fn new(
        config: &'a PlannerConfig,
        tracks: &'a [LinearTrack],
        ownship: VesselState,
        goal_m: DVec2,
        start_time_s: f64,
    ) -> Self {
        Self {
            config,
            tracks,
            ownship,
            goal_m,
            start_time_s,
            steady_course_rad: ownship.course_rad,
            turning_at_start: false,
            constraint: &NoConstraint,
            in_reach: None,
            leg_memo: true,
            state_velocities: &[],
        }
    }
}

impl<'a, C: Constraint> SafetyChecker<'a, C> {
    /// The same checker, also keeping `constraint` on every piece of motion.
    #[must_use]
    pub fn with_constraint<D: Constraint>(self, constraint: &'a D) -> SafetyChecker<'a, D> {
        SafetyChecker {
            config: self.config,
            tracks: self.tracks,
            ownship: self.ownship,
            goal_m: self.goal_m,
            start_time_s: self.start_time_s,
            steady_course_rad: self.steady_course_rad,
            turning_at_start: self.turning_at_start,
            constraint,
            in_reach: self.in_reach,
            leg_memo: self.leg_memo,
            state_velocities: self.state_velocities,
        }
    }

    /// The same checker, taking each target's velocity from `velocities`
    /// (one per track, [`StateVelocities::of`]) where it applies: the same
    /// velocities, bit for bit, worked out once for every leg judged.
    #[must_use]
    pub fn with_state_velocities(mut self, velocities: &'a [StateVelocities]) -> Self {
        self.state_velocities = velocities;
        self
    }

    /// Target `index`'s velocity in state `target`: from the velocities
    /// worked out once where they apply, else from `memo` (or worked out).
    pub(crate) fn target_velocity(
        &self,
        index: usize,
        target: &VesselState,
        memo: &mut LegMemo,
    ) -> DVec2 {
        known_velocity(self.state_velocities, index, target)
            .unwrap_or_else(|| memo.target_velocity(index, target))
    }

    /// The same checker, judging only the targets `in_reach` marks (from
    /// [`within_reach`](Self::within_reach), for the leg it judges).
    #[must_use]
    pub fn only_within<'b>(&self, in_reach: &'b [bool]) -> SafetyChecker<'b, C>
    where
        'a: 'b,
    {
        SafetyChecker {
            config: self.config,
            tracks: self.tracks,
            ownship: self.ownship,
            goal_m: self.goal_m,
            start_time_s: self.start_time_s,
            steady_course_rad: self.steady_course_rad,
            turning_at_start: self.turning_at_start,
            constraint: self.constraint,
            in_reach: Some(in_reach),
            leg_memo: self.leg_memo,
            state_velocities: self.state_velocities,
        }
    }

    /// Whether target `index` may matter to what is judged (every target
    /// unless [`only_within`](Self::only_within) said otherwise).
    #[must_use]
    pub fn may_reach(&self, index: usize) -> bool {
        self.in_reach
            .is_none_or(|in_reach| in_reach.get(index).copied().unwrap_or(true))
    }

    /// The planner's settings.
    #[must_use]
    pub fn config(&self) -> &'a PlannerConfig {
        self.config
    }

    /// The goal, metres.
    pub(crate) fn goal_m(&self) -> DVec2 {
        self.goal_m
    }

    /// Each target's predicted motion from the plan's start.
    #[must_use]
    pub fn tracks(&self) -> &'a [LinearTrack] {
        self.tracks
    }

    /// Ownship at the plan's start, at its service speed.
    #[must_use]
    pub fn ownship(&self) -> &VesselState {
        &self.ownship
    }

    /// The clock at the plan's start, seconds.
    #[must_use]
    pub fn start_time_s(&self) -> f64 {
        self.start_time_s
    }

    /// The course ownship held steadily before the turn it is in at the
    /// plan's start (`PlanningProblem::steady_course_rad`), radians; its
    /// present course when it is not turning.
    #[must_use]
    pub fn steady_course_rad(&self) -> f64 {
        self.steady_course_rad
    }

    /// The user constraint kept.
    #[must_use]
    pub fn constraint(&self) -> &'a C {
        self.constraint
    }

    /// The checker with [`PlanningProblem::turning_at_start`](crate::PlanningProblem::turning_at_start).
    #[must_use]
    pub fn with_turning_at_start(mut self, turning: bool) -> Self {
        self.turning_at_start = turning;
        self
    }

    /// The checker with `steady_course_rad` (if given) as the course ownship
    /// held before the turn it is in at the plan's start.
    #[must_use]
    pub fn with_steady_course(mut self, steady_course_rad: Option<f64>) -> Self {
        if let Some(course) = steady_course_rad {
            self.steady_course_rad = course;
        }
        self
    }

    /// The distance between reference points that keeps `d_th` between the
    /// hulls of ownship and the target on `track`: `d_th` plus their contact
    /// range (half the sum of the lengths, `vorrt_colregs::rules`), so that
    /// "`d_th` kept" can never be hull contact.
    #[must_use]
    pub fn required_distance_m(&self, track: &LinearTrack) -> f64 {
        self.config.clearance_m
            + vorrt_colregs::rules::contact_range_m(self.ownship.length_m, track.vessel.length_m)
    }

    /// Checks only that every target keeps `d_th` plus `margin_m` from the
    /// move: the check of a chord of a turn, whose course is transient.
    ///
    /// # Errors
    /// [`RejectionCause::Clearance`] when a target comes nearer.
    pub fn check_clearance(&self, candidate: &Move, margin_m: f64) -> Result<(), RejectionCause> {
        for (index, track) in self.tracks.iter().enumerate() {
            if !self.may_reach(index) {
                continue;
            }
            let clearance = self.required_distance_m(track) + margin_m;
            let range_m = candidate
                .start_m
                .distance(track.position_at(candidate.start_elapsed_s));
            if beyond_reach(
                range_m,
                candidate.velocity_mps.length(),
                track,
                candidate.duration_s,
                clearance,
            ) {
                continue;
            }
            let during = min_distance_over(
                candidate.start_m,
                candidate.velocity_mps,
                track,
                candidate.start_elapsed_s,
                candidate.duration_s,
            );
            if during < clearance {
                return Err(RejectionCause::Clearance);
            }
        }
        Ok(())
    }

    /// Checks a chord of a turn: every target keeps `d_th` plus `margin_m`
    /// ([`check_clearance`](Self::check_clearance)), and the heading swept
    /// through breaks no rule an observer would see broken on the way
    /// ([`vorrt_colregs::check_heading`] for every encounter in force at
    /// the turn's start): a stand-on vessel that may not yet act keeps its course
    /// through the turn too (rule 17(a)(i)), and a turn to port for a vessel
    /// on the port side is one whichever course it settles on (rules 14,
    /// 15, 17(c)). The rules that judge the alteration made (its size, when
    /// it began, that it is held) judge the settled course, as an observer
    /// does (rule 8(b)), so they are not applied here.
    ///
    /// # Errors
    /// The first [`RejectionCause`] the chord runs into.
    pub fn check_turning(
        &self,
        candidate: &Move,
        latches: &[Option<EncounterLatch>],
        alterations: &[f64],
        margin_m: f64,
    ) -> Result<(), RejectionCause> {
        self.check_clearance(candidate, margin_m)?;
        if self.config.compliance == Compliance::SafetyOnly {
            return Ok(());
        }
        let giving_way = self.acting_for_any(candidate, latches);
        let motion = Self::candidate_motion(candidate);
        for (index, track) in self.tracks.iter().enumerate() {
            let Some(latch) = latches.get(index).copied().flatten() else {
                continue;
            };
            let target_position = track.position_at(candidate.start_elapsed_s);
            let range = candidate.start_m.distance(target_position);
            check_heading(
                &latch,
                &motion,
                target_position,
                &self.config.rules,
                may_act(range, giving_way, &self.config.rules),
                alterations.get(index).copied().unwrap_or(0.0),
            )
            .map_err(RejectionCause::Colregs)?;
        }
        Ok(())
    }

    /// Checks the course a turn settles on against every vessel, latched or
    /// not, as an observer judges the turn (rules 2(a), 8(a), 17(c)): a turn
    /// to port from `course_before_rad` (the course held before the turn)
    /// toward a vessel on the port side forward of the beam that makes it a
    /// risk of collision (whichever would cross ahead), where on the course
    /// before it was none ([`is_port_turn_toward_vessel`](vorrt_colregs::rules::is_port_turn_toward_vessel)), creates a new
    /// danger, such as a return toward the goal onto a vessel crossing from
    /// port (issue 24; decisions 28 and 51). `candidate` is a piece on the
    /// settled course or a chord of the turn; the manoeuvre search then holds the alteration
    /// longer, or passes astern of the vessel beyond the risk distance.
    ///
    /// # Errors
    /// [`ManeuverViolation::PortTurnTowardVessel`].
    pub fn check_settled_turn(
        &self,
        course_before_rad: f64,
        candidate: &Move,
    ) -> Result<(), RejectionCause> {
        self.check_settled_turn_reusing(course_before_rad, candidate, &mut LegMemo::default())
    }

    /// Whether some target that may matter is within MTD of `candidate`'s
    /// start: the first test of a port turn toward a vessel
    /// ([`check_settled_turn_reusing`](Self::check_settled_turn_reusing)).
    /// Without one no port turn there is toward a vessel, from whatever
    /// course and onto whatever course, so the courses an observer sees
    /// need not be worked out (decision 57).
    pub(crate) fn any_within_mtd(&self, candidate: &Move) -> bool {
        self.tracks.iter().enumerate().any(|(index, track)| {
            self.may_reach(index) && self.within_mtd_at(track, candidate).is_some()
        })
    }

    /// Where `track`'s vessel is at `candidate`'s start, if within MTD of
    /// ownship then.
    fn within_mtd_at(&self, track: &LinearTrack, candidate: &Move) -> Option<DVec2> {
        let position_m = track.position_at(candidate.start_elapsed_s);
        vorrt_colregs::rules::within_mtd(candidate.start_m.distance(position_m), &self.config.rules)
            .then_some(position_m)
    }

    /// [`check_settled_turn`](Self::check_settled_turn) with a leg's
    /// `memo`: ownship's velocities on the course turned to and the course
    /// before, and each target's, reused from an earlier piece where worked
    /// out for the same bits (the same verdict).
    pub(crate) fn check_settled_turn_reusing(
        &self,
        course_before_rad: f64,
        candidate: &Move,
        memo: &mut LegMemo,
    ) -> Result<(), RejectionCause> {
        let rules = &self.config.rules;
        // At every level (decision 57): rules 2(b), 17(b) allow a departure
        // to avoid immediate danger, not one that makes a vessel a risk.
        let turn_rad = course_change_rad(course_before_rad, candidate.course_rad);
        if !is_port_turn(turn_rad, rules) {
            return Ok(());
        }
        let own = VesselState {
            position_m: candidate.start_m,
            course_rad: candidate.course_rad,
            speed_mps: candidate.velocity_mps.length(),
            ..self.ownship
        };
        // Ownship's velocities on the course turned to and the course
        // before, and the gate's unit vectors, worked out once a vessel is
        // within MTD, and kept for the same turn (decisions 46, 54).
        let mut turn = None;
        for (index, track) in self.tracks.iter().enumerate() {
            if !self.may_reach(index) {
                continue;
            }
            // Beyond MTD no vessel is one turned toward (the rule's first
            // test, on the same distance), nor abaft the beam or to
            // starboard of the course before (its bearing tests, by the
            // gate's dot products: decision 46); for those its full state,
            // dearer than its position, is not needed.
            let Some(position_m) = self.within_mtd_at(track, candidate) else {
                continue;
            };
            let TurnGeometry {
                own_mps,
                before_mps,
                gate,
            } = *turn.get_or_insert_with(|| memo.turn_geometry(course_before_rad, &own));
            if !gate.may_turn_toward(position_m - candidate.start_m) {
                continue;
            }
            let target = track.state_at(candidate.start_elapsed_s);
            if is_port_turn_toward_vessel_moving(
                course_before_rad,
                (&own, own_mps, before_mps),
                &target,
                self.target_velocity(index, &target, memo),
                rules,
            ) {
                return Err(RejectionCause::Colregs(
                    ManeuverViolation::PortTurnTowardVessel,
                ));
            }
        }
        Ok(())
    }

    /// Whether ownship acts for some vessel at `candidate`'s start
    /// ([`acting_for_any`]: it gives way to one, or stands on for one within
    /// the action range).
    fn acting_for_any(&self, candidate: &Move, latches: &[Option<EncounterLatch>]) -> bool {
        acting_for_any(
            self.tracks
                .iter()
                .zip(latches)
                .filter_map(|(track, latch)| {
                    let range_m = candidate
                        .start_m
                        .distance(track.position_at(candidate.start_elapsed_s));
                    latch.as_ref().map(|latch| (latch, range_m))
                }),
            &self.config.rules,
        )
    }

    /// Ownship's motion along `candidate`, as the rule checks see it.
    fn candidate_motion(candidate: &Move) -> CandidateMotion {
        CandidateMotion {
            position_m: candidate.start_m,
            course_rad: candidate.course_rad,
            // The move's own speed (it may be slowing down): rule 17(a)(i)
            // judges it against the latch's reference speed.
            speed_mps: candidate.velocity_mps.length(),
            velocity_mps: candidate.velocity_mps,
        }
    }

    /// Checks one move given the encounters in force at its parent.
    ///
    /// # Errors
    /// The first [`RejectionCause`] the move runs into.
    pub fn check(
        &self,
        candidate: &Move,
        latches: &[Option<EncounterLatch>],
        alterations: &[f64],
    ) -> Result<(), RejectionCause> {
        let rules = &self.config.rules;
        let end_m = candidate.start_m + candidate.velocity_mps * candidate.duration_s;
        let end_elapsed_s = candidate.start_elapsed_s + candidate.duration_s;
        let to_goal_s = end_m.distance(self.goal_m) / self.ownship.speed_mps;
        let lookahead_s = self.config.lookahead_s.min(to_goal_s);
        let giving_way = self.acting_for_any(candidate, latches);
        let motion = Self::candidate_motion(candidate);
        for (index, track) in self.tracks.iter().enumerate() {
            if !self.may_reach(index) {
                continue;
            }
            let target_position = track.position_at(candidate.start_elapsed_s);
            let target_velocity = track.velocity_at(candidate.start_elapsed_s);
            let range = candidate.start_m.distance(target_position);
            let latch = latches.get(index).copied().flatten();
            let clearance = self.required_distance_m(track);
            if latch.is_none() && range >= rules.mtd_m {
                // Beyond MTD with no encounter, only the segment's clearance
                // applies, and it cannot fail while the two could not close
                // the range to d_th even heading straight for each other.
                let reach =
                    (self.ownship.speed_mps + target_velocity.length()) * candidate.duration_s;
                if range - reach >= clearance {
                    continue;
                }
            }
            let acting = may_act(range, giving_way, rules);
            let waived =
                latch.is_some_and(|latch| latch.encounter.role() == Role::StandOn && !acting);
            let near = range < rules.mtd_m && !waived;
            if near
                && VelocityObstacle::blocks(
                    candidate.start_m,
                    target_position,
                    target_velocity,
                    self.ownship.length_m + track.vessel.length_m,
                    candidate.velocity_mps,
                )
            {
                return Err(RejectionCause::VelocityObstacle);
            }
            // The segment's clearance, unless the range shows it wide.
            if !beyond_reach(
                range,
                candidate.velocity_mps.length(),
                track,
                candidate.duration_s,
                clearance,
            ) && min_distance_over(
                candidate.start_m,
                candidate.velocity_mps,
                track,
                candidate.start_elapsed_s,
                candidate.duration_s,
            ) < clearance
            {
                return Err(RejectionCause::Clearance);
            }
            if near && lookahead_s > 0.0 {
                let ahead = min_distance_over(
                    end_m,
                    candidate.velocity_mps,
                    track,
                    end_elapsed_s,
                    lookahead_s,
                );
                if ahead < clearance {
                    return Err(RejectionCause::ClearanceAhead);
                }
            }
            if let Some(latch) = latch
                && self.config.compliance != Compliance::SafetyOnly
            {
                let altered = alterations.get(index).copied().unwrap_or(0.0);
                check_motion(
                    &latch,
                    &motion,
                    target_position,
                    target_velocity,
                    rules,
                    acting,
                    altered,
                )
                .map_err(RejectionCause::Colregs)?;
                if self.config.compliance == Compliance::Full {
                    self.check_give_way(&latch, &motion, target_position, target_velocity, altered)
                        .map_err(RejectionCause::Colregs)?;
                }
            }
        }
        Ok(())
    }

    /// A give-way vessel's alteration is readily apparent, early and held
    /// (rules 8, 16: `check_alteration`, `check_action`); on a route that
    /// crosses a lane a reduction of speed held is an action too
    /// ([`Constraint::prefers_speed_changes`], decision 47).
    fn check_give_way(
        &self,
        latch: &EncounterLatch,
        motion: &CandidateMotion,
        target_position_m: DVec2,
        target_velocity_mps: DVec2,
        altered_rad: f64,
    ) -> Result<(), ManeuverViolation> {
        let rules = &self.config.rules;
        check_alteration(latch, altered_rad, motion.course_rad, rules)?;
        check_action(
            latch,
            motion,
            target_position_m,
            target_velocity_mps,
            rules,
            altered_rad,
            self.constraint.prefers_speed_changes(),
        )
    }
}
