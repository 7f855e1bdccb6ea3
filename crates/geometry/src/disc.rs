//! Discs: the shape the paper gives every vessel.
//!
//! The paper encloses each vessel in a disc whose radius is the vessel's length
//! (notes, erratum 7). The velocity obstacle is built on the Minkowski sum
//! `B ⊕ -A`, which for discs is again a disc: centred at `c_B - c_A` (or at
//! `c_B` when `A` is reflected in its own reference point) with the radii added.
//!
//! ```
//! use vorrt_geometry::{Disc, DVec2};
//! let own = Disc::new(DVec2::ZERO, 50.0);
//! let target = Disc::new(DVec2::new(300.0, 0.0), 80.0);
//! let sum = target.minkowski_sum(&own.reflected());
//! assert_eq!(sum.radius_m, 130.0);
//! assert!(sum.contains(DVec2::new(200.0, 0.0)));
//! ```

use glam::DVec2;
use serde::{Deserialize, Serialize};

/// A closed disc in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Disc {
    /// Centre, metres (x east, y north).
    pub center_m: DVec2,
    /// Radius, metres; never negative.
    pub radius_m: f64,
}

impl Disc {
    /// A disc at `center_m` with `radius_m` (negative radii are taken as 0).
    #[must_use]
    pub fn new(center_m: DVec2, radius_m: f64) -> Self {
        Self {
            center_m,
            radius_m: radius_m.max(0.0),
        }
    }

    /// `-A`: the disc reflected through the origin of its reference frame.
    #[must_use]
    pub fn reflected(&self) -> Self {
        Self::new(-self.center_m, self.radius_m)
    }

    /// `A ⊕ B = {a + b | a ∈ A, b ∈ B}`: for discs, centres and radii add.
    #[must_use]
    pub fn minkowski_sum(&self, other: &Disc) -> Self {
        Self::new(
            self.center_m + other.center_m,
            self.radius_m + other.radius_m,
        )
    }

    /// Whether `point_m` lies in the closed disc.
    #[must_use]
    pub fn contains(&self, point_m: DVec2) -> bool {
        self.center_m.distance_squared(point_m) <= self.radius_m * self.radius_m
    }

    /// Whether two closed discs share a point.
    #[must_use]
    pub fn overlaps(&self, other: &Disc) -> bool {
        let reach = self.radius_m + other.radius_m;
        self.center_m.distance_squared(other.center_m) <= reach * reach
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn minkowski_sum_of_reflection_is_centred_on_difference() {
        let a = Disc::new(DVec2::new(10.0, 5.0), 3.0);
        let b = Disc::new(DVec2::new(40.0, -5.0), 4.0);
        let sum = b.minkowski_sum(&a.reflected());
        assert_eq!(sum.center_m, DVec2::new(30.0, -10.0));
        assert_eq!(sum.radius_m, 7.0);
    }

    #[test]
    fn overlap_is_symmetric_and_touching_counts() {
        let a = Disc::new(DVec2::ZERO, 1.0);
        let b = Disc::new(DVec2::new(2.0, 0.0), 1.0);
        assert!(a.overlaps(&b) && b.overlaps(&a));
        assert!(!a.overlaps(&Disc::new(DVec2::new(2.1, 0.0), 1.0)));
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn negative_radius_clamps_to_zero() {
        assert_eq!(Disc::new(DVec2::ZERO, -2.0).radius_m, 0.0);
    }
}
