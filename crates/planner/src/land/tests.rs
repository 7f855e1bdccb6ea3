use super::*;
use geo::{Contains, Coord, Distance, Euclidean, Line, LineString, Point};
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};

fn ring(points: &[(f64, f64)]) -> LineString<f64> {
    LineString::from(points.to_vec())
}

/// A 2 km square island with a 1 km square lagoon (a hole) in its middle.
fn atoll() -> Polygon<f64> {
    Polygon::new(
        ring(&[(0.0, 0.0), (2000.0, 0.0), (2000.0, 2000.0), (0.0, 2000.0)]),
        vec![ring(&[
            (500.0, 500.0),
            (1500.0, 500.0),
            (1500.0, 1500.0),
            (500.0, 1500.0),
        ])],
    )
}

fn segment(start_m: DVec2, end_m: DVec2, margin_m: f64) -> Segment {
    Segment {
        start_m,
        end_m,
        margin_m,
        start_elapsed_s: 0.0,
        duration_s: 1.0,
        course_rad: 0.0,
        course_spread_rad: 0.0,
    }
}

fn unit(rng: &mut ChaCha8Rng) -> f64 {
    #[expect(clippy::cast_precision_loss, reason = "53 random bits are exact")]
    let value = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    value
}

/// A star-shaped polygon about `centre`: simple by construction.
fn random_star(rng: &mut ChaCha8Rng, centre: DVec2) -> Polygon<f64> {
    let vertices = 3 + usize::try_from(rng.next_u64() % 30).unwrap_or(0);
    #[expect(clippy::cast_precision_loss, reason = "a few dozen vertices")]
    let points: Vec<(f64, f64)> = (0..vertices)
        .map(|index| {
            let angle = std::f64::consts::TAU * (index as f64 + 0.5 * unit(rng)) / vertices as f64;
            let radius = 200.0 + 1500.0 * unit(rng);
            (
                centre.x + radius * angle.cos(),
                centre.y + radius * angle.sin(),
            )
        })
        .collect();
    Polygon::new(ring(&points), Vec::new())
}

#[test]
#[expect(
    clippy::float_cmp,
    reason = "distances to axis-aligned edges are exact"
)]
fn distances_and_inside_with_a_hole() {
    let land = LandConstraint::new(&[atoll()], 100.0).unwrap();
    assert_eq!(land.edge_count(), 8);
    assert!(land.contains(DVec2::new(250.0, 1000.0)));
    // The lagoon is water.
    assert!(!land.contains(DVec2::new(1000.0, 1000.0)));
    assert_eq!(land.distance_m(DVec2::new(1000.0, 1000.0)), 500.0);
    assert_eq!(land.distance_m(DVec2::new(250.0, 1000.0)), 0.0);
    assert_eq!(land.distance_m(DVec2::new(-300.0, 1000.0)), 300.0);
    assert_eq!(land.distance_m(DVec2::new(2300.0, 2400.0)), 500.0);
    // A segment crossing the island, and one wholly on it.
    assert_eq!(
        land.segment_distance_m(DVec2::new(-100.0, 100.0), DVec2::new(3000.0, 100.0)),
        0.0
    );
    assert_eq!(
        land.segment_distance_m(DVec2::new(100.0, 100.0), DVec2::new(200.0, 200.0)),
        0.0
    );
    assert_eq!(
        land.segment_distance_m(DVec2::new(-400.0, -100.0), DVec2::new(3000.0, -100.0)),
        100.0
    );
    assert!(LandConstraint::new(&[], 100.0).unwrap().is_empty());
    assert_eq!(
        LandConstraint::new(&[], 100.0)
            .unwrap()
            .distance_m(DVec2::ZERO),
        f64::INFINITY
    );
}

#[test]
fn segments_are_refused_within_the_clearance_and_margin() {
    let land = LandConstraint::new(&[atoll()], 100.0).unwrap();
    let below = |y: f64, margin_m: f64| {
        land.check_segment(&segment(
            DVec2::new(-500.0, y),
            DVec2::new(2500.0, y),
            margin_m,
        ))
    };
    assert_eq!(below(-99.0, 0.0), Err(ConstraintViolation::Land));
    assert_eq!(below(-101.0, 0.0), Ok(()));
    assert_eq!(below(-101.0, 5.0), Err(ConstraintViolation::Land));
    // Wholly inside the island, far from every edge of a thin clearance.
    let thin = LandConstraint::new(&[atoll()], 1.0).unwrap();
    let inland = segment(DVec2::new(200.0, 900.0), DVec2::new(200.0, 1100.0), 0.0);
    assert_eq!(thin.check_segment(&inland), Err(ConstraintViolation::Land));
    // Inside the lagoon, clear of its shore.
    let lagoon = segment(DVec2::new(800.0, 800.0), DVec2::new(1200.0, 1200.0), 0.0);
    assert_eq!(land.check_segment(&lagoon), Ok(()));
    assert!(land.admits_point(DVec2::new(1000.0, 1000.0)));
    assert!(!land.admits_point(DVec2::new(1000.0, 1450.0)));
    assert!(!land.admits_point(DVec2::new(100.0, 100.0)));
    assert!(!land.admits_point(DVec2::new(-50.0, 100.0)));
    let no_go = LandConstraint::no_go(&[atoll()], 0.0).unwrap();
    assert_eq!(no_go.violation(), ConstraintViolation::NoGoArea);
    assert_eq!(
        no_go.check_segment(&inland),
        Err(ConstraintViolation::NoGoArea)
    );
    assert!((no_go.clearance_m() - 0.0).abs() < f64::EPSILON);
}

