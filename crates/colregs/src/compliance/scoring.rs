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
        }
    }
}

/// Constants of compliance scoring (Woerner 2019 / Minne 2017 style).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ScoringParameters {
    /// Clearance d_th (r_min): a minimum range at or above this is fully
    /// safe; under it is a [`ClearanceViolated`](super::ComplianceViolation::ClearanceViolated).
    /// Default 200 m (the paper's open-sea d_th; use 100 m in a TSS).
    pub clearance_m: f64,
    /// Near-miss range r_nm, where the safety score is `near_miss_safety`.
    /// Default 100 m.
    pub near_miss_m: f64,
    /// Zero-safety range r_col: the bottom of the safety scale, at or under
    /// which the safety score is 0. Default 25 m. Not a collision test: a
    /// [`Collision`](super::ComplianceViolation::Collision) is hull contact
    /// from the two lengths ([`in_contact`](crate::rules::in_contact)), and a
    /// collision scores safety 0 whatever this range.
    pub collision_m: f64,
    /// Safety score at the near-miss range, in `[0, 1]`. Default 0.5.
    pub near_miss_safety: f64,
    /// An action begun with the range already under this is late (rule 16:
    /// "early"). Default 1 nm (1852 m).
    pub late_action_range_m: f64,
    /// An action begun within this long after the latch is never late: the
    /// risk arose too close to have been met earlier. Default 60 s.
    pub reaction_time_s: f64,
    /// A speed reduction of at least this fraction of the reference speed is
    /// readily apparent on its own (notes: "a speed reduction of half").
    /// Default 0.5.
    pub apparent_speed_reduction_fraction: f64,
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
            late_action_range_m: 1852.0,
            reaction_time_s: 60.0,
            apparent_speed_reduction_fraction: 0.5,
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
        ];
        for (field, value) in non_negative {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(field, value, "a finite number of at least 0");
            }
        }
        let fraction = self.apparent_speed_reduction_fraction;
        if !(fraction > 0.0 && fraction <= 1.0) {
            return invalid(
                "apparent_speed_reduction_fraction",
                fraction,
                "a number in (0, 1]",
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
