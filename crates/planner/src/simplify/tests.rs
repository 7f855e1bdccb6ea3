//! Tests of the simplifier and the manoeuvre search.

use super::*;
use crate::plan::RejectionCause;
use std::cell::Cell;
use vorrt_jfs::RateLimitedTurn;

/// Refuses every leg from `start_m` but the one toward `first_m`, and
/// accepts every other leg; counts the legs it judges.
struct OnlyToFirst {
    start_m: DVec2,
    first_m: DVec2,
    judged: Cell<usize>,
}

impl MotionValidator for OnlyToFirst {
    fn validate(
        &self,
        leg: &Leg,
        _start_elapsed_s: f64,
        _state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        self.judged.set(self.judged.get() + 1);
        if leg.start_m.distance(self.start_m) < 1e-9 && leg.end_m().distance(self.first_m) > 1e-6 {
            Err(RejectionCause::Clearance)
        } else {
            Ok(())
        }
    }
}

/// Accepts holding the course north at 6 m/s, and any other leg only
/// from `from_north_m` on.
struct OnlyFarNorth {
    from_north_m: f64,
}

impl MotionValidator for OnlyFarNorth {
    #[expect(
        clippy::float_cmp,
        reason = "the hold is sailed at exactly the start's course and speed"
    )]
    fn validate(
        &self,
        leg: &Leg,
        _start_elapsed_s: f64,
        _state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        let holding_north = leg.turn_rad == 0.0 && leg.course_rad == 0.0 && leg.speed_mps == 6.0;
        if holding_north || leg.start_m.y >= self.from_north_m {
            Ok(())
        } else {
            Err(RejectionCause::Clearance)
        }
    }
}

#[test]
fn two_alterations_never_hold_a_course_past_the_goal() {
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let start = Pose {
        position_m: DVec2::ZERO,
        course_rad: 0.0,
    };
    let search = |goal_m: DVec2| {
        hold_then_alter(
            &model,
            &OnlyFarNorth {
                from_north_m: 6000.0,
            },
            start,
            Speeds::constant(6.0),
            goal_m,
            &EncounterState::default(),
        )
    };
    // With the goal 8 km ahead, the course is held 6 km, then the
    // smallest alteration, then the goal.
    let legs = search(DVec2::new(500.0, 8000.0)).expect("a manoeuvre");
    assert!((legs[0].leg.end_m().y - 6000.0).abs() < 1e-6);
    // With the goal 4 km ahead, the only valid manoeuvre holds the
    // course 2 km past it: none is offered.
    assert!(search(DVec2::new(500.0, 4000.0)).is_none());
}

#[test]
fn a_start_already_searched_is_not_searched_again_and_the_legs_are_the_same() {
    let first_m = DVec2::new(600.0, 1500.0);
    let points = [first_m, DVec2::new(0.0, 4000.0)];
    let start = Pose {
        position_m: DVec2::ZERO,
        course_rad: 0.0,
    };
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let run = |start_searched: bool| {
        let validator = OnlyToFirst {
            start_m: DVec2::ZERO,
            first_m,
            judged: Cell::new(0),
        };
        let legs = simplify_after(
            &model,
            &validator,
            start,
            Speeds::constant(6.0),
            &points,
            &EncounterState::default(),
            start_searched,
        );
        (legs, validator.judged.get())
    };
    let (searched, fresh) = (run(true), run(false));
    assert!(searched.0.is_some());
    assert_eq!(searched.0, fresh.0);
    // The leg to the goal and the first hold of each of the 24
    // alterations and speeds, refused at the start, are not judged again.
    assert_eq!(fresh.1 - searched.1, 1 + 24);
}

