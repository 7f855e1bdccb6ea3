//! One row of results per scenario of a batch.

use super::BatchItem;
use crate::evaluation::{Evaluation, TargetEvaluation, succeeded};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use vorrt_colregs::compliance::StandOnDeparture;
use vorrt_colregs::rule10::Rule10Clause;
use vorrt_colregs::{ComplianceViolation, Role};

/// The results of one scenario of a batch: one CSV row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "a flat CSV row of documented outcome flags"
)]
pub struct BatchRow {
    /// Position in the whole batch.
    pub index: u64,
    /// The scenario's name.
    pub name: String,
    /// Number of targets.
    pub targets: usize,
    /// The simulation seed.
    pub seed: u64,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// Whether any hull touched another.
    pub collision: bool,
    /// Smallest distance to any target, metres.
    pub min_distance_m: f64,
    /// The clearance `d_th` of the scenario, metres.
    pub clearance_m: f64,
    /// Whether any target came closer than `d_th`.
    pub clearance_violation: bool,
    /// Whether every encounter was handled compliantly (rules 13-17).
    pub compliant: bool,
    /// Rule 13 (overtaking): `None` when it never applied, else whether every
    /// encounter it applied to scored full marks on it.
    pub rule_13: Option<bool>,
    /// Rule 14 (head-on), as `rule_13`.
    pub rule_14: Option<bool>,
    /// Rule 15 (crossing, give way), as `rule_13`.
    pub rule_15: Option<bool>,
    /// Rule 16 (action by give-way vessel), as `rule_13`.
    pub rule_16: Option<bool>,
    /// Rule 17 (action by stand-on vessel), as `rule_13`.
    pub rule_17: Option<bool>,
    /// Extra sailed length over the straight route, percent.
    pub path_overhead_pct: f64,
    /// Wall-clock planning time of the whole run, milliseconds.
    pub planning_time_ms: f64,
    /// Mean wall-clock time per planner call, milliseconds.
    pub planning_time_per_plan_ms: f64,
    /// Planner calls.
    pub plans: usize,
    /// Planner calls after the first.
    pub replans: usize,
    /// Planner calls that failed.
    pub failed_plans: usize,
    /// The target that came closest.
    pub closest_target: String,
    /// Its encounter type (`none` if risk never arose).
    pub closest_encounter: String,
    /// Every distinct finding over all targets, `;`-separated
    /// (`clearance_violated;late_action`).
    pub violations: String,
    /// Why the scenario could not be run at all (empty when it ran).
    pub error: String,
    /// Ownship's largest rate of turn as sailed, degrees per second.
    #[serde(default)]
    pub max_turn_rate_deg_s: f64,
    /// Turn-direction reversals of ownship's course as observed.
    #[serde(default)]
    pub turn_reversals: usize,
    /// Ownship's total course change per nautical mile sailed, degrees.
    #[serde(default)]
    pub course_change_deg_per_nm: f64,
    /// Encounters in which ownship was the give-way vessel (head-on,
    /// crossing give-way, overtaking) with risk latched and rule 16 judged
    /// (not those whose closest approach came within the reaction time).
    #[serde(default)]
    pub give_way_encounters: usize,
    /// Of those, the ones with a readily apparent alteration as observed.
    #[serde(default)]
    pub give_way_apparent: usize,
    /// Of those, the ones whose action began early (rules 8(a), 16).
    #[serde(default)]
    pub give_way_early: usize,
    /// Planner calls after which ownship departed from the rules.
    #[serde(default)]
    pub rule_departures: usize,
    /// Extra time over the straight route at the service speed, percent
    /// ([`Evaluation::time_overhead_pct`]): a slowed ship's overhead, which
    /// the path overhead does not show. Not a number in rows written before
    /// the column existed.
    #[serde(default = "not_recorded")]
    pub time_overhead_pct: f64,
    /// The least distance from ownship's track to land, metres
    /// ([`Evaluation::min_land_distance_m`]); empty when the scenario has
    /// no land (or the row predates the column).
    #[serde(default)]
    pub min_land_distance_m: Option<f64>,
    /// Whether ownship's track touched or crossed land.
    #[serde(default)]
    pub grounding: bool,
    /// Whether it came within `land_clearance_m` of land.
    #[serde(default)]
    pub land_clearance_violation: bool,
    /// Lanes crossed (rule 10, on the track as sailed).
    #[serde(default)]
    pub lane_crossings: usize,
    /// Of those, the ones within the crossing tolerance of perpendicular
    /// to the flow (10(c)).
    #[serde(default)]
    pub lane_crossings_square: usize,
    /// The largest angle of the heading from perpendicular to the flow in
    /// any crossing, degrees (empty without a crossing).
    #[serde(default)]
    pub crossing_off_perpendicular_deg: Option<f64>,
    /// Stretches inside a separation zone other than crossing it (10(e)).
    #[serde(default)]
    pub separation_zone_entries: usize,
    /// Every distinct rule-10 finding (as sailed), `;`-separated
    /// (`rule_10c_crossing_not_square`).
    #[serde(default)]
    pub rule10_findings: String,
    /// Stand-on encounters (crossing stand-on, being overtaken) judged.
    #[serde(default)]
    pub stand_on_encounters: usize,
    /// Of those, the ones in which ownship kept its course and speed until
    /// the give-way vessel came within the stand-on action range (no
    /// departure, rule 17(a)(i); decision 45).
    #[serde(default)]
    pub stand_on_kept: usize,
    /// Of the others, the ones whose every departure was justified by a duty
    /// toward another vessel that took precedence (rules 2(b), 16,
    /// 17(a)(ii); decision 45).
    #[serde(default)]
    pub stand_on_justified: usize,
}

