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
    let range_m = own.range_to(target);
    let cpa = closest_point_of_approach(
        own.position_m,
        own.velocity_mps(),
        target.position_m,
        target.velocity_mps(),
    );
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

    #[test]
    fn opening_target_is_not_a_risk() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let behind = VesselState::new(DVec2::new(0.0, -500.0), std::f64::consts::PI, 6.0, 50.0);
        assert!(!assess_risk(&own, &behind, &RuleParameters::default()).at_risk);
    }
}
