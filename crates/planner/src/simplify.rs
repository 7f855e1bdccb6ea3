//! Path simplification: a branch of the tree becomes the fewest legs ownship
//! can sail that pass the same validity check.
//!
//! The tree's branch is a chain of `d'`-long steps with a course change at
//! every node: safe, but a zig-zag no mariner would steer and no observer
//! could read (rule 8(b): a succession of small alterations should be
//! avoided). As OMPL's path simplifier does, each shortcut is re-validated by
//! the planner's own [`MotionValidator`], never by a weaker test; and each
//! shortcut is a [`Leg`] of the [`MotionModel`] ownship really sails (a turn
//! at its rate of turn, then a straight run), so the curve judged is the curve
//! sailed. Because the legs are timed (ownship arrives earlier on a shortcut,
//! and the targets are elsewhere then), each leg is validated at the time it
//! is sailed, from the encounters in force where it starts.
//!
//! From the present pose, the farthest point of the branch reachable by one
//! valid leg is sought: the goal first, then by a galloping search (1, 2, 4,
//! ... points on, then bisection), which assumes nearer points are easier to
//! reach; when the next point itself cannot be reached, a few more are tried.
//! Before the branch's points, at every step, the simplifier tries the
//! manoeuvre mariners use: one alteration of course ([`ALTERATIONS_DEG`];
//! none at all first of all), held for a while ([`HOLD_M`], shortest first,
//! and between two of them the shortest whose end is past and clear), then
//! one leg to the goal, the shortest such manoeuvre of the alterations up
//! to 55° winning (decision 44); when no alteration to
//! starboard (or holding on) at service speed is valid, the same at reduced
//! speed ([`SPEED_FACTORS`]: rules 8(e), 17(b); scenario-based MPC's speed
//! factors),
//! then the alterations to port. Where the leg to the goal would turn to
//! port onto a vessel crossing from port (decision 28), a course astern of
//! it, then a course part of the way back (decision 61), is tried before
//! the next, longer hold. The branch is what is left
//! when no such manoeuvre is valid, as among several vessels.
//!
//! From the planner's root, before any tree, where no single alteration
//! held can be sailed, [`hold_then_alter`] tries the manoeuvres of two
//! alterations: the present course kept, then one action (a stand-on
//! vessel's, rule 17), and an alteration held, then the course held before
//! it resumed; [`hold_then_alter_shorter_than`] the same, shorter than a
//! plan in hand (decision 67).
//!
//! Every leg starts at the speed the one before ends at (the first at
//! ownship's present speed) and changes speed toward its settled speed at
//! the rate of [`Speeds`]: the leg to the goal, and the legs along the
//! branch, settle at the service speed.

use crate::plan::RejectionCause;
use crate::validity::{EncounterState, MotionValidator};
use glam::DVec2;
use vorrt_colregs::{ManeuverViolation, Role};
use vorrt_geometry::angle;
use vorrt_jfs::{Leg, MotionModel, Pose};

mod hold;
use hold::{Grade, HoldOutcome, RETURN_BISECTIONS, hold_and_return};

/// When the next branch point cannot be reached by a valid leg, how many
/// points beyond it are tried before the simplification gives up.
pub const LOOK_PAST: usize = 12;

/// One leg of a simplified path, with the encounters in force at its end and
/// the time it ends.
#[derive(Debug, Clone, PartialEq)]
pub struct SimplifiedLeg {
    /// The leg.
    pub leg: Leg,
    /// Seconds from the start to the leg's end.
    pub end_elapsed_s: f64,
    /// The encounters in force at its end.
    pub state: EncounterState,
}

/// Ownship's speeds for a simplification.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Speeds {
    /// The speed ownship is at when the first leg starts, m/s.
    pub start_mps: f64,
    /// The speed it sails at when not slowing down, m/s (positive).
    pub service_mps: f64,
    /// How fast it changes speed, m/s² (infinite: at once).
    pub change_mps2: f64,
}

impl Speeds {
    /// Sailing at `speed_mps` throughout.
    #[must_use]
    pub fn constant(speed_mps: f64) -> Self {
        Self {
            start_mps: speed_mps,
            service_mps: speed_mps,
            change_mps2: f64::INFINITY,
        }
    }
}

