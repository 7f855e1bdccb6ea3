//! The rule book: the shared judgements every other part of the workspace
//! makes about an encounter, written once.
//!
//! The prospective checks ([`check_motion`](crate::check_motion),
//! [`check_alteration`](crate::check_alteration)), the retrospective scoring
//! ([`assess_encounter`](crate::assess_encounter)) and the planner call these
//! predicates instead of writing their own, so that they can never judge
//! differently:
//!
//! | judgement | predicate | rule |
//! |---|---|---|
//! | the target inside the minimum threshold distance (MTD) | [`within_mtd`] | 7 |
//! | a closest approach near enough to be a risk | [`is_close_approach`] | 7 |
//! | course change from the course held when the encounter began | [`course_change_rad`] | 8, 16, 17 |
//! | a detectable turn (beyond the 2° tolerance) | [`is_detectable_turn`] | 16 |
//! | a turn to port of the reference course | [`is_port_turn`] | 14(a), 15, 17(c) |
//! | a readily apparent alteration (30°) | [`is_readily_apparent`], measured: [`is_measured_readily_apparent`] | 8(b), 16 |
//! | a readily apparent alteration eased back (no longer held) | [`is_alteration_eased_back`] | 8(a), 16 |
//! | a speed change beyond the stand-on tolerance | [`is_speed_change`] | 17(a)(i) |
//! | a course change beyond the stand-on tolerance | [`is_stand_on_course_change`] | 17(a)(i) |
//! | the target on ownship's port side | [`is_on_port_side`] | 17(c) |
//! | a port turn toward a port-side vessel onto a risk of collision | [`is_port_turn_toward_vessel`] | 2(a), 8(a), 17(c) |
//! | ownship gives way in an encounter | [`gives_way`] | 16 |
//! | ownship gives way to any target | [`giving_way_to_any`] | 16, 17 |
//! | the give-way vessel inside the stand-on action range | [`within_action_range`] | 17(a)(ii) |
//! | ownship may act (manoeuvre) in a stand-on encounter | [`may_act`] | 17(a)(ii), 17(b) |
//! | ownship must keep its course and speed | [`must_stand_on`] | 17(a)(i) |
//! | hull contact (collision) | [`contact_range_m`], [`in_contact`] | - |
//!
//! ## Collision
//!
//! A collision is **hull contact**: each vessel is taken as a disc whose
//! diameter is its length, centred on its reference position, and the two
//! are in contact when their centres are closer than the sum of the radii,
//! `distance < (length_a + length_b) / 2` ([`in_contact`]). This is the only
//! definition of collision in the workspace. The velocity obstacle's disc of
//! radius `length_a + length_b` (`docs/decisions/0003-vo-disc-radius-vs-d-th.md`) is a
//! safety margin the planner keeps, not a collision test; the clearance
//! `d_th` is the distance the planner and the scoring require, also not a
//! collision test.

use crate::encounter::{Encounter, EncounterLatch, Role};
use crate::parameters::RuleParameters;
use glam::DVec2;
use std::f64::consts::PI;
use vorrt_geometry::{Cpa, angle};

pub use crate::port_turn_gate::PortTurnGate;
use crate::port_turn_gate::{forward_of_beam_moving, on_port_side_moving};
pub use contact::{contact_range_m, in_contact, keeps_clearance};

mod contact;

/// Whether a target at `range_m` is inside the minimum threshold distance
/// ([`mtd_m`](RuleParameters::mtd_m)): nearer, it can be a risk of collision
/// (rule 7) and an encounter; farther, it is not yet one.
///
/// ```
/// use vorrt_colregs::{rules::within_mtd, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(within_mtd(params.mtd_m - 1.0, &params));
/// assert!(!within_mtd(params.mtd_m, &params));
/// ```
#[inline]
#[must_use]
pub fn within_mtd(range_m: f64, parameters: &RuleParameters) -> bool {
    range_m < parameters.mtd_m
}

