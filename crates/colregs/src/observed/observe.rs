//! Course and speed over ground as another vessel observes them: the
//! displacement over a sliding window (see the [module
//! documentation](super), "Observed course and speed").

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

/// Course and speed over ground at one sample, as observed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct OverGround {
    /// Course over ground (COG), radians clockwise from north in `[0, 2π)`.
    pub course_rad: f64,
    /// Speed over ground (SOG), metres per second.
    pub speed_mps: f64,
}

/// Displacements shorter than this are no movement: the course is carried
/// over from the sample before, metres.
const STILL_M: f64 = 1e-9;

/// The observed course and speed over ground at every sample of a track:
/// COG is the direction of `p(t) - p(t - window)`, SOG its length over the
/// window. `p(t - window)` is interpolated linearly between samples; near the
/// start, where `t - window` precedes the first sample, the window is
/// shortened to what is available, and at the first sample itself the first
/// step is used (`p(t₁) - p(t₀)`). A vessel that has not moved over its
/// window keeps the course observed before (north at the start) with speed 0.
///
/// `times_s` must be increasing and as long as `positions_m` (the
/// [`Recording`](super::Recording) checks this); extra entries of either are
/// ignored. [`over_ground_from`] takes the velocity held before the first
/// sample, where it is known, instead of shortening the window.
///
/// ```
/// use vorrt_colregs::observed::over_ground;
/// use glam::DVec2;
/// let times: Vec<f64> = (0..10).map(|i| f64::from(i) * 10.0).collect();
/// // East at 5 m/s.
/// let positions: Vec<DVec2> = times.iter().map(|t| DVec2::new(5.0 * t, 0.0)).collect();
/// let observed = over_ground(&times, &positions, 60.0);
/// assert!((observed[7].course_rad.to_degrees() - 90.0).abs() < 1e-9);
/// assert!((observed[7].speed_mps - 5.0).abs() < 1e-9);
/// ```
#[must_use]
pub fn over_ground(times_s: &[f64], positions_m: &[DVec2], window_s: f64) -> Vec<OverGround> {
    over_ground_from(times_s, positions_m, window_s, None)
}

/// As [`over_ground`], for a vessel known to have held `before_start_mps`
/// (a velocity over ground, m/s) before the first sample: a recorded run
/// starts with every vessel in steady motion on its first course, so the
/// window reaches back before the start along that velocity instead of
/// shrinking (with `None`, as [`over_ground`]).
///
/// ```
/// use vorrt_colregs::observed::over_ground_from;
/// use glam::DVec2;
/// // North at 5 m/s before the start, then turned east at once.
/// let times = [0.0, 10.0, 20.0];
/// let positions = [DVec2::ZERO, DVec2::new(50.0, 0.0), DVec2::new(100.0, 0.0)];
/// let observed = over_ground_from(&times, &positions, 20.0, Some(DVec2::new(0.0, 5.0)));
/// assert!(observed[0].course_rad.abs() < 1e-12);
/// assert!((observed[1].course_rad.to_degrees() - 45.0).abs() < 1e-9);
/// assert!((observed[2].course_rad.to_degrees() - 90.0).abs() < 1e-9);
/// ```
#[must_use]
pub fn over_ground_from(
    times_s: &[f64],
    positions_m: &[DVec2],
    window_s: f64,
    before_start_mps: Option<DVec2>,
) -> Vec<OverGround> {
    let mut observed = Vec::with_capacity(times_s.len().min(positions_m.len()));
    let mut last_course = 0.0;
    for_each_window(
        times_s,
        positions_m,
        (window_s, before_start_mps),
        |displacement, elapsed_s| {
            let (course_rad, speed_mps) = match speed_if_moved_mps(displacement, elapsed_s) {
                Some(speed_mps) => (angle::unit_to_course(displacement), speed_mps),
                None => (last_course, 0.0),
            };
            last_course = course_rad;
            observed.push(OverGround {
                course_rad,
                speed_mps,
            });
        },
    );
    observed
}

/// The speeds over ground of [`over_ground_from`] alone, m/s (the same
/// values, without working out the courses).
pub(super) fn speeds_over_ground_from(
    times_s: &[f64],
    positions_m: &[DVec2],
    window_s: f64,
    before_start_mps: Option<DVec2>,
) -> Vec<f64> {
    let mut speeds = Vec::with_capacity(times_s.len().min(positions_m.len()));
    for_each_window(
        times_s,
        positions_m,
        (window_s, before_start_mps),
        |displacement, elapsed_s| {
            speeds.push(speed_if_moved_mps(displacement, elapsed_s).unwrap_or(0.0));
        },
    );
    speeds
}

/// The speed over a window of `elapsed_s` in which the vessel moved by
/// `displacement`, m/s; `None` where it did not move ([`STILL_M`]) or the
/// window is empty.
fn speed_if_moved_mps(displacement: DVec2, elapsed_s: f64) -> Option<f64> {
    let moved_m = displacement.length();
    // The test is for standing still, as it was: a NaN is not still.
    if moved_m <= STILL_M || elapsed_s <= 0.0 {
        None
    } else {
        Some(moved_m / elapsed_s)
    }
}

