//! Synthetic tracks whose verdict is obvious to a mariner, each asserted.

use super::*;
use crate::encounter::Encounter;
use glam::DVec2;
use proptest::prelude::*;
use vorrt_geometry::angle;

/// Time step of the synthetic recordings, seconds.
const STEP_S: f64 = 5.0;

/// A vessel of the synthetic runs: state and a steering law giving the
/// commanded course (degrees) from the time, its own and the other's
/// position.
struct Sailor<'a> {
    position_m: DVec2,
    course_rad: f64,
    speed_mps: f64,
    rate_deg_s: f64,
    steer: Box<dyn Fn(f64, DVec2, DVec2) -> f64 + 'a>,
    /// The commanded speed from the time, m/s (`None`: the speed held).
    throttle: Option<Box<dyn Fn(f64) -> f64 + 'a>>,
    /// How fast the speed follows the command, m/s².
    speed_change_mps2: f64,
}

impl<'a> Sailor<'a> {
    fn new(
        x_m: f64,
        y_m: f64,
        course_deg: f64,
        speed_mps: f64,
        steer: impl Fn(f64, DVec2, DVec2) -> f64 + 'a,
    ) -> Self {
        Self {
            position_m: DVec2::new(x_m, y_m),
            course_rad: course_deg.to_radians(),
            speed_mps,
            rate_deg_s: 1.0,
            steer: Box::new(steer),
            throttle: None,
            speed_change_mps2: 0.05,
        }
    }

    fn holding(x_m: f64, y_m: f64, course_deg: f64, speed_mps: f64) -> Self {
        Self::new(x_m, y_m, course_deg, speed_mps, move |_, _, _| course_deg)
    }

    fn throttle(mut self, throttle: impl Fn(f64) -> f64 + 'a) -> Self {
        self.throttle = Some(Box::new(throttle));
        self
    }

    fn rate(mut self, rate_deg_s: f64) -> Self {
        self.rate_deg_s = rate_deg_s;
        self
    }

    /// One step: turn toward the commanded course at the rate limit, then
    /// sail the step on the new course.
    fn step(&mut self, time_s: f64, other_m: DVec2) {
        let command = (self.steer)(time_s, self.position_m, other_m).to_radians();
        let turn = angle::signed_turn(self.course_rad, command);
        let limit = self.rate_deg_s.to_radians() * STEP_S;
        self.course_rad = angle::normalize_2pi(self.course_rad + turn.clamp(-limit, limit));
        if let Some(throttle) = &self.throttle {
            let change = throttle(time_s) - self.speed_mps;
            let limit = self.speed_change_mps2 * STEP_S;
            self.speed_mps += change.clamp(-limit, limit);
        }
        self.position_m += angle::velocity(self.course_rad, self.speed_mps) * STEP_S;
    }
}

/// Sails ownship and one target for `duration_s`; records both (ownship's
/// courses recorded, the target's positions only).
fn sail(mut own: Sailor<'_>, mut target: Sailor<'_>, duration_s: f64) -> Recording {
    let mut times_s = Vec::new();
    let (mut own_m, mut own_courses, mut target_m) = (Vec::new(), Vec::new(), Vec::new());
    let mut now_s = 0.0;
    while now_s <= duration_s {
        times_s.push(now_s);
        own_m.push(own.position_m);
        own_courses.push(own.course_rad);
        target_m.push(target.position_m);
        let (own_before, target_before) = (own.position_m, target.position_m);
        own.step(now_s, target_before);
        target.step(now_s, own_before);
        now_s += STEP_S;
    }
    Recording {
        times_s,
        ownship: RecordedTrack {
            name: "ownship".into(),
            length_m: 100.0,
            positions_m: own_m,
            courses_rad: Some(own_courses),
            observation: TrackObservation::default(),
        },
        targets: vec![RecordedTrack {
            name: "TS1".into(),
            length_m: 100.0,
            positions_m: target_m,
            courses_rad: None,
            observation: TrackObservation::default(),
        }],
    }
}

