//! A leg's poses asked many times: what [`Leg::pose_at`] works out afresh
//! at every call (the turn's centre, where it ends, the velocity on the
//! settled course) worked out once, and every pose the same bit for bit.
//!
//! A closed loop's observer of course over ground samples a leg every few
//! seconds over a window and a turn search (`vorrt_planner`'s observed
//! turn, decision 57), and each [`Leg::pose_at`] on the straight run costs
//! three sines and cosines that do not depend on the time asked.

use super::{Leg, Pose};
use glam::DVec2;
use vorrt_geometry::angle;

/// [`Leg::pose_at`] for one leg asked at many times, with the same result
/// bit for bit.
///
/// ```
/// use vorrt_jfs::motion::{Leg, LegPoses, Pose};
/// use glam::DVec2;
/// let from = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
/// let leg = Leg::turning_onto(from, 1.0, 400.0, 6.0, 2000.0);
/// let poses = LegPoses::new(&leg);
/// for elapsed_s in [0.0, 30.0, 120.0, 400.0] {
///     assert_eq!(poses.pose_at(elapsed_s), leg.pose_at(elapsed_s));
/// }
/// ```
#[derive(Debug, Clone, Copy)]
pub struct LegPoses<'a> {
    leg: &'a Leg,
    /// The turn's centre (`Leg::arc_centre_m`).
    centre_m: DVec2,
    /// Where the turn ends.
    turn_end_m: DVec2,
    /// The unit vector of the settled course.
    unit: DVec2,
}

impl<'a> LegPoses<'a> {
    /// The poses of `leg`.
    #[must_use]
    pub fn new(leg: &'a Leg) -> Self {
        let centre_m = leg.arc_centre_m();
        Self {
            leg,
            centre_m,
            turn_end_m: leg.on_arc_about(centre_m, leg.turn_rad.abs()),
            unit: angle::course_to_unit(leg.course_rad),
        }
    }

    /// The leg these are the poses of.
    ///
    /// ```
    /// use vorrt_jfs::motion::{Leg, LegPoses};
    /// use glam::DVec2;
    /// let leg = Leg::straight(DVec2::ZERO, 0.0, 100.0, 5.0);
    /// assert_eq!(LegPoses::new(&leg).leg(), &leg);
    /// ```
    #[must_use]
    pub fn leg(&self) -> &'a Leg {
        self.leg
    }

    /// [`Leg::pose_at`]`(elapsed_s)`, bit for bit.
    #[must_use]
    pub fn pose_at(&self, elapsed_s: f64) -> Pose {
        self.leg.pose_at_from(
            elapsed_s,
            || self.centre_m,
            || self.turn_end_m,
            || self.unit,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::SpeedChange;
    use proptest::prelude::*;

    proptest! {
        /// Every pose, and every course alone, is the leg's own, bit for bit.
        #[test]
        fn the_poses_are_the_legs_bit_for_bit(
            course_deg in 0.0f64..360.0,
            turn_deg in -180.0f64..180.0,
            radius_m in prop_oneof![Just(0.0), 50.0f64..2000.0],
            straight_m in prop_oneof![Just(0.0), 1.0f64..20_000.0],
            speed_mps in 0.5f64..12.0,
            change in prop_oneof![Just(None), (0.0f64..12.0, 0.001f64..0.2).prop_map(Some)],
            times in proptest::collection::vec(-50.0f64..6000.0, 1..20),
        ) {
            let from = Pose { position_m: DVec2::new(120.0, -340.0), course_rad: course_deg.to_radians() };
            let course_rad = angle::normalize_2pi((course_deg + turn_deg).to_radians());
            let mut leg = Leg::turning_onto(from, course_rad, radius_m, speed_mps, straight_m);
            leg.speed_change = change.map(|(start_speed_mps, rate_mps2)| SpeedChange { start_speed_mps, rate_mps2 });
            let poses = LegPoses::new(&leg);
            for elapsed_s in times.into_iter().chain([0.0, leg.turn_duration_s(), leg.duration_s()]) {
                let expected = leg.pose_at(elapsed_s);
                let got = poses.pose_at(elapsed_s);
                prop_assert_eq!(got.position_m.x.to_bits(), expected.position_m.x.to_bits());
                prop_assert_eq!(got.position_m.y.to_bits(), expected.position_m.y.to_bits());
                prop_assert_eq!(got.course_rad.to_bits(), expected.course_rad.to_bits());
                prop_assert_eq!(leg.course_at(elapsed_s).to_bits(), expected.course_rad.to_bits());
            }
        }
    }
}