/// A value a row read back from an older `rows.csv` lacks.
fn not_recorded() -> f64 {
    f64::NAN
}

impl BatchRow {
    /// Whether the run counts as a success: [`Evaluation::success`] of the
    /// row's evaluation (goal reached, no collision and no grounding, `d_th`
    /// and the land clearance kept); a run that could not be made never
    /// does.
    #[must_use]
    pub fn success(&self) -> bool {
        self.error.is_empty()
            && succeeded(
                self.reached_goal,
                self.collision || self.grounding,
                !self.clearance_violation && !self.land_clearance_violation,
            )
    }

    /// The compliance with `rule` (13-17), as in the row.
    #[must_use]
    pub fn rule(&self, rule: u8) -> Option<bool> {
        match rule {
            13 => self.rule_13,
            14 => self.rule_14,
            15 => self.rule_15,
            16 => self.rule_16,
            17 => self.rule_17,
            _ => None,
        }
    }

    /// The row of a run that could not be made.
    pub(super) fn failed(item: &BatchItem, error: String) -> Self {
        Self {
            index: item.index,
            name: item.scenario.name.clone(),
            targets: item.scenario.targets.len(),
            seed: item.seed,
            reached_goal: false,
            collision: false,
            min_distance_m: f64::NAN,
            clearance_m: f64::NAN,
            clearance_violation: false,
            compliant: false,
            rule_13: None,
            rule_14: None,
            rule_15: None,
            rule_16: None,
            rule_17: None,
            path_overhead_pct: f64::NAN,
            planning_time_ms: 0.0,
            planning_time_per_plan_ms: 0.0,
            plans: 0,
            replans: 0,
            failed_plans: 0,
            closest_target: String::new(),
            closest_encounter: String::new(),
            violations: String::new(),
            error,
            max_turn_rate_deg_s: f64::NAN,
            turn_reversals: 0,
            course_change_deg_per_nm: f64::NAN,
            give_way_encounters: 0,
            give_way_apparent: 0,
            give_way_early: 0,
            rule_departures: 0,
            time_overhead_pct: f64::NAN,
            min_land_distance_m: None,
            grounding: false,
            land_clearance_violation: false,
            lane_crossings: 0,
            lane_crossings_square: 0,
            crossing_off_perpendicular_deg: None,
            separation_zone_entries: 0,
            rule10_findings: String::new(),
            stand_on_encounters: 0,
            stand_on_kept: 0,
            stand_on_justified: 0,
        }
    }

