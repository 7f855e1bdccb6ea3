//! Mariners' units and SI.
//!
//! Scenario files carry knots, nautical miles and degrees; code works in metres,
//! metres per second and radians. 1 kn = 1852/3600 m/s; 1 nm = 1852 m.
//!
//! ```
//! use vorrt_geometry::units;
//! assert!((units::knots_to_mps(12.0) - 6.173_333).abs() < 1e-6);
//! assert_eq!(units::nautical_miles_to_m(1.0), 1852.0);
//! ```

/// Metres in one international nautical mile.
pub const NAUTICAL_MILE_M: f64 = 1852.0;

/// Metres per second in one knot.
pub const KNOT_MPS: f64 = NAUTICAL_MILE_M / 3600.0;

/// Knots to metres per second.
#[inline]
#[must_use]
pub fn knots_to_mps(speed_kn: f64) -> f64 {
    speed_kn * KNOT_MPS
}

/// Metres per second to knots.
#[inline]
#[must_use]
pub fn mps_to_knots(speed_mps: f64) -> f64 {
    speed_mps / KNOT_MPS
}

/// Nautical miles to metres.
#[inline]
#[must_use]
pub fn nautical_miles_to_m(distance_nm: f64) -> f64 {
    distance_nm * NAUTICAL_MILE_M
}

/// Metres to nautical miles.
#[inline]
#[must_use]
pub fn m_to_nautical_miles(distance_m: f64) -> f64 {
    distance_m / NAUTICAL_MILE_M
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips() {
        assert!((mps_to_knots(knots_to_mps(17.5)) - 17.5).abs() < 1e-12);
        assert!((m_to_nautical_miles(nautical_miles_to_m(3.2)) - 3.2).abs() < 1e-12);
    }
}
