//! Risk of collision (paper §III-A; rule 7).
//!
//! A target is a risk when it is inside the minimum threshold distance (MTD),
//! the distance at CPA is under the pair's risk-of-collision distance
//! ([`RuleParameters::risk_distance_m`]: 1 nm in open sea for vessels up to
//! 289 m, scaled with their lengths and the sea room, decision 50) and the
//! CPA lies ahead in time (`t_cpa > 0`: the vessels are still closing).

use crate::parameters::RuleParameters;
use crate::rules::{is_close_approach, within_mtd};
use crate::vessel::VesselState;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::{Cpa, closest_point_of_approach};

/// The measurements behind a risk judgement.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RiskAssessment {
    /// Present distance between the vessels, metres.
    pub range_m: f64,
    /// Closest point of approach over the unbounded future at present velocities.
    pub cpa: Cpa,
    /// Whether the three conditions of a risk of collision all hold.
    pub at_risk: bool,
}

/// Assesses the risk of collision between `own` and `target`.
///
/// ```
/// use vorrt_colregs::{assess_risk, RuleParameters, VesselState};
/// use glam::DVec2;
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let head_on = VesselState::new(DVec2::new(0.0, 5000.0), std::f64::consts::PI, 6.0, 50.0);
/// assert!(assess_risk(&own, &head_on, &RuleParameters::default()).at_risk);
/// ```
#[must_use]
pub fn assess_risk(
    own: &VesselState,
    target: &VesselState,
    parameters: &RuleParameters,
) -> RiskAssessment {
    assess_risk_moving(
        own,
        own.velocity_mps(),
        target,
        target.velocity_mps(),
        parameters,
    )
}

/// As [`assess_risk`], with the two velocities already worked out (`own_mps`,
/// `target_mps`: `own`'s and `target`'s [`VesselState::velocity_mps`]): a
/// caller judging many targets against one state of ownship works ownship's
/// out once. The same assessment as [`assess_risk`].
#[inline]
#[must_use]
pub fn assess_risk_moving(
    own: &VesselState,
    own_mps: DVec2,
    target: &VesselState,
    target_mps: DVec2,
    parameters: &RuleParameters,
) -> RiskAssessment {
    let range_m = own.range_to(target);
    let cpa = closest_point_of_approach(own.position_m, own_mps, target.position_m, target_mps);
    let risk_distance_m = parameters.risk_distance_m(own.length_m, target.length_m);
    let at_risk = within_mtd(range_m, parameters)
        && is_close_approach(&cpa, risk_distance_m)
        && cpa.time_s > 0.0;
    RiskAssessment {
        range_m,
        cpa,
        at_risk,
    }
}

/// How far past its closest approach, or how far outside its risk
/// distance ([`RuleParameters::risk_distance_m`]), a pair must be for
/// [`no_risk_while_steady`] to hold, metres: far above the rounding of the
/// positions and velocities it is judged from (under a micrometre at ranges
/// of hundreds of kilometres).
pub const STEADY_ROUNDING_M: f64 = 1e-3;

