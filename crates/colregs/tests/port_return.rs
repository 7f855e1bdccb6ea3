//! Issue 24: the return toward the goal after a starboard alteration swings
//! to port onto a vessel crossing from port, and ownship then stands on. The
//! encounter with that vessel is latched only on the new course, where it is
//! a stand-on encounter; the port turn that made it is what an observer
//! sees, and the evaluation must find it
//! (`rules::is_port_turn_toward_vessel`).

use glam::DVec2;
use vorrt_colregs::Encounter;
use vorrt_colregs::geometry::angle;
use vorrt_colregs::observed::{
    ObservedJudgement, ObservedParameters, RecordedTrack, Recording, judge,
};

/// Time step of the recording, seconds.
const STEP_S: f64 = 5.0;
/// Ownship's and the targets' speed, m/s (about 11.7 kn).
const SPEED_MPS: f64 = 6.0;
/// Ownship's rate of turn, degrees per second.
const RATE_DEG_S: f64 = 0.5;
/// When ownship alters 35° to starboard for the vessel crossing from
/// starboard (4.9 nm off), seconds.
const ALTER_AT_S: f64 = 100.0;
/// The recording's length, steps (40 minutes).
const STEPS: u32 = 480;
/// The recording's length, seconds.
const DURATION_S: f64 = STEPS as f64 * STEP_S;

/// Ownship's track: north, 35° to starboard at [`ALTER_AT_S`], then back
/// to `return_course_deg` at `return_at_s`, each turn at [`RATE_DEG_S`];
/// positions and courses at every step.
fn ownship(return_at_s: f64, return_course_deg: f64) -> (Vec<DVec2>, Vec<f64>) {
    let mut position_m = DVec2::ZERO;
    let mut course_rad: f64 = 0.0;
    let mut track = (Vec::new(), Vec::new());
    for step in 0..=STEPS {
        let time_s = f64::from(step) * STEP_S;
        track.0.push(position_m);
        track.1.push(course_rad);
        let command_deg = if time_s >= return_at_s {
            return_course_deg
        } else if time_s >= ALTER_AT_S {
            35.0
        } else {
            0.0
        };
        let turn = angle::signed_turn(course_rad, command_deg.to_radians());
        let limit = RATE_DEG_S.to_radians() * STEP_S;
        course_rad = angle::normalize_2pi(course_rad + turn.clamp(-limit, limit));
        position_m += angle::velocity(course_rad, SPEED_MPS) * STEP_S;
    }
    track
}

fn times_s() -> Vec<f64> {
    (0..=STEPS).map(|step| f64::from(step) * STEP_S).collect()
}

/// A target sailing `course_deg` at [`SPEED_MPS`] from `start_m`.
fn target(name: &str, start_m: DVec2, course_deg: f64) -> RecordedTrack {
    let velocity = angle::velocity(course_deg.to_radians(), SPEED_MPS);
    RecordedTrack {
        name: name.into(),
        length_m: 100.0,
        positions_m: times_s().iter().map(|t| start_m + velocity * *t).collect(),
        courses_rad: None,
        observation: vorrt_colregs::observed::TrackObservation::default(),
    }
}

/// When ownship turns back toward its goal in the run of issue 24, steps.
const RETURN_AT_STEP: u32 = 240;
/// When ownship turns back toward its goal in the run of issue 24, seconds.
const RETURN_AT_S: f64 = RETURN_AT_STEP as f64 * STEP_S;
/// Where the return to 357° ends: 38° at 0.5°/s (76 s, 16 steps), on the
/// step after.
const TURN_END_STEP: usize = RETURN_AT_STEP as usize + 17;