fn judged(recording: &Recording) -> ObservedJudgement {
    judge(recording, &ObservedParameters::default()).expect("valid")
}

fn findings(judgement: &ObservedJudgement) -> Vec<&'static str> {
    judgement.targets[0]
        .findings
        .iter()
        .map(crate::ComplianceViolation::name)
        .collect()
}

/// Head-on at 6 m/s each from 12 km: ownship's steering law.
fn head_on(own_steer: impl Fn(f64, DVec2, DVec2) -> f64) -> ObservedJudgement {
    judged(&sail(
        Sailor::new(0.0, 0.0, 0.0, 6.0, own_steer),
        Sailor::holding(0.0, 12_000.0, 180.0, 6.0),
        2000.0,
    ))
}

#[test]
fn head_on_early_starboard_turn_held_until_past_has_no_finding() {
    // Risk arises near 9.3 km (MTD); ownship turns 35° to starboard at
    // 240 s (about 9 km) and holds it until the target is abaft, then returns.
    let judgement = head_on(|time_s, own, target| {
        if time_s >= 240.0 && target.y > own.y {
            35.0
        } else {
            0.0
        }
    });
    let target = &judgement.targets[0];
    assert_eq!(target.latch.expect("risk").encounter, Encounter::HeadOn);
    assert!(judgement.compliant, "{:?}", findings(&judgement));
    assert!(target.findings.is_empty(), "{:?}", findings(&judgement));
    let assessment = target.assessment.as_ref().expect("assessed");
    assert!(assessment.action_range_m.expect("acted") > 2.0 * 1852.0);
    assert!(assessment.max_course_change_rad.to_degrees() > 30.0);
    assert!(assessment.first_turn_rad.expect("turned") > 0.0);
    assert_eq!(judgement.path.turn_reversals, 1);
    assert!((judgement.path.max_turn_rate_deg_s - 1.0).abs() < 1e-9);
}

#[test]
fn head_on_same_turn_begun_at_one_mile_is_late() {
    let judgement = head_on(|_, own: DVec2, target: DVec2| {
        if own.distance(target) < 1852.0 && target.y > own.y {
            35.0
        } else {
            0.0
        }
    });
    assert!(
        findings(&judgement).contains(&"late_action"),
        "{:?}",
        findings(&judgement)
    );
    assert!(!judgement.compliant);
}

#[test]
fn head_on_port_turn_is_a_finding() {
    let judgement = head_on(|time_s, own, target| {
        if time_s >= 240.0 && target.y > own.y {
            -35.0
        } else {
            0.0
        }
    });
    assert!(
        findings(&judgement).contains(&"port_turn"),
        "{:?}",
        findings(&judgement)
    );
}

#[test]
#[expect(
    clippy::cast_possible_truncation,
    reason = "test step counts and indices are small whole numbers"
)]
fn head_on_zig_zag_of_small_alterations_breaks_rule_8b() {
    // 10° to starboard and back every 90 s: each alteration detectable,
    // none readily apparent.
    let judgement = head_on(|time_s, _, _| {
        if time_s >= 240.0 && ((time_s - 240.0) / 90.0).floor() as i64 % 2 == 0 {
            10.0
        } else {
            0.0
        }
    });
    let names = findings(&judgement);
    assert!(names.contains(&"small_alterations"), "{names:?}");
    assert!(names.contains(&"action_not_apparent"), "{names:?}");
    assert!(judgement.path.turn_reversals >= 4);
}

#[test]
fn head_on_alteration_eased_back_before_the_closest_approach_is_not_held() {
    // 35° at 240 s, back to 0 at 600 s while still closing.
    let judgement = head_on(|time_s, _, _| {
        if (240.0..600.0).contains(&time_s) {
            35.0
        } else {
            0.0
        }
    });
    assert!(
        findings(&judgement).contains(&"alteration_not_held"),
        "{:?}",
        findings(&judgement)
    );
}

