//! What an assessment reports: the measurements, the findings and the scores.

use super::{ComplianceViolation, StandOnDeparture};
use crate::encounter::{Encounter, Role};
use crate::passing::PassingSide;
use serde::{Deserialize, Serialize};

/// Scores of one encounter, each in `[0, 1]` (1 = best); a rule's score is
/// `None` when that rule places no obligation on ownship in this encounter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RuleScores {
    /// From the minimum range ([`safety_score`](super::safety_score)); 0 when
    /// the hulls touched.
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
    /// Alteration episodes while in force that were detectable (2°) but not
    /// readily apparent (30°): two or more are a succession of small
    /// alterations (rule 8(b)).
    pub small_alterations: usize,
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
    /// Standing on, the departures from the course or speed to keep while
    /// the give-way vessel was beyond the stand-on action range: the first
    /// justified by each other vessel's duty, which took precedence (rules
    /// 2(b), 16, 17(a)(ii); no finding), and the first unjustified one (a
    /// finding). Empty when the course and speed were kept (decision 45).
    #[serde(default)]
    pub stand_on_departures: Vec<StandOnDeparture>,
    /// The scores.
    pub scores: RuleScores,
    /// Whether the minimum range stayed at or above the clearance.
    pub safe: bool,
    /// Whether no rule was broken (safety findings do not count).
    pub compliant: bool,
}
