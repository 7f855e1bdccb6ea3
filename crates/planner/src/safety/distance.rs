//! The clearance of a move: the smallest distance to a target's predicted
//! track over an interval ([`min_distance_over`]), and the range test that
//! shows it wide without working it out ([`beyond_reach`]).

use glam::DVec2;
use vorrt_geometry::cpa::cpa_clamped;
use vorrt_jfs::LinearTrack;

/// The smallest distance between ownship, leaving `start_m` with
/// `velocity_mps`, and a target on `track`, over `duration_s` seconds starting
/// `track_elapsed_s` after the track's time zero. The target may turn onto
/// its second leg, or stop, part way: each piece of constant target velocity
/// is one closest-point-of-approach test, and distances to the second leg
/// are counted `track.then_margin_m` short (the timing of the turn is
/// uncertain).
#[must_use]
pub fn min_distance_over(
    start_m: DVec2,
    velocity_mps: DVec2,
    track: &LinearTrack,
    track_elapsed_s: f64,
    duration_s: f64,
) -> f64 {
    // Seconds into the interval at which the target stops.
    let stops_s = (track.moving_for_s - track_elapsed_s).clamp(0.0, duration_s);
    if track.turns_at_s >= track.moving_for_s {
        // One leg (every target but one expected to return to its route):
        // moving, then at rest. The general pieces below give the same
        // values, but written once for both cases they made `plan/tss` a
        // fifth and `plan/tss_instant` a quarter slower (criterion), so the
        // common case keeps its own two tests.
        let target_start = track.position_at(track_elapsed_s);
        let mut best = f64::INFINITY;
        if stops_s > 0.0 {
            best = cpa_clamped(
                start_m - target_start,
                velocity_mps - track.velocity_mps,
                stops_s,
            )
            .distance_m;
        }
        if stops_s < duration_s {
            let own_then = start_m + velocity_mps * stops_s;
            let target_then = track.position_at(track_elapsed_s + stops_s);
            let cpa = cpa_clamped(own_then - target_then, velocity_mps, duration_s - stops_s);
            best = best.min(cpa.distance_m);
        }
        return best;
    }
    // Seconds into the interval at which the target turns.
    let turns_s = (track.turns_at_s - track_elapsed_s).clamp(0.0, duration_s);
    let piece = |from_s: f64, to_s: f64, target_velocity_mps: DVec2| {
        if to_s > from_s {
            let own_then = start_m + velocity_mps * from_s;
            let target_then = track.position_at(track_elapsed_s + from_s);
            cpa_clamped(
                own_then - target_then,
                velocity_mps - target_velocity_mps,
                to_s - from_s,
            )
            .distance_m
        } else {
            f64::INFINITY
        }
    };
    let mut best = piece(0.0, turns_s, track.velocity_mps);
    // Where it turns is known only so well: its second leg is kept
    // `then_margin_m` farther off.
    best = best.min(piece(turns_s, stops_s, track.then_velocity_mps) - track.then_margin_m);
    // The target is at rest for the rest of the interval.
    best = best.min(piece(stops_s, duration_s, DVec2::ZERO));
    best
}

/// Metres spared for rounding by [`beyond_reach`]: the rounding of
/// [`min_distance_over`] at ranges of tens of kilometres is under a
/// micrometre.
const REACH_ROUNDING_M: f64 = 1.0;

