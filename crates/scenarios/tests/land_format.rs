//! The land fields of the scenario format (decision 29): every scenario
//! without them loads as before, bad areas are refused naming the field
//! (`land[1].outer_nm`), and `land_geojson` polygons are read from a file
//! beside the scenario and projected like vessel positions.

use std::path::PathBuf;
use vorrt_scenarios::{Chart, DEFAULT_LAND_CLEARANCE_M, Scenario, ScenarioError};

const BASE: &str = r#"
Scenario(
    name: "base",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -3.0), course_deg: 0.0, speed_kn: 12.0,
                    length_m: 100.0, goal_nm: (0.0, 3.0)),
    targets: [
        Vessel(name: "TS1", start_nm: (3.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-4.0, 0.0)),
    ],
    LAND
)
"#;

fn with_land(land: &str) -> String {
    BASE.replace("LAND", land)
}

/// The (field, message) of loading `land` into the base scenario.
fn invalid(land: &str) -> (String, String) {
    match Scenario::from_ron_str(&with_land(land), "bad.ron") {
        Err(error @ ScenarioError::Invalid { .. }) => {
            let message = error.to_string();
            assert!(message.starts_with("bad.ron: "), "{message}");
            (error.field().unwrap_or_default().to_owned(), message)
        }
        other => panic!("expected Invalid, got {other:?}"),
    }
}

const ISLAND: &str =
    r#"Area(name: "island", outer_nm: [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)])"#;

#[test]
fn land_loads_and_round_trips() {
    let text = with_land(&format!(
        "land: [{ISLAND}], no_go: [Area(name: \"range\", outer_m: [(3000.0, 3000.0), (4000.0, 3000.0), (4000.0, 4000.0)])], land_clearance_m: 300.0,"
    ));
    let scenario = Scenario::from_ron_str(&text, "island.ron").expect("valid");
    assert_eq!(scenario.land.len(), 1);
    assert!((scenario.land_clearance_m() - 300.0).abs() < 1e-9);
    assert_eq!(scenario.land[0].rings_m[0].len(), 4);
    let back = Scenario::from_ron_str(&scenario.to_ron_string().expect("writes"), "back")
        .expect("reads back");
    assert_eq!(back, scenario);
    let chart = Chart::from_scenario(&scenario).expect("chart");
    assert!(chart.in_no_go(vorrt_scenarios::DVec2::new(3800.0, 3200.0)));
    // Without land fields, the default clearance and an empty chart.
    let open = Scenario::from_ron_str(&with_land(""), "open.ron").expect("valid");
    assert!((open.land_clearance_m() - DEFAULT_LAND_CLEARANCE_M).abs() < 1e-9);
    assert!(Chart::from_scenario(&open).expect("chart").is_empty());
}

