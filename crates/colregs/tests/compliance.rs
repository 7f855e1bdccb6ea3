//! Integration tests of compliance scoring on synthetic recorded encounters:
//! ownship (and, where a test says so, the target) follows a scripted plan of
//! course and speed changes; every other leg is at constant velocity.

use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::compliance::{
    ComplianceViolation, EncounterAssessment, EncounterSample, ScoringParameters, assess_encounter,
    first_latch, safety_score,
};
use vorrt_colregs::rules::in_contact;
use vorrt_colregs::{
    Duty, Encounter, EncounterLatch, OtherDuty, PassingSide, Role, RuleParameters, VesselState,
};

/// One leg of a plan: from `from_s` on, steer `course_deg` at `speed_mps`.
#[derive(Clone, Copy, Debug)]
struct Leg {
    from_s: f64,
    course_deg: f64,
    speed_mps: f64,
}

fn leg(from_s: f64, course_deg: f64, speed_mps: f64) -> Leg {
    Leg {
        from_s,
        course_deg,
        speed_mps,
    }
}

/// The leg in force at `time_s` (the last one that has begun).
fn leg_at(plan: &[Leg], time_s: f64) -> Leg {
    plan.iter()
        .rev()
        .find(|l| l.from_s <= time_s)
        .copied()
        .unwrap_or(plan[0])
}

/// Records both vessels every `step_s` from 0 to `duration_s`.
#[expect(
    clippy::cast_possible_truncation,
    reason = "test step counts and indices are small whole numbers"
)]
#[expect(
    clippy::cast_sign_loss,
    reason = "test step counts and indices are small whole numbers"
)]
#[expect(
    clippy::cast_precision_loss,
    reason = "test step counts and indices are small whole numbers"
)]
fn simulate(
    own_start_m: DVec2,
    own_plan: &[Leg],
    target_start_m: DVec2,
    target_plan: &[Leg],
    duration_s: f64,
    step_s: f64,
) -> Vec<EncounterSample> {
    let mut own = VesselState::new(own_start_m, 0.0, 0.0, 50.0);
    let mut target = VesselState::new(target_start_m, 0.0, 0.0, 80.0);
    let mut samples = Vec::new();
    let step_count = (duration_s / step_s).round() as usize;
    for step in 0..=step_count {
        let time_s = step as f64 * step_s;
        for (vessel, plan) in [(&mut own, own_plan), (&mut target, target_plan)] {
            let l = leg_at(plan, time_s);
            vessel.course_rad = l.course_deg.to_radians();
            vessel.speed_mps = l.speed_mps;
        }
        samples.push(EncounterSample::new(time_s, own, target));
        own = own.advanced(step_s);
        target = target.advanced(step_s);
    }
    samples
}

/// Latches as a planner would and assesses with default parameters.
fn assess(samples: &[EncounterSample]) -> EncounterAssessment {
    let rules = RuleParameters::default();
    let latch = first_latch(samples, &rules).expect("risk of collision arises");
    assess_encounter(samples, &latch, &rules, &ScoringParameters::default())
}

fn has(assessment: &EncounterAssessment, name: &str) -> bool {
    assessment.violations.iter().any(|v| v.name() == name)
}

/// Ownship north at 6 m/s from the origin; the target 9 km north heading south.
fn head_on(own_plan: &[Leg]) -> EncounterAssessment {
    assess(&simulate(
        DVec2::ZERO,
        own_plan,
        DVec2::new(0.0, 9000.0),
        &[leg(0.0, 180.0, 6.0)],
        1800.0,
        5.0,
    ))
}

/// Ownship north at 6 m/s; the target from the starboard bow heading west
/// at 6 m/s, `target_north_m` north and 3 km east of ownship.
fn crossing_from_starboard(own_plan: &[Leg], target_north_m: f64) -> EncounterAssessment {
    assess(&simulate(
        DVec2::ZERO,
        own_plan,
        DVec2::new(3000.0, target_north_m),
        &[leg(0.0, 270.0, 6.0)],
        1800.0,
        5.0,
    ))
}

