//! # vorrt-geometry
//!
//! Planar geometry for ship collision avoidance, in SI units (metres, seconds,
//! radians) on `f64` with [`glam::DVec2`]. The frame is x = east, y = north;
//! courses and bearings are nautical (clockwise from north).
//!
//! This crate does no I/O and knows nothing of COLREGs or planning; the layers
//! above it (`vorrt-colregs`, `vorrt-jfs`, `vorrt-planner`) build on it.
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`angle`] | course ↔ unit vector, normalisation to `[0, 2π)` and `(-π, π]`, relative bearing, signed turns |
//! | [`units`] | knots and nautical miles to SI and back |
//! | [`disc`] | [`Disc`]: a vessel's enclosing disc, its reflection `-A` and the Minkowski sum `A ⊕ B` |
//! | [`ray`] | [`Ray`]: `λ(P, V) = {P + tV, t ≥ 0}` (paper eq. 1) and its first hit on a disc |
//! | [`velocity_obstacle`] | [`VelocityObstacle`]: the cone of velocities of A that lead to contact with B (paper eq. 2) |
//! | [`cpa`] | [`Cpa`]: time and distance of closest point of approach, unbounded or over `[0, T]` (paper eqs. 3-4, sign corrected) |
//!
//! ## Example
//!
//! ```
//! use glam::DVec2;
//! use vorrt_geometry::{angle, closest_point_of_approach};
//!
//! // Ownship heads north at 6 m/s; a target 2 km to the north heads south at 4 m/s.
//! let own_velocity = angle::velocity(0.0, 6.0);
//! let target_velocity = angle::velocity(std::f64::consts::PI, 4.0);
//! let cpa = closest_point_of_approach(
//!     DVec2::ZERO, own_velocity, DVec2::new(0.0, 2000.0), target_velocity);
//! assert!((cpa.time_s - 200.0).abs() < 1e-9);
//! assert!(cpa.distance_m < 1e-9);
//! ```
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
pub use ray::Ray;
pub use velocity_obstacle::VelocityObstacle;

/// The 2-D cross product `a.x * b.y - a.y * b.x`: positive when `b` lies
/// counter-clockwise of `a` (to port, in the x-east / y-north frame).
#[inline]
#[must_use]
pub fn cross(a: DVec2, b: DVec2) -> f64 {
    a.perp_dot(b)
}
