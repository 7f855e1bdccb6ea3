//! Coastlines for geographic scenarios: land polygons in longitude and
//! latitude clipped to a bounding box, simplified to a tolerance in metres
//! and written as `GeoJSON` (RFC 7946), the file a scenario's `land_geojson`
//! names.
//!
//! The readers of coastline files (`GeoJSON`, `TopoJSON`, ESRI shapefiles) are
//! the command line's (`vorrt coast`); this module is the geometry, which
//! reads nothing: [`prepare_coast`] clips ([`clip_to_bbox`]), projects into
//! a local metric frame about the box's centre ([`LocalFrame`]), simplifies
//! with Douglas-Peucker at the tolerance while keeping every ring valid
//! ([`simplify_land_m`]), drops slivers below a minimum area, and projects
//! back. Why these choices: `docs/decisions/0038-coastline-sources-and-simplification.md`.
//!
//! ```
//! use geo::{MultiPolygon, polygon};
//! use vorrt_scenarios::coastline::{BoundingBox, CoastOptions, prepare_coast};
//! // A square island of 0.2 degrees, half of it inside the box.
//! let island = polygon![(x: 1.0, y: 50.0), (x: 1.2, y: 50.0), (x: 1.2, y: 50.2), (x: 1.0, y: 50.2)];
//! let bbox = BoundingBox::new(1.1, 49.9, 1.4, 50.3).unwrap();
//! let coast = prepare_coast(&MultiPolygon::new(vec![island]), &CoastOptions::new(bbox, 50.0)).unwrap();
//! assert_eq!(coast.land_lon_lat.0.len(), 1);
//! assert_eq!(coast.stats.polygons_out, 1);
//! ```

mod clip;
mod geojson;
mod simplify;

pub use clip::clip_to_bbox;
pub use geojson::to_geojson_string;
pub use simplify::{SimplifyStats, simplify_land_m};

use crate::geo::LocalFrame;
use ::geo::orient::{Direction, Orient};
use ::geo::{Coord, CoordsIter, LineString, MultiPolygon, Polygon};
use thiserror::Error;

/// The tolerance `vorrt coast` simplifies to unless told otherwise, metres:
/// well under the 500 m a harbour approach keeps from land (decision 38), and
/// below the scale of Natural Earth's 1:10m data (about 1 km), so that data
/// passes almost unchanged while full-resolution GSHHS shrinks.
pub const DEFAULT_TOLERANCE_M: f64 = 50.0;

/// The widest bounding box accepted, degrees of latitude or longitude: the
/// simplification runs in one azimuthal equidistant frame about the box's
/// centre, whose scale error at 5 degrees (about 300 nm) from it is 0.25 %
/// (`ρ²/6`), small against any tolerance; wider areas are not what a
/// scenario's coast is for.
pub const MAX_BBOX_SPAN_DEG: f64 = 10.0;

/// Why a coastline could not be prepared.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum CoastlineError {
    /// A bounding box is malformed or out of range.
    #[error("bounding box {text}: {problem}")]
    BadBbox {
        /// The box as given.
        text: String,
        /// What is wrong with it.
        problem: String,
    },
    /// The tolerance or the minimum area is not a finite number >= 0.
    #[error("{field} is {value}, expected a finite number >= 0")]
    BadOption {
        /// The option (`tolerance_m`, `min_area_m2`).
        field: &'static str,
        /// The value given.
        value: f64,
    },
}

/// A box in longitude and latitude, degrees WGS84: west < east, south <
/// north, neither side wider than [`MAX_BBOX_SPAN_DEG`]. A box across the
/// antimeridian is not supported.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox {
    /// Western edge, degrees east in `[-180, 180]`.
    pub west_deg: f64,
    /// Southern edge, degrees north in `[-90, 90]`.
    pub south_deg: f64,
    /// Eastern edge, degrees east, greater than `west_deg`.
    pub east_deg: f64,
    /// Northern edge, degrees north, greater than `south_deg`.
    pub north_deg: f64,
}

