//! The summary of a batch: rates, compliance per rule and percentiles.

use super::{BatchRow, RULES};
use serde::{Deserialize, Serialize};

/// Percentiles of a distribution (nearest rank over the finite values).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Percentiles {
    /// How many finite values there were.
    pub count: usize,
    /// Smallest.
    pub min: Option<f64>,
    /// 1st percentile.
    pub p1: Option<f64>,
    /// 10th percentile.
    pub p10: Option<f64>,
    /// Median.
    pub p50: Option<f64>,
    /// 90th percentile.
    pub p90: Option<f64>,
    /// 99th percentile.
    pub p99: Option<f64>,
    /// Largest.
    pub max: Option<f64>,
    /// Mean.
    pub mean: Option<f64>,
}

impl Percentiles {
    /// Of `values` (NaN and infinite values left out).
    #[must_use]
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let mut sorted: Vec<f64> = values.into_iter().filter(|v| v.is_finite()).collect();
        sorted.sort_by(f64::total_cmp);
        #[expect(
            clippy::cast_precision_loss,
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a count of values; the rank is rounded up, non-negative and clamped"
        )]
        let rank = |p: f64| -> Option<f64> {
            if sorted.is_empty() {
                return None;
            }
            let position = ((p / 100.0) * sorted.len() as f64).ceil() as usize;
            Some(sorted[position.clamp(1, sorted.len()) - 1])
        };
        #[expect(
            clippy::cast_precision_loss,
            reason = "a count of values, far below 2^52"
        )]
        let mean = (!sorted.is_empty()).then(|| sorted.iter().sum::<f64>() / sorted.len() as f64);
        Self {
            count: sorted.len(),
            min: sorted.first().copied(),
            p1: rank(1.0),
            p10: rank(10.0),
            p50: rank(50.0),
            p90: rank(90.0),
            p99: rank(99.0),
            max: sorted.last().copied(),
            mean,
        }
    }
}

/// Compliance with one rule over a batch.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RuleRate {
    /// The rule (13-17).
    pub rule: u8,
    /// Runs in which it applied.
    pub applicable: usize,
    /// Of those, runs in which every encounter scored full marks on it.
    pub compliant: usize,
    /// `compliant / applicable` (`None` when it never applied).
    pub rate: Option<f64>,
}