/// Rule 7: whether a closest approach (from
/// [`closest_point_of_approach`](vorrt_geometry::closest_point_of_approach),
/// at present velocities) is near enough to be a risk of collision: under
/// `risk_distance_m`, the pair's risk-of-collision distance
/// ([`RuleParameters::risk_distance_m`], decision 50: 1 nm in open sea for
/// vessels up to 289 m). The risk test ([`assess_risk`](crate::assess_risk))
/// and the give-way check of early action
/// ([`check_action`](crate::check_action)) both judge it with this.
///
/// ```
/// use vorrt_colregs::{rules::is_close_approach, RuleParameters};
/// use vorrt_geometry::Cpa;
/// let risk_m = RuleParameters::default().risk_distance_m(50.0, 50.0);
/// assert!(is_close_approach(&Cpa { time_s: 60.0, distance_m: 500.0 }, risk_m));
/// assert!(!is_close_approach(&Cpa { time_s: 60.0, distance_m: 1852.0 }, risk_m));
/// ```
#[inline]
#[must_use]
pub fn is_close_approach(cpa: &Cpa, risk_distance_m: f64) -> bool {
    cpa.distance_m < risk_distance_m
}

/// The signed course change from the reference course (the course held when
/// the encounter began, [`EncounterLatch::reference_course_rad`]) to
/// `course_rad`, in `(-π, π]`: positive to starboard, negative to port.
///
/// ```
/// use vorrt_colregs::rules::course_change_rad;
/// let change = course_change_rad(350f64.to_radians(), 20f64.to_radians());
/// assert!((change - 30f64.to_radians()).abs() < 1e-12);
/// ```
#[inline]
#[must_use]
pub fn course_change_rad(reference_course_rad: f64, course_rad: f64) -> f64 {
    angle::signed_turn(reference_course_rad, course_rad)
}

/// How far back an observer's view of ownship's course reaches, seconds: the
/// window over which radar and AIS show course over ground (60 s, as the
/// published evaluators observe it; `docs/evaluation.md`).
pub const STEADY_COURSE_WINDOW_S: f64 = 60.0;

/// The rate of course change above which ownship counts as turning when its
/// steady course is sought ([`steady_course_rad`]), rad/s (3° a minute): well
/// under the rates ships alter course at (0.2-0.5°/s, `docs/decisions/0013-rate-of-turn.md`)
/// and above the wander of a course held.
pub const STEADY_TURN_RATE_RAD_S: f64 = 0.05 * std::f64::consts::PI / 180.0;

/// The course ownship held steadily before any recent turn, from its course
/// history (`times_s` ascending, the last one now, one course per time): the
/// course `look_back_s` ago, or, if a turn (faster than
/// [`STEADY_TURN_RATE_RAD_S`]) was under way then, the course before that turn
/// began, looking back at most [`STEADY_TURN_SEARCH_S`] more. `None` for an
/// empty history. A new encounter is judged against this course
/// ([`update_latch_steady`](crate::update_latch_steady)).
///
/// On courses steered (the planner, the closed loop) `look_back_s` is the
/// observation window [`STEADY_COURSE_WINDOW_S`]: a turn of the last minute
/// does not yet show over ground. On courses over ground observed over that
/// window (the evaluation as observed) it is 0: the lag is in the
/// observation already, and a course over ground still changing now is a
/// turn under way.
///
/// ```
/// use vorrt_colregs::rules::{steady_course_rad, STEADY_COURSE_WINDOW_S};
/// // North until 100 s, then turning 5° per 10 s to starboard until 200 s.
/// let times: Vec<f64> = (0..=30).map(|i| 10.0 * f64::from(i)).collect();
/// let courses: Vec<f64> = times
///     .iter()
///     .map(|t| (0.5 * (t.min(200.0) - 100.0).max(0.0)).to_radians())
///     .collect();
/// let window = STEADY_COURSE_WINDOW_S;
/// // At 150 s the turn began 50 s ago: the course before it.
/// assert_eq!(steady_course_rad(&times[..16], &courses[..16], window), Some(0.0));
/// // At 200 s, 60 s ago it was already turning: the course before the turn.
/// assert_eq!(steady_course_rad(&times[..21], &courses[..21], window), Some(0.0));
/// // At 300 s the turn ended 100 s ago: the new course.
/// assert_eq!(steady_course_rad(&times, &courses, window), Some(50f64.to_radians()));
/// // Looking back 0 s at 150 s (courses over ground): still turning, so 0°.
/// assert_eq!(steady_course_rad(&times[..16], &courses[..16], 0.0), Some(0.0));
/// ```
#[must_use]
pub fn steady_course_rad(times_s: &[f64], courses_rad: &[f64], look_back_s: f64) -> Option<f64> {
    let count = times_s.len().min(courses_rad.len());
    steady_course_rad_of(
        count,
        |index| times_s[index],
        |index| courses_rad[index],
        look_back_s,
    )
}

