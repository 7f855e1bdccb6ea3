//! The constants of the COLREGs geometry, as one documented parameter set.
//!
//! Defaults follow the values used in the field (`docs/decisions/README.md`); each can be changed, and [`RuleParameters::validate`] says which
//! value is out of range.

use crate::error::ColregsError;
use crate::risk_distance::RiskDistanceRule;
use serde::{Deserialize, Serialize};

/// Thresholds used to detect risk, classify encounters and judge manoeuvres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RuleParameters {
    /// Minimum threshold distance (MTD, notes erratum 8): a target farther than
    /// this is not yet an encounter. Default 5 nm (9260 m).
    pub mtd_m: f64,
    /// A CPA distance under this, with the target inside MTD and the CPA ahead
    /// in time, is a risk of collision, for vessels up to 289 m in open sea.
    /// Default 1 nm (1852 m). The distance the rule book judges with is
    /// [`risk_distance_m`](Self::risk_distance_m), which scales it with the
    /// vessels' length and the sea room ([`risk_distance`](Self::risk_distance)).
    pub risk_cpa_m: f64,
    /// How the risk-of-collision distance scales with the vessels' lengths
    /// and the sea room (decision 50, [`crate::risk_distance`]).
    pub risk_distance: RiskDistanceRule,
    /// Half-width of the head-on sector around dead ahead (rule 14), radians.
    /// Default 13° (Woerner; Minne).
    pub head_on_half_width_rad: f64,
    /// Relative bearing from dead ahead at which the stern sector starts
    /// (rule 13: 22.5° abaft the beam), radians. Default 112.5°.
    pub abaft_beam_rad: f64,
    /// A latched encounter is over when the range opens and the velocities
    /// point more than this far from the line of sight, radians. Default 112.5°.
    pub passed_angle_rad: f64,
    /// Course change under this is not a turn (port turns smaller than this are
    /// tolerated), radians. Default 2° (not detectable, notes rule 16).
    pub turn_tolerance_rad: f64,
    /// Course change from the course held when the encounter began that a
    /// stand-on vessel may drift before it no longer "keeps her course"
    /// (rule 17(a)(i)), radians. Default 15°.
    pub stand_on_course_tolerance_rad: f64,
    /// Speed change a stand-on vessel may drift, m/s. Default 1 m/s.
    pub stand_on_speed_tolerance_mps: f64,
    /// Range under which a stand-on vessel may act on its own because the
    /// give-way vessel has not (rule 17(a)(ii), 17(b)). Default 2 nm (3704 m).
    pub stand_on_action_range_m: f64,
    /// Course change that counts as "readily apparent" (rules 8(b), 16): the
    /// smallest give-way alteration [`check_alteration`](crate::check_alteration)
    /// allows, and the one compliance scoring asks for. Default 30°.
    pub apparent_turn_rad: f64,
    /// Range by which a give-way vessel has begun its readily apparent
    /// action (rules 8(a), 16: early and substantial): holding course at
    /// risk of collision nearer than this is late action. Default 2.5 nm
    /// (4630 m): evaluators ask for action begun at 2 nm or more where risk
    /// arose beyond it (Woerner 2019), and a turn at a bounded rate of turn
    /// shows over ground a little after it begins.
    pub give_way_action_range_m: f64,
    /// Range out to which a judge of a recorded track counts a turn as
    /// action taken for a vessel beyond MTD that ownship would give way
    /// to on the course it held before the turn
    /// ([`update_latch_judged`](crate::update_latch_judged), decision 73).
    /// Default 10 nm (18 520 m): long-range scanning (rule 7(b)) on the
    /// 12 nm radar range, and about 30 minutes before the closest approach
    /// at a closing speed of 20 kn, where an independent evaluator
    /// classifies a situation from its start (DNV trafficgen situations
    /// begin 7-9 nm off).
    pub early_action_range_m: f64,
}

