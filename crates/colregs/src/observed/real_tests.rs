//! Status and unfinished encounters on recorded tracks (decision 32).

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
    assert!(target.undecided);
    let whole = judge(&recording(1200.0, None, false), &parameters).expect("valid");
    assert!(!whole.targets[0].undecided);
}