/// Whether no risk of collision can arise between two vessels at
/// `own_m` and `target_m` while each keeps its velocity (`own_mps`,
/// `target_mps`, the velocities [`assess_risk`] would judge them by): the
/// range is opening, so the closest approach is past and stays past; or the
/// closest approach of the line they sail relative to each other is at
/// least `risk_distance_m` off (the pair's
/// [`RuleParameters::risk_distance_m`], decision 50), and it is the same
/// at every point of that line. Either way [`assess_risk`] finds no risk at
/// any later point of the same relative line (rule 7; decision 54), with
/// [`STEADY_ROUNDING_M`] to spare. Range does not enter: beyond MTD there is
/// no risk either.
///
/// ```
/// use vorrt_colregs::{risk::no_risk_while_steady, RuleParameters};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// // A vessel 3 km ahead on a parallel course 2.5 km to starboard.
/// let (own, target) = (DVec2::ZERO, DVec2::new(2500.0, 3000.0));
/// let (north, south) = (DVec2::new(0.0, 6.0), DVec2::new(0.0, -6.0));
/// assert!(no_risk_while_steady(own, north, target, south, params.risk_cpa_m));
/// // 1 km to starboard it passes within 1 nm: risk may arise.
/// assert!(!no_risk_while_steady(own, north, DVec2::new(1000.0, 3000.0), south, params.risk_cpa_m));
/// ```
#[must_use]
pub fn no_risk_while_steady(
    own_m: DVec2,
    own_mps: DVec2,
    target_m: DVec2,
    target_mps: DVec2,
    risk_distance_m: f64,
) -> bool {
    let relative_m = own_m - target_m;
    let relative_mps = own_mps - target_mps;
    // Opening by more than the rounding: past the CPA (t_cpa <= 0), and the
    // range keeps opening along the same line.
    let along_m = relative_m.dot(relative_mps);
    if along_m >= STEADY_ROUNDING_M * relative_mps.length() {
        return true;
    }
    // Closing: the CPA of the line, the same from every point of it.
    let cpa = closest_point_of_approach(own_m, own_mps, target_m, target_mps);
    cpa.distance_m >= risk_distance_m + STEADY_ROUNDING_M
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn far_target_is_not_a_risk() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let far = VesselState::new(DVec2::new(0.0, 50_000.0), std::f64::consts::PI, 6.0, 50.0);
        let risk = assess_risk(&own, &far, &RuleParameters::default());
        assert!(!risk.at_risk);
        assert!(risk.cpa.distance_m < 1e-6);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(512))]

        /// Where [`no_risk_while_steady`] holds, [`assess_risk`] finds no
        /// risk anywhere later on the same two straight courses (decision
        /// 54); where it does not, the closest approach is within
        /// the pair's risk distance (and the rounding spared).
        #[test]
        fn no_risk_while_steady_holds_along_the_courses(
            x_m in -12_000.0f64..12_000.0,
            y_m in -12_000.0f64..12_000.0,
            own_course in 0.0f64..6.3,
            own_speed in 0.0f64..12.0,
            target_course in 0.0f64..6.3,
            target_speed in 0.0f64..15.0,
            later_s in proptest::collection::vec(0.0f64..7_200.0, 1..16),
        ) {
            let params = RuleParameters::default();
            let own = VesselState::new(DVec2::new(300.0, -200.0), own_course, own_speed, 50.0);
            let target = VesselState::new(DVec2::new(x_m, y_m), target_course, target_speed, 80.0);
            let (own_mps, target_mps) = (own.velocity_mps(), target.velocity_mps());
            let steady = no_risk_while_steady(own.position_m, own_mps, target.position_m, target_mps, params.risk_distance_m(own.length_m, target.length_m));
            let risk = assess_risk(&own, &target, &params);
            if steady {
                for elapsed_s in later_s {
                    let own_then = VesselState { position_m: own.position_m + own_mps * elapsed_s, ..own };
                    let target_then = VesselState { position_m: target.position_m + target_mps * elapsed_s, ..target };
                    proptest::prop_assert!(!assess_risk(&own_then, &target_then, &params).at_risk, "{elapsed_s}");
                }
            } else {
                // Not steady only within the CPA distance (and the rounding
                // to spare): it misses no pair passing clear.
                proptest::prop_assert!(risk.cpa.distance_m < params.risk_distance_m(own.length_m, target.length_m) + STEADY_ROUNDING_M);
            }
        }
    }

    #[test]
    fn opening_target_is_not_a_risk() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let behind = VesselState::new(DVec2::new(0.0, -500.0), std::f64::consts::PI, 6.0, 50.0);
        assert!(!assess_risk(&own, &behind, &RuleParameters::default()).at_risk);
    }
}
