//! Latching an encounter once risk arises, and releasing it when the vessels
//! have passed (notes, "COLREGs geometry": latch so that the classification
//! does not flip at sector boundaries).

// The latch's state lives with the encounter types, so the rule book can
// judge it without depending on this module.
pub use crate::encounter::EncounterLatch;
use crate::encounter::{Encounter, Role, classify};
use crate::parameters::RuleParameters;
use crate::risk::{assess_risk, assess_risk_moving};
use crate::rules::{course_change_rad, within_mtd};
use crate::vessel::VesselState;

/// Whether ownship and the target have passed each other: the range is
/// opening and the velocities point more than
/// [`passed_angle_rad`](RuleParameters::passed_angle_rad) away from the line of
/// sight — both of them in head-on and crossing, either of them in the
/// overtaking encounters (the overtaken vessel keeps pointing at the other).
/// A range that opens while already wider than the risk-of-collision
/// distance also ends it: the CPA is now and it is no risk (vessels running
/// side by side would otherwise stay latched for ever). Ownship's length is
/// not known here, so the distance is that for the target's length alone
/// ([`RuleParameters::risk_distance_m`]`(0, target length)`, decision 50),
/// never more than the pair's: 1 nm in open sea up to 289 m.
#[must_use]
pub fn has_passed(
    own: &VesselState,
    target: &VesselState,
    encounter: Encounter,
    parameters: &RuleParameters,
) -> bool {
    has_passed_moving(
        own.position_m,
        (own.velocity_mps(), target.velocity_mps()),
        target,
        encounter,
        parameters,
    )
}

/// As [`has_passed`], for ownship at `own_m`, with the two velocities
/// already worked out (`velocities_mps`: ownship's and the target's
/// [`VesselState::velocity_mps`]): a caller judging many targets against one
/// state of ownship, or one target along many, works them out once.
#[inline]
#[must_use]
pub fn has_passed_moving(
    own_m: glam::DVec2,
    velocities_mps: (glam::DVec2, glam::DVec2),
    target: &VesselState,
    encounter: Encounter,
    parameters: &RuleParameters,
) -> bool {
    let line_of_sight = target.position_m - own_m;
    let (own_velocity, target_velocity) = velocities_mps;
    let relative_velocity = own_velocity - target_velocity;
    let opening = line_of_sight.dot(relative_velocity) <= 0.0;
    if !opening {
        return false;
    }
    if line_of_sight.length() > parameters.risk_distance_m(0.0, target.length_m) {
        return true;
    }
    let points_away = |velocity: glam::DVec2, towards: glam::DVec2| {
        velocity == glam::DVec2::ZERO
            || velocity.angle_to(towards).abs() > parameters.passed_angle_rad
    };
    let own_away = points_away(own_velocity, line_of_sight);
    let target_away = points_away(target_velocity, -line_of_sight);
    match encounter {
        Encounter::Overtaking | Encounter::BeingOvertaken => own_away || target_away,
        _ => own_away && target_away,
    }
}

/// One step of the latch: keeps a latched encounter until the vessels have
/// passed; latches a new one when risk of collision arises and a rule applies.
///
/// ```
/// use vorrt_colregs::{update_latch, Encounter, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let target = VesselState::new(DVec2::new(0.0, 6000.0), std::f64::consts::PI, 6.0, 50.0);
/// let latch = update_latch(None, &own, &target, 0.0, &params).expect("risk");
/// assert_eq!(latch.encounter, Encounter::HeadOn);
/// ```
#[must_use]
pub fn update_latch(
    current: Option<EncounterLatch>,
    own: &VesselState,
    target: &VesselState,
    time_s: f64,
    parameters: &RuleParameters,
) -> Option<EncounterLatch> {
    update_latch_steady(current, own, own.course_rad, target, time_s, parameters)
}

