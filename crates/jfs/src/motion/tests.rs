//! Tests of ownship's motion models and legs.
use super::*;

fn pose(x: f64, y: f64, course_deg: f64) -> Pose {
    Pose {
        position_m: DVec2::new(x, y),
        course_rad: course_deg.to_radians(),
    }
}

#[test]
fn rate_limited_leg_ends_on_the_point_facing_away_from_the_tangent_point() {
    let model = RateLimitedTurn {
        turn_radius_m: 300.0,
    };
    for (x, y) in [
        (2000.0, 100.0),
        (-1500.0, -800.0),
        (10.0, 5000.0),
        (900.0, -50.0),
    ] {
        let leg = model
            .steer(pose(0.0, 0.0, 20.0), DVec2::new(x, y), 6.0, f64::INFINITY)
            .unwrap();
        assert!(leg.end_m().distance(DVec2::new(x, y)) < 1e-6, "{x} {y}");
        let bearing = angle::unit_to_course(DVec2::new(x, y) - leg.turn_end_m());
        assert!(angle::signed_turn(leg.course_rad, bearing).abs() < 1e-6);
    }
}

#[test]
fn point_inside_the_turning_circle_is_unreachable() {
    let model = RateLimitedTurn {
        turn_radius_m: 500.0,
    };
    assert!(
        model
            .steer(
                pose(0.0, 0.0, 0.0),
                DVec2::new(400.0, 0.0),
                6.0,
                f64::INFINITY
            )
            .is_none()
    );
}