/// Head-on at 6 m/s each from 16 km (8.6 nm, beyond MTD), as a DNV
/// trafficgen situation begins: ownship's steering law.
fn head_on_from_beyond_mtd(own_steer: impl Fn(f64, DVec2, DVec2) -> f64) -> ObservedJudgement {
    judged(&sail(
        Sailor::new(0.0, 0.0, 0.0, 6.0, own_steer),
        Sailor::holding(0.0, 16_000.0, 180.0, 6.0),
        2400.0,
    ))
}

/// Decision 73, the pattern of trafficgen runs 179-199 before decision 72:
/// ownship alters 40° to starboard at once, 8.6 nm off a vessel met
/// head-on, then at 500 s swings 80° to port across her bow to 40° port
/// of its first course and passes her starboard to starboard. Latched only
/// within MTD, on the course then steered, the swing went unseen; judged
/// from the course held before the first turn, it is a head-on encounter
/// passed starboard to starboard (rule 14(a)).
#[test]
fn a_swing_to_port_across_the_bow_of_a_vessel_met_head_on_beyond_mtd_is_a_finding() {
    let judgement =
        head_on_from_beyond_mtd(|time_s, _, _| if time_s < 500.0 { 40.0 } else { -40.0 });
    let target = &judgement.targets[0];
    let latch = target.latch.expect("early action latches");
    assert_eq!(latch.encounter, Encounter::HeadOn);
    assert!(latch.reference_course_rad.abs() < 1e-9);
    assert!(latch.latched_at_s < 60.0, "{}", latch.latched_at_s);
    let names = findings(&judgement);
    assert!(names.contains(&"starboard_to_starboard"), "{names:?}");
    assert!(!judgement.compliant);
}

/// The same early alteration held until the vessel is abaft, then the
/// return: judged from the course held before it, and no finding.
#[test]
fn an_early_alteration_beyond_mtd_held_until_past_has_no_finding() {
    let judgement = head_on_from_beyond_mtd(
        |_, own, target| {
            if target.y > own.y - 500.0 { 40.0 } else { 0.0 }
        },
    );
    let target = &judgement.targets[0];
    let latch = target.latch.expect("early action latches");
    assert_eq!(latch.encounter, Encounter::HeadOn);
    assert!(latch.latched_at_s < 60.0, "{}", latch.latched_at_s);
    assert!(target.findings.is_empty(), "{:?}", findings(&judgement));
}

/// A vessel ownship would stand on for is not latched early: a turn made
/// beyond MTD, before risk of collision exists, keeps a stand-on
/// situation from arising and is no departure from rule 17.
#[test]
fn an_early_turn_for_a_vessel_crossing_from_port_is_no_stand_on_departure() {
    // From port, 10 km west and 10 km north, heading east; ownship turns
    // 60° to starboard at once and holds it.
    let judgement = judged(&sail(
        Sailor::new(0.0, 0.0, 0.0, 6.0, |_, _, _| 60.0),
        Sailor::holding(-10_000.0, 10_000.0, 90.0, 6.0),
        2400.0,
    ));
    let target = &judgement.targets[0];
    assert!(
        target
            .latch
            .is_none_or(|latch| latch.encounter != Encounter::CrossingStandOn),
        "{:?}",
        target.latch
    );
    assert!(target.findings.is_empty(), "{:?}", findings(&judgement));
}

/// Crossing from starboard: the target 6 km east and `north_m` north,
/// heading west at 6 m/s; ownship north at 6 m/s.
fn crossing(own_steer: impl Fn(f64, DVec2, DVec2) -> f64, north_m: f64) -> ObservedJudgement {
    judged(&sail(
        Sailor::new(0.0, 0.0, 0.0, 6.0, own_steer),
        Sailor::holding(6000.0, north_m, 270.0, 6.0),
        2400.0,
    ))
}