impl BoundingBox {
    /// The box with these edges, checked.
    ///
    /// # Errors
    /// [`CoastlineError::BadBbox`] when an edge is not finite, out of range,
    /// the edges are in the wrong order or the box is wider than
    /// [`MAX_BBOX_SPAN_DEG`].
    pub fn new(
        west_deg: f64,
        south_deg: f64,
        east_deg: f64,
        north_deg: f64,
    ) -> Result<Self, CoastlineError> {
        let bad = |problem: &str| CoastlineError::BadBbox {
            text: format!("{west_deg},{south_deg},{east_deg},{north_deg}"),
            problem: problem.to_owned(),
        };
        let edges = [west_deg, south_deg, east_deg, north_deg];
        if edges.iter().any(|edge| !edge.is_finite()) {
            return Err(bad("has an edge that is not a finite number"));
        }
        if ![west_deg, east_deg]
            .iter()
            .all(|lon| (-180.0..=180.0).contains(lon))
        {
            return Err(bad("has a longitude outside [-180, 180]"));
        }
        if ![south_deg, north_deg]
            .iter()
            .all(|lat| (-90.0..=90.0).contains(lat))
        {
            return Err(bad("has a latitude outside [-90, 90]"));
        }
        if west_deg >= east_deg || south_deg >= north_deg {
            return Err(bad(
                "needs west < east and south < north (WEST,SOUTH,EAST,NORTH; boxes across the antimeridian are not supported)",
            ));
        }
        if east_deg - west_deg > MAX_BBOX_SPAN_DEG || north_deg - south_deg > MAX_BBOX_SPAN_DEG {
            return Err(bad(&format!(
                "is wider than {MAX_BBOX_SPAN_DEG} degrees, more than one local frame should span"
            )));
        }
        Ok(Self {
            west_deg,
            south_deg,
            east_deg,
            north_deg,
        })
    }

    /// Parses `WEST,SOUTH,EAST,NORTH` in degrees (the order of `GeoJSON`'s
    /// `bbox`, RFC 7946 section 5), e.g. `1.0,50.8,2.0,51.3`.
    ///
    /// # Errors
    /// [`CoastlineError::BadBbox`] when the text is not four numbers or
    /// [`BoundingBox::new`] refuses them.
    pub fn parse(text: &str) -> Result<Self, CoastlineError> {
        let numbers: Result<Vec<f64>, _> =
            text.split(',').map(|part| part.trim().parse()).collect();
        match numbers.as_deref() {
            Ok(&[west, south, east, north]) => Self::new(west, south, east, north),
            _ => Err(CoastlineError::BadBbox {
                text: text.to_owned(),
                problem:
                    "is not four numbers WEST,SOUTH,EAST,NORTH in degrees (e.g. 1.0,50.8,2.0,51.3)"
                        .into(),
            }),
        }
    }

