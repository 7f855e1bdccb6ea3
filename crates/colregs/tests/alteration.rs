//! Property tests of the give-way alteration rules with history (rules 8(b),
//! 14-16): until a readily apparent alteration has been made, no smaller one
//! is allowed; once it has, easing back is allowed by less than the
//! alteration made, while crossing ahead stays forbidden.

use proptest::prelude::*;
use vorrt_colregs::{
    CandidateMotion, Encounter, EncounterLatch, ManeuverViolation, RuleParameters, VesselState,
    check_alteration, check_motion, crosses_ahead,
};
use vorrt_geometry::{DVec2, angle};

fn give_way() -> impl Strategy<Value = Encounter> {
    prop_oneof![
        Just(Encounter::HeadOn),
        Just(Encounter::CrossingGiveWay),
        Just(Encounter::Overtaking),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Rule 16: before 30° has been made, an alteration between the
    /// detectable 2° and 30° is refused, whatever the side.
    #[test]
    fn small_alterations_are_refused_until_an_apparent_one(
        encounter in give_way(),
        reference in 0.0..std::f64::consts::TAU,
        turn_deg in 2.5..29.5f64,
        side in prop_oneof![Just(1.0), Just(-1.0)],
        altered_deg in 0.0..29.5f64,
    ) {
        let parameters = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, reference, 6.0, 50.0);
        let latch = EncounterLatch::new(encounter, &own, 0.0);
        let course = angle::normalize_2pi(reference + side * turn_deg.to_radians());
        prop_assert_eq!(
            check_alteration(&latch, altered_deg.to_radians(), course, &parameters),
            Err(ManeuverViolation::InsufficientAlteration)
        );
        // An apparent alteration, or none, is allowed.
        let apparent = angle::normalize_2pi(reference + side * 35f64.to_radians());
        prop_assert_eq!(check_alteration(&latch, altered_deg.to_radians(), apparent, &parameters), Ok(()));
        prop_assert_eq!(check_alteration(&latch, altered_deg.to_radians(), reference, &parameters), Ok(()));
    }

    /// Rules 14-16 with history: after a starboard alteration of at least
    /// 30°, a course to port of the reference by less than that alteration is
    /// not a port turn; one by more still is. Head-on, target far ahead.
    #[test]
    fn easing_back_is_bounded_by_the_alteration_made(
        altered_deg in 30.0..80.0f64,
        fraction in 0.05..0.95f64,
    ) {
        let parameters = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let latch = EncounterLatch::new(Encounter::HeadOn, &own, 0.0);
        // The target is far off to port and astern of ownship's beam, so the
        // passing side does not decide; only the turn does.
        let target_position = DVec2::new(-5000.0, -5000.0);
        let target_velocity = DVec2::new(0.0, -5.0);
        let altered = altered_deg.to_radians();
        let within = angle::normalize_2pi(-fraction * altered);
        let beyond = angle::normalize_2pi(-(altered + 5f64.to_radians()));
        let motion = |course| CandidateMotion::new(own.position_m, course, own.speed_mps);
        prop_assert_eq!(
            check_motion(&latch, &motion(within), target_position, target_velocity, &parameters, false, altered),
            Ok(())
        );
        prop_assert_eq!(
            check_motion(&latch, &motion(beyond), target_position, target_velocity, &parameters, false, altered),
            Err(ManeuverViolation::PortTurn)
        );
        // Without history the same easing back is a port turn.
        if fraction * altered > parameters.turn_tolerance_rad {
            prop_assert_eq!(
                check_motion(&latch, &motion(within), target_position, target_velocity, &parameters, false, 0.0),
                Err(ManeuverViolation::PortTurn)
            );
        }
    }

    /// Rule 15: whatever alteration has been made, crossing ahead of the
    /// stand-on vessel stays forbidden.
    #[test]
    fn crossing_ahead_stays_forbidden_after_altering(
        altered_deg in 30.0..90.0f64,
        course_deg in -60.0..60.0f64,
        target_east in 1000.0..6000.0f64,
        target_north in 1000.0..6000.0f64,
    ) {
        let parameters = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let latch = EncounterLatch::new(Encounter::CrossingGiveWay, &own, 0.0);
        let target_position = DVec2::new(target_east, target_north);
        let target_velocity = DVec2::new(-6.0, 0.0);
        let course = angle::normalize_2pi(course_deg.to_radians());
        let motion = CandidateMotion::new(own.position_m, course, own.speed_mps);
        let verdict = check_motion(
            &latch, &motion, target_position, target_velocity, &parameters, false, altered_deg.to_radians(),
        );
        if crosses_ahead(own.position_m, motion.velocity_mps, target_position, target_velocity) {
            prop_assert!(verdict.is_err(), "crossing ahead allowed: {:?}", verdict);
        }
    }
}
