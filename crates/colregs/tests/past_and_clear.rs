//! "Past and clear" (rule 8(d): an alteration held "until the other vessel
//! is finally past and clear") for each encounter type, as
//! `has_passed` reads it (decision 44): the range opening, and then either
//! the range wider than `risk_cpa_m` (no risk any more), or the vessels
//! turned away from each other by more than `passed_angle_rad` (112.5°: the
//! other vessel 22.5° abaft the beam, the sternlight's sector of rule
//! 21(c)) — both of them in head-on and crossing, either in overtaking (the
//! overtaken vessel keeps pointing at the other).

use glam::DVec2;
use vorrt_colregs::{Encounter, RuleParameters, VesselState, has_passed};

fn own() -> VesselState {
    VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0)
}

fn target(east_m: f64, north_m: f64, course_deg: f64, speed_mps: f64) -> VesselState {
    VesselState::new(
        DVec2::new(east_m, north_m),
        course_deg.to_radians(),
        speed_mps,
        50.0,
    )
}

#[test]
fn head_on_is_past_once_abaft_the_beam_of_both_and_opening() {
    let rules = RuleParameters::default();
    let passed = |north_m| {
        has_passed(
            &own(),
            &target(-400.0, north_m, 180.0, 6.0),
            Encounter::HeadOn,
            &rules,
        )
    };
    // Still ahead, closing: not past.
    assert!(!passed(500.0));
    // Abeam: the range stops closing, neither is abaft the other's beam.
    assert!(!passed(0.0));
    // 10° abaft the beam: opening, but less than 22.5° abaft.
    assert!(!passed(-400.0 * (10f64).to_radians().tan()));
    // 30° abaft the beam of both: past and clear.
    assert!(passed(-400.0 * (30f64).to_radians().tan()));
}

#[test]
fn crossing_is_past_for_both_roles_once_astern_and_opening() {
    let rules = RuleParameters::default();
    for encounter in [Encounter::CrossingGiveWay, Encounter::CrossingStandOn] {
        // The other vessel heads west and has crossed ahead of ownship,
        // 600 m off: it is on ownship's port bow, ownship on its quarter.
        let ahead = target(-600.0, 600.0, 270.0, 6.0);
        assert!(
            !has_passed(&own(), &ahead, encounter, &rules),
            "{encounter:?}"
        );
        // Both have gone on: it lies abaft ownship's port beam.
        let astern = target(-1400.0, -900.0, 270.0, 6.0);
        assert!(
            has_passed(&own(), &astern, encounter, &rules),
            "{encounter:?}"
        );
    }
}

#[test]
fn overtaking_is_past_once_either_vessel_points_away() {
    let rules = RuleParameters::default();
    // Ownship at 6 m/s overtakes a vessel making 3 m/s 300 m to starboard.
    let slower = |north_m| target(300.0, north_m, 0.0, 3.0);
    // Abeam: not yet opening.
    assert!(!has_passed(
        &own(),
        &slower(0.0),
        Encounter::Overtaking,
        &rules
    ));
    // 30° abaft ownship's beam, the range opening: past, though the
    // overtaken vessel still points at ownship's side.
    let north_m = -300.0 * (30f64).to_radians().tan();
    assert!(has_passed(
        &own(),
        &slower(north_m),
        Encounter::Overtaking,
        &rules
    ));
    // The same pair judged from the overtaken vessel (it is being
    // overtaken): ownship now draws ahead of it.
    let fast = target(-300.0, -north_m, 0.0, 6.0);
    let slow_own = VesselState::new(DVec2::ZERO, 0.0, 3.0, 50.0);
    assert!(has_passed(
        &slow_own,
        &fast,
        Encounter::BeingOvertaken,
        &rules
    ));
    assert!(!has_passed(
        &slow_own,
        &target(-300.0, 0.0, 0.0, 6.0),
        Encounter::BeingOvertaken,
        &rules
    ));
}

#[test]
fn any_encounter_is_past_once_opening_beyond_the_risk_distance() {
    let rules = RuleParameters::default();
    let far = target(-1200.0, -1500.0, 180.0, 6.0);
    for encounter in [
        Encounter::HeadOn,
        Encounter::CrossingGiveWay,
        Encounter::CrossingStandOn,
        Encounter::Overtaking,
        Encounter::BeingOvertaken,
    ] {
        assert!(has_passed(&own(), &far, encounter, &rules), "{encounter:?}");
        // The same range, still closing, is not past.
        let closing = target(-1200.0, 1500.0, 180.0, 6.0);
        assert!(
            !has_passed(&own(), &closing, encounter, &rules),
            "{encounter:?}"
        );
    }
}
