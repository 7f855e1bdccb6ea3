//! Closest point of approach (paper, eqs. 3-4, with erratum 1 applied).
//!
//! With `p = P_A - P_B` and `v = V_A - V_B`, the time of closest approach is
//! `t_cpa = -(p · v) / |v|²` (the paper drops the minus sign), or 0 when
//! `|v| = 0`. It is clamped to `t ≥ 0` (a CPA in the past means the vessels
//! are opening) and, over a segment of duration `T`, to `[0, T]`. The distance
//! is `d_cpa = |p + t_cpa v|`.
//!
//! ```
//! use vorrt_geometry::{closest_point_of_approach, closest_point_of_approach_within, DVec2};
//! // A target 1 km east heading west at 5 m/s while ownship heads north at 5 m/s.
//! let cpa = closest_point_of_approach(
//!     DVec2::ZERO, DVec2::new(0.0, 5.0), DVec2::new(1000.0, 0.0), DVec2::new(-5.0, 0.0));
//! assert!((cpa.time_s - 100.0).abs() < 1e-9);
//! assert!((cpa.distance_m - 500.0 * 2f64.sqrt()).abs() < 1e-9);
//! // Over only the first 50 s the closest point is the segment's end.
//! let early = closest_point_of_approach_within(
//!     DVec2::ZERO, DVec2::new(0.0, 5.0), DVec2::new(1000.0, 0.0), DVec2::new(-5.0, 0.0), 50.0);
//! assert_eq!(early.time_s, 50.0);
//! ```

use glam::DVec2;
use serde::{Deserialize, Serialize};

/// Time and distance of the closest point of approach of two vessels moving at
/// constant velocity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Cpa {
    /// Seconds from now until the closest approach; never negative.
    pub time_s: f64,
    /// Distance between the two reference points at that time, metres.
    pub distance_m: f64,
}

/// The CPA over the unbounded future `t ≥ 0`.
#[must_use]
#[expect(
    clippy::similar_names,
    reason = "a and b name the two vessels, as P_A and P_B do in the paper"
)]
pub fn closest_point_of_approach(
    position_a_m: DVec2,
    velocity_a_mps: DVec2,
    position_b_m: DVec2,
    velocity_b_mps: DVec2,
) -> Cpa {
    cpa_clamped(
        position_a_m - position_b_m,
        velocity_a_mps - velocity_b_mps,
        f64::INFINITY,
    )
}

/// The CPA over the segment `t ∈ [0, horizon_s]` (a non-positive or NaN
/// horizon gives the present distance at `t = 0`).
#[must_use]
#[expect(
    clippy::similar_names,
    reason = "a and b name the two vessels, as P_A and P_B do in the paper"
)]
pub fn closest_point_of_approach_within(
    position_a_m: DVec2,
    velocity_a_mps: DVec2,
    position_b_m: DVec2,
    velocity_b_mps: DVec2,
    horizon_s: f64,
) -> Cpa {
    cpa_clamped(
        position_a_m - position_b_m,
        velocity_a_mps - velocity_b_mps,
        if horizon_s > 0.0 { horizon_s } else { 0.0 },
    )
}

/// CPA of a relative position and velocity, with `t_cpa` clamped to `[0, max_time_s]`.
#[inline]
#[must_use]
pub fn cpa_clamped(
    relative_position_m: DVec2,
    relative_velocity_mps: DVec2,
    max_time_s: f64,
) -> Cpa {
    let speed_squared = relative_velocity_mps.length_squared();
    let time_s = if speed_squared > 0.0 {
        (-relative_position_m.dot(relative_velocity_mps) / speed_squared).clamp(0.0, max_time_s)
    } else {
        0.0
    };
    Cpa {
        time_s,
        distance_m: (relative_position_m + relative_velocity_mps * time_s).length(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn opening_vessels_have_cpa_now() {
        let cpa = closest_point_of_approach(
            DVec2::ZERO,
            DVec2::new(0.0, -1.0),
            DVec2::new(0.0, 100.0),
            DVec2::new(0.0, 1.0),
        );
        assert_eq!(cpa.time_s, 0.0);
        assert_eq!(cpa.distance_m, 100.0);
    }

    #[test]
    fn equal_velocities_keep_distance() {
        let cpa = closest_point_of_approach(
            DVec2::ZERO,
            DVec2::new(3.0, 4.0),
            DVec2::new(30.0, 40.0),
            DVec2::new(3.0, 4.0),
        );
        assert_eq!(
            cpa,
            Cpa {
                time_s: 0.0,
                distance_m: 50.0
            }
        );
    }

    #[test]
    fn head_on_collision_time() {
        let cpa = closest_point_of_approach(
            DVec2::ZERO,
            DVec2::new(0.0, 5.0),
            DVec2::new(0.0, 1000.0),
            DVec2::new(0.0, -5.0),
        );
        assert!((cpa.time_s - 100.0).abs() < 1e-12);
        assert!(cpa.distance_m < 1e-9);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn nan_horizon_is_now() {
        let cpa = closest_point_of_approach_within(
            DVec2::ZERO,
            DVec2::new(0.0, 5.0),
            DVec2::new(0.0, 1000.0),
            DVec2::ZERO,
            f64::NAN,
        );
        assert_eq!(cpa.time_s, 0.0);
    }
}