/// A vessel crossing from starboard on a collision course: ownship, north
/// at 6 m/s for a goal 20 km ahead, gives way (rule 15), holds its
/// alteration until the vessel is past and clear (rule 8(d)), and begins
/// its return then, not at the next hold of [`HOLD_M`] (decision 44).
#[test]
fn the_return_in_a_crossing_begins_once_the_vessel_is_past_and_clear() {
    use crate::PlannerConfig;
    use crate::safety::SafetyChecker;
    use vorrt_colregs::{Encounter, VesselState, has_passed, update_latch};
    use vorrt_jfs::TargetState;
    let config = PlannerConfig::default();
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    // West at 6 m/s, meeting ownship at (0, 4 km) after 667 s.
    let target = VesselState::new(DVec2::new(4000.0, 4000.0), 270f64.to_radians(), 6.0, 50.0);
    let tracks = [TargetState::constant_velocity(target).track()];
    let goal_m = DVec2::new(0.0, 20_000.0);
    let checker = SafetyChecker::new(&config, &tracks, own, goal_m, 0.0);
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let start = Pose {
        position_m: DVec2::ZERO,
        course_rad: 0.0,
    };
    // The encounter is in force from the start, as the closed loop has it.
    let latch = update_latch(None, &own, &target, 0.0, &config.rules);
    assert_eq!(
        latch.map(|latch| latch.encounter),
        Some(Encounter::CrossingGiveWay)
    );
    let state = EncounterState::new(vec![latch], vec![0.0]);
    let legs = simplify(
        &model,
        &checker,
        start,
        Speeds::constant(6.0),
        &[goal_m],
        &state,
    )
    .expect("a manoeuvre");
    let hold = &legs[0].leg;
    assert!(
        hold.course_rad > 30f64.to_radians(),
        "a starboard alteration"
    );
    // Past and clear as the rules judge it, along the hold.
    let passed_at = |elapsed_s: f64| {
        let pose = hold.pose_at(elapsed_s);
        let own = VesselState::new(pose.position_m, pose.course_rad, 6.0, 50.0);
        has_passed(
            &own,
            &tracks[0].state_at(elapsed_s),
            Encounter::CrossingGiveWay,
            &config.rules,
        )
    };
    let return_s = legs[0].end_elapsed_s;
    let described: Vec<String> = legs
        .iter()
        .map(|leg| {
            format!(
                "{:.0} deg {:.0} m to {:.0} s",
                leg.leg.course_rad.to_degrees(),
                leg.leg.length_m(),
                leg.end_elapsed_s
            )
        })
        .collect();
    let first_passed_s = (0..3000)
        .map(f64::from)
        .find(|&elapsed_s| passed_at(elapsed_s))
        .expect("passes within the hold");
    assert!(
        passed_at(return_s),
        "the return begins once past and clear: {described:?}, past from {first_passed_s} s"
    );
    // Within a few seconds of the moment it holds (here 5 s; the holds of
    // HOLD_M alone returned after the 4 km hold, about 110 s after it).
    assert!(
        return_s - first_passed_s < 45.0,
        "return at {return_s:.0} s, past and clear from {first_passed_s:.0} s"
    );
    assert!(legs.last().expect("legs").leg.end_m().distance(goal_m) < 1e-6);
}

/// Refuses, from `hold_end_m`, the leg to the goal as a port turn onto a
/// vessel, and every other leg from there for clearance: those to port of
/// the goal's bearing only, or (`every`) all of them (decision 61); records
/// the course and straight run of every leg it judges from there.
struct ReturnRefused {
    hold_end_m: DVec2,
    goal_m: DVec2,
    every: bool,
    judged: std::cell::RefCell<Vec<(f64, f64)>>,
}

impl ReturnRefused {
    fn new(hold_end_m: DVec2, goal_m: DVec2, every: bool) -> Self {
        Self {
            hold_end_m,
            goal_m,
            every,
            judged: std::cell::RefCell::new(Vec::new()),
        }
    }
}

impl MotionValidator for ReturnRefused {
    fn validate(
        &self,
        leg: &Leg,
        _start_elapsed_s: f64,
        _state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        if leg.start_m.distance(self.hold_end_m) > 1e-6 {
            return Ok(());
        }
        self.judged
            .borrow_mut()
            .push((leg.course_rad, leg.straight_m));
        let goal_course_rad = angle::unit_to_course(self.goal_m - self.hold_end_m);
        let off_rad = angle::normalize_pi(leg.course_rad - goal_course_rad);
        if leg.end_m().distance(self.goal_m) < 1e-6 {
            Err(RejectionCause::Colregs(
                ManeuverViolation::PortTurnTowardVessel,
            ))
        } else if self.every || off_rad < 0.0 {
            Err(RejectionCause::Clearance)
        } else {
            Ok(())
        }
    }
}

