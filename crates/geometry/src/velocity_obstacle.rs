//! The velocity obstacle `VO_B^A(V_B)` (paper, eq. 2; Fiorini and Shiller 1998).
//!
//! The set of ownship velocities `V_A` for which the ray `λ(P_A, V_A - V_B)`
//! meets the disc `B ⊕ -A` centred at `P_B`: keeping such a velocity brings the
//! two discs into contact at some future time. It is a cone with apex `V_B`,
//! axis along `P_B - P_A` and half-angle `asin(R / |P_B - P_A|)`, where `R` is
//! the sum of the two radii. When the discs already overlap every velocity is
//! inside (the cone opens to the whole plane).
//!
//! ```
//! use vorrt_geometry::{VelocityObstacle, DVec2};
//! // Target 1 km north, stationary; combined radius 100 m.
//! let vo = VelocityObstacle::new(DVec2::ZERO, DVec2::new(0.0, 1000.0), DVec2::ZERO, 100.0);
//! assert!(vo.contains(DVec2::new(0.0, 5.0)));      // straight at it
//! assert!(!vo.contains(DVec2::new(5.0, 0.0)));     // due east
//! assert!(!vo.contains(DVec2::new(0.0, -5.0)));    // away
//! ```

use crate::cross;
use crate::disc::Disc;
use crate::ray::Ray;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The velocity-obstacle cone of a vessel B for a vessel A.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct VelocityObstacle {
    /// The cone's apex: B's velocity, m/s.
    pub apex_mps: DVec2,
    /// Unit vector along the cone's axis, from A toward B (zero when the centres coincide).
    pub axis: DVec2,
    /// Half-angle of the cone, radians, in `[0, π]`; π when the discs overlap.
    pub half_angle_rad: f64,
    /// True when the discs already overlap: every velocity is inside.
    pub overlapping: bool,
    /// B's position relative to A, metres.
    pub relative_position_m: DVec2,
    /// Sum of the two disc radii, metres.
    pub combined_radius_m: f64,
}

