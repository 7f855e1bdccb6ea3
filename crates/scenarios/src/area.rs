//! Static surroundings in a scenario file: land and no-go areas, polygons
//! with holes (decision 29).
//!
//! An [`Area`] gives its outer ring and holes in exactly one of local
//! nautical miles (`outer_nm`, `holes_nm`), local metres (`outer_m`,
//! `holes_m`) or latitude and longitude (`outer_lat_lon`,
//! `holes_lat_lon`, geographic scenarios only), as vessels do. Validation
//! checks every ring and projects it into the local frame
//! ([`Area::rings_m`]); `land_geojson` polygons are read from a `GeoJSON`
//! file ([`crate::geojson_land`]).

use crate::geo::{LocalFrame, MAX_GEO_EXTENT_NM, check_lat_lon};
use crate::geojson_land::read_land_geojson;
use crate::scenario::Scenario;
use crate::validate::MAX_EXTENT_NM;
use ::geo::algorithm::validation::{InvalidPolygon, RingRole};
use ::geo::{LineString, Polygon, Validation};
use serde::{Deserialize, Serialize};
use std::path::Path;
use vorrt_geometry::{DVec2, units};

/// The distance ownship keeps from land when a scenario does not say
/// (`land_clearance_m`), metres: a quarter of a nautical mile (463 m).
/// Passage plans keep a margin from the coast that depends on ship size,
/// speed and visibility, 1-2 nm off an open coast and far less in a
/// harbour approach (decision 29); the scenarios here are coastal
/// encounters a few miles across, between the two.
pub const DEFAULT_LAND_CLEARANCE_M: f64 = 0.25 * units::NAUTICAL_MILE_M;

/// The largest `land_clearance_m` a scenario may ask for, metres (10 nm).
pub const MAX_LAND_CLEARANCE_M: f64 = 10.0 * units::NAUTICAL_MILE_M;

/// The most vertices all of a scenario's areas may have together: keeps
/// validation (the self-intersection check) and loading within seconds.
pub const MAX_AREA_VERTICES: usize = 200_000;

/// An area's rings as written: the unit's name, the outer ring, the holes.
type Rings<'a> = (&'static str, &'a [(f64, f64)], &'a [Vec<(f64, f64)>]);

/// One polygon with holes: an island, a coast, a no-go area (written
/// `Area(...)` in RON). Rings are `(east, north)` (or `(latitude,
/// longitude)`) points in order, at least three, closed implicitly (a last
/// point equal to the first is allowed); either orientation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename = "Area")]
pub struct Area {
    /// Name, for messages and plots (`"island"`). Must not be empty.
    pub name: String,
    /// The outer ring `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_nm: Option<Vec<(f64, f64)>>,
    /// Holes (water inside the outer ring), nautical miles; with `outer_nm`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes_nm: Vec<Vec<(f64, f64)>>,
    /// The outer ring `(east, north)`, metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_m: Option<Vec<(f64, f64)>>,
    /// Holes, metres; with `outer_m`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes_m: Vec<Vec<(f64, f64)>>,
    /// The outer ring `(latitude, longitude)`, degrees WGS84 (geographic
    /// scenarios only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_lat_lon: Option<Vec<(f64, f64)>>,
    /// Holes, degrees WGS84; with `outer_lat_lon`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes_lat_lon: Vec<Vec<(f64, f64)>>,
    /// The outer ring then the holes in the scenario's local frame, metres:
    /// derived by [`Scenario::validate`](crate::Scenario::validate), not
    /// part of the file.
    #[serde(skip)]
    pub rings_m: Vec<Vec<DVec2>>,
}