#[test]
fn crossing_astern_is_compliant_and_ahead_is_not() {
    let astern = crossing(
        |time_s, _, _| if time_s >= 30.0 { 60.0 } else { 0.0 },
        6000.0,
    );
    assert_eq!(
        astern.targets[0].latch.expect("risk").encounter,
        Encounter::CrossingGiveWay
    );
    assert!(astern.compliant, "{:?}", findings(&astern));
    // Holding course with the target 1.5 km later: ownship crosses its bow
    // (within the 1 nm of decision 42); the pass, 1.06 km, was clear of d_th,
    // so no action was owed.
    let ahead = crossing(|_, _, _| 0.0, 4500.0);
    assert_eq!(
        ahead.targets[0].latch.expect("risk").encounter,
        Encounter::CrossingGiveWay
    );
    let names = findings(&ahead);
    assert_eq!(names, vec!["crossed_ahead"]);
}

#[test]
fn crossing_give_way_by_halving_speed_early_is_readily_apparent() {
    // On a collision course (both at (0, 6 km) at 1000 s), ownship holds its
    // course and slows from 6 to 3 m/s from 30 s on (at 0.05 m/s²): the
    // target passes about 1.9 km ahead. The speed halved is the action:
    // begun early, readily apparent, held until past.
    let halving = |time_s: f64| if time_s >= 30.0 { 3.0 } else { 6.0 };
    let judgement = judged(&sail(
        Sailor::holding(0.0, 0.0, 0.0, 6.0).throttle(halving),
        Sailor::holding(6000.0, 6000.0, 270.0, 6.0),
        2400.0,
    ));
    let target = &judgement.targets[0];
    assert_eq!(
        target.latch.expect("risk").encounter,
        Encounter::CrossingGiveWay
    );
    assert!(judgement.compliant, "{:?}", findings(&judgement));
    let assessment = target.assessment.as_ref().expect("assessed");
    assert!(assessment.action_range_m.expect("acted") > 2.0 * 1852.0);
    // Slowing by a third is seen as an action, but not a readily apparent one.
    let third = |time_s: f64| if time_s >= 30.0 { 4.0 } else { 6.0 };
    let judgement = judged(&sail(
        Sailor::holding(0.0, 0.0, 0.0, 6.0).throttle(third),
        Sailor::holding(6000.0, 6000.0, 270.0, 6.0),
        2400.0,
    ));
    assert!(
        findings(&judgement).contains(&"action_not_apparent"),
        "{:?}",
        findings(&judgement)
    );
}

/// Crossing from port: the target 6 km west and north heading east, giving
/// way (turning to 150°) after one minute; ownship north at 6 m/s.
fn stand_on(own_steer: impl Fn(f64, DVec2, DVec2) -> f64) -> ObservedJudgement {
    judged(&sail(
        Sailor::new(0.0, 0.0, 0.0, 6.0, own_steer),
        Sailor::new(-6000.0, 6000.0, 90.0, 6.0, |time_s, _, _| {
            if time_s >= 60.0 { 150.0 } else { 90.0 }
        }),
        2400.0,
    ))
}

#[test]
fn stand_on_holding_has_no_finding_and_turning_to_port_breaks_17() {
    let holding = stand_on(|_, _, _| 0.0);
    assert_eq!(
        holding.targets[0].latch.expect("risk").encounter,
        Encounter::CrossingStandOn
    );
    assert!(holding.compliant, "{:?}", findings(&holding));
    let port = stand_on(|time_s, _, _| if time_s >= 120.0 { -40.0 } else { 0.0 });
    let names = findings(&port);
    assert!(names.contains(&"stand_on_turned_to_port"), "{names:?}");
    assert!(names.contains(&"stand_on_course_changed"), "{names:?}");
}