impl VelocityObstacle {
    /// The velocity obstacle of B (at `position_b_m`, moving at `velocity_b_mps`)
    /// for A (at `position_a_m`), with `combined_radius_m = r_A + r_B`.
    #[must_use]
    #[expect(
        clippy::similar_names,
        reason = "a and b name the two vessels, as P_A and P_B do in the paper"
    )]
    pub fn new(
        position_a_m: DVec2,
        position_b_m: DVec2,
        velocity_b_mps: DVec2,
        combined_radius_m: f64,
    ) -> Self {
        let combined_radius_m = combined_radius_m.max(0.0);
        let relative_position_m = position_b_m - position_a_m;
        let distance = relative_position_m.length();
        let overlapping = distance <= combined_radius_m;
        let (axis, half_angle_rad) = if overlapping {
            (relative_position_m.normalize_or_zero(), PI)
        } else {
            (
                relative_position_m / distance,
                (combined_radius_m / distance).asin(),
            )
        };
        Self {
            apex_mps: velocity_b_mps,
            axis,
            half_angle_rad,
            overlapping,
            relative_position_m,
            combined_radius_m,
        }
    }

    /// Whether keeping `velocity_a_mps` brings the discs into contact: the ray
    /// `λ(P_A, V_A - V_B)` meets `B ⊕ -A`. Closed cone; the apex itself (equal
    /// velocities) is inside only when the discs overlap.
    #[must_use]
    pub fn contains(&self, velocity_a_mps: DVec2) -> bool {
        if self.overlapping {
            return true;
        }
        let relative_velocity = velocity_a_mps - self.apex_mps;
        if relative_velocity.dot(self.relative_position_m) <= 0.0 {
            return false;
        }
        // Perpendicular distance of B's centre from the ray's line, squared, against R².
        let lever = cross(self.relative_position_m, relative_velocity);
        lever * lever
            <= self.combined_radius_m * self.combined_radius_m * relative_velocity.length_squared()
    }

    /// `VelocityObstacle::new(position_a_m, position_b_m, velocity_b_mps,
    /// combined_radius_m).contains(velocity_a_mps)` without building the cone
    /// (no `asin`): the same verdict, for callers that test one velocity.
    ///
    /// ```
    /// use vorrt_geometry::{VelocityObstacle, DVec2};
    /// let (a, b, vb, v) = (DVec2::ZERO, DVec2::new(0.0, 1000.0), DVec2::new(-1.0, 0.0), DVec2::new(-1.0, 4.0));
    /// assert_eq!(
    ///     VelocityObstacle::blocks(a, b, vb, 100.0, v),
    ///     VelocityObstacle::new(a, b, vb, 100.0).contains(v)
    /// );
    /// ```
    #[inline]
    #[must_use]
    #[expect(
        clippy::similar_names,
        reason = "a and b name the two vessels, as P_A and P_B do in the paper"
    )]
    pub fn blocks(
        position_a_m: DVec2,
        position_b_m: DVec2,
        velocity_b_mps: DVec2,
        combined_radius_m: f64,
        velocity_a_mps: DVec2,
    ) -> bool {
        let combined_radius_m = combined_radius_m.max(0.0);
        let relative_position_m = position_b_m - position_a_m;
        if relative_position_m.length() <= combined_radius_m {
            return true;
        }
        let relative_velocity = velocity_a_mps - velocity_b_mps;
        if relative_velocity.dot(relative_position_m) <= 0.0 {
            return false;
        }
        let lever = cross(relative_position_m, relative_velocity);
        lever * lever <= combined_radius_m * combined_radius_m * relative_velocity.length_squared()
    }

    /// The same test done literally as the paper states it: a ray from `P_A`
    /// along `V_A - V_B` against the Minkowski-sum disc. Slower than
    /// [`contains`](Self::contains); kept as the reference the fast test is checked against.
    #[must_use]
    pub fn contains_by_ray(&self, velocity_a_mps: DVec2) -> bool {
        let sum = Disc::new(self.relative_position_m, self.combined_radius_m);
        Ray::new(DVec2::ZERO, velocity_a_mps - self.apex_mps).intersects(&sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_discs_block_every_velocity() {
        let vo = VelocityObstacle::new(DVec2::ZERO, DVec2::new(10.0, 0.0), DVec2::ZERO, 20.0);
        assert!(vo.overlapping);
        assert!(vo.contains(DVec2::ZERO));
        assert!(vo.contains(DVec2::new(-3.0, 0.0)));
    }

    #[test]
    fn half_angle_matches_tangent_geometry() {
        let vo = VelocityObstacle::new(DVec2::ZERO, DVec2::new(0.0, 200.0), DVec2::ZERO, 100.0);
        assert!((vo.half_angle_rad - std::f64::consts::FRAC_PI_6).abs() < 1e-12);
    }

    #[test]
    fn moving_target_shifts_apex() {
        // Target 1 km north heading west at 5 m/s: matching its velocity is safe,
        // heading straight at where it is while it leaves is not inside the cone.
        let vo = VelocityObstacle::new(
            DVec2::ZERO,
            DVec2::new(0.0, 1000.0),
            DVec2::new(-5.0, 0.0),
            50.0,
        );
        assert!(!vo.contains(DVec2::new(-5.0, 0.0)));
        assert!(vo.contains(DVec2::new(-5.0, 3.0)));
        assert!(!vo.contains(DVec2::new(0.0, 3.0)));
    }

    #[test]
    fn fast_test_agrees_with_ray_test() {
        let vo = VelocityObstacle::new(
            DVec2::new(3.0, -4.0),
            DVec2::new(400.0, 900.0),
            DVec2::new(-2.0, -1.0),
            120.0,
        );
        for i in 0..72 {
            let velocity = crate::angle::velocity(f64::from(i) * 5f64.to_radians(), 6.0);
            assert_eq!(
                vo.contains(velocity),
                vo.contains_by_ray(velocity),
                "course {i}"
            );
        }
    }
}