    /// The smallest box holding every `(latitude, longitude)` point, grown by
    /// `margin_m` on every side (metres along the meridian, and along the
    /// parallel at the box's most poleward latitude, so that the margin is at
    /// least `margin_m` everywhere).
    ///
    /// # Errors
    /// [`CoastlineError::BadBbox`] when there are no points, a point is not a
    /// valid position, or the grown box is refused by [`BoundingBox::new`].
    pub fn around(points_lat_lon: &[(f64, f64)], margin_m: f64) -> Result<Self, CoastlineError> {
        let bad = |problem: String| CoastlineError::BadBbox {
            text: format!("around {} points", points_lat_lon.len()),
            problem,
        };
        if points_lat_lon.is_empty() {
            return Err(bad("has no points".into()));
        }
        if !(margin_m.is_finite() && margin_m >= 0.0) {
            return Err(bad(format!("has margin {margin_m} m, expected >= 0")));
        }
        for &point in points_lat_lon {
            crate::geo::check_lat_lon(point).map_err(|problem| bad(format!("point {problem}")))?;
        }
        let (mut south, mut north, mut west, mut east) =
            (90.0_f64, -90.0_f64, 180.0_f64, -180.0_f64);
        for &(lat, lon) in points_lat_lon {
            south = south.min(lat);
            north = north.max(lat);
            west = west.min(lon);
            east = east.max(lon);
        }
        // One degree of latitude is at least 110.5 km on WGS84; a degree of
        // longitude is that times cos(latitude) at most 111.4 km.
        let margin_lat_deg = margin_m / 110_500.0;
        let poleward_deg = south.abs().max(north.abs()) + margin_lat_deg;
        let cos_lat = poleward_deg.min(89.0).to_radians().cos();
        let margin_lon_deg = margin_m / (111_400.0 * cos_lat);
        Self::new(
            (west - margin_lon_deg).max(-180.0),
            (south - margin_lat_deg).max(-90.0),
            (east + margin_lon_deg).min(180.0),
            (north + margin_lat_deg).min(90.0),
        )
    }

    /// The box's centre `(latitude, longitude)`, degrees: the origin of the
    /// frame in which [`prepare_coast`] simplifies.
    #[must_use]
    pub fn centre_lat_lon_deg(&self) -> (f64, f64) {
        (
            0.5 * (self.south_deg + self.north_deg),
            0.5 * (self.west_deg + self.east_deg),
        )
    }

    /// The box as a polygon in `(longitude, latitude)`, counter-clockwise.
    #[must_use]
    pub fn to_polygon(&self) -> Polygon<f64> {
        Polygon::new(
            LineString::from(vec![
                (self.west_deg, self.south_deg),
                (self.east_deg, self.south_deg),
                (self.east_deg, self.north_deg),
                (self.west_deg, self.north_deg),
            ]),
            Vec::new(),
        )
    }

    /// Whether a `(longitude, latitude)` point lies in the box (edges included).
    #[must_use]
    pub fn contains_lon_lat(&self, point: Coord<f64>) -> bool {
        (self.west_deg..=self.east_deg).contains(&point.x)
            && (self.south_deg..=self.north_deg).contains(&point.y)
    }
}

/// What [`prepare_coast`] does: the box, the tolerance, the sliver limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoastOptions {
    /// The area to keep.
    pub bbox: BoundingBox,
    /// Douglas-Peucker tolerance, metres: no vertex of the clipped coast ends
    /// farther than this from the simplified one (0 keeps every vertex).
    pub tolerance_m: f64,
    /// Polygons and holes smaller than this are dropped, square metres.
    pub min_area_m2: f64,
}

impl CoastOptions {
    /// The options for `bbox` at `tolerance_m`, dropping pieces smaller than
    /// a square one tolerance on a side (`min_area_m2 = tolerance_m²`): what
    /// the simplification cannot draw at that tolerance.
    #[must_use]
    pub fn new(bbox: BoundingBox, tolerance_m: f64) -> Self {
        Self {
            bbox,
            tolerance_m,
            min_area_m2: tolerance_m * tolerance_m,
        }
    }
}

/// What [`prepare_coast`] made, with its counts.
#[derive(Debug, Clone, PartialEq)]
pub struct Coast {
    /// The land, `(longitude, latitude)` degrees, outer rings
    /// counter-clockwise and holes clockwise (RFC 7946 section 3.1.6).
    pub land_lon_lat: MultiPolygon<f64>,
    /// How many polygons and vertices each stage kept.
    pub stats: CoastStats,
}

/// Counts of [`prepare_coast`]'s stages.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CoastStats {
    /// Polygons given.
    pub polygons_in: usize,
    /// Vertices given (ring-closing repeats included).
    pub vertices_in: usize,
    /// Polygons left after clipping to the box.
    pub polygons_clipped: usize,
    /// Vertices left after clipping.
    pub vertices_clipped: usize,
    /// Polygons written.
    pub polygons_out: usize,
    /// Vertices written.
    pub vertices_out: usize,
    /// The simplification's own counts.
    pub simplify: SimplifyStats,
}