#[test]
fn a_turn_faster_than_the_vessel_can_is_reported() {
    let recording = sail(
        Sailor::new(
            0.0,
            0.0,
            0.0,
            6.0,
            |time_s, _, _| if time_s >= 100.0 { 90.0 } else { 0.0 },
        )
        .rate(3.0),
        Sailor::holding(50_000.0, 0.0, 0.0, 6.0),
        600.0,
    );
    let limited = ObservedParameters {
        max_turn_rate_rad_s: Some(1f64.to_radians()),
        ..ObservedParameters::default()
    };
    let judgement = judge(&recording, &limited).expect("valid");
    assert!((judgement.path.max_turn_rate_deg_s - 3.0).abs() < 1e-9);
    assert!(
        matches!(
            judgement.track_findings.as_slice(),
            [TrackFinding::TurnRateExceeded { limit_deg_s, .. }] if (*limit_deg_s - 1.0).abs() < 1e-9
        ),
        "{:?}",
        judgement.track_findings
    );
    assert!(!judgement.compliant);
    // Within the limit of a nimbler vessel: no finding.
    let nimble = ObservedParameters {
        max_turn_rate_rad_s: Some(3f64.to_radians()),
        ..ObservedParameters::default()
    };
    let judgement = judge(&recording, &nimble).expect("valid");
    assert!(judgement.track_findings.is_empty());
    assert!(judgement.compliant);
}

#[test]
fn a_malformed_recording_is_an_error_naming_the_vessel() {
    let mut recording = sail(
        Sailor::holding(0.0, 0.0, 0.0, 6.0),
        Sailor::holding(0.0, 9000.0, 180.0, 6.0),
        100.0,
    );
    recording.targets[0].positions_m.pop();
    let message = judge(&recording, &ObservedParameters::default())
        .expect_err("short track")
        .to_string();
    assert!(message.contains("TS1"), "{message}");
    recording.targets.clear();
    recording.times_s[1] = recording.times_s[0];
    let message = judge(&recording, &ObservedParameters::default())
        .expect_err("time does not advance")
        .to_string();
    assert!(message.contains("times_s[1]"), "{message}");
}

#[test]
fn the_window_shortens_at_the_start_and_holds_a_stopped_course() {
    let times = [0.0, 10.0, 20.0, 30.0];
    let positions = [
        DVec2::ZERO,
        DVec2::new(0.0, 50.0),
        DVec2::new(50.0, 50.0),
        DVec2::new(50.0, 50.0),
    ];
    let observed = over_ground(&times, &positions, 60.0);
    assert!((observed[0].course_rad - 0.0).abs() < 1e-12);
    assert!((observed[0].speed_mps - 5.0).abs() < 1e-12);
    // Over the 20 s available: 50 m north, 50 m east.
    assert!((observed[2].course_rad.to_degrees() - 45.0).abs() < 1e-9);
    // The 30 s window still sees the 50 m north and 50 m east.
    assert!((observed[3].course_rad.to_degrees() - 45.0).abs() < 1e-9);
    // A vessel that never moves: course carried over, speed 0.
    let still = over_ground(&times, &[DVec2::ZERO; 4], 60.0);
    assert!(
        still
            .iter()
            .all(|o| o.speed_mps == 0.0 && o.course_rad == 0.0)
    );
}

#[test]
fn small_counter_moves_do_not_split_an_episode() {
    let rules = crate::RuleParameters::default();
    let deg = |d: &[f64]| d.iter().map(|x| x.to_radians()).collect::<Vec<_>>();
    // A 1.5° wobble inside a starboard turn: one episode.
    assert_eq!(
        turn_episodes(&deg(&[0.0, 10.0, 8.5, 20.0]), &rules).len(),
        1
    );
    // A 3° counter-move: three episodes, two reversals.
    assert_eq!(turn_reversals(&deg(&[0.0, 10.0, 7.0, 20.0]), &rules), 2);
    // Across north, the short way round.
    let across = turn_episodes(&deg(&[350.0, 10.0, 350.0]), &rules);
    assert_eq!(across.len(), 2);
    assert!((across[0].change_rad.to_degrees() - 20.0).abs() < 1e-9);
}