/// Calls `observe` with the displacement over the window ending at each
/// sample and the window's length, seconds ([`over_ground_from`]).
fn for_each_window(
    times_s: &[f64],
    positions_m: &[DVec2],
    (window_s, before_start_mps): (f64, Option<DVec2>),
    mut observe: impl FnMut(DVec2, f64),
) {
    let count = times_s.len().min(positions_m.len());
    let (times_s, positions_m) = (&times_s[..count], &positions_m[..count]);
    // The windows' starts move forward with the samples: each is found
    // from where the last one was.
    let mut cursor = 0;
    for index in 0..count {
        let (displacement, elapsed_s) = if let Some(velocity) = before_start_mps {
            let from_s = times_s[index] - window_s;
            let from_m = if from_s < times_s[0] {
                positions_m[0] + velocity * (from_s - times_s[0])
            } else {
                position_at(times_s, positions_m, from_s, (index, &mut cursor))
            };
            (positions_m[index] - from_m, window_s)
        } else if index == 0 {
            match (times_s.get(1), positions_m.get(1)) {
                (Some(next_s), Some(next_m)) => (*next_m - positions_m[0], next_s - times_s[0]),
                _ => (DVec2::ZERO, 0.0),
            }
        } else {
            let from_s = (times_s[index] - window_s).max(times_s[0]);
            let from_m = position_at(times_s, positions_m, from_s, (index, &mut cursor));
            (positions_m[index] - from_m, times_s[index] - from_s)
        };
        observe(displacement, elapsed_s);
    }
}

/// The position at `at_s`, interpolated between the samples at or before
/// `upto` (the sample whose window this is). `cursor` is the first sample
/// after the last time asked: searched on from there while the times asked
/// do not go back, else from the start.
fn position_at(
    times_s: &[f64],
    positions_m: &[DVec2],
    at_s: f64,
    (upto, cursor): (usize, &mut usize),
) -> DVec2 {
    // The first sample after `at_s` (the last at or before it is the one
    // before), as `partition_point` finds it in increasing times.
    let mut after = (*cursor).min(upto + 1);
    if after > 0
        && matches!(
            times_s[after - 1].partial_cmp(&at_s),
            Some(std::cmp::Ordering::Greater) | None
        )
    {
        after = times_s[..=upto].partition_point(|t| *t <= at_s);
    }
    while after <= upto && times_s[after] <= at_s {
        after += 1;
    }
    *cursor = after;
    interpolated(times_s, positions_m, at_s, (after, upto))
}

/// The position at `at_s` between the sample before `after` and `after`
/// (the first sample after `at_s`); at the first sample, or at `upto`'s
/// when no sample up to it is after `at_s`.
fn interpolated(
    times_s: &[f64],
    positions_m: &[DVec2],
    at_s: f64,
    (after, upto): (usize, usize),
) -> DVec2 {
    let before = after.saturating_sub(1);
    if after > upto || after == 0 {
        return positions_m[before];
    }
    let (t0, t1) = (times_s[before], times_s[after]);
    let fraction = if t1 > t0 {
        ((at_s - t0) / (t1 - t0)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    positions_m[before].lerp(positions_m[after], fraction)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `position_at` as it was before the cursor: a binary search of every
    /// sample up to `upto`.
    fn position_at_searched(
        times_s: &[f64],
        positions_m: &[DVec2],
        at_s: f64,
        upto: usize,
    ) -> DVec2 {
        let after = times_s[..=upto].partition_point(|t| *t <= at_s);
        interpolated(times_s, positions_m, at_s, (after, upto))
    }

    /// Increasing times at irregular steps, and positions anywhere.
    fn track() -> impl Strategy<Value = (Vec<f64>, Vec<DVec2>)> {
        prop::collection::vec((0.5f64..30.0, -500.0f64..500.0, -500.0f64..500.0), 1..60).prop_map(
            |steps| {
                let mut time_s = 0.0;
                steps
                    .into_iter()
                    .map(|(step_s, east_m, north_m)| {
                        time_s += step_s;
                        (time_s, DVec2::new(east_m, north_m))
                    })
                    .unzip()
            },
        )
    }

    proptest! {
        #[test]
        fn the_cursor_finds_what_the_search_finds(
            (times_s, positions_m) in track(),
            window_s in 1.0f64..200.0,
            going_back in 0usize..60,
        ) {
            let mut cursor = 0;
            for upto in 0..times_s.len() {
                // A time asked earlier than the last one is searched afresh.
                let back_s = if upto == going_back { 2.0 * window_s } else { 0.0 };
                let at_s = times_s[upto] - window_s - back_s;
                let found = position_at(&times_s, &positions_m, at_s, (upto, &mut cursor));
                let searched = position_at_searched(&times_s, &positions_m, at_s, upto);
                prop_assert_eq!(found, searched);
            }
        }

        #[test]
        fn speeds_alone_are_those_of_the_courses_and_speeds(
            (times_s, positions_m) in track(),
            window_s in 1.0f64..200.0,
            before in prop::option::of((-8.0f64..8.0, -8.0f64..8.0)),
        ) {
            let before_mps = before.map(|(east, north)| DVec2::new(east, north));
            let observed = over_ground_from(&times_s, &positions_m, window_s, before_mps);
            let speeds = speeds_over_ground_from(&times_s, &positions_m, window_s, before_mps);
            let expected: Vec<f64> = observed.iter().map(|over| over.speed_mps).collect();
            prop_assert_eq!(speeds, expected);
        }
    }
}