/// [`steady_course_rad`] over a history of `count` samples given by index
/// (0 the oldest, `count - 1` now): `time_s(index)` ascending, and
/// `course_rad(index)`, asked only for the samples the search reaches, each
/// once, newest first. For a history worked out on demand (the planner's
/// courses over ground along a leg, decision 62), where most searches stop
/// a step or two back; the same verdict as on the slices.
///
/// ```
/// use vorrt_colregs::rules::{steady_course_rad, steady_course_rad_of};
/// // A turn from 0 to 0.3 rad between 10 s and 20 s, the course held since.
/// let times = [0.0, 10.0, 20.0, 30.0, 40.0];
/// let courses = [0.0, 0.0, 0.3, 0.3, 0.3];
/// let mut asked = Vec::new();
/// let before = steady_course_rad_of(5, |i| times[i], |i| { asked.push(i); courses[i] }, 0.0);
/// assert_eq!(before, steady_course_rad(&times, &courses, 0.0));
/// assert_eq!(before, Some(0.3));
/// // Steady at once: the two newest courses only.
/// assert_eq!(asked, [4, 3]);
/// // Looking back 25 s, into the turn: back to the course before it.
/// assert_eq!(steady_course_rad_of(5, |i| times[i], |i| courses[i], 25.0), Some(0.0));
/// ```
#[must_use]
pub fn steady_course_rad_of(
    count: usize,
    time_s: impl Fn(usize) -> f64,
    mut course_rad: impl FnMut(usize) -> f64,
    look_back_s: f64,
) -> Option<f64> {
    let mut index = count.checked_sub(1)?;
    let now_s = time_s(index);
    while index > 0 && time_s(index - 1) >= now_s - look_back_s {
        index -= 1;
    }
    let search_from_s = time_s(index) - STEADY_TURN_SEARCH_S;
    let mut course_now_rad = course_rad(index);
    while index > 0 && time_s(index - 1) >= search_from_s {
        let step_s = time_s(index) - time_s(index - 1);
        let course_back_rad = course_rad(index - 1);
        let turned = angle::signed_turn(course_back_rad, course_now_rad).abs();
        if turned <= STEADY_TURN_RATE_RAD_S * step_s + 1e-9 {
            break;
        }
        index -= 1;
        course_now_rad = course_back_rad;
    }
    Some(course_now_rad)
}

/// How far back [`steady_course_rad`] looks for the start of a turn under
/// way, seconds: long enough for a 90° alteration at 0.5°/s and the window
/// over which it shows.
pub const STEADY_TURN_SEARCH_S: f64 = 240.0;

