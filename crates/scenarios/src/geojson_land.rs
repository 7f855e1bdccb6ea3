//! Land polygons from a `GeoJSON` file (RFC 7946): a scenario's
//! `land_geojson`.
//!
//! The file holds a `FeatureCollection`, a `Feature`, a
//! `GeometryCollection` or a bare geometry; every `Polygon` and
//! `MultiPolygon` in it becomes one [`Area`] given in latitude and
//! longitude (RFC 7946 positions are `[longitude, latitude]`, WGS84), named
//! after the feature's `name` property where it has one. Other geometries
//! (points, lines) are skipped: they bound no land.

use crate::area::Area;
use serde_json::Value;
use std::path::Path;

/// Reads the land polygons of the `GeoJSON` file at `path`.
///
/// # Errors
/// What is wrong, naming the place in the file (`features[2].geometry.coordinates[0][5]`):
/// the file cannot be read, is not JSON, or a polygon's coordinates are not
/// arrays of `[longitude, latitude]` numbers.
pub fn read_land_geojson(path: &Path) -> Result<Vec<Area>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|error| format!("cannot read {}: {error}", path.display()))?;
    parse_land_geojson(&text).map_err(|problem| format!("{}: {problem}", path.display()))
}

/// The land polygons of `GeoJSON` text (see [`read_land_geojson`]).
///
/// ```
/// let text = r#"{"type": "Feature", "properties": {"name": "rock"},
///   "geometry": {"type": "Polygon", "coordinates": [[[-1.0, 50.0], [-0.99, 50.0], [-0.99, 50.01], [-1.0, 50.0]]]}}"#;
/// let areas = vorrt_scenarios::geojson_land::parse_land_geojson(text).unwrap();
/// assert_eq!(areas[0].name, "rock");
/// assert_eq!(areas[0].outer_lat_lon.as_ref().unwrap()[1], (50.0, -0.99));
/// ```
///
/// # Errors
/// As [`read_land_geojson`].
pub fn parse_land_geojson(text: &str) -> Result<Vec<Area>, String> {
    let value: Value =
        serde_json::from_str(text).map_err(|error| format!("not GeoJSON: {error}"))?;
    let mut areas = Vec::new();
    collect(&value, "", "land", &mut areas)?;
    Ok(areas)
}

/// The `type` member of a `GeoJSON` object.
fn kind<'a>(value: &'a Value, at: &str) -> Result<&'a str, String> {
    value
        .get("type")
        .and_then(Value::as_str)
        .ok_or_else(|| format!("{}: has no \"type\" string", place(at)))
}

fn place(at: &str) -> &str {
    if at.is_empty() { "the top level" } else { at }
}

/// Every polygon in `value` (at `at` in the file), named from `name`.
fn collect(value: &Value, at: &str, name: &str, areas: &mut Vec<Area>) -> Result<(), String> {
    let join = |member: &str| {
        if at.is_empty() {
            member.to_owned()
        } else {
            format!("{at}.{member}")
        }
    };
    let array = |member: &str| -> Result<&Vec<Value>, String> {
        value
            .get(member)
            .and_then(Value::as_array)
            .ok_or_else(|| format!("{}: has no \"{member}\" array", place(at)))
    };
    match kind(value, at)? {
        "FeatureCollection" => {
            for (index, feature) in array("features")?.iter().enumerate() {
                let feature_name = feature
                    .pointer("/properties/name")
                    .and_then(Value::as_str)
                    .map_or_else(|| format!("{name} feature {index}"), str::to_owned);
                collect(
                    feature,
                    &join(&format!("features[{index}]")),
                    &feature_name,
                    areas,
                )?;
            }
        }
        "Feature" => {
            let own_name = value
                .pointer("/properties/name")
                .and_then(Value::as_str)
                .unwrap_or(name);
            match value.get("geometry") {
                None | Some(Value::Null) => {}
                Some(geometry) => collect(geometry, &join("geometry"), own_name, areas)?,
            }
        }
        "GeometryCollection" => {
            for (index, geometry) in array("geometries")?.iter().enumerate() {
                collect(
                    geometry,
                    &join(&format!("geometries[{index}]")),
                    name,
                    areas,
                )?;
            }
        }
        "Polygon" => areas.push(polygon(array("coordinates")?, &join("coordinates"), name)?),
        "MultiPolygon" => {
            let at = join("coordinates");
            for (index, rings) in array("coordinates")?.iter().enumerate() {
                let rings = rings
                    .as_array()
                    .ok_or_else(|| format!("{at}[{index}]: is not an array of rings"))?;
                let part = format!("{name} part {index}");
                areas.push(polygon(rings, &format!("{at}[{index}]"), &part)?);
            }
        }
        "Point" | "MultiPoint" | "LineString" | "MultiLineString" => {}
        other => return Err(format!("{}: unknown GeoJSON type {other:?}", place(at))),
    }
    Ok(())
}