/// Simplifies the path through `points` (the branch after its root; the last
/// is the goal) from `start` with `state` in force into legs of `model` at
/// `speeds`, every one accepted by `validator`. `None` when some point
/// cannot be passed on by any valid leg.
///
/// ```
/// use vorrt_planner::simplify::{simplify, Speeds};
/// use vorrt_planner::validity::EncounterState;
/// use vorrt_planner::{safety::SafetyChecker, PlannerConfig};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{Pose, RateLimitedTurn};
/// use glam::DVec2;
/// let config = PlannerConfig::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let checker = SafetyChecker::new(&config, &[], own, DVec2::new(0.0, 3000.0), 0.0);
/// // A zig-zag with nothing in the way becomes one straight leg.
/// let points: Vec<DVec2> = (1..=30)
///     .map(|i| DVec2::new(if i % 2 == 0 { 0.0 } else { 20.0 }, 100.0 * i as f64))
///     .collect();
/// let legs = simplify(
///     &RateLimitedTurn { turn_radius_m: 300.0 },
///     &checker,
///     Pose { position_m: DVec2::ZERO, course_rad: 0.0 },
///     Speeds::constant(6.0),
///     &points,
///     &EncounterState::default(),
/// )
/// .unwrap();
/// assert_eq!(legs.len(), 1);
/// ```
pub fn simplify<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    start: Pose,
    speeds: Speeds,
    points: &[DVec2],
    state: &EncounterState,
) -> Option<Vec<SimplifiedLeg>> {
    simplify_after(model, validator, start, speeds, points, state, false)
}

/// As [`simplify`]; with `start_searched`, the leg from `start` to the
/// goal and the manoeuvre search from `start` are known to fail (the same
/// model, validator, start, speeds, encounters and goal were searched
/// before: the planner's manoeuvre search from the root, before a branch of
/// its tree is simplified), so they are not validated again. Every verdict
/// is a pure function of the leg and the encounters, so the legs returned
/// are the same.
pub fn simplify_after<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    start: Pose,
    speeds: Speeds,
    points: &[DVec2],
    state: &EncounterState,
    start_searched: bool,
) -> Option<Vec<SimplifiedLeg>> {
    let mut legs = Vec::new();
    let mut searched = start_searched;
    let mut pose = start;
    let mut speed_mps = speeds.start_mps;
    let mut elapsed_s = 0.0;
    let mut state = state.clone();
    let mut next = 0usize;
    let last = points.len().checked_sub(1)?;
    while next <= last {
        let attempt = |index: usize| -> Option<SimplifiedLeg> {
            let leg = model
                .steer(pose, points[index], speeds.service_mps, f64::INFINITY)?
                .from_speed(speed_mps, speeds.change_mps2);
            let mut after = state.clone();
            validator.validate(&leg, elapsed_s, &mut after).ok()?;
            Some(SimplifiedLeg {
                end_elapsed_s: elapsed_s + leg.duration_s(),
                leg,
                state: after,
            })
        };
        if !std::mem::take(&mut searched) {
            if let Some(leg) = attempt(last) {
                legs.push(leg);
                break;
            }
            // The manoeuvre mariners use: turn onto a course (or hold the
            // present one), hold it a while, then one leg to the goal.
            let from = SimplifiedLeg {
                leg: Leg::straight(pose.position_m, pose.course_rad, 0.0, speed_mps),
                end_elapsed_s: elapsed_s,
                state: state.clone(),
            };
            if let Some(manoeuvre) = alter_hold_return(
                model,
                validator,
                &from,
                speeds,
                points[last],
                (Alterations::Mariners, f64::INFINITY),
            ) {
                legs.extend(manoeuvre);
                break;
            }
        }
        let (index, leg) = farthest_reachable(next, last, &attempt)?;
        pose = leg.leg.end_pose();
        speed_mps = leg.leg.end_speed_mps();
        elapsed_s = leg.end_elapsed_s;
        state = leg.state.clone();
        legs.push(leg);
        next = index + 1;
    }
    Some(legs)
}

/// The length sailed along `legs`, metres.
pub(crate) fn length_of(legs: &[SimplifiedLeg]) -> f64 {
    legs.iter().map(|leg| leg.leg.length_m()).sum()
}

