//! Simplifying land in a metric frame while keeping every ring valid.

use ::geo::{Area, MultiPolygon, Polygon, Simplify, Validation, unary_union};

/// How often [`simplify_land_m`] halves the tolerance of a polygon whose
/// simplification is not valid before it keeps the polygon as it was:
/// 50 m comes down to 0.2 m.
const MAX_HALVINGS: usize = 8;

/// What [`simplify_land_m`] did besides simplifying.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SimplifyStats {
    /// Polygons dropped because they were smaller than the minimum area.
    pub slivers_dropped: usize,
    /// Holes (lakes, enclosed water) dropped because they were smaller than
    /// the minimum area: the land grows over them, the safe side.
    pub holes_dropped: usize,
    /// Polygons whose simplification at the full tolerance was not valid and
    /// that were simplified at a smaller one.
    pub tolerance_reduced: usize,
    /// Polygons kept unsimplified because no tolerance down to
    /// 1/256 of the given one gave a valid polygon.
    pub kept_unsimplified: usize,
    /// Whether polygons overlapped after simplifying (or already in the
    /// input) and were merged by a union.
    pub merged_overlaps: bool,
}

/// Simplifies land given in a local metric frame (`x` east, `y` north,
/// metres) with Douglas-Peucker at `tolerance_m`: every vertex removed lies
/// within `tolerance_m` of the simplified ring, so the simplified coast is
/// within the tolerance of the original everywhere (Hausdorff distance).
///
/// Douglas-Peucker alone may make a ring cross itself or a hole cross its
/// outer ring; a polygon whose result fails `geo`'s OGC validity check is
/// simplified again at half the tolerance, up to 8 times (down to 1/256 of it),
/// then kept as it was. Polygons and holes smaller than `min_area_m2` are
/// dropped first (a dropped hole becomes land, a dropped islet water: the
/// limit should stay well below any islet a chart cares about). Polygons that
/// overlap one another at the end are merged by a union, so the result is a
/// valid multipolygon.
#[must_use]
pub fn simplify_land_m(
    land_m: &MultiPolygon<f64>,
    tolerance_m: f64,
    min_area_m2: f64,
) -> (MultiPolygon<f64>, SimplifyStats) {
    let mut stats = SimplifyStats::default();
    let mut kept = Vec::with_capacity(land_m.0.len());
    for polygon in &land_m.0 {
        if polygon.unsigned_area() < min_area_m2 {
            stats.slivers_dropped += 1;
            continue;
        }
        let holes: Vec<_> = polygon
            .interiors()
            .iter()
            .filter(|hole| Polygon::new((*hole).clone(), Vec::new()).unsigned_area() >= min_area_m2)
            .cloned()
            .collect();
        stats.holes_dropped += polygon.interiors().len() - holes.len();
        let polygon = Polygon::new(polygon.exterior().clone(), holes);
        kept.push(simplify_valid(&polygon, tolerance_m, &mut stats));
    }
    let mut land = MultiPolygon::new(kept);
    if !land.is_valid() {
        land = unary_union(&land.0);
        stats.merged_overlaps = true;
    }
    (land, stats)
}

/// One polygon simplified at the largest of `tolerance_m`, its half, ...
/// that gives a valid polygon, or the polygon itself.
fn simplify_valid(
    polygon: &Polygon<f64>,
    tolerance_m: f64,
    stats: &mut SimplifyStats,
) -> Polygon<f64> {
    if tolerance_m <= 0.0 {
        return polygon.clone();
    }
    let mut epsilon_m = tolerance_m;
    for halvings in 0..=MAX_HALVINGS {
        let simplified = polygon.simplify(epsilon_m);
        if simplified.exterior().0.len() >= 4 && simplified.is_valid() {
            if halvings > 0 {
                stats.tolerance_reduced += 1;
            }
            return simplified;
        }
        epsilon_m *= 0.5;
    }
    stats.kept_unsimplified += 1;
    polygon.clone()
}

