//! The coastal fixtures (`fixtures/coastal/`) against their own land: start
//! and goal in water and clear of it, the straight routes clear of it, the
//! Dover lanes in water and crossed at right angles, and the Kent coast
//! really limiting the starboard alteration.
//!
//! The land is read here from the `GeoJSON` by hand and measured with `geo`,
//! independently of the planner's land constraint; the scenario itself is
//! loaded with `Scenario::load`, as a user loads it.

use geo::{
    Contains, Coord, Distance, Euclidean, LineString, MultiPolygon, Point, Polygon, Validation,
    Winding,
};
use std::path::{Path, PathBuf};
use vorrt_scenarios::geometry::units::NAUTICAL_MILE_M;
use vorrt_scenarios::{DVec2, Lane, LocalFrame, Scenario};

fn coastal_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/coastal")
}

/// A fixture: the scenario validated without its land and lanes, its lanes,
/// its land in the scenario's local frame (metres) and its land clearance.
struct Fixture {
    scenario: Scenario,
    lanes: Vec<Lane>,
    land_m: MultiPolygon<f64>,
    clearance_m: f64,
}

/// The value of a `field: value` line of a RON text (quotes taken off).
fn field_value<'a>(text: &'a str, field: &str) -> &'a str {
    let line = text
        .lines()
        .map(str::trim)
        .find(|line| line.starts_with(&format!("{field}:")))
        .unwrap_or_else(|| panic!("no {field}"));
    line.split_once(':')
        .map_or(line, |(_, value)| value)
        .trim()
        .trim_end_matches(',')
        .trim_matches('"')
}

fn load(name: &str) -> Fixture {
    let path = coastal_dir().join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    let geojson = field_value(&text, "land_geojson").to_owned();
    let clearance_m: f64 = field_value(&text, "land_clearance_m").parse().unwrap();
    // Loaded as a user loads it: land, lanes and separation zones validated
    // by the format (start and goal off land, lanes well formed).
    let scenario = Scenario::load(&path).unwrap();
    let lanes = scenario.lanes.clone();
    let frame = scenario.local_frame().expect("a geographic scenario");
    let land_lon_lat = read_land(&coastal_dir().join(geojson));
    let land_m = project(&land_lon_lat, &frame);
    Fixture {
        scenario,
        lanes,
        land_m,
        clearance_m,
    }
}

/// The polygons of a land `GeoJSON` file as `vorrt coast` writes it.
fn read_land(path: &Path) -> MultiPolygon<f64> {
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let ring = |ring: &serde_json::Value| -> LineString<f64> {
        ring.as_array()
            .unwrap()
            .iter()
            .map(|position| Coord {
                x: position[0].as_f64().unwrap(),
                y: position[1].as_f64().unwrap(),
            })
            .collect()
    };
    let polygons = value["features"]
        .as_array()
        .unwrap()
        .iter()
        .map(|feature| {
            assert_eq!(feature["geometry"]["type"], "Polygon");
            let rings = feature["geometry"]["coordinates"].as_array().unwrap();
            Polygon::new(ring(&rings[0]), rings[1..].iter().map(ring).collect())
        })
        .collect();
    MultiPolygon::new(polygons)
}

fn project(land: &MultiPolygon<f64>, frame: &LocalFrame) -> MultiPolygon<f64> {
    let ring = |ring: &LineString<f64>| -> LineString<f64> {
        ring.0
            .iter()
            .map(|coord| {
                let position_m = frame.to_local_m(coord.y, coord.x);
                Coord {
                    x: position_m.x,
                    y: position_m.y,
                }
            })
            .collect()
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

fn point(position_m: DVec2) -> Point<f64> {
    Point::new(position_m.x, position_m.y)
}

/// Distance from a point to land, metres; 0 on land.
fn to_land_m(land_m: &MultiPolygon<f64>, position_m: DVec2) -> f64 {
    if land_m.contains(&point(position_m)) {
        return 0.0;
    }
    land_m
        .0
        .iter()
        .flat_map(|polygon| std::iter::once(polygon.exterior()).chain(polygon.interiors()))
        .map(|ring| Euclidean.distance(&point(position_m), ring))
        .fold(f64::INFINITY, f64::min)
}

/// The least distance to land along a straight leg, sampled every 10 m.
fn leg_to_land_m(land_m: &MultiPolygon<f64>, from_m: DVec2, to_m: DVec2) -> f64 {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a positive sample count of a few thousand"
    )]
    let samples = (from_m.distance(to_m) / 10.0).ceil().max(1.0) as u32;
    (0..=samples)
        .map(|index| from_m.lerp(to_m, f64::from(index) / f64::from(samples)))
        .map(|position_m| to_land_m(land_m, position_m))
        .fold(f64::INFINITY, f64::min)
}

/// The unit vector of a nautical course in degrees.
fn heading(course_deg: f64) -> DVec2 {
    let course_rad = course_deg.to_radians();
    DVec2::new(course_rad.sin(), course_rad.cos())
}