/// The run of issue 24: TS1 crosses from starboard on a collision course
/// with ownship's first course (ownship gives way with 35° to starboard at
/// 4.9 nm and holds it until TS1 is past); TS2 crosses from port, heading
/// east, and passes 1.1 nm clear of the altered course. At `return_at_s`
/// ownship turns back to `return_course_deg`: with 357° at [`RETURN_AT_S`]
/// (38° to port) TS2, 2.8 nm off its port bow when the turn ends, is
/// brought onto a collision course, to be crossed ahead of.
fn run(return_at_s: f64, return_course_deg: f64) -> ObservedJudgement {
    let (positions_m, courses_rad) = ownship(return_at_s, return_course_deg);
    // TS2 is placed by the return to 357° at RETURN_AT_S, whichever track
    // is sailed, 2.8 nm off the port bow where that turn ends.
    let crossing_at_s = times_s()[TURN_END_STEP];
    let ts2_start = ownship(RETURN_AT_S, 357.0).0[TURN_END_STEP] + DVec2::new(-4000.0, 3300.0)
        - DVec2::new(SPEED_MPS * crossing_at_s, 0.0);
    let recording = Recording {
        ownship: RecordedTrack {
            name: "ownship".into(),
            length_m: 100.0,
            positions_m,
            courses_rad: Some(courses_rad),
            observation: vorrt_colregs::observed::TrackObservation::default(),
        },
        targets: vec![
            target("TS1", DVec2::new(7000.0, 7000.0), 270.0),
            target("TS2", ts2_start, 90.0),
        ],
        times_s: times_s(),
    };
    judge(&recording, &ObservedParameters::default()).expect("a valid recording")
}

fn names(judgement: &ObservedJudgement, index: usize) -> Vec<&'static str> {
    judgement.targets[index]
        .findings
        .iter()
        .map(vorrt_colregs::ComplianceViolation::name)
        .collect()
}

#[test]
fn a_return_to_port_onto_a_vessel_crossing_from_port_is_a_finding() {
    let judgement = run(RETURN_AT_S, 357.0);
    let ts1 = &judgement.targets[0];
    assert_eq!(
        ts1.latch.map(|latch| latch.encounter),
        Some(Encounter::CrossingGiveWay)
    );
    assert!(ts1.compliant, "TS1: {:?}", ts1.findings);
    let ts2 = &judgement.targets[1];
    // Latched on the new course, TS2 is a vessel ownship stands on for ...
    assert_eq!(
        ts2.latch.map(|latch| latch.encounter),
        Some(Encounter::CrossingStandOn)
    );
    assert!(ts2.min_distance_m < 1852.0, "{}", ts2.min_distance_m);
    // ... but the port turn that made it one is what TS2 saw.
    assert!(
        names(&judgement, 1).contains(&"port_turn_toward_vessel"),
        "TS2: {:?}",
        ts2.findings
    );
    assert!(!ts2.compliant);
    assert!(!judgement.compliant);
}

#[test]
fn holding_the_alteration_until_the_vessel_from_port_is_past_is_no_finding() {
    // Held on 035° (no return): TS2 passes 1.1 nm clear ahead and no
    // port turn is made.
    let judgement = run(DURATION_S + 1.0, 357.0);
    assert!(judgement.compliant, "{:?}", judgement.targets);
    // The same return to 357°, 15 minutes later, once TS2 has crossed
    // ahead of the altered course: a port turn, but onto no risk.
    let judgement = run(RETURN_AT_S + 900.0, 357.0);
    assert!(
        !names(&judgement, 1).contains(&"port_turn_toward_vessel"),
        "TS2: {:?}",
        judgement.targets[1].findings
    );
}