/// As [`update_latch`], for an ownship that may have begun a turn shortly
/// before: a new encounter is classified, and its reference course taken, on
/// `steady_course_rad`, the course ownship held steadily before any turn of
/// the last [`STEADY_COURSE_WINDOW_S`](crate::rules::STEADY_COURSE_WINDOW_S)
/// (see [`steady_course_rad`](crate::rules::steady_course_rad)). An observer
/// on the other vessel, judging course over ground over such a window, sees
/// that course until the turn shows, so an alteration begun just before risk
/// arose counts as action taken for the encounter (rules 8(b), 16), and a
/// turn cannot dodge an encounter it was made for. Whether a latched
/// encounter has passed is judged on the course steered (`own`), and for
/// an encounter in which ownship stands on, on `steady_course_rad` as well:
/// her own turn, while it shows, does not end it (decision 58).
///
/// ```
/// use vorrt_colregs::{update_latch_steady, Encounter, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// // Ownship has just turned 35° to starboard from north; a vessel comes head-on.
/// let own = VesselState::new(DVec2::ZERO, 35f64.to_radians(), 6.0, 50.0);
/// let target = VesselState::new(DVec2::new(0.0, 6000.0), std::f64::consts::PI, 6.0, 50.0);
/// let latch = update_latch_steady(None, &own, 0.0, &target, 0.0, &params).expect("risk");
/// assert_eq!(latch.encounter, Encounter::HeadOn);
/// assert_eq!(latch.reference_course_rad, 0.0);
/// ```
#[must_use]
pub fn update_latch_steady(
    current: Option<EncounterLatch>,
    own: &VesselState,
    steady_course_rad: f64,
    target: &VesselState,
    time_s: f64,
    parameters: &RuleParameters,
) -> Option<EncounterLatch> {
    latch_step(
        current,
        own,
        (
            || (own.velocity_mps(), target.velocity_mps()),
            |seen: &VesselState| (seen.velocity_mps(), target.velocity_mps()),
        ),
        steady_course_rad,
        target,
        (time_s, parameters),
    )
}

/// As [`update_latch_steady`], with the two velocities already worked out
/// (`velocities_mps`: ownship's and the target's
/// [`VesselState::velocity_mps`]): a caller stepping many targets' latches
/// against one state of ownship, or one target's along many, works them out
/// once. The same latch as [`update_latch_steady`].
#[inline]
#[must_use]
pub fn update_latch_steady_moving(
    current: Option<EncounterLatch>,
    own: &VesselState,
    velocities_mps: (glam::DVec2, glam::DVec2),
    steady_course_rad: f64,
    target: &VesselState,
    time_s: f64,
    parameters: &RuleParameters,
) -> Option<EncounterLatch> {
    latch_step(
        current,
        own,
        (
            || velocities_mps,
            |seen: &VesselState| (seen.velocity_mps(), velocities_mps.1),
        ),
        steady_course_rad,
        target,
        (time_s, parameters),
    )
}

/// As [`update_latch_steady_moving`], with ownship's velocity on its steady
/// course also worked out (`seen_mps`: [`VesselState::velocity_mps`] of
/// `own` on `steady_course_rad`, the velocity a new encounter's risk is
/// judged by): a caller stepping many targets against one state of ownship
/// works every velocity of ownship out once (decision 54). The same latch as
/// [`update_latch_steady`].
#[inline]
#[must_use]
pub fn update_latch_seen_moving(
    current: Option<EncounterLatch>,
    own: &VesselState,
    velocities_mps: (glam::DVec2, glam::DVec2),
    (steady_course_rad, seen_mps): (f64, glam::DVec2),
    target: &VesselState,
    time_s: f64,
    parameters: &RuleParameters,
) -> Option<EncounterLatch> {
    latch_step(
        current,
        own,
        (
            || velocities_mps,
            |_: &VesselState| (seen_mps, velocities_mps.1),
        ),
        steady_course_rad,
        target,
        (time_s, parameters),
    )
}

