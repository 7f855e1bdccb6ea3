//! Post-hoc compliance scoring of one recorded encounter (rules 8, 13-17).
//!
//! Given the recorded tracks of ownship and one target
//! ([`EncounterSample`]s in increasing time, covering the whole run) and the
//! [`EncounterLatch`] fixed when risk of collision arose, [`assess_encounter`]
//! measures what ownship did and scores it, in the style of the evaluators of
//! Woerner et al. (Autonomous Robots, 2019) and Minne (NTNU, 2017) described in
//! `vorrt-paper-notes.md`, "Compliance scoring in the literature". The
//! definitions below are this crate's own; every constant is a field of
//! [`ScoringParameters`] or [`RuleParameters`].
//!
//! ## Measurements
//! - **Closest approach**: the minimum range over the whole run. Between two
//!   samples both vessels are taken to move in straight lines, so the minimum
//!   inside a step is found exactly (CPA of the relative motion over the step),
//!   not only at sample instants.
//! - **In force**: from the first sample at or after the latch time up to (not
//!   including) the first sample at which the vessels have passed
//!   ([`has_passed`]), or to the end of the run.
//! - **Action**: the first in-force sample at which ownship's course differs
//!   from the latch's reference course by more than
//!   [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad) or its speed
//!   from the reference speed by more than
//!   [`stand_on_speed_tolerance_mps`](RuleParameters::stand_on_speed_tolerance_mps).
//! - **Passing side**: the side of ownship (relative bearing from ownship's
//!   course in `(0, π)` = starboard) on which the target lies at the closest
//!   approach.
//! - **Crossed ahead**: while in force, ownship's track relative to the target
//!   crosses the target's heading line ahead of the target's bow.
//!
//! ## Violations, by role
//! - Always: [`ClearanceViolated`](ComplianceViolation::ClearanceViolated)
//!   when the minimum range is under `clearance_m` (d_th) and
//!   [`Collision`](ComplianceViolation::Collision) when under `collision_m`.
//!   These are safety findings, not rule violations: they do not make an
//!   assessment non-compliant.
//! - Give way (head-on, crossing give-way, overtaking; rule 16, with rule 8(b)
//!   for "readily apparent"):
//!   - [`NoAction`](ComplianceViolation::NoAction): no action while in force,
//!     **and** action was needed: the CPA predicted at the latch instant (both
//!     vessels holding their velocities) or the actual minimum range was under
//!     `clearance_m`. A risk latched at, say, 1500 m of predicted CPA with a
//!     200 m clearance needed no manoeuvre, so holding course there is not
//!     penalised (the latch's risk threshold is a planner trigger, wider than
//!     the clearance that scoring judges). The manner of passing
//!     (port turn, starboard-to-starboard, crossing ahead) is judged whether
//!     or not action was needed: rules 14(a) and 15 prescribe it.
//!   - [`LateAction`](ComplianceViolation::LateAction): the action began with
//!     the range already under `late_action_range_m`, unless it began within
//!     `reaction_time_s` of the latch (risk that arises at close range cannot
//!     be met earlier).
//!   - [`ActionNotApparent`](ComplianceViolation::ActionNotApparent): the
//!     largest course change while in force is under
//!     [`apparent_turn_rad`](RuleParameters::apparent_turn_rad) (30°) and the
//!     largest speed reduction is under `apparent_speed_reduction_fraction` of
//!     the reference speed (one half).
//!   - [`PortTurn`](ComplianceViolation::PortTurn) (head-on, rule 14(a);
//!     crossing give-way, rules 15 and 16): the first detectable course change
//!     is to port, or the largest one is.
//!   - [`StarboardToStarboard`](ComplianceViolation::StarboardToStarboard)
//!     (head-on, rule 14(a)): the target passed on ownship's starboard side.
//!   - [`CrossedAhead`](ComplianceViolation::CrossedAhead): in crossing
//!     give-way (rule 15) any crossing of the target's bow; when overtaking
//!     (rule 13) a crossing of the overtaken vessel's bow closer than
//!     `clearance_m` ahead of it (cutting in).
//! - Stand on (crossing stand-on, being overtaken; rule 17):
//!   - [`StandOnCourseChanged`](ComplianceViolation::StandOnCourseChanged) /
//!     [`StandOnSpeedChanged`](ComplianceViolation::StandOnSpeedChanged)
//!     (rule 17(a)(i)): course changed by more than
//!     [`stand_on_course_tolerance_rad`](RuleParameters::stand_on_course_tolerance_rad)
//!     or speed by more than
//!     [`stand_on_speed_tolerance_mps`](RuleParameters::stand_on_speed_tolerance_mps)
//!     while the range was still over
//!     [`stand_on_action_range_m`](RuleParameters::stand_on_action_range_m).
//!   - [`StandOnTurnedToPort`](ComplianceViolation::StandOnTurnedToPort)
//!     (rule 17(c), crossing only): at its first detectable port turn ownship
//!     had the target on its port side (relative to the reference course).
//!
//! ## Scores (each in `[0, 1]`, 1 = best)
//! - **Safety** ([`safety_score`]): 1 at or above `clearance_m`, linear down
//!   to `near_miss_safety` at `near_miss_m`, linear down to 0 at `collision_m`
//!   and 0 below it. It never increases as the minimum range shrinks.
//! - **Rule scores**: 1 minus the sum of the penalties of that rule's
//!   violations (weights in [`PenaltyWeights`]), clamped to `[0, 1]`; `None`
//!   when the rule places no obligation on ownship in this encounter:
//!   rule 13 when overtaking; rule 14 in head-on; rule 15 in crossing
//!   give-way; rule 16 whenever ownship gives way; rule 17 whenever it stands
//!   on. Late action and a not-apparent action are graded by how far they
//!   fall short; every other penalty is its full weight.
//! - **Overall**: the product of safety and every applicable rule score, so a
//!   collision or a wholly broken rule gives 0 and only a safe, fully
//!   compliant encounter gives 1.