/// The shortest a manoeuvre that sails `hold` can be to `goal_m`, metres:
/// the hold, then the straight line from its end (the triangle
/// inequality; a longer hold of the same course is no shorter).
fn shortest_through_m(hold: &Leg, goal_m: DVec2) -> f64 {
    hold.length_m() + hold.end_m().distance(goal_m)
}

/// Which manoeuvres [`alter_hold_return`] tries.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Alterations {
    /// Holding on and the starboard alterations (smallest first) at service
    /// speed, then the same at reduced speed, then the port alterations
    /// likewise (the manoeuvre search of [`simplify`]).
    Mariners,
    /// As `Mariners` without holding on at service speed (after a hold of
    /// the present course: holding on further is a longer first hold).
    MarinersAfterHolding,
    /// Back onto the course held before an alteration of this many degrees
    /// (a return toward the route), at service speed.
    Resume(f64),
}

impl Alterations {
    /// The (alteration, speed factor) pairs, in order.
    #[expect(
        clippy::float_cmp,
        reason = "picks out one exact entry of the alteration and speed tables"
    )]
    fn order(self) -> impl Iterator<Item = (f64, f64)> {
        let resume = match self {
            Self::Resume(alteration_deg) => Some((-alteration_deg, 1.0)),
            _ => None,
        };
        let starboard = ALTERATIONS_DEG.iter().filter(|deg| **deg >= 0.0);
        let port = ALTERATIONS_DEG.iter().filter(|deg| **deg < 0.0);
        let mariners = SPEED_FACTORS
            .iter()
            .flat_map(move |factor| starboard.clone().map(move |deg| (*deg, *factor)))
            .chain(
                SPEED_FACTORS
                    .iter()
                    .flat_map(move |factor| port.clone().map(move |deg| (*deg, *factor))),
            )
            .filter(move |&(deg, factor)| {
                !(self == Self::MarinersAfterHolding && deg == 0.0 && factor == 1.0)
            })
            // A return is one course, not the search.
            .take(if resume.is_some() { 0 } else { usize::MAX });
        resume.into_iter().chain(mariners)
    }

    /// The holds tried on a course onto which `turn` turns (with no
    /// straight run): those of [`HOLD_M`], and for the two-alteration
    /// manoeuvres only those short of abeam of `goal_m` ([`holds_short_of`]).
    fn holds(self, goal_m: DVec2, turn: impl FnOnce() -> Leg) -> impl Iterator<Item = f64> {
        let abeam_m = if self == Self::Mariners {
            f64::INFINITY
        } else {
            abeam_of(goal_m, &turn())
        };
        holds_short_of(abeam_m)
    }
}

