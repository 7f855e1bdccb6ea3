//! Reading land polygons from `GeoJSON`, `TopoJSON` and ESRI shapefiles, in
//! `(longitude, latitude)` degrees.

use crate::error::CliError;
use geo::{Coord, LineString, MultiPolygon, Polygon};
use std::path::Path;
use vorrt_scenarios::coastline::BoundingBox;

/// Reads the land polygons of `path`: `.shp` as an ESRI shapefile (its
/// polygon shapes), `.json` / `.geojson` / `.topojson` as `TopoJSON` when its
/// `type` is `Topology`, else `GeoJSON`. `layer` names the `TopoJSON` object to
/// read (default: `land` when there is one, else every object). With `bbox`,
/// shapefile polygons wholly outside it are skipped while reading (a global
/// coastline is large).
///
/// # Errors
/// [`CliError::BadInput`] naming the file: missing or unreadable, an unknown
/// extension, malformed content, or a geometry that is not a polygon.
pub(crate) fn read_land(
    path: &Path,
    layer: Option<&str>,
    bbox: Option<&BoundingBox>,
) -> Result<MultiPolygon<f64>, CliError> {
    let name = path.display();
    let extension = path
        .extension()
        .and_then(|extension| extension.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("shp") => read_shapefile(path, bbox),
        Some("json" | "geojson" | "topojson") => {
            let text = std::fs::read_to_string(path)
                .map_err(|error| CliError::BadInput(format!("cannot read {name}: {error}")))?;
            let value: serde_json::Value = serde_json::from_str(&text)
                .map_err(|error| CliError::BadInput(format!("{name}: not JSON: {error}")))?;
            if value.get("type").and_then(serde_json::Value::as_str) == Some("Topology") {
                read_topojson(&text, layer)
                    .map_err(|problem| CliError::BadInput(format!("{name}: {problem}")))
            } else {
                read_geojson(value)
                    .map_err(|problem| CliError::BadInput(format!("{name}: {problem}")))
            }
        }
        _ => Err(CliError::BadInput(format!(
            "{name}: unknown coastline format; expected .geojson/.json (GeoJSON or TopoJSON), .topojson or .shp (ESRI shapefile)"
        ))),
    }
}

/// The polygons of a `GeoJSON` object (RFC 7946): a `FeatureCollection`, a
/// Feature or a bare geometry; features without a geometry are skipped.
fn read_geojson(value: serde_json::Value) -> Result<MultiPolygon<f64>, String> {
    let geojson: geojson::GeoJson =
        serde_json::from_value(value).map_err(|error| format!("not GeoJSON: {error}"))?;
    let mut polygons = Vec::new();
    match geojson {
        geojson::GeoJson::FeatureCollection(collection) => {
            for (index, feature) in collection.features.iter().enumerate() {
                if let Some(geometry) = &feature.geometry {
                    add_geojson_geometry(&geometry.value, &mut polygons)
                        .map_err(|problem| format!("features[{index}]: {problem}"))?;
                }
            }
        }
        geojson::GeoJson::Feature(feature) => {
            if let Some(geometry) = &feature.geometry {
                add_geojson_geometry(&geometry.value, &mut polygons)?;
            }
        }
        geojson::GeoJson::Geometry(geometry) => {
            add_geojson_geometry(&geometry.value, &mut polygons)?;
        }
    }
    Ok(MultiPolygon::new(polygons))
}

fn add_geojson_geometry(
    value: &geojson::GeometryValue,
    polygons: &mut Vec<Polygon<f64>>,
) -> Result<(), String> {
    use geojson::GeometryValue;
    let ring = |ring: &[geojson::Position]| -> Result<LineString<f64>, String> {
        ring.iter()
            .map(|position| match position.as_slice() {
                [lon, lat, ..] => Ok(Coord { x: *lon, y: *lat }),
                _ => Err("has a position with fewer than two numbers".to_owned()),
            })
            .collect()
    };
    let polygon = |rings: &[Vec<geojson::Position>]| -> Result<Polygon<f64>, String> {
        let (outer, holes) = rings.split_first().ok_or("has a Polygon without rings")?;
        let holes = holes
            .iter()
            .map(|hole| ring(hole))
            .collect::<Result<_, _>>()?;
        Ok(Polygon::new(ring(outer)?, holes))
    };
    match value {
        GeometryValue::Polygon { coordinates } => polygons.push(polygon(coordinates)?),
        GeometryValue::MultiPolygon { coordinates } => {
            for rings in coordinates {
                polygons.push(polygon(rings)?);
            }
        }
        GeometryValue::GeometryCollection { geometries } => {
            for geometry in geometries {
                add_geojson_geometry(&geometry.value, polygons)?;
            }
        }
        other => {
            return Err(format!(
                "has a {} geometry; land must be Polygon or MultiPolygon",
                other.type_name()
            ));
        }
    }
    Ok(())
}