impl Area {
    /// An area with its outer ring in nautical miles and no holes.
    #[must_use]
    pub fn from_nm(name: impl Into<String>, outer_nm: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            outer_nm: Some(outer_nm),
            holes_nm: Vec::new(),
            outer_m: None,
            holes_m: Vec::new(),
            outer_lat_lon: None,
            holes_lat_lon: Vec::new(),
            rings_m: Vec::new(),
        }
    }

    /// The polygon in local metres (x east, y north), from
    /// [`rings_m`](Self::rings_m): empty before validation.
    #[must_use]
    pub fn polygon_m(&self) -> Polygon<f64> {
        let ring = |points: &Vec<DVec2>| {
            LineString::from(
                points
                    .iter()
                    .map(|point| (point.x, point.y))
                    .collect::<Vec<_>>(),
            )
        };
        let mut rings = self.rings_m.iter();
        let outer = rings
            .next()
            .map_or_else(|| LineString::new(Vec::new()), ring);
        Polygon::new(outer, rings.map(ring).collect())
    }

    /// The unit the area is given in: `"nm"`, `"m"` or `"lat_lon"`, with
    /// its outer ring and holes; `Err` names the field at fault when none or
    /// several outer rings are given, or holes in another unit.
    fn rings(&self) -> Result<Rings<'_>, (String, String)> {
        let given: Vec<Rings<'_>> = [
            ("nm", self.outer_nm.as_deref(), self.holes_nm.as_slice()),
            ("m", self.outer_m.as_deref(), self.holes_m.as_slice()),
            (
                "lat_lon",
                self.outer_lat_lon.as_deref(),
                self.holes_lat_lon.as_slice(),
            ),
        ]
        .into_iter()
        .filter_map(|(unit, outer, holes)| outer.map(|outer| (unit, outer, holes)))
        .collect();
        let Some(&(unit, outer, holes)) = given.first() else {
            return Err((
                "outer_nm".into(),
                "is missing: give the outer ring as exactly one of outer_nm, outer_m or outer_lat_lon".into(),
            ));
        };
        if let Some((other, _, _)) = given.get(1) {
            return Err((
                format!("outer_{other}"),
                format!("is given beside outer_{unit}: give the outer ring in one unit only"),
            ));
        }
        for (name, holes_given) in [
            ("nm", !self.holes_nm.is_empty()),
            ("m", !self.holes_m.is_empty()),
            ("lat_lon", !self.holes_lat_lon.is_empty()),
        ] {
            if holes_given && name != unit {
                return Err((
                    format!("holes_{name}"),
                    format!("are given with outer_{unit}: holes take the outer ring's unit"),
                ));
            }
        }
        Ok((unit, outer, holes))
    }

    /// Checks the area and fills [`rings_m`](Self::rings_m): `Err((field,
    /// problem))` with `field` relative to the area (`"outer_nm"`,
    /// `"holes_m[1]"`).
    pub(crate) fn check_and_project(
        &mut self,
        frame: Option<&LocalFrame>,
    ) -> Result<usize, (String, String)> {
        if self.name.trim().is_empty() {
            return Err(("name".into(), "must not be empty".into()));
        }
        let (unit, outer, holes) = self.rings()?;
        let geographic = unit == "lat_lon";
        match (geographic, frame) {
            (true, None) => {
                return Err((
                    "outer_lat_lon".into(),
                    "is given in a local scenario: a scenario is all geographic (ownship has start_lat_lon) or all local".into(),
                ));
            }
            (false, Some(_)) => {
                return Err((
                    format!("outer_{unit}"),
                    "is given in a geographic scenario: use outer_lat_lon and holes_lat_lon".into(),
                ));
            }
            _ => {}
        }
        let mut rings_m = Vec::with_capacity(1 + holes.len());
        let mut vertices = 0;
        for (index, ring) in std::iter::once(outer)
            .chain(holes.iter().map(Vec::as_slice))
            .enumerate()
        {
            let field = if index == 0 {
                format!("outer_{unit}")
            } else {
                format!("holes_{unit}[{}]", index - 1)
            };
            let projected = project_ring(ring, unit, frame).map_err(|problem| (field, problem))?;
            vertices += projected.len();
            rings_m.push(projected);
        }
        self.rings_m = rings_m;
        let polygon = self.polygon_m();
        if let Err(problem) = polygon.check_validation() {
            let field = |role: RingRole| match role {
                RingRole::Exterior => format!("outer_{unit}"),
                RingRole::Interior(hole) => format!("holes_{unit}[{hole}]"),
            };
            self.rings_m.clear();
            return Err(match problem {
                InvalidPolygon::SelfIntersection(role) => (
                    field(role),
                    "crosses itself: a ring must be a simple polygon".into(),
                ),
                InvalidPolygon::InteriorRingNotContainedInExteriorRing(role) => (
                    field(role),
                    format!("lies outside the outer ring outer_{unit}: a hole must be inside it"),
                ),
                InvalidPolygon::IntersectingRingsOnALine(first, second)
                | InvalidPolygon::IntersectingRingsOnAnArea(first, second) => (
                    field(second),
                    format!("crosses {}: rings of an area must not cross", field(first)),
                ),
                other => (field(RingRole::Exterior), other.to_string()),
            });
        }
        Ok(vertices)
    }
}