/// Checks every fixture's start, goal and straight route against its land,
/// and returns ownship's least distance to land along the route.
fn check_water(fixture: &Fixture, min_start_goal_m: f64) -> f64 {
    let scenario = &fixture.scenario;
    let own = &scenario.ownship;
    let start_m = own.projected.start_m.unwrap();
    let goal_m = own.projected.goal_m.unwrap();
    for (what, position_m) in [("start", start_m), ("goal", goal_m)] {
        let distance_m = to_land_m(&fixture.land_m, position_m);
        assert!(
            distance_m >= min_start_goal_m.max(fixture.clearance_m),
            "{}: ownship {what} is {distance_m:.0} m from land",
            scenario.name
        );
    }
    let route_m = leg_to_land_m(&fixture.land_m, start_m, goal_m);
    assert!(
        route_m >= fixture.clearance_m,
        "{}: the straight route comes {route_m:.0} m from land",
        scenario.name
    );
    for target in &scenario.targets {
        let start_m = target.projected.start_m.unwrap();
        let goal_m = target.projected.goal_m.unwrap();
        let track_m = leg_to_land_m(&fixture.land_m, start_m, goal_m);
        assert!(
            track_m >= fixture.clearance_m,
            "{}: target {} comes {track_m:.0} m from land",
            scenario.name,
            target.name
        );
    }
    route_m
}

#[test]
fn the_land_files_are_valid_natural_earth_clips() {
    for name in [
        "dover_strait_ne10m.geojson",
        "new_york_harbor_ne10m.geojson",
    ] {
        let path = coastal_dir().join(name);
        let land = read_land(&path);
        assert!(!land.0.is_empty(), "{name}");
        assert!(land.is_valid(), "{name}: {:?}", land.validation_errors());
        for polygon in &land.0 {
            assert!(
                polygon.exterior().is_ccw(),
                "{name}: RFC 7946 outer rings are counter-clockwise"
            );
        }
        let value: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let note = value["vorrt"]["note"].as_str().unwrap();
        assert!(
            note.contains("Natural Earth") && note.contains("public domain"),
            "{name}"
        );
        assert_eq!(value["vorrt"]["source"], "land-10m.json");
    }
}

#[test]
fn dover_tss_crossing_is_in_water_and_crosses_the_lanes_square() {
    let fixture = load("dover_tss_crossing.ron");
    let route_m = check_water(&fixture, 1.5 * NAUTICAL_MILE_M);
    assert!(route_m > 2_500.0, "{route_m}");
    let own = &fixture.scenario.ownship;
    let start_m = own.projected.start_m.unwrap();
    let goal_m = own.projected.goal_m.unwrap();
    let route = (goal_m - start_m).normalize();
    assert_eq!(fixture.lanes.len(), 2);
    let mut crossings_m = Vec::new();
    for lane in &fixture.lanes {
        let from_m = lane.from_m();
        let to_m = lane.to_m();
        let flow = (to_m - from_m).normalize();
        // Rule 10(c): the route crosses the flow at right angles (within 1°).
        let angle_deg = route.dot(flow).abs().acos().to_degrees();
        assert!((angle_deg - 90.0).abs() < 1.0, "{}: {angle_deg}", lane.name);
        // The lane's whole strip is water, with the land clearance to spare.
        let half_width_m = 0.5 * lane.width_nm * NAUTICAL_MILE_M;
        let side = flow.perp() * half_width_m;
        for (a_m, b_m) in [
            (from_m + side, to_m + side),
            (from_m - side, to_m - side),
            (from_m - side, from_m + side),
            (to_m - side, to_m + side),
        ] {
            let edge_m = leg_to_land_m(&fixture.land_m, a_m, b_m);
            assert!(
                edge_m >= fixture.clearance_m,
                "{}: an edge is {edge_m:.0} m from land",
                lane.name
            );
        }
        // Start and goal lie outside the lanes (in the inshore zones); the route crosses each.
        let offset = |position_m: DVec2| (position_m - from_m).perp_dot(flow);
        assert!(
            offset(start_m).abs() > half_width_m && offset(goal_m).abs() > half_width_m,
            "{}",
            lane.name
        );
        assert!(
            offset(start_m).signum() != offset(goal_m).signum(),
            "{}",
            lane.name
        );
        crossings_m.push(offset(start_m).abs());
    }
    // The south-west-bound lane is the English one: ownship meets it first,
    // and the two lanes leave a separation zone of 1.5 nm between them.
    let lane_sw = &fixture.lanes[0];
    assert!(lane_sw.name.contains("south-west"));
    let flow_sw = (lane_sw.to_m() - lane_sw.from_m()).normalize();
    assert!(heading(220.0).dot(flow_sw) > 0.999);
    assert!(crossings_m[0] < crossings_m[1]);
    let gap_nm = (crossings_m[1] - crossings_m[0]) / NAUTICAL_MILE_M - 2.5;
    assert!((gap_nm - 1.5).abs() < 0.01, "{gap_nm}");
    // Every target starts inside a lane and steers along its flow.
    for target in &fixture.scenario.targets {
        let start_m = target.projected.start_m.unwrap();
        let course = (target.projected.goal_m.unwrap() - start_m).normalize();
        let in_lane = fixture.lanes.iter().any(|lane| {
            let from_m = lane.from_m();
            let flow = (lane.to_m() - from_m).normalize();
            (start_m - from_m).perp_dot(flow).abs() < 0.5 * lane.width_nm * NAUTICAL_MILE_M
                && course.dot(flow) > 0.999
        });
        assert!(in_lane, "{}", target.name);
    }
}