/// From where `from` ends (at its end speed), the shortest manoeuvre of the
/// form "turn onto the present course plus an alteration, at a fraction of
/// the service speed, hold it for one of [`HOLD_M`], then one leg to the
/// goal at service speed" that the validator accepts, from the first
/// [`Grade`] of `alterations` (in order) that has one: for each alteration
/// of the grade the shortest hold whose return is valid, and of these the
/// manoeuvre with the least length sailed to the goal (decision 44);
/// alterations onto a course more than [`AWAY_FROM_GOAL_RAD`] off the
/// goal's bearing only where no other is valid, grade by grade, and a port
/// alteration whose return turns to port again held at least 2 km (decision
/// 68). The hold and the return ([`return_to_goal`]: the leg to the goal,
/// or a course astern of a vessel then that leg), or `None`.
///
/// Taking the first alteration that works (smallest first) held 35° for up
/// to 12 km where 45° or 55° would have cleared the same vessels held for a
/// fraction of it: on generated open-sea runs most of the path overhead was
/// a small alteration held long. Every alteration of a grade is readily
/// apparent (rule 8(b)) and begun at once (rule 8(a)), so the shortest of
/// them is the smallest deviation that achieves the passing distance. A
/// hold whose length plus the straight line from its end to the goal is no
/// shorter than the best found cannot win (the triangle inequality: longer
/// holds only lengthen it), so it is not validated.
///
/// A reduced speed is held until it is reached (a speed change is readily
/// apparent only once made: rule 8(b), half the speed) and until every
/// encounter in which ownship gives way has passed (rule 8(d)), so ownship
/// does not speed up again before the other vessel is past.
fn alter_hold_return<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    from: &SimplifiedLeg,
    speeds: Speeds,
    goal_m: DVec2,
    (alterations, shorter_than_m): (Alterations, f64),
) -> Option<Vec<SimplifiedLeg>> {
    let pose = from.leg.end_pose();
    let start_mps = from.leg.end_speed_mps();
    let goal_course_rad = angle::unit_to_course(goal_m - pose.position_m);
    let mut best: Option<((bool, Grade), f64, Vec<SimplifiedLeg>)> = None;
    for (alteration_deg, factor, grade) in goal_forward_first(alterations, pose, goal_course_rad) {
        if best.as_ref().is_some_and(|(found, ..)| *found != grade) {
            // A grade that has a manoeuvre is preferred to every later one.
            break;
        }
        let course_rad = pose.course_rad + alteration_deg.to_radians();
        let hold_speed_mps = factor * speeds.service_mps;
        let holds = alterations.holds(goal_m, || {
            model.turn_onto(pose, course_rad, hold_speed_mps, 0.0)
        });
        // `clear_only`: the hold is wanted only if it ends past and clear.
        let sail = |hold_m: f64, clear_only: bool| {
            let hold = model
                .turn_onto(pose, course_rad, hold_speed_mps, hold_m)
                .from_speed(start_mps, speeds.change_mps2);
            let shortest_m = shortest_through_m(&hold, goal_m);
            if shortest_m >= shorter_than_m
                || best
                    .as_ref()
                    .is_some_and(|(_, best_m, _)| shortest_m >= *best_m)
            {
                // This hold, and every longer one, sails farther than the best.
                return HoldOutcome::Invalid;
            }
            hold_and_return(
                model, validator, from, hold, factor, speeds, goal_m, clear_only,
            )
        };
        // A port alteration whose return turns to port again is held long
        // enough for an observer to see two turns, not one: held shorter,
        // the course over ground swings on through both, and a vessel
        // judged clear of each was seen turned toward (decision 68; as a
        // course part of the way back is held, SHORT_OF_HOLD_M).
        let goal_to_port = angle::normalize_pi(goal_course_rad - course_rad) < 0.0;
        let shortest_m = if alteration_deg < 0.0 && goal_to_port {
            SHORT_OF_HOLD_M[0]
        } else {
            0.0
        };
        // The longest hold known to be valid whose return was refused.
        let mut refused_m: Option<f64> = None;
        for hold_m in holds.filter(|hold_m| *hold_m >= shortest_m) {
            match sail(hold_m, best.is_some()) {
                // Holding on is already invalid this far: longer holds are too.
                HoldOutcome::Invalid => break,
                HoldOutcome::Refused => refused_m = Some(hold_m),
                // Another alteration than the first found wins only with a
                // return begun once past and clear: judged on the course it
                // settles on, a return begun earlier swings back before the
                // closest approach as observed (rule 8(d); decision 44).
                HoldOutcome::Found(legs) if best.is_some() && !past_and_clear(&legs[0].state) => {
                    refused_m = Some(hold_m);
                }
                HoldOutcome::Found(mut legs) => {
                    // The return is begun as soon as it is valid and every
                    // vessel ownship gives way to is past and clear
                    // ([`past_and_clear`]): between the hold refused and this
                    // one, the shortest such hold found by bisection (the
                    // moment between two holds of HOLD_M was otherwise waited
                    // for up to the longer one).
                    if let Some(mut short_m) = refused_m {
                        let mut long_m = hold_m;
                        for _ in 0..RETURN_BISECTIONS {
                            let middle_m = 0.5 * (short_m + long_m);
                            match sail(middle_m, true) {
                                HoldOutcome::Found(sooner) if past_and_clear(&sooner[0].state) => {
                                    legs = sooner;
                                    long_m = middle_m;
                                }
                                _ => short_m = middle_m,
                            }
                        }
                    }
                    let length_m = length_of(&legs);
                    if best
                        .as_ref()
                        .is_none_or(|(_, best_m, _)| length_m < *best_m)
                    {
                        best = Some((grade, length_m, legs));
                    }
                    // The shortest valid hold of this alteration is found.
                    break;
                }
            }
        }
    }
    best.map(|(_, _, legs)| legs)
}