/// Whether the target on `track`, `range_m` from ownship at the start of an
/// interval of `duration_s` seconds, stays at least `clearance_m` away over
/// it whatever either does: ownship sails at most `own_speed_mps` times the
/// duration, the target at most its highest speed on its track times the
/// duration, and its second leg is counted `then_margin_m` nearer
/// (`min_distance_over`). Where this holds, [`min_distance_over`] over the
/// interval is at least `clearance_m` (with [`REACH_ROUNDING_M`] to spare),
/// so the check it would make passes: it need not be worked out, and no
/// verdict changes.
#[must_use]
pub(crate) fn beyond_reach(
    range_m: f64,
    own_speed_mps: f64,
    track: &LinearTrack,
    duration_s: f64,
    clearance_m: f64,
) -> bool {
    let target_speed_mps = track
        .velocity_mps
        .length()
        .max(track.then_velocity_mps.length());
    let reach_m = (own_speed_mps + target_speed_mps) * duration_s
        + track.then_margin_m.max(0.0)
        + REACH_ROUNDING_M;
    // A NaN anywhere keeps the full test.
    range_m - reach_m >= clearance_m
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use vorrt_colregs::VesselState;
    use vorrt_jfs::TargetState;

    #[test]
    fn stopping_target_is_split_into_two_pieces() {
        // Target moves east from x = 0 to x = 100 at 10 m/s, then waits there.
        let track = TargetState::toward_goal(
            VesselState::new(DVec2::ZERO, 0.0, 10.0, 10.0),
            DVec2::new(100.0, 0.0),
        )
        .track();
        // Ownship passes over x = 150 going south, from y = 100, at 10 m/s: it is
        // nearest the stopped target at t = 10 s, 50 m away.
        let distance = min_distance_over(
            DVec2::new(100.0, 100.0),
            DVec2::new(0.0, -10.0),
            &track,
            0.0,
            20.0,
        );
        assert!((distance - 0.0).abs() < 1e-9, "{distance}");
        let distance = min_distance_over(
            DVec2::new(150.0, 100.0),
            DVec2::new(0.0, -10.0),
            &track,
            0.0,
            20.0,
        );
        assert!((distance - 50.0).abs() < 1e-9, "{distance}");
    }

    #[test]
    fn a_turning_target_is_checked_on_both_legs() {
        // East from the origin at 10 m/s for 10 s, then north for (100, 1000).
        let track = TargetState::holding_course_then_toward_goal(
            VesselState::new(DVec2::ZERO, std::f64::consts::FRAC_PI_2, 10.0, 10.0),
            DVec2::new(100.0, 1000.0),
            10.0,
        )
        .track();
        // Ownship lies still at (100, 300): the target's second leg runs over it
        // at t = 40 s (counted 100 m short: its turn's timing is uncertain by
        // 10 s at 10 m/s), while its first leg alone passes 300 m off.
        assert!((track.then_margin_m - 100.0).abs() < 1e-9);
        let distance = min_distance_over(DVec2::new(100.0, 300.0), DVec2::ZERO, &track, 0.0, 60.0);
        assert!((distance + 100.0).abs() < 1e-9, "{distance}");
        let first_leg_only =
            min_distance_over(DVec2::new(100.0, 300.0), DVec2::ZERO, &track, 0.0, 10.0);
        assert!((first_leg_only - 300.0).abs() < 1e-9, "{first_leg_only}");
        // From 20 s into the track: the second leg only.
        let later = min_distance_over(DVec2::new(100.0, 300.0), DVec2::ZERO, &track, 20.0, 30.0);
        assert!((later + 100.0).abs() < 1e-9, "{later}");
    }

    proptest! {
        /// Where [`beyond_reach`] holds, the distance it stands for is at
        /// least the clearance: on targets that hold a course, turn for a
        /// goal part way (their second leg counted nearer) or stop at it.
        #[test]
        fn beyond_reach_never_hides_a_near_pass(
            (x_m, y_m) in (-6_000.0..6_000.0f64, -6_000.0..6_000.0f64),
            course_rad in 0.0..std::f64::consts::TAU,
            speed_mps in 0.0..12.0f64,
            (goal_x_m, goal_y_m) in (-6_000.0..6_000.0f64, -6_000.0..6_000.0f64),
            hold_s in 0.0..200.0f64,
            own_course_rad in 0.0..std::f64::consts::TAU,
            own_speed_mps in 0.0..12.0f64,
            elapsed_s in 0.0..400.0f64,
            duration_s in 0.0..300.0f64,
            clearance_m in 0.0..2_000.0f64,
        ) {
            let target = VesselState::new(DVec2::new(x_m, y_m), course_rad, speed_mps, 100.0);
            let track = TargetState::holding_course_then_toward_goal(
                target,
                DVec2::new(goal_x_m, goal_y_m),
                hold_s,
            )
            .track();
            let own_velocity_mps = vorrt_geometry::angle::velocity(own_course_rad, own_speed_mps);
            let range_m = track.position_at(elapsed_s).length();
            if beyond_reach(range_m, own_speed_mps, &track, duration_s, clearance_m) {
                let distance_m =
                    min_distance_over(DVec2::ZERO, own_velocity_mps, &track, elapsed_s, duration_s);
                prop_assert!(distance_m >= clearance_m, "{distance_m} < {clearance_m}");
            }
        }
    }

    /// The second leg's margin is counted: a target 1 000 m off, still,
    /// whose second leg is counted 100 m nearer, is not beyond reach of a
    /// 950 m clearance, though its range less its motion would be.
    #[test]
    fn beyond_reach_counts_the_second_legs_margin() {
        let track = TargetState::holding_course_then_toward_goal(
            VesselState::new(DVec2::new(0.0, 1_000.0), 0.0, 10.0, 10.0),
            DVec2::new(0.0, 1_000.0 + 50.0),
            1.0,
        )
        .track();
        assert!(track.then_margin_m > 50.0);
        // Ownship lies still; the target sails 10 m/s for at most 1 s.
        assert!(!beyond_reach(1_000.0, 0.0, &track, 1.0, 950.0));
        assert!(beyond_reach(1_000.0, 0.0, &track, 1.0, 800.0));
    }
}