/// What ownship carries for an encounter from one instant to the next, after
/// it takes `course_rad` while the latch goes from `before` to `now`
/// (`acting_for_others`: it gives way to some other vessel then), radians.
/// The planner keeps it along a branch and the closed loop along the track
/// sailed, with this one rule.
///
/// - **Give-way** (rules 8(b), 16): the largest alteration from the reference
///   made; it grows while the same latch holds, and a new latch starts from
///   the change between its reference (the steady course, see
///   [`update_latch_steady`](crate::update_latch_steady)) and `course_rad`,
///   the alteration already begun.
/// - **Stand-on** (rule 17(a)(i)): the course change from the reference that
///   ownship was last free to make, while it gave way to another vessel
///   (with several vessels rule 17 yields to the duty to keep out of the way,
///   [`may_act`]); the course it must then keep is the reference plus this
///   ([`stand_on_course_rad`]). A new latch starts from none.
///
/// With no latch in force there is nothing (0).
///
/// ```
/// use vorrt_colregs::{rules::alteration_made, Encounter, EncounterLatch, VesselState};
/// use glam::DVec2;
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let latch = Some(EncounterLatch::new(Encounter::HeadOn, &own, 0.0));
/// let altered = alteration_made(latch, latch, 0.0, 35f64.to_radians(), false);
/// assert!((altered - 35f64.to_radians()).abs() < 1e-12);
/// // Easing back keeps the largest alteration made.
/// assert_eq!(alteration_made(latch, latch, altered, 10f64.to_radians(), false), altered);
/// // A new encounter starts from the alteration already begun from its
/// // reference; with none in force there is none.
/// let started = alteration_made(None, latch, altered, 10f64.to_radians(), false);
/// assert!((started - 10f64.to_radians()).abs() < 1e-12);
/// assert_eq!(alteration_made(latch, None, altered, 10f64.to_radians(), false), 0.0);
/// // Standing on: the course taken while giving way to another is kept.
/// let stand_on = Some(EncounterLatch::new(Encounter::BeingOvertaken, &own, 0.0));
/// let offset = alteration_made(stand_on, stand_on, 0.0, 35f64.to_radians(), true);
/// assert!((offset - 35f64.to_radians()).abs() < 1e-12);
/// assert_eq!(alteration_made(stand_on, stand_on, offset, 0.0, false), offset);
/// ```
#[must_use]
pub fn alteration_made(
    before: Option<EncounterLatch>,
    now: Option<EncounterLatch>,
    altered_rad: f64,
    course_rad: f64,
    acting_for_others: bool,
) -> f64 {
    let Some(latch) = now else {
        return 0.0;
    };
    let same = before == now;
    let change = course_change_rad(latch.reference_course_rad, course_rad);
    match latch.encounter.role() {
        Role::StandOn => match (same, acting_for_others) {
            (_, true) => change,
            (true, false) => altered_rad,
            (false, false) => 0.0,
        },
        _ if same => altered_rad.max(change.abs()),
        _ => change.abs(),
    }
}

/// The course a stand-on vessel must keep while it may not act (rule
/// 17(a)(i)): the latch's reference course plus the change it was last free
/// to make while giving way to another vessel (`offset_rad`, see
/// [`alteration_made`]), radians.
///
/// ```
/// use vorrt_colregs::{rules::stand_on_course_rad, Encounter, EncounterLatch, VesselState};
/// use glam::DVec2;
/// let own = VesselState::new(DVec2::ZERO, 0.5, 6.0, 50.0);
/// let latch = EncounterLatch::new(Encounter::CrossingStandOn, &own, 0.0);
/// assert!((stand_on_course_rad(&latch, 0.25) - 0.75).abs() < 1e-12);
/// ```
#[must_use]
pub fn stand_on_course_rad(latch: &EncounterLatch, offset_rad: f64) -> f64 {
    angle::normalize_2pi(latch.reference_course_rad + offset_rad)
}

/// Whether a course change (from [`course_change_rad`]) is a turn at all:
/// larger than [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad)
/// (2° by default) either way. Smaller changes are not detectable.
///
/// ```
/// use vorrt_colregs::{rules::is_detectable_turn, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(!is_detectable_turn(1f64.to_radians(), &params));
/// assert!(is_detectable_turn(-5f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_detectable_turn(course_change_rad: f64, parameters: &RuleParameters) -> bool {
    course_change_rad.abs() > parameters.turn_tolerance_rad
}

/// Whether a course change (from [`course_change_rad`], judged from the
/// reference course) is a turn to port: more than
/// [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad) to port. A
/// return toward the reference course after a starboard turn is not a port
/// turn; any course to port of the reference is.
///
/// ```
/// use vorrt_colregs::{rules::is_port_turn, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(is_port_turn(-10f64.to_radians(), &params));
/// assert!(!is_port_turn(-1f64.to_radians(), &params)); // within the 2° tolerance
/// assert!(!is_port_turn(10f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_port_turn(course_change_rad: f64, parameters: &RuleParameters) -> bool {
    course_change_rad < -parameters.turn_tolerance_rad
}