/// The summary of a batch (`summary.json`): a function of its rows alone, so
/// merged shards give the same summary as the unsharded batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BatchSummary {
    /// Scenarios in the batch.
    pub count: usize,
    /// Scenarios that could not be run at all.
    pub errors: usize,
    /// Fraction that reached the goal.
    pub reached_goal_rate: f64,
    /// Fraction that reached the goal with no collision or grounding and
    /// `d_th` and the land clearance kept
    /// ([`BatchRow::success`]).
    pub success_rate: f64,
    /// Fraction with a collision (hulls touching).
    pub collision_rate: f64,
    /// Fraction in which some target came closer than `d_th`.
    pub clearance_violation_rate: f64,
    /// Fraction in which every encounter was handled compliantly.
    pub compliance_rate: f64,
    /// Compliance per rule, 13 to 17.
    pub rules: Vec<RuleRate>,
    /// Smallest distance to any target per run, metres.
    pub min_distance_m: Percentiles,
    /// Path overhead per run, percent.
    pub path_overhead_pct: Percentiles,
    /// Time overhead per run (at the service speed), percent.
    #[serde(default)]
    pub time_overhead_pct: Percentiles,
    /// Planning time per run, milliseconds.
    pub planning_time_ms: Percentiles,
    /// Mean planning time per planner call per run, milliseconds.
    pub planning_time_per_plan_ms: Percentiles,
    /// Replans per run.
    pub replans: Percentiles,
    /// Failed planner calls over the batch.
    pub failed_plans: usize,
    /// Runs with at least one failed planner call.
    pub runs_with_failed_plans: usize,
    /// Ownship's largest rate of turn per run, degrees per second.
    #[serde(default)]
    pub max_turn_rate_deg_s: Percentiles,
    /// Turn-direction reversals per run.
    #[serde(default)]
    pub turn_reversals: Percentiles,
    /// Course change per nautical mile sailed, degrees.
    #[serde(default)]
    pub course_change_deg_per_nm: Percentiles,
    /// Give-way encounters over the batch.
    #[serde(default)]
    pub give_way_encounters: usize,
    /// The share of them with a readily apparent alteration as observed.
    #[serde(default)]
    pub give_way_apparent_rate: Option<f64>,
    /// The share of them whose action began early.
    #[serde(default)]
    pub give_way_early_rate: Option<f64>,
    /// Runs in which ownship departed from the rules at least once (a
    /// graded fallback plan or the evasive manoeuvre).
    #[serde(default)]
    pub runs_with_rule_departures: usize,
    /// Stand-on encounters over the batch.
    #[serde(default)]
    pub stand_on_encounters: usize,
    /// The share of them in which ownship kept its course and speed until
    /// the give-way vessel came within the stand-on action range (decision
    /// 45); `null` with none.
    #[serde(default)]
    pub stand_on_kept_rate: Option<f64>,
    /// Of the stand-on encounters with a departure, the share whose every
    /// departure a duty toward another vessel justified (decision 45);
    /// `null` with none.
    #[serde(default)]
    pub stand_on_justified_rate: Option<f64>,
    /// Runs whose track touched or crossed land (a safety failure).
    #[serde(default)]
    pub groundings: usize,
    /// Runs whose track came within `land_clearance_m` of land.
    #[serde(default)]
    pub land_clearance_violations: usize,
    /// The least distance to land per run with land, metres.
    #[serde(default)]
    pub min_land_distance_m: Percentiles,
    /// Lane crossings over the batch (rule 10, as sailed).
    #[serde(default)]
    pub lane_crossings: usize,
    /// The share of them within the crossing tolerance of perpendicular
    /// to the flow (10(c)); `None` without a crossing.
    #[serde(default)]
    pub lane_crossing_square_rate: Option<f64>,
    /// Per run with a crossing, the largest angle of the heading from
    /// perpendicular to the flow, degrees.
    #[serde(default)]
    pub crossing_off_perpendicular_deg: Percentiles,
    /// Runs with a stretch inside a separation zone other than crossing it
    /// (10(e)).
    #[serde(default)]
    pub runs_with_separation_zone_entry: usize,
    /// Runs with any rule-10 finding.
    #[serde(default)]
    pub runs_with_rule10_findings: usize,
}

