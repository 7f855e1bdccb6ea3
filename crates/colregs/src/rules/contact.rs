//! Hull contact and the clearance between hulls (decision 16): the
//! judgements of a collision and of `d_th` kept, written once.

/// The range under which two vessels of lengths `length_a_m` and `length_b_m`
/// are in hull contact: `(length_a + length_b) / 2`, the sum of the radii of
/// the discs whose diameters are the lengths (see the [module
/// documentation](super)).
///
/// ```
/// use vorrt_colregs::rules::contact_range_m;
/// assert_eq!(contact_range_m(150.0, 150.0), 150.0);
/// assert_eq!(contact_range_m(50.0, 100.0), 75.0);
/// ```
#[inline]
#[must_use]
#[expect(clippy::similar_names, reason = "a and b name the two vessels")]
pub fn contact_range_m(length_a_m: f64, length_b_m: f64) -> f64 {
    0.5 * (length_a_m + length_b_m)
}

/// Whether two vessels of lengths `length_a_m` and `length_b_m`, their
/// reference positions `distance_m` apart, are in hull contact: a collision,
/// `distance_m < contact_range_m(length_a_m, length_b_m)`.
///
/// ```
/// use vorrt_colregs::rules::in_contact;
/// // Two 150 m ships passing 60 m apart collide.
/// assert!(in_contact(60.0, 150.0, 150.0));
/// assert!(!in_contact(150.0, 150.0, 150.0));
/// ```
#[inline]
#[must_use]
#[expect(clippy::similar_names, reason = "a and b name the two vessels")]
pub fn in_contact(distance_m: f64, length_a_m: f64, length_b_m: f64) -> bool {
    distance_m < contact_range_m(length_a_m, length_b_m)
}

/// Whether two vessels of lengths `length_a_m` and `length_b_m`, their
/// reference positions `distance_m` apart, keep the clearance `clearance_m`
/// (`d_th`) between their hulls: `distance_m - contact_range_m(..) >= clearance_m`.
/// The planner keeps its reference points that far apart, so "`d_th` kept" is
/// never hull contact (`docs/decisions/0016-clearance-between-hulls.md`).
///
/// ```
/// use vorrt_colregs::rules::keeps_clearance;
/// // Two 150 m ships 300 m apart: 150 m between the hulls, under 200 m.
/// assert!(!keeps_clearance(300.0, 150.0, 150.0, 200.0));
/// assert!(keeps_clearance(350.0, 150.0, 150.0, 200.0));
/// ```
#[must_use]
#[expect(clippy::similar_names, reason = "a and b name the two vessels")]
pub fn keeps_clearance(
    distance_m: f64,
    length_a_m: f64,
    length_b_m: f64,
    clearance_m: f64,
) -> bool {
    distance_m - contact_range_m(length_a_m, length_b_m) >= clearance_m
}