use crate::encounter::{Encounter, Role};
use crate::error::ColregsError;
use crate::latch::{EncounterLatch, has_passed, update_latch};
use crate::parameters::RuleParameters;
use crate::passing::PassingSide;
use crate::vessel::VesselState;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use vorrt_geometry::{angle, closest_point_of_approach, cpa::cpa_clamped, cross};

/// One instant of a recorded encounter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EncounterSample {
    /// Time of the sample, seconds.
    pub time_s: f64,
    /// Ownship's state at that time.
    pub own: VesselState,
    /// The target's state at that time.
    pub target: VesselState,
}

impl EncounterSample {
    /// A sample from its parts.
    #[must_use]
    pub fn new(time_s: f64, own: VesselState, target: VesselState) -> Self {
        Self {
            time_s,
            own,
            target,
        }
    }

    /// Distance between ownship and the target, metres.
    #[must_use]
    pub fn range_m(&self) -> f64 {
        self.own.range_to(&self.target)
    }
}

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
    /// safe; under it is a [`ClearanceViolated`](ComplianceViolation::ClearanceViolated).
    /// Default 200 m (the paper's open-sea d_th; use 100 m in a TSS).
    pub clearance_m: f64,
    /// Near-miss range r_nm, where the safety score is `near_miss_safety`.
    /// Default 100 m.
    pub near_miss_m: f64,
    /// Collision range r_col: at or under it the safety score is 0 and a
    /// [`Collision`](ComplianceViolation::Collision) is reported. Default
    /// 25 m (reference points of two vessels this close are in contact for
    /// lengths of about 50 m; raise it for larger vessels).
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

/// A finding about one recorded encounter: a safety shortfall or a broken rule.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum ComplianceViolation {
    /// The minimum range was under the clearance d_th (rules 8(d), 16: "keep
    /// well clear"). A safety finding, not a rule violation.
    ClearanceViolated {
        /// The minimum range, metres.
        min_distance_m: f64,
    },
    /// The minimum range was under the collision range. A safety finding.
    Collision {
        /// The minimum range, metres.
        min_distance_m: f64,
    },
    /// A give-way vessel took no action although action was needed (rule 16).
    NoAction,
    /// A give-way vessel's action began late (rule 16: "early action").
    LateAction {
        /// The range when the action began, metres.
        range_m: f64,
    },
    /// A give-way vessel's action was not readily apparent (rules 8(b), 16:
    /// "substantial action").
    ActionNotApparent {
        /// The largest course change while in force, radians, positive to starboard.
        course_change_rad: f64,
        /// The largest speed change while in force, m/s, negative = slower.
        speed_change_mps: f64,
    },
    /// A give-way vessel turned to port (rule 14(a) in head-on; rules 15, 16
    /// in crossing).
    PortTurn {
        /// The port turn judged (first detectable, or largest), radians (negative).
        course_change_rad: f64,
    },
    /// In head-on the target passed on ownship's starboard side (rule 14(a):
    /// pass port to port).
    StarboardToStarboard,
    /// Ownship crossed ahead of the target: of the stand-on vessel in crossing
    /// (rule 15), or cutting across the overtaken vessel's bow (rule 13).
    CrossedAhead {
        /// How far ahead of the target's bow the track was crossed, metres.
        distance_ahead_m: f64,
    },
    /// A stand-on vessel changed course before it might act (rule 17(a)(i)).
    StandOnCourseChanged {
        /// The largest course change while beyond the action range, radians.
        course_change_rad: f64,
    },
    /// A stand-on vessel changed speed before it might act (rule 17(a)(i)).
    StandOnSpeedChanged {
        /// The largest speed change while beyond the action range, m/s.
        speed_change_mps: f64,
    },
    /// A stand-on vessel in a crossing turned to port for a vessel on its own
    /// port side (rule 17(c)).
    StandOnTurnedToPort {
        /// The course change at that moment, radians (negative).
        course_change_rad: f64,
    },
}

impl ComplianceViolation {
    /// The COLREGs rule the finding is judged under; `None` for the safety
    /// findings ([`ClearanceViolated`](Self::ClearanceViolated),
    /// [`Collision`](Self::Collision)), which the safety score covers.
    /// [`PortTurn`](Self::PortTurn) and [`CrossedAhead`](Self::CrossedAhead)
    /// depend on the encounter and give their usual rule (14 and 15); the
    /// assessment books them against the encounter's own rule.
    #[must_use]
    pub fn rule(&self) -> Option<u8> {
        match self {
            Self::ClearanceViolated { .. } | Self::Collision { .. } => None,
            Self::NoAction | Self::LateAction { .. } | Self::ActionNotApparent { .. } => Some(16),
            Self::PortTurn { .. } | Self::StarboardToStarboard => Some(14),
            Self::CrossedAhead { .. } => Some(15),
            Self::StandOnCourseChanged { .. }
            | Self::StandOnSpeedChanged { .. }
            | Self::StandOnTurnedToPort { .. } => Some(17),
        }
    }