/// Ownship north at 6 m/s; the target from the port bow heading east, and
/// giving way (turning to 150°) after one minute.
fn crossing_from_port(own_plan: &[Leg]) -> EncounterAssessment {
    assess(&simulate(
        DVec2::ZERO,
        own_plan,
        DVec2::new(-4000.0, 4000.0),
        &[leg(0.0, 90.0, 6.0), leg(60.0, 150.0, 6.0)],
        1800.0,
        5.0,
    ))
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn head_on_starboard_turn_is_compliant() {
    let a = head_on(&[
        leg(0.0, 0.0, 6.0),
        leg(60.0, 35.0, 6.0),
        leg(1200.0, 0.0, 6.0),
    ]);
    assert_eq!(a.encounter, Encounter::HeadOn);
    assert_eq!(a.role, Role::GiveWay);
    assert!(a.compliant && a.safe, "{:?}", a.violations);
    assert_eq!(a.passing_side, Some(PassingSide::Port));
    assert!(a.first_turn_rad.expect("turned") > 0.0);
    assert_eq!(a.scores.rule_14, Some(1.0));
    assert_eq!(a.scores.rule_16, Some(1.0));
    assert_eq!(a.scores.overall, 1.0);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn head_on_port_turn_is_named() {
    let a = head_on(&[
        leg(0.0, 0.0, 6.0),
        leg(60.0, -35.0, 6.0),
        leg(1200.0, 0.0, 6.0),
    ]);
    assert!(has(&a, "port_turn"), "{:?}", a.violations);
    assert!(has(&a, "starboard_to_starboard"), "{:?}", a.violations);
    assert_eq!(a.passing_side, Some(PassingSide::Starboard));
    assert!(a.first_turn_rad.expect("turned") < 0.0);
    assert!(!a.compliant);
    assert!(a.safe, "a port turn can be safe and still break rule 14");
    assert_eq!(a.scores.rule_14, Some(0.0));
    assert_eq!(a.scores.rule_16, Some(1.0));
    assert_eq!(a.scores.overall, 0.0);
}

#[test]
fn late_small_turn_is_late_and_not_apparent() {
    // Range about 960 m when ownship turns 10° to starboard.
    let a = head_on(&[leg(0.0, 0.0, 6.0), leg(670.0, 10.0, 6.0)]);
    assert!(has(&a, "late_action"), "{:?}", a.violations);
    assert!(has(&a, "action_not_apparent"), "{:?}", a.violations);
    let range = a.action_range_m.expect("acted");
    assert!((range - 960.0).abs() < 1.0, "{range}");
    let rule_16 = a.scores.rule_16.expect("give way");
    assert!(rule_16 > 0.0 && rule_16 < 1.0, "{rule_16}");
    assert!(!a.compliant);
}

#[test]
fn early_small_turn_is_only_not_apparent() {
    let a = head_on(&[leg(0.0, 0.0, 6.0), leg(60.0, 15.0, 6.0)]);
    assert!(has(&a, "action_not_apparent"), "{:?}", a.violations);
    assert!(!has(&a, "late_action"));
    // Half the apparent turn: half the not-apparent weight.
    assert!((a.scores.rule_16.expect("give way") - 0.75).abs() < 1e-9);
}

#[test]
fn halving_speed_is_apparent_action() {
    let a = head_on(&[leg(0.0, 0.0, 6.0), leg(60.0, 5.0, 3.0)]);
    assert!(!has(&a, "action_not_apparent"), "{:?}", a.violations);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn crossing_give_way_passing_astern_is_compliant() {
    let a = crossing_from_starboard(
        &[
            leg(0.0, 0.0, 6.0),
            leg(30.0, 60.0, 6.0),
            leg(1200.0, 0.0, 6.0),
        ],
        3000.0,
    );
    assert_eq!(a.encounter, Encounter::CrossingGiveWay);
    assert!(a.compliant && a.safe, "{:?}", a.violations);
    assert!(!a.crossed_ahead);
    assert_eq!(a.scores.rule_15, Some(1.0));
    assert_eq!(a.scores.overall, 1.0);
}

#[test]
fn crossing_give_way_holding_course_crosses_ahead() {
    // The target passes 150 m astern of ownship's track-crossing point.
    let a = crossing_from_starboard(&[leg(0.0, 0.0, 6.0)], 2850.0);
    assert_eq!(a.encounter, Encounter::CrossingGiveWay);
    assert!(a.crossed_ahead);
    let ahead = a.crossed_ahead_distance_m.expect("crossed");
    assert!((ahead - 150.0).abs() < 1.0, "{ahead}");
    assert!(has(&a, "crossed_ahead"), "{:?}", a.violations);
    assert!(has(&a, "clearance_violated"), "{:?}", a.violations);
    assert!(has(&a, "no_action"), "{:?}", a.violations);
    assert!(!has(&a, "collision"));
    assert!(!a.compliant && !a.safe);
    assert!((a.min_distance_m - 150.0 / 2f64.sqrt()).abs() < 1e-6);
    assert_eq!(a.scores.rule_15, Some(0.5));
    assert_eq!(a.scores.rule_16, Some(0.0));
    let safety = a.scores.safety;
    assert!(safety > 0.0 && safety < 1.0, "{safety}");
}

#[test]
fn crossing_give_way_port_turn_is_named() {
    let a = crossing_from_starboard(&[leg(0.0, 0.0, 6.0), leg(30.0, -60.0, 6.0)], 3000.0);
    assert!(has(&a, "port_turn"), "{:?}", a.violations);
    assert!(a.scores.rule_15.expect("crossing") < 1.0);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn stand_on_that_keeps_course_is_compliant() {
    let a = crossing_from_port(&[leg(0.0, 0.0, 6.0)]);
    assert_eq!(a.encounter, Encounter::CrossingStandOn);
    assert_eq!(a.role, Role::StandOn);
    assert!(a.compliant && a.safe, "{:?}", a.violations);
    assert_eq!(a.action_time_s, None);
    assert_eq!(a.scores.rule_17, Some(1.0));
    assert_eq!(a.scores.rule_16, None);
    assert_eq!(a.scores.overall, 1.0);
}

#[test]
fn stand_on_that_turns_early_changed_course() {
    let a = crossing_from_port(&[leg(0.0, 0.0, 6.0), leg(60.0, 30.0, 6.0)]);
    assert!(has(&a, "stand_on_course_changed"), "{:?}", a.violations);
    assert!(!has(&a, "stand_on_turned_to_port"));
    assert_eq!(a.scores.rule_17, Some(0.5));
    assert!(!a.compliant);
}

#[test]
fn stand_on_that_slows_early_changed_speed() {
    let a = crossing_from_port(&[leg(0.0, 0.0, 6.0), leg(60.0, 0.0, 3.0)]);
    assert!(has(&a, "stand_on_speed_changed"), "{:?}", a.violations);
    assert!(!has(&a, "stand_on_course_changed"));
}

#[test]
fn stand_on_turning_to_port_for_a_port_vessel_breaks_17c() {
    let a = crossing_from_port(&[leg(0.0, 0.0, 6.0), leg(60.0, -30.0, 6.0)]);
    assert!(has(&a, "stand_on_course_changed"), "{:?}", a.violations);
    assert!(has(&a, "stand_on_turned_to_port"), "{:?}", a.violations);
    assert_eq!(a.scores.rule_17, Some(0.0));
}

#[test]
fn stand_on_may_act_inside_the_action_range() {
    // Target holding course for a collision at (0, 4000) at t ≈ 667 s; ownship
    // turns to starboard at t = 400 s, when the range is about 2260 m, under
    // the 2 nm action range (rule 17(a)(ii), 17(b)).
    let samples = simulate(
        DVec2::ZERO,
        &[leg(0.0, 0.0, 6.0), leg(400.0, 60.0, 6.0)],
        DVec2::new(-4000.0, 4000.0),
        &[leg(0.0, 90.0, 6.0)],
        1800.0,
        5.0,
    );
    let a = assess(&samples);
    assert_eq!(a.encounter, Encounter::CrossingStandOn);
    assert!(a.compliant, "{:?}", a.violations);
    assert!(a.action_range_m.expect("acted") < 3704.0);
}

#[test]
fn overtaking_with_a_starboard_alteration_is_compliant() {
    let samples = simulate(
        DVec2::ZERO,
        &[
            leg(0.0, 0.0, 8.0),
            leg(30.0, 30.0, 8.0),
            leg(600.0, 0.0, 8.0),
        ],
        DVec2::new(0.0, 2000.0),
        &[leg(0.0, 0.0, 3.0)],
        1500.0,
        5.0,
    );
    let a = assess(&samples);
    assert_eq!(a.encounter, Encounter::Overtaking);
    assert!(a.compliant && a.safe, "{:?}", a.violations);
    assert_eq!(a.scores.rule_13, Some(1.0));
    assert_eq!((a.scores.rule_14, a.scores.rule_15), (None, None));
}

#[test]
fn overtaking_that_cuts_across_the_bow_crossed_ahead() {
    // Ownship comes up 150 m to port of the target, then turns across its bow
    // when abeam.
    let samples = simulate(
        DVec2::ZERO,
        &[leg(0.0, 0.0, 8.0), leg(400.0, 60.0, 8.0)],
        DVec2::new(150.0, 2000.0),
        &[leg(0.0, 0.0, 3.0)],
        1500.0,
        5.0,
    );
    let a = assess(&samples);
    assert_eq!(a.encounter, Encounter::Overtaking);
    assert!(has(&a, "crossed_ahead"), "{:?}", a.violations);
    assert!(a.scores.rule_13.expect("overtaking") < 1.0);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn a_closer_pass_never_scores_higher_safety() {
    // Head-on recordings without action at lateral offsets 0..600 m.
    let rules = RuleParameters::default();
    let scoring = ScoringParameters::default();
    let mut results: Vec<(f64, f64)> = (0..=60)
        .map(|i| {
            let offset = f64::from(i) * 10.0;
            let samples = simulate(
                DVec2::ZERO,
                &[leg(0.0, 0.0, 6.0)],
                DVec2::new(-offset, 9000.0),
                &[leg(0.0, 180.0, 6.0)],
                1500.0,
                5.0,
            );
            let latch = first_latch(&samples, &rules).expect("risk");
            let a = assess_encounter(&samples, &latch, &rules, &scoring);
            (a.min_distance_m, a.scores.safety)
        })
        .collect();
    results.sort_by(|a, b| a.0.total_cmp(&b.0));
    for pair in results.windows(2) {
        assert!(pair[0].1 <= pair[1].1, "{pair:?}");
    }
    assert_eq!(results[0].1, 0.0);
    assert_eq!(results[results.len() - 1].1, 1.0);
}

/// Head-on, neither vessel acting, both `length_m` long, the target offset
/// `offset_m` to port: the pass is exactly `offset_m` abeam.
fn head_on_pass(length_m: f64, offset_m: f64) -> EncounterAssessment {
    let mut samples = simulate(
        DVec2::ZERO,
        &[leg(0.0, 0.0, 6.0)],
        DVec2::new(-offset_m, 9000.0),
        &[leg(0.0, 180.0, 6.0)],
        1500.0,
        10.0,
    );
    for sample in &mut samples {
        sample.own.length_m = length_m;
        sample.target.length_m = length_m;
    }
    assess(&samples)
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn collision_is_hull_contact_from_the_lengths() {
    // The case: two 150 m ships passing 60 m apart touch (contact
    // range 150 m), far outside the scoring's zero-safety range of 25 m.
    let scoring = ScoringParameters::default();
    let a = head_on_pass(150.0, 60.0);
    assert!(
        (a.min_distance_m - 60.0).abs() < 1e-6,
        "{}",
        a.min_distance_m
    );
    assert!(a.min_distance_m > scoring.collision_m);
    assert!(has(&a, "collision"), "{:?}", a.violations);
    assert_eq!(a.scores.safety, 0.0);
    assert_eq!(a.scores.overall, 0.0);
    // Two 10 m boats 20 m apart do not touch (contact range 10 m), though
    // the pass is under the zero-safety range: no collision, safety 0.
    let a = head_on_pass(10.0, 20.0);
    assert!(a.min_distance_m < scoring.collision_m);
    assert!(!has(&a, "collision"), "{:?}", a.violations);
    assert!(has(&a, "clearance_violated"), "{:?}", a.violations);
    assert_eq!(a.scores.safety, 0.0);
    // Just outside contact for 150 m ships: no collision.
    assert!(!has(&head_on_pass(150.0, 151.0), "collision"));
}

#[test]
fn violations_serialise_with_their_kind() {
    let violation = ComplianceViolation::LateAction { range_m: 900.0 };
    assert!(violation.to_string().contains("rule 16"));
    assert_eq!(violation.rule(), Some(16));
    assert_eq!(violation.name(), "late_action");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Safety never increases as the minimum range shrinks, stays in [0, 1],
    /// and is 0 at or under the collision range.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn safety_is_monotone_and_bounded(a in 0.0..1000.0f64, b in 0.0..1000.0f64) {
        let scoring = ScoringParameters::default();
        let (near, far) = if a <= b { (a, b) } else { (b, a) };
        let (s_near, s_far) = (safety_score(near, &scoring), safety_score(far, &scoring));
        prop_assert!((0.0..=1.0).contains(&s_near) && (0.0..=1.0).contains(&s_far));
        prop_assert!(s_near <= s_far);
        if near <= scoring.collision_m {
            prop_assert_eq!(s_near, 0.0);
        }
    }

    /// Every score of any recorded encounter lies in [0, 1]; overall is never
    /// above safety or any applicable rule score; a minimum range under the
    /// zero-safety range gives safety 0 and overall 0; a collision is found
    /// exactly when the hulls touched, and scores 0.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn scores_always_lie_in_the_unit_interval(
        target_x in -6000.0..6000.0f64,
        target_y in -6000.0..6000.0f64,
        target_course in 0.0..360.0f64,
        target_speed in 0.0..10.0f64,
        own_speed in 1.0..10.0f64,
        turn_at in 0.0..1200.0f64,
        turn in -120.0..120.0f64,
        new_speed in 0.0..10.0f64,
        encounter_index in 0usize..6,
    ) {
        let rules = RuleParameters::default();
        let scoring = ScoringParameters::default();
        let samples = simulate(
            DVec2::ZERO,
            &[leg(0.0, 0.0, own_speed), leg(turn_at, turn, new_speed)],
            DVec2::new(target_x, target_y),
            &[leg(0.0, target_course, target_speed)],
            1500.0,
            10.0,
        );
        let latch = first_latch(&samples, &rules).unwrap_or_else(|| {
            EncounterLatch::new(Encounter::ALL[encounter_index], &samples[0].own, 0.0)
        });
        let a = assess_encounter(&samples, &latch, &rules, &scoring);
        let s = a.scores;
        let unit = |x: f64| (0.0..=1.0).contains(&x);
        prop_assert!(unit(s.safety) && unit(s.overall), "{:?}", s);
        for (rule, score) in s.applicable() {
            prop_assert!(unit(score), "rule {} scored {}", rule, score);
            prop_assert!(s.overall <= score + 1e-12);
        }
        prop_assert!(s.overall <= s.safety + 1e-12);
        prop_assert_eq!(a.compliant, a.violations.iter().all(|v| !v.is_rule_violation()));
        if a.min_distance_m < scoring.collision_m {
            prop_assert_eq!(s.safety, 0.0);
            prop_assert_eq!(s.overall, 0.0);
            prop_assert!(!a.safe);
        }
        // A collision is hull contact (50 m and 80 m hulls: 65 m), nothing else.
        let collided = in_contact(a.min_distance_m, 50.0, 80.0);
        prop_assert_eq!(a.violations.iter().any(|v| v.name() == "collision"), collided);
        if collided {
            prop_assert_eq!(s.safety, 0.0);
            prop_assert_eq!(s.overall, 0.0);
        }
    }

    /// A recording whose closest approach is forced under the collision range
    /// (the target's track passes through ownship's position at one instant)
    /// always scores safety 0.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn a_collision_scores_zero_safety(
        meet_at in 100.0..1000.0f64,
        target_course in 0.0..360.0f64,
        target_speed in 1.0..10.0f64,
        own_speed in 1.0..10.0f64,
    ) {
        let rules = RuleParameters::default();
        let scoring = ScoringParameters::default();
        // Both vessels reach the point (0, own_speed · meet_at) at meet_at.
        let meeting = DVec2::new(0.0, own_speed * meet_at);
        let target_start = meeting
            - vorrt_geometry::angle::velocity(target_course.to_radians(), target_speed) * meet_at;
        let samples = simulate(
            DVec2::ZERO,
            &[leg(0.0, 0.0, own_speed)],
            target_start,
            &[leg(0.0, target_course, target_speed)],
            1200.0,
            7.0,
        );
        let latch = first_latch(&samples, &rules)
            .unwrap_or_else(|| EncounterLatch::new(Encounter::HeadOn, &samples[0].own, 0.0));
        let a = assess_encounter(&samples, &latch, &rules, &scoring);
        prop_assert!(a.min_distance_m < 1e-6, "{}", a.min_distance_m);
        prop_assert_eq!(a.scores.safety, 0.0);
        prop_assert_eq!(a.scores.overall, 0.0);
        prop_assert!(a.violations.iter().any(|v| v.name() == "collision"));
    }
}

/// A stand-on vessel that also had to give way to another vessel (from 60 s
/// to 150 s) turned 30° to starboard then: holding that course afterwards is
/// keeping its course (rule 17(a)(i), the course last taken while free to
/// act), and turning back before the action range is changing it.
#[test]
fn stand_on_keeps_the_course_taken_while_giving_way_to_another() {
    let rules = RuleParameters::default();
    let judge = |own_plan: &[Leg]| {
        let samples = simulate(
            DVec2::ZERO,
            own_plan,
            DVec2::new(-4000.0, 4000.0),
            &[leg(0.0, 90.0, 6.0)],
            1800.0,
            5.0,
        );
        let giving_way: Vec<Option<OtherDuty>> = samples
            .iter()
            .map(|s| {
                (60.0..=150.0).contains(&s.time_s).then_some(OtherDuty {
                    vessel: 1,
                    encounter: Encounter::CrossingGiveWay,
                    duty: Duty::KeepOutOfTheWay,
                    range_m: 5000.0,
                })
            })
            .collect();
        let latch = first_latch(&samples, &rules).expect("risk of collision arises");
        assert_eq!(latch.encounter, Encounter::CrossingStandOn);
        vorrt_colregs::compliance::assess_encounter_acting(
            &samples,
            &latch,
            &rules,
            &ScoringParameters::default(),
            &giving_way,
        )
    };
    let held = judge(&[leg(0.0, 0.0, 6.0), leg(60.0, 30.0, 6.0)]);
    assert!(
        !has(&held, "stand_on_course_changed"),
        "{:?}",
        held.violations
    );
    let returned = judge(&[
        leg(0.0, 0.0, 6.0),
        leg(60.0, 30.0, 6.0),
        leg(200.0, 0.0, 6.0),
    ]);
    assert!(
        has(&returned, "stand_on_course_changed"),
        "{:?}",
        returned.violations
    );
}