/// The (alteration, speed factor) pairs of `alterations` from `pose`, each
/// with its grade: first those onto a course no more than
/// [`AWAY_FROM_GOAL_RAD`] off the goal's bearing `goal_course_rad`, in
/// order, then the others, in order, each marked `true` (decision 68).
/// Turning further away, alteration after alteration, took ownship 180° off
/// its route among many vessels and the run ended short of the goal.
/// Holding on such a course counts as one: exempting it let ownship hold a
/// course away from the goal for an hour among COLREGs-obeying vessels
/// (decision 68's measurements).
fn goal_forward_first(
    alterations: Alterations,
    pose: Pose,
    goal_course_rad: f64,
) -> Vec<(f64, f64, (bool, Grade))> {
    let away = |alteration_deg: f64| {
        let course_rad = pose.course_rad + alteration_deg.to_radians();
        angle::normalize_pi(course_rad - goal_course_rad).abs() > AWAY_FROM_GOAL_RAD
    };
    let (mut order, away_from): (Vec<_>, Vec<_>) = alterations
        .order()
        .map(|(deg, factor)| (deg, factor, (away(deg), Grade::of(deg, factor))))
        .partition(|(.., (away, _))| !away);
    order.extend(away_from);
    order
}

/// An alteration onto a course more than this off the goal's bearing is
/// tried only where no other is valid, radians (112.5°: the goal more than
/// 22.5° abaft the beam, in the sector of the sternlight, rule 21(c), the
/// bearing at which the project reads a vessel as past; decision 68).
pub const AWAY_FROM_GOAL_RAD: f64 = 5.0 * std::f64::consts::FRAC_PI_8;

/// The courses to port of the goal's bearing that a return refused for
/// turning to port onto a vessel tries instead, degrees: to pass astern of
/// the vessel it would have crossed ahead of.
const ASTERN_DEG: [f64; 3] = [15.0, 30.0, 45.0];

/// How far a course astern of a vessel ([`ASTERN_DEG`]) is held before the
/// leg to the goal, metres, shortest first; a course refused held the
/// shortest is not asked held longer.
const ASTERN_HOLD_M: [f64; 3] = [1000.0, 2000.0, 4000.0];

