//! Nautical angles.
//!
//! A course `c` (radians, clockwise from north) points along `(sin c, cos c)` in
//! the x-east / y-north frame. A relative bearing is the direction to another
//! point minus one's own course, normalised to `[0, 2π)`: 0 is dead ahead, π/2
//! the starboard beam, 3π/2 the port beam (notes, "Units and frames").
//!
//! ```
//! use vorrt_geometry::angle;
//! use glam::DVec2;
//! let east = angle::course_to_unit(std::f64::consts::FRAC_PI_2);
//! assert!((east - DVec2::X).length() < 1e-12);
//! assert!((angle::unit_to_course(DVec2::X) - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
//! ```

use glam::DVec2;
use std::f64::consts::{PI, TAU};

/// The unit vector of a nautical course: `(sin c, cos c)`.
#[inline]
#[must_use]
pub fn course_to_unit(course_rad: f64) -> DVec2 {
    let (sin, cos) = course_rad.sin_cos();
    DVec2::new(sin, cos)
}

/// The velocity of a vessel making `speed_mps` on `course_rad`.
#[inline]
#[must_use]
pub fn velocity(course_rad: f64, speed_mps: f64) -> DVec2 {
    course_to_unit(course_rad) * speed_mps
}

/// The nautical course of a direction vector, in `[0, 2π)`; 0 for the zero vector.
#[inline]
#[must_use]
pub fn unit_to_course(direction: DVec2) -> f64 {
    if direction == DVec2::ZERO {
        return 0.0;
    }
    normalize_2pi(direction.x.atan2(direction.y))
}

/// An angle normalised to `[0, 2π)`.
#[inline]
#[must_use]
pub fn normalize_2pi(angle_rad: f64) -> f64 {
    // The common cases without `fmod`, to the same bits as `rem_euclid`:
    // within [0, 2π) the remainder is the angle itself; within (-2π, 0) it
    // is the angle, to which `rem_euclid` adds 2π (-2π itself gives -0.0
    // there, so it takes the general path).
    if (0.0..TAU).contains(&angle_rad) {
        return angle_rad;
    }
    if angle_rad > -TAU && angle_rad < 0.0 {
        let wrapped = angle_rad + TAU;
        return if wrapped >= TAU { 0.0 } else { wrapped };
    }
    let wrapped = angle_rad.rem_euclid(TAU);
    // rem_euclid can return TAU itself for tiny negative inputs.
    if wrapped >= TAU { 0.0 } else { wrapped }
}

/// An angle normalised to `(-π, π]`.
#[inline]
#[must_use]
pub fn normalize_pi(angle_rad: f64) -> f64 {
    let wrapped = normalize_2pi(angle_rad);
    if wrapped > PI { wrapped - TAU } else { wrapped }
}

/// The signed turn from `from_course_rad` to `to_course_rad`, in `(-π, π]`:
/// positive to starboard (clockwise), negative to port.
#[inline]
#[must_use]
pub fn signed_turn(from_course_rad: f64, to_course_rad: f64) -> f64 {
    normalize_pi(to_course_rad - from_course_rad)
}

/// The relative bearing of `to_position` seen from a vessel at
/// `from_position` on `from_course_rad`, in `[0, 2π)`.
#[inline]
#[must_use]
pub fn relative_bearing(from_position: DVec2, from_course_rad: f64, to_position: DVec2) -> f64 {
    normalize_2pi(unit_to_course(to_position - from_position) - from_course_rad)
}

/// The relative bearing folded to `(-π, π]`: positive on the starboard side,
/// negative on the port side. Handy for "within ±x of dead ahead" tests.
#[inline]
#[must_use]
pub fn signed_relative_bearing(
    from_position: DVec2,
    from_course_rad: f64,
    to_position: DVec2,
) -> f64 {
    normalize_pi(relative_bearing(
        from_position,
        from_course_rad,
        to_position,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn cardinal_courses() {
        assert!((course_to_unit(0.0) - DVec2::Y).length() < 1e-12);
        assert!((course_to_unit(PI) + DVec2::Y).length() < 1e-12);
        assert!((course_to_unit(3.0 * FRAC_PI_2) + DVec2::X).length() < 1e-12);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn normalisation_ranges() {
        assert!((normalize_2pi(-FRAC_PI_2) - 3.0 * FRAC_PI_2).abs() < 1e-12);
        assert!((normalize_pi(3.0 * FRAC_PI_2) + FRAC_PI_2).abs() < 1e-12);
        assert_eq!(normalize_pi(PI), PI);
        assert!(normalize_2pi(-1e-18) < TAU);
    }

    /// The reference: `normalize_2pi` as written before its fast paths.
    fn normalize_2pi_by_rem_euclid(angle_rad: f64) -> f64 {
        let wrapped = angle_rad.rem_euclid(TAU);
        if wrapped >= TAU { 0.0 } else { wrapped }
    }

    /// The fast paths give the same bits as `rem_euclid` everywhere: at the
    /// edges of both ranges, for tiny, huge and non-finite angles, and for
    /// a million angles spread over (-8π, 8π).
    #[test]
    fn normalisation_fast_paths_keep_the_bits() {
        let mut angles = vec![
            0.0,
            -0.0,
            TAU,
            -TAU,
            PI,
            -PI,
            TAU - f64::EPSILON * 4.0,
            -TAU + f64::EPSILON * 4.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            -1e-18,
            1e-300,
            -1e-300,
            1e18,
            -1e18,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for base in [TAU, -TAU, 0.0] {
            let mut up = base;
            let mut down = base;
            for _ in 0..8 {
                up = f64::from_bits(up.to_bits() + 1);
                down = f64::from_bits(down.to_bits().wrapping_sub(1));
                angles.extend([up, down]);
            }
        }
        // A linear congruential walk: deterministic, no dependency.
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        for _ in 0..1_000_000 {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            #[expect(clippy::cast_precision_loss, reason = "a uniform draw")]
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            angles.push((unit - 0.5) * 16.0 * PI);
        }
        for angle in angles {
            assert_eq!(
                normalize_2pi(angle).to_bits(),
                normalize_2pi_by_rem_euclid(angle).to_bits(),
                "{angle:e}"
            );
        }
    }

    #[test]
    fn bearing_of_target_on_starboard_beam() {
        let bearing = relative_bearing(DVec2::ZERO, 0.0, DVec2::new(100.0, 0.0));
        assert!((bearing - FRAC_PI_2).abs() < 1e-12);
        let port = signed_relative_bearing(DVec2::ZERO, 0.0, DVec2::new(-100.0, 0.0));
        assert!((port + FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn turns_are_signed_starboard_positive() {
        assert!((signed_turn(0.1, 0.3) - 0.2).abs() < 1e-12);
        assert!((signed_turn(0.1, TAU - 0.1) + 0.2).abs() < 1e-12);
    }
}