/// The polygons of a `TopoJSON` topology's object `layer` (default `land`, or
/// every object when there is none), arcs decoded as the `TopoJSON`
/// specification (sections 2.1.3-2.1.4) says: quantized positions
/// delta-encoded and scaled by the transform, a negative index `~i` the arc
/// `i` reversed, and the first position of each following arc of a ring
/// dropped (it repeats the last one of the arc before).
pub(crate) fn read_topojson(text: &str, layer: Option<&str>) -> Result<MultiPolygon<f64>, String> {
    let topology = text
        .parse::<topojson::TopoJson>()
        .map_err(|error| format!("not TopoJSON: {error}"))?
        .try_unwrap_topology()
        .ok_or("is not a TopoJSON Topology")?;
    let arcs = decode_arcs(&topology)?;
    let names = topology.list_names();
    let chosen: Vec<&topojson::NamedGeometry> = match layer {
        Some(layer) => {
            let found: Vec<_> = topology
                .objects
                .iter()
                .filter(|object| object.name == layer)
                .collect();
            if found.is_empty() {
                return Err(format!("has no object {layer:?} (it has {names:?})"));
            }
            found
        }
        None if names.iter().any(|name| name == "land") => topology
            .objects
            .iter()
            .filter(|object| object.name == "land")
            .collect(),
        None => topology.objects.iter().collect(),
    };
    let mut polygons = Vec::new();
    for object in chosen {
        add_topo_geometry(&object.geometry.value, &arcs, &mut polygons)
            .map_err(|problem| format!("object {:?}: {problem}", object.name))?;
    }
    Ok(MultiPolygon::new(polygons))
}

/// Every arc of the topology in degrees.
fn decode_arcs(topology: &topojson::Topology) -> Result<Vec<Vec<Coord<f64>>>, String> {
    topology
        .arcs
        .iter()
        .enumerate()
        .map(|(index, arc)| {
            let (mut x, mut y) = (0.0, 0.0);
            arc.iter()
                .map(|position| {
                    let [px, py, ..] = position.as_slice() else {
                        return Err(format!(
                            "arcs[{index}] has a position with fewer than two numbers"
                        ));
                    };
                    Ok(match &topology.transform {
                        Some(transform) => {
                            x += px;
                            y += py;
                            Coord {
                                x: x * transform.scale[0] + transform.translate[0],
                                y: y * transform.scale[1] + transform.translate[1],
                            }
                        }
                        None => Coord { x: *px, y: *py },
                    })
                })
                .collect()
        })
        .collect()
}

fn topo_ring(arcs: &[Vec<Coord<f64>>], indexes: &[i32]) -> Result<LineString<f64>, String> {
    let mut ring: Vec<Coord<f64>> = Vec::new();
    for &index in indexes {
        let (arc_index, reversed) = if index < 0 {
            (!index, true)
        } else {
            (index, false)
        };
        let arc = usize::try_from(arc_index)
            .ok()
            .and_then(|arc_index| arcs.get(arc_index))
            .ok_or_else(|| {
                format!(
                    "refers to arc {index}, but the topology has {} arcs",
                    arcs.len()
                )
            })?;
        let mut points = arc.clone();
        if reversed {
            points.reverse();
        }
        let skip = usize::from(!ring.is_empty());
        ring.extend(points.into_iter().skip(skip));
    }
    Ok(LineString::from(ring))
}