#[test]
fn the_kent_coast_limits_the_starboard_alteration() {
    let fixture = load("kent_coast_head_on.ron");
    check_water(&fixture, 2_000.0);
    let own = &fixture.scenario.ownship;
    let target = &fixture.scenario.targets[0];
    let start_m = own.projected.start_m.unwrap();
    let course = (own.projected.goal_m.unwrap() - start_m).normalize();
    let own_speed_mps = own.speed_kn * NAUTICAL_MILE_M / 3600.0;
    let target_start_m = target.projected.start_m.unwrap();
    let target_speed_mps = target.speed_kn * NAUTICAL_MILE_M / 3600.0;
    let target_course = (target.projected.goal_m.unwrap() - target_start_m).normalize();
    // Nearly end-on (rule 14: reciprocal within a few degrees).
    assert!(course.dot(target_course) < -0.999);
    // Where the two would meet on their straight tracks (closest approach).
    let relative_m = target_start_m - start_m;
    let relative_mps = target_course * target_speed_mps - course * own_speed_mps;
    let meet_s = -relative_m.dot(relative_mps) / relative_mps.length_squared();
    let meet_m = start_m + course * own_speed_mps * meet_s;
    let miss_m = (relative_m + relative_mps * meet_s).length();
    assert!(miss_m < 200.0, "a real collision course: {miss_m} m");
    let along_nm = meet_m.distance(start_m) / NAUTICAL_MILE_M;
    assert!((4.5..5.5).contains(&along_nm), "{along_nm}");
    // The land is to starboard, within 2 km of the meeting point.
    let starboard = -course.perp();
    let to_starboard_m = (0..400)
        .map(|step| meet_m + starboard * f64::from(step) * 10.0)
        .find(|&position_m| to_land_m(&fixture.land_m, position_m) == 0.0)
        .map(|position_m| position_m.distance(meet_m));
    assert!(
        to_starboard_m.is_some_and(|distance_m| distance_m < 2_000.0),
        "{to_starboard_m:?}"
    );
    // A bold alteration (35°, held for 2 nm from 1.5 nm before the meeting
    // point) runs within the clearance of the coast to starboard, while the
    // same alteration to port only opens the distance to land.
    let turn_from_m = meet_m - course * 1.5 * NAUTICAL_MILE_M;
    let leg = |turn_deg: f64| {
        let (sin, cos) = turn_deg.to_radians().sin_cos();
        // Positive turns are clockwise (to starboard) in the east-north frame.
        let turned = DVec2::new(
            course.x * cos + course.y * sin,
            -course.x * sin + course.y * cos,
        );
        leg_to_land_m(
            &fixture.land_m,
            turn_from_m,
            turn_from_m + turned * 2.0 * NAUTICAL_MILE_M,
        )
    };
    let starboard_m = leg(35.0);
    let port_m = leg(-35.0);
    assert!(
        starboard_m < fixture.clearance_m,
        "starboard leg {starboard_m:.0} m from land"
    );
    let turn_from_land_m = to_land_m(&fixture.land_m, turn_from_m);
    assert!(
        turn_from_land_m > 3.0 * fixture.clearance_m,
        "{turn_from_land_m}"
    );
    assert!(
        port_m >= turn_from_land_m - 1.0,
        "port leg {port_m:.0} m from land"
    );
}

#[test]
fn the_narrows_approach_has_land_on_both_sides() {
    let fixture = load("new_york_narrows_approach.ron");
    let route_m = check_water(&fixture, 1_000.0);
    assert!(route_m < 1_000.0, "the Narrows are narrow: {route_m}");
    let own = &fixture.scenario.ownship;
    let start_m = own.projected.start_m.unwrap();
    let goal_m = own.projected.goal_m.unwrap();
    let course = (goal_m - start_m).normalize();
    // Halfway along, land lies within 2 km on either beam.
    let middle_m = start_m.lerp(goal_m, 0.5);
    for side in [course.perp(), -course.perp()] {
        let land_m = (0..200)
            .map(|step| middle_m + side * f64::from(step) * 10.0)
            .find(|&position_m| to_land_m(&fixture.land_m, position_m) == 0.0);
        assert!(land_m.is_some(), "no land within 2 km abeam");
    }
    assert!((fixture.clearance_m - 200.0).abs() < 1e-9);
}
