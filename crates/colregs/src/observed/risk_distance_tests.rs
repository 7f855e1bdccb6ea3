//! Issue 23, item 3: risk of collision that scales with vessel size and sea
//! room (decision 50). Straight tracks whose verdict is obvious.

use super::*;
use crate::encounter::Encounter;
use glam::DVec2;

/// Two vessels on reciprocal courses north and south at `speed_mps` each,
/// set up to pass port to port `miss_m` apart, both `length_m` long,
/// sampled every 10 s for 1800 s; positions only.
fn meeting(length_m: f64, speed_mps: f64, miss_m: f64) -> Recording {
    let times_s: Vec<f64> = (0..=180).map(|i| f64::from(i) * 10.0).collect();
    let track = |name: &str, start: DVec2, velocity: DVec2| RecordedTrack {
        name: name.into(),
        length_m,
        positions_m: times_s.iter().map(|t| start + velocity * *t).collect(),
        courses_rad: None,
        observation: TrackObservation::default(),
    };
    Recording {
        ownship: track("ownship", DVec2::ZERO, DVec2::new(0.0, speed_mps)),
        targets: vec![track(
            "TS1",
            DVec2::new(-miss_m, 3600.0 * speed_mps / 2.0),
            DVec2::new(0.0, -speed_mps),
        )],
        times_s,
    }
}

fn judged(recording: &Recording, parameters: &ObservedParameters) -> ObservedEncounter {
    judge(recording, parameters).expect("valid").targets[0].clone()
}

fn in_channel(sea_room_m: f64) -> ObservedParameters {
    let mut parameters = ObservedParameters::default();
    parameters.rules.risk_distance.sea_room_m = Some(sea_room_m);
    parameters
}

#[test]
fn small_craft_half_a_mile_apart_in_a_narrow_channel_are_no_encounter() {
    // Two 20 m launches at 5 m/s passing 0.5 nm (926 m) apart.
    let recording = meeting(20.0, 5.0, 0.5 * 1852.0);
    // In open sea that is under 1 nm: an encounter (head-on).
    let open = judged(&recording, &ObservedParameters::default());
    assert_eq!(open.latch.expect("risk").encounter, Encounter::HeadOn);
    // In a 1500 m channel the risk distance is a quarter of it, 375 m: an
    // already-clear pass, no encounter and nothing to find.
    let channel = judged(&recording, &in_channel(1500.0));
    assert_eq!(channel.latch, None);
    assert!(channel.findings.is_empty(), "{:?}", channel.findings);
    assert!(channel.compliant);
    // The same launches set up to pass 150 m apart (130 m between the
    // hulls, under d_th) are an encounter even there: never under d_th
    // between the hulls.
    let close = judged(&meeting(20.0, 5.0, 150.0), &in_channel(1500.0));
    assert_eq!(close.latch.expect("risk").encounter, Encounter::HeadOn);
}

#[test]
fn large_ships_are_at_risk_farther_out_in_open_sea() {
    // Two 300 m ships at 0.8 nm predicted miss in open sea: an encounter.
    let ships = judged(
        &meeting(300.0, 7.0, 0.8 * 1852.0),
        &ObservedParameters::default(),
    );
    assert_eq!(ships.latch.expect("risk").encounter, Encounter::HeadOn);
    // At 1.1 nm (2037 m), two 350 m ships still are (6.4 lengths, 2240 m);
    // two 100 m vessels are not (1 nm).
    let miss_m = 1.1 * 1852.0;
    let large = judged(&meeting(350.0, 7.0, miss_m), &ObservedParameters::default());
    let latch = large.latch.expect("risk");
    assert_eq!(latch.encounter, Encounter::HeadOn);
    assert!((latch.risk_distance_m.expect("pair's") - 2240.0).abs() < 1e-6);
    let small = judged(&meeting(100.0, 7.0, miss_m), &ObservedParameters::default());
    assert_eq!(small.latch, None);
}

/// Ownship at 8 m/s overtakes a vessel at 5 m/s, 3 km ahead on a parallel
/// track `offset_m` to starboard (100 m each, 1 s steps sampled every
/// 10 s, positions only); from 60 s ownship turns at 0.5°/s to
/// `turn_deg` (negative: to port) and holds it.
fn overtaking(offset_m: f64, turn_deg: f64) -> Recording {
    let (mut own_m, mut course_rad) = (DVec2::ZERO, 0.0_f64);
    let target_course_rad = turn_deg.to_radians();
    let mut positions_m = Vec::new();
    let mut times_s = Vec::new();
    for second in 0..=1800_u32 {
        if second % 10 == 0 {
            positions_m.push(own_m);
            times_s.push(f64::from(second));
        }
        if second >= 60 {
            let step =
                (target_course_rad - course_rad).clamp(-0.5_f64.to_radians(), 0.5_f64.to_radians());
            course_rad += step;
        }
        own_m += DVec2::new(course_rad.sin(), course_rad.cos()) * 8.0;
    }
    let target_start = DVec2::new(offset_m, 3000.0);
    let track = |name: &str, positions_m: Vec<DVec2>| RecordedTrack {
        name: name.into(),
        length_m: 100.0,
        positions_m,
        courses_rad: None,
        observation: TrackObservation::default(),
    };
    Recording {
        ownship: track("ownship", positions_m),
        targets: vec![track(
            "TS1",
            times_s
                .iter()
                .map(|t| target_start + DVec2::new(0.0, 5.0) * *t)
                .collect(),
        )],
        times_s,
    }
}

fn names(target: &ObservedEncounter) -> Vec<&'static str> {
    target
        .findings
        .iter()
        .map(crate::ComplianceViolation::name)
        .collect()
}

#[test]
fn an_overtaking_vessel_owes_a_readily_apparent_action() {
    // Rule 13(a) puts the overtaking vessel under Section II, and so under
    // rules 16 and 8(b): set up to pass 150 m off (under d_th between the
    // hulls), a 15 degree alteration that opens the pass is still not
    // readily apparent (decision 50 keeps this reading).
    let target = judged(&overtaking(150.0, -15.0), &ObservedParameters::default());
    assert_eq!(target.latch.expect("risk").encounter, Encounter::Overtaking);
    assert!(target.clearance_kept);
    assert!(
        names(&target).contains(&"action_not_apparent"),
        "{:?}",
        names(&target)
    );
    // Holding on and passing 150 m off: the clearance broken and the
    // action that was owed not taken.
    let held = judged(&overtaking(150.0, 0.0), &ObservedParameters::default());
    let found = names(&held);
    assert!(
        found.contains(&"clearance_violated") && found.contains(&"no_action"),
        "{found:?}"
    );
    // The parallel pass 0.2 nm off has no finding (decision 42): no
    // action is demanded of a pass that keeps d_th.
    let parallel = judged(
        &overtaking(0.2 * 1852.0, 0.0),
        &ObservedParameters::default(),
    );
    assert!(parallel.findings.is_empty(), "{:?}", names(&parallel));
}
