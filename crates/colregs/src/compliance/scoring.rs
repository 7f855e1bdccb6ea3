//! The constants of compliance scoring and the safety score they define.

use crate::error::ColregsError;
use serde::{Deserialize, Serialize};

/// Penalty weights subtracted from a rule score (each in `[0, 1]`).
///
/// A rule score is `1 - Σ penalties`, clamped to `[0, 1]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PenaltyWeights {
    /// Rule 16: a give-way vessel that did not act when action was needed.
    /// Default 1 (the rule-16 score is 0).
    pub no_action: f64,
    /// Rule 16: late action, scaled by `1 - action_range / late_action_range_m`
    /// (0 for an action just inside the late range, the full weight for one
    /// begun at zero range). Default 0.5.
    pub late_action: f64,
    /// Rules 8(b), 16: action not readily apparent, scaled by the shortfall
    /// `1 - max(|course change| / apparent_turn, speed reduction / apparent
    /// reduction)`. Default 0.5.
    pub not_apparent: f64,
    /// Rules 14(a), 15: a turn to port by a give-way vessel. Default 0.5.
    pub port_turn: f64,
    /// Rule 14(a): passing starboard to starboard in head-on. Default 0.5.
    pub starboard_to_starboard: f64,
    /// Rules 15 and 13: crossing ahead of the stand-on or overtaken vessel.
    /// Default 0.5.
    pub crossed_ahead: f64,
    /// Rule 17(a)(i): a stand-on vessel that changed course too early.
    /// Default 0.5.
    pub stand_on_course_change: f64,
    /// Rule 17(a)(i): a stand-on vessel that changed speed too early.
    /// Default 0.5.
    pub stand_on_speed_change: f64,
    /// Rule 17(c): a stand-on vessel that turned to port for a vessel on its
    /// own port side. Default 0.5.
    pub stand_on_port_turn: f64,
    /// Rule 8(b): a succession of small alterations. Default 0.5.
    pub small_alterations: f64,
    /// Rules 8(d), 16: a give-way alteration eased back before the closest
    /// approach. Default 0.5.
    pub not_held: f64,
}

impl Default for PenaltyWeights {
    fn default() -> Self {
        Self {
            no_action: 1.0,
            late_action: 0.5,
            not_apparent: 0.5,
            port_turn: 0.5,
            starboard_to_starboard: 0.5,
            crossed_ahead: 0.5,
            stand_on_course_change: 0.5,
            stand_on_speed_change: 0.5,
            stand_on_port_turn: 0.5,
            small_alterations: 0.5,
            not_held: 0.5,
        }
    }
}

/// Constants of compliance scoring (Woerner 2019 / Minne 2017 style).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ScoringParameters {
    /// Clearance `d_th` (`r_min`): a minimum range at or above this is fully
    /// safe; under it is a [`ClearanceViolated`](super::ComplianceViolation::ClearanceViolated).
    /// Default 200 m (the paper's open-sea `d_th`; use 100 m in a TSS).
    pub clearance_m: f64,
    /// Near-miss range `r_nm`, where the safety score is `near_miss_safety`.
    /// Default 100 m.
    pub near_miss_m: f64,
    /// Zero-safety range `r_col`: the bottom of the safety scale, at or under
    /// which the safety score is 0. Default 25 m. Not a collision test: a
    /// [`Collision`](super::ComplianceViolation::Collision) is hull contact
    /// from the two lengths ([`in_contact`](crate::rules::in_contact)), and a
    /// collision scores safety 0 whatever this range.
    pub collision_m: f64,
    /// Safety score at the near-miss range, in `[0, 1]`. Default 0.5.
    pub near_miss_safety: f64,
    /// Early-action range (rules 8(a), 16: "early"): where risk of collision
    /// arose at or beyond this range, an action begun with the range already
    /// under it is late. Default 2 nm (3704 m), after Woerner et al. (2019),
    /// whose evaluator asks for the give-way manoeuvre at 2 nm or more.
    pub late_action_range_m: f64,
    /// Grace time: where risk arose nearer than `late_action_range_m`, an
    /// action begun within this long after the latch is early enough (the
    /// risk could not have been met earlier); one begun later is late.
    /// Default 60 s (one observation window; `CommonOcean`'s rule monitor,
    /// Krasowski and Althoff, allows about 2 minutes).
    pub reaction_time_s: f64,
    /// A course over ground that differs from the reference course by at
    /// least this much means the give-way action has begun, radians. Default
    /// 5°: above the 2° smallest detectable change (Woerner 2019), so that
    /// course noise does not start an action, below the 10° "starboard
    /// manoeuvre" of the NTNU evaluator (Hagen et al., Ocean Engineering 2023).
    pub action_detection_rad: f64,
    /// A speed over ground reduced by at least this fraction of the reference
    /// speed means the give-way action has begun. Default 0.2 (20 %).
    pub action_speed_drop_fraction: f64,
    /// A speed reduction of at least this fraction of the reference speed is
    /// readily apparent on its own (notes: "a speed reduction of half").
    /// Default 0.5.
    pub apparent_speed_reduction_fraction: f64,
    /// Rule 15 ("avoid crossing ahead"): ownship crossing the other vessel's
    /// heading line farther ahead of her bow than this is not crossing ahead
    /// so as to involve risk of collision, metres. Default 1 nm (1852 m),
    /// the predicted miss under which a pass is a risk of collision
    /// ([`risk_cpa_m`](crate::RuleParameters::risk_cpa_m)): a crossing
    /// farther ahead would be an already-clear pass (issue 23, where one was
    /// found at 5 079 m; decision 42).
    pub crossed_ahead_range_m: f64,
    /// Weights of the rule penalties.
    pub penalties: PenaltyWeights,
}