/// Checks `land_clearance_m`, reads `land_geojson`, and checks and projects
/// every area of `land`, `no_go` and the `GeoJSON` file: `Err((field,
/// problem))` naming the area (`land[2].outer_nm`). Run by
/// [`Scenario::validate`] after the geographic fields.
pub(crate) fn check_areas(scenario: &mut Scenario) -> Result<(), (String, String)> {
    if let Some(clearance_m) = scenario.land_clearance_m
        && !(clearance_m.is_finite() && (0.0..=MAX_LAND_CLEARANCE_M).contains(&clearance_m))
    {
        return Err((
            "land_clearance_m".into(),
            format!("is {clearance_m}, expected a distance in [0, {MAX_LAND_CLEARANCE_M}] metres"),
        ));
    }
    let frame = scenario.local_frame();
    scenario.geojson_land = match &scenario.land_geojson {
        None => Vec::new(),
        Some(_) if frame.is_none() => {
            return Err((
                "land_geojson".into(),
                "is given in a local scenario: GeoJSON is longitude and latitude, so it needs a geographic scenario (ownship.start_lat_lon)".into(),
            ));
        }
        Some(file) => {
            let path = Path::new(file);
            let path = match &scenario.base_dir {
                Some(base) if path.is_relative() => base.join(path),
                _ => path.to_path_buf(),
            };
            read_land_geojson(&path).map_err(|problem| ("land_geojson".to_owned(), problem))?
        }
    };
    let mut vertices = 0;
    for (list, areas) in [
        ("land", &mut scenario.land),
        ("no_go", &mut scenario.no_go),
        ("land_geojson", &mut scenario.geojson_land),
    ] {
        for (index, area) in areas.iter_mut().enumerate() {
            let count = area
                .check_and_project(frame.as_ref())
                .map_err(|(field, problem)| {
                    let problem = if list == "land_geojson" {
                        format!("{:?}: {field} {problem}", area.name)
                    } else {
                        problem
                    };
                    let field = if list == "land_geojson" {
                        list.to_owned()
                    } else {
                        format!("{list}[{index}].{field}")
                    };
                    (field, problem)
                })?;
            vertices += count;
            if vertices > MAX_AREA_VERTICES {
                return Err((
                    list.into(),
                    format!("the areas hold more than the {MAX_AREA_VERTICES} vertices allowed"),
                ));
            }
        }
    }
    Ok(())
}