/// Rules 8(b), 16: whether a course change (either way) is large enough to be
/// readily apparent to another vessel: at least
/// [`apparent_turn_rad`](RuleParameters::apparent_turn_rad) (30° by default).
/// A change measured from positions is judged with
/// [`is_measured_readily_apparent`].
///
/// ```
/// use vorrt_colregs::{rules::is_readily_apparent, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(is_readily_apparent(35f64.to_radians(), &params));
/// assert!(!is_readily_apparent(10f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_readily_apparent(course_change_rad: f64, parameters: &RuleParameters) -> bool {
    course_change_rad.abs() >= parameters.apparent_turn_rad
}

/// The fraction of the reference speed whose loss is a readily apparent
/// reduction (rules 8(b), 8(e), 16): a speed halved (Woerner 2019); the
/// default of `ScoringParameters::apparent_speed_reduction_fraction`.
pub const APPARENT_SPEED_REDUCTION_FRACTION: f64 = 0.5;

/// Whether `speed_mps` is a readily apparent reduction from
/// `reference_speed_mps` ([`APPARENT_SPEED_REDUCTION_FRACTION`] shed).
///
/// ```
/// use vorrt_colregs::rules::is_readily_apparent_reduction;
/// assert!(is_readily_apparent_reduction(2.7, 6.0) && !is_readily_apparent_reduction(4.0, 6.0));
/// ```
#[must_use]
pub fn is_readily_apparent_reduction(speed_mps: f64, reference_speed_mps: f64) -> bool {
    reference_speed_mps > 0.0
        && reference_speed_mps - speed_mps
            >= APPARENT_SPEED_REDUCTION_FRACTION * reference_speed_mps
}

/// Rules 8(a), 16: whether a readily apparent alteration has been eased back,
/// so that it is no longer held: the course change in the alteration's
/// direction (`change_toward_rad`: the signed change from
/// [`course_change_rad`], times the side the alteration went to) has fallen
/// more than [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad) (not
/// detectable) below [`apparent_turn_rad`](RuleParameters::apparent_turn_rad).
/// The prospective check ([`check_action`](crate::check_action)) and the
/// retrospective scoring both judge holding with it.
///
/// ```
/// use vorrt_colregs::{rules::is_alteration_eased_back, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(!is_alteration_eased_back(29f64.to_radians(), &params)); // within 2° of 30°
/// assert!(is_alteration_eased_back(10f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_alteration_eased_back(change_toward_rad: f64, parameters: &RuleParameters) -> bool {
    change_toward_rad < parameters.apparent_turn_rad - parameters.turn_tolerance_rad
}

/// The rounding allowed when an angle computed from positions is compared
/// with a threshold it should meet exactly, radians (about 6e-8 degrees).
pub const ANGLE_ROUNDING_RAD: f64 = 1e-9;

/// [`is_readily_apparent`] for a course change measured after the fact
/// (from observed courses over ground, computed from positions), allowing
/// [`ANGLE_ROUNDING_RAD`] of rounding: a 30° leg must not read as a
/// 29.999999999° one.
///
/// ```
/// use vorrt_colregs::{rules::is_measured_readily_apparent, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(is_measured_readily_apparent(params.apparent_turn_rad - 1e-12, &params));
/// assert!(!is_measured_readily_apparent(29f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_measured_readily_apparent(course_change_rad: f64, parameters: &RuleParameters) -> bool {
    is_readily_apparent(course_change_rad.abs() + ANGLE_ROUNDING_RAD, parameters)
}

/// Whether a speed change from the reference speed (either way) is beyond
/// [`stand_on_speed_tolerance_mps`](RuleParameters::stand_on_speed_tolerance_mps):
/// an action, and for a stand-on vessel a failure to keep her speed.
///
/// ```
/// use vorrt_colregs::{rules::is_speed_change, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(is_speed_change(-3.0, &params));
/// assert!(!is_speed_change(0.5, &params));
/// ```
#[inline]
#[must_use]
pub fn is_speed_change(speed_change_mps: f64, parameters: &RuleParameters) -> bool {
    speed_change_mps.abs() > parameters.stand_on_speed_tolerance_mps
}