/// From the end of `hold`, the return toward the goal the validator
/// accepts: one leg to the goal; or, where that leg would turn to port onto
/// a vessel on the port side, to cross ahead of it
/// ([`ManeuverViolation::PortTurnTowardVessel`](vorrt_colregs::ManeuverViolation::PortTurnTowardVessel):
/// rules 2(a), 8(a), 17(c)), a course further to port held to pass astern
/// of it ([`ASTERN_DEG`], [`ASTERN_HOLD_M`], smallest first), then the leg
/// to the goal; where none is valid, a course part of the way back, short
/// of the goal's bearing ([`SHORT_OF_DEG`], [`SHORT_OF_HOLD_M`]), then the
/// leg to the goal. A longer hold of the alteration is the caller's next
/// try.
pub(crate) fn return_to_goal<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    hold: &SimplifiedLeg,
    speeds: Speeds,
    goal_m: DVec2,
) -> Option<Vec<SimplifiedLeg>> {
    let sail = |from: &SimplifiedLeg, leg: Leg| {
        let leg = leg.from_speed(from.leg.end_speed_mps(), speeds.change_mps2);
        let mut state = from.state.clone();
        validator
            .validate(&leg, from.end_elapsed_s, &mut state)
            .map(|()| SimplifiedLeg {
                end_elapsed_s: from.end_elapsed_s + leg.duration_s(),
                leg,
                state,
            })
    };
    let to_goal = |from: &SimplifiedLeg| {
        model.steer(
            from.leg.end_pose(),
            goal_m,
            speeds.service_mps,
            f64::INFINITY,
        )
    };
    match sail(hold, to_goal(hold)?) {
        Ok(back) => return Some(vec![back]),
        Err(RejectionCause::Colregs(ManeuverViolation::PortTurnTowardVessel)) => {}
        Err(_) => return None,
    }
    let pose = hold.leg.end_pose();
    let goal_course_rad = angle::unit_to_course(goal_m - pose.position_m);
    let astern = ASTERN_DEG.map(|deg| (-deg, ASTERN_HOLD_M));
    let short_of = SHORT_OF_DEG.map(|deg| (deg, SHORT_OF_HOLD_M));
    // Part of the way back only once every vessel given way to is past and
    // clear (a smaller turn while one is in force is a small alteration in
    // its encounter, rule 8(b)), and from a hold at service speed: turning
    // while speeding up again, the course over ground an observer measures
    // swings on after the settled course the validator judges (open sea, 2
    // constant targets, run 244: a vessel from port latched part way
    // round, `port_turn_toward_vessel`).
    let at_service = hold.leg.end_speed_mps() >= speeds.service_mps;
    let short_of = short_of
        .into_iter()
        .filter(|_| at_service && past_and_clear(&hold.state));
    for (offset_deg, holds_m) in astern.into_iter().chain(short_of) {
        let course_rad = angle::normalize_2pi(goal_course_rad + offset_deg.to_radians());
        if offset_deg < 0.0 && angle::normalize_pi(course_rad - hold.leg.start_course_rad) < 0.0 {
            // Astern of the vessel only on a course still to starboard of
            // the one held before the alteration: further round it is a
            // port alteration from the course an observer saw ownship act
            // on, and for the vessel ownship first met head-on a
            // starboard-to-starboard pass (rule 14(a)) or, for one crossing
            // from port, a port turn for her (rule 17(c); decision 72).
            continue;
        }
        if offset_deg > 0.0
            && angle::normalize_pi(course_rad - pose.course_rad) >= -SHORT_OF_DEG[0].to_radians()
        {
            // Not a port turn toward the goal of at least the smallest
            // offset: nothing short of the goal's bearing to try.
            continue;
        }
        for hold_m in holds_m {
            let part = model.turn_onto(pose, course_rad, speeds.service_mps, hold_m);
            let Ok(part) = sail(hold, part) else {
                // A longer hold of this course sails the same turn and the
                // same pieces first (`Leg::pieces`, exactly where `step_m`
                // divides the holds, as the default 100 m does), so it is
                // refused where this one was, as a longer hold of an
                // alteration is (`HoldOutcome::Invalid`).
                break;
            };
            if let Some(back) = to_goal(&part).and_then(|leg| sail(&part, leg).ok()) {
                return Some(vec![part, back]);
            }
        }
    }
    None
}

/// The courses to starboard of the goal's bearing that a return refused
/// for turning to port onto a vessel tries where no course astern of it
/// ([`ASTERN_DEG`]) is valid, degrees: part of the way back, a port turn
/// smaller than the one refused that makes no vessel a risk, held while the
/// other vessel crosses ahead (decision 61).
const SHORT_OF_DEG: [f64; 2] = [15.0, 25.0];

/// How far a course short of the goal's bearing ([`SHORT_OF_DEG`]) is held
/// before the leg to the goal, metres, shortest first: 2 km (about 5
/// minutes at 13 kn) or more, so that an observer judging the course over
/// ground sees two port turns and not one (decision 55's run 116: a course
/// held 819 m between two port turns was seen as one of 56°).
const SHORT_OF_HOLD_M: [f64; 3] = [2000.0, 4000.0, 6000.0];

/// How far along the course onto which `turn` turns (with no straight run)
/// `goal_m` comes abeam, metres from the turn's end (negative: already
/// abaft the beam).
fn abeam_of(goal_m: DVec2, turn: &Leg) -> f64 {
    (goal_m - turn.turn_end_m()).dot(angle::course_to_unit(turn.course_rad))
}

/// The holds of [`HOLD_M`] that end short of `abeam_m` (where the goal
/// comes abeam), then one that ends abeam of it, if any of [`HOLD_M`] would
/// have gone past: a longer hold only sails farther from the goal. The
/// holds of the two-alteration manoeuvres ([`hold_then_alter`]) are these;
/// on a generated trafficgen situation
/// (`scripts/peers/trafficgen_scenarios.py`, seed 11, 25 a kind,
/// `03-CR-GW-CR-GW-HO`) the course resumed after an alteration was
/// otherwise held 2.8 km past the goal, and the run ended, three times the
/// straight route's duration later, short of it.
fn holds_short_of(abeam_m: f64) -> impl Iterator<Item = f64> {
    let longest_m = HOLD_M[HOLD_M.len() - 1];
    let abeam = (abeam_m > 0.0 && abeam_m <= longest_m).then_some(abeam_m);
    HOLD_M
        .iter()
        .copied()
        .take_while(move |hold_m| *hold_m < abeam_m)
        .chain(abeam)
}