/// The fixture of the returns' tests: a 300 m turning radius, the goal
/// 12 km north, and 2 km held on 045 at 6 m/s from the origin with no
/// encounter in force, turned onto from `before_deg` (the course held
/// before the alteration).
fn held_2_km_on_045_from(before_deg: f64) -> (RateLimitedTurn, DVec2, SimplifiedLeg) {
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let hold = model.turn_onto(
        Pose {
            position_m: DVec2::ZERO,
            course_rad: before_deg.to_radians(),
        },
        45f64.to_radians(),
        6.0,
        2000.0,
    );
    let hold = SimplifiedLeg {
        end_elapsed_s: hold.duration_s(),
        leg: hold,
        state: EncounterState::default(),
    };
    (model, DVec2::new(0.0, 12_000.0), hold)
}

/// As [`held_2_km_on_045_from`], from 300°: every course astern of a vessel
/// ([`ASTERN_DEG`] to port of the goal's bearing, about 352°) is still to
/// starboard of the course held before the alteration.
fn held_2_km_on_045() -> (RateLimitedTurn, DVec2, SimplifiedLeg) {
    held_2_km_on_045_from(300.0)
}

/// Where the leg to the goal is refused for turning to port onto a vessel
/// and no course astern of it is valid, the return comes back part of the
/// way: a course short of the goal's bearing, held 2 km, then the goal
/// (without it, no return: a longer hold of the alteration was the only
/// way, decision 61).
#[test]
fn a_return_refused_for_a_port_vessel_comes_back_part_of_the_way() {
    let (model, goal_m, hold) = held_2_km_on_045();
    let validator = ReturnRefused::new(hold.leg.end_m(), goal_m, false);
    let back = return_to_goal(&model, &validator, &hold, Speeds::constant(6.0), goal_m)
        .expect("a return part of the way");
    assert_eq!(back.len(), 2);
    let goal_course_rad = angle::unit_to_course(goal_m - hold.leg.end_m());
    let short_of_deg = angle::normalize_pi(back[0].leg.course_rad - goal_course_rad).to_degrees();
    assert!(
        (short_of_deg - SHORT_OF_DEG[0]).abs() < 1e-6,
        "{short_of_deg}"
    );
    assert!((back[0].leg.straight_m - SHORT_OF_HOLD_M[0]).abs() < 1e-6);
    assert!(back[1].leg.end_m().distance(goal_m) < 1e-6);
}

#[test]
fn a_hold_that_ends_before_past_and_clear_searches_no_return_where_none_is_wanted() {
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let own = vorrt_colregs::VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    // A head-on encounter in force: ownship gives way, not yet past.
    let giving_way = EncounterState::new(
        vec![Some(vorrt_colregs::EncounterLatch::new(
            vorrt_colregs::Encounter::HeadOn,
            &own,
            0.0,
        ))],
        vec![0.0],
    );
    let from = SimplifiedLeg {
        leg: Leg::straight(DVec2::ZERO, 0.0, 0.0, 6.0),
        end_elapsed_s: 0.0,
        state: giving_way,
    };
    let start = Pose {
        position_m: DVec2::ZERO,
        course_rad: 0.0,
    };
    let hold = || model.turn_onto(start, 35f64.to_radians(), 6.0, 1000.0);
    let goal_m = DVec2::new(0.0, 5000.0);
    let speeds = Speeds::constant(6.0);
    // No leg starts where this one refuses: every leg is accepted, and counted.
    let counting = OnlyToFirst {
        start_m: DVec2::splat(1e9),
        first_m: DVec2::ZERO,
        judged: Cell::new(0),
    };
    // Wanted only past and clear: the hold is judged, no return searched.
    let outcome =
        hold::hold_and_return(&model, &counting, &from, hold(), 1.0, speeds, goal_m, true);
    assert!(matches!(outcome, hold::HoldOutcome::Refused));
    assert_eq!(counting.judged.get(), 1);
    // Otherwise the return is searched (here, the leg to the goal).
    let outcome =
        hold::hold_and_return(&model, &counting, &from, hold(), 1.0, speeds, goal_m, false);
    assert!(matches!(outcome, hold::HoldOutcome::Found(ref legs) if legs.len() == 2));
    assert_eq!(counting.judged.get(), 3);
}