    /// Whether this is a rule violation (as opposed to a safety finding).
    #[must_use]
    pub fn is_rule_violation(&self) -> bool {
        self.rule().is_some()
    }

    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::ClearanceViolated { .. } => "clearance_violated",
            Self::Collision { .. } => "collision",
            Self::NoAction => "no_action",
            Self::LateAction { .. } => "late_action",
            Self::ActionNotApparent { .. } => "action_not_apparent",
            Self::PortTurn { .. } => "port_turn",
            Self::StarboardToStarboard => "starboard_to_starboard",
            Self::CrossedAhead { .. } => "crossed_ahead",
            Self::StandOnCourseChanged { .. } => "stand_on_course_changed",
            Self::StandOnSpeedChanged { .. } => "stand_on_speed_changed",
            Self::StandOnTurnedToPort { .. } => "stand_on_turned_to_port",
        }
    }
}

impl std::fmt::Display for ComplianceViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::ClearanceViolated { min_distance_m } => write!(
                f,
                "minimum range {min_distance_m:.0} m under the clearance (rules 8(d), 16: keep well clear)"
            ),
            Self::Collision { min_distance_m } => write!(
                f,
                "collision: minimum range {min_distance_m:.0} m under the collision range"
            ),
            Self::NoAction => f.write_str("give-way vessel took no action (rule 16)"),
            Self::LateAction { range_m } => write!(
                f,
                "give-way action began late, at {range_m:.0} m (rule 16: early action)"
            ),
            Self::ActionNotApparent {
                course_change_rad,
                speed_change_mps,
            } => write!(
                f,
                "give-way action not readily apparent: course change {:.1}°, speed change {speed_change_mps:.2} m/s (rules 8(b), 16)",
                course_change_rad.to_degrees()
            ),
            Self::PortTurn { course_change_rad } => write!(
                f,
                "give-way vessel turned {:.1}° to port (rules 14(a), 15)",
                -course_change_rad.to_degrees()
            ),
            Self::StarboardToStarboard => {
                f.write_str("head-on vessels passed starboard to starboard (rule 14(a))")
            }
            Self::CrossedAhead { distance_ahead_m } => write!(
                f,
                "crossed {distance_ahead_m:.0} m ahead of the other vessel's bow (rules 15, 13)"
            ),
            Self::StandOnCourseChanged { course_change_rad } => write!(
                f,
                "stand-on vessel changed course by {:.1}° before it might act (rule 17(a)(i))",
                course_change_rad.to_degrees()
            ),
            Self::StandOnSpeedChanged { speed_change_mps } => write!(
                f,
                "stand-on vessel changed speed by {speed_change_mps:.2} m/s before it might act (rule 17(a)(i))"
            ),
            Self::StandOnTurnedToPort { course_change_rad } => write!(
                f,
                "stand-on vessel turned {:.1}° to port for a vessel on its own port side (rule 17(c))",
                -course_change_rad.to_degrees()
            ),
        }
    }
}

/// Scores of one encounter, each in `[0, 1]` (1 = best); a rule's score is
/// `None` when that rule places no obligation on ownship in this encounter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RuleScores {
    /// From the minimum range alone ([`safety_score`]).
    pub safety: f64,
    /// Rule 13 (overtaking): penalised for cutting across the overtaken bow.
    pub rule_13: Option<f64>,
    /// Rule 14 (head-on): port turn, starboard-to-starboard passing.
    pub rule_14: Option<f64>,
    /// Rule 15 (crossing, give way): crossing ahead, port turn.
    pub rule_15: Option<f64>,
    /// Rule 16 (action by give-way vessel): no, late or not apparent action.
    pub rule_16: Option<f64>,
    /// Rule 17 (action by stand-on vessel): early course or speed change,
    /// port turn for a vessel on the port side.
    pub rule_17: Option<f64>,
    /// Safety times every applicable rule score.
    pub overall: f64,
}

impl RuleScores {
    /// The applicable rule scores as `(rule number, score)`, in rule order.
    #[must_use]
    pub fn applicable(&self) -> Vec<(u8, f64)> {
        [
            (13, self.rule_13),
            (14, self.rule_14),
            (15, self.rule_15),
            (16, self.rule_16),
            (17, self.rule_17),
        ]
        .into_iter()
        .filter_map(|(rule, score)| score.map(|score| (rule, score)))
        .collect()
    }
}

