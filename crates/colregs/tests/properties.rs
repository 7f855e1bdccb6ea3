//! Property tests of the COLREGs layer: encounter classification (rules
//! 13-15), its symmetries, the manoeuvre rules (14-17) and latching.

use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use vorrt_colregs::{
    Encounter, EncounterLatch, ManeuverViolation, RuleParameters, VesselState, check_maneuver,
    classify, crosses_ahead, update_latch,
};
use vorrt_geometry::{DVec2, angle, closest_point_of_approach};

/// Margin kept between a generated bearing and any sector boundary.
const BEARING_MARGIN_RAD: f64 = PI / 180.0;

/// Vessel length used throughout; classification does not depend on it.
const LENGTH_M: f64 = 60.0;

fn position() -> impl Strategy<Value = DVec2> {
    (-20_000.0..20_000.0f64, -20_000.0..20_000.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

fn any_angle() -> impl Strategy<Value = f64> {
    -2.0 * TAU..2.0 * TAU
}

fn speed() -> impl Strategy<Value = f64> {
    0.5..15.0f64
}

/// The relative bearings at which the default classifier changes its answer:
/// dead ahead, the head-on sector's edges, the stern sector's edges, astern.
fn sector_boundaries(parameters: &RuleParameters) -> [f64; 6] {
    [
        0.0,
        parameters.head_on_half_width_rad,
        TAU - parameters.head_on_half_width_rad,
        parameters.abaft_beam_rad,
        TAU - parameters.abaft_beam_rad,
        PI,
    ]
}

/// Whether a relative bearing is at least the margin away from every boundary.
fn clear_of_boundaries(bearing_rad: f64, parameters: &RuleParameters) -> bool {
    sector_boundaries(parameters)
        .iter()
        .all(|boundary| angle::signed_turn(*boundary, bearing_rad).abs() > BEARING_MARGIN_RAD)
}

/// Whether both bearings of the pair are clear of the boundaries and the
/// speeds are not (nearly) equal, so the classification is not decided by
/// rounding.
fn unambiguous(own: &VesselState, target: &VesselState, parameters: &RuleParameters) -> bool {
    clear_of_boundaries(own.bearing_to(target), parameters)
        && clear_of_boundaries(target.bearing_to(own), parameters)
        && (own.speed_mps - target.speed_mps).abs() > 0.1
}

/// A pair of vessels described by ownship's course, the target's bearing from
/// ownship (β) and ownship's bearing from the target (α). Half the cases put
/// both bearings near dead ahead so that head-on encounters come up often.
fn encounter_by_bearings() -> impl Strategy<Value = (VesselState, VesselState)> {
    let anywhere = (0.0..TAU, 0.0..TAU);
    let near_ahead = (-0.5..0.5f64, -0.5..0.5f64);
    (
        position(),
        any_angle(),
        prop_oneof![anywhere, near_ahead],
        100.0..15_000.0f64,
        speed(),
        speed(),
    )
        .prop_map(
            |(own_position, own_course, (beta, alpha), range_m, own_speed, target_speed)| {
                let target_position =
                    own_position + angle::course_to_unit(own_course + beta) * range_m;
                // Ownship lies at absolute direction own_course + β + π from the target.
                let target_course = angle::normalize_2pi(own_course + beta + PI - alpha);
                (
                    VesselState::new(own_position, own_course, own_speed, LENGTH_M),
                    VesselState::new(target_position, target_course, target_speed, LENGTH_M),
                )
            },
        )
}

/// A pair on (or very near) a collision course: both vessels would reach the
/// same point after `time_to_collision`, and the target is then offset across
/// the relative velocity by less than the line of sight can turn within the
/// bearing margin (so each vessel sees the other on the same side as on the
/// exact collision course).
fn converging_encounter() -> impl Strategy<Value = (VesselState, VesselState)> {
    (
        position(),
        any_angle(),
        speed(),
        any_angle(),
        speed(),
        60.0..3_000.0f64,
        -0.9..0.9f64,
    )
        .prop_filter_map(
            "relative velocity too small",
            |(own_position, own_course, own_speed, target_course, target_speed, time_s, offset)| {
                let own = VesselState::new(own_position, own_course, own_speed, LENGTH_M);
                let meeting_point = own_position + own.velocity_mps() * time_s;
                let mut target = VesselState::new(
                    meeting_point - angle::velocity(target_course, target_speed) * time_s,
                    target_course,
                    target_speed,
                    LENGTH_M,
                );
                let relative_velocity = own.velocity_mps() - target.velocity_mps();
                let relative_speed = relative_velocity.length();
                if relative_speed < 0.5 {
                    return None;
                }
                let range_m = relative_speed * time_s;
                // Also at most 1 % of the range: a near-collision course.
                let largest_offset_m = range_m
                    * (BEARING_MARGIN_RAD.sin() * own_speed.min(target_speed) / relative_speed)
                        .min(0.01);
                target.position_m +=
                    relative_velocity.perp() / relative_speed * offset * largest_offset_m;
                Some((own, target))
            },
        )
}

/// Mirror a vessel east-west: x -> -x, course c -> -c.
fn mirrored(vessel: &VesselState) -> VesselState {
    VesselState::new(
        DVec2::new(-vessel.position_m.x, vessel.position_m.y),
        angle::normalize_2pi(-vessel.course_rad),
        vessel.speed_mps,
        vessel.length_m,
    )
}

/// Rotate a vessel clockwise by `turn_rad` about the origin (its course turns
/// by the same amount), then shift it.
fn rotated_and_shifted(vessel: &VesselState, turn_rad: f64, shift_m: DVec2) -> VesselState {
    VesselState::new(
        DVec2::from_angle(-turn_rad).rotate(vessel.position_m) + shift_m,
        angle::normalize_2pi(vessel.course_rad + turn_rad),
        vessel.speed_mps,
        vessel.length_m,
    )
}

fn latch(
    encounter: Encounter,
    reference_course_rad: f64,
    reference_speed_mps: f64,
) -> EncounterLatch {
    EncounterLatch {
        encounter,
        reference_course_rad,
        reference_speed_mps,
        latched_at_s: 0.0,
        risk_distance_m: None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Rules 13-15 depend only on relative bearings and speeds: rotating and
    /// translating both vessels together leaves the encounter type unchanged.
    #[test]
    fn classification_is_invariant_under_rotation_and_translation(
        (own, target) in encounter_by_bearings(), turn in any_angle(), shift in position(),
    ) {
        let parameters = RuleParameters::default();
        prop_assume!(unambiguous(&own, &target, &parameters));
        let before = classify(&own, &target, &parameters);
        let after = classify(
            &rotated_and_shifted(&own, turn, shift),
            &rotated_and_shifted(&target, turn, shift),
            &parameters,
        );
        prop_assert_eq!(before, after);
    }

    /// Seen from the other vessel, a converging encounter swaps roles: give-way
    /// crossing <-> stand-on crossing (rule 15), overtaking <-> being overtaken
    /// (rule 13), head-on stays head-on (rule 14).
    #[test]
    fn swapping_converging_vessels_swaps_roles((own, target) in converging_encounter()) {
        let parameters = RuleParameters::default();
        prop_assume!(unambiguous(&own, &target, &parameters));
        let cpa = closest_point_of_approach(
            own.position_m, own.velocity_mps(), target.position_m, target.velocity_mps());
        prop_assert!(cpa.distance_m < 0.02 * own.range_to(&target));
        let from_own = classify(&own, &target, &parameters);
        let from_target = classify(&target, &own, &parameters);
        prop_assert_eq!(from_target, from_own.swapped(), "own sees {}", from_own);
    }

    /// Mirroring the picture east-west turns starboard into port: the crossing
    /// roles swap (rule 15), every other encounter type is kept.
    #[test]
    fn east_west_mirror_swaps_crossing_roles((own, target) in encounter_by_bearings()) {
        let parameters = RuleParameters::default();
        prop_assume!(unambiguous(&own, &target, &parameters));
        let before = classify(&own, &target, &parameters);
        let after = classify(&mirrored(&own), &mirrored(&target), &parameters);
        let expected = match before {
            Encounter::CrossingGiveWay => Encounter::CrossingStandOn,
            Encounter::CrossingStandOn => Encounter::CrossingGiveWay,
            other => other,
        };
        prop_assert_eq!(after, expected);
    }

    /// Rules 14(a) and 15/16: in head-on and give-way crossing, a course to
    /// port of the latch's reference course by more than the turn tolerance
    /// is never allowed.
    #[test]
    fn port_turn_is_never_allowed_in_head_on_or_give_way_crossing(
        head_on in any::<bool>(),
        reference_course in any_angle(), reference_speed in speed(),
        port_fraction in 0.0..1.0f64, candidate_speed in speed(),
        own_position in position(), target_position in position(),
        target_course in any_angle(), target_speed in speed(),
    ) {
        let parameters = RuleParameters::default();
        let encounter = if head_on { Encounter::HeadOn } else { Encounter::CrossingGiveWay };
        let smallest = parameters.turn_tolerance_rad + 1e-6;
        let largest = PI - 1e-6;
        let port_turn = smallest + port_fraction * (largest - smallest);
        let target = VesselState::new(target_position, target_course, target_speed, LENGTH_M);
        let verdict = check_maneuver(
            &latch(encounter, reference_course, reference_speed),
            own_position,
            reference_course - port_turn,
            candidate_speed,
            &target,
            &parameters,
        );
        prop_assert_eq!(verdict, Err(ManeuverViolation::PortTurn));
    }

    /// Rule 15: a give-way vessel shall avoid crossing ahead of the stand-on
    /// vessel. A velocity whose relative track meets the target's bow ray
    /// (`crosses_ahead`) is never allowed, whatever the reference course.
    #[test]
    fn crossing_ahead_is_never_allowed_when_giving_way(
        target_position in position(), target_course in any_angle(), target_speed in speed(),
        ahead_m in 10.0..10_000.0f64, relative_course in any_angle(),
        relative_speed in 0.5..25.0f64, time_s in 1.0..3_000.0f64,
        reference_course in any_angle(),
    ) {
        let parameters = RuleParameters::default();
        let target = VesselState::new(target_position, target_course, target_speed, LENGTH_M);
        let heading = angle::course_to_unit(target_course);
        let relative_velocity = angle::velocity(relative_course, relative_speed);
        // Not (nearly) parallel to the target's track, so the crossing is well defined.
        prop_assume!(heading.perp_dot(relative_velocity).abs() > 0.05 * relative_speed);
        // In the target's frame ownship reaches the bow ray `ahead_m` ahead after `time_s`.
        let own_position = target_position + heading * ahead_m - relative_velocity * time_s;
        let own_velocity = relative_velocity + target.velocity_mps();
        prop_assume!(own_velocity.length() > 0.1);
        let course = angle::unit_to_course(own_velocity);
        let speed = own_velocity.length();
        prop_assert!(crosses_ahead(
            own_position, angle::velocity(course, speed), target.position_m, target.velocity_mps()));
        let verdict = check_maneuver(
            &latch(Encounter::CrossingGiveWay, reference_course, speed),
            own_position,
            course,
            speed,
            &target,
            &parameters,
        );
        prop_assert!(verdict.is_err(), "crossing ahead allowed");
    }

    /// Rule 17(a)(i): before the give-way vessel is within the action range,
    /// the stand-on vessel keeps her course and speed: a course change beyond
    /// the tolerance, or a speed change beyond its tolerance, is rejected.
    #[test]
    fn stand_on_before_action_range_keeps_course_and_speed(
        being_overtaken in any::<bool>(),
        own_position in position(), reference_course in any_angle(), reference_speed in speed(),
        direction in any_angle(), beyond_m in 1.0..20_000.0f64,
        target_course in any_angle(), target_speed in speed(),
        turn_fraction in 0.0..1.0f64, to_starboard in any::<bool>(),
        speed_excess in 1e-6..5.0f64, faster in any::<bool>(),
    ) {
        let parameters = RuleParameters::default();
        let encounter =
            if being_overtaken { Encounter::BeingOvertaken } else { Encounter::CrossingStandOn };
        let range_m = parameters.stand_on_action_range_m + beyond_m;
        let target = VesselState::new(
            own_position + angle::course_to_unit(direction) * range_m,
            target_course,
            target_speed,
            LENGTH_M,
        );
        let latched = latch(encounter, reference_course, reference_speed);
        let smallest = parameters.stand_on_course_tolerance_rad + 1e-6;
        let turn = smallest + turn_fraction * (PI - 1e-6 - smallest);
        let course = if to_starboard { reference_course + turn } else { reference_course - turn };
        prop_assert_eq!(
            check_maneuver(&latched, own_position, course, reference_speed, &target, &parameters),
            Err(ManeuverViolation::StandOnCourseChange)
        );
        let change = parameters.stand_on_speed_tolerance_mps + speed_excess;
        let speed = if faster { reference_speed + change } else { (reference_speed - change).max(0.0) };
        prop_assume!((speed - reference_speed).abs() > parameters.stand_on_speed_tolerance_mps);
        prop_assert_eq!(
            check_maneuver(&latched, own_position, reference_course, speed, &target, &parameters),
            Err(ManeuverViolation::StandOnSpeedChange)
        );
        // Holding course and speed is always allowed.
        prop_assert_eq!(
            check_maneuver(&latched, own_position, reference_course, reference_speed, &target, &parameters),
            Ok(())
        );
    }

    /// Rule 17(c): once a stand-on vessel in a crossing may act, it still
    /// shall not alter course to port for a vessel on its own port side (the
    /// side as seen on the course it held, before the alteration).
    #[test]
    fn stand_on_never_turns_to_port_for_a_vessel_on_its_port_side(
        own_position in position(), reference_course in any_angle(), speed in speed(),
        port_bearing in (PI + 0.01)..(TAU - 0.01), range_fraction in 0.02..1.0f64,
        target_course in any_angle(), target_speed in speed(),
        port_fraction in 0.0..1.0f64,
    ) {
        let parameters = RuleParameters::default();
        let range_m = parameters.stand_on_action_range_m * range_fraction;
        let target = VesselState::new(
            own_position + angle::course_to_unit(reference_course + port_bearing) * range_m,
            target_course,
            target_speed,
            LENGTH_M,
        );
        let smallest = parameters.turn_tolerance_rad + 1e-6;
        let port_turn = smallest + port_fraction * (PI - 1e-6 - smallest);
        prop_assert_eq!(
            check_maneuver(
                &latch(Encounter::CrossingStandOn, reference_course, speed),
                own_position,
                reference_course - port_turn,
                speed,
                &target,
                &parameters,
            ),
            Err(ManeuverViolation::PortTurnForPortVessel)
        );
    }

    /// Latching (notes, "COLREGs geometry"): while the range is still closing
    /// the vessels have not passed, so a latched encounter is kept unchanged,
    /// however the geometry looks now.
    #[test]
    fn latch_holds_while_vessels_are_closing(
        encounter_index in 0..Encounter::ALL.len(),
        own_position in position(), own_course in any_angle(), own_speed in speed(),
        target_position in position(), target_course in any_angle(), target_speed in speed(),
        reference_course in any_angle(), time_s in 0.0..10_000.0f64,
    ) {
        let parameters = RuleParameters::default();
        let mut own = VesselState::new(own_position, own_course, own_speed, LENGTH_M);
        let mut target = VesselState::new(target_position, target_course, target_speed, LENGTH_M);
        let closing_rate = |own: &VesselState, target: &VesselState| {
            (target.position_m - own.position_m).dot(own.velocity_mps() - target.velocity_mps())
        };
        if closing_rate(&own, &target) < 0.0 {
            // Reversing both courses reverses the relative velocity.
            own.course_rad += PI;
            target.course_rad += PI;
        }
        prop_assume!(closing_rate(&own, &target) > 1e-6);
        let latched = latch(Encounter::ALL[encounter_index], reference_course, own_speed);
        prop_assert_eq!(
            update_latch(Some(latched), &own, &target, time_s, &parameters),
            Some(latched)
        );
    }

    /// A new latch takes the encounter type the classifier gives at the moment
    /// risk arises, with ownship's course and speed as its reference.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn new_latch_records_classification_and_reference((own, target) in converging_encounter()) {
        let parameters = RuleParameters::default();
        let encounter = classify(&own, &target, &parameters);
        if let Some(latched) = update_latch(None, &own, &target, 12.0, &parameters) {
            prop_assert_eq!(latched.encounter, encounter);
            prop_assert_eq!(latched.reference_course_rad, own.course_rad);
            prop_assert_eq!(latched.reference_speed_mps, own.speed_mps);
            prop_assert_eq!(latched.latched_at_s, 12.0);
        } else {
            let far = own.range_to(&target) >= parameters.mtd_m;
            prop_assert!(far || encounter == Encounter::None, "no latch for {}", encounter);
        }
    }
}

/// The steady-course search as first written over slices (before decision
/// 62), kept as the oracle of the search by index.
fn steady_course_over_slices(times_s: &[f64], courses_rad: &[f64], look_back_s: f64) -> f64 {
    use vorrt_colregs::rules::{STEADY_TURN_RATE_RAD_S, STEADY_TURN_SEARCH_S};
    let now_s = times_s[times_s.len() - 1];
    let mut index = times_s.len() - 1;
    while index > 0 && times_s[index - 1] >= now_s - look_back_s {
        index -= 1;
    }
    let search_from_s = times_s[index] - STEADY_TURN_SEARCH_S;
    while index > 0 && times_s[index - 1] >= search_from_s {
        let step_s = times_s[index] - times_s[index - 1];
        let turned = angle::signed_turn(courses_rad[index - 1], courses_rad[index]).abs();
        if turned <= STEADY_TURN_RATE_RAD_S * step_s + 1e-9 {
            break;
        }
        index -= 1;
    }
    courses_rad[index]
}

proptest! {
    /// The steady course over a history given by index, and over slices,
    /// is the search as first written, and asks no course twice (decision
    /// 62).
    #[test]
    fn the_steady_course_by_index_is_the_one_over_slices(
        steps in proptest::collection::vec((1.0f64..20.0, -0.05f64..0.05, 0u8..4), 1..80),
        look_back_s in 0.0f64..120.0,
    ) {
        use vorrt_colregs::rules::{steady_course_rad, steady_course_rad_of};
        let mut times_s = vec![0.0];
        let mut courses_rad = vec![1.0];
        for (step_s, turn_rad, held) in steps {
            times_s.push(times_s.last().copied().unwrap_or(0.0) + step_s);
            // Some steps hold the course exactly, as a steered course does.
            let turn = if held == 0 { 0.0 } else { turn_rad * step_s };
            courses_rad.push(courses_rad.last().copied().unwrap_or(0.0) + turn);
        }
        let mut asked = Vec::new();
        let by_index = steady_course_rad_of(
            times_s.len(),
            |i| times_s[i],
            |i| {
                asked.push(i);
                courses_rad[i]
            },
            look_back_s,
        );
        let oracle = steady_course_over_slices(&times_s, &courses_rad, look_back_s);
        prop_assert_eq!(by_index, Some(oracle));
        prop_assert_eq!(steady_course_rad(&times_s, &courses_rad, look_back_s), Some(oracle));
        let mut unique = asked.clone();
        unique.dedup();
        prop_assert_eq!(unique, asked);
    }
}
