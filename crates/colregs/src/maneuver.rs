//! Which ownship velocities COLREGs allow in an encounter in force.
//!
//! For a latched encounter and a candidate velocity (course and speed),
//! [`check_maneuver`] answers `Ok(())` or names the rule the candidate breaks:
//! - **head-on** (rule 14): no turn to port of the course held when the
//!   encounter began, and the target must pass port to port;
//! - **crossing, give way** (rules 15, 16): no turn to port, and never cross
//!   ahead of the stand-on vessel;
//! - **overtaking** (rule 13): either side; keeping clear is the clearance
//!   check's business, not this one's;
//! - **stand on** (rule 17): while the target is farther than
//!   [`stand_on_action_range_m`](RuleParameters::stand_on_action_range_m), keep
//!   course and speed within the stated tolerances (17(a)(i)); nearer, ownship
//!   may act (17(a)(ii), 17(b)) but not turn to port for a vessel on its own
//!   port side (17(c)).
//!
//! Turns are measured from the latch's reference course, so a return toward
//! the original course after a starboard turn is not a port turn, while any
//! course to port of it is.

use crate::encounter::Encounter;
use crate::latch::EncounterLatch;
use crate::parameters::RuleParameters;
use crate::passing::{PassingSide, crosses_ahead, passing_side};
use crate::rules;
use crate::vessel::VesselState;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

/// The rule a candidate manoeuvre would break.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ManeuverViolation {
    /// A turn to port in head-on or give-way crossing (rules 14(a), 15, 16).
    PortTurn,
    /// The target would pass starboard to starboard in head-on (rule 14(a)).
    StarboardPassing,
    /// Ownship would cross ahead of a stand-on vessel (rule 15).
    CrossingAhead,
    /// A stand-on vessel changed course before it may act (rule 17(a)(i)).
    StandOnCourseChange,
    /// A stand-on vessel changed speed before it may act (rule 17(a)(i)).
    StandOnSpeedChange,
    /// A stand-on vessel turned to port for a vessel on its own port side (rule 17(c)).
    PortTurnForPortVessel,
    /// A give-way alteration too small to be readily apparent (rules 8(b), 16).
    InsufficientAlteration,
    /// A give-way vessel still holding its course at risk of collision
    /// nearer than the give-way action range (rules 8(a), 16: early action).
    LateAction,
    /// A give-way vessel easing back from its readily apparent alteration
    /// before the other vessel is past (rule 8(d): until finally past and clear).
    AlterationNotHeld,
    /// A turn to port toward a vessel on the port side forward of the beam
    /// that makes it a risk of collision, such as a return toward the goal
    /// onto a vessel crossing from port (rule 17(c) for a stand-on vessel,
    /// good seamanship, rules 2(a) and 8(a), otherwise;
    /// [`rules::is_port_turn_toward_vessel`]).
    PortTurnTowardVessel,
}

impl ManeuverViolation {
    /// Every violation, in a fixed order.
    pub const ALL: [ManeuverViolation; 10] = [
        ManeuverViolation::PortTurn,
        ManeuverViolation::StarboardPassing,
        ManeuverViolation::CrossingAhead,
        ManeuverViolation::StandOnCourseChange,
        ManeuverViolation::StandOnSpeedChange,
        ManeuverViolation::PortTurnForPortVessel,
        ManeuverViolation::InsufficientAlteration,
        ManeuverViolation::LateAction,
        ManeuverViolation::AlterationNotHeld,
        ManeuverViolation::PortTurnTowardVessel,
    ];