/// What ownship did in one recorded encounter, and how it scores.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EncounterAssessment {
    /// The encounter type, from the latch.
    pub encounter: Encounter,
    /// Ownship's role in it.
    pub role: Role,
    /// Minimum range over the whole run, metres (`+∞` with no samples).
    pub min_distance_m: f64,
    /// When the minimum range occurred, seconds (the latch time with no samples).
    pub time_of_min_s: f64,
    /// Range at the first in-force sample, metres.
    pub latch_range_m: Option<f64>,
    /// CPA distance predicted at the first in-force sample with both vessels
    /// holding their velocities, metres: the pass ownship would have had
    /// without acting.
    pub latch_cpa_m: Option<f64>,
    /// Time of the first sample at which the vessels had passed; `None` if the
    /// run ends first.
    pub passed_at_s: Option<f64>,
    /// When ownship's action began, seconds (`None`: no action while in force).
    pub action_time_s: Option<f64>,
    /// Range when the action began, metres.
    pub action_range_m: Option<f64>,
    /// The largest course change from the reference course while in force,
    /// signed: positive to starboard. 0 with no in-force samples.
    pub max_course_change_rad: f64,
    /// The largest speed change from the reference speed while in force,
    /// signed: negative = slower. 0 with no in-force samples.
    pub max_speed_change_mps: f64,
    /// The first course change beyond the turn tolerance while in force,
    /// signed: positive to starboard.
    pub first_turn_rad: Option<f64>,
    /// Side of ownship on which the target lay at the closest approach
    /// (relative bearing from ownship's course in `(0, π)` = starboard);
    /// `None` at zero range or dead ahead / astern.
    pub passing_side: Option<PassingSide>,
    /// Whether ownship crossed the target's heading line ahead of the target
    /// while the encounter was in force.
    pub crossed_ahead: bool,
    /// The smallest distance ahead of the target's bow at which ownship crossed
    /// its heading line while in force, metres.
    pub crossed_ahead_distance_m: Option<f64>,
    /// Every finding, safety findings first.
    pub violations: Vec<ComplianceViolation>,
    /// The scores.
    pub scores: RuleScores,
    /// Whether the minimum range stayed at or above the clearance.
    pub safe: bool,
    /// Whether no rule was broken (safety findings do not count).
    pub compliant: bool,
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

/// The first encounter latched in a recording: runs [`update_latch`] over the
/// samples in order and returns the first latch it makes.
#[must_use]
pub fn first_latch(samples: &[EncounterSample], rules: &RuleParameters) -> Option<EncounterLatch> {
    samples
        .iter()
        .find_map(|sample| update_latch(None, &sample.own, &sample.target, sample.time_s, rules))
}

/// The closest approach over the run: (distance, time, index of the sample
/// that starts the step holding it).
fn closest_approach(samples: &[EncounterSample]) -> Option<(f64, f64, usize)> {
    let first = samples.first()?;
    let mut best = (first.range_m(), first.time_s, 0);
    for (index, pair) in samples.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let step_s = b.time_s - a.time_s;
        let relative_a = a.own.position_m - a.target.position_m;
        let relative_b = b.own.position_m - b.target.position_m;
        let (distance_m, time_s) = if step_s > 0.0 {
            let cpa = cpa_clamped(relative_a, (relative_b - relative_a) / step_s, step_s);
            (cpa.distance_m, a.time_s + cpa.time_s)
        } else {
            (relative_b.length(), b.time_s)
        };
        if distance_m < best.0 {
            best = (distance_m, time_s, index);
        }
    }
    Some(best)
}

/// Side of ownship on which the target lies at the closest approach.
fn side_at(samples: &[EncounterSample], index: usize, time_s: f64) -> Option<PassingSide> {
    let a = &samples[index];
    let relative = |sample: &EncounterSample| sample.target.position_m - sample.own.position_m;
    let (line_of_sight, course_rad) = match samples.get(index + 1) {
        Some(b) if b.time_s > a.time_s => {
            let fraction = ((time_s - a.time_s) / (b.time_s - a.time_s)).clamp(0.0, 1.0);
            let course = if fraction >= 1.0 {
                b.own.course_rad
            } else {
                a.own.course_rad
            };
            (relative(a).lerp(relative(b), fraction), course)
        }
        _ => (relative(a), a.own.course_rad),
    };
    if line_of_sight.length() <= 1e-9 {
        return None;
    }
    let bearing = angle::relative_bearing(DVec2::ZERO, course_rad, line_of_sight);
    if bearing > 0.0 && bearing < PI {
        Some(PassingSide::Starboard)
    } else if bearing > PI {
        Some(PassingSide::Port)
    } else {
        None
    }
}

/// The smallest distance ahead of the target's bow at which ownship's
/// relative track crosses the target's heading line, over `segments`.
fn crossing_ahead_distance(segments: &[EncounterSample]) -> Option<f64> {
    let mut nearest: Option<f64> = None;
    for pair in segments.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        let heading = a.target.velocity_mps().normalize_or_zero();
        if heading == DVec2::ZERO {
            continue;
        }
        let relative_a = a.own.position_m - a.target.position_m;
        let relative_b = b.own.position_m - b.target.position_m;
        let offset_a = cross(heading, relative_a);
        let offset_b = cross(heading, relative_b);
        let crosses = (offset_a < 0.0 && offset_b >= 0.0) || (offset_a > 0.0 && offset_b <= 0.0);
        if !crosses {
            continue;
        }
        let fraction = offset_a / (offset_a - offset_b);
        let ahead_m = heading.dot(relative_a.lerp(relative_b, fraction));
        if ahead_m > 0.0 {
            nearest = Some(nearest.map_or(ahead_m, |n: f64| n.min(ahead_m)));
        }
    }
    nearest
}