    /// The row of an evaluated run.
    #[must_use]
    pub fn from_evaluation(item: &BatchItem, evaluation: &Evaluation) -> Self {
        let rule = |rule: u8| rule_compliance(evaluation, rule);
        let closest = evaluation
            .targets
            .iter()
            .min_by(|a, b| a.min_distance_m.total_cmp(&b.min_distance_m));
        let plans = evaluation.plans_made + evaluation.failed_plans;
        #[expect(
            clippy::cast_precision_loss,
            reason = "a count of plans, far below 2^52"
        )]
        let plans_f64 = plans as f64;
        let give_way = judged_give_way(evaluation);
        let stand_on = stand_on_departures(evaluation);
        let planning_time_ms = 1000.0 * evaluation.planning_time_s;
        Self {
            index: item.index,
            name: evaluation.scenario.clone(),
            targets: evaluation.targets.len(),
            seed: evaluation.seed,
            reached_goal: evaluation.reached_goal,
            collision: evaluation.collision,
            min_distance_m: evaluation.min_distance_m,
            clearance_m: evaluation.clearance_m,
            clearance_violation: !evaluation.clearance_kept,
            min_land_distance_m: evaluation.min_land_distance_m,
            grounding: evaluation.grounding,
            land_clearance_violation: !evaluation.land_clearance_kept,
            compliant: evaluation.compliant,
            rule_13: rule(13),
            rule_14: rule(14),
            rule_15: rule(15),
            rule_16: rule(16),
            rule_17: rule(17),
            path_overhead_pct: evaluation.path_overhead_pct,
            planning_time_ms,
            planning_time_per_plan_ms: if plans > 0 {
                planning_time_ms / plans_f64
            } else {
                0.0
            },
            plans,
            replans: evaluation.replans,
            failed_plans: evaluation.failed_plans,
            closest_target: closest.map(|t| t.name.clone()).unwrap_or_default(),
            closest_encounter: closest
                .map(|t| t.encounter.name().to_owned())
                .unwrap_or_default(),
            violations: finding_names(evaluation),
            error: String::new(),
            max_turn_rate_deg_s: evaluation.max_turn_rate_deg_s,
            turn_reversals: evaluation.turn_reversals,
            course_change_deg_per_nm: evaluation.course_change_deg_per_nm,
            give_way_encounters: give_way.len(),
            give_way_apparent: count_without(&give_way, |finding| {
                matches!(
                    finding,
                    ComplianceViolation::ActionNotApparent { .. } | ComplianceViolation::NoAction
                )
            }),
            give_way_early: count_without(&give_way, |finding| {
                matches!(
                    finding,
                    ComplianceViolation::LateAction { .. } | ComplianceViolation::NoAction
                )
            }),
            rule_departures: evaluation.rule_departures,
            time_overhead_pct: evaluation.time_overhead_pct,
            lane_crossings: evaluation.rule10.crossings.len(),
            lane_crossings_square: evaluation.rule10.square_crossings(),
            crossing_off_perpendicular_deg: evaluation
                .rule10
                .crossings
                .iter()
                .map(|crossing| crossing.max_off_perpendicular_deg)
                .reduce(f64::max),
            separation_zone_entries: evaluation.rule10.count(Rule10Clause::SeparationZone),
            rule10_findings: evaluation
                .rule10
                .findings
                .iter()
                .map(|finding| finding.clause.key())
                .collect::<BTreeSet<_>>()
                .into_iter()
                .collect::<Vec<_>>()
                .join(";"),
            stand_on_encounters: stand_on.len(),
            stand_on_kept: stand_on
                .iter()
                .filter(|departures| departures.is_empty())
                .count(),
            stand_on_justified: stand_on
                .iter()
                .filter(|departures| {
                    !departures.is_empty() && departures.iter().all(|d| d.precedence.is_some())
                })
                .count(),
        }
    }
}

/// The stand-on departures of every stand-on encounter judged, one list per
/// encounter (empty: course and speed kept).
fn stand_on_departures(evaluation: &Evaluation) -> Vec<&[StandOnDeparture]> {
    evaluation
        .targets
        .iter()
        .filter(|target| target.role == Role::StandOn)
        .filter_map(|target| target.assessment.as_ref())
        .map(|assessment| assessment.stand_on_departures.as_slice())
        .collect()
}

/// Compliance with `rule` over the run: `None` when it applied to no
/// encounter, else whether every encounter it applied to scored full marks.
fn rule_compliance(evaluation: &Evaluation, rule: u8) -> Option<bool> {
    let scores: Vec<f64> = evaluation
        .targets
        .iter()
        .filter_map(|target| target.assessment.as_ref())
        .filter_map(|assessment| {
            assessment
                .scores
                .applicable()
                .into_iter()
                .find(|(number, _)| *number == rule)
                .map(|(_, score)| score)
        })
        .collect();
    (!scores.is_empty()).then(|| scores.iter().all(|score| *score >= 1.0))
}

/// Every distinct finding over all targets, sorted, `;`-separated; a target
/// with no encounter contributes only a broken clearance.
fn finding_names(evaluation: &Evaluation) -> String {
    let mut findings = BTreeSet::new();
    for target in &evaluation.targets {
        match &target.assessment {
            Some(assessment) => {
                findings.extend(assessment.violations.iter().map(ComplianceViolation::name));
            }
            None if !target.clearance_kept => {
                findings.insert("clearance_violated");
            }
            None => {}
        }
    }
    findings.into_iter().collect::<Vec<_>>().join(";")
}

/// The give-way encounters in which rule 16 was judged (not those whose
/// closest approach came too soon after risk arose).
fn judged_give_way(evaluation: &Evaluation) -> Vec<&TargetEvaluation> {
    evaluation
        .targets
        .iter()
        .filter(|target| {
            target.role == Role::GiveWay
                && target.risk_time_s.is_some()
                && target
                    .assessment
                    .as_ref()
                    .is_some_and(|assessment| assessment.scores.rule_16.is_some())
        })
        .collect()
}

/// How many of `targets` have no finding for which `is_failure` holds.
fn count_without(
    targets: &[&TargetEvaluation],
    is_failure: impl Fn(&ComplianceViolation) -> bool,
) -> usize {
    targets
        .iter()
        .filter(|target| !target.findings.iter().any(&is_failure))
        .count()
}