fn add_topo_geometry(
    value: &topojson::Value,
    arcs: &[Vec<Coord<f64>>],
    polygons: &mut Vec<Polygon<f64>>,
) -> Result<(), String> {
    let polygon = |rings: &[Vec<i32>]| -> Result<Option<Polygon<f64>>, String> {
        let Some((outer, holes)) = rings.split_first() else {
            return Ok(None);
        };
        let holes = holes
            .iter()
            .map(|hole| topo_ring(arcs, hole))
            .collect::<Result<_, _>>()?;
        Ok(Some(Polygon::new(topo_ring(arcs, outer)?, holes)))
    };
    match value {
        topojson::Value::Polygon(rings) => polygons.extend(polygon(rings)?),
        topojson::Value::MultiPolygon(parts) => {
            for rings in parts {
                polygons.extend(polygon(rings)?);
            }
        }
        topojson::Value::GeometryCollection(geometries) => {
            for geometry in geometries {
                add_topo_geometry(&geometry.value, arcs, polygons)?;
            }
        }
        _ => return Err("has a geometry that is not a Polygon or MultiPolygon".into()),
    }
    Ok(())
}

/// The polygon shapes of an ESRI shapefile (`.shp`, with its `.shx` when
/// present; the `.dbf` is not needed). Each outer ring (clockwise in a
/// shapefile) takes the holes that follow it, as the format writes them.
fn read_shapefile(path: &Path, bbox: Option<&BoundingBox>) -> Result<MultiPolygon<f64>, CliError> {
    let name = path.display();
    let bad = |error: shapefile::Error| {
        CliError::BadInput(format!("{name}: cannot read the shapefile: {error}"))
    };
    if !path.exists() {
        return Err(CliError::BadInput(format!(
            "cannot read {name}: no such file"
        )));
    }
    let mut reader = shapefile::ShapeReader::from_path(path).map_err(bad)?;
    let mut polygons = Vec::new();
    for (index, shape) in reader.iter_shapes().enumerate() {
        let shape = shape.map_err(bad)?;
        let polygon = match shape {
            shapefile::Shape::Polygon(polygon) => polygon,
            shapefile::Shape::NullShape => continue,
            other => {
                return Err(CliError::BadInput(format!(
                    "{name}: shape {index} is a {}, not a polygon; land must be polygons",
                    other.shapetype()
                )));
            }
        };
        if let Some(bbox) = bbox {
            let (low, high) = (polygon.bbox().min, polygon.bbox().max);
            if high.x < bbox.west_deg
                || low.x > bbox.east_deg
                || high.y < bbox.south_deg
                || low.y > bbox.north_deg
            {
                continue;
            }
        }
        add_shapefile_polygon(&polygon, &mut polygons);
    }
    Ok(MultiPolygon::new(polygons))
}

