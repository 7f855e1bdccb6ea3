//! Jitter is not a turn: straight and steadily turning tracks sampled at
//! irregular intervals with position noise give no turn finding (decision
//! 31). Seeded `ChaCha`; 24 cases, 400 with `VORRT_HEAVY_TESTS=1`.

use super::*;
use crate::compliance::ComplianceViolation;
use glam::DVec2;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{RngCore, SeedableRng};
use vorrt_geometry::angle;

/// A uniform number in `[low, high)`.
fn uniform(rng: &mut ChaCha8Rng, low: f64, high: f64) -> f64 {
    #[expect(
        clippy::cast_precision_loss,
        reason = "53 random bits are exact in an f64"
    )]
    let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    low + (high - low) * unit
}

/// A standard normal number (Box-Muller).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let u = uniform(rng, f64::EPSILON, 1.0);
    let v = uniform(rng, 0.0, 1.0);
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// One random case: ownship straight or turning steadily to starboard,
/// fixes at irregular intervals with Gaussian jitter, and a target crossing
/// from port or starboard, or meeting it, on the fix times. Returns the
/// recording and a description for failures.
fn case(rng: &mut ChaCha8Rng) -> (Recording, String) {
    let speed_mps = uniform(rng, 3.0, 10.0);
    let rate_rad_s = if rng.next_u32().is_multiple_of(2) {
        0.0
    } else {
        uniform(rng, 0.002, 0.02).to_radians()
    };
    let sigma_m = uniform(rng, 0.0, 15.0);
    let longest_s = uniform(rng, 2.0, 180.0);
    let mut times_s = vec![0.0];
    while times_s[times_s.len() - 1] < 2400.0 {
        let last = times_s[times_s.len() - 1];
        times_s.push(last + uniform(rng, 2.0, longest_s.max(2.0)));
    }
    let course_at = |t: f64| rate_rad_s * t;
    let own_at = |t: f64| {
        if rate_rad_s == 0.0 {
            DVec2::new(0.0, speed_mps * t)
        } else {
            // A circle of radius v / ω, starting north from the origin.
            let radius_m = speed_mps / rate_rad_s;
            DVec2::new(
                radius_m * (1.0 - course_at(t).cos()),
                radius_m * course_at(t).sin(),
            )
        }
    };
    let kind = rng.next_u32() % 3;
    let meet_s = 1500.0;
    let target_course_rad = course_at(meet_s)
        + match kind {
            0 => 90f64.to_radians(),  // from port: ownship stands on
            1 => -90f64.to_radians(), // from starboard: ownship gives way
            _ => 180f64.to_radians(), // head-on
        };
    let target_velocity = angle::velocity(target_course_rad, uniform(rng, 4.0, 8.0));
    let miss_m = uniform(rng, -300.0, 300.0);
    let target_start =
        own_at(meet_s) + angle::velocity(course_at(meet_s), miss_m) - target_velocity * meet_s;
    let mut own_m = Vec::with_capacity(times_s.len());
    for t in &times_s {
        let jitter = DVec2::new(normal(rng), normal(rng)) * sigma_m;
        own_m.push(own_at(*t) + jitter);
    }
    let track = |name: &str, positions_m: Vec<DVec2>| RecordedTrack {
        name: name.into(),
        length_m: 50.0,
        positions_m,
        courses_rad: None,
        observation: TrackObservation::default(),
    };
    let recording = Recording {
        ownship: track("ownship", own_m),
        targets: vec![track(
            "TS1",
            times_s
                .iter()
                .map(|t| target_start + target_velocity * *t)
                .collect(),
        )],
        times_s,
    };
    let description = format!(
        "speed {speed_mps:.1} m/s, rate {:.3}°/s, jitter {sigma_m:.1} m, intervals 2-{longest_s:.0} s, kind {kind}",
        rate_rad_s.to_degrees()
    );
    (recording, description)
}

#[test]
fn jitter_on_straight_and_steady_turns_is_no_turn_finding() {
    let heavy = std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1");
    let cases = if heavy { 400 } else { 24 };
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    for _ in 0..cases {
        let (recording, description) = case(&mut rng);
        let judgement = judge(&recording, &ObservedParameters::default()).expect("valid");
        let turn_findings: Vec<&str> = judgement
            .targets
            .iter()
            .flat_map(|target| &target.findings)
            .map(ComplianceViolation::name)
            .filter(|name| {
                matches!(
                    *name,
                    "port_turn"
                        | "small_alterations"
                        | "stand_on_turned_to_port"
                        | "port_turn_toward_vessel"
                )
            })
            .collect();
        assert!(
            turn_findings.is_empty(),
            "{description}: {turn_findings:?}, noise {:?}",
            judgement.noise[0]
        );
        assert_eq!(
            judgement.path.turn_reversals, 0,
            "{description}: noise {:?}",
            judgement.noise[0]
        );
    }
}

#[test]
#[expect(
    clippy::float_cmp,
    reason = "without jitter the published values are passed on as they are"
)]
fn exact_tracks_keep_the_published_thresholds() {
    let times_s: Vec<f64> = (0..200).map(|i| f64::from(i) * 5.0).collect();
    let track = RecordedTrack {
        name: "ownship".into(),
        length_m: 100.0,
        positions_m: times_s.iter().map(|t| DVec2::new(0.0, 6.0 * t)).collect(),
        courses_rad: None,
        observation: TrackObservation::default(),
    };
    let recording = Recording {
        ownship: track,
        targets: Vec::new(),
        times_s,
    };
    let parameters = ObservedParameters::default();
    let judgement = judge(&recording, &parameters).expect("valid");
    let noise = judgement.noise[0];
    assert!(noise.position_noise_m < 1e-9);
    assert_eq!(noise.window_s, parameters.window_s);
    assert_eq!(
        noise.turn_tolerance_rad,
        parameters.rules.turn_tolerance_rad
    );
    assert_eq!(
        noise.action_detection_rad,
        parameters.scoring.action_detection_rad
    );
}
