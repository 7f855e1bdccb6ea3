//! A cheap, exact gate before the settled-turn predicate
//! ([`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel)):
//! the vessels its bearing tests certainly refuse, found by dot products
//! (decision 46).

use crate::VesselState;
use crate::rules::is_on_port_side;
use glam::DVec2;
use std::f64::consts::PI;
use vorrt_geometry::angle;

/// The bearing tests of [`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel) for one turn, worked
/// out once for every vessel it is judged against: a vessel certainly abaft
/// the beam on the present course, or certainly on the starboard side of the
/// course held before, is never one turned toward, and [`Self::may_turn_toward`]
/// says so from a dot product, without the predicate's angles. A vessel
/// within a hair (1e-9 of its range) of either line is left to the predicate,
/// whose verdict it then gives; so the gate changes no verdict, only the
/// work: among 100 vessels near, the predicate's bearings were 40 % of a run's
/// instructions (issue 24, decision 46).
///
/// ```
/// use vorrt_colregs::{rules::{is_port_turn_toward_vessel, PortTurnGate}, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 357f64.to_radians(), 6.0, 100.0);
/// let gate = PortTurnGate::new(35f64.to_radians(), own.course_rad);
/// let crossing = VesselState::new(DVec2::new(-4000.0, 3300.0), 90f64.to_radians(), 6.0, 100.0);
/// assert!(gate.may_turn_toward(crossing.position_m - own.position_m));
/// assert!(is_port_turn_toward_vessel(35f64.to_radians(), &own, &crossing, &params));
/// // A vessel astern is never one turned toward.
/// assert!(!gate.may_turn_toward(DVec2::new(0.0, -3000.0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PortTurnGate {
    /// Unit vector of the present course (forward of the beam: positive).
    ahead: DVec2,
    /// Unit vector to starboard of the course held before the turn (the
    /// port side: negative).
    starboard_before: DVec2,
}

impl PortTurnGate {
    /// The gate for a turn from `course_before_rad` to `course_rad`.
    #[must_use]
    pub fn new(course_before_rad: f64, course_rad: f64) -> Self {
        let before = angle::course_to_unit(course_before_rad);
        Self {
            ahead: angle::course_to_unit(course_rad),
            // Course plus 90°: (sin(c + 90°), cos(c + 90°)) = (cos c, -sin c).
            starboard_before: DVec2::new(before.y, -before.x),
        }
    }

    /// `false` only where [`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel) is certainly
    /// `false` for a vessel `offset_m` from ownship (its position less
    /// ownship's): abaft the beam, or on the starboard side of the course
    /// before, by more than 1e-9 of the range (far beyond the rounding of
    /// the predicate's angles).
    #[must_use]
    pub fn may_turn_toward(&self, offset_m: DVec2) -> bool {
        let margin_m = 1e-9 * (offset_m.x.abs() + offset_m.y.abs());
        offset_m.dot(self.ahead) >= -margin_m && offset_m.dot(self.starboard_before) <= margin_m
    }
}

/// The sign of `offset_m · direction_mps` (a vessel's offset from ownship
/// against ownship's velocity on some course, `speed_mps` its length), where
/// it is certain: beyond 1e-9 of the range times the speed, far beyond the
/// rounding of a bearing worked out from angles. `Some(true)`: the vessel
/// is certainly ahead of the line square to that course; `Some(false)`:
/// certainly behind it; `None`: within a hair of it, or no speed (the caller
/// then works the bearing out). The bearings of the settled-turn predicate
/// take their verdicts from this where it answers (decision 46's argument):
/// the same verdicts, without an arctangent for most vessels.
#[must_use]
pub(crate) fn certain_side(offset_m: DVec2, direction_mps: DVec2, speed_mps: f64) -> Option<bool> {
    let margin = 1e-9 * (offset_m.x.abs() + offset_m.y.abs()) * speed_mps;
    let dot = offset_m.dot(direction_mps);
    (speed_mps > 0.0 && dot.abs() > margin).then_some(dot > 0.0)
}

/// Whether a vessel at `target_m` is forward of `own`'s beam (its relative
/// bearing outside 90°-270°), `own_mps` being `own`'s velocity: from
/// [`certain_side`] where it answers, else from the bearing.
pub(crate) fn forward_of_beam_moving(own: &VesselState, own_mps: DVec2, target_m: DVec2) -> bool {
    certain_side(target_m - own.position_m, own_mps, own.speed_mps).unwrap_or_else(|| {
        let bearing = angle::relative_bearing(own.position_m, own.course_rad, target_m);
        !(0.5 * PI..=1.5 * PI).contains(&bearing)
    })
}