/// As [`update_latch_steady`], for a judge of a recorded track (the
/// evaluation, `vorrt judge`): a vessel beyond MTD but nearer than
/// [`early_action_range_m`](RuleParameters::early_action_range_m) is also
/// latched at a sample where a turn of ownship to starboard shows
/// (`own.course_rad` more than
/// [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad) to starboard
/// of `steady_course_rad`) if, on the course held before the turn, she would be
/// a risk of collision but for the range (closest approach ahead and under
/// the pair's risk distance) in an encounter where ownship gives way
/// (head-on, crossing from starboard, overtaking). A turn made that early
/// for such a vessel is ownship's action for her (rules 7(b), 8(a), 16),
/// as an observer classifying the situation from its start sees it; latched
/// only once within MTD, on the new course, a later turn back across her
/// bow would be judged as no encounter or a crossing (decision 73). A
/// vessel ownship would stand on for is not latched early: until risk of
/// collision exists ownship is free to act so that no stand-on situation
/// arises. The planner latches the same way once its turn is readily
/// apparent (decision 74), and holds the alteration until she is past.
///
/// ```
/// use vorrt_colregs::{update_latch_judged, update_latch_steady, Encounter, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// // 8 nm off, a vessel head-on on the course held (north); ownship turning to starboard.
/// let own = VesselState::new(DVec2::ZERO, 20f64.to_radians(), 6.0, 100.0);
/// let target = VesselState::new(DVec2::new(0.0, 8.0 * 1852.0), std::f64::consts::PI, 6.0, 100.0);
/// assert_eq!(update_latch_steady(None, &own, 0.0, &target, 0.0, &params), None);
/// let latch = update_latch_judged(None, &own, 0.0, &target, 0.0, &params).expect("early action");
/// assert_eq!(latch.encounter, Encounter::HeadOn);
/// assert_eq!(latch.reference_course_rad, 0.0);
/// // Not turning: nothing is latched beyond MTD.
/// assert_eq!(update_latch_judged(None, &own, own.course_rad, &target, 0.0, &params), None);
/// ```
#[must_use]
pub fn update_latch_judged(
    current: Option<EncounterLatch>,
    own: &VesselState,
    steady_course_rad: f64,
    target: &VesselState,
    time_s: f64,
    parameters: &RuleParameters,
) -> Option<EncounterLatch> {
    let latch = update_latch_steady(current, own, steady_course_rad, target, time_s, parameters);
    if latch.is_some() || current.is_some() {
        return latch;
    }
    let range_m = own.range_to(target);
    // Only a turn to starboard is the action of a vessel that gives way
    // (rules 14(a), 15, 16); a bend of the route to port is not taken for one.
    let turning =
        course_change_rad(steady_course_rad, own.course_rad) > parameters.turn_tolerance_rad;
    if !turning || within_mtd(range_m, parameters) || range_m >= parameters.early_action_range_m {
        return None;
    }
    let seen = VesselState {
        course_rad: steady_course_rad,
        ..*own
    };
    // The one risk judgement (rule 7), with MTD widened to the early-action
    // range: the range was checked above.
    let early = RuleParameters {
        mtd_m: parameters.early_action_range_m,
        ..*parameters
    };
    if !assess_risk(&seen, target, &early).at_risk {
        return None;
    }
    let risk_distance_m = parameters.risk_distance_m(own.length_m, target.length_m);
    match classify(&seen, target, parameters) {
        encounter if encounter.role() != Role::GiveWay => None,
        encounter if has_passed(own, target, encounter, parameters) => None,
        encounter => {
            Some(EncounterLatch::new(encounter, &seen, time_s).with_risk_distance(risk_distance_m))
        }
    }
}