#[test]
fn pieces_cover_the_leg_continuously() {
    let model = RateLimitedTurn {
        turn_radius_m: 400.0,
    };
    let leg = model
        .steer(
            pose(0.0, 0.0, 0.0),
            DVec2::new(-3000.0, -200.0),
            5.0,
            f64::INFINITY,
        )
        .unwrap();
    let pieces: Vec<Piece> = leg.pieces(100.0).collect();
    let mut at = leg.start_m;
    let mut elapsed = 0.0;
    for piece in &pieces {
        assert!(piece.start_m.distance(at) < 1e-6);
        assert!((piece.elapsed_s - elapsed).abs() < 1e-6);
        at = piece.end_m();
        elapsed += piece.duration_s;
    }
    assert!(at.distance(leg.end_m()) < 1e-6);
    assert!((elapsed - leg.duration_s()).abs() < 1e-6);
    assert!(pieces.iter().filter(|piece| !piece.turning).count() >= 20);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn max_length_cuts_the_arc() {
    let model = RateLimitedTurn {
        turn_radius_m: 400.0,
    };
    let leg = model
        .steer(pose(0.0, 0.0, 0.0), DVec2::new(-3000.0, -100.0), 5.0, 100.0)
        .unwrap();
    assert!((leg.length_m() - 100.0).abs() < 1e-9);
    assert_eq!(leg.straight_m, 0.0);
    assert!((leg.turn_rad.abs() - 0.25).abs() < 1e-12);
}

#[test]
fn default_rate_is_capped_and_from_length() {
    assert!((default_turn_rate_rad_s(10.0, 10.0) - MAX_DEFAULT_TURN_RATE_RAD_S).abs() < 1e-15);
    assert!((default_turn_rate_rad_s(400.0, 6.0) - 6.0 / 1200.0).abs() < 1e-15);
}

/// A 90° starboard turn on 400 m then 2 km straight, at 6 m/s.
fn turn_then_run() -> Leg {
    RateLimitedTurn {
        turn_radius_m: 400.0,
    }
    .turn_onto(pose(0.0, 0.0, 0.0), 90f64.to_radians(), 6.0, 2000.0)
}

#[test]
fn deceleration_covers_v0_t_minus_a_t2_over_2_then_the_settled_speed() {
    let leg = Leg {
        speed_mps: 3.0,
        ..turn_then_run()
    }
    .from_speed(6.0, 0.03);
    // 100 s to slow from 6 to 3 m/s, 450 m sailed meanwhile.
    assert!((leg.speed_change_s() - 100.0).abs() < 1e-9);
    assert!((leg.speed_change_m() - 450.0).abs() < 1e-9);
    for t in [0.0, 10.0, 50.0, 99.0] {
        let expected = 6.0 * t - 0.5 * 0.03 * t * t;
        assert!((leg.distance_at(t) - expected).abs() < 1e-9, "{t}");
        assert!((leg.speed_at(t) - (6.0 - 0.03 * t)).abs() < 1e-9);
        assert!((leg.time_at_distance(expected) - t).abs() < 1e-9);
    }
    assert!((leg.distance_at(200.0) - (450.0 + 300.0)).abs() < 1e-9);
    let length = leg.length_m();
    assert!((leg.duration_s() - (100.0 + (length - 450.0) / 3.0)).abs() < 1e-9);
    // The curve is the same as at constant speed.
    assert!(leg.end_m().distance(turn_then_run().end_m()) < 1e-9);
    // Slower than the constant-speed leg at every time.
    let constant = turn_then_run();
    for t in [20.0, 80.0, 150.0, 400.0] {
        assert!(leg.distance_at(t) < constant.distance_at(t));
    }
}

#[test]
fn pose_is_continuous_across_the_turn_end_and_the_speed_change_end() {
    let leg = Leg {
        speed_mps: 6.0,
        ..turn_then_run()
    }
    .from_speed(1.0, 0.02);
    for at in [leg.turn_duration_s(), leg.speed_change_s()] {
        let before = leg.pose_at(at - 1e-6);
        let after = leg.pose_at(at + 1e-6);
        assert!(before.position_m.distance(after.position_m) < 1e-4, "{at}");
        assert!(angle::signed_turn(before.course_rad, after.course_rad).abs() < 1e-6);
    }
    // Speeding up on the arc, the rate of turn never exceeds the one at the
    // settled speed: v / R with v at most the service speed.
    assert!(leg.turn_rate_rad_s() <= 6.0 / 400.0 + 1e-15);
}

#[test]
fn remainder_of_a_speed_change_continues_the_same_motion() {
    let leg = Leg {
        speed_mps: 2.0,
        ..turn_then_run()
    }
    .from_speed(6.0, 0.05);
    for cut_s in [10.0, 79.0, 81.0, 200.0] {
        let rest = leg.remainder(cut_s);
        assert!((rest.start_speed_mps() - leg.speed_at(cut_s)).abs() < 1e-9);
        for later in [0.0, 5.0, 60.0, 300.0] {
            let expected = leg.pose_at(cut_s + later).position_m;
            assert!(rest.pose_at(later).position_m.distance(expected) < 1e-6);
            assert!((rest.speed_at(later) - leg.speed_at(cut_s + later)).abs() < 1e-9);
        }
        assert!((rest.duration_s() - (leg.duration_s() - cut_s)).abs() < 1e-6);
    }
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn a_leg_that_stops_ends_at_its_stopping_distance_even_on_the_arc() {
    // From 6 m/s at 0.03 m/s²: 600 m to stop, inside the 628 m of the arc.
    let stop = Leg {
        speed_mps: 0.0,
        ..turn_then_run()
    }
    .from_speed(6.0, 0.03);
    assert!((stop.length_m() - 600.0).abs() < 1e-9);
    assert_eq!(stop.straight_m, 0.0);
    assert!((stop.duration_s() - 200.0).abs() < 1e-9);
    assert_eq!(stop.end_speed_mps(), 0.0);
    assert!(stop.pose_at(500.0).position_m.distance(stop.end_m()) < 1e-9);
    assert!(stop.pieces(100.0).all(|piece| piece.turning));
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn a_stopped_ownship_that_stays_stopped_has_a_leg_of_no_time_not_nan() {
    // The evasive fallback's stop (speed factor 0) asked of an ownship
    // already at rest: no speed change, no length; 0/0 made pose_at panic.
    let still = Leg {
        speed_mps: 0.0,
        ..turn_then_run()
    }
    .from_speed(0.0, 0.03);
    assert_eq!(still.length_m(), 0.0);
    assert_eq!(still.duration_s(), 0.0);
    let start = turn_then_run().pose_at(0.0).position_m;
    assert!(still.pose_at(30.0).position_m.distance(start) < 1e-9);
}

proptest::proptest! {
    /// Along any leg with a change of speed, the pieces cover the leg in
    /// order, every pose sampled densely lies within the leg's piece error
    /// of its piece sailed at its mean velocity, and the speed changes no
    /// faster than the rate and stays between the start and settled speeds.
    #[test]
    fn pieces_follow_the_speed_profile_within_the_piece_error(
        turn_deg in -170.0f64..170.0,
        radius_m in 0.0f64..800.0,
        straight_m in 0.0f64..3000.0,
        start_mps in 0.0f64..8.0,
        settled_mps in 0.0f64..8.0,
        rate_mps2 in 0.005f64..0.2,
    ) {
        let leg = RateLimitedTurn { turn_radius_m: radius_m }
            .turn_onto(pose(10.0, -20.0, 30.0), (30.0 + turn_deg).to_radians(), settled_mps, straight_m)
            .from_speed(start_mps, rate_mps2);
        proptest::prop_assume!(leg.length_m() > 1.0);
        let pieces: Vec<Piece> = leg.pieces(100.0).collect();
        let mut at = leg.start_m;
        let mut elapsed = 0.0;
        let margin = leg.piece_error_m() + 1e-6;
        for piece in &pieces {
            proptest::prop_assert!(piece.start_m.distance(at) < 1e-6);
            proptest::prop_assert!((piece.elapsed_s - elapsed).abs() < 1e-6);
            for k in 0..=8 {
                let t = piece.duration_s * f64::from(k) / 8.0;
                let sailed = leg.pose_at(piece.elapsed_s + t).position_m;
                let chord = piece.start_m + piece.velocity_mps * t;
                proptest::prop_assert!(sailed.distance(chord) <= margin,
                    "{} > {margin}", sailed.distance(chord));
            }
            at = piece.end_m();
            elapsed += piece.duration_s;
        }
        proptest::prop_assert!(at.distance(leg.end_m()) < 1e-6);
        proptest::prop_assert!((elapsed - leg.duration_s()).abs() < 1e-6);
        let (low, high) = (start_mps.min(settled_mps), start_mps.max(settled_mps));
        let step_s = 1.0;
        let mut previous = leg.speed_at(0.0);
        let mut t = step_s;
        while t <= leg.duration_s() + step_s {
            let speed = leg.speed_at(t);
            proptest::prop_assert!(speed >= low - 1e-12 && speed <= high + 1e-12);
            proptest::prop_assert!((speed - previous).abs() <= rate_mps2 * step_s + 1e-12);
            previous = speed;
            t += step_s;
        }
    }
}