    /// The rule broken, as text.
    #[must_use]
    pub fn description(self) -> &'static str {
        match self {
            ManeuverViolation::PortTurn => {
                "turn to port in head-on or give-way crossing (rules 14, 15)"
            }
            ManeuverViolation::StarboardPassing => {
                "passing starboard to starboard in head-on (rule 14)"
            }
            ManeuverViolation::CrossingAhead => "crossing ahead of the stand-on vessel (rule 15)",
            ManeuverViolation::StandOnCourseChange => {
                "stand-on vessel changed course (rule 17(a)(i))"
            }
            ManeuverViolation::StandOnSpeedChange => {
                "stand-on vessel changed speed (rule 17(a)(i))"
            }
            ManeuverViolation::PortTurnForPortVessel => {
                "stand-on vessel turned to port for a vessel on its port side (rule 17(c))"
            }
            ManeuverViolation::InsufficientAlteration => {
                "give-way alteration too small to be readily apparent (rules 8(b), 16)"
            }
            ManeuverViolation::LateAction => {
                "give-way vessel holding course at risk of collision within the action range (rules 8(a), 16)"
            }
            ManeuverViolation::AlterationNotHeld => {
                "give-way alteration eased back before the other vessel is past (rule 8(d))"
            }
            ManeuverViolation::PortTurnTowardVessel => {
                "turn to port toward a vessel on the port side forward of the beam, onto a risk of collision (rules 2(a), 8(a), 17(c))"
            }
        }
    }
}

impl std::fmt::Display for ManeuverViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.description())
    }
}

/// Whether a stand-on vessel may act on its own: the give-way vessel is
/// within [`stand_on_action_range_m`](RuleParameters::stand_on_action_range_m).
#[must_use]
pub fn stand_on_may_act(
    own_position_m: DVec2,
    target: &VesselState,
    parameters: &RuleParameters,
) -> bool {
    rules::within_action_range(own_position_m.distance(target.position_m), parameters)
}

/// Whether COLREGs allow ownship, at `own_position_m`, to take course
/// `course_rad` at `speed_mps` while `latch` is in force against `target`.
///
/// ```
/// use vorrt_colregs::{check_maneuver, EncounterLatch, Encounter, ManeuverViolation, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let target = VesselState::new(DVec2::new(0.0, 6000.0), std::f64::consts::PI, 6.0, 50.0);
/// let latch = EncounterLatch::new(Encounter::HeadOn, &own, 0.0);
/// let starboard = 30f64.to_radians();
/// assert_eq!(check_maneuver(&latch, own.position_m, starboard, 6.0, &target, &params), Ok(()));
/// assert_eq!(
///     check_maneuver(&latch, own.position_m, -starboard, 6.0, &target, &params),
///     Err(ManeuverViolation::PortTurn)
/// );
/// ```
///
/// # Errors
/// The [`ManeuverViolation`] the candidate would commit.
pub fn check_maneuver(
    latch: &EncounterLatch,
    own_position_m: DVec2,
    course_rad: f64,
    speed_mps: f64,
    target: &VesselState,
    parameters: &RuleParameters,
) -> Result<(), ManeuverViolation> {
    let may_act = stand_on_may_act(own_position_m, target, parameters);
    check_maneuver_acting(
        latch,
        own_position_m,
        course_rad,
        speed_mps,
        target,
        parameters,
        may_act,
    )
}

/// As [`check_maneuver`], with the caller deciding whether a stand-on vessel
/// may act (`stand_on_acting`): with several targets, a vessel that must give
/// way to one of them cannot also keep course for another (rule 17 yields to
/// the duty to keep out of the way), though it still may not turn to port for
/// a vessel on its port side (rule 17(c)).
///
/// # Errors
/// The [`ManeuverViolation`] the candidate would commit.
pub fn check_maneuver_acting(
    latch: &EncounterLatch,
    own_position_m: DVec2,
    course_rad: f64,
    speed_mps: f64,
    target: &VesselState,
    parameters: &RuleParameters,
    stand_on_acting: bool,
) -> Result<(), ManeuverViolation> {
    check_motion(
        latch,
        &CandidateMotion::new(own_position_m, course_rad, speed_mps),
        target.position_m,
        target.velocity_mps(),
        parameters,
        stand_on_acting,
        0.0,
    )
}

/// A candidate motion of ownship: where it starts, its course and speed, and
/// the velocity they make (computed once, for callers that test many targets).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CandidateMotion {
    /// Where the motion starts, metres.
    pub position_m: DVec2,
    /// Course, radians.
    pub course_rad: f64,
    /// Speed, m/s.
    pub speed_mps: f64,
    /// `speed · (sin c, cos c)`, m/s.
    pub velocity_mps: DVec2,
}