#[test]
fn overlapping_polygons_are_both_land() {
    let square = |x: f64| {
        Polygon::new(
            ring(&[
                (x, 0.0),
                (x + 1000.0, 0.0),
                (x + 1000.0, 1000.0),
                (x, 1000.0),
            ]),
            Vec::new(),
        )
    };
    // Even-odd over both would call the overlap water.
    let land = LandConstraint::new(&[square(0.0), square(500.0)], 0.0).unwrap();
    assert!(land.contains(DVec2::new(750.0, 500.0)));
    assert!(land.contains(DVec2::new(250.0, 500.0)));
    assert!(!land.contains(DVec2::new(1750.0, 500.0)));
}

#[test]
fn bad_polygons_are_refused() {
    let two = Polygon::new(ring(&[(0.0, 0.0), (1.0, 0.0)]), Vec::new());
    assert_eq!(
        LandConstraint::new(&[atoll(), two], 0.0).unwrap_err(),
        LandError::TooFewPoints {
            polygon: 1,
            ring: 0
        }
    );
    let nan = Polygon::new(ring(&[(0.0, 0.0), (1.0, 0.0), (f64::NAN, 1.0)]), Vec::new());
    assert!(matches!(
        LandConstraint::new(&[nan], 0.0),
        Err(LandError::NonFinite { vertex: 2, .. })
    ));
    assert!(matches!(
        LandConstraint::new(&[atoll()], -1.0),
        Err(LandError::Clearance { .. })
    ));
    assert!(
        LandError::TooFewPoints {
            polygon: 0,
            ring: 1
        }
        .to_string()
        .contains("ring 1")
    );
}

/// The index's answers equal a brute force over every polygon by `geo`'s
/// own distance and containment.
#[test]
fn the_index_agrees_with_brute_force_on_random_polygons() {
    let mut rng = ChaCha8Rng::seed_from_u64(29);
    for _ in 0..20 {
        let polygons: Vec<Polygon<f64>> = (0..4)
            .map(|_| {
                let centre = DVec2::new(8000.0 * unit(&mut rng), 8000.0 * unit(&mut rng));
                random_star(&mut rng, centre)
            })
            .collect();
        let land = LandConstraint::new(&polygons, 150.0).unwrap();
        let random_point = |rng: &mut ChaCha8Rng| {
            DVec2::new(
                -1000.0 + 10_000.0 * unit(rng),
                -1000.0 + 10_000.0 * unit(rng),
            )
        };
        let coord = |point: DVec2| Coord {
            x: point.x,
            y: point.y,
        };
        for _ in 0..50 {
            let a = random_point(&mut rng);
            let b = a + DVec2::new(
                1500.0 * unit(&mut rng) - 750.0,
                1500.0 * unit(&mut rng) - 750.0,
            );
            let point = Point::from(coord(a));
            let line = Line::new(coord(a), coord(b));
            let inside = polygons.iter().any(|polygon| polygon.contains(&point));
            let point_brute = polygons
                .iter()
                .map(|polygon| Euclidean.distance(&point, polygon))
                .fold(f64::INFINITY, f64::min);
            let segment_brute = polygons
                .iter()
                .map(|polygon| Euclidean.distance(&line, polygon))
                .fold(f64::INFINITY, f64::min);
            assert_eq!(land.contains(a), inside, "{a}");
            assert!((land.distance_m(a) - point_brute).abs() < 1e-6, "{a}");
            assert!(
                (land.segment_distance_m(a, b) - segment_brute).abs() < 1e-6,
                "{a} {b}: {} vs {segment_brute}",
                land.segment_distance_m(a, b)
            );
            assert_eq!(
                land.check_segment(&segment(a, b, 0.0)).is_err(),
                segment_brute < 150.0,
                "{a} {b}: {segment_brute}"
            );
        }
    }
}