proptest! {
    #[test]
    #[expect(clippy::cast_precision_loss, reason = "test step counts and indices are small whole numbers")]
    fn observed_course_of_a_straight_track_is_its_course(
        course_deg in 0.0f64..360.0,
        speed_mps in 0.5f64..15.0,
        step_s in 1.0f64..20.0,
        window_s in 5.0f64..180.0,
        samples in 2usize..80,
    ) {
        let velocity = angle::velocity(course_deg.to_radians(), speed_mps);
        let times: Vec<f64> = (0..samples).map(|i| i as f64 * step_s).collect();
        let positions: Vec<DVec2> = times.iter().map(|t| DVec2::new(100.0, -50.0) + velocity * *t).collect();
        for observed in over_ground(&times, &positions, window_s) {
            let error = angle::signed_turn(course_deg.to_radians(), observed.course_rad).abs();
            prop_assert!(error < 1e-9, "{} vs {course_deg}", observed.course_rad.to_degrees());
            prop_assert!((observed.speed_mps - speed_mps).abs() < 1e-9);
        }
    }

    #[test]
    #[expect(clippy::cast_possible_truncation, reason = "test step counts and indices are small whole numbers")]
    #[expect(clippy::cast_sign_loss, reason = "test step counts and indices are small whole numbers")]
    #[expect(clippy::cast_precision_loss, reason = "test step counts and indices are small whole numbers")]
    fn rate_of_turn_of_a_constant_rate_arc_is_the_rate(
        rate_deg_s in 0.05f64..3.0,
        speed_mps in 1.0f64..15.0,
        step_s in 1.0f64..10.0,
        start_deg in 0.0f64..360.0,
    ) {
        // Sailed for up to 120°: positions exactly on the circle.
        let rate = rate_deg_s.to_radians();
        let samples = ((120f64.to_radians() / rate / step_s) as usize).clamp(3, 400);
        let times: Vec<f64> = (0..samples).map(|i| i as f64 * step_s).collect();
        let radius = speed_mps / rate;
        let start = start_deg.to_radians();
        let courses: Vec<f64> = times.iter().map(|t| start + rate * t).collect();
        // Centre to starboard of the start; position = centre + radius * (turned left normal).
        let centre = angle::course_to_unit(start + std::f64::consts::FRAC_PI_2) * radius;
        let positions: Vec<DVec2> = courses
            .iter()
            .map(|c| centre - angle::course_to_unit(c + std::f64::consts::FRAC_PI_2) * radius)
            .collect();
        let rules = crate::RuleParameters::default();
        let recorded = path_quality(&times, &positions, &courses, &rules);
        prop_assert!((recorded.max_turn_rate_deg_s - rate_deg_s).abs() < 1e-6 * rate_deg_s.max(1.0));
        prop_assert_eq!(recorded.turn_reversals, 0);
        // From the observed COG (a chord of the arc): the same rate once the
        // window is full, half of it while the window grows.
        let observed: Vec<f64> = over_ground(&times, &positions, 60.0).iter().map(|o| o.course_rad).collect();
        let from_cog = path_quality(&times, &positions, &observed, &rules);
        prop_assert!(from_cog.max_turn_rate_deg_s <= rate_deg_s * (1.0 + 1e-6));
        prop_assert!(from_cog.max_turn_rate_deg_s >= 0.5 * rate_deg_s * (1.0 - 1e-6));
    }
}

/// The pattern of trafficgen run 185 before decision 74: ownship alters
/// 35° to starboard at once, 8.6 nm off a vessel met head-on, then at
/// 400 s, still closing, eases back to 10°. Latched early (decision 73)
/// part way round the turn, the pass predicted on the course then steered
/// looked clear and no action was owed, not even to be held; predicted on
/// the course held, the alteration was owed and not held (decision 75).
#[test]
fn an_early_alteration_eased_back_while_closing_is_not_held() {
    let judgement =
        head_on_from_beyond_mtd(|time_s, _, _| if time_s < 400.0 { 35.0 } else { 10.0 });
    let latch = judgement.targets[0].latch.expect("early action latches");
    assert_eq!(latch.encounter, Encounter::HeadOn);
    assert!(latch.reference_course_rad.abs() < 1e-9);
    assert!(
        findings(&judgement).contains(&"alteration_not_held"),
        "{:?}",
        findings(&judgement)
    );
}
