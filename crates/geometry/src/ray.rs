//! Rays `λ(P, V) = {P + tV | t ≥ 0}` (paper, eq. 1).
//!
//! The velocity obstacle asks whether the ray from ownship's position along the
//! relative velocity meets the Minkowski-sum disc around the target.
//!
//! ```
//! use vorrt_geometry::{Disc, Ray, DVec2};
//! let ray = Ray::new(DVec2::ZERO, DVec2::new(1.0, 0.0));
//! let disc = Disc::new(DVec2::new(10.0, 0.0), 2.0);
//! assert_eq!(ray.first_hit(&disc), Some(8.0));
//! assert!(Ray::new(DVec2::ZERO, DVec2::new(-1.0, 0.0)).first_hit(&disc).is_none());
//! ```

use crate::disc::Disc;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// A ray from `origin_m` along `direction` (not necessarily unit length: the
/// parameter `t` of a hit is in units of `direction`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Ray {
    /// Where the ray starts, metres.
    pub origin_m: DVec2,
    /// The direction of travel; the zero vector makes a ray that stays at its origin.
    pub direction: DVec2,
}

impl Ray {
    /// The ray `λ(origin, direction)`.
    #[must_use]
    pub fn new(origin_m: DVec2, direction: DVec2) -> Self {
        Self {
            origin_m,
            direction,
        }
    }

    /// The point at parameter `t`.
    #[must_use]
    pub fn at(&self, t: f64) -> DVec2 {
        self.origin_m + self.direction * t
    }

    /// The smallest `t ≥ 0` at which the ray is in the closed disc, if any.
    /// A ray that starts inside the disc hits it at `t = 0`.
    #[must_use]
    pub fn first_hit(&self, disc: &Disc) -> Option<f64> {
        let offset = self.origin_m - disc.center_m;
        let c = offset.length_squared() - disc.radius_m * disc.radius_m;
        if c <= 0.0 {
            return Some(0.0);
        }
        let a = self.direction.length_squared();
        if a == 0.0 {
            return None;
        }
        let half_b = offset.dot(self.direction);
        if half_b >= 0.0 {
            // Moving away from (or tangentially past) the centre, starting outside.
            return None;
        }
        let discriminant = half_b * half_b - a * c;
        if discriminant < 0.0 {
            return None;
        }
        // The nearer root, in the cancellation-free form c / q.
        let q = -half_b + discriminant.sqrt();
        Some(c / q)
    }

    /// Whether the ray meets the closed disc.
    #[must_use]
    pub fn intersects(&self, disc: &Disc) -> bool {
        self.first_hit(disc).is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ray_starting_inside_hits_at_zero() {
        let disc = Disc::new(DVec2::ZERO, 5.0);
        assert_eq!(
            Ray::new(DVec2::new(1.0, 1.0), DVec2::X).first_hit(&disc),
            Some(0.0)
        );
    }

    #[test]
    fn tangent_ray_touches() {
        let disc = Disc::new(DVec2::new(10.0, 1.0), 1.0);
        let hit = Ray::new(DVec2::ZERO, DVec2::X)
            .first_hit(&disc)
            .expect("tangent");
        assert!((hit - 10.0).abs() < 1e-6);
    }

    #[test]
    fn ray_that_misses() {
        let disc = Disc::new(DVec2::new(10.0, 3.0), 1.0);
        assert!(!Ray::new(DVec2::ZERO, DVec2::X).intersects(&disc));
    }

    #[test]
    fn zero_direction_only_hits_when_inside() {
        let disc = Disc::new(DVec2::new(10.0, 0.0), 1.0);
        assert!(!Ray::new(DVec2::ZERO, DVec2::ZERO).intersects(&disc));
    }
}
