//! Status, unfinished encounters and what a target did not report, on
//! recorded tracks (decisions 32 and 49).

use super::*;
use crate::encounter::Encounter;
use glam::DVec2;

/// Ownship north at 6 m/s from the origin for `duration_s`, and a target
/// meeting it head-on (or lying still 6 km ahead when `at_rest`).
fn recording(duration_s: f64, status: Option<NavigationalStatus>, at_rest: bool) -> Recording {
    let times_s: Vec<f64> = (0..1000)
        .map(|i| f64::from(i) * 10.0)
        .take_while(|t| *t <= duration_s)
        .collect();
    let track = |name: &str, start: DVec2, velocity: DVec2, status| RecordedTrack {
        name: name.into(),
        length_m: 100.0,
        positions_m: times_s.iter().map(|t| start + velocity * *t).collect(),
        courses_rad: None,
        observation: TrackObservation {
            position_noise_m: None,
            status,
            ..TrackObservation::default()
        },
    };
    let target_velocity = if at_rest {
        DVec2::ZERO
    } else {
        DVec2::new(0.0, -6.0)
    };
    Recording {
        ownship: track("ownship", DVec2::ZERO, DVec2::new(0.0, 6.0), None),
        targets: vec![track(
            "TS1",
            DVec2::new(100.0, 9000.0),
            target_velocity,
            status,
        )],
        times_s,
    }
}

#[test]
fn a_vessel_at_anchor_is_an_obstacle_not_an_encounter() {
    let judged = |status| {
        judge(
            &recording(1600.0, status, true),
            &ObservedParameters::default(),
        )
        .expect("valid")
    };
    let anchored = judged(Some(NavigationalStatus::AtAnchor));
    let target = &anchored.targets[0];
    assert!(target.latch.is_none(), "{:?}", target.latch);
    assert_eq!(target.status, Some(NavigationalStatus::AtAnchor));
    assert!(
        target
            .findings
            .iter()
            .any(|f| f.name() == "clearance_violated")
    );
    // The same still vessel, no status: an encounter (an observer sees a
    // vessel stopped in the water, under way).
    let unknown = judged(None);
    assert!(unknown.targets[0].latch.is_some());
}

#[test]
fn tracks_that_end_while_closing_are_undecided() {
    let parameters = ObservedParameters::default();
    // Head-on, 9 km apart at 12 m/s closing: the closest approach at 750 s.
    let cut = judge(&recording(600.0, None, false), &parameters).expect("valid");
    let target = &cut.targets[0];
    assert_eq!(
        target.latch.map(|latch| latch.encounter),
        Some(Encounter::HeadOn)
    );
    assert_eq!(target.undecided, Some(Undecided::StillClosing));
    let whole = judge(&recording(1200.0, None, false), &parameters).expect("valid");
    assert!(whole.targets[0].undecided.is_none());
}

#[test]
fn a_moored_vessel_making_way_is_no_encounter_and_undecided() {
    let parameters = ObservedParameters::default();
    // Reports moored but meets ownship head-on at 6 m/s (decision 49): no
    // latch, judged on clearance alone, undecided.
    let moving = judge(
        &recording(1600.0, Some(NavigationalStatus::Moored), false),
        &parameters,
    )
    .expect("valid");
    let target = &moving.targets[0];
    assert!(target.latch.is_none(), "{:?}", target.latch);
    assert!(
        target.findings.iter().all(|f| !f.is_rule_violation()),
        "{:?}",
        target.findings
    );
    match target.undecided {
        Some(Undecided::StatusContradictsMotion { status, speed_kn }) => {
            assert_eq!(status, NavigationalStatus::Moored);
            assert!((speed_kn - 11.66).abs() < 0.05, "{speed_kn}");
        }
        other => panic!("{other:?}"),
    }
    // Moored and still: a stationary obstacle, decided.
    let still = judge(
        &recording(1600.0, Some(NavigationalStatus::Moored), true),
        &parameters,
    )
    .expect("valid");
    assert!(still.targets[0].latch.is_none());
    assert!(still.targets[0].undecided.is_none());
    // Under way: the encounter as before.
    let under_way = judge(
        &recording(1600.0, Some(NavigationalStatus::UnderWayUsingEngine), false),
        &parameters,
    )
    .expect("valid");
    assert_eq!(
        under_way.targets[0].latch.map(|latch| latch.encounter),
        Some(Encounter::HeadOn)
    );
    assert!(under_way.targets[0].undecided.is_none());
}

#[test]
fn a_closest_approach_the_target_did_not_report_is_undecided() {
    let parameters = ObservedParameters::default();
    // Head-on, closest approach at 750 s; the target's last report at 600 s.
    let mut silent = recording(1600.0, None, false);
    silent.targets[0].observation.unreported = vec![Unreported {
        from_s: 660.0,
        to_s: 1600.0,
        last_fix_s: Some(600.0),
        next_fix_s: None,
    }];
    let judged = judge(&silent, &parameters).expect("valid");
    let target = &judged.targets[0];
    assert_eq!(
        target.latch.map(|latch| latch.encounter),
        Some(Encounter::HeadOn)
    );
    assert!(
        matches!(
            target.undecided,
            Some(Undecided::NotReported {
                closest_approach_unreported: true,
                ..
            })
        ),
        "{:?}",
        target.undecided
    );
    // Reports through the closest approach: decided.
    silent.targets[0].observation.unreported[0].from_s = 860.0;
    let judged = judge(&silent, &parameters).expect("valid");
    assert!(judged.targets[0].undecided.is_none());
}