/// One ring in local metres: at least three distinct, finite points within
/// the scenario's extent; a repeated closing point is dropped.
fn project_ring(
    ring: &[(f64, f64)],
    unit: &str,
    frame: Option<&LocalFrame>,
) -> Result<Vec<DVec2>, String> {
    let mut points: Vec<DVec2> = Vec::with_capacity(ring.len());
    for (index, &(first, second)) in ring.iter().enumerate() {
        if !first.is_finite() || !second.is_finite() {
            return Err(format!(
                "point {index} is ({first}, {second}), not a pair of finite numbers"
            ));
        }
        let (point_m, extent_nm) = match (unit, frame) {
            ("lat_lon", Some(frame)) => {
                check_lat_lon((first, second))
                    .map_err(|problem| format!("point {index} {problem}"))?;
                (frame.to_local_m(first, second), MAX_GEO_EXTENT_NM)
            }
            ("nm", _) => (
                DVec2::new(first, second) * units::NAUTICAL_MILE_M,
                MAX_EXTENT_NM,
            ),
            _ => (DVec2::new(first, second), MAX_EXTENT_NM),
        };
        let distance_nm = point_m.length() / units::NAUTICAL_MILE_M;
        if distance_nm > extent_nm {
            return Err(format!(
                "point {index} is {distance_nm:.1} nm from the origin, more than the {extent_nm} nm allowed"
            ));
        }
        if points.last() != Some(&point_m) {
            points.push(point_m);
        }
    }
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    if points.len() < 3 {
        return Err(format!(
            "has {} distinct points: a ring needs at least 3",
            points.len()
        ));
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_nm(size: f64) -> Vec<(f64, f64)> {
        vec![(0.0, 0.0), (size, 0.0), (size, size), (0.0, size)]
    }

    #[test]
    fn an_area_in_miles_projects_to_metres() {
        let mut area = Area::from_nm("island", square_nm(1.0));
        area.holes_nm = vec![vec![
            (0.25, 0.25),
            (0.75, 0.25),
            (0.75, 0.75),
            (0.25, 0.75),
            (0.25, 0.25),
        ]];
        assert_eq!(area.check_and_project(None), Ok(8));
        assert_eq!(area.rings_m[0][2], DVec2::splat(units::NAUTICAL_MILE_M));
        let polygon = area.polygon_m();
        assert_eq!(polygon.interiors().len(), 1);
    }

    #[test]
    fn bad_areas_name_their_field() {
        let check = |area: &mut Area| area.check_and_project(None).unwrap_err();
        let mut bow_tie = Area::from_nm("x", vec![(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        assert_eq!(check(&mut bow_tie).0, "outer_nm");
        let mut two = Area::from_nm("x", vec![(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)]);
        assert!(check(&mut two).1.contains("at least 3"));
        let mut nan = Area::from_nm("x", vec![(0.0, 0.0), (f64::NAN, 1.0), (1.0, 0.0)]);
        assert!(check(&mut nan).1.contains("finite"));
        let mut outside = Area::from_nm("x", square_nm(1.0));
        outside.holes_nm = vec![
            vec![(0.25, 0.25), (0.5, 0.25), (0.5, 0.5)],
            vec![(3.0, 3.0), (4.0, 3.0), (4.0, 4.0)],
        ];
        let (field, problem) = check(&mut outside);
        assert_eq!(field, "holes_nm[1]", "{problem}");
        let mut mixed = Area::from_nm("x", square_nm(1.0));
        mixed.holes_m = vec![square_nm(100.0)];
        assert_eq!(check(&mut mixed).0, "holes_m");
        let mut none = Area::from_nm("x", square_nm(1.0));
        none.outer_nm = None;
        assert_eq!(check(&mut none).0, "outer_nm");
        let mut both = Area::from_nm("x", square_nm(1.0));
        both.outer_m = Some(square_nm(1.0));
        assert_eq!(check(&mut both).0, "outer_m");
        let mut lat_lon = Area::from_nm("x", square_nm(1.0));
        lat_lon.outer_nm = None;
        lat_lon.outer_lat_lon = Some(square_nm(1.0));
        assert_eq!(check(&mut lat_lon).0, "outer_lat_lon");
        let mut far = Area::from_nm("x", square_nm(20_000.0));
        assert!(check(&mut far).1.contains("from the origin"));
    }

    #[test]
    fn a_geographic_area_projects_about_the_origin() {
        let frame = LocalFrame::new(50.0, -1.0);
        let mut area = Area::from_nm("x", Vec::new());
        area.outer_nm = None;
        area.outer_lat_lon = Some(vec![(50.01, -1.0), (50.02, -1.0), (50.02, -0.98)]);
        assert_eq!(area.check_and_project(Some(&frame)), Ok(3));
        assert!((area.rings_m[0][0].y - 1112.0).abs() < 5.0);
        let mut local = Area::from_nm("x", square_nm(1.0));
        assert_eq!(
            local.check_and_project(Some(&frame)).unwrap_err().0,
            "outer_nm"
        );
    }
}