#[cfg(test)]
mod tests {
    use super::*;
    use ::geo::{Distance, Euclidean, LineString, Point, polygon};
    use rand_chacha::ChaCha8Rng;
    use rand_core::{RngCore, SeedableRng};

    /// A closed ring about the origin: radius `radius_m` plus noise of up to
    /// `noise_m`, `count` vertices, anticlockwise.
    fn noisy_ring(seed: u64, count: u32, radius_m: f64, noise_m: f64) -> LineString<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        (0..count)
            .map(|index| {
                let angle = std::f64::consts::TAU * f64::from(index) / f64::from(count);
                let unit = f64::from(rng.next_u32()) / (f64::from(u32::MAX) + 1.0);
                let radius = radius_m + noise_m * (2.0 * unit - 1.0);
                (radius * angle.cos(), radius * angle.sin())
            })
            .collect()
    }

    #[test]
    fn a_simplified_ring_stays_valid_and_within_the_tolerance() {
        for seed in 0..3 {
            let ring = noisy_ring(seed, 600, 2_000.0, 40.0);
            let original = Polygon::new(ring, Vec::new());
            assert!(original.is_valid());
            let land = MultiPolygon::new(vec![original.clone()]);
            let (simplified, stats) = simplify_land_m(&land, 25.0, 625.0);
            let [kept] = simplified.0.as_slice() else {
                panic!("{simplified:?}")
            };
            assert!(kept.is_valid(), "seed {seed}");
            assert!(
                kept.exterior().0.len() < original.exterior().0.len() / 2,
                "seed {seed}: {}",
                kept.exterior().0.len()
            );
            // Every original vertex is within the tolerance of the simplified ring.
            let worst_m = original
                .exterior()
                .points()
                .map(|point: Point<f64>| Euclidean.distance(&point, kept.exterior()))
                .fold(0.0, f64::max);
            assert!(worst_m <= 25.0 + 1e-9, "seed {seed}: {worst_m} m");
            assert!(
                worst_m > 5.0,
                "seed {seed}: the tolerance was used ({worst_m} m)"
            );
            assert_eq!(stats, SimplifyStats::default());
        }
    }

    #[test]
    fn islands_with_lakes_stay_valid_at_any_tolerance() {
        // Round islands (radius 1 km +- 30 m) with a lake 150 m from the
        // shore, simplified at tolerances from 5 m to 320 m: from about
        // 150 m on, Douglas-Peucker alone cuts the shore across the lake;
        // the result must always be valid, and within the tolerance of
        // every original vertex.
        let mut reduced = 0;
        for seed in 0..24_u32 {
            let exterior = noisy_ring(u64::from(seed), 160, 1_000.0, 30.0);
            let bearing = 0.7 * f64::from(seed);
            let centre = (700.0 * bearing.cos(), 700.0 * bearing.sin());
            let lake: LineString<f64> = noisy_ring(u64::from(seed) + 1_000, 24, 150.0, 10.0)
                .0
                .iter()
                .map(|c| (c.x + centre.0, c.y + centre.1))
                .collect();
            let island = Polygon::new(exterior, vec![lake]);
            assert!(island.is_valid(), "seed {seed}");
            let tolerance_m = 5.0 * f64::from(1 + seed % 8).powi(2);
            let (land, stats) =
                simplify_land_m(&MultiPolygon::new(vec![island.clone()]), tolerance_m, 1.0);
            assert!(
                land.is_valid(),
                "seed {seed}: {:?}",
                land.validation_errors()
            );
            reduced += stats.tolerance_reduced;
            for kept in &land.0 {
                let worst_m = island
                    .exterior()
                    .points()
                    .map(|point: Point<f64>| Euclidean.distance(&point, kept.exterior()))
                    .fold(0.0, f64::max);
                assert!(
                    worst_m <= tolerance_m + 1e-9,
                    "seed {seed}: {worst_m} m at {tolerance_m} m"
                );
            }
        }
        assert!(
            reduced > 0,
            "no case needed the finer tolerance: the test tests nothing"
        );
    }

    #[test]
    fn a_simplification_that_would_cut_a_hole_is_redone_finer() {
        // Land above y = 0 with a 50 m bump south into the water, and a lake
        // 20 m square inside the bump. At a 60 m tolerance Douglas-Peucker
        // would cut the bump off across the lake (and close the lake up);
        // at 30 m the bump stays but the lake collapses; at 7.5 m both stay.
        let land = polygon![
            exterior: [
                (x: 0.0, y: 0.0), (x: 400.0, y: 0.0), (x: 500.0, y: -50.0), (x: 600.0, y: 0.0),
                (x: 1_000.0, y: 0.0), (x: 1_000.0, y: 1_000.0), (x: 0.0, y: 1_000.0)
            ],
            interiors: [[(x: 490.0, y: -35.0), (x: 510.0, y: -35.0), (x: 510.0, y: -15.0), (x: 490.0, y: -15.0)]],
        ];
        assert!(land.is_valid());
        let (simplified, stats) =
            simplify_land_m(&MultiPolygon::new(vec![land.clone()]), 60.0, 100.0);
        assert!(simplified.is_valid(), "{simplified:?}");
        assert_eq!(stats.tolerance_reduced, 1, "{stats:?}");
        assert_eq!(simplified.0[0].interiors().len(), 1);
        assert!((simplified.unsigned_area() - land.unsigned_area()).abs() < 1e-6);
        // Without the halving the first answer would not have been valid.
        assert!(!land.simplify(60.0).is_valid() || land.simplify(60.0).interiors()[0].0.len() < 4);
    }

    #[test]
    fn slivers_and_small_holes_go() {
        let big = polygon![
            exterior: [(x: 0.0, y: 0.0), (x: 1_000.0, y: 0.0), (x: 1_000.0, y: 1_000.0), (x: 0.0, y: 1_000.0)],
            interiors: [
                [(x: 100.0, y: 100.0), (x: 105.0, y: 100.0), (x: 105.0, y: 105.0), (x: 100.0, y: 105.0)],
                [(x: 500.0, y: 500.0), (x: 700.0, y: 500.0), (x: 700.0, y: 700.0), (x: 500.0, y: 700.0)],
            ],
        ];
        let sliver = polygon![(x: 2_000.0, y: 0.0), (x: 2_100.0, y: 0.0), (x: 2_100.0, y: 0.5)];
        let (land, stats) = simplify_land_m(&MultiPolygon::new(vec![big, sliver]), 10.0, 100.0);
        assert_eq!(land.0.len(), 1);
        assert_eq!(land.0[0].interiors().len(), 1);
        assert_eq!((stats.slivers_dropped, stats.holes_dropped), (1, 1));
    }

    #[test]
    fn overlapping_polygons_are_merged() {
        let a = polygon![(x: 0.0, y: 0.0), (x: 100.0, y: 0.0), (x: 100.0, y: 100.0), (x: 0.0, y: 100.0)];
        let b = polygon![(x: 50.0, y: 50.0), (x: 150.0, y: 50.0), (x: 150.0, y: 150.0), (x: 50.0, y: 150.0)];
        let (land, stats) = simplify_land_m(&MultiPolygon::new(vec![a, b]), 1.0, 1.0);
        assert!(stats.merged_overlaps);
        assert!(land.is_valid());
        assert_eq!(land.0.len(), 1);
        assert!((land.unsigned_area() - 17_500.0).abs() < 1e-6);
    }

    #[test]
    fn tolerance_zero_keeps_every_vertex() {
        let ring = noisy_ring(7, 100, 1_000.0, 10.0);
        let land = MultiPolygon::new(vec![Polygon::new(ring, Vec::new())]);
        let (same, _) = simplify_land_m(&land, 0.0, 0.0);
        assert_eq!(same, land);
    }
}