/// The signed value of largest magnitude, or 0 for none.
fn largest_signed(values: impl Iterator<Item = f64>) -> f64 {
    values.fold(0.0, |best, value| {
        if value.abs() > best.abs() {
            value
        } else {
            best
        }
    })
}

/// `1 - Σ penalties`, clamped to `[0, 1]`.
fn rule_score(penalties: &[f64]) -> f64 {
    (1.0 - penalties.iter().sum::<f64>()).clamp(0.0, 1.0)
}

/// Assesses one recorded encounter between ownship and one target.
///
/// `samples` must be in increasing time and should cover the whole run
/// (before and after the latch); `latch` gives the encounter type and the
/// reference course and speed (see [`first_latch`]). The semantics of every
/// measurement, violation and score are in the [module documentation](self).
/// With no samples nothing is measured: the minimum range is `+∞`, nothing is
/// found and every score is 1.
///
/// ```
/// use vorrt_colregs::compliance::{assess_encounter, first_latch, EncounterSample, ScoringParameters};
/// use vorrt_colregs::{Encounter, PassingSide, RuleParameters, VesselState};
/// use glam::DVec2;
///
/// // Head-on at 6 m/s each; ownship turns 35° to starboard after one minute.
/// let rules = RuleParameters::default();
/// let mut own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let mut target = VesselState::new(DVec2::new(0.0, 9000.0), std::f64::consts::PI, 6.0, 50.0);
/// let mut samples = Vec::new();
/// for step in 0..=150 {
///     let time_s = f64::from(step) * 10.0;
///     own.course_rad = if time_s >= 60.0 { 35f64.to_radians() } else { 0.0 };
///     samples.push(EncounterSample::new(time_s, own, target));
///     own = own.advanced(10.0);
///     target = target.advanced(10.0);
/// }
/// let latch = first_latch(&samples, &rules).expect("risk of collision");
/// assert_eq!(latch.encounter, Encounter::HeadOn);
/// let assessment = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
/// assert!(assessment.compliant, "{:?}", assessment.violations);
/// assert_eq!(assessment.passing_side, Some(PassingSide::Port));
/// assert_eq!(assessment.scores.overall, 1.0);
/// ```
#[must_use]
pub fn assess_encounter(
    samples: &[EncounterSample],
    latch: &EncounterLatch,
    rules: &RuleParameters,
    scoring: &ScoringParameters,
) -> EncounterAssessment {
    assess_encounter_acting(samples, latch, rules, scoring, &[])
}

