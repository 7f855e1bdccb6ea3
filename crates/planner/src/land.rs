//! Land and no-go areas as a [`Constraint`]: polygons with holes that
//! ownship keeps a clearance from (decision 29).
//!
//! The polygons' edges go into an R-tree (`rstar`), so a query costs about
//! log(edges) whatever the length of the coast: a segment is refused when an
//! edge lies within `clearance + margin` of it (an envelope query, then the
//! exact segment-to-segment distance), or when it lies wholly inside a
//! polygon (a crossing count along a ray, on the edges the ray meets). The
//! same distances judge a sailed track (`vorrt_scenarios::Chart`), so the
//! planner and the evaluation cannot measure land differently.
//!
//! ```
//! use vorrt_planner::land::LandConstraint;
//! use vorrt_planner::constraint::{Constraint, ConstraintViolation, Segment};
//! use vorrt_planner::DVec2;
//! use geo::{polygon, Polygon};
//!
//! // A 1 km square island north of the start, kept 200 m off.
//! let island: Polygon<f64> = polygon![
//!     (x: -500.0, y: 3000.0), (x: 500.0, y: 3000.0), (x: 500.0, y: 4000.0), (x: -500.0, y: 4000.0),
//! ];
//! let land = LandConstraint::new(&[island], 200.0).unwrap();
//! assert!(land.contains(DVec2::new(0.0, 3500.0)));
//! assert_eq!(land.distance_m(DVec2::new(0.0, 2000.0)), 1000.0);
//! let north = Segment {
//!     start_m: DVec2::ZERO, end_m: DVec2::new(0.0, 6000.0), margin_m: 0.0,
//!     start_elapsed_s: 0.0, duration_s: 1000.0, course_rad: 0.0, course_spread_rad: 0.0,
//! };
//! assert_eq!(land.check_segment(&north), Err(ConstraintViolation::Land));
//! assert!(!land.admits_point(DVec2::new(0.0, 2900.0)));
//! assert!(land.admits_point(DVec2::new(0.0, 2700.0)));
//! ```

use crate::constraint::{Constraint, ConstraintViolation, Segment};
use geo::{CoordsIter, Polygon};
use glam::DVec2;
use rstar::{AABB, PointDistance, RTree, RTreeObject};
use thiserror::Error;

/// Why polygons cannot make a [`LandConstraint`].
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum LandError {
    /// A vertex is not a finite number.
    #[error("polygon {polygon}, ring {ring}: vertex {vertex} is not finite")]
    NonFinite {
        /// The polygon's index in the list given.
        polygon: usize,
        /// The ring: 0 the outer ring, 1.. the holes.
        ring: usize,
        /// The vertex's index in the ring.
        vertex: usize,
    },
    /// A ring has fewer than three distinct points.
    #[error("polygon {polygon}, ring {ring}: fewer than 3 points")]
    TooFewPoints {
        /// The polygon's index in the list given.
        polygon: usize,
        /// The ring: 0 the outer ring, 1.. the holes.
        ring: usize,
    },
    /// The clearance is negative or not finite.
    #[error("clearance {clearance_m} m is not a finite distance >= 0")]
    Clearance {
        /// The clearance given, metres.
        clearance_m: f64,
    },
}

/// One edge of a polygon's ring, in the R-tree.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Edge {
    start_m: DVec2,
    end_m: DVec2,
    /// Which polygon the edge bounds (its outer ring or a hole).
    polygon: usize,
}

impl RTreeObject for Edge {
    type Envelope = AABB<[f64; 2]>;

    fn envelope(&self) -> Self::Envelope {
        AABB::from_corners(self.start_m.to_array(), self.end_m.to_array())
    }
}

impl PointDistance for Edge {
    fn distance_2(&self, point: &[f64; 2]) -> f64 {
        point_segment_distance_m(DVec2::from_array(*point), self.start_m, self.end_m).powi(2)
    }
}

