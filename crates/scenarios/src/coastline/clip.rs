//! Clipping land to a bounding box.

use super::BoundingBox;
use ::geo::{BooleanOps, BoundingRect, MultiPolygon, Polygon};

/// The part of `land_lon_lat` (`(longitude, latitude)` degrees) inside
/// `bbox`: a polygon wholly inside is kept as it is, one wholly outside is
/// left out, and one across an edge is cut by a boolean intersection with
/// the box (`geo`'s `BooleanOps`, Martinez-style sweep in `i_overlay`), so
/// a concave coast cut by the box gives separate, valid pieces rather than
/// the zero-width bridges a Sutherland-Hodgman rectangle clip leaves. Rings
/// with fewer than three distinct vertices are dropped.
///
/// Edges are clipped as straight lines in longitude and latitude; the box is
/// a frame, not a chart limit, so that is enough.
#[must_use]
pub fn clip_to_bbox(land_lon_lat: &MultiPolygon<f64>, bbox: &BoundingBox) -> MultiPolygon<f64> {
    let window = bbox.to_polygon();
    let mut kept: Vec<Polygon<f64>> = Vec::new();
    for polygon in &land_lon_lat.0 {
        if polygon.exterior().0.len() < 4 {
            continue;
        }
        let Some(rect) = polygon.bounding_rect() else {
            continue;
        };
        let (low, high) = (rect.min(), rect.max());
        let disjoint = high.x < bbox.west_deg
            || low.x > bbox.east_deg
            || high.y < bbox.south_deg
            || low.y > bbox.north_deg;
        if disjoint {
            continue;
        }
        if bbox.contains_lon_lat(low) && bbox.contains_lon_lat(high) {
            kept.push(polygon.clone());
        } else {
            kept.extend(polygon.intersection(&window));
        }
    }
    MultiPolygon::new(kept)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ::geo::{Area, Validation, polygon};

    #[test]
    fn a_square_across_the_box_is_cut_to_it() {
        let square =
            polygon![(x: 0.0, y: 0.0), (x: 2.0, y: 0.0), (x: 2.0, y: 2.0), (x: 0.0, y: 2.0)];
        let bbox = BoundingBox::new(1.0, 1.0, 3.0, 3.0).unwrap();
        let clipped = clip_to_bbox(&MultiPolygon::new(vec![square]), &bbox);
        let [piece] = clipped.0.as_slice() else {
            panic!("{clipped:?}")
        };
        assert!((piece.unsigned_area() - 1.0).abs() < 1e-12);
        assert!(piece.is_valid());
        assert!(piece.exterior().0.iter().all(|&c| bbox.contains_lon_lat(c)));
    }

    #[test]
    fn inside_is_kept_and_outside_dropped() {
        let inside = polygon![(x: 1.5, y: 1.5), (x: 2.0, y: 1.5), (x: 2.0, y: 2.0)];
        let outside = polygon![(x: 5.0, y: 5.0), (x: 6.0, y: 5.0), (x: 6.0, y: 6.0)];
        let bbox = BoundingBox::new(1.0, 1.0, 3.0, 3.0).unwrap();
        let clipped = clip_to_bbox(&MultiPolygon::new(vec![inside.clone(), outside]), &bbox);
        assert_eq!(clipped.0, vec![inside]);
    }

    #[test]
    fn a_concave_coast_cut_by_the_box_falls_into_valid_pieces() {
        // A U open to the north whose arms cross the box's southern edge:
        // inside the box two separate arms remain.
        let u = polygon![
            (x: 0.0, y: 0.0), (x: 3.0, y: 0.0), (x: 3.0, y: 3.0), (x: 2.0, y: 3.0),
            (x: 2.0, y: 1.0), (x: 1.0, y: 1.0), (x: 1.0, y: 3.0), (x: 0.0, y: 3.0)
        ];
        let bbox = BoundingBox::new(-1.0, 2.0, 4.0, 4.0).unwrap();
        let clipped = clip_to_bbox(&MultiPolygon::new(vec![u]), &bbox);
        assert_eq!(clipped.0.len(), 2, "{clipped:?}");
        assert!(clipped.is_valid());
        assert!((clipped.unsigned_area() - 2.0).abs() < 1e-12);
    }
}
