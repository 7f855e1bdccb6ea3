//! Writing land as `GeoJSON` (RFC 7946).

use ::geo::{LineString, MultiPolygon};
use serde_json::{Value, json};

/// Decimal places of the degrees written: 1e-7 degrees is about 1 cm, far
/// below any tolerance, and keeps a file small.
const DECIMALS: i32 = 7;

/// `land_lon_lat` as a `GeoJSON` `FeatureCollection` text (RFC 7946): one
/// `Polygon` feature per polygon, positions `[longitude, latitude]` in
/// degrees rounded to 1e-7 (about a centimetre), rings as given (give them
/// counter-clockwise outside and clockwise holes, as
/// [`prepare_coast`](super::prepare_coast) does). `properties` (a JSON
/// object, e.g. the source and its licence) go on the collection as a foreign
/// member `"vorrt"` and on no feature, so that the features stay plain land.
#[must_use]
pub fn to_geojson_string(land_lon_lat: &MultiPolygon<f64>, properties: &Value) -> String {
    let scale = 10_f64.powi(DECIMALS);
    let ring = |ring: &LineString<f64>| -> Value {
        Value::Array(
            ring.0
                .iter()
                .map(|coord| {
                    json!([
                        (coord.x * scale).round() / scale,
                        (coord.y * scale).round() / scale
                    ])
                })
                .collect(),
        )
    };
    let features: Vec<Value> = land_lon_lat
        .0
        .iter()
        .map(|polygon| {
            let mut rings = vec![ring(polygon.exterior())];
            rings.extend(polygon.interiors().iter().map(ring));
            json!({
                "type": "Feature",
                "properties": {},
                "geometry": {"type": "Polygon", "coordinates": rings},
            })
        })
        .collect();
    let collection = json!({
        "type": "FeatureCollection",
        "vorrt": properties,
        "features": features,
    });
    // One feature per line: readable in a diff, small on disk.
    let mut text = String::from("{\"type\":\"FeatureCollection\",\"vorrt\":");
    text.push_str(&collection["vorrt"].to_string());
    text.push_str(",\"features\":[\n");
    let lines: Vec<String> = features.iter().map(Value::to_string).collect();
    text.push_str(&lines.join(",\n"));
    text.push_str("\n]}\n");
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use ::geo::polygon;

    #[test]
    fn polygons_become_features_in_lon_lat() {
        let land = MultiPolygon::new(vec![polygon![
            (x: 1.123_456_789, y: 50.0), (x: 1.2, y: 50.0), (x: 1.2, y: 50.1)
        ]]);
        let text = to_geojson_string(&land, &json!({"source": "test"}));
        let value: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(value["type"], "FeatureCollection");
        assert_eq!(value["vorrt"]["source"], "test");
        let feature = &value["features"][0];
        assert_eq!(feature["geometry"]["type"], "Polygon");
        let first = &feature["geometry"]["coordinates"][0][0];
        assert_eq!(first[0].as_f64(), Some(1.123_456_8));
        assert_eq!(first[1].as_f64(), Some(50.0));
        // The ring is closed, as RFC 7946 section 3.1.6 requires.
        assert_eq!(feature["geometry"]["coordinates"][0][3], *first);
        assert!(
            to_geojson_string(&MultiPolygon::new(vec![]), &json!({}))
                .contains("\"features\":[\n\n]")
        );
    }
}