/// Whether a vessel at `target_m` is on the port side of `course_before_rad`
/// from `own`'s position ([`is_on_port_side`]), `before_mps` being `own`'s
/// velocity on that course: from [`certain_side`] against the starboard
/// normal where it answers, else from the bearing.
pub(crate) fn on_port_side_moving(
    own: &VesselState,
    (course_before_rad, before_mps): (f64, DVec2),
    target_m: DVec2,
) -> bool {
    let starboard_mps = DVec2::new(before_mps.y, -before_mps.x);
    certain_side(target_m - own.position_m, starboard_mps, own.speed_mps).map_or_else(
        || is_on_port_side(own.position_m, course_before_rad, target_m),
        |starboard| !starboard,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rules::is_port_turn_toward_vessel;
    use crate::{RuleParameters, VesselState};
    use proptest::prelude::*;

    proptest! {
        /// The gate refuses only vessels the predicate refuses (a gate that
        /// refused too much would fail here on the vessels it hides).
        #[test]
        fn the_gate_hides_no_vessel_turned_toward(
            before_deg in 0.0f64..360.0,
            turn_deg in -120.0f64..-2.0,
            east_m in -8000.0f64..8000.0,
            north_m in -8000.0f64..8000.0,
            target_deg in 0.0f64..360.0,
            speed_mps in 0.5f64..10.0,
        ) {
            let params = RuleParameters::default();
            let course_rad = (before_deg + turn_deg).rem_euclid(360.0).to_radians();
            let own = VesselState::new(DVec2::ZERO, course_rad, 6.0, 100.0);
            let target = VesselState::new(
                DVec2::new(east_m, north_m),
                target_deg.to_radians(),
                speed_mps,
                100.0,
            );
            let before_rad = before_deg.to_radians();
            let gate = PortTurnGate::new(before_rad, course_rad);
            if is_port_turn_toward_vessel(before_rad, &own, &target, &params) {
                prop_assert!(gate.may_turn_toward(target.position_m));
            }
        }
    }

    proptest! {
        /// Where `certain_side` answers, it gives the relative bearing's
        /// verdicts: forward of the beam on the course, and on the port side
        /// of it (the starboard normal's side), as the predicate's angles do.
        #[test]
        fn a_certain_side_is_the_bearings_verdict(
            course_deg in 0.0f64..360.0,
            speed_mps in 0.0f64..12.0,
            bearing_deg in prop_oneof![0.0f64..360.0, Just(90.0), Just(270.0), Just(180.0), Just(0.0)],
            range_m in 1.0f64..20_000.0,
        ) {
            let course_rad = course_deg.to_radians();
            let to = course_rad + bearing_deg.to_radians();
            let offset_m = DVec2::new(to.sin(), to.cos()) * range_m;
            let own_mps = angle::velocity(course_rad, speed_mps);
            let bearing = angle::relative_bearing(DVec2::ZERO, course_rad, offset_m);
            if let Some(ahead) = certain_side(offset_m, own_mps, speed_mps) {
                prop_assert_eq!(ahead, !(0.5 * std::f64::consts::PI..=1.5 * std::f64::consts::PI).contains(&bearing));
            }
            let starboard_mps = DVec2::new(own_mps.y, -own_mps.x);
            if let Some(starboard) = certain_side(offset_m, starboard_mps, speed_mps) {
                prop_assert_eq!(!starboard, bearing > std::f64::consts::PI);
            }
            if speed_mps == 0.0 {
                prop_assert!(certain_side(offset_m, own_mps, speed_mps).is_none());
            }
        }
    }

    #[test]
    fn the_gate_refuses_vessels_astern_and_to_starboard() {
        let gate = PortTurnGate::new(0.0, 330f64.to_radians());
        assert!(!gate.may_turn_toward(DVec2::new(0.0, -1000.0)));
        assert!(!gate.may_turn_toward(DVec2::new(1000.0, 200.0)));
        assert!(gate.may_turn_toward(DVec2::new(-1000.0, 1000.0)));
    }
}