/// A course astern of a vessel, or part of the way back, that is refused
/// for its shortest hold is not asked again held longer: the longer leg
/// sails the same pieces first, and is refused where the shorter one was.
#[test]
fn a_return_course_refused_is_not_asked_again_held_longer() {
    let (model, goal_m, hold) = held_2_km_on_045();
    let validator = ReturnRefused::new(hold.leg.end_m(), goal_m, true);
    assert!(return_to_goal(&model, &validator, &hold, Speeds::constant(6.0), goal_m).is_none());
    let judged = validator.judged.into_inner();
    // The leg to the goal, then each course astern and short of the goal's
    // bearing once, at its shortest hold.
    assert_eq!(
        judged.len(),
        1 + ASTERN_DEG.len() + SHORT_OF_DEG.len(),
        "{judged:?}"
    );
    for (index, (course_rad, straight_m)) in judged.iter().enumerate().skip(1) {
        assert!(
            judged[1..index]
                .iter()
                .all(|(other_rad, _)| (other_rad - course_rad).abs() > 1e-9),
            "{judged:?}"
        );
        let shortest_m = if index <= ASTERN_DEG.len() {
            ASTERN_HOLD_M[0]
        } else {
            SHORT_OF_HOLD_M[0]
        };
        assert!((straight_m - shortest_m).abs() < 1e-6, "{judged:?}");
    }
}

/// A course astern of a vessel that lies to port of the course held before
/// the alteration is not tried (decision 72): it would be a port
/// alteration from the course ownship acted on, for a vessel first met
/// head-on a starboard-to-starboard pass. Only the courses part of the way
/// back are, after the leg to the goal.
#[test]
fn no_course_astern_is_to_port_of_the_course_before_the_alteration() {
    // Held on 045 from 000: every course astern (some 336°, 321° and 306°)
    // is to port of 000.
    let (model, goal_m, hold) = held_2_km_on_045_from(0.0);
    let validator = ReturnRefused::new(hold.leg.end_m(), goal_m, true);
    assert!(return_to_goal(&model, &validator, &hold, Speeds::constant(6.0), goal_m).is_none());
    let judged = validator.judged.into_inner();
    assert_eq!(judged.len(), 1 + SHORT_OF_DEG.len(), "{judged:?}");
    let goal_course_rad = angle::unit_to_course(goal_m - hold.leg.end_m());
    for (course_rad, _) in &judged[1..] {
        assert!(
            angle::normalize_pi(course_rad - goal_course_rad) > 0.0,
            "{judged:?}"
        );
    }
    // From 315°: the first two (some 336° and 321°) are to starboard of it
    // and tried, the third (306°) is not.
    let (model, goal_m, hold) = held_2_km_on_045_from(315.0);
    let validator = ReturnRefused::new(hold.leg.end_m(), goal_m, true);
    assert!(return_to_goal(&model, &validator, &hold, Speeds::constant(6.0), goal_m).is_none());
    let judged = validator.judged.into_inner();
    let astern = judged[1..]
        .iter()
        .filter(|(course_rad, _)| {
            angle::normalize_pi(course_rad - angle::unit_to_course(goal_m - hold.leg.end_m())) < 0.0
        })
        .count();
    assert_eq!(astern, 2, "{judged:?}");
}

/// A validator of the legs' shape alone: `refuses` says which legs it
/// refuses (for clearance); it accepts every other.
struct RefusingWhere<F>(F);

impl<F: Fn(&Leg) -> bool> MotionValidator for RefusingWhere<F> {
    fn validate(
        &self,
        leg: &Leg,
        _start_elapsed_s: f64,
        _state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        if (self.0)(leg) {
            Err(RejectionCause::Clearance)
        } else {
            Ok(())
        }
    }
}

