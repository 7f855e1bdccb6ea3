//! `vorrt coast` and `vorrt import-ais --coast` end to end, and, when
//! `VORRT_GSHHS` names a `GSHHS` L1 shapefile (LGPL, never committed; `PyPI`
//! `tracktable-data` ships it), a real high-resolution coastline.

use geo::{
    Contains, Coord, Distance, Euclidean, LineString, MultiPolygon, Point, Polygon, Validation,
};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use vorrt_scenarios::LocalFrame;

fn vorrt(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .output()
        .expect("the vorrt binary runs")
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// The polygons of a `GeoJSON` `FeatureCollection` of Polygon features.
fn read_polygons(path: &Path) -> MultiPolygon<f64> {
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let ring = |ring: &serde_json::Value| -> LineString<f64> {
        ring.as_array()
            .unwrap()
            .iter()
            .map(|p| Coord {
                x: p[0].as_f64().unwrap(),
                y: p[1].as_f64().unwrap(),
            })
            .collect()
    };
    MultiPolygon::new(
        value["features"]
            .as_array()
            .unwrap()
            .iter()
            .map(|feature| {
                let rings = feature["geometry"]["coordinates"].as_array().unwrap();
                Polygon::new(ring(&rings[0]), rings[1..].iter().map(ring).collect())
            })
            .collect(),
    )
}

fn write_geojson(path: &Path, geometries: &[serde_json::Value]) {
    let features: Vec<serde_json::Value> = geometries
        .iter()
        .map(|geometry| serde_json::json!({"type": "Feature", "properties": {}, "geometry": geometry}))
        .collect();
    let collection = serde_json::json!({"type": "FeatureCollection", "features": features});
    std::fs::write(path, collection.to_string()).unwrap();
}

#[test]
fn coast_clips_a_geojson_island_to_the_box() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("world.geojson");
    write_geojson(
        &input,
        &[
            serde_json::json!({"type": "Polygon", "coordinates": [[[1.0, 50.0], [1.2, 50.0], [1.2, 50.2], [1.0, 50.2], [1.0, 50.0]]]}),
            serde_json::json!({"type": "Polygon", "coordinates": [[[5.0, 50.0], [5.2, 50.0], [5.2, 50.2], [5.0, 50.0]]]}),
        ],
    );
    let out = dir.path().join("deep/land.geojson");
    let output = vorrt(&[
        "coast",
        text(&input),
        "--bbox",
        "1.1,49.9,1.5,50.3",
        "--out",
        text(&out),
        "--note",
        "made up",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("1 polygons"),
        "{}",
        stdout(&output)
    );
    let land = read_polygons(&out);
    let [island] = land.0.as_slice() else {
        panic!("{land:?}")
    };
    assert!(island.is_valid());
    assert!(
        island
            .exterior()
            .0
            .iter()
            .all(|c| (1.1 - 1e-9..=1.2 + 1e-9).contains(&c.x)),
        "{island:?}"
    );
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(value["vorrt"]["note"], "made up");
    assert_eq!(value["vorrt"]["source"], "world.geojson");
    assert_eq!(value["vorrt"]["tolerance_m"], 50.0);

    // No land in the box: a warning, an empty collection, success.
    let empty = dir.path().join("empty.geojson");
    let output = vorrt(&[
        "coast",
        text(&input),
        "--bbox",
        "-10,40,-9,41",
        "--out",
        text(&empty),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("warning") && stderr(&output).contains("no land"),
        "{}",
        stderr(&output)
    );
    assert!(read_polygons(&empty).0.is_empty());
}

#[test]
fn coast_errors_name_the_file_and_the_problem() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("land.geojson");
    let missing = dir.path().join("missing.shp");
    let output = vorrt(&[
        "coast",
        text(&missing),
        "--bbox",
        "1,50,2,51",
        "--out",
        text(&out),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("missing.shp"),
        "{}",
        stderr(&output)
    );

    let lines = dir.path().join("lines.geojson");
    write_geojson(
        &lines,
        &[serde_json::json!({"type": "LineString", "coordinates": [[1.0, 50.0], [1.5, 50.5]]})],
    );
    let output = vorrt(&[
        "coast",
        text(&lines),
        "--bbox",
        "1,50,2,51",
        "--out",
        text(&out),
    ]);
    assert_eq!(output.status.code(), Some(2));
    let error = stderr(&output);
    assert!(
        error.contains("lines.geojson")
            && error.contains("features[0]")
            && error.contains("LineString"),
        "{error}"
    );

    let output = vorrt(&[
        "coast",
        text(&lines),
        "--bbox",
        "2,50,1,51",
        "--out",
        text(&out),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("--bbox") && stderr(&output).contains("west < east"),
        "{}",
        stderr(&output)
    );
    assert!(!out.exists());
}

#[test]
fn import_ais_with_a_coast_writes_the_land_beside_the_scenario() {
    let dir = tempfile::tempdir().unwrap();
    let log = Path::new(env!("CARGO_MANIFEST_DIR")).join("../ais/fixtures/encounter.nmea");
    // An island 1.5 nm north of the northernmost vessel of the log (a yacht
    // at 50.34 N; the others about 50.30 N, 1.00-0.80 W), and a continent
    // far away.
    let coast = dir.path().join("coast.geojson");
    write_geojson(
        &coast,
        &[
            serde_json::json!({"type": "Polygon", "coordinates": [[[-0.95, 50.37], [-0.85, 50.37], [-0.85, 50.42], [-0.95, 50.42], [-0.95, 50.37]]]}),
            serde_json::json!({"type": "Polygon", "coordinates": [[[10.0, 50.0], [11.0, 50.0], [11.0, 51.0], [10.0, 50.0]]]}),
        ],
    );
    let scenario = dir.path().join("run/encounter.ron");
    let output = vorrt(&[
        "import-ais",
        text(&log),
        "--ownship",
        "235000001",
        "--goal",
        "50.30,-0.80",
        "--out",
        text(&scenario),
        "--coast",
        text(&coast),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let written = std::fs::read_to_string(&scenario).unwrap();
    assert!(
        written.contains("\n    land_geojson: \"land.geojson\",\n"),
        "{written}"
    );
    // It loads with its land, from the file beside it.
    let loaded = vorrt_scenarios::Scenario::load(&scenario).unwrap();
    assert_eq!(loaded.land_areas().count(), 1);
    let land = read_polygons(&dir.path().join("run/land.geojson"));
    assert_eq!(land.0.len(), 1, "the island only: {land:?}");
    // With a margin of 1 nm the island (1.5 nm off) is clipped away: a warning.
    let output = vorrt(&[
        "import-ais",
        text(&log),
        "--ownship",
        "235000001",
        "--goal",
        "50.30,-0.80",
        "--out",
        text(&scenario),
        "--coast",
        text(&coast),
        "--coast-margin-nm",
        "1",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(stderr(&output).contains("no land"), "{}", stderr(&output));
}

/// Distance from `(lat, lon)` to land given in degrees, metres, in the frame
/// about that point.
fn to_land_m(land_lon_lat: &MultiPolygon<f64>, lat_lon: (f64, f64)) -> f64 {
    let frame = LocalFrame::new(lat_lon.0, lat_lon.1);
    let ring = |ring: &LineString<f64>| -> LineString<f64> {
        ring.0
            .iter()
            .map(|c| {
                let p = frame.to_local_m(c.y, c.x);
                Coord { x: p.x, y: p.y }
            })
            .collect()
    };
    let land_m = MultiPolygon::new(
        land_lon_lat
            .0
            .iter()
            .map(|p| Polygon::new(ring(p.exterior()), p.interiors().iter().map(ring).collect()))
            .collect(),
    );
    let origin = Point::new(0.0, 0.0);
    if land_m.contains(&origin) {
        return 0.0;
    }
    land_m
        .0
        .iter()
        .map(|p| Euclidean.distance(&origin, p.exterior()))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn gshhs_when_present_clips_new_york_harbor() {
    let Some(gshhs) = std::env::var_os("VORRT_GSHHS").map(PathBuf::from) else {
        eprintln!("VORRT_GSHHS is not set: the GSHHS check is skipped");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ny.geojson");
    let output = vorrt(&[
        "coast",
        text(&gshhs),
        "--bbox",
        "-74.3,40.45,-73.7,40.95",
        "--tolerance-m",
        "20",
        "--out",
        text(&out),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let land = read_polygons(&out);
    assert!(land.is_valid(), "{:?}", land.validation_errors());
    // Manhattan, Staten Island, Long Island, New Jersey and the islands.
    assert!(land.0.len() >= 5, "{}", land.0.len());
    // The Narrows fixture's ends are in water, over 1 km from land here too.
    for end in [(40.560, -74.028), (40.655, -74.060)] {
        let distance_m = to_land_m(&land, end);
        assert!(distance_m > 1_000.0, "{end:?}: {distance_m} m");
    }
    // Manhattan (Central Park) is land.
    assert!(to_land_m(&land, (40.78, -73.965)) == 0.0);
}