/// TS2's track for [`run_19`]: heading east at [`SPEED_MPS`] from `start_m`;
/// from `gives_way_at_s`, if any, it turns 35° to starboard at 1°/s, the
/// give-way action of a vessel that obeys the rules.
fn crossing_from_port(start_m: DVec2, gives_way_at_s: Option<f64>) -> RecordedTrack {
    let mut here_m = start_m;
    let mut course_rad = 90f64.to_radians();
    let mut positions_m = Vec::new();
    for time_s in times_s() {
        positions_m.push(here_m);
        if gives_way_at_s.is_some_and(|at_s| time_s >= at_s) {
            let limit = 1f64.to_radians() * STEP_S;
            course_rad += angle::signed_turn(course_rad, 125f64.to_radians()).clamp(-limit, limit);
        }
        here_m += angle::velocity(course_rad, SPEED_MPS) * STEP_S;
    }
    RecordedTrack {
        name: "TS2".into(),
        length_m: 100.0,
        positions_m,
        courses_rad: None,
        observation: vorrt_colregs::observed::TrackObservation::default(),
    }
}

/// Where the return to 330° of [`run_19`] ends: 65° at 0.5°/s (130 s, 26
/// steps), on the step after.
const RETURN_19_END_STEP: usize = RETURN_AT_STEP as usize + 27;

/// The pattern of open-sea run 19 (2 targets, seed 11): ownship, altered to
/// starboard, comes back to port, to 330°, with TS2 crossing from port
/// 5.2 nm off the bow where the turn ends, just beyond the MTD; held on,
/// TS2 would cross about 810 m ahead of ownship (ownship passing astern of
/// it), where on 035° it would pass 2.4 nm off; `gives_way_at_s`: TS2
/// answers with 35° to starboard then, as a COLREGs-obeying vessel did in
/// run 19 just as risk arose.
fn run_19(gives_way_at_s: Option<f64>) -> ObservedJudgement {
    let (positions_m, courses_rad) = ownship(RETURN_AT_S, 330.0);
    let ts2_start = positions_m[RETURN_19_END_STEP] + DVec2::new(-7900.0, 5500.0)
        - DVec2::new(SPEED_MPS * crossing_at_s(), 0.0);
    let recording = Recording {
        ownship: RecordedTrack {
            name: "ownship".into(),
            length_m: 100.0,
            positions_m,
            courses_rad: Some(courses_rad),
            observation: vorrt_colregs::observed::TrackObservation::default(),
        },
        targets: vec![
            target("TS1", DVec2::new(7000.0, 7000.0), 270.0),
            crossing_from_port(ts2_start, gives_way_at_s),
        ],
        times_s: times_s(),
    };
    judge(&recording, &ObservedParameters::default()).expect("a valid recording")
}

/// When the return of [`run_19`] ends, seconds.
fn crossing_at_s() -> f64 {
    times_s()[RETURN_19_END_STEP]
}

#[test]
fn a_return_onto_a_vessel_from_port_is_a_finding_whichever_vessel_would_cross_ahead() {
    // Decision 51. TS2 keeps on: it would cross ahead of ownship, inside
    // 1 nm. The return made it a collision course all the same (it was
    // none on 035°), and made ownship the stand-on vessel of a new
    // crossing: a finding (before, none: ownship passed astern).
    let kept_on = run_19(None);
    let ts2 = &kept_on.targets[1];
    assert_eq!(
        ts2.latch.map(|latch| latch.encounter),
        Some(Encounter::CrossingStandOn)
    );
    assert!(ts2.min_distance_m < 1852.0, "{}", ts2.min_distance_m);
    assert!(
        names(&kept_on, 1).contains(&"port_turn_toward_vessel"),
        "TS2: {:?}",
        ts2.findings
    );
    // TS2 gives way to starboard as risk arises, as it did in run 19: the
    // same turn of ownship, the same finding (before, a finding only here,
    // where TS2's turn, half seen at the latch, put ownship ahead of it).
    for gives_way_at_s in [crossing_at_s() + 30.0, crossing_at_s() + 60.0] {
        let answered = run_19(Some(gives_way_at_s));
        assert!(
            names(&answered, 1).contains(&"port_turn_toward_vessel"),
            "TS2 giving way at {gives_way_at_s} s: {:?}",
            answered.targets[1].findings
        );
    }
}
