//! Issue 23, item 3: rules read as a mariner reads them on tracks recorded
//! at sea (decision 42). Straight tracks whose verdict is obvious, each
//! asserted with the finding it must or must not bring.

use super::*;
use crate::encounter::Encounter;
use glam::DVec2;

/// Two vessels in straight, steady motion, sampled every 10 s for
/// `duration_s`: ownship from `own_m` at `own_mps`, the target from
/// `target_m` at `target_mps`; 100 m each; positions only.
fn straight(
    own_m: DVec2,
    own_mps: DVec2,
    target_m: DVec2,
    target_mps: DVec2,
    duration_s: f64,
) -> Recording {
    let times_s: Vec<f64> = (0..=10_000)
        .map(|i| f64::from(i) * 10.0)
        .take_while(|t| *t <= duration_s)
        .collect();
    let track = |name: &str, start: DVec2, velocity: DVec2| RecordedTrack {
        name: name.into(),
        length_m: 100.0,
        positions_m: times_s.iter().map(|t| start + velocity * *t).collect(),
        courses_rad: None,
        observation: TrackObservation::default(),
    };
    Recording {
        ownship: track("ownship", own_m, own_mps),
        targets: vec![track("TS1", target_m, target_mps)],
        times_s: times_s.clone(),
    }
}

fn judged_with(recording: &Recording, parameters: &ObservedParameters) -> ObservedEncounter {
    judge(recording, parameters).expect("valid").targets[0].clone()
}

fn names(target: &ObservedEncounter) -> Vec<&'static str> {
    target
        .findings
        .iter()
        .map(crate::ComplianceViolation::name)
        .collect()
}

/// Ownship north at 3 m/s holds course across the bow of a vessel crossing
/// from starboard at 12 m/s westward, `ahead_m` ahead of her bow when it
/// crosses her heading line (3 km north of ownship's start).
fn slow_crossing_ahead_of_fast(ahead_m: f64) -> Recording {
    // Ownship reaches y = 3000 m at 1000 s; the target is then ahead_m east.
    straight(
        DVec2::ZERO,
        DVec2::new(0.0, 3.0),
        DVec2::new(ahead_m + 12_000.0, 3000.0),
        DVec2::new(-12.0, 0.0),
        2400.0,
    )
}

#[test]
fn crossing_five_km_ahead_is_not_crossing_ahead() {
    // Predicted miss 1.2 km (risk: under 1 nm), crossing 5 km ahead of her
    // bow: an already-clear pass, neither crossed ahead nor an action owed.
    let recording = slow_crossing_ahead_of_fast(5000.0);
    let target = judged_with(&recording, &ObservedParameters::default());
    assert_eq!(
        target.latch.expect("risk").encounter,
        Encounter::CrossingGiveWay
    );
    assert!(target.findings.is_empty(), "{:?}", names(&target));
    assert!(target.compliant);
    // The range is settable: asked for 6 km, the crossing is found.
    let mut wide = ObservedParameters::default();
    wide.scoring.crossed_ahead_range_m = 6000.0;
    let target = judged_with(&recording, &wide);
    match target.findings.as_slice() {
        [crate::ComplianceViolation::CrossedAhead { distance_ahead_m }] => {
            assert!(
                (distance_ahead_m - 5000.0).abs() < 50.0,
                "{distance_ahead_m}"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn crossing_three_hundred_metres_ahead_is_crossing_ahead() {
    // Both at 6 m/s on crossing courses, ownship 300 m ahead of her bow at
    // the crossing (a predicted miss of 212 m, 112 m between the hulls):
    // crossed ahead, and the action that was owed not taken.
    let recording = straight(
        DVec2::ZERO,
        DVec2::new(0.0, 6.0),
        DVec2::new(6000.0, 5700.0),
        DVec2::new(-6.0, 0.0),
        2400.0,
    );
    let target = judged_with(&recording, &ObservedParameters::default());
    assert_eq!(
        target.latch.expect("risk").encounter,
        Encounter::CrossingGiveWay
    );
    let found = names(&target);
    assert!(found.contains(&"no_action"), "{found:?}");
    let ahead = target.findings.iter().find_map(|f| match f {
        crate::ComplianceViolation::CrossedAhead { distance_ahead_m } => Some(*distance_ahead_m),
        _ => None,
    });
    assert!(
        (ahead.expect("crossed ahead") - 300.0).abs() < 10.0,
        "{ahead:?}"
    );
}

#[test]
fn a_set_up_port_to_port_pass_of_fast_craft_needs_no_action() {
    // Two craft at 15 m/s (29 kn) on reciprocal courses, set up to pass
    // port to port 0.8 nm apart: risk latched (under 1 nm), the pass clear.
    let recording = straight(
        DVec2::ZERO,
        DVec2::new(0.0, 15.0),
        DVec2::new(-0.8 * 1852.0, 20_000.0),
        DVec2::new(0.0, -15.0),
        1200.0,
    );
    let target = judged_with(&recording, &ObservedParameters::default());
    assert!(target.latch.is_some(), "risk latched");
    assert!(target.findings.is_empty(), "{:?}", names(&target));
    assert!(target.compliant);
    // The same pass set up at 0.1 nm (85 m between the hulls) owes an
    // action, and none was taken.
    let close = straight(
        DVec2::ZERO,
        DVec2::new(0.0, 15.0),
        DVec2::new(-0.1 * 1852.0, 20_000.0),
        DVec2::new(0.0, -15.0),
        1200.0,
    );
    let target = judged_with(&close, &ObservedParameters::default());
    assert!(
        names(&target).contains(&"no_action"),
        "{:?}",
        names(&target)
    );
}

#[test]
fn an_overtaking_a_fifth_of_a_mile_off_needs_no_alteration() {
    // Ownship at 8 m/s overtakes a vessel at 5 m/s on a parallel track
    // 0.2 nm (370 m) off: keeping out of the way, no 30° alteration owed.
    let recording = straight(
        DVec2::ZERO,
        DVec2::new(0.0, 8.0),
        DVec2::new(0.2 * 1852.0, 3000.0),
        DVec2::new(0.0, 5.0),
        2400.0,
    );
    let target = judged_with(&recording, &ObservedParameters::default());
    assert_eq!(target.latch.expect("risk").encounter, Encounter::Overtaking);
    assert!(target.findings.is_empty(), "{:?}", names(&target));
    assert!(target.compliant);
}
