use super::*;

fn westbound(width_m: f64) -> TrafficLane {
    TrafficLane {
        from_m: DVec2::new(10_000.0, 0.0),
        to_m: DVec2::new(-10_000.0, 0.0),
        width_m,
    }
}

fn one_lane() -> Scheme {
    Scheme {
        lanes: vec![westbound(1852.0)],
        ..Scheme::default()
    }
}

/// A straight track from `start_m` on `course_deg` at 6 m/s, sampled every 5 s for `count` samples.
fn straight(start_m: DVec2, course_deg: f64, count: usize) -> (Vec<f64>, Vec<DVec2>, Vec<f64>) {
    let course = course_deg.to_radians();
    let times: Vec<f64> = std::iter::successors(Some(0.0), |t| Some(t + 5.0))
        .take(count)
        .collect();
    let positions = times
        .iter()
        .map(|t| start_m + angle::velocity(course, 6.0) * *t)
        .collect();
    (times, positions, vec![course; count])
}

#[test]
fn a_perpendicular_crossing_is_clean() {
    let (t, p, c) = straight(DVec2::new(0.0, -2000.0), 0.0, 150);
    let judgement = judge_track(&one_lane(), &t, &p, &c);
    assert_eq!(judgement.crossings.len(), 1);
    assert!(judgement.crossings[0].square);
    assert!(judgement.is_clean(), "{:?}", judgement.findings);
    assert_eq!(judgement.square_crossings(), 1);
}

#[test]
fn a_crossing_at_45_degrees_is_a_10c_finding() {
    let (t, p, c) = straight(DVec2::new(-2000.0, -2000.0), 45.0, 250);
    let judgement = judge_track(&one_lane(), &t, &p, &c);
    assert_eq!(judgement.crossings.len(), 1);
    assert!(!judgement.crossings[0].square);
    assert!((judgement.crossings[0].max_off_perpendicular_deg - 45.0).abs() < 1e-6);
    assert_eq!(judgement.count(Rule10Clause::CrossingNotSquare), 1);
    assert_eq!(judgement.findings.len(), 1);
}

#[test]
fn sailing_against_the_flow_is_a_10b_i_finding() {
    // Eastbound along the centre of a westbound lane.
    let (t, p, c) = straight(DVec2::new(-3000.0, 0.0), 90.0, 100);
    let judgement = judge_track(&one_lane(), &t, &p, &c);
    assert!(judgement.crossings.is_empty());
    assert_eq!(judgement.count(Rule10Clause::AgainstFlow), 1);
    let finding = judgement.findings[0];
    assert!((finding.worst_angle_deg - 180.0).abs() < 1e-6);
    // With the flow: clean.
    let (t, p, c) = straight(DVec2::new(3000.0, 0.0), 270.0, 100);
    assert!(judge_track(&one_lane(), &t, &p, &c).is_clean());
}

#[test]
fn joining_from_the_side_at_a_large_angle_is_a_10b_iii_finding() {
    // North-west into the lane, then stops inside it: a join at 45°.
    let (t, p, c) = straight(DVec2::new(0.0, -1500.0), 315.0, 100);
    let inside = p
        .iter()
        .rposition(|point| one_lane().lanes[0].contains_m(*point))
        .expect("enters");
    let judgement = judge_track(&one_lane(), &t[..=inside], &p[..=inside], &c[..=inside]);
    assert!(judgement.crossings.is_empty());
    assert_eq!(judgement.count(Rule10Clause::JoinOrLeaveAngle), 1);
}

fn zone_between() -> Scheme {
    let lane = |y: f64, westward: bool| TrafficLane {
        from_m: DVec2::new(if westward { 10_000.0 } else { -10_000.0 }, y),
        to_m: DVec2::new(if westward { -10_000.0 } else { 10_000.0 }, y),
        width_m: 1000.0,
    };
    Scheme {
        lanes: vec![lane(-750.0, false), lane(750.0, true)],
        zones: vec![SeparationZone {
            vertices_m: vec![
                DVec2::new(-10_000.0, -250.0),
                DVec2::new(10_000.0, -250.0),
                DVec2::new(10_000.0, 250.0),
                DVec2::new(-10_000.0, 250.0),
            ],
            axis_course_rad: 90f64.to_radians(),
        }],
        parameters: Rule10Parameters::default(),
    }
}