/// Rule 17(a)(i): whether a course change (from [`course_change_rad`]) is
/// more than a stand-on vessel may drift while she keeps her course
/// ([`stand_on_course_tolerance_rad`](RuleParameters::stand_on_course_tolerance_rad)).
///
/// ```
/// use vorrt_colregs::{rules::is_stand_on_course_change, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(is_stand_on_course_change(40f64.to_radians(), &params));
/// assert!(!is_stand_on_course_change(-10f64.to_radians(), &params));
/// ```
#[inline]
#[must_use]
pub fn is_stand_on_course_change(course_change_rad: f64, parameters: &RuleParameters) -> bool {
    course_change_rad.abs() > parameters.stand_on_course_tolerance_rad
}

/// Rule 17(c): whether the target lies on ownship's port side, seen from
/// `own_position_m` on the reference course (the course held when the
/// encounter began): relative bearing strictly between 180° and 360°. Dead
/// ahead and dead astern are on neither side. The reference course, not the
/// present one, because a port turn can bring a port-side vessel onto the
/// bow, which is what rule 17(c) forbids.
///
/// ```
/// use vorrt_colregs::rules::is_on_port_side;
/// use glam::DVec2;
/// assert!(is_on_port_side(DVec2::ZERO, 0.0, DVec2::new(-1000.0, 1000.0)));
/// assert!(!is_on_port_side(DVec2::ZERO, 0.0, DVec2::new(1000.0, 1000.0)));
/// ```
#[inline]
#[must_use]
pub fn is_on_port_side(
    own_position_m: DVec2,
    reference_course_rad: f64,
    target_position_m: DVec2,
) -> bool {
    angle::relative_bearing(own_position_m, reference_course_rad, target_position_m) > PI
}

/// Rule 17(c) for a stand-on vessel, good seamanship (rules 2(a), 8(a))
/// for any: whether ownship, having turned from `course_before_rad` (the
/// course it held before the turn, as an observer saw it) to its present
/// course (`own`), turned to port **toward** `target` and so put it in
/// danger: the turn is to port ([`is_port_turn`]), the target lay on the
/// port side of the course before ([`is_on_port_side`]) and lies forward of
/// the beam on the new course, and on the new course it is a risk of
/// collision ([`assess_risk`](crate::assess_risk): inside the MTD, a closest
/// approach ahead under [`risk_cpa_m`](RuleParameters::risk_cpa_m)) where
/// on the course held before it was no risk: the turn made the danger (a
/// vessel already a risk is an encounter in force, whose own rules judge
/// the turn: 14, 15, 17(a)(i), 17(c)). Nor is a vessel that ownship
/// overtakes, or that overtakes it, on the new course: rule 13 keeps them
/// apart (the clearance, and no cutting across the overtaken vessel's bow).
///
/// Which of the two would cross ahead of the other is no part of it
/// (decision 51): a return that brings a vessel from port onto a collision
/// course makes ownship the stand-on vessel of a new crossing whichever way
/// it would end, and that way is what the other vessel's own action
/// decides (giving way to starboard, it passes astern). Judged on the
/// observed states at the latch, part way through that vessel's turn, the
/// crossing's side flipped with it, so the same track was a finding with a
/// vessel that acted and none with one that did not, and the planner, which
/// predicts the vessel's steady motion, could not see it. A return that
/// passes astern of the vessel beyond `risk_cpa_m` is not one.
///
/// This is the return toward the goal that swings onto a vessel crossing
/// from port after an alteration to starboard for another (issue 24), which
/// a latch made only on the new course would judge as a stand-on encounter.
/// The planner refuses such a leg and the evaluation finds it, with this
/// one predicate.
///
/// ```
/// use vorrt_colregs::{rules::is_port_turn_toward_vessel, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// // Ownship has come back from 035 to 357; a vessel 2.8 nm off the port
/// // bow heads east across its new course, to be crossed 670 m ahead.
/// let own = VesselState::new(DVec2::ZERO, 357f64.to_radians(), 6.0, 100.0);
/// let crossing = VesselState::new(DVec2::new(-4000.0, 3300.0), 90f64.to_radians(), 6.0, 100.0);
/// assert!(is_port_turn_toward_vessel(35f64.to_radians(), &own, &crossing, &params));
/// // Held on 035 the same vessel passes 1.1 nm off: no turn, no finding.
/// let held = VesselState { course_rad: 35f64.to_radians(), ..own };
/// assert!(!is_port_turn_toward_vessel(35f64.to_radians(), &held, &crossing, &params));
/// // Coming back to 330 passes 860 m astern of it: still a collision
/// // course made by the turn, a finding.
/// let astern = VesselState { course_rad: 330f64.to_radians(), ..own };
/// assert!(is_port_turn_toward_vessel(35f64.to_radians(), &astern, &crossing, &params));
/// // Coming back to 300 passes more than 1 nm astern: no finding.
/// let wide = VesselState { course_rad: 300f64.to_radians(), ..own };
/// assert!(!is_port_turn_toward_vessel(35f64.to_radians(), &wide, &crossing, &params));
/// ```
#[must_use]
pub fn is_port_turn_toward_vessel(
    course_before_rad: f64,
    own: &crate::VesselState,
    target: &crate::VesselState,
    parameters: &RuleParameters,
) -> bool {
    let before_mps = crate::VesselState {
        course_rad: course_before_rad,
        ..*own
    }
    .velocity_mps();
    is_port_turn_toward_vessel_moving(
        course_before_rad,
        (own, own.velocity_mps(), before_mps),
        target,
        target.velocity_mps(),
        parameters,
    )
}