/// The one step behind [`update_latch_steady`],
/// [`update_latch_steady_moving`] and [`update_latch_seen_moving`], with
/// ownship's and the target's velocities given by `velocities` (asked for
/// only where passing is judged) and, for ownship as seen on its steady
/// course (`seen`) and the target, by `risk_velocities(seen)` (asked for
/// only within MTD); `clock` is the time and the rules.
fn latch_step(
    current: Option<EncounterLatch>,
    own: &VesselState,
    (velocities, risk_velocities): (
        impl Fn() -> (glam::DVec2, glam::DVec2),
        impl Fn(&VesselState) -> (glam::DVec2, glam::DVec2),
    ),
    steady_course_rad: f64,
    target: &VesselState,
    (time_s, parameters): (f64, &RuleParameters),
) -> Option<EncounterLatch> {
    // A stand-on vessel's own turn does not end her encounter (rule 17(a)(i)
    // with 8(d): she keeps course and speed until the other vessel is finally
    // past and clear): a range that opens only because ownship's velocity
    // swings round in a turn (for another vessel, say) is no passing. Passed
    // is then judged on the course she held as well (her steady course, as
    // an observer still sees it), and the encounter ends when both say so
    // (decision 58). A give-way vessel's turn is her action and may end it.
    let stand_on_passed = |latch: &EncounterLatch| {
        latch.encounter.role() != Role::StandOn
            || steady_course_rad.to_bits() == own.course_rad.to_bits()
            || {
                let seen = VesselState {
                    course_rad: steady_course_rad,
                    ..*own
                };
                has_passed_moving(
                    own.position_m,
                    risk_velocities(&seen),
                    target,
                    latch.encounter,
                    parameters,
                )
            }
    };
    let passed = |encounter: Encounter| {
        has_passed_moving(own.position_m, velocities(), target, encounter, parameters)
    };
    match current {
        Some(latch) if passed(latch.encounter) && stand_on_passed(&latch) => None,
        Some(latch) => Some(latch),
        None => {
            // Beyond MTD there is no risk (and no need to work out the CPA).
            if !within_mtd(own.range_to(target), parameters) {
                return None;
            }
            let seen = VesselState {
                course_rad: steady_course_rad,
                ..*own
            };
            let (seen_mps, target_mps) = risk_velocities(&seen);
            if !assess_risk_moving(&seen, seen_mps, target, target_mps, parameters).at_risk {
                return None;
            }
            match classify(&seen, target, parameters) {
                Encounter::None => None,
                // Not one that has already passed on the course steered: it
                // would be released at once and latched again at the next
                // step, for ever.
                encounter if passed(encounter) => None,
                encounter => Some(
                    EncounterLatch::new(encounter, &seen, time_s).with_risk_distance(
                        parameters.risk_distance_m(own.length_m, target.length_m),
                    ),
                ),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::risk::assess_risk;
    use glam::DVec2;
    use std::f64::consts::PI;

    #[test]
    fn head_on_latch_releases_after_passing() {
        let params = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let target = VesselState::new(DVec2::new(0.0, 6000.0), PI, 6.0, 50.0);
        let latch = update_latch(None, &own, &target, 0.0, &params);
        assert!(latch.is_some());
        // 10 minutes later, offset 500 m: the two have passed.
        let own_later = VesselState::new(DVec2::new(500.0, 3600.0), 0.0, 6.0, 50.0);
        let target_later = VesselState::new(DVec2::new(0.0, 2400.0), PI, 6.0, 50.0);
        assert!(update_latch(latch, &own_later, &target_later, 600.0, &params).is_none());
    }

    /// Decision 58: open sea, 8 COLREGs-obeying targets, seed 11, run 48.
    /// Ownship stands on for a vessel crossing from port 4.3 km off on her
    /// port quarter and turns 35° to starboard for another vessel; part way
    /// round, her velocity points away and the range opens for a moment
    /// while wider than the risk distance. The vessel from port has not
    /// passed: on the course ownship held (as an observer still sees it)
    /// the range is closing. The stand-on encounter stays latched until
    /// it has passed on both; a give-way encounter ends on the turn.
    #[test]
    fn a_stand_on_vessels_own_turn_does_not_end_her_encounter() {
        let params = RuleParameters::default();
        // Turned to east (90°) from north (0°), the vessel from port 4.3 km
        // due west heading east, slower: opening on the course steered,
        // closing on the course held.
        let own = VesselState::new(DVec2::ZERO, 0.5 * PI, 6.0, 100.0);
        let target = VesselState::new(DVec2::new(-4300.0, 0.0), 0.5 * PI, 5.0, 100.0);
        assert!(has_passed(
            &own,
            &target,
            Encounter::CrossingStandOn,
            &params
        ));
        let held = VesselState {
            course_rad: 0.0,
            ..own
        };
        assert!(!has_passed(
            &held,
            &target,
            Encounter::CrossingStandOn,
            &params
        ));
        for encounter in [Encounter::CrossingStandOn, Encounter::BeingOvertaken] {
            let latch = Some(EncounterLatch::new(encounter, &held, 0.0));
            assert_eq!(
                update_latch_steady(latch, &own, 0.0, &target, 100.0, &params),
                latch,
                "{encounter:?}"
            );
            // Once the new course is the one held, the opening range ends it.
            assert_eq!(
                update_latch_steady(latch, &own, 0.5 * PI, &target, 200.0, &params),
                None,
                "{encounter:?}"
            );
        }
        let give_way = Some(EncounterLatch::new(Encounter::CrossingGiveWay, &held, 0.0));
        assert_eq!(
            update_latch_steady(give_way, &own, 0.0, &target, 100.0, &params),
            None
        );
    }

    #[test]
    fn a_steady_course_does_not_latch_an_encounter_already_passed() {
        let params = RuleParameters::default();
        // Ownship has turned from west to north; a vessel heading west lies
        // on its port quarter, the range opening. On the course held a
        // minute ago (west) the two would still be in an encounter.
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let target = VesselState::new(DVec2::new(-1000.0, -1200.0), 1.5 * PI, 5.0, 50.0);
        let seen = VesselState {
            course_rad: 1.5 * PI,
            ..own
        };
        let encounter = classify(&seen, &target, &params);
        assert!(assess_risk(&seen, &target, &params).at_risk && encounter != Encounter::None);
        assert!(has_passed(&own, &target, encounter, &params));
        assert_eq!(
            update_latch_steady(None, &own, 1.5 * PI, &target, 0.0, &params),
            None
        );
    }

    /// Decision 73: beyond MTD a turn latches only a vessel ownship would
    /// give way to on the course held, within the early-action range.
    #[test]
    fn a_judged_latch_beyond_mtd_needs_a_turn_a_give_way_duty_and_the_range() {
        let params = RuleParameters::default();
        let turned = VesselState::new(DVec2::ZERO, 30f64.to_radians(), 6.0, 100.0);
        let at = |x_m: f64, y_m: f64, course_deg: f64| {
            VesselState::new(DVec2::new(x_m, y_m), course_deg.to_radians(), 6.0, 100.0)
        };
        // From starboard, 7 km east and 7 km north heading west: give way.
        let starboard = at(7000.0, 7000.0, 270.0);
        let latch = update_latch_judged(None, &turned, 0.0, &starboard, 5.0, &params);
        assert_eq!(latch.map(|l| l.encounter), Some(Encounter::CrossingGiveWay));
        assert_eq!(latch.map(|l| l.latched_at_s), Some(5.0));
        // From port, heading east: ownship would stand on; not latched early.
        let port = at(-7000.0, 7000.0, 90.0);
        assert_eq!(
            update_latch_judged(None, &turned, 0.0, &port, 5.0, &params),
            None
        );
        // Head-on, beyond the early-action range: not latched.
        let far = at(0.0, params.early_action_range_m + 100.0, 180.0);
        assert_eq!(
            update_latch_judged(None, &turned, 0.0, &far, 5.0, &params),
            None
        );
        // A miss of 2 nm on the course held: no risk, not latched.
        let wide = at(2.0 * 1852.0, 8.0 * 1852.0, 180.0);
        assert_eq!(
            update_latch_judged(None, &turned, 0.0, &wide, 5.0, &params),
            None
        );
        // Within MTD it is the steady latch.
        let near = at(0.0, 6000.0, 180.0);
        assert_eq!(
            update_latch_judged(None, &turned, 0.0, &near, 5.0, &params),
            update_latch_steady(None, &turned, 0.0, &near, 5.0, &params)
        );
    }

    #[test]
    fn latch_holds_while_converging() {
        let params = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let target = VesselState::new(DVec2::new(3000.0, 3000.0), 1.5 * PI, 6.0, 50.0);
        let latch = update_latch(None, &own, &target, 0.0, &params).expect("risk");
        assert_eq!(latch.encounter, Encounter::CrossingGiveWay);
        // Ownship has turned hard to starboard: the geometry now looks different,
        // but the latch keeps the encounter type.
        let turned = VesselState::new(DVec2::new(200.0, 400.0), 0.5 * PI, 6.0, 50.0);
        let target_later = target.advanced(60.0);
        assert_eq!(
            update_latch(Some(latch), &turned, &target_later, 60.0, &params).map(|l| l.encounter),
            Some(Encounter::CrossingGiveWay)
        );
    }
}
