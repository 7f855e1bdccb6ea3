//! A cheap, exact gate before the settled-turn predicate
//! ([`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel)):
//! the vessels its bearing tests certainly refuse, found by dot products
//! (decision 46).

use glam::DVec2;
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

    #[test]
    fn the_gate_refuses_vessels_astern_and_to_starboard() {
        let gate = PortTurnGate::new(0.0, 330f64.to_radians());
        assert!(!gate.may_turn_toward(DVec2::new(0.0, -1000.0)));
        assert!(!gate.may_turn_toward(DVec2::new(1000.0, 200.0)));
        assert!(gate.may_turn_toward(DVec2::new(-1000.0, 1000.0)));
    }
}