/// Whether a hold at reduced speed has reached it and ends with no
/// encounter in force in which ownship gives way (the other vessel is past).
pub(crate) fn reduction_held(hold: &Leg, after: &EncounterState) -> bool {
    hold.duration_s() >= hold.speed_change_s() && past_and_clear(after)
}

/// Whether every vessel ownship gives way to is past and clear (rule 8(d)):
/// no encounter in which ownship gives way is in force in `state`. An
/// encounter is released when [`vorrt_colregs::has_passed`] holds (decision
/// 44 gives its reading for each encounter type and its sources: the range
/// opening, and the other vessel abaft the beam by the sternlight's 22.5°,
/// rule 21(c), or more than the risk distance off).
#[must_use]
pub fn past_and_clear(state: &EncounterState) -> bool {
    !state
        .latches
        .iter()
        .flatten()
        .any(|latch| latch.encounter.role() == Role::GiveWay)
}

/// The speeds the manoeuvre search holds, as fractions of the service
/// speed, in order: full speed, then a reduction to 45 % (scenario-based
/// MPC's speed factors are 1 and 0.5, Johansen et al. 2016; a speed halved
/// is readily apparent, Woerner 2019; 0.45 rather than 0.5 so that an
/// observer measuring speed over ground from a slightly different reference
/// still sees it halved, as 35° is planned for a 30° alteration). Stopping
/// is the evasive fallback's ([`crate::evasion`]).
pub const SPEED_FACTORS: [f64; 2] = [1.0, 0.45];

/// The alterations of course the manoeuvre search tries, degrees (positive
/// to starboard), in order: holding on, then readily apparent alterations to
/// starboard (rules 14, 15, 16: at least 30°; the smallest tried is 35° so
/// that an observer measuring course over ground with some error still sees
/// 30°), then to port (where the rules allow it: overtaking, or a stand-on
/// vessel that may act).
pub const ALTERATIONS_DEG: [f64; 12] = [
    0.0, 35.0, 45.0, 55.0, 65.0, 80.0, 90.0, -35.0, -45.0, -55.0, -65.0, -90.0,
];

/// How far the present course is held before heading for the goal, metres,
/// shortest first (the earliest valid return wins).
pub const HOLD_M: [f64; 10] = [
    250.0, 500.0, 1000.0, 1500.0, 2000.0, 3000.0, 4000.0, 6000.0, 8000.0, 12000.0,
];

/// The farthest index in `first..last` (where `last` is known unreachable)
/// that `attempt` accepts, by galloping then bisection.
fn farthest_reachable<F: Fn(usize) -> Option<SimplifiedLeg>>(
    first: usize,
    last: usize,
    attempt: &F,
) -> Option<(usize, SimplifiedLeg)> {
    // The first reachable point at or after `first`, within LOOK_PAST.
    let mut best = (first..last.min(first + LOOK_PAST + 1))
        .find_map(|index| attempt(index).map(|leg| (index, leg)))?;
    let mut unreachable = last;
    let mut stride = 1;
    // Gallop: double the stride while points stay reachable.
    loop {
        let probe = best.0 + stride;
        if probe >= unreachable {
            break;
        }
        if let Some(leg) = attempt(probe) {
            best = (probe, leg);
            stride *= 2;
        } else {
            unreachable = probe;
            break;
        }
    }
    // Bisect between the best reachable and the nearest known unreachable.
    while unreachable - best.0 > 1 {
        let probe = best.0 + (unreachable - best.0) / 2;
        match attempt(probe) {
            Some(leg) => best = (probe, leg),
            None => unreachable = probe,
        }
    }
    Some(best)
}

mod two;
pub use two::{STAND_ON_DRIFT_DEG, hold_then_alter, hold_then_alter_shorter_than};

#[cfg(test)]
mod tests;
