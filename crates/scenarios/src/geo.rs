//! Geographic scenarios: positions in latitude and longitude (WGS84) and an
//! optional UTC start time, projected into the planner's flat local frame.
//!
//! A scenario is geographic when its ownship is placed with `start_lat_lon`;
//! then every vessel must be (`start_lat_lon`, `goal_lat_lon`) and none may use
//! `start_nm`/`start_m`/`goal_nm`/`goal_m`. The local frame is an azimuthal
//! equidistant projection about ownship's start ([`LocalFrame`]): east and
//! north metres, distances and bearings from the origin exact on the WGS84
//! ellipsoid (geodesics computed by `geographiclib-rs`, after Karney 2013).
//! Every position must lie within [`MAX_GEO_EXTENT_NM`] of the origin, where the
//! projection's distortion of other distances stays below 0.015 %
//! (see `docs/scenario-format.md`, "Geographic scenarios").

use geographiclib_rs::{DirectGeodesic, Geodesic, InverseGeodesic};
use time::OffsetDateTime;
use time::format_description::well_known::Rfc3339;
use vorrt_geometry::DVec2;

/// In a geographic scenario, every position must lie within this distance of
/// the origin (ownship's start), nautical miles. Within it the local frame's
/// distortion of distances between two positions stays below about 0.015 %
/// (the azimuthal equidistant scale error, `ρ²/6` for an angular distance `ρ`
/// from the origin: 1.4e-4 at 100 nm).
pub const MAX_GEO_EXTENT_NM: f64 = 100.0;

/// The planner's local frame about a geographic origin: azimuthal equidistant
/// projection on the WGS84 ellipsoid. A point's local position has the length
/// of the geodesic from the origin to it and the direction of that geodesic's
/// azimuth at the origin (east = `s sin α`, north = `s cos α`).
///
/// ```
/// use vorrt_scenarios::geo::LocalFrame;
/// let frame = LocalFrame::new(50.0, -1.0);
/// let east_m = frame.to_local_m(50.0, -0.9);
/// assert!((east_m.x - 7_170.0).abs() < 10.0 && east_m.y > 0.0);
/// let (lat_deg, lon_deg) = frame.to_lat_lon_deg(east_m);
/// assert!((lat_deg - 50.0).abs() < 1e-9 && (lon_deg + 0.9).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalFrame {
    origin_lat_deg: f64,
    origin_lon_deg: f64,
    ellipsoid: Geodesic,
}

impl LocalFrame {
    /// The frame about `(origin_lat_deg, origin_lon_deg)`, degrees WGS84.
    /// The origin is taken as given; check it with [`check_lat_lon`] first.
    #[must_use]
    pub fn new(origin_lat_deg: f64, origin_lon_deg: f64) -> Self {
        Self {
            origin_lat_deg,
            origin_lon_deg,
            ellipsoid: Geodesic::wgs84(),
        }
    }

    /// The origin, `(latitude, longitude)` in degrees.
    #[must_use]
    pub fn origin_lat_lon_deg(&self) -> (f64, f64) {
        (self.origin_lat_deg, self.origin_lon_deg)
    }

    /// The local position `(east, north)` in metres of a point given in degrees.
    #[must_use]
    pub fn to_local_m(&self, lat_deg: f64, lon_deg: f64) -> DVec2 {
        let (distance_m, azimuth_deg, _, _): (f64, f64, f64, f64) =
            self.ellipsoid
                .inverse(self.origin_lat_deg, self.origin_lon_deg, lat_deg, lon_deg);
        let azimuth_rad = azimuth_deg.to_radians();
        DVec2::new(
            distance_m * azimuth_rad.sin(),
            distance_m * azimuth_rad.cos(),
        )
    }

    /// The point `(latitude, longitude)` in degrees of a local position in
    /// metres; longitudes come back in `[-180, 180]`.
    #[must_use]
    pub fn to_lat_lon_deg(&self, position_m: DVec2) -> (f64, f64) {
        let distance_m = position_m.length();
        let azimuth_deg = position_m.x.atan2(position_m.y).to_degrees();
        self.ellipsoid.direct(
            self.origin_lat_deg,
            self.origin_lon_deg,
            azimuth_deg,
            distance_m,
        )
    }
}

/// Checks a `(latitude, longitude)` pair in degrees: both finite, latitude in
/// `[-90, 90]`, longitude in `[-180, 180]`.
///
/// # Errors
/// What is wrong, as a phrase that follows the field name.
pub fn check_lat_lon((lat_deg, lon_deg): (f64, f64)) -> Result<(), String> {
    if !(lat_deg.is_finite() && lon_deg.is_finite()) {
        return Err(format!(
            "holds ({lat_deg}, {lon_deg}), not two finite numbers (latitude, longitude in degrees)"
        ));
    }
    if !(-90.0..=90.0).contains(&lat_deg) {
        return Err(format!(
            "has latitude {lat_deg}, expected degrees in [-90, 90]"
        ));
    }
    if !(-180.0..=180.0).contains(&lon_deg) {
        return Err(format!(
            "has longitude {lon_deg}, expected degrees in [-180, 180]"
        ));
    }
    Ok(())
}