impl BatchSummary {
    /// Summarises `rows` (in any order).
    #[must_use]
    #[expect(
        clippy::cast_precision_loss,
        reason = "counts of runs, encounters and replans, far below 2^52"
    )]
    pub fn from_rows(rows: &[BatchRow]) -> Self {
        let mut rows: Vec<&BatchRow> = rows.iter().collect();
        rows.sort_by_key(|row| row.index);
        let count = rows.len();
        let rate = |predicate: &dyn Fn(&BatchRow) -> bool| {
            if count == 0 {
                0.0
            } else {
                rows.iter().filter(|row| predicate(row)).count() as f64 / count as f64
            }
        };
        let rules = RULES
            .iter()
            .map(|&rule| {
                let applicable = rows.iter().filter(|row| row.rule(rule).is_some()).count();
                let compliant = rows
                    .iter()
                    .filter(|row| row.rule(rule) == Some(true))
                    .count();
                RuleRate {
                    rule,
                    applicable,
                    compliant,
                    rate: (applicable > 0).then(|| compliant as f64 / applicable as f64),
                }
            })
            .collect();
        let ran: Vec<&&BatchRow> = rows.iter().filter(|row| row.error.is_empty()).collect();
        let give_way_encounters: usize = ran.iter().map(|row| row.give_way_encounters).sum();
        let lane_crossings: usize = ran.iter().map(|row| row.lane_crossings).sum();
        let stand_on_encounters: usize = ran.iter().map(|row| row.stand_on_encounters).sum();
        let stand_on_kept: usize = ran.iter().map(|row| row.stand_on_kept).sum();
        let share = |count: usize| {
            (give_way_encounters > 0).then(|| count as f64 / give_way_encounters as f64)
        };
        Self {
            count,
            errors: count - ran.len(),
            reached_goal_rate: rate(&|row| row.reached_goal),
            success_rate: rate(&|row| row.success()),
            collision_rate: rate(&|row| row.collision),
            clearance_violation_rate: rate(&|row| row.clearance_violation),
            compliance_rate: rate(&|row| row.error.is_empty() && row.compliant),
            rules,
            min_distance_m: Percentiles::of(ran.iter().map(|row| row.min_distance_m)),
            path_overhead_pct: Percentiles::of(ran.iter().map(|row| row.path_overhead_pct)),
            time_overhead_pct: Percentiles::of(ran.iter().map(|row| row.time_overhead_pct)),
            planning_time_ms: Percentiles::of(ran.iter().map(|row| row.planning_time_ms)),
            planning_time_per_plan_ms: Percentiles::of(
                ran.iter().map(|row| row.planning_time_per_plan_ms),
            ),
            replans: Percentiles::of(ran.iter().map(|row| row.replans as f64)),
            failed_plans: rows.iter().map(|row| row.failed_plans).sum(),
            runs_with_failed_plans: rows.iter().filter(|row| row.failed_plans > 0).count(),
            max_turn_rate_deg_s: Percentiles::of(ran.iter().map(|row| row.max_turn_rate_deg_s)),
            turn_reversals: Percentiles::of(ran.iter().map(|row| row.turn_reversals as f64)),
            course_change_deg_per_nm: Percentiles::of(
                ran.iter().map(|row| row.course_change_deg_per_nm),
            ),
            give_way_encounters,
            give_way_apparent_rate: share(ran.iter().map(|row| row.give_way_apparent).sum()),
            give_way_early_rate: share(ran.iter().map(|row| row.give_way_early).sum()),
            runs_with_rule_departures: rows.iter().filter(|row| row.rule_departures > 0).count(),
            stand_on_encounters,
            stand_on_kept_rate: (stand_on_encounters > 0)
                .then(|| stand_on_kept as f64 / stand_on_encounters as f64),
            stand_on_justified_rate: (stand_on_encounters > stand_on_kept).then(|| {
                ran.iter().map(|row| row.stand_on_justified).sum::<usize>() as f64
                    / (stand_on_encounters - stand_on_kept) as f64
            }),
            groundings: ran.iter().filter(|row| row.grounding).count(),
            land_clearance_violations: ran
                .iter()
                .filter(|row| row.land_clearance_violation)
                .count(),
            min_land_distance_m: Percentiles::of(
                ran.iter().filter_map(|row| row.min_land_distance_m),
            ),
            lane_crossings,
            lane_crossing_square_rate: (lane_crossings > 0).then(|| {
                ran.iter()
                    .map(|row| row.lane_crossings_square)
                    .sum::<usize>() as f64
                    / lane_crossings as f64
            }),
            crossing_off_perpendicular_deg: Percentiles::of(
                ran.iter()
                    .filter_map(|row| row.crossing_off_perpendicular_deg),
            ),
            runs_with_separation_zone_entry: ran
                .iter()
                .filter(|row| row.separation_zone_entries > 0)
                .count(),
            runs_with_rule10_findings: ran
                .iter()
                .filter(|row| !row.rule10_findings.is_empty())
                .count(),
        }
    }

    /// The summary as pretty JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        // Serialising plain numbers, strings and options cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_by_nearest_rank() {
        let p = Percentiles::of((1..=100).map(f64::from).chain([f64::NAN, f64::INFINITY]));
        assert_eq!(p.count, 100);
        assert_eq!(p.p50, Some(50.0));
        assert_eq!(p.p90, Some(90.0));
        assert_eq!(p.p99, Some(99.0));
        assert_eq!(p.p1, Some(1.0));
        assert_eq!(p.max, Some(100.0));
        assert_eq!(p.mean, Some(50.5));
        assert_eq!(Percentiles::of([]).p50, None);
        assert_eq!(Percentiles::of([7.0]).p1, Some(7.0));
    }
}