/// As [`is_port_turn_toward_vessel`], with the velocities already worked
/// out: `own` with its [`VesselState::velocity_mps`](crate::VesselState::velocity_mps)
/// and its velocity on `course_before_rad`, and `target_mps`, `target`'s: a
/// caller judging many targets against one course works ownship's out once
/// (decision 54). The same judgement as [`is_port_turn_toward_vessel`].
#[must_use]
pub fn is_port_turn_toward_vessel_moving(
    course_before_rad: f64,
    (own, own_mps, before_mps): (&crate::VesselState, DVec2, DVec2),
    target: &crate::VesselState,
    target_mps: DVec2,
    parameters: &RuleParameters,
) -> bool {
    let turn = course_change_rad(course_before_rad, own.course_rad);
    if !is_port_turn(turn, parameters) || !within_mtd(own.range_to(target), parameters) {
        return false;
    }
    // The tests are pure and joined by "and", so their order changes no
    // verdict, only the work: the risk on the new course first, which
    // refuses most of the vessels the planner asks about (those its
    // bearing gate lets through, `PortTurnGate`: 93 % of 3.7 M calls on
    // 60 runs with 8 COLREGs-obeying targets), before the two bearings
    // (decision 53).
    crate::risk::assess_risk_moving(own, own_mps, target, target_mps, parameters).at_risk
        && forward_of_beam_moving(own, own_mps, target.position_m)
        && on_port_side_moving(own, (course_before_rad, before_mps), target.position_m)
        && !crate::risk::assess_risk_moving(
            &crate::VesselState {
                course_rad: course_before_rad,
                ..*own
            },
            before_mps,
            target,
            target_mps,
            parameters,
        )
        .at_risk
        && !matches!(
            crate::classify(own, target, parameters),
            Encounter::Overtaking | Encounter::BeingOvertaken
        )
}

/// Whether ownship gives way in `encounter` (head-on, crossing give-way,
/// overtaking: rule 16).
///
/// ```
/// use vorrt_colregs::{rules::gives_way, Encounter};
/// assert!(gives_way(Encounter::HeadOn));
/// assert!(!gives_way(Encounter::CrossingStandOn));
/// ```
#[inline]
#[must_use]
pub fn gives_way(encounter: Encounter) -> bool {
    encounter.role() == Role::GiveWay
}

/// Whether ownship gives way to any target among the encounters in force.
///
/// ```
/// use vorrt_colregs::{rules::giving_way_to_any, Encounter, EncounterLatch, VesselState};
/// use glam::DVec2;
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let stand_on = EncounterLatch::new(Encounter::CrossingStandOn, &own, 0.0);
/// let give_way = EncounterLatch::new(Encounter::CrossingGiveWay, &own, 0.0);
/// let latches = [Some(stand_on), None, Some(give_way)];
/// assert!(giving_way_to_any(latches.iter().flatten()));
/// assert!(!giving_way_to_any(latches[..2].iter().flatten()));
/// ```
#[inline]
#[must_use]
pub fn giving_way_to_any<'a>(latches: impl IntoIterator<Item = &'a EncounterLatch>) -> bool {
    latches.into_iter().any(|latch| gives_way(latch.encounter))
}