impl CandidateMotion {
    /// The motion on `course_rad` at `speed_mps` from `position_m`.
    #[must_use]
    pub fn new(position_m: DVec2, course_rad: f64, speed_mps: f64) -> Self {
        Self {
            position_m,
            course_rad,
            speed_mps,
            velocity_mps: angle::velocity(course_rad, speed_mps),
        }
    }
}

/// [`check_maneuver_acting`] for a precomputed [`CandidateMotion`] and a
/// target given by its position and velocity, without a trigonometric call
/// per target, and knowing the history of the encounter: `altered_rad` is the
/// largest alteration from the reference course already made while it has
/// been in force (0 for none: then the verdicts are `check_maneuver_acting`'s).
///
/// In head-on and give-way crossing the action is a turn to starboard (rules
/// 14, 15, 16): the first alteration must be to starboard, and so must the
/// largest. Once a readily apparent starboard alteration has been made
/// (`altered_rad` at least [`apparent_turn_rad`](RuleParameters::apparent_turn_rad)),
/// ownship may ease back and beyond its original course by less than that
/// alteration, as evaluators judge it (notes, "Compliance scoring"); crossing
/// ahead and passing starboard to starboard stay forbidden. Without this a
/// vessel crossing a stream of traffic could never come back toward its route
/// while any vessel of the stream was in force.
///
/// # Errors
/// The [`ManeuverViolation`] the candidate would commit.
pub fn check_motion(
    latch: &EncounterLatch,
    own: &CandidateMotion,
    target_position_m: DVec2,
    target_velocity_mps: DVec2,
    parameters: &RuleParameters,
    stand_on_acting: bool,
    altered_rad: f64,
) -> Result<(), ManeuverViolation> {
    check_heading(
        latch,
        own,
        target_position_m,
        parameters,
        stand_on_acting,
        altered_rad,
    )?;
    let own_position_m = own.position_m;
    let own_velocity = own.velocity_mps;
    let target_velocity = target_velocity_mps;
    match latch.encounter {
        Encounter::HeadOn => {
            let closing =
                (target_position_m - own_position_m).dot(own_velocity - target_velocity) > 0.0;
            if closing
                && passing_side(
                    own_position_m,
                    own_velocity,
                    target_position_m,
                    target_velocity,
                ) == PassingSide::Starboard
            {
                return Err(ManeuverViolation::StarboardPassing);
            }
            Ok(())
        }
        Encounter::CrossingGiveWay => {
            if crosses_ahead(
                own_position_m,
                own_velocity,
                target_position_m,
                target_velocity,
            ) {
                return Err(ManeuverViolation::CrossingAhead);
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// The part of [`check_motion`] that the heading alone decides, which an
/// observer sees broken even while ownship is turning through it: no turn to
/// port of the reference course in head-on and give-way crossing (unless
/// easing back, see [`check_motion`]; rules 14, 15), a stand-on vessel that
/// may not act keeps its course and speed (17(a)(i)), and one that acts does
/// not turn to port for a vessel on its port side (17(c)). The predicted
/// passes (starboard to starboard, crossing ahead) are judged on a settled
/// course only.
///
/// ```
/// use vorrt_colregs::{check_heading, CandidateMotion, EncounterLatch, Encounter, ManeuverViolation, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let latch = EncounterLatch::new(Encounter::CrossingStandOn, &own, 0.0);
/// let turning = CandidateMotion::new(DVec2::ZERO, 20f64.to_radians(), 6.0);
/// let target = DVec2::new(5000.0, 5000.0);
/// // Far off, the stand-on vessel may not swing 20° off its course ...
/// assert_eq!(check_heading(&latch, &turning, target, &params, false, 0.0),
///            Err(ManeuverViolation::StandOnCourseChange));
/// // ... but may once it may act.
/// assert_eq!(check_heading(&latch, &turning, target, &params, true, 0.0), Ok(()));
/// ```
///
/// # Errors
/// The [`ManeuverViolation`] the heading commits.
pub fn check_heading(
    latch: &EncounterLatch,
    own: &CandidateMotion,
    target_position_m: DVec2,
    parameters: &RuleParameters,
    stand_on_acting: bool,
    altered_rad: f64,
) -> Result<(), ManeuverViolation> {
    let turn = rules::course_change_rad(latch.reference_course_rad, own.course_rad);
    let turned_to_port = rules::is_port_turn(turn, parameters);
    let eased_back = rules::is_readily_apparent(altered_rad, parameters) && -turn < altered_rad;
    match latch.encounter {
        Encounter::HeadOn | Encounter::CrossingGiveWay => {
            if turned_to_port && !eased_back {
                return Err(ManeuverViolation::PortTurn);
            }
            Ok(())
        }
        Encounter::CrossingStandOn | Encounter::BeingOvertaken => {
            if !rules::must_stand_on(latch.encounter, stand_on_acting) {
                // The port side as seen on the course held (the reference),
                // not on the candidate (rules::is_on_port_side).
                if latch.encounter == Encounter::CrossingStandOn
                    && turned_to_port
                    && rules::is_on_port_side(
                        own.position_m,
                        latch.reference_course_rad,
                        target_position_m,
                    )
                {
                    return Err(ManeuverViolation::PortTurnForPortVessel);
                }
                return Ok(());
            }
            // The course to keep: the reference, or the one last taken
            // while giving way to another vessel (`altered_rad` carries it
            // for a stand-on encounter, rules::alteration_made).
            let kept = rules::course_change_rad(
                rules::stand_on_course_rad(latch, altered_rad),
                own.course_rad,
            );
            if rules::is_stand_on_course_change(kept, parameters) {
                return Err(ManeuverViolation::StandOnCourseChange);
            }
            if rules::is_speed_change(own.speed_mps - latch.reference_speed_mps, parameters) {
                return Err(ManeuverViolation::StandOnSpeedChange);
            }
            Ok(())
        }
        Encounter::Overtaking | Encounter::None => Ok(()),
    }
}

/// Rules 8(b) and 16: a give-way vessel's alteration of course must be large
/// enough to be readily apparent to the other vessel
/// ([`apparent_turn_rad`](RuleParameters::apparent_turn_rad), 30° by default);
/// a succession of small alterations is to be avoided.
///
/// `altered_rad` is the largest alteration from the latch's reference course
/// already made while the encounter has been in force. Until it reaches the
/// apparent size, a candidate course that alters at all (by more than
/// [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad)) must alter by
/// at least that much. Stand-on encounters are not concerned.
///
/// ```
/// use vorrt_colregs::{check_alteration, EncounterLatch, Encounter, ManeuverViolation, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let latch = EncounterLatch::new(Encounter::HeadOn, &own, 0.0);
/// assert_eq!(check_alteration(&latch, 0.0, 0.0, &params), Ok(()));                  // holding course
/// assert_eq!(check_alteration(&latch, 0.0, 35f64.to_radians(), &params), Ok(()));    // substantial
/// assert_eq!(
///     check_alteration(&latch, 0.0, 10f64.to_radians(), &params),
///     Err(ManeuverViolation::InsufficientAlteration)
/// );
/// // Once 35° has been made, easing back to 10° is allowed.
/// assert_eq!(check_alteration(&latch, 35f64.to_radians(), 10f64.to_radians(), &params), Ok(()));
/// ```
///
/// # Errors
/// [`ManeuverViolation::InsufficientAlteration`].
pub fn check_alteration(
    latch: &EncounterLatch,
    altered_rad: f64,
    course_rad: f64,
    parameters: &RuleParameters,
) -> Result<(), ManeuverViolation> {
    if !rules::gives_way(latch.encounter) || rules::is_readily_apparent(altered_rad, parameters) {
        return Ok(());
    }
    let turn = rules::course_change_rad(latch.reference_course_rad, course_rad);
    if rules::is_detectable_turn(turn, parameters) && !rules::is_readily_apparent(turn, parameters)
    {
        return Err(ManeuverViolation::InsufficientAlteration);
    }
    Ok(())
}

/// Rules 8(a), 8(d) and 16 for a give-way vessel (head-on, crossing or
/// overtaking): the action is early, and held until the other vessel is past.
///
/// - **Early** (`LateAction`): until a readily apparent alteration has been
///   made (`altered_rad` under [`apparent_turn_rad`](RuleParameters::apparent_turn_rad)),
///   a candidate that still holds the reference course (within
///   [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad)) while its
///   closest approach is under the encounter's risk-of-collision distance
///   ([`EncounterLatch::risk_distance_or`], decision 50: 1 nm in open sea)
///   must be farther than [`give_way_action_range_m`](RuleParameters::give_way_action_range_m).
///   With `reduction_acts`, a candidate at a readily apparent reduction of
///   the reference speed ([`rules::is_readily_apparent_reduction`]) is not
///   holding: the reduction is the action (rules 8(b), 8(e); a lane
///   crossing holding short of the stream, decision 47). Elsewhere a
///   reduction shows too slowly over ground to count (a ship sheds half its
///   speed over minutes, decision 19), and only a turn does.
/// - **Held** (`AlterationNotHeld`): once it has been made, while the range
///   is still closing, the candidate's course stays at least the apparent
///   alteration to starboard of the reference, in head-on and crossing (an
///   overtaking vessel may come back to a parallel course once it has opened
///   its passing distance: rule 13 asks it to keep out of the way, which the
///   clearance checks judge).
///
/// ```
/// use vorrt_colregs::{check_action, CandidateMotion, EncounterLatch, Encounter, ManeuverViolation, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let latch = EncounterLatch::new(Encounter::HeadOn, &own, 0.0);
/// let (target, target_velocity) = (DVec2::new(0.0, 3000.0), DVec2::new(0.0, -6.0));
/// let hold = CandidateMotion::new(DVec2::ZERO, 0.0, 6.0);
/// // Holding course 3000 m (1.6 nm) from a head-on vessel: late.
/// assert_eq!(check_action(&latch, &hold, target, target_velocity, &params, 0.0, false),
///            Err(ManeuverViolation::LateAction));
/// // Slowed to 45 % on a lane crossing: the reduction is the action.
/// let slowed = CandidateMotion::new(DVec2::ZERO, 0.0, 2.7);
/// assert_eq!(check_action(&latch, &slowed, target, target_velocity, &params, 0.0, true), Ok(()));
/// assert_eq!(check_action(&latch, &slowed, target, target_velocity, &params, 0.0, false),
///            Err(ManeuverViolation::LateAction));
/// // After a 35° alteration, easing back to 10° before passing: not held.
/// let eased = CandidateMotion::new(DVec2::ZERO, 10f64.to_radians(), 6.0);
/// assert_eq!(check_action(&latch, &eased, target, target_velocity, &params, 35f64.to_radians(), false),
///            Err(ManeuverViolation::AlterationNotHeld));
/// ```
///
/// # Errors
/// [`ManeuverViolation::LateAction`] or [`ManeuverViolation::AlterationNotHeld`].
pub fn check_action(
    latch: &EncounterLatch,
    own: &CandidateMotion,
    target_position_m: DVec2,
    target_velocity_mps: DVec2,
    parameters: &RuleParameters,
    altered_rad: f64,
    reduction_acts: bool,
) -> Result<(), ManeuverViolation> {
    let keeps_clear = matches!(
        latch.encounter,
        Encounter::HeadOn | Encounter::CrossingGiveWay
    );
    if !keeps_clear && latch.encounter != Encounter::Overtaking {
        return Ok(());
    }
    let offset = target_position_m - own.position_m;
    let relative_velocity = own.velocity_mps - target_velocity_mps;
    let closing = offset.dot(relative_velocity) > 0.0;
    let turn = angle::signed_turn(latch.reference_course_rad, own.course_rad);
    if altered_rad < parameters.apparent_turn_rad {
        // Where a reduction of speed counts, one readily apparent and held
        // is the action too (rules 8(b), 8(e), 16): a vessel holding short
        // of a lane's stream slows on its course rather than turning
        // (decision 47).
        let holding = turn.abs() <= parameters.turn_tolerance_rad
            && !(reduction_acts
                && rules::is_readily_apparent_reduction(own.speed_mps, latch.reference_speed_mps));
        if holding && closing && offset.length() < parameters.give_way_action_range_m {
            let cpa = vorrt_geometry::cpa::cpa_clamped(
                own.position_m - target_position_m,
                relative_velocity,
                f64::INFINITY,
            );
            if rules::is_close_approach(&cpa, latch.risk_distance_or(parameters)) {
                return Err(ManeuverViolation::LateAction);
            }
        }
        return Ok(());
    }
    // An overtaking vessel may come back to a parallel course once it has
    // opened its passing distance (rule 13 asks it to keep out of the way,
    // which the clearance checks judge); head-on and crossing hold on.
    if keeps_clear && closing && rules::is_alteration_eased_back(turn, parameters) {
        return Err(ManeuverViolation::AlterationNotHeld);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn state(x: f64, y: f64, course_deg: f64) -> VesselState {
        VesselState::new(DVec2::new(x, y), course_deg.to_radians(), 6.0, 50.0)
    }

    #[test]
    fn give_way_crossing_may_turn_starboard_but_not_cross_ahead() {
        let params = RuleParameters::default();
        let own = state(0.0, 0.0, 0.0);
        let target = state(3000.0, 3000.0, 270.0);
        let latch = EncounterLatch::new(Encounter::CrossingGiveWay, &own, 0.0);
        assert_eq!(
            check_maneuver(
                &latch,
                own.position_m,
                60f64.to_radians(),
                6.0,
                &target,
                &params
            ),
            Ok(())
        );
        assert_eq!(
            check_maneuver(&latch, own.position_m, 0.0, 6.0, &target, &params),
            Err(ManeuverViolation::CrossingAhead)
        );
        assert_eq!(
            check_maneuver(&latch, own.position_m, -0.5, 6.0, &target, &params),
            Err(ManeuverViolation::PortTurn)
        );
    }

    #[test]
    fn stand_on_keeps_course_until_action_range() {
        let params = RuleParameters::default();
        let own = state(0.0, 0.0, 0.0);
        let far = state(-5000.0, 5000.0, 90.0);
        let latch = EncounterLatch::new(Encounter::CrossingStandOn, &own, 0.0);
        assert_eq!(
            check_maneuver(
                &latch,
                own.position_m,
                40f64.to_radians(),
                6.0,
                &far,
                &params
            ),
            Err(ManeuverViolation::StandOnCourseChange)
        );
        assert_eq!(
            check_maneuver(&latch, own.position_m, 0.0, 3.0, &far, &params),
            Err(ManeuverViolation::StandOnSpeedChange)
        );
        let near = state(-1000.0, 1000.0, 90.0);
        assert_eq!(
            check_maneuver(
                &latch,
                own.position_m,
                40f64.to_radians(),
                6.0,
                &near,
                &params
            ),
            Ok(())
        );
        assert_eq!(
            check_maneuver(
                &latch,
                own.position_m,
                -40f64.to_radians(),
                6.0,
                &near,
                &params
            ),
            Err(ManeuverViolation::PortTurnForPortVessel)
        );
    }

    #[test]
    fn overtaking_may_pass_either_side() {
        let params = RuleParameters::default();
        let own = state(0.0, 0.0, 0.0);
        let ahead = VesselState::new(DVec2::new(0.0, 2000.0), 0.0, 3.0, 50.0);
        let latch = EncounterLatch::new(Encounter::Overtaking, &own, 0.0);
        for course in [-0.5, 0.5] {
            assert_eq!(
                check_maneuver(&latch, own.position_m, course, 6.0, &ahead, &params),
                Ok(())
            );
        }
        let _ = PI;
    }
}
