//! The kinematic state of one vessel.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::{Disc, angle};

/// Position, course, speed and size of a vessel at one instant.
///
/// ```
/// use vorrt_colregs::VesselState;
/// use glam::DVec2;
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let target = VesselState::new(DVec2::new(1000.0, 0.0), std::f64::consts::PI, 5.0, 80.0);
/// assert!((own.bearing_to(&target).to_degrees() - 90.0).abs() < 1e-9);
/// assert!((target.bearing_to(&own).to_degrees() - 90.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct VesselState {
    /// Position, metres (x east, y north).
    pub position_m: DVec2,
    /// Course over ground, radians clockwise from north.
    pub course_rad: f64,
    /// Speed over ground, metres per second.
    pub speed_mps: f64,
    /// Length overall, metres; the paper's disc radius (erratum 7).
    pub length_m: f64,
}

impl VesselState {
    /// A vessel state from its parts.
    #[must_use]
    pub fn new(position_m: DVec2, course_rad: f64, speed_mps: f64, length_m: f64) -> Self {
        Self {
            position_m,
            course_rad,
            speed_mps,
            length_m,
        }
    }

    /// Velocity over ground, m/s: `speed · (sin c, cos c)`.
    #[must_use]
    pub fn velocity_mps(&self) -> DVec2 {
        angle::velocity(self.course_rad, self.speed_mps)
    }

    /// The vessel's enclosing disc (radius = length, as in the paper).
    #[must_use]
    pub fn disc(&self) -> Disc {
        Disc::new(self.position_m, self.length_m)
    }

    /// Relative bearing of `other` from this vessel, radians in `[0, 2π)`.
    #[must_use]
    pub fn bearing_to(&self, other: &VesselState) -> f64 {
        angle::relative_bearing(self.position_m, self.course_rad, other.position_m)
    }

    /// Distance to `other`, metres.
    #[must_use]
    pub fn range_to(&self, other: &VesselState) -> f64 {
        self.position_m.distance(other.position_m)
    }

    /// The state after `duration_s` at constant course and speed.
    #[must_use]
    pub fn advanced(&self, duration_s: f64) -> Self {
        Self {
            position_m: self.position_m + self.velocity_mps() * duration_s,
            ..*self
        }
    }

    /// Whether every number is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.position_m.is_finite()
            && self.course_rad.is_finite()
            && self.speed_mps.is_finite()
            && self.length_m.is_finite()
    }
}