/// Clips `land_lon_lat` to the options' box, simplifies it in metres and
/// returns it in longitude and latitude. An empty result (no land in the box)
/// is not an error: the caller decides whether to warn.
///
/// # Errors
/// [`CoastlineError::BadOption`] when the tolerance or the minimum area is
/// negative or not finite.
pub fn prepare_coast(
    land_lon_lat: &MultiPolygon<f64>,
    options: &CoastOptions,
) -> Result<Coast, CoastlineError> {
    for (field, value) in [
        ("tolerance_m", options.tolerance_m),
        ("min_area_m2", options.min_area_m2),
    ] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(CoastlineError::BadOption { field, value });
        }
    }
    let clipped = clip_to_bbox(land_lon_lat, &options.bbox);
    let (lat0, lon0) = options.bbox.centre_lat_lon_deg();
    let frame = LocalFrame::new(lat0, lon0);
    let land_m = map_coords(&clipped, |coord| {
        let position_m = frame.to_local_m(coord.y, coord.x);
        Coord {
            x: position_m.x,
            y: position_m.y,
        }
    });
    let (simplified_m, simplify) =
        simplify_land_m(&land_m, options.tolerance_m, options.min_area_m2);
    let land_lon_lat_out = map_coords(&simplified_m, |coord| {
        let (lat, lon) = frame.to_lat_lon_deg(crate::DVec2::new(coord.x, coord.y));
        // The round trip through the frame moves a point by micrometres; keep
        // the edges of the box exactly on it.
        let bbox = &options.bbox;
        Coord {
            x: lon.clamp(bbox.west_deg, bbox.east_deg),
            y: lat.clamp(bbox.south_deg, bbox.north_deg),
        }
    })
    .orient(Direction::Default);
    let stats = CoastStats {
        polygons_in: land_lon_lat.0.len(),
        vertices_in: land_lon_lat.coords_count(),
        polygons_clipped: clipped.0.len(),
        vertices_clipped: clipped.coords_count(),
        polygons_out: land_lon_lat_out.0.len(),
        vertices_out: land_lon_lat_out.coords_count(),
        simplify,
    };
    Ok(Coast {
        land_lon_lat: land_lon_lat_out,
        stats,
    })
}