impl Default for ScoringParameters {
    fn default() -> Self {
        Self {
            clearance_m: 200.0,
            near_miss_m: 100.0,
            collision_m: 25.0,
            near_miss_safety: 0.5,
            late_action_range_m: 2.0 * 1852.0,
            reaction_time_s: 60.0,
            action_detection_rad: 5f64.to_radians(),
            action_speed_drop_fraction: 0.2,
            apparent_speed_reduction_fraction: crate::rules::APPARENT_SPEED_REDUCTION_FRACTION,
            crossed_ahead_range_m: 1852.0,
            penalties: PenaltyWeights::default(),
        }
    }
}

impl ScoringParameters {
    /// Checks every field: `0 <= collision_m < near_miss_m < clearance_m`,
    /// all finite; fractions and weights in `[0, 1]` (the speed fraction in
    /// `(0, 1]`); ranges and times finite and not negative.
    ///
    /// # Errors
    /// [`ColregsError::InvalidParameter`] naming the first field that is wrong.
    pub fn validate(&self) -> Result<(), ColregsError> {
        let invalid = |field, value, expected| {
            Err(ColregsError::InvalidParameter {
                field,
                value,
                expected,
            })
        };
        if !(self.collision_m.is_finite() && self.collision_m >= 0.0) {
            return invalid(
                "collision_m",
                self.collision_m,
                "a finite number of at least 0",
            );
        }
        if !(self.near_miss_m.is_finite() && self.near_miss_m > self.collision_m) {
            return invalid(
                "near_miss_m",
                self.near_miss_m,
                "a finite number greater than collision_m",
            );
        }
        if !(self.clearance_m.is_finite() && self.clearance_m > self.near_miss_m) {
            return invalid(
                "clearance_m",
                self.clearance_m,
                "a finite number greater than near_miss_m",
            );
        }
        let non_negative = [
            ("late_action_range_m", self.late_action_range_m),
            ("reaction_time_s", self.reaction_time_s),
            ("crossed_ahead_range_m", self.crossed_ahead_range_m),
        ];
        for (field, value) in non_negative {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(field, value, "a finite number of at least 0");
            }
        }
        let fractions = [
            (
                "apparent_speed_reduction_fraction",
                self.apparent_speed_reduction_fraction,
            ),
            (
                "action_speed_drop_fraction",
                self.action_speed_drop_fraction,
            ),
        ];
        for (field, fraction) in fractions {
            if !(fraction > 0.0 && fraction <= 1.0) {
                return invalid(field, fraction, "a number in (0, 1]");
            }
        }
        let detection = self.action_detection_rad;
        if !(detection.is_finite() && detection > 0.0 && detection <= std::f64::consts::PI) {
            return invalid(
                "action_detection_rad",
                detection,
                "an angle in (0, π] radians",
            );
        }
        let p = &self.penalties;
        let unit = [
            ("near_miss_safety", self.near_miss_safety),
            ("penalties.no_action", p.no_action),
            ("penalties.late_action", p.late_action),
            ("penalties.not_apparent", p.not_apparent),
            ("penalties.port_turn", p.port_turn),
            ("penalties.starboard_to_starboard", p.starboard_to_starboard),
            ("penalties.crossed_ahead", p.crossed_ahead),
            ("penalties.stand_on_course_change", p.stand_on_course_change),
            ("penalties.stand_on_speed_change", p.stand_on_speed_change),
            ("penalties.stand_on_port_turn", p.stand_on_port_turn),
            ("penalties.small_alterations", p.small_alterations),
            ("penalties.not_held", p.not_held),
        ];
        for (field, value) in unit {
            if !(0.0..=1.0).contains(&value) {
                return invalid(field, value, "a number in [0, 1]");
            }
        }
        Ok(())
    }
}

/// The safety score of a minimum range: 1 at or above `clearance_m`, linear
/// to `near_miss_safety` at `near_miss_m`, linear to 0 at `collision_m`, 0 at
/// or below it (and for NaN). Non-decreasing in the range.
///
/// ```
/// use vorrt_colregs::compliance::{safety_score, ScoringParameters};
/// let scoring = ScoringParameters::default();
/// assert_eq!(safety_score(500.0, &scoring), 1.0);
/// assert_eq!(safety_score(scoring.near_miss_m, &scoring), scoring.near_miss_safety);
/// assert_eq!(safety_score(0.0, &scoring), 0.0);
/// ```
#[must_use]
pub fn safety_score(min_distance_m: f64, scoring: &ScoringParameters) -> f64 {
    let d = min_distance_m;
    let score = if d.is_nan() || d <= scoring.collision_m {
        0.0
    } else if d >= scoring.clearance_m {
        1.0
    } else if d >= scoring.near_miss_m {
        let fraction = (d - scoring.near_miss_m) / (scoring.clearance_m - scoring.near_miss_m);
        scoring.near_miss_safety + (1.0 - scoring.near_miss_safety) * fraction
    } else {
        let fraction = (d - scoring.collision_m) / (scoring.near_miss_m - scoring.collision_m);
        scoring.near_miss_safety * fraction
    };
    score.clamp(0.0, 1.0)
}
