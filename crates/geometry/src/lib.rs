#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub mod angle;
pub mod cpa;
pub mod disc;
pub mod ray;
pub mod units;
pub mod velocity_obstacle;

pub use cpa::{Cpa, closest_point_of_approach, closest_point_of_approach_within};
pub use disc::Disc;
pub use glam::DVec2;
// Every position and velocity here is a `glam::DVec2`: a user of this crate
// alone reaches glam through it.
pub use glam;
pub use ray::Ray;
pub use velocity_obstacle::VelocityObstacle;

/// The 2-D cross product `a.x * b.y - a.y * b.x`: positive when `b` lies
/// counter-clockwise of `a` (to port, in the x-east / y-north frame).
#[inline]
#[must_use]
pub fn cross(a: DVec2, b: DVec2) -> f64 {
    a.perp_dot(b)
}