/// As [`assess_encounter`], for a stand-on ownship that also had to give way
/// to other vessels: `giving_way[i]` says whether it did at `samples[i]`
/// (missing entries count as `false`). With several targets, rule 17 yields
/// to the duty to keep out of the way (the planner reads it the same way), so
/// while it gives way an early course or speed change is not held against
/// it; rule 17(c) still is.
#[must_use]
pub fn assess_encounter_acting(
    samples: &[EncounterSample],
    latch: &EncounterLatch,
    rules: &RuleParameters,
    scoring: &ScoringParameters,
    giving_way: &[bool],
) -> EncounterAssessment {
    let acting_at: std::collections::HashSet<u64> = samples
        .iter()
        .zip(giving_way)
        .filter(|(_, giving)| **giving)
        .map(|(sample, _)| sample.time_s.to_bits())
        .collect();
    let may_act = |s: &EncounterSample| {
        s.range_m() <= rules.stand_on_action_range_m || acting_at.contains(&s.time_s.to_bits())
    };
    let encounter = latch.encounter;
    let role = encounter.role();
    let weights = &scoring.penalties;

    let (min_distance_m, time_of_min_s, passing_side) = match closest_approach(samples) {
        Some((distance, time, index)) => (distance, time, side_at(samples, index, time)),
        None => (f64::INFINITY, latch.latched_at_s, None),
    };

    // The in-force window: from the latch to the first sample at which the
    // vessels have passed.
    let start = samples
        .iter()
        .position(|s| s.time_s >= latch.latched_at_s - 1e-9)
        .unwrap_or(samples.len());
    // Passed is judged on the course ownship was steering when it got there
    // (the previous sample's course and speed): a turn made once the vessels
    // have passed is not a manoeuvre for this encounter, as a bridge officer
    // resumes course only after judging the other vessel passed. The planner
    // judges it the same way, at each node on the course that led there.
    let passed_index = (start..samples.len()).find(|&index| {
        let sample = &samples[index];
        let steering = index
            .checked_sub(1)
            .map_or(&sample.own, |previous| &samples[previous].own);
        let own = VesselState {
            course_rad: steering.course_rad,
            speed_mps: steering.speed_mps,
            ..sample.own
        };
        has_passed(&own, &sample.target, encounter, rules)
    });
    let end = passed_index.unwrap_or(samples.len());
    let in_force = &samples[start..end];
    let segment_end = (end + 1).min(samples.len());
    let segments = &samples[start.min(segment_end)..segment_end];

    let latch_sample = in_force.first();
    let latch_range_m = latch_sample.map(EncounterSample::range_m);
    let latch_cpa_m = latch_sample.map(|s| {
        closest_point_of_approach(
            s.own.position_m,
            s.own.velocity_mps(),
            s.target.position_m,
            s.target.velocity_mps(),
        )
        .distance_m
    });

    let turn_of =
        |s: &EncounterSample| angle::signed_turn(latch.reference_course_rad, s.own.course_rad);
    let speed_change_of = |s: &EncounterSample| s.own.speed_mps - latch.reference_speed_mps;
    let action = in_force.iter().find(|s| {
        turn_of(s).abs() > rules.turn_tolerance_rad
            || speed_change_of(s).abs() > rules.stand_on_speed_tolerance_mps
    });
    let action_time_s = action.map(|s| s.time_s);
    let action_range_m = action.map(EncounterSample::range_m);
    let first_turn_sample = in_force
        .iter()
        .find(|s| turn_of(s).abs() > rules.turn_tolerance_rad);
    let first_turn_rad = first_turn_sample.map(turn_of);
    let max_course_change_rad = largest_signed(in_force.iter().map(turn_of));
    let max_speed_change_mps = largest_signed(in_force.iter().map(speed_change_of));
    let max_speed_reduction_mps = in_force
        .iter()
        .map(|s| -speed_change_of(s))
        .fold(0.0, f64::max);

    let crossed_ahead_distance_m = crossing_ahead_distance(segments);
    let crossed_ahead = crossed_ahead_distance_m.is_some();

    let mut violations = Vec::new();
    if min_distance_m < scoring.clearance_m {
        violations.push(ComplianceViolation::ClearanceViolated { min_distance_m });
    }
    if min_distance_m <= scoring.collision_m {
        violations.push(ComplianceViolation::Collision { min_distance_m });
    }

    let mut rule_13 = None;
    let mut rule_14 = None;
    let mut rule_15 = None;
    let mut rule_16 = None;
    let mut rule_17 = None;

    match role {
        Role::GiveWay => {
            // Rule 16: early and substantial action.
            let mut penalties = Vec::new();
            match action {
                None => {
                    let needed = min_distance_m < scoring.clearance_m
                        || latch_cpa_m.is_some_and(|cpa| cpa < scoring.clearance_m);
                    if needed {
                        violations.push(ComplianceViolation::NoAction);
                        penalties.push(weights.no_action);
                    }
                }
                Some(acted) => {
                    let range_m = acted.range_m();
                    let prompt = acted.time_s - latch.latched_at_s <= scoring.reaction_time_s;
                    if range_m < scoring.late_action_range_m && !prompt {
                        violations.push(ComplianceViolation::LateAction { range_m });
                        let lateness = 1.0 - range_m / scoring.late_action_range_m;
                        penalties.push(weights.late_action * lateness.clamp(0.0, 1.0));
                    }
                    let by_turn = max_course_change_rad.abs() / rules.apparent_turn_rad;
                    let apparent_reduction_mps =
                        scoring.apparent_speed_reduction_fraction * latch.reference_speed_mps;
                    let by_speed = if apparent_reduction_mps > 0.0 {
                        max_speed_reduction_mps / apparent_reduction_mps
                    } else {
                        0.0
                    };
                    let apparentness = by_turn.max(by_speed);
                    if apparentness < 1.0 {
                        violations.push(ComplianceViolation::ActionNotApparent {
                            course_change_rad: max_course_change_rad,
                            speed_change_mps: max_speed_change_mps,
                        });
                        penalties.push(weights.not_apparent * (1.0 - apparentness).clamp(0.0, 1.0));
                    }
                }
            }
            rule_16 = Some(rule_score(&penalties));

            // Rules 13-15: the manner of giving way.
            let port_turn = match first_turn_rad {
                Some(first) if first < 0.0 => Some(first),
                _ if max_course_change_rad < -rules.turn_tolerance_rad => {
                    Some(max_course_change_rad)
                }
                _ => None,
            };
            let mut penalties = Vec::new();
            let port_turn = port_turn
                .filter(|_| matches!(encounter, Encounter::HeadOn | Encounter::CrossingGiveWay));
            if let Some(course_change_rad) = port_turn {
                violations.push(ComplianceViolation::PortTurn { course_change_rad });
                penalties.push(weights.port_turn);
            }
            match encounter {
                Encounter::HeadOn => {
                    if passing_side == Some(PassingSide::Starboard) {
                        violations.push(ComplianceViolation::StarboardToStarboard);
                        penalties.push(weights.starboard_to_starboard);
                    }
                    rule_14 = Some(rule_score(&penalties));
                }
                Encounter::CrossingGiveWay => {
                    if let Some(distance_ahead_m) = crossed_ahead_distance_m {
                        violations.push(ComplianceViolation::CrossedAhead { distance_ahead_m });
                        penalties.push(weights.crossed_ahead);
                    }
                    rule_15 = Some(rule_score(&penalties));
                }
                Encounter::Overtaking => {
                    if let Some(distance_ahead_m) =
                        crossed_ahead_distance_m.filter(|d| *d < scoring.clearance_m)
                    {
                        violations.push(ComplianceViolation::CrossedAhead { distance_ahead_m });
                        penalties.push(weights.crossed_ahead);
                    }
                    rule_13 = Some(rule_score(&penalties));
                }
                _ => {}
            }
        }
        Role::StandOn => {
            // Rule 17(a)(i): keep course and speed while the range is beyond
            // the action range.
            let mut penalties = Vec::new();
            let early = || in_force.iter().filter(|s| !may_act(s));
            let early_turn = largest_signed(early().map(turn_of));
            let early_speed = largest_signed(early().map(speed_change_of));
            if early_turn.abs() > rules.stand_on_course_tolerance_rad {
                violations.push(ComplianceViolation::StandOnCourseChanged {
                    course_change_rad: early_turn,
                });
                penalties.push(weights.stand_on_course_change);
            }
            if early_speed.abs() > rules.stand_on_speed_tolerance_mps {
                violations.push(ComplianceViolation::StandOnSpeedChanged {
                    speed_change_mps: early_speed,
                });
                penalties.push(weights.stand_on_speed_change);
            }
            // Rule 17(c): in a crossing, a vessel that acts does not alter
            // course to port (of the course held when the encounter began) for
            // a vessel on its port side. Only a newly taken course counts, and
            // before the stand-on vessel may act (17(a)(ii)) only one beyond
            // the stand-on tolerance: drift within it is not action, nor is
            // holding such a course into the action range.
            if encounter == Encounter::CrossingStandOn {
                let port_turn = in_force
                    .iter()
                    .zip(std::iter::once(None).chain(in_force.iter().map(Some)))
                    .find(|(s, previous)| {
                        let altered = previous.is_none_or(|p| p.own.course_rad != s.own.course_rad);
                        let acting =
                            may_act(s) || turn_of(s).abs() > rules.stand_on_course_tolerance_rad;
                        altered && acting && turn_of(s) < -rules.turn_tolerance_rad
                    })
                    .map(|(s, _)| s);
                if let Some(s) = port_turn {
                    let bearing = angle::relative_bearing(
                        s.own.position_m,
                        latch.reference_course_rad,
                        s.target.position_m,
                    );
                    if bearing > PI {
                        violations.push(ComplianceViolation::StandOnTurnedToPort {
                            course_change_rad: turn_of(s),
                        });
                        penalties.push(weights.stand_on_port_turn);
                    }
                }
            }
            rule_17 = Some(rule_score(&penalties));
        }
        Role::None => {}
    }

    let safety = safety_score(min_distance_m, scoring);
    let overall = [rule_13, rule_14, rule_15, rule_16, rule_17]
        .into_iter()
        .flatten()
        .fold(safety, |product, score| product * score)
        .clamp(0.0, 1.0);
    let compliant = violations.iter().all(|v| !v.is_rule_violation());
    EncounterAssessment {
        encounter,
        role,
        min_distance_m,
        time_of_min_s,
        latch_range_m,
        latch_cpa_m,
        passed_at_s: passed_index.map(|index| samples[index].time_s),
        action_time_s,
        action_range_m,
        max_course_change_rad,
        max_speed_change_mps,
        first_turn_rad,
        passing_side,
        crossed_ahead,
        crossed_ahead_distance_m,
        violations,
        scores: RuleScores {
            safety,
            rule_13,
            rule_14,
            rule_15,
            rule_16,
            rule_17,
            overall,
        },
        safe: min_distance_m >= scoring.clearance_m,
        compliant,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ownship north at 6 m/s from the origin; the target given; both hold
    /// course except that ownship takes `own_course_deg` from `turn_at_s`.
    fn run(
        target: VesselState,
        turn_at_s: f64,
        own_course_deg: f64,
        duration_s: f64,
    ) -> Vec<EncounterSample> {
        let mut own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let mut target = target;
        let mut samples = Vec::new();
        let mut time_s = 0.0;
        while time_s <= duration_s {
            if time_s >= turn_at_s {
                own.course_rad = own_course_deg.to_radians();
            }
            samples.push(EncounterSample::new(time_s, own, target));
            own = own.advanced(5.0);
            target = target.advanced(5.0);
            time_s += 5.0;
        }
        samples
    }

    fn head_on_target() -> VesselState {
        VesselState::new(DVec2::new(0.0, 9000.0), PI, 6.0, 50.0)
    }

    #[test]
    fn default_parameters_are_valid() {
        ScoringParameters::default().validate().expect("defaults");
    }

    #[test]
    fn misordered_ranges_are_named() {
        let scoring = ScoringParameters {
            near_miss_m: 300.0,
            ..ScoringParameters::default()
        };
        let message = scoring.validate().expect_err("near miss beyond clearance");
        assert!(message.to_string().contains("clearance_m"), "{message}");
        let scoring = ScoringParameters {
            penalties: PenaltyWeights {
                port_turn: 1.5,
                ..PenaltyWeights::default()
            },
            ..ScoringParameters::default()
        };
        let message = scoring.validate().expect_err("weight above 1").to_string();
        assert!(message.contains("penalties.port_turn"), "{message}");
    }

    #[test]
    fn safety_score_breakpoints() {
        let s = ScoringParameters::default();
        assert_eq!(safety_score(f64::INFINITY, &s), 1.0);
        assert_eq!(safety_score(s.clearance_m, &s), 1.0);
        assert!((safety_score(150.0, &s) - 0.75).abs() < 1e-12);
        assert_eq!(safety_score(s.near_miss_m, &s), s.near_miss_safety);
        assert_eq!(safety_score(s.collision_m, &s), 0.0);
        assert_eq!(safety_score(f64::NAN, &s), 0.0);
    }

    #[test]
    fn closest_approach_is_found_between_samples() {
        // Head-on, 150 m lateral offset, 12 m/s closing: with 5 s samples the
        // instants miss the exact pass; the interpolated minimum does not.
        let target = VesselState::new(DVec2::new(150.0, 9033.0), PI, 6.0, 50.0);
        let samples = run(target, f64::INFINITY, 0.0, 1500.0);
        let (distance, time, _) = closest_approach(&samples).expect("samples");
        assert!((distance - 150.0).abs() < 1e-6, "{distance}");
        assert!((time - 9033.0 / 12.0).abs() < 1e-6, "{time}");
    }

    #[test]
    fn compliant_head_on() {
        let rules = RuleParameters::default();
        let samples = run(head_on_target(), 60.0, 35.0, 1500.0);
        let latch = first_latch(&samples, &rules).expect("risk");
        assert_eq!(latch.encounter, Encounter::HeadOn);
        let a = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
        assert!(a.compliant && a.safe, "{:?}", a.violations);
        assert!(a.violations.is_empty());
        assert_eq!(a.passing_side, Some(PassingSide::Port));
        assert_eq!(a.action_time_s, Some(60.0));
        assert!((a.max_course_change_rad - 35f64.to_radians()).abs() < 1e-12);
        assert!(a.passed_at_s.is_some());
        assert_eq!(a.scores.rule_14, Some(1.0));
        assert_eq!(a.scores.rule_16, Some(1.0));
        assert_eq!(
            (a.scores.rule_13, a.scores.rule_15, a.scores.rule_17),
            (None, None, None)
        );
        assert_eq!(a.scores.overall, 1.0);
    }

    #[test]
    fn head_on_without_action_is_no_action_and_collision() {
        let rules = RuleParameters::default();
        let samples = run(head_on_target(), f64::INFINITY, 0.0, 1500.0);
        let latch = first_latch(&samples, &rules).expect("risk");
        let a = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
        assert!(a.violations.contains(&ComplianceViolation::NoAction));
        assert!(
            a.violations
                .iter()
                .any(|v| matches!(v, ComplianceViolation::Collision { .. }))
        );
        assert!(!a.compliant);
        assert_eq!(a.passing_side, None);
        assert_eq!(a.scores.safety, 0.0);
        assert_eq!(a.scores.rule_16, Some(0.0));
        assert_eq!(a.scores.overall, 0.0);
    }

    #[test]
    fn no_action_is_not_needed_when_the_pass_was_already_clear() {
        // Predicted CPA 800 m to port: risk latched (under 1 nm) but clear of d_th.
        let rules = RuleParameters::default();
        let target = VesselState::new(DVec2::new(-800.0, 9000.0), PI, 6.0, 50.0);
        let samples = run(target, f64::INFINITY, 0.0, 1500.0);
        let latch = first_latch(&samples, &rules).expect("risk");
        let a = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
        assert!(a.compliant, "{:?}", a.violations);
        assert_eq!(a.action_time_s, None);
        assert!((a.latch_cpa_m.expect("latched") - 800.0).abs() < 1e-6);
        // The mirror image needs no action either, but passes starboard to
        // starboard, which rule 14(a) names whatever the distance.
        let target = VesselState::new(DVec2::new(800.0, 9000.0), PI, 6.0, 50.0);
        let samples = run(target, f64::INFINITY, 0.0, 1500.0);
        let latch = first_latch(&samples, &rules).expect("risk");
        let a = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
        assert_eq!(
            a.violations,
            vec![ComplianceViolation::StarboardToStarboard]
        );
        assert_eq!(a.scores.rule_16, Some(1.0));
        assert_eq!(a.scores.rule_14, Some(0.5));
    }

    #[test]
    fn role_none_scores_only_safety() {
        let rules = RuleParameters::default();
        let samples = run(head_on_target(), f64::INFINITY, 0.0, 100.0);
        let latch = EncounterLatch::new(Encounter::None, &samples[0].own, 0.0);
        let a = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
        assert!(a.scores.applicable().is_empty());
        assert_eq!(a.scores.overall, a.scores.safety);
        assert!(a.compliant);
    }

    #[test]
    fn empty_recording_finds_nothing() {
        let rules = RuleParameters::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let latch = EncounterLatch::new(Encounter::HeadOn, &own, 0.0);
        let a = assess_encounter(&[], &latch, &rules, &ScoringParameters::default());
        assert_eq!(a.min_distance_m, f64::INFINITY);
        assert!(a.violations.is_empty() && a.compliant && a.safe);
        assert_eq!(a.scores.overall, 1.0);
    }

    #[test]
    fn displays_name_the_rule() {
        let texts = [
            ComplianceViolation::NoAction.to_string(),
            ComplianceViolation::StarboardToStarboard.to_string(),
            ComplianceViolation::StandOnTurnedToPort {
                course_change_rad: -0.5,
            }
            .to_string(),
        ];
        for (text, rule) in texts.iter().zip(["rule 16", "rule 14", "rule 17(c)"]) {
            assert!(text.contains(rule), "{text}");
        }
        assert!(
            !ComplianceViolation::ClearanceViolated {
                min_distance_m: 10.0
            }
            .is_rule_violation()
        );
    }
}