/// Every coordinate of `land` through `map`, ring structure kept.
fn map_coords(
    land: &MultiPolygon<f64>,
    map: impl Fn(Coord<f64>) -> Coord<f64>,
) -> MultiPolygon<f64> {
    let ring = |ring: &LineString<f64>| {
        ring.0
            .iter()
            .map(|&coord| map(coord))
            .collect::<LineString<f64>>()
    };
    MultiPolygon::new(
        land.0
            .iter()
            .map(|polygon| {
                Polygon::new(
                    ring(polygon.exterior()),
                    polygon.interiors().iter().map(ring).collect(),
                )
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use ::geo::{Area, Validation, polygon};

    #[test]
    fn boxes_are_checked_and_parsed() {
        let bbox = BoundingBox::parse("1.0, 50.8,2.0,51.3").unwrap();
        assert_eq!(bbox, BoundingBox::new(1.0, 50.8, 2.0, 51.3).unwrap());
        assert_eq!(bbox.centre_lat_lon_deg(), (51.05, 1.5));
        for (text, phrase) in [
            ("1,2,3", "four numbers"),
            ("2,50,1,51", "west < east"),
            ("1,51,2,50", "south < north"),
            ("-181,50,1,51", "longitude"),
            ("1,-91,2,51", "latitude"),
            ("0,40,20,41", "wider than"),
            ("0,40,nan,41", "finite"),
        ] {
            let error = BoundingBox::parse(text).unwrap_err().to_string();
            assert!(error.contains(phrase), "{text}: {error}");
        }
    }

    #[test]
    fn a_box_around_points_keeps_the_margin() {
        let points = [(51.0, 1.3), (51.1, 1.6)];
        let bbox = BoundingBox::around(&points, 5_000.0).unwrap();
        let frame = LocalFrame::new(51.0, 1.3);
        // The south-west corner is at least 5 km south and west of the first point.
        let corner_m = frame.to_local_m(bbox.south_deg, bbox.west_deg);
        assert!(corner_m.x < -5_000.0 && corner_m.y < -5_000.0, "{corner_m}");
        assert!(corner_m.x > -5_200.0 && corner_m.y > -5_200.0, "{corner_m}");
        assert!(bbox.contains_lon_lat(Coord { x: 1.6, y: 51.1 }));
        assert!(BoundingBox::around(&[], 1.0).is_err());
        assert!(BoundingBox::around(&points, -1.0).is_err());
    }

    #[test]
    fn the_box_polygon_is_counter_clockwise() {
        let polygon = BoundingBox::new(0.0, 0.0, 1.0, 2.0).unwrap().to_polygon();
        assert!((polygon.signed_area() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn prepare_coast_clips_simplifies_and_orients() {
        // A clockwise square with a wiggle of a few metres on its south edge.
        let island = polygon![
            (x: 1.0, y: 50.0), (x: 1.0, y: 50.2), (x: 1.2, y: 50.2), (x: 1.2, y: 50.0),
            (x: 1.12, y: 50.00001), (x: 1.1, y: 50.0)
        ];
        let bbox = BoundingBox::new(0.9, 49.9, 1.15, 50.3).unwrap();
        let coast = prepare_coast(
            &MultiPolygon::new(vec![island]),
            &CoastOptions::new(bbox, 50.0),
        )
        .unwrap();
        let [kept] = coast.land_lon_lat.0.as_slice() else {
            panic!("{:?}", coast.land_lon_lat)
        };
        assert!(kept.is_valid());
        assert!(kept.signed_area() > 0.0, "outer ring counter-clockwise");
        assert!(
            kept.exterior()
                .0
                .iter()
                .all(|&c| bbox.contains_lon_lat(c) || (c.x - 1.15).abs() < 1e-9)
        );
        // The wiggle (1.1 m high) went: only the four corners are left.
        assert_eq!(kept.exterior().0.len(), 5, "{kept:?}");
        let corner = |x: f64, y: f64| {
            kept.exterior()
                .0
                .iter()
                .any(|c| (c.x - x).abs() < 1e-6 && (c.y - y).abs() < 1e-4)
        };
        assert!(
            corner(1.0, 50.0) && corner(1.0, 50.2) && corner(1.15, 50.2) && corner(1.15, 50.0),
            "{kept:?}"
        );
        assert_eq!(coast.stats.polygons_in, 1);
        assert_eq!(coast.stats.polygons_out, 1);
        let bad = CoastOptions {
            tolerance_m: -1.0,
            ..CoastOptions::new(bbox, 1.0)
        };
        assert!(
            prepare_coast(&MultiPolygon::new(vec![]), &bad)
                .unwrap_err()
                .to_string()
                .contains("tolerance_m")
        );
    }

    #[test]
    fn no_land_in_the_box_is_empty_not_an_error() {
        let island = polygon![(x: 1.0, y: 50.0), (x: 1.2, y: 50.0), (x: 1.2, y: 50.2)];
        let bbox = BoundingBox::new(3.0, 49.0, 4.0, 50.0).unwrap();
        let coast = prepare_coast(
            &MultiPolygon::new(vec![island]),
            &CoastOptions::new(bbox, 10.0),
        )
        .unwrap();
        assert!(coast.land_lon_lat.0.is_empty());
        assert_eq!(coast.stats.polygons_clipped, 0);
    }
}