/// Parses an ISO 8601 (RFC 3339) time such as `2024-05-01T12:00:00Z`,
/// converted to UTC.
///
/// # Errors
/// What is wrong, as a phrase that follows the field name.
pub fn parse_utc_time(text: &str) -> Result<OffsetDateTime, String> {
    OffsetDateTime::parse(text, &Rfc3339)
        .map(|time| time.to_offset(time::UtcOffset::UTC))
        .map_err(|error| {
            format!("is {text:?}, not an ISO 8601 time like 2024-05-01T12:00:00Z ({error})")
        })
}

/// Formats a UTC time as ISO 8601 (RFC 3339), e.g. `2024-05-01T12:00:00Z`.
#[must_use]
pub fn format_utc_time(time: OffsetDateTime) -> String {
    time.to_offset(time::UtcOffset::UTC)
        .format(&Rfc3339)
        .unwrap_or_else(|_| time.unix_timestamp().to_string())
}

/// The local positions of a vessel's `start_lat_lon` and `goal_lat_lon`,
/// metres `(east, north)`: derived from them by
/// [`Scenario::validate`](crate::Scenario::validate), not part of the file.
/// Empty in a local scenario.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ProjectedPositions {
    /// `start_lat_lon` in the local frame, metres.
    pub start_m: Option<DVec2>,
    /// `goal_lat_lon` in the local frame, metres.
    pub goal_m: Option<DVec2>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use vorrt_geometry::units;

    proptest! {
        /// Local -> geographic -> local comes back within 1 m (in fact within
        /// micrometres) anywhere within 50 nm of any origin off the poles.
        #[test]
        fn round_trip_within_a_metre(
            origin_lat_deg in -85.0..85.0f64,
            origin_lon_deg in -180.0..180.0f64,
            distance_nm in 0.0..50.0f64,
            bearing_deg in 0.0..360.0f64,
        ) {
            let frame = LocalFrame::new(origin_lat_deg, origin_lon_deg);
            let bearing = bearing_deg.to_radians();
            let local_m = DVec2::new(bearing.sin(), bearing.cos()) * distance_nm * units::NAUTICAL_MILE_M;
            let (lat_deg, lon_deg) = frame.to_lat_lon_deg(local_m);
            prop_assert!(check_lat_lon((lat_deg, lon_deg)).is_ok());
            let back_m = frame.to_local_m(lat_deg, lon_deg);
            prop_assert!(back_m.distance(local_m) < 1.0, "{local_m} -> {back_m}");
            // And geographic -> local -> geographic, on the ellipsoid.
            let (lat2, lon2) = frame.to_lat_lon_deg(frame.to_local_m(lat_deg, lon_deg));
            let ground_m = frame.to_local_m(lat2, lon2).distance(back_m);
            prop_assert!(ground_m < 1.0);
        }

        /// Distances from the origin are the geodesic distances: one degree
        /// of latitude north is about 111 km everywhere.
        #[test]
        fn north_is_north(origin_lat_deg in -80.0..80.0f64, origin_lon_deg in -180.0..180.0f64) {
            let frame = LocalFrame::new(origin_lat_deg, origin_lon_deg);
            let north = frame.to_local_m(origin_lat_deg + 0.5, origin_lon_deg);
            prop_assert!(north.x.abs() < 1e-6 && (55_000.0..56_000.0).contains(&north.y));
        }
    }

    #[test]
    fn known_geodesic() {
        // One minute of latitude centred on 45° N is 1852.2 m on WGS84.
        let frame = LocalFrame::new(44.991_666_666_666_67, 0.0);
        let north_m = frame.to_local_m(45.008_333_333_333_33, 0.0);
        assert!((north_m.y - 1852.2).abs() < 0.1, "{north_m}");
    }

    #[test]
    fn bad_coordinates_are_named() {
        assert!(
            check_lat_lon((91.0, 0.0))
                .unwrap_err()
                .contains("latitude 91")
        );
        assert!(
            check_lat_lon((0.0, 181.0))
                .unwrap_err()
                .contains("longitude")
        );
        assert!(
            check_lat_lon((f64::NAN, 0.0))
                .unwrap_err()
                .contains("finite")
        );
        assert!(check_lat_lon((-90.0, 180.0)).is_ok());
    }

    #[test]
    fn times_parse_as_utc() {
        let time = parse_utc_time("2024-05-01T14:00:00+02:00").unwrap();
        assert_eq!(format_utc_time(time), "2024-05-01T12:00:00Z");
        assert!(
            parse_utc_time("yesterday")
                .unwrap_err()
                .contains("ISO 8601")
        );
    }
}