/// Refuses holding on at the start (course 080°).
fn no_holding_on() -> RefusingWhere<impl Fn(&Leg) -> bool> {
    RefusingWhere(|leg: &Leg| {
        leg.start_m.length() < 1e-9
            && angle::normalize_pi(leg.course_rad - 80f64.to_radians()).abs() < 1e-9
    })
}

/// Refuses, from the start, every leg onto a course within 90° of north
/// (the goal's bearing).
fn only_away() -> RefusingWhere<impl Fn(&Leg) -> bool> {
    RefusingWhere(|leg: &Leg| {
        leg.start_m.length() < 1e-9
            && angle::normalize_pi(leg.course_rad).to_degrees().abs() <= 90.0
    })
}

/// The manoeuvre search of the mariners' alterations (300 m turning radius,
/// 6 m/s) from the origin heading `course_deg`, toward a goal 10 km north,
/// with `validator`.
fn mariners_heading<V: MotionValidator>(
    validator: &V,
    course_deg: f64,
) -> Option<Vec<SimplifiedLeg>> {
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    let from = SimplifiedLeg {
        leg: Leg::straight(DVec2::ZERO, course_deg.to_radians(), 0.0, 6.0),
        end_elapsed_s: 0.0,
        state: EncounterState::default(),
    };
    alter_hold_return(
        &model,
        validator,
        &from,
        Speeds::constant(6.0),
        DVec2::new(0.0, 10_000.0),
        (Alterations::Mariners, f64::INFINITY),
    )
}

/// Heading 080° with the goal due north, every starboard alteration puts
/// the goal more than 22.5° abaft the beam: a port alteration toward it is
/// taken first (decision 68), where before the smallest starboard one (115°
/// off the goal) won its grade.
#[test]
fn a_course_that_puts_the_goal_abaft_the_beam_is_tried_last() {
    let legs = mariners_heading(&no_holding_on(), 80.0).expect("a manoeuvre");
    let altered_deg = angle::normalize_pi(legs[0].leg.course_rad - 80f64.to_radians()).to_degrees();
    assert!(altered_deg < 0.0, "{altered_deg}");
    let off_goal_deg = angle::normalize_pi(legs[0].leg.course_rad)
        .to_degrees()
        .abs();
    assert!(off_goal_deg <= 90.0, "{off_goal_deg}");
    // Where the only valid alterations turn away, one of them is taken.
    let legs = mariners_heading(&only_away(), 80.0).expect("a manoeuvre away");
    let off_goal_deg = angle::normalize_pi(legs[0].leg.course_rad)
        .to_degrees()
        .abs();
    assert!(off_goal_deg > 90.0, "{off_goal_deg}");
    // Heading 120°, the goal more than 22.5° abaft the beam, where no
    // course toward it is valid: holding on comes first of those away.
    let legs = mariners_heading(&only_away(), 120.0).expect("holding on, away");
    let held_deg = angle::normalize_pi(legs[0].leg.course_rad - 120f64.to_radians()).to_degrees();
    assert!(held_deg.abs() < 1e-9, "{held_deg}");
}

/// Heading 130° with the goal due north, every course toward the goal is a
/// port alteration whose return turns to port again: it is held at least
/// [`SHORT_OF_HOLD_M`]'s first, so that an observer sees two port turns and
/// not one (decision 68), where the shortest hold (250 m) won before.
#[test]
fn a_port_alteration_whose_return_turns_to_port_is_held_to_be_seen_as_two_turns() {
    let legs = mariners_heading(&no_holding_on(), 130.0).expect("a manoeuvre");
    let altered_deg =
        angle::normalize_pi(legs[0].leg.course_rad - 130f64.to_radians()).to_degrees();
    assert!(altered_deg < 0.0, "{altered_deg}");
    assert!(
        legs[0].leg.straight_m >= SHORT_OF_HOLD_M[0] - 1e-6,
        "{}",
        legs[0].leg.straight_m
    );
}