impl Default for RuleParameters {
    fn default() -> Self {
        Self {
            mtd_m: 5.0 * 1852.0,
            risk_cpa_m: 1852.0,
            risk_distance: RiskDistanceRule::default(),
            head_on_half_width_rad: 13f64.to_radians(),
            abaft_beam_rad: 112.5f64.to_radians(),
            passed_angle_rad: 112.5f64.to_radians(),
            turn_tolerance_rad: 2f64.to_radians(),
            stand_on_course_tolerance_rad: 15f64.to_radians(),
            stand_on_speed_tolerance_mps: 1.0,
            stand_on_action_range_m: 2.0 * 1852.0,
            apparent_turn_rad: 30f64.to_radians(),
            give_way_action_range_m: 2.5 * 1852.0,
            early_action_range_m: 10.0 * 1852.0,
        }
    }
}

impl RuleParameters {
    /// The risk-of-collision distance (rule 7, decision 50) for ownship of
    /// `own_length_m` and a target of `target_length_m`: a predicted miss
    /// under it is a risk. [`risk_cpa_m`](Self::risk_cpa_m) in open sea for
    /// vessels up to 289 m, more for larger ones, less where the sea room is
    /// known to be confined, never under `d_th` between the hulls
    /// ([`crate::risk_distance`]).
    ///
    /// ```
    /// use vorrt_colregs::RuleParameters;
    /// let mut rules = RuleParameters::default();
    /// assert_eq!(rules.risk_distance_m(100.0, 200.0), 1852.0);
    /// rules.risk_distance.sea_room_m = Some(1200.0);
    /// assert_eq!(rules.risk_distance_m(20.0, 20.0), 300.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn risk_distance_m(&self, own_length_m: f64, target_length_m: f64) -> f64 {
        self.risk_distance
            .distance_m(self.risk_cpa_m, own_length_m, target_length_m)
    }

    /// Checks every field: distances positive and finite, angles in range.
    ///
    /// # Errors
    /// [`ColregsError::InvalidParameter`] naming the first field that is wrong.
    pub fn validate(&self) -> Result<(), ColregsError> {
        use std::f64::consts::PI;
        let positive = [
            ("mtd_m", self.mtd_m),
            ("risk_cpa_m", self.risk_cpa_m),
            ("stand_on_action_range_m", self.stand_on_action_range_m),
            ("give_way_action_range_m", self.give_way_action_range_m),
            ("early_action_range_m", self.early_action_range_m),
        ];
        for (field, value) in positive {
            if !(value.is_finite() && value > 0.0) {
                return Err(ColregsError::InvalidParameter {
                    field,
                    value,
                    expected: "a finite number greater than 0",
                });
            }
        }
        let non_negative = [
            ("turn_tolerance_rad", self.turn_tolerance_rad),
            (
                "stand_on_speed_tolerance_mps",
                self.stand_on_speed_tolerance_mps,
            ),
        ];
        for (field, value) in non_negative {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ColregsError::InvalidParameter {
                    field,
                    value,
                    expected: "a finite number of at least 0",
                });
            }
        }
        let angles = [
            (
                "head_on_half_width_rad",
                self.head_on_half_width_rad,
                0.0,
                PI / 2.0,
            ),
            ("abaft_beam_rad", self.abaft_beam_rad, PI / 2.0, PI),
            ("passed_angle_rad", self.passed_angle_rad, 0.0, PI),
            (
                "stand_on_course_tolerance_rad",
                self.stand_on_course_tolerance_rad,
                0.0,
                PI,
            ),
            ("apparent_turn_rad", self.apparent_turn_rad, 0.0, PI),
        ];
        for (field, value, low, high) in angles {
            if !(value.is_finite() && value >= low && value <= high) {
                return Err(ColregsError::InvalidParameter {
                    field,
                    value,
                    expected: "an angle in its documented range (see RuleParameters)",
                });
            }
        }
        if let Err((field, value, expected)) = self.risk_distance.check() {
            return Err(ColregsError::InvalidParameter {
                field,
                value,
                expected,
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid() {
        RuleParameters::default().validate().expect("defaults");
    }

    #[test]
    fn nan_mtd_is_named() {
        let params = RuleParameters {
            mtd_m: f64::NAN,
            ..RuleParameters::default()
        };
        let message = params.validate().expect_err("nan").to_string();
        assert!(message.contains("mtd_m"), "{message}");
    }
}