fn add_shapefile_polygon(polygon: &shapefile::Polygon, polygons: &mut Vec<Polygon<f64>>) {
    let ring = |points: &[shapefile::Point]| -> LineString<f64> {
        points
            .iter()
            .map(|point| Coord {
                x: point.x,
                y: point.y,
            })
            .collect()
    };
    let mut current: Option<(LineString<f64>, Vec<LineString<f64>>)> = None;
    for shape_ring in polygon.rings() {
        match shape_ring {
            shapefile::PolygonRing::Outer(points) => {
                if let Some((outer, holes)) = current.take() {
                    polygons.push(Polygon::new(outer, holes));
                }
                current = Some((ring(points), Vec::new()));
            }
            // A hole before any outer ring has nothing to cut: water in
            // water, which changes no land.
            shapefile::PolygonRing::Inner(points) => {
                if let Some((_, holes)) = &mut current {
                    holes.push(ring(points));
                }
            }
        }
    }
    if let Some((outer, holes)) = current {
        polygons.push(Polygon::new(outer, holes));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::Area;

    #[test]
    fn a_tiny_topojson_decodes_its_arcs() {
        // Two arcs make a unit square at (10, 50): the bottom-right half as
        // arc 0, the top-left half as arc 1 stored backwards (used as ~1 = -2).
        // Quantized with scale 0.5 and translate (10, 50), delta-encoded.
        let text = r#"{
            "type": "Topology",
            "transform": {"scale": [0.5, 0.5], "translate": [10, 50]},
            "objects": {
                "land": {"type": "GeometryCollection", "geometries": [
                    {"type": "Polygon", "arcs": [[0, -2]]}
                ]},
                "other": {"type": "Polygon", "arcs": [[0, -2]]}
            },
            "arcs": [
                [[0, 0], [2, 0], [0, 2]],
                [[0, 0], [0, 2], [2, 0]]
            ]
        }"#;
        let land = read_topojson(text, None).unwrap();
        let [square] = land.0.as_slice() else {
            panic!("{land:?}")
        };
        let expected: Vec<(f64, f64)> = vec![
            (10.0, 50.0),
            (11.0, 50.0),
            (11.0, 51.0),
            (10.0, 51.0),
            (10.0, 50.0),
        ];
        let got: Vec<(f64, f64)> = square.exterior().0.iter().map(|c| (c.x, c.y)).collect();
        assert_eq!(got, expected);
        assert!((square.unsigned_area() - 1.0).abs() < 1e-12);
        // A named layer, and errors that say what is wrong.
        assert_eq!(read_topojson(text, Some("other")).unwrap().0.len(), 1);
        assert!(
            read_topojson(text, Some("sea"))
                .unwrap_err()
                .contains("no object \"sea\"")
        );
        let bad_index = text.replace(
            "[[0, -2]]}\n                ]}",
            "[[0, 7]]}\n                ]}",
        );
        assert!(
            read_topojson(&bad_index, None)
                .unwrap_err()
                .contains("arc 7")
        );
        assert!(read_topojson("{\"type\": \"Polygon\"}", None).is_err());
    }

    #[test]
    fn geojson_polygons_are_read_and_lines_refused() {
        let collection = serde_json::json!({
            "type": "FeatureCollection",
            "features": [
                {"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates": [
                    [[[0, 0], [1, 0], [1, 1], [0, 0]]],
                    [[[2, 0], [3, 0], [3, 1], [2, 0]], [[2.5, 0.2], [2.8, 0.2], [2.8, 0.5], [2.5, 0.2]]]
                ]}},
                {"type": "Feature", "properties": {}, "geometry": null}
            ]
        });
        let land = read_geojson(collection).unwrap();
        assert_eq!(land.0.len(), 2);
        assert_eq!(land.0[1].interiors().len(), 1);
        let line = serde_json::json!({"type": "LineString", "coordinates": [[0, 0], [1, 1]]});
        assert!(read_geojson(line).unwrap_err().contains("LineString"));
    }

    #[test]
    fn a_tiny_shapefile_written_by_the_crate_is_read_back() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("tiny.shp");
        let point = shapefile::Point::new;
        let island = shapefile::Polygon::with_rings(vec![
            shapefile::PolygonRing::Outer(vec![
                point(1.0, 50.0),
                point(1.0, 50.5),
                point(1.5, 50.5),
                point(1.5, 50.0),
                point(1.0, 50.0),
            ]),
            shapefile::PolygonRing::Inner(vec![
                point(1.1, 50.1),
                point(1.2, 50.1),
                point(1.2, 50.2),
                point(1.1, 50.2),
                point(1.1, 50.1),
            ]),
        ]);
        let far = shapefile::Polygon::new(shapefile::PolygonRing::Outer(vec![
            point(20.0, 10.0),
            point(20.0, 11.0),
            point(21.0, 11.0),
            point(20.0, 10.0),
        ]));
        {
            let writer = shapefile::ShapeWriter::from_path(&path).unwrap();
            writer.write_shapes(&[island, far]).unwrap();
        }
        let land = read_land(&path, None, None).unwrap();
        assert_eq!(land.0.len(), 2);
        assert_eq!(land.0[0].interiors().len(), 1);
        assert!((land.0[0].unsigned_area() - (0.25 - 0.01)).abs() < 1e-9);
        // The bounding box skips the far polygon while reading.
        let bbox = BoundingBox::new(0.0, 49.0, 2.0, 51.0).unwrap();
        assert_eq!(read_land(&path, None, Some(&bbox)).unwrap().0.len(), 1);
        let missing = read_land(&dir.path().join("none.shp"), None, None)
            .unwrap_err()
            .to_string();
        assert!(
            missing.contains("none.shp") && missing.contains("no such file"),
            "{missing}"
        );
        let unknown = read_land(&dir.path().join("coast.kml"), None, None)
            .unwrap_err()
            .to_string();
        assert!(
            unknown.contains("coast.kml") && unknown.contains("unknown coastline format"),
            "{unknown}"
        );
    }
}