/// The distance from `point_m` to the segment `start_m`-`end_m`, metres.
fn point_segment_distance_m(point_m: DVec2, start_m: DVec2, end_m: DVec2) -> f64 {
    let along = end_m - start_m;
    let length_sq = along.length_squared();
    let fraction = if length_sq > 0.0 {
        ((point_m - start_m).dot(along) / length_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    point_m.distance(start_m + along * fraction)
}

/// The least distance between two segments, metres: 0 where they cross,
/// else the least of the four endpoint-to-segment distances.
fn segment_segment_distance_m(a: (DVec2, DVec2), b: (DVec2, DVec2)) -> f64 {
    let side = |from: DVec2, to: DVec2, point: DVec2| (to - from).perp_dot(point - from);
    let (a_first, a_second) = (side(a.0, a.1, b.0), side(a.0, a.1, b.1));
    let (b_first, b_second) = (side(b.0, b.1, a.0), side(b.0, b.1, a.1));
    if a_first * a_second < 0.0 && b_first * b_second < 0.0 {
        return 0.0;
    }
    point_segment_distance_m(a.0, b.0, b.1)
        .min(point_segment_distance_m(a.1, b.0, b.1))
        .min(point_segment_distance_m(b.0, a.0, a.1))
        .min(point_segment_distance_m(b.1, a.0, a.1))
}

/// Polygons (with holes, local metres) that ownship keeps `clearance_m`
/// from: land (refused as [`ConstraintViolation::Land`]) or no-go areas
/// ([`ConstraintViolation::NoGoArea`]). Overlapping polygons are allowed: a
/// point is inside when it is inside any of them.
#[derive(Debug, Clone)]
pub struct LandConstraint {
    edges: RTree<Edge>,
    polygon_count: usize,
    clearance_m: f64,
    violation: ConstraintViolation,
}

impl LandConstraint {
    /// Land: `polygons` (x east, y north, metres) kept `clearance_m` off.
    ///
    /// # Errors
    /// [`LandError`] for a non-finite vertex, a ring of fewer than three
    /// points, or a negative or non-finite clearance.
    pub fn new(polygons: &[Polygon<f64>], clearance_m: f64) -> Result<Self, LandError> {
        Self::with_violation(polygons, clearance_m, ConstraintViolation::Land)
    }

    /// No-go areas: as [`new`](Self::new), refused as
    /// [`ConstraintViolation::NoGoArea`].
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn no_go(polygons: &[Polygon<f64>], clearance_m: f64) -> Result<Self, LandError> {
        Self::with_violation(polygons, clearance_m, ConstraintViolation::NoGoArea)
    }

    /// As [`new`](Self::new), refusing with `violation`.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn with_violation(
        polygons: &[Polygon<f64>],
        clearance_m: f64,
        violation: ConstraintViolation,
    ) -> Result<Self, LandError> {
        if !clearance_m.is_finite() || clearance_m < 0.0 {
            return Err(LandError::Clearance { clearance_m });
        }
        let mut edges = Vec::new();
        for (polygon, shape) in polygons.iter().enumerate() {
            let rings = std::iter::once(shape.exterior()).chain(shape.interiors());
            for (ring, line_string) in rings.enumerate() {
                let mut points: Vec<DVec2> = Vec::with_capacity(line_string.coords_count());
                for (vertex, coord) in line_string.coords().enumerate() {
                    if !coord.x.is_finite() || !coord.y.is_finite() {
                        return Err(LandError::NonFinite {
                            polygon,
                            ring,
                            vertex,
                        });
                    }
                    let point = DVec2::new(coord.x, coord.y);
                    if points.last() != Some(&point) {
                        points.push(point);
                    }
                }
                // geo closes rings: the last point repeats the first.
                if points.len() > 1 && points.first() == points.last() {
                    points.pop();
                }
                if points.len() < 3 {
                    return Err(LandError::TooFewPoints { polygon, ring });
                }
                for (index, &start_m) in points.iter().enumerate() {
                    edges.push(Edge {
                        start_m,
                        end_m: points[(index + 1) % points.len()],
                        polygon,
                    });
                }
            }
        }
        Ok(Self {
            edges: RTree::bulk_load(edges),
            polygon_count: polygons.len(),
            clearance_m,
            violation,
        })
    }

    /// The distance kept from the polygons, metres.
    #[must_use]
    pub fn clearance_m(&self) -> f64 {
        self.clearance_m
    }

    /// What a refusal says: land or a no-go area.
    #[must_use]
    pub fn violation(&self) -> ConstraintViolation {
        self.violation
    }

    /// Whether there are no polygons (then nothing is refused).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.polygon_count == 0
    }

    /// How many edges the polygons have, holes included.
    #[must_use]
    pub fn edge_count(&self) -> usize {
        self.edges.size()
    }

    /// Whether `point_m` lies inside a polygon (not in one of its holes);
    /// a point on an edge may count either way.
    #[must_use]
    pub fn contains(&self, point_m: DVec2) -> bool {
        if self.is_empty() {
            return false;
        }
        let upper = self.edges.root().envelope().upper();
        if point_m.x > upper[0] {
            return false;
        }
        // Crossings of the ray east from the point, counted per polygon
        // (even-odd over its outer ring and holes): polygons may overlap.
        let ray = AABB::from_corners(point_m.to_array(), [upper[0], point_m.y]);
        let mut odd: Vec<usize> = Vec::new();
        for edge in self.edges.locate_in_envelope_intersecting(&ray) {
            let (a, b) = (edge.start_m, edge.end_m);
            if (a.y > point_m.y) != (b.y > point_m.y)
                && point_m.x < a.x + (point_m.y - a.y) * (b.x - a.x) / (b.y - a.y)
            {
                match odd.iter().position(|&polygon| polygon == edge.polygon) {
                    Some(index) => {
                        odd.swap_remove(index);
                    }
                    None => odd.push(edge.polygon),
                }
            }
        }
        !odd.is_empty()
    }

    /// The distance from `point_m` to the polygons, metres: 0 inside one,
    /// infinite when there are none.
    #[must_use]
    pub fn distance_m(&self, point_m: DVec2) -> f64 {
        if self.contains(point_m) {
            return 0.0;
        }
        self.edges
            .nearest_neighbor(&point_m.to_array())
            .map_or(f64::INFINITY, |edge| {
                point_segment_distance_m(point_m, edge.start_m, edge.end_m)
            })
    }

    /// The least distance from the segment `start_m`-`end_m` to the
    /// polygons, metres: 0 when it crosses an edge or lies inside,
    /// infinite when there are none.
    #[must_use]
    pub fn segment_distance_m(&self, start_m: DVec2, end_m: DVec2) -> f64 {
        if self.is_empty() {
            return f64::INFINITY;
        }
        if self.contains(start_m) {
            return 0.0;
        }
        // Edges in order of distance from the midpoint: the segment is no
        // nearer an edge than that distance less half its length, so the
        // search stops once that bound passes the best found.
        let middle_m = (start_m + end_m) / 2.0;
        let half_length_m = start_m.distance(end_m) / 2.0;
        let mut best_m = f64::INFINITY;
        for (edge, distance_2) in self
            .edges
            .nearest_neighbor_iter_with_distance_2(&middle_m.to_array())
        {
            if distance_2.sqrt() - half_length_m >= best_m {
                break;
            }
            best_m = best_m.min(segment_segment_distance_m(
                (start_m, end_m),
                (edge.start_m, edge.end_m),
            ));
            if best_m == 0.0 {
                break;
            }
        }
        best_m
    }

    /// Whether the segment `start_m`-`end_m` comes nearer the polygons than
    /// `distance_m` (or lies inside one): an envelope query, then exact
    /// distances; cheaper than [`segment_distance_m`](Self::segment_distance_m).
    #[must_use]
    pub fn segment_within(&self, start_m: DVec2, end_m: DVec2, distance_m: f64) -> bool {
        if self.is_empty() {
            return false;
        }
        let lower = start_m.min(end_m) - DVec2::splat(distance_m);
        let upper = start_m.max(end_m) + DVec2::splat(distance_m);
        let envelope = AABB::from_corners(lower.to_array(), upper.to_array());
        let near = self
            .edges
            .locate_in_envelope_intersecting(&envelope)
            .any(|edge| {
                segment_segment_distance_m((start_m, end_m), (edge.start_m, edge.end_m))
                    < distance_m
            });
        // No edge near: the segment is wholly inside or wholly outside.
        near || self.contains(start_m)
    }
}

impl Constraint for LandConstraint {
    fn check_segment(&self, segment: &Segment) -> Result<(), ConstraintViolation> {
        if self.segment_within(
            segment.start_m,
            segment.end_m,
            self.clearance_m + segment.margin_m,
        ) {
            Err(self.violation)
        } else {
            Ok(())
        }
    }

    fn admits_point(&self, point_m: DVec2) -> bool {
        !self.segment_within(point_m, point_m, self.clearance_m)
    }
}

#[cfg(test)]
mod tests;
