//! Property tests of the geometry layer: CPA (paper eqs. 3-4 with erratum 1),
//! the velocity obstacle (paper eq. 2) and nautical angles.

use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use vorrt_geometry::{
    DVec2, VelocityObstacle, angle, closest_point_of_approach, closest_point_of_approach_within,
    units,
};

/// Positions within 20 km of the origin, metres.
fn position() -> impl Strategy<Value = DVec2> {
    (-20_000.0..20_000.0f64, -20_000.0..20_000.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

/// Velocities up to about 20 m/s (39 kn) per axis.
fn velocity() -> impl Strategy<Value = DVec2> {
    (-20.0..20.0f64, -20.0..20.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

/// Any angle, including several turns either way.
fn any_angle() -> impl Strategy<Value = f64> {
    -4.0 * TAU..4.0 * TAU
}

/// The rotation that turns a nautical course `c` into `c + turn` (clockwise).
fn rotate_clockwise(vector: DVec2, turn_rad: f64) -> DVec2 {
    DVec2::from_angle(-turn_rad).rotate(vector)
}

/// A velocity-obstacle case: positions of A and B, B's velocity, the combined
/// radius and a candidate velocity for A. Half the candidates are aimed within
/// twice the cone's half-angle of B, so both answers come up often.
fn velocity_obstacle_case() -> impl Strategy<Value = (DVec2, DVec2, DVec2, f64, DVec2)> {
    let random = velocity().prop_map(|velocity_a| (velocity_a, None));
    let aimed = (-2.0..2.0f64, 0.05..20.0f64)
        .prop_map(|(aim, relative_speed)| (DVec2::ZERO, Some((aim, relative_speed))));
    (
        position(),
        position(),
        velocity(),
        0.0..3_000.0f64,
        prop_oneof![random, aimed],
    )
        .prop_map(|(position_a, position_b, velocity_b, radius, candidate)| {
            let velocity_a = match candidate {
                (velocity_a, None) => velocity_a,
                (_, Some((aim, relative_speed))) => {
                    let line_of_sight = position_b - position_a;
                    let distance = line_of_sight.length().max(1e-9);
                    let half_angle = (radius / distance).min(1.0).asin();
                    let direction = angle::unit_to_course(line_of_sight) + aim * half_angle;
                    velocity_b + angle::velocity(direction, relative_speed)
                }
            };
            (position_a, position_b, velocity_b, radius, velocity_a)
        })
}

/// Whether two times agree to a relative tolerance.
fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * (1.0 + a.abs().max(b.abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Eq. 4 with t_cpa clamped to t >= 0: the closest approach is never
    /// farther than the vessels are now.
    #[test]
    fn cpa_distance_never_exceeds_current_distance(
        position_a in position(), velocity_a in velocity(),
        position_b in position(), velocity_b in velocity(),
    ) {
        let cpa = closest_point_of_approach(position_a, velocity_a, position_b, velocity_b);
        let now = position_a.distance(position_b);
        prop_assert!(cpa.time_s >= 0.0);
        prop_assert!(cpa.distance_m <= now + 1e-9 * (1.0 + now));
    }

    /// CPA depends only on relative position and velocity: translating both
    /// vessels, rotating the whole picture, or adding one velocity to both
    /// leaves t_cpa and d_cpa unchanged (eqs. 3-4).
    #[test]
    fn cpa_is_invariant_under_translation_rotation_and_common_velocity(
        position_a in position(), velocity_a in velocity(),
        position_b in position(), velocity_b in velocity(),
        shift in position(), turn in any_angle(), drift in velocity(),
    ) {
        // A relative speed near zero makes t_cpa ill-conditioned; such pairs
        // have t_cpa = 0 in every frame only when exactly equal.
        prop_assume!((velocity_a - velocity_b).length() > 0.5);
        let original = closest_point_of_approach(position_a, velocity_a, position_b, velocity_b);
        let tolerance = 1e-7;

        let translated = closest_point_of_approach(
            position_a + shift, velocity_a, position_b + shift, velocity_b);
        prop_assert!(close(original.time_s, translated.time_s, tolerance),
            "translation: {original:?} vs {translated:?}");
        prop_assert!(close(original.distance_m, translated.distance_m, tolerance),
            "translation: {original:?} vs {translated:?}");

        let rotated = closest_point_of_approach(
            rotate_clockwise(position_a, turn), rotate_clockwise(velocity_a, turn),
            rotate_clockwise(position_b, turn), rotate_clockwise(velocity_b, turn));
        prop_assert!(close(original.time_s, rotated.time_s, tolerance),
            "rotation: {original:?} vs {rotated:?}");
        prop_assert!(close(original.distance_m, rotated.distance_m, tolerance),
            "rotation: {original:?} vs {rotated:?}");

        let drifted = closest_point_of_approach(
            position_a, velocity_a + drift, position_b, velocity_b + drift);
        prop_assert!(close(original.time_s, drifted.time_s, tolerance),
            "common velocity: {original:?} vs {drifted:?}");
        prop_assert!(close(original.distance_m, drifted.distance_m, tolerance),
            "common velocity: {original:?} vs {drifted:?}");
    }

    /// Erratum 6: restricting t_cpa to a segment [0, T] can only make the
    /// closest approach farther, never nearer, and never past the segment.
    #[test]
    fn segment_cpa_is_no_closer_than_unbounded_cpa(
        position_a in position(), velocity_a in velocity(),
        position_b in position(), velocity_b in velocity(),
        horizon_s in 0.0..5_000.0f64,
    ) {
        let unbounded = closest_point_of_approach(position_a, velocity_a, position_b, velocity_b);
        let segment = closest_point_of_approach_within(
            position_a, velocity_a, position_b, velocity_b, horizon_s);
        prop_assert!(segment.distance_m >= unbounded.distance_m - 1e-9 * (1.0 + segment.distance_m));
        prop_assert!(segment.time_s >= 0.0 && segment.time_s <= horizon_s);
        if unbounded.time_s <= horizon_s {
            prop_assert!(close(segment.time_s, unbounded.time_s, 1e-9));
        }
    }

    /// Eq. 2: V_A is in VO_B^A exactly when the ray λ(P_A, V_A - V_B) meets
    /// B ⊕ -A, i.e. when the unbounded d_cpa is under the combined radius.
    /// A thin band around d_cpa = R is left out (rounding decides it).
    #[test]
    fn velocity_obstacle_contains_exactly_the_velocities_with_cpa_inside_radius(
        (position_a, position_b, velocity_b, combined_radius_m, velocity_a)
            in velocity_obstacle_case(),
    ) {
        let vo = VelocityObstacle::new(position_a, position_b, velocity_b, combined_radius_m);
        let cpa = closest_point_of_approach(position_a, velocity_a, position_b, velocity_b);
        let scale = position_a.distance(position_b) + combined_radius_m + 1.0;
        prop_assume!((cpa.distance_m - combined_radius_m).abs() > 1e-6 * scale);
        prop_assert_eq!(vo.contains(velocity_a), cpa.distance_m < combined_radius_m,
            "d_cpa {} against R {}", cpa.distance_m, combined_radius_m);
    }

    /// Overlapping discs: the cone opens to the whole plane, every velocity
    /// (including the apex, equal velocities) is inside.
    #[test]
    fn overlapping_discs_put_every_velocity_inside_the_obstacle(
        position_a in position(), offset_direction in any_angle(),
        combined_radius_m in 1.0..3_000.0f64, fraction in 0.0..1.0f64,
        velocity_a in velocity(), velocity_b in velocity(),
    ) {
        let position_b = position_a
            + angle::course_to_unit(offset_direction) * combined_radius_m * fraction;
        let vo = VelocityObstacle::new(position_a, position_b, velocity_b, combined_radius_m);
        prop_assert!(vo.overlapping);
        prop_assert!(vo.contains(velocity_a));
        prop_assert!(vo.contains(velocity_b));
        prop_assert!(vo.contains_by_ray(velocity_a));
    }

    /// The fast cone test agrees with the paper's literal ray-against-disc
    /// test (eqs. 1-2), away from the cone's boundary.
    #[test]
    fn cone_test_agrees_with_ray_test(
        (position_a, position_b, velocity_b, combined_radius_m, velocity_a)
            in velocity_obstacle_case(),
    ) {
        let vo = VelocityObstacle::new(position_a, position_b, velocity_b, combined_radius_m);
        let cpa = closest_point_of_approach(position_a, velocity_a, position_b, velocity_b);
        let scale = position_a.distance(position_b) + combined_radius_m + 1.0;
        prop_assume!((cpa.distance_m - combined_radius_m).abs() > 1e-6 * scale);
        prop_assert_eq!(vo.contains(velocity_a), vo.contains_by_ray(velocity_a));
    }

    /// A course turns into the unit vector (sin c, cos c) and back into the
    /// same course, normalised to [0, 2π).
    #[test]
    fn course_round_trips_through_unit_vector(course in any_angle()) {
        let unit = angle::course_to_unit(course);
        prop_assert!((unit.length() - 1.0).abs() < 1e-12);
        let back = angle::unit_to_course(unit);
        prop_assert!((0.0..TAU).contains(&back));
        prop_assert!(angle::signed_turn(course, back).abs() < 1e-9);
        // Speed scales the same unit vector.
        let v = angle::velocity(course, 7.5);
        prop_assert!((v - unit * 7.5).length() < 1e-12);
    }

    /// normalize_2pi lands in [0, 2π), normalize_pi in (-π, π], and both
    /// differ from the input by a whole number of turns.
    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn normalisation_stays_in_range_and_preserves_direction(raw in any_angle()) {
        let full = angle::normalize_2pi(raw);
        let half = angle::normalize_pi(raw);
        prop_assert!((0.0..TAU).contains(&full), "{raw} -> {full}");
        prop_assert!(half > -PI && half <= PI, "{raw} -> {half}");
        for normalised in [full, half] {
            let turns = (raw - normalised) / TAU;
            prop_assert!((turns - turns.round()).abs() < 1e-9, "{raw} -> {normalised}");
        }
        prop_assert_eq!(angle::normalize_2pi(full), full);
        prop_assert_eq!(angle::normalize_pi(half), half);
    }

    /// Relative bearing = direction to the other point minus own course:
    /// a point placed at bearing b is seen at b; the signed form is its
    /// fold into (-π, π]; the reverse bearing is the reciprocal direction.
    #[test]
    fn relative_bearing_is_consistent(
        from in position(), course in any_angle(), bearing in 0.0..TAU,
        range_m in 1.0..20_000.0f64, other_course in any_angle(),
    ) {
        let to = from + angle::course_to_unit(course + bearing) * range_m;
        let seen = angle::relative_bearing(from, course, to);
        prop_assert!((0.0..TAU).contains(&seen));
        prop_assert!(angle::signed_turn(bearing, seen).abs() < 1e-9, "{bearing} vs {seen}");
        let signed = angle::signed_relative_bearing(from, course, to);
        prop_assert!((signed - angle::normalize_pi(seen)).abs() < 1e-12);
        // Absolute directions A->B and B->A are reciprocal.
        let back = angle::relative_bearing(to, other_course, from);
        let absolute_there = course + seen;
        let absolute_back = other_course + back;
        prop_assert!((angle::signed_turn(absolute_there, absolute_back).abs() - PI).abs() < 1e-9);
    }

    /// Knots and nautical miles convert to SI and back (1 kn = 1852/3600 m/s).
    #[test]
    fn units_round_trip(speed_kn in 0.0..60.0f64, distance_nm in 0.0..100.0f64) {
        prop_assert!((units::mps_to_knots(units::knots_to_mps(speed_kn)) - speed_kn).abs() < 1e-12);
        prop_assert!(
            (units::m_to_nautical_miles(units::nautical_miles_to_m(distance_nm)) - distance_nm).abs()
                < 1e-12
        );
        prop_assert!((units::knots_to_mps(speed_kn) * 3600.0 - speed_kn * 1852.0).abs() < 1e-9);
    }
}