#[test]
fn bad_areas_name_the_field() {
    let cases = [
        (
            format!("land: [{ISLAND}, Area(name: \"x\", outer_nm: [(2.0, 2.0), (3.0, 2.0)])],"),
            "land[1].outer_nm",
            "at least 3",
        ),
        (
            format!("land: [{ISLAND}, Area(name: \"bow tie\", outer_nm: [(2.0, 2.0), (3.0, 3.0), (3.0, 2.0), (2.0, 3.0)])],"),
            "land[1].outer_nm",
            "crosses itself",
        ),
        (
            "land: [Area(name: \"x\", outer_nm: [(2.0, 2.0), (3.0, 2.0), (3.0, inf)])],".to_owned(),
            "land[0].outer_nm",
            "finite",
        ),
        (
            "land: [Area(name: \"x\", outer_nm: [(2.0, 2.0), (3.0, 2.0), (3.0, 3.0)], holes_nm: [[(5.0, 5.0), (6.0, 5.0), (6.0, 6.0)]])],".to_owned(),
            "land[0].holes_nm[0]",
            "outside the outer ring",
        ),
        (
            "no_go: [Area(name: \"x\", outer_lat_lon: [(50.0, 1.0), (50.1, 1.0), (50.1, 1.1)])],".to_owned(),
            "no_go[0].outer_lat_lon",
            "local scenario",
        ),
        (
            "land: [Area(name: \"rock\", outer_nm: [(-0.1, -3.1), (0.1, -3.1), (0.1, -2.9)])],".to_owned(),
            "ownship.start_nm",
            "is on land",
        ),
        (
            "land: [Area(name: \"rock\", outer_nm: [(0.2, 2.9), (0.4, 2.9), (0.4, 3.1)])],".to_owned(),
            "ownship.goal_nm",
            "within the",
        ),
        (
            "land: [Area(name: \"rock\", outer_nm: [(2.9, -0.1), (3.1, -0.1), (3.1, 0.1)])],".to_owned(),
            "targets[0] \"TS1\".start_nm",
            "is on land",
        ),
        (
            "no_go: [Area(name: \"range\", outer_nm: [(-1.0, 2.0), (1.0, 2.0), (0.0, 4.0)])],".to_owned(),
            "ownship.goal_nm",
            "no-go",
        ),
        ("land_clearance_m: -1.0,".to_owned(), "land_clearance_m", "expected a distance"),
        (
            "land_geojson: \"coast.geojson\",".to_owned(),
            "land_geojson",
            "geographic scenario",
        ),
    ];
    for (land, field, problem) in cases {
        let (got, message) = invalid(&land);
        assert_eq!(got, field, "{message}");
        assert!(message.contains(problem), "{message}");
    }
}

/// A geographic scenario off a coast, with land read from a `GeoJSON` file
/// beside it.
#[test]
fn land_geojson_is_read_beside_the_scenario_and_projected() {
    let dir: PathBuf = std::env::temp_dir().join(format!("vorrt-land-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    // A square of land 0.05° (about 3.2 km) east of ownship, [lon, lat].
    let geojson = r#"{"type": "FeatureCollection", "features": [{"type": "Feature",
        "properties": {"name": "cape"}, "geometry": {"type": "Polygon", "coordinates":
        [[[-0.95, 50.25], [-0.9, 50.25], [-0.9, 50.35], [-0.95, 50.35], [-0.95, 50.25]]]}}]}"#;
    std::fs::write(dir.join("coast.geojson"), geojson).expect("write");
    let scenario_text = r#"Scenario(
        name: "cape",
        ownship: Vessel(name: "own", course_deg: 0.0, speed_kn: 10.0, length_m: 80.0,
                        start_lat_lon: (50.2, -1.0), goal_lat_lon: (50.3, -1.0)),
        land_geojson: "coast.geojson",
    )"#;
    std::fs::write(dir.join("cape.ron"), scenario_text).expect("write");
    let scenario = Scenario::load(&dir.join("cape.ron")).expect("loads");
    assert_eq!(scenario.geojson_land.len(), 1);
    assert_eq!(scenario.geojson_land[0].name, "cape");
    let chart = Chart::from_scenario(&scenario).expect("chart");
    // The cape's west shore is 0.05° of longitude (3.56 km at 50.3° N)
    // east of ownship's goal.
    let at_goal = chart.land_distance_m(scenario.ownship_goal_m());
    assert!((at_goal - 3_556.0).abs() < 20.0, "{at_goal}");
    // From text, a relative path is resolved from the current directory.
    let error = Scenario::from_ron_str(scenario_text, "text").unwrap_err();
    assert_eq!(error.field(), Some("land_geojson"), "{error}");
    assert!(error.to_string().contains("cannot read"), "{error}");
    // A bad polygon in the file names the file and the place in it.
    std::fs::write(
        dir.join("coast.geojson"),
        r#"{"type": "Polygon", "coordinates": [[[-0.95, 50.25], [-0.9, 50.35], [-0.9, 50.25], [-0.95, 50.35]]]}"#,
    )
    .expect("write");
    let error = Scenario::load(&dir.join("cape.ron")).unwrap_err();
    assert_eq!(error.field(), Some("land_geojson"), "{error}");
    assert!(error.to_string().contains("crosses itself"), "{error}");
    std::fs::remove_dir_all(&dir).expect("clean up");
}