#[test]
fn crossing_a_zone_square_is_clean_and_sailing_in_it_is_a_10e_finding() {
    let scheme = zone_between();
    let (t, p, c) = straight(DVec2::new(0.0, -2000.0), 0.0, 150);
    let judgement = judge_track(&scheme, &t, &p, &c);
    assert_eq!(judgement.crossings.len(), 2);
    assert!(judgement.is_clean(), "{:?}", judgement.findings);
    let (t, p, c) = straight(DVec2::new(-3000.0, 0.0), 90.0, 100);
    let judgement = judge_track(&scheme, &t, &p, &c);
    assert_eq!(judgement.count(Rule10Clause::SeparationZone), 1);
    let uses = scheme.lane_uses(DVec2::new(0.0, -2000.0), DVec2::new(0.0, 2000.0));
    assert_eq!(uses, [LaneUse::Crossing, LaneUse::Crossing]);
    assert!(
        scheme
            .check_segment(
                &uses,
                DVec2::new(0.0, 0.0),
                DVec2::new(100.0, 0.0),
                0.0,
                90f64.to_radians()
            )
            .is_err()
    );
    assert!(
        scheme
            .check_segment(
                &uses,
                DVec2::new(0.0, -50.0),
                DVec2::new(0.0, 50.0),
                0.0,
                0.0
            )
            .is_ok()
    );
}

#[test]
fn the_planner_check_refuses_oblique_and_against_flow_headings_in_a_lane_only() {
    let scheme = one_lane();
    let inside = (DVec2::new(0.0, -100.0), DVec2::new(50.0, 0.0));
    let outside = (DVec2::new(0.0, -3000.0), DVec2::new(50.0, -2900.0));
    let crossing = [LaneUse::Crossing];
    let following = [LaneUse::Following];
    for (course_deg, crossed, followed) in [
        (0.0, true, true),
        (14.0, true, true),
        (20.0, false, false),
        (90.0, false, false),
        (260.0, false, true),
        (180.0, true, true),
    ] {
        let course = f64::to_radians(course_deg);
        assert_eq!(
            scheme
                .check_segment(&crossing, inside.0, inside.1, 0.0, course)
                .is_ok(),
            crossed,
            "{course_deg}° crossing"
        );
        assert_eq!(
            scheme
                .check_segment(&following, inside.0, inside.1, 0.0, course)
                .is_ok(),
            followed,
            "{course_deg}° following"
        );
        assert!(
            scheme
                .check_segment(&crossing, outside.0, outside.1, 0.0, course)
                .is_ok()
        );
    }
    // A margin reaches into the lane from just outside it.
    let edge = (DVec2::new(0.0, -960.0), DVec2::new(50.0, -960.0));
    let east = 90f64.to_radians();
    assert!(
        scheme
            .check_segment(&crossing, edge.0, edge.1, 0.0, east)
            .is_ok()
    );
    assert!(
        scheme
            .check_segment(&crossing, edge.0, edge.1, 50.0, east)
            .is_err()
    );
    // A segment passing right through the lane, both ends outside.
    assert!(
        scheme
            .check_segment(
                &crossing,
                DVec2::new(0.0, -2000.0),
                DVec2::new(2000.0, 2000.0),
                0.0,
                0.46
            )
            .is_err()
    );
    assert!(
        Scheme::default()
            .check_segment(&[], inside.0, inside.1, 0.0, east)
            .is_ok()
    );
    // A lane the uses do not name is crossed.
    assert!(
        scheme
            .check_segment(&[], inside.0, inside.1, 0.0, east)
            .is_err()
    );
}

#[test]
fn tolerances_are_validated() {
    assert!(Rule10Parameters::default().validate().is_ok());
    let wide = Rule10Parameters {
        crossing_tolerance_rad: 1.0,
        ..Rule10Parameters::default()
    };
    assert!(matches!(
        wide.validate(),
        Err(ColregsError::InvalidParameter {
            field: "crossing_tolerance_rad",
            ..
        })
    ));
    let none = Rule10Parameters {
        flow_tolerance_rad: 0.0,
        ..Rule10Parameters::default()
    };
    assert!(none.validate().is_err());
}

#[test]
fn every_clause_has_a_distinct_key() {
    let keys: std::collections::HashSet<_> = Rule10Clause::ALL.iter().map(|c| c.key()).collect();
    assert_eq!(keys.len(), Rule10Clause::ALL.len());
}

#[test]
fn lane_geometry() {
    let lane = westbound(1000.0);
    assert!((lane.flow_course_rad().to_degrees() - 270.0).abs() < 1e-9);
    let (along, across) = lane.lane_coordinates_m(DVec2::new(9000.0, 100.0));
    assert!((along - 1000.0).abs() < 1e-9);
    // North of a westbound lane is to its starboard.
    assert!((across - 100.0).abs() < 1e-9);
    assert!(!lane.contains_m(DVec2::new(10_500.0, 0.0)));
}