/// Whether ownship acts for some vessel among the encounters in force, each
/// given with its range (metres): it gives way to one ([`gives_way`]), or it
/// stands on for one within the stand-on action range, where it may act on
/// its own (rule 17(a)(ii), [`within_action_range`]). With several vessels
/// rule 17(a)(i) yields to such action: a vessel that turns for one vessel
/// cannot also keep its course for another ([`may_act`]).
///
/// ```
/// use vorrt_colregs::{rules::acting_for_any, Encounter, EncounterLatch, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let stand_on = EncounterLatch::new(Encounter::CrossingStandOn, &own, 0.0);
/// let give_way = EncounterLatch::new(Encounter::CrossingGiveWay, &own, 0.0);
/// assert!(acting_for_any([(&give_way, 9000.0)], &params));
/// assert!(acting_for_any([(&stand_on, 3000.0)], &params)); // within 2 nm
/// assert!(!acting_for_any([(&stand_on, 9000.0)], &params));
/// ```
#[must_use]
pub fn acting_for_any<'a>(
    encounters: impl IntoIterator<Item = (&'a EncounterLatch, f64)>,
    parameters: &RuleParameters,
) -> bool {
    encounters.into_iter().any(|(latch, range_m)| {
        gives_way(latch.encounter)
            || (latch.encounter.role() == Role::StandOn && within_action_range(range_m, parameters))
    })
}

/// Rule 17(a)(ii): whether the range to the give-way vessel is within
/// [`stand_on_action_range_m`](RuleParameters::stand_on_action_range_m), so
/// that a stand-on vessel may act on her own.
///
/// ```
/// use vorrt_colregs::{rules::within_action_range, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(within_action_range(params.stand_on_action_range_m, &params));
/// assert!(!within_action_range(params.stand_on_action_range_m + 1.0, &params));
/// ```
#[inline]
#[must_use]
pub fn within_action_range(range_m: f64, parameters: &RuleParameters) -> bool {
    range_m <= parameters.stand_on_action_range_m
}

/// Whether ownship, in a stand-on encounter with a target at `range_m`, may
/// act (manoeuvre): the target is within the stand-on action range (rule
/// 17(a)(ii), 17(b)), or ownship acts for some other vessel
/// (`giving_way_to_any`: see [`acting_for_any`]; it gives way to it, or may
/// act for it): with several targets, a vessel that must give way to one of
/// them, or acts for one within the action range, cannot also keep its
/// course for another, so rule 17 yields. Rule 17(c) holds either way.
///
/// ```
/// use vorrt_colregs::{rules::may_act, RuleParameters};
/// let params = RuleParameters::default();
/// assert!(!may_act(10_000.0, false, &params));
/// assert!(may_act(10_000.0, true, &params));
/// assert!(may_act(1_000.0, false, &params));
/// ```
#[inline]
#[must_use]
pub fn may_act(range_m: f64, giving_way_to_any: bool, parameters: &RuleParameters) -> bool {
    giving_way_to_any || within_action_range(range_m, parameters)
}

/// Rule 17(a)(i): whether ownship must keep its course and speed in
/// `encounter`: it stands on and may not act ([`may_act`]).
///
/// ```
/// use vorrt_colregs::{rules::must_stand_on, Encounter};
/// assert!(must_stand_on(Encounter::BeingOvertaken, false));
/// assert!(!must_stand_on(Encounter::BeingOvertaken, true));
/// assert!(!must_stand_on(Encounter::HeadOn, false));
/// ```
#[inline]
#[must_use]
pub fn must_stand_on(encounter: Encounter, may_act: bool) -> bool {
    encounter.role() == Role::StandOn && !may_act
}

#[cfg(test)]
#[path = "rules_tests.rs"]
mod tests;
