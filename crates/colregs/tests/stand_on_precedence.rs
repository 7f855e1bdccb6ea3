//! Issue 24 item 4, decision 45: ownship stands on for a vessel overtaking
//! it from far astern (A) and gives way to a vessel meeting it head-on (B).
//! Its 35° alteration to starboard for B, made while A is still beyond the
//! stand-on action range, is justified by the duty to keep out of the way
//! of B (rules 16 and 2(b) over 17(a)(i)): the assessment of A names the
//! duty, the vessel and the rule, and finds nothing. The same alteration
//! without B is a finding.

use glam::DVec2;
use vorrt_colregs::geometry::angle;
use vorrt_colregs::observed::{
    ObservedJudgement, ObservedParameters, RecordedTrack, Recording, TrackObservation, judge,
};
use vorrt_colregs::{ComplianceViolation, Duty, Encounter, Role};

/// Time step of the recording, seconds.
const STEP_S: f64 = 5.0;
/// Ownship's speed, m/s (about 11.7 kn).
const SPEED_MPS: f64 = 6.0;
/// Ownship's rate of turn, degrees per second.
const RATE_DEG_S: f64 = 0.5;
/// When ownship alters 35° to starboard, seconds.
const ALTER_AT_S: f64 = 60.0;
/// The recording's length, steps (20 minutes).
const STEPS: u32 = 240;

fn times_s() -> Vec<f64> {
    (0..=STEPS).map(|step| f64::from(step) * STEP_S).collect()
}

/// Ownship: north, then 35° to starboard at [`ALTER_AT_S`] at
/// [`RATE_DEG_S`], held.
fn ownship() -> RecordedTrack {
    let mut position_m = DVec2::ZERO;
    let mut course_rad: f64 = 0.0;
    let (mut track_m, mut headings_rad) = (Vec::new(), Vec::new());
    for time_s in times_s() {
        track_m.push(position_m);
        headings_rad.push(course_rad);
        let command_rad = if time_s >= ALTER_AT_S {
            35f64.to_radians()
        } else {
            0.0
        };
        let limit = RATE_DEG_S.to_radians() * STEP_S;
        let turn = angle::signed_turn(course_rad, command_rad).clamp(-limit, limit);
        course_rad = angle::normalize_2pi(course_rad + turn);
        position_m += angle::velocity(course_rad, SPEED_MPS) * STEP_S;
    }
    RecordedTrack {
        name: "ownship".into(),
        length_m: 100.0,
        positions_m: track_m,
        courses_rad: Some(headings_rad),
        observation: TrackObservation::default(),
    }
}

/// A target sailing `course_deg` at `speed_mps` from `start_m`.
fn target(name: &str, start_m: DVec2, course_deg: f64, speed_mps: f64) -> RecordedTrack {
    let velocity = angle::velocity(course_deg.to_radians(), speed_mps);
    RecordedTrack {
        name: name.into(),
        length_m: 100.0,
        positions_m: times_s().iter().map(|t| start_m + velocity * *t).collect(),
        courses_rad: None,
        observation: TrackObservation::default(),
    }
}

/// A overtakes from 3.8 nm astern at 9 m/s (beyond the 2 nm action range
/// for the whole alteration); B, with `head_on`, meets ownship head-on
/// from 4.3 nm.
fn run(head_on: bool) -> ObservedJudgement {
    let mut targets = vec![target("A", DVec2::new(30.0, -7000.0), 0.0, 9.0)];
    if head_on {
        targets.push(target("B", DVec2::new(0.0, 8000.0), 180.0, SPEED_MPS));
    }
    let recording = Recording {
        ownship: ownship(),
        targets,
        times_s: times_s(),
    };
    judge(&recording, &ObservedParameters::default()).expect("a valid recording")
}

fn stand_on_course_changed(judgement: &ObservedJudgement) -> bool {
    judgement.targets[0]
        .findings
        .iter()
        .any(|finding| matches!(finding, ComplianceViolation::StandOnCourseChanged { .. }))
}

#[test]
fn altering_for_a_vessel_given_way_to_names_the_duty_and_is_no_finding() {
    let judgement = run(true);
    let a = judgement.targets[0].assessment.as_ref().expect("A latched");
    assert_eq!(a.encounter, Encounter::BeingOvertaken);
    assert_eq!(a.role, Role::StandOn);
    let b = judgement.targets[1].assessment.as_ref().expect("B latched");
    assert_eq!(b.encounter, Encounter::HeadOn);
    assert!(!stand_on_course_changed(&judgement), "{:?}", a.violations);
    let [departure] = a.stand_on_departures.as_slice() else {
        panic!("one departure: {:?}", a.stand_on_departures);
    };
    assert!(departure.range_m > 2.0 * 1852.0, "{departure:?}");
    assert!(
        departure.course_change_rad > 15f64.to_radians(),
        "{departure:?}"
    );
    let precedence = departure.precedence.as_ref().expect("justified");
    assert_eq!(precedence.duty, Duty::KeepOutOfTheWay);
    assert_eq!(precedence.rule, "16, 2(b)");
    assert_eq!(precedence.vessel_name, "B");
    assert_eq!(precedence.encounter, Encounter::HeadOn);
}

#[test]
fn the_same_alteration_without_a_vessel_to_give_way_to_is_a_finding() {
    let judgement = run(false);
    let a = judgement.targets[0].assessment.as_ref().expect("A latched");
    assert_eq!(a.role, Role::StandOn);
    assert!(stand_on_course_changed(&judgement), "{:?}", a.violations);
    let [departure] = a.stand_on_departures.as_slice() else {
        panic!("one departure: {:?}", a.stand_on_departures);
    };
    assert!(departure.precedence.is_none(), "{departure:?}");
    assert!(departure.range_m > 2.0 * 1852.0, "{departure:?}");
}
