use super::*;
use crate::error::ScenarioError;

const LOCAL: &str = r#"Scenario(
    name: "scheme",
    ownship: Vessel(name: "own", start_nm: (0.0, -3.0), course_deg: 0.0, speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 3.0)),
    lanes: [
        Lane(name: "eastbound", from_nm: (-6.0, -0.75), to_nm: (6.0, -0.75), width_nm: 1.0),
        Lane(name: "westbound", from_nm: (6.0, 0.75), to_nm: (-6.0, 0.75), width_nm: 1.0),
    ],
    separation_zones: [
        SeparationZone(name: "central", vertices_nm: [(-6.0, -0.25), (6.0, -0.25), (6.0, 0.25), (-6.0, 0.25)]),
    ],
    rule10: (crossing_tolerance_deg: 10.0),
)"#;

fn field_of(text: &str) -> String {
    match Scenario::from_ron_str(text, "test.ron") {
        Err(ScenarioError::Invalid { field, .. }) => field,
        other => panic!("expected an invalid scenario, got {other:?}"),
    }
}

#[test]
fn a_local_scheme_loads_with_its_zone_axis_and_tolerances() {
    let scenario = Scenario::from_ron_str(LOCAL, "test.ron").expect("valid");
    let scheme = scenario.traffic_scheme();
    assert_eq!(scheme.lanes.len(), 2);
    assert_eq!(scheme.zones.len(), 1);
    // The nearer lane of the two is as near as the other: either flow is
    // east-west, and a crossing is square to it either way.
    let axis_deg = scheme.zones[0].axis_course_rad.to_degrees();
    assert!((axis_deg - 90.0).abs() < 1e-9 || (axis_deg - 270.0).abs() < 1e-9);
    assert!(scheme.zones[0].contains_m(DVec2::ZERO));
    assert!((scheme.parameters.crossing_tolerance_rad.to_degrees() - 10.0).abs() < 1e-12);
    assert!((scheme.parameters.flow_tolerance_rad.to_degrees() - 30.0).abs() < 1e-12);
    let constraint = scenario_constraint(&scenario);
    assert_eq!(constraint.scheme(), &scheme);
}

#[test]
fn bad_zones_and_tolerances_are_named() {
    let two_vertices = LOCAL.replace(
        "[(-6.0, -0.25), (6.0, -0.25), (6.0, 0.25), (-6.0, 0.25)]",
        "[(-6.0, -0.25), (6.0, -0.25)]",
    );
    assert_eq!(
        field_of(&two_vertices),
        "separation_zones[0] \"central\".vertices_nm"
    );
    let on_a_line = LOCAL.replace("(6.0, 0.25), (-6.0, 0.25)", "(7.0, -0.25), (8.0, -0.25)");
    assert_eq!(
        field_of(&on_a_line),
        "separation_zones[0] \"central\".vertices_nm"
    );
    let not_finite = LOCAL.replace("(6.0, 0.25), (-6.0", "(6.0, inf), (-6.0");
    assert_eq!(
        field_of(&not_finite),
        "separation_zones[0] \"central\".vertices_nm[2]"
    );
    let none = LOCAL.replace(
        "vertices_nm: [(-6.0, -0.25), (6.0, -0.25), (6.0, 0.25), (-6.0, 0.25)]",
        "",
    );
    assert_eq!(
        field_of(&none),
        "separation_zones[0] \"central\".vertices_nm"
    );
    let geographic_in_local = LOCAL.replace("vertices_nm:", "vertices_lat_lon:");
    assert_eq!(
        field_of(&geographic_in_local),
        "separation_zones[0] \"central\".vertices_lat_lon"
    );
    let wide = LOCAL.replace(
        "crossing_tolerance_deg: 10.0",
        "crossing_tolerance_deg: 60.0",
    );
    assert_eq!(field_of(&wide), "rule10.crossing_tolerance_deg");
    let lane_lat_lon = LOCAL.replace(
        "from_nm: (-6.0, -0.75), to_nm",
        "from_lat_lon: (51.0, 1.4), to_nm",
    );
    assert_eq!(
        field_of(&lane_lat_lon),
        "lanes[0] \"eastbound\".from_lat_lon"
    );
    let no_end = LOCAL.replace("from_nm: (-6.0, -0.75), ", "");
    assert_eq!(field_of(&no_end), "lanes[0] \"eastbound\".from_nm");
}

const GEOGRAPHIC: &str = r#"Scenario(
    name: "geo scheme",
    ownship: Vessel(name: "own", start_lat_lon: (50.95, 1.40), course_deg: 0.0, speed_kn: 12.0, length_m: 100.0, goal_lat_lon: (51.05, 1.40)),
    lanes: [
        Lane(name: "westbound", from_lat_lon: (51.0, 1.55), to_lat_lon: (51.0, 1.25), width_nm: 1.0),
    ],
    separation_zones: [
        SeparationZone(name: "south", vertices_lat_lon: [(50.985, 1.25), (50.985, 1.55), (50.99, 1.55), (50.99, 1.25)]),
    ],
)"#;

#[test]
fn a_geographic_scheme_is_projected_about_ownships_start() {
    let scenario = Scenario::from_ron_str(GEOGRAPHIC, "geo.ron").expect("valid");
    let scheme = scenario.traffic_scheme();
    let lane = scheme.lanes[0];
    // 51.0 N is 0.05° = 3 nm north of the start.
    assert!(
        (lane.from_m.y / units::NAUTICAL_MILE_M - 3.0).abs() < 0.05,
        "{lane:?}"
    );
    assert!(lane.from_m.x > 0.0 && lane.to_m.x < 0.0);
    assert!((lane.flow_course_rad().to_degrees() - 270.0).abs() < 0.5);
    assert!(scheme.zones[0].contains_m(DVec2::new(0.0, lane.from_m.y - 1500.0)));
    let local_lane = GEOGRAPHIC.replace("from_lat_lon: (51.0, 1.55)", "from_nm: (3.0, 3.0)");
    assert_eq!(field_of(&local_lane), "lanes[0] \"westbound\".from_nm");
    let local_zone = GEOGRAPHIC.replace("vertices_lat_lon:", "vertices_m:");
    assert_eq!(
        field_of(&local_zone),
        "separation_zones[0] \"south\".vertices_m"
    );
}

#[test]
fn settings_default_to_the_rule10_parameters() {
    assert!(Rule10Settings::default().is_empty());
    assert_eq!(
        Rule10Settings::default().parameters(),
        Rule10Parameters::default()
    );
    let lane = Lane::new_nm("l", (1.0, 0.0), (-1.0, 0.0), 0.5);
    assert!((lane.traffic_course_rad().to_degrees() - 270.0).abs() < 1e-9);
    let zone = SeparationZoneSpec::new_nm("z", vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]);
    assert_eq!(zone.vertices_in_m().len(), 3);
}