/// One polygon's rings (the first is the outer ring) as an [`Area`].
fn polygon(rings: &[Value], at: &str, name: &str) -> Result<Area, String> {
    let mut lat_lon_rings = Vec::with_capacity(rings.len());
    for (ring_index, ring) in rings.iter().enumerate() {
        let ring_at = format!("{at}[{ring_index}]");
        let positions = ring
            .as_array()
            .ok_or_else(|| format!("{ring_at}: is not an array of positions"))?;
        let mut points = Vec::with_capacity(positions.len());
        for (index, position) in positions.iter().enumerate() {
            let numbers = position.as_array().map(|numbers| {
                numbers
                    .iter()
                    .take(2)
                    .filter_map(Value::as_f64)
                    .collect::<Vec<_>>()
            });
            match numbers.as_deref() {
                Some(&[lon_deg, lat_deg]) => points.push((lat_deg, lon_deg)),
                _ => {
                    return Err(format!(
                        "{ring_at}[{index}]: is not a [longitude, latitude] pair of numbers"
                    ));
                }
            }
        }
        lat_lon_rings.push(points);
    }
    if lat_lon_rings.is_empty() {
        return Err(format!("{at}: a polygon needs an outer ring"));
    }
    let outer = lat_lon_rings.remove(0);
    Ok(Area {
        name: name.to_owned(),
        outer_nm: None,
        holes_nm: Vec::new(),
        outer_m: None,
        holes_m: Vec::new(),
        outer_lat_lon: Some(outer),
        holes_lat_lon: lat_lon_rings,
        rings_m: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collections_and_multipolygons_are_read() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates": [
                [[[0, 0], [1, 0], [1, 1], [0, 0]]],
                [[[5, 5], [6, 5], [6, 6], [5, 5]], [[5.2, 5.1], [5.8, 5.1], [5.8, 5.7], [5.2, 5.1]]]]}},
            {"type": "Feature", "properties": {"name": "pier"}, "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}},
            {"type": "Feature", "geometry": null}]}"#;
        let areas = parse_land_geojson(text).unwrap();
        assert_eq!(areas.len(), 2);
        assert_eq!(areas[0].name, "land feature 0 part 0");
        assert_eq!(areas[1].holes_lat_lon.len(), 1);
        assert_eq!(areas[1].outer_lat_lon.as_ref().unwrap()[1], (5.0, 6.0));
    }

    #[test]
    fn bad_geojson_names_the_place() {
        let bad = r#"{"type": "FeatureCollection", "features": [{"type": "Feature",
            "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, "x"], [1, 1]]]}}]}"#;
        let problem = parse_land_geojson(bad).unwrap_err();
        assert!(
            problem.starts_with("features[0].geometry.coordinates[0][1]:"),
            "{problem}"
        );
        assert!(parse_land_geojson("[").unwrap_err().contains("not GeoJSON"));
        assert!(
            parse_land_geojson(r#"{"type": "Circle"}"#)
                .unwrap_err()
                .contains("unknown GeoJSON type")
        );
        assert!(
            read_land_geojson(Path::new("/nonexistent/land.geojson"))
                .unwrap_err()
                .contains("cannot read")
        );
    }
}
